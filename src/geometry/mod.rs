//! Geometry: shapes without style.

mod triangle;

pub use triangle::{Orientation, Triangle};
