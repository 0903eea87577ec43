//! The post-transform vertex cache of indexed draws, as hardware and Mesa keep one: a vertex
//! that several primitives share is fetched, transformed and lit once per draw while it stays
//! in the cache, not once per reference. Direct-mapped by index, of a fixed size, so a draw
//! of any size uses the same memory.

use super::block::{InputBlock, OutputBlock};
use super::fetch::ArrayFetch;
use super::vertex::{DerivedState, ProcessedVertex};
use crate::lighting::batch::{Reads, process_blocks};
use crate::lighting::lanes::LANES;

/// Slots in the cache: a mesh whose rows are shorter than half of this reuses every vertex.
const SLOTS: usize = 4096;

/// Indices taken at a time: their misses are lit together, then they are sent on in order.
const WINDOW: usize = 256;

/// Blocks of misses lit at a time: up to 16, so the widest kernel takes them two by two.
const LIT_BLOCKS: usize = 16;

#[derive(Clone, Copy, Debug, Default)]
struct Slot {
    /// The array index whose vertex the slot holds; `usize::MAX` for none.
    index: usize,
    /// The window that last used the slot: its vertex must stay until that window is sent.
    window: u64,
    vertex: ProcessedVertex,
}

/// The cache, kept by the context between draws (emptied at each draw: the state or the
/// arrays may have changed).
#[derive(Debug, Default)]
pub struct VertexCache {
    slots: Vec<Slot>,
    window: u64,
    /// The current window's indices, and those of them that missed.
    pending: Vec<usize>,
    misses: Vec<usize>,
    /// The blocks the misses are lit in.
    inputs: Vec<InputBlock>,
    outputs: Vec<OutputBlock>,
    /// The cache of indexed separate triangles in feedback and selection.
    pub(crate) mesh: super::mesh::MeshCache,
    /// What a large mesh draw on several threads keeps for the next.
    pub(crate) mesh_threads: super::mesh::MeshThreads,
    /// What the draw reads of its vertices.
    reads: Reads,
}

/// Scratch space: a copy of a context starts with an empty cache.
impl Clone for VertexCache {
    fn clone(&self) -> VertexCache {
        VertexCache::default()
    }
}

impl VertexCache {
    /// Empties the cache for a new draw that reads what `reads` says of its vertices.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::batch::Faces;
    /// use fflight::pipeline::vertex_cache::VertexCache;
    /// let mut cache = VertexCache::default();
    /// cache.start_draw(Faces::Both); // allocates the slots once, then only marks them empty
    /// cache.start_draw(Faces::Front);
    /// ```
    pub fn start_draw(&mut self, reads: impl Into<Reads>) {
        self.reads = reads.into();
        if self.slots.is_empty() {
            self.slots = vec![
                Slot {
                    index: usize::MAX,
                    ..Slot::default()
                };
                SLOTS
            ];
            self.pending.reserve(WINDOW);
            self.misses.reserve(WINDOW);
        }
        self.slots
            .iter_mut()
            .for_each(|slot| slot.index = usize::MAX);
        self.pending.clear();
        self.misses.clear();
        self.window += 1;
    }

    /// Takes the next index of the draw; sends the pending ones on, lit, through `send` when
    /// the window is full or the index's slot is still needed by it.
    ///
    /// # Examples
    ///
    /// ```
    /// # use fflight::lighting::PreparedLighting;
    /// # use fflight::pipeline::vertex::{DerivedState, VertexTransform};
    /// # use fflight::state::{light::Light, light_model::LightModel};
    /// # use fflight::state::material::{ColorMaterial, Material};
    /// # use glam::Mat4;
    /// // Identity matrices, lighting off.
    /// let derived = DerivedState::new(
    ///     VertexTransform::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY, false, false, None),
    ///     PreparedLighting::new(
    ///         false,
    ///         &std::array::from_fn(Light::initial),
    ///         &[Material::default(); 2],
    ///         &LightModel::default(),
    ///         &ColorMaterial::default(),
    ///     ),
    /// );
    /// # use fflight::{gl::*, pipeline::fetch::ArrayFetch};
    /// # use fflight::state::arrays::{ARRAY_KINDS, ClientArray};
    /// // A vertex array of two floats per element: (1, 2), (3, 4), (5, 6).
    /// let vertex_array = ClientArray {
    ///     enabled: true,
    ///     size: 2,
    ///     component_type: GL_FLOAT,
    ///     stride: 0,
    ///     address: 0,
    ///     buffer: 0,
    /// };
    /// let bytes: Vec<u8> = [1.0f32, 2.0, 3.0, 4.0, 5.0, 6.0]
    ///     .iter()
    ///     .flat_map(|v| v.to_ne_bytes())
    ///     .collect();
    /// let mut arrays = [None; ARRAY_KINDS];
    /// arrays[0] = Some((&vertex_array, &bytes[..])); // ALL_KINDS[0] is the vertex array
    /// use fflight::pipeline::{block::InputBlock, vertex_cache::VertexCache};
    /// let fetch = ArrayFetch::new(0, arrays);
    /// let mut input = InputBlock::default();
    /// let mut cache = VertexCache::default();
    /// cache.start_draw(fflight::lighting::batch::Faces::Both);
    /// let mut xs = Vec::new();
    /// for index in [0, 2, 0] {
    ///     cache.push(index, (&derived, &fetch, &mut input), |v| xs.push(v.clip.x));
    /// }
    /// assert!(xs.is_empty()); // the window is not full: nothing sent yet
    /// cache.flush(&derived, &fetch, &mut input, |v| xs.push(v.clip.x));
    /// assert_eq!(xs, [1.0, 5.0, 1.0]);
    /// ```
    pub fn push(
        &mut self,
        index: usize,
        lighting: (&DerivedState, &ArrayFetch, &mut InputBlock),
        send: impl FnMut(&ProcessedVertex),
    ) {
        let slot = index % SLOTS;
        let mut send = send;
        if self.slots[slot].index != index && self.slots[slot].window == self.window {
            self.flush(lighting.0, lighting.1, lighting.2, &mut send);
        }
        let entry = &mut self.slots[slot];
        if entry.index != index {
            entry.index = index;
            self.misses.push(index);
        }
        entry.window = self.window;
        self.pending.push(index);
        if self.pending.len() == WINDOW {
            self.flush(lighting.0, lighting.1, lighting.2, &mut send);
        }
    }

    /// Lights the misses of the window, up to `LIT_BLOCKS` blocks at a time, and sends its
    /// indices' vertices on in order.
    ///
    /// # Examples
    ///
    /// ```
    /// # use fflight::lighting::PreparedLighting;
    /// # use fflight::pipeline::vertex::{DerivedState, VertexTransform};
    /// # use fflight::state::{light::Light, light_model::LightModel};
    /// # use fflight::state::material::{ColorMaterial, Material};
    /// # use glam::Mat4;
    /// // Identity matrices, lighting off.
    /// let derived = DerivedState::new(
    ///     VertexTransform::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY, false, false, None),
    ///     PreparedLighting::new(
    ///         false,
    ///         &std::array::from_fn(Light::initial),
    ///         &[Material::default(); 2],
    ///         &LightModel::default(),
    ///         &ColorMaterial::default(),
    ///     ),
    /// );
    /// # use fflight::{gl::*, pipeline::fetch::ArrayFetch};
    /// # use fflight::state::arrays::{ARRAY_KINDS, ClientArray};
    /// // A vertex array of two floats per element: (1, 2), (3, 4), (5, 6).
    /// let vertex_array = ClientArray {
    ///     enabled: true,
    ///     size: 2,
    ///     component_type: GL_FLOAT,
    ///     stride: 0,
    ///     address: 0,
    ///     buffer: 0,
    /// };
    /// let bytes: Vec<u8> = [1.0f32, 2.0, 3.0, 4.0, 5.0, 6.0]
    ///     .iter()
    ///     .flat_map(|v| v.to_ne_bytes())
    ///     .collect();
    /// let mut arrays = [None; ARRAY_KINDS];
    /// arrays[0] = Some((&vertex_array, &bytes[..])); // ALL_KINDS[0] is the vertex array
    /// use fflight::pipeline::{block::InputBlock, vertex_cache::VertexCache};
    /// let fetch = ArrayFetch::new(0, arrays);
    /// let mut input = InputBlock::default();
    /// let mut cache = VertexCache::default();
    /// cache.start_draw(fflight::lighting::batch::Faces::Both);
    /// cache.push(1, (&derived, &fetch, &mut input), |_| {});
    /// let mut sent = Vec::new();
    /// cache.flush(&derived, &fetch, &mut input, |v| sent.push(v.clip.y));
    /// assert_eq!(sent, [4.0]);
    /// ```
    pub fn flush(
        &mut self,
        derived: &DerivedState,
        fetch: &ArrayFetch,
        input: &mut InputBlock,
        mut send: impl FnMut(&ProcessedVertex),
    ) {
        for batch in self.misses.chunks(LANES * LIT_BLOCKS) {
            let blocks = batch.len().div_ceil(LANES);
            // Each block starts as `input` (the attributes no array gives).
            self.inputs.clear();
            self.inputs.resize(blocks, *input);
            self.outputs.resize(blocks, OutputBlock::default());
            for (block, indices) in self.inputs.iter_mut().zip(batch.chunks(LANES)) {
                fetch.fill(block, indices);
            }
            process_blocks(
                derived,
                self.reads,
                &self.inputs,
                &mut self.outputs[..blocks],
            );
            for (k, &index) in batch.iter().enumerate() {
                self.slots[index % SLOTS].vertex = self.outputs[k / LANES].vertex(k % LANES);
            }
        }
        for &index in &self.pending {
            send(&self.slots[index % SLOTS].vertex);
        }
        self.pending.clear();
        self.misses.clear();
        self.window += 1;
    }
}
