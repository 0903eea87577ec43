//! Clip planes, shading, facing, culling and polygon modes (§2.12, §2.14.7, §3.5).

use glam::{DVec4, Vec4};

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::enables::MAX_CLIP_PLANES;
use crate::state::material::faces;

fn clip_plane_index(plane: GLenum) -> GlResult<usize> {
    let index = plane.wrapping_sub(GL_CLIP_PLANE0) as usize;
    if index < MAX_CLIP_PLANES {
        Ok(index)
    } else {
        Err(GlError::InvalidEnum)
    }
}

impl Context {
    /// glClipPlane: the equation is transformed to eye coordinates by the inverse of the
    /// current modelview matrix (§2.12).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.translate(0.0, 0.0, -5.0)?;
    /// ctx.clip_plane(GL_CLIP_PLANE0, [0.0, 0.0, 1.0, 0.0])?; // z >= 0 in object coordinates
    /// // In eye coordinates: z >= -5.
    /// assert_eq!(ctx.get_clip_plane(GL_CLIP_PLANE0)?, [0.0, 0.0, 1.0, 5.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn clip_plane(&mut self, plane: GLenum, equation: [f64; 4]) -> GlResult {
        self.outside_begin_end()?;
        let index = clip_plane_index(plane)?;
        let inverse = self.matrices.modelview.top().as_dmat4().inverse();
        // The plane is a row vector: p_eye = p * M^-1.
        self.raster.clip_planes[index] = inverse.transpose() * DVec4::from_array(equation);
        Ok(())
    }

    /// glGetClipPlane: the eye-space equation.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_clip_plane(GL_CLIP_PLANE5)?, [0.0; 4]);
    /// assert_eq!(ctx.get_clip_plane(GL_CLIP_PLANE0 + 6), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_clip_plane(&self, plane: GLenum) -> GlResult<[f64; 4]> {
        self.outside_begin_end()?;
        Ok(self.raster.clip_planes[clip_plane_index(plane)?].to_array())
    }

    /// glShadeModel.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.shade_model(GL_FLAT)?;
    /// assert_eq!(ctx.get(GL_SHADE_MODEL)?.as_ints(), [GL_FLAT as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn shade_model(&mut self, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        if !matches!(mode, GL_FLAT | GL_SMOOTH) {
            return Err(GlError::InvalidEnum);
        }
        self.raster.shade_model = mode;
        Ok(())
    }

    /// glFrontFace.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.front_face(GL_CW)?;
    /// assert_eq!(ctx.get(GL_FRONT_FACE)?.as_ints(), [GL_CW as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn front_face(&mut self, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        if !matches!(mode, GL_CW | GL_CCW) {
            return Err(GlError::InvalidEnum);
        }
        self.raster.front_face = mode;
        Ok(())
    }

    /// glCullFace.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.cull_face(GL_FRONT_AND_BACK)?;
    /// assert_eq!(ctx.get(GL_CULL_FACE_MODE)?.as_ints(), [GL_FRONT_AND_BACK as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn cull_face(&mut self, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        faces(mode)?;
        self.raster.cull_face_mode = mode;
        Ok(())
    }

    /// glPolygonMode.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.polygon_mode(GL_BACK, GL_LINE)?;
    /// assert_eq!(ctx.get(GL_POLYGON_MODE)?.as_ints(), [GL_FILL as i32, GL_LINE as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn polygon_mode(&mut self, face: GLenum, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        let [front, back] = faces(face)?;
        if !matches!(mode, GL_POINT | GL_LINE | GL_FILL) {
            return Err(GlError::InvalidEnum);
        }
        if front {
            self.raster.polygon_mode[0] = mode;
        }
        if back {
            self.raster.polygon_mode[1] = mode;
        }
        Ok(())
    }

    /// glRect{s,i,f,d}v: two corners of two values each; fewer values (a NULL pointer) is
    /// GL_INVALID_VALUE.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.capture_begin()?;
    /// ctx.rect_v(&[0i32, 0], &[2, 1])?; // glRectiv
    /// ctx.capture_end()?;
    /// assert_eq!(ctx.captured().vertices().len(), 4);
    /// assert_eq!(ctx.rect_v::<f32>(&[], &[1.0, 1.0]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn rect_v<T: Copy + Into<f64>>(&mut self, v1: &[T], v2: &[T]) -> GlResult {
        match (v1, v2) {
            ([x1, y1, ..], [x2, y2, ..]) => {
                let [x1, y1, x2, y2] = [*x1, *y1, *x2, *y2].map(|v| v.into() as f32);
                self.rect(x1, y1, x2, y2)
            }
            _ => Err(GlError::InvalidValue),
        }
    }

    /// glRect (§2.9): a GL_POLYGON of the four corners at z = 0, counterclockwise.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.capture_begin()?;
    /// ctx.rect(0.0, 0.0, 1.0, 1.0)?;
    /// ctx.capture_end()?;
    /// let primitives = ctx.captured().primitives();
    /// assert_eq!(primitives.len(), 2); // a polygon of four corners: two triangles
    /// assert!(primitives.iter().all(|p| p.mode == GL_POLYGON));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn rect(&mut self, x1: f32, y1: f32, x2: f32, y2: f32) -> GlResult {
        self.begin(GL_POLYGON)?;
        for (x, y) in [(x1, y1), (x2, y1), (x2, y2), (x1, y2)] {
            self.vertex(Vec4::new(x, y, 0.0, 1.0));
        }
        self.end()
    }
}
