//! Per-fragment operations and framebuffer control (§4.1, §4.2; tables 6.19 and 6.20): stored,
//! validated and queried, with no effect on vertex processing (there is no rasterizer).
//!
//! One struct per attribute group of the state tables, holding the group's enable flags too, so
//! that glPushAttrib can save and restore a group as one clone.

use glam::Vec4;

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// The stencil bits of the framebuffer fflight describes (GL_STENCIL_BITS): the reference value
/// is clamped to [0, 2^8 - 1] (§4.1.5).
pub const STENCIL_BITS: u32 = 8;

/// The scissor attribute group (GL_SCISSOR_BIT, §4.1.2).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ScissorAttribs {
    /// GL_SCISSOR_TEST.
    pub test: bool,
    /// x, y, width, height. GL starts it at the window's size; with no window, (0, 0, 0, 0),
    /// as the viewport.
    pub scissor_box: [i32; 4],
}

/// The depth-buffer attribute group (GL_DEPTH_BUFFER_BIT, §4.1.6, §4.2.2, §4.2.3).
#[derive(Clone, Debug, PartialEq)]
pub struct DepthBufferAttribs {
    /// GL_DEPTH_TEST.
    pub test: bool,
    /// GL_DEPTH_FUNC.
    pub func: GLenum,
    /// Clamped to [0, 1].
    pub clear_value: f64,
    /// GL_DEPTH_WRITEMASK.
    pub write_mask: bool,
}

impl Default for DepthBufferAttribs {
    fn default() -> DepthBufferAttribs {
        DepthBufferAttribs {
            test: false,
            func: GL_LESS,
            clear_value: 1.0,
            write_mask: true,
        }
    }
}

/// The stencil-buffer attribute group (GL_STENCIL_BUFFER_BIT, §4.1.5, §4.2.2, §4.2.3).
#[derive(Clone, Debug, PartialEq)]
pub struct StencilBufferAttribs {
    /// GL_STENCIL_TEST.
    pub test: bool,
    /// GL_STENCIL_FUNC.
    pub func: GLenum,
    /// GL_STENCIL_VALUE_MASK.
    pub value_mask: GLuint,
    /// Clamped to [0, 2^STENCIL_BITS - 1].
    pub reference: GLint,
    /// GL_STENCIL_FAIL.
    pub fail: GLenum,
    /// GL_STENCIL_PASS_DEPTH_FAIL.
    pub pass_depth_fail: GLenum,
    /// GL_STENCIL_PASS_DEPTH_PASS.
    pub pass_depth_pass: GLenum,
    /// GL_STENCIL_CLEAR_VALUE.
    pub clear_value: GLint,
    /// GL_STENCIL_WRITEMASK.
    pub write_mask: GLuint,
}

impl Default for StencilBufferAttribs {
    fn default() -> StencilBufferAttribs {
        StencilBufferAttribs {
            test: false,
            func: GL_ALWAYS,
            // "1's": every stencil bit, as Mesa has them.
            value_mask: (1 << STENCIL_BITS) - 1,
            reference: 0,
            fail: GL_KEEP,
            pass_depth_fail: GL_KEEP,
            pass_depth_pass: GL_KEEP,
            clear_value: 0,
            write_mask: (1 << STENCIL_BITS) - 1,
        }
    }
}

/// The color-buffer attribute group (GL_COLOR_BUFFER_BIT: alpha test, blending, dithering,
/// logic op, draw buffer, write masks and clear values; §4.1.4, §4.1.8-4.1.10, §4.2).
#[derive(Clone, Debug, PartialEq)]
pub struct ColorBufferAttribs {
    /// GL_ALPHA_TEST.
    pub alpha_test: bool,
    /// GL_ALPHA_TEST_FUNC.
    pub alpha_func: GLenum,
    /// Clamped to [0, 1].
    pub alpha_ref: f32,
    /// GL_BLEND.
    pub blend: bool,
    /// GL_BLEND_SRC_RGB.
    pub blend_src_rgb: GLenum,
    /// GL_BLEND_SRC_ALPHA.
    pub blend_src_alpha: GLenum,
    /// GL_BLEND_DST_RGB.
    pub blend_dst_rgb: GLenum,
    /// GL_BLEND_DST_ALPHA.
    pub blend_dst_alpha: GLenum,
    /// GL_BLEND_EQUATION.
    pub blend_equation: GLenum,
    /// Clamped to [0, 1].
    pub blend_color: Vec4,
    /// GL_DITHER.
    pub dither: bool,
    /// GL_INDEX_LOGIC_OP.
    pub index_logic_op: bool,
    /// GL_COLOR_LOGIC_OP.
    pub color_logic_op: bool,
    /// GL_LOGIC_OP_MODE.
    pub logic_op_mode: GLenum,
    /// GL_DRAW_BUFFER.
    pub draw_buffer: GLenum,
    /// GL_INDEX_WRITEMASK.
    pub index_write_mask: GLuint,
    /// Red, green, blue, alpha.
    pub color_write_mask: [bool; 4],
    /// Clamped to [0, 1].
    pub clear_color: Vec4,
    /// GL_INDEX_CLEAR_VALUE.
    pub clear_index: f32,
}

impl Default for ColorBufferAttribs {
    fn default() -> ColorBufferAttribs {
        ColorBufferAttribs {
            alpha_test: false,
            alpha_func: GL_ALWAYS,
            alpha_ref: 0.0,
            blend: false,
            blend_src_rgb: GL_ONE,
            blend_src_alpha: GL_ONE,
            blend_dst_rgb: GL_ZERO,
            blend_dst_alpha: GL_ZERO,
            blend_equation: GL_FUNC_ADD,
            blend_color: Vec4::ZERO,
            dither: true,
            index_logic_op: false,
            color_logic_op: false,
            logic_op_mode: GL_COPY,
            // Single-buffered (§4.2.1: FRONT when there is no back buffer).
            draw_buffer: GL_FRONT,
            index_write_mask: !0,
            color_write_mask: [true; 4],
            clear_color: Vec4::ZERO,
            clear_index: 0.0,
        }
    }
}

/// The accumulation-buffer attribute group (GL_ACCUM_BUFFER_BIT, §4.2.3).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AccumBufferAttribs {
    /// Clamped to [-1, 1].
    pub clear_value: Vec4,
}

/// The comparison functions of the alpha, stencil and depth tests (§4.1.4-4.1.6).
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::fragment::comparison_function, GlError};
/// assert_eq!(comparison_function(GL_GEQUAL), Ok(GL_GEQUAL));
/// assert_eq!(comparison_function(GL_ZERO), Err(GlError::InvalidEnum));
/// ```
pub fn comparison_function(func: GLenum) -> GlResult<GLenum> {
    match func {
        GL_NEVER..=GL_ALWAYS => Ok(func),
        _ => Err(GlError::InvalidEnum),
    }
}

/// The stencil operations (§4.1.5, with GL 1.4's wrapping ones).
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::fragment::stencil_operation};
/// assert!(stencil_operation(GL_INCR_WRAP).is_ok() && stencil_operation(GL_NEVER).is_err());
/// ```
pub fn stencil_operation(op: GLenum) -> GlResult<GLenum> {
    match op {
        GL_KEEP | GL_ZERO | GL_REPLACE | GL_INCR | GL_DECR | GL_INVERT | GL_INCR_WRAP
        | GL_DECR_WRAP => Ok(op),
        _ => Err(GlError::InvalidEnum),
    }
}

/// The blending factors both sides take (tables 4.1 and 4.2).
fn blend_factor(factor: GLenum) -> bool {
    matches!(
        factor,
        GL_ZERO
            | GL_ONE
            | GL_SRC_COLOR
            | GL_ONE_MINUS_SRC_COLOR
            | GL_DST_COLOR
            | GL_ONE_MINUS_DST_COLOR
            | GL_SRC_ALPHA
            | GL_ONE_MINUS_SRC_ALPHA
            | GL_DST_ALPHA
            | GL_ONE_MINUS_DST_ALPHA
            | GL_CONSTANT_COLOR
            | GL_ONE_MINUS_CONSTANT_COLOR
            | GL_CONSTANT_ALPHA
            | GL_ONE_MINUS_CONSTANT_ALPHA
    )
}

/// A source blending factor (table 4.1): any factor, and SRC_ALPHA_SATURATE.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::fragment::blend_source_factor};
/// assert!(blend_source_factor(GL_SRC_ALPHA_SATURATE).is_ok());
/// ```
pub fn blend_source_factor(factor: GLenum) -> GlResult<GLenum> {
    if blend_factor(factor) || factor == GL_SRC_ALPHA_SATURATE {
        Ok(factor)
    } else {
        Err(GlError::InvalidEnum)
    }
}

/// A destination blending factor (table 4.2): SRC_ALPHA_SATURATE is for the source only.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::fragment::blend_destination_factor, GlError};
/// assert_eq!(blend_destination_factor(GL_SRC_ALPHA_SATURATE), Err(GlError::InvalidEnum));
/// ```
pub fn blend_destination_factor(factor: GLenum) -> GlResult<GLenum> {
    if blend_factor(factor) {
        Ok(factor)
    } else {
        Err(GlError::InvalidEnum)
    }
}

/// The blend equations (§4.1.8).
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::fragment::blend_equation};
/// assert!(blend_equation(GL_MAX).is_ok() && blend_equation(GL_ADD).is_err());
/// ```
pub fn blend_equation(mode: GLenum) -> GlResult<GLenum> {
    match mode {
        GL_FUNC_ADD | GL_FUNC_SUBTRACT | GL_FUNC_REVERSE_SUBTRACT | GL_MIN | GL_MAX => Ok(mode),
        _ => Err(GlError::InvalidEnum),
    }
}

/// The sixteen logic operations (table 4.3).
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::fragment::logic_operation};
/// assert!(logic_operation(GL_NAND).is_ok() && logic_operation(GL_AND + 16).is_err());
/// ```
pub fn logic_operation(opcode: GLenum) -> GlResult<GLenum> {
    match opcode {
        GL_CLEAR..=GL_SET => Ok(opcode),
        _ => Err(GlError::InvalidEnum),
    }
}

/// Which buffers a glDrawBuffer or glReadBuffer mode names, of the framebuffer fflight
/// describes: single-buffered, monoscopic, no auxiliary buffers (GL_DOUBLEBUFFER and GL_STEREO
/// false, GL_AUX_BUFFERS 0). `Err(InvalidEnum)` for a name that is no buffer (§4.2.1),
/// `Err(InvalidOperation)` for buffers that do not exist here (every one the mode names).
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::fragment::color_buffer, GlError};
/// assert_eq!(color_buffer(GL_FRONT, false), Ok(GL_FRONT));
/// // Single-buffered, no auxiliary buffers.
/// assert_eq!(color_buffer(GL_AUX0, false), Err(GlError::InvalidOperation));
/// ```
pub fn color_buffer(mode: GLenum, for_reading: bool) -> GlResult<GLenum> {
    match mode {
        GL_FRONT | GL_LEFT | GL_FRONT_LEFT => Ok(mode),
        GL_NONE if !for_reading => Ok(mode),
        GL_FRONT_AND_BACK if !for_reading => Ok(mode),
        GL_FRONT_RIGHT | GL_BACK_LEFT | GL_BACK_RIGHT | GL_BACK | GL_RIGHT => {
            Err(GlError::InvalidOperation)
        }
        _ if (GL_AUX0..=GL_AUX3).contains(&mode) => Err(GlError::InvalidOperation),
        _ => Err(GlError::InvalidEnum),
    }
}
