//! Interpolation, the stage between coverage and shading: barycentric coordinates and plane
//! equations of per-vertex attributes.
//!
//! The public part is the point query [`Triangle::barycentric`](crate::Triangle::barycentric).
//! Drawing uses fixed-point plane equations set up once per triangle (one reciprocal of the
//! area for all gradients), evaluated exactly at the start of each span and stepped by
//! additions along it.

mod barycentric;
mod perspective;
mod planes;

pub use barycentric::{Barycentric, Location};
pub(crate) use perspective::{mul_small, PerspectivePlanes, SubSpan};
pub(crate) use planes::{Planes, TrackedPlanes};
