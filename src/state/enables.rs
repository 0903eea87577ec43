//! glEnable / glDisable capabilities (§2.14, §2.11, table 6.x).

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// GL_MAX_CLIP_PLANES.
pub const MAX_CLIP_PLANES: usize = 6;

/// GL 1.5 capabilities fflight accepts and reports but that do not affect vertex processing
/// (rasterization and per-fragment state): glEnable stores them so glIsEnabled answers.
const OTHER_CAPABILITIES: &[GLenum] = &[
    0x0BC0, // GL_ALPHA_TEST
    0x0D80, // GL_AUTO_NORMAL
    0x0BE2, // GL_BLEND
    0x0BF2, // GL_COLOR_LOGIC_OP
    0x8458, // GL_COLOR_SUM
    0x0B71, // GL_DEPTH_TEST
    0x0BD0, // GL_DITHER
    0x0B60, // GL_FOG
    0x0BF1, // GL_INDEX_LOGIC_OP
    0x0B20, // GL_LINE_SMOOTH
    0x0B24, // GL_LINE_STIPPLE
    0x809D, // GL_MULTISAMPLE
    0x0B10, // GL_POINT_SMOOTH
    0x8037, // GL_POLYGON_OFFSET_FILL
    0x2A02, // GL_POLYGON_OFFSET_LINE
    0x2A01, // GL_POLYGON_OFFSET_POINT
    0x0B41, // GL_POLYGON_SMOOTH
    0x0B42, // GL_POLYGON_STIPPLE
    0x0C11, // GL_SCISSOR_TEST
    0x0B90, // GL_STENCIL_TEST
    0x0DE0, // GL_TEXTURE_1D
    0x0DE1, // GL_TEXTURE_2D
    0x806F, // GL_TEXTURE_3D
    0x8513, // GL_TEXTURE_CUBE_MAP
    0x0C60, // GL_TEXTURE_GEN_S
    0x0C61, // GL_TEXTURE_GEN_T
    0x0C62, // GL_TEXTURE_GEN_R
    0x0C63, // GL_TEXTURE_GEN_Q
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
            other: vec![0x0BD0], // GL_DITHER is enabled initially
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
