//! Generates the C header with cbindgen into OUT_DIR; `FFLIGHT_BLESS=1` also copies it over
//! the checked-in `include/fflight.h` (tests/header.rs fails when the two differ).

use std::env;
use std::fs;
use std::path::PathBuf;

fn main() {
    let crate_dir = PathBuf::from(env::var("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let out_dir = PathBuf::from(env::var("OUT_DIR").expect("set by cargo"));
    println!("cargo:rerun-if-changed=src");
    println!("cargo:rerun-if-changed=cbindgen.toml");
    println!("cargo:rerun-if-env-changed=FFLIGHT_BLESS");

    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml"))
        .expect("cbindgen.toml is valid");
    let mut generated = Vec::new();
    cbindgen::generate_with_config(&crate_dir, config)
        .expect("cbindgen can read the crate")
        .write(&mut generated);
    let header = guard_gl_names(&String::from_utf8(generated).expect("cbindgen writes UTF-8"));
    let header = match_gl_array_parameters(header);

    fs::write(out_dir.join("fflight.h"), &header).expect("OUT_DIR is writable");
    if env::var_os("FFLIGHT_BLESS").is_some_and(|v| v == "1") {
        fs::write(crate_dir.join("include/fflight.h"), &header).expect("include/ is writable");
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
