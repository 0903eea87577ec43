//! Current attributes, glBegin / glEnd and glVertex (§2.6-2.7).

use glam::{Vec3, Vec4};

use crate::context::{Context, PrimitiveInProgress};
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::convert::Component;

impl Context {
    /// glColor: also sets the material properties that an enabled color material tracks.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.color(glam::Vec4::new(1.0, 0.5, 0.0, 1.0));
    /// assert_eq!(ctx.get(GL_CURRENT_COLOR)?.as_floats(), [1.0, 0.5, 0.0, 1.0]);
    /// // With color material on, the color also becomes the tracked material property.
    /// ctx.color_material(GL_FRONT, GL_EMISSION)?;
    /// ctx.set_capability(GL_COLOR_MATERIAL, true)?;
    /// ctx.color(glam::Vec4::new(0.0, 0.0, 1.0, 1.0));
    /// assert_eq!(ctx.get_material(GL_FRONT, GL_EMISSION)?.0, glam::Vec4::new(0.0, 0.0, 1.0, 1.0));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn color(&mut self, color: Vec4) {
        self.current.color = color;
        if self.color_material.enabled {
            self.apply_color_material();
        }
    }

    /// glSecondaryColor3 (§2.7): the alpha of the current secondary color stays 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.secondary_color([0.25, 0.5, 0.75]);
    /// assert_eq!(ctx.get(GL_CURRENT_SECONDARY_COLOR)?.as_floats(), [0.25, 0.5, 0.75, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn secondary_color(&mut self, [red, green, blue]: [f32; 3]) {
        self.current.secondary_color = Vec4::new(red, green, blue, 1.0);
    }

    /// glSecondaryColor3 from integer or float components, converted per table 2.9.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.secondary_color_of([255u8, 0, 255]); // glSecondaryColor3ub
    /// assert_eq!(ctx.get(GL_CURRENT_SECONDARY_COLOR)?.as_floats(), [1.0, 0.0, 1.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn secondary_color_of<T: Component>(&mut self, components: [T; 3]) {
        self.secondary_color(components.map(Component::normalized));
    }

    /// glSecondaryColor3v: GL_INVALID_VALUE for a NULL (empty) vector.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.secondary_color_v(&[0u16, 65535, 0])?; // glSecondaryColor3usv
    /// assert_eq!(ctx.get(GL_CURRENT_SECONDARY_COLOR)?.as_floats(), [0.0, 1.0, 0.0, 1.0]);
    /// assert_eq!(ctx.secondary_color_v::<f32>(&[]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn secondary_color_v<T: Component>(&mut self, v: &[T]) -> GlResult {
        let components: [T; 3] = v.try_into().map_err(|_| GlError::InvalidValue)?;
        self.secondary_color_of(components);
        Ok(())
    }

    /// glIndex (§2.7): the current color index, which RGBA mode never uses.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.index(3.0);
    /// assert_eq!(ctx.get(GL_CURRENT_INDEX)?.as_floats(), [3.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn index(&mut self, index: f32) {
        self.current.index = index;
    }

    /// glIndexv: GL_INVALID_VALUE for a NULL (empty) vector.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.index_v(&[7i16])?; // glIndexsv: converted directly, not normalized
    /// assert_eq!(ctx.get(GL_CURRENT_INDEX)?.as_floats(), [7.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn index_v<T: Component>(&mut self, v: &[T]) -> GlResult {
        let [index]: [T; 1] = v.try_into().map_err(|_| GlError::InvalidValue)?;
        self.index(index.direct());
        Ok(())
    }

    /// glFogCoord (§2.7).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.fog_coord(2.5);
    /// assert_eq!(ctx.get(GL_CURRENT_FOG_COORD)?.as_floats(), [2.5]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn fog_coord(&mut self, coord: f32) {
        self.current.fog_coord = coord;
    }

    /// glFogCoordv: GL_INVALID_VALUE for a NULL (empty) vector.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.fog_coord_v(&[4.0f64])?; // glFogCoorddv
    /// assert_eq!(ctx.get(GL_CURRENT_FOG_COORD)?.as_floats(), [4.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn fog_coord_v<T: Component>(&mut self, v: &[T]) -> GlResult {
        let [coord]: [T; 1] = v.try_into().map_err(|_| GlError::InvalidValue)?;
        self.fog_coord(coord.direct());
        Ok(())
    }

    /// glNormal.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.get(GL_CURRENT_NORMAL)?.as_floats(), [0.0, 0.0, 1.0]);
    /// ctx.normal(glam::Vec3::new(0.0, 2.0, 0.0)); // kept as given; GL_NORMALIZE acts per vertex
    /// assert_eq!(ctx.get(GL_CURRENT_NORMAL)?.as_floats(), [0.0, 2.0, 0.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn normal(&mut self, normal: Vec3) {
        self.current.normal = normal;
    }

    /// glTexCoord.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.tex_coord(glam::Vec4::new(0.5, 0.25, 0.0, 1.0));
    /// assert_eq!(ctx.get(GL_CURRENT_TEXTURE_COORDS)?.as_floats(), [0.5, 0.25, 0.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_coord(&mut self, tex_coord: Vec4) {
        self.current.tex_coord = tex_coord;
    }

    /// glEdgeFlag.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.edge_flag(false);
    /// assert_eq!(ctx.get(GL_EDGE_FLAG)?.as_bools(), [false]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn edge_flag(&mut self, flag: bool) {
        self.current.edge_flag = flag;
    }

    /// glBegin (§2.6.1).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.begin(GL_POLYGON + 1), Err(GlError::InvalidEnum));
    /// ctx.begin(GL_TRIANGLES)?;
    /// assert_eq!(ctx.begin(GL_TRIANGLES), Err(GlError::InvalidOperation)); // already begun
    /// ctx.end()?;
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn begin(&mut self, mode: GLenum) -> GlResult {
        self.outside_begin_end()?;
        if mode > GL_POLYGON {
            return Err(GlError::InvalidEnum);
        }
        let stream = self.begin_stream(mode);
        let units = self.pending_units();
        self.primitive = Some(Box::new(PrimitiveInProgress {
            pending: Default::default(),
            filling: 0,
            stream,
            units,
        }));
        Ok(())
    }

    /// glEnd: the last vertices are processed and the draw ends.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.end(), Err(GlError::InvalidOperation)); // no glBegin
    /// ctx.begin(GL_LINES)?;
    /// ctx.vertex(glam::Vec4::new(0.0, 0.0, 0.0, 1.0)); // an incomplete line: dropped at glEnd
    /// ctx.end()?;
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn end(&mut self) -> GlResult {
        self.flush_vertices();
        let primitive = self.primitive.take().ok_or(GlError::InvalidOperation)?;
        self.end_stream(primitive.stream);
        Ok(())
    }

    /// glVertex: the vertex joins the block of pending vertices with the current attributes;
    /// a full block is transformed, lit and assembled. Outside glBegin/glEnd it has no effect
    /// (§2.6.3 leaves it undefined).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// use glam::Vec4;
    /// let mut ctx = Context::new();
    /// ctx.viewport(0, 0, 100, 100)?;
    /// ctx.feedback_buffer(64, GL_3D, 1)?; // the address only matters to the C layer
    /// ctx.render_mode(GL_FEEDBACK)?;
    /// ctx.begin(GL_POINTS)?;
    /// ctx.vertex(Vec4::new(0.5, -0.5, 0.0, 1.0));
    /// ctx.end()?;
    /// let (count, finished) = ctx.render_mode(GL_RENDER)?;
    /// // GL_POINT_TOKEN, then the window coordinates x y z.
    /// assert_eq!(count, 4);
    /// assert_eq!(finished.unwrap().values, [GL_POINT_TOKEN as f32, 75.0, 25.0, 0.5]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn vertex(&mut self, object: Vec4) {
        if !self.vertices_observed() {
            return;
        }
        let Some(primitive) = &mut self.primitive else {
            return;
        };
        let block = &mut primitive.pending[primitive.filling];
        if let Some(units) = &mut primitive.units {
            units.set(block.len, &self.current.other_tex_coords);
        }
        block.push(object, &self.current);
        if block.is_full() {
            // Capture records units 1 and up a block at a time.
            if primitive.units.is_none() && primitive.filling + 1 < primitive.pending.len() {
                primitive.filling += 1;
            } else {
                self.flush_vertices();
            }
        }
    }

    /// Processes the pending vertices of the primitive in progress, in order, with the state
    /// in force: before anything changes that state between glBegin and glEnd (glMaterial),
    /// when the block fills, and at glEnd.
    pub(crate) fn flush_vertices(&mut self) {
        let Some(mut primitive) = self.primitive.take() else {
            return;
        };
        let used = primitive.filling + usize::from(primitive.pending[primitive.filling].len > 0);
        if used > 0 {
            let derived = self.shared_derived();
            self.stream_blocks(&mut primitive.stream, &derived, &primitive.pending[..used]);
            if let Some(units) = &primitive.units {
                units.capture_block(&primitive.pending[0], &mut self.capture);
            }
            for block in &mut primitive.pending[..used] {
                block.len = 0;
            }
            primitive.filling = 0;
        }
        self.primitive = Some(primitive);
    }
}
