//! Matrix entry points (§2.11.2).

use super::{read, with_context};
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;

/// Runs a matrix command on the 16 values at `m` (doubles are narrowed to floats, as GL keeps
/// matrices); NULL is GL_INVALID_VALUE.
///
/// # Safety
/// A non-NULL `m` must point to 16 values.
unsafe fn with_matrix<T: Copy + Into<f64>>(
    m: *const T,
    command: fn(&mut Context, &[f32; 16]) -> GlResult,
) {
    // SAFETY: forwarded from the caller.
    let values = unsafe { read(m, 16) };
    with_context(|ctx| {
        // between glBegin and glEnd the command itself is the error, NULL or not (§2.6.3)
        ctx.outside_begin_end()?;
        if values.is_empty() {
            return Err(GlError::InvalidValue);
        }
        let matrix: [f32; 16] = std::array::from_fn(|i| values[i].into() as f32);
        command(ctx, &matrix)
    })
}

#[unsafe(no_mangle)]
pub extern "C" fn glMatrixMode(mode: GLenum) {
    with_context(|ctx| ctx.matrix_mode(mode))
}

#[unsafe(no_mangle)]
pub extern "C" fn glLoadIdentity() {
    with_context(|ctx| ctx.load_identity())
}

/// # Safety
/// `m` is NULL or points to 16 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glLoadMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { with_matrix(m, Context::load_matrix) }
}

/// # Safety
/// `m` is NULL or points to 16 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glLoadMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { with_matrix(m, Context::load_matrix) }
}

/// # Safety
/// `m` is NULL or points to 16 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glMultMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { with_matrix(m, Context::mult_matrix) }
}

/// # Safety
/// `m` is NULL or points to 16 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glMultMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { with_matrix(m, Context::mult_matrix) }
}

/// # Safety
/// `m` is NULL or points to 16 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glLoadTransposeMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { with_matrix(m, Context::load_transpose_matrix) }
}

/// # Safety
/// `m` is NULL or points to 16 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glLoadTransposeMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { with_matrix(m, Context::load_transpose_matrix) }
}

/// # Safety
/// `m` is NULL or points to 16 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glMultTransposeMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { with_matrix(m, Context::mult_transpose_matrix) }
}

/// # Safety
/// `m` is NULL or points to 16 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glMultTransposeMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { with_matrix(m, Context::mult_transpose_matrix) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat) {
    with_context(|ctx| ctx.translate(x.into(), y.into(), z.into()))
}

#[unsafe(no_mangle)]
pub extern "C" fn glTranslated(x: GLdouble, y: GLdouble, z: GLdouble) {
    with_context(|ctx| ctx.translate(x, y, z))
}

#[unsafe(no_mangle)]
pub extern "C" fn glRotatef(angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat) {
    with_context(|ctx| ctx.rotate(angle.into(), x.into(), y.into(), z.into()))
}

#[unsafe(no_mangle)]
pub extern "C" fn glRotated(angle: GLdouble, x: GLdouble, y: GLdouble, z: GLdouble) {
    with_context(|ctx| ctx.rotate(angle, x, y, z))
}

#[unsafe(no_mangle)]
pub extern "C" fn glScalef(x: GLfloat, y: GLfloat, z: GLfloat) {
    with_context(|ctx| ctx.scale(x.into(), y.into(), z.into()))
}

#[unsafe(no_mangle)]
pub extern "C" fn glScaled(x: GLdouble, y: GLdouble, z: GLdouble) {
    with_context(|ctx| ctx.scale(x, y, z))
}

#[unsafe(no_mangle)]
pub extern "C" fn glFrustum(
    left: GLdouble,
    right: GLdouble,
    bottom: GLdouble,
    top: GLdouble,
    near: GLdouble,
    far: GLdouble,
) {
    with_context(|ctx| ctx.frustum(left, right, bottom, top, near, far))
}

#[unsafe(no_mangle)]
pub extern "C" fn glOrtho(
    left: GLdouble,
    right: GLdouble,
    bottom: GLdouble,
    top: GLdouble,
    near: GLdouble,
    far: GLdouble,
) {
    with_context(|ctx| ctx.ortho(left, right, bottom, top, near, far))
}

#[unsafe(no_mangle)]
pub extern "C" fn glPushMatrix() {
    with_context(|ctx| ctx.push_matrix())
}

#[unsafe(no_mangle)]
pub extern "C" fn glPopMatrix() {
    with_context(|ctx| ctx.pop_matrix())
}
