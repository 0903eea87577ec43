//! The entry-point sweep (issue 9): every function `include/fflight.h` declares, called with
//! hostile arguments by a generated C program, `tests/sweep/sweep.c`.
//!
//! This test parses the header's prototypes and `#define GL_*` values, writes
//! `target/sweep/sweep_functions.h` (one caller per function, its parameter types and names,
//! every enum value), compiles `tests/sweep/sweep.c` against it and `libfflight.a`, and runs
//! it with a fixed seed. A function added to the header is swept the day it is added; one
//! with a pointer parameter the program has no size rule for fails the run (the program
//! says which). What the program checks is described at the top of `tests/sweep/sweep.c`.
//!
//! `make test-sweep-sanitize` builds the same program under ASan and UBSan, and
//! `make test-valgrind` runs it under memcheck (both after `cargo test`, which writes the
//! generated header).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

fn manifest_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// One parameter: its C type as written (arrays `T name[16]` become `T *`) and its name.
#[derive(Debug, Clone)]
struct Param {
    ty: String,
    name: String,
}

#[derive(Debug, Clone)]
struct Prototype {
    ret: String,
    name: String,
    params: Vec<Param>,
}

/// The header without its comments.
fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(start) = rest.find("/*") {
        out.push_str(&rest[..start]);
        rest = match rest[start..].find("*/") {
            Some(end) => &rest[start + end + 2..],
            None => "",
        };
    }
    out.push_str(rest);
    out.lines()
        .map(|line| line.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

fn parse_param(text: &str) -> Param {
    let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
    let (text, array) = match text.find('[') {
        Some(at) => (text[..at].trim().to_string(), true),
        None => (text, false),
    };
    let split = text
        .rfind(|c: char| !(c.is_alphanumeric() || c == '_'))
        .expect("a parameter has a type and a name");
    let mut ty = text[..=split].trim().to_string();
    if array {
        ty.push_str(" *");
    }
    let ty = ty.replace(" *", "*").replace('*', " *").replace("  ", " ");
    Param {
        ty: ty.trim().to_string(),
        name: text[split + 1..].to_string(),
    }
}

/// Every function prototype of the header, in header order.
fn prototypes(header: &str) -> Vec<Prototype> {
    let text = strip_comments(header);
    let mut out = Vec::new();
    // Statements end with ';': join each one onto a line.
    for statement in text.split(';') {
        let statement = statement.split_whitespace().collect::<Vec<_>>().join(" ");
        let statement = statement
            .rsplit(['}', '{'])
            .next()
            .unwrap_or("")
            .trim()
            .to_string();
        let statement = statement
            .split("#endif")
            .last()
            .unwrap_or("")
            .trim()
            .to_string();
        if statement.starts_with("typedef") || statement.starts_with('#') {
            continue;
        }
        let Some(open) = statement.find('(') else {
            continue;
        };
        if !statement.ends_with(')') {
            continue;
        }
        let head = statement[..open].trim();
        let Some(split) = head.rfind(|c: char| !(c.is_alphanumeric() || c == '_')) else {
            continue;
        };
        let name = head[split + 1..].to_string();
        if !(name.starts_with("gl") || name.starts_with("ffl")) {
            continue;
        }
        let ret = head[..=split].trim().replace(" *", "*").replace('*', " *");
        let args = &statement[open + 1..statement.len() - 1];
        let params = if args.trim() == "void" || args.trim().is_empty() {
            Vec::new()
        } else {
            args.split(',').map(parse_param).collect()
        };
        out.push(Prototype {
            ret: ret.trim().to_string(),
            name,
            params,
        });
    }
    out
}

/// Every `#define GL_NAME value` of the header.
fn enum_values(header: &str) -> Vec<(String, u64)> {
    header
        .lines()
        .filter_map(|line| {
            let mut words = line.split_whitespace();
            (words.next()? == "#define").then_some(())?;
            let name = words.next()?;
            let value = words.next()?;
            if !name.starts_with("GL_") {
                return None;
            }
            let value = match value.strip_prefix("0x") {
                Some(hex) => u64::from_str_radix(hex, 16).ok()?,
                None => value.parse().ok()?,
            };
            Some((name.to_string(), value))
        })
        .collect()
}

/// The sweep's kind of a C type (tests/sweep/sweep.c's `enum sweep_type`).
fn kind(ty: &str) -> &'static str {
    let base = ty.replace("const ", "");
    let base = base.trim();
    if base.ends_with("* *") || base.ends_with("**") || base == "void * *" {
        return "SWEEP_POINTER_ARRAY";
    }
    if base.ends_with('*') {
        return "SWEEP_POINTER";
    }
    match base {
        "GLenum" => "SWEEP_ENUM",
        "GLboolean" => "SWEEP_BOOLEAN",
        "GLbitfield" => "SWEEP_BITFIELD",
        "GLbyte" | "GLshort" | "GLint" | "GLubyte" | "GLushort" | "GLuint" | "GLfixed"
        | "GLclampx" => "SWEEP_INTEGER",
        "GLsizei" => "SWEEP_SIZE",
        "GLintptr" | "GLsizeiptr" => "SWEEP_POINTER_SIZED",
        "GLfloat" | "GLclampf" | "GLdouble" | "GLclampd" => "SWEEP_REAL",
        other => panic!("the sweep has no kind for the C type {other:?}"),
    }
}

/// The element type a pointer parameter points to, for `sizeof` (void: bytes).
fn pointee(ty: &str) -> String {
    if ty.matches('*').count() > 1 {
        return "void *".into(); // an array of pointers
    }
    let base = ty.replace("const ", "");
    match base.trim().trim_end_matches('*').trim() {
        "void" | "struct FflContext" => "unsigned char".into(),
        other => other.into(),
    }
}

fn generate(protos: &[Prototype], enums: &[(String, u64)]) -> String {
    let mut out = String::new();
    out.push_str("/* Generated by tests/sweep.rs from include/fflight.h: do not edit. */\n\n");
    writeln!(out, "#define SWEEP_FUNCTION_COUNT {}", protos.len()).unwrap();
    out.push_str("enum sweep_function_id {\n");
    for p in protos {
        writeln!(out, "    FN_{},", p.name).unwrap();
    }
    out.push_str("};\n\n");
    for p in protos {
        writeln!(
            out,
            "static void call_{}(union sweep_arg *a, union sweep_arg *ret)\n{{",
            p.name
        )
        .unwrap();
        let args = p
            .params
            .iter()
            .enumerate()
            .map(|(i, param)| {
                let member = match kind(&param.ty) {
                    "SWEEP_POINTER" | "SWEEP_POINTER_ARRAY" => "p",
                    "SWEEP_REAL" => "f",
                    _ => "i",
                };
                format!("({})a[{i}].{member}", param.ty)
            })
            .collect::<Vec<_>>()
            .join(", ");
        let call = format!("{}({args})", p.name);
        match p.ret.as_str() {
            "void" => writeln!(out, "    (void)a; (void)ret; {call};").unwrap(),
            r if r.ends_with('*') => {
                writeln!(out, "    (void)a; ret->p = (void *){call};").unwrap()
            }
            _ => writeln!(out, "    (void)a; ret->i = (long long){call};").unwrap(),
        }
        out.push_str("}\n");
    }
    out.push_str(
        "\nstatic const struct sweep_function SWEEP_FUNCTIONS[SWEEP_FUNCTION_COUNT] = {\n",
    );
    for p in protos {
        write!(
            out,
            "    {{ \"{}\", call_{}, {}, {}, {{",
            p.name,
            p.name,
            p.params.len(),
            match p.ret.as_str() {
                "void" => "SWEEP_RETURNS_NOTHING",
                r if r.ends_with('*') => "SWEEP_RETURNS_POINTER",
                _ => "SWEEP_RETURNS_VALUE",
            }
        )
        .unwrap();
        for param in &p.params {
            let k = kind(&param.ty);
            let (size, constant) = if k.starts_with("SWEEP_POINTER") && k != "SWEEP_POINTER_SIZED" {
                (
                    format!("sizeof({})", pointee(&param.ty)),
                    param.ty.starts_with("const"),
                )
            } else {
                (format!("sizeof({})", param.ty), false)
            };
            let integer_type = match param.ty.as_str() {
                "GLbyte" => "SWEEP_SIGNED",
                "GLshort" | "GLint" | "GLfixed" | "GLclampx" | "GLsizei" | "GLintptr"
                | "GLsizeiptr" => "SWEEP_SIGNED",
                _ => "SWEEP_UNSIGNED",
            };
            write!(
                out,
                " {{ {k}, {size}, {}, {integer_type}, \"{}\", \"{}\" }},",
                constant as i32, param.ty, param.name
            )
            .unwrap();
        }
        if p.params.is_empty() {
            out.push_str(" { SWEEP_NONE, 0, 0, SWEEP_UNSIGNED, \"\", \"\" }");
        }
        out.push_str(" } },\n");
    }
    out.push_str("};\n\n");
    let mut values: Vec<u64> = enums
        .iter()
        .map(|(_, v)| *v)
        .filter(|v| *v <= u32::MAX as u64)
        .collect();
    values.sort_unstable();
    values.dedup();
    writeln!(
        out,
        "#define SWEEP_ENUM_COUNT {}\nstatic const GLenum SWEEP_ENUMS[SWEEP_ENUM_COUNT] = {{",
        values.len()
    )
    .unwrap();
    for chunk in values.chunks(8) {
        let line = chunk
            .iter()
            .map(|v| format!("0x{v:x}u"))
            .collect::<Vec<_>>()
            .join(", ");
        writeln!(out, "    {line},").unwrap();
    }
    out.push_str("};\n");
    out
}

/// The static library `cargo test` just built (the newer of deps/ and the profile's).
fn static_library() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let deps = exe.parent().unwrap();
    [
        deps.join("libfflight.a"),
        deps.parent().unwrap().join("libfflight.a"),
    ]
    .into_iter()
    .filter_map(|p| Some((std::fs::metadata(&p).ok()?.modified().ok()?, p)))
    .max()
    .map(|(_, p)| p)
    .expect("libfflight.a next to the test binary")
}

fn out_dir() -> PathBuf {
    let dir = manifest_dir().join("target/sweep");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Writes the generated header and returns the prototypes.
fn write_generated() -> Vec<Prototype> {
    let header = std::fs::read_to_string(manifest_dir().join("include/fflight.h")).unwrap();
    let protos = prototypes(&header);
    let generated = generate(&protos, &enum_values(&header));
    let path = out_dir().join("sweep_functions.h");
    if std::fs::read_to_string(&path).ok().as_deref() != Some(generated.as_str()) {
        std::fs::write(&path, generated).unwrap();
    }
    protos
}

fn compile(source: &Path, exe: &Path) {
    let out = Command::new(std::env::var("CC").unwrap_or_else(|_| "gcc".into()))
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
            "-O1",
            "-g",
            "-D_DEFAULT_SOURCE",
        ])
        .arg("-I")
        .arg(manifest_dir().join("include"))
        .arg("-I")
        .arg(out_dir())
        .arg(source)
        .arg(static_library())
        .args(["-lm", "-lpthread", "-ldl", "-o"])
        .arg(exe)
        .output()
        .expect("run the C compiler");
    assert!(
        out.status.success(),
        "compiling {}:\n{}",
        source.display(),
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn the_header_parses_into_every_exported_function() {
    let header = std::fs::read_to_string(manifest_dir().join("include/fflight.h")).unwrap();
    let protos = prototypes(&header);
    let names: std::collections::BTreeSet<&str> = protos.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names.len(), protos.len(), "a function declared twice");
    // Every GL 1.5 function and every fflight one the docs list is among the prototypes.
    for list in ["docs/gl15-functions.txt", "docs/fflight-functions.txt"] {
        let text = std::fs::read_to_string(manifest_dir().join(list)).unwrap();
        for name in text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.is_empty())
        {
            assert!(
                names.contains(name.trim()) || list.contains("gl15") && !header.contains(name),
                "{name} ({list}) is not among the parsed prototypes"
            );
        }
    }
    let multi = protos
        .iter()
        .find(|p| p.name == "glMultiDrawElements")
        .unwrap();
    assert_eq!(multi.params.len(), 5);
    assert_eq!(multi.params[3].ty, "const void *const *");
    let transpose = protos
        .iter()
        .find(|p| p.name == "glLoadTransposeMatrixf")
        .unwrap();
    assert_eq!(transpose.params[0].ty, "const GLfloat *");
}

/// How long the sweep may run (it stops its random phase by itself well before).
const RUN_TIMEOUT: Duration = Duration::from_secs(120);

#[test]
fn every_entry_point_survives_hostile_arguments() {
    let protos = write_generated();
    let exe = out_dir().join("sweep");
    compile(&manifest_dir().join("tests/sweep/sweep.c"), &exe);
    let start = Instant::now();
    let mut child = Command::new(&exe)
        .env("SWEEP_SECONDS", "20")
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > RUN_TIMEOUT {
            child.kill().ok();
            panic!("the sweep ran longer than {RUN_TIMEOUT:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let out = child.wait_with_output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    println!("{stdout}");
    assert!(
        status.success(),
        "the sweep failed ({status}):\n{stdout}\n{stderr}"
    );
    // A panic inside fflight is caught at the C boundary (the call returns, nothing crashes)
    // but is a bug all the same: Rust prints it on stderr.
    assert!(
        !stderr.contains("panicked at"),
        "a call panicked inside fflight:\n{stderr}"
    );
    // The program's own count of the functions it called, in every situation.
    let called = stdout
        .lines()
        .find_map(|l| l.strip_prefix("functions called: "))
        .and_then(|l| l.split_whitespace().next())
        .and_then(|n| n.parse::<usize>().ok())
        .expect("the sweep reports how many functions it called");
    assert_eq!(
        called,
        protos.len(),
        "not every declared function was called"
    );
}
