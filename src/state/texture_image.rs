//! Texture images (§3.8.1-3.8.3, §6.1.4): internal formats, unpacking client pixels with the
//! GL_UNPACK_* modes and pixel transfer (§3.6.4-3.6.5), and packing them back for
//! glGetTexImage with the GL_PACK_* modes (§4.3.2). A texel is kept as four floats: the
//! components of its base internal format (table 3.15) in R, G, B, A order (luminance and
//! intensity in R, depth in R), quantized to the resolution the internal format reports.

use std::sync::Arc;

use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::pixel::{PixelMaps, PixelModeAttribs, PixelStoreModes};

/// The base internal formats (table 3.15), and depth (§3.8.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Base {
    /// GL_ALPHA.
    Alpha,
    /// GL_LUMINANCE.
    Luminance,
    /// GL_LUMINANCE_ALPHA.
    LuminanceAlpha,
    /// GL_INTENSITY.
    Intensity,
    /// GL_RGB.
    Rgb,
    /// GL_RGBA.
    Rgba,
    /// GL_DEPTH_COMPONENT.
    Depth,
}

/// The component resolutions glGetTexLevelParameter reports: red, green, blue, alpha,
/// luminance, intensity, depth.
pub type ComponentSizes = [u8; 7];

/// The base format and resolutions of an internal format (tables 3.15-3.16, and the depth
/// formats of §3.8.1), or None if `internal_format` is none. Unsized formats (1-4, the base
/// formats, the generic compressed ones, which fflight stores uncompressed) get 8 bits a
/// component, depth 24.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::texture_image::{internal_format, Base}};
/// assert_eq!(internal_format(GL_LUMINANCE_ALPHA as i32).map(|f| f.0), Some(Base::LuminanceAlpha));
/// assert_eq!(internal_format(3).map(|f| f.0), Some(Base::Rgb)); // GL 1.0's component count
/// assert!(internal_format(GL_LIGHT0 as i32).is_none());
/// ```
pub fn internal_format(internal_format: GLint) -> Option<(Base, ComponentSizes)> {
    use Base::*;
    let format = GLenum::try_from(internal_format).ok()?;
    let color = |base: Base, bits: [u8; 4]| {
        let [r, g, b, a] = bits;
        Some((base, [r, g, b, a, 0, 0, 0]))
    };
    let lum = |l: u8, a: u8| {
        Some((
            if a > 0 { LuminanceAlpha } else { Luminance },
            [0, 0, 0, a, l, 0, 0],
        ))
    };
    match format {
        1 | GL_LUMINANCE | GL_COMPRESSED_LUMINANCE => lum(8, 0),
        2 | GL_LUMINANCE_ALPHA | GL_COMPRESSED_LUMINANCE_ALPHA => lum(8, 8),
        3 | GL_RGB | GL_COMPRESSED_RGB => color(Rgb, [8, 8, 8, 0]),
        4 | GL_RGBA | GL_COMPRESSED_RGBA => color(Rgba, [8; 4]),
        GL_ALPHA | GL_COMPRESSED_ALPHA => color(Alpha, [0, 0, 0, 8]),
        GL_INTENSITY | GL_COMPRESSED_INTENSITY => Some((Intensity, [0, 0, 0, 0, 0, 8, 0])),
        GL_ALPHA4 => color(Alpha, [0, 0, 0, 4]),
        GL_ALPHA8 => color(Alpha, [0, 0, 0, 8]),
        GL_ALPHA12 => color(Alpha, [0, 0, 0, 12]),
        GL_ALPHA16 => color(Alpha, [0, 0, 0, 16]),
        GL_LUMINANCE4 => lum(4, 0),
        GL_LUMINANCE8 => lum(8, 0),
        GL_LUMINANCE12 => lum(12, 0),
        GL_LUMINANCE16 => lum(16, 0),
        GL_LUMINANCE4_ALPHA4 => lum(4, 4),
        GL_LUMINANCE6_ALPHA2 => lum(6, 2),
        GL_LUMINANCE8_ALPHA8 => lum(8, 8),
        GL_LUMINANCE12_ALPHA4 => lum(12, 4),
        GL_LUMINANCE12_ALPHA12 => lum(12, 12),
        GL_LUMINANCE16_ALPHA16 => lum(16, 16),
        GL_INTENSITY4 => Some((Intensity, [0, 0, 0, 0, 0, 4, 0])),
        GL_INTENSITY8 => Some((Intensity, [0, 0, 0, 0, 0, 8, 0])),
        GL_INTENSITY12 => Some((Intensity, [0, 0, 0, 0, 0, 12, 0])),
        GL_INTENSITY16 => Some((Intensity, [0, 0, 0, 0, 0, 16, 0])),
        GL_R3_G3_B2 => color(Rgb, [3, 3, 2, 0]),
        GL_RGB4 => color(Rgb, [4, 4, 4, 0]),
        GL_RGB5 => color(Rgb, [5, 5, 5, 0]),
        GL_RGB8 => color(Rgb, [8, 8, 8, 0]),
        GL_RGB10 => color(Rgb, [10, 10, 10, 0]),
        GL_RGB12 => color(Rgb, [12, 12, 12, 0]),
        GL_RGB16 => color(Rgb, [16, 16, 16, 0]),
        GL_RGBA2 => color(Rgba, [2; 4]),
        GL_RGBA4 => color(Rgba, [4; 4]),
        GL_RGB5_A1 => color(Rgba, [5, 5, 5, 1]),
        GL_RGBA8 => color(Rgba, [8; 4]),
        GL_RGB10_A2 => color(Rgba, [10, 10, 10, 2]),
        GL_RGBA12 => color(Rgba, [12; 4]),
        GL_RGBA16 => color(Rgba, [16; 4]),
        GL_DEPTH_COMPONENT => Some((Depth, [0, 0, 0, 0, 0, 0, 24])),
        GL_DEPTH_COMPONENT16 => Some((Depth, [0, 0, 0, 0, 0, 0, 16])),
        GL_DEPTH_COMPONENT24 => Some((Depth, [0, 0, 0, 0, 0, 0, 24])),
        GL_DEPTH_COMPONENT32 => Some((Depth, [0, 0, 0, 0, 0, 0, 32])),
        _ => None,
    }
}

/// One level (of one cube map face) of a texture: its size with the border, its internal
/// format as given, and its texels (none for a proxy), row by row, image by image.
#[derive(Clone, Debug, PartialEq)]
pub struct TexImage {
    /// GL_TEXTURE_WIDTH, the border included.
    pub width: i32,
    /// GL_TEXTURE_HEIGHT, the border included.
    pub height: i32,
    /// GL_TEXTURE_DEPTH, the border included.
    pub depth: i32,
    /// GL_TEXTURE_BORDER.
    pub border: i32,
    /// GL_TEXTURE_INTERNAL_FORMAT, as given.
    pub internal_format: GLint,
    /// Its base internal format.
    pub base: Base,
    /// The component resolutions it keeps (GL_TEXTURE_RED_SIZE ...).
    pub sizes: ComponentSizes,
    /// Shared: a glPushAttrib copy of a texture object must not copy its images.
    pub texels: Arc<Vec<[f32; 4]>>,
}

impl TexImage {
    /// The number of texels.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture_image::{internal_format, TexImage}};
    /// use std::sync::Arc;
    /// let (base, sizes) = internal_format(GL_RGBA8 as i32).unwrap();
    /// let image = TexImage {
    ///     width: 4, height: 2, depth: 1, border: 0, internal_format: GL_RGBA8 as i32, base, sizes,
    ///     texels: Arc::new(vec![[0.0; 4]; 8]),
    /// };
    /// assert_eq!(image.len(), 8);
    /// assert_eq!(image.size(GL_TEXTURE_RED_SIZE), Some(8));
    /// ```
    pub fn len(&self) -> usize {
        self.width as usize * self.height as usize * self.depth as usize
    }

    /// Whether the image has no texel.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture_image::{internal_format, TexImage}};
    /// use std::sync::Arc;
    /// let (base, sizes) = internal_format(GL_RGB as i32).unwrap();
    /// let image = TexImage {
    ///     width: 0, height: 1, depth: 1, border: 0, internal_format: GL_RGB as i32, base, sizes,
    ///     texels: Arc::new(Vec::new()),
    /// };
    /// assert!(image.is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The component resolution `pname` asks for (GL_TEXTURE_RED_SIZE ...), or None.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture_image::{internal_format, TexImage}};
    /// use std::sync::Arc;
    /// let (base, sizes) = internal_format(GL_R3_G3_B2 as i32).unwrap();
    /// let image = TexImage {
    ///     width: 1, height: 1, depth: 1, border: 0, internal_format: GL_R3_G3_B2 as i32, base, sizes,
    ///     texels: Arc::new(vec![[0.0; 4]]),
    /// };
    /// assert_eq!((image.size(GL_TEXTURE_BLUE_SIZE), image.size(GL_TEXTURE_ALPHA_SIZE)), (Some(2), Some(0)));
    /// ```
    pub fn size(&self, pname: GLenum) -> Option<u8> {
        let index = match pname {
            GL_TEXTURE_RED_SIZE => 0,
            GL_TEXTURE_GREEN_SIZE => 1,
            GL_TEXTURE_BLUE_SIZE => 2,
            GL_TEXTURE_ALPHA_SIZE => 3,
            GL_TEXTURE_LUMINANCE_SIZE => 4,
            GL_TEXTURE_INTENSITY_SIZE => 5,
            GL_TEXTURE_DEPTH_SIZE => 6,
            _ => return None,
        };
        Some(self.sizes[index])
    }

    /// The texel values of the base format after quantization to `sizes`, from an RGBA (or
    /// depth in R) color: table 3.15 keeps A for alpha, R for luminance and intensity.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture_image::{internal_format, TexImage}};
    /// let (base, sizes) = internal_format(GL_RGB8 as i32).unwrap();
    /// // 8 bits a component; RGB keeps no alpha (stored 0; `rgba` reads it back as 1).
    /// assert_eq!(TexImage::store(base, &sizes, [1.0, 0.0, 1.0, 0.25]), [1.0, 0.0, 1.0, 0.0]);
    /// ```
    pub fn store(base: Base, sizes: &ComponentSizes, rgba: [f32; 4]) -> [f32; 4] {
        let q = |v: f32, bits: u8| quantize(v, bits);
        let [r, g, b, a] = rgba;
        match base {
            Base::Alpha => [0.0, 0.0, 0.0, q(a, sizes[3])],
            Base::Luminance => [q(r, sizes[4]), 0.0, 0.0, 0.0],
            Base::LuminanceAlpha => [q(r, sizes[4]), 0.0, 0.0, q(a, sizes[3])],
            Base::Intensity => [q(r, sizes[5]), 0.0, 0.0, 0.0],
            Base::Rgb => [q(r, sizes[0]), q(g, sizes[1]), q(b, sizes[2]), 0.0],
            Base::Rgba => [
                q(r, sizes[0]),
                q(g, sizes[1]),
                q(b, sizes[2]),
                q(a, sizes[3]),
            ],
            Base::Depth => [q(r, sizes[6]), 0.0, 0.0, 0.0],
        }
    }

    /// A texel as the RGBA color glGetTexImage packs (table 6.1), depth in R.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture_image::{internal_format, TexImage}};
    /// use std::sync::Arc;
    /// let (base, sizes) = internal_format(GL_LUMINANCE8 as i32).unwrap();
    /// let image = TexImage {
    ///     width: 1, height: 1, depth: 1, border: 0, internal_format: GL_LUMINANCE8 as i32, base, sizes,
    ///     texels: Arc::new(vec![[1.0, 0.0, 0.0, 1.0]]),
    /// };
    /// assert_eq!(image.rgba(image.texels[0])[0], 1.0);
    /// ```
    pub fn rgba(&self, texel: [f32; 4]) -> [f32; 4] {
        let [r, g, b, a] = texel;
        match self.base {
            Base::Alpha => [0.0, 0.0, 0.0, a],
            Base::Luminance => [r, 0.0, 0.0, 1.0],
            Base::LuminanceAlpha => [r, 0.0, 0.0, a],
            Base::Intensity => [r, 0.0, 0.0, 1.0],
            Base::Rgb => [r, g, b, 1.0],
            Base::Rgba => [r, g, b, a],
            Base::Depth => [r, 0.0, 0.0, 0.0],
        }
    }
}

/// `v` in [0, 1] rounded to the nearest of 2^bits - 1 steps (bits above 23 keep the float).
fn quantize(v: f32, bits: u8) -> f32 {
    if bits == 0 || bits > 23 {
        return v;
    }
    let steps = ((1u32 << bits) - 1) as f64;
    ((v as f64 * steps).round() / steps) as f32
}

/// A client pixel format (table 3.6) that texture images take: its components in memory
/// order as indices into RGBA (depth: 0).
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::texture_image::format_components};
/// assert_eq!(format_components(GL_BGR), Some(&[2, 1, 0][..]));
/// ```
pub fn format_components(format: GLenum) -> Option<&'static [usize]> {
    Some(match format {
        GL_RED | GL_LUMINANCE | GL_DEPTH_COMPONENT => &[0],
        GL_GREEN => &[1],
        GL_BLUE => &[2],
        GL_ALPHA => &[3],
        GL_LUMINANCE_ALPHA => &[0, 3],
        GL_RGB => &[0, 1, 2],
        GL_BGR => &[2, 1, 0],
        GL_RGBA => &[0, 1, 2, 3],
        GL_BGRA => &[2, 1, 0, 3],
        _ => return None,
    })
}

/// A client data type (table 3.5): its size in bytes and, for the packed types, the widths of
/// its fields in component order, and whether the first component is in the low bits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelType {
    /// The type's enum.
    pub ty: GLenum,
    /// Bytes per element (per component, or per pixel for the packed types).
    pub size: usize,
    /// The packed types' field widths and whether they are reversed (_REV).
    pub packed: Option<(&'static [u32], bool)>,
}

/// The client type `ty`, or None for an unknown one.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::texture_image::pixel_type};
/// let packed = pixel_type(GL_UNSIGNED_SHORT_5_6_5).unwrap();
/// assert_eq!((packed.size, packed.packed), (2, Some((&[5, 6, 5][..], false))));
/// assert!(pixel_type(GL_BITMAP).is_none());
/// ```
pub fn pixel_type(ty: GLenum) -> Option<PixelType> {
    let (size, packed): (usize, Option<(&'static [u32], bool)>) = match ty {
        GL_UNSIGNED_BYTE | GL_BYTE => (1, None),
        GL_UNSIGNED_SHORT | GL_SHORT => (2, None),
        GL_UNSIGNED_INT | GL_INT | GL_FLOAT => (4, None),
        GL_UNSIGNED_BYTE_3_3_2 => (1, Some((&[3, 3, 2], false))),
        GL_UNSIGNED_BYTE_2_3_3_REV => (1, Some((&[3, 3, 2], true))),
        GL_UNSIGNED_SHORT_5_6_5 => (2, Some((&[5, 6, 5], false))),
        GL_UNSIGNED_SHORT_5_6_5_REV => (2, Some((&[5, 6, 5], true))),
        GL_UNSIGNED_SHORT_4_4_4_4 => (2, Some((&[4, 4, 4, 4], false))),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => (2, Some((&[4, 4, 4, 4], true))),
        GL_UNSIGNED_SHORT_5_5_5_1 => (2, Some((&[5, 5, 5, 1], false))),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => (2, Some((&[5, 5, 5, 1], true))),
        GL_UNSIGNED_INT_8_8_8_8 => (4, Some((&[8, 8, 8, 8], false))),
        GL_UNSIGNED_INT_8_8_8_8_REV => (4, Some((&[8, 8, 8, 8], true))),
        GL_UNSIGNED_INT_10_10_10_2 => (4, Some((&[10, 10, 10, 2], false))),
        GL_UNSIGNED_INT_2_10_10_10_REV => (4, Some((&[10, 10, 10, 2], true))),
        _ => return None,
    };
    Some(PixelType { ty, size, packed })
}

/// A checked format and type pair of an image transfer (§3.6.4): GL_INVALID_ENUM for a
/// format or type that is none (GL_BITMAP is only for color indices and stencil, which
/// texture images do not take), GL_INVALID_OPERATION for a packed type whose component count
/// differs from the format's (table 3.8).
#[derive(Clone, Copy, Debug)]
pub struct PixelFormat {
    /// The format's components in memory order, by RGBA index.
    pub components: &'static [usize],
    /// The client type.
    pub ty: PixelType,
    /// GL_DEPTH_COMPONENT.
    pub depth: bool,
    /// GL_LUMINANCE or GL_LUMINANCE_ALPHA: unpacking copies L to R, G and B.
    pub luminance: bool,
}

impl PixelFormat {
    /// Checks `format` and `ty` as described above.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture_image::PixelFormat, GlError};
    /// assert!(PixelFormat::new(GL_RGBA, GL_UNSIGNED_INT_8_8_8_8).is_ok());
    /// // A packed type of three components for a four-component format.
    /// assert_eq!(PixelFormat::new(GL_RGBA, GL_UNSIGNED_BYTE_3_3_2).err(), Some(GlError::InvalidOperation));
    /// ```
    pub fn new(format: GLenum, ty: GLenum) -> GlResult<PixelFormat> {
        let components = format_components(format).ok_or(GlError::InvalidEnum)?;
        let ty = pixel_type(ty).ok_or(GlError::InvalidEnum)?;
        if let Some((fields, _)) = ty.packed {
            let three = matches!(format, GL_RGB | GL_BGR);
            let four = matches!(format, GL_RGBA | GL_BGRA);
            if (fields.len() == 3 && !three) || (fields.len() == 4 && !four) {
                return Err(GlError::InvalidOperation);
            }
        }
        Ok(PixelFormat {
            components,
            ty,
            depth: format == GL_DEPTH_COMPONENT,
            luminance: matches!(format, GL_LUMINANCE | GL_LUMINANCE_ALPHA),
        })
    }

    /// Bytes of one pixel in memory.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texture_image::PixelFormat};
    /// assert_eq!(PixelFormat::new(GL_RGB, GL_SHORT)?.pixel_bytes(), 6);
    /// assert_eq!(PixelFormat::new(GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4)?.pixel_bytes(), 2);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn pixel_bytes(&self) -> usize {
        match self.ty.packed {
            Some(_) => self.ty.size,
            None => self.ty.size * self.components.len(),
        }
    }
}

/// Where the pixels of a width x height x depth image lie in client memory under the pixel
/// store modes (§3.6.4, §3.8.1 for images of 3D textures, §4.3.2 for packing).
#[derive(Clone, Copy, Debug)]
pub struct Layout {
    /// The offset of the first pixel (the skip modes applied).
    pub start: usize,
    /// Bytes per pixel.
    pub pixel_bytes: usize,
    /// Bytes from one row to the next (row length and alignment applied).
    pub row_stride: usize,
    /// Bytes from one image to the next (image height applied).
    pub image_stride: usize,
    /// Width, height, depth in pixels.
    pub size: [usize; 3],
}

impl Layout {
    /// `three_d`: the image-height and skip-images modes apply (images of 3D textures only).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::{pixel::PixelStoreModes, texture_image::{Layout, PixelFormat}}};
    /// let format = PixelFormat::new(GL_RGB, GL_UNSIGNED_BYTE)?;
    /// let modes = PixelStoreModes { skip_rows: 1, ..PixelStoreModes::default() };
    /// let layout = Layout::new(&modes, &format, [3, 2, 1], false);
    /// assert_eq!((layout.start, layout.row_stride), (12, 12)); // one row of 9 bytes padded to 12 skipped
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn new(
        modes: &PixelStoreModes,
        format: &PixelFormat,
        size: [usize; 3],
        three_d: bool,
    ) -> Layout {
        let [width, height, _] = size;
        let row_length = if modes.row_length > 0 {
            modes.row_length as usize
        } else {
            width
        };
        let image_height = if three_d && modes.image_height > 0 {
            modes.image_height as usize
        } else {
            height
        };
        let element = format.ty.size;
        let pixel_bytes = format.pixel_bytes();
        let alignment = modes.alignment.max(1) as usize;
        // Saturating: hostile sizes and pixel store modes (2^31 rows of 2^31 pixels) must give
        // a span no memory holds, never an overflow (found by the entry-point sweep).
        let row_bytes = pixel_bytes.saturating_mul(row_length);
        let row_stride = if element >= alignment {
            row_bytes
        } else {
            row_bytes.div_ceil(alignment).saturating_mul(alignment)
        };
        let image_stride = row_stride.saturating_mul(image_height);
        let skip_images = if three_d {
            modes.skip_images.max(0) as usize
        } else {
            0
        };
        Layout {
            start: skip_images
                .saturating_mul(image_stride)
                .saturating_add((modes.skip_rows.max(0) as usize).saturating_mul(row_stride))
                .saturating_add((modes.skip_pixels.max(0) as usize).saturating_mul(pixel_bytes)),
            pixel_bytes,
            row_stride,
            image_stride,
            size,
        }
    }

    /// The bytes from the start of client memory to the end of the last pixel (0 for an
    /// empty image).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::{pixel::PixelStoreModes, texture_image::{Layout, PixelFormat}}};
    /// let format = PixelFormat::new(GL_RGB, GL_UNSIGNED_BYTE)?;
    /// let layout = Layout::new(&PixelStoreModes::default(), &format, [3, 2, 1], false);
    /// assert_eq!(layout.span(), 12 + 9);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn span(&self) -> usize {
        let [w, h, d] = self.size;
        if w == 0 || h == 0 || d == 0 {
            return 0;
        }
        self.start
            .saturating_add((d - 1).saturating_mul(self.image_stride))
            .saturating_add((h - 1).saturating_mul(self.row_stride))
            .saturating_add(w.saturating_mul(self.pixel_bytes))
    }

    fn offset(&self, x: usize, y: usize, z: usize) -> usize {
        self.start + z * self.image_stride + y * self.row_stride + x * self.pixel_bytes
    }
}

/// Reads `n` bytes at `at` as one element, swapping bytes if asked.
fn element(bytes: &[u8], at: usize, size: usize, swap: bool) -> u32 {
    let mut raw = [0u8; 4];
    raw[..size].copy_from_slice(&bytes[at..at + size]);
    if swap {
        raw[..size].reverse();
    }
    match size {
        1 => raw[0] as u32,
        2 => u16::from_ne_bytes([raw[0], raw[1]]) as u32,
        _ => u32::from_ne_bytes(raw),
    }
}

pub(crate) fn write_element(bytes: &mut [u8], at: usize, size: usize, swap: bool, value: u32) {
    let mut raw = [0u8; 4];
    match size {
        1 => raw[0] = value as u8,
        2 => raw[..2].copy_from_slice(&(value as u16).to_ne_bytes()),
        _ => raw = value.to_ne_bytes(),
    }
    if swap {
        raw[..size].reverse();
    }
    bytes[at..at + size].copy_from_slice(&raw[..size]);
}

/// The fields of a packed value, in component order.
fn unpack_fields(value: u32, fields: &[u32], reversed: bool, total_bits: u32) -> Vec<f32> {
    let mut shift = if reversed { 0 } else { total_bits };
    fields
        .iter()
        .map(|&width| {
            if !reversed {
                shift -= width;
            }
            let max = (1u32 << width) - 1;
            let field = (value >> shift) & max;
            if reversed {
                shift += width;
            }
            field as f32 / max as f32
        })
        .collect()
}

fn pack_fields(values: &[f32], fields: &[u32], reversed: bool, total_bits: u32) -> u32 {
    let mut shift = if reversed { 0 } else { total_bits };
    let mut packed = 0u32;
    for (&v, &width) in values.iter().zip(fields) {
        if !reversed {
            shift -= width;
        }
        let max = (1u32 << width) - 1;
        packed |= ((v.clamp(0.0, 1.0) as f64 * max as f64).round() as u32) << shift;
        if reversed {
            shift += width;
        }
    }
    packed
}

/// A component of a non-packed type as a float (table 2.9: unsigned normalized c / (2^b - 1),
/// signed (2c + 1) / (2^b - 1)).
fn component_to_float(ty: GLenum, raw: u32) -> f32 {
    match ty {
        GL_UNSIGNED_BYTE => raw as f32 / 255.0,
        GL_BYTE => crate::state::convert::byte_to_float(raw as u8 as i8),
        GL_UNSIGNED_SHORT => crate::state::convert::ushort_to_float(raw as u16),
        GL_SHORT => crate::state::convert::short_to_float(raw as u16 as i16),
        GL_UNSIGNED_INT => crate::state::convert::uint_to_float(raw),
        GL_INT => crate::state::convert::int_to_color(raw as i32),
        _ => f32::from_bits(raw),
    }
}

/// A float in [0, 1] (or [-1, 1] for signed types) as a component of a non-packed type
/// (table 4.7): unsigned round(c (2^b - 1)), signed round(((2^b - 1) c - 1) / 2).
fn float_to_component(ty: GLenum, v: f32) -> u32 {
    let v = v as f64;
    let unsigned = |bits: u32| {
        let max = ((1u64 << bits) - 1) as f64;
        (v.clamp(0.0, 1.0) * max).round() as u32
    };
    let signed = |bits: u32| {
        let max = ((1u64 << bits) - 1) as f64;
        let c = ((max * v.clamp(-1.0, 1.0) - 1.0) / 2.0).round();
        c as i64 as u32
    };
    match ty {
        GL_UNSIGNED_BYTE => unsigned(8),
        GL_BYTE => signed(8) & 0xFF,
        GL_UNSIGNED_SHORT => unsigned(16),
        GL_SHORT => signed(16) & 0xFFFF,
        GL_UNSIGNED_INT => unsigned(32),
        GL_INT => signed(32),
        _ => (v as f32).to_bits(),
    }
}

/// The pixel transfer operations of §3.6.5 on an unpacked color: scale and bias, then the
/// R_TO_R ... A_TO_A maps if GL_MAP_COLOR, then the clamp to [0, 1]. Depth: its scale and
/// bias, then the clamp.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::{pixel::{PixelMaps, PixelModeAttribs}, texture_image::transfer}};
/// let mut mode = PixelModeAttribs::default();
/// mode.set_transfer(GL_RED_SCALE, 2.0)?;
/// mode.set_transfer(GL_GREEN_BIAS, 0.5)?;
/// let out = transfer(&mode, &PixelMaps::default(), [0.25, 0.75, 0.0, 1.0], false);
/// assert_eq!(out, [0.5, 1.0, 0.0, 1.0]); // scaled, biased, clamped
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn transfer(
    mode: &PixelModeAttribs,
    maps: &PixelMaps,
    rgba: [f32; 4],
    depth: bool,
) -> [f32; 4] {
    if depth {
        let d = rgba[0] * mode.scale[4] + mode.bias[4];
        return [d.clamp(0.0, 1.0), 0.0, 0.0, 0.0];
    }
    std::array::from_fn(|i| {
        let mut c = rgba[i] * mode.scale[i] + mode.bias[i];
        if mode.map_color {
            let map = &maps.maps[6 + i];
            let index = (c.clamp(0.0, 1.0) * (map.len() - 1) as f32).round() as usize;
            c = map[index.min(map.len() - 1)];
        }
        c.clamp(0.0, 1.0)
    })
}

/// Unpacks a width x height x depth image (§3.6.4): each pixel's components converted to
/// floats and expanded to RGBA (luminance copied to R, G and B; missing color components 0,
/// alpha 1), then `per_pixel` (the transfer and the internal format's conversion).
/// GL_INVALID_OPERATION when `bytes` is shorter than the layout's span.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::{pixel::PixelStoreModes, texture_image::{unpack, Layout, PixelFormat}}};
/// let format = PixelFormat::new(GL_LUMINANCE, GL_UNSIGNED_BYTE)?;
/// let modes = PixelStoreModes::default();
/// let layout = Layout::new(&modes, &format, [2, 1, 1], false);
/// let pixels = unpack(&[255, 0], &modes, &format, &layout, |rgba| rgba)?;
/// assert_eq!(pixels, [[1.0, 1.0, 1.0, 1.0], [0.0, 0.0, 0.0, 1.0]]); // L copied to R, G, B
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn unpack(
    bytes: &[u8],
    modes: &PixelStoreModes,
    format: &PixelFormat,
    layout: &Layout,
    mut per_pixel: impl FnMut([f32; 4]) -> [f32; 4],
) -> GlResult<Vec<[f32; 4]>> {
    if bytes.len() < layout.span() {
        return Err(GlError::InvalidOperation);
    }
    let [w, h, d] = layout.size;
    let size = format.ty.size;
    let mut texels = Vec::new();
    texels
        .try_reserve_exact(w * h * d)
        .map_err(|_| GlError::OutOfMemory)?;
    for z in 0..d {
        for y in 0..h {
            for x in 0..w {
                let at = layout.offset(x, y, z);
                let values: Vec<f32> = match format.ty.packed {
                    Some((fields, reversed)) => {
                        let raw = element(bytes, at, size, modes.swap_bytes);
                        unpack_fields(raw, fields, reversed, size as u32 * 8)
                    }
                    None => (0..format.components.len())
                        .map(|k| {
                            let raw = element(bytes, at + k * size, size, modes.swap_bytes);
                            component_to_float(format.ty.ty, raw)
                        })
                        .collect(),
                };
                let mut rgba = [0.0, 0.0, 0.0, 1.0];
                for (&component, value) in format.components.iter().zip(values) {
                    rgba[component] = value;
                }
                if format.luminance {
                    rgba[1] = rgba[0];
                    rgba[2] = rgba[0];
                }
                texels.push(per_pixel(rgba));
            }
        }
    }
    Ok(texels)
}

/// Packs `w x h x d` RGBA colors (depth in R) into `bytes` (§4.3.2 as §6.1.4 uses it: no
/// pixel transfer; luminance is R): the bytes between pixels are left as they are.
/// GL_INVALID_OPERATION when `bytes` is shorter than the layout's span.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::{pixel::PixelStoreModes, texture_image::{pack, Layout, PixelFormat}}};
/// let format = PixelFormat::new(GL_RGBA, GL_UNSIGNED_BYTE)?;
/// let modes = PixelStoreModes::default();
/// let layout = Layout::new(&modes, &format, [1, 1, 1], false);
/// let mut bytes = [0u8; 4];
/// pack(&[[1.0, 0.0, 0.5, 1.0]], &mut bytes, &modes, &format, &layout)?;
/// assert_eq!(bytes, [255, 0, 128, 255]);
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn pack(
    colors: &[[f32; 4]],
    bytes: &mut [u8],
    modes: &PixelStoreModes,
    format: &PixelFormat,
    layout: &Layout,
) -> GlResult {
    if bytes.len() < layout.span() {
        return Err(GlError::InvalidOperation);
    }
    let [w, h, d] = layout.size;
    let size = format.ty.size;
    let mut colors = colors.iter();
    for z in 0..d {
        for y in 0..h {
            for x in 0..w {
                let rgba = colors.next().copied().unwrap_or_default();
                let at = layout.offset(x, y, z);
                let values: Vec<f32> = format.components.iter().map(|&c| rgba[c]).collect();
                match format.ty.packed {
                    Some((fields, reversed)) => {
                        let raw = pack_fields(&values, fields, reversed, size as u32 * 8);
                        write_element(bytes, at, size, modes.swap_bytes, raw);
                    }
                    None => {
                        for (k, &v) in values.iter().enumerate() {
                            let raw = float_to_component(format.ty.ty, v);
                            write_element(bytes, at + k * size, size, modes.swap_bytes, raw);
                        }
                    }
                }
            }
        }
    }
    Ok(())
}
