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
#[cfg(feature = "sdl")]
#[path = "common/demo_window.rs"]
mod demo_window;

use std::{
    path::PathBuf,
    time::{Duration, Instant},
};

use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};

const WIDTH: u32 = 240;
const HEIGHT: u32 = 180;

/// The texture, frame, depth buffer and display a frame is drawn through, allocated once.
struct Renderer {
    texels: [Rgb565; (cube::TEXTURE * cube::TEXTURE) as usize],
    pixels: Vec<Rgb565>,
    depths: Vec<u16>,
    display: SimulatorDisplay<Rgb565>,
}

impl Renderer {
    fn new() -> Self {
        Self {
            texels: cube::texels(),
            pixels: vec![Rgb565::BLACK; (WIDTH * HEIGHT) as usize],
            depths: vec![0u16; (WIDTH * HEIGHT) as usize],
            display: SimulatorDisplay::new(Size::new(WIDTH, HEIGHT)),
        }
    }

    /// Draws frame `frame` of `frames` (one turn) and copies it to the simulator display;
    /// returns the display and the time spent drawing (the copy not included).
    fn render(&mut self, frame: u32, frames: u32) -> (&SimulatorDisplay<Rgb565>, Duration) {
        let start = Instant::now();
        let (pixels, depths) = (&mut self.pixels, &mut self.depths);
        cube::render(
            &self.texels,
            pixels,
            depths,
            (WIDTH, HEIGHT),
            (frame, frames),
        );
        let drawn = start.elapsed();
        let area = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
        self.display
            .fill_contiguous(&area, self.pixels.iter().copied())
            .unwrap();
        (&self.display, drawn)
    }
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

    let mut renderer = Renderer::new();
    println!("writing {frames} frames to {}", dir.display());
    for frame in 0..frames {
        let (display, drawn) = renderer.render(frame, frames);
        let path = dir.join(format!("frame_{frame:02}.png"));
        display
            .to_rgb_output_image(&OutputSettingsBuilder::new().scale(2).build())
            .save_png(&path)
            .expect("cannot write the PNG");
        println!("  {} ({:.2} ms)", path.display(), drawn.as_secs_f64() * 1e3);
    }
}

/// The cube spinning in a window, one turn every four seconds; Escape or closing quits.
#[cfg(feature = "sdl")]
fn window() {
    use embedded_graphics_simulator::Window;
    const FRAMES_PER_TURN: u32 = 240;
    let mut renderer = Renderer::new();
    let mut window = Window::new(
        "trirast: textured cube, depth buffer",
        &OutputSettingsBuilder::new().scale(3).build(),
    );
    window.set_max_fps(60);
    for frame in 0.. {
        let (display, _) = renderer.render(frame % (2 * FRAMES_PER_TURN), FRAMES_PER_TURN);
        // With EG_SIMULATOR_DUMP set this writes the first frame and exits (a smoke test).
        window.update(display);
        if window.events().any(|e| demo_window::is_quit(&e)) {
            return;
        }
    }
}
