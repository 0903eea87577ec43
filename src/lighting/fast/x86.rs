//! The fast engine's kernel for x86-64, written once (`kernel.rs`) over thin lane types and
//! compiled for each: for AVX2 with FMA over sixteen lanes in two `__m256` (`pair.rs`: two
//! blocks of the pipeline at a time) and over eight in one (`narrow.rs`: a block without a
//! pair), and for AVX-512 over sixteen lanes in a `__m512` (`wide.rs`: two blocks at a time,
//! so each chain of dependent operations serves twice the vertices) and eight in a `__m256`.
//! The lane types' operations are `#[inline(always)]` and only ever run inside the kernel's
//! functions, which carry their instruction set's target features and are only called once
//! the CPU was found to have them. Besides the C ABI layer, this is the crate's only
//! `unsafe` code: the intrinsics.
#![allow(unsafe_code)]

use super::{FastState, InstructionSet};
use crate::lighting::batch::Reads;
use crate::pipeline::block::{InputBlock, OutputBlock};

#[path = "narrow.rs"]
mod narrow;
#[path = "pair.rs"]
mod pair;
#[path = "wide.rs"]
mod wide;

/// A kernel: the blocks of a call for what the consumer reads, each block's refused
/// lanes written to the byte of the same index.
pub(super) type Kernel = fn(&FastState, Reads, &[InputBlock], &mut [OutputBlock], &mut [u8]);

/// The kernel for this CPU: AVX-512 or AVX2 with FMA, or `None` without them (found once).
pub(super) fn kernel() -> Option<Kernel> {
    static KERNEL: std::sync::OnceLock<Option<Kernel>> = std::sync::OnceLock::new();
    *KERNEL.get_or_init(|| kernel_for(InstructionSet::Avx512).or(kernel_for(InstructionSet::Avx2)))
}

/// The kernel for `set`, or `None` when the CPU lacks it.
pub(super) fn kernel_for(set: InstructionSet) -> Option<Kernel> {
    let avx2 = is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma");
    let avx512 = is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx512vl");
    if set == InstructionSet::Avx512 && avx2 && avx512 {
        // SAFETY: the CPU has the features both are compiled with.
        Some(|state, reads, inputs, outputs, refused| unsafe {
            in_pairs(
                avx512::process_blocks,
                avx512_narrow::process_blocks,
                state,
                reads,
                inputs,
                outputs,
                refused,
            )
        })
    } else if set == InstructionSet::Avx2 && avx2 {
        // SAFETY: the CPU has the features both are compiled with.
        Some(|state, reads, inputs, outputs, refused| unsafe {
            if state.lights().len() < PAIRED_LIGHTS {
                avx2::process_blocks(state, reads, inputs, outputs, refused);
                return;
            }
            in_pairs(
                avx2_pair::process_blocks,
                avx2::process_blocks,
                state,
                reads,
                inputs,
                outputs,
                refused,
            )
        })
    } else {
        None
    }
}

/// The fewest lights for which AVX2 lights two blocks at a time: what the pair shares (a
/// light's constants, the control of its powers' loops) grows with the lights, and what it
/// costs (AVX2's sixteen registers holding half as many values) does not. On the AMD EPYC
/// (Zen 3), lowest of 14-16 alternating processes, 20,000 points on one thread: one
/// directional light 11.4 ns/vertex a block at a time, 12.2 paired; one attenuated spot light
/// 21.2 and 22.1; two 19.5 and 18.9; eight (the bulk call) 42.9 and 38.6 (1M points).
const PAIRED_LIGHTS: usize = 2;

/// A `Kernel` compiled with target features.
type Compiled = unsafe fn(&FastState, Reads, &[InputBlock], &mut [OutputBlock], &mut [u8]);

/// Pairs of blocks by `paired` (sixteen lanes), an odd last block by `single` (eight): the
/// same operations lane by lane, so a vertex's result does not depend on its pairing.
///
/// # Safety
/// The CPU has the features both kernels are compiled with.
unsafe fn in_pairs(
    paired: Compiled,
    single: Compiled,
    state: &FastState,
    reads: Reads,
    inputs: &[InputBlock],
    outputs: &mut [OutputBlock],
    refused: &mut [u8],
) {
    let count = inputs.len().min(outputs.len()).min(refused.len());
    let pairs = count - count % 2;
    // SAFETY: the caller's.
    unsafe {
        paired(state, reads, &inputs[..pairs], outputs, refused);
        single(
            state,
            reads,
            &inputs[pairs..count],
            &mut outputs[pairs..],
            &mut refused[pairs..],
        );
    }
}

/// `reciprocal_sqrt` and `reciprocal` from AVX-512's 14-bit estimates and one Newton step
/// (within about 2 units in the last place, without the divider's latency): the same
/// operations in the wide kernel and in the eight-lane one that serves its odd blocks.
macro_rules! newton_reciprocals {
    () => {
        with_features! {
            /// 1/√x: y·(3 - x·y²)/2 from the estimate y.
            #[inline]
            fn reciprocal_sqrt(x: F) -> F {
                let y = x.reciprocal_sqrt_estimate();
                let half_y = y * F::splat(0.5);
                half_y * (x * y).mul_add(-y, F::splat(3.0))
            }

            /// 1/x: y·(2 - x·y) from the estimate y.
            #[inline]
            fn reciprocal(x: F) -> F {
                let y = x.reciprocal_estimate();
                y * x.mul_add(-y, F::splat(2.0))
            }
        }
    };
}

/// `reciprocal_sqrt` and `reciprocal` from AVX's 12-bit estimates, by one third-order step
/// each (about 1 unit in the last place, as the square root and division they replace, which
/// both go to the one divider: the pair kernel would have doubled its work a step; alone, no
/// change measured): the same operations in the pair kernel and the one-block one.
macro_rules! estimate_reciprocals {
    () => {
        with_features! {
            /// 1/√x from the 12-bit estimate y by one third-order step: with r = 1 - x·y²,
            /// y·(1 + r/2 + 3r²/8), whose truncation (5r³/16, r < 2^-10.4) lies far below the
            /// step's own rounding.
            #[inline]
            fn reciprocal_sqrt(x: F) -> F {
                let y = x.reciprocal_sqrt_estimate_12();
                let r = (x * y).mul_add(-y, F::splat(1.0));
                let correction = r.mul_add(F::splat(0.375), F::splat(0.5)) * r;
                y.mul_add(correction, y)
            }

            /// 1/x from the 12-bit estimate y by one third-order step: with r = 1 - x·y,
            /// y·(1 + r + r²).
            #[inline]
            fn reciprocal(x: F) -> F {
                let y = x.reciprocal_estimate_12();
                let r = x.mul_add(-y, F::splat(1.0));
                y.mul_add(r.mul_add(r, r), y)
            }
        }
    };
}

/// The kernel compiled for AVX2 with FMA, two blocks at a time (as two `__m256`).
mod avx2_pair {
    use super::pair as lanes;

    /// Gives an item the module's target features.
    macro_rules! with_features {
        ($($item:item)*) => { $(#[target_feature(enable = "avx,avx2,fma")] $item)* };
    }
    estimate_reciprocals!();
    include!("kernel.rs");
}

/// The kernel compiled for AVX2 with FMA, a block at a time: for a block without a pair.
mod avx2 {
    use super::narrow as lanes;

    /// Gives an item the module's target features.
    macro_rules! with_features {
        ($($item:item)*) => { $(#[target_feature(enable = "avx,avx2,fma")] $item)* };
    }
    estimate_reciprocals!();
    include!("kernel.rs");
}

/// The kernel compiled for AVX-512 on eight lanes, for a block without a pair: the wide
/// kernel's operations, its reciprocal estimates included, on a `__m256`.
mod avx512_narrow {
    use super::narrow as lanes;

    /// Gives an item the module's target features.
    macro_rules! with_features {
        ($($item:item)*) => { $(#[target_feature(enable = "avx,avx2,fma,avx512f,avx512vl")] $item)* };
    }
    newton_reciprocals!();
    include!("kernel.rs");
}

/// The kernel compiled for AVX-512, two blocks at a time.
mod avx512 {
    use super::wide as lanes;

    /// Gives an item the module's target features.
    macro_rules! with_features {
        ($($item:item)*) => { $(#[target_feature(enable = "avx,avx2,fma,avx512f,avx512vl")] $item)* };
    }
    newton_reciprocals!();
    include!("kernel.rs");
}
