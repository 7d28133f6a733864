//! Targets, the last pipeline stage: where spans land.
//!
//! Everything in the crate draws into any embedded-graphics
//! [`DrawTarget`](embedded_graphics::draw_target::DrawTarget). This module adds a framebuffer
//! over caller-provided memory whose span fills write straight into the slice, and targets
//! that draw translucently ([`Framebuffer::translucent`], [`OverBackground`]).

mod framebuffer;
mod storage;
mod translucency;

pub use framebuffer::Framebuffer;
pub(crate) use framebuffer::fill_run;
pub use storage::StoredPixel;
pub use translucency::{BlendTarget, OverBackground, Translucent, blend};
