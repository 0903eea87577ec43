//! Attribute stacks (§6.1.14): glPushAttrib, glPopAttrib, glPushClientAttrib,
//! glPopClientAttrib.
//!
//! Each attribute group is the list of `Context` fields the state tables (6.5-6.29, the
//! "Attribute" column) assign to its bit; pushing clones them, popping assigns them back. A
//! group is one line of the tables below. Capabilities are saved as flags through
//! `is_enabled` and restored through `store_capability`, so every enable is covered wherever
//! it lives.

use crate::commands::raster_pos::RasterPosition;
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::pipeline::vertex::CurrentAttribs;
use crate::state::arrays::VertexArrays;
use crate::state::enables::{EVAL_CAPABILITIES, MAX_CLIP_PLANES};
use crate::state::eval::EvalAttribs;
use crate::state::fog::FogAttribs;
use crate::state::fragment::{
    AccumBufferAttribs, ColorBufferAttribs, DepthBufferAttribs, ScissorAttribs,
    StencilBufferAttribs,
};
use crate::state::hints::HintAttribs;
use crate::state::imaging::ImagingModes;
use crate::state::light::{Light, MAX_LIGHTS};
use crate::state::light_model::LightModel;
use crate::state::material::{ColorMaterial, Material};
use crate::state::pixel::{PixelModeAttribs, PixelStoreAttribs};
use crate::state::rasterization::{
    LineAttribs, MultisampleAttribs, PointAttribs, PolygonAttribs, PolygonStippleAttribs,
};
use crate::state::texture::{MAX_TEXTURE_UNITS, TextureAttribs, UnitEnables};

/// GL_MAX_ATTRIB_STACK_DEPTH (the minimum GL allows, and Mesa's).
pub const MAX_ATTRIB_STACK_DEPTH: usize = 16;
/// GL_MAX_CLIENT_ATTRIB_STACK_DEPTH (the minimum GL allows, and Mesa's).
pub const MAX_CLIENT_ATTRIB_STACK_DEPTH: usize = 16;

/// Every capability glEnable accepts (GL_ENABLE_BIT), the client arrays aside. A test checks
/// that glIsEnabled accepts no other.
pub const ENABLE_BIT_CAPABILITIES: &[GLenum] = &[
    GL_LIGHTING,
    GL_LIGHT0,
    GL_LIGHT1,
    GL_LIGHT2,
    GL_LIGHT3,
    GL_LIGHT4,
    GL_LIGHT5,
    GL_LIGHT6,
    GL_LIGHT7,
    GL_COLOR_MATERIAL,
    GL_NORMALIZE,
    GL_RESCALE_NORMAL,
    GL_CULL_FACE,
    GL_CLIP_PLANE0,
    GL_CLIP_PLANE1,
    GL_CLIP_PLANE2,
    GL_CLIP_PLANE3,
    GL_CLIP_PLANE4,
    GL_CLIP_PLANE5,
    GL_AUTO_NORMAL,
    GL_MAP1_COLOR_4,
    GL_MAP1_INDEX,
    GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1,
    GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4,
    GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,
    GL_MAP2_COLOR_4,
    GL_MAP2_INDEX,
    GL_MAP2_NORMAL,
    GL_MAP2_TEXTURE_COORD_1,
    GL_MAP2_TEXTURE_COORD_2,
    GL_MAP2_TEXTURE_COORD_3,
    GL_MAP2_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4,
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T,
    GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_Q,
    GL_SCISSOR_TEST,
    GL_ALPHA_TEST,
    GL_STENCIL_TEST,
    GL_DEPTH_TEST,
    GL_BLEND,
    GL_DITHER,
    GL_INDEX_LOGIC_OP,
    GL_COLOR_LOGIC_OP,
    GL_FOG,
    GL_COLOR_SUM,
    GL_POINT_SMOOTH,
    GL_LINE_SMOOTH,
    GL_LINE_STIPPLE,
    GL_POLYGON_SMOOTH,
    GL_POLYGON_STIPPLE,
    GL_POLYGON_OFFSET_POINT,
    GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_FILL,
    GL_COLOR_TABLE,
    GL_POST_CONVOLUTION_COLOR_TABLE,
    GL_POST_COLOR_MATRIX_COLOR_TABLE,
    GL_CONVOLUTION_1D,
    GL_CONVOLUTION_2D,
    GL_SEPARABLE_2D,
    GL_HISTOGRAM,
    GL_MINMAX,
    GL_MULTISAMPLE,
    GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_SAMPLE_ALPHA_TO_ONE,
    GL_SAMPLE_COVERAGE,
];

/// The groups whose restoring can change what an enabled color material tracks: afterwards
/// the tracked material properties take the current color again (§2.14.3).
const COLOR_MATERIAL_BITS: GLbitfield = GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_ENABLE_BIT;

/// Each group's bit and the function that saves it.
type GroupTable<G> = [(GLbitfield, fn(&Context) -> G)];

/// Defines the saved form of a stack's groups (`$saved`, one variant per group holding a
/// tuple of its fields' values) and the table of groups (`$table`: each group's bit and the
/// function that saves it). A group is `BIT => Variant { field.path: Type, ... }` in `groups`,
/// `BIT => LIST` of capabilities in `capabilities`, or `BIT => Variant(Type, save, restore)`
/// in `custom` for state saved and restored by functions.
macro_rules! attribute_groups {
    (
        $saved:ident, $table:ident;
        groups { $($bit:ident => $group:ident { $($($field:ident).+ : $ty:ty),+ $(,)? },)* }
        $(capabilities { $($cap_bit:ident => $list:ident,)* })?
        $(custom { $($c_bit:ident => $c_group:ident($c_ty:ty, $c_save:expr, $c_restore:expr),)* })?
    ) => {
        #[derive(Clone, Debug, PartialEq)]
        pub(crate) enum $saved {
            $($group(Box<($($ty,)+)>),)*
            $($($c_group(Box<$c_ty>),)*)?
            /// Capabilities and whether each was enabled.
            #[allow(dead_code)]
            Capabilities(Vec<(GLenum, bool)>),
        }

        const $table: &GroupTable<$saved> = &[
            $(($bit, |ctx| $saved::$group(Box::new(($(ctx.$($field).+.clone(),)+)))),)*
            $($(($cap_bit, |ctx| $saved::Capabilities(save_capabilities(ctx, $list))),)*)?
            $($(($c_bit, |ctx| $saved::$c_group(Box::new($c_save(ctx)))),)*)?
        ];

        impl $saved {
            fn restore(self, ctx: &mut Context) {
                match self {
                    $($saved::$group(saved) => ($(ctx.$($field).+,)+) = *saved,)*
                    $saved::Capabilities(flags) => restore_capabilities(ctx, flags),
                    $($($saved::$c_group(saved) => $c_restore(ctx, *saved),)*)?
                }
            }
        }
    };
}

attribute_groups! {
    SavedGroup, SERVER_GROUPS;
    groups {
    GL_CURRENT_BIT => Current { current: CurrentAttribs, raster_position: RasterPosition },
    GL_POINT_BIT => Point { point: PointAttribs },
    GL_LINE_BIT => Line { line: LineAttribs },
    GL_POLYGON_BIT => Polygon {
        polygon: PolygonAttribs,
        raster.cull_face_mode: GLenum,
        raster.front_face: GLenum,
        raster.polygon_mode: [GLenum; 2],
        enables.cull_face: bool,
    },
    GL_POLYGON_STIPPLE_BIT => PolygonStipple { polygon_stipple: PolygonStippleAttribs },
    // The pixel maps are in no group (table 6.25).
    GL_PIXEL_MODE_BIT => PixelMode { pixel_mode: PixelModeAttribs, imaging_modes: ImagingModes },
    GL_LIGHTING_BIT => Lighting {
        lights: [Light; MAX_LIGHTS],
        materials: [Material; 2],
        light_model: LightModel,
        color_material: ColorMaterial,
        enables.lighting: bool,
        raster.shade_model: GLenum,
    },
    GL_FOG_BIT => Fog { fog: FogAttribs },
    GL_DEPTH_BUFFER_BIT => DepthBuffer { depth: DepthBufferAttribs },
    GL_ACCUM_BUFFER_BIT => AccumBuffer { accum: AccumBufferAttribs },
    GL_STENCIL_BUFFER_BIT => StencilBuffer { stencil: StencilBufferAttribs },
    GL_VIEWPORT_BIT => Viewport { raster.viewport: [i32; 4], raster.depth_range: [f64; 2] },
    GL_TRANSFORM_BIT => Transform {
        matrices.mode: GLenum,
        enables.normalize: bool,
        enables.rescale_normal: bool,
        enables.clip_planes: [bool; MAX_CLIP_PLANES],
        raster.clip_planes: [glam::DVec4; MAX_CLIP_PLANES],
    },
    GL_COLOR_BUFFER_BIT => ColorBuffer { color_buffer: ColorBufferAttribs },
    GL_HINT_BIT => Hint { hints: HintAttribs },
    GL_SCISSOR_BIT => Scissor { scissor: ScissorAttribs },
    GL_MULTISAMPLE_BIT => Multisample { multisample: MultisampleAttribs },
    GL_LIST_BIT => List { lists.base: u32 },
    // The map enables and the grids (the maps themselves are in no group).
    GL_EVAL_BIT => Eval { eval: EvalAttribs },
    }
    capabilities {
    GL_ENABLE_BIT => ENABLE_BIT_CAPABILITIES,
    GL_EVAL_BIT => EVAL_CAPABILITIES,
    }
    custom {
    // Every unit's target and coordinate generation enables (the capabilities above are the
    // active unit's), restored after them.
    GL_ENABLE_BIT => TextureEnables(
        [UnitEnables; MAX_TEXTURE_UNITS],
        |ctx: &Context| ctx.textures.enables(),
        |ctx: &mut Context, saved| ctx.textures.restore_enables(saved)
    ),
    GL_TEXTURE_BIT => Texture(
        TextureAttribs,
        |ctx: &Context| ctx.textures.attribs(),
        |ctx: &mut Context, saved| ctx.textures.restore_attribs(saved)
    ),
    }
}

attribute_groups! {
    SavedClientGroup, CLIENT_GROUPS;
    groups {
    GL_CLIENT_PIXEL_STORE_BIT => PixelStore { pixel_store: PixelStoreAttribs },
    // Every array's state and buffer binding, and the GL_ARRAY_BUFFER and
    // GL_ELEMENT_ARRAY_BUFFER bindings (table 6.7).
    GL_CLIENT_VERTEX_ARRAY_BIT => VertexArray { arrays: VertexArrays },
    }
}

fn save_capabilities(ctx: &Context, caps: &[GLenum]) -> Vec<(GLenum, bool)> {
    caps.iter()
        .map(|&cap| (cap, ctx.is_enabled(cap) == Ok(true)))
        .collect()
}

fn restore_capabilities(ctx: &mut Context, flags: Vec<(GLenum, bool)>) {
    for (cap, enabled) in flags {
        // Every saved capability was accepted by glIsEnabled.
        let _ = ctx.store_capability(cap, enabled);
    }
}

/// One entry of the server attribute stack: the mask given to glPushAttrib and the groups it
/// saved.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SavedAttribs {
    mask: GLbitfield,
    groups: Vec<SavedGroup>,
}

/// One entry of the client attribute stack.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SavedClientAttribs {
    groups: Vec<SavedClientGroup>,
}

/// The groups of `table` whose bit is in `mask`, saved.
fn save<G>(ctx: &Context, table: &GroupTable<G>, mask: GLbitfield) -> Vec<G> {
    table
        .iter()
        .filter(|(bit, _)| mask & bit != 0)
        .map(|(_, save)| save(ctx))
        .collect()
}

impl Context {
    /// glPushAttrib (§6.1.14): saves the groups `mask` names (bits naming no group are
    /// ignored, GL_ALL_ATTRIB_BITS names them all). GL_STACK_OVERFLOW when the stack is full.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.push_attrib(GL_LIGHTING_BIT)?;
    /// ctx.set_capability(GL_LIGHTING, true)?;
    /// ctx.light(GL_LIGHT0, GL_DIFFUSE, &[1.0, 0.0, 0.0, 1.0])?;
    /// ctx.pop_attrib()?;
    /// assert!(!ctx.is_enabled(GL_LIGHTING)?);
    /// assert_eq!(ctx.get_light(GL_LIGHT0, GL_DIFFUSE)?.0, glam::Vec4::ONE);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn push_attrib(&mut self, mask: GLbitfield) -> GlResult {
        self.outside_begin_end()?;
        if self.attrib_stack.len() >= MAX_ATTRIB_STACK_DEPTH {
            return Err(GlError::StackOverflow);
        }
        let groups = save(self, SERVER_GROUPS, mask);
        self.attrib_stack.push(SavedAttribs { mask, groups });
        Ok(())
    }

    /// glPopAttrib (§6.1.14): restores the groups the matching glPushAttrib saved.
    /// GL_STACK_UNDERFLOW when the stack is empty.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.pop_attrib(), Err(GlError::StackUnderflow));
    /// ```
    pub fn pop_attrib(&mut self) -> GlResult {
        self.outside_begin_end()?;
        let saved = self.attrib_stack.pop().ok_or(GlError::StackUnderflow)?;
        for group in saved.groups {
            group.restore(self);
        }
        if saved.mask & COLOR_MATERIAL_BITS != 0 {
            self.apply_color_material();
        }
        self.invalidate();
        Ok(())
    }

    /// glPushClientAttrib (§6.1.14): as glPushAttrib, for the client groups.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.push_client_attrib(GL_CLIENT_PIXEL_STORE_BIT)?;
    /// assert_eq!(ctx.client_attrib_stack_depth(), 1);
    /// ctx.pop_client_attrib()?;
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn push_client_attrib(&mut self, mask: GLbitfield) -> GlResult {
        self.outside_begin_end()?;
        if self.client_attrib_stack.len() >= MAX_CLIENT_ATTRIB_STACK_DEPTH {
            return Err(GlError::StackOverflow);
        }
        let groups = save(self, CLIENT_GROUPS, mask);
        self.client_attrib_stack.push(SavedClientAttribs { groups });
        Ok(())
    }

    /// glPopClientAttrib (§6.1.14).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.pop_client_attrib(), Err(GlError::StackUnderflow));
    /// ```
    pub fn pop_client_attrib(&mut self) -> GlResult {
        self.outside_begin_end()?;
        let saved = self
            .client_attrib_stack
            .pop()
            .ok_or(GlError::StackUnderflow)?;
        for group in saved.groups {
            group.restore(self);
        }
        Ok(())
    }

    /// GL_ATTRIB_STACK_DEPTH.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.push_attrib(GL_ALL_ATTRIB_BITS)?;
    /// assert_eq!(ctx.attrib_stack_depth(), 1);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn attrib_stack_depth(&self) -> usize {
        self.attrib_stack.len()
    }

    /// GL_CLIENT_ATTRIB_STACK_DEPTH.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::Context;
    /// assert_eq!(Context::new().client_attrib_stack_depth(), 0);
    /// ```
    pub fn client_attrib_stack_depth(&self) -> usize {
        self.client_attrib_stack.len()
    }

    /// glDeleteBuffers' rule for saved state: a saved binding to a deleted buffer object is
    /// 0, as the binding would be had it been current (§2.9), so glPopClientAttrib never
    /// binds a deleted object (nor a new object made later with the same name).
    pub(crate) fn forget_saved_buffer(&mut self, name: GLuint) {
        for entry in &mut self.client_attrib_stack {
            for group in &mut entry.groups {
                if let SavedClientGroup::VertexArray(saved) = group {
                    saved.0.reset_bindings(name);
                }
            }
        }
    }
}
