//! Viewport, depth range, user clip planes and the polygon state primitive assembly reads
//! (§2.11.1, §2.12, §2.14.7, §3.5).

use glam::{DVec4, Vec4};

use super::enables::MAX_CLIP_PLANES;
use crate::gl::*;
use crate::lighting::lanes::LANES;
use crate::pipeline::block::Lanes4;

/// The transformation, clipping and polygon state primitive assembly reads.
#[derive(Clone, Debug, PartialEq)]
pub struct RasterState {
    /// x, y, width, height.
    pub viewport: [i32; 4],
    /// near, far, clamped to [0, 1].
    pub depth_range: [f64; 2],
    /// Eye-space plane equations (§2.12), transformed when specified.
    pub clip_planes: [DVec4; MAX_CLIP_PLANES],
    /// GL_SHADE_MODEL.
    pub shade_model: GLenum,
    /// GL_FRONT_FACE.
    pub front_face: GLenum,
    /// GL_CULL_FACE_MODE.
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::raster::RasterState;
    /// use glam::Vec4;
    /// let mut raster = RasterState::default();
    /// raster.viewport = [0, 0, 200, 100];
    /// assert_eq!(raster.window(Vec4::new(1.0, -1.0, 0.0, 2.0)), Vec4::new(150.0, 25.0, 0.5, 2.0));
    /// ```
    pub fn window(&self, clip: Vec4) -> Vec4 {
        Vec4::from_array(self.viewport_map().window(clip.to_array()))
    }

    /// The viewport transform's constants, for mapping many points.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::raster::RasterState;
    /// let mut raster = RasterState::default();
    /// raster.viewport = [10, 0, 100, 100];
    /// assert_eq!(raster.viewport_map().window([0.0, 0.0, 0.0, 1.0]), [60.0, 50.0, 0.5, 1.0]);
    /// ```
    pub fn viewport_map(&self) -> ViewportMap {
        let [x, y, width, height] = self.viewport;
        let [near, far] = self.depth_range;
        let half_width = width as f32 / 2.0;
        let half_height = height as f32 / 2.0;
        ViewportMap {
            half_width,
            x_center: x as f32 + half_width,
            half_height,
            y_center: y as f32 + half_height,
            depth_range: far - near,
            depth_center: (near + far) / 2.0,
        }
    }
}

/// The viewport transform (§2.11.1) with its constants computed once.
#[derive(Clone, Copy, Debug)]
pub struct ViewportMap {
    half_width: f32,
    x_center: f32,
    half_height: f32,
    y_center: f32,
    depth_range: f64,
    depth_center: f64,
}

impl ViewportMap {
    /// `window` of every lane of a block of clip-space points.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::raster::RasterState;
    /// let mut raster = RasterState::default();
    /// raster.viewport = [0, 0, 100, 100];
    /// let map = raster.viewport_map();
    /// let lanes = [[0.0f32; 8], [0.0; 8], [0.0; 8], [1.0; 8]];
    /// assert_eq!(map.window_lanes(&lanes)[0], [50.0; 8]);
    /// ```
    #[inline(always)]
    pub fn window_lanes(&self, [x, y, z, w]: &Lanes4) -> Lanes4 {
        let mut out = [[0.0; LANES]; 4];
        for lane in 0..LANES {
            let window = self.window([x[lane], y[lane], z[lane], w[lane]]);
            for (component, value) in out.iter_mut().zip(window) {
                component[lane] = value;
            }
        }
        out
    }

    /// Window x, y, z and the clip w of the clip-space point `[x, y, z, w]`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::raster::RasterState;
    /// let mut raster = RasterState::default();
    /// raster.viewport = [0, 0, 100, 100];
    /// raster.depth_range = [0.5, 1.0];
    /// assert_eq!(raster.viewport_map().window([1.0, 1.0, -1.0, 1.0]), [100.0, 100.0, 0.5, 1.0]);
    /// ```
    #[inline(always)]
    pub fn window(&self, [x, y, z, w]: [f32; 4]) -> [f32; 4] {
        let (x, y, z) = (x / w, y / w, z / w);
        [
            x * self.half_width + self.x_center,
            y * self.half_height + self.y_center,
            (z as f64 * self.depth_range / 2.0 + self.depth_center) as f32,
            w,
        ]
    }
}
