//! Generates the fuzz harness's call table (`fuzz/src/calls.rs`) and the libFuzzer dictionary
//! (`fuzz/gl_enums.dict`) from `include/fflight.h`: one decoder line per exported function,
//! so every entry point the library exports is reachable by the fuzzer, and the table cannot
//! drift from the header (`tests/fuzz_replay.rs` regenerates both and compares; `FFLIGHT_BLESS=1`
//! rewrites them).
//!
//! Each argument is decoded by its C type and, for integers, by its name (`width` and the
//! other sizes are kept small so the fuzzer's buffers always hold what GL reads: a C caller
//! guarantees that, and fflight's safety rests on it). Pointers point into the harness's
//! arena; a few functions are handled by hand in `harness.rs` (contexts, feedback and
//! selection buffers, glRenderMode, glGetError, ...).

/// One C parameter.
struct Param {
    ty: String,
    name: String,
}

/// One prototype of the header.
struct Prototype {
    ret: String,
    name: String,
    params: Vec<Param>,
}

/// Functions `harness.rs` calls itself (`Harness::special`): their arguments need care (a
/// buffer that must outlive the call, a context handle) or their results are checked.
pub const SPECIAL: &[&str] = &[
    "fflCreateContext",
    "fflMakeCurrent",
    "fflDestroyContext",
    "fflGetCurrentContext",
    "fflSetThreads",
    "fflCaptureReadVertices",
    "glFeedbackBuffer",
    "glSelectBuffer",
    "glRenderMode",
    "glGetError",
    "glMultiDrawElements",
    "glPixelStoref",
    "glPixelStorei",
    "glCallList",
    "glCallLists",
];

fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(start) = rest.find("/*") {
        out.push_str(&rest[..start]);
        match rest[start..].find("*/") {
            Some(end) => rest = &rest[start + end + 2..],
            None => return out,
        }
    }
    out.push_str(rest);
    out
}

fn parse_param(text: &str) -> Param {
    let text = text.trim();
    // `const GLfloat m[16]` is a pointer.
    let (text, array) = match text.find('[') {
        Some(at) => (&text[..at], true),
        None => (text, false),
    };
    let split = text
        .rfind(|c: char| !(c.is_alphanumeric() || c == '_'))
        .expect("a parameter has a type and a name");
    let name = text[split + 1..].to_string();
    let mut ty = text[..split + 1]
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    ty = ty.replace(" *", "*").replace("* ", "*");
    if array {
        ty.push('*');
    }
    Param { ty, name }
}

fn prototypes(header: &str) -> Vec<Prototype> {
    let text = strip_comments(header);
    let mut out = Vec::new();
    let mut statement = String::new();
    for line in text.lines() {
        let line = line.trim();
        if line.starts_with('#') || line.is_empty() {
            continue;
        }
        statement.push(' ');
        statement.push_str(line);
        if !line.ends_with(';') && !line.ends_with('{') && !line.ends_with('}') {
            continue;
        }
        let s = std::mem::take(&mut statement);
        let s = s.trim();
        if !s.ends_with(");") || s.starts_with("typedef") || s.contains('{') {
            continue;
        }
        let open = s.find('(').unwrap();
        let head = s[..open].trim();
        let split = head
            .rfind(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap();
        let name = head[split + 1..].to_string();
        if !(name.starts_with("gl") || name.starts_with("ffl")) {
            continue;
        }
        let ret = head[..split + 1]
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        let ret = ret.replace(" *", "*");
        let inner = s[open + 1..s.len() - 2].trim();
        let params = if inner == "void" || inner.is_empty() {
            Vec::new()
        } else {
            inner.split(',').map(parse_param).collect()
        };
        out.push(Prototype { ret, name, params });
    }
    out
}

/// The Rust type of a C type (struct pointers are opaque).
fn rust_type(c: &str) -> String {
    let c = c.trim();
    if let Some(pointee) = c.strip_suffix('*') {
        let pointee = pointee.trim();
        // `const T *` or, for a pointer to a pointer, `T *const *`.
        let (constant, pointee) = match (
            pointee.strip_prefix("const "),
            pointee.strip_suffix("const"),
        ) {
            (_, Some(inner)) if inner.trim_end().ends_with('*') => (true, inner.trim()),
            (Some(base), _) => (true, base.trim()),
            _ => (false, pointee),
        };
        let pointee = if pointee.starts_with("struct ") || pointee == "void" {
            "c_void".to_string()
        } else {
            rust_type(pointee)
        };
        return format!("*{} {pointee}", if constant { "const" } else { "mut" });
    }
    match c {
        "void" => "()".to_string(),
        other => other.to_string(),
    }
}

/// How the harness decodes an integer argument, chosen by the parameter's name: the sizes of
/// what GL reads or writes through a pointer stay small, as a C caller's buffers bound them.
fn int_class(function: &str, name: &str) -> &'static str {
    match name {
        "width" | "height" | "depth" | "i1" | "i2" | "j1" | "j2" | "un" | "vn" | "uorder"
        | "vorder" | "order" => "IntClass::Dimension",
        "stride" | "ustride" | "vstride" => "IntClass::Stride",
        _ if name.ends_with("_stride") => "IntClass::Stride",
        "count" | "n" | "size" | "range" | "mapsize" | "first" | "primcount" | "offset"
        | "bufsize" | "bufSize" | "start" | "end" => "IntClass::Count",
        _ if function.starts_with("glPixelStore") => "IntClass::Dimension",
        _ => "IntClass::Any",
    }
}

fn decode(function: &str, param: &Param, index: usize) -> String {
    let ty = param.ty.as_str();
    let rust = rust_type(ty);
    if ty.ends_with('*') {
        let constant = ty.starts_with("const");
        let base = ty
            .trim_start_matches("const ")
            .trim_end_matches('*')
            .trim_end_matches("const")
            .trim();
        let region = match base {
            "GLfloat" | "GLclampf" => "Region::Floats",
            "GLdouble" | "GLclampd" => "Region::Doubles",
            "GLfixed" | "GLclampx" => "Region::Fixed",
            "GLint" | "GLuint" | "GLsizei" | "GLenum" => "Region::Ints",
            "GLshort" | "GLushort" => "Region::Shorts",
            "GLbyte" | "GLubyte" | "GLboolean" => "Region::Bytes",
            "void*" | "const void*" => "Region::Pointers",
            _ => "Region::Any",
        };
        return if constant {
            format!("h.input_pointer({region}) as {rust}")
        } else {
            format!("h.output_pointer({index}) as {rust}")
        };
    }
    match ty {
        "GLenum" => "h.enumeration()".to_string(),
        "GLfloat" | "GLclampf" => "h.float()".to_string(),
        "GLdouble" | "GLclampd" => "h.double()".to_string(),
        "GLboolean" => "h.byte()".to_string(),
        "GLbitfield" => "h.bitfield()".to_string(),
        "GLint" | "GLuint" | "GLsizei" | "GLshort" | "GLushort" | "GLbyte" | "GLubyte"
        | "GLfixed" | "GLclampx" | "GLintptr" | "GLsizeiptr" => {
            let class = int_class(function, &param.name);
            format!("h.integer({class}) as {rust}")
        }
        other => panic!("{function}: no decoder for parameter type `{other}`"),
    }
}

/// The call table: `calls.rs`.
pub fn calls(header: &str) -> String {
    let protos = prototypes(header);
    let mut s = String::new();
    s.push_str(
        "// Generated by fuzz/src/generate.rs from include/fflight.h: do not edit.\n\
         // `FFLIGHT_BLESS=1 cargo test --test fuzz_replay` regenerates it.\n\n",
    );
    s.push_str("unsafe extern \"C\" {\n");
    for p in &protos {
        let params: Vec<String> = p
            .params
            .iter()
            .map(|q| format!("{}: {}", rust_name(&q.name), rust_type(&q.ty)))
            .collect();
        let ret = rust_type(&p.ret);
        let ret = if ret == "()" {
            String::new()
        } else {
            format!(" -> {ret}")
        };
        s.push_str(&format!("    fn {}({}){ret};\n", p.name, params.join(", ")));
    }
    s.push_str("}\n\n/// Every exported function, in the header's order.\n");
    s.push_str("pub const FUNCTIONS: &[&str] = &[\n");
    for p in &protos {
        s.push_str(&format!("    \"{}\",\n", p.name));
    }
    s.push_str("];\n\n");
    s.push_str(
        "/// Calls function `index` of [`FUNCTIONS`] with arguments decoded from the input.\n\
         #[allow(clippy::unnecessary_cast, clippy::let_unit_value, unused_unsafe)]\n\
         pub fn call(h: &mut Harness, index: usize) {\n    match index {\n",
    );
    for (i, p) in protos.iter().enumerate() {
        if SPECIAL.contains(&p.name.as_str()) {
            s.push_str(&format!("        {i} => h.special(\"{}\"),\n", p.name));
            continue;
        }
        s.push_str(&format!("        {i} => {{\n"));
        let mut args = Vec::new();
        for (k, q) in p.params.iter().enumerate() {
            s.push_str(&format!(
                "            let a{k} = {};\n",
                decode(&p.name, q, k)
            ));
            args.push(format!("a{k}"));
        }
        s.push_str(&format!(
            "            let _ = unsafe {{ {}({}) }};\n        }}\n",
            p.name,
            args.join(", ")
        ));
    }
    s.push_str("        _ => {}\n    }\n}\n\n");
    s.push_str("/// Every GL enum value of the header, for arguments of type GLenum.\n");
    s.push_str("pub const ENUMS: &[u32] = &[\n");
    for value in enums(header) {
        s.push_str(&format!("    {value:#x},\n"));
    }
    s.push_str("];\n");
    s
}

fn rust_name(name: &str) -> String {
    match name {
        "type" | "ref" | "fn" | "mod" | "in" | "match" => format!("{name}_"),
        other => other.to_string(),
    }
}

/// The distinct values of the header's `#define GL_* <number>`, sorted.
fn enums(header: &str) -> Vec<u32> {
    let mut values: Vec<u32> = header
        .lines()
        .filter_map(|line| {
            let rest = line.trim().strip_prefix("#define GL_")?;
            let value = rest.split_whitespace().nth(1)?;
            let value = value.trim_end_matches(['u', 'U']);
            match value
                .strip_prefix("0x")
                .or_else(|| value.strip_prefix("0X"))
            {
                Some(hex) => u32::from_str_radix(hex, 16).ok(),
                None => value.parse::<u32>().ok(),
            }
        })
        .collect();
    values.sort_unstable();
    values.dedup();
    values
}

/// The libFuzzer dictionary: every GL enum as the 4 little-endian bytes the harness decodes
/// a raw GLenum from.
pub fn dictionary(header: &str) -> String {
    let mut s = String::from(
        "# GL enum values of include/fflight.h as the harness reads a raw GLenum (4 bytes,\n\
         # little-endian). Generated by fuzz/src/generate.rs: do not edit.\n",
    );
    for value in enums(header) {
        let bytes: String = value
            .to_le_bytes()
            .iter()
            .map(|b| format!("\\x{b:02X}"))
            .collect();
        s.push_str(&format!("\"{bytes}\"\n"));
    }
    s
}
