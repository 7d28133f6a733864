//! The library's test suite, one test binary: each module below was a binary of its own, and
//! each compiled and linked the shared references (`common`) and the library's painters again
//! (merged, a clean `cargo test --no-run` took 142 s instead of 169 s, and running the tests
//! 22 s instead of 30 s, 2-core machine). Tests that include the examples' own modules
//! (`breakout`, `display_wire`, `firmware_frames`, `ssd0323`) stay binaries of their own, as
//! those modules expect to sit at their crate's root.
//!
//! Run one part with a filter: `cargo test --test suite band::`.

mod common;

mod antialias;
mod band;
mod barycentric;
mod coverage_reference;
mod depth;
mod gouraud;
mod invariance;
mod patterns;
mod perspective;
mod readme;
mod subpixel;
mod targets;
mod texture;
mod translucency;
mod watertight;
