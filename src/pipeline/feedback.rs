//! Feedback mode (§5.3): tokens and vertex values collected for glRenderMode to return.

use glam::Vec4;

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// Which values a fed-back vertex carries (glFeedbackBuffer's `type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FeedbackLayout {
    pub kind: GLenum,
    pub z: bool,
    pub w: bool,
    pub color: bool,
    pub texture: bool,
}

impl FeedbackLayout {
    pub fn of(kind: GLenum) -> GlResult<FeedbackLayout> {
        let (z, w, color, texture) = match kind {
            GL_2D => (false, false, false, false),
            GL_3D => (true, false, false, false),
            GL_3D_COLOR => (true, false, true, false),
            GL_3D_COLOR_TEXTURE => (true, false, true, true),
            GL_4D_COLOR_TEXTURE => (true, true, true, true),
            _ => return Err(GlError::InvalidEnum),
        };
        Ok(FeedbackLayout {
            kind,
            z,
            w,
            color,
            texture,
        })
    }
}

/// One vertex as feedback reports it: window coordinates (w = clip w), color, texture coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FeedbackVertex {
    pub window: Vec4,
    pub color: Vec4,
    pub tex_coord: Vec4,
}

/// The feedback buffer as the context keeps it: at most `capacity` values, then overflow.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FeedbackBuffer {
    pub layout: Option<FeedbackLayout>,
    pub capacity: usize,
    pub values: Vec<f32>,
    pub overflowed: bool,
    /// Set when the line stipple restarts: the next segment is a GL_LINE_RESET_TOKEN.
    pub line_reset_pending: bool,
}

impl FeedbackBuffer {
    /// Starts a new feedback pass: the buffer empties.
    pub fn restart(&mut self) {
        self.values.clear();
        self.overflowed = false;
        self.line_reset_pending = false;
    }

    pub fn value(&mut self, value: f32) {
        if self.values.len() < self.capacity {
            self.values.push(value);
        } else {
            self.overflowed = true;
        }
    }

    pub fn token(&mut self, token: GLenum) {
        self.value(token as f32);
    }

    pub fn pass_through(&mut self, value: f32) {
        self.token(GL_PASS_THROUGH_TOKEN);
        self.value(value);
    }

    /// The line stipple restarts (a new independent segment, strip or polygon outline).
    pub fn reset_line_stipple(&mut self) {
        self.line_reset_pending = true;
    }

    /// A segment: GL_LINE_RESET_TOKEN after a stipple restart, else GL_LINE_TOKEN.
    pub fn line(&mut self, ends: &[FeedbackVertex; 2]) {
        let reset = std::mem::take(&mut self.line_reset_pending);
        self.token(if reset {
            GL_LINE_RESET_TOKEN
        } else {
            GL_LINE_TOKEN
        });
        self.vertex(&ends[0]);
        self.vertex(&ends[1]);
    }

    pub fn vertex(&mut self, vertex: &FeedbackVertex) {
        let Some(layout) = self.layout else { return };
        self.value(vertex.window.x);
        self.value(vertex.window.y);
        if layout.z {
            self.value(vertex.window.z);
        }
        if layout.w {
            self.value(vertex.window.w);
        }
        if layout.color {
            for c in vertex.color.to_array() {
                self.value(c);
            }
        }
        if layout.texture {
            for t in vertex.tex_coord.to_array() {
                self.value(t);
            }
        }
    }

    /// glRenderMode's return value when feedback ends: the value count, or -1 on overflow.
    pub fn result(&self) -> i32 {
        if self.overflowed {
            -1
        } else {
            self.values.len() as i32
        }
    }
}
