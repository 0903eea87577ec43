//! glEnable / glDisable capabilities (§2.14, §2.11, table 6.x).

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// GL_MAX_CLIP_PLANES.
pub const MAX_CLIP_PLANES: usize = 6;

// The rasterization and per-fragment capabilities live in their attribute groups (see
// `Context::group_flag`).

/// GL_AUTO_NORMAL, kept in `Enables` (GL_EVAL_BIT's; the maps' enables are in `EvalAttribs`).
pub const EVAL_CAPABILITIES: &[GLenum] = &[GL_AUTO_NORMAL];
/// Texture coordinate generation's (GL_TEXTURE_BIT's); the texture target enables are per
/// texture unit (`TextureUnit::enabled`).
pub const TEXTURE_CAPABILITIES: &[GLenum] = &[
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T,
    GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_Q,
];

/// The enable flags.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Enables {
    /// GL_LIGHTING.
    pub lighting: bool,
    /// GL_NORMALIZE.
    pub normalize: bool,
    /// GL_RESCALE_NORMAL.
    pub rescale_normal: bool,
    /// GL_CULL_FACE.
    pub cull_face: bool,
    /// GL_CLIP_PLANE0 to GL_CLIP_PLANE5.
    pub clip_planes: [bool; MAX_CLIP_PLANES],
    /// EVAL_CAPABILITIES that are enabled (all start disabled).
    other: Vec<GLenum>,
}

/// What a capability names, for the context to route glEnable to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Capability {
    /// GL_LIGHTING.
    Lighting,
    /// GL_LIGHT0 to GL_LIGHT7, by number.
    Light(usize),
    /// GL_NORMALIZE.
    Normalize,
    /// GL_RESCALE_NORMAL.
    RescaleNormal,
    /// GL_COLOR_MATERIAL.
    ColorMaterial,
    /// GL_CULL_FACE.
    CullFace,
    /// GL_CLIP_PLANE0 to GL_CLIP_PLANE5, by number.
    ClipPlane(usize),
    /// GL_TEXTURE_GEN_S to _Q of the active texture unit.
    TexGen(usize),
    /// GL_MAP1_* (dimension 1) and GL_MAP2_* (2) evaluator maps, by kind.
    Map(usize, usize),
    /// A capability of `EVAL_CAPABILITIES` kept in `Enables::other`.
    Other(GLenum),
}

impl Capability {
    /// What `cap` names, or GL_INVALID_ENUM for no capability this module routes (the fragment, fog and texture enables are routed by the context before).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::enables::Capability, GlError};
    /// assert_eq!(Capability::of(GL_LIGHT2), Ok(Capability::Light(2)));
    /// assert_eq!(Capability::of(GL_MAP2_VERTEX_4), Ok(Capability::Map(2, 8)));
    /// assert_eq!(Capability::of(GL_LIGHT0 + 8), Err(GlError::InvalidEnum));
    /// ```
    pub fn of(cap: GLenum) -> GlResult<Capability> {
        Ok(match cap {
            GL_LIGHTING => Capability::Lighting,
            GL_LIGHT0..=GL_LIGHT7 => Capability::Light((cap - GL_LIGHT0) as usize),
            GL_NORMALIZE => Capability::Normalize,
            GL_RESCALE_NORMAL => Capability::RescaleNormal,
            GL_COLOR_MATERIAL => Capability::ColorMaterial,
            GL_CULL_FACE => Capability::CullFace,
            GL_CLIP_PLANE0..=GL_CLIP_PLANE5 => {
                Capability::ClipPlane((cap - GL_CLIP_PLANE0) as usize)
            }
            GL_TEXTURE_GEN_S..=GL_TEXTURE_GEN_Q => {
                Capability::TexGen((cap - GL_TEXTURE_GEN_S) as usize)
            }
            GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4 => {
                Capability::Map(1, (cap - GL_MAP1_COLOR_4) as usize)
            }
            GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4 => {
                Capability::Map(2, (cap - GL_MAP2_COLOR_4) as usize)
            }
            _ if EVAL_CAPABILITIES.contains(&cap) => Capability::Other(cap),
            _ => return Err(GlError::InvalidEnum),
        })
    }
}

impl Enables {
    /// The initial enables: all off.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::enables::Enables;
    /// let enables = Enables::initial();
    /// assert!(!enables.lighting && !enables.normalize && enables.clip_planes == [false; 6]);
    /// ```
    pub fn initial() -> Enables {
        Enables {
            other: Vec::new(),
            ..Enables::default()
        }
    }

    /// Whether `cap` (one of `EVAL_CAPABILITIES`) is enabled.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::enables::Enables};
    /// assert!(!Enables::initial().other(GL_AUTO_NORMAL));
    /// ```
    pub fn other(&self, cap: GLenum) -> bool {
        self.other.contains(&cap)
    }

    /// Enables or disables `cap` (one of `EVAL_CAPABILITIES`).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::enables::Enables};
    /// let mut enables = Enables::initial();
    /// enables.set_other(GL_AUTO_NORMAL, true);
    /// assert!(enables.other(GL_AUTO_NORMAL));
    /// ```
    pub fn set_other(&mut self, cap: GLenum, enabled: bool) {
        self.other.retain(|&c| c != cap);
        if enabled {
            self.other.push(cap);
        }
    }
}
