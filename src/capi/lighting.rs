//! glLight*, glMaterial*, glLightModel*, glColorMaterial, glEnable, glDisable, glIsEnabled.

use super::{read, with_context, write};
use crate::gl::*;
use crate::state::light::light_param_count;
use crate::state::light_model::light_model_param_count;
use crate::state::material::material_param_count;

#[unsafe(no_mangle)]
pub extern "C" fn glLightf(light: GLenum, pname: GLenum, param: GLfloat) {
    with_context(|ctx| ctx.light_scalar(light, pname, param))
}

#[unsafe(no_mangle)]
pub extern "C" fn glLighti(light: GLenum, pname: GLenum, param: GLint) {
    with_context(|ctx| ctx.light_scalar(light, pname, param as f32))
}

/// # Safety
/// `params` is NULL or holds the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    let params = unsafe { read(params, light_param_count(pname).unwrap_or(0)) };
    with_context(|ctx| ctx.light(light, pname, params))
}

/// # Safety
/// `params` is NULL or holds the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glLightiv(light: GLenum, pname: GLenum, params: *const GLint) {
    // SAFETY: forwarded from the caller.
    let params = unsafe { read(params, light_param_count(pname).unwrap_or(0)) };
    with_context(|ctx| ctx.light_i(light, pname, params))
}

/// # Safety
/// `params` is NULL or has room for the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetLightfv(light: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_context(|ctx| {
        let (values, count) = ctx.get_light(light, pname)?;
        // SAFETY: forwarded from the caller.
        unsafe { write(params, &values.to_array()[..count]) }
    })
}

/// # Safety
/// `params` is NULL or has room for the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetLightiv(light: GLenum, pname: GLenum, params: *mut GLint) {
    with_context(|ctx| {
        let (values, count) = ctx.get_light_i(light, pname)?;
        // SAFETY: forwarded from the caller.
        unsafe { write(params, &values[..count]) }
    })
}

#[unsafe(no_mangle)]
pub extern "C" fn glMaterialf(face: GLenum, pname: GLenum, param: GLfloat) {
    with_context(|ctx| ctx.material_scalar(face, pname, param))
}

#[unsafe(no_mangle)]
pub extern "C" fn glMateriali(face: GLenum, pname: GLenum, param: GLint) {
    with_context(|ctx| ctx.material_scalar(face, pname, param as f32))
}

/// # Safety
/// `params` is NULL or holds the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    let params = unsafe { read(params, material_param_count(pname).unwrap_or(0)) };
    with_context(|ctx| ctx.material(face, pname, params))
}

/// # Safety
/// `params` is NULL or holds the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glMaterialiv(face: GLenum, pname: GLenum, params: *const GLint) {
    // SAFETY: forwarded from the caller.
    let params = unsafe { read(params, material_param_count(pname).unwrap_or(0)) };
    with_context(|ctx| ctx.material_i(face, pname, params))
}

/// # Safety
/// `params` is NULL or has room for the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_context(|ctx| {
        let (values, count) = ctx.get_material(face, pname)?;
        // SAFETY: forwarded from the caller.
        unsafe { write(params, &values.to_array()[..count]) }
    })
}

/// # Safety
/// `params` is NULL or has room for the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetMaterialiv(face: GLenum, pname: GLenum, params: *mut GLint) {
    with_context(|ctx| {
        let (values, count) = ctx.get_material_i(face, pname)?;
        // SAFETY: forwarded from the caller.
        unsafe { write(params, &values[..count]) }
    })
}

#[unsafe(no_mangle)]
pub extern "C" fn glLightModelf(pname: GLenum, param: GLfloat) {
    with_context(|ctx| ctx.light_model_scalar(pname, param))
}

#[unsafe(no_mangle)]
pub extern "C" fn glLightModeli(pname: GLenum, param: GLint) {
    with_context(|ctx| ctx.light_model_scalar(pname, param as f32))
}

/// # Safety
/// `params` is NULL or holds the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glLightModelfv(pname: GLenum, params: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    let params = unsafe { read(params, light_model_param_count(pname).unwrap_or(0)) };
    with_context(|ctx| ctx.light_model(pname, params))
}

/// # Safety
/// `params` is NULL or holds the values `pname` defines.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glLightModeliv(pname: GLenum, params: *const GLint) {
    // SAFETY: forwarded from the caller.
    let params = unsafe { read(params, light_model_param_count(pname).unwrap_or(0)) };
    with_context(|ctx| ctx.light_model_i(pname, params))
}

#[unsafe(no_mangle)]
pub extern "C" fn glColorMaterial(face: GLenum, mode: GLenum) {
    with_context(|ctx| ctx.color_material(face, mode))
}

#[unsafe(no_mangle)]
pub extern "C" fn glEnable(cap: GLenum) {
    with_context(|ctx| ctx.set_capability(cap, true))
}

#[unsafe(no_mangle)]
pub extern "C" fn glDisable(cap: GLenum) {
    with_context(|ctx| ctx.set_capability(cap, false))
}

#[unsafe(no_mangle)]
pub extern "C" fn glIsEnabled(cap: GLenum) -> GLboolean {
    with_context(|ctx| ctx.is_enabled(cap).map(GLboolean::from))
}
