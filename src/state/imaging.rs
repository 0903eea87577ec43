//! The imaging subset (§3.6.2-3.6.3, §3.6.5, §6.1.7-6.1.9): color tables, convolution
//! filters, histogram and minmax. Kept, validated and queried; no pixel rectangle reaches
//! them (nothing is rasterized), so the histogram counts and the minmax values stay as the
//! last reset left them.

use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::texture_image::{Base, ComponentSizes, TexImage, internal_format};

/// The widest color table (Mesa's MAX_COLOR_TABLE_SIZE) and histogram.
pub const MAX_COLOR_TABLE_WIDTH: usize = 256;
/// GL_MAX_CONVOLUTION_WIDTH and GL_MAX_CONVOLUTION_HEIGHT (Mesa's).
pub const MAX_CONVOLUTION_SIZE: usize = 9;

/// The color table targets, in order; their proxies follow them by 3 in the enum values.
pub const COLOR_TABLES: [GLenum; 3] = [
    GL_COLOR_TABLE,
    GL_POST_CONVOLUTION_COLOR_TABLE,
    GL_POST_COLOR_MATRIX_COLOR_TABLE,
];
/// The convolution targets, in order.
pub const CONVOLUTIONS: [GLenum; 3] = [GL_CONVOLUTION_1D, GL_CONVOLUTION_2D, GL_SEPARABLE_2D];

/// An image of RGBA entries in an internal format (a color table, a filter, a histogram's
/// format): each entry as the internal format keeps it (`TexImage::store`).
#[derive(Clone, Debug, PartialEq)]
pub struct Entries {
    /// The internal format, as given.
    pub internal_format: GLenum,
    /// Its base internal format.
    pub base: Base,
    /// The component resolutions the internal format keeps.
    pub sizes: ComponentSizes,
    /// Width (and height, for two-dimensional filters).
    pub size: [usize; 2],
    /// The entries, row by row.
    pub values: Vec<[f32; 4]>,
}

impl Entries {
    fn empty(internal_format: GLenum) -> Entries {
        let (base, _) = internal_format_of(internal_format as GLint, false).expect("valid");
        Entries {
            internal_format,
            base,
            sizes: [0; 7],
            size: [0, 0],
            values: Vec::new(),
        }
    }

    /// Entries of `internal_format` and `size` from RGBA colors.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::imaging::{internal_format_of, Entries}};
    /// let format = internal_format_of(GL_LUMINANCE8 as i32, false)?;
    /// let entries = Entries::new(GL_LUMINANCE8, format, [2, 1], &[[0.5, 0.2, 0.1, 1.0], [1.0; 4]]);
    /// assert_eq!(entries.values.len(), 2);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn new(
        internal_format: GLenum,
        (base, sizes): (Base, ComponentSizes),
        size: [usize; 2],
        colors: &[[f32; 4]],
    ) -> Entries {
        Entries {
            internal_format,
            base,
            sizes,
            size,
            values: colors
                .iter()
                .map(|&c| TexImage::store(base, &sizes, c))
                .collect(),
        }
    }

    /// Entry `i` as the RGBA color the queries pack (table 6.1's conversion of a texture
    /// image: luminance in R).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::imaging::{internal_format_of, Entries}};
    /// let format = internal_format_of(GL_ALPHA8 as i32, false)?;
    /// let entries = Entries::new(GL_ALPHA8, format, [1, 1], &[[0.3, 0.3, 0.3, 1.0]]);
    /// assert_eq!(entries.rgba(0), [0.0, 0.0, 0.0, 1.0]); // an alpha table keeps alpha only
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn rgba(&self, i: usize) -> [f32; 4] {
        let [r, g, b, a] = self.values[i];
        match self.base {
            Base::Alpha => [0.0, 0.0, 0.0, a],
            Base::Luminance | Base::Intensity => [r, 0.0, 0.0, 1.0],
            Base::LuminanceAlpha => [r, 0.0, 0.0, a],
            Base::Rgb => [r, g, b, 1.0],
            _ => [r, g, b, a],
        }
    }

    /// GL_*_RED_SIZE ... GL_*_INTENSITY_SIZE (`k` 0 to 5).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::imaging::{internal_format_of, Entries}};
    /// let format = internal_format_of(GL_RGB5 as i32, false)?;
    /// let entries = Entries::new(GL_RGB5, format, [0, 1], &[]);
    /// assert_eq!((entries.component_size(0), entries.component_size(3)), (5, 0)); // red, alpha
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn component_size(&self, k: usize) -> i32 {
        i32::from(self.sizes[k])
    }
}

/// An internal format the imaging commands accept (the color ones of table 3.16), with its
/// base and resolutions; `intensity` says whether GL_INTENSITY* is allowed (not for
/// histograms and minmax). GL_INVALID_ENUM otherwise.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::imaging::internal_format_of, GlError};
/// assert!(internal_format_of(GL_INTENSITY8 as i32, false).is_ok());
/// assert_eq!(internal_format_of(GL_INTENSITY8 as i32, true).err(), Some(GlError::InvalidEnum)); // histograms
/// ```
pub fn internal_format_of(format: GLint, histogram: bool) -> GlResult<(Base, ComponentSizes)> {
    match internal_format(format) {
        Some((Base::Depth, _)) | None => Err(GlError::InvalidEnum),
        Some((Base::Intensity, _)) if histogram => Err(GlError::InvalidEnum),
        Some(found) => Ok(found),
    }
}

/// One color table: its entries and its scale and bias (GL_COLOR_TABLE_SCALE, _BIAS).
#[derive(Clone, Debug, PartialEq)]
pub struct ColorTable {
    /// The table's entries.
    pub entries: Entries,
}

impl Default for ColorTable {
    fn default() -> ColorTable {
        ColorTable {
            entries: Entries::empty(GL_RGBA),
        }
    }
}

/// A convolution filter: its entries (a separable filter's row, then its column).
#[derive(Clone, Debug, PartialEq)]
pub struct Filter {
    /// The filter's entries (a separable filter's row).
    pub entries: Entries,
    /// A separable filter's column (empty otherwise).
    pub column: Vec<[f32; 4]>,
}

impl Default for Filter {
    fn default() -> Filter {
        Filter {
            entries: Entries::empty(GL_RGBA),
            column: Vec::new(),
        }
    }
}

/// The pixel-mode state of the imaging subset (GL_PIXEL_MODE_BIT; the enables also
/// GL_ENABLE_BIT): the enables, the color table scales and biases, the filters' border
/// modes, colors, scales and biases.
#[derive(Clone, Debug, PartialEq)]
pub struct ImagingModes {
    /// GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE, GL_POST_COLOR_MATRIX_COLOR_TABLE.
    pub tables_enabled: [bool; 3],
    /// GL_CONVOLUTION_1D, GL_CONVOLUTION_2D, GL_SEPARABLE_2D.
    pub convolutions_enabled: [bool; 3],
    /// GL_HISTOGRAM.
    pub histogram_enabled: bool,
    /// GL_MINMAX.
    pub minmax_enabled: bool,
    /// GL_COLOR_TABLE_SCALE of each table, in `tables_enabled` order.
    pub table_scale: [[f32; 4]; 3],
    /// GL_COLOR_TABLE_BIAS of each table.
    pub table_bias: [[f32; 4]; 3],
    /// GL_CONVOLUTION_BORDER_MODE of each filter, in `convolutions_enabled` order.
    pub border_mode: [GLenum; 3],
    /// GL_CONVOLUTION_BORDER_COLOR of each filter.
    pub border_color: [[f32; 4]; 3],
    /// GL_CONVOLUTION_FILTER_SCALE of each filter.
    pub filter_scale: [[f32; 4]; 3],
    /// GL_CONVOLUTION_FILTER_BIAS of each filter.
    pub filter_bias: [[f32; 4]; 3],
}

impl Default for ImagingModes {
    fn default() -> ImagingModes {
        ImagingModes {
            tables_enabled: [false; 3],
            convolutions_enabled: [false; 3],
            histogram_enabled: false,
            minmax_enabled: false,
            table_scale: [[1.0; 4]; 3],
            table_bias: [[0.0; 4]; 3],
            border_mode: [GL_REDUCE; 3],
            border_color: [[0.0; 4]; 3],
            filter_scale: [[1.0; 4]; 3],
            filter_bias: [[0.0; 4]; 3],
        }
    }
}

/// The histogram (§3.6.5): its format, width, sink flag and counts.
#[derive(Clone, Debug, PartialEq)]
pub struct Histogram {
    /// Its format, width and counts.
    pub entries: Entries,
    /// GL_HISTOGRAM_SINK.
    pub sink: bool,
}

impl Default for Histogram {
    fn default() -> Histogram {
        Histogram {
            entries: Entries::empty(GL_RGBA),
            sink: false,
        }
    }
}

/// Minmax (§3.6.5): its format, sink flag and the minimum and maximum.
#[derive(Clone, Debug, PartialEq)]
pub struct Minmax {
    /// GL_MINMAX_FORMAT.
    pub internal_format: GLenum,
    /// Its base internal format.
    pub base: Base,
    /// GL_MINMAX_SINK.
    pub sink: bool,
    /// The minimum of each component.
    pub min: [f32; 4],
    /// The maximum of each component.
    pub max: [f32; 4],
}

impl Default for Minmax {
    fn default() -> Minmax {
        Minmax {
            internal_format: GL_RGBA,
            base: Base::Rgba,
            sink: false,
            min: [f32::MAX; 4],
            max: [f32::MIN; 4],
        }
    }
}

/// The imaging subset's images and results (in no attribute group).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Imaging {
    /// GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE, GL_POST_COLOR_MATRIX_COLOR_TABLE.
    pub tables: [ColorTable; 3],
    /// The proxies of the three tables.
    pub proxy_tables: [ColorTable; 3],
    /// GL_CONVOLUTION_1D, GL_CONVOLUTION_2D, GL_SEPARABLE_2D.
    pub filters: [Filter; 3],
    /// GL_HISTOGRAM.
    pub histogram: Histogram,
    /// GL_PROXY_HISTOGRAM.
    pub proxy_histogram: Histogram,
    /// GL_MINMAX.
    pub minmax: Minmax,
}

/// The color table a target names: (index, proxy), or GL_INVALID_ENUM.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::imaging::color_table_target};
/// assert_eq!(color_table_target(GL_PROXY_POST_COLOR_MATRIX_COLOR_TABLE)?, (2, true));
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn color_table_target(target: GLenum) -> GlResult<(usize, bool)> {
    match target {
        GL_COLOR_TABLE..=GL_POST_COLOR_MATRIX_COLOR_TABLE => {
            Ok(((target - GL_COLOR_TABLE) as usize, false))
        }
        GL_PROXY_COLOR_TABLE..=GL_PROXY_POST_COLOR_MATRIX_COLOR_TABLE => {
            Ok(((target - GL_PROXY_COLOR_TABLE) as usize, true))
        }
        _ => Err(GlError::InvalidEnum),
    }
}

/// How many values glColorTableParameter{if}v reads for `pname`: 4 for the scale and the
/// bias, 0 for any other pname (GL_INVALID_ENUM, which reads nothing).
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::imaging::color_table_param_count};
/// assert_eq!(color_table_param_count(GL_COLOR_TABLE_BIAS), 4);
/// assert_eq!(color_table_param_count(GL_COLOR_TABLE_WIDTH), 0); // a query's pname
/// ```
pub fn color_table_param_count(pname: GLenum) -> usize {
    match pname {
        GL_COLOR_TABLE_SCALE | GL_COLOR_TABLE_BIAS => 4,
        _ => 0,
    }
}

/// How many values glConvolutionParameter{if}v reads for `pname`: 1 for the border mode, 4
/// for the border color, the filter scale and the bias, 0 for any other pname
/// (GL_INVALID_ENUM, which reads nothing).
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::imaging::convolution_param_count};
/// assert_eq!(convolution_param_count(GL_CONVOLUTION_BORDER_MODE), 1);
/// assert_eq!(convolution_param_count(GL_CONVOLUTION_FILTER_SCALE), 4);
/// assert_eq!(convolution_param_count(GL_CONVOLUTION_WIDTH), 0); // a query's pname
/// ```
pub fn convolution_param_count(pname: GLenum) -> usize {
    match pname {
        GL_CONVOLUTION_BORDER_MODE => 1,
        GL_CONVOLUTION_BORDER_COLOR | GL_CONVOLUTION_FILTER_SCALE | GL_CONVOLUTION_FILTER_BIAS => 4,
        _ => 0,
    }
}

/// The convolution filter a target names, or GL_INVALID_ENUM.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::imaging::convolution_target};
/// assert_eq!(convolution_target(GL_SEPARABLE_2D)?, 2);
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn convolution_target(target: GLenum) -> GlResult<usize> {
    CONVOLUTIONS
        .iter()
        .position(|&t| t == target)
        .ok_or(GlError::InvalidEnum)
}

/// A table or histogram width: GL_INVALID_VALUE unless 0 or a power of two; whether it fits.
///
/// # Examples
///
/// ```
/// use fflight::{state::imaging::table_width, GlError};
/// assert_eq!(table_width(256), Ok(true));
/// assert_eq!(table_width(512), Ok(false)); // too wide: GL_TABLE_TOO_LARGE, or a zero proxy
/// assert_eq!(table_width(6), Err(GlError::InvalidValue));
/// ```
pub fn table_width(width: i32) -> GlResult<bool> {
    let width = usize::try_from(width).map_err(|_| GlError::InvalidValue)?;
    if width != 0 && !width.is_power_of_two() {
        return Err(GlError::InvalidValue);
    }
    Ok(width <= MAX_COLOR_TABLE_WIDTH)
}
