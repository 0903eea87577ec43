// The kernel's code, compiled once per instruction set: `x86.rs` includes it into a module
// whose `with_features!` gives every function that set's target features, so the intrinsics
// the wrappers call inline into each function. Closures here only pick fields: they would not
// inherit the features, so no vector operation may run inside one.

use std::ops::{Add, Sub};

use lanes::{BLOCKS, D2, F, Mask};
use crate::lighting::fast::{
    DISCONTINUITY, DOT_ERROR, ERROR_BUDGET, FastFace, FastLight, FastState, ILL_CONDITIONED,
    SHORTEST_HALF_SQUARED,
};
use crate::lighting::batch::{Faces, Reads};
use crate::pipeline::block::{InputBlock, OutputBlock};
use crate::state::material::MaterialMask;

/// Clamped to [0, 1]; NaN becomes 0, as `lighting::clamp01` makes it.
#[inline(always)]
fn clamp01(x: F) -> F {
    x.max(F::zero()).min(F::splat(1.0))
}

/// (`x^(e-1)`, `x^e`) for `x` >= 0, with 0^0 = 1 and `x^(e-1)` 0 for `e` = 0: the power and
/// its slope over `e`, by repeated squaring. The slope's factor `e` is left to the constants
/// it meets (`FastLight::specular_sensitivity`, `FastLight::spot_term_bounds`). The lanes of
/// `small` count as 0 (see `FastLight::smallest_specular_base`): their squarings could reach
/// subnormal numbers, which the CPU multiplies about a hundred times slower.
#[inline(always)]
fn power_and_below(x: F, exponent: u32, small: Mask) -> (F, F) {
    if exponent <= 1 {
        return if exponent == 0 {
            (F::zero(), F::splat(1.0))
        } else {
            (F::splat(1.0), x)
        };
    }
    let x = (!small).keep(x);
    // x^(e-1) from the bits of e - 1, the lowest set bit's power first (no product by 1).
    let mut bits = exponent - 1;
    let mut base = x;
    while bits & 1 == 0 {
        base = base * base;
        bits >>= 1;
    }
    let mut below = base;
    bits >>= 1;
    while bits != 0 {
        base = base * base;
        if bits & 1 != 0 {
            below = below * base;
        }
        bits >>= 1;
    }
    (below, below * x)
}

/// A 3-vector per lane.
#[derive(Clone, Copy)]
struct V3 {
    x: F,
    y: F,
    z: F,
}

impl V3 {
    #[inline(always)]
    fn splat(v: [f32; 3]) -> V3 {
        V3 {
            x: F::splat(v[0]),
            y: F::splat(v[1]),
            z: F::splat(v[2]),
        }
    }

    #[inline(always)]
    fn zero() -> V3 {
        V3 {
            x: F::zero(),
            y: F::zero(),
            z: F::zero(),
        }
    }

    #[inline(always)]
    fn dot(self, o: V3) -> F {
        self.x.mul_add(o.x, self.y.mul_add(o.y, self.z * o.z))
    }

    #[inline(always)]
    fn scale(self, s: F) -> V3 {
        V3 {
            x: self.x * s,
            y: self.y * s,
            z: self.z * s,
        }
    }

    #[inline(always)]
    fn mul(self, o: V3) -> V3 {
        V3 {
            x: self.x * o.x,
            y: self.y * o.y,
            z: self.z * o.z,
        }
    }
}

/// A constant of light `$light` in every lane, broadcast from its place in the `FastLight`:
/// `constant!(light, field)` for an f32 field, `constant!(light, field[i])` for an array's
/// element of an array of at most 3 (`i` a constant once the face loop is unrolled, so that
/// the check and the match fold away).
macro_rules! constant {
    ($light:expr, $field:ident) => {
        F::broadcast_at::<{ std::mem::offset_of!(FastLight, $field) }, FastLight>($light)
    };
    ($light:expr, $field:ident[$index:expr]) => {{
        let light: &FastLight = $light;
        let index: usize = $index;
        assert!(index < light.$field.len());
        match index {
            0 => F::broadcast_at::<{ std::mem::offset_of!(FastLight, $field) }, FastLight>(light),
            1 => F::broadcast_at::<{ std::mem::offset_of!(FastLight, $field) + 4 }, FastLight>(light),
            2 => F::broadcast_at::<{ std::mem::offset_of!(FastLight, $field) + 8 }, FastLight>(light),
            _ => unreachable!("arrays of at most 3"),
        }
    }};
}

/// A 3-component constant of light `$light` in every lane.
macro_rules! constant3 {
    ($light:expr, $field:ident) => {
        V3 {
            x: constant!($light, $field[0]),
            y: constant!($light, $field[1]),
            z: constant!($light, $field[2]),
        }
    };
}

with_features! {
/// `sum + weight * color`.
#[inline]
fn add_weighted(sum: V3, weight: F, color: V3) -> V3 {
    V3 {
        x: weight.mul_add(color.x, sum.x),
        y: weight.mul_add(color.y, sum.y),
        z: weight.mul_add(color.z, sum.z),
    }
}
}

impl Add for V3 {
    type Output = V3;
    #[inline(always)]
    fn add(self, o: V3) -> V3 {
        V3 {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }
}

impl Sub for V3 {
    type Output = V3;
    #[inline(always)]
    fn sub(self, o: V3) -> V3 {
        V3 {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

/// What the kernel computes beyond the clip coordinates and front primary colors
/// (`process_blocks`).
#[derive(Clone, Copy)]
struct Writes {
    back: bool,
    eye: bool,
    secondary: bool,
    tex_coord: bool,
}

/// The blocks a vector holds, in and out.
type Inputs<'a> = [&'a InputBlock; BLOCKS];
type Outputs<'a> = [&'a mut OutputBlock; BLOCKS];

with_features! {
/// Every block of `inputs` into `outputs` (pairwise), `BLOCKS` at a time (a count of blocks
/// `BLOCKS` divides), for what `reads` says: each block's refused lanes (one bit each, whose
/// outputs the caller replaces) at its index in `refused`. For the front face alone,
/// two-sided lighting runs as one-sided: the front colors are the same.
pub(super) fn process_blocks(
    state: &FastState,
    reads: Reads,
    inputs: &[InputBlock],
    outputs: &mut [OutputBlock],
    refused: &mut [u8],
) {
    let count = inputs.len().min(outputs.len()).min(refused.len());
    debug_assert!(count.is_multiple_of(BLOCKS));
    let two_side = state.two_side && reads.faces == Faces::Both;
    // What is not read is not written: the back and secondary colors and the texture
    // coordinates are a store each, which a short kernel waits on; the eye coordinates a
    // product in double precision.
    let writes = Writes {
        back: reads.faces == Faces::Both,
        eye: reads.eye || state.reads_position,
        secondary: reads.secondary,
        tex_coord: reads.tex_coord,
    };
    let groups = inputs[..count]
        .chunks_exact(BLOCKS)
        .zip(outputs[..count].chunks_exact_mut(BLOCKS))
        .zip(refused[..count].chunks_exact_mut(BLOCKS));
    for ((ins, outs), refused) in groups {
        let ins: Inputs = std::array::from_fn(|k| &ins[k]);
        let mut outs = outs.iter_mut();
        let outs: Outputs = std::array::from_fn(|_| outs.next().expect("BLOCKS outputs"));
        macro_rules! group {
            ($($key:literal),+) => { group_of::<$($key),+>(state, ins, outs, writes) };
        }
        let bits = match (state.lit, two_side, state.local_viewer, state.directional) {
            (false, ..) => group!(false, false, false, false),
            (true, false, false, true) => group!(true, false, false, true),
            (true, false, false, false) => group!(true, false, false, false),
            (true, false, true, _) => group!(true, false, true, false),
            (true, true, false, true) => group!(true, true, false, true),
            (true, true, false, false) => group!(true, true, false, false),
            (true, true, true, _) => group!(true, true, true, false),
        };
        for (k, (refused, input)) in refused.iter_mut().zip(ins).enumerate() {
            *refused = bits.block_bits(k) & crate::lighting::lanes::filled_lanes(input.len);
        }
    }
}
}

/// Four components of the group's blocks: `load4!(ins, field)`, a macro so that the field's
/// projection inlines.
macro_rules! load4 {
    ($ins:expr, $field:ident) => {{
        let ins: &Inputs = &$ins;
        [
            F::load(ins.map(|b| &b.$field[0])),
            F::load(ins.map(|b| &b.$field[1])),
            F::load(ins.map(|b| &b.$field[2])),
            F::load(ins.map(|b| &b.$field[3])),
        ]
    }};
}

/// Stores four components into a field of each of the group's blocks:
/// `store4!(values, outs, field)`.
macro_rules! store4 {
    ($values:expr, $outs:expr, $field:ident) => {{
        let values: [F; 4] = $values;
        for (k, value) in values.into_iter().enumerate() {
            value.store($outs.each_mut().map(|o| &mut o.$field[k]));
        }
    }};
}

with_features! {
#[inline]
fn clamp4(c: [F; 4]) -> [F; 4] {
    [clamp01(c[0]), clamp01(c[1]), clamp01(c[2]), clamp01(c[3])]
}
}

with_features! {
/// `m * v` in double precision with `m` in columns, in glam's order of operations (no fused
/// multiply-add), rounded to single precision: the scalar path's results to the last bit.
#[inline]
fn transform4_exact(m: &[[f64; 4]; 4], v: [D2; 4]) -> [F; 4] {
    let mut rounded = [F::zero(); 4];
    for (row, r) in rounded.iter_mut().enumerate() {
        let mut sum = v[0].scale(m[0][row]);
        sum = sum.add(v[1].scale(m[1][row]));
        sum = sum.add(v[2].scale(m[2][row]));
        *r = sum.add(v[3].scale(m[3][row])).to_f32();
    }
    rounded
}
}

with_features! {
/// `m * v` with `m` in columns, in glam's order of operations (no fused multiply-add), as
/// the scalar path computes texture coordinates.
#[inline]
fn transform4(m: &[[f32; 4]; 4], v: [F; 4]) -> [F; 4] {
    let mut out = [F::zero(); 4];
    for (row, o) in out.iter_mut().enumerate() {
        let xy = F::splat(m[0][row]) * v[0] + F::splat(m[1][row]) * v[1];
        *o = (xy + F::splat(m[2][row]) * v[2]) + F::splat(m[3][row]) * v[3];
    }
    out
}
}

with_features! {
#[inline]
fn transform3(m: &[[f32; 3]; 3], v: V3) -> V3 {
    let mut out = [F::zero(); 3];
    for (r, o) in out.iter_mut().enumerate() {
        let z = F::splat(m[2][r]) * v.z;
        *o = F::splat(m[0][r]).mul_add(v.x, F::splat(m[1][r]).mul_add(v.y, z));
    }
    V3 {
        x: out[0],
        y: out[1],
        z: out[2],
    }
}
}

/// The sums of light colors weighted by the light-dependent factors, per face, and the
/// lanes' sensitivity to the rounding of their dot products.
struct Sums {
    ambient: V3,
    diffuse: [V3; 2],
    specular: [V3; 2],
    /// Through the terms both faces share (diffuse, spot).
    sensitivity: F,
    /// Through each face's specular terms.
    specular_sensitivity: [F; 2],
    refused: Mask,
}

/// What every light reads of the vertex.
struct Vertex {
    position: V3,
    /// |position| / `ILL_CONDITIONED`: with a light's, how near the light the vertex may be
    /// before the rounding of the direction to it grows too large.
    conditioning: F,
    normal: V3,
    /// Lanes whose normal is longer than 1 (beyond rounding).
    long_normal: Mask,
    eye_direction: V3,
    /// n·e: the normal's component along `eye_direction`.
    normal_dot_eye: F,
}

with_features! {
// Not inlined: one function per state key keeps each variant's registers to itself.
// DIRECTIONAL (`FastState::directional`): every light is directional, without a spot; taken
// with an infinite viewer only. Against the loop over every kind, the 1-light arrays scene
// with 30,000 points on one thread: median pair ratio 0.977 (20 of 30 faster).
#[inline(never)]
fn group_of<const LIT: bool, const TWO_SIDE: bool, const LOCAL_VIEWER: bool, const DIRECTIONAL: bool>(
    state: &FastState,
    ins: Inputs,
    mut outs: Outputs,
    writes: Writes,
) -> Mask {
    let object = load4!(ins, position);
    let mut refused = Mask::none();
    for c in &object {
        refused = refused | c.out_of_range();
    }
    let object = [D2::from_f32(object[0]), D2::from_f32(object[1]), D2::from_f32(object[2]), D2::from_f32(object[3])];
    store4!(transform4_exact(&state.object_to_clip, object), outs, clip);
    let eye = if writes.eye {
        let eye = transform4_exact(&state.modelview, object);
        store4!(eye, outs, eye);
        eye
    } else {
        [F::zero(); 4]
    };
    if writes.tex_coord {
        if state.texture_is_identity {
            for (out, input) in outs.iter_mut().zip(ins) {
                out.tex_coord = input.tex_coord;
            }
        } else {
            let tex_coord = transform4(&state.texture, load4!(ins, tex_coord));
            store4!(tex_coord, outs, tex_coord);
        }
    }
    for (out, input) in outs.iter_mut().zip(ins) {
        out.edge_flag = input.edge_flag;
        out.len = input.len;
    }
    let color = load4!(ins, color);
    if !LIT {
        let secondary = load4!(ins, secondary_color);
        for c in color.iter().chain(&secondary) {
            refused = refused | c.out_of_range();
        }
        // Each face's colors stored from registers: copying the front's blocks would load
        // what was just stored in halves, which stalls.
        let (primary, secondary) = (clamp4(color), clamp4(secondary));
        store4!(primary, outs, front_primary);
        if writes.secondary {
            store4!(secondary, outs, front_secondary);
        }
        if writes.back {
            store4!(primary, outs, back_primary);
            if writes.secondary {
                store4!(secondary, outs, back_secondary);
            }
        }
        return refused;
    }
    if state.tracks_color {
        for c in &color {
            refused = refused | c.outside_unit();
        }
    }

    let normal = V3 {
        x: F::load(ins.map(|b| &b.normal[0])),
        y: F::load(ins.map(|b| &b.normal[1])),
        z: F::load(ins.map(|b| &b.normal[2])),
    };
    for c in [normal.x, normal.y, normal.z] {
        refused = refused | c.out_of_range();
    }
    let mut normal = transform3(&state.normal_matrix, normal);
    let length_squared = normal.dot(normal);
    // The dot products' rounding grows with the normal's length.
    let mut normal_scale = F::splat(1.0);
    if state.normalize {
        refused = refused | length_squared.lt(F::splat(1e-12));
        normal = normal.scale(F::splat(1.0).div(length_squared.sqrt()));
    } else {
        let scale = state.normal_rescale.unwrap_or(1.0);
        normal = normal.scale(F::splat(scale));
        // |n| bounded by (|n|² + 1) / 2, which is |n| to within |n|'s excess over 1 squared,
        // instead of a square root of every lane (on AVX-512 the instruction after it held
        // 9.6% of the 1-light kernel's samples).
        let length_bound = length_squared.mul_add(F::splat(0.5), F::splat(0.5));
        normal_scale = (length_bound * F::splat(scale)).max(normal_scale);
    }

    // The vertex's position and its length, where lighting reads them (0 elsewhere).
    let (mut position, mut position_length) = (V3::zero(), F::zero());
    if state.reads_position {
        let w = eye[3];
        position = V3 {
            x: eye[0],
            y: eye[1],
            z: eye[2],
        };
        if !w.all_eq(1.0) {
            // §2.14.1 reads V as homogeneous: divided by w unless w is 0.
            let divisor = w.abs().gt(F::zero()).select(w, F::splat(1.0));
            let inverse = F::splat(1.0).div(divisor);
            position = position.scale(inverse);
            refused = refused | divisor.abs().lt(F::splat(1.0 / 1024.0));
        }
        position_length = position.dot(position).sqrt();
    }
    let eye_direction = if LOCAL_VIEWER {
        refused = refused | position_length.lt(F::splat(1e-6));
        position.scale(-F::splat(1.0).div(position_length))
    } else {
        V3::splat([0.0, 0.0, 1.0])
    };
    let vertex = Vertex {
        position,
        conditioning: position_length * F::splat(1.0 / ILL_CONDITIONED),
        normal,
        long_normal: normal_scale.gt(F::splat(1.0)),
        eye_direction,
        normal_dot_eye: if LOCAL_VIEWER { normal.dot(eye_direction) } else { normal.z },
    };
    let mut sums = Sums {
        ambient: V3::zero(),
        diffuse: [V3::zero(); 2],
        specular: [V3::zero(); 2],
        sensitivity: F::zero(),
        specular_sensitivity: [F::zero(); 2],
        refused,
    };
    for light in state.lights() {
        macro_rules! add {
            ($positional:literal, $spot:literal, $attenuation:literal) => {
                add_light::<$positional, $spot, $attenuation, TWO_SIDE, LOCAL_VIEWER>(
                    light, &state.faces, &vertex, &mut sums,
                )
            };
        }
        if DIRECTIONAL {
            add!(false, false, false);
            continue;
        }
        match (light.positional, light.spot, light.attenuation) {
            (false, false, _) => add!(false, false, false),
            (false, true, _) => add!(false, true, false),
            (true, false, false) => add!(true, false, false),
            (true, false, true) => add!(true, false, true),
            (true, true, false) => add!(true, true, false),
            (true, true, true) => add!(true, true, true),
        }
    }
    let mut refused = sums.refused;
    let face_count = if TWO_SIDE { 2 } else { 1 };
    for face in 0..face_count {
        // The lowest color channel before clamping: a face whose every channel exceeds 1 by
        // more than its error clamps to the same colors, however large the error.
        let mut lowest = F::splat(f32::INFINITY);
        // The face's primary and secondary colors from the light sums (§2.14.1), written
        // here rather than in a function of their own: with the pair lanes the compiler
        // kept that one out of line, and the sums in memory for it.
        let fast = &state.faces[face];
        let diffuse = material_property(fast, MaterialMask::DIFFUSE, fast.diffuse, &color);
        let ambient = material_property(fast, MaterialMask::AMBIENT, fast.ambient, &color);
        let emission = material_property(fast, MaterialMask::EMISSION, fast.emission, &color);
        let specular = material_property(fast, MaterialMask::SPECULAR, fast.specular, &color);
        let scene = V3::splat(state.scene_ambient) + sums.ambient;
        let unlit = rgb(&emission) + rgb(&ambient).mul(scene);
        let lit_diffuse = unlit + rgb(&diffuse).mul(sums.diffuse[face]);
        let lit_specular = rgb(&specular).mul(sums.specular[face]);
        let (primary, secondary) = if state.separate_specular {
            (
                clamp_rgba(lit_diffuse, diffuse[3], &mut refused, &mut lowest),
                clamp_rgba(lit_specular, F::zero(), &mut refused, &mut lowest),
            )
        } else {
            let sum = lit_diffuse + lit_specular;
            (clamp_rgba(sum, diffuse[3], &mut refused, &mut lowest), [F::zero(); 4])
        };
        // One-sided, the back's colors are the front's, stored from registers too.
        if face == 0 {
            store4!(primary, outs, front_primary);
            if writes.secondary {
                store4!(secondary, outs, front_secondary);
            }
        }
        if face == 1 || (!TWO_SIDE && writes.back) {
            store4!(primary, outs, back_primary);
            if writes.secondary {
                store4!(secondary, outs, back_secondary);
            }
        }
        let sensitivity = sums.sensitivity + sums.specular_sensitivity[face];
        let error = sensitivity * normal_scale * F::splat(DOT_ERROR);
        let saturated = lowest.gt(F::splat(1.0) + error);
        refused = refused | (error.exceeds(F::splat(ERROR_BUDGET)) & !saturated);
    }
    refused
}
}

with_features! {
/// Light `light`'s terms, added to `sums` (§2.14.1), with their sensitivities and refusals.
#[inline]
fn add_light<
    const POSITIONAL: bool,
    const SPOT: bool,
    const ATTENUATION: bool,
    const TWO_SIDE: bool,
    const LOCAL_VIEWER: bool,
>(
    light: &FastLight,
    faces: &[FastFace; 2],
    vertex: &Vertex,
    sums: &mut Sums,
) {
    let one = F::splat(1.0);
    let (to_light, attenuation) = if POSITIONAL {
        let offset = constant3!(light, position) - vertex.position;
        let distance_squared = offset.dot(offset);
        let inverse_distance = reciprocal_sqrt(distance_squared);
        let distance = distance_squared * inverse_distance;
        // The direction carries the positions' rounding divided by the distance.
        let conditioning = vertex.conditioning + constant!(light, conditioning);
        sums.refused = sums.refused | distance.lt(conditioning.max(F::splat(1e-6)));
        let to_light = offset.scale(inverse_distance);
        let attenuation = if ATTENUATION {
            let k0 = constant!(light, attenuation_factors[0]);
            let k1 = constant!(light, attenuation_factors[1]);
            let k2 = constant!(light, attenuation_factors[2]);
            let denominator = distance.mul_add(distance.mul_add(k2, k1), k0);
            if light.checks_attenuation {
                sums.refused = sums.refused | denominator.lt(F::splat(1.0 / 1024.0));
            }
            Some(reciprocal(denominator))
        } else {
            None
        };
        (to_light, attenuation)
    } else {
        (constant3!(light, position), None)
    };
    // The spot factor and its slope over the exponent, 0 outside the cone.
    let spot = if SPOT {
        let cos_angle = to_light.dot(constant3!(light, spot_axis_to_light));
        let cutoff = constant!(light, spot_cos_cutoff);
        sums.refused = sums.refused | (cos_angle - cutoff).abs().lt(F::splat(DISCONTINUITY));
        let inside = cos_angle.ge(cutoff);
        // Where the normal is longer than 1, the terms the spot factor weighs are not bounded.
        let small = cos_angle.lt(constant!(light, smallest_spot_base)) & !vertex.long_normal;
        let (below, power) = power_and_below(cos_angle.max(F::zero()), light.spot_exponent, small);
        let below = match attenuation {
            Some(a) => inside.keep_product(a, below),
            None => inside.keep(below),
        };
        Some((inside.keep(power), below))
    } else {
        None
    };
    // The spot factor's rounding reaches the light's whole contribution: its slope times
    // the light's terms, bounded after the faces below.
    let (spot, spot_below) = match spot {
        Some((power, below)) => (Some(power), Some(below)),
        None => (None, None),
    };
    let weight = match (attenuation, spot) {
        (Some(a), Some(s)) => a * s,
        (Some(a), None) => a,
        (None, Some(s)) => s,
        (None, None) => one,
    };
    if light.has_ambient {
        sums.ambient = add_weighted(sums.ambient, weight, constant3!(light, ambient));
    }

    let normal = vertex.normal;
    let n_dot_l = normal.dot(to_light);
    let n_dot_h = if POSITIONAL || LOCAL_VIEWER {
        let half = to_light + vertex.eye_direction;
        let length_squared = half.dot(half);
        sums.refused = sums.refused | length_squared.lt(F::splat(SHORTEST_HALF_SQUARED));
        // n·(L + e) as n·L + n·e: the second is the vertex's, once for every light.
        (n_dot_l + vertex.normal_dot_eye) * reciprocal_sqrt(length_squared)
    } else {
        normal.dot(constant3!(light, infinite_half))
    };
    // Whether the specular term counts changes at n·L = 0.
    sums.refused = sums.refused | n_dot_l.abs().lt(F::splat(DISCONTINUITY));
    sums.sensitivity = weight.mul_add(constant!(light, term_bounds[1]), sums.sensitivity);
    let face_count = if TWO_SIDE { 2 } else { 1 };
    // The faces see n·h and -n·h, of which one at most is positive: with one shininess
    // (and a power of 0 that is 0), one power of |n·h| serves both.
    let shininess = faces[0].shininess;
    let shared = if TWO_SIDE && shininess > 0 && faces[1].shininess == shininess {
        let [front, back] = light.smallest_specular_base;
        let base = n_dot_h.abs();
        Some(power_and_below(base, shininess, base.lt(F::splat(front.min(back)))))
    } else {
        None
    };
    let mut largest_power = F::zero();
    for (face, fast) in faces.iter().enumerate().take(face_count) {
        // The back face sees the negated normal.
        let (n_dot_l, n_dot_h) = if face == 0 {
            (n_dot_l, n_dot_h)
        } else {
            (-n_dot_l, -n_dot_h)
        };
        let diffuse = n_dot_l.max(F::zero());
        let lit = diffuse.gt(F::zero());
        // The specular term counts where the face is lit (and, for the shared power, faces
        // the half vector).
        let ((below, power), counts) = match shared {
            Some(powers) => (powers, lit & n_dot_h.gt(F::zero())),
            None => {
                let small = n_dot_h.lt(constant!(light, smallest_specular_base[face]));
                (power_and_below(n_dot_h.max(F::zero()), fast.shininess, small), lit)
            }
        };
        let power = counts.keep(power);
        sums.diffuse[face] = add_weighted(sums.diffuse[face], weight * diffuse, constant3!(light, diffuse));
        sums.specular[face] = add_weighted(sums.specular[face], weight * power, constant3!(light, specular));
        sums.specular_sensitivity[face] = counts.keep_product(weight, below).mul_add(
            constant!(light, specular_sensitivity[face]),
            sums.specular_sensitivity[face],
        );
        if SPOT {
            largest_power = if face == 0 { power } else { largest_power.max(power) };
        }
    }
    if let Some(below) = spot_below {
        let terms = constant!(light, spot_term_bounds[1]).mul_add(
            n_dot_l.abs(),
            constant!(light, spot_term_bounds[2])
                .mul_add(largest_power, constant!(light, spot_term_bounds[0])),
        );
        sums.sensitivity = below.mul_add(terms, sums.sensitivity);
    }
}
}

with_features! {
/// The material property `mask` of `face` per lane: the vertex color where color material
/// tracks it (§2.14.3), else the material's.
#[inline]
fn material_property(face: &FastFace, mask: MaterialMask, value: [f32; 4], color: &[F; 4]) -> [F; 4] {
    if face.tracked.contains(mask) {
        *color
    } else {
        [F::splat(value[0]), F::splat(value[1]), F::splat(value[2]), F::splat(value[3])]
    }
}
}

with_features! {
#[inline]
fn rgb(c: &[F; 4]) -> V3 {
    V3 {
        x: c[0],
        y: c[1],
        z: c[2],
    }
}
}

with_features! {
/// `c` clamped, with `alpha`. Lanes where `c` is NaN (an overflow times 0: a power of a
/// normal longer than 1 beyond single precision's range) are added to `refused`, and
/// `lowest` keeps the lowest channel before clamping.
#[inline]
fn clamp_rgba(c: V3, alpha: F, refused: &mut Mask, lowest: &mut F) -> [F; 4] {
    *refused = *refused | c.x.is_nan() | c.y.is_nan() | c.z.is_nan();
    *lowest = lowest.min(c.x).min(c.y).min(c.z);
    [clamp01(c.x), clamp01(c.y), clamp01(c.z), clamp01(alpha)]
}
}
