//! The library exports OpenGL 1.5's functions and fflight's own, nothing else, and
//! include/fflight.h declares exactly what it exports.
//!
//! - docs/gl15-functions.txt: every GL 1.5 function (tools/gl15_functions.py, from gl.xml);
//! - docs/gl15-not-exported.txt: the GL 1.5 functions not exported yet; a name there that the
//!   library exports fails, so the file only shrinks;
//! - docs/fflight-functions.txt: fflight's own additions (`ffl*`).
//!
//! The exported names are read from the shared library's dynamic symbol table with
//! `nm -D --defined-only` (binutils).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

fn manifest_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The names of a list file: the first word of each line that is not blank or a `#` comment.
fn names(file: &str) -> BTreeSet<String> {
    let path = manifest_dir().join(file);
    let text =
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("read {}: {e}", path.display()));
    text.lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| l.split_whitespace().next().unwrap_or_default().to_string())
        .collect()
}

/// The shared library this test run built: `cargo test` puts it next to the test binary
/// (target/<profile>/deps), `cargo build` in target/<profile>; the newer one wins, so a stale
/// build never stands in for the current sources.
fn shared_library() -> PathBuf {
    let exe = std::env::current_exe().expect("the test binary's path");
    let deps = exe.parent().expect("the deps directory");
    let candidates = [
        deps.join("libfflight.so"),
        deps.parent()
            .expect("the profile directory")
            .join("libfflight.so"),
    ];
    candidates
        .iter()
        .filter_map(|p| Some((std::fs::metadata(p).ok()?.modified().ok()?, p.clone())))
        .max()
        .map(|(_, p)| p)
        .unwrap_or_else(|| panic!("libfflight.so not found at {candidates:?}"))
}

/// The symbols the library defines in its dynamic symbol table.
fn exported() -> BTreeSet<String> {
    let library = shared_library();
    let output = Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(&library)
        .output()
        .expect("nm (binutils) is installed");
    assert!(
        output.status.success(),
        "nm -D {}: {}",
        library.display(),
        String::from_utf8_lossy(&output.stderr)
    );
    let symbols: BTreeSet<String> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter_map(|l| l.split_whitespace().nth(2))
        .map(str::to_string)
        .collect();
    assert!(
        symbols.contains("glGetError"),
        "nm found no glGetError in {}: {symbols:?}",
        library.display()
    );
    symbols
}

/// The functions include/fflight.h declares: `name(` at the start of a declaration.
fn declared_in_header() -> BTreeSet<String> {
    let header = std::fs::read_to_string(manifest_dir().join("include/fflight.h"))
        .expect("include/fflight.h exists");
    header
        .lines()
        .filter(|l| !l.starts_with([' ', '#', '/', '*', '}', '\t']) && l.contains('('))
        .filter_map(|l| {
            let before_paren = &l[..l.find('(')?];
            let name = before_paren.rsplit([' ', '*']).next()?;
            (name.starts_with("gl") || name.starts_with("ffl")).then(|| name.to_string())
        })
        .collect()
}

fn listing(names: &BTreeSet<String>) -> String {
    names.iter().cloned().collect::<Vec<_>>().join(" ")
}

#[test]
fn every_export_is_a_gl15_function_or_an_fflight_one() {
    let gl15 = names("docs/gl15-functions.txt");
    let own = names("docs/fflight-functions.txt");
    let stray: BTreeSet<String> = exported()
        .into_iter()
        .filter(|s| !gl15.contains(s) && !own.contains(s))
        .collect();
    assert!(
        stray.is_empty(),
        "exported, but neither a GL 1.5 function nor listed in docs/fflight-functions.txt: {}",
        listing(&stray)
    );
}

#[test]
fn every_gl15_function_is_exported_or_listed_as_not_yet() {
    let exported = exported();
    let not_yet = names("docs/gl15-not-exported.txt");
    let missing: BTreeSet<String> = names("docs/gl15-functions.txt")
        .into_iter()
        .filter(|f| !exported.contains(f) && !not_yet.contains(f))
        .collect();
    assert!(
        missing.is_empty(),
        "GL 1.5 functions neither exported nor in docs/gl15-not-exported.txt: {}",
        listing(&missing)
    );
}

#[test]
fn the_not_yet_list_holds_only_unexported_gl15_functions() {
    let exported = exported();
    let gl15 = names("docs/gl15-functions.txt");
    let not_yet = names("docs/gl15-not-exported.txt");
    let now_exported: BTreeSet<String> = not_yet.intersection(&exported).cloned().collect();
    assert!(
        now_exported.is_empty(),
        "exported now: delete them from docs/gl15-not-exported.txt: {}",
        listing(&now_exported)
    );
    let unknown: BTreeSet<String> = not_yet.difference(&gl15).cloned().collect();
    assert!(
        unknown.is_empty(),
        "not GL 1.5 functions, yet in docs/gl15-not-exported.txt: {}",
        listing(&unknown)
    );
}

#[test]
fn every_fflight_function_is_exported() {
    let exported = exported();
    let absent: BTreeSet<String> = names("docs/fflight-functions.txt")
        .into_iter()
        .filter(|f| !exported.contains(f))
        .collect();
    assert!(
        absent.is_empty(),
        "listed in docs/fflight-functions.txt but not exported: {}",
        listing(&absent)
    );
}

/// A function exported without a declaration (say, made by a macro cbindgen cannot expand)
/// cannot be called from C; a declaration without a symbol fails to link.
#[test]
fn the_header_declares_exactly_the_exported_functions() {
    let exported = exported();
    let declared = declared_in_header();
    let undeclared: BTreeSet<String> = exported.difference(&declared).cloned().collect();
    let unexported: BTreeSet<String> = declared.difference(&exported).cloned().collect();
    assert!(
        undeclared.is_empty() && unexported.is_empty(),
        "exported but not in include/fflight.h: {}\nin include/fflight.h but not exported: {}",
        listing(&undeclared),
        listing(&unexported)
    );
}

/// docs/gl15-functions.txt is what tools/gl15_functions.py makes of the registry: a sorted list
/// of distinct `gl` names with their origin, holding the landmarks of each version.
#[test]
fn the_gl15_list_is_well_formed() {
    let text = std::fs::read_to_string(manifest_dir().join("docs/gl15-functions.txt")).unwrap();
    let rows: Vec<(&str, &str)> = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let mut words = l.split_whitespace();
            (words.next().unwrap_or(""), words.next().unwrap_or(""))
        })
        .collect();
    let mut sorted = rows.clone();
    sorted.sort();
    sorted.dedup_by_key(|r| r.0);
    assert_eq!(rows, sorted, "sorted, one row per name");
    for (name, origin) in &rows {
        assert!(name.starts_with("gl"), "{name}");
        assert!(
            origin.starts_with("GL_VERSION_1_") || *origin == "GL_ARB_imaging",
            "{name} {origin}"
        );
    }
    for landmark in [
        ("glBegin", "GL_VERSION_1_0"),
        ("glBindTexture", "GL_VERSION_1_1"),
        ("glDrawRangeElements", "GL_VERSION_1_2"),
        ("glActiveTexture", "GL_VERSION_1_3"),
        ("glBlendFuncSeparate", "GL_VERSION_1_4"),
        ("glBindBuffer", "GL_VERSION_1_5"),
        ("glColorTable", "GL_ARB_imaging"),
    ] {
        assert!(rows.contains(&landmark), "{landmark:?}");
    }
    assert_eq!(rows.len(), 484, "GL 1.0-1.5 and the imaging subset");
}

/// The list agrees with the system headers (libosmesa6-dev's, which `make deps` installs): the
/// unsuffixed functions <GL/gl.h> declares are exactly its GL 1.0-1.3 and imaging ones (with
/// glBlendColor and glBlendEquation, imaging functions the list dates from 1.4, when they
/// became core), and <GL/glext.h> declares each of its GL 1.4 and 1.5 ones.
#[test]
fn the_gl15_list_agrees_with_the_system_headers() {
    let read = |path: &str| {
        std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path} (libosmesa6-dev): {e}"))
    };
    let declared = |text: &str, marker: &str| -> BTreeSet<String> {
        text.split(marker)
            .skip(1)
            .filter_map(|rest| {
                let name = rest.trim_start().split(['(', ' ']).next()?;
                let suffixed = ["ARB", "EXT", "MESA", "ATI", "NV", "SGI", "IBM"]
                    .iter()
                    .any(|s| name.ends_with(s));
                (name.starts_with("gl") && !suffixed).then(|| name.to_string())
            })
            .collect()
    };
    let gl_h = declared(&read("/usr/include/GL/gl.h"), "GLAPIENTRY");
    let glext_h = declared(&read("/usr/include/GL/glext.h"), "APIENTRY");
    let text = std::fs::read_to_string(manifest_dir().join("docs/gl15-functions.txt")).unwrap();
    let mut early = BTreeSet::new();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let (name, origin) = line.split_once(' ').unwrap_or((line, ""));
        if matches!(origin, "GL_VERSION_1_4" | "GL_VERSION_1_5") {
            assert!(
                glext_h.contains(name),
                "{name} ({origin}) is not in <GL/glext.h>"
            );
            if matches!(name, "glBlendColor" | "glBlendEquation") {
                early.insert(name.to_string());
            }
        } else {
            early.insert(name.to_string());
        }
    }
    assert_eq!(early, gl_h, "GL 1.0-1.3 and imaging functions vs <GL/gl.h>");
}

/// A C program compiled with -Werror against the system's <GL/gl.h> and <GL/glext.h>
/// (GL_GLEXT_PROTOTYPES) takes the address of every GL 1.5 function fflight exports, so each
/// export has the system prototype's exact signature (a mismatch is a compile error where
/// fflight.h is included too), links against libfflight.a and calls through none of them.
#[test]
fn every_exported_gl15_function_links_with_the_system_prototypes() {
    let not_yet = names("docs/gl15-not-exported.txt");
    let functions: Vec<String> = names("docs/gl15-functions.txt")
        .into_iter()
        .filter(|f| !not_yet.contains(f))
        .collect();
    let mut source = String::from(
        "#define GL_GLEXT_PROTOTYPES 1\n#include <GL/gl.h>\n#include <GL/glext.h>\n\
         #include \"fflight.h\"\n#include <stdio.h>\n\n\
         typedef void (*any_function)(void);\n\nstatic const any_function functions[] = {\n",
    );
    for f in &functions {
        source.push_str(&format!("    (any_function){f},\n"));
    }
    source.push_str(
        "};\n\nint main(void)\n{\n    size_t i, linked = 0;\n    \
         for (i = 0; i < sizeof functions / sizeof functions[0]; i++)\n        \
         linked += functions[i] != NULL;\n    printf(\"%u\\n\", (unsigned)linked);\n    \
         return 0;\n}\n",
    );
    let dir = manifest_dir().join("target/gl15_addresses");
    std::fs::create_dir_all(&dir).expect("create target/gl15_addresses");
    let c_file = dir.join("gl15_addresses.c");
    std::fs::write(&c_file, source).expect("write the C program");
    let static_library = shared_library().with_file_name("libfflight.a");
    let exe = dir.join("gl15_addresses");
    let compile = Command::new("gcc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"])
        .arg("-I")
        .arg(manifest_dir().join("include"))
        .arg(&c_file)
        .arg(&static_library)
        .args(["-lm", "-lpthread", "-ldl", "-o"])
        .arg(&exe)
        .output()
        .expect("gcc is installed");
    assert!(
        compile.status.success(),
        "{}",
        String::from_utf8_lossy(&compile.stderr)
    );
    let run = Command::new(&exe).output().expect("run gl15_addresses");
    assert_eq!(
        String::from_utf8_lossy(&run.stdout).trim(),
        functions.len().to_string()
    );
}
