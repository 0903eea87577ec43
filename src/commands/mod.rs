//! Every GL command as a method on `Context`, grouped like the specification.

pub mod arrays;
pub mod attrib_stack;
pub mod buffers;
pub mod capture;
pub mod eval;
pub mod feedback;
pub mod fragment;
pub mod imaging;
pub mod lighting;
pub mod list;
pub mod matrix;
pub mod multitexture;
pub mod pixel;
pub mod query;
pub mod raster;
pub mod raster_pos;
pub mod rasterization;
pub mod select;
pub mod texture;
pub mod vertex;
