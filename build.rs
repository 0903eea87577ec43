//! Generates the table-made entry points (src/capi/entry_points.txt, see
//! build/entry_points.rs) and the C header with cbindgen into OUT_DIR; `FFLIGHT_BLESS=1` also
//! copies them over the checked-in `src/capi/generated.rs` and `include/fflight.h`
//! (tests/header.rs fails when a checked-in copy differs from its generated one).

#[path = "build/entry_points.rs"]
mod entry_points;

use std::env;
use std::fs;
use std::path::PathBuf;

fn main() {
    let crate_dir = PathBuf::from(env::var("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let out_dir = PathBuf::from(env::var("OUT_DIR").expect("set by cargo"));
    println!("cargo:rerun-if-changed=src");
    println!("cargo:rerun-if-changed=build");
    println!("cargo:rerun-if-changed=cbindgen.toml");
    println!("cargo:rerun-if-env-changed=FFLIGHT_BLESS");

    let bless = env::var_os("FFLIGHT_BLESS").is_some_and(|v| v == "1");

    // The shared library's SONAME: its major version (docs/abi.md), so that programs linked
    // against libfflight.so.0 load any 0.x release.
    let major = env::var("CARGO_PKG_VERSION_MAJOR").expect("set by cargo");
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libfflight.so.{major}");

    // First the entry points, so that a blessed run's header declares the new ones.
    let table = fs::read_to_string(crate_dir.join("src/capi/entry_points.txt"))
        .expect("src/capi/entry_points.txt exists");
    let generated =
        entry_points::generate(&table).unwrap_or_else(|e| panic!("src/capi/entry_points.txt, {e}"));
    fs::write(out_dir.join("generated.rs"), &generated).expect("OUT_DIR is writable");
    let checked_in = crate_dir.join("src/capi/generated.rs");
    if bless && fs::read_to_string(&checked_in).ok().as_deref() != Some(&generated) {
        fs::write(&checked_in, &generated).expect("src/capi is writable");
    }

    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml"))
        .expect("cbindgen.toml is valid");
    let mut bindings = Vec::new();
    cbindgen::generate_with_config(&crate_dir, config)
        .expect("cbindgen can read the crate")
        .write(&mut bindings);
    let header = guard_gl_names(&String::from_utf8(bindings).expect("cbindgen writes UTF-8"));
    let header = match_gl_array_parameters(header);

    let prefixed = prefixed_header(&header);
    fs::write(out_dir.join("fflight.h"), &header).expect("OUT_DIR is writable");
    fs::write(out_dir.join("fflight_prefixed.h"), &prefixed).expect("OUT_DIR is writable");
    if bless {
        fs::write(crate_dir.join("include/fflight.h"), &header).expect("include/ is writable");
        fs::write(crate_dir.join("include/fflight_prefixed.h"), &prefixed)
            .expect("include/ is writable");
    }
}

/// The header of libfflight_prefixed.a (tools/prefix_library.sh, docs/coexistence.md): the
/// same declarations with every GL function named `ffl_glX`, so that a program can include it
/// after the system <GL/gl.h> and call both libraries. Declarations start at column 0 and
/// name their function on their first line (comment lines start with a space).
fn prefixed_header(header: &str) -> String {
    let mut out = String::from(
        "/* fflight_prefixed.h: include/fflight.h for libfflight_prefixed.a, every GL function\n   \
         named ffl_glX (glLightfv is ffl_glLightfv); the ffl* functions keep their names. For\n   \
         programs that also link a real GL library: see docs/coexistence.md. */\n",
    );
    for line in header.lines() {
        let renamed = match line.as_bytes().first() {
            Some(c) if c.is_ascii_alphabetic() && line.contains('(') => prefix_gl_call(line),
            Some(b'#') => line.replace("FFLIGHT_H", "FFLIGHT_PREFIXED_H"),
            _ => line.to_string(),
        };
        out.push_str(&renamed);
        out.push('\n');
    }
    out
}

/// `ffl_` before the GL function name a declaration line names (`void glEnd(void);`).
fn prefix_gl_call(line: &str) -> String {
    let open = line.find('(').expect("a declaration has a `(`");
    let start = line[..open]
        .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .map_or(0, |i| i + 1);
    let name = &line[start..open];
    if name.starts_with("gl") && name[2..].starts_with(|c: char| c.is_ascii_uppercase()) {
        format!("{}ffl_{}", &line[..start], &line[start..])
    } else {
        line.to_string()
    }
}

/// Wraps every `#define GL_x` in `#ifndef GL_x`: the values are <GL/gl.h>'s, so either header
/// may come first.
fn guard_gl_names(header: &str) -> String {
    let mut out = String::new();
    for line in header.lines() {
        match line.strip_prefix("#define ") {
            Some(rest) if rest.starts_with("GL_") => {
                let name = rest.split_whitespace().next().unwrap_or(rest);
                out.push_str(&format!("#ifndef {name}\n{line}\n#endif\n"));
            }
            _ => {
                out.push_str(line);
                out.push('\n');
            }
        }
    }
    out
}

/// <GL/gl.h> declares the transpose-matrix parameters as `m[16]`; gcc's -Warray-parameter
/// rejects a pointer redeclaration, so the header spells them the same way.
fn match_gl_array_parameters(mut header: String) -> String {
    for function in ["glLoadTransposeMatrix", "glMultTransposeMatrix"] {
        for (suffix, ty) in [("f", "GLfloat"), ("d", "GLdouble")] {
            header = header.replace(
                &format!("{function}{suffix}(const {ty} *m)"),
                &format!("{function}{suffix}(const {ty} m[16])"),
            );
        }
    }
    header
}
