//! The batch engines against the scalar reference path (`DerivedState::process`) on random
//! states and vertices: every lane of the double-precision engine (`process_blocks_exact`)
//! must equal the scalar result to the last bit, and every lane of the fast single-precision
//! engine (`process_blocks`) must be within 1e-5 of it, with every kind of light, both viewers, one- and two-sided
//! lighting, color material, normalize and rescale, w != 1, and integer and fractional
//! exponents up to 128.

use fflight::Context;
use fflight::gl::*;
use fflight::lighting::batch::{Faces, Reads, process_blocks, process_blocks_exact};
use fflight::lighting::fast::{InstructionSet, kernel_blocks_on};
use fflight::lighting::lanes::LANES;
use fflight::pipeline::block::{InputBlock, OutputBlock};
use fflight::pipeline::vertex::{CurrentAttribs, DerivedState, ProcessedVertex};
use glam::{Vec3, Vec4};

/// splitmix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn uniform(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }
    fn coin(&mut self) -> bool {
        self.next() & 1 == 1
    }
    fn vec4(&mut self, lo: f32, hi: f32) -> Vec4 {
        Vec4::new(
            self.uniform(lo, hi),
            self.uniform(lo, hi),
            self.uniform(lo, hi),
            self.uniform(lo, hi),
        )
    }
    fn exponent(&mut self) -> f32 {
        if self.coin() {
            (self.next() % 129) as f32
        } else {
            self.uniform(0.0, 128.0)
        }
    }
}

fn random_state(rng: &mut Rng) -> Context {
    let mut ctx = Context::new();
    let on = |ctx: &mut Context, cap, enabled| ctx.set_capability(cap, enabled).unwrap();
    on(&mut ctx, GL_LIGHTING, !rng.next().is_multiple_of(8));
    ctx.matrix_mode(GL_MODELVIEW).unwrap();
    ctx.rotate(
        f64::from(rng.uniform(0.0, 360.0)),
        1.0,
        f64::from(rng.uniform(-1.0, 1.0)),
        0.5,
    )
    .unwrap();
    if rng.coin() {
        ctx.scale(
            f64::from(rng.uniform(0.3, 3.0)),
            f64::from(rng.uniform(0.3, 3.0)),
            f64::from(rng.uniform(0.3, 3.0)),
        )
        .unwrap();
    }
    for i in 0..8 {
        let light = GL_LIGHT0 + i;
        on(&mut ctx, light, rng.coin());
        let w = if rng.coin() {
            0.0
        } else {
            rng.uniform(0.5, 2.0)
        };
        let p = rng.vec4(-3.0, 3.0);
        ctx.light(light, GL_POSITION, &[p.x, p.y, p.z, w]).unwrap();
        for pname in [GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR] {
            ctx.light(light, pname, &rng.vec4(0.0, 1.0).to_array())
                .unwrap();
        }
        if rng.coin() {
            let d = rng.vec4(-1.0, 1.0);
            ctx.light(light, GL_SPOT_DIRECTION, &[d.x, d.y, d.z])
                .unwrap();
            ctx.light(light, GL_SPOT_CUTOFF, &[rng.uniform(5.0, 90.0)])
                .unwrap();
            ctx.light(light, GL_SPOT_EXPONENT, &[rng.exponent()])
                .unwrap();
        }
        if rng.coin() {
            ctx.light(light, GL_CONSTANT_ATTENUATION, &[rng.uniform(0.5, 2.0)])
                .unwrap();
            ctx.light(light, GL_LINEAR_ATTENUATION, &[rng.uniform(0.0, 1.0)])
                .unwrap();
            ctx.light(light, GL_QUADRATIC_ATTENUATION, &[rng.uniform(0.0, 0.5)])
                .unwrap();
        }
    }
    ctx.load_identity().unwrap();
    ctx.translate(0.0, 0.0, f64::from(rng.uniform(-4.0, 0.0)))
        .unwrap();
    if rng.coin() {
        ctx.scale(1.0, f64::from(rng.uniform(0.5, 2.0)), 1.0)
            .unwrap();
    }
    ctx.matrix_mode(GL_PROJECTION).unwrap();
    ctx.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0).unwrap();
    ctx.matrix_mode(GL_TEXTURE).unwrap();
    ctx.rotate(30.0, 0.0, 0.0, 1.0).unwrap();
    for face in [GL_FRONT, GL_BACK] {
        for pname in [GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION] {
            ctx.material(face, pname, &rng.vec4(0.0, 1.0).to_array())
                .unwrap();
        }
        ctx.material(face, GL_SHININESS, &[rng.exponent()]).unwrap();
    }
    let flag = |rng: &mut Rng| if rng.coin() { 1.0 } else { 0.0 };
    ctx.light_model(GL_LIGHT_MODEL_TWO_SIDE, &[flag(rng)])
        .unwrap();
    ctx.light_model(GL_LIGHT_MODEL_LOCAL_VIEWER, &[flag(rng)])
        .unwrap();
    let separate = if rng.coin() {
        GL_SEPARATE_SPECULAR_COLOR
    } else {
        GL_SINGLE_COLOR
    };
    ctx.light_model(GL_LIGHT_MODEL_COLOR_CONTROL, &[separate as f32])
        .unwrap();
    ctx.light_model(GL_LIGHT_MODEL_AMBIENT, &rng.vec4(0.0, 0.5).to_array())
        .unwrap();
    let faces = [GL_FRONT, GL_BACK, GL_FRONT_AND_BACK];
    let modes = [
        GL_AMBIENT,
        GL_DIFFUSE,
        GL_SPECULAR,
        GL_EMISSION,
        GL_AMBIENT_AND_DIFFUSE,
    ];
    ctx.color_material(
        faces[(rng.next() % 3) as usize],
        modes[(rng.next() % 5) as usize],
    )
    .unwrap();
    on(&mut ctx, GL_COLOR_MATERIAL, rng.coin());
    on(&mut ctx, GL_NORMALIZE, rng.coin());
    on(&mut ctx, GL_RESCALE_NORMAL, rng.coin());
    // Texture coordinate generation on some coordinates, in every mode a coordinate takes.
    let modes: [&[GLenum]; 4] = [
        &[
            GL_OBJECT_LINEAR,
            GL_EYE_LINEAR,
            GL_SPHERE_MAP,
            GL_REFLECTION_MAP,
            GL_NORMAL_MAP,
        ],
        &[
            GL_OBJECT_LINEAR,
            GL_EYE_LINEAR,
            GL_SPHERE_MAP,
            GL_REFLECTION_MAP,
            GL_NORMAL_MAP,
        ],
        &[
            GL_OBJECT_LINEAR,
            GL_EYE_LINEAR,
            GL_REFLECTION_MAP,
            GL_NORMAL_MAP,
        ],
        &[GL_OBJECT_LINEAR, GL_EYE_LINEAR],
    ];
    for (k, coord) in [GL_S, GL_T, GL_R, GL_Q].into_iter().enumerate() {
        let mode = modes[k][(rng.next() as usize) % modes[k].len()];
        ctx.tex_gen(coord, GL_TEXTURE_GEN_MODE, &[mode as f32])
            .unwrap();
        ctx.tex_gen(coord, GL_OBJECT_PLANE, &rng.vec4(-2.0, 2.0).to_array())
            .unwrap();
        ctx.tex_gen(coord, GL_EYE_PLANE, &rng.vec4(-2.0, 2.0).to_array())
            .unwrap();
        on(
            &mut ctx,
            GL_TEXTURE_GEN_S + k as GLenum,
            rng.next().is_multiple_of(3),
        );
    }
    ctx
}

fn random_vertex(rng: &mut Rng) -> (Vec4, CurrentAttribs) {
    let mut position = rng.vec4(-2.0, 2.0);
    position.w = if rng.next().is_multiple_of(4) {
        rng.uniform(0.5, 2.0)
    } else {
        1.0
    };
    let attribs = CurrentAttribs {
        color: rng.vec4(0.0, 1.0),
        secondary_color: rng.vec4(0.0, 1.0),
        normal: Vec3::new(
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
        ),
        tex_coord: rng.vec4(-1.0, 1.0),
        edge_flag: rng.coin(),
        fog_coord: rng.uniform(-1.0, 1.0),
        index: rng.uniform(0.0, 8.0),
        ..CurrentAttribs::default()
    };
    (position, attribs)
}

/// `N` blocks of 1 to `LANES` random vertices, and each vertex through the scalar path.
fn random_blocks<const N: usize>(
    rng: &mut Rng,
    derived: &DerivedState,
) -> ([InputBlock; N], Vec<ProcessedVertex>) {
    let mut inputs = [InputBlock::default(); N];
    let mut expected = Vec::new();
    for block in &mut inputs {
        let len = 1 + (rng.next() as usize) % LANES;
        for _ in 0..len {
            let (position, attribs) = random_vertex(rng);
            block.push(position, &attribs);
            expected.push(derived.process(position, &attribs));
        }
    }
    (inputs, expected)
}

#[test]
fn blocks_equal_the_scalar_path_on_random_states() {
    let mut rng = Rng(2024);
    let mut lanes_checked = 0;
    for state in 0..600 {
        let mut ctx = random_state(&mut rng);
        let derived = ctx.derived().clone();
        let (inputs, expected) = random_blocks::<3>(&mut rng, &derived);
        let mut outputs = [OutputBlock::default(); 3];
        process_blocks_exact(&derived, &inputs, &mut outputs);
        let got: Vec<_> = outputs
            .iter()
            .flat_map(|o| (0..o.len).map(|lane| o.vertex(lane)))
            .collect();
        assert_eq!(got.len(), expected.len());
        for (k, (got, want)) in got.iter().zip(&expected).enumerate() {
            assert_eq!(got, want, "state {state}, vertex {k}");
        }
        lanes_checked += got.len();
    }
    assert!(lanes_checked > 3000);
}

#[test]
fn non_finite_inputs_give_clamped_colors() {
    let mut rng = Rng(7);
    let specials = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 1e30, -1e30, 0.0];
    for state in 0..200 {
        let mut ctx = random_state(&mut rng);
        let derived = ctx.derived().clone();
        let mut input = InputBlock::default();
        for lane in 0..LANES {
            let (mut position, mut attribs) = random_vertex(&mut rng);
            let special = specials[(rng.next() % 6) as usize];
            match lane % 4 {
                0 => position.x = special,
                1 => position.w = special,
                2 => attribs.normal.y = special,
                _ => attribs.color.z = special,
            }
            input.push(position, &attribs);
        }
        let mut output = [OutputBlock::default()];
        process_blocks(&derived, Faces::Both, &[input], &mut output);
        for lane in 0..LANES {
            let v = output[0].vertex(lane);
            for c in [v.colors.front, v.colors.back] {
                for value in c.primary.to_array().iter().chain(&c.secondary.to_array()) {
                    assert!(
                        (0.0..=1.0).contains(value),
                        "state {state} lane {lane}: {v:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn bulk_results_do_not_depend_on_the_thread_count() {
    let mut rng = Rng(99);
    let mut ctx = random_state(&mut rng);
    let count = 3 * fflight::threads::MIN_VERTICES_PER_THREAD + 5;
    let vertices: Vec<_> = (0..count).map(|_| random_vertex(&mut rng)).collect();
    let positions: Vec<Vec4> = vertices.iter().map(|v| v.0).collect();
    let normals: Vec<Vec3> = vertices.iter().map(|v| v.1.normal).collect();
    let colors: Vec<Vec4> = vertices.iter().map(|v| v.1.color).collect();
    let mut results = Vec::new();
    for threads in [1, 2, 3] {
        fflight::threads::set_threads(threads).unwrap();
        let mut out = vec![Default::default(); count];
        ctx.light_vertices(&positions, Some(&normals), Some(&colors), &mut out)
            .unwrap();
        results.push(out);
    }
    fflight::threads::set_threads(0).unwrap();
    assert!(results[1] == results[0] && results[2] == results[0]);
    // And each is within 1e-5 of the scalar reference path.
    let derived = ctx.derived().clone();
    for (i, (position, attribs)) in vertices.iter().enumerate().step_by(97) {
        let attribs = CurrentAttribs {
            secondary_color: Vec4::W,
            tex_coord: Vec4::W,
            edge_flag: true,
            ..*attribs
        };
        let want = derived.process(*position, &attribs);
        let (color, position) = largest_difference(&results[0][i], &want, Faces::Both);
        assert!(color <= 1e-5 && position <= 1e-5, "vertex {i}");
    }
}

/// glDrawElements through the post-transform cache equals glArrayElement per index, also
/// when indices collide in the cache (indices 4096 apart) and repeat across windows.
#[test]
fn cached_indexed_draws_equal_immediate_mode() {
    use fflight::commands::arrays::{ArraySources, ElementIndices};
    use fflight::state::arrays::ArrayKind;
    let mut rng = Rng(5);
    let mut ctx = random_state(&mut rng);
    let count = 3 * 4096 + 17;
    let floats: Vec<f32> = (0..count * 3).map(|_| rng.uniform(-1.0, 1.0)).collect();
    let bytes: Vec<u8> = floats.iter().flat_map(|f| f.to_ne_bytes()).collect();
    ctx.vertex_pointer(3, GL_FLOAT, 0, 4096).unwrap();
    ctx.normal_pointer(GL_FLOAT, 0, 4096).unwrap();
    ctx.client_state(GL_VERTEX_ARRAY, true).unwrap();
    ctx.client_state(GL_NORMAL_ARRAY, true).unwrap();
    let mut indices: Vec<u32> = Vec::new();
    for k in 0..3000u32 {
        let base = (rng.next() % 4096) as u32;
        indices.push(base + 4096 * (k % 3));
        indices.push((base + 1) % 4096 + 4096 * ((k + 1) % 3));
        indices.push(if k % 7 == 0 {
            base
        } else {
            (rng.next() % count as u64) as u32
        });
    }
    let index_bytes: Vec<u8> = indices.iter().flat_map(|i| i.to_ne_bytes()).collect();
    let sources = ArraySources::new(0)
        .with(ArrayKind::Vertex, &bytes)
        .with(ArrayKind::Normal, &bytes);
    ctx.capture_begin().unwrap();
    let listed = ElementIndices::Listed {
        index_type: GL_UNSIGNED_INT,
        bytes: &index_bytes,
    };
    ctx.draw_arrays_from(GL_TRIANGLES, &sources, &listed)
        .unwrap();
    ctx.begin(GL_TRIANGLES).unwrap();
    for &i in &indices {
        ctx.array_element_from(i as usize, &sources).unwrap();
    }
    ctx.end().unwrap();
    ctx.capture_end().unwrap();
    let vertices = ctx.captured().vertices();
    let (drawn, immediate) = vertices.split_at(indices.len());
    assert_eq!(drawn.len(), immediate.len());
    for (k, (a, b)) in drawn.iter().zip(immediate).enumerate() {
        assert_eq!(a, b, "index {k} ({})", indices[k]);
    }
}

/// Points are fed back and selected a block at a time unless capture is on, which sends them
/// down the per-vertex path of every other primitive: both must give the same values, with
/// points inside, outside and on the edge of the view volume and of user clip planes.
#[test]
fn point_blocks_equal_the_per_vertex_path() {
    let mut rng = Rng(77);
    let mut drawn = 0;
    for state in 0..40 {
        let mut base = random_state(&mut rng);
        for plane in 0..(state % 3) {
            let equation = rng.vec4(-1.0, 1.0).as_dvec4().to_array();
            base.clip_plane(GL_CLIP_PLANE0 + plane, equation).unwrap();
            base.set_capability(GL_CLIP_PLANE0 + plane, true).unwrap();
        }
        let mut points: Vec<Vec4> = (0..37).map(|_| rng.vec4(-3.0, 3.0)).collect();
        points.extend([
            Vec4::new(1.0, 0.0, 0.0, 1.0),
            Vec4::new(f32::NAN, 0.0, 0.0, 1.0),
            Vec4::new(f32::INFINITY, 0.0, 0.0, 1.0),
            Vec4::new(0.0, 0.0, 0.0, f32::INFINITY),
        ]);
        let (kind, mode) = if state % 2 == 0 {
            (GL_4D_COLOR_TEXTURE, GL_FEEDBACK)
        } else {
            (GL_3D, GL_SELECT)
        };
        let run = |capture: bool| {
            let mut ctx = base.clone();
            if mode == GL_FEEDBACK {
                ctx.feedback_buffer(100_000, kind, 1).unwrap();
            } else {
                ctx.select_buffer(1000, 1).unwrap();
            }
            ctx.render_mode(mode).unwrap();
            ctx.init_names().unwrap();
            ctx.push_name(7).unwrap();
            if capture {
                ctx.capture_begin().unwrap();
            }
            ctx.begin(GL_POINTS).unwrap();
            for p in &points {
                ctx.vertex(*p);
            }
            ctx.end().unwrap();
            let (count, finished) = ctx.render_mode(GL_RENDER).unwrap();
            let finished = finished.expect("feedback or selection ended");
            (count, finished.values, finished.hit_records)
        };
        let (blocks, per_vertex) = (run(false), run(true));
        drawn += blocks.0;
        let same = |a: &[f32], b: &[f32]| {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
        };
        assert!(same(&blocks.1, &per_vertex.1), "state {state}");
        assert_eq!(blocks.0, per_vertex.0, "state {state}");
        assert_eq!(blocks.2, per_vertex.2, "state {state}");
    }
    assert!(
        drawn > 400,
        "only {drawn} values and hits: the test draws too little"
    );
}

/// `count` random positions of three floats, read as both the vertex and the normal array.
fn random_arrays(rng: &mut Rng, count: usize) -> Vec<u8> {
    let floats: Vec<f32> = (0..count * 3).map(|_| rng.uniform(-1.5, 1.5)).collect();
    floats.iter().flat_map(|f| f.to_ne_bytes()).collect()
}

/// A copy of `base` drawing from `random_arrays`.
fn with_arrays(base: &Context) -> Context {
    let mut ctx = base.clone();
    ctx.vertex_pointer(3, GL_FLOAT, 0, 4096).unwrap();
    ctx.normal_pointer(GL_FLOAT, 0, 4096).unwrap();
    ctx.client_state(GL_VERTEX_ARRAY, true).unwrap();
    ctx.client_state(GL_NORMAL_ARRAY, true).unwrap();
    ctx
}

/// Indices `0..count` as a list of GL_UNSIGNED_INT: the same vertices as a sequential draw,
/// through the indexed path (the post-transform cache, vertex by vertex), a reference that
/// shares neither its fetch nor its streaming.
fn listed_indices(count: usize) -> Vec<u8> {
    (0..count as u32).flat_map(|i| i.to_ne_bytes()).collect()
}

/// Large glDrawArrays are lit on helper threads and streamed in order: the feedback is the
/// same, token for token, whatever the thread count (and the same as the indexed path's), for
/// points and for a strip whose triangles span the chunks the helpers share out.
#[test]
fn draws_do_not_depend_on_the_thread_count() {
    use fflight::commands::arrays::{ArraySources, ElementIndices};
    use fflight::state::arrays::ArrayKind;
    let mut rng = Rng(31);
    let base = random_state(&mut rng);
    let count = 2 * fflight::threads::MIN_VERTICES_PER_THREAD + 1001;
    let bytes = random_arrays(&mut rng, count);
    let sources = ArraySources::new(0)
        .with(ArrayKind::Vertex, &bytes)
        .with(ArrayKind::Normal, &bytes);
    let listed = listed_indices(count);
    for mode in [GL_POINTS, GL_TRIANGLE_STRIP] {
        let mut results = Vec::new();
        // One thread through the indexed path, then 1, 2 and 3 threads.
        for threads in [0, 1, 2, 3] {
            fflight::threads::set_threads(threads.max(1)).unwrap();
            let mut ctx = with_arrays(&base);
            ctx.feedback_buffer(i32::MAX, GL_3D_COLOR, 1).unwrap();
            ctx.render_mode(GL_FEEDBACK).unwrap();
            let all = match threads {
                0 => ElementIndices::Listed {
                    index_type: GL_UNSIGNED_INT,
                    bytes: &listed,
                },
                _ => ElementIndices::Sequential { first: 0, count },
            };
            ctx.draw_arrays_from(mode, &sources, &all).unwrap();
            let (written, finished) = ctx.render_mode(GL_RENDER).unwrap();
            let values = finished.expect("feedback ended").values;
            assert!(written > 10_000, "{written} values");
            results.push(values.iter().map(|v| v.to_bits()).collect::<Vec<_>>());
        }
        fflight::threads::set_threads(0).unwrap();
        for (k, result) in results.iter().enumerate().skip(1) {
            assert!(*result == results[0], "{k} threads, mode {mode:#x}");
        }
    }
}

/// The largest difference between two vertices' values: the colors of `faces` absolutely,
/// positions and texture coordinates relative to their magnitude (at least 1).
fn largest_difference(a: &ProcessedVertex, b: &ProcessedVertex, faces: Faces) -> (f32, f32) {
    let face_count = if faces == Faces::Both { 2 } else { 1 };
    let colors = |v: &ProcessedVertex| {
        [v.colors.front, v.colors.back]
            .into_iter()
            .take(face_count)
            .flat_map(|c| {
                c.primary
                    .to_array()
                    .into_iter()
                    .chain(c.secondary.to_array())
            })
            .collect::<Vec<f32>>()
    };
    let color = colors(a)
        .iter()
        .zip(colors(b))
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f32::max);
    let relative = |x: Vec4, y: Vec4| {
        let scale = x.abs().max(y.abs()).max_element().max(1.0);
        (x - y).abs().max_element() / scale
    };
    let position = relative(a.eye, b.eye)
        .max(relative(a.clip, b.clip))
        .max(relative(a.tex_coord, b.tex_coord));
    (color, position)
}

/// Random states with integer exponents (every fifth with fractional ones, which the fast
/// engine leaves to the double-precision one), without texture coordinate generation half
/// of the time, and every fourth with directional lights alone, none a spot.
fn random_fast_state(rng: &mut Rng, state: usize) -> Context {
    let mut ctx = random_state(rng);
    if !state.is_multiple_of(5) {
        for face in [GL_FRONT, GL_BACK] {
            let e = (rng.next() % 129) as f32;
            ctx.material(face, GL_SHININESS, &[e]).unwrap();
        }
        for i in 0..8 {
            let e = (rng.next() % 129) as f32;
            ctx.light(GL_LIGHT0 + i, GL_SPOT_EXPONENT, &[e]).unwrap();
        }
    }
    if rng.coin() {
        for k in 0..4 {
            ctx.set_capability(GL_TEXTURE_GEN_S + k, false).unwrap();
        }
    }
    if state % 4 == 3 {
        // Every light directional, without a spot: the kernel's loop of that kind alone.
        for i in 0..8 {
            let d = rng.vec4(-1.0, 1.0);
            ctx.light(GL_LIGHT0 + i, GL_POSITION, &[d.x, d.y, d.z, 0.0])
                .unwrap();
            ctx.light(GL_LIGHT0 + i, GL_SPOT_CUTOFF, &[180.0]).unwrap();
        }
    }
    ctx
}

/// The fast engine (`process_blocks`: single precision where its error bound holds, the
/// scalar double-precision path for the lanes it refuses) within 1e-5 of the scalar path on
/// random states, exponents up to 128 included, for both faces and for the front face alone
/// (two-sided lighting run one-sided); and the kernel serving most lanes.
#[test]
fn fast_engine_is_within_1e5_of_the_scalar_path() {
    let mut rng = Rng(4242);
    let (mut served, mut kernel_lanes) = (0, 0);
    let (mut worst_color, mut worst_position) = (0.0f32, 0.0f32);
    let states = std::env::var("FFL_FAST_STATES").map_or(1500, |n| n.parse().unwrap());
    for state in 0..states {
        let mut ctx = random_fast_state(&mut rng, state);
        let derived = ctx.derived().clone();
        let (inputs, expected) = random_blocks::<4>(&mut rng, &derived);
        let faces = if state % 2 == 0 {
            Faces::Both
        } else {
            Faces::Front
        };
        let mut outputs = [OutputBlock::default(); 4];
        process_blocks(&derived, faces, &inputs, &mut outputs);
        let got = outputs
            .iter()
            .flat_map(|o| (0..o.len).map(|lane| o.vertex(lane)));
        for (k, (got, want)) in got.zip(&expected).enumerate() {
            let (color, position) = largest_difference(&got, want, faces);
            // Colors within 1e-5; eye, clip and texture coordinates exact (the fast engine
            // transforms in double precision, in the scalar path's order).
            assert!(
                color <= 1e-5 && position == 0.0,
                "state {state}, {faces:?}, vertex {k}: colors {color:e}, positions {position:e}\n{got:?}\n{want:?}"
            );
            assert_eq!(got.edge_flag, want.edge_flag);
            worst_color = worst_color.max(color);
            worst_position = worst_position.max(position);
        }
        if let Some(fast) = &derived.fast {
            let (mut outputs, mut refused) = ([OutputBlock::default(); 4], [0u8; 4]);
            if kernel_blocks_on(
                InstructionSet::Avx2,
                fast,
                faces,
                &inputs,
                &mut outputs,
                &mut refused,
            ) {
                for (input, refused) in inputs.iter().zip(refused) {
                    kernel_lanes += input.len;
                    served += input.len - refused.count_ones() as usize;
                }
            }
        }
    }
    eprintln!(
        "largest differences: colors {worst_color:e}, positions {worst_position:e}; \
         the kernel served {served} of {kernel_lanes} lanes of the states it takes"
    );
    if kernel_lanes > 0 {
        assert!(
            served * 10 >= kernel_lanes * 6,
            "{served} of {kernel_lanes}"
        );
    }
}

/// Every instruction set the kernel is compiled for that this CPU has (whichever the engine
/// would pick): the lanes each serves within 1e-5 of the scalar path, positions exact, a
/// block's results the same alone as paired with another (AVX-512 takes two at a time, AVX2
/// with two lights or more), and the same without the eye coordinates.
#[test]
fn every_instruction_set_agrees_with_the_scalar_path() {
    let mut rng = Rng(777);
    let mut served = [0usize; 2];
    // States AVX2 lights in pairs of blocks (two lights or more).
    let mut paired = 0;
    for state in 0..400 {
        let mut ctx = random_fast_state(&mut rng, state);
        let derived = ctx.derived().clone();
        let Some(fast) = derived.fast.clone() else {
            continue;
        };
        let lights = (0..8)
            .filter(|&i| ctx.is_enabled(GL_LIGHT0 + i) == Ok(true))
            .count();
        paired += usize::from(ctx.is_enabled(GL_LIGHTING) == Ok(true) && lights >= 2);
        let (inputs, expected) = random_blocks::<3>(&mut rng, &derived);
        let faces = if state % 3 == 0 {
            Faces::Front
        } else {
            Faces::Both
        };
        for (k, set) in [InstructionSet::Avx2, InstructionSet::Avx512]
            .into_iter()
            .enumerate()
        {
            let mut outputs = [OutputBlock::default(); 3];
            let mut refused = [0u8; 3];
            if !kernel_blocks_on(set, &fast, faces, &inputs, &mut outputs, &mut refused) {
                continue;
            }
            let mut want = expected.iter();
            for (b, output) in outputs.iter().enumerate() {
                for lane in 0..output.len {
                    let want = want.next().unwrap();
                    if refused[b] & 1 << lane != 0 || derived.transform.tex_gen.is_some() {
                        continue;
                    }
                    let (color, position) = largest_difference(&output.vertex(lane), want, faces);
                    assert!(
                        color <= 1e-5 && position == 0.0,
                        "{set:?} state {state} block {b} lane {lane}: {color:e} {position:e}"
                    );
                    served[k] += 1;
                }
            }
            // The first block alone gives what it gave in the group (AVX-512, and AVX2 with
            // two lights or more: paired with the second in sixteen lanes, alone in eight).
            let mut alone = [OutputBlock::default()];
            let mut alone_refused = [0u8];
            kernel_blocks_on(
                set,
                &fast,
                faces,
                &inputs[..1],
                &mut alone,
                &mut alone_refused,
            );
            assert_eq!(alone_refused[0], refused[0], "{set:?} state {state}");
            assert_eq!(alone[0], outputs[0], "{set:?} state {state}");
            // The eye coordinates, secondary colors and texture coordinates unread (points
            // fed back as GL_3D_COLOR without user clip planes): the rest the same, to the bit.
            let mut unread = [OutputBlock::default(); 3];
            let mut unread_refused = [0u8; 3];
            let reads = Reads {
                faces,
                eye: false,
                secondary: false,
                tex_coord: false,
            };
            kernel_blocks_on(set, &fast, reads, &inputs, &mut unread, &mut unread_refused);
            assert_eq!(unread_refused, refused, "{set:?} state {state}");
            for (mut block, all) in unread.into_iter().zip(&outputs) {
                block.eye = all.eye;
                block.front_secondary = all.front_secondary;
                block.back_secondary = all.back_secondary;
                block.tex_coord = all.tex_coord;
                assert_eq!(&block, all, "{set:?} state {state}");
            }
        }
    }
    eprintln!("lanes served: AVX2 {}, AVX-512 {}", served[0], served[1]);
    assert!(paired >= 100, "{paired} states with two lights or more");
}

/// Large glDrawArrays(GL_POINTS) in feedback or selection mode run chunk by chunk on the
/// threads (`pipeline::points`): the same feedback values, token for token, and the same hit
/// records on any thread count as the indexed path gives, with a user clip plane culling
/// some points, and with a feedback buffer too small for them (GL_RenderMode then returns -1
/// and the values that fit).
#[test]
fn threaded_points_equal_one_thread() {
    use fflight::commands::arrays::{ArraySources, ElementIndices};
    use fflight::state::arrays::ArrayKind;
    let mut rng = Rng(47);
    let base = random_state(&mut rng);
    let count = 3 * fflight::threads::MIN_VERTICES_PER_THREAD + 777;
    let bytes = random_arrays(&mut rng, count);
    let sources = ArraySources::new(0)
        .with(ArrayKind::Vertex, &bytes)
        .with(ArrayKind::Normal, &bytes);
    // (render mode, feedback buffer size, user clip plane)
    let cases = [
        (GL_FEEDBACK, i32::MAX, false),
        (GL_FEEDBACK, i32::MAX, true),
        (GL_FEEDBACK, 100_003, false),
        (GL_SELECT, 0, true),
    ];
    let listed = listed_indices(count);
    let mut unclipped = 0;
    for (mode, size, plane) in cases {
        let mut results = Vec::new();
        // One thread through the indexed path, then 1, 2 and 3 threads.
        for threads in [0, 1, 2, 3] {
            fflight::threads::set_threads(threads.max(1)).unwrap();
            let mut ctx = with_arrays(&base);
            if plane {
                ctx.clip_plane(GL_CLIP_PLANE0, [1.0, 0.5, 0.0, 0.2])
                    .unwrap();
                ctx.set_capability(GL_CLIP_PLANE0, true).unwrap();
            }
            if mode == GL_FEEDBACK {
                ctx.feedback_buffer(size, GL_3D_COLOR, 1).unwrap();
            } else {
                ctx.select_buffer(64, 1).unwrap();
            }
            ctx.render_mode(mode).unwrap();
            if mode == GL_SELECT {
                ctx.init_names().unwrap();
                ctx.push_name(7).unwrap();
            }
            let all = match threads {
                0 => ElementIndices::Listed {
                    index_type: GL_UNSIGNED_INT,
                    bytes: &listed,
                },
                _ => ElementIndices::Sequential { first: 0, count },
            };
            ctx.draw_arrays_from(GL_POINTS, &sources, &all).unwrap();
            let (written, finished) = ctx.render_mode(GL_RENDER).unwrap();
            let finished = finished.expect("feedback or selection ended");
            let values: Vec<u32> = finished.values.iter().map(|v| v.to_bits()).collect();
            results.push((written, values, finished.hit_records));
        }
        fflight::threads::set_threads(0).unwrap();
        let (written, values, hits) = &results[0];
        if mode == GL_FEEDBACK && size < i32::MAX {
            assert_eq!((*written, values.len()), (-1, size as usize), "overflow");
        } else if mode == GL_FEEDBACK && !plane {
            assert!(*written > 10_000, "{written} values");
            unclipped = *written;
        } else if mode == GL_FEEDBACK {
            assert!(
                (10_000..unclipped).contains(written),
                "the plane culls some points"
            );
        } else {
            assert_eq!((*written, hits.len()), (1, 4), "one hit record of one name");
        }
        for (k, result) in results.iter().enumerate().skip(1) {
            assert!(
                *result == results[0],
                "{k} threads, {mode:#x} {size} {plane}"
            );
        }
    }
}

/// A context keeps the value buffers of a large draw of points on several threads for its
/// next (`pipeline::points::PointBuffers`): draws after the first, whose buffers still hold
/// the first's values, of other feedback layouts and of fewer points, give what a new
/// context gives, token for token.
#[test]
fn threaded_points_reuse_their_buffers_across_draws() {
    use fflight::commands::arrays::{ArraySources, ElementIndices};
    use fflight::state::arrays::ArrayKind;
    let mut rng = Rng(48);
    let base = random_state(&mut rng);
    let count = 3 * fflight::threads::MIN_VERTICES_PER_THREAD + 321;
    let bytes = random_arrays(&mut rng, count);
    let sources = ArraySources::new(0)
        .with(ArrayKind::Vertex, &bytes)
        .with(ArrayKind::Normal, &bytes);
    let draw = |ctx: &mut Context, layout: GLenum, points: usize| {
        ctx.feedback_buffer(i32::MAX, layout, 1).unwrap();
        ctx.render_mode(GL_FEEDBACK).unwrap();
        let all = ElementIndices::Sequential {
            first: 0,
            count: points,
        };
        ctx.draw_arrays_from(GL_POINTS, &sources, &all).unwrap();
        let (written, finished) = ctx.render_mode(GL_RENDER).unwrap();
        let values: Vec<u32> = finished
            .unwrap()
            .values
            .iter()
            .map(|v| v.to_bits())
            .collect();
        (written, values)
    };
    fflight::threads::set_threads(2).unwrap();
    let mut reused = with_arrays(&base);
    let draws = [
        (GL_4D_COLOR_TEXTURE, count),
        (GL_2D, count),
        (GL_3D_COLOR, count - 2000),
        (GL_4D_COLOR_TEXTURE, count),
    ];
    for (k, (layout, points)) in draws.into_iter().enumerate() {
        let got = draw(&mut reused, layout, points);
        let want = draw(&mut with_arrays(&base), layout, points);
        assert!(got.0 > 10_000, "draw {k}: {} values", got.0);
        assert!(got == want, "draw {k}: layout {layout:#x}, {points} points");
    }
    fflight::threads::set_threads(0).unwrap();
}
