//! Material state (§2.14.1, table 2.11) and color material tracking (§2.14.3).

use glam::Vec4;

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// Index of the front and back material in `[Material; 2]`.
pub const FRONT: usize = 0;
/// Index of the back material.
pub const BACK: usize = 1;

/// The material of one face.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// GL_AMBIENT.
    pub ambient: Vec4,
    /// GL_DIFFUSE.
    pub diffuse: Vec4,
    /// GL_SPECULAR.
    pub specular: Vec4,
    /// GL_EMISSION.
    pub emission: Vec4,
    /// GL_SHININESS.
    pub shininess: f32,
    /// GL_COLOR_INDEXES: ambient, diffuse and specular indexes (stored for queries only).
    pub color_indexes: [f32; 3],
}

impl Default for Material {
    fn default() -> Material {
        Material {
            ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            diffuse: Vec4::new(0.8, 0.8, 0.8, 1.0),
            specular: Vec4::W,
            emission: Vec4::W,
            shininess: 0.0,
            color_indexes: [0.0, 1.0, 1.0],
        }
    }
}

/// A set of material properties, as bits: which properties a glMaterial or color material touches.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MaterialMask(pub u8);

impl MaterialMask {
    /// No property.
    pub const NONE: MaterialMask = MaterialMask(0);
    /// GL_AMBIENT.
    pub const AMBIENT: MaterialMask = MaterialMask(1);
    /// GL_DIFFUSE.
    pub const DIFFUSE: MaterialMask = MaterialMask(2);
    /// GL_SPECULAR.
    pub const SPECULAR: MaterialMask = MaterialMask(4);
    /// GL_EMISSION.
    pub const EMISSION: MaterialMask = MaterialMask(8);
    /// GL_SHININESS.
    pub const SHININESS: MaterialMask = MaterialMask(16);
    /// GL_COLOR_INDEXES.
    pub const COLOR_INDEXES: MaterialMask = MaterialMask(32);

    /// Whether every property of `other` is in the set (never for the empty set).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::material::MaterialMask;
    /// let both = MaterialMask::AMBIENT.union(MaterialMask::DIFFUSE);
    /// assert!(both.contains(MaterialMask::DIFFUSE));
    /// assert!(!both.contains(MaterialMask::SPECULAR));
    /// assert!(!both.contains(MaterialMask::NONE));
    /// ```
    pub fn contains(self, other: MaterialMask) -> bool {
        self.0 & other.0 == other.0 && other.0 != 0
    }

    /// The properties of both sets.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::material::MaterialMask;
    /// assert_eq!(MaterialMask::AMBIENT.union(MaterialMask::DIFFUSE), MaterialMask(3));
    /// ```
    pub fn union(self, other: MaterialMask) -> MaterialMask {
        MaterialMask(self.0 | other.0)
    }

    /// The properties of `self` that are not in `other`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::material::MaterialMask;
    /// let both = MaterialMask::AMBIENT.union(MaterialMask::DIFFUSE);
    /// assert_eq!(both.without(MaterialMask::AMBIENT), MaterialMask::DIFFUSE);
    /// ```
    pub fn without(self, other: MaterialMask) -> MaterialMask {
        MaterialMask(self.0 & !other.0)
    }

    /// The properties a glMaterial pname sets, or GL_INVALID_ENUM.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::material::MaterialMask};
    /// let both = MaterialMask::AMBIENT.union(MaterialMask::DIFFUSE);
    /// assert_eq!(MaterialMask::of_pname(GL_AMBIENT_AND_DIFFUSE)?, both);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn of_pname(pname: GLenum) -> GlResult<MaterialMask> {
        Ok(match pname {
            GL_AMBIENT => Self::AMBIENT,
            GL_DIFFUSE => Self::DIFFUSE,
            GL_SPECULAR => Self::SPECULAR,
            GL_EMISSION => Self::EMISSION,
            GL_SHININESS => Self::SHININESS,
            GL_AMBIENT_AND_DIFFUSE => Self::AMBIENT.union(Self::DIFFUSE),
            GL_COLOR_INDEXES => Self::COLOR_INDEXES,
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// The properties a glColorMaterial mode tracks, or GL_INVALID_ENUM.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::material::MaterialMask, GlError};
    /// assert_eq!(MaterialMask::of_color_material_mode(GL_EMISSION)?, MaterialMask::EMISSION);
    /// assert_eq!(MaterialMask::of_color_material_mode(GL_SHININESS), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn of_color_material_mode(mode: GLenum) -> GlResult<MaterialMask> {
        match mode {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => {
                Self::of_pname(mode)
            }
            _ => Err(GlError::InvalidEnum),
        }
    }
}

/// The faces a GL_FRONT / GL_BACK / GL_FRONT_AND_BACK argument names, as `[front, back]`.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::material::faces, GlError};
/// assert_eq!(faces(GL_FRONT_AND_BACK)?, [true, true]);
/// assert_eq!(faces(GL_BACK)?, [false, true]);
/// assert_eq!(faces(GL_LEFT), Err(GlError::InvalidEnum));
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn faces(face: GLenum) -> GlResult<[bool; 2]> {
    match face {
        GL_FRONT => Ok([true, false]),
        GL_BACK => Ok([false, true]),
        GL_FRONT_AND_BACK => Ok([true, true]),
        _ => Err(GlError::InvalidEnum),
    }
}

/// How many values a glMaterial / glGetMaterial pname takes, or `None` for a bad pname.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::material::material_param_count};
/// assert_eq!(material_param_count(GL_SHININESS), Some(1));
/// assert_eq!(material_param_count(GL_COLOR_INDEXES), Some(3));
/// ```
pub fn material_param_count(pname: GLenum) -> Option<usize> {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => Some(4),
        GL_SHININESS => Some(1),
        GL_COLOR_INDEXES => Some(3),
        _ => None,
    }
}

/// Whether `pname` is a color, converted with the signed-integer color mapping in glMaterialiv.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::material::is_material_color};
/// assert!(is_material_color(GL_EMISSION) && !is_material_color(GL_SHININESS));
/// ```
pub fn is_material_color(pname: GLenum) -> bool {
    matches!(
        pname,
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE
    )
}

impl Material {
    /// Stores the properties of `mask` from `params` (validated by the caller).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::material::{Material, MaterialMask};
    /// use glam::Vec4;
    /// let mut material = Material::default();
    /// let red = Vec4::new(1.0, 0.0, 0.0, 1.0);
    /// material.set(MaterialMask::AMBIENT.union(MaterialMask::DIFFUSE), red);
    /// assert_eq!((material.ambient, material.diffuse), (red, red));
    /// ```
    pub fn set(&mut self, mask: MaterialMask, params: Vec4) {
        if mask.contains(MaterialMask::AMBIENT) {
            self.ambient = params;
        }
        if mask.contains(MaterialMask::DIFFUSE) {
            self.diffuse = params;
        }
        if mask.contains(MaterialMask::SPECULAR) {
            self.specular = params;
        }
        if mask.contains(MaterialMask::EMISSION) {
            self.emission = params;
        }
        if mask.contains(MaterialMask::SHININESS) {
            self.shininess = params.x;
        }
        if mask.contains(MaterialMask::COLOR_INDEXES) {
            self.color_indexes = [params.x, params.y, params.z];
        }
    }

    /// glGetMaterialfv: the stored value, padded to four.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::material::Material};
    /// assert_eq!(Material::default().get(GL_DIFFUSE)?, glam::Vec4::new(0.8, 0.8, 0.8, 1.0));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get(&self, pname: GLenum) -> GlResult<Vec4> {
        Ok(match pname {
            GL_AMBIENT => self.ambient,
            GL_DIFFUSE => self.diffuse,
            GL_SPECULAR => self.specular,
            GL_EMISSION => self.emission,
            GL_SHININESS => Vec4::new(self.shininess, 0.0, 0.0, 0.0),
            GL_COLOR_INDEXES => Vec4::new(
                self.color_indexes[0],
                self.color_indexes[1],
                self.color_indexes[2],
                0.0,
            ),
            _ => return Err(GlError::InvalidEnum),
        })
    }
}

/// glColorMaterial state (§2.14.3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColorMaterial {
    /// GL_COLOR_MATERIAL.
    pub enabled: bool,
    /// GL_COLOR_MATERIAL_FACE.
    pub face: GLenum,
    /// GL_COLOR_MATERIAL_PARAMETER.
    pub mode: GLenum,
}

impl Default for ColorMaterial {
    fn default() -> ColorMaterial {
        ColorMaterial {
            enabled: false,
            face: GL_FRONT_AND_BACK,
            mode: GL_AMBIENT_AND_DIFFUSE,
        }
    }
}

impl ColorMaterial {
    /// The properties of each face that follow the current color: none while disabled.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::material::{ColorMaterial, MaterialMask}};
    /// let mut color_material = ColorMaterial::default();
    /// assert_eq!(color_material.tracked(), [MaterialMask::NONE; 2]); // disabled
    /// color_material.enabled = true;
    /// color_material.face = GL_FRONT;
    /// let both = MaterialMask::AMBIENT.union(MaterialMask::DIFFUSE);
    /// assert_eq!(color_material.tracked(), [both, MaterialMask::NONE]);
    /// ```
    pub fn tracked(&self) -> [MaterialMask; 2] {
        if !self.enabled {
            return [MaterialMask::NONE; 2];
        }
        // face and mode were validated when stored.
        let mask = MaterialMask::of_color_material_mode(self.mode).unwrap_or_default();
        let [front, back] = faces(self.face).unwrap_or([false, false]);
        [
            if front { mask } else { MaterialMask::NONE },
            if back { mask } else { MaterialMask::NONE },
        ]
    }
}
