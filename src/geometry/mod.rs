//! Geometry: shapes without style, and the viewport mapping onto pixels.

mod triangle;
mod viewport;

pub use triangle::{Orientation, Triangle};
pub use viewport::Viewport;
