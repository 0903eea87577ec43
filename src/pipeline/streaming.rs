//! Memory streamed through: copies of many values into memory that is not read again soon
//! (the application's feedback buffer, written a chunk of laid-out points at a time), and
//! hints that ask for the lines of memory read or written in order a little before. Plain
//! stores first read each line of the destination into the cache; non-temporal stores write
//! the lines whole, without that read. Which is faster depends on the CPU (`streaming_pays`)
//! and on the copy's length (`STREAMING_ALWAYS`).
//! Besides the C ABI layer, the fast kernel's intrinsics and the call by which the immediate
//! mode helper writes points into the application's memory (`commands::vertex::helper`'s
//! `place`), this is the crate's only `unsafe` code: the stores and the hints.
#![allow(unsafe_code)]

use std::sync::OnceLock;

/// Fewer values than this are copied with plain stores: the fence that ends streaming
/// stores, and the lines left out of the cache, cost more than they save on a short copy.
const STREAMING_MIN: usize = 1024;

/// Copies of at least this many values (512 KiB: a mesh chunk's triangles, copied whole once
/// another thread made them) stream on every CPU: their plain stores would wait on the reads
/// of lines of a buffer far larger than the caches. On an Intel Xeon with
/// AVX-512 (family 6, model 167) a C loop copying 1.5 MB pieces into 184 MB wrote 20.6 GB/s
/// streaming against 9.7 with memcpy, and the 1000x1000 mesh on two threads took 0.925 of
/// the time (7 of 7 alternating pairs faster); immediate mode's chunks of 2048 points
/// (64 KiB), streamed too, took 1.058 of the time there, and so stay with `streaming_pays`.
/// Not measured on the Cascade Lake Xeon of `streaming_pays`, where one core streamed
/// slower than it wrote with plain stores.
const STREAMING_ALWAYS: usize = 128 * 1024;

/// Whether non-temporal stores copy faster than plain ones on this CPU, for copies shorter
/// than `STREAMING_ALWAYS` and the pieces of `copy_streaming_piece`: on AMD's (and
/// Hygon's), whose streaming stores write at the memory's speed (an EPYC, arrays 1 light on 2
/// threads: 6.9 -> 6.2 ns/vertex with them); not elsewhere, as measured on Intel's server
/// cores, where one core's streaming stores are slower than plain stores with their reads (a
/// Cascade Lake Xeon: 6.5 against 8.7 GB/s written; arrays 1 light on 2 threads 0.94 times
/// the time with plain stores, 10 of 10 alternating pairs faster; immediate mode with one
/// light 6 of 6, median 0.92).
fn streaming_pays() -> bool {
    static PAYS: OnceLock<bool> = OnceLock::new();
    *PAYS.get_or_init(|| {
        #[cfg(target_arch = "x86_64")]
        {
            let vendor = std::arch::x86_64::__cpuid(0);
            let name = [vendor.ebx, vendor.edx, vendor.ecx].map(u32::to_le_bytes);
            matches!(name.as_flattened(), b"AuthenticAMD" | b"HygonGenuine")
        }
        #[cfg(not(target_arch = "x86_64"))]
        false
    })
}

/// Copies `from` to the start of `to` (at least as long), with non-temporal stores when the
/// copy is very long (`STREAMING_ALWAYS`), or long and they pay on this CPU
/// (`streaming_pays`; every x86-64 has SSE's).
///
/// # Examples
///
/// ```
/// use fflight::pipeline::streaming::copy_streaming;
/// let from: Vec<f32> = (0..5000).map(|k| k as f32).collect();
/// let mut to = vec![0.0; 5003];
/// copy_streaming(&mut to[1..], &from);
/// assert_eq!(&to[1..5001], &from[..]);
/// assert_eq!((to[0], to[5001]), (0.0, 0.0));
/// ```
pub fn copy_streaming(to: &mut [f32], from: &[f32]) {
    let to = &mut to[..from.len()];
    #[cfg(target_arch = "x86_64")]
    if from.len() >= STREAMING_ALWAYS || (from.len() >= STREAMING_MIN && streaming_pays()) {
        stream_sse(to, from);
        return fence();
    }
    to.copy_from_slice(from);
}

/// A piece of a long copy made a piece at a time between other work, so that the stores
/// drain while that work runs: `copy_streaming` without its threshold and without the fence,
/// which `fence` gives once the last piece is copied.
pub(crate) fn copy_streaming_piece(to: &mut [f32], from: &[f32]) {
    let to = &mut to[..from.len()];
    #[cfg(target_arch = "x86_64")]
    if streaming_pays() {
        return stream_sse(to, from);
    }
    to.copy_from_slice(from);
}

/// Orders the streaming stores made so far before any later store, as plain stores are
/// ordered: before the values are handed to another thread or to the application.
pub(crate) fn fence() {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: SSE is part of x86-64.
    unsafe {
        std::arch::x86_64::_mm_sfence()
    };
}

/// Asks the first-level cache for the lines that hold `values[start..start + len]` (the part
/// of it inside `values`): a hint, which reads nothing the program sees and never faults.
///
/// # Examples
///
/// ```
/// use fflight::pipeline::streaming::prefetch;
/// let bytes = vec![0u8; 1000];
/// prefetch(&bytes, 900, 500); // the lines of bytes 900..1000
/// prefetch(&bytes, 2000, 64); // nothing: past the end
/// ```
pub fn prefetch<T>(values: &[T], start: usize, len: usize) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        let end = values.len().min(start.saturating_add(len));
        let per_line = (64 / size_of::<T>().max(1)).max(1);
        let line = |at: usize| {
            // SAFETY: SSE is part of x86-64; a prefetch reads nothing and cannot fault, and
            // the address is inside `values`.
            unsafe { _mm_prefetch::<_MM_HINT_T0>(values.as_ptr().wrapping_add(at).cast()) }
        };
        if start < end {
            (start..end).step_by(per_line).for_each(line);
            // The last line, which the steps miss when `start` is not at a line's start.
            line(end - 1);
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (values, start, len);
}

/// How many blocks' values ahead of those it writes into the application's feedback buffer
/// a thread asks for the lines it will write, which its plain stores would otherwise wait to
/// read (the buffer is larger than the caches): 1M points, 1 light, 2 threads, against none,
/// median pair ratios 0.927 one block ahead (9 of 10 faster), 0.896 four (10 of 10), 0.905
/// eight (8 of 10); sixteen as four.
const BLOCKS_AHEAD: usize = 4;

/// Asks for the lines of the block of `len` values `BLOCKS_AHEAD` blocks on in `to`, whose
/// values from `next` on the next blocks' plain stores will write.
pub(crate) fn prefetch_block_ahead(to: &[f32], next: usize, len: usize) {
    prefetch(to, next + (BLOCKS_AHEAD - 1) * len, len);
}

/// `prefetch_block_ahead` for `copy_streaming_piece`'s copies, a block's values each;
/// nothing where their stores stream (`streaming_pays`), writing lines without reading them.
pub(crate) fn prefetch_for_copy(to: &[f32], next: usize, len: usize) {
    if !streaming_pays() {
        prefetch_block_ahead(to, next, len);
    }
}

/// `copy_streaming` with SSE's `movntps`, four values at a time into 16-byte aligned places,
/// unfenced.
#[cfg(target_arch = "x86_64")]
fn stream_sse(to: &mut [f32], from: &[f32]) {
    use std::arch::x86_64::{_mm_loadu_ps, _mm_stream_ps};
    // The values before the first 16-byte boundary of `to`, plainly.
    let head = to.as_ptr().align_offset(16).min(to.len());
    to[..head].copy_from_slice(&from[..head]);
    let (to, from) = (&mut to[head..], &from[head..]);
    let mut to_fours = to.chunks_exact_mut(4);
    let mut from_fours = from.chunks_exact(4);
    for (to, from) in (&mut to_fours).zip(&mut from_fours) {
        // SAFETY: both are 4 values in bounds; `to` starts on a 16-byte boundary (`head`
        // reached one, and each step is 16 bytes), as `movntps` needs. SSE is part of
        // x86-64.
        unsafe { _mm_stream_ps(to.as_mut_ptr(), _mm_loadu_ps(from.as_ptr())) };
    }
    to_fours
        .into_remainder()
        .copy_from_slice(from_fours.remainder());
}

/// The CPU's `prefetchw` (x86-64, CPUID 8000_0001h ECX bit 8), found once: kept by its users
/// so that asking for lines costs no check of the CPU (glVertex's usual case has no call).
#[derive(Clone, Copy, Debug)]
pub(crate) struct PrefetchW(());

impl PrefetchW {
    /// The instruction, if the CPU has it.
    pub(crate) fn detect() -> Option<PrefetchW> {
        static HAS: OnceLock<bool> = OnceLock::new();
        let has = *HAS.get_or_init(|| {
            #[cfg(target_arch = "x86_64")]
            {
                use std::arch::x86_64::__cpuid;
                __cpuid(0x8000_0000).eax >= 0x8000_0001 && __cpuid(0x8000_0001).ecx & 1 << 8 != 0
            }
            #[cfg(not(target_arch = "x86_64"))]
            false
        });
        has.then_some(PrefetchW(()))
    }

    /// Asks for the lines of `value` at byte offsets `offsets`, to write them: a hint that
    /// reads nothing the program sees and never faults, which takes each line from another
    /// core's cache before the stores that need it wait for it. Immediate mode with one light
    /// on two threads, batches shared with the helper thread, which read the blocks last: the
    /// block after next asked for as each fills, median pair ratio 0.84 (8 of 8 faster); four
    /// blocks ahead, the same.
    #[inline(always)]
    pub(crate) fn lines<T>(self, value: &T, offsets: &[usize]) {
        for &offset in offsets {
            let at = std::ptr::from_ref(value).cast::<u8>().wrapping_add(offset);
            #[cfg(target_arch = "x86_64")]
            // SAFETY: the CPU has the instruction (`detect`); a prefetch reads nothing and
            // cannot fault.
            unsafe {
                std::arch::asm!("prefetchw [{}]", in(reg) at, options(nostack, preserves_flags, readonly))
            };
            #[cfg(not(target_arch = "x86_64"))]
            let _ = at;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every length around the streaming threshold, at every offset from a 16-byte
    /// boundary, copies exactly the values given and writes nothing around them: the copy
    /// this CPU makes, and the streaming stores whichever CPU this is.
    #[test]
    fn a_streamed_copy_is_the_values_and_nothing_else() {
        let streamed = |to: &mut [f32], from: &[f32]| {
            #[cfg(target_arch = "x86_64")]
            stream_sse(&mut to[..from.len()], from);
            #[cfg(not(target_arch = "x86_64"))]
            copy_streaming(to, from);
            fence();
        };
        let from: Vec<f32> = (0..STREAMING_ALWAYS + 8).map(|k| k as f32 + 0.5).collect();
        for len in [
            0,
            1,
            7,
            STREAMING_MIN - 1,
            STREAMING_MIN,
            STREAMING_MIN + 3,
            4099,
            STREAMING_ALWAYS - 1,
            STREAMING_ALWAYS + 5,
        ] {
            for offset in 0..4 {
                let mut expected = vec![-1.0f32; len + 8];
                expected[offset..offset + len].copy_from_slice(&from[..len]);
                for copy in [copy_streaming, streamed] {
                    let mut to = vec![-1.0f32; len + 8];
                    copy(&mut to[offset..], &from[..len]);
                    assert_eq!(to, expected, "length {len}, offset {offset}");
                }
            }
        }
    }
}
