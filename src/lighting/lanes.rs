//! Lanes: one f64 or f32 value per vertex of a block, with the element-wise arithmetic the
//! batch engine needs. Every operation is a plain loop over a fixed-size array, which the
//! compiler turns into vector instructions of the width the calling kernel was compiled for
//! (AVX-512, AVX2 or NEON through `multiversion`, SSE2 otherwise). Each lane rounds exactly as
//! the scalar operation would: no fused multiply-add, no approximate reciprocals, so results
//! are the same on every machine and every vector width.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// `Lanes` whose lane `i` is `expr`: a plain loop, no closure, so it compiles inline with the
/// calling kernel's vector instructions.
macro_rules! lanewise {
    ($i:ident => $expr:expr) => {{
        let mut out = [0.0f64; LANES];
        for $i in 0..LANES {
            out[$i] = $expr;
        }
        Lanes(out)
    }};
}

/// `then` if `condition`, else `otherwise`, by masking bits: compilers keep it a vector
/// blend where an `if` can become a branch per lane.
#[inline(always)]
fn select(condition: bool, then: f64, otherwise: f64) -> f64 {
    let mask = (condition as u64).wrapping_neg();
    f64::from_bits((then.to_bits() & mask) | (otherwise.to_bits() & !mask))
}

/// Vertices per block.
pub const LANES: usize = 8;

/// The mask of a block's first `len` lanes (a bit each, lane 0 lowest), `len` at most
/// `LANES`.
///
/// # Examples
///
/// ```
/// use fflight::lighting::lanes::filled_lanes;
/// assert_eq!((filled_lanes(0), filled_lanes(3), filled_lanes(8)), (0, 0b111, 0xff));
/// ```
#[inline(always)]
pub fn filled_lanes(len: usize) -> u8 {
    ((1u16 << len) - 1) as u8
}

/// The lanes whose bits `mask` sets (lane 0 lowest), in order: a step per set bit, none for
/// an empty mask (the usual one).
///
/// # Examples
///
/// ```
/// use fflight::lighting::lanes::lanes_of;
/// assert_eq!(lanes_of(0b1000_0101).collect::<Vec<_>>(), [0, 2, 7]);
/// ```
#[inline(always)]
pub fn lanes_of(mask: u8) -> impl Iterator<Item = usize> {
    let mut rest = mask;
    std::iter::from_fn(move || {
        (rest != 0).then(|| {
            let lane = rest.trailing_zeros() as usize;
            rest &= rest - 1;
            lane
        })
    })
}

/// One f64 per lane.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(align(64))]
pub struct Lanes(pub [f64; LANES]);

/// One f32 per lane: the block's inputs and outputs.
pub type LanesF32 = [f32; LANES];

impl Lanes {
    /// 0 in every lane.
    pub const ZERO: Lanes = Lanes([0.0; LANES]);
    /// 1 in every lane.
    pub const ONE: Lanes = Lanes([1.0; LANES]);

    /// `value` in every lane: a per-state constant (a light's color, a matrix element) made
    /// ready to combine with per-vertex lanes.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{LANES, Lanes};
    /// assert_eq!(Lanes::splat(0.5).0, [0.5; LANES]);
    /// assert_eq!(Lanes::splat(1.0), Lanes::ONE);
    /// ```
    #[inline(always)]
    pub fn splat(value: f64) -> Lanes {
        Lanes([value; LANES])
    }

    /// The block's single-precision values, widened exactly to f64.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{LANES, Lanes};
    /// let lanes = Lanes::from_f32(&[0.1; LANES]);
    /// assert_eq!(lanes.0[0], f64::from(0.1f32));
    /// ```
    #[inline(always)]
    pub fn from_f32(values: &LanesF32) -> Lanes {
        lanewise!(i => f64::from(values[i]))
    }

    /// Each lane rounded to the nearest f32, as the scalar path's `as f32` does.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{LANES, Lanes};
    /// let third = Lanes::splat(1.0 / 3.0).to_f32();
    /// assert_eq!(third, [(1.0f64 / 3.0) as f32; LANES]);
    /// ```
    #[inline(always)]
    pub fn to_f32(self) -> LanesF32 {
        let mut out = [0.0; LANES];
        for (o, v) in out.iter_mut().zip(self.0) {
            *o = v as f32;
        }
        out
    }

    /// The square root of each lane (correctly rounded, like `f64::sqrt`).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{LANES, Lanes};
    /// assert_eq!(Lanes::splat(9.0).sqrt(), Lanes::splat(3.0));
    /// assert!(Lanes::splat(-1.0).sqrt().0[0].is_nan());
    /// ```
    #[inline(always)]
    pub fn sqrt(self) -> Lanes {
        lanewise!(i => self.0[i].sqrt())
    }

    /// `self` where it is greater than `floor`, else `floor`: a NaN lane becomes `floor`, as
    /// with `f64::max`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{LANES, Lanes};
    /// let lanes = Lanes([-1.0, 2.0, f64::NAN, 0.0, 5.0, -0.5, 1.0, 3.0]);
    /// assert_eq!(lanes.max(Lanes::ZERO).0, [0.0, 2.0, 0.0, 0.0, 5.0, 0.0, 1.0, 3.0]);
    /// ```
    #[inline(always)]
    pub fn max(self, floor: Lanes) -> Lanes {
        lanewise!(i => self.0[i].max(floor.0[i]))
    }

    /// `then` in the lanes where `self > bound`, else `otherwise`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{LANES, Lanes};
    /// let x = Lanes([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
    /// let picked = x.select_gt(Lanes::splat(3.0), Lanes::ONE, Lanes::ZERO);
    /// assert_eq!(picked.0, [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]);
    /// ```
    #[inline(always)]
    pub fn select_gt(self, bound: Lanes, then: Lanes, otherwise: Lanes) -> Lanes {
        lanewise!(i => select(self.0[i] > bound.0[i], then.0[i], otherwise.0[i]))
    }

    /// `then` in the lanes where `self >= bound`, else `otherwise`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{LANES, Lanes};
    /// let x = Lanes([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
    /// let picked = x.select_ge(Lanes::splat(3.0), Lanes::ONE, Lanes::ZERO);
    /// assert_eq!(picked.0, [0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0]);
    /// ```
    #[inline(always)]
    pub fn select_ge(self, bound: Lanes, then: Lanes, otherwise: Lanes) -> Lanes {
        lanewise!(i => select(self.0[i] >= bound.0[i], then.0[i], otherwise.0[i]))
    }

    /// 1 in the lanes that are not 0, else 0 (a NaN lane is not 0).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{LANES, Lanes};
    /// let x = Lanes([0.0, -0.0, 2.0, f64::NAN, 0.0, 0.0, 0.0, -3.0]);
    /// assert_eq!(x.nonzero().0, [0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0]);
    /// ```
    #[inline(always)]
    pub fn nonzero(self) -> Lanes {
        lanewise!(i => select(self.0[i] != 0.0, 1.0, 0.0))
    }

    /// `self` to the power `exponent`, one exponent for every lane (a shininess or spot
    /// exponent, in [0, 128]). Integer exponents multiply by squaring, in the order compiler
    /// runtimes' `powi` uses, so a lane equals the scalar `powi`; others take `powf` per lane.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{LANES, Lanes};
    /// assert_eq!(Lanes::splat(0.9).pow(10.0).0[0], 0.9f64.powi(10));
    /// assert_eq!(Lanes::splat(0.25).pow(0.5), Lanes::splat(0.5));
    /// assert_eq!(Lanes::ZERO.pow(0.0), Lanes::ONE); // 0^0 = 1, as the equation needs
    /// ```
    #[inline(always)]
    pub fn pow(self, exponent: f64) -> Lanes {
        if exponent.fract() != 0.0 {
            return lanewise!(i => self.0[i].powf(exponent));
        }
        let mut bits = exponent as u32;
        let mut base = self;
        let mut result = Lanes::ONE;
        loop {
            if bits & 1 != 0 {
                result = result * base;
            }
            bits /= 2;
            if bits == 0 {
                return result;
            }
            base = base * base;
        }
    }
}

macro_rules! lane_operator {
    ($trait:ident, $method:ident, $op:tt) => {
        impl $trait for Lanes {
            type Output = Lanes;
            #[inline(always)]
            fn $method(self, other: Lanes) -> Lanes {
                lanewise!(i => self.0[i] $op other.0[i])
            }
        }
    };
}
lane_operator!(Add, add, +);
lane_operator!(Sub, sub, -);
lane_operator!(Mul, mul, *);
lane_operator!(Div, div, /);

impl Neg for Lanes {
    type Output = Lanes;
    #[inline(always)]
    fn neg(self) -> Lanes {
        lanewise!(i => -self.0[i])
    }
}

/// A 3-vector per lane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vec3s {
    /// The x components.
    pub x: Lanes,
    /// The y components.
    pub y: Lanes,
    /// The z components.
    pub z: Lanes,
}

impl Vec3s {
    /// The zero vector in every lane.
    pub const ZERO: Vec3s = Vec3s {
        x: Lanes::ZERO,
        y: Lanes::ZERO,
        z: Lanes::ZERO,
    };

    /// `v` in every lane: a per-state vector (a light's direction or color) for a block.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{Lanes, Vec3s};
    /// use glam::DVec3;
    /// let v = Vec3s::splat(DVec3::new(1.0, 2.0, 3.0));
    /// assert_eq!(v.y, Lanes::splat(2.0));
    /// ```
    #[inline(always)]
    pub fn splat(v: glam::DVec3) -> Vec3s {
        Vec3s {
            x: Lanes::splat(v.x),
            y: Lanes::splat(v.y),
            z: Lanes::splat(v.z),
        }
    }

    /// The dot product per lane, summed x, y, z in order like glam's `dot` (n⊙L of §2.14.1
    /// once clamped).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{Lanes, Vec3s};
    /// use glam::DVec3;
    /// let a = Vec3s::splat(DVec3::new(1.0, 2.0, 3.0));
    /// let b = Vec3s::splat(DVec3::new(4.0, -5.0, 6.0));
    /// assert_eq!(a.dot(b), Lanes::splat(12.0));
    /// ```
    #[inline(always)]
    pub fn dot(self, other: Vec3s) -> Lanes {
        self.x * other.x + self.y * other.y + self.z * other.z
    }

    /// Each lane's vector times that lane's scalar.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{Lanes, Vec3s};
    /// use glam::DVec3;
    /// let v = Vec3s::splat(DVec3::new(1.0, 2.0, 3.0)).scale(Lanes::splat(2.0));
    /// assert_eq!(v, Vec3s::splat(DVec3::new(2.0, 4.0, 6.0)));
    /// ```
    #[inline(always)]
    pub fn scale(self, s: Lanes) -> Vec3s {
        Vec3s {
            x: self.x * s,
            y: self.y * s,
            z: self.z * s,
        }
    }

    /// The Euclidean length per lane (the distance ||VP_pli|| of §2.14.1 for a light offset).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{Lanes, Vec3s};
    /// use glam::DVec3;
    /// let v = Vec3s::splat(DVec3::new(3.0, 4.0, 12.0));
    /// assert_eq!(v.length(), Lanes::splat(13.0));
    /// ```
    #[inline(always)]
    pub fn length(self) -> Lanes {
        self.dot(self).sqrt()
    }

    /// The unit vector in this direction, or zero where the length is zero or not finite
    /// (glam's `normalize_or_zero`, lane by lane).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::lanes::{Lanes, Vec3s};
    /// use glam::DVec3;
    /// let v = DVec3::new(0.0, 3.0, 4.0);
    /// assert_eq!(Vec3s::splat(v).normalize_or_zero(), Vec3s::splat(v.normalize_or_zero()));
    /// assert_eq!(Vec3s::ZERO.normalize_or_zero(), Vec3s::ZERO);
    /// ```
    #[inline(always)]
    pub fn normalize_or_zero(self) -> Vec3s {
        let recip = Lanes::ONE / self.length();
        let usable = lanewise!(i => {
            let r = recip.0[i];
            // `&`, not `&&`: no branch per lane.
            select((r > 0.0) & (r < f64::INFINITY), r, 0.0)
        });
        Vec3s {
            x: usable.select_gt(Lanes::ZERO, self.x * usable, Lanes::ZERO),
            y: usable.select_gt(Lanes::ZERO, self.y * usable, Lanes::ZERO),
            z: usable.select_gt(Lanes::ZERO, self.z * usable, Lanes::ZERO),
        }
    }
}

impl Add for Vec3s {
    type Output = Vec3s;
    #[inline(always)]
    fn add(self, o: Vec3s) -> Vec3s {
        Vec3s {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }
}

impl Sub for Vec3s {
    type Output = Vec3s;
    #[inline(always)]
    fn sub(self, o: Vec3s) -> Vec3s {
        Vec3s {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

impl Mul for Vec3s {
    type Output = Vec3s;
    /// Component-wise.
    #[inline(always)]
    fn mul(self, o: Vec3s) -> Vec3s {
        Vec3s {
            x: self.x * o.x,
            y: self.y * o.y,
            z: self.z * o.z,
        }
    }
}

impl Neg for Vec3s {
    type Output = Vec3s;
    #[inline(always)]
    fn neg(self) -> Vec3s {
        Vec3s {
            x: -self.x,
            y: -self.y,
            z: -self.z,
        }
    }
}

/// Clamps each lane to [0, 1], a NaN lane to 0 (`lighting::clamp01`'s rule): the color
/// clamp of §2.14.8.
///
/// # Examples
///
/// ```
/// use fflight::lighting::lanes::clamp01;
/// let c = clamp01([-0.5, 0.25, 1.5, f32::NAN, 0.0, 1.0, 2.0, 0.5]);
/// assert_eq!(c, [0.0, 0.25, 1.0, 0.0, 0.0, 1.0, 1.0, 0.5]);
/// ```
#[inline(always)]
pub fn clamp01(c: LanesF32) -> LanesF32 {
    let mut out = [0.0; LANES];
    for (o, v) in out.iter_mut().zip(c) {
        // Not `clamp`, which keeps NaN: max first turns a NaN lane into 0.
        #[allow(clippy::manual_clamp)]
        {
            *o = v.max(0.0).min(1.0);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lane_power_equals_scalar_powi() {
        let bases = Lanes([0.0, 0.3, 0.5, 0.9, 0.999, 1.0, 1.02, 0.7]);
        for exponent in 0..=128 {
            let lanes = bases.pow(f64::from(exponent));
            for (lane, base) in lanes.0.iter().zip(bases.0) {
                assert_eq!(*lane, base.powi(exponent), "{base}^{exponent}");
            }
        }
        assert_eq!(Lanes::splat(0.25).pow(0.5).0[0], 0.5);
    }

    #[test]
    fn normalize_or_zero_matches_glam() {
        let v = glam::DVec3::new(3.0, -4.0, 12.0);
        let lanes = Vec3s::splat(v).normalize_or_zero();
        let expected = v.normalize_or_zero();
        assert_eq!(
            [lanes.x.0[0], lanes.y.0[0], lanes.z.0[0]],
            expected.to_array()
        );
        let zero = Vec3s::ZERO.normalize_or_zero();
        assert_eq!(zero, Vec3s::ZERO);
    }

    #[test]
    fn clamp_sends_nan_to_zero() {
        let c = clamp01([f32::NAN, -1.0, 0.5, 2.0, 1.0, 0.0, f32::INFINITY, -0.0]);
        assert_eq!(c, [0.0, 0.0, 0.5, 1.0, 1.0, 0.0, 1.0, 0.0]);
    }
}
