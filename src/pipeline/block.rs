//! Blocks of vertices in structure-of-arrays form: what the batch engine reads
//! (`InputBlock`: object positions and the attributes each vertex carries) and writes
//! (`OutputBlock`: eye and clip positions, lit colors, texture coordinates).

use glam::{Vec3, Vec4};

use super::vertex::{CurrentAttribs, ProcessedVertex};
use crate::lighting::lanes::{LANES, LanesF32};
use crate::lighting::{FaceColors, LitVertex};

/// Four components per lane.
pub type Lanes4 = [LanesF32; 4];

/// Sets lane `lane` of four-component lanes to `value` (a `Vec4`, or components apart, which
/// are stored from the registers they are in).
#[inline(always)]
pub(crate) fn lanes4_set(lanes: &mut Lanes4, lane: usize, value: impl Into<[f32; 4]>) {
    for (component, v) in lanes.iter_mut().zip(value.into()) {
        component[lane] = v;
    }
}

/// Lane `lane` of four-component lanes, as one vector.
///
/// # Examples
///
/// ```
/// use fflight::pipeline::block::{Lanes4, lanes4_get};
/// use glam::Vec4;
/// let mut lanes: Lanes4 = [[0.0; 8], [0.0; 8], [0.0; 8], [1.0; 8]];
/// lanes[0][5] = 2.0;
/// assert_eq!(lanes4_get(&lanes, 5), Vec4::new(2.0, 0.0, 0.0, 1.0));
/// ```
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
// A cache line's alignment and the lane arrays first (each 32 bytes, at a multiple of 32), so
// that no load or store of a component straddles two lines; `OutputBlock` likewise.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct InputBlock {
    /// Object coordinates (x, y, z, w).
    pub position: Lanes4,
    /// The current normal (x, y, z), in object coordinates.
    pub normal: [LanesF32; 3],
    /// The current color.
    pub color: Lanes4,
    /// The current secondary color.
    pub secondary_color: Lanes4,
    /// Texture unit 0's current texture coordinates.
    pub tex_coord: Lanes4,
    /// The current edge flag.
    pub edge_flag: [bool; LANES],
    /// How many lanes hold vertices; the others hold copies that are processed and ignored.
    pub len: usize,
}

impl Default for InputBlock {
    fn default() -> InputBlock {
        InputBlock::with_attribs(&CurrentAttribs::default())
    }
}

impl InputBlock {
    /// An empty block whose every lane carries `attribs` (at the origin).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::block::InputBlock;
    /// use fflight::pipeline::vertex::CurrentAttribs;
    /// use glam::Vec4;
    /// let attribs = CurrentAttribs { color: Vec4::new(1.0, 0.0, 0.0, 1.0), ..Default::default() };
    /// let block = InputBlock::with_attribs(&attribs);
    /// assert_eq!(block.len, 0);
    /// assert_eq!(block.color[0], [1.0; 8]); // every lane's red
    /// ```
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

    /// Whether every lane holds a vertex: the block takes no more.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::block::InputBlock;
    /// use fflight::pipeline::vertex::CurrentAttribs;
    /// use glam::Vec4;
    /// let attribs = CurrentAttribs::default();
    /// let mut block = InputBlock::with_attribs(&attribs);
    /// while !block.is_full() {
    ///     block.push(Vec4::W, &attribs);
    /// }
    /// assert_eq!(block.len, fflight::lighting::lanes::LANES);
    /// ```
    pub fn is_full(&self) -> bool {
        self.len == LANES
    }

    /// Appends a vertex at `position` with `attribs`.
    ///
    /// # Panics
    ///
    /// When the block is full.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::block::InputBlock;
    /// use fflight::pipeline::vertex::CurrentAttribs;
    /// use glam::Vec4;
    /// let mut block = InputBlock::default();
    /// let attribs = CurrentAttribs { edge_flag: false, ..Default::default() };
    /// block.push(Vec4::new(1.0, 2.0, 3.0, 1.0), &attribs);
    /// assert_eq!(block.len, 1);
    /// assert_eq!(block.position[1][0], 2.0); // y of lane 0
    /// assert!(!block.edge_flag[0]);
    /// ```
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

    /// Lane `lane` as glVertex saw it: object coordinates and the attributes it carries.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::block::InputBlock;
    /// use fflight::pipeline::vertex::CurrentAttribs;
    /// use glam::{Vec3, Vec4};
    /// let mut block = InputBlock::default();
    /// let attribs = CurrentAttribs { normal: Vec3::X, edge_flag: false, ..Default::default() };
    /// block.push(Vec4::new(1.0, 2.0, 3.0, 1.0), &attribs);
    /// let (position, got) = block.vertex(0);
    /// assert_eq!(position, Vec4::new(1.0, 2.0, 3.0, 1.0));
    /// assert_eq!((got.normal, got.edge_flag), (Vec3::X, false));
    /// ```
    pub fn vertex(&self, lane: usize) -> (Vec4, CurrentAttribs) {
        let attribs = CurrentAttribs {
            color: lanes4_get(&self.color, lane),
            secondary_color: lanes4_get(&self.secondary_color, lane),
            normal: Vec3::from_array(self.normal.map(|component| component[lane])),
            tex_coord: lanes4_get(&self.tex_coord, lane),
            edge_flag: self.edge_flag[lane],
            ..CurrentAttribs::default()
        };
        (lanes4_get(&self.position, lane), attribs)
    }

    /// Sets lane `lane`'s object coordinates; the length is unchanged.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::block::InputBlock;
    /// use fflight::pipeline::vertex::CurrentAttribs;
    /// use glam::Vec4;
    /// let mut block = InputBlock::default();
    /// block.set_position(3, Vec4::new(4.0, 5.0, 6.0, 1.0));
    /// assert_eq!(block.position[2][3], 6.0);
    /// ```
    pub fn set_position(&mut self, lane: usize, position: impl Into<[f32; 4]>) {
        lanes4_set(&mut self.position, lane, position);
    }

    /// Sets lane `lane`'s normal; the length is unchanged.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::block::InputBlock;
    /// use fflight::pipeline::vertex::CurrentAttribs;
    /// use glam::Vec4;
    /// let mut block = InputBlock::default();
    /// block.set_normal(0, glam::Vec3::X);
    /// assert_eq!([block.normal[0][0], block.normal[2][0]], [1.0, 0.0]);
    /// ```
    pub fn set_normal(&mut self, lane: usize, normal: Vec3) {
        for (component, v) in self.normal.iter_mut().zip(normal.to_array()) {
            component[lane] = v;
        }
    }

    /// Sets lane `lane`'s color; the length is unchanged.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::block::InputBlock;
    /// use fflight::pipeline::vertex::CurrentAttribs;
    /// use glam::Vec4;
    /// let mut block = InputBlock::default();
    /// block.set_color(7, Vec4::new(0.0, 0.5, 0.0, 1.0));
    /// assert_eq!(block.color[1][7], 0.5);
    /// ```
    #[inline(always)]
    pub fn set_color(&mut self, lane: usize, color: Vec4) {
        lanes4_set(&mut self.color, lane, color);
    }
}

/// The processed vertices of an `InputBlock`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct OutputBlock {
    /// Eye coordinates.
    pub eye: Lanes4,
    /// Clip coordinates.
    pub clip: Lanes4,
    /// The front face's primary color.
    pub front_primary: Lanes4,
    /// The front face's secondary color.
    pub front_secondary: Lanes4,
    /// The back face's primary color (the front's without two-sided lighting).
    pub back_primary: Lanes4,
    /// The back face's secondary color.
    pub back_secondary: Lanes4,
    /// Texture unit 0's coordinates after generation and the texture matrix.
    pub tex_coord: Lanes4,
    /// The edge flags, passed through.
    pub edge_flag: [bool; LANES],
    /// How many lanes hold vertices: the input block's `len`.
    pub len: usize,
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::block::OutputBlock;
    /// use glam::Vec4;
    /// let mut block = OutputBlock::default();
    /// block.clip[3][2] = 1.0; // w of lane 2
    /// block.edge_flag[2] = true;
    /// let vertex = block.vertex(2);
    /// assert_eq!(vertex.clip, Vec4::W);
    /// assert!(vertex.edge_flag);
    /// ```
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

    /// Replaces lane `lane` with `vertex`; the length is unchanged.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::pipeline::block::OutputBlock;
    /// use fflight::pipeline::vertex::ProcessedVertex;
    /// use glam::Vec4;
    /// let mut block = OutputBlock::default();
    /// let vertex = ProcessedVertex { clip: Vec4::new(1.0, 2.0, 3.0, 4.0), ..Default::default() };
    /// block.set_vertex(5, &vertex);
    /// assert_eq!(block.vertex(5), vertex);
    /// ```
    pub fn set_vertex(&mut self, lane: usize, vertex: &ProcessedVertex) {
        lanes4_set(&mut self.eye, lane, vertex.eye);
        lanes4_set(&mut self.clip, lane, vertex.clip);
        lanes4_set(&mut self.front_primary, lane, vertex.colors.front.primary);
        lanes4_set(
            &mut self.front_secondary,
            lane,
            vertex.colors.front.secondary,
        );
        lanes4_set(&mut self.back_primary, lane, vertex.colors.back.primary);
        lanes4_set(&mut self.back_secondary, lane, vertex.colors.back.secondary);
        lanes4_set(&mut self.tex_coord, lane, vertex.tex_coord);
        self.edge_flag[lane] = vertex.edge_flag;
    }
}
