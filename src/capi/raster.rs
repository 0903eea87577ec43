//! glClipPlane, glGetClipPlane, glShadeModel, glFrontFace, glCullFace, glPolygonMode.

use super::{read, with_context, write};
use crate::error::GlError;
use crate::gl::*;

/// # Safety
/// `equation` is NULL or points to 4 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glClipPlane(plane: GLenum, equation: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    let equation = unsafe { read(equation, 4) };
    with_context(|ctx| {
        let equation: [f64; 4] = equation.try_into().map_err(|_| GlError::InvalidValue)?;
        ctx.clip_plane(plane, equation)
    })
}

/// # Safety
/// `equation` is NULL or has room for 4 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetClipPlane(plane: GLenum, equation: *mut GLdouble) {
    with_context(|ctx| {
        let values = ctx.get_clip_plane(plane)?;
        // SAFETY: forwarded from the caller.
        unsafe { write(equation, &values) }
    })
}

#[unsafe(no_mangle)]
pub extern "C" fn glShadeModel(mode: GLenum) {
    with_context(|ctx| ctx.shade_model(mode))
}

#[unsafe(no_mangle)]
pub extern "C" fn glFrontFace(mode: GLenum) {
    with_context(|ctx| ctx.front_face(mode))
}

#[unsafe(no_mangle)]
pub extern "C" fn glCullFace(mode: GLenum) {
    with_context(|ctx| ctx.cull_face(mode))
}

#[unsafe(no_mangle)]
pub extern "C" fn glPolygonMode(face: GLenum, mode: GLenum) {
    with_context(|ctx| ctx.polygon_mode(face, mode))
}
