//! glSelectBuffer and the name stack: glInitNames, glPushName, glPopName, glLoadName (§5.2).
//! glRenderMode enters and leaves selection mode (commands/feedback.rs).

use crate::context::{Context, RenderMode};
use crate::error::{GlError, GlResult};
use crate::pipeline::select::MAX_NAME_STACK_DEPTH;

impl Context {
    /// glSelectBuffer: `address` is where the C layer will write the hit records. Checks in
    /// Mesa's order: glBegin/glEnd, a negative size, selection mode; then a NULL address with
    /// a positive size is GL_INVALID_VALUE (as glFeedbackBuffer).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.viewport(0, 0, 10, 10)?;
    /// ctx.select_buffer(16, 1)?; // the address only matters to the C layer
    /// ctx.render_mode(GL_SELECT)?;
    /// ctx.init_names()?;
    /// ctx.push_name(42)?;
    /// ctx.begin(GL_POINTS)?;
    /// ctx.vertex(glam::Vec4::new(0.0, 0.0, 0.5, 1.0));
    /// ctx.end()?;
    /// let (hits, finished) = ctx.render_mode(GL_RENDER)?;
    /// let records = finished.unwrap().hit_records;
    /// // One hit: one name, the depth range of the hit (z = 0.5 as unsigned ints), the name.
    /// assert_eq!((hits, records.len(), records[0], records[3]), (1, 4, 1, 42));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn select_buffer(&mut self, size: i32, address: usize) -> GlResult {
        self.outside_begin_end()?;
        if size < 0 {
            return Err(GlError::InvalidValue);
        }
        if self.render_mode == RenderMode::Select {
            return Err(GlError::InvalidOperation);
        }
        if address == 0 && size > 0 {
            return Err(GlError::InvalidValue);
        }
        let selection = &mut self.selection;
        selection.buffer_given = true;
        selection.capacity = size as usize;
        selection.address = address;
        selection.restart();
        Ok(())
    }

    /// Whether a name-stack command acts: outside selection mode they are ignored (§5.2),
    /// between glBegin and glEnd they are GL_INVALID_OPERATION.
    fn name_stack_active(&self) -> GlResult<bool> {
        self.outside_begin_end()?;
        Ok(self.render_mode == RenderMode::Select)
    }

    /// glInitNames: writes the pending hit record and empties the name stack.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.select_buffer(16, 1)?;
    /// ctx.render_mode(GL_SELECT)?;
    /// ctx.push_name(1)?;
    /// ctx.init_names()?;
    /// assert_eq!(ctx.get(GL_NAME_STACK_DEPTH)?.as_ints(), [0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn init_names(&mut self) -> GlResult {
        if self.name_stack_active()? {
            self.selection.write_hit_record();
            self.selection.names.clear();
        }
        Ok(())
    }

    /// glPushName: GL_STACK_OVERFLOW on a full stack. A command in error has no effect
    /// (§2.5), so it writes no hit record either (Mesa writes one before the check).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.push_name(1)?; // outside selection mode: ignored
    /// assert_eq!(ctx.get(GL_NAME_STACK_DEPTH)?.as_ints(), [0]);
    /// ctx.select_buffer(16, 1)?;
    /// ctx.render_mode(GL_SELECT)?;
    /// for name in 0..64 {
    ///     ctx.push_name(name)?;
    /// }
    /// assert_eq!(ctx.push_name(64), Err(GlError::StackOverflow)); // depth 64
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn push_name(&mut self, name: u32) -> GlResult {
        if self.name_stack_active()? {
            if self.selection.names.len() >= MAX_NAME_STACK_DEPTH {
                return Err(GlError::StackOverflow);
            }
            self.selection.write_hit_record();
            self.selection.names.push(name);
        }
        Ok(())
    }

    /// glPopName: GL_STACK_UNDERFLOW on an empty stack, with no hit record written (§2.5).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.select_buffer(16, 1)?;
    /// ctx.render_mode(GL_SELECT)?;
    /// assert_eq!(ctx.pop_name(), Err(GlError::StackUnderflow));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn pop_name(&mut self) -> GlResult {
        if self.name_stack_active()? {
            if self.selection.names.is_empty() {
                return Err(GlError::StackUnderflow);
            }
            self.selection.write_hit_record();
            self.selection.names.pop();
        }
        Ok(())
    }

    /// glLoadName: replaces the top name; GL_INVALID_OPERATION on an empty stack.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.select_buffer(16, 1)?;
    /// ctx.render_mode(GL_SELECT)?;
    /// assert_eq!(ctx.load_name(3), Err(GlError::InvalidOperation)); // the stack is empty
    /// ctx.push_name(1)?;
    /// ctx.load_name(3)?; // replaces the top name
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn load_name(&mut self, name: u32) -> GlResult {
        if self.name_stack_active()? {
            if self.selection.names.is_empty() {
                return Err(GlError::InvalidOperation);
            }
            self.selection.write_hit_record();
            *self.selection.names.last_mut().expect("not empty") = name;
        }
        Ok(())
    }
}
