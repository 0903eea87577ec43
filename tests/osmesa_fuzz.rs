//! Differential command-sequence fuzzing against OSMesa: random sequences of valid and invalid
//! GL calls (lighting, materials, light model, color material, matrices and their stack,
//! enables, culling, current attributes, primitives in glBegin/glEnd, vertex arrays with
//! glDrawArrays and glDrawElements, feedback, selection with small buffers and name stack
//! overflows and underflows, queries of current values, matrices, lights and materials),
//! generated from a seed, run by this one
//! process on both libraries, each loaded with dlopen (`libfflight.so` built by cargo and
//! Debian's `libOSMesa.so.8`): every call's error and every feedback pass are printed in the
//! canonical format of `c_tests/ffl_test.h` and compared with the C harness's own comparison
//! (`tests/common/compare.rs`: the same tolerances, no known difference accepted).
//!
//! The generator stays clear of the documented OSMesa differences (docs/osmesa-differences.md:
//! no line primitives (1), smooth shading only (2), fill polygon mode (3), vector pnames
//! through the vector commands (4), no glColorMaterial(GL_BACK) (5), no texture coordinates
//! (6), shininess and spot exponent at least 1 (7, 8), w = 1 (9), no raster position (13),
//! no triangle of zero area (22), the color material mode chosen once and a glColor after its glEnable (23)),
//! and keeps geometry inside the view volume (no vertex is made by clipping, whose tolerance
//! needs the reference's `clip-made` marks).
//!
//! `cargo test` runs a fixed set of seeds; `make fuzz-osmesa SEQUENCES=N` runs N
//! (`FFL_OSMESA_SEQUENCES`, `FFL_OSMESA_FIRST_SEED`) and prints the figures.

#[path = "common/compare.rs"]
mod compare;

use std::ffi::{CString, c_void};
use std::fmt::Write as _;
use std::path::PathBuf;

use compare::*;

type E = u32;
type F = f32;

/// The GL entry points the sequences use, from one library.
#[allow(non_snake_case)]
struct Gl {
    glEnable: unsafe extern "C" fn(E),
    glDisable: unsafe extern "C" fn(E),
    glLightfv: unsafe extern "C" fn(E, E, *const F),
    glMaterialfv: unsafe extern "C" fn(E, E, *const F),
    glLightModelfv: unsafe extern "C" fn(E, *const F),
    glColorMaterial: unsafe extern "C" fn(E, E),
    glMatrixMode: unsafe extern "C" fn(E),
    glLoadIdentity: unsafe extern "C" fn(),
    glTranslatef: unsafe extern "C" fn(F, F, F),
    glRotatef: unsafe extern "C" fn(F, F, F, F),
    glScalef: unsafe extern "C" fn(F, F, F),
    glPushMatrix: unsafe extern "C" fn(),
    glPopMatrix: unsafe extern "C" fn(),
    glOrtho: unsafe extern "C" fn(f64, f64, f64, f64, f64, f64),
    glViewport: unsafe extern "C" fn(i32, i32, i32, i32),
    glColor4f: unsafe extern "C" fn(F, F, F, F),
    glNormal3f: unsafe extern "C" fn(F, F, F),
    glVertex3f: unsafe extern "C" fn(F, F, F),
    glBegin: unsafe extern "C" fn(E),
    glEnd: unsafe extern "C" fn(),
    glGetError: unsafe extern "C" fn() -> E,
    glFeedbackBuffer: unsafe extern "C" fn(i32, E, *mut F),
    glRenderMode: unsafe extern "C" fn(E) -> i32,
    glPassThrough: unsafe extern "C" fn(F),
    glVertexPointer: unsafe extern "C" fn(i32, E, i32, *const c_void),
    glNormalPointer: unsafe extern "C" fn(E, i32, *const c_void),
    glColorPointer: unsafe extern "C" fn(i32, E, i32, *const c_void),
    glEnableClientState: unsafe extern "C" fn(E),
    glDisableClientState: unsafe extern "C" fn(E),
    glDrawArrays: unsafe extern "C" fn(E, i32, i32),
    glDrawElements: unsafe extern "C" fn(E, i32, E, *const c_void),
    glGetFloatv: unsafe extern "C" fn(E, *mut F),
    glGetIntegerv: unsafe extern "C" fn(E, *mut i32),
    glIsEnabled: unsafe extern "C" fn(E) -> u8,
    glFrontFace: unsafe extern "C" fn(E),
    glCullFace: unsafe extern "C" fn(E),
    glSelectBuffer: unsafe extern "C" fn(i32, *mut u32),
    glInitNames: unsafe extern "C" fn(),
    glPushName: unsafe extern "C" fn(u32),
    glPopName: unsafe extern "C" fn(),
    glLoadName: unsafe extern "C" fn(u32),
    glGetLightfv: unsafe extern "C" fn(E, E, *mut F),
    glGetMaterialfv: unsafe extern "C" fn(E, E, *mut F),
    create: unsafe extern "C" fn() -> *mut c_void,
    destroy: unsafe extern "C" fn(*mut c_void),
}

struct Library {
    build: Build,
    gl: Gl,
    osmesa_make_current: Option<unsafe extern "C" fn(*mut c_void, *mut c_void, E, i32, i32) -> u8>,
}

fn open(path: &str) -> *mut c_void {
    let name = CString::new(path).unwrap();
    // SAFETY: a valid C string; RTLD_LOCAL keeps each library's symbols apart.
    let handle = unsafe { libc::dlopen(name.as_ptr(), libc::RTLD_NOW | libc::RTLD_LOCAL) };
    assert!(!handle.is_null(), "dlopen {path} failed");
    handle
}

fn symbol<T: Copy>(handle: *mut c_void, name: &str) -> T {
    let c = CString::new(name).unwrap();
    // SAFETY: a live handle.
    let p = unsafe { libc::dlsym(handle, c.as_ptr()) };
    assert!(!p.is_null(), "{name} not found");
    assert_eq!(size_of::<T>(), size_of::<*mut c_void>());
    // SAFETY: T is the function pointer type of `name`.
    unsafe { std::mem::transmute_copy(&p) }
}

// OSMesa: a context of its own per sequence, with a 64x64 buffer.
static mut OSMESA_BUFFER: [u8; 64 * 64 * 4] = [0; 64 * 64 * 4];
static mut OSMESA_CREATE: Option<
    unsafe extern "C" fn(E, i32, i32, i32, *mut c_void) -> *mut c_void,
> = None;
static mut OSMESA_DESTROY: Option<unsafe extern "C" fn(*mut c_void)> = None;

unsafe extern "C" fn osmesa_create() -> *mut c_void {
    // SAFETY: set once by `load` before any sequence runs, on this thread.
    unsafe {
        (OSMESA_CREATE.unwrap())(
            0x1908, /* OSMESA_RGBA */
            24,
            8,
            0,
            std::ptr::null_mut(),
        )
    }
}

unsafe extern "C" fn osmesa_destroy(ctx: *mut c_void) {
    // SAFETY: as above.
    unsafe { (OSMESA_DESTROY.unwrap())(ctx) }
}

fn libfflight_path() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let deps = exe.parent().unwrap();
    [
        deps.join("libfflight.so"),
        deps.parent().unwrap().join("libfflight.so"),
    ]
    .into_iter()
    .filter_map(|p| Some((std::fs::metadata(&p).ok()?.modified().ok()?, p)))
    .max()
    .map(|(_, p)| p)
    .expect("libfflight.so next to the test binary (crate-type cdylib)")
}

macro_rules! load_gl {
    ($h:expr, $create:expr, $destroy:expr, $($name:ident),*) => {
        Gl { $($name: symbol($h, stringify!($name)),)* create: $create, destroy: $destroy }
    };
}

fn load(build: Build) -> Library {
    let (handle, create, destroy, make_current): (
        _,
        unsafe extern "C" fn() -> *mut c_void,
        unsafe extern "C" fn(*mut c_void),
        _,
    ) = match build {
        Build::Osmesa => {
            let h = open("libOSMesa.so.8");
            // SAFETY: set before use, on this thread only.
            unsafe {
                OSMESA_CREATE = Some(symbol(h, "OSMesaCreateContextExt"));
                OSMESA_DESTROY = Some(symbol(h, "OSMesaDestroyContext"));
            }
            (
                h,
                osmesa_create as _,
                osmesa_destroy as _,
                Some(symbol(h, "OSMesaMakeCurrent")),
            )
        }
        Build::Fflight => {
            let h = open(libfflight_path().to_str().unwrap());
            let destroy: unsafe extern "C" fn(*mut c_void) -> u8 = symbol(h, "fflDestroyContext");
            // The harness ignores fflDestroyContext's result (a transmute of the return type).
            let destroy: unsafe extern "C" fn(*mut c_void) =
                    // SAFETY: the result is returned in a register the caller ignores.
                    unsafe { std::mem::transmute(destroy) };
            (h, symbol(h, "fflCreateContext"), destroy, None)
        }
    };
    let gl = load_gl!(
        handle,
        create,
        destroy,
        glEnable,
        glDisable,
        glLightfv,
        glMaterialfv,
        glLightModelfv,
        glColorMaterial,
        glMatrixMode,
        glLoadIdentity,
        glTranslatef,
        glRotatef,
        glScalef,
        glPushMatrix,
        glPopMatrix,
        glOrtho,
        glViewport,
        glColor4f,
        glNormal3f,
        glVertex3f,
        glBegin,
        glEnd,
        glGetError,
        glFeedbackBuffer,
        glRenderMode,
        glPassThrough,
        glVertexPointer,
        glNormalPointer,
        glColorPointer,
        glEnableClientState,
        glDisableClientState,
        glDrawArrays,
        glDrawElements,
        glGetFloatv,
        glGetIntegerv,
        glIsEnabled,
        glFrontFace,
        glCullFace,
        glSelectBuffer,
        glInitNames,
        glPushName,
        glPopName,
        glLoadName,
        glGetLightfv,
        glGetMaterialfv
    );
    let library = Library {
        build,
        gl,
        osmesa_make_current: make_current,
    };
    if build == Build::Fflight {
        let make: unsafe extern "C" fn(*mut c_void) -> u8 = symbol(handle, "fflMakeCurrent");
        FFL_MAKE_CURRENT.with(|m| m.set(Some(make)));
    }
    library
}

thread_local! {
    static FFL_MAKE_CURRENT: std::cell::Cell<Option<unsafe extern "C" fn(*mut c_void) -> u8>> =
        const { std::cell::Cell::new(None) };
}

// ---- the generator ----

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[self.below(v.len())]
    }
    fn uniform(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * ((self.next() >> 40) as f32 / (1u64 << 24) as f32)
    }
    fn vec4(&mut self, lo: f32, hi: f32) -> [f32; 4] {
        [
            self.uniform(lo, hi),
            self.uniform(lo, hi),
            self.uniform(lo, hi),
            self.uniform(lo, hi),
        ]
    }
}

const GL_LIGHTING: E = 0x0B50;
const GL_LIGHT0: E = 0x4000;
const GL_NORMALIZE: E = 0x0BA1;
const GL_RESCALE_NORMAL: E = 0x803A;
const GL_COLOR_MATERIAL: E = 0x0B57;
const GL_CULL_FACE: E = 0x0B44;
const GL_FRONT: E = 0x0404;
const GL_BACK: E = 0x0405;
const GL_FRONT_AND_BACK: E = 0x0408;
const GL_MODELVIEW: E = 0x1700;
const GL_PROJECTION: E = 0x1701;
const GL_FEEDBACK: E = 0x1C01;
const GL_RENDER: E = 0x1C00;
const GL_SELECT: E = 0x1C02;
const GL_3D_COLOR: E = 0x0602;
const GL_FLOAT: E = 0x1406;
const GL_UNSIGNED_BYTE: E = 0x1401;
const GL_UNSIGNED_SHORT: E = 0x1403;
const GL_UNSIGNED_INT: E = 0x1405;
const GL_VERTEX_ARRAY: E = 0x8074;
const GL_NORMAL_ARRAY: E = 0x8075;
const GL_COLOR_ARRAY: E = 0x8076;
const GL_CURRENT_COLOR: E = 0x0B00;
const GL_CURRENT_NORMAL: E = 0x0B02;
const GL_MODELVIEW_STACK_DEPTH: E = 0x0BA3;
const GL_PROJECTION_STACK_DEPTH: E = 0x0BA4;
const GL_CW: E = 0x0900;
const GL_CCW: E = 0x0901;

/// Light parameters with their value counts and ranges (clear of differences 7 and 8).
const LIGHT_PNAMES: [(E, usize, f32, f32); 10] = [
    (0x1200, 4, 0.0, 1.0),   // GL_AMBIENT
    (0x1201, 4, 0.0, 1.0),   // GL_DIFFUSE
    (0x1202, 4, 0.0, 1.0),   // GL_SPECULAR
    (0x1203, 4, -2.0, 2.0),  // GL_POSITION
    (0x1204, 3, -1.0, 1.0),  // GL_SPOT_DIRECTION
    (0x1205, 1, 1.0, 16.0),  // GL_SPOT_EXPONENT
    (0x1206, 1, 10.0, 90.0), // GL_SPOT_CUTOFF
    (0x1207, 1, 0.5, 2.0),   // GL_CONSTANT_ATTENUATION
    (0x1208, 1, 0.0, 0.5),   // GL_LINEAR_ATTENUATION
    (0x1209, 1, 0.0, 0.2),   // GL_QUADRATIC_ATTENUATION
];

const MATERIAL_PNAMES: [(E, usize, f32, f32); 6] = [
    (0x1200, 4, 0.0, 1.0),  // GL_AMBIENT
    (0x1201, 4, 0.0, 1.0),  // GL_DIFFUSE
    (0x1202, 4, 0.0, 1.0),  // GL_SPECULAR
    (0x1600, 4, 0.0, 0.5),  // GL_EMISSION
    (0x1601, 1, 1.0, 20.0), // GL_SHININESS
    (0x1602, 4, 0.0, 1.0),  // GL_AMBIENT_AND_DIFFUSE
];

/// Primitive modes without lines (difference 1).
const MODES: [E; 7] = [0x0000, 0x0004, 0x0005, 0x0006, 0x0007, 0x0008, 0x0009];

#[derive(Clone, Debug)]
enum Op {
    Enable(E, bool),
    Light(E, E, Vec<f32>),
    Material(E, E, Vec<f32>),
    LightModel(E, Vec<f32>),
    ColorMaterial(E, E),
    MatrixMode(E),
    LoadIdentity,
    /// glLoadIdentity and the ortho projection of `run` (in GL_PROJECTION mode).
    LoadOrtho,
    Translate([f32; 3]),
    Rotate([f32; 4]),
    Scale([f32; 3]),
    Push,
    Pop,
    Color([f32; 4]),
    Normal([f32; 3]),
    FrontFace(E),
    CullFace(E),
    /// glBegin(mode), vertices (color, normal, position), glEnd; `nest` adds a glBegin inside.
    Primitive(E, Vec<([f32; 4], [f32; 3], [f32; 3])>, bool),
    EndAlone,
    /// Enabled arrays (normals, colors), mode, first/count or indices of a type.
    Arrays {
        normals: bool,
        colors: bool,
        mode: E,
        elements: Option<(E, Vec<u32>)>,
        first: i32,
        count: i32,
    },
    /// glRenderMode(GL_RENDER): print the pass, start another.
    Flush,
    /// Leaves feedback for a selection pass into a buffer of `size` names, then back.
    Select(i32, Vec<Named>),
    Query,
}

/// What a selection pass does.
#[derive(Clone, Debug)]
enum Named {
    Push(u32),
    Pop,
    Load(u32),
    /// glPushName `n` times (past the stack's 64: GL_STACK_OVERFLOW).
    PushMany(u32),
    Primitive(E, Vec<([f32; 4], [f32; 3], [f32; 3])>),
}

/// Vertex data of the array draws: 64 vertices inside the view volume.
struct Arrays {
    positions: Vec<f32>,
    normals: Vec<f32>,
    colors: Vec<f32>,
}

fn arrays(rng: &mut Rng) -> Arrays {
    let mut a = Arrays {
        positions: vec![],
        normals: vec![],
        colors: vec![],
    };
    for _ in 0..64 {
        a.positions.extend((0..3).map(|_| rng.uniform(-0.5, 0.5)));
        a.normals.extend((0..3).map(|_| rng.uniform(-1.0, 1.0)));
        a.colors.extend((0..4).map(|_| rng.uniform(0.0, 1.0)));
    }
    a
}

fn vertex(rng: &mut Rng) -> ([f32; 4], [f32; 3], [f32; 3]) {
    let c = rng.vec4(0.0, 1.0);
    let n = [
        rng.uniform(-1.0, 1.0),
        rng.uniform(-1.0, 1.0),
        rng.uniform(-1.0, 1.0),
    ];
    let p = [
        rng.uniform(-0.5, 0.5),
        rng.uniform(-0.5, 0.5),
        rng.uniform(-0.5, 0.5),
    ];
    (c, n, p)
}

/// What the generator keeps track of: the modelview's transforms since an identity (at most
/// 3, so the geometry stays inside the view volume) and whether the projection matrix is the
/// current one (it is only ever the ortho of `run`, pushed and popped).
struct Shape {
    transforms: usize,
    projection: bool,
}

fn op(rng: &mut Rng, shape: &mut Shape) -> Op {
    let bad_enum = |rng: &mut Rng| rng.pick(&[0u32, 1, 0x1234, 0x4008, 0xFFFF_FFFF]);
    match rng.below(24) {
        0 | 1 => {
            let cap = rng.pick(&[
                GL_LIGHTING,
                GL_LIGHTING,
                GL_LIGHT0,
                GL_LIGHT0 + 1,
                GL_LIGHT0 + 7,
                GL_NORMALIZE,
                GL_RESCALE_NORMAL,
                GL_COLOR_MATERIAL,
                GL_CULL_FACE,
            ]);
            let cap = if rng.below(12) == 0 {
                bad_enum(rng)
            } else {
                cap
            };
            Op::Enable(cap, rng.below(4) != 0)
        }
        2 | 3 => {
            let (pname, n, lo, hi) = rng.pick(&LIGHT_PNAMES);
            // A material pname is no light pname (GL_INVALID_ENUM).
            let pname = if rng.below(20) == 0 { 0x1600 } else { pname };
            let light = if rng.below(16) == 0 {
                GL_LIGHT0 + 8
            } else {
                GL_LIGHT0 + rng.below(3) as E
            };
            let mut v: Vec<f32> = (0..n).map(|_| rng.uniform(lo, hi)).collect();
            if pname == 0x1203 {
                v[3] = rng.pick(&[0.0, 1.0]); // directional or positional
            }
            if pname == 0x1206 && rng.below(3) == 0 {
                v[0] = 180.0;
            }
            Op::Light(light, pname, v)
        }
        4 | 5 => {
            let (pname, n, lo, hi) = rng.pick(&MATERIAL_PNAMES);
            // A light pname is no material pname (GL_INVALID_ENUM).
            let pname = if rng.below(20) == 0 { 0x1205 } else { pname };
            let face = rng.pick(&[GL_FRONT, GL_BACK, GL_FRONT_AND_BACK, GL_FRONT_AND_BACK]);
            let face = if rng.below(16) == 0 {
                bad_enum(rng)
            } else {
                face
            };
            Op::Material(face, pname, (0..n).map(|_| rng.uniform(lo, hi)).collect())
        }
        6 => match rng.below(4) {
            0 => Op::LightModel(0x0B53, rng.vec4(0.0, 0.5).to_vec()), // GL_LIGHT_MODEL_AMBIENT
            1 => Op::LightModel(0x0B52, vec![rng.below(2) as f32]),   // GL_LIGHT_MODEL_TWO_SIDE
            2 => Op::LightModel(0x0B51, vec![rng.below(2) as f32]),   // GL_LIGHT_MODEL_LOCAL_VIEWER
            _ => Op::LightModel(0x81F8, vec![rng.pick(&[0x81F9u32, 0x81FA]) as f32]), // COLOR_CONTROL
        },
        7 => Op::Normal([
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
        ]),
        8 => Op::MatrixMode(match rng.below(8) {
            0 => bad_enum(rng),
            1 => {
                shape.projection = true;
                GL_PROJECTION
            }
            _ => {
                shape.projection = false;
                GL_MODELVIEW
            }
        }),
        9 if shape.projection => Op::LoadOrtho,
        9 => {
            shape.transforms = 0;
            Op::LoadIdentity
        }
        10 | 11 if shape.transforms < 3 && !shape.projection => {
            shape.transforms += 1;
            match rng.below(3) {
                0 => Op::Translate([
                    rng.uniform(-0.3, 0.3),
                    rng.uniform(-0.3, 0.3),
                    rng.uniform(-0.3, 0.3),
                ]),
                1 => Op::Rotate([
                    rng.uniform(-180.0, 180.0),
                    rng.uniform(-1.0, 1.0),
                    rng.uniform(-1.0, 1.0),
                    rng.uniform(0.1, 1.0),
                ]),
                _ => Op::Scale([
                    rng.uniform(0.5, 1.5),
                    rng.uniform(0.5, 1.5),
                    rng.uniform(0.5, 1.5),
                ]),
            }
        }
        12 => Op::Push,
        13 => {
            if !shape.projection {
                // The matrix popped may have had more transforms than the count says.
                shape.transforms = 3;
            }
            Op::Pop
        }
        14 => Op::Color(rng.vec4(0.0, 1.0)),
        15 => Op::Normal([
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
        ]),
        16 => match rng.below(2) {
            0 => Op::FrontFace(rng.pick(&[GL_CW, GL_CCW])),
            _ => Op::CullFace(rng.pick(&[GL_FRONT, GL_BACK, GL_FRONT_AND_BACK])),
        },
        17..=19 => {
            let mode = if rng.below(20) == 0 {
                0x000F
            } else {
                rng.pick(&MODES)
            };
            // glVertex outside glBegin/glEnd is undefined (§2.6.3): a glBegin that fails gets
            // no vertices.
            let n = if MODES.contains(&mode) {
                rng.below(10)
            } else {
                0
            };
            Op::Primitive(
                mode,
                (0..n).map(|_| vertex(rng)).collect(),
                rng.below(20) == 0,
            )
        }
        20 => {
            let mode = rng.pick(&MODES);
            let count = rng.below(20) as i32;
            let elements = (rng.below(2) == 0).then(|| {
                let kind = rng.pick(&[GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT]);
                // Distinct indices: a repeated one in a strip or fan makes a triangle of zero
                // area, whose two-sided lighting OSMesa gets wrong (difference 22).
                let mut indices: Vec<u32> = (0..64).collect();
                for i in 0..count as usize {
                    let j = i + rng.below(64 - i);
                    indices.swap(i, j);
                }
                indices.truncate(count as usize);
                (kind, indices)
            });
            let first = rng.below(64 - count as usize) as i32;
            // Invalid draws now and then: a negative count (GL_INVALID_VALUE), an index type
            // or a mode GL does not know (GL_INVALID_ENUM).
            let (mode, count, elements) = match rng.below(12) {
                0 => (mode, -1 - rng.below(3) as i32, elements),
                1 => (0x000F, count, elements),
                2 => (
                    mode,
                    count,
                    elements.map(|(_, indices)| (GL_FLOAT, indices)),
                ),
                _ => (mode, count, elements),
            };
            Op::Arrays {
                normals: rng.below(2) == 0,
                colors: rng.below(2) == 0,
                mode,
                elements,
                first,
                count,
            }
        }
        21 => {
            if rng.below(8) == 0 {
                Op::EndAlone
            } else {
                Op::Query
            }
        }
        22 => Op::Flush,
        23 if rng.below(2) == 0 => {
            let size = 1 + rng.below(40) as i32;
            let body = (0..1 + rng.below(12))
                .map(|_| match rng.below(7) {
                    0 => Named::Push(rng.below(100) as u32),
                    1 => Named::Pop,
                    2 => Named::Load(rng.below(100) as u32),
                    3 if rng.below(4) == 0 => Named::PushMany(60 + rng.below(10) as u32),
                    _ => {
                        let mode = rng.pick(&MODES);
                        let n = 1 + rng.below(8);
                        Named::Primitive(mode, (0..n).map(|_| vertex(rng)).collect())
                    }
                })
                .collect();
            Op::Select(size, body)
        }
        _ => Op::Query,
    }
}

fn sequence(seed: u64) -> (Vec<Op>, Arrays) {
    let mut rng = Rng(seed);
    let data = arrays(&mut rng);
    let mut shape = Shape {
        transforms: 0,
        projection: false,
    };
    let n = 10 + rng.below(60);
    // The color material face and mode are chosen once, before anything is tracked
    // (difference 23), and the shininess is at least 1 from the start (difference 7).
    let mut ops = vec![
        Op::ColorMaterial(
            rng.pick(&[GL_FRONT, GL_FRONT_AND_BACK]),
            rng.pick(&[0x1200, 0x1201, 0x1202, 0x1600, 0x1602]),
        ),
        Op::Material(GL_FRONT_AND_BACK, 0x1601, vec![rng.uniform(1.0, 20.0)]),
    ];
    for _ in 0..n {
        let next = op(&mut rng, &mut shape);
        let enables_color_material = matches!(next, Op::Enable(GL_COLOR_MATERIAL, true));
        ops.push(next);
        if enables_color_material {
            // A glColor after glEnable(GL_COLOR_MATERIAL): OSMesa does not give the tracked
            // properties the current color at the glEnable (difference 23).
            ops.push(Op::Color(rng.vec4(0.0, 1.0)));
        }
    }
    (ops, data)
}

// ---- running a sequence on one library ----

const FEEDBACK_SIZE: usize = 8192;

fn error_name(e: E) -> &'static str {
    match e {
        0 => "GL_NO_ERROR",
        0x0500 => "GL_INVALID_ENUM",
        0x0501 => "GL_INVALID_VALUE",
        0x0502 => "GL_INVALID_OPERATION",
        0x0503 => "GL_STACK_OVERFLOW",
        0x0504 => "GL_STACK_UNDERFLOW",
        _ => "GL_UNKNOWN_ERROR",
    }
}

fn pf(out: &mut String, label: &str, v: &[f32]) {
    write!(out, " {label}").unwrap();
    for &x in v {
        let x = if x == 0.0 { 0.0 } else { x };
        if x.is_nan() {
            out.push_str(" nan");
        } else {
            write!(out, " {:e}", x as f64).unwrap();
        }
    }
}

/// Prints a GL_3D_COLOR feedback pass the way ffl_print_feedback does.
fn print_feedback(out: &mut String, buf: &[f32], n: i32) {
    writeln!(out, "pass {n}").unwrap();
    let mut i = 0;
    let n = n.max(0) as usize;
    while i < n {
        let token = buf[i] as u32;
        i += 1;
        let (name, count) = match token {
            0x0700 => {
                writeln!(out, "fb pass {}", buf[i]).unwrap();
                i += 1;
                continue;
            }
            0x0701 => ("point", 1),
            0x0703 => {
                i += 1;
                ("polygon", buf[i - 1] as usize)
            }
            other => {
                writeln!(out, "fb token {other:#x}").unwrap();
                return;
            }
        };
        writeln!(out, "fb {name} {count}").unwrap();
        for _ in 0..count {
            if i + 7 > n {
                writeln!(out, "fb truncated").unwrap();
                return;
            }
            out.push_str("fb  v");
            pf(out, "xyz", &buf[i..i + 3]);
            pf(out, "rgba", &buf[i + 3..i + 7]);
            out.push('\n');
            i += 7;
        }
    }
}

/// Prints hit records the way ffl_print_hits does (depths labelled `zhit`), then what lies
/// past the buffer's size (nothing may be written there).
fn print_hits(out: &mut String, buf: &[u32], hits: i32, size: usize) {
    writeln!(out, "sel hits {hits}").unwrap();
    let (mut i, mut h) = (0, 0);
    while if hits < 0 { i < size } else { h < hits } {
        let names = buf[i] as usize;
        i += 1;
        write!(out, "sel hit names {names} zhit").unwrap();
        let mut k = 0;
        while k < 2 && i < size {
            write!(out, " {}", buf[i]).unwrap();
            i += 1;
            k += 1;
        }
        out.push_str(" stack");
        let mut k = 0;
        while k < names && i < size {
            write!(out, " {}", buf[i]).unwrap();
            i += 1;
            k += 1;
        }
        if k < names {
            out.push_str(" cut\n");
            return;
        }
        out.push('\n');
        h += 1;
    }
    writeln!(out, "sel guard {:?}", &buf[size..]).unwrap();
}

fn run(lib: &Library, ops: &[Op], data: &Arrays) -> String {
    let g = &lib.gl;
    let mut out = String::new();
    let mut feedback = vec![0f32; FEEDBACK_SIZE];
    // SAFETY: every pointer given to GL below points to live data of the size GL reads, and
    // the feedback buffer outlives the context.
    unsafe {
        reset(g);
        (g.glViewport)(0, 0, 64, 64);
        (g.glMatrixMode)(GL_PROJECTION);
        (g.glOrtho)(-6.0, 6.0, -6.0, 6.0, -6.0, 6.0);
        (g.glMatrixMode)(GL_MODELVIEW);
        (g.glVertexPointer)(3, GL_FLOAT, 0, data.positions.as_ptr().cast());
        (g.glNormalPointer)(GL_FLOAT, 0, data.normals.as_ptr().cast());
        (g.glColorPointer)(4, GL_FLOAT, 0, data.colors.as_ptr().cast());
        (g.glEnableClientState)(GL_VERTEX_ARRAY);
        (g.glFeedbackBuffer)(FEEDBACK_SIZE as i32, GL_3D_COLOR, feedback.as_mut_ptr());
        (g.glRenderMode)(GL_FEEDBACK);
        writeln!(out, "setup {}", error_name((g.glGetError)())).unwrap();
        let mut depth = 0;
        for (k, op) in ops.iter().enumerate() {
            match op {
                Op::Enable(cap, true) => (g.glEnable)(*cap),
                Op::Enable(cap, false) => (g.glDisable)(*cap),
                Op::Light(l, p, v) => (g.glLightfv)(*l, *p, v.as_ptr()),
                Op::Material(f, p, v) => (g.glMaterialfv)(*f, *p, v.as_ptr()),
                Op::LightModel(p, v) => (g.glLightModelfv)(*p, v.as_ptr()),
                Op::ColorMaterial(f, m) => (g.glColorMaterial)(*f, *m),
                Op::MatrixMode(m) => (g.glMatrixMode)(*m),
                Op::LoadIdentity => (g.glLoadIdentity)(),
                Op::LoadOrtho => {
                    (g.glLoadIdentity)();
                    (g.glOrtho)(-6.0, 6.0, -6.0, 6.0, -6.0, 6.0);
                }
                Op::Translate(v) => (g.glTranslatef)(v[0], v[1], v[2]),
                Op::Rotate(v) => (g.glRotatef)(v[0], v[1], v[2], v[3]),
                Op::Scale(v) => (g.glScalef)(v[0], v[1], v[2]),
                Op::Push => {
                    depth += 1;
                    (g.glPushMatrix)()
                }
                Op::Pop => {
                    depth -= 1;
                    (g.glPopMatrix)()
                }
                Op::Color(c) => (g.glColor4f)(c[0], c[1], c[2], c[3]),
                Op::Normal(n) => (g.glNormal3f)(n[0], n[1], n[2]),
                Op::FrontFace(m) => (g.glFrontFace)(*m),
                Op::CullFace(m) => (g.glCullFace)(*m),
                Op::Primitive(mode, vertices, nest) => {
                    (g.glPassThrough)(k as f32);
                    (g.glBegin)(*mode);
                    for (i, (c, n, p)) in vertices.iter().enumerate() {
                        if *nest && i == 1 {
                            (g.glBegin)(*mode);
                        }
                        (g.glColor4f)(c[0], c[1], c[2], c[3]);
                        (g.glNormal3f)(n[0], n[1], n[2]);
                        (g.glVertex3f)(p[0], p[1], p[2]);
                    }
                    (g.glEnd)();
                }
                Op::EndAlone => (g.glEnd)(),
                Op::Arrays {
                    normals,
                    colors,
                    mode,
                    elements,
                    first,
                    count,
                } => {
                    let set = |on: bool, array: E| {
                        if on {
                            (g.glEnableClientState)(array)
                        } else {
                            (g.glDisableClientState)(array)
                        }
                    };
                    set(*normals, GL_NORMAL_ARRAY);
                    set(*colors, GL_COLOR_ARRAY);
                    (g.glPassThrough)(k as f32);
                    match elements {
                        None => (g.glDrawArrays)(*mode, *first, *count),
                        Some((kind, indices)) => {
                            let bytes: Vec<u8> = match *kind {
                                GL_UNSIGNED_BYTE => indices.iter().map(|&i| i as u8).collect(),
                                GL_UNSIGNED_SHORT => indices
                                    .iter()
                                    .flat_map(|&i| (i as u16).to_ne_bytes())
                                    .collect(),
                                _ => indices.iter().flat_map(|&i| i.to_ne_bytes()).collect(),
                            };
                            (g.glDrawElements)(*mode, *count, *kind, bytes.as_ptr().cast());
                        }
                    }
                }
                Op::Flush => {
                    let n = (g.glRenderMode)(GL_RENDER);
                    print_feedback(&mut out, &feedback, n);
                    (g.glRenderMode)(GL_FEEDBACK);
                }
                Op::Select(size, body) => {
                    let n = (g.glRenderMode)(GL_RENDER);
                    print_feedback(&mut out, &feedback, n);
                    let mut names = vec![0xdead_beef_u32; *size as usize + 8];
                    (g.glSelectBuffer)(*size, names.as_mut_ptr());
                    (g.glRenderMode)(GL_SELECT);
                    (g.glInitNames)();
                    for (i, named) in body.iter().enumerate() {
                        match named {
                            Named::Push(name) => (g.glPushName)(*name),
                            Named::Pop => (g.glPopName)(),
                            Named::Load(name) => (g.glLoadName)(*name),
                            Named::PushMany(count) => (0..*count).for_each(|n| (g.glPushName)(n)),
                            Named::Primitive(mode, vertices) => {
                                (g.glBegin)(*mode);
                                for (_, _, p) in vertices {
                                    (g.glVertex3f)(p[0], p[1], p[2]);
                                }
                                (g.glEnd)();
                            }
                        }
                        writeln!(out, "s{i} {}", error_name((g.glGetError)())).unwrap();
                    }
                    let hits = (g.glRenderMode)(GL_RENDER);
                    print_hits(&mut out, &names, hits, *size as usize);
                    (g.glRenderMode)(GL_FEEDBACK);
                }
                Op::Query => {
                    let mut v = [-7.0f32; 16];
                    (g.glGetFloatv)(0x0BA6, v.as_mut_ptr()); // GL_MODELVIEW_MATRIX
                    out.push_str("q modelview");
                    pf(&mut out, "m", &v);
                    out.push('\n');
                    (g.glGetLightfv)(GL_LIGHT0 + 1, 0x1203, v.as_mut_ptr()); // GL_POSITION
                    out.push_str("q light1");
                    pf(&mut out, "position", &v[..4]);
                    (g.glGetLightfv)(GL_LIGHT0 + 1, 0x1204, v.as_mut_ptr()); // GL_SPOT_DIRECTION
                    pf(&mut out, "direction", &v[..3]);
                    out.push('\n');
                    for face in [GL_FRONT, GL_BACK] {
                        write!(out, "q material {face:#x}").unwrap();
                        for pname in [0x1200, 0x1201, 0x1202, 0x1600, 0x1601] {
                            (g.glGetMaterialfv)(face, pname, v.as_mut_ptr());
                            let n = if pname == 0x1601 { 1 } else { 4 };
                            pf(&mut out, &format!("p{pname:x}"), &v[..n]);
                        }
                        out.push('\n');
                    }
                    (g.glGetFloatv)(GL_CURRENT_COLOR, v.as_mut_ptr());
                    out.push_str("q color");
                    pf(&mut out, "rgba", &v[..4]);
                    (g.glGetFloatv)(GL_CURRENT_NORMAL, v.as_mut_ptr());
                    pf(&mut out, "n", &v[..3]);
                    let mut d = [-7i32; 2];
                    (g.glGetIntegerv)(GL_MODELVIEW_STACK_DEPTH, d.as_mut_ptr());
                    (g.glGetIntegerv)(GL_PROJECTION_STACK_DEPTH, d[1..].as_mut_ptr());
                    write!(out, " depth i {} {}", d[0], d[1]).unwrap();
                    for cap in [
                        GL_LIGHTING,
                        GL_LIGHT0,
                        GL_LIGHT0 + 1,
                        GL_NORMALIZE,
                        GL_COLOR_MATERIAL,
                        GL_CULL_FACE,
                    ] {
                        write!(out, " {}", (g.glIsEnabled)(cap)).unwrap();
                    }
                    out.push('\n');
                }
            }
            writeln!(out, "c{k} {}", error_name((g.glGetError)())).unwrap();
        }
        let _ = depth;
        let n = (g.glRenderMode)(GL_RENDER);
        print_feedback(&mut out, &feedback, n);
        writeln!(out, "end {}", error_name((g.glGetError)())).unwrap();
    }
    out
}

/// Creates the library's context and makes it current: one context serves every sequence
/// (OSMesa compiles a vertex program per lighting state and caches it in the context; a
/// new context per sequence spends most of the time compiling the same programs again).
fn start(lib: &Library) -> *mut c_void {
    // SAFETY: the library's own context calls, with a live 64x64 buffer for OSMesa.
    unsafe {
        let ctx = (lib.gl.create)();
        assert!(!ctx.is_null());
        match lib.osmesa_make_current {
            Some(make) => {
                let buffer = (&raw mut OSMESA_BUFFER).cast::<c_void>();
                assert_eq!(make(ctx, buffer, 0x1401, 64, 64), 1);
            }
            None => {
                FFL_MAKE_CURRENT.with(|m| m.get().unwrap()(ctx));
            }
        }
        ctx
    }
}

fn stop(lib: &Library, ctx: *mut c_void) {
    // SAFETY: the context `start` made; fflight's is released first.
    unsafe {
        if lib.build == Build::Fflight {
            FFL_MAKE_CURRENT.with(|m| m.get().unwrap()(std::ptr::null_mut()));
        }
        (lib.gl.destroy)(ctx);
    }
}

/// Puts back GL's initial values of everything a sequence may change (§6.2's tables), so each
/// sequence starts from the state of a new context.
///
/// # Safety
/// The library's context is current; no glBegin is open (every sequence closes its own).
unsafe fn reset(g: &Gl) {
    const GL_AMBIENT: E = 0x1200;
    const GL_AMBIENT_AND_DIFFUSE: E = 0x1602;
    // SAFETY: plain values and pointers to arrays of the sizes each pname reads.
    unsafe {
        for cap in [
            GL_LIGHTING,
            GL_NORMALIZE,
            GL_RESCALE_NORMAL,
            GL_COLOR_MATERIAL,
            GL_CULL_FACE,
        ] {
            (g.glDisable)(cap);
        }
        for light in 0..8 {
            (g.glDisable)(GL_LIGHT0 + light);
        }
        for (mode, depth_pname) in [
            (GL_PROJECTION, GL_PROJECTION_STACK_DEPTH),
            (GL_MODELVIEW, GL_MODELVIEW_STACK_DEPTH),
        ] {
            (g.glMatrixMode)(mode);
            let mut depth = 0;
            (g.glGetIntegerv)(depth_pname, &mut depth);
            for _ in 1..depth {
                (g.glPopMatrix)();
            }
            (g.glLoadIdentity)();
        }
        let none = [0.0, 0.0, 0.0, 1.0];
        let white = [1.0; 4];
        for light in 0..3 {
            let lit = if light == 0 { white } else { none };
            (g.glLightfv)(GL_LIGHT0 + light, GL_AMBIENT, none.as_ptr());
            (g.glLightfv)(GL_LIGHT0 + light, 0x1201, lit.as_ptr());
            (g.glLightfv)(GL_LIGHT0 + light, 0x1202, lit.as_ptr());
            (g.glLightfv)(GL_LIGHT0 + light, 0x1203, [0.0, 0.0, 1.0, 0.0].as_ptr());
            (g.glLightfv)(GL_LIGHT0 + light, 0x1204, [0.0, 0.0, -1.0].as_ptr());
            for (pname, value) in [
                (0x1205, 0.0),
                (0x1206, 180.0),
                (0x1207, 1.0),
                (0x1208, 0.0),
                (0x1209, 0.0),
            ] {
                (g.glLightfv)(GL_LIGHT0 + light, pname, &value);
            }
        }
        (g.glMaterialfv)(GL_FRONT_AND_BACK, GL_AMBIENT, [0.2, 0.2, 0.2, 1.0].as_ptr());
        (g.glMaterialfv)(GL_FRONT_AND_BACK, 0x1201, [0.8, 0.8, 0.8, 1.0].as_ptr());
        (g.glMaterialfv)(GL_FRONT_AND_BACK, 0x1202, none.as_ptr());
        (g.glMaterialfv)(GL_FRONT_AND_BACK, 0x1600, none.as_ptr());
        (g.glMaterialfv)(GL_FRONT_AND_BACK, 0x1601, &0.0);
        (g.glLightModelfv)(0x0B53, [0.2, 0.2, 0.2, 1.0].as_ptr());
        (g.glLightModelfv)(0x0B52, &0.0);
        (g.glLightModelfv)(0x0B51, &0.0);
        (g.glLightModelfv)(0x81F8, &(0x81F9 as f32));
        (g.glColorMaterial)(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
        (g.glColor4f)(1.0, 1.0, 1.0, 1.0);
        (g.glNormal3f)(0.0, 0.0, 1.0);
        (g.glFrontFace)(GL_CCW);
        (g.glCullFace)(GL_BACK);
        (g.glDisableClientState)(GL_NORMAL_ARRAY);
        (g.glDisableClientState)(GL_COLOR_ARRAY);
        while (g.glGetError)() != 0 {}
    }
}

/// Runs `count` sequences from `first`; returns (differing seeds with their report, stats).
fn fuzz(first: u64, count: u64) -> (Vec<(u64, String)>, MaxDiff) {
    let fflight = load(Build::Fflight);
    let osmesa = load(Build::Osmesa);
    let mut stats = MaxDiff::default();
    let mut differences = Vec::new();
    let (fflight_context, osmesa_context) = (start(&fflight), start(&osmesa));
    for seed in first..first + count {
        let (ops, data) = sequence(seed);
        let a = run(&fflight, &ops, &data);
        let b = run(&osmesa, &ops, &data);
        if std::env::var("FFL_OSMESA_DUMP").is_ok_and(|s| s == seed.to_string()) {
            let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/osmesa_fuzz");
            std::fs::create_dir_all(&dir).unwrap();
            std::fs::write(dir.join(format!("{seed}.fflight")), &a).unwrap();
            std::fs::write(dir.join(format!("{seed}.osmesa")), &b).unwrap();
        }
        let mut report = Report::new(&format!("seed {seed}"));
        check_differential(&mut report, &a, &b, &mut stats);
        if !report.failures.is_empty() {
            let mut text = report
                .failures
                .iter()
                .take(3)
                .cloned()
                .collect::<Vec<_>>()
                .join("\n");
            for (k, op) in ops.iter().enumerate() {
                write!(text, "\n  c{k}: {op:?}").unwrap();
            }
            differences.push((seed, text));
        }
    }
    stop(&fflight, fflight_context);
    stop(&osmesa, osmesa_context);
    (differences, stats)
}

/// `FFL_OSMESA_MINIMIZE=<seed>`: drops the calls of a differing sequence one at a time while
/// the outputs still differ, and prints what is left (to find a difference's cause).
#[test]
fn minimize_a_difference() {
    let Some(seed) = std::env::var("FFL_OSMESA_MINIMIZE")
        .ok()
        .and_then(|s| s.parse().ok())
    else {
        return;
    };
    let (fflight, osmesa) = (load(Build::Fflight), load(Build::Osmesa));
    let contexts = (start(&fflight), start(&osmesa));
    let (mut ops, data) = sequence(seed);
    let differs = |ops: &[Op]| {
        let mut report = Report::new("minimize");
        let (a, b) = (run(&fflight, ops, &data), run(&osmesa, ops, &data));
        check_differential(&mut report, &a, &b, &mut MaxDiff::default());
        (!report.failures.is_empty()).then(|| report.failures[0].clone())
    };
    assert!(differs(&ops).is_some(), "seed {seed} does not differ");
    let mut i = 0;
    while i < ops.len() {
        let mut fewer = ops.clone();
        fewer.remove(i);
        if differs(&fewer).is_some() {
            ops = fewer;
        } else {
            i += 1;
        }
    }
    println!(
        "seed {seed}, {} calls left: {}",
        ops.len(),
        differs(&ops).unwrap()
    );
    for (k, op) in ops.iter().enumerate() {
        println!("  {k}: {op:?}");
    }
    stop(&fflight, contexts.0);
    stop(&osmesa, contexts.1);
}

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// The fixed seeds of `cargo test` (60 sequences, about 20 s in a debug build), or `FFL_OSMESA_SEQUENCES` of them.
#[test]
fn fflight_agrees_with_osmesa_on_random_sequences() {
    if std::env::var_os("FFL_NO_OSMESA").is_some_and(|v| v == "1") {
        return; // as tests/c_programs.rs: only the fflight builds are checked
    }
    let first = env_u64("FFL_OSMESA_FIRST_SEED", 0);
    let count = env_u64("FFL_OSMESA_SEQUENCES", 60);
    let start = std::time::Instant::now();
    let (differences, stats) = fuzz(first, count);
    println!(
        "osmesa-fuzz: {count} sequences (seeds {first}..{}), {} with an unexplained difference {:?}, \
         {:.1} s; {}",
        first + count,
        differences.len(),
        differences.iter().map(|d| d.0).collect::<Vec<_>>(),
        start.elapsed().as_secs_f64(),
        summarize(&stats)
    );
    for (seed, text) in differences.iter().take(5) {
        println!("seed {seed}:\n{text}\n");
    }
    assert!(
        differences.is_empty(),
        "{} sequences differ",
        differences.len()
    );
}
