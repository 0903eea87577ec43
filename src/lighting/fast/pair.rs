//! Sixteen f32 lanes as two `__m256` (AVX2 with FMA): two blocks of the pipeline at a time,
//! each operation the eight-lane one (`narrow.rs`) on both halves. With AVX2's sixteen
//! registers the halves spill more, but a light's constants, its powers' loops and the other
//! work that does not depend on the lanes serve twice the vertices.

use std::ops::{Add, BitAnd, BitOr, Mul, Neg, Not, Sub};

use super::narrow;
use crate::lighting::lanes::LanesF32;

/// Blocks of the pipeline (8 lanes each) a vector holds.
pub(super) const BLOCKS: usize = 2;

/// Sixteen f32 lanes: the first block's and the second's.
#[derive(Clone, Copy)]
pub(super) struct F(narrow::F, narrow::F);

/// Sixteen f64 lanes.
#[derive(Clone, Copy)]
pub(super) struct D2(narrow::D2, narrow::D2);

/// A per-lane condition.
#[derive(Clone, Copy)]
pub(super) struct Mask(narrow::Mask, narrow::Mask);

impl D2 {
    #[inline(always)]
    pub(super) fn from_f32(v: F) -> D2 {
        D2(narrow::D2::from_f32(v.0), narrow::D2::from_f32(v.1))
    }

    #[inline(always)]
    pub(super) fn to_f32(self) -> F {
        F(self.0.to_f32(), self.1.to_f32())
    }

    #[inline(always)]
    pub(super) fn scale(self, factor: f64) -> D2 {
        D2(self.0.scale(factor), self.1.scale(factor))
    }

    #[inline(always)]
    pub(super) fn add(self, other: D2) -> D2 {
        D2(self.0.add(other.0), self.1.add(other.1))
    }
}

/// Methods of `F` that apply the eight-lane method to both halves.
macro_rules! halves {
    ($(fn $method:ident(self $(, $arg:ident: $type:ty)*) -> $out:ident;)*) => {
        $(
            #[inline(always)]
            pub(super) fn $method(self $(, $arg: $type)*) -> $out {
                $out(self.0.$method($($arg.0),*), self.1.$method($($arg.1),*))
            }
        )*
    };
}

impl F {
    #[inline(always)]
    pub(super) fn splat(value: f32) -> F {
        let half = narrow::F::splat(value);
        F(half, half)
    }

    /// The f32 at byte `OFFSET` of `*base` in every lane: one broadcast for both halves.
    #[target_feature(enable = "avx")]
    #[inline]
    pub(super) fn broadcast_at<const OFFSET: usize, T>(base: &T) -> F {
        let half = narrow::F::broadcast_at::<OFFSET, T>(base);
        F(half, half)
    }

    #[inline(always)]
    pub(super) fn zero() -> F {
        F(narrow::F::zero(), narrow::F::zero())
    }

    /// The lanes of the group's two blocks.
    #[inline(always)]
    pub(super) fn load(parts: [&LanesF32; BLOCKS]) -> F {
        F(narrow::F::load([parts[0]]), narrow::F::load([parts[1]]))
    }

    #[inline(always)]
    pub(super) fn store(self, parts: [&mut LanesF32; BLOCKS]) {
        let [first, second] = parts;
        self.0.store([first]);
        self.1.store([second]);
    }

    halves! {
        fn mul_add(self, b: F, c: F) -> F;
        fn max(self, other: F) -> F;
        fn min(self, other: F) -> F;
        fn sqrt(self) -> F;
        fn div(self, other: F) -> F;
        fn reciprocal_sqrt_estimate_12(self) -> F;
        fn reciprocal_estimate_12(self) -> F;
        fn abs(self) -> F;
        fn lt(self, other: F) -> Mask;
        fn gt(self, other: F) -> Mask;
        fn ge(self, other: F) -> Mask;
        fn out_of_range(self) -> Mask;
        fn exceeds(self, limit: F) -> Mask;
        fn is_nan(self) -> Mask;
        fn outside_unit(self) -> Mask;
    }

    /// Whether every lane equals `value`.
    #[inline(always)]
    pub(super) fn all_eq(self, value: f32) -> bool {
        self.0.all_eq(value) && self.1.all_eq(value)
    }
}

macro_rules! binary {
    ($type:ident, $trait:ident, $method:ident) => {
        impl $trait for $type {
            type Output = $type;
            #[inline(always)]
            fn $method(self, other: $type) -> $type {
                $type(self.0.$method(other.0), self.1.$method(other.1))
            }
        }
    };
}
binary!(F, Add, add);
binary!(F, Sub, sub);
binary!(F, Mul, mul);
binary!(Mask, BitOr, bitor);
binary!(Mask, BitAnd, bitand);

impl Neg for F {
    type Output = F;
    #[inline(always)]
    fn neg(self) -> F {
        F(-self.0, -self.1)
    }
}

impl Mask {
    #[inline(always)]
    pub(super) fn none() -> Mask {
        Mask(narrow::Mask::none(), narrow::Mask::none())
    }

    halves! {
        fn select(self, then: F, otherwise: F) -> F;
        fn keep(self, value: F) -> F;
        fn keep_product(self, a: F, b: F) -> F;
    }

    /// One bit per lane of block `block` of the group.
    #[inline(always)]
    pub(super) fn block_bits(self, block: usize) -> u8 {
        if block == 0 {
            self.0.block_bits(0)
        } else {
            self.1.block_bits(0)
        }
    }
}

impl Not for Mask {
    type Output = Mask;
    #[inline(always)]
    fn not(self) -> Mask {
        Mask(!self.0, !self.1)
    }
}
