//! glCallLists (§5.4), whose names come in any of ten types (the other display list
//! commands are lines of entry_points.txt).

use std::ffi::c_void;

use super::{read, with_context};
use crate::commands::list::{Command, call_lists_bytes};
use crate::gl::*;

/// While a list is being compiled, the offsets are read then and compiled; the list base is
/// the one in force when the list executes.
///
/// # Safety
/// `lists` is NULL or points to `n` names of `type_`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glCallLists(n: GLsizei, type_: GLenum, lists: *const c_void) {
    with_context(|ctx| {
        // SAFETY: forwarded from the caller.
        let bytes = unsafe { read(lists.cast::<u8>(), call_lists_bytes(n, type_)) };
        let offsets = ctx.call_lists_offsets(n, type_, bytes);
        ctx.record_or_run(offsets.map_or_else(Command::Error, Command::CallLists))
    })
}
