//! The imaging subset's commands (§3.6.3, §6.1.7-6.1.9): color tables, convolution filters,
//! histogram and minmax. Images are unpacked with the GL_UNPACK_* modes, scaled, biased and
//! clamped (§3.6.3), kept in their internal format and packed back with the GL_PACK_*
//! modes; the copies read a framebuffer nothing was drawn into ((0, 0, 0, 0) pixels).

use super::query::{StateValue, enumeration, floats, int};
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::imaging::{
    COLOR_TABLES, Entries, MAX_CONVOLUTION_SIZE, color_table_target, convolution_target,
    internal_format_of, table_width,
};
use crate::state::texture_image::{Base, Layout, PixelFormat, pack, unpack};

/// The scale-and-bias pnames' index: 0 scale, 1 bias.
fn scale_or_bias(pname: GLenum, scale: GLenum, bias: GLenum) -> GlResult<usize> {
    match pname {
        p if p == scale => Ok(0),
        p if p == bias => Ok(1),
        _ => Err(GlError::InvalidEnum),
    }
}

/// `colors` scaled, biased and clamped to [0, 1].
fn scale_bias(colors: Vec<[f32; 4]>, scale: [f32; 4], bias: [f32; 4]) -> Vec<[f32; 4]> {
    colors
        .into_iter()
        .map(|c| std::array::from_fn(|k| (c[k] * scale[k] + bias[k]).clamp(0.0, 1.0)))
        .collect()
}

/// The component sizes the GL_*_RED_SIZE ... pnames report (`first`: the RED_SIZE pname of
/// the family; red, green, blue, alpha, luminance, intensity follow it).
fn component_size(entries: &Entries, pname: GLenum, first: GLenum) -> Option<StateValue> {
    let k = pname.checked_sub(first)? as usize;
    (k < 6).then(|| int(entries.component_size(k)))
}

impl Context {
    /// The bytes a `width` x `height` rectangle of `format` and `ty` takes under the unpack
    /// (`packing` false) or pack modes; 0 for a format or type no imaging command takes.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// // Two rows of 3 RGB pixels: the first padded to the unpack alignment of 4.
    /// assert_eq!(ctx.imaging_span(false, GL_RGB, GL_UNSIGNED_BYTE, [3, 2]), 12 + 9);
    /// assert_eq!(ctx.imaging_span(false, GL_RGB, GL_LIGHT0, [3, 2]), 0);
    /// ```
    pub fn imaging_span(&self, packing: bool, format: GLenum, ty: GLenum, size: [i32; 2]) -> usize {
        let (Ok(format), Ok(w), Ok(h)) = (
            PixelFormat::new(format, ty),
            usize::try_from(size[0]),
            usize::try_from(size[1]),
        ) else {
            return 0;
        };
        let modes = if packing {
            &self.pixel_store.pack
        } else {
            &self.pixel_store.unpack
        };
        Layout::new(modes, &format, [w, h, 1], false).span()
    }

    /// Unpacks a color image of `size` (GL_INVALID_ENUM for depth, GL_INVALID_OPERATION when
    /// `bytes` is short: a NULL pointer).
    fn unpack_colors(
        &self,
        format: GLenum,
        ty: GLenum,
        size: [usize; 2],
        bytes: &[u8],
    ) -> GlResult<Vec<[f32; 4]>> {
        let pixel_format = PixelFormat::new(format, ty)?;
        if pixel_format.depth {
            return Err(GlError::InvalidEnum);
        }
        let modes = &self.pixel_store.unpack;
        let layout = Layout::new(modes, &pixel_format, [size[0], size[1], 1], false);
        unpack(bytes, modes, &pixel_format, &layout, |c| c)
    }

    /// Packs `count` entries' RGBA colors into `out` (GL_INVALID_ENUM for a depth format).
    fn pack_colors(
        &self,
        colors: &[[f32; 4]],
        size: [usize; 2],
        format: GLenum,
        ty: GLenum,
        out: &mut [u8],
    ) -> GlResult {
        let pixel_format = PixelFormat::new(format, ty)?;
        if pixel_format.depth {
            return Err(GlError::InvalidEnum);
        }
        let modes = &self.pixel_store.pack;
        let layout = Layout::new(modes, &pixel_format, [size[0], size[1], 1], false);
        if out.len() < layout.span() {
            return Err(GlError::InvalidValue);
        }
        pack(colors, out, modes, &pixel_format, &layout)
    }

    /// glColorTable (§3.6.3): a table of `width` entries (0 or a power of two). A proxy
    /// target only checks: a table too wide leaves the proxy's state zero; the real target
    /// gives GL_TABLE_TOO_LARGE.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// let entries: Vec<u8> = (0..16).map(|i| i * 8).collect();
    /// ctx.color_table(GL_COLOR_TABLE, GL_RGBA8, 4, GL_RGBA, GL_UNSIGNED_BYTE, &entries)?;
    /// assert_eq!(ctx.get_color_table_parameter(GL_COLOR_TABLE, GL_COLOR_TABLE_WIDTH)?.as_ints(), [4]);
    /// // Widths are powers of two.
    /// assert_eq!(ctx.color_table(GL_COLOR_TABLE, GL_RGBA8, 3, GL_RGBA, GL_UNSIGNED_BYTE, &entries), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn color_table(
        &mut self,
        target: GLenum,
        internal: GLenum,
        width: i32,
        format: GLenum,
        ty: GLenum,
        bytes: &[u8],
    ) -> GlResult {
        self.outside_begin_end()?;
        let (index, proxy) = color_table_target(target)?;
        let found = internal_format_of(internal as GLint, false)?;
        let fits = table_width(width)?;
        PixelFormat::new(format, ty)?;
        let width = width as usize;
        if proxy {
            let entries = if fits {
                Entries::new(internal, found, [width, 1], &vec![[0.0; 4]; width])
            } else {
                Entries::new(GL_RGBA, (Base::Rgba, [0; 7]), [0, 0], &[])
            };
            self.imaging.proxy_tables[index].entries = entries;
            return Ok(());
        }
        if !fits {
            return Err(GlError::TableTooLarge);
        }
        let colors = self.unpack_colors(format, ty, [width, 1], bytes)?;
        let modes = &self.imaging_modes;
        let colors = scale_bias(colors, modes.table_scale[index], modes.table_bias[index]);
        self.imaging.tables[index].entries = Entries::new(internal, found, [width, 1], &colors);
        Ok(())
    }

    /// glCopyColorTable: `width` pixels of the (empty) framebuffer.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.copy_color_table(GL_POST_CONVOLUTION_COLOR_TABLE, GL_RGB8, 2)?;
    /// let mut out = [9u8; 6];
    /// ctx.get_color_table(GL_POST_CONVOLUTION_COLOR_TABLE, GL_RGB, GL_UNSIGNED_BYTE, &mut out)?;
    /// assert_eq!(out, [0; 6]); // the empty framebuffer
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn copy_color_table(&mut self, target: GLenum, internal: GLenum, width: i32) -> GlResult {
        self.outside_begin_end()?;
        let (index, proxy) = color_table_target(target)?;
        if proxy {
            return Err(GlError::InvalidEnum);
        }
        let found = internal_format_of(internal as GLint, false)?;
        if !table_width(width)? {
            return Err(GlError::TableTooLarge);
        }
        let modes = &self.imaging_modes;
        let colors = scale_bias(
            vec![[0.0; 4]; width as usize],
            modes.table_scale[index],
            modes.table_bias[index],
        );
        self.imaging.tables[index].entries =
            Entries::new(internal, found, [width as usize, 1], &colors);
        Ok(())
    }

    /// glColorSubTable / glCopyColorSubTable (`bytes` None: the empty framebuffer's pixels):
    /// entries `start` to `start + count`, GL_INVALID_VALUE past the table's end.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.copy_color_table(GL_COLOR_TABLE, GL_RGBA8, 2)?;
    /// ctx.color_sub_table(GL_COLOR_TABLE, 1, 1, Some((GL_RGBA, GL_UNSIGNED_BYTE, &[255; 4])))?;
    /// let mut out = [0u8; 8];
    /// ctx.get_color_table(GL_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE, &mut out)?;
    /// assert_eq!(out, [0, 0, 0, 0, 255, 255, 255, 255]);
    /// assert_eq!(ctx.color_sub_table(GL_COLOR_TABLE, 2, 1, None), Err(GlError::InvalidValue)); // past the end
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn color_sub_table(
        &mut self,
        target: GLenum,
        start: i32,
        count: i32,
        source: Option<(GLenum, GLenum, &[u8])>,
    ) -> GlResult {
        self.outside_begin_end()?;
        let (index, proxy) = color_table_target(target)?;
        if proxy {
            return Err(GlError::InvalidEnum);
        }
        if let Some((format, ty, _)) = source {
            PixelFormat::new(format, ty)?;
        }
        let (Ok(start), Ok(count)) = (usize::try_from(start), usize::try_from(count)) else {
            return Err(GlError::InvalidValue);
        };
        let entries = &self.imaging.tables[index].entries;
        if start + count > entries.size[0] {
            return Err(GlError::InvalidValue);
        }
        let colors = match source {
            Some((format, ty, bytes)) => self.unpack_colors(format, ty, [count, 1], bytes)?,
            None => vec![[0.0; 4]; count],
        };
        let modes = &self.imaging_modes;
        let colors = scale_bias(colors, modes.table_scale[index], modes.table_bias[index]);
        let entries = &mut self.imaging.tables[index].entries;
        let stored = Entries::new(
            entries.internal_format,
            (entries.base, entries.sizes),
            [count, 1],
            &colors,
        );
        entries.values[start..start + count].copy_from_slice(&stored.values);
        Ok(())
    }

    /// glColorTableParameter{if}v: GL_COLOR_TABLE_SCALE or _BIAS, four values.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.color_table_parameter(GL_COLOR_TABLE, GL_COLOR_TABLE_SCALE, &[2.0, 2.0, 2.0, 1.0])?;
    /// let scale = ctx.get_color_table_parameter(GL_COLOR_TABLE, GL_COLOR_TABLE_SCALE)?;
    /// assert_eq!(scale.as_floats(), [2.0, 2.0, 2.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn color_table_parameter(
        &mut self,
        target: GLenum,
        pname: GLenum,
        params: &[f32],
    ) -> GlResult {
        self.outside_begin_end()?;
        let (index, proxy) = color_table_target(target)?;
        if proxy {
            return Err(GlError::InvalidEnum);
        }
        let which = scale_or_bias(pname, GL_COLOR_TABLE_SCALE, GL_COLOR_TABLE_BIAS)?;
        let values: [f32; 4] = params.try_into().map_err(|_| GlError::InvalidValue)?;
        let modes = &mut self.imaging_modes;
        [&mut modes.table_scale, &mut modes.table_bias][which][index] = values;
        Ok(())
    }

    /// glGetColorTableParameter{if}v.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// let format = ctx.get_color_table_parameter(GL_COLOR_TABLE, GL_COLOR_TABLE_FORMAT)?;
    /// assert_eq!(format.as_ints(), [GL_RGBA as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_color_table_parameter(&self, target: GLenum, pname: GLenum) -> GlResult<StateValue> {
        self.outside_begin_end()?;
        let (index, proxy) = color_table_target(target)?;
        let table = if proxy {
            &self.imaging.proxy_tables[index]
        } else {
            &self.imaging.tables[index]
        };
        let entries = &table.entries;
        if let Some(size) = component_size(entries, pname, GL_COLOR_TABLE_RED_SIZE) {
            return Ok(size);
        }
        Ok(match pname {
            GL_COLOR_TABLE_FORMAT => enumeration(entries.internal_format),
            GL_COLOR_TABLE_WIDTH => int(entries.size[0] as i32),
            GL_COLOR_TABLE_SCALE | GL_COLOR_TABLE_BIAS if !proxy => {
                let modes = &self.imaging_modes;
                let which = scale_or_bias(pname, GL_COLOR_TABLE_SCALE, GL_COLOR_TABLE_BIAS)?;
                floats(&[modes.table_scale, modes.table_bias][which][index])
            }
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glGetColorTable: the entries packed as one row.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.color_table(GL_COLOR_TABLE, GL_LUMINANCE8, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, &[10, 20])?;
    /// let mut out = [0u8; 6];
    /// ctx.get_color_table(GL_COLOR_TABLE, GL_RGB, GL_UNSIGNED_BYTE, &mut out)?;
    /// assert_eq!(out, [10, 0, 0, 20, 0, 0]); // luminance returned as red, as table 6.1 says
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_color_table(
        &self,
        target: GLenum,
        format: GLenum,
        ty: GLenum,
        out: &mut [u8],
    ) -> GlResult {
        self.outside_begin_end()?;
        let index = COLOR_TABLES
            .iter()
            .position(|&t| t == target)
            .ok_or(GlError::InvalidEnum)?;
        let entries = &self.imaging.tables[index].entries;
        let colors: Vec<[f32; 4]> = (0..entries.values.len()).map(|i| entries.rgba(i)).collect();
        self.pack_colors(&colors, [entries.size[0], 1], format, ty, out)
    }

    /// glConvolutionFilter1D / 2D (`dimensions`), glCopyConvolutionFilter1D / 2D (`source`
    /// None) and glSeparableFilter2D (`column` Some): GL_INVALID_VALUE beyond
    /// GL_MAX_CONVOLUTION_WIDTH / _HEIGHT.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// let weights: Vec<u8> = [0.25f32, 0.5, 0.25].iter().flat_map(|w| w.to_ne_bytes()).collect();
    /// ctx.convolution_filter(GL_CONVOLUTION_1D, GL_LUMINANCE, [3, 1], Some((GL_LUMINANCE, GL_FLOAT, &weights)), None)?;
    /// assert_eq!(ctx.get_convolution_parameter(GL_CONVOLUTION_1D, GL_CONVOLUTION_WIDTH)?.as_ints(), [3]);
    /// // At most GL_MAX_CONVOLUTION_WIDTH (9).
    /// assert_eq!(ctx.convolution_filter(GL_CONVOLUTION_1D, GL_LUMINANCE, [10, 1], None, None), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn convolution_filter(
        &mut self,
        target: GLenum,
        internal: GLenum,
        size: [i32; 2],
        source: Option<(GLenum, GLenum, &[u8])>,
        column: Option<&[u8]>,
    ) -> GlResult {
        self.outside_begin_end()?;
        let index = convolution_target(target)?;
        let wanted = match (source.is_some(), column.is_some()) {
            (_, true) => 2,
            _ => index.min(1),
        };
        if index != wanted {
            return Err(GlError::InvalidEnum);
        }
        let found = internal_format_of(internal as GLint, false)?;
        let dimensions = if index == 0 { 1 } else { 2 };
        let mut extent = [1usize; 2];
        for d in 0..dimensions {
            extent[d] = usize::try_from(size[d])
                .ok()
                .filter(|&s| s <= MAX_CONVOLUTION_SIZE)
                .ok_or(GlError::InvalidValue)?;
        }
        let scale = self.imaging_modes.filter_scale[index];
        let bias = self.imaging_modes.filter_bias[index];
        let (row_size, colors, column) = match (source, column) {
            (Some((format, ty, row)), Some(column)) => (
                [extent[0], 1],
                self.unpack_colors(format, ty, [extent[0], 1], row)?,
                scale_bias(
                    self.unpack_colors(format, ty, [extent[1], 1], column)?,
                    scale,
                    bias,
                ),
            ),
            (Some((format, ty, bytes)), None) => (
                extent,
                self.unpack_colors(format, ty, extent, bytes)?,
                Vec::new(),
            ),
            (None, _) => (extent, vec![[0.0; 4]; extent[0] * extent[1]], Vec::new()),
        };
        let colors = scale_bias(colors, scale, bias);
        let filter = &mut self.imaging.filters[index];
        filter.entries = Entries::new(internal, found, row_size, &colors);
        if index == 2 {
            filter.entries.size = extent;
        }
        filter.column = column
            .iter()
            .map(|&c| crate::state::texture_image::TexImage::store(found.0, &found.1, c))
            .collect();
        Ok(())
    }

    /// glConvolutionParameter{if}\[v\]: the border mode (scalar or vector), the border color,
    /// the filter scale and bias (vector only).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.convolution_parameter(GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_MODE, &[GL_CONSTANT_BORDER as f32], false)?;
    /// let mode = ctx.get_convolution_parameter(GL_CONVOLUTION_2D, GL_CONVOLUTION_BORDER_MODE)?;
    /// assert_eq!(mode.as_ints(), [GL_CONSTANT_BORDER as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn convolution_parameter(
        &mut self,
        target: GLenum,
        pname: GLenum,
        params: &[f32],
        vector: bool,
    ) -> GlResult {
        self.outside_begin_end()?;
        let index = convolution_target(target)?;
        let modes = &mut self.imaging_modes;
        match pname {
            GL_CONVOLUTION_BORDER_MODE => {
                let mode = *params.first().ok_or(GlError::InvalidValue)? as GLenum;
                if !matches!(mode, GL_REDUCE | GL_CONSTANT_BORDER | GL_REPLICATE_BORDER) {
                    return Err(GlError::InvalidEnum);
                }
                modes.border_mode[index] = mode;
            }
            GL_CONVOLUTION_BORDER_COLOR
            | GL_CONVOLUTION_FILTER_SCALE
            | GL_CONVOLUTION_FILTER_BIAS
                if vector =>
            {
                let values: [f32; 4] = params.try_into().map_err(|_| GlError::InvalidValue)?;
                let slot = match pname {
                    GL_CONVOLUTION_BORDER_COLOR => &mut modes.border_color,
                    GL_CONVOLUTION_FILTER_SCALE => &mut modes.filter_scale,
                    _ => &mut modes.filter_bias,
                };
                slot[index] = values;
            }
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }

    /// glGetConvolutionParameter{if}v.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// let border = ctx.get_convolution_parameter(GL_SEPARABLE_2D, GL_CONVOLUTION_BORDER_MODE)?;
    /// assert_eq!(border.as_ints(), [GL_REDUCE as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_convolution_parameter(&self, target: GLenum, pname: GLenum) -> GlResult<StateValue> {
        self.outside_begin_end()?;
        let index = convolution_target(target)?;
        let modes = &self.imaging_modes;
        let entries = &self.imaging.filters[index].entries;
        Ok(match pname {
            GL_CONVOLUTION_BORDER_MODE => enumeration(modes.border_mode[index]),
            GL_CONVOLUTION_BORDER_COLOR => floats(&modes.border_color[index]),
            GL_CONVOLUTION_FILTER_SCALE => floats(&modes.filter_scale[index]),
            GL_CONVOLUTION_FILTER_BIAS => floats(&modes.filter_bias[index]),
            GL_CONVOLUTION_FORMAT => enumeration(entries.internal_format),
            GL_CONVOLUTION_WIDTH => int(entries.size[0] as i32),
            GL_CONVOLUTION_HEIGHT => int(entries.size[1] as i32),
            GL_MAX_CONVOLUTION_WIDTH | GL_MAX_CONVOLUTION_HEIGHT => {
                int(MAX_CONVOLUTION_SIZE as i32)
            }
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glGetConvolutionFilter (1D and 2D filters).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.convolution_filter(GL_CONVOLUTION_2D, GL_RGB8, [1, 1], Some((GL_RGB, GL_UNSIGNED_BYTE, &[1, 2, 3])), None)?;
    /// let mut out = [0u8; 3];
    /// ctx.get_convolution_filter(GL_CONVOLUTION_2D, GL_RGB, GL_UNSIGNED_BYTE, &mut out)?;
    /// assert_eq!(out, [1, 2, 3]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_convolution_filter(
        &self,
        target: GLenum,
        format: GLenum,
        ty: GLenum,
        out: &mut [u8],
    ) -> GlResult {
        self.outside_begin_end()?;
        let index = convolution_target(target)?;
        if index == 2 {
            return Err(GlError::InvalidEnum);
        }
        let entries = &self.imaging.filters[index].entries;
        let colors: Vec<[f32; 4]> = (0..entries.values.len()).map(|i| entries.rgba(i)).collect();
        self.pack_colors(&colors, entries.size, format, ty, out)
    }

    /// glGetSeparableFilter: the row and the column.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.convolution_filter(GL_SEPARABLE_2D, GL_LUMINANCE8, [2, 1], Some((GL_LUMINANCE, GL_UNSIGNED_BYTE, &[1, 2])), Some(&[3]))?;
    /// let (mut row, mut column) = ([0u8; 2], [0u8; 1]);
    /// ctx.get_separable_filter(GL_SEPARABLE_2D, GL_LUMINANCE, GL_UNSIGNED_BYTE, &mut row, &mut column)?;
    /// assert_eq!((row, column), ([1, 2], [3]));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_separable_filter(
        &self,
        target: GLenum,
        format: GLenum,
        ty: GLenum,
        row: &mut [u8],
        column: &mut [u8],
    ) -> GlResult {
        self.outside_begin_end()?;
        if target != GL_SEPARABLE_2D {
            return Err(GlError::InvalidEnum);
        }
        let filter = &self.imaging.filters[2];
        let entries = &filter.entries;
        let row_colors: Vec<[f32; 4]> =
            (0..entries.values.len()).map(|i| entries.rgba(i)).collect();
        let column_entries = Entries {
            values: filter.column.clone(),
            ..entries.clone()
        };
        let column_colors: Vec<[f32; 4]> = (0..filter.column.len())
            .map(|i| column_entries.rgba(i))
            .collect();
        self.pack_colors(&row_colors, [entries.size[0], 1], format, ty, row)?;
        self.pack_colors(&column_colors, [entries.size[1], 1], format, ty, column)
    }

    /// glHistogram (§3.6.3): a width of 0 or a power of two, no intensity format.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.histogram(GL_HISTOGRAM, 8, GL_RGBA, false)?;
    /// assert_eq!(ctx.get_histogram_parameter(GL_HISTOGRAM, GL_HISTOGRAM_WIDTH)?.as_ints(), [8]);
    /// assert_eq!(ctx.histogram(GL_HISTOGRAM, 8, GL_INTENSITY, false), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn histogram(
        &mut self,
        target: GLenum,
        width: i32,
        internal: GLenum,
        sink: bool,
    ) -> GlResult {
        self.outside_begin_end()?;
        let proxy = match target {
            GL_HISTOGRAM => false,
            GL_PROXY_HISTOGRAM => true,
            _ => return Err(GlError::InvalidEnum),
        };
        let fits = table_width(width)?;
        let found = internal_format_of(internal as GLint, true)?;
        let histogram = if proxy {
            &mut self.imaging.proxy_histogram
        } else if fits {
            &mut self.imaging.histogram
        } else {
            return Err(GlError::TableTooLarge);
        };
        let width = if fits { width as usize } else { 0 };
        histogram.entries = Entries::new(internal, found, [width, 1], &vec![[0.0; 4]; width]);
        histogram.sink = sink;
        Ok(())
    }

    /// glResetHistogram: every count 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.reset_histogram(GL_HISTOGRAM)?;
    /// assert_eq!(ctx.reset_histogram(GL_PROXY_HISTOGRAM), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn reset_histogram(&mut self, target: GLenum) -> GlResult {
        self.outside_begin_end()?;
        if target != GL_HISTOGRAM {
            return Err(GlError::InvalidEnum);
        }
        self.imaging.histogram.entries.values.fill([0.0; 4]);
        Ok(())
    }

    /// glGetHistogram: the counts packed as a row (then reset if asked).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.histogram(GL_HISTOGRAM, 2, GL_LUMINANCE, false)?;
    /// let mut counts = [9u8; 8];
    /// ctx.get_histogram(GL_HISTOGRAM, true, GL_LUMINANCE, GL_UNSIGNED_INT, &mut counts)?;
    /// assert_eq!(counts, [0; 8]); // no pixel rectangle ever reaches it
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_histogram(
        &mut self,
        target: GLenum,
        reset: bool,
        format: GLenum,
        ty: GLenum,
        out: &mut [u8],
    ) -> GlResult {
        self.outside_begin_end()?;
        if target != GL_HISTOGRAM {
            return Err(GlError::InvalidEnum);
        }
        let entries = &self.imaging.histogram.entries;
        let colors: Vec<[f32; 4]> = entries.values.clone();
        self.pack_colors(&colors, [entries.size[0], 1], format, ty, out)?;
        if reset {
            self.imaging.histogram.entries.values.fill([0.0; 4]);
        }
        Ok(())
    }

    /// glGetHistogramParameter{if}v.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_histogram_parameter(GL_HISTOGRAM, GL_HISTOGRAM_SINK)?.as_bools(), [false]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_histogram_parameter(&self, target: GLenum, pname: GLenum) -> GlResult<StateValue> {
        self.outside_begin_end()?;
        let histogram = match target {
            GL_HISTOGRAM => &self.imaging.histogram,
            GL_PROXY_HISTOGRAM => &self.imaging.proxy_histogram,
            _ => return Err(GlError::InvalidEnum),
        };
        if let Some(size) = component_size(&histogram.entries, pname, GL_HISTOGRAM_RED_SIZE)
            .filter(|_| pname != GL_HISTOGRAM_SINK)
        {
            return Ok(size);
        }
        Ok(match pname {
            GL_HISTOGRAM_WIDTH => int(histogram.entries.size[0] as i32),
            GL_HISTOGRAM_FORMAT => enumeration(histogram.entries.internal_format),
            GL_HISTOGRAM_SINK => StateValue::Bools(vec![histogram.sink]),
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glMinmax: no intensity format.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.minmax(GL_MINMAX, GL_RGB, true)?;
    /// assert_eq!(ctx.get_minmax_parameter(GL_MINMAX, GL_MINMAX_SINK)?.as_bools(), [true]);
    /// assert_eq!(ctx.minmax(GL_MINMAX, GL_INTENSITY, false), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn minmax(&mut self, target: GLenum, internal: GLenum, sink: bool) -> GlResult {
        self.outside_begin_end()?;
        if target != GL_MINMAX {
            return Err(GlError::InvalidEnum);
        }
        let (base, _) = internal_format_of(internal as GLint, true)?;
        let minmax = &mut self.imaging.minmax;
        minmax.internal_format = internal;
        minmax.base = base;
        minmax.sink = sink;
        Ok(())
    }

    /// glResetMinmax: the minimum the largest representable value, the maximum the smallest.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.reset_minmax(GL_MINMAX)?;
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn reset_minmax(&mut self, target: GLenum) -> GlResult {
        self.outside_begin_end()?;
        if target != GL_MINMAX {
            return Err(GlError::InvalidEnum);
        }
        let minmax = &mut self.imaging.minmax;
        minmax.min = [f32::MAX; 4];
        minmax.max = [f32::MIN; 4];
        Ok(())
    }

    /// glGetMinmax: the minimum then the maximum, packed as a row of two (then reset if
    /// asked).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let mut out = [0u8; 8];
    /// ctx.get_minmax(GL_MINMAX, false, GL_LUMINANCE, GL_FLOAT, &mut out)?;
    /// let min = f32::from_ne_bytes(out[..4].try_into().unwrap());
    /// let max = f32::from_ne_bytes(out[4..].try_into().unwrap());
    /// assert!(min > max); // reset, and nothing reached it since
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_minmax(
        &mut self,
        target: GLenum,
        reset: bool,
        format: GLenum,
        ty: GLenum,
        out: &mut [u8],
    ) -> GlResult {
        self.outside_begin_end()?;
        if target != GL_MINMAX {
            return Err(GlError::InvalidEnum);
        }
        let minmax = &self.imaging.minmax;
        let colors = [minmax.min, minmax.max];
        self.pack_colors(&colors, [2, 1], format, ty, out)?;
        if reset {
            self.reset_minmax(target)?;
        }
        Ok(())
    }

    /// glGetMinmaxParameter{if}v.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_minmax_parameter(GL_MINMAX, GL_MINMAX_FORMAT)?.as_ints(), [GL_RGBA as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_minmax_parameter(&self, target: GLenum, pname: GLenum) -> GlResult<StateValue> {
        self.outside_begin_end()?;
        if target != GL_MINMAX {
            return Err(GlError::InvalidEnum);
        }
        let minmax = &self.imaging.minmax;
        Ok(match pname {
            GL_MINMAX_FORMAT => enumeration(minmax.internal_format),
            GL_MINMAX_SINK => StateValue::Bools(vec![minmax.sink]),
            _ => return Err(GlError::InvalidEnum),
        })
    }
}

impl Context {
    /// The bytes glGetColorTable writes (0 for a bad target, format or type).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.copy_color_table(GL_COLOR_TABLE, GL_RGBA8, 4)?;
    /// assert_eq!(ctx.color_table_pack_span(GL_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE), 16);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn color_table_pack_span(&self, target: GLenum, format: GLenum, ty: GLenum) -> usize {
        let width = COLOR_TABLES
            .iter()
            .position(|&t| t == target)
            .map_or(0, |i| self.imaging.tables[i].entries.size[0]);
        self.imaging_span(true, format, ty, [width as i32, 1])
    }

    /// The bytes glGetConvolutionFilter writes (`part` 0), or glGetSeparableFilter's row (1)
    /// and column (2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let (row, column) = (vec![0u8; 3 * 16], vec![0u8; 2 * 16]);
    /// ctx.convolution_filter(GL_SEPARABLE_2D, GL_RGBA, [3, 2], Some((GL_RGBA, GL_FLOAT, &row)), Some(&column))?;
    /// assert_eq!(ctx.filter_pack_span(GL_SEPARABLE_2D, GL_RGBA, GL_FLOAT, 1), 3 * 16); // the row
    /// assert_eq!(ctx.filter_pack_span(GL_SEPARABLE_2D, GL_RGBA, GL_FLOAT, 2), 2 * 16); // the column
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn filter_pack_span(
        &self,
        target: GLenum,
        format: GLenum,
        ty: GLenum,
        part: usize,
    ) -> usize {
        let Ok(index) = convolution_target(target) else {
            return 0;
        };
        let [w, h] = self.imaging.filters[index].entries.size;
        let size = match part {
            0 => [w, h],
            1 => [w, 1],
            _ => [h, 1],
        };
        self.imaging_span(true, format, ty, size.map(|s| s as i32))
    }

    /// The bytes glGetHistogram writes.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.histogram(GL_HISTOGRAM, 16, GL_RGBA, false)?;
    /// assert_eq!(ctx.histogram_pack_span(GL_RGBA, GL_UNSIGNED_SHORT), 16 * 8);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn histogram_pack_span(&self, format: GLenum, ty: GLenum) -> usize {
        let width = self.imaging.histogram.entries.size[0] as i32;
        self.imaging_span(true, format, ty, [width, 1])
    }
}
