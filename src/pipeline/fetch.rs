//! Array fetch (§2.8): each enabled array gets one converter per draw, chosen from its type,
//! size and kind (normalized or not), that decodes a block of elements at a time into the
//! lanes of an `InputBlock`. No per-element dispatch on the type.

use crate::gl::*;
use crate::lighting::lanes::LanesF32;
use crate::pipeline::block::InputBlock;
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
}

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
        let arrays = std::array::from_fn(|k| {
            arrays[k].map(|(array, bytes)| ArraySource {
                bytes,
                stride: array.effective_stride(),
                convert: converter(array, ALL_KINDS[k].normalized()),
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
        let mut offsets = [0; crate::lighting::lanes::LANES];
        block.len = indices.len();
        let mut edge_flags = [[0.0; crate::lighting::lanes::LANES]; 1];
        for (kind, source) in ALL_KINDS.into_iter().zip(&self.arrays) {
            let Some(source) = source else { continue };
            let out: &mut [LanesF32] = match kind {
                ArrayKind::Vertex => &mut block.position,
                ArrayKind::Normal => &mut block.normal,
                ArrayKind::Color => &mut block.color,
                ArrayKind::TexCoord => &mut block.tex_coord,
                ArrayKind::SecondaryColor => &mut block.secondary_color,
                ArrayKind::EdgeFlag => &mut edge_flags,
                // Fog coordinates and color indices reach nothing an RGBA vertex computes.
                ArrayKind::FogCoord | ArrayKind::Index => continue,
            };
            for (offset, &index) in offsets.iter_mut().zip(indices) {
                *offset = (index - self.base) * source.stride;
            }
            let offsets = &offsets[..indices.len()];
            (source.convert)(source.bytes, offsets, out);
            if kind == ArrayKind::EdgeFlag {
                for (flag, value) in block.edge_flag.iter_mut().zip(edge_flags[0]) {
                    *flag = value != 0.0;
                }
            }
        }
    }
}
