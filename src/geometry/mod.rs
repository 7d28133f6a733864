//! Geometry: shapes without style, and the viewport mapping onto pixels.

mod subpixel;
mod triangle;
mod viewport;

pub use subpixel::{SubPixelTriangle, SubPoint};
pub use triangle::{Orientation, Triangle};
pub use viewport::Viewport;
