//! fflight's capture API: fflCaptureBegin, fflCaptureEnd, fflCaptureVertexCount,
//! fflCapturePrimitiveCount, fflCaptureReadVertices, fflCaptureReadPrimitives,
//! fflCaptureReadTexCoords (every texture unit's coordinates) and the bulk
//! lighting call fflLightVertices (see `commands::capture` and `pipeline::capture`).

use glam::{Mat4, Vec4};

use super::{bulk_lanes, with_context};
use crate::commands::capture::{BulkLayout, FloatLayout};
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::lighting::batch::{Faces, Reads};
use crate::lighting::lanes::{LANES, LanesF32};
use crate::pipeline::block::{Lanes4, OutputBlock};
use crate::pipeline::capture::CapturedPrimitive;
use crate::pipeline::fetch::read_floats;
use crate::pipeline::vertex::ProcessedVertex;
use crate::state::texture::MAX_TEXTURE_UNITS;

/// One captured vertex: positions in eye and clip coordinates, the lit colors of both faces
/// (without two-sided lighting the back colors equal the front ones), texture unit 0's
/// coordinates after generation and the texture matrix (fflCaptureReadTexCoords reads every
/// unit's), and the edge flag it was given.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FflCapturedVertex {
    pub eye: [GLfloat; 4],
    pub clip: [GLfloat; 4],
    pub front_primary: [GLfloat; 4],
    pub front_secondary: [GLfloat; 4],
    pub back_primary: [GLfloat; 4],
    pub back_secondary: [GLfloat; 4],
    pub tex_coord: [GLfloat; 4],
    pub edge_flag: GLboolean,
    /// Zero: the struct has no undefined padding bytes (memcmp works).
    pub reserved: [GLubyte; 3],
}

impl From<&ProcessedVertex> for FflCapturedVertex {
    fn from(v: &ProcessedVertex) -> FflCapturedVertex {
        FflCapturedVertex {
            eye: v.eye.to_array(),
            clip: v.clip.to_array(),
            front_primary: v.colors.front.primary.to_array(),
            front_secondary: v.colors.front.secondary.to_array(),
            back_primary: v.colors.back.primary.to_array(),
            back_secondary: v.colors.back.secondary.to_array(),
            tex_coord: v.tex_coord.to_array(),
            edge_flag: v.edge_flag.into(),
            reserved: [0; 3],
        }
    }
}

/// One captured point, segment or triangle.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FflCapturedPrimitive {
    /// GL_POINTS, GL_LINES or GL_TRIANGLES.
    pub kind: GLenum,
    /// The mode of the draw it came from.
    pub mode: GLenum,
    /// Which draw it came from, counted from 0 since fflCaptureBegin.
    pub draw: GLuint,
    /// 1, 2 or 3: how many of `vertices` are used.
    pub vertex_count: GLuint,
    /// Indices of its vertices for fflCaptureReadVertices; the last used is the provoking
    /// vertex (the one whose colors flat shading uses).
    pub vertices: [GLuint; 3],
    /// Triangles: whether edge k (vertices[k] to the next) is drawn in polygon mode GL_LINE.
    pub edges: [GLboolean; 3],
    /// Zero: the struct has no undefined padding bytes (memcmp works).
    pub reserved: GLubyte,
}

/// A count or index as a GLuint, saturated.
fn gl_uint(n: usize) -> GLuint {
    GLuint::try_from(n).unwrap_or(GLuint::MAX)
}

impl From<&CapturedPrimitive> for FflCapturedPrimitive {
    fn from(p: &CapturedPrimitive) -> FflCapturedPrimitive {
        FflCapturedPrimitive {
            kind: p.kind,
            mode: p.mode,
            draw: gl_uint(p.draw),
            vertex_count: gl_uint(p.vertex_count()),
            vertices: p.vertices.map(gl_uint),
            edges: p.edges.map(GLboolean::from),
            reserved: 0,
        }
    }
}

/// Starts capturing the vertices and primitives of every draw (glBegin/glEnd and vertex
/// array draws), dropping what an earlier capture collected. Primitives are captured after
/// assembly, before clipping; capture does not stop feedback. GL_INVALID_OPERATION between
/// glBegin and glEnd.
#[unsafe(no_mangle)]
pub extern "C" fn fflCaptureBegin() {
    with_context(|ctx| ctx.capture_begin())
}

/// Stops capturing; what was collected stays readable until the next fflCaptureBegin.
/// GL_INVALID_OPERATION between glBegin and glEnd.
#[unsafe(no_mangle)]
pub extern "C" fn fflCaptureEnd() {
    with_context(|ctx| ctx.capture_end())
}

/// How many vertices capture collected (every vertex given to a captured draw).
#[unsafe(no_mangle)]
pub extern "C" fn fflCaptureVertexCount() -> GLuint {
    with_context(|ctx| Ok(gl_uint(ctx.captured().vertices().len())))
}

/// How many primitives capture collected.
#[unsafe(no_mangle)]
pub extern "C" fn fflCapturePrimitiveCount() -> GLuint {
    with_context(|ctx| Ok(gl_uint(ctx.captured().primitives().len())))
}

/// Copies items `first..first + count` of `len` (fewer at the end), each made by `item` from
/// its index, to `out`; returns how many were copied. NULL `out` with a positive count is
/// GL_INVALID_VALUE.
///
/// # Safety
/// A non-NULL `out` must have room for `count` values.
unsafe fn copy_out<C>(
    len: usize,
    first: GLuint,
    count: GLuint,
    out: *mut C,
    item: impl Fn(usize) -> C,
) -> GlResult<GLuint> {
    let first = first as usize;
    let copied = len.saturating_sub(first).min(count as usize);
    if copied == 0 {
        return Ok(0);
    }
    if out.is_null() {
        return Err(GlError::InvalidValue);
    }
    for k in 0..copied {
        // SAFETY: the caller guarantees room for `count` values; k < count.
        unsafe { out.add(k).write_unaligned(item(first + k)) };
    }
    Ok(gl_uint(copied))
}

/// Copies captured vertices `first..first + count` (fewer at the end) to `vertices` and
/// returns how many were copied.
///
/// # Safety
/// `vertices` is NULL or has room for `count` values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fflCaptureReadVertices(
    first: GLuint,
    count: GLuint,
    vertices: *mut FflCapturedVertex,
) -> GLuint {
    with_context(|ctx| {
        let items = ctx.captured().vertices();
        // SAFETY: forwarded from the caller.
        unsafe { copy_out(items.len(), first, count, vertices, |k| (&items[k]).into()) }
    })
}

/// Copies captured primitives `first..first + count` (fewer at the end) to `primitives` and
/// returns how many were copied.
///
/// # Safety
/// `primitives` is NULL or has room for `count` values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fflCaptureReadPrimitives(
    first: GLuint,
    count: GLuint,
    primitives: *mut FflCapturedPrimitive,
) -> GLuint {
    with_context(|ctx| {
        let items = ctx.captured().primitives();
        // SAFETY: forwarded from the caller.
        unsafe {
            copy_out(items.len(), first, count, primitives, |k| {
                (&items[k]).into()
            })
        }
    })
}

/// Copies texture unit `texture`'s coordinates (after that unit's coordinate generation and
/// texture matrix) of captured vertices `first..first + count` (fewer at the end) to
/// `coords`, 4 floats per vertex, and returns how many vertices were copied. Unit 0's are the
/// `tex_coord` of fflCaptureReadVertices. GL_INVALID_ENUM (nothing copied) unless `texture`
/// is GL_TEXTUREi of a unit (i below GL_MAX_TEXTURE_UNITS); NULL `coords` with a positive
/// count is GL_INVALID_VALUE.
///
/// # Safety
/// `coords` is NULL or has room for `4 * count` floats.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fflCaptureReadTexCoords(
    texture: GLenum,
    first: GLuint,
    count: GLuint,
    coords: *mut GLfloat,
) -> GLuint {
    with_context(|ctx| {
        let unit = texture.wrapping_sub(GL_TEXTURE0) as usize;
        if unit >= MAX_TEXTURE_UNITS {
            return Err(GlError::InvalidEnum);
        }
        let capture = ctx.captured();
        let len = capture.vertices().len();
        let out = coords.cast::<[GLfloat; 4]>();
        // SAFETY: `coords` has room for `4 * count` floats, `count` values of 4.
        unsafe {
            copy_out(len, first, count, out, |k| {
                capture.tex_coord(k, unit).unwrap_or(Vec4::W).to_array()
            })
        }
    })
}

/// `len` bytes at `ptr`, or `None` for NULL.
///
/// # Safety
/// A non-NULL `ptr` must point to `len` readable bytes.
unsafe fn bytes<'a>(ptr: *const GLfloat, len: usize) -> Option<&'a [u8]> {
    // SAFETY: forwarded from the caller.
    (!ptr.is_null()).then(|| unsafe { std::slice::from_raw_parts(ptr.cast::<u8>(), len) })
}

/// Lights `count` vertices with the current state, exactly as glColor4fv, glNormal3fv and
/// glVertex{2,3,4}fv would in immediate mode, without drawing them: the current attributes
/// stay unchanged, nothing is captured or fed back.
///
/// Inputs: `positions` has `position_size` (2, 3 or 4) floats per vertex; `normals` 3 and
/// `colors` 4 (RGBA), or NULL for the current normal or color. Outputs (4 floats per vertex,
/// any of them NULL to skip): eye and clip coordinates, primary and secondary colors of the
/// front and back faces. Strides are in bytes, 0 meaning tightly packed, so outputs can be
/// interleaved in one array of structs. GL_INVALID_VALUE for a negative count or stride, a
/// bad position size or NULL positions; GL_INVALID_OPERATION between glBegin and glEnd.
///
/// # Safety
/// Every non-NULL array must hold `count` elements at its stride; outputs must not overlap
/// inputs.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn fflLightVertices(
    count: GLsizei,
    position_size: GLint,
    positions: *const GLfloat,
    position_stride: GLsizei,
    normals: *const GLfloat,
    normal_stride: GLsizei,
    colors: *const GLfloat,
    color_stride: GLsizei,
    eye_positions: *mut GLfloat,
    eye_stride: GLsizei,
    clip_positions: *mut GLfloat,
    clip_stride: GLsizei,
    front_primary: *mut GLfloat,
    front_primary_stride: GLsizei,
    front_secondary: *mut GLfloat,
    front_secondary_stride: GLsizei,
    back_primary: *mut GLfloat,
    back_primary_stride: GLsizei,
    back_secondary: *mut GLfloat,
    back_secondary_stride: GLsizei,
) {
    with_context(|ctx| {
        ctx.outside_begin_end()?;
        let layout = BulkLayout::new(
            count,
            position_size,
            [position_stride, normal_stride, color_stride],
            [
                eye_stride,
                clip_stride,
                front_primary_stride,
                front_secondary_stride,
                back_primary_stride,
                back_secondary_stride,
            ],
        )?;
        let count = layout.count;
        let len = |l: crate::commands::capture::FloatLayout| l.len(count).unwrap_or(0);
        // SAFETY (all three): the caller guarantees `count` elements at the stride.
        let positions = match unsafe { bytes(positions, len(layout.positions)) } {
            Some(positions) => positions,
            None if count == 0 => &[],
            None => return Err(GlError::InvalidValue),
        };
        let normals = unsafe { bytes(normals, len(layout.normals)) };
        let colors = unsafe { bytes(colors, len(layout.colors)) };
        let outputs = BulkOutputs::new(
            [
                eye_positions,
                clip_positions,
                front_primary,
                front_secondary,
                back_primary,
                back_secondary,
            ],
            layout.outputs,
            count,
        );
        // Without a back output, two-sided lighting need not light the back face; without an
        // eye output, the eye coordinates are computed only where lighting needs them; without
        // a secondary output, the secondary colors are not stored.
        let reads = Reads {
            faces: if back_primary.is_null() && back_secondary.is_null() {
                Faces::Front
            } else {
                Faces::Both
            },
            eye: !eye_positions.is_null(),
            secondary: !front_secondary.is_null() || !back_secondary.is_null(),
            // No output takes them.
            tex_coord: false,
        };
        ctx.light_blocks(
            count,
            reads,
            |first, block| {
                let (len, ahead) = (block.len, first + PREFETCH_AHEAD);
                read_bulk(positions, layout.positions, first, len, &mut block.position);
                prefetch_block(positions.as_ptr(), layout.positions, count, ahead);
                if let Some(normals) = normals {
                    read_bulk(normals, layout.normals, first, len, &mut block.normal);
                    prefetch_block(normals.as_ptr(), layout.normals, count, ahead);
                }
                if let Some(colors) = colors {
                    read_bulk(colors, layout.colors, first, len, &mut block.color);
                    prefetch_block(colors.as_ptr(), layout.colors, count, ahead);
                }
            },
            // SAFETY: the caller guarantees `count` elements at each output's stride, not
            // overlapping the inputs or each other; each block is emitted once.
            |first, block| unsafe { outputs.write(first, block) },
        )
    })
}

/// Elements `first..first + len` of the array `bytes` laid out as `layout` into `lanes`
/// (`read_floats`), a full block of packed 3-float elements by `bulk_lanes` where the CPU
/// can.
#[inline(always)]
fn read_bulk(bytes: &[u8], layout: FloatLayout, first: usize, len: usize, lanes: &mut [LanesF32]) {
    let packed3 = len == LANES && layout.size == 3 && layout.stride == 12;
    let read = packed3
        && bytes
            .get(12 * first..)
            .is_some_and(|run| bulk_lanes::read_packed3(run, lanes));
    if !read {
        read_floats(bytes, (layout.size, layout.stride), first, len, lanes);
    }
}

/// How many vertices ahead of the block it reads or writes the bulk call prefetches: the
/// memory's latency covered, the lines still in the cache when their turn comes.
const PREFETCH_AHEAD: usize = 256;

/// Asks the second-level cache for the lines of elements `first..first + LANES` (those below
/// `count`) of the array at `base` laid out as `layout`: a hint, which reads nothing the
/// program sees. (Into the first level, 256 vertices ahead, measured a little slower.)
#[inline(always)]
fn prefetch_block(base: *const u8, layout: FloatLayout, count: usize, first: usize) {
    #[cfg(target_arch = "x86_64")]
    if first < count {
        use std::arch::x86_64::{_MM_HINT_T1, _mm_prefetch};
        let start = layout.offset(first);
        let end = layout.offset(count.min(first + LANES) - 1) + 4 * layout.size;
        // Every line of the elements when they share lines, else each element's first.
        let step = layout.stride.max(64);
        let mut at = start;
        while at < end {
            // SAFETY: SSE is part of x86-64; the address is inside the array.
            unsafe { _mm_prefetch::<_MM_HINT_T1>(base.wrapping_add(at).cast()) };
            at += step;
        }
        // The last line, which the steps miss when `start` is not at a line's start.
        unsafe { _mm_prefetch::<_MM_HINT_T1>(base.wrapping_add(end - 1).cast()) };
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (base, layout, count, first);
}

/// One output of fflLightVertices: where it goes, and which of a block's lanes.
#[derive(Clone, Copy)]
struct BulkOutput {
    pointer: *mut GLfloat,
    layout: FloatLayout,
    /// Which of `output_lanes`.
    field: usize,
}

/// A lit block's lanes of fflLightVertices' output `field`: eye, clip, front primary, front
/// secondary, back primary, back secondary.
fn output_lanes(block: &OutputBlock, field: usize) -> &Lanes4 {
    [
        &block.eye,
        &block.clip,
        &block.front_primary,
        &block.front_secondary,
        &block.back_primary,
        &block.back_secondary,
    ][field]
}

/// fflLightVertices' outputs given (not NULL), written from the bulk call's threads.
struct BulkOutputs {
    outputs: [BulkOutput; 6],
    /// How many of `outputs` are given.
    len: usize,
    /// Vertices in the call.
    count: usize,
}

// SAFETY: the threads write disjoint vertices of the application's arrays, which the caller
// guarantees do not overlap.
unsafe impl Sync for BulkOutputs {}

impl BulkOutputs {
    /// The outputs among `pointers` (eye, clip, front primary, front secondary, back primary,
    /// back secondary; NULL: skipped) laid out as `layouts`, of `count` vertices.
    fn new(pointers: [*mut GLfloat; 6], layouts: [FloatLayout; 6], count: usize) -> BulkOutputs {
        let mut outputs = [BulkOutput {
            pointer: std::ptr::null_mut(),
            layout: layouts[0],
            field: 0,
        }; 6];
        let mut len = 0;
        for (field, (pointer, layout)) in pointers.into_iter().zip(layouts).enumerate() {
            if !pointer.is_null() {
                outputs[len] = BulkOutput {
                    pointer,
                    layout,
                    field,
                };
                len += 1;
            }
        }
        BulkOutputs {
            outputs,
            len,
            count,
        }
    }

    /// Writes the lit vertices of `block`, vertices `first..`, and prefetches the outputs'
    /// lines `PREFETCH_AHEAD` vertices on.
    ///
    /// # Safety
    /// Each output holds vertex `first + block.len - 1` at its stride.
    unsafe fn write(&self, first: usize, block: &OutputBlock) {
        for output in &self.outputs[..self.len] {
            let layout = output.layout;
            let lanes = output_lanes(block, output.field);
            let base = output.pointer.cast::<u8>();
            prefetch_block(base, layout, self.count, first + PREFETCH_AHEAD);
            // SAFETY: forwarded from the caller. Specialized (inlined with constants) for full
            // blocks, and for packed outputs, the common case.
            unsafe {
                let out = output.pointer.byte_add(layout.offset(first));
                match (block.len, layout.stride) {
                    (LANES, 16) => {
                        if !bulk_lanes::write_packed4(out, lanes) {
                            write_transposed(out, 16, lanes, LANES)
                        }
                    }
                    (LANES, stride) => write_transposed(out, stride, lanes, LANES),
                    (len, stride) => write_transposed(out, stride, lanes, len),
                }
            }
        }
    }
}

/// Lanes `0..len` of the four components `lanes` to `out`, a vertex every `stride` bytes: 4
/// lanes at a time, a 4 x 4 transposition (a few shuffles on SSE2 and NEON), each vertex
/// stored whole, in lane order.
///
/// # Safety
/// `out` holds `len` vertices of 4 floats at `stride`.
#[inline(always)]
unsafe fn write_transposed(out: *mut GLfloat, stride: usize, lanes: &Lanes4, len: usize) {
    for half in 0..LANES / 4 {
        let vertices =
            Mat4::from_cols_array_2d(&lanes.map(|c| c[4 * half..][..4].try_into().expect("4")))
                .transpose();
        for k in 0..4.min(len.saturating_sub(4 * half)) {
            // SAFETY: forwarded from the caller; 4 * half + k < len.
            unsafe {
                out.byte_add((4 * half + k) * stride)
                    .cast::<[GLfloat; 4]>()
                    .write_unaligned(vertices.col(k).to_array())
            };
        }
    }
}
