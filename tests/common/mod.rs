//! Shared by the core-semantics tests: the C entry points as the crate exports them, safe
//! wrappers that check how many values a query writes, error assertions, and
//! `assert_approx_eq!`.
//!
//! Each test runs on its own thread; `fresh()` also gives it a context of its own, created for
//! the test and destroyed at its end, so no test sees another's state.
#![allow(dead_code)]

use std::ffi::{CStr, c_void};

pub use fflight::gl::*;

/// An opaque `FflContext *`.
pub type ContextPtr = *mut c_void;

unsafe extern "C" {
    pub safe fn fflCreateContext() -> ContextPtr;
    pub fn fflMakeCurrent(context: ContextPtr) -> GLboolean;
    pub safe fn fflGetCurrentContext() -> ContextPtr;
    pub fn fflDestroyContext(context: ContextPtr) -> GLboolean;

    pub safe fn glGetError() -> GLenum;
    pub fn glGetBooleanv(pname: GLenum, params: *mut GLboolean);
    pub fn glGetIntegerv(pname: GLenum, params: *mut GLint);
    pub fn glGetFloatv(pname: GLenum, params: *mut GLfloat);
    pub fn glGetDoublev(pname: GLenum, params: *mut GLdouble);
    pub safe fn glGetString(name: GLenum) -> *const GLubyte;

    pub safe fn glLightf(light: GLenum, pname: GLenum, param: GLfloat);
    pub safe fn glLighti(light: GLenum, pname: GLenum, param: GLint);
    pub fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat);
    pub fn glLightiv(light: GLenum, pname: GLenum, params: *const GLint);
    pub fn glGetLightfv(light: GLenum, pname: GLenum, params: *mut GLfloat);
    pub fn glGetLightiv(light: GLenum, pname: GLenum, params: *mut GLint);
    pub safe fn glMaterialf(face: GLenum, pname: GLenum, param: GLfloat);
    pub safe fn glMateriali(face: GLenum, pname: GLenum, param: GLint);
    pub fn glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat);
    pub fn glMaterialiv(face: GLenum, pname: GLenum, params: *const GLint);
    pub fn glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut GLfloat);
    pub fn glGetMaterialiv(face: GLenum, pname: GLenum, params: *mut GLint);
    pub safe fn glLightModelf(pname: GLenum, param: GLfloat);
    pub safe fn glLightModeli(pname: GLenum, param: GLint);
    pub fn glLightModelfv(pname: GLenum, params: *const GLfloat);
    pub fn glLightModeliv(pname: GLenum, params: *const GLint);
    pub safe fn glColorMaterial(face: GLenum, mode: GLenum);
    pub safe fn glEnable(cap: GLenum);
    pub safe fn glDisable(cap: GLenum);
    pub safe fn glIsEnabled(cap: GLenum) -> GLboolean;

    pub safe fn glMatrixMode(mode: GLenum);
    pub safe fn glLoadIdentity();
    pub fn glLoadMatrixf(m: *const GLfloat);
    pub fn glLoadMatrixd(m: *const GLdouble);
    pub fn glMultMatrixf(m: *const GLfloat);
    pub fn glMultMatrixd(m: *const GLdouble);
    pub fn glLoadTransposeMatrixf(m: *const GLfloat);
    pub fn glLoadTransposeMatrixd(m: *const GLdouble);
    pub fn glMultTransposeMatrixf(m: *const GLfloat);
    pub fn glMultTransposeMatrixd(m: *const GLdouble);
    pub safe fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat);
    pub safe fn glTranslated(x: GLdouble, y: GLdouble, z: GLdouble);
    pub safe fn glRotatef(angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat);
    pub safe fn glRotated(angle: GLdouble, x: GLdouble, y: GLdouble, z: GLdouble);
    pub safe fn glScalef(x: GLfloat, y: GLfloat, z: GLfloat);
    pub safe fn glScaled(x: GLdouble, y: GLdouble, z: GLdouble);
    pub safe fn glFrustum(
        l: GLdouble,
        r: GLdouble,
        b: GLdouble,
        t: GLdouble,
        n: GLdouble,
        f: GLdouble,
    );
    pub safe fn glOrtho(
        l: GLdouble,
        r: GLdouble,
        b: GLdouble,
        t: GLdouble,
        n: GLdouble,
        f: GLdouble,
    );
    pub safe fn glPushMatrix();
    pub safe fn glPopMatrix();

    pub safe fn glBegin(mode: GLenum);
    pub safe fn glEnd();
    pub safe fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei);
    pub safe fn glDepthRange(near: GLclampd, far: GLclampd);
    pub fn glFeedbackBuffer(size: GLsizei, kind: GLenum, buffer: *mut GLfloat);
    pub safe fn glRenderMode(mode: GLenum) -> GLint;
    pub safe fn glPassThrough(token: GLfloat);
    pub fn glVertexPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    pub fn glEnableClientState(array: GLenum);
    pub fn glDisableClientState(array: GLenum);
    pub fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei);

    pub safe fn glEdgeFlag(flag: GLboolean);
    pub fn glEdgeFlagv(flag: *const GLboolean);
    pub safe fn glVertex2f(x: GLfloat, y: GLfloat);
    pub safe fn glVertex3f(x: GLfloat, y: GLfloat, z: GLfloat);
    pub fn glVertex3fv(v: *const GLfloat);

    pub safe fn glNormal3b(x: GLbyte, y: GLbyte, z: GLbyte);
    pub safe fn glNormal3s(x: GLshort, y: GLshort, z: GLshort);
    pub safe fn glNormal3i(x: GLint, y: GLint, z: GLint);
    pub safe fn glNormal3f(x: GLfloat, y: GLfloat, z: GLfloat);
    pub safe fn glNormal3d(x: GLdouble, y: GLdouble, z: GLdouble);
    pub fn glNormal3bv(v: *const GLbyte);
    pub fn glNormal3sv(v: *const GLshort);
    pub fn glNormal3iv(v: *const GLint);
    pub fn glNormal3fv(v: *const GLfloat);
    pub fn glNormal3dv(v: *const GLdouble);

    pub safe fn glColor3b(r: GLbyte, g: GLbyte, b: GLbyte);
    pub safe fn glColor3s(r: GLshort, g: GLshort, b: GLshort);
    pub safe fn glColor3i(r: GLint, g: GLint, b: GLint);
    pub safe fn glColor3f(r: GLfloat, g: GLfloat, b: GLfloat);
    pub safe fn glColor3d(r: GLdouble, g: GLdouble, b: GLdouble);
    pub safe fn glColor3ub(r: GLubyte, g: GLubyte, b: GLubyte);
    pub safe fn glColor3us(r: GLushort, g: GLushort, b: GLushort);
    pub safe fn glColor3ui(r: GLuint, g: GLuint, b: GLuint);
    pub safe fn glColor4b(r: GLbyte, g: GLbyte, b: GLbyte, a: GLbyte);
    pub safe fn glColor4s(r: GLshort, g: GLshort, b: GLshort, a: GLshort);
    pub safe fn glColor4i(r: GLint, g: GLint, b: GLint, a: GLint);
    pub safe fn glColor4f(r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat);
    pub safe fn glColor4d(r: GLdouble, g: GLdouble, b: GLdouble, a: GLdouble);
    pub safe fn glColor4ub(r: GLubyte, g: GLubyte, b: GLubyte, a: GLubyte);
    pub safe fn glColor4us(r: GLushort, g: GLushort, b: GLushort, a: GLushort);
    pub safe fn glColor4ui(r: GLuint, g: GLuint, b: GLuint, a: GLuint);
    pub fn glColor3bv(v: *const GLbyte);
    pub fn glColor3sv(v: *const GLshort);
    pub fn glColor3iv(v: *const GLint);
    pub fn glColor3fv(v: *const GLfloat);
    pub fn glColor3dv(v: *const GLdouble);
    pub fn glColor3ubv(v: *const GLubyte);
    pub fn glColor3usv(v: *const GLushort);
    pub fn glColor3uiv(v: *const GLuint);
    pub fn glColor4bv(v: *const GLbyte);
    pub fn glColor4sv(v: *const GLshort);
    pub fn glColor4iv(v: *const GLint);
    pub fn glColor4fv(v: *const GLfloat);
    pub fn glColor4dv(v: *const GLdouble);
    pub fn glColor4ubv(v: *const GLubyte);
    pub fn glColor4usv(v: *const GLushort);
    pub fn glColor4uiv(v: *const GLuint);

    pub safe fn glTexCoord1s(s: GLshort);
    pub safe fn glTexCoord1i(s: GLint);
    pub safe fn glTexCoord1f(s: GLfloat);
    pub safe fn glTexCoord1d(s: GLdouble);
    pub safe fn glTexCoord2s(s: GLshort, t: GLshort);
    pub safe fn glTexCoord2i(s: GLint, t: GLint);
    pub safe fn glTexCoord2f(s: GLfloat, t: GLfloat);
    pub safe fn glTexCoord2d(s: GLdouble, t: GLdouble);
    pub safe fn glTexCoord3s(s: GLshort, t: GLshort, r: GLshort);
    pub safe fn glTexCoord3i(s: GLint, t: GLint, r: GLint);
    pub safe fn glTexCoord3f(s: GLfloat, t: GLfloat, r: GLfloat);
    pub safe fn glTexCoord3d(s: GLdouble, t: GLdouble, r: GLdouble);
    pub safe fn glTexCoord4s(s: GLshort, t: GLshort, r: GLshort, q: GLshort);
    pub safe fn glTexCoord4i(s: GLint, t: GLint, r: GLint, q: GLint);
    pub safe fn glTexCoord4f(s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat);
    pub safe fn glTexCoord4d(s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble);
    pub fn glTexCoord1sv(v: *const GLshort);
    pub fn glTexCoord1iv(v: *const GLint);
    pub fn glTexCoord1fv(v: *const GLfloat);
    pub fn glTexCoord1dv(v: *const GLdouble);
    pub fn glTexCoord2sv(v: *const GLshort);
    pub fn glTexCoord2iv(v: *const GLint);
    pub fn glTexCoord2fv(v: *const GLfloat);
    pub fn glTexCoord2dv(v: *const GLdouble);
    pub fn glTexCoord3sv(v: *const GLshort);
    pub fn glTexCoord3iv(v: *const GLint);
    pub fn glTexCoord3fv(v: *const GLfloat);
    pub fn glTexCoord3dv(v: *const GLdouble);
    pub fn glTexCoord4sv(v: *const GLshort);
    pub fn glTexCoord4iv(v: *const GLint);
    pub fn glTexCoord4fv(v: *const GLfloat);
    pub fn glTexCoord4dv(v: *const GLdouble);
}

/// 2^32 - 1: the divisor of the signed 32-bit color mapping (2c + 1) / (2^32 - 1).
pub const INT_RANGE: f64 = 4_294_967_295.0;

/// The float a signed 32-bit color component stands for (table 2.9).
pub fn int_color(c: i32) -> f32 {
    ((2.0 * c as f64 + 1.0) / INT_RANGE) as f32
}

/// A GL enum by name, for messages.
pub fn error_name(error: GLenum) -> String {
    match error {
        GL_NO_ERROR => "GL_NO_ERROR".into(),
        GL_INVALID_ENUM => "GL_INVALID_ENUM".into(),
        GL_INVALID_VALUE => "GL_INVALID_VALUE".into(),
        GL_INVALID_OPERATION => "GL_INVALID_OPERATION".into(),
        GL_STACK_OVERFLOW => "GL_STACK_OVERFLOW".into(),
        GL_STACK_UNDERFLOW => "GL_STACK_UNDERFLOW".into(),
        GL_OUT_OF_MEMORY => "GL_OUT_OF_MEMORY".into(),
        other => format!("{other:#x}"),
    }
}

/// Reads glGetError and checks it is `expected`; the flag is clear afterwards.
#[track_caller]
pub fn expect_error(expected: GLenum, what: &str) {
    let got = glGetError();
    assert!(
        got == expected,
        "{what}: expected {}, got {}",
        error_name(expected),
        error_name(got)
    );
    assert_eq!(
        glGetError(),
        GL_NO_ERROR,
        "{what}: glGetError did not clear the flag"
    );
}

#[track_caller]
pub fn expect_no_error(what: &str) {
    expect_error(GL_NO_ERROR, what);
}

/// A context of the test's own, current on its thread until dropped.
pub struct Fresh(ContextPtr);

pub fn fresh() -> Fresh {
    let context = fflCreateContext();
    assert!(!context.is_null());
    // SAFETY: a live context from fflCreateContext.
    assert_eq!(unsafe { fflMakeCurrent(context) }, GL_TRUE);
    Fresh(context)
}

impl Drop for Fresh {
    fn drop(&mut self) {
        // SAFETY: the context this guard created; releasing and destroying it ends its use.
        unsafe {
            fflMakeCurrent(std::ptr::null_mut());
            fflDestroyContext(self.0);
        }
    }
}

/// Values a query must not write: anything left there after the call was never written.
/// glFeedbackBuffer's five types.
pub const FEEDBACK_TYPES: [GLenum; 5] = [
    GL_2D,
    GL_3D,
    GL_3D_COLOR,
    GL_3D_COLOR_TEXTURE,
    GL_4D_COLOR_TEXTURE,
];

pub const SENTINEL_F: f32 = -12345.5;
pub const SENTINEL_D: f64 = -12345.5;
pub const SENTINEL_I: i32 = -123_456_789;
pub const SENTINEL_B: GLboolean = 0xAB;
/// Room past the values a pname defines, to catch a query writing too many.
const SLACK: usize = 4;

#[track_caller]
fn check_tail<T: PartialEq + std::fmt::Debug + Copy>(buf: &[T], n: usize, sentinel: T, what: &str) {
    assert!(
        buf[n..].iter().all(|&v| v == sentinel),
        "{what}: wrote past the {n} values it defines: {buf:?}"
    );
}

/// glGetFloatv(pname), checking it writes exactly `n` values.
#[track_caller]
pub fn get_floats(pname: GLenum, n: usize) -> Vec<f32> {
    let mut buf = vec![SENTINEL_F; n + SLACK];
    // SAFETY: `buf` has room for more than `n` values.
    unsafe { glGetFloatv(pname, buf.as_mut_ptr()) };
    check_tail(&buf, n, SENTINEL_F, &format!("glGetFloatv({pname:#x})"));
    buf.truncate(n);
    buf
}

#[track_caller]
pub fn get_doubles(pname: GLenum, n: usize) -> Vec<f64> {
    let mut buf = vec![SENTINEL_D; n + SLACK];
    // SAFETY: `buf` has room for more than `n` values.
    unsafe { glGetDoublev(pname, buf.as_mut_ptr()) };
    check_tail(&buf, n, SENTINEL_D, &format!("glGetDoublev({pname:#x})"));
    buf.truncate(n);
    buf
}

#[track_caller]
pub fn get_ints(pname: GLenum, n: usize) -> Vec<i32> {
    let mut buf = vec![SENTINEL_I; n + SLACK];
    // SAFETY: `buf` has room for more than `n` values.
    unsafe { glGetIntegerv(pname, buf.as_mut_ptr()) };
    check_tail(&buf, n, SENTINEL_I, &format!("glGetIntegerv({pname:#x})"));
    buf.truncate(n);
    buf
}

#[track_caller]
pub fn get_bools(pname: GLenum, n: usize) -> Vec<GLboolean> {
    let mut buf = vec![SENTINEL_B; n + SLACK];
    // SAFETY: `buf` has room for more than `n` values.
    unsafe { glGetBooleanv(pname, buf.as_mut_ptr()) };
    check_tail(&buf, n, SENTINEL_B, &format!("glGetBooleanv({pname:#x})"));
    buf.truncate(n);
    buf
}

#[track_caller]
pub fn get_int(pname: GLenum) -> i32 {
    get_ints(pname, 1)[0]
}

/// glGetLightfv, checking it writes exactly `n` values.
#[track_caller]
pub fn get_light(light: GLenum, pname: GLenum, n: usize) -> Vec<f32> {
    let mut buf = vec![SENTINEL_F; n + SLACK];
    // SAFETY: `buf` has room for more than `n` values.
    unsafe { glGetLightfv(light, pname, buf.as_mut_ptr()) };
    check_tail(
        &buf,
        n,
        SENTINEL_F,
        &format!("glGetLightfv({light:#x}, {pname:#x})"),
    );
    buf.truncate(n);
    buf
}

#[track_caller]
pub fn get_light_i(light: GLenum, pname: GLenum, n: usize) -> Vec<i32> {
    let mut buf = vec![SENTINEL_I; n + SLACK];
    // SAFETY: `buf` has room for more than `n` values.
    unsafe { glGetLightiv(light, pname, buf.as_mut_ptr()) };
    check_tail(
        &buf,
        n,
        SENTINEL_I,
        &format!("glGetLightiv({light:#x}, {pname:#x})"),
    );
    buf.truncate(n);
    buf
}

#[track_caller]
pub fn get_material(face: GLenum, pname: GLenum, n: usize) -> Vec<f32> {
    let mut buf = vec![SENTINEL_F; n + SLACK];
    // SAFETY: `buf` has room for more than `n` values.
    unsafe { glGetMaterialfv(face, pname, buf.as_mut_ptr()) };
    check_tail(
        &buf,
        n,
        SENTINEL_F,
        &format!("glGetMaterialfv({face:#x}, {pname:#x})"),
    );
    buf.truncate(n);
    buf
}

#[track_caller]
pub fn get_material_i(face: GLenum, pname: GLenum, n: usize) -> Vec<i32> {
    let mut buf = vec![SENTINEL_I; n + SLACK];
    // SAFETY: `buf` has room for more than `n` values.
    unsafe { glGetMaterialiv(face, pname, buf.as_mut_ptr()) };
    check_tail(
        &buf,
        n,
        SENTINEL_I,
        &format!("glGetMaterialiv({face:#x}, {pname:#x})"),
    );
    buf.truncate(n);
    buf
}

/// glLightfv with a slice (the pname decides how many values are read).
pub fn light_fv(light: GLenum, pname: GLenum, params: &[f32]) {
    let mut padded = [0.0f32; 4];
    padded[..params.len()].copy_from_slice(params);
    // SAFETY: four readable values, the most any light pname reads.
    unsafe { glLightfv(light, pname, padded.as_ptr()) }
}

pub fn light_iv(light: GLenum, pname: GLenum, params: &[i32]) {
    let mut padded = [0i32; 4];
    padded[..params.len()].copy_from_slice(params);
    // SAFETY: four readable values, the most any light pname reads.
    unsafe { glLightiv(light, pname, padded.as_ptr()) }
}

pub fn material_fv(face: GLenum, pname: GLenum, params: &[f32]) {
    let mut padded = [0.0f32; 4];
    padded[..params.len()].copy_from_slice(params);
    // SAFETY: four readable values, the most any material pname reads.
    unsafe { glMaterialfv(face, pname, padded.as_ptr()) }
}

pub fn material_iv(face: GLenum, pname: GLenum, params: &[i32]) {
    let mut padded = [0i32; 4];
    padded[..params.len()].copy_from_slice(params);
    // SAFETY: four readable values, the most any material pname reads.
    unsafe { glMaterialiv(face, pname, padded.as_ptr()) }
}

pub fn light_model_fv(pname: GLenum, params: &[f32]) {
    let mut padded = [0.0f32; 4];
    padded[..params.len()].copy_from_slice(params);
    // SAFETY: four readable values, the most any light model pname reads.
    unsafe { glLightModelfv(pname, padded.as_ptr()) }
}

pub fn light_model_iv(pname: GLenum, params: &[i32]) {
    let mut padded = [0i32; 4];
    padded[..params.len()].copy_from_slice(params);
    // SAFETY: four readable values, the most any light model pname reads.
    unsafe { glLightModeliv(pname, padded.as_ptr()) }
}

pub fn load_matrix(m: &[f32; 16]) {
    // SAFETY: 16 readable values.
    unsafe { glLoadMatrixf(m.as_ptr()) }
}

/// The current matrix of `pname` (GL_MODELVIEW_MATRIX ...), column-major.
#[track_caller]
pub fn matrix(pname: GLenum) -> [f32; 16] {
    get_floats(pname, 16).try_into().unwrap()
}

/// glGetString as a Rust string; None for NULL.
pub fn get_string(name: GLenum) -> Option<String> {
    let s = glGetString(name);
    if s.is_null() {
        None
    } else {
        // SAFETY: a non-NULL glGetString result is a NUL-terminated string that lives as
        // long as the library.
        Some(
            unsafe { CStr::from_ptr(s.cast()) }
                .to_string_lossy()
                .into_owned(),
        )
    }
}

/// Values `assert_approx_eq!` can compare.
pub trait Approx {
    fn values(&self) -> Vec<f64>;
}

impl Approx for f32 {
    fn values(&self) -> Vec<f64> {
        vec![*self as f64]
    }
}

impl Approx for f64 {
    fn values(&self) -> Vec<f64> {
        vec![*self]
    }
}

impl<const N: usize> Approx for [f32; N] {
    fn values(&self) -> Vec<f64> {
        self.iter().map(|&v| v as f64).collect()
    }
}

impl<const N: usize> Approx for [f64; N] {
    fn values(&self) -> Vec<f64> {
        self.to_vec()
    }
}

impl Approx for Vec<f32> {
    fn values(&self) -> Vec<f64> {
        self.iter().map(|&v| v as f64).collect()
    }
}

impl Approx for Vec<f64> {
    fn values(&self) -> Vec<f64> {
        self.clone()
    }
}

impl Approx for [f32] {
    fn values(&self) -> Vec<f64> {
        self.iter().map(|&v| v as f64).collect()
    }
}

/// Whether `got` and `want` agree within `tolerance` (absolute, or relative above 1).
pub fn approx_equal(got: &[f64], want: &[f64], tolerance: f64) -> bool {
    got.len() == want.len()
        && got
            .iter()
            .zip(want)
            .all(|(&g, &w)| (g - w).abs() <= tolerance * w.abs().max(1.0))
}

/// `assert_approx_eq!(got, want)` or `assert_approx_eq!(got, want, tolerance)`, with an
/// optional message after: fails with both values and the tolerance.
#[macro_export]
macro_rules! assert_approx_eq {
    ($got:expr, $want:expr) => {
        $crate::assert_approx_eq!($got, $want, 1e-6)
    };
    ($got:expr, $want:expr, $tolerance:expr $(, $($message:tt)+)?) => {{
        let got = $crate::common::Approx::values(&$got);
        let want = $crate::common::Approx::values(&$want);
        let tolerance: f64 = $tolerance;
        let context: String = ::std::string::String::new() $(+ &format!($($message)+))?;
        assert!(
            $crate::common::approx_equal(&got, &want, tolerance),
            "assert_approx_eq!({}, {}) {}\n   got: {:?}\n  want: {:?}\n   tolerance: {:e}",
            stringify!($got),
            stringify!($want),
            context,
            got,
            want,
            tolerance
        );
    }};
}
