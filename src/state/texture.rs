//! Texture objects, their parameters, the texture units and their environments (§3.8,
//! tables 6.15-6.20): stored, validated and queried. There is no rasterizer, so no texture
//! is ever sampled; the images themselves are in `texture_image.rs`.

use std::collections::{BTreeMap, BTreeSet, HashMap};

use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::texture_image::TexImage;

/// GL_MAX_TEXTURE_UNITS: OSMesa's value.
pub const MAX_TEXTURE_UNITS: usize = 8;

/// GL_MAX_TEXTURE_LOD_BIAS (OSMesa's value).
pub const MAX_TEXTURE_LOD_BIAS: f32 = 16.0;

/// The four texture targets of GL 1.5, in the order of `TextureUnit::bindings`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Target {
    /// GL_TEXTURE_1D.
    Texture1D,
    /// GL_TEXTURE_2D.
    Texture2D,
    /// GL_TEXTURE_3D.
    Texture3D,
    /// GL_TEXTURE_CUBE_MAP.
    CubeMap,
}

impl Target {
    /// The four targets, in order.
    pub const ALL: [Target; 4] = [
        Target::Texture1D,
        Target::Texture2D,
        Target::Texture3D,
        Target::CubeMap,
    ];

    /// The target glBindTexture, glTexParameter and glEnable name, or None.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture::Target};
    /// assert_eq!(Target::of(GL_TEXTURE_3D), Some(Target::Texture3D));
    /// assert_eq!(Target::of(GL_PROXY_TEXTURE_3D), None);
    /// ```
    pub fn of(target: GLenum) -> Option<Target> {
        Target::ALL.into_iter().find(|t| t.enumeration() == target)
    }

    /// The target's enum (GL_TEXTURE_1D ...).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture::Target};
    /// assert_eq!(Target::CubeMap.enumeration(), GL_TEXTURE_CUBE_MAP);
    /// ```
    pub fn enumeration(self) -> GLenum {
        match self {
            Target::Texture1D => GL_TEXTURE_1D,
            Target::Texture2D => GL_TEXTURE_2D,
            Target::Texture3D => GL_TEXTURE_3D,
            Target::CubeMap => GL_TEXTURE_CUBE_MAP,
        }
    }

    /// The query of the unit's binding of this target.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture::Target};
    /// assert_eq!(Target::Texture2D.binding_pname(), GL_TEXTURE_BINDING_2D);
    /// ```
    pub fn binding_pname(self) -> GLenum {
        match self {
            Target::Texture1D => GL_TEXTURE_BINDING_1D,
            Target::Texture2D => GL_TEXTURE_BINDING_2D,
            Target::Texture3D => GL_TEXTURE_BINDING_3D,
            Target::CubeMap => GL_TEXTURE_BINDING_CUBE_MAP,
        }
    }

    /// The proxy target of the same kind.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture::Target};
    /// assert_eq!(Target::Texture1D.proxy(), GL_PROXY_TEXTURE_1D);
    /// ```
    pub fn proxy(self) -> GLenum {
        match self {
            Target::Texture1D => GL_PROXY_TEXTURE_1D,
            Target::Texture2D => GL_PROXY_TEXTURE_2D,
            Target::Texture3D => GL_PROXY_TEXTURE_3D,
            Target::CubeMap => GL_PROXY_TEXTURE_CUBE_MAP,
        }
    }

    /// The number of dimensions of its images.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::Target;
    /// assert_eq!((Target::Texture3D.dimensions(), Target::CubeMap.dimensions()), (3, 2));
    /// ```
    pub fn dimensions(self) -> usize {
        match self {
            Target::Texture1D => 1,
            Target::Texture2D | Target::CubeMap => 2,
            Target::Texture3D => 3,
        }
    }

    /// GL_MAX_TEXTURE_SIZE, GL_MAX_3D_TEXTURE_SIZE or GL_MAX_CUBE_MAP_TEXTURE_SIZE: small
    /// enough that a largest image, stored as four floats a texel, fits in memory.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::Target;
    /// assert_eq!((Target::Texture2D.max_size(), Target::Texture3D.max_size()), (2048, 128));
    /// ```
    pub fn max_size(self) -> i32 {
        match self {
            Target::Texture1D | Target::Texture2D => 2048,
            Target::Texture3D => 128,
            Target::CubeMap => 1024,
        }
    }

    /// The number of levels: log2 of the largest size, plus one.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::Target;
    /// assert_eq!(Target::Texture2D.levels(), 12); // 2048 down to 1
    /// ```
    pub fn levels(self) -> usize {
        self.max_size().trailing_zeros() as usize + 1
    }
}

/// The parameters of a texture object (table 6.16, glTexParameter): GL_TEXTURE_BIT state of
/// the bound objects.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureParams {
    /// GL_TEXTURE_MIN_FILTER.
    pub min_filter: GLenum,
    /// GL_TEXTURE_MAG_FILTER.
    pub mag_filter: GLenum,
    /// S, T, R.
    pub wrap: [GLenum; 3],
    /// Clamped to [0, 1] when set.
    pub border_color: [f32; 4],
    /// Clamped to [0, 1] when set.
    pub priority: f32,
    /// GL_TEXTURE_MIN_LOD.
    pub min_lod: f32,
    /// GL_TEXTURE_MAX_LOD.
    pub max_lod: f32,
    /// GL_TEXTURE_BASE_LEVEL.
    pub base_level: GLint,
    /// GL_TEXTURE_MAX_LEVEL.
    pub max_level: GLint,
    /// GL_GENERATE_MIPMAP.
    pub generate_mipmap: bool,
    /// GL_DEPTH_TEXTURE_MODE.
    pub depth_texture_mode: GLenum,
    /// GL_TEXTURE_COMPARE_MODE.
    pub compare_mode: GLenum,
    /// GL_TEXTURE_COMPARE_FUNC.
    pub compare_func: GLenum,
}

impl Default for TextureParams {
    fn default() -> TextureParams {
        TextureParams {
            min_filter: GL_NEAREST_MIPMAP_LINEAR,
            mag_filter: GL_LINEAR,
            wrap: [GL_REPEAT; 3],
            border_color: [0.0; 4],
            priority: 1.0,
            min_lod: -1000.0,
            max_lod: 1000.0,
            base_level: 0,
            max_level: 1000,
            generate_mipmap: false,
            depth_texture_mode: GL_LUMINANCE,
            compare_mode: GL_NONE,
            compare_func: GL_LEQUAL,
        }
    }
}

/// How many values a glTexParameter pname takes (GL_TEXTURE_BORDER_COLOR four, the others
/// one), or None for a pname that is none.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::texture::tex_parameter_count};
/// assert_eq!(tex_parameter_count(GL_TEXTURE_BORDER_COLOR), Some(4));
/// assert_eq!(tex_parameter_count(GL_TEXTURE_WRAP_R), Some(1));
/// ```
pub fn tex_parameter_count(pname: GLenum) -> Option<usize> {
    match pname {
        GL_TEXTURE_BORDER_COLOR => Some(4),
        GL_TEXTURE_MIN_FILTER
        | GL_TEXTURE_MAG_FILTER
        | GL_TEXTURE_WRAP_S
        | GL_TEXTURE_WRAP_T
        | GL_TEXTURE_WRAP_R
        | GL_TEXTURE_PRIORITY
        | GL_TEXTURE_MIN_LOD
        | GL_TEXTURE_MAX_LOD
        | GL_TEXTURE_BASE_LEVEL
        | GL_TEXTURE_MAX_LEVEL
        | GL_GENERATE_MIPMAP
        | GL_DEPTH_TEXTURE_MODE
        | GL_TEXTURE_COMPARE_MODE
        | GL_TEXTURE_COMPARE_FUNC => Some(1),
        _ => None,
    }
}

/// An enum given as a float parameter: truncated, as Mesa does (GL_LINEAR + 0.4 is
/// GL_LINEAR); values no enum can have are never valid.
fn enum_param(value: f32) -> GLenum {
    if value.is_finite() && value >= 0.0 && value < u32::MAX as f32 {
        value as GLenum
    } else {
        GLenum::MAX
    }
}

fn one_of(value: GLenum, valid: &[GLenum]) -> GlResult<GLenum> {
    if valid.contains(&value) {
        Ok(value)
    } else {
        Err(GlError::InvalidEnum)
    }
}

const MIN_FILTERS: [GLenum; 6] = [
    GL_NEAREST,
    GL_LINEAR,
    GL_NEAREST_MIPMAP_NEAREST,
    GL_LINEAR_MIPMAP_NEAREST,
    GL_NEAREST_MIPMAP_LINEAR,
    GL_LINEAR_MIPMAP_LINEAR,
];
const WRAP_MODES: [GLenum; 5] = [
    GL_CLAMP,
    GL_REPEAT,
    GL_CLAMP_TO_EDGE,
    GL_CLAMP_TO_BORDER,
    GL_MIRRORED_REPEAT,
];
/// GL 1.5 takes all eight functions (EXT_shadow_funcs).
const COMPARE_FUNCS: [GLenum; 8] = [
    GL_NEVER,
    GL_LESS,
    GL_EQUAL,
    GL_LEQUAL,
    GL_GREATER,
    GL_NOTEQUAL,
    GL_GEQUAL,
    GL_ALWAYS,
];

impl TextureParams {
    /// glTexParameter (§3.8.4) with its values as floats (glTexParameteri's converted
    /// directly, their border color already mapped to [0, 1]): GL_INVALID_ENUM for an enum
    /// value a pname does not take, GL_INVALID_VALUE for a negative base or max level.
    /// Nothing changes on an error.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture::TextureParams, GlError};
    /// let mut params = TextureParams::default();
    /// params.set(GL_TEXTURE_MIN_LOD, &[-4.0])?;
    /// assert_eq!(params.min_lod, -4.0);
    /// assert_eq!(params.set(GL_TEXTURE_BASE_LEVEL, &[-1.0]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(&mut self, pname: GLenum, values: &[f32]) -> GlResult {
        let count = tex_parameter_count(pname).ok_or(GlError::InvalidEnum)?;
        let values = values.get(..count).ok_or(GlError::InvalidValue)?;
        let value = values[0];
        let level = || {
            let level = crate::state::convert::float_to_int(value);
            if level < 0 {
                Err(GlError::InvalidValue)
            } else {
                Ok(level)
            }
        };
        match pname {
            GL_TEXTURE_MIN_FILTER => self.min_filter = one_of(enum_param(value), &MIN_FILTERS)?,
            GL_TEXTURE_MAG_FILTER => {
                self.mag_filter = one_of(enum_param(value), &[GL_NEAREST, GL_LINEAR])?
            }
            GL_TEXTURE_WRAP_S => self.wrap[0] = one_of(enum_param(value), &WRAP_MODES)?,
            GL_TEXTURE_WRAP_T => self.wrap[1] = one_of(enum_param(value), &WRAP_MODES)?,
            GL_TEXTURE_WRAP_R => self.wrap[2] = one_of(enum_param(value), &WRAP_MODES)?,
            GL_TEXTURE_BORDER_COLOR => {
                self.border_color = std::array::from_fn(|i| values[i].clamp(0.0, 1.0))
            }
            GL_TEXTURE_PRIORITY => self.priority = value.clamp(0.0, 1.0),
            GL_TEXTURE_MIN_LOD => self.min_lod = value,
            GL_TEXTURE_MAX_LOD => self.max_lod = value,
            GL_TEXTURE_BASE_LEVEL => self.base_level = level()?,
            GL_TEXTURE_MAX_LEVEL => self.max_level = level()?,
            GL_GENERATE_MIPMAP => self.generate_mipmap = value != 0.0,
            GL_DEPTH_TEXTURE_MODE => {
                self.depth_texture_mode =
                    one_of(enum_param(value), &[GL_LUMINANCE, GL_INTENSITY, GL_ALPHA])?
            }
            GL_TEXTURE_COMPARE_MODE => {
                self.compare_mode = one_of(enum_param(value), &[GL_NONE, GL_COMPARE_R_TO_TEXTURE])?
            }
            GL_TEXTURE_COMPARE_FUNC => {
                self.compare_func = one_of(enum_param(value), &COMPARE_FUNCS)?
            }
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }
}

/// The combiner state of a texture environment (§3.8.13, table 3.20), GL 1.3's
/// ARB_texture_env_combine with GL 1.4's crossbar sources (GL_TEXTUREn).
#[derive(Clone, Debug, PartialEq)]
pub struct Combine {
    /// GL_COMBINE_RGB.
    pub combine_rgb: GLenum,
    /// GL_COMBINE_ALPHA.
    pub combine_alpha: GLenum,
    /// GL_SOURCE0_RGB to GL_SOURCE2_RGB.
    pub source_rgb: [GLenum; 3],
    /// GL_SOURCE0_ALPHA to GL_SOURCE2_ALPHA.
    pub source_alpha: [GLenum; 3],
    /// GL_OPERAND0_RGB to GL_OPERAND2_RGB.
    pub operand_rgb: [GLenum; 3],
    /// GL_OPERAND0_ALPHA to GL_OPERAND2_ALPHA.
    pub operand_alpha: [GLenum; 3],
    /// GL_RGB_SCALE.
    pub rgb_scale: f32,
    /// GL_ALPHA_SCALE.
    pub alpha_scale: f32,
}

impl Default for Combine {
    fn default() -> Combine {
        Combine {
            combine_rgb: GL_MODULATE,
            combine_alpha: GL_MODULATE,
            source_rgb: [GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT],
            source_alpha: [GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT],
            operand_rgb: [GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA],
            operand_alpha: [GL_SRC_ALPHA; 3],
            rgb_scale: 1.0,
            alpha_scale: 1.0,
        }
    }
}

/// One texture unit's environment (table 6.19) and its LOD bias (GL_TEXTURE_FILTER_CONTROL).
#[derive(Clone, Debug, PartialEq)]
pub struct TexEnv {
    /// GL_TEXTURE_ENV_MODE.
    pub mode: GLenum,
    /// Clamped to [0, 1] when set.
    pub color: [f32; 4],
    /// The combiner state (GL_COMBINE mode).
    pub combine: Combine,
    /// GL_TEXTURE_LOD_BIAS.
    pub lod_bias: f32,
}

impl Default for TexEnv {
    fn default() -> TexEnv {
        TexEnv {
            mode: GL_MODULATE,
            color: [0.0; 4],
            combine: Combine::default(),
            lod_bias: 0.0,
        }
    }
}

/// How many values a glTexEnv pname takes for `target` (the color four, the others one), or
/// None when the pair is none.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::texture::tex_env_count};
/// assert_eq!(tex_env_count(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR), Some(4));
/// assert_eq!(tex_env_count(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS), Some(1));
/// assert_eq!(tex_env_count(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE), None);
/// ```
pub fn tex_env_count(target: GLenum, pname: GLenum) -> Option<usize> {
    match (target, pname) {
        (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => Some(4),
        (GL_TEXTURE_ENV, p) if env_scalar(p) => Some(1),
        (GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS) => Some(1),
        _ => None,
    }
}

fn env_scalar(pname: GLenum) -> bool {
    matches!(
        pname,
        GL_TEXTURE_ENV_MODE
            | GL_COMBINE_RGB
            | GL_COMBINE_ALPHA
            | GL_SOURCE0_RGB
            | GL_SOURCE1_RGB
            | GL_SOURCE2_RGB
            | GL_SOURCE0_ALPHA
            | GL_SOURCE1_ALPHA
            | GL_SOURCE2_ALPHA
            | GL_OPERAND0_RGB
            | GL_OPERAND1_RGB
            | GL_OPERAND2_RGB
            | GL_OPERAND0_ALPHA
            | GL_OPERAND1_ALPHA
            | GL_OPERAND2_ALPHA
            | GL_RGB_SCALE
            | GL_ALPHA_SCALE
    )
}

/// A source of a combiner argument: GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS,
/// or GL_TEXTUREn of an existing unit.
fn combine_source(value: GLenum) -> GlResult<GLenum> {
    let units = GL_TEXTURE0..GL_TEXTURE0 + MAX_TEXTURE_UNITS as GLenum;
    if units.contains(&value) {
        return Ok(value);
    }
    one_of(
        value,
        &[GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS],
    )
}

const COMBINE_ALPHA: [GLenum; 6] = [
    GL_REPLACE,
    GL_MODULATE,
    GL_ADD,
    GL_ADD_SIGNED,
    GL_INTERPOLATE,
    GL_SUBTRACT,
];

impl TexEnv {
    /// glTexEnv (§3.8.13) with its values as floats (glTexEnvi's converted directly, the
    /// color already mapped to [0, 1]): Mesa's order, target, pname, then the value
    /// (GL_INVALID_ENUM, or GL_INVALID_VALUE for a scale other than 1, 2 or 4). The color is
    /// clamped to [0, 1]; the LOD bias is stored as given.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture::TexEnv};
    /// let mut env = TexEnv::default();
    /// env.set(GL_TEXTURE_ENV, GL_COMBINE_RGB, &[GL_DOT3_RGB as f32])?;
    /// assert_eq!(env.combine.combine_rgb, GL_DOT3_RGB);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(&mut self, target: GLenum, pname: GLenum, values: &[f32]) -> GlResult {
        if !matches!(target, GL_TEXTURE_ENV | GL_TEXTURE_FILTER_CONTROL) {
            return Err(GlError::InvalidEnum);
        }
        let count = tex_env_count(target, pname).ok_or(GlError::InvalidEnum)?;
        let values = values.get(..count).ok_or(GlError::InvalidValue)?;
        let value = enum_param(values[0]);
        let c = &mut self.combine;
        match pname {
            GL_TEXTURE_LOD_BIAS => self.lod_bias = values[0],
            GL_TEXTURE_ENV_COLOR => {
                self.color = std::array::from_fn(|i| values[i].clamp(0.0, 1.0));
            }
            GL_TEXTURE_ENV_MODE => {
                self.mode = one_of(
                    value,
                    &[
                        GL_MODULATE,
                        GL_DECAL,
                        GL_BLEND,
                        GL_REPLACE,
                        GL_ADD,
                        GL_COMBINE,
                    ],
                )?
            }
            GL_COMBINE_RGB => {
                c.combine_rgb = match value {
                    GL_DOT3_RGB | GL_DOT3_RGBA => value,
                    _ => one_of(value, &COMBINE_ALPHA)?,
                }
            }
            GL_COMBINE_ALPHA => c.combine_alpha = one_of(value, &COMBINE_ALPHA)?,
            GL_SOURCE0_RGB..=GL_SOURCE2_RGB => {
                c.source_rgb[(pname - GL_SOURCE0_RGB) as usize] = combine_source(value)?
            }
            GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA => {
                c.source_alpha[(pname - GL_SOURCE0_ALPHA) as usize] = combine_source(value)?
            }
            GL_OPERAND0_RGB..=GL_OPERAND2_RGB => {
                c.operand_rgb[(pname - GL_OPERAND0_RGB) as usize] = one_of(
                    value,
                    &[
                        GL_SRC_COLOR,
                        GL_ONE_MINUS_SRC_COLOR,
                        GL_SRC_ALPHA,
                        GL_ONE_MINUS_SRC_ALPHA,
                    ],
                )?
            }
            GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA => {
                c.operand_alpha[(pname - GL_OPERAND0_ALPHA) as usize] =
                    one_of(value, &[GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA])?
            }
            GL_RGB_SCALE | GL_ALPHA_SCALE => {
                let scale = values[0];
                if ![1.0, 2.0, 4.0].contains(&scale) {
                    return Err(GlError::InvalidValue);
                }
                if pname == GL_RGB_SCALE {
                    c.rgb_scale = scale;
                } else {
                    c.alpha_scale = scale;
                }
            }
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }

    /// glGetTexEnv's values: the color and the LOD bias and scales as floats (`true`), the
    /// others as enums.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture::TexEnv};
    /// let env = TexEnv::default();
    /// assert_eq!(env.get(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE)?, (vec![GL_MODULATE as f32], false)); // an enum
    /// assert_eq!(env.get(GL_TEXTURE_ENV, GL_RGB_SCALE)?, (vec![1.0], true)); // a float
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get(&self, target: GLenum, pname: GLenum) -> GlResult<(Vec<f32>, bool)> {
        if !matches!(target, GL_TEXTURE_ENV | GL_TEXTURE_FILTER_CONTROL) {
            return Err(GlError::InvalidEnum);
        }
        tex_env_count(target, pname).ok_or(GlError::InvalidEnum)?;
        let c = &self.combine;
        let enumeration = |e: GLenum| Ok((vec![e as f32], false));
        match pname {
            GL_TEXTURE_LOD_BIAS => Ok((vec![self.lod_bias], true)),
            GL_TEXTURE_ENV_COLOR => Ok((self.color.to_vec(), true)),
            GL_RGB_SCALE => Ok((vec![c.rgb_scale], true)),
            GL_ALPHA_SCALE => Ok((vec![c.alpha_scale], true)),
            GL_TEXTURE_ENV_MODE => enumeration(self.mode),
            GL_COMBINE_RGB => enumeration(c.combine_rgb),
            GL_COMBINE_ALPHA => enumeration(c.combine_alpha),
            GL_SOURCE0_RGB..=GL_SOURCE2_RGB => {
                enumeration(c.source_rgb[(pname - GL_SOURCE0_RGB) as usize])
            }
            GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA => {
                enumeration(c.source_alpha[(pname - GL_SOURCE0_ALPHA) as usize])
            }
            GL_OPERAND0_RGB..=GL_OPERAND2_RGB => {
                enumeration(c.operand_rgb[(pname - GL_OPERAND0_RGB) as usize])
            }
            _ => enumeration(c.operand_alpha[(pname - GL_OPERAND0_ALPHA) as usize]),
        }
    }
}

/// The state of one texture unit that is not in the texture objects (GL_TEXTURE_BIT, the
/// enables GL_ENABLE_BIT too): which targets are enabled, the object bound to each target,
/// the environment and texture coordinate generation. (The unit's current texture
/// coordinates are in `CurrentAttribs`, its texture matrix stack in `Matrices`.)
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TextureUnit {
    /// GL_TEXTURE_1D, _2D, _3D, _CUBE_MAP, in `Target` order.
    pub enabled: [bool; 4],
    /// The names bound, in `Target` order; 0 is the target's default object.
    pub bindings: [GLuint; 4],
    /// The texture environment.
    pub env: TexEnv,
    /// The texture coordinate generation state.
    pub tex_gen: crate::state::texgen::TexGen,
}

/// One texture object: its target (fixed by the first bind), parameters and images.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureObject {
    /// The target, fixed by the first bind.
    pub target: Target,
    /// glTexParameter's state.
    pub params: TextureParams,
    /// Images by (cube map face, or 0; level); a level absent here has width 0.
    pub images: BTreeMap<(usize, usize), TexImage>,
}

impl TextureObject {
    /// An object of `target` with the initial parameters and no image.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture::{Target, TextureObject}};
    /// let object = TextureObject::new(Target::Texture3D);
    /// assert!(object.images.is_empty());
    /// assert_eq!(object.params.wrap, [GL_REPEAT; 3]);
    /// ```
    pub fn new(target: Target) -> TextureObject {
        TextureObject {
            target,
            params: TextureParams::default(),
            images: BTreeMap::new(),
        }
    }
}

/// Every texture state of a context: the units, the active unit, the objects (the default
/// objects, name 0, one per target) and the proxy images.
#[derive(Clone, Debug, PartialEq)]
pub struct Textures {
    /// GL_ACTIVE_TEXTURE - GL_TEXTURE0.
    pub active_unit: usize,
    /// The texture units.
    pub units: [TextureUnit; MAX_TEXTURE_UNITS],
    /// The default objects, in `Target` order.
    pub defaults: [TextureObject; 4],
    objects: HashMap<GLuint, TextureObject>,
    /// Names glGenTextures returned that no bind has made objects yet.
    reserved: BTreeSet<GLuint>,
    /// The proxy images, by target and (face 0; level).
    pub proxies: [BTreeMap<(usize, usize), TexImage>; 4],
}

impl Default for Textures {
    fn default() -> Textures {
        Textures {
            active_unit: 0,
            units: Default::default(),
            defaults: Target::ALL.map(TextureObject::new),
            objects: HashMap::new(),
            reserved: BTreeSet::new(),
            proxies: Default::default(),
        }
    }
}

impl Textures {
    /// The active unit.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::Textures;
    /// assert_eq!(Textures::default().unit().bindings, [0; 4]);
    /// ```
    pub fn unit(&self) -> &TextureUnit {
        &self.units[self.active_unit]
    }

    /// The active unit, to change.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::Textures;
    /// let mut textures = Textures::default();
    /// textures.unit_mut().enabled[1] = true; // GL_TEXTURE_2D on the active unit
    /// assert!(textures.units[0].enabled[1]);
    /// ```
    pub fn unit_mut(&mut self) -> &mut TextureUnit {
        &mut self.units[self.active_unit]
    }

    /// glActiveTexture (§2.7): GL_INVALID_ENUM unless `texture` is GL_TEXTUREi of a unit.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture::Textures, GlError};
    /// let mut textures = Textures::default();
    /// textures.set_active(GL_TEXTURE7)?;
    /// assert_eq!(textures.active_unit, 7);
    /// assert_eq!(textures.set_active(GL_TEXTURE0 + 8), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set_active(&mut self, texture: GLenum) -> GlResult {
        let unit = texture.wrapping_sub(GL_TEXTURE0) as usize;
        if unit >= MAX_TEXTURE_UNITS {
            return Err(GlError::InvalidEnum);
        }
        self.active_unit = unit;
        Ok(())
    }

    /// glGenTextures.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::Textures;
    /// let mut textures = Textures::default();
    /// let names = textures.generate(2);
    /// assert!(names.iter().all(|&n| n > 0 && !textures.is_texture(n)));
    /// ```
    pub fn generate(&mut self, count: usize) -> Vec<GLuint> {
        super::names::generate(self.objects.keys().copied(), &mut self.reserved, count)
    }

    /// glIsTexture: whether `name` is an object (a name glGenTextures returned is not one
    /// until it is bound).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::{Target, Textures};
    /// let mut textures = Textures::default();
    /// textures.bind(Target::Texture2D, 4)?;
    /// assert!(textures.is_texture(4) && !textures.is_texture(0));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn is_texture(&self, name: GLuint) -> bool {
        self.objects.contains_key(&name)
    }

    /// glBindTexture (§3.8.12) on the active unit: binding an unused name creates its object
    /// with `target`; GL_INVALID_OPERATION for an object of another target.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{state::texture::{Target, Textures}, GlError};
    /// let mut textures = Textures::default();
    /// textures.bind(Target::CubeMap, 4)?;
    /// assert_eq!(textures.bind(Target::Texture1D, 4), Err(GlError::InvalidOperation));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn bind(&mut self, target: Target, name: GLuint) -> GlResult {
        if name != 0 {
            let object = self
                .objects
                .entry(name)
                .or_insert_with(|| TextureObject::new(target));
            if object.target != target {
                return Err(GlError::InvalidOperation);
            }
            self.reserved.remove(&name);
        }
        self.unit_mut().bindings[target as usize] = name;
        Ok(())
    }

    /// glDeleteTextures of one name: every unit's binding to it reverts to 0 (0 and unused
    /// names are ignored).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::{Target, Textures};
    /// let mut textures = Textures::default();
    /// textures.bind(Target::Texture2D, 4)?;
    /// textures.delete(4);
    /// assert_eq!(textures.unit().bindings[Target::Texture2D as usize], 0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn delete(&mut self, name: GLuint) {
        self.reserved.remove(&name);
        if name != 0 && self.objects.remove(&name).is_some() {
            for unit in &mut self.units {
                for binding in &mut unit.bindings {
                    if *binding == name {
                        *binding = 0;
                    }
                }
            }
        }
    }

    /// The object `name` if it exists (0: none, the defaults have no name).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::{Target, Textures};
    /// let mut textures = Textures::default();
    /// assert!(textures.object_mut(4).is_none());
    /// textures.bind(Target::Texture2D, 4)?;
    /// textures.object_mut(4).unwrap().params.priority = 0.5;
    /// assert_eq!(textures.bound(Target::Texture2D).params.priority, 0.5);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn object_mut(&mut self, name: GLuint) -> Option<&mut TextureObject> {
        self.objects.get_mut(&name).filter(|_| name != 0)
    }

    /// The object bound to `target` on the active unit.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::{Target, Textures};
    /// let textures = Textures::default();
    /// assert_eq!(textures.bound(Target::Texture3D).target, Target::Texture3D); // the default object
    /// ```
    pub fn bound(&self, target: Target) -> &TextureObject {
        let name = self.unit().bindings[target as usize];
        self.objects
            .get(&name)
            .unwrap_or(&self.defaults[target as usize])
    }

    /// The object bound to `target` on the active unit, to change.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::{Target, Textures};
    /// let mut textures = Textures::default();
    /// textures.bound_mut(Target::Texture1D).params.max_level = 3;
    /// assert_eq!(textures.defaults[Target::Texture1D as usize].params.max_level, 3);
    /// ```
    pub fn bound_mut(&mut self, target: Target) -> &mut TextureObject {
        let name = self.units[self.active_unit].bindings[target as usize];
        match self.objects.get_mut(&name) {
            Some(object) => object,
            None => &mut self.defaults[target as usize],
        }
    }
}

/// A unit's target enables and coordinate generation enables.
pub type UnitEnables = ([bool; 4], [bool; 4]);

/// GL_TEXTURE_BIT's texture state (tables 6.16-6.20): the active unit, each unit's enables,
/// bindings and environment, and the parameters of every object bound to a unit.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureAttribs {
    active_unit: usize,
    units: [TextureUnit; MAX_TEXTURE_UNITS],
    /// Each bound object's name (0: the default object), target and parameters.
    bound_params: Vec<(GLuint, Target, TextureParams)>,
}

impl Textures {
    /// The texture state glPushAttrib(GL_TEXTURE_BIT) saves.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::Textures;
    /// let mut textures = Textures::default();
    /// let saved = textures.attribs(); // glPushAttrib(GL_TEXTURE_BIT)
    /// textures.unit_mut().env.lod_bias = 1.0;
    /// textures.restore_attribs(saved); // glPopAttrib
    /// assert_eq!(textures.unit().env.lod_bias, 0.0);
    /// ```
    pub fn attribs(&self) -> TextureAttribs {
        let mut bound_params = Vec::new();
        for unit in &self.units {
            for target in Target::ALL {
                let name = unit.bindings[target as usize];
                let object = self
                    .objects
                    .get(&name)
                    .unwrap_or(&self.defaults[target as usize]);
                bound_params.push((name, target, object.params.clone()));
            }
        }
        TextureAttribs {
            active_unit: self.active_unit,
            units: self.units.clone(),
            bound_params,
        }
    }

    /// glPopAttrib(GL_TEXTURE_BIT): restores `saved`. An object deleted since the push stays
    /// deleted: its bindings revert to 0 as glDeleteTextures made them (§3.8.12).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::{Target, Textures};
    /// let mut textures = Textures::default();
    /// textures.bind(Target::Texture2D, 4)?;
    /// let saved = textures.attribs();
    /// textures.delete(4);
    /// textures.restore_attribs(saved);
    /// assert_eq!(textures.unit().bindings[Target::Texture2D as usize], 0); // stays deleted
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn restore_attribs(&mut self, saved: TextureAttribs) {
        self.active_unit = saved.active_unit;
        self.units = saved.units;
        for unit in &mut self.units {
            for binding in &mut unit.bindings {
                if !self.objects.contains_key(binding) {
                    *binding = 0;
                }
            }
        }
        for (name, target, params) in saved.bound_params {
            if name == 0 {
                self.defaults[target as usize].params = params;
            } else if let Some(object) = self.objects.get_mut(&name) {
                object.params = params;
            }
        }
    }

    /// Every unit's texture target and coordinate generation enables (GL_ENABLE_BIT saves
    /// all units').
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::Textures;
    /// let mut textures = Textures::default();
    /// textures.units[2].enabled[0] = true;
    /// assert_eq!(textures.enables()[2].0, [true, false, false, false]);
    /// ```
    pub fn enables(&self) -> [UnitEnables; MAX_TEXTURE_UNITS] {
        self.units
            .each_ref()
            .map(|unit| (unit.enabled, unit.tex_gen.coords.map(|c| c.enabled)))
    }

    /// Restores every unit's enables as `enables` gave them.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texture::Textures;
    /// let mut textures = Textures::default();
    /// let saved = textures.enables();
    /// textures.units[0].tex_gen.coords[1].enabled = true;
    /// textures.restore_enables(saved);
    /// assert!(!textures.units[0].tex_gen.coords[1].enabled);
    /// ```
    pub fn restore_enables(&mut self, enables: [UnitEnables; MAX_TEXTURE_UNITS]) {
        for (unit, (targets, generation)) in self.units.iter_mut().zip(enables) {
            unit.enabled = targets;
            for (coord, enabled) in unit.tex_gen.coords.iter_mut().zip(generation) {
                coord.enabled = enabled;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binding_creates_and_deleting_unbinds_on_every_unit() {
        let mut textures = Textures::default();
        let names = textures.generate(2);
        assert_eq!(names, vec![1, 2]);
        assert!(!textures.is_texture(1));
        textures.bind(Target::Texture2D, 1).unwrap();
        textures.set_active(GL_TEXTURE3).unwrap();
        textures.bind(Target::Texture2D, 1).unwrap();
        assert_eq!(
            textures.bind(Target::Texture1D, 1),
            Err(GlError::InvalidOperation)
        );
        assert!(textures.is_texture(1));
        textures.delete(1);
        assert_eq!(textures.units[0].bindings[1], 0);
        assert_eq!(textures.units[3].bindings[1], 0);
        assert!(!textures.is_texture(1));
        // 2 is still reserved: the next name is 3.
        assert_eq!(textures.generate(1), vec![3]);
    }

    #[test]
    fn parameters_are_checked_before_they_change() {
        let mut params = TextureParams::default();
        assert_eq!(
            params.set(GL_TEXTURE_MAG_FILTER, &[GL_NEAREST_MIPMAP_NEAREST as f32]),
            Err(GlError::InvalidEnum)
        );
        assert_eq!(
            params.set(GL_TEXTURE_MAX_LEVEL, &[-1.0]),
            Err(GlError::InvalidValue)
        );
        assert_eq!(params, TextureParams::default());
        params
            .set(GL_TEXTURE_BORDER_COLOR, &[2.0, -1.0, 0.5, 0.25])
            .unwrap();
        assert_eq!(params.border_color, [1.0, 0.0, 0.5, 0.25]);
        params.set(GL_TEXTURE_BASE_LEVEL, &[2.7]).unwrap();
        assert_eq!(params.base_level, 3);
    }

    #[test]
    fn environment_scales_and_sources() {
        let mut env = TexEnv::default();
        assert_eq!(
            env.set(GL_TEXTURE_ENV, GL_RGB_SCALE, &[3.0]),
            Err(GlError::InvalidValue)
        );
        assert_eq!(
            env.set(GL_TEXTURE_ENV, GL_SOURCE0_RGB, &[(GL_TEXTURE0 + 8) as f32]),
            Err(GlError::InvalidEnum)
        );
        env.set(GL_TEXTURE_ENV, GL_SOURCE0_RGB, &[GL_TEXTURE7 as f32])
            .unwrap();
        assert_eq!(env.combine.source_rgb[0], GL_TEXTURE7);
        assert_eq!(
            env.set(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, &[1.0]),
            Err(GlError::InvalidEnum)
        );
    }
}
