//! glRasterPos{2,3,4}{s,i,f,d}[v] (§2.13): coordinates convert directly, as glVertex's do.

use glam::Vec4;

use super::attribs::{read_vector, record_or_run};
use crate::commands::list::Command;
use crate::gl::*;
use crate::state::convert::Component;

fn raster_pos(v: [f32; 4]) {
    record_or_run(Command::RasterPos(Vec4::from_array(v)))
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos2s(x: GLshort, y: GLshort) {
    raster_pos([x.direct(), y.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos2sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos2i(x: GLint, y: GLint) {
    raster_pos([x.direct(), y.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos2iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos2f(x: GLfloat, y: GLfloat) {
    raster_pos([x.direct(), y.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos2fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos2d(x: GLdouble, y: GLdouble) {
    raster_pos([x.direct(), y.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos2dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos3s(x: GLshort, y: GLshort, z: GLshort) {
    raster_pos([x.direct(), y.direct(), z.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos3sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos3i(x: GLint, y: GLint, z: GLint) {
    raster_pos([x.direct(), y.direct(), z.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos3iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos3f(x: GLfloat, y: GLfloat, z: GLfloat) {
    raster_pos([x.direct(), y.direct(), z.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos3fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos3d(x: GLdouble, y: GLdouble, z: GLdouble) {
    raster_pos([x.direct(), y.direct(), z.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos3dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) {
    raster_pos([x.direct(), y.direct(), z.direct(), w.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos4sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos4i(x: GLint, y: GLint, z: GLint, w: GLint) {
    raster_pos([x.direct(), y.direct(), z.direct(), w.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos4iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) {
    raster_pos([x.direct(), y.direct(), z.direct(), w.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos4fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glRasterPos4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) {
    raster_pos([x.direct(), y.direct(), z.direct(), w.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glRasterPos4dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, raster_pos) }
}
