//! fflight: OpenGL 1.x fixed-function lighting and vertex pipeline in safe Rust, exported over
//! a C ABI (`include/fflight.h`).
//!
//! The Rust API is the [`Context`]: one method per GL command, returning `GlResult`. The C
//! entry points (module `capi`) run the same methods on the calling thread's current context.
//!
//! ```
//! use fflight::{gl::*, Context};
//! let mut ctx = Context::new();
//! ctx.set_capability(GL_LIGHTING, true).unwrap();
//! ctx.set_capability(GL_LIGHT0, true).unwrap();
//! ctx.light(GL_LIGHT0, GL_POSITION, &[0.0, 0.0, 1.0, 0.0]).unwrap();
//! ```
#![deny(unsafe_code)]
#![warn(missing_docs)]

pub mod capi;
pub mod commands;
pub mod context;
pub mod current;
pub mod error;
pub mod gl;
pub mod lighting;
pub mod pipeline;
pub mod state;
pub mod threads;

pub use context::Context;
pub use error::{GlError, GlResult};
