//! glFeedbackBuffer, glRenderMode, glFlush, glFinish.

use super::with_context;
use crate::gl::*;
use crate::pipeline::feedback::FeedbackStorage;

/// `buffer` must have room for `size` floats whenever the context is in feedback mode until
/// glFeedbackBuffer is called again: fed-back values are written straight into it, and
/// glRenderMode only returns their count.
#[unsafe(no_mangle)]
pub extern "C" fn glFeedbackBuffer(size: GLsizei, kind: GLenum, buffer: *mut GLfloat) {
    with_context(|ctx| {
        ctx.feedback_buffer(size, kind, buffer as usize)?;
        // SAFETY: the contract above; feedback_buffer accepted a non-NULL buffer for a
        // positive size.
        let memory = unsafe { ApplicationFloats::new(buffer, size as usize) };
        ctx.feedback_storage(FeedbackStorage::Application(memory));
        Ok(())
    })
}

/// Floats of the application's, written in place (the feedback buffer).
#[derive(Debug)]
pub struct ApplicationFloats {
    pointer: *mut GLfloat,
    len: usize,
}

// SAFETY: the memory belongs to the application, which may use the context on any thread;
// only the context that holds this writes through it.
unsafe impl Send for ApplicationFloats {}

impl ApplicationFloats {
    /// # Safety
    /// `pointer` is NULL with `len` 0, or has room for `len` floats for as long as the value
    /// lives, and nothing else writes there meanwhile.
    unsafe fn new(pointer: *mut GLfloat, len: usize) -> ApplicationFloats {
        ApplicationFloats { pointer, len }
    }

    /// The application's floats, to read.
    pub fn as_slice(&self) -> &[GLfloat] {
        if self.len == 0 {
            return &[];
        }
        // SAFETY: the promise of `new`.
        unsafe { std::slice::from_raw_parts(self.pointer, self.len) }
    }

    /// The application's floats, to write.
    pub fn as_mut_slice(&mut self) -> &mut [GLfloat] {
        if self.len == 0 {
            return &mut [];
        }
        // SAFETY: the promise of `new`.
        unsafe { std::slice::from_raw_parts_mut(self.pointer, self.len) }
    }
}

/// Fed-back values are already in the buffer glFeedbackBuffer gave; ending selection writes
/// the hit records (never more than the buffer's size) to the buffer glSelectBuffer gave.
#[unsafe(no_mangle)]
pub extern "C" fn glRenderMode(mode: GLenum) -> GLint {
    with_context(|ctx| {
        let (count, finished) = ctx.render_mode(mode)?;
        if let Some(finished) = &finished {
            // SAFETY: glSelectBuffer's contract (the records are empty after feedback).
            unsafe { super::select::write_hit_records(finished) };
        }
        Ok(count)
    })
}

/// Every command has finished when it returns: there is nothing to flush.
#[unsafe(no_mangle)]
pub extern "C" fn glFlush() {
    with_context(|ctx| ctx.finish())
}

/// Every command has finished when it returns: there is nothing to wait for.
#[unsafe(no_mangle)]
pub extern "C" fn glFinish() {
    with_context(|ctx| ctx.finish())
}
