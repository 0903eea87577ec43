//! The vertex pipeline after lighting: primitive assembly, clipping, facing, flat shading,
//! polygon mode and feedback or selection (§2.6, §2.12, §2.14.1, §2.14.7, §3.5, §5.2, §5.3).
//!
//! One path, two sinks: the primitives that survive clipping and culling are fed back in
//! GL_FEEDBACK mode and recorded as selection hits in GL_SELECT mode.

pub mod assembly;
pub mod block;
pub mod capture;
pub mod clip;
pub mod feedback;
pub mod fetch;
pub mod mesh;
pub mod parallel;
pub mod points;
pub mod select;
pub mod streaming;
pub mod units;
pub mod vertex;
pub mod vertex_cache;

use glam::Vec4;

use crate::context::{Context, RenderMode};
use crate::gl::*;
use crate::lighting::FaceColors;
use crate::lighting::batch::{Faces, Reads, process_blocks};
use crate::lighting::lanes::lanes_of;
use crate::state::raster::ViewportMap;
use assembly::{Assembler, Primitive};
use block::{InputBlock, OutputBlock};
use clip::{ClipPlanes, PolygonVertex, clip_line, clip_triangle, point_visible};
use feedback::FeedbackVertex;
use vertex::{DerivedState, ProcessedVertex};

/// The vertices of a draw that its next primitives may still refer to: vertex 0 and the last
/// four (`Assembler`'s promise), so a draw of any size is held in a fixed space.
#[derive(Clone, Copy, Debug, Default)]
pub struct VertexWindow {
    first: ProcessedVertex,
    recent: [ProcessedVertex; 4],
}

impl VertexWindow {
    fn put(&mut self, index: usize, vertex: &ProcessedVertex) {
        if index == 0 {
            self.first = *vertex;
        }
        self.recent[index % 4] = *vertex;
    }

    /// Vertex `index` of the draw: 0 or one of the last four put.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::{VertexWindow, vertex::ProcessedVertex};
    /// let window = VertexWindow::default();
    /// assert_eq!(window.get(0), &ProcessedVertex::default());
    /// ```
    pub fn get(&self, index: usize) -> &ProcessedVertex {
        if index == 0 {
            &self.first
        } else {
            &self.recent[index % 4]
        }
    }
}

/// The primitives one vertex completes: at most two (a quadrilateral's triangles).
#[derive(Default)]
struct Completed {
    primitives: [Option<Primitive>; 2],
}

impl Completed {
    fn add(&mut self, primitive: Primitive) {
        let free = self.primitives.iter_mut().find(|p| p.is_none());
        *free.expect("a vertex completes at most two primitives") = Some(primitive);
    }

    fn for_each(self, f: impl FnMut(Primitive)) {
        self.primitives.into_iter().flatten().for_each(f);
    }
}

/// A draw in progress: assembly state, the vertices primitives may still use, the clip
/// planes, and the capture's record of the draw when capture is on.
#[derive(Clone, Debug)]
pub struct DrawStream {
    assembler: Assembler,
    window: VertexWindow,
    planes: ClipPlanes,
    /// The viewport transform, made once for the draw's blocks of points.
    viewport: ViewportMap,
    capture: Option<capture::CapturedDraw>,
    /// Scratch for clipped polygons, kept across the draw's triangles.
    polygon: Vec<PolygonVertex>,
    /// Whether the feedback layout carries texture coordinates.
    feedback_tex_coord: bool,
}

impl DrawStream {
    /// What the draw reads of its vertices: points and lines only the front colors, unless
    /// capture records both; the eye coordinates only for capture and user clip planes; the
    /// secondary colors only for capture; the texture coordinates for capture and the
    /// feedback layouts that carry them.
    pub(crate) fn reads(&self) -> Reads {
        let lines_or_points = matches!(
            self.assembler.mode(),
            GL_POINTS | GL_LINES | GL_LINE_STRIP | GL_LINE_LOOP
        );
        let captured = self.capture.is_some();
        Reads {
            faces: if lines_or_points && !captured {
                Faces::Front
            } else {
                Faces::Both
            },
            eye: captured || self.planes.has_user_planes(),
            secondary: captured,
            tex_coord: captured || self.feedback_tex_coord,
        }
    }
}

/// How many blocks `Context::stream_blocks` takes at a time: two, so that the fast engine's
/// widest kernel (two blocks in sixteen lanes) serves the draws streamed through it.
pub(crate) const STREAMED_BLOCKS: usize = 2;

/// What feedback needs of a vertex after its colors were chosen.
fn feedback_vertex(ctx: &Context, v: &ProcessedVertex, color: Vec4) -> FeedbackVertex {
    FeedbackVertex {
        window: ctx.raster.window(v.clip),
        color,
        tex_coord: v.tex_coord,
    }
}

impl Context {
    /// The enabled user clip planes, in eye coordinates.
    pub(crate) fn clip_planes(&self) -> ClipPlanes {
        ClipPlanes::new(
            self.enables
                .clip_planes
                .iter()
                .zip(&self.raster.clip_planes)
                .filter(|(enabled, _)| **enabled)
                .map(|(_, plane)| *plane)
                .collect(),
        )
    }

    fn flat_shading(&self) -> bool {
        self.raster.shade_model == GL_FLAT
    }

    fn selecting(&self) -> bool {
        self.render_mode == RenderMode::Select
    }

    /// Starts a draw of `mode` whose processed vertices `stream_vertex` receives one by one.
    pub(crate) fn begin_stream(&mut self, mode: GLenum) -> DrawStream {
        DrawStream {
            assembler: Assembler::new(mode),
            window: VertexWindow::default(),
            planes: self.clip_planes(),
            viewport: self.raster.viewport_map(),
            capture: self.capture.begin_draw(mode),
            polygon: Vec::new(),
            feedback_tex_coord: self.render_mode == RenderMode::Feedback
                && self.feedback.layout.is_some_and(|layout| layout.texture),
        }
    }

    /// Processes `inputs` (at most `STREAMED_BLOCKS`) with `derived` and streams their
    /// vertices into the draw, in order.
    pub(crate) fn stream_blocks(
        &mut self,
        stream: &mut DrawStream,
        derived: &DerivedState,
        inputs: &[InputBlock],
    ) {
        let mut outputs = self.lit_blocks.take().unwrap_or_default();
        let outputs_used = &mut outputs[..inputs.len()];
        process_blocks(derived, stream.reads(), inputs, outputs_used);
        for output in outputs_used.iter() {
            self.stream_lit_block(stream, output);
        }
        self.lit_blocks = Some(outputs);
    }

    /// Where a thread without the context may lay out the draw's points (`points_sink`):
    /// points not captured, in feedback or selection mode.
    pub(crate) fn stream_points_sink(&self, stream: &DrawStream) -> Option<points::PointsSink> {
        if stream.assembler.mode() != GL_POINTS || stream.capture.is_some() {
            return None;
        }
        self.points_sink(stream.viewport, stream.planes.clone())
    }

    /// Streams a processed block's vertices into the draw, in order.
    pub(crate) fn stream_lit_block(&mut self, stream: &mut DrawStream, output: &OutputBlock) {
        if stream.assembler.mode() == GL_POINTS && stream.capture.is_none() {
            // Points need no assembly and no window of earlier vertices.
            if self.render_mode != RenderMode::Render {
                self.feedback_points(&stream.viewport, &stream.planes, output);
            }
            return;
        }
        for lane in 0..output.len {
            self.stream_vertex(stream, &output.vertex(lane));
        }
    }

    /// A block of points (front colors), each culled unless inside every plane: fed back or
    /// selected lane by lane, the same as `feedback_point` for each.
    fn feedback_points(
        &mut self,
        viewport: &ViewportMap,
        planes: &ClipPlanes,
        block: &OutputBlock,
    ) {
        let points::VisiblePoints { visible, window } =
            points::visible_points(viewport, planes, block);
        if self.selecting() {
            for lane in lanes_of(visible) {
                self.selection.hit(window[2][lane]);
            }
        } else {
            self.feedback
                .points(visible, &window, &block.front_primary, &block.tex_coord);
        }
    }

    /// The next vertex of the draw: captured, and assembled into the primitives it completes,
    /// which are clipped and fed back or selected (§2.6.1).
    pub(crate) fn stream_vertex(&mut self, stream: &mut DrawStream, vertex: &ProcessedVertex) {
        stream.window.put(stream.assembler.count(), vertex);
        if stream.capture.is_some() {
            self.capture.push_vertex(vertex);
        }
        let mut completed = Completed::default();
        stream.assembler.push(|p| completed.add(p));
        completed.for_each(|p| self.route(stream, p));
    }

    /// The draw ends: the primitives its end completes are sent on.
    pub(crate) fn end_stream(&mut self, mut stream: DrawStream) {
        let mut completed = Completed::default();
        stream.assembler.finish(|p| completed.add(p));
        completed.for_each(|p| self.route(&mut stream, p));
    }

    /// A completed primitive to capture, and to clipping and feedback or selection.
    fn route(&mut self, stream: &mut DrawStream, primitive: Primitive) {
        if let Some(draw) = &stream.capture {
            self.capture.push_primitive(primitive, draw, &stream.window);
        }
        if self.render_mode != RenderMode::Render {
            self.send_primitive(stream, primitive);
        }
    }

    /// One assembled primitive to clipping, culling and feedback or selection.
    fn send_primitive(&mut self, stream: &mut DrawStream, primitive: Primitive) {
        let DrawStream {
            window,
            planes,
            polygon,
            ..
        } = stream;
        match primitive {
            Primitive::Point(i) => self.feedback_point(planes, window.get(i)),
            Primitive::Line {
                vertices: [a, b],
                reset,
            } => self.feedback_line(planes, [window.get(a), window.get(b)], reset),
            Primitive::Triangle {
                vertices: [a, b, c],
                boundary,
                edge_flags,
                reset,
            } => {
                let mut owned: [ProcessedVertex; 3];
                let [a, b, c] = if edge_flags {
                    [window.get(a), window.get(b), window.get(c)]
                } else {
                    // Strips and fans draw every edge whatever the edge flags (§2.6.2).
                    owned = [*window.get(a), *window.get(b), *window.get(c)];
                    owned.iter_mut().for_each(|v| v.edge_flag = true);
                    [&owned[0], &owned[1], &owned[2]]
                };
                if clip_triangle(planes, [a, b, c], boundary, polygon) {
                    self.feedback_polygon(polygon, c);
                } else {
                    self.feedback_triangle([a, b, c], boundary, c, reset);
                }
            }
        }
    }

    /// A point: culled unless inside every plane; points always use the front colors.
    fn feedback_point(&mut self, planes: &ClipPlanes, v: &ProcessedVertex) {
        if !point_visible(planes, v) {
            return;
        }
        if self.selecting() {
            self.selection.hit(self.raster.window(v.clip).z);
            return;
        }
        let fed = feedback_vertex(self, v, v.colors.front.primary);
        self.feedback.token(GL_POINT_TOKEN);
        self.feedback.vertex(&fed);
    }

    /// A segment, clipped; flat shading gives both ends the provoking (second) vertex's color.
    fn feedback_line(&mut self, planes: &ClipPlanes, ends: [&ProcessedVertex; 2], reset: bool) {
        if reset && !self.selecting() {
            // The counter restarts even if this segment is clipped away: it advances only
            // with the fragments of a drawn segment (§3.4.2).
            self.feedback.reset_line_stipple();
        }
        let Some(clipped) = clip_line(planes, ends[0], ends[1]) else {
            return;
        };
        if self.selecting() {
            for v in &clipped {
                self.selection.hit(self.raster.window(v.clip).z);
            }
            return;
        }
        let flat = self.flat_shading().then_some(ends[1].colors.front.primary);
        let fed =
            clipped.map(|v| feedback_vertex(self, &v, flat.unwrap_or(v.colors.front.primary)));
        self.feedback.line(&fed);
    }

    /// A clipped triangle, emitted as a fan of triangles whose last vertex is the polygon's
    /// first; the first of them restarts the line stipple, as in Mesa.
    fn feedback_polygon(&mut self, polygon: &[PolygonVertex], provoking: &ProcessedVertex) {
        let n = polygon.len();
        for i in 2..n {
            let corners = [&polygon[i - 1], &polygon[i], &polygon[0]];
            // Edge 0 runs corners 0 -> 1, edge 1 corners 1 -> 2 (closing the polygon), edge 2
            // corners 2 -> 0 (the polygon's first edge).
            let boundary = [
                corners[0].boundary,
                i == n - 1 && corners[1].boundary,
                i == 2 && corners[2].boundary,
            ];
            self.feedback_triangle(corners.map(|c| &c.vertex), boundary, provoking, i == 2);
        }
    }

    /// One triangle: faced, culled, colored, then drawn in its face's polygon mode. `reset`
    /// restarts the line stipple of its outline. In selection mode a triangle that is not
    /// culled hits with all its corners, whatever the polygon mode and edge flags (§5.2:
    /// "selection is based on the polygon itself, regardless of the setting of PolygonMode").
    fn feedback_triangle(
        &mut self,
        corners: [&ProcessedVertex; 3],
        boundary: [bool; 3],
        provoking: &ProcessedVertex,
        reset: bool,
    ) {
        let window = corners.map(|v| self.raster.window(v.clip));
        let front = self.is_front_facing(window);
        if self.enables.cull_face && self.culls(front) {
            return;
        }
        if self.selecting() {
            for w in &window {
                self.selection.hit(w.z);
            }
            return;
        }
        let face_colors = |v: &ProcessedVertex| -> FaceColors {
            if front { v.colors.front } else { v.colors.back }
        };
        let flat = self.flat_shading().then(|| face_colors(provoking).primary);
        let fed: [FeedbackVertex; 3] = std::array::from_fn(|k| FeedbackVertex {
            window: window[k],
            color: flat.unwrap_or(face_colors(corners[k]).primary),
            tex_coord: corners[k].tex_coord,
        });
        let drawn_edge = |k: usize| boundary[k] && corners[k].edge_flag;
        match self.raster.polygon_mode[if front { 0 } else { 1 }] {
            GL_POINT => {
                for k in (0..3).filter(|&k| drawn_edge(k)) {
                    self.feedback.token(GL_POINT_TOKEN);
                    self.feedback.vertex(&fed[k]);
                }
            }
            GL_LINE => {
                if reset {
                    self.feedback.reset_line_stipple();
                }
                // Mesa's order: the edge closing the triangle first.
                for k in [2, 0, 1].into_iter().filter(|&k| drawn_edge(k)) {
                    self.feedback.line(&[fed[k], fed[(k + 1) % 3]]);
                }
            }
            _ => self.feedback.triangle(&fed),
        }
    }

    /// Facing from the sign of the window-space area (§2.14.1): counterclockwise is positive.
    /// A polygon of zero area is front-facing under neither winding: back-facing.
    fn is_front_facing(&self, window: [Vec4; 3]) -> bool {
        let e = window[0] - window[2];
        let f = window[1] - window[2];
        let twice_area = e.x * f.y - e.y * f.x;
        if self.raster.front_face == GL_CCW {
            twice_area > 0.0
        } else {
            twice_area < 0.0
        }
    }

    fn culls(&self, front: bool) -> bool {
        match self.raster.cull_face_mode {
            GL_FRONT => front,
            GL_BACK => !front,
            _ => true,
        }
    }
}
