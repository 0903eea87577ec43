//! Runs the C programs in `c_tests/`: each is compiled against fflight's C
//! header and shared library and, for the differential ones, unchanged
//! against Mesa's OSMesa; the canonical text they print is compared token by
//! token (the protocol is described at the top of `c_tests/ffl_test.h`).
//!
//! The first line of a program names its mode:
//! - `/* ffl-test: differential */`: both builds; their outputs must agree,
//!   and every `ref` group must agree with the program's own reference (on
//!   OSMesa too, except on lines marked `osmesa-exempt=<reason>`).
//! - `/* ffl-test: fflight-only */`: only the fflight build; the program
//!   checks itself and its exit status decides (its `ref` groups are checked).
//! - `/* ffl-test: osmesa-diff */`: shows a known OSMesa-vs-spec difference:
//!   both builds run and their outputs are printed, only the fflight build is
//!   checked against the program's reference.
//!
//! Tolerances: see COLOR_TOLERANCE, coordinate_tolerance and
//! CLIP_MADE_COORDINATE_TOLERANCE below; a line's own `tol` widens only
//! comparisons involving OSMesa (float32), never fflight against the reference.
//!
//! A program may declare, in its header comment, a known OSMesa-vs-spec
//! difference that the fflight-vs-OSMesa comparison accepts under a narrow
//! rule (`osmesa-known: line-reset`, see [`Known`]); fflight is still checked
//! against the spec there (the program's `line-prim=` marks).
//!
//! Build outputs go to `target/c_tests/`. Without OSMesa installed the tests
//! fail with a message, unless `FFL_NO_OSMESA=1` is set: then the OSMesa side
//! is skipped and only the fflight build is checked.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

#[path = "common/compare.rs"]
mod compare;
use compare::*;

/// How long one program may run.
const RUN_TIMEOUT: Duration = Duration::from_secs(150);

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    Differential,
    FflightOnly,
    OsmesaDiff,
}

fn manifest_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn out_dir() -> PathBuf {
    let dir = manifest_dir().join("target").join("c_tests");
    std::fs::create_dir_all(&dir).expect("create target/c_tests");
    dir
}

/// The shared library the fflight builds link: `cargo test` builds it next to this test
/// binary (target/<profile>/deps/libfflight.so) while `cargo build` puts it in
/// target/<profile>/; the newer is taken, so a stale `cargo build` output never shadows the
/// library this test run just compiled. It is copied once to target/c_tests/lib under its
/// SONAME (libfflight.so.MAJOR, what the programs ask the loader for) and the programs find
/// it there by their run path. Linking the debug library statically would make every program
/// a 45 MB copy of it, 4 GB for the directory, more than a small CI disk holds; `make
/// test-sanitize` still links every program statically, one at a time.
fn shared_library() -> &'static Path {
    static COPY: OnceLock<PathBuf> = OnceLock::new();
    COPY.get_or_init(|| {
        let built = newest_build_output("libfflight.so");
        let dir = out_dir().join("lib");
        std::fs::create_dir_all(&dir).expect("create target/c_tests/lib");
        let soname = format!("libfflight.so.{}", env!("CARGO_PKG_VERSION_MAJOR"));
        let copy = dir.join(&soname);
        // Through a temporary name, so a program never loads a half-written library.
        let partial = dir.join(format!("{soname}.partial"));
        std::fs::copy(&built, &partial)
            .and_then(|_| std::fs::rename(&partial, &copy))
            .unwrap_or_else(|e| panic!("copy {} to {}: {e}", built.display(), copy.display()));
        copy
    })
}

/// The newest of the crate's build outputs named `file_name` (see [`shared_library`]).
fn newest_build_output(file_name: &str) -> PathBuf {
    let mut candidates = Vec::new();
    if let Ok(exe) = std::env::current_exe()
        && let Some(deps) = exe.parent()
    {
        candidates.push(deps.join(file_name));
        if let Some(profile) = deps.parent() {
            candidates.push(profile.join(file_name));
        }
    }
    candidates.push(manifest_dir().join("target/debug").join(file_name));
    candidates
        .iter()
        .filter_map(|p| {
            let modified = std::fs::metadata(p).and_then(|m| m.modified()).ok()?;
            Some((modified, p.clone()))
        })
        .max()
        .map(|(_, p)| p)
        .unwrap_or_else(|| {
            panic!(
                "{file_name} not found (looked at {candidates:?}); the crate's \
                 crate-type must include \"cdylib\": run `cargo build` and retry"
            )
        })
}

fn osmesa_wanted() -> bool {
    if std::env::var_os("FFL_NO_OSMESA").is_some_and(|v| v == "1") {
        return false;
    }
    assert!(
        Path::new("/usr/include/GL/osmesa.h").exists(),
        "OSMesa is not installed: `apt-get install -y libosmesa6-dev`, \
         or set FFL_NO_OSMESA=1 to check the fflight builds alone"
    );
    true
}

fn read_mode(source: &Path) -> Mode {
    let text = std::fs::read_to_string(source)
        .unwrap_or_else(|e| panic!("read {}: {e}", source.display()));
    let first = text.lines().next().unwrap_or("");
    if first.contains("ffl-test: differential") {
        Mode::Differential
    } else if first.contains("ffl-test: fflight-only") {
        Mode::FflightOnly
    } else if first.contains("ffl-test: osmesa-diff") {
        Mode::OsmesaDiff
    } else {
        panic!(
            "{}: the first line must be /* ffl-test: differential */, \
             /* ffl-test: fflight-only */ or /* ffl-test: osmesa-diff */",
            source.display()
        )
    }
}

const KNOWN_PREFIX: &str = "osmesa-known:";

/// The `osmesa-known:` declarations in a program's header comment (the text
/// before the first `#include`). An unknown name is an error.
fn read_known(source: &Path) -> Vec<Known> {
    let text = std::fs::read_to_string(source)
        .unwrap_or_else(|e| panic!("read {}: {e}", source.display()));
    let mut known = Vec::new();
    for line in text.lines().take_while(|l| !l.starts_with("#include")) {
        let Some(at) = line.find(KNOWN_PREFIX) else {
            continue;
        };
        for name in line[at + KNOWN_PREFIX.len()..]
            .split([',', ' ', '*', '/'])
            .filter(|n| !n.is_empty())
        {
            match name {
                "line-reset" => known.push(Known::LineReset),
                other => panic!(
                    "{}: unknown osmesa-known difference `{other}` (known: line-reset)",
                    source.display()
                ),
            }
        }
    }
    known
}

/// The mark a program prints on a segment of a line primitive: the token kind
/// the spec gives it (`line-prim=line_reset` or `line-prim=line`).
const LINE_PRIM_PREFIX: &str = "line-prim=";

/// The feedback token kind of a segment line (`line` or `line_reset`).
fn segment_kind<'a>(tokens: &[&'a str]) -> Option<&'a str> {
    tokens
        .iter()
        .copied()
        .find(|&t| t == "line" || t == "line_reset")
}

/// Checks every segment a program marked `line-prim=<kind>` against the token
/// the build fed back. Returns how many marks were checked.
fn check_line_marks(report: &mut Report, build: Build, output: &str) -> usize {
    let mut checked = 0;
    for (index, line) in output.lines().enumerate() {
        let tokens: Vec<&str> = line.split_whitespace().collect();
        let Some(expected) = tokens.iter().find_map(|t| t.strip_prefix(LINE_PRIM_PREFIX)) else {
            continue;
        };
        checked += 1;
        let got = segment_kind(&tokens);
        if got != Some(expected) {
            report.fail(format!(
                "{} vs spec, line {}: segment token {got:?}, the spec gives `{expected}`\n  {line}",
                build.name(),
                index + 1
            ));
        }
    }
    checked
}

const CFLAGS: &[&str] = &[
    "-std=c99",
    "-Wall",
    "-Wextra",
    "-Werror",
    "-pedantic",
    // -Og: the warnings that need data-flow analysis (-Wmaybe-uninitialized), in less than
    // half -O1's compile time.
    "-Og",
    "-g",
];

/// The libraries a program's header comment asks for on a line `ffl-libs: -lGLU ...`: client
/// libraries that draw through the GL (libGLU). The fflight build links them beside
/// libfflight.so, which the loader searches before their own dependencies (libGL), so the
/// libraries' GL calls resolve to fflight's at run time, not to another GL also loaded.
fn client_libraries(source: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(source).unwrap_or_default();
    // The comments before the first #include.
    let header = text.split("#include").next().unwrap_or("");
    header
        .lines()
        .filter_map(|line| line.split("ffl-libs:").nth(1))
        .flat_map(|libs| libs.split_whitespace().map(str::to_string))
        .collect()
}

fn compile(name: &str, build: Build) -> PathBuf {
    let root = manifest_dir();
    let source = root.join("c_tests").join(format!("{name}.c"));
    let libraries = client_libraries(&source);
    let exe = out_dir().join(format!("{name}.{}", build.name()));
    let mut cmd = Command::new(std::env::var("CC").unwrap_or_else(|_| "gcc".into()));
    cmd.args(CFLAGS).arg("-I").arg(root.join("c_tests"));
    match build {
        Build::Fflight => {
            cmd.arg("-I").arg(root.join("include")).arg(&source);
            cmd.args(&libraries);
            let library = shared_library();
            let run_path = library.parent().expect("target/c_tests/lib");
            cmd.arg(library)
                .arg(format!("-Wl,-rpath,{}", run_path.display()))
                .args(["-lm", "-lpthread", "-ldl"]);
        }
        Build::Osmesa => {
            // OSMesa before the client libraries: theirs is the GL they find first.
            cmd.arg("-DFFL_OSMESA")
                .arg(&source)
                .arg("-lOSMesa")
                .args(&libraries)
                .arg("-lm");
        }
    }
    cmd.arg("-o").arg(&exe);
    let out = cmd.output().expect("run the C compiler (gcc, or $CC)");
    assert!(
        out.status.success(),
        "compiling c_tests/{name}.c for {} failed:\n{cmd:?}\n{}{}",
        build.name(),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

struct RunOutput {
    stdout: String,
    stderr: String,
    success: bool,
    status: String,
}

fn run(exe: &Path, build: Build) -> RunOutput {
    let mut command = Command::new(exe);
    if build == Build::Osmesa {
        // Mesa's JIT without LLVM's optimization passes: every program prints the same text
        // with and without them (the osmesa_diff programs that print memory OSMesa leaves
        // unset aside), and random_lighting's states compile in 11.6 s instead of 51.7.
        command.env("GALLIVM_PERF", "nopt");
    }
    let mut child = command
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("run {}: {e}", exe.display()));
    // Drain the pipes on threads so a chatty program cannot block.
    let mut out_pipe = child.stdout.take().unwrap();
    let mut err_pipe = child.stderr.take().unwrap();
    let out_thread = std::thread::spawn(move || {
        let mut s = Vec::new();
        out_pipe.read_to_end(&mut s).ok();
        s
    });
    let err_thread = std::thread::spawn(move || {
        let mut s = Vec::new();
        err_pipe.read_to_end(&mut s).ok();
        s
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait for a C program") {
            break status;
        }
        if start.elapsed() > RUN_TIMEOUT {
            child.kill().ok();
            child.wait().ok();
            panic!("{} ran longer than {RUN_TIMEOUT:?}", exe.display());
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    RunOutput {
        stdout: String::from_utf8_lossy(&out_thread.join().unwrap()).into_owned(),
        stderr: String::from_utf8_lossy(&err_thread.join().unwrap()).into_owned(),
        success: status.success(),
        status: format!("{status}"),
    }
}

/// Compiles and runs one program in every build its mode asks for, checks
/// the outputs, prints a summary and panics with every failure found.
fn run_program(name: &str) {
    let source = manifest_dir().join("c_tests").join(format!("{name}.c"));
    let mode = read_mode(&source);
    let known = read_known(&source);
    let mut builds = vec![Build::Fflight];
    let with_osmesa = mode != Mode::FflightOnly && osmesa_wanted();
    if with_osmesa {
        builds.push(Build::Osmesa);
    }

    // Compile and run the builds in parallel.
    let results: Vec<(Build, RunOutput)> = std::thread::scope(|scope| {
        let handles: Vec<_> = builds
            .iter()
            .map(|&build| scope.spawn(move || (build, run(&compile(name, build), build))))
            .collect();
        handles
            .into_iter()
            .map(|h| match h.join() {
                Ok(r) => r,
                Err(panic) => std::panic::resume_unwind(panic),
            })
            .collect()
    });
    for (build, out) in &results {
        std::fs::write(
            out_dir().join(format!("{name}.{}.txt", build.name())),
            &out.stdout,
        )
        .ok();
    }

    let mut report = Report::new(name);
    for (build, out) in &results {
        if !out.success {
            report.fail(format!(
                "the {} build exited with {}; stderr:\n{}\nlast lines of stdout:\n{}",
                build.name(),
                out.status,
                out.stderr,
                tail(&out.stdout, 10)
            ));
        }
    }

    let fflight = &results[0].1.stdout;
    let osmesa = results.get(1).map(|r| &r.1.stdout);
    let mut summary = String::new();

    let mut ff_ref = MaxDiff::default();
    let mut exempt = BTreeMap::new();
    check_references(
        &mut report,
        Build::Fflight,
        fflight,
        false,
        &mut ff_ref,
        &mut exempt,
    );
    if ff_ref.compared > 0 {
        writeln!(summary, "  fflight vs reference: {}", summarize(&ff_ref)).unwrap();
    }
    let marks = check_line_marks(&mut report, Build::Fflight, fflight);
    if marks > 0 {
        writeln!(
            summary,
            "  fflight vs spec: {marks} segment tokens of line primitives"
        )
        .unwrap();
    }

    if let Some(osmesa) = osmesa {
        match mode {
            Mode::Differential => {
                let mut cross = MaxDiff::default();
                let mut accepted = BTreeMap::new();
                check_differential_known(
                    &mut report,
                    fflight,
                    osmesa,
                    &known,
                    &mut cross,
                    &mut accepted,
                );
                writeln!(summary, "  fflight vs OSMesa: {}", summarize(&cross)).unwrap();
                for (name, count) in &accepted {
                    writeln!(
                        summary,
                        "  accepted (declared osmesa-known: {name}): {count} tokens"
                    )
                    .unwrap();
                }
                let mut os_ref = MaxDiff::default();
                let mut os_exempt = BTreeMap::new();
                check_references(
                    &mut report,
                    Build::Osmesa,
                    osmesa,
                    true,
                    &mut os_ref,
                    &mut os_exempt,
                );
                if os_ref.compared > 0 {
                    writeln!(summary, "  OSMesa vs reference: {}", summarize(&os_ref)).unwrap();
                }
                for (reason, count) in &os_exempt {
                    writeln!(
                        summary,
                        "  exempted from fflight-vs-OSMesa (known OSMesa difference `{reason}`): {count} lines"
                    )
                    .unwrap();
                }
            }
            Mode::OsmesaDiff => {
                // Not an error either way: this output documents OSMesa.
                let mut probe = Report::new(name);
                let mut os_ref = MaxDiff::default();
                let mut ignored = BTreeMap::new();
                check_references(
                    &mut probe,
                    Build::Osmesa,
                    osmesa,
                    false,
                    &mut os_ref,
                    &mut ignored,
                );
                check_line_marks(&mut probe, Build::Osmesa, osmesa);
                if probe.failures.is_empty() {
                    report.notes.push(
                        "note: OSMesa now agrees with the spec here; update docs/osmesa-differences.md"
                            .into(),
                    );
                }
                writeln!(
                    summary,
                    "  OSMesa vs reference (known to differ): {}",
                    summarize(&os_ref)
                )
                .unwrap();
                writeln!(summary, "  fflight output:\n{}", indent(fflight)).unwrap();
                writeln!(summary, "  OSMesa output:\n{}", indent(osmesa)).unwrap();
            }
            Mode::FflightOnly => {}
        }
    } else if mode != Mode::FflightOnly {
        report
            .notes
            .push("note: OSMesa side skipped (FFL_NO_OSMESA=1)".into());
    }

    println!("c_tests/{name}.c ({mode:?}):\n{summary}");
    for note in &report.notes {
        println!("  {note}");
    }
    if !report.failures.is_empty() {
        let total = report.failures.len();
        let shown: Vec<&String> = report.failures.iter().take(MAX_FAILURES_SHOWN).collect();
        let mut msg = format!(
            "c_tests/{}.c: {total} mismatch(es) (outputs in target/c_tests/{}.*.txt)\n",
            report.program, report.program
        );
        for f in shown {
            writeln!(msg, "- {f}").unwrap();
        }
        if total > MAX_FAILURES_SHOWN {
            writeln!(msg, "... and {} more", total - MAX_FAILURES_SHOWN).unwrap();
        }
        write!(msg, "{summary}").unwrap();
        panic!("{msg}");
    }
}

fn tail(s: &str, n: usize) -> String {
    let lines: Vec<&str> = s.lines().collect();
    lines[lines.len().saturating_sub(n)..].join("\n")
}

fn indent(s: &str) -> String {
    s.lines()
        .map(|l| format!("    {l}"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// One test per program. A program that shows a reported fflight bug is
/// listed with `#[ignore = "fflight bug (reported): ..."]` until the fix
/// lands (`cargo test --test c_programs -- --ignored` runs it).
macro_rules! c_programs {
    ($($(#[$attr:meta])* $name:ident),* $(,)?) => {
        $(
            #[test]
            $(#[$attr])*
            fn $name() {
                run_program(stringify!($name));
            }
        )*

        const PROGRAMS: &[&str] = &[$(stringify!($name)),*];
    };
}

c_programs!(
    random_lighting,
    osmesa_diff_shininess0_attenuation,
    osmesa_diff_zero_pow_zero,
    osmesa_diff_zero_area_facing,
    osmesa_diff_color_material_change,
    osmesa_diff_get_integer,
    osmesa_diff_vertex_w,
    osmesa_diff_line_reset,
    osmesa_diff_flat_feedback,
    osmesa_diff_edge_flags,
    osmesa_diff_scalar_pnames,
    attrib_stack,
    osmesa_diff_attrib_stack,
    osmesa_diff_back_color_material,
    osmesa_diff_texture_matrix,
    texgen_osmesa_diff_modes,
    multitexture_state,
    draw_read_pixels,
    eval_maps,
    eval_osmesa_diff_mesh_fill,
    glu_nurbs,
    glu_quadrics_tess,
    gles_fixed_point,
    imaging_osmesa_diff_subset,
    raster_pos,
    osmesa_diff_raster_pos_lighting,
    system_gl_header,
    spot_cutoff,
    local_viewer,
    window_pos_secondary_fog,
    bitmap_copy_pixels,
    arrays_secondary_fog,
    arrays_osmesa_diff_interleaved_disables,
    occlusion_queries,
    color_index_state,
    multi_draw,
    multi_draw_osmesa_diff_negative_count,
    two_sided_points,
    color_material_modes,
    separate_specular,
    normalize_rescale,
    feedback_types_points,
    feedback_overflow,
    errors,
    integer_forms,
    prim_lines,
    prim_triangles,
    prim_strips_fans,
    prim_quads_polygons,
    clip_view_volume,
    clip_user_planes,
    cull_face,
    polygon_mode,
    two_sided_polygons,
    shade_model_smooth,
    random_meshes,
    arrays_types,
    buffer_objects,
    buffer_osmesa_diff_mapped_draw,
    arrays_draws,
    arrays_interleaved,
    arrays_errors,
    arrays_osmesa_diff_signed_normalization,
    arrays_osmesa_diff_no_vertex_array,
    arrays_osmesa_diff_negative_stride,
    capture_api,
    capture_light_vertices,
    capture_example,
    capture_texture_units,
    feedback_types_polygons,
    feedback_overflow_polygons,
    clip_line_strip_reset,
    select_primitives,
    select_overflow,
    select_errors,
    select_osmesa_diff,
    state_depth_stencil_scissor,
    state_color_buffer,
    state_fog_hints,
    state_points_lines_polygons,
    state_pixels,
    osmesa_diff_buffers_and_factors,
    dlist_compile_call,
    dlist_nesting,
    dlist_images,
    legacy_redbook_scene,
    legacy_bezier_patches,
    legacy_torus_envmap,
    legacy_multitexture_quad,
    legacy_nurbs_surface,
    thread_exit_context,
    thread_stress,
    limits_misuse,
    dlist_call_lists,
    dlist_arrays,
    dlist_errors,
    texture_objects_params,
    texture_osmesa_diff_unbound_names,
    texture_images,
);

/// The line-reset rule accepts exactly fflight `line_reset` vs OSMesa `line`
/// on a segment marked `line-prim=line_reset`, in a program that declares it;
/// fflight's segment tokens are checked against the marks.
#[test]
fn line_reset_rule_is_narrow() {
    let fflight =
        "p begin GL_LINE_STRIP\np line_reset 2 line-prim=line_reset\np  v xy 1 2 xy 3 4\n";
    let osmesa = fflight.replace("p line_reset 2", "p line 2");
    let run = |known: &[Known], ff: &str, os: &str| {
        let mut report = Report::new("self-test");
        let mut accepted = BTreeMap::new();
        check_differential_known(
            &mut report,
            ff,
            os,
            known,
            &mut MaxDiff::default(),
            &mut accepted,
        );
        (report.failures.len(), accepted.get("line-reset").copied())
    };
    assert_eq!(run(&[Known::LineReset], fflight, &osmesa), (0, Some(1)));
    // not declared
    assert_eq!(run(&[], fflight, &osmesa).0, 1);
    // not a segment of a line primitive (a polygon outline has no mark)
    let outline = fflight.replace(" line-prim=line_reset", "");
    let outline_os = osmesa.replace(" line-prim=line_reset", "");
    assert_eq!(run(&[Known::LineReset], &outline, &outline_os).0, 1);
    // the spec gives `line` here: no reset difference to accept
    let plain = fflight.replace("line-prim=line_reset", "line-prim=line");
    let plain_os = osmesa.replace("line-prim=line_reset", "line-prim=line");
    assert_eq!(run(&[Known::LineReset], &plain, &plain_os).0, 1);
    // the other way round
    assert_eq!(run(&[Known::LineReset], &osmesa, fflight).0, 1);
    // a different coordinate on an accepted line still fails
    let moved = osmesa.replace("xy 3 4", "xy 3 5");
    assert_eq!(run(&[Known::LineReset], fflight, &moved), (1, Some(1)));

    // fflight against the marks
    let mut report = Report::new("self-test");
    assert_eq!(check_line_marks(&mut report, Build::Fflight, fflight), 1);
    assert!(report.failures.is_empty());
    check_line_marks(&mut report, Build::Fflight, &osmesa);
    assert_eq!(report.failures.len(), 1);
    check_line_marks(&mut report, Build::Fflight, &plain);
    assert_eq!(report.failures.len(), 2);
}

/// Every program in c_tests/ has a test above, and every test a program.
#[test]
fn every_c_program_is_run() {
    let mut found: Vec<String> = std::fs::read_dir(manifest_dir().join("c_tests"))
        .expect("read c_tests/")
        .filter_map(|e| {
            let path = e.ok()?.path();
            if path.extension()? != "c" {
                return None;
            }
            Some(path.file_stem()?.to_string_lossy().into_owned())
        })
        .collect();
    found.sort();
    let mut listed: Vec<String> = PROGRAMS.iter().map(|s| s.to_string()).collect();
    listed.sort();
    assert_eq!(
        found, listed,
        "c_tests/*.c and the c_programs! list in tests/c_programs.rs must match"
    );
}

/// The comparison itself can fail: a changed color, a changed token, an
/// exempt line and a reference mismatch are all caught.
#[test]
fn comparison_catches_differences() {
    let base = "v 1 2 xyz 32 31.5 0.5 rgba 0.25 0.5 0.75 1 ref rgba 0.25 0.5 0.75 1\n";

    let mut report = Report::new("self-test");
    let mut stats = MaxDiff::default();
    check_differential(&mut report, base, base, &mut stats);
    assert!(report.failures.is_empty());

    let color = base.replacen("0.5 0.75", "0.50002 0.75", 1);
    check_differential(&mut report, &color, base, &mut stats);
    assert_eq!(report.failures.len(), 1, "{:?}", report.failures);

    // 32 vs 32.00005 is inside the coordinate tolerance, 32.001 is not.
    let mut report = Report::new("self-test");
    check_differential(
        &mut report,
        &base.replace(" 32 ", " 32.00005 "),
        base,
        &mut stats,
    );
    assert!(report.failures.is_empty(), "{:?}", report.failures);
    check_differential(
        &mut report,
        &base.replace(" 32 ", " 32.001 "),
        base,
        &mut stats,
    );
    assert_eq!(report.failures.len(), 1);

    // x and y: the floor is relative to the viewport's half size; z: 1e-5.
    let mut report = Report::new("self-test");
    let small_x = base.replace(" 32 ", " 3.9 ");
    check_differential(
        &mut report,
        &small_x.replace(" 3.9 ", " 3.90005 "),
        &small_x,
        &mut stats,
    );
    assert!(report.failures.is_empty(), "{:?}", report.failures);
    check_differential(
        &mut report,
        &base.replace(" 0.5 rgba", " 0.50005 rgba"),
        base,
        &mut stats,
    );
    assert_eq!(report.failures.len(), 1);

    // A vertex made by clipping: 5e-4 pixels.
    let mut report = Report::new("self-test");
    let made = base.replace("\n", " clip-made\n");
    check_differential(
        &mut report,
        &made.replace(" 32 ", " 32.0004 "),
        &made,
        &mut stats,
    );
    assert!(report.failures.is_empty(), "{:?}", report.failures);
    check_differential(
        &mut report,
        &made.replace(" 32 ", " 32.0006 "),
        &made,
        &mut stats,
    );
    check_differential(
        &mut report,
        &base.replace(" 32 ", " 32.0004 "),
        base,
        &mut stats,
    );
    assert_eq!(report.failures.len(), 2);

    // Hit-record depths: 1e-5 of depth in integer steps, nothing else widened.
    let hit = "p hit names 1 zhit 2147483648 4294967295 stack 7\n";
    let mut report = Report::new("self-test");
    check_differential(
        &mut report,
        &hit.replace("2147483648", "2147526000"),
        hit,
        &mut stats,
    );
    assert!(report.failures.is_empty(), "{:?}", report.failures);
    check_differential(
        &mut report,
        &hit.replace(" 4294967295", " 0"),
        hit,
        &mut stats,
    );
    check_differential(
        &mut report,
        &hit.replace("2147483648", "2147527000"),
        hit,
        &mut stats,
    );
    check_differential(
        &mut report,
        &hit.replace("stack 7", "stack 8"),
        hit,
        &mut stats,
    );
    check_differential(
        &mut report,
        &hit.replace("names 1", "names 2"),
        hit,
        &mut stats,
    );
    assert_eq!(report.failures.len(), 4, "{:?}", report.failures);

    let mut report = Report::new("self-test");
    check_differential(&mut report, &base.replace("rgba", "rgb"), base, &mut stats);
    assert!(!report.failures.is_empty());

    // Exempt: the color is not compared across builds, the coordinates are.
    let exempt = base.replace("v 1 2", "v 1 2 osmesa-exempt=shininess0");
    let mut report = Report::new("self-test");
    check_differential(
        &mut report,
        &exempt,
        &exempt.replacen("0.25", "0.9", 1),
        &mut stats,
    );
    assert!(report.failures.is_empty(), "{:?}", report.failures);
    check_differential(
        &mut report,
        &exempt,
        &exempt.replacen("32", "33", 1),
        &mut stats,
    );
    assert_eq!(report.failures.len(), 1);

    // Reference checks.
    let mut exempt_counts = BTreeMap::new();
    let mut report = Report::new("self-test");
    let wrong = base.replacen("0.25", "0.2501", 1);
    check_references(
        &mut report,
        Build::Fflight,
        &wrong,
        false,
        &mut stats,
        &mut exempt_counts,
    );
    assert_eq!(report.failures.len(), 1);
    let wrong_exempt = exempt.replacen("0.25", "0.2501", 1);
    check_references(
        &mut report,
        Build::Osmesa,
        &wrong_exempt,
        true,
        &mut stats,
        &mut exempt_counts,
    );
    assert_eq!(report.failures.len(), 1);
    assert_eq!(exempt_counts.get("shininess0"), Some(&1));
    check_references(
        &mut report,
        Build::Fflight,
        &wrong_exempt,
        false,
        &mut stats,
        &mut exempt_counts,
    );
    assert_eq!(report.failures.len(), 2);

    // A line's own `tol` widens the color tolerance of OSMesa comparisons,
    // never of coordinates, never of fflight against the reference.
    let with_tol = base.replace("\n", " tol 0.001\n");
    let mut report = Report::new("self-test");
    let off = with_tol.replacen("0.25", "0.2505", 1);
    check_references(
        &mut report,
        Build::Osmesa,
        &off,
        false,
        &mut stats,
        &mut exempt_counts,
    );
    check_differential(&mut report, &off, &with_tol, &mut stats);
    assert!(report.failures.is_empty(), "{:?}", report.failures);
    check_references(
        &mut report,
        Build::Fflight,
        &off,
        false,
        &mut stats,
        &mut exempt_counts,
    );
    assert_eq!(report.failures.len(), 1, "{:?}", report.failures);
    let far = with_tol.replacen("0.25", "0.252", 1);
    check_references(
        &mut report,
        Build::Osmesa,
        &far,
        false,
        &mut stats,
        &mut exempt_counts,
    );
    assert_eq!(report.failures.len(), 2);
    check_differential(
        &mut report,
        &with_tol.replace(" 32 ", " 32.001 "),
        &with_tol,
        &mut stats,
    );
    assert_eq!(report.failures.len(), 3);
}
