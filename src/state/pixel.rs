//! Pixel storage modes, pixel transfer, pixel maps, zoom and the read buffer (§3.6, §4.3,
//! tables 6.21-6.25): stored, validated and queried. fflight draws no pixels; the one image it
//! does unpack and pack is the polygon stipple, a 32 x 32 bitmap (§3.5.2).

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// GL_MAX_PIXEL_MAP_TABLE (Mesa's value; the minimum is 32).
pub const MAX_PIXEL_MAP_TABLE: usize = 256;

/// One direction's storage modes (table 3.1 for unpacking, 4.5 for packing).
#[derive(Clone, Debug, PartialEq)]
pub struct PixelStoreModes {
    /// GL_*_SWAP_BYTES.
    pub swap_bytes: bool,
    /// GL_*_LSB_FIRST.
    pub lsb_first: bool,
    /// GL_*_ROW_LENGTH.
    pub row_length: GLint,
    /// GL_*_IMAGE_HEIGHT.
    pub image_height: GLint,
    /// GL_*_SKIP_ROWS.
    pub skip_rows: GLint,
    /// GL_*_SKIP_PIXELS.
    pub skip_pixels: GLint,
    /// GL_*_SKIP_IMAGES.
    pub skip_images: GLint,
    /// GL_*_ALIGNMENT.
    pub alignment: GLint,
}

impl Default for PixelStoreModes {
    fn default() -> PixelStoreModes {
        PixelStoreModes {
            swap_bytes: false,
            lsb_first: false,
            row_length: 0,
            image_height: 0,
            skip_rows: 0,
            skip_pixels: 0,
            skip_images: 0,
            alignment: 4,
        }
    }
}

/// A glPixelStore parameter as given: glPixelStorei's integer or glPixelStoref's float.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StoreParam {
    /// glPixelStorei's.
    Int(GLint),
    /// glPixelStoref's.
    Float(GLfloat),
}

impl StoreParam {
    /// A boolean mode: false exactly for zero (§3.6.1).
    fn boolean(self) -> bool {
        match self {
            StoreParam::Int(i) => i != 0,
            StoreParam::Float(f) => f != 0.0,
        }
    }

    /// An integer mode: a float is rounded to the nearest integer (§3.6.1).
    fn integer(self) -> GLint {
        match self {
            StoreParam::Int(i) => i,
            StoreParam::Float(f) => crate::state::convert::float_to_int(f),
        }
    }
}

/// The storage modes: client state (GL_CLIENT_PIXEL_STORE_BIT).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PixelStoreAttribs {
    /// The GL_PACK_* modes (glReadPixels, glGetTexImage, ...).
    pub pack: PixelStoreModes,
    /// The GL_UNPACK_* modes (glTexImage, glDrawPixels, ...).
    pub unpack: PixelStoreModes,
}

impl PixelStoreAttribs {
    /// glPixelStore (§3.6.1): GL_INVALID_ENUM for a pname that is none, GL_INVALID_VALUE for a
    /// negative length or skip, or an alignment other than 1, 2, 4 or 8.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::pixel::{PixelStoreAttribs, StoreParam}, GlError};
    /// let mut store = PixelStoreAttribs::default();
    /// store.set(GL_UNPACK_SWAP_BYTES, StoreParam::Int(1))?;
    /// assert!(store.unpack.swap_bytes);
    /// assert_eq!(store.set(GL_PACK_SKIP_ROWS, StoreParam::Int(-1)), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(&mut self, pname: GLenum, param: StoreParam) -> GlResult {
        let (packing, mode) = mode_of(pname).ok_or(GlError::InvalidEnum)?;
        let modes = if packing {
            &mut self.pack
        } else {
            &mut self.unpack
        };
        let value = param.integer();
        match mode {
            Mode::SwapBytes => modes.swap_bytes = param.boolean(),
            Mode::LsbFirst => modes.lsb_first = param.boolean(),
            Mode::Alignment if !matches!(value, 1 | 2 | 4 | 8) => {
                return Err(GlError::InvalidValue);
            }
            Mode::Alignment => modes.alignment = value,
            _ if value < 0 => return Err(GlError::InvalidValue),
            Mode::RowLength => modes.row_length = value,
            Mode::ImageHeight => modes.image_height = value,
            Mode::SkipRows => modes.skip_rows = value,
            Mode::SkipPixels => modes.skip_pixels = value,
            Mode::SkipImages => modes.skip_images = value,
        }
        Ok(())
    }

    /// The value of a storage mode for glGet, with whether it is a boolean, or None if
    /// `pname` is none.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::pixel::PixelStoreAttribs};
    /// let store = PixelStoreAttribs::default();
    /// assert_eq!(store.get(GL_PACK_ALIGNMENT), Some((4, false)));
    /// assert_eq!(store.get(GL_UNPACK_LSB_FIRST), Some((0, true))); // a boolean
    /// ```
    pub fn get(&self, pname: GLenum) -> Option<(GLint, bool)> {
        let (packing, mode) = mode_of(pname)?;
        let modes = if packing { &self.pack } else { &self.unpack };
        Some(match mode {
            Mode::SwapBytes => (modes.swap_bytes as GLint, true),
            Mode::LsbFirst => (modes.lsb_first as GLint, true),
            Mode::RowLength => (modes.row_length, false),
            Mode::ImageHeight => (modes.image_height, false),
            Mode::SkipRows => (modes.skip_rows, false),
            Mode::SkipPixels => (modes.skip_pixels, false),
            Mode::SkipImages => (modes.skip_images, false),
            Mode::Alignment => (modes.alignment, false),
        })
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Mode {
    SwapBytes,
    LsbFirst,
    RowLength,
    ImageHeight,
    SkipRows,
    SkipPixels,
    SkipImages,
    Alignment,
}

/// The mode a pname names, and whether it is a packing one.
fn mode_of(pname: GLenum) -> Option<(bool, Mode)> {
    Some(match pname {
        GL_PACK_SWAP_BYTES => (true, Mode::SwapBytes),
        GL_PACK_LSB_FIRST => (true, Mode::LsbFirst),
        GL_PACK_ROW_LENGTH => (true, Mode::RowLength),
        GL_PACK_IMAGE_HEIGHT => (true, Mode::ImageHeight),
        GL_PACK_SKIP_ROWS => (true, Mode::SkipRows),
        GL_PACK_SKIP_PIXELS => (true, Mode::SkipPixels),
        GL_PACK_SKIP_IMAGES => (true, Mode::SkipImages),
        GL_PACK_ALIGNMENT => (true, Mode::Alignment),
        GL_UNPACK_SWAP_BYTES => (false, Mode::SwapBytes),
        GL_UNPACK_LSB_FIRST => (false, Mode::LsbFirst),
        GL_UNPACK_ROW_LENGTH => (false, Mode::RowLength),
        GL_UNPACK_IMAGE_HEIGHT => (false, Mode::ImageHeight),
        GL_UNPACK_SKIP_ROWS => (false, Mode::SkipRows),
        GL_UNPACK_SKIP_PIXELS => (false, Mode::SkipPixels),
        GL_UNPACK_SKIP_IMAGES => (false, Mode::SkipImages),
        GL_UNPACK_ALIGNMENT => (false, Mode::Alignment),
        _ => return None,
    })
}

/// Where the bits of a `width` x `height` bitmap lie in memory under `modes` (§3.6.4, the
/// BITMAP type; §4.3.2 for packing): each row starts at a multiple of the alignment, after
/// SKIP_ROWS rows and SKIP_PIXELS bits.
#[derive(Clone, Copy, Debug)]
struct BitmapLayout {
    row_bytes: usize,
    first_bit: usize,
    lsb_first: bool,
    width: usize,
    height: usize,
}

impl BitmapLayout {
    fn new(modes: &PixelStoreModes, width: usize, height: usize) -> BitmapLayout {
        let row_length = if modes.row_length > 0 {
            modes.row_length as usize
        } else {
            width
        };
        let alignment = modes.alignment.max(1) as usize;
        let skip_rows = modes.skip_rows.max(0) as usize;
        let row_bytes = row_length.div_ceil(8 * alignment) * alignment;
        BitmapLayout {
            row_bytes,
            first_bit: skip_rows * row_bytes * 8 + modes.skip_pixels.max(0) as usize,
            lsb_first: modes.lsb_first,
            width,
            height,
        }
    }

    /// The bytes from the start of the memory to the last bit of the image.
    fn span(&self) -> usize {
        let last_row = self.first_bit + (self.height - 1) * self.row_bytes * 8;
        (last_row + self.width).div_ceil(8)
    }

    /// The byte and the bit mask of pixel (x, y).
    fn bit(&self, x: usize, y: usize) -> (usize, u8) {
        let bit = self.first_bit + y * self.row_bytes * 8 + x;
        let shift = if self.lsb_first { bit % 8 } else { 7 - bit % 8 };
        (bit / 8, 1 << shift)
    }
}

/// The bytes glPolygonStipple reads under the unpack modes.
///
/// # Examples
///
/// ```
/// use fflight::state::pixel::{stipple_unpack_span, PixelStoreModes};
/// let modes = PixelStoreModes { alignment: 8, ..PixelStoreModes::default() };
/// assert_eq!(stipple_unpack_span(&modes), 31 * 8 + 4);
/// ```
pub fn stipple_unpack_span(unpack: &PixelStoreModes) -> usize {
    BitmapLayout::new(unpack, 32, 32).span()
}

/// The bytes glGetPolygonStipple writes into under the pack modes.
///
/// # Examples
///
/// ```
/// use fflight::state::pixel::{stipple_pack_span, PixelStoreModes};
/// assert_eq!(stipple_pack_span(&PixelStoreModes::default()), 128);
/// ```
pub fn stipple_pack_span(pack: &PixelStoreModes) -> usize {
    BitmapLayout::new(pack, 32, 32).span()
}

/// The 32 rows of a stipple unpacked from `bytes` (at least `stipple_unpack_span` of them).
///
/// # Examples
///
/// ```
/// use fflight::state::pixel::{unpack_stipple, PixelStoreModes};
/// let mut bytes = [0u8; 128];
/// bytes[0] = 0x80; // the first pixel of the first row
/// let rows = unpack_stipple(&PixelStoreModes::default(), &bytes)?;
/// assert_eq!(rows[0], 0x8000_0000);
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn unpack_stipple(unpack: &PixelStoreModes, bytes: &[u8]) -> GlResult<[u32; 32]> {
    let layout = BitmapLayout::new(unpack, 32, 32);
    if bytes.len() < layout.span() {
        return Err(GlError::InvalidValue);
    }
    Ok(std::array::from_fn(|y| {
        (0..32).fold(0u32, |row, x| {
            let (byte, mask) = layout.bit(x, y);
            row | (((bytes[byte] & mask != 0) as u32) << (31 - x))
        })
    }))
}

/// Packs the stipple's rows into `bytes` (at least `stipple_pack_span` of them), leaving the
/// bits that are not the image's as they were.
///
/// # Examples
///
/// ```
/// use fflight::state::pixel::{pack_stipple, PixelStoreModes};
/// let mut rows = [0u32; 32];
/// rows[31] = 1; // the last pixel of the last row
/// let mut bytes = [0u8; 128];
/// pack_stipple(&PixelStoreModes::default(), &rows, &mut bytes)?;
/// assert_eq!(bytes[127], 1);
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn pack_stipple(pack: &PixelStoreModes, rows: &[u32; 32], bytes: &mut [u8]) -> GlResult {
    let layout = BitmapLayout::new(pack, 32, 32);
    if bytes.len() < layout.span() {
        return Err(GlError::InvalidValue);
    }
    for (y, row) in rows.iter().enumerate() {
        for x in 0..32 {
            let (byte, mask) = layout.bit(x, y);
            if row & (1 << (31 - x)) != 0 {
                bytes[byte] |= mask;
            } else {
                bytes[byte] &= !mask;
            }
        }
    }
    Ok(())
}

/// The pixel attribute group (GL_PIXEL_MODE_BIT): transfer modes (§3.6.3), zoom (§3.6.4) and
/// the read buffer (§4.3.2).
#[derive(Clone, Debug, PartialEq)]
pub struct PixelModeAttribs {
    /// GL_MAP_COLOR.
    pub map_color: bool,
    /// GL_MAP_STENCIL.
    pub map_stencil: bool,
    /// GL_INDEX_SHIFT.
    pub index_shift: GLint,
    /// GL_INDEX_OFFSET.
    pub index_offset: GLint,
    /// Red, green, blue, alpha, depth.
    pub scale: [f32; 5],
    /// Red, green, blue, alpha, depth.
    pub bias: [f32; 5],
    /// x, y.
    pub zoom: [f32; 2],
    /// GL_READ_BUFFER.
    pub read_buffer: GLenum,
    /// The imaging subset's post-convolution and post-color-matrix scales (red to alpha)
    /// then biases: kept and queried (no pixel rectangle goes through them).
    pub post_convolution: [f32; 8],
    /// The same for the color matrix.
    pub post_color_matrix: [f32; 8],
}

impl Default for PixelModeAttribs {
    fn default() -> PixelModeAttribs {
        PixelModeAttribs {
            map_color: false,
            map_stencil: false,
            index_shift: 0,
            index_offset: 0,
            scale: [1.0; 5],
            bias: [0.0; 5],
            zoom: [1.0, 1.0],
            // Single-buffered, as the draw buffer.
            read_buffer: GL_FRONT,
            post_convolution: [1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0],
            post_color_matrix: [1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0],
        }
    }
}

/// The transfer pnames that are scales or biases: their index in `scale` / `bias`.
fn scale_or_bias(pname: GLenum) -> Option<(usize, bool)> {
    Some(match pname {
        GL_RED_SCALE => (0, true),
        GL_GREEN_SCALE => (1, true),
        GL_BLUE_SCALE => (2, true),
        GL_ALPHA_SCALE => (3, true),
        GL_DEPTH_SCALE => (4, true),
        GL_RED_BIAS => (0, false),
        GL_GREEN_BIAS => (1, false),
        GL_BLUE_BIAS => (2, false),
        GL_ALPHA_BIAS => (3, false),
        GL_DEPTH_BIAS => (4, false),
        _ => return None,
    })
}

impl PixelModeAttribs {
    /// The imaging subset's post-convolution or post-color-matrix scale or bias `pname`.
    fn post_transfer_mut(&mut self, pname: GLenum) -> Option<&mut f32> {
        match pname {
            GL_POST_CONVOLUTION_RED_SCALE..=GL_POST_CONVOLUTION_ALPHA_BIAS => {
                Some(&mut self.post_convolution[(pname - GL_POST_CONVOLUTION_RED_SCALE) as usize])
            }
            GL_POST_COLOR_MATRIX_RED_SCALE..=GL_POST_COLOR_MATRIX_ALPHA_BIAS => {
                Some(&mut self.post_color_matrix[(pname - GL_POST_COLOR_MATRIX_RED_SCALE) as usize])
            }
            _ => None,
        }
    }

    /// glPixelTransfer (§3.6.3), with the parameter as a float (glPixelTransferi's converts
    /// exactly enough); integer modes are rounded.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::pixel::{PixelModeAttribs, TransferValue}};
    /// let mut mode = PixelModeAttribs::default();
    /// mode.set_transfer(GL_INDEX_SHIFT, 2.6)?; // rounded
    /// assert_eq!(mode.transfer(GL_INDEX_SHIFT), Some(TransferValue::Int(3)));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set_transfer(&mut self, pname: GLenum, param: f32) -> GlResult {
        if let Some(value) = self.post_transfer_mut(pname) {
            *value = param;
            return Ok(());
        }
        match pname {
            GL_MAP_COLOR => self.map_color = param != 0.0,
            GL_MAP_STENCIL => self.map_stencil = param != 0.0,
            GL_INDEX_SHIFT => self.index_shift = crate::state::convert::float_to_int(param),
            GL_INDEX_OFFSET => self.index_offset = crate::state::convert::float_to_int(param),
            _ => {
                let (index, is_scale) = scale_or_bias(pname).ok_or(GlError::InvalidEnum)?;
                if is_scale {
                    self.scale[index] = param;
                } else {
                    self.bias[index] = param;
                }
            }
        }
        Ok(())
    }

    /// A transfer mode's value (a float, or an integer with whether it is a boolean), or None.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::pixel::{PixelModeAttribs, TransferValue}};
    /// let mode = PixelModeAttribs::default();
    /// assert_eq!(mode.transfer(GL_MAP_COLOR), Some(TransferValue::Bool(false)));
    /// assert_eq!(mode.transfer(GL_ALPHA_SCALE), Some(TransferValue::Float(1.0)));
    /// assert_eq!(mode.transfer(GL_FOG), None);
    /// ```
    pub fn transfer(&self, pname: GLenum) -> Option<TransferValue> {
        if let Some(value) = self.clone().post_transfer_mut(pname) {
            return Some(TransferValue::Float(*value));
        }
        Some(match pname {
            GL_MAP_COLOR => TransferValue::Bool(self.map_color),
            GL_MAP_STENCIL => TransferValue::Bool(self.map_stencil),
            GL_INDEX_SHIFT => TransferValue::Int(self.index_shift),
            GL_INDEX_OFFSET => TransferValue::Int(self.index_offset),
            _ => {
                let (index, is_scale) = scale_or_bias(pname)?;
                TransferValue::Float(if is_scale {
                    self.scale[index]
                } else {
                    self.bias[index]
                })
            }
        })
    }
}

/// A pixel transfer mode's value, in its own type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TransferValue {
    /// A boolean mode.
    Bool(bool),
    /// An integer mode.
    Int(GLint),
    /// A float mode.
    Float(f32),
}

/// The ten pixel maps in the order of their enums (GL_PIXEL_MAP_I_TO_I ...
/// GL_PIXEL_MAP_A_TO_A); their sizes are GL_PIXEL_MAP_x_SIZE, in the same order.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelMaps {
    /// Each map's entries.
    pub maps: [Vec<f32>; 10],
}

impl Default for PixelMaps {
    /// Each map has one entry, 0 (table 6.25).
    fn default() -> PixelMaps {
        PixelMaps {
            maps: std::array::from_fn(|_| vec![0.0]),
        }
    }
}

/// The index of a pixel map, or None if `map` names none.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::pixel::pixel_map_index};
/// assert_eq!(pixel_map_index(GL_PIXEL_MAP_A_TO_A), Some(9));
/// ```
pub fn pixel_map_index(map: GLenum) -> Option<usize> {
    (GL_PIXEL_MAP_I_TO_I..=GL_PIXEL_MAP_A_TO_A)
        .contains(&map)
        .then(|| (map - GL_PIXEL_MAP_I_TO_I) as usize)
}

/// Whether a map holds indices (I_TO_I, S_TO_S) rather than color components.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::pixel::is_index_map};
/// assert!(is_index_map(GL_PIXEL_MAP_S_TO_S) && !is_index_map(GL_PIXEL_MAP_I_TO_R));
/// ```
pub fn is_index_map(map: GLenum) -> bool {
    matches!(map, GL_PIXEL_MAP_I_TO_I | GL_PIXEL_MAP_S_TO_S)
}

/// How many values glPixelMap reads: `mapsize` when it is a size GL accepts, else none (the
/// command reports the error without reading).
///
/// # Examples
///
/// ```
/// use fflight::state::pixel::pixel_map_read_count;
/// assert_eq!((pixel_map_read_count(16), pixel_map_read_count(-1)), (16, 0));
/// ```
pub fn pixel_map_read_count(mapsize: GLsizei) -> usize {
    if (1..=MAX_PIXEL_MAP_TABLE as GLsizei).contains(&mapsize) {
        mapsize as usize
    } else {
        0
    }
}

impl PixelMaps {
    /// glPixelMap (§3.6.3), values already converted to floats. Mesa's order: the size, then
    /// the power of two of the maps indexed by an index, then the map name. Color values are
    /// clamped to [0, 1].
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::pixel::PixelMaps};
    /// let mut maps = PixelMaps::default();
    /// maps.set(GL_PIXEL_MAP_I_TO_B, 2, &[2.0, -1.0])?; // color values clamped
    /// assert_eq!(maps.get(GL_PIXEL_MAP_I_TO_B)?, [1.0, 0.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(&mut self, map: GLenum, mapsize: GLsizei, values: &[f32]) -> GlResult {
        if !(1..=MAX_PIXEL_MAP_TABLE as GLsizei).contains(&mapsize) {
            return Err(GlError::InvalidValue);
        }
        let indexed_by_index = (GL_PIXEL_MAP_I_TO_I..=GL_PIXEL_MAP_I_TO_A).contains(&map);
        if indexed_by_index && !(mapsize as u32).is_power_of_two() {
            return Err(GlError::InvalidValue);
        }
        let index = pixel_map_index(map).ok_or(GlError::InvalidEnum)?;
        let values = values
            .get(..mapsize as usize)
            .ok_or(GlError::InvalidValue)?;
        self.maps[index] = if is_index_map(map) {
            values.to_vec()
        } else {
            values.iter().map(|v| v.clamp(0.0, 1.0)).collect()
        };
        Ok(())
    }

    /// glGetPixelMap: the map's values.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::pixel::PixelMaps, GlError};
    /// let maps = PixelMaps::default();
    /// assert_eq!(maps.get(GL_PIXEL_MAP_R_TO_R)?, [0.0]);
    /// assert_eq!(maps.get(GL_FOG).err(), Some(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get(&self, map: GLenum) -> GlResult<&[f32]> {
        let index = pixel_map_index(map).ok_or(GlError::InvalidEnum)?;
        Ok(&self.maps[index])
    }
}
