//! Capture (an fflight extension, for applications that light geometry with fflight and draw
//! it with another renderer): while capture is on, every draw (a glBegin/glEnd or a vertex
//! array draw) appends its vertices, transformed and lit, and the points, segments and
//! triangles primitive assembly makes of them, in draw order.
//!
//! Primitives are captured after assembly and before clipping, culling, flat shading and
//! polygon mode: quadrilaterals and polygons come out as the same triangles feedback reports
//! (`assembly::assemble` decides both), a segment or triangle's provoking vertex is its last.
//! Capture only observes: glRenderMode(GL_FEEDBACK) still gets its tokens.

use glam::Vec4;

use super::VertexWindow;
use super::assembly::Primitive;
use super::units::UnitCoords;
use super::vertex::ProcessedVertex;
use crate::gl::*;
use crate::state::texture::MAX_TEXTURE_UNITS;

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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::capture::CapturedPrimitive};
    /// let segment = CapturedPrimitive {
    ///     kind: GL_LINES,
    ///     mode: GL_LINE_STRIP,
    ///     draw: 0,
    ///     vertices: [4, 5, 0],
    ///     edges: [false; 3],
    /// };
    /// assert_eq!(segment.vertex_count(), 2);
    /// ```
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
    /// Texture units 1 and up's coordinates of the vertices, in runs: `(first, coords)` holds
    /// for vertices `first` up to the next run's first (most draws need one run).
    unit_runs: Vec<(usize, UnitCoords)>,
    /// How many vertices `unit_runs` covers.
    unit_vertices: usize,
}

impl Capture {
    /// Whether capture is on: between fflCaptureBegin and fflCaptureEnd.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::capture::Capture};
    /// let mut capture = Capture::default();
    /// assert!(!capture.is_active());
    /// capture.start();
    /// assert!(capture.is_active());
    /// ```
    pub fn is_active(&self) -> bool {
        self.active
    }

    /// Starts capturing, dropping what an earlier capture collected.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.capture_begin()?;
    /// ctx.begin(GL_POINTS)?;
    /// ctx.vertex(glam::Vec4::W);
    /// ctx.end()?;
    /// ctx.capture_begin()?; // starts again: the point is dropped
    /// assert_eq!(ctx.captured().draws(), 0);
    /// assert!(ctx.captured().vertices().is_empty());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn start(&mut self) {
        *self = Capture {
            active: true,
            ..Capture::default()
        };
    }

    /// Stops capturing; what was collected stays until the next `start`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::capture::Capture};
    /// let mut capture = Capture::default();
    /// capture.start();
    /// capture.stop();
    /// assert!(!capture.is_active());
    /// ```
    pub fn stop(&mut self) {
        self.active = false;
    }

    /// The captured vertices, transformed and lit.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// use glam::Vec4;
    /// let mut ctx = Context::new();
    /// ctx.capture_begin()?;
    /// ctx.begin(GL_LINES)?;
    /// ctx.vertex(Vec4::new(0.5, 0.0, 0.0, 1.0));
    /// ctx.vertex(Vec4::new(0.0, 0.5, 0.0, 1.0));
    /// ctx.end()?;
    /// let vertices = ctx.captured().vertices();
    /// assert_eq!(vertices.len(), 2);
    /// assert_eq!(vertices[0].clip, Vec4::new(0.5, 0.0, 0.0, 1.0)); // identity matrices
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn vertices(&self) -> &[ProcessedVertex] {
        &self.vertices
    }

    /// Texture unit `unit`'s coordinates of captured vertex `vertex`, after that unit's
    /// coordinate generation and texture matrix (unit 0's are `vertices()[vertex].tex_coord`);
    /// `None` past the vertices or the units (GL_MAX_TEXTURE_UNITS).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// use glam::Vec4;
    /// let mut ctx = Context::new();
    /// ctx.capture_begin()?;
    /// ctx.begin(GL_POINTS)?;
    /// ctx.multi_tex_coord(GL_TEXTURE0, Vec4::new(0.5, 0.0, 0.0, 1.0))?;
    /// ctx.multi_tex_coord(GL_TEXTURE3, Vec4::new(0.0, 0.25, 0.0, 1.0))?;
    /// ctx.vertex(Vec4::W);
    /// ctx.end()?;
    /// let capture = ctx.captured();
    /// assert_eq!(capture.tex_coord(0, 0), Some(Vec4::new(0.5, 0.0, 0.0, 1.0)));
    /// assert_eq!(capture.tex_coord(0, 3), Some(Vec4::new(0.0, 0.25, 0.0, 1.0)));
    /// assert_eq!(capture.tex_coord(0, 1), Some(Vec4::W)); // the initial (0, 0, 0, 1)
    /// assert_eq!(capture.tex_coord(0, 8), None);
    /// assert_eq!(capture.tex_coord(1, 0), None);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_coord(&self, vertex: usize, unit: usize) -> Option<Vec4> {
        let captured = self.vertices.get(vertex)?;
        match unit {
            0 => Some(captured.tex_coord),
            1..MAX_TEXTURE_UNITS => {
                let runs = self
                    .unit_runs
                    .partition_point(|&(first, _)| first <= vertex);
                Some(self.unit_runs.get(runs.checked_sub(1)?)?.1[unit - 1])
            }
            _ => None,
        }
    }

    /// The captured primitives, in draw order.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// use glam::Vec4;
    /// let mut ctx = Context::new();
    /// ctx.capture_begin()?;
    /// ctx.begin(GL_QUADS)?;
    /// for (x, y) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
    ///     ctx.vertex(Vec4::new(x, y, 0.0, 1.0));
    /// }
    /// ctx.end()?;
    /// let primitives = ctx.captured().primitives();
    /// assert_eq!(primitives.len(), 2); // a quadrilateral is two triangles
    /// assert!(primitives.iter().all(|p| p.kind == GL_TRIANGLES && p.mode == GL_QUADS));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn primitives(&self) -> &[CapturedPrimitive] {
        &self.primitives
    }

    /// How many draws were captured.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.capture_begin()?;
    /// for _ in 0..2 {
    ///     ctx.begin(GL_POINTS)?;
    ///     ctx.vertex(glam::Vec4::W);
    ///     ctx.end()?;
    /// }
    /// assert_eq!(ctx.captured().draws(), 2);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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

    /// Texture units 1 and up's coordinates of the next vertex (vertex `n` gets the `n`th
    /// call's: every path that captures a vertex makes one call for it).
    pub(crate) fn push_units(&mut self, coords: &UnitCoords) {
        if self.unit_runs.last().is_none_or(|(_, last)| last != coords) {
            self.unit_runs.push((self.unit_vertices, *coords));
        }
        self.unit_vertices += 1;
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
