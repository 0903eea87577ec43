//! The current raster position (§2.13): glRasterPos processes one position like a vertex and
//! keeps the result for the queries of §6.1.

use glam::{DVec3, DVec4, Vec4};

use crate::context::{Context, RenderMode};
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::lighting::batch::process_vertex;
use crate::lighting::clamp01;
use crate::pipeline::clip::point_visible;
use crate::pipeline::feedback::FeedbackVertex;
use crate::state::texgen::GenInput;
use crate::state::texture::MAX_TEXTURE_UNITS;
use crate::state::texture_image::{format_components, pixel_type};

/// The current raster position and the attributes it carries (table 6.5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterPosition {
    /// Window x, y, z and the clip w.
    pub window: Vec4,
    /// GL_CURRENT_RASTER_POSITION_VALID.
    pub valid: bool,
    /// The front primary color, lit when lighting is on.
    pub color: Vec4,
    /// The front secondary color, lit when lighting is on.
    pub secondary_color: Vec4,
    /// Texture unit 0's texture coordinates, generated and through the texture matrix.
    pub tex_coord: Vec4,
    /// Texture units 1 and up's.
    pub other_tex_coords: [Vec4; MAX_TEXTURE_UNITS - 1],
    /// The eye-space distance from the origin to the position.
    pub distance: f32,
}

impl Default for RasterPosition {
    fn default() -> RasterPosition {
        RasterPosition {
            window: Vec4::W,
            valid: true,
            color: Vec4::ONE,
            secondary_color: Vec4::W,
            tex_coord: Vec4::W,
            other_tex_coords: [Vec4::W; MAX_TEXTURE_UNITS - 1],
            distance: 0.0,
        }
    }
}

impl RasterPosition {
    /// Texture unit `unit`'s texture coordinates.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.multi_tex_coord(GL_TEXTURE1, glam::Vec4::new(0.5, 0.5, 0.0, 1.0))?;
    /// ctx.raster_pos(glam::Vec4::W)?;
    /// // The raster position carries each unit's coordinates.
    /// ctx.active_texture(GL_TEXTURE1)?;
    /// assert_eq!(ctx.get(GL_CURRENT_RASTER_TEXTURE_COORDS)?.as_floats(), [0.5, 0.5, 0.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn unit_tex_coord(&self, unit: usize) -> Vec4 {
        match unit {
            0 => self.tex_coord,
            _ => self.other_tex_coords[unit - 1],
        }
    }
}

impl Context {
    /// Texture unit `unit`'s texture coordinates for a vertex at `object` (eye coordinates
    /// `eye`) with eye-space normal `normal` (§2.11.4, §2.11.2): what the vertex path
    /// computes for unit 0.
    fn unit_tex_coord(&self, unit: usize, object: Vec4, eye: DVec4, normal: DVec3) -> Vec4 {
        let current = self.current.unit_tex_coord(unit);
        let coords = match self.textures.units[unit].tex_gen.prepared() {
            None => current,
            Some(tex_gen) => {
                let input = GenInput {
                    object: object.as_dvec4(),
                    eye,
                    normal,
                };
                tex_gen.generate(&input, current)
            }
        };
        *self.matrices.texture[unit].top() * coords
    }

    /// glRasterPos (§2.13): the position is transformed and lit as a vertex with the current
    /// normal, colors and texture coordinate, then clipped as a point against the view volume
    /// and the enabled user clip planes. If culled, the raster position becomes invalid and
    /// its other values stay as they were. In selection mode a valid position is a hit (§5.2);
    /// in feedback mode it emits nothing (GL_BITMAP_TOKEN and GL_DRAW_PIXEL_TOKEN belong to
    /// glBitmap and glDrawPixels).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.viewport(0, 0, 100, 100)?;
    /// ctx.raster_pos(glam::Vec4::new(0.5, 0.0, 0.0, 1.0))?;
    /// assert_eq!(ctx.get(GL_CURRENT_RASTER_POSITION)?.as_floats(), [75.0, 50.0, 0.5, 1.0]);
    /// ctx.raster_pos(glam::Vec4::new(2.0, 0.0, 0.0, 1.0))?; // clipped away
    /// assert_eq!(ctx.get(GL_CURRENT_RASTER_POSITION_VALID)?.as_bools(), [false]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn raster_pos(&mut self, object: Vec4) -> GlResult {
        self.outside_begin_end()?;
        let attribs = self.current;
        let derived = self.derived();
        let vertex = process_vertex(derived, object, &attribs);
        let eye_normal = derived.transform.eye_normal(attribs.normal);
        if !point_visible(&self.clip_planes(), &vertex) {
            self.raster_position.valid = false;
            return Ok(());
        }
        let eye = vertex.eye.as_dvec4();
        // The distance to the point (x, y, z) / w, as the spec's "distance to the vertex".
        let eye_point = if eye.w != 0.0 && eye.w != 1.0 {
            eye.truncate() / eye.w
        } else {
            eye.truncate()
        };
        let window = self.raster.window(vertex.clip);
        self.raster_position = RasterPosition {
            window,
            valid: true,
            color: vertex.colors.front.primary,
            secondary_color: vertex.colors.front.secondary,
            tex_coord: vertex.tex_coord,
            other_tex_coords: std::array::from_fn(|i| {
                self.unit_tex_coord(i + 1, object, eye, eye_normal)
            }),
            distance: self.raster_distance(eye_point.length() as f32),
        };
        if self.render_mode == RenderMode::Select {
            self.selection.hit(window.z);
        }
        Ok(())
    }

    /// The raster distance (§2.13): the current fog coordinate when it is the fog source, else
    /// `eye_distance`.
    fn raster_distance(&self, eye_distance: f32) -> f32 {
        if self.fog.coord_src == GL_FOG_COORD {
            self.current.fog_coord
        } else {
            eye_distance
        }
    }

    /// glWindowPos (§2.13): the raster position in window coordinates, z mapped into the depth
    /// range (clamped to it); no transformation, lighting or clipping: the raster colors are
    /// the current ones clamped to [0, 1], the texture coordinate is the current one, and the
    /// position is valid. In selection mode it is a hit, as in Mesa.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.window_pos([10.0, 20.0, 2.0])?; // z clamped to the depth range
    /// assert_eq!(ctx.get(GL_CURRENT_RASTER_POSITION)?.as_floats(), [10.0, 20.0, 1.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn window_pos(&mut self, [x, y, z]: [f64; 3]) -> GlResult {
        self.outside_begin_end()?;
        let [near, far] = self.raster.depth_range;
        let depth = if z <= 0.0 {
            near
        } else if z >= 1.0 {
            far
        } else {
            near + z * (far - near)
        };
        let window = Vec4::new(x as f32, y as f32, depth as f32, 1.0);
        self.raster_position = RasterPosition {
            window,
            valid: true,
            color: clamp01(self.current.color),
            secondary_color: clamp01(self.current.secondary_color),
            tex_coord: self.current.tex_coord,
            other_tex_coords: self.current.other_tex_coords,
            distance: self.raster_distance(0.0),
        };
        if self.render_mode == RenderMode::Select {
            self.selection.hit(window.z);
        }
        Ok(())
    }

    /// glBitmap (§3.7): with a valid raster position, fed back as GL_BITMAP_TOKEN and the
    /// raster position's vertex (§5.3), then the raster position moves by (`xmove`, `ymove`).
    /// There is no framebuffer to draw the bitmap into, and no selection hit (§5.2 counts
    /// primitives and raster positions only). Negative sizes are GL_INVALID_VALUE.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.window_pos([10.0, 10.0, 0.0])?;
    /// ctx.bitmap(8, 8, 8.0, 0.0)?; // moves the raster position
    /// assert_eq!(ctx.get(GL_CURRENT_RASTER_POSITION)?.as_floats()[0], 18.0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn bitmap(&mut self, width: i32, height: i32, xmove: f32, ymove: f32) -> GlResult {
        self.outside_begin_end()?;
        if width < 0 || height < 0 {
            return Err(GlError::InvalidValue);
        }
        if self.raster_position.valid {
            self.feed_back_raster_position(GL_BITMAP_TOKEN);
            let window = &mut self.raster_position.window;
            window.x += xmove;
            window.y += ymove;
        }
        Ok(())
    }

    /// glCopyPixels (§4.3.3): checked (sizes, then the type), and with a valid raster
    /// position fed back as GL_COPY_PIXEL_TOKEN and the raster position's vertex. Nothing is
    /// copied: there is no framebuffer.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.window_pos([1.0, 2.0, 0.0])?;
    /// ctx.feedback_buffer(16, GL_2D, 1)?;
    /// ctx.render_mode(GL_FEEDBACK)?;
    /// ctx.copy_pixels(4, 4, GL_COLOR)?;
    /// let (_, finished) = ctx.render_mode(GL_RENDER)?;
    /// assert_eq!(finished.unwrap().values, [GL_COPY_PIXEL_TOKEN as f32, 1.0, 2.0]);
    /// assert_eq!(ctx.copy_pixels(-1, 4, GL_COLOR), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn copy_pixels(&mut self, width: i32, height: i32, kind: GLenum) -> GlResult {
        self.outside_begin_end()?;
        if width < 0 || height < 0 {
            return Err(GlError::InvalidValue);
        }
        if !matches!(kind, GL_COLOR | GL_DEPTH | GL_STENCIL) {
            return Err(GlError::InvalidEnum);
        }
        if self.raster_position.valid {
            self.feed_back_raster_position(GL_COPY_PIXEL_TOKEN);
        }
        Ok(())
    }

    /// In feedback mode, `token` and the current raster position as a vertex (window
    /// coordinates, clip w, raster color and texture coordinate).
    fn feed_back_raster_position(&mut self, token: GLenum) {
        if self.render_mode != RenderMode::Feedback {
            return;
        }
        let raster = self.raster_position;
        self.feedback.token(token);
        self.feedback.vertex(&FeedbackVertex {
            window: raster.window,
            color: raster.color,
            tex_coord: raster.tex_coord,
        });
    }

    /// glWindowPos from any component type (converted directly).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.window_pos_of(3i32, 4, 0)?; // glWindowPos3i
    /// assert_eq!(ctx.get(GL_CURRENT_RASTER_POSITION)?.as_floats()[..2], [3.0, 4.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn window_pos_of<T: Into<f64>>(&mut self, x: T, y: T, z: T) -> GlResult {
        self.window_pos([x.into(), y.into(), z.into()])
    }

    /// glWindowPos2v / glWindowPos3v: `v` holds 2 or 3 values (z 0 for 2); GL_INVALID_VALUE
    /// for a NULL (empty) vector.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.window_pos_v(&[5.0f32, 6.0])?; // glWindowPos2fv: z is 0
    /// assert_eq!(ctx.get(GL_CURRENT_RASTER_POSITION)?.as_floats(), [5.0, 6.0, 0.0, 1.0]);
    /// assert_eq!(ctx.window_pos_v::<f32>(&[]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn window_pos_v<T: Into<f64> + Copy>(&mut self, v: &[T]) -> GlResult {
        match *v {
            [x, y] => self.window_pos([x.into(), y.into(), 0.0]),
            [x, y, z] => self.window_pos([x.into(), y.into(), z.into()]),
            _ => {
                self.outside_begin_end()?;
                Err(GlError::InvalidValue)
            }
        }
    }
}

/// The format and type of glDrawPixels and glReadPixels (§3.6.4, tables 3.5 and 3.6):
/// GL_INVALID_ENUM for a format or type that is none, or GL_BITMAP with a format other than
/// the index ones; GL_INVALID_OPERATION for a packed type whose component count is not the
/// format's. Returns the bytes of one pixel, or None for GL_BITMAP (a bit a pixel).
pub(crate) fn pixel_rectangle_format(format: GLenum, ty: GLenum) -> GlResult<Option<usize>> {
    let index = matches!(format, GL_COLOR_INDEX | GL_STENCIL_INDEX);
    let components = match format {
        GL_COLOR_INDEX | GL_STENCIL_INDEX => 1,
        _ => format_components(format).ok_or(GlError::InvalidEnum)?.len(),
    };
    if ty == GL_BITMAP {
        return if index {
            Ok(None)
        } else {
            Err(GlError::InvalidEnum)
        };
    }
    let ty = pixel_type(ty).ok_or(GlError::InvalidEnum)?;
    match ty.packed {
        Some((fields, _)) if fields.len() != components || index => Err(GlError::InvalidOperation),
        Some(_) => Ok(Some(ty.size)),
        None => Ok(Some(ty.size * components)),
    }
}

impl Context {
    /// glDrawPixels (§3.6.4, §4.3.1): checked (sizes, then the format and type), and with a
    /// valid raster position fed back as GL_DRAW_PIXEL_TOKEN and the raster position's
    /// vertex (§5.3). The pixels are not read: there is no framebuffer to draw them into. Not
    /// a selection hit (§5.2 counts primitives and raster positions only).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.draw_pixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE)?; // checked; nothing to draw into
    /// assert_eq!(ctx.draw_pixels(2, 2, GL_RGBA, GL_RGBA), Err(GlError::InvalidEnum)); // bad type
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn draw_pixels(&mut self, width: i32, height: i32, format: GLenum, ty: GLenum) -> GlResult {
        self.outside_begin_end()?;
        if width < 0 || height < 0 {
            return Err(GlError::InvalidValue);
        }
        pixel_rectangle_format(format, ty)?;
        if self.raster_position.valid {
            self.feed_back_raster_position(GL_DRAW_PIXEL_TOKEN);
        }
        Ok(())
    }
}
