//! The fuzz targets' shared code: the C ABI harness (`harness.rs`) and the generator of its
//! call table (`generate.rs`).

pub mod generate;
pub mod harness;

// The GL entry points the call table declares are fflight's exports.
use fflight as _;
pub mod seeds;
