//! Feedback mode (§5.3): tokens and vertex values collected for glRenderMode to return.

use glam::{Mat4, Vec4};
use multiversion::multiversion;

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
pub(crate) const MAX_VERTEX_VALUES: usize = 12;

/// The most values a fed-back point takes: its token and a vertex.
pub(crate) const MAX_POINT_VALUES: usize = 1 + MAX_VERTEX_VALUES;

/// Writes lane `lane` of a block's `[window, color, tex_coord]` to the start of `out` as a
/// fed-back vertex of the layout whose flags are `[z, w, color, texture]`; returns how many
/// values. Inlined with constant flags, it compiles to the layout's moves alone.
#[inline(always)]
pub(crate) fn encode_lane(
    [z, w, with_color, with_texture]: [bool; 4],
    lane: usize,
    [window, color, tex_coord]: [&Lanes4; 3],
    out: &mut [f32; MAX_VERTEX_VALUES],
) -> usize {
    // Plain stores at offsets the flags decide: a closure counting them did not inline.
    out[0] = window[0][lane];
    out[1] = window[1][lane];
    let mut k = 2;
    for (flag, value) in [(z, window[2][lane]), (w, window[3][lane])] {
        if flag {
            out[k] = value;
            k += 1;
        }
    }
    for (flag, values) in [(with_color, color), (with_texture, tex_coord)] {
        if flag {
            for (c, component) in values.iter().enumerate() {
                out[k + c] = component[lane];
            }
            k += 4;
        }
    }
    k
}

/// Lays out the points of a block's `[window, color, tex_coord]` whose lanes are `visible`
/// (a bit each, lane 0 lowest) as feedback does (GL_POINT_TOKEN, then the values of `FeedbackBuffer::vertex`); returns
/// how many values it wrote. Z, W, COLOR and TEXTURE are the layout's; WIDTH (8 or 16) is at
/// least its values per point. The block's values, a column per value, are turned into a row
/// per point at once: a transposition the compiler does in vector shuffles, where a lane's
/// values stored one by one take a store each.
#[inline(always)]
fn encode_points<
    const Z: bool,
    const W: bool,
    const COLOR: bool,
    const TEXTURE: bool,
    const WIDTH: usize,
>(
    visible: u8,
    [window, color, tex_coord]: [&Lanes4; 3],
    out: &mut [f32],
) -> usize {
    // A constant, so that the copies below compile to the layout's moves.
    let per_point = 3 + Z as usize + W as usize + 4 * COLOR as usize + 4 * TEXTURE as usize;
    // Each value's column at an offset the layout fixes, so that every copy is constant.
    let (z, w) = (3, 3 + Z as usize);
    let color_at = w + W as usize;
    let tex_coord_at = color_at + 4 * COLOR as usize;
    let mut columns = [[GL_POINT_TOKEN as f32; LANES]; WIDTH];
    columns[1] = window[0];
    columns[2] = window[1];
    if Z {
        columns[z] = window[2];
    }
    if W {
        columns[w] = window[3];
    }
    if COLOR {
        columns[color_at..color_at + 4].copy_from_slice(color);
    }
    if TEXTURE {
        columns[tex_coord_at..tex_coord_at + 4].copy_from_slice(tex_coord);
    }
    // Four values of four points at a time: a 4 x 4 transposition, which glam does in a few
    // shuffles (the compiler turns a transposition written lane by lane into one move per
    // value).
    let mut points = [[0.0; WIDTH]; LANES];
    for values in (0..WIDTH).step_by(4) {
        for lanes in (0..LANES).step_by(4) {
            let column = |k: usize| Vec4::from_slice(&columns[values + k][lanes..]);
            let rows = Mat4::from_cols(column(0), column(1), column(2), column(3)).transpose();
            for k in 0..4 {
                rows.col(k).write_to_slice(&mut points[lanes + k][values..]);
            }
        }
    }
    if visible == u8::MAX {
        // Every point drawn (the usual block): each at a constant offset.
        let rooms = out[..LANES * per_point].chunks_exact_mut(per_point);
        for (room, point) in rooms.zip(&points) {
            room.copy_from_slice(&point[..per_point]);
        }
        return LANES * per_point;
    }
    // Every lane written, only the visible ones kept: the loop does not branch.
    let mut n = 0;
    for (lane, point) in points.iter().enumerate() {
        out[n..n + per_point].copy_from_slice(&point[..per_point]);
        n += per_point * usize::from(visible >> lane & 1);
    }
    n
}

/// `FeedbackLayout::encode_points`, compiled for AVX2 where the CPU has it, as
/// `points::visible_points` is.
#[multiversion(targets("x86_64+avx2+fma+bmi1+bmi2+lzcnt+popcnt", "aarch64+neon"))]
fn encode_points_of_layout(
    layout: &FeedbackLayout,
    visible: u8,
    arrays: [&Lanes4; 3],
    out: &mut [f32],
) -> usize {
    match (layout.z, layout.w, layout.color, layout.texture) {
        (false, ..) => encode_points::<false, false, false, false, 8>(visible, arrays, out),
        (true, false, false, false) => {
            encode_points::<true, false, false, false, 8>(visible, arrays, out)
        }
        (true, false, true, false) => {
            encode_points::<true, false, true, false, 8>(visible, arrays, out)
        }
        (true, false, true, true) => {
            encode_points::<true, false, true, true, 16>(visible, arrays, out)
        }
        _ => encode_points::<true, true, true, true, 16>(visible, arrays, out),
    }
}

/// Which values a fed-back vertex carries (glFeedbackBuffer's `type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FeedbackLayout {
    /// The type: GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE or GL_4D_COLOR_TEXTURE.
    pub kind: GLenum,
    /// Whether a vertex carries its window z.
    pub z: bool,
    /// Whether a vertex carries its clip w.
    pub w: bool,
    /// Whether a vertex carries its color (4 values).
    pub color: bool,
    /// Whether a vertex carries its texture coordinates (4 values).
    pub texture: bool,
}

impl FeedbackLayout {
    /// Lays out the points of a block's `[window, color, tex_coord]` whose lanes are `visible`
    /// (a bit each, lane 0 lowest; GL_POINT_TOKEN, then each vertex's values) into `out`; returns how many values it
    /// wrote. `out` has room for a whole block's points (`point_values` each): past the
    /// values of the visible points, it may be written over.
    pub(crate) fn encode_points(
        &self,
        visible: u8,
        arrays: [&Lanes4; 3],
        out: &mut [f32],
    ) -> usize {
        encode_points_of_layout(self, visible, arrays, out)
    }

    /// How many values a fed-back point takes: its token and its vertex's values.
    pub(crate) fn point_values(&self) -> usize {
        3 + usize::from(self.z)
            + usize::from(self.w)
            + 4 * usize::from(self.color)
            + 4 * usize::from(self.texture)
    }

    /// Writes `vertex`'s values in this layout to the start of `out`; returns how many.
    pub(crate) fn encode(&self, vertex: &FeedbackVertex, out: &mut [f32]) -> usize {
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

    /// The layout of glFeedbackBuffer's `type` (§5.3, table 5.2); GL_INVALID_ENUM for
    /// another value.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let layout = FeedbackLayout::of(GL_3D_COLOR)?;
    /// assert!(layout.z && layout.color && !layout.w && !layout.texture);
    /// assert_eq!(FeedbackLayout::of(GL_RGBA), Err(fflight::GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    /// Window x, y, z, and clip w.
    pub window: Vec4,
    /// The color the vertex takes after facing and flat shading.
    pub color: Vec4,
    /// Texture unit 0's coordinates.
    pub tex_coord: Vec4,
}

/// Where fed-back values go: into memory the application gave to glFeedbackBuffer (the C
/// layer installs it, so a draw of any size needs no copy of its own), or into a vector the
/// context keeps until glRenderMode hands it over (Rust callers).
#[derive(Debug)]
pub enum FeedbackStorage {
    /// Values the context keeps.
    Kept(Vec<f32>),
    /// The application's glFeedbackBuffer memory.
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
    /// glFeedbackBuffer's layout; `None` until one is given (then only tokens are written).
    pub layout: Option<FeedbackLayout>,
    /// glFeedbackBuffer's size: the most values a pass writes.
    pub capacity: usize,
    /// Where the values go.
    pub storage: FeedbackStorage,
    /// How many values this feedback pass wrote.
    pub written: usize,
    /// Whether a value did not fit: glRenderMode then returns -1.
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// buffer.pass_through(1.0);
    /// buffer.restart();
    /// assert_eq!((buffer.written, buffer.take_kept()), (0, vec![]));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn restart(&mut self) {
        if let FeedbackStorage::Kept(values) = &mut self.storage {
            values.clear();
        }
        self.written = 0;
        self.overflowed = false;
        self.line_reset_pending = false;
    }

    /// Appends one value, unless the buffer is full.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 1,
    ///     ..FeedbackBuffer::default()
    /// };
    /// buffer.value(3.0);
    /// buffer.value(4.0); // overflows
    /// assert_eq!(buffer.take_kept(), [3.0]);
    /// assert!(buffer.overflowed);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn value(&mut self, value: f32) {
        self.values_of(&[value]);
    }

    /// Appends `values`, as many as fit; the rest overflow.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 2,
    ///     ..FeedbackBuffer::default()
    /// };
    /// buffer.values_of(&[1.0, 2.0, 3.0]);
    /// assert_eq!(buffer.take_kept(), [1.0, 2.0]);
    /// assert_eq!(buffer.result(), -1);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn values_of(&mut self, values: &[f32]) {
        let room = self.capacity - self.written;
        let fitting = &values[..values.len().min(room)];
        match &mut self.storage {
            FeedbackStorage::Kept(kept) => kept.extend_from_slice(fitting),
            FeedbackStorage::Application(memory) => {
                // Only the floats written: the immediate mode helper may write later ones.
                let to = memory.range_mut(self.written..self.written + fitting.len());
                if fitting.len() > MAX_POINT_VALUES {
                    // A chunk another thread laid out (points, triangles).
                    super::streaming::copy_streaming(to, fitting);
                } else {
                    copy_short(to, fitting);
                }
            }
        }
        self.written += fitting.len();
        if fitting.len() < values.len() {
            self.overflowed = true;
        }
    }

    /// Counts the values another thread wrote in their place in the application's memory,
    /// after those written so far, up to `end`.
    pub(crate) fn placed(&mut self, end: usize) {
        debug_assert!(self.written <= end && end <= self.capacity);
        self.written = end;
    }

    /// The application's memory, where another thread may place values that fit in the
    /// capacity; `None` with the context's own storage.
    pub(crate) fn places(&mut self) -> Option<crate::capi::ApplicationPlaces> {
        match &mut self.storage {
            FeedbackStorage::Application(memory) => Some(memory.places(self.capacity)),
            FeedbackStorage::Kept(_) => None,
        }
    }

    /// Appends `len` values (at most a triangle's: 2 + 3 * 12) that `write` puts in the slice
    /// it is given: in place in the application's memory when they fit, else through
    /// `values_of`, which keeps those that fit and marks the overflow.
    #[inline(always)]
    pub(crate) fn append_with(&mut self, len: usize, write: impl FnOnce(&mut [f32])) {
        if let FeedbackStorage::Application(memory) = &mut self.storage
            && self.capacity - self.written >= len
        {
            write(memory.range_mut(self.written..self.written + len));
            self.written += len;
            return;
        }
        self.append_staged(len, write);
    }

    /// `append_with` where the values do not go straight into the application's memory (they
    /// overflow it, or the context keeps them: the Rust API): out of line, so that the usual
    /// case compiles into the mesh's loop over its triangles.
    #[cold]
    #[inline(never)]
    fn append_staged(&mut self, len: usize, write: impl FnOnce(&mut [f32])) {
        let mut staged = [0.0; 2 + 3 * MAX_VERTEX_VALUES];
        write(&mut staged[..len]);
        self.values_of(&staged[..len]);
    }

    /// Appends a token, as a float (§5.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// buffer.token(GL_BITMAP_TOKEN);
    /// assert_eq!(buffer.take_kept(), [GL_BITMAP_TOKEN as f32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn token(&mut self, token: GLenum) {
        self.value(token as f32);
    }

    /// glPassThrough: GL_PASS_THROUGH_TOKEN and `value` (§5.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// buffer.pass_through(7.0);
    /// assert_eq!(buffer.take_kept(), [GL_PASS_THROUGH_TOKEN as f32, 7.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn pass_through(&mut self, value: f32) {
        self.token(GL_PASS_THROUGH_TOKEN);
        self.value(value);
    }

    /// The line stipple restarts (a new independent segment, strip or polygon outline).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// let vertex = FeedbackVertex {
    ///     window: Vec4::new(10.0, 20.0, 0.5, 1.0),
    ///     color: Vec4::ONE,
    ///     tex_coord: Vec4::W,
    /// };
    /// buffer.reset_line_stipple();
    /// buffer.line(&[vertex, vertex]);
    /// buffer.line(&[vertex, vertex]);
    /// let values = buffer.take_kept();
    /// assert_eq!((values[0], values[5]), (GL_LINE_RESET_TOKEN as f32, GL_LINE_TOKEN as f32));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn reset_line_stipple(&mut self) {
        self.line_reset_pending = true;
    }

    /// A segment: GL_LINE_RESET_TOKEN after a stipple restart, else GL_LINE_TOKEN, then its
    /// two ends.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// let vertex = FeedbackVertex {
    ///     window: Vec4::new(10.0, 20.0, 0.5, 1.0),
    ///     color: Vec4::ONE,
    ///     tex_coord: Vec4::W,
    /// };
    /// buffer.line(&[vertex, vertex]);
    /// assert_eq!(buffer.take_kept(), [GL_LINE_TOKEN as f32, 10.0, 20.0, 10.0, 20.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// let vertex = FeedbackVertex {
    ///     window: Vec4::new(10.0, 20.0, 0.5, 1.0),
    ///     color: Vec4::ONE,
    ///     tex_coord: Vec4::W,
    /// };
    /// buffer.point(&vertex);
    /// assert_eq!(buffer.take_kept(), [GL_POINT_TOKEN as f32, 10.0, 20.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn point(&mut self, vertex: &FeedbackVertex) {
        self.token_and_vertex(Some(GL_POINT_TOKEN), vertex);
    }

    /// The points of a block in the lanes that are `visible` (a bit each, lane 0 lowest):
    /// window coordinates (w = clip w), colors and texture coordinates, one component per
    /// array. The block's values are laid out with code chosen once for the layout, then
    /// written with one copy.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// let mut window = [[0.0; 8]; 4];
    /// window[0] = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]; // x
    /// let zero = [[0.0; 8]; 4];
    /// buffer.points(1 << 2, &window, &zero, &zero); // lane 2 alone
    /// assert_eq!(buffer.take_kept(), [GL_POINT_TOKEN as f32, 2.0, 0.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn points(&mut self, visible: u8, window: &Lanes4, color: &Lanes4, tex_coord: &Lanes4) {
        let Some(layout) = self.layout else {
            for _ in 0..visible.count_ones() {
                self.token(GL_POINT_TOKEN);
            }
            return;
        };
        let arrays = [window, color, tex_coord];
        // A block whose every point is drawn fills exactly the room it is laid out in: in
        // place in the application's memory when it fits.
        let whole = LANES * layout.point_values();
        if let FeedbackStorage::Application(memory) = &mut self.storage
            && visible == u8::MAX
            && self.capacity - self.written >= whole
        {
            let room = memory.range_mut(self.written..self.written + whole);
            self.written += layout.encode_points(visible, arrays, room);
            super::streaming::prefetch_block_ahead(memory.as_slice(), self.written, whole);
            return;
        }
        let mut values = [0.0; LANES * MAX_POINT_VALUES];
        let len = layout.encode_points(visible, arrays, &mut values);
        self.values_of(&values[..len]);
    }

    /// A vertex's values in the layout, without a token (a polygon's vertices follow its
    /// count).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_3D_COLOR)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// let vertex = FeedbackVertex {
    ///     window: Vec4::new(10.0, 20.0, 0.5, 1.0),
    ///     color: Vec4::ONE,
    ///     tex_coord: Vec4::W,
    /// };
    /// buffer.vertex(&vertex);
    /// assert_eq!(buffer.take_kept(), [10.0, 20.0, 0.5, 1.0, 1.0, 1.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// let vertex = FeedbackVertex {
    ///     window: Vec4::new(10.0, 20.0, 0.5, 1.0),
    ///     color: Vec4::ONE,
    ///     tex_coord: Vec4::W,
    /// };
    /// buffer.triangle(&[vertex; 3]);
    /// let values = buffer.take_kept();
    /// assert_eq!(values.len(), 2 + 3 * 2);
    /// assert_eq!(values[..2], [GL_POLYGON_TOKEN as f32, 3.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// buffer.value(1.0);
    /// assert_eq!(buffer.take_kept(), [1.0]);
    /// assert!(buffer.take_kept().is_empty()); // taken
    /// assert_eq!(buffer.written, 1); // still counted for glRenderMode
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn take_kept(&mut self) -> Vec<f32> {
        match &mut self.storage {
            FeedbackStorage::Kept(values) => std::mem::take(values),
            FeedbackStorage::Application(_) => Vec::new(),
        }
    }

    /// glRenderMode's return value when feedback ends: the value count, or -1 on overflow.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, pipeline::feedback::*};
    /// use glam::Vec4;
    /// let mut buffer = FeedbackBuffer {
    ///     layout: Some(FeedbackLayout::of(GL_2D)?),
    ///     capacity: 16,
    ///     ..FeedbackBuffer::default()
    /// };
    /// buffer.pass_through(0.0);
    /// assert_eq!(buffer.result(), 2);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn result(&self) -> i32 {
        if self.overflowed {
            -1
        } else {
            self.written as i32
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A block's points laid out at once equal each visible lane laid out alone, for every
    /// feedback type and a few visibility patterns (all, none, alternate, one).
    #[test]
    fn a_block_of_points_is_its_visible_lanes_one_by_one() {
        let lanes = |base: f32| -> Lanes4 {
            std::array::from_fn(|c| std::array::from_fn(|lane| base + (10 * c + lane) as f32))
        };
        let (window, color, tex_coord) = (lanes(100.0), lanes(200.0), lanes(300.0));
        let types = [
            GL_2D,
            GL_3D,
            GL_3D_COLOR,
            GL_3D_COLOR_TEXTURE,
            GL_4D_COLOR_TEXTURE,
        ];
        let patterns = [u8::MAX, 0, 0b1010_1010, 1 << (LANES - 1)];
        for kind in types {
            let layout = FeedbackLayout::of(kind).unwrap();
            for visible in patterns {
                let mut expected = Vec::new();
                for lane in crate::lighting::lanes::lanes_of(visible) {
                    let vertex = FeedbackVertex {
                        window: crate::pipeline::block::lanes4_get(&window, lane),
                        color: crate::pipeline::block::lanes4_get(&color, lane),
                        tex_coord: crate::pipeline::block::lanes4_get(&tex_coord, lane),
                    };
                    let mut values = [0.0; MAX_VERTEX_VALUES];
                    let n = layout.encode(&vertex, &mut values);
                    expected.push(GL_POINT_TOKEN as f32);
                    expected.extend_from_slice(&values[..n]);
                }
                let mut out = [f32::NAN; LANES * MAX_POINT_VALUES];
                let n = layout.encode_points(visible, [&window, &color, &tex_coord], &mut out);
                assert_eq!(
                    &out[..n],
                    &expected[..],
                    "type {kind:#x}, visible {visible:#b}"
                );
            }
        }
    }
}
