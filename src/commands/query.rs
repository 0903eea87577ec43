//! State queries (§6.1): glGet{Boolean,Integer,Float,Double}v and glGetString.

use std::ffi::CStr;

use crate::commands::attrib_stack::{MAX_ATTRIB_STACK_DEPTH, MAX_CLIENT_ATTRIB_STACK_DEPTH};
use crate::commands::list::MAX_LIST_NESTING;
use crate::context::{Context, RenderMode};
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::pipeline::select::MAX_NAME_STACK_DEPTH;
use crate::state::arrays::ArrayKind;
use crate::state::convert::{float_to_int, normalized_to_int};
use crate::state::enables::{Capability, MAX_CLIP_PLANES};
use crate::state::light::MAX_LIGHTS;
use crate::state::raster::MAX_VIEWPORT_DIMS;

/// The largest index count and vertex range glDrawRangeElements is tuned for.
pub const MAX_ELEMENTS: i32 = 3000;

/// A queried state value in its own type; §6.1.2 converts it to the type asked for.
#[derive(Clone, Debug, PartialEq)]
pub enum StateValue {
    /// Booleans (glGetBooleanv's natural type).
    Bools(Vec<bool>),
    /// Integers; colors among them are converted as §6.1.2 says when read as floats.
    Ints(Vec<i32>),
    /// Floating-point values, kept in double.
    Floats(Vec<f64>),
    /// Colors, normals and the depth range: mapped linearly to integers when asked as such.
    Normalized(Vec<f64>),
}

impl StateValue {
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// assert_eq!(Context::new().get(GL_DEPTH_RANGE)?.as_doubles(), [0.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn as_doubles(&self) -> Vec<f64> {
        match self {
            StateValue::Bools(v) => v.iter().map(|&b| b as u8 as f64).collect(),
            StateValue::Ints(v) => v.iter().map(|&i| i as f64).collect(),
            StateValue::Floats(v) | StateValue::Normalized(v) => v.clone(),
        }
    }

    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// // Booleans read as floats are 0.0 or 1.0.
    /// assert_eq!(Context::new().get(GL_DITHER)?.as_floats(), [1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn as_floats(&self) -> Vec<f32> {
        self.as_doubles().into_iter().map(|v| v as f32).collect()
    }

    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// // Colors read as integers map [-1, 1] to the whole integer range (§6.1.2).
    /// assert_eq!(Context::new().get(GL_CURRENT_COLOR)?.as_ints(), [i32::MAX; 4]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn as_ints(&self) -> Vec<i32> {
        match self {
            StateValue::Bools(v) => v.iter().map(|&b| b as i32).collect(),
            StateValue::Ints(v) => v.clone(),
            StateValue::Floats(v) => v.iter().map(|&f| float_to_int(f as f32)).collect(),
            StateValue::Normalized(v) => v.iter().map(|&f| normalized_to_int(f)).collect(),
        }
    }

    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// // Non-zero numbers read as booleans are true.
    /// assert_eq!(Context::new().get(GL_MAX_LIGHTS)?.as_bools(), [true]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn as_bools(&self) -> Vec<bool> {
        match self {
            StateValue::Bools(v) => v.clone(),
            StateValue::Ints(v) => v.iter().map(|&i| i != 0).collect(),
            StateValue::Floats(v) | StateValue::Normalized(v) => {
                v.iter().map(|&f| f != 0.0).collect()
            }
        }
    }
}

pub(crate) fn floats(values: &[f32]) -> StateValue {
    StateValue::Floats(values.iter().map(|&v| v as f64).collect())
}

pub(crate) fn normalized(values: &[f32]) -> StateValue {
    StateValue::Normalized(values.iter().map(|&v| v as f64).collect())
}

pub(crate) fn int(value: i32) -> StateValue {
    StateValue::Ints(vec![value])
}

pub(crate) fn enumeration(value: GLenum) -> StateValue {
    StateValue::Ints(vec![value as i32])
}

impl Context {
    /// The value of `pname` for glGet*v.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get(GL_MAX_LIGHTS)?.as_ints(), [8]);
    /// assert_eq!(ctx.get(GL_LIGHT_MODEL_AMBIENT)?.as_floats(), [0.2, 0.2, 0.2, 1.0]);
    /// assert_eq!(ctx.get(GL_LIGHTING)?.as_bools(), [false]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get(&self, pname: GLenum) -> GlResult<StateValue> {
        self.outside_begin_end()?;
        if self.group_flag(pname).is_some() || Capability::of(pname).is_ok() {
            return Ok(StateValue::Bools(vec![self.is_enabled(pname)?]));
        }
        let m = &self.matrices;
        Ok(match pname {
            GL_MAX_LIGHTS => int(MAX_LIGHTS as i32),
            GL_MAX_CLIP_PLANES => int(MAX_CLIP_PLANES as i32),
            GL_MAX_VIEWPORT_DIMS => StateValue::Ints(vec![MAX_VIEWPORT_DIMS; 2]),
            GL_MAX_MODELVIEW_STACK_DEPTH => int(m.modelview.max_depth() as i32),
            GL_MAX_PROJECTION_STACK_DEPTH => int(m.projection.max_depth() as i32),
            GL_MAX_TEXTURE_STACK_DEPTH => int(m.texture[0].max_depth() as i32),
            GL_MAX_ATTRIB_STACK_DEPTH => int(MAX_ATTRIB_STACK_DEPTH as i32),
            GL_MAX_CLIENT_ATTRIB_STACK_DEPTH => int(MAX_CLIENT_ATTRIB_STACK_DEPTH as i32),
            GL_ATTRIB_STACK_DEPTH => int(self.attrib_stack_depth() as i32),
            GL_CLIENT_ATTRIB_STACK_DEPTH => int(self.client_attrib_stack_depth() as i32),
            GL_MAX_ELEMENTS_VERTICES | GL_MAX_ELEMENTS_INDICES => int(MAX_ELEMENTS),
            GL_CURRENT_COLOR => normalized(&self.current.color.to_array()),
            GL_CURRENT_NORMAL => normalized(&self.current.normal.to_array()),
            GL_CURRENT_TEXTURE_COORDS => floats(
                &self
                    .current
                    .unit_tex_coord(self.textures.active_unit)
                    .to_array(),
            ),
            GL_CURRENT_SECONDARY_COLOR => normalized(&self.current.secondary_color.to_array()),
            GL_CURRENT_FOG_COORD => floats(&[self.current.fog_coord]),
            GL_CURRENT_RASTER_POSITION => floats(&self.raster_position.window.to_array()),
            GL_CURRENT_RASTER_POSITION_VALID => StateValue::Bools(vec![self.raster_position.valid]),
            GL_CURRENT_RASTER_COLOR => normalized(&self.raster_position.color.to_array()),
            GL_CURRENT_RASTER_SECONDARY_COLOR => {
                normalized(&self.raster_position.secondary_color.to_array())
            }
            GL_CURRENT_RASTER_TEXTURE_COORDS => {
                let unit = self.textures.active_unit;
                floats(&self.raster_position.unit_tex_coord(unit).to_array())
            }
            GL_CURRENT_RASTER_DISTANCE => floats(&[self.raster_position.distance]),
            GL_EDGE_FLAG => StateValue::Bools(vec![self.current.edge_flag]),
            GL_LIGHT_MODEL_AMBIENT => normalized(&self.light_model.ambient.to_array()),
            GL_LIGHT_MODEL_LOCAL_VIEWER => StateValue::Bools(vec![self.light_model.local_viewer]),
            GL_LIGHT_MODEL_TWO_SIDE => StateValue::Bools(vec![self.light_model.two_side]),
            GL_LIGHT_MODEL_COLOR_CONTROL => enumeration(self.light_model.color_control),
            GL_COLOR_MATERIAL_FACE => enumeration(self.color_material.face),
            GL_COLOR_MATERIAL_PARAMETER => enumeration(self.color_material.mode),
            GL_MATRIX_MODE => enumeration(m.mode),
            GL_COLOR_MATRIX_STACK_DEPTH => int(m.color.depth() as i32),
            GL_MAX_COLOR_MATRIX_STACK_DEPTH => int(m.color.max_depth() as i32),
            GL_MODELVIEW_MATRIX | GL_PROJECTION_MATRIX | GL_TEXTURE_MATRIX | GL_COLOR_MATRIX => {
                floats(
                    &m.stack(matrix_of(pname), self.textures.active_unit)
                        .top()
                        .to_cols_array(),
                )
            }
            GL_TRANSPOSE_MODELVIEW_MATRIX
            | GL_TRANSPOSE_PROJECTION_MATRIX
            | GL_TRANSPOSE_TEXTURE_MATRIX
            | GL_TRANSPOSE_COLOR_MATRIX => floats(
                &m.stack(matrix_of(pname), self.textures.active_unit)
                    .top()
                    .transpose()
                    .to_cols_array(),
            ),
            GL_MODELVIEW_STACK_DEPTH => int(m.modelview.depth() as i32),
            GL_PROJECTION_STACK_DEPTH => int(m.projection.depth() as i32),
            GL_TEXTURE_STACK_DEPTH => int(m.texture[self.textures.active_unit].depth() as i32),
            GL_VIEWPORT => StateValue::Ints(self.raster.viewport.to_vec()),
            GL_DEPTH_RANGE => StateValue::Normalized(self.raster.depth_range.to_vec()),
            GL_SHADE_MODEL => enumeration(self.raster.shade_model),
            GL_FRONT_FACE => enumeration(self.raster.front_face),
            GL_CULL_FACE_MODE => enumeration(self.raster.cull_face_mode),
            GL_POLYGON_MODE => {
                StateValue::Ints(self.raster.polygon_mode.iter().map(|&m| m as i32).collect())
            }
            GL_RENDER_MODE => enumeration(match self.render_mode {
                RenderMode::Render => GL_RENDER,
                RenderMode::Feedback => GL_FEEDBACK,
                RenderMode::Select => GL_SELECT,
            }),
            GL_SELECTION_BUFFER_SIZE => int(self.selection.capacity as i32),
            GL_NAME_STACK_DEPTH => int(self.selection.names.len() as i32),
            GL_MAX_NAME_STACK_DEPTH => int(MAX_NAME_STACK_DEPTH as i32),
            GL_LIST_BASE => int(self.lists.base as i32),
            GL_LIST_INDEX => int(self.lists.index() as i32),
            GL_LIST_MODE => enumeration(self.lists.mode()),
            GL_MAX_LIST_NESTING => int(MAX_LIST_NESTING as i32),
            GL_MAX_EVAL_ORDER => int(crate::state::eval::MAX_EVAL_ORDER as i32),
            GL_MAP1_GRID_DOMAIN => StateValue::Floats(self.eval.grids[0].domain[..2].to_vec()),
            GL_MAP2_GRID_DOMAIN => StateValue::Floats(self.eval.grids[1].domain.to_vec()),
            GL_MAP1_GRID_SEGMENTS => int(self.eval.grids[0].segments[0]),
            GL_MAP2_GRID_SEGMENTS => StateValue::Ints(self.eval.grids[1].segments.to_vec()),
            GL_FEEDBACK_BUFFER_SIZE => int(self.feedback.capacity as i32),
            GL_FEEDBACK_BUFFER_TYPE => {
                enumeration(self.feedback.layout.map_or(GL_2D, |layout| layout.kind))
            }
            GL_VERTEX_ARRAY
            | GL_NORMAL_ARRAY
            | GL_COLOR_ARRAY
            | GL_INDEX_ARRAY
            | GL_TEXTURE_COORD_ARRAY
            | GL_EDGE_FLAG_ARRAY
            | GL_SECONDARY_COLOR_ARRAY
            | GL_FOG_COORD_ARRAY => {
                StateValue::Bools(vec![self.arrays.is_enabled(pname) == Some(true)])
            }
            GL_VERTEX_ARRAY_SIZE => int(self.arrays.get(ArrayKind::Vertex).size),
            GL_VERTEX_ARRAY_TYPE => enumeration(self.arrays.get(ArrayKind::Vertex).component_type),
            GL_VERTEX_ARRAY_STRIDE => int(self.arrays.get(ArrayKind::Vertex).stride),
            GL_NORMAL_ARRAY_TYPE => enumeration(self.arrays.get(ArrayKind::Normal).component_type),
            GL_NORMAL_ARRAY_STRIDE => int(self.arrays.get(ArrayKind::Normal).stride),
            GL_COLOR_ARRAY_SIZE => int(self.arrays.get(ArrayKind::Color).size),
            GL_COLOR_ARRAY_TYPE => enumeration(self.arrays.get(ArrayKind::Color).component_type),
            GL_COLOR_ARRAY_STRIDE => int(self.arrays.get(ArrayKind::Color).stride),
            GL_TEXTURE_COORD_ARRAY_SIZE => int(self.arrays.get(ArrayKind::TexCoord).size),
            GL_TEXTURE_COORD_ARRAY_TYPE => {
                enumeration(self.arrays.get(ArrayKind::TexCoord).component_type)
            }
            GL_TEXTURE_COORD_ARRAY_STRIDE => int(self.arrays.get(ArrayKind::TexCoord).stride),
            GL_EDGE_FLAG_ARRAY_STRIDE => int(self.arrays.get(ArrayKind::EdgeFlag).stride),
            GL_SECONDARY_COLOR_ARRAY_SIZE => int(self.arrays.get(ArrayKind::SecondaryColor).size),
            GL_SECONDARY_COLOR_ARRAY_TYPE => {
                enumeration(self.arrays.get(ArrayKind::SecondaryColor).component_type)
            }
            GL_SECONDARY_COLOR_ARRAY_STRIDE => {
                int(self.arrays.get(ArrayKind::SecondaryColor).stride)
            }
            GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING => {
                int(self.arrays.get(ArrayKind::SecondaryColor).buffer as i32)
            }
            GL_INDEX_ARRAY_TYPE => enumeration(self.arrays.get(ArrayKind::Index).component_type),
            GL_INDEX_ARRAY_STRIDE => int(self.arrays.get(ArrayKind::Index).stride),
            GL_INDEX_ARRAY_BUFFER_BINDING => int(self.arrays.get(ArrayKind::Index).buffer as i32),
            GL_CURRENT_INDEX => floats(&[self.current.index]),
            GL_FOG_COORD_ARRAY_TYPE => {
                enumeration(self.arrays.get(ArrayKind::FogCoord).component_type)
            }
            GL_FOG_COORD_ARRAY_STRIDE => int(self.arrays.get(ArrayKind::FogCoord).stride),
            GL_FOG_COORD_ARRAY_BUFFER_BINDING => {
                int(self.arrays.get(ArrayKind::FogCoord).buffer as i32)
            }
            GL_ARRAY_BUFFER_BINDING => int(self.arrays.array_buffer as i32),
            GL_ELEMENT_ARRAY_BUFFER_BINDING => int(self.arrays.element_array_buffer as i32),
            GL_VERTEX_ARRAY_BUFFER_BINDING => int(self.arrays.get(ArrayKind::Vertex).buffer as i32),
            GL_NORMAL_ARRAY_BUFFER_BINDING => int(self.arrays.get(ArrayKind::Normal).buffer as i32),
            GL_COLOR_ARRAY_BUFFER_BINDING => int(self.arrays.get(ArrayKind::Color).buffer as i32),
            GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING => {
                int(self.arrays.get(ArrayKind::TexCoord).buffer as i32)
            }
            GL_EDGE_FLAG_ARRAY_BUFFER_BINDING => {
                int(self.arrays.get(ArrayKind::EdgeFlag).buffer as i32)
            }
            _ => {
                return self
                    .get_fragment_state(pname)
                    .or_else(|| self.get_rasterization_state(pname))
                    .or_else(|| self.get_pixel_state(pname))
                    .or_else(|| self.get_texture_state(pname))
                    .ok_or(GlError::InvalidEnum);
            }
        })
    }

    /// glGetString.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// assert!(ctx.get_string(GL_VERSION)?.to_str().unwrap().starts_with("1.5"));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_string(&self, name: GLenum) -> GlResult<&'static CStr> {
        self.outside_begin_end()?;
        Ok(match name {
            GL_VENDOR => c"fflight",
            GL_RENDERER => c"fflight fixed-function pipeline",
            GL_VERSION => c"1.5 fflight",
            GL_EXTENSIONS => c"",
            _ => return Err(GlError::InvalidEnum),
        })
    }
}

/// The matrix mode a matrix query names.
fn matrix_of(pname: GLenum) -> GLenum {
    match pname {
        GL_PROJECTION_MATRIX | GL_TRANSPOSE_PROJECTION_MATRIX => GL_PROJECTION,
        GL_TEXTURE_MATRIX | GL_TRANSPOSE_TEXTURE_MATRIX => GL_TEXTURE,
        GL_COLOR_MATRIX | GL_TRANSPOSE_COLOR_MATRIX => GL_COLOR,
        _ => GL_MODELVIEW,
    }
}
