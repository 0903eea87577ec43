//! glSelectBuffer, glInitNames, glPushName, glPopName, glLoadName (§5.2); glRenderMode, in
//! capi/feedback.rs, writes the hit records through `write_hit_records`.

use super::with_context;
use crate::commands::feedback::FinishedFeedback;
use crate::gl::*;

/// `buffer` must have room for `size` unsigned integers until glRenderMode ends selection.
#[unsafe(no_mangle)]
pub extern "C" fn glSelectBuffer(size: GLsizei, buffer: *mut GLuint) {
    with_context(|ctx| ctx.select_buffer(size, buffer as usize))
}

#[unsafe(no_mangle)]
pub extern "C" fn glInitNames() {
    with_context(|ctx| ctx.init_names())
}

#[unsafe(no_mangle)]
pub extern "C" fn glPushName(name: GLuint) {
    with_context(|ctx| ctx.push_name(name))
}

#[unsafe(no_mangle)]
pub extern "C" fn glPopName() {
    with_context(|ctx| ctx.pop_name())
}

#[unsafe(no_mangle)]
pub extern "C" fn glLoadName(name: GLuint) {
    with_context(|ctx| ctx.load_name(name))
}

/// Writes the hit records of a selection that ended to the buffer glSelectBuffer gave.
///
/// # Safety
/// glSelectBuffer's contract: room for `size` values at the address, and the context never
/// keeps more than `size` values.
pub(super) unsafe fn write_hit_records(finished: &FinishedFeedback) {
    if finished.address != 0 && !finished.hit_records.is_empty() {
        let buffer = finished.address as *mut GLuint;
        // SAFETY: forwarded from the caller.
        unsafe {
            std::ptr::copy_nonoverlapping(
                finished.hit_records.as_ptr(),
                buffer,
                finished.hit_records.len(),
            )
        };
    }
}
