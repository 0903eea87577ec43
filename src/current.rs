//! Which context each thread is using (GL's "current context").
//!
//! A context is owned by its handle while no thread uses it; making it current moves it into
//! the thread's slot, so GL calls reach it without any lock, and a context current on one
//! thread cannot be made current on another.

use std::cell::RefCell;
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

/// The context current on this thread, out of its handle until released.
struct Current {
    handle: Arc<FflContext>,
    context: Option<Box<Context>>,
}

impl Drop for Current {
    fn drop(&mut self) {
        if let Some(context) = self.context.take() {
            self.handle.put_back(context);
        }
    }
}

thread_local! {
    static CURRENT: RefCell<Option<Current>> = const { RefCell::new(None) };
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

/// Runs `f` on this thread's current context; with none current, on the thread's default one.
/// `None` when the thread is exiting or the call is re-entrant (a GL call from a callback).
///
/// # Examples
///
/// ```
/// use fflight::{current::with_current, gl::*};
/// // The thread's default context, created on first use, as the C entry points see it.
/// with_current(|ctx| ctx.set_capability(GL_LIGHTING, true)).unwrap()?;
/// assert_eq!(with_current(|ctx| ctx.is_enabled(GL_LIGHTING)).unwrap(), Ok(true));
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn with_current<R>(f: impl FnOnce(&mut Context) -> R) -> Option<R> {
    CURRENT
        .try_with(|slot| {
            let mut slot = slot.try_borrow_mut().ok()?;
            if slot.is_none() {
                let handle = default_handle()?;
                // The default is current on another thread (its pointer was handed there):
                // it is not current here too, until that thread releases it.
                let context = handle.take()?;
                *slot = Some(Current {
                    handle,
                    context: Some(context),
                });
            }
            slot.as_mut()?.context.as_deref_mut().map(f)
        })
        .ok()
        .flatten()
}

/// Makes `handle` current on this thread (`None` releases the current one). A context that is
/// current on another thread is GL_INVALID_OPERATION, and nothing changes.
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
    CURRENT
        .try_with(|slot| {
            let mut slot = slot
                .try_borrow_mut()
                .map_err(|_| GlError::InvalidOperation)?;
            if let (Some(current), Some(handle)) = (slot.as_ref(), handle.as_ref())
                && Arc::ptr_eq(&current.handle, handle)
            {
                return Ok(());
            }
            let next = match handle {
                Some(handle) => {
                    let context = handle.take().ok_or(GlError::InvalidOperation)?;
                    Some(Current {
                        handle,
                        context: Some(context),
                    })
                }
                None => None,
            };
            *slot = next; // the previous context goes back to its handle
            Ok(())
        })
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
        .try_with(|slot| {
            let slot = slot.try_borrow().ok()?;
            slot.as_ref().map(|current| current.handle.clone())
        })
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
