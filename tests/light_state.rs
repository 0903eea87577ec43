//! glLight{f,i}[v], glGetLight{f,i}v and glLightModel{f,i}[v]: defaults, round trips, the
//! eye-space transforms of GL_POSITION and GL_SPOT_DIRECTION, the integer conversions and every
//! error (OpenGL 1.5 §2.14.1-2.14.2, §6.1.2, tables 2.10 and 6.9-6.10).

#[macro_use]
mod common;

use common::*;

const LIGHTS: [GLenum; 8] = [
    GL_LIGHT0, GL_LIGHT1, GL_LIGHT2, GL_LIGHT3, GL_LIGHT4, GL_LIGHT5, GL_LIGHT6, GL_LIGHT7,
];

/// Every light pname and how many values it has.
const LIGHT_PNAMES: [(GLenum, usize); 10] = [
    (GL_AMBIENT, 4),
    (GL_DIFFUSE, 4),
    (GL_SPECULAR, 4),
    (GL_POSITION, 4),
    (GL_SPOT_DIRECTION, 3),
    (GL_SPOT_EXPONENT, 1),
    (GL_SPOT_CUTOFF, 1),
    (GL_CONSTANT_ATTENUATION, 1),
    (GL_LINEAR_ATTENUATION, 1),
    (GL_QUADRATIC_ATTENUATION, 1),
];

/// All of one light's state, as glGetLightfv reports it.
fn light_state(light: GLenum) -> Vec<Vec<f32>> {
    LIGHT_PNAMES
        .iter()
        .map(|&(pname, n)| get_light(light, pname, n))
        .collect()
}

#[test]
fn max_lights_is_eight() {
    let _ctx = fresh();
    assert_eq!(get_int(GL_MAX_LIGHTS), 8);
    expect_no_error("GL_MAX_LIGHTS");
}

#[test]
fn every_light_starts_with_the_table_2_10_defaults() {
    let _ctx = fresh();
    for (i, &light) in LIGHTS.iter().enumerate() {
        let white_if_first = if i == 0 {
            [1.0, 1.0, 1.0, 1.0]
        } else {
            [0.0, 0.0, 0.0, 1.0]
        };
        assert_eq!(
            get_light(light, GL_AMBIENT, 4),
            [0.0, 0.0, 0.0, 1.0],
            "light {i}"
        );
        assert_eq!(get_light(light, GL_DIFFUSE, 4), white_if_first, "light {i}");
        assert_eq!(
            get_light(light, GL_SPECULAR, 4),
            white_if_first,
            "light {i}"
        );
        assert_eq!(
            get_light(light, GL_POSITION, 4),
            [0.0, 0.0, 1.0, 0.0],
            "light {i}"
        );
        assert_eq!(
            get_light(light, GL_SPOT_DIRECTION, 3),
            [0.0, 0.0, -1.0],
            "light {i}"
        );
        assert_eq!(get_light(light, GL_SPOT_EXPONENT, 1), [0.0], "light {i}");
        assert_eq!(get_light(light, GL_SPOT_CUTOFF, 1), [180.0], "light {i}");
        assert_eq!(
            get_light(light, GL_CONSTANT_ATTENUATION, 1),
            [1.0],
            "light {i}"
        );
        assert_eq!(
            get_light(light, GL_LINEAR_ATTENUATION, 1),
            [0.0],
            "light {i}"
        );
        assert_eq!(
            get_light(light, GL_QUADRATIC_ATTENUATION, 1),
            [0.0],
            "light {i}"
        );
        assert_eq!(glIsEnabled(light), GL_FALSE, "light {i}");
    }
    expect_no_error("default queries");
}

#[test]
fn defaults_read_through_get_light_iv() {
    let _ctx = fresh();
    assert_eq!(get_light_i(GL_LIGHT0, GL_DIFFUSE, 4), [i32::MAX; 4]);
    assert_eq!(get_light_i(GL_LIGHT0, GL_POSITION, 4), [0, 0, 1, 0]);
    assert_eq!(get_light_i(GL_LIGHT0, GL_SPOT_DIRECTION, 3), [0, 0, -1]);
    assert_eq!(get_light_i(GL_LIGHT0, GL_SPOT_CUTOFF, 1), [180]);
    assert_eq!(get_light_i(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1), [1]);
    // 0.0 sits halfway between -1 and 0 in the linear mapping; it reads back as 0
    assert_eq!(get_light_i(GL_LIGHT5, GL_SPECULAR, 4), [0, 0, 0, i32::MAX]);
    assert_eq!(get_light_i(GL_LIGHT0, GL_AMBIENT, 4), [0, 0, 0, i32::MAX]);
    expect_no_error("default integer queries");
}

#[test]
fn colors_round_trip_unclamped_on_each_light_alone() {
    let _ctx = fresh();
    let colors = [
        (GL_AMBIENT, [0.1, -0.2, 1.5, 0.75]),
        (GL_DIFFUSE, [2.0, 0.5, -1.0, 0.25]),
        (GL_SPECULAR, [0.3, 0.6, 0.9, 0.0]),
    ];
    for (pname, color) in colors {
        light_fv(GL_LIGHT3, pname, &color);
        assert_eq!(get_light(GL_LIGHT3, pname, 4), color);
    }
    // the other lights are untouched
    assert_eq!(get_light(GL_LIGHT2, GL_DIFFUSE, 4), [0.0, 0.0, 0.0, 1.0]);
    assert_eq!(get_light(GL_LIGHT0, GL_DIFFUSE, 4), [1.0, 1.0, 1.0, 1.0]);
    expect_no_error("colors");
}

#[test]
fn scalar_parameters_round_trip_through_every_form() {
    let _ctx = fresh();
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 12.5);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 33.25);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.5);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.125);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 3.0);
    expect_no_error("glLightf");
    assert_eq!(get_light(GL_LIGHT1, GL_SPOT_EXPONENT, 1), [12.5]);
    assert_eq!(get_light(GL_LIGHT1, GL_SPOT_CUTOFF, 1), [33.25]);
    assert_eq!(get_light(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 1), [0.5]);
    assert_eq!(get_light(GL_LIGHT1, GL_LINEAR_ATTENUATION, 1), [0.125]);
    assert_eq!(get_light(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 1), [3.0]);

    light_fv(GL_LIGHT2, GL_SPOT_EXPONENT, &[7.0]);
    light_fv(GL_LIGHT2, GL_SPOT_CUTOFF, &[90.0]);
    light_fv(GL_LIGHT2, GL_LINEAR_ATTENUATION, &[2.0]);
    assert_eq!(get_light(GL_LIGHT2, GL_SPOT_EXPONENT, 1), [7.0]);
    assert_eq!(get_light(GL_LIGHT2, GL_SPOT_CUTOFF, 1), [90.0]);
    assert_eq!(get_light(GL_LIGHT2, GL_LINEAR_ATTENUATION, 1), [2.0]);

    // glLighti and glLightiv convert these directly, not by the color mapping
    glLighti(GL_LIGHT4, GL_SPOT_EXPONENT, 100);
    glLighti(GL_LIGHT4, GL_SPOT_CUTOFF, 45);
    glLighti(GL_LIGHT4, GL_QUADRATIC_ATTENUATION, 9);
    light_iv(GL_LIGHT4, GL_CONSTANT_ATTENUATION, &[4]);
    light_iv(GL_LIGHT4, GL_LINEAR_ATTENUATION, &[6]);
    expect_no_error("glLighti");
    assert_eq!(get_light(GL_LIGHT4, GL_SPOT_EXPONENT, 1), [100.0]);
    assert_eq!(get_light(GL_LIGHT4, GL_SPOT_CUTOFF, 1), [45.0]);
    assert_eq!(get_light(GL_LIGHT4, GL_QUADRATIC_ATTENUATION, 1), [9.0]);
    assert_eq!(get_light(GL_LIGHT4, GL_CONSTANT_ATTENUATION, 1), [4.0]);
    assert_eq!(get_light(GL_LIGHT4, GL_LINEAR_ATTENUATION, 1), [6.0]);
}

#[test]
fn position_is_transformed_by_the_modelview_current_at_the_call() {
    let _ctx = fresh();
    glTranslatef(1.0, 2.0, 3.0);
    glRotatef(90.0, 0.0, 0.0, 1.0);
    // local light: rotated (1,0,0) -> (0,1,0), then translated
    light_fv(GL_LIGHT0, GL_POSITION, &[1.0, 0.0, 0.0, 1.0]);
    // directional light: the translation does not apply
    light_fv(GL_LIGHT1, GL_POSITION, &[1.0, 0.0, 0.0, 0.0]);
    // a homogeneous position keeps its w
    light_fv(GL_LIGHT2, GL_POSITION, &[2.0, 0.0, 0.0, 2.0]);
    expect_no_error("glLightfv(GL_POSITION)");
    assert_approx_eq!(
        get_light(GL_LIGHT0, GL_POSITION, 4),
        [1.0, 3.0, 3.0, 1.0f32]
    );
    assert_approx_eq!(
        get_light(GL_LIGHT1, GL_POSITION, 4),
        [0.0, 1.0, 0.0, 0.0f32]
    );
    assert_approx_eq!(
        get_light(GL_LIGHT2, GL_POSITION, 4),
        [2.0, 6.0, 6.0, 2.0f32]
    );

    // later matrix changes leave the stored eye-space position alone
    glLoadIdentity();
    glScalef(5.0, 5.0, 5.0);
    assert_approx_eq!(
        get_light(GL_LIGHT0, GL_POSITION, 4),
        [1.0, 3.0, 3.0, 1.0f32]
    );

    // the integer form goes through the same matrix, converted directly
    light_iv(GL_LIGHT3, GL_POSITION, &[1, -2, 3, 1]);
    assert_approx_eq!(
        get_light(GL_LIGHT3, GL_POSITION, 4),
        [5.0, -10.0, 15.0, 1.0f32]
    );
    expect_no_error("after");
}

#[test]
fn position_uses_the_modelview_even_when_another_matrix_mode_is_selected() {
    let _ctx = fresh();
    glTranslatef(0.0, 0.0, -4.0);
    glMatrixMode(GL_PROJECTION);
    glTranslatef(10.0, 10.0, 10.0);
    glMatrixMode(GL_TEXTURE);
    glScalef(3.0, 3.0, 3.0);
    light_fv(GL_LIGHT0, GL_POSITION, &[1.0, 1.0, 1.0, 1.0]);
    light_fv(GL_LIGHT0, GL_SPOT_DIRECTION, &[0.0, 1.0, 0.0]);
    assert_approx_eq!(
        get_light(GL_LIGHT0, GL_POSITION, 4),
        [1.0, 1.0, -3.0, 1.0f32]
    );
    assert_approx_eq!(
        get_light(GL_LIGHT0, GL_SPOT_DIRECTION, 3),
        [0.0, 1.0, 0.0f32]
    );
    expect_no_error("after");
}

#[test]
fn spot_direction_goes_through_the_upper_3x3_unnormalized() {
    let _ctx = fresh();
    glTranslatef(7.0, 8.0, 9.0);
    glScalef(2.0, 3.0, 4.0);
    light_fv(GL_LIGHT6, GL_SPOT_DIRECTION, &[1.0, 1.0, 1.0]);
    assert_approx_eq!(
        get_light(GL_LIGHT6, GL_SPOT_DIRECTION, 3),
        [2.0, 3.0, 4.0f32]
    );

    glLoadIdentity();
    glRotatef(90.0, 1.0, 0.0, 0.0);
    light_fv(GL_LIGHT6, GL_SPOT_DIRECTION, &[0.0, 0.0, -1.0]);
    assert_approx_eq!(
        get_light(GL_LIGHT6, GL_SPOT_DIRECTION, 3),
        [0.0, 1.0, 0.0f32]
    );
    light_iv(GL_LIGHT7, GL_SPOT_DIRECTION, &[0, 2, 0]);
    assert_approx_eq!(
        get_light(GL_LIGHT7, GL_SPOT_DIRECTION, 3),
        [0.0, 0.0, 2.0f32]
    );
    expect_no_error("spot direction");
}

#[test]
fn spot_exponent_accepts_0_to_128_only() {
    let _ctx = fresh();
    for good in [0.0, 0.5, 64.0, 128.0] {
        glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, good);
        expect_no_error(&format!("spot exponent {good}"));
        assert_eq!(get_light(GL_LIGHT1, GL_SPOT_EXPONENT, 1), [good]);
    }
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 20.0);
    for bad in [-0.001, -1.0, 128.001, 200.0, f32::NAN, f32::INFINITY] {
        glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, bad);
        expect_error(GL_INVALID_VALUE, &format!("spot exponent {bad}"));
        light_fv(GL_LIGHT1, GL_SPOT_EXPONENT, &[bad]);
        expect_error(GL_INVALID_VALUE, &format!("spot exponent fv {bad}"));
        assert_eq!(
            get_light(GL_LIGHT1, GL_SPOT_EXPONENT, 1),
            [20.0],
            "after {bad}"
        );
    }
    glLighti(GL_LIGHT1, GL_SPOT_EXPONENT, 129);
    expect_error(GL_INVALID_VALUE, "glLighti exponent 129");
    light_iv(GL_LIGHT1, GL_SPOT_EXPONENT, &[-1]);
    expect_error(GL_INVALID_VALUE, "glLightiv exponent -1");
    assert_eq!(get_light(GL_LIGHT1, GL_SPOT_EXPONENT, 1), [20.0]);
}

#[test]
fn spot_cutoff_accepts_0_to_90_and_180_only() {
    let _ctx = fresh();
    for good in [0.0, 45.5, 90.0, 180.0] {
        glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, good);
        expect_no_error(&format!("cutoff {good}"));
        assert_eq!(get_light(GL_LIGHT2, GL_SPOT_CUTOFF, 1), [good]);
    }
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 30.0);
    for bad in [
        -0.001,
        -90.0,
        90.001,
        91.0,
        179.999,
        180.001,
        360.0,
        f32::NAN,
    ] {
        glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, bad);
        expect_error(GL_INVALID_VALUE, &format!("cutoff {bad}"));
        light_fv(GL_LIGHT2, GL_SPOT_CUTOFF, &[bad]);
        expect_error(GL_INVALID_VALUE, &format!("cutoff fv {bad}"));
        assert_eq!(
            get_light(GL_LIGHT2, GL_SPOT_CUTOFF, 1),
            [30.0],
            "after {bad}"
        );
    }
    glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, 179);
    expect_error(GL_INVALID_VALUE, "glLighti cutoff 179");
    glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, 180);
    expect_no_error("glLighti cutoff 180");
    assert_eq!(get_light(GL_LIGHT2, GL_SPOT_CUTOFF, 1), [180.0]);
}

#[test]
fn attenuations_must_not_be_negative() {
    let _ctx = fresh();
    for pname in [
        GL_CONSTANT_ATTENUATION,
        GL_LINEAR_ATTENUATION,
        GL_QUADRATIC_ATTENUATION,
    ] {
        glLightf(GL_LIGHT3, pname, 0.0);
        expect_no_error("attenuation 0");
        glLightf(GL_LIGHT3, pname, 1e6);
        expect_no_error("attenuation 1e6");
        glLightf(GL_LIGHT3, pname, 2.5);
        for bad in [-1e-6, -1.0, f32::NEG_INFINITY, f32::NAN] {
            glLightf(GL_LIGHT3, pname, bad);
            expect_error(GL_INVALID_VALUE, &format!("attenuation {pname:#x} = {bad}"));
            light_fv(GL_LIGHT3, pname, &[bad]);
            expect_error(
                GL_INVALID_VALUE,
                &format!("attenuation fv {pname:#x} = {bad}"),
            );
        }
        glLighti(GL_LIGHT3, pname, -3);
        expect_error(GL_INVALID_VALUE, "glLighti attenuation -3");
        assert_eq!(get_light(GL_LIGHT3, pname, 1), [2.5]);
    }
}

#[test]
fn integer_colors_map_linearly_from_the_signed_range() {
    let _ctx = fresh();
    light_iv(GL_LIGHT5, GL_AMBIENT, &[i32::MAX, i32::MIN, 0, 1 << 30]);
    let want = [1.0, -1.0, int_color(0), int_color(1 << 30)];
    assert_approx_eq!(get_light(GL_LIGHT5, GL_AMBIENT, 4), want, 1e-7);
    // (2c + 1) / (2^32 - 1): 0 is not exactly 0, 2^30 is just over 0.5
    assert!(int_color(0) > 0.0 && int_color(0) < 1e-9);
    assert_approx_eq!(int_color(1 << 30), 0.5f64, 1e-9);

    light_iv(GL_LIGHT5, GL_DIFFUSE, &[-(1 << 29), 1 << 29, i32::MAX, -1]);
    assert_approx_eq!(
        get_light(GL_LIGHT5, GL_DIFFUSE, 4),
        [-0.25, 0.25, 1.0, int_color(-1)],
        1e-7
    );
    light_iv(
        GL_LIGHT5,
        GL_SPECULAR,
        &[i32::MAX, i32::MAX, i32::MAX, i32::MAX],
    );
    assert_eq!(get_light(GL_LIGHT5, GL_SPECULAR, 4), [1.0; 4]);
    expect_no_error("glLightiv colors");
}

#[test]
fn get_light_iv_maps_colors_linearly_and_rounds_the_rest() {
    let _ctx = fresh();
    // §6.1.2: 1.0 -> the most positive integer, -1.0 -> the most negative, linearly:
    // ((2^32 - 1) c - 1) / 2. 0.25 -> 536870911.375, -0.5 -> -1073741824.25.
    light_fv(GL_LIGHT1, GL_DIFFUSE, &[-1.0, 1.0, 0.25, -0.5]);
    assert_eq!(
        get_light_i(GL_LIGHT1, GL_DIFFUSE, 4),
        [i32::MIN, i32::MAX, 536_870_911, -1_073_741_824]
    );
    // out of range colors clamp to the integer range
    light_fv(GL_LIGHT1, GL_AMBIENT, &[2.0, -3.0, 1.0, 1.0]);
    assert_eq!(
        get_light_i(GL_LIGHT1, GL_AMBIENT, 4)[..2],
        [i32::MAX, i32::MIN]
    );
    // small integer colors survive the round trip
    light_iv(GL_LIGHT1, GL_SPECULAR, &[12345, -777, i32::MAX, i32::MIN]);
    assert_eq!(
        get_light_i(GL_LIGHT1, GL_SPECULAR, 4),
        [12345, -777, i32::MAX, i32::MIN]
    );

    // everything else rounds to the nearest integer (not truncated)
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 2.75);
    assert_eq!(get_light_i(GL_LIGHT1, GL_SPOT_EXPONENT, 1), [3]);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 2.25);
    assert_eq!(get_light_i(GL_LIGHT1, GL_SPOT_EXPONENT, 1), [2]);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 44.6);
    assert_eq!(get_light_i(GL_LIGHT1, GL_SPOT_CUTOFF, 1), [45]);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.7);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 1.3);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 99.9);
    assert_eq!(get_light_i(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 1), [1]);
    assert_eq!(get_light_i(GL_LIGHT1, GL_LINEAR_ATTENUATION, 1), [1]);
    assert_eq!(get_light_i(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 1), [100]);
    light_fv(GL_LIGHT1, GL_POSITION, &[1.4, -2.6, 3.49, 0.51]);
    assert_eq!(get_light_i(GL_LIGHT1, GL_POSITION, 4), [1, -3, 3, 1]);
    light_fv(GL_LIGHT1, GL_SPOT_DIRECTION, &[0.4, -0.6, -1.7]);
    assert_eq!(get_light_i(GL_LIGHT1, GL_SPOT_DIRECTION, 3), [0, -1, -2]);
    expect_no_error("glGetLightiv");
}

#[test]
fn bad_light_numbers_are_invalid_enum() {
    let _ctx = fresh();
    let before = light_state(GL_LIGHT0);
    for bad in [GL_LIGHT0 + 8, GL_LIGHT0 - 1, 0, 0x1234, u32::MAX] {
        glLightf(bad, GL_SPOT_EXPONENT, 1.0);
        expect_error(GL_INVALID_ENUM, "glLightf bad light");
        glLighti(bad, GL_SPOT_EXPONENT, 1);
        expect_error(GL_INVALID_ENUM, "glLighti bad light");
        light_fv(bad, GL_AMBIENT, &[0.5; 4]);
        expect_error(GL_INVALID_ENUM, "glLightfv bad light");
        light_iv(bad, GL_AMBIENT, &[5; 4]);
        expect_error(GL_INVALID_ENUM, "glLightiv bad light");
        let mut v = [SENTINEL_F; 4];
        // SAFETY: room for four values.
        unsafe { glGetLightfv(bad, GL_AMBIENT, v.as_mut_ptr()) };
        expect_error(GL_INVALID_ENUM, "glGetLightfv bad light");
        assert_eq!(v, [SENTINEL_F; 4], "glGetLightfv wrote on an error");
        let mut iv = [SENTINEL_I; 4];
        // SAFETY: room for four values.
        unsafe { glGetLightiv(bad, GL_AMBIENT, iv.as_mut_ptr()) };
        expect_error(GL_INVALID_ENUM, "glGetLightiv bad light");
        assert_eq!(iv, [SENTINEL_I; 4], "glGetLightiv wrote on an error");
    }
    assert_eq!(light_state(GL_LIGHT0), before);
}

#[test]
fn bad_pnames_are_invalid_enum() {
    let _ctx = fresh();
    let before = light_state(GL_LIGHT2);
    for bad in [
        GL_SHININESS,
        GL_EMISSION,
        GL_AMBIENT_AND_DIFFUSE,
        GL_LIGHTING,
        0x1234,
    ] {
        glLightf(GL_LIGHT2, bad, 1.0);
        expect_error(GL_INVALID_ENUM, "glLightf bad pname");
        glLighti(GL_LIGHT2, bad, 1);
        expect_error(GL_INVALID_ENUM, "glLighti bad pname");
        light_fv(GL_LIGHT2, bad, &[1.0; 4]);
        expect_error(GL_INVALID_ENUM, "glLightfv bad pname");
        light_iv(GL_LIGHT2, bad, &[1; 4]);
        expect_error(GL_INVALID_ENUM, "glLightiv bad pname");
        let mut v = [SENTINEL_F; 4];
        // SAFETY: room for four values.
        unsafe { glGetLightfv(GL_LIGHT2, bad, v.as_mut_ptr()) };
        expect_error(GL_INVALID_ENUM, "glGetLightfv bad pname");
        assert_eq!(v, [SENTINEL_F; 4]);
        let mut iv = [SENTINEL_I; 4];
        // SAFETY: room for four values.
        unsafe { glGetLightiv(GL_LIGHT2, bad, iv.as_mut_ptr()) };
        expect_error(GL_INVALID_ENUM, "glGetLightiv bad pname");
        assert_eq!(iv, [SENTINEL_I; 4]);
    }
    assert_eq!(light_state(GL_LIGHT2), before);
}

#[test]
fn scalar_forms_reject_multi_valued_pnames() {
    // §2.14.2: "If param corresponds to a multi-valued parameter, the error INVALID_ENUM
    // results."
    let _ctx = fresh();
    let before = light_state(GL_LIGHT0);
    for pname in [
        GL_AMBIENT,
        GL_DIFFUSE,
        GL_SPECULAR,
        GL_POSITION,
        GL_SPOT_DIRECTION,
    ] {
        glLightf(GL_LIGHT0, pname, 0.5);
        expect_error(GL_INVALID_ENUM, "glLightf multi-valued");
        glLighti(GL_LIGHT0, pname, 1);
        expect_error(GL_INVALID_ENUM, "glLighti multi-valued");
    }
    assert_eq!(light_state(GL_LIGHT0), before);
}

#[test]
fn errors_follow_mesa_order_light_then_pname_then_value() {
    let _ctx = fresh();
    // bad light and bad value: the light is reported
    glLightf(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, 500.0);
    expect_error(GL_INVALID_ENUM, "bad light + bad value");
    // bad light and bad pname
    glLightf(GL_LIGHT0 + 8, 0x1234, 1.0);
    expect_error(GL_INVALID_ENUM, "bad light + bad pname");
    // bad pname and a value that would be out of range for any scalar pname
    glLightf(GL_LIGHT0, 0x1234, -1.0);
    expect_error(GL_INVALID_ENUM, "bad pname + bad value");
    // bad light with a NULL pointer: the enum comes first
    // SAFETY: NULL is allowed and must be reported, never read.
    unsafe { glLightfv(GL_LIGHT0 + 8, GL_AMBIENT, std::ptr::null()) };
    expect_error(GL_INVALID_ENUM, "bad light + NULL");
    // SAFETY: as above.
    unsafe { glLightfv(GL_LIGHT0, 0x1234, std::ptr::null()) };
    expect_error(GL_INVALID_ENUM, "bad pname + NULL");
    // SAFETY: as above.
    unsafe { glGetLightfv(GL_LIGHT0 + 8, GL_AMBIENT, std::ptr::null_mut()) };
    expect_error(GL_INVALID_ENUM, "get: bad light + NULL");
}

#[test]
fn null_params_are_invalid_value_and_change_nothing() {
    let _ctx = fresh();
    let before = light_state(GL_LIGHT0);
    for &(pname, _) in &LIGHT_PNAMES {
        // SAFETY: NULL is allowed and must be reported, never dereferenced.
        unsafe {
            glLightfv(GL_LIGHT0, pname, std::ptr::null());
            expect_error(GL_INVALID_VALUE, "glLightfv NULL");
            glLightiv(GL_LIGHT0, pname, std::ptr::null());
            expect_error(GL_INVALID_VALUE, "glLightiv NULL");
            glGetLightfv(GL_LIGHT0, pname, std::ptr::null_mut());
            expect_error(GL_INVALID_VALUE, "glGetLightfv NULL");
            glGetLightiv(GL_LIGHT0, pname, std::ptr::null_mut());
            expect_error(GL_INVALID_VALUE, "glGetLightiv NULL");
        }
    }
    assert_eq!(light_state(GL_LIGHT0), before);
}

#[test]
fn light_commands_between_begin_and_end_are_invalid_operation() {
    let _ctx = fresh();
    let before = light_state(GL_LIGHT1);
    glBegin(GL_POINTS);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 5.0);
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glLightf in begin/end");
    glBegin(GL_POINTS);
    glLighti(GL_LIGHT1, GL_SPOT_CUTOFF, 5);
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glLighti in begin/end");
    glBegin(GL_POINTS);
    light_fv(GL_LIGHT1, GL_POSITION, &[1.0, 2.0, 3.0, 1.0]);
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glLightfv in begin/end");
    glBegin(GL_POINTS);
    light_iv(GL_LIGHT1, GL_DIFFUSE, &[1, 2, 3, 4]);
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glLightiv in begin/end");
    glBegin(GL_POINTS);
    let mut v = [SENTINEL_F; 4];
    // SAFETY: room for four values.
    unsafe { glGetLightfv(GL_LIGHT1, GL_DIFFUSE, v.as_mut_ptr()) };
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glGetLightfv in begin/end");
    assert_eq!(v, [SENTINEL_F; 4]);
    glBegin(GL_POINTS);
    let mut iv = [SENTINEL_I; 4];
    // SAFETY: room for four values.
    unsafe { glGetLightiv(GL_LIGHT1, GL_DIFFUSE, iv.as_mut_ptr()) };
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glGetLightiv in begin/end");
    assert_eq!(iv, [SENTINEL_I; 4]);
    assert_eq!(light_state(GL_LIGHT1), before);
}

#[test]
fn through_the_safe_context_api() {
    use fflight::{Context, GlError};
    let mut ctx = Context::new();
    assert_eq!(
        ctx.get_light(GL_LIGHT0, GL_DIFFUSE).unwrap().0.to_array(),
        [1.0; 4]
    );
    ctx.translate(0.0, 0.0, 2.0).unwrap();
    ctx.light(GL_LIGHT7, GL_POSITION, &[0.0, 0.0, 0.0, 1.0])
        .unwrap();
    let (position, count) = ctx.get_light(GL_LIGHT7, GL_POSITION).unwrap();
    assert_eq!((position.to_array(), count), ([0.0, 0.0, 2.0, 1.0], 4));
    assert_eq!(
        ctx.light_scalar(GL_LIGHT0 + 8, GL_SPOT_CUTOFF, 200.0),
        Err(GlError::InvalidEnum)
    );
    assert_eq!(
        ctx.light_scalar(GL_LIGHT0, GL_SPOT_CUTOFF, 200.0),
        Err(GlError::InvalidValue)
    );
    assert_eq!(
        ctx.light(GL_LIGHT0, GL_AMBIENT, &[1.0, 2.0]),
        Err(GlError::InvalidValue),
        "too few values"
    );
    assert_eq!(
        ctx.get_light_i(GL_LIGHT0, GL_SPOT_CUTOFF).unwrap(),
        ([180, 0, 0, 0], 1)
    );
    // a Context's methods return errors; only settle() records them
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let result = ctx.light_scalar(GL_LIGHT0, GL_SPOT_EXPONENT, -1.0);
    ctx.settle(result);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
}

// ---- glLightModel ----

#[test]
fn light_model_defaults() {
    let _ctx = fresh();
    assert_eq!(get_floats(GL_LIGHT_MODEL_AMBIENT, 4), [0.2, 0.2, 0.2, 1.0]);
    assert_eq!(get_bools(GL_LIGHT_MODEL_LOCAL_VIEWER, 1), [GL_FALSE]);
    assert_eq!(get_bools(GL_LIGHT_MODEL_TWO_SIDE, 1), [GL_FALSE]);
    assert_eq!(
        get_int(GL_LIGHT_MODEL_COLOR_CONTROL),
        GL_SINGLE_COLOR as i32
    );
    expect_no_error("light model defaults");
}

#[test]
fn light_model_round_trips_through_every_form() {
    let _ctx = fresh();
    light_model_fv(GL_LIGHT_MODEL_AMBIENT, &[0.1, -0.5, 1.5, 0.25]);
    assert_eq!(
        get_floats(GL_LIGHT_MODEL_AMBIENT, 4),
        [0.1, -0.5, 1.5, 0.25]
    );
    assert_approx_eq!(
        get_doubles(GL_LIGHT_MODEL_AMBIENT, 4),
        [0.1, -0.5, 1.5, 0.25f64]
    );

    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    assert_eq!(get_bools(GL_LIGHT_MODEL_LOCAL_VIEWER, 1), [GL_TRUE]);
    glLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, 0.0);
    assert_eq!(get_bools(GL_LIGHT_MODEL_LOCAL_VIEWER, 1), [GL_FALSE]);
    // any nonzero value is true
    glLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, 0.25);
    assert_eq!(get_ints(GL_LIGHT_MODEL_LOCAL_VIEWER, 1), [1]);

    light_model_iv(GL_LIGHT_MODEL_TWO_SIDE, &[-7]);
    assert_eq!(get_bools(GL_LIGHT_MODEL_TWO_SIDE, 1), [GL_TRUE]);
    assert_eq!(get_floats(GL_LIGHT_MODEL_TWO_SIDE, 1), [1.0]);
    light_model_fv(GL_LIGHT_MODEL_TWO_SIDE, &[0.0]);
    assert_eq!(get_bools(GL_LIGHT_MODEL_TWO_SIDE, 1), [GL_FALSE]);

    glLightModeli(
        GL_LIGHT_MODEL_COLOR_CONTROL,
        GL_SEPARATE_SPECULAR_COLOR as i32,
    );
    assert_eq!(
        get_int(GL_LIGHT_MODEL_COLOR_CONTROL),
        GL_SEPARATE_SPECULAR_COLOR as i32
    );
    assert_eq!(
        get_floats(GL_LIGHT_MODEL_COLOR_CONTROL, 1),
        [GL_SEPARATE_SPECULAR_COLOR as f32]
    );
    light_model_fv(GL_LIGHT_MODEL_COLOR_CONTROL, &[GL_SINGLE_COLOR as f32]);
    assert_eq!(
        get_int(GL_LIGHT_MODEL_COLOR_CONTROL),
        GL_SINGLE_COLOR as i32
    );
    expect_no_error("light model");
}

#[test]
fn light_model_integer_ambient_maps_linearly_both_ways() {
    let _ctx = fresh();
    light_model_iv(GL_LIGHT_MODEL_AMBIENT, &[i32::MAX, i32::MIN, 1 << 29, 0]);
    assert_approx_eq!(
        get_floats(GL_LIGHT_MODEL_AMBIENT, 4),
        [1.0, -1.0, 0.25, int_color(0)],
        1e-7
    );
    light_model_fv(GL_LIGHT_MODEL_AMBIENT, &[1.0, -1.0, 0.25, -0.5]);
    assert_eq!(
        get_ints(GL_LIGHT_MODEL_AMBIENT, 4),
        [i32::MAX, i32::MIN, 536_870_911, -1_073_741_824]
    );
    expect_no_error("light model ambient ints");
}

#[test]
fn light_model_errors_leave_the_state_alone() {
    let _ctx = fresh();
    light_model_fv(GL_LIGHT_MODEL_AMBIENT, &[0.5, 0.5, 0.5, 0.5]);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);

    for bad in [0x1234, GL_AMBIENT, GL_LIGHT_MODEL_COLOR_CONTROL + 1] {
        glLightModelf(bad, 1.0);
        expect_error(GL_INVALID_ENUM, "glLightModelf bad pname");
        glLightModeli(bad, 1);
        expect_error(GL_INVALID_ENUM, "glLightModeli bad pname");
        light_model_fv(bad, &[1.0; 4]);
        expect_error(GL_INVALID_ENUM, "glLightModelfv bad pname");
        light_model_iv(bad, &[1; 4]);
        expect_error(GL_INVALID_ENUM, "glLightModeliv bad pname");
    }
    // a bad color control value is an enum error
    for bad in [GL_FRONT as f32, 0.0, GL_SINGLE_COLOR as f32 + 0.5, f32::NAN] {
        glLightModelf(GL_LIGHT_MODEL_COLOR_CONTROL, bad);
        expect_error(GL_INVALID_ENUM, &format!("color control {bad}"));
    }
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FRONT as i32);
    expect_error(GL_INVALID_ENUM, "color control GL_FRONT (int)");
    // the ambient color has four values: the scalar forms refuse it
    glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.0);
    expect_error(GL_INVALID_ENUM, "glLightModelf(GL_LIGHT_MODEL_AMBIENT)");
    glLightModeli(GL_LIGHT_MODEL_AMBIENT, 0);
    expect_error(GL_INVALID_ENUM, "glLightModeli(GL_LIGHT_MODEL_AMBIENT)");
    // NULL
    for pname in [
        GL_LIGHT_MODEL_AMBIENT,
        GL_LIGHT_MODEL_LOCAL_VIEWER,
        GL_LIGHT_MODEL_TWO_SIDE,
        GL_LIGHT_MODEL_COLOR_CONTROL,
    ] {
        // SAFETY: NULL is allowed and must be reported, never dereferenced.
        unsafe { glLightModelfv(pname, std::ptr::null()) };
        expect_error(GL_INVALID_VALUE, "glLightModelfv NULL");
        // SAFETY: as above.
        unsafe { glLightModeliv(pname, std::ptr::null()) };
        expect_error(GL_INVALID_VALUE, "glLightModeliv NULL");
    }
    // SAFETY: as above; the bad pname is reported first.
    unsafe { glLightModelfv(0x1234, std::ptr::null()) };
    expect_error(GL_INVALID_ENUM, "glLightModelfv bad pname + NULL");
    // inside glBegin/glEnd
    glBegin(GL_POINTS);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
    light_model_fv(GL_LIGHT_MODEL_AMBIENT, &[0.0; 4]);
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glLightModel in begin/end");

    assert_eq!(get_floats(GL_LIGHT_MODEL_AMBIENT, 4), [0.5; 4]);
    assert_eq!(get_bools(GL_LIGHT_MODEL_TWO_SIDE, 1), [GL_TRUE]);
    assert_eq!(get_bools(GL_LIGHT_MODEL_LOCAL_VIEWER, 1), [GL_FALSE]);
    assert_eq!(
        get_int(GL_LIGHT_MODEL_COLOR_CONTROL),
        GL_SINGLE_COLOR as i32
    );
}
