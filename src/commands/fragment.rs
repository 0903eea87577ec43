//! Per-fragment operations and framebuffer control (§4.1, §4.2): the scissor, alpha, stencil
//! and depth tests, blending, logic op, buffer selection, write masks and clears. Stored for
//! queries; nothing is rasterized. Every command is GL_INVALID_OPERATION between glBegin and
//! glEnd (§2.6.3) and changes nothing on an error.

use glam::Vec4;

use super::query::{StateValue, enumeration, floats, int, normalized};
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::fragment::{
    STENCIL_BITS, blend_destination_factor, blend_equation, blend_source_factor, color_buffer,
    comparison_function, logic_operation, stencil_operation,
};

/// The enable flag of a capability that lives in its attribute group (`$borrow` is `&` or
/// `&mut`), or None: one list for glEnable, glDisable and glIsEnabled.
macro_rules! group_flag {
    ($ctx:ident, $cap:expr, $($borrow:tt)+) => {
        match $cap {
            GL_SCISSOR_TEST => Some($($borrow)+ $ctx.scissor.test),
            GL_ALPHA_TEST => Some($($borrow)+ $ctx.color_buffer.alpha_test),
            GL_STENCIL_TEST => Some($($borrow)+ $ctx.stencil.test),
            GL_DEPTH_TEST => Some($($borrow)+ $ctx.depth.test),
            GL_BLEND => Some($($borrow)+ $ctx.color_buffer.blend),
            GL_DITHER => Some($($borrow)+ $ctx.color_buffer.dither),
            GL_INDEX_LOGIC_OP => Some($($borrow)+ $ctx.color_buffer.index_logic_op),
            GL_COLOR_LOGIC_OP => Some($($borrow)+ $ctx.color_buffer.color_logic_op),
            GL_FOG => Some($($borrow)+ $ctx.fog.enabled),
            GL_COLOR_SUM => Some($($borrow)+ $ctx.fog.color_sum),
            GL_POINT_SMOOTH => Some($($borrow)+ $ctx.point.smooth),
            GL_LINE_SMOOTH => Some($($borrow)+ $ctx.line.smooth),
            GL_LINE_STIPPLE => Some($($borrow)+ $ctx.line.stipple),
            GL_POLYGON_SMOOTH => Some($($borrow)+ $ctx.polygon.smooth),
            GL_POLYGON_STIPPLE => Some($($borrow)+ $ctx.polygon.stipple),
            GL_POLYGON_OFFSET_POINT => Some($($borrow)+ $ctx.polygon.offset_point),
            GL_POLYGON_OFFSET_LINE => Some($($borrow)+ $ctx.polygon.offset_line),
            GL_POLYGON_OFFSET_FILL => Some($($borrow)+ $ctx.polygon.offset_fill),
            GL_MULTISAMPLE => Some($($borrow)+ $ctx.multisample.multisample),
            GL_SAMPLE_ALPHA_TO_COVERAGE => {
                Some($($borrow)+ $ctx.multisample.sample_alpha_to_coverage)
            }
            GL_SAMPLE_ALPHA_TO_ONE => Some($($borrow)+ $ctx.multisample.sample_alpha_to_one),
            GL_SAMPLE_COVERAGE => Some($($borrow)+ $ctx.multisample.sample_coverage),
            GL_COLOR_TABLE..=GL_POST_COLOR_MATRIX_COLOR_TABLE => {
                let index = ($cap - GL_COLOR_TABLE) as usize;
                Some($($borrow)+ $ctx.imaging_modes.tables_enabled[index])
            }
            GL_CONVOLUTION_1D..=GL_SEPARABLE_2D => {
                let index = ($cap - GL_CONVOLUTION_1D) as usize;
                Some($($borrow)+ $ctx.imaging_modes.convolutions_enabled[index])
            }
            GL_HISTOGRAM => Some($($borrow)+ $ctx.imaging_modes.histogram_enabled),
            GL_MINMAX => Some($($borrow)+ $ctx.imaging_modes.minmax_enabled),
            // The active texture unit's.
            GL_TEXTURE_1D | GL_TEXTURE_2D | GL_TEXTURE_3D | GL_TEXTURE_CUBE_MAP => {
                let unit = $ctx.textures.active_unit;
                let target = crate::state::texture::Target::of($cap).expect("a texture target");
                Some($($borrow)+ $ctx.textures.units[unit].enabled[target as usize])
            }
            _ => None,
        }
    };
}

/// An unsigned mask as glGet reports it: clamped to the largest GLint, as Mesa does.
fn unsigned(mask: GLuint) -> StateValue {
    int(mask.min(GLint::MAX as GLuint) as GLint)
}

impl Context {
    /// The enable flag of a rasterization or per-fragment capability, kept in its attribute
    /// group (so glPushAttrib saves it with the group), or None for another capability.
    pub(crate) fn group_flag_mut(&mut self, cap: GLenum) -> Option<&mut bool> {
        group_flag!(self, cap, &mut)
    }

    /// `group_flag_mut`'s value.
    pub(crate) fn group_flag(&self, cap: GLenum) -> Option<bool> {
        group_flag!(self, cap, &).copied()
    }

    /// glScissor (§4.1.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.scissor(1, 2, 30, 40)?;
    /// assert_eq!(ctx.get(GL_SCISSOR_BOX)?.as_ints(), [1, 2, 30, 40]);
    /// assert_eq!(ctx.scissor(0, 0, -1, 1), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn scissor(&mut self, x: GLint, y: GLint, width: GLsizei, height: GLsizei) -> GlResult {
        self.outside_begin_end()?;
        if width < 0 || height < 0 {
            return Err(GlError::InvalidValue);
        }
        self.scissor.scissor_box = [x, y, width, height];
        Ok(())
    }

    /// glAlphaFunc (§4.1.4): the reference is clamped to [0, 1].
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.alpha_func(GL_GREATER, 2.0)?;
    /// assert_eq!(ctx.get(GL_ALPHA_TEST_REF)?.as_floats(), [1.0]); // clamped
    /// assert_eq!(ctx.get(GL_ALPHA_TEST_FUNC)?.as_ints(), [GL_GREATER as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn alpha_func(&mut self, func: GLenum, reference: f32) -> GlResult {
        self.outside_begin_end()?;
        self.color_buffer.alpha_func = comparison_function(func)?;
        self.color_buffer.alpha_ref = reference.clamp(0.0, 1.0);
        Ok(())
    }

    /// glStencilFunc (§4.1.5): the reference is clamped to [0, 2^s - 1].
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.stencil_func(GL_EQUAL, 300, 0x0f)?;
    /// assert_eq!(ctx.get(GL_STENCIL_REF)?.as_ints(), [255]); // 8 stencil bits
    /// assert_eq!(ctx.get(GL_STENCIL_VALUE_MASK)?.as_ints(), [0x0f]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn stencil_func(&mut self, func: GLenum, reference: GLint, mask: GLuint) -> GlResult {
        self.outside_begin_end()?;
        let stencil = &mut self.stencil;
        stencil.func = comparison_function(func)?;
        stencil.reference = reference.clamp(0, (1 << STENCIL_BITS) - 1);
        stencil.value_mask = mask;
        Ok(())
    }

    /// glStencilOp (§4.1.5).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.stencil_op(GL_ZERO, GL_INCR, GL_REPLACE)?;
    /// assert_eq!(ctx.get(GL_STENCIL_PASS_DEPTH_PASS)?.as_ints(), [GL_REPLACE as i32]);
    /// assert_eq!(ctx.stencil_op(GL_ZERO, GL_ZERO, GL_LESS), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn stencil_op(&mut self, fail: GLenum, depth_fail: GLenum, depth_pass: GLenum) -> GlResult {
        self.outside_begin_end()?;
        let fail = stencil_operation(fail)?;
        let depth_fail = stencil_operation(depth_fail)?;
        let depth_pass = stencil_operation(depth_pass)?;
        self.stencil.fail = fail;
        self.stencil.pass_depth_fail = depth_fail;
        self.stencil.pass_depth_pass = depth_pass;
        Ok(())
    }

    /// glDepthFunc (§4.1.6).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.depth_func(GL_LEQUAL)?;
    /// assert_eq!(ctx.get(GL_DEPTH_FUNC)?.as_ints(), [GL_LEQUAL as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn depth_func(&mut self, func: GLenum) -> GlResult {
        self.outside_begin_end()?;
        self.depth.func = comparison_function(func)?;
        Ok(())
    }

    /// glBlendFunc (§4.1.8): the same factors for RGB and alpha.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)?;
    /// assert_eq!(ctx.get(GL_BLEND_SRC_ALPHA)?.as_ints(), [GL_SRC_ALPHA as i32]);
    /// assert_eq!(ctx.get(GL_BLEND_DST_RGB)?.as_ints(), [GL_ONE_MINUS_SRC_ALPHA as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn blend_func(&mut self, source: GLenum, destination: GLenum) -> GlResult {
        self.blend_func_separate(source, destination, source, destination)
    }

    /// glBlendFuncSeparate (§4.1.8): sources, then destinations, in argument order.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.blend_func_separate(GL_ONE, GL_ZERO, GL_SRC_ALPHA, GL_DST_ALPHA)?;
    /// assert_eq!(ctx.get(GL_BLEND_DST_ALPHA)?.as_ints(), [GL_DST_ALPHA as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn blend_func_separate(
        &mut self,
        source_rgb: GLenum,
        destination_rgb: GLenum,
        source_alpha: GLenum,
        destination_alpha: GLenum,
    ) -> GlResult {
        self.outside_begin_end()?;
        let source_rgb = blend_source_factor(source_rgb)?;
        let destination_rgb = blend_destination_factor(destination_rgb)?;
        let source_alpha = blend_source_factor(source_alpha)?;
        let destination_alpha = blend_destination_factor(destination_alpha)?;
        let color = &mut self.color_buffer;
        color.blend_src_rgb = source_rgb;
        color.blend_dst_rgb = destination_rgb;
        color.blend_src_alpha = source_alpha;
        color.blend_dst_alpha = destination_alpha;
        Ok(())
    }

    /// glBlendColor (§4.1.8): clamped to [0, 1].
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.blend_color(glam::Vec4::new(2.0, 0.5, -1.0, 1.0))?;
    /// assert_eq!(ctx.get(GL_BLEND_COLOR)?.as_floats(), [1.0, 0.5, 0.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn blend_color(&mut self, color: Vec4) -> GlResult {
        self.outside_begin_end()?;
        self.color_buffer.blend_color = color.clamp(Vec4::ZERO, Vec4::ONE);
        Ok(())
    }

    /// glBlendEquation (§4.1.8).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.blend_equation(GL_FUNC_SUBTRACT)?;
    /// assert_eq!(ctx.get(GL_BLEND_EQUATION)?.as_ints(), [GL_FUNC_SUBTRACT as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn blend_equation(&mut self, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        self.color_buffer.blend_equation = blend_equation(mode)?;
        Ok(())
    }

    /// glLogicOp (§4.1.10).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.logic_op(GL_XOR)?;
    /// assert_eq!(ctx.get(GL_LOGIC_OP_MODE)?.as_ints(), [GL_XOR as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn logic_op(&mut self, opcode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        self.color_buffer.logic_op_mode = logic_operation(opcode)?;
        Ok(())
    }

    /// glDrawBuffer (§4.2.1).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.draw_buffer(GL_FRONT)?;
    /// assert_eq!(ctx.get(GL_DRAW_BUFFER)?.as_ints(), [GL_FRONT as i32]);
    /// assert_eq!(ctx.draw_buffer(GL_LIGHT0), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn draw_buffer(&mut self, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        self.color_buffer.draw_buffer = color_buffer(mode, false)?;
        Ok(())
    }

    /// glReadBuffer (§4.3.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.read_buffer(GL_FRONT_LEFT)?;
    /// assert_eq!(ctx.get(GL_READ_BUFFER)?.as_ints(), [GL_FRONT_LEFT as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn read_buffer(&mut self, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        self.pixel_mode.read_buffer = color_buffer(mode, true)?;
        Ok(())
    }

    /// glIndexMask (§4.2.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.index_mask(0xff)?;
    /// assert_eq!(ctx.get(GL_INDEX_WRITEMASK)?.as_ints(), [0xff]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn index_mask(&mut self, mask: GLuint) -> GlResult {
        self.outside_begin_end()?;
        self.color_buffer.index_write_mask = mask;
        Ok(())
    }

    /// glColorMask (§4.2.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.color_mask([true, false, true, false])?;
    /// assert_eq!(ctx.get(GL_COLOR_WRITEMASK)?.as_bools(), [true, false, true, false]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn color_mask(&mut self, mask: [bool; 4]) -> GlResult {
        self.outside_begin_end()?;
        self.color_buffer.color_write_mask = mask;
        Ok(())
    }

    /// glDepthMask (§4.2.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.depth_mask(false)?;
    /// assert_eq!(ctx.get(GL_DEPTH_WRITEMASK)?.as_bools(), [false]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn depth_mask(&mut self, mask: bool) -> GlResult {
        self.outside_begin_end()?;
        self.depth.write_mask = mask;
        Ok(())
    }

    /// glStencilMask (§4.2.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.stencil_mask(0x3)?;
    /// assert_eq!(ctx.get(GL_STENCIL_WRITEMASK)?.as_ints(), [0x3]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn stencil_mask(&mut self, mask: GLuint) -> GlResult {
        self.outside_begin_end()?;
        self.stencil.write_mask = mask;
        Ok(())
    }

    /// glClear (§4.2.3): fflight has no framebuffer, so only the mask is checked.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT)?;
    /// assert_eq!(ctx.clear(0x1), Err(GlError::InvalidValue)); // a bit naming no buffer
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn clear(&mut self, mask: GLbitfield) -> GlResult {
        self.outside_begin_end()?;
        let buffers =
            GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
        if mask & !buffers != 0 {
            return Err(GlError::InvalidValue);
        }
        Ok(())
    }

    /// glClearColor (§4.2.3): clamped to [0, 1].
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.clear_color(glam::Vec4::new(0.1, 0.2, 0.3, 2.0))?;
    /// assert_eq!(ctx.get(GL_COLOR_CLEAR_VALUE)?.as_floats(), [0.1, 0.2, 0.3, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn clear_color(&mut self, color: Vec4) -> GlResult {
        self.outside_begin_end()?;
        self.color_buffer.clear_color = color.clamp(Vec4::ZERO, Vec4::ONE);
        Ok(())
    }

    /// glClearIndex (§4.2.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.clear_index(4.0)?;
    /// assert_eq!(ctx.get(GL_INDEX_CLEAR_VALUE)?.as_floats(), [4.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn clear_index(&mut self, index: f32) -> GlResult {
        self.outside_begin_end()?;
        self.color_buffer.clear_index = index;
        Ok(())
    }

    /// glClearDepth (§4.2.3): clamped to [0, 1].
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.clear_depth(2.0)?;
    /// assert_eq!(ctx.get(GL_DEPTH_CLEAR_VALUE)?.as_doubles(), [1.0]); // clamped
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn clear_depth(&mut self, depth: f64) -> GlResult {
        self.outside_begin_end()?;
        self.depth.clear_value = depth.clamp(0.0, 1.0);
        Ok(())
    }

    /// glClearStencil (§4.2.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.clear_stencil(5)?;
    /// assert_eq!(ctx.get(GL_STENCIL_CLEAR_VALUE)?.as_ints(), [5]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn clear_stencil(&mut self, stencil: GLint) -> GlResult {
        self.outside_begin_end()?;
        self.stencil.clear_value = stencil;
        Ok(())
    }

    /// glClearAccum (§4.2.3): clamped to [-1, 1].
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.clear_accum(glam::Vec4::new(-2.0, 0.5, 0.0, 3.0))?;
    /// assert_eq!(ctx.get(GL_ACCUM_CLEAR_VALUE)?.as_floats(), [-1.0, 0.5, 0.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn clear_accum(&mut self, color: Vec4) -> GlResult {
        self.outside_begin_end()?;
        self.accum.clear_value = color.clamp(Vec4::NEG_ONE, Vec4::ONE);
        Ok(())
    }

    /// glAccum (§4.2.4): fflight's framebuffer has no accumulation buffer (GL_ACCUM_*_BITS 0),
    /// so a valid operation is GL_INVALID_OPERATION; the operation is checked first, as Mesa
    /// does.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.accum(GL_ACCUM, 1.0), Err(GlError::InvalidOperation)); // no accumulation buffer
    /// assert_eq!(ctx.accum(GL_LIGHT0, 1.0), Err(GlError::InvalidEnum));
    /// ```
    pub fn accum(&mut self, op: GLenum, _value: f32) -> GlResult {
        self.outside_begin_end()?;
        if !(GL_ACCUM..=GL_ADD).contains(&op) {
            return Err(GlError::InvalidEnum);
        }
        Err(GlError::InvalidOperation)
    }

    /// The per-fragment and framebuffer-control values of glGet (tables 6.19, 6.20), or None
    /// for a pname that is not theirs.
    pub(crate) fn get_fragment_state(&self, pname: GLenum) -> Option<StateValue> {
        let color = &self.color_buffer;
        let stencil = &self.stencil;
        Some(match pname {
            GL_SCISSOR_BOX => StateValue::Ints(self.scissor.scissor_box.to_vec()),
            GL_ALPHA_TEST_FUNC => enumeration(color.alpha_func),
            GL_ALPHA_TEST_REF => normalized(&[color.alpha_ref]),
            GL_STENCIL_FUNC => enumeration(stencil.func),
            GL_STENCIL_VALUE_MASK => unsigned(stencil.value_mask),
            GL_STENCIL_REF => int(stencil.reference),
            GL_STENCIL_FAIL => enumeration(stencil.fail),
            GL_STENCIL_PASS_DEPTH_FAIL => enumeration(stencil.pass_depth_fail),
            GL_STENCIL_PASS_DEPTH_PASS => enumeration(stencil.pass_depth_pass),
            GL_STENCIL_WRITEMASK => unsigned(stencil.write_mask),
            GL_STENCIL_CLEAR_VALUE => int(stencil.clear_value),
            GL_STENCIL_BITS => int(STENCIL_BITS as GLint),
            GL_DEPTH_FUNC => enumeration(self.depth.func),
            GL_DEPTH_WRITEMASK => StateValue::Bools(vec![self.depth.write_mask]),
            GL_DEPTH_CLEAR_VALUE => StateValue::Normalized(vec![self.depth.clear_value]),
            // GL 1.3's names of the RGB factors.
            GL_BLEND_SRC | GL_BLEND_SRC_RGB => enumeration(color.blend_src_rgb),
            GL_BLEND_DST | GL_BLEND_DST_RGB => enumeration(color.blend_dst_rgb),
            GL_BLEND_SRC_ALPHA => enumeration(color.blend_src_alpha),
            GL_BLEND_DST_ALPHA => enumeration(color.blend_dst_alpha),
            GL_BLEND_EQUATION => enumeration(color.blend_equation),
            GL_BLEND_COLOR => normalized(&color.blend_color.to_array()),
            GL_LOGIC_OP_MODE => enumeration(color.logic_op_mode),
            GL_DRAW_BUFFER => enumeration(color.draw_buffer),
            GL_READ_BUFFER => enumeration(self.pixel_mode.read_buffer),
            // All its bits, as Mesa reports it (unlike the stencil masks).
            GL_INDEX_WRITEMASK => int(color.index_write_mask as GLint),
            GL_COLOR_WRITEMASK => StateValue::Bools(color.color_write_mask.to_vec()),
            GL_COLOR_CLEAR_VALUE => normalized(&color.clear_color.to_array()),
            GL_INDEX_CLEAR_VALUE => floats(&[color.clear_index]),
            GL_ACCUM_CLEAR_VALUE => normalized(&self.accum.clear_value.to_array()),
            GL_AUX_BUFFERS | GL_ACCUM_RED_BITS | GL_ACCUM_GREEN_BITS | GL_ACCUM_BLUE_BITS
            | GL_ACCUM_ALPHA_BITS => int(0),
            GL_DOUBLEBUFFER | GL_STEREO => StateValue::Bools(vec![false]),
            _ => return None,
        })
    }
}
