//! Vertex array state (§2.8, table 6.8): each array's size, type, stride, enable and the
//! application's pointer, kept as an address that only the C layer dereferences. Also the
//! decoding of one array element from bytes, with the conversions of table 2.9.

use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::convert::Component;
use crate::state::texture::MAX_TEXTURE_UNITS;

/// The arrays fflight draws from, in the order `VertexArrays` stores them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArrayKind {
    /// GL_VERTEX_ARRAY.
    Vertex,
    /// GL_NORMAL_ARRAY.
    Normal,
    /// GL_COLOR_ARRAY.
    Color,
    /// GL_TEXTURE_COORD_ARRAY (of the client active texture unit).
    TexCoord,
    /// GL_EDGE_FLAG_ARRAY.
    EdgeFlag,
    /// GL_SECONDARY_COLOR_ARRAY.
    SecondaryColor,
    /// GL_FOG_COORD_ARRAY.
    FogCoord,
    /// Color indices: made current by glArrayElement, used by nothing in RGBA mode.
    Index,
}

/// How many arrays there are.
pub const ARRAY_KINDS: usize = 8;

/// Every array, in storage order.
pub const ALL_KINDS: [ArrayKind; ARRAY_KINDS] = [
    ArrayKind::Vertex,
    ArrayKind::Normal,
    ArrayKind::Color,
    ArrayKind::TexCoord,
    ArrayKind::EdgeFlag,
    ArrayKind::SecondaryColor,
    ArrayKind::FogCoord,
    ArrayKind::Index,
];

impl ArrayKind {
    /// The array glEnableClientState names; `None` for unknown names.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::ArrayKind};
    /// assert_eq!(ArrayKind::of_client_state(GL_FOG_COORD_ARRAY), Some(ArrayKind::FogCoord));
    /// assert_eq!(ArrayKind::of_client_state(GL_LIGHTING), None);
    /// ```
    pub fn of_client_state(array: GLenum) -> Option<ArrayKind> {
        Some(match array {
            GL_VERTEX_ARRAY => ArrayKind::Vertex,
            GL_NORMAL_ARRAY => ArrayKind::Normal,
            GL_COLOR_ARRAY => ArrayKind::Color,
            GL_TEXTURE_COORD_ARRAY => ArrayKind::TexCoord,
            GL_EDGE_FLAG_ARRAY => ArrayKind::EdgeFlag,
            GL_SECONDARY_COLOR_ARRAY => ArrayKind::SecondaryColor,
            GL_FOG_COORD_ARRAY => ArrayKind::FogCoord,
            GL_INDEX_ARRAY => ArrayKind::Index,
            _ => return None,
        })
    }

    /// The array whose pointer glGetPointerv's `pname` asks for.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::ArrayKind};
    /// assert_eq!(ArrayKind::of_pointer_name(GL_COLOR_ARRAY_POINTER), Some(ArrayKind::Color));
    /// ```
    pub fn of_pointer_name(pname: GLenum) -> Option<ArrayKind> {
        Some(match pname {
            GL_VERTEX_ARRAY_POINTER => ArrayKind::Vertex,
            GL_NORMAL_ARRAY_POINTER => ArrayKind::Normal,
            GL_COLOR_ARRAY_POINTER => ArrayKind::Color,
            GL_TEXTURE_COORD_ARRAY_POINTER => ArrayKind::TexCoord,
            GL_EDGE_FLAG_ARRAY_POINTER => ArrayKind::EdgeFlag,
            GL_SECONDARY_COLOR_ARRAY_POINTER => ArrayKind::SecondaryColor,
            GL_FOG_COORD_ARRAY_POINTER => ArrayKind::FogCoord,
            GL_INDEX_ARRAY_POINTER => ArrayKind::Index,
            _ => return None,
        })
    }

    /// The component types the array's pointer command accepts (§2.8, table 2.4).
    fn accepts_type(self, component_type: GLenum) -> bool {
        match self {
            ArrayKind::Vertex | ArrayKind::TexCoord => {
                matches!(component_type, GL_SHORT | GL_INT | GL_FLOAT | GL_DOUBLE)
            }
            ArrayKind::Normal => {
                matches!(
                    component_type,
                    GL_BYTE | GL_SHORT | GL_INT | GL_FLOAT | GL_DOUBLE
                )
            }
            ArrayKind::Color | ArrayKind::SecondaryColor => {
                component_size(component_type).is_some()
            }
            ArrayKind::EdgeFlag => component_type == GL_UNSIGNED_BYTE,
            ArrayKind::FogCoord => matches!(component_type, GL_FLOAT | GL_DOUBLE),
            ArrayKind::Index => matches!(
                component_type,
                GL_UNSIGNED_BYTE | GL_SHORT | GL_INT | GL_FLOAT | GL_DOUBLE
            ),
        }
    }

    /// The component counts the array's pointer command accepts (table 2.4).
    fn accepts_size(self, size: i32) -> bool {
        match self {
            ArrayKind::Vertex => (2..=4).contains(&size),
            ArrayKind::Normal => size == 3,
            ArrayKind::Color => (3..=4).contains(&size),
            ArrayKind::TexCoord => (1..=4).contains(&size),
            ArrayKind::EdgeFlag | ArrayKind::FogCoord | ArrayKind::Index => size == 1,
            ArrayKind::SecondaryColor => size == 3,
        }
    }

    /// Integer colors and normals are normalized (table 2.9); coordinates convert directly.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::arrays::ArrayKind;
    /// assert!(ArrayKind::Normal.normalized() && !ArrayKind::Vertex.normalized());
    /// ```
    pub fn normalized(self) -> bool {
        matches!(
            self,
            ArrayKind::Normal | ArrayKind::Color | ArrayKind::SecondaryColor
        )
    }
}

/// The size in bytes of a GL component type; `None` for a type no array accepts.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::arrays::component_size};
/// assert_eq!((component_size(GL_SHORT), component_size(GL_DOUBLE)), (Some(2), Some(8)));
/// assert_eq!(component_size(GL_BITMAP), None);
/// ```
pub fn component_size(component_type: GLenum) -> Option<usize> {
    Some(match component_type {
        GL_BYTE | GL_UNSIGNED_BYTE => 1,
        GL_SHORT | GL_UNSIGNED_SHORT => 2,
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT => 4,
        GL_DOUBLE => 8,
        _ => return None,
    })
}

/// One vertex array's state (table 6.8).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ClientArray {
    /// Enabled with glEnableClientState.
    pub enabled: bool,
    /// Components per element.
    pub size: i32,
    /// The component type (GL_FLOAT, GL_SHORT, ...).
    pub component_type: GLenum,
    /// Bytes from one element to the next as specified: 0 means tightly packed.
    pub stride: i32,
    /// The application's pointer as an address (0 = NULL), or with `buffer` an offset into
    /// that buffer object's store. Only src/capi/ dereferences addresses.
    pub address: usize,
    /// The buffer object the array is sourced from (§2.9.1), 0 for client memory.
    pub buffer: u32,
}

impl ClientArray {
    fn initial(size: i32, component_type: GLenum) -> ClientArray {
        ClientArray {
            enabled: false,
            size,
            component_type,
            stride: 0,
            address: 0,
            buffer: 0,
        }
    }

    /// Where elements `first..=last` are in client memory (`None` for an array in a buffer
    /// object): see `VertexArrays::spans`.
    fn client_span(&self, first: usize, last: usize) -> GlResult<Option<ByteSpan>> {
        if self.buffer != 0 {
            return Ok(None);
        }
        if self.address == 0 {
            return Err(GlError::InvalidOperation);
        }
        let (address, len) = first
            .checked_mul(self.effective_stride())
            .and_then(|offset| self.address.checked_add(offset))
            .zip(self.span_len(first, last))
            .filter(|&(address, len)| address.checked_add(len).is_some())
            .ok_or(GlError::InvalidValue)?;
        Ok(Some(ByteSpan { address, len }))
    }

    /// Bytes one element occupies.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_pointer(ArrayKind::Vertex, 3, GL_SHORT, 0, 0x100)?;
    /// assert_eq!(arrays.get(ArrayKind::Vertex).element_size(), 6);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn element_size(&self) -> usize {
        self.size as usize * component_size(self.component_type).unwrap_or(1)
    }

    /// Bytes from one element to the next: the stride, or the element size for 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_pointer(ArrayKind::Color, 4, GL_UNSIGNED_BYTE, 0, 0x100)?;
    /// assert_eq!(arrays.get(ArrayKind::Color).effective_stride(), 4); // 0: tightly packed
    /// arrays.set_pointer(ArrayKind::Color, 4, GL_UNSIGNED_BYTE, 16, 0x100)?;
    /// assert_eq!(arrays.get(ArrayKind::Color).effective_stride(), 16);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn effective_stride(&self) -> usize {
        if self.stride == 0 {
            self.element_size()
        } else {
            self.stride as usize
        }
    }

    /// Bytes elements `first..=last` occupy, counted from the start of element `first`;
    /// `None` if that does not fit the address space.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_pointer(ArrayKind::Vertex, 2, GL_FLOAT, 12, 0x100)?;
    /// // Elements 1 to 3: two strides, then one element of 8 bytes.
    /// assert_eq!(arrays.get(ArrayKind::Vertex).span_len(1, 3), Some(2 * 12 + 8));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn span_len(&self, first: usize, last: usize) -> Option<usize> {
        (last - first)
            .checked_mul(self.effective_stride())?
            .checked_add(self.element_size())
            .filter(|&len| len <= isize::MAX as usize)
    }

    /// Element `index` of the array whose bytes start with element `base`, as 4 components
    /// padded with (0, 0, 0, 1) and converted as the array's commands convert them. `bytes`
    /// must hold the element (see `span_len`).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_pointer(ArrayKind::Vertex, 2, GL_FLOAT, 0, 0x100)?;
    /// let bytes: Vec<u8> = [1.0f32, 2.0, 3.0, 4.0].iter().flat_map(|v| v.to_ne_bytes()).collect();
    /// // Element 1 of bytes starting at element 0, padded to four components.
    /// assert_eq!(arrays.get(ArrayKind::Vertex).read(ArrayKind::Vertex, &bytes, 0, 1), [3.0, 4.0, 0.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn read(&self, kind: ArrayKind, bytes: &[u8], base: usize, index: usize) -> [f32; 4] {
        let offset = (index - base) * self.effective_stride();
        let mut out = [0.0, 0.0, 0.0, 1.0];
        read_components(
            &bytes[offset..offset + self.element_size()],
            self.component_type,
            kind.normalized(),
            &mut out[..self.size as usize],
        );
        out
    }
}

/// Decodes `out.len()` components of `component_type` from the front of `bytes` (native byte
/// order, any alignment): normalized per table 2.9, or converted directly.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::arrays::read_components};
/// let mut out = [0.0; 2];
/// read_components(&[255, 0], GL_UNSIGNED_BYTE, true, &mut out);
/// assert_eq!(out, [1.0, 0.0]);
/// read_components(&[255, 0], GL_UNSIGNED_BYTE, false, &mut out);
/// assert_eq!(out, [255.0, 0.0]);
/// ```
pub fn read_components(bytes: &[u8], component_type: GLenum, normalize: bool, out: &mut [f32]) {
    fn each<T: Component, const N: usize>(
        bytes: &[u8],
        from_bytes: fn([u8; N]) -> T,
        normalize: bool,
        out: &mut [f32],
    ) {
        for (o, chunk) in out.iter_mut().zip(bytes.chunks_exact(N)) {
            let value = from_bytes(chunk.try_into().expect("chunks of N bytes"));
            *o = if normalize {
                value.normalized()
            } else {
                value.direct()
            };
        }
    }
    match component_type {
        GL_BYTE => each(bytes, i8::from_ne_bytes, normalize, out),
        GL_UNSIGNED_BYTE => each(bytes, u8::from_ne_bytes, normalize, out),
        GL_SHORT => each(bytes, i16::from_ne_bytes, normalize, out),
        GL_UNSIGNED_SHORT => each(bytes, u16::from_ne_bytes, normalize, out),
        GL_INT => each(bytes, i32::from_ne_bytes, normalize, out),
        GL_UNSIGNED_INT => each(bytes, u32::from_ne_bytes, normalize, out),
        GL_FLOAT => each(bytes, f32::from_ne_bytes, normalize, out),
        GL_DOUBLE => each(bytes, f64::from_ne_bytes, normalize, out),
        _ => {}
    }
}

/// Where one enabled array's bytes for a draw are: `len` bytes at `address`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ByteSpan {
    /// The first byte.
    pub address: usize,
    /// How many bytes.
    pub len: usize,
}

/// The vertex arrays of a context (table 6.8).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VertexArrays {
    /// The arrays draws read; the texture coordinate array is texture unit 0's.
    arrays: [ClientArray; ARRAY_KINDS],
    /// Texture units 1 and up's texture coordinate arrays: draws read them for capture only
    /// (feedback reports unit 0's coordinates, §5.3).
    other_tex_coords: [ClientArray; MAX_TEXTURE_UNITS - 1],
    /// GL_CLIENT_ACTIVE_TEXTURE - GL_TEXTURE0: the unit whose texture coordinate array
    /// glTexCoordPointer, glEnableClientState and the array queries address (§2.8).
    pub client_active_texture: usize,
    /// The buffer objects bound to GL_ARRAY_BUFFER (copied into each array whose pointer is
    /// set) and GL_ELEMENT_ARRAY_BUFFER (where glDrawElements finds its indices).
    pub array_buffer: u32,
    /// See `array_buffer`.
    pub element_array_buffer: u32,
}

impl Default for VertexArrays {
    fn default() -> VertexArrays {
        VertexArrays {
            arrays: [
                ClientArray::initial(4, GL_FLOAT),
                ClientArray::initial(3, GL_FLOAT),
                ClientArray::initial(4, GL_FLOAT),
                ClientArray::initial(4, GL_FLOAT),
                ClientArray::initial(1, GL_UNSIGNED_BYTE),
                ClientArray::initial(3, GL_FLOAT),
                ClientArray::initial(1, GL_FLOAT),
                ClientArray::initial(1, GL_FLOAT),
            ],
            other_tex_coords: [ClientArray::initial(4, GL_FLOAT); MAX_TEXTURE_UNITS - 1],
            client_active_texture: 0,
            array_buffer: 0,
            element_array_buffer: 0,
        }
    }
}

impl VertexArrays {
    /// The array `kind` as the array commands and queries see it: for texture coordinates,
    /// the client active texture unit's.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let arrays = VertexArrays::default();
    /// let normals = arrays.get(ArrayKind::Normal);
    /// assert_eq!((normals.enabled, normals.size, normals.component_type), (false, 3, GL_FLOAT));
    /// ```
    pub fn get(&self, kind: ArrayKind) -> &ClientArray {
        match (kind, self.client_active_texture) {
            (ArrayKind::TexCoord, unit @ 1..) => &self.other_tex_coords[unit - 1],
            _ => &self.arrays[kind as usize],
        }
    }

    fn get_mut(&mut self, kind: ArrayKind) -> &mut ClientArray {
        match (kind, self.client_active_texture) {
            (ArrayKind::TexCoord, unit @ 1..) => &mut self.other_tex_coords[unit - 1],
            _ => &mut self.arrays[kind as usize],
        }
    }

    /// The array `kind` that draws read (texture unit 0's texture coordinates).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_client_active_texture(GL_TEXTURE1)?;
    /// arrays.set_pointer(ArrayKind::TexCoord, 2, GL_FLOAT, 0, 0x100)?; // unit 1's
    /// assert_eq!(arrays.get(ArrayKind::TexCoord).size, 2);
    /// assert_eq!(arrays.drawn(ArrayKind::TexCoord).size, 4); // unit 0's, untouched
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn drawn(&self, kind: ArrayKind) -> &ClientArray {
        &self.arrays[kind as usize]
    }

    /// glClientActiveTexture (§2.8): GL_INVALID_ENUM unless `texture` is GL_TEXTUREi of a unit.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::VertexArrays, GlError};
    /// let mut arrays = VertexArrays::default();
    /// assert_eq!(arrays.set_client_active_texture(GL_TEXTURE0 + 8), Err(GlError::InvalidEnum));
    /// ```
    pub fn set_client_active_texture(&mut self, texture: GLenum) -> GlResult {
        let unit = texture.wrapping_sub(GL_TEXTURE0) as usize;
        if unit >= MAX_TEXTURE_UNITS {
            return Err(GlError::InvalidEnum);
        }
        self.client_active_texture = unit;
        Ok(())
    }

    /// glVertexPointer, glNormalPointer ...: Mesa's order of checks (stride, type, size).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}, GlError};
    /// let mut arrays = VertexArrays::default();
    /// // Mesa's order: the stride first.
    /// assert_eq!(arrays.set_pointer(ArrayKind::Vertex, 5, GL_FLOAT, -4, 0x100), Err(GlError::InvalidValue));
    /// assert_eq!(arrays.set_pointer(ArrayKind::Vertex, 3, GL_UNSIGNED_BYTE, 0, 0x100), Err(GlError::InvalidEnum));
    /// ```
    pub fn set_pointer(
        &mut self,
        kind: ArrayKind,
        size: i32,
        component_type: GLenum,
        stride: i32,
        address: usize,
    ) -> GlResult {
        if stride < 0 {
            return Err(GlError::InvalidValue);
        }
        if !kind.accepts_type(component_type) {
            return Err(GlError::InvalidEnum);
        }
        if !kind.accepts_size(size) {
            return Err(GlError::InvalidValue);
        }
        let buffer = self.array_buffer;
        let array = self.get_mut(kind);
        array.size = size;
        array.component_type = component_type;
        array.stride = stride;
        array.address = address;
        array.buffer = buffer;
        Ok(())
    }

    /// Every binding to buffer object `name` returns to 0 (it was deleted): GL_ARRAY_BUFFER,
    /// GL_ELEMENT_ARRAY_BUFFER, and the arrays sourced from it go back to client memory.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.array_buffer = 3;
    /// arrays.set_pointer(ArrayKind::Vertex, 3, GL_FLOAT, 0, 0)?; // sourced from buffer 3
    /// arrays.reset_bindings(3); // buffer 3 deleted
    /// assert_eq!(arrays.array_buffer, 0);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn reset_bindings(&mut self, name: u32) {
        let arrays = (self.arrays.iter_mut().chain(&mut self.other_tex_coords))
            .map(|array| &mut array.buffer);
        for binding in arrays.chain([&mut self.array_buffer, &mut self.element_array_buffer]) {
            if *binding == name {
                *binding = 0;
            }
        }
    }

    /// glEnableClientState / glDisableClientState.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::VertexArrays, GlError};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_enabled(GL_EDGE_FLAG_ARRAY, true)?;
    /// assert_eq!(arrays.is_enabled(GL_EDGE_FLAG_ARRAY), Some(true));
    /// assert_eq!(arrays.set_enabled(GL_TEXTURE_2D, true), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set_enabled(&mut self, array: GLenum, enabled: bool) -> GlResult {
        match ArrayKind::of_client_state(array) {
            Some(kind) => self.get_mut(kind).enabled = enabled,
            None => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }

    /// Whether a client-state array is enabled; `None` if `array` names none.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::VertexArrays};
    /// let arrays = VertexArrays::default();
    /// assert_eq!(arrays.is_enabled(GL_INDEX_ARRAY), Some(false));
    /// assert_eq!(arrays.is_enabled(GL_LIGHTING), None);
    /// ```
    pub fn is_enabled(&self, array: GLenum) -> Option<bool> {
        ArrayKind::of_client_state(array).map(|kind| self.get(kind).enabled)
    }

    /// The enabled arrays, with their kinds.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_enabled(GL_VERTEX_ARRAY, true)?;
    /// arrays.set_enabled(GL_COLOR_ARRAY, true)?;
    /// let kinds: Vec<ArrayKind> = arrays.enabled().map(|(kind, _)| kind).collect();
    /// assert_eq!(kinds, [ArrayKind::Vertex, ArrayKind::Color]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn enabled(&self) -> impl Iterator<Item = (ArrayKind, &ClientArray)> {
        ALL_KINDS
            .into_iter()
            .zip(&self.arrays)
            .filter(|(_, array)| array.enabled)
    }

    /// Where the bytes of elements `first..=last` of every enabled array in client memory
    /// are: what the C layer may read for a draw using those elements (arrays in buffer
    /// objects are the context's to read). A NULL pointer is GL's undefined behavior;
    /// fflight's documented choice is GL_INVALID_OPERATION (nothing is drawn).
    /// GL_INVALID_VALUE when the range does not fit the address space.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_pointer(ArrayKind::Vertex, 4, GL_FLOAT, 0, 0x1000)?;
    /// arrays.set_enabled(GL_VERTEX_ARRAY, true)?;
    /// let spans = arrays.spans(0, 9)?;
    /// assert_eq!(spans[ArrayKind::Vertex as usize].map(|s| s.len), Some(160));
    /// assert!(spans[ArrayKind::Normal as usize].is_none()); // not enabled
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn spans(&self, first: usize, last: usize) -> GlResult<[Option<ByteSpan>; ARRAY_KINDS]> {
        let mut spans = [None; ARRAY_KINDS];
        for (kind, array) in self.enabled() {
            spans[kind as usize] = array.client_span(first, last)?;
        }
        Ok(spans)
    }

    /// Texture unit `unit`'s texture coordinate array (§2.8: glClientActiveTexture selects
    /// which one glTexCoordPointer sets), whatever the client active unit.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_client_active_texture(GL_TEXTURE3)?;
    /// arrays.set_pointer(ArrayKind::TexCoord, 2, GL_SHORT, 0, 0x100)?;
    /// arrays.set_client_active_texture(GL_TEXTURE0)?;
    /// assert_eq!(arrays.unit_tex_coords(3).component_type, GL_SHORT);
    /// assert_eq!(arrays.unit_tex_coords(0).component_type, GL_FLOAT);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn unit_tex_coords(&self, unit: usize) -> &ClientArray {
        match unit {
            0 => &self.arrays[ArrayKind::TexCoord as usize],
            _ => &self.other_tex_coords[unit - 1],
        }
    }

    /// Texture units 1 and up's texture coordinate arrays, indexed by unit - 1; `None` for
    /// those that are not enabled.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::VertexArrays};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_client_active_texture(GL_TEXTURE2)?;
    /// arrays.set_enabled(GL_TEXTURE_COORD_ARRAY, true)?;
    /// let enabled = arrays.enabled_unit_arrays();
    /// assert!(enabled[1].is_some() && enabled[0].is_none());
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn enabled_unit_arrays(&self) -> [Option<&ClientArray>; MAX_TEXTURE_UNITS - 1] {
        std::array::from_fn(|k| Some(&self.other_tex_coords[k]).filter(|a| a.enabled))
    }

    /// `spans` for texture units 1 and up's enabled texture coordinate arrays (indexed by
    /// unit - 1), which draws read for capture.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_client_active_texture(GL_TEXTURE1)?;
    /// arrays.set_pointer(ArrayKind::TexCoord, 2, GL_FLOAT, 0, 0x1000)?;
    /// arrays.set_enabled(GL_TEXTURE_COORD_ARRAY, true)?;
    /// let spans = arrays.unit_spans(1, 2)?;
    /// assert_eq!(spans[0].map(|s| (s.address, s.len)), Some((0x1008, 16)));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn unit_spans(
        &self,
        first: usize,
        last: usize,
    ) -> GlResult<[Option<ByteSpan>; MAX_TEXTURE_UNITS - 1]> {
        let mut spans = [None; MAX_TEXTURE_UNITS - 1];
        for (span, array) in spans.iter_mut().zip(self.enabled_unit_arrays()) {
            if let Some(array) = array {
                *span = array.client_span(first, last)?;
            }
        }
        Ok(spans)
    }

    /// glInterleavedArrays (§2.8, table 2.5): sets and enables the arrays `format` packs,
    /// disables the others. In client memory a NULL `address` leaves every pointer NULL
    /// (rather than small offsets from NULL, which could only crash); in a buffer object it
    /// is offset 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::arrays::{ArrayKind, VertexArrays}};
    /// let mut arrays = VertexArrays::default();
    /// arrays.set_interleaved(GL_C4UB_V2F, 0, 0x100)?;
    /// let color = arrays.get(ArrayKind::Color);
    /// assert_eq!((color.enabled, color.size, color.component_type), (true, 4, GL_UNSIGNED_BYTE));
    /// assert_eq!(arrays.get(ArrayKind::Vertex).effective_stride(), 12);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set_interleaved(&mut self, format: GLenum, stride: i32, address: usize) -> GlResult {
        if stride < 0 {
            return Err(GlError::InvalidValue);
        }
        let layout = InterleavedLayout::of(format)?;
        let stride = if stride == 0 { layout.stride } else { stride };
        let in_buffer = self.array_buffer != 0;
        let at = |offset: usize| {
            if address == 0 && !in_buffer {
                0
            } else {
                address.wrapping_add(offset)
            }
        };
        for kind in [
            ArrayKind::EdgeFlag,
            ArrayKind::Index,
            ArrayKind::SecondaryColor,
            ArrayKind::FogCoord,
        ] {
            self.arrays[kind as usize].enabled = false;
        }
        let parts = [
            (ArrayKind::TexCoord, layout.tex_coord),
            (ArrayKind::Color, layout.color),
            (ArrayKind::Normal, layout.normal),
            (ArrayKind::Vertex, Some(layout.vertex)),
        ];
        let buffer = self.array_buffer;
        for (kind, part) in parts {
            let array = self.get_mut(kind);
            array.enabled = part.is_some();
            if let Some((size, component_type, offset)) = part {
                array.size = size;
                array.component_type = component_type;
                array.stride = stride;
                array.address = at(offset);
                array.buffer = buffer;
            }
        }
        Ok(())
    }
}

/// One row of table 2.5: each packed array as (size, type, byte offset), and the stride of
/// a tightly packed element.
struct InterleavedLayout {
    tex_coord: Option<(i32, GLenum, usize)>,
    color: Option<(i32, GLenum, usize)>,
    normal: Option<(i32, GLenum, usize)>,
    vertex: (i32, GLenum, usize),
    stride: i32,
}

impl InterleavedLayout {
    fn of(format: GLenum) -> GlResult<InterleavedLayout> {
        const F: usize = 4; // sizeof(GLfloat)
        let t = |size: i32| Some((size, GL_FLOAT, 0));
        let c4ub = |offset: usize| Some((4, GL_UNSIGNED_BYTE, offset));
        let cf = |size: i32, offset: usize| Some((size, GL_FLOAT, offset));
        let n = |offset: usize| Some((3, GL_FLOAT, offset));
        let v = |size: i32, offset: usize| (size, GL_FLOAT, offset);
        let (tex_coord, color, normal, vertex, stride) = match format {
            GL_V2F => (None, None, None, v(2, 0), 2 * F),
            GL_V3F => (None, None, None, v(3, 0), 3 * F),
            GL_C4UB_V2F => (None, c4ub(0), None, v(2, 4), 4 + 2 * F),
            GL_C4UB_V3F => (None, c4ub(0), None, v(3, 4), 4 + 3 * F),
            GL_C3F_V3F => (None, cf(3, 0), None, v(3, 3 * F), 6 * F),
            GL_N3F_V3F => (None, None, n(0), v(3, 3 * F), 6 * F),
            GL_C4F_N3F_V3F => (None, cf(4, 0), n(4 * F), v(3, 7 * F), 10 * F),
            GL_T2F_V3F => (t(2), None, None, v(3, 2 * F), 5 * F),
            GL_T4F_V4F => (t(4), None, None, v(4, 4 * F), 8 * F),
            GL_T2F_C4UB_V3F => (t(2), c4ub(2 * F), None, v(3, 4 + 2 * F), 4 + 5 * F),
            GL_T2F_C3F_V3F => (t(2), cf(3, 2 * F), None, v(3, 5 * F), 8 * F),
            GL_T2F_N3F_V3F => (t(2), None, n(2 * F), v(3, 5 * F), 8 * F),
            GL_T2F_C4F_N3F_V3F => (t(2), cf(4, 2 * F), n(6 * F), v(3, 9 * F), 12 * F),
            GL_T4F_C4F_N3F_V4F => (t(4), cf(4, 4 * F), n(8 * F), v(4, 11 * F), 15 * F),
            _ => return Err(GlError::InvalidEnum),
        };
        Ok(InterleavedLayout {
            tex_coord,
            color,
            normal,
            vertex,
            stride: stride as i32,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pointer_checks_follow_mesa_order() {
        let mut arrays = VertexArrays::default();
        assert_eq!(
            arrays.set_pointer(ArrayKind::Vertex, 5, GL_BYTE, -1, 8),
            Err(GlError::InvalidValue)
        );
        assert_eq!(
            arrays.set_pointer(ArrayKind::Vertex, 5, GL_BYTE, 0, 8),
            Err(GlError::InvalidEnum)
        );
        assert_eq!(
            arrays.set_pointer(ArrayKind::Vertex, 1, GL_FLOAT, 0, 8),
            Err(GlError::InvalidValue)
        );
        assert_eq!(arrays, VertexArrays::default());
    }

    #[test]
    fn interleaved_strides_match_table_2_5() {
        let expected = [
            (GL_V2F, 8),
            (GL_V3F, 12),
            (GL_C4UB_V2F, 12),
            (GL_C4UB_V3F, 16),
            (GL_C3F_V3F, 24),
            (GL_N3F_V3F, 24),
            (GL_C4F_N3F_V3F, 40),
            (GL_T2F_V3F, 20),
            (GL_T4F_V4F, 32),
            (GL_T2F_C4UB_V3F, 24),
            (GL_T2F_C3F_V3F, 32),
            (GL_T2F_N3F_V3F, 32),
            (GL_T2F_C4F_N3F_V3F, 48),
            (GL_T4F_C4F_N3F_V4F, 60),
        ];
        for (format, stride) in expected {
            let layout = InterleavedLayout::of(format).unwrap();
            assert_eq!(layout.stride, stride, "format {format:#x}");
            // The vertex is last: the element ends where the stride does.
            let (size, _, offset) = layout.vertex;
            assert_eq!(offset + 4 * size as usize, stride as usize, "{format:#x}");
        }
    }

    #[test]
    fn spans_cover_exactly_the_elements_used() {
        let mut arrays = VertexArrays::default();
        arrays
            .set_pointer(ArrayKind::Vertex, 3, GL_SHORT, 10, 1000)
            .unwrap();
        arrays.set_enabled(GL_VERTEX_ARRAY, true).unwrap();
        let spans = arrays.spans(2, 4).unwrap();
        assert_eq!(
            spans[0],
            Some(ByteSpan {
                address: 1020,
                len: 26
            })
        );
        assert!(spans[1..].iter().all(Option::is_none));
        arrays
            .set_pointer(ArrayKind::Vertex, 3, GL_SHORT, 10, 0)
            .unwrap();
        assert_eq!(arrays.spans(0, 0), Err(GlError::InvalidOperation));
        arrays
            .set_pointer(ArrayKind::Vertex, 3, GL_SHORT, 10, usize::MAX - 100)
            .unwrap();
        assert_eq!(arrays.spans(0, 1000), Err(GlError::InvalidValue));
    }
}
