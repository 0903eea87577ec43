//! The comparison of the C harness (`tests/c_programs.rs`): tolerances, the canonical
//! output's labelled number groups, the fflight-vs-OSMesa comparison with its narrow rules for
//! known OSMesa differences. Shared with the differential sequence fuzzer
//! (`tests/osmesa_fuzz.rs`).
#![allow(dead_code)]

use std::collections::BTreeMap;

/// Which library a program was built against.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Build {
    Fflight,
    Osmesa,
}

impl Build {
    pub fn name(self) -> &'static str {
        match self {
            Build::Fflight => "fflight",
            Build::Osmesa => "osmesa",
        }
    }
}

/// Colors and every other non-coordinate number. fflight evaluates the
/// lighting equation in double precision from its single-precision state, and
/// the reference evaluates it in double on that same stored state (it reads
/// the state back through GL queries, see `mirror_read_stored_state`), so
/// fflight-vs-reference differences are the float32 rounding of the fed-back
/// values and nothing else. OSMesa evaluates in float32: two such results
/// differ by a few ulps of the largest term (measured: OSMesa vs the reference
/// within 5.2e-6 over 10,400 random vertices); 1e-5 is twice that.
pub const COLOR_TOLERANCE: f64 = 1e-5;

/// Window coordinates (labels `xy`, `xyz`, `xyzw`). They are the end of a
/// chain of float32 steps (modelview, projection, perspective divide,
/// viewport), each rounding relative to operands that can be larger than the
/// result, and two correct implementations may associate the sums
/// differently (and store matrices built by glRotate, glMultMatrix, ...
/// rounded differently: the reference, which reads each build's stored
/// matrices, moves with them). A float32 ulp is 1.2e-7 |v|: we allow about 16
/// ulps relative (2e-6 |v|). x and y are the viewport offset plus (ndc + 1)
/// times half the viewport size, so their rounding is relative to that half
/// size (32 pixels in every test's 64-pixel viewport), not to the result: x
/// near the left edge carries the error of x = 32 (measured 1.5e-5 at
/// x = 3.9, random_meshes mesh 72), hence a floor of 2e-6 * 32 = 6.4e-5 for
/// x and y. z (depth, in [0, 1]) and w have the color tolerance as floor.
pub fn coordinate_tolerance(component: usize, v: f64) -> f64 {
    let floor = if component < 2 {
        XY_TOLERANCE_FLOOR
    } else {
        COLOR_TOLERANCE
    };
    floor.max(2e-6 * v.abs())
}

/// 2e-6 times half of the 64-pixel viewports the programs use.
pub const XY_TOLERANCE_FLOOR: f64 = 6.4e-5;

/// Window coordinates of a vertex that clipping made (a line marked
/// `clip-made`, see `c_tests/reference/vertex_ref.h`). Such a vertex is
/// interpolated along an edge whose far end can lie far outside the view, even
/// behind the eye: the interpolation parameter carries float32 rounding
/// relative to the whole edge, not to the result, and the two implementations
/// evaluate the plane distances in different spaces (OSMesa user planes in
/// clip space, fflight in eye space). Measured fflight vs OSMesa: up to
/// 1.8e-4 pixels in a 64-pixel viewport (shade_model_smooth.c: frustum with
/// near 1, far 20, a user plane; 1.5e-4 with its current shapes). Allowed:
/// 5e-4 pixels, or the ordinary relative tolerance where that is larger.
pub const CLIP_MADE_COORDINATE_TOLERANCE: f64 = 5e-4;

/// Depths in selection hit records (label `zhit`): unsigned integers, window z
/// in [0, 1] scaled by 2^32 - 1 (§5.2). Compared as window z is (1e-5 of
/// depth), so the tolerance is 1e-5 * (2^32 - 1) integer steps. Mesa converts
/// with a float product truncated, fflight rounds the exact product: they
/// differ by a few hundred steps (float32 resolution of z * 2^32) where both
/// are right; one unit of depth is 4294967295 steps, so a wrong depth shows.
pub const HIT_DEPTH_TOLERANCE: f64 = 1e-5 * 4294967295.0;

/// The label of hit-record depths.
pub const HIT_DEPTH_LABEL: &str = "zhit";

/// The mark of a fed-back vertex that no glVertex gave: clipping made it.
pub const CLIP_MADE: &str = "clip-made";

pub fn is_coordinate_label(label: &str) -> bool {
    matches!(label, "xy" | "xyz" | "xyzw")
}

/// `line_tolerance` is the line's own `tol` value, if its reference gave one:
/// where float32 rounding of a dot product is raised to a high power
/// (shininess, spot exponent), the reference computes how far a float32
/// evaluation may land, never less than COLOR_TOLERANCE. It applies only
/// where an OSMesa value is compared (OSMesa vs reference, fflight vs OSMesa):
/// OSMesa evaluates in float32. fflight evaluates in double from the stored
/// state, and is held to COLOR_TOLERANCE against the reference everywhere.
pub fn tolerance(
    label: &str,
    component: usize,
    a: f64,
    b: f64,
    line_tolerance: Option<f64>,
) -> f64 {
    if label == HIT_DEPTH_LABEL {
        HIT_DEPTH_TOLERANCE
    } else if is_coordinate_label(label) {
        coordinate_tolerance(component, a.abs().max(b.abs()))
    } else {
        COLOR_TOLERANCE.max(line_tolerance.unwrap_or(0.0))
    }
}

/// The label of the reference's tolerance group, not compared itself.
pub const TOLERANCE_LABEL: &str = "tol";

/// The `tol` value after `ref` on a line, if any.
pub fn line_tolerance(tokens: &[&str]) -> Option<f64> {
    let split = tokens.iter().position(|&t| t == "ref")?;
    groups(&tokens[split + 1..])
        .into_iter()
        .find(|(label, values)| *label == TOLERANCE_LABEL && values.len() == 1)
        .map(|(_, values)| values[0])
}

pub const EXEMPT_PREFIX: &str = "osmesa-exempt=";

/// A known OSMesa-vs-spec difference a program declares in its header
/// comment (`osmesa-known: line-reset`), accepted by a narrow rule in
/// [`check_differential`]. Declarations are per program, never global.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Known {
    /// GL 1.5 §3.4.2 and §5.3: the line stipple counter is reset before
    /// every segment of GL_LINES and at the start of each strip or loop, so
    /// feedback gives GL_LINE_RESET_TOKEN there; OSMesa (Mesa's draw module,
    /// stipple disabled) gives GL_LINE_TOKEN for every segment of a line
    /// primitive. Accepted: fflight `line_reset` where OSMesa has `line`, only
    /// on a segment the program marked `line-prim=line_reset` (a segment of a
    /// line primitive where the spec gives the reset token). fflight's own
    /// tokens are still checked against every `line-prim=` mark.
    LineReset,
}

impl Known {
    pub fn name(self) -> &'static str {
        match self {
            Known::LineReset => "line-reset",
        }
    }
}

/// A number token: Rust parses `nan`, `inf` and `-inf` as ffl_pf prints them.
pub fn number(token: &str) -> Option<f64> {
    token.parse::<f64>().ok()
}

/// The labelled number groups of a run of tokens (flags are skipped).
pub fn groups<'a>(tokens: &[&'a str]) -> Vec<(&'a str, Vec<f64>)> {
    let mut out: Vec<(&str, Vec<f64>)> = Vec::new();
    for &t in tokens {
        if t.starts_with(EXEMPT_PREFIX) {
            continue;
        }
        match number(t) {
            Some(v) => match out.last_mut() {
                Some((_, values)) => values.push(v),
                None => out.push(("", vec![v])),
            },
            None => out.push((t, Vec::new())),
        }
    }
    out
}

pub fn exemption(tokens: &[&str]) -> Option<String> {
    tokens
        .iter()
        .find_map(|t| t.strip_prefix(EXEMPT_PREFIX))
        .map(str::to_string)
}

pub fn close(a: f64, b: f64, tol: f64) -> bool {
    if a.is_nan() || b.is_nan() {
        return a.is_nan() && b.is_nan();
    }
    if a.is_infinite() || b.is_infinite() {
        return a == b;
    }
    (a - b).abs() <= tol
}

/// Largest differences seen, per label (`rgba`, `xyz`, `dev`, ...).
#[derive(Default)]
pub struct MaxDiff {
    pub by_label: BTreeMap<String, f64>,
    pub compared: usize,
}

impl MaxDiff {
    pub fn record(&mut self, label: &str, a: f64, b: f64) {
        let max = self.by_label.entry(label.to_string()).or_insert(0.0);
        if a.is_finite() && b.is_finite() {
            *max = max.max((a - b).abs());
        }
        self.compared += 1;
    }
}

pub struct Report {
    pub program: String,
    pub failures: Vec<String>,
    pub notes: Vec<String>,
}

pub const MAX_FAILURES_SHOWN: usize = 25;

impl Report {
    pub fn new(program: &str) -> Self {
        Report {
            program: program.to_string(),
            failures: Vec::new(),
            notes: Vec::new(),
        }
    }

    pub fn fail(&mut self, msg: String) {
        self.failures.push(msg);
    }
}

/// Checks every `ref` group of one output against the implementation's group
/// with the same label. Lines marked exempt are counted in `exempt` and
/// skipped when `honor_exemptions` is set.
pub fn check_references(
    report: &mut Report,
    build: Build,
    output: &str,
    honor_exemptions: bool,
    stats: &mut MaxDiff,
    exempt: &mut BTreeMap<String, usize>,
) {
    for (index, line) in output.lines().enumerate() {
        let tokens: Vec<&str> = line.split_whitespace().collect();
        let Some(split) = tokens.iter().position(|&t| t == "ref") else {
            continue;
        };
        if let Some(reason) = exemption(&tokens) {
            *exempt.entry(reason).or_default() += 1;
            if honor_exemptions {
                continue;
            }
        }
        let implementation = groups(&tokens[..split]);
        // A line's `tol` is for float32 evaluations (OSMesa) only.
        let line_tol = match build {
            Build::Fflight => None,
            Build::Osmesa => line_tolerance(&tokens),
        };
        for (label, expected) in groups(&tokens[split + 1..]) {
            if label == TOLERANCE_LABEL {
                continue;
            }
            let Some((_, got)) = implementation.iter().find(|(l, _)| *l == label) else {
                report.fail(format!(
                    "{} line {}: ref group `{label}` has no counterpart\n  {line}",
                    build.name(),
                    index + 1
                ));
                continue;
            };
            if got.len() != expected.len() {
                report.fail(format!(
                    "{} line {}: `{label}` has {} values, its ref {}\n  {line}",
                    build.name(),
                    index + 1,
                    got.len(),
                    expected.len()
                ));
                continue;
            }
            for (k, (&g, &e)) in got.iter().zip(&expected).enumerate() {
                stats.record(label, g, e);
                let tol = tolerance(label, k, g, e, line_tol);
                if !close(g, e, tol) {
                    report.fail(format!(
                        "{} vs reference, line {}: {label}[{k}] = {g:.9} expected {e:.9} \
                         (|diff| {:.3e} > tolerance {tol:.1e})\n  {line}",
                        build.name(),
                        index + 1,
                        (g - e).abs()
                    ));
                }
            }
        }
    }
}

/// Compares the fflight output with the OSMesa output token by token.
pub fn check_differential(report: &mut Report, fflight: &str, osmesa: &str, stats: &mut MaxDiff) {
    check_differential_known(report, fflight, osmesa, &[], stats, &mut BTreeMap::new());
}

/// [`check_differential`], accepting the differences `known` declares; each
/// accepted token is counted in `accepted` under the difference's name.
pub fn check_differential_known(
    report: &mut Report,
    fflight: &str,
    osmesa: &str,
    known: &[Known],
    stats: &mut MaxDiff,
    accepted: &mut BTreeMap<String, usize>,
) {
    let a: Vec<&str> = fflight.lines().collect();
    let b: Vec<&str> = osmesa.lines().collect();
    if a.len() != b.len() {
        report.fail(format!(
            "fflight printed {} lines, OSMesa {}",
            a.len(),
            b.len()
        ));
    }
    for (index, (la, lb)) in a.iter().zip(&b).enumerate() {
        let ta: Vec<&str> = la.split_whitespace().collect();
        let tb: Vec<&str> = lb.split_whitespace().collect();
        let where_ = || format!("line {}\n  fflight: {la}\n  osmesa:  {lb}", index + 1);
        if ta.len() != tb.len() {
            report.fail(format!("token counts differ, {}", where_()));
            continue;
        }
        // On an exempt line the groups the reference covers are compared
        // with the reference only.
        let split = ta.iter().position(|&t| t == "ref");
        let line_tol = line_tolerance(&ta);
        let clip_made = ta.contains(&CLIP_MADE);
        let exempt_labels: Vec<&str> = match (exemption(&ta), split) {
            (Some(_), Some(split)) => groups(&ta[split + 1..]).iter().map(|g| g.0).collect(),
            _ => Vec::new(),
        };
        let mut label = "";
        let mut component = 0;
        for (k, (&x, &y)) in ta.iter().zip(&tb).enumerate() {
            match (number(x), number(y)) {
                (Some(u), Some(v)) => {
                    component += 1;
                    let before_ref = split.is_none_or(|s| k < s);
                    if before_ref && exempt_labels.contains(&label) {
                        continue;
                    }
                    let mut tol = tolerance(label, component - 1, u, v, line_tol);
                    if clip_made && is_coordinate_label(label) {
                        tol = tol.max(CLIP_MADE_COORDINATE_TOLERANCE);
                        stats.record("xyz(clip-made)", u, v);
                    } else {
                        stats.record(label, u, v);
                    }
                    if !close(u, v, tol) {
                        report.fail(format!(
                            "`{label}` token {k}: fflight {u:.9} OSMesa {v:.9} \
                             (|diff| {:.3e} > tolerance {tol:.1e}), {}",
                            (u - v).abs(),
                            where_()
                        ));
                    }
                }
                _ => {
                    let line_reset_known = known.contains(&Known::LineReset)
                        && x == "line_reset"
                        && y == "line"
                        && ta.contains(&"line-prim=line_reset");
                    if line_reset_known {
                        *accepted
                            .entry(Known::LineReset.name().to_string())
                            .or_default() += 1;
                    } else if x != y {
                        report.fail(format!("token {k}: `{x}` vs `{y}`, {}", where_()));
                    }
                    if !x.starts_with(EXEMPT_PREFIX) {
                        label = x;
                        component = 0;
                    }
                }
            }
        }
    }
}

pub fn summarize(stats: &MaxDiff) -> String {
    let maxima: Vec<String> = stats
        .by_label
        .iter()
        .filter(|(_, max)| **max > 0.0)
        .map(|(label, max)| format!("{label} {max:.3e}"))
        .collect();
    let exact = stats.by_label.len() - maxima.len();
    format!(
        "{} numbers, max |diff| per label: {} ({exact} other labels exact)",
        stats.compared,
        if maxima.is_empty() {
            "all exact".to_string()
        } else {
            maxima.join(", ")
        }
    )
}
