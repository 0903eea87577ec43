//! Indexed separate triangles (glDrawElements(GL_TRIANGLES, ..)) in feedback and selection
//! take the mesh path (`pipeline::mesh`), which works per cached vertex; everything else
//! takes the general path. The two must agree to the bit: the same draw is run with capture
//! on (which sends it through the general path) and off, over meshes that straddle the view
//! volume and user clip planes, with culling, both windings, flat shading, two-sided lighting,
//! every feedback type, selection, an overflowing buffer and indices whose vertices share
//! cache slots; and against glDrawArrays of the same vertices, not indexed.

#[path = "common/gl_api.rs"]
mod gl_api;

use std::ffi::c_void;

use fflight::gl::*;
use gl_api::*;

unsafe extern "C" {
    fn glClipPlane(plane: GLenum, equation: *const GLdouble);
    fn glCullFace(mode: GLenum);
    fn glFrontFace(mode: GLenum);
    fn glShadeModel(mode: GLenum);
    fn glSelectBuffer(size: GLsizei, buffer: *mut GLuint);
    fn glInitNames();
    fn glPushName(name: GLuint);
    fn glLoadName(name: GLuint);
    fn glEnableClientState(array: GLenum);
    fn glVertexPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glNormalPointer(ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glColorPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glTexCoordPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn fflSetThreads(count: GLint);
}

const FEEDBACK_TYPES: [GLenum; 5] = [
    GL_2D,
    GL_3D,
    GL_3D_COLOR,
    GL_3D_COLOR_TEXTURE,
    GL_4D_COLOR_TEXTURE,
];

/// A vertex's attributes, one array each.
struct Mesh {
    positions: Vec<f32>,
    normals: Vec<f32>,
    colors: Vec<f32>,
    tex_coords: Vec<f32>,
    indices: Vec<u32>,
}

fn lcg(state: &mut u32) -> f32 {
    *state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
    (*state >> 8) as f32 / (1 << 24) as f32
}

/// A `side` x `rows` height field wider than the view volume, of which the first
/// `triangle_rows` rows of cells are drawn (two triangles per cell, so that a vertex is shared
/// by six), then `extra` triangles of random vertices of the whole field, among them triangles
/// whose corners are 4096 indices apart (one cache slot).
fn mesh(side: usize, rows: usize, triangle_rows: usize, extra: usize) -> Mesh {
    let mut state = 7;
    let n = side * rows;
    let mut m = Mesh {
        positions: Vec::with_capacity(3 * n),
        normals: Vec::with_capacity(3 * n),
        colors: Vec::with_capacity(4 * n),
        tex_coords: Vec::with_capacity(2 * n),
        indices: Vec::new(),
    };
    for j in 0..rows {
        for i in 0..side {
            let x = 9.0 * i as f32 / (side - 1) as f32 - 4.5;
            let y = 7.0 * j as f32 / (rows - 1) as f32 - 3.5;
            let z = 1.5 * (0.7 * x).sin() * (0.9 * y).cos();
            m.positions.extend([x, y, z]);
            m.normals
                .extend([lcg(&mut state) - 0.5, lcg(&mut state) - 0.5, 1.0]);
            m.colors
                .extend([lcg(&mut state), lcg(&mut state), 0.5, 1.0]);
            m.tex_coords.extend([x, y]);
        }
    }
    for j in 0..triangle_rows.min(rows - 1) {
        for i in 0..side - 1 {
            let a = (j * side + i) as u32;
            let (b, c) = (a + 1, a + side as u32);
            m.indices.extend([a, b, c, b, c + 1, c]);
        }
    }
    for k in 0..extra {
        // In range of the arrays: the draw reads every vertex its indices name.
        let mut pick = || (lcg(&mut state) * n as f32) as u32 % n as u32;
        let a = pick();
        let corners = match k % 4 {
            // Corners that share a slot of the 4096-slot cache, when the mesh is that large.
            0 if n > 8192 => {
                let b = a % (n as u32 - 8192);
                [b, b + 4096, b + 8192]
            }
            1 if n > 4096 => {
                let b = a % (n as u32 - 4096);
                [b, pick(), b + 4096]
            }
            2 => [a, a, pick()], // degenerate
            _ => [a, pick(), pick()],
        };
        m.indices.extend(corners);
    }
    m
}

fn set_arrays(m: &Mesh) {
    unsafe {
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, m.positions.as_ptr().cast());
        glNormalPointer(GL_FLOAT, 0, m.normals.as_ptr().cast());
        glColorPointer(4, GL_FLOAT, 0, m.colors.as_ptr().cast());
        glTexCoordPointer(2, GL_FLOAT, 0, m.tex_coords.as_ptr().cast());
    }
}

/// The state of one run: what the mesh path specializes on.
#[derive(Clone, Copy, Debug)]
struct Config {
    cull: Option<GLenum>,
    front_face: GLenum,
    flat: bool,
    user_planes: bool,
}

fn configs() -> Vec<Config> {
    let mut all = Vec::new();
    for cull in [None, Some(GL_BACK), Some(GL_FRONT), Some(GL_FRONT_AND_BACK)] {
        for front_face in [GL_CCW, GL_CW] {
            for flat in [false, true] {
                for user_planes in [false, true] {
                    all.push(Config {
                        cull,
                        front_face,
                        flat,
                        user_planes,
                    });
                }
            }
        }
    }
    all
}

fn apply(config: Config) {
    unsafe {
        match config.cull {
            Some(mode) => {
                glEnable(GL_CULL_FACE);
                glCullFace(mode);
            }
            None => glDisable(GL_CULL_FACE),
        }
        glFrontFace(config.front_face);
        glShadeModel(if config.flat { GL_FLAT } else { GL_SMOOTH });
        if config.user_planes {
            // Set with the modelview of the draw: two planes across the mesh.
            glClipPlane(GL_CLIP_PLANE0, [1.0, 0.3, 0.0, 1.0].as_ptr());
            glClipPlane(GL_CLIP_PLANE1, [-0.2, -1.0, 0.5, 1.5].as_ptr());
            glEnable(GL_CLIP_PLANE0);
            glEnable(GL_CLIP_PLANE1);
        } else {
            glDisable(GL_CLIP_PLANE0);
            glDisable(GL_CLIP_PLANE1);
        }
    }
}

/// What a draw gave: glRenderMode's result and the whole buffer (canaries after the size).
type Result = (i32, Vec<u32>);

/// Feeds back `draw` into a buffer of `size` values of `kind` (with capture on: the general
/// path).
fn feedback(kind: GLenum, size: usize, general: bool, draw: &dyn Fn()) -> Result {
    let mut buffer = vec![-7.5f32; size + 16];
    unsafe {
        glFeedbackBuffer(size as GLsizei, kind, buffer.as_mut_ptr());
        glRenderMode(GL_FEEDBACK);
        if general {
            fflCaptureBegin();
        }
        draw();
        if general {
            fflCaptureEnd();
        }
    }
    let count = unsafe { glRenderMode(GL_RENDER) };
    assert_eq!(error(), "GL_NO_ERROR");
    (count, buffer.iter().map(|v| v.to_bits()).collect())
}

/// Selects `draw` in two name scopes (with capture on: the general path).
fn select(general: bool, draw: &dyn Fn()) -> Result {
    let mut buffer = vec![0xdead_beefu32; 64];
    unsafe {
        glSelectBuffer(48, buffer.as_mut_ptr());
        glRenderMode(GL_SELECT);
        glInitNames();
        glPushName(1);
        if general {
            fflCaptureBegin();
        }
        draw();
        glLoadName(2);
        draw();
        if general {
            fflCaptureEnd();
        }
    }
    let count = unsafe { glRenderMode(GL_RENDER) };
    assert_eq!(error(), "GL_NO_ERROR");
    (count, buffer)
}

fn draw_elements(indices: &[u32]) {
    unsafe {
        glDrawElements(
            GL_TRIANGLES,
            indices.len() as GLsizei,
            GL_UNSIGNED_INT,
            indices.as_ptr().cast(),
        )
    };
}

/// Asserts that two draws gave the same count and buffer, bit for bit; else names the first
/// value that differs, after `what`.
fn assert_same(a: &Result, b: &Result, what: impl std::fmt::Display) {
    if a == b {
        return;
    }
    match a.1.iter().zip(&b.1).position(|(x, y)| x != y) {
        Some(i) => panic!(
            "{what}: counts {} and {}, value {i}: {} and {}",
            a.0,
            b.0,
            f32::from_bits(a.1[i]),
            f32::from_bits(b.1[i])
        ),
        None => panic!("{what}: counts {} and {}", a.0, b.0),
    }
}

/// Configurations, each with one feedback type in turn and with selection: the mesh path
/// equals the general path bit for bit, and draws something unless both faces are culled.
#[test]
fn mesh_path_equals_general_path() {
    set_lit_state();
    // 9000 vertices (corners 8192 apart exist), 20 rows of cells drawn: about 4,300 triangles.
    let m = mesh(100, 90, 20, 300);
    set_arrays(&m);
    let draw = || draw_elements(&m.indices);
    let size = m.indices.len() * 40;
    // Every third configuration: each value of each setting, in varied combinations.
    for (k, config) in configs().into_iter().enumerate().step_by(3) {
        apply(config);
        let kind = FEEDBACK_TYPES[k % FEEDBACK_TYPES.len()];
        let fast = feedback(kind, size, false, &draw);
        let general = feedback(kind, size, true, &draw);
        assert_same(&fast, &general, format_args!("{config:?} type {kind:#x}"));
        let drawn = config.cull != Some(GL_FRONT_AND_BACK);
        assert_eq!(fast.0 > 0, drawn, "{config:?}: something is drawn");
        let fast = select(false, &draw);
        let general = select(true, &draw);
        assert_eq!(fast, general, "{config:?} selection");
        assert_eq!(fast.0 > 0, drawn, "{config:?}: a hit");
    }
}

/// The view volume cuts some triangles, rejects others and keeps others whole: the mesh
/// takes all three ways (so the test above covers them).
#[test]
fn the_mesh_straddles_the_view_volume() {
    set_lit_state();
    let m = mesh(60, 60, 60, 0);
    set_arrays(&m);
    let triangles = m.indices.len() / 3;
    let (count, values) = feedback(GL_2D, triangles * 8 * 4, false, &|| {
        draw_elements(&m.indices)
    });
    // GL_POLYGON_TOKEN, 3, then three (x, y): clipped polygons come as triangles too.
    let mut fed = 0;
    let mut on_edge = 0;
    for polygon in values[..count as usize].chunks(8) {
        assert_eq!(f32::from_bits(polygon[0]), GL_POLYGON_TOKEN as f32);
        assert_eq!(f32::from_bits(polygon[1]), 3.0);
        fed += 1;
        let near_edge = |v: f32| v.abs() < 1e-3 || (v - 64.0).abs() < 1e-3;
        on_edge += polygon[2..]
            .iter()
            .filter(|&&v| near_edge(f32::from_bits(v)))
            .count();
    }
    assert!(
        fed > triangles / 4 && fed < triangles,
        "{fed} of {triangles}"
    );
    assert!(on_edge > 100, "{on_edge} corners on the window's edges");
}

/// A buffer too small: the values that fit, then -1, the same whichever path.
#[test]
fn overflow_is_the_same_on_both_paths() {
    set_lit_state();
    let m = mesh(40, 30, 30, 50);
    set_arrays(&m);
    let draw = || draw_elements(&m.indices);
    for kind in FEEDBACK_TYPES {
        for size in [0, 5, 23, 4001] {
            let fast = feedback(kind, size, false, &draw);
            let general = feedback(kind, size, true, &draw);
            assert_same(&fast, &general, format_args!("type {kind:#x} size {size}"));
            assert_eq!(fast.0, -1, "type {kind:#x} size {size} overflows");
        }
    }
}

/// A draw to run in either mode.
type Draw<'a> = Box<dyn Fn() + 'a>;

/// Byte and short indices (read three at a time by the generic loop), and counts that are not
/// a multiple of 3.
#[test]
fn other_index_types_and_partial_triangles() {
    set_lit_state();
    let m = mesh(16, 16, 16, 40);
    set_arrays(&m);
    for drop in 0..3 {
        let indices = &m.indices[..m.indices.len() - drop];
        let bytes: Vec<u8> = indices.iter().map(|&i| i as u8).collect();
        let shorts: Vec<u16> = indices.iter().map(|&i| i as u16).collect();
        let draws: [(&str, Draw); 2] = [
            (
                "bytes",
                Box::new(|| unsafe {
                    glDrawElements(
                        GL_TRIANGLES,
                        bytes.len() as GLsizei,
                        GL_UNSIGNED_BYTE,
                        bytes.as_ptr().cast(),
                    )
                }),
            ),
            (
                "shorts",
                Box::new(|| unsafe {
                    glDrawElements(
                        GL_TRIANGLES,
                        shorts.len() as GLsizei,
                        GL_UNSIGNED_SHORT,
                        shorts.as_ptr().cast(),
                    )
                }),
            ),
        ];
        for (what, draw) in &draws {
            let fast = feedback(GL_3D_COLOR, 100_000, false, draw);
            let general = feedback(GL_3D_COLOR, 100_000, true, draw);
            assert_same(&fast, &general, format_args!("{what}, {drop} dropped"));
            assert!(fast.0 > 0);
        }
    }
}

/// The indexed draw against glDrawArrays of the same vertices one by one (a different path
/// through lighting as well as assembly).
#[test]
fn mesh_path_equals_a_draw_of_the_vertices_in_order() {
    set_lit_state();
    let m = mesh(70, 70, 70, 300);
    let expanded = Mesh {
        positions: m
            .indices
            .iter()
            .flat_map(|&i| m.positions[3 * i as usize..][..3].to_vec())
            .collect(),
        normals: m
            .indices
            .iter()
            .flat_map(|&i| m.normals[3 * i as usize..][..3].to_vec())
            .collect(),
        colors: m
            .indices
            .iter()
            .flat_map(|&i| m.colors[4 * i as usize..][..4].to_vec())
            .collect(),
        tex_coords: m
            .indices
            .iter()
            .flat_map(|&i| m.tex_coords[2 * i as usize..][..2].to_vec())
            .collect(),
        indices: Vec::new(),
    };
    let size = m.indices.len() * 40;
    for config in configs().into_iter().step_by(11) {
        apply(config);
        set_arrays(&m);
        let indexed = feedback(GL_4D_COLOR_TEXTURE, size, false, &|| {
            draw_elements(&m.indices)
        });
        set_arrays(&expanded);
        let in_order = feedback(GL_4D_COLOR_TEXTURE, size, false, &|| unsafe {
            glDrawArrays(GL_TRIANGLES, 0, m.indices.len() as GLsizei)
        });
        assert_same(&indexed, &in_order, format_args!("{config:?}"));
    }
}

/// A draw large enough to be split into chunks on several threads gives the one-thread result
/// bit for bit, whatever the thread count: feedback (clipped, culled, flat, overflowing) and
/// selection. (The thread count is process-wide; the other tests' results do not depend on it.)
#[test]
fn threaded_draws_equal_one_thread() {
    set_lit_state();
    // 150 x 120 vertices: about 37,000 triangles, three chunks (of 16384).
    let m = mesh(150, 120, 120, 2000);
    set_arrays(&m);
    let draw = || draw_elements(&m.indices);
    let size = m.indices.len() * 40;
    // Culling back faces, clockwise, two user planes.
    let config = configs()[13];
    apply(config);
    let kind = GL_3D_COLOR;
    let run = |threads: i32| {
        unsafe { fflSetThreads(threads) };
        let all = feedback(kind, size, false, &draw);
        // Overflowing in the second chunk.
        let part = feedback(kind, all.0 as usize / 2 + 7, false, &draw);
        (all, part, select(false, &draw))
    };
    let one = run(1);
    assert!(one.0.0 > 0 && one.1.0 == -1, "{config:?}");
    for threads in [2, 3] {
        let many = run(threads);
        assert_same(
            &many.0,
            &one.0,
            format_args!("{config:?}, {threads} threads"),
        );
        assert_same(
            &many.1,
            &one.1,
            format_args!("{config:?} overflow, {threads} threads"),
        );
        assert_eq!(many.2, one.2, "{config:?} selection, {threads} threads");
    }
    unsafe { fflSetThreads(0) };
}

/// The context keeps a large draw's chunk outputs and helper caches for its next
/// (`pipeline::mesh::MeshThreads`): draws after the first, into whose outputs the first wrote,
/// of more chunks than outputs (so that kept ones are filled again) and in other feedback
/// types, give the one-thread result bit for bit.
#[test]
fn threaded_draws_reuse_their_buffers() {
    set_lit_state();
    // 300 x 150 vertices: about 89,000 triangles, six chunks (of 16384).
    let m = mesh(300, 150, 150, 500);
    set_arrays(&m);
    let draw = || draw_elements(&m.indices);
    let size = m.indices.len() * 40;
    apply(configs()[5]);
    let run = |threads: i32| {
        unsafe { fflSetThreads(threads) };
        [GL_3D_COLOR, GL_4D_COLOR_TEXTURE, GL_3D_COLOR, GL_2D]
            .map(|kind| feedback(kind, size, false, &draw))
    };
    let one = run(1);
    let many = run(2);
    unsafe { fflSetThreads(0) };
    for (k, (many, one)) in many.iter().zip(&one).enumerate() {
        assert!(one.0 > 0, "draw {k}");
        assert_same(many, one, format_args!("draw {k}, 2 threads"));
    }
}

/// Large glDrawArrays(GL_POINTS) into the application's feedback buffer, split into chunks
/// that the threads lay out and copy into their places (`pipeline::points`): the one-thread
/// buffer bit for bit, canaries past the count included, in every feedback layout, with
/// points culled by the view volume and by user planes (so that each chunk lands below the
/// place all-drawn points would take), and overflowing halfway.
#[test]
fn threaded_points_fill_the_buffer_as_one_thread() {
    set_lit_state();
    // 52,000 points: enough for three threads, 26 chunks.
    let m = mesh(400, 130, 0, 0);
    set_arrays(&m);
    let n = m.positions.len() / 3;
    let draw = || unsafe { glDrawArrays(GL_POINTS, 0, n as GLsizei) };
    for user_planes in [false, true] {
        apply(Config {
            cull: None,
            front_face: GL_CCW,
            flat: false,
            user_planes,
        });
        for kind in FEEDBACK_TYPES {
            let run = |threads: i32| {
                unsafe { fflSetThreads(threads) };
                let all = feedback(kind, 14 * n, false, &draw);
                let part = feedback(kind, all.0 as usize / 2 + 7, false, &draw);
                (all, part)
            };
            let one = run(1);
            assert!(one.0.0 > 0 && one.1.0 == -1, "{kind:#x}");
            // GL_POINT_TOKEN and the vertex's values.
            let per_point = match kind {
                GL_2D => 3,
                GL_3D => 4,
                GL_3D_COLOR => 8,
                GL_3D_COLOR_TEXTURE => 12,
                _ => 13,
            };
            let drawn = one.0.0 / per_point;
            assert_eq!(drawn * per_point, one.0.0, "{kind:#x}");
            assert!(
                drawn < n as i32 * 9 / 10,
                "{kind:#x}: {drawn} of {n} points drawn"
            );
            for threads in [2, 3] {
                let many = run(threads);
                let what = format!("{kind:#x}, planes {user_planes}, {threads} threads");
                assert_same(&many.0, &one.0, &what);
                assert_same(&many.1, &one.1, format_args!("{what} overflow"));
            }
        }
    }
    unsafe { fflSetThreads(0) };
}
