//! `glDrawArrays(GL_POINTS)` in feedback or selection mode, in chunks. Points need no
//! assembly, so a chunk of them is fetched, lit a few blocks at a time, culled and laid out as
//! feedback values (or reduced to its hits' extreme depths). On one thread the chunks go
//! straight into the buffer; on several, by whichever thread takes a chunk, and the calling
//! thread appends the chunks' results in order: the same values, in the same order, as one
//! thread streaming the points (`Context::feedback_points`).

use std::sync::Mutex;

use multiversion::multiversion;

use super::DrawStream;
use super::block::{InputBlock, OutputBlock};
use super::clip::ClipPlanes;
use super::feedback::{FeedbackLayout, FeedbackStorage};
use super::fetch::ArrayFetch;
use super::parallel::{BUFFERS_PER_THREAD, Step, in_order};
use super::streaming::{copy_streaming, copy_streaming_piece, fence, prefetch_for_copy};
use super::vertex::DerivedState;
use crate::context::{Context, RenderMode};
use crate::lighting::batch::{Reads, process_blocks};
use crate::lighting::lanes::{LANES, filled_lanes, lanes_of};
use crate::state::raster::ViewportMap;

/// Blocks per chunk: 2048 points, whose feedback values (at most 13 each) take about 100 KiB.
const CHUNK_BLOCKS: usize = 256;

/// Blocks lit at a time: even, so the widest kernel takes them two by two; and few, so that
/// the lit blocks (8 KiB) are still in the first-level cache when they are laid out. Against
/// 4, the batch engine's cost per call shared by twice the points: arrays 1 light on one
/// thread 139 -> 133 instructions a vertex (callgrind), 7 of 8 alternating pairs faster
/// (median ratio 0.93), on two threads 5 of 6 (with 8 spots 5 of 6). 16 measured the same
/// as 8 in time.
const LIT_BLOCKS: usize = 8;

/// The window coordinates of a lit block's points, and which of them are drawn (a bit each,
/// lane 0 lowest): inside the view volume and every enabled user clip plane (§2.12), and
/// among the block's `len`.
/// Compiled for AVX2 where the CPU has it (the code outside the kernels is otherwise built for
/// the baseline instruction set): eight lanes, a component of a block to a register. With
/// AVX-512's sixteen, the compiler loads two components that the kernel stored apart as one,
/// which stalls until the stores complete.
#[multiversion(targets("x86_64+avx2+fma+bmi1+bmi2+lzcnt+popcnt", "aarch64+neon"))]
pub(crate) fn visible_points(
    viewport: &ViewportMap,
    planes: &ClipPlanes,
    block: &OutputBlock,
) -> VisiblePoints {
    let masks = planes.block_masks(block);
    let mut visible = 0;
    for (lane, mask) in masks.into_iter().enumerate() {
        visible |= u8::from(mask == 0) << lane;
    }
    VisiblePoints {
        window: viewport.window_lanes(&block.clip),
        visible: visible & filled_lanes(block.len),
    }
}

/// `visible_points`' result: window coordinates (x, y, z and the clip w) and the drawn
/// points' bits, aligned as the blocks are, so that no component straddles a cache line.
#[repr(C, align(64))]
pub(crate) struct VisiblePoints {
    pub window: super::block::Lanes4,
    pub visible: u8,
}

/// Blocks `inputs` filled with the elements from `start` on (at most `count` of them),
/// `LANES` a block: compiled for AVX2 where the CPU has it, as `visible_points` is.
#[multiversion(targets("x86_64+avx2+fma+bmi1+bmi2+lzcnt+popcnt", "aarch64+neon"))]
fn fill_runs(fetch: &ArrayFetch, inputs: &mut [InputBlock], start: usize, count: usize) {
    fetch.fill_runs(inputs, start, count);
}

/// Lit points laid out away from the context, by another thread, for the calling thread to
/// append in turn (`Context::append_points`): their feedback values (the first `len` of
/// `values`), or the extreme depths of their selection hits.
///
/// A large draw into the application's memory gives each its place there instead
/// (`destination`): its values are copied by the thread that next lays points out into it,
/// a piece per block while it lays out the next chunk (`PointsSink::clear`, `lay_out`), or
/// when it is dropped. The copies are shared among the threads rather than all made by the
/// calling thread, and their stores drain while the points are lit (1M points, 1 light, 2
/// threads on the Xeon: 12.3-14.5 -> 10.6-11.2 ns/vertex against a copy per chunk).
#[derive(Debug, Default)]
pub(crate) struct LaidOutPoints<'a> {
    values: Vec<f32>,
    len: usize,
    hits: Option<(f32, f32)>,
    destination: Option<&'a mut [f32]>,
    /// The values of the chunk before, being copied to their place.
    delivering: Delivery<'a>,
}

/// A context's value buffers of points laid out on several threads, kept from one draw for
/// the next: allocated anew, they were zeroed on pages the system had taken back since the
/// last draw (1M points, 1 light, 2 threads: about 115 page faults a draw). At most the
/// buffers of the draw before are kept, two for each output it used, each a chunk's values
/// (64 KiB as GL_3D_COLOR, 104 KiB at most). A copy of the context starts without them.
#[derive(Debug, Default)]
pub(crate) struct PointBuffers(Vec<Vec<f32>>);

impl Clone for PointBuffers {
    fn clone(&self) -> PointBuffers {
        PointBuffers::default()
    }
}

impl PointBuffers {
    /// The buffers, lent to a draw (`LaidOutPoints::recycled`) while the context is borrowed
    /// elsewhere, and taken back by `keep`.
    fn lend(&mut self) -> Mutex<Vec<Vec<f32>>> {
        Mutex::new(std::mem::take(&mut self.0))
    }

    /// Keeps the buffers of the outputs of a draw of `threads` threads, once they have
    /// delivered their values, and what is left of `lent`.
    fn keep<'a>(
        &mut self,
        lent: Mutex<Vec<Vec<f32>>>,
        outputs: impl IntoIterator<Item = LaidOutPoints<'a>>,
        threads: usize,
    ) {
        let mut buffers = lent.into_inner().unwrap_or_else(|e| e.into_inner());
        buffers.extend(outputs.into_iter().flat_map(LaidOutPoints::into_buffers));
        buffers.truncate(2 * (BUFFERS_PER_THREAD * threads + 1));
        self.0 = buffers;
    }
}

/// Values on their way to their place in the application's memory, a piece at a time.
#[derive(Debug, Default)]
struct Delivery<'a> {
    values: Vec<f32>,
    /// The rest of the place, and of the values (from `done`) to copy there.
    to: &'a mut [f32],
    done: usize,
    /// Values per piece.
    piece: usize,
}

impl Delivery<'_> {
    /// Copies the next piece, or every value left with `all`; fenced after the last.
    fn copy(&mut self, all: bool) {
        if self.to.is_empty() {
            return;
        }
        let count = if all {
            self.to.len()
        } else {
            self.piece.min(self.to.len())
        };
        let (piece, rest) = std::mem::take(&mut self.to).split_at_mut(count);
        copy_streaming_piece(piece, &self.values[self.done..][..count]);
        // A piece is a block's values.
        prefetch_for_copy(rest, 0, count);
        self.to = rest;
        self.done += count;
        if self.to.is_empty() {
            fence();
        }
    }
}

impl LaidOutPoints<'_> {
    /// The values laid out (none in selection mode).
    pub(crate) fn values(&self) -> &[f32] {
        &self.values[..self.len]
    }

    /// Copies every value still to go to its place: those being delivered, then those whose
    /// place was just given.
    fn deliver(&mut self) {
        self.delivering.copy(true);
        if let Some(to) = self.destination.take() {
            copy_streaming(to, &self.values[..to.len()]);
        }
    }

    /// Starts delivering the values whose place was given, in `pieces` pieces (finishing
    /// what was being delivered before, if anything): their memory becomes the delivery's,
    /// the delivery's theirs.
    fn start_delivery(&mut self, pieces: usize) {
        self.delivering.copy(true);
        let Some(to) = self.destination.take() else {
            return;
        };
        std::mem::swap(&mut self.values, &mut self.delivering.values);
        // Whole lines of 16 values, at least.
        self.delivering.piece = to.len().div_ceil(pieces).next_multiple_of(16);
        self.delivering.to = to;
        self.delivering.done = 0;
    }
}

impl<'a> LaidOutPoints<'a> {
    /// Empty, with buffers from `buffers` (`PointBuffers::lend`).
    fn recycled(buffers: &Mutex<Vec<Vec<f32>>>) -> LaidOutPoints<'a> {
        let mut lent = buffers.lock().unwrap_or_else(|e| e.into_inner());
        LaidOutPoints {
            values: lent.pop().unwrap_or_default(),
            len: 0,
            hits: None,
            destination: None,
            delivering: Delivery {
                values: lent.pop().unwrap_or_default(),
                ..Delivery::default()
            },
        }
    }

    /// Its two buffers, once its values are delivered.
    fn into_buffers(mut self) -> [Vec<f32>; 2] {
        self.deliver();
        [
            std::mem::take(&mut self.values),
            std::mem::take(&mut self.delivering.values),
        ]
    }
}

impl Drop for LaidOutPoints<'_> {
    fn drop(&mut self) {
        self.deliver();
    }
}

/// Where lit points go in feedback or selection mode, for a thread without the context: the
/// viewport, the clip planes, and the feedback layout (`None` in selection mode).
#[derive(Clone, Debug)]
pub(crate) struct PointsSink {
    viewport: ViewportMap,
    planes: ClipPlanes,
    layout: Option<FeedbackLayout>,
}

impl PointsSink {
    /// Empties `out` for the points of up to `blocks` blocks. Its room is made at its first
    /// use, not per block.
    pub(crate) fn clear(&self, out: &mut LaidOutPoints, blocks: usize) {
        out.start_delivery(blocks);
        out.len = 0;
        out.hits = None;
        if let Some(layout) = &self.layout {
            out.values
                .resize(blocks * LANES * layout.point_values(), 0.0);
        }
    }

    /// `out` emptied, then the drawn points of `blocks` laid out in it.
    pub(crate) fn lay_out_blocks(&self, blocks: &[OutputBlock], out: &mut LaidOutPoints) {
        self.clear(out, blocks.len());
        for block in blocks {
            self.lay_out(block, out);
        }
    }

    /// Appends the drawn points of `block` (front colors) to `out`: the same values, in the
    /// same order, as `Context::feedback_points`.
    pub(crate) fn lay_out(&self, block: &OutputBlock, out: &mut LaidOutPoints) {
        out.delivering.copy(false);
        let VisiblePoints { visible, window } = visible_points(&self.viewport, &self.planes, block);
        match &self.layout {
            Some(layout) => {
                let arrays = [&window, &block.front_primary, &block.tex_coord];
                out.len += layout.encode_points(visible, arrays, &mut out.values[out.len..]);
            }
            None => {
                for lane in lanes_of(visible) {
                    let z = window[2][lane];
                    let (min, max) = out.hits.get_or_insert((z, z));
                    *min = min.min(z);
                    *max = max.max(z);
                }
            }
        }
    }
}

/// What every chunk of a draw shares.
struct PointsDraw<'a> {
    derived: &'a DerivedState,
    fetch: &'a ArrayFetch<'a>,
    template: InputBlock,
    first: usize,
    count: usize,
    /// What the draw reads of the lit points (`DrawStream::reads`).
    reads: Reads,
    sink: PointsSink,
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
            let done = batch * LANES;
            fill_runs(
                self.fetch,
                &mut inputs[..batch_len],
                self.first + done,
                self.count - done,
            );
            let lit = &mut outputs[..batch_len];
            process_blocks(self.derived, self.reads, &inputs[..batch_len], lit);
            lit.iter().for_each(&mut keep);
        }
    }

    /// Chunk `chunk`'s points into `out`, for the calling thread to append in turn (`out`
    /// first delivers the values it holds, if they have a place). An output gets its room at
    /// its first chunk: one never run into costs nothing.
    fn run_into(&self, chunk: usize, out: &mut LaidOutPoints) {
        self.sink.clear(out, CHUNK_BLOCKS);
        self.run(chunk, |block| self.sink.lay_out(block, out));
        // The rest of the chunk before's values (a piece or so), fenced before `out` is
        // handed on.
        out.delivering.copy(true);
    }

    /// All `chunks` chunks on `helpers` helper threads and the calling thread, fed back into
    /// `room`, the application's memory: each chunk's values get their place there in order,
    /// and whichever thread reuses their output next (or drops it) copies them, so that the
    /// calling thread does not make every copy. Returns how many values were written, and
    /// whether some did not fit.
    fn run_into_places(
        &self,
        chunks: usize,
        helpers: usize,
        mut room: &mut [f32],
        kept: &mut PointBuffers,
    ) -> (usize, bool) {
        let (mut appended, mut overflowed) = (0, false);
        let buffers = kept.lend();
        let mut own = LaidOutPoints::recycled(&buffers);
        let outputs = in_order(
            chunks,
            helpers,
            || LaidOutPoints::recycled(&buffers),
            |k, out| self.run_into(k, out),
            |step| {
                let out = match step {
                    Step::Run(k) => {
                        self.run_into(k, &mut own);
                        &mut own
                    }
                    Step::Take(out) => out,
                };
                let fitting = out.len.min(room.len());
                let (place, rest) = std::mem::take(&mut room).split_at_mut(fitting);
                room = rest;
                appended += fitting;
                overflowed |= fitting < out.len;
                out.destination = Some(place);
            },
        );
        kept.keep(buffers, outputs.into_iter().chain([own]), helpers + 1);
        (appended, overflowed)
    }
}

impl Context {
    /// `count` points of `stream` from element `first` of `fetch`'s arrays in chunks on
    /// `threads` threads (one: the calling thread alone, straight into the buffer), when the
    /// draw is of points, not captured, and fed back (with a layout) or selected; false,
    /// having done nothing, otherwise (`stream_points_sink`).
    pub(crate) fn draw_points_in_chunks(
        &mut self,
        stream: &DrawStream,
        derived: &DerivedState,
        fetch: &ArrayFetch,
        template: &InputBlock,
        (first, count): (usize, usize),
        threads: usize,
    ) -> bool {
        let Some(sink) = self.stream_points_sink(stream) else {
            return false;
        };
        let draw = PointsDraw {
            derived,
            fetch,
            template: *template,
            first,
            count,
            reads: stream.reads(),
            sink,
        };
        let chunks = count.div_ceil(LANES * CHUNK_BLOCKS);
        if threads == 1 {
            for k in 0..chunks {
                draw.run(k, |block| {
                    self.feedback_points(&draw.sink.viewport, &draw.sink.planes, block)
                });
            }
            return true;
        }
        let feedback = &mut self.feedback;
        if let (Some(_), FeedbackStorage::Application(memory)) =
            (draw.sink.layout, &mut feedback.storage)
        {
            let room = &mut memory.as_mut_slice()[feedback.written..feedback.capacity];
            let (appended, overflowed) =
                draw.run_into_places(chunks, threads - 1, room, &mut self.point_buffers);
            feedback.written += appended;
            feedback.overflowed |= overflowed;
            return true;
        }
        let buffers = self.point_buffers.lend();
        let outputs = in_order(
            chunks,
            threads - 1,
            || LaidOutPoints::recycled(&buffers),
            |k, out| draw.run_into(k, out),
            |step| match step {
                // Every earlier chunk is appended: this one's points go straight in.
                Step::Run(k) => draw.run(k, |block| {
                    self.feedback_points(&draw.sink.viewport, &draw.sink.planes, block)
                }),
                Step::Take(out) => self.append_points(out),
            },
        );
        self.point_buffers.keep(buffers, outputs, threads);
        true
    }

    /// Where points drawn with `viewport` and `planes` go, for threads without the context;
    /// `None` in render mode, and in feedback mode without a buffer.
    pub(crate) fn points_sink(
        &self,
        viewport: ViewportMap,
        planes: ClipPlanes,
    ) -> Option<PointsSink> {
        let layout = match self.render_mode {
            RenderMode::Render => return None,
            RenderMode::Select => None,
            RenderMode::Feedback => Some(self.feedback.layout?),
        };
        Some(PointsSink {
            viewport,
            planes,
            layout,
        })
    }

    /// Appends points another thread laid out, as `feedback_points` would have.
    pub(crate) fn append_points(&mut self, points: &LaidOutPoints) {
        if let Some((min, max)) = points.hits {
            self.selection.hit(min);
            self.selection.hit(max);
        }
        if self.render_mode == RenderMode::Feedback {
            self.feedback.values_of(points.values());
        }
    }
}
