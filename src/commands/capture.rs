//! fflight's capture API, for applications that light geometry with fflight and draw it
//! with another renderer: capture of the assembled primitives of every draw
//! (`pipeline::capture`), and bulk lighting of whole vertex arrays.

use std::sync::atomic::{AtomicUsize, Ordering};

use glam::{Vec3, Vec4};

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::lighting::batch::{Faces, Reads, process_blocks};
use crate::lighting::lanes::LANES;
use crate::pipeline::block::{InputBlock, OutputBlock};
use crate::pipeline::capture::Capture;
use crate::pipeline::vertex::{CurrentAttribs, ProcessedVertex};
use crate::threads::threads_for;

/// The layout of one strided array of floats of a bulk call: element i starts `i * stride`
/// bytes in and has `size` floats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FloatLayout {
    /// Floats per element (a position has 2 to 4).
    pub size: usize,
    /// Bytes from one element to the next (0 given: tightly packed, made explicit here).
    pub stride: usize,
}

impl FloatLayout {
    /// `stride` in bytes, 0 for tightly packed; negative is GL_INVALID_VALUE.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::capture::FloatLayout, GlError};
    /// assert_eq!(FloatLayout::new(3, 0)?.stride, 12); // 0: tightly packed
    /// assert_eq!(FloatLayout::new(3, -4).err(), Some(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn new(size: usize, stride: i32) -> GlResult<FloatLayout> {
        let stride = usize::try_from(stride).map_err(|_| GlError::InvalidValue)?;
        Ok(FloatLayout {
            size,
            stride: if stride == 0 { 4 * size } else { stride },
        })
    }

    /// Bytes `count` elements occupy; `None` if that does not fit the address space.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::commands::capture::FloatLayout;
    /// let layout = FloatLayout::new(3, 16)?; // 3 floats every 16 bytes
    /// assert_eq!(layout.len(2), Some(16 + 12)); // the last element unpadded
    /// assert_eq!(layout.len(0), Some(0));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn len(&self, count: usize) -> Option<usize> {
        match count {
            0 => Some(0),
            _ => (count - 1)
                .checked_mul(self.stride)?
                .checked_add(4 * self.size)
                .filter(|&len| len <= isize::MAX as usize),
        }
    }

    /// Byte offset of element `i`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::commands::capture::FloatLayout;
    /// assert_eq!(FloatLayout::new(4, 0)?.offset(3), 48);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn offset(&self, i: usize) -> usize {
        i * self.stride
    }
}

impl Context {
    /// fflCaptureBegin: starts capturing the primitives of every draw, dropping what an
    /// earlier capture collected. GL_INVALID_OPERATION between glBegin and glEnd.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// use glam::Vec4;
    /// let mut ctx = Context::new();
    /// ctx.capture_begin()?;
    /// ctx.begin(GL_TRIANGLES)?;
    /// for x in [0.0, 1.0, 0.0] {
    ///     ctx.vertex(Vec4::new(x, x, -1.0, 1.0));
    /// }
    /// ctx.end()?;
    /// ctx.capture_end()?;
    /// let capture = ctx.captured();
    /// assert_eq!((capture.vertices().len(), capture.primitives().len()), (3, 1));
    /// assert_eq!(capture.primitives()[0].kind, GL_TRIANGLES);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn capture_begin(&mut self) -> GlResult {
        self.outside_begin_end()?;
        self.capture.start();
        Ok(())
    }

    /// fflCaptureEnd: stops capturing; what was collected stays readable.
    /// GL_INVALID_OPERATION between glBegin and glEnd (the primitive in progress is not drawn
    /// yet).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.capture_begin()?;
    /// ctx.capture_end()?;
    /// ctx.begin(GL_POINTS)?; // not captured: capture ended
    /// ctx.vertex(glam::Vec4::W);
    /// ctx.end()?;
    /// assert!(ctx.captured().vertices().is_empty());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn capture_end(&mut self) -> GlResult {
        self.outside_begin_end()?;
        self.capture.stop();
        Ok(())
    }

    /// What capture collected.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.set_capability(GL_LIGHTING, true)?;
    /// ctx.set_capability(GL_LIGHT0, true)?;
    /// ctx.capture_begin()?;
    /// ctx.begin(GL_POINTS)?;
    /// ctx.vertex(glam::Vec4::new(0.0, 0.0, -1.0, 1.0));
    /// ctx.end()?;
    /// ctx.capture_end()?;
    /// let lit = ctx.captured().vertices()[0].colors.front.primary;
    /// // Light 0 from +z on the default normal: ambient 0.2 * 0.2 plus diffuse 0.8.
    /// assert!((lit.x - 0.84).abs() < 1e-6);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn captured(&self) -> &Capture {
        &self.capture
    }

    /// Lights `count` vertices with the current state through the batch engine, the path
    /// every draw takes: `vertex(i)` gives vertex i's object position and its normal and color
    /// (`None`: the current ones), `lit(i, v)` receives the result. Each result equals what
    /// glColor, glNormal, glVertex would give the vertex in immediate mode; the current
    /// attributes are left unchanged, and nothing is drawn or captured. GL_INVALID_OPERATION
    /// between glBegin and glEnd.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// use glam::{Vec3, Vec4};
    /// let mut ctx = Context::new();
    /// ctx.set_capability(GL_LIGHTING, true)?;
    /// ctx.set_capability(GL_LIGHT0, true)?;
    /// let normals = [Vec3::Z, Vec3::X];
    /// let mut red = [0.0; 2];
    /// ctx.light_vertices_with(
    ///     2,
    ///     |i| (Vec4::new(i as f32, 0.0, 0.0, 1.0), Some(normals[i]), None),
    ///     |i, lit| red[i] = lit.colors.front.primary.x,
    /// )?;
    /// // Facing the light: 0.04 + 0.8; at right angles to it: the ambient part only.
    /// assert!((red[0] - 0.84).abs() < 1e-6 && (red[1] - 0.04).abs() < 1e-6);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn light_vertices_with(
        &mut self,
        count: usize,
        mut vertex: impl FnMut(usize) -> (Vec4, Option<Vec3>, Option<Vec4>),
        mut lit: impl FnMut(usize, &ProcessedVertex),
    ) -> GlResult {
        self.outside_begin_end()?;
        let current = self.current;
        let derived = self.shared_derived();
        let mut input = [InputBlock::with_attribs(&current)];
        let mut output = [OutputBlock::default()];
        for first in (0..count).step_by(LANES) {
            input[0].len = 0;
            for i in first..count.min(first + LANES) {
                let (position, normal, color) = vertex(i);
                let attribs = CurrentAttribs {
                    normal: normal.unwrap_or(current.normal),
                    color: color.unwrap_or(current.color),
                    ..current
                };
                input[0].push(position, &attribs);
            }
            process_blocks(&derived, Faces::Both, &input, &mut output);
            for lane in 0..output[0].len {
                lit(first + lane, &output[0].vertex(lane));
            }
        }
        Ok(())
    }

    /// Bulk lighting a block at a time, on several threads for large counts
    /// (`threads::thread_count`): `fill(first, block)` puts vertices `first..first +
    /// block.len` into the block's lanes (the lanes hold the current attributes and the
    /// position (0, 0, 0, 1), and what `fill` puts there stays until it puts something else),
    /// `emit(first, block)` receives them lit (what `reads` says: a `Faces` reads the eye
    /// coordinates too). Blocks are
    /// independent, so the results do not depend on the thread count; `emit` is called from
    /// the threads, each block once.
    /// GL_INVALID_OPERATION between glBegin and glEnd.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// use std::sync::Mutex;
    /// let mut ctx = Context::new();
    /// let lit = Mutex::new(vec![0.0f32; 20]);
    /// ctx.light_blocks(
    ///     20,
    ///     fflight::lighting::batch::Faces::Both,
    ///     |first, block| {
    ///         for lane in 0..block.len {
    ///             let x = (first + lane) as f32;
    ///             block.set_position(lane, glam::Vec4::new(x, 0.0, 0.0, 1.0));
    ///         }
    ///     },
    ///     |first, block| {
    ///         let mut lit = lit.lock().unwrap();
    ///         for lane in 0..block.len {
    ///             lit[first + lane] = block.vertex(lane).eye.x;
    ///         }
    ///     },
    /// )?;
    /// assert_eq!(lit.into_inner().unwrap()[19], 19.0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn light_blocks(
        &mut self,
        count: usize,
        reads: impl Into<Reads>,
        fill: impl Fn(usize, &mut InputBlock) + Sync,
        emit: impl Fn(usize, &OutputBlock) + Sync,
    ) -> GlResult {
        self.outside_begin_end()?;
        let reads = reads.into();
        let derived = self.shared_derived();
        let template = InputBlock::with_attribs(&self.current);
        // Lights the ranges of blocks `claim` gives until it gives none.
        let run = |claim: &dyn Fn() -> Option<std::ops::Range<usize>>| {
            let mut inputs = [template; CHUNK_BLOCKS];
            let mut outputs = [OutputBlock::default(); CHUNK_BLOCKS];
            while let Some(blocks) = claim() {
                for chunk in blocks.clone().step_by(CHUNK_BLOCKS) {
                    let chunk_len = CHUNK_BLOCKS.min(blocks.end - chunk);
                    for (k, input) in inputs[..chunk_len].iter_mut().enumerate() {
                        let first = (chunk + k) * LANES;
                        input.len = LANES.min(count - first);
                        fill(first, input);
                    }
                    process_blocks(
                        &derived,
                        reads,
                        &inputs[..chunk_len],
                        &mut outputs[..chunk_len],
                    );
                    for (k, output) in outputs[..chunk_len].iter().enumerate() {
                        emit((chunk + k) * LANES, output);
                    }
                }
            }
        };
        let blocks = count.div_ceil(LANES);
        let threads = threads_for(count);
        // Ranges of `CLAIMED_BLOCKS` taken in turn: a thread the machine runs less takes
        // fewer, so the threads finish together (halves fixed in advance waited for the
        // slower one).
        let next = AtomicUsize::new(0);
        let claim = || {
            let start = next.fetch_add(CLAIMED_BLOCKS, Ordering::Relaxed);
            (start < blocks).then(|| start..(start + CLAIMED_BLOCKS).min(blocks))
        };
        if threads == 1 {
            run(&claim);
            return Ok(());
        }
        std::thread::scope(|scope| {
            let (run, claim) = (&run, &claim);
            for _ in 1..threads {
                scope.spawn(move || run(claim));
            }
            run(claim);
        });
        Ok(())
    }

    /// `light_vertices_with` over slices: one result per position in `out`. Normals and
    /// colors, when given, and `out` must have an element per position (else
    /// GL_INVALID_VALUE). Large counts are split across threads.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::vertex::ProcessedVertex, Context};
    /// use glam::{Vec3, Vec4};
    /// let mut ctx = Context::new();
    /// ctx.set_capability(GL_LIGHTING, true)?;
    /// ctx.set_capability(GL_LIGHT0, true)?;
    /// let positions = vec![Vec4::new(0.0, 0.0, -1.0, 1.0); 100];
    /// let normals = vec![Vec3::Z; 100];
    /// let mut out = vec![ProcessedVertex::default(); 100];
    /// ctx.light_vertices(&positions, Some(&normals), None, &mut out)?;
    /// assert!(out.iter().all(|v| (v.colors.front.primary.x - 0.84).abs() < 1e-6));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn light_vertices(
        &mut self,
        positions: &[Vec4],
        normals: Option<&[Vec3]>,
        colors: Option<&[Vec4]>,
        out: &mut [ProcessedVertex],
    ) -> GlResult {
        let count = positions.len();
        let short = |len: Option<usize>| len.is_some_and(|len| len < count);
        if short(normals.map(<[_]>::len)) || short(colors.map(<[_]>::len)) || out.len() < count {
            return Err(GlError::InvalidValue);
        }
        let out = OutputSlots(std::sync::Mutex::new(out));
        self.light_blocks(
            count,
            Faces::Both,
            |first, block| {
                for (lane, i) in (first..first + block.len).enumerate() {
                    block.set_position(lane, positions[i]);
                    if let Some(normals) = normals {
                        block.set_normal(lane, normals[i]);
                    }
                    if let Some(colors) = colors {
                        block.set_color(lane, colors[i]);
                    }
                }
            },
            |first, block| {
                let mut out = out.0.lock().unwrap_or_else(|e| e.into_inner());
                for lane in 0..block.len {
                    out[first + lane] = block.vertex(lane);
                }
            },
        )
    }
}

/// The output slice of `light_vertices`, shared by the threads.
struct OutputSlots<'a>(std::sync::Mutex<&'a mut [ProcessedVertex]>);

/// Blocks a thread processes at a time: inputs and outputs stay in the first-level cache.
const CHUNK_BLOCKS: usize = 16;

/// Blocks a thread of the bulk call claims at a time: 4096 vertices, about 100 us of lighting
/// with 8 lights. Claims of 512 vertices interleave the threads' outputs finely enough that
/// the prefetches pull lines the other thread writes (bulk, 8 spots, 2 threads: 13.2 -> 14.3
/// ns/vertex).
const CLAIMED_BLOCKS: usize = 32 * CHUNK_BLOCKS;

/// fflLightVertices' layout, validated: the vertex count, the input arrays (positions of
/// `position_size` floats, normals of 3, colors of 4) and the six outputs (4 floats each:
/// eye position, clip position, front primary, front secondary, back primary, back
/// secondary).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BulkLayout {
    /// How many vertices to light.
    pub count: usize,
    /// The positions: 2, 3 or 4 floats each.
    pub positions: FloatLayout,
    /// The normals (3 floats), or size 0 for the current normal.
    pub normals: FloatLayout,
    /// The colors (4 floats), or size 0 for the current color.
    pub colors: FloatLayout,
    /// Eye position, clip position, front primary, front secondary, back primary and back secondary color, 4 floats each (size 0: not written).
    pub outputs: [FloatLayout; 6],
}

impl BulkLayout {
    /// GL_INVALID_VALUE for a negative count or stride, a position size other than 2, 3 or
    /// 4, or arrays too large for the address space.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::capture::BulkLayout, GlError};
    /// let layout = BulkLayout::new(10, 3, [0, 0, 0], [0; 6])?;
    /// assert_eq!((layout.count, layout.positions.size, layout.positions.stride), (10, 3, 12));
    /// assert_eq!(BulkLayout::new(10, 5, [0; 3], [0; 6]).err(), Some(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn new(
        count: i32,
        position_size: i32,
        input_strides: [i32; 3],
        output_strides: [i32; 6],
    ) -> GlResult<BulkLayout> {
        let count = usize::try_from(count).map_err(|_| GlError::InvalidValue)?;
        if !(2..=4).contains(&position_size) {
            return Err(GlError::InvalidValue);
        }
        let [positions, normals, colors] = input_strides;
        let mut outputs = [FloatLayout { size: 4, stride: 0 }; 6];
        for (output, stride) in outputs.iter_mut().zip(output_strides) {
            *output = FloatLayout::new(4, stride)?;
        }
        let layout = BulkLayout {
            count,
            positions: FloatLayout::new(position_size as usize, positions)?,
            normals: FloatLayout::new(3, normals)?,
            colors: FloatLayout::new(4, colors)?,
            outputs,
        };
        let arrays = [layout.positions, layout.normals, layout.colors];
        if arrays
            .iter()
            .chain(&outputs)
            .any(|a| a.len(count).is_none())
        {
            return Err(GlError::InvalidValue);
        }
        Ok(layout)
    }
}
