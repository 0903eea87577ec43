//! Eight f32 lanes in a `__m256` (AVX2 with FMA): the types the kernel is written over
//! (`kernel.rs`), one block of the pipeline at a time.

use std::arch::x86_64::*;
use std::ops::{Add, BitAnd, BitOr, Mul, Neg, Sub};

use super::super::SINGLE_RANGE;
use crate::lighting::lanes::LanesF32;

// SAFETY (every `unsafe` block of this file): the intrinsics need AVX, AVX2 or FMA (the
// estimates AVX-512 VL, and only the AVX-512 modules call them), and these
// values are only made and used inside the kernel's functions, compiled with those features
// and called only once the CPU was found to have them (`x86::kernel`). Loads and stores go
// through references to `[f32; 8]`, so they stay in bounds.

/// Blocks of the pipeline (8 lanes each) a vector holds.
pub(super) const BLOCKS: usize = 1;

/// Eight f32 lanes.
#[derive(Clone, Copy)]
pub(super) struct F(__m256);

/// Eight f64 lanes, in two halves: for the transformation, which matches the scalar path's
/// double precision.
#[derive(Clone, Copy)]
pub(super) struct D2(__m256d, __m256d);

impl D2 {
    #[inline(always)]
    pub(super) fn from_f32(v: F) -> D2 {
        unsafe {
            D2(
                _mm256_cvtps_pd(_mm256_castps256_ps128(v.0)),
                _mm256_cvtps_pd(_mm256_extractf128_ps::<1>(v.0)),
            )
        }
    }

    /// Each lane rounded to the nearest f32.
    #[inline(always)]
    pub(super) fn to_f32(self) -> F {
        unsafe {
            F(_mm256_set_m128(
                _mm256_cvtpd_ps(self.1),
                _mm256_cvtpd_ps(self.0),
            ))
        }
    }

    #[inline(always)]
    pub(super) fn scale(self, factor: f64) -> D2 {
        unsafe {
            let f = _mm256_set1_pd(factor);
            D2(_mm256_mul_pd(self.0, f), _mm256_mul_pd(self.1, f))
        }
    }

    #[inline(always)]
    pub(super) fn add(self, other: D2) -> D2 {
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
pub(super) struct Mask(__m256);

impl F {
    #[inline(always)]
    pub(super) fn splat(value: f32) -> F {
        F(unsafe { _mm256_set1_ps(value) })
    }

    /// The f32 at byte `OFFSET` of `*base` in every lane, broadcast from memory (see the wide
    /// type's).
    #[target_feature(enable = "avx")]
    #[inline]
    pub(super) fn broadcast_at<const OFFSET: usize, T>(base: &T) -> F {
        const { assert!(OFFSET + 4 <= size_of::<T>() && OFFSET.is_multiple_of(4)) };
        let lanes;
        // SAFETY: reads 4 bytes inside `*base` (the assertion above), aligned as an f32
        // within `T` (whose fields there are f32).
        unsafe {
            std::arch::asm!(
                "vbroadcastss {lanes}, dword ptr [{base} + {offset}]",
                lanes = out(ymm_reg) lanes,
                base = in(reg) base,
                offset = const OFFSET,
                options(pure, readonly, nostack, preserves_flags),
            )
        };
        F(lanes)
    }

    #[inline(always)]
    pub(super) fn zero() -> F {
        F(unsafe { _mm256_setzero_ps() })
    }

    /// The lanes of the group's block.
    #[inline(always)]
    pub(super) fn load(parts: [&LanesF32; BLOCKS]) -> F {
        F(unsafe { _mm256_loadu_ps(parts[0].as_ptr()) })
    }

    #[inline(always)]
    pub(super) fn store(self, parts: [&mut LanesF32; BLOCKS]) {
        let [part] = parts;
        unsafe { _mm256_storeu_ps(part.as_mut_ptr(), self.0) }
    }

    /// `self * b + c`, with one rounding.
    #[inline(always)]
    pub(super) fn mul_add(self, b: F, c: F) -> F {
        F(unsafe { _mm256_fmadd_ps(self.0, b.0, c.0) })
    }

    /// The larger of each pair; `other` where `self` is NaN.
    #[inline(always)]
    pub(super) fn max(self, other: F) -> F {
        F(unsafe { _mm256_max_ps(self.0, other.0) })
    }

    #[inline(always)]
    pub(super) fn min(self, other: F) -> F {
        F(unsafe { _mm256_min_ps(self.0, other.0) })
    }

    #[inline(always)]
    pub(super) fn sqrt(self) -> F {
        F(unsafe { _mm256_sqrt_ps(self.0) })
    }

    #[inline(always)]
    pub(super) fn div(self, other: F) -> F {
        F(unsafe { _mm256_div_ps(self.0, other.0) })
    }

    /// 1/√x to 12 bits (AVX).
    #[inline(always)]
    pub(super) fn reciprocal_sqrt_estimate_12(self) -> F {
        F(unsafe { _mm256_rsqrt_ps(self.0) })
    }

    /// 1/x to 12 bits (AVX).
    #[inline(always)]
    pub(super) fn reciprocal_estimate_12(self) -> F {
        F(unsafe { _mm256_rcp_ps(self.0) })
    }

    /// 1/√x to 14 bits: AVX-512 VL only (the kernel's AVX-512 modules).
    #[inline(always)]
    pub(super) fn reciprocal_sqrt_estimate(self) -> F {
        F(unsafe { _mm256_rsqrt14_ps(self.0) })
    }

    /// 1/x to 14 bits: AVX-512 VL only.
    #[inline(always)]
    pub(super) fn reciprocal_estimate(self) -> F {
        F(unsafe { _mm256_rcp14_ps(self.0) })
    }

    #[inline(always)]
    pub(super) fn abs(self) -> F {
        F(unsafe { _mm256_andnot_ps(_mm256_set1_ps(-0.0), self.0) })
    }

    #[inline(always)]
    pub(super) fn lt(self, other: F) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_LT_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    pub(super) fn gt(self, other: F) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_GT_OQ>(self.0, other.0) })
    }

    #[inline(always)]
    pub(super) fn ge(self, other: F) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_GE_OQ>(self.0, other.0) })
    }

    /// True where `self` is NaN or beyond `SINGLE_RANGE` in magnitude.
    #[inline(always)]
    pub(super) fn out_of_range(self) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_NLE_UQ>(self.abs().0, _mm256_set1_ps(SINGLE_RANGE)) })
    }

    /// True where `self` is NaN or greater than `limit`.
    #[inline(always)]
    pub(super) fn exceeds(self, limit: F) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_NLE_UQ>(self.0, limit.0) })
    }

    /// True where `self` is NaN.
    #[inline(always)]
    pub(super) fn is_nan(self) -> Mask {
        Mask(unsafe { _mm256_cmp_ps::<_CMP_UNORD_Q>(self.0, self.0) })
    }

    /// True where `self` is not in [0, 1] (NaN included).
    #[inline(always)]
    pub(super) fn outside_unit(self) -> Mask {
        Mask(unsafe {
            _mm256_or_ps(
                _mm256_cmp_ps::<_CMP_NGE_UQ>(self.0, _mm256_setzero_ps()),
                _mm256_cmp_ps::<_CMP_NLE_UQ>(self.0, _mm256_set1_ps(1.0)),
            )
        })
    }

    /// Whether every lane equals `value`.
    #[inline(always)]
    pub(super) fn all_eq(self, value: f32) -> bool {
        unsafe {
            _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_EQ_OQ>(self.0, _mm256_set1_ps(value))) == 0xff
        }
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
    pub(super) fn none() -> Mask {
        Mask(unsafe { _mm256_setzero_ps() })
    }

    /// `then` where true, else `otherwise`.
    #[inline(always)]
    pub(super) fn select(self, then: F, otherwise: F) -> F {
        F(unsafe { _mm256_blendv_ps(otherwise.0, then.0, self.0) })
    }

    /// `value` where true, else 0.
    #[inline(always)]
    pub(super) fn keep(self, value: F) -> F {
        F(unsafe { _mm256_and_ps(self.0, value.0) })
    }

    /// `a * b` where true, else 0.
    #[inline(always)]
    pub(super) fn keep_product(self, a: F, b: F) -> F {
        F(unsafe { _mm256_and_ps(self.0, _mm256_mul_ps(a.0, b.0)) })
    }

    /// One bit per lane of block `block` of the group.
    #[inline(always)]
    pub(super) fn block_bits(self, block: usize) -> u8 {
        debug_assert_eq!(block, 0);
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
