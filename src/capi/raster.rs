//! glClipPlane, glGetClipPlane, glShadeModel, glFrontFace, glCullFace, glPolygonMode, glRect.

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

#[unsafe(no_mangle)]
pub extern "C" fn glRectf(x1: GLfloat, y1: GLfloat, x2: GLfloat, y2: GLfloat) {
    with_context(|ctx| ctx.rect(x1, y1, x2, y2))
}

#[unsafe(no_mangle)]
pub extern "C" fn glRectd(x1: GLdouble, y1: GLdouble, x2: GLdouble, y2: GLdouble) {
    with_context(|ctx| ctx.rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32))
}

#[unsafe(no_mangle)]
pub extern "C" fn glRecti(x1: GLint, y1: GLint, x2: GLint, y2: GLint) {
    with_context(|ctx| ctx.rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32))
}

#[unsafe(no_mangle)]
pub extern "C" fn glRects(x1: GLshort, y1: GLshort, x2: GLshort, y2: GLshort) {
    with_context(|ctx| ctx.rect(x1.into(), y1.into(), x2.into(), y2.into()))
}
