//! Per-vertex transformation (§2.11) and lighting: object coordinates in, eye and clip
//! coordinates, lit colors and the transformed texture coordinate out.

use glam::{DMat3, DMat4, DVec3, DVec4, Mat4, Vec3, Vec4};

use crate::lighting::fast::FastState;
use crate::lighting::{LitVertex, PreparedLighting, VertexInput};
use crate::state::texgen::{GenInput, PreparedTexGen};
use crate::state::texture::MAX_TEXTURE_UNITS;

/// The current vertex attributes (§2.7) that each glVertex copies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurrentAttribs {
    /// The current color (glColor).
    pub color: Vec4,
    /// The current secondary color (glSecondaryColor).
    pub secondary_color: Vec4,
    /// The current normal (glNormal), in object coordinates.
    pub normal: Vec3,
    /// Texture unit 0's texture coordinates.
    pub tex_coord: Vec4,
    /// Texture units 1 and up's (§2.7: glMultiTexCoord).
    pub other_tex_coords: [Vec4; MAX_TEXTURE_UNITS - 1],
    /// The current edge flag (glEdgeFlag).
    pub edge_flag: bool,
    /// The current fog coordinate (§2.7): raster distance with GL_FOG_COORD as fog source.
    pub fog_coord: f32,
    /// The current color index (§2.7): kept and queried, unused in RGBA mode.
    pub index: f32,
}

impl Default for CurrentAttribs {
    fn default() -> CurrentAttribs {
        CurrentAttribs {
            color: Vec4::ONE,
            // The state tables' initial value (and Mesa's), like the raster secondary color.
            secondary_color: Vec4::W,
            normal: Vec3::Z,
            tex_coord: Vec4::W,
            other_tex_coords: [Vec4::W; MAX_TEXTURE_UNITS - 1],
            edge_flag: true,
            fog_coord: 0.0,
            index: 1.0,
        }
    }
}

impl CurrentAttribs {
    /// Texture unit `unit`'s current texture coordinates.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::vertex::CurrentAttribs;
    /// use glam::Vec4;
    /// assert_eq!(CurrentAttribs::default().unit_tex_coord(1), Vec4::W); // (0, 0, 0, 1)
    /// ```
    pub fn unit_tex_coord(&self, unit: usize) -> Vec4 {
        match unit {
            0 => self.tex_coord,
            _ => self.other_tex_coords[unit - 1],
        }
    }

    /// Sets texture unit `unit`'s current texture coordinates (glMultiTexCoord).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::vertex::CurrentAttribs;
    /// use glam::Vec4;
    /// let mut attribs = CurrentAttribs::default();
    /// attribs.set_unit_tex_coord(0, Vec4::new(0.5, 0.5, 0.0, 1.0));
    /// assert_eq!(attribs.tex_coord, Vec4::new(0.5, 0.5, 0.0, 1.0));
    /// ```
    pub fn set_unit_tex_coord(&mut self, unit: usize, tex_coord: Vec4) {
        match unit {
            0 => self.tex_coord = tex_coord,
            _ => self.other_tex_coords[unit - 1] = tex_coord,
        }
    }
}

/// A vertex after transformation and lighting, ready for primitive assembly.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ProcessedVertex {
    /// Eye coordinates (§2.11).
    pub eye: Vec4,
    /// Clip coordinates: the eye coordinates through the projection matrix.
    pub clip: Vec4,
    /// Both faces' colors, lit or passed through.
    pub colors: LitVertex,
    /// The texture coordinate after the texture matrix.
    pub tex_coord: Vec4,
    /// The edge flag, passed through.
    pub edge_flag: bool,
}

/// The matrices a vertex goes through, derived once per matrix or enable change. Vertices
/// are transformed in double precision from GL's single-precision matrices.
#[derive(Clone, Debug, PartialEq)]
pub struct VertexTransform {
    /// The modelview matrix, object to eye coordinates.
    pub modelview: DMat4,
    /// The projection matrix times the modelview matrix, object to clip coordinates: a
    /// vertex's clip coordinates in one product, which every engine computes the same way.
    pub object_to_clip: DMat4,
    /// Texture unit 0's texture matrix.
    pub texture: Mat4,
    /// The inverse transpose of the modelview's upper-left 3x3 (§2.11.3).
    pub normal_matrix: DMat3,
    /// GL_RESCALE_NORMAL's factor, when rescaling applies (enabled, GL_NORMALIZE off).
    pub normal_rescale: Option<f64>,
    /// GL_NORMALIZE: eye-space normals are made unit length.
    pub normalize: bool,
    /// Texture unit 0's coordinate generation, when a coordinate is generated.
    pub tex_gen: Option<PreparedTexGen>,
}

impl VertexTransform {
    /// Derives the transformation from the matrices, GL_NORMALIZE, GL_RESCALE_NORMAL and texture
    /// unit 0's prepared coordinate generation: the normal matrix and the rescale factor of
    /// §2.11.3 are computed here, once.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::vertex::VertexTransform;
    /// use glam::{Mat4, Vec3, Vec4};
    /// let modelview = Mat4::from_scale(Vec3::splat(2.0));
    /// let transform = VertexTransform::new(modelview, Mat4::IDENTITY, Mat4::IDENTITY, false, true, None);
    /// assert_eq!(transform.normal_rescale, Some(2.0)); // undoes the inverse's 1/2
    /// ```
    pub fn new(
        modelview: Mat4,
        projection: Mat4,
        texture: Mat4,
        normalize: bool,
        rescale_normal: bool,
        tex_gen: Option<PreparedTexGen>,
    ) -> VertexTransform {
        let modelview = modelview.as_dmat4();
        let inverse = DMat3::from_mat4(modelview).inverse();
        let normal_rescale = (rescale_normal && !normalize).then(|| {
            // §2.11.3: 1 / sqrt(m31² + m32² + m33²) of the inverse's third row.
            let length_squared = inverse.row(2).length_squared();
            if length_squared < 1e-12 {
                1.0
            } else {
                1.0 / length_squared.sqrt()
            }
        });
        VertexTransform {
            modelview,
            object_to_clip: projection.as_dmat4() * modelview,
            texture,
            normal_matrix: inverse.transpose(),
            normal_rescale,
            normalize,
            tex_gen,
        }
    }

    /// The texture coordinates of texture unit 0 (§2.11.4, §2.11.2): generated where
    /// generation is enabled, then through the texture matrix. `eye` is the vertex's eye
    /// coordinates, `normal` its normal as given.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::vertex::VertexTransform;
    /// use glam::{Mat4, Vec3, Vec4};
    /// let texture = Mat4::from_translation(Vec3::new(0.5, 0.0, 0.0));
    /// let transform = VertexTransform::new(Mat4::IDENTITY, Mat4::IDENTITY, texture, false, false, None);
    /// let current = Vec4::new(0.25, 0.0, 0.0, 1.0);
    /// let s = transform.tex_coord(Vec4::W, glam::DVec4::W, Vec3::Z, current).x;
    /// assert_eq!(s, 0.75); // no generation: the current coordinates, then the texture matrix
    /// ```
    #[inline(always)]
    pub fn tex_coord(&self, object: Vec4, eye: DVec4, normal: Vec3, current: Vec4) -> Vec4 {
        let coords = match &self.tex_gen {
            None => current,
            Some(tex_gen) => tex_gen.generate(
                &GenInput {
                    object: object.as_dvec4(),
                    eye,
                    normal: self.eye_normal(normal),
                },
                current,
            ),
        };
        self.texture * coords
    }

    /// The eye-space normal (§2.11.3): transformed, then rescaled or normalized as enabled.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::vertex::VertexTransform;
    /// use glam::{Mat4, Vec3, Vec4};
    /// let modelview = Mat4::from_scale(Vec3::new(1.0, 1.0, 4.0));
    /// let normalizing = VertexTransform::new(modelview, Mat4::IDENTITY, Mat4::IDENTITY, true, false, None);
    /// assert_eq!(normalizing.eye_normal(Vec3::Z), glam::DVec3::Z);
    /// let plain = VertexTransform::new(modelview, Mat4::IDENTITY, Mat4::IDENTITY, false, false, None);
    /// assert_eq!(plain.eye_normal(Vec3::Z), glam::DVec3::new(0.0, 0.0, 0.25));
    /// ```
    pub fn eye_normal(&self, normal: Vec3) -> DVec3 {
        let eye = self.normal_matrix * normal.as_dvec3();
        if self.normalize {
            eye.normalize_or_zero()
        } else if let Some(scale) = self.normal_rescale {
            eye * scale
        } else {
            eye
        }
    }
}

/// All per-vertex constants: what a draw call reads instead of the raw state.
#[derive(Clone, Debug, PartialEq)]
pub struct DerivedState {
    /// The matrices and normal handling.
    pub transform: VertexTransform,
    /// The lighting constants.
    pub lighting: PreparedLighting,
    /// The same constants in single precision, for the fast engine; `None` where it cannot
    /// serve the state (`FastState::new`).
    pub fast: Option<FastState>,
}

impl DerivedState {
    /// The derived state of `transform` and `lighting`, with the fast engine's constants.
    ///
    /// # Examples
    ///
    /// ```
    /// # use fflight::lighting::PreparedLighting;
    /// # use fflight::pipeline::vertex::{DerivedState, VertexTransform};
    /// # use fflight::state::{light::Light, light_model::LightModel};
    /// # use fflight::state::material::{ColorMaterial, Material};
    /// # use glam::Mat4;
    /// let derived = DerivedState::new(
    ///     VertexTransform::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY, false, false, None),
    ///     PreparedLighting::new(
    ///         false,
    ///         &std::array::from_fn(Light::initial),
    ///         &[Material::default(); 2],
    ///         &LightModel::default(),
    ///         &ColorMaterial::default(),
    ///     ),
    /// );
    /// assert!(derived.fast.is_some());
    /// ```
    pub fn new(transform: VertexTransform, lighting: PreparedLighting) -> DerivedState {
        let fast = FastState::new(&transform, &lighting);
        DerivedState {
            transform,
            lighting,
            fast,
        }
    }

    /// Transforms (§2.11) and lights (§2.14.1) one vertex given in object coordinates: the
    /// scalar reference path.
    ///
    /// # Examples
    ///
    /// ```
    /// # use fflight::lighting::PreparedLighting;
    /// # use fflight::pipeline::vertex::{DerivedState, VertexTransform};
    /// # use fflight::state::{light::Light, light_model::LightModel};
    /// # use fflight::state::material::{ColorMaterial, Material};
    /// # use glam::Mat4;
    /// // Identity matrices, lighting off.
    /// let derived = DerivedState::new(
    ///     VertexTransform::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY, false, false, None),
    ///     PreparedLighting::new(
    ///         false,
    ///         &std::array::from_fn(Light::initial),
    ///         &[Material::default(); 2],
    ///         &LightModel::default(),
    ///         &ColorMaterial::default(),
    ///     ),
    /// );
    /// use fflight::pipeline::vertex::CurrentAttribs;
    /// use glam::Vec4;
    /// let attribs = CurrentAttribs { color: Vec4::new(2.0, 0.5, 0.0, 1.0), ..Default::default() };
    /// let vertex = derived.process(Vec4::new(1.0, 2.0, 3.0, 1.0), &attribs);
    /// assert_eq!(vertex.clip, Vec4::new(1.0, 2.0, 3.0, 1.0));
    /// // Lighting off: the current color, clamped (§2.14.8).
    /// assert_eq!(vertex.colors.front.primary, Vec4::new(1.0, 0.5, 0.0, 1.0));
    /// ```
    pub fn process(&self, object: Vec4, attribs: &CurrentAttribs) -> ProcessedVertex {
        let transform = &self.transform;
        let eye = transform.modelview * object.as_dvec4();
        let colors = self.lighting.shade(&VertexInput {
            eye,
            normal: if self.lighting.enabled {
                transform.eye_normal(attribs.normal)
            } else {
                DVec3::ZERO
            },
            color: attribs.color,
            secondary_color: attribs.secondary_color,
        });
        ProcessedVertex {
            eye: eye.as_vec4(),
            clip: (transform.object_to_clip * object.as_dvec4()).as_vec4(),
            colors,
            tex_coord: transform.tex_coord(object, eye, attribs.normal, attribs.tex_coord),
            edge_flag: attribs.edge_flag,
        }
    }
}
