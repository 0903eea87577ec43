//! Primitive assembly (§2.6.1): which vertices of a glBegin/glEnd (or a vertex array draw)
//! form which points, segments and triangles. Quadrilaterals and polygons are split into
//! triangles in the order Mesa's draw module uses, so that feedback streams compare
//! token for token; the provoking vertex (§2.14.7) is always the last vertex of a segment
//! or triangle.

use crate::gl::*;

/// One assembled primitive, by indices into the vertex list.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitive {
    Point(usize),
    /// A segment; `reset` starts a new line stipple (GL_LINE_RESET_TOKEN in feedback): every
    /// independent segment, and the first of a strip or loop.
    Line {
        vertices: [usize; 2],
        reset: bool,
    },
    /// A triangle. `boundary[i]` says whether edge i (from `vertices[i]` to the next vertex)
    /// is an edge of the polygon it came from (the split of a quad or polygon adds inner edges);
    /// `edge_flags` whether the vertices' edge flags decide which boundary edges are drawn
    /// (separate triangles, quads and polygons only, §2.6.2); `reset` starts a polygon.
    Triangle {
        vertices: [usize; 3],
        boundary: [bool; 3],
        edge_flags: bool,
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
pub fn assemble(mode: GLenum, count: usize, mut emit: impl FnMut(Primitive)) {
    match mode {
        GL_POINTS => (0..count).for_each(|i| emit(Primitive::Point(i))),
        GL_LINES => (0..count / 2).for_each(|i| {
            emit(Primitive::Line {
                vertices: [2 * i, 2 * i + 1],
                reset: true,
            })
        }),
        GL_LINE_STRIP | GL_LINE_LOOP if count >= 2 => {
            for i in 1..count {
                emit(Primitive::Line {
                    vertices: [i - 1, i],
                    reset: i == 1,
                });
            }
            if mode == GL_LINE_LOOP {
                emit(Primitive::Line {
                    vertices: [count - 1, 0],
                    reset: false,
                });
            }
        }
        GL_TRIANGLES => (0..count / 3).for_each(|i| {
            let v = 3 * i;
            emit(triangle([v, v + 1, v + 2], ALL_EDGES, true, true))
        }),
        GL_TRIANGLE_STRIP => (0..count.saturating_sub(2)).for_each(|i| {
            // Odd triangles swap their first two vertices to keep the strip's orientation.
            let vertices = if i % 2 == 0 {
                [i, i + 1, i + 2]
            } else {
                [i + 1, i, i + 2]
            };
            emit(triangle(vertices, ALL_EDGES, false, true))
        }),
        GL_TRIANGLE_FAN => (0..count.saturating_sub(2))
            .for_each(|i| emit(triangle([0, i + 1, i + 2], ALL_EDGES, false, true))),
        GL_QUADS => (0..count / 4).for_each(|i| {
            let v = 4 * i;
            emit(triangle([v, v + 1, v + 3], [true, false, true], true, true));
            emit(triangle(
                [v + 1, v + 2, v + 3],
                [true, true, false],
                true,
                false,
            ));
        }),
        GL_QUAD_STRIP => (0..count.saturating_sub(2) / 2).for_each(|i| {
            let v = 2 * i;
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
        }),
        GL_POLYGON if count >= 3 => {
            // A fan around vertex 0, which comes last in each triangle: it provokes.
            for i in 0..count - 2 {
                let first = i == 0;
                let last = i + 3 == count;
                emit(triangle(
                    [i + 1, i + 2, 0],
                    [true, last, first],
                    true,
                    first,
                ));
            }
        }
        _ => {}
    }
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
