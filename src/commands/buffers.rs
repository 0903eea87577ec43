//! Buffer objects (§2.9): glGenBuffers, glDeleteBuffers, glBindBuffer, glIsBuffer,
//! glBufferData, glBufferSubData, glGetBufferSubData, glMapBuffer, glUnmapBuffer,
//! glGetBufferParameteriv, glGetBufferPointerv; the stores a draw reads its arrays from; and
//! the occlusion queries of the same GL version (§4.1.7): glGenQueries ... glGetQueryObject.

use std::sync::Arc;

use crate::commands::arrays::ArraySources;
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::arrays::{ALL_KINDS, ARRAY_KINDS, VertexArrays};
use crate::state::buffers::check_target;

/// The stores of the enabled arrays sourced from buffer objects, held for one draw.
pub type ArrayStores = [Option<Arc<Vec<u8>>>; ARRAY_KINDS];

impl Context {
    /// The buffer object name bound to `target` (0 if none): GL_INVALID_ENUM for another
    /// target.
    fn buffer_binding(&self, target: GLenum) -> GlResult<GLuint> {
        check_target(target)?;
        Ok(if target == GL_ARRAY_BUFFER {
            self.arrays.array_buffer
        } else {
            self.arrays.element_array_buffer
        })
    }

    /// The checks every buffer command starts with: outside glBegin/glEnd, a valid target.
    fn bound_buffer(&self, target: GLenum) -> GlResult<GLuint> {
        self.outside_begin_end()?;
        self.buffer_binding(target)
    }

    /// glGenBuffers.
    pub fn gen_buffers(&mut self, count: i32) -> GlResult<Vec<GLuint>> {
        self.outside_begin_end()?;
        let count = usize::try_from(count).map_err(|_| GlError::InvalidValue)?;
        let names = self.buffers.generate(count);
        if names.len() < count {
            return Err(GlError::OutOfMemory);
        }
        Ok(names)
    }

    /// glDeleteBuffers: every binding to a deleted object, the arrays' included, returns to 0.
    pub fn delete_buffers(&mut self, names: &[GLuint]) -> GlResult {
        self.outside_begin_end()?;
        for &name in names {
            if self.buffers.delete(name) {
                self.arrays.reset_bindings(name);
                self.forget_saved_buffer(name);
            }
        }
        Ok(())
    }

    /// glBindBuffer: binding an unused name creates its object.
    pub fn bind_buffer(&mut self, target: GLenum, name: GLuint) -> GlResult {
        self.bound_buffer(target)?;
        self.buffers.bind(name);
        if target == GL_ARRAY_BUFFER {
            self.arrays.array_buffer = name;
        } else {
            self.arrays.element_array_buffer = name;
        }
        Ok(())
    }

    /// glIsBuffer.
    pub fn is_buffer(&self, name: GLuint) -> GlResult<bool> {
        self.outside_begin_end()?;
        Ok(self.buffers.is_buffer(name))
    }

    /// glBufferData: `data` holds `size` bytes, or is `None` for a zeroed store.
    pub fn buffer_data(
        &mut self,
        target: GLenum,
        size: isize,
        data: Option<&[u8]>,
        usage: GLenum,
    ) -> GlResult {
        let name = self.bound_buffer(target)?;
        self.buffers.data(name, size, data, usage)
    }

    /// glBufferSubData: `data` holds `size` bytes.
    pub fn buffer_sub_data(
        &mut self,
        target: GLenum,
        offset: isize,
        size: isize,
        data: &[u8],
    ) -> GlResult {
        let name = self.bound_buffer(target)?;
        let store = self.buffers.sub_data_mut(name, offset, size)?;
        store.copy_from_slice(&data[..store.len()]);
        Ok(())
    }

    /// glGetBufferSubData.
    pub fn get_buffer_sub_data(
        &self,
        target: GLenum,
        offset: isize,
        size: isize,
    ) -> GlResult<&[u8]> {
        let name = self.bound_buffer(target)?;
        self.buffers.sub_data(name, offset, size)
    }

    /// glMapBuffer: the address of the store, valid until it is unmapped, replaced or deleted.
    pub fn map_buffer(&mut self, target: GLenum, access: GLenum) -> GlResult<usize> {
        let name = self.bound_buffer(target)?;
        self.buffers.map(name, access)
    }

    /// glUnmapBuffer.
    pub fn unmap_buffer(&mut self, target: GLenum) -> GlResult<bool> {
        let name = self.bound_buffer(target)?;
        self.buffers.unmap(name)
    }

    /// glGetBufferParameteriv.
    pub fn get_buffer_parameter(&self, target: GLenum, pname: GLenum) -> GlResult<i32> {
        let name = self.bound_buffer(target)?;
        self.buffers.parameter(name, pname)
    }

    /// glGetBufferPointerv.
    pub fn get_buffer_pointer(&mut self, target: GLenum, pname: GLenum) -> GlResult<usize> {
        let name = self.bound_buffer(target)?;
        self.buffers.map_pointer(name, pname)
    }

    /// The stores of the enabled arrays that buffer objects hold, for a draw: GL_INVALID_OPERATION
    /// if one is mapped.
    pub(crate) fn array_stores(&self, arrays: &VertexArrays) -> GlResult<ArrayStores> {
        let mut stores = ArrayStores::default();
        for (kind, array) in arrays.enabled() {
            stores[kind as usize] = self.buffers.store_for_draw(array.buffer)?;
        }
        Ok(stores)
    }

    /// The store of the buffer bound to GL_ELEMENT_ARRAY_BUFFER, if one is: glDrawElements'
    /// indices are then an offset into it. GL_INVALID_OPERATION while it is mapped.
    pub fn element_store(&self) -> GlResult<Option<Arc<Vec<u8>>>> {
        self.buffers
            .store_for_draw(self.arrays.element_array_buffer)
    }
}

/// `sources` with the arrays held by buffer objects read from `stores`: each from its offset
/// plus element `sources.base`. An offset past the store gives no bytes, which the draw's
/// checks reject (GL_INVALID_OPERATION).
pub(crate) fn with_stores<'a>(
    arrays: &VertexArrays,
    sources: &ArraySources<'a>,
    stores: &'a ArrayStores,
) -> ArraySources<'a> {
    let mut sources = *sources;
    for (kind, store) in ALL_KINDS.into_iter().zip(stores) {
        let Some(store) = store else { continue };
        let array = arrays.drawn(kind);
        let start = sources
            .base
            .checked_mul(array.effective_stride())
            .and_then(|offset| offset.checked_add(array.address));
        sources.bytes[kind as usize] = start.and_then(|start| store.get(start..)).unwrap_or(&[]);
    }
    sources
}

impl Context {
    /// glGenQueries.
    pub fn gen_queries(&mut self, count: i32) -> GlResult<Vec<GLuint>> {
        self.outside_begin_end()?;
        let count = usize::try_from(count).map_err(|_| GlError::InvalidValue)?;
        let names = self.queries.generate(count);
        if names.len() < count {
            return Err(GlError::OutOfMemory);
        }
        Ok(names)
    }

    /// glDeleteQueries: `ids` holds `count` names (fewer: a NULL pointer).
    pub fn delete_queries(&mut self, count: i32, ids: &[GLuint]) -> GlResult {
        self.outside_begin_end()?;
        let count = usize::try_from(count).map_err(|_| GlError::InvalidValue)?;
        if ids.len() < count {
            return Err(GlError::InvalidValue);
        }
        ids.iter().for_each(|&id| self.queries.delete(id));
        Ok(())
    }

    /// glIsQuery.
    pub fn is_query(&self, id: GLuint) -> GlResult<bool> {
        self.outside_begin_end()?;
        Ok(self.queries.is_query(id))
    }

    /// glBeginQuery.
    pub fn begin_query(&mut self, target: GLenum, id: GLuint) -> GlResult {
        self.outside_begin_end()?;
        self.queries.begin(target, id)
    }

    /// glEndQuery.
    pub fn end_query(&mut self, target: GLenum) -> GlResult {
        self.outside_begin_end()?;
        self.queries.end(target)
    }

    /// glGetQueryiv.
    pub fn get_query(&self, target: GLenum, pname: GLenum) -> GlResult<i32> {
        self.outside_begin_end()?;
        self.queries.target_parameter(target, pname)
    }

    /// glGetQueryObject{i,ui}v.
    pub fn get_query_object(&self, id: GLuint, pname: GLenum) -> GlResult<u32> {
        self.outside_begin_end()?;
        self.queries.object_parameter(id, pname)
    }
}
