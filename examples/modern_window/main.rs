//! Legacy lighting in an OpenGL 3.3 core profile window, checked against the GL's own
//! fixed-function lighting.
//!
//! ```sh
//! cargo run --example modern_window [-- OUTPUT.png]      # under X11, or: make test-window
//! ```
//!
//! 1. GLFW opens a window with an OpenGL 3.3 **core** context, where fixed-function lighting
//!    does not exist (the example checks: `glEnable(GL_LIGHTING)` is `GL_INVALID_ENUM` there).
//! 2. The legacy routine (`scene.rs`: lights, materials, color material, glBegin/glEnd quad
//!    strips, vertex arrays with glDrawElements, a display list called twice, two-sided
//!    lighting) runs unchanged through fflight between `fflCaptureBegin` and `fflCaptureEnd`.
//! 3. The captured triangles (clip coordinates and lit colors of both faces) are drawn in the
//!    core context by a pass-through shader, with the raster state the routine set, read
//!    back from fflight (viewport, clear color, depth test, culling, front face, shade model).
//! 4. A second window with a compatibility context runs the same routine through the system
//!    GL (Mesa's llvmpipe under Xvfb), which lights it with its own fixed-function pipeline.
//! 5. Both framebuffers (RGBA8, the same size) are read back with glReadPixels and compared
//!    pixel by pixel (`compare.rs`: largest and mean difference, away from silhouettes);
//!    the two renderings and their amplified difference are written side by side to a PNG.
//!
//! The process exits with status 1 when the renderings differ by more than the tolerance
//! (2/255 away from silhouettes, justified in `compare.rs`), or when a check that keeps the
//! comparison meaningful fails. Why fflight's `glBegin` and the system GL's never get mixed
//! up, although both are in the process: see `gl.rs`.

mod compare;
mod gl;
mod scene;

use std::ffi::{CStr, CString, c_void};
use std::process::ExitCode;
use std::time::Instant;

use glfw::Context as _;

use gl::*;

const WIDTH: u32 = 400;
const HEIGHT: u32 = 300;

/// fflight's capture API as `include/fflight.h` declares it (fflight-only names: nothing in
/// the system GL has them).
#[repr(C)]
#[derive(Clone, Copy, Default)]
struct FflCapturedVertex {
    eye: [f32; 4],
    clip: [f32; 4],
    front_primary: [f32; 4],
    front_secondary: [f32; 4],
    back_primary: [f32; 4],
    back_secondary: [f32; 4],
    tex_coord: [f32; 4],
    edge_flag: u8,
    reserved: [u8; 3],
}

#[repr(C)]
#[derive(Clone, Copy, Default)]
struct FflCapturedPrimitive {
    kind: GLenum,
    mode: GLenum,
    draw: GLuint,
    vertex_count: GLuint,
    vertices: [GLuint; 3],
    edges: [GLboolean; 3],
    reserved: u8,
}

unsafe extern "C" {
    fn fflCaptureBegin();
    fn fflCaptureEnd();
    fn fflCaptureVertexCount() -> GLuint;
    fn fflCapturePrimitiveCount() -> GLuint;
    fn fflCaptureReadVertices(first: GLuint, count: GLuint, out: *mut FflCapturedVertex) -> GLuint;
    fn fflCaptureReadPrimitives(
        first: GLuint,
        count: GLuint,
        out: *mut FflCapturedPrimitive,
    ) -> GLuint;
}

fn main() -> ExitCode {
    let output = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "fflight-vs-gl.png".into());
    match run(&output) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("modern_window: FAIL: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run(output: &str) -> Result<(), String> {
    let start = Instant::now();
    let mut glfw = glfw::init(|error, description| eprintln!("GLFW: {error:?}: {description}"))
        .map_err(|e| format!("GLFW cannot start (is there an X display?): {e:?}"))?;

    // 1. The core profile window.
    glfw.window_hint(glfw::WindowHint::ContextVersion(3, 3));
    glfw.window_hint(glfw::WindowHint::OpenGlProfile(
        glfw::OpenGlProfileHint::Core,
    ));
    glfw.window_hint(glfw::WindowHint::OpenGlForwardCompat(true));
    let mut core_window = GlWindow::open(&mut glfw, "fflight in a 3.3 core context", "core")?;
    let core = Core::load(|name| core_window.proc_address(name))?;
    let core_target = &core_window.target;
    // SAFETY (this block and the others calling GL): the tables were loaded from the context
    // current on this thread, or are fflight's, whose context is this thread's default one.
    unsafe {
        let mut profile = 0;
        (core_target.glGetIntegerv)(GL_CONTEXT_PROFILE_MASK, &mut profile);
        if profile & GL_CONTEXT_CORE_PROFILE_BIT == 0 {
            return Err("not a core profile context".into());
        }
        (core.glEnable)(GL_LIGHTING);
        let error = (core.glGetError)();
        if error != GL_INVALID_ENUM {
            return Err(format!(
                "glEnable(GL_LIGHTING) in the core context gave {error:#x}"
            ));
        }
    }

    // 2. The legacy routine through fflight, captured.
    let fflight = Legacy::fflight();
    let (vertices, primitives, raster) = unsafe {
        fflCaptureBegin();
        scene::draw(&fflight, WIDTH as i32, HEIGHT as i32);
        fflCaptureEnd();
        check_error("fflight", (fflight.glGetError)())?;
        let mut vertices = vec![FflCapturedVertex::default(); fflCaptureVertexCount() as usize];
        let mut primitives =
            vec![FflCapturedPrimitive::default(); fflCapturePrimitiveCount() as usize];
        fflCaptureReadVertices(0, vertices.len() as u32, vertices.as_mut_ptr());
        fflCaptureReadPrimitives(0, primitives.len() as u32, primitives.as_mut_ptr());
        (vertices, primitives, RasterState::query(&fflight))
    };
    let triangles = triangle_stream(&vertices, &primitives);
    println!(
        "fflight captured:      {} vertices, {} primitives, {} triangles",
        vertices.len(),
        primitives.len(),
        triangles.len() / (3 * FLOATS_PER_VERTEX)
    );
    if triangles.is_empty() {
        return Err("fflight captured no triangle".into());
    }

    // 3. Drawn by a pass-through shader in the core context.
    let modern = unsafe {
        let framebuffer = Offscreen::new(core_target)?;
        draw_captured(&core, &triangles, &raster)?;
        check_error("core context", (core.glGetError)())?;
        let pixels = framebuffer.read(core_target);
        framebuffer.show(core_target);
        pixels
    };
    core_window.window.swap_buffers();

    // 4. The same routine lit by the system GL's fixed-function pipeline.
    glfw.default_window_hints();
    let mut compat_window = GlWindow::open(
        &mut glfw,
        "the GL's own fixed-function lighting",
        "compatibility",
    )?;
    let system = Legacy::load(|name| compat_window.proc_address(name))?;
    let compat_target = &compat_window.target;
    // Two different glBegin functions. Whatever a lookup of the name in the process's global
    // scope finds (the libraries GLFW and libglvnd opened may export glBegin), it is not
    // fflight's: the executable exports no gl* symbol, and nothing here calls GL by name.
    let global = global_symbol(c"glBegin");
    println!(
        "glBegin: fflight's at {:p}, the system GL's at {:p}; by name: {}",
        fflight.glBegin as *const c_void,
        system.glBegin as *const c_void,
        global.as_ref().map_or("none", |(_, library)| library),
    );
    if fflight.glBegin as usize == system.glBegin as usize
        || global.is_some_and(|(address, _)| address == fflight.glBegin as usize)
    {
        return Err("fflight's glBegin is reachable as the system GL's".into());
    }
    let fixed_function = unsafe {
        let framebuffer = Offscreen::new(compat_target)?;
        scene::draw(&system, WIDTH as i32, HEIGHT as i32);
        check_error("compatibility context", (system.glGetError)())?;
        let pixels = framebuffer.read(compat_target);
        framebuffer.show(compat_target);
        pixels
    };
    compat_window.window.swap_buffers();

    // 5. The comparison.
    let report = compare::compare(&modern, &fixed_function, WIDTH as usize, HEIGHT as usize);
    print!("{report}");
    compare::write_png(
        output,
        &modern,
        &fixed_function,
        WIDTH as usize,
        HEIGHT as usize,
    )?;
    println!("wrote {output} ({:.2} s)", start.elapsed().as_secs_f64());
    report.verdict()
}

/// A WIDTH x HEIGHT window, its context, and the functions its framebuffer is read with.
struct GlWindow {
    window: glfw::PWindow,
    _events: glfw::GlfwReceiver<(f64, glfw::WindowEvent)>,
    target: Target,
}

impl GlWindow {
    /// Opens a window with the current window hints and makes its context current.
    fn open(glfw: &mut glfw::Glfw, title: &str, kind: &str) -> Result<GlWindow, String> {
        let (mut window, events) = glfw
            .create_window(WIDTH, HEIGHT, title, glfw::WindowMode::Windowed)
            .ok_or(format!("no {kind} context"))?;
        window.make_current();
        let target = Target::load(|name| proc_address(&mut window, name))?;
        println!(
            "{:<22} {}",
            format!("{kind} context:"),
            context_info(&target)
        );
        Ok(GlWindow {
            window,
            _events: events,
            target,
        })
    }

    fn proc_address(&mut self, name: &str) -> *const c_void {
        proc_address(&mut self.window, name)
    }
}

/// The address of `name` in the context of `window` (made current), as glfwGetProcAddress
/// gives it.
fn proc_address(window: &mut glfw::PWindow, name: &str) -> *const c_void {
    window
        .get_proc_address(name)
        .map_or(std::ptr::null(), |f| f as *const c_void)
}

/// What `dlsym(RTLD_DEFAULT, name)` finds: its address and the library that defines it.
fn global_symbol(name: &CStr) -> Option<(usize, String)> {
    // SAFETY: dlsym and dladdr only look up; dladdr fills `info` with pointers to strings of
    // the loaded library, read here while it stays loaded.
    unsafe {
        let address = libc::dlsym(libc::RTLD_DEFAULT, name.as_ptr());
        if address.is_null() {
            return None;
        }
        let mut info: libc::Dl_info = std::mem::zeroed();
        let library = if libc::dladdr(address, &mut info) != 0 && !info.dli_fname.is_null() {
            CStr::from_ptr(info.dli_fname)
                .to_string_lossy()
                .into_owned()
        } else {
            "?".into()
        };
        Some((address as usize, library))
    }
}

fn context_info(gl: &Target) -> String {
    // SAFETY: glGetString returns NULL or a static NUL-terminated string.
    let string = |name| unsafe {
        let s = (gl.glGetString)(name);
        if s.is_null() {
            "?".into()
        } else {
            CStr::from_ptr(s.cast()).to_string_lossy().into_owned()
        }
    };
    format!("{} ({})", string(GL_VERSION), string(GL_RENDERER))
}

fn check_error(what: &str, error: GLenum) -> Result<(), String> {
    match error {
        GL_NO_ERROR => Ok(()),
        error => Err(format!("{what}: GL error {error:#x}")),
    }
}

/// The rasterization state the legacy routine set, read back from fflight: what the renderer
/// of the captured triangles must apply itself (fflight does not rasterize). It is read once,
/// after the routine; a routine that changed it between draws would need it per draw (the
/// captured primitives say which draw they come from), which this renderer does not do.
struct RasterState {
    viewport: [GLint; 4],
    clear_color: [GLfloat; 4],
    depth_test: bool,
    depth_func: GLenum,
    cull_face: bool,
    cull_face_mode: GLenum,
    front_face: GLenum,
    flat: bool,
}

impl RasterState {
    /// # Safety
    /// `gl` holds valid functions of a GL with a current context on this thread.
    unsafe fn query(gl: &Legacy) -> RasterState {
        let integer = |pname| {
            let mut value = 0;
            // SAFETY: each of these pnames has one value.
            unsafe { (gl.glGetIntegerv)(pname, &mut value) };
            value as GLenum
        };
        let mut viewport = [0; 4];
        let mut clear_color = [0.0; 4];
        // SAFETY: four values each.
        unsafe {
            (gl.glGetIntegerv)(GL_VIEWPORT, viewport.as_mut_ptr());
            (gl.glGetFloatv)(GL_COLOR_CLEAR_VALUE, clear_color.as_mut_ptr());
        }
        // SAFETY: the caller's guarantee.
        let enabled = |cap| unsafe { (gl.glIsEnabled)(cap) } != 0;
        RasterState {
            viewport,
            clear_color,
            depth_test: enabled(GL_DEPTH_TEST),
            depth_func: integer(GL_DEPTH_FUNC),
            cull_face: enabled(GL_CULL_FACE),
            cull_face_mode: integer(GL_CULL_FACE_MODE),
            front_face: integer(GL_FRONT_FACE),
            flat: integer(GL_SHADE_MODEL) == GL_FLAT,
        }
    }
}

/// Floats per vertex of the core renderer's vertex buffer: clip coordinates, then the
/// primary and secondary colors of the front and the back face.
const FLOATS_PER_VERTEX: usize = 20;

/// The captured triangles as a vertex stream for glDrawArrays(GL_TRIANGLES), each vertex
/// copied in primitive order (points and lines: the scene has none).
fn triangle_stream(
    vertices: &[FflCapturedVertex],
    primitives: &[FflCapturedPrimitive],
) -> Vec<f32> {
    let mut stream = Vec::new();
    for primitive in primitives.iter().filter(|p| p.kind == GL_TRIANGLES) {
        for &index in &primitive.vertices {
            let v = &vertices[index as usize];
            for attribute in [
                v.clip,
                v.front_primary,
                v.front_secondary,
                v.back_primary,
                v.back_secondary,
            ] {
                stream.extend_from_slice(&attribute);
            }
        }
    }
    stream
}

/// The pass-through shaders: the vertex's clip coordinates as they are, its lit colors
/// interpolated; per fragment, the face's primary color plus its secondary color (the color
/// sum of GL 1.5 §3.9, which fixed-function GL does per fragment too), clamped by the RGBA8
/// framebuffer. `INTERPOLATION` is `smooth` or `flat` (glShadeModel); the provoking vertex is
/// the last in both GLs.
const VERTEX_SHADER: &str = "#version 330 core
in vec4 clip;
in vec4 front_primary;
in vec4 front_secondary;
in vec4 back_primary;
in vec4 back_secondary;
INTERPOLATION out vec4 front_color;
INTERPOLATION out vec4 front_specular;
INTERPOLATION out vec4 back_color;
INTERPOLATION out vec4 back_specular;
void main() {
    gl_Position = clip;
    front_color = front_primary;
    front_specular = front_secondary;
    back_color = back_primary;
    back_specular = back_secondary;
}
";

const FRAGMENT_SHADER: &str = "#version 330 core
INTERPOLATION in vec4 front_color;
INTERPOLATION in vec4 front_specular;
INTERPOLATION in vec4 back_color;
INTERPOLATION in vec4 back_specular;
out vec4 fragment;
void main() {
    vec4 primary = gl_FrontFacing ? front_color : back_color;
    vec4 secondary = gl_FrontFacing ? front_specular : back_specular;
    fragment = vec4(primary.rgb + secondary.rgb, primary.a);
}
";

const ATTRIBUTES: [&str; 5] = [
    "clip",
    "front_primary",
    "front_secondary",
    "back_primary",
    "back_secondary",
];

/// Draws `stream` (see [`triangle_stream`]) into the bound framebuffer with `raster`.
///
/// # Safety
/// `gl` holds valid functions of the context current on this thread.
unsafe fn draw_captured(gl: &Core, stream: &[f32], raster: &RasterState) -> Result<(), String> {
    let interpolation = if raster.flat { "flat" } else { "smooth" };
    unsafe {
        let program = link_program(
            gl,
            &VERTEX_SHADER.replace("INTERPOLATION", interpolation),
            &FRAGMENT_SHADER.replace("INTERPOLATION", interpolation),
        )?;
        (gl.glUseProgram)(program);

        let (mut vao, mut vbo) = (0, 0);
        (gl.glGenVertexArrays)(1, &mut vao);
        (gl.glBindVertexArray)(vao);
        (gl.glGenBuffers)(1, &mut vbo);
        (gl.glBindBuffer)(GL_ARRAY_BUFFER, vbo);
        (gl.glBufferData)(
            GL_ARRAY_BUFFER,
            std::mem::size_of_val(stream) as isize,
            stream.as_ptr().cast(),
            GL_STATIC_DRAW,
        );
        let stride = (FLOATS_PER_VERTEX * 4) as i32;
        for index in 0..ATTRIBUTES.len() {
            let offset = (index * 16) as *const c_void;
            (gl.glVertexAttribPointer)(index as u32, 4, GL_FLOAT, GL_FALSE, stride, offset);
            (gl.glEnableVertexAttribArray)(index as u32);
        }

        let [x, y, w, h] = raster.viewport;
        (gl.glViewport)(x, y, w, h);
        let [r, g, b, a] = raster.clear_color;
        (gl.glClearColor)(r, g, b, a);
        (gl.glClear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        if raster.depth_test {
            (gl.glEnable)(GL_DEPTH_TEST);
            (gl.glDepthFunc)(raster.depth_func);
        }
        if raster.cull_face {
            (gl.glEnable)(GL_CULL_FACE);
            (gl.glCullFace)(raster.cull_face_mode);
        }
        (gl.glFrontFace)(raster.front_face);
        (gl.glDrawArrays)(GL_TRIANGLES, 0, (stream.len() / FLOATS_PER_VERTEX) as i32);
    }
    Ok(())
}

/// Compiles and links the two shaders, the attributes bound to locations 0 to 4.
///
/// # Safety
/// `gl` holds valid functions of the context current on this thread.
unsafe fn link_program(gl: &Core, vertex: &str, fragment: &str) -> Result<GLuint, String> {
    unsafe {
        let program = (gl.glCreateProgram)();
        for (kind, source) in [(GL_VERTEX_SHADER, vertex), (GL_FRAGMENT_SHADER, fragment)] {
            let shader = (gl.glCreateShader)(kind);
            let source = CString::new(source).map_err(|e| e.to_string())?;
            (gl.glShaderSource)(shader, 1, &source.as_ptr(), std::ptr::null());
            (gl.glCompileShader)(shader);
            let mut ok = 0;
            (gl.glGetShaderiv)(shader, GL_COMPILE_STATUS, &mut ok);
            if ok == 0 {
                let mut log = [0u8; 1024];
                let mut length = 0;
                (gl.glGetShaderInfoLog)(shader, 1024, &mut length, log.as_mut_ptr().cast());
                return Err(format!(
                    "shader: {}",
                    String::from_utf8_lossy(&log[..length as usize])
                ));
            }
            (gl.glAttachShader)(program, shader);
        }
        for (index, name) in ATTRIBUTES.iter().enumerate() {
            let name = CString::new(*name).map_err(|e| e.to_string())?;
            (gl.glBindAttribLocation)(program, index as u32, name.as_ptr());
        }
        (gl.glLinkProgram)(program);
        let mut ok = 0;
        (gl.glGetProgramiv)(program, GL_LINK_STATUS, &mut ok);
        if ok == 0 {
            let mut log = [0u8; 1024];
            let mut length = 0;
            (gl.glGetProgramInfoLog)(program, 1024, &mut length, log.as_mut_ptr().cast());
            return Err(format!(
                "link: {}",
                String::from_utf8_lossy(&log[..length as usize])
            ));
        }
        Ok(program)
    }
}

/// A WIDTH x HEIGHT framebuffer object with RGBA8 color (the alpha channel tells the objects
/// apart, which the window's visual may not have) and 24-bit depth, bound for drawing.
struct Offscreen {
    framebuffer: GLuint,
}

impl Offscreen {
    /// # Safety
    /// `gl` holds valid functions of the context current on this thread.
    unsafe fn new(gl: &Target) -> Result<Offscreen, String> {
        unsafe {
            let mut framebuffer = 0;
            (gl.glGenFramebuffers)(1, &mut framebuffer);
            (gl.glBindFramebuffer)(GL_FRAMEBUFFER, framebuffer);
            for (format, attachment) in [
                (GL_RGBA8, GL_COLOR_ATTACHMENT0),
                (GL_DEPTH_COMPONENT24, GL_DEPTH_ATTACHMENT),
            ] {
                let mut renderbuffer = 0;
                (gl.glGenRenderbuffers)(1, &mut renderbuffer);
                (gl.glBindRenderbuffer)(GL_RENDERBUFFER, renderbuffer);
                (gl.glRenderbufferStorage)(GL_RENDERBUFFER, format, WIDTH as i32, HEIGHT as i32);
                (gl.glFramebufferRenderbuffer)(
                    GL_FRAMEBUFFER,
                    attachment,
                    GL_RENDERBUFFER,
                    renderbuffer,
                );
            }
            match (gl.glCheckFramebufferStatus)(GL_FRAMEBUFFER) {
                GL_FRAMEBUFFER_COMPLETE => Ok(Offscreen { framebuffer }),
                status => Err(format!("framebuffer incomplete: {status:#x}")),
            }
        }
    }

    /// The color buffer, RGBA8, rows bottom to top.
    ///
    /// # Safety
    /// As for `new`, in the same context.
    unsafe fn read(&self, gl: &Target) -> Vec<u8> {
        let mut pixels = vec![0u8; (WIDTH * HEIGHT * 4) as usize];
        unsafe {
            (gl.glBindFramebuffer)(GL_READ_FRAMEBUFFER, self.framebuffer);
            (gl.glReadPixels)(
                0,
                0,
                WIDTH as i32,
                HEIGHT as i32,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                pixels.as_mut_ptr().cast(),
            );
        }
        pixels
    }

    /// Copies the color buffer to the window's back buffer (shown by the next swap).
    ///
    /// # Safety
    /// As for `new`, in the same context.
    unsafe fn show(&self, gl: &Target) {
        unsafe {
            (gl.glBindFramebuffer)(GL_READ_FRAMEBUFFER, self.framebuffer);
            (gl.glBindFramebuffer)(GL_DRAW_FRAMEBUFFER, 0);
            let (w, h) = (WIDTH as i32, HEIGHT as i32);
            (gl.glBlitFramebuffer)(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
            (gl.glFinish)();
        }
    }
}
