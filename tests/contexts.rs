//! The context API (src/capi/context.rs, src/current.rs): fflCreateContext, fflMakeCurrent,
//! fflGetCurrentContext, fflDestroyContext. Contexts keep separate state; a context current on
//! one thread cannot be made current on, or destroyed from, another; each thread that makes a
//! GL call without one gets a default context.

#[macro_use]
mod common;

use std::sync::mpsc;
use std::thread;

use common::*;

/// A context pointer that can cross threads (the API is what keeps its use safe).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Handle(usize);

impl Handle {
    fn create() -> Handle {
        let context = fflCreateContext();
        assert!(!context.is_null());
        Handle(context as usize)
    }

    fn ptr(self) -> ContextPtr {
        self.0 as ContextPtr
    }

    fn make_current(self) -> GLboolean {
        // SAFETY: a live context from fflCreateContext (the tests destroy each one last).
        unsafe { fflMakeCurrent(self.ptr()) }
    }

    fn destroy(self) -> GLboolean {
        // SAFETY: as above; not used after.
        unsafe { fflDestroyContext(self.ptr()) }
    }

    fn current() -> Option<Handle> {
        let context = fflGetCurrentContext();
        (!context.is_null()).then_some(Handle(context as usize))
    }
}

fn release() -> GLboolean {
    // SAFETY: NULL releases the current context.
    unsafe { fflMakeCurrent(std::ptr::null_mut()) }
}

fn normal() -> Vec<f32> {
    get_floats(GL_CURRENT_NORMAL, 3)
}

/// Runs `f` on a new thread and returns its result (each test body that cares about the
/// thread's own default context runs this way).
fn on_new_thread<R: Send + 'static>(f: impl FnOnce() -> R + Send + 'static) -> R {
    thread::spawn(f).join().expect("thread panicked")
}

#[test]
fn a_thread_has_no_current_context_until_its_first_gl_call() {
    on_new_thread(|| {
        assert_eq!(Handle::current(), None);
        glGetError();
        let default = Handle::current().expect("a default context after a GL call");
        glNormal3f(1.0, 0.0, 0.0);
        assert_eq!(
            Handle::current(),
            Some(default),
            "the default context stays current"
        );
        assert_eq!(normal(), [1.0, 0.0, 0.0]);
    });
}

#[test]
fn created_contexts_are_distinct_and_not_made_current() {
    on_new_thread(|| {
        let (a, b) = (Handle::create(), Handle::create());
        assert_ne!(a, b);
        assert_eq!(
            Handle::current(),
            None,
            "fflCreateContext made a context current"
        );
        assert_eq!(a.make_current(), GL_TRUE);
        assert_eq!(Handle::current(), Some(a));
        assert_eq!(b.make_current(), GL_TRUE);
        assert_eq!(Handle::current(), Some(b));
        assert_eq!(release(), GL_TRUE);
        assert_eq!(Handle::current(), None);
        assert_eq!(a.destroy(), GL_TRUE);
        assert_eq!(b.destroy(), GL_TRUE);
    });
}

#[test]
fn two_contexts_keep_separate_state() {
    on_new_thread(|| {
        let (a, b) = (Handle::create(), Handle::create());
        a.make_current();
        glNormal3f(1.0, 0.0, 0.0);
        glEnable(GL_LIGHTING);
        light_fv(GL_LIGHT2, GL_DIFFUSE, &[0.5, 0.25, 0.125, 1.0]);
        glMatrixMode(GL_PROJECTION);
        glPushMatrix();

        b.make_current();
        assert_eq!(normal(), [0.0, 0.0, 1.0]);
        assert_eq!(glIsEnabled(GL_LIGHTING), GL_FALSE);
        assert_eq!(get_light(GL_LIGHT2, GL_DIFFUSE, 4), [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(get_int(GL_MATRIX_MODE), GL_MODELVIEW as i32);
        assert_eq!(get_int(GL_PROJECTION_STACK_DEPTH), 1);
        glNormal3f(0.0, 1.0, 0.0);

        a.make_current();
        assert_eq!(normal(), [1.0, 0.0, 0.0]);
        assert_eq!(glIsEnabled(GL_LIGHTING), GL_TRUE);
        assert_eq!(get_light(GL_LIGHT2, GL_DIFFUSE, 4), [0.5, 0.25, 0.125, 1.0]);
        assert_eq!(get_int(GL_MATRIX_MODE), GL_PROJECTION as i32);
        assert_eq!(get_int(GL_PROJECTION_STACK_DEPTH), 2);

        b.make_current();
        assert_eq!(normal(), [0.0, 1.0, 0.0]);
        release();
        a.destroy();
        b.destroy();
    });
}

#[test]
fn each_context_has_its_own_error_flag() {
    on_new_thread(|| {
        let (a, b) = (Handle::create(), Handle::create());
        a.make_current();
        glEnable(0x1234);
        b.make_current();
        assert_eq!(glGetError(), GL_NO_ERROR);
        glPopMatrix();
        a.make_current();
        assert_eq!(error_name(glGetError()), "GL_INVALID_ENUM");
        b.make_current();
        assert_eq!(error_name(glGetError()), "GL_STACK_UNDERFLOW");
        release();
        a.destroy();
        b.destroy();
    });
}

#[test]
fn making_the_current_context_current_again_changes_nothing() {
    on_new_thread(|| {
        let a = Handle::create();
        a.make_current();
        glNormal3f(0.0, 0.0, -1.0);
        assert_eq!(a.make_current(), GL_TRUE);
        assert_eq!(normal(), [0.0, 0.0, -1.0]);
        assert_eq!(Handle::current(), Some(a));
        release();
        a.destroy();
    });
}

#[test]
fn releasing_returns_to_the_threads_default_context_intact() {
    on_new_thread(|| {
        glNormal3f(0.0, -1.0, 0.0);
        let default = Handle::current().expect("a default context");
        let a = Handle::create();
        a.make_current();
        assert_eq!(
            normal(),
            [0.0, 0.0, 1.0],
            "a created context has the initial state"
        );
        glNormal3f(1.0, 0.0, 0.0);
        assert_eq!(release(), GL_TRUE);
        assert_eq!(Handle::current(), None);
        // the next GL call goes to the thread's default context, as it was
        assert_eq!(normal(), [0.0, -1.0, 0.0]);
        assert_eq!(Handle::current(), Some(default));
        // and `a` kept its state
        a.make_current();
        assert_eq!(normal(), [1.0, 0.0, 0.0]);
        release();
        a.destroy();
    });
}

#[test]
fn a_threads_default_context_cannot_be_destroyed() {
    on_new_thread(|| {
        glNormal3f(0.0, 1.0, 0.0);
        let default = Handle::current().expect("a default context");
        assert_eq!(default.destroy(), GL_FALSE);
        expect_error(GL_INVALID_OPERATION, "fflDestroyContext(default)");
        assert_eq!(Handle::current(), Some(default));
        assert_eq!(normal(), [0.0, 1.0, 0.0]);
        // not while another context is current either
        let a = Handle::create();
        a.make_current();
        assert_eq!(default.destroy(), GL_FALSE);
        expect_error(
            GL_INVALID_OPERATION,
            "fflDestroyContext(default) while released",
        );
        release();
        assert_eq!(normal(), [0.0, 1.0, 0.0]);
        a.destroy();
    });
}

#[test]
fn a_context_current_on_another_thread_cannot_be_made_current_or_destroyed() {
    let a = Handle::create();
    let (to_owner, owner_rx) = mpsc::channel::<&'static str>();
    let (owner_tx, from_owner) = mpsc::channel::<()>();
    let owner = thread::spawn(move || {
        assert_eq!(a.make_current(), GL_TRUE);
        glNormal3f(0.0, 1.0, 0.0);
        owner_tx.send(()).unwrap();
        // wait while the other thread tries
        assert_eq!(owner_rx.recv().unwrap(), "check");
        // still current here, state intact, and no error recorded in it
        assert_eq!(Handle::current(), Some(a));
        assert_eq!(normal(), [0.0, 1.0, 0.0]);
        assert_eq!(glGetError(), GL_NO_ERROR);
        owner_tx.send(()).unwrap();
        assert_eq!(owner_rx.recv().unwrap(), "release");
        assert_eq!(release(), GL_TRUE);
        owner_tx.send(()).unwrap();
    });
    on_new_thread(move || {
        from_owner.recv().unwrap();
        glGetError(); // this thread's own default context
        let mine = Handle::current().unwrap();
        assert_eq!(a.make_current(), GL_FALSE);
        expect_error(
            GL_INVALID_OPERATION,
            "fflMakeCurrent of a context current elsewhere",
        );
        assert_eq!(
            Handle::current(),
            Some(mine),
            "the failed call changed the current context"
        );
        assert_eq!(a.destroy(), GL_FALSE);
        expect_error(
            GL_INVALID_OPERATION,
            "fflDestroyContext of a context current elsewhere",
        );

        to_owner.send("check").unwrap();
        from_owner.recv().unwrap();
        to_owner.send("release").unwrap();
        from_owner.recv().unwrap();

        // released there: now it can be made current here, with the state set there
        assert_eq!(a.make_current(), GL_TRUE);
        assert_eq!(normal(), [0.0, 1.0, 0.0]);
        release();
        assert_eq!(a.destroy(), GL_TRUE);
    });
    owner.join().unwrap();
}

#[test]
fn a_thread_that_exits_releases_its_context() {
    let a = Handle::create();
    on_new_thread(move || {
        a.make_current();
        glNormal3f(0.5, 0.5, 0.0);
        // exits without releasing
    });
    on_new_thread(move || {
        assert_eq!(a.make_current(), GL_TRUE);
        assert_eq!(normal(), [0.5, 0.5, 0.0]);
        release();
        assert_eq!(a.destroy(), GL_TRUE);
    });
}

#[test]
fn destroying_the_current_context_releases_it_first() {
    on_new_thread(|| {
        let a = Handle::create();
        a.make_current();
        glNormal3f(1.0, 1.0, 1.0);
        assert_eq!(a.destroy(), GL_TRUE);
        assert_eq!(Handle::current(), None);
        // GL calls go on, to the thread's default context (new here, so initial state)
        assert_eq!(normal(), [0.0, 0.0, 1.0]);
        assert_ne!(Handle::current(), Some(a));
        expect_no_error("after destroying the current context");
    });
}

#[test]
fn destroying_null_is_refused() {
    on_new_thread(|| {
        // SAFETY: NULL is allowed.
        assert_eq!(unsafe { fflDestroyContext(std::ptr::null_mut()) }, GL_FALSE);
    });
}

#[test]
fn the_default_context_can_be_saved_and_made_current_again() {
    // The usual save/restore pattern: keep what fflGetCurrentContext returned, switch to
    // another context, switch back.
    on_new_thread(|| {
        glNormal3f(0.25, 0.5, 0.75);
        let saved = Handle::current().expect("a default context");
        let a = Handle::create();
        a.make_current();
        glNormal3f(1.0, 0.0, 0.0);
        assert_eq!(
            saved.make_current(),
            GL_TRUE,
            "restoring the saved default context"
        );
        assert_eq!(Handle::current(), Some(saved));
        assert_eq!(normal(), [0.25, 0.5, 0.75]);
        expect_no_error("after restoring");
        a.destroy();
    });
}

#[test]
fn a_default_context_current_on_another_thread_is_not_current_at_home() {
    // Thread T saves its default context D, switches to another context and hands D to
    // thread U, which makes it current. While U has D, T has no current context: its GL calls
    // reach nothing and fflGetCurrentContext is NULL. Once U releases D, T's next call finds D
    // again, with its state.
    let (to_u, u_rx) = mpsc::channel::<Handle>();
    let (u_tx, from_u) = mpsc::channel::<()>();
    let (to_t, t_rx) = mpsc::channel::<()>();
    let u = thread::spawn(move || {
        let d = u_rx.recv().unwrap();
        assert_eq!(d.make_current(), GL_TRUE);
        assert_eq!(normal(), [0.0, 1.0, 0.0]);
        u_tx.send(()).unwrap();
        t_rx.recv().unwrap();
        glNormal3f(0.0, 0.0, -1.0);
        assert_eq!(release(), GL_TRUE);
        u_tx.send(()).unwrap();
    });
    on_new_thread(move || {
        glNormal3f(0.0, 1.0, 0.0);
        let d = Handle::current().unwrap();
        let a = Handle::create();
        a.make_current();
        to_u.send(d).unwrap();
        from_u.recv().unwrap();
        // D is current on U: releasing `a` must not make D current here as well
        release();
        glNormal3f(1.0, 1.0, 1.0);
        assert_eq!(Handle::current(), None, "D is current on two threads");
        to_t.send(()).unwrap();
        from_u.recv().unwrap();
        // U released D: this thread's calls reach it again, with what U set
        assert_eq!(normal(), [0.0, 0.0, -1.0]);
        assert_eq!(Handle::current(), Some(d));
        a.destroy();
    });
    u.join().unwrap();
}
