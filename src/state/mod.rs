//! GL state and its validation, one module per group of state. No pointers here.

pub mod arrays;
pub mod buffers;
pub mod convert;
pub mod enables;
pub mod eval;
pub mod fog;
pub mod fragment;
pub mod hints;
pub mod imaging;
pub mod light;
pub mod light_model;
pub mod material;
pub mod matrix;
pub mod names;
pub mod pixel;
pub mod queries;
pub mod raster;
pub mod rasterization;
pub mod texgen;
pub mod texture;
pub mod texture_image;
