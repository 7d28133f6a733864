//! Renders FRAMES frames of a seeded scene into the crate's 320x240 `Rgb565` framebuffer, for
//! instruction counting (see `benches/compare.sh`) or timing.
//!
//! ```text
//! cargo run --release --example perf -- MODE SCENE FRAMES
//! ```
//!
//! MODE: `flat`, `gouraud`, `gouraud-z` and `flat-z` (through a 16-bit depth buffer cleared
//! each frame; each triangle nearer than the ones before, so every pixel passes), `band` (the
//! `gouraud-z` frame as a band-rendered scene: triangles pushed to a `band::Scene` each frame,
//! rendered in 16-row bands with a depth band, each band copied to the framebuffer with one
//! `fill_contiguous`; same image as `gouraud-z`), `band-cache` (the same keeping each
//! triangle's set-up between bands, `Bands::with_setup_cache`), `tex-nearest`, `tex-bilinear` (a 64x64 `Rgb565` texture stretched
//! over each triangle's bounding box, clamped), `tex-modulated` (the same, bilinear, times
//! Gouraud colours), `tex-nearest-repeat`, `tex-bilinear-repeat` (the texture tiled across
//! the screen, rotated: repeat by masking), `tex-nearest-clamp` (tiled coordinates, clamped),
//! `tex-nearest-odd` (a 63x63 texture tiled: repeat by modulo), `tex-nearest-persp`,
//! `tex-bilinear-persp`, `tex-modulated-persp` (perspective-correct, `w` from 1 to 4 down the
//! screen) (this crate), `eg-flat` (embedded-graphics' own `Triangle`, same
//! scene and framebuffer), `fill-baseline` (the flat spans, precomputed, filled by
//! `slice::fill`: no covering at all), `coverage` (edge walking alone, nothing drawn).
//! SCENE: `big`, `small`, `mesh`, `scene200` (200 overlapping triangles of up to a few thousand
//! pixels). The last line printed is
//! `pixels=<pixels drawn> triangles=<triangles drawn>` over all frames; the line before it gives
//! overdraw and gaps of one frame. Counting runs once, outside the timed frames, so instruction
//! counts are best taken as the difference between two FRAMES values.

#[path = "common/counting.rs"]
mod counting;
#[path = "common/modes.rs"]
mod modes;
#[path = "common/scenes.rs"]
mod scenes;

use std::{process::ExitCode, time::Instant};

use counting::Counting;
use embedded_graphics::{
    pixelcolor::Rgb565,
    prelude::*,
    primitives::{PrimitiveStyle, Rectangle, Triangle as EgTriangle},
};
use fixed::types::I16F16;
use modes::DisplayList;
use scenes::{HEIGHT, Scene, SceneTriangle, WIDTH};
use trirast::{
    FillRule, FlatStyle, Framebuffer, GouraudStyle, TextureStyle, Triangle,
    band::{Bands, SceneStyle, SetupCache, SetupSlot},
    coverage::{Span, for_each_span},
    depth::{DepthBuffer, DepthTarget},
    texture::{Filter, Perspective, Texels, Wrap},
};

const MODES: &[&str] = &[
    "flat",
    "gouraud",
    "flat-sub",
    "gouraud-sub",
    "gouraud-z",
    "flat-z",
    "band",
    "band-cache",
    "tex-nearest",
    "tex-bilinear",
    "tex-modulated",
    "tex-nearest-repeat",
    "tex-bilinear-repeat",
    "tex-nearest-clamp",
    "tex-nearest-odd",
    "tex-nearest-persp",
    "tex-bilinear-persp",
    "tex-modulated-persp",
    "eg-flat",
    "fill-baseline",
    "coverage",
];

/// Texture coordinates for a screen position, tiling the screen: rotated and scaled by 3/4
/// (magnified).
fn tiled_coordinates(p: Point) -> [I16F16; 2] {
    [
        I16F16::from_bits((p.x * 3 + p.y) << 14),
        I16F16::from_bits((p.y * 3 - p.x) << 14),
    ]
}

/// The spans of a frame, computed once, for the `fill-baseline` mode: what the flat fill costs
/// if covering were free and each span were a bare `slice::fill`.
fn frame_spans(scene: &[SceneTriangle]) -> Vec<(Span, Rgb565)> {
    let screen = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
    let mut spans = Vec::new();
    for t in scene {
        let [a, b, c] = t.vertices;
        for_each_span(&Triangle::new(a, b, c), FillRule::TopLeft, &screen, |s| {
            spans.push((s, t.color));
            Ok::<(), ()>(())
        })
        .unwrap();
    }
    spans
}

#[inline(never)]
fn coverage_frame(scene: &[SceneTriangle]) -> u64 {
    let screen = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
    let mut sum = 0u64;
    for t in scene {
        let [a, b, c] = t.vertices;
        for_each_span(&Triangle::new(a, b, c), FillRule::TopLeft, &screen, |s| {
            sum += u64::from(s.len);
            Ok::<(), ()>(())
        })
        .unwrap();
    }
    sum
}

fn fill_baseline(spans: &[(Span, Rgb565)], pixels: &mut [Rgb565]) {
    for &(s, color) in spans {
        let start = s.y as usize * WIDTH as usize + s.x as usize;
        pixels[start..start + s.len as usize].fill(color);
    }
}

/// Draws one frame in `mode`. Each mode is its own non-inlined function so that its code
/// (and so its instruction count) does not depend on what the other modes do.
fn draw_frame<D>(mode: &str, scene: &[SceneTriangle], texels: &[Rgb565], target: &mut D)
where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
{
    match mode {
        "flat" => flat_frame(scene, target),
        "gouraud" => gouraud_frame(scene, target),
        "flat-sub" => flat_subpixel_frame(scene, target),
        "gouraud-sub" => gouraud_subpixel_frame(scene, target),
        "eg-flat" => eg_flat_frame(scene, target),
        "gouraud-z" | "flat-z" => {
            let size = target.bounding_box().size;
            let mut depths = vec![0u16; (size.width * size.height) as usize];
            let mut zbuffer = DepthBuffer::new(&mut depths, size.width, size.height).unwrap();
            depth_frame(scene, mode == "gouraud-z", &mut zbuffer, target);
        }
        "band" | "band-cache" => BAND_MEMORY.with_borrow_mut(|memory| {
            // Allocated once: a 5,000-triangle scene is half a megabyte, which a frame
            // should not pay to allocate and clear.
            let (list, band, depth_band, setups) = memory.get_or_insert_with(|| {
                let width = WIDTH as usize * BAND_ROWS as usize;
                let screen = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
                (
                    Box::new(DisplayList::new(screen)),
                    vec![Rgb565::BLACK; width],
                    vec![0u16; width],
                    (0..BAND_CAPACITY).map(|_| SetupSlot::EMPTY).collect(),
                )
            });
            let bands = Bands::new(band, WIDTH, BAND_ROWS)
                .and_then(|b| b.with_depth(depth_band))
                .unwrap();
            if mode == "band" {
                band_frame(scene, list, bands, target);
            } else {
                band_frame(scene, list, bands.with_setup_cache(setups), target);
            }
        }),
        "fill-baseline" | "coverage" => {
            // Only for counting: the timed loop fills precomputed spans directly.
            for (span, color) in frame_spans(scene) {
                target.fill_solid(&span.rectangle(), color).unwrap();
            }
        }
        _ => {
            let kind = mode.strip_prefix("tex-").expect("mode checked in main");
            let (filter, wrap, side, tiled) = match kind {
                "nearest" | "nearest-persp" => (Filter::Nearest, Wrap::Clamp, 64, false),
                "bilinear" | "modulated" | "bilinear-persp" | "modulated-persp" => {
                    (Filter::Bilinear, Wrap::Clamp, 64, false)
                }
                "nearest-repeat" => (Filter::Nearest, Wrap::Repeat, 64, true),
                "bilinear-repeat" => (Filter::Bilinear, Wrap::Repeat, 64, true),
                "nearest-clamp" => (Filter::Nearest, Wrap::Clamp, 64, true),
                "nearest-odd" => (Filter::Nearest, Wrap::Repeat, 63, true),
                _ => unreachable!("mode checked in main"),
            };
            let texture = Texels::new(&texels[..(side * side) as usize], side, side).unwrap();
            let modulated = kind.starts_with("modulated");
            let perspective = kind.ends_with("-persp");
            let options = (filter, wrap, tiled, modulated, perspective);
            texture_frame(scene, texture, options, target);
        }
    }
}

#[inline(never)]
fn flat_frame<D>(scene: &[SceneTriangle], target: &mut D)
where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
{
    for t in scene {
        let [a, b, c] = t.vertices;
        Triangle::new(a, b, c)
            .into_styled(FlatStyle::new(t.color))
            .draw(target)
            .unwrap();
    }
}

#[inline(never)]
fn gouraud_frame<D>(scene: &[SceneTriangle], target: &mut D)
where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
{
    for t in scene {
        let [a, b, c] = t.vertices;
        Triangle::new(a, b, c)
            .into_styled(GouraudStyle::new(t.vertex_colors))
            .draw(target)
            .unwrap();
    }
}

/// `flat` at the scene's sub-pixel vertices (as the firmware's `flat-sub`).
#[inline(never)]
fn flat_subpixel_frame<D>(scene: &[SceneTriangle], target: &mut D)
where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
{
    for t in scene {
        modes::subpixel_triangle(t)
            .into_styled(FlatStyle::new(t.color))
            .draw(target)
            .unwrap();
    }
}

/// `gouraud` at the scene's sub-pixel vertices (as the firmware's `gouraud-sub`).
#[inline(never)]
fn gouraud_subpixel_frame<D>(scene: &[SceneTriangle], target: &mut D)
where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
{
    for t in scene {
        modes::subpixel_triangle(t)
            .into_styled(GouraudStyle::new(t.vertex_colors))
            .draw(target)
            .unwrap();
    }
}

/// Draws through a depth buffer, cleared first; each triangle is nearer than those before it.
#[inline(never)]
fn depth_frame<D>(scene: &[SceneTriangle], gouraud: bool, zbuffer: &mut DepthBuffer, target: &mut D)
where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
{
    zbuffer.clear(u16::MAX);
    let mut layered = DepthTarget::new(target, zbuffer).unwrap();
    for (k, t) in scene.iter().enumerate() {
        let [a, b, c] = t.vertices;
        let depths = modes::layered_depths(k, scene.len());
        let triangle = Triangle::new(a, b, c);
        if gouraud {
            layered
                .draw(&triangle, depths, &GouraudStyle::new(t.vertex_colors))
                .unwrap();
        } else {
            layered
                .draw(&triangle, depths, &FlatStyle::new(t.color))
                .unwrap();
        }
    }
}

/// Rows per band in the `band` mode.
const BAND_ROWS: u32 = 16;

/// Scene capacity in the `band` mode: the largest scene (`small`) fits.
const BAND_CAPACITY: usize = 5000;

/// What the `band` modes' frames share: the scene, the band, the depth band and the set-up
/// slots.
type BandMemory = (
    Box<DisplayList<BAND_CAPACITY>>,
    Vec<Rgb565>,
    Vec<u16>,
    Vec<SetupSlot>,
);

thread_local! {
    static BAND_MEMORY: std::cell::RefCell<Option<BandMemory>> = const { std::cell::RefCell::new(None) };
}

/// The `gouraud-z` frame, band-rendered: the scene is built and rendered every frame.
#[inline(never)]
fn band_frame<D, K: SetupCache>(
    scene: &[SceneTriangle],
    list: &mut DisplayList<BAND_CAPACITY>,
    mut bands: Bands<'_, Rgb565, Rgb565, K>,
    target: &mut D,
) where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
{
    list.clear();
    for (k, t) in scene.iter().enumerate() {
        let [a, b, c] = t.vertices;
        let style = SceneStyle::Gouraud(GouraudStyle::new(t.vertex_colors));
        list.push_with_depth(
            Triangle::new(a, b, c),
            modes::layered_depths(k, scene.len()),
            style,
        )
        .unwrap();
    }
    bands.render(list, Rgb565::BLACK, target).unwrap();
}

#[inline(never)]
fn eg_flat_frame<D>(scene: &[SceneTriangle], target: &mut D)
where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
{
    for t in scene {
        let [a, b, c] = t.vertices;
        EgTriangle::new(a, b, c)
            .into_styled(PrimitiveStyle::with_fill(t.color))
            .draw(target)
            .unwrap();
    }
}

#[inline(never)]
fn texture_frame<D>(
    scene: &[SceneTriangle],
    texture: Texels<'_, Rgb565>,
    (filter, wrap, tiled, modulated, perspective): (Filter, Wrap, bool, bool, bool),
    target: &mut D,
) where
    D: DrawTarget<Color = Rgb565>,
    D::Error: core::fmt::Debug,
{
    for t in scene {
        let [a, b, c] = t.vertices;
        let uv = if tiled {
            t.vertices.map(tiled_coordinates)
        } else {
            modes::coordinates(t)
        };
        let mut style = TextureStyle::new(texture, uv)
            .with_filter(filter)
            .with_wrap(wrap);
        if modulated {
            style = style.with_modulation(t.vertex_colors);
        }
        if perspective {
            // w from 1 at the top of the screen to 4 at the bottom, as the firmware's modes.
            style = style.with_perspective(Perspective::new(modes::receding_w(t.vertices)));
        }
        Triangle::new(a, b, c)
            .into_styled(style)
            .draw(target)
            .unwrap();
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = || {
        eprintln!(
            "usage: perf MODE SCENE FRAMES\n  MODE: {}\n  SCENE: big | small | mesh | scene200",
            MODES.join(" | ")
        );
        ExitCode::from(2)
    };
    let [mode, scene, frames] = args.as_slice() else {
        return usage();
    };
    let (Some(scene_kind), Ok(frames)) = (Scene::parse(scene), frames.parse::<u64>()) else {
        return usage();
    };
    if !MODES.contains(&mode.as_str()) {
        return usage();
    }
    let mut scene = Vec::new();
    scene_kind.for_each(|t| scene.push(t));
    let texels: Vec<Rgb565> = (0..64 * 64).map(|i| modes::texel(i, 64)).collect();
    let mut pixels = vec![Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
    let mut fb = Framebuffer::new(&mut pixels, WIDTH, HEIGHT).expect("buffer sized for the screen");

    // One counted frame (not part of the FRAMES loop).
    let (per_frame, overdraw, gaps) = {
        let mut counting = Counting::new(&mut fb);
        draw_frame(mode, &scene, &texels, &mut counting);
        (counting.pixels(), counting.overdraw(), counting.gaps())
    };

    let start = Instant::now();
    if mode == "fill-baseline" {
        // Spans are computed once; only the fills repeat.
        let spans = frame_spans(&scene);
        for _ in 0..frames {
            fill_baseline(std::hint::black_box(&spans), fb.pixels_mut());
        }
    } else if mode == "coverage" {
        // Edge walking alone: spans are summed, nothing is drawn.
        let mut sum = 0u64;
        for _ in 0..frames {
            sum += coverage_frame(std::hint::black_box(&scene));
        }
        std::hint::black_box(sum);
    } else {
        for _ in 0..frames {
            draw_frame(mode, std::hint::black_box(&scene), &texels, &mut fb);
        }
    }
    let elapsed = start.elapsed();
    let total = per_frame * frames;
    let secs = elapsed.as_secs_f64();
    let rate = if secs > 0.0 {
        total as f64 / secs / 1e6
    } else {
        f64::NAN
    };
    println!(
        "mode={mode} scene={} frames={frames} time={:.3}ms mpixels_per_s={rate:.1} checksum={:08x}",
        scene_kind.name(),
        secs * 1e3,
        modes::fnv1a(fb.pixels())
    );
    println!("per_frame: pixels={per_frame} overdraw={overdraw} gaps={gaps}");
    println!("pixels={total} triangles={}", scene.len() as u64 * frames);
    ExitCode::SUCCESS
}
