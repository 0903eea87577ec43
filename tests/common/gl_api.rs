//! The C entry points the array and capture tests call, declared as a C program would see
//! them, plus small helpers around them. Each test runs on its own thread, so it gets its
//! own default context.
#![allow(dead_code)]

use std::ffi::c_void;

use fflight::current::with_current;
use fflight::gl::*;
use fflight::pipeline::capture::CapturedPrimitive;
use fflight::pipeline::vertex::ProcessedVertex;

unsafe extern "C" {
    pub fn glGetError() -> GLenum;
    pub fn glEnable(cap: GLenum);
    pub fn glDisable(cap: GLenum);
    pub fn glIsEnabled(cap: GLenum) -> GLboolean;
    pub fn glGetIntegerv(pname: GLenum, params: *mut GLint);
    pub fn glGetBooleanv(pname: GLenum, params: *mut GLboolean);
    pub fn glGetFloatv(pname: GLenum, params: *mut GLfloat);
    pub fn glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut GLfloat);
    pub fn glBegin(mode: GLenum);
    pub fn glEnd();
    pub fn glMatrixMode(mode: GLenum);
    pub fn glLoadIdentity();
    pub fn glRotatef(angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat);
    pub fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat);
    pub fn glScalef(x: GLfloat, y: GLfloat, z: GLfloat);
    pub fn glFrustum(l: GLdouble, r: GLdouble, b: GLdouble, t: GLdouble, n: GLdouble, f: GLdouble);
    pub fn glViewport(x: GLint, y: GLint, w: GLsizei, h: GLsizei);
    pub fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat);
    pub fn glLightf(light: GLenum, pname: GLenum, param: GLfloat);
    pub fn glLightModeli(pname: GLenum, param: GLint);
    pub fn glLightModelfv(pname: GLenum, params: *const GLfloat);
    pub fn glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat);
    pub fn glMaterialf(face: GLenum, pname: GLenum, param: GLfloat);
    pub fn glColorMaterial(face: GLenum, mode: GLenum);
    pub fn glFeedbackBuffer(size: GLsizei, kind: GLenum, buffer: *mut GLfloat);
    pub fn glRenderMode(mode: GLenum) -> GLint;
    pub fn glPolygonMode(face: GLenum, mode: GLenum);

    pub fn glColor4f(r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat);
    pub fn glNormal3f(x: GLfloat, y: GLfloat, z: GLfloat);
    pub fn glTexCoord4f(s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat);
    pub fn glVertex3f(x: GLfloat, y: GLfloat, z: GLfloat);
    pub fn glEdgeFlag(flag: GLboolean);
    pub fn glEdgeFlagv(flag: *const GLboolean);

    pub fn glColor3bv(v: *const GLbyte);
    pub fn glColor3ubv(v: *const GLubyte);
    pub fn glColor3sv(v: *const GLshort);
    pub fn glColor3usv(v: *const GLushort);
    pub fn glColor3iv(v: *const GLint);
    pub fn glColor3uiv(v: *const GLuint);
    pub fn glColor3fv(v: *const GLfloat);
    pub fn glColor3dv(v: *const GLdouble);
    pub fn glColor4bv(v: *const GLbyte);
    pub fn glColor4ubv(v: *const GLubyte);
    pub fn glColor4sv(v: *const GLshort);
    pub fn glColor4usv(v: *const GLushort);
    pub fn glColor4iv(v: *const GLint);
    pub fn glColor4uiv(v: *const GLuint);
    pub fn glColor4fv(v: *const GLfloat);
    pub fn glColor4dv(v: *const GLdouble);
    pub fn glNormal3bv(v: *const GLbyte);
    pub fn glNormal3sv(v: *const GLshort);
    pub fn glNormal3iv(v: *const GLint);
    pub fn glNormal3fv(v: *const GLfloat);
    pub fn glNormal3dv(v: *const GLdouble);
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
    pub fn glVertex2sv(v: *const GLshort);
    pub fn glVertex2iv(v: *const GLint);
    pub fn glVertex2fv(v: *const GLfloat);
    pub fn glVertex2dv(v: *const GLdouble);
    pub fn glVertex3sv(v: *const GLshort);
    pub fn glVertex3iv(v: *const GLint);
    pub fn glVertex3fv(v: *const GLfloat);
    pub fn glVertex3dv(v: *const GLdouble);
    pub fn glVertex4sv(v: *const GLshort);
    pub fn glVertex4iv(v: *const GLint);
    pub fn glVertex4fv(v: *const GLfloat);
    pub fn glVertex4dv(v: *const GLdouble);

    pub fn glVertexPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    pub fn glNormalPointer(ty: GLenum, stride: GLsizei, ptr: *const c_void);
    pub fn glColorPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    pub fn glTexCoordPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    pub fn glEdgeFlagPointer(stride: GLsizei, ptr: *const c_void);
    pub fn glSecondaryColorPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    pub fn glFogCoordPointer(ty: GLenum, stride: GLsizei, ptr: *const c_void);
    pub fn glIndexPointer(ty: GLenum, stride: GLsizei, ptr: *const c_void);
    pub fn glIndexubv(v: *const GLubyte);
    pub fn glIndexsv(v: *const GLshort);
    pub fn glIndexiv(v: *const GLint);
    pub fn glIndexfv(v: *const GLfloat);
    pub fn glIndexdv(v: *const GLdouble);
    pub fn glSecondaryColor3bv(v: *const GLbyte);
    pub fn glSecondaryColor3ubv(v: *const GLubyte);
    pub fn glSecondaryColor3sv(v: *const GLshort);
    pub fn glSecondaryColor3usv(v: *const GLushort);
    pub fn glSecondaryColor3iv(v: *const GLint);
    pub fn glSecondaryColor3uiv(v: *const GLuint);
    pub fn glSecondaryColor3fv(v: *const GLfloat);
    pub fn glSecondaryColor3dv(v: *const GLdouble);
    pub fn glFogCoordfv(v: *const GLfloat);
    pub fn glFogCoorddv(v: *const GLdouble);
    pub fn glEnableClientState(array: GLenum);
    pub fn glDisableClientState(array: GLenum);
    pub fn glInterleavedArrays(format: GLenum, stride: GLsizei, ptr: *const c_void);
    pub fn glGetPointerv(pname: GLenum, params: *mut *mut c_void);
    pub fn glArrayElement(i: GLint);
    pub fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei);
    pub fn glDrawElements(mode: GLenum, count: GLsizei, ty: GLenum, indices: *const c_void);
    pub fn glDrawRangeElements(
        mode: GLenum,
        start: GLuint,
        end: GLuint,
        count: GLsizei,
        ty: GLenum,
        indices: *const c_void,
    );

    pub fn fflCaptureBegin();
    pub fn fflCaptureEnd();
    pub fn fflCaptureVertexCount() -> GLuint;
    pub fn fflCapturePrimitiveCount() -> GLuint;
    pub fn fflLightVertices(
        count: GLsizei,
        position_size: GLint,
        positions: *const GLfloat,
        position_stride: GLsizei,
        normals: *const GLfloat,
        normal_stride: GLsizei,
        colors: *const GLfloat,
        color_stride: GLsizei,
        eye: *mut GLfloat,
        eye_stride: GLsizei,
        clip: *mut GLfloat,
        clip_stride: GLsizei,
        front_primary: *mut GLfloat,
        front_primary_stride: GLsizei,
        front_secondary: *mut GLfloat,
        front_secondary_stride: GLsizei,
        back_primary: *mut GLfloat,
        back_primary_stride: GLsizei,
        back_secondary: *mut GLfloat,
        back_secondary_stride: GLsizei,
    );
}

/// The next GL error, by name, for readable assertions.
pub fn error() -> &'static str {
    match unsafe { glGetError() } {
        GL_NO_ERROR => "GL_NO_ERROR",
        GL_INVALID_ENUM => "GL_INVALID_ENUM",
        GL_INVALID_VALUE => "GL_INVALID_VALUE",
        GL_INVALID_OPERATION => "GL_INVALID_OPERATION",
        GL_OUT_OF_MEMORY => "GL_OUT_OF_MEMORY",
        _ => "other",
    }
}

pub fn get_int(pname: GLenum) -> GLint {
    let mut value = -12345;
    unsafe { glGetIntegerv(pname, &mut value) };
    value
}

pub fn get_pointer(pname: GLenum) -> usize {
    let mut value: *mut c_void = std::ptr::null_mut();
    unsafe { glGetPointerv(pname, &mut value) };
    value as usize
}

/// What capture collected on this thread's context.
pub fn captured() -> (Vec<ProcessedVertex>, Vec<CapturedPrimitive>) {
    with_current(|ctx| {
        let capture = ctx.captured();
        (capture.vertices().to_vec(), capture.primitives().to_vec())
    })
    .expect("a current context")
}

/// Bit-exact equality of two processed vertices (NaN equals itself, 0 and -0 differ).
pub fn same_vertex(a: &ProcessedVertex, b: &ProcessedVertex) -> bool {
    let bits = |v: &ProcessedVertex| -> Vec<u32> {
        [
            v.eye,
            v.clip,
            v.colors.front.primary,
            v.colors.front.secondary,
            v.colors.back.primary,
            v.colors.back.secondary,
            v.tex_coord,
        ]
        .iter()
        .flat_map(|c| c.to_array().map(f32::to_bits))
        .chain([v.edge_flag as u32])
        .collect()
    };
    bits(a) == bits(b)
}

pub fn assert_same_vertices(what: &str, a: &[ProcessedVertex], b: &[ProcessedVertex]) {
    assert_eq!(a.len(), b.len(), "{what}: vertex counts");
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        assert!(
            same_vertex(x, y),
            "{what}: vertex {i} differs:\n{x:?}\n{y:?}"
        );
    }
}

/// A lit state that uses every input: two lights (one positional, attenuated, a spot), a
/// local viewer, two-sided lighting, separate specular, color material on ambient and
/// diffuse, a modelview with scaling (non-unit normals matter), a projection and a texture
/// matrix.
pub fn set_lit_state() {
    unsafe {
        glViewport(0, 0, 64, 64);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 100.0);
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glRotatef(30.0, 0.0, 0.0, 1.0);
        glScalef(2.0, 0.5, 1.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glTranslatef(0.1, -0.2, -5.0);
        glRotatef(25.0, 1.0, 1.0, 0.0);
        glScalef(1.5, 0.75, 1.0);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_LIGHT1);
        glLightfv(GL_LIGHT0, GL_POSITION, [0.3, 0.5, 1.0, 0.0].as_ptr());
        glLightfv(GL_LIGHT0, GL_SPECULAR, [0.9, 0.8, 0.7, 1.0].as_ptr());
        glLightfv(GL_LIGHT1, GL_POSITION, [-2.0, 1.0, 3.0, 1.0].as_ptr());
        glLightfv(GL_LIGHT1, GL_DIFFUSE, [0.4, 0.7, 0.2, 1.0].as_ptr());
        glLightfv(GL_LIGHT1, GL_SPECULAR, [0.5, 0.5, 0.9, 1.0].as_ptr());
        glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, [1.0, -0.5, -1.0].as_ptr());
        glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 80.0);
        glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 2.0);
        glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.1);
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
        glLightModeli(
            GL_LIGHT_MODEL_COLOR_CONTROL,
            GL_SEPARATE_SPECULAR_COLOR as GLint,
        );
        glMaterialfv(GL_FRONT, GL_SPECULAR, [0.6, 0.6, 0.6, 1.0].as_ptr());
        glMaterialf(GL_FRONT, GL_SHININESS, 20.0);
        glMaterialfv(GL_BACK, GL_EMISSION, [0.1, 0.0, 0.2, 1.0].as_ptr());
        glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
        glEnable(GL_COLOR_MATERIAL);
    }
}

/// Sets the current attributes to fixed values (which, with color material on, also sets
/// the tracked material).
pub fn reset_current() {
    unsafe {
        glColor4f(0.3, 0.6, 0.9, 0.5);
        glNormal3f(0.1, -0.2, 0.9);
        glTexCoord4f(0.25, 0.5, 0.75, 1.0);
        glEdgeFlag(GL_TRUE);
    }
}

/// A small deterministic generator (xorshift64*).
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// The current color, normal, texture coordinates and edge flag, as glGetFloatv gives them.
pub fn current_attribs() -> Vec<f32> {
    let mut values = Vec::new();
    for (pname, count) in [
        (GL_CURRENT_COLOR, 4),
        (GL_CURRENT_NORMAL, 3),
        (GL_CURRENT_TEXTURE_COORDS, 4),
        (GL_EDGE_FLAG, 1),
    ] {
        let mut v = [0.0f32; 4];
        unsafe { glGetFloatv(pname, v.as_mut_ptr()) };
        values.extend_from_slice(&v[..count]);
    }
    values
}
