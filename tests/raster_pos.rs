//! The current raster position (§2.13): glRasterPos{2,3,4}{s,i,f,d}[v], the initial state,
//! the queries, validity after clipping (view volume and user planes), errors, and the lit
//! color: the same as the color the same vertex gets in feedback.

#[macro_use]
mod common;

use common::*;

unsafe extern "C" {
    safe fn glRasterPos2s(x: GLshort, y: GLshort);
    safe fn glRasterPos2i(x: GLint, y: GLint);
    safe fn glRasterPos2f(x: GLfloat, y: GLfloat);
    safe fn glRasterPos2d(x: GLdouble, y: GLdouble);
    safe fn glRasterPos3s(x: GLshort, y: GLshort, z: GLshort);
    safe fn glRasterPos3i(x: GLint, y: GLint, z: GLint);
    safe fn glRasterPos3f(x: GLfloat, y: GLfloat, z: GLfloat);
    safe fn glRasterPos3d(x: GLdouble, y: GLdouble, z: GLdouble);
    safe fn glRasterPos4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort);
    safe fn glRasterPos4i(x: GLint, y: GLint, z: GLint, w: GLint);
    safe fn glRasterPos4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat);
    safe fn glRasterPos4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble);
    fn glRasterPos2sv(v: *const GLshort);
    fn glRasterPos2iv(v: *const GLint);
    fn glRasterPos2fv(v: *const GLfloat);
    fn glRasterPos2dv(v: *const GLdouble);
    fn glRasterPos3sv(v: *const GLshort);
    fn glRasterPos3iv(v: *const GLint);
    fn glRasterPos3fv(v: *const GLfloat);
    fn glRasterPos3dv(v: *const GLdouble);
    fn glRasterPos4sv(v: *const GLshort);
    fn glRasterPos4iv(v: *const GLint);
    fn glRasterPos4fv(v: *const GLfloat);
    fn glRasterPos4dv(v: *const GLdouble);
    fn glClipPlane(plane: GLenum, equation: *const GLdouble);
    fn glSelectBuffer(size: GLsizei, buffer: *mut GLuint);
    safe fn glInitNames();
    safe fn glPushName(name: GLuint);
}

fn position() -> Vec<f32> {
    get_floats(GL_CURRENT_RASTER_POSITION, 4)
}

fn valid() -> bool {
    get_bools(GL_CURRENT_RASTER_POSITION_VALID, 1)[0] == GL_TRUE
}

/// A 100x100 viewport and an orthographic volume [-10, 10]^3: window x = 50 + 5 x.
fn ortho_view() {
    glViewport(0, 0, 100, 100);
    glMatrixMode(GL_PROJECTION);
    glOrtho(-10.0, 10.0, -10.0, 10.0, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
}

#[test]
fn initial_state() {
    let _context = fresh();
    assert_eq!(position(), [0.0, 0.0, 0.0, 1.0]);
    assert!(valid());
    assert_eq!(get_floats(GL_CURRENT_RASTER_COLOR, 4), [1.0; 4]);
    assert_eq!(get_ints(GL_CURRENT_RASTER_COLOR, 4), [i32::MAX; 4]);
    assert_eq!(
        get_floats(GL_CURRENT_RASTER_SECONDARY_COLOR, 4),
        [0.0, 0.0, 0.0, 1.0]
    );
    assert_eq!(
        get_floats(GL_CURRENT_RASTER_TEXTURE_COORDS, 4),
        [0.0, 0.0, 0.0, 1.0]
    );
    assert_eq!(get_floats(GL_CURRENT_RASTER_DISTANCE, 1), [0.0]);
    expect_no_error("initial queries");
}

#[test]
fn every_entry_point_form() {
    let _context = fresh();
    ortho_view();
    // Each form sets (x, y, z, w) = (1, 2, 3, 4) as far as it has components; the ortho
    // projection keeps w, so window x = 50 + 5 x / w and y = 50 + 5 y / w.
    let check = |name: &str, size: usize| {
        let (x, y, z, w) = (
            1.0,
            2.0,
            if size > 2 { 3.0 } else { 0.0 },
            if size > 3 { 4.0 } else { 1.0 },
        );
        let want = [
            50.0 + 5.0 * x / w,
            50.0 + 5.0 * y / w,
            0.5 - 0.5 * z / 10.0 / w,
            w,
        ];
        assert_approx_eq!(position(), want, 1e-5, "{name}");
        assert!(valid(), "{name}");
        expect_no_error(name);
        glRasterPos2f(0.0, 0.0);
    };
    glRasterPos2s(1, 2);
    check("glRasterPos2s", 2);
    glRasterPos2i(1, 2);
    check("glRasterPos2i", 2);
    glRasterPos2f(1.0, 2.0);
    check("glRasterPos2f", 2);
    glRasterPos2d(1.0, 2.0);
    check("glRasterPos2d", 2);
    glRasterPos3s(1, 2, 3);
    check("glRasterPos3s", 3);
    glRasterPos3i(1, 2, 3);
    check("glRasterPos3i", 3);
    glRasterPos3f(1.0, 2.0, 3.0);
    check("glRasterPos3f", 3);
    glRasterPos3d(1.0, 2.0, 3.0);
    check("glRasterPos3d", 3);
    glRasterPos4s(1, 2, 3, 4);
    check("glRasterPos4s", 4);
    glRasterPos4i(1, 2, 3, 4);
    check("glRasterPos4i", 4);
    glRasterPos4f(1.0, 2.0, 3.0, 4.0);
    check("glRasterPos4f", 4);
    glRasterPos4d(1.0, 2.0, 3.0, 4.0);
    check("glRasterPos4d", 4);
    let (s, i, f, d) = (
        [1i16, 2, 3, 4],
        [1i32, 2, 3, 4],
        [1.0f32, 2.0, 3.0, 4.0],
        [1.0f64, 2.0, 3.0, 4.0],
    );
    // SAFETY: each array has four readable values, the most any form reads.
    unsafe {
        glRasterPos2sv(s.as_ptr());
        check("glRasterPos2sv", 2);
        glRasterPos2iv(i.as_ptr());
        check("glRasterPos2iv", 2);
        glRasterPos2fv(f.as_ptr());
        check("glRasterPos2fv", 2);
        glRasterPos2dv(d.as_ptr());
        check("glRasterPos2dv", 2);
        glRasterPos3sv(s.as_ptr());
        check("glRasterPos3sv", 3);
        glRasterPos3iv(i.as_ptr());
        check("glRasterPos3iv", 3);
        glRasterPos3fv(f.as_ptr());
        check("glRasterPos3fv", 3);
        glRasterPos3dv(d.as_ptr());
        check("glRasterPos3dv", 3);
        glRasterPos4sv(s.as_ptr());
        check("glRasterPos4sv", 4);
        glRasterPos4iv(i.as_ptr());
        check("glRasterPos4iv", 4);
        glRasterPos4fv(f.as_ptr());
        check("glRasterPos4fv", 4);
        glRasterPos4dv(d.as_ptr());
        check("glRasterPos4dv", 4);
    }
}

#[test]
fn errors() {
    let _context = fresh();
    ortho_view();
    glRasterPos2f(1.0, 1.0);
    let before = position();
    glBegin(GL_POINTS);
    glRasterPos2f(5.0, 5.0);
    glEnd();
    expect_error(
        GL_INVALID_OPERATION,
        "glRasterPos between glBegin and glEnd",
    );
    assert_eq!(position(), before);
    // SAFETY: NULL is checked before anything is read.
    unsafe { glRasterPos3fv(std::ptr::null()) };
    expect_error(GL_INVALID_VALUE, "glRasterPos3fv(NULL)");
    assert_eq!(position(), before);
}

#[test]
fn culled_positions_are_invalid_and_keep_the_rest() {
    let _context = fresh();
    ortho_view();
    glColor4f(0.25, 0.5, 0.75, 1.0);
    glTexCoord4f(0.5, 0.25, 0.0, 1.0);
    glRasterPos3f(2.0, -3.0, 4.0);
    assert!(valid());
    let kept = (
        position(),
        get_floats(GL_CURRENT_RASTER_COLOR, 4),
        get_floats(GL_CURRENT_RASTER_TEXTURE_COORDS, 4),
        get_floats(GL_CURRENT_RASTER_DISTANCE, 1),
    );
    assert_approx_eq!(kept.3, [29.0f32.sqrt()], 1e-6);
    glColor4f(1.0, 0.0, 0.0, 1.0);
    glTexCoord4f(0.0, 1.0, 0.0, 1.0);
    for (x, y, z) in [(11.0, 0.0, 0.0), (0.0, -10.5, 0.0), (0.0, 0.0, 12.0)] {
        glRasterPos3f(x, y, z);
        assert!(!valid(), "({x}, {y}, {z}) is outside the view volume");
        let now = (
            position(),
            get_floats(GL_CURRENT_RASTER_COLOR, 4),
            get_floats(GL_CURRENT_RASTER_TEXTURE_COORDS, 4),
            get_floats(GL_CURRENT_RASTER_DISTANCE, 1),
        );
        assert_eq!(now, kept);
    }
    // On the view volume's boundary the point is inside.
    glRasterPos3f(10.0, -10.0, 10.0);
    assert!(valid());

    // A user clip plane: y <= 1.
    // SAFETY: four readable values.
    unsafe { glClipPlane(GL_CLIP_PLANE0, [0.0, -1.0, 0.0, 1.0].as_ptr()) };
    glRasterPos2f(0.0, 2.0);
    assert!(valid(), "disabled planes do not clip");
    glEnable(GL_CLIP_PLANE0);
    glRasterPos2f(0.0, 2.0);
    assert!(!valid());
    glRasterPos2f(0.0, 0.5);
    assert!(valid());
    assert_approx_eq!(
        get_floats(GL_CURRENT_RASTER_COLOR, 4),
        [1.0f32, 0.0, 0.0, 1.0]
    );
    expect_no_error("clipping");
}

#[test]
fn texture_matrix_and_distance() {
    let _context = fresh();
    ortho_view();
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.25, -0.5, 0.0);
    glScalef(2.0, 4.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0, 0.0, -3.0);
    glTexCoord4f(0.5, 0.25, 0.0, 1.0);
    glRasterPos3f(0.0, 4.0, 0.0);
    assert_approx_eq!(
        get_floats(GL_CURRENT_RASTER_TEXTURE_COORDS, 4),
        [1.25f32, 0.5, 0.0, 1.0]
    );
    assert_approx_eq!(get_floats(GL_CURRENT_RASTER_DISTANCE, 1), [5.0f32]);
}

/// The raster color is the front primary color the same vertex gets in feedback, under
/// lighting with two sides, a spot, a local viewer and color material; integer queries map
/// it linearly.
#[test]
fn lit_color_equals_feedback_color() {
    let _context = fresh();
    ortho_view();
    glRotatef(20.0, 1.0, 1.0, 0.0);
    glTranslatef(0.5, -1.0, -2.0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    light_fv(GL_LIGHT0, GL_POSITION, &[1.0, 2.0, 3.0, 1.0]);
    light_fv(GL_LIGHT0, GL_SPECULAR, &[0.8, 0.7, 0.6, 1.0]);
    light_fv(GL_LIGHT1, GL_POSITION, &[-1.0, 1.0, 2.0, 0.0]);
    light_fv(GL_LIGHT1, GL_DIFFUSE, &[0.3, 0.6, 0.9, 1.0]);
    light_fv(GL_LIGHT1, GL_SPOT_DIRECTION, &[1.0, -1.0, -2.0]);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.3);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glMaterialf(GL_FRONT, GL_SHININESS, 12.0);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    let points = [[0.5f32, 0.5, 0.0], [-2.0, 1.0, 3.0], [3.0, -2.0, -1.0]];
    for (k, p) in points.iter().enumerate() {
        let k = k as f32;
        glColor4f(0.9, 0.3 + 0.2 * k, 0.4, 0.8);
        glNormal3f(0.2 * k - 0.3, 0.5, 0.7);
        // SAFETY: three readable values.
        unsafe { glRasterPos3fv(p.as_ptr()) };
        let raster = get_floats(GL_CURRENT_RASTER_COLOR, 4);
        let mut buffer = [0.0f32; 8];
        // SAFETY: `buffer` outlives feedback mode, which ends below.
        unsafe { glFeedbackBuffer(8, GL_3D_COLOR, buffer.as_mut_ptr()) };
        glRenderMode(GL_FEEDBACK);
        glBegin(GL_POINTS);
        // SAFETY: three readable values.
        unsafe { glVertex3fv(p.as_ptr()) };
        glEnd();
        assert_eq!(glRenderMode(GL_RENDER), 8);
        assert_eq!(raster, buffer[4..8], "point {k}: raster vs feedback color");
        assert_ne!(raster, [1.0; 4], "point {k} is lit");
        let ints = get_ints(GL_CURRENT_RASTER_COLOR, 4);
        for (i, c) in ints.iter().zip(&raster) {
            assert!(
                (*i as f64 - *c as f64 * i32::MAX as f64).abs() <= 1.0,
                "{ints:?} vs {raster:?}"
            );
        }
        assert_eq!(
            position()[..3],
            buffer[1..4],
            "point {k}: window coordinates"
        );
    }
    expect_no_error("lit raster positions");
}

/// Feedback gets no token from glRasterPos; selection gets a hit.
#[test]
fn feedback_and_selection() {
    let _context = fresh();
    ortho_view();
    let mut buffer = [0.0f32; 8];
    // SAFETY: `buffer` outlives feedback mode, which ends below.
    unsafe { glFeedbackBuffer(8, GL_3D, buffer.as_mut_ptr()) };
    glRenderMode(GL_FEEDBACK);
    glRasterPos2f(1.0, 1.0);
    glPassThrough(3.0);
    assert_eq!(glRenderMode(GL_RENDER), 2);
    assert_eq!(buffer[..2], [GL_PASS_THROUGH_TOKEN as f32, 3.0]);
    assert!(valid());

    let mut hits = [0u32; 8];
    // SAFETY: `hits` outlives selection mode, which ends below.
    unsafe { glSelectBuffer(8, hits.as_mut_ptr()) };
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(7);
    glRasterPos3f(20.0, 0.0, 0.0);
    assert_eq!(glRenderMode(GL_RENDER), 0, "a culled position is no hit");
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(7);
    glRasterPos3f(0.0, 0.0, 0.0);
    assert_eq!(glRenderMode(GL_RENDER), 1);
    assert_eq!(hits[0], 1);
    assert_eq!(hits[3], 7);
    expect_no_error("feedback and selection");
}
