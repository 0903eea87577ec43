//! Matrix commands (§2.11.2).

use glam::{DMat4, DVec3, Mat4};

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::matrix::{frustum, ortho, rotation};

impl Context {
    /// glMatrixMode.
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
    pub fn load_identity(&mut self) -> GlResult {
        self.update_matrix(|top| *top = Mat4::IDENTITY)
    }

    /// Runs a matrix command on the 16 values of glLoadMatrix, glMultMatrix and their
    /// transpose forms, doubles narrowed to floats as GL keeps matrices. Between glBegin and
    /// glEnd the command itself is the error, values or not (§2.6.3); no values (NULL) is
    /// GL_INVALID_VALUE.
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
    pub fn load_matrix(&mut self, m: &[f32; 16]) -> GlResult {
        self.update_matrix(|top| *top = Mat4::from_cols_array(m))
    }

    /// glMultMatrixf: the current matrix times `m` (column-major).
    pub fn mult_matrix(&mut self, m: &[f32; 16]) -> GlResult {
        self.update_matrix(|top| *top *= Mat4::from_cols_array(m))
    }

    /// glLoadTransposeMatrixf: `m` in row-major order.
    pub fn load_transpose_matrix(&mut self, m: &[f32; 16]) -> GlResult {
        self.update_matrix(|top| *top = Mat4::from_cols_array(m).transpose())
    }

    /// glMultTransposeMatrixf.
    pub fn mult_transpose_matrix(&mut self, m: &[f32; 16]) -> GlResult {
        self.update_matrix(|top| *top *= Mat4::from_cols_array(m).transpose())
    }

    /// glTranslate.
    pub fn translate(&mut self, x: f64, y: f64, z: f64) -> GlResult {
        self.multiply_matrix(DMat4::from_translation(DVec3::new(x, y, z)))
    }

    /// glScale.
    pub fn scale(&mut self, x: f64, y: f64, z: f64) -> GlResult {
        self.multiply_matrix(DMat4::from_scale(DVec3::new(x, y, z)))
    }

    /// glRotate: `angle` degrees about (x, y, z).
    pub fn rotate(&mut self, angle: f64, x: f64, y: f64, z: f64) -> GlResult {
        self.multiply_matrix(rotation(angle, x, y, z))
    }

    /// glFrustum.
    pub fn frustum(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult {
        self.outside_begin_end()?;
        self.multiply_matrix(frustum(l, r, b, t, n, f)?)
    }

    /// glOrtho.
    pub fn ortho(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult {
        self.outside_begin_end()?;
        self.multiply_matrix(ortho(l, r, b, t, n, f)?)
    }

    /// glPushMatrix.
    pub fn push_matrix(&mut self) -> GlResult {
        self.outside_begin_end()?;
        self.matrices.current_mut(self.textures.active_unit).push()
    }

    /// glPopMatrix.
    pub fn pop_matrix(&mut self) -> GlResult {
        self.outside_begin_end()?;
        self.matrices.current_mut(self.textures.active_unit).pop()?;
        self.invalidate();
        Ok(())
    }
}
