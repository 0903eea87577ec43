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
//!
//! A line that starts with `list` is a command display lists compile (§5.4):
//!
//! ```text
//! list void glFogfv(GLenum pname, const GLfloat *params[fog_param_count(pname).unwrap_or(0)]) => ctx.fog(pname, params)
//! ```
//!
//! A line that starts with `overlap` (before `list`) is a command that runs while batches of
//! points a primitive left to the helper thread at its glEnd are still lit (glBegin, whose
//! primitive streams them first); every other command first waits for them (`with_context`
//! against `with_context_overlapping`).
//!
//! The generator also writes a variant of `TableCommand` for it, holding its scalar
//! parameters and a copy of the values each pointer parameter reads (read at compile time, as
//! §5.4 says), and an arm of `TableCommand::execute` that runs the same expression on them.
//! While a list is being compiled the entry point records that variant instead of running
//! (GL_COMPILE) or as well (GL_COMPILE_AND_EXECUTE); see src/commands/list.rs. Such a
//! command returns nothing and writes nothing back: a query is never compiled.

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
    /// Compiled into display lists (the line starts with `list`).
    recordable: bool,
    /// Runs while a primitive's batches are still lit (the line starts with `overlap`).
    overlaps: bool,
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
    let (overlaps, line) = match line.strip_prefix("overlap ") {
        Some(rest) => (true, rest.trim_start()),
        None => (false, line),
    };
    let (recordable, line) = match line.strip_prefix("list ") {
        Some(rest) => (true, rest.trim_start()),
        None => (false, line),
    };
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
    if recordable
        && (returns.is_some()
            || parameters
                .iter()
                .any(|p| matches!(p.pointer, Some(Pointer::Out | Pointer::Fill(_)))))
    {
        return Err("a `list` command returns nothing and writes nothing back".into());
    }
    Ok(EntryPoint {
        docs,
        recordable,
        overlaps,
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
    out.push_str(if entry.overlaps {
        "    with_context_overlapping(|ctx| {\n"
    } else {
        "    with_context(|ctx| {\n"
    });
    for p in &pointers {
        let (function, count) = match &p.pointer {
            Some(Pointer::Read(count)) => ("read", count),
            Some(Pointer::Fill(count)) => ("read_mut", count),
            _ => continue,
        };
        // Untyped memory is read and written as bytes.
        let cast = if p.rust_type.ends_with("c_void") {
            ".cast::<u8>()"
        } else {
            ""
        };
        let _ = writeln!(
            out,
            "        // SAFETY: the caller's guarantee, forwarded.\n        \
             let {name} = unsafe {{ {function}({name}{cast}, {count}) }};",
            name = p.name
        );
    }
    if entry.recordable {
        let fields: Vec<String> = entry
            .parameters
            .iter()
            .map(|p| match p.pointer {
                Some(_) => format!("{}: {}.to_vec()", p.name, p.name),
                None => p.name.clone(),
            })
            .collect();
        let _ = writeln!(
            out,
            "        if ctx.record(|| TableCommand::{} {{ {} }}.into()) {{
            \
             return Ok(());
        }}",
            entry.name,
            fields.join(", ")
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

/// `TableCommand`, one variant per `list` line, and its `execute`: the line's expression on
/// the recorded values.
fn write_table_commands(out: &mut String, entries: &[EntryPoint]) {
    let recordable: Vec<&EntryPoint> = entries.iter().filter(|e| e.recordable).collect();
    if recordable.is_empty() {
        return;
    }
    out.push_str(
        "/// A command of the table compiled into a display list: its parameters, and a copy \
         of the\n/// values its pointers gave at compile time.\n\
         #[allow(non_camel_case_types)]\n#[derive(Clone, Debug, PartialEq)]\n\
         pub enum TableCommand {\n",
    );
    for entry in &recordable {
        let _ = writeln!(out, "    /// {}, compiled into a list.", entry.name);
        if entry.parameters.is_empty() {
            let _ = writeln!(out, "    {} {{}},", entry.name);
            continue;
        }
        let _ = writeln!(out, "    {} {{", entry.name);
        for p in &entry.parameters {
            let _ = match p.pointer {
                Some(_) => writeln!(
                    out,
                    "        /// The values `{0}` pointed to at compile time.\n        \
                     {0}: Vec<{1}>,",
                    p.name,
                    pointee(&p.rust_type)
                ),
                None => writeln!(
                    out,
                    "        /// `{0}`, as given.\n        {0}: {1},",
                    p.name, p.rust_type
                ),
            };
        }
        out.push_str("    },\n");
    }
    out.push_str(
        "}\n\nimpl TableCommand {\n    \
         /// Runs the command as its entry point would, on the recorded values.\n    \
         pub fn execute(&self, ctx: &mut Context) -> GlResult {\n        match self {\n",
    );
    for entry in &recordable {
        let names: Vec<String> = entry.parameters.iter().map(|p| p.name.clone()).collect();
        let _ = writeln!(
            out,
            "            TableCommand::{}{} => {{",
            entry.name,
            braced(&names)
        );
        for p in &entry.parameters {
            let _ = match p.pointer {
                Some(_) => writeln!(out, "                let {0} = &{0}[..];", p.name),
                None => writeln!(out, "                let {0} = *{0};", p.name),
            };
        }
        let _ = writeln!(out, "                {}\n            }}", entry.body);
    }
    out.push_str("        }\n    }\n}\n");
}

/// ` { a, b }`, or ` {}` for no fields.
fn braced(fields: &[String]) -> String {
    if fields.is_empty() {
        " {}".into()
    } else {
        format!(" {{ {} }}", fields.join(", "))
    }
}

/// The type a pointer type points to (`*const GLfloat` -> `GLfloat`).
/// The values a pointer parameter points to: bytes for `void *`.
fn pointee(rust_type: &str) -> &str {
    match rust_type
        .trim_start_matches("*const ")
        .trim_start_matches("*mut ")
    {
        "c_void" => "u8",
        pointee => pointee,
    }
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
        (
            entries.iter().any(|e| e.overlaps),
            "with_context_overlapping",
        ),
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
    if entries.iter().any(|e| e.recordable) {
        out.push_str("use crate::context::Context;\nuse crate::error::GlResult;\n");
    }
    for u in &uses {
        let _ = writeln!(out, "{u}");
    }
    out.push('\n');
    for entry in &entries {
        write_entry_point(&mut out, entry);
    }
    write_table_commands(&mut out, &entries);
    out.truncate(out.trim_end().len());
    out.push('\n');
    Ok(out)
}
