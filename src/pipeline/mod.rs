//! The vertex pipeline after lighting: primitive assembly, clipping and feedback.

pub mod feedback;
pub mod vertex;

use crate::context::{Context, RenderMode};
use crate::gl::*;
use feedback::FeedbackVertex;
use vertex::ProcessedVertex;

impl Context {
    /// Assembles the primitives of `mode` from processed vertices and sends them on (§2.6.1).
    pub(crate) fn draw_vertices(&mut self, mode: GLenum, vertices: &[ProcessedVertex]) {
        if self.render_mode != RenderMode::Feedback {
            return;
        }
        if mode == GL_POINTS {
            for vertex in vertices {
                self.feedback_point(vertex);
            }
        }
    }

    /// A point in feedback: culled unless inside the view volume and every enabled clip plane.
    fn feedback_point(&mut self, vertex: &ProcessedVertex) {
        if !self.point_visible(vertex) {
            return;
        }
        let fed = FeedbackVertex {
            window: self.raster.window(vertex.clip),
            color: vertex.colors.front.primary,
            tex_coord: vertex.tex_coord,
        };
        self.feedback.token(GL_POINT_TOKEN);
        self.feedback.vertex(&fed);
    }

    fn point_visible(&self, vertex: &ProcessedVertex) -> bool {
        let c = vertex.clip;
        let in_volume = [c.x, c.y, c.z].iter().all(|&v| -c.w <= v && v <= c.w);
        in_volume
            && self
                .enables
                .clip_planes
                .iter()
                .zip(&self.raster.clip_planes)
                .filter(|(enabled, _)| **enabled)
                .all(|(_, plane)| plane.dot(vertex.eye.as_dvec4()) >= 0.0)
    }
}
