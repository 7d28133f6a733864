//! Translucent drawing: every covered pixel is the exact blend of the drawn colour over what
//! was there (within 3/5 of a level per channel: `Rgb565` blends in 256ths), blended once, and nothing else changes;
//! opacity 255 draws what opaque drawing draws.

use crate::common;

use common::{Recorder, Rng, Rule, jittered_grid, reference_covers};
use embedded_graphics::{
    pixelcolor::{Gray8, Rgb565},
    prelude::*,
    primitives::Rectangle,
};
use proptest::prelude::*;
use trirast::{
    FlatStyle, Framebuffer, GouraudStyle, Triangle,
    depth::{DepthBuffer, DepthTarget},
    shading::ChannelColor,
    target::OverBackground,
};

const W: u32 = 40;
const H: u32 = 30;

/// True when each channel of `got` is within 3/5 of a level of the exact blend of `source`
/// over `under` at `opacity`: `|got - (s a + d (255 - a)) / 255| <= 3/5` (the documented
/// bound for channels of up to 6 bits).
fn exact_blend(got: Rgb565, source: Rgb565, under: Rgb565, opacity: u8) -> bool {
    let (a, b) = (i64::from(opacity), 255 - i64::from(opacity));
    let (g, s, d) = (got.channels(), source.channels(), under.channels());
    (0..3).all(|k| {
        let numerator = i64::from(s[k]) * a + i64::from(d[k]) * b;
        // |g - n / 255| <= 3/5  <=>  |1275 g - 5 n| <= 765
        (1275 * i64::from(g[k]) - 5 * numerator).abs() <= 765
    })
}

fn color(rng: &mut Rng) -> Rgb565 {
    Rgb565::new(
        rng.range(0, 31) as u8,
        rng.range(0, 63) as u8,
        rng.range(0, 31) as u8,
    )
}

fn point(rng: &mut Rng, reach: i32) -> Point {
    Point::new(
        rng.range(-reach, W as i32 + reach),
        rng.range(-reach, H as i32 + reach),
    )
}

fn frame_points() -> impl Iterator<Item = Point> {
    (0..H as i32).flat_map(|y| (0..W as i32).map(move |x| Point::new(x, y)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// A flat triangle drawn translucently over a frame of random pixels: covered pixels are
    /// the exact blend over their old colour, the rest unchanged.
    #[test]
    fn covered_pixels_blend_over_what_was_there(seed in any::<u64>()) {
        let mut rng = Rng(seed);
        let under: Vec<Rgb565> = (0..W * H).map(|_| color(&mut rng)).collect();
        let mut pixels = under.clone();
        let reach = [2, 20, 5000][rng.range(0, 2) as usize];
        let v = [(); 3].map(|()| point(&mut rng, reach));
        let source = color(&mut rng);
        let opacity = rng.range(0, 255) as u8;
        let mut frame = Framebuffer::new(&mut pixels, W, H).unwrap();
        Triangle { vertices: v }
            .into_styled(FlatStyle::new(source))
            .draw(&mut frame.translucent(opacity))
            .unwrap();
        for (i, p) in frame_points().enumerate() {
            if reference_covers(v, p, Rule::TopLeft) {
                prop_assert!(exact_blend(pixels[i], source, under[i], opacity), "{:?} at {:?}", v, p);
            } else {
                prop_assert_eq!(pixels[i], under[i], "{:?} at {:?}", v, p);
            }
        }
    }

    /// A translucent mesh blends each pixel once: its owner's colour over the background.
    #[test]
    fn a_translucent_mesh_blends_each_pixel_once(seed in any::<u64>(), nx in 2..8i32, ny in 2..6i32) {
        let mut rng = Rng(seed);
        let background = color(&mut rng);
        let opacity = rng.range(1, 254) as u8;
        let frame = Rectangle::new(Point::zero(), Size::new(W, H));
        let triangles = jittered_grid(frame, nx, ny, &mut rng);
        let colors: Vec<Rgb565> = triangles.iter().map(|_| color(&mut rng)).collect();
        let mut pixels = vec![background; (W * H) as usize];
        let mut frame = Framebuffer::new(&mut pixels, W, H).unwrap();
        let mut translucent = frame.translucent(opacity);
        for (v, &c) in triangles.iter().zip(&colors) {
            Triangle { vertices: *v }.into_styled(FlatStyle::new(c)).draw(&mut translucent).unwrap();
        }
        for (i, p) in frame_points().enumerate() {
            let owners: Vec<usize> = (0..triangles.len())
                .filter(|&k| reference_covers(triangles[k], p, Rule::TopLeft))
                .collect();
            match owners[..] {
                [] => prop_assert_eq!(pixels[i], background, "{:?}", p),
                [k] => prop_assert!(exact_blend(pixels[i], colors[k], background, opacity), "{:?}", p),
                _ => prop_assert!(false, "the reference gives {:?} owners {:?}", p, owners),
            }
        }
    }

    /// Over a known background, straight to a target that is never read: the same blend,
    /// each pixel written once.
    #[test]
    fn over_a_background_blends_without_reading(seed in any::<u64>()) {
        let mut rng = Rng(seed);
        let window = Rectangle::new(Point::new(-3, 2), Size::new(W, H));
        let v = [(); 3].map(|()| point(&mut rng, 10));
        let (source, background) = (color(&mut rng), color(&mut rng));
        let opacity = rng.range(0, 255) as u8;
        let mut display = Recorder::<Rgb565>::new(window);
        Triangle { vertices: v }
            .into_styled(FlatStyle::new(source))
            .draw(&mut OverBackground::new(&mut display, background, opacity))
            .unwrap();
        for p in common::window_points(&window) {
            if reference_covers(v, p, Rule::TopLeft) {
                let got = display.get(p);
                prop_assert!(got.is_some_and(|c| exact_blend(c, source, background, opacity)), "{:?}", p);
                prop_assert_eq!(display.writes_at(p), 1);
            } else {
                prop_assert_eq!(display.writes_at(p), 0);
            }
        }
    }

    /// Opacity 255 draws exactly what opaque drawing draws, for shaded styles too.
    #[test]
    fn full_opacity_is_opaque(seed in any::<u64>()) {
        let mut rng = Rng(seed);
        let v = [(); 3].map(|()| point(&mut rng, 30));
        let style = GouraudStyle::new([color(&mut rng), color(&mut rng), color(&mut rng)])
            .with_dither(rng.range(0, 1) == 1);
        let background = color(&mut rng);
        let mut opaque = vec![background; (W * H) as usize];
        let mut blended = opaque.clone();
        Triangle { vertices: v }
            .into_styled(style)
            .draw(&mut Framebuffer::new(&mut opaque, W, H).unwrap())
            .unwrap();
        Triangle { vertices: v }
            .into_styled(style)
            .draw(&mut Framebuffer::new(&mut blended, W, H).unwrap().translucent(255))
            .unwrap();
        prop_assert_eq!(opaque, blended);
    }
}

/// Translucency composes with the depth test: hidden pixels are not blended.
#[test]
fn depth_tested_translucent_drawing() {
    let mut pixels = [Gray8::new(100); 8 * 8];
    let mut depths = [u16::MAX; 8 * 8];
    let mut frame = Framebuffer::new(&mut pixels, 8, 8).unwrap();
    let mut zbuffer = DepthBuffer::new(&mut depths, 8, 8).unwrap();
    let square = [
        Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(8, 8)),
        Triangle::new(Point::new(0, 0), Point::new(8, 8), Point::new(0, 8)),
    ];
    // A near opaque floor on the left half, then a translucent far square over everything.
    let left = Triangle::new(Point::new(0, 0), Point::new(4, 0), Point::new(0, 16));
    {
        let mut scene = DepthTarget::new(&mut frame, &mut zbuffer).unwrap();
        scene
            .draw(&left, [10; 3], &FlatStyle::new(Gray8::new(0)))
            .unwrap();
    }
    let mut translucent = frame.translucent(128);
    let mut scene = DepthTarget::new(&mut translucent, &mut zbuffer).unwrap();
    for t in &square {
        scene
            .draw(t, [1000; 3], &FlatStyle::new(Gray8::new(200)))
            .unwrap();
    }
    // Hidden behind the floor: still black. Elsewhere: 200 over 100 at 128/255.
    assert_eq!(frame.pixel(Point::new(0, 1)), Some(Gray8::new(0)));
    assert_eq!(frame.pixel(Point::new(7, 1)), Some(Gray8::new(150)));
}
