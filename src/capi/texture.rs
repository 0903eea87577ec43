//! The texture image transfers (§3.8.1-3.8.3, §6.1.4): their pixels are untyped (`void *`),
//! read or written as the bytes the format, type and pixel store modes describe.

use std::ffi::c_void;

use super::{read, read_mut, with_context};
use crate::commands::list::{Command, ImageCommand};
use crate::commands::texture::{SubImageArgs, TexImageArgs};
use crate::context::Context;
use crate::error::GlResult;
use crate::gl::*;

/// The compressed image commands always fail (no compressed format); while a list is
/// compiled, §5.4 compiles them, so their error is recorded and raised when the list runs.
fn compressed(command: impl FnOnce(&mut Context) -> GlResult) {
    with_context(|ctx| match command(ctx) {
        Err(error) if ctx.compiling_list() => ctx.record_or_run(Command::Error(error)),
        result => result,
    })
}

/// # Safety
/// `pixels` is NULL (an image of zeros) or points to the bytes the image occupies under the
/// GL_UNPACK_* modes.
unsafe fn tex_image(dimensions: usize, args: TexImageArgs, pixels: *const c_void) {
    with_context(|ctx| {
        let span = ctx.tex_image_span(dimensions, &args);
        // SAFETY: the caller's guarantee, forwarded.
        let pixels = unsafe { read(pixels.cast::<u8>(), span) };
        ctx.run_image_command(ImageCommand::TexImage(dimensions, args), pixels)
    })
}

/// # Safety
/// As `tex_image`; NULL changes nothing.
unsafe fn tex_sub_image(dimensions: usize, args: SubImageArgs, pixels: *const c_void) {
    with_context(|ctx| {
        let span = ctx.tex_sub_image_span(dimensions, &args);
        // SAFETY: the caller's guarantee, forwarded.
        let pixels = unsafe { read(pixels.cast::<u8>(), span) };
        ctx.run_image_command(ImageCommand::TexSubImage(dimensions, args), pixels)
    })
}

/// # Safety
/// `pixels` is NULL or points to the bytes the image occupies.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexImage1D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    border: GLint,
    format: GLenum,
    ty: GLenum,
    pixels: *const c_void,
) {
    let size = [width, 1, 1];
    let args = TexImageArgs {
        target,
        level,
        internal_format: internalformat,
        size,
        border,
        format,
        ty,
    };
    // SAFETY: forwarded.
    unsafe { tex_image(1, args, pixels) }
}

/// # Safety
/// `pixels` is NULL or points to the bytes the image occupies.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexImage2D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
    format: GLenum,
    ty: GLenum,
    pixels: *const c_void,
) {
    let size = [width, height, 1];
    let args = TexImageArgs {
        target,
        level,
        internal_format: internalformat,
        size,
        border,
        format,
        ty,
    };
    // SAFETY: forwarded.
    unsafe { tex_image(2, args, pixels) }
}

/// # Safety
/// `pixels` is NULL or points to the bytes the image occupies.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexImage3D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    height: GLsizei,
    depth: GLsizei,
    border: GLint,
    format: GLenum,
    ty: GLenum,
    pixels: *const c_void,
) {
    let size = [width, height, depth];
    let args = TexImageArgs {
        target,
        level,
        internal_format: internalformat,
        size,
        border,
        format,
        ty,
    };
    // SAFETY: forwarded.
    unsafe { tex_image(3, args, pixels) }
}

/// # Safety
/// `pixels` is NULL or points to the bytes the region occupies.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexSubImage1D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    width: GLsizei,
    format: GLenum,
    ty: GLenum,
    pixels: *const c_void,
) {
    let args = SubImageArgs {
        target,
        level,
        offset: [xoffset, 0, 0],
        size: [width, 1, 1],
        format,
        ty,
    };
    // SAFETY: forwarded.
    unsafe { tex_sub_image(1, args, pixels) }
}

/// # Safety
/// `pixels` is NULL or points to the bytes the region occupies.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexSubImage2D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    ty: GLenum,
    pixels: *const c_void,
) {
    let offset = [xoffset, yoffset, 0];
    let args = SubImageArgs {
        target,
        level,
        offset,
        size: [width, height, 1],
        format,
        ty,
    };
    // SAFETY: forwarded.
    unsafe { tex_sub_image(2, args, pixels) }
}

/// # Safety
/// `pixels` is NULL or points to the bytes the region occupies.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexSubImage3D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    zoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    depth: GLsizei,
    format: GLenum,
    ty: GLenum,
    pixels: *const c_void,
) {
    let offset = [xoffset, yoffset, zoffset];
    let args = SubImageArgs {
        target,
        level,
        offset,
        size: [width, height, depth],
        format,
        ty,
    };
    // SAFETY: forwarded.
    unsafe { tex_sub_image(3, args, pixels) }
}

/// Packs the image with the GL_PACK_* modes; bytes between its pixels are left as they are.
///
/// # Safety
/// `pixels` is NULL or has room for the bytes the image occupies under the pack modes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetTexImage(
    target: GLenum,
    level: GLint,
    format: GLenum,
    ty: GLenum,
    pixels: *mut c_void,
) {
    with_context(|ctx| {
        let span = ctx.get_tex_image_span(target, level, format, ty);
        // SAFETY: the caller guarantees room for the image at a non-NULL `pixels`.
        let pixels = unsafe { read_mut(pixels.cast::<u8>(), span) };
        ctx.get_tex_image(target, level, format, ty, pixels)
    })
}

/// No compressed format is supported: GL_INVALID_ENUM (nothing is read).
#[unsafe(no_mangle)]
pub extern "C" fn glCompressedTexImage1D(
    _target: GLenum,
    _level: GLint,
    _internalformat: GLenum,
    _width: GLsizei,
    _border: GLint,
    _image_size: GLsizei,
    _data: *const c_void,
) {
    compressed(|ctx| ctx.compressed_tex_image())
}

/// No compressed format is supported: GL_INVALID_ENUM (nothing is read).
#[unsafe(no_mangle)]
pub extern "C" fn glCompressedTexImage2D(
    _target: GLenum,
    _level: GLint,
    _internalformat: GLenum,
    _width: GLsizei,
    _height: GLsizei,
    _border: GLint,
    _image_size: GLsizei,
    _data: *const c_void,
) {
    compressed(|ctx| ctx.compressed_tex_image())
}

/// No compressed format is supported: GL_INVALID_ENUM (nothing is read).
#[unsafe(no_mangle)]
pub extern "C" fn glCompressedTexImage3D(
    _target: GLenum,
    _level: GLint,
    _internalformat: GLenum,
    _width: GLsizei,
    _height: GLsizei,
    _depth: GLsizei,
    _border: GLint,
    _image_size: GLsizei,
    _data: *const c_void,
) {
    compressed(|ctx| ctx.compressed_tex_image())
}

/// No image is compressed: GL_INVALID_OPERATION for a valid target and level (nothing is
/// read).
#[unsafe(no_mangle)]
pub extern "C" fn glCompressedTexSubImage1D(
    target: GLenum,
    level: GLint,
    _xoffset: GLint,
    _width: GLsizei,
    _format: GLenum,
    _image_size: GLsizei,
    _data: *const c_void,
) {
    compressed(|ctx| ctx.compressed_tex_sub_image(1, target, level))
}

/// No image is compressed: GL_INVALID_OPERATION for a valid target and level (nothing is
/// read).
#[unsafe(no_mangle)]
pub extern "C" fn glCompressedTexSubImage2D(
    target: GLenum,
    level: GLint,
    _xoffset: GLint,
    _yoffset: GLint,
    _width: GLsizei,
    _height: GLsizei,
    _format: GLenum,
    _image_size: GLsizei,
    _data: *const c_void,
) {
    compressed(|ctx| ctx.compressed_tex_sub_image(2, target, level))
}

/// No image is compressed: GL_INVALID_OPERATION for a valid target and level (nothing is
/// read).
#[unsafe(no_mangle)]
pub extern "C" fn glCompressedTexSubImage3D(
    target: GLenum,
    level: GLint,
    _xoffset: GLint,
    _yoffset: GLint,
    _zoffset: GLint,
    _width: GLsizei,
    _height: GLsizei,
    _depth: GLsizei,
    _format: GLenum,
    _image_size: GLsizei,
    _data: *const c_void,
) {
    compressed(|ctx| ctx.compressed_tex_sub_image(3, target, level))
}

/// No image is compressed: GL_INVALID_OPERATION for a valid target and level (nothing is
/// written).
#[unsafe(no_mangle)]
pub extern "C" fn glGetCompressedTexImage(target: GLenum, level: GLint, _img: *mut c_void) {
    with_context(|ctx| ctx.get_compressed_tex_image(target, level))
}
