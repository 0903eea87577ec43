//! Context management for applications with several contexts (`ffl*`). Legacy code needs
//! none of it: each thread gets a default context on its first GL call.

use std::sync::Arc;

use super::with_context;
use crate::current::{self, FflContext};
use crate::error::GlError;
use crate::gl::*;

/// Creates a context with GL's initial state. It is not made current.
#[unsafe(no_mangle)]
pub extern "C" fn fflCreateContext() -> *mut FflContext {
    Arc::into_raw(FflContext::new()).cast_mut()
}

/// Makes `context` current on the calling thread (NULL releases the current context).
/// Returns GL_FALSE, and records GL_INVALID_OPERATION, when the context is current on
/// another thread.
///
/// # Safety
/// `context` is NULL or a live pointer from `fflCreateContext`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fflMakeCurrent(context: *mut FflContext) -> GLboolean {
    let handle = (!context.is_null()).then(|| {
        // SAFETY: a live pointer from fflCreateContext: take a new reference to it.
        unsafe {
            Arc::increment_strong_count(context);
            Arc::from_raw(context.cast_const())
        }
    });
    match current::make_current(handle) {
        Ok(()) => GL_TRUE,
        Err(error) => {
            with_context::<()>(|_| Err(error));
            GL_FALSE
        }
    }
}

/// The calling thread's current context (its default one, once a GL call has made it), or NULL.
#[unsafe(no_mangle)]
pub extern "C" fn fflGetCurrentContext() -> *mut FflContext {
    current::current_handle().map_or(std::ptr::null_mut(), |handle| {
        Arc::as_ptr(&handle).cast_mut()
    })
}

/// Destroys `context`. A context current on the calling thread is released first; one current
/// on another thread, or a thread's default context, is not destroyed (GL_FALSE,
/// GL_INVALID_OPERATION).
///
/// # Safety
/// `context` is NULL or a live pointer from `fflCreateContext`; it must not be used after.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fflDestroyContext(context: *mut FflContext) -> GLboolean {
    if context.is_null() {
        return GL_FALSE;
    }
    // SAFETY: a live pointer from fflCreateContext: borrow it without taking ownership.
    let handle = unsafe {
        Arc::increment_strong_count(context);
        Arc::from_raw(context.cast_const())
    };
    if current::current_elsewhere(&handle) || handle.is_thread_default() {
        with_context::<()>(|_| Err(GlError::InvalidOperation));
        return GL_FALSE;
    }
    if current::current_handle().is_some_and(|current| Arc::ptr_eq(&current, &handle)) {
        let _ = current::make_current(None);
    }
    drop(handle);
    // SAFETY: releases the reference fflCreateContext returned.
    unsafe { drop(Arc::from_raw(context.cast_const())) };
    GL_TRUE
}

/// Sets how many threads fflight may use for large draws, bulk calls and immediate mode's
/// batches of vertices (process-wide):
/// 1 keeps all work on the calling thread, 0 restores the default (the environment variable
/// FFLIGHT_THREADS, else the number of cores). Results are the same whatever the count.
/// GL_INVALID_VALUE for a negative count.
#[unsafe(no_mangle)]
pub extern "C" fn fflSetThreads(count: GLint) {
    with_context(|_| crate::threads::set_threads(count))
}

/// How many threads fflight uses for large draws and bulk calls.
#[unsafe(no_mangle)]
pub extern "C" fn fflGetThreads() -> GLint {
    with_context(|_| Ok(crate::threads::thread_count() as GLint))
}
