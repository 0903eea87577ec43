//! glEnable / glDisable capabilities (§2.14, §2.11, table 6.x).

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// GL_MAX_CLIP_PLANES.
pub const MAX_CLIP_PLANES: usize = 6;

/// GL 1.5 capabilities fflight accepts and reports but that do not affect vertex processing
/// (rasterization and per-fragment state): glEnable stores them so glIsEnabled answers.
const OTHER_CAPABILITIES: &[GLenum] = &[
    GL_ALPHA_TEST,
    GL_AUTO_NORMAL,
    GL_BLEND,
    GL_COLOR_LOGIC_OP,
    GL_COLOR_SUM,
    GL_DEPTH_TEST,
    GL_DITHER,
    GL_FOG,
    GL_INDEX_LOGIC_OP,
    GL_LINE_SMOOTH,
    GL_LINE_STIPPLE,
    GL_MULTISAMPLE,
    GL_POINT_SMOOTH,
    GL_POLYGON_OFFSET_FILL,
    GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_POINT,
    GL_POLYGON_SMOOTH,
    GL_POLYGON_STIPPLE,
    GL_SCISSOR_TEST,
    GL_STENCIL_TEST,
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T,
    GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_Q,
];

/// The enable flags.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Enables {
    pub lighting: bool,
    pub normalize: bool,
    pub rescale_normal: bool,
    pub cull_face: bool,
    pub clip_planes: [bool; MAX_CLIP_PLANES],
    /// OTHER_CAPABILITIES that are enabled (GL_DITHER starts enabled, see `Enables::initial`).
    other: Vec<GLenum>,
}

/// What a capability names, for the context to route glEnable to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Capability {
    Lighting,
    Light(usize),
    Normalize,
    RescaleNormal,
    ColorMaterial,
    CullFace,
    ClipPlane(usize),
    Other(GLenum),
}

impl Capability {
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
            _ if OTHER_CAPABILITIES.contains(&cap) => Capability::Other(cap),
            _ => return Err(GlError::InvalidEnum),
        })
    }
}

impl Enables {
    pub fn initial() -> Enables {
        Enables {
            other: vec![GL_DITHER], // enabled initially (§4.1.6)
            ..Enables::default()
        }
    }

    pub fn other(&self, cap: GLenum) -> bool {
        self.other.contains(&cap)
    }

    pub fn set_other(&mut self, cap: GLenum, enabled: bool) {
        self.other.retain(|&c| c != cap);
        if enabled {
            self.other.push(cap);
        }
    }
}
