//! Tables of GL function pointers, the way programs that load GL with glad or GLEW call it.
//!
//! Two implementations of the same GL names live in this process: fflight's entry points,
//! linked statically into the executable from the fflight crate, and the system's GL (Mesa
//! through libglvnd), which GLFW opens with `dlopen("libGL.so.1")` when it makes a GLX
//! context. They never get mixed up because no call here finds its function by name at run
//! time:
//!
//! - [`Legacy::fflight`] takes fflight's functions through an `extern "C"` block: the static
//!   linker resolves `glBegin` and the others to the definitions in fflight's rlib (the
//!   executable links no libGL: GLFW loads it at run time), and the calls are direct calls
//!   inside the executable. An executable's references to its own definitions cannot be
//!   interposed by a shared library.
//! - `load` takes the system GL's functions from `glfwGetProcAddress` (`glXGetProcAddressARB`,
//!   answered from libglvnd's dispatch table, which routes each call to the current
//!   context's driver).
//! - The other way round, nothing in the GL libraries can reach fflight's functions by name:
//!   a Rust executable exports no symbol dynamically (`nm -D` lists no `gl*`). A lookup of
//!   `glBegin` in the global scope does find one once the GL is loaded (libGLX_mesa's, in
//!   Debian 12), which `main.rs` prints and checks is not fflight's.
//!
//! `main.rs` also checks the outcome both ways: the core context rejects
//! `glEnable(GL_LIGHTING)`, so no lit color can come from the system GL there, and the
//! compatibility context draws lit pixels, which fflight (it has no rasterizer) cannot.

use std::ffi::c_void;

pub use fflight::gl::*;

// GL 3.x names fflight's GL 1.5 module does not have.
pub const GL_FRAMEBUFFER: GLenum = 0x8D40;
pub const GL_READ_FRAMEBUFFER: GLenum = 0x8CA8;
pub const GL_DRAW_FRAMEBUFFER: GLenum = 0x8CA9;
pub const GL_RENDERBUFFER: GLenum = 0x8D41;
pub const GL_COLOR_ATTACHMENT0: GLenum = 0x8CE0;
pub const GL_DEPTH_ATTACHMENT: GLenum = 0x8D00;
pub const GL_FRAMEBUFFER_COMPLETE: GLenum = 0x8CD5;
pub const GL_VERTEX_SHADER: GLenum = 0x8B31;
pub const GL_FRAGMENT_SHADER: GLenum = 0x8B30;
pub const GL_COMPILE_STATUS: GLenum = 0x8B81;
pub const GL_LINK_STATUS: GLenum = 0x8B82;
pub const GL_CONTEXT_PROFILE_MASK: GLenum = 0x9126;
pub const GL_CONTEXT_CORE_PROFILE_BIT: GLint = 0x1;

/// Declares a struct of GL function pointers (fields named as the C functions) with `load`,
/// which fills it from a `name -> address` function such as `glfwGetProcAddress`, and, with
/// `linked(module)`, `fflight()`, which fills it with the functions of the same names that
/// the executable links (fflight's).
macro_rules! gl_table {
    ($(#[$doc:meta])* $table:ident, linked($module:ident) {
        $(fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)?;)*
    }) => {
        gl_table! { $(#[$doc])* $table { $(fn $name($($arg: $ty),*) $(-> $ret)?;)* } }

        mod $module {
            use super::*;
            unsafe extern "C" {
                $(pub fn $name($($arg: $ty),*) $(-> $ret)?;)*
            }
        }

        impl $table {
            /// fflight's entry points, resolved by the static linker.
            pub fn fflight() -> $table {
                $table { $($name: $module::$name,)* }
            }
        }
    };
    ($(#[$doc:meta])* $table:ident {
        $(fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)?;)*
    }) => {
        $(#[$doc])*
        #[allow(non_snake_case)]
        pub struct $table {
            $(pub $name: unsafe extern "C" fn($($ty),*) $(-> $ret)?,)*
        }

        impl $table {
            /// Every function from `load`, or the name of the first one it does not have.
            pub fn load(mut load: impl FnMut(&str) -> *const c_void) -> Result<$table, String> {
                Ok($table {
                    $($name: {
                        let address = load(stringify!($name));
                        if address.is_null() {
                            return Err(format!("{} is not available", stringify!($name)));
                        }
                        // SAFETY: the GL returns the address of the function of this name,
                        // whose C signature is the one declared here (the Khronos registry's).
                        unsafe {
                            std::mem::transmute::<
                                *const c_void,
                                unsafe extern "C" fn($($ty),*) $(-> $ret)?,
                            >(address)
                        }
                    },)*
                })
            }
        }
    };
}

gl_table! {
    /// What the legacy routine calls: OpenGL 1.x with fixed-function lighting, vertex arrays
    /// and display lists, and the queries a renderer reads raster state back with.
    Legacy, linked(fflight_symbols) {
        fn glGetError() -> GLenum;
        fn glEnable(cap: GLenum);
        fn glDisable(cap: GLenum);
        fn glIsEnabled(cap: GLenum) -> GLboolean;
        fn glGetIntegerv(pname: GLenum, params: *mut GLint);
        fn glGetFloatv(pname: GLenum, params: *mut GLfloat);
        fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei);
        fn glClearColor(r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat);
        fn glClear(mask: GLbitfield);
        fn glFrontFace(mode: GLenum);
        fn glDepthFunc(func: GLenum);
        fn glShadeModel(mode: GLenum);
        fn glMatrixMode(mode: GLenum);
        fn glLoadIdentity();
        fn glFrustum(l: GLdouble, r: GLdouble, b: GLdouble, t: GLdouble, n: GLdouble, f: GLdouble);
        fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat);
        fn glRotatef(angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat);
        fn glScalef(x: GLfloat, y: GLfloat, z: GLfloat);
        fn glPushMatrix();
        fn glPopMatrix();
        fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat);
        fn glLightf(light: GLenum, pname: GLenum, param: GLfloat);
        fn glLightModelfv(pname: GLenum, params: *const GLfloat);
        fn glLightModeli(pname: GLenum, param: GLint);
        fn glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat);
        fn glMaterialf(face: GLenum, pname: GLenum, param: GLfloat);
        fn glColorMaterial(face: GLenum, mode: GLenum);
        fn glBegin(mode: GLenum);
        fn glEnd();
        fn glNormal3f(x: GLfloat, y: GLfloat, z: GLfloat);
        fn glNormal3fv(v: *const GLfloat);
        fn glVertex3f(x: GLfloat, y: GLfloat, z: GLfloat);
        fn glVertex3fv(v: *const GLfloat);
        fn glVertexPointer(size: GLint, type_: GLenum, stride: GLsizei, pointer: *const c_void);
        fn glNormalPointer(type_: GLenum, stride: GLsizei, pointer: *const c_void);
        fn glColorPointer(size: GLint, type_: GLenum, stride: GLsizei, pointer: *const c_void);
        fn glEnableClientState(array: GLenum);
        fn glDisableClientState(array: GLenum);
        fn glDrawElements(mode: GLenum, count: GLsizei, type_: GLenum, indices: *const c_void);
        fn glGenLists(range: GLsizei) -> GLuint;
        fn glNewList(list: GLuint, mode: GLenum);
        fn glEndList();
        fn glCallList(list: GLuint);
        fn glDeleteLists(list: GLuint, range: GLsizei);
    }
}

gl_table! {
    /// The system GL in the compatibility context: the legacy routine's functions plus an
    /// offscreen framebuffer to draw into and read back.
    Target {
        fn glGetString(name: GLenum) -> *const GLubyte;
        fn glGetIntegerv(pname: GLenum, params: *mut GLint);
        fn glGenFramebuffers(n: GLsizei, framebuffers: *mut GLuint);
        fn glBindFramebuffer(target: GLenum, framebuffer: GLuint);
        fn glGenRenderbuffers(n: GLsizei, renderbuffers: *mut GLuint);
        fn glBindRenderbuffer(target: GLenum, renderbuffer: GLuint);
        fn glRenderbufferStorage(target: GLenum, format: GLenum, width: GLsizei, height: GLsizei);
        fn glFramebufferRenderbuffer(target: GLenum, attachment: GLenum, rbtarget: GLenum, rb: GLuint);
        fn glCheckFramebufferStatus(target: GLenum) -> GLenum;
        fn glReadPixels(x: GLint, y: GLint, w: GLsizei, h: GLsizei, format: GLenum, type_: GLenum, data: *mut c_void);
        fn glBlitFramebuffer(
            sx0: GLint, sy0: GLint, sx1: GLint, sy1: GLint,
            dx0: GLint, dy0: GLint, dx1: GLint, dy1: GLint,
            mask: GLbitfield, filter: GLenum,
        );
        fn glFinish();
    }
}

gl_table! {
    /// The OpenGL 3.3 core profile functions the pass-through renderer uses.
    Core {
        fn glGetError() -> GLenum;
        fn glEnable(cap: GLenum);
        fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei);
        fn glClearColor(r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat);
        fn glClear(mask: GLbitfield);
        fn glCullFace(mode: GLenum);
        fn glFrontFace(mode: GLenum);
        fn glDepthFunc(func: GLenum);
        fn glCreateShader(kind: GLenum) -> GLuint;
        fn glShaderSource(shader: GLuint, count: GLsizei, strings: *const *const GLchar, lengths: *const GLint);
        fn glCompileShader(shader: GLuint);
        fn glGetShaderiv(shader: GLuint, pname: GLenum, params: *mut GLint);
        fn glGetShaderInfoLog(shader: GLuint, size: GLsizei, length: *mut GLsizei, log: *mut GLchar);
        fn glCreateProgram() -> GLuint;
        fn glAttachShader(program: GLuint, shader: GLuint);
        fn glBindAttribLocation(program: GLuint, index: GLuint, name: *const GLchar);
        fn glLinkProgram(program: GLuint);
        fn glGetProgramiv(program: GLuint, pname: GLenum, params: *mut GLint);
        fn glGetProgramInfoLog(program: GLuint, size: GLsizei, length: *mut GLsizei, log: *mut GLchar);
        fn glUseProgram(program: GLuint);
        fn glGenVertexArrays(n: GLsizei, arrays: *mut GLuint);
        fn glBindVertexArray(array: GLuint);
        fn glGenBuffers(n: GLsizei, buffers: *mut GLuint);
        fn glBindBuffer(target: GLenum, buffer: GLuint);
        fn glBufferData(target: GLenum, size: GLsizeiptr, data: *const c_void, usage: GLenum);
        fn glVertexAttribPointer(index: GLuint, size: GLint, type_: GLenum, normalized: GLboolean, stride: GLsizei, offset: *const c_void);
        fn glEnableVertexAttribArray(index: GLuint);
        fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei);
    }
}
