//! Texture units 1 and up (GL 1.3 multitexture, §2.7, §2.8, §2.11.4) for capture.
//!
//! The batch engine carries unit 0's texture coordinates, the only ones feedback reports
//! (§5.3). Only capture returns the other units', so their coordinates travel beside the
//! engine, and only while capture is on: glVertex keeps them in a side buffer of the
//! primitive in progress (`PendingUnits`), array draws read them from each unit's texture
//! coordinate array after the draw. Each unit's coordinates go through that unit's texture
//! coordinate generation and texture matrix by the scalar function unit 0's reference path
//! uses (`VertexTransform::tex_coord`), and are appended to the capture in vertex order.

use glam::{Vec3, Vec4};

use super::block::InputBlock;
use super::capture::Capture;
use super::vertex::VertexTransform;
use crate::context::Context;
use crate::lighting::lanes::LANES;
use crate::state::texture::MAX_TEXTURE_UNITS;

/// How many texture units there are besides unit 0.
pub const EXTRA_UNITS: usize = MAX_TEXTURE_UNITS - 1;

/// Texture coordinates of units 1 and up (index: unit - 1).
pub type UnitCoords = [Vec4; EXTRA_UNITS];

/// Each of units 1 and up's vertex transformation: unit 0's `VertexTransform` with the unit's
/// own texture matrix and coordinate generation, taken once per captured draw.
#[derive(Clone, Debug, PartialEq)]
pub struct UnitTransforms {
    units: Vec<VertexTransform>,
}

impl UnitTransforms {
    /// The transformation of `base` (unit 0's) with, for unit k + 1, `units[k]`'s texture
    /// matrix and coordinate generation.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::units::UnitTransforms;
    /// use fflight::pipeline::vertex::VertexTransform;
    /// use glam::{Mat4, Vec3, Vec4};
    /// let base = VertexTransform::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY, false, false, None);
    /// let shift = Mat4::from_translation(Vec3::new(0.5, 0.0, 0.0));
    /// let units = UnitTransforms::new(&base, std::array::from_fn(|k| (if k == 0 { shift } else { Mat4::IDENTITY }, None)));
    /// let coords = units.process(Vec4::W, Vec3::Z, &[Vec4::W; 7]);
    /// assert_eq!(coords[0], Vec4::new(0.5, 0.0, 0.0, 1.0)); // unit 1: its texture matrix
    /// assert_eq!(coords[1], Vec4::W); // unit 2: identity
    /// ```
    pub fn new(
        base: &VertexTransform,
        units: [(glam::Mat4, Option<crate::state::texgen::PreparedTexGen>); EXTRA_UNITS],
    ) -> UnitTransforms {
        UnitTransforms {
            units: units
                .into_iter()
                .map(|(texture, tex_gen)| VertexTransform {
                    texture,
                    tex_gen,
                    ..base.clone()
                })
                .collect(),
        }
    }

    /// Units 1 and up's texture coordinates of a vertex at `object` with `normal` (object
    /// coordinates, as given) whose current or array coordinates are `given`: generated where
    /// the unit generates them, then through the unit's texture matrix.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::units::UnitTransforms;
    /// use fflight::pipeline::vertex::VertexTransform;
    /// use glam::{Mat4, Vec3, Vec4};
    /// let base = VertexTransform::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY, false, false, None);
    /// let units = UnitTransforms::new(&base, [(Mat4::IDENTITY, None); 7]);
    /// let given = std::array::from_fn(|k| Vec4::new(k as f32, 0.0, 0.0, 1.0));
    /// assert_eq!(units.process(Vec4::W, Vec3::Z, &given), given); // nothing to apply
    /// ```
    pub fn process(&self, object: Vec4, normal: Vec3, given: &UnitCoords) -> UnitCoords {
        let eye = self.units[0].modelview * object.as_dvec4();
        std::array::from_fn(|k| self.units[k].tex_coord(object, eye, normal, given[k]))
    }
}

/// Units 1 and up's coordinates of the pending vertices of a primitive in progress, lane by
/// lane (kept only while capture is on).
#[derive(Clone, Debug, PartialEq)]
pub struct PendingUnits {
    transforms: UnitTransforms,
    given: [UnitCoords; LANES],
}

impl PendingUnits {
    /// The coordinates of the vertex in lane `lane` of the pending block.
    pub(crate) fn set(&mut self, lane: usize, coords: &UnitCoords) {
        self.given[lane] = *coords;
    }

    /// Appends to `capture` the processed coordinates of `input`'s vertices, whose other
    /// attributes were just captured.
    pub(crate) fn capture_block(&self, input: &InputBlock, capture: &mut Capture) {
        for (lane, given) in self.given.iter().enumerate().take(input.len) {
            let (object, attribs) = input.vertex(lane);
            capture.push_units(&self.transforms.process(object, attribs.normal, given));
        }
    }
}

impl Context {
    /// Units 1 and up's transformations with the state in force.
    pub(crate) fn unit_transforms(&mut self) -> UnitTransforms {
        let derived = self.shared_derived();
        UnitTransforms::new(
            &derived.transform,
            std::array::from_fn(|k| {
                (
                    *self.matrices.texture[k + 1].top(),
                    self.textures.units[k + 1].tex_gen.prepared(),
                )
            }),
        )
    }

    /// The side buffer of a glBegin made while capture is on; `None` otherwise.
    pub(crate) fn pending_units(&mut self) -> Option<Box<PendingUnits>> {
        self.capture.is_active().then(|| {
            Box::new(PendingUnits {
                transforms: self.unit_transforms(),
                given: [[Vec4::W; EXTRA_UNITS]; LANES],
            })
        })
    }
}
