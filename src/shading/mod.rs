//! Shading, the stage that turns covered spans into colours, and the styles that select it.
//!
//! A style pairs with a [`Triangle`](crate::Triangle) through embedded-graphics'
//! `into_styled`, and the result is [`Drawable`](embedded_graphics::Drawable).

mod channels;
mod flat;
mod gouraud;
#[doc(hidden)]
pub mod paint;
mod shader;
mod spans;
mod textured;

pub use channels::ChannelColor;
pub use flat::FlatStyle;
pub use gouraud::GouraudStyle;
pub use paint::TriangleStyle;
pub use shader::{Fragment, PerspectiveShaderStyle, ShaderStyle};
pub use textured::TextureStyle;
