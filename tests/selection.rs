//! Selection mode (§5.2) through the safe `Context` API: hit records, the depths they hold,
//! the name stack and its errors, overflow, and how primitives hit (clipping, culling,
//! polygon mode). One C-ABI test checks that glRenderMode writes the records to the buffer
//! glSelectBuffer gave and nothing past it.

use fflight::gl::*;
use fflight::{Context, GlError};
use glam::Vec4;

/// A window depth (as fflight computes it, in float) in a hit record: round(z * (2^32 - 1)).
fn depth(z: f32) -> u32 {
    (f64::from(z) * f64::from(u32::MAX)).round() as u32
}

/// The hit-record depth of object z under identity matrices and the default depth range.
fn depth_at(object_z: f32) -> u32 {
    depth((f64::from(object_z) * 0.5 + 0.5) as f32)
}

/// A context with a 100x100 viewport and identity matrices: object z = -1 is window depth 0,
/// z = 1 depth 1, and (0, 0, 0) is the window's center at depth 0.5.
fn context() -> Context {
    let mut ctx = Context::new();
    ctx.viewport(0, 0, 100, 100).unwrap();
    ctx
}

fn select(ctx: &mut Context, size: i32) {
    ctx.select_buffer(size, 64).unwrap();
    assert_eq!(ctx.render_mode(GL_SELECT).unwrap().0, 0);
}

/// Leaves selection mode: the hit count and the records written.
fn finish(ctx: &mut Context) -> (i32, Vec<u32>) {
    let (count, finished) = ctx.render_mode(GL_RENDER).unwrap();
    (count, finished.unwrap().hit_records)
}

fn draw(ctx: &mut Context, mode: GLenum, vertices: &[[f32; 3]]) {
    ctx.begin(mode).unwrap();
    for v in vertices {
        ctx.vertex(Vec4::new(v[0], v[1], v[2], 1.0));
    }
    ctx.end().unwrap();
}

fn get_int(ctx: &Context, pname: GLenum) -> i32 {
    ctx.get(pname).unwrap().as_ints()[0]
}

#[test]
fn state_and_defaults() {
    let mut ctx = context();
    assert_eq!(get_int(&ctx, GL_MAX_NAME_STACK_DEPTH), 64);
    assert_eq!(get_int(&ctx, GL_NAME_STACK_DEPTH), 0);
    assert_eq!(get_int(&ctx, GL_SELECTION_BUFFER_SIZE), 0);
    assert_eq!(ctx.get_pointer(GL_SELECTION_BUFFER_POINTER), Ok(0));
    ctx.select_buffer(12, 0x1000).unwrap();
    assert_eq!(get_int(&ctx, GL_SELECTION_BUFFER_SIZE), 12);
    assert_eq!(ctx.get_pointer(GL_SELECTION_BUFFER_POINTER), Ok(0x1000));
    ctx.render_mode(GL_SELECT).unwrap();
    assert_eq!(get_int(&ctx, GL_RENDER_MODE), GL_SELECT as i32);
    ctx.push_name(1).unwrap();
    ctx.push_name(2).unwrap();
    assert_eq!(get_int(&ctx, GL_NAME_STACK_DEPTH), 2);
    // Leaving selection empties the name stack.
    ctx.render_mode(GL_RENDER).unwrap();
    assert_eq!(get_int(&ctx, GL_NAME_STACK_DEPTH), 0);
}

#[test]
fn a_hit_record_holds_names_and_the_depth_range() {
    let mut ctx = context();
    select(&mut ctx, 64);
    ctx.init_names().unwrap();
    ctx.push_name(7).unwrap();
    draw(&mut ctx, GL_POINTS, &[[0.0, 0.0, 0.5], [0.2, 0.0, -0.5]]);
    ctx.push_name(8).unwrap();
    draw(&mut ctx, GL_LINES, &[[0.0, 0.0, 0.0], [0.5, 0.0, 0.2]]);
    // No hit since the last record: glLoadName writes nothing.
    ctx.load_name(9).unwrap();
    ctx.load_name(10).unwrap();
    draw(
        &mut ctx,
        GL_TRIANGLES,
        &[[0.0, 0.0, -0.8], [0.5, 0.0, 0.0], [0.0, 0.5, 0.6]],
    );
    let (count, records) = finish(&mut ctx);
    assert_eq!(count, 3);
    assert_eq!(
        records,
        [
            1,
            depth(0.25),
            depth(0.75),
            7,
            2,
            depth(0.5),
            depth(0.6),
            7,
            8,
            2,
            depth_at(-0.8),
            depth(0.8),
            7,
            10
        ]
    );
}

#[test]
fn only_what_survives_clipping_and_culling_hits() {
    let mut ctx = context();
    select(&mut ctx, 64);
    ctx.push_name(1).unwrap();
    // Outside the view volume: no hit.
    draw(&mut ctx, GL_POINTS, &[[2.0, 0.0, 0.0]]);
    draw(&mut ctx, GL_LINES, &[[2.0, 0.0, 0.0], [3.0, 0.5, 0.0]]);
    draw(
        &mut ctx,
        GL_TRIANGLES,
        &[[2.0, 0.0, 0.0], [3.0, 0.0, 0.0], [2.0, 1.0, 0.0]],
    );
    ctx.load_name(2).unwrap();
    // A segment crossing the far plane: clipped at depth 1.
    draw(&mut ctx, GL_LINES, &[[0.0, 0.0, 0.0], [0.0, 0.0, 3.0]]);
    ctx.load_name(3).unwrap();
    // A triangle crossing the near plane: the clipped polygon reaches depth 0.
    draw(
        &mut ctx,
        GL_TRIANGLES,
        &[[0.0, 0.0, -3.0], [0.5, 0.0, 0.0], [0.0, 0.5, 0.0]],
    );
    ctx.load_name(4).unwrap();
    // Back-facing (clockwise) and culled.
    ctx.set_capability(GL_CULL_FACE, true).unwrap();
    draw(
        &mut ctx,
        GL_TRIANGLES,
        &[[0.0, 0.0, 0.0], [0.0, 0.5, 0.0], [0.5, 0.0, 0.0]],
    );
    let (count, records) = finish(&mut ctx);
    assert_eq!(count, 2);
    assert_eq!(
        records,
        [1, depth(0.5), depth(1.0), 2, 1, depth(0.0), depth(0.5), 3]
    );
}

#[test]
fn polygons_hit_whatever_the_polygon_mode_and_edge_flags() {
    let mut ctx = context();
    ctx.polygon_mode(GL_FRONT_AND_BACK, GL_LINE).unwrap();
    ctx.edge_flag(false);
    select(&mut ctx, 64);
    ctx.push_name(1).unwrap();
    draw(
        &mut ctx,
        GL_TRIANGLES,
        &[[0.0, 0.0, 0.0], [0.5, 0.0, 0.2], [0.0, 0.5, 0.4]],
    );
    ctx.polygon_mode(GL_FRONT_AND_BACK, GL_POINT).unwrap();
    ctx.load_name(2).unwrap();
    draw(
        &mut ctx,
        GL_POLYGON,
        &[
            [0.0, 0.0, -0.2],
            [0.5, 0.0, 0.0],
            [0.5, 0.5, 0.0],
            [0.0, 0.5, 0.0],
        ],
    );
    let (count, records) = finish(&mut ctx);
    assert_eq!(count, 2);
    assert_eq!(
        records,
        [1, depth(0.5), depth(0.7), 1, 1, depth(0.4), depth(0.5), 2]
    );
}

#[test]
fn name_stack_errors_change_nothing() {
    let mut ctx = context();
    select(&mut ctx, 256);
    assert_eq!(ctx.load_name(1), Err(GlError::InvalidOperation));
    assert_eq!(ctx.pop_name(), Err(GlError::StackUnderflow));
    for name in 0..64 {
        ctx.push_name(name).unwrap();
    }
    draw(&mut ctx, GL_POINTS, &[[0.0, 0.0, 0.0]]);
    // A full stack: the error writes no record (§2.5); the hit stays pending.
    assert_eq!(ctx.push_name(64), Err(GlError::StackOverflow));
    assert_eq!(get_int(&ctx, GL_NAME_STACK_DEPTH), 64);
    ctx.init_names().unwrap();
    draw(&mut ctx, GL_POINTS, &[[0.0, 0.0, 0.5]]);
    // An empty stack: no record either.
    assert_eq!(ctx.pop_name(), Err(GlError::StackUnderflow));
    assert_eq!(ctx.load_name(3), Err(GlError::InvalidOperation));
    // An invalid mode leaves selection mode alone.
    assert_eq!(ctx.render_mode(0x1234), Err(GlError::InvalidEnum));
    assert_eq!(ctx.render_mode(GL_FEEDBACK), Err(GlError::InvalidOperation));
    assert_eq!(get_int(&ctx, GL_RENDER_MODE), GL_SELECT as i32);
    assert_eq!(ctx.select_buffer(4, 64), Err(GlError::InvalidOperation));
    assert_eq!(ctx.select_buffer(-1, 64), Err(GlError::InvalidValue));
    let (count, records) = finish(&mut ctx);
    assert_eq!(count, 2);
    assert_eq!(records.len(), 3 + 64 + 3);
    assert_eq!(records[..3], [64, depth(0.5), depth(0.5)]);
    assert_eq!(records[67..], [0, depth(0.75), depth(0.75)]);
}

#[test]
fn errors_outside_selection_and_between_begin_and_end() {
    let mut ctx = context();
    assert_eq!(ctx.render_mode(GL_SELECT), Err(GlError::InvalidOperation));
    assert_eq!(ctx.select_buffer(-1, 64), Err(GlError::InvalidValue));
    assert_eq!(ctx.select_buffer(4, 0), Err(GlError::InvalidValue));
    // Outside selection mode the name stack commands are ignored, even in error.
    ctx.push_name(1).unwrap();
    ctx.pop_name().unwrap();
    ctx.pop_name().unwrap();
    ctx.load_name(1).unwrap();
    ctx.init_names().unwrap();
    assert_eq!(get_int(&ctx, GL_NAME_STACK_DEPTH), 0);
    // A zero-sized buffer given by glSelectBuffer is a buffer.
    ctx.select_buffer(0, 0).unwrap();
    ctx.render_mode(GL_SELECT).unwrap();
    ctx.begin(GL_POINTS).unwrap();
    assert_eq!(ctx.init_names(), Err(GlError::InvalidOperation));
    assert_eq!(ctx.push_name(1), Err(GlError::InvalidOperation));
    assert_eq!(ctx.pop_name(), Err(GlError::InvalidOperation));
    assert_eq!(ctx.load_name(1), Err(GlError::InvalidOperation));
    assert_eq!(ctx.select_buffer(4, 64), Err(GlError::InvalidOperation));
    assert_eq!(ctx.render_mode(GL_RENDER), Err(GlError::InvalidOperation));
    ctx.vertex(Vec4::new(0.0, 0.0, 0.0, 1.0));
    ctx.end().unwrap();
    // The point hit: its record does not fit in a buffer of size 0.
    assert_eq!(finish(&mut ctx), (-1, vec![]));
}

#[test]
fn overflow_returns_minus_one_and_keeps_what_fits() {
    for size in 0..8 {
        let mut ctx = context();
        select(&mut ctx, size);
        ctx.push_name(5).unwrap();
        draw(&mut ctx, GL_POINTS, &[[0.0, 0.0, 0.0]]);
        ctx.push_name(6).unwrap();
        draw(&mut ctx, GL_POINTS, &[[0.0, 0.0, 0.0]]);
        let all = [
            1,
            depth(0.5),
            depth(0.5),
            5,
            2,
            depth(0.5),
            depth(0.5),
            5,
            6,
        ];
        let (count, records) = finish(&mut ctx);
        assert_eq!(count, if size >= 9 { 2 } else { -1 }, "size {size}");
        assert_eq!(records, all[..size as usize], "size {size}");
    }
}

#[test]
fn feedback_is_not_written_in_selection_mode() {
    let mut ctx = context();
    ctx.feedback_buffer(64, GL_3D, 128).unwrap();
    select(&mut ctx, 16);
    ctx.pass_through(1.0).unwrap();
    draw(
        &mut ctx,
        GL_LINE_STRIP,
        &[[0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [0.5, 0.5, 0.0]],
    );
    assert_eq!(finish(&mut ctx), (1, vec![0, depth(0.5), depth(0.5)]));
    ctx.render_mode(GL_FEEDBACK).unwrap();
    let (count, finished) = ctx.render_mode(GL_RENDER).unwrap();
    assert_eq!((count, finished.unwrap().values), (0, vec![]));
}

mod c_abi {
    use super::*;

    unsafe extern "C" {
        safe fn fflCreateContext() -> *mut std::ffi::c_void;
        fn fflMakeCurrent(context: *mut std::ffi::c_void) -> GLboolean;
        fn fflDestroyContext(context: *mut std::ffi::c_void) -> GLboolean;
        fn glSelectBuffer(size: GLsizei, buffer: *mut GLuint);
        safe fn glRenderMode(mode: GLenum) -> GLint;
        safe fn glPushName(name: GLuint);
        safe fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei);
        safe fn glBegin(mode: GLenum);
        safe fn glVertex3f(x: GLfloat, y: GLfloat, z: GLfloat);
        safe fn glEnd();
        safe fn glGetError() -> GLenum;
    }

    #[test]
    fn records_are_written_to_the_select_buffer_and_not_past_it() {
        let context = fflCreateContext();
        // SAFETY: a fresh context for this test's thread.
        assert_eq!(unsafe { fflMakeCurrent(context) }, GL_TRUE);
        glViewport(0, 0, 100, 100);
        const SENTINEL: GLuint = 0xDEAD_BEEF;
        let mut buffer = [SENTINEL; 8];
        for (size, expected) in [(8, 1), (4, -1)] {
            buffer.fill(SENTINEL);
            // SAFETY: `buffer` has room for `size` values and outlives the selection.
            unsafe { glSelectBuffer(size, buffer.as_mut_ptr()) };
            glRenderMode(GL_SELECT);
            glPushName(3);
            glPushName(4);
            glBegin(GL_POINTS);
            glVertex3f(0.0, 0.0, 0.0);
            glEnd();
            assert_eq!(glRenderMode(GL_RENDER), expected);
            assert_eq!(glGetError(), GL_NO_ERROR);
            let record = [2, depth(0.5), depth(0.5), 3, 4];
            let written = record.len().min(size as usize);
            assert_eq!(buffer[..written], record[..written]);
            assert!(buffer[written..].iter().all(|&v| v == SENTINEL));
        }
        // Destroyed (released first), or memcheck reports it lost (make test-valgrind-rust).
        // SAFETY: the context created above, used no more.
        assert_eq!(unsafe { fflDestroyContext(context) }, GL_TRUE);
    }
}
