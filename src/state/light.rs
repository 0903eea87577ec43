//! Light source state (§2.14.1, table 2.10): one `Light` per GL_LIGHTi.

use glam::{Mat4, Vec3, Vec4};

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// GL_MAX_LIGHTS.
pub const MAX_LIGHTS: usize = 8;

/// One light source. Position and spot direction are stored in eye coordinates,
/// transformed by the modelview matrix in force when they were specified.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// GL_LIGHTi enabled.
    pub enabled: bool,
    /// GL_AMBIENT.
    pub ambient: Vec4,
    /// GL_DIFFUSE.
    pub diffuse: Vec4,
    /// GL_SPECULAR.
    pub specular: Vec4,
    /// GL_POSITION, in eye coordinates (taken through the modelview matrix when set).
    pub eye_position: Vec4,
    /// GL_SPOT_DIRECTION, in eye coordinates (through the modelview's upper 3x3 when set).
    pub eye_spot_direction: Vec3,
    /// GL_SPOT_EXPONENT.
    pub spot_exponent: f32,
    /// GL_SPOT_CUTOFF, in degrees.
    pub spot_cutoff: f32,
    /// GL_CONSTANT_ATTENUATION.
    pub constant_attenuation: f32,
    /// GL_LINEAR_ATTENUATION.
    pub linear_attenuation: f32,
    /// GL_QUADRATIC_ATTENUATION.
    pub quadratic_attenuation: f32,
}

impl Light {
    /// The initial state of light `index`: light 0 is white, the others black.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::light::Light;
    /// use glam::Vec4;
    /// assert_eq!(Light::initial(0).diffuse, Vec4::ONE);
    /// assert_eq!(Light::initial(1).diffuse, Vec4::new(0.0, 0.0, 0.0, 1.0));
    /// assert_eq!(Light::initial(3).spot_cutoff, 180.0);
    /// ```
    pub fn initial(index: usize) -> Light {
        let white_if_first = if index == 0 { Vec4::ONE } else { Vec4::W };
        Light {
            enabled: false,
            ambient: Vec4::W,
            diffuse: white_if_first,
            specular: white_if_first,
            eye_position: Vec4::new(0.0, 0.0, 1.0, 0.0),
            eye_spot_direction: Vec3::new(0.0, 0.0, -1.0),
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            constant_attenuation: 1.0,
            linear_attenuation: 0.0,
            quadratic_attenuation: 0.0,
        }
    }
}

/// The index of GL_LIGHTi, or GL_INVALID_ENUM.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::light::light_index, GlError};
/// assert_eq!(light_index(GL_LIGHT3), Ok(3));
/// assert_eq!(light_index(GL_LIGHTING), Err(GlError::InvalidEnum));
/// ```
pub fn light_index(light: GLenum) -> GlResult<usize> {
    let index = light.wrapping_sub(GL_LIGHT0) as usize;
    if index < MAX_LIGHTS {
        Ok(index)
    } else {
        Err(GlError::InvalidEnum)
    }
}

/// How many values `pname` takes in glLight / glGetLight, or `None` when it is not a light parameter.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::light::light_param_count};
/// assert_eq!(light_param_count(GL_SPOT_DIRECTION), Some(3));
/// assert_eq!(light_param_count(GL_QUADRATIC_ATTENUATION), Some(1));
/// assert_eq!(light_param_count(GL_SHININESS), None); // a material parameter
/// ```
pub fn light_param_count(pname: GLenum) -> Option<usize> {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => Some(4),
        GL_SPOT_DIRECTION => Some(3),
        GL_SPOT_EXPONENT
        | GL_SPOT_CUTOFF
        | GL_CONSTANT_ATTENUATION
        | GL_LINEAR_ATTENUATION
        | GL_QUADRATIC_ATTENUATION => Some(1),
        _ => None,
    }
}

/// Whether `pname` is a color, converted with the signed-integer color mapping in glLightiv.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::light::is_light_color};
/// assert!(is_light_color(GL_SPECULAR) && !is_light_color(GL_POSITION));
/// ```
pub fn is_light_color(pname: GLenum) -> bool {
    matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR)
}

impl Light {
    /// glLightfv on this light, `params` holding at least `light_param_count(pname)` values
    /// (the caller checked the pname). Validates, then stores.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::light::Light, GlError};
    /// use glam::{Mat4, Vec3, Vec4};
    /// let mut light = Light::initial(0);
    /// let modelview = Mat4::from_translation(Vec3::new(0.0, 0.0, -2.0));
    /// light.set(GL_POSITION, Vec4::new(0.0, 0.0, 0.0, 1.0), &modelview)?;
    /// assert_eq!(light.eye_position, Vec4::new(0.0, 0.0, -2.0, 1.0));
    /// assert_eq!(light.set(GL_SPOT_EXPONENT, Vec4::splat(200.0), &modelview), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(&mut self, pname: GLenum, params: Vec4, modelview: &Mat4) -> GlResult {
        let scalar = params.x;
        match pname {
            GL_AMBIENT => self.ambient = params,
            GL_DIFFUSE => self.diffuse = params,
            GL_SPECULAR => self.specular = params,
            GL_POSITION => self.eye_position = *modelview * params,
            GL_SPOT_DIRECTION => {
                self.eye_spot_direction = modelview.transform_vector3(params.truncate())
            }
            GL_SPOT_EXPONENT => {
                if !(0.0..=128.0).contains(&scalar) {
                    return Err(GlError::InvalidValue);
                }
                self.spot_exponent = scalar;
            }
            GL_SPOT_CUTOFF => {
                if !((0.0..=90.0).contains(&scalar) || scalar == 180.0) {
                    return Err(GlError::InvalidValue);
                }
                self.spot_cutoff = scalar;
            }
            GL_CONSTANT_ATTENUATION | GL_LINEAR_ATTENUATION | GL_QUADRATIC_ATTENUATION => {
                if scalar.is_nan() || scalar < 0.0 {
                    return Err(GlError::InvalidValue);
                }
                match pname {
                    GL_CONSTANT_ATTENUATION => self.constant_attenuation = scalar,
                    GL_LINEAR_ATTENUATION => self.linear_attenuation = scalar,
                    _ => self.quadratic_attenuation = scalar,
                }
            }
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }

    /// glGetLightfv: the stored value, padded to four.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::light::Light};
    /// let light = Light::initial(0);
    /// assert_eq!(light.get(GL_SPOT_DIRECTION)?.truncate(), glam::Vec3::NEG_Z);
    /// assert_eq!(light.get(GL_CONSTANT_ATTENUATION)?.x, 1.0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get(&self, pname: GLenum) -> GlResult<Vec4> {
        let scalar = |v: f32| Vec4::new(v, 0.0, 0.0, 0.0);
        Ok(match pname {
            GL_AMBIENT => self.ambient,
            GL_DIFFUSE => self.diffuse,
            GL_SPECULAR => self.specular,
            GL_POSITION => self.eye_position,
            GL_SPOT_DIRECTION => self.eye_spot_direction.extend(0.0),
            GL_SPOT_EXPONENT => scalar(self.spot_exponent),
            GL_SPOT_CUTOFF => scalar(self.spot_cutoff),
            GL_CONSTANT_ATTENUATION => scalar(self.constant_attenuation),
            GL_LINEAR_ATTENUATION => scalar(self.linear_attenuation),
            GL_QUADRATIC_ATTENUATION => scalar(self.quadratic_attenuation),
            _ => return Err(GlError::InvalidEnum),
        })
    }
}
