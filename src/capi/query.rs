//! glGetError, glGet{Boolean,Integer,Float,Double}v, glGetString.

use super::{with_context, write};
use crate::gl::*;

#[unsafe(no_mangle)]
pub extern "C" fn glGetError() -> GLenum {
    // §2.6.3: GetError is not allowed between Begin and End; there it is GL_INVALID_OPERATION
    // and returns 0 (GL_NO_ERROR), leaving an earlier error in the flag, as in Mesa.
    with_context(|ctx| {
        ctx.outside_begin_end()?;
        Ok(ctx.get_error())
    })
}

/// # Safety
/// `params` is NULL or has room for the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetBooleanv(pname: GLenum, params: *mut GLboolean) {
    with_context(|ctx| {
        let values: Vec<GLboolean> = ctx
            .get(pname)?
            .as_bools()
            .into_iter()
            .map(GLboolean::from)
            .collect();
        // SAFETY: forwarded from the caller.
        unsafe { write(params, &values) }
    })
}

/// # Safety
/// `params` is NULL or has room for the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetIntegerv(pname: GLenum, params: *mut GLint) {
    with_context(|ctx| {
        let values = ctx.get(pname)?.as_ints();
        // SAFETY: forwarded from the caller.
        unsafe { write(params, &values) }
    })
}

/// # Safety
/// `params` is NULL or has room for the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetFloatv(pname: GLenum, params: *mut GLfloat) {
    with_context(|ctx| {
        let values = ctx.get(pname)?.as_floats();
        // SAFETY: forwarded from the caller.
        unsafe { write(params, &values) }
    })
}

/// # Safety
/// `params` is NULL or has room for the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetDoublev(pname: GLenum, params: *mut GLdouble) {
    with_context(|ctx| {
        let values = ctx.get(pname)?.as_doubles();
        // SAFETY: forwarded from the caller.
        unsafe { write(params, &values) }
    })
}

/// The string lives as long as the library; NULL for a bad name.
#[unsafe(no_mangle)]
pub extern "C" fn glGetString(name: GLenum) -> *const GLubyte {
    with_context(|ctx| Ok(Some(ctx.get_string(name)?)))
        .map_or(std::ptr::null(), |s| s.as_ptr().cast())
}
