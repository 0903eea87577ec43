//! Which context each thread is using (GL's "current context").
//!
//! A context is owned by its handle while no thread uses it; making it current moves it into
//! the thread's slot, so GL calls reach it without any lock, and a context current on one
//! thread cannot be made current on another.

use std::cell::{Cell, RefCell};
use std::mem::ManuallyDrop;
use std::sync::{Arc, Mutex};

use crate::context::Context;
use crate::error::{GlError, GlResult};

/// A context as applications hold it (`FflContext *` in C).
#[derive(Debug, Default)]
pub struct FflContext {
    /// The context while no thread has it current.
    idle: Mutex<Option<Box<Context>>>,
    /// Whether this is a thread's default context, which lives as long as its thread.
    thread_default: bool,
}

impl FflContext {
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::current::{FflContext, current_handle, make_current};
    /// let context = FflContext::new();
    /// make_current(Some(context.clone()))?;
    /// assert!(current_handle().is_some_and(|h| std::sync::Arc::ptr_eq(&h, &context)));
    /// make_current(None)?; // back to the thread's default context
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn new() -> Arc<FflContext> {
        Arc::new(FflContext {
            idle: Mutex::new(Some(Box::new(Context::new()))),
            thread_default: false,
        })
    }

    fn new_thread_default() -> Arc<FflContext> {
        Arc::new(FflContext {
            idle: Mutex::new(Some(Box::new(Context::new()))),
            thread_default: true,
        })
    }

    /// Whether this is some thread's default context (only the thread's end destroys it).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::current::FflContext;
    /// assert!(!FflContext::new().is_thread_default());
    /// ```
    pub fn is_thread_default(&self) -> bool {
        self.thread_default
    }

    fn take(&self) -> Option<Box<Context>> {
        self.idle.lock().unwrap_or_else(|e| e.into_inner()).take()
    }

    fn put_back(&self, context: Box<Context>) {
        *self.idle.lock().unwrap_or_else(|e| e.into_inner()) = Some(context);
    }
}

/// The context current on this thread, while no GL call of this thread has it out (a call
/// takes it for its duration, so a re-entrant call finds the cell empty with a handle set,
/// and is refused; the attribute commands' usual case, which calls nothing, uses it where it
/// is: `current_cell`). A cell with no destructor, so that a call reaches it at one thread-local
/// address, with no check that it is initialized or registration of a destructor (the
/// attribute commands' usual case then needs no stack frame); `Slot`, whose destructor is
/// registered when a context is first made current here, gives it back at the thread's end.
type ContextCell = Cell<ManuallyDrop<Option<Box<Context>>>>;

/// Takes the context out of its cell.
#[inline(always)]
fn take(cell: &ContextCell) -> Option<Box<Context>> {
    ManuallyDrop::into_inner(cell.take())
}

/// Puts `context` in its cell, which is empty (holds nothing to drop).
#[inline(always)]
fn put(cell: &ContextCell, context: Option<Box<Context>>) {
    let empty = cell.replace(ManuallyDrop::new(context));
    debug_assert!(empty.is_none());
}

/// This thread's current context's handle.
struct Slot {
    handle: RefCell<Option<Arc<FflContext>>>,
}

impl Drop for Slot {
    fn drop(&mut self) {
        // The thread ends: its current context goes back to its handle. (The cell, which
        // has no destructor, is still there.)
        let context = CONTEXT.try_with(take).ok().flatten();
        if let (Some(handle), Some(context)) = (self.handle.get_mut().take(), context) {
            handle.put_back(context);
        }
    }
}

/// The current context, out of its cell: gives it back when the call ends, also when it
/// unwinds.
pub(crate) struct Borrowed {
    context: Option<Box<Context>>,
}

impl Borrowed {
    /// The context (always there: `None` is a branch never taken, not a panic).
    #[inline(always)]
    pub(crate) fn context(&mut self) -> Option<&mut Context> {
        self.context.as_deref_mut()
    }
}

impl Drop for Borrowed {
    #[inline(always)]
    fn drop(&mut self) {
        let context = self.context.take();
        CONTEXT.with(|cell| put(cell, context));
    }
}

thread_local! {
    static CONTEXT: ContextCell = const { Cell::new(ManuallyDrop::new(None)) };
    static CURRENT: Slot = const {
        Slot {
            handle: RefCell::new(None),
        }
    };
    /// The context a thread falls back to when none is current: made on its first GL call,
    /// kept for the thread's life, so releasing another context returns to it intact.
    static DEFAULT: RefCell<Option<Arc<FflContext>>> = const { RefCell::new(None) };
}

fn default_handle() -> Option<Arc<FflContext>> {
    DEFAULT
        .try_with(|slot| {
            slot.borrow_mut()
                .get_or_insert_with(FflContext::new_thread_default)
                .clone()
        })
        .ok()
}

/// The thread's default context made current, when no context is (the first GL call);
/// `None` when one is current but a call has it out (a re-entrant call), or the thread is
/// ending.
#[cold]
#[inline(never)]
fn current_default() -> Option<Box<Context>> {
    CURRENT
        .try_with(|slot| {
            let mut handle = slot.handle.try_borrow_mut().ok()?;
            if handle.is_some() {
                return None;
            }
            let default = default_handle()?;
            // The default is current on another thread (its pointer was handed there): it is
            // not current here too, until that thread releases it.
            let context = default.take()?;
            *handle = Some(default);
            Some(context)
        })
        .ok()
        .flatten()
}

/// Runs `f` on this thread's current context; with none current, on the thread's default one.
/// `None` when the thread is exiting or the call is re-entrant (a GL call from a callback).
///
/// This runs around every GL call: a thread-local access, and the context moved out of its
/// cell and back (two pointer stores), nothing more while a context is current (but for
/// collecting the points of a primitive still lit by the helper thread after its glEnd:
/// `Context::collect_carried`).
///
/// # Examples
///
/// ```
/// use fflight::{current::with_current, gl::*};
/// // The thread's default context, created on first use, as the C entry points see it.
/// with_current(|ctx| ctx.set_capability(GL_LIGHTING, true)).unwrap()?;
/// assert_eq!(with_current(|ctx| ctx.is_enabled(GL_LIGHTING)).unwrap(), Ok(true));
/// // A GL call made from inside a GL call is refused.
/// assert_eq!(with_current(|_| with_current(|_| ())), Some(None));
/// # Ok::<(), fflight::GlError>(())
/// ```
#[inline(always)]
pub fn with_current<R>(f: impl FnOnce(&mut Context) -> R) -> Option<R> {
    with_current_overlapping(|ctx| {
        ctx.collect_carried();
        f(ctx)
    })
}

/// `with_current` that leaves in flight the batches of points a primitive left to the helper
/// thread at its glEnd (`Context::collect_carried`): for glBegin, whose primitive collects
/// them first.
#[inline(always)]
pub(crate) fn with_current_overlapping<R>(f: impl FnOnce(&mut Context) -> R) -> Option<R> {
    let context = match CONTEXT.with(take) {
        Some(context) => context,
        None => current_default()?,
    };
    Borrowed {
        context: Some(context),
    }
    .context()
    .map(f)
}

/// This thread's cell of the current context, for a command's usual case to use the context
/// in place (`capi::quick!`).
#[inline(always)]
pub(crate) fn current_cell() -> *mut Option<Box<Context>> {
    CONTEXT.with(|cell| cell.as_ptr().cast())
}

/// Makes `handle` current on this thread (`None` releases the current one). A context that is
/// current on another thread is GL_INVALID_OPERATION, and nothing changes; so is a call made
/// while a GL call of this thread is running.
///
/// # Examples
///
/// ```
/// use fflight::{current::{FflContext, make_current, with_current}, gl::*};
/// let context = FflContext::new();
/// make_current(Some(context.clone()))?;
/// with_current(|ctx| ctx.set_capability(GL_NORMALIZE, true)).unwrap()?;
/// make_current(None)?;
/// // The default context did not see the change.
/// assert_eq!(with_current(|ctx| ctx.is_enabled(GL_NORMALIZE)).unwrap(), Ok(false));
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn make_current(handle: Option<Arc<FflContext>>) -> GlResult {
    let cell = |slot: &Slot| {
        CONTEXT
            .try_with(|cell| {
                let mut current = slot
                    .handle
                    .try_borrow_mut()
                    .map_err(|_| GlError::InvalidOperation)?;
                let context = take(cell);
                if current.is_some() && context.is_none() {
                    return Err(GlError::InvalidOperation); // a GL call has it out
                }
                if let (Some(current), Some(handle)) = (current.as_ref(), handle.as_ref())
                    && Arc::ptr_eq(current, handle)
                {
                    put(cell, context);
                    return Ok(());
                }
                let next = match &handle {
                    Some(handle) => match handle.take() {
                        Some(next) => Some(next),
                        None => {
                            put(cell, context);
                            return Err(GlError::InvalidOperation);
                        }
                    },
                    None => None,
                };
                // The previous context goes back to its handle.
                if let (Some(previous), Some(context)) = (current.take(), context) {
                    previous.put_back(context);
                }
                *current = handle;
                put(cell, next);
                Ok(())
            })
            .unwrap_or(Err(GlError::InvalidOperation))
    };
    CURRENT
        .try_with(cell)
        .unwrap_or(Err(GlError::InvalidOperation))
}

/// The handle of this thread's current context, if any.
///
/// # Examples
///
/// ```
/// use fflight::current::{current_handle, make_current, with_current};
/// make_current(None)?;
/// assert!(current_handle().is_none());
/// with_current(|_| ()); // a GL call makes the thread's default context current
/// assert!(current_handle().is_some_and(|h| h.is_thread_default()));
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn current_handle() -> Option<Arc<FflContext>> {
    CURRENT
        .try_with(|slot| slot.handle.try_borrow().ok()?.clone())
        .ok()
        .flatten()
}

/// Whether the context behind `handle` is current on some thread other than this one.
///
/// # Examples
///
/// ```
/// use fflight::current::{current_elsewhere, make_current, FflContext};
/// let context = FflContext::new();
/// make_current(Some(context.clone()))?;
/// assert!(!current_elsewhere(&context)); // current here, not on another thread
/// let other = context.clone();
/// std::thread::spawn(move || assert!(current_elsewhere(&other))).join().unwrap();
/// make_current(None)?;
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn current_elsewhere(handle: &Arc<FflContext>) -> bool {
    let here = current_handle().is_some_and(|current| Arc::ptr_eq(&current, handle));
    !here
        && handle
            .idle
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .is_none()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_context_current_elsewhere_cannot_be_made_current() {
        let handle = FflContext::new();
        make_current(Some(handle.clone())).unwrap();
        let other = handle.clone();
        let result = std::thread::spawn(move || make_current(Some(other)))
            .join()
            .unwrap();
        assert_eq!(result, Err(GlError::InvalidOperation));
        make_current(None).unwrap();
        let other = handle.clone();
        let result = std::thread::spawn(move || make_current(Some(other)))
            .join()
            .unwrap();
        assert_eq!(result, Ok(()));
    }

    #[test]
    fn a_context_current_on_a_thread_that_ends_returns_to_its_handle() {
        let handle = FflContext::new();
        let other = handle.clone();
        std::thread::spawn(move || {
            make_current(Some(other)).unwrap();
            with_current(|ctx| ctx.normal(glam::Vec3::X)).unwrap();
        })
        .join()
        .unwrap();
        assert!(!current_elsewhere(&handle));
        make_current(Some(handle)).unwrap();
        assert_eq!(with_current(|ctx| ctx.current.normal), Some(glam::Vec3::X));
        make_current(None).unwrap();
    }

    #[test]
    fn releasing_a_context_returns_to_the_thread_default_intact() {
        with_current(|ctx| ctx.normal(glam::Vec3::Y)).unwrap();
        let other = FflContext::new();
        make_current(Some(other.clone())).unwrap();
        assert_eq!(with_current(|ctx| ctx.current.normal), Some(glam::Vec3::Z));
        make_current(None).unwrap();
        assert_eq!(with_current(|ctx| ctx.current.normal), Some(glam::Vec3::Y));
    }

    #[test]
    fn each_thread_gets_its_own_default_context() {
        with_current(|ctx| ctx.normal(glam::Vec3::X)).unwrap();
        let other = std::thread::spawn(|| with_current(|ctx| ctx.current.normal).unwrap())
            .join()
            .unwrap();
        assert_eq!(other, glam::Vec3::Z);
        assert_eq!(with_current(|ctx| ctx.current.normal), Some(glam::Vec3::X));
    }
}
