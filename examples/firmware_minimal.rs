//! The smallest useful firmware: a flat and a Gouraud triangle drawn into a RAM framebuffer,
//! whose checksum is written over semihosting (without `core::fmt`, which its baseline build
//! then does not link: a mode whose code can panic shows the formatting that links in its
//! share). A template for your own, and the build that
//! `benches/firmware-size.sh` measures the library's flash cost with.
//!
//! ```text
//! cargo run --release --target thumbv6m-none-eabi --example firmware_minimal --features firmware
//! ```
//!
//! For measuring, `FW_MODE` (read at build time) draws one mode instead: `none` (nothing: the
//! baseline every other build is measured against), `flat`, `gouraud`, `gouraud-z` (Gouraud
//! through a depth buffer), `mesh` (an indexed mesh of flat triangles, clockwise ones culled),
//! `anti-aliased` (flat with anti-aliased edges), `texture` (every filter, wrap and modulation, affine) or
//! `texture-perspective` (the same, perspective-correct where the `w` differ, affine where
//! they are equal). Vertices, colours,
//! depths, coordinates and options pass through `core::hint::black_box`, so the compiler
//! cannot fold any of the library away: each build minus `none` is what that mode costs in
//! flash.
#![no_std]
#![no_main]

use core::hint::black_box;

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hio};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
use fixed::types::I16F16;
use panic_halt as _;
use trirast::{
    FlatStyle, Framebuffer, GouraudStyle, TextureStyle, Triangle,
    depth::{DepthBuffer, DepthTarget},
    mesh::{Cull, Mesh},
    target::BlendTarget,
    texture::{Filter, Perspective, Texels, Wrap},
};

const WIDTH: u32 = 320;
const HEIGHT: u32 = 240;

#[entry]
fn main() -> ! {
    let mut pixels = [Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
    // In firmware this would be your display driver's DrawTarget (mipidsi, ssd1306, ...).
    // Not `unwrap`: its message would link the error's `Debug` and `core::fmt`.
    let Ok(mut display) = Framebuffer::new(&mut pixels, WIDTH, HEIGHT) else {
        halt();
    };
    let triangle = black_box(Triangle::new(
        Point::new(10, 10),
        Point::new(300, 40),
        Point::new(60, 220),
    ));
    let colors = black_box([Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE]);
    match option_env!("FW_MODE") {
        Some("none") => {}
        Some("flat") => {
            let _ = triangle
                .into_styled(FlatStyle::new(colors[0]))
                .draw(&mut display);
        }
        Some("mesh") => {
            let points = black_box([
                Point::new(10, 10),
                Point::new(300, 40),
                Point::new(60, 220),
                Point::new(310, 230),
            ]);
            let Ok(mesh) = Mesh::new(&points, black_box(&[[0, 1, 2], [1, 3, 2]])) else {
                halt();
            };
            let _ = mesh.draw(&mut display, black_box(Cull::Clockwise), |k, _| {
                FlatStyle::new(colors[k % 3])
            });
        }
        Some("anti-aliased") => {
            let style = FlatStyle::new(colors[0]);
            let _ = display.draw_anti_aliased(&triangle, &style);
        }
        Some("gouraud") => {
            let style = GouraudStyle::new(colors).with_dither(black_box(false));
            let _ = triangle.into_styled(style).draw(&mut display);
        }
        Some("gouraud-z") => {
            let mut depths = [u16::MAX; (WIDTH * HEIGHT) as usize];
            // Errors only for mismatched buffers; `unwrap` would add its formatting to the count.
            let Ok(mut zbuffer) = DepthBuffer::new(&mut depths, WIDTH, HEIGHT) else {
                halt();
            };
            let Ok(mut scene) = DepthTarget::new(&mut display, &mut zbuffer) else {
                halt();
            };
            let _ = scene.draw(
                &triangle,
                black_box([100, 2000, 30000]),
                &GouraudStyle::new(colors).with_dither(black_box(false)),
            );
        }
        Some(mode @ ("texture" | "texture-perspective")) => {
            let texels = black_box([Rgb565::WHITE, Rgb565::BLACK, Rgb565::RED, Rgb565::BLUE]);
            let Ok(texture) = Texels::new(&texels, 2, 2) else {
                halt();
            };
            let at = |u: i32, v: i32| [I16F16::from_num(u), I16F16::from_num(v)];
            let coordinates = black_box([at(0, 0), at(5, 0), at(0, 7)]);
            for filter in [Filter::Nearest, Filter::Bilinear] {
                for wrap in [Wrap::Clamp, Wrap::Repeat] {
                    for modulation in [None, Some(colors)] {
                        let mut style = TextureStyle::new(texture, coordinates)
                            .with_filter(black_box(filter))
                            .with_wrap(black_box(wrap));
                        style.modulation = black_box(modulation);
                        if mode == "texture-perspective" {
                            let w = black_box([1, 2, 3].map(I16F16::from_num));
                            style = style.with_perspective(Perspective::new(w));
                        }
                        let _ = triangle.into_styled(style).draw(&mut display);
                    }
                }
            }
        }
        _ => {
            let _ = triangle
                .into_styled(FlatStyle::new(Rgb565::CSS_ORANGE))
                .draw(&mut display);
            let _ = Triangle::new(Point::new(160, 0), Point::new(319, 239), Point::new(0, 200))
                .into_styled(GouraudStyle::new(colors))
                .draw(&mut display);
        }
    }
    let mut sum: u32 = 0x811C_9DC5;
    for &p in black_box(&pixels[..]) {
        for byte in p.into_storage().to_le_bytes() {
            sum = (sum ^ u32::from(byte)).wrapping_mul(0x0100_0193);
        }
    }
    // Written without `core::fmt` (`hprintln!` links its integer formatting, about 2 KB), so
    // that a mode whose code can panic shows the formatting its panic message links in its
    // share, as in a firmware that prints nothing.
    let mut line = *b"checksum=00000000\n";
    for (k, digit) in line[9..17].iter_mut().enumerate() {
        let nibble = (sum >> (28 - 4 * k)) as u8 & 0xF;
        *digit = if nibble < 10 {
            b'0' + nibble
        } else {
            b'a' + nibble - 10
        };
    }
    if let Ok(mut out) = hio::hstdout() {
        let _ = out.write_all(&line);
    }
    debug::exit(debug::EXIT_SUCCESS);
    halt()
}

/// Stops here for good: what the error branches do (a panic's message and location would
/// add to a mode's share, `unwrap`'s its formatting too).
fn halt() -> ! {
    loop {
        cortex_m::asm::wfi();
    }
}
