//! Primitive assembly (§2.6.1): which vertices of a glBegin/glEnd (or a vertex array draw)
//! form which points, segments and triangles. Quadrilaterals and polygons are split into
//! triangles in the order Mesa's draw module uses, so that feedback streams compare
//! token for token; the provoking vertex (§2.14.7) is always the last vertex of a segment
//! or triangle.

use crate::gl::*;

/// One assembled primitive, by indices into the vertex list.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitive {
    /// A point: the index of its vertex.
    Point(usize),
    /// A segment; `reset` starts a new line stipple (GL_LINE_RESET_TOKEN in feedback): every
    /// independent segment, and the first of a strip or loop.
    Line {
        /// Its two vertices; the second provokes.
        vertices: [usize; 2],
        /// Whether the segment starts a new line stipple.
        reset: bool,
    },
    /// A triangle. `boundary[i]` says whether edge i (from `vertices[i]` to the next vertex)
    /// is an edge of the polygon it came from (the split of a quad or polygon adds inner edges);
    /// `edge_flags` whether the vertices' edge flags decide which boundary edges are drawn
    /// (separate triangles, quads and polygons only, §2.6.2); `reset` starts a polygon.
    Triangle {
        /// Its three vertices, in the order that keeps the primitive's orientation; the
        /// third provokes.
        vertices: [usize; 3],
        /// Whether each edge is an edge of the primitive it came from.
        boundary: [bool; 3],
        /// Whether the vertices' edge flags decide which boundary edges are drawn.
        edge_flags: bool,
        /// Whether the triangle starts a polygon (a new line stipple in polygon mode GL_LINE).
        reset: bool,
    },
}

const ALL_EDGES: [bool; 3] = [true, true, true];

fn triangle(vertices: [usize; 3], boundary: [bool; 3], edge_flags: bool, reset: bool) -> Primitive {
    Primitive::Triangle {
        vertices,
        boundary,
        edge_flags,
        reset,
    }
}

/// Calls `emit` for each primitive `mode` makes of `count` vertices, in order. Incomplete
/// primitives are dropped (§2.6.1); an unknown mode makes nothing.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, pipeline::assembly::{Primitive, assemble}};
/// let mut primitives = Vec::new();
/// assemble(GL_LINE_LOOP, 3, |p| primitives.push(p));
/// assert_eq!(primitives.len(), 3);
/// // The loop closes from the last vertex back to the first.
/// assert_eq!(primitives[2], Primitive::Line { vertices: [2, 0], reset: false });
/// let mut count = 0;
/// assemble(GL_TRIANGLES, 5, |_| count += 1);
/// assert_eq!(count, 1); // the incomplete second triangle is dropped
/// ```
pub fn assemble(mode: GLenum, count: usize, mut emit: impl FnMut(Primitive)) {
    let mut assembler = Assembler::new(mode);
    for _ in 0..count {
        assembler.push(&mut emit);
    }
    assembler.finish(&mut emit);
}

/// Primitive assembly one vertex at a time, for draws that are never held whole: `push`
/// announces the next vertex and emits the primitives it completes, `finish` the ones the
/// end of the draw completes (a loop's closing segment, a polygon's last triangle). A
/// primitive only refers to vertex 0 and the last four vertices pushed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Assembler {
    mode: GLenum,
    /// Vertices pushed so far.
    count: usize,
}

impl Assembler {
    /// An assembler for a draw of `mode` (glBegin's or the array draw's), no vertex pushed.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::assembly::{Assembler, Primitive}};
    /// let assembler = Assembler::new(GL_QUADS);
    /// assert_eq!((assembler.mode(), assembler.count()), (GL_QUADS, 0));
    /// ```
    pub fn new(mode: GLenum) -> Assembler {
        Assembler { mode, count: 0 }
    }

    /// The draw's mode.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::assembly::{Assembler, Primitive}};
    /// assert_eq!(Assembler::new(GL_LINE_STRIP).mode(), GL_LINE_STRIP);
    /// ```
    pub fn mode(&self) -> GLenum {
        self.mode
    }

    /// Vertices pushed so far.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::assembly::{Assembler, Primitive}};
    /// let mut assembler = Assembler::new(GL_POINTS);
    /// assembler.push(|_| {});
    /// assembler.push(|_| {});
    /// assert_eq!(assembler.count(), 2);
    /// ```
    pub fn count(&self) -> usize {
        self.count
    }

    /// Vertex number `count()` arrives.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::assembly::{Assembler, Primitive}};
    /// let mut assembler = Assembler::new(GL_TRIANGLES);
    /// let mut made = Vec::new();
    /// for _ in 0..3 {
    ///     assembler.push(|p| made.push(p));
    /// }
    /// assert_eq!(made.len(), 1); // the third vertex completes the triangle
    /// assert!(matches!(made[0], Primitive::Triangle { vertices: [0, 1, 2], .. }));
    /// ```
    pub fn push(&mut self, mut emit: impl FnMut(Primitive)) {
        let i = self.count;
        self.count += 1;
        match self.mode {
            GL_POINTS => emit(Primitive::Point(i)),
            GL_LINES if i % 2 == 1 => emit(Primitive::Line {
                vertices: [i - 1, i],
                reset: true,
            }),
            GL_LINE_STRIP | GL_LINE_LOOP if i >= 1 => emit(Primitive::Line {
                vertices: [i - 1, i],
                reset: i == 1,
            }),
            GL_TRIANGLES if i % 3 == 2 => emit(triangle([i - 2, i - 1, i], ALL_EDGES, true, true)),
            GL_TRIANGLE_STRIP if i >= 2 => {
                // Odd triangles swap their first two vertices to keep the strip's orientation.
                let j = i - 2;
                let vertices = if j.is_multiple_of(2) {
                    [j, j + 1, j + 2]
                } else {
                    [j + 1, j, j + 2]
                };
                emit(triangle(vertices, ALL_EDGES, false, true))
            }
            GL_TRIANGLE_FAN if i >= 2 => emit(triangle([0, i - 1, i], ALL_EDGES, false, true)),
            GL_QUADS if i % 4 == 3 => {
                let v = i - 3;
                emit(triangle([v, v + 1, v + 3], [true, false, true], true, true));
                emit(triangle(
                    [v + 1, v + 2, v + 3],
                    [true, true, false],
                    true,
                    false,
                ));
            }
            GL_QUAD_STRIP if i >= 3 && i % 2 == 1 => {
                let v = i - 3;
                emit(triangle(
                    [v + 2, v, v + 3],
                    [true, false, true],
                    false,
                    true,
                ));
                emit(triangle(
                    [v, v + 1, v + 3],
                    [true, true, false],
                    false,
                    false,
                ));
            }
            // The triangle of vertices i - 2 and i - 1 is known not to be the last one only
            // now: its closing edge is a polygon edge only if it is.
            GL_POLYGON if i >= 3 => emit(polygon_triangle(i - 3, false)),
            _ => {}
        }
    }

    /// The draw ends.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::assembly::{Assembler, Primitive}};
    /// let mut assembler = Assembler::new(GL_POLYGON);
    /// let mut made = Vec::new();
    /// for _ in 0..4 {
    ///     assembler.push(|p| made.push(p));
    /// }
    /// assert_eq!(made.len(), 1);
    /// assembler.finish(|p| made.push(p)); // only now is the last triangle known to be last
    /// let last = Primitive::Triangle {
    ///     vertices: [2, 3, 0],
    ///     boundary: [true, true, false],
    ///     edge_flags: true,
    ///     reset: false,
    /// };
    /// assert_eq!(made[1], last);
    /// ```
    pub fn finish(&mut self, mut emit: impl FnMut(Primitive)) {
        let count = self.count;
        match self.mode {
            GL_LINE_LOOP if count >= 2 => emit(Primitive::Line {
                vertices: [count - 1, 0],
                reset: false,
            }),
            GL_POLYGON if count >= 3 => emit(polygon_triangle(count - 3, true)),
            _ => {}
        }
    }
}

/// Triangle `k` of a polygon: a fan around vertex 0, which comes last in each triangle and
/// so provokes.
fn polygon_triangle(k: usize, last: bool) -> Primitive {
    let first = k == 0;
    triangle([k + 1, k + 2, 0], [true, last, first], true, first)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn collect(mode: GLenum, count: usize) -> Vec<Primitive> {
        let mut out = Vec::new();
        assemble(mode, count, |p| out.push(p));
        out
    }

    fn triangles(mode: GLenum, count: usize) -> Vec<[usize; 3]> {
        collect(mode, count)
            .into_iter()
            .filter_map(|p| match p {
                Primitive::Triangle { vertices, .. } => Some(vertices),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn incomplete_primitives_are_dropped() {
        assert_eq!(collect(GL_LINES, 3).len(), 1);
        assert_eq!(collect(GL_LINE_STRIP, 1).len(), 0);
        assert_eq!(collect(GL_TRIANGLES, 5).len(), 1);
        assert_eq!(collect(GL_QUADS, 7).len(), 2);
        assert_eq!(collect(GL_QUAD_STRIP, 5).len(), 2);
        assert_eq!(collect(GL_POLYGON, 2).len(), 0);
    }

    #[test]
    fn provoking_vertex_is_last() {
        assert_eq!(
            triangles(GL_TRIANGLE_STRIP, 5),
            [[0, 1, 2], [2, 1, 3], [2, 3, 4]]
        );
        assert_eq!(triangles(GL_TRIANGLE_FAN, 4), [[0, 1, 2], [0, 2, 3]]);
        assert_eq!(triangles(GL_QUADS, 4), [[0, 1, 3], [1, 2, 3]]);
        assert_eq!(triangles(GL_QUAD_STRIP, 4), [[2, 0, 3], [0, 1, 3]]);
        assert_eq!(triangles(GL_POLYGON, 5), [[1, 2, 0], [2, 3, 0], [3, 4, 0]]);
    }

    #[test]
    fn line_loop_closes_and_resets_once() {
        let lines = collect(GL_LINE_LOOP, 3);
        assert_eq!(
            lines,
            [
                Primitive::Line {
                    vertices: [0, 1],
                    reset: true
                },
                Primitive::Line {
                    vertices: [1, 2],
                    reset: false
                },
                Primitive::Line {
                    vertices: [2, 0],
                    reset: false
                },
            ]
        );
    }
}
