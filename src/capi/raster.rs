//! glGetClipPlane (glClipPlane, glShadeModel, glFrontFace, glCullFace, glPolygonMode and
//! glRect are lines of entry_points.txt).

use super::{with_context, write};
use crate::gl::*;

/// # Safety
/// `equation` is NULL or has room for 4 values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glGetClipPlane(plane: GLenum, equation: *mut GLdouble) {
    with_context(|ctx| {
        let values = ctx.get_clip_plane(plane)?;
        // SAFETY: forwarded from the caller.
        unsafe { write(equation, &values) }
    })
}
