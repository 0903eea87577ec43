//! The GL context: all state of one rendering context, and the per-thread current context.

use std::sync::Arc;

use glam::Vec4;

use crate::error::{ErrorFlag, GlError, GlResult};
use crate::gl::*;
use crate::lighting::PreparedLighting;
use crate::pipeline::DrawStream;
use crate::pipeline::feedback::FeedbackBuffer;
use crate::pipeline::vertex::{CurrentAttribs, DerivedState, VertexTransform};
use crate::state::enables::Enables;
use crate::state::fog::FogAttribs;
use crate::state::fragment::{
    AccumBufferAttribs, ColorBufferAttribs, DepthBufferAttribs, ScissorAttribs,
    StencilBufferAttribs,
};
use crate::state::hints::HintAttribs;
use crate::state::light::{Light, MAX_LIGHTS};
use crate::state::light_model::LightModel;
use crate::state::material::{ColorMaterial, Material};
use crate::state::matrix::Matrices;
use crate::state::pixel::{PixelMaps, PixelModeAttribs, PixelStoreAttribs};
use crate::state::raster::RasterState;
use crate::state::rasterization::{
    LineAttribs, MultisampleAttribs, PointAttribs, PolygonAttribs, PolygonStippleAttribs,
};

/// glRenderMode's modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RenderMode {
    /// GL_RENDER: primitives are rasterized (here: go nowhere but capture).
    Render,
    /// GL_FEEDBACK (§5.3).
    Feedback,
    /// GL_SELECT (§5.2).
    Select,
}

/// The primitive being specified between glBegin and glEnd: the vertices not processed yet
/// (a batch of blocks is processed when it fills, before a glMaterial, and at glEnd) and the
/// draw they stream into.
#[derive(Clone, Debug)]
pub struct PrimitiveInProgress {
    /// The pending vertices, in blocks (reused from one primitive to the next).
    pub(crate) pending: crate::commands::vertex::PendingBlocks,
    /// The block being filled: `pending`'s blocks before it are full.
    pub(crate) filling: usize,
    /// How many blocks a batch has: 1 while capture is on (it records units 1 and up a block
    /// at a time), more where lighting is costly enough to share with a helper thread.
    pub(crate) batch: usize,
    pub(crate) stream: DrawStream,
    /// Texture units 1 and up's coordinates of the pending vertices, while capture is on.
    pub(crate) units: Option<Box<crate::pipeline::units::PendingUnits>>,
    /// The vertices processed or offered so far.
    pub(crate) vertices: u64,
    /// When the primitive began, if its way of lighting was chosen by trial (one light).
    pub(crate) timing: Option<crate::commands::vertex::Timing>,
}

/// One GL context. Every GL command is a method; state changes that affect vertex processing
/// drop the cached `DerivedState`, which the next vertex rebuilds.
#[derive(Clone, Debug)]
pub struct Context {
    pub(crate) error: ErrorFlag,
    pub(crate) lights: [Light; MAX_LIGHTS],
    pub(crate) materials: [Material; 2],
    pub(crate) light_model: LightModel,
    pub(crate) color_material: ColorMaterial,
    pub(crate) enables: Enables,
    pub(crate) current: CurrentAttribs,
    /// The current attributes set since glBegin (what glVertex copies into its lane).
    pub(crate) varying: crate::commands::vertex::Varying,
    pub(crate) matrices: Matrices,
    pub(crate) raster: RasterState,
    /// The state that does not change vertex processing, one attribute group each (the
    /// groups of glPushAttrib: the struct holds the group's enables too).
    pub(crate) point: PointAttribs,
    pub(crate) line: LineAttribs,
    pub(crate) polygon: PolygonAttribs,
    pub(crate) polygon_stipple: PolygonStippleAttribs,
    pub(crate) multisample: MultisampleAttribs,
    pub(crate) fog: FogAttribs,
    pub(crate) scissor: ScissorAttribs,
    pub(crate) depth: DepthBufferAttribs,
    pub(crate) stencil: StencilBufferAttribs,
    pub(crate) color_buffer: ColorBufferAttribs,
    pub(crate) accum: AccumBufferAttribs,
    pub(crate) hints: HintAttribs,
    pub(crate) pixel_mode: PixelModeAttribs,
    /// Client state (GL_CLIENT_PIXEL_STORE_BIT).
    pub(crate) pixel_store: PixelStoreAttribs,
    /// In no attribute group.
    pub(crate) pixel_maps: PixelMaps,
    /// Texture units, objects and proxies (GL_TEXTURE_BIT: see docs/architecture.md).
    pub(crate) textures: crate::state::texture::Textures,
    pub(crate) raster_position: crate::commands::raster_pos::RasterPosition,
    pub(crate) render_mode: RenderMode,
    pub(crate) feedback: FeedbackBuffer,
    /// The address glFeedbackBuffer was given: only the C layer writes through it.
    pub(crate) feedback_address: usize,
    pub(crate) selection: crate::pipeline::select::Selection,
    /// Boxed: it moves out of the context and back for every block it processes.
    pub(crate) primitive: Option<Box<PrimitiveInProgress>>,
    /// The pending blocks of the last primitive, for the next one.
    pub(crate) spare_pending: Option<crate::commands::vertex::PendingBlocks>,
    /// The lit block a draw streams from, kept between blocks (it is large, and every field
    /// is rewritten for each block).
    pub(crate) lit_blocks:
        Option<Box<[crate::pipeline::block::OutputBlock; crate::pipeline::STREAMED_BLOCKS]>>,
    /// The value buffers of a draw of points on several threads, for the next such draw.
    pub(crate) point_buffers: crate::pipeline::points::PointBuffers,
    pub(crate) arrays: crate::state::arrays::VertexArrays,
    pub(crate) buffers: crate::state::buffers::BufferObjects,
    pub(crate) queries: crate::state::queries::QueryObjects,
    pub(crate) capture: crate::pipeline::capture::Capture,
    /// glPushAttrib's and glPushClientAttrib's stacks (§6.1.14).
    pub(crate) attrib_stack: Vec<crate::commands::attrib_stack::SavedAttribs>,
    pub(crate) client_attrib_stack: Vec<crate::commands::attrib_stack::SavedClientAttribs>,
    derived: Option<Arc<DerivedState>>,
    pub(crate) vertex_cache: crate::pipeline::vertex_cache::VertexCache,
    pub(crate) lists: crate::commands::list::DisplayLists,
    /// The evaluator maps (§5.1), in no attribute group.
    pub(crate) maps: crate::state::eval::Maps,
    /// The evaluator enables and grids (GL_EVAL_BIT).
    pub(crate) eval: crate::state::eval::EvalAttribs,
    /// The imaging subset's images and results, and its modes (GL_PIXEL_MODE_BIT).
    pub(crate) imaging: crate::state::imaging::Imaging,
    pub(crate) imaging_modes: crate::state::imaging::ImagingModes,
}

impl Default for Context {
    fn default() -> Context {
        Context::new()
    }
}

impl Context {
    /// A context with GL's initial state.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// // GL's initial state: lighting off, GL_LIGHT0's diffuse color white.
    /// assert!(!ctx.is_enabled(GL_LIGHTING)?);
    /// assert_eq!(ctx.get_light(GL_LIGHT0, GL_DIFFUSE)?.0, glam::Vec4::ONE);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn new() -> Context {
        Context {
            error: ErrorFlag::default(),
            lights: std::array::from_fn(Light::initial),
            materials: [Material::default(); 2],
            light_model: LightModel::default(),
            color_material: ColorMaterial::default(),
            enables: Enables::initial(),
            current: CurrentAttribs::default(),
            varying: Default::default(),
            matrices: Matrices::default(),
            raster: RasterState::default(),
            point: Default::default(),
            line: Default::default(),
            polygon: Default::default(),
            polygon_stipple: Default::default(),
            multisample: Default::default(),
            fog: Default::default(),
            scissor: Default::default(),
            depth: Default::default(),
            stencil: Default::default(),
            color_buffer: Default::default(),
            accum: Default::default(),
            hints: Default::default(),
            pixel_mode: Default::default(),
            pixel_store: Default::default(),
            pixel_maps: Default::default(),
            textures: Default::default(),
            raster_position: Default::default(),
            render_mode: RenderMode::Render,
            feedback: FeedbackBuffer::default(),
            feedback_address: 0,
            selection: Default::default(),
            primitive: None,
            spare_pending: None,
            lit_blocks: None,
            point_buffers: Default::default(),
            arrays: Default::default(),
            buffers: Default::default(),
            queries: Default::default(),
            capture: Default::default(),
            attrib_stack: Vec::new(),
            client_attrib_stack: Vec::new(),
            derived: None,
            vertex_cache: Default::default(),
            lists: Default::default(),
            maps: Default::default(),
            eval: Default::default(),
            imaging: Default::default(),
            imaging_modes: Default::default(),
        }
    }

    /// Records `error` unless an earlier one is still unread.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.record_error(GlError::InvalidValue);
    /// ctx.record_error(GlError::InvalidEnum); // the first error is kept until read
    /// assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    /// assert_eq!(ctx.get_error(), GL_NO_ERROR);
    /// ```
    pub fn record_error(&mut self, error: GlError) {
        self.error.record(error);
    }

    /// glGetError.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let result = ctx.set_capability(0x1234, true); // not a capability
    /// ctx.settle(result);
    /// assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    /// assert_eq!(ctx.get_error(), GL_NO_ERROR);
    /// ```
    pub fn get_error(&mut self) -> GLenum {
        self.error.take()
    }

    /// Runs a command's result into the error flag: the C layer's single exit.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let result = ctx.is_enabled(GL_LIGHTING);
    /// assert_eq!(ctx.settle(result), false);
    /// let result = ctx.is_enabled(0x1234);
    /// assert_eq!(ctx.settle(result), false); // the default value, and the error recorded
    /// assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    /// ```
    pub fn settle<T: Default>(&mut self, result: GlResult<T>) -> T {
        result.unwrap_or_else(|error| {
            self.record_error(error);
            T::default()
        })
    }

    /// Whether the context is between glBegin and glEnd.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.begin(GL_POINTS)?;
    /// assert!(ctx.inside_begin_end());
    /// ctx.end()?;
    /// assert!(!ctx.inside_begin_end());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn inside_begin_end(&self) -> bool {
        self.primitive.is_some()
    }

    /// glFlush / glFinish: every command completes before it returns, so only the
    /// glBegin/glEnd check remains.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.finish()?;
    /// ctx.begin(GL_LINES)?;
    /// assert_eq!(ctx.finish(), Err(GlError::InvalidOperation));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn finish(&self) -> GlResult {
        self.outside_begin_end()
    }

    /// GL_INVALID_OPERATION between glBegin and glEnd, for the commands the spec forbids there.
    pub(crate) fn outside_begin_end(&self) -> GlResult {
        if self.inside_begin_end() {
            Err(GlError::InvalidOperation)
        } else {
            Ok(())
        }
    }

    /// Whether drawn vertices reach anything: feedback, selection or capture. In GL_RENDER
    /// mode without capture there is no rasterizer to feed, so vertices are not processed.
    pub(crate) fn vertices_observed(&self) -> bool {
        self.render_mode != RenderMode::Render || self.capture.is_active()
    }

    /// Marks every derived constant stale (a state change that affects vertices).
    pub(crate) fn invalidate(&mut self) {
        self.derived = None;
    }

    /// The derived per-vertex constants, rebuilt if a state change made them stale.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.set_capability(GL_LIGHTING, true)?;
    /// ctx.set_capability(GL_LIGHT0, true)?;
    /// ctx.light_model_scalar(GL_LIGHT_MODEL_TWO_SIDE, 1.0)?;
    /// let derived = ctx.derived();
    /// assert!(derived.lighting.enabled && derived.lighting.two_side);
    /// assert_eq!(derived.lighting.lights().count(), 1);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn derived(&mut self) -> &DerivedState {
        self.shared_derived_ref()
    }

    /// The derived constants as a shared handle, for draws that go on using them while
    /// they change the context (feedback, capture).
    pub(crate) fn shared_derived(&mut self) -> Arc<DerivedState> {
        self.shared_derived_ref().clone()
    }

    fn shared_derived_ref(&mut self) -> &Arc<DerivedState> {
        if self.derived.is_none() {
            self.derived = Some(Arc::new(self.build_derived()));
        }
        self.derived.as_ref().expect("just built")
    }

    fn build_derived(&self) -> DerivedState {
        DerivedState::new(
            VertexTransform::new(
                *self.matrices.modelview.top(),
                *self.matrices.projection.top(),
                *self.matrices.texture[0].top(),
                self.enables.normalize,
                self.enables.rescale_normal,
                self.textures.units[0].tex_gen.prepared(),
            ),
            PreparedLighting::new(
                self.enables.lighting,
                &self.lights,
                &self.materials,
                &self.light_model,
                &self.color_material,
            ),
        )
    }

    /// Applies the current color to the properties color material tracks (§2.14.3).
    pub(crate) fn apply_color_material(&mut self) {
        let tracked = self.color_material.tracked();
        let color: Vec4 = self.current.color;
        for (material, mask) in self.materials.iter_mut().zip(tracked) {
            material.set(mask, color);
        }
    }
}
