//! A spinning, lit, textured cube with a depth buffer, rendered headless to PNG frames.
//!
//! ```text
//! cargo run --release --example cube               # 24 frames to target/cube/
//! cargo run --release --example cube -- DIR N      # N frames to DIR
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
    mesh::{Cull, Mesh},
    texture::{Filter, Texels},
    Framebuffer, TextureStyle,
};

const WIDTH: u32 = 240;
const HEIGHT: u32 = 180;

fn main() {
    let mut args = std::env::args().skip(1);
    let dir = args
        .next()
        .map_or_else(|| PathBuf::from("target/cube"), PathBuf::from);
    let frames: u32 = args.next().and_then(|n| n.parse().ok()).unwrap_or(24);
    std::fs::create_dir_all(&dir).expect("cannot create the output folder");

    let texels: Vec<Rgb565> = (0..cube::TEXTURE * cube::TEXTURE)
        .map(|i| {
            let [r, g, b] = cube::texel(i % cube::TEXTURE, i / cube::TEXTURE);
            Rgb888::new(r, g, b).into()
        })
        .collect();
    let side = cube::TEXTURE as u32;
    let texture = Texels::new(&texels, side, side).unwrap();
    let mut pixels = vec![Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
    let mut depths = vec![0u16; (WIDTH * HEIGHT) as usize];
    let area = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));

    println!("writing {frames} frames to {}", dir.display());
    for frame in 0..frames {
        let start = Instant::now();
        let mut display = Framebuffer::new(&mut pixels, WIDTH, HEIGHT).unwrap();
        display.clear(Rgb565::new(3, 8, 12)).unwrap();
        let mut zbuffer = DepthBuffer::new(&mut depths, WIDTH, HEIGHT).unwrap();
        zbuffer.clear(u16::MAX);
        let vertices = cube::vertices(frame, frames, area);
        let mesh = Mesh::new(&vertices, &cube::TRIANGLES).unwrap();
        let mut scene = DepthTarget::new(&mut display, &mut zbuffer).unwrap();
        mesh.draw_with_depth(&mut scene, Cull::Clockwise, |_, corners| {
            let gray = |l: u8| Rgb565::new(l >> 3, l >> 2, l >> 3);
            TextureStyle::new(texture, corners.map(|v| v.uv))
                .with_filter(Filter::Bilinear)
                .with_modulation(corners.map(|v| gray(v.light)))
        })
        .unwrap();
        let drawn = start.elapsed();

        let mut out = SimulatorDisplay::<Rgb888>::new(Size::new(WIDTH, HEIGHT));
        for (i, &c) in pixels.iter().enumerate() {
            let p = Point::new((i as u32 % WIDTH) as i32, (i as u32 / WIDTH) as i32);
            Pixel(p, Rgb888::from(c)).draw(&mut out).unwrap();
        }
        let path = dir.join(format!("frame_{frame:02}.png"));
        out.to_rgb_output_image(&OutputSettingsBuilder::new().scale(2).build())
            .save_png(&path)
            .expect("cannot write the PNG");
        println!("  {} ({:.2} ms)", path.display(), drawn.as_secs_f64() * 1e3);
    }
}
