//! Viewport, depth range, glFeedbackBuffer, glRenderMode and glPassThrough (§2.11.1, §5.2,
//! §5.3).

use crate::context::{Context, RenderMode};
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::pipeline::feedback::{FeedbackLayout, FeedbackStorage};
use crate::state::raster::MAX_VIEWPORT_DIMS;

/// What glRenderMode hands the C layer when feedback or selection ends: the values to write
/// to the address glFeedbackBuffer or glSelectBuffer was given.
#[derive(Debug, Default, PartialEq)]
pub struct FinishedFeedback {
    /// Where the application asked the values to go (glFeedbackBuffer's or glSelectBuffer's pointer); the Rust API ignores it.
    pub address: usize,
    /// Feedback: the values fed back.
    pub values: Vec<f32>,
    /// Selection: the hit records (`values` is then empty).
    pub hit_records: Vec<u32>,
}

impl Context {
    /// glViewport: width and height are clamped to GL_MAX_VIEWPORT_DIMS.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.viewport(10, 20, 640, 480)?;
    /// assert_eq!(ctx.get(GL_VIEWPORT)?.as_ints(), [10, 20, 640, 480]);
    /// assert_eq!(ctx.viewport(0, 0, -1, 480), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn viewport(&mut self, x: i32, y: i32, width: i32, height: i32) -> GlResult {
        self.outside_begin_end()?;
        if width < 0 || height < 0 {
            return Err(GlError::InvalidValue);
        }
        self.raster.viewport = [
            x,
            y,
            width.min(MAX_VIEWPORT_DIMS),
            height.min(MAX_VIEWPORT_DIMS),
        ];
        Ok(())
    }

    /// glDepthRange: both values are clamped to [0, 1].
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.depth_range(0.25, 2.0)?;
    /// assert_eq!(ctx.get(GL_DEPTH_RANGE)?.as_doubles(), [0.25, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn depth_range(&mut self, near: f64, far: f64) -> GlResult {
        self.outside_begin_end()?;
        self.raster.depth_range = [near.clamp(0.0, 1.0), far.clamp(0.0, 1.0)];
        Ok(())
    }

    /// glFeedbackBuffer: `address` is where the C layer will write the values; a NULL address
    /// with a positive size is GL_INVALID_VALUE.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.feedback_buffer(16, 0x1234, 1), Err(GlError::InvalidEnum));
    /// assert_eq!(ctx.feedback_buffer(16, GL_2D, 0), Err(GlError::InvalidValue)); // NULL
    /// ctx.feedback_buffer(16, GL_2D, 1)?;
    /// ctx.render_mode(GL_FEEDBACK)?;
    /// ctx.pass_through(7.0)?;
    /// let (count, finished) = ctx.render_mode(GL_RENDER)?;
    /// assert_eq!((count, finished.unwrap().values), (2, vec![GL_PASS_THROUGH_TOKEN as f32, 7.0]));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn feedback_buffer(&mut self, size: i32, kind: GLenum, address: usize) -> GlResult {
        self.outside_begin_end()?;
        if self.render_mode == RenderMode::Feedback {
            return Err(GlError::InvalidOperation);
        }
        if size < 0 || (address == 0 && size > 0) {
            return Err(GlError::InvalidValue);
        }
        let layout = FeedbackLayout::of(kind)?;
        self.feedback.storage = FeedbackStorage::default();
        self.feedback.layout = Some(layout);
        self.feedback.capacity = size as usize;
        self.feedback.restart();
        self.feedback_address = address;
        Ok(())
    }

    /// Where the values of the feedback buffer set last go (the C layer: the application's
    /// memory).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::FeedbackStorage, Context};
    /// let mut ctx = Context::new();
    /// ctx.feedback_buffer(8, GL_2D, 1)?;
    /// ctx.feedback_storage(FeedbackStorage::default()); // kept by the context (what the Rust API uses)
    /// ctx.render_mode(GL_FEEDBACK)?;
    /// ctx.pass_through(1.0)?;
    /// assert_eq!(ctx.render_mode(GL_RENDER)?.1.unwrap().values.len(), 2);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn feedback_storage(&mut self, storage: FeedbackStorage) {
        self.feedback.storage = storage;
    }

    /// glRenderMode: returns the value count of the feedback that ends or the hit count of
    /// the selection that ends (-1 if either overflowed) and the values for the C layer to
    /// write, or 0 when leaving GL_RENDER. A call in error changes nothing (§2.5): the mode
    /// is checked before the one that ends is touched.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.render_mode(GL_FEEDBACK), Err(GlError::InvalidOperation)); // no buffer yet
    /// ctx.feedback_buffer(2, GL_2D, 1)?;
    /// ctx.render_mode(GL_FEEDBACK)?;
    /// ctx.viewport(0, 0, 10, 10)?;
    /// ctx.begin(GL_POINTS)?;
    /// ctx.vertex(glam::Vec4::new(0.0, 0.0, 0.0, 1.0));
    /// ctx.end()?;
    /// // Three values do not fit in two: the count is -1 (overflow).
    /// assert_eq!(ctx.render_mode(GL_RENDER)?.0, -1);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn render_mode(&mut self, mode: GLenum) -> GlResult<(i32, Option<FinishedFeedback>)> {
        self.outside_begin_end()?;
        let new_mode = match mode {
            GL_RENDER => RenderMode::Render,
            GL_FEEDBACK => RenderMode::Feedback,
            GL_SELECT => RenderMode::Select,
            _ => return Err(GlError::InvalidEnum),
        };
        if new_mode == RenderMode::Feedback && self.feedback.layout.is_none() {
            return Err(GlError::InvalidOperation);
        }
        if new_mode == RenderMode::Select && !self.selection.buffer_given {
            return Err(GlError::InvalidOperation);
        }
        let finished = match self.render_mode {
            RenderMode::Render => (0, None),
            RenderMode::Feedback => {
                let count = self.feedback.result();
                let values = self.feedback.take_kept();
                self.feedback.restart();
                let address = self.feedback_address;
                (
                    count,
                    Some(FinishedFeedback {
                        address,
                        values,
                        ..Default::default()
                    }),
                )
            }
            RenderMode::Select => {
                self.selection.write_hit_record();
                let count = self.selection.result();
                let hit_records = std::mem::take(&mut self.selection.records);
                self.selection.restart();
                let address = self.selection.address;
                (
                    count,
                    Some(FinishedFeedback {
                        address,
                        hit_records,
                        ..Default::default()
                    }),
                )
            }
        };
        self.render_mode = new_mode;
        Ok(finished)
    }

    /// glPassThrough: a GL_PASS_THROUGH_TOKEN in feedback mode, nothing otherwise.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.pass_through(1.0)?; // in GL_RENDER mode: nothing
    /// ctx.feedback_buffer(8, GL_2D, 1)?;
    /// ctx.render_mode(GL_FEEDBACK)?;
    /// ctx.pass_through(2.0)?;
    /// assert_eq!(ctx.render_mode(GL_RENDER)?.0, 2);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn pass_through(&mut self, value: f32) -> GlResult {
        self.outside_begin_end()?;
        if self.render_mode == RenderMode::Feedback {
            self.feedback.pass_through(value);
        }
        Ok(())
    }
}
