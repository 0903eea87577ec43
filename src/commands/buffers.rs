//! Buffer objects (§2.9): glGenBuffers, glDeleteBuffers, glBindBuffer, glIsBuffer,
//! glBufferData, glBufferSubData, glGetBufferSubData, glMapBuffer, glUnmapBuffer,
//! glGetBufferParameteriv, glGetBufferPointerv; the stores a draw reads its arrays from; and
//! the occlusion queries of the same GL version (§4.1.7): glGenQueries ... glGetQueryObject.

use std::sync::Arc;

use crate::commands::arrays::ArraySources;
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::arrays::{ALL_KINDS, ARRAY_KINDS, ClientArray, VertexArrays};
use crate::state::buffers::check_target;
use crate::state::texture::MAX_TEXTURE_UNITS;

/// The stores of the enabled arrays sourced from buffer objects, held for one draw: by
/// `ArrayKind`, then texture units 1 and up's texture coordinate arrays (by unit - 1).
pub type ArrayStores = (
    [Option<Arc<Vec<u8>>>; ARRAY_KINDS],
    [Option<Arc<Vec<u8>>>; MAX_TEXTURE_UNITS - 1],
);

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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let names = ctx.gen_buffers(2)?;
    /// assert_eq!(names.len(), 2);
    /// assert!(!ctx.is_buffer(names[0])?); // a name only, until first bound
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.bind_buffer(GL_ARRAY_BUFFER, 5)?;
    /// ctx.delete_buffers(&[5])?;
    /// assert!(!ctx.is_buffer(5)?);
    /// assert_eq!(ctx.get(GL_ARRAY_BUFFER_BINDING)?.as_ints(), [0]); // unbound with it
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 3)?;
    /// assert!(ctx.is_buffer(3)?);
    /// assert_eq!(ctx.bind_buffer(GL_TEXTURE_2D, 3), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::Context;
    /// let mut ctx = Context::new();
    /// assert!(!ctx.is_buffer(0)?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn is_buffer(&self, name: GLuint) -> GlResult<bool> {
        self.outside_begin_end()?;
        Ok(self.buffers.is_buffer(name))
    }

    /// glBufferData: `data` holds `size` bytes, or is `None` for a zeroed store.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.bind_buffer(GL_ARRAY_BUFFER, 1)?;
    /// ctx.buffer_data(GL_ARRAY_BUFFER, 4, Some(&[1, 2, 3, 4]), GL_STATIC_DRAW)?;
    /// assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_SIZE)?, 4);
    /// ctx.buffer_data(GL_ARRAY_BUFFER, 2, None, GL_STREAM_DRAW)?; // a zeroed store
    /// assert_eq!(ctx.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 2)?, [0, 0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.bind_buffer(GL_ARRAY_BUFFER, 1)?;
    /// ctx.buffer_data(GL_ARRAY_BUFFER, 4, None, GL_STATIC_DRAW)?;
    /// ctx.buffer_sub_data(GL_ARRAY_BUFFER, 1, 2, &[7, 8])?;
    /// assert_eq!(ctx.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 4)?, [0, 7, 8, 0]);
    /// // Past the end of the store.
    /// assert_eq!(ctx.buffer_sub_data(GL_ARRAY_BUFFER, 3, 2, &[1, 1]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.bind_buffer(GL_ARRAY_BUFFER, 1)?;
    /// ctx.buffer_data(GL_ARRAY_BUFFER, 3, Some(&[9, 8, 7]), GL_STATIC_DRAW)?;
    /// assert_eq!(ctx.get_buffer_sub_data(GL_ARRAY_BUFFER, 1, 2)?, [8, 7]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.bind_buffer(GL_ARRAY_BUFFER, 1)?;
    /// ctx.buffer_data(GL_ARRAY_BUFFER, 16, None, GL_DYNAMIC_DRAW)?;
    /// let address = ctx.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY)?;
    /// assert_ne!(address, 0);
    /// assert_eq!(ctx.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY), Err(GlError::InvalidOperation));
    /// assert!(ctx.unmap_buffer(GL_ARRAY_BUFFER)?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn map_buffer(&mut self, target: GLenum, access: GLenum) -> GlResult<usize> {
        let name = self.bound_buffer(target)?;
        self.buffers.map(name, access)
    }

    /// glUnmapBuffer.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.bind_buffer(GL_ARRAY_BUFFER, 1)?;
    /// assert_eq!(ctx.unmap_buffer(GL_ARRAY_BUFFER), Err(GlError::InvalidOperation)); // not mapped
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn unmap_buffer(&mut self, target: GLenum) -> GlResult<bool> {
        let name = self.bound_buffer(target)?;
        self.buffers.unmap(name)
    }

    /// glGetBufferParameteriv.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.bind_buffer(GL_ARRAY_BUFFER, 1)?;
    /// assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_USAGE)?, GL_STATIC_DRAW as i32);
    /// assert_eq!(ctx.get_buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED)?, 0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_buffer_parameter(&self, target: GLenum, pname: GLenum) -> GlResult<i32> {
        let name = self.bound_buffer(target)?;
        self.buffers.parameter(name, pname)
    }

    /// glGetBufferPointerv.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.bind_buffer(GL_ARRAY_BUFFER, 1)?;
    /// ctx.buffer_data(GL_ARRAY_BUFFER, 8, None, GL_STATIC_DRAW)?;
    /// assert_eq!(ctx.get_buffer_pointer(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER)?, 0); // not mapped
    /// let address = ctx.map_buffer(GL_ARRAY_BUFFER, GL_READ_ONLY)?;
    /// assert_eq!(ctx.get_buffer_pointer(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER)?, address);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_buffer_pointer(&mut self, target: GLenum, pname: GLenum) -> GlResult<usize> {
        let name = self.bound_buffer(target)?;
        self.buffers.map_pointer(name, pname)
    }

    /// The stores of the enabled arrays that buffer objects hold, for a draw: GL_INVALID_OPERATION
    /// if one is mapped.
    pub(crate) fn array_stores(&self, arrays: &VertexArrays) -> GlResult<ArrayStores> {
        let mut stores = ArrayStores::default();
        for (kind, array) in arrays.enabled() {
            stores.0[kind as usize] = self.buffers.store_for_draw(array.buffer)?;
        }
        for (store, array) in stores.1.iter_mut().zip(arrays.enabled_unit_arrays()) {
            if let Some(array) = array {
                *store = self.buffers.store_for_draw(array.buffer)?;
            }
        }
        Ok(stores)
    }

    /// The store of the buffer bound to GL_ELEMENT_ARRAY_BUFFER, if one is: glDrawElements'
    /// indices are then an offset into it. GL_INVALID_OPERATION while it is mapped.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// assert!(ctx.element_store()?.is_none());
    /// ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 1)?;
    /// ctx.buffer_data(GL_ELEMENT_ARRAY_BUFFER, 2, Some(&[0, 1]), GL_STATIC_DRAW)?;
    /// assert_eq!(ctx.element_store()?.unwrap().as_slice(), [0, 1]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    let base = sources.base;
    let from_store = |array: &ClientArray, store: &'a Arc<Vec<u8>>| -> &'a [u8] {
        let start = base
            .checked_mul(array.effective_stride())
            .and_then(|offset| offset.checked_add(array.address));
        start.and_then(|start| store.get(start..)).unwrap_or(&[])
    };
    for (kind, store) in ALL_KINDS.into_iter().zip(&stores.0) {
        if let Some(store) = store {
            sources.bytes[kind as usize] = from_store(arrays.drawn(kind), store);
        }
    }
    for (unit, store) in (1..).zip(&stores.1) {
        if let Some(store) = store {
            sources.unit_bytes[unit - 1] = from_store(arrays.unit_tex_coords(unit), store);
        }
    }
    sources
}

impl Context {
    /// glGenQueries.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let mut ids = [0; 1];
    /// ctx.gen_queries(1, &mut ids)?;
    /// ctx.begin_query(GL_SAMPLES_PASSED, ids[0])?;
    /// ctx.end_query(GL_SAMPLES_PASSED)?;
    /// // Nothing is rasterized: no sample ever passes, and the result is available at once.
    /// assert_eq!(ctx.get_query_object(ids[0], GL_QUERY_RESULT)?, 0);
    /// assert_eq!(ctx.get_query_object(ids[0], GL_QUERY_RESULT_AVAILABLE)?, 1);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn gen_queries(&mut self, count: i32, names: &mut [GLuint]) -> GlResult {
        self.outside_begin_end()?;
        let count = usize::try_from(count).map_err(|_| GlError::InvalidValue)?;
        // Checked before any name is made: a NULL destination (an empty slice) changes nothing.
        let names = names.get_mut(..count).ok_or(GlError::InvalidValue)?;
        let generated = self.queries.generate(count);
        if generated.len() < count {
            return Err(GlError::OutOfMemory);
        }
        names.copy_from_slice(&generated);
        Ok(())
    }

    /// glDeleteQueries: `ids` holds `count` names (fewer: a NULL pointer).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let mut ids = [0; 2];
    /// ctx.gen_queries(2, &mut ids)?;
    /// ctx.begin_query(GL_SAMPLES_PASSED, ids[0])?;
    /// ctx.end_query(GL_SAMPLES_PASSED)?;
    /// ctx.delete_queries(2, &ids)?;
    /// assert!(!ctx.is_query(ids[0])?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let mut ids = [0; 1];
    /// ctx.gen_queries(1, &mut ids)?;
    /// assert!(!ctx.is_query(ids[0])?); // an object only once a query began with it
    /// ctx.begin_query(GL_SAMPLES_PASSED, ids[0])?;
    /// assert!(ctx.is_query(ids[0])?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn is_query(&self, id: GLuint) -> GlResult<bool> {
        self.outside_begin_end()?;
        Ok(self.queries.is_query(id))
    }

    /// glBeginQuery.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.begin_query(GL_SAMPLES_PASSED, 0), Err(GlError::InvalidOperation)); // name 0
    /// ctx.begin_query(GL_SAMPLES_PASSED, 1)?;
    /// assert_eq!(ctx.get_query(GL_SAMPLES_PASSED, GL_CURRENT_QUERY)?, 1);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn begin_query(&mut self, target: GLenum, id: GLuint) -> GlResult {
        self.outside_begin_end()?;
        self.queries.begin(target, id)
    }

    /// glEndQuery.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.end_query(GL_SAMPLES_PASSED), Err(GlError::InvalidOperation)); // none active
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn end_query(&mut self, target: GLenum) -> GlResult {
        self.outside_begin_end()?;
        self.queries.end(target)
    }

    /// glGetQueryiv.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_query(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS)?, 0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_query(&self, target: GLenum, pname: GLenum) -> GlResult<i32> {
        self.outside_begin_end()?;
        self.queries.target_parameter(target, pname)
    }

    /// glGetQueryObject{i,ui}v.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_query_object(9, GL_QUERY_RESULT), Err(GlError::InvalidOperation)); // no such query
    /// ```
    pub fn get_query_object(&self, id: GLuint, pname: GLenum) -> GlResult<u32> {
        self.outside_begin_end()?;
        self.queries.object_parameter(id, pname)
    }
}
