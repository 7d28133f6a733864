//! Renders a gallery of scenes to PNG files, headless (no SDL needed).
//!
//! ```text
//! cargo run --release --example showcase            # writes target/showcase/*.png
//! cargo run --release --example showcase -- DIR     # writes DIR/*.png
//! ```

#[path = "common/breakout.rs"]
mod breakout;
#[path = "common/cube.rs"]
mod cube;
#[path = "common/scenes.rs"]
mod scenes;
#[path = "common/ssd0323.rs"]
mod ssd0323;

use std::{path::PathBuf, time::Instant};

use embedded_graphics::{
    mono_font::{MonoTextStyle, ascii::FONT_6X10},
    pixelcolor::{BinaryColor, Gray2, Gray4, Gray8, GrayColor, Rgb565, Rgb888},
    prelude::*,
    primitives::{PrimitiveStyle, Rectangle, Triangle as EgTriangle},
    text::Text,
};
use embedded_graphics_simulator::{OutputSettings, OutputSettingsBuilder, SimulatorDisplay};
use fixed::types::{I16F16, I24F8};
use tinybmp::Bmp;
use trirast::{
    FillRule, FlatStyle, Framebuffer, GouraudStyle, ShaderStyle, TextureStyle, Triangle,
    band::{Bands, Scene as BandScene, SceneStyle},
    geometry::{SubPixelTriangle, SubPoint, Viewport},
    mesh::MeshVertex,
    shading::Fragment,
    target::BlendTarget,
    texture::{Filter, ImageTexels, Perspective, Texels, Wrap},
};

/// Six frames of a needle turning one degree a frame: vertices snapped to whole pixels
/// (top row) move in jumps, some frames not at all; vertices in 1/256 pixel (bottom row) move
/// the needle every frame.
fn subpixel_motion() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (cell, frames) = (36i32, 6i32);
    let mut display = SimulatorDisplay::new(Size::new((cell * frames) as u32, (2 * cell) as u32));
    let background = Rgb888::new(24, 30, 48);
    display.clear(background).unwrap();
    for frame in 0..frames {
        // The needle's three corners in 1/256 pixel: the tip 30 pixels out, the base 2.5
        // pixels either side of the pivot, turned `frame` degrees (182 / 65536 of a turn each).
        let turn = 7_000 + i64::from(frame) * 182;
        let pivot = (i64::from(frame * cell + 5) * 256, 32 * 256);
        let at = |turn: i64, r: i64| {
            let (s, c) = (cube::sin(turn), cube::cos(turn));
            (pivot.0 + ((r * s) >> 16), pivot.1 - ((r * c) >> 16))
        };
        let corners = [
            at(turn, 30 * 256),
            at(turn + 16_384, 640),
            at(turn - 16_384, 640),
        ];
        let sub = |(x, y): (i64, i64)| {
            SubPoint::new(I24F8::from_bits(x as i32), I24F8::from_bits(y as i32))
        };
        let exact = SubPixelTriangle::new(sub(corners[0]), sub(corners[1]), sub(corners[2]));
        let snapped = Triangle {
            vertices: exact.vertices.map(|v| MeshVertex::position(&v)),
        };
        let style = FlatStyle::new(Rgb888::new(255, 210, 90));
        snapped.into_styled(style).draw(&mut display).unwrap();
        let mut lower = display.translated(Point::new(0, cell));
        exact.into_styled(style).draw(&mut lower).unwrap();
    }
    (display, OutputSettingsBuilder::new().scale(4).build())
}

/// A checkered floor receding to the horizon, as two triangles: mapped affinely (left), the
/// checks bend along the diagonal the triangles share; perspective-correct (right), with each
/// vertex's `w` from `Viewport::project_clip`, the rows of checks stay straight.
fn perspective_floor() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (w, h) = (160u32, 120u32);
    let (light, dark) = (Rgb565::new(29, 52, 16), Rgb565::new(5, 14, 9));
    // 8 x 8 texels, four checks of 4 x 4.
    let checks: Vec<Rgb565> = (0..64)
        .map(|i| {
            if (i % 8 / 4 + i / 32) % 2 == 0 {
                light
            } else {
                dark
            }
        })
        .collect();
    let texture = Texels::new(&checks, 8, 8).unwrap();
    let viewport = Viewport::new(Rectangle::new(Point::zero(), Size::new(w, h)));
    // The floor 1.5 below the eye, 160 wide (its far edge crosses the whole view: a level
    // horizon), from 1.2 to 60 ahead; 8 texels a unit.
    let corner = |x: f32, z: f32| {
        let clip = [x * 0.75, -1.5, 0.0, z].map(I16F16::from_num);
        let uv = [(x + 80.0) * 8.0, z * 8.0].map(I16F16::from_num);
        (viewport.project_clip(clip), uv)
    };
    let quad = [
        corner(-80.0, 60.0),
        corner(80.0, 60.0),
        corner(80.0, 1.2),
        corner(-80.0, 1.2),
    ];
    let mut display = SimulatorDisplay::new(Size::new(2 * w + 4, h));
    for (x0, perspective) in [(0, false), (w as i32 + 4, true)] {
        let mut pixels = vec![Rgb565::new(17, 42, 29); (w * h) as usize];
        let mut frame = Framebuffer::new(&mut pixels, w, h).unwrap();
        for [a, b, c] in [[0, 1, 2], [0, 2, 3]] {
            let [(pa, ta), (pb, tb), (pc, tc)] = [quad[a], quad[b], quad[c]];
            let mut style = TextureStyle::new(texture, [ta, tb, tc]).with_wrap(Wrap::Repeat);
            if perspective {
                style = style.with_perspective(Perspective::new([pa.w, pb.w, pc.w]));
            }
            let floor = SubPixelTriangle::new(pa.position, pb.position, pc.position);
            floor.into_styled(style).draw(&mut frame).unwrap();
        }
        for (i, c) in pixels.iter().enumerate() {
            let p = Point::new(x0 + (i as u32 % w) as i32, (i as u32 / w) as i32);
            Pixel(p, to_888(*c)).draw(&mut display).unwrap();
        }
    }
    (display, OutputSettingsBuilder::new().scale(3).build())
}

/// A gauge, aliased (left) and with anti-aliased edges (right): each edge pixel blended over
/// the dial by the area of it the triangle covers.
fn anti_aliased() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (w, h) = (112u32, 84u32);
    let mut display = SimulatorDisplay::new(Size::new(2 * w + 2, h));
    for (x0, smooth) in [(0, false), (w as i32 + 2, true)] {
        let mut pixels = vec![Rgb565::new(3, 7, 6); (w * h) as usize];
        let mut frame = Framebuffer::new(&mut pixels, w, h).unwrap();
        for (triangle, color) in gauge(Point::new(56, 56), 50) {
            let style = FlatStyle::new(color);
            if smooth {
                frame.draw_anti_aliased(&triangle, &style).unwrap();
            } else {
                triangle.into_styled(style).draw(&mut frame).unwrap();
            }
        }
        for (i, c) in pixels.iter().enumerate() {
            let p = Point::new(x0 + (i as u32 % w) as i32, (i as u32 / w) as i32);
            Pixel(p, to_888(*c)).draw(&mut display).unwrap();
        }
    }
    (display, OutputSettingsBuilder::new().scale(3).build())
}

/// A gauge's triangles around `center`: 13 tapered ticks on a 240-degree arc of `radius` and
/// a needle, one triangle each (triangles sharing an edge would each blend their part of it,
/// and the dial would show through the seam).
fn gauge(center: Point, radius: i64) -> Vec<(Triangle, Rgb565)> {
    // A point at `r` pixels from the centre, `turn` / 65536 of a turn clockwise from up.
    let at = |turn: i64, r: i64| {
        let (s, c) = (cube::sin(turn), cube::cos(turn));
        let round = |v: i64| ((v + (1 << 15)) >> 16) as i32;
        center + Point::new(round(r * s), round(-r * c))
    };
    let mut triangles = Vec::new();
    for k in 0..13i64 {
        let turn = -21_845 + k * 3_641; // -120 to +120 degrees, every 20
        let (inner, width) = if k % 3 == 0 {
            (radius - 14, 420)
        } else {
            (radius - 8, 300)
        };
        let color = if k >= 10 {
            Rgb565::new(31, 12, 4)
        } else {
            Rgb565::new(26, 54, 26)
        };
        let (a, b) = (at(turn - width, radius), at(turn + width, radius));
        triangles.push((Triangle::new(a, b, at(turn, inner)), color));
    }
    // The needle, 35 degrees past noon.
    let needle = 6_371;
    let tip = at(needle, radius - 4);
    let (left, right) = (at(needle - 16_384, 4), at(needle + 16_384, 4));
    triangles.push((Triangle::new(left, tip, right), Rgb565::new(31, 40, 0)));
    triangles
}

/// Draws an `Rgb565` framebuffer's pixels into a new display of its size.
fn show(pixels: &[Rgb565], width: u32) -> SimulatorDisplay<Rgb888> {
    let height = pixels.len() as u32 / width;
    let mut display = SimulatorDisplay::new(Size::new(width, height));
    for (i, c) in pixels.iter().enumerate() {
        let p = Point::new((i as u32 % width) as i32, (i as u32 / width) as i32);
        Pixel(p, Rgb888::from(*c)).draw(&mut display).unwrap();
    }
    display
}

/// The examples' texture: a 64x64 wooden crate (see `assets/make_crate_bmp.py`).
const CRATE_BMP: &[u8] = include_bytes!("assets/crate.bmp");

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
        name: "gouraud_rgb565",
        about: "Gouraud shading in Rgb565: a colour wheel of 24 triangles",
        render: gouraud_rgb565,
    },
    Scene {
        name: "gouraud_gray",
        about: "the same fade in Gray8, Gray4, Gray2 and dithered BinaryColor (left to right)",
        render: gouraud_gray,
    },
    Scene {
        name: "dither_rgb565",
        about: "a slow Rgb565 gradient, rounded (left) vs dithered (right), 4x zoom",
        render: dither_rgb565,
    },
    Scene {
        name: "translucent",
        about: "translucent triangles over a Gouraud wheel: a HUD panel and a fan, each pixel blended once",
        render: translucent,
    },
    Scene {
        name: "anti_aliased",
        about: "a gauge's ticks and needle, aliased (left) and anti-aliased by exact coverage (right)",
        render: anti_aliased,
    },
    Scene {
        name: "subpixel",
        about: "a needle turning 1 degree a frame: whole-pixel vertices (top) jump, 1/256-pixel ones (bottom) turn",
        render: subpixel_motion,
    },
    Scene {
        name: "perspective",
        about: "a checkered floor to the horizon: affine textures (left) bend, perspective-correct ones (right) do not",
        render: perspective_floor,
    },
    Scene {
        name: "shader",
        about: "a user shader: per-vertex light intensity and a procedural checker",
        render: shader,
    },
    Scene {
        name: "texture_filters",
        about: "a BMP (tinybmp, read in place) magnified: nearest (left) vs bilinear (right)",
        render: texture_filters,
    },
    Scene {
        name: "textured_cube",
        about: "an isometric crate: Rgb565 texels, bilinear, modulated by per-vertex light",
        render: textured_cube,
    },
    Scene {
        name: "depth_cube",
        about: "a textured, lit cube through a 16-bit depth buffer (right: the depth buffer)",
        render: depth_cube,
    },
    Scene {
        name: "band_frame",
        about: "200 depth-tested triangles (Gouraud, textured, flat) rendered 16 rows at a time",
        render: band_frame,
    },
    Scene {
        name: "ssd0323",
        about: "the cube in dithered 4-bit grey: what QEMU's emulated SSD0323 OLED shows (examples/ssd0323.sh)",
        render: ssd0323_oled,
    },
    Scene {
        name: "overdraw",
        about: "times each pixel of a mesh is written: trirast (left) vs embedded-graphics (right)",
        render: overdraw,
    },
    Scene {
        name: "breakout",
        about: "Breakout (examples/breakout.rs) after 3,000 frames of the autopilot",
        render: breakout_frame,
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
            "  {:<15} {:>8.2} ms  {}  ({})",
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
    scenes::Scene::Mesh.for_each(|t| {
        let [a, b, c] = t.vertices;
        Triangle::new(a, b, c)
            .into_styled(FlatStyle::new(to_888(t.color)))
            .draw(&mut display)
            .unwrap();
    });
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

/// A wheel of triangles around a white centre, each rim vertex a hue.
fn gouraud_rgb565() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (pixels, width) = gouraud_rgb565_pixels();
    (
        show(&pixels, width),
        OutputSettingsBuilder::new().scale(2).build(),
    )
}

/// The wheel of [`gouraud_rgb565`] in a 160 x 160 `Rgb565` frame, and its width.
fn gouraud_rgb565_pixels() -> (Vec<Rgb565>, u32) {
    let mut fb_pixels = vec![Rgb565::BLACK; 160 * 160];
    let mut fb = Framebuffer::new(&mut fb_pixels, 160, 160).unwrap();
    let center = Point::new(80, 80);
    let n = 24;
    let hue = |i: usize| -> Rgb565 {
        // A hue wheel from six corners, without floats: red, yellow, green, cyan, blue, magenta.
        let corners = [
            (31, 0, 0),
            (31, 63, 0),
            (0, 63, 0),
            (0, 63, 31),
            (0, 0, 31),
            (31, 0, 31),
        ];
        let (a, b) = (corners[(i * 6 / n) % 6], corners[(i * 6 / n + 1) % 6]);
        let t = (i * 6 % n) as u32;
        let mix =
            |x: u8, y: u8| ((u32::from(x) * (n as u32 - t) + u32::from(y) * t) / n as u32) as u8;
        Rgb565::new(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
    };
    let ring: Vec<Point> = (0..n)
        .map(|i| {
            let t = i as f64 / n as f64 * std::f64::consts::TAU;
            center
                + Point::new(
                    (76.0 * t.cos()).round() as i32,
                    (76.0 * t.sin()).round() as i32,
                )
        })
        .collect();
    for i in 0..n {
        let j = (i + 1) % n;
        Triangle::new(center, ring[i], ring[j])
            .into_styled(GouraudStyle::new([Rgb565::WHITE, hue(i), hue(j)]))
            .draw(&mut fb)
            .unwrap();
    }
    (fb_pixels, 160)
}

/// A night-sky gradient over few `Rgb565` levels: rounding shows bands, dithering hides them.
fn dither_rgb565() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (w, h) = (120, 72);
    let mut pixels = vec![Rgb565::BLACK; w * h];
    let mut fb = Framebuffer::new(&mut pixels, w as u32, h as u32).unwrap();
    let (top, bottom) = (Rgb565::new(1, 4, 6), Rgb565::new(6, 22, 14));
    let half = w as i32 / 2;
    for (x0, dither) in [(0, false), (half + 1, true)] {
        let (x1, y1) = (x0 + half - 1, h as i32);
        let p = Point::new;
        for (t, colors) in [
            (
                Triangle::new(p(x0, 0), p(x1, 0), p(x0, y1)),
                [top, top, bottom],
            ),
            (
                Triangle::new(p(x1, 0), p(x1, y1), p(x0, y1)),
                [top, bottom, bottom],
            ),
        ] {
            t.into_styled(GouraudStyle::new(colors).with_dither(dither))
                .draw(&mut fb)
                .unwrap();
        }
    }
    (
        show(&pixels, w as u32),
        OutputSettingsBuilder::new().scale(4).build(),
    )
}

/// A Gouraud wheel under a translucent HUD panel and a translucent fan (a gauge's sweep):
/// `Framebuffer::translucent` blends each triangle over what is there, and the fan's shared
/// edges are blended once, so no seams darken.
fn translucent() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (background, _) = gouraud_rgb565_pixels();
    let mut pixels = background;
    let mut fb = Framebuffer::new(&mut pixels, 160, 160).unwrap();
    let p = Point::new;
    // The panel: two triangles, black at 60%.
    let mut panel = fb.translucent(153);
    for t in [
        Triangle::new(p(8, 112), p(152, 112), p(152, 152)),
        Triangle::new(p(8, 112), p(152, 152), p(8, 152)),
    ] {
        t.into_styled(FlatStyle::new(Rgb565::BLACK))
            .draw(&mut panel)
            .unwrap();
    }
    // The fan: 12 sectors from the centre, alternating white and yellow at 40%.
    let mut fan = fb.translucent(102);
    let center = p(80, 80);
    let rim: Vec<Point> = (0..=12)
        .map(|i| {
            let t = std::f64::consts::PI * (0.75 + 1.5 * f64::from(i) / 12.0);
            center
                + p(
                    (70.0 * t.cos()).round() as i32,
                    (70.0 * t.sin()).round() as i32,
                )
        })
        .collect();
    for i in 0..12 {
        let color = if i % 2 == 0 {
            Rgb565::WHITE
        } else {
            Rgb565::YELLOW
        };
        Triangle::new(center, rim[i], rim[i + 1])
            .into_styled(FlatStyle::new(color))
            .draw(&mut fan)
            .unwrap();
    }
    (
        show(&pixels, 160),
        OutputSettingsBuilder::new().scale(2).build(),
    )
}

/// One fade from black to white, rendered in four colour depths.
fn gouraud_gray() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (w, h) = (64, 96);
    let mut display = SimulatorDisplay::new(Size::new(4 * w + 12, h));
    let p = Point::new;
    let tri = |x0: i32| {
        [
            Triangle::new(p(x0, 0), p(x0 + w as i32, 0), p(x0, h as i32)),
            Triangle::new(
                p(x0 + w as i32, 0),
                p(x0 + w as i32, h as i32),
                p(x0, h as i32),
            ),
        ]
    };
    let blit = |display: &mut SimulatorDisplay<Rgb888>, x0: i32, luma: &dyn Fn(Point) -> u8| {
        for y in 0..h as i32 {
            for x in x0..x0 + w as i32 {
                let l = luma(p(x, y));
                Pixel(p(x, y), Rgb888::new(l, l, l)).draw(display).unwrap();
            }
        }
    };
    for (panel, depth) in [(0, 8u8), (1, 4), (2, 2), (3, 1)] {
        let x0 = panel * (w as i32 + 4);
        let mut g8 = SimulatorDisplay::<Gray8>::new(Size::new(4 * w + 12, h));
        let mut g4 = SimulatorDisplay::<Gray4>::new(Size::new(4 * w + 12, h));
        let mut g2 = SimulatorDisplay::<Gray2>::new(Size::new(4 * w + 12, h));
        let mut bin = SimulatorDisplay::<BinaryColor>::new(Size::new(4 * w + 12, h));
        for (k, t) in tri(x0).into_iter().enumerate() {
            // Dark on the left, bright on the right.
            let levels = |max: u8| if k == 0 { [0, max, 0] } else { [max, max, 0] };
            match depth {
                8 => t
                    .into_styled(GouraudStyle::new(levels(255).map(Gray8::new)))
                    .draw(&mut g8)
                    .unwrap(),
                4 => t
                    .into_styled(GouraudStyle::new(levels(15).map(Gray4::new)))
                    .draw(&mut g4)
                    .unwrap(),
                2 => t
                    .into_styled(GouraudStyle::new(levels(3).map(Gray2::new)))
                    .draw(&mut g2)
                    .unwrap(),
                _ => {
                    let on = levels(1).map(|v| {
                        if v == 1 {
                            BinaryColor::On
                        } else {
                            BinaryColor::Off
                        }
                    });
                    t.into_styled(GouraudStyle::new(on).with_dither(true))
                        .draw(&mut bin)
                        .unwrap()
                }
            }
        }
        match depth {
            8 => blit(&mut display, x0, &|q| g8.get_pixel(q).luma()),
            4 => blit(&mut display, x0, &|q| g4.get_pixel(q).luma() * 17),
            2 => blit(&mut display, x0, &|q| g2.get_pixel(q).luma() * 85),
            _ => blit(&mut display, x0, &|q| {
                if bin.get_pixel(q).is_on() { 255 } else { 0 }
            }),
        }
    }
    (display, OutputSettingsBuilder::new().scale(2).build())
}

/// A shader with two attributes: light intensity per vertex, and texture-like coordinates for a
/// procedural checkerboard.
fn shader() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let mut display = SimulatorDisplay::new(Size::new(160, 120));
    let f = |v: f64| I16F16::from_num(v);
    let attributes = [
        [f(1.0), f(0.0), f(0.0)],
        [f(0.3), f(8.0), f(0.0)],
        [f(0.6), f(0.0), f(6.0)],
    ];
    let style = ShaderStyle::new(attributes, |frag: Fragment<3>| {
        let [light, u, v] = frag.values;
        let check = (u.to_num::<i32>() + v.to_num::<i32>()) & 1 == 0;
        let base: u8 = if check { 230 } else { 90 };
        let level = (light * I16F16::from_num(base)).to_num::<u8>();
        Rgb888::new(level, level / 2 + 20, 255 - level)
    });
    Triangle::new(Point::new(10, 8), Point::new(150, 30), Point::new(40, 112))
        .into_styled(style)
        .draw(&mut display)
        .unwrap();
    (display, OutputSettingsBuilder::new().scale(2).build())
}

/// Copies an `Rgb565` framebuffer's pixels into a simulator display.
fn blit_565(pixels: &[Rgb565], width: u32, display: &mut SimulatorDisplay<Rgb888>) {
    for (i, c) in pixels.iter().enumerate() {
        let p = Point::new((i as u32 % width) as i32, (i as u32 / width) as i32);
        Pixel(p, to_888(*c)).draw(display).unwrap();
    }
}

/// Draws the quad `corners` (clockwise from the texture's top left) as two triangles.
fn textured_quad<D, T>(display: &mut D, corners: [Point; 4], style: TextureStyle<T>)
where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
    T: trirast::texture::TexelSource<Color = Rgb565> + Copy,
{
    let side = I16F16::from_num(64);
    let uv = [
        [I16F16::ZERO, I16F16::ZERO],
        [side, I16F16::ZERO],
        [side, side],
        [I16F16::ZERO, side],
    ];
    for [a, b, c] in [[0, 1, 2], [0, 2, 3]] {
        let mut face = style;
        face.coordinates = [uv[a], uv[b], uv[c]];
        if let Some(light) = style.modulation {
            face.modulation = Some([light[a.min(2)], light[b.min(2)], light[c.min(2)]]);
        }
        Triangle::new(corners[a], corners[b], corners[c])
            .into_styled(face)
            .draw(display)
            .unwrap();
    }
}

/// The crate texture read straight from the BMP file's bytes through `tinybmp` (no copy),
/// magnified about 3.4x on a slightly rotated square, with each filter.
fn texture_filters() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let bmp = Bmp::<Rgb565>::from_slice(CRATE_BMP).expect("a valid BMP");
    let texture = ImageTexels::new(&bmp).expect("a non-empty image");
    let (w, h) = (460u32, 230u32);
    let mut pixels = vec![Rgb565::new(4, 8, 6); (w * h) as usize];
    let mut fb = Framebuffer::new(&mut pixels, w, h).unwrap();
    for (x0, filter) in [(8, Filter::Nearest), (238, Filter::Bilinear)] {
        let p = |x: i32, y: i32| Point::new(x0 + x, 4 + y);
        let corners = [p(30, 0), p(214, 30), p(184, 214), p(0, 184)];
        let style = TextureStyle::new(texture, [[I16F16::ZERO; 2]; 3]).with_filter(filter);
        textured_quad(&mut fb, corners, style);
    }
    let mut display = SimulatorDisplay::new(Size::new(w, h));
    blit_565(&pixels, w, &mut display);
    (display, OutputSettingsBuilder::new().scale(2).build())
}

/// An isometric cube whose three visible faces carry the crate texture, decoded once into an
/// `Rgb565` slice (the fast source), filtered bilinearly and lit per vertex by modulation.
fn textured_cube() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let bmp = Bmp::<Rgb565>::from_slice(CRATE_BMP).expect("a valid BMP");
    let texels: Vec<Rgb565> = bmp.pixels().map(|Pixel(_, c)| c).collect();
    let texture = Texels::new(&texels, 64, 64).unwrap();
    let (w, h) = (240u32, 240u32);
    let mut pixels = vec![Rgb565::new(2, 6, 10); (w * h) as usize];
    let mut fb = Framebuffer::new(&mut pixels, w, h).unwrap();
    let p = Point::new;
    // Isometric corners: top vertex, and the hexagon around the centre.
    let (c, top, left, right) = (p(120, 124), p(120, 20), p(30, 72), p(210, 72));
    let (bottom, low_left, low_right) = (p(120, 228), p(30, 176), p(210, 176));
    let gray = |l: u8| Rgb565::new(l >> 3, l >> 2, l >> 3);
    let faces = [
        // Top face: bright, a little darker towards the back.
        ([left, top, right, c], [gray(200), gray(255), gray(230)]),
        // Left face: medium light, fading downwards.
        (
            [left, c, bottom, low_left],
            [gray(190), gray(170), gray(110)],
        ),
        // Right face: in shadow.
        (
            [c, right, low_right, bottom],
            [gray(120), gray(100), gray(60)],
        ),
    ];
    for (corners, light) in faces {
        let style = TextureStyle::new(texture, [[I16F16::ZERO; 2]; 3])
            .with_filter(Filter::Bilinear)
            .with_modulation(light);
        textured_quad(&mut fb, corners, style);
    }
    let mut display = SimulatorDisplay::new(Size::new(w, h));
    blit_565(&pixels, w, &mut display);
    (display, OutputSettingsBuilder::new().scale(2).build())
}

/// The OLED scene of `examples/ssd0323.rs` at 4x, as QEMU magnifies its SSD0323 display
/// (`examples/ssd0323.sh` checks that QEMU shows exactly these pixels).
fn ssd0323_oled() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let mut display = SimulatorDisplay::new(Size::new(ssd0323::WIDTH, ssd0323::HEIGHT));
    for (i, color) in ssd0323::render().into_iter().enumerate() {
        let (x, y) = (i as u32 % ssd0323::WIDTH, i as u32 / ssd0323::WIDTH);
        Pixel(Point::new(x as i32, y as i32), Rgb888::from(color))
            .draw(&mut display)
            .unwrap();
    }
    (display, OutputSettingsBuilder::new().scale(4).build())
}

/// The spinning cube of `examples/cube.rs`, one frame, beside its depth buffer.
fn depth_cube() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (w, h) = (200u32, 160u32);
    let mut pixels = vec![Rgb565::BLACK; (w * h) as usize];
    let mut depths = vec![0; (w * h) as usize];
    cube::render(&cube::texels(), &mut pixels, &mut depths, (w, h), (5, 24));
    let mut display = SimulatorDisplay::new(Size::new(2 * w + 8, h));
    blit_565(&pixels, w, &mut display);
    // Depths as gray: near is bright; the cleared background stays black.
    let (near, far) = depths
        .iter()
        .filter(|&&d| d != u16::MAX)
        .fold((u16::MAX, 0), |(lo, hi), &d| (lo.min(d), hi.max(d)));
    for (i, &d) in depths.iter().enumerate() {
        let level = if d == u16::MAX {
            0
        } else {
            255 - (u32::from(d - near) * 200 / u32::from((far - near).max(1))) as u8
        };
        let p = Point::new(
            (w + 8) as i32 + (i as u32 % w) as i32,
            (i as u32 / w) as i32,
        );
        Pixel(p, Rgb888::new(level, level, level))
            .draw(&mut display)
            .unwrap();
    }
    (display, OutputSettingsBuilder::new().scale(2).build())
}

/// The 200-triangle benchmark scene as a display list, mixing Gouraud, textured and flat
/// triangles through a depth band, handed to the simulator display one 16-row band at a time
/// (through `color_converted`, as to any display driver). The strip on the right marks the
/// bands as the display received them.
fn band_frame() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    const ROWS: u32 = 16;
    let (w, h) = (scenes::WIDTH, scenes::HEIGHT);
    let bmp = Bmp::<Rgb565>::from_slice(CRATE_BMP).expect("a valid BMP");
    let texels: Vec<Rgb565> = bmp.pixels().map(|Pixel(_, c)| c).collect();
    let texture = Texels::new(&texels, 64, 64).unwrap();
    let screen = Rectangle::new(Point::zero(), Size::new(w, h));
    let mut scene: Box<BandScene<Rgb565, 256>> = Box::new(BandScene::new(screen));
    let mut k = 0u16;
    scenes::Scene::Scene200.for_each(|t| {
        let [a, b, c] = t.vertices;
        let triangle = Triangle::new(a, b, c);
        // Depths spread per triangle so that they interpenetrate.
        let depth = |i: u16| 1000 + (k.wrapping_mul(7919).wrapping_add(i * 12_345)) % 60_000;
        let depths = [depth(0), depth(1), depth(2)];
        let style = match k % 4 {
            0 => SceneStyle::Texture(
                TextureStyle::from_points(texture, [p(0, 0), p(63, 0), p(0, 63)])
                    .with_filter(Filter::Bilinear),
            ),
            1 => SceneStyle::Flat(FlatStyle::new(t.color)),
            _ => SceneStyle::Gouraud(GouraudStyle::new(t.vertex_colors)),
        };
        scene.push_with_depth(triangle, depths, style).unwrap();
        k += 1;
    });
    let mut band = vec![Rgb565::BLACK; (w * ROWS) as usize];
    let mut depth_band = vec![0u16; (w * ROWS) as usize];
    let mut bands = Bands::new(&mut band, w, ROWS)
        .and_then(|b| b.with_depth(&mut depth_band))
        .unwrap();
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(w + 6, h));
    let mut received = BandLog {
        display: &mut display,
        bands: Vec::new(),
    };
    bands
        .render(
            &scene,
            Rgb565::new(2, 5, 9),
            &mut received.color_converted(),
        )
        .unwrap();
    let log = received.bands;
    for (i, area) in log.iter().enumerate() {
        let color = if i % 2 == 0 {
            Rgb888::CSS_ORANGE
        } else {
            Rgb888::CSS_STEEL_BLUE
        };
        Rectangle::new(
            Point::new(w as i32 + 2, area.top_left.y),
            Size::new(4, area.size.height),
        )
        .into_styled(PrimitiveStyle::with_fill(color))
        .draw(&mut display)
        .unwrap();
    }
    (display, OutputSettingsBuilder::new().scale(2).build())
}

fn p(x: i32, y: i32) -> Point {
    Point::new(x, y)
}

/// A display that logs the area of each `fill_contiguous` call it receives.
struct BandLog<'a> {
    display: &'a mut SimulatorDisplay<Rgb888>,
    bands: Vec<Rectangle>,
}

impl OriginDimensions for BandLog<'_> {
    fn size(&self) -> Size {
        Size::new(scenes::WIDTH, scenes::HEIGHT)
    }
}

impl DrawTarget for BandLog<'_> {
    type Color = Rgb888;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb888>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        self.display.draw_iter(pixels)
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb888>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        self.bands.push(*area);
        self.display.fill_contiguous(area, colors)
    }
}

/// Counts writes per pixel while drawing a mesh, then shows the counts as colours:
/// black = never (a gap), grey = once, red = twice or more.
fn overdraw() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (w, h) = (120u32, 90u32);
    let mut tris: Vec<[Point; 3]> = Vec::new();
    scenes::mesh(12, 9, |t| tris.push(t.vertices));
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

/// A frame of the Breakout example, mid-game: every rectangle is two Gouraud triangles.
fn breakout_frame() -> (SimulatorDisplay<Rgb888>, OutputSettings) {
    let (w, h) = (breakout::WIDTH as u32, breakout::HEIGHT as u32);
    let mut game = breakout::Game::new();
    for _ in 0..3_000 {
        game.play(breakout::Command::Auto);
    }
    let mut pixels = vec![Rgb565::BLACK; (w * h) as usize];
    let mut fb = Framebuffer::new(&mut pixels, w, h).unwrap();
    game.draw(&mut fb).unwrap();
    let mut display = SimulatorDisplay::new(Size::new(w, h));
    blit_565(&pixels, w, &mut display);
    (display, OutputSettingsBuilder::new().scale(2).build())
}
