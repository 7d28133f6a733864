//! Renders a gallery of scenes to PNG files, headless (no SDL needed).
//!
//! ```text
//! cargo run --release --example showcase            # writes target/showcase/*.png
//! cargo run --release --example showcase -- DIR     # writes DIR/*.png
//! ```

#[path = "common/scenes.rs"]
mod scenes;

use std::{path::PathBuf, time::Instant};

use embedded_graphics::{
    mono_font::{ascii::FONT_6X10, MonoTextStyle},
    pixelcolor::{BinaryColor, Rgb565, Rgb888},
    prelude::*,
    primitives::{PrimitiveStyle, Triangle as EgTriangle},
    text::Text,
};
use embedded_graphics_simulator::{OutputSettings, OutputSettingsBuilder, SimulatorDisplay};
use trirast::{FillRule, FlatStyle, Triangle};

/// One picture: a name, what it shows, and how to draw it.
struct Scene {
    name: &'static str,
    about: &'static str,
    render: fn() -> (SimulatorDisplay<Rgb888>, OutputSettings),
}

const SCENES: &[Scene] = &[
    Scene {
        name: "fill_rules",
        about: "two triangles sharing an edge, top-left rule vs inclusive, 12x zoom",
        render: fill_rules,
    },
    Scene {
        name: "mesh",
        about: "the 2,000-triangle benchmark mesh, each triangle a random colour",
        render: mesh,
    },
    Scene {
        name: "fan",
        about: "a 48-triangle fan: every pixel drawn once, the centre by exactly one triangle",
        render: fan,
    },
    Scene {
        name: "overdraw",
        about: "times each pixel of a mesh is written: trirast (left) vs embedded-graphics (right)",
        render: overdraw,
    },
];

fn main() {
    let dir = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("target/showcase"), PathBuf::from);
    std::fs::create_dir_all(&dir).expect("cannot create the output folder");
    println!("writing {} scenes to {}", SCENES.len(), dir.display());
    for scene in SCENES {
        let start = Instant::now();
        let (display, settings) = (scene.render)();
        let rendered = start.elapsed();
        let path = dir.join(format!("{}.png", scene.name));
        display
            .to_rgb_output_image(&settings)
            .save_png(&path)
            .expect("cannot write the PNG");
        println!(
            "  {:<12} {:>8.2} ms  {}  ({})",
            scene.name,
            rendered.as_secs_f64() * 1e3,
            path.display(),
            scene.about
        );
    }
}

fn label(display: &mut SimulatorDisplay<Rgb888>, text: &str, at: Point) {
    let style = MonoTextStyle::new(&FONT_6X10, Rgb888::WHITE);
    Text::new(text, at, style).draw(display).unwrap();
}

/// Each half: a square split along its diagonal into a red and a blue triangle. Top-left draws
/// each pixel once (the shared diagonal goes to one triangle); inclusive draws both closed
/// triangles, so the diagonal shows the one drawn last.
fn fill_rules() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let mut display = SimulatorDisplay::new(Size::new(23, 10));
    let p = Point::new;
    for (origin, rule) in [(0, FillRule::TopLeft), (12, FillRule::Inclusive)] {
        let (a, b, c, d) = (
            p(origin + 1, 1),
            p(origin + 9, 1),
            p(origin + 9, 9),
            p(origin + 1, 9),
        );
        let red = FlatStyle::new(Rgb888::new(230, 60, 60)).with_fill_rule(rule);
        let blue = FlatStyle::new(Rgb888::new(60, 110, 230)).with_fill_rule(rule);
        Triangle::new(a, b, c)
            .into_styled(red)
            .draw(&mut display)
            .unwrap();
        Triangle::new(a, c, d)
            .into_styled(blue)
            .draw(&mut display)
            .unwrap();
    }
    let settings = OutputSettingsBuilder::new()
        .scale(12)
        .pixel_spacing(1)
        .build();
    (display, settings)
}

fn to_888(c: Rgb565) -> Rgb888 {
    c.into()
}

fn mesh() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let mut display = SimulatorDisplay::new(Size::new(scenes::WIDTH, scenes::HEIGHT));
    for t in scenes::Scene::Mesh.build() {
        let [a, b, c] = t.vertices;
        Triangle::new(a, b, c)
            .into_styled(FlatStyle::new(to_888(t.color)))
            .draw(&mut display)
            .unwrap();
    }
    (display, OutputSettingsBuilder::new().scale(2).build())
}

fn fan() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let mut display = SimulatorDisplay::new(Size::new(160, 160));
    let center = Point::new(80, 80);
    let spokes = 48;
    // Integer ring points from a fixed table of turns (no floating point needed at runtime
    // in the library; the example may use it to place vertices).
    let ring: Vec<Point> = (0..spokes)
        .map(|i| {
            let t = f64::from(i) / f64::from(spokes) * std::f64::consts::TAU;
            let r = if i % 2 == 0 { 74.0 } else { 52.0 };
            center + Point::new((r * t.cos()).round() as i32, (r * t.sin()).round() as i32)
        })
        .collect();
    for i in 0..ring.len() {
        let shade = (i * 255 / ring.len()) as u8;
        let color = Rgb888::new(shade, 255 - shade, 160);
        Triangle::new(center, ring[i], ring[(i + 1) % ring.len()])
            .into_styled(FlatStyle::new(color))
            .draw(&mut display)
            .unwrap();
    }
    (display, OutputSettingsBuilder::new().scale(2).build())
}

/// Counts writes per pixel while drawing a mesh, then shows the counts as colours:
/// black = never (a gap), grey = once, red = twice or more.
fn overdraw() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (w, h) = (120u32, 90u32);
    let tris: Vec<[Point; 3]> = scenes::mesh(12, 9).iter().map(|t| t.vertices).collect();
    let mut display = SimulatorDisplay::new(Size::new(w * 2 + 8, h + 14));
    for (panel, eg) in [(0, false), (1, true)] {
        let mut counts = Counter {
            hits: vec![0; (w * h) as usize],
            w,
            h,
        };
        for [a, b, c] in &tris {
            // The benchmark mesh covers 320x240; scale it into the panel.
            let s = |p: &Point| Point::new(p.x * w as i32 / 320, p.y * h as i32 / 240);
            if eg {
                EgTriangle::new(s(a), s(b), s(c))
                    .into_styled(PrimitiveStyle::with_fill(BinaryColor::On))
                    .draw(&mut counts)
                    .unwrap();
            } else {
                Triangle::new(s(a), s(b), s(c))
                    .into_styled(FlatStyle::new(BinaryColor::On))
                    .draw(&mut counts)
                    .unwrap();
            }
        }
        let x0 = panel * (w as i32 + 8);
        for y in 0..h as i32 {
            for x in 0..w as i32 {
                let color = match counts.hits[(y as u32 * w + x as u32) as usize] {
                    0 => Rgb888::BLACK,
                    1 => Rgb888::new(90, 90, 100),
                    _ => Rgb888::new(255, 40, 40),
                };
                Pixel(Point::new(x0 + x, y), color)
                    .draw(&mut display)
                    .unwrap();
            }
        }
        let twice = counts.hits.iter().filter(|&&n| n > 1).count();
        let text = if eg {
            format!("e-g: {twice} twice")
        } else {
            format!("trirast: {twice} twice")
        };
        label(&mut display, &text, Point::new(x0 + 2, h as i32 + 10));
    }
    (display, OutputSettingsBuilder::new().scale(3).build())
}

/// A target that counts writes per pixel.
struct Counter {
    hits: Vec<u8>,
    w: u32,
    h: u32,
}

impl OriginDimensions for Counter {
    fn size(&self) -> Size {
        Size::new(self.w, self.h)
    }
}

impl DrawTarget for Counter {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Self::Color>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, _) in pixels {
            if p.x >= 0 && p.y >= 0 && (p.x as u32) < self.w && (p.y as u32) < self.h {
                let i = (p.y as u32 * self.w + p.x as u32) as usize;
                self.hits[i] = self.hits[i].saturating_add(1);
            }
        }
        Ok(())
    }
}
