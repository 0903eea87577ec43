//! Vertex arrays (§2.8): the pointer commands, glEnableClientState, glInterleavedArrays,
//! glGetPointerv, glArrayElement, glDrawArrays, glDrawElements and glDrawRangeElements.
//!
//! A draw happens in three steps, so that only the C layer touches the application's memory:
//! 1. `check_draw_arrays` / `check_draw_elements` / `check_draw_range_elements` validate the
//!    call (GL errors) and say what the indices are;
//! 2. the C layer reads the indices, and `array_spans` says which bytes of each enabled array
//!    the indices actually reference (never more; glDrawRangeElements' start and end are not
//!    trusted); the C layer turns those spans into slices;
//! 3. `draw_arrays_from` decodes the referenced elements, runs each vertex through
//!    `DerivedState::process` (the path glVertex takes) and hands the vertices to primitive
//!    assembly.
//!
//! Rust callers skip step 2: they pass the bytes of their arrays in an `ArraySources` (the
//! addresses given to the pointer commands are then only what glGetPointerv returns).

use glam::{Vec3, Vec4};
use multiversion::multiversion;

use crate::commands::buffers::with_stores;
use crate::context::Context;
use crate::error::{GlError, GlResult, try_copy};
use crate::gl::*;
use crate::lighting::lanes::LANES;
use crate::pipeline::STREAMED_BLOCKS;
use crate::pipeline::block::InputBlock;
use crate::pipeline::fetch::ArrayFetch;
use crate::pipeline::parallel::light_in_order;
use crate::pipeline::units::EXTRA_UNITS;
use crate::state::arrays::{ARRAY_KINDS, ArrayKind, ByteSpan, ClientArray, VertexArrays};
use crate::threads::threads_for;

/// The size of one index of glDrawElements' `type`; `None` for an invalid type.
///
/// # Examples
///
/// ```
/// use fflight::{commands::arrays::index_size, gl::*};
/// assert_eq!(index_size(GL_UNSIGNED_SHORT), Some(2));
/// assert_eq!(index_size(GL_FLOAT), None);
/// ```
pub fn index_size(index_type: GLenum) -> Option<usize> {
    match index_type {
        GL_UNSIGNED_BYTE => Some(1),
        GL_UNSIGNED_SHORT => Some(2),
        GL_UNSIGNED_INT => Some(4),
        _ => None,
    }
}

/// The smallest and the largest of `bytes`' indices of `index_type` (`None` when there are
/// none), folded in the index's own type without a branch per index and compiled for AVX2
/// where the CPU has it, so that the loop runs near memory speed: a draw scans its indices
/// before it starts (6M GL_UNSIGNED_INT indices: 8.5 ms folded as usize on SSE2, 2.7 here).
#[multiversion(targets("x86_64+avx2+fma+bmi1+bmi2+lzcnt+popcnt", "aarch64+neon"))]
fn listed_range(index_type: GLenum, bytes: &[u8]) -> Option<(usize, usize)> {
    // Empty leaves the lowest above the highest.
    macro_rules! min_max {
        ($t:ty, $indices:expr) => {{
            let (lo, hi) = $indices.fold((<$t>::MAX, 0), |(lo, hi): ($t, $t), i| {
                (lo.min(i), hi.max(i))
            });
            (lo <= hi).then_some((lo as usize, hi as usize))
        }};
    }
    match index_type {
        GL_UNSIGNED_BYTE => min_max!(u8, bytes.iter().copied()),
        GL_UNSIGNED_SHORT => min_max!(
            u16,
            bytes
                .chunks_exact(2)
                .map(|c| u16::from_ne_bytes([c[0], c[1]]))
        ),
        GL_UNSIGNED_INT => min_max!(
            u32,
            bytes
                .chunks_exact(4)
                .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
        ),
        _ => None,
    }
}

/// The array elements a draw uses, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ElementIndices<'a> {
    /// glDrawArrays: `first`, `first + 1`, ..., `count` of them.
    Sequential {
        /// The first element.
        first: usize,
        /// How many elements.
        count: usize,
    },
    /// glDrawElements: indices of `index_type` (GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or
    /// GL_UNSIGNED_INT) in native byte order, at any alignment; a partial index at the end
    /// is ignored.
    Listed {
        /// GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or GL_UNSIGNED_INT.
        index_type: GLenum,
        /// The indices' bytes.
        bytes: &'a [u8],
    },
}

impl<'a> ElementIndices<'a> {
    /// How many vertices the draw has.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ElementIndices, gl::*};
    /// let indices = [0u16, 1, 2];
    /// let bytes: Vec<u8> = indices.iter().flat_map(|i| i.to_ne_bytes()).collect();
    /// let listed = ElementIndices::Listed { index_type: GL_UNSIGNED_SHORT, bytes: &bytes };
    /// assert_eq!(listed.len(), 3);
    /// assert_eq!(ElementIndices::Sequential { first: 4, count: 2 }.range(), Some((4, 5)));
    /// ```
    pub fn len(&self) -> usize {
        match *self {
            ElementIndices::Sequential { count, .. } => count,
            ElementIndices::Listed { index_type, bytes } => {
                bytes.len() / index_size(index_type).unwrap_or(usize::MAX)
            }
        }
    }

    /// Whether the draw has no vertex.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::commands::arrays::ElementIndices;
    /// assert!(ElementIndices::Sequential { first: 3, count: 0 }.is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Calls `f` with each index, in order.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ElementIndices, gl::*};
    /// let mut seen = Vec::new();
    /// ElementIndices::Listed { index_type: GL_UNSIGNED_BYTE, bytes: &[2, 0, 1] }.for_each(|i| seen.push(i));
    /// assert_eq!(seen, [2, 0, 1]);
    /// ```
    pub fn for_each(&self, mut f: impl FnMut(usize)) {
        match *self {
            ElementIndices::Sequential { first, count } => {
                // Inclusive, so that an index of usize::MAX ends the range instead of
                // overflowing it.
                let last = first.saturating_add(count.saturating_sub(1));
                (first..=last).take(count).for_each(f)
            }
            ElementIndices::Listed { index_type, bytes } => match index_type {
                GL_UNSIGNED_BYTE => bytes.iter().for_each(|&i| f(i as usize)),
                GL_UNSIGNED_SHORT => bytes
                    .chunks_exact(2)
                    .for_each(|c| f(u16::from_ne_bytes([c[0], c[1]]) as usize)),
                GL_UNSIGNED_INT => bytes
                    .chunks_exact(4)
                    .for_each(|c| f(u32::from_ne_bytes([c[0], c[1], c[2], c[3]]) as usize)),
                _ => {}
            },
        }
    }

    /// The smallest and the largest index; `None` when there are none.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ElementIndices, gl::*};
    /// let listed = ElementIndices::Listed { index_type: GL_UNSIGNED_BYTE, bytes: &[7, 3, 5] };
    /// assert_eq!(listed.range(), Some((3, 7)));
    /// assert_eq!(ElementIndices::Sequential { first: 0, count: 0 }.range(), None);
    /// ```
    pub fn range(&self) -> Option<(usize, usize)> {
        match *self {
            ElementIndices::Sequential { count: 0, .. } => None,
            ElementIndices::Sequential { first, count } => {
                Some((first, first.saturating_add(count - 1)))
            }
            ElementIndices::Listed { index_type, bytes } => listed_range(index_type, bytes),
        }
    }

    /// Elements `start..end` of these (clamped to their number).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ElementIndices, gl::*};
    /// let listed = ElementIndices::Listed { index_type: GL_UNSIGNED_BYTE, bytes: &[2, 0, 1, 5] };
    /// assert_eq!(listed.slice(1, 3).range(), Some((0, 1)));
    /// let sequential = ElementIndices::Sequential { first: 10, count: 5 };
    /// assert_eq!(sequential.slice(3, 9), ElementIndices::Sequential { first: 13, count: 2 });
    /// ```
    pub fn slice(&self, start: usize, end: usize) -> ElementIndices<'a> {
        let end = end.min(self.len());
        let start = start.min(end);
        match *self {
            ElementIndices::Sequential { first, .. } => ElementIndices::Sequential {
                first: first + start,
                count: end - start,
            },
            ElementIndices::Listed { index_type, bytes } => {
                let size = index_size(index_type).unwrap_or(1);
                ElementIndices::Listed {
                    index_type,
                    bytes: &bytes[start * size..end * size],
                }
            }
        }
    }

    /// Calls `f` with the indices of each separate triangle, in order (GL_TRIANGLES' grouping,
    /// §2.6.1): an incomplete last triangle is dropped.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ElementIndices, gl::*};
    /// let mut seen = Vec::new();
    /// let listed = ElementIndices::Listed { index_type: GL_UNSIGNED_BYTE, bytes: &[2, 0, 1, 5, 4] };
    /// listed.for_each_triangle(|t| seen.push(t));
    /// assert_eq!(seen, [[2, 0, 1]]);
    /// ```
    pub fn for_each_triangle(&self, mut f: impl FnMut([usize; 3])) {
        match *self {
            ElementIndices::Listed {
                index_type: GL_UNSIGNED_INT,
                bytes,
            } => bytes.chunks_exact(12).for_each(|c| {
                f(std::array::from_fn(|k| {
                    u32::from_ne_bytes([c[4 * k], c[4 * k + 1], c[4 * k + 2], c[4 * k + 3]])
                        as usize
                }))
            }),
            _ => {
                let (mut corners, mut k) = ([0; 3], 0);
                self.for_each(|index| {
                    corners[k] = index;
                    k += 1;
                    if k == 3 {
                        k = 0;
                        f(corners);
                    }
                });
            }
        }
    }
}

/// The bytes of the enabled arrays that a draw reads: `bytes[kind as usize]` starts with
/// element `base` of that array and holds every element the draw uses. Arrays that are not
/// enabled are not read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ArraySources<'a> {
    /// The first element any array's bytes hold.
    pub base: usize,
    /// Each array's bytes by `ArrayKind`, empty for the arrays that are not read.
    pub bytes: [&'a [u8]; ARRAY_KINDS],
    /// Texture units 1 and up's texture coordinate arrays' bytes (by unit - 1), read for
    /// capture; `bytes[ArrayKind::TexCoord]` is unit 0's.
    pub unit_bytes: [&'a [u8]; EXTRA_UNITS],
}

impl<'a> ArraySources<'a> {
    /// Sources whose slices start with element `base`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ArraySources, state::arrays::ArrayKind};
    /// let sources = ArraySources::new(10);
    /// assert_eq!(sources.base, 10);
    /// assert!(sources.bytes[ArrayKind::Vertex as usize].is_empty());
    /// ```
    pub fn new(base: usize) -> ArraySources<'a> {
        ArraySources {
            base,
            bytes: [&[]; ARRAY_KINDS],
            unit_bytes: [&[]; EXTRA_UNITS],
        }
    }

    /// These sources with `bytes` for texture unit `unit`'s texture coordinate array.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ArraySources, state::arrays::ArrayKind};
    /// let bytes = [0u8; 8];
    /// let sources = ArraySources::new(0).with_unit(2, &bytes);
    /// assert_eq!(sources.unit_bytes[1].len(), 8);
    /// let sources = sources.with_unit(0, &bytes); // unit 0's is the ArrayKind::TexCoord slot
    /// assert_eq!(sources.bytes[ArrayKind::TexCoord as usize].len(), 8);
    /// ```
    pub fn with_unit(mut self, unit: usize, bytes: &'a [u8]) -> ArraySources<'a> {
        match unit {
            0 => self.bytes[ArrayKind::TexCoord as usize] = bytes,
            _ => self.unit_bytes[unit - 1] = bytes,
        }
        self
    }

    /// These sources with `bytes` for the array `kind`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ArraySources, state::arrays::ArrayKind};
    /// let bytes = [0u8; 12];
    /// let sources = ArraySources::new(0).with(ArrayKind::Normal, &bytes);
    /// assert_eq!(sources.bytes[ArrayKind::Normal as usize].len(), 12);
    /// ```
    pub fn with(mut self, kind: ArrayKind, bytes: &'a [u8]) -> ArraySources<'a> {
        self.bytes[kind as usize] = bytes;
        self
    }
}

/// What the enabled arrays give one element; `None` for an array that is not enabled.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ArrayElementValues {
    position: Option<Vec4>,
    normal: Option<Vec3>,
    color: Option<Vec4>,
    tex_coord: Option<Vec4>,
    edge_flag: Option<bool>,
    secondary_color: Option<[f32; 3]>,
    fog_coord: Option<f32>,
    index: Option<f32>,
    /// Texture units 1 and up's (by unit - 1); `None` when none of their arrays is enabled
    /// (boxed: display lists keep many elements).
    unit_tex_coords: Option<Box<[Option<Vec4>; EXTRA_UNITS]>>,
}

/// Decodes elements of the enabled arrays from sources checked to hold them.
struct ArrayReader<'a> {
    arrays: [Option<(&'a ClientArray, &'a [u8])>; ARRAY_KINDS],
    /// Texture units 1 and up's texture coordinate arrays.
    units: [Option<(&'a ClientArray, &'a [u8])>; EXTRA_UNITS],
    base: usize,
}

impl<'a> ArrayReader<'a> {
    /// GL_INVALID_OPERATION unless every enabled array's bytes hold elements `first..=last`.
    fn new(
        arrays: &'a VertexArrays,
        sources: &ArraySources<'a>,
        first: usize,
        last: usize,
    ) -> GlResult<ArrayReader<'a>> {
        let mut reader = ArrayReader {
            arrays: [None; ARRAY_KINDS],
            units: [None; EXTRA_UNITS],
            base: sources.base,
        };
        if first < sources.base {
            return Err(GlError::InvalidOperation);
        }
        let holding =
            |array: &'a ClientArray, bytes: &'a [u8]| match array.span_len(sources.base, last) {
                Some(len) if len <= bytes.len() => Ok(Some((array, bytes))),
                _ => Err(GlError::InvalidOperation),
            };
        for (kind, array) in arrays.enabled() {
            reader.arrays[kind as usize] = holding(array, sources.bytes[kind as usize])?;
        }
        let units = arrays.enabled_unit_arrays();
        for ((unit, array), bytes) in reader.units.iter_mut().zip(units).zip(sources.unit_bytes) {
            if let Some(array) = array {
                *unit = holding(array, bytes)?;
            }
        }
        Ok(reader)
    }

    fn read(&self, kind: ArrayKind, index: usize) -> Option<[f32; 4]> {
        let (array, bytes) = self.arrays[kind as usize]?;
        Some(array.read(kind, bytes, self.base, index))
    }

    /// Texture unit `k + 1`'s coordinates of element `index`.
    fn read_unit(&self, k: usize, index: usize) -> Option<Vec4> {
        let (array, bytes) = self.units[k]?;
        let coords = array.read(ArrayKind::TexCoord, bytes, self.base, index);
        Some(Vec4::from_array(coords))
    }

    /// Appends to the capture texture units 1 and up's coordinates of each vertex of a
    /// draw of `indices` that was just captured (`pipeline::units`): each unit's array
    /// element, or its current coordinates, through its generation and texture matrix.
    fn capture_units(&self, ctx: &mut Context, indices: &ElementIndices) {
        let transforms = ctx.unit_transforms();
        let current = ctx.current;
        indices.for_each(|index| {
            let object = self.read(ArrayKind::Vertex, index).map(Vec4::from_array);
            let normal = self.read(ArrayKind::Normal, index);
            let given = std::array::from_fn(|k| {
                self.read_unit(k, index)
                    .unwrap_or(current.other_tex_coords[k])
            });
            ctx.capture.push_units(&transforms.process(
                object.unwrap_or(Vec4::W),
                normal.map_or(current.normal, |n| Vec3::new(n[0], n[1], n[2])),
                &given,
            ));
        });
    }

    fn element(&self, index: usize) -> ArrayElementValues {
        ArrayElementValues {
            position: self.read(ArrayKind::Vertex, index).map(Vec4::from_array),
            normal: self
                .read(ArrayKind::Normal, index)
                .map(|n| Vec3::new(n[0], n[1], n[2])),
            color: self.read(ArrayKind::Color, index).map(Vec4::from_array),
            tex_coord: self.read(ArrayKind::TexCoord, index).map(Vec4::from_array),
            edge_flag: self.read(ArrayKind::EdgeFlag, index).map(|e| e[0] != 0.0),
            secondary_color: self
                .read(ArrayKind::SecondaryColor, index)
                .map(|c| [c[0], c[1], c[2]]),
            fog_coord: self.read(ArrayKind::FogCoord, index).map(|f| f[0]),
            index: self.read(ArrayKind::Index, index).map(|i| i[0]),
            unit_tex_coords: self
                .units
                .iter()
                .any(Option::is_some)
                .then(|| Box::new(std::array::from_fn(|k| self.read_unit(k, index)))),
        }
    }
}

/// A vertex-array draw compiled into a display list: the enabled arrays as they were, each
/// with a copy of its bytes from element `base` to the last element the draw uses (buffer
/// objects' data included: §5.4 dereferences them at compile time), and the indices.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordedDraw {
    mode: GLenum,
    base: usize,
    arrays: [Option<(ClientArray, Vec<u8>)>; ARRAY_KINDS],
    /// Texture units 1 and up's texture coordinate arrays (read for capture).
    units: [Option<(ClientArray, Vec<u8>)>; EXTRA_UNITS],
    indices: RecordedIndices,
}

/// `ElementIndices` that own their bytes.
#[derive(Clone, Debug, PartialEq)]
enum RecordedIndices {
    Sequential { first: usize, count: usize },
    Listed { index_type: GLenum, bytes: Vec<u8> },
}

impl RecordedIndices {
    fn borrow(&self) -> ElementIndices<'_> {
        match *self {
            RecordedIndices::Sequential { first, count } => {
                ElementIndices::Sequential { first, count }
            }
            RecordedIndices::Listed {
                index_type,
                ref bytes,
            } => ElementIndices::Listed { index_type, bytes },
        }
    }
}

/// GL_INVALID_ENUM unless `mode` is a primitive (§2.6.1).
fn check_mode(mode: GLenum) -> GlResult {
    if mode > GL_POLYGON {
        Err(GlError::InvalidEnum)
    } else {
        Ok(())
    }
}

/// The checks every draw of `indices` makes when it runs.
fn check_draw(ctx: &Context, mode: GLenum, indices: &ElementIndices) -> GlResult {
    ctx.outside_begin_end()?;
    check_mode(mode)?;
    match *indices {
        ElementIndices::Listed { index_type, .. } => {
            index_size(index_type).ok_or(GlError::InvalidEnum)?;
        }
        ElementIndices::Sequential { first, count } => {
            if count > 0 && first.checked_add(count - 1).is_none() {
                return Err(GlError::InvalidValue);
            }
        }
    }
    Ok(())
}

impl Context {
    /// The vertex array state.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.client_state(GL_TEXTURE_COORD_ARRAY, true)?;
    /// ctx.client_active_texture(GL_TEXTURE1)?;
    /// assert_eq!(ctx.vertex_arrays().client_active_texture, 1);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn vertex_arrays(&self) -> &VertexArrays {
        &self.arrays
    }

    /// glVertexPointer. `address` is the application's pointer (0 for NULL): only the C
    /// layer reads through it. Like Mesa, the pointer commands are accepted between glBegin
    /// and glEnd (GL 1.5 §2.6.3 leaves the error optional).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// let positions = [0.0f32; 12];
    /// ctx.vertex_pointer(3, GL_FLOAT, 0, positions.as_ptr() as usize)?;
    /// assert_eq!(ctx.get_pointer(GL_VERTEX_ARRAY_POINTER)?, positions.as_ptr() as usize);
    /// assert_eq!(ctx.vertex_pointer(1, GL_FLOAT, 0, 0), Err(GlError::InvalidValue)); // size 1
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn vertex_pointer(
        &mut self,
        size: i32,
        component_type: GLenum,
        stride: i32,
        address: usize,
    ) -> GlResult {
        self.arrays
            .set_pointer(ArrayKind::Vertex, size, component_type, stride, address)
    }

    /// glNormalPointer.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.normal_pointer(GL_BYTE, 0, 0x100)?;
    /// assert_eq!(ctx.get(GL_NORMAL_ARRAY_TYPE)?.as_ints(), [GL_BYTE as i32]);
    /// assert_eq!(ctx.normal_pointer(GL_UNSIGNED_BYTE, 0, 0x100), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn normal_pointer(
        &mut self,
        component_type: GLenum,
        stride: i32,
        address: usize,
    ) -> GlResult {
        self.arrays
            .set_pointer(ArrayKind::Normal, 3, component_type, stride, address)
    }

    /// glColorPointer.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.color_pointer(4, GL_UNSIGNED_BYTE, 0, 0x100)?;
    /// assert_eq!(ctx.get(GL_COLOR_ARRAY_SIZE)?.as_ints(), [4]);
    /// assert_eq!(ctx.color_pointer(2, GL_FLOAT, 0, 0x100), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn color_pointer(
        &mut self,
        size: i32,
        component_type: GLenum,
        stride: i32,
        address: usize,
    ) -> GlResult {
        self.arrays
            .set_pointer(ArrayKind::Color, size, component_type, stride, address)
    }

    /// glTexCoordPointer.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.tex_coord_pointer(2, GL_FLOAT, 16, 0x100)?;
    /// assert_eq!(ctx.get(GL_TEXTURE_COORD_ARRAY_STRIDE)?.as_ints(), [16]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_coord_pointer(
        &mut self,
        size: i32,
        component_type: GLenum,
        stride: i32,
        address: usize,
    ) -> GlResult {
        self.arrays
            .set_pointer(ArrayKind::TexCoord, size, component_type, stride, address)
    }

    /// glEdgeFlagPointer: the flags are GLbooleans.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.edge_flag_pointer(0, 0x100)?;
    /// assert_eq!(ctx.get_pointer(GL_EDGE_FLAG_ARRAY_POINTER)?, 0x100);
    /// assert_eq!(ctx.edge_flag_pointer(-1, 0x100), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn edge_flag_pointer(&mut self, stride: i32, address: usize) -> GlResult {
        self.arrays
            .set_pointer(ArrayKind::EdgeFlag, 1, GL_UNSIGNED_BYTE, stride, address)
    }

    /// glSecondaryColorPointer (GL 1.4).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.secondary_color_pointer(3, GL_FLOAT, 0, 0x100)?;
    /// assert_eq!(ctx.secondary_color_pointer(4, GL_FLOAT, 0, 0x100), Err(GlError::InvalidValue)); // 3 only
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn secondary_color_pointer(
        &mut self,
        size: i32,
        component_type: GLenum,
        stride: i32,
        address: usize,
    ) -> GlResult {
        self.arrays.set_pointer(
            ArrayKind::SecondaryColor,
            size,
            component_type,
            stride,
            address,
        )
    }

    /// glIndexPointer.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.index_pointer(GL_SHORT, 0, 0x100)?;
    /// assert_eq!(ctx.get(GL_INDEX_ARRAY_TYPE)?.as_ints(), [GL_SHORT as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn index_pointer(
        &mut self,
        component_type: GLenum,
        stride: i32,
        address: usize,
    ) -> GlResult {
        self.arrays
            .set_pointer(ArrayKind::Index, 1, component_type, stride, address)
    }

    /// glFogCoordPointer (GL 1.4).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.fog_coord_pointer(GL_DOUBLE, 0, 0x100)?;
    /// assert_eq!(ctx.fog_coord_pointer(GL_INT, 0, 0x100), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn fog_coord_pointer(
        &mut self,
        component_type: GLenum,
        stride: i32,
        address: usize,
    ) -> GlResult {
        self.arrays
            .set_pointer(ArrayKind::FogCoord, 1, component_type, stride, address)
    }

    /// glEnableClientState / glDisableClientState. GL_INDEX_ARRAY is accepted and only
    /// stored (fflight has no color index mode).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.client_state(GL_NORMAL_ARRAY, true)?;
    /// assert_eq!(ctx.get(GL_NORMAL_ARRAY)?.as_bools(), [true]);
    /// assert_eq!(ctx.client_state(GL_LIGHTING, true), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn client_state(&mut self, array: GLenum, enabled: bool) -> GlResult {
        self.arrays.set_enabled(array, enabled)
    }

    /// glInterleavedArrays (table 2.5).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.interleaved_arrays(GL_N3F_V3F, 0, 0x1000)?;
    /// assert_eq!(ctx.get(GL_NORMAL_ARRAY)?.as_bools(), [true]);
    /// assert_eq!(ctx.get(GL_VERTEX_ARRAY_STRIDE)?.as_ints(), [24]); // the normal and the vertex
    /// assert_eq!(ctx.get_pointer(GL_VERTEX_ARRAY_POINTER)?, 0x1000 + 12);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn interleaved_arrays(&mut self, format: GLenum, stride: i32, address: usize) -> GlResult {
        self.arrays.set_interleaved(format, stride, address)
    }

    /// glGetPointerv: an array's address, or the feedback buffer's.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.feedback_buffer(4, GL_2D, 0x2000)?;
    /// assert_eq!(ctx.get_pointer(GL_FEEDBACK_BUFFER_POINTER)?, 0x2000);
    /// assert_eq!(ctx.get_pointer(GL_COLOR_ARRAY_POINTER)?, 0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_pointer(&self, pname: GLenum) -> GlResult<usize> {
        self.outside_begin_end()?;
        match ArrayKind::of_pointer_name(pname) {
            Some(kind) => Ok(self.arrays.get(kind).address),
            None if pname == GL_FEEDBACK_BUFFER_POINTER => Ok(self.feedback_address),
            None if pname == GL_SELECTION_BUFFER_POINTER => Ok(self.selection.address),
            None => Err(GlError::InvalidEnum),
        }
    }

    /// glArrayElement's checks: a negative index is GL_INVALID_VALUE (GL leaves it
    /// undefined; it would read before the arrays). Legal between glBegin and glEnd.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{Context, GlError};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.check_array_element(5)?, 5);
    /// assert_eq!(ctx.check_array_element(-1), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn check_array_element(&self, index: i32) -> GlResult<usize> {
        usize::try_from(index).map_err(|_| GlError::InvalidValue)
    }

    /// glDrawArrays' checks, in Mesa's order: glBegin/glEnd, count, mode. A negative
    /// `first` is GL_INVALID_VALUE (GL leaves it undefined, Mesa reads before the arrays).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ElementIndices, gl::*, Context, GlError};
    /// let ctx = Context::new();
    /// let elements = ctx.check_draw_arrays(GL_TRIANGLES, 2, 3)?;
    /// assert_eq!(elements, ElementIndices::Sequential { first: 2, count: 3 });
    /// assert_eq!(ctx.check_draw_arrays(GL_TRIANGLES, 0, -1), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn check_draw_arrays(
        &self,
        mode: GLenum,
        first: i32,
        count: i32,
    ) -> GlResult<ElementIndices<'static>> {
        self.outside_begin_end()?;
        let count = usize::try_from(count).map_err(|_| GlError::InvalidValue)?;
        check_mode(mode)?;
        let first = usize::try_from(first).map_err(|_| GlError::InvalidValue)?;
        Ok(ElementIndices::Sequential { first, count })
    }

    /// glMultiDrawArrays / glMultiDrawElements (§2.8): the checks of the whole call, in Mesa's
    /// order (glBegin/glEnd, primcount, mode, index type); returns how many draws it holds.
    /// Each draw is then the glDrawArrays or glDrawElements the spec's loop makes, for the
    /// counts above 0 only: a negative count is skipped, not an error (Mesa rejects the call).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.check_multi_draw(GL_TRIANGLES, None, 3)?, 3); // glMultiDrawArrays
    /// assert_eq!(ctx.check_multi_draw(GL_TRIANGLES, Some(GL_FLOAT), 3), Err(GlError::InvalidEnum));
    /// assert_eq!(ctx.check_multi_draw(GL_TRIANGLES, None, -1), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn check_multi_draw(
        &self,
        mode: GLenum,
        index_type: Option<GLenum>,
        primcount: i32,
    ) -> GlResult<usize> {
        self.outside_begin_end()?;
        let primcount = usize::try_from(primcount).map_err(|_| GlError::InvalidValue)?;
        check_mode(mode)?;
        if let Some(index_type) = index_type {
            index_size(index_type).ok_or(GlError::InvalidEnum)?;
        }
        Ok(primcount)
    }

    /// glDrawElements' checks, in Mesa's order: glBegin/glEnd, count, mode, type. Returns
    /// how many bytes of indices the draw reads.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// // With the vertex array disabled nothing is drawn, so no index is read.
    /// assert_eq!(ctx.check_draw_elements(GL_LINES, 4, GL_UNSIGNED_SHORT)?, 0);
    /// ctx.client_state(GL_VERTEX_ARRAY, true)?;
    /// assert_eq!(ctx.check_draw_elements(GL_LINES, 4, GL_UNSIGNED_SHORT)?, 8); // bytes of indices
    /// assert_eq!(ctx.check_draw_elements(GL_LINES, 4, GL_FLOAT), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn check_draw_elements(
        &self,
        mode: GLenum,
        count: i32,
        index_type: GLenum,
    ) -> GlResult<usize> {
        self.outside_begin_end()?;
        let count = usize::try_from(count).map_err(|_| GlError::InvalidValue)?;
        check_mode(mode)?;
        let size = index_size(index_type).ok_or(GlError::InvalidEnum)?;
        if !self.arrays.get(ArrayKind::Vertex).enabled {
            return Ok(0); // nothing is drawn, so not even the indices are read
        }
        Ok(count * size)
    }

    /// glDrawRangeElements' checks: `end < start` first (Mesa's order), then glDrawElements'.
    /// `start` and `end` are a hint only: indices outside them are drawn, and what is read
    /// is decided by the indices themselves.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.check_draw_range_elements(GL_POINTS, 5, 2, 1, GL_UNSIGNED_INT), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn check_draw_range_elements(
        &self,
        mode: GLenum,
        start: u32,
        end: u32,
        count: i32,
        index_type: GLenum,
    ) -> GlResult<usize> {
        self.outside_begin_end()?;
        if end < start {
            return Err(GlError::InvalidValue);
        }
        self.check_draw_elements(mode, count, index_type)
    }

    /// Which bytes of each enabled array (then of texture units 1 and up's enabled texture
    /// coordinate arrays, by unit - 1) a draw of `indices` reads, and the first and last
    /// index they hold; `None` when the draw reads nothing (no indices, or the vertex array is
    /// disabled: then no vertex is made, §2.8). A NULL pointer among the enabled arrays is
    /// GL_INVALID_OPERATION: GL leaves it undefined, fflight draws nothing.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ElementIndices, gl::*, state::arrays::ArrayKind, Context};
    /// let mut ctx = Context::new();
    /// ctx.vertex_pointer(3, GL_FLOAT, 0, 0x1000)?;
    /// ctx.client_state(GL_VERTEX_ARRAY, true)?;
    /// let ((first, last), spans, unit_spans) = ctx.array_spans(&ElementIndices::Sequential { first: 2, count: 2 })?.unwrap();
    /// let vertices = spans[ArrayKind::Vertex as usize].unwrap();
    /// // Elements 2 and 3: 24 bytes from element 2 on.
    /// assert_eq!((first, last, vertices.address, vertices.len), (2, 3, 0x1000 + 24, 24));
    /// assert!(unit_spans.iter().all(Option::is_none)); // no array of texture units 1 and up
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    #[allow(clippy::type_complexity)]
    pub fn array_spans(
        &self,
        indices: &ElementIndices,
    ) -> GlResult<
        Option<(
            (usize, usize),
            [Option<ByteSpan>; ARRAY_KINDS],
            [Option<ByteSpan>; EXTRA_UNITS],
        )>,
    > {
        // Without the vertex array not even the indices are read.
        if !self.arrays.get(ArrayKind::Vertex).enabled {
            return Ok(None);
        }
        let Some((first, last)) = indices.range() else {
            return Ok(None);
        };
        let spans = self.arrays.spans(first, last)?;
        let unit_spans = self.arrays.unit_spans(first, last)?;
        Ok(Some(((first, last), spans, unit_spans)))
    }

    /// glArrayElement (§2.8) from the arrays' bytes: the same as the glEdgeFlag,
    /// glTexCoord, glColor, glNormal and glVertex calls of the enabled arrays, so the
    /// current attributes become the element's (and an enabled color material follows the
    /// color). Legal between glBegin and glEnd, where the vertex joins the primitive.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ArraySources, gl::*, state::arrays::ArrayKind, Context};
    /// let mut ctx = Context::new();
    /// let colors = [1.0f32, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0];
    /// ctx.color_pointer(4, GL_FLOAT, 0, colors.as_ptr() as usize)?;
    /// ctx.client_state(GL_COLOR_ARRAY, true)?;
    /// let bytes: Vec<u8> = colors.iter().flat_map(|c| c.to_ne_bytes()).collect();
    /// ctx.array_element_from(1, &ArraySources::new(0).with(ArrayKind::Color, &bytes))?;
    /// assert_eq!(ctx.get(GL_CURRENT_COLOR)?.as_floats(), [0.0, 1.0, 0.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn array_element_from(&mut self, index: usize, sources: &ArraySources) -> GlResult {
        let element = self.array_element_values(index, sources)?;
        self.apply_array_element(&element);
        Ok(())
    }

    /// The values the enabled arrays give element `index` (what glArrayElement compiles).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ArraySources, commands::list::Command, gl::*};
    /// use fflight::{state::arrays::ArrayKind, Context};
    /// let mut ctx = Context::new();
    /// let normals = [0i16, 0, 32767];
    /// ctx.normal_pointer(GL_SHORT, 0, normals.as_ptr() as usize)?;
    /// ctx.client_state(GL_NORMAL_ARRAY, true)?;
    /// let bytes: Vec<u8> = normals.iter().flat_map(|n| n.to_ne_bytes()).collect();
    /// let element = ctx.array_element_values(0, &ArraySources::new(0).with(ArrayKind::Normal, &bytes))?;
    /// // What a display list keeps of glArrayElement(0); replayed, it sets the normal.
    /// Command::ArrayElement(element).execute(&mut ctx)?;
    /// // Shorts map to [-1, 1] as table 2.9 says: (2c + 1) / (2^16 - 1), so 0 is not quite 0.
    /// let normal = ctx.get(GL_CURRENT_NORMAL)?.as_floats();
    /// assert_eq!(normal[2], 1.0);
    /// assert!((normal[0] - 1.0 / 65535.0).abs() < 1e-9);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn array_element_values(
        &self,
        index: usize,
        sources: &ArraySources,
    ) -> GlResult<ArrayElementValues> {
        let arrays = self.arrays;
        let stores = self.array_stores(&arrays)?;
        let sources = with_stores(&arrays, sources, &stores);
        Ok(ArrayReader::new(&arrays, &sources, index, index)?.element(index))
    }

    /// glArrayElement's calls: glEdgeFlag, glTexCoord, glColor, glNormal and glVertex with
    /// the values of the enabled arrays.
    pub(crate) fn apply_array_element(&mut self, element: &ArrayElementValues) {
        if let Some(flag) = element.edge_flag {
            self.edge_flag(flag);
        }
        if let Some(tex_coord) = element.tex_coord {
            self.tex_coord(tex_coord);
        }
        for (unit, tex_coord) in (1..).zip(element.unit_tex_coords.iter().flat_map(|t| t.iter())) {
            if let Some(tex_coord) = tex_coord {
                self.current.set_unit_tex_coord(unit, *tex_coord);
            }
        }
        if let Some(color) = element.color {
            self.color(color);
        }
        if let Some(secondary_color) = element.secondary_color {
            self.secondary_color(secondary_color);
        }
        if let Some(color_index) = element.index {
            self.index(color_index);
        }
        if let Some(normal) = element.normal {
            self.normal(normal);
        }
        if let Some(fog_coord) = element.fog_coord {
            self.fog_coord(fog_coord);
        }
        if let Some(position) = element.position {
            self.vertex(position);
        }
    }

    /// glDrawArrays / glDrawElements / glDrawRangeElements from the arrays' bytes: the
    /// vertices of glBegin(mode), glArrayElement(i) for each index, glEnd. Each vertex is
    /// lit exactly as the equivalent immediate-mode calls light it (same
    /// `DerivedState::process`; with color material on, each vertex's color stands in for
    /// the tracked material, as after a glColor). The current attributes are left as they
    /// were (GL 1.5 §2.8 leaves them undefined after a draw), and so is the material color
    /// material tracks: it follows the current color.
    ///
    /// GL_INVALID_OPERATION when `sources` misses bytes of an enabled array;
    /// GL_INVALID_VALUE when sequential indices would run past `usize::MAX`;
    /// GL_OUT_OF_MEMORY when the vertices do not fit in memory.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ArraySources, gl::*, state::arrays::ArrayKind, Context};
    /// let mut ctx = Context::new();
    /// let positions = [0.0f32, 0.0, 1.0, 0.0, 0.0, 1.0];
    /// ctx.vertex_pointer(2, GL_FLOAT, 0, positions.as_ptr() as usize)?;
    /// ctx.client_state(GL_VERTEX_ARRAY, true)?;
    /// // The C layer finds the bytes through the pointers; from Rust, hand them over.
    /// let bytes: Vec<u8> = positions.iter().flat_map(|p| p.to_ne_bytes()).collect();
    /// let sources = ArraySources::new(0).with(ArrayKind::Vertex, &bytes);
    /// let indices = ctx.check_draw_arrays(GL_TRIANGLES, 0, 3)?;
    /// ctx.capture_begin()?;
    /// ctx.draw_arrays_from(GL_TRIANGLES, &sources, &indices)?;
    /// ctx.capture_end()?;
    /// assert_eq!(ctx.captured().primitives().len(), 1);
    /// assert_eq!(ctx.captured().vertices()[1].eye.x, 1.0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn draw_arrays_from(
        &mut self,
        mode: GLenum,
        sources: &ArraySources,
        indices: &ElementIndices,
    ) -> GlResult {
        self.draw_arrays_over(mode, sources, indices, || indices.range())
    }

    /// `draw_arrays_from` with the indices' range from `range`, called only when the draw
    /// reads the arrays: the C layer has it already from `array_spans` (a scan of every index).
    pub(crate) fn draw_arrays_over(
        &mut self,
        mode: GLenum,
        sources: &ArraySources,
        indices: &ElementIndices,
        range: impl FnOnce() -> Option<(usize, usize)>,
    ) -> GlResult {
        check_draw(self, mode, indices)?;
        let arrays = self.arrays;
        if !arrays.get(ArrayKind::Vertex).enabled {
            return Ok(());
        }
        let stores = self.array_stores(&arrays)?;
        if !self.vertices_observed() {
            return Ok(());
        }
        let Some((first, last)) = range() else {
            return Ok(());
        };
        let sources = with_stores(&arrays, sources, &stores);
        let reader = ArrayReader::new(&arrays, &sources, first, last)?;
        let fetch = ArrayFetch::new(reader.base, reader.arrays);
        self.draw_arrays_with(mode, &fetch, indices);
        if self.capture.is_active() {
            reader.capture_units(self, indices);
        }
        Ok(())
    }

    /// A draw compiled into a display list (§5.4): `draw_arrays_from`'s checks, then a copy
    /// of the elements the draw uses, so that the list keeps them whatever later happens to
    /// the arrays.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::arrays::ArraySources, commands::list::Command, gl::*};
    /// use fflight::{state::arrays::ArrayKind, Context};
    /// let mut ctx = Context::new();
    /// let positions = [0.0f32, 0.0, 1.0, 0.0];
    /// ctx.vertex_pointer(2, GL_FLOAT, 0, positions.as_ptr() as usize)?;
    /// ctx.client_state(GL_VERTEX_ARRAY, true)?;
    /// let bytes: Vec<u8> = positions.iter().flat_map(|p| p.to_ne_bytes()).collect();
    /// let sources = ArraySources::new(0).with(ArrayKind::Vertex, &bytes);
    /// let indices = ctx.check_draw_arrays(GL_LINES, 0, 2)?;
    /// let recorded = ctx.record_draw(GL_LINES, &sources, &indices)?;
    /// // The copy draws the line whatever happens to `positions` later.
    /// ctx.capture_begin()?;
    /// Command::Draw(Box::new(recorded)).execute(&mut ctx)?;
    /// ctx.capture_end()?;
    /// assert_eq!(ctx.captured().primitives()[0].kind, GL_LINES);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn record_draw(
        &self,
        mode: GLenum,
        sources: &ArraySources,
        indices: &ElementIndices,
    ) -> GlResult<RecordedDraw> {
        check_draw(self, mode, indices)?;
        let arrays = self.arrays;
        let mut draw = RecordedDraw {
            mode,
            base: 0,
            arrays: Default::default(),
            units: Default::default(),
            indices: match *indices {
                ElementIndices::Sequential { first, count } => {
                    RecordedIndices::Sequential { first, count }
                }
                ElementIndices::Listed { index_type, bytes } => RecordedIndices::Listed {
                    index_type,
                    bytes: try_copy(bytes)?,
                },
            },
        };
        let (true, Some((first, last))) = (arrays.get(ArrayKind::Vertex).enabled, indices.range())
        else {
            return Ok(draw); // draws nothing
        };
        let stores = self.array_stores(&arrays)?;
        let sources = with_stores(&arrays, sources, &stores);
        let reader = ArrayReader::new(&arrays, &sources, first, last)?;
        draw.base = reader.base;
        // Sizes the application decides: a copy too large to allocate is GL_OUT_OF_MEMORY.
        let copy = |array: Option<(&ClientArray, &[u8])>| -> GlResult<_> {
            array
                .map(|(array, bytes)| {
                    let len = array.span_len(reader.base, last).unwrap_or(0);
                    Ok((*array, try_copy(&bytes[..len])?))
                })
                .transpose()
        };
        for (recorded, array) in draw.arrays.iter_mut().zip(reader.arrays) {
            *recorded = copy(array)?;
        }
        for (recorded, array) in draw.units.iter_mut().zip(reader.units) {
            *recorded = copy(array)?;
        }
        Ok(draw)
    }

    /// Executes a draw compiled into a list: the vertices an immediate draw of the same
    /// elements makes, through the same path.
    pub(crate) fn draw_recorded(&mut self, draw: &RecordedDraw) -> GlResult {
        let indices = draw.indices.borrow();
        check_draw(self, draw.mode, &indices)?;
        // No copied vertex array: the vertex array was disabled, nothing is drawn.
        if draw.arrays[ArrayKind::Vertex as usize].is_none()
            || !self.vertices_observed()
            || indices.is_empty()
        {
            return Ok(());
        }
        fn borrow(copy: &Option<(ClientArray, Vec<u8>)>) -> Option<(&ClientArray, &[u8])> {
            copy.as_ref().map(|(array, bytes)| (array, &bytes[..]))
        }
        let reader = ArrayReader {
            arrays: std::array::from_fn(|k| borrow(&draw.arrays[k])),
            units: std::array::from_fn(|k| borrow(&draw.units[k])),
            base: draw.base,
        };
        let fetch = ArrayFetch::new(draw.base, reader.arrays);
        self.draw_arrays_with(draw.mode, &fetch, &indices);
        if self.capture.is_active() {
            reader.capture_units(self, &indices);
        }
        Ok(())
    }

    /// The vertices of `indices`: runs of consecutive elements fetched a few blocks at a
    /// time (split among the threads when the draw is large), processed by the batch engine
    /// and streamed into primitive assembly; listed indices through the post-transform cache.
    fn draw_arrays_with(&mut self, mode: GLenum, fetch: &ArrayFetch, indices: &ElementIndices) {
        let ElementIndices::Sequential { first, count } = *indices else {
            return self.draw_elements_with(mode, fetch, indices);
        };
        let derived = self.shared_derived();
        let input = InputBlock::with_attribs(&self.current);
        let mut stream = self.begin_stream(mode);
        let threads = threads_for(count);
        let range = (first, count);
        if self.draw_points_in_chunks(&stream, &derived, fetch, &input, range, threads) {
            return self.end_stream(stream);
        }
        if threads > 1 {
            let fill = |block: usize, input: &mut InputBlock| {
                let done = block * LANES;
                fetch.fill_run(input, first + done, LANES.min(count - done));
            };
            let blocks = count.div_ceil(LANES);
            let reads = stream.reads();
            light_in_order(&derived, reads, &input, blocks, threads - 1, fill, |lit| {
                self.stream_lit_block(&mut stream, lit)
            });
            return self.end_stream(stream);
        }
        // A few blocks at a time, so that the widest kernel serves them. Counted from
        // `first`: the last index may be usize::MAX.
        let mut inputs = [input; STREAMED_BLOCKS];
        for done in (0..count).step_by(STREAMED_BLOCKS * LANES) {
            let blocks = (count - done).div_ceil(LANES).min(STREAMED_BLOCKS);
            fetch.fill_runs(&mut inputs[..blocks], first + done, count - done);
            self.stream_blocks(&mut stream, &derived, &inputs[..blocks]);
        }
        self.end_stream(stream);
    }

    /// Indexed draws: through the post-transform cache, so each vertex the primitives share
    /// is lit once while it stays cached.
    fn draw_elements_with(&mut self, mode: GLenum, fetch: &ArrayFetch, indices: &ElementIndices) {
        let derived = self.shared_derived();
        if let Some(draw) = self.mesh_draw(mode, &derived, fetch) {
            let mut cache = std::mem::take(&mut self.vertex_cache.mesh);
            self.draw_mesh(&mut cache, &draw, indices);
            self.vertex_cache.mesh = cache;
            return;
        }
        let mut input = InputBlock::with_attribs(&self.current);
        let mut stream = self.begin_stream(mode);
        let mut cache = std::mem::take(&mut self.vertex_cache);
        cache.start_draw(stream.reads());
        indices.for_each(|index| {
            cache.push(index, (&derived, fetch, &mut input), |v| {
                self.stream_vertex(&mut stream, v)
            });
        });
        cache.flush(&derived, fetch, &mut input, |v| {
            self.stream_vertex(&mut stream, v)
        });
        self.vertex_cache = cache;
        self.end_stream(stream);
    }
}
