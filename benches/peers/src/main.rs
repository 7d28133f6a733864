//! embedded-3dgfx's rasterizer on the perf example's scenes, drawing into trirast's 320x240
//! `Rgb565` framebuffer (see `Cargo.toml`).
//!
//! MODE: `3dgfx-flat` (`DrawPrimitive::ColoredTriangle`), `3dgfx-gouraud`
//! (`DrawPrimitive::GouraudTriangle`). SCENE: `big`, `small`, `mesh`, `scene200`.

#[path = "../../../examples/common/counting.rs"]
mod counting;
#[path = "../../../examples/common/scenes.rs"]
mod scenes;

use std::{process::ExitCode, time::Instant};

use counting::Counting;
use embedded_3dgfx::pipeline::{assemble::primitive::DrawPrimitive, rasterize::draw::draw};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
use nalgebra::Point2;
use scenes::{HEIGHT, Scene, SceneTriangle, WIDTH};
use trirast::Framebuffer;

const MODES: &[&str] = &["3dgfx-flat", "3dgfx-gouraud"];

#[inline(never)]
fn draw_frame<D>(mode: &str, scene: &[SceneTriangle], target: &mut D)
where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
{
    for t in scene {
        let points = t.vertices.map(|p| Point2::new(p.x, p.y));
        let primitive = if mode == "3dgfx-flat" {
            DrawPrimitive::ColoredTriangle(points, t.color)
        } else {
            DrawPrimitive::GouraudTriangle {
                points,
                colors: t.vertex_colors,
            }
        };
        draw(primitive, target);
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [mode, scene, frames] = args.as_slice() else {
        eprintln!(
            "usage: trirast-peers MODE SCENE FRAMES\n  MODE: {}",
            MODES.join(" | ")
        );
        return ExitCode::from(2);
    };
    let (Some(kind), Ok(frames), true) = (
        Scene::parse(scene),
        frames.parse::<u64>(),
        MODES.contains(&mode.as_str()),
    ) else {
        eprintln!(
            "usage: trirast-peers MODE SCENE FRAMES\n  MODE: {}",
            MODES.join(" | ")
        );
        return ExitCode::from(2);
    };
    let mut scene = Vec::new();
    kind.for_each(|t| scene.push(t));
    let mut pixels = vec![Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
    let mut fb = Framebuffer::new(&mut pixels, WIDTH, HEIGHT).expect("sized for the screen");
    let (per_frame, overdraw, gaps) = {
        let mut counting = Counting::new(&mut fb);
        draw_frame(mode, &scene, &mut counting);
        (counting.pixels(), counting.overdraw(), counting.gaps())
    };
    let start = Instant::now();
    for _ in 0..frames {
        draw_frame(mode, std::hint::black_box(&scene), &mut fb);
    }
    let secs = start.elapsed().as_secs_f64();
    println!(
        "mode={mode} scene={} frames={frames} time={:.3}ms",
        kind.name(),
        secs * 1e3
    );
    println!("per_frame: pixels={per_frame} overdraw={overdraw} gaps={gaps}");
    println!(
        "pixels={} triangles={}",
        per_frame * frames,
        scene.len() as u64 * frames
    );
    ExitCode::SUCCESS
}
