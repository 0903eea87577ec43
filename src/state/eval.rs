//! Evaluators (§5.1): the one- and two-dimensional maps, their enables and grids, and the
//! evaluation of Bernstein polynomials.

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// GL_MAX_EVAL_ORDER (Mesa's).
pub const MAX_EVAL_ORDER: usize = 30;

/// The nine kinds of map, in the order of their enums (GL_MAP1_COLOR_4 ... GL_MAP1_VERTEX_4).
pub const MAP_KINDS: usize = 9;
/// GL_MAPn_COLOR_4.
pub const COLOR_4: usize = 0;
/// GL_MAPn_INDEX.
pub const INDEX: usize = 1;
/// GL_MAPn_NORMAL.
pub const NORMAL: usize = 2;
/// GL_MAPn_TEXTURE_COORD_1; _2, _3 and _4 follow.
pub const TEXTURE_COORD_1: usize = 3;
/// GL_MAPn_VERTEX_3.
pub const VERTEX_3: usize = 7;
/// GL_MAPn_VERTEX_4.
pub const VERTEX_4: usize = 8;

/// Values a control point of map kind `kind` has (table 5.1's k).
///
/// # Examples
///
/// ```
/// use fflight::state::eval::{values_per_point, COLOR_4, NORMAL, VERTEX_3};
/// assert_eq!((values_per_point(COLOR_4), values_per_point(NORMAL), values_per_point(VERTEX_3)), (4, 3, 3));
/// ```
pub fn values_per_point(kind: usize) -> usize {
    [4, 1, 3, 1, 2, 3, 4, 3, 4][kind]
}

/// The kind of a GL_MAP1_* (`dimensions` 1) or GL_MAP2_* (2) target; GL_INVALID_ENUM for
/// another.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::eval::{map_kind, VERTEX_4}, GlError};
/// assert_eq!(map_kind(GL_MAP2_VERTEX_4, 2), Ok(VERTEX_4));
/// assert_eq!(map_kind(GL_MAP2_VERTEX_4, 1), Err(GlError::InvalidEnum)); // a 2D map for glMap1
/// ```
pub fn map_kind(target: GLenum, dimensions: usize) -> GlResult<usize> {
    let base = if dimensions == 1 {
        GL_MAP1_COLOR_4
    } else {
        GL_MAP2_COLOR_4
    };
    let kind = target.wrapping_sub(base) as usize;
    if kind < MAP_KINDS {
        Ok(kind)
    } else {
        Err(GlError::InvalidEnum)
    }
}

/// A map's initial single control point (§5.1): vertices (0, 0, 0, 1), normals (0, 0, 1),
/// colors (1, 1, 1, 1), indices 1, texture coordinates (0, 0, 0, 1) (each its first k values).
fn initial_point(kind: usize) -> Vec<f32> {
    let point: &[f32] = match kind {
        COLOR_4 => &[1.0, 1.0, 1.0, 1.0],
        INDEX => &[1.0],
        NORMAL => &[0.0, 0.0, 1.0],
        VERTEX_4 | 6 => &[0.0, 0.0, 0.0, 1.0],
        _ => &[0.0; 3],
    };
    point[..values_per_point(kind)].to_vec()
}

/// One map: its orders (v's is 1 for a one-dimensional map), domain and control points,
/// compacted: point (i, j) (i along u) at `(i * vorder + j) * k`.
#[derive(Clone, Debug, PartialEq)]
pub struct Map {
    /// The order along u and along v.
    pub order: [usize; 2],
    /// u1, u2 (and v1, v2).
    pub domain: [f64; 4],
    /// The control points, compacted (see above).
    pub points: Vec<f32>,
}

impl Map {
    fn initial(kind: usize) -> Map {
        Map {
            order: [1, 1],
            domain: [0.0, 1.0, 0.0, 1.0],
            points: initial_point(kind),
        }
    }
}

/// A grid (glMapGrid): segments and domain along u (and v).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// The number of segments along u and along v.
    pub segments: [i32; 2],
    /// u1, u2, v1, v2.
    pub domain: [f64; 4],
}

impl Default for Grid {
    fn default() -> Grid {
        Grid {
            segments: [1, 1],
            domain: [0.0, 1.0, 0.0, 1.0],
        }
    }
}

/// GL_EVAL_BIT's state: the map enables and the grids (the maps themselves are in no
/// attribute group).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EvalAttribs {
    /// GL_MAP1_* and GL_MAP2_* enables, by dimension - 1 and kind.
    pub enabled: [[bool; MAP_KINDS]; 2],
    /// The grid of glMapGrid1 and of glMapGrid2.
    pub grids: [Grid; 2],
}

/// Every map of both dimensions.
#[derive(Clone, Debug, PartialEq)]
pub struct Maps {
    /// The maps by dimension - 1 and kind.
    pub maps: [[Map; MAP_KINDS]; 2],
}

impl Default for Maps {
    fn default() -> Maps {
        Maps {
            maps: std::array::from_fn(|_| std::array::from_fn(Map::initial)),
        }
    }
}

/// How many values glMap1 reads: `order` points `stride` apart, k values each (0 when the
/// arguments are rejected, so nothing is read).
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::eval::map1_values};
/// // 3 points of 3 values, 4 apart: the last point's values end the read.
/// assert_eq!(map1_values(GL_MAP1_VERTEX_3, 4, 3), 2 * 4 + 3);
/// ```
pub fn map1_values(target: GLenum, stride: GLint, order: GLint) -> usize {
    map_values(target, 1, [stride, 1], [order, 1])
}

/// How many values glMap2 reads.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::eval::map2_values};
/// // 2 x 2 points of 3 values: u stride 3, v stride 6; the last point starts at 3 + 6.
/// assert_eq!(map2_values(GL_MAP2_VERTEX_3, 3, 2, 6, 2), 3 + 6 + 3);
/// ```
pub fn map2_values(
    target: GLenum,
    ustride: GLint,
    uorder: GLint,
    vstride: GLint,
    vorder: GLint,
) -> usize {
    map_values(target, 2, [ustride, vstride], [uorder, vorder])
}

fn map_values(target: GLenum, dimensions: usize, strides: [GLint; 2], orders: [GLint; 2]) -> usize {
    let Ok(kind) = map_kind(target, dimensions) else {
        return 0;
    };
    let k = values_per_point(kind) as i64;
    let mut last = 0i64;
    for (stride, order) in strides.into_iter().zip(orders).take(dimensions) {
        if order < 1 || order as usize > MAX_EVAL_ORDER || i64::from(stride) < k {
            return 0;
        }
        last += i64::from(stride) * i64::from(order - 1);
    }
    usize::try_from(last + k).unwrap_or(0)
}

impl Maps {
    /// glMap1 / glMap2 (§5.1): Mesa's order of checks (the target, the domain, the orders,
    /// the strides). `points` holds the values `map_values` counts (fewer: a NULL pointer,
    /// GL_INVALID_VALUE).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::eval::Maps, GlError};
    /// let mut maps = Maps::default();
    /// maps.set(GL_MAP1_COLOR_4, 1, [0.0, 1.0, 0.0, 0.0], [4, 0], [1, 0], &[1.0, 0.0, 0.0, 1.0])?;
    /// assert_eq!(maps.get(GL_MAP1_COLOR_4, GL_COEFF)?, [1.0, 0.0, 0.0, 1.0]);
    /// // u1 = u2 is GL_INVALID_VALUE.
    /// assert_eq!(maps.set(GL_MAP1_COLOR_4, 1, [1.0, 1.0, 0.0, 0.0], [4, 0], [1, 0], &[0.0; 4]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(
        &mut self,
        target: GLenum,
        dimensions: usize,
        domain: [f64; 4],
        strides: [GLint; 2],
        orders: [GLint; 2],
        points: &[f64],
    ) -> GlResult {
        let kind = map_kind(target, dimensions)?;
        let k = values_per_point(kind);
        for d in 0..dimensions {
            if domain[2 * d] == domain[2 * d + 1] {
                return Err(GlError::InvalidValue);
            }
            if orders[d] < 1 || orders[d] as usize > MAX_EVAL_ORDER {
                return Err(GlError::InvalidValue);
            }
            if (strides[d] as i64) < k as i64 {
                return Err(GlError::InvalidValue);
            }
        }
        let count = map_values(target, dimensions, strides, orders);
        if points.len() < count {
            return Err(GlError::InvalidValue);
        }
        let order = [
            orders[0] as usize,
            if dimensions == 2 {
                orders[1] as usize
            } else {
                1
            },
        ];
        let mut compact = Vec::with_capacity(order[0] * order[1] * k);
        for i in 0..order[0] {
            for j in 0..order[1] {
                let at = i * strides[0] as usize + j * strides[1].max(0) as usize;
                compact.extend(points[at..at + k].iter().map(|&v| v as f32));
            }
        }
        let domain = if dimensions == 1 {
            [domain[0], domain[1], 0.0, 1.0]
        } else {
            domain
        };
        self.maps[dimensions - 1][kind] = Map {
            order,
            domain: domain.map(|d| d as f32 as f64),
            points: compact,
        };
        Ok(())
    }

    /// glGetMap (§6.1.3): GL_COEFF, GL_ORDER or GL_DOMAIN of a map.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::eval::Maps};
    /// let maps = Maps::default();
    /// assert_eq!(maps.get(GL_MAP2_TEXTURE_COORD_2, GL_ORDER)?, [1.0, 1.0]);
    /// assert_eq!(maps.get(GL_MAP2_TEXTURE_COORD_2, GL_DOMAIN)?, [0.0, 1.0, 0.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get(&self, target: GLenum, query: GLenum) -> GlResult<Vec<f64>> {
        let dimensions = if map_kind(target, 1).is_ok() { 1 } else { 2 };
        let map = &self.maps[dimensions - 1][map_kind(target, dimensions)?];
        Ok(match query {
            GL_COEFF => map.points.iter().map(|&v| f64::from(v)).collect(),
            GL_ORDER => map.order[..dimensions].iter().map(|&o| o as f64).collect(),
            GL_DOMAIN => map.domain[..2 * dimensions].to_vec(),
            _ => return Err(GlError::InvalidEnum),
        })
    }
}

/// A map evaluated at a domain point: its k values and, for two-dimensional maps, their
/// partial derivatives with respect to the domain coordinates u and v (for automatic
/// normals).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Evaluated {
    /// The k values at the point.
    pub value: [f64; 4],
    /// Their derivatives with respect to u.
    pub du: [f64; 4],
    /// Their derivatives with respect to v.
    pub dv: [f64; 4],
}

/// De Casteljau's algorithm on `points` (k values each) at `t`: the value and the
/// derivative with respect to t.
fn de_casteljau(points: &mut [[f64; 4]], t: f64) -> ([f64; 4], [f64; 4]) {
    let n = points.len();
    let mut derivative = [0.0; 4];
    for level in 1..n {
        if level == n - 1 {
            derivative = std::array::from_fn(|c| (n - 1) as f64 * (points[1][c] - points[0][c]));
        }
        for i in 0..n - level {
            let next = points[i + 1];
            for (value, next) in points[i].iter_mut().zip(next) {
                *value = (1.0 - t) * *value + t * next;
            }
        }
    }
    (points[0], derivative)
}

impl Map {
    /// The map at domain point (u, v) (§5.1: p((u - u1) / (u2 - u1), (v - v1) / (v2 - v1))),
    /// with the derivatives of the value with respect to u and v themselves.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::eval::{Maps, VERTEX_3}};
    /// let mut maps = Maps::default();
    /// // A quadratic curve through (0, 0, 0), control (1, 2, 0), (2, 0, 0).
    /// let points = [0.0, 0.0, 0.0, 1.0, 2.0, 0.0, 2.0, 0.0, 0.0];
    /// maps.set(GL_MAP1_VERTEX_3, 1, [0.0, 1.0, 0.0, 0.0], [3, 0], [3, 0], &points)?;
    /// let at = maps.maps[0][VERTEX_3].evaluate(3, 0.5, 0.0);
    /// assert_eq!(&at.value[..3], [1.0, 1.0, 0.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn evaluate(&self, k: usize, u: f64, v: f64) -> Evaluated {
        let [u1, u2, v1, v2] = self.domain;
        let s = (u - u1) / (u2 - u1);
        let t = (v - v1) / (v2 - v1);
        let [uorder, vorder] = self.order;
        let point = |i: usize, j: usize| {
            let at = (i * vorder + j) * k;
            let mut p = [0.0; 4];
            for (c, value) in self.points[at..at + k].iter().enumerate() {
                p[c] = f64::from(*value);
            }
            p
        };
        // Along v first, one curve a column; then along u through the columns and their
        // v-derivatives.
        let mut columns = Vec::with_capacity(uorder);
        let mut column_dv = Vec::with_capacity(uorder);
        for i in 0..uorder {
            let mut row: Vec<[f64; 4]> = (0..vorder).map(|j| point(i, j)).collect();
            let (value, derivative) = de_casteljau(&mut row, t);
            columns.push(value);
            column_dv.push(derivative);
        }
        let (value, ds) = de_casteljau(&mut columns, s);
        let (dt, _) = de_casteljau(&mut column_dv, s);
        // The chain rule: d/du = d/ds / (u2 - u1).
        Evaluated {
            value,
            du: ds.map(|d| d / (u2 - u1)),
            dv: dt.map(|d| d / (v2 - v1)),
        }
    }
}
