//! The checked-in C header and table-made entry points (src/capi/generated.rs) equal what
//! build.rs generates now, and the header compiles under the strictest flags alone and
//! together with the system <GL/gl.h>, in either order, and with <GL/glext.h>'s prototypes
//! (so every declaration matches the system headers' types).

use std::path::{Path, PathBuf};
use std::process::Command;

fn manifest_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// `path`, checked in, equals what build.rs generated this build.
fn assert_fresh(generated: &str, path: &str) {
    let checked_in = std::fs::read_to_string(manifest_dir().join(path))
        .unwrap_or_else(|e| panic!("{path}: {e}"));
    assert!(
        generated == checked_in,
        "{path} is stale: run `make header` (FFLIGHT_BLESS=1 cargo build) and commit it"
    );
}

#[test]
fn checked_in_header_matches_the_generated_one() {
    assert_fresh(
        include_str!(concat!(env!("OUT_DIR"), "/fflight.h")),
        "include/fflight.h",
    );
}

/// The header of libfflight_prefixed.a (docs/coexistence.md, tests/prefixed.rs).
#[test]
fn checked_in_prefixed_header_matches_the_generated_one() {
    assert_fresh(
        include_str!(concat!(env!("OUT_DIR"), "/fflight_prefixed.h")),
        "include/fflight_prefixed.h",
    );
}

#[test]
fn checked_in_entry_points_match_the_table() {
    assert_fresh(
        include_str!(concat!(env!("OUT_DIR"), "/generated.rs")),
        "src/capi/generated.rs",
    );
}

/// The header defines GL's names and its own guard only: a crate-internal `pub const` that
/// cbindgen would export belongs in cbindgen.toml's `exclude`.
#[test]
fn header_defines_only_gl_names() {
    let header = std::fs::read_to_string(manifest_dir().join("include/fflight.h")).unwrap();
    let strays: Vec<&str> = header
        .lines()
        .filter_map(|l| l.strip_prefix("#define "))
        .filter_map(|rest| rest.split_whitespace().next())
        .filter(|name| !name.starts_with("GL_") && *name != "FFLIGHT_H")
        .collect();
    assert!(
        strays.is_empty(),
        "not GL names: {strays:?} (see cbindgen.toml's exclude)"
    );
}

fn compile(name: &str, source: &str, extra_flags: &[&str]) {
    let dir = manifest_dir().join("target/header_tests");
    std::fs::create_dir_all(&dir).unwrap();
    let path: PathBuf = dir.join(name);
    std::fs::write(&path, source).unwrap();
    let output = Command::new("cc")
        .args(["-Wall", "-Wextra", "-Werror", "-pedantic", "-fsyntax-only"])
        .args(if extra_flags.is_empty() {
            &["-std=c99"][..]
        } else {
            extra_flags
        })
        .arg("-I")
        .arg(manifest_dir().join("include"))
        .arg(&path)
        .output()
        .expect("a C compiler (cc) is installed");
    assert!(
        output.status.success(),
        "{name} does not compile:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

const BODY: &str = "
int main(void) {
    GLfloat ambient[4] = {0.1f, 0.2f, 0.3f, 1.0f};
    GLfloat m[16] = {1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1};
    glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
    glLoadTransposeMatrixf(m);
    return (int)glGetError();
}
";

#[test]
fn header_compiles_alone() {
    compile("alone.c", &format!("#include \"fflight.h\"\n{BODY}"), &[]);
}

#[test]
fn header_compiles_after_the_system_gl_header() {
    compile(
        "gl_first.c",
        &format!("#include <GL/gl.h>\n#include \"fflight.h\"\n{BODY}"),
        &[],
    );
}

/// <GL/glext.h> declares the GL 1.4 and 1.5 functions only with GL_GLEXT_PROTOTYPES: a
/// declaration of fflight.h whose types differ from the system header's is then an error.
#[test]
fn header_compiles_after_the_system_gl_and_glext_prototypes() {
    compile(
        "glext_first.c",
        &format!(
            "#define GL_GLEXT_PROTOTYPES 1\n#include <GL/gl.h>\n#include <GL/glext.h>\n\
             #include \"fflight.h\"\n{BODY}"
        ),
        &[],
    );
}

#[test]
fn header_compiles_before_the_system_gl_header() {
    compile(
        "gl_last.c",
        &format!("#include \"fflight.h\"\n#include <GL/gl.h>\n{BODY}"),
        &[],
    );
}

#[test]
fn header_compiles_as_cpp() {
    compile(
        "as_cpp.c",
        &format!("#include \"fflight.h\"\n{BODY}"),
        &["-x", "c++", "-std=c++11"],
    );
}

/// The generator build.rs runs on src/capi/entry_points.txt.
#[path = "../build/entry_points.rs"]
mod entry_points;

/// One line of each kind makes the function it describes: reads before the call, a written
/// result through `write`, a filled slice through `read_mut`, docs and a safety section.
#[test]
fn the_entry_point_generator_writes_what_a_line_says() {
    let table = "\
use crate::state::fog::fog_param_count;
/// Fog.
void glFogfv(GLenum pname, const GLfloat *params[fog_param_count(pname).unwrap_or(0)]) => ctx.fog(pname, params)
void glGetPixelMapfv(GLenum map, GLfloat *values[out]) => ctx.get_pixel_map(map)
void glGetPolygonStipple(GLubyte *mask[ctx.polygon_stipple_pack_span()]) => ctx.get_polygon_stipple(mask)
GLboolean glIsEnabled(GLenum cap) => ctx.is_enabled(cap).map(GLboolean::from)
";
    let code = entry_points::generate(table).expect("a valid table");
    for expected in [
        "use super::{read, read_mut, with_context, write};",
        "use crate::state::fog::fog_param_count;",
        "/// Fog.\n///\n/// # Safety\n/// `params` is NULL or points to the values the command reads.\n",
        "pub unsafe extern \"C\" fn glFogfv(pname: GLenum, params: *const GLfloat) {",
        "let params = unsafe { read(params, fog_param_count(pname).unwrap_or(0)) };\n        \
         ctx.fog(pname, params)",
        "pub unsafe extern \"C\" fn glGetPixelMapfv(map: GLenum, values: *mut GLfloat) {",
        "let written = ctx.get_pixel_map(map)?;",
        "unsafe { write(values, &written[..]) }",
        "let mask = unsafe { read_mut(mask, ctx.polygon_stipple_pack_span()) };",
        "pub extern \"C\" fn glIsEnabled(cap: GLenum) -> GLboolean {",
    ] {
        assert!(code.contains(expected), "missing:\n{expected}\nin:\n{code}");
    }
}

/// A line the generator cannot read is an error naming it, never a guess.
#[test]
fn the_entry_point_generator_rejects_malformed_lines() {
    for (line, message) in [
        ("void glFoo(GLenum a)", "no `=>`"),
        (
            "void glFoo(const GLfloat *v) => ctx.foo(v)",
            "needs `[count]`",
        ),
        (
            "void glFoo(GLenum a[2]) => ctx.foo(a)",
            "only a pointer takes brackets",
        ),
        (
            "void glFoo(const GLfloat *v[out]) => ctx.foo(v)",
            "not const",
        ),
        ("void glFoo(unsigned a) => ctx.foo(a)", "unknown C type"),
        (
            "void glFoo(GLfloat *a[out], GLfloat *b[out]) => ctx.foo()",
            "more than one",
        ),
        (
            "GLint glFoo(GLfloat *a[out]) => ctx.foo()",
            "cannot also have",
        ),
    ] {
        let error = entry_points::generate(line).expect_err(line);
        assert!(
            error.contains(message) && error.contains("line 1"),
            "{line}: {error}"
        );
    }
}
