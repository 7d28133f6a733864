//! embedded-graphics' `Triangle` (fill style) and embedded-3dgfx 0.7.2 (`draw` of
//! `ColoredTriangle` / `GouraudTriangle`) on emulated Cortex-M, on the scenes of trirast's
//! firmware example, drawing into trirast's 320x240 `Rgb565` framebuffer: the same pixels
//! counted the same way, so their figures stand beside `examples/firmware.rs`'s (see
//! `Cargo.toml` for the command). Per pixel divides by the pixels the exact rasterizer covers,
//! as trirast's firmware does; the peers draw shared edges twice, so compare per triangle.
#![no_std]
#![no_main]

#[path = "../../../examples/common/scenes.rs"]
mod scenes;
#[path = "../../../examples/common/systick.rs"]
mod systick;

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use embedded_3dgfx::pipeline::{assemble::primitive::DrawPrimitive, rasterize::draw::draw};
use embedded_graphics::{
    pixelcolor::Rgb565,
    prelude::*,
    primitives::{PrimitiveStyle, Triangle as EgTriangle},
};
use heapless::Vec;
use nalgebra::Point2;
use panic_halt as _;
use scenes::{HEIGHT, Scene, SceneTriangle, WIDTH, covered_pixels};
use systick::{Ratio, count};
use trirast::Framebuffer;

const FRAME_LEN: usize = (WIDTH * HEIGHT) as usize;
const MAX_TRIANGLES: usize = 5000;

#[inline(never)]
fn eg_flat(triangles: &[SceneTriangle], frame: &mut Framebuffer<'_, Rgb565>) {
    for t in triangles {
        let [a, b, c] = t.vertices;
        let _ = EgTriangle::new(a, b, c)
            .into_styled(PrimitiveStyle::with_fill(t.color))
            .draw(frame);
    }
}

#[inline(never)]
fn gfx_flat(triangles: &[SceneTriangle], frame: &mut Framebuffer<'_, Rgb565>) {
    for t in triangles {
        let points = t.vertices.map(|p| Point2::new(p.x, p.y));
        draw(DrawPrimitive::ColoredTriangle(points, t.color), frame);
    }
}

#[inline(never)]
fn gfx_gouraud(triangles: &[SceneTriangle], frame: &mut Framebuffer<'_, Rgb565>) {
    for t in triangles {
        let points = t.vertices.map(|p| Point2::new(p.x, p.y));
        let colors = t.vertex_colors;
        draw(DrawPrimitive::GouraudTriangle { points, colors }, frame);
    }
}

#[entry]
fn main() -> ! {
    let mut core = cortex_m::Peripherals::take().unwrap();
    systick::start(&mut core.SYST);

    let mut pixels = [Rgb565::BLACK; FRAME_LEN];
    let mut triangles: Vec<SceneTriangle, MAX_TRIANGLES> = Vec::new();
    hprintln!(
        "peers on Cortex-M: {}x{} Rgb565, instructions counted by SysTick",
        WIDTH,
        HEIGHT
    );
    let modes: [(&str, fn(&[SceneTriangle], &mut Framebuffer<'_, Rgb565>)); 3] = [
        ("eg-flat", eg_flat),
        ("3dgfx-flat", gfx_flat),
        ("3dgfx-gouraud", gfx_gouraud),
    ];
    for (name, draw_mode) in modes {
        for scene in Scene::ALL {
            triangles.clear();
            scene.for_each(|t| {
                let _ = triangles.push(t);
            });
            let covered = covered_pixels(&triangles);
            pixels.fill(Rgb565::BLACK);
            let mut frame = Framebuffer::new(&mut pixels, WIDTH, HEIGHT).unwrap();
            let spent = count(|| draw_mode(&triangles, &mut frame));
            hprintln!(
                "{:<13} {:<8} instructions={} pixels={} triangles={} per_pixel={} per_triangle={}",
                name,
                scene.name(),
                spent,
                covered,
                triangles.len(),
                Ratio(spent, u64::from(covered)),
                Ratio(spent, triangles.len() as u64)
            );
        }
    }
    hprintln!("done");
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
