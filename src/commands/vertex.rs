//! Current attributes, glBegin / glEnd and glVertex (§2.6-2.7).

use glam::{Vec3, Vec4};

use crate::context::{Context, PrimitiveInProgress};
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::pipeline::block::InputBlock;
use crate::state::convert::Component;

impl Context {
    /// glColor: also sets the material properties that an enabled color material tracks.
    pub fn color(&mut self, color: Vec4) {
        self.current.color = color;
        if self.color_material.enabled {
            self.apply_color_material();
        }
    }

    /// glSecondaryColor3 (§2.7): the alpha of the current secondary color stays 1.
    pub fn secondary_color(&mut self, [red, green, blue]: [f32; 3]) {
        self.current.secondary_color = Vec4::new(red, green, blue, 1.0);
    }

    /// glSecondaryColor3 from integer or float components, converted per table 2.9.
    pub fn secondary_color_of<T: Component>(&mut self, components: [T; 3]) {
        self.secondary_color(components.map(Component::normalized));
    }

    /// glSecondaryColor3v: GL_INVALID_VALUE for a NULL (empty) vector.
    pub fn secondary_color_v<T: Component>(&mut self, v: &[T]) -> GlResult {
        let components: [T; 3] = v.try_into().map_err(|_| GlError::InvalidValue)?;
        self.secondary_color_of(components);
        Ok(())
    }

    /// glIndex (§2.7): the current color index, which RGBA mode never uses.
    pub fn index(&mut self, index: f32) {
        self.current.index = index;
    }

    /// glIndexv: GL_INVALID_VALUE for a NULL (empty) vector.
    pub fn index_v<T: Component>(&mut self, v: &[T]) -> GlResult {
        let [index]: [T; 1] = v.try_into().map_err(|_| GlError::InvalidValue)?;
        self.index(index.direct());
        Ok(())
    }

    /// glFogCoord (§2.7).
    pub fn fog_coord(&mut self, coord: f32) {
        self.current.fog_coord = coord;
    }

    /// glFogCoordv: GL_INVALID_VALUE for a NULL (empty) vector.
    pub fn fog_coord_v<T: Component>(&mut self, v: &[T]) -> GlResult {
        let [coord]: [T; 1] = v.try_into().map_err(|_| GlError::InvalidValue)?;
        self.fog_coord(coord.direct());
        Ok(())
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
        let stream = self.begin_stream(mode);
        self.primitive = Some(Box::new(PrimitiveInProgress {
            pending: InputBlock::default(),
            stream,
        }));
        Ok(())
    }

    /// glEnd: the last vertices are processed and the draw ends.
    pub fn end(&mut self) -> GlResult {
        self.flush_vertices();
        let primitive = self.primitive.take().ok_or(GlError::InvalidOperation)?;
        self.end_stream(primitive.stream);
        Ok(())
    }

    /// glVertex: the vertex joins the block of pending vertices with the current attributes;
    /// a full block is transformed, lit and assembled. Outside glBegin/glEnd it has no effect
    /// (§2.6.3 leaves it undefined).
    pub fn vertex(&mut self, object: Vec4) {
        if !self.vertices_observed() {
            return;
        }
        let Some(primitive) = &mut self.primitive else {
            return;
        };
        primitive.pending.push(object, &self.current);
        if primitive.pending.is_full() {
            self.flush_vertices();
        }
    }

    /// Processes the pending vertices of the primitive in progress, in order, with the state
    /// in force: before anything changes that state between glBegin and glEnd (glMaterial),
    /// when the block fills, and at glEnd.
    pub(crate) fn flush_vertices(&mut self) {
        let Some(mut primitive) = self.primitive.take() else {
            return;
        };
        if primitive.pending.len > 0 {
            let derived = self.shared_derived();
            self.stream_block(&mut primitive.stream, &derived, &primitive.pending);
            primitive.pending.len = 0;
        }
        self.primitive = Some(primitive);
    }
}
