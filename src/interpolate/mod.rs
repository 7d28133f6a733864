//! Interpolation, the stage between coverage and shading: barycentric coordinates and plane
//! equations of per-vertex attributes.
//!
//! The public part is the point query [`Triangle::barycentric`](crate::Triangle::barycentric)
//! and the [`Perspective`] option of the texture and shader styles. Drawing uses fixed-point
//! plane equations set up once per triangle (one reciprocal of the area for all gradients),
//! evaluated exactly at the start of each span and stepped by additions along it; in
//! perspective, attributes over `w` are the planes, divided at the ends of sub-spans.

mod barycentric;
mod perspective;
mod planes;

pub use barycentric::{Barycentric, Location};
pub(crate) use perspective::PerspectivePlanes;
pub use perspective::{Perspective, SubSpan};
pub(crate) use planes::{AreaMemo, CHANNEL_BITS, DEPTH_BITS, Planes, TrackedPlanes};
