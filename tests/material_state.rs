//! glMaterial{f,i}[v], glGetMaterial{f,i}v and glColorMaterial: defaults, faces,
//! GL_AMBIENT_AND_DIFFUSE, GL_COLOR_INDEXES, the shininess range, the integer conversions,
//! color material tracking and every error (OpenGL 1.5 §2.14.1-2.14.3, §6.1.2, tables 2.11,
//! 6.9-6.10).

#[macro_use]
mod common;

use common::*;

const FACES: [GLenum; 2] = [GL_FRONT, GL_BACK];

/// Every glGetMaterial pname and its value count.
const MATERIAL_PNAMES: [(GLenum, usize); 6] = [
    (GL_AMBIENT, 4),
    (GL_DIFFUSE, 4),
    (GL_SPECULAR, 4),
    (GL_EMISSION, 4),
    (GL_SHININESS, 1),
    (GL_COLOR_INDEXES, 3),
];

/// Both faces' material, as glGetMaterialfv reports it.
fn materials() -> Vec<Vec<f32>> {
    FACES
        .iter()
        .flat_map(|&face| {
            MATERIAL_PNAMES
                .iter()
                .map(move |&(pname, n)| get_material(face, pname, n))
        })
        .collect()
}

fn color(face: GLenum, pname: GLenum) -> Vec<f32> {
    get_material(face, pname, 4)
}

#[test]
fn both_faces_start_with_the_table_2_11_defaults() {
    let _ctx = fresh();
    for face in FACES {
        assert_eq!(color(face, GL_AMBIENT), [0.2, 0.2, 0.2, 1.0]);
        assert_eq!(color(face, GL_DIFFUSE), [0.8, 0.8, 0.8, 1.0]);
        assert_eq!(color(face, GL_SPECULAR), [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(color(face, GL_EMISSION), [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(get_material(face, GL_SHININESS, 1), [0.0]);
        assert_eq!(get_material(face, GL_COLOR_INDEXES, 3), [0.0, 1.0, 1.0]);
        assert_eq!(get_material_i(face, GL_COLOR_INDEXES, 3), [0, 1, 1]);
        assert_eq!(get_material_i(face, GL_SPECULAR, 4)[3], i32::MAX);
    }
    expect_no_error("material defaults");
}

#[test]
fn each_face_argument_sets_only_its_faces() {
    let _ctx = fresh();
    for pname in [GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION] {
        let front = [0.1, 0.2, 0.3, 0.4];
        let back = [0.9, -0.8, 1.7, 0.6];
        let both = [0.5, 0.25, 0.125, 1.0];
        material_fv(GL_FRONT, pname, &front);
        assert_eq!(color(GL_FRONT, pname), front);
        material_fv(GL_BACK, pname, &back);
        assert_eq!(color(GL_BACK, pname), back);
        assert_eq!(color(GL_FRONT, pname), front, "GL_BACK changed the front");
        material_fv(GL_FRONT_AND_BACK, pname, &both);
        assert_eq!(color(GL_FRONT, pname), both);
        assert_eq!(color(GL_BACK, pname), both);
    }
    glMaterialf(GL_FRONT, GL_SHININESS, 10.0);
    glMaterialf(GL_BACK, GL_SHININESS, 20.0);
    assert_eq!(get_material(GL_FRONT, GL_SHININESS, 1), [10.0]);
    assert_eq!(get_material(GL_BACK, GL_SHININESS, 1), [20.0]);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0);
    assert_eq!(get_material(GL_FRONT, GL_SHININESS, 1), [30.0]);
    assert_eq!(get_material(GL_BACK, GL_SHININESS, 1), [30.0]);
    expect_no_error("faces");
}

#[test]
fn ambient_and_diffuse_sets_both_properties() {
    let _ctx = fresh();
    material_fv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, &[0.3, 0.4, 0.5, 0.6]);
    assert_eq!(color(GL_BACK, GL_AMBIENT), [0.3, 0.4, 0.5, 0.6]);
    assert_eq!(color(GL_BACK, GL_DIFFUSE), [0.3, 0.4, 0.5, 0.6]);
    assert_eq!(color(GL_BACK, GL_SPECULAR), [0.0, 0.0, 0.0, 1.0]);
    assert_eq!(color(GL_FRONT, GL_AMBIENT), [0.2, 0.2, 0.2, 1.0]);
    material_iv(
        GL_FRONT_AND_BACK,
        GL_AMBIENT_AND_DIFFUSE,
        &[i32::MAX, 0, i32::MIN, i32::MAX],
    );
    for face in FACES {
        for pname in [GL_AMBIENT, GL_DIFFUSE] {
            assert_approx_eq!(color(face, pname), [1.0, int_color(0), -1.0, 1.0], 1e-7);
        }
    }
    expect_no_error("ambient and diffuse");
}

#[test]
fn color_indexes_take_three_values_converted_directly() {
    let _ctx = fresh();
    material_fv(GL_FRONT, GL_COLOR_INDEXES, &[2.0, 5.5, 9.0]);
    assert_eq!(get_material(GL_FRONT, GL_COLOR_INDEXES, 3), [2.0, 5.5, 9.0]);
    assert_eq!(get_material(GL_BACK, GL_COLOR_INDEXES, 3), [0.0, 1.0, 1.0]);
    material_iv(GL_BACK, GL_COLOR_INDEXES, &[3, 4, 200]);
    assert_eq!(
        get_material(GL_BACK, GL_COLOR_INDEXES, 3),
        [3.0, 4.0, 200.0]
    );
    // glMaterialfv reads exactly three values: a fourth (garbage) value is never read, so a
    // three-element array is enough
    let three = [7.0f32, 8.0, 9.0];
    // SAFETY: GL_COLOR_INDEXES reads three values.
    unsafe { glMaterialfv(GL_FRONT_AND_BACK, GL_COLOR_INDEXES, three.as_ptr()) };
    assert_eq!(get_material(GL_BACK, GL_COLOR_INDEXES, 3), [7.0, 8.0, 9.0]);
    // integer query rounds
    material_fv(GL_FRONT, GL_COLOR_INDEXES, &[1.4, 2.6, 3.3]);
    assert_eq!(get_material_i(GL_FRONT, GL_COLOR_INDEXES, 3), [1, 3, 3]);
    expect_no_error("color indexes");
}

#[test]
fn shininess_accepts_0_to_128_only() {
    let _ctx = fresh();
    for good in [0.0, 0.5, 64.0, 128.0] {
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, good);
        expect_no_error(&format!("shininess {good}"));
        assert_eq!(get_material(GL_BACK, GL_SHININESS, 1), [good]);
    }
    glMaterialf(GL_FRONT, GL_SHININESS, 12.0);
    glMaterialf(GL_BACK, GL_SHININESS, 24.0);
    for bad in [-0.001, -1.0, 128.001, 1000.0, f32::NAN, f32::INFINITY] {
        for face in [GL_FRONT, GL_BACK, GL_FRONT_AND_BACK] {
            glMaterialf(face, GL_SHININESS, bad);
            expect_error(GL_INVALID_VALUE, &format!("shininess {bad}"));
            material_fv(face, GL_SHININESS, &[bad]);
            expect_error(GL_INVALID_VALUE, &format!("shininess fv {bad}"));
        }
    }
    glMateriali(GL_FRONT, GL_SHININESS, 129);
    expect_error(GL_INVALID_VALUE, "glMateriali shininess 129");
    material_iv(GL_FRONT, GL_SHININESS, &[-1]);
    expect_error(GL_INVALID_VALUE, "glMaterialiv shininess -1");
    assert_eq!(get_material(GL_FRONT, GL_SHININESS, 1), [12.0]);
    assert_eq!(get_material(GL_BACK, GL_SHININESS, 1), [24.0]);
    glMateriali(GL_FRONT, GL_SHININESS, 77);
    material_iv(GL_BACK, GL_SHININESS, &[128]);
    assert_eq!(get_material(GL_FRONT, GL_SHININESS, 1), [77.0]);
    assert_eq!(get_material(GL_BACK, GL_SHININESS, 1), [128.0]);
    expect_no_error("shininess ints");
}

#[test]
fn integer_colors_map_linearly_and_integer_queries_invert_it() {
    let _ctx = fresh();
    material_iv(
        GL_FRONT,
        GL_EMISSION,
        &[1 << 29, -(1 << 29), i32::MAX, i32::MIN],
    );
    assert_approx_eq!(color(GL_FRONT, GL_EMISSION), [0.25, -0.25, 1.0, -1.0], 1e-7);
    material_iv(GL_BACK, GL_SPECULAR, &[12345, -777, 0, i32::MAX]);
    assert_eq!(
        get_material_i(GL_BACK, GL_SPECULAR, 4),
        [12345, -777, 0, i32::MAX]
    );
    material_fv(GL_FRONT, GL_DIFFUSE, &[-1.0, 1.0, 0.25, -0.5]);
    assert_eq!(
        get_material_i(GL_FRONT, GL_DIFFUSE, 4),
        [i32::MIN, i32::MAX, 536_870_911, -1_073_741_824]
    );
    // shininess rounds to the nearest integer
    glMaterialf(GL_FRONT, GL_SHININESS, 12.75);
    assert_eq!(get_material_i(GL_FRONT, GL_SHININESS, 1), [13]);
    glMaterialf(GL_FRONT, GL_SHININESS, 12.25);
    assert_eq!(get_material_i(GL_FRONT, GL_SHININESS, 1), [12]);
    expect_no_error("integer material");
}

#[test]
fn scalar_forms_take_shininess_only() {
    let _ctx = fresh();
    let before = materials();
    for pname in [
        GL_AMBIENT,
        GL_DIFFUSE,
        GL_SPECULAR,
        GL_EMISSION,
        GL_AMBIENT_AND_DIFFUSE,
        GL_COLOR_INDEXES,
    ] {
        glMaterialf(GL_FRONT, pname, 0.5);
        expect_error(GL_INVALID_ENUM, &format!("glMaterialf {pname:#x}"));
        glMateriali(GL_FRONT, pname, 1);
        expect_error(GL_INVALID_ENUM, &format!("glMateriali {pname:#x}"));
    }
    assert_eq!(materials(), before);
}

#[test]
fn material_errors_are_face_then_pname_then_value() {
    let _ctx = fresh();
    let before = materials();
    const GL_LEFT: GLenum = 0x0406;
    for bad_face in [GL_LEFT, 0, GL_FRONT_AND_BACK + 1, 0x1234] {
        material_fv(bad_face, GL_AMBIENT, &[0.5; 4]);
        expect_error(GL_INVALID_ENUM, "glMaterialfv bad face");
        material_iv(bad_face, GL_AMBIENT, &[5; 4]);
        expect_error(GL_INVALID_ENUM, "glMaterialiv bad face");
        glMaterialf(bad_face, GL_SHININESS, 5.0);
        expect_error(GL_INVALID_ENUM, "glMaterialf bad face");
        glMateriali(bad_face, GL_SHININESS, 5);
        expect_error(GL_INVALID_ENUM, "glMateriali bad face");
        // a bad face with a bad value: the face is reported
        glMaterialf(bad_face, GL_SHININESS, 500.0);
        expect_error(GL_INVALID_ENUM, "bad face + bad shininess");
    }
    for bad_pname in [GL_POSITION, GL_SPOT_CUTOFF, GL_LIGHTING, 0x1234] {
        material_fv(GL_FRONT, bad_pname, &[0.5; 4]);
        expect_error(GL_INVALID_ENUM, "glMaterialfv bad pname");
        material_iv(GL_BACK, bad_pname, &[5; 4]);
        expect_error(GL_INVALID_ENUM, "glMaterialiv bad pname");
        glMaterialf(GL_FRONT_AND_BACK, bad_pname, -5.0);
        expect_error(GL_INVALID_ENUM, "glMaterialf bad pname + bad value");
    }
    // NULL pointers
    for &(pname, _) in &MATERIAL_PNAMES {
        // SAFETY: NULL is allowed and must be reported, never dereferenced.
        unsafe {
            glMaterialfv(GL_FRONT, pname, std::ptr::null());
            expect_error(GL_INVALID_VALUE, "glMaterialfv NULL");
            glMaterialiv(GL_FRONT_AND_BACK, pname, std::ptr::null());
            expect_error(GL_INVALID_VALUE, "glMaterialiv NULL");
            glGetMaterialfv(GL_FRONT, pname, std::ptr::null_mut());
            expect_error(GL_INVALID_VALUE, "glGetMaterialfv NULL");
            glGetMaterialiv(GL_BACK, pname, std::ptr::null_mut());
            expect_error(GL_INVALID_VALUE, "glGetMaterialiv NULL");
        }
    }
    // SAFETY: as above; the bad face is reported first.
    unsafe { glMaterialfv(GL_LEFT, GL_AMBIENT, std::ptr::null()) };
    expect_error(GL_INVALID_ENUM, "bad face + NULL");
    assert_eq!(materials(), before);
}

#[test]
fn get_material_takes_one_face_and_one_property() {
    let _ctx = fresh();
    // GL_FRONT_AND_BACK names two values: the query refuses it
    for (pname, _) in MATERIAL_PNAMES {
        let mut v = [SENTINEL_F; 4];
        // SAFETY: room for four values.
        unsafe { glGetMaterialfv(GL_FRONT_AND_BACK, pname, v.as_mut_ptr()) };
        expect_error(GL_INVALID_ENUM, "glGetMaterialfv(GL_FRONT_AND_BACK)");
        assert_eq!(v, [SENTINEL_F; 4]);
        let mut iv = [SENTINEL_I; 4];
        // SAFETY: room for four values.
        unsafe { glGetMaterialiv(GL_FRONT_AND_BACK, pname, iv.as_mut_ptr()) };
        expect_error(GL_INVALID_ENUM, "glGetMaterialiv(GL_FRONT_AND_BACK)");
        assert_eq!(iv, [SENTINEL_I; 4]);
    }
    for bad in [GL_AMBIENT_AND_DIFFUSE, GL_POSITION, 0x1234] {
        let mut v = [SENTINEL_F; 4];
        // SAFETY: room for four values.
        unsafe { glGetMaterialfv(GL_FRONT, bad, v.as_mut_ptr()) };
        expect_error(GL_INVALID_ENUM, &format!("glGetMaterialfv pname {bad:#x}"));
        assert_eq!(v, [SENTINEL_F; 4]);
        let mut iv = [SENTINEL_I; 4];
        // SAFETY: room for four values.
        unsafe { glGetMaterialiv(GL_BACK, bad, iv.as_mut_ptr()) };
        expect_error(GL_INVALID_ENUM, &format!("glGetMaterialiv pname {bad:#x}"));
    }
    let mut v = [SENTINEL_F; 4];
    // SAFETY: room for four values.
    unsafe { glGetMaterialfv(0x0406, GL_AMBIENT, v.as_mut_ptr()) };
    expect_error(GL_INVALID_ENUM, "glGetMaterialfv(GL_LEFT)");
    // SAFETY: NULL must be reported after the enum checks.
    unsafe { glGetMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, std::ptr::null_mut()) };
    expect_error(GL_INVALID_ENUM, "GL_FRONT_AND_BACK + NULL");
}

#[test]
fn material_is_legal_between_begin_and_end() {
    let _ctx = fresh();
    glBegin(GL_TRIANGLES);
    material_fv(GL_FRONT, GL_DIFFUSE, &[0.1, 0.2, 0.3, 0.4]);
    material_iv(GL_BACK, GL_EMISSION, &[i32::MAX, 0, 0, i32::MAX]);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 64.0);
    glMateriali(GL_BACK, GL_SHININESS, 32);
    glEnd();
    expect_no_error("glMaterial in begin/end");
    assert_eq!(color(GL_FRONT, GL_DIFFUSE), [0.1, 0.2, 0.3, 0.4]);
    assert_eq!(color(GL_BACK, GL_EMISSION)[0], 1.0);
    assert_eq!(get_material(GL_FRONT, GL_SHININESS, 1), [64.0]);
    assert_eq!(get_material(GL_BACK, GL_SHININESS, 1), [32.0]);
    // errors inside are still the usual ones, not GL_INVALID_OPERATION
    glBegin(GL_POINTS);
    glMaterialf(GL_FRONT, GL_SHININESS, 200.0);
    glEnd();
    expect_error(GL_INVALID_VALUE, "bad shininess in begin/end");
    // but the query is not allowed there
    glBegin(GL_POINTS);
    let mut v = [SENTINEL_F; 4];
    // SAFETY: room for four values.
    unsafe { glGetMaterialfv(GL_FRONT, GL_DIFFUSE, v.as_mut_ptr()) };
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glGetMaterialfv in begin/end");
    assert_eq!(v, [SENTINEL_F; 4]);
}

// ---- glColorMaterial (§2.14.3) ----

const COLOR_MATERIAL_MODES: [GLenum; 5] = [
    GL_EMISSION,
    GL_AMBIENT,
    GL_DIFFUSE,
    GL_SPECULAR,
    GL_AMBIENT_AND_DIFFUSE,
];

/// The color properties a mode tracks.
fn tracked_by(mode: GLenum) -> Vec<GLenum> {
    if mode == GL_AMBIENT_AND_DIFFUSE {
        vec![GL_AMBIENT, GL_DIFFUSE]
    } else {
        vec![mode]
    }
}

fn faces_of(face: GLenum) -> Vec<GLenum> {
    match face {
        GL_FRONT => vec![GL_FRONT],
        GL_BACK => vec![GL_BACK],
        _ => vec![GL_FRONT, GL_BACK],
    }
}

#[test]
fn color_material_defaults() {
    let _ctx = fresh();
    assert_eq!(glIsEnabled(GL_COLOR_MATERIAL), GL_FALSE);
    assert_eq!(get_int(GL_COLOR_MATERIAL_FACE), GL_FRONT_AND_BACK as i32);
    assert_eq!(
        get_int(GL_COLOR_MATERIAL_PARAMETER),
        GL_AMBIENT_AND_DIFFUSE as i32
    );
    // disabled, glColor leaves the material alone
    glColor4f(0.1, 0.2, 0.3, 0.4);
    assert_eq!(color(GL_FRONT, GL_AMBIENT), [0.2, 0.2, 0.2, 1.0]);
    assert_eq!(color(GL_BACK, GL_DIFFUSE), [0.8, 0.8, 0.8, 1.0]);
    expect_no_error("color material defaults");
}

#[test]
fn every_face_and_mode_round_trips_and_tracks_the_current_color() {
    for face in [GL_FRONT, GL_BACK, GL_FRONT_AND_BACK] {
        for mode in COLOR_MATERIAL_MODES {
            let _ctx = fresh();
            let before = materials();
            glColorMaterial(face, mode);
            expect_no_error("glColorMaterial");
            assert_eq!(get_int(GL_COLOR_MATERIAL_FACE), face as i32);
            assert_eq!(get_int(GL_COLOR_MATERIAL_PARAMETER), mode as i32);
            // not enabled yet: nothing tracks
            glColor4f(0.9, 0.8, 0.7, 0.6);
            assert_eq!(
                materials(),
                before,
                "face {face:#x} mode {mode:#x} while disabled"
            );

            // enabling makes the tracked properties take the current color at once
            glEnable(GL_COLOR_MATERIAL);
            let tracked_faces = faces_of(face);
            for f in FACES {
                for pname in [GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION] {
                    let tracked = tracked_faces.contains(&f) && tracked_by(mode).contains(&pname);
                    let want = if tracked {
                        vec![0.9, 0.8, 0.7, 0.6]
                    } else {
                        get_material_default(pname)
                    };
                    assert_eq!(
                        color(f, pname),
                        want,
                        "after glEnable: face {face:#x} mode {mode:#x}, reading {f:#x} {pname:#x}"
                    );
                }
            }
            // then they follow every glColor, in any form
            glColor3ub(255, 0, 51);
            for f in FACES {
                for pname in [GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION] {
                    let tracked = tracked_faces.contains(&f) && tracked_by(mode).contains(&pname);
                    let want = if tracked {
                        vec![1.0, 0.0, 0.2, 1.0]
                    } else {
                        get_material_default(pname)
                    };
                    assert_eq!(
                        color(f, pname),
                        want,
                        "after glColor3ub: face {face:#x} mode {mode:#x}, reading {f:#x} {pname:#x}"
                    );
                }
                // shininess and color indexes are never tracked
                assert_eq!(get_material(f, GL_SHININESS, 1), [0.0]);
                assert_eq!(get_material(f, GL_COLOR_INDEXES, 3), [0.0, 1.0, 1.0]);
            }
            expect_no_error("tracking");
        }
    }
}

fn get_material_default(pname: GLenum) -> Vec<f32> {
    match pname {
        GL_AMBIENT => vec![0.2, 0.2, 0.2, 1.0],
        GL_DIFFUSE => vec![0.8, 0.8, 0.8, 1.0],
        _ => vec![0.0, 0.0, 0.0, 1.0],
    }
}

#[test]
fn glmaterial_on_a_tracked_property_is_ignored() {
    let _ctx = fresh();
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glColor4f(0.5, 0.5, 0.5, 1.0);
    material_fv(GL_FRONT, GL_DIFFUSE, &[0.1, 0.1, 0.1, 0.1]);
    expect_no_error("glMaterial on a tracked property is not an error");
    assert_eq!(color(GL_FRONT, GL_DIFFUSE), [0.5, 0.5, 0.5, 1.0]);
    // GL_AMBIENT_AND_DIFFUSE sets the untracked half only
    material_fv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, &[0.3, 0.3, 0.3, 0.3]);
    assert_eq!(color(GL_FRONT, GL_AMBIENT), [0.3, 0.3, 0.3, 0.3]);
    assert_eq!(color(GL_FRONT, GL_DIFFUSE), [0.5, 0.5, 0.5, 1.0]);
    // the untracked face takes both
    material_fv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.7, 0.7, 0.7, 0.7]);
    assert_eq!(color(GL_BACK, GL_DIFFUSE), [0.7, 0.7, 0.7, 0.7]);
    assert_eq!(color(GL_FRONT, GL_DIFFUSE), [0.5, 0.5, 0.5, 1.0]);
    // untracked properties of the tracked face are set as usual
    material_fv(GL_FRONT, GL_SPECULAR, &[0.4, 0.4, 0.4, 0.4]);
    glMaterialf(GL_FRONT, GL_SHININESS, 5.0);
    assert_eq!(color(GL_FRONT, GL_SPECULAR), [0.4, 0.4, 0.4, 0.4]);
    assert_eq!(get_material(GL_FRONT, GL_SHININESS, 1), [5.0]);

    // once disabled, the material keeps the last tracked color and glMaterial works again
    glDisable(GL_COLOR_MATERIAL);
    glColor4f(0.0, 1.0, 0.0, 1.0);
    assert_eq!(color(GL_FRONT, GL_DIFFUSE), [0.5, 0.5, 0.5, 1.0]);
    material_fv(GL_FRONT, GL_DIFFUSE, &[0.1, 0.1, 0.1, 0.1]);
    assert_eq!(color(GL_FRONT, GL_DIFFUSE), [0.1, 0.1, 0.1, 0.1]);
    expect_no_error("after");
}

#[test]
fn changing_the_mode_while_enabled_retracks_at_once() {
    let _ctx = fresh();
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT);
    glEnable(GL_COLOR_MATERIAL);
    glColor4f(0.25, 0.5, 0.75, 1.0);
    assert_eq!(color(GL_BACK, GL_AMBIENT), [0.25, 0.5, 0.75, 1.0]);
    glColorMaterial(GL_BACK, GL_EMISSION);
    // the newly tracked property has the current color already
    assert_eq!(color(GL_BACK, GL_EMISSION), [0.25, 0.5, 0.75, 1.0]);
    assert_eq!(color(GL_FRONT, GL_EMISSION), [0.0, 0.0, 0.0, 1.0]);
    // the formerly tracked one keeps its last value and no longer follows
    glColor4f(1.0, 0.0, 0.0, 1.0);
    assert_eq!(color(GL_BACK, GL_AMBIENT), [0.25, 0.5, 0.75, 1.0]);
    assert_eq!(color(GL_FRONT, GL_AMBIENT), [0.25, 0.5, 0.75, 1.0]);
    assert_eq!(color(GL_BACK, GL_EMISSION), [1.0, 0.0, 0.0, 1.0]);
    // and glMaterial works on it again
    material_fv(GL_FRONT_AND_BACK, GL_AMBIENT, &[0.0; 4]);
    assert_eq!(color(GL_BACK, GL_AMBIENT), [0.0; 4]);
    expect_no_error("mode change");
}

#[test]
fn glcolor_between_begin_and_end_updates_the_tracked_material() {
    let _ctx = fresh();
    glEnable(GL_COLOR_MATERIAL);
    glBegin(GL_POINTS);
    glColor3f(0.0, 0.5, 1.0);
    glVertex3f(0.0, 0.0, 0.0);
    glColor4ub(255, 255, 0, 0);
    glEnd();
    expect_no_error("glColor in begin/end");
    for face in FACES {
        assert_eq!(color(face, GL_AMBIENT), [1.0, 1.0, 0.0, 0.0]);
        assert_eq!(color(face, GL_DIFFUSE), [1.0, 1.0, 0.0, 0.0]);
    }
}

#[test]
fn color_material_errors_leave_the_state_alone() {
    let _ctx = fresh();
    glColorMaterial(GL_BACK, GL_SPECULAR);
    for bad_mode in [GL_SHININESS, GL_COLOR_INDEXES, GL_POSITION, 0, 0x1234] {
        glColorMaterial(GL_FRONT, bad_mode);
        expect_error(
            GL_INVALID_ENUM,
            &format!("glColorMaterial mode {bad_mode:#x}"),
        );
    }
    for bad_face in [0x0406, 0, 0x1234] {
        glColorMaterial(bad_face, GL_DIFFUSE);
        expect_error(
            GL_INVALID_ENUM,
            &format!("glColorMaterial face {bad_face:#x}"),
        );
    }
    glColorMaterial(0x1234, 0x1234);
    expect_error(GL_INVALID_ENUM, "both bad");
    glBegin(GL_POINTS);
    glColorMaterial(GL_FRONT, GL_EMISSION);
    glEnd();
    expect_error(GL_INVALID_OPERATION, "glColorMaterial in begin/end");
    assert_eq!(get_int(GL_COLOR_MATERIAL_FACE), GL_BACK as i32);
    assert_eq!(get_int(GL_COLOR_MATERIAL_PARAMETER), GL_SPECULAR as i32);
}
