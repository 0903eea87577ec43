//! Buffer objects (§2.9): glGenBuffers, glDeleteBuffers, glBindBuffer, glIsBuffer,
//! glBufferData, glBufferSubData, glGetBufferSubData, glMapBuffer, glUnmapBuffer,
//! glGetBufferParameteriv, glGetBufferPointerv.

use std::ffi::c_void;

use super::{read, with_context, write};
use crate::error::GlError;
use crate::gl::*;

/// `size` bytes at `data` (NULL gives none), or GL_INVALID_VALUE for a negative size.
///
/// # Safety
/// A non-NULL `data` must point to `size` readable bytes.
unsafe fn bytes<'a>(data: *const c_void, size: GLsizeiptr) -> &'a [u8] {
    // SAFETY: forwarded from the caller; a negative size reads nothing.
    unsafe { read(data.cast::<u8>(), usize::try_from(size).unwrap_or(0)) }
}

/// # Safety
/// `buffers` is NULL or has room for `n` names.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGenBuffers(n: GLsizei, buffers: *mut GLuint) {
    with_context(|ctx| {
        ctx.outside_begin_end()?;
        // A NULL destination is refused before any name is made (no effect on error).
        if n > 0 && buffers.is_null() {
            return Err(GlError::InvalidValue);
        }
        let names = ctx.gen_buffers(n)?;
        // SAFETY: the caller guarantees room for `n` names at a non-NULL `buffers`.
        unsafe { write(buffers, &names) }
    })
}

/// # Safety
/// `buffers` is NULL or points to `n` names.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glDeleteBuffers(n: GLsizei, buffers: *const GLuint) {
    with_context(|ctx| {
        ctx.outside_begin_end()?;
        let count = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
        // SAFETY: the caller guarantees `n` names at a non-NULL `buffers`.
        let names = unsafe { read(buffers, count) };
        if names.len() < count {
            return Err(GlError::InvalidValue);
        }
        ctx.delete_buffers(names)
    })
}

#[unsafe(no_mangle)]
pub extern "C" fn glBindBuffer(target: GLenum, buffer: GLuint) {
    with_context(|ctx| ctx.bind_buffer(target, buffer))
}

#[unsafe(no_mangle)]
pub extern "C" fn glIsBuffer(buffer: GLuint) -> GLboolean {
    with_context(|ctx| ctx.is_buffer(buffer).map(GLboolean::from))
}

/// # Safety
/// `data` is NULL (a zeroed store) or points to `size` readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glBufferData(
    target: GLenum,
    size: GLsizeiptr,
    data: *const c_void,
    usage: GLenum,
) {
    with_context(|ctx| {
        // SAFETY: forwarded from the caller.
        let data = (!data.is_null()).then(|| unsafe { bytes(data, size) });
        ctx.buffer_data(target, size, data, usage)
    })
}

/// # Safety
/// `data` is NULL or points to `size` readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glBufferSubData(
    target: GLenum,
    offset: GLintptr,
    size: GLsizeiptr,
    data: *const c_void,
) {
    with_context(|ctx| {
        // SAFETY: forwarded from the caller.
        let data = unsafe { bytes(data, size) };
        if data.is_empty() && size > 0 {
            // The checks of the command first, then the missing data.
            ctx.get_buffer_sub_data(target, offset, size)?;
            return Err(GlError::InvalidValue);
        }
        ctx.buffer_sub_data(target, offset, size, data)
    })
}

/// # Safety
/// `data` is NULL or has room for `size` bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetBufferSubData(
    target: GLenum,
    offset: GLintptr,
    size: GLsizeiptr,
    data: *mut c_void,
) {
    with_context(|ctx| {
        let values = ctx.get_buffer_sub_data(target, offset, size)?;
        // SAFETY: the caller guarantees room for `size` bytes at a non-NULL `data`.
        unsafe { write(data.cast::<u8>(), values) }
    })
}

/// The pointer is valid until the buffer is unmapped, given new data or deleted.
#[unsafe(no_mangle)]
pub extern "C" fn glMapBuffer(target: GLenum, access: GLenum) -> *mut c_void {
    let address: usize = with_context(|ctx| ctx.map_buffer(target, access));
    address as *mut c_void
}

#[unsafe(no_mangle)]
pub extern "C" fn glUnmapBuffer(target: GLenum) -> GLboolean {
    with_context(|ctx| ctx.unmap_buffer(target).map(GLboolean::from))
}

/// # Safety
/// `params` is NULL or has room for one value.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetBufferParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) {
    with_context(|ctx| {
        let value = ctx.get_buffer_parameter(target, pname)?;
        // SAFETY: the caller guarantees room for one value at a non-NULL `params`.
        unsafe { write(params, &[value]) }
    })
}

/// # Safety
/// `params` is NULL or has room for one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetBufferPointerv(
    target: GLenum,
    pname: GLenum,
    params: *mut *mut c_void,
) {
    with_context(|ctx| {
        let address = ctx.get_buffer_pointer(target, pname)?;
        // SAFETY: the caller guarantees room for one pointer at a non-NULL `params`.
        unsafe { write(params, &[address as *mut c_void]) }
    })
}
