//! Pixel storage, transfer, maps and zoom (§3.6): stored for queries and for the one image
//! fflight unpacks, the polygon stipple. Every command is GL_INVALID_OPERATION between glBegin
//! and glEnd (§2.6.3) and changes nothing on an error.

use super::query::{StateValue, floats, int};
use crate::commands::raster_pos::pixel_rectangle_format;
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::pixel::{
    MAX_PIXEL_MAP_TABLE, PixelStoreModes, StoreParam, TransferValue, is_index_map, pixel_map_index,
};
use crate::state::texture_image::{Layout, PixelFormat, pack, pixel_type, transfer, write_element};

impl Context {
    /// glPixelStorei / glPixelStoref (§3.6.1, §4.3.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::pixel::StoreParam, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.pixel_store(GL_UNPACK_ALIGNMENT, StoreParam::Int(1))?;
    /// ctx.pixel_store(GL_PACK_ROW_LENGTH, StoreParam::Float(7.6))?; // rounded
    /// assert_eq!(ctx.get(GL_PACK_ROW_LENGTH)?.as_ints(), [8]);
    /// assert_eq!(ctx.pixel_store(GL_UNPACK_ALIGNMENT, StoreParam::Int(3)), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn pixel_store(&mut self, pname: GLenum, param: StoreParam) -> GlResult {
        self.outside_begin_end()?;
        self.pixel_store.set(pname, param)
    }

    /// glPixelTransferf / glPixelTransferi (§3.6.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.pixel_transfer(GL_RED_SCALE, 2.0)?;
    /// assert_eq!(ctx.get(GL_RED_SCALE)?.as_floats(), [2.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn pixel_transfer(&mut self, pname: GLenum, param: f32) -> GlResult {
        self.outside_begin_end()?;
        self.pixel_mode.set_transfer(pname, param)
    }

    /// glPixelZoom (§3.6.4).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.pixel_zoom(2.0, -1.0)?;
    /// assert_eq!(ctx.get(GL_ZOOM_Y)?.as_floats(), [-1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn pixel_zoom(&mut self, x: f32, y: f32) -> GlResult {
        self.outside_begin_end()?;
        self.pixel_mode.zoom = [x, y];
        Ok(())
    }

    /// glPixelMapfv (§3.6.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.pixel_map(GL_PIXEL_MAP_R_TO_R, 2, &[1.0, 0.0])?;
    /// assert_eq!(ctx.get_pixel_map(GL_PIXEL_MAP_R_TO_R)?, [1.0, 0.0]);
    /// // Maps from indices have a power-of-two size.
    /// assert_eq!(ctx.pixel_map(GL_PIXEL_MAP_I_TO_R, 3, &[0.0; 3]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn pixel_map(&mut self, map: GLenum, mapsize: GLsizei, values: &[f32]) -> GlResult {
        self.outside_begin_end()?;
        self.pixel_maps.set(map, mapsize, values)
    }

    /// glPixelMapuiv / glPixelMapusv: color values are mapped from [0, max] to [0, 1] (`max`
    /// is the type's largest value), index values converted directly.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.pixel_map_integers(GL_PIXEL_MAP_G_TO_G, 2, &[0u16, 65535], 65535.0)?; // glPixelMapusv
    /// assert_eq!(ctx.get_pixel_map(GL_PIXEL_MAP_G_TO_G)?, [0.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn pixel_map_integers<T: Copy + Into<f64>>(
        &mut self,
        map: GLenum,
        mapsize: GLsizei,
        values: &[T],
        max: f64,
    ) -> GlResult {
        let index_map = is_index_map(map);
        let floats: Vec<f32> = values
            .iter()
            .map(|&v| {
                let v: f64 = v.into();
                (if index_map { v } else { v / max }) as f32
            })
            .collect();
        self.pixel_map(map, mapsize, &floats)
    }

    /// glGetPixelMapfv (§6.1.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_pixel_map(GL_PIXEL_MAP_I_TO_I)?, [0.0]); // one entry initially
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_pixel_map(&self, map: GLenum) -> GlResult<Vec<f32>> {
        self.outside_begin_end()?;
        Ok(self.pixel_maps.get(map)?.to_vec())
    }

    /// glGetPixelMapusv: color values mapped from [0, 1] to [0, 65535] and rounded, index
    /// values rounded; both clamped to the type.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.pixel_map(GL_PIXEL_MAP_A_TO_A, 1, &[0.5])?;
    /// assert_eq!(ctx.get_pixel_map_ushort(GL_PIXEL_MAP_A_TO_A)?, [32768]); // 0.5 * 65535, rounded
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_pixel_map_ushort(&self, map: GLenum) -> GlResult<Vec<GLushort>> {
        let scale = if is_index_map(map) { 1.0 } else { 65535.0 };
        let values = self.get_pixel_map(map)?;
        Ok(values
            .iter()
            .map(|&v| (v as f64 * scale).round().clamp(0.0, 65535.0) as GLushort)
            .collect())
    }

    /// glGetPixelMapuiv: color values mapped from [0, 1] to [0, 2^32 - 1] and truncated (the
    /// spec leaves the rounding open; Mesa truncates here, and rounds for glGetPixelMapusv),
    /// index values rounded; both clamped to the type.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.pixel_map(GL_PIXEL_MAP_I_TO_I, 1, &[6.6])?;
    /// assert_eq!(ctx.get_pixel_map_uint(GL_PIXEL_MAP_I_TO_I)?, [7]); // index values rounded
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_pixel_map_uint(&self, map: GLenum) -> GlResult<Vec<GLuint>> {
        let index_map = is_index_map(map);
        let values = self.get_pixel_map(map)?;
        Ok(values
            .iter()
            .map(|&v| {
                let v = if index_map {
                    (v as f64).round()
                } else {
                    (v as f64 * 4_294_967_295.0).trunc()
                };
                v.clamp(0.0, 4_294_967_295.0) as GLuint
            })
            .collect())
    }

    /// The pixel values of glGet (tables 6.21-6.25), or None for a pname that is not theirs.
    pub(crate) fn get_pixel_state(&self, pname: GLenum) -> Option<StateValue> {
        if let Some((value, boolean)) = self.pixel_store.get(pname) {
            return Some(if boolean {
                StateValue::Bools(vec![value != 0])
            } else {
                int(value)
            });
        }
        if let Some(value) = self.pixel_mode.transfer(pname) {
            return Some(match value {
                TransferValue::Bool(b) => StateValue::Bools(vec![b]),
                TransferValue::Int(i) => int(i),
                TransferValue::Float(f) => floats(&[f]),
            });
        }
        let sizes = GL_PIXEL_MAP_I_TO_I_SIZE..=GL_PIXEL_MAP_A_TO_A_SIZE;
        if sizes.contains(&pname) {
            let map = pname - GL_PIXEL_MAP_I_TO_I_SIZE + GL_PIXEL_MAP_I_TO_I;
            let index = pixel_map_index(map)?;
            return Some(int(self.pixel_maps.maps[index].len() as GLint));
        }
        Some(match pname {
            GL_ZOOM_X => floats(&[self.pixel_mode.zoom[0]]),
            GL_ZOOM_Y => floats(&[self.pixel_mode.zoom[1]]),
            GL_MAX_PIXEL_MAP_TABLE => int(MAX_PIXEL_MAP_TABLE as GLint),
            _ => return None,
        })
    }
}

/// Where a width x height pixel rectangle lies in client memory under `modes` (§4.3.2 for
/// packing, §3.6.4 for unpacking): its first byte, the bytes from one row to the next and
/// the bytes of the whole span. `pixel_bytes` is None for GL_BITMAP (a bit a pixel).
struct RectangleLayout {
    start: usize,
    row_stride: usize,
    span: usize,
}

impl RectangleLayout {
    fn new(
        modes: &PixelStoreModes,
        pixel_bytes: Option<usize>,
        element: usize,
        [width, height]: [usize; 2],
    ) -> RectangleLayout {
        let row_length = if modes.row_length > 0 {
            modes.row_length as usize
        } else {
            width
        };
        let alignment = modes.alignment.max(1) as usize;
        let skip_pixels = modes.skip_pixels.max(0) as usize;
        let (row_bytes, element, skip_bytes, last_row_bytes) = match pixel_bytes {
            Some(bytes) => (
                row_length * bytes,
                element,
                skip_pixels * bytes,
                width * bytes,
            ),
            // Bits: the skipped pixels and the row's pixels round up to whole bytes.
            None => (
                row_length.div_ceil(8),
                1,
                skip_pixels / 8,
                (skip_pixels % 8 + width).div_ceil(8),
            ),
        };
        let row_stride = if element >= alignment {
            row_bytes
        } else {
            row_bytes.div_ceil(alignment) * alignment
        };
        let start = modes.skip_rows.max(0) as usize * row_stride + skip_bytes;
        let span = if width == 0 || height == 0 {
            0
        } else {
            start + (height - 1) * row_stride + last_row_bytes
        };
        RectangleLayout {
            start,
            row_stride,
            span,
        }
    }
}

impl Context {
    /// The layout glReadPixels writes, or None for arguments it rejects.
    fn read_pixels_layout(
        &self,
        [width, height]: [GLsizei; 2],
        format: GLenum,
        ty: GLenum,
    ) -> Option<RectangleLayout> {
        let pixel_bytes = pixel_rectangle_format(format, ty).ok()?;
        let element = pixel_type(ty).map_or(1, |t| t.size);
        let size = [usize::try_from(width).ok()?, usize::try_from(height).ok()?];
        Some(RectangleLayout::new(
            &self.pixel_store.pack,
            pixel_bytes,
            element,
            size,
        ))
    }

    /// How many bytes glReadPixels writes into under the current pack modes (0 for
    /// arguments it rejects).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.read_pixels_span(3, 2, GL_RGBA, GL_UNSIGNED_BYTE), 24);
    /// assert_eq!(ctx.read_pixels_span(3, 2, GL_RGBA, GL_LIGHT0), 0); // rejected
    /// ```
    pub fn read_pixels_span(
        &self,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        ty: GLenum,
    ) -> usize {
        self.read_pixels_layout([width, height], format, ty)
            .map_or(0, |layout| layout.span)
    }

    /// glReadPixels (§4.3.2): sizes, then the format and type are checked; color indices are
    /// GL_INVALID_OPERATION in RGBA mode. fflight's framebuffer holds nothing drawn: every
    /// pixel read is color (0, 0, 0, 0), depth 0 and stencil 0, which then go through pixel
    /// transfer (§3.6.5: scale, bias and maps; index shift, offset and map) and are packed
    /// with the GL_PACK_* modes into `pixels`; the bytes between them are left as they are.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// let mut pixels = [7u8; 8];
    /// ctx.read_pixels([2, 1], GL_RGBA, GL_UNSIGNED_BYTE, &mut pixels)?;
    /// assert_eq!(pixels, [0; 8]); // nothing was drawn
    /// assert_eq!(ctx.read_pixels([1, 1], GL_COLOR_INDEX, GL_UNSIGNED_BYTE, &mut pixels), Err(GlError::InvalidOperation));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn read_pixels(
        &mut self,
        [width, height]: [GLsizei; 2],
        format: GLenum,
        ty: GLenum,
        pixels: &mut [u8],
    ) -> GlResult {
        self.outside_begin_end()?;
        if width < 0 || height < 0 {
            return Err(GlError::InvalidValue);
        }
        pixel_rectangle_format(format, ty)?;
        if format == GL_COLOR_INDEX {
            return Err(GlError::InvalidOperation);
        }
        let layout = self
            .read_pixels_layout([width, height], format, ty)
            .ok_or(GlError::InvalidValue)?;
        if pixels.len() < layout.span {
            // A NULL pointer (fflight's choice: an error, nothing written).
            return Err(GlError::InvalidValue);
        }
        let size = [width as usize, height as usize, 1];
        if format == GL_STENCIL_INDEX {
            self.pack_stencil(&layout, [size[0], size[1]], ty, pixels);
            return Ok(());
        }
        let format = PixelFormat::new(format, ty)?;
        let pixel = transfer(&self.pixel_mode, &self.pixel_maps, [0.0; 4], format.depth);
        let colors = vec![pixel; size[0] * size[1]];
        let modes = &self.pixel_store.pack;
        pack(
            &colors,
            pixels,
            modes,
            &format,
            &Layout::new(modes, &format, size, false),
        )
    }

    /// The stencil index every pixel reads (0 shifted, offset and mapped, §3.6.5) packed as
    /// `ty` (GL_BITMAP: its lowest bit).
    fn pack_stencil(
        &self,
        layout: &RectangleLayout,
        [width, height]: [usize; 2],
        ty: GLenum,
        out: &mut [u8],
    ) {
        let mode = &self.pixel_mode;
        let shifted = if mode.index_shift >= 0 {
            0i64 << mode.index_shift.min(63)
        } else {
            0
        };
        let mut index = shifted + i64::from(mode.index_offset);
        if mode.map_stencil {
            let map = &self.pixel_maps.maps[1];
            index = map[(index.max(0) as usize) & (map.len() - 1)] as i64;
        }
        let modes = &self.pixel_store.pack;
        let skip = modes.skip_pixels.max(0) as usize;
        for y in 0..height {
            let row = layout.start + y * layout.row_stride;
            for x in 0..width {
                match pixel_type(ty) {
                    Some(t) => {
                        let raw = if ty == GL_FLOAT {
                            (index as f32).to_bits()
                        } else {
                            index as u32
                        };
                        write_element(out, row + x * t.size, t.size, modes.swap_bytes, raw);
                    }
                    None => {
                        let bit = skip % 8 + x;
                        let mask = if modes.lsb_first {
                            1u8 << (bit % 8)
                        } else {
                            0x80u8 >> (bit % 8)
                        };
                        let byte = &mut out[row + bit / 8];
                        if index & 1 != 0 {
                            *byte |= mask;
                        } else {
                            *byte &= !mask;
                        }
                    }
                }
            }
        }
    }
}
