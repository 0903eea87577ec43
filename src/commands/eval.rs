//! Evaluators (§5.1): glMap1, glMap2, glMapGrid, glEvalCoord, glEvalPoint, glEvalMesh and
//! glGetMap. Evaluated vertices go through the same path as glVertex.

use glam::{DVec3, Vec3, Vec4};

use crate::commands::vertex::Varying;
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::eval::{
    COLOR_4, Evaluated, Grid, NORMAL, TEXTURE_COORD_1, VERTEX_3, VERTEX_4, values_per_point,
};

/// A domain coordinate of a grid: `i` steps of (end - start) / n from start, exactly start
/// and end at 0 and n (§5.1's requirement).
fn grid_coordinate(i: i32, n: i32, start: f64, end: f64) -> f64 {
    if i == n {
        end
    } else {
        start + f64::from(i) * (end - start) / f64::from(n)
    }
}

impl Context {
    /// glMap1{fd} / glMap2{fd} (§5.1). GL_INVALID_OPERATION inside glBegin/glEnd and when the
    /// active texture unit is not GL_TEXTURE0.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// // A line from (0, 0, 0) to (2, 0, 0) over u in [0, 1].
    /// let points = [0.0f32, 0.0, 0.0, 2.0, 0.0, 0.0];
    /// ctx.map(GL_MAP1_VERTEX_3, 1, [0.0, 1.0, 0.0, 0.0], [3, 0], [2, 0], &points)?;
    /// ctx.set_capability(GL_MAP1_VERTEX_3, true)?;
    /// ctx.capture_begin()?;
    /// ctx.begin(GL_POINTS)?;
    /// ctx.eval_coord(1, 0.25, 0.0);
    /// ctx.end()?;
    /// ctx.capture_end()?;
    /// assert_eq!(ctx.captured().vertices()[0].eye.x, 0.5);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn map<T: Into<f64> + Copy>(
        &mut self,
        target: GLenum,
        dimensions: usize,
        domain: [f64; 4],
        strides: [GLint; 2],
        orders: [GLint; 2],
        points: &[T],
    ) -> GlResult {
        self.outside_begin_end()?;
        crate::state::eval::map_kind(target, dimensions)?;
        if self.textures.active_unit != 0 {
            return Err(GlError::InvalidOperation);
        }
        let points: Vec<f64> = points.iter().map(|&v| v.into()).collect();
        self.maps
            .set(target, dimensions, domain, strides, orders, &points)
    }

    /// glGetMap{fdi}v.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.map(GL_MAP1_INDEX, 1, [1.0, 3.0, 0.0, 0.0], [1, 0], [2, 0], &[5.0f64, 6.0])?;
    /// assert_eq!(ctx.get_map(GL_MAP1_INDEX, GL_ORDER)?, [2.0]);
    /// assert_eq!(ctx.get_map(GL_MAP1_INDEX, GL_DOMAIN)?, [1.0, 3.0]);
    /// assert_eq!(ctx.get_map(GL_MAP1_INDEX, GL_COEFF)?, [5.0, 6.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_map(&self, target: GLenum, query: GLenum) -> GlResult<Vec<f64>> {
        self.outside_begin_end()?;
        self.maps.get(target, query)
    }

    /// glGetMapiv: values rounded to the nearest integer (§6.1.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// // The initial map: order 1, domain [0, 1], the default normal (0, 0, 1).
    /// assert_eq!(ctx.get_map_i(GL_MAP1_NORMAL, GL_COEFF)?, [0, 0, 1]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_map_i(&self, target: GLenum, query: GLenum) -> GlResult<Vec<GLint>> {
        let values = self.get_map(target, query)?;
        Ok(values.into_iter().map(|v| v.round() as GLint).collect())
    }

    /// glMapGrid1 / glMapGrid2: GL_INVALID_VALUE for a segment count of 0 or less.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.map_grid(1, [4, 0], [0.0, 1.0, 0.0, 0.0])?;
    /// assert_eq!(ctx.get(GL_MAP1_GRID_SEGMENTS)?.as_ints(), [4]);
    /// assert_eq!(ctx.map_grid(2, [0, 1], [0.0, 1.0, 0.0, 1.0]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn map_grid(
        &mut self,
        dimensions: usize,
        segments: [i32; 2],
        domain: [f64; 4],
    ) -> GlResult {
        self.outside_begin_end()?;
        if segments[..dimensions].iter().any(|&n| n <= 0) {
            return Err(GlError::InvalidValue);
        }
        let grid = &mut self.eval.grids[dimensions - 1];
        grid.segments[..dimensions].copy_from_slice(&segments[..dimensions]);
        for (to, from) in grid.domain.iter_mut().zip(domain).take(2 * dimensions) {
            *to = from as f32 as f64;
        }
        Ok(())
    }

    /// glEvalCoord1 / glEvalCoord2 (§5.1): the enabled maps of the dimension at (u, v); with no
    /// vertex map enabled nothing happens. The evaluated color, normal and texture
    /// coordinates replace the current ones for this vertex only: the current values, and
    /// the material color material tracks, stay as they are.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.capture_begin()?;
    /// ctx.begin(GL_POINTS)?;
    /// ctx.eval_coord(1, 0.5, 0.0); // no vertex map enabled: nothing happens
    /// ctx.end()?;
    /// ctx.capture_end()?;
    /// assert!(ctx.captured().vertices().is_empty());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn eval_coord(&mut self, dimensions: usize, u: f64, v: f64) {
        let enabled = self.eval.enabled[dimensions - 1];
        let maps = &self.maps.maps[dimensions - 1];
        let evaluate = |kind: usize| maps[kind].evaluate(values_per_point(kind), u, v);
        let vertex = if enabled[VERTEX_4] {
            let p = evaluate(VERTEX_4);
            (Vec4::from_array(p.value.map(|c| c as f32)), Some(p), true)
        } else if enabled[VERTEX_3] {
            let p = evaluate(VERTEX_3);
            let [x, y, z, _] = p.value;
            (Vec4::new(x as f32, y as f32, z as f32, 1.0), Some(p), false)
        } else {
            return;
        };
        let (position, evaluated, homogeneous) = vertex;
        let saved = self.current;
        // Set for this vertex and back after it: glVertex writes them into its lane, from
        // here to glEnd.
        self.varying.insert(Varying::COLOR);
        self.varying.insert(Varying::NORMAL);
        self.varying.insert(Varying::TEX_COORD);
        if enabled[COLOR_4] {
            self.current.color = Vec4::from_array(evaluate(COLOR_4).value.map(|c| c as f32));
        }
        let auto_normal = dimensions == 2 && self.enables.other(GL_AUTO_NORMAL);
        if auto_normal {
            if let Some(p) = evaluated {
                self.current.normal = surface_normal(&p, homogeneous);
            }
        } else if enabled[NORMAL] {
            let [x, y, z, _] = evaluate(NORMAL).value;
            self.current.normal = Vec3::new(x as f32, y as f32, z as f32);
        }
        // The texture coordinate map with the most coordinates, as glTexCoord would give it.
        if let Some(kind) = (TEXTURE_COORD_1..TEXTURE_COORD_1 + 4)
            .rev()
            .find(|&kind| enabled[kind])
        {
            let mut coords = [0.0, 0.0, 0.0, 1.0];
            let value = evaluate(kind).value;
            let n = values_per_point(kind);
            for (to, from) in coords.iter_mut().zip(value).take(n) {
                *to = from as f32;
            }
            self.current.tex_coord = Vec4::from_array(coords);
        }
        self.vertex(position);
        self.current.color = saved.color;
        self.current.normal = saved.normal;
        self.current.tex_coord = saved.tex_coord;
    }

    /// glEvalCoord{12}{fd}v: GL_INVALID_VALUE for a NULL (empty) vector.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.eval_coord_v::<f32>(2, &[]), Err(GlError::InvalidValue));
    /// ```
    pub fn eval_coord_v<T: Into<f64> + Copy>(&mut self, dimensions: usize, v: &[T]) -> GlResult {
        let coords = v.get(..dimensions).ok_or(GlError::InvalidValue)?;
        let u = coords[0].into();
        let v = coords.get(1).map_or(0.0, |&v| v.into());
        self.eval_coord(dimensions, u, v);
        Ok(())
    }

    /// glEvalPoint1 / glEvalPoint2: the grid's point (i, j).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.map(GL_MAP1_VERTEX_4, 1, [0.0, 1.0, 0.0, 0.0], [4, 0], [2, 0], &[0.0f32, 0.0, 0.0, 1.0, 4.0, 0.0, 0.0, 1.0])?;
    /// ctx.set_capability(GL_MAP1_VERTEX_4, true)?;
    /// ctx.map_grid(1, [4, 0], [0.0, 1.0, 0.0, 0.0])?;
    /// ctx.capture_begin()?;
    /// ctx.begin(GL_POINTS)?;
    /// ctx.eval_point(1, 1, 0); // u = 1/4
    /// ctx.end()?;
    /// ctx.capture_end()?;
    /// assert_eq!(ctx.captured().vertices()[0].eye.x, 1.0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn eval_point(&mut self, dimensions: usize, i: i32, j: i32) {
        let Grid { segments, domain } = self.eval.grids[dimensions - 1];
        let u = grid_coordinate(i, segments[0], domain[0], domain[1]);
        let v = grid_coordinate(j, segments[1], domain[2], domain[3]);
        self.eval_coord(dimensions, u, v);
    }

    /// glEvalMesh1 (§5.1): GL_POINT or GL_LINE, points i1 to i2 of the grid as GL_POINTS or a
    /// GL_LINE_STRIP.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.map(GL_MAP1_VERTEX_3, 1, [0.0, 1.0, 0.0, 0.0], [3, 0], [2, 0], &[0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0])?;
    /// ctx.set_capability(GL_MAP1_VERTEX_3, true)?;
    /// ctx.map_grid(1, [4, 0], [0.0, 1.0, 0.0, 0.0])?;
    /// ctx.capture_begin()?;
    /// ctx.eval_mesh1(GL_LINE, 0, 4)?; // a line strip of 5 points
    /// ctx.capture_end()?;
    /// assert_eq!(ctx.captured().primitives().len(), 4);
    /// assert_eq!(ctx.eval_mesh1(GL_FILL, 0, 4), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn eval_mesh1(&mut self, mode: GLenum, i1: i32, i2: i32) -> GlResult {
        self.outside_begin_end()?;
        let primitive = match mode {
            GL_POINT => GL_POINTS,
            GL_LINE => GL_LINE_STRIP,
            _ => return Err(GlError::InvalidEnum),
        };
        self.begin(primitive)?;
        for i in i1..=i2 {
            self.eval_point(1, i, 0);
        }
        self.end()
    }

    /// glEvalMesh2 (§5.1): GL_FILL as a GL_QUAD_STRIP a grid row, GL_LINE as line strips
    /// along both directions, GL_POINT as points, over grid points (i1..i2, j1..j2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// // A flat 2 x 2 control net: the unit square at z = 0.
    /// let net = [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0];
    /// ctx.map(GL_MAP2_VERTEX_3, 2, [0.0, 1.0, 0.0, 1.0], [3, 6], [2, 2], &net)?;
    /// ctx.set_capability(GL_MAP2_VERTEX_3, true)?;
    /// ctx.map_grid(2, [2, 2], [0.0, 1.0, 0.0, 1.0])?;
    /// ctx.capture_begin()?;
    /// ctx.eval_mesh2(GL_FILL, [0, 2], [0, 2])?; // 2 x 2 cells, two triangles each
    /// ctx.capture_end()?;
    /// assert_eq!(ctx.captured().primitives().len(), 8);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn eval_mesh2(&mut self, mode: GLenum, [i1, i2]: [i32; 2], [j1, j2]: [i32; 2]) -> GlResult {
        self.outside_begin_end()?;
        // An empty range in either direction makes only empty strips: skip the up to 2^32
        // of them a hostile range would begin and end one by one (found by the sweep).
        if i1 > i2 || j1 > j2 {
            return match mode {
                GL_FILL | GL_LINE | GL_POINT => Ok(()),
                _ => Err(GlError::InvalidEnum),
            };
        }
        match mode {
            GL_FILL => {
                for j in j1..j2 {
                    self.begin(GL_QUAD_STRIP)?;
                    for i in i1..=i2 {
                        self.eval_point(2, i, j);
                        self.eval_point(2, i, j + 1);
                    }
                    self.end()?;
                }
            }
            GL_LINE => {
                for j in j1..=j2 {
                    self.begin(GL_LINE_STRIP)?;
                    for i in i1..=i2 {
                        self.eval_point(2, i, j);
                    }
                    self.end()?;
                }
                for i in i1..=i2 {
                    self.begin(GL_LINE_STRIP)?;
                    for j in j1..=j2 {
                        self.eval_point(2, i, j);
                    }
                    self.end()?;
                }
            }
            GL_POINT => {
                self.begin(GL_POINTS)?;
                for j in j1..=j2 {
                    for i in i1..=i2 {
                        self.eval_point(2, i, j);
                    }
                }
                self.end()?;
            }
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }
}

/// GL_AUTO_NORMAL's normal (§5.1): the cross product of the partial derivatives of q, the
/// vertex map's point (divided by w for GL_MAP2_VERTEX_4), normalized.
fn surface_normal(p: &Evaluated, homogeneous: bool) -> Vec3 {
    let xyz = |v: [f64; 4]| DVec3::new(v[0], v[1], v[2]);
    let (du, dv) = if homogeneous {
        // d(x/w) = (dx w - x dw) / w^2; the common 1/w^2 does not change the direction.
        let w = p.value[3];
        let q = xyz(p.value);
        (xyz(p.du) * w - q * p.du[3], xyz(p.dv) * w - q * p.dv[3])
    } else {
        (xyz(p.du), xyz(p.dv))
    };
    du.cross(dv).normalize_or_zero().as_vec3()
}
