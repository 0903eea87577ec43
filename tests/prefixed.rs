//! The prefixed static library (docs/coexistence.md): tools/prefix_library.sh turns this
//! build's libfflight.a into libfflight_prefixed.a, whose GL functions are all named `ffl_glX`;
//! it defines exactly the functions include/fflight_prefixed.h declares (whose freshness
//! tests/header.rs checks), and a C program
//! linking it together with OSMesa (a real GL exporting `glLightfv`, ...) reaches each library
//! where it means to (tests/coexist/fflight_and_osmesa.c).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

fn manifest_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn run(command: &mut Command) -> String {
    let output = command
        .output()
        .unwrap_or_else(|e| panic!("{command:?}: {e}"));
    let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    assert!(
        output.status.success(),
        "{command:?} failed ({}):\n{stdout}{}",
        output.status,
        String::from_utf8_lossy(&output.stderr)
    );
    stdout
}

/// libfflight_prefixed.a made from the static library `cargo test` built next to this test
/// binary (target/<profile>/deps), in its own directory, once for all the tests.
fn prefixed_library() -> PathBuf {
    static LIBRARY: OnceLock<PathBuf> = OnceLock::new();
    LIBRARY.get_or_init(make_prefixed_library).clone()
}

fn make_prefixed_library() -> PathBuf {
    let exe = std::env::current_exe().expect("the test binary's path");
    let library = exe.with_file_name("libfflight.a");
    assert!(library.exists(), "{} was not built", library.display());
    let dir = manifest_dir().join("target/prefixed_test");
    std::fs::create_dir_all(&dir).unwrap();
    let prefixed = dir.join("libfflight_prefixed.a");
    run(Command::new(manifest_dir().join("tools/prefix_library.sh"))
        .arg(&library)
        .arg(&prefixed));
    prefixed
}

/// The prefixed library defines the functions the prefixed header declares, no GL name, and
/// as many functions as the normal header declares.
#[test]
fn prefixed_library_defines_what_its_header_declares() {
    let symbols = run(Command::new("nm")
        .args(["-g", "--defined-only"])
        .arg(prefixed_library()));
    let defined: BTreeSet<&str> = symbols
        .lines()
        .filter_map(|l| match l.split_whitespace().collect::<Vec<_>>()[..] {
            [_, "T", name] if name.starts_with("ffl") || name.starts_with("gl") => Some(name),
            _ => None,
        })
        .collect();
    let declared = |file: &str| -> BTreeSet<String> {
        std::fs::read_to_string(manifest_dir().join(file))
            .unwrap()
            .lines()
            .filter(|l| l.starts_with(|c: char| c.is_ascii_alphabetic()))
            .filter_map(|l| {
                let head = &l[..l.find('(')?];
                let start = head.rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))?;
                Some(head[start + 1..].to_string())
            })
            .collect()
    };
    let prefixed = declared("include/fflight_prefixed.h");
    let normal = declared("include/fflight.h");
    let defined: BTreeSet<String> = defined.iter().map(|s| s.to_string()).collect();
    assert_eq!(
        defined, prefixed,
        "libfflight_prefixed.a vs fflight_prefixed.h"
    );
    assert!(prefixed.iter().all(|name| !name.starts_with("gl")));
    let unprefixed: BTreeSet<String> = prefixed
        .iter()
        .map(|name| name.strip_prefix("ffl_").unwrap_or(name).to_string())
        .collect();
    assert_eq!(unprefixed, normal, "fflight_prefixed.h vs fflight.h");
}

#[test]
fn c_program_calls_osmesa_and_fflight_each_where_it_means_to() {
    let library = prefixed_library();
    let exe = library.with_file_name("fflight_and_osmesa");
    run(
        Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()))
            .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"])
            .arg("-D_GNU_SOURCE")
            .arg("-I")
            .arg(manifest_dir().join("include"))
            .arg(manifest_dir().join("tests/coexist/fflight_and_osmesa.c"))
            .arg(&library)
            .args(["-lOSMesa", "-lm", "-lpthread", "-ldl", "-o"])
            .arg(&exe),
    );
    let output = run(&mut Command::new(&exe));
    assert!(!output.contains("FAILED"), "{output}");
    assert_eq!(output.matches("ok: ").count(), 12, "{output}");
}
