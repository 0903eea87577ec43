//! The fast engine: transformation (§2.11) and lighting (§2.14.1) of blocks in single
//! precision, with explicit SIMD code (AVX2 with FMA, and the same code compiled for AVX-512's
//! 32 registers), chosen at run time. `process_blocks` uses it wherever it meets the double
//! precision reference's tolerance and the CPU has the instructions; elsewhere the
//! double-precision engine (`batch::process_blocks_exact`) runs.
//!
//! Single precision is not accurate enough everywhere: a power x^e multiplies the error of its
//! base by e·x^(e-1) (up to 128 near a highlight of shininess 128), and a weight above 1 (an
//! attenuation of a near light) magnifies the error of its dot product. So the kernel keeps,
//! per lane, the *sensitivity* of its colors to the rounding of its dot products, and bounds
//! the error by it: a lane whose colors could move by more than `ERROR_BUDGET`, whose
//! geometry is ill-conditioned (a vertex nearly on a positional light, a half vector between
//! almost opposite directions, a normal too short to normalize, a dot product at a
//! discontinuity of the equation: n·L at 0, a spot cosine at its cutoff), or whose inputs lie
//! outside single precision's comfortable range is *refused* and lit again by the scalar
//! double-precision path. States the bound does not hold for (fractional exponents, negative
//! colors that could cancel, huge matrices) never reach the kernel. A power whose term no
//! color shows counts as 0 (`smallest_base`), so that no squaring reaches subnormal numbers.

#[cfg(target_arch = "x86_64")]
mod x86;

use glam::{DVec3, Mat3, Mat4, Vec4};

use super::batch::{Reads, generate_tex_coords, process_blocks_exact};
use super::lanes::{LANES, lanes_of};
use super::{PreparedFace, PreparedLight, PreparedLighting};
use crate::pipeline::block::{InputBlock, OutputBlock};
use crate::pipeline::vertex::{DerivedState, VertexTransform};
use crate::state::light::MAX_LIGHTS;
use crate::state::material::MaterialMask;

/// How far single precision may move a color from the double-precision result through the
/// rounding of its dot products. The tests hold the engine to 1e-5 of the reference; the rest
/// of single precision's error (products and sums of non-negative terms, each within a few
/// units in the last place of a result no larger than 1 once clamped) stays below 1e-6.
const ERROR_BUDGET: f32 = 5e-6;

/// The rounding error of a dot product of unit vectors in the kernel (under 2 units in the
/// last place of 1), by which the sensitivities are multiplied. The sensitivities are upper
/// bounds (every term at its largest), so the product bounds the color error: on 30,000 random
/// states `tests/batch_engine.rs` finds served lanes within 4.6e-6, and 1.7e-5 without the
/// bound.
const DOT_ERROR: f32 = 1e-7;

/// How many dot products' rounding n·h carries: the half vector is the sum of two normalized
/// directions (to the light, and to the eye under a local viewer), normalized once more. On
/// 30,000 random states the served lanes stay within 4.6e-6 of the reference with 4 (4.4e-6
/// before n·h was taken as n·L + n·e), and reached 6.7e-6 with 1.
const HALF_VECTOR_ROUNDINGS: f32 = 4.0;

/// Inputs beyond this magnitude (and NaN) are refused: their squares and products stay far
/// from overflow. Matrices and light positions beyond it keep the whole state out.
const SINGLE_RANGE: f32 = 1_048_576.0;

/// A vertex nearer a positional light than 1/64 of their distances from the eye is refused:
/// the direction to the light carries the eye position's rounding divided by the distance.
/// Likewise a half vector shorter than 1/16 before normalization.
const ILL_CONDITIONED: f32 = 64.0;
const SHORTEST_HALF_SQUARED: f32 = 1.0 / 256.0;

/// A dot product this close to a discontinuity of the equation (n·L at 0, a spot cosine at
/// its cutoff) may fall on the other side of it than in double precision: refused.
const DISCONTINUITY: f32 = 1e-6;

/// One enabled light in single precision, with its sensitivities.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct FastLight {
    positional: bool,
    spot: bool,
    attenuation: bool,
    ambient: [f32; 3],
    diffuse: [f32; 3],
    specular: [f32; 3],
    /// Some ambient component is not 0: else the light adds no ambient term.
    has_ambient: bool,
    /// Positional: the eye-space position. Directional: the unit direction to the light.
    position: [f32; 3],
    /// |position| / `ILL_CONDITIONED`, for the conditioning of the direction to a positional
    /// light.
    conditioning: f32,
    infinite_half: [f32; 3],
    /// The direction from the spot light, negated: the cosine of a vertex's angle from the
    /// spot's axis is its dot product with the direction to the light.
    spot_axis_to_light: [f32; 3],
    spot_cos_cutoff: f32,
    spot_exponent: u32,
    /// (constant, linear, quadratic).
    attenuation_factors: [f32; 3],
    /// Whether the attenuation's denominator can fall below 1/1024 (and so magnify errors):
    /// not when k0 >= 1/1024 and k1, k2 >= 0.
    checks_attenuation: bool,
    /// The largest ambient, diffuse and specular products of the light's colors with the
    /// faces' materials: what its terms weigh at most, per unit of n·L and (n·h)^s. The
    /// diffuse one is also by how much an error in n·L moves a color.
    term_bounds: [f32; 3],
    /// `term_bounds` times the spot exponent e: a spot factor's slope e·x^(e-1) is kept as
    /// x^(e-1), and these bound its terms per unit of it.
    spot_term_bounds: [f32; 3],
    /// Each face's largest specular product, times `HALF_VECTOR_ROUNDINGS` and the face's
    /// shininess s: how much an error in n·h moves a color, per unit of (n·h)^(s-1) (the
    /// power's slope over s).
    specular_sensitivity: [f32; 2],
    /// The `smallest_base` of each face's specular power, and of the spot factor's (which
    /// the kernel applies only where the normal is no longer than 1: elsewhere n·L and n·h,
    /// and so the terms the spot factor weighs, are not bounded by `term_bounds`).
    smallest_specular_base: [f32; 2],
    smallest_spot_base: f32,
}

/// One face's material in single precision.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct FastFace {
    ambient: [f32; 4],
    diffuse: [f32; 4],
    specular: [f32; 4],
    emission: [f32; 4],
    tracked: MaterialMask,
    shininess: u32,
}

/// The single-precision constants of a state the fast engine serves: what `DerivedState`
/// holds, rounded to f32 once per state change.
#[derive(Clone, Debug, PartialEq)]
pub struct FastState {
    /// In double precision: eye and clip coordinates are computed as the scalar path computes
    /// them, to the last bit, so clipping and window coordinates do not depend on the engine.
    modelview: [[f64; 4]; 4],
    object_to_clip: [[f64; 4]; 4],
    texture: [[f32; 4]; 4],
    texture_is_identity: bool,
    tex_gen: bool,
    normal_matrix: [[f32; 3]; 3],
    normalize: bool,
    normal_rescale: Option<f32>,
    lit: bool,
    two_side: bool,
    local_viewer: bool,
    /// Some light is positional, or the viewer local: lighting reads the eye coordinates.
    reads_position: bool,
    separate_specular: bool,
    /// Every light is directional, without a spot: the kernel's light loop has that kind
    /// alone, so its registers are that kind's (no spills of the sums around the loop).
    directional: bool,
    lights: [FastLight; MAX_LIGHTS],
    light_count: usize,
    faces: [FastFace; 2],
    scene_ambient: [f32; 3],
    /// Some material property follows the vertex color: lanes whose color leaves [0, 1] are
    /// refused (the sensitivities assume it).
    tracks_color: bool,
}

fn rgb(v: DVec3) -> [f32; 3] {
    v.as_vec3().to_array()
}

fn in_range(values: &[f32]) -> bool {
    values.iter().all(|v| v.abs() <= SINGLE_RANGE)
}

/// The smallest base the kernel raises to `exponent` for a term of at most `bound` per unit of
/// the power; below it the base counts as 0. There the power is under 2^-50 and the term
/// under 2^-40 (a light's weight, attenuation times spot factor, is at most 1024 where the
/// kernel serves a lane): no color shows it, and a product of two such powers (a spot factor
/// and a specular one) stays a normal number. The power's slope goes with it, so the
/// sensitivities lose nothing either. 0 for exponents 0 and 1, which multiply nothing.
fn smallest_base(exponent: u32, bound: f32) -> f32 {
    if exponent <= 1 {
        return 0.0;
    }
    let negligible = (2f64.powi(-50) / f64::from(bound)).min(2f64.powi(-50));
    negligible.powf(1.0 / f64::from(exponent)) as f32
}

fn integer_exponent(e: f64) -> Option<u32> {
    (e.fract() == 0.0 && (0.0..=128.0).contains(&e)).then_some(e as u32)
}

impl FastState {
    /// The constants for `transform` and `lighting`, or `None` where single precision cannot
    /// be bounded: fractional or out-of-range exponents, negative colors, matrices or light
    /// positions beyond 2^20.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::fast::FastState;
    /// use fflight::Context;
    /// let mut ctx = Context::new();
    /// let derived = ctx.derived();
    /// assert!(FastState::new(&derived.transform, &derived.lighting).is_some());
    /// ```
    pub fn new(transform: &VertexTransform, lighting: &PreparedLighting) -> Option<FastState> {
        let modelview = transform.modelview.as_mat4();
        let object_to_clip = transform.object_to_clip.as_mat4();
        let normal_matrix = transform.normal_matrix.as_mat3();
        let matrices_ok = in_range(&modelview.to_cols_array())
            && in_range(&object_to_clip.to_cols_array())
            && in_range(&transform.texture.to_cols_array())
            && in_range(&normal_matrix.to_cols_array())
            && transform
                .normal_rescale
                .is_none_or(|s| in_range(&[s as f32]));
        if !matrices_ok {
            return None;
        }
        let mut state = FastState {
            modelview: transform.modelview.to_cols_array_2d(),
            object_to_clip: transform.object_to_clip.to_cols_array_2d(),
            texture: transform.texture.to_cols_array_2d(),
            texture_is_identity: transform.texture == Mat4::IDENTITY,
            tex_gen: transform.tex_gen.is_some(),
            normal_matrix: Mat3::to_cols_array_2d(&normal_matrix),
            normalize: transform.normalize,
            normal_rescale: transform.normal_rescale.map(|s| s as f32),
            lit: lighting.enabled,
            two_side: lighting.two_side,
            local_viewer: lighting.local_viewer,
            reads_position: lighting.enabled
                && (lighting.local_viewer || lighting.lights().any(|l| l.positional)),
            separate_specular: lighting.separate_specular,
            directional: false,
            lights: [FastLight::default(); MAX_LIGHTS],
            light_count: 0,
            faces: [FastFace::default(); 2],
            scene_ambient: rgb(lighting.scene_ambient),
            tracks_color: false,
        };
        if !lighting.enabled {
            return Some(state);
        }
        let face_count = if lighting.two_side { 2 } else { 1 };
        // Only the faces lit: one-sided lighting ignores the back material.
        for (fast, face) in state.faces.iter_mut().zip(&lighting.faces).take(face_count) {
            *fast = FastFace::new(face)?;
        }
        let faces = &state.faces[..face_count];
        state.tracks_color = faces.iter().any(|f| f.tracked != MaterialMask::NONE);
        let colors_ok = |c: &[f32]| c.iter().all(|v| *v >= 0.0);
        if !colors_ok(&state.scene_ambient) {
            return None;
        }
        for light in lighting.lights() {
            state.lights[state.light_count] = FastLight::new(light, faces)?;
            state.light_count += 1;
        }
        state.directional = state.lights().iter().all(|l| !l.positional && !l.spot);
        Some(state)
    }

    fn lights(&self) -> &[FastLight] {
        &self.lights[..self.light_count]
    }
}

impl FastFace {
    fn new(face: &PreparedFace) -> Option<FastFace> {
        let m = &face.material;
        let fast = FastFace {
            ambient: m.ambient.to_array(),
            diffuse: m.diffuse.to_array(),
            specular: m.specular.to_array(),
            emission: m.emission.to_array(),
            tracked: face.tracked,
            shininess: integer_exponent(face.shininess)?,
        };
        // A tracked property is the vertex color, checked per lane.
        let untracked_ok = [
            (MaterialMask::AMBIENT, m.ambient),
            (MaterialMask::DIFFUSE, m.diffuse),
            (MaterialMask::SPECULAR, m.specular),
            (MaterialMask::EMISSION, m.emission),
        ]
        .into_iter()
        .all(|(mask, value)| face.tracked.contains(mask) || value.truncate().min_element() >= 0.0);
        untracked_ok.then_some(fast)
    }

    /// The property `mask`'s RGB as the sensitivities see it: 1 where the color tracks it.
    fn bound(&self, mask: MaterialMask, value: [f32; 4]) -> Vec4 {
        if self.tracked.contains(mask) {
            Vec4::ONE
        } else {
            Vec4::from_array(value)
        }
    }
}

impl FastLight {
    fn new(light: &PreparedLight, faces: &[FastFace]) -> Option<FastLight> {
        let colors = [light.ambient, light.diffuse, light.specular];
        if colors.iter().any(|c| c.min_element() < 0.0) {
            return None;
        }
        let position = rgb(light.position);
        if !in_range(&position) {
            return None;
        }
        let spot = light.spot_cos_cutoff.is_some();
        let attenuation = light.attenuation.unwrap_or(DVec3::X);
        let mut fast = FastLight {
            positional: light.positional,
            spot,
            attenuation: light.attenuation.is_some(),
            ambient: rgb(light.ambient),
            has_ambient: light.ambient != DVec3::ZERO,
            diffuse: rgb(light.diffuse),
            specular: rgb(light.specular),
            position,
            conditioning: light.position.length() as f32 / ILL_CONDITIONED,
            infinite_half: rgb(light.infinite_half),
            spot_axis_to_light: rgb(-light.spot_direction),
            spot_cos_cutoff: light.spot_cos_cutoff.unwrap_or(-1.0) as f32,
            spot_exponent: if spot {
                integer_exponent(light.spot_exponent)?
            } else {
                0
            },
            attenuation_factors: rgb(attenuation),
            checks_attenuation: !(attenuation.x >= 1.0 / 1024.0
                && attenuation.y >= 0.0
                && attenuation.z >= 0.0),
            ..FastLight::default()
        };
        let largest =
            |a: [f32; 3], m: Vec4| (glam::Vec3::from_array(a) * m.truncate()).max_element();
        for (k, face) in faces.iter().enumerate() {
            let a = largest(
                fast.ambient,
                face.bound(MaterialMask::AMBIENT, face.ambient),
            );
            let d = largest(
                fast.diffuse,
                face.bound(MaterialMask::DIFFUSE, face.diffuse),
            );
            let s = largest(
                fast.specular,
                face.bound(MaterialMask::SPECULAR, face.specular),
            );
            fast.specular_sensitivity[k] = HALF_VECTOR_ROUNDINGS * s * face.shininess as f32;
            fast.smallest_specular_base[k] = smallest_base(face.shininess, s);
            for (bound, value) in fast.term_bounds.iter_mut().zip([a, d, s]) {
                *bound = bound.max(value);
            }
        }
        fast.spot_term_bounds = fast.term_bounds.map(|b| b * fast.spot_exponent as f32);
        fast.smallest_spot_base = smallest_base(fast.spot_exponent, fast.term_bounds.iter().sum());
        Some(fast)
    }
}

/// Processes `inputs` into `outputs` (pairwise) with the fast engine for what `reads` says,
/// and returns true; or returns false, having written nothing, when the CPU lacks the
/// instructions.
pub(crate) fn process_blocks(
    state: &FastState,
    derived: &DerivedState,
    reads: Reads,
    inputs: &[InputBlock],
    outputs: &mut [OutputBlock],
) -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        let Some(kernel) = x86::kernel() else {
            return false;
        };
        // Made at the first refusal, most calls have none; on the stack, not the heap: a tenth
        // of the 1-light arrays scene's calls have one.
        let mut queue: Option<RefusedLanes> = None;
        let count = inputs.len().min(outputs.len());
        const CHUNK: usize = 16;
        let mut refused = [0u8; CHUNK];
        for first in (0..count).step_by(CHUNK) {
            let end = count.min(first + CHUNK);
            let refused = &mut refused[..end - first];
            kernel(
                state,
                reads,
                &inputs[first..end],
                &mut outputs[first..end],
                refused,
            );
            for (k, &lanes) in refused.iter().enumerate() {
                let block = first + k;
                if state.tex_gen && reads.tex_coord {
                    // Refused lanes get theirs from the scalar path.
                    generate_tex_coords(
                        &derived.transform,
                        &inputs[block],
                        &mut outputs[block],
                        lanes,
                    );
                }
                for lane in lanes_of(lanes) {
                    let queue = queue.get_or_insert_default();
                    if queue.push(&inputs[block], block, lane) {
                        queue.relight(derived, &mut outputs[..=block]);
                    }
                }
            }
        }
        if let Some(queue) = &mut queue {
            queue.relight(derived, outputs);
        }
        true
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = (state, derived, reads, inputs, outputs);
        false
    }
}

/// The instruction sets the kernel is compiled for on x86-64.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InstructionSet {
    /// AVX2 with FMA: eight lanes, a block at a time.
    Avx2,
    /// AVX-512 (F and VL): sixteen lanes, two blocks at a time.
    Avx512,
}

/// The kernel of instruction set `set` alone on `inputs` into `outputs` for what `reads`
/// says (the colors of some faces, and maybe the eye coordinates): its outputs for the lanes
/// it serves, and each block's refused lanes (one bit each; their outputs are to be
/// replaced) at the block's index in `refused`; false when this CPU lacks `set`. Texture
/// coordinate generation is left out. For tests that compare the instruction sets whatever
/// the machine would pick, and measure what the kernel serves.
///
/// # Examples
///
/// ```
/// use fflight::lighting::{batch::Faces, fast::{InstructionSet, kernel_blocks_on}};
/// use fflight::pipeline::block::{InputBlock, OutputBlock};
/// use fflight::pipeline::vertex::CurrentAttribs;
/// use fflight::Context;
/// use glam::Vec4;
/// let mut ctx = Context::new();
/// let fast = ctx.derived().fast.clone().unwrap();
/// let mut input = InputBlock::default();
/// input.push(Vec4::new(f32::NAN, 0.0, 0.0, 1.0), &CurrentAttribs::default());
/// input.push(Vec4::new(1.0, 2.0, 3.0, 1.0), &CurrentAttribs::default());
/// let (mut outputs, mut refused) = ([OutputBlock::default()], [0]);
/// if kernel_blocks_on(InstructionSet::Avx2, &fast, Faces::Both, &[input], &mut outputs, &mut refused) {
///     assert_eq!(refused, [0b01]); // the NaN lane goes to the scalar path
///     assert_eq!(outputs[0].vertex(1).clip, Vec4::new(1.0, 2.0, 3.0, 1.0));
/// }
/// ```
pub fn kernel_blocks_on(
    set: InstructionSet,
    state: &FastState,
    reads: impl Into<Reads>,
    inputs: &[InputBlock],
    outputs: &mut [OutputBlock],
    refused: &mut [u8],
) -> bool {
    let reads = reads.into();
    #[cfg(target_arch = "x86_64")]
    {
        x86::kernel_for(set).is_some_and(|kernel| {
            kernel(state, reads, inputs, outputs, refused);
            true
        })
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = (set, state, reads, inputs, outputs, refused);
        false
    }
}

/// Lanes the kernel refused, gathered from the blocks of a call into one block and lit again
/// by the double-precision engine eight at a time (the scalar path's results to the last bit,
/// at a fraction of its cost per vertex).
#[derive(Default)]
struct RefusedLanes {
    input: InputBlock,
    /// Where each lane came from: (block, lane).
    origins: [(usize, usize); LANES],
}

impl RefusedLanes {
    /// Queues lane `lane` of `input`, block `block` of the call; true when the queue is full.
    fn push(&mut self, input: &InputBlock, block: usize, lane: usize) -> bool {
        let (position, attribs) = input.vertex(lane);
        self.origins[self.input.len] = (block, lane);
        self.input.push(position, &attribs);
        self.input.is_full()
    }

    /// Lights the queued lanes into their places in `outputs`, and empties the queue.
    fn relight(&mut self, derived: &DerivedState, outputs: &mut [OutputBlock]) {
        let len = self.input.len;
        if len <= 2 {
            // Fewer lanes than the block engine's cost: one by one (the same results).
            for (k, &(block, lane)) in self.origins[..len].iter().enumerate() {
                let (position, attribs) = self.input.vertex(k);
                outputs[block].set_vertex(lane, &derived.process(position, &attribs));
            }
        } else {
            let mut lit = [OutputBlock::default()];
            process_blocks_exact(derived, std::slice::from_ref(&self.input), &mut lit);
            for (k, &(block, lane)) in self.origins[..len].iter().enumerate() {
                outputs[block].set_vertex(lane, &lit[0].vertex(k));
            }
        }
        self.input.len = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::smallest_base;

    /// Below `smallest_base` a power's term is under 2^-40 whatever the light's brightness,
    /// and at it the product of two powers (a spot factor and a specular one) is a normal
    /// number for terms of ordinary brightness.
    #[test]
    fn powers_counted_as_zero_are_negligible_and_the_others_normal() {
        for exponent in 2..=128 {
            for bound in [0.0, 1e-3, 0.5, 1.0, 3.0, 1e3, 1e6, 1e12] {
                let base = f64::from(smallest_base(exponent, bound));
                let power = base.powi(exponent as i32);
                assert!(
                    power * 1024.0 * f64::from(bound) <= 2f64.powi(-40) * (1.0 + 1e-5),
                    "{exponent} {bound}"
                );
                if bound <= 1e3 {
                    assert!(
                        power * power >= f64::from(f32::MIN_POSITIVE),
                        "{exponent} {bound}"
                    );
                }
            }
        }
        assert_eq!(smallest_base(0, 1.0), 0.0);
        assert_eq!(smallest_base(1, 1.0), 0.0);
    }
}
