//! Every texture unit's coordinates travel with each vertex to capture (GL 1.3
//! multitexture): immediate mode (glMultiTexCoord), array draws reading each unit's
//! texture coordinate array (glClientActiveTexture + glTexCoordPointer, any type, size and
//! stride), glArrayElement, indexed draws, large threaded draws and display-list copies of
//! draws, each unit with its own coordinate generation (§2.11.4) and texture matrix.
//! Checked against an independent double-precision evaluation, and against unit 0 (the
//! batch engine) given the same state; feedback still reports unit 0's (§5.3).

use fflight::commands::arrays::ArraySources;
use fflight::commands::list::Command;
use fflight::state::arrays::ArrayKind;
use fflight::{Context, GlError, gl::*};
use glam::{DMat4, DVec3, DVec4, Mat4, Vec3, Vec4};

/// Tolerance of the single-precision results against the double-precision reference.
const TOLERANCE: f64 = 2e-5;

fn units(ctx: &Context) -> usize {
    ctx.get(GL_MAX_TEXTURE_UNITS).unwrap().as_ints()[0] as usize
}

/// What unit `unit` generates: per coordinate S, T, R, Q, `None` or the mode.
fn gen_modes(unit: usize) -> [Option<GLenum>; 4] {
    match unit % 8 {
        0 => [None; 4],
        1 => [Some(GL_OBJECT_LINEAR), Some(GL_OBJECT_LINEAR), None, None],
        2 => [
            Some(GL_EYE_LINEAR),
            None,
            Some(GL_EYE_LINEAR),
            Some(GL_OBJECT_LINEAR),
        ],
        3 => [Some(GL_SPHERE_MAP), Some(GL_SPHERE_MAP), None, None],
        4 => [
            Some(GL_REFLECTION_MAP),
            Some(GL_REFLECTION_MAP),
            Some(GL_REFLECTION_MAP),
            None,
        ],
        5 => [
            Some(GL_NORMAL_MAP),
            Some(GL_NORMAL_MAP),
            Some(GL_NORMAL_MAP),
            None,
        ],
        6 => [None; 4],
        _ => [Some(GL_EYE_LINEAR), Some(GL_NORMAL_MAP), None, None],
    }
}

/// Unit `unit`'s planes for coordinate `c` (object and eye).
fn plane(unit: usize, c: usize) -> [f64; 4] {
    let u = unit as f64;
    let c = c as f64;
    [
        0.5 + 0.1 * u - 0.2 * c,
        -0.3 + 0.05 * u * c,
        0.2 * c - 0.1,
        0.25 - 0.05 * u,
    ]
}

/// Unit `unit`'s texture matrix: a different one per unit.
fn texture_matrix(unit: usize) -> Mat4 {
    let u = unit as f32;
    Mat4::from_translation(Vec3::new(0.1 * u, -0.05 * u, 0.02 * u))
        * Mat4::from_axis_angle(Vec3::new(1.0, u, 2.0).normalize(), 0.3 * u)
        * Mat4::from_scale(Vec3::new(1.0 + 0.1 * u, 1.0, 1.0 - 0.05 * u))
}

/// The modelview in force while the eye planes are given (§2.11.4 takes them into eye
/// coordinates with its inverse).
fn plane_modelview() -> Mat4 {
    Mat4::from_translation(Vec3::new(0.2, -0.1, -0.5)) * Mat4::from_rotation_y(0.4)
}

/// The modelview the vertices are drawn under.
fn draw_modelview() -> Mat4 {
    Mat4::from_translation(Vec3::new(0.1, 0.3, -3.0))
        * Mat4::from_rotation_x(0.7)
        * Mat4::from_scale(Vec3::new(1.5, 0.8, 1.2))
}

/// Sets texture unit `to`'s generation and matrix as `gen_modes(from)`, `plane(from, ..)`,
/// `texture_matrix(from)` say, leaving the active unit and matrix mode as they were.
fn configure_unit(ctx: &mut Context, to: usize, from: usize) {
    ctx.active_texture(GL_TEXTURE0 + to as GLenum).unwrap();
    ctx.matrix_mode(GL_TEXTURE).unwrap();
    ctx.load_matrix(&texture_matrix(from).to_cols_array())
        .unwrap();
    ctx.matrix_mode(GL_MODELVIEW).unwrap();
    for (c, mode) in gen_modes(from).into_iter().enumerate() {
        let coord = GL_S + c as GLenum;
        ctx.tex_gen(coord, GL_OBJECT_PLANE, &plane(from, c))
            .unwrap();
        ctx.tex_gen(coord, GL_EYE_PLANE, &plane(from, c + 4))
            .unwrap();
        if let Some(mode) = mode {
            ctx.tex_gen(coord, GL_TEXTURE_GEN_MODE, &[mode as f64])
                .unwrap();
        }
        ctx.set_capability(GL_TEXTURE_GEN_S + c as GLenum, mode.is_some())
            .unwrap();
    }
}

/// A context whose every unit generates and transforms as unit `unit_state(u)` says.
fn context_with(unit_state: impl Fn(usize) -> usize) -> Context {
    let mut ctx = Context::new();
    ctx.viewport(0, 0, 100, 100).unwrap();
    ctx.set_capability(GL_NORMALIZE, true).unwrap();
    ctx.load_matrix(&plane_modelview().to_cols_array()).unwrap();
    for unit in 0..units(&ctx) {
        configure_unit(&mut ctx, unit, unit_state(unit));
    }
    ctx.active_texture(GL_TEXTURE0).unwrap();
    ctx.load_matrix(&draw_modelview().to_cols_array()).unwrap();
    ctx
}

/// §2.11.4 and the texture matrix in double precision: unit `unit`'s coordinates of a vertex
/// at `object` with normal `normal` whose given coordinates are `given`.
fn reference(unit: usize, object: Vec4, normal: Vec3, given: Vec4) -> DVec4 {
    let modelview = draw_modelview().as_dmat4();
    let eye = modelview * object.as_dvec4();
    let inverse = modelview.inverse();
    let n = DVec3::new(
        inverse.col(0).truncate().dot(normal.as_dvec3()),
        inverse.col(1).truncate().dot(normal.as_dvec3()),
        inverse.col(2).truncate().dot(normal.as_dvec3()),
    )
    .normalize();
    let u = eye.truncate().normalize();
    let r = u - 2.0 * n * n.dot(u);
    let m = 2.0 * (r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0)).sqrt();
    let plane_inverse: DMat4 = plane_modelview().as_dmat4().inverse();
    let mut coords = given.as_dvec4().to_array();
    for (c, mode) in gen_modes(unit).into_iter().enumerate() {
        let Some(mode) = mode else { continue };
        let object_plane = DVec4::from_array(plane(unit, c));
        // p M^-1, p a row vector.
        let eye_plane = plane_inverse.transpose() * DVec4::from_array(plane(unit, c + 4));
        coords[c] = match mode {
            GL_OBJECT_LINEAR => object_plane.dot(object.as_dvec4()),
            GL_EYE_LINEAR => eye_plane.dot(eye),
            GL_SPHERE_MAP => [r.x / m + 0.5, r.y / m + 0.5][c],
            GL_REFLECTION_MAP => r[c],
            _ => n[c],
        };
    }
    texture_matrix(unit).as_dmat4() * DVec4::from_array(coords)
}

fn assert_close(got: Vec4, want: DVec4, what: &str) {
    let error = (got.as_dvec4() - want).abs().max_element();
    assert!(
        error <= TOLERANCE * want.abs().max_element().max(1.0),
        "{what}: got {got}, want {want} (difference {error:e}, tolerance {TOLERANCE:e})"
    );
}

/// The vertices the tests draw: position, normal, and unit u's given coordinates.
fn vertex(i: usize) -> (Vec4, Vec3) {
    let t = i as f32;
    let position = Vec4::new(
        (t * 0.7).sin(),
        (t * 1.3).cos() * 0.8,
        0.3 * (t * 0.4).sin(),
        1.0,
    );
    let normal = Vec3::new((t * 0.9).cos(), 0.5, (t * 0.5).sin() + 0.2);
    (position, normal)
}

fn given(i: usize, unit: usize) -> Vec4 {
    let (t, u) = (i as f32, unit as f32);
    Vec4::new(
        0.1 * t + u,
        0.05 * t - 0.3 * u,
        0.5 - 0.02 * t * u,
        1.0 + 0.25 * u,
    )
}

/// Checks every unit of captured vertices `first..first + count` (vertex k drawn as
/// `element(k)`, whose given coordinates are `given_of(k, unit)`) against the reference.
fn check_capture(
    ctx: &Context,
    first: usize,
    count: usize,
    element: impl Fn(usize) -> usize,
    given_of: impl Fn(usize, usize) -> Vec4,
    what: &str,
) {
    let capture = ctx.captured();
    assert_eq!(capture.vertices().len(), first + count, "{what}: vertices");
    for k in 0..count {
        let (position, normal) = vertex(element(k));
        for unit in 0..units(ctx) {
            let got = capture.tex_coord(first + k, unit).expect("captured");
            let want = reference(unit, position, normal, given_of(k, unit));
            assert_close(got, want, &format!("{what}: vertex {k} unit {unit}"));
        }
    }
}

#[test]
fn there_are_eight_units() {
    let ctx = Context::new();
    assert_eq!(units(&ctx), 8);
}

#[test]
fn immediate_mode_carries_every_unit() {
    let mut ctx = context_with(|unit| unit);
    let n = units(&ctx);
    ctx.capture_begin().unwrap();
    ctx.begin(GL_TRIANGLE_STRIP).unwrap();
    // 19 vertices: more than two blocks of pending vertices.
    for i in 0..19 {
        let (position, normal) = vertex(i);
        ctx.normal(normal);
        for unit in 0..n {
            // Unit 6 keeps the coordinates of vertex 0: its value is current, not per vertex.
            if unit != 6 || i == 0 {
                ctx.multi_tex_coord(GL_TEXTURE0 + unit as GLenum, given(i, unit))
                    .unwrap();
            }
        }
        ctx.vertex(position);
    }
    ctx.end().unwrap();
    ctx.capture_end().unwrap();
    let given_of = |k, unit| given(if unit == 6 { 0 } else { k }, unit);
    check_capture(&ctx, 0, 19, |k| k, given_of, "immediate");
}

#[test]
fn each_unit_matches_unit_0_given_the_same_state() {
    // Unit 0 goes through the batch engine; the others through the capture's side path.
    // Given the same state and inputs they must agree to the bit.
    let n = Context::new().get(GL_MAX_TEXTURE_UNITS).unwrap().as_ints()[0] as usize;
    let mut all = context_with(|unit| unit);
    all.capture_begin().unwrap();
    all.begin(GL_POINTS).unwrap();
    for i in 0..11 {
        let (position, normal) = vertex(i);
        all.normal(normal);
        for unit in 0..n {
            all.multi_tex_coord(GL_TEXTURE0 + unit as GLenum, given(i, unit))
                .unwrap();
        }
        all.vertex(position);
    }
    all.end().unwrap();
    for unit in 1..n {
        let mut single = context_with(|_| unit);
        single.capture_begin().unwrap();
        single.begin(GL_POINTS).unwrap();
        for i in 0..11 {
            let (position, normal) = vertex(i);
            single.normal(normal);
            single.tex_coord(given(i, unit));
            single.vertex(position);
        }
        single.end().unwrap();
        for i in 0..11 {
            assert_eq!(
                all.captured().tex_coord(i, unit),
                single.captured().tex_coord(i, 0),
                "vertex {i} unit {unit}"
            );
        }
    }
}

fn bytes_of<T: Copy>(values: &[T], to_bytes: impl Fn(T) -> Vec<u8>) -> Vec<u8> {
    values.iter().flat_map(|&v| to_bytes(v)).collect()
}

/// Unit u's texture coordinate array of `count` elements: a type, size and stride of its
/// own (stride padded by `4 * (u % 3)` bytes); values are `given(i, u)` rounded to what the
/// type holds, so the reference reads them back as `array_given`.
fn unit_array(unit: usize, count: usize) -> (i32, GLenum, i32, Vec<u8>) {
    let size = 1 + (unit % 4) as i32;
    let pad = 4 * (unit % 3);
    let component_type = [GL_FLOAT, GL_SHORT, GL_DOUBLE, GL_INT][unit % 4];
    let mut bytes = Vec::new();
    for i in 0..count {
        let g = array_given(i, unit).to_array();
        for &value in &g[..size as usize] {
            match component_type {
                GL_FLOAT => bytes.extend((value).to_ne_bytes()),
                GL_SHORT => bytes.extend((value as i16).to_ne_bytes()),
                GL_DOUBLE => bytes.extend((value as f64).to_ne_bytes()),
                _ => bytes.extend((value as i32).to_ne_bytes()),
            }
        }
        bytes.extend(std::iter::repeat_n(0xA5, pad));
    }
    let element = size as usize * [4, 2, 8, 4][unit % 4];
    let stride = if pad == 0 { 0 } else { (element + pad) as i32 };
    (size, component_type, stride, bytes)
}

/// What unit u's array gives element i, padded with (0, 0, 0, 1).
fn array_given(i: usize, unit: usize) -> Vec4 {
    let size = 1 + unit % 4;
    let g = given(i, unit).to_array();
    let integer = matches!(unit % 4, 1 | 3);
    let mut out = [0.0, 0.0, 0.0, 1.0];
    for c in 0..size {
        out[c] = if integer { (g[c] * 10.0).round() } else { g[c] };
    }
    Vec4::from_array(out)
}

/// A context with a vertex and a normal array of `count` elements and a texture coordinate
/// array on every even unit (the odd ones keep their current coordinates `given(99, u)`),
/// with the bytes the draws read.
struct ArrayScene {
    positions: Vec<u8>,
    normals: Vec<u8>,
    units: Vec<Option<Vec<u8>>>,
}

impl ArrayScene {
    fn new(ctx: &mut Context, count: usize) -> ArrayScene {
        let n = units(ctx);
        let positions: Vec<f32> = (0..count)
            .flat_map(|i| vertex(i).0.truncate().to_array())
            .collect();
        let normals: Vec<f32> = (0..count).flat_map(|i| vertex(i).1.to_array()).collect();
        let positions = bytes_of(&positions, |v: f32| v.to_ne_bytes().to_vec());
        let normals = bytes_of(&normals, |v: f32| v.to_ne_bytes().to_vec());
        ctx.vertex_pointer(3, GL_FLOAT, 0, positions.as_ptr() as usize)
            .unwrap();
        ctx.normal_pointer(GL_FLOAT, 0, normals.as_ptr() as usize)
            .unwrap();
        ctx.client_state(GL_VERTEX_ARRAY, true).unwrap();
        ctx.client_state(GL_NORMAL_ARRAY, true).unwrap();
        let mut arrays = Vec::new();
        for unit in 0..n {
            ctx.multi_tex_coord(GL_TEXTURE0 + unit as GLenum, given(99, unit))
                .unwrap();
            ctx.client_active_texture(GL_TEXTURE0 + unit as GLenum)
                .unwrap();
            if unit.is_multiple_of(2) {
                let (size, component_type, stride, bytes) = unit_array(unit, count);
                ctx.tex_coord_pointer(size, component_type, stride, bytes.as_ptr() as usize)
                    .unwrap();
                ctx.client_state(GL_TEXTURE_COORD_ARRAY, true).unwrap();
                arrays.push(Some(bytes));
            } else {
                arrays.push(None);
            }
        }
        ctx.client_active_texture(GL_TEXTURE0).unwrap();
        ArrayScene {
            positions,
            normals,
            units: arrays,
        }
    }

    fn sources(&self) -> ArraySources<'_> {
        let mut sources = ArraySources::new(0)
            .with(ArrayKind::Vertex, &self.positions)
            .with(ArrayKind::Normal, &self.normals);
        for (unit, bytes) in self.units.iter().enumerate() {
            if let Some(bytes) = bytes {
                sources = sources.with_unit(unit, bytes);
            }
        }
        sources
    }

    fn given(element: usize, unit: usize) -> Vec4 {
        if unit.is_multiple_of(2) {
            array_given(element, unit)
        } else {
            given(99, unit)
        }
    }
}

#[test]
fn array_draws_read_every_units_array() {
    let mut ctx = context_with(|unit| unit);
    let scene = ArrayScene::new(&mut ctx, 40);
    let sources = scene.sources();
    ctx.capture_begin().unwrap();
    // glDrawArrays.
    let indices = ctx.check_draw_arrays(GL_TRIANGLES, 3, 30).unwrap();
    ctx.draw_arrays_from(GL_TRIANGLES, &sources, &indices)
        .unwrap();
    check_capture(
        &ctx,
        0,
        30,
        |k| 3 + k,
        |k, u| ArrayScene::given(3 + k, u),
        "DrawArrays",
    );
    // glDrawElements: indices repeat (the post-transform cache).
    let listed: Vec<u16> = (0..36).map(|k| ((k * 7) % 40) as u16).collect();
    let index_bytes = bytes_of(&listed, |i: u16| i.to_ne_bytes().to_vec());
    let indices = fflight::commands::arrays::ElementIndices::Listed {
        index_type: GL_UNSIGNED_SHORT,
        bytes: &index_bytes,
    };
    ctx.draw_arrays_from(GL_LINES, &sources, &indices).unwrap();
    let element = |k: usize| listed[k] as usize;
    check_capture(
        &ctx,
        30,
        36,
        element,
        |k, u| ArrayScene::given(element(k), u),
        "DrawElements",
    );
    // glArrayElement between glBegin and glEnd makes each unit's element current.
    ctx.begin(GL_POINTS).unwrap();
    for index in [5, 17, 2] {
        ctx.array_element_from(index, &sources).unwrap();
    }
    ctx.end().unwrap();
    let element = |k: usize| [5, 17, 2][k];
    check_capture(
        &ctx,
        66,
        3,
        element,
        |k, u| ArrayScene::given(element(k), u),
        "ArrayElement",
    );
    for unit in (0..units(&ctx)).step_by(2) {
        ctx.active_texture(GL_TEXTURE0 + unit as GLenum).unwrap();
        let current = ctx.get(GL_CURRENT_TEXTURE_COORDS).unwrap().as_floats();
        assert_eq!(
            current,
            array_given(2, unit).to_array(),
            "unit {unit}'s current coordinates"
        );
    }
}

#[test]
fn large_threaded_draws_carry_every_unit() {
    let mut ctx = context_with(|unit| unit);
    let count = 20_000;
    let scene = ArrayScene::new(&mut ctx, count);
    let sources = scene.sources();
    ctx.capture_begin().unwrap();
    let indices = ctx.check_draw_arrays(GL_POINTS, 0, count as i32).unwrap();
    ctx.draw_arrays_from(GL_POINTS, &sources, &indices).unwrap();
    let capture = ctx.captured();
    assert_eq!(capture.vertices().len(), count);
    for k in (0..count).step_by(997).chain([count - 1]) {
        let (position, normal) = vertex(k);
        for unit in 0..units(&ctx) {
            let want = reference(unit, position, normal, ArrayScene::given(k, unit));
            assert_close(
                capture.tex_coord(k, unit).unwrap(),
                want,
                &format!("vertex {k} unit {unit}"),
            );
        }
    }
}

#[test]
fn display_lists_keep_every_units_array() {
    let mut ctx = context_with(|unit| unit);
    let scene = ArrayScene::new(&mut ctx, 12);
    let indices = ctx.check_draw_arrays(GL_TRIANGLE_FAN, 0, 12).unwrap();
    let recorded = ctx
        .record_draw(GL_TRIANGLE_FAN, &scene.sources(), &indices)
        .unwrap();
    drop(scene); // the list keeps its own copy
    ctx.capture_begin().unwrap();
    Command::Draw(Box::new(recorded)).execute(&mut ctx).unwrap();
    check_capture(&ctx, 0, 12, |k| k, ArrayScene::given, "list");
}

#[test]
fn feedback_reports_unit_0_only() {
    let mut ctx = context_with(|unit| unit);
    ctx.load_identity().unwrap(); // the points inside the view volume: all fed back
    ctx.feedback_buffer(1000, GL_4D_COLOR_TEXTURE, 1).unwrap();
    ctx.render_mode(GL_FEEDBACK).unwrap();
    let n = units(&ctx);
    ctx.capture_begin().unwrap();
    ctx.begin(GL_POINTS).unwrap();
    for i in 0..3 {
        let (position, normal) = vertex(i);
        ctx.normal(normal);
        for unit in 0..n {
            ctx.multi_tex_coord(GL_TEXTURE0 + unit as GLenum, given(i, unit))
                .unwrap();
        }
        ctx.vertex((position.truncate() * 0.5).extend(1.0));
    }
    ctx.end().unwrap();
    let (count, finished) = ctx.render_mode(GL_RENDER).unwrap();
    let values = finished.unwrap().values;
    // GL_POINT_TOKEN, x y z w, r g b a, s t r q.
    assert_eq!(count, 3 * 13);
    for (i, point) in values.chunks(13).enumerate() {
        let unit_0 = ctx.captured().tex_coord(i, 0).unwrap().to_array();
        assert_eq!(point[9..], unit_0, "point {i}");
        for unit in 1..units(&ctx) {
            let other = ctx.captured().tex_coord(i, unit).unwrap().to_array();
            assert_ne!(point[9..], other, "point {i} unit {unit}");
        }
    }
}

#[test]
fn units_beyond_the_limit_are_invalid_enums_that_change_nothing() {
    let mut ctx = Context::new();
    let n = units(&ctx) as GLenum;
    ctx.active_texture(GL_TEXTURE2).unwrap();
    ctx.client_active_texture(GL_TEXTURE3).unwrap();
    for texture in [GL_TEXTURE0 + n, GL_TEXTURE0 + 31, GL_TEXTURE0 - 1, 0] {
        assert_eq!(ctx.active_texture(texture), Err(GlError::InvalidEnum));
        assert_eq!(
            ctx.client_active_texture(texture),
            Err(GlError::InvalidEnum)
        );
        assert_eq!(
            ctx.multi_tex_coord(texture, Vec4::ONE),
            Err(GlError::InvalidEnum)
        );
        assert_eq!(
            ctx.get(GL_ACTIVE_TEXTURE).unwrap().as_ints(),
            [GL_TEXTURE2 as i32]
        );
        assert_eq!(
            ctx.get(GL_CLIENT_ACTIVE_TEXTURE).unwrap().as_ints(),
            [GL_TEXTURE3 as i32]
        );
    }
    for unit in 0..n {
        ctx.active_texture(GL_TEXTURE0 + unit).unwrap();
        assert_eq!(
            ctx.get(GL_CURRENT_TEXTURE_COORDS).unwrap().as_floats(),
            [0.0, 0.0, 0.0, 1.0]
        );
    }
}

#[test]
fn capture_without_units_in_use_keeps_one_run() {
    // Units 1 and up at their defaults: every vertex shares one run of coordinates.
    let mut ctx = Context::new();
    ctx.capture_begin().unwrap();
    ctx.begin(GL_POINTS).unwrap();
    for i in 0..100 {
        ctx.tex_coord(Vec4::new(i as f32, 0.0, 0.0, 1.0));
        ctx.vertex(Vec4::W);
    }
    ctx.end().unwrap();
    for i in [0, 50, 99] {
        assert_eq!(
            ctx.captured().tex_coord(i, 0),
            Some(Vec4::new(i as f32, 0.0, 0.0, 1.0))
        );
        assert_eq!(ctx.captured().tex_coord(i, 7), Some(Vec4::W));
    }
}
