//! Vertices lit per second through the C entry points: fflLightVertices against the same
//! vertices in immediate mode (glColor4fv, glNormal3fv, glVertex3fv between glBegin and
//! glEnd), against immediate mode with capture on (the per-vertex way to get the results
//! back), against glDrawArrays from float arrays (with and without capture), and the Rust API
//! (Context::light_vertices). Two lights (one a positional spot with attenuation), local
//! viewer, two-sided lighting, color material, separate specular.
//!
//! Without capture (and in GL_RENDER mode) a draw processes nothing, as nothing would receive
//! the vertices: those rows measure the calls alone.
//!
//! `cargo run --release --example light_throughput [vertices] [runs]`; prints the median.

use std::ffi::c_void;
use std::hint::black_box;
use std::time::Instant;

use fflight::gl::*;
use fflight::lighting::{FaceColors, LitVertex};
use fflight::pipeline::vertex::ProcessedVertex;
use glam::{Vec3, Vec4};

unsafe extern "C" {
    fn glEnable(cap: GLenum);
    fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat);
    fn glLightf(light: GLenum, pname: GLenum, param: GLfloat);
    fn glLightModeli(pname: GLenum, param: GLint);
    fn glMatrixMode(mode: GLenum);
    fn glFrustum(l: GLdouble, r: GLdouble, b: GLdouble, t: GLdouble, n: GLdouble, f: GLdouble);
    fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat);
    fn glRotatef(angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat);
    fn glBegin(mode: GLenum);
    fn glEnd();
    fn glColor4fv(v: *const GLfloat);
    fn glNormal3fv(v: *const GLfloat);
    fn glVertex3fv(v: *const GLfloat);
    fn glVertexPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glNormalPointer(ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glColorPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glEnableClientState(array: GLenum);
    fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei);
    fn glGetError() -> GLenum;
    fn fflCaptureBegin();
    fn fflCaptureEnd();
    fn fflCaptureVertexCount() -> GLuint;
    fn fflLightVertices(
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

fn set_state() {
    unsafe {
        glMatrixMode(GL_PROJECTION);
        glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 100.0);
        glMatrixMode(GL_MODELVIEW);
        glTranslatef(0.0, 0.0, -5.0);
        glRotatef(30.0, 1.0, 1.0, 0.0);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_LIGHT1);
        glLightfv(GL_LIGHT0, GL_POSITION, [0.3, 0.5, 1.0, 0.0].as_ptr());
        glLightfv(GL_LIGHT1, GL_POSITION, [-2.0, 1.0, 3.0, 1.0].as_ptr());
        glLightfv(GL_LIGHT1, GL_SPECULAR, [0.9, 0.9, 0.9, 1.0].as_ptr());
        glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, [1.0, -0.5, -1.0].as_ptr());
        glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 60.0);
        glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.1);
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
        glLightModeli(
            GL_LIGHT_MODEL_COLOR_CONTROL,
            GL_SEPARATE_SPECULAR_COLOR as GLint,
        );
        glEnable(GL_COLOR_MATERIAL);
    }
}

/// The median of `runs` timings of `f`, in vertices per second.
fn rate(count: usize, runs: usize, mut f: impl FnMut()) -> f64 {
    let mut seconds: Vec<f64> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .collect();
    seconds.sort_by(f64::total_cmp);
    count as f64 / seconds[runs / 2]
}

fn main() {
    let mut args = std::env::args().skip(1);
    let count: usize = args
        .next()
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let runs: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(5);
    set_state();

    let mut seed = 0x1234_5678_u32;
    let mut random = move || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        seed as f32 / u32::MAX as f32 * 2.0 - 1.0
    };
    let positions: Vec<f32> = (0..3 * count).map(|_| random() * 2.0).collect();
    let normals: Vec<f32> = (0..3 * count).map(|_| random()).collect();
    let colors: Vec<f32> = (0..4 * count).map(|_| random() * 0.5 + 0.5).collect();
    let mut out = vec![0.0f32; 24 * count];

    let bulk = rate(count, runs, || unsafe {
        let o = out.as_mut_ptr();
        let s = 96;
        fflLightVertices(
            count as GLsizei,
            3,
            positions.as_ptr(),
            0,
            normals.as_ptr(),
            0,
            colors.as_ptr(),
            0,
            o,
            s,
            o.add(4),
            s,
            o.add(8),
            s,
            o.add(12),
            s,
            o.add(16),
            s,
            o.add(20),
            s,
        );
        black_box(&out);
    });

    let immediate = |capture: bool| {
        rate(count, runs, || unsafe {
            if capture {
                fflCaptureBegin();
            }
            glBegin(GL_POINTS);
            for i in 0..count {
                glColor4fv(colors.as_ptr().add(4 * i));
                glNormal3fv(normals.as_ptr().add(3 * i));
                glVertex3fv(positions.as_ptr().add(3 * i));
            }
            glEnd();
            if capture {
                fflCaptureEnd();
                black_box(fflCaptureVertexCount());
            }
        })
    };
    let immediate_plain = immediate(false);
    let immediate_captured = immediate(true);

    let arrays = |capture: bool| {
        rate(count, runs, || unsafe {
            glVertexPointer(3, GL_FLOAT, 0, positions.as_ptr().cast());
            glNormalPointer(GL_FLOAT, 0, normals.as_ptr().cast());
            glColorPointer(4, GL_FLOAT, 0, colors.as_ptr().cast());
            glEnableClientState(GL_VERTEX_ARRAY);
            glEnableClientState(GL_NORMAL_ARRAY);
            glEnableClientState(GL_COLOR_ARRAY);
            if capture {
                fflCaptureBegin();
            }
            glDrawArrays(GL_POINTS, 0, count as GLsizei);
            if capture {
                fflCaptureEnd();
                black_box(fflCaptureVertexCount());
            }
        })
    };
    let arrays_plain = arrays(false);
    let arrays_captured = arrays(true);

    let positions4: Vec<Vec4> = positions
        .chunks_exact(3)
        .map(|p| Vec3::from_slice(p).extend(1.0))
        .collect();
    let normals3: Vec<Vec3> = normals.chunks_exact(3).map(Vec3::from_slice).collect();
    let colors4: Vec<Vec4> = colors.chunks_exact(4).map(Vec4::from_slice).collect();
    let mut processed = Vec::new();
    let rust = fflight::current::with_current(|ctx| {
        let face = FaceColors {
            primary: Vec4::ZERO,
            secondary: Vec4::ZERO,
        };
        let placeholder = ProcessedVertex {
            eye: Vec4::ZERO,
            clip: Vec4::ZERO,
            colors: LitVertex {
                front: face,
                back: face,
            },
            tex_coord: Vec4::ZERO,
            edge_flag: true,
        };
        processed.resize(count, placeholder);
        rate(count, runs, || {
            ctx.light_vertices(&positions4, Some(&normals3), Some(&colors4), &mut processed)
                .unwrap();
            black_box(&processed);
        })
    })
    .unwrap();

    assert_eq!(unsafe { glGetError() }, GL_NO_ERROR);
    println!("{count} vertices, median of {runs} runs, vertices per second:");
    println!("  fflLightVertices (6 outputs)         {bulk:>12.0}");
    println!("  Context::light_vertices (Rust)       {rust:>12.0}");
    println!("  immediate mode + capture             {immediate_captured:>12.0}");
    println!("  glDrawArrays + capture               {arrays_captured:>12.0}");
    println!("  immediate mode, calls only (GL_RENDER) {immediate_plain:>10.0}");
    println!("  glDrawArrays, call only (GL_RENDER)  {arrays_plain:>12.0}");
    println!(
        "  bulk / immediate with capture: {:.2}x, bulk / glDrawArrays with capture: {:.2}x",
        bulk / immediate_captured,
        bulk / arrays_captured
    );
}
