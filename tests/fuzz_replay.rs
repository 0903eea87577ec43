//! The coverage-guided fuzz target's harness (`fuzz/src/harness.rs`) in `cargo test`: every
//! input of the seed corpus (`fuzz/seeds/capi_calls/`) and every finding
//! (`fuzz/regressions/capi_calls/`, one file per fixed bug) is replayed through the same
//! decoder and invariant checks as in `make fuzz`, and the call table and the dictionary
//! generated from `include/fflight.h` must be up to date (`FFLIGHT_BLESS=1` rewrites them).
//! A panic inside fflight aborts this test binary (the harness's panic hook), as it stops the
//! fuzzer.

#[path = "../fuzz/src/generate.rs"]
mod generate;
#[path = "../fuzz/src/harness.rs"]
mod harness;
#[path = "../fuzz/src/seeds.rs"]
mod seeds;

use std::path::{Path, PathBuf};

use fflight::gl::*;
use harness::Harness;

fn fuzz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz")
}

fn inputs(dir: &str) -> Vec<(String, Vec<u8>)> {
    let dir = fuzz_dir().join(dir);
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("read {}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_file())
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read(&p).unwrap())
        })
        .collect()
}

/// Replays on a thread with the 8 MiB stack of a C program's main thread: a debug build of
/// fflight needs about 2 MiB for 64 nested display lists ending in a draw (16 KiB a level, and
/// 1 MiB for the lighting kernel's frame), more than a test thread's default 2 MiB.
fn replay(dir: &str) -> usize {
    let dir = dir.to_string();
    std::thread::Builder::new()
        .stack_size(8 << 20)
        .spawn(move || replay_here(&dir))
        .unwrap()
        .join()
        .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
}

fn replay_here(dir: &str) -> usize {
    let mut calls = 0;
    for (name, data) in inputs(dir) {
        let h = Harness::run(&data);
        if let Err(problem) = h.outcome() {
            panic!("fuzz/{dir}/{name}: {problem}");
        }
        calls += h.calls;
    }
    calls
}

fn blessing() -> bool {
    std::env::var_os("FFLIGHT_BLESS").is_some_and(|v| v == "1")
}

#[test]
fn seed_corpus_replays_cleanly() {
    let dir = fuzz_dir().join("seeds/capi_calls");
    for (name, bytes) in seeds::seeds() {
        let path = dir.join(name);
        if blessing() {
            std::fs::write(&path, &bytes).unwrap();
        }
        assert!(
            std::fs::read(&path).is_ok_and(|found| found == bytes),
            "fuzz/seeds/capi_calls/{name} is not what fuzz/src/seeds.rs writes: \
             FFLIGHT_BLESS=1 cargo test --test fuzz_replay"
        );
    }
    let calls = replay("seeds/capi_calls");
    assert!(calls > 1000, "the seeds make only {calls} calls");
}

#[test]
fn findings_stay_fixed() {
    let dir = fuzz_dir().join("regressions/capi_calls");
    for (name, bytes) in seeds::regressions() {
        let path = dir.join(name);
        if blessing() {
            std::fs::write(&path, &bytes).unwrap();
        }
        assert!(
            std::fs::read(&path).is_ok_and(|found| found == bytes),
            "fuzz/regressions/capi_calls/{name} is not what fuzz/src/seeds.rs writes: \
             FFLIGHT_BLESS=1 cargo test --test fuzz_replay"
        );
    }
    let start = std::time::Instant::now();
    replay("regressions/capi_calls");
    // The self-calling list must not hang the harness.
    assert!(start.elapsed().as_secs() < 60, "{:?}", start.elapsed());
}

#[test]
fn call_table_and_dictionary_match_the_header() {
    let header =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("include/fflight.h"))
            .unwrap();
    let expected = [
        ("src/calls.rs", generate::calls(&header)),
        ("gl_enums.dict", generate::dictionary(&header)),
    ];
    for (file, text) in expected {
        let path = fuzz_dir().join(file);
        if blessing() {
            std::fs::write(&path, &text).unwrap();
        }
        let found = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            found == text,
            "fuzz/{file} is stale: FFLIGHT_BLESS=1 cargo test --test fuzz_replay"
        );
    }
    // Every exported function is in the table: fflight's own and GL 1.5's but those not
    // exported yet.
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let names = |file: &str| -> Vec<String> {
        std::fs::read_to_string(docs.join(file))
            .unwrap()
            .lines()
            .filter(|l| !l.starts_with('#'))
            .filter_map(|l| l.split_whitespace().next().map(str::to_string))
            .collect()
    };
    let missing = names("gl15-not-exported.txt");
    let mut exported = names("fflight-functions.txt");
    exported.extend(
        names("gl15-functions.txt")
            .into_iter()
            .filter(|n| !missing.contains(n)),
    );
    assert!(exported.len() > 480, "{} names", exported.len());
    for name in &exported {
        assert!(
            harness::FUNCTIONS.contains(&name.as_str()),
            "{name} is exported but not in the fuzz call table"
        );
    }
}

/// The checks themselves can fail.
#[test]
fn invariant_checks_catch_bad_output() {
    let point = |r: f32| vec![GL_POINT_TOKEN as f32, 1.0, 2.0, 3.0, r, 0.5, 0.5, 1.0];
    assert!(harness::check_feedback(&point(0.25), false, GL_3D_COLOR).is_ok());
    assert!(harness::check_feedback(&point(1.5), false, GL_3D_COLOR).is_err());
    assert!(harness::check_feedback(&point(f32::NAN), false, GL_3D_COLOR).is_err());
    assert!(harness::check_feedback(&point(0.25)[..5], false, GL_3D_COLOR).is_err());
    assert!(harness::check_feedback(&point(0.25)[..5], true, GL_3D_COLOR).is_ok());
    assert!(harness::check_feedback(&[1234.0], false, GL_3D).is_err());
    assert!(harness::check_hits(&[1, 5, 9, 7], 1).is_ok());
    assert!(harness::check_hits(&[1, 9, 5, 7], 1).is_err());
    assert!(harness::check_hits(&[65, 1, 2], 1).is_err());
    assert!(harness::check_hits(&[1, 5, 9], 1).is_err());
    assert!(harness::check_hits(&[1, 5, 9], -1).is_ok());
}

// Declared as the harness's generated table declares them (`fuzz/src/calls.rs`).
unsafe extern "C" {
    fn glNewList(list: GLuint, mode: GLenum);
    fn glEndList();
    fn glCallList(list: GLuint);
    fn glEnableClientState(array: GLenum);
    fn glGetError() -> GLenum;
    fn glVertexPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const std::ffi::c_void);
    fn glDrawElements(
        mode: GLenum,
        count: GLsizei,
        type_: GLenum,
        indices: *const std::ffi::c_void,
    );
}

/// Found by `make fuzz` (a crash, fixed): a draw compiled into a display list copies the
/// array elements it references, and an index far into an array of a huge stride asked for
/// 38 GB, which aborted the process. Now GL_OUT_OF_MEMORY, raised when the list runs: here,
/// 900 GiB of a read-only mapping no memory backs.
#[test]
fn compiling_a_draw_too_large_to_copy_is_out_of_memory() {
    const SPAN: usize = 1 << 40;
    // SAFETY: a fresh private mapping, unmapped below; nothing else uses it.
    let base = unsafe {
        libc::mmap(
            std::ptr::null_mut(),
            SPAN,
            libc::PROT_READ,
            libc::MAP_PRIVATE | libc::MAP_ANONYMOUS | libc::MAP_NORESERVE,
            -1,
            0,
        )
    };
    assert!(base != libc::MAP_FAILED, "mmap of 1 TiB failed");
    // The copy spans the elements from the lowest index to the highest.
    let indices: [GLuint; 2] = [0, 900];
    // SAFETY: element 900 at a stride of 1 GiB lies inside the mapping; the draw reads its
    // two indices from `indices`; the other calls take no pointer.
    unsafe {
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(3, GL_FLOAT, 1 << 30, base);
        glNewList(1, GL_COMPILE);
        glDrawElements(GL_POINTS, 2, GL_UNSIGNED_INT, indices.as_ptr().cast());
        glEndList();
        // An error of a compiled draw is compiled in its place (src/capi/arrays.rs).
        assert_eq!(glGetError(), GL_NO_ERROR);
        glCallList(1);
        assert_eq!(glGetError(), GL_OUT_OF_MEMORY);
    }
    // SAFETY: the mapping made above, no longer read (the draw failed to compile).
    unsafe { libc::munmap(base, SPAN) };
}
