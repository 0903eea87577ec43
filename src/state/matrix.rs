//! Matrix stacks (§2.11.2): modelview, projection and each texture unit's texture matrix.

use glam::{DMat4, DVec3, Mat4};

use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::texture::MAX_TEXTURE_UNITS;

/// GL_MAX_MODELVIEW_STACK_DEPTH.
pub const MAX_MODELVIEW_STACK_DEPTH: usize = 32;
/// GL_MAX_PROJECTION_STACK_DEPTH.
pub const MAX_PROJECTION_STACK_DEPTH: usize = 32;
/// GL_MAX_TEXTURE_STACK_DEPTH.
pub const MAX_TEXTURE_STACK_DEPTH: usize = 10;
/// GL_MAX_COLOR_MATRIX_STACK_DEPTH (Mesa's).
pub const MAX_COLOR_MATRIX_STACK_DEPTH: usize = 4;

/// One stack: the top is the current matrix.
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixStack {
    entries: Vec<Mat4>,
    max_depth: usize,
}

impl MatrixStack {
    /// A stack holding the identity, of at most `max_depth` matrices.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::matrix::MatrixStack;
    /// let stack = MatrixStack::new(4);
    /// assert_eq!((stack.depth(), stack.max_depth()), (1, 4));
    /// assert_eq!(*stack.top(), glam::Mat4::IDENTITY);
    /// ```
    pub fn new(max_depth: usize) -> MatrixStack {
        let mut entries = Vec::with_capacity(max_depth);
        entries.push(Mat4::IDENTITY);
        MatrixStack { entries, max_depth }
    }

    /// The current matrix.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::matrix::MatrixStack;
    /// assert_eq!(*MatrixStack::new(2).top(), glam::Mat4::IDENTITY);
    /// ```
    pub fn top(&self) -> &Mat4 {
        self.entries.last().expect("a matrix stack is never empty")
    }

    /// The current matrix, to change.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::matrix::MatrixStack;
    /// let mut stack = MatrixStack::new(2);
    /// *stack.top_mut() = glam::Mat4::from_scale(glam::Vec3::splat(2.0));
    /// assert_eq!(stack.top().x_axis.x, 2.0);
    /// ```
    pub fn top_mut(&mut self) -> &mut Mat4 {
        self.entries
            .last_mut()
            .expect("a matrix stack is never empty")
    }

    /// How many matrices the stack holds (GL_*_STACK_DEPTH), at least 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::matrix::MatrixStack;
    /// let mut stack = MatrixStack::new(2);
    /// stack.push()?;
    /// assert_eq!(stack.depth(), 2);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn depth(&self) -> usize {
        self.entries.len()
    }

    /// The most it can hold (GL_MAX_*_STACK_DEPTH).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::matrix::{MatrixStack, MAX_TEXTURE_STACK_DEPTH};
    /// assert_eq!(MatrixStack::new(MAX_TEXTURE_STACK_DEPTH).max_depth(), 10);
    /// ```
    pub fn max_depth(&self) -> usize {
        self.max_depth
    }

    /// glPushMatrix: a copy of the top on top; GL_STACK_OVERFLOW when full.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{state::matrix::MatrixStack, GlError};
    /// let mut stack = MatrixStack::new(2);
    /// stack.push()?;
    /// assert_eq!(stack.push(), Err(GlError::StackOverflow));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn push(&mut self) -> GlResult {
        if self.entries.len() >= self.max_depth {
            return Err(GlError::StackOverflow);
        }
        self.entries.push(*self.top());
        Ok(())
    }

    /// glPopMatrix; GL_STACK_UNDERFLOW with one matrix left.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{state::matrix::MatrixStack, GlError};
    /// let mut stack = MatrixStack::new(2);
    /// stack.push()?;
    /// *stack.top_mut() = glam::Mat4::ZERO;
    /// stack.pop()?;
    /// assert_eq!(*stack.top(), glam::Mat4::IDENTITY);
    /// assert_eq!(stack.pop(), Err(GlError::StackUnderflow));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn pop(&mut self) -> GlResult {
        if self.entries.len() <= 1 {
            return Err(GlError::StackUnderflow);
        }
        self.entries.pop();
        Ok(())
    }
}

/// The stacks and glMatrixMode: a texture matrix stack for each texture unit (§2.11.2).
#[derive(Clone, Debug, PartialEq)]
pub struct Matrices {
    /// GL_MATRIX_MODE.
    pub mode: GLenum,
    /// The modelview stack.
    pub modelview: MatrixStack,
    /// The projection stack.
    pub projection: MatrixStack,
    /// Each texture unit's texture matrix stack.
    pub texture: [MatrixStack; MAX_TEXTURE_UNITS],
    /// The imaging subset's color matrix (§3.6.3): kept and queried.
    pub color: MatrixStack,
}

impl Default for Matrices {
    fn default() -> Matrices {
        Matrices {
            mode: GL_MODELVIEW,
            modelview: MatrixStack::new(MAX_MODELVIEW_STACK_DEPTH),
            projection: MatrixStack::new(MAX_PROJECTION_STACK_DEPTH),
            texture: std::array::from_fn(|_| MatrixStack::new(MAX_TEXTURE_STACK_DEPTH)),
            color: MatrixStack::new(MAX_COLOR_MATRIX_STACK_DEPTH),
        }
    }
}

impl Matrices {
    /// The stack of `mode`; GL_TEXTURE's is texture unit `unit`'s.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::matrix::Matrices};
    /// let matrices = Matrices::default();
    /// assert_eq!(matrices.stack(GL_PROJECTION, 0).max_depth(), 32);
    /// assert_eq!(matrices.stack(GL_TEXTURE, 3).max_depth(), 10);
    /// ```
    pub fn stack(&self, mode: GLenum, unit: usize) -> &MatrixStack {
        match mode {
            GL_PROJECTION => &self.projection,
            GL_TEXTURE => &self.texture[unit],
            GL_COLOR => &self.color,
            _ => &self.modelview,
        }
    }

    /// The stack glMatrixMode selects (the active texture unit `unit`'s for GL_TEXTURE).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::matrix::Matrices};
    /// let mut matrices = Matrices::default();
    /// matrices.set_mode(GL_COLOR)?;
    /// assert_eq!(matrices.current_mut(0).max_depth(), 4); // the color matrix stack
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn current_mut(&mut self, unit: usize) -> &mut MatrixStack {
        match self.mode {
            GL_PROJECTION => &mut self.projection,
            GL_TEXTURE => &mut self.texture[unit],
            GL_COLOR => &mut self.color,
            _ => &mut self.modelview,
        }
    }

    /// glMatrixMode: GL_INVALID_ENUM for anything but the four stacks.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::matrix::Matrices, GlError};
    /// let mut matrices = Matrices::default();
    /// matrices.set_mode(GL_TEXTURE)?;
    /// assert_eq!(matrices.mode, GL_TEXTURE);
    /// assert_eq!(matrices.set_mode(GL_LIGHTING), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set_mode(&mut self, mode: GLenum) -> GlResult {
        if !matches!(mode, GL_MODELVIEW | GL_PROJECTION | GL_TEXTURE | GL_COLOR) {
            return Err(GlError::InvalidEnum);
        }
        self.mode = mode;
        Ok(())
    }
}

/// glRotate's matrix (§2.11.2): `angle` in degrees about (x, y, z); a zero axis leaves identity.
///
/// # Examples
///
/// ```
/// use fflight::state::matrix::rotation;
/// use glam::DVec3;
/// let m = rotation(90.0, 0.0, 0.0, 2.0); // the axis need not be unit length
/// assert!((m.transform_vector3(DVec3::X) - DVec3::Y).length() < 1e-12);
/// assert_eq!(rotation(45.0, 0.0, 0.0, 0.0), glam::DMat4::IDENTITY);
/// ```
pub fn rotation(angle: f64, x: f64, y: f64, z: f64) -> DMat4 {
    let axis = DVec3::new(x, y, z);
    let length = axis.length();
    if length == 0.0 || !length.is_finite() {
        return DMat4::IDENTITY;
    }
    DMat4::from_axis_angle(axis / length, angle.to_radians())
}

/// glFrustum's matrix, or GL_INVALID_VALUE for a degenerate volume.
///
/// # Examples
///
/// ```
/// use fflight::{state::matrix::frustum, GlError};
/// let m = frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 3.0)?;
/// assert_eq!((m.z_axis.w, m.w_axis.z), (-1.0, -3.0));
/// assert_eq!(frustum(-1.0, 1.0, -1.0, 1.0, -1.0, 3.0), Err(GlError::InvalidValue));
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn frustum(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult<DMat4> {
    if n <= 0.0 || f <= 0.0 || l == r || b == t || n == f {
        return Err(GlError::InvalidValue);
    }
    Ok(DMat4::from_cols_array(&[
        2.0 * n / (r - l),
        0.0,
        0.0,
        0.0,
        0.0,
        2.0 * n / (t - b),
        0.0,
        0.0,
        (r + l) / (r - l),
        (t + b) / (t - b),
        -(f + n) / (f - n),
        -1.0,
        0.0,
        0.0,
        -2.0 * f * n / (f - n),
        0.0,
    ]))
}

/// glOrtho's matrix, or GL_INVALID_VALUE for a degenerate volume.
///
/// # Examples
///
/// ```
/// use fflight::{state::matrix::ortho, GlError};
/// let m = ortho(-2.0, 2.0, -1.0, 1.0, 0.0, 1.0)?;
/// assert_eq!((m.x_axis.x, m.y_axis.y, m.z_axis.z), (0.5, 1.0, -2.0));
/// assert_eq!(ortho(1.0, 1.0, -1.0, 1.0, 0.0, 1.0), Err(GlError::InvalidValue));
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn ortho(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult<DMat4> {
    if l == r || b == t || n == f {
        return Err(GlError::InvalidValue);
    }
    Ok(DMat4::from_cols_array(&[
        2.0 / (r - l),
        0.0,
        0.0,
        0.0,
        0.0,
        2.0 / (t - b),
        0.0,
        0.0,
        0.0,
        0.0,
        -2.0 / (f - n),
        0.0,
        -(r + l) / (r - l),
        -(t + b) / (t - b),
        -(f + n) / (f - n),
        1.0,
    ]))
}
