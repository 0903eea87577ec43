//! glLight, glMaterial, glLightModel, glColorMaterial and glEnable (§2.14).

use glam::Vec4;

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::convert::{color_to_int, float_to_int, int_to_color};
use crate::state::enables::Capability;
use crate::state::light::{is_light_color, light_index, light_param_count};
use crate::state::light_model::light_model_param_count;
use crate::state::material::{
    BACK, FRONT, MaterialMask, faces, is_material_color, material_param_count,
};

/// The first `count` values of `params` as a padded Vec4, or GL_INVALID_VALUE if too few
/// (a NULL pointer reaches here as an empty slice).
pub(crate) fn take_params(params: &[f32], count: usize) -> GlResult<Vec4> {
    if params.len() < count {
        return Err(GlError::InvalidValue);
    }
    let mut values = [0.0; 4];
    values[..count].copy_from_slice(&params[..count]);
    Ok(Vec4::from_array(values))
}

/// Integer params as floats: colors by the signed linear mapping, others directly.
fn ints_to_floats(params: &[i32], count: usize, is_color: bool) -> GlResult<Vec4> {
    if params.len() < count {
        return Err(GlError::InvalidValue);
    }
    let mut values = [0.0; 4];
    for (value, &param) in values.iter_mut().zip(&params[..count]) {
        *value = if is_color {
            int_to_color(param)
        } else {
            param as f32
        };
    }
    Ok(Vec4::from_array(values))
}

/// Values of a glGet*iv: colors by the linear mapping, other float state rounded.
pub(crate) fn floats_to_ints(values: Vec4, is_color: bool) -> [i32; 4] {
    values.to_array().map(|v| {
        if is_color {
            color_to_int(v)
        } else {
            float_to_int(v)
        }
    })
}

/// Whether a pname names a single value: the only ones the scalar forms (glLightf ...) accept.
fn require_scalar(count: usize) -> GlResult {
    if count == 1 {
        Ok(())
    } else {
        Err(GlError::InvalidEnum)
    }
}

impl Context {
    /// glLightfv (§2.14.1): positions and spot directions go through the current modelview.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.light(GL_LIGHT1, GL_DIFFUSE, &[1.0, 0.5, 0.25, 1.0])?;
    /// assert_eq!(ctx.get_light(GL_LIGHT1, GL_DIFFUSE)?.0.to_array(), [1.0, 0.5, 0.25, 1.0]);
    /// // Positions are taken into eye coordinates by the current modelview matrix.
    /// ctx.translate(0.0, 0.0, -5.0)?;
    /// ctx.light(GL_LIGHT1, GL_POSITION, &[0.0, 0.0, 0.0, 1.0])?;
    /// assert_eq!(ctx.get_light(GL_LIGHT1, GL_POSITION)?.0.to_array(), [0.0, 0.0, -5.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn light(&mut self, light: GLenum, pname: GLenum, params: &[f32]) -> GlResult {
        self.outside_begin_end()?;
        let index = light_index(light)?;
        let count = light_param_count(pname).ok_or(GlError::InvalidEnum)?;
        let values = take_params(params, count)?;
        self.store_light(index, pname, values)
    }

    /// glLightiv: colors map linearly from the signed integer range, the rest converts directly.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// // Integer colors map [-2^31, 2^31 - 1] linearly to [-1, 1] (table 2.9).
    /// ctx.light_i(GL_LIGHT0, GL_AMBIENT, &[i32::MAX, i32::MIN, 0, i32::MAX])?;
    /// let ambient = ctx.get_light(GL_LIGHT0, GL_AMBIENT)?.0;
    /// assert_eq!((ambient.x, ambient.y, ambient.w), (1.0, -1.0, 1.0));
    /// assert!(ambient.z.abs() < 1e-9);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn light_i(&mut self, light: GLenum, pname: GLenum, params: &[i32]) -> GlResult {
        self.outside_begin_end()?;
        let index = light_index(light)?;
        let count = light_param_count(pname).ok_or(GlError::InvalidEnum)?;
        let values = ints_to_floats(params, count, is_light_color(pname))?;
        self.store_light(index, pname, values)
    }

    /// glLightf / glLighti: single-valued parameters only.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.light_scalar(GL_LIGHT0, GL_SPOT_CUTOFF, 45.0)?;
    /// assert_eq!(ctx.get_light(GL_LIGHT0, GL_SPOT_CUTOFF)?, (glam::Vec4::new(45.0, 0.0, 0.0, 0.0), 1));
    /// // A cutoff outside [0, 90] other than 180 is an error, the value unchanged.
    /// assert_eq!(ctx.light_scalar(GL_LIGHT0, GL_SPOT_CUTOFF, 100.0), Err(GlError::InvalidValue));
    /// // A vector parameter is not a scalar one.
    /// assert_eq!(ctx.light_scalar(GL_LIGHT0, GL_POSITION, 1.0), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn light_scalar(&mut self, light: GLenum, pname: GLenum, param: f32) -> GlResult {
        self.outside_begin_end()?;
        let index = light_index(light)?;
        require_scalar(light_param_count(pname).ok_or(GlError::InvalidEnum)?)?;
        self.store_light(index, pname, Vec4::new(param, 0.0, 0.0, 0.0))
    }

    fn store_light(&mut self, index: usize, pname: GLenum, values: Vec4) -> GlResult {
        let modelview = *self.matrices.modelview.top();
        self.lights[index].set(pname, values, &modelview)?;
        self.invalidate();
        Ok(())
    }

    /// glGetLightfv: the values and how many of them the pname defines.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// // GL_LIGHT0's specular color is white, the other lights' black; 4 values.
    /// assert_eq!(ctx.get_light(GL_LIGHT0, GL_SPECULAR)?, (glam::Vec4::ONE, 4));
    /// assert_eq!(ctx.get_light(GL_LIGHT1, GL_SPECULAR)?.0, glam::Vec4::new(0.0, 0.0, 0.0, 1.0));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_light(&self, light: GLenum, pname: GLenum) -> GlResult<(Vec4, usize)> {
        self.outside_begin_end()?;
        let index = light_index(light)?;
        let count = light_param_count(pname).ok_or(GlError::InvalidEnum)?;
        Ok((self.lights[index].get(pname)?, count))
    }

    /// glGetLightiv.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// let (values, count) = ctx.get_light_i(GL_LIGHT0, GL_DIFFUSE)?;
    /// assert_eq!((values, count), ([i32::MAX; 4], 4));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_light_i(&self, light: GLenum, pname: GLenum) -> GlResult<([i32; 4], usize)> {
        let (values, count) = self.get_light(light, pname)?;
        Ok((floats_to_ints(values, is_light_color(pname)), count))
    }

    /// glMaterialfv (§2.14.1), legal between glBegin and glEnd. Properties that an enabled
    /// color material tracks are left alone, as Mesa does.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.material(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.2, 0.4, 0.6, 1.0])?;
    /// assert_eq!(ctx.get_material(GL_BACK, GL_DIFFUSE)?.0.to_array(), [0.2, 0.4, 0.6, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn material(&mut self, face: GLenum, pname: GLenum, params: &[f32]) -> GlResult {
        let faces = faces(face)?;
        let count = material_param_count(pname).ok_or(GlError::InvalidEnum)?;
        let values = take_params(params, count)?;
        self.store_material(faces, pname, values)
    }

    /// glMaterialiv.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.material_i(GL_FRONT, GL_SHININESS, &[64])?;
    /// assert_eq!(ctx.get_material(GL_FRONT, GL_SHININESS)?, (glam::Vec4::new(64.0, 0.0, 0.0, 0.0), 1));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn material_i(&mut self, face: GLenum, pname: GLenum, params: &[i32]) -> GlResult {
        let faces = faces(face)?;
        let count = material_param_count(pname).ok_or(GlError::InvalidEnum)?;
        let values = ints_to_floats(params, count, is_material_color(pname))?;
        self.store_material(faces, pname, values)
    }

    /// glMaterialf / glMateriali: GL_SHININESS only.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.material_scalar(GL_FRONT, GL_SHININESS, 32.0)?;
    /// assert_eq!(ctx.material_scalar(GL_FRONT, GL_SHININESS, 200.0), Err(GlError::InvalidValue));
    /// assert_eq!(ctx.get_material(GL_FRONT, GL_SHININESS)?.0.x, 32.0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn material_scalar(&mut self, face: GLenum, pname: GLenum, param: f32) -> GlResult {
        let faces = faces(face)?;
        require_scalar(material_param_count(pname).ok_or(GlError::InvalidEnum)?)?;
        self.store_material(faces, pname, Vec4::new(param, 0.0, 0.0, 0.0))
    }

    fn store_material(&mut self, faces: [bool; 2], pname: GLenum, values: Vec4) -> GlResult {
        let mask = MaterialMask::of_pname(pname)?;
        if pname == GL_SHININESS && !(0.0..=128.0).contains(&values.x) {
            return Err(GlError::InvalidValue);
        }
        // Vertices given before this glMaterial are lit with the material they were given
        // with.
        self.flush_vertices();
        let tracked = self.color_material.tracked();
        for face in [FRONT, BACK] {
            if faces[face] {
                self.materials[face].set(mask.without(tracked[face]), values);
            }
        }
        self.invalidate();
        Ok(())
    }

    /// glGetMaterialfv: GL_FRONT or GL_BACK only.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_material(GL_FRONT, GL_AMBIENT)?.0, glam::Vec4::new(0.2, 0.2, 0.2, 1.0));
    /// // A query names one face.
    /// assert_eq!(ctx.get_material(GL_FRONT_AND_BACK, GL_AMBIENT), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_material(&self, face: GLenum, pname: GLenum) -> GlResult<(Vec4, usize)> {
        self.outside_begin_end()?;
        let face = match face {
            GL_FRONT => FRONT,
            GL_BACK => BACK,
            _ => return Err(GlError::InvalidEnum),
        };
        if pname == GL_AMBIENT_AND_DIFFUSE {
            return Err(GlError::InvalidEnum);
        }
        let count = material_param_count(pname).ok_or(GlError::InvalidEnum)?;
        Ok((self.materials[face].get(pname)?, count))
    }

    /// glGetMaterialiv.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.material(GL_FRONT, GL_EMISSION, &[1.0, 0.0, 0.0, 1.0])?;
    /// assert_eq!(ctx.get_material_i(GL_FRONT, GL_EMISSION)?.0, [i32::MAX, 0, 0, i32::MAX]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_material_i(&self, face: GLenum, pname: GLenum) -> GlResult<([i32; 4], usize)> {
        let (values, count) = self.get_material(face, pname)?;
        Ok((floats_to_ints(values, is_material_color(pname)), count))
    }

    /// glLightModelfv.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.light_model(GL_LIGHT_MODEL_AMBIENT, &[0.1, 0.1, 0.1, 1.0])?;
    /// ctx.light_model(GL_LIGHT_MODEL_LOCAL_VIEWER, &[1.0])?;
    /// assert!(ctx.derived().lighting.local_viewer);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn light_model(&mut self, pname: GLenum, params: &[f32]) -> GlResult {
        self.outside_begin_end()?;
        let count = light_model_param_count(pname).ok_or(GlError::InvalidEnum)?;
        let values = take_params(params, count)?;
        self.store_light_model(pname, values)
    }

    /// glLightModeliv: the ambient color maps linearly, the rest converts directly.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.light_model_i(GL_LIGHT_MODEL_COLOR_CONTROL, &[GL_SEPARATE_SPECULAR_COLOR as i32])?;
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn light_model_i(&mut self, pname: GLenum, params: &[i32]) -> GlResult {
        self.outside_begin_end()?;
        let count = light_model_param_count(pname).ok_or(GlError::InvalidEnum)?;
        let values = ints_to_floats(params, count, pname == GL_LIGHT_MODEL_AMBIENT)?;
        self.store_light_model(pname, values)
    }

    /// glLightModelf / glLightModeli: single-valued parameters only.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.light_model_scalar(GL_LIGHT_MODEL_TWO_SIDE, 1.0)?;
    /// // GL_LIGHT_MODEL_AMBIENT has four values: not a scalar parameter.
    /// assert_eq!(ctx.light_model_scalar(GL_LIGHT_MODEL_AMBIENT, 0.5), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn light_model_scalar(&mut self, pname: GLenum, param: f32) -> GlResult {
        self.outside_begin_end()?;
        require_scalar(light_model_param_count(pname).ok_or(GlError::InvalidEnum)?)?;
        self.store_light_model(pname, Vec4::new(param, 0.0, 0.0, 0.0))
    }

    fn store_light_model(&mut self, pname: GLenum, values: Vec4) -> GlResult {
        self.light_model.set(pname, values)?;
        self.invalidate();
        Ok(())
    }

    /// glColorMaterial (§2.14.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.color_material(GL_FRONT, GL_DIFFUSE)?;
    /// ctx.set_capability(GL_COLOR_MATERIAL, true)?;
    /// assert_eq!(ctx.color_material(GL_FRONT, GL_SHININESS), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn color_material(&mut self, face: GLenum, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        faces(face)?;
        MaterialMask::of_color_material_mode(mode)?;
        self.color_material.face = face;
        self.color_material.mode = mode;
        self.apply_color_material();
        self.invalidate();
        Ok(())
    }

    /// glEnable / glDisable.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.set_capability(GL_LIGHT7, true)?;
    /// assert!(ctx.is_enabled(GL_LIGHT7)?);
    /// assert_eq!(ctx.set_capability(GL_LIGHT0 + 8, true), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set_capability(&mut self, cap: GLenum, enabled: bool) -> GlResult {
        self.outside_begin_end()?;
        if self.arrays.is_enabled(cap).is_some() {
            // Client-state arrays, which Mesa accepts here as glEnableClientState.
            return self.client_state(cap, enabled);
        }
        self.store_capability(cap, enabled)?;
        if cap == GL_COLOR_MATERIAL {
            self.apply_color_material();
        }
        Ok(())
    }

    /// Stores a server capability's enable flag, with no other effect (glPopAttrib restores
    /// flags this way): GL_INVALID_ENUM for a name that is none.
    pub(crate) fn store_capability(&mut self, cap: GLenum, enabled: bool) -> GlResult {
        if let Some(flag) = self.group_flag_mut(cap) {
            // Rasterization and per-fragment state: nothing derived depends on it.
            *flag = enabled;
            return Ok(());
        }
        match Capability::of(cap)? {
            Capability::Lighting => self.enables.lighting = enabled,
            Capability::Light(i) => self.lights[i].enabled = enabled,
            Capability::Normalize => self.enables.normalize = enabled,
            Capability::RescaleNormal => self.enables.rescale_normal = enabled,
            Capability::ColorMaterial => self.color_material.enabled = enabled,
            Capability::CullFace => self.enables.cull_face = enabled,
            Capability::ClipPlane(i) => self.enables.clip_planes[i] = enabled,
            Capability::TexGen(i) => self.textures.unit_mut().tex_gen.coords[i].enabled = enabled,
            Capability::Map(dimensions, kind) => {
                self.eval.enabled[dimensions - 1][kind] = enabled;
                return Ok(());
            }
            Capability::Other(cap) => self.enables.set_other(cap, enabled),
        }
        self.invalidate();
        Ok(())
    }

    /// glIsEnabled.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// assert!(!ctx.is_enabled(GL_NORMALIZE)?);
    /// ctx.set_capability(GL_NORMALIZE, true)?;
    /// assert!(ctx.is_enabled(GL_NORMALIZE)?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn is_enabled(&self, cap: GLenum) -> GlResult<bool> {
        self.outside_begin_end()?;
        if let Some(enabled) = self.arrays.is_enabled(cap) {
            return Ok(enabled);
        }
        if let Some(enabled) = self.group_flag(cap) {
            return Ok(enabled);
        }
        Ok(match Capability::of(cap)? {
            Capability::Lighting => self.enables.lighting,
            Capability::Light(i) => self.lights[i].enabled,
            Capability::Normalize => self.enables.normalize,
            Capability::RescaleNormal => self.enables.rescale_normal,
            Capability::ColorMaterial => self.color_material.enabled,
            Capability::CullFace => self.enables.cull_face,
            Capability::ClipPlane(i) => self.enables.clip_planes[i],
            Capability::TexGen(i) => self.textures.unit().tex_gen.coords[i].enabled,
            Capability::Map(dimensions, kind) => self.eval.enabled[dimensions - 1][kind],
            Capability::Other(cap) => self.enables.other(cap),
        })
    }
}
