//! Display lists (§5.4) through the Rust API, and the entry-point table's `list` marks.

use fflight::commands::list::{Command, MAX_LIST_NESTING, TableCommand};
use fflight::{Context, GlError, gl::*};
use glam::Vec4;

fn manifest_dir() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// §5.4's commands that are executed immediately while a list is compiled, besides the Get
/// and Is queries.
const NOT_COMPILED: &[&str] = &[
    "glGenLists",
    "glDeleteLists",
    "glNewList",
    "glEndList",
    "glFeedbackBuffer",
    "glSelectBuffer",
    "glRenderMode",
    "glColorPointer",
    "glFogCoordPointer",
    "glEdgeFlagPointer",
    "glIndexPointer",
    "glNormalPointer",
    "glTexCoordPointer",
    "glSecondaryColorPointer",
    "glVertexPointer",
    "glClientActiveTexture",
    "glInterleavedArrays",
    "glEnableClientState",
    "glDisableClientState",
    "glPushClientAttrib",
    "glPopClientAttrib",
    "glReadPixels",
    "glPixelStoref",
    "glPixelStorei",
    "glGenTextures",
    "glDeleteTextures",
    "glAreTexturesResident",
    "glGenQueries",
    "glDeleteQueries",
    "glBindBuffer",
    "glDeleteBuffers",
    "glGenBuffers",
    "glBufferData",
    "glBufferSubData",
    "glMapBuffer",
    "glUnmapBuffer",
    "glFlush",
    "glFinish",
];

/// Table commands that §5.4 compiles but fflight does not compile yet, and why.
const NOT_COMPILED_YET: &[(&str, &str)] = &[(
    "glPolygonStipple",
    "the pattern must be unpacked with the pixel store modes of compile time",
)];

/// Every line of src/capi/entry_points.txt is compiled (`list`) unless §5.4 runs it at
/// once or it is a query; a new table line must say which it is.
#[test]
fn every_table_command_is_compiled_unless_the_spec_runs_it_at_once() {
    let table = std::fs::read_to_string(manifest_dir().join("src/capi/entry_points.txt"))
        .expect("the table exists");
    let mut wrong = Vec::new();
    for line in table.lines().map(str::trim) {
        let (marked, declaration) = match line.strip_prefix("list ") {
            Some(rest) => (true, rest),
            None => (false, line),
        };
        let Some(name) = declaration
            .split('(')
            .next()
            .and_then(|head| head.split_whitespace().nth(1))
            .filter(|name| name.starts_with("gl") && declaration.contains("=>"))
        else {
            continue;
        };
        let query = name.starts_with("glGet") || name.starts_with("glIs");
        let immediate = query
            || NOT_COMPILED.contains(&name)
            || NOT_COMPILED_YET.iter().any(|(n, _)| *n == name);
        if marked == immediate {
            wrong.push(name.to_string());
        }
    }
    assert!(
        wrong.is_empty(),
        "mark these `list` exactly when §5.4 compiles them: {wrong:?}"
    );
}

fn translate_x(x: f32) -> Command {
    TableCommand::glTranslatef { x, y: 0.0, z: 0.0 }.into()
}

fn modelview_x(ctx: &Context) -> f64 {
    ctx.get(GL_MODELVIEW_MATRIX).unwrap().as_doubles()[12]
}

#[test]
fn compile_records_and_call_replays() {
    let mut ctx = Context::new();
    ctx.new_list(5, GL_COMPILE).unwrap();
    assert_eq!(ctx.get(GL_LIST_INDEX).unwrap().as_ints(), [5]);
    assert_eq!(
        ctx.get(GL_LIST_MODE).unwrap().as_ints(),
        [GL_COMPILE as i32]
    );
    ctx.record_or_run(translate_x(2.0)).unwrap();
    ctx.record_or_run(Command::Color(Vec4::new(1.0, 0.0, 0.0, 1.0)))
        .unwrap();
    assert_eq!(modelview_x(&ctx), 0.0, "GL_COMPILE does not execute");
    assert!(!ctx.is_list(5).unwrap(), "defined only at glEndList");
    ctx.end_list().unwrap();
    assert_eq!(ctx.display_lists().get(5).unwrap().len(), 2);
    ctx.call_list(5).unwrap();
    ctx.call_list(5).unwrap();
    assert_eq!(modelview_x(&ctx), 4.0);
    assert_eq!(
        ctx.get(GL_CURRENT_COLOR).unwrap().as_doubles(),
        [1.0, 0.0, 0.0, 1.0]
    );

    ctx.new_list(6, GL_COMPILE_AND_EXECUTE).unwrap();
    ctx.record_or_run(translate_x(1.0)).unwrap();
    ctx.end_list().unwrap();
    assert_eq!(modelview_x(&ctx), 5.0, "GL_COMPILE_AND_EXECUTE executes");
    ctx.call_list(6).unwrap();
    assert_eq!(modelview_x(&ctx), 6.0);
}

#[test]
fn errors_of_compiled_commands_are_raised_when_the_list_executes() {
    let mut ctx = Context::new();
    ctx.new_list(1, GL_COMPILE).unwrap();
    ctx.record_or_run(TableCommand::glPopMatrix {}.into())
        .unwrap();
    ctx.record_or_run(Command::Error(GlError::InvalidValue))
        .unwrap();
    ctx.end_list().unwrap();
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.call_list(1).unwrap();
    assert_eq!(
        ctx.get_error(),
        GL_STACK_UNDERFLOW,
        "the first error is kept"
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

#[test]
fn list_management_errors() {
    let mut ctx = Context::new();
    assert_eq!(ctx.new_list(0, GL_COMPILE), Err(GlError::InvalidValue));
    assert_eq!(ctx.new_list(1, GL_RENDER), Err(GlError::InvalidEnum));
    assert_eq!(ctx.end_list(), Err(GlError::InvalidOperation));
    assert_eq!(ctx.gen_lists(-1), Err(GlError::InvalidValue));
    assert_eq!(ctx.delete_lists(1, -1), Err(GlError::InvalidValue));
    assert_eq!(ctx.call_list(0), Err(GlError::InvalidValue));
    assert_eq!(ctx.call_lists(-1, GL_INT, &[]), Err(GlError::InvalidValue));
    assert_eq!(ctx.call_lists(0, GL_DOUBLE, &[]), Err(GlError::InvalidEnum));
    assert_eq!(ctx.call_lists(1, GL_INT, &[]), Err(GlError::InvalidValue));
    ctx.new_list(1, GL_COMPILE).unwrap();
    assert_eq!(ctx.new_list(2, GL_COMPILE), Err(GlError::InvalidOperation));
    assert_eq!(ctx.get(GL_LIST_INDEX).unwrap().as_ints(), [1]);
    ctx.end_list().unwrap();
    ctx.begin(GL_POINTS).unwrap();
    assert_eq!(ctx.new_list(3, GL_COMPILE), Err(GlError::InvalidOperation));
    assert_eq!(ctx.gen_lists(1), Err(GlError::InvalidOperation));
    assert_eq!(ctx.is_list(1), Err(GlError::InvalidOperation));
    assert_eq!(ctx.list_base(1), Err(GlError::InvalidOperation));
    assert_eq!(
        ctx.call_list(1),
        Ok(()),
        "glCallList is legal in glBegin/glEnd"
    );
    ctx.end().unwrap();
    assert_eq!(ctx.get(GL_MAX_LIST_NESTING).unwrap().as_ints(), [64]);
}

#[test]
fn gen_lists_reserves_unused_names_and_delete_frees_them() {
    let mut ctx = Context::new();
    assert_eq!(ctx.gen_lists(0), Ok(0));
    let first = ctx.gen_lists(3).unwrap();
    assert!(first > 0);
    assert!((first..first + 3).all(|n| ctx.is_list(n).unwrap()));
    let next = ctx.gen_lists(2).unwrap();
    assert!(next >= first + 3);
    ctx.delete_lists(first, i32::MAX).unwrap();
    assert!(!ctx.is_list(first).unwrap() && !ctx.is_list(next + 1).unwrap());
    // With the largest names taken, a gap is found.
    ctx.new_list(u32::MAX, GL_COMPILE).unwrap();
    ctx.end_list().unwrap();
    let gap = ctx.gen_lists(4).unwrap();
    assert!(gap >= 1 && gap.checked_add(3).is_some_and(|last| last < u32::MAX));
}

#[test]
fn nesting_stops_at_the_limit_and_call_lists_decodes_every_type() {
    let mut ctx = Context::new();
    ctx.new_list(1, GL_COMPILE).unwrap();
    ctx.record_or_run(translate_x(1.0)).unwrap();
    ctx.record_or_run(TableCommand::glCallList { list: 1 }.into())
        .unwrap();
    ctx.end_list().unwrap();
    ctx.call_list(1).unwrap();
    assert_eq!(modelview_x(&ctx), MAX_LIST_NESTING as f64);

    for n in 2..=9 {
        ctx.new_list(n, GL_COMPILE).unwrap();
        ctx.record_or_run(translate_x(n as f32)).unwrap();
        ctx.end_list().unwrap();
    }
    let cases: [(GLenum, Vec<u8>, f64); 10] = [
        (GL_BYTE, vec![2, 3], 5.0),
        (GL_UNSIGNED_BYTE, vec![4], 4.0),
        (GL_SHORT, 5i16.to_ne_bytes().to_vec(), 5.0),
        (GL_UNSIGNED_SHORT, 6u16.to_ne_bytes().to_vec(), 6.0),
        (GL_INT, 7i32.to_ne_bytes().to_vec(), 7.0),
        (GL_UNSIGNED_INT, 8u32.to_ne_bytes().to_vec(), 8.0),
        (GL_FLOAT, 9.9f32.to_ne_bytes().to_vec(), 9.0),
        (GL_2_BYTES, vec![0, 2], 2.0),
        (GL_3_BYTES, vec![0, 0, 3], 3.0),
        (GL_4_BYTES, vec![0, 0, 0, 4], 4.0),
    ];
    for (list_type, bytes, expected) in cases {
        ctx.load_identity().unwrap();
        let n = (bytes.len() / fflight::commands::list::call_lists_type_size(list_type).unwrap())
            as i32;
        ctx.call_lists(n, list_type, &bytes).unwrap();
        assert_eq!(modelview_x(&ctx), expected, "type {list_type:#x}");
    }
    ctx.load_identity().unwrap();
    ctx.list_base(10).unwrap();
    ctx.call_lists(2, GL_BYTE, &[(-2i8) as u8, (-8i8) as u8])
        .unwrap();
    assert_eq!(modelview_x(&ctx), 10.0, "lists 8 and 2");
}
