//! Hints (§5.6, table 6.27): stored and queried.

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// The targets of glHint.
pub const HINT_TARGETS: [GLenum; 7] = [
    GL_PERSPECTIVE_CORRECTION_HINT,
    GL_POINT_SMOOTH_HINT,
    GL_LINE_SMOOTH_HINT,
    GL_POLYGON_SMOOTH_HINT,
    GL_FOG_HINT,
    GL_GENERATE_MIPMAP_HINT,
    GL_TEXTURE_COMPRESSION_HINT,
];

/// The hint attribute group (GL_HINT_BIT): each target's mode, in `HINT_TARGETS` order.
#[derive(Clone, Debug, PartialEq)]
pub struct HintAttribs {
    /// Each target's mode (GL_DONT_CARE, GL_FASTEST or GL_NICEST).
    pub modes: [GLenum; HINT_TARGETS.len()],
}

impl Default for HintAttribs {
    fn default() -> HintAttribs {
        HintAttribs {
            modes: [GL_DONT_CARE; HINT_TARGETS.len()],
        }
    }
}

impl HintAttribs {
    /// The mode of `target`, or None if it is no hint target.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::hints::HintAttribs};
    /// assert_eq!(HintAttribs::default().get(GL_FOG_HINT), Some(GL_DONT_CARE));
    /// assert_eq!(HintAttribs::default().get(GL_FOG), None);
    /// ```
    pub fn get(&self, target: GLenum) -> Option<GLenum> {
        let index = HINT_TARGETS.iter().position(|&t| t == target)?;
        Some(self.modes[index])
    }

    /// glHint: GL_INVALID_ENUM for a target or mode that is none.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::hints::HintAttribs, GlError};
    /// let mut hints = HintAttribs::default();
    /// hints.set(GL_GENERATE_MIPMAP_HINT, GL_FASTEST)?;
    /// assert_eq!(hints.get(GL_GENERATE_MIPMAP_HINT), Some(GL_FASTEST));
    /// assert_eq!(hints.set(GL_FOG_HINT, GL_FOG), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(&mut self, target: GLenum, mode: GLenum) -> GlResult {
        let index = HINT_TARGETS
            .iter()
            .position(|&t| t == target)
            .ok_or(GlError::InvalidEnum)?;
        if !matches!(mode, GL_DONT_CARE | GL_FASTEST | GL_NICEST) {
            return Err(GlError::InvalidEnum);
        }
        self.modes[index] = mode;
        Ok(())
    }
}
