//! glFeedbackBuffer, glRenderMode and glPassThrough (§5.3): their errors, the state they
//! report, the value count glRenderMode returns, and the -1 of an overflow with nothing
//! written past the buffer.

#[macro_use]
mod common;

use common::*;

fn feedback_buffer(size: i32, kind: GLenum, buffer: &mut [f32]) {
    assert!(size <= buffer.len() as i32);
    // SAFETY: `buffer` has room for `size` floats and outlives the feedback pass of each test.
    unsafe { glFeedbackBuffer(size, kind, buffer.as_mut_ptr()) }
}

fn render_mode() -> GLenum {
    get_int(GL_RENDER_MODE) as GLenum
}

/// A point at the window's center: with identity matrices and a 100x100 viewport,
/// (0, 0, 0) lands at (50, 50, 0.5).
fn center_point() {
    glBegin(GL_POINTS);
    glVertex3f(0.0, 0.0, 0.0);
    glEnd();
}

#[test]
fn defaults() {
    let _ctx = fresh();
    assert_eq!(render_mode(), GL_RENDER);
    assert_eq!(get_int(GL_FEEDBACK_BUFFER_SIZE), 0);
    assert_eq!(get_int(GL_FEEDBACK_BUFFER_TYPE), GL_2D as i32);
    // leaving GL_RENDER returns 0
    assert_eq!(glRenderMode(GL_RENDER), 0);
    expect_no_error("defaults");
}

#[test]
fn feedback_mode_needs_a_feedback_buffer_first() {
    let _ctx = fresh();
    assert_eq!(glRenderMode(GL_FEEDBACK), 0);
    expect_error(
        GL_INVALID_OPERATION,
        "glRenderMode(GL_FEEDBACK) before glFeedbackBuffer",
    );
    assert_eq!(render_mode(), GL_RENDER);
    // a failed glFeedbackBuffer does not count as one
    let mut buf = [SENTINEL_F; 8];
    feedback_buffer(8, 0x1234, &mut buf);
    expect_error(GL_INVALID_ENUM, "bad type");
    glRenderMode(GL_FEEDBACK);
    expect_error(GL_INVALID_OPERATION, "after a failed glFeedbackBuffer");
    assert_eq!(render_mode(), GL_RENDER);
}

#[test]
fn select_mode_without_a_selection_buffer_is_invalid_operation() {
    let _ctx = fresh();
    assert_eq!(glRenderMode(GL_SELECT), 0);
    expect_error(
        GL_INVALID_OPERATION,
        "glRenderMode(GL_SELECT) before glSelectBuffer",
    );
    assert_eq!(render_mode(), GL_RENDER);
}

#[test]
fn feedback_buffer_state_round_trips_for_every_type() {
    let _ctx = fresh();
    let mut buf = [SENTINEL_F; 64];
    for (i, kind) in FEEDBACK_TYPES.into_iter().enumerate() {
        let size = 10 + i as i32;
        feedback_buffer(size, kind, &mut buf);
        expect_no_error(&format!("glFeedbackBuffer type {kind:#x}"));
        assert_eq!(get_int(GL_FEEDBACK_BUFFER_SIZE), size);
        assert_eq!(get_int(GL_FEEDBACK_BUFFER_TYPE), kind as i32);
    }
    assert_eq!(glRenderMode(GL_FEEDBACK), 0);
    assert_eq!(render_mode(), GL_FEEDBACK);
    assert_eq!(glRenderMode(GL_RENDER), 0, "nothing was fed back");
    assert_eq!(render_mode(), GL_RENDER);
    assert_eq!(buf, [SENTINEL_F; 64]);
    expect_no_error("round trip");
}

#[test]
fn feedback_buffer_errors_follow_mesas_order_and_change_nothing() {
    let _ctx = fresh();
    let mut buf = [SENTINEL_F; 16];
    feedback_buffer(16, GL_3D, &mut buf);
    let before = (
        get_int(GL_FEEDBACK_BUFFER_SIZE),
        get_int(GL_FEEDBACK_BUFFER_TYPE),
    );
    let mut other = [SENTINEL_F; 16];
    feedback_buffer(-1, GL_2D, &mut other);
    expect_error(GL_INVALID_VALUE, "negative size");
    feedback_buffer(i32::MIN, GL_2D, &mut other);
    expect_error(GL_INVALID_VALUE, "most negative size");
    for bad in [0x1234, GL_FEEDBACK, GL_POINT_TOKEN] {
        feedback_buffer(4, bad, &mut other);
        expect_error(GL_INVALID_ENUM, &format!("type {bad:#x}"));
    }
    // negative size and bad type: the size is checked first
    feedback_buffer(-4, 0x1234, &mut other);
    expect_error(GL_INVALID_VALUE, "negative size + bad type");
    // NULL with room promised
    // SAFETY: NULL is allowed and must be reported, never written.
    unsafe { glFeedbackBuffer(4, GL_2D, std::ptr::null_mut()) };
    expect_error(GL_INVALID_VALUE, "NULL buffer with size 4");
    assert_eq!(
        (
            get_int(GL_FEEDBACK_BUFFER_SIZE),
            get_int(GL_FEEDBACK_BUFFER_TYPE)
        ),
        before
    );

    // in feedback mode, glFeedbackBuffer is GL_INVALID_OPERATION, before any other check
    glRenderMode(GL_FEEDBACK);
    feedback_buffer(8, GL_2D, &mut other);
    expect_error(GL_INVALID_OPERATION, "glFeedbackBuffer in feedback mode");
    feedback_buffer(-1, 0x1234, &mut other);
    expect_error(
        GL_INVALID_OPERATION,
        "bad glFeedbackBuffer in feedback mode",
    );
    assert_eq!(get_int(GL_FEEDBACK_BUFFER_SIZE), 16);
    // the original buffer is still the one in use
    glPassThrough(7.0);
    assert_eq!(glRenderMode(GL_RENDER), 2);
    assert_eq!(buf[..2], [GL_PASS_THROUGH_TOKEN as f32, 7.0]);
    assert_eq!(other, [SENTINEL_F; 16]);
    expect_no_error("after");
}

#[test]
fn render_mode_rejects_other_enums_and_keeps_the_mode() {
    let _ctx = fresh();
    for bad in [0x1234, GL_FEEDBACK_BUFFER_SIZE, GL_2D] {
        assert_eq!(glRenderMode(bad), 0);
        expect_error(GL_INVALID_ENUM, &format!("glRenderMode({bad:#x})"));
        assert_eq!(render_mode(), GL_RENDER);
    }
    let mut buf = [SENTINEL_F; 8];
    feedback_buffer(8, GL_2D, &mut buf);
    glRenderMode(GL_FEEDBACK);
    glPassThrough(1.0);
    // a bad mode in feedback neither ends the pass nor loses its values
    assert_eq!(glRenderMode(0x1234), 0);
    expect_error(GL_INVALID_ENUM, "glRenderMode(bad) in feedback");
    assert_eq!(render_mode(), GL_FEEDBACK);
    glPassThrough(2.0);
    assert_eq!(glRenderMode(GL_RENDER), 4);
    assert_eq!(
        buf[..5],
        [
            GL_PASS_THROUGH_TOKEN as f32,
            1.0,
            GL_PASS_THROUGH_TOKEN as f32,
            2.0,
            SENTINEL_F
        ]
    );
}

#[test]
fn pass_through_outside_feedback_does_nothing() {
    let _ctx = fresh();
    glPassThrough(3.0);
    expect_no_error("glPassThrough in render mode");
    let mut buf = [SENTINEL_F; 8];
    feedback_buffer(8, GL_3D, &mut buf);
    glPassThrough(3.0);
    glRenderMode(GL_FEEDBACK);
    assert_eq!(glRenderMode(GL_RENDER), 0);
    assert_eq!(buf, [SENTINEL_F; 8]);
}

#[test]
fn render_mode_returns_the_value_count_and_restarts_each_pass() {
    let _ctx = fresh();
    glViewport(0, 0, 100, 100);
    let mut buf = [SENTINEL_F; 16];
    feedback_buffer(16, GL_3D, &mut buf);
    glRenderMode(GL_FEEDBACK);
    center_point();
    glPassThrough(9.0);
    assert_eq!(glRenderMode(GL_RENDER), 6);
    assert_approx_eq!(
        buf[..6].to_vec(),
        [
            GL_POINT_TOKEN as f32,
            50.0,
            50.0,
            0.5,
            GL_PASS_THROUGH_TOKEN as f32,
            9.0
        ],
        1e-6
    );
    assert_eq!(buf[6..], [SENTINEL_F; 10]);

    // a second pass writes from the start again
    let mut buf2 = [SENTINEL_F; 16];
    feedback_buffer(16, GL_2D, &mut buf2);
    glRenderMode(GL_FEEDBACK);
    glPassThrough(1.5);
    // switching to feedback while in feedback ends one pass and starts another
    assert_eq!(glRenderMode(GL_FEEDBACK), 2);
    center_point();
    assert_eq!(glRenderMode(GL_RENDER), 3);
    assert_approx_eq!(
        buf2[..3].to_vec(),
        [GL_POINT_TOKEN as f32, 50.0, 50.0],
        1e-6
    );
    expect_no_error("passes");
}

#[test]
fn an_exact_fit_is_not_an_overflow() {
    let _ctx = fresh();
    glViewport(0, 0, 100, 100);
    let mut buf = [SENTINEL_F; 8];
    feedback_buffer(4, GL_3D, &mut buf);
    glRenderMode(GL_FEEDBACK);
    center_point();
    assert_eq!(glRenderMode(GL_RENDER), 4);
    assert_eq!(buf[4..], [SENTINEL_F; 4]);
}

#[test]
fn overflow_returns_minus_one_and_writes_nothing_past_the_buffer() {
    let _ctx = fresh();
    glViewport(0, 0, 100, 100);
    // pass-through tokens: 3 of the 4 values fit
    let mut buf = [SENTINEL_F; 8];
    feedback_buffer(3, GL_2D, &mut buf);
    glRenderMode(GL_FEEDBACK);
    glPassThrough(1.0);
    glPassThrough(2.0);
    assert_eq!(glRenderMode(GL_RENDER), -1);
    assert_eq!(
        buf[..3],
        [
            GL_PASS_THROUGH_TOKEN as f32,
            1.0,
            GL_PASS_THROUGH_TOKEN as f32
        ]
    );
    assert_eq!(buf[3..], [SENTINEL_F; 5], "wrote past the buffer");

    // vertices: a GL_4D_COLOR_TEXTURE point is 13 values
    let mut buf = [SENTINEL_F; 32];
    feedback_buffer(20, GL_4D_COLOR_TEXTURE, &mut buf);
    glRenderMode(GL_FEEDBACK);
    center_point();
    center_point();
    assert_eq!(glRenderMode(GL_RENDER), -1);
    assert_eq!(buf[0], GL_POINT_TOKEN as f32);
    assert_eq!(buf[13], GL_POINT_TOKEN as f32);
    assert!(buf[..20].iter().all(|&v| v != SENTINEL_F));
    assert_eq!(buf[20..], [SENTINEL_F; 12], "wrote past the buffer");

    // a zero-size buffer overflows on the first value and writes nothing
    let mut empty = [SENTINEL_F; 4];
    feedback_buffer(0, GL_2D, &mut empty);
    expect_no_error("size 0");
    glRenderMode(GL_FEEDBACK);
    glGetError();
    glPassThrough(1.0);
    assert_eq!(glRenderMode(GL_RENDER), -1);
    assert_eq!(empty, [SENTINEL_F; 4]);
}

#[test]
fn through_the_safe_context_api() {
    use fflight::{Context, GlError};
    let mut ctx = Context::new();
    assert_eq!(ctx.render_mode(GL_FEEDBACK), Err(GlError::InvalidOperation));
    assert_eq!(
        ctx.feedback_buffer(-1, GL_2D, 0),
        Err(GlError::InvalidValue)
    );
    assert_eq!(ctx.feedback_buffer(4, GL_2D, 0), Err(GlError::InvalidValue));
    assert_eq!(
        ctx.feedback_buffer(4, 0x1234, 64),
        Err(GlError::InvalidEnum)
    );
    ctx.feedback_buffer(3, GL_2D, 64).unwrap();
    assert_eq!(ctx.render_mode(GL_FEEDBACK).unwrap().0, 0);
    ctx.pass_through(5.0).unwrap();
    ctx.pass_through(6.0).unwrap();
    let (count, finished) = ctx.render_mode(GL_RENDER).unwrap();
    assert_eq!(count, -1);
    let finished = finished.unwrap();
    assert_eq!(finished.address, 64);
    assert_eq!(
        finished.values,
        [
            GL_PASS_THROUGH_TOKEN as f32,
            5.0,
            GL_PASS_THROUGH_TOKEN as f32
        ]
    );
}

/// Points drawn from arrays, some blocks of eight all inside the view volume (laid out in
/// place in the application's buffer) and some not: the values of the safe API's feedback
/// (kept by the library) for every type, nothing written past the count, and overflows cut
/// at every length give the values that fit and -1.
#[test]
fn array_points_in_place_equal_kept_values_and_stop_at_the_count() {
    let _ctx = fresh();
    glViewport(0, 0, 100, 100);
    // 37 points: blocks 0 and 2 all inside, block 1 with one outside, the last block (5
    // points) ending with two outside.
    let mut positions = Vec::new();
    for i in 0..37 {
        let outside = i == 11 || i >= 35;
        let x = if outside { 2.0 } else { -0.9 + 0.05 * i as f32 };
        positions.extend_from_slice(&[x, 0.01 * i as f32, -0.5]);
    }
    for kind in FEEDBACK_TYPES {
        let mut kept = fflight::Context::new();
        kept.viewport(0, 0, 100, 100).unwrap();
        kept.feedback_buffer(1000, kind, 64).unwrap();
        kept.render_mode(GL_FEEDBACK).unwrap();
        kept.begin(GL_POINTS).unwrap();
        for p in positions.chunks(3) {
            kept.vertex(glam::Vec4::new(p[0], p[1], p[2], 1.0));
        }
        kept.end().unwrap();
        let (count, finished) = kept.render_mode(GL_RENDER).unwrap();
        let want = finished.unwrap().values;
        assert_eq!(count as usize, want.len());

        // SAFETY: `positions` outlives the draws below, which read its 37 points.
        unsafe {
            glVertexPointer(3, GL_FLOAT, 0, positions.as_ptr().cast());
            glEnableClientState(GL_VERTEX_ARRAY);
        }
        // Room for whole blocks past the count, and every shorter size.
        let room = want.len() + 8 * 13 + 1;
        for size in std::iter::once(room).chain((0..=want.len() + 1).rev()) {
            let mut buf = vec![SENTINEL_F; room + 16];
            feedback_buffer(size as i32, kind, &mut buf);
            glRenderMode(GL_FEEDBACK);
            // SAFETY: the array holds the 37 points drawn.
            unsafe { glDrawArrays(GL_POINTS, 0, 37) };
            let got = glRenderMode(GL_RENDER);
            let fits = size.min(want.len());
            let expected = if size >= want.len() {
                want.len() as i32
            } else {
                -1
            };
            assert_eq!(got, expected, "type {kind:#x}, size {size}");
            assert_eq!(buf[..fits], want[..fits], "type {kind:#x}, size {size}");
            assert!(
                buf[fits..].iter().all(|&v| v == SENTINEL_F),
                "type {kind:#x}, size {size}: written past the count"
            );
        }
        // SAFETY: a valid enum; no array is read.
        unsafe { glDisableClientState(GL_VERTEX_ARRAY) };
    }
    expect_no_error("array points");
}
