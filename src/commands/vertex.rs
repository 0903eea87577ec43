//! Current attributes, glBegin / glEnd and glVertex (§2.6-2.7).

use glam::{Vec3, Vec4};

use crate::context::{Context, PrimitiveInProgress};
use crate::error::{GlError, GlResult};
use crate::gl::*;

impl Context {
    /// glColor: also sets the material properties that an enabled color material tracks.
    pub fn color(&mut self, color: Vec4) {
        self.current.color = color;
        if self.color_material.enabled {
            self.apply_color_material();
        }
    }

    /// glNormal.
    pub fn normal(&mut self, normal: Vec3) {
        self.current.normal = normal;
    }

    /// glTexCoord.
    pub fn tex_coord(&mut self, tex_coord: Vec4) {
        self.current.tex_coord = tex_coord;
    }

    /// glEdgeFlag.
    pub fn edge_flag(&mut self, flag: bool) {
        self.current.edge_flag = flag;
    }

    /// glBegin (§2.6.1).
    pub fn begin(&mut self, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        if mode > GL_POLYGON {
            return Err(GlError::InvalidEnum);
        }
        self.primitive = Some(PrimitiveInProgress {
            mode,
            vertices: Vec::new(),
        });
        Ok(())
    }

    /// glEnd: assembles the primitives of the vertices given since glBegin.
    pub fn end(&mut self) -> GlResult {
        let primitive = self.primitive.take().ok_or(GlError::InvalidOperation)?;
        self.draw_vertices(primitive.mode, &primitive.vertices);
        Ok(())
    }

    /// glVertex: the vertex is transformed and lit with the current attributes now. Outside
    /// glBegin/glEnd it has no effect (§2.6.3 leaves it undefined).
    pub fn vertex(&mut self, object: Vec4) {
        if self.primitive.is_none() || !self.vertices_observed() {
            return;
        }
        let attribs = self.current;
        let vertex = self.derived().process(object, &attribs);
        if let Some(primitive) = &mut self.primitive {
            primitive.vertices.push(vertex);
        }
    }
}
