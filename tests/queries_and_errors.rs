//! glGetError (§2.5), glGet{Boolean,Integer,Float,Double}v and their conversions (§6.1.2),
//! glGetString (§6.1.11), glEnable/glDisable/glIsEnabled, glViewport and glDepthRange
//! (§2.11.1), and the commands the spec forbids between glBegin and glEnd (§2.6.3).

#[macro_use]
mod common;

use std::cell::RefCell;

use common::*;

const LIGHTING_CAPS: [GLenum; 12] = [
    GL_LIGHTING,
    GL_LIGHT0,
    GL_LIGHT1,
    GL_LIGHT2,
    GL_LIGHT3,
    GL_LIGHT4,
    GL_LIGHT5,
    GL_LIGHT6,
    GL_LIGHT7,
    GL_NORMALIZE,
    GL_RESCALE_NORMAL,
    GL_COLOR_MATERIAL,
];

fn enabled(cap: GLenum) -> bool {
    let is = glIsEnabled(cap);
    assert!(is == GL_TRUE || is == GL_FALSE, "glIsEnabled returned {is}");
    is == GL_TRUE
}

fn enables() -> Vec<bool> {
    LIGHTING_CAPS.iter().map(|&cap| enabled(cap)).collect()
}

// ---- glGetError ----

#[test]
fn a_fresh_context_has_no_error() {
    let _ctx = fresh();
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(glGetError(), GL_NO_ERROR);
}

#[test]
fn the_first_error_is_kept_until_read_then_cleared() {
    let _ctx = fresh();
    glEnable(0x1234); // GL_INVALID_ENUM
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 100.0); // GL_INVALID_VALUE
    glPopMatrix(); // GL_STACK_UNDERFLOW
    glEnd(); // GL_INVALID_OPERATION
    assert_eq!(error_name(glGetError()), "GL_INVALID_ENUM");
    assert_eq!(error_name(glGetError()), "GL_NO_ERROR");
    // a later error is recorded again once the flag is clear
    glPopMatrix();
    glEnable(0x1234);
    assert_eq!(error_name(glGetError()), "GL_STACK_UNDERFLOW");
    assert_eq!(error_name(glGetError()), "GL_NO_ERROR");
    // valid commands do not clear the flag
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, -5.0);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 5.0);
    glEnable(GL_LIGHTING);
    assert_eq!(error_name(glGetError()), "GL_INVALID_VALUE");
    assert_eq!(get_light(GL_LIGHT0, GL_SPOT_CUTOFF, 1), [5.0]);
}

#[test]
fn get_error_between_begin_and_end_is_invalid_operation() {
    // §2.6.3: GetError is not among the commands allowed between Begin and End; the man page
    // and Mesa: it returns 0 there and records GL_INVALID_OPERATION.
    let _ctx = fresh();
    glBegin(GL_POINTS);
    let inside = glGetError();
    glEnd();
    assert_eq!(
        error_name(inside),
        "GL_NO_ERROR",
        "glGetError inside glBegin/glEnd"
    );
    expect_error(
        GL_INVALID_OPERATION,
        "after glGetError inside glBegin/glEnd",
    );

    // an error recorded before glBegin is neither returned nor cleared inside
    glEnable(0x1234);
    glBegin(GL_POINTS);
    let inside = glGetError();
    glEnd();
    assert_eq!(error_name(inside), "GL_NO_ERROR");
    expect_error(GL_INVALID_ENUM, "the error from before glBegin");
}

// ---- glGet*v ----

#[test]
fn every_get_converts_per_6_1_2() {
    let _ctx = fresh();
    // an integer
    assert_eq!(get_bools(GL_MAX_LIGHTS, 1), [GL_TRUE]);
    assert_eq!(get_ints(GL_MAX_LIGHTS, 1), [8]);
    assert_eq!(get_floats(GL_MAX_LIGHTS, 1), [8.0]);
    assert_eq!(get_doubles(GL_MAX_LIGHTS, 1), [8.0]);
    // an enum
    assert_eq!(get_ints(GL_MATRIX_MODE, 1), [GL_MODELVIEW as i32]);
    assert_eq!(get_floats(GL_MATRIX_MODE, 1), [GL_MODELVIEW as f32]);
    assert_eq!(get_doubles(GL_MATRIX_MODE, 1), [GL_MODELVIEW as f64]);
    assert_eq!(get_bools(GL_MATRIX_MODE, 1), [GL_TRUE]);
    // a boolean
    glEnable(GL_LIGHT3);
    assert_eq!(get_bools(GL_LIGHT3, 1), [GL_TRUE]);
    assert_eq!(get_ints(GL_LIGHT3, 1), [1]);
    assert_eq!(get_floats(GL_LIGHT3, 1), [1.0]);
    assert_eq!(get_doubles(GL_LIGHT3, 1), [1.0]);
    assert_eq!(get_ints(GL_LIGHT4, 1), [0]);
    // a float that is not a color: rounded for integers, nonzero for booleans
    glLoadIdentity();
    glTranslatef(0.4, -2.6, 0.0);
    let m = get_ints(GL_MODELVIEW_MATRIX, 16);
    assert_eq!(m[12..], [0, -3, 0, 1]);
    assert_eq!(
        get_bools(GL_MODELVIEW_MATRIX, 16)[12..],
        [GL_TRUE, GL_TRUE, GL_FALSE, GL_TRUE]
    );
    // the color-material enums
    assert_eq!(
        get_ints(GL_COLOR_MATERIAL_FACE, 1),
        [GL_FRONT_AND_BACK as i32]
    );
    assert_eq!(
        get_floats(GL_COLOR_MATERIAL_PARAMETER, 1),
        [GL_AMBIENT_AND_DIFFUSE as f32]
    );
    assert_eq!(get_ints(GL_MAX_VIEWPORT_DIMS, 2).len(), 2);
    assert!(get_ints(GL_MAX_VIEWPORT_DIMS, 2).iter().all(|&d| d > 0));
    expect_no_error("conversions");
}

/// §6.1.2's integer mapping of colors, normals and depth range values.
fn linear_int(v: f64) -> i32 {
    ((INT_RANGE * v - 1.0) / 2.0 + 0.5)
        .floor()
        .clamp(i32::MIN as f64, i32::MAX as f64) as i32
}

#[test]
fn the_four_gets_agree_on_every_pname() {
    let _ctx = fresh();
    // state away from the defaults, avoiding the .5 ties of rounding
    glNormal3f(0.3, -0.6, 2.2);
    glColor4f(0.1, 0.7, -0.2, 1.3);
    glTexCoord4f(1.4, -2.7, 3.1, 0.9);
    light_model_fv(GL_LIGHT_MODEL_AMBIENT, &[0.05, 0.6, 0.35, 0.9]);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glLightModeli(
        GL_LIGHT_MODEL_COLOR_CONTROL,
        GL_SEPARATE_SPECULAR_COLOR as i32,
    );
    glColorMaterial(GL_BACK, GL_SPECULAR);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 7.0);
    glMatrixMode(GL_TEXTURE);
    glScalef(3.3, 0.2, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glRotatef(33.0, 1.0, 2.0, 3.0);
    glTranslatef(4.2, -1.1, 0.0);
    glViewport(3, 4, 500, 600);
    glDepthRange(0.2, 0.9);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT6);
    glEnable(GL_RESCALE_NORMAL);
    expect_no_error("setup");

    // (pname, value count, whether integers map linearly)
    let table: [(GLenum, usize, bool); 28] = [
        (GL_MAX_LIGHTS, 1, false),
        (GL_CURRENT_NORMAL, 3, true),
        (GL_CURRENT_COLOR, 4, true),
        (GL_CURRENT_TEXTURE_COORDS, 4, false),
        (GL_LIGHT_MODEL_AMBIENT, 4, true),
        (GL_LIGHT_MODEL_LOCAL_VIEWER, 1, false),
        (GL_LIGHT_MODEL_TWO_SIDE, 1, false),
        (GL_LIGHT_MODEL_COLOR_CONTROL, 1, false),
        (GL_COLOR_MATERIAL_FACE, 1, false),
        (GL_COLOR_MATERIAL_PARAMETER, 1, false),
        (GL_MATRIX_MODE, 1, false),
        (GL_MODELVIEW_MATRIX, 16, false),
        (GL_PROJECTION_MATRIX, 16, false),
        (GL_TEXTURE_MATRIX, 16, false),
        (GL_TRANSPOSE_MODELVIEW_MATRIX, 16, false),
        (GL_TRANSPOSE_PROJECTION_MATRIX, 16, false),
        (GL_TRANSPOSE_TEXTURE_MATRIX, 16, false),
        (GL_MODELVIEW_STACK_DEPTH, 1, false),
        (GL_PROJECTION_STACK_DEPTH, 1, false),
        (GL_TEXTURE_STACK_DEPTH, 1, false),
        (GL_MAX_MODELVIEW_STACK_DEPTH, 1, false),
        (GL_MAX_PROJECTION_STACK_DEPTH, 1, false),
        (GL_MAX_TEXTURE_STACK_DEPTH, 1, false),
        (GL_VIEWPORT, 4, false),
        (GL_DEPTH_RANGE, 2, true),
        (GL_LIGHTING, 1, false),
        (GL_LIGHT6, 1, false),
        (GL_RESCALE_NORMAL, 1, false),
    ];
    for (pname, n, linear) in table {
        let d = get_doubles(pname, n);
        let f = get_floats(pname, n);
        let i = get_ints(pname, n);
        let b = get_bools(pname, n);
        let want_f: Vec<f32> = d.iter().map(|&v| v as f32).collect();
        let want_i: Vec<i32> = d
            .iter()
            .map(|&v| {
                if linear {
                    linear_int(v)
                } else {
                    v.round() as i32
                }
            })
            .collect();
        let want_b: Vec<GLboolean> = d.iter().map(|&v| (v != 0.0) as GLboolean).collect();
        assert_eq!(f, want_f, "glGetFloatv({pname:#x}) vs glGetDoublev");
        assert_eq!(i, want_i, "glGetIntegerv({pname:#x}) vs glGetDoublev");
        assert_eq!(b, want_b, "glGetBooleanv({pname:#x}) vs glGetDoublev");
    }
    // spot checks of the values themselves
    assert_eq!(get_floats(GL_CURRENT_NORMAL, 3), [0.3, -0.6, 2.2]);
    assert_eq!(
        get_floats(GL_CURRENT_TEXTURE_COORDS, 4),
        [1.4, -2.7, 3.1, 0.9]
    );
    assert_eq!(get_ints(GL_CURRENT_TEXTURE_COORDS, 4), [1, -3, 3, 1]);
    assert_eq!(get_int(GL_COLOR_MATERIAL_FACE), GL_BACK as i32);
    assert_eq!(get_int(GL_PROJECTION_STACK_DEPTH), 2);
    assert_eq!(get_ints(GL_VIEWPORT, 4), [3, 4, 500, 600]);
    assert_approx_eq!(get_doubles(GL_DEPTH_RANGE, 2), [0.2, 0.9f64]);
    expect_no_error("the four gets");
}

#[test]
fn bad_pnames_are_invalid_enum_and_write_nothing() {
    let _ctx = fresh();
    for bad in [0, 0x1234, GL_AMBIENT, GL_SPOT_CUTOFF, GL_FRONT, 0xFFFF_FFFF] {
        let mut b = [SENTINEL_B; 16];
        let mut i = [SENTINEL_I; 16];
        let mut f = [SENTINEL_F; 16];
        let mut d = [SENTINEL_D; 16];
        // SAFETY: room for 16 values, more than any pname defines.
        unsafe {
            glGetBooleanv(bad, b.as_mut_ptr());
            expect_error(GL_INVALID_ENUM, &format!("glGetBooleanv({bad:#x})"));
            glGetIntegerv(bad, i.as_mut_ptr());
            expect_error(GL_INVALID_ENUM, &format!("glGetIntegerv({bad:#x})"));
            glGetFloatv(bad, f.as_mut_ptr());
            expect_error(GL_INVALID_ENUM, &format!("glGetFloatv({bad:#x})"));
            glGetDoublev(bad, d.as_mut_ptr());
            expect_error(GL_INVALID_ENUM, &format!("glGetDoublev({bad:#x})"));
        }
        assert_eq!(b, [SENTINEL_B; 16]);
        assert_eq!(i, [SENTINEL_I; 16]);
        assert_eq!(f, [SENTINEL_F; 16]);
        assert_eq!(d, [SENTINEL_D; 16]);
    }
}

#[test]
fn null_get_pointers_are_invalid_value_after_the_pname_check() {
    let _ctx = fresh();
    for pname in [
        GL_MAX_LIGHTS,
        GL_MODELVIEW_MATRIX,
        GL_CURRENT_COLOR,
        GL_LIGHTING,
    ] {
        // SAFETY: NULL is allowed and must be reported, never written.
        unsafe {
            glGetBooleanv(pname, std::ptr::null_mut());
            expect_error(GL_INVALID_VALUE, "glGetBooleanv(NULL)");
            glGetIntegerv(pname, std::ptr::null_mut());
            expect_error(GL_INVALID_VALUE, "glGetIntegerv(NULL)");
            glGetFloatv(pname, std::ptr::null_mut());
            expect_error(GL_INVALID_VALUE, "glGetFloatv(NULL)");
            glGetDoublev(pname, std::ptr::null_mut());
            expect_error(GL_INVALID_VALUE, "glGetDoublev(NULL)");
        }
    }
    // SAFETY: as above.
    unsafe { glGetFloatv(0x1234, std::ptr::null_mut()) };
    expect_error(GL_INVALID_ENUM, "bad pname + NULL");
}

// ---- glEnable / glDisable / glIsEnabled ----

#[test]
fn lighting_capabilities_start_disabled_and_toggle_one_at_a_time() {
    let _ctx = fresh();
    assert_eq!(enables(), [false; 12]);
    for (i, &cap) in LIGHTING_CAPS.iter().enumerate() {
        glEnable(cap);
        expect_no_error(&format!("glEnable({cap:#x})"));
        let want: Vec<bool> = (0..12).map(|j| j == i).collect();
        assert_eq!(enables(), want, "after glEnable({cap:#x})");
        assert_eq!(get_bools(cap, 1), [GL_TRUE]);
        glEnable(cap); // enabling twice is fine
        glDisable(cap);
        expect_no_error(&format!("glDisable({cap:#x})"));
        assert_eq!(enables(), [false; 12], "after glDisable({cap:#x})");
        assert_eq!(get_bools(cap, 1), [GL_FALSE]);
    }
    for &cap in &LIGHTING_CAPS {
        glEnable(cap);
    }
    assert_eq!(enables(), [true; 12]);
    expect_no_error("all enabled");
}

#[test]
fn bad_capabilities_are_invalid_enum_and_change_nothing() {
    let _ctx = fresh();
    glEnable(GL_LIGHT2);
    glEnable(GL_NORMALIZE);
    let before = enables();
    for bad in [
        GL_LIGHT0 + 8,
        GL_LIGHT0 - 1,
        GL_AMBIENT,
        GL_MODELVIEW,
        GL_COLOR_MATERIAL_FACE,
        0,
        0x1234,
    ] {
        glEnable(bad);
        expect_error(GL_INVALID_ENUM, &format!("glEnable({bad:#x})"));
        glDisable(bad);
        expect_error(GL_INVALID_ENUM, &format!("glDisable({bad:#x})"));
        assert_eq!(glIsEnabled(bad), GL_FALSE);
        expect_error(GL_INVALID_ENUM, &format!("glIsEnabled({bad:#x})"));
    }
    assert_eq!(enables(), before);
}

// ---- glViewport, glDepthRange ----

#[test]
fn viewport_round_trips_clamps_and_rejects_negative_sizes() {
    let _ctx = fresh();
    glViewport(10, -20, 300, 200);
    assert_eq!(get_ints(GL_VIEWPORT, 4), [10, -20, 300, 200]);
    assert_eq!(get_floats(GL_VIEWPORT, 4), [10.0, -20.0, 300.0, 200.0]);
    let max = get_ints(GL_MAX_VIEWPORT_DIMS, 2);
    glViewport(0, 0, i32::MAX, i32::MAX);
    assert_eq!(get_ints(GL_VIEWPORT, 4), [0, 0, max[0], max[1]]);
    glViewport(1, 2, 3, 4);
    for (w, h) in [(-1, 10), (10, -1), (-5, -5)] {
        glViewport(7, 7, w, h);
        expect_error(GL_INVALID_VALUE, &format!("glViewport size {w}x{h}"));
    }
    assert_eq!(get_ints(GL_VIEWPORT, 4), [1, 2, 3, 4]);
    glViewport(0, 0, 0, 0);
    expect_no_error("zero-size viewport");
}

#[test]
fn depth_range_round_trips_clamped_to_0_1() {
    let _ctx = fresh();
    assert_eq!(get_doubles(GL_DEPTH_RANGE, 2), [0.0, 1.0]);
    assert_eq!(get_ints(GL_DEPTH_RANGE, 2), [0, i32::MAX]);
    glDepthRange(0.25, 0.75);
    assert_eq!(get_doubles(GL_DEPTH_RANGE, 2), [0.25, 0.75]);
    assert_eq!(get_floats(GL_DEPTH_RANGE, 2), [0.25, 0.75]);
    // integer queries map depth range values linearly, like colors
    assert_eq!(get_ints(GL_DEPTH_RANGE, 2), [536_870_911, 1_610_612_735]);
    glDepthRange(-1.0, 2.0);
    assert_eq!(get_doubles(GL_DEPTH_RANGE, 2), [0.0, 1.0]);
    glDepthRange(1.0, 0.0); // reversed is allowed
    assert_eq!(get_doubles(GL_DEPTH_RANGE, 2), [1.0, 0.0]);
    assert_eq!(get_ints(GL_DEPTH_RANGE, 2)[0], i32::MAX);
    expect_no_error("depth range");
}

// ---- glGetString ----

#[test]
fn get_string_names_a_1_5_implementation() {
    let _ctx = fresh();
    let version = get_string(GL_VERSION).expect("GL_VERSION");
    assert!(version.starts_with("1.5"), "GL_VERSION {version:?}");
    assert!(!get_string(GL_VENDOR).expect("GL_VENDOR").is_empty());
    assert!(!get_string(GL_RENDERER).expect("GL_RENDERER").is_empty());
    assert!(get_string(GL_EXTENSIONS).is_some());
    // the same pointer every time: the strings live as long as the library
    assert_eq!(glGetString(GL_VERSION), glGetString(GL_VERSION));
    expect_no_error("glGetString");
    for bad in [0, GL_LIGHTING, 0x1234] {
        assert!(glGetString(bad).is_null());
        expect_error(GL_INVALID_ENUM, &format!("glGetString({bad:#x})"));
    }
}

// ---- glBegin / glEnd ----

#[test]
fn begin_and_end_errors() {
    let _ctx = fresh();
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glEnd without glBegin");
    for bad in [GL_POLYGON + 1, 0x1234, GL_LIGHTING] {
        glBegin(bad);
        expect_error(GL_INVALID_ENUM, &format!("glBegin({bad:#x})"));
        // the bad glBegin did not start a primitive
        glEnd();
        expect_error(GL_INVALID_OPERATION, "glEnd after a bad glBegin");
    }
    for mode in [
        GL_POINTS,
        GL_LINES,
        GL_LINE_LOOP,
        GL_LINE_STRIP,
        GL_TRIANGLES,
        GL_TRIANGLE_STRIP,
        GL_TRIANGLE_FAN,
        GL_QUADS,
        GL_QUAD_STRIP,
        GL_POLYGON,
    ] {
        glBegin(mode);
        glEnd();
        expect_no_error(&format!("glBegin({mode:#x})"));
    }
    glBegin(GL_POINTS);
    glBegin(GL_POINTS);
    glEnd();
    expect_error(GL_INVALID_OPERATION, "nested glBegin");
    // the first glEnd ended the one primitive
    glEnd();
    expect_error(GL_INVALID_OPERATION, "a second glEnd");
}

#[test]
fn nested_begin_with_a_bad_mode_is_invalid_operation_as_in_mesa() {
    let _ctx = fresh();
    glBegin(GL_POINTS);
    glBegin(0x1234);
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glBegin(bad) inside glBegin/glEnd");
}

type Command<'a> = Box<dyn Fn() + 'a>;

/// Where the queries below would write, if they wrongly wrote.
struct Sinks {
    b: RefCell<[GLboolean; 16]>,
    i: RefCell<[i32; 16]>,
    f: RefCell<[f32; 16]>,
    d: RefCell<[f64; 16]>,
}

impl Sinks {
    fn new() -> Sinks {
        Sinks {
            b: RefCell::new([SENTINEL_B; 16]),
            i: RefCell::new([SENTINEL_I; 16]),
            f: RefCell::new([SENTINEL_F; 16]),
            d: RefCell::new([SENTINEL_D; 16]),
        }
    }

    fn untouched(&self) -> bool {
        *self.b.borrow() == [SENTINEL_B; 16]
            && *self.i.borrow() == [SENTINEL_I; 16]
            && *self.f.borrow() == [SENTINEL_F; 16]
            && *self.d.borrow() == [SENTINEL_D; 16]
    }
}

/// One call of every command that §2.6.3 does not allow between glBegin and glEnd, except the
/// matrix, light and material queries covered in their own files.
fn forbidden_commands<'a>(
    fb: &'a RefCell<[f32; 8]>,
    sinks: &'a Sinks,
) -> Vec<(&'static str, Command<'a>)> {
    vec![
        ("glEnable", Box::new(|| glEnable(GL_LIGHTING))),
        ("glDisable", Box::new(|| glDisable(GL_LIGHT0))),
        (
            "glIsEnabled",
            Box::new(|| assert_eq!(glIsEnabled(GL_LIGHTING), GL_FALSE)),
        ),
        (
            "glLightModelf",
            Box::new(|| glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1.0)),
        ),
        (
            "glLightModeli",
            Box::new(|| glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1)),
        ),
        (
            "glLightModelfv",
            Box::new(|| light_model_fv(GL_LIGHT_MODEL_AMBIENT, &[1.0; 4])),
        ),
        (
            "glLightModeliv",
            Box::new(|| light_model_iv(GL_LIGHT_MODEL_AMBIENT, &[0; 4])),
        ),
        (
            "glColorMaterial",
            Box::new(|| glColorMaterial(GL_FRONT, GL_EMISSION)),
        ),
        ("glViewport", Box::new(|| glViewport(1, 2, 3, 4))),
        ("glDepthRange", Box::new(|| glDepthRange(0.5, 0.6))),
        (
            "glFeedbackBuffer",
            // SAFETY: the buffer outlives the call and any feedback it could start.
            Box::new(|| unsafe { glFeedbackBuffer(8, GL_2D, fb.borrow_mut().as_mut_ptr()) }),
        ),
        (
            "glRenderMode",
            Box::new(|| assert_eq!(glRenderMode(GL_RENDER), 0)),
        ),
        ("glPassThrough", Box::new(|| glPassThrough(1.0))),
        (
            "glGetBooleanv",
            // SAFETY: room for 16 values.
            Box::new(|| unsafe { glGetBooleanv(GL_LIGHTING, sinks.b.borrow_mut().as_mut_ptr()) }),
        ),
        (
            "glGetIntegerv",
            // SAFETY: room for 16 values.
            Box::new(|| unsafe { glGetIntegerv(GL_MAX_LIGHTS, sinks.i.borrow_mut().as_mut_ptr()) }),
        ),
        (
            "glGetFloatv",
            // SAFETY: room for 16 values.
            Box::new(|| unsafe {
                glGetFloatv(GL_CURRENT_COLOR, sinks.f.borrow_mut().as_mut_ptr())
            }),
        ),
        (
            "glGetDoublev",
            // SAFETY: room for 16 values.
            Box::new(|| unsafe { glGetDoublev(GL_DEPTH_RANGE, sinks.d.borrow_mut().as_mut_ptr()) }),
        ),
        (
            "glGetString",
            Box::new(|| assert!(glGetString(GL_VERSION).is_null())),
        ),
    ]
}

/// The state the forbidden commands above would change.
fn observable_state() -> Vec<f64> {
    let mut all = Vec::new();
    all.extend(enables().iter().map(|&b| b as u8 as f64));
    all.extend(get_doubles(GL_LIGHT_MODEL_AMBIENT, 4));
    all.extend(get_doubles(GL_LIGHT_MODEL_TWO_SIDE, 1));
    all.extend(get_doubles(GL_LIGHT_MODEL_LOCAL_VIEWER, 1));
    all.extend(get_doubles(GL_COLOR_MATERIAL_FACE, 1));
    all.extend(get_doubles(GL_COLOR_MATERIAL_PARAMETER, 1));
    all.extend(get_doubles(GL_VIEWPORT, 4));
    all.extend(get_doubles(GL_DEPTH_RANGE, 2));
    all.extend(get_doubles(GL_RENDER_MODE, 1));
    all.extend(get_doubles(GL_FEEDBACK_BUFFER_SIZE, 1));
    all
}

#[test]
fn commands_outside_the_allowed_set_are_invalid_operation_between_begin_and_end() {
    let _ctx = fresh();
    glEnable(GL_LIGHT0);
    let fb = RefCell::new([SENTINEL_F; 8]);
    let sinks = Sinks::new();
    let before = observable_state();
    for (name, command) in forbidden_commands(&fb, &sinks) {
        glBegin(GL_POINTS);
        command();
        glEnd();
        expect_error(
            GL_INVALID_OPERATION,
            &format!("{name} between glBegin and glEnd"),
        );
        assert_eq!(
            observable_state(),
            before,
            "{name} between glBegin and glEnd changed the state"
        );
        assert!(
            sinks.untouched(),
            "{name} wrote its result between glBegin and glEnd"
        );
    }
    assert_eq!(*fb.borrow(), [SENTINEL_F; 8]);
}

#[test]
fn the_allowed_commands_raise_no_error_between_begin_and_end() {
    let _ctx = fresh();
    glBegin(GL_TRIANGLES);
    glColor4f(1.0, 0.0, 0.0, 1.0);
    glNormal3f(0.0, 0.0, 1.0);
    glTexCoord2f(0.5, 0.5);
    glEdgeFlag(GL_TRUE);
    material_fv(GL_FRONT, GL_EMISSION, &[0.1, 0.1, 0.1, 1.0]);
    glVertex3f(0.0, 0.0, 0.0);
    glVertex3f(1.0, 0.0, 0.0);
    glVertex3f(0.0, 1.0, 0.0);
    glEnd();
    expect_no_error("allowed commands");
}

#[test]
fn through_the_safe_context_api() {
    use fflight::{Context, GlError};
    let mut ctx = Context::new();
    assert_eq!(ctx.get(0x1234), Err(GlError::InvalidEnum));
    assert_eq!(
        ctx.set_capability(GL_LIGHT0 + 8, true),
        Err(GlError::InvalidEnum)
    );
    assert_eq!(ctx.is_enabled(GL_RESCALE_NORMAL), Ok(false));
    ctx.set_capability(GL_RESCALE_NORMAL, true).unwrap();
    assert_eq!(ctx.get(GL_RESCALE_NORMAL).unwrap().as_bools(), [true]);
    assert_eq!(
        ctx.get_string(GL_VERSION)
            .unwrap()
            .to_str()
            .unwrap()
            .get(..3),
        Some("1.5")
    );
    ctx.begin(GL_POINTS).unwrap();
    assert_eq!(ctx.get(GL_MAX_LIGHTS), Err(GlError::InvalidOperation));
    assert_eq!(ctx.viewport(0, 0, 1, 1), Err(GlError::InvalidOperation));
    ctx.end().unwrap();
    assert_eq!(ctx.viewport(0, 0, -1, 1), Err(GlError::InvalidValue));
}
