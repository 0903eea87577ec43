//! The C ABI: every exported GL entry point. The only `unsafe` code of the crate.
//!
//! Each entry point decodes its pointers into slices and runs one `Context` method through
//! `with_context`, which finds the current context, records the GL error and keeps Rust
//! panics from crossing into C.
#![allow(unsafe_code)]

mod arrays;
mod attribs;
mod buffers;
mod bulk_lanes;
mod capture;
mod context;
mod feedback;
#[rustfmt::skip]
mod generated;
mod lighting;
mod list;
mod query;
mod raster;
mod raster_pos;
mod select;
mod texture;

pub use feedback::ApplicationFloats;
pub(crate) use feedback::ApplicationPlaces;
pub use generated::TableCommand;

use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::context::Context;
use crate::current;
use crate::error::GlResult;

/// The guard around every entry point: runs `command` on the current context, records its
/// error, and returns `R::default()` on an error, a panic, or when no context can be had.
/// Batches of points a primitive left in flight at its glEnd are collected first.
pub(crate) fn with_context<R: Default>(command: impl FnOnce(&mut Context) -> GlResult<R>) -> R {
    guarded(|| {
        current::with_current(|ctx| {
            let result = command(ctx);
            ctx.settle(result)
        })
    })
}

/// `with_context` for glBegin, whose primitive collects those batches itself, in order.
pub(crate) fn with_context_overlapping<R: Default>(
    command: impl FnOnce(&mut Context) -> GlResult<R>,
) -> R {
    guarded(|| {
        current::with_current_overlapping(|ctx| {
            let result = command(ctx);
            ctx.settle(result)
        })
    })
}

/// `run`, which keeps panics from crossing into C; `R::default()` when it gives nothing.
fn guarded<R: Default>(run: impl FnOnce() -> Option<R>) -> R {
    catch_unwind(AssertUnwindSafe(run))
        .ok()
        .flatten()
        .unwrap_or_default()
}

/// The guard of a command's usual case, which cannot panic (no indexing, no call): runs
/// `$command` (an expression of `$ctx` that is whether it did the command) on the current
/// context outside display list compilation, and is `false` (the command not done) in a list
/// or when no context is in this thread's cell, for the caller to run the command through
/// `with_context`. Without
/// `catch_unwind`, whose closure the compiler keeps out of line, and without a closure of
/// its own, so that the usual case of glVertex needs no saved registers; were a panic to
/// happen here anyway, the `extern "C"` boundary aborts rather than unwind into C. The
/// context is used in its cell, not taken out and put back as `with_context` does (which a
/// re-entrant call must find empty; the usual case calls nothing): two stores fewer a
/// command, and with the components read only after the checks (`attribute!`), immediate
/// mode 1 light median pair ratio 0.94 on two threads (6 of 8 faster), 0.96 on one (4 of 6).
macro_rules! quick {
    (|$ctx:ident| $command:expr) => {
        // SAFETY: the cell is this thread's, and nothing else reaches it while the usual
        // case runs (it calls nothing).
        match unsafe { &mut *crate::current::current_cell() } {
            Some($ctx) if !$ctx.compiling_list() => $command,
            _ => false,
        }
    };
}
pub(crate) use quick;

/// Whether `count` values are more than any memory holds (isize::MAX bytes): a size made of
/// hostile arguments, which no pointer can honor; it reads nothing, like NULL.
fn beyond_memory<T>(count: usize) -> bool {
    count > isize::MAX as usize / std::mem::size_of::<T>().max(1)
}

/// `count` values at `ptr`, or an empty slice for NULL (the command then reports
/// GL_INVALID_VALUE when it needs values).
///
/// # Safety
/// A non-NULL `ptr` must point to at least `count` readable values.
pub(crate) unsafe fn read<'a, T>(ptr: *const T, count: usize) -> &'a [T] {
    if ptr.is_null() || beyond_memory::<T>(count) {
        &[]
    } else {
        // SAFETY: the caller guarantees `count` readable values at a non-NULL `ptr`.
        unsafe { std::slice::from_raw_parts(ptr, count) }
    }
}

/// `count` values at `ptr` for the command to write into, or an empty slice for NULL (the
/// command then reports GL_INVALID_VALUE).
///
/// # Safety
/// A non-NULL `ptr` must point to at least `count` writable values.
pub(crate) unsafe fn read_mut<'a, T>(ptr: *mut T, count: usize) -> &'a mut [T] {
    if ptr.is_null() || beyond_memory::<T>(count) {
        &mut []
    } else {
        // SAFETY: the caller guarantees `count` writable values at a non-NULL `ptr`.
        unsafe { std::slice::from_raw_parts_mut(ptr, count) }
    }
}

/// Writes `values` to `ptr`; a NULL destination for values to write is GL_INVALID_VALUE
/// (with nothing to write, any pointer will do: glGenQueries(0, NULL) is no error).
///
/// # Safety
/// A non-NULL `ptr` must have room for `values.len()` values.
pub(crate) unsafe fn write<T: Copy>(ptr: *mut T, values: &[T]) -> GlResult {
    if values.is_empty() {
        return Ok(());
    }
    if ptr.is_null() {
        return Err(crate::error::GlError::InvalidValue);
    }
    // SAFETY: the caller guarantees room for `values.len()` values at a non-NULL `ptr`.
    unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), ptr, values.len()) };
    Ok(())
}
