//! Geometry: shapes without style, and the viewport mapping onto pixels.

mod shape;
mod subpixel;
mod triangle;
mod viewport;

pub use shape::Shape;
pub use subpixel::{SubPixelTriangle, SubPoint};
pub use triangle::{Orientation, Points, Triangle};
pub use viewport::{Projected, Viewport};
