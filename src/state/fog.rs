//! Fog (§3.10, table 6.10): stored, validated and queried; there is no rasterizer to apply it.

use glam::Vec4;

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// The fog attribute group (GL_FOG_BIT), with its enables (GL_FOG, and GL_COLOR_SUM, which the
/// state tables put in the same group).
#[derive(Clone, Debug, PartialEq)]
pub struct FogAttribs {
    /// GL_FOG.
    pub enabled: bool,
    /// GL_COLOR_SUM.
    pub color_sum: bool,
    /// Clamped to [0, 1].
    pub color: Vec4,
    /// GL_FOG_INDEX.
    pub index: f32,
    /// GL_FOG_DENSITY.
    pub density: f32,
    /// GL_FOG_START.
    pub start: f32,
    /// GL_FOG_END.
    pub end: f32,
    /// GL_FOG_MODE.
    pub mode: GLenum,
    /// GL_FOG_COORD_SRC.
    pub coord_src: GLenum,
}

impl Default for FogAttribs {
    fn default() -> FogAttribs {
        FogAttribs {
            enabled: false,
            color_sum: false,
            color: Vec4::ZERO,
            index: 0.0,
            density: 1.0,
            start: 0.0,
            end: 1.0,
            mode: GL_EXP,
            coord_src: GL_FRAGMENT_DEPTH,
        }
    }
}

/// How many values a glFog pname takes, or None for a pname that is not fog's.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::fog::fog_param_count};
/// assert_eq!((fog_param_count(GL_FOG_COLOR), fog_param_count(GL_FOG_END)), (Some(4), Some(1)));
/// ```
pub fn fog_param_count(pname: GLenum) -> Option<usize> {
    match pname {
        GL_FOG_COLOR => Some(4),
        GL_FOG_MODE | GL_FOG_DENSITY | GL_FOG_START | GL_FOG_END | GL_FOG_INDEX
        | GL_FOG_COORD_SRC => Some(1),
        _ => None,
    }
}

/// An enum passed as a float parameter: truncated to an integer, as Mesa does.
fn enum_value(value: f32) -> GLenum {
    value as GLint as GLenum
}

impl FogAttribs {
    /// glFog (§3.10): `params` as floats (integer colors already mapped to [-1, 1]). Checks
    /// the pname, then the count, then the value, as Mesa does; nothing changes on an error.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::fog::FogAttribs, GlError};
    /// let mut fog = FogAttribs::default();
    /// fog.set(GL_FOG_MODE, &[GL_EXP2 as f32])?;
    /// assert_eq!(fog.mode, GL_EXP2);
    /// assert_eq!(fog.set(GL_FOG_MODE, &[GL_LINEAR as f32 + 1.0]), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(&mut self, pname: GLenum, params: &[f32]) -> GlResult {
        let count = fog_param_count(pname).ok_or(GlError::InvalidEnum)?;
        if params.len() < count {
            return Err(GlError::InvalidValue);
        }
        let value = params[0];
        match pname {
            GL_FOG_MODE => {
                let mode = enum_value(value);
                if !matches!(mode, GL_LINEAR | GL_EXP | GL_EXP2) {
                    return Err(GlError::InvalidEnum);
                }
                self.mode = mode;
            }
            GL_FOG_DENSITY if value < 0.0 || value.is_nan() => return Err(GlError::InvalidValue),
            GL_FOG_DENSITY => self.density = value,
            GL_FOG_START => self.start = value,
            GL_FOG_END => self.end = value,
            GL_FOG_INDEX => self.index = value,
            GL_FOG_COORD_SRC => {
                let source = enum_value(value);
                if !matches!(source, GL_FOG_COORD | GL_FRAGMENT_DEPTH) {
                    return Err(GlError::InvalidEnum);
                }
                self.coord_src = source;
            }
            _ => self.color = Vec4::from_slice(&params[..4]).clamp(Vec4::ZERO, Vec4::ONE),
        }
        Ok(())
    }
}
