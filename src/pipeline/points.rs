//! Large `glDrawArrays(GL_POINTS)` in feedback or selection mode on several threads. Points
//! need no assembly, so a chunk of them is fetched, lit, culled and laid out as feedback
//! values (or reduced to its hits' extreme depths) by whichever thread takes it, and the
//! calling thread appends the chunks' results in order: the same values, in the same order,
//! as one thread streaming the points (`Context::feedback_points`).

use multiversion::multiversion;

use super::block::{InputBlock, OutputBlock};
use super::clip::ClipPlanes;
use super::feedback::FeedbackLayout;
use super::fetch::ArrayFetch;
use super::parallel::{Step, in_order};
use super::vertex::DerivedState;
use crate::context::{Context, RenderMode};
use crate::lighting::batch::{Faces, process_blocks};
use crate::lighting::lanes::LANES;
use crate::state::raster::ViewportMap;

/// Blocks per chunk: 2048 points, whose feedback values (at most 13 each) take about 100 KiB.
const CHUNK_BLOCKS: usize = 256;

/// Blocks lit at a time: even, so the widest kernel takes them two by two.
const LIT_BLOCKS: usize = 16;

/// The window coordinates of a lit block's points, and which of them are drawn: inside the
/// view volume and every enabled user clip plane (§2.12), and among the block's `len`.
/// Compiled for AVX2 where the CPU has it (the code outside the kernels is otherwise built for
/// the baseline instruction set): eight lanes, a component of a block to a register. With
/// AVX-512's sixteen, the compiler loads two components that the kernel stored apart as one,
/// which stalls until the stores complete.
#[multiversion(targets("x86_64+avx2+fma+bmi1+bmi2+lzcnt+popcnt", "aarch64+neon"))]
pub(crate) fn visible_points(
    viewport: &ViewportMap,
    planes: &ClipPlanes,
    block: &OutputBlock,
) -> ([bool; LANES], super::block::Lanes4) {
    let masks = planes.block_masks(block);
    let visible = std::array::from_fn(|lane| lane < block.len && masks[lane] == 0);
    (visible, viewport.window_lanes(&block.clip))
}

/// Blocks `inputs` filled with the elements from `start` on (at most to `end`), `LANES` a
/// block: compiled for AVX2 where the CPU has it, as `visible_points` is.
#[multiversion(targets("x86_64+avx2+fma+bmi1+bmi2+lzcnt+popcnt", "aarch64+neon"))]
fn fill_runs(fetch: &ArrayFetch, inputs: &mut [InputBlock], start: usize, end: usize) {
    for (k, input) in inputs.iter_mut().enumerate() {
        let first = start + k * LANES;
        fetch.fill_run(input, first, LANES.min(end - first));
    }
}

/// A chunk's results: its feedback values (the first `len` of `values`, which has room for
/// every point of a chunk once a chunk was run into it), or the extreme depths of its
/// selection hits.
#[derive(Default)]
struct ChunkPoints {
    values: Vec<f32>,
    len: usize,
    hits: Option<(f32, f32)>,
}

/// What every chunk of a draw shares.
struct PointsDraw<'a> {
    derived: &'a DerivedState,
    fetch: &'a ArrayFetch<'a>,
    template: InputBlock,
    first: usize,
    count: usize,
    viewport: ViewportMap,
    planes: ClipPlanes,
    /// `None` in selection mode.
    layout: Option<FeedbackLayout>,
}

impl PointsDraw<'_> {
    /// Chunk `chunk`'s points, fetched and lit, to `keep` a block at a time.
    fn run(&self, chunk: usize, mut keep: impl FnMut(&OutputBlock)) {
        let mut inputs = [self.template; LIT_BLOCKS];
        let mut outputs = [OutputBlock::default(); LIT_BLOCKS];
        let blocks = self.count.div_ceil(LANES);
        let chunk_end = blocks.min((chunk + 1) * CHUNK_BLOCKS);
        for batch in (chunk * CHUNK_BLOCKS..chunk_end).step_by(LIT_BLOCKS) {
            let batch_len = LIT_BLOCKS.min(chunk_end - batch);
            let start = self.first + batch * LANES;
            fill_runs(
                self.fetch,
                &mut inputs[..batch_len],
                start,
                self.first + self.count,
            );
            let lit = &mut outputs[..batch_len];
            process_blocks(self.derived, Faces::Front, &inputs[..batch_len], lit);
            lit.iter().for_each(&mut keep);
        }
    }

    /// Chunk `chunk`'s points into `out`, for the calling thread to append in turn.
    fn run_into(&self, chunk: usize, out: &mut ChunkPoints) {
        out.len = 0;
        out.hits = None;
        if let Some(layout) = &self.layout {
            // Sized at an output's first chunk, not per block: outputs never run into (most
            // of the calling thread's, which lays its own chunks out in place) cost nothing.
            out.values
                .resize(CHUNK_BLOCKS * LANES * layout.point_values(), 0.0);
        }
        self.run(chunk, |block| {
            let (visible, window) = visible_points(&self.viewport, &self.planes, block);
            match &self.layout {
                Some(layout) => {
                    let arrays = [&window, &block.front_primary, &block.tex_coord];
                    out.len += layout.encode_points(&visible, arrays, &mut out.values[out.len..]);
                }
                None => {
                    for lane in (0..LANES).filter(|&lane| visible[lane]) {
                        let z = window[2][lane];
                        let (min, max) = out.hits.get_or_insert((z, z));
                        *min = min.min(z);
                        *max = max.max(z);
                    }
                }
            }
        });
    }
}

impl Context {
    /// `count` points from element `first` of `fetch`'s arrays on `threads` threads, when
    /// the draw is fed back (with a layout) or selected; false, having done nothing,
    /// otherwise (render mode, or a feedback buffer without a layout).
    pub(crate) fn draw_points_on_threads(
        &mut self,
        derived: &DerivedState,
        fetch: &ArrayFetch,
        template: &InputBlock,
        (first, count): (usize, usize),
        threads: usize,
    ) -> bool {
        let layout = match self.render_mode {
            RenderMode::Render => return false,
            RenderMode::Select => None,
            RenderMode::Feedback => match self.feedback.layout {
                Some(layout) => Some(layout),
                None => return false,
            },
        };
        let draw = PointsDraw {
            derived,
            fetch,
            template: *template,
            first,
            count,
            viewport: self.raster.viewport_map(),
            planes: self.clip_planes(),
            layout,
        };
        let chunks = count.div_ceil(LANES * CHUNK_BLOCKS);
        in_order(
            chunks,
            threads - 1,
            ChunkPoints::default,
            |k, out| draw.run_into(k, out),
            |step| match step {
                // Every earlier chunk is appended: this one's points go straight in.
                Step::Run(k) => draw.run(k, |block| self.feedback_points(&draw.planes, block)),
                Step::Take(out) => {
                    if let Some((min, max)) = out.hits {
                        self.selection.hit(min);
                        self.selection.hit(max);
                    }
                    if layout.is_some() {
                        self.feedback.values_of(&out.values[..out.len]);
                    }
                }
            },
        );
        true
    }
}
