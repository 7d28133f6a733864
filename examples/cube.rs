//! A spinning, lit, textured cube with a depth buffer: headless to PNG frames, or in an SDL
//! window with the `sdl` feature.
//!
//! ```text
//! cargo run --release --example cube                          # 24 frames to target/cube/
//! cargo run --release --example cube -- DIR N                 # N frames to DIR
//! cargo run --release --example cube --features sdl           # spinning in a window
//! ```
//!
//! The 3D transform, perspective and per-vertex lighting are integer arithmetic in
//! `examples/common/cube.rs` (the firmware example renders the same cube); the crate maps NDC
//! to pixels (`Viewport`), culls back faces and draws the mesh through the depth buffer, each
//! face's texture modulated by the interpolated light.

#[path = "common/cube.rs"]
mod cube;

use std::{path::PathBuf, time::Instant};

use embedded_graphics::{
    pixelcolor::{Rgb565, Rgb888},
    prelude::*,
    primitives::Rectangle,
};
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};
use trirast::{
    depth::{DepthBuffer, DepthTarget},
    texture::Texels,
    Framebuffer,
};

const WIDTH: u32 = 240;
const HEIGHT: u32 = 180;

/// The cube's texture as `Rgb565` texels.
fn texels() -> Vec<Rgb565> {
    (0..cube::TEXTURE * cube::TEXTURE)
        .map(|i| {
            let [r, g, b] = cube::texel(i % cube::TEXTURE, i / cube::TEXTURE);
            Rgb888::new(r, g, b).into()
        })
        .collect()
}

/// Draws frame `frame` of `frames` (one turn) into `pixels` through `depths`.
fn render(texels: &[Rgb565], pixels: &mut [Rgb565], depths: &mut [u16], frame: u32, frames: u32) {
    let side = cube::TEXTURE as u32;
    let texture = Texels::new(texels, side, side).unwrap();
    let mut display = Framebuffer::new(pixels, WIDTH, HEIGHT).unwrap();
    display.clear(Rgb565::new(3, 8, 12)).unwrap();
    let mut zbuffer = DepthBuffer::new(depths, WIDTH, HEIGHT).unwrap();
    zbuffer.clear(u16::MAX);
    let area = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
    let mut scene = DepthTarget::new(&mut display, &mut zbuffer).unwrap();
    cube::draw(&mut scene, area, texture, (frame, frames)).unwrap();
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    #[cfg(feature = "sdl")]
    if args.is_empty() {
        return window();
    }
    let dir = args
        .first()
        .map_or_else(|| PathBuf::from("target/cube"), PathBuf::from);
    let frames: u32 = args.get(1).and_then(|n| n.parse().ok()).unwrap_or(24);
    std::fs::create_dir_all(&dir).expect("cannot create the output folder");

    let texels = texels();
    let mut pixels = vec![Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
    let mut depths = vec![0u16; (WIDTH * HEIGHT) as usize];
    let mut out = SimulatorDisplay::<Rgb565>::new(Size::new(WIDTH, HEIGHT));
    let area = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));

    println!("writing {frames} frames to {}", dir.display());
    for frame in 0..frames {
        let start = Instant::now();
        render(&texels, &mut pixels, &mut depths, frame, frames);
        let drawn = start.elapsed();
        out.fill_contiguous(&area, pixels.iter().copied()).unwrap();
        let path = dir.join(format!("frame_{frame:02}.png"));
        out.to_rgb_output_image(&OutputSettingsBuilder::new().scale(2).build())
            .save_png(&path)
            .expect("cannot write the PNG");
        println!("  {} ({:.2} ms)", path.display(), drawn.as_secs_f64() * 1e3);
    }
}

/// The cube spinning in a window, one turn every four seconds; Escape or closing quits.
#[cfg(feature = "sdl")]
fn window() {
    use embedded_graphics_simulator::{sdl2::Keycode, SimulatorEvent, Window};
    const FRAMES_PER_TURN: u32 = 240;
    let texels = texels();
    let mut pixels = vec![Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
    let mut depths = vec![0u16; (WIDTH * HEIGHT) as usize];
    let mut out = SimulatorDisplay::<Rgb565>::new(Size::new(WIDTH, HEIGHT));
    let area = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
    let mut window = Window::new(
        "trirast: textured cube, depth buffer",
        &OutputSettingsBuilder::new().scale(3).build(),
    );
    window.set_max_fps(60);
    for frame in 0.. {
        render(
            &texels,
            &mut pixels,
            &mut depths,
            frame % (2 * FRAMES_PER_TURN),
            FRAMES_PER_TURN,
        );
        out.fill_contiguous(&area, pixels.iter().copied()).unwrap();
        // With EG_SIMULATOR_DUMP set this writes the first frame and exits (a smoke test).
        window.update(&out);
        let quit = window.events().any(|e| {
            matches!(
                e,
                SimulatorEvent::Quit
                    | SimulatorEvent::KeyDown {
                        keycode: Keycode::Escape,
                        ..
                    }
            )
        });
        if quit {
            return;
        }
    }
}
