//! Vertex arrays (§2.8) through the C entry points.
//!
//! The reference for every draw is the sequence of immediate-mode calls GL defines it as
//! (glBegin, then per index glEdgeFlagv, glTexCoord*v, glColor*v, glNormal*v, glVertex*v of
//! the enabled arrays, glEnd), made with the typed entry points of each component type.
//! Both draws are captured (fflCaptureBegin) and must give bit-identical vertices and the
//! same primitives: every type, size and stride (packed, unaligned, padded) of every array,
//! glDrawArrays, glDrawElements with each index type, glDrawRangeElements and glArrayElement
//! inside glBegin/glEnd, every primitive mode, lit (with color material) and unlit.
//!
//! Also: the 14 interleaved formats, queries, errors, NULL pointers, and reads bounded by the
//! elements the indices reference (arrays placed just before an inaccessible page).

#[path = "common/gl_api.rs"]
mod gl_api;

use std::ffi::c_void;

use fflight::commands::arrays::{ArraySources, ElementIndices};
use fflight::current::with_current;
use fflight::gl::*;
use fflight::state::arrays::ArrayKind;
use gl_api::*;

/// One array of test data: `count` elements of `size` components of `ty`, `stride` bytes
/// apart (the declared stride; 0 = packed), with garbage between elements.
#[derive(Clone, Debug)]
struct Array {
    kind: ArrayKind,
    ty: GLenum,
    size: i32,
    stride: i32,
    bytes: Vec<u8>,
}

fn type_size(ty: GLenum) -> usize {
    match ty {
        GL_BYTE | GL_UNSIGNED_BYTE => 1,
        GL_SHORT | GL_UNSIGNED_SHORT => 2,
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT => 4,
        GL_DOUBLE => 8,
        _ => unreachable!(),
    }
}

/// One random component of `ty`: the full range for integers (extremes included now and
/// then), [-2, 2) for floats (doubles with more precision than a float holds).
fn component(rng: &mut Rng, ty: GLenum) -> Vec<u8> {
    let extreme = rng.below(6) == 0;
    let pick = |rng: &mut Rng, lo: i64, hi: i64| -> i64 {
        if extreme {
            if rng.below(2) == 0 { lo } else { hi }
        } else {
            lo + (rng.next() % (hi - lo + 1) as u64) as i64
        }
    };
    match ty {
        GL_BYTE => (pick(rng, -128, 127) as i8).to_ne_bytes().to_vec(),
        GL_UNSIGNED_BYTE => (pick(rng, 0, 255) as u8).to_ne_bytes().to_vec(),
        GL_SHORT => (pick(rng, -32768, 32767) as i16).to_ne_bytes().to_vec(),
        GL_UNSIGNED_SHORT => (pick(rng, 0, 65535) as u16).to_ne_bytes().to_vec(),
        GL_INT => (pick(rng, i32::MIN as i64, i32::MAX as i64) as i32)
            .to_ne_bytes()
            .to_vec(),
        GL_UNSIGNED_INT => (pick(rng, 0, u32::MAX as i64) as u32)
            .to_ne_bytes()
            .to_vec(),
        GL_FLOAT => (rng.range(-2.0, 2.0) as f32).to_ne_bytes().to_vec(),
        GL_DOUBLE => rng.range(-2.0, 2.0).to_ne_bytes().to_vec(),
        _ => unreachable!(),
    }
}

impl Array {
    fn new(
        kind: ArrayKind,
        ty: GLenum,
        size: i32,
        stride: i32,
        count: usize,
        rng: &mut Rng,
    ) -> Array {
        let element = size as usize * type_size(ty);
        let step = if stride == 0 {
            element
        } else {
            stride as usize
        };
        let mut bytes = vec![0xA5; (count - 1) * step + element];
        for i in 0..count {
            let mut at = i * step;
            for _ in 0..size {
                let value = if kind == ArrayKind::EdgeFlag {
                    vec![[0u8, 1, 2][rng.below(3)]]
                } else {
                    component(rng, ty)
                };
                bytes[at..at + value.len()].copy_from_slice(&value);
                at += value.len();
            }
        }
        Array {
            kind,
            ty,
            size,
            stride,
            bytes,
        }
    }

    fn element_size(&self) -> usize {
        self.size as usize * type_size(self.ty)
    }

    fn step(&self) -> usize {
        if self.stride == 0 {
            self.element_size()
        } else {
            self.stride as usize
        }
    }

    /// Element `i`, copied to an 8-byte aligned buffer (the typed entry points take
    /// aligned pointers; the array itself may be unaligned).
    fn element(&self, i: usize) -> [u64; 4] {
        let mut buffer = [0u64; 4];
        let at = i * self.step();
        let bytes = &self.bytes[at..at + self.element_size()];
        for (k, b) in bytes.iter().enumerate() {
            buffer[k / 8] |= (*b as u64) << (8 * (k % 8));
        }
        if cfg!(target_endian = "big") {
            unimplemented!("the element copy assumes little endian");
        }
        buffer
    }

    /// Points the array's GL pointer at this data and enables it.
    fn bind(&self) {
        let ptr = self.bytes.as_ptr().cast::<c_void>();
        unsafe {
            match self.kind {
                ArrayKind::Vertex => glVertexPointer(self.size, self.ty, self.stride, ptr),
                ArrayKind::Normal => glNormalPointer(self.ty, self.stride, ptr),
                ArrayKind::Color => glColorPointer(self.size, self.ty, self.stride, ptr),
                ArrayKind::TexCoord => glTexCoordPointer(self.size, self.ty, self.stride, ptr),
                ArrayKind::EdgeFlag => glEdgeFlagPointer(self.stride, ptr),
                ArrayKind::SecondaryColor => {
                    glSecondaryColorPointer(self.size, self.ty, self.stride, ptr)
                }
                ArrayKind::FogCoord => glFogCoordPointer(self.ty, self.stride, ptr),
                ArrayKind::Index => glIndexPointer(self.ty, self.stride, ptr),
            }
            glEnableClientState(client_state(self.kind));
        }
    }

    /// The immediate-mode call for element `i`.
    fn immediate(&self, i: usize) {
        let buffer = self.element(i);
        let p = buffer.as_ptr().cast::<c_void>();
        macro_rules! call {
            ($($pattern:pat => $function:ident),* $(,)?) => {
                match (self.kind, self.size, self.ty) {
                    $($pattern => unsafe { $function(p.cast()) },)*
                    key => panic!("no immediate form for {key:?}"),
                }
            };
        }
        use ArrayKind::*;
        call!(
            (EdgeFlag, 1, GL_UNSIGNED_BYTE) => glEdgeFlagv,
            (SecondaryColor, 3, GL_BYTE) => glSecondaryColor3bv,
            (SecondaryColor, 3, GL_UNSIGNED_BYTE) => glSecondaryColor3ubv,
            (SecondaryColor, 3, GL_SHORT) => glSecondaryColor3sv,
            (SecondaryColor, 3, GL_UNSIGNED_SHORT) => glSecondaryColor3usv,
            (SecondaryColor, 3, GL_INT) => glSecondaryColor3iv,
            (SecondaryColor, 3, GL_UNSIGNED_INT) => glSecondaryColor3uiv,
            (SecondaryColor, 3, GL_FLOAT) => glSecondaryColor3fv,
            (SecondaryColor, 3, GL_DOUBLE) => glSecondaryColor3dv,
            (FogCoord, 1, GL_FLOAT) => glFogCoordfv,
            (FogCoord, 1, GL_DOUBLE) => glFogCoorddv,
            (Index, 1, GL_UNSIGNED_BYTE) => glIndexubv,
            (Index, 1, GL_SHORT) => glIndexsv,
            (Index, 1, GL_INT) => glIndexiv,
            (Index, 1, GL_FLOAT) => glIndexfv,
            (Index, 1, GL_DOUBLE) => glIndexdv,
            (Color, 3, GL_BYTE) => glColor3bv,
            (Color, 3, GL_UNSIGNED_BYTE) => glColor3ubv,
            (Color, 3, GL_SHORT) => glColor3sv,
            (Color, 3, GL_UNSIGNED_SHORT) => glColor3usv,
            (Color, 3, GL_INT) => glColor3iv,
            (Color, 3, GL_UNSIGNED_INT) => glColor3uiv,
            (Color, 3, GL_FLOAT) => glColor3fv,
            (Color, 3, GL_DOUBLE) => glColor3dv,
            (Color, 4, GL_BYTE) => glColor4bv,
            (Color, 4, GL_UNSIGNED_BYTE) => glColor4ubv,
            (Color, 4, GL_SHORT) => glColor4sv,
            (Color, 4, GL_UNSIGNED_SHORT) => glColor4usv,
            (Color, 4, GL_INT) => glColor4iv,
            (Color, 4, GL_UNSIGNED_INT) => glColor4uiv,
            (Color, 4, GL_FLOAT) => glColor4fv,
            (Color, 4, GL_DOUBLE) => glColor4dv,
            (Normal, 3, GL_BYTE) => glNormal3bv,
            (Normal, 3, GL_SHORT) => glNormal3sv,
            (Normal, 3, GL_INT) => glNormal3iv,
            (Normal, 3, GL_FLOAT) => glNormal3fv,
            (Normal, 3, GL_DOUBLE) => glNormal3dv,
            (TexCoord, 1, GL_SHORT) => glTexCoord1sv,
            (TexCoord, 1, GL_INT) => glTexCoord1iv,
            (TexCoord, 1, GL_FLOAT) => glTexCoord1fv,
            (TexCoord, 1, GL_DOUBLE) => glTexCoord1dv,
            (TexCoord, 2, GL_SHORT) => glTexCoord2sv,
            (TexCoord, 2, GL_INT) => glTexCoord2iv,
            (TexCoord, 2, GL_FLOAT) => glTexCoord2fv,
            (TexCoord, 2, GL_DOUBLE) => glTexCoord2dv,
            (TexCoord, 3, GL_SHORT) => glTexCoord3sv,
            (TexCoord, 3, GL_INT) => glTexCoord3iv,
            (TexCoord, 3, GL_FLOAT) => glTexCoord3fv,
            (TexCoord, 3, GL_DOUBLE) => glTexCoord3dv,
            (TexCoord, 4, GL_SHORT) => glTexCoord4sv,
            (TexCoord, 4, GL_INT) => glTexCoord4iv,
            (TexCoord, 4, GL_FLOAT) => glTexCoord4fv,
            (TexCoord, 4, GL_DOUBLE) => glTexCoord4dv,
            (Vertex, 2, GL_SHORT) => glVertex2sv,
            (Vertex, 2, GL_INT) => glVertex2iv,
            (Vertex, 2, GL_FLOAT) => glVertex2fv,
            (Vertex, 2, GL_DOUBLE) => glVertex2dv,
            (Vertex, 3, GL_SHORT) => glVertex3sv,
            (Vertex, 3, GL_INT) => glVertex3iv,
            (Vertex, 3, GL_FLOAT) => glVertex3fv,
            (Vertex, 3, GL_DOUBLE) => glVertex3dv,
            (Vertex, 4, GL_SHORT) => glVertex4sv,
            (Vertex, 4, GL_INT) => glVertex4iv,
            (Vertex, 4, GL_FLOAT) => glVertex4fv,
            (Vertex, 4, GL_DOUBLE) => glVertex4dv,
        )
    }
}

fn client_state(kind: ArrayKind) -> GLenum {
    match kind {
        ArrayKind::Vertex => GL_VERTEX_ARRAY,
        ArrayKind::Normal => GL_NORMAL_ARRAY,
        ArrayKind::Color => GL_COLOR_ARRAY,
        ArrayKind::TexCoord => GL_TEXTURE_COORD_ARRAY,
        ArrayKind::EdgeFlag => GL_EDGE_FLAG_ARRAY,
        ArrayKind::SecondaryColor => GL_SECONDARY_COLOR_ARRAY,
        ArrayKind::FogCoord => GL_FOG_COORD_ARRAY,
        ArrayKind::Index => GL_INDEX_ARRAY,
    }
}

/// Every client array (valgrind on this test found a freed secondary color array left
/// enabled, and read by the next draw, when this list had only the first five).
const ALL_STATES: [GLenum; 8] = [
    GL_VERTEX_ARRAY,
    GL_NORMAL_ARRAY,
    GL_COLOR_ARRAY,
    GL_TEXTURE_COORD_ARRAY,
    GL_EDGE_FLAG_ARRAY,
    GL_SECONDARY_COLOR_ARRAY,
    GL_FOG_COORD_ARRAY,
    GL_INDEX_ARRAY,
];

/// How a test draws.
#[derive(Clone, Copy, Debug)]
enum Draw {
    Arrays,
    Elements(GLenum),
    RangeElements(GLenum),
    ArrayElement,
}

/// Index bytes of `indices` as `ty`.
fn index_bytes(indices: &[usize], ty: GLenum) -> Vec<u8> {
    indices
        .iter()
        .flat_map(|&i| match ty {
            GL_UNSIGNED_BYTE => vec![i as u8],
            GL_UNSIGNED_SHORT => (i as u16).to_ne_bytes().to_vec(),
            _ => (i as u32).to_ne_bytes().to_vec(),
        })
        .collect()
}

/// Draws `indices` of `arrays` (which must include a vertex array) as `mode` both ways and
/// checks the captured results are identical; also that an array draw leaves the current
/// attributes alone.
fn check(what: &str, arrays: &[Array], mode: GLenum, draw: Draw, indices: &[usize]) {
    unsafe {
        for state in ALL_STATES {
            glDisableClientState(state);
        }
    }
    arrays.iter().for_each(Array::bind);
    reset_current();
    let current_before = current_attribs();

    unsafe { fflCaptureBegin() };
    match draw {
        Draw::Arrays => {
            assert!(indices.windows(2).all(|w| w[1] == w[0] + 1), "consecutive");
            unsafe { glDrawArrays(mode, indices[0] as GLint, indices.len() as GLsizei) }
        }
        Draw::Elements(ty) => {
            let bytes = index_bytes(indices, ty);
            unsafe { glDrawElements(mode, indices.len() as GLsizei, ty, bytes.as_ptr().cast()) }
        }
        Draw::RangeElements(ty) => {
            let bytes = index_bytes(indices, ty);
            let (lo, hi) = (indices.iter().min().unwrap(), indices.iter().max().unwrap());
            unsafe {
                glDrawRangeElements(
                    mode,
                    *lo as GLuint,
                    *hi as GLuint,
                    indices.len() as GLsizei,
                    ty,
                    bytes.as_ptr().cast(),
                )
            }
        }
        Draw::ArrayElement => unsafe {
            glBegin(mode);
            indices.iter().for_each(|&i| glArrayElement(i as GLint));
            glEnd();
        },
    }
    unsafe { fflCaptureEnd() };
    assert_eq!(error(), "GL_NO_ERROR", "{what}: array draw");
    let (array_vertices, array_primitives) = captured();
    if !matches!(draw, Draw::ArrayElement) {
        let current_after = current_attribs();
        assert_eq!(current_before, current_after, "{what}: current attributes");
    }

    reset_current();
    unsafe {
        fflCaptureBegin();
        glBegin(mode);
    }
    // §2.8's order of the commands glArrayElement stands for; the vertex last.
    let order = [
        ArrayKind::EdgeFlag,
        ArrayKind::TexCoord,
        ArrayKind::Color,
        ArrayKind::SecondaryColor,
        ArrayKind::Index,
        ArrayKind::Normal,
        ArrayKind::FogCoord,
        ArrayKind::Vertex,
    ];
    for &i in indices {
        for kind in order {
            if let Some(array) = arrays.iter().find(|a| a.kind == kind) {
                array.immediate(i);
            }
        }
    }
    unsafe {
        glEnd();
        fflCaptureEnd();
    }
    assert_eq!(error(), "GL_NO_ERROR", "{what}: immediate draw");
    let (immediate_vertices, immediate_primitives) = captured();

    assert_eq!(array_vertices.len(), indices.len(), "{what}");
    assert_same_vertices(what, &array_vertices, &immediate_vertices);
    assert_eq!(array_primitives, immediate_primitives, "{what}: primitives");
}

const COLOR_TYPES: [GLenum; 8] = [
    GL_BYTE,
    GL_UNSIGNED_BYTE,
    GL_SHORT,
    GL_UNSIGNED_SHORT,
    GL_INT,
    GL_UNSIGNED_INT,
    GL_FLOAT,
    GL_DOUBLE,
];

/// Every type, size and stride (packed, unaligned, padded) of array `kind`, with the other
/// arrays fixed (float vertices always, so that something is drawn).
fn every_format_of(kind: ArrayKind, lit: bool) {
    if lit {
        set_lit_state();
    }
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15 ^ kind as u64);
    let (types, sizes): (&[GLenum], &[i32]) = match kind {
        ArrayKind::Vertex => (&[GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE], &[2, 3, 4]),
        ArrayKind::Normal => (&[GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE], &[3]),
        ArrayKind::Color => (&COLOR_TYPES, &[3, 4]),
        ArrayKind::SecondaryColor => (&COLOR_TYPES, &[3]),
        ArrayKind::FogCoord => (&[GL_FLOAT, GL_DOUBLE], &[1]),
        ArrayKind::Index => (
            &[GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
            &[1],
        ),
        ArrayKind::TexCoord => (&[GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE], &[1, 2, 3, 4]),
        ArrayKind::EdgeFlag => (&[GL_UNSIGNED_BYTE], &[1]),
    };
    let draws = [
        Draw::Arrays,
        Draw::Elements(GL_UNSIGNED_BYTE),
        Draw::Elements(GL_UNSIGNED_SHORT),
        Draw::Elements(GL_UNSIGNED_INT),
        Draw::RangeElements(GL_UNSIGNED_SHORT),
        Draw::ArrayElement,
    ];
    let count = 7;
    let mut combination = 0;
    for &ty in types {
        for &size in sizes {
            let element = size * type_size(ty) as i32;
            for stride in [0, element + 1, element + 13] {
                let array = Array::new(kind, ty, size, stride, count, &mut rng);
                let mut arrays = vec![array];
                if kind != ArrayKind::Vertex {
                    arrays.push(Array::new(
                        ArrayKind::Vertex,
                        GL_FLOAT,
                        3,
                        0,
                        count,
                        &mut rng,
                    ));
                }
                if kind != ArrayKind::Normal {
                    arrays.push(Array::new(
                        ArrayKind::Normal,
                        GL_FLOAT,
                        3,
                        0,
                        count,
                        &mut rng,
                    ));
                }
                let draw = draws[combination % draws.len()];
                let mode = (combination % 10) as GLenum;
                let indices: Vec<usize> = match draw {
                    Draw::Arrays => (1..count).collect(),
                    _ => (0..9).map(|_| rng.below(count)).collect(),
                };
                let what =
                    format!("{kind:?} {ty:#x} size {size} stride {stride} {draw:?} mode {mode}");
                check(&what, &arrays, mode, draw, &indices);
                combination += 1;
            }
        }
    }
}

#[test]
fn vertex_arrays_of_every_format_equal_immediate_mode_lit() {
    for kind in [
        ArrayKind::Vertex,
        ArrayKind::Normal,
        ArrayKind::Color,
        ArrayKind::TexCoord,
        ArrayKind::EdgeFlag,
        ArrayKind::SecondaryColor,
        ArrayKind::FogCoord,
        ArrayKind::Index,
    ] {
        every_format_of(kind, true);
    }
}

#[test]
fn vertex_arrays_of_every_format_equal_immediate_mode_unlit() {
    for kind in [
        ArrayKind::Vertex,
        ArrayKind::Color,
        ArrayKind::TexCoord,
        ArrayKind::EdgeFlag,
        ArrayKind::SecondaryColor,
    ] {
        every_format_of(kind, false);
    }
}

#[test]
fn all_arrays_at_once_in_every_mode_and_draw() {
    set_lit_state();
    let mut rng = Rng(77);
    let count = 12;
    for mode in GL_POINTS..=GL_POLYGON {
        for (k, draw) in [
            Draw::Arrays,
            Draw::Elements(GL_UNSIGNED_BYTE),
            Draw::Elements(GL_UNSIGNED_INT),
            Draw::RangeElements(GL_UNSIGNED_BYTE),
            Draw::ArrayElement,
        ]
        .into_iter()
        .enumerate()
        {
            let arrays = [
                Array::new(
                    ArrayKind::Vertex,
                    [GL_FLOAT, GL_DOUBLE][k % 2],
                    4,
                    40,
                    count,
                    &mut rng,
                ),
                Array::new(ArrayKind::Normal, GL_SHORT, 3, 0, count, &mut rng),
                Array::new(ArrayKind::Color, GL_UNSIGNED_BYTE, 4, 5, count, &mut rng),
                Array::new(ArrayKind::TexCoord, GL_FLOAT, 2, 0, count, &mut rng),
                Array::new(ArrayKind::EdgeFlag, GL_UNSIGNED_BYTE, 1, 3, count, &mut rng),
            ];
            let indices: Vec<usize> = match draw {
                Draw::Arrays => (2..count).collect(),
                _ => (0..11).map(|_| rng.below(count)).collect(),
            };
            check(
                &format!("mode {mode} {draw:?}"),
                &arrays,
                mode,
                draw,
                &indices,
            );
        }
    }
}

/// Table 2.5: (format, [texture, color, normal, vertex] as (size, type, offset), stride).
type Part = Option<(i32, GLenum, usize)>;
const INTERLEAVED: [(GLenum, [Part; 4], usize); 14] = {
    const F: GLenum = GL_FLOAT;
    const UB: GLenum = GL_UNSIGNED_BYTE;
    [
        (GL_V2F, [None, None, None, Some((2, F, 0))], 8),
        (GL_V3F, [None, None, None, Some((3, F, 0))], 12),
        (
            GL_C4UB_V2F,
            [None, Some((4, UB, 0)), None, Some((2, F, 4))],
            12,
        ),
        (
            GL_C4UB_V3F,
            [None, Some((4, UB, 0)), None, Some((3, F, 4))],
            16,
        ),
        (
            GL_C3F_V3F,
            [None, Some((3, F, 0)), None, Some((3, F, 12))],
            24,
        ),
        (
            GL_N3F_V3F,
            [None, None, Some((3, F, 0)), Some((3, F, 12))],
            24,
        ),
        (
            GL_C4F_N3F_V3F,
            [None, Some((4, F, 0)), Some((3, F, 16)), Some((3, F, 28))],
            40,
        ),
        (
            GL_T2F_V3F,
            [Some((2, F, 0)), None, None, Some((3, F, 8))],
            20,
        ),
        (
            GL_T4F_V4F,
            [Some((4, F, 0)), None, None, Some((4, F, 16))],
            32,
        ),
        (
            GL_T2F_C4UB_V3F,
            [Some((2, F, 0)), Some((4, UB, 8)), None, Some((3, F, 12))],
            24,
        ),
        (
            GL_T2F_C3F_V3F,
            [Some((2, F, 0)), Some((3, F, 8)), None, Some((3, F, 20))],
            32,
        ),
        (
            GL_T2F_N3F_V3F,
            [Some((2, F, 0)), None, Some((3, F, 8)), Some((3, F, 20))],
            32,
        ),
        (
            GL_T2F_C4F_N3F_V3F,
            [
                Some((2, F, 0)),
                Some((4, F, 8)),
                Some((3, F, 24)),
                Some((3, F, 36)),
            ],
            48,
        ),
        (
            GL_T4F_C4F_N3F_V4F,
            [
                Some((4, F, 0)),
                Some((4, F, 16)),
                Some((3, F, 32)),
                Some((4, F, 44)),
            ],
            60,
        ),
    ]
};

#[test]
fn interleaved_arrays_set_table_2_5_and_draw_like_immediate_mode() {
    set_lit_state();
    let kinds = [
        ArrayKind::TexCoord,
        ArrayKind::Color,
        ArrayKind::Normal,
        ArrayKind::Vertex,
    ];
    let mut rng = Rng(5);
    let count = 6;
    for (format, parts, packed) in INTERLEAVED {
        for extra in [0, 12] {
            let stride = packed + extra;
            // Every part as its own array over one shared buffer, for the reference.
            let mut buffer = vec![0x5Au8; count * stride];
            for i in 0..count {
                for (size, ty, offset) in parts.iter().flatten() {
                    for c in 0..*size as usize {
                        let value = component(&mut rng, *ty);
                        let at = i * stride + offset + c * value.len();
                        buffer[at..at + value.len()].copy_from_slice(&value);
                    }
                }
            }
            // An edge flag array must be disabled by glInterleavedArrays.
            let flags = [0u8; 8];
            unsafe {
                glEdgeFlagPointer(0, flags.as_ptr().cast());
                glEnableClientState(GL_EDGE_FLAG_ARRAY);
                let declared = if extra == 0 { 0 } else { stride as GLsizei };
                glInterleavedArrays(format, declared, buffer.as_ptr().cast());
            }
            assert_eq!(error(), "GL_NO_ERROR");
            let what = format!("format {format:#x} stride {stride}");
            assert_eq!(
                unsafe { glIsEnabled(GL_EDGE_FLAG_ARRAY) },
                GL_FALSE,
                "{what}"
            );
            let queries = [
                (
                    GL_TEXTURE_COORD_ARRAY,
                    GL_TEXTURE_COORD_ARRAY_SIZE,
                    GL_TEXTURE_COORD_ARRAY_TYPE,
                    GL_TEXTURE_COORD_ARRAY_STRIDE,
                    GL_TEXTURE_COORD_ARRAY_POINTER,
                ),
                (
                    GL_COLOR_ARRAY,
                    GL_COLOR_ARRAY_SIZE,
                    GL_COLOR_ARRAY_TYPE,
                    GL_COLOR_ARRAY_STRIDE,
                    GL_COLOR_ARRAY_POINTER,
                ),
                (
                    GL_NORMAL_ARRAY,
                    0,
                    GL_NORMAL_ARRAY_TYPE,
                    GL_NORMAL_ARRAY_STRIDE,
                    GL_NORMAL_ARRAY_POINTER,
                ),
                (
                    GL_VERTEX_ARRAY,
                    GL_VERTEX_ARRAY_SIZE,
                    GL_VERTEX_ARRAY_TYPE,
                    GL_VERTEX_ARRAY_STRIDE,
                    GL_VERTEX_ARRAY_POINTER,
                ),
            ];
            let mut arrays = Vec::new();
            for ((part, kind), (state, size, ty, stride_name, pointer)) in
                parts.iter().zip(kinds).zip(queries)
            {
                assert_eq!(
                    unsafe { glIsEnabled(state) },
                    part.is_some() as GLboolean,
                    "{what} {kind:?}"
                );
                if let Some((part_size, part_type, offset)) = *part {
                    if size != 0 {
                        assert_eq!(get_int(size), part_size, "{what} {kind:?}");
                    }
                    assert_eq!(get_int(ty), part_type as GLint, "{what} {kind:?}");
                    assert_eq!(get_int(stride_name), stride as GLint, "{what} {kind:?}");
                    assert_eq!(
                        get_pointer(pointer),
                        buffer.as_ptr() as usize + offset,
                        "{what}"
                    );
                    arrays.push(Array {
                        kind,
                        ty: part_type,
                        size: part_size,
                        stride: stride as i32,
                        bytes: buffer[offset..].to_vec(),
                    });
                }
            }
            // The reference draws from separate arrays: same bytes, same layout.
            let mode = (format - GL_V2F) % 10;
            reset_current();
            unsafe {
                fflCaptureBegin();
                glDrawArrays(mode, 0, count as GLsizei);
                fflCaptureEnd();
            }
            let (interleaved, interleaved_primitives) = captured();
            check(
                &what,
                &arrays,
                mode,
                Draw::Arrays,
                &(0..count).collect::<Vec<_>>(),
            );
            let (separate, separate_primitives) = captured();
            assert_same_vertices(&what, &interleaved, &separate);
            assert_eq!(interleaved_primitives, separate_primitives, "{what}");
        }
    }
}

#[test]
fn array_state_queries_and_defaults() {
    let defaults = [
        (GL_VERTEX_ARRAY_SIZE, 4),
        (GL_VERTEX_ARRAY_TYPE, GL_FLOAT as GLint),
        (GL_VERTEX_ARRAY_STRIDE, 0),
        (GL_NORMAL_ARRAY_TYPE, GL_FLOAT as GLint),
        (GL_NORMAL_ARRAY_STRIDE, 0),
        (GL_COLOR_ARRAY_SIZE, 4),
        (GL_COLOR_ARRAY_TYPE, GL_FLOAT as GLint),
        (GL_COLOR_ARRAY_STRIDE, 0),
        (GL_TEXTURE_COORD_ARRAY_SIZE, 4),
        (GL_TEXTURE_COORD_ARRAY_TYPE, GL_FLOAT as GLint),
        (GL_TEXTURE_COORD_ARRAY_STRIDE, 0),
        (GL_EDGE_FLAG_ARRAY_STRIDE, 0),
    ];
    for (pname, value) in defaults {
        assert_eq!(get_int(pname), value, "{pname:#x}");
    }
    for state in ALL_STATES {
        assert_eq!(unsafe { glIsEnabled(state) }, GL_FALSE);
        unsafe { glEnableClientState(state) };
        assert_eq!(unsafe { glIsEnabled(state) }, GL_TRUE);
        let mut b = 7;
        unsafe { glGetBooleanv(state, &mut b) };
        assert_eq!(b, GL_TRUE, "{state:#x}");
        unsafe { glDisableClientState(state) };
        assert_eq!(get_int(state), 0, "{state:#x}");
        // Like Mesa, glEnable accepts the client-state arrays.
        unsafe { glEnable(state) };
        assert_eq!(unsafe { glIsEnabled(state) }, GL_TRUE);
        unsafe { glDisable(state) };
    }
    for pname in [
        GL_VERTEX_ARRAY_POINTER,
        GL_NORMAL_ARRAY_POINTER,
        GL_COLOR_ARRAY_POINTER,
        GL_TEXTURE_COORD_ARRAY_POINTER,
        GL_EDGE_FLAG_ARRAY_POINTER,
        GL_FEEDBACK_BUFFER_POINTER,
    ] {
        assert_eq!(get_pointer(pname), 0);
    }
    let data = [0.0f64; 64];
    let p = data.as_ptr().cast::<c_void>();
    unsafe {
        glVertexPointer(2, GL_DOUBLE, 24, p);
        glNormalPointer(GL_BYTE, 5, p.wrapping_byte_add(1));
        glColorPointer(3, GL_UNSIGNED_SHORT, 7, p.wrapping_byte_add(2));
        glTexCoordPointer(1, GL_SHORT, 9, p.wrapping_byte_add(3));
        glEdgeFlagPointer(11, p.wrapping_byte_add(4));
    }
    assert_eq!(error(), "GL_NO_ERROR");
    let set = [
        (GL_VERTEX_ARRAY_SIZE, 2),
        (GL_VERTEX_ARRAY_TYPE, GL_DOUBLE as GLint),
        (GL_VERTEX_ARRAY_STRIDE, 24),
        (GL_NORMAL_ARRAY_TYPE, GL_BYTE as GLint),
        (GL_NORMAL_ARRAY_STRIDE, 5),
        (GL_COLOR_ARRAY_SIZE, 3),
        (GL_COLOR_ARRAY_TYPE, GL_UNSIGNED_SHORT as GLint),
        (GL_COLOR_ARRAY_STRIDE, 7),
        (GL_TEXTURE_COORD_ARRAY_SIZE, 1),
        (GL_TEXTURE_COORD_ARRAY_TYPE, GL_SHORT as GLint),
        (GL_TEXTURE_COORD_ARRAY_STRIDE, 9),
        (GL_EDGE_FLAG_ARRAY_STRIDE, 11),
    ];
    for (pname, value) in set {
        assert_eq!(get_int(pname), value, "{pname:#x}");
    }
    for (k, pname) in [
        GL_VERTEX_ARRAY_POINTER,
        GL_NORMAL_ARRAY_POINTER,
        GL_COLOR_ARRAY_POINTER,
        GL_TEXTURE_COORD_ARRAY_POINTER,
        GL_EDGE_FLAG_ARRAY_POINTER,
    ]
    .into_iter()
    .enumerate()
    {
        assert_eq!(get_pointer(pname), p as usize + k);
    }
    let mut feedback = [0.0f32; 4];
    unsafe { glFeedbackBuffer(4, GL_2D, feedback.as_mut_ptr()) };
    assert_eq!(
        get_pointer(GL_FEEDBACK_BUFFER_POINTER),
        feedback.as_ptr() as usize
    );
    assert_eq!(error(), "GL_NO_ERROR");
}

/// A GL call to check the error of.
type Call<'a> = Box<dyn Fn() + 'a>;

#[test]
fn errors_follow_mesa_and_leave_the_state_alone() {
    let data = [1.0f32; 64];
    let p = data.as_ptr().cast::<c_void>();
    unsafe { glVertexPointer(3, GL_FLOAT, 16, p) };
    let cases: Vec<(&str, Call, &str)> = vec![
        (
            "vertex size 1",
            Box::new(|| unsafe { glVertexPointer(1, GL_FLOAT, 0, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "vertex size 5",
            Box::new(|| unsafe { glVertexPointer(5, GL_FLOAT, 0, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "vertex byte",
            Box::new(|| unsafe { glVertexPointer(3, GL_BYTE, 0, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "vertex ubyte",
            Box::new(|| unsafe { glVertexPointer(3, GL_UNSIGNED_BYTE, 0, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "vertex stride -1",
            Box::new(|| unsafe { glVertexPointer(3, GL_FLOAT, -1, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "stride before type",
            Box::new(|| unsafe { glVertexPointer(5, GL_BYTE, -1, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "type before size",
            Box::new(|| unsafe { glVertexPointer(5, GL_BYTE, 0, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "normal ubyte",
            Box::new(|| unsafe { glNormalPointer(GL_UNSIGNED_BYTE, 0, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "normal stride",
            Box::new(|| unsafe { glNormalPointer(GL_FLOAT, -4, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "color size 2",
            Box::new(|| unsafe { glColorPointer(2, GL_FLOAT, 0, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "color type",
            Box::new(|| unsafe { glColorPointer(4, 0x1234, 0, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "texcoord size 0",
            Box::new(|| unsafe { glTexCoordPointer(0, GL_FLOAT, 0, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "texcoord byte",
            Box::new(|| unsafe { glTexCoordPointer(2, GL_BYTE, 0, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "edge flag stride",
            Box::new(|| unsafe { glEdgeFlagPointer(-1, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "client state",
            Box::new(|| unsafe { glEnableClientState(GL_LIGHTING) }),
            "GL_INVALID_ENUM",
        ),
        (
            "client state off",
            Box::new(|| unsafe { glDisableClientState(0x1234) }),
            "GL_INVALID_ENUM",
        ),
        (
            "interleaved format",
            Box::new(|| unsafe { glInterleavedArrays(0x1234, 0, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "interleaved stride",
            Box::new(|| unsafe { glInterleavedArrays(0x1234, -1, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "draw mode",
            Box::new(|| unsafe { glDrawArrays(GL_POLYGON + 1, 0, 3) }),
            "GL_INVALID_ENUM",
        ),
        (
            "draw count",
            Box::new(|| unsafe { glDrawArrays(GL_POINTS, 0, -1) }),
            "GL_INVALID_VALUE",
        ),
        (
            "count before mode",
            Box::new(|| unsafe { glDrawArrays(99, 0, -1) }),
            "GL_INVALID_VALUE",
        ),
        (
            "draw first",
            Box::new(|| unsafe { glDrawArrays(GL_POINTS, -1, 3) }),
            "GL_INVALID_VALUE",
        ),
        (
            "elements type",
            Box::new(|| unsafe { glDrawElements(GL_POINTS, 3, GL_FLOAT, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "elements signed type",
            Box::new(|| unsafe { glDrawElements(GL_POINTS, 3, GL_INT, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "elements count",
            Box::new(|| unsafe { glDrawElements(GL_POINTS, -1, GL_UNSIGNED_INT, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "elements mode",
            Box::new(|| unsafe { glDrawElements(99, 3, GL_UNSIGNED_INT, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "range end < start",
            Box::new(|| unsafe { glDrawRangeElements(GL_POINTS, 5, 1, 3, GL_UNSIGNED_INT, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "range order",
            Box::new(|| unsafe { glDrawRangeElements(99, 5, 1, -1, GL_FLOAT, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "range count",
            Box::new(|| unsafe { glDrawRangeElements(GL_POINTS, 0, 1, -1, GL_FLOAT, p) }),
            "GL_INVALID_VALUE",
        ),
        (
            "range type",
            Box::new(|| unsafe { glDrawRangeElements(GL_POINTS, 0, 1, 3, GL_SHORT, p) }),
            "GL_INVALID_ENUM",
        ),
        (
            "array element -1",
            Box::new(|| unsafe { glArrayElement(-1) }),
            "GL_INVALID_VALUE",
        ),
        (
            "pointer name",
            Box::new(|| {
                get_pointer(GL_VERTEX_ARRAY_SIZE);
            }),
            "GL_INVALID_ENUM",
        ),
        (
            "pointer NULL",
            Box::new(|| unsafe { glGetPointerv(GL_VERTEX_ARRAY_POINTER, std::ptr::null_mut()) }),
            "GL_INVALID_VALUE",
        ),
    ];
    unsafe { glEnableClientState(GL_VERTEX_ARRAY) };
    let state = || with_current(|ctx| *ctx.vertex_arrays()).unwrap();
    let before = state();
    unsafe { fflCaptureBegin() };
    for (what, call, expected) in &cases {
        call();
        assert_eq!(error(), *expected, "{what}");
        assert_eq!(error(), "GL_NO_ERROR", "{what}: one error");
        assert_eq!(state(), before, "{what}: state unchanged");
    }
    unsafe { fflCaptureEnd() };
    assert_eq!(captured().0.len(), 0, "nothing was drawn");

    // Between glBegin and glEnd: draws and glGetPointerv are GL_INVALID_OPERATION (read
    // after glEnd: glGetError is not allowed inside) and the primitive being specified is
    // unharmed; glArrayElement and (as in Mesa) the pointer and client-state commands are
    // accepted.
    let indices = [0u8, 1, 2];
    let forbidden: [(&str, Call); 4] = [
        (
            "glDrawArrays",
            Box::new(|| unsafe { glDrawArrays(GL_POINTS, 0, 1) }),
        ),
        (
            "glDrawElements",
            Box::new(|| unsafe {
                glDrawElements(GL_POINTS, 1, GL_UNSIGNED_BYTE, indices.as_ptr().cast())
            }),
        ),
        (
            "glDrawRangeElements",
            Box::new(|| unsafe {
                glDrawRangeElements(
                    GL_POINTS,
                    0,
                    0,
                    1,
                    GL_UNSIGNED_BYTE,
                    indices.as_ptr().cast(),
                )
            }),
        ),
        (
            "glGetPointerv",
            Box::new(|| {
                get_pointer(GL_VERTEX_ARRAY_POINTER);
            }),
        ),
    ];
    for (what, call) in forbidden {
        unsafe {
            fflCaptureBegin();
            glBegin(GL_TRIANGLES);
            glArrayElement(0);
        }
        call();
        unsafe {
            glVertexPointer(3, GL_FLOAT, 0, p);
            glEnableClientState(GL_VERTEX_ARRAY);
            glArrayElement(1);
            glArrayElement(2);
            glEnd();
            fflCaptureEnd();
        }
        assert_eq!(
            error(),
            "GL_INVALID_OPERATION",
            "{what} inside glBegin/glEnd"
        );
        assert_eq!(error(), "GL_NO_ERROR");
        let (vertices, primitives) = captured();
        assert_eq!((vertices.len(), primitives.len()), (3, 1), "{what}");
    }
}

#[test]
fn null_pointers_draw_nothing_and_say_so() {
    let vertices = [0.0f32; 12];
    let indices = [0u8, 1, 2];
    let draw_all = || unsafe {
        glDrawArrays(GL_TRIANGLES, 0, 3);
        let arrays = error();
        glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, indices.as_ptr().cast());
        let elements = error();
        glDrawRangeElements(
            GL_TRIANGLES,
            0,
            2,
            3,
            GL_UNSIGNED_BYTE,
            indices.as_ptr().cast(),
        );
        let range = error();
        glArrayElement(0);
        [arrays, elements, range, error()]
    };
    unsafe { fflCaptureBegin() };
    // An enabled vertex array with a NULL pointer.
    unsafe {
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, std::ptr::null());
    }
    assert_eq!(draw_all(), ["GL_INVALID_OPERATION"; 4]);
    // A valid vertex array, an enabled color array with a NULL pointer.
    unsafe {
        glVertexPointer(3, GL_FLOAT, 0, vertices.as_ptr().cast());
        glEnableClientState(GL_COLOR_ARRAY);
        glColorPointer(4, GL_FLOAT, 0, std::ptr::null());
    }
    let color_before = current_attribs();
    assert_eq!(draw_all(), ["GL_INVALID_OPERATION"; 4]);
    assert_eq!(current_attribs(), color_before);
    // NULL indices: GL_INVALID_OPERATION when there are indices to read, nothing otherwise.
    unsafe {
        glDisableClientState(GL_COLOR_ARRAY);
        glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, std::ptr::null());
    }
    assert_eq!(error(), "GL_INVALID_OPERATION");
    unsafe { glDrawElements(GL_TRIANGLES, i32::MAX, GL_UNSIGNED_INT, std::ptr::null()) };
    assert_eq!(error(), "GL_INVALID_OPERATION");
    unsafe { glDrawElements(GL_TRIANGLES, 0, GL_UNSIGNED_BYTE, std::ptr::null()) };
    assert_eq!(error(), "GL_NO_ERROR");
    // glInterleavedArrays with NULL leaves every pointer NULL: draws are caught.
    unsafe { glInterleavedArrays(GL_T2F_C4F_N3F_V3F, 0, std::ptr::null()) };
    assert_eq!(get_pointer(GL_COLOR_ARRAY_POINTER), 0);
    assert_eq!(draw_all(), ["GL_INVALID_OPERATION"; 4]);
    // Without the vertex array nothing is read: NULL attribute arrays do not matter.
    unsafe { glDisableClientState(GL_VERTEX_ARRAY) };
    unsafe { glDrawArrays(GL_TRIANGLES, 0, i32::MAX) };
    assert_eq!(error(), "GL_NO_ERROR");
    unsafe { fflCaptureEnd() };
    assert_eq!(captured().0.len(), 0, "nothing was drawn");
}

/// `data` copied to the end of a readable mapping followed by an inaccessible page: reading
/// one byte past it faults.
struct Guarded {
    mapping: *mut u8,
    len: usize,
    data: *const u8,
}

impl Guarded {
    fn new(data: &[u8]) -> Guarded {
        let page = 4096;
        let readable = data.len().div_ceil(page) * page;
        let len = readable + page;
        unsafe {
            let mapping = libc::mmap(
                std::ptr::null_mut(),
                len,
                libc::PROT_READ | libc::PROT_WRITE,
                libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
                -1,
                0,
            );
            assert_ne!(mapping, libc::MAP_FAILED);
            let mapping = mapping.cast::<u8>();
            assert_eq!(
                libc::mprotect(mapping.add(readable).cast(), page, libc::PROT_NONE),
                0
            );
            let start = mapping.add(readable - data.len());
            std::ptr::copy_nonoverlapping(data.as_ptr(), start, data.len());
            Guarded {
                mapping,
                len,
                data: start,
            }
        }
    }

    fn ptr(&self) -> *const c_void {
        self.data.cast()
    }
}

impl Drop for Guarded {
    fn drop(&mut self) {
        unsafe { libc::munmap(self.mapping.cast(), self.len) };
    }
}

#[test]
fn draws_read_only_the_elements_their_indices_reference() {
    set_lit_state();
    let mut rng = Rng(11);
    // Four elements each, the last one ending right before an inaccessible page; strides
    // larger than the elements, so reading a whole stride after the last element faults.
    let vertex = Array::new(ArrayKind::Vertex, GL_FLOAT, 3, 20, 4, &mut rng);
    let color = Array::new(ArrayKind::Color, GL_UNSIGNED_BYTE, 4, 9, 4, &mut rng);
    let normal = Array::new(ArrayKind::Normal, GL_DOUBLE, 3, 0, 4, &mut rng);
    let guarded: Vec<Guarded> = [&vertex, &color, &normal]
        .iter()
        .map(|a| Guarded::new(&a.bytes))
        .collect();
    unsafe {
        glVertexPointer(3, GL_FLOAT, 20, guarded[0].ptr());
        glColorPointer(4, GL_UNSIGNED_BYTE, 9, guarded[1].ptr());
        glNormalPointer(GL_DOUBLE, 0, guarded[2].ptr());
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
    }
    // The last element alone.
    unsafe {
        fflCaptureBegin();
        glDrawArrays(GL_POINTS, 3, 1);
        glArrayElement(3);
        fflCaptureEnd();
    }
    assert_eq!(error(), "GL_NO_ERROR");
    assert_eq!(captured().0.len(), 1);

    // Many indices, all within the four elements: the vertex data read is four elements,
    // however many vertices are drawn (and glDrawRangeElements' range is not trusted,
    // neither too wide nor too narrow). Enough for the draws to run on two threads
    // (`MIN_VERTICES_PER_THREAD` each), few enough for memcheck (make test-valgrind-rust).
    let count = 3 * fflight::threads::MIN_VERTICES_PER_THREAD;
    let indices: Vec<u8> = (0..count).map(|_| rng.below(4) as u8).collect();
    let guarded_indices = Guarded::new(&indices);
    reset_current();
    unsafe {
        fflCaptureBegin();
        glDrawElements(
            GL_TRIANGLES,
            count as GLsizei,
            GL_UNSIGNED_BYTE,
            guarded_indices.ptr(),
        );
        glDrawRangeElements(
            GL_LINES,
            0,
            4_000_000_000,
            count as GLsizei,
            GL_UNSIGNED_BYTE,
            guarded_indices.ptr(),
        );
        glDrawRangeElements(
            GL_POINTS,
            1,
            1,
            count as GLsizei,
            GL_UNSIGNED_BYTE,
            guarded_indices.ptr(),
        );
        fflCaptureEnd();
    }
    assert_eq!(error(), "GL_NO_ERROR");
    let (vertices, primitives) = captured();
    assert_eq!(vertices.len(), 3 * count);
    assert_eq!(primitives.len(), count / 3 + count / 2 + count);
    // Each drawn vertex is the processed element its index names.
    unsafe {
        fflCaptureBegin();
        glDrawArrays(GL_POINTS, 0, 4);
        fflCaptureEnd();
    }
    let (elements, _) = captured();
    for (k, &index) in indices.iter().enumerate().step_by(997) {
        for draw in 0..3 {
            let v = &vertices[draw * count + k];
            assert!(
                same_vertex(v, &elements[index as usize]),
                "draw {draw} vertex {k}"
            );
        }
    }
}

/// The Rust API: sources must hold what the indices reference.
#[test]
fn rust_sources_must_hold_the_elements_drawn() {
    let mut ctx = fflight::Context::new();
    let data: Vec<u8> = [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .collect();
    ctx.vertex_pointer(3, GL_FLOAT, 0, 0).unwrap();
    ctx.client_state(GL_VERTEX_ARRAY, true).unwrap();
    ctx.capture_begin().unwrap();
    let sources = ArraySources::new(0).with(ArrayKind::Vertex, &data);
    let three = ElementIndices::Sequential { first: 0, count: 3 };
    ctx.draw_arrays_from(GL_TRIANGLES, &sources, &three)
        .unwrap();
    let four = ElementIndices::Sequential { first: 0, count: 4 };
    assert_eq!(
        ctx.draw_arrays_from(GL_TRIANGLES, &sources, &four),
        Err(fflight::GlError::InvalidOperation)
    );
    // Sources that start after the first element used.
    let late = ArraySources::new(1).with(ArrayKind::Vertex, &data[12..]);
    assert_eq!(
        ctx.draw_arrays_from(GL_POINTS, &late, &three),
        Err(fflight::GlError::InvalidOperation)
    );
    let from_one = ElementIndices::Sequential { first: 1, count: 2 };
    ctx.draw_arrays_from(GL_LINES, &late, &from_one).unwrap();
    // An enabled color array without bytes.
    ctx.client_state(GL_COLOR_ARRAY, true).unwrap();
    assert_eq!(
        ctx.draw_arrays_from(GL_TRIANGLES, &sources, &three),
        Err(fflight::GlError::InvalidOperation)
    );
    ctx.capture_end().unwrap();
    assert_eq!(ctx.captured().primitives().len(), 2);
    assert_eq!(ctx.captured().vertices()[3], ctx.captured().vertices()[1]);
}

#[test]
fn array_element_sets_the_current_attributes_and_color_material() {
    set_lit_state();
    let colors: [u8; 8] = [255, 0, 0, 255, 0, 128, 255, 64];
    let normals: [i16; 6] = [0, 0, 32767, -32768, 0, 0];
    unsafe {
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors.as_ptr().cast());
        glNormalPointer(GL_SHORT, 0, normals.as_ptr().cast());
        glEnableClientState(GL_COLOR_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
    }
    reset_current();
    let before = with_current(|ctx| {
        (
            ctx.get(GL_CURRENT_COLOR).unwrap(),
            ctx.get_material(GL_FRONT, GL_DIFFUSE).unwrap(),
        )
    })
    .unwrap();
    // Outside glBegin/glEnd (no vertex array): only the current attributes change.
    unsafe { glArrayElement(1) };
    let mut diffuse = [0.0f32; 4];
    unsafe { glGetMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse.as_mut_ptr()) };
    let expected = [0.0, 128.0 / 255.0, 1.0, 64.0 / 255.0];
    assert_eq!(
        diffuse, expected,
        "color material follows the array's color"
    );
    let mut color = [0.0f32; 4];
    unsafe { glGetFloatv(GL_CURRENT_COLOR, color.as_mut_ptr()) };
    assert_eq!(color, expected);
    let mut normal = [0.0f32; 3];
    unsafe { glGetFloatv(GL_CURRENT_NORMAL, normal.as_mut_ptr()) };
    assert_eq!(normal, [-1.0, 1.0 / 65535.0, 1.0 / 65535.0]);
    assert_eq!(error(), "GL_NO_ERROR");

    // A draw leaves the current attributes and the tracked material as they were.
    reset_current();
    let vertices = [0.0f32; 6];
    unsafe {
        glVertexPointer(3, GL_FLOAT, 0, vertices.as_ptr().cast());
        glEnableClientState(GL_VERTEX_ARRAY);
        glDrawArrays(GL_LINES, 0, 2);
    }
    let after = with_current(|ctx| {
        (
            ctx.get(GL_CURRENT_COLOR).unwrap(),
            ctx.get_material(GL_FRONT, GL_DIFFUSE).unwrap(),
        )
    })
    .unwrap();
    assert_eq!(before, after);
}

/// The range of listed indices (the smallest and largest, scanned before every glDrawElements
/// in the index's own type, vectorized) equals a plain scan for every index type, at every
/// alignment, for counts around the vector widths, with a partial index at the end ignored,
/// and with the extreme values of each type.
#[test]
fn listed_index_ranges_equal_a_plain_scan() {
    let mut rng = Rng(0x51);
    for (ty, size, max) in [
        (GL_UNSIGNED_BYTE, 1, u8::MAX as usize),
        (GL_UNSIGNED_SHORT, 2, u16::MAX as usize),
        (GL_UNSIGNED_INT, 4, u32::MAX as usize),
    ] {
        for count in (0..80).chain([255, 256, 257, 1000, 4099]) {
            for offset in 0..size {
                let indices: Vec<usize> = (0..count)
                    .map(|_| match rng.below(8) {
                        0 => 0,
                        1 => max,
                        _ => rng.below(max) + 1,
                    })
                    .collect();
                let mut bytes = vec![0xAB; offset];
                bytes.extend(index_bytes(&indices, ty));
                // A partial index at the end counts for nothing.
                bytes.extend(vec![0xFF; size - 1]);
                let listed = ElementIndices::Listed {
                    index_type: ty,
                    bytes: &bytes[offset..],
                };
                let expected = indices.iter().min().zip(indices.iter().max());
                let expected = expected.map(|(&lo, &hi)| (lo, hi));
                assert_eq!(
                    listed.range(),
                    expected,
                    "type {ty:#x}, count {count}, offset {offset}"
                );
            }
        }
    }
}
