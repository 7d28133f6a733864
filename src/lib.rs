//! Exact, integer-only triangle rasterization for [embedded-graphics] targets.
//!
//! `trirast` fills triangles with integer vertices for microcontroller firmware driving small
//! displays, and for host code drawing into the embedded-graphics simulator:
//!
//! - **Exact.** Coverage is bit for bit the exact half-space test, for any `i32` vertices.
//!   The default [top-left fill rule](FillRule::TopLeft) draws every pixel of a mesh exactly
//!   once: no gaps, no overdraw, whatever the winding.
//! - **Integer only.** Edges are walked Bresenham-style (quotient and error term), with one
//!   division per edge and none per row or pixel. No floating point anywhere.
//! - **Span output.** Each covered row reaches the target as one `fill_solid` call, so display
//!   drivers and the crate's [`Framebuffer`] write whole runs.
//! - **`no_std`, no allocation, no `unsafe`.**
//!
//! The pipeline, one module per stage: setup (sort, orient, reject degenerate triangles, clip)
//! → [`coverage`] (edge stepping, spans) → [`shading`] (styles) → [`target`] (any
//! `DrawTarget`; the crate's framebuffer). Shapes live in [`geometry`], apart from style.
//!
//! # Examples
//!
//! ```
//! use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
//! use trirast::{Framebuffer, FlatStyle, Triangle};
//!
//! let mut pixels = [Rgb565::BLACK; 64 * 48];
//! let mut display = Framebuffer::new(&mut pixels, 64, 48)?;
//!
//! // Two triangles sharing an edge: each pixel of the square is drawn exactly once.
//! let (a, b, c, d) = (Point::new(4, 4), Point::new(40, 4), Point::new(40, 40), Point::new(4, 40));
//! Triangle::new(a, b, c).into_styled(FlatStyle::new(Rgb565::RED)).draw(&mut display).unwrap();
//! Triangle::new(a, c, d).into_styled(FlatStyle::new(Rgb565::BLUE)).draw(&mut display).unwrap();
//!
//! assert_eq!(display.pixel(Point::new(30, 10)), Some(Rgb565::RED));
//! assert_eq!(display.pixel(Point::new(10, 30)), Some(Rgb565::BLUE));
//! assert_eq!(display.pixel(Point::new(40, 40)), Some(Rgb565::BLACK)); // bottom-right: not ours
//! # Ok::<(), trirast::Error>(())
//! ```
//!
//! # Coordinate range
//!
//! Vertices may be any `i32`, also in debug builds with overflow checks. When all six
//! coordinates lie within ±[`FAST_LIMIT`] (±1,073,741,823) the edge walk runs in 32-bit
//! arithmetic; beyond, the same walk runs in 64-bit arithmetic, equally exact and a little
//! slower per row. Either way only rows and columns inside the target are visited.
//!
//! [embedded-graphics]: https://docs.rs/embedded-graphics

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs, missing_debug_implementations)]
#![deny(clippy::float_arithmetic, clippy::float_cmp, clippy::float_cmp_const)]
#![warn(clippy::pedantic)]
// Narrowing casts are on values that setup has proven to be in range; each site says why.
// `inline(always)` sits only where callgrind showed the inlining matters for the span loops.
#![allow(
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss,
    clippy::module_name_repetitions,
    clippy::inline_always,
    // Loops over N parallel arrays read best indexed.
    clippy::needless_range_loop
)]

mod arch;
pub mod band;
mod bounds;
pub mod coverage;
pub mod depth;
mod error;
pub mod geometry;
pub mod interpolate;
pub mod mesh;
mod setup;
pub mod shading;
pub mod target;
pub mod texture;
mod unroll;

pub use coverage::FillRule;
pub use error::Error;
pub use geometry::{Orientation, Triangle};
pub use setup::lane::FAST_LIMIT;
pub use shading::{FlatStyle, GouraudStyle, ShaderStyle, TextureStyle};
pub use target::{Framebuffer, StoredPixel};

/// The README's examples, compiled and run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

#[cfg(test)]
mod test_rng {
    /// Xorshift64 (shifts 13, 7, 17): the unit tests' random inputs, the same sequence from a
    /// seed on every run.
    pub(crate) struct XorShift(pub(crate) u64);

    impl XorShift {
        /// The next value (the seed must not be zero).
        pub(crate) fn next_u64(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
    }
}
