//! The capture API: bulk lighting (fflLightVertices, Context::light_vertices) bit-identical to
//! immediate mode, and captured primitives that match what feedback draws.

#[path = "common/gl_api.rs"]
mod gl_api;

use std::ptr::{null, null_mut};

use fflight::current::with_current;
use fflight::gl::*;
use fflight::pipeline::capture::CapturedPrimitive;
use fflight::pipeline::vertex::ProcessedVertex;
use fflight::threads::MIN_VERTICES_PER_THREAD;
use gl_api::*;
use glam::{Vec3, Vec4};

/// Random inputs for `count` vertices: positions of `size` floats, normals, RGBA colors.
fn inputs(rng: &mut Rng, count: usize, size: usize) -> (Vec<f32>, Vec<f32>, Vec<f32>) {
    let mut floats = |n: usize, lo: f64, hi: f64| -> Vec<f32> {
        (0..n).map(|_| rng.range(lo, hi) as f32).collect()
    };
    (
        floats(count * size, -3.0, 3.0),
        floats(count * 3, -1.5, 1.5),
        floats(count * 4, -0.2, 1.2),
    )
}

/// What immediate mode makes of the inputs: glBegin(GL_POINTS), then per vertex glColor4fv
/// (unless `colors` is None), glNormal3fv (unless None), glVertex{2,3,4}fv, glEnd; captured.
fn immediate(
    size: usize,
    positions: &[f32],
    normals: Option<&[f32]>,
    colors: Option<&[f32]>,
) -> Vec<ProcessedVertex> {
    reset_current();
    unsafe {
        fflCaptureBegin();
        glBegin(GL_POINTS);
        for (i, position) in positions.chunks_exact(size).enumerate() {
            if let Some(colors) = colors {
                glColor4fv(colors[4 * i..].as_ptr());
            }
            if let Some(normals) = normals {
                glNormal3fv(normals[3 * i..].as_ptr());
            }
            match size {
                2 => glVertex2fv(position.as_ptr()),
                3 => glVertex3fv(position.as_ptr()),
                _ => glVertex4fv(position.as_ptr()),
            }
        }
        glEnd();
        fflCaptureEnd();
    }
    assert_eq!(error(), "GL_NO_ERROR");
    reset_current();
    captured().0
}

/// The six outputs of the bulk call for one vertex: eye, clip, front primary, front
/// secondary, back primary, back secondary.
fn outputs_of(v: &ProcessedVertex) -> [[f32; 4]; 6] {
    [
        v.eye,
        v.clip,
        v.colors.front.primary,
        v.colors.front.secondary,
        v.colors.back.primary,
        v.colors.back.secondary,
    ]
    .map(|c| c.to_array())
}

fn bits(values: &[[f32; 4]]) -> Vec<u32> {
    values.iter().flatten().map(|v| v.to_bits()).collect()
}

#[test]
fn bulk_lighting_equals_immediate_mode_exactly() {
    for lit in [true, false] {
        if lit {
            set_lit_state();
        } else {
            unsafe { glDisable(GL_LIGHTING) };
        }
        let mut rng = Rng(2024 + lit as u64);
        let count = 101;
        for size in 2..=4 {
            let (positions, normals, colors) = inputs(&mut rng, count, size);
            for (with_normals, with_colors) in
                [(true, true), (false, true), (true, false), (false, false)]
            {
                let normals = with_normals.then_some(&normals[..]);
                let colors = with_colors.then_some(&colors[..]);
                let what =
                    format!("lit {lit} size {size} normals {with_normals} colors {with_colors}");
                let expected: Vec<[[f32; 4]; 6]> = immediate(size, &positions, normals, colors)
                    .iter()
                    .map(outputs_of)
                    .collect();

                // Packed inputs, outputs interleaved in one array of six vec4s per vertex.
                let mut interleaved = vec![[[f32::NAN; 4]; 6]; count + 1];
                let out = interleaved.as_mut_ptr().cast::<f32>();
                let stride = 96;
                unsafe {
                    fflLightVertices(
                        count as GLsizei,
                        size as GLint,
                        positions.as_ptr(),
                        0,
                        normals.map_or(null(), |n| n.as_ptr()),
                        0,
                        colors.map_or(null(), |c| c.as_ptr()),
                        0,
                        out,
                        stride,
                        out.add(4),
                        stride,
                        out.add(8),
                        stride,
                        out.add(12),
                        stride,
                        out.add(16),
                        stride,
                        out.add(20),
                        stride,
                    )
                };
                assert_eq!(error(), "GL_NO_ERROR", "{what}");
                for (i, (got, want)) in interleaved.iter().zip(&expected).enumerate() {
                    assert_eq!(
                        bits(got),
                        bits(want),
                        "{what}: vertex {i}:\n{got:?}\n{want:?}"
                    );
                }
                assert!(
                    interleaved[count].iter().flatten().all(|v| v.is_nan()),
                    "{what}: wrote past count"
                );

                // Inputs interleaved with padding (unaligned), separate packed outputs.
                let record = 4 * size + 12 + 16 + 5;
                let mut packed_in = vec![0xEEu8; count * record];
                for i in 0..count {
                    let at = i * record;
                    let mut put = |offset: usize, values: &[f32]| {
                        for (k, v) in values.iter().enumerate() {
                            let p = at + offset + 4 * k;
                            packed_in[p..p + 4].copy_from_slice(&v.to_ne_bytes());
                        }
                    };
                    put(1, &positions[size * i..size * (i + 1)]);
                    if let Some(n) = normals {
                        put(1 + 4 * size, &n[3 * i..3 * i + 3]);
                    }
                    if let Some(c) = colors {
                        put(1 + 4 * size + 12, &c[4 * i..4 * i + 4]);
                    }
                }
                let base = packed_in.as_ptr();
                let mut separate: Vec<[[f32; 4]; 6]> = Vec::new();
                let mut columns = vec![vec![[0.0f32; 4]; count]; 6];
                let ptrs: Vec<*mut f32> =
                    columns.iter_mut().map(|c| c.as_mut_ptr().cast()).collect();
                unsafe {
                    fflLightVertices(
                        count as GLsizei,
                        size as GLint,
                        base.add(1).cast(),
                        record as GLsizei,
                        if with_normals {
                            base.add(1 + 4 * size).cast()
                        } else {
                            null()
                        },
                        record as GLsizei,
                        if with_colors {
                            base.add(1 + 4 * size + 12).cast()
                        } else {
                            null()
                        },
                        record as GLsizei,
                        ptrs[0],
                        0,
                        ptrs[1],
                        16,
                        ptrs[2],
                        0,
                        ptrs[3],
                        0,
                        ptrs[4],
                        0,
                        ptrs[5],
                        0,
                    )
                };
                assert_eq!(error(), "GL_NO_ERROR", "{what}");
                separate.extend((0..count).map(|i| std::array::from_fn(|k| columns[k][i])));
                for (i, (got, want)) in separate.iter().zip(&expected).enumerate() {
                    assert_eq!(bits(got), bits(want), "{what}: strided vertex {i}");
                }

                // The Rust API.
                let positions4: Vec<Vec4> = positions
                    .chunks_exact(size)
                    .map(|p| {
                        let mut v = [0.0, 0.0, 0.0, 1.0];
                        v[..size].copy_from_slice(p);
                        Vec4::from_array(v)
                    })
                    .collect();
                let normals3: Option<Vec<Vec3>> =
                    normals.map(|n| n.chunks_exact(3).map(Vec3::from_slice).collect());
                let colors4: Option<Vec<Vec4>> =
                    colors.map(|c| c.chunks_exact(4).map(Vec4::from_slice).collect());
                let rust = with_current(|ctx| {
                    let mut out = vec![immediate_placeholder(); count];
                    ctx.light_vertices(
                        &positions4,
                        normals3.as_deref(),
                        colors4.as_deref(),
                        &mut out,
                    )
                    .unwrap();
                    out
                })
                .unwrap();
                let rust: Vec<_> = rust.iter().map(outputs_of).collect();
                assert_eq!(
                    bits(&rust.concat()),
                    bits(&expected.concat()),
                    "{what}: Rust API"
                );
            }
        }
    }
}

fn immediate_placeholder() -> ProcessedVertex {
    let colors = fflight::lighting::FaceColors {
        primary: Vec4::ZERO,
        secondary: Vec4::ZERO,
    };
    ProcessedVertex {
        eye: Vec4::ZERO,
        clip: Vec4::ZERO,
        colors: fflight::lighting::LitVertex {
            front: colors,
            back: colors,
        },
        tex_coord: Vec4::ZERO,
        edge_flag: false,
    }
}

#[test]
fn bulk_lighting_leaves_state_alone_and_skips_null_outputs() {
    set_lit_state();
    reset_current();
    let before = current_attribs();
    let positions = [0.5f32, 0.25, -1.0, 1.0, 2.0, 3.0];
    let colors = [1.0f32, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0];
    let mut clip = [[7.0f32; 4]; 3];
    let mut feedback = [0.0f32; 64];
    unsafe {
        glFeedbackBuffer(64, GL_3D_COLOR, feedback.as_mut_ptr());
        glRenderMode(GL_FEEDBACK);
        fflCaptureBegin();
        fflLightVertices(
            2,
            3,
            positions.as_ptr(),
            0,
            null(),
            0,
            colors.as_ptr(),
            0,
            null_mut(),
            0,
            clip.as_mut_ptr().cast(),
            0,
            null_mut(),
            0,
            null_mut(),
            0,
            null_mut(),
            0,
            null_mut(),
            0,
        );
        fflCaptureEnd();
    }
    assert_eq!(unsafe { glRenderMode(GL_RENDER) }, 0, "nothing fed back");
    assert_eq!(error(), "GL_NO_ERROR");
    assert_eq!(captured().0.len(), 0, "nothing captured");
    assert_eq!(current_attribs(), before, "current attributes unchanged");
    assert_ne!(clip[0], [7.0; 4]);
    assert_ne!(clip[1], [7.0; 4]);
    assert_eq!(clip[2], [7.0; 4], "nothing written past count");
}

#[test]
fn bulk_lighting_errors() {
    let p = [0.0f32; 16];
    let mut out = [0.0f32; 16];
    let call = |count: GLsizei,
                size: GLint,
                positions: *const f32,
                stride: GLsizei,
                out_stride: GLsizei,
                out: *mut f32| unsafe {
        fflLightVertices(
            count,
            size,
            positions,
            stride,
            null(),
            0,
            null(),
            0,
            out,
            out_stride,
            null_mut(),
            0,
            null_mut(),
            0,
            null_mut(),
            0,
            null_mut(),
            0,
            null_mut(),
            0,
        )
    };
    let o = out.as_mut_ptr();
    call(-1, 3, p.as_ptr(), 0, 0, o);
    assert_eq!(error(), "GL_INVALID_VALUE", "negative count");
    call(1, 1, p.as_ptr(), 0, 0, o);
    assert_eq!(error(), "GL_INVALID_VALUE", "size 1");
    call(1, 5, p.as_ptr(), 0, 0, o);
    assert_eq!(error(), "GL_INVALID_VALUE", "size 5");
    call(1, 3, p.as_ptr(), -4, 0, o);
    assert_eq!(error(), "GL_INVALID_VALUE", "negative input stride");
    call(1, 3, p.as_ptr(), 0, -16, o);
    assert_eq!(error(), "GL_INVALID_VALUE", "negative output stride");
    call(1, 3, null(), 0, 0, o);
    assert_eq!(error(), "GL_INVALID_VALUE", "NULL positions");
    call(0, 3, null(), 0, 0, o);
    assert_eq!(error(), "GL_NO_ERROR", "nothing to light");
    unsafe { glBegin(GL_POINTS) };
    call(1, 3, p.as_ptr(), 0, 0, o);
    unsafe { glEnd() };
    assert_eq!(error(), "GL_INVALID_OPERATION", "inside glBegin/glEnd");
    assert_eq!(out, [0.0; 16], "no error call wrote anything");
    let mut ctx = fflight::Context::new();
    let mut short = vec![immediate_placeholder(); 1];
    assert_eq!(
        ctx.light_vertices(&[Vec4::W, Vec4::W], None, None, &mut short),
        Err(fflight::GlError::InvalidValue)
    );
}

/// Feedback's tokens for the captured primitives of one draw, when nothing is clipped or
/// culled, polygons are filled and shading is smooth: the primitives GL draws.
fn expected_feedback(
    primitives: &[CapturedPrimitive],
    vertices: &[ProcessedVertex],
    window: impl Fn(Vec4) -> Vec4,
) -> Vec<f32> {
    let mut out = Vec::new();
    let mut first_line = true;
    for p in primitives {
        match p.kind {
            GL_POINTS => out.push(GL_POINT_TOKEN as f32),
            GL_LINES => {
                let reset = p.mode == GL_LINES || first_line;
                first_line = false;
                out.push(if reset {
                    GL_LINE_RESET_TOKEN
                } else {
                    GL_LINE_TOKEN
                } as f32);
            }
            _ => out.extend([GL_POLYGON_TOKEN as f32, 3.0]),
        }
        for &index in &p.vertices[..p.vertex_count()] {
            let v = &vertices[index];
            out.extend(window(v.clip).to_array());
            out.extend(v.colors.front.primary.to_array());
            out.extend(v.tex_coord.to_array());
        }
    }
    out
}

#[test]
fn captured_primitives_are_the_primitives_drawn() {
    set_lit_state();
    unsafe { glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0) };
    let (width, height) = (64.0f32, 64.0f32);
    let window = |clip: Vec4| {
        let ndc = clip.truncate() / clip.w;
        Vec4::new(
            (ndc.x + 1.0) * width / 2.0,
            (ndc.y + 1.0) * height / 2.0,
            (ndc.z + 1.0) / 2.0,
            clip.w,
        )
    };
    let mut rng = Rng(99);
    for mode in GL_POINTS..=GL_POLYGON {
        for arrays in [false, true] {
            // A convex fan of vertices well inside the view volume (polygons must be convex).
            let count = 9;
            let positions: Vec<f32> = (0..count)
                .flat_map(|i| {
                    let angle = i as f32 * 0.6;
                    [
                        angle.cos(),
                        angle.sin(),
                        -0.5 - 0.1 * rng.range(0.0, 1.0) as f32,
                    ]
                })
                .collect();
            let mut buffer = vec![0.0f32; 4096];
            unsafe {
                glFeedbackBuffer(4096, GL_4D_COLOR_TEXTURE, buffer.as_mut_ptr());
                glRenderMode(GL_FEEDBACK);
                fflCaptureBegin();
                if arrays {
                    glVertexPointer(3, GL_FLOAT, 0, positions.as_ptr().cast());
                    glEnableClientState(GL_VERTEX_ARRAY);
                    let indices: Vec<u16> = (0..count as u16).collect();
                    glDrawElements(
                        mode,
                        count as GLsizei,
                        GL_UNSIGNED_SHORT,
                        indices.as_ptr().cast(),
                    );
                } else {
                    glBegin(mode);
                    for (i, p) in positions.chunks_exact(3).enumerate() {
                        glColor4f(0.1 * i as f32, 0.5, 0.9 - 0.1 * i as f32, 1.0);
                        glNormal3f(0.0, 0.3, 1.0);
                        glTexCoord4f(i as f32, 0.5, 0.0, 1.0);
                        glVertex3f(p[0] * 2.0, p[1] * 2.0, p[2] * 4.0 - 2.0);
                    }
                    glEnd();
                }
                fflCaptureEnd();
            }
            let n = unsafe { glRenderMode(GL_RENDER) };
            assert_eq!(error(), "GL_NO_ERROR");
            let fed = &buffer[..n as usize];
            let (vertices, primitives) = captured();
            assert_eq!(vertices.len(), count);
            let expected = expected_feedback(&primitives, &vertices, window);
            let what = format!("mode {mode} arrays {arrays}");
            assert_eq!(
                fed.len(),
                expected.len(),
                "{what}: feedback values\n{fed:?}\n{expected:?}"
            );
            for (k, (a, b)) in fed.iter().zip(&expected).enumerate() {
                assert!(
                    (a - b).abs() <= 1e-4 * b.abs().max(1.0),
                    "{what}: value {k}: {a} vs {b}"
                );
            }
            let kinds = match mode {
                GL_POINTS => GL_POINTS,
                GL_LINES | GL_LINE_STRIP | GL_LINE_LOOP => GL_LINES,
                _ => GL_TRIANGLES,
            };
            assert!(
                primitives
                    .iter()
                    .all(|p| p.kind == kinds && p.mode == mode && p.draw == 0)
            );
            let expected_count = match mode {
                GL_POINTS => 9,
                GL_LINES => 4,
                GL_LINE_LOOP => 9,
                GL_LINE_STRIP => 8,
                GL_TRIANGLES => 3,
                GL_QUADS => 4,
                GL_QUAD_STRIP => 6,
                _ => 7,
            };
            assert_eq!(primitives.len(), expected_count, "{what}");
        }
    }
}

#[test]
fn capture_collects_draws_in_order_and_only_while_on() {
    let quad = |z: f32| unsafe {
        glBegin(GL_QUADS);
        glVertex3f(0.0, 0.0, z);
        glVertex3f(1.0, 0.0, z);
        glEdgeFlag(GL_FALSE);
        glVertex3f(1.0, 1.0, z);
        glEdgeFlag(GL_TRUE);
        glVertex3f(0.0, 1.0, z);
        glEnd();
    };
    quad(-1.0);
    assert_eq!(captured().0.len(), 0, "off by default");
    unsafe { fflCaptureBegin() };
    quad(-2.0);
    unsafe {
        glBegin(GL_TRIANGLES); // incomplete: vertices but no primitive
        glVertex3f(0.0, 0.0, 0.0);
        glVertex3f(1.0, 0.0, 0.0);
        glEnd();
        glBegin(GL_TRIANGLE_STRIP);
        glEdgeFlag(GL_FALSE);
        for i in 0..4 {
            glVertex3f(i as f32, (i % 2) as f32, -3.0);
        }
        glEdgeFlag(GL_TRUE);
        glEnd();
        fflCaptureEnd();
    }
    quad(-4.0);
    assert_eq!(error(), "GL_NO_ERROR");
    let (vertices, primitives) = captured();
    assert_eq!(vertices.len(), 4 + 2 + 4);
    assert_eq!(with_current(|ctx| ctx.captured().draws()).unwrap(), 3);
    assert_eq!(vertices[0].eye.z, -2.0);
    let triangle =
        |draw: usize, vertices: [usize; 3], edges: [bool; 3], mode: GLenum| CapturedPrimitive {
            kind: GL_TRIANGLES,
            mode,
            draw,
            vertices,
            edges,
        };
    assert_eq!(
        primitives,
        [
            // The quad's two triangles, as feedback splits them: the inner edge is not
            // drawn, nor the edge from the vertex whose edge flag is off.
            triangle(0, [0, 1, 3], [true, false, true], GL_QUADS),
            triangle(0, [1, 2, 3], [true, false, false], GL_QUADS),
            // The strip: every edge is drawn whatever the edge flags (§2.6.2).
            triangle(2, [6, 7, 8], [true; 3], GL_TRIANGLE_STRIP),
            triangle(2, [8, 7, 9], [true; 3], GL_TRIANGLE_STRIP),
        ]
    );
    assert!(
        !vertices[8].edge_flag,
        "the vertex keeps the edge flag it was given"
    );

    // Begin drops the earlier capture; both are refused between glBegin and glEnd.
    unsafe {
        fflCaptureBegin();
        glBegin(GL_POINTS);
        fflCaptureEnd();
        fflCaptureBegin();
        glVertex3f(0.0, 0.0, 0.0);
        glEnd();
    }
    assert_eq!(error(), "GL_INVALID_OPERATION");
    assert_eq!(unsafe { fflCaptureVertexCount() }, 1, "still capturing");
    assert_eq!(unsafe { fflCapturePrimitiveCount() }, 1);
    unsafe { fflCaptureEnd() };
    assert_eq!(error(), "GL_NO_ERROR");
}

unsafe extern "C" {
    fn fflSetThreads(count: GLint);
}

/// Where an array of a bulk call lives in its buffer: `stride` bytes apart (0: packed) from
/// byte `offset`.
#[derive(Clone, Copy, Debug)]
struct Placed {
    stride: usize,
    offset: usize,
}

const fn at(stride: usize, offset: usize) -> Option<Placed> {
    Some(Placed { stride, offset })
}

/// One layout of fflLightVertices' arrays: the position size and the places of the
/// positions, normals, colors (None: NULL) and of the six outputs (None: NULL), each in an
/// array of its own or, `shared`, all in one array of structs.
struct BulkCase {
    size: usize,
    positions: Placed,
    normals: Option<Placed>,
    colors: Option<Placed>,
    outputs: [Option<Placed>; 6],
    shared: bool,
}

impl Placed {
    fn stride(&self, floats: usize) -> usize {
        if self.stride == 0 {
            4 * floats
        } else {
            self.stride
        }
    }

    /// Bytes of `count` elements of `floats` floats: up to the end of the last one.
    fn end(&self, count: usize, floats: usize) -> usize {
        self.offset
            + count.saturating_sub(1) * self.stride(floats)
            + 4 * floats * (count > 0) as usize
    }
}

/// `count` random elements of `floats` floats placed in a buffer that ends where the last
/// element does (a read past it panics), and the elements as read back (elements that
/// overlap share floats).
fn placed_input(
    rng: &mut Rng,
    place: Placed,
    count: usize,
    floats: usize,
    lo: f64,
    hi: f64,
) -> (Vec<u8>, Vec<f32>) {
    let mut bytes = vec![0u8; place.end(count, floats)];
    let float_at = |i: usize, k: usize| place.offset + i * place.stride(floats) + 4 * k;
    for i in 0..count {
        for k in 0..floats {
            let v = rng.range(lo, hi) as f32;
            bytes[float_at(i, k)..][..4].copy_from_slice(&v.to_ne_bytes());
        }
    }
    let elements = (0..count)
        .flat_map(|i| (0..floats).map(move |k| (i, k)))
        .map(|(i, k)| f32::from_ne_bytes(bytes[float_at(i, k)..][..4].try_into().unwrap()))
        .collect();
    (bytes, elements)
}

/// fflLightVertices over every kind of layout it accepts (position sizes 2 to 4; packed,
/// padded, unaligned, overlapping and wide strides; NULL normals and colors; any subset of
/// the outputs, packed, strided or interleaved in one array of structs), at counts around the
/// block (8) and the chunk (128) sizes and on two threads: every output bit-identical to
/// immediate mode, and no byte of the output buffer written outside the outputs' elements.
#[test]
fn bulk_lighting_reads_and_writes_every_layout() {
    set_lit_state();
    let none = None;
    let all_six = |stride: usize| std::array::from_fn(|k| at(stride, 16 * k));
    let cases = [
        // The bench's: packed positions and normals, clip positions and front colors.
        BulkCase {
            size: 3,
            positions: Placed {
                stride: 0,
                offset: 0,
            },
            normals: at(0, 0),
            colors: none,
            outputs: [none, at(0, 0), at(16, 0), none, none, none],
            shared: false,
        },
        BulkCase {
            size: 2,
            positions: Placed {
                stride: 0,
                offset: 0,
            },
            normals: none,
            colors: at(0, 0),
            outputs: [at(0, 0); 6],
            shared: false,
        },
        BulkCase {
            size: 4,
            positions: Placed {
                stride: 16,
                offset: 0,
            },
            normals: at(12, 0),
            colors: at(16, 0),
            outputs: all_six(96),
            shared: true,
        },
        // Unaligned, padded.
        BulkCase {
            size: 3,
            positions: Placed {
                stride: 21,
                offset: 1,
            },
            normals: at(28, 3),
            colors: at(40, 2),
            outputs: [at(20, 0), none, none, at(36, 4), none, at(64, 8)],
            shared: false,
        },
        // Padded records; outputs interleaved with a gap.
        BulkCase {
            size: 2,
            positions: Placed {
                stride: 12,
                offset: 0,
            },
            normals: at(12, 0),
            colors: none,
            outputs: [none, at(100, 16), none, none, at(100, 64), none],
            shared: true,
        },
        // Wide strides (an element per cache line and more).
        BulkCase {
            size: 4,
            positions: Placed {
                stride: 80,
                offset: 16,
            },
            normals: at(72, 4),
            colors: at(136, 32),
            outputs: [none, none, at(128, 0), none, at(16, 4), at(0, 12)],
            shared: false,
        },
        // Overlapping elements: positions 8 bytes apart share a float.
        BulkCase {
            size: 3,
            positions: Placed {
                stride: 8,
                offset: 0,
            },
            normals: none,
            colors: none,
            outputs: all_six(0x60),
            shared: true,
        },
    ];
    let sentinel = 0xA5u8;
    let mut rng = Rng(77);
    for (c, case) in cases.iter().enumerate() {
        // The unaligned case on two threads too (one case, two threads: its reference is
        // slow under memcheck, make test-valgrind-rust).
        let threaded = 2 * MIN_VERTICES_PER_THREAD + 13;
        let counts = [1, 7, 8, 9, 127, 129, 1003]
            .into_iter()
            .chain((c == 3).then_some(threaded));
        for count in counts {
            let what = format!("case {c} count {count}");
            unsafe { fflSetThreads(if count == threaded { 2 } else { 0 }) };
            let (positions, position_values) =
                placed_input(&mut rng, case.positions, count, case.size, -3.0, 3.0);
            let normals = case
                .normals
                .map(|p| placed_input(&mut rng, p, count, 3, -1.5, 1.5));
            let colors = case
                .colors
                .map(|p| placed_input(&mut rng, p, count, 4, -0.2, 1.2));
            let expected = immediate(
                case.size,
                &position_values,
                normals.as_ref().map(|n| &n.1[..]),
                colors.as_ref().map(|c| &c.1[..]),
            );

            // The outputs one after the other in one buffer (each in its own region, or all
            // interleaved when their places say so), with a guard after the last.
            let region = case
                .outputs
                .iter()
                .flatten()
                .map(|p| p.end(count, 4))
                .max()
                .unwrap_or(0)
                + 64;
            let base = |k: usize| if case.shared { 0 } else { k * region };
            let mut out = vec![sentinel; 6 * region];
            let mut want = out.clone();
            for (k, place) in case.outputs.iter().enumerate() {
                let Some(place) = place else { continue };
                for (i, vertex) in expected.iter().enumerate() {
                    let at = base(k) + place.offset + i * place.stride(4);
                    let value = outputs_of(vertex)[k];
                    for (j, v) in value.iter().enumerate() {
                        want[at + 4 * j..][..4].copy_from_slice(&v.to_ne_bytes());
                    }
                }
            }
            let input = |p: Option<&(Vec<u8>, Vec<f32>)>, place: Option<Placed>| match (p, place) {
                (Some((bytes, _)), Some(place)) => (
                    unsafe { bytes.as_ptr().add(place.offset) }.cast(),
                    place.stride as GLsizei,
                ),
                _ => (null(), 0),
            };
            let (n, n_stride) = input(normals.as_ref(), case.normals);
            let (col, col_stride) = input(colors.as_ref(), case.colors);
            let o = out.as_mut_ptr();
            let output = |k: usize| match case.outputs[k] {
                Some(place) => (
                    unsafe { o.add(base(k) + place.offset) }.cast::<f32>(),
                    place.stride as GLsizei,
                ),
                None => (null_mut(), 0),
            };
            unsafe {
                fflLightVertices(
                    count as GLsizei,
                    case.size as GLint,
                    positions.as_ptr().add(case.positions.offset).cast(),
                    case.positions.stride as GLsizei,
                    n,
                    n_stride,
                    col,
                    col_stride,
                    output(0).0,
                    output(0).1,
                    output(1).0,
                    output(1).1,
                    output(2).0,
                    output(2).1,
                    output(3).0,
                    output(3).1,
                    output(4).0,
                    output(4).1,
                    output(5).0,
                    output(5).1,
                )
            };
            assert_eq!(error(), "GL_NO_ERROR", "{what}");
            // Compared whole first: a search byte by byte takes minutes under memcheck.
            if out != want {
                let byte = (0..out.len()).find(|&b| out[b] != want[b]).unwrap();
                panic!("{what}: byte {byte} of the outputs differs (region size {region})");
            }
        }
    }
    unsafe { fflSetThreads(0) };
}
