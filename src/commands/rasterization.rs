//! Point, line and polygon rasterization state, fog and hints (§3.3-3.5, §3.10, §5.6): stored
//! for queries; nothing is rasterized. Every command is GL_INVALID_OPERATION between glBegin
//! and glEnd (§2.6.3) and changes nothing on an error.

use super::query::{StateValue, enumeration, floats, int, normalized};
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::convert::int_params;
use crate::state::fog::fog_param_count;
use crate::state::pixel::{pack_stipple, unpack_stipple};
use crate::state::rasterization::{MAX_POINT_SIZE, point_param_count, positive_size};

/// The scalar forms (glFogf, glPointParameteri, ...) take only single-valued pnames: another
/// known pname is GL_INVALID_ENUM, as an unknown one is.
fn scalar(count: Option<usize>) -> GlResult {
    match count {
        Some(1) => Ok(()),
        _ => Err(GlError::InvalidEnum),
    }
}

impl Context {
    /// glPointSize (§3.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.point_size(4.0)?;
    /// assert_eq!(ctx.get(GL_POINT_SIZE)?.as_floats(), [4.0]);
    /// assert_eq!(ctx.point_size(0.0), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn point_size(&mut self, size: f32) -> GlResult {
        self.outside_begin_end()?;
        self.point.size = positive_size(size)?;
        Ok(())
    }

    /// glPointParameterfv (§3.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.point_parameter(GL_POINT_DISTANCE_ATTENUATION, &[1.0, 0.5, 0.25])?;
    /// assert_eq!(ctx.get(GL_POINT_DISTANCE_ATTENUATION)?.as_floats(), [1.0, 0.5, 0.25]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn point_parameter(&mut self, pname: GLenum, params: &[f32]) -> GlResult {
        self.outside_begin_end()?;
        self.point.set(pname, params)
    }

    /// glPointParameteriv: the integers converted directly.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.point_parameter_i(GL_POINT_SIZE_MIN, &[2])?;
    /// assert_eq!(ctx.get(GL_POINT_SIZE_MIN)?.as_floats(), [2.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn point_parameter_i(&mut self, pname: GLenum, params: &[GLint]) -> GlResult {
        let floats: Vec<f32> = params.iter().map(|&p| p as f32).collect();
        self.point_parameter(pname, &floats)
    }

    /// glPointParameterf / glPointParameteri.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.point_parameter_scalar(GL_POINT_FADE_THRESHOLD_SIZE, 2.0)?;
    /// assert_eq!(ctx.point_parameter_scalar(GL_POINT_SIZE_MIN, -1.0), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn point_parameter_scalar(&mut self, pname: GLenum, param: f32) -> GlResult {
        self.outside_begin_end()?;
        scalar(point_param_count(pname))?;
        self.point.set(pname, &[param])
    }

    /// glLineWidth (§3.4).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.line_width(2.5)?;
    /// assert_eq!(ctx.get(GL_LINE_WIDTH)?.as_floats(), [2.5]);
    /// assert_eq!(ctx.line_width(-1.0), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn line_width(&mut self, width: f32) -> GlResult {
        self.outside_begin_end()?;
        self.line.width = positive_size(width)?;
        Ok(())
    }

    /// glLineStipple (§3.4.2): the repeat factor is clamped to [1, 256].
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.line_stipple(0, 0xaaaa)?;
    /// assert_eq!(ctx.get(GL_LINE_STIPPLE_REPEAT)?.as_ints(), [1]); // clamped to [1, 256]
    /// assert_eq!(ctx.get(GL_LINE_STIPPLE_PATTERN)?.as_ints(), [0xaaaa]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn line_stipple(&mut self, factor: GLint, pattern: GLushort) -> GlResult {
        self.outside_begin_end()?;
        self.line.stipple_repeat = factor.clamp(1, 256);
        self.line.stipple_pattern = pattern;
        Ok(())
    }

    /// glPolygonOffset (§3.5.5).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.polygon_offset(1.0, 2.0)?;
    /// assert_eq!(ctx.get(GL_POLYGON_OFFSET_UNITS)?.as_floats(), [2.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn polygon_offset(&mut self, factor: f32, units: f32) -> GlResult {
        self.outside_begin_end()?;
        self.polygon.offset_factor = factor;
        self.polygon.offset_units = units;
        Ok(())
    }

    /// How many bytes glPolygonStipple reads under the current unpack modes.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::Context;
    /// // 32 rows of 4 bytes under the initial unpack modes.
    /// assert_eq!(Context::new().polygon_stipple_unpack_span(), 128);
    /// ```
    pub fn polygon_stipple_unpack_span(&self) -> usize {
        crate::state::pixel::stipple_unpack_span(&self.pixel_store.unpack)
    }

    /// How many bytes glGetPolygonStipple writes into under the current pack modes.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::Context;
    /// assert_eq!(Context::new().polygon_stipple_pack_span(), 128);
    /// ```
    pub fn polygon_stipple_pack_span(&self) -> usize {
        crate::state::pixel::stipple_pack_span(&self.pixel_store.pack)
    }

    /// glPolygonStipple (§3.5.2): a 32 x 32 bitmap unpacked with the unpack modes (§3.6.4).
    /// Too few bytes (a NULL pointer) is GL_INVALID_VALUE.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{Context, GlError};
    /// let mut ctx = Context::new();
    /// let pattern: Vec<u8> = (0..128).map(|i| if i % 8 < 4 { 0xf0 } else { 0x0f }).collect();
    /// ctx.polygon_stipple(&pattern)?;
    /// let mut back = [0u8; 128];
    /// ctx.get_polygon_stipple(&mut back)?;
    /// assert_eq!(back.to_vec(), pattern);
    /// assert_eq!(ctx.polygon_stipple(&pattern[..10]), Err(GlError::InvalidValue)); // too few bytes
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn polygon_stipple(&mut self, bytes: &[u8]) -> GlResult {
        self.outside_begin_end()?;
        self.polygon_stipple.rows = unpack_stipple(&self.pixel_store.unpack, bytes)?;
        Ok(())
    }

    /// glGetPolygonStipple (§6.1.6): packed into `bytes` with the pack modes (§4.3.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::Context;
    /// let ctx = Context::new();
    /// let mut bytes = [0u8; 128];
    /// ctx.get_polygon_stipple(&mut bytes)?;
    /// assert!(bytes.iter().all(|&b| b == 0xff)); // initially all ones
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_polygon_stipple(&self, bytes: &mut [u8]) -> GlResult {
        self.outside_begin_end()?;
        pack_stipple(&self.pixel_store.pack, &self.polygon_stipple.rows, bytes)
    }

    /// glFogfv (§3.10).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.fog(GL_FOG_COLOR, &[0.5, 0.5, 0.5, 1.0])?;
    /// assert_eq!(ctx.get(GL_FOG_COLOR)?.as_floats(), [0.5, 0.5, 0.5, 1.0]);
    /// assert_eq!(ctx.fog(GL_FOG_DENSITY, &[-1.0]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn fog(&mut self, pname: GLenum, params: &[f32]) -> GlResult {
        self.outside_begin_end()?;
        self.fog.set(pname, params)
    }

    /// glFogiv: the color mapped linearly to [-1, 1] (table 2.9) before clamping, other values
    /// converted directly.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.fog_i(GL_FOG_MODE, &[GL_LINEAR as i32])?;
    /// ctx.fog_i(GL_FOG_END, &[10])?;
    /// assert_eq!(ctx.get(GL_FOG_END)?.as_floats(), [10.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn fog_i(&mut self, pname: GLenum, params: &[GLint]) -> GlResult {
        self.fog(pname, &int_params(params, pname == GL_FOG_COLOR))
    }

    /// glFogf / glFogi.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.fog_scalar(GL_FOG_START, 2.0)?;
    /// assert_eq!(ctx.fog_scalar(GL_FOG_COLOR, 1.0), Err(GlError::InvalidEnum)); // a vector
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn fog_scalar(&mut self, pname: GLenum, param: f32) -> GlResult {
        self.outside_begin_end()?;
        scalar(fog_param_count(pname))?;
        self.fog.set(pname, &[param])
    }

    /// glSampleCoverage (§4.1.3): the value is clamped to [0, 1].
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.sample_coverage(2.0, true)?;
    /// assert_eq!(ctx.get(GL_SAMPLE_COVERAGE_VALUE)?.as_floats(), [1.0]);
    /// assert_eq!(ctx.get(GL_SAMPLE_COVERAGE_INVERT)?.as_bools(), [true]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn sample_coverage(&mut self, value: f32, invert: bool) -> GlResult {
        self.outside_begin_end()?;
        self.multisample.coverage_value = value.clamp(0.0, 1.0);
        self.multisample.coverage_invert = invert;
        Ok(())
    }

    /// glHint (§5.6).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.hint(GL_FOG_HINT, GL_NICEST)?;
    /// assert_eq!(ctx.get(GL_FOG_HINT)?.as_ints(), [GL_NICEST as i32]);
    /// assert_eq!(ctx.hint(GL_FOG_HINT, GL_LIGHT0), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn hint(&mut self, target: GLenum, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        self.hints.set(target, mode)
    }

    /// The point, line, polygon, fog and hint values of glGet (tables 6.10, 6.13, 6.27), or
    /// None for a pname that is not theirs.
    pub(crate) fn get_rasterization_state(&self, pname: GLenum) -> Option<StateValue> {
        if let Some(mode) = self.hints.get(pname) {
            return Some(enumeration(mode));
        }
        let (point, fog) = (&self.point, &self.fog);
        Some(match pname {
            GL_POINT_SIZE => floats(&[point.size]),
            GL_POINT_SIZE_MIN => floats(&[point.size_min]),
            GL_POINT_SIZE_MAX => floats(&[point.size_max]),
            GL_POINT_FADE_THRESHOLD_SIZE => floats(&[point.fade_threshold_size]),
            GL_POINT_DISTANCE_ATTENUATION => floats(&point.distance_attenuation),
            // Points and lines are not rasterized: any size is as good as any other.
            GL_POINT_SIZE_RANGE | GL_LINE_WIDTH_RANGE => floats(&[1.0, MAX_POINT_SIZE]),
            GL_LINE_WIDTH => floats(&[self.line.width]),
            GL_LINE_STIPPLE_PATTERN => int(self.line.stipple_pattern.into()),
            GL_LINE_STIPPLE_REPEAT => int(self.line.stipple_repeat),
            GL_POLYGON_OFFSET_FACTOR => floats(&[self.polygon.offset_factor]),
            GL_POLYGON_OFFSET_UNITS => floats(&[self.polygon.offset_units]),
            GL_SAMPLE_COVERAGE_VALUE => floats(&[self.multisample.coverage_value]),
            GL_SAMPLE_COVERAGE_INVERT => StateValue::Bools(vec![self.multisample.coverage_invert]),
            GL_SAMPLE_BUFFERS | GL_SAMPLES => int(0),
            GL_FOG_COLOR => normalized(&fog.color.to_array()),
            GL_FOG_INDEX => floats(&[fog.index]),
            GL_FOG_DENSITY => floats(&[fog.density]),
            GL_FOG_START => floats(&[fog.start]),
            GL_FOG_END => floats(&[fog.end]),
            GL_FOG_MODE => enumeration(fog.mode),
            GL_FOG_COORD_SRC => enumeration(fog.coord_src),
            _ => return None,
        })
    }
}
