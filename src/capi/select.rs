//! glSelectBuffer (§5.2; the name stack commands are lines of entry_points.txt); glRenderMode, in
//! capi/feedback.rs, writes the hit records through `write_hit_records`.

use super::with_context;
use crate::commands::feedback::FinishedFeedback;
use crate::gl::*;

/// `buffer` must have room for `size` unsigned integers until glRenderMode ends selection.
#[unsafe(no_mangle)]
pub extern "C" fn glSelectBuffer(size: GLsizei, buffer: *mut GLuint) {
    with_context(|ctx| ctx.select_buffer(size, buffer as usize))
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
