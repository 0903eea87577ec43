//! Generates src/capi/generated.rs from the one-line declarations of src/capi/entry_points.txt.
//!
//! Why generated source rather than a `macro_rules!` table: cbindgen does not expand macros on
//! stable Rust, so entry points a macro made would be exported but missing from
//! include/fflight.h. Written out as plain `#[unsafe(no_mangle)] pub extern "C" fn`s, cbindgen
//! declares them like the hand-written ones, from the same C types, and the file stays readable
//! and reviewable. The table carries each C declaration as <GL/gl.h> spells it, so the exported
//! signature is the system header's by construction (tests/header.rs compiles the two together).
//!
//! The format, one entry point a line:
//!
//! ```text
//! /// Doc comment lines, copied to the function (and so to the header).
//! void glFogfv(GLenum pname, const GLfloat *params[fog_param_count(pname)]) => ctx.fog(pname, params)
//! void glGetPixelMapfv(GLenum map, GLfloat *values[out]) => ctx.get_pixel_map(map)
//! ```
//!
//! Left of `=>`, the C declaration; a pointer parameter carries in brackets how many values the
//! command reads (a Rust `usize` expression over the other parameters and `ctx`, evaluated
//! before the command runs, so it must be 0 where the parameters define no count, say for a
//! bad pname; NULL gives an empty slice, which the command rejects when it needs values), or
//! `out` for the one parameter the command writes what the expression returns. A non-const
//! pointer with a count instead is handed to the expression as a `&mut` slice of that many values
//! (glGetPolygonStipple packs bits into the application's bytes). Right of `=>`, a Rust
//! expression over `ctx` (the current `&mut Context`) and the parameters, with the pointers already read into slices: a
//! `GlResult<R>` for a function returning `R`, or, with an `out` parameter, a `GlResult` of the
//! values to write there. `use` lines are copied to the top of the generated file; `#` lines
//! and blank lines are comments.

use std::fmt::Write as _;

/// What the command does with a pointer parameter.
#[derive(PartialEq)]
enum Pointer {
    /// Reads this many values.
    Read(String),
    /// Writes into this many values, handed to it as a slice.
    Fill(String),
    /// Receives the values the expression returns.
    Out,
}

struct Parameter {
    name: String,
    rust_type: String,
    pointer: Option<Pointer>,
}

struct EntryPoint {
    docs: Vec<String>,
    name: String,
    returns: Option<String>,
    parameters: Vec<Parameter>,
    body: String,
}

/// The Rust spelling of a C type name (`void` only behind a pointer).
fn rust_type(c_type: &str) -> Result<&str, String> {
    match c_type {
        "void" | "GLvoid" => Ok("c_void"),
        t if t.starts_with("GL") && t.chars().all(|c| c.is_ascii_alphanumeric()) => Ok(t),
        t => Err(format!("unknown C type `{t}`")),
    }
}

/// Splits at the commas that are not inside brackets or parentheses.
fn split_top_level(text: &str) -> Vec<&str> {
    let (mut parts, mut depth, mut start) = (Vec::new(), 0i32, 0);
    for (i, c) in text.char_indices() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&text[start..]);
    parts
}

fn parse_parameter(text: &str) -> Result<Parameter, String> {
    let (declaration, count) = match text.find('[') {
        Some(open) => {
            let close = text.rfind(']').ok_or("unclosed `[`")?;
            (
                &text[..open],
                Some(text[open + 1..close].trim().to_string()),
            )
        }
        None => (text, None),
    };
    let spaced = declaration.replace('*', " * ");
    let mut words: Vec<&str> = spaced.split_whitespace().collect();
    let name = words.pop().ok_or("a parameter without a name")?.to_string();
    let is_const = words.first() == Some(&"const");
    if is_const {
        words.remove(0);
    }
    let is_pointer = words.last() == Some(&"*");
    if is_pointer {
        words.pop();
    }
    let [c_type] = words[..] else {
        return Err(format!("cannot read the parameter `{text}`"));
    };
    let base = rust_type(c_type)?;
    let (rust_type, pointer) = match (is_pointer, count) {
        (false, None) if base != "c_void" => (base.to_string(), None),
        (true, Some(count)) if is_const && count != "out" => {
            (format!("*const {base}"), Some(Pointer::Read(count)))
        }
        (true, Some(count)) if !is_const && count == "out" => {
            (format!("*mut {base}"), Some(Pointer::Out))
        }
        (true, Some(count)) if !is_const => (format!("*mut {base}"), Some(Pointer::Fill(count))),
        _ => {
            return Err(format!(
                "`{text}`: a pointer needs `[count]` or (not const) `[out]`, \
                 and only a pointer takes brackets"
            ));
        }
    };
    Ok(Parameter {
        name,
        rust_type,
        pointer,
    })
}

fn parse_entry_point(line: &str, docs: Vec<String>) -> Result<EntryPoint, String> {
    let (declaration, body) = line.split_once("=>").ok_or("no `=>`")?;
    let open = declaration.find('(').ok_or("no `(`")?;
    let close = declaration.rfind(')').ok_or("no `)`")?;
    let mut head = declaration[..open].split_whitespace();
    let (Some(returns), Some(name), None) = (head.next(), head.next(), head.next()) else {
        return Err("expected `<return type> <name>(`".into());
    };
    let parameter_list = declaration[open + 1..close].trim();
    let parameters = if parameter_list == "void" {
        Vec::new()
    } else {
        split_top_level(parameter_list)
            .into_iter()
            .map(parse_parameter)
            .collect::<Result<Vec<_>, _>>()?
    };
    if parameters
        .iter()
        .filter(|p| p.pointer == Some(Pointer::Out))
        .count()
        > 1
    {
        return Err("more than one `[out]` parameter".into());
    }
    let returns = match returns {
        "void" => None,
        t => Some(rust_type(t)?.to_string()),
    };
    if returns.is_some() && parameters.iter().any(|p| p.pointer == Some(Pointer::Out)) {
        return Err("a function with a result cannot also have an `[out]` parameter".into());
    }
    Ok(EntryPoint {
        docs,
        name: name.to_string(),
        returns,
        parameters,
        body: body.trim().to_string(),
    })
}

fn write_entry_point(out: &mut String, entry: &EntryPoint) {
    let pointers: Vec<&Parameter> = entry
        .parameters
        .iter()
        .filter(|p| p.pointer.is_some())
        .collect();
    for doc in &entry.docs {
        let _ = writeln!(out, "{doc}");
    }
    if !pointers.is_empty() {
        if !entry.docs.is_empty() {
            out.push_str("///\n");
        }
        out.push_str("/// # Safety\n");
        for p in &pointers {
            let _ = match p.pointer {
                Some(Pointer::Read(_)) => writeln!(
                    out,
                    "/// `{}` is NULL or points to the values the command reads.",
                    p.name
                ),
                _ => writeln!(
                    out,
                    "/// `{}` is NULL or has room for the values the command writes.",
                    p.name
                ),
            };
        }
    }
    let parameters: Vec<String> = entry
        .parameters
        .iter()
        .map(|p| format!("{}: {}", p.name, p.rust_type))
        .collect();
    let _ = writeln!(
        out,
        "#[unsafe(no_mangle)]\npub {}extern \"C\" fn {}({}){} {{",
        if pointers.is_empty() { "" } else { "unsafe " },
        entry.name,
        parameters.join(", "),
        entry
            .returns
            .as_ref()
            .map_or(String::new(), |r| format!(" -> {r}"))
    );
    out.push_str("    with_context(|ctx| {\n");
    for p in &pointers {
        let (function, count) = match &p.pointer {
            Some(Pointer::Read(count)) => ("read", count),
            Some(Pointer::Fill(count)) => ("read_mut", count),
            _ => continue,
        };
        let _ = writeln!(
            out,
            "        // SAFETY: the caller's guarantee, forwarded.\n        \
             let {name} = unsafe {{ {function}({name}, {count}) }};",
            name = p.name
        );
    }
    match pointers.iter().find(|p| p.pointer == Some(Pointer::Out)) {
        Some(written) => {
            let _ = writeln!(
                out,
                "        let written = {}?;\n        \
                 // SAFETY: the caller's guarantee, forwarded.\n        \
                 unsafe {{ write({}, &written[..]) }}",
                entry.body, written.name
            );
        }
        None => {
            let _ = writeln!(out, "        {}", entry.body);
        }
    }
    out.push_str("    })\n}\n\n");
}

/// The Rust source for the table `table`, or the first line it cannot read.
pub fn generate(table: &str) -> Result<String, String> {
    let mut uses = Vec::new();
    let mut entries = Vec::new();
    let mut docs = Vec::new();
    for (number, line) in table.lines().enumerate() {
        let line = line.trim();
        if line.starts_with("///") {
            docs.push(line.to_string());
        } else if line.starts_with("use ") {
            uses.push(line.to_string());
        } else if !line.is_empty() && !line.starts_with('#') {
            let entry = parse_entry_point(line, std::mem::take(&mut docs))
                .map_err(|e| format!("line {}: {e}\n  {line}", number + 1))?;
            entries.push(entry);
        }
    }
    let mut out = String::from(
        "//! The entry points of src/capi/entry_points.txt, one function each.\n//!\n\
         //! @generated by build.rs (build/entry_points.rs): do not edit. `make header` \
         regenerates\n//! this file and the header; tests/header.rs fails when either is \
         stale.\n\n",
    );
    let uses_pointer = |wanted: fn(&Pointer) -> bool| {
        entries
            .iter()
            .flat_map(|e| &e.parameters)
            .any(|p| p.pointer.as_ref().is_some_and(wanted))
    };
    let imports: Vec<&str> = [
        (uses_pointer(|p| matches!(p, Pointer::Read(_))), "read"),
        (uses_pointer(|p| matches!(p, Pointer::Fill(_))), "read_mut"),
        (true, "with_context"),
        (uses_pointer(|p| *p == Pointer::Out), "write"),
    ]
    .iter()
    .filter(|(used, _)| *used)
    .map(|&(_, name)| name)
    .collect();
    let _ = writeln!(out, "use super::{{{}}};", imports.join(", "));
    if entries
        .iter()
        .flat_map(|e| &e.parameters)
        .any(|p| p.rust_type.ends_with("c_void"))
    {
        out.push_str("use std::ffi::c_void;\n");
    }
    out.push_str("use crate::gl::*;\n");
    for u in &uses {
        let _ = writeln!(out, "{u}");
    }
    out.push('\n');
    for entry in &entries {
        write_entry_point(&mut out, entry);
    }
    out.truncate(out.trim_end().len());
    out.push('\n');
    Ok(out)
}
