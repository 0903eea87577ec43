//! Pixel storage, transfer, maps and zoom (§3.6): stored for queries and for the one image
//! fflight unpacks, the polygon stipple. Every command is GL_INVALID_OPERATION between glBegin
//! and glEnd (§2.6.3) and changes nothing on an error.

use super::query::{StateValue, floats, int};
use crate::context::Context;
use crate::error::GlResult;
use crate::gl::*;
use crate::state::pixel::{
    MAX_PIXEL_MAP_TABLE, StoreParam, TransferValue, is_index_map, pixel_map_index,
};

impl Context {
    /// glPixelStorei / glPixelStoref (§3.6.1, §4.3.2).
    pub fn pixel_store(&mut self, pname: GLenum, param: StoreParam) -> GlResult {
        self.outside_begin_end()?;
        self.pixel_store.set(pname, param)
    }

    /// glPixelTransferf / glPixelTransferi (§3.6.3).
    pub fn pixel_transfer(&mut self, pname: GLenum, param: f32) -> GlResult {
        self.outside_begin_end()?;
        self.pixel_mode.set_transfer(pname, param)
    }

    /// glPixelZoom (§3.6.4).
    pub fn pixel_zoom(&mut self, x: f32, y: f32) -> GlResult {
        self.outside_begin_end()?;
        self.pixel_mode.zoom = [x, y];
        Ok(())
    }

    /// glPixelMapfv (§3.6.3).
    pub fn pixel_map(&mut self, map: GLenum, mapsize: GLsizei, values: &[f32]) -> GlResult {
        self.outside_begin_end()?;
        self.pixel_maps.set(map, mapsize, values)
    }

    /// glPixelMapuiv / glPixelMapusv: color values are mapped from [0, max] to [0, 1] (`max`
    /// is the type's largest value), index values converted directly.
    pub fn pixel_map_integers<T: Copy + Into<f64>>(
        &mut self,
        map: GLenum,
        mapsize: GLsizei,
        values: &[T],
        max: f64,
    ) -> GlResult {
        let index_map = is_index_map(map);
        let floats: Vec<f32> = values
            .iter()
            .map(|&v| {
                let v: f64 = v.into();
                (if index_map { v } else { v / max }) as f32
            })
            .collect();
        self.pixel_map(map, mapsize, &floats)
    }

    /// glGetPixelMapfv (§6.1.3).
    pub fn get_pixel_map(&self, map: GLenum) -> GlResult<Vec<f32>> {
        self.outside_begin_end()?;
        Ok(self.pixel_maps.get(map)?.to_vec())
    }

    /// glGetPixelMapusv: color values mapped from [0, 1] to [0, 65535] and rounded, index
    /// values rounded; both clamped to the type.
    pub fn get_pixel_map_ushort(&self, map: GLenum) -> GlResult<Vec<GLushort>> {
        let scale = if is_index_map(map) { 1.0 } else { 65535.0 };
        let values = self.get_pixel_map(map)?;
        Ok(values
            .iter()
            .map(|&v| (v as f64 * scale).round().clamp(0.0, 65535.0) as GLushort)
            .collect())
    }

    /// glGetPixelMapuiv: color values mapped from [0, 1] to [0, 2^32 - 1] and truncated (the
    /// spec leaves the rounding open; Mesa truncates here, and rounds for glGetPixelMapusv),
    /// index values rounded; both clamped to the type.
    pub fn get_pixel_map_uint(&self, map: GLenum) -> GlResult<Vec<GLuint>> {
        let index_map = is_index_map(map);
        let values = self.get_pixel_map(map)?;
        Ok(values
            .iter()
            .map(|&v| {
                let v = if index_map {
                    (v as f64).round()
                } else {
                    (v as f64 * 4_294_967_295.0).trunc()
                };
                v.clamp(0.0, 4_294_967_295.0) as GLuint
            })
            .collect())
    }

    /// The pixel values of glGet (tables 6.21-6.25), or None for a pname that is not theirs.
    pub(crate) fn get_pixel_state(&self, pname: GLenum) -> Option<StateValue> {
        if let Some((value, boolean)) = self.pixel_store.get(pname) {
            return Some(if boolean {
                StateValue::Bools(vec![value != 0])
            } else {
                int(value)
            });
        }
        if let Some(value) = self.pixel_mode.transfer(pname) {
            return Some(match value {
                TransferValue::Bool(b) => StateValue::Bools(vec![b]),
                TransferValue::Int(i) => int(i),
                TransferValue::Float(f) => floats(&[f]),
            });
        }
        let sizes = GL_PIXEL_MAP_I_TO_I_SIZE..=GL_PIXEL_MAP_A_TO_A_SIZE;
        if sizes.contains(&pname) {
            let map = pname - GL_PIXEL_MAP_I_TO_I_SIZE + GL_PIXEL_MAP_I_TO_I;
            let index = pixel_map_index(map)?;
            return Some(int(self.pixel_maps.maps[index].len() as GLint));
        }
        Some(match pname {
            GL_ZOOM_X => floats(&[self.pixel_mode.zoom[0]]),
            GL_ZOOM_Y => floats(&[self.pixel_mode.zoom[1]]),
            GL_MAX_PIXEL_MAP_TABLE => int(MAX_PIXEL_MAP_TABLE as GLint),
            _ => return None,
        })
    }
}
