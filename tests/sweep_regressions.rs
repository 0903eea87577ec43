//! What the entry-point sweep (tests/sweep.rs) found, one test each, so a return of the bug
//! fails here whatever the sweep's random draws.

mod common;

use std::time::Duration;

use common::*;

unsafe extern "C" {
    fn glGenQueries(n: GLsizei, ids: *mut GLuint);
    safe fn glIsQuery(id: GLuint) -> GLboolean;
    fn glGenBuffers(n: GLsizei, buffers: *mut GLuint);
    fn glDeleteBuffers(n: GLsizei, buffers: *const GLuint);
    safe fn glIsBuffer(buffer: GLuint) -> GLboolean;
    safe fn glBindBuffer(target: GLenum, buffer: GLuint);
    fn glGenTextures(n: GLsizei, textures: *mut GLuint);
    safe fn glBindTexture(target: GLenum, texture: GLuint);
    safe fn glGenLists(range: GLsizei) -> GLuint;
    safe fn glEvalMesh2(mode: GLenum, i1: GLint, i2: GLint, j1: GLint, j2: GLint);
    safe fn glNewList(list: GLuint, mode: GLenum);
    safe fn glEndList();
    safe fn glCallList(list: GLuint);
    safe fn glBegin(mode: GLenum);
    safe fn glEnd();
    fn glCompressedTexImage2D(
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        width: GLsizei,
        height: GLsizei,
        border: GLint,
        image_size: GLsizei,
        data: *const std::ffi::c_void,
    );
}

/// Runs `f` on a thread of its own (with its own context) and fails if it takes 5 s (room for
/// memcheck on a loaded machine): a regression of these would otherwise run for minutes.
fn returns_at_once(f: impl FnOnce() + Send + 'static) {
    let (done, finished) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _context = fresh();
        f();
        done.send(()).ok();
    });
    finished
        .recv_timeout(Duration::from_secs(5))
        .expect("the call returns at once");
}

#[test]
fn gen_with_a_null_destination_makes_no_name() {
    let _context = fresh();
    // SAFETY: NULL is refused before anything is written.
    unsafe { glGenQueries(1, std::ptr::null_mut()) };
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    // SAFETY: as above.
    unsafe { glGenBuffers(1, std::ptr::null_mut()) };
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    let mut query = 0;
    let mut buffer = 0;
    // SAFETY: room for one name each.
    unsafe {
        glGenQueries(1, &mut query);
        glGenBuffers(1, &mut buffer);
    }
    // The first names: the refused calls reserved none.
    assert_eq!((query, buffer), (1, 1));
    assert_eq!(glIsQuery(query), GL_FALSE); // a name only, until glBeginQuery
    assert_eq!(glIsBuffer(buffer), GL_FALSE);
    // glGenQueries(INT_MAX, NULL) made two billion names (minutes, gigabytes) before
    // refusing the pointer.
    returns_at_once(|| {
        // SAFETY: as above.
        unsafe { glGenQueries(i32::MAX, std::ptr::null_mut()) };
        assert_eq!(glGetError(), GL_INVALID_VALUE);
    });
}

#[test]
fn gen_after_the_last_name_gives_unused_names() {
    let _context = fresh();
    glBindTexture(GL_TEXTURE_2D, u32::MAX);
    let mut names = [0; 3];
    // SAFETY: room for three names (this call panicked, inside fflight, and wrote nothing).
    unsafe { glGenTextures(3, names.as_mut_ptr()) };
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(names, [1, 2, 3]);
}

#[test]
fn gen_lists_of_a_huge_range_returns_0_at_once() {
    returns_at_once(|| {
        assert_eq!(glGenLists(1 << 30), 0);
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_ne!(glGenLists(3), 0);
    });
}

#[test]
fn an_eval_mesh_over_an_empty_range_returns_at_once() {
    returns_at_once(|| {
        for mode in [GL_POINT, GL_LINE, GL_FILL] {
            glEvalMesh2(mode, i32::MAX, i32::MIN, 0, i32::MAX);
            glEvalMesh2(mode, 0, i32::MAX, i32::MAX, 0);
        }
        assert_eq!(glGetError(), GL_NO_ERROR);
        glEvalMesh2(0x1234, 1, 0, 0, 0);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
    });
}

#[test]
fn delete_buffers_between_begin_and_end_is_an_invalid_operation_first() {
    let _context = fresh();
    let name = 1;
    glBegin(GL_POINTS);
    // SAFETY: one name; the negative count is never used to read.
    unsafe { glDeleteBuffers(-1, &name) };
    glEnd();
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

#[test]
fn compressed_images_are_compiled_and_fail_when_the_list_runs() {
    let _context = fresh();
    let list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    // SAFETY: NULL data, never read (no compressed format).
    unsafe { glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 16, std::ptr::null()) };
    assert_eq!(glGetError(), GL_NO_ERROR);
    glEndList();
    glCallList(list);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
}

unsafe extern "C" {
    fn glConvolutionFilter2D(
        target: GLenum,
        internalformat: GLenum,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        ty: GLenum,
        image: *const std::ffi::c_void,
    );
    fn glTexImage2D(
        target: GLenum,
        level: GLint,
        internalformat: GLint,
        width: GLsizei,
        height: GLsizei,
        border: GLint,
        format: GLenum,
        ty: GLenum,
        pixels: *const std::ffi::c_void,
    );
    safe fn glPixelStorei(pname: GLenum, param: GLint);
}

#[test]
fn images_of_hostile_sizes_are_refused_not_overflowed() {
    let _context = fresh();
    let pixels = [0u8; 64];
    // The bytes these would read overflowed usize (2^31 rows of 2^31 float pixels, skipped
    // rows on top): a panic inside fflight, no error recorded.
    glPixelStorei(GL_UNPACK_SKIP_ROWS, i32::MAX);
    let (huge, data) = (i32::MAX, pixels.as_ptr().cast());
    // SAFETY: the sizes are refused before anything is read.
    unsafe {
        glConvolutionFilter2D(
            GL_CONVOLUTION_2D,
            GL_RGBA,
            huge,
            huge,
            GL_RGBA,
            GL_FLOAT,
            data,
        )
    };
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    // SAFETY: as above.
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as GLint,
            huge,
            huge,
            0,
            GL_RGBA,
            GL_FLOAT,
            data,
        )
    };
    assert_eq!(glGetError(), GL_INVALID_VALUE);
}
