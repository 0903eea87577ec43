//! Viewport, depth range, user clip planes and the polygon state primitive assembly reads
//! (§2.11.1, §2.12, §2.14.7, §3.5).

use glam::{DVec4, Vec4};

use super::enables::MAX_CLIP_PLANES;
use crate::gl::*;

#[derive(Clone, Debug, PartialEq)]
pub struct RasterState {
    /// x, y, width, height.
    pub viewport: [i32; 4],
    /// near, far, clamped to [0, 1].
    pub depth_range: [f64; 2],
    /// Eye-space plane equations (§2.12), transformed when specified.
    pub clip_planes: [DVec4; MAX_CLIP_PLANES],
    pub shade_model: GLenum,
    pub front_face: GLenum,
    pub cull_face_mode: GLenum,
    /// Front and back polygon modes.
    pub polygon_mode: [GLenum; 2],
}

impl Default for RasterState {
    fn default() -> RasterState {
        RasterState {
            viewport: [0, 0, 0, 0],
            depth_range: [0.0, 1.0],
            clip_planes: [DVec4::ZERO; MAX_CLIP_PLANES],
            shade_model: GL_SMOOTH,
            front_face: GL_CCW,
            cull_face_mode: GL_BACK,
            polygon_mode: [GL_FILL, GL_FILL],
        }
    }
}

/// GL_MAX_VIEWPORT_DIMS.
pub const MAX_VIEWPORT_DIMS: i32 = 16384;

impl RasterState {
    /// The viewport transform (§2.11.1) of a clip-space point: window x, y, z and the clip w.
    pub fn window(&self, clip: Vec4) -> Vec4 {
        let [x, y, width, height] = self.viewport;
        let [near, far] = self.depth_range;
        let ndc = clip.truncate() / clip.w;
        let half_width = width as f32 / 2.0;
        let half_height = height as f32 / 2.0;
        Vec4::new(
            ndc.x * half_width + (x as f32 + half_width),
            ndc.y * half_height + (y as f32 + half_height),
            (ndc.z as f64 * (far - near) / 2.0 + (near + far) / 2.0) as f32,
            clip.w,
        )
    }
}
