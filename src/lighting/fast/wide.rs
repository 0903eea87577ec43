//! Sixteen f32 lanes in a `__m512` (AVX-512 F): the types the kernel is written over
//! (`kernel.rs`), two blocks of the pipeline at a time (lanes 0-7 the first, 8-15 the second).
//! Conditions are mask registers. Only AVX-512 F instructions are used.

use std::arch::x86_64::*;
use std::ops::{Add, BitAnd, BitOr, Mul, Neg, Not, Sub};

use super::super::SINGLE_RANGE;
use crate::lighting::lanes::LanesF32;

// SAFETY (every `unsafe` block of this file): the intrinsics need AVX, AVX2, FMA or AVX-512 F,
// and these values are only made and used inside the kernel's functions, compiled with those
// features and called only once the CPU was found to have them (`x86::kernel`). Loads and
// stores go through references to `[f32; 8]`, eight lanes each, so they stay in bounds.

/// Blocks of the pipeline (8 lanes each) a vector holds.
pub(super) const BLOCKS: usize = 2;

/// Sixteen f32 lanes.
#[derive(Clone, Copy)]
pub(super) struct F(__m512);

/// Sixteen f64 lanes, in two halves: for the transformation, which matches the scalar path's
/// double precision.
#[derive(Clone, Copy)]
pub(super) struct D2(__m512d, __m512d);

/// A per-lane condition: one bit per lane.
#[derive(Clone, Copy)]
pub(super) struct Mask(__mmask16);

/// `low` in lanes 0-7 and `high` in lanes 8-15.
#[inline(always)]
fn join(low: __m256, high: __m256) -> __m512 {
    unsafe {
        _mm512_castpd_ps(_mm512_insertf64x4::<1>(
            _mm512_castpd256_pd512(_mm256_castps_pd(low)),
            _mm256_castps_pd(high),
        ))
    }
}

/// Lanes 0-7 and lanes 8-15.
#[inline(always)]
fn halves(v: __m512) -> (__m256, __m256) {
    unsafe {
        (
            _mm512_castps512_ps256(v),
            _mm256_castpd_ps(_mm512_extractf64x4_pd::<1>(_mm512_castps_pd(v))),
        )
    }
}

impl D2 {
    #[inline(always)]
    pub(super) fn from_f32(v: F) -> D2 {
        let (low, high) = halves(v.0);
        unsafe { D2(_mm512_cvtps_pd(low), _mm512_cvtps_pd(high)) }
    }

    /// Each lane rounded to the nearest f32.
    #[inline(always)]
    pub(super) fn to_f32(self) -> F {
        unsafe { F(join(_mm512_cvtpd_ps(self.0), _mm512_cvtpd_ps(self.1))) }
    }

    #[inline(always)]
    pub(super) fn scale(self, factor: f64) -> D2 {
        unsafe {
            let f = _mm512_set1_pd(factor);
            D2(_mm512_mul_pd(self.0, f), _mm512_mul_pd(self.1, f))
        }
    }

    #[inline(always)]
    pub(super) fn add(self, other: D2) -> D2 {
        unsafe {
            D2(
                _mm512_add_pd(self.0, other.0),
                _mm512_add_pd(self.1, other.1),
            )
        }
    }
}

impl F {
    #[inline(always)]
    pub(super) fn splat(value: f32) -> F {
        F(unsafe { _mm512_set1_ps(value) })
    }

    /// The f32 at byte `OFFSET` of `*base` in every lane, broadcast from memory by the load
    /// unit: the compiler would otherwise load a light's neighboring constants together and
    /// spread each with shuffles, on the port that the arithmetic needs. The address is the
    /// base register and the offset, not one more register computed for each constant.
    #[target_feature(enable = "avx512f")]
    #[inline]
    pub(super) fn broadcast_at<const OFFSET: usize, T>(base: &T) -> F {
        const { assert!(OFFSET + 4 <= size_of::<T>() && OFFSET.is_multiple_of(4)) };
        let lanes;
        // SAFETY: reads 4 bytes inside `*base` (the assertion above), aligned as an f32
        // within `T` (whose fields there are f32).
        unsafe {
            std::arch::asm!(
                "vbroadcastss {lanes}, dword ptr [{base} + {offset}]",
                lanes = out(zmm_reg) lanes,
                base = in(reg) base,
                offset = const OFFSET,
                options(pure, readonly, nostack, preserves_flags),
            )
        };
        F(lanes)
    }

    #[inline(always)]
    pub(super) fn zero() -> F {
        F(unsafe { _mm512_setzero_ps() })
    }

    /// The lanes of the group's two blocks.
    #[inline(always)]
    pub(super) fn load(parts: [&LanesF32; BLOCKS]) -> F {
        unsafe {
            F(join(
                _mm256_loadu_ps(parts[0].as_ptr()),
                _mm256_loadu_ps(parts[1].as_ptr()),
            ))
        }
    }

    #[inline(always)]
    pub(super) fn store(self, parts: [&mut LanesF32; BLOCKS]) {
        let (low, high) = halves(self.0);
        let [first, second] = parts;
        unsafe {
            _mm256_storeu_ps(first.as_mut_ptr(), low);
            _mm256_storeu_ps(second.as_mut_ptr(), high);
        }
    }

    /// `self * b + c`, with one rounding.
    #[inline(always)]
    pub(super) fn mul_add(self, b: F, c: F) -> F {
        F(unsafe { _mm512_fmadd_ps(self.0, b.0, c.0) })
    }

    /// The larger of each pair; `other` where `self` is NaN.
    #[inline(always)]
    pub(super) fn max(self, other: F) -> F {
        F(unsafe { _mm512_max_ps(self.0, other.0) })
    }

    #[inline(always)]
    pub(super) fn min(self, other: F) -> F {
        F(unsafe { _mm512_min_ps(self.0, other.0) })
    }

    #[inline(always)]
    pub(super) fn sqrt(self) -> F {
        F(unsafe { _mm512_sqrt_ps(self.0) })
    }

    #[inline(always)]
    pub(super) fn div(self, other: F) -> F {
        F(unsafe { _mm512_div_ps(self.0, other.0) })
    }

    /// 1/√x to 14 bits.
    #[inline(always)]
    pub(super) fn reciprocal_sqrt_estimate(self) -> F {
        F(unsafe { _mm512_rsqrt14_ps(self.0) })
    }

    /// 1/x to 14 bits.
    #[inline(always)]
    pub(super) fn reciprocal_estimate(self) -> F {
        F(unsafe { _mm512_rcp14_ps(self.0) })
    }

    #[inline(always)]
    pub(super) fn abs(self) -> F {
        F(unsafe { _mm512_abs_ps(self.0) })
    }

    #[inline(always)]
    fn compare<const PREDICATE: i32>(self, other: F) -> Mask {
        Mask(unsafe { _mm512_cmp_ps_mask::<PREDICATE>(self.0, other.0) })
    }

    #[inline(always)]
    pub(super) fn lt(self, other: F) -> Mask {
        self.compare::<_CMP_LT_OQ>(other)
    }

    #[inline(always)]
    pub(super) fn gt(self, other: F) -> Mask {
        self.compare::<_CMP_GT_OQ>(other)
    }

    #[inline(always)]
    pub(super) fn ge(self, other: F) -> Mask {
        self.compare::<_CMP_GE_OQ>(other)
    }

    /// True where `self` is NaN or beyond `SINGLE_RANGE` in magnitude.
    #[inline(always)]
    pub(super) fn out_of_range(self) -> Mask {
        self.abs().exceeds(F::splat(SINGLE_RANGE))
    }

    /// True where `self` is NaN or greater than `limit`.
    #[inline(always)]
    pub(super) fn exceeds(self, limit: F) -> Mask {
        self.compare::<_CMP_NLE_UQ>(limit)
    }

    /// True where `self` is NaN.
    #[inline(always)]
    pub(super) fn is_nan(self) -> Mask {
        self.compare::<_CMP_UNORD_Q>(self)
    }

    /// True where `self` is not in [0, 1] (NaN included).
    #[inline(always)]
    pub(super) fn outside_unit(self) -> Mask {
        self.compare::<_CMP_NGE_UQ>(F::zero()) | self.exceeds(F::splat(1.0))
    }

    /// Whether every lane equals `value`.
    #[inline(always)]
    pub(super) fn all_eq(self, value: f32) -> bool {
        self.compare::<_CMP_EQ_OQ>(F::splat(value)).0 == 0xffff
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
binary!(Add, add, _mm512_add_ps);
binary!(Sub, sub, _mm512_sub_ps);
binary!(Mul, mul, _mm512_mul_ps);

impl Neg for F {
    type Output = F;
    #[inline(always)]
    fn neg(self) -> F {
        // The sign bit flipped, with AVX-512 F's integer xor.
        F(unsafe {
            _mm512_castsi512_ps(_mm512_xor_si512(
                _mm512_castps_si512(self.0),
                _mm512_set1_epi32(i32::MIN),
            ))
        })
    }
}

impl Mask {
    #[inline(always)]
    pub(super) fn none() -> Mask {
        Mask(0)
    }

    /// `then` where true, else `otherwise`.
    #[inline(always)]
    pub(super) fn select(self, then: F, otherwise: F) -> F {
        F(unsafe { _mm512_mask_blend_ps(self.0, otherwise.0, then.0) })
    }

    /// `value` where true, else 0.
    #[inline(always)]
    pub(super) fn keep(self, value: F) -> F {
        F(unsafe { _mm512_maskz_mov_ps(self.0, value.0) })
    }

    /// `a * b` where true, else 0.
    #[inline(always)]
    pub(super) fn keep_product(self, a: F, b: F) -> F {
        F(unsafe { _mm512_maskz_mul_ps(self.0, a.0, b.0) })
    }

    /// One bit per lane of block `block` of the group.
    #[inline(always)]
    pub(super) fn block_bits(self, block: usize) -> u8 {
        (self.0 >> (8 * block)) as u8
    }
}

impl BitOr for Mask {
    type Output = Mask;
    #[inline(always)]
    fn bitor(self, other: Mask) -> Mask {
        Mask(self.0 | other.0)
    }
}

impl Not for Mask {
    type Output = Mask;
    #[inline(always)]
    fn not(self) -> Mask {
        Mask(!self.0)
    }
}

impl BitAnd for Mask {
    type Output = Mask;
    #[inline(always)]
    fn bitand(self, other: Mask) -> Mask {
        Mask(self.0 & other.0)
    }
}
