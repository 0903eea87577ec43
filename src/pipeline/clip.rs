//! Clipping (§2.12): points, segments and triangles against the view volume
//! (-w <= x, y, z <= w) and the enabled user clip planes (in eye coordinates). Attributes
//! of the new vertices (positions, both faces' colors, texture coordinates) are
//! interpolated linearly in clip space. Planes are taken in the order Mesa's draw module
//! uses (x, y, z, then user planes), which fixes the order of a clipped polygon's vertices.

use glam::{DVec4, Vec4};

use super::block::{Lanes4, OutputBlock, lanes4_get};
use super::vertex::ProcessedVertex;
use crate::lighting::lanes::LANES;
use crate::lighting::{FaceColors, LitVertex};

/// The view-volume planes as clip-space plane equations: w - x, w + x, w - y, w + y, w + z, w - z.
const VIEW_VOLUME: [Vec4; 6] = [
    Vec4::new(-1.0, 0.0, 0.0, 1.0),
    Vec4::new(1.0, 0.0, 0.0, 1.0),
    Vec4::new(0.0, -1.0, 0.0, 1.0),
    Vec4::new(0.0, 1.0, 0.0, 1.0),
    Vec4::new(0.0, 0.0, 1.0, 1.0),
    Vec4::new(0.0, 0.0, -1.0, 1.0),
];

/// 1 for a plane distance that puts a point outside: negative or NaN.
#[inline(always)]
fn outside(distance: f32) -> u32 {
    u32::from(distance < 0.0 || distance.is_nan())
}

/// One bit per view-volume plane (in `VIEW_VOLUME`'s order) that the clip-space point
/// `[x, y, z, w]` is outside of, as the planes' dot products decide: each is w ± one
/// coordinate, plus the other two coordinates times 0, which is NaN (outside) when one of them
/// is not finite.
///
/// # Examples
///
/// ```
/// use fflight::pipeline::clip::view_volume_mask;
/// assert_eq!(view_volume_mask([0.5, -0.5, 0.0, 1.0]), 0); // inside
/// assert_eq!(view_volume_mask([2.0, 0.0, 0.0, 1.0]), 0b1); // beyond x = w
/// assert_eq!(view_volume_mask([0.0, 0.0, -2.0, 1.0]), 0b1_0000); // beyond z = -w
/// assert_eq!(view_volume_mask([f32::NAN, 0.0, 0.0, 1.0]), 0b11_1111);
/// // x infinite: beyond x = w, and NaN for the other axes' planes.
/// assert_eq!(view_volume_mask([f32::INFINITY, 0.0, 0.0, 1.0]), 0b11_1101);
/// ```
#[inline(always)]
pub fn view_volume_mask([x, y, z, w]: [f32; 4]) -> u32 {
    // The other two coordinates times 0, added to each plane's w ± coordinate: 0 (which
    // leaves the sign of a distance as it is) or NaN. No branch, so lanes vectorize.
    let (x0, y0, z0) = (x * 0.0, y * 0.0, z * 0.0);
    let distances = [
        (w - x) + (y0 + z0),
        (w + x) + (y0 + z0),
        (w - y) + (x0 + z0),
        (w + y) + (x0 + z0),
        (w + z) + (x0 + y0),
        (w - z) + (x0 + y0),
    ];
    let mut mask = 0;
    for (plane, distance) in distances.into_iter().enumerate() {
        mask |= outside(distance) << plane;
    }
    mask
}

/// `view_volume_mask` of each lane's clip-space point.
///
/// # Examples
///
/// ```
/// use fflight::pipeline::clip::view_volume_masks;
/// let mut clip = [[0.0; 8], [0.0; 8], [0.0; 8], [1.0; 8]];
/// clip[0][1] = 1.5; // lane 1 beyond x = w
/// assert_eq!(view_volume_masks(&clip)[..2], [0, 0b1]);
/// ```
#[inline(always)]
pub fn view_volume_masks([x, y, z, w]: &Lanes4) -> [u32; LANES] {
    std::array::from_fn(|lane| view_volume_mask([x[lane], y[lane], z[lane], w[lane]]))
}

/// The planes a vertex is tested against: the view volume and the enabled user planes.
#[derive(Clone, Debug)]
pub struct ClipPlanes {
    user: Vec<DVec4>,
}

impl ClipPlanes {
    /// The view volume and the user planes `user`: the eye-space equations of the enabled user
    /// clip planes, in plane order.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::{clip::*, vertex::ProcessedVertex};
    /// use glam::{DVec4, Vec4};
    /// let planes = ClipPlanes::new(vec![DVec4::new(1.0, 0.0, 0.0, 0.0)]); // keeps x >= 0
    /// assert!(planes.has_user_planes());
    /// ```
    pub fn new(user: Vec<DVec4>) -> ClipPlanes {
        ClipPlanes { user }
    }

    fn count(&self) -> usize {
        VIEW_VOLUME.len() + self.user.len()
    }

    /// The signed distance of `v` from plane `plane`: negative outside.
    fn distance(&self, plane: usize, v: &ProcessedVertex) -> f32 {
        match VIEW_VOLUME.get(plane) {
            Some(equation) => equation.dot(v.clip),
            None => self.user[plane - VIEW_VOLUME.len()].dot(v.eye.as_dvec4()) as f32,
        }
    }

    /// Whether a user clip plane is enabled.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::{clip::*, vertex::ProcessedVertex};
    /// use glam::{DVec4, Vec4};
    /// assert!(!ClipPlanes::new(Vec::new()).has_user_planes());
    /// ```
    pub fn has_user_planes(&self) -> bool {
        !self.user.is_empty()
    }

    /// One bit per user plane (from bit 6) that a point at `eye` (eye coordinates) is outside.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::{clip::*, vertex::ProcessedVertex};
    /// use glam::{DVec4, Vec4};
    /// let planes = ClipPlanes::new(vec![DVec4::X, DVec4::Y]); // x >= 0, y >= 0
    /// assert_eq!(planes.user_mask(Vec4::new(-1.0, 1.0, 0.0, 1.0)), 1 << 6);
    /// assert_eq!(planes.user_mask(Vec4::new(1.0, -1.0, 0.0, 1.0)), 1 << 7);
    /// ```
    pub fn user_mask(&self, eye: Vec4) -> u32 {
        let eye = eye.as_dvec4();
        self.user.iter().enumerate().fold(0, |mask, (k, equation)| {
            mask | outside(equation.dot(eye) as f32) << (VIEW_VOLUME.len() + k)
        })
    }

    /// `outside_mask` of every lane of a processed block (lanes past its `len` included).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::{block::OutputBlock, clip::*};
    /// use glam::DVec4;
    /// let mut block = OutputBlock::default();
    /// block.clip[3] = [1.0; 8];
    /// block.clip[0][1] = 2.0; // lane 1 beyond x = w
    /// block.eye[0][2] = -1.0; // lane 2 on the wrong side of x >= 0
    /// let masks = ClipPlanes::new(vec![DVec4::X]).block_masks(&block);
    /// assert_eq!(masks[..3], [0, 0b1, 1 << 6]);
    /// ```
    #[inline(always)]
    pub fn block_masks(&self, block: &OutputBlock) -> [u32; LANES] {
        let mut masks = view_volume_masks(&block.clip);
        if self.has_user_planes() {
            for (lane, mask) in masks.iter_mut().enumerate() {
                *mask |= self.user_mask(lanes4_get(&block.eye, lane));
            }
        }
        masks
    }

    /// One bit per plane that `v` is outside of: its `distance` is negative or NaN (bits 0 to
    /// 5 the view volume's, as `view_volume_mask`, then the user planes').
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::{clip::*, vertex::ProcessedVertex};
    /// use glam::{DVec4, Vec4};
    /// let planes = ClipPlanes::new(vec![DVec4::X]);
    /// let v = ProcessedVertex {
    ///     clip: Vec4::new(2.0, 0.0, 0.0, 1.0),
    ///     eye: Vec4::new(-1.0, 0.0, 0.0, 1.0),
    ///     ..Default::default()
    /// };
    /// assert_eq!(planes.outside_mask(&v), 0b1 | 1 << 6);
    /// ```
    pub fn outside_mask(&self, v: &ProcessedVertex) -> u32 {
        let view = view_volume_mask(v.clip.to_array());
        if self.user.is_empty() {
            view
        } else {
            view | self.user_mask(v.eye)
        }
    }

    fn is_user_plane(plane: usize) -> bool {
        plane >= VIEW_VOLUME.len()
    }
}

fn lerp4(t: f32, from: Vec4, to: Vec4) -> Vec4 {
    from + t * (to - from)
}

fn lerp_face(t: f32, from: &FaceColors, to: &FaceColors) -> FaceColors {
    FaceColors {
        primary: lerp4(t, from.primary, to.primary),
        secondary: lerp4(t, from.secondary, to.secondary),
    }
}

/// The vertex at `t` from `from` to `to` (edge flag: the caller decides).
fn interpolate(t: f32, from: &ProcessedVertex, to: &ProcessedVertex) -> ProcessedVertex {
    ProcessedVertex {
        eye: lerp4(t, from.eye, to.eye),
        clip: lerp4(t, from.clip, to.clip),
        colors: LitVertex {
            front: lerp_face(t, &from.colors.front, &to.colors.front),
            back: lerp_face(t, &from.colors.back, &to.colors.back),
        },
        tex_coord: lerp4(t, from.tex_coord, to.tex_coord),
        edge_flag: from.edge_flag,
    }
}

/// Whether a point is inside every plane (§2.12: a clipped point is discarded).
///
/// # Examples
///
/// ```
/// use fflight::pipeline::{clip::*, vertex::ProcessedVertex};
/// use glam::{DVec4, Vec4};
/// let at = |x: f32, y: f32| ProcessedVertex { clip: Vec4::new(x, y, 0.0, 1.0), ..Default::default() };
/// let planes = ClipPlanes::new(Vec::new());
/// assert!(point_visible(&planes, &at(0.5, 0.5)));
/// assert!(!point_visible(&planes, &at(0.5, 1.5)));
/// ```
pub fn point_visible(planes: &ClipPlanes, v: &ProcessedVertex) -> bool {
    planes.outside_mask(v) == 0
}

/// Clips a segment (§2.12): `None` when nothing of it is inside, else its visible part, the
/// attributes of a new end interpolated in clip space.
///
/// # Examples
///
/// ```
/// use fflight::pipeline::{clip::*, vertex::ProcessedVertex};
/// use glam::{DVec4, Vec4};
/// let at = |x: f32, y: f32| ProcessedVertex { clip: Vec4::new(x, y, 0.0, 1.0), ..Default::default() };
/// let planes = ClipPlanes::new(Vec::new());
/// let [a, b] = clip_line(&planes, &at(0.0, 0.0), &at(2.0, 0.0)).unwrap();
/// assert_eq!((a.clip, b.clip), (Vec4::W, Vec4::new(1.0, 0.0, 0.0, 1.0))); // cut at x = w
/// assert!(clip_line(&planes, &at(2.0, 0.0), &at(3.0, 0.0)).is_none());
/// ```
pub fn clip_line(
    planes: &ClipPlanes,
    a: &ProcessedVertex,
    b: &ProcessedVertex,
) -> Option<[ProcessedVertex; 2]> {
    let (mask_a, mask_b) = (planes.outside_mask(a), planes.outside_mask(b));
    if mask_a & mask_b != 0 {
        return None;
    }
    if mask_a | mask_b == 0 {
        return Some([*a, *b]);
    }
    // How much of the segment each end loses: the largest cut over the planes.
    let (mut cut_a, mut cut_b) = (0.0f32, 0.0f32);
    for plane in (0..planes.count()).filter(|p| (mask_a | mask_b) & 1 << p != 0) {
        let (da, db) = (planes.distance(plane, a), planes.distance(plane, b));
        if !da.is_finite() || !db.is_finite() {
            return None;
        }
        if da < 0.0 {
            cut_a = cut_a.max(da / (da - db));
        }
        if db < 0.0 {
            cut_b = cut_b.max(db / (db - da));
        }
        if cut_a + cut_b >= 1.0 {
            return None;
        }
    }
    let new_a = if mask_a != 0 {
        interpolate(cut_a, a, b)
    } else {
        *a
    };
    let new_b = if mask_b != 0 {
        interpolate(cut_b, b, a)
    } else {
        *b
    };
    Some([new_a, new_b])
}

/// A vertex of a clipped polygon and whether the edge that starts at it is a boundary edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolygonVertex {
    /// The vertex, original or made by the clip.
    pub vertex: ProcessedVertex,
    /// Whether the edge from this vertex to the next is drawn as a polygon edge.
    pub boundary: bool,
}

/// Clips a triangle (Sutherland-Hodgman, plane by plane) into a convex polygon, written to
/// `polygon` (emptied first); fewer than three vertices means nothing is visible. Returns
/// whether the triangle crossed a plane (else `polygon` stays empty: the triangle itself is
/// wholly inside).
///
/// # Examples
///
/// ```
/// use fflight::pipeline::{clip::*, vertex::ProcessedVertex};
/// use glam::{DVec4, Vec4};
/// let at = |x: f32, y: f32| ProcessedVertex { clip: Vec4::new(x, y, 0.0, 1.0), ..Default::default() };
/// let planes = ClipPlanes::new(Vec::new());
/// let mut polygon = Vec::new();
/// // One corner beyond x = w: the clip cuts it off, leaving a quadrilateral.
/// let (a, b, c) = (at(0.0, 0.0), at(2.0, 0.0), at(0.0, 0.5));
/// assert!(clip_triangle(&planes, [&a, &b, &c], [true; 3], &mut polygon));
/// assert_eq!(polygon.len(), 4);
/// assert!(polygon.iter().all(|p| p.vertex.clip.x <= 1.0));
/// // Wholly inside: not clipped.
/// let b = at(0.5, 0.0);
/// assert!(!clip_triangle(&planes, [&a, &b, &c], [true; 3], &mut polygon));
/// assert!(polygon.is_empty());
/// ```
pub fn clip_triangle(
    planes: &ClipPlanes,
    triangle: [&ProcessedVertex; 3],
    boundary: [bool; 3],
    polygon: &mut Vec<PolygonVertex>,
) -> bool {
    polygon.clear();
    let masks = triangle.map(|v| planes.outside_mask(v));
    if masks[0] & masks[1] & masks[2] != 0 {
        return true;
    }
    let planes_crossed = masks[0] | masks[1] | masks[2];
    if planes_crossed == 0 {
        return false;
    }
    polygon.extend((0..3).map(|i| PolygonVertex {
        vertex: *triangle[i],
        boundary: boundary[i],
    }));
    let mut output = Vec::with_capacity(polygon.len() + 2);
    for plane in (0..planes.count()).filter(|p| planes_crossed & 1 << p != 0) {
        if polygon.len() < 3 {
            break;
        }
        output.clear();
        let distances: Vec<f32> = polygon
            .iter()
            .map(|p| planes.distance(plane, &p.vertex))
            .collect();
        if distances.iter().any(|d| !d.is_finite()) {
            polygon.clear();
            return true;
        }
        let n = polygon.len();
        for i in 0..n {
            let (current, next) = (&polygon[i], &polygon[(i + 1) % n]);
            let (d_current, d_next) = (distances[i], distances[(i + 1) % n]);
            if d_current >= 0.0 {
                output.push(*current);
            }
            if (d_current >= 0.0) != (d_next >= 0.0) {
                // Interpolate from the end nearer the plane, for precision.
                let mut vertex = if d_current.abs() < d_next.abs() {
                    interpolate(
                        d_current / (d_current - d_next),
                        &current.vertex,
                        &next.vertex,
                    )
                } else {
                    interpolate(d_next / (d_next - d_current), &next.vertex, &current.vertex)
                };
                let leaving = d_current >= 0.0;
                let boundary = if leaving && ClipPlanes::is_user_plane(plane) {
                    // The new edge along a user clip plane is drawn; along the view volume not.
                    vertex.edge_flag = true;
                    true
                } else {
                    vertex.edge_flag = if leaving {
                        false
                    } else {
                        current.vertex.edge_flag
                    };
                    current.boundary
                };
                output.push(PolygonVertex { vertex, boundary });
            }
        }
        std::mem::swap(polygon, &mut output);
    }
    if polygon.len() < 3 {
        polygon.clear();
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `outside_mask` computes the view planes' dot products term by term: it must flag
    /// exactly the planes whose `distance` (glam's dot product) is negative or NaN.
    #[test]
    fn outside_mask_equals_the_dot_products() {
        let values = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.5,
            2.0,
            -3.0,
            1e30,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        let planes = ClipPlanes::new(vec![DVec4::new(1.0, -1.0, 0.5, 0.25)]);
        let mut checked = 0;
        for &x in &values {
            for &y in &values {
                for &z in &values {
                    for &w in &values {
                        let v = ProcessedVertex {
                            clip: Vec4::new(x, y, z, w),
                            eye: Vec4::new(w, z, y, x),
                            ..Default::default()
                        };
                        let expected = (0..planes.count())
                            .filter(|&p| {
                                let d = planes.distance(p, &v);
                                d < 0.0 || d.is_nan()
                            })
                            .fold(0, |mask, p| mask | 1 << p);
                        assert_eq!(planes.outside_mask(&v), expected, "{:?}", v.clip);
                        checked += 1;
                    }
                }
            }
        }
        assert_eq!(checked, 11 * 11 * 11 * 11);
    }
}
