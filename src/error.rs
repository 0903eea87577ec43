//! GL errors: the error enum and the first-error-sticky flag (§2.5).

use crate::gl::*;

/// One GL error, as `glGetError` reports it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlError {
    /// GL_INVALID_ENUM: an enumerated argument out of range.
    InvalidEnum,
    /// GL_INVALID_VALUE: a numeric argument out of range.
    InvalidValue,
    /// GL_INVALID_OPERATION: not allowed in the current state.
    InvalidOperation,
    /// GL_STACK_OVERFLOW: a push on a full stack.
    StackOverflow,
    /// GL_STACK_UNDERFLOW: a pop of an empty stack.
    StackUnderflow,
    /// GL_OUT_OF_MEMORY.
    OutOfMemory,
    /// GL_TABLE_TOO_LARGE (the imaging subset, §3.6.3).
    TableTooLarge,
}

impl GlError {
    /// The GL enum value of this error.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, GlError};
    /// assert_eq!(GlError::InvalidEnum.code(), GL_INVALID_ENUM);
    /// assert_eq!(GlError::StackOverflow.code(), GL_STACK_OVERFLOW);
    /// ```
    pub fn code(self) -> GLenum {
        match self {
            GlError::InvalidEnum => GL_INVALID_ENUM,
            GlError::InvalidValue => GL_INVALID_VALUE,
            GlError::InvalidOperation => GL_INVALID_OPERATION,
            GlError::StackOverflow => GL_STACK_OVERFLOW,
            GlError::StackUnderflow => GL_STACK_UNDERFLOW,
            GlError::OutOfMemory => GL_OUT_OF_MEMORY,
            GlError::TableTooLarge => GL_TABLE_TOO_LARGE,
        }
    }
}

/// The result of a GL command: `Err` leaves the state unchanged and sets the error flag.
pub type GlResult<T = ()> = Result<T, GlError>;

/// The error flag: the first error is kept until `glGetError` reads it.
#[derive(Clone, Copy, Debug, Default)]
pub struct ErrorFlag(Option<GlError>);

impl ErrorFlag {
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{error::ErrorFlag, gl::*, GlError};
    /// let mut flag = ErrorFlag::default();
    /// flag.record(GlError::InvalidValue);
    /// flag.record(GlError::InvalidOperation); // ignored: the first error stays
    /// assert_eq!(flag.take(), GL_INVALID_VALUE);
    /// ```
    pub fn record(&mut self, error: GlError) {
        self.0.get_or_insert(error);
    }

    /// `glGetError`: returns the recorded error and clears it.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{error::ErrorFlag, gl::*, GlError};
    /// let mut flag = ErrorFlag::default();
    /// assert_eq!(flag.take(), GL_NO_ERROR);
    /// flag.record(GlError::OutOfMemory);
    /// assert_eq!(flag.take(), GL_OUT_OF_MEMORY);
    /// assert_eq!(flag.take(), GL_NO_ERROR);
    /// ```
    pub fn take(&mut self) -> GLenum {
        self.0.take().map_or(GL_NO_ERROR, GlError::code)
    }
}

/// A copy of `bytes`, or GL_OUT_OF_MEMORY when it cannot be allocated: for copies whose size
/// the application decides (arrays compiled into a display list), which must fail as GL
/// fails, not abort the process.
///
/// # Examples
///
/// ```
/// assert_eq!(fflight::error::try_copy(&[1, 2, 3]), Ok(vec![1, 2, 3]));
/// ```
pub fn try_copy(bytes: &[u8]) -> GlResult<Vec<u8>> {
    let mut copy = Vec::new();
    copy.try_reserve_exact(bytes.len())
        .map_err(|_| GlError::OutOfMemory)?;
    copy.extend_from_slice(bytes);
    Ok(copy)
}
