//! Current attributes, glBegin / glEnd and glVertex (§2.6-2.7).

use glam::{Vec3, Vec4};

use crate::context::{Context, PrimitiveInProgress, RenderMode};
use crate::error::{GlError, GlResult};
use crate::gl::*;
use std::collections::VecDeque;
use std::sync::Arc;

use crate::lighting::batch::{Reads, process_blocks};
use crate::lighting::lanes::LANES;
use crate::pipeline::DrawStream;
use crate::pipeline::block::{InputBlock, OutputBlock, lanes4_set};
use crate::pipeline::points::LaidOutPoints;
use crate::pipeline::streaming::PrefetchW;
use crate::pipeline::vertex::CurrentAttribs;
use crate::pipeline::vertex::DerivedState;
use crate::state::convert::Component;

mod helper;
mod sharing;

pub(crate) use sharing::Timing;
use sharing::{SharingChoice, Way};

/// The current attributes set since glBegin. The pending blocks' lanes start with the current
/// attributes of glBegin, and an attribute nothing set since keeps that value in every lane
/// still, so glVertex writes only the position and the attributes named here.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Varying(u8);

impl Varying {
    pub(crate) const COLOR: Varying = Varying(1);
    pub(crate) const SECONDARY_COLOR: Varying = Varying(2);
    pub(crate) const NORMAL: Varying = Varying(4);
    pub(crate) const TEX_COORD: Varying = Varying(8);
    pub(crate) const EDGE_FLAG: Varying = Varying(16);

    /// No attribute set.
    pub(crate) const fn empty() -> Varying {
        Varying(0)
    }

    /// Adds `other`'s attributes.
    pub(crate) fn insert(&mut self, other: Varying) {
        self.0 |= other.0;
    }

    /// Whether some attribute of `other` is set.
    fn contains(self, other: Varying) -> bool {
        self.0 & other.0 != 0
    }

    /// Whether no attribute but the normal and the color is set.
    fn normal_and_color_at_most(self) -> bool {
        self.0 & !(Varying::NORMAL.0 | Varying::COLOR.0) == 0
    }
}

/// What every lane of a set of blocks holds, in the attributes glVertex writes only when set
/// since glBegin (all but the position and the normal): `attribs`' values, but for those
/// `varied` since (set per vertex, each lane its own). A primitive whose attributes these
/// are reuses the blocks without refreshing them (`PendingBlocks::hold`): once the helper
/// thread has read them, a refresh writes lines it must first take back from the helper's
/// cache (immediate 1 light, 2 threads, batches shared: 0.83 of the time without refreshes).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Filled {
    color: Vec4,
    secondary_color: Vec4,
    tex_coord: Vec4,
    edge_flag: bool,
    varied: Varying,
}

impl Filled {
    /// Blocks refreshed with `attribs`, with the attributes in `varying` set per vertex.
    fn of(attribs: &CurrentAttribs, varying: Varying) -> Filled {
        Filled {
            color: attribs.color,
            secondary_color: attribs.secondary_color,
            tex_coord: attribs.tex_coord,
            edge_flag: attribs.edge_flag,
            varied: varying,
        }
    }

    /// Whether the blocks hold, in every lane, what a primitive needs whose current attributes
    /// are `attribs`, those in `varying` set since glBegin: each attribute either set per
    /// vertex from now on, or the same (to the bit) and never varied in the blocks.
    fn serves(&self, attribs: &CurrentAttribs, varying: Varying) -> bool {
        let same =
            |a: Vec4, b: Vec4| a.to_array().map(f32::to_bits) == b.to_array().map(f32::to_bits);
        let kept = |attribute: Varying, unchanged: bool| {
            varying.contains(attribute) || (!self.varied.contains(attribute) && unchanged)
        };
        kept(Varying::COLOR, same(self.color, attribs.color))
            && kept(
                Varying::SECONDARY_COLOR,
                same(self.secondary_color, attribs.secondary_color),
            )
            && kept(Varying::TEX_COORD, same(self.tex_coord, attribs.tex_coord))
            && kept(Varying::EDGE_FLAG, self.edge_flag == attribs.edge_flag)
    }

    /// The same blocks after a primitive that set `varying` per vertex.
    fn after(mut self, varying: Varying) -> Filled {
        self.varied.insert(varying);
        self
    }
}

/// Appends a vertex at `position` to `block`: its position, its normal, and of `attribs` the
/// others in `varying` (the other lanes' attributes already hold the right values).
#[inline(always)]
fn push_varying(
    block: &mut InputBlock,
    position: [f32; 4],
    attribs: &CurrentAttribs,
    varying: Varying,
) {
    let lane = block.len;
    block.set_position(lane, position);
    block.set_normal(lane, attribs.normal);
    // The usual case, only a normal per vertex, tested at once.
    if varying != Varying::empty() && varying != Varying::NORMAL {
        if varying.contains(Varying::COLOR) {
            block.set_color(lane, attribs.color);
        }
        if varying.contains(Varying::SECONDARY_COLOR) {
            lanes4_set(&mut block.secondary_color, lane, attribs.secondary_color);
        }
        if varying.contains(Varying::TEX_COORD) {
            lanes4_set(&mut block.tex_coord, lane, attribs.tex_coord);
        }
        if varying.contains(Varying::EDGE_FLAG) {
            block.edge_flag[lane] = attribs.edge_flag;
        }
    }
    block.len = lane + 1;
}

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
        self.store_color(color);
        if self.color_material.enabled {
            self.apply_color_material();
        }
    }

    /// glColor with its components apart: the C entry points' way in, which keeps them in
    /// registers (`vertex_xyzw`).
    #[inline(never)]
    pub(crate) fn color_rgba(&mut self, r: f32, g: f32, b: f32, a: f32) {
        self.color(Vec4::new(r, g, b, a));
    }

    /// glNormal with its components apart, compiled into the C entry points: stored from
    /// registers, with no call (glNormal3fv 45 -> 36 instructions, callgrind).
    #[inline(always)]
    pub(crate) fn normal_xyz(&mut self, x: f32, y: f32, z: f32) {
        self.normal(Vec3::new(x, y, z));
    }

    /// Marks `attribute` set since glBegin. Tested first: a store each call would chain the
    /// calls through the flags' memory (glNormal3fv + glVertex3fv outside feedback 6.6 -> 6.4
    /// ns, 3 alternating pairs).
    #[inline(always)]
    pub(crate) fn vary(&mut self, attribute: Varying) {
        if !self.varying.contains(attribute) {
            self.varying.insert(attribute);
        }
    }

    /// glTexCoord with its components apart (`vertex_xyzw`).
    #[inline(never)]
    pub(crate) fn tex_coord_strq(&mut self, s: f32, t: f32, r: f32, q: f32) {
        self.tex_coord(Vec4::new(s, t, r, q));
    }

    /// glVertex with its coordinates apart: the C entry points' way in. Separate arguments
    /// travel in registers, where a `Vec4` goes through memory.
    #[inline(never)]
    pub(crate) fn vertex_xyzw(&mut self, x: f32, y: f32, z: f32, w: f32) {
        self.vertex_components([x, y, z, w]);
    }

    /// glColor's usual case outside display list compilation, compiled into the C entry
    /// points: with color material off, the color stored. `false`, with nothing done,
    /// otherwise.
    #[inline(always)]
    pub(crate) fn try_color_quick(&mut self, r: f32, g: f32, b: f32, a: f32) -> bool {
        if self.color_material.enabled {
            return false;
        }
        self.store_color(Vec4::new(r, g, b, a));
        true
    }

    /// The current color, set since glBegin: glColor but for color material.
    #[inline(always)]
    fn store_color(&mut self, color: Vec4) {
        self.current.color = color;
        self.vary(Varying::COLOR);
    }

    /// glVertex's usual case outside display list compilation, compiled into the C entry
    /// points with no call and no check that panics, so that they need no saved registers:
    /// a vertex not observed (in GL_RENDER mode), or one that goes into a fresh block
    /// without completing its batch, with at most the normal and the color set since
    /// glBegin. `false`, with nothing done, for every other case, which `vertex_xyzw` takes.
    #[inline(always)]
    pub(crate) fn try_vertex_quick(&mut self, x: f32, y: f32, z: f32, w: f32) -> bool {
        if !self.vertices_observed() {
            return true;
        }
        let varying = self.varying;
        let Some(primitive) = &mut self.primitive else {
            return false;
        };
        let index = primitive.filling;
        let last_block = index + 1 == primitive.batch;
        if index >= primitive.pending.fresh
            || primitive.units.is_some()
            || !varying.normal_and_color_at_most()
        {
            return false;
        }
        // Checked here, not by indexing: the path has no panic, which would need a frame.
        let Some(block) = primitive.pending.get_block(index) else {
            return false;
        };
        let lane = block.len;
        if lane >= LANES || (lane + 1 == LANES && last_block) {
            return false;
        }
        block.set_position(lane, [x, y, z, w]);
        block.set_normal(lane, self.current.normal);
        if varying.contains(Varying::COLOR) {
            block.set_color(lane, self.current.color);
        }
        block.len = lane + 1;
        if block.is_full() {
            primitive.filling += 1;
            // The lines glVertex writes in the block after next, which the helper thread may
            // hold (it read them in the last batch).
            if let (Some(prefetch), true) =
                (primitive.pending.prefetch, index + 2 < primitive.batch)
                && let Some(ahead) = primitive.pending.get_block(index + 2)
            {
                prefetch.lines(ahead, &WRITTEN_LINES);
            }
        }
        true
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
        self.vary(Varying::SECONDARY_COLOR);
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
        self.vary(Varying::NORMAL);
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
        self.vary(Varying::TEX_COORD);
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
        self.vary(Varying::EDGE_FLAG);
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
        let mut pending = self.spare_pending.take().unwrap_or_default();
        let (batch, timing) = if units.is_some() {
            (1, None)
        } else {
            match self.way_to_light(&pending.sharing) {
                (Way::Shared, timing) => (2 * HALF_BLOCKS, timing),
                (Way::Alone, timing) => (LONE_BATCH_BLOCKS, timing),
            }
        };
        // None set since glBegin yet; the blocks may hold another primitive's attributes.
        self.varying = Varying::empty();
        pending.hold(pending.filled, pending.fresh, &self.current, self.varying);
        self.primitive = Some(Box::new(PrimitiveInProgress {
            pending,
            filling: 0,
            batch,
            stream,
            units,
            vertices: 0,
            timing,
        }));
        Ok(())
    }

    /// How a primitive's batches are lit, by what lighting a vertex costs against the
    /// application's thread writing blocks the helper thread has read: alone when nothing is
    /// observed, unlit or without lights; shared with two lights or more (batches of 128
    /// blocks, one call of the batch engine for 1024 vertices rather than
    /// `LONE_BATCH_BLOCKS`' 64: against 16, immediate 8 spots on 1 thread 64 -> 55
    /// ns/vertex); with one light, where the helper pays on some machines and not on others,
    /// by trial (`SharingChoice`, with the trial's timing of the primitive).
    fn way_to_light(&mut self, sharing: &SharingChoice) -> (Way, Option<Timing>) {
        if !self.vertices_observed() {
            return (Way::Alone, None);
        }
        let lighting = &self.derived().lighting;
        let lights = if lighting.enabled {
            lighting.lights().take(2).count()
        } else {
            0
        };
        match lights {
            2 => (Way::Shared, None),
            1 if crate::threads::thread_count() > 1 => {
                let (way, timing) = sharing.begin();
                (way, Some(timing))
            }
            _ => (Way::Alone, None),
        }
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
        let mut primitive = self.primitive.take().ok_or(GlError::InvalidOperation)?;
        if !self.leave_in_flight(&mut primitive) {
            self.primitive = Some(primitive);
            self.flush_vertices();
            primitive = self.primitive.take().ok_or(GlError::InvalidOperation)?;
        }
        let PrimitiveInProgress {
            mut pending,
            stream,
            vertices,
            timing,
            ..
        } = *primitive;
        if let Some(began) = timing {
            pending.sharing.end(began, vertices);
        }
        pending.filled = pending.filled.map(|filled| filled.after(self.varying));
        self.spare_pending = Some(pending);
        self.end_stream(stream);
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
    #[inline]
    pub fn vertex(&mut self, object: Vec4) {
        self.vertex_components(object.to_array());
    }

    /// `vertex`, compiled into each caller: stored a component at a time from the registers
    /// they arrive in, with no vector to take apart (immediate mode, 1 light: 277 -> 266
    /// instructions a vertex, callgrind).
    #[inline(always)]
    fn vertex_components(&mut self, object: [f32; 4]) {
        if !self.vertices_observed() {
            return;
        }
        let Some(primitive) = &mut self.primitive else {
            return;
        };
        let index = primitive.filling;
        if index >= primitive.pending.fresh {
            primitive.pending.refresh(index, &self.current);
        }
        let block = primitive.pending.block(index);
        if let Some(units) = &mut primitive.units {
            units.set(block.len, &self.current.other_tex_coords);
        }
        push_varying(block, object, &self.current, self.varying);
        if block.is_full() {
            primitive.filling += 1;
            if primitive.filling == primitive.batch {
                self.batch_full();
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
        self.stream_in_flight(&mut primitive, 0);
        let (used, vertices) = primitive.pending_vertices();
        primitive.vertices += vertices as u64;
        if used > 0 {
            // Lit with the context's derived state borrowed, not shared: an `Arc` clone and
            // drop per batch are two atomic operations, which some hosts make slow.
            let reads = primitive.stream.reads();
            primitive.pending.light(self.derived(), reads, used);
            for output in &primitive.pending.outputs[..used] {
                self.stream_lit_block(&mut primitive.stream, output);
            }
            if let Some(units) = &primitive.units {
                units.capture_block(primitive.pending.block(0), &mut self.capture);
            }
            primitive.pending.restart(used);
            primitive.filling = 0;
        }
        self.primitive = Some(primitive);
    }

    /// Every block of the batch is full: with more than one thread (`threads::thread_count`,
    /// by default the number of cores) the batch goes to the helper thread, the batch before
    /// it (if any) is collected and streamed meanwhile, and glVertex fills the next; else it
    /// is processed here. Immediate 8 spots, 2 cores: 32 ns/vertex against 40 on one thread
    /// when idle, 57 against 63 (CFS) and 130 against 207 with two busy loops besides.
    #[inline(never)]
    fn batch_full(&mut self) {
        let Some(mut primitive) = self.primitive.take() else {
            return;
        };
        if self.offer_pending(&mut primitive) {
            self.stream_in_flight(&mut primitive, helper::RING - 1);
            self.primitive = Some(primitive);
            return;
        }
        self.primitive = Some(primitive);
        self.flush_vertices();
    }

    /// At glEnd: whether the primitive's batches stay in flight, its last blocks offered to
    /// the helper first (a batch that ends before the others), for the next command to
    /// collect (`collect_carried`) or the next primitive to stream before its own
    /// (`PrimitiveInProgress::may_carry`).
    fn leave_in_flight(&mut self, primitive: &mut PrimitiveInProgress) -> bool {
        if !primitive.may_carry() {
            return false;
        }
        primitive.pending_vertices().0 == 0 || self.offer_pending(primitive)
    }

    /// Offers the pending blocks that hold vertices (full but for the last) of a primitive
    /// whose batches are shared to the helper thread, when there is one and it has helped of
    /// late; the primitive then fills blocks of a batch collected before. Whether it did.
    fn offer_pending(&mut self, primitive: &mut PrimitiveInProgress) -> bool {
        if primitive.batch != 2 * HALF_BLOCKS
            || crate::threads::thread_count() < 2
            || !primitive.pending.offers.offer_now()
        {
            return false;
        }
        // Room for one more batch in flight (a primitive may begin with its predecessor's
        // last two).
        self.stream_in_flight(primitive, helper::RING - 1);
        let (blocks, vertices) = primitive.pending_vertices();
        let derived = self.shared_derived();
        let pending = &mut primitive.pending;
        let job = pending.job.get_or_insert_with(helper::Job::new);
        let reads = primitive.stream.reads();
        // Points the helper lays out too (made per batch: a glBegin costs nothing more),
        // and places in the application's feedback memory.
        let places = match self.render_mode {
            RenderMode::Feedback => self.feedback.places(),
            _ => None,
        };
        if places.is_some() && pending.in_flight.is_empty() {
            job.begin_places(self.feedback.written);
        }
        let points = self
            .stream_points_sink(&primitive.stream)
            .map(|sink| (Arc::new(sink), places));
        // What the batch's blocks hold, if every one was refreshed for the primitive.
        let filled = pending
            .filled
            .filter(|_| pending.fresh >= primitive.batch)
            .map(|filled| filled.after(self.varying));
        let offered = helper::OfferedBlocks {
            halves: &mut pending.halves,
            blocks,
            filled,
        };
        let Some((offer, reused)) =
            helper::offer(job, &derived, reads, points, offered, &mut pending.spare)
        else {
            return false;
        };
        pending.in_flight.push_back(offer);
        primitive.vertices += vertices as u64;
        // The blocks now pending are those of an earlier batch, all filled.
        pending.hold(reused, primitive.batch, &self.current, self.varying);
        pending.restart(primitive.batch);
        primitive.filling = 0;
        true
    }

    /// Streams the batches the helper thread has, oldest first, once lit, until `keep` are
    /// left in flight.
    fn stream_in_flight(&mut self, primitive: &mut PrimitiveInProgress, keep: usize) {
        self.collect_in_flight(&mut primitive.pending, Some(&mut primitive.stream), keep);
    }

    /// Collects the batches of points that a primitive left to the helper thread at its
    /// glEnd (`PrimitiveInProgress::may_carry`), before any command but glBegin runs: the
    /// GL's memory is then as if they had been lit at the glEnd.
    pub(crate) fn collect_carried(&mut self) {
        if let Some(mut pending) = self.spare_pending.take_if(|p| !p.in_flight.is_empty()) {
            self.collect_in_flight(&mut pending, None, 0);
            self.spare_pending = Some(pending);
        }
    }

    /// `stream_in_flight` of `pending`'s batches: those laid out as points by the helper go
    /// through their own sink (those carried past their primitive's glEnd among them, which
    /// another primitive, or none, collects), the others through `stream`.
    fn collect_in_flight(
        &mut self,
        pending: &mut PendingBlocks,
        mut stream: Option<&mut DrawStream>,
        keep: usize,
    ) {
        let PendingBlocks {
            job,
            in_flight,
            spare,
            offers,
            outputs,
            laid_out,
            ..
        } = pending;
        let Some(job) = job else {
            return;
        };
        while in_flight.len() > keep {
            let Some(offer) = in_flight.pop_front() else {
                return;
            };
            let sink = offer.points_sink().cloned();
            let collected = helper::collect(job, offer, offers, outputs, |lit| {
                match lit {
                    helper::Lit::Blocks(blocks) => match (&sink, stream.as_deref_mut()) {
                        (Some(sink), _) => {
                            sink.lay_out_blocks(blocks, laid_out);
                            self.append_points(laid_out);
                        }
                        (None, Some(stream)) => {
                            for block in blocks {
                                self.stream_lit_block(stream, block);
                            }
                        }
                        // Only batches of points outlive their primitive (`may_carry`).
                        (None, None) => debug_assert!(false, "a batch of points without its sink"),
                    },
                    helper::Lit::Points(points) => self.append_points(points),
                    helper::Lit::Placed { end } => self.feedback.placed(end),
                }
                self.feedback.written
            });
            if spare.len() < helper::RING {
                spare.push(collected);
            }
        }
    }
}

impl PrimitiveInProgress {
    /// How many pending blocks hold vertices (the one being filled among them, if it has
    /// any), and how many vertices they hold.
    fn pending_vertices(&mut self) -> (usize, usize) {
        let partial = if self.filling < self.batch {
            self.pending.block(self.filling).len
        } else {
            0
        };
        (
            self.filling + usize::from(partial > 0),
            self.filling * LANES + partial,
        )
    }

    /// Whether glEnd may leave the primitive's batches in flight (its last blocks offered
    /// with them: `Context::leave_in_flight`), for the next command to collect
    /// (`Context::collect_carried`) or the next primitive to stream before its own, while
    /// the application's thread goes on: when the helper places them as points in the
    /// application's feedback memory, which nothing reads before the next command
    /// (glRenderMode's count, above all). Immediate mode, 1 light, 2 threads: at glEnd the
    /// application's thread waited for the last batch, lighting its second half; leaving it
    /// in flight, median pair ratio 0.916 (6 of 8 faster).
    fn may_carry(&self) -> bool {
        let in_flight = &self.pending.in_flight;
        !in_flight.is_empty() && in_flight.iter().all(|offer| offer.places_points())
    }
}

/// The byte offsets of the lines of an `InputBlock` that glVertex's usual case writes: the
/// positions' and the normals' (224 bytes from the block's start), and its length's.
const WRITTEN_LINES: [usize; 5] = [0, 64, 128, 192, std::mem::offset_of!(InputBlock, len)];

/// Sets every lane of `lanes` to `value`, unless each holds it already (to the bit).
fn set_every_lane<const N: usize>(lanes: &mut [[f32; LANES]; N], value: [f32; N]) {
    let holds = |c: usize| lanes[c].iter().all(|v| v.to_bits() == value[c].to_bits());
    if !(0..N).all(holds) {
        *lanes = value.map(|c| [c; LANES]);
    }
}

/// Blocks per batch lit on the application's thread alone (one light, where the helper does
/// not pay): 64 vertices, whose input and lit blocks (12 KiB) stay in the first-level cache.
/// Against 2 blocks a batch, immediate mode with one light 266 -> 251 instructions a vertex
/// (callgrind), and 65.5 -> 57.9 ns/vertex on the Xeon, medians of 10 alternating pairs, each
/// faster; 16 blocks saved 2 more instructions and were within the noise.
const LONE_BATCH_BLOCKS: usize = 8;

/// Blocks per half batch: 512 vertices.
pub(crate) const HALF_BLOCKS: usize = 64;

/// Half a batch of blocks.
pub(crate) type HalfBlocks = Box<[InputBlock; HALF_BLOCKS]>;

/// A new half batch, made on the heap (it is 40 KiB).
pub(crate) fn half_blocks() -> HalfBlocks {
    vec![InputBlock::default(); HALF_BLOCKS]
        .into_boxed_slice()
        .try_into()
        .expect("HALF_BLOCKS blocks")
}

/// The pending vertices of a primitive in blocks, two halves of `HALF_BLOCKS`, and where they
/// are lit.
#[derive(Debug)]
pub struct PendingBlocks {
    halves: [HalfBlocks; 2],
    /// The lit blocks, when lit here.
    outputs: Vec<OutputBlock>,
    /// The batches offered to the helper thread (made on the first offer: 250 KiB).
    job: Option<Arc<helper::Job>>,
    /// The batches offered, oldest first, to collect and stream (before the pending blocks).
    in_flight: VecDeque<Arc<helper::Offer>>,
    /// The batches collected last (at most `helper::RING`), whose blocks the next offers fill
    /// again: kept across primitives, so that no batch's blocks are made anew.
    spare: Vec<Arc<helper::Offer>>,
    /// How many blocks, from the first, have every lane's attributes set for the primitive in
    /// progress: its attributes of glBegin, which those not set since (not in
    /// `Context::varying`) still have.
    fresh: usize,
    /// What those blocks hold (`None`: no block was refreshed yet).
    filled: Option<Filled>,
    /// Asks for the lines glVertex writes ahead, where the CPU can.
    prefetch: Option<PrefetchW>,
    /// The points of blocks lit here, laid out by the sink of the batch they are in.
    laid_out: LaidOutPoints<'static>,
    offers: helper::Offers,
    /// Whether primitives with one light share their batches with the helper.
    sharing: SharingChoice,
}

impl Default for PendingBlocks {
    fn default() -> PendingBlocks {
        PendingBlocks {
            halves: [half_blocks(), half_blocks()],
            outputs: vec![OutputBlock::default(); 2 * HALF_BLOCKS],
            job: None,
            in_flight: VecDeque::new(),
            spare: Vec::new(),
            fresh: 0,
            filled: None,
            prefetch: PrefetchW::detect(),
            laid_out: LaidOutPoints::default(),
            offers: Default::default(),
            sharing: Default::default(),
        }
    }
}

/// A copy has its own job (two contexts never share one). A batch in flight stays with the
/// original: copying a context between glBegin and glEnd while the helper thread lights a
/// batch of it (never done by fflight itself) gives a copy without that batch.
impl Clone for PendingBlocks {
    fn clone(&self) -> PendingBlocks {
        PendingBlocks {
            halves: self.halves.clone(),
            outputs: self.outputs.clone(),
            job: None,
            in_flight: VecDeque::new(),
            spare: Vec::new(),
            fresh: self.fresh,
            filled: self.filled,
            prefetch: self.prefetch,
            laid_out: LaidOutPoints::default(),
            offers: Default::default(),
            sharing: self.sharing.clone(),
        }
    }
}

/// A context dropped between glBegin and glEnd takes its batches in flight back from the
/// helper, which may be writing points into the application's memory.
impl Drop for PendingBlocks {
    fn drop(&mut self) {
        if let Some(job) = &self.job {
            for offer in &self.in_flight {
                helper::withdraw(job, offer);
            }
        }
    }
}

impl PendingBlocks {
    /// Lights the first `used` blocks into `outputs`.
    fn light(&mut self, derived: &DerivedState, reads: Reads, used: usize) {
        let PendingBlocks {
            halves, outputs, ..
        } = self;
        let first = used.min(HALF_BLOCKS);
        process_blocks(derived, reads, &halves[0][..first], &mut outputs[..first]);
        if used > HALF_BLOCKS {
            let (_, second) = outputs.split_at_mut(HALF_BLOCKS);
            process_blocks(derived, reads, &halves[1][..used - HALF_BLOCKS], second);
        }
    }

    /// The first `used` blocks are empty again.
    fn restart(&mut self, used: usize) {
        for index in 0..used {
            self.block(index).len = 0;
        }
    }

    /// The pending blocks now hold `filled` in their first `blocks`: they serve the primitive
    /// in progress, whose current attributes are `attribs` (those in `varying` set since
    /// glBegin), if `filled` does; else every block is refreshed at its first vertex.
    fn hold(
        &mut self,
        filled: Option<Filled>,
        blocks: usize,
        attribs: &CurrentAttribs,
        varying: Varying,
    ) {
        match filled {
            Some(filled) if filled.serves(attribs, varying) => {
                self.filled = Some(filled);
                self.fresh = blocks;
            }
            _ => {
                self.filled = Some(Filled::of(attribs, varying));
                self.fresh = 0;
            }
        }
    }

    /// Block `index`, about to take its first vertex of the primitive: every lane takes
    /// `attribs` (what `InputBlock::with_attribs` gives, in place). Once a primitive per
    /// block, so glVertex writes only the attributes set since glBegin. An attribute whose
    /// lanes all hold its value already is not written: the blocks a primitive reuses mostly
    /// do, and when the helper thread has read them, each line written would first be taken
    /// back from its cache (immediate 1 light, 2 threads, batches shared: 0.89 of the time
    /// without refreshing at all).
    #[cold]
    #[inline(never)]
    fn refresh(&mut self, index: usize, attribs: &CurrentAttribs) {
        let block = self.block(index);
        set_every_lane(&mut block.color, attribs.color.to_array());
        set_every_lane(
            &mut block.secondary_color,
            attribs.secondary_color.to_array(),
        );
        set_every_lane(&mut block.tex_coord, attribs.tex_coord.to_array());
        if block.edge_flag != [attribs.edge_flag; LANES] {
            block.edge_flag = [attribs.edge_flag; LANES];
        }
        self.fresh = index + 1;
    }

    /// Block `index` of the batch.
    #[inline(always)]
    fn block(&mut self, index: usize) -> &mut InputBlock {
        &mut self.halves[index / HALF_BLOCKS][index % HALF_BLOCKS]
    }

    #[inline(always)]
    fn get_block(&mut self, index: usize) -> Option<&mut InputBlock> {
        self.halves
            .get_mut(index / HALF_BLOCKS)?
            .get_mut(index % HALF_BLOCKS)
    }
}
