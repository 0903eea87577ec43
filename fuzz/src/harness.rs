//! The coverage-guided fuzz target of the C ABI: an input is decoded into a sequence of calls
//! over every function `include/fflight.h` exports (the table `calls.rs` is generated from
//! the header), with contexts created, made current and destroyed, and after each call the
//! invariants fflight promises are checked:
//!
//! - no Rust panic (the panic hook aborts: fflight's guard would otherwise hide it);
//! - glGetError returns a GL error code;
//! - outside glBegin/glEnd, the matrix, attribute and name stack depths are within 1 and
//!   their queried maxima (0 for the attribute and name stacks), the render and matrix modes
//!   and the active texture units are valid, the current raster colors are in [0, 1], and the
//!   queries themselves raise no error;
//! - fflGetCurrentContext is the context the harness made current;
//! - feedback and selection never write past the size given to glFeedbackBuffer /
//!   glSelectBuffer (the buffers are followed by a guard, and what lies past the size is
//!   checked after every call), and what glRenderMode says was written parses: known tokens,
//!   fed-back colors in [0, 1], hit records with at most 64 names and min z <= max z;
//! - captured vertices read with fflCaptureReadVertices have colors in [0, 1].
//!
//! Every integer that sizes what GL reads or writes through a pointer is kept small, and every
//! pointer points into a large arena, so the harness always gives GL the memory a correct C
//! caller would: a crash is fflight's.
//!
//! This file is shared by the fuzz target (`fuzz/fuzz_targets/capi_calls.rs`) and by the
//! replay of the seed corpus and the regressions in `cargo test` (`tests/fuzz_replay.rs`).

#![allow(dead_code, non_snake_case)]

use std::ffi::c_void;
use std::sync::OnceLock;
use std::sync::atomic::{AtomicBool, Ordering};

use fflight::gl::*;

include!("calls.rs");

/// How an integer argument is decoded (see `generate.rs`).
#[derive(Clone, Copy)]
pub enum IntClass {
    /// Image sizes, evaluator orders and grid bounds: -2 to 32.
    Dimension,
    /// Counts and sizes of buffers: -2 to 4096.
    Count,
    /// Strides: -2 to 256.
    Stride,
    /// Anything.
    Any,
}

/// Where a `const T *` argument points.
#[derive(Clone, Copy, PartialEq)]
pub enum Region {
    Floats,
    Doubles,
    Fixed,
    Ints,
    Shorts,
    Bytes,
    /// Pointers to index data (glMultiDrawElements' `indices`).
    Pointers,
    /// Any region, the fuzz-written data included.
    Any,
}

// ---- the arena ----

const KIB: usize = 1024;
const REGION: usize = 64 * KIB;
/// Input regions, in this order from offset 0: floats, doubles, fixed, ints, shorts, bytes,
/// pointers, data (written by the input).
const INPUT_REGIONS: usize = 8;
const DATA: usize = 7 * REGION;
const OUTPUT_BASE: usize = 1024 * KIB;
const OUTPUT_SLOT: usize = 1024 * KIB;
const OUTPUT_SLOTS: usize = 24;
/// The arena proper: input regions and output slots.
const ARENA_USED: usize = OUTPUT_BASE + OUTPUT_SLOTS * OUTPUT_SLOT;
/// The whole mapping: 2 TiB of address space reserved without memory (MAP_NORESERVE), so
/// that every read GL may make from the harness's pointers lands in mapped memory, whatever
/// index a draw reads through an element buffer the input filled (4G indices times a stride
/// of 256 bytes): reading a page never written costs no memory.
const ARENA_BYTES: usize = 2 << 40;

struct Arena(*mut u8);
// SAFETY: the arena is only ever used by the fuzzing thread; the pointer is just an address.
unsafe impl Send for Arena {}
unsafe impl Sync for Arena {}

fn arena() -> *mut u8 {
    static ARENA: OnceLock<Arena> = OnceLock::new();
    ARENA
        .get_or_init(|| {
            // SAFETY: a new private anonymous mapping; nothing else refers to it.
            let base = unsafe {
                libc::mmap(
                    std::ptr::null_mut(),
                    ARENA_BYTES,
                    libc::PROT_READ | libc::PROT_WRITE,
                    libc::MAP_PRIVATE | libc::MAP_ANONYMOUS | libc::MAP_NORESERVE,
                    -1,
                    0,
                )
            };
            assert!(base != libc::MAP_FAILED, "mmap of the fuzz arena failed");
            let base = base.cast::<u8>();
            // SAFETY: `base` has ARENA_BYTES bytes; each region is written within its bounds.
            unsafe { fill_input_regions(base) };
            Arena(base)
        })
        .0
}

/// Gives back the pages an input touched past the arena proper (page tables included).
fn release_far_pages() {
    // SAFETY: inside the mapping; its contents there are never relied on.
    unsafe {
        libc::madvise(
            arena().add(ARENA_USED).cast(),
            ARENA_BYTES - ARENA_USED,
            libc::MADV_DONTNEED,
        );
    }
}

/// Interesting floats (mostly ordinary, some GL boundaries, huge, tiny, NaN and infinities).
const SPECIAL_FLOATS: [f32; 24] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    2.0,
    -2.0,
    0.25,
    90.0,
    180.0,
    128.0,
    129.0,
    1e-30,
    -1e-30,
    1e20,
    -1e20,
    f32::MAX,
    -f32::MAX,
    f32::MIN_POSITIVE,
    1e-45,
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    3.0,
];

/// # Safety
/// `base` points to the arena.
unsafe fn fill_input_regions(base: *mut u8) {
    let mut state = 0x1234_5678_9abc_def0_u64;
    let mut next = || {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    };
    // SAFETY: every write below stays inside its region of the arena.
    unsafe {
        let floats = base.cast::<f32>();
        for i in 0..REGION / 4 {
            let r = next();
            let v = if i % 16 == 15 {
                SPECIAL_FLOATS[(r % 24) as usize]
            } else {
                ((r >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0) as f32
            };
            *floats.add(i) = v;
        }
        let doubles = base.add(REGION).cast::<f64>();
        for i in 0..REGION / 8 {
            *doubles.add(i) = *floats.add(i) as f64;
        }
        let fixed = base.add(2 * REGION).cast::<i32>();
        for i in 0..REGION / 4 {
            let v = *floats.add(i);
            *fixed.add(i) = if v.is_finite() && v.abs() < 30000.0 {
                (v * 65536.0) as i32
            } else {
                next() as i32
            };
        }
        let ints = base.add(3 * REGION).cast::<u32>();
        for i in 0..REGION / 4 {
            let r = next();
            *ints.add(i) = (r % 64) as u32;
        }
        let shorts = base.add(4 * REGION).cast::<u16>();
        for i in 0..REGION / 2 {
            let r = next();
            *shorts.add(i) = (r % 64) as u16;
        }
        let bytes = base.add(5 * REGION);
        for i in 0..REGION {
            *bytes.add(i) = next() as u8;
        }
        // Pointers to index data: ints, shorts and bytes at varied offsets.
        let pointers = base.add(6 * REGION).cast::<usize>();
        for i in 0..REGION / 8 {
            let region = 3 + (i % 3);
            let offset = (next() as usize % 256) * 4;
            *pointers.add(i) = base.add(region * REGION + offset) as usize;
        }
    }
}

// ---- feedback and selection buffers: a slot per context ----

/// Values glFeedbackBuffer and glSelectBuffer may be given.
const BUFFER_CAPACITY: usize = 4096;
/// Values after the capacity that nothing may write.
const GUARD: usize = 64;
const FEEDBACK_SENTINEL: u32 = 0x7fc0_dead; // a NaN fflight never writes (it writes 0x7fc00000)
const SELECT_SENTINEL: u32 = 0xdead_beef;

static FEEDBACK_FILL: [u32; BUFFER_CAPACITY + GUARD] = [FEEDBACK_SENTINEL; BUFFER_CAPACITY + GUARD];
static SELECT_FILL: [u32; BUFFER_CAPACITY + GUARD] = [SELECT_SENTINEL; BUFFER_CAPACITY + GUARD];

/// The harness keeps at most this many contexts (slot 0 is the base context of the input).
const SLOTS: usize = 4;

struct Slot {
    handle: *mut c_void,
    feedback: Box<[u32]>,
    /// Size and type of the feedback buffer in force, once glFeedbackBuffer succeeded.
    feedback_in_force: Option<(usize, GLenum)>,
    select: Box<[u32]>,
    select_in_force: Option<usize>,
}

impl Slot {
    fn new(handle: *mut c_void) -> Slot {
        Slot {
            handle,
            feedback: vec![FEEDBACK_SENTINEL; BUFFER_CAPACITY + GUARD].into_boxed_slice(),
            feedback_in_force: None,
            select: vec![SELECT_SENTINEL; BUFFER_CAPACITY + GUARD].into_boxed_slice(),
            select_in_force: None,
        }
    }
}

/// How an input ended: normally, or with a broken invariant (the message).
pub type Outcome = Result<(), String>;

/// The decoder and checker of one input.
pub struct Harness<'a> {
    data: &'a [u8],
    pos: usize,
    slots: Vec<Slot>,
    current: usize,
    failure: Option<String>,
    /// The name of the call being made, for messages.
    calling: &'static str,
    maxima: [i32; 5],
    /// How many glCallList / glCallLists each list being compiled got (by GL_LIST_INDEX).
    list_calls: Vec<(i32, u32)>,
    /// How many calls were made.
    pub calls: usize,
}

/// Harness operations besides the functions of the table.
const EXTRA_OPS: usize = 3;

impl<'a> Harness<'a> {
    // ---- decoding ----

    pub fn byte(&mut self) -> u8 {
        let b = self.data.get(self.pos).copied().unwrap_or(0);
        self.pos += 1;
        b
    }

    fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.byte(), self.byte()])
    }

    fn u32(&mut self) -> u32 {
        u32::from_le_bytes([self.byte(), self.byte(), self.byte(), self.byte()])
    }

    fn exhausted(&self) -> bool {
        self.pos >= self.data.len()
    }

    /// A GLenum: a value of the header's (most of the time) or any 4 bytes.
    pub fn enumeration(&mut self) -> GLenum {
        let tag = self.byte();
        match tag % 8 {
            0 => self.u32(),
            1 => tag as u32 >> 3,
            _ => ENUMS[self.u16() as usize % ENUMS.len()],
        }
    }

    pub fn integer(&mut self, class: IntClass) -> i64 {
        let tag = self.byte();
        let limit = match class {
            IntClass::Dimension => 32,
            IntClass::Count => BUFFER_CAPACITY as i64,
            IntClass::Stride => 256,
            IntClass::Any => i64::MAX,
        };
        let value = match tag % 8 {
            0..=3 => (tag >> 3) as i64 - 2,
            4 => self.u16() as i64,
            5 => match tag >> 3 {
                0 => i32::MAX as i64,
                1 => i32::MIN as i64,
                2 => u32::MAX as i64,
                3 => -1,
                4 => 65536,
                5 => i64::MAX,
                6 => i64::MIN,
                _ => self.u32() as i32 as i64,
            },
            6 => ENUMS[self.u16() as usize % ENUMS.len()] as i64,
            _ => self.u32() as i32 as i64,
        };
        if value > limit || (limit != i64::MAX && value < -2) {
            // Out of range for a size: fold it into [-2, limit].
            value.rem_euclid(limit + 3) - 2
        } else {
            value
        }
    }

    pub fn float(&mut self) -> f32 {
        let tag = self.byte();
        match tag % 4 {
            0 | 1 => SPECIAL_FLOATS[(tag >> 2) as usize % SPECIAL_FLOATS.len()],
            2 => (tag >> 2) as f32 / 8.0 - 4.0,
            _ => f32::from_bits(self.u32()),
        }
    }

    pub fn double(&mut self) -> f64 {
        let tag = self.byte();
        match tag % 8 {
            0 => f64::from_bits(self.u32() as u64 | (self.u32() as u64) << 32),
            1 => [1e300, -1e300, f64::MIN_POSITIVE, 5e-324][(tag >> 3) as usize % 4],
            _ => {
                self.pos -= 1;
                self.float() as f64
            }
        }
    }

    pub fn bitfield(&mut self) -> GLbitfield {
        match self.byte() % 4 {
            0 => self.u32(),
            1 => GL_ALL_ATTRIB_BITS,
            _ => 1 << (self.byte() % 32),
        }
    }

    /// A pointer for a command to read from (NULL one time in 32).
    pub fn input_pointer(&mut self, region: Region) -> *const c_void {
        let tag = self.byte();
        if tag.is_multiple_of(32) {
            return std::ptr::null();
        }
        let region = match region {
            Region::Floats => 0,
            Region::Doubles => 1,
            Region::Fixed => 2,
            Region::Ints => 3,
            Region::Shorts => 4,
            Region::Bytes => 5,
            Region::Pointers => 6,
            Region::Any => (tag as usize >> 5) % INPUT_REGIONS,
        };
        let offset = self.byte() as usize * 8;
        // SAFETY: inside the arena.
        unsafe { arena().add(region * REGION + offset) as *const c_void }
    }

    /// A pointer for a command to write to: parameter `index` has its own slot, so no two
    /// outputs of a call overlap (NULL one time in 64).
    pub fn output_pointer(&mut self, index: usize) -> *mut c_void {
        if self.byte().is_multiple_of(64) {
            return std::ptr::null_mut();
        }
        // SAFETY: inside the arena.
        unsafe { arena().add(OUTPUT_BASE + (index % OUTPUT_SLOTS) * OUTPUT_SLOT) as *mut c_void }
    }

    // ---- checking ----

    fn fail(&mut self, what: String) {
        if self.failure.is_none() {
            self.failure = Some(format!("call {} ({}): {what}", self.calls, self.calling));
        }
    }

    /// glGetError, which must return a GL error code.
    fn error(&mut self) -> GLenum {
        // SAFETY: no arguments.
        let error = unsafe { glGetError() };
        let known = [
            GL_NO_ERROR,
            GL_INVALID_ENUM,
            GL_INVALID_VALUE,
            GL_INVALID_OPERATION,
            GL_STACK_OVERFLOW,
            GL_STACK_UNDERFLOW,
            GL_OUT_OF_MEMORY,
            GL_TABLE_TOO_LARGE,
        ];
        if !known.contains(&error) {
            self.fail(format!("glGetError returned {error:#x}"));
        }
        error
    }

    fn get_ints<const N: usize>(&mut self, pname: GLenum) -> [i32; N] {
        let mut v = [i32::MIN; 16];
        // SAFETY: 16 values of room, more than any pname returns.
        unsafe { glGetIntegerv(pname, v.as_mut_ptr()) };
        let mut out = [0; N];
        out.copy_from_slice(&v[..N]);
        out
    }

    fn get_floats<const N: usize>(&mut self, pname: GLenum) -> [f32; N] {
        let mut v = [f32::NAN; 16];
        // SAFETY: 16 values of room.
        unsafe { glGetFloatv(pname, v.as_mut_ptr()) };
        let mut out = [0.0; N];
        out.copy_from_slice(&v[..N]);
        out
    }

    /// The queried state (outside glBegin/glEnd) within its documented ranges.
    fn check_state(&mut self) {
        let [mode] = self.get_ints::<1>(GL_RENDER_MODE);
        if mode == i32::MIN {
            // Nothing written: between glBegin and glEnd, where queries (glGetError too)
            // are errors; nothing else to look at.
            self.error();
            return;
        }
        if ![GL_RENDER, GL_FEEDBACK, GL_SELECT].contains(&(mode as GLenum)) {
            self.fail(format!("GL_RENDER_MODE {mode:#x}"));
        }
        let stacks = [
            (GL_MODELVIEW_STACK_DEPTH, 1, self.maxima[0]),
            (GL_PROJECTION_STACK_DEPTH, 1, self.maxima[1]),
            (GL_TEXTURE_STACK_DEPTH, 1, self.maxima[2]),
            (GL_COLOR_MATRIX_STACK_DEPTH, 1, self.maxima[3]),
            (GL_ATTRIB_STACK_DEPTH, 0, self.maxima[4]),
            (GL_CLIENT_ATTRIB_STACK_DEPTH, 0, 16),
            (GL_NAME_STACK_DEPTH, 0, 64),
        ];
        for (pname, low, high) in stacks {
            let [depth] = self.get_ints::<1>(pname);
            if depth < low || depth > high {
                self.fail(format!(
                    "stack depth {pname:#x} = {depth}, not in [{low}, {high}]"
                ));
            }
        }
        let [matrix_mode] = self.get_ints::<1>(GL_MATRIX_MODE);
        if ![GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE, GL_COLOR].contains(&(matrix_mode as GLenum)) {
            self.fail(format!("GL_MATRIX_MODE {matrix_mode:#x}"));
        }
        for pname in [GL_ACTIVE_TEXTURE, GL_CLIENT_ACTIVE_TEXTURE] {
            let [unit] = self.get_ints::<1>(pname);
            if !(GL_TEXTURE0 as i32..GL_TEXTURE0 as i32 + 8).contains(&unit) {
                self.fail(format!("texture unit {pname:#x} = {unit:#x}"));
            }
        }
        for pname in [GL_CURRENT_RASTER_COLOR, GL_CURRENT_RASTER_SECONDARY_COLOR] {
            let color = self.get_floats::<4>(pname);
            if !color.iter().all(|c| (0.0..=1.0).contains(c)) {
                self.fail(format!(
                    "raster color {pname:#x} = {color:?} outside [0, 1]"
                ));
            }
        }
        let [size] = self.get_ints::<1>(GL_FEEDBACK_BUFFER_SIZE);
        let [select_size] = self.get_ints::<1>(GL_SELECTION_BUFFER_SIZE);
        if size < 0 || select_size < 0 {
            self.fail(format!("buffer sizes {size}, {select_size}"));
        }
        let error = self.error();
        if error != GL_NO_ERROR {
            self.fail(format!("the state queries raised {error:#x}"));
        }
    }

    /// Nothing written past the feedback and selection sizes in force, nor into the guards.
    fn check_buffers(&mut self) {
        let slot = &self.slots[self.current];
        let feedback_size = slot.feedback_in_force.map_or(0, |(size, _)| size);
        let select_size = slot.select_in_force.unwrap_or(0);
        // Whole-slice comparisons (memcmp): an instrumented loop would cost more than the
        // calls themselves.
        let feedback = (slot.feedback[feedback_size..] != FEEDBACK_FILL[feedback_size..])
            .then(|| {
                slot.feedback[feedback_size..]
                    .iter()
                    .position(|&v| v != FEEDBACK_SENTINEL)
            })
            .flatten();
        let select = (slot.select[select_size..] != SELECT_FILL[select_size..])
            .then(|| {
                slot.select[select_size..]
                    .iter()
                    .position(|&v| v != SELECT_SENTINEL)
            })
            .flatten();
        if let Some(at) = feedback {
            self.fail(format!(
                "feedback wrote at {} past its size {feedback_size}",
                feedback_size + at
            ));
        }
        if let Some(at) = select {
            self.fail(format!(
                "selection wrote at {} past its size {select_size}",
                select_size + at
            ));
        }
    }

    fn after_call(&mut self) {
        self.error();
        self.check_buffers();
        self.check_state();
        // SAFETY: no arguments.
        let current = unsafe { fflGetCurrentContext() };
        if current != self.slots[self.current].handle {
            self.fail(format!(
                "fflGetCurrentContext is {current:?}, the harness made {:?} current",
                self.slots[self.current].handle
            ));
        }
    }

    // ---- the functions the table leaves to the harness ----

    /// Whether a glBegin is open (where glGetError itself is an error and returns 0): a query
    /// that writes nothing.
    fn inside_begin_end(&mut self) -> bool {
        self.get_ints::<1>(GL_RENDER_MODE)[0] == i32::MIN
    }

    fn slot_index(&mut self, from: usize) -> usize {
        from + self.byte() as usize % (self.slots.len() - from).max(1)
    }

    pub fn special(&mut self, name: &'static str) {
        match name {
            "fflCreateContext" => {
                // SAFETY: no arguments.
                let handle = unsafe { fflCreateContext() };
                if handle.is_null() {
                    self.fail("fflCreateContext returned NULL".into());
                } else if self.slots.len() < SLOTS {
                    self.slots.push(Slot::new(handle.cast()));
                } else {
                    // SAFETY: a live context, not current.
                    unsafe { fflDestroyContext(handle) };
                }
            }
            "fflMakeCurrent" => {
                let index = self.slot_index(0);
                // SAFETY: a live context from fflCreateContext.
                let made = unsafe { fflMakeCurrent(self.slots[index].handle.cast()) };
                if made == GL_TRUE {
                    self.current = index;
                } else {
                    self.fail("fflMakeCurrent failed on a context of this thread".into());
                }
            }
            "fflDestroyContext" => {
                if self.slots.len() == 1 || self.byte().is_multiple_of(16) {
                    // SAFETY: NULL is allowed.
                    if unsafe { fflDestroyContext(std::ptr::null_mut()) } != GL_FALSE {
                        self.fail("fflDestroyContext(NULL) succeeded".into());
                    }
                    return;
                }
                let index = self.slot_index(1);
                let slot = self.slots.remove(index);
                // SAFETY: a live context, used no more by the harness.
                if unsafe { fflDestroyContext(slot.handle.cast()) } != GL_TRUE {
                    self.fail("fflDestroyContext failed".into());
                }
                if index == self.current {
                    // The base context becomes current again (a thread's default context
                    // would carry state from one input to the next).
                    self.current = 0;
                    // SAFETY: the base context is live.
                    unsafe { fflMakeCurrent(self.slots[0].handle.cast()) };
                } else if index < self.current {
                    self.current -= 1;
                }
            }
            "fflGetCurrentContext" => {} // checked after every call
            "fflSetThreads" => {
                let count = self.byte() as i32 % 4 - 1;
                // SAFETY: plain value.
                unsafe { fflSetThreads(count) };
            }
            "fflCaptureReadVertices" => {
                let first = self.integer(IntClass::Count) as GLuint;
                let count = self.integer(IntClass::Count) as GLuint;
                let out = self.output_pointer(0);
                // SAFETY: the output slot holds 4096 vertices.
                let n = unsafe { fflCaptureReadVertices(first, count, out) };
                if n > count {
                    self.fail(format!("fflCaptureReadVertices wrote {n} of {count}"));
                }
                if !out.is_null() {
                    // 28 floats then the edge flag and 3 bytes: 29 words a vertex.
                    let words = out.cast::<f32>();
                    for i in 0..n.min(count) as usize {
                        for k in 8..24 {
                            // SAFETY: written by the call above.
                            let c = unsafe { *words.add(i * 29 + k) };
                            if !(0.0..=1.0).contains(&c) {
                                self.fail(format!("captured vertex {i}: color {c} outside [0, 1]"));
                            }
                        }
                    }
                }
            }
            "glFeedbackBuffer" => {
                let inside = self.inside_begin_end();
                let size = self.integer(IntClass::Count) as GLsizei;
                let kind = self.enumeration();
                let null = self.byte().is_multiple_of(32);
                let slot = &mut self.slots[self.current];
                let buffer = if null {
                    std::ptr::null_mut()
                } else {
                    slot.feedback.as_mut_ptr().cast::<f32>()
                };
                // SAFETY: the buffer holds BUFFER_CAPACITY >= size values and lives as long as
                // the context.
                unsafe { glFeedbackBuffer(size, kind, buffer) };
                if self.error() == GL_NO_ERROR && !inside {
                    if size < 0 || (null && size > 0) {
                        self.fail(format!(
                            "glFeedbackBuffer({size}, {kind:#x}, {buffer:?}) accepted"
                        ));
                        return;
                    }
                    let slot = &mut self.slots[self.current];
                    let size = size as usize;
                    slot.feedback_in_force = Some((size, kind));
                    slot.feedback[size..].fill(FEEDBACK_SENTINEL);
                }
            }
            "glSelectBuffer" => {
                let inside = self.inside_begin_end();
                let size = self.integer(IntClass::Count) as GLsizei;
                let null = self.byte().is_multiple_of(32);
                let slot = &mut self.slots[self.current];
                let buffer = if null {
                    std::ptr::null_mut()
                } else {
                    slot.select.as_mut_ptr()
                };
                // SAFETY: as for glFeedbackBuffer.
                unsafe { glSelectBuffer(size, buffer) };
                if self.error() == GL_NO_ERROR && !inside {
                    if size < 0 || (null && size > 0) {
                        self.fail(format!("glSelectBuffer({size}, {buffer:?}) accepted"));
                        return;
                    }
                    let slot = &mut self.slots[self.current];
                    slot.select_in_force = Some(size as usize);
                    slot.select[size as usize..].fill(SELECT_SENTINEL);
                }
            }
            "glRenderMode" => {
                let mode = self.enumeration();
                let [before] = self.get_ints::<1>(GL_RENDER_MODE);
                let queried = before != i32::MIN;
                // SAFETY: plain value.
                let result = unsafe { glRenderMode(mode) };
                if self.error() != GL_NO_ERROR || !queried {
                    if result != 0 {
                        self.fail(format!("glRenderMode failed but returned {result}"));
                    }
                    return;
                }
                self.check_render_mode_result(before as GLenum, result);
            }
            "glGetError" => {} // called after every call
            "glMultiDrawElements" => {
                let mode = self.enumeration();
                let count = self.input_pointer(Region::Ints) as *const GLsizei;
                let kind = self.enumeration();
                let indices = self.input_pointer(Region::Pointers) as *const *const c_void;
                let primcount = (self.byte() % 20) as GLsizei - 2;
                // SAFETY: counts below 64 (with a few large ones that GL must reject or
                // read within the arena), pointers into the arena.
                unsafe { glMultiDrawElements(mode, count, kind, indices, primcount) };
            }
            "glPixelStoref" => {
                let pname = self.enumeration();
                let param = (self.byte() % 20) as f32 - 2.0;
                // SAFETY: plain values.
                unsafe { glPixelStoref(pname, param) };
            }
            "glPixelStorei" => {
                let pname = self.enumeration();
                let param = (self.byte() % 20) as GLint - 2;
                // SAFETY: plain values.
                unsafe { glPixelStorei(pname, param) };
            }
            "glCallList" | "glCallLists" => {
                let (mut n, kind, lists) = match name {
                    "glCallList" => (1, 0, std::ptr::null()),
                    _ => (
                        self.integer(IntClass::Count).min(64) as GLsizei,
                        self.enumeration(),
                        self.input_pointer(Region::Any),
                    ),
                };
                let list = (name == "glCallList").then(|| self.integer(IntClass::Any) as GLuint);
                // A list that calls lists twice, nested 64 deep, runs 2^64 times: GL allows
                // it (and hangs), the fuzzer must not. Each list being compiled gets one call
                // of one list (GL_LIST_INDEX; unknown between a compiled-and-executed glBegin
                // and glEnd, counted together), so nested lists stay a chain.
                let [index] = self.get_ints::<1>(GL_LIST_INDEX);
                if index != 0 {
                    match self.list_calls.iter_mut().find(|(i, _)| *i == index) {
                        Some((_, calls)) if *calls >= 1 => return,
                        Some((_, calls)) => *calls += 1,
                        None => self.list_calls.push((index, 1)),
                    }
                    n = n.min(1);
                }
                // SAFETY: n names of at most 4 bytes in the arena.
                unsafe {
                    match list {
                        Some(list) => glCallList(list),
                        None => glCallLists(n, kind, lists),
                    }
                }
            }
            other => self.fail(format!("no special handling for {other}")),
        }
    }

    /// What glRenderMode returned when leaving `before` (§5.2, §5.3).
    fn check_render_mode_result(&mut self, before: GLenum, result: GLint) {
        let slot = &self.slots[self.current];
        match before {
            GL_FEEDBACK => {
                let Some((size, kind)) = slot.feedback_in_force else {
                    return self.fail("in feedback mode without a feedback buffer".into());
                };
                if result < -1 || result > size as i32 {
                    return self.fail(format!("feedback count {result}, size {size}"));
                }
                let written = if result == -1 { size } else { result as usize };
                let values: Vec<f32> = slot.feedback[..written]
                    .iter()
                    .map(|&b| f32::from_bits(b))
                    .collect();
                if let Err(problem) = check_feedback(&values, result == -1, kind) {
                    self.fail(problem);
                }
            }
            GL_SELECT => {
                let Some(size) = slot.select_in_force else {
                    return self.fail("in selection mode without a selection buffer".into());
                };
                let records = slot.select[..size].to_vec();
                if let Err(problem) = check_hits(&records, result) {
                    self.fail(problem);
                }
            }
            _ => {
                if result != 0 {
                    self.fail(format!(
                        "glRenderMode returned {result} leaving render mode"
                    ));
                }
            }
        }
    }

    // ---- running ----

    /// Decodes and runs the calls of `data` on a new context, checking after each call.
    pub fn run(data: &'a [u8]) -> Harness<'a> {
        install_panic_hook();
        RUNNING.store(true, Ordering::Relaxed);
        // SAFETY: no arguments.
        let base = unsafe { fflCreateContext() };
        // SAFETY: a live context.
        unsafe {
            fflMakeCurrent(base);
            fflSetThreads(0);
        }
        let mut h = Harness {
            data,
            pos: 0,
            slots: vec![Slot::new(base.cast())],
            current: 0,
            failure: None,
            calling: "setup",
            maxima: [0; 5],
            list_calls: Vec::new(),
            calls: 0,
        };
        h.maxima = [
            h.get_ints::<1>(GL_MAX_MODELVIEW_STACK_DEPTH)[0],
            h.get_ints::<1>(GL_MAX_PROJECTION_STACK_DEPTH)[0],
            h.get_ints::<1>(GL_MAX_TEXTURE_STACK_DEPTH)[0],
            h.get_ints::<1>(GL_MAX_COLOR_MATRIX_STACK_DEPTH)[0],
            h.get_ints::<1>(GL_MAX_ATTRIB_STACK_DEPTH)[0],
        ];
        // SAFETY: the data region is inside the arena.
        unsafe { std::ptr::write_bytes(arena().add(DATA), 0, REGION) };
        while !h.exhausted() && h.failure.is_none() {
            let op = h.u16() as usize % (FUNCTIONS.len() + EXTRA_OPS);
            h.op(op);
        }
        release_far_pages();
        // Tear down: every context of the input, whatever is current.
        for slot in std::mem::take(&mut h.slots) {
            // SAFETY: live contexts of this input.
            unsafe { fflDestroyContext(slot.handle.cast()) };
        }
        RUNNING.store(false, Ordering::Relaxed);
        h
    }

    fn op(&mut self, op: usize) {
        if op < FUNCTIONS.len() {
            self.calling = FUNCTIONS[op];
            call(self, op);
            self.calls += 1;
            self.after_call();
            return;
        }
        match op - FUNCTIONS.len() {
            // Repeat the next call 2 to 80 times with the same arguments (stack overflows).
            0 => {
                let times = 2 + self.byte() as usize % 79;
                let function = self.u16() as usize % FUNCTIONS.len();
                let start = self.pos;
                for _ in 0..times {
                    self.pos = start;
                    self.op(function);
                    if self.failure.is_some() {
                        break;
                    }
                }
            }
            // Write up to 64 bytes of the input into the data region.
            1 => {
                let offset = self.byte() as usize * 16;
                let len = (self.byte() % 65) as usize;
                let end = (self.pos + len).min(self.data.len());
                let bytes = &self.data[self.pos.min(end)..end];
                // SAFETY: offset + 64 bytes is inside the data region.
                unsafe {
                    std::ptr::copy_nonoverlapping(
                        bytes.as_ptr(),
                        arena().add(DATA + offset),
                        bytes.len(),
                    )
                };
                self.pos = end;
            }
            // A glBegin/glEnd pair around the next calls: the vertices of a primitive.
            _ => {
                let mode = self.byte() as GLenum % 11;
                let vertices = self.byte() % 9;
                // SAFETY: plain values; float region pointers hold 4 values.
                unsafe {
                    glBegin(mode);
                    for _ in 0..vertices {
                        let v = self.input_pointer(Region::Floats) as *const GLfloat;
                        if !v.is_null() {
                            glNormal3fv(v.add(1));
                            glVertex4fv(v);
                        }
                    }
                    glEnd();
                }
                self.calling = "glBegin/glEnd";
                self.calls += 1;
                self.after_call();
            }
        }
    }

    /// The first broken invariant, if any.
    pub fn outcome(&self) -> Outcome {
        match &self.failure {
            Some(failure) => Err(failure.clone()),
            None => Ok(()),
        }
    }
}

/// A panic inside fflight is caught by its guard and turned into a neutral result; the fuzzer
/// must see it: print it and abort.
pub fn install_panic_hook() {
    static HOOK: OnceLock<()> = OnceLock::new();
    HOOK.get_or_init(|| {
        let default = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            default(info);
            if RUNNING.load(Ordering::Relaxed) {
                eprintln!("fflight panicked: the fuzz harness aborts");
                std::process::abort();
            }
        }));
    });
}

/// Set while an input runs: a panic then comes from fflight (the harness's own checks
/// record failures, they do not panic).
static RUNNING: AtomicBool = AtomicBool::new(false);

/// A fed-back stream (§5.3): known tokens, whole vertices unless it overflowed, colors in
/// [0, 1].
pub fn check_feedback(values: &[f32], overflowed: bool, kind: GLenum) -> Outcome {
    let (coords, color, texture) = match kind {
        GL_2D => (2, false, false),
        GL_3D => (3, false, false),
        GL_3D_COLOR => (3, true, false),
        GL_3D_COLOR_TEXTURE => (3, true, true),
        GL_4D_COLOR_TEXTURE => (4, true, true),
        _ => return Err(format!("feedback type {kind:#x} in force")),
    };
    let vertex = coords + 4 * color as usize + 4 * texture as usize;
    let mut i = 0;
    while i < values.len() {
        let token = values[i];
        let vertices = match token as GLenum {
            _ if token != (token as GLenum) as f32 => {
                return Err(format!("feedback: value {token} at {i} is no token"));
            }
            GL_POINT_TOKEN | GL_BITMAP_TOKEN | GL_DRAW_PIXEL_TOKEN | GL_COPY_PIXEL_TOKEN => 1,
            GL_LINE_TOKEN | GL_LINE_RESET_TOKEN => 2,
            GL_POLYGON_TOKEN => match values.get(i + 1) {
                Some(&n) if n >= 3.0 && n == n.trunc() => {
                    i += 1;
                    n as usize
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
        i += 1;
        for _ in 0..vertices {
            let Some(v) = values.get(i..i + vertex) else {
                return if overflowed {
                    Ok(())
                } else {
                    Err(format!("feedback: vertex cut at {i} without overflow"))
                };
            };
            if color
                && !v[coords..coords + 4]
                    .iter()
                    .all(|c| (0.0..=1.0).contains(c))
            {
                return Err(format!("feedback: color {v:?} at {i} outside [0, 1]"));
            }
            i += vertex;
        }
    }
    Ok(())
}

/// Hit records (§5.2): `hits` whole records (or -1 after an overflow, the last one cut), each
/// a name count of at most 64, min z <= max z, then the names.
pub fn check_hits(records: &[u32], hits: GLint) -> Outcome {
    if hits < -1 {
        return Err(format!("selection: {hits} hits"));
    }
    let (mut i, mut parsed) = (0, 0);
    while i < records.len() && (hits == -1 || parsed < hits) {
        let n = records[i] as usize;
        if n > 64 {
            return Err(format!("selection: {n} names in the record at {i}"));
        }
        let Some(record) = records.get(i..i + 3 + n) else {
            return if hits == -1 {
                Ok(())
            } else {
                Err(format!("selection: record cut at {i} without overflow"))
            };
        };
        if record[1] > record[2] {
            return Err(format!("selection: min z > max z at {i}: {record:?}"));
        }
        i += 3 + n;
        parsed += 1;
    }
    if hits >= 0 && parsed != hits {
        return Err(format!("selection: {hits} hits, {parsed} records fit"));
    }
    Ok(())
}
