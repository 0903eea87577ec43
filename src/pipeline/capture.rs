//! Capture (an fflight extension, for applications that light geometry with fflight and draw
//! it with another renderer): while capture is on, every draw (a glBegin/glEnd or a vertex
//! array draw) appends its vertices, transformed and lit, and the points, segments and
//! triangles primitive assembly makes of them, in draw order.
//!
//! Primitives are captured after assembly and before clipping, culling, flat shading and
//! polygon mode: quadrilaterals and polygons come out as the same triangles feedback reports
//! (`assembly::assemble` decides both), a segment or triangle's provoking vertex is its last.
//! Capture only observes: glRenderMode(GL_FEEDBACK) still gets its tokens.

use super::VertexWindow;
use super::assembly::Primitive;
use super::vertex::ProcessedVertex;
use crate::gl::*;

/// One captured point, segment or triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CapturedPrimitive {
    /// GL_POINTS, GL_LINES or GL_TRIANGLES.
    pub kind: GLenum,
    /// The mode of the draw it came from (glBegin's or the array draw's).
    pub mode: GLenum,
    /// Which draw it came from, counted from 0 since capture began.
    pub draw: usize,
    /// Its vertices, as indices into `Capture::vertices`: the first 1, 2 or 3 are used (the
    /// rest are 0); the last used one is the provoking vertex (§2.14.7).
    pub vertices: [usize; 3],
    /// Triangles only: whether edge k (from `vertices[k]` to the next) is an edge GL draws in
    /// polygon mode GL_LINE: an edge of the primitive the triangle came from (not the inner
    /// edge of a split quad or polygon) whose edge flag is set (strips and fans draw every
    /// edge, §2.6.2).
    pub edges: [bool; 3],
}

impl CapturedPrimitive {
    /// How many of `vertices` are used: 1, 2 or 3.
    pub fn vertex_count(&self) -> usize {
        match self.kind {
            GL_POINTS => 1,
            GL_LINES => 2,
            _ => 3,
        }
    }

    fn of(primitive: Primitive, draw: &CapturedDraw, window: &VertexWindow) -> Self {
        let (kind, indices, edges) = match primitive {
            Primitive::Point(a) => (GL_POINTS, [a, 0, 0], [false; 3]),
            Primitive::Line {
                vertices: [a, b], ..
            } => (GL_LINES, [a, b, 0], [false; 3]),
            Primitive::Triangle {
                vertices: corners,
                boundary,
                edge_flags,
                ..
            } => {
                let edges = std::array::from_fn(|k| {
                    boundary[k] && (!edge_flags || window.get(corners[k]).edge_flag)
                });
                (GL_TRIANGLES, corners, edges)
            }
        };
        let mut captured = CapturedPrimitive {
            kind,
            mode: draw.mode,
            draw: draw.index,
            vertices: [0; 3],
            edges,
        };
        let used = captured.vertex_count();
        for (vertex, index) in captured.vertices.iter_mut().zip(indices).take(used) {
            *vertex = draw.first_vertex + index;
        }
        captured
    }
}

/// A draw being captured: its number, mode and where its vertices start.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CapturedDraw {
    index: usize,
    mode: GLenum,
    first_vertex: usize,
}

/// What capture collected: every vertex given to a draw (vertex i of a draw is
/// `vertices[first + i]`, also when it ends up in no primitive), and the primitives.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Capture {
    active: bool,
    draws: usize,
    vertices: Vec<ProcessedVertex>,
    primitives: Vec<CapturedPrimitive>,
}

impl Capture {
    pub fn is_active(&self) -> bool {
        self.active
    }

    /// Starts capturing, dropping what an earlier capture collected.
    pub fn start(&mut self) {
        *self = Capture {
            active: true,
            ..Capture::default()
        };
    }

    /// Stops capturing; what was collected stays until the next `start`.
    pub fn stop(&mut self) {
        self.active = false;
    }

    /// The captured vertices, transformed and lit.
    pub fn vertices(&self) -> &[ProcessedVertex] {
        &self.vertices
    }

    /// The captured primitives, in draw order.
    pub fn primitives(&self) -> &[CapturedPrimitive] {
        &self.primitives
    }

    /// How many draws were captured.
    pub fn draws(&self) -> usize {
        self.draws
    }

    /// A draw of `mode` starts; `None` when capture is off.
    pub(crate) fn begin_draw(&mut self, mode: GLenum) -> Option<CapturedDraw> {
        if !self.active {
            return None;
        }
        let draw = CapturedDraw {
            index: self.draws,
            mode,
            first_vertex: self.vertices.len(),
        };
        self.draws += 1;
        Some(draw)
    }

    /// The draw's next vertex.
    pub(crate) fn push_vertex(&mut self, vertex: &ProcessedVertex) {
        self.vertices.push(*vertex);
    }

    /// A primitive of `draw`, whose vertices `window` holds.
    pub(crate) fn push_primitive(
        &mut self,
        primitive: Primitive,
        draw: &CapturedDraw,
        window: &VertexWindow,
    ) {
        self.primitives
            .push(CapturedPrimitive::of(primitive, draw, window));
    }
}
