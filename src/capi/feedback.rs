//! glBegin, glEnd, glViewport, glDepthRange, glFeedbackBuffer, glRenderMode, glPassThrough.

use super::with_context;
use crate::gl::*;

#[unsafe(no_mangle)]
pub extern "C" fn glBegin(mode: GLenum) {
    with_context(|ctx| ctx.begin(mode))
}

#[unsafe(no_mangle)]
pub extern "C" fn glEnd() {
    with_context(|ctx| ctx.end())
}

#[unsafe(no_mangle)]
pub extern "C" fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
    with_context(|ctx| ctx.viewport(x, y, width, height))
}

#[unsafe(no_mangle)]
pub extern "C" fn glDepthRange(near: GLclampd, far: GLclampd) {
    with_context(|ctx| ctx.depth_range(near, far))
}

/// `buffer` must have room for `size` floats until glRenderMode ends feedback.
#[unsafe(no_mangle)]
pub extern "C" fn glFeedbackBuffer(size: GLsizei, kind: GLenum, buffer: *mut GLfloat) {
    with_context(|ctx| ctx.feedback_buffer(size, kind, buffer as usize))
}

/// Ending feedback writes the collected values (never more than the buffer's size) to the
/// buffer glFeedbackBuffer gave; ending selection writes the hit records (never more than the
/// buffer's size) to the buffer glSelectBuffer gave.
#[unsafe(no_mangle)]
pub extern "C" fn glRenderMode(mode: GLenum) -> GLint {
    with_context(|ctx| {
        let (count, finished) = ctx.render_mode(mode)?;
        if let Some(finished) = &finished {
            // SAFETY: glSelectBuffer's contract (the records are empty after feedback).
            unsafe { super::select::write_hit_records(finished) };
        }
        if let Some(finished) = finished.filter(|f| f.address != 0 && !f.values.is_empty()) {
            let buffer = finished.address as *mut GLfloat;
            // SAFETY: glFeedbackBuffer's contract: room for `size` floats, and the context
            // never keeps more than `size` values.
            unsafe {
                std::ptr::copy_nonoverlapping(
                    finished.values.as_ptr(),
                    buffer,
                    finished.values.len(),
                )
            };
        }
        Ok(count)
    })
}

#[unsafe(no_mangle)]
pub extern "C" fn glPassThrough(token: GLfloat) {
    with_context(|ctx| ctx.pass_through(token))
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
