//! Matrix commands (§2.11.2).

use glam::{DMat4, DVec3, Mat4};

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::matrix::{frustum, ortho, rotation};

impl Context {
    /// glMatrixMode.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.matrix_mode(GL_PROJECTION)?;
    /// assert_eq!(ctx.get(GL_MATRIX_MODE)?.as_ints(), [GL_PROJECTION as i32]);
    /// assert_eq!(ctx.matrix_mode(GL_LIGHT0), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn matrix_mode(&mut self, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        self.matrices.set_mode(mode)
    }

    fn update_matrix(&mut self, update: impl FnOnce(&mut Mat4)) -> GlResult {
        self.outside_begin_end()?;
        update(
            self.matrices
                .current_mut(self.textures.active_unit)
                .top_mut(),
        );
        self.invalidate();
        Ok(())
    }

    fn multiply_matrix(&mut self, m: DMat4) -> GlResult {
        self.update_matrix(|top| *top *= m.as_mat4())
    }

    /// glLoadIdentity.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.scale(2.0, 2.0, 2.0)?;
    /// ctx.load_identity()?;
    /// assert_eq!(ctx.get(GL_MODELVIEW_MATRIX)?.as_floats(), glam::Mat4::IDENTITY.to_cols_array());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn load_identity(&mut self) -> GlResult {
        self.update_matrix(|top| *top = Mat4::IDENTITY)
    }

    /// Runs a matrix command on the 16 values of glLoadMatrix, glMultMatrix and their
    /// transpose forms, doubles narrowed to floats as GL keeps matrices. Between glBegin and
    /// glEnd the command itself is the error, values or not (§2.6.3); no values (NULL) is
    /// GL_INVALID_VALUE.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// // glLoadMatrixd: doubles narrowed to floats, then loaded.
    /// let m: [f64; 16] = glam::DMat4::from_translation(glam::DVec3::new(1.0, 2.0, 3.0)).to_cols_array();
    /// ctx.matrix_values(&m, Context::load_matrix)?;
    /// assert_eq!(ctx.get(GL_MODELVIEW_MATRIX)?.as_floats()[12..15], [1.0, 2.0, 3.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn matrix_values<T: Copy + Into<f64>>(
        &mut self,
        m: &[T],
        command: fn(&mut Context, &[f32; 16]) -> GlResult,
    ) -> GlResult {
        self.outside_begin_end()?;
        if m.len() < 16 {
            return Err(GlError::InvalidValue);
        }
        let matrix: [f32; 16] = std::array::from_fn(|i| m[i].into() as f32);
        command(self, &matrix)
    }

    /// glLoadMatrixf: `m` in GL's column-major order.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let m = glam::Mat4::from_scale(glam::Vec3::splat(3.0)).to_cols_array(); // column-major, as GL
    /// ctx.load_matrix(&m)?;
    /// assert_eq!(ctx.get(GL_MODELVIEW_MATRIX)?.as_floats(), m);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn load_matrix(&mut self, m: &[f32; 16]) -> GlResult {
        self.update_matrix(|top| *top = Mat4::from_cols_array(m))
    }

    /// glMultMatrixf: the current matrix times `m` (column-major).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.translate(1.0, 0.0, 0.0)?;
    /// ctx.mult_matrix(&glam::Mat4::from_scale(glam::Vec3::splat(2.0)).to_cols_array())?;
    /// let expected = glam::Mat4::from_translation(glam::Vec3::X) * glam::Mat4::from_scale(glam::Vec3::splat(2.0));
    /// assert_eq!(ctx.get(GL_MODELVIEW_MATRIX)?.as_floats(), expected.to_cols_array());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn mult_matrix(&mut self, m: &[f32; 16]) -> GlResult {
        self.update_matrix(|top| *top *= Mat4::from_cols_array(m))
    }

    /// glLoadTransposeMatrixf: `m` in row-major order.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let translation = glam::Mat4::from_translation(glam::Vec3::new(4.0, 5.0, 6.0));
    /// ctx.load_transpose_matrix(&translation.transpose().to_cols_array())?; // row-major
    /// assert_eq!(ctx.get(GL_MODELVIEW_MATRIX)?.as_floats(), translation.to_cols_array());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn load_transpose_matrix(&mut self, m: &[f32; 16]) -> GlResult {
        self.update_matrix(|top| *top = Mat4::from_cols_array(m).transpose())
    }

    /// glMultTransposeMatrixf.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let translation = glam::Mat4::from_translation(glam::Vec3::new(4.0, 5.0, 6.0));
    /// ctx.mult_transpose_matrix(&translation.transpose().to_cols_array())?;
    /// assert_eq!(ctx.get(GL_TRANSPOSE_MODELVIEW_MATRIX)?.as_floats(), translation.transpose().to_cols_array());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn mult_transpose_matrix(&mut self, m: &[f32; 16]) -> GlResult {
        self.update_matrix(|top| *top *= Mat4::from_cols_array(m).transpose())
    }

    /// glTranslate.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.translate(0.0, 0.0, -5.0)?;
    /// assert_eq!(ctx.get(GL_MODELVIEW_MATRIX)?.as_floats()[14], -5.0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn translate(&mut self, x: f64, y: f64, z: f64) -> GlResult {
        self.multiply_matrix(DMat4::from_translation(DVec3::new(x, y, z)))
    }

    /// glScale.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.scale(1.0, 2.0, 3.0)?;
    /// let m = ctx.get(GL_MODELVIEW_MATRIX)?.as_floats();
    /// assert_eq!((m[0], m[5], m[10]), (1.0, 2.0, 3.0));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn scale(&mut self, x: f64, y: f64, z: f64) -> GlResult {
        self.multiply_matrix(DMat4::from_scale(DVec3::new(x, y, z)))
    }

    /// glRotate: `angle` degrees about (x, y, z).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.rotate(90.0, 0.0, 0.0, 1.0)?; // degrees, about +z: x goes to y
    /// let m = ctx.get(GL_MODELVIEW_MATRIX)?.as_floats();
    /// assert!((m[1] - 1.0).abs() < 1e-6 && m[0].abs() < 1e-6);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn rotate(&mut self, angle: f64, x: f64, y: f64, z: f64) -> GlResult {
        self.multiply_matrix(rotation(angle, x, y, z))
    }

    /// glFrustum.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.matrix_mode(GL_PROJECTION)?;
    /// ctx.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0)?;
    /// assert_eq!(ctx.get(GL_PROJECTION_MATRIX)?.as_floats()[11], -1.0);
    /// assert_eq!(ctx.frustum(-1.0, 1.0, -1.0, 1.0, 0.0, 10.0), Err(GlError::InvalidValue)); // near 0
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn frustum(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult {
        self.outside_begin_end()?;
        self.multiply_matrix(frustum(l, r, b, t, n, f)?)
    }

    /// glOrtho.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.matrix_mode(GL_PROJECTION)?;
    /// ctx.ortho(0.0, 200.0, 0.0, 100.0, -1.0, 1.0)?;
    /// let m = ctx.get(GL_PROJECTION_MATRIX)?.as_floats();
    /// assert_eq!((m[0], m[5], m[12], m[13]), (0.01, 0.02, -1.0, -1.0));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn ortho(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult {
        self.outside_begin_end()?;
        self.multiply_matrix(ortho(l, r, b, t, n, f)?)
    }

    /// glPushMatrix.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.push_matrix()?;
    /// ctx.translate(1.0, 0.0, 0.0)?;
    /// assert_eq!(ctx.get(GL_MODELVIEW_STACK_DEPTH)?.as_ints(), [2]);
    /// ctx.pop_matrix()?;
    /// assert_eq!(ctx.get(GL_MODELVIEW_MATRIX)?.as_floats(), glam::Mat4::IDENTITY.to_cols_array());
    /// for _ in 1..32 {
    ///     ctx.push_matrix()?;
    /// }
    /// assert_eq!(ctx.push_matrix(), Err(GlError::StackOverflow)); // depth 32
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn push_matrix(&mut self) -> GlResult {
        self.outside_begin_end()?;
        self.matrices.current_mut(self.textures.active_unit).push()
    }

    /// glPopMatrix.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.pop_matrix(), Err(GlError::StackUnderflow));
    /// ```
    pub fn pop_matrix(&mut self) -> GlResult {
        self.outside_begin_end()?;
        self.matrices.current_mut(self.textures.active_unit).pop()?;
        self.invalidate();
        Ok(())
    }
}
