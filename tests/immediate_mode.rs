//! Immediate mode's buffering (glBegin / glVertex / glEnd): vertices wait in blocks and are
//! lit a batch at a time, with only the attributes set since glBegin written per vertex. Every
//! vertex must still be fed back exactly as if it were drawn alone with the attributes current
//! at its glVertex, whatever changed between vertices, wherever the blocks and batches break,
//! and whatever the thread count (a helper thread lights large batches, or parts of them).

use fflight::{Context, gl::*};
use glam::{Vec3, Vec4};

/// A small deterministic generator (the same sequence on every run).
struct Lcg(u32);

impl Lcg {
    fn next(&mut self) -> f32 {
        self.0 = self.0.wrapping_mul(1664525).wrapping_add(1013904223);
        (self.0 >> 8) as f32 / 16777216.0
    }

    fn signed(&mut self) -> f32 {
        2.0 * self.next() - 1.0
    }

    fn chance(&mut self, p: f32) -> bool {
        self.next() < p
    }
}

/// `lights` spot lights (attenuated, local viewer, two-sided, GL_NORMALIZE), or lighting off
/// for 0; color material on (so glColor between vertices changes the lit color).
fn scene(lights: u32) -> Context {
    let mut ctx = Context::new();
    ctx.viewport(0, 0, 256, 256).unwrap();
    if lights > 0 {
        ctx.set_capability(GL_LIGHTING, true).unwrap();
        ctx.set_capability(GL_NORMALIZE, true).unwrap();
        ctx.set_capability(GL_COLOR_MATERIAL, true).unwrap();
        ctx.color_material(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE)
            .unwrap();
        ctx.light_model_scalar(GL_LIGHT_MODEL_TWO_SIDE, 1.0)
            .unwrap();
        ctx.light_model_scalar(GL_LIGHT_MODEL_LOCAL_VIEWER, 1.0)
            .unwrap();
        ctx.material(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0])
            .unwrap();
        ctx.material(GL_FRONT_AND_BACK, GL_SHININESS, &[32.0])
            .unwrap();
    }
    for i in 0..lights {
        let light = GL_LIGHT0 + i;
        let a = std::f32::consts::FRAC_PI_4 * i as f32;
        let (x, y) = (0.5 * a.cos(), 0.5 * a.sin());
        ctx.set_capability(light, true).unwrap();
        ctx.light(light, GL_POSITION, &[x, y, 1.0, 1.0]).unwrap();
        ctx.light(light, GL_SPOT_DIRECTION, &[-x, -y, -1.0])
            .unwrap();
        ctx.light(light, GL_SPOT_CUTOFF, &[60.0]).unwrap();
        ctx.light(light, GL_SPOT_EXPONENT, &[2.0]).unwrap();
        ctx.light(light, GL_LINEAR_ATTENUATION, &[0.1]).unwrap();
        ctx.light(light, GL_SPECULAR, &[0.3, 0.6, 0.9, 1.0])
            .unwrap();
    }
    // A curve for glEvalCoord1: positions and colors.
    let points = [-0.5f32, -0.5, 0.2, 0.5, 0.3, -0.2, 0.1, 0.6, 0.0];
    ctx.map(
        GL_MAP1_VERTEX_3,
        1,
        [0.0, 1.0, 0.0, 1.0],
        [3, 0],
        [3, 0],
        &points,
    )
    .unwrap();
    let colors = [
        1.0f32, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.5,
    ];
    ctx.map(
        GL_MAP1_COLOR_4,
        1,
        [0.0, 1.0, 0.0, 1.0],
        [4, 0],
        [3, 0],
        &colors,
    )
    .unwrap();
    ctx.set_capability(GL_MAP1_VERTEX_3, true).unwrap();
    ctx.set_capability(GL_MAP1_COLOR_4, true).unwrap();
    ctx
}

/// What may happen before a vertex.
#[derive(Clone, Copy, Debug)]
enum Step {
    Color(Vec4),
    Normal(Vec3),
    TexCoord(Vec4),
    Unit0TexCoord(Vec4),
    SecondaryColor([f32; 3]),
    EdgeFlag(bool),
    /// glMaterial between vertices: the pending vertices are lit with the material before.
    Shininess(f32),
    Vertex(Vec4),
    /// glEvalCoord1: a vertex with the evaluated color, the current one unchanged.
    Eval(f64),
}

fn run(ctx: &mut Context, step: Step) {
    match step {
        Step::Color(c) => ctx.color(c),
        Step::Normal(n) => ctx.normal(n),
        Step::TexCoord(t) => ctx.tex_coord(t),
        Step::Unit0TexCoord(t) => ctx.multi_tex_coord(GL_TEXTURE0, t).unwrap(),
        Step::SecondaryColor(c) => ctx.secondary_color(c),
        Step::EdgeFlag(f) => ctx.edge_flag(f),
        Step::Shininess(s) => ctx.material(GL_FRONT_AND_BACK, GL_SHININESS, &[s]).unwrap(),
        Step::Vertex(v) => ctx.vertex(v),
        Step::Eval(u) => ctx.eval_coord(1, u, 0.0),
    }
}

/// Which changes `steps` makes, one bit per kind (`Step`'s order, glMaterial and
/// glEvalCoord1 last).
const ALL: u32 = 0xff;

/// `vertices` vertices with random attribute changes between them, of the kinds in `kinds`:
/// each changes now and then, so blocks start with some set and some not since glBegin.
fn steps(seed: u32, vertices: usize, kinds: u32) -> Vec<Step> {
    let mut r = Lcg(seed);
    let mut steps = Vec::new();
    for _ in 0..vertices {
        let v4 = |r: &mut Lcg| Vec4::new(r.next(), r.next(), r.next(), 1.0);
        // One draw per kind whatever `kinds`, so the vertices are the same.
        let chance = |r: &mut Lcg, kind: u32, p: f32| r.chance(p) && kinds & (1 << kind) != 0;
        if chance(&mut r, 0, 0.05) {
            steps.push(Step::Color(v4(&mut r)));
        }
        if chance(&mut r, 1, 0.3) {
            steps.push(Step::Normal(Vec3::new(
                r.signed(),
                r.signed(),
                r.signed() + 1.5,
            )));
        }
        if chance(&mut r, 2, 0.02) {
            steps.push(Step::TexCoord(v4(&mut r)));
        }
        if chance(&mut r, 3, 0.02) {
            steps.push(Step::Unit0TexCoord(v4(&mut r)));
        }
        if chance(&mut r, 4, 0.02) {
            steps.push(Step::SecondaryColor([r.next(), r.next(), r.next()]));
        }
        if chance(&mut r, 5, 0.02) {
            steps.push(Step::EdgeFlag(r.chance(0.5)));
        }
        if chance(&mut r, 6, 0.002) {
            steps.push(Step::Shininess(1.0 + 100.0 * r.next()));
        }
        if chance(&mut r, 7, 0.03) {
            steps.push(Step::Eval(r.next() as f64));
        } else {
            let (x, y, z) = (0.9 * r.signed(), 0.9 * r.signed(), 0.9 * r.signed());
            steps.push(Step::Vertex(Vec4::new(x, y, z, 1.0)));
        }
    }
    steps
}

fn feedback(ctx: &mut Context, kind: GLenum, draw: impl FnOnce(&mut Context)) -> Vec<f32> {
    ctx.feedback_buffer(1 << 22, kind, 1).unwrap();
    ctx.render_mode(GL_FEEDBACK).unwrap();
    draw(ctx);
    let (count, finished) = ctx.render_mode(GL_RENDER).unwrap();
    assert!(count > 0);
    finished.unwrap().values
}

/// The steps in one glBegin(GL_POINTS) / glEnd.
/// `got` equals `expected` to the bit, value for value.
fn assert_same_bits(got: &[f32], expected: &[f32], what: &str) {
    assert_eq!(got.len(), expected.len(), "{what}: value counts");
    let first = got
        .iter()
        .zip(expected)
        .position(|(a, b)| a.to_bits() != b.to_bits());
    assert_eq!(first, None, "{what}: first differing value");
}

fn together(ctx: &mut Context, steps: &[Step]) -> Vec<f32> {
    feedback(ctx, GL_4D_COLOR_TEXTURE, |ctx| {
        ctx.begin(GL_POINTS).unwrap();
        steps.iter().for_each(|&s| run(ctx, s));
        ctx.end().unwrap();
    })
}

/// Each vertex in a glBegin / glEnd of its own, after the same attribute changes.
fn apart(ctx: &mut Context, steps: &[Step]) -> Vec<f32> {
    feedback(ctx, GL_4D_COLOR_TEXTURE, |ctx| {
        for &step in steps {
            match step {
                Step::Vertex(_) | Step::Eval(_) => {
                    ctx.begin(GL_POINTS).unwrap();
                    run(ctx, step);
                    ctx.end().unwrap();
                }
                _ => run(ctx, step),
            }
        }
    })
}

#[test]
fn each_vertex_takes_the_attributes_current_at_its_glvertex() {
    // No lighting, one light (small batches), three lights (large batches); every kind of
    // change alone, then all of them.
    for (seed, lights) in [(1, 0), (2, 1), (3, 3)] {
        for kinds in (0..8).map(|kind| 1 << kind).chain([ALL]) {
            let steps = steps(seed, 3000, kinds);
            let got = together(&mut scene(lights), &steps);
            let expected = apart(&mut scene(lights), &steps);
            assert_eq!(got.len(), expected.len(), "{lights} lights");
            let first = got
                .iter()
                .zip(&expected)
                .position(|(a, b)| a.to_bits() != b.to_bits());
            assert_eq!(
                first, None,
                "{lights} lights, changes {kinds:#x}: first differing value"
            );
        }
    }
}

/// Primitives that reuse the blocks of those before (two or three batches each, with one
/// light and three, on two threads): an attribute set per vertex in one and not in the next,
/// or changed between them, still reaches each vertex as current at its glVertex.
#[test]
fn primitives_reusing_blocks_take_the_attributes_current_at_each_glvertex() {
    const NORMAL: u32 = 1 << 1;
    // Per primitive, the kinds of change between its vertices; between primitives, a color,
    // texture coordinates, a secondary color and an edge flag, now and then.
    let kinds = [
        0b11,
        NORMAL,
        NORMAL | 1 << 2,
        NORMAL,
        NORMAL | 1 << 4 | 1 << 5,
        NORMAL,
        ALL & !(1 << 6),
        NORMAL,
        0,
    ];
    let mut between = Lcg(5);
    let primitives: Vec<(Vec<Step>, Vec<Step>)> = kinds
        .iter()
        .enumerate()
        .map(|(p, &kinds)| {
            let v4 = |r: &mut Lcg| Vec4::new(r.next(), r.next(), r.next(), 1.0);
            let changes = [
                Step::Color(v4(&mut between)),
                Step::TexCoord(v4(&mut between)),
                Step::SecondaryColor([between.next(), 0.5, 0.25]),
                Step::EdgeFlag(between.chance(0.5)),
            ];
            let before = changes
                .into_iter()
                .filter(|_| between.chance(0.4))
                .collect();
            (before, steps(40 + p as u32, 2048 + 512 * (p % 3), kinds))
        })
        .collect();
    for lights in [1, 3] {
        fflight::threads::set_threads(2).unwrap();
        let got = feedback(&mut scene(lights), GL_4D_COLOR_TEXTURE, |ctx| {
            for (before, steps) in &primitives {
                before.iter().for_each(|&s| run(ctx, s));
                ctx.begin(GL_POINTS).unwrap();
                steps.iter().for_each(|&s| run(ctx, s));
                ctx.end().unwrap();
            }
        });
        fflight::threads::set_threads(0).unwrap();
        let all: Vec<Step> = primitives
            .iter()
            .flat_map(|(before, steps)| before.iter().chain(steps))
            .copied()
            .collect();
        let expected = apart(&mut scene(lights), &all);
        assert_same_bits(&got, &expected, &format!("{lights} lights"));
    }
}

#[test]
fn current_attributes_after_glend_are_the_last_set() {
    let mut ctx = scene(3);
    let steps = steps(4, 1000, ALL);
    together(&mut ctx, &steps);
    let last = |pick: &dyn Fn(&Step) -> Option<Vec4>| steps.iter().rev().find_map(pick);
    let color = last(&|s| match s {
        Step::Color(c) => Some(*c),
        _ => None,
    });
    let normal = last(&|s| match s {
        Step::Normal(n) => Some(n.extend(0.0)),
        _ => None,
    });
    assert_eq!(
        ctx.get(GL_CURRENT_COLOR).unwrap().as_floats(),
        color.unwrap().to_array()
    );
    assert_eq!(
        ctx.get(GL_CURRENT_NORMAL).unwrap().as_floats(),
        normal.unwrap().truncate().to_array()
    );
}

/// Triangles with edge flags in GL_LINE mode: the edge flag of each vertex decides its edges.
#[test]
fn edge_flags_between_vertices_are_honored() {
    let steps = steps(5, 3000, ALL);
    let draw = |ctx: &mut Context, steps: &[Step], apart: bool| {
        ctx.polygon_mode(GL_FRONT_AND_BACK, GL_LINE).unwrap();
        feedback(ctx, GL_3D_COLOR, |ctx| {
            let vertices: Vec<&Step> = steps.iter().collect();
            let mut in_triangle = 0;
            if !apart {
                ctx.begin(GL_TRIANGLES).unwrap();
            }
            for step in vertices {
                let is_vertex = matches!(step, Step::Vertex(_) | Step::Eval(_));
                if apart && is_vertex && in_triangle == 0 {
                    ctx.begin(GL_TRIANGLES).unwrap();
                }
                run(ctx, *step);
                if is_vertex {
                    in_triangle = (in_triangle + 1) % 3;
                    if apart && in_triangle == 0 {
                        ctx.end().unwrap();
                    }
                }
            }
            if apart && in_triangle != 0 {
                ctx.end().unwrap();
            }
            if !apart {
                ctx.end().unwrap();
            }
        })
    };
    let got = draw(&mut scene(2), &steps, false);
    let expected = draw(&mut scene(2), &steps, true);
    assert_same_bits(&got, &expected, "edge flags");
}

/// Many primitives of lengths about a batch's (1024 vertices) and its multiples, of three
/// modes, glMaterial between vertices now and then (at a batch's end too): with 1, 2 and 3
/// threads the feedback is the same to the bit, in the same order, run after run (the
/// helper thread's timing, and so which thread lights what, differs from run to run).
#[test]
fn primitives_across_batches_feed_back_the_same_on_any_thread_count() {
    primitives_across_batches_with_lights(3);
}

/// The same with one light, where a context's first primitives share their batches with
/// the helper too (`SharingChoice`).
#[test]
fn primitives_across_batches_with_one_light_feed_back_the_same_on_any_thread_count() {
    primitives_across_batches_with_lights(1);
}

fn primitives_across_batches_with_lights(lights: u32) {
    let lengths = [1, 1023, 1024, 1025, 2049, 3072, 4100];
    // Every kind of change but glMaterial, which `draw` adds at chosen vertices.
    let steps = steps(7, lengths.iter().sum(), ALL & !(1 << 6));
    let draw = |threads: i32| {
        fflight::threads::set_threads(threads).unwrap();
        let values = feedback(&mut scene(lights), GL_4D_COLOR_TEXTURE, |ctx| {
            let mut steps = steps.iter();
            for (p, &length) in lengths.iter().enumerate() {
                ctx.begin([GL_POINTS, GL_TRIANGLES, GL_LINE_STRIP][p % 3])
                    .unwrap();
                let mut vertices = 0;
                while vertices < length {
                    let Some(&step) = steps.next() else { break };
                    run(ctx, step);
                    if matches!(step, Step::Vertex(_) | Step::Eval(_)) {
                        vertices += 1;
                        if [1024, 2500, 2501, 3072].contains(&vertices) {
                            run(ctx, Step::Shininess(vertices as f32 / 100.0));
                        }
                    }
                }
                ctx.end().unwrap();
            }
        });
        fflight::threads::set_threads(0).unwrap();
        values
    };
    let one = draw(1);
    for threads in [2, 3] {
        let what = format!("{lights} lights, {threads} threads");
        assert_same_bits(&draw(threads), &one, &what);
    }
}

/// Points the helper thread lights it also lays out (feedback values, or the depths of
/// selection hits): with a user clip plane culling about half of them, with a feedback
/// buffer too small for them all, and in selection mode with a name per primitive, 1, 2 and
/// 3 threads give the same values, counts and hit records.
#[test]
fn points_laid_out_by_the_helper_are_the_same_on_any_thread_count() {
    points_laid_out_with_lights(3);
}

/// The same with one light (`SharingChoice`).
#[test]
fn points_laid_out_by_the_helper_with_one_light_are_the_same_on_any_thread_count() {
    points_laid_out_with_lights(1);
}

/// The lengths of the primitives of points the helper lays out.
const POINTS_LENGTHS: [usize; 4] = [1024, 3000, 4097, 700];

/// A step of drawing the primitives of points the helper lays out.
enum PointsStep {
    /// glBegin of primitive `p`.
    Begin(usize),
    /// A normal, then a vertex.
    Point(Vec3, Vec4),
    End,
}

/// Each primitive of `POINTS_LENGTHS` in turn, through `step`: its glBegin, a normal and a
/// vertex at a time (random, the same on every call), its glEnd.
fn each_point(mut step: impl FnMut(PointsStep)) {
    let mut rng = Lcg(99);
    for (p, &length) in POINTS_LENGTHS.iter().enumerate() {
        step(PointsStep::Begin(p));
        for _ in 0..length {
            let normal = Vec3::new(rng.signed(), rng.signed(), rng.signed());
            let position = Vec4::new(rng.signed(), rng.signed(), rng.signed(), 1.0);
            step(PointsStep::Point(normal, position));
        }
        step(PointsStep::End);
    }
}

/// `scene(lights)` with a user clip plane that culls about half of the points.
fn scene_culling_half(lights: u32) -> Context {
    let mut ctx = scene(lights);
    ctx.clip_plane(GL_CLIP_PLANE0, [1.0, 0.5, 0.0, 0.1])
        .unwrap();
    ctx.set_capability(GL_CLIP_PLANE0, true).unwrap();
    ctx
}

fn points_laid_out_with_lights(lights: u32) {
    let draw = |ctx: &mut Context| {
        each_point(|step| match step {
            PointsStep::Begin(p) => {
                ctx.load_name(p as u32).unwrap();
                ctx.begin(GL_POINTS).unwrap();
            }
            PointsStep::Point(normal, position) => {
                ctx.normal(normal);
                ctx.vertex(position);
            }
            PointsStep::End => ctx.end().unwrap(),
        });
    };
    let run = |threads: i32, mode: GLenum, size: i32| {
        fflight::threads::set_threads(threads).unwrap();
        let mut ctx = scene_culling_half(lights);
        if mode == GL_FEEDBACK {
            ctx.feedback_buffer(size, GL_3D_COLOR, 1).unwrap();
        } else {
            ctx.select_buffer(size, 1).unwrap();
        }
        ctx.render_mode(mode).unwrap();
        if mode == GL_SELECT {
            ctx.init_names().unwrap();
            ctx.push_name(0).unwrap();
        }
        draw(&mut ctx);
        let (count, finished) = ctx.render_mode(GL_RENDER).unwrap();
        fflight::threads::set_threads(0).unwrap();
        let finished = finished.unwrap();
        (count, finished.values, finished.hit_records)
    };
    for (mode, size) in [
        (GL_FEEDBACK, 1 << 20),
        (GL_FEEDBACK, 30_000),
        (GL_SELECT, 64),
    ] {
        let one = run(1, mode, size);
        assert!(one.0 != 0, "mode {mode:#x}, size {size}: something drawn");
        for threads in [2, 3] {
            let many = run(threads, mode, size);
            let what = format!("{lights} lights, mode {mode:#x}, size {size}, {threads} threads");
            assert_eq!(many.0, one.0, "{what}: count");
            assert_same_bits(&many.1, &one.1, &what);
            assert_eq!(many.2, one.2, "{what}: hit records");
        }
    }
}

// The C entry points, as a C program declares them: their usual case (`capi::attribs`'
// `attribute!`: `try_vertex_quick`, `try_color_quick`, glNormal's and glTexCoord's stores) is
// compiled apart from the context's methods.
unsafe extern "C" {
    fn glBegin(mode: GLenum);
    fn glEnd();
    fn glColor4f(r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat);
    fn glNormal3fv(v: *const GLfloat);
    fn glTexCoord4f(s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat);
    fn glMultiTexCoord4f(unit: GLenum, s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat);
    fn glSecondaryColor3f(r: GLfloat, g: GLfloat, b: GLfloat);
    fn glEdgeFlag(flag: GLboolean);
    fn glMaterialf(face: GLenum, pname: GLenum, param: GLfloat);
    fn glVertex3fv(v: *const GLfloat);
    fn glVertex4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat);
    fn glEvalCoord1d(u: GLdouble);
    fn glFeedbackBuffer(size: GLsizei, kind: GLenum, buffer: *mut GLfloat);
    fn glRenderMode(mode: GLenum) -> GLint;
    fn glPassThrough(token: GLfloat);
    fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei);
    fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat);
}

/// `step` through the C entry points, on this thread's current context.
fn run_c(step: Step) {
    // SAFETY: the vectors passed hold the values each command reads.
    unsafe {
        match step {
            Step::Color(c) => glColor4f(c.x, c.y, c.z, c.w),
            Step::Normal(n) => glNormal3fv(n.to_array().as_ptr()),
            Step::TexCoord(t) => glTexCoord4f(t.x, t.y, t.z, t.w),
            Step::Unit0TexCoord(t) => glMultiTexCoord4f(GL_TEXTURE0, t.x, t.y, t.z, t.w),
            Step::SecondaryColor([r, g, b]) => glSecondaryColor3f(r, g, b),
            Step::EdgeFlag(f) => glEdgeFlag(GLboolean::from(f)),
            Step::Shininess(s) => glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, s),
            Step::Vertex(v) if v.w == 1.0 => glVertex3fv(v.truncate().to_array().as_ptr()),
            Step::Vertex(v) => glVertex4f(v.x, v.y, v.z, v.w),
            Step::Eval(u) => glEvalCoord1d(u),
        }
    }
}

/// glVertex, glNormal and glColor through the C entry points (whose usual case has a path
/// of its own) feed back the same values, to the bit, as through the context's methods:
/// unlit (glColor's usual case) and lit with color material (glColor's general case), with
/// only normals and colors changing between vertices (glVertex's usual case throughout) and
/// with every kind of change.
#[test]
fn the_c_entry_points_feed_back_what_the_context_methods_do() {
    const NORMAL_AND_COLOR: u32 = 0b11;
    for (seed, lights) in [(11, 0), (12, 1), (13, 3)] {
        for kinds in [NORMAL_AND_COLOR, 1 << 2, 1 << 6, ALL] {
            let steps = steps(seed, 5000, kinds);
            let expected = together(&mut scene(lights), &steps);
            fflight::current::with_current(|ctx| *ctx = scene(lights)).unwrap();
            let mut buffer = vec![0.0f32; 1 << 20];
            // SAFETY: the buffer outlives feedback mode, which ends below.
            let count = unsafe {
                glFeedbackBuffer(
                    buffer.len() as GLsizei,
                    GL_4D_COLOR_TEXTURE,
                    buffer.as_mut_ptr(),
                );
                glRenderMode(GL_FEEDBACK);
                glBegin(GL_POINTS);
                steps.iter().for_each(|&s| run_c(s));
                glEnd();
                glRenderMode(GL_RENDER)
            };
            let what = format!("{lights} lights, changes {kinds:#x}");
            assert_same_bits(&buffer[..count as usize], &expected, &what);
        }
    }
}

/// Points the helper places straight into the application's feedback memory (through the C
/// entry points, which give it): with about half of them culled, and with a buffer too
/// small for them all, 1 and 2 threads give the same count and the same buffer to the bit,
/// and nothing is written past the values counted.
#[test]
fn points_placed_in_the_application_memory_are_the_same_on_any_thread_count() {
    points_placed_with_lights(3);
}

/// The same with one light (`SharingChoice`).
#[test]
fn points_placed_in_the_application_memory_with_one_light_are_the_same_on_any_thread_count() {
    points_placed_with_lights(1);
}

fn points_placed_with_lights(lights: u32) {
    // A value no point feeds back: its bits must stay where nothing was written.
    const UNWRITTEN: f32 = -12345.0;
    let run = |threads: i32, size: usize| {
        fflight::threads::set_threads(threads).unwrap();
        fflight::current::with_current(|ctx| *ctx = scene_culling_half(lights)).unwrap();
        let mut buffer = vec![UNWRITTEN; size + 64];
        // SAFETY: the buffer outlives feedback mode, which ends below; the vectors passed hold
        // three values each.
        let count = unsafe {
            glFeedbackBuffer(size as GLsizei, GL_3D_COLOR, buffer.as_mut_ptr());
            glRenderMode(GL_FEEDBACK);
            each_point(|step| match step {
                PointsStep::Begin(_) => glBegin(GL_POINTS),
                PointsStep::Point(normal, position) => {
                    glNormal3fv(normal.to_array().as_ptr());
                    glVertex3fv(position.truncate().to_array().as_ptr());
                }
                PointsStep::End => glEnd(),
            });
            glRenderMode(GL_RENDER)
        };
        fflight::threads::set_threads(0).unwrap();
        (count, buffer)
    };
    for size in [1 << 18, 30_000] {
        let (count, one) = run(1, size);
        let written = if count < 0 { size } else { count as usize };
        assert!(written > 0, "something drawn");
        assert!(
            one[written..]
                .iter()
                .all(|v| v.to_bits() == UNWRITTEN.to_bits()),
            "nothing past the values"
        );
        // Immediate mode has one helper thread, whatever the count above one.
        let (many_count, many) = run(2, size);
        let what = format!("{lights} lights, size {size}");
        assert_eq!(many_count, count, "{what}: count");
        assert_same_bits(&many, &one, &what);
    }
}

/// Primitives of points in batches of 1024, whole or not: at their glEnd the helper may
/// still be lighting and placing the last ones (`PrimitiveInProgress::may_carry`; a
/// primitive's last blocks go to it too, a batch that ends early), which the next command
/// collects first, or the next primitive before its own (a short one, 700 points, among
/// them). Between primitives, the
/// viewport and a light change (the points in flight keep the state of their glVertex), a
/// pass-through token is fed back (after the points before it), and another primitive
/// follows at once; 1 and 2 threads give the same count and buffer, to the bit, also with a
/// buffer too small for them all.
#[test]
fn points_in_flight_past_glend_are_where_one_thread_puts_them() {
    points_in_flight_past_glend_with_lights(3);
}

/// The same with one light (`SharingChoice`).
#[test]
fn points_in_flight_past_glend_with_one_light_are_where_one_thread_puts_them() {
    points_in_flight_past_glend_with_lights(1);
}

fn points_in_flight_past_glend_with_lights(lights: u32) {
    let run = |threads: i32, size: usize| {
        fflight::threads::set_threads(threads).unwrap();
        fflight::current::with_current(|ctx| *ctx = scene_culling_half(lights)).unwrap();
        let mut buffer = vec![-1.0; size];
        let mut rng = Lcg(7);
        // SAFETY: the buffer outlives feedback mode, which ends below; the vectors passed
        // hold the values each command reads.
        let count = unsafe {
            glFeedbackBuffer(size as GLsizei, GL_3D_COLOR, buffer.as_mut_ptr());
            glRenderMode(GL_FEEDBACK);
            for (p, points) in [2048, 1500, 3072, 700, 2500].into_iter().enumerate() {
                glBegin(GL_POINTS);
                for _ in 0..points {
                    let normal = [rng.signed(), rng.signed(), rng.signed()];
                    let position = [rng.signed(), rng.signed(), rng.signed()];
                    glNormal3fv(normal.as_ptr());
                    glVertex3fv(position.as_ptr());
                }
                glEnd();
                match p {
                    0 => glViewport(10, 20, 200, 100),
                    1 => glLightfv(GL_LIGHT0, GL_POSITION, [0.5, -1.0, 2.0, 0.0].as_ptr()),
                    2 => glPassThrough(p as f32),
                    _ => {}
                }
            }
            glRenderMode(GL_RENDER)
        };
        fflight::threads::set_threads(0).unwrap();
        (count, buffer)
    };
    for size in [1 << 18, 20_000] {
        let (count, one) = run(1, size);
        let (many_count, many) = run(2, size);
        let what = format!("{lights} lights, size {size}");
        assert!(count != 0, "{what}: something drawn");
        assert_eq!(many_count, count, "{what}: count");
        assert_same_bits(&many, &one, &what);
    }
}

/// A context dropped with points still in flight past a glEnd takes them back from the
/// helper: nothing is written into the application's memory after (which is then freed:
/// under memcheck, where the helper runs slowly, a late write is an invalid write).
#[test]
fn a_context_dropped_with_points_in_flight_past_glend_writes_nothing_after() {
    let context = fflight::current::FflContext::new();
    fflight::current::make_current(Some(context.clone())).unwrap();
    fflight::threads::set_threads(2).unwrap();
    fflight::current::with_current(|ctx| *ctx = scene(1)).unwrap();
    let mut buffer = vec![0.0f32; 1 << 16];
    let mut rng = Lcg(3);
    // SAFETY: the buffer outlives the context, dropped below; the vectors passed hold the
    // values each command reads.
    unsafe {
        glFeedbackBuffer(buffer.len() as GLsizei, GL_3D_COLOR, buffer.as_mut_ptr());
        glRenderMode(GL_FEEDBACK);
        glBegin(GL_POINTS);
        for _ in 0..4 * 1024 {
            let normal = [rng.signed(), rng.signed(), rng.signed()];
            let position = [rng.signed(), rng.signed(), rng.signed()];
            glNormal3fv(normal.as_ptr());
            glVertex3fv(position.as_ptr());
        }
        glEnd();
    }
    fflight::current::make_current(None).unwrap();
    drop(context);
    fflight::threads::set_threads(0).unwrap();
    let after: Vec<u32> = buffer.iter().map(|v| v.to_bits()).collect();
    std::thread::sleep(std::time::Duration::from_millis(20));
    assert!(
        buffer.iter().map(|v| v.to_bits()).eq(after),
        "written after the context was dropped"
    );
    drop(buffer);
    std::thread::sleep(std::time::Duration::from_millis(20));
}
