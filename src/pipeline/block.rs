//! Blocks of vertices in structure-of-arrays form: what the batch engine reads
//! (`InputBlock`: object positions and the attributes each vertex carries) and writes
//! (`OutputBlock`: eye and clip positions, lit colors, texture coordinates).

use glam::{Vec3, Vec4};

use super::vertex::{CurrentAttribs, ProcessedVertex};
use crate::lighting::lanes::{LANES, LanesF32};
use crate::lighting::{FaceColors, LitVertex};

/// Four components per lane.
pub type Lanes4 = [LanesF32; 4];

fn lanes4_set(lanes: &mut Lanes4, lane: usize, value: Vec4) {
    for (component, v) in lanes.iter_mut().zip(value.to_array()) {
        component[lane] = v;
    }
}

pub fn lanes4_get(lanes: &Lanes4, lane: usize) -> Vec4 {
    Vec4::new(
        lanes[0][lane],
        lanes[1][lane],
        lanes[2][lane],
        lanes[3][lane],
    )
}

fn splat4(value: Vec4) -> Lanes4 {
    value.to_array().map(|v| [v; LANES])
}

/// Up to `LANES` vertices as glVertex would see them: position and current attributes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InputBlock {
    /// How many lanes hold vertices; the others hold copies that are processed and ignored.
    pub len: usize,
    pub position: Lanes4,
    pub normal: [LanesF32; 3],
    pub color: Lanes4,
    pub secondary_color: Lanes4,
    pub tex_coord: Lanes4,
    pub edge_flag: [bool; LANES],
}

impl Default for InputBlock {
    fn default() -> InputBlock {
        InputBlock::with_attribs(&CurrentAttribs::default())
    }
}

impl InputBlock {
    /// An empty block whose every lane carries `attribs` (at the origin).
    pub fn with_attribs(attribs: &CurrentAttribs) -> InputBlock {
        InputBlock {
            len: 0,
            position: splat4(Vec4::W),
            normal: attribs.normal.to_array().map(|v| [v; LANES]),
            color: splat4(attribs.color),
            secondary_color: splat4(attribs.secondary_color),
            tex_coord: splat4(attribs.tex_coord),
            edge_flag: [attribs.edge_flag; LANES],
        }
    }

    pub fn is_full(&self) -> bool {
        self.len == LANES
    }

    /// Appends a vertex at `position` with `attribs`.
    pub fn push(&mut self, position: Vec4, attribs: &CurrentAttribs) {
        let lane = self.len;
        // Once here, not in every store below.
        assert!(lane < LANES, "a full block takes no more vertices");
        self.set_position(lane, position);
        self.set_normal(lane, attribs.normal);
        self.set_color(lane, attribs.color);
        lanes4_set(&mut self.secondary_color, lane, attribs.secondary_color);
        lanes4_set(&mut self.tex_coord, lane, attribs.tex_coord);
        self.edge_flag[lane] = attribs.edge_flag;
        self.len += 1;
    }

    pub fn set_position(&mut self, lane: usize, position: Vec4) {
        lanes4_set(&mut self.position, lane, position);
    }

    pub fn set_normal(&mut self, lane: usize, normal: Vec3) {
        for (component, v) in self.normal.iter_mut().zip(normal.to_array()) {
            component[lane] = v;
        }
    }

    pub fn set_color(&mut self, lane: usize, color: Vec4) {
        lanes4_set(&mut self.color, lane, color);
    }
}

/// The processed vertices of an `InputBlock`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutputBlock {
    pub len: usize,
    pub eye: Lanes4,
    pub clip: Lanes4,
    pub front_primary: Lanes4,
    pub front_secondary: Lanes4,
    pub back_primary: Lanes4,
    pub back_secondary: Lanes4,
    pub tex_coord: Lanes4,
    pub edge_flag: [bool; LANES],
}

impl Default for OutputBlock {
    fn default() -> OutputBlock {
        let zero = [[0.0; LANES]; 4];
        OutputBlock {
            len: 0,
            eye: zero,
            clip: zero,
            front_primary: zero,
            front_secondary: zero,
            back_primary: zero,
            back_secondary: zero,
            tex_coord: zero,
            edge_flag: [false; LANES],
        }
    }
}

impl OutputBlock {
    /// Lane `lane` as one vertex.
    pub fn vertex(&self, lane: usize) -> ProcessedVertex {
        let face = |primary: &Lanes4, secondary: &Lanes4| FaceColors {
            primary: lanes4_get(primary, lane),
            secondary: lanes4_get(secondary, lane),
        };
        ProcessedVertex {
            eye: lanes4_get(&self.eye, lane),
            clip: lanes4_get(&self.clip, lane),
            colors: LitVertex {
                front: face(&self.front_primary, &self.front_secondary),
                back: face(&self.back_primary, &self.back_secondary),
            },
            tex_coord: lanes4_get(&self.tex_coord, lane),
            edge_flag: self.edge_flag[lane],
        }
    }
}
