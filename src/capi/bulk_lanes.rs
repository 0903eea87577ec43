//! fflLightVertices' full blocks between the application's arrays and the blocks' lanes by
//! AVX-512's two-register permutations, where the CPU has them (found at run time): a block
//! of packed 3-float elements read in 2 loads and 2 permutations, a block of 4 lanes written
//! to packed 4-float vertices in 2 loads, 2 permutations and 2 stores. The bulk call's own
//! code is compiled for x86-64's baseline, SSE2, where the same moves take a few dozen
//! instructions (a sixth of its time with 8 spot lights). Elsewhere, and for every other
//! layout, `pipeline::fetch::read_floats` and `write_transposed` do it.

use crate::lighting::lanes::{LANES, LanesF32};
use crate::pipeline::block::Lanes4;

/// Whether the CPU has AVX-512 F (the standard library's detection, found once).
#[inline(always)]
fn avx512() -> bool {
    #[cfg(target_arch = "x86_64")]
    return std::arch::is_x86_feature_detected!("avx512f");
    #[cfg(not(target_arch = "x86_64"))]
    false
}

/// Reads the full block of packed 3-float elements at the start of `run` (at least
/// `LANES * 12` bytes) into the components `lanes` (at least 3), when the CPU has AVX-512;
/// false, having read nothing, otherwise.
#[inline(always)]
pub(super) fn read_packed3(run: &[u8], lanes: &mut [LanesF32]) -> bool {
    let (Some(run), Some(lanes)) = (
        run.first_chunk::<{ LANES * 12 }>(),
        lanes.first_chunk_mut::<3>(),
    ) else {
        return false;
    };
    if !avx512() {
        return false;
    }
    // SAFETY: the CPU has AVX-512 F.
    #[cfg(target_arch = "x86_64")]
    unsafe {
        x86::read_packed3(run, lanes)
    };
    true
}

/// Writes the full block of four components `lanes` to 8 packed vertices of 4 floats at
/// `out`, when the CPU has AVX-512; false, having written nothing, otherwise.
///
/// # Safety
/// `out` has room for `LANES * 4` floats.
#[inline(always)]
pub(super) unsafe fn write_packed4(out: *mut f32, lanes: &Lanes4) -> bool {
    if !avx512() {
        return false;
    }
    // SAFETY: the CPU has AVX-512 F; the caller guarantees the room.
    #[cfg(target_arch = "x86_64")]
    unsafe {
        x86::write_packed4(out, lanes)
    };
    true
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;

    use super::{LANES, Lanes4, LanesF32};

    /// Element k of the run is floats 3k..3k+3: x from 0, 3, ..., 21, y from 1, ..., 22 (both
    /// in one register), z from 2, ..., 23; floats 16 and on come from the second register.
    #[target_feature(enable = "avx512f")]
    pub(super) unsafe fn read_packed3(run: &[u8; LANES * 12], lanes: &mut [LanesF32; 3]) {
        let floats = run.as_ptr().cast::<f32>();
        // SAFETY: 24 floats at `floats`, read unaligned; 3 lane arrays of 8 at `lanes`,
        // contiguous (an array of arrays).
        unsafe {
            let low = _mm512_loadu_ps(floats);
            let high = _mm512_castps256_ps512(_mm256_loadu_ps(floats.add(16)));
            let xy = _mm512_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21, 1, 4, 7, 10, 13, 16, 19, 22);
            let z = _mm512_setr_epi32(2, 5, 8, 11, 14, 17, 20, 23, 0, 0, 0, 0, 0, 0, 0, 0);
            let out = lanes.as_mut_ptr().cast::<f32>();
            _mm512_storeu_ps(out, _mm512_permutex2var_ps(low, xy, high));
            let z = _mm512_permutex2var_ps(low, z, high);
            _mm256_storeu_ps(out.add(16), _mm512_castps512_ps256(z));
        }
    }

    /// Vertex k is lanes k of x, y (the first register, at k and 8 + k), z and w (the second,
    /// at 16 + k and 24 + k); vertices 0..4 make the first register out, 4..8 the second.
    #[target_feature(enable = "avx512f")]
    pub(super) unsafe fn write_packed4(out: *mut f32, lanes: &Lanes4) {
        let lanes = lanes.as_ptr().cast::<f32>();
        // SAFETY: 4 lane arrays of 8, contiguous, at `lanes`; the caller guarantees room for
        // 32 floats at `out`, written unaligned.
        unsafe {
            let xy = _mm512_loadu_ps(lanes);
            let zw = _mm512_loadu_ps(lanes.add(16));
            let first = _mm512_setr_epi32(0, 8, 16, 24, 1, 9, 17, 25, 2, 10, 18, 26, 3, 11, 19, 27);
            let second = _mm512_add_epi32(first, _mm512_set1_epi32(4));
            _mm512_storeu_ps(out, _mm512_permutex2var_ps(xy, first, zw));
            _mm512_storeu_ps(out.add(16), _mm512_permutex2var_ps(xy, second, zw));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Distinct floats, so that a misplaced one shows.
    fn numbered(k: usize) -> f32 {
        1.0 + k as f32 * 0.5
    }

    #[test]
    fn read_packed3_regroups_by_component_and_leaves_the_rest() {
        let run: Vec<u8> = (0..LANES * 3 + 5)
            .flat_map(|k| numbered(k).to_ne_bytes())
            .collect();
        let mut lanes = [[-1.0; LANES]; 4];
        let read = read_packed3(&run, &mut lanes);
        assert_eq!(read, avx512());
        for (c, component) in lanes.iter().enumerate() {
            let expected: LanesF32 = if read && c < 3 {
                std::array::from_fn(|k| numbered(3 * k + c))
            } else {
                [-1.0; LANES]
            };
            assert_eq!(*component, expected, "component {c}");
        }
        // Too short a run, or too few components: nothing read.
        assert!(!read_packed3(&run[..LANES * 12 - 1], &mut lanes));
        assert!(!read_packed3(&run, &mut lanes[..2]));
    }

    #[test]
    fn write_packed4_writes_whole_vertices_in_lane_order() {
        let lanes: Lanes4 = std::array::from_fn(|c| std::array::from_fn(|k| numbered(8 * c + k)));
        // One float of room either side, which must stay as it was.
        let mut out = [-1.0f32; LANES * 4 + 2];
        // SAFETY: room for LANES * 4 floats after the first.
        let written = unsafe { write_packed4(out[1..].as_mut_ptr(), &lanes) };
        assert_eq!(written, avx512());
        assert_eq!((out[0], out[LANES * 4 + 1]), (-1.0, -1.0));
        for (k, vertex) in out[1..=LANES * 4].chunks_exact(4).enumerate() {
            let expected: [f32; 4] = if written {
                std::array::from_fn(|c| lanes[c][k])
            } else {
                [-1.0; 4]
            };
            assert_eq!(vertex, expected, "vertex {k}");
        }
    }
}
