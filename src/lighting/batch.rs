//! The batch engine: transformation (§2.11) and lighting (§2.14.1) of whole blocks of
//! vertices, one lane per vertex. `process_blocks` runs the single-precision kernel
//! (`lighting::fast`) where its error bound holds, and this file's double-precision engine
//! (`process_blocks_exact`) elsewhere: for the lanes the kernel refuses, for states it cannot
//! bound and on CPUs without AVX2 and FMA. The double-precision engine mirrors the scalar
//! path (`DerivedState::process`, kept as the reference the tests compare both with).
//!
//! The state decides the code, not the vertices: the kernel is chosen once per call from
//! lighting on or off, two-sided lighting and the local viewer (const parameters, so each
//! combination compiles to its own loop), and each light's kind (directional, or positional
//! with or without spot and attenuation) selects its code once per block. Nothing branches on
//! state per vertex. `multiversion` compiles the whole loop for AVX-512, AVX2+FMA and NEON and
//! picks the best the CPU has at run time.
//!
//! Every lane follows the scalar path's operations in the same order, so the two agree to the
//! last bit for ordinary inputs (tests check it on random states).

use glam::{DMat3, DMat4, DVec3, Mat4, Vec4};
use multiversion::multiversion;

use super::lanes::{LANES, Lanes, LanesF32, Vec3s, clamp01, lanes_of};
use super::{PreparedFace, PreparedLight, PreparedLighting};
use crate::pipeline::block::{InputBlock, Lanes4, OutputBlock};
use crate::pipeline::vertex::{DerivedState, VertexTransform};
use crate::state::material::MaterialMask;

/// Which faces' colors the consumer of processed vertices reads.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Faces {
    /// Front and back: polygons (their facing picks the colors), and capture.
    #[default]
    Both,
    /// Front only: points and lines always take the front colors (§2.14.1), as the raster
    /// position does (§2.13); two-sided lighting need not light their back face. The back
    /// colors are then unspecified.
    Front,
}

/// What the consumer of processed vertices reads of them besides their clip coordinates and
/// primary colors: the colors of which faces, and whether the eye coordinates, the secondary
/// colors and the texture coordinates. What is not read is unspecified: the fast engine
/// computes or copies it only where lighting needs it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Reads {
    /// The faces whose colors are read.
    pub faces: Faces,
    /// Whether the eye coordinates are read (by user clip planes, capture, the raster
    /// position).
    pub eye: bool,
    /// Whether the secondary colors are read (by capture and fflLightVertices' outputs;
    /// feedback carries the primary color alone).
    pub secondary: bool,
    /// Whether the texture coordinates are read (by capture, fflLightVertices' outputs and
    /// the feedback layouts with texture coordinates).
    pub tex_coord: bool,
}

/// Everything.
impl Default for Reads {
    fn default() -> Reads {
        Faces::Both.into()
    }
}

/// The colors of `faces`, and everything else.
impl From<Faces> for Reads {
    fn from(faces: Faces) -> Reads {
        Reads {
            faces,
            eye: true,
            secondary: true,
            tex_coord: true,
        }
    }
}

/// Processes `inputs` into `outputs` (pairwise; the shorter decides) with the state `derived`:
/// transformation (§2.11) and lighting (§2.14.1) of every lane, for what `reads` says (a
/// `Faces` reads everything else too). Against `DerivedState::process` vertex by vertex:
/// eye (where read), clip and texture coordinates the same to the last bit, colors within
/// 1e-5 (the fast kernel's bound is 5e-6).
///
/// # Examples
///
/// ```
/// use fflight::lighting::{PreparedLighting, batch::{Faces, process_blocks}};
/// use fflight::pipeline::block::{InputBlock, OutputBlock};
/// use fflight::pipeline::vertex::{CurrentAttribs, DerivedState, VertexTransform};
/// use fflight::state::{light::Light, light_model::LightModel};
/// use fflight::state::material::{ColorMaterial, Material};
/// use glam::{Mat4, Vec3, Vec4};
/// let mut lights = std::array::from_fn(Light::initial);
/// lights[0].enabled = true;
/// let derived = DerivedState::new(
///     VertexTransform::new(
///         Mat4::from_translation(Vec3::new(0.0, 0.0, -5.0)),
///         Mat4::IDENTITY,
///         Mat4::IDENTITY,
///         false,
///         false,
///         None,
///     ),
///     PreparedLighting::new(
///         true,
///         &lights,
///         &[Material::default(); 2],
///         &LightModel::default(),
///         &ColorMaterial::default(),
///     ),
/// );
/// let attribs = CurrentAttribs::default();
/// let mut input = InputBlock::with_attribs(&attribs);
/// input.push(Vec4::new(1.0, 2.0, 3.0, 1.0), &attribs);
/// let mut outputs = [OutputBlock::default()];
/// process_blocks(&derived, Faces::Both, &[input], &mut outputs);
/// let (lit, scalar) = (outputs[0].vertex(0), derived.process(Vec4::new(1.0, 2.0, 3.0, 1.0), &attribs));
/// assert_eq!((lit.eye, lit.clip), (scalar.eye, scalar.clip));
/// assert!((lit.colors.front.primary - scalar.colors.front.primary).abs().max_element() <= 1e-5);
/// assert_eq!(scalar.eye, Vec4::new(1.0, 2.0, -2.0, 1.0));
/// ```
pub fn process_blocks(
    derived: &DerivedState,
    reads: impl Into<Reads>,
    inputs: &[InputBlock],
    outputs: &mut [OutputBlock],
) {
    let reads = reads.into();
    let served = derived
        .fast
        .as_ref()
        .is_some_and(|fast| super::fast::process_blocks(fast, derived, reads, inputs, outputs));
    if !served {
        process_blocks_exact(derived, inputs, outputs);
    }
}

/// One vertex through the engine `process_blocks` runs, so that a lone vertex (the raster
/// position) is lit exactly as the same vertex among other points: the front colors.
///
/// # Examples
///
/// ```
/// use fflight::lighting::batch::process_vertex;
/// use fflight::pipeline::vertex::CurrentAttribs;
/// use fflight::Context;
/// use glam::Vec4;
/// let mut ctx = Context::new();
/// let vertex = process_vertex(ctx.derived(), Vec4::new(1.0, 2.0, 3.0, 1.0), &CurrentAttribs::default());
/// assert_eq!(vertex.clip, Vec4::new(1.0, 2.0, 3.0, 1.0));
/// ```
pub fn process_vertex(
    derived: &DerivedState,
    object: Vec4,
    attribs: &crate::pipeline::vertex::CurrentAttribs,
) -> crate::pipeline::vertex::ProcessedVertex {
    let mut input = InputBlock::with_attribs(attribs);
    input.push(object, attribs);
    let mut output = [OutputBlock::default()];
    process_blocks(
        derived,
        Faces::Front,
        std::slice::from_ref(&input),
        &mut output,
    );
    output[0].vertex(0)
}

/// `process_blocks` in double precision throughout: equal to the scalar path
/// (`DerivedState::process`) to the last bit for ordinary inputs.
#[multiversion(targets(
    "x86_64+avx512f+avx512bw+avx512cd+avx512dq+avx512vl+avx2+fma+bmi1+bmi2+lzcnt+popcnt",
    "x86_64+avx2+fma+bmi1+bmi2+lzcnt+popcnt",
    "aarch64+neon"
))]
pub fn process_blocks_exact(
    derived: &DerivedState,
    inputs: &[InputBlock],
    outputs: &mut [OutputBlock],
) {
    let lighting = &derived.lighting;
    // Plain loops, no closures: a closure would be compiled apart from this function and
    // without its target features.
    macro_rules! run {
        ($lit:literal, $two_side:literal, $local_viewer:literal) => {
            for (input, output) in inputs.iter().zip(outputs.iter_mut()) {
                process::<$lit, $two_side, $local_viewer>(derived, input, output);
            }
        };
    }
    match (lighting.enabled, lighting.two_side, lighting.local_viewer) {
        (false, _, _) => run!(false, false, false),
        (true, false, false) => run!(true, false, false),
        (true, false, true) => run!(true, false, true),
        (true, true, false) => run!(true, true, false),
        (true, true, true) => run!(true, true, true),
    }
}

/// `m * v` per lane, in glam's order of operations.
#[inline(always)]
fn transform4(m: &DMat4, v: &[Lanes; 4]) -> [Lanes; 4] {
    let c = m.to_cols_array_2d();
    let mut out = [Lanes::ZERO; 4];
    for (row, o) in out.iter_mut().enumerate() {
        *o = Lanes::splat(c[0][row]) * v[0]
            + Lanes::splat(c[1][row]) * v[1]
            + Lanes::splat(c[2][row]) * v[2]
            + Lanes::splat(c[3][row]) * v[3];
    }
    out
}

/// `m * v` per lane for the single-precision texture matrix, in glam's order.
#[inline(always)]
fn transform4_f32(m: &Mat4, v: &Lanes4) -> Lanes4 {
    let c = m.to_cols_array_2d();
    let mut out = [[0.0; LANES]; 4];
    for (row, o) in out.iter_mut().enumerate() {
        for lane in 0..LANES {
            o[lane] = c[0][row] * v[0][lane]
                + c[1][row] * v[1][lane]
                + c[2][row] * v[2][lane]
                + c[3][row] * v[3][lane];
        }
    }
    out
}

#[inline(always)]
fn transform3(m: &DMat3, v: Vec3s) -> Vec3s {
    let c = m.to_cols_array_2d();
    let mut out = [Lanes::ZERO; 3];
    for (r, o) in out.iter_mut().enumerate() {
        *o =
            Lanes::splat(c[0][r]) * v.x + Lanes::splat(c[1][r]) * v.y + Lanes::splat(c[2][r]) * v.z;
    }
    Vec3s {
        x: out[0],
        y: out[1],
        z: out[2],
    }
}

#[inline(always)]
fn to_f32(v: [Lanes; 4]) -> Lanes4 {
    [v[0].to_f32(), v[1].to_f32(), v[2].to_f32(), v[3].to_f32()]
}

#[inline(always)]
fn from_f32(v: &Lanes4) -> [Lanes; 4] {
    [
        Lanes::from_f32(&v[0]),
        Lanes::from_f32(&v[1]),
        Lanes::from_f32(&v[2]),
        Lanes::from_f32(&v[3]),
    ]
}

/// The per-face sums of light colors weighted by the light-dependent factors.
struct LightSums {
    ambient: Vec3s,
    diffuse: [Vec3s; 2],
    specular: [Vec3s; 2],
}

/// Adds `weight * color` to `sum` in the lanes where `keep` is positive.
#[inline(always)]
fn accumulate(sum: &mut Vec3s, keep: Lanes, weight: Lanes, color: DVec3) {
    let zero = Lanes::ZERO;
    sum.x = sum.x + keep.select_gt(zero, weight * Lanes::splat(color.x), zero);
    sum.y = sum.y + keep.select_gt(zero, weight * Lanes::splat(color.y), zero);
    sum.z = sum.z + keep.select_gt(zero, weight * Lanes::splat(color.z), zero);
}

/// Light `light`'s terms for the block, added to `sums` (§2.14.1). POSITIONAL, SPOT and
/// ATTENUATION are the light's kind.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn add_light<
    const POSITIONAL: bool,
    const SPOT: bool,
    const ATTENUATION: bool,
    const TWO_SIDE: bool,
    const LOCAL_VIEWER: bool,
>(
    light: &PreparedLight,
    faces: &[PreparedFace; 2],
    position: Vec3s,
    normal: Vec3s,
    eye_direction: Vec3s,
    sums: &mut LightSums,
) {
    let light_position = Vec3s::splat(light.position);
    let (to_light, attenuation) = if POSITIONAL {
        let offset = light_position - position;
        let distance = offset.length();
        // One division, not three: divisions are the kernel's slowest instructions.
        let to_light = offset.scale(Lanes::ONE / distance);
        let k = light.attenuation.unwrap_or(DVec3::X);
        let attenuation = if ATTENUATION {
            Some(
                Lanes::ONE
                    / (Lanes::splat(k.x)
                        + Lanes::splat(k.y) * distance
                        + Lanes::splat(k.z) * distance * distance),
            )
        } else {
            None
        };
        (to_light, attenuation)
    } else {
        (light_position, None)
    };
    let spot = if SPOT {
        let cos_cutoff = light.spot_cos_cutoff.unwrap_or(-1.0);
        let cos_angle = (-to_light).dot(Vec3s::splat(light.spot_direction));
        let factor = cos_angle.max(Lanes::ZERO).pow(light.spot_exponent);
        Some(cos_angle.select_ge(Lanes::splat(cos_cutoff), factor, Lanes::ZERO))
    } else {
        None
    };
    // The scalar path multiplies by an attenuation of 1 and skips lights whose spot factor is
    // 0: a lane whose spot factor is 0 adds nothing.
    let weight = match (attenuation, spot) {
        (Some(a), Some(s)) => a * s,
        (Some(a), None) => a,
        (None, Some(s)) => s,
        (None, None) => Lanes::ONE,
    };
    let lit = match spot {
        Some(s) => s.nonzero(),
        None => Lanes::ONE,
    };
    accumulate(&mut sums.ambient, lit, weight, light.ambient);

    let half = if POSITIONAL || LOCAL_VIEWER {
        (to_light + eye_direction).normalize_or_zero()
    } else {
        Vec3s::splat(light.infinite_half)
    };
    let n_dot_l = normal.dot(to_light);
    let n_dot_h = normal.dot(half);
    let face_count = if TWO_SIDE { 2 } else { 1 };
    for (face, prepared) in faces.iter().enumerate().take(face_count) {
        // The back face sees the negated normal.
        let (n_dot_l, n_dot_h) = if face == 0 {
            (n_dot_l, n_dot_h)
        } else {
            (-n_dot_l, -n_dot_h)
        };
        let diffuse = n_dot_l.max(Lanes::ZERO);
        let specular = n_dot_h.max(Lanes::ZERO).pow(prepared.shininess);
        let keep = diffuse.select_gt(Lanes::ZERO, lit, Lanes::ZERO);
        accumulate(
            &mut sums.diffuse[face],
            keep,
            weight * diffuse,
            light.diffuse,
        );
        accumulate(
            &mut sums.specular[face],
            keep,
            weight * specular,
            light.specular,
        );
    }
}

/// The material property `mask` of `face` per lane: the vertex color where color material
/// tracks it (§2.14.3), else the material's.
#[inline(always)]
fn material_property(
    face: &PreparedFace,
    mask: MaterialMask,
    value: Vec4,
    color: &Lanes4,
) -> Lanes4 {
    if face.tracked.contains(mask) {
        *color
    } else {
        let v = value.to_array();
        [[v[0]; LANES], [v[1]; LANES], [v[2]; LANES], [v[3]; LANES]]
    }
}

#[inline(always)]
fn rgb(c: &Lanes4) -> Vec3s {
    Vec3s {
        x: Lanes::from_f32(&c[0]),
        y: Lanes::from_f32(&c[1]),
        z: Lanes::from_f32(&c[2]),
    }
}

#[inline(always)]
fn clamp_rgba(c: Vec3s, alpha: LanesF32) -> Lanes4 {
    [
        clamp01(c.x.to_f32()),
        clamp01(c.y.to_f32()),
        clamp01(c.z.to_f32()),
        clamp01(alpha),
    ]
}

/// One face's primary and secondary colors from the light sums (§2.14.1).
#[inline(always)]
fn face_colors(
    lighting: &PreparedLighting,
    face: usize,
    sums: &LightSums,
    color: &Lanes4,
) -> (Lanes4, Lanes4) {
    let prepared = &lighting.faces[face];
    let material = &prepared.material;
    let diffuse_rgba = material_property(prepared, MaterialMask::DIFFUSE, material.diffuse, color);
    let ambient = material_property(prepared, MaterialMask::AMBIENT, material.ambient, color);
    let emission = material_property(prepared, MaterialMask::EMISSION, material.emission, color);
    let specular = material_property(prepared, MaterialMask::SPECULAR, material.specular, color);
    let (ambient, emission, specular_color) = (rgb(&ambient), rgb(&emission), rgb(&specular));
    let unlit = emission + ambient * (Vec3s::splat(lighting.scene_ambient) + sums.ambient);
    let diffuse = rgb(&diffuse_rgba) * sums.diffuse[face];
    let specular = specular_color * sums.specular[face];
    let alpha = diffuse_rgba[3];
    if lighting.separate_specular {
        (
            clamp_rgba(unlit + diffuse, alpha),
            clamp_rgba(specular, [0.0; LANES]),
        )
    } else {
        (
            clamp_rgba(unlit + diffuse + specular, alpha),
            [[0.0; LANES]; 4],
        )
    }
}

/// One block through transformation and lighting.
#[inline(always)]
fn process<const LIT: bool, const TWO_SIDE: bool, const LOCAL_VIEWER: bool>(
    derived: &DerivedState,
    input: &InputBlock,
    out: &mut OutputBlock,
) {
    let transform = &derived.transform;
    let object = from_f32(&input.position);
    let eye = transform4(&transform.modelview, &object);
    out.len = input.len;
    out.eye = to_f32(eye);
    out.clip = to_f32(transform4(&transform.object_to_clip, &object));
    if transform.tex_gen.is_some() {
        generate_tex_coords(transform, input, out, 0);
    } else {
        out.tex_coord = transform4_f32(&transform.texture, &input.tex_coord);
    }
    out.edge_flag = input.edge_flag;

    if !LIT {
        let c = &input.color;
        let s = &input.secondary_color;
        let primary = [clamp01(c[0]), clamp01(c[1]), clamp01(c[2]), clamp01(c[3])];
        let secondary = [clamp01(s[0]), clamp01(s[1]), clamp01(s[2]), clamp01(s[3])];
        (out.front_primary, out.front_secondary) = (primary, secondary);
        (out.back_primary, out.back_secondary) = (primary, secondary);
        return;
    }
    let lighting = &derived.lighting;
    let normal = transform3(
        &transform.normal_matrix,
        Vec3s {
            x: Lanes::from_f32(&input.normal[0]),
            y: Lanes::from_f32(&input.normal[1]),
            z: Lanes::from_f32(&input.normal[2]),
        },
    );
    let normal = if transform.normalize {
        normal.normalize_or_zero()
    } else if let Some(scale) = transform.normal_rescale {
        normal.scale(Lanes::splat(scale))
    } else {
        normal
    };
    let position = homogenize(eye);
    let eye_direction = if LOCAL_VIEWER {
        (-position).normalize_or_zero()
    } else {
        Vec3s::splat(DVec3::Z)
    };
    let mut sums = LightSums {
        ambient: Vec3s::ZERO,
        diffuse: [Vec3s::ZERO; 2],
        specular: [Vec3s::ZERO; 2],
    };
    let faces = &lighting.faces;
    for light in lighting.lights() {
        macro_rules! add {
            ($positional:literal, $spot:literal, $attenuation:literal) => {
                add_light::<$positional, $spot, $attenuation, TWO_SIDE, LOCAL_VIEWER>(
                    light,
                    faces,
                    position,
                    normal,
                    eye_direction,
                    &mut sums,
                )
            };
        }
        match (
            light.positional,
            light.spot_cos_cutoff.is_some(),
            light.attenuation.is_some(),
        ) {
            (false, false, _) => add!(false, false, false),
            (false, true, _) => add!(false, true, false),
            (true, false, false) => add!(true, false, false),
            (true, false, true) => add!(true, false, true),
            (true, true, false) => add!(true, true, false),
            (true, true, true) => add!(true, true, true),
        }
    }
    (out.front_primary, out.front_secondary) = face_colors(lighting, 0, &sums, &input.color);
    if TWO_SIDE {
        (out.back_primary, out.back_secondary) = face_colors(lighting, 1, &sums, &input.color);
    } else {
        (out.back_primary, out.back_secondary) = (out.front_primary, out.front_secondary);
    }
}

/// A homogeneous eye-space point as a 3D point, lane by lane (`lighting::homogenize`).
#[inline(always)]
fn homogenize(eye: [Lanes; 4]) -> Vec3s {
    // Dividing by 1 changes nothing: only w = 0 must not divide. A block of w = 1 (affine
    // modelviews of 3D vertices: nearly every block) skips the three divisions, the slowest
    // instructions of the kernel.
    let w = eye[3];
    if w == Lanes::ONE {
        return Vec3s {
            x: eye[0],
            y: eye[1],
            z: eye[2],
        };
    }
    let divisor = w.nonzero().select_gt(Lanes::ZERO, w, Lanes::ONE);
    Vec3s {
        x: eye[0] / divisor,
        y: eye[1] / divisor,
        z: eye[2] / divisor,
    }
}

/// Texture coordinate generation (§2.11.4) and the texture matrix for each lane of `input`
/// but those of `skip`, into `output`: lane by lane, as the scalar path does it (generation
/// is rare and reads double-precision eye coordinates and normals).
pub(crate) fn generate_tex_coords(
    transform: &VertexTransform,
    input: &InputBlock,
    output: &mut OutputBlock,
    skip: u8,
) {
    for lane in lanes_of(!skip) {
        let (position, attribs) = input.vertex(lane);
        let eye = transform.modelview * position.as_dvec4();
        let tex_coord = transform.tex_coord(position, eye, attribs.normal, attribs.tex_coord);
        for (component, value) in output.tex_coord.iter_mut().zip(tex_coord.to_array()) {
            component[lane] = value;
        }
    }
}
