//! Light model state (§2.14.1, table 2.10 glLightModel).

use glam::Vec4;

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// The light model (§2.14.1, glLightModel).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightModel {
    /// GL_LIGHT_MODEL_AMBIENT.
    pub ambient: Vec4,
    /// GL_LIGHT_MODEL_LOCAL_VIEWER.
    pub local_viewer: bool,
    /// GL_LIGHT_MODEL_TWO_SIDE.
    pub two_side: bool,
    /// GL_SINGLE_COLOR or GL_SEPARATE_SPECULAR_COLOR.
    pub color_control: GLenum,
}

impl Default for LightModel {
    fn default() -> LightModel {
        LightModel {
            ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            local_viewer: false,
            two_side: false,
            color_control: GL_SINGLE_COLOR,
        }
    }
}

/// How many values a glLightModel pname takes, or `None` for a bad pname.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::light_model::light_model_param_count};
/// assert_eq!(light_model_param_count(GL_LIGHT_MODEL_AMBIENT), Some(4));
/// assert_eq!(light_model_param_count(GL_LIGHT_MODEL_TWO_SIDE), Some(1));
/// assert_eq!(light_model_param_count(GL_LIGHT0), None);
/// ```
pub fn light_model_param_count(pname: GLenum) -> Option<usize> {
    match pname {
        GL_LIGHT_MODEL_AMBIENT => Some(4),
        GL_LIGHT_MODEL_LOCAL_VIEWER | GL_LIGHT_MODEL_TWO_SIDE | GL_LIGHT_MODEL_COLOR_CONTROL => {
            Some(1)
        }
        _ => None,
    }
}

impl LightModel {
    /// glLightModelfv with validated-count `params`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::light_model::LightModel, GlError};
    /// use glam::Vec4;
    /// let mut model = LightModel::default();
    /// model.set(GL_LIGHT_MODEL_LOCAL_VIEWER, Vec4::new(1.0, 0.0, 0.0, 0.0))?;
    /// assert!(model.local_viewer);
    /// let bad = Vec4::new(GL_LIGHT0 as f32, 0.0, 0.0, 0.0);
    /// assert_eq!(model.set(GL_LIGHT_MODEL_COLOR_CONTROL, bad), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(&mut self, pname: GLenum, params: Vec4) -> GlResult {
        match pname {
            GL_LIGHT_MODEL_AMBIENT => self.ambient = params,
            GL_LIGHT_MODEL_LOCAL_VIEWER => self.local_viewer = params.x != 0.0,
            GL_LIGHT_MODEL_TWO_SIDE => self.two_side = params.x != 0.0,
            GL_LIGHT_MODEL_COLOR_CONTROL => {
                let mode = params.x as GLenum;
                if params.x != mode as f32
                    || !matches!(mode, GL_SINGLE_COLOR | GL_SEPARATE_SPECULAR_COLOR)
                {
                    return Err(GlError::InvalidEnum);
                }
                self.color_control = mode;
            }
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }

    /// Whether GL_LIGHT_MODEL_COLOR_CONTROL is GL_SEPARATE_SPECULAR_COLOR.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::light_model::LightModel};
    /// let mut model = LightModel::default();
    /// assert!(!model.separate_specular());
    /// let control = glam::Vec4::new(GL_SEPARATE_SPECULAR_COLOR as f32, 0.0, 0.0, 0.0);
    /// model.set(GL_LIGHT_MODEL_COLOR_CONTROL, control)?;
    /// assert!(model.separate_specular());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn separate_specular(&self) -> bool {
        self.color_control == GL_SEPARATE_SPECULAR_COLOR
    }
}
