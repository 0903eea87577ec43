//! Point, line and polygon rasterization state (§3.3-3.5, table 6.13) that vertex processing
//! does not read: stored, validated and queried. (The polygon state the pipeline reads, cull
//! face mode, front face and polygon mode, is in `RasterState`; GL_CULL_FACE in `Enables`.)

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// The largest point size and line width (GL_POINT_SIZE_RANGE, GL_LINE_WIDTH_RANGE): there is
/// no rasterizer, so any size is as good as any other.
pub const MAX_POINT_SIZE: f32 = 1024.0;

/// The point attribute group (GL_POINT_BIT, §3.3).
#[derive(Clone, Debug, PartialEq)]
pub struct PointAttribs {
    /// GL_POINT_SMOOTH.
    pub smooth: bool,
    /// GL_POINT_SIZE.
    pub size: f32,
    /// GL_POINT_SIZE_MIN.
    pub size_min: f32,
    /// GL_POINT_SIZE_MAX.
    pub size_max: f32,
    /// GL_POINT_FADE_THRESHOLD_SIZE.
    pub fade_threshold_size: f32,
    /// The constant, linear and quadratic coefficients.
    pub distance_attenuation: [f32; 3],
}

impl Default for PointAttribs {
    fn default() -> PointAttribs {
        PointAttribs {
            smooth: false,
            size: 1.0,
            size_min: 0.0,
            size_max: MAX_POINT_SIZE,
            fade_threshold_size: 1.0,
            distance_attenuation: [1.0, 0.0, 0.0],
        }
    }
}

/// How many values a glPointParameter pname takes, or None for a pname that is none.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::rasterization::point_param_count};
/// assert_eq!(point_param_count(GL_POINT_DISTANCE_ATTENUATION), Some(3));
/// ```
pub fn point_param_count(pname: GLenum) -> Option<usize> {
    match pname {
        GL_POINT_DISTANCE_ATTENUATION => Some(3),
        GL_POINT_SIZE_MIN | GL_POINT_SIZE_MAX | GL_POINT_FADE_THRESHOLD_SIZE => Some(1),
        _ => None,
    }
}

impl PointAttribs {
    /// glPointParameter (§3.3): the pname, then the count, then the value; sizes and the
    /// threshold must not be negative.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::rasterization::PointAttribs};
    /// let mut point = PointAttribs::default();
    /// point.set(GL_POINT_SIZE_MAX, &[8.0])?;
    /// assert_eq!(point.size_max, 8.0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(&mut self, pname: GLenum, params: &[f32]) -> GlResult {
        let count = point_param_count(pname).ok_or(GlError::InvalidEnum)?;
        if params.len() < count {
            return Err(GlError::InvalidValue);
        }
        let value = params[0];
        if count == 1 && (value < 0.0 || value.is_nan()) {
            return Err(GlError::InvalidValue);
        }
        match pname {
            GL_POINT_SIZE_MIN => self.size_min = value,
            GL_POINT_SIZE_MAX => self.size_max = value,
            GL_POINT_FADE_THRESHOLD_SIZE => self.fade_threshold_size = value,
            _ => self.distance_attenuation.copy_from_slice(&params[..3]),
        }
        Ok(())
    }
}

/// A point size or line width: positive (§3.3, §3.4).
///
/// # Examples
///
/// ```
/// use fflight::{state::rasterization::positive_size, GlError};
/// assert_eq!(positive_size(1.5), Ok(1.5));
/// assert_eq!(positive_size(0.0), Err(GlError::InvalidValue));
/// ```
pub fn positive_size(size: f32) -> GlResult<f32> {
    if size > 0.0 {
        Ok(size)
    } else {
        Err(GlError::InvalidValue)
    }
}

/// The line attribute group (GL_LINE_BIT, §3.4).
#[derive(Clone, Debug, PartialEq)]
pub struct LineAttribs {
    /// GL_LINE_SMOOTH.
    pub smooth: bool,
    /// GL_LINE_STIPPLE.
    pub stipple: bool,
    /// GL_LINE_WIDTH.
    pub width: f32,
    /// GL_LINE_STIPPLE_PATTERN.
    pub stipple_pattern: GLushort,
    /// Clamped to [1, 256].
    pub stipple_repeat: GLint,
}

impl Default for LineAttribs {
    fn default() -> LineAttribs {
        LineAttribs {
            smooth: false,
            stipple: false,
            width: 1.0,
            stipple_pattern: 0xFFFF,
            stipple_repeat: 1,
        }
    }
}

/// The polygon attribute group's state that vertex processing does not read (GL_POLYGON_BIT,
/// §3.5): antialiasing, stipple and offset enables, the offset.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonAttribs {
    /// GL_POLYGON_SMOOTH.
    pub smooth: bool,
    /// GL_POLYGON_STIPPLE.
    pub stipple: bool,
    /// GL_POLYGON_OFFSET_POINT.
    pub offset_point: bool,
    /// GL_POLYGON_OFFSET_LINE.
    pub offset_line: bool,
    /// GL_POLYGON_OFFSET_FILL.
    pub offset_fill: bool,
    /// GL_POLYGON_OFFSET_FACTOR.
    pub offset_factor: f32,
    /// GL_POLYGON_OFFSET_UNITS.
    pub offset_units: f32,
}

/// The multisample attribute group (GL_MULTISAMPLE_BIT, §3.2.1, §4.1.3). fflight's framebuffer
/// has no sample buffers (GL_SAMPLE_BUFFERS 0), so none of it has an effect there either.
#[derive(Clone, Debug, PartialEq)]
pub struct MultisampleAttribs {
    /// GL_MULTISAMPLE.
    pub multisample: bool,
    /// GL_SAMPLE_ALPHA_TO_COVERAGE.
    pub sample_alpha_to_coverage: bool,
    /// GL_SAMPLE_ALPHA_TO_ONE.
    pub sample_alpha_to_one: bool,
    /// GL_SAMPLE_COVERAGE.
    pub sample_coverage: bool,
    /// Clamped to [0, 1].
    pub coverage_value: f32,
    /// GL_SAMPLE_COVERAGE_INVERT.
    pub coverage_invert: bool,
}

impl Default for MultisampleAttribs {
    fn default() -> MultisampleAttribs {
        MultisampleAttribs {
            multisample: true,
            sample_alpha_to_coverage: false,
            sample_alpha_to_one: false,
            sample_coverage: false,
            coverage_value: 1.0,
            coverage_invert: false,
        }
    }
}

/// The polygon stipple attribute group (GL_POLYGON_STIPPLE_BIT, §3.5.2): 32 rows of 32 bits,
/// the first (leftmost) pixel of a row in the most significant bit.
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonStippleAttribs {
    /// The rows, in the order glPolygonStipple unpacks them.
    pub rows: [u32; 32],
}

impl Default for PolygonStippleAttribs {
    fn default() -> PolygonStippleAttribs {
        PolygonStippleAttribs { rows: [!0; 32] }
    }
}
