//! glGetLight*, glGetMaterial*, glIsEnabled (the lighting commands and glEnable/glDisable
//! are lines of entry_points.txt).

use super::{with_context, write};
use crate::gl::*;

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
pub extern "C" fn glIsEnabled(cap: GLenum) -> GLboolean {
    with_context(|ctx| ctx.is_enabled(cap).map(GLboolean::from))
}
