//! Coverage-guided fuzzing of the C ABI: see `fuzz/src/harness.rs`.
#![no_main]

use fflight_fuzz::harness::Harness;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(problem) = Harness::run(data).outcome() {
        panic!("{problem}");
    }
});
