//! Vertex arrays (§2.8): glVertexPointer, glNormalPointer, glColorPointer,
//! glTexCoordPointer, glEdgeFlagPointer, glEnableClientState, glDisableClientState,
//! glInterleavedArrays, glGetPointerv, glArrayElement, glDrawArrays, glDrawElements,
//! glDrawRangeElements.
//!
//! The pointer commands only store the address. A draw reads, for each enabled array, the
//! bytes of exactly the elements its indices reference (a slice from the smallest to the
//! largest index actually used, of which only the referenced elements are decoded), never
//! more: glDrawRangeElements' start and end are not trusted, and a draw without the vertex
//! array reads nothing, not even its indices.
//!
//! What cannot be checked is whether the application's memory really holds what the call
//! says it does: GL makes that the application's duty, and a glDrawArrays count larger than
//! the arrays, a glDrawElements count larger than the index array, or an index past the end
//! of the arrays reads past them as it would in any GL. A NULL pointer, however, is caught:
//! GL_INVALID_OPERATION, nothing is drawn. Address arithmetic that would overflow is
//! GL_INVALID_VALUE; a draw whose vertices do not fit in memory is GL_OUT_OF_MEMORY (before
//! any array element is read).
//!
//! While a display list is being compiled, glArrayElement and the draws read the elements
//! they use then (§5.4) and compile a copy of them; an error of their checks is compiled in
//! their place, raised when the list executes.

use std::ffi::c_void;

use super::{read, with_context};
use crate::commands::arrays::{ArraySources, ElementIndices};
use crate::commands::list::Command;
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::pipeline::units::EXTRA_UNITS;
use crate::state::arrays::{ARRAY_KINDS, ByteSpan};

/// The enabled arrays' bytes at `spans`, starting with element `base`.
///
/// # Safety
/// Each span must lie in memory that stays readable for `'a` (the application's arrays
/// hold the elements the draw uses).
unsafe fn sources<'a>(
    base: usize,
    spans: &[Option<ByteSpan>; ARRAY_KINDS],
    unit_spans: &[Option<ByteSpan>; EXTRA_UNITS],
) -> ArraySources<'a> {
    let mut sources = ArraySources::new(base);
    let slots = sources.bytes.iter_mut().chain(&mut sources.unit_bytes);
    for (bytes, span) in slots.zip(spans.iter().chain(unit_spans)) {
        if let Some(span) = span {
            // SAFETY: the caller guarantees the span is readable; `VertexArrays::spans`
            // rejected NULL addresses and lengths beyond isize::MAX.
            *bytes = unsafe { std::slice::from_raw_parts(span.address as *const u8, span.len) };
        }
    }
    sources
}

/// Draws `indices` from the enabled arrays, or compiles the draw: reads exactly the bytes
/// they reference. `indices` is the result of the entry point's own checks.
///
/// # Safety
/// The enabled arrays' pointers must hold every element `indices` references.
unsafe fn draw(ctx: &mut Context, mode: GLenum, indices: GlResult<ElementIndices>) -> GlResult {
    let prepared = indices.and_then(|indices| {
        let (range, sources) = match ctx.array_spans(&indices)? {
            // SAFETY: forwarded from the caller.
            Some((range, spans, unit_spans)) => (Some(range), unsafe {
                sources(range.0, &spans, &unit_spans)
            }),
            // Nothing is read; the call still validates as a draw.
            None => (None, ArraySources::default()),
        };
        Ok((indices, range, sources))
    });
    let compiled = ctx.record_checked(|ctx| {
        let (indices, _, sources) = prepared.as_ref().map_err(|e| *e)?;
        Ok(Command::Draw(Box::new(
            ctx.record_draw(mode, sources, indices)?,
        )))
    });
    if compiled {
        return Ok(());
    }
    let (indices, range, sources) = prepared?;
    // The range `array_spans` found: the indices are not scanned again.
    ctx.draw_arrays_over(mode, &sources, &indices, || range)
}

/// `ptr` must stay valid, holding the elements later draws use, until it is replaced.
#[unsafe(no_mangle)]
pub extern "C" fn glVertexPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void) {
    with_context(|ctx| ctx.vertex_pointer(size, type_, stride, ptr as usize))
}

/// `ptr` must stay valid, holding the elements later draws use, until it is replaced.
#[unsafe(no_mangle)]
pub extern "C" fn glNormalPointer(type_: GLenum, stride: GLsizei, ptr: *const c_void) {
    with_context(|ctx| ctx.normal_pointer(type_, stride, ptr as usize))
}

/// `ptr` must stay valid, holding the elements later draws use, until it is replaced.
#[unsafe(no_mangle)]
pub extern "C" fn glColorPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void) {
    with_context(|ctx| ctx.color_pointer(size, type_, stride, ptr as usize))
}

/// `ptr` must stay valid, holding the elements later draws use, until it is replaced.
#[unsafe(no_mangle)]
pub extern "C" fn glTexCoordPointer(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    ptr: *const c_void,
) {
    with_context(|ctx| ctx.tex_coord_pointer(size, type_, stride, ptr as usize))
}

/// `ptr` (GLbooleans) must stay valid, holding the elements later draws use, until it is
/// replaced.
#[unsafe(no_mangle)]
pub extern "C" fn glEdgeFlagPointer(stride: GLsizei, ptr: *const c_void) {
    with_context(|ctx| ctx.edge_flag_pointer(stride, ptr as usize))
}

/// `ptr` must stay valid, holding the elements later draws use, until it is replaced.
#[unsafe(no_mangle)]
pub extern "C" fn glSecondaryColorPointer(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    ptr: *const c_void,
) {
    with_context(|ctx| ctx.secondary_color_pointer(size, type_, stride, ptr as usize))
}

/// `ptr` must stay valid, holding the elements later draws use, until it is replaced.
#[unsafe(no_mangle)]
pub extern "C" fn glIndexPointer(type_: GLenum, stride: GLsizei, ptr: *const c_void) {
    with_context(|ctx| ctx.index_pointer(type_, stride, ptr as usize))
}

/// `ptr` must stay valid, holding the elements later draws use, until it is replaced.
#[unsafe(no_mangle)]
pub extern "C" fn glFogCoordPointer(type_: GLenum, stride: GLsizei, ptr: *const c_void) {
    with_context(|ctx| ctx.fog_coord_pointer(type_, stride, ptr as usize))
}

#[unsafe(no_mangle)]
pub extern "C" fn glEnableClientState(array: GLenum) {
    with_context(|ctx| ctx.client_state(array, true))
}

#[unsafe(no_mangle)]
pub extern "C" fn glDisableClientState(array: GLenum) {
    with_context(|ctx| ctx.client_state(array, false))
}

/// `pointer` must stay valid, holding the elements later draws use, until it is replaced.
#[unsafe(no_mangle)]
pub extern "C" fn glInterleavedArrays(format: GLenum, stride: GLsizei, pointer: *const c_void) {
    with_context(|ctx| ctx.interleaved_arrays(format, stride, pointer as usize))
}

/// # Safety
/// `params` is NULL or has room for one pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetPointerv(pname: GLenum, params: *mut *mut c_void) {
    with_context(|ctx| {
        let address = ctx.get_pointer(pname)?;
        if params.is_null() {
            return Err(GlError::InvalidValue);
        }
        // SAFETY: the caller guarantees room for one pointer at a non-NULL `params`.
        unsafe { params.write_unaligned(address as *mut c_void) };
        Ok(())
    })
}

/// # Safety
/// The enabled arrays' pointers must hold element `i`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glArrayElement(i: GLint) {
    with_context(|ctx| {
        let element = ctx.check_array_element(i).and_then(|index| {
            let spans = ctx.vertex_arrays().spans(index, index)?;
            let unit_spans = ctx.vertex_arrays().unit_spans(index, index)?;
            // SAFETY: forwarded from the caller.
            let sources = unsafe { sources(index, &spans, &unit_spans) };
            ctx.array_element_values(index, &sources)
        });
        ctx.record_or_run(element.map_or_else(Command::Error, Command::ArrayElement))
    })
}

/// # Safety
/// The enabled arrays' pointers must hold elements `first..first + count`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei) {
    with_context(|ctx| {
        let indices = ctx.check_draw_arrays(mode, first, count);
        // SAFETY: forwarded from the caller.
        unsafe { draw(ctx, mode, indices) }
    })
}

/// The `primcount` values at `values`: GL_INVALID_VALUE for NULL when there are any.
///
/// # Safety
/// A non-NULL `values` must point to `primcount` readable values.
unsafe fn read_list<'a, T>(values: *const T, primcount: usize) -> GlResult<&'a [T]> {
    // SAFETY: forwarded from the caller.
    let list = unsafe { read(values, primcount) };
    if list.len() < primcount {
        return Err(GlError::InvalidValue);
    }
    Ok(list)
}

/// One draw of glMultiDrawArrays or glMultiDrawElements: its error is recorded as its own
/// call's would be, and the next draw still runs.
fn record(ctx: &mut Context, result: GlResult) {
    if let Err(error) = result {
        ctx.record_error(error);
    }
}

/// # Safety
/// `first` and `count` are NULL or point to `primcount` values; the enabled arrays' pointers
/// must hold every element the draws use.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glMultiDrawArrays(
    mode: GLenum,
    first: *const GLint,
    count: *const GLsizei,
    primcount: GLsizei,
) {
    with_context(|ctx| {
        let n = ctx.check_multi_draw(mode, None, primcount)?;
        // SAFETY: forwarded from the caller.
        let (first, count) = unsafe { (read_list(first, n)?, read_list(count, n)?) };
        for (&first, &count) in first.iter().zip(count).filter(|(_, count)| **count > 0) {
            let indices = ctx.check_draw_arrays(mode, first, count);
            // SAFETY: forwarded from the caller.
            let result = unsafe { draw(ctx, mode, indices) };
            record(ctx, result);
        }
        Ok(())
    })
}

/// # Safety
/// `count` and `indices` are NULL or point to `primcount` values, each `indices[i]` to
/// `count[i]` indices of `type_` (offsets into the element array buffer if one is bound);
/// the enabled arrays' pointers must hold every element they reference.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glMultiDrawElements(
    mode: GLenum,
    count: *const GLsizei,
    type_: GLenum,
    indices: *const *const c_void,
    primcount: GLsizei,
) {
    with_context(|ctx| {
        let n = ctx.check_multi_draw(mode, Some(type_), primcount)?;
        // SAFETY: forwarded from the caller.
        let (count, indices) = unsafe { (read_list(count, n)?, read_list(indices, n)?) };
        for (&count, &indices) in count.iter().zip(indices).filter(|(count, _)| **count > 0) {
            let size = ctx.check_draw_elements(mode, count, type_);
            // SAFETY: forwarded from the caller.
            let result = unsafe { draw_elements(ctx, mode, type_, indices, size) };
            record(ctx, result);
        }
        Ok(())
    })
}

/// Reads `size` bytes of indices at `indices`: NULL is GL_INVALID_OPERATION when there are
/// any to read.
///
/// # Safety
/// A non-NULL `indices` must point to `size` readable bytes.
unsafe fn read_indices<'a>(indices: *const c_void, size: usize) -> GlResult<&'a [u8]> {
    if size == 0 {
        Ok(&[])
    } else if indices.is_null() {
        Err(GlError::InvalidOperation)
    } else {
        // SAFETY: the caller guarantees `size` readable bytes; `size` is at most
        // i32::MAX * 4, well below isize::MAX.
        Ok(unsafe { std::slice::from_raw_parts(indices.cast::<u8>(), size) })
    }
}

/// Draws the `size` bytes of indices at `indices`: an offset into the buffer bound to
/// GL_ELEMENT_ARRAY_BUFFER if one is (GL_INVALID_OPERATION if they are not all in it),
/// else an address.
///
/// # Safety
/// Without an element array buffer, `indices` is NULL or points to `size` bytes; the
/// enabled arrays' pointers must hold every element they reference.
unsafe fn draw_elements(
    ctx: &mut Context,
    mode: GLenum,
    index_type: GLenum,
    indices: *const c_void,
    size: GlResult<usize>,
) -> GlResult {
    let store = size.and_then(|size| Ok((size, ctx.element_store()?)));
    let bytes = store
        .as_ref()
        .map_err(|e| *e)
        .and_then(|(size, store)| match store {
            Some(store) => {
                let offset = indices as usize;
                let range = offset..offset.checked_add(*size).ok_or(GlError::InvalidOperation)?;
                store.get(range).ok_or(GlError::InvalidOperation)
            }
            // SAFETY: forwarded from the caller.
            None => unsafe { read_indices(indices, *size) },
        });
    let indices = bytes.map(|bytes| ElementIndices::Listed { index_type, bytes });
    // SAFETY: forwarded from the caller.
    unsafe { draw(ctx, mode, indices) }
}

/// # Safety
/// `indices` is NULL or points to `count` indices of `type_` (an offset into the element
/// array buffer if one is bound); the enabled arrays' pointers must hold every element they
/// reference.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glDrawElements(
    mode: GLenum,
    count: GLsizei,
    type_: GLenum,
    indices: *const c_void,
) {
    with_context(|ctx| {
        let size = ctx.check_draw_elements(mode, count, type_);
        // SAFETY: forwarded from the caller.
        unsafe { draw_elements(ctx, mode, type_, indices, size) }
    })
}

/// `start` and `end` are not trusted: what is read is decided by the indices alone.
///
/// # Safety
/// `indices` is NULL or points to `count` indices of `type_`; the enabled arrays' pointers
/// must hold every element they reference.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glDrawRangeElements(
    mode: GLenum,
    start: GLuint,
    end: GLuint,
    count: GLsizei,
    type_: GLenum,
    indices: *const c_void,
) {
    with_context(|ctx| {
        let size = ctx.check_draw_range_elements(mode, start, end, count, type_);
        // SAFETY: forwarded from the caller.
        unsafe { draw_elements(ctx, mode, type_, indices, size) }
    })
}
