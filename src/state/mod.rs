//! GL state and its validation, one module per group of state. No pointers here.

pub mod arrays;
pub mod buffers;
pub mod convert;
pub mod enables;
pub mod light;
pub mod light_model;
pub mod material;
pub mod matrix;
pub mod raster;
