//! Buffer objects (§2.9, tables 2.6-2.8): named data stores the vertex arrays and the element
//! indices may be sourced from. The name space and the objects are server state; the
//! bindings to GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER are client vertex array state and
//! live in `VertexArrays`.

use std::collections::{BTreeSet, HashMap};
use std::sync::Arc;

use crate::error::{GlError, GlResult};
use crate::gl::*;

/// One buffer object: its data store and the state of table 2.6.
#[derive(Clone, Debug, PartialEq)]
pub struct BufferObject {
    /// Shared so that a draw can read it while the context changes (nothing writes a store
    /// a draw reads: a mapped store cannot be drawn from).
    pub data: Arc<Vec<u8>>,
    /// GL_BUFFER_USAGE.
    pub usage: GLenum,
    /// GL_BUFFER_ACCESS, given by glMapBuffer.
    pub access: GLenum,
    /// GL_BUFFER_MAPPED.
    pub mapped: bool,
}

impl Default for BufferObject {
    /// A new object: a zero-sized store (table 2.6).
    fn default() -> BufferObject {
        BufferObject {
            data: Arc::new(Vec::new()),
            usage: GL_STATIC_DRAW,
            access: GL_READ_WRITE,
            mapped: false,
        }
    }
}

/// The buffer object name space: the objects, and the names glGenBuffers handed out that no
/// bind has made objects yet.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BufferObjects {
    objects: HashMap<GLuint, BufferObject>,
    reserved: BTreeSet<GLuint>,
}

/// GL_INVALID_ENUM unless `target` is a buffer binding point.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::buffers::check_target, GlError};
/// assert_eq!(check_target(GL_ARRAY_BUFFER), Ok(()));
/// assert_eq!(check_target(GL_TEXTURE_2D), Err(GlError::InvalidEnum));
/// ```
pub fn check_target(target: GLenum) -> GlResult {
    match target {
        GL_ARRAY_BUFFER | GL_ELEMENT_ARRAY_BUFFER => Ok(()),
        _ => Err(GlError::InvalidEnum),
    }
}

fn check_usage(usage: GLenum) -> GlResult {
    match usage {
        GL_STREAM_DRAW | GL_STREAM_READ | GL_STREAM_COPY | GL_STATIC_DRAW | GL_STATIC_READ
        | GL_STATIC_COPY | GL_DYNAMIC_DRAW | GL_DYNAMIC_READ | GL_DYNAMIC_COPY => Ok(()),
        _ => Err(GlError::InvalidEnum),
    }
}

/// `offset..offset + size` as a range of a store of `len` bytes: GL_INVALID_VALUE if either
/// is negative or the range runs past the end (§2.9).
fn range(offset: isize, size: isize, len: usize) -> GlResult<std::ops::Range<usize>> {
    let (offset, size) = (usize::try_from(offset), usize::try_from(size));
    let (Ok(offset), Ok(size)) = (offset, size) else {
        return Err(GlError::InvalidValue);
    };
    match offset.checked_add(size) {
        Some(end) if end <= len => Ok(offset..end),
        _ => Err(GlError::InvalidValue),
    }
}

impl BufferObjects {
    /// glGenBuffers.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::buffers::BufferObjects;
    /// let mut buffers = BufferObjects::default();
    /// let names = buffers.generate(2);
    /// assert_ne!(names[0], names[1]);
    /// assert!(!buffers.is_buffer(names[0]));
    /// ```
    pub fn generate(&mut self, count: usize) -> Vec<GLuint> {
        super::names::generate(self.objects.keys().copied(), &mut self.reserved, count)
    }

    /// glIsBuffer: whether `name` is an object (a name glGenBuffers returned is not one
    /// until it is bound).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::buffers::BufferObjects;
    /// let mut buffers = BufferObjects::default();
    /// buffers.bind(5);
    /// assert!(buffers.is_buffer(5) && !buffers.is_buffer(0));
    /// ```
    pub fn is_buffer(&self, name: GLuint) -> bool {
        self.objects.contains_key(&name)
    }

    /// Binding `name` (not 0) creates its object if it has none (§2.9).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::buffers::BufferObjects;
    /// let mut buffers = BufferObjects::default();
    /// buffers.bind(2);
    /// assert!(buffers.bound(2)?.data.is_empty()); // a new object has an empty store
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn bind(&mut self, name: GLuint) {
        if name != 0 {
            self.reserved.remove(&name);
            self.objects.entry(name).or_default();
        }
    }

    /// glDeleteBuffers of one name: whether an object was deleted (0 and unused names are
    /// ignored). The caller resets the bindings to it.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::buffers::BufferObjects;
    /// let mut buffers = BufferObjects::default();
    /// buffers.bind(2);
    /// assert!(buffers.delete(2));
    /// assert!(!buffers.delete(2)); // already gone
    /// ```
    pub fn delete(&mut self, name: GLuint) -> bool {
        self.reserved.remove(&name);
        self.objects.remove(&name).is_some()
    }

    /// The object bound as `name`: GL_INVALID_OPERATION for 0 (no object to modify or query).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{state::buffers::BufferObjects, GlError};
    /// let buffers = BufferObjects::default();
    /// assert_eq!(buffers.bound(0).err(), Some(GlError::InvalidOperation));
    /// ```
    pub fn bound(&self, name: GLuint) -> GlResult<&BufferObject> {
        self.objects.get(&name).ok_or(GlError::InvalidOperation)
    }

    fn bound_mut(&mut self, name: GLuint) -> GlResult<&mut BufferObject> {
        self.objects.get_mut(&name).ok_or(GlError::InvalidOperation)
    }

    /// glBufferData on the object bound as `name`: Mesa's order of checks (binding, size,
    /// usage). A new store of `size` bytes, copied from `data` or zeroed; a mapped store is
    /// unmapped. GL_OUT_OF_MEMORY when the store cannot be allocated.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::buffers::BufferObjects, GlError};
    /// let mut buffers = BufferObjects::default();
    /// buffers.bind(1);
    /// buffers.data(1, 3, Some(&[1, 2, 3]), GL_STREAM_READ)?;
    /// assert_eq!(buffers.bound(1)?.data.as_slice(), [1, 2, 3]);
    /// assert_eq!(buffers.data(1, -1, None, GL_STREAM_READ), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn data(
        &mut self,
        name: GLuint,
        size: isize,
        data: Option<&[u8]>,
        usage: GLenum,
    ) -> GlResult {
        let object = self.bound_mut(name)?;
        let size = usize::try_from(size).map_err(|_| GlError::InvalidValue)?;
        check_usage(usage)?;
        let mut store = Vec::new();
        store
            .try_reserve_exact(size)
            .map_err(|_| GlError::OutOfMemory)?;
        match data {
            Some(data) => store.extend_from_slice(&data[..size]),
            None => store.resize(size, 0),
        }
        *object = BufferObject {
            data: Arc::new(store),
            usage,
            ..BufferObject::default()
        };
        Ok(())
    }

    /// The bytes `offset..offset + size` of the unmapped object bound as `name`, for
    /// glBufferSubData to replace: GL_INVALID_VALUE outside the store, GL_INVALID_OPERATION
    /// while mapped.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::buffers::BufferObjects};
    /// let mut buffers = BufferObjects::default();
    /// buffers.bind(1);
    /// buffers.data(1, 4, None, GL_STATIC_DRAW)?;
    /// buffers.sub_data_mut(1, 2, 2)?.copy_from_slice(&[9, 9]);
    /// assert_eq!(buffers.sub_data(1, 0, 4)?, [0, 0, 9, 9]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn sub_data_mut(
        &mut self,
        name: GLuint,
        offset: isize,
        size: isize,
    ) -> GlResult<&mut [u8]> {
        let object = self.bound_mut(name)?;
        let range = range(offset, size, object.data.len())?;
        if object.mapped {
            return Err(GlError::InvalidOperation);
        }
        Ok(&mut Arc::make_mut(&mut object.data)[range])
    }

    /// glGetBufferSubData's bytes, with glBufferSubData's errors.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::buffers::BufferObjects, GlError};
    /// let mut buffers = BufferObjects::default();
    /// buffers.bind(1);
    /// buffers.data(1, 4, None, GL_STATIC_DRAW)?;
    /// assert_eq!(buffers.sub_data(1, 3, 2).err(), Some(GlError::InvalidValue)); // past the end
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn sub_data(&self, name: GLuint, offset: isize, size: isize) -> GlResult<&[u8]> {
        let object = self.bound(name)?;
        let range = range(offset, size, object.data.len())?;
        if object.mapped {
            return Err(GlError::InvalidOperation);
        }
        Ok(&object.data[range])
    }

    /// glMapBuffer: the store's address, which stays valid until it is unmapped, replaced or
    /// deleted. GL_INVALID_OPERATION if already mapped or (as in Mesa) empty.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::buffers::BufferObjects, GlError};
    /// let mut buffers = BufferObjects::default();
    /// buffers.bind(1);
    /// assert_eq!(buffers.map(1, GL_READ_WRITE), Err(GlError::InvalidOperation)); // empty, as in Mesa
    /// buffers.data(1, 8, None, GL_STATIC_DRAW)?;
    /// assert_ne!(buffers.map(1, GL_READ_WRITE)?, 0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn map(&mut self, name: GLuint, access: GLenum) -> GlResult<usize> {
        if !matches!(access, GL_READ_ONLY | GL_WRITE_ONLY | GL_READ_WRITE) {
            return Err(GlError::InvalidEnum);
        }
        let object = self.bound_mut(name)?;
        if object.mapped || object.data.is_empty() {
            return Err(GlError::InvalidOperation);
        }
        object.mapped = true;
        object.access = access;
        Ok(Arc::make_mut(&mut object.data).as_mut_ptr() as usize)
    }

    /// glUnmapBuffer: GL_INVALID_OPERATION unless mapped. The store is never lost while
    /// mapped, so the answer is always GL_TRUE.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::buffers::BufferObjects};
    /// let mut buffers = BufferObjects::default();
    /// buffers.bind(1);
    /// buffers.data(1, 8, None, GL_STATIC_DRAW)?;
    /// buffers.map(1, GL_WRITE_ONLY)?;
    /// assert!(buffers.unmap(1)?);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn unmap(&mut self, name: GLuint) -> GlResult<bool> {
        let object = self.bound_mut(name)?;
        if !object.mapped {
            return Err(GlError::InvalidOperation);
        }
        object.mapped = false;
        object.access = GL_READ_WRITE;
        Ok(true)
    }

    /// glGetBufferParameteriv (table 2.6).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::buffers::BufferObjects};
    /// let mut buffers = BufferObjects::default();
    /// buffers.bind(1);
    /// assert_eq!(buffers.parameter(1, GL_BUFFER_ACCESS)?, GL_READ_WRITE as i32);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn parameter(&self, name: GLuint, pname: GLenum) -> GlResult<i32> {
        let object = self.bound(name)?;
        Ok(match pname {
            GL_BUFFER_SIZE => i32::try_from(object.data.len()).unwrap_or(i32::MAX),
            GL_BUFFER_USAGE => object.usage as i32,
            GL_BUFFER_ACCESS => object.access as i32,
            GL_BUFFER_MAPPED => object.mapped as i32,
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glGetBufferPointerv: the mapped store's address, or 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::buffers::BufferObjects};
    /// let mut buffers = BufferObjects::default();
    /// buffers.bind(1);
    /// assert_eq!(buffers.map_pointer(1, GL_BUFFER_MAP_POINTER)?, 0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn map_pointer(&mut self, name: GLuint, pname: GLenum) -> GlResult<usize> {
        if pname != GL_BUFFER_MAP_POINTER {
            return Err(GlError::InvalidEnum);
        }
        let object = self.bound_mut(name)?;
        Ok(if object.mapped {
            Arc::make_mut(&mut object.data).as_mut_ptr() as usize
        } else {
            0
        })
    }

    /// The store of object `name` for a draw to read: GL_INVALID_OPERATION while it is
    /// mapped (§2.9.1). `None` for 0, which sources from client memory.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::buffers::BufferObjects, GlError};
    /// let mut buffers = BufferObjects::default();
    /// assert!(buffers.store_for_draw(0)?.is_none()); // client memory
    /// buffers.bind(1);
    /// buffers.data(1, 4, None, GL_STATIC_DRAW)?;
    /// buffers.map(1, GL_READ_ONLY)?;
    /// assert_eq!(buffers.store_for_draw(1).err(), Some(GlError::InvalidOperation)); // mapped
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn store_for_draw(&self, name: GLuint) -> GlResult<Option<Arc<Vec<u8>>>> {
        if name == 0 {
            return Ok(None);
        }
        // A binding to a deleted object was reset; an object always exists for a binding.
        let object = self.bound(name)?;
        if object.mapped {
            return Err(GlError::InvalidOperation);
        }
        Ok(Some(object.data.clone()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_count_up_from_the_largest_in_use() {
        let mut buffers = BufferObjects::default();
        assert_eq!(buffers.generate(3), [1, 2, 3]);
        assert!(!buffers.is_buffer(1));
        buffers.bind(10);
        assert_eq!(buffers.generate(1), [11]);
        assert!(buffers.delete(10));
        assert!(!buffers.delete(10));
    }

    #[test]
    fn sub_data_ranges_are_checked() {
        let mut buffers = BufferObjects::default();
        buffers.bind(1);
        buffers.data(1, 8, None, GL_STATIC_DRAW).unwrap();
        assert_eq!(buffers.sub_data(1, 4, 4).unwrap(), &[0; 4]);
        for (offset, size) in [(-1, 1), (0, -1), (5, 4), (isize::MAX, 2)] {
            assert_eq!(
                buffers.sub_data(1, offset, size),
                Err(GlError::InvalidValue)
            );
        }
        buffers.map(1, GL_READ_ONLY).unwrap();
        assert_eq!(
            buffers.sub_data_mut(1, 0, 1).map(|_| ()),
            Err(GlError::InvalidOperation)
        );
        assert_eq!(
            buffers.store_for_draw(1).map(|_| ()),
            Err(GlError::InvalidOperation)
        );
    }
}
