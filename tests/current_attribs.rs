//! glNormal3{b,s,i,f,d}[v], glColor{3,4}{b,s,i,f,d,ub,us,ui}[v] and
//! glTexCoord{1,2,3,4}{s,i,f,d}[v]: the current values they set, the conversions of table 2.9
//! (signed types map (2c + 1) / (2^b - 1), unsigned c / (2^b - 1), floats and texture
//! coordinates as they are), the defaults, and the integer queries of §6.1.2.

#[macro_use]
mod common;

use common::*;

fn current_normal() -> Vec<f32> {
    get_floats(GL_CURRENT_NORMAL, 3)
}

fn current_color() -> Vec<f32> {
    get_floats(GL_CURRENT_COLOR, 4)
}

fn current_tex_coord() -> Vec<f32> {
    get_floats(GL_CURRENT_TEXTURE_COORDS, 4)
}

fn signed(c: i64, bits: u32) -> f32 {
    ((2 * c + 1) as f64 / ((1u64 << bits) - 1) as f64) as f32
}

fn unsigned(c: u64, bits: u32) -> f32 {
    (c as f64 / ((1u64 << bits) - 1) as f64) as f32
}

#[test]
fn defaults() {
    let _ctx = fresh();
    assert_eq!(current_normal(), [0.0, 0.0, 1.0]);
    assert_eq!(current_color(), [1.0, 1.0, 1.0, 1.0]);
    assert_eq!(current_tex_coord(), [0.0, 0.0, 0.0, 1.0]);
    assert_eq!(get_doubles(GL_CURRENT_NORMAL, 3), [0.0, 0.0, 1.0]);
    assert_eq!(get_ints(GL_CURRENT_COLOR, 4), [i32::MAX; 4]);
    assert_eq!(get_ints(GL_CURRENT_NORMAL, 3), [0, 0, i32::MAX]);
    assert_eq!(get_ints(GL_CURRENT_TEXTURE_COORDS, 4), [0, 0, 0, 1]);
    expect_no_error("defaults");
}

#[test]
fn normals_of_signed_types_map_to_minus_one_to_one() {
    let _ctx = fresh();
    glNormal3b(-128, 127, 0);
    assert_approx_eq!(current_normal(), [-1.0, 1.0, signed(0, 8)], 1e-7);
    // SAFETY: three readable values.
    unsafe { glNormal3bv([10i8, -10, 64].as_ptr()) };
    assert_approx_eq!(
        current_normal(),
        [signed(10, 8), signed(-10, 8), signed(64, 8)],
        1e-7
    );

    glNormal3s(i16::MIN, i16::MAX, -1);
    assert_approx_eq!(current_normal(), [-1.0, 1.0, signed(-1, 16)], 1e-7);
    // SAFETY: three readable values.
    unsafe { glNormal3sv([1000i16, -2000, 0].as_ptr()) };
    assert_approx_eq!(
        current_normal(),
        [signed(1000, 16), signed(-2000, 16), signed(0, 16)],
        1e-7
    );

    glNormal3i(i32::MIN, i32::MAX, 1 << 30);
    assert_approx_eq!(current_normal(), [-1.0, 1.0, int_color(1 << 30)], 1e-7);
    // SAFETY: three readable values.
    unsafe { glNormal3iv([0i32, -(1 << 29), 1 << 29].as_ptr()) };
    assert_approx_eq!(current_normal(), [int_color(0), -0.25, 0.25], 1e-7);
    expect_no_error("integer normals");
}

#[test]
fn float_normals_are_stored_as_given_not_normalized() {
    let _ctx = fresh();
    glNormal3f(3.0, 4.0, 12.0);
    assert_eq!(current_normal(), [3.0, 4.0, 12.0]);
    glNormal3d(-0.5, 0.25, 100.0);
    assert_eq!(current_normal(), [-0.5, 0.25, 100.0]);
    // SAFETY: three readable values.
    unsafe { glNormal3fv([0.0f32, 0.0, 0.0].as_ptr()) };
    assert_eq!(current_normal(), [0.0, 0.0, 0.0]);
    // SAFETY: three readable values.
    unsafe { glNormal3dv([1.0f64, 2.0, -3.0].as_ptr()) };
    assert_eq!(current_normal(), [1.0, 2.0, -3.0]);
    // GL_NORMALIZE changes vertex processing, not the current normal
    glEnable(GL_NORMALIZE);
    glNormal3f(0.0, 2.0, 0.0);
    assert_eq!(current_normal(), [0.0, 2.0, 0.0]);
    expect_no_error("float normals");
}

#[test]
fn normal_integer_query_maps_linearly() {
    let _ctx = fresh();
    glNormal3f(1.0, -1.0, 0.25);
    assert_eq!(
        get_ints(GL_CURRENT_NORMAL, 3),
        [i32::MAX, i32::MIN, 536_870_911]
    );
    glNormal3i(12345, -777, i32::MAX);
    assert_eq!(get_ints(GL_CURRENT_NORMAL, 3), [12345, -777, i32::MAX]);
    expect_no_error("normal ints");
}

#[test]
fn colors_of_every_type_in_three_and_four_components() {
    let _ctx = fresh();
    // each 3-component form resets alpha to 1
    let reset = || glColor4f(0.0, 0.0, 0.0, 0.5);

    reset();
    glColor3b(-128, 127, 0);
    assert_approx_eq!(current_color(), [-1.0, 1.0, signed(0, 8), 1.0], 1e-7);
    glColor4b(1, -2, 3, -4);
    assert_approx_eq!(
        current_color(),
        [signed(1, 8), signed(-2, 8), signed(3, 8), signed(-4, 8)],
        1e-7
    );

    reset();
    glColor3s(i16::MIN, i16::MAX, 100);
    assert_approx_eq!(current_color(), [-1.0, 1.0, signed(100, 16), 1.0], 1e-7);
    glColor4s(-5, 6, -7, 8);
    assert_approx_eq!(
        current_color(),
        [signed(-5, 16), signed(6, 16), signed(-7, 16), signed(8, 16)],
        1e-7
    );

    reset();
    glColor3i(i32::MIN, i32::MAX, 1 << 29);
    assert_approx_eq!(current_color(), [-1.0, 1.0, 0.25, 1.0], 1e-7);
    glColor4i(0, -(1 << 30), 1 << 30, i32::MAX);
    assert_approx_eq!(
        current_color(),
        [int_color(0), int_color(-(1 << 30)), int_color(1 << 30), 1.0],
        1e-7
    );

    reset();
    glColor3ub(0, 255, 51);
    assert_approx_eq!(current_color(), [0.0, 1.0, 0.2, 1.0], 1e-7);
    glColor4ub(1, 2, 3, 128);
    assert_approx_eq!(
        current_color(),
        [
            unsigned(1, 8),
            unsigned(2, 8),
            unsigned(3, 8),
            unsigned(128, 8)
        ],
        1e-7
    );

    reset();
    glColor3us(0, u16::MAX, 32768);
    assert_approx_eq!(current_color(), [0.0, 1.0, unsigned(32768, 16), 1.0], 1e-7);
    glColor4us(1, 1000, 65534, 0);
    assert_approx_eq!(
        current_color(),
        [
            unsigned(1, 16),
            unsigned(1000, 16),
            unsigned(65534, 16),
            0.0
        ],
        1e-7
    );

    reset();
    glColor3ui(0, u32::MAX, 1 << 31);
    assert_approx_eq!(
        current_color(),
        [0.0, 1.0, unsigned(1 << 31, 32), 1.0],
        1e-7
    );
    glColor4ui(u32::MAX, 0, u32::MAX, 1 << 30);
    assert_approx_eq!(current_color(), [1.0, 0.0, 1.0, 0.25], 1e-7);

    // floating-point colors are stored unclamped
    reset();
    glColor3f(1.5, -0.25, 0.5);
    assert_eq!(current_color(), [1.5, -0.25, 0.5, 1.0]);
    glColor4f(0.1, 0.2, 0.3, 2.0);
    assert_eq!(current_color(), [0.1, 0.2, 0.3, 2.0]);
    reset();
    glColor3d(0.75, -3.0, 0.0);
    assert_eq!(current_color(), [0.75, -3.0, 0.0, 1.0]);
    glColor4d(0.125, 0.25, 0.375, -0.5);
    assert_eq!(current_color(), [0.125, 0.25, 0.375, -0.5]);
    expect_no_error("colors");
}

#[test]
fn color_vector_forms_read_their_components() {
    let _ctx = fresh();
    let reset = || glColor4f(0.0, 0.0, 0.0, 0.5);
    // SAFETY: every pointer below points to as many values as the command reads.
    unsafe {
        reset();
        glColor3bv([127i8, -128, 0].as_ptr());
        assert_approx_eq!(current_color(), [1.0, -1.0, signed(0, 8), 1.0], 1e-7);
        glColor4bv([127i8, 127, -128, -128].as_ptr());
        assert_approx_eq!(current_color(), [1.0, 1.0, -1.0, -1.0], 1e-7);

        reset();
        glColor3sv([i16::MAX, 0, i16::MIN].as_ptr());
        assert_approx_eq!(current_color(), [1.0, signed(0, 16), -1.0, 1.0], 1e-7);
        glColor4sv([0i16, 0, 0, i16::MAX].as_ptr());
        assert_approx_eq!(
            current_color(),
            [signed(0, 16), signed(0, 16), signed(0, 16), 1.0],
            1e-7
        );

        reset();
        glColor3iv([1i32 << 29, -(1 << 29), i32::MAX].as_ptr());
        assert_approx_eq!(current_color(), [0.25, -0.25, 1.0, 1.0], 1e-7);
        glColor4iv([i32::MIN, i32::MIN, i32::MIN, i32::MAX].as_ptr());
        assert_approx_eq!(current_color(), [-1.0, -1.0, -1.0, 1.0], 1e-7);

        reset();
        glColor3fv([0.5f32, 1.5, -1.0].as_ptr());
        assert_eq!(current_color(), [0.5, 1.5, -1.0, 1.0]);
        glColor4fv([0.1f32, 0.2, 0.3, 0.4].as_ptr());
        assert_eq!(current_color(), [0.1, 0.2, 0.3, 0.4]);

        reset();
        glColor3dv([0.25f64, 0.5, 0.75].as_ptr());
        assert_eq!(current_color(), [0.25, 0.5, 0.75, 1.0]);
        glColor4dv([1.0f64, 0.0, 1.0, 0.0].as_ptr());
        assert_eq!(current_color(), [1.0, 0.0, 1.0, 0.0]);

        reset();
        glColor3ubv([255u8, 0, 51].as_ptr());
        assert_approx_eq!(current_color(), [1.0, 0.0, 0.2, 1.0], 1e-7);
        glColor4ubv([0u8, 51, 102, 255].as_ptr());
        assert_approx_eq!(current_color(), [0.0, 0.2, 0.4, 1.0], 1e-7);

        reset();
        glColor3usv([u16::MAX, 0, 13107].as_ptr());
        assert_approx_eq!(current_color(), [1.0, 0.0, 0.2, 1.0], 1e-7);
        glColor4usv([0u16, 0, 0, u16::MAX].as_ptr());
        assert_eq!(current_color(), [0.0, 0.0, 0.0, 1.0]);

        reset();
        glColor3uiv([u32::MAX, 0, 1 << 30].as_ptr());
        assert_approx_eq!(current_color(), [1.0, 0.0, 0.25, 1.0], 1e-7);
        glColor4uiv([0u32, u32::MAX, 0, u32::MAX].as_ptr());
        assert_eq!(current_color(), [0.0, 1.0, 0.0, 1.0]);
    }
    expect_no_error("color vectors");
}

#[test]
fn color_integer_and_boolean_queries() {
    let _ctx = fresh();
    glColor4f(1.0, -1.0, 0.25, -0.5);
    assert_eq!(
        get_ints(GL_CURRENT_COLOR, 4),
        [i32::MAX, i32::MIN, 536_870_911, -1_073_741_824]
    );
    glColor4i(12345, -777, 0, i32::MAX);
    assert_eq!(get_ints(GL_CURRENT_COLOR, 4), [12345, -777, 0, i32::MAX]);
    glColor4f(0.0, 0.5, 0.0, 1.0);
    assert_eq!(
        get_bools(GL_CURRENT_COLOR, 4),
        [GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE]
    );
    assert_eq!(get_doubles(GL_CURRENT_COLOR, 4), [0.0, 0.5, 0.0, 1.0]);
    expect_no_error("color queries");
}

#[test]
fn tex_coords_fill_missing_components_with_0_0_1() {
    let _ctx = fresh();
    let reset = || glTexCoord4f(9.0, 9.0, 9.0, 9.0);

    reset();
    glTexCoord1s(-3);
    assert_eq!(current_tex_coord(), [-3.0, 0.0, 0.0, 1.0]);
    reset();
    glTexCoord1i(100_000);
    assert_eq!(current_tex_coord(), [100_000.0, 0.0, 0.0, 1.0]);
    reset();
    glTexCoord1f(0.5);
    assert_eq!(current_tex_coord(), [0.5, 0.0, 0.0, 1.0]);
    reset();
    glTexCoord1d(-0.25);
    assert_eq!(current_tex_coord(), [-0.25, 0.0, 0.0, 1.0]);

    reset();
    glTexCoord2s(1, -2);
    assert_eq!(current_tex_coord(), [1.0, -2.0, 0.0, 1.0]);
    reset();
    glTexCoord2i(3, -7);
    assert_eq!(current_tex_coord(), [3.0, -7.0, 0.0, 1.0]);
    reset();
    glTexCoord2f(0.25, 0.75);
    assert_eq!(current_tex_coord(), [0.25, 0.75, 0.0, 1.0]);
    reset();
    glTexCoord2d(2.5, 3.5);
    assert_eq!(current_tex_coord(), [2.5, 3.5, 0.0, 1.0]);

    reset();
    glTexCoord3s(1, 2, 3);
    assert_eq!(current_tex_coord(), [1.0, 2.0, 3.0, 1.0]);
    reset();
    glTexCoord3i(-1, -2, -3);
    assert_eq!(current_tex_coord(), [-1.0, -2.0, -3.0, 1.0]);
    reset();
    glTexCoord3f(0.1, 0.2, 0.3);
    assert_eq!(current_tex_coord(), [0.1, 0.2, 0.3, 1.0]);
    reset();
    glTexCoord3d(4.0, 5.0, 6.0);
    assert_eq!(current_tex_coord(), [4.0, 5.0, 6.0, 1.0]);

    glTexCoord4s(1, 2, 3, 4);
    assert_eq!(current_tex_coord(), [1.0, 2.0, 3.0, 4.0]);
    glTexCoord4i(i16::MAX as i32 + 1, 0, -5, 2);
    assert_eq!(current_tex_coord(), [32768.0, 0.0, -5.0, 2.0]);
    glTexCoord4f(0.5, 0.25, 0.125, 0.0);
    assert_eq!(current_tex_coord(), [0.5, 0.25, 0.125, 0.0]);
    glTexCoord4d(-1.0, -2.0, -3.0, -4.0);
    assert_eq!(current_tex_coord(), [-1.0, -2.0, -3.0, -4.0]);
    expect_no_error("tex coords");
}

#[test]
fn tex_coord_vector_forms() {
    let _ctx = fresh();
    let reset = || glTexCoord4f(9.0, 9.0, 9.0, 9.0);
    // SAFETY: every pointer below points to as many values as the command reads.
    unsafe {
        reset();
        glTexCoord1sv([7i16].as_ptr());
        assert_eq!(current_tex_coord(), [7.0, 0.0, 0.0, 1.0]);
        reset();
        glTexCoord1iv([-7i32].as_ptr());
        assert_eq!(current_tex_coord(), [-7.0, 0.0, 0.0, 1.0]);
        reset();
        glTexCoord1fv([0.5f32].as_ptr());
        assert_eq!(current_tex_coord(), [0.5, 0.0, 0.0, 1.0]);
        reset();
        glTexCoord1dv([1.5f64].as_ptr());
        assert_eq!(current_tex_coord(), [1.5, 0.0, 0.0, 1.0]);

        reset();
        glTexCoord2sv([1i16, 2].as_ptr());
        assert_eq!(current_tex_coord(), [1.0, 2.0, 0.0, 1.0]);
        reset();
        glTexCoord2iv([3i32, 4].as_ptr());
        assert_eq!(current_tex_coord(), [3.0, 4.0, 0.0, 1.0]);
        reset();
        glTexCoord2fv([0.5f32, 0.25].as_ptr());
        assert_eq!(current_tex_coord(), [0.5, 0.25, 0.0, 1.0]);
        reset();
        glTexCoord2dv([5.0f64, 6.0].as_ptr());
        assert_eq!(current_tex_coord(), [5.0, 6.0, 0.0, 1.0]);

        reset();
        glTexCoord3sv([1i16, 2, 3].as_ptr());
        assert_eq!(current_tex_coord(), [1.0, 2.0, 3.0, 1.0]);
        reset();
        glTexCoord3iv([4i32, 5, 6].as_ptr());
        assert_eq!(current_tex_coord(), [4.0, 5.0, 6.0, 1.0]);
        reset();
        glTexCoord3fv([0.1f32, 0.2, 0.3].as_ptr());
        assert_eq!(current_tex_coord(), [0.1, 0.2, 0.3, 1.0]);
        reset();
        glTexCoord3dv([7.0f64, 8.0, 9.0].as_ptr());
        assert_eq!(current_tex_coord(), [7.0, 8.0, 9.0, 1.0]);

        glTexCoord4sv([1i16, 2, 3, 4].as_ptr());
        assert_eq!(current_tex_coord(), [1.0, 2.0, 3.0, 4.0]);
        glTexCoord4iv([5i32, 6, 7, 8].as_ptr());
        assert_eq!(current_tex_coord(), [5.0, 6.0, 7.0, 8.0]);
        glTexCoord4fv([0.5f32, 0.5, 0.5, 0.5].as_ptr());
        assert_eq!(current_tex_coord(), [0.5, 0.5, 0.5, 0.5]);
        glTexCoord4dv([-1.0f64, 0.0, 1.0, 2.0].as_ptr());
        assert_eq!(current_tex_coord(), [-1.0, 0.0, 1.0, 2.0]);
    }
    // integer query rounds texture coordinates (they are not colors)
    glTexCoord4f(2.6, -2.6, 0.4, 1.0);
    assert_eq!(get_ints(GL_CURRENT_TEXTURE_COORDS, 4), [3, -3, 0, 1]);
    expect_no_error("tex coord vectors");
}

#[test]
fn all_of_them_are_legal_between_begin_and_end() {
    let _ctx = fresh();
    glBegin(GL_POINTS);
    glNormal3b(0, 127, 0);
    glColor4ub(0, 0, 255, 255);
    glTexCoord2f(0.5, 0.5);
    glVertex3f(0.0, 0.0, 0.0);
    glNormal3f(1.0, 0.0, 0.0);
    glColor3f(1.0, 0.0, 0.0);
    glTexCoord4i(1, 2, 3, 4);
    glEdgeFlag(GL_FALSE);
    glEnd();
    expect_no_error("current attributes in begin/end");
    assert_eq!(current_normal(), [1.0, 0.0, 0.0]);
    assert_eq!(current_color(), [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(current_tex_coord(), [1.0, 2.0, 3.0, 4.0]);
    assert_eq!(get_bools(GL_EDGE_FLAG, 1), [GL_FALSE]);
}

#[test]
fn null_vectors_are_invalid_value_and_change_nothing() {
    let _ctx = fresh();
    glNormal3f(0.1, 0.2, 0.3);
    glColor4f(0.4, 0.5, 0.6, 0.7);
    glTexCoord4f(1.0, 2.0, 3.0, 4.0);
    macro_rules! null {
        ($($f:ident),* $(,)?) => {
            $(
                // SAFETY: NULL is allowed and must be reported, never dereferenced.
                unsafe { $f(std::ptr::null()) };
                expect_error(GL_INVALID_VALUE, stringify!($f));
            )*
        };
    }
    null!(
        glNormal3bv,
        glNormal3sv,
        glNormal3iv,
        glNormal3fv,
        glNormal3dv
    );
    null!(
        glColor3bv,
        glColor3sv,
        glColor3iv,
        glColor3fv,
        glColor3dv,
        glColor3ubv,
        glColor3usv,
        glColor3uiv,
        glColor4bv,
        glColor4sv,
        glColor4iv,
        glColor4fv,
        glColor4dv,
        glColor4ubv,
        glColor4usv,
        glColor4uiv,
    );
    null!(
        glTexCoord1sv,
        glTexCoord1iv,
        glTexCoord1fv,
        glTexCoord1dv,
        glTexCoord2sv,
        glTexCoord2iv,
        glTexCoord2fv,
        glTexCoord2dv,
        glTexCoord3sv,
        glTexCoord3iv,
        glTexCoord3fv,
        glTexCoord3dv,
        glTexCoord4sv,
        glTexCoord4iv,
        glTexCoord4fv,
        glTexCoord4dv,
    );
    null!(glEdgeFlagv, glVertex3fv);
    assert_eq!(current_normal(), [0.1, 0.2, 0.3]);
    assert_eq!(current_color(), [0.4, 0.5, 0.6, 0.7]);
    assert_eq!(current_tex_coord(), [1.0, 2.0, 3.0, 4.0]);
    assert_eq!(get_bools(GL_EDGE_FLAG, 1), [GL_TRUE]);
}

#[test]
fn through_the_safe_context_api() {
    let mut ctx = fflight::Context::new();
    ctx.normal(glam::Vec3::new(0.0, 1.0, 0.0));
    ctx.color(glam::Vec4::new(0.5, 0.25, 0.0, 1.0));
    ctx.tex_coord(glam::Vec4::new(1.0, 2.0, 0.0, 1.0));
    assert_eq!(
        ctx.get(GL_CURRENT_NORMAL).unwrap().as_floats(),
        [0.0, 1.0, 0.0]
    );
    assert_eq!(
        ctx.get(GL_CURRENT_COLOR).unwrap().as_floats(),
        [0.5, 0.25, 0.0, 1.0]
    );
    assert_eq!(
        ctx.get(GL_CURRENT_TEXTURE_COORDS).unwrap().as_ints(),
        [1, 2, 0, 1]
    );
}
