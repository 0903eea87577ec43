//! Randomized robustness: GL's rule for bad input (§2.5: a command that raises an error has no
//! other effect) and fflight's own (never a crash, nothing lost), checked over long random
//! sequences of every command with valid and invalid arguments.
//!
//! - Through `fflight::Context` directly, so a panic fails the test (the C layer would catch
//!   it): a call whose arguments GL must reject returns `Err` (`Op::must_fail`, a conservative
//!   oracle); after every call that returns `Err`, everything the queries report (every glGet
//!   pname, every light and material parameter, clip planes, array pointers, the polygon
//!   stipple, the pixel maps, the whole of each matrix stack, capture and the feedback buffer, with the primitive in progress ended on a
//!   copy, and in selection mode the name stack, shown by a hit made on a copy, and the hit
//!   records) is what it was before; the error flag keeps the first error until read. Mode
//!   and name-stack commands (§5.2, §5.3) must end exactly as GL says (GL_STACK_OVERFLOW at
//!   depth 64, GL_STACK_UNDERFLOW, glLoadName on an empty stack, ignored outside selection
//!   mode), and hit records must be well formed (n, min z <= max z, n names of a stack the
//!   selection had; -1 exactly when the buffer overflowed). Fed-back, captured and bulk-lit
//!   colors stay in [0, 1] whatever the inputs (NaN and infinities included), and feedback
//!   streams parse. glPushAttrib, glPopAttrib and their client forms run with any mask, to
//!   overflow and underflow (the stack depths are among the queries).
//! - Through the C entry points: NULL pointers and wrong enums (glSelectBuffer with NULL or a
//!   negative size, name-stack errors; NULL for glFog*v, glPointParameter*v, glPolygonStipple,
//!   glPixelMap* and glGetPixelMap*, negative sizes for glScissor and glPixelMap, wrong enums
//!   for the per-fragment, fog, point and pixel commands), inside and outside glBegin/glEnd,
//!   set an error and change nothing; hit records written through glSelectBuffer's pointer are well formed.
//!
//! Each sequence has a fixed seed (printed on failure with the call that failed and the calls
//! before it), so a failure reproduces with `sequence(seed)`.

mod common;
#[path = "common/state_lists.rs"]
mod state_lists;

use std::ffi::c_void;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::ptr::{null, null_mut};

use common::*;
use fflight::commands::arrays::{ArraySources, ElementIndices};
use fflight::commands::attrib_stack::ENABLE_BIT_CAPABILITIES;
use fflight::commands::query::StateValue;
use fflight::current::with_current;
use fflight::lighting::{FaceColors, LitVertex};
use fflight::pipeline::vertex::ProcessedVertex;
use fflight::state::arrays::ArrayKind;
use fflight::state::pixel::StoreParam;
use fflight::{Context, GlError, GlResult};
use glam::{Vec3, Vec4};
use state_lists::*;

// ---- a small deterministic generator ----

/// splitmix64: the same seed gives the same sequence everywhere.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }

    fn one_in(&mut self, n: usize) -> bool {
        self.below(n) == 0
    }

    fn coin(&mut self) -> bool {
        self.next_u64() & 1 == 1
    }

    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }

    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }

    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }

    /// An enum argument: half the time one of `valid`, else a neighbor of one or any value.
    fn enumeration(&mut self, valid: &[GLenum]) -> GLenum {
        match self.below(4) {
            0 | 1 => self.pick(valid),
            2 => {
                let offset = self.pick(&[-3, -2, -1, 1, 2, 3]);
                self.pick(valid).wrapping_add_signed(offset)
            }
            _ => self.any_u32(),
        }
    }

    /// An enum argument the command must reject.
    fn invalid_enum(&mut self, valid: &[GLenum]) -> GLenum {
        loop {
            let value = self.enumeration(valid);
            if !valid.contains(&value) {
                return value;
            }
        }
    }

    fn any_u32(&mut self) -> u32 {
        match self.below(4) {
            0 => self.pick(&[0, 1, 0xFFFF, 0x7FFF_FFFF, 0x8000_0000, u32::MAX]),
            1 => self.below(0x10000) as u32,
            _ => self.next_u64() as u32,
        }
    }

    /// A float argument: mostly ordinary values, also GL's boundaries, huge and tiny ones,
    /// and NaN and infinities unless `finite`.
    fn float(&mut self, finite: bool) -> f32 {
        match self.below(20) {
            0..=7 => self.uniform(-2.0, 2.0) as f32,
            8 | 9 => self.uniform(0.0, 1.0) as f32,
            10 => self.pick(&[
                0.0, -0.0, 1.0, -1.0, 0.5, 90.0, 90.0001, 128.0, 128.0001, 179.9, 180.0,
            ]),
            11 => self.uniform(-200.0, 200.0) as f32,
            12 => self.range(-3, 200) as f32,
            13 => self.pick(&[1e20, -1e20, 1e38, -1e38, f32::MAX, -f32::MAX]),
            14 => self.pick(&[1e-30, -1e-30, f32::MIN_POSITIVE, 1e-45, -1e-45]),
            15..=17 if !finite => self.pick(&[f32::NAN, f32::INFINITY, f32::NEG_INFINITY]),
            _ => self.uniform(-10.0, 10.0) as f32,
        }
    }

    fn double(&mut self, finite: bool) -> f64 {
        match self.below(12) {
            0 => self.pick(&[1e300, -1e300, f64::MIN_POSITIVE, 5e-324]),
            _ => self.float(finite) as f64,
        }
    }

    /// A scalar parameter: a float, or sometimes an enum value as a float (light model).
    fn param(&mut self, finite: bool) -> f32 {
        if self.one_in(8) {
            let value = self.enumeration(&[GL_SINGLE_COLOR, GL_SEPARATE_SPECULAR_COLOR]);
            value as f32 + self.pick(&[0.0, 0.0, 0.5])
        } else {
            self.float(finite)
        }
    }

    /// Vector parameters, usually as many as the longest pname takes (4), sometimes fewer.
    fn params(&mut self, finite: bool) -> Vec<f32> {
        let len = if self.one_in(8) { self.below(4) } else { 4 };
        (0..len).map(|_| self.param(finite)).collect()
    }

    fn int(&mut self) -> i32 {
        match self.below(5) {
            0 => self.pick(&[
                i32::MIN,
                i32::MAX,
                0,
                -1,
                1,
                GL_SEPARATE_SPECULAR_COLOR as i32,
            ]),
            1 | 2 => self.range(-5, 200) as i32,
            _ => self.next_u64() as i32,
        }
    }

    fn ints(&mut self) -> Vec<i32> {
        let len = if self.one_in(8) { self.below(4) } else { 4 };
        (0..len).map(|_| self.int()).collect()
    }

    fn vec4(&mut self, finite: bool) -> Vec4 {
        Vec4::new(
            self.float(finite),
            self.float(finite),
            self.float(finite),
            self.float(finite),
        )
    }

    fn vec3(&mut self, finite: bool) -> Vec3 {
        Vec3::new(self.float(finite), self.float(finite), self.float(finite))
    }

    /// A vertex position: mostly in and around the view volume with w = 1.
    fn position(&mut self, finite: bool) -> Vec4 {
        if self.one_in(6) {
            return self.vec4(finite);
        }
        let mut c = || self.uniform(-3.0, 3.0) as f32;
        let (x, y, z) = (c(), c(), c());
        let w = if self.one_in(8) {
            self.pick(&[0.0, -1.0, 2.0, 1e-20])
        } else {
            1.0
        };
        Vec4::new(x, y, z, w)
    }

    /// A matrix: identity-like, affine, singular (zero or rank-one), or arbitrary values.
    fn matrix(&mut self, finite: bool) -> [f32; 16] {
        let mut m = [0.0; 16];
        match self.below(6) {
            0 => [0, 5, 10, 15].into_iter().for_each(|i| m[i] = 1.0),
            1 => {
                [0, 5, 10, 15].into_iter().for_each(|i| m[i] = 1.0);
                for v in &mut m[..15] {
                    *v += self.uniform(-0.5, 0.5) as f32;
                }
            }
            // A zero matrix, or one whose columns are all multiples of one column.
            2 => {
                if self.coin() {
                    let column: [f32; 4] = std::array::from_fn(|_| self.float(finite));
                    for (i, v) in m.iter_mut().enumerate() {
                        *v = column[i % 4] * (i / 4) as f32;
                    }
                }
            }
            _ => m.iter_mut().for_each(|v| *v = self.float(finite)),
        }
        m
    }

    fn address(&mut self) -> usize {
        match self.below(6) {
            0 => 0,
            1 => usize::MAX - self.below(64),
            2 => self.next_u64() as usize,
            _ => 0x1000 + 4 * self.below(1000),
        }
    }

    fn stride(&mut self) -> i32 {
        match self.below(8) {
            0 => self.pick(&[-1, -4, i32::MIN, i32::MAX]),
            1..=4 => 0,
            _ => self.range(1, 64) as i32,
        }
    }

    /// A count: mostly small, sometimes negative or huge.
    fn count(&mut self) -> i32 {
        match self.below(10) {
            0 => self.pick(&[-1, -100, i32::MIN, i32::MAX, 1 << 20]),
            1..=5 => self.range(0, 12) as i32,
            _ => self.range(0, 60) as i32,
        }
    }
}

// ---- the valid arguments of each command ----

const LIGHTS: [GLenum; 8] = [
    GL_LIGHT0, GL_LIGHT1, GL_LIGHT2, GL_LIGHT3, GL_LIGHT4, GL_LIGHT5, GL_LIGHT6, GL_LIGHT7,
];
const LIGHT_PNAMES: [GLenum; 10] = [
    GL_AMBIENT,
    GL_DIFFUSE,
    GL_SPECULAR,
    GL_POSITION,
    GL_SPOT_DIRECTION,
    GL_SPOT_EXPONENT,
    GL_SPOT_CUTOFF,
    GL_CONSTANT_ATTENUATION,
    GL_LINEAR_ATTENUATION,
    GL_QUADRATIC_ATTENUATION,
];
const FACES: [GLenum; 3] = [GL_FRONT, GL_BACK, GL_FRONT_AND_BACK];
const MATERIAL_PNAMES: [GLenum; 7] = [
    GL_AMBIENT,
    GL_DIFFUSE,
    GL_SPECULAR,
    GL_EMISSION,
    GL_SHININESS,
    GL_AMBIENT_AND_DIFFUSE,
    GL_COLOR_INDEXES,
];
/// What glGetMaterial accepts.
const MATERIAL_QUERIES: [GLenum; 6] = [
    GL_AMBIENT,
    GL_DIFFUSE,
    GL_SPECULAR,
    GL_EMISSION,
    GL_SHININESS,
    GL_COLOR_INDEXES,
];
const LIGHT_MODEL_PNAMES: [GLenum; 4] = [
    GL_LIGHT_MODEL_AMBIENT,
    GL_LIGHT_MODEL_LOCAL_VIEWER,
    GL_LIGHT_MODEL_TWO_SIDE,
    GL_LIGHT_MODEL_COLOR_CONTROL,
];
const COLOR_MATERIAL_MODES: [GLenum; 5] = [
    GL_AMBIENT,
    GL_DIFFUSE,
    GL_SPECULAR,
    GL_EMISSION,
    GL_AMBIENT_AND_DIFFUSE,
];
const CLIENT_ARRAYS: [GLenum; 8] = [
    GL_VERTEX_ARRAY,
    GL_NORMAL_ARRAY,
    GL_COLOR_ARRAY,
    GL_INDEX_ARRAY,
    GL_TEXTURE_COORD_ARRAY,
    GL_EDGE_FLAG_ARRAY,
    GL_SECONDARY_COLOR_ARRAY,
    GL_FOG_COORD_ARRAY,
];
/// Not capabilities: glEnable must reject these neighbors of real ones.
const NOT_CAPS: [GLenum; 3] = [
    GL_COLOR_MATERIAL_FACE,
    GL_LIGHT_MODEL_AMBIENT,
    GL_MAX_LIGHTS,
];

/// Every capability glEnable accepts (the attribute stack's list of them, and the client
/// arrays, which fflight accepts there as Mesa does), then `NOT_CAPS`.
fn caps() -> Vec<GLenum> {
    ENABLE_BIT_CAPABILITIES
        .iter()
        .chain(&CLIENT_ARRAYS)
        .chain(&NOT_CAPS)
        .copied()
        .collect()
}

/// The capabilities of `caps()`.
fn valid_caps() -> Vec<GLenum> {
    let caps = caps();
    caps[..caps.len() - NOT_CAPS.len()].to_vec()
}
const TEXTURE_UNITS: [GLenum; 8] = [
    GL_TEXTURE0,
    GL_TEXTURE1,
    GL_TEXTURE2,
    GL_TEXTURE3,
    GL_TEXTURE4,
    GL_TEXTURE5,
    GL_TEXTURE6,
    GL_TEXTURE7,
];
const TEX_GEN_COORDS: [GLenum; 4] = [GL_S, GL_T, GL_R, GL_Q];
const PIXEL_FORMATS: [GLenum; 6] = [
    GL_RGBA,
    GL_RGB,
    GL_LUMINANCE,
    GL_DEPTH_COMPONENT,
    GL_STENCIL_INDEX,
    GL_COLOR_INDEX,
];
const TEXTURE_TARGETS: [GLenum; 4] = [
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
];
const MAP1_TARGETS: [GLenum; 9] = [
    GL_MAP1_COLOR_4,
    GL_MAP1_INDEX,
    GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1,
    GL_MAP1_TEXTURE_COORD_2,
    GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4,
    GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,
];

/// Values a control point of a GL_MAP1_* target has (0: no such target).
fn map1_values_per_point(target: GLenum) -> usize {
    MAP1_TARGETS
        .iter()
        .position(|&t| t == target)
        .map_or(0, |kind| [4, 1, 3, 1, 2, 3, 4, 3, 4][kind])
}
const TEX_GEN_PNAMES: [GLenum; 3] = [GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE];
/// The modes every coordinate takes (sphere, normal and reflection maps are not q's).
const TEX_GEN_MODES: [GLenum; 2] = [GL_OBJECT_LINEAR, GL_EYE_LINEAR];
/// The glGet pnames of vertex processing, the older rasterization state and the buffer
/// bindings; `get_pnames` adds those of tests/common/state_lists.rs.
const GET_PNAMES: [GLenum; 110] = [
    GL_TRANSPOSE_COLOR_MATRIX,
    GL_COLOR_MATRIX,
    GL_COLOR_MATRIX_STACK_DEPTH,
    GL_MAX_COLOR_MATRIX_STACK_DEPTH,
    GL_MAX_EVAL_ORDER,
    GL_MAP1_GRID_DOMAIN,
    GL_MAP1_GRID_SEGMENTS,
    GL_MAP2_GRID_DOMAIN,
    GL_MAP2_GRID_SEGMENTS,
    GL_ACTIVE_TEXTURE,
    GL_CLIENT_ACTIVE_TEXTURE,
    GL_INDEX_ARRAY_TYPE,
    GL_INDEX_ARRAY_STRIDE,
    GL_INDEX_ARRAY_BUFFER_BINDING,
    GL_CURRENT_INDEX,
    GL_MAX_ATTRIB_STACK_DEPTH,
    GL_MAX_CLIENT_ATTRIB_STACK_DEPTH,
    GL_ATTRIB_STACK_DEPTH,
    GL_CLIENT_ATTRIB_STACK_DEPTH,
    GL_MAX_LIGHTS,
    GL_MAX_CLIP_PLANES,
    GL_MAX_VIEWPORT_DIMS,
    GL_MAX_MODELVIEW_STACK_DEPTH,
    GL_MAX_PROJECTION_STACK_DEPTH,
    GL_MAX_TEXTURE_STACK_DEPTH,
    GL_MAX_ELEMENTS_VERTICES,
    GL_MAX_ELEMENTS_INDICES,
    GL_CURRENT_COLOR,
    GL_CURRENT_NORMAL,
    GL_CURRENT_TEXTURE_COORDS,
    GL_CURRENT_RASTER_POSITION,
    GL_CURRENT_RASTER_POSITION_VALID,
    GL_CURRENT_RASTER_COLOR,
    GL_CURRENT_RASTER_SECONDARY_COLOR,
    GL_CURRENT_RASTER_TEXTURE_COORDS,
    GL_CURRENT_RASTER_DISTANCE,
    GL_EDGE_FLAG,
    GL_LIGHT_MODEL_AMBIENT,
    GL_LIGHT_MODEL_LOCAL_VIEWER,
    GL_LIGHT_MODEL_TWO_SIDE,
    GL_LIGHT_MODEL_COLOR_CONTROL,
    GL_COLOR_MATERIAL_FACE,
    GL_COLOR_MATERIAL_PARAMETER,
    GL_MATRIX_MODE,
    GL_MODELVIEW_MATRIX,
    GL_PROJECTION_MATRIX,
    GL_TEXTURE_MATRIX,
    GL_TRANSPOSE_MODELVIEW_MATRIX,
    GL_TRANSPOSE_PROJECTION_MATRIX,
    GL_TRANSPOSE_TEXTURE_MATRIX,
    GL_MODELVIEW_STACK_DEPTH,
    GL_PROJECTION_STACK_DEPTH,
    GL_TEXTURE_STACK_DEPTH,
    GL_VIEWPORT,
    GL_DEPTH_RANGE,
    GL_SHADE_MODEL,
    GL_FRONT_FACE,
    GL_CULL_FACE_MODE,
    GL_POLYGON_MODE,
    GL_POINT_SIZE,
    GL_LINE_WIDTH,
    GL_POINT_SIZE_RANGE,
    GL_LINE_WIDTH_RANGE,
    GL_COLOR_CLEAR_VALUE,
    GL_DEPTH_CLEAR_VALUE,
    GL_PERSPECTIVE_CORRECTION_HINT,
    GL_POINT_SMOOTH_HINT,
    GL_LINE_SMOOTH_HINT,
    GL_POLYGON_SMOOTH_HINT,
    GL_FOG_HINT,
    GL_RENDER_MODE,
    GL_FEEDBACK_BUFFER_SIZE,
    GL_FEEDBACK_BUFFER_TYPE,
    GL_SELECTION_BUFFER_SIZE,
    GL_NAME_STACK_DEPTH,
    GL_MAX_NAME_STACK_DEPTH,
    GL_VERTEX_ARRAY,
    GL_NORMAL_ARRAY,
    GL_COLOR_ARRAY,
    GL_INDEX_ARRAY,
    GL_TEXTURE_COORD_ARRAY,
    GL_EDGE_FLAG_ARRAY,
    GL_VERTEX_ARRAY_SIZE,
    GL_VERTEX_ARRAY_TYPE,
    GL_VERTEX_ARRAY_STRIDE,
    GL_NORMAL_ARRAY_TYPE,
    GL_NORMAL_ARRAY_STRIDE,
    GL_COLOR_ARRAY_SIZE,
    GL_COLOR_ARRAY_TYPE,
    GL_COLOR_ARRAY_STRIDE,
    GL_TEXTURE_COORD_ARRAY_SIZE,
    GL_TEXTURE_COORD_ARRAY_TYPE,
    GL_TEXTURE_COORD_ARRAY_STRIDE,
    GL_EDGE_FLAG_ARRAY_STRIDE,
    GL_ARRAY_BUFFER_BINDING,
    GL_ELEMENT_ARRAY_BUFFER_BINDING,
    GL_VERTEX_ARRAY_BUFFER_BINDING,
    GL_NORMAL_ARRAY_BUFFER_BINDING,
    GL_COLOR_ARRAY_BUFFER_BINDING,
    GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING,
    GL_EDGE_FLAG_ARRAY_BUFFER_BINDING,
    GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING,
    GL_FOG_COORD_ARRAY_BUFFER_BINDING,
    GL_SECONDARY_COLOR_ARRAY_SIZE,
    GL_SECONDARY_COLOR_ARRAY_TYPE,
    GL_SECONDARY_COLOR_ARRAY_STRIDE,
    GL_FOG_COORD_ARRAY_TYPE,
    GL_FOG_COORD_ARRAY_STRIDE,
    GL_CURRENT_SECONDARY_COLOR,
    GL_CURRENT_FOG_COORD,
];
const BUFFER_TARGETS: [GLenum; 2] = [GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER];
const BUFFER_USAGES: [GLenum; 9] = [
    GL_STREAM_DRAW,
    GL_STREAM_READ,
    GL_STREAM_COPY,
    GL_STATIC_DRAW,
    GL_STATIC_READ,
    GL_STATIC_COPY,
    GL_DYNAMIC_DRAW,
    GL_DYNAMIC_READ,
    GL_DYNAMIC_COPY,
];
const BUFFER_ACCESSES: [GLenum; 3] = [GL_READ_ONLY, GL_WRITE_ONLY, GL_READ_WRITE];
const BUFFER_PNAMES: [GLenum; 4] = [
    GL_BUFFER_SIZE,
    GL_BUFFER_USAGE,
    GL_BUFFER_ACCESS,
    GL_BUFFER_MAPPED,
];
/// The texture pnames of glGet (tables 6.15-6.20, 6.30).
const TEXTURE_PNAMES: [GLenum; 12] = [
    GL_TEXTURE_BINDING_1D,
    GL_TEXTURE_BINDING_2D,
    GL_TEXTURE_BINDING_3D,
    GL_TEXTURE_BINDING_CUBE_MAP,
    GL_ACTIVE_TEXTURE,
    GL_MAX_TEXTURE_UNITS,
    GL_MAX_TEXTURE_SIZE,
    GL_MAX_3D_TEXTURE_SIZE,
    GL_MAX_CUBE_MAP_TEXTURE_SIZE,
    GL_MAX_TEXTURE_LOD_BIAS,
    GL_NUM_COMPRESSED_TEXTURE_FORMATS,
    GL_COMPRESSED_TEXTURE_FORMATS,
];
/// Every glGet pname fflight answers, besides the capabilities.
fn get_pnames() -> Vec<GLenum> {
    GET_PNAMES
        .iter()
        .chain(&TEXTURE_PNAMES)
        .copied()
        .chain(state_pnames())
        .collect()
}
const MATRIX_MODES: [GLenum; 4] = [GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE, GL_COLOR];
const COMPARISON_FUNCS: [GLenum; 8] = [
    GL_NEVER,
    GL_LESS,
    GL_EQUAL,
    GL_LEQUAL,
    GL_GREATER,
    GL_NOTEQUAL,
    GL_GEQUAL,
    GL_ALWAYS,
];
const STENCIL_OPS: [GLenum; 8] = [
    GL_KEEP,
    GL_ZERO,
    GL_REPLACE,
    GL_INCR,
    GL_DECR,
    GL_INVERT,
    GL_INCR_WRAP,
    GL_DECR_WRAP,
];
const BLEND_FACTORS: [GLenum; 15] = [
    GL_ZERO,
    GL_ONE,
    GL_SRC_COLOR,
    GL_ONE_MINUS_SRC_COLOR,
    GL_DST_COLOR,
    GL_ONE_MINUS_DST_COLOR,
    GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA,
    GL_DST_ALPHA,
    GL_ONE_MINUS_DST_ALPHA,
    GL_CONSTANT_COLOR,
    GL_ONE_MINUS_CONSTANT_COLOR,
    GL_CONSTANT_ALPHA,
    GL_ONE_MINUS_CONSTANT_ALPHA,
    GL_SRC_ALPHA_SATURATE,
];
const BLEND_EQUATIONS: [GLenum; 5] = [
    GL_FUNC_ADD,
    GL_FUNC_SUBTRACT,
    GL_FUNC_REVERSE_SUBTRACT,
    GL_MIN,
    GL_MAX,
];
/// What glDrawBuffer and glReadBuffer accept without an error here (glReadBuffer takes no
/// GL_NONE or GL_FRONT_AND_BACK; the others name buffers fflight's framebuffer lacks).
const COLOR_BUFFERS: [GLenum; 5] = [GL_FRONT, GL_LEFT, GL_FRONT_LEFT, GL_NONE, GL_FRONT_AND_BACK];
const PRIMITIVES: [GLenum; 10] = [
    GL_POINTS,
    GL_LINES,
    GL_LINE_LOOP,
    GL_LINE_STRIP,
    GL_TRIANGLES,
    GL_TRIANGLE_STRIP,
    GL_TRIANGLE_FAN,
    GL_QUADS,
    GL_QUAD_STRIP,
    GL_POLYGON,
];
const RENDER_MODES: [GLenum; 3] = [GL_RENDER, GL_FEEDBACK, GL_SELECT];
const CLIP_PLANES: [GLenum; 6] = [
    GL_CLIP_PLANE0,
    GL_CLIP_PLANE1,
    GL_CLIP_PLANE2,
    GL_CLIP_PLANE3,
    GL_CLIP_PLANE4,
    GL_CLIP_PLANE5,
];
const SHADE_MODELS: [GLenum; 2] = [GL_FLAT, GL_SMOOTH];
const WINDINGS: [GLenum; 2] = [GL_CW, GL_CCW];
const POLYGON_MODES: [GLenum; 3] = [GL_POINT, GL_LINE, GL_FILL];
const HINT_TARGETS: [GLenum; 7] = [
    GL_PERSPECTIVE_CORRECTION_HINT,
    GL_POINT_SMOOTH_HINT,
    GL_LINE_SMOOTH_HINT,
    GL_POLYGON_SMOOTH_HINT,
    GL_FOG_HINT,
    GL_GENERATE_MIPMAP_HINT,
    GL_TEXTURE_COMPRESSION_HINT,
];
const HINT_MODES: [GLenum; 3] = [GL_DONT_CARE, GL_FASTEST, GL_NICEST];
const COMPONENT_TYPES: [GLenum; 8] = [
    GL_BYTE,
    GL_UNSIGNED_BYTE,
    GL_SHORT,
    GL_UNSIGNED_SHORT,
    GL_INT,
    GL_UNSIGNED_INT,
    GL_FLOAT,
    GL_DOUBLE,
];
const INDEX_TYPES: [GLenum; 3] = [GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT];
const INTERLEAVED_FORMATS: [GLenum; 14] = [
    GL_V2F,
    GL_V3F,
    GL_C4UB_V2F,
    GL_C4UB_V3F,
    GL_C3F_V3F,
    GL_N3F_V3F,
    GL_C4F_N3F_V3F,
    GL_T2F_V3F,
    GL_T4F_V4F,
    GL_T2F_C4UB_V3F,
    GL_T2F_C3F_V3F,
    GL_T2F_N3F_V3F,
    GL_T2F_C4F_N3F_V3F,
    GL_T4F_C4F_N3F_V4F,
];
const POINTER_PNAMES: [GLenum; 10] = [
    GL_INDEX_ARRAY_POINTER,
    GL_VERTEX_ARRAY_POINTER,
    GL_NORMAL_ARRAY_POINTER,
    GL_COLOR_ARRAY_POINTER,
    GL_TEXTURE_COORD_ARRAY_POINTER,
    GL_EDGE_FLAG_ARRAY_POINTER,
    GL_SECONDARY_COLOR_ARRAY_POINTER,
    GL_FOG_COORD_ARRAY_POINTER,
    GL_FEEDBACK_BUFFER_POINTER,
    GL_SELECTION_BUFFER_POINTER,
];
const STRING_NAMES: [GLenum; 4] = [GL_VENDOR, GL_RENDERER, GL_VERSION, GL_EXTENSIONS];
const ARRAY_KINDS: [ArrayKind; 8] = [
    ArrayKind::Vertex,
    ArrayKind::Normal,
    ArrayKind::Color,
    ArrayKind::TexCoord,
    ArrayKind::EdgeFlag,
    ArrayKind::SecondaryColor,
    ArrayKind::FogCoord,
    ArrayKind::Index,
];

// ---- the commands ----

/// The commands of the state that does not change vertex processing (fragment, fog, point,
/// pixel), with arguments valid or not.
#[derive(Clone, Debug)]
enum StateOp {
    DepthFunc(GLenum),
    StencilFunc(GLenum, i32, u32),
    StencilOp([GLenum; 3]),
    AlphaFunc(GLenum, f32),
    BlendFuncSeparate([GLenum; 4]),
    BlendEquation(GLenum),
    LogicOp(GLenum),
    Scissor([i32; 4]),
    Fog(GLenum, Vec<f32>),
    PointParameter(GLenum, Vec<f32>),
    PixelStore(GLenum, i32),
    PixelTransfer(GLenum, f32),
    PixelMap(GLenum, i32, Vec<f32>),
    PolygonStipple(Vec<u8>),
    DrawBuffer(GLenum),
    ReadBuffer(GLenum),
}

fn state_op(rng: &mut Rng, finite: bool) -> StateOp {
    let logic_ops: Vec<GLenum> = (GL_CLEAR..=GL_SET).collect();
    match rng.below(16) {
        0 => StateOp::DepthFunc(rng.enumeration(&COMPARISON_FUNCS)),
        1 => StateOp::StencilFunc(rng.enumeration(&COMPARISON_FUNCS), rng.int(), rng.any_u32()),
        2 => StateOp::StencilOp(std::array::from_fn(|_| rng.enumeration(&STENCIL_OPS))),
        3 => StateOp::AlphaFunc(rng.enumeration(&COMPARISON_FUNCS), rng.float(finite)),
        4 => StateOp::BlendFuncSeparate(std::array::from_fn(|_| rng.enumeration(&BLEND_FACTORS))),
        5 => StateOp::BlendEquation(rng.enumeration(&BLEND_EQUATIONS)),
        6 => StateOp::LogicOp(rng.enumeration(&logic_ops)),
        7 => StateOp::Scissor([rng.int(), rng.int(), rng.count(), rng.count()]),
        8 => {
            let pname = rng.enumeration(&FOG_PNAMES);
            let mut params = rng.params(finite);
            if pname == GL_FOG_MODE || pname == GL_FOG_COORD_SRC {
                let modes = [GL_LINEAR, GL_EXP, GL_EXP2, GL_FOG_COORD, GL_FRAGMENT_DEPTH];
                params
                    .iter_mut()
                    .for_each(|p| *p = rng.enumeration(&modes) as f32);
            }
            StateOp::Fog(pname, params)
        }
        9 => StateOp::PointParameter(rng.enumeration(&POINT_PNAMES), rng.params(finite)),
        10 => StateOp::PixelStore(
            rng.enumeration(&PIXEL_STORE_PNAMES),
            rng.pick(&[0, 1, 2, 3, 4, 8, 16, -1, 33]),
        ),
        11 => StateOp::PixelTransfer(rng.enumeration(&PIXEL_TRANSFER_PNAMES), rng.float(finite)),
        12 => {
            let size = rng.pick(&[-1, 0, 1, 2, 3, 4, 16, 256, 257]);
            let values = (0..rng.below(20)).map(|_| rng.float(finite)).collect();
            StateOp::PixelMap(rng.enumeration(&PIXEL_MAPS), size, values)
        }
        13 => {
            let length = rng.pick(&[0, 34, 128, 300]);
            StateOp::PolygonStipple((0..length).map(|_| rng.next_u64() as u8).collect())
        }
        14 => StateOp::DrawBuffer(rng.enumeration(&COLOR_BUFFERS)),
        _ => StateOp::ReadBuffer(rng.enumeration(&COLOR_BUFFERS)),
    }
}

impl StateOp {
    /// Whether GL must reject the call, from its arguments alone (conservatively for the
    /// stipple, whose length depends on the unpack modes: at least 35 bytes, 31 rows of one
    /// byte and four for the last).
    fn must_fail(&self) -> bool {
        let valid = |value: GLenum, set: &[GLenum]| set.contains(&value);
        let negative = |v: f32| v < 0.0 || v.is_nan();
        match *self {
            StateOp::DepthFunc(func)
            | StateOp::StencilFunc(func, ..)
            | StateOp::AlphaFunc(func, _) => !valid(func, &COMPARISON_FUNCS),
            StateOp::StencilOp(ops) => ops.iter().any(|&op| !valid(op, &STENCIL_OPS)),
            StateOp::BlendFuncSeparate([src, dst, src_alpha, dst_alpha]) => {
                // GL_SRC_ALPHA_SATURATE (the last) is for sources only.
                let destinations = &BLEND_FACTORS[..BLEND_FACTORS.len() - 1];
                !valid(src, &BLEND_FACTORS)
                    || !valid(src_alpha, &BLEND_FACTORS)
                    || !valid(dst, destinations)
                    || !valid(dst_alpha, destinations)
            }
            StateOp::BlendEquation(mode) => !valid(mode, &BLEND_EQUATIONS),
            StateOp::LogicOp(opcode) => !(GL_CLEAR..=GL_SET).contains(&opcode),
            StateOp::Scissor([_, _, width, height]) => width < 0 || height < 0,
            StateOp::Fog(pname, ref params) => {
                let count = if pname == GL_FOG_COLOR { 4 } else { 1 };
                let first = params.first().copied().unwrap_or(0.0);
                let as_enum = first as i32 as GLenum;
                !valid(pname, &FOG_PNAMES)
                    || params.len() < count
                    || (pname == GL_FOG_MODE && !valid(as_enum, &[GL_LINEAR, GL_EXP, GL_EXP2]))
                    || (pname == GL_FOG_COORD_SRC
                        && !valid(as_enum, &[GL_FOG_COORD, GL_FRAGMENT_DEPTH]))
                    || (pname == GL_FOG_DENSITY && negative(first))
            }
            StateOp::PointParameter(pname, ref params) => {
                let count = if pname == GL_POINT_DISTANCE_ATTENUATION {
                    3
                } else {
                    1
                };
                !valid(pname, &POINT_PNAMES)
                    || params.len() < count
                    || (count == 1 && negative(params[0]))
            }
            StateOp::PixelStore(pname, value) => {
                let alignment = matches!(pname, GL_PACK_ALIGNMENT | GL_UNPACK_ALIGNMENT);
                let boolean = matches!(
                    pname,
                    GL_PACK_SWAP_BYTES
                        | GL_UNPACK_SWAP_BYTES
                        | GL_PACK_LSB_FIRST
                        | GL_UNPACK_LSB_FIRST
                );
                !valid(pname, &PIXEL_STORE_PNAMES)
                    || (alignment && !matches!(value, 1 | 2 | 4 | 8))
                    || (!boolean && value < 0)
            }
            StateOp::PixelTransfer(pname, _) => !valid(pname, &PIXEL_TRANSFER_PNAMES),
            StateOp::PixelMap(map, size, ref values) => {
                let indexed_by_index = (GL_PIXEL_MAP_I_TO_I..=GL_PIXEL_MAP_I_TO_A).contains(&map);
                !(1..=256).contains(&size)
                    || (indexed_by_index && !(size as u32).is_power_of_two())
                    || !valid(map, &PIXEL_MAPS)
                    || values.len() < size as usize
            }
            StateOp::PolygonStipple(ref bytes) => bytes.len() < 35,
            StateOp::DrawBuffer(mode) => !valid(mode, &COLOR_BUFFERS),
            StateOp::ReadBuffer(mode) => !valid(mode, &COLOR_BUFFERS[..3]),
        }
    }

    fn apply(&self, ctx: &mut Context) -> GlResult {
        match *self {
            StateOp::DepthFunc(func) => ctx.depth_func(func),
            StateOp::StencilFunc(func, reference, mask) => ctx.stencil_func(func, reference, mask),
            StateOp::StencilOp([fail, depth_fail, depth_pass]) => {
                ctx.stencil_op(fail, depth_fail, depth_pass)
            }
            StateOp::AlphaFunc(func, reference) => ctx.alpha_func(func, reference),
            StateOp::BlendFuncSeparate([a, b, c, d]) => ctx.blend_func_separate(a, b, c, d),
            StateOp::BlendEquation(mode) => ctx.blend_equation(mode),
            StateOp::LogicOp(opcode) => ctx.logic_op(opcode),
            StateOp::Scissor([x, y, width, height]) => ctx.scissor(x, y, width, height),
            StateOp::Fog(pname, ref params) => ctx.fog(pname, params),
            StateOp::PointParameter(pname, ref params) => ctx.point_parameter(pname, params),
            StateOp::PixelStore(pname, value) => ctx.pixel_store(pname, StoreParam::Int(value)),
            StateOp::PixelTransfer(pname, value) => ctx.pixel_transfer(pname, value),
            StateOp::PixelMap(map, size, ref values) => ctx.pixel_map(map, size, values),
            StateOp::PolygonStipple(ref bytes) => ctx.polygon_stipple(bytes),
            StateOp::DrawBuffer(mode) => ctx.draw_buffer(mode),
            StateOp::ReadBuffer(mode) => ctx.read_buffer(mode),
        }
    }
}

/// Where the `ArraySources` of a Rust draw start: at the draw's lowest index, as the C layer
/// builds them, at element 0, or past the lowest index (a caller's mistake).
#[derive(Clone, Copy, Debug)]
enum Base {
    Lowest,
    Zero,
    Above(usize),
}

impl Base {
    fn random(rng: &mut Rng) -> Base {
        match rng.below(6) {
            0 => Base::Zero,
            1 => Base::Above(1 + rng.below(3)),
            _ => Base::Lowest,
        }
    }

    fn of(self, lowest: usize) -> usize {
        match self {
            Base::Lowest => lowest,
            Base::Zero => 0,
            Base::Above(k) => lowest.saturating_add(k),
        }
    }
}

/// One call of the Rust API, with its arguments (printed when a check fails).
#[derive(Clone, Debug)]
enum Op {
    Light {
        light: GLenum,
        pname: GLenum,
        params: Vec<f32>,
    },
    LightI {
        light: GLenum,
        pname: GLenum,
        params: Vec<i32>,
    },
    LightScalar {
        light: GLenum,
        pname: GLenum,
        param: f32,
    },
    Material {
        face: GLenum,
        pname: GLenum,
        params: Vec<f32>,
    },
    MaterialI {
        face: GLenum,
        pname: GLenum,
        params: Vec<i32>,
    },
    MaterialScalar {
        face: GLenum,
        pname: GLenum,
        param: f32,
    },
    LightModel {
        pname: GLenum,
        params: Vec<f32>,
    },
    LightModelI {
        pname: GLenum,
        params: Vec<i32>,
    },
    LightModelScalar {
        pname: GLenum,
        param: f32,
    },
    ColorMaterial {
        face: GLenum,
        mode: GLenum,
    },
    Capability {
        cap: GLenum,
        enabled: bool,
    },
    Color(Vec4),
    Normal(Vec3),
    TexCoord(Vec4),
    MultiTexCoord {
        target: GLenum,
        coords: Vec4,
    },
    TexGen {
        coord: GLenum,
        pname: GLenum,
        params: Vec<f32>,
    },
    ActiveTexture(GLenum),
    ClientActiveTexture(GLenum),
    Map1 {
        target: GLenum,
        domain: [f64; 2],
        stride: i32,
        order: i32,
        points: Vec<f32>,
    },
    MapGrid1 {
        segments: i32,
        domain: [f64; 2],
    },
    EvalCoord2([f64; 2]),
    TexImage2D {
        target: GLenum,
        level: i32,
        internal: i32,
        size: [i32; 2],
        format: GLenum,
        ty: GLenum,
        bytes: Vec<u8>,
    },
    BindTexture {
        target: GLenum,
        name: u32,
    },
    DeleteTexture(u32),
    DrawPixels {
        size: [i32; 2],
        format: GLenum,
        ty: GLenum,
    },
    ReadPixels {
        size: [i32; 2],
        format: GLenum,
        ty: GLenum,
        room: usize,
    },
    ColorTable {
        target: GLenum,
        internal: GLenum,
        width: i32,
        bytes: Vec<u8>,
    },
    EvalMesh1 {
        mode: GLenum,
        range: [i32; 2],
    },
    EdgeFlag(bool),
    MatrixMode(GLenum),
    LoadIdentity,
    LoadMatrix([f32; 16]),
    MultMatrix([f32; 16]),
    LoadTransposeMatrix([f32; 16]),
    MultTransposeMatrix([f32; 16]),
    Translate([f64; 3]),
    Scale([f64; 3]),
    Rotate([f64; 4]),
    Frustum([f64; 6]),
    Ortho([f64; 6]),
    PushMatrix,
    PopMatrix,
    PushAttrib(GLbitfield),
    PopAttrib,
    PushClientAttrib(GLbitfield),
    PopClientAttrib,
    Begin(GLenum),
    Vertex(Vec4),
    End,
    Rect([f32; 4]),
    FeedbackBuffer {
        size: i32,
        kind: GLenum,
        address: usize,
    },
    RenderMode(GLenum),
    SelectBuffer {
        size: i32,
        address: usize,
    },
    InitNames,
    PushName(u32),
    PopName,
    LoadName(u32),
    PassThrough(f32),
    Viewport([i32; 4]),
    DepthRange([f64; 2]),
    ClipPlane {
        plane: GLenum,
        equation: [f64; 4],
    },
    ShadeModel(GLenum),
    FrontFace(GLenum),
    CullFace(GLenum),
    PolygonMode {
        face: GLenum,
        mode: GLenum,
    },
    PointSize(f32),
    LineWidth(f32),
    Hint {
        target: GLenum,
        mode: GLenum,
    },
    ClearColor(Vec4),
    ClearDepth(f64),
    Clear(u32),
    /// A command of the state that does not change vertex processing.
    State(StateOp),
    Finish,
    Pointer {
        kind: ArrayKind,
        size: i32,
        component_type: GLenum,
        stride: i32,
        address: usize,
    },
    ClientState {
        array: GLenum,
        enabled: bool,
    },
    InterleavedArrays {
        format: GLenum,
        stride: i32,
        address: usize,
    },
    /// check_array_element, then array_element_from.
    ArrayElement {
        index: i32,
        base: Base,
    },
    /// check_draw_arrays, array_spans (as the C layer, when `spans`), draw_arrays_from.
    DrawArrays {
        mode: GLenum,
        first: i32,
        count: i32,
        base: Base,
        spans: bool,
    },
    /// check_draw_elements or check_draw_range_elements, then as DrawArrays.
    DrawElements {
        mode: GLenum,
        count: i32,
        index_type: GLenum,
        indices: Vec<u8>,
        range: Option<(u32, u32)>,
        base: Base,
        spans: bool,
    },
    /// draw_arrays_from alone, with indices no C call could make.
    DrawFrom {
        mode: GLenum,
        first: usize,
        count: usize,
        base: Base,
    },
    LightVertices {
        positions: Vec<Vec4>,
        normals: Option<Vec<Vec3>>,
        colors: Option<Vec<Vec4>>,
        out: usize,
    },
    CaptureBegin,
    CaptureEnd,
    Get(GLenum),
    GetLight {
        light: GLenum,
        pname: GLenum,
        ints: bool,
    },
    GetMaterial {
        face: GLenum,
        pname: GLenum,
        ints: bool,
    },
    GetClipPlane(GLenum),
    IsEnabled(GLenum),
    GetString(GLenum),
    GetPointer(GLenum),
    /// get_error: checked against the first error recorded since the last one.
    GetError,
    /// The buffer object commands (§2.9); `data` says whether glBufferData copies bytes.
    GenBuffers(i32),
    BindBuffer {
        target: GLenum,
        name: u32,
    },
    DeleteBuffers(Vec<u32>),
    BufferData {
        target: GLenum,
        size: isize,
        data: bool,
        usage: GLenum,
    },
    BufferSubData {
        target: GLenum,
        offset: isize,
        size: isize,
    },
    MapBuffer {
        target: GLenum,
        access: GLenum,
    },
    UnmapBuffer(GLenum),
    GetBufferParameter {
        target: GLenum,
        pname: GLenum,
    },
}

impl Op {
    /// Whether the call only reads state (or the error flag, which snapshots leave out).
    fn is_query(&self) -> bool {
        matches!(
            self,
            Op::Get(_)
                | Op::GetLight { .. }
                | Op::GetMaterial { .. }
                | Op::GetClipPlane(_)
                | Op::IsEnabled(_)
                | Op::GetString(_)
                | Op::GetPointer(_)
                | Op::GetError
                | Op::Finish
                | Op::GetBufferParameter { .. }
        )
    }

    /// Whether GL must reject the call (§2.5, §2.6.3, and each command's errors), judged
    /// from its arguments alone, conservatively: `inside` says whether it comes between
    /// glBegin and glEnd.
    fn must_fail(&self, inside: bool) -> bool {
        let valid = |value: GLenum, set: &[GLenum]| set.contains(&value);
        let short = |params: usize, count: usize| params < count;
        // The commands legal between glBegin and glEnd (§2.6.3), and the array pointer
        // commands, which fflight accepts there as Mesa does.
        let legal_inside = matches!(
            self,
            Op::Color(_)
                | Op::Normal(_)
                | Op::TexCoord(_)
                | Op::MultiTexCoord { .. }
                | Op::EvalCoord2(_)
                | Op::EdgeFlag(_)
                | Op::Vertex(_)
                | Op::Material { .. }
                | Op::MaterialI { .. }
                | Op::MaterialScalar { .. }
                | Op::ArrayElement { .. }
                | Op::End
                | Op::Pointer { .. }
                | Op::ClientState { .. }
                | Op::ClientActiveTexture(_)
                | Op::InterleavedArrays { .. }
                | Op::GetError
        );
        if inside && !legal_inside {
            return true;
        }
        match *self {
            Op::Light {
                light,
                pname,
                ref params,
            } => {
                !valid(light, &LIGHTS)
                    || !valid(pname, &LIGHT_PNAMES)
                    || short(params.len(), light_values(pname))
            }
            Op::LightI {
                light,
                pname,
                ref params,
            } => {
                !valid(light, &LIGHTS)
                    || !valid(pname, &LIGHT_PNAMES)
                    || short(params.len(), light_values(pname))
            }
            Op::LightScalar { light, pname, .. } => {
                !valid(light, &LIGHTS) || !valid(pname, &LIGHT_PNAMES) || light_values(pname) > 1
            }
            Op::Material {
                face,
                pname,
                ref params,
            } => {
                !valid(face, &FACES)
                    || !valid(pname, &MATERIAL_PNAMES)
                    || short(params.len(), material_values(pname))
            }
            Op::MaterialI {
                face,
                pname,
                ref params,
            } => {
                !valid(face, &FACES)
                    || !valid(pname, &MATERIAL_PNAMES)
                    || short(params.len(), material_values(pname))
            }
            Op::MaterialScalar { face, pname, .. } => !valid(face, &FACES) || pname != GL_SHININESS,
            Op::LightModel { pname, ref params } => {
                !valid(pname, &LIGHT_MODEL_PNAMES) || short(params.len(), light_model_values(pname))
            }
            Op::LightModelI { pname, ref params } => {
                !valid(pname, &LIGHT_MODEL_PNAMES) || short(params.len(), light_model_values(pname))
            }
            Op::LightModelScalar { pname, .. } => {
                !valid(pname, &LIGHT_MODEL_PNAMES) || pname == GL_LIGHT_MODEL_AMBIENT
            }
            Op::ColorMaterial { face, mode } => {
                !valid(face, &FACES) || !valid(mode, &COLOR_MATERIAL_MODES)
            }
            Op::Capability { cap, .. } | Op::IsEnabled(cap) => !valid(cap, &valid_caps()),
            Op::MatrixMode(mode) => !valid(mode, &MATRIX_MODES),
            Op::Map1 {
                target,
                domain,
                stride,
                order,
                ref points,
            } => {
                let k = map1_values_per_point(target);
                k == 0
                    || domain[0] == domain[1]
                    || !(1..=30).contains(&order)
                    || stride < k as i32
                    || short(
                        points.len(),
                        (order.max(1) - 1) as usize * stride.max(0) as usize + k,
                    )
            }
            Op::MapGrid1 { segments, .. } => segments <= 0,
            Op::TexImage2D {
                target,
                level,
                size,
                format,
                ..
            } => {
                !valid(target, &[GL_TEXTURE_2D, GL_PROXY_TEXTURE_2D])
                    || level < 0
                    || size.iter().any(|&s| s < 0)
                    || !valid(format, &PIXEL_FORMATS)
            }
            Op::BindTexture { target, .. } => !valid(target, &TEXTURE_TARGETS),
            Op::DrawPixels { size, format, .. } | Op::ReadPixels { size, format, .. } => {
                size.iter().any(|&s| s < 0) || !valid(format, &PIXEL_FORMATS)
            }
            Op::ColorTable { target, width, .. } => {
                !(GL_COLOR_TABLE..=GL_PROXY_POST_COLOR_MATRIX_COLOR_TABLE).contains(&target)
                    || width < 0
            }
            Op::EvalMesh1 { mode, .. } => !valid(mode, &[GL_POINT, GL_LINE]),
            Op::MultiTexCoord { target, .. }
            | Op::ActiveTexture(target)
            | Op::ClientActiveTexture(target) => !valid(target, &TEXTURE_UNITS),
            Op::TexGen {
                coord,
                pname,
                ref params,
            } => {
                let count = if pname == GL_TEXTURE_GEN_MODE { 1 } else { 4 };
                !valid(coord, &TEX_GEN_COORDS)
                    || !valid(pname, &TEX_GEN_PNAMES)
                    || short(params.len(), count)
                    || (pname == GL_TEXTURE_GEN_MODE && !valid(params[0] as GLenum, &TEX_GEN_MODES))
            }
            Op::Begin(mode) => !valid(mode, &PRIMITIVES),
            Op::End => !inside,
            Op::FeedbackBuffer {
                size,
                kind,
                address,
            } => size < 0 || !valid(kind, &FEEDBACK_TYPES) || (address == 0 && size > 0),
            Op::RenderMode(mode) => !valid(mode, &RENDER_MODES),
            Op::SelectBuffer { size, address } => size < 0 || (address == 0 && size > 0),
            Op::Viewport([_, _, w, h]) => w < 0 || h < 0,
            Op::ClipPlane { plane, .. } | Op::GetClipPlane(plane) => !valid(plane, &CLIP_PLANES),
            Op::ShadeModel(mode) => !valid(mode, &SHADE_MODELS),
            Op::FrontFace(mode) => !valid(mode, &WINDINGS),
            Op::CullFace(mode) => !valid(mode, &FACES),
            Op::PolygonMode { face, mode } => !valid(face, &FACES) || !valid(mode, &POLYGON_MODES),
            Op::PointSize(size) | Op::LineWidth(size) => size.is_nan() || size <= 0.0,
            Op::Hint { target, mode } => !valid(target, &HINT_TARGETS) || !valid(mode, &HINT_MODES),
            Op::Clear(mask) => {
                let buffers = GL_COLOR_BUFFER_BIT
                    | GL_DEPTH_BUFFER_BIT
                    | GL_STENCIL_BUFFER_BIT
                    | GL_ACCUM_BUFFER_BIT;
                mask & !buffers != 0
            }
            // Table 2.4; glNormalPointer has no size, glEdgeFlagPointer neither size nor type.
            Op::Pointer {
                kind,
                size,
                component_type,
                stride,
                ..
            } => {
                let coordinates = [GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE];
                stride < 0
                    || match kind {
                        ArrayKind::Vertex => {
                            !valid(component_type, &coordinates) || !(2..=4).contains(&size)
                        }
                        ArrayKind::TexCoord => {
                            !valid(component_type, &coordinates) || !(1..=4).contains(&size)
                        }
                        ArrayKind::Normal => !valid(
                            component_type,
                            &[GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
                        ),
                        ArrayKind::Color => {
                            !valid(component_type, &COMPONENT_TYPES) || !(3..=4).contains(&size)
                        }
                        ArrayKind::SecondaryColor => {
                            !valid(component_type, &COMPONENT_TYPES) || size != 3
                        }
                        ArrayKind::FogCoord => !valid(component_type, &[GL_FLOAT, GL_DOUBLE]),
                        ArrayKind::Index => !valid(
                            component_type,
                            &[GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
                        ),
                        ArrayKind::EdgeFlag => false,
                    }
            }
            Op::ClientState { array, .. } => !valid(array, &CLIENT_ARRAYS),
            Op::InterleavedArrays { format, stride, .. } => {
                stride < 0 || !valid(format, &INTERLEAVED_FORMATS)
            }
            Op::ArrayElement { index, .. } => index < 0,
            Op::DrawArrays {
                mode, first, count, ..
            } => !valid(mode, &PRIMITIVES) || first < 0 || count < 0,
            Op::DrawElements {
                mode,
                count,
                index_type,
                range,
                ..
            } => {
                !valid(mode, &PRIMITIVES)
                    || count < 0
                    || !valid(index_type, &INDEX_TYPES)
                    || range.is_some_and(|(start, end)| end < start)
            }
            Op::DrawFrom { mode, .. } => !valid(mode, &PRIMITIVES),
            Op::LightVertices {
                ref positions,
                ref normals,
                ref colors,
                out,
            } => {
                let n = positions.len();
                normals.as_ref().is_some_and(|v| v.len() < n)
                    || colors.as_ref().is_some_and(|v| v.len() < n)
                    || out < n
            }
            Op::Get(pname) => !valid(pname, &get_pnames()) && !valid(pname, &valid_caps()),
            Op::GetLight { light, pname, .. } => {
                !valid(light, &LIGHTS) || !valid(pname, &LIGHT_PNAMES)
            }
            Op::GetMaterial { face, pname, .. } => {
                !valid(face, &[GL_FRONT, GL_BACK]) || !valid(pname, &MATERIAL_QUERIES)
            }
            Op::GetString(name) => !valid(name, &STRING_NAMES),
            Op::GetPointer(pname) => !valid(pname, &POINTER_PNAMES),
            Op::GenBuffers(n) => n < 0,
            Op::BindBuffer { target, .. } | Op::UnmapBuffer(target) => {
                !valid(target, &BUFFER_TARGETS)
            }
            // With nothing bound these fail too (GL_INVALID_OPERATION).
            Op::BufferData {
                target,
                size,
                usage,
                ..
            } => !valid(target, &BUFFER_TARGETS) || size < 0 || !valid(usage, &BUFFER_USAGES),
            Op::BufferSubData {
                target,
                offset,
                size,
            } => !valid(target, &BUFFER_TARGETS) || offset < 0 || size < 0,
            Op::MapBuffer { target, access } => {
                !valid(target, &BUFFER_TARGETS) || !valid(access, &BUFFER_ACCESSES)
            }
            Op::GetBufferParameter { target, pname } => {
                !valid(target, &BUFFER_TARGETS) || !valid(pname, &BUFFER_PNAMES)
            }
            Op::State(ref command) => command.must_fail(),
            _ => false,
        }
    }
}

/// How many values a glLight pname takes (table 2.10).
fn light_values(pname: GLenum) -> usize {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => 4,
        GL_SPOT_DIRECTION => 3,
        _ => 1,
    }
}

/// How many values a glMaterial pname takes (table 2.11).
fn material_values(pname: GLenum) -> usize {
    match pname {
        GL_SHININESS => 1,
        GL_COLOR_INDEXES => 3,
        _ => 4,
    }
}

/// How many values a glLightModel pname takes.
fn light_model_values(pname: GLenum) -> usize {
    match pname {
        GL_LIGHT_MODEL_AMBIENT => 4,
        _ => 1,
    }
}

/// The bytes a sequence's vertex arrays read, one buffer per array.
struct ArrayBytes([Vec<u8>; 8]);

impl ArrayBytes {
    /// Random contents; with `finite`, every float or double read at any offset is finite.
    fn random(rng: &mut Rng, finite: bool) -> ArrayBytes {
        ArrayBytes(std::array::from_fn(|_| {
            let len = match rng.below(4) {
                0 => rng.below(16),
                1 => rng.below(512),
                _ => rng.below(4096),
            };
            let mut bytes: Vec<u8> = Vec::with_capacity(len + 4);
            while bytes.len() < len {
                if finite {
                    bytes.extend((rng.uniform(-2.0, 2.0) as f32).to_ne_bytes());
                } else {
                    bytes.extend(rng.next_u64().to_ne_bytes());
                }
            }
            bytes.truncate(len);
            if finite {
                // No byte can then be the exponent byte of an infinity or a NaN.
                bytes
                    .iter_mut()
                    .filter(|b| **b & 0x7F == 0x7F)
                    .for_each(|b| *b ^= 1);
            }
            bytes
        }))
    }

    fn sources(&self, base: usize) -> ArraySources<'_> {
        ARRAY_KINDS
            .iter()
            .zip(&self.0)
            .fold(ArraySources::new(base), |sources, (&kind, bytes)| {
                sources.with(kind, bytes)
            })
    }
}

/// A buffer object command: small names (so binds, deletes and draws meet), sizes and offsets
/// around a small store, now and then negative or huge.
fn buffer_op(rng: &mut Rng) -> Op {
    let target = rng.enumeration(&BUFFER_TARGETS);
    let size = |rng: &mut Rng| match rng.below(8) {
        0 => -(rng.below(3) as isize) - 1,
        1 => isize::MAX - rng.below(2) as isize,
        _ => rng.below(64) as isize,
    };
    match rng.below(8) {
        0 => Op::GenBuffers(rng.range(-1, 4) as i32),
        1 | 2 => Op::BindBuffer {
            target,
            name: rng.below(5) as u32,
        },
        3 => Op::DeleteBuffers((0..rng.below(3)).map(|_| rng.below(5) as u32).collect()),
        4 => Op::BufferData {
            target,
            size: size(rng),
            data: rng.coin(),
            usage: rng.enumeration(&BUFFER_USAGES),
        },
        5 => Op::BufferSubData {
            target,
            offset: size(rng),
            size: size(rng),
        },
        6 => Op::MapBuffer {
            target,
            access: rng.enumeration(&BUFFER_ACCESSES),
        },
        _ if rng.coin() => Op::UnmapBuffer(target),
        _ => Op::GetBufferParameter {
            target,
            pname: rng.enumeration(&BUFFER_PNAMES),
        },
    }
}

/// Any command, arguments half valid, half not.
fn any_op(rng: &mut Rng, finite: bool) -> Op {
    let f = finite;
    match rng.below(100) {
        0..=2 => Op::Light {
            light: rng.enumeration(&LIGHTS),
            pname: rng.enumeration(&LIGHT_PNAMES),
            params: rng.params(f),
        },
        3 => Op::LightI {
            light: rng.enumeration(&LIGHTS),
            pname: rng.enumeration(&LIGHT_PNAMES),
            params: rng.ints(),
        },
        4 => Op::LightScalar {
            light: rng.enumeration(&LIGHTS),
            pname: rng.enumeration(&LIGHT_PNAMES),
            param: rng.param(f),
        },
        5 | 6 => Op::Material {
            face: rng.enumeration(&FACES),
            pname: rng.enumeration(&MATERIAL_PNAMES),
            params: rng.params(f),
        },
        7 => Op::MaterialI {
            face: rng.enumeration(&FACES),
            pname: rng.enumeration(&MATERIAL_PNAMES),
            params: rng.ints(),
        },
        8 => Op::MaterialScalar {
            face: rng.enumeration(&FACES),
            pname: rng.enumeration(&MATERIAL_PNAMES),
            param: rng.param(f),
        },
        9 => Op::LightModel {
            pname: rng.enumeration(&LIGHT_MODEL_PNAMES),
            params: rng.params(f),
        },
        10 => Op::LightModelI {
            pname: rng.enumeration(&LIGHT_MODEL_PNAMES),
            params: rng.ints(),
        },
        11 => Op::LightModelScalar {
            pname: rng.enumeration(&LIGHT_MODEL_PNAMES),
            param: rng.param(f),
        },
        12 => Op::ColorMaterial {
            face: rng.enumeration(&FACES),
            mode: rng.enumeration(&COLOR_MATERIAL_MODES),
        },
        13..=15 => Op::Capability {
            cap: rng.enumeration(&caps()),
            enabled: !rng.one_in(3),
        },
        16 => Op::Color(rng.vec4(f)),
        17 => Op::Normal(rng.vec3(f)),
        18 => Op::TexCoord(rng.vec4(f)),
        19 => Op::EdgeFlag(rng.coin()),
        20 => Op::MatrixMode(rng.enumeration(&MATRIX_MODES)),
        21 => Op::LoadIdentity,
        22 => Op::LoadMatrix(rng.matrix(f)),
        23 => Op::MultMatrix(rng.matrix(f)),
        24 => Op::LoadTransposeMatrix(rng.matrix(f)),
        25 => Op::MultTransposeMatrix(rng.matrix(f)),
        26 => Op::Translate(std::array::from_fn(|_| rng.double(f))),
        27 => Op::Scale(std::array::from_fn(|_| rng.double(f))),
        28 => Op::Rotate(std::array::from_fn(|_| rng.double(f))),
        29 => Op::Frustum(std::array::from_fn(|_| rng.double(f))),
        30 => Op::Ortho(std::array::from_fn(|_| rng.double(f))),
        31 if rng.coin() => Op::PushMatrix,
        32 if rng.coin() => Op::PopMatrix,
        31 | 32 => attrib_op(rng),
        33..=37 => Op::Begin(rng.enumeration(&PRIMITIVES)),
        38 => Op::End,
        39 => Op::Rect(std::array::from_fn(|_| rng.float(f))),
        40 => Op::FeedbackBuffer {
            size: match rng.below(6) {
                0 => rng.pick(&[-1, i32::MIN, i32::MAX, 1 << 20]),
                1 => rng.below(16) as i32,
                _ => rng.below(3000) as i32,
            },
            kind: rng.enumeration(&FEEDBACK_TYPES),
            address: if rng.one_in(6) { 0 } else { 0x1000 },
        },
        41 | 42 => Op::RenderMode(rng.enumeration(&RENDER_MODES)),
        43 => Op::PassThrough(rng.float(f)),
        44 => Op::Viewport(std::array::from_fn(|_| match rng.below(4) {
            0 => rng.int(),
            _ => rng.range(-10, 300) as i32,
        })),
        45 => Op::DepthRange([rng.double(f), rng.double(f)]),
        46 => Op::ClipPlane {
            plane: rng.enumeration(&CLIP_PLANES),
            equation: std::array::from_fn(|_| rng.double(f)),
        },
        47 => Op::ShadeModel(rng.enumeration(&SHADE_MODELS)),
        48 => Op::FrontFace(rng.enumeration(&WINDINGS)),
        49 => Op::CullFace(rng.enumeration(&FACES)),
        50 => Op::PolygonMode {
            face: rng.enumeration(&FACES),
            mode: rng.enumeration(&POLYGON_MODES),
        },
        51 => Op::PointSize(rng.float(f)),
        52 => Op::LineWidth(rng.float(f)),
        53 => Op::Hint {
            target: rng.enumeration(&HINT_TARGETS),
            mode: rng.enumeration(&HINT_MODES),
        },
        54 => Op::ClearColor(rng.vec4(f)),
        55 => Op::ClearDepth(rng.double(f)),
        56 => Op::Clear(if rng.coin() {
            rng.pick(&[
                GL_COLOR_BUFFER_BIT,
                GL_DEPTH_BUFFER_BIT,
                GL_STENCIL_BUFFER_BIT,
            ])
        } else {
            rng.any_u32()
        }),
        57 => match rng.below(9) {
            5 => {
                let target = rng.enumeration(&MAP1_TARGETS);
                let count = rng.below(40);
                Op::Map1 {
                    target,
                    domain: [rng.double(f), rng.double(f)],
                    stride: rng.range(-1, 6) as i32,
                    order: rng.range(-1, 33) as i32,
                    points: (0..count).map(|_| rng.float(f)).collect(),
                }
            }
            6 => Op::MapGrid1 {
                segments: rng.range(-2, 20) as i32,
                domain: [rng.double(f), rng.double(f)],
            },
            7 => match rng.below(7) {
                0 => Op::EvalCoord2([rng.double(f), rng.double(f)]),
                1 => {
                    let bytes = rng.below(80);
                    Op::TexImage2D {
                        target: rng.enumeration(&[GL_TEXTURE_2D, GL_PROXY_TEXTURE_2D]),
                        level: rng.range(-1, 4) as i32,
                        internal: rng.pick(&[GL_RGBA, GL_RGB8, GL_LUMINANCE, 3, 0x1234]) as i32,
                        size: [rng.range(-1, 5) as i32, rng.range(-1, 5) as i32],
                        format: rng.enumeration(&PIXEL_FORMATS),
                        ty: rng.enumeration(&[GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_SHORT_5_6_5]),
                        bytes: (0..bytes).map(|_| rng.below(256) as u8).collect(),
                    }
                }
                2 => Op::BindTexture {
                    target: rng.enumeration(&TEXTURE_TARGETS),
                    name: rng.below(4) as u32,
                },
                3 => Op::DeleteTexture(rng.below(4) as u32),
                4 => Op::DrawPixels {
                    size: [rng.range(-1, 5) as i32, rng.range(-1, 5) as i32],
                    format: rng.enumeration(&PIXEL_FORMATS),
                    ty: rng.enumeration(&[GL_UNSIGNED_BYTE, GL_FLOAT, GL_BITMAP]),
                },
                5 => Op::ReadPixels {
                    size: [rng.range(-1, 5) as i32, rng.range(-1, 5) as i32],
                    format: rng.enumeration(&PIXEL_FORMATS),
                    ty: rng.enumeration(&[GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_INT_8_8_8_8]),
                    room: rng.below(200),
                },
                _ => {
                    let bytes = rng.below(40);
                    Op::ColorTable {
                        target: rng.enumeration(&[GL_COLOR_TABLE, GL_PROXY_COLOR_TABLE]),
                        internal: rng.pick(&[GL_RGBA, GL_LUMINANCE8, GL_DEPTH_COMPONENT]),
                        width: rng.range(-1, 9) as i32,
                        bytes: (0..bytes).map(|_| rng.below(256) as u8).collect(),
                    }
                }
            },
            8 => Op::EvalMesh1 {
                mode: rng.enumeration(&[GL_POINT, GL_LINE]),
                range: [rng.range(-3, 10) as i32, rng.range(-3, 10) as i32],
            },
            0 => Op::Finish,
            1 => Op::MultiTexCoord {
                target: rng.enumeration(&TEXTURE_UNITS),
                coords: rng.vec4(f),
            },
            2 => Op::TexGen {
                coord: rng.enumeration(&TEX_GEN_COORDS),
                pname: rng.enumeration(&TEX_GEN_PNAMES),
                params: if rng.coin() {
                    vec![rng.enumeration(&TEX_GEN_MODES) as f32]
                } else {
                    rng.params(f)
                },
            },
            3 => Op::ActiveTexture(rng.enumeration(&TEXTURE_UNITS)),
            _ => Op::ClientActiveTexture(rng.enumeration(&TEXTURE_UNITS)),
        },
        58 | 59 => Op::Pointer {
            kind: rng.pick(&ARRAY_KINDS),
            size: rng.range(-1, 5) as i32,
            component_type: rng.enumeration(&COMPONENT_TYPES),
            stride: rng.stride(),
            address: rng.address(),
        },
        60 => Op::ClientState {
            array: rng.enumeration(&CLIENT_ARRAYS),
            enabled: !rng.one_in(3),
        },
        61 => Op::InterleavedArrays {
            format: rng.enumeration(&INTERLEAVED_FORMATS),
            stride: rng.stride(),
            address: rng.address(),
        },
        62..=64 => Op::DrawArrays {
            mode: rng.enumeration(&PRIMITIVES),
            first: if rng.one_in(8) {
                rng.int()
            } else {
                rng.below(8) as i32
            },
            count: rng.count(),
            base: Base::random(rng),
            spans: rng.coin(),
        },
        65..=67 => draw_elements(rng),
        68 => Op::DrawFrom {
            mode: rng.enumeration(&PRIMITIVES),
            first: match rng.below(3) {
                0 => usize::MAX - rng.below(4),
                1 => rng.next_u64() as usize,
                _ => rng.below(8),
            },
            count: if rng.one_in(4) {
                usize::MAX - rng.below(4)
            } else {
                rng.below(8)
            },
            base: Base::random(rng),
        },
        69 => light_vertices(rng, f),
        70 => Op::CaptureBegin,
        71 => Op::CaptureEnd,
        72 => {
            let get_pnames = get_pnames();
            let pnames: &[GLenum] = if rng.coin() { &get_pnames } else { &caps() };
            Op::Get(rng.enumeration(pnames))
        }
        73 => Op::GetLight {
            light: rng.enumeration(&LIGHTS),
            pname: rng.enumeration(&LIGHT_PNAMES),
            ints: rng.coin(),
        },
        74 => Op::GetMaterial {
            face: rng.enumeration(&FACES),
            pname: rng.enumeration(&MATERIAL_PNAMES),
            ints: rng.coin(),
        },
        75 => match rng.below(4) {
            0 => Op::GetClipPlane(rng.enumeration(&CLIP_PLANES)),
            1 => Op::IsEnabled(rng.enumeration(&caps())),
            2 => Op::GetString(rng.enumeration(&STRING_NAMES)),
            _ => Op::GetPointer(rng.enumeration(&POINTER_PNAMES)),
        },
        76..=79 => Op::GetError,
        80 => select_buffer(rng),
        81 => Op::RenderMode(GL_SELECT),
        88..=91 => buffer_op(rng),
        92..=99 => Op::State(state_op(rng, finite)),
        _ => name_op(rng),
    }
}

/// glSelectBuffer: sizes negative, zero, small (overflow likely), large; sometimes NULL.
/// glPushAttrib, glPopAttrib and their client forms: one bit, every bit, or any mask (bits
/// naming no group are ignored); the stacks overflow and underflow.
fn attrib_op(rng: &mut Rng) -> Op {
    let mask = match rng.below(3) {
        0 => 1 << rng.below(32),
        1 => GL_ALL_ATTRIB_BITS,
        _ => rng.any_u32(),
    };
    match rng.below(4) {
        0 => Op::PushAttrib(mask),
        1 => Op::PopAttrib,
        2 => Op::PushClientAttrib(mask),
        _ => Op::PopClientAttrib,
    }
}

fn select_buffer(rng: &mut Rng) -> Op {
    Op::SelectBuffer {
        size: match rng.below(6) {
            0 => rng.pick(&[-1, -64, i32::MIN, 0, i32::MAX]),
            1 | 2 => rng.below(12) as i32,
            _ => rng.below(400) as i32,
        },
        address: if rng.one_in(6) { 0 } else { 0x3000 },
    }
}

/// A name-stack command: names include 0 and the largest.
fn name_op(rng: &mut Rng) -> Op {
    let name = if rng.one_in(4) {
        rng.pick(&[0, u32::MAX])
    } else {
        rng.below(1000) as u32
    };
    match rng.below(8) {
        0 => Op::InitNames,
        1..=3 => Op::PushName(name),
        4 | 5 => Op::PopName,
        _ => Op::LoadName(name),
    }
}

fn draw_elements(rng: &mut Rng) -> Op {
    let index_type = rng.enumeration(&INDEX_TYPES);
    let count = rng.count();
    let values = count.clamp(0, 80) as usize + rng.below(2);
    let mut indices = Vec::new();
    for _ in 0..values {
        let index: u32 = if rng.one_in(16) {
            rng.pick(&[255, 65535, u32::MAX])
        } else {
            rng.below(24) as u32
        };
        match index_type {
            GL_UNSIGNED_BYTE => indices.push(index as u8),
            GL_UNSIGNED_SHORT => indices.extend((index as u16).to_ne_bytes()),
            _ => indices.extend(index.to_ne_bytes()),
        }
    }
    // A Rust caller may hand over fewer bytes than count indices, or a partial index.
    if rng.one_in(6) {
        indices.truncate(rng.below(indices.len() + 1));
    }
    Op::DrawElements {
        mode: rng.enumeration(&PRIMITIVES),
        count,
        index_type,
        indices,
        range: rng.coin().then(|| (rng.any_u32() % 32, rng.any_u32() % 64)),
        base: Base::random(rng),
        spans: rng.coin(),
    }
}

fn light_vertices(rng: &mut Rng, finite: bool) -> Op {
    let count = rng.below(12);
    let len = |rng: &mut Rng| {
        if rng.one_in(6) {
            rng.below(count + 2)
        } else {
            count
        }
    };
    let positions = (0..count).map(|_| rng.position(finite)).collect();
    let normals = rng.coin().then(|| {
        let n = len(rng);
        (0..n).map(|_| rng.vec3(finite)).collect()
    });
    let colors = rng.coin().then(|| {
        let n = len(rng);
        (0..n).map(|_| rng.vec4(finite)).collect()
    });
    let out = len(rng);
    Op::LightVertices {
        positions,
        normals,
        colors,
        out,
    }
}

/// The next command: between glBegin and glEnd mostly vertices and what may come between
/// them, sometimes anything (GL_INVALID_OPERATION for most).
fn next_op(rng: &mut Rng, inside_begin_end: bool, selecting: bool, finite: bool) -> Op {
    if !inside_begin_end {
        // In selection mode, enough name-stack commands to fill the stack now and then, and
        // rectangles that hit under identity matrices.
        if selecting && rng.one_in(3) {
            return match rng.below(8) {
                0..=3 => Op::PushName(rng.below(1000) as u32),
                4 | 5 => name_op(rng),
                _ => Op::Rect(std::array::from_fn(|_| rng.uniform(-1.5, 1.5) as f32)),
            };
        }
        return any_op(rng, finite);
    }
    match rng.below(100) {
        0..=39 => Op::Vertex(rng.position(finite)),
        40..=49 => Op::Color(rng.vec4(finite)),
        50..=54 => Op::Normal(rng.vec3(finite)),
        55..=57 => Op::TexCoord(rng.vec4(finite)),
        58 | 59 => Op::EdgeFlag(rng.coin()),
        60..=63 => Op::Material {
            face: rng.enumeration(&FACES),
            pname: rng.enumeration(&MATERIAL_PNAMES),
            params: rng.params(finite),
        },
        64..=67 => Op::ArrayElement {
            index: if rng.one_in(8) {
                rng.int()
            } else {
                rng.below(16) as i32
            },
            base: Base::random(rng),
        },
        68..=75 => Op::End,
        76 => name_op(rng),
        _ => any_op(rng, finite),
    }
}

// ---- running a command ----

/// The first problem found: a message for the failure report.
type Check = Result<(), String>;

fn unit<T>(result: GlResult<T>) -> GlResult {
    result.map(|_| ())
}

/// A color each of whose components is in [0, 1] (NaN is not).
fn clamped(color: Vec4) -> bool {
    color.to_array().iter().all(|c| (0.0..=1.0).contains(c))
}

/// Runs `op`. Invariants of a successful call (feedback streams, lit colors) are checked here;
/// the unchanged state of a failed one by the caller.
/// `names_seen`: every name stack the selection in progress has had (hit records hold one).
fn apply(
    ctx: &mut Context,
    op: &Op,
    arrays: &ArrayBytes,
    names_seen: &[Vec<u32>],
    stats: &mut Stats,
) -> (GlResult, Check) {
    let mut check = Ok(());
    let result = match op {
        Op::Light {
            light,
            pname,
            params,
        } => ctx.light(*light, *pname, params),
        Op::LightI {
            light,
            pname,
            params,
        } => ctx.light_i(*light, *pname, params),
        Op::LightScalar {
            light,
            pname,
            param,
        } => ctx.light_scalar(*light, *pname, *param),
        Op::Material {
            face,
            pname,
            params,
        } => ctx.material(*face, *pname, params),
        Op::MaterialI {
            face,
            pname,
            params,
        } => ctx.material_i(*face, *pname, params),
        Op::MaterialScalar { face, pname, param } => ctx.material_scalar(*face, *pname, *param),
        Op::LightModel { pname, params } => ctx.light_model(*pname, params),
        Op::LightModelI { pname, params } => ctx.light_model_i(*pname, params),
        Op::LightModelScalar { pname, param } => ctx.light_model_scalar(*pname, *param),
        Op::ColorMaterial { face, mode } => ctx.color_material(*face, *mode),
        Op::Capability { cap, enabled } => ctx.set_capability(*cap, *enabled),
        Op::Color(c) => {
            ctx.color(*c);
            Ok(())
        }
        Op::Normal(n) => {
            ctx.normal(*n);
            Ok(())
        }
        Op::TexCoord(t) => {
            ctx.tex_coord(*t);
            Ok(())
        }
        Op::MultiTexCoord { target, coords } => ctx.multi_tex_coord(*target, *coords),
        Op::TexGen {
            coord,
            pname,
            params,
        } => ctx.tex_gen(*coord, *pname, params),
        Op::ActiveTexture(texture) => ctx.active_texture(*texture),
        Op::Map1 {
            target,
            domain,
            stride,
            order,
            points,
        } => ctx.map(
            *target,
            1,
            [domain[0], domain[1], 0.0, 1.0],
            [*stride, 0],
            [*order, 1],
            points,
        ),
        Op::MapGrid1 { segments, domain } => {
            ctx.map_grid(1, [*segments, 1], [domain[0], domain[1], 0.0, 1.0])
        }
        Op::EvalCoord2([u, v]) => {
            ctx.eval_coord(2, *u, *v);
            Ok(())
        }
        Op::TexImage2D {
            target,
            level,
            internal,
            size,
            format,
            ty,
            bytes,
        } => {
            let args = fflight::commands::texture::TexImageArgs {
                target: *target,
                level: *level,
                internal_format: *internal,
                size: [size[0], size[1], 1],
                border: 0,
                format: *format,
                ty: *ty,
            };
            // Only as many bytes as the image takes, or none (a NULL pointer).
            let span = ctx.tex_image_span(2, &args);
            ctx.tex_image(2, &args, if bytes.len() >= span { bytes } else { &[] })
        }
        Op::BindTexture { target, name } => ctx.bind_texture(*target, *name),
        Op::DeleteTexture(name) => ctx.delete_textures(1, &[*name]),
        Op::DrawPixels { size, format, ty } => ctx.draw_pixels(size[0], size[1], *format, *ty),
        Op::ReadPixels {
            size,
            format,
            ty,
            room,
        } => {
            let mut out = vec![0xA5u8; *room + 16];
            // `room` bytes, then a guard zone that must stay as it is.
            let result = ctx.read_pixels(*size, *format, *ty, &mut out[..*room]);
            if out[*room..].iter().any(|&b| b != 0xA5) {
                check = Err("glReadPixels wrote past its buffer".into());
            }
            result
        }
        Op::ColorTable {
            target,
            internal,
            width,
            bytes,
        } => ctx.color_table(*target, *internal, *width, GL_RGBA, GL_UNSIGNED_BYTE, bytes),
        Op::EvalMesh1 { mode, range } => ctx.eval_mesh1(*mode, range[0], range[1]),
        Op::ClientActiveTexture(texture) => ctx.client_active_texture(*texture),
        Op::EdgeFlag(e) => {
            ctx.edge_flag(*e);
            Ok(())
        }
        Op::MatrixMode(mode) => ctx.matrix_mode(*mode),
        Op::LoadIdentity => ctx.load_identity(),
        Op::LoadMatrix(m) => ctx.load_matrix(m),
        Op::MultMatrix(m) => ctx.mult_matrix(m),
        Op::LoadTransposeMatrix(m) => ctx.load_transpose_matrix(m),
        Op::MultTransposeMatrix(m) => ctx.mult_transpose_matrix(m),
        Op::Translate([x, y, z]) => ctx.translate(*x, *y, *z),
        Op::Scale([x, y, z]) => ctx.scale(*x, *y, *z),
        Op::Rotate([a, x, y, z]) => ctx.rotate(*a, *x, *y, *z),
        Op::Frustum([l, r, b, t, n, f]) => ctx.frustum(*l, *r, *b, *t, *n, *f),
        Op::Ortho([l, r, b, t, n, f]) => ctx.ortho(*l, *r, *b, *t, *n, *f),
        Op::PushMatrix => ctx.push_matrix(),
        Op::PopMatrix => ctx.pop_matrix(),
        Op::PushAttrib(mask) => ctx.push_attrib(*mask),
        Op::PopAttrib => ctx.pop_attrib(),
        Op::PushClientAttrib(mask) => ctx.push_client_attrib(*mask),
        Op::PopClientAttrib => ctx.pop_client_attrib(),
        Op::Begin(mode) => ctx.begin(*mode),
        Op::Vertex(v) => {
            ctx.vertex(*v);
            Ok(())
        }
        Op::End => ctx.end(),
        Op::Rect([x1, y1, x2, y2]) => ctx.rect(*x1, *y1, *x2, *y2),
        Op::FeedbackBuffer {
            size,
            kind,
            address,
        } => ctx.feedback_buffer(*size, *kind, *address),
        Op::RenderMode(mode) => {
            let int = |ctx: &Context, pname| ctx.get(pname).map(|v| v.as_ints()[0]);
            let left = int(ctx, GL_RENDER_MODE).map(|m| m as GLenum);
            let layout = int(ctx, GL_FEEDBACK_BUFFER_TYPE).map(|t| t as GLenum);
            let capacity = int(ctx, GL_FEEDBACK_BUFFER_SIZE);
            let select_capacity = int(ctx, GL_SELECTION_BUFFER_SIZE);
            ctx.render_mode(*mode).map(|(count, finished)| {
                check = match (left, finished) {
                    (Ok(GL_SELECT), Some(finished)) => {
                        stats.selections += 1;
                        stats.hits += count.max(0) as usize;
                        stats.overflows += (count == -1) as usize;
                        let capacity = select_capacity.unwrap_or(-2) as usize;
                        let records = &finished.hit_records;
                        if !finished.values.is_empty() {
                            Err("selection ended with feedback values".into())
                        } else if records.len() > capacity
                            || (count == -1 && records.len() != capacity)
                        {
                            Err(format!(
                                "selection: {} values, count {count}, capacity {capacity}",
                                records.len()
                            ))
                        } else {
                            check_hit_records(records, count, true, Some(names_seen))
                        }
                    }
                    (Ok(GL_SELECT), None) => Err("selection ended with no records".into()),
                    (_, Some(finished)) if !finished.hit_records.is_empty() => {
                        Err("feedback ended with hit records".into())
                    }
                    (Ok(GL_FEEDBACK), Some(finished)) => match (layout, capacity) {
                        (Ok(kind), Ok(capacity)) => {
                            check_feedback(&finished.values, count, capacity, kind)
                        }
                        _ => Err("feedback: no layout".into()),
                    },
                    (_, Some(_)) => Err("GL_RENDER ended with values".into()),
                    (_, None) if count != 0 => Err(format!("GL_RENDER ended with {count}")),
                    _ => Ok(()),
                };
            })
        }
        Op::SelectBuffer { size, address } => ctx.select_buffer(*size, *address),
        Op::InitNames => ctx.init_names(),
        Op::PushName(name) => ctx.push_name(*name),
        Op::PopName => ctx.pop_name(),
        Op::LoadName(name) => ctx.load_name(*name),
        Op::PassThrough(v) => ctx.pass_through(*v),
        Op::Viewport([x, y, w, h]) => ctx.viewport(*x, *y, *w, *h),
        Op::DepthRange([n, f]) => ctx.depth_range(*n, *f),
        Op::ClipPlane { plane, equation } => ctx.clip_plane(*plane, *equation),
        Op::ShadeModel(mode) => ctx.shade_model(*mode),
        Op::FrontFace(mode) => ctx.front_face(*mode),
        Op::CullFace(mode) => ctx.cull_face(*mode),
        Op::PolygonMode { face, mode } => ctx.polygon_mode(*face, *mode),
        Op::PointSize(size) => ctx.point_size(*size),
        Op::LineWidth(width) => ctx.line_width(*width),
        Op::Hint { target, mode } => ctx.hint(*target, *mode),
        Op::ClearColor(c) => ctx.clear_color(*c),
        Op::ClearDepth(d) => ctx.clear_depth(*d),
        Op::Clear(mask) => ctx.clear(*mask),
        Op::State(command) => command.apply(ctx),
        Op::Finish => ctx.finish(),
        Op::Pointer {
            kind,
            size,
            component_type,
            stride,
            address,
        } => match kind {
            ArrayKind::Vertex => ctx.vertex_pointer(*size, *component_type, *stride, *address),
            ArrayKind::Normal => ctx.normal_pointer(*component_type, *stride, *address),
            ArrayKind::Color => ctx.color_pointer(*size, *component_type, *stride, *address),
            ArrayKind::TexCoord => ctx.tex_coord_pointer(*size, *component_type, *stride, *address),
            ArrayKind::EdgeFlag => ctx.edge_flag_pointer(*stride, *address),
            ArrayKind::SecondaryColor => {
                ctx.secondary_color_pointer(*size, *component_type, *stride, *address)
            }
            ArrayKind::FogCoord => ctx.fog_coord_pointer(*component_type, *stride, *address),
            ArrayKind::Index => ctx.index_pointer(*component_type, *stride, *address),
        },
        Op::ClientState { array, enabled } => ctx.client_state(*array, *enabled),
        Op::InterleavedArrays {
            format,
            stride,
            address,
        } => ctx.interleaved_arrays(*format, *stride, *address),
        Op::ArrayElement { index, base } => ctx
            .check_array_element(*index)
            .and_then(|index| ctx.array_element_from(index, &arrays.sources(base.of(index)))),
        Op::DrawArrays {
            mode,
            first,
            count,
            base,
            spans,
        } => ctx
            .check_draw_arrays(*mode, *first, *count)
            .and_then(|indices| draw(ctx, *mode, &indices, *base, *spans, arrays)),
        Op::DrawElements {
            mode,
            count,
            index_type,
            indices,
            range,
            base,
            spans,
        } => {
            let size = match range {
                Some((start, end)) => {
                    ctx.check_draw_range_elements(*mode, *start, *end, *count, *index_type)
                }
                None => ctx.check_draw_elements(*mode, *count, *index_type),
            };
            size.and_then(|size| {
                let indices = ElementIndices::Listed {
                    index_type: *index_type,
                    bytes: &indices[..size.min(indices.len())],
                };
                draw(ctx, *mode, &indices, *base, *spans, arrays)
            })
        }
        Op::DrawFrom {
            mode,
            first,
            count,
            base,
        } => {
            let indices = ElementIndices::Sequential {
                first: *first,
                count: *count,
            };
            ctx.draw_arrays_from(*mode, &arrays.sources(base.of(*first)), &indices)
        }
        Op::LightVertices {
            positions,
            normals,
            colors,
            out,
        } => {
            let mut lit = vec![BLANK_VERTEX; *out];
            let result =
                ctx.light_vertices(positions, normals.as_deref(), colors.as_deref(), &mut lit);
            if result.is_ok() {
                check = lit[..positions.len()]
                    .iter()
                    .position(|v| !lit_colors_clamped(v))
                    .map_or(Ok(()), |i| {
                        Err(format!("light_vertices: vertex {i}: {:?}", lit[i]))
                    });
            }
            result
        }
        Op::CaptureBegin => ctx.capture_begin(),
        Op::CaptureEnd => ctx.capture_end(),
        Op::Get(pname) => unit(ctx.get(*pname)),
        Op::GetLight { light, pname, ints } => {
            if *ints {
                unit(ctx.get_light_i(*light, *pname))
            } else {
                unit(ctx.get_light(*light, *pname))
            }
        }
        Op::GetMaterial { face, pname, ints } => {
            if *ints {
                unit(ctx.get_material_i(*face, *pname))
            } else {
                unit(ctx.get_material(*face, *pname))
            }
        }
        Op::GetClipPlane(plane) => unit(ctx.get_clip_plane(*plane)),
        Op::IsEnabled(cap) => unit(ctx.is_enabled(*cap)),
        Op::GetString(name) => unit(ctx.get_string(*name)),
        Op::GetPointer(pname) => unit(ctx.get_pointer(*pname)),
        Op::GetError => unreachable!("the driver reads the error flag"),
        Op::GenBuffers(n) => ctx.gen_buffers(*n).map(drop),
        Op::BindBuffer { target, name } => ctx.bind_buffer(*target, *name),
        Op::DeleteBuffers(names) => ctx.delete_buffers(names),
        Op::BufferData {
            target,
            size,
            data,
            usage,
        } => {
            // Bytes only for sizes that fit in memory; a huge store is asked for zeroed.
            let bytes: Vec<u8> = (0..(*size).clamp(0, 1 << 16)).map(|i| i as u8).collect();
            let data = (*data && *size <= 1 << 16).then_some(bytes.as_slice());
            ctx.buffer_data(*target, *size, data, *usage)
        }
        Op::BufferSubData {
            target,
            offset,
            size,
        } => {
            let bytes = vec![0xA5; (*size).clamp(0, 1 << 16) as usize];
            match usize::try_from(*size) {
                Ok(n) if n > bytes.len() => {
                    // More than the test holds: only the checks run (no store is that big).
                    ctx.get_buffer_sub_data(*target, *offset, *size).map(drop)
                }
                _ => ctx.buffer_sub_data(*target, *offset, *size, &bytes),
            }
        }
        Op::MapBuffer { target, access } => ctx.map_buffer(*target, *access).map(drop),
        Op::UnmapBuffer(target) => ctx.unmap_buffer(*target).map(drop),
        Op::GetBufferParameter { target, pname } => {
            ctx.get_buffer_parameter(*target, *pname).map(drop)
        }
    };
    (result, check)
}

/// A vertex array draw as a Rust caller makes one: optionally the C layer's span check, then
/// the arrays' bytes from `base`.
fn draw(
    ctx: &mut Context,
    mode: GLenum,
    indices: &ElementIndices,
    base: Base,
    spans: bool,
    arrays: &ArrayBytes,
) -> GlResult {
    if spans {
        ctx.array_spans(indices)?;
    }
    let lowest = indices.range().map_or(0, |(lowest, _)| lowest);
    ctx.draw_arrays_from(mode, &arrays.sources(base.of(lowest)), indices)
}

/// What `light_vertices` overwrites.
const BLANK_VERTEX: ProcessedVertex = ProcessedVertex {
    eye: Vec4::ZERO,
    clip: Vec4::ZERO,
    colors: LitVertex {
        front: FaceColors {
            primary: Vec4::NAN,
            secondary: Vec4::NAN,
        },
        back: FaceColors {
            primary: Vec4::NAN,
            secondary: Vec4::NAN,
        },
    },
    tex_coord: Vec4::ZERO,
    edge_flag: false,
};

fn lit_colors_clamped(v: &ProcessedVertex) -> bool {
    let c = v.colors;
    [
        c.front.primary,
        c.front.secondary,
        c.back.primary,
        c.back.secondary,
    ]
    .into_iter()
    .all(clamped)
}

/// Walks a finished feedback stream (§5.3, figure 5.2): `count` is glRenderMode's result (-1
/// after an overflow, when the stream is cut at `capacity` values), every token is known,
/// polygons are fflight's triangles, and every color is in [0, 1].
fn check_feedback(values: &[f32], count: i32, capacity: i32, kind: GLenum) -> Check {
    let overflowed = count == -1;
    if values.len() > capacity as usize || (overflowed && values.len() != capacity as usize) {
        return Err(format!(
            "feedback: {} values, count {count}, capacity {capacity}",
            values.len()
        ));
    }
    if !overflowed && count as usize != values.len() {
        return Err(format!(
            "feedback: count {count} for {} values",
            values.len()
        ));
    }
    let (coords, color, texture) = match kind {
        GL_2D => (2, false, false),
        GL_3D => (3, false, false),
        GL_3D_COLOR => (3, true, false),
        GL_3D_COLOR_TEXTURE => (3, true, true),
        GL_4D_COLOR_TEXTURE => (4, true, true),
        _ => return Err(format!("feedback type {kind:#x}")),
    };
    let vertex_len = coords + 4 * color as usize + 4 * texture as usize;
    let mut i = 0;
    while i < values.len() {
        let token = values[i];
        let vertices = match token as GLenum {
            GL_POINT_TOKEN => 1,
            GL_LINE_TOKEN | GL_LINE_RESET_TOKEN => 2,
            GL_POLYGON_TOKEN => match values.get(i + 1) {
                Some(&3.0) => {
                    i += 1;
                    3
                }
                None if overflowed => return Ok(()),
                n => return Err(format!("feedback: polygon of {n:?} vertices at {i}")),
            },
            GL_PASS_THROUGH_TOKEN => {
                i += 2;
                continue;
            }
            _ => return Err(format!("feedback: value {token} at {i} is no token")),
        };
        if token != (token as GLenum) as f32 {
            return Err(format!("feedback: token {token} at {i}"));
        }
        i += 1;
        for _ in 0..vertices {
            let Some(vertex) = values.get(i..i + vertex_len) else {
                return match overflowed {
                    true => Ok(()),
                    false => Err(format!("feedback: vertex cut at {i} without overflow")),
                };
            };
            if color && !clamped(Vec4::from_slice(&vertex[coords..coords + 4])) {
                return Err(format!("feedback: color {vertex:?} at {i} outside [0, 1]"));
            }
            i += vertex_len;
        }
    }
    Ok(())
}

/// Checks hit records (§5.2): each is a name count n (at most GL_MAX_NAME_STACK_DEPTH), the
/// minimum and maximum depth (min <= max), then n names, a name stack of `names_seen` when
/// given. A count of -1 (overflow) allows the last record to be cut short; otherwise exactly
/// `count` whole records, and with `complete` nothing after them.
fn check_hit_records(
    records: &[u32],
    count: i32,
    complete: bool,
    names_seen: Option<&[Vec<u32>]>,
) -> Check {
    if count < -1 {
        return Err(format!("selection: count {count}"));
    }
    let (mut i, mut parsed) = (0, 0);
    while i < records.len() && (count == -1 || parsed < count) {
        let n = records[i] as usize;
        if n > 64 {
            return Err(format!(
                "selection: {n} names in the record at {i}: {records:?}"
            ));
        }
        let Some(record) = records.get(i..i + 3 + n) else {
            return match count {
                -1 => Ok(()),
                _ => Err(format!("selection: record cut at {i} without overflow")),
            };
        };
        if record[1] > record[2] {
            return Err(format!("selection: min z > max z at {i}: {record:?}"));
        }
        let names = &record[3..];
        if names_seen.is_some_and(|seen| !seen.iter().any(|s| s == names)) {
            return Err(format!(
                "selection: names {names:?} at {i} never on the stack"
            ));
        }
        i += 3 + n;
        parsed += 1;
    }
    if count >= 0 && parsed != count {
        return Err(format!("selection: count {count}, {parsed} records"));
    }
    if complete && count >= 0 && i != records.len() {
        return Err(format!(
            "selection: {} values after {count} records",
            records.len() - i
        ));
    }
    Ok(())
}

// ---- what the queries report ----

/// Which query a snapshot entry came from.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Key {
    InsideBeginEnd,
    Get(GLenum),
    Light(GLenum, GLenum),
    Material(GLenum, GLenum),
    ClipPlane(GLenum),
    Pointer(GLenum),
    Capture,
    Feedback,
    Selection,
    NameStack,
    MatrixStack(GLenum, usize),
    Buffer(GLenum),
    PolygonStipple,
    PixelMap(GLenum),
}

/// Everything the public queries report about a context, as bits (NaN equals itself, 0 and
/// -0 differ): what a failed command must leave exactly as it was.
#[derive(Default)]
struct Snapshot {
    values: Vec<u64>,
    /// Each entry's key and where its values start.
    keys: Vec<(Key, usize)>,
}

const ERROR_TAG: u64 = 0xE000_0000;

impl Snapshot {
    /// Starts the entry of `key`: its values follow.
    fn start(&mut self, key: Key) -> &mut Vec<u64> {
        self.keys.push((key, self.values.len()));
        &mut self.values
    }

    fn push(&mut self, key: Key, values: impl IntoIterator<Item = u64>) {
        self.keys.push((key, self.values.len()));
        self.values.extend(values);
    }

    /// A glGetLight / glGetMaterial result: the values the pname defines.
    fn push_vector(&mut self, key: Key, result: GlResult<(Vec4, usize)>) {
        let values = self.start(key);
        match result {
            Ok((v, n)) => values.extend(v.to_array()[..n].iter().map(|f| f.to_bits() as u64)),
            Err(error) => values.push(ERROR_TAG | error.code() as u64),
        }
    }

    /// The snapshot of `ctx`, taken on a copy: a primitive in progress is ended there (its
    /// vertices show in capture and feedback), the feedback buffer is read by leaving feedback
    /// mode, and every matrix stack is popped to the bottom.
    fn of(ctx: &Context) -> Snapshot {
        let mut c = ctx.clone();
        let mut s = Snapshot::default();
        s.push(Key::InsideBeginEnd, [c.inside_begin_end() as u64]);
        if c.inside_begin_end() {
            c.end().expect("glEnd ends the primitive in progress");
        }
        for &pname in valid_caps().iter().chain(&get_pnames()) {
            let values = s.start(Key::Get(pname));
            match c.get(pname) {
                Ok(StateValue::Bools(v)) => values.extend(v.iter().map(|&b| 0x100 | b as u64)),
                Ok(StateValue::Ints(v)) => {
                    values.extend(v.iter().map(|&i| 0x200_0000_0000 | i as u32 as u64))
                }
                Ok(StateValue::Floats(v) | StateValue::Normalized(v)) => {
                    values.extend(v.iter().map(|f| f.to_bits()))
                }
                Err(error) => values.push(ERROR_TAG | error.code() as u64),
            }
        }
        for light in LIGHTS {
            for pname in LIGHT_PNAMES {
                s.push_vector(Key::Light(light, pname), c.get_light(light, pname));
            }
        }
        for face in [GL_FRONT, GL_BACK] {
            for pname in MATERIAL_QUERIES {
                s.push_vector(Key::Material(face, pname), c.get_material(face, pname));
            }
        }
        for plane in CLIP_PLANES {
            let equation = c.get_clip_plane(plane).expect("a clip plane");
            s.push(Key::ClipPlane(plane), equation.map(f64::to_bits));
        }
        for pname in POINTER_PNAMES {
            let address = c.get_pointer(pname).expect("a pointer");
            s.push(Key::Pointer(pname), [address as u64]);
        }
        // The bound buffers: parameters and contents (when not mapped).
        for target in BUFFER_TARGETS {
            let values = s.start(Key::Buffer(target));
            for pname in BUFFER_PNAMES {
                match c.get_buffer_parameter(target, pname) {
                    Ok(value) => values.push(value as u32 as u64),
                    Err(error) => values.push(ERROR_TAG | error.code() as u64),
                }
            }
            let size = c.get_buffer_parameter(target, GL_BUFFER_SIZE).unwrap_or(0);
            if let Ok(bytes) = c.get_buffer_sub_data(target, 0, size as isize) {
                values.extend(bytes.iter().map(|&b| b as u64));
            }
        }
        // The stipple packed with the current modes into a buffer that starts as 0xAA.
        let mut stipple = vec![0xAA_u8; c.polygon_stipple_pack_span()];
        c.get_polygon_stipple(&mut stipple).expect("the stipple");
        s.push(Key::PolygonStipple, stipple.iter().map(|&b| b as u64));
        for map in PIXEL_MAPS {
            let values = c.get_pixel_map(map).expect("a pixel map");
            s.push(
                Key::PixelMap(map),
                values.iter().map(|v| v.to_bits() as u64),
            );
        }
        // Capture only grows (or restarts): its counts and last entries show any change.
        let capture = c.captured();
        let (vertices, primitives) = (capture.vertices(), capture.primitives());
        let mut captured = vec![
            capture.is_active() as u64,
            vertices.len() as u64,
            primitives.len() as u64,
        ];
        for v in &vertices[vertices.len().saturating_sub(4)..] {
            let c = v.colors;
            let vectors = [
                v.eye,
                v.clip,
                c.front.primary,
                c.front.secondary,
                c.back.primary,
                c.back.secondary,
                v.tex_coord,
            ];
            captured.extend(
                vectors
                    .iter()
                    .flat_map(|x| x.to_array().map(|f| f.to_bits() as u64)),
            );
            captured.push(v.edge_flag as u64);
        }
        for p in &primitives[primitives.len().saturating_sub(4)..] {
            captured.extend([p.kind as u64, p.mode as u64, p.draw as u64]);
            captured.extend(p.vertices.map(|i| i as u64));
            captured.extend(p.edges.map(|e| e as u64));
        }
        s.push(Key::Capture, captured);
        // In selection mode, the name stack shows in the record of a hit made on purpose.
        if c.get(GL_RENDER_MODE).expect("the render mode").as_ints()[0] == GL_SELECT as i32 {
            let mut probe = c.clone();
            for mode in [GL_PROJECTION, GL_MODELVIEW] {
                probe.matrix_mode(mode).expect("a matrix mode");
                probe.load_identity().expect("glLoadIdentity");
            }
            for plane in CLIP_PLANES {
                probe.set_capability(plane, false).expect("a clip plane");
            }
            probe.begin(GL_POINTS).expect("glBegin");
            probe.vertex(Vec4::new(0.0, 0.0, 0.0, 1.0));
            probe.end().expect("glEnd");
            let (_, finished) = probe.render_mode(GL_RENDER).expect("leaving selection");
            let records = finished.map(|f| f.hit_records).unwrap_or_default();
            // The last record's names (that of the probe's hit, unless the buffer is full).
            let depth = c.get(GL_NAME_STACK_DEPTH).expect("a depth").as_ints()[0] as usize;
            let names = records.len().saturating_sub(depth)..;
            s.push(
                Key::NameStack,
                [depth as u64]
                    .into_iter()
                    .chain(records[names].iter().map(|&v| v as u64)),
            );
        }
        // Leaving feedback or selection mode hands over what the buffer holds (the copy's).
        let (count, finished) = c.render_mode(GL_RENDER).expect("glRenderMode(GL_RENDER)");
        let finished = finished.unwrap_or_default();
        let (values, records) = (finished.values, finished.hit_records);
        s.push(
            Key::Feedback,
            [count as u64, values.len() as u64]
                .into_iter()
                .chain(values.iter().map(|v| v.to_bits() as u64)),
        );
        s.push(Key::Selection, records.iter().map(|&v| v as u64));
        for mode in MATRIX_MODES {
            c.matrix_mode(mode).expect("a matrix mode");
            let pname = match mode {
                GL_MODELVIEW => GL_MODELVIEW_MATRIX,
                GL_PROJECTION => GL_PROJECTION_MATRIX,
                _ => GL_TEXTURE_MATRIX,
            };
            for level in 0.. {
                let top = c.get(pname).expect("a matrix").as_doubles();
                s.push(
                    Key::MatrixStack(mode, level),
                    top.into_iter().map(f64::to_bits),
                );
                if c.pop_matrix().is_err() {
                    break;
                }
            }
        }
        s
    }

    /// The first entry that differs from `other`'s, described.
    fn difference(&self, other: &Snapshot) -> Option<String> {
        if self.values == other.values && self.keys == other.keys {
            return None;
        }
        let entry = |s: &Snapshot, k: usize| {
            let start = s.keys.get(k).map_or(s.values.len(), |e| e.1);
            let end = s.keys.get(k + 1).map_or(s.values.len(), |e| e.1);
            (s.keys.get(k).map(|e| e.0), s.values[start..end].to_vec())
        };
        (0..self.keys.len().max(other.keys.len()))
            .map(|k| (entry(self, k), entry(other, k)))
            .find(|(a, b)| a != b)
            .map(|((key, was), (_, is))| format!("{key:?}: {was:x?}\n  became {is:x?}"))
    }
}

// ---- the Rust sequences ----

/// What the sequences did, for the checks that they exercise what they should.
#[derive(Default, Debug)]
struct Stats {
    calls: usize,
    failed: usize,
    /// Selections ended, the hit records they returned, those that overflowed.
    selections: usize,
    hits: usize,
    overflows: usize,
    /// GL_STACK_OVERFLOW and GL_STACK_UNDERFLOW from glPushName and glPopName.
    name_overflows: usize,
    name_underflows: usize,
}

/// What a sequence knows of the render modes and the name stack, from the calls that
/// succeeded: enough to say exactly how a mode or name-stack command must end (§5.2, §5.3).
#[derive(Default)]
struct Modes {
    feedback_buffer: bool,
    select_buffer: bool,
    selecting: bool,
    names: Vec<u32>,
    /// Every name stack of the selection in progress, for its hit records.
    names_seen: Vec<Vec<u32>>,
}

impl Modes {
    /// The result `op` must have, outside glBegin/glEnd, if it is a mode or name-stack
    /// command.
    fn expected(&self, op: &Op) -> Option<GlResult> {
        let depth = self.names.len();
        Some(match *op {
            Op::RenderMode(GL_FEEDBACK) if !self.feedback_buffer => Err(GlError::InvalidOperation),
            Op::RenderMode(GL_SELECT) if !self.select_buffer => Err(GlError::InvalidOperation),
            Op::RenderMode(mode) if !RENDER_MODES.contains(&mode) => Err(GlError::InvalidEnum),
            Op::RenderMode(_) | Op::InitNames => Ok(()),
            Op::SelectBuffer { size, .. } if size < 0 => Err(GlError::InvalidValue),
            Op::SelectBuffer { .. } if self.selecting => Err(GlError::InvalidOperation),
            Op::SelectBuffer { size, address } if size > 0 && address == 0 => {
                Err(GlError::InvalidValue)
            }
            Op::SelectBuffer { .. } => Ok(()),
            _ if !matches!(op, Op::PushName(_) | Op::PopName | Op::LoadName(_)) => return None,
            _ if !self.selecting => Ok(()),
            Op::PushName(_) if depth >= 64 => Err(GlError::StackOverflow),
            Op::PopName if depth == 0 => Err(GlError::StackUnderflow),
            Op::LoadName(_) if depth == 0 => Err(GlError::InvalidOperation),
            _ => Ok(()),
        })
    }

    /// Follows a call that succeeded.
    fn succeeded(&mut self, op: &Op) {
        match *op {
            Op::FeedbackBuffer { .. } => self.feedback_buffer = true,
            Op::SelectBuffer { .. } => self.select_buffer = true,
            Op::RenderMode(mode) => {
                self.selecting = mode == GL_SELECT;
                self.names.clear();
                self.names_seen = vec![Vec::new()];
            }
            _ if !self.selecting => {}
            Op::InitNames => self.names.clear(),
            Op::PushName(name) => self.names.push(name),
            Op::PopName => {
                self.names.pop();
            }
            Op::LoadName(name) => *self.names.last_mut().expect("a name") = name,
            _ => return,
        }
        if self.selecting && !self.names_seen.contains(&self.names) {
            self.names_seen.push(self.names.clone());
        }
    }
}

/// One random sequence of `seed`: panics with the seed, the failing call and the calls before
/// it when a call panics, a failed call changes what the queries report, the error flag is
/// wrong, or a fed-back, captured or lit color leaves [0, 1]. A third of the sequences feed
/// NaN and infinities, the others only finite values (so that lit colors mean something).
/// Counts what it did in `stats`.
fn sequence(seed: u64, stats: &mut Stats) {
    let mut rng = Rng(seed);
    let finite = !rng.one_in(3);
    let arrays = ArrayBytes::random(&mut rng, finite);
    let mut ctx = Context::new();
    let mut first_error = None;
    let mut history: Vec<Op> = Vec::new();
    let fail = |history: &[Op], step: usize, what: &str| -> ! {
        let recent = history.len().saturating_sub(12);
        let calls: Vec<String> = history[recent..]
            .iter()
            .enumerate()
            .map(|(i, op)| format!("  {}: {op:?}", recent + i))
            .collect();
        panic!(
            "sequence({seed}) (finite inputs: {finite}), call {step}: {what}\ncalls:\n{}",
            calls.join("\n")
        );
    };

    // A prologue that makes feedback, capture and lighting likely, through the same checks.
    let mut prologue = Vec::new();
    if rng.coin() {
        prologue.push(Op::Viewport([0, 0, 64, 48]));
    }
    if !rng.one_in(4) {
        prologue.push(Op::FeedbackBuffer {
            size: rng.below(4000) as i32,
            kind: rng.pick(&FEEDBACK_TYPES),
            address: 0x1000,
        });
        prologue.push(Op::RenderMode(GL_FEEDBACK));
    }
    // Selection in a third of the sequences (leaving feedback if it began), its name stack
    // sometimes empty, sometimes near or at its limit.
    if rng.one_in(3) {
        prologue.push(select_buffer(&mut rng));
        prologue.push(Op::RenderMode(GL_SELECT));
        prologue.push(Op::InitNames);
        let names = match rng.below(4) {
            0 => 0,
            1 => rng.range(1, 5),
            _ => rng.range(60, 66),
        };
        prologue.extend((0..names).map(|name| Op::PushName(name as u32)));
    }
    if !rng.one_in(4) {
        prologue.push(Op::CaptureBegin);
    }
    if rng.coin() {
        prologue.push(Op::Capability {
            cap: GL_LIGHTING,
            enabled: true,
        });
        prologue.push(Op::Capability {
            cap: rng.pick(&LIGHTS),
            enabled: true,
        });
    }
    if !rng.one_in(4) {
        prologue.push(Op::Pointer {
            kind: ArrayKind::Vertex,
            size: rng.range(2, 4) as i32,
            component_type: rng.pick(&[GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE]),
            stride: 0,
            address: 0x1000,
        });
        prologue.push(Op::ClientState {
            array: GL_VERTEX_ARRAY,
            enabled: true,
        });
        if rng.coin() {
            prologue.push(Op::Pointer {
                kind: ArrayKind::Color,
                size: 4,
                component_type: rng.pick(&COMPONENT_TYPES),
                stride: 0,
                address: 0x2000,
            });
            prologue.push(Op::ClientState {
                array: GL_COLOR_ARRAY,
                enabled: true,
            });
        }
    }

    let steps = prologue.len() + 20 + rng.below(100);
    let mut modes = Modes::default();
    let mut failed = 0;
    // The snapshot of the state since the last failed call, while no other call could change it.
    let mut unchanged: Option<Snapshot> = None;
    for step in 0..steps {
        let op = match prologue.get(step) {
            Some(op) => op.clone(),
            None => next_op(&mut rng, ctx.inside_begin_end(), modes.selecting, finite),
        };
        history.push(op.clone());
        if let Op::GetError = op {
            let got = ctx.get_error();
            let want = first_error.take().unwrap_or(GL_NO_ERROR);
            if got != want {
                fail(
                    &history,
                    step,
                    &format!("get_error {got:#x}, expected {want:#x}"),
                );
            }
            continue;
        }
        let must_fail = op.must_fail(ctx.inside_begin_end());
        let before = ctx.clone();
        let expected = (!ctx.inside_begin_end())
            .then(|| modes.expected(&op))
            .flatten();
        let outcome = catch_unwind(AssertUnwindSafe(|| {
            apply(&mut ctx, &op, &arrays, &modes.names_seen, stats)
        }));
        let (result, check) = match outcome {
            Ok(outcome) => outcome,
            Err(_) => fail(&history, step, "panicked"),
        };
        if let Err(problem) = check {
            fail(&history, step, &problem);
        }
        if must_fail && result.is_ok() {
            fail(&history, step, "accepted a call GL must reject");
        }
        if expected.is_some_and(|expected| expected != result) {
            let what = format!(
                "{result:?}, expected {expected:?} (modes: {:?})",
                modes.names
            );
            fail(&history, step, &what);
        }
        match (&op, result) {
            (_, Ok(())) => modes.succeeded(&op),
            (Op::PushName(_), Err(GlError::StackOverflow)) => stats.name_overflows += 1,
            (Op::PopName, Err(GlError::StackUnderflow)) => stats.name_underflows += 1,
            _ => {}
        }
        if !ctx.inside_begin_end() {
            let depth = ctx.get(GL_NAME_STACK_DEPTH).map(|v| v.as_ints()[0]);
            let mode = ctx.get(GL_RENDER_MODE).map(|v| v.as_ints()[0] as GLenum);
            if depth != Ok(modes.names.len() as i32) || (mode == Ok(GL_SELECT)) != modes.selecting {
                let what = format!(
                    "name stack {depth:?} in {mode:?}, expected {:?}",
                    modes.names
                );
                fail(&history, step, &what);
            }
        }
        if let Err(error) = result {
            failed += 1;
            let earlier = unchanged.take().unwrap_or_else(|| Snapshot::of(&before));
            let now = Snapshot::of(&ctx);
            if let Some(change) = earlier.difference(&now) {
                fail(&history, step, &format!("{error:?}, but changed {change}"));
            }
            unchanged = Some(now);
            first_error.get_or_insert(error.code());
        }
        if result.is_ok() && !op.is_query() {
            unchanged = None;
        }
        ctx.settle(result);
    }

    // Finish: end the primitive, check what capture collected, end feedback.
    if ctx.inside_begin_end() {
        ctx.end().expect("glEnd");
    }
    let captured = ctx.captured().vertices();
    if let Some(i) = captured.iter().position(|v| !lit_colors_clamped(v)) {
        let what = format!("captured vertex {i}: {:?}", captured[i]);
        fail(&history, steps, &what);
    }
    let (result, check) = apply(
        &mut ctx,
        &Op::RenderMode(GL_RENDER),
        &arrays,
        &modes.names_seen,
        stats,
    );
    history.push(Op::RenderMode(GL_RENDER));
    if let Err(problem) = check.and(result.map_err(|e| format!("{e:?}"))) {
        fail(&history, steps, &problem);
    }
    if ctx.get_error() != first_error.unwrap_or(GL_NO_ERROR) {
        fail(&history, steps, "the error flag lost its first error");
    }
    stats.calls += steps;
    stats.failed += failed;
}

fn sequences(seeds: std::ops::Range<u64>) {
    let mut stats = Stats::default();
    for seed in seeds.clone() {
        sequence(seed, &mut stats);
    }
    // The sequences must exercise both sides of the rule, and selection's.
    let n = seeds.end - seeds.start;
    let Stats { calls, failed, .. } = stats;
    assert!(calls > 50 * n as usize, "{calls} calls in {n} sequences");
    assert!(
        failed > calls / 5 && failed < calls * 4 / 5,
        "{failed} of {calls} failed"
    );
    assert!(
        stats.hits > 0 && stats.overflows > 0 && stats.name_overflows > 0,
        "{stats:?}"
    );
}

// Four tests, so the harness runs them in parallel.

#[test]
fn random_sequences_0() {
    sequences(0..600);
}

#[test]
fn random_sequences_1() {
    sequences(600..1200);
}

#[test]
fn random_sequences_2() {
    sequences(1200..1800);
}

#[test]
fn random_sequences_3() {
    sequences(1800..2400);
}

/// Found by these sequences: sequential indices ending at usize::MAX overflowed the index
/// iterator (a panic in debug builds, an out-of-bounds read in release ones).
#[test]
fn sequential_draws_end_at_the_last_index() {
    let mut ctx = Context::new();
    let positions: Vec<u8> = [0.0f32, 0.0, 0.5, 0.5]
        .iter()
        .flat_map(|v| v.to_ne_bytes())
        .collect();
    ctx.vertex_pointer(2, GL_FLOAT, 0, 0x1000).unwrap();
    ctx.client_state(GL_VERTEX_ARRAY, true).unwrap();
    ctx.capture_begin().unwrap();
    let last_two = ElementIndices::Sequential {
        first: usize::MAX - 1,
        count: 2,
    };
    let sources = ArraySources::new(usize::MAX - 1).with(ArrayKind::Vertex, &positions);
    assert_eq!(ctx.draw_arrays_from(GL_LINES, &sources, &last_two), Ok(()));
    assert_eq!(ctx.captured().vertices().len(), 2);
    assert_eq!(ctx.captured().primitives().len(), 1);
    for (first, count) in [(usize::MAX - 1, 3), (usize::MAX, 2), (2, usize::MAX)] {
        let past_the_end = ElementIndices::Sequential { first, count };
        let sources = ArraySources::new(first).with(ArrayKind::Vertex, &positions);
        assert_eq!(
            ctx.draw_arrays_from(GL_POINTS, &sources, &past_the_end),
            Err(GlError::InvalidValue),
            "first {first}, count {count}"
        );
    }
    assert_eq!(ctx.captured().vertices().len(), 2);
}

// ---- the C entry points ----

unsafe extern "C" {
    fn glClipPlane(plane: GLenum, equation: *const GLdouble);
    fn glGetClipPlane(plane: GLenum, equation: *mut GLdouble);
    fn glShadeModel(mode: GLenum);
    fn glFrontFace(mode: GLenum);
    fn glCullFace(mode: GLenum);
    fn glPolygonMode(face: GLenum, mode: GLenum);
    fn glHint(target: GLenum, mode: GLenum);
    fn glFogfv(pname: GLenum, params: *const GLfloat);
    fn glFogiv(pname: GLenum, params: *const GLint);
    safe fn glFogf(pname: GLenum, param: GLfloat);
    fn glPointParameterfv(pname: GLenum, params: *const GLfloat);
    fn glPointParameteriv(pname: GLenum, params: *const GLint);
    safe fn glPointParameterf(pname: GLenum, param: GLfloat);
    fn glPolygonStipple(mask: *const GLubyte);
    fn glGetPolygonStipple(mask: *mut GLubyte);
    fn glPixelMapfv(map: GLenum, mapsize: GLsizei, values: *const GLfloat);
    fn glPixelMapuiv(map: GLenum, mapsize: GLsizei, values: *const GLuint);
    fn glPixelMapusv(map: GLenum, mapsize: GLsizei, values: *const GLushort);
    fn glGetPixelMapfv(map: GLenum, values: *mut GLfloat);
    fn glGetPixelMapuiv(map: GLenum, values: *mut GLuint);
    fn glGetPixelMapusv(map: GLenum, values: *mut GLushort);
    safe fn glScissor(x: GLint, y: GLint, width: GLsizei, height: GLsizei);
    safe fn glPointSize(size: GLfloat);
    safe fn glLineWidth(width: GLfloat);
    safe fn glPixelStorei(pname: GLenum, param: GLint);
    safe fn glPixelTransferf(pname: GLenum, param: GLfloat);
    safe fn glDepthFunc(func: GLenum);
    safe fn glStencilFunc(func: GLenum, reference: GLint, mask: GLuint);
    safe fn glAlphaFunc(func: GLenum, reference: GLclampf);
    safe fn glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum);
    safe fn glBlendFunc(sfactor: GLenum, dfactor: GLenum);
    safe fn glBlendEquation(mode: GLenum);
    safe fn glLogicOp(opcode: GLenum);
    safe fn glDrawBuffer(mode: GLenum);
    safe fn glReadBuffer(mode: GLenum);
    safe fn glAccum(op: GLenum, value: GLfloat);
    fn glRectfv(v1: *const GLfloat, v2: *const GLfloat);
    fn glRectdv(v1: *const GLdouble, v2: *const GLdouble);
    fn glRectiv(v1: *const GLint, v2: *const GLint);
    fn glRectsv(v1: *const GLshort, v2: *const GLshort);
    fn glVertex2fv(v: *const GLfloat);
    fn glVertex4fv(v: *const GLfloat);
    fn glVertex2sv(v: *const GLshort);
    fn glVertex3dv(v: *const GLdouble);
    fn glVertex4iv(v: *const GLint);
    fn glVertexPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glColorPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glEnableClientState(array: GLenum);
    fn glDisableClientState(array: GLenum);
    fn glInterleavedArrays(format: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glGetPointerv(pname: GLenum, params: *mut *mut c_void);
    fn glArrayElement(i: GLint);
    fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei);
    fn glDrawElements(mode: GLenum, count: GLsizei, ty: GLenum, indices: *const c_void);
    fn glDrawRangeElements(
        mode: GLenum,
        start: GLuint,
        end: GLuint,
        count: GLsizei,
        ty: GLenum,
        indices: *const c_void,
    );
    fn glSelectBuffer(size: GLsizei, buffer: *mut GLuint);
    safe fn glInitNames();
    safe fn glPushName(name: GLuint);
    safe fn glPopName();
    safe fn glLoadName(name: GLuint);
    fn fflCaptureBegin();
    fn fflCaptureEnd();
    fn fflCaptureReadVertices(first: GLuint, count: GLuint, out: *mut c_void) -> GLuint;
    fn fflCaptureReadPrimitives(first: GLuint, count: GLuint, out: *mut c_void) -> GLuint;
    fn fflLightVertices(
        count: GLsizei,
        position_size: GLint,
        positions: *const GLfloat,
        position_stride: GLsizei,
        normals: *const GLfloat,
        normal_stride: GLsizei,
        colors: *const GLfloat,
        color_stride: GLsizei,
        eye: *mut GLfloat,
        eye_stride: GLsizei,
        clip: *mut GLfloat,
        clip_stride: GLsizei,
        front_primary: *mut GLfloat,
        front_primary_stride: GLsizei,
        front_secondary: *mut GLfloat,
        front_secondary_stride: GLsizei,
        back_primary: *mut GLfloat,
        back_primary_stride: GLsizei,
        back_secondary: *mut GLfloat,
        back_secondary_stride: GLsizei,
    );
}

fn current_snapshot() -> Snapshot {
    with_current(|ctx| Snapshot::of(ctx)).expect("a current context")
}

/// A call GL must reject: a NULL pointer where the command needs one (with enum arguments
/// valid or not), or an invalid enum. Returns the call's name for the failure report.
///
/// # Safety
/// Every non-NULL pointer passed is valid for what the command reads or writes.
unsafe fn bad_call(rng: &mut Rng) -> String {
    let light = rng.enumeration(&LIGHTS);
    let light_pname = rng.enumeration(&LIGHT_PNAMES);
    let face = rng.enumeration(&FACES);
    let material_pname = rng.enumeration(&MATERIAL_PNAMES);
    let model_pname = rng.enumeration(&LIGHT_MODEL_PNAMES);
    let pname = rng.enumeration(&get_pnames());
    let plane = rng.enumeration(&CLIP_PLANES);
    let mode = rng.enumeration(&PRIMITIVES);
    let count = 1 + rng.below(8) as i32;
    let floats = [0.5f32; 4];
    let doubles = [0.5f64; 4];
    let call = rng.below(64);
    let pixel_map = rng.enumeration(&PIXEL_MAPS);
    let mut out = [0.0f32; 4];
    // SAFETY: NULL pointers, or pointers to local arrays of 4 values, enough for every call.
    unsafe {
        match call {
            0 => glLightfv(light, light_pname, null()),
            1 => glLightiv(light, light_pname, null()),
            2 => glGetLightfv(light, light_pname, null_mut()),
            3 => glGetLightiv(light, light_pname, null_mut()),
            4 => glMaterialfv(face, material_pname, null()),
            5 => glMaterialiv(face, material_pname, null()),
            6 => glGetMaterialfv(
                rng.enumeration(&[GL_FRONT, GL_BACK]),
                material_pname,
                null_mut(),
            ),
            7 => glGetMaterialiv(
                rng.enumeration(&[GL_FRONT, GL_BACK]),
                material_pname,
                null_mut(),
            ),
            8 => glLightModelfv(model_pname, null()),
            9 => glLightModeliv(model_pname, null()),
            10 => glGetBooleanv(pname, null_mut()),
            11 => glGetIntegerv(pname, null_mut()),
            12 => glGetFloatv(pname, null_mut()),
            13 => glGetDoublev(pname, null_mut()),
            14 => glLoadMatrixf(null()),
            15 => glLoadMatrixd(null()),
            16 => glMultMatrixf(null()),
            17 => glMultMatrixd(null()),
            18 => glLoadTransposeMatrixf(null()),
            19 => glMultTransposeMatrixd(null()),
            20 => glClipPlane(plane, null()),
            21 => glGetClipPlane(plane, null_mut()),
            22 => glColor3fv(null()),
            23 => glColor4ubv(null()),
            24 => glColor4dv(null()),
            25 => glNormal3fv(null()),
            26 => glNormal3bv(null()),
            27 => glTexCoord2fv(null()),
            28 => glTexCoord4dv(null()),
            29 => match rng.below(5) {
                0 => glVertex2fv(null()),
                1 => glVertex3fv(null()),
                2 => glVertex4fv(null()),
                3 => glVertex2sv(null()),
                _ => glVertex3dv(null()),
            },
            30 => glVertex4iv(null()),
            31 => glEdgeFlagv(null()),
            32 => match rng.below(4) {
                0 => glRectfv(null(), floats.as_ptr()),
                1 => glRectdv(doubles.as_ptr(), null()),
                2 => glRectiv(null(), null()),
                _ => glRectsv([1i16, 2].as_ptr(), null()),
            },
            33 => glFeedbackBuffer(count, rng.enumeration(&FEEDBACK_TYPES), null_mut()),
            34 => glGetPointerv(rng.enumeration(&POINTER_PNAMES), null_mut()),
            35 => glDrawElements(mode, count, rng.enumeration(&INDEX_TYPES), null()),
            36 => glDrawRangeElements(mode, 0, 9, count, rng.enumeration(&INDEX_TYPES), null()),
            37 => fflLightVertices(
                count,
                rng.range(1, 5) as i32,
                null(),
                0,
                null(),
                0,
                null(),
                0,
                null_mut(),
                0,
                null_mut(),
                0,
                null_mut(),
                0,
                null_mut(),
                0,
                null_mut(),
                0,
                null_mut(),
                0,
            ),
            // Wrong enums.
            38 => match rng.coin() {
                true => glEnable(rng.invalid_enum(&valid_caps())),
                false => glDisable(rng.invalid_enum(&valid_caps())),
            },
            39 => {
                glIsEnabled(rng.invalid_enum(&valid_caps()));
            }
            40 => match rng.coin() {
                true => glLightf(rng.invalid_enum(&LIGHTS), light_pname, 1.0),
                false => glLighti(light, rng.invalid_enum(&LIGHT_PNAMES), 1),
            },
            41 => match rng.coin() {
                true => glMaterialf(rng.invalid_enum(&FACES), GL_SHININESS, 1.0),
                false => glMaterialfv(face, rng.invalid_enum(&MATERIAL_PNAMES), floats.as_ptr()),
            },
            42 => match rng.coin() {
                true => glLightModeli(rng.invalid_enum(&LIGHT_MODEL_PNAMES), 0),
                false => glLightModeli(
                    GL_LIGHT_MODEL_COLOR_CONTROL,
                    rng.invalid_enum(&[GL_SINGLE_COLOR, GL_SEPARATE_SPECULAR_COLOR]) as i32,
                ),
            },
            43 => match rng.coin() {
                true => glColorMaterial(rng.invalid_enum(&FACES), GL_DIFFUSE),
                false => glColorMaterial(face, rng.invalid_enum(&COLOR_MATERIAL_MODES)),
            },
            44 => glMatrixMode(rng.invalid_enum(&MATRIX_MODES)),
            45 => glBegin(rng.invalid_enum(&PRIMITIVES)),
            46 => match rng.below(5) {
                0 => glShadeModel(rng.invalid_enum(&SHADE_MODELS)),
                1 => glFrontFace(rng.invalid_enum(&WINDINGS)),
                2 => glCullFace(rng.invalid_enum(&FACES)),
                3 => glPolygonMode(face, rng.invalid_enum(&POLYGON_MODES)),
                _ => glHint(
                    rng.enumeration(&HINT_TARGETS),
                    rng.invalid_enum(&HINT_MODES),
                ),
            },
            47 => {
                glRenderMode(rng.invalid_enum(&RENDER_MODES));
            }
            48 => {
                assert!(glGetString(rng.invalid_enum(&STRING_NAMES)).is_null());
            }
            49 => match rng.coin() {
                true => glEnableClientState(rng.invalid_enum(&CLIENT_ARRAYS)),
                false => glInterleavedArrays(rng.invalid_enum(&INTERLEAVED_FORMATS), 0, null()),
            },
            50 => glDrawArrays(rng.invalid_enum(&PRIMITIVES), 0, count),
            52 => glSelectBuffer(count, null_mut()),
            53 => {
                let mut names = [0 as GLuint; 4];
                let buffer = if rng.coin() {
                    names.as_mut_ptr()
                } else {
                    null_mut()
                };
                glSelectBuffer(rng.pick(&[-1, -4, i32::MIN]), buffer);
            }
            // The state that does not change vertex processing: NULL pointers...
            54 => match rng.coin() {
                true => glFogfv(rng.enumeration(&FOG_PNAMES), null()),
                false => glFogiv(rng.enumeration(&FOG_PNAMES), null()),
            },
            55 => match rng.coin() {
                true => glPointParameterfv(rng.enumeration(&POINT_PNAMES), null()),
                false => glPointParameteriv(rng.enumeration(&POINT_PNAMES), null()),
            },
            56 => match rng.coin() {
                true => glPolygonStipple(null()),
                false => glGetPolygonStipple(null_mut()),
            },
            57 => match rng.below(3) {
                0 => glPixelMapfv(pixel_map, 1 << rng.below(4), null()),
                1 => glPixelMapuiv(pixel_map, 1 << rng.below(4), null()),
                _ => glPixelMapusv(pixel_map, 1 << rng.below(4), null()),
            },
            58 => match rng.below(3) {
                0 => glGetPixelMapfv(pixel_map, null_mut()),
                1 => glGetPixelMapuiv(pixel_map, null_mut()),
                _ => glGetPixelMapusv(pixel_map, null_mut()),
            },
            // ... negative sizes and bad values ...
            59 => match rng.below(3) {
                0 => glPixelMapfv(
                    pixel_map,
                    rng.pick(&[0, -1, 257, i32::MIN]),
                    floats.as_ptr(),
                ),
                1 => glScissor(0, 0, rng.pick(&[-1, i32::MIN]), count),
                _ => glScissor(0, 0, count, rng.pick(&[-1, i32::MIN])),
            },
            60 => match rng.below(4) {
                0 => glPointSize(rng.pick(&[0.0, -1.0, f32::NAN])),
                1 => glLineWidth(rng.pick(&[0.0, -1.0, f32::NAN])),
                2 => glPixelStorei(
                    rng.pick(&[GL_PACK_ALIGNMENT, GL_UNPACK_ALIGNMENT]),
                    rng.pick(&[0, 3, 16, -4]),
                ),
                _ => glFogf(GL_FOG_DENSITY, rng.pick(&[-1.0, f32::NAN])),
            },
            // ... and wrong enums.
            61 => match rng.below(7) {
                0 => glDepthFunc(rng.invalid_enum(&COMPARISON_FUNCS)),
                1 => glStencilFunc(rng.invalid_enum(&COMPARISON_FUNCS), 1, 1),
                2 => glAlphaFunc(rng.invalid_enum(&COMPARISON_FUNCS), 0.5),
                3 => glStencilOp(GL_KEEP, rng.invalid_enum(&STENCIL_OPS), GL_KEEP),
                4 => glBlendFunc(rng.invalid_enum(&BLEND_FACTORS), GL_ZERO),
                5 => glBlendEquation(rng.invalid_enum(&BLEND_EQUATIONS)),
                _ => glLogicOp(rng.invalid_enum(&(GL_CLEAR..=GL_SET).collect::<Vec<_>>())),
            },
            62 => match rng.below(6) {
                0 => glPixelStorei(rng.invalid_enum(&PIXEL_STORE_PNAMES), 1),
                1 => glPixelTransferf(rng.invalid_enum(&PIXEL_TRANSFER_PNAMES), 1.0),
                2 => glFogf(rng.invalid_enum(&FOG_PNAMES), 1.0),
                3 => glPointParameterf(rng.invalid_enum(&POINT_PNAMES), 1.0),
                4 => glDrawBuffer(rng.invalid_enum(&COLOR_BUFFERS)),
                _ => glReadBuffer(rng.invalid_enum(&COLOR_BUFFERS[..3])),
            },
            63 => match rng.below(4) {
                // Without an accumulation buffer every glAccum is an error.
                3 => glAccum(
                    rng.enumeration(&[GL_ACCUM, GL_LOAD, GL_RETURN, GL_MULT, GL_ADD]),
                    0.5,
                ),
                0 => glHint(rng.invalid_enum(&HINT_TARGETS), GL_NICEST),
                1 => glPixelMapfv(rng.invalid_enum(&PIXEL_MAPS), 2, floats.as_ptr()),
                _ => glGetPixelMapfv(rng.invalid_enum(&PIXEL_MAPS), out.as_mut_ptr()),
            },
            _ => glVertexPointer(4, rng.invalid_enum(&COMPONENT_TYPES[2..]), 0, null()),
        }
    }
    format!("bad call {call}")
}

/// A position for the arrays the C setups enable.
static POSITION: [GLfloat; 3] = [0.0, 0.0, -0.5];

/// A call that fails because of state its setup leaves (an enabled array with a NULL pointer,
/// captured data to read into NULL): runs the setup, returns the call.
fn setup_bad_call(rng: &mut Rng, select: &mut [GLuint]) -> (&'static str, Box<dyn FnOnce()>) {
    let mode = rng.enumeration(&PRIMITIVES);
    let count = 1 + rng.below(8) as i32;
    // SAFETY (all blocks): NULL pointers, which the commands store or reject, or POSITION,
    // which lives as long as the program.
    match rng.below(6) {
        4 | 5 => {
            // Selection with an empty name stack, or a full one.
            leave_render_mode(select);
            let (size, buffer) = (select.len() as GLsizei, select.as_mut_ptr());
            // SAFETY: `select` outlives the selection (the test ends it).
            unsafe { glSelectBuffer(size, buffer) };
            glRenderMode(GL_SELECT);
            glInitNames();
            if rng.coin() {
                (0..64).for_each(|name| glPushName(name));
                return (
                    "glPushName on a full name stack",
                    Box::new(|| glPushName(64)),
                );
            }
            match rng.below(4) {
                0 => ("glPopName on an empty name stack", Box::new(|| glPopName())),
                1 => (
                    "glLoadName on an empty name stack",
                    Box::new(|| glLoadName(1)),
                ),
                // SAFETY (both): glSelectBuffer in selection mode stores nothing.
                2 => (
                    "glSelectBuffer in selection mode",
                    Box::new(move || unsafe { glSelectBuffer(size, buffer) }),
                ),
                _ => (
                    "glSelectBuffer(NULL) in selection mode",
                    Box::new(move || unsafe { glSelectBuffer(0, null_mut()) }),
                ),
            }
        }
        0 => {
            unsafe {
                glVertexPointer(3, GL_FLOAT, 0, null());
                glEnableClientState(GL_VERTEX_ARRAY);
            }
            (
                "glDrawArrays, NULL vertex array",
                Box::new(move || unsafe { glDrawArrays(mode, 0, count) }),
            )
        }
        1 => {
            unsafe { glInterleavedArrays(rng.pick(&INTERLEAVED_FORMATS), 0, null()) };
            (
                "glArrayElement, NULL interleaved arrays",
                Box::new(|| unsafe { glArrayElement(0) }),
            )
        }
        2 => {
            unsafe {
                glVertexPointer(3, GL_FLOAT, 0, POSITION.as_ptr().cast());
                glEnableClientState(GL_VERTEX_ARRAY);
                glColorPointer(4, GL_FLOAT, 0, null());
                glEnableClientState(GL_COLOR_ARRAY);
            }
            (
                "glDrawArrays, NULL color array",
                Box::new(move || unsafe { glDrawArrays(mode, 0, 1) }),
            )
        }
        _ => {
            unsafe { fflCaptureBegin() };
            glBegin(GL_TRIANGLES);
            for _ in 0..3 {
                glVertex3f(0.0, 0.0, -0.5);
            }
            glEnd();
            unsafe { fflCaptureEnd() };
            if rng.coin() {
                (
                    "fflCaptureReadPrimitives into NULL",
                    Box::new(|| unsafe {
                        fflCaptureReadPrimitives(0, 1, null_mut());
                    }),
                )
            } else {
                (
                    "fflCaptureReadVertices into NULL",
                    Box::new(|| unsafe {
                        fflCaptureReadVertices(1, 3, null_mut());
                    }),
                )
            }
        }
    }
}

/// Leaves feedback or selection mode; hit records left in `select` must be well formed.
fn leave_render_mode(select: &[GLuint]) {
    let mut mode = 0;
    let mut capacity = 0;
    // SAFETY: one value each.
    unsafe {
        glGetIntegerv(GL_RENDER_MODE, &mut mode);
        glGetIntegerv(GL_SELECTION_BUFFER_SIZE, &mut capacity);
    }
    let count = glRenderMode(GL_RENDER);
    expect_no_error("glRenderMode(GL_RENDER)");
    if mode as GLenum == GL_SELECT {
        // The buffer is `select`, or NULL with size 0.
        let records = &select[..capacity as usize];
        if let Err(problem) = check_hit_records(records, count, false, None) {
            panic!("glRenderMode(GL_RENDER) from GL_SELECT: {problem}");
        }
    }
}

/// Random valid state for the bad calls to meet: lighting, feedback into `buffer` or
/// selection into `select` (or NULL, size 0), capture.
fn random_valid_state(rng: &mut Rng, buffer: &mut [GLfloat], select: &mut [GLuint]) {
    glViewport(0, 0, 64, 64);
    if rng.coin() {
        glEnable(GL_LIGHTING);
        glEnable(rng.pick(&LIGHTS));
    } else {
        glDisable(GL_LIGHTING);
    }
    // SAFETY: no pointers.
    unsafe { glDisableClientState(GL_COLOR_ARRAY) };
    leave_render_mode(select);
    if rng.coin() {
        let kind = rng.pick(&FEEDBACK_TYPES);
        // SAFETY: `buffer` outlives the context's use of it (the test ends feedback).
        unsafe { glFeedbackBuffer(buffer.len() as i32, kind, buffer.as_mut_ptr()) };
        glRenderMode(GL_FEEDBACK);
    } else if rng.coin() {
        let (size, address) = match rng.below(3) {
            0 => (0, null_mut()),
            1 => (rng.below(8) as i32, select.as_mut_ptr()),
            _ => (select.len() as i32, select.as_mut_ptr()),
        };
        // SAFETY: `select` outlives the selection (the test ends it); NULL with size 0.
        unsafe { glSelectBuffer(size, address) };
        glRenderMode(GL_SELECT);
        glInitNames();
        (0..rng.below(4) as GLuint).for_each(|name| glPushName(name));
    }
    if rng.coin() {
        // SAFETY: no pointers.
        unsafe { fflCaptureBegin() };
    }
    expect_no_error("the valid setup");
}

#[test]
fn c_calls_with_null_pointers_and_wrong_enums_set_an_error_and_change_nothing() {
    let _context = fresh();
    let mut rng = Rng(0xC0FFEE);
    let mut buffer = vec![0.0f32; 4096];
    let mut select = vec![0 as GLuint; 256];
    for round in 0..3000 {
        if round % 50 == 0 {
            random_valid_state(&mut rng, &mut buffer, &mut select);
        }
        let setup = rng.one_in(5).then(|| setup_bad_call(&mut rng, &mut select));
        expect_no_error("the setup");
        let inside = rng.one_in(3);
        if inside {
            glBegin(rng.pick(&PRIMITIVES));
            for _ in 0..rng.below(4) {
                glVertex3f(rng.uniform(-1.0, 1.0) as f32, 0.5, -0.5);
            }
        }
        let before = current_snapshot();
        let name = match setup {
            Some((name, call)) => {
                call();
                name.to_string()
            }
            None if inside && rng.one_in(6) => {
                match rng.below(4) {
                    0 => glInitNames(),
                    1 => glPushName(7),
                    2 => glPopName(),
                    _ => glLoadName(7),
                }
                "a name-stack command inside glBegin/glEnd".to_string()
            }
            // SAFETY: the calls pass NULL or local arrays of four values.
            None => unsafe { bad_call(&mut rng) },
        };
        let after = current_snapshot();
        let what = format!("round {round}, {name} (inside glBegin/glEnd: {inside})");
        if let Some(change) = before.difference(&after) {
            panic!("{what}: changed {change}");
        }
        if inside {
            glEnd();
        }
        assert_ne!(glGetError(), GL_NO_ERROR, "{what}: no error");
        assert_eq!(
            glGetError(),
            GL_NO_ERROR,
            "{what}: the flag was not cleared"
        );
    }
    leave_render_mode(&select);
}
