//! Feedback mode (§5.3): tokens and vertex values collected for glRenderMode to return.

use glam::Vec4;

use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::lighting::lanes::LANES;
use crate::pipeline::block::Lanes4;

/// Copies `values` to the start of `to`: a vertex (at most 13 values, token included) with a
/// copy of fixed length, which compiles to a few moves where a copy of any length calls memcpy.
fn copy_short(to: &mut [f32], values: &[f32]) {
    macro_rules! fixed {
        ($($n:literal),*) => {
            match values.len() {
                $($n => to[..$n].copy_from_slice(&values[..$n]),)*
                n => to[..n].copy_from_slice(values),
            }
        };
    }
    fixed!(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13)
}

/// The most values a fed-back vertex takes: a GL_4D_COLOR_TEXTURE one.
const MAX_VERTEX_VALUES: usize = 12;

/// The most values a fed-back point takes: its token and a vertex.
const MAX_POINT_VALUES: usize = 1 + MAX_VERTEX_VALUES;

/// Lays out the points of a block's `[window, color, tex_coord]` whose lanes are `visible`
/// as feedback does (GL_POINT_TOKEN, then the values of `FeedbackBuffer::vertex`); returns
/// how many values it wrote. Z, W, COLOR and TEXTURE are the layout's. Every lane is written
/// and only the visible ones kept, so the loop does not branch.
#[inline(always)]
fn encode_points<const Z: bool, const W: bool, const COLOR: bool, const TEXTURE: bool>(
    visible: &[bool; LANES],
    [window, color, tex_coord]: [&Lanes4; 3],
    out: &mut [f32; LANES * MAX_POINT_VALUES],
) -> usize {
    let per_point = 3 + Z as usize + W as usize + 4 * COLOR as usize + 4 * TEXTURE as usize;
    let mut n = 0;
    for lane in 0..LANES {
        let mut point = [GL_POINT_TOKEN as f32; MAX_POINT_VALUES];
        let mut k = 1;
        let mut put = |value: f32| {
            point[k] = value;
            k += 1;
        };
        put(window[0][lane]);
        put(window[1][lane]);
        if Z {
            put(window[2][lane]);
        }
        if W {
            put(window[3][lane]);
        }
        if COLOR {
            (0..4).for_each(|c| put(color[c][lane]));
        }
        if TEXTURE {
            (0..4).for_each(|c| put(tex_coord[c][lane]));
        }
        out[n..n + per_point].copy_from_slice(&point[..per_point]);
        n += per_point * usize::from(visible[lane]);
    }
    n
}

/// Which values a fed-back vertex carries (glFeedbackBuffer's `type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FeedbackLayout {
    pub kind: GLenum,
    pub z: bool,
    pub w: bool,
    pub color: bool,
    pub texture: bool,
}

impl FeedbackLayout {
    /// Writes `vertex`'s values in this layout to the start of `out`; returns how many.
    fn encode(&self, vertex: &FeedbackVertex, out: &mut [f32]) -> usize {
        let mut n = 0;
        let mut put = |v: &[f32]| {
            out[n..n + v.len()].copy_from_slice(v);
            n += v.len();
        };
        put(&[vertex.window.x, vertex.window.y]);
        if self.z {
            put(&[vertex.window.z]);
        }
        if self.w {
            put(&[vertex.window.w]);
        }
        if self.color {
            put(&vertex.color.to_array());
        }
        if self.texture {
            put(&vertex.tex_coord.to_array());
        }
        n
    }

    pub fn of(kind: GLenum) -> GlResult<FeedbackLayout> {
        let (z, w, color, texture) = match kind {
            GL_2D => (false, false, false, false),
            GL_3D => (true, false, false, false),
            GL_3D_COLOR => (true, false, true, false),
            GL_3D_COLOR_TEXTURE => (true, false, true, true),
            GL_4D_COLOR_TEXTURE => (true, true, true, true),
            _ => return Err(GlError::InvalidEnum),
        };
        Ok(FeedbackLayout {
            kind,
            z,
            w,
            color,
            texture,
        })
    }
}

/// One vertex as feedback reports it: window coordinates (w = clip w), color, texture coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FeedbackVertex {
    pub window: Vec4,
    pub color: Vec4,
    pub tex_coord: Vec4,
}

/// Where fed-back values go: into memory the application gave to glFeedbackBuffer (the C
/// layer installs it, so a draw of any size needs no copy of its own), or into a vector the
/// context keeps until glRenderMode hands it over (Rust callers).
#[derive(Debug)]
pub enum FeedbackStorage {
    Kept(Vec<f32>),
    Application(crate::capi::ApplicationFloats),
}

impl Default for FeedbackStorage {
    fn default() -> FeedbackStorage {
        FeedbackStorage::Kept(Vec::new())
    }
}

/// The feedback buffer as the context keeps it: at most `capacity` values, then overflow.
#[derive(Debug, Default)]
pub struct FeedbackBuffer {
    pub layout: Option<FeedbackLayout>,
    pub capacity: usize,
    pub storage: FeedbackStorage,
    /// How many values this feedback pass wrote.
    pub written: usize,
    pub overflowed: bool,
    /// Set when the line stipple restarts: the next segment is a GL_LINE_RESET_TOKEN.
    pub line_reset_pending: bool,
}

/// A copy keeps its own values: a clone of a buffer writing into the application's memory
/// takes what was written so far and goes on in a vector of its own.
impl Clone for FeedbackBuffer {
    fn clone(&self) -> FeedbackBuffer {
        let values = match &self.storage {
            FeedbackStorage::Kept(values) => values.clone(),
            FeedbackStorage::Application(memory) => memory.as_slice()[..self.written].to_vec(),
        };
        FeedbackBuffer {
            layout: self.layout,
            capacity: self.capacity,
            storage: FeedbackStorage::Kept(values),
            written: self.written,
            overflowed: self.overflowed,
            line_reset_pending: self.line_reset_pending,
        }
    }
}

impl FeedbackBuffer {
    /// Starts a new feedback pass: the buffer empties.
    pub fn restart(&mut self) {
        if let FeedbackStorage::Kept(values) = &mut self.storage {
            values.clear();
        }
        self.written = 0;
        self.overflowed = false;
        self.line_reset_pending = false;
    }

    pub fn value(&mut self, value: f32) {
        self.values_of(&[value]);
    }

    /// Appends `values`, as many as fit; the rest overflow.
    pub fn values_of(&mut self, values: &[f32]) {
        let room = self.capacity - self.written;
        let fitting = &values[..values.len().min(room)];
        match &mut self.storage {
            FeedbackStorage::Kept(kept) => kept.extend_from_slice(fitting),
            FeedbackStorage::Application(memory) => {
                copy_short(&mut memory.as_mut_slice()[self.written..], fitting)
            }
        }
        self.written += fitting.len();
        if fitting.len() < values.len() {
            self.overflowed = true;
        }
    }

    pub fn token(&mut self, token: GLenum) {
        self.value(token as f32);
    }

    pub fn pass_through(&mut self, value: f32) {
        self.token(GL_PASS_THROUGH_TOKEN);
        self.value(value);
    }

    /// The line stipple restarts (a new independent segment, strip or polygon outline).
    pub fn reset_line_stipple(&mut self) {
        self.line_reset_pending = true;
    }

    /// A segment: GL_LINE_RESET_TOKEN after a stipple restart, else GL_LINE_TOKEN.
    pub fn line(&mut self, ends: &[FeedbackVertex; 2]) {
        let reset = std::mem::take(&mut self.line_reset_pending);
        self.token(if reset {
            GL_LINE_RESET_TOKEN
        } else {
            GL_LINE_TOKEN
        });
        self.vertex(&ends[0]);
        self.vertex(&ends[1]);
    }

    /// A point: GL_POINT_TOKEN and its vertex.
    pub fn point(&mut self, vertex: &FeedbackVertex) {
        self.token_and_vertex(Some(GL_POINT_TOKEN), vertex);
    }

    /// The points of a block in the lanes that are `visible`: window coordinates (w = clip
    /// w), colors and texture coordinates, one component per array. The block's values are
    /// laid out with code chosen once for the layout, then written with one copy.
    pub fn points(
        &mut self,
        visible: &[bool; LANES],
        window: &Lanes4,
        color: &Lanes4,
        tex_coord: &Lanes4,
    ) {
        let Some(layout) = self.layout else {
            visible
                .iter()
                .filter(|&&v| v)
                .for_each(|_| self.token(GL_POINT_TOKEN));
            return;
        };
        let mut values = [0.0; LANES * MAX_POINT_VALUES];
        let arrays = [window, color, tex_coord];
        let out = &mut values;
        let len = match (layout.z, layout.w, layout.color, layout.texture) {
            (false, ..) => encode_points::<false, false, false, false>(visible, arrays, out),
            (true, false, false, false) => {
                encode_points::<true, false, false, false>(visible, arrays, out)
            }
            (true, false, true, false) => {
                encode_points::<true, false, true, false>(visible, arrays, out)
            }
            (true, false, true, true) => {
                encode_points::<true, false, true, true>(visible, arrays, out)
            }
            _ => encode_points::<true, true, true, true>(visible, arrays, out),
        };
        self.values_of(&values[..len]);
    }

    pub fn vertex(&mut self, vertex: &FeedbackVertex) {
        self.token_and_vertex(None, vertex);
    }

    /// `vertex`'s values as the layout has them, after `token` if one is given: written at
    /// once, so a point is a single copy into the buffer.
    fn token_and_vertex(&mut self, token: Option<GLenum>, vertex: &FeedbackVertex) {
        let Some(layout) = self.layout else {
            token.into_iter().for_each(|token| self.token(token));
            return;
        };
        let mut values = [0.0; MAX_POINT_VALUES];
        let mut n = 0;
        if let Some(token) = token {
            values[0] = token as f32;
            n = 1;
        }
        n += layout.encode(vertex, &mut values[n..]);
        self.values_of(&values[..n]);
    }

    /// A triangle: GL_POLYGON_TOKEN, the count 3 and the three vertices, with one copy.
    pub fn triangle(&mut self, corners: &[FeedbackVertex; 3]) {
        let Some(layout) = self.layout else {
            self.token(GL_POLYGON_TOKEN);
            self.value(3.0);
            return;
        };
        let mut values = [0.0; 2 + 3 * MAX_VERTEX_VALUES];
        values[..2].copy_from_slice(&[GL_POLYGON_TOKEN as f32, 3.0]);
        let mut n = 2;
        for corner in corners {
            n += layout.encode(corner, &mut values[n..]);
        }
        self.values_of(&values[..n]);
    }

    /// The values of a pass kept by the context (none for the application's memory, which
    /// holds them already).
    pub fn take_kept(&mut self) -> Vec<f32> {
        match &mut self.storage {
            FeedbackStorage::Kept(values) => std::mem::take(values),
            FeedbackStorage::Application(_) => Vec::new(),
        }
    }

    /// glRenderMode's return value when feedback ends: the value count, or -1 on overflow.
    pub fn result(&self) -> i32 {
        if self.overflowed {
            -1
        } else {
            self.written as i32
        }
    }
}
