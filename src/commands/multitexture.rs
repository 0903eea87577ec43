//! Texture coordinate generation (§2.11.4) and the multitexture commands of GL 1.3 (§2.7,
//! §2.8): glTexGen, glGetTexGen, glMultiTexCoord, glClientActiveTexture.

use glam::Vec4;

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::convert::Component;
use crate::state::texgen::coord_index;
use crate::state::texture::MAX_TEXTURE_UNITS;

/// The unit glMultiTexCoord's `target` names: GL_INVALID_ENUM unless GL_TEXTUREi of a unit.
fn unit_of(target: GLenum) -> GlResult<usize> {
    let unit = target.wrapping_sub(GL_TEXTURE0) as usize;
    if unit < MAX_TEXTURE_UNITS {
        Ok(unit)
    } else {
        Err(GlError::InvalidEnum)
    }
}

impl Context {
    /// glTexGen{ifd}v (§2.11.4) on the active texture unit: Mesa's order of checks (the
    /// coordinate, the pname, the values). An eye plane is taken into eye coordinates by the
    /// inverse of the current modelview matrix.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.tex_gen(GL_S, GL_TEXTURE_GEN_MODE, &[GL_SPHERE_MAP as f64])?;
    /// assert_eq!(ctx.get_tex_gen(GL_S, GL_TEXTURE_GEN_MODE)?, [GL_SPHERE_MAP as f64]);
    /// // The sphere map gives s and t only.
    /// assert_eq!(ctx.tex_gen(GL_R, GL_TEXTURE_GEN_MODE, &[GL_SPHERE_MAP as f64]), Err(GlError::InvalidEnum));
    /// ctx.tex_gen(GL_T, GL_OBJECT_PLANE, &[0i32, 1, 0, 0])?; // glTexGeniv
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_gen<T: Into<f64> + Copy>(
        &mut self,
        coord: GLenum,
        pname: GLenum,
        params: &[T],
    ) -> GlResult {
        self.outside_begin_end()?;
        let coord = coord_index(coord)?;
        let params: Vec<f64> = params.iter().map(|&v| v.into()).collect();
        let modelview = self.matrices.modelview.top().as_dmat4();
        self.textures
            .unit_mut()
            .tex_gen
            .set(coord, pname, &params, &modelview)?;
        self.invalidate();
        Ok(())
    }

    /// glTexGen{ifd}: the scalar form takes GL_TEXTURE_GEN_MODE only.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.tex_gen_scalar(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR as f64)?;
    /// assert_eq!(ctx.tex_gen_scalar(GL_Q, GL_EYE_PLANE, 1.0), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_gen_scalar(&mut self, coord: GLenum, pname: GLenum, param: f64) -> GlResult {
        self.outside_begin_end()?;
        coord_index(coord)?;
        if pname != GL_TEXTURE_GEN_MODE {
            return Err(GlError::InvalidEnum);
        }
        self.tex_gen(coord, pname, &[param])
    }

    /// glGetTexGen{ifd}v on the active texture unit.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_tex_gen(GL_S, GL_OBJECT_PLANE)?, [1.0, 0.0, 0.0, 0.0]);
    /// assert_eq!(ctx.get_tex_gen(GL_T, GL_EYE_PLANE)?, [0.0, 1.0, 0.0, 0.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_tex_gen(&self, coord: GLenum, pname: GLenum) -> GlResult<Vec<f64>> {
        self.outside_begin_end()?;
        self.textures.unit().tex_gen.get(coord_index(coord)?, pname)
    }

    /// glGetTexGeniv: plane coefficients rounded to the nearest integer (§6.1.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.tex_gen(GL_S, GL_OBJECT_PLANE, &[0.4f64, 0.6, -1.5, 2.0])?;
    /// assert_eq!(ctx.get_tex_gen_i(GL_S, GL_OBJECT_PLANE)?, [0, 1, -2, 2]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_tex_gen_i(&self, coord: GLenum, pname: GLenum) -> GlResult<Vec<GLint>> {
        let values = self.get_tex_gen(coord, pname)?;
        Ok(values.into_iter().map(|v| v.round() as GLint).collect())
    }

    /// glMultiTexCoord (§2.7): texture unit `target`'s current texture coordinates, missing
    /// components (0, 0, 1) as glTexCoord's. Allowed between glBegin and glEnd.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.multi_tex_coord(GL_TEXTURE0, glam::Vec4::new(0.5, 0.25, 0.0, 1.0))?;
    /// assert_eq!(ctx.get(GL_CURRENT_TEXTURE_COORDS)?.as_floats(), [0.5, 0.25, 0.0, 1.0]);
    /// assert_eq!(ctx.multi_tex_coord(GL_TEXTURE0 + 8, glam::Vec4::W), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn multi_tex_coord(&mut self, target: GLenum, tex_coord: Vec4) -> GlResult {
        let unit = unit_of(target)?;
        self.current.set_unit_tex_coord(unit, tex_coord);
        if unit == 0 {
            self.varying
                .insert(crate::commands::vertex::Varying::TEX_COORD);
        }
        Ok(())
    }

    /// glMultiTexCoord{1234}{sifd}: `N` components converted directly.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.multi_tex_coord_of(GL_TEXTURE0, [3i16, 4])?; // glMultiTexCoord2s
    /// assert_eq!(ctx.get(GL_CURRENT_TEXTURE_COORDS)?.as_floats(), [3.0, 4.0, 0.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn multi_tex_coord_of<T: Component, const N: usize>(
        &mut self,
        target: GLenum,
        components: [T; N],
    ) -> GlResult {
        let mut tex_coord = [0.0, 0.0, 0.0, 1.0];
        for (to, from) in tex_coord.iter_mut().zip(components) {
            *to = from.direct();
        }
        self.multi_tex_coord(target, Vec4::from_array(tex_coord))
    }

    /// glMultiTexCoord{1234}{sifd}v: GL_INVALID_VALUE for a NULL (empty) vector.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.multi_tex_coord_v::<f64, 1>(GL_TEXTURE0, &[0.75])?; // glMultiTexCoord1dv
    /// assert_eq!(ctx.get(GL_CURRENT_TEXTURE_COORDS)?.as_floats(), [0.75, 0.0, 0.0, 1.0]);
    /// assert_eq!(ctx.multi_tex_coord_v::<f64, 3>(GL_TEXTURE0, &[]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn multi_tex_coord_v<T: Component, const N: usize>(
        &mut self,
        target: GLenum,
        v: &[T],
    ) -> GlResult {
        let components: [T; N] = v.try_into().map_err(|_| GlError::InvalidValue)?;
        self.multi_tex_coord_of(target, components)
    }

    /// glClientActiveTexture (§2.8).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.client_active_texture(GL_TEXTURE2)?;
    /// assert_eq!(ctx.get(GL_CLIENT_ACTIVE_TEXTURE)?.as_ints(), [GL_TEXTURE2 as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn client_active_texture(&mut self, texture: GLenum) -> GlResult {
        self.arrays.set_client_active_texture(texture)
    }
}
