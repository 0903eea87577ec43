//! Indexed separate triangles (glDrawElements(GL_TRIANGLES, ..)) in feedback or selection
//! mode, with the work that belongs to a vertex done once per vertex, not once per triangle
//! that uses it: through a post-transform cache like `vertex_cache`'s, each cached vertex
//! keeps its clip outcode (§2.12), its window coordinates (§2.11.1) and its feedback values
//! for either face (§5.3). A triangle is then three outcodes (trivially inside, trivially
//! outside, or else clipped by the general `clip_triangle`), its facing from the window
//! coordinates (§2.14.1, the formula of `Context::is_front_facing`), culling, and its values
//! copied into the application's feedback buffer.
//!
//! The state this serves (`Context::mesh_draw`): no capture, both polygon modes GL_FILL in
//! feedback (selection ignores polygon modes, §5.2). Edge flags only matter to the other
//! polygon modes. Everything else takes the general path (`DrawStream`); the values are the
//! same bits either way, since each is computed by the same operations from the same inputs.
//!
//! A large draw is split into chunks of `CHUNK_TRIANGLES` triangles run on helper threads
//! (`parallel::in_order`), each into an output of its own (values, clipped triangles,
//! selection depths) that the calling thread writes in order; the calling thread runs a chunk
//! itself straight into the buffer when it is the next one. Which thread lights a vertex, and
//! with which others, changes nothing in its bits, so the result is the same for any thread
//! count. The working set is fixed: per thread a cache (about 0.5 MiB) and two outputs of at
//! most a chunk's values.

use std::sync::Mutex;

use glam::Vec4;

use super::block::{InputBlock, OutputBlock};
use super::clip::{ClipPlanes, PolygonVertex, clip_triangle};
use super::feedback::{FeedbackLayout, FeedbackVertex, MAX_VERTEX_VALUES, encode_lane};
use super::fetch::ArrayFetch;
use super::vertex::{DerivedState, ProcessedVertex};
use crate::commands::arrays::ElementIndices;
use crate::context::{Context, RenderMode};
use crate::gl::*;
use crate::lighting::batch::{Faces, process_blocks};
use crate::lighting::lanes::LANES;
use crate::state::raster::ViewportMap;
use crate::threads::threads_for;

use super::parallel::{Step, in_order};

/// Slots of the direct-mapped cache: a grid whose rows are shorter than half of this lights
/// each vertex once.
const SLOTS: usize = 4096;

/// Slots past `SLOTS` for a triangle whose own corners map to one slot.
const SPARE_SLOTS: usize = 3;

/// Every slot of the cache: its tags, masks and values are this many, always (made at the
/// first draw), so that they are read through fixed-size views without bounds checks.
const CACHE_SLOTS: usize = SLOTS + SPARE_SLOTS;

/// Triangles gathered before their new vertices are lit and the triangles sent on.
const WINDOW_TRIANGLES: usize = 512;

/// Blocks lit at a time: even, so the widest kernel takes them two by two.
const LIT_BLOCKS: usize = 16;

/// Triangles per chunk of a draw split across threads: a chunk starts with an empty cache,
/// so a mesh lights the vertices its first row shares with the chunk before again (for rows
/// of 1000 vertices, one vertex in 8); its output is at most 16384 * 38 values (2.4 MiB).
const CHUNK_TRIANGLES: usize = 16 * 1024;

/// The most values a vertex keeps for both faces.
const MAX_SLOT_VALUES: usize = 2 * MAX_VERTEX_VALUES;

#[derive(Clone, Copy, Debug)]
struct Tag {
    /// The array index whose vertex the slot holds; `usize::MAX` for none.
    index: usize,
    /// The last window that used the slot: its vertex must stay until that window is sent.
    window: u64,
}

const EMPTY: Tag = Tag {
    index: usize::MAX,
    window: 0,
};

/// The cache and scratch of mesh draws, kept by the context between draws (emptied at each
/// draw): a fixed size whatever the draw.
#[derive(Debug, Default)]
pub struct MeshCache {
    tags: Vec<Tag>,
    slots: Slots,
    window: u64,
    /// The window's triangles, as slots.
    triangles: Vec<[u32; 3]>,
    /// The window's vertices not in the cache, and the slots they go to.
    miss_indices: Vec<usize>,
    miss_slots: Vec<u32>,
    inputs: Vec<InputBlock>,
    outputs: Vec<OutputBlock>,
    polygon: Vec<PolygonVertex>,
}

/// What the cache keeps of each slot's vertex. A triangle that needs clipping (rare: it
/// crosses a plane) lights its corners again (`relight`), to the same bits, so that the
/// cache keeps no whole vertex, each gathered from its block's lanes (`light_misses` 284 ->
/// 252 M instructions on a 500x500 mesh), and is half the size.
#[derive(Debug, Default)]
struct Slots {
    /// The planes the vertex is outside of (`ClipPlanes::outside_mask`).
    masks: Vec<u32>,
    /// `2 * N` values: the vertex's feedback values with the front colors, then with the back
    /// colors (in selection mode, its window x, y, z).
    values: Vec<f32>,
}

/// Scratch space: a copy of a context starts with an empty cache.
impl Clone for MeshCache {
    fn clone(&self) -> MeshCache {
        MeshCache::default()
    }
}

/// What a mesh draw needs of the state, taken once per draw.
pub(crate) struct MeshDraw<'a> {
    pub(crate) derived: &'a DerivedState,
    pub(crate) fetch: &'a ArrayFetch<'a>,
    pub(crate) template: InputBlock,
    planes: ClipPlanes,
    viewport: ViewportMap,
    /// The feedback layout; `None` in selection mode.
    layout: Option<FeedbackLayout>,
    /// Whether counterclockwise triangles face front (glFrontFace).
    ccw: bool,
    /// glCullFace's mode when GL_CULL_FACE is on.
    cull: Option<GLenum>,
    /// Where a vertex's color starts among its feedback values, under flat shading (the
    /// provoking vertex's color replaces the others').
    flat_color: Option<usize>,
}

impl Context {
    /// A mesh draw of `mode` when the state allows one (see the module's documentation).
    pub(crate) fn mesh_draw<'a>(
        &self,
        mode: GLenum,
        derived: &'a DerivedState,
        fetch: &'a ArrayFetch<'a>,
    ) -> Option<MeshDraw<'a>> {
        if mode != GL_TRIANGLES || self.capture.is_active() {
            return None;
        }
        let layout = match self.render_mode {
            RenderMode::Render => return None,
            RenderMode::Select => None,
            RenderMode::Feedback => {
                if self.raster.polygon_mode != [GL_FILL, GL_FILL] {
                    return None;
                }
                Some(self.feedback.layout?)
            }
        };
        let flat_color = layout.filter(|l| l.color && self.flat_shading());
        Some(MeshDraw {
            derived,
            fetch,
            template: InputBlock::with_attribs(&self.current),
            planes: self.clip_planes(),
            viewport: self.raster.viewport_map(),
            layout,
            ccw: self.raster.front_face == GL_CCW,
            cull: self.enables.cull_face.then_some(self.raster.cull_face_mode),
            flat_color: flat_color.map(|l| 2 + usize::from(l.z) + usize::from(l.w)),
        })
    }

    /// Draws `indices` as separate triangles the mesh way.
    pub(crate) fn draw_mesh(
        &mut self,
        cache: &mut MeshCache,
        draw: &MeshDraw,
        indices: &ElementIndices,
    ) {
        let values = draw.layout.map_or(3, |layout| {
            let encoded = FeedbackVertex {
                window: Vec4::ZERO,
                color: Vec4::ZERO,
                tex_coord: Vec4::ZERO,
            };
            layout.encode(&encoded, &mut [0.0; MAX_SLOT_VALUES])
        });
        match values {
            2 => self.draw_mesh_n::<2>(cache, draw, indices),
            3 => self.draw_mesh_n::<3>(cache, draw, indices),
            7 => self.draw_mesh_n::<7>(cache, draw, indices),
            11 => self.draw_mesh_n::<11>(cache, draw, indices),
            _ => self.draw_mesh_n::<12>(cache, draw, indices),
        }
    }

    /// `draw_mesh` for vertices of `N` feedback values: on the calling thread into the
    /// context's buffer, or, for a large draw, in chunks of `CHUNK_TRIANGLES` on several
    /// threads, each with a cache of its own, the calling thread writing each chunk's values
    /// in order (straight into the buffer when it works on the next chunk itself).
    fn draw_mesh_n<const N: usize>(
        &mut self,
        cache: &mut MeshCache,
        draw: &MeshDraw,
        indices: &ElementIndices,
    ) {
        let triangles = indices.len() / 3;
        let chunks = triangles.div_ceil(CHUNK_TRIANGLES);
        let threads = threads_for(indices.len()).min(chunks);
        let chunk =
            |k: usize| indices.slice(3 * k * CHUNK_TRIANGLES, 3 * (k + 1) * CHUNK_TRIANGLES);
        if threads <= 1 {
            return cache.draw::<N>(self, draw, indices);
        }
        let kept = std::mem::take(&mut self.vertex_cache.mesh_threads);
        let (helper_caches, outputs) = (Mutex::new(kept.caches), Mutex::new(kept.outputs));
        let outputs = in_order(
            chunks,
            threads - 1,
            || {
                let kept = outputs.lock().unwrap_or_else(|e| e.into_inner()).pop();
                // Emptied by `send_to` when the draw before took it.
                kept.unwrap_or_default()
            },
            |k, output: &mut ChunkOutput| {
                let mut cache = helper_caches
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .pop();
                let cache = cache.get_or_insert_with(MeshCache::default);
                cache.draw::<N>(output, draw, &chunk(k));
                helper_caches
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .push(std::mem::take(cache));
            },
            |step| match step {
                Step::Run(k) => cache.draw::<N>(self, draw, &chunk(k)),
                Step::Take(output) => output.send_to(self, &draw.planes, &mut cache.polygon),
            },
        );
        self.vertex_cache.mesh_threads = MeshThreads {
            caches: helper_caches
                .into_inner()
                .unwrap_or_else(|e| e.into_inner()),
            outputs,
        };
    }
}

/// Where the triangles of a mesh draw go: the context (its feedback buffer or selection, and
/// the general path for the clipped ones), or a chunk's output, which the context takes later.
trait TriangleSink {
    /// A triangle's `len` feedback values, which `write` puts in the slice it is given.
    fn triangle(&mut self, len: usize, write: impl FnOnce(&mut [f32]));
    /// A selection hit at window depth `z`.
    fn hit(&mut self, z: f32);
    /// A triangle that crosses a plane, for the general clipper.
    fn clipped(
        &mut self,
        planes: &ClipPlanes,
        corners: [&ProcessedVertex; 3],
        polygon: &mut Vec<PolygonVertex>,
    );
}

impl TriangleSink for Context {
    // Compiled into the loop over the window's triangles (`send_triangles`): called, its
    // arguments and the closure's captures went through memory.
    #[inline(always)]
    fn triangle(&mut self, len: usize, write: impl FnOnce(&mut [f32])) {
        self.feedback.append_with(len, write);
    }

    fn hit(&mut self, z: f32) {
        self.selection.hit(z);
    }

    fn clipped(
        &mut self,
        planes: &ClipPlanes,
        corners: [&ProcessedVertex; 3],
        polygon: &mut Vec<PolygonVertex>,
    ) {
        if clip_triangle(planes, corners, [true; 3], polygon) {
            self.feedback_polygon(polygon, corners[2]);
        } else {
            self.feedback_triangle(corners, [true; 3], corners[2], true);
        }
    }
}

/// What a large mesh draw on several threads keeps for the next (in the context's
/// `VertexCache`): the helper threads' caches and the chunks' outputs, whose memory, made
/// anew for each draw, was faulted in again each time (a 1000 x 1000 grid with 8 lights on 2
/// threads: about 700 page faults a draw).
#[derive(Debug, Default)]
pub(crate) struct MeshThreads {
    caches: Vec<MeshCache>,
    outputs: Vec<ChunkOutput>,
}

/// What a chunk of a mesh draw made on a helper thread, for the context to take in order.
#[derive(Debug, Default)]
struct ChunkOutput {
    values: Vec<f32>,
    /// The clipped triangles, each with how many of `values` come before it.
    clipped: Vec<(usize, [ProcessedVertex; 3])>,
    /// The smallest and largest depth of its selection hits.
    hits: Option<(f32, f32)>,
}

impl TriangleSink for ChunkOutput {
    #[inline(always)]
    fn triangle(&mut self, len: usize, write: impl FnOnce(&mut [f32])) {
        let at = self.values.len();
        self.values.resize(at + len, 0.0);
        write(&mut self.values[at..]);
    }

    fn hit(&mut self, z: f32) {
        let (min, max) = self.hits.get_or_insert((z, z));
        *min = min.min(z);
        *max = max.max(z);
    }

    fn clipped(
        &mut self,
        _planes: &ClipPlanes,
        corners: [&ProcessedVertex; 3],
        _polygon: &mut Vec<PolygonVertex>,
    ) {
        self.clipped
            .push((self.values.len(), [*corners[0], *corners[1], *corners[2]]));
    }
}

impl ChunkOutput {
    /// Sends the chunk to the context, as if its triangles came one by one, and empties it.
    fn send_to(
        &mut self,
        ctx: &mut Context,
        planes: &ClipPlanes,
        polygon: &mut Vec<PolygonVertex>,
    ) {
        let mut sent = 0;
        for (at, [a, b, c]) in &self.clipped {
            ctx.feedback.values_of(&self.values[sent..*at]);
            sent = *at;
            ctx.clipped(planes, [a, b, c], polygon);
        }
        ctx.feedback.values_of(&self.values[sent..]);
        // Selection keeps only the extreme depths of the hits: their order does not matter.
        if let Some((min, max)) = self.hits.take() {
            ctx.selection.hit(min);
            ctx.selection.hit(max);
        }
        self.values.clear();
        self.clipped.clear();
    }
}

impl MeshCache {
    /// Sends the separate triangles of `indices` to `sink`, in order.
    fn draw<const N: usize>(
        &mut self,
        sink: &mut impl TriangleSink,
        draw: &MeshDraw,
        indices: &ElementIndices,
    ) {
        self.start_draw(draw);
        indices.for_each_triangle(|corners| self.push_triangle::<N>(sink, draw, corners));
        self.flush::<N>(sink, draw);
    }

    fn start_draw(&mut self, draw: &MeshDraw) {
        if self.tags.is_empty() {
            let slots = CACHE_SLOTS;
            self.tags = vec![EMPTY; slots];
            self.slots = Slots {
                masks: vec![0; slots],
                values: vec![0.0; slots * MAX_SLOT_VALUES],
            };
            self.triangles.reserve(WINDOW_TRIANGLES);
            self.miss_indices.reserve(3 * WINDOW_TRIANGLES);
            self.miss_slots.reserve(3 * WINDOW_TRIANGLES);
        }
        self.tags.fill(EMPTY);
        self.window += 1;
        self.inputs.clear();
        self.inputs.resize(LIT_BLOCKS, draw.template);
        self.outputs.resize(LIT_BLOCKS, OutputBlock::default());
        self.triangles.clear();
        self.miss_indices.clear();
        self.miss_slots.clear();
    }

    /// Takes the next triangle's indices; sends the window on first when it is full or when
    /// a corner's slot still holds a vertex the window needs.
    fn push_triangle<const N: usize>(
        &mut self,
        sink: &mut impl TriangleSink,
        draw: &MeshDraw,
        corners: [usize; 3],
    ) {
        if self.triangles.len() == WINDOW_TRIANGLES {
            self.flush::<N>(sink, draw);
        }
        'retry: loop {
            let mut slots = [0; 3];
            let mut spare = false;
            let tags: &mut [Tag; CACHE_SLOTS] =
                (&mut self.tags[..]).try_into().expect("the cache's slots");
            for (k, &index) in corners.iter().enumerate() {
                let mut slot = index % SLOTS;
                let tag = &mut tags[slot];
                if tag.index != index {
                    if tag.window == self.window {
                        if !self.triangles.is_empty() {
                            self.flush::<N>(sink, draw);
                            continue 'retry;
                        }
                        // Two corners of this triangle share a slot: a spare one, used once.
                        slot = SLOTS + k;
                        tags[slot].index = index;
                        spare = true;
                    } else {
                        tag.index = index;
                    }
                    self.miss_indices.push(index);
                    self.miss_slots.push(slot as u32);
                }
                tags[slot].window = self.window;
                slots[k] = slot as u32;
            }
            self.triangles.push(slots);
            if spare {
                self.flush::<N>(sink, draw);
            }
            return;
        }
    }

    /// Lights the window's new vertices, then sends its triangles on, in order.
    fn flush<const N: usize>(&mut self, sink: &mut impl TriangleSink, draw: &MeshDraw) {
        self.light_misses::<N>(draw);
        self.send_triangles::<N>(sink, draw);
        self.triangles.clear();
        self.miss_indices.clear();
        self.miss_slots.clear();
        self.window += 1;
    }

    /// Fetches and lights the misses, `LIT_BLOCKS` blocks at a time, and keeps for each what
    /// its triangles need.
    fn light_misses<const N: usize>(&mut self, draw: &MeshDraw) {
        let per_batch = LANES * LIT_BLOCKS;
        for (batch, indices) in self.miss_indices.chunks(per_batch).enumerate() {
            let blocks = indices.len().div_ceil(LANES);
            for (input, indices) in self.inputs.iter_mut().zip(indices.chunks(LANES)) {
                draw.fetch.fill(input, indices);
            }
            process_blocks(
                draw.derived,
                Faces::Both,
                &self.inputs[..blocks],
                &mut self.outputs[..blocks],
            );
            let slots = &self.miss_slots[batch * per_batch..][..indices.len()];
            for (output, slots) in self.outputs.iter().zip(slots.chunks(LANES)) {
                self.slots.keep_block::<N>(draw, output, slots);
            }
        }
    }

    /// The window's triangles: trivially rejected, clipped by the general path, or faced,
    /// culled and fed back or selected here.
    fn send_triangles<const N: usize>(&mut self, sink: &mut impl TriangleSink, draw: &MeshDraw) {
        // Slots bounded by the views (every slot is below `CACHE_SLOTS`: `min` changes none),
        // so that a slot's mask and values need no check of their own (MeshCache::draw on a
        // 500x500 mesh: 480 -> 457 M instructions).
        let Slots { masks, values } = &self.slots;
        let masks: &[u32; CACHE_SLOTS] = masks[..].try_into().expect("the cache's slots");
        let values = &values[..CACHE_SLOTS * 2 * N];
        for &triangle in &self.triangles {
            let [a, b, c] = triangle.map(|slot| (slot as usize).min(CACHE_SLOTS - 1));
            let masks = [masks[a], masks[b], masks[c]];
            if masks[0] | masks[1] | masks[2] != 0 {
                if masks[0] & masks[1] & masks[2] == 0 {
                    let [a, b, c] = relight(draw, [a, b, c].map(|slot| self.tags[slot].index));
                    sink.clipped(&draw.planes, [&a, &b, &c], &mut self.polygon);
                }
                continue;
            }
            let values = |slot: usize| -> &[f32] { &values[slot * 2 * N..][..2 * N] };
            let (va, vb, vc) = (values(a), values(b), values(c));
            // `Context::is_front_facing`'s operations, in its order.
            let (ex, ey) = (va[0] - vc[0], va[1] - vc[1]);
            let (fx, fy) = (vb[0] - vc[0], vb[1] - vc[1]);
            let twice_area = ex * fy - ey * fx;
            let front = if draw.ccw {
                twice_area > 0.0
            } else {
                twice_area < 0.0
            };
            let culled = match draw.cull {
                None => false,
                Some(GL_FRONT) => front,
                Some(GL_BACK) => !front,
                Some(_) => true,
            };
            if culled {
                continue;
            }
            if draw.layout.is_none() {
                for v in [va, vb, vc] {
                    sink.hit(v[2]);
                }
                continue;
            }
            let face = if front { 0 } else { N };
            // Each corner's values of the face, N of them: the copies below need no check.
            let corners = [va, vb, vc].map(|v| &v[face..face + N]);
            sink.triangle(2 + 3 * N, |out| {
                let (head, rooms) = out.split_at_mut(2);
                head.copy_from_slice(&[GL_POLYGON_TOKEN as f32, 3.0]);
                for (room, corner) in rooms.chunks_exact_mut(N).zip(corners) {
                    room.copy_from_slice(corner);
                }
                if let Some(color) = draw.flat_color {
                    let provoking = &corners[2][color..color + 4];
                    for room in rooms.chunks_exact_mut(N).take(2) {
                        room[color..color + 4].copy_from_slice(provoking);
                    }
                }
            });
        }
    }
}

impl Slots {
    /// Keeps the vertices of a lit block in `slots`, with what their triangles need: each
    /// vertex's clip outcode and, per face, its feedback values (in selection, window x, y, z).
    fn keep_block<const N: usize>(&mut self, draw: &MeshDraw, output: &OutputBlock, slots: &[u32]) {
        let window = draw.viewport.window_lanes(&output.clip);
        let masks = draw.planes.block_masks(output);
        // The layout N values make: GL_2D, GL_3D (and selection), GL_3D_COLOR,
        // GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE.
        let flags = [N >= 3, N == 12, N >= 7, N >= 11];
        for (lane, &slot) in slots.iter().enumerate() {
            let slot = slot as usize;
            self.masks[slot] = masks[lane];
            let values = &mut self.values[slot * 2 * N..][..2 * N];
            for (face, color) in [&output.front_primary, &output.back_primary]
                .into_iter()
                .enumerate()
            {
                let mut encoded = [0.0; MAX_VERTEX_VALUES];
                encode_lane(
                    flags,
                    lane,
                    [&window, color, &output.tex_coord],
                    &mut encoded,
                );
                values[face * N..][..N].copy_from_slice(&encoded[..N]);
            }
        }
    }
}

/// The vertices of array elements `indices`, lit again: the bits they had when the cache
/// kept them, since a lane's results do not depend on the others of its block.
#[cold]
#[inline(never)]
fn relight(draw: &MeshDraw, indices: [usize; 3]) -> [ProcessedVertex; 3] {
    let mut input = draw.template;
    draw.fetch.fill(&mut input, &indices);
    let mut output = [OutputBlock::default()];
    process_blocks(draw.derived, Faces::Both, &[input], &mut output);
    [0, 1, 2].map(|lane| output[0].vertex(lane))
}
