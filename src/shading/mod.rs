//! Shading, the stage that turns covered spans into colours, and the styles that select it.
//!
//! A style pairs with a [`Triangle`](crate::Triangle) through embedded-graphics'
//! `into_styled`, and the result is [`Drawable`](embedded_graphics::Drawable).

mod flat;
mod gouraud;
mod shader;
mod spans;

pub use flat::FlatStyle;
pub use gouraud::{GouraudColor, GouraudStyle};
pub use shader::{Fragment, ShaderStyle};
