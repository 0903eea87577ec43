//! The fast engine's kernel for x86-64: eight lanes in a `__m256`, written once over a thin
//! wrapper (`F`, `Mask`) and compiled twice: for AVX2 with FMA, and for AVX-512 (the same
//! eight-lane code with 32 vector registers instead of 16, so the light sums stay in
//! registers). The wrapper's operations are `#[inline(always)]` and only ever run inside
//! those two functions, which are only called once the CPU was found to have their features.
//! Besides the C ABI layer, this is the crate's only `unsafe` code: the intrinsics.
#![allow(unsafe_code)]

use std::arch::x86_64::*;
use std::ops::{Add, BitAnd, BitOr, Mul, Neg, Sub};

use super::{FastState, SINGLE_RANGE};
use crate::lighting::lanes::{LANES, LanesF32};
use crate::pipeline::block::{InputBlock, OutputBlock};

// SAFETY (every `unsafe` block of this file): the intrinsics need AVX, AVX2 or FMA, and `F`
// and `Mask` values are only made and used inside `kernel_avx2` and `kernel_avx512`, whose
// features include all three and which `kernel` hands out only when the CPU has them. Loads
// and stores go through references to `[f32; 8]`, so they stay in bounds.

/// Eight f32 lanes.
#[derive(Clone, Copy)]
struct F(__m256);

/// Eight f64 lanes, in two halves: for the transformation, which matches the scalar path's
/// double precision.
#[derive(Clone, Copy)]
struct D2(__m256d, __m256d);

impl D2 {
    #[inline(always)]
    fn from_f32(v: F) -> D2 {
        unsafe {
            D2(
                _mm256_cvtps_pd(_mm256_castps256_ps128(v.0)),
                _mm256_cvtps_pd(_mm256_extractf128_ps::<1>(v.0)),
            )
        }
    }

    /// Each lane rounded to the nearest f32.
    #[inline(always)]
    fn to_f32(self) -> F {
        unsafe {
            F(_mm256_set_m128(
                _mm256_cvtpd_ps(self.1),
                _mm256_cvtpd_ps(self.0),
            ))
        }
    }

    #[inline(always)]
    fn scale(self, factor: f64) -> D2 {
        unsafe {
            let f = _mm256_set1_pd(factor);
            D2(_mm256_mul_pd(self.0, f), _mm256_mul_pd(self.1, f))
        }
    }

    #[inline(always)]
    fn add(self, other: D2) -> D2 {
        unsafe {
            D2(
                _mm256_add_pd(self.0, other.0),
                _mm256_add_pd(self.1, other.1),
            )
        }
    }
}

/// A per-lane condition: all bits set where true.
#[derive(Clone, Copy)]
struct Mask(__m256);

impl F {
    #[inline(always)]
    fn splat(value: f32) -> F {
        F(unsafe { _mm256_set1_ps(value) })
    }

    #[inline(always)]
    fn zero() -> F {
        F(unsafe { _mm256_setzero_ps() })
    }

    #[inline(always)]
    fn load(lanes: &LanesF32) -> F {
        F(unsafe { _mm256_loadu_ps(lanes.as_ptr()) })
    }

    #[inline(always)]
    fn store(self, lanes: &mut LanesF32) {
        unsafe { _mm256_storeu_ps(lanes.as_mut_ptr(), self.0) }
    }

    /// `self * b + c`, with one rounding.
    #[inline(always)]
    fn mul_add(self, b: F, c: F) -> F {
        F(unsafe { _mm256_fmadd_ps(self.0, b.0, c.0) })
    }

    /// The larger of each pair; `other` where `self` is NaN.
    #[inline(always)]
    fn max(self, other: F) -> F {
        F(unsafe { _mm256_max_ps(self.0, other.0) })
    }

    #[inline(always)]
    fn min(self, other: F) -> F {
        F(unsafe { _mm256_min_ps(self.0, other.0) })
    }

    #[inline(always)]
    fn sqrt(self) -> F {
        F(unsafe { _mm256_sqrt_ps(self.0) })
    }

    #[inline(always)]
    fn div(self, other: F) -> F {
        F(unsafe { _mm256_div_ps(self.0, other.0) })
    }

    #[inline(always)]
    fn abs(self) -> F {
        F(unsafe { _mm256_andnot_ps(_mm256_set1_ps(-0.0), self.0) })
    }

    #[inline(always)]
    fn lt(self, other: F) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_LT_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn gt(self, other: F) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_GT_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    fn ge(self, other: F) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_GE_OQ>(self.0, other.0) })
    }

    /// True where `self` is NaN or beyond `SINGLE_RANGE` in magnitude.
    #[inline(always)]
    fn out_of_range(self) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_NLE_UQ>(self.abs().0, _mm256_set1_ps(SINGLE_RANGE)) })
    }

    /// True where `self` is NaN or greater than `limit`.
    #[inline(always)]
    fn exceeds(self, limit: F) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_NLE_UQ>(self.0, limit.0) })
    }

    /// True where `self` is NaN.
    #[inline(always)]
    fn is_nan(self) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_UNORD_Q>(self.0, self.0) })
    }

    /// True where `self` is not in [0, 1] (NaN included).
    #[inline(always)]
    fn outside_unit(self) -> Mask {
        Mask(unsafe {
            _mm256_or_ps(
                _mm256_cmp_ps::<_CMP_NGE_UQ>(self.0, _mm256_setzero_ps()),
                _mm256_cmp_ps::<_CMP_NLE_UQ>(self.0, _mm256_set1_ps(1.0)),
            )
        })
    }

    /// Clamped to [0, 1]; NaN becomes 0, as `lighting::clamp01` makes it.
    #[inline(always)]
    fn clamp01(self) -> F {
        self.max(F::zero()).min(F::splat(1.0))
    }

    /// Whether every lane equals `value`.
    #[inline(always)]
    fn all_eq(self, value: f32) -> bool {
        unsafe {
            _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_EQ_OQ>(self.0, _mm256_set1_ps(value))) == 0xff
        }
    }

    /// (`e·self^(e-1)`, `self^e`) for `self` >= 0, with 0^0 = 1: the power and its
    /// derivative, by repeated squaring.
    #[inline(always)]
    fn power_and_slope(self, exponent: u32) -> (F, F) {
        if exponent == 0 {
            return (F::zero(), F::splat(1.0));
        }
        let mut bits = exponent - 1;
        let mut base = self;
        let mut below = F::splat(1.0);
        while bits != 0 {
            if bits & 1 != 0 {
                below = below * base;
            }
            bits >>= 1;
            if bits != 0 {
                base = base * base;
            }
        }
        (below * F::splat(exponent as f32), below * self)
    }
}

macro_rules! binary {
    ($trait:ident, $method:ident, $intrinsic:ident) => {
        impl $trait for F {
            type Output = F;
            #[inline(always)]
            fn $method(self, other: F) -> F {
                F(unsafe { $intrinsic(self.0, other.0) })
            }
        }
    };
}
binary!(Add, add, _mm256_add_ps);
binary!(Sub, sub, _mm256_sub_ps);
binary!(Mul, mul, _mm256_mul_ps);

impl Neg for F {
    type Output = F;
    #[inline(always)]
    fn neg(self) -> F {
        F(unsafe { _mm256_xor_ps(self.0, _mm256_set1_ps(-0.0)) })
    }
}

impl Mask {
    #[inline(always)]
    fn none() -> Mask {
        Mask(unsafe { _mm256_setzero_ps() })
    }

    /// `then` where true, else `otherwise`.
    #[inline(always)]
    fn select(self, then: F, otherwise: F) -> F {
        F(unsafe { _mm256_blendv_ps(otherwise.0, then.0, self.0) })
    }

    /// `value` where true, else 0.
    #[inline(always)]
    fn keep(self, value: F) -> F {
        F(unsafe { _mm256_and_ps(self.0, value.0) })
    }

    /// One bit per lane.
    #[inline(always)]
    fn bits(self) -> u8 {
        unsafe { _mm256_movemask_ps(self.0) as u8 }
    }
}

impl BitOr for Mask {
    type Output = Mask;
    #[inline(always)]
    fn bitor(self, other: Mask) -> Mask {
        Mask(unsafe { _mm256_or_ps(self.0, other.0) })
    }
}

impl std::ops::Not for Mask {
    type Output = Mask;
    #[inline(always)]
    fn not(self) -> Mask {
        Mask(unsafe { _mm256_xor_ps(self.0, _mm256_castsi256_ps(_mm256_set1_epi32(-1))) })
    }
}

impl BitAnd for Mask {
    type Output = Mask;
    #[inline(always)]
    fn bitand(self, other: Mask) -> Mask {
        Mask(unsafe { _mm256_and_ps(self.0, other.0) })
    }
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

    /// `self + weight * color`.
    #[inline(always)]
    fn add_weighted(self, weight: F, color: [f32; 3]) -> V3 {
        V3 {
            x: weight.mul_add(F::splat(color[0]), self.x),
            y: weight.mul_add(F::splat(color[1]), self.y),
            z: weight.mul_add(F::splat(color[2]), self.z),
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

/// A kernel: one block, its refused lanes.
type Kernel = fn(&FastState, &InputBlock, &mut OutputBlock) -> u8;

/// The kernel for this CPU: AVX-512 or AVX2 with FMA, or `None` without them (found once).
pub(super) fn kernel() -> Option<Kernel> {
    static KERNEL: std::sync::OnceLock<Option<Kernel>> = std::sync::OnceLock::new();
    *KERNEL.get_or_init(|| {
        let avx2 = is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma");
        if avx2 && is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx512vl") {
            Some(|state, input, output| unsafe { avx512::process(state, input, output) })
        } else if avx2 {
            Some(|state, input, output| unsafe { avx2::process(state, input, output) })
        } else {
            None
        }
    })
}

/// The kernel compiled for AVX2 with FMA.
mod avx2 {
    /// Gives an item the module's target features.
    macro_rules! with_features {
        ($($item:item)*) => { $(#[target_feature(enable = "avx,avx2,fma")] $item)* };
    }
    with_features! {
        /// 1/√x, correctly rounded twice: AVX2's estimate has too few bits.
        #[inline]
        fn reciprocal_sqrt(x: super::F) -> super::F {
            super::F::splat(1.0).div(x.sqrt())
        }

        /// 1/x, correctly rounded.
        #[inline]
        fn reciprocal(x: super::F) -> super::F {
            super::F::splat(1.0).div(x)
        }
    }
    include!("kernel.rs");
}

/// The kernel compiled for AVX-512: the same eight-lane code, with 32 registers.
mod avx512 {
    /// Gives an item the module's target features.
    macro_rules! with_features {
        ($($item:item)*) => { $(#[target_feature(enable = "avx,avx2,fma,avx512f,avx512vl")] $item)* };
    }
    use std::arch::x86_64::{_mm256_rcp14_ps, _mm256_rsqrt14_ps};
    with_features! {
        /// 1/√x: the 14-bit estimate and one Newton step, within about 2 units in the last
        /// place, without the divider's latency.
        #[inline]
        fn reciprocal_sqrt(x: super::F) -> super::F {
            let y = super::F(_mm256_rsqrt14_ps(x.0));
            // y·(3 - x·y²)/2
            let half_y = y * super::F::splat(0.5);
            half_y * (x * y).mul_add(-y, super::F::splat(3.0))
        }

        /// 1/x: the 14-bit estimate and one Newton step.
        #[inline]
        fn reciprocal(x: super::F) -> super::F {
            let y = super::F(_mm256_rcp14_ps(x.0));
            // y·(2 - x·y)
            y * x.mul_add(-y, super::F::splat(2.0))
        }
    }
    include!("kernel.rs");
}

const _: () = assert!(LANES == 8, "the x86 kernel holds a block in one __m256");
