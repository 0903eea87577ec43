//! fflight's capture API, for applications that light geometry with fflight and draw it
//! with another renderer: capture of the assembled primitives of every draw
//! (`pipeline::capture`), and bulk lighting of whole vertex arrays.

use glam::{Vec3, Vec4};

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::pipeline::capture::Capture;
use crate::pipeline::vertex::{CurrentAttribs, ProcessedVertex};
use crate::state::arrays::read_components;

/// The layout of one strided array of floats of a bulk call: element i starts `i * stride`
/// bytes in and has `size` floats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FloatLayout {
    pub size: usize,
    pub stride: usize,
}

impl FloatLayout {
    /// `stride` in bytes, 0 for tightly packed; negative is GL_INVALID_VALUE.
    pub fn new(size: usize, stride: i32) -> GlResult<FloatLayout> {
        let stride = usize::try_from(stride).map_err(|_| GlError::InvalidValue)?;
        Ok(FloatLayout {
            size,
            stride: if stride == 0 { 4 * size } else { stride },
        })
    }

    /// Bytes `count` elements occupy; `None` if that does not fit the address space.
    pub fn len(&self, count: usize) -> Option<usize> {
        match count {
            0 => Some(0),
            _ => (count - 1)
                .checked_mul(self.stride)?
                .checked_add(4 * self.size)
                .filter(|&len| len <= isize::MAX as usize),
        }
    }

    /// Byte offset of element `i`.
    pub fn offset(&self, i: usize) -> usize {
        i * self.stride
    }

    /// Element `i` of `bytes`, padded with (0, 0, 0, 1).
    pub fn read(&self, bytes: &[u8], i: usize) -> [f32; 4] {
        let mut out = [0.0, 0.0, 0.0, 1.0];
        let offset = self.offset(i);
        read_components(
            &bytes[offset..offset + 4 * self.size],
            GL_FLOAT,
            false,
            &mut out[..self.size],
        );
        out
    }
}

impl Context {
    /// fflCaptureBegin: starts capturing the primitives of every draw, dropping what an
    /// earlier capture collected. GL_INVALID_OPERATION between glBegin and glEnd.
    pub fn capture_begin(&mut self) -> GlResult {
        self.outside_begin_end()?;
        self.capture.start();
        Ok(())
    }

    /// fflCaptureEnd: stops capturing; what was collected stays readable.
    /// GL_INVALID_OPERATION between glBegin and glEnd (the primitive in progress is not drawn
    /// yet).
    pub fn capture_end(&mut self) -> GlResult {
        self.outside_begin_end()?;
        self.capture.stop();
        Ok(())
    }

    /// What capture collected.
    pub fn captured(&self) -> &Capture {
        &self.capture
    }

    /// Lights `count` vertices with the current state through the same per-vertex path as
    /// glVertex (`DerivedState::process`): `vertex(i)` gives vertex i's object position and
    /// its normal and color (`None`: the current ones), `lit(i, v)` receives the result. Each
    /// result equals what glColor, glNormal, glVertex would give the vertex in immediate
    /// mode; the current attributes are left unchanged, and nothing is drawn or captured.
    /// GL_INVALID_OPERATION between glBegin and glEnd.
    pub fn light_vertices_with(
        &mut self,
        count: usize,
        mut vertex: impl FnMut(usize) -> (Vec4, Option<Vec3>, Option<Vec4>),
        mut lit: impl FnMut(usize, &ProcessedVertex),
    ) -> GlResult {
        self.outside_begin_end()?;
        let current = self.current;
        let derived = self.derived();
        for i in 0..count {
            let (position, normal, color) = vertex(i);
            let attribs = CurrentAttribs {
                normal: normal.unwrap_or(current.normal),
                color: color.unwrap_or(current.color),
                ..current
            };
            lit(i, &derived.process(position, &attribs));
        }
        Ok(())
    }

    /// `light_vertices_with` over slices: one result per position in `out`. Normals and
    /// colors, when given, and `out` must have an element per position (else
    /// GL_INVALID_VALUE).
    pub fn light_vertices(
        &mut self,
        positions: &[Vec4],
        normals: Option<&[Vec3]>,
        colors: Option<&[Vec4]>,
        out: &mut [ProcessedVertex],
    ) -> GlResult {
        let count = positions.len();
        let short = |len: Option<usize>| len.is_some_and(|len| len < count);
        if short(normals.map(<[_]>::len)) || short(colors.map(<[_]>::len)) || out.len() < count {
            return Err(GlError::InvalidValue);
        }
        self.light_vertices_with(
            count,
            |i| (positions[i], normals.map(|n| n[i]), colors.map(|c| c[i])),
            |i, v| out[i] = *v,
        )
    }
}

/// fflLightVertices' layout, validated: the vertex count, the input arrays (positions of
/// `position_size` floats, normals of 3, colors of 4) and the six outputs (4 floats each:
/// eye position, clip position, front primary, front secondary, back primary, back
/// secondary).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BulkLayout {
    pub count: usize,
    pub positions: FloatLayout,
    pub normals: FloatLayout,
    pub colors: FloatLayout,
    pub outputs: [FloatLayout; 6],
}

impl BulkLayout {
    /// GL_INVALID_VALUE for a negative count or stride, a position size other than 2, 3 or
    /// 4, or arrays too large for the address space.
    pub fn new(
        count: i32,
        position_size: i32,
        input_strides: [i32; 3],
        output_strides: [i32; 6],
    ) -> GlResult<BulkLayout> {
        let count = usize::try_from(count).map_err(|_| GlError::InvalidValue)?;
        if !(2..=4).contains(&position_size) {
            return Err(GlError::InvalidValue);
        }
        let [positions, normals, colors] = input_strides;
        let mut outputs = [FloatLayout { size: 4, stride: 0 }; 6];
        for (output, stride) in outputs.iter_mut().zip(output_strides) {
            *output = FloatLayout::new(4, stride)?;
        }
        let layout = BulkLayout {
            count,
            positions: FloatLayout::new(position_size as usize, positions)?,
            normals: FloatLayout::new(3, normals)?,
            colors: FloatLayout::new(4, colors)?,
            outputs,
        };
        let arrays = [layout.positions, layout.normals, layout.colors];
        if arrays
            .iter()
            .chain(&outputs)
            .any(|a| a.len(count).is_none())
        {
            return Err(GlError::InvalidValue);
        }
        Ok(layout)
    }
}
