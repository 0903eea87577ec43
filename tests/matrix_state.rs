//! glMatrixMode, glLoad/MultMatrix (and the transpose forms), glTranslate, glRotate, glScale,
//! glFrustum, glOrtho, glPushMatrix/glPopMatrix: the matrices the spec defines (§2.11.2), the
//! stacks and their depths (tables 6.5 and 6.31), and every error.

#[macro_use]
mod common;

use common::*;

/// A column-major 4x4 matrix, as GL stores it.
type M = [f64; 16];

const IDENTITY: M = [
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];

/// `a · b` (GL's glMultMatrix order: the current matrix on the left).
fn mul(a: &M, b: &M) -> M {
    std::array::from_fn(|i| {
        let (col, row) = (i / 4, i % 4);
        (0..4).map(|k| a[k * 4 + row] * b[col * 4 + k]).sum()
    })
}

fn transpose(m: &M) -> M {
    std::array::from_fn(|i| m[(i % 4) * 4 + i / 4])
}

/// A matrix written row by row, as the spec prints it.
fn rows(r: [[f64; 4]; 4]) -> M {
    std::array::from_fn(|i| r[i % 4][i / 4])
}

fn translation(x: f64, y: f64, z: f64) -> M {
    rows([
        [1.0, 0.0, 0.0, x],
        [0.0, 1.0, 0.0, y],
        [0.0, 0.0, 1.0, z],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

fn scaling(x: f64, y: f64, z: f64) -> M {
    rows([
        [x, 0.0, 0.0, 0.0],
        [0.0, y, 0.0, 0.0],
        [0.0, 0.0, z, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// §2.11.2: R = u uᵀ + cos θ (I − u uᵀ) + sin θ S, u the normalized axis.
fn rotation(degrees: f64, x: f64, y: f64, z: f64) -> M {
    let length = (x * x + y * y + z * z).sqrt();
    let u = [x / length, y / length, z / length];
    let (s, c) = degrees.to_radians().sin_cos();
    let skew = [[0.0, -u[2], u[1]], [u[2], 0.0, -u[0]], [-u[1], u[0], 0.0]];
    let mut r = [[0.0; 4]; 4];
    for i in 0..3 {
        for j in 0..3 {
            let uu = u[i] * u[j];
            let identity = if i == j { 1.0 } else { 0.0 };
            r[i][j] = uu + c * (identity - uu) + s * skew[i][j];
        }
    }
    r[3][3] = 1.0;
    rows(r)
}

fn frustum(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> M {
    rows([
        [2.0 * n / (r - l), 0.0, (r + l) / (r - l), 0.0],
        [0.0, 2.0 * n / (t - b), (t + b) / (t - b), 0.0],
        [0.0, 0.0, -(f + n) / (f - n), -2.0 * f * n / (f - n)],
        [0.0, 0.0, -1.0, 0.0],
    ])
}

fn ortho(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> M {
    rows([
        [2.0 / (r - l), 0.0, 0.0, -(r + l) / (r - l)],
        [0.0, 2.0 / (t - b), 0.0, -(t + b) / (t - b)],
        [0.0, 0.0, -2.0 / (f - n), -(f + n) / (f - n)],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

/// A matrix with no symmetry, so that order and transposition mistakes show.
fn sample() -> M {
    std::array::from_fn(|i| ((i * 7 + 3) % 11) as f64 - 4.5)
}

fn sample2() -> M {
    std::array::from_fn(|i| ((i * 5 + 2) % 13) as f64 * 0.25 - 1.0)
}

fn f32s(m: &M) -> [f32; 16] {
    m.map(|v| v as f32)
}

fn load(m: &M) {
    load_matrix(&f32s(m))
}

fn current(pname: GLenum) -> [f32; 16] {
    matrix(pname)
}

const MATRIX_PNAMES: [GLenum; 3] = [GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX, GL_TEXTURE_MATRIX];

/// Everything this file touches: the three matrices, their depths and the mode.
fn snapshot() -> Vec<Vec<f32>> {
    let mut all: Vec<Vec<f32>> = MATRIX_PNAMES.iter().map(|&p| current(p).to_vec()).collect();
    for p in [
        GL_MODELVIEW_STACK_DEPTH,
        GL_PROJECTION_STACK_DEPTH,
        GL_TEXTURE_STACK_DEPTH,
        GL_MATRIX_MODE,
    ] {
        all.push(get_floats(p, 1));
    }
    all
}

#[test]
fn defaults() {
    let _ctx = fresh();
    assert_eq!(get_int(GL_MATRIX_MODE), GL_MODELVIEW as i32);
    for pname in MATRIX_PNAMES {
        assert_eq!(current(pname), f32s(&IDENTITY));
    }
    for pname in [
        GL_TRANSPOSE_MODELVIEW_MATRIX,
        GL_TRANSPOSE_PROJECTION_MATRIX,
        GL_TRANSPOSE_TEXTURE_MATRIX,
    ] {
        assert_eq!(current(pname), f32s(&IDENTITY));
    }
    assert_eq!(get_int(GL_MODELVIEW_STACK_DEPTH), 1);
    assert_eq!(get_int(GL_PROJECTION_STACK_DEPTH), 1);
    assert_eq!(get_int(GL_TEXTURE_STACK_DEPTH), 1);
    // table 6.31's minimums
    assert!(get_int(GL_MAX_MODELVIEW_STACK_DEPTH) >= 32);
    assert!(get_int(GL_MAX_PROJECTION_STACK_DEPTH) >= 2);
    assert!(get_int(GL_MAX_TEXTURE_STACK_DEPTH) >= 2);
    assert_eq!(get_int(GL_MAX_MODELVIEW_STACK_DEPTH), 32);
    expect_no_error("defaults");
}

#[test]
fn matrix_mode_round_trips_and_rejects_other_enums() {
    let _ctx = fresh();
    for mode in [GL_PROJECTION, GL_TEXTURE, GL_MODELVIEW] {
        glMatrixMode(mode);
        expect_no_error("glMatrixMode");
        assert_eq!(get_int(GL_MATRIX_MODE), mode as i32);
    }
    glMatrixMode(GL_TEXTURE);
    for bad in [
        GL_MODELVIEW_MATRIX,
        GL_COLOR_MATERIAL,
        0,
        0x1234,
        0x1703, /* GL_COLOR */
    ] {
        glMatrixMode(bad);
        expect_error(GL_INVALID_ENUM, &format!("glMatrixMode({bad:#x})"));
        assert_eq!(get_int(GL_MATRIX_MODE), GL_TEXTURE as i32);
    }
}

#[test]
fn load_matrix_is_column_major_and_queries_return_it_and_its_transpose() {
    let _ctx = fresh();
    let m = sample();
    load(&m);
    assert_eq!(current(GL_MODELVIEW_MATRIX), f32s(&m));
    assert_eq!(current(GL_TRANSPOSE_MODELVIEW_MATRIX), f32s(&transpose(&m)));
    assert_eq!(get_doubles(GL_MODELVIEW_MATRIX, 16), m.to_vec());
    // the integer query rounds (away from the .5 ties)
    let quarters: M = std::array::from_fn(|i| i as f64 * 0.6 - 4.15);
    load(&quarters);
    let want: Vec<i32> = quarters.iter().map(|v| v.round() as i32).collect();
    assert_eq!(get_ints(GL_MODELVIEW_MATRIX, 16), want);
    assert_eq!(get_bools(GL_MODELVIEW_MATRIX, 16)[0], GL_TRUE);

    let d = sample2();
    // SAFETY: 16 readable values.
    unsafe { glLoadMatrixd(d.as_ptr()) };
    assert_eq!(current(GL_MODELVIEW_MATRIX), f32s(&d));
    expect_no_error("load");
}

#[test]
fn load_transpose_matrix_takes_rows() {
    let _ctx = fresh();
    let m = sample();
    let t = f32s(&m);
    // SAFETY: 16 readable values.
    unsafe { glLoadTransposeMatrixf(t.as_ptr()) };
    assert_eq!(current(GL_MODELVIEW_MATRIX), f32s(&transpose(&m)));
    assert_eq!(current(GL_TRANSPOSE_MODELVIEW_MATRIX), f32s(&m));
    let d = sample2();
    // SAFETY: 16 readable values.
    unsafe { glLoadTransposeMatrixd(d.as_ptr()) };
    assert_eq!(current(GL_MODELVIEW_MATRIX), f32s(&transpose(&d)));
    expect_no_error("load transpose");
}

#[test]
fn mult_matrix_multiplies_on_the_right() {
    let _ctx = fresh();
    let (a, b) = (sample(), sample2());
    let want = mul(&a, &b);
    assert_ne!(want, mul(&b, &a), "the samples must not commute");

    load(&a);
    let bf = f32s(&b);
    // SAFETY: 16 readable values.
    unsafe { glMultMatrixf(bf.as_ptr()) };
    assert_approx_eq!(current(GL_MODELVIEW_MATRIX), want, 1e-5);

    load(&a);
    // SAFETY: 16 readable values.
    unsafe { glMultMatrixd(b.as_ptr()) };
    assert_approx_eq!(current(GL_MODELVIEW_MATRIX), want, 1e-5);

    let bt = transpose(&b);
    load(&a);
    let btf = f32s(&bt);
    // SAFETY: 16 readable values.
    unsafe { glMultTransposeMatrixf(btf.as_ptr()) };
    assert_approx_eq!(current(GL_MODELVIEW_MATRIX), want, 1e-5);

    load(&a);
    // SAFETY: 16 readable values.
    unsafe { glMultTransposeMatrixd(bt.as_ptr()) };
    assert_approx_eq!(current(GL_MODELVIEW_MATRIX), want, 1e-5);
    expect_no_error("mult");
}

#[test]
fn translate_scale_and_rotate_multiply_the_spec_matrices_on_the_right() {
    let _ctx = fresh();
    let a = sample2();

    load(&a);
    glTranslatef(1.5, -2.0, 3.25);
    assert_approx_eq!(
        current(GL_MODELVIEW_MATRIX),
        mul(&a, &translation(1.5, -2.0, 3.25)),
        1e-5
    );
    load(&a);
    glTranslated(-4.0, 0.5, 8.0);
    assert_approx_eq!(
        current(GL_MODELVIEW_MATRIX),
        mul(&a, &translation(-4.0, 0.5, 8.0)),
        1e-5
    );

    load(&a);
    glScalef(2.0, -3.0, 0.5);
    assert_approx_eq!(
        current(GL_MODELVIEW_MATRIX),
        mul(&a, &scaling(2.0, -3.0, 0.5)),
        1e-5
    );
    load(&a);
    glScaled(0.0, 1.0, 10.0);
    assert_approx_eq!(
        current(GL_MODELVIEW_MATRIX),
        mul(&a, &scaling(0.0, 1.0, 10.0)),
        1e-5
    );

    for (angle, x, y, z) in [
        (90.0, 0.0, 0.0, 1.0),
        (30.0, 1.0, 0.0, 0.0),
        (-45.0, 0.0, 1.0, 0.0),
        (123.0, 1.0, 2.0, 3.0),
        (60.0, 0.0, 0.0, 5.0), // a non-unit axis is normalized
        (0.0, 1.0, 1.0, 0.0),
        (720.0, 0.0, 1.0, 1.0),
    ] {
        load(&a);
        glRotatef(angle as f32, x as f32, y as f32, z as f32);
        assert_approx_eq!(
            current(GL_MODELVIEW_MATRIX),
            mul(&a, &rotation(angle, x, y, z)),
            1e-5,
            "glRotatef({angle}, {x}, {y}, {z})"
        );
        load(&a);
        glRotated(angle, x, y, z);
        assert_approx_eq!(
            current(GL_MODELVIEW_MATRIX),
            mul(&a, &rotation(angle, x, y, z)),
            1e-5,
            "glRotated({angle}, {x}, {y}, {z})"
        );
    }
    // 90 degrees about z maps x to y
    glLoadIdentity();
    glRotatef(90.0, 0.0, 0.0, 1.0);
    assert_approx_eq!(
        current(GL_MODELVIEW_MATRIX),
        rows([
            [0.0, -1.0, 0.0, 0.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0]
        ]),
        1e-6
    );
    expect_no_error("translate/scale/rotate");
}

#[test]
fn frustum_and_ortho_build_the_spec_matrices() {
    let _ctx = fresh();
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1.0, 2.0, -0.5, 1.5, 0.5, 20.0);
    expect_no_error("glFrustum");
    assert_approx_eq!(
        current(GL_PROJECTION_MATRIX),
        frustum(-1.0, 2.0, -0.5, 1.5, 0.5, 20.0),
        1e-6
    );
    // it multiplies, like every other matrix command
    let a = sample2();
    load(&a);
    glFrustum(-2.0, 2.0, -1.0, 1.0, 1.0, 3.0);
    assert_approx_eq!(
        current(GL_PROJECTION_MATRIX),
        mul(&a, &frustum(-2.0, 2.0, -1.0, 1.0, 1.0, 3.0)),
        1e-5
    );

    glLoadIdentity();
    glOrtho(0.0, 640.0, 480.0, 0.0, -1.0, 1.0);
    expect_no_error("glOrtho");
    assert_approx_eq!(
        current(GL_PROJECTION_MATRIX),
        ortho(0.0, 640.0, 480.0, 0.0, -1.0, 1.0),
        1e-6
    );
    load(&a);
    // near and far may be negative or reversed for glOrtho
    glOrtho(-3.0, 1.0, -2.0, 2.0, 5.0, -5.0);
    expect_no_error("glOrtho reversed depth");
    assert_approx_eq!(
        current(GL_PROJECTION_MATRIX),
        mul(&a, &ortho(-3.0, 1.0, -2.0, 2.0, 5.0, -5.0)),
        1e-5
    );
    // the modelview is untouched
    assert_eq!(current(GL_MODELVIEW_MATRIX), f32s(&IDENTITY));
}

#[test]
fn degenerate_frustum_and_ortho_are_invalid_value() {
    let _ctx = fresh();
    let a = sample();
    load(&a);
    let before = snapshot();
    for (l, r, b, t, n, f) in [
        (-1.0, 1.0, -1.0, 1.0, 0.0, 10.0),  // near = 0
        (-1.0, 1.0, -1.0, 1.0, -1.0, 10.0), // near < 0
        (-1.0, 1.0, -1.0, 1.0, 1.0, 0.0),   // far = 0
        (-1.0, 1.0, -1.0, 1.0, 1.0, -2.0),  // far < 0
        (1.0, 1.0, -1.0, 1.0, 1.0, 10.0),   // left = right
        (-1.0, 1.0, 2.0, 2.0, 1.0, 10.0),   // bottom = top
        (-1.0, 1.0, -1.0, 1.0, 3.0, 3.0),   // near = far
    ] {
        glFrustum(l, r, b, t, n, f);
        expect_error(
            GL_INVALID_VALUE,
            &format!("glFrustum({l}, {r}, {b}, {t}, {n}, {f})"),
        );
    }
    for (l, r, b, t, n, f) in [
        (1.0, 1.0, -1.0, 1.0, -1.0, 1.0), // left = right
        (-1.0, 1.0, 0.0, 0.0, -1.0, 1.0), // bottom = top
        (-1.0, 1.0, -1.0, 1.0, 2.0, 2.0), // near = far
    ] {
        glOrtho(l, r, b, t, n, f);
        expect_error(
            GL_INVALID_VALUE,
            &format!("glOrtho({l}, {r}, {b}, {t}, {n}, {f})"),
        );
    }
    assert_eq!(snapshot(), before);
}

#[test]
fn commands_act_on_the_stack_the_mode_selects() {
    let _ctx = fresh();
    glMatrixMode(GL_PROJECTION);
    glTranslatef(1.0, 2.0, 3.0);
    glMatrixMode(GL_TEXTURE);
    glScalef(2.0, 2.0, 2.0);
    glMatrixMode(GL_MODELVIEW);
    glRotatef(90.0, 1.0, 0.0, 0.0);
    assert_approx_eq!(
        current(GL_PROJECTION_MATRIX),
        translation(1.0, 2.0, 3.0),
        1e-6
    );
    assert_approx_eq!(current(GL_TEXTURE_MATRIX), scaling(2.0, 2.0, 2.0), 1e-6);
    assert_approx_eq!(
        current(GL_MODELVIEW_MATRIX),
        rotation(90.0, 1.0, 0.0, 0.0),
        1e-6
    );
    assert_approx_eq!(
        current(GL_TRANSPOSE_PROJECTION_MATRIX),
        transpose(&translation(1.0, 2.0, 3.0)),
        1e-6
    );
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    assert_eq!(current(GL_TEXTURE_MATRIX), f32s(&IDENTITY));
    assert_approx_eq!(
        current(GL_PROJECTION_MATRIX),
        translation(1.0, 2.0, 3.0),
        1e-6
    );
    expect_no_error("modes");
}

#[test]
fn push_copies_the_top_and_pop_restores_it() {
    let _ctx = fresh();
    let a = sample();
    load(&a);
    glPushMatrix();
    assert_eq!(get_int(GL_MODELVIEW_STACK_DEPTH), 2);
    assert_eq!(
        current(GL_MODELVIEW_MATRIX),
        f32s(&a),
        "push copies the top"
    );
    glTranslatef(1.0, 1.0, 1.0);
    glPushMatrix();
    glLoadIdentity();
    assert_eq!(get_int(GL_MODELVIEW_STACK_DEPTH), 3);
    glPopMatrix();
    assert_approx_eq!(
        current(GL_MODELVIEW_MATRIX),
        mul(&a, &translation(1.0, 1.0, 1.0)),
        1e-5
    );
    glPopMatrix();
    assert_eq!(current(GL_MODELVIEW_MATRIX), f32s(&a));
    assert_eq!(get_int(GL_MODELVIEW_STACK_DEPTH), 1);

    // each mode has its own stack
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glMatrixMode(GL_TEXTURE);
    glPushMatrix();
    glPushMatrix();
    assert_eq!(get_int(GL_MODELVIEW_STACK_DEPTH), 1);
    assert_eq!(get_int(GL_PROJECTION_STACK_DEPTH), 2);
    assert_eq!(get_int(GL_TEXTURE_STACK_DEPTH), 3);
    expect_no_error("push/pop");
}

fn matrix_pname_of(mode: GLenum) -> GLenum {
    match mode {
        GL_PROJECTION => GL_PROJECTION_MATRIX,
        GL_TEXTURE => GL_TEXTURE_MATRIX,
        _ => GL_MODELVIEW_MATRIX,
    }
}

/// Pushes the stack of `mode` to its maximum depth, checks the overflow, then pops it back to
/// one and checks the underflow; an error changes nothing.
fn exercise_stack(mode: GLenum, depth_pname: GLenum, max_pname: GLenum) {
    glMatrixMode(mode);
    let max = get_int(max_pname);
    let a = sample();
    load(&a);
    let others: Vec<[f32; 16]> = MATRIX_PNAMES
        .iter()
        .filter(|&&p| p != matrix_pname_of(mode))
        .map(|&p| current(p))
        .collect();
    for depth in 2..=max {
        glPushMatrix();
        expect_no_error(&format!("push to depth {depth}"));
        assert_eq!(get_int(depth_pname), depth);
    }
    glScalef(2.0, 2.0, 2.0);
    let before = snapshot();
    glPushMatrix();
    expect_error(GL_STACK_OVERFLOW, &format!("push past depth {max}"));
    assert_eq!(snapshot(), before, "overflow changed the state");
    for depth in (1..max).rev() {
        glPopMatrix();
        expect_no_error(&format!("pop to depth {depth}"));
        assert_eq!(get_int(depth_pname), depth);
    }
    assert_eq!(current(matrix_pname_of(mode)), f32s(&a));
    let others_now: Vec<[f32; 16]> = MATRIX_PNAMES
        .iter()
        .filter(|&&p| p != matrix_pname_of(mode))
        .map(|&p| current(p))
        .collect();
    assert_eq!(others_now, others);
    let before = snapshot();
    glPopMatrix();
    expect_error(GL_STACK_UNDERFLOW, "pop at depth 1");
    assert_eq!(snapshot(), before, "underflow changed the state");
}

#[test]
fn modelview_stack_overflows_at_32_and_underflows_at_1() {
    let _ctx = fresh();
    assert_eq!(get_int(GL_MAX_MODELVIEW_STACK_DEPTH), 32);
    exercise_stack(
        GL_MODELVIEW,
        GL_MODELVIEW_STACK_DEPTH,
        GL_MAX_MODELVIEW_STACK_DEPTH,
    );
}

#[test]
fn projection_stack_overflows_at_its_maximum() {
    let _ctx = fresh();
    exercise_stack(
        GL_PROJECTION,
        GL_PROJECTION_STACK_DEPTH,
        GL_MAX_PROJECTION_STACK_DEPTH,
    );
}

#[test]
fn texture_stack_overflows_at_its_maximum() {
    let _ctx = fresh();
    exercise_stack(
        GL_TEXTURE,
        GL_TEXTURE_STACK_DEPTH,
        GL_MAX_TEXTURE_STACK_DEPTH,
    );
}

#[test]
fn null_matrices_are_invalid_value_and_change_nothing() {
    let _ctx = fresh();
    load(&sample());
    let before = snapshot();
    // SAFETY: NULL is allowed and must be reported, never dereferenced.
    unsafe {
        glLoadMatrixf(std::ptr::null());
        expect_error(GL_INVALID_VALUE, "glLoadMatrixf(NULL)");
        glLoadMatrixd(std::ptr::null());
        expect_error(GL_INVALID_VALUE, "glLoadMatrixd(NULL)");
        glMultMatrixf(std::ptr::null());
        expect_error(GL_INVALID_VALUE, "glMultMatrixf(NULL)");
        glMultMatrixd(std::ptr::null());
        expect_error(GL_INVALID_VALUE, "glMultMatrixd(NULL)");
        glLoadTransposeMatrixf(std::ptr::null());
        expect_error(GL_INVALID_VALUE, "glLoadTransposeMatrixf(NULL)");
        glLoadTransposeMatrixd(std::ptr::null());
        expect_error(GL_INVALID_VALUE, "glLoadTransposeMatrixd(NULL)");
        glMultTransposeMatrixf(std::ptr::null());
        expect_error(GL_INVALID_VALUE, "glMultTransposeMatrixf(NULL)");
        glMultTransposeMatrixd(std::ptr::null());
        expect_error(GL_INVALID_VALUE, "glMultTransposeMatrixd(NULL)");
    }
    assert_eq!(snapshot(), before);
}

type Command<'a> = Box<dyn Fn() + 'a>;

#[test]
fn matrix_commands_between_begin_and_end_are_invalid_operation() {
    let _ctx = fresh();
    load(&sample());
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    let before = snapshot();
    let m = f32s(&sample2());
    let d = sample2();
    let commands: Vec<(&str, Command)> = vec![
        ("glMatrixMode", Box::new(|| glMatrixMode(GL_TEXTURE))),
        ("glLoadIdentity", Box::new(|| glLoadIdentity())),
        // SAFETY (all pointer forms): 16 readable values.
        (
            "glLoadMatrixf",
            Box::new(|| unsafe { glLoadMatrixf(m.as_ptr()) }),
        ),
        (
            "glLoadMatrixd",
            Box::new(|| unsafe { glLoadMatrixd(d.as_ptr()) }),
        ),
        (
            "glMultMatrixf",
            Box::new(|| unsafe { glMultMatrixf(m.as_ptr()) }),
        ),
        (
            "glMultMatrixd",
            Box::new(|| unsafe { glMultMatrixd(d.as_ptr()) }),
        ),
        (
            "glLoadTransposeMatrixf",
            Box::new(|| unsafe { glLoadTransposeMatrixf(m.as_ptr()) }),
        ),
        (
            "glLoadTransposeMatrixd",
            Box::new(|| unsafe { glLoadTransposeMatrixd(d.as_ptr()) }),
        ),
        (
            "glMultTransposeMatrixf",
            Box::new(|| unsafe { glMultTransposeMatrixf(m.as_ptr()) }),
        ),
        (
            "glMultTransposeMatrixd",
            Box::new(|| unsafe { glMultTransposeMatrixd(d.as_ptr()) }),
        ),
        ("glTranslatef", Box::new(|| glTranslatef(1.0, 2.0, 3.0))),
        ("glTranslated", Box::new(|| glTranslated(1.0, 2.0, 3.0))),
        ("glRotatef", Box::new(|| glRotatef(30.0, 1.0, 0.0, 0.0))),
        ("glRotated", Box::new(|| glRotated(30.0, 1.0, 0.0, 0.0))),
        ("glScalef", Box::new(|| glScalef(2.0, 2.0, 2.0))),
        ("glScaled", Box::new(|| glScaled(2.0, 2.0, 2.0))),
        (
            "glFrustum",
            Box::new(|| glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0)),
        ),
        (
            "glOrtho",
            Box::new(|| glOrtho(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0)),
        ),
        ("glPushMatrix", Box::new(|| glPushMatrix())),
        ("glPopMatrix", Box::new(|| glPopMatrix())),
    ];
    for (name, command) in &commands {
        glBegin(GL_POINTS);
        command();
        glEnd();
        expect_error(
            GL_INVALID_OPERATION,
            &format!("{name} between glBegin and glEnd"),
        );
        assert_eq!(
            snapshot(),
            before,
            "{name} between glBegin and glEnd changed the state"
        );
    }
    // so is a NULL matrix
    // SAFETY: NULL is allowed and must be reported, never dereferenced.
    unsafe {
        glBegin(GL_POINTS);
        glLoadMatrixf(std::ptr::null());
        glEnd();
        expect_error(
            GL_INVALID_OPERATION,
            "glLoadMatrixf(NULL) between glBegin and glEnd",
        );
        glBegin(GL_POINTS);
        glMultTransposeMatrixd(std::ptr::null());
        glEnd();
        expect_error(
            GL_INVALID_OPERATION,
            "glMultTransposeMatrixd(NULL) between glBegin and glEnd",
        );
    }
    // a degenerate frustum there is still GL_INVALID_OPERATION (checked first, as Mesa does)
    glBegin(GL_POINTS);
    glFrustum(1.0, 1.0, -1.0, 1.0, 0.0, 10.0);
    glEnd();
    expect_error(
        GL_INVALID_OPERATION,
        "bad glFrustum between glBegin and glEnd",
    );
}

#[test]
fn through_the_safe_context_api() {
    use fflight::{Context, GlError};
    let mut ctx = Context::new();
    assert_eq!(ctx.pop_matrix(), Err(GlError::StackUnderflow));
    for _ in 1..32 {
        ctx.push_matrix().unwrap();
    }
    assert_eq!(ctx.push_matrix(), Err(GlError::StackOverflow));
    assert_eq!(
        ctx.frustum(0.0, 0.0, 0.0, 1.0, 1.0, 2.0),
        Err(GlError::InvalidValue)
    );
    assert_eq!(
        ctx.matrix_mode(GL_MODELVIEW_MATRIX),
        Err(GlError::InvalidEnum)
    );
    ctx.scale(2.0, 3.0, 4.0).unwrap();
    assert_eq!(
        ctx.get(GL_MODELVIEW_MATRIX).unwrap().as_floats()[..11],
        [2.0, 0.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 4.0]
    );
    assert_eq!(ctx.get(GL_MODELVIEW_STACK_DEPTH).unwrap().as_ints(), [32]);
}
