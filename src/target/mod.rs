//! Targets, the last pipeline stage: where spans land.
//!
//! Everything in the crate draws into any embedded-graphics
//! [`DrawTarget`](embedded_graphics::draw_target::DrawTarget). This module adds a framebuffer
//! over caller-provided memory whose span fills write straight into the slice.

mod framebuffer;
mod storage;

pub use framebuffer::Framebuffer;
pub use storage::StoredPixel;
