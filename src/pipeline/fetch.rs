//! Array fetch (§2.8): each enabled array gets one converter per draw, chosen from its type,
//! size and kind (normalized or not), that decodes a block of elements at a time into the
//! lanes of an `InputBlock`. No per-element dispatch on the type.

use glam::{Mat4, Vec4};

use crate::gl::*;
use crate::lighting::lanes::{LANES, LanesF32};
use crate::pipeline::block::InputBlock;
use crate::pipeline::streaming::prefetch;
use crate::state::arrays::{ALL_KINDS, ARRAY_KINDS, ArrayKind, ClientArray};
use crate::state::convert::Component;

/// A component type as it sits in an array's bytes (native byte order, any alignment).
trait ArrayComponent: Component {
    const BYTES: usize;
    fn from_bytes(bytes: &[u8]) -> Self;
}

macro_rules! array_component {
    ($($t:ty),*) => {$(
        impl ArrayComponent for $t {
            const BYTES: usize = std::mem::size_of::<$t>();
            #[inline(always)]
            fn from_bytes(bytes: &[u8]) -> $t {
                <$t>::from_ne_bytes(bytes[..Self::BYTES].try_into().expect("sized"))
            }
        }
    )*};
}
array_component!(i8, u8, i16, u16, i32, u32, f32, f64);

/// Decodes the elements at `offsets` into lanes `0..offsets.len()` of `out`, padding
/// components past `SIZE` with (0, 0, 0, 1).
type Converter = fn(bytes: &[u8], offsets: &[usize], out: &mut [LanesF32]);

fn convert<T: ArrayComponent, const SIZE: usize, const NORMALIZE: bool>(
    bytes: &[u8],
    offsets: &[usize],
    out: &mut [LanesF32],
) {
    for (lane, &offset) in offsets.iter().enumerate() {
        let element = &bytes[offset..offset + SIZE * T::BYTES];
        for (c, component) in out.iter_mut().enumerate() {
            component[lane] = if c < SIZE {
                let value = T::from_bytes(&element[c * T::BYTES..]);
                if NORMALIZE {
                    value.normalized()
                } else {
                    value.direct()
                }
            } else if c == 3 {
                1.0
            } else {
                0.0
            };
        }
    }
}

/// The converter for elements of `size` components of `T`.
fn converter_of<T: ArrayComponent>(size: i32, normalize: bool) -> Converter {
    macro_rules! pick {
        ($($size:literal),*) => {
            match (size, normalize) {
                $(($size, true) => convert::<T, $size, true>,
                  ($size, false) => convert::<T, $size, false>,)*
                _ => convert::<T, 4, false>,
            }
        };
    }
    pick!(1, 2, 3, 4)
}

/// The converter for an array's type and size (types and sizes the pointer commands
/// accepted).
fn converter(array: &ClientArray, normalize: bool) -> Converter {
    let size = array.size;
    match array.component_type {
        GL_BYTE => converter_of::<i8>(size, normalize),
        GL_UNSIGNED_BYTE => converter_of::<u8>(size, normalize),
        GL_SHORT => converter_of::<i16>(size, normalize),
        GL_UNSIGNED_SHORT => converter_of::<u16>(size, normalize),
        GL_INT => converter_of::<i32>(size, normalize),
        GL_UNSIGNED_INT => converter_of::<u32>(size, normalize),
        GL_DOUBLE => converter_of::<f64>(size, normalize),
        _ => converter_of::<f32>(size, normalize),
    }
}

/// One enabled array of a draw: its bytes (starting with element `base`), stride and
/// converter.
#[derive(Clone, Copy)]
struct ArraySource<'a> {
    bytes: &'a [u8],
    stride: usize,
    convert: Converter,
    /// Its size when its elements are 2 to 4 floats: read with `read_floats`.
    floats: Option<usize>,
}

/// The 16 bytes at `at` in `bytes` as four floats: one load where it inlines (built with
/// `array::from_fn`, the closure stopped inlining and the floats went through the stack).
#[inline(always)]
fn four_floats(bytes: &[u8], at: usize) -> Vec4 {
    let element: &[u8; 16] = bytes[at..][..16].try_into().expect("16 bytes");
    let float = |c: usize| {
        f32::from_ne_bytes([
            element[4 * c],
            element[4 * c + 1],
            element[4 * c + 2],
            element[4 * c + 3],
        ])
    };
    Vec4::new(float(0), float(1), float(2), float(3))
}

/// A full block's elements, `stride` bytes apart in `run`, each read as 16 bytes (its floats
/// and what follows them), into the components `lanes`: 4 lanes at a time, a 4 x 4
/// transposition, which glam does in a few shuffles on SSE2 and NEON.
#[inline(always)]
fn read_transposed(run: &[u8], stride: usize, lanes: &mut [LanesF32]) {
    for half in 0..LANES / 4 {
        let at = |k: usize| (4 * half + k) * stride;
        let elements = Mat4::from_cols(
            four_floats(run, at(0)),
            four_floats(run, at(1)),
            four_floats(run, at(2)),
            four_floats(run, at(3)),
        )
        .transpose();
        for (c, component) in lanes.iter_mut().enumerate() {
            component[4 * half..][..4].copy_from_slice(&elements.col(c).to_array());
        }
    }
}

/// A full block of packed elements of `N` floats (the first `LANES * N` floats of `run`) into
/// the components `lanes` (the first `N` of them): read as one run of floats and regrouped by
/// component, which the compiler makes blends and permutations of whole registers (for 3
/// floats on AVX2, 3 loads and about ten shuffles a block, against 4 x 4 transpositions
/// whose loads it split into single floats). Elements of 4 floats are the transpositions'
/// own.
#[inline(always)]
fn read_packed<const N: usize>(run: &[u8], lanes: &mut [LanesF32]) {
    if N == 4 {
        return read_transposed(&run[..LANES * 16], 16, lanes);
    }
    let mut floats = [0.0f32; 4 * LANES];
    for (float, bytes) in floats.iter_mut().zip(run[..LANES * 4 * N].chunks_exact(4)) {
        *float = f32::from_ne_bytes(bytes.try_into().expect("4 bytes"));
    }
    for (c, component) in lanes.iter_mut().take(N).enumerate() {
        *component = std::array::from_fn(|lane| floats[N * lane + c]);
    }
}

/// Elements `first..first + len` (at most `LANES`) of an array of `size` floats (2 to 4),
/// element i `i * stride` bytes into `bytes`, into lanes `0..len` of the first `size`
/// components of `lanes` (the other components and lanes left as they are). A full block
/// whose last element has 16 bytes to read is read as one run and transposed, with constant
/// offsets when the array is packed; the rest element by element. For array draws and for
/// fflLightVertices.
///
/// # Panics
///
/// When `bytes` does not hold the elements.
#[inline(always)]
pub(crate) fn read_floats(
    bytes: &[u8],
    (size, stride): (usize, usize),
    first: usize,
    len: usize,
    lanes: &mut [LanesF32],
) {
    debug_assert!((2..=4).contains(&size));
    match size {
        2 => read_floats_of::<2>(bytes, stride, first, len, lanes),
        3 => read_floats_of::<3>(bytes, stride, first, len, lanes),
        _ => read_floats_of::<4>(bytes, stride, first, len, lanes),
    }
}

/// `read_floats` for elements of `N` floats: the sizes known, the loops unrolled.
#[inline(always)]
fn read_floats_of<const N: usize>(
    bytes: &[u8],
    stride: usize,
    first: usize,
    len: usize,
    lanes: &mut [LanesF32],
) {
    let components = N.min(lanes.len());
    let lanes = &mut lanes[..components];
    let start = first * stride;
    let end = start + (LANES - 1) * stride + 16;
    let packed = (len == LANES && stride == 4 * N)
        .then(|| bytes.get(start..start + LANES * stride))
        .flatten();
    if let Some(run) = packed {
        read_packed::<N>(run, lanes);
    } else if len == LANES && bytes.len() >= end {
        read_transposed(&bytes[start..end], stride, lanes);
    } else {
        for lane in 0..len {
            let element = &bytes[start + lane * stride..][..4 * N];
            for (c, component) in lanes.iter_mut().enumerate() {
                component[lane] = f32::from_ne_bytes(element[4 * c..][..4].try_into().expect("4"));
            }
        }
    }
}

/// Full blocks `inputs` of the packed array of `N` floats `bytes` (an array of `kind`), from
/// element `first` on: the whole run sliced once, so that each block's reads have constant
/// offsets and no check. False, having read nothing, when the bytes end before the last
/// element.
#[inline(always)]
fn read_packed_blocks<const N: usize>(
    bytes: &[u8],
    first: usize,
    kind: ArrayKind,
    inputs: &mut [InputBlock],
) -> bool {
    let block_bytes = LANES * 4 * N;
    let start = first * 4 * N;
    let Some(run) = bytes.get(start..start + inputs.len() * block_bytes) else {
        return false;
    };
    for (k, input) in inputs.iter_mut().enumerate() {
        let Some(lanes) = float_lanes(kind, input) else {
            return false;
        };
        read_packed::<N>(&run[k * block_bytes..], lanes);
        fill_missing(lanes, N);
    }
    true
}

/// The components from `size` on of elements that have only `size`: (z, w) = (0, 1) (§2.8).
#[inline(always)]
fn fill_missing(lanes: &mut [LanesF32], size: usize) {
    for (c, component) in lanes.iter_mut().enumerate().skip(size) {
        *component = [if c == 3 { 1.0 } else { 0.0 }; LANES];
    }
}

/// The lanes of `block` that an array of `kind` read as floats fills; `None` for the edge
/// flag, fog coordinate and color index arrays.
fn float_lanes(kind: ArrayKind, block: &mut InputBlock) -> Option<&mut [LanesF32]> {
    match kind {
        ArrayKind::Vertex => Some(&mut block.position),
        ArrayKind::Normal => Some(&mut block.normal),
        ArrayKind::Color => Some(&mut block.color),
        ArrayKind::TexCoord => Some(&mut block.tex_coord),
        ArrayKind::SecondaryColor => Some(&mut block.secondary_color),
        ArrayKind::EdgeFlag | ArrayKind::FogCoord | ArrayKind::Index => None,
    }
}

/// Elements `first..first + len` of `source`, an array of `size` floats, into `out`; the
/// components it lacks are (z, w) = (0, 1) (§2.8).
#[inline(always)]
fn read_float_run(
    source: &ArraySource,
    size: usize,
    first: usize,
    len: usize,
    out: &mut [LanesF32],
) {
    read_floats(source.bytes, (size, source.stride), first, len, out);
    fill_missing(out, size);
}

/// How many elements ahead of those it reads `ArrayFetch::fill_runs` asks for the arrays'
/// lines (1.5 KiB of an array of 3 floats): the hardware's prefetchers bring a draw's arrays
/// into the second-level cache, not the first. 1M points, 1 light, 2 threads, against none:
/// 1 KiB ahead median pair ratio 0.968 (8 of 10 faster), 2 KiB 0.973 (7 of 10), 4 KiB 1.01,
/// 0.5 KiB 0.985; with the arrays in the cache, the same (0.995). The lines of one batch
/// ahead were slower.
const PREFETCH_AHEAD: usize = 128;

/// The enabled arrays of a draw, ready to fill blocks.
pub struct ArrayFetch<'a> {
    base: usize,
    arrays: [Option<ArraySource<'a>>; ARRAY_KINDS],
}

impl<'a> ArrayFetch<'a> {
    /// `arrays[kind]`: the enabled arrays' state and bytes, which start with element `base`
    /// and hold every element the draw reads (checked by the caller).
    ///
    /// # Examples
    ///
    /// ```
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
    /// let fetch = ArrayFetch::new(0, arrays);
    /// let mut block = fflight::pipeline::block::InputBlock::default();
    /// fetch.fill(&mut block, &[2]);
    /// assert_eq!(block.len, 1);
    /// ```
    pub fn new(
        base: usize,
        arrays: [Option<(&ClientArray, &'a [u8])>; ARRAY_KINDS],
    ) -> ArrayFetch<'a> {
        // Fog coordinates and color indices reach nothing an RGBA vertex computes: their
        // arrays are neither read nor asked for.
        let read = |k: usize| !matches!(ALL_KINDS[k], ArrayKind::FogCoord | ArrayKind::Index);
        let arrays = std::array::from_fn(|k| {
            arrays[k]
                .filter(|_| read(k))
                .map(|(array, bytes)| ArraySource {
                    bytes,
                    stride: array.effective_stride(),
                    convert: converter(array, ALL_KINDS[k].normalized()),
                    floats: (array.component_type == GL_FLOAT && (2..=4).contains(&array.size))
                        .then_some(array.size as usize),
                })
        });
        ArrayFetch { base, arrays }
    }

    /// Puts elements `indices` (at most a block's lanes) into `block`'s lanes; attributes
    /// without an enabled array keep what the block holds.
    ///
    /// # Examples
    ///
    /// ```
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
    /// # use fflight::pipeline::block::{InputBlock, lanes4_get};
    /// # use glam::Vec4;
    /// let fetch = ArrayFetch::new(0, arrays);
    /// let mut block = InputBlock::default();
    /// fetch.fill(&mut block, &[1, 0]);
    /// assert_eq!(block.len, 2);
    /// // Missing components are (z, w) = (0, 1) (§2.8).
    /// assert_eq!(lanes4_get(&block.position, 0), Vec4::new(3.0, 4.0, 0.0, 1.0));
    /// assert_eq!(lanes4_get(&block.position, 1), Vec4::new(1.0, 2.0, 0.0, 1.0));
    /// assert_eq!(lanes4_get(&block.color, 0), Vec4::ONE); // no color array: kept
    /// ```
    pub fn fill(&self, block: &mut InputBlock, indices: &[usize]) {
        if let [first, ..] = *indices
            && indices.len() == LANES
            && indices.windows(2).all(|pair| pair[1] == pair[0] + 1)
        {
            return self.fill_run(block, first, LANES);
        }
        self.fill_with(block, indices.len(), |source, offsets| {
            for (offset, &index) in offsets.iter_mut().zip(indices) {
                *offset = (index - self.base) * source.stride;
            }
            None
        });
    }

    /// `fill` with elements `first..first + len` (at most a block's lanes): a full block of
    /// an array of floats is read as one run and transposed.
    ///
    /// # Examples
    ///
    /// ```
    /// # use fflight::{gl::*, pipeline::fetch::ArrayFetch};
    /// # use fflight::state::arrays::{ARRAY_KINDS, ClientArray};
    /// # use fflight::pipeline::block::{InputBlock, lanes4_get};
    /// # use glam::Vec4;
    /// let vertex_array = ClientArray {
    ///     enabled: true,
    ///     size: 3,
    ///     component_type: GL_FLOAT,
    ///     stride: 0,
    ///     address: 0,
    ///     buffer: 0,
    /// };
    /// let bytes: Vec<u8> = (0..30).flat_map(|v| (v as f32).to_ne_bytes()).collect();
    /// let mut arrays = [None; ARRAY_KINDS];
    /// arrays[0] = Some((&vertex_array, &bytes[..]));
    /// let fetch = ArrayFetch::new(0, arrays);
    /// let mut block = InputBlock::default();
    /// fetch.fill_run(&mut block, 1, 8); // elements 1 to 8
    /// assert_eq!(lanes4_get(&block.position, 7), Vec4::new(24.0, 25.0, 26.0, 1.0));
    /// ```
    #[inline(always)]
    pub fn fill_run(&self, block: &mut InputBlock, first: usize, len: usize) {
        self.fill_with(block, len, |source, offsets| {
            if source.floats.is_some() {
                return Some(first - self.base);
            }
            for (lane, offset) in offsets.iter_mut().enumerate() {
                *offset = (first - self.base + lane) * source.stride;
            }
            None
        });
    }

    /// `fill_run` for consecutive blocks: `inputs[k]` gets the elements from
    /// `first + k * LANES` on, of the `count` from `first` (a count, not an end, so that a
    /// run may end at index usize::MAX). When every array is read as floats (or not at
    /// all), they are read an array at a time, each over all the blocks, so that the choice
    /// of array and converter is made once per call rather than once per block; a packed
    /// array of 2 to 4 floats filling every block is sliced once for them all.
    #[inline(always)]
    pub fn fill_runs(&self, inputs: &mut [InputBlock], first: usize, count: usize) {
        let start = |k: usize| first + k * LANES;
        let len = |k: usize| LANES.min(count - k * LANES);
        let by_array = self.arrays.iter().flatten().all(|s| s.floats.is_some());
        self.prefetch_ahead(first, inputs.len());
        if !by_array {
            for (k, input) in inputs.iter_mut().enumerate() {
                self.fill_run(input, start(k), len(k));
            }
            return;
        }
        for (k, input) in inputs.iter_mut().enumerate() {
            input.len = len(k);
        }
        let full = inputs.iter().all(|input| input.len == LANES);
        for (kind, source) in ALL_KINDS.into_iter().zip(&self.arrays) {
            let Some(source) = source else { continue };
            let Some(size) = source.floats else { continue };
            let packed = |n: usize| full && size == n && source.stride == 4 * n;
            let first = first - self.base;
            let done = if packed(2) {
                read_packed_blocks::<2>(source.bytes, first, kind, inputs)
            } else if packed(3) {
                read_packed_blocks::<3>(source.bytes, first, kind, inputs)
            } else if packed(4) {
                read_packed_blocks::<4>(source.bytes, first, kind, inputs)
            } else {
                false
            };
            if done {
                continue;
            }
            for (k, input) in inputs.iter_mut().enumerate() {
                let len = input.len;
                if let Some(out) = float_lanes(kind, input) {
                    read_float_run(source, size, first + k * LANES, len, out);
                }
            }
        }
    }

    /// Asks for the lines of the elements `blocks` blocks from element `first` will hold
    /// when they are `PREFETCH_AHEAD` elements on: `fill_runs` reads a draw's runs in order.
    fn prefetch_ahead(&self, first: usize, blocks: usize) {
        for source in self.arrays.iter().flatten() {
            // Saturating: past the arrays' end (huge strides included) nothing is asked.
            let ahead = first - self.base + PREFETCH_AHEAD;
            let start = ahead.saturating_mul(source.stride);
            prefetch(
                source.bytes,
                start,
                (blocks * LANES).saturating_mul(source.stride),
            );
        }
    }

    /// The arrays' elements into `block`'s `len` lanes: `locate(source, offsets)` gives the
    /// first element of a run of an array of floats (`read_floats`), or sets the elements'
    /// byte offsets for its converter.
    #[inline(always)]
    fn fill_with(
        &self,
        block: &mut InputBlock,
        len: usize,
        locate: impl Fn(&ArraySource, &mut [usize; LANES]) -> Option<usize>,
    ) {
        let mut offsets = [0; LANES];
        block.len = len;
        let mut edge_flags = [[0.0; LANES]; 1];
        for (kind, source) in ALL_KINDS.into_iter().zip(&self.arrays) {
            let Some(source) = source else { continue };
            let out: &mut [LanesF32] = match kind {
                ArrayKind::EdgeFlag => &mut edge_flags,
                _ => float_lanes(kind, block).expect("the arrays kept have lanes"),
            };
            match (locate(source, &mut offsets), source.floats) {
                (Some(first), Some(size)) => read_float_run(source, size, first, len, out),
                _ => (source.convert)(source.bytes, &offsets[..len], out),
            }
            if kind == ArrayKind::EdgeFlag {
                for (flag, value) in block.edge_flag.iter_mut().zip(edge_flags[0]) {
                    *flag = value != 0.0;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every float array layout a full block can be read as one run from (sizes 2 to 4 of
    /// each kind, packed, padded and unaligned strides, the bytes ending with the last
    /// element) gives the lanes reading the elements one by one gives, to the bit, and a
    /// block whose indices are not consecutive is read element by element.
    #[test]
    fn runs_of_floats_equal_elements_one_by_one() {
        let kinds = [(0, 2..=4), (1, 3..=3), (2, 3..=4), (3, 2..=4), (5, 3..=3)];
        for (kind, sizes) in kinds {
            for size in sizes {
                for (stride, skew) in [(0, 0), (4 * size + 8, 0), (4 * size, 1), (4 * size + 4, 3)]
                {
                    let array = ClientArray {
                        enabled: true,
                        size,
                        component_type: GL_FLOAT,
                        stride,
                        address: 0,
                        buffer: 0,
                    };
                    let stride = array.effective_stride();
                    let elements = 19;
                    // The last element ends the bytes: a 16-byte read past it would panic.
                    let len = skew + (elements - 1) * stride + 4 * size as usize;
                    let bytes: Vec<u8> = (0..len).map(|k| (k * 7 % 251) as u8 ^ 0x40).collect();
                    let mut arrays = [None; ARRAY_KINDS];
                    arrays[kind] = Some((&array, &bytes[skew..]));
                    let fetch = ArrayFetch::new(3, arrays);
                    for first in 3..3 + elements - LANES + 1 {
                        let mut run = InputBlock::default();
                        fetch.fill_run(&mut run, first, LANES);
                        let mut contiguous = InputBlock::default();
                        let indices: [usize; LANES] = std::array::from_fn(|k| first + k);
                        fetch.fill(&mut contiguous, &indices);
                        let mut one_by_one = InputBlock::default();
                        for k in 0..LANES {
                            let mut single = InputBlock::default();
                            fetch.fill(&mut single, &[first + k]);
                            one_by_one.push(single.vertex(0).0, &single.vertex(0).1);
                        }
                        let bits = |b: &InputBlock| {
                            format!("{:?}", (0..LANES).map(|k| b.vertex(k)).collect::<Vec<_>>())
                        };
                        let what =
                            format!("kind {kind}, size {size}, stride {stride}, first {first}");
                        assert_eq!(bits(&run), bits(&one_by_one), "{what}");
                        assert_eq!(bits(&contiguous), bits(&one_by_one), "{what}");
                    }
                }
            }
        }
    }

    /// Consecutive blocks filled together (`fill_runs`) hold what each filled alone
    /// (`fill_run`) holds, to the bit: arrays of floats alone (read an array at a time, a fog
    /// coordinate array among them), and with an array of bytes or edge flags (block by
    /// block); over full blocks (packed arrays of 2, 3 and 4 floats read as one run) and over a
    /// last block that is not full; with bytes to spare after the last element, and with none.
    #[test]
    fn blocks_filled_together_equal_blocks_filled_alone() {
        let array = |size, component_type| ClientArray {
            enabled: true,
            size,
            component_type,
            stride: 0,
            address: 0,
            buffer: 0,
        };
        let (base, elements) = (3, 5 * LANES - 3);
        let bytes: Vec<u8> = (0..16 * (base + elements))
            .map(|k| (k * 7 % 251) as u8 ^ 0x40)
            .collect();
        let (float3, float4, float1) = (array(3, GL_FLOAT), array(4, GL_FLOAT), array(1, GL_FLOAT));
        let float2 = array(2, GL_FLOAT);
        let (bytes4, flags) = (array(4, GL_UNSIGNED_BYTE), array(1, GL_UNSIGNED_BYTE));
        let kind = |kind| ALL_KINDS.iter().position(|&k| k == kind).unwrap();
        let cases: [&[(ArrayKind, &ClientArray)]; 3] = [
            &[
                (ArrayKind::Vertex, &float3),
                (ArrayKind::Normal, &float3),
                (ArrayKind::Color, &float4),
                (ArrayKind::TexCoord, &float2),
                (ArrayKind::FogCoord, &float1),
            ],
            &[(ArrayKind::Vertex, &float3), (ArrayKind::Color, &bytes4)],
            &[(ArrayKind::Vertex, &float4), (ArrayKind::EdgeFlag, &flags)],
        ];
        let first = base + 1;
        for (case, count, spare) in cases
            .into_iter()
            .flat_map(|case| {
                [(case, 4 * LANES), (case, elements - 1)]
                    .map(|(c, n)| [(c, n, true), (c, n, false)])
            })
            .flatten()
        {
            let end = first + count;
            let mut arrays = [None; ARRAY_KINDS];
            for &(k, array) in case {
                let len = if spare {
                    bytes.len()
                } else {
                    (end - base) * array.element_size()
                };
                arrays[kind(k)] = Some((array, &bytes[..len]));
            }
            let fetch = ArrayFetch::new(base, arrays);
            let mut together = vec![InputBlock::default(); count.div_ceil(LANES)];
            fetch.fill_runs(&mut together, first, count);
            for (k, block) in together.iter().enumerate() {
                let start = first + k * LANES;
                let mut alone = InputBlock::default();
                fetch.fill_run(&mut alone, start, LANES.min(end - start));
                let lanes = |b: &InputBlock| {
                    format!(
                        "{} {:?}",
                        b.len,
                        (0..b.len).map(|k| b.vertex(k)).collect::<Vec<_>>()
                    )
                };
                assert_eq!(
                    lanes(block),
                    lanes(&alone),
                    "{case:?}, {count} elements, spare {spare}, block {k}"
                );
            }
        }
    }
}
