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

    /// The floats `range` of them, to write (only those: another thread may write others,
    /// `ApplicationPlaces`).
    pub(crate) fn range_mut(&mut self, range: std::ops::Range<usize>) -> &mut [GLfloat] {
        assert!(range.start <= range.end && range.end <= self.len);
        if range.is_empty() {
            return &mut [];
        }
        // SAFETY: inside the memory (checked), which `new` promises writable.
        unsafe { std::slice::from_raw_parts_mut(self.pointer.add(range.start), range.len()) }
    }

    /// The first `len` floats of the same memory (or all of it, if fewer), for another
    /// thread to write parts of (`ApplicationPlaces`).
    pub(crate) fn places(&mut self, len: usize) -> ApplicationPlaces {
        ApplicationPlaces {
            pointer: self.pointer,
            len: self.len.min(len),
        }
    }
}

/// The application's feedback memory as a thread without the context sees it: the immediate
/// mode helper writes there the points it lays out, each chunk's values in a place no other
/// thread writes or reads meanwhile (`commands::vertex::helper`'s frontier).
#[derive(Clone, Copy, Debug)]
pub(crate) struct ApplicationPlaces {
    pointer: *mut GLfloat,
    len: usize,
}

// SAFETY: the memory is the application's, alive while the context keeps its `ApplicationFloats`;
// `write`'s contract keeps the writers of each part apart.
unsafe impl Send for ApplicationPlaces {}
unsafe impl Sync for ApplicationPlaces {}

impl ApplicationPlaces {
    /// `values` as memory of a test's own, kept for the life of the program (its address in
    /// a static list: memcheck counts it reachable, not leaked).
    #[cfg(test)]
    pub(crate) fn kept_for_tests(values: Vec<GLfloat>) -> ApplicationPlaces {
        static KEPT: std::sync::Mutex<Vec<usize>> = std::sync::Mutex::new(Vec::new());
        let values: &'static mut [GLfloat] = Box::leak(values.into_boxed_slice());
        let pointer = values.as_mut_ptr();
        KEPT.lock()
            .unwrap_or_else(|e| e.into_inner())
            .push(pointer as usize);
        ApplicationPlaces {
            pointer,
            len: values.len(),
        }
    }

    /// The floats, read once no thread writes them (tests).
    #[cfg(test)]
    pub(crate) fn read(&self) -> Vec<GLfloat> {
        // SAFETY: the memory `kept_for_tests` keeps; the caller's promise that no one writes.
        unsafe { std::slice::from_raw_parts(self.pointer, self.len) }.to_vec()
    }

    /// How many floats the memory holds.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Copies `values` to the floats from `start` (they must fit: `start + values.len()` at
    /// most `len`), with `copy_streaming`.
    ///
    /// # Safety
    /// The context's `ApplicationFloats` is still installed, and no other thread reads or
    /// writes those floats until this thread hands them over (with a release store).
    pub(crate) unsafe fn write(&self, start: usize, values: &[GLfloat]) {
        assert!(start <= self.len && values.len() <= self.len - start);
        if values.is_empty() {
            return;
        }
        // SAFETY: inside the memory (checked), which `new` promises writable and the caller
        // keeps to this thread.
        let to = unsafe { std::slice::from_raw_parts_mut(self.pointer.add(start), values.len()) };
        crate::pipeline::streaming::copy_streaming(to, values);
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
