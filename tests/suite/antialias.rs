//! Anti-aliased coverage against the exact area of each pixel's square inside the triangle,
//! computed here by clipping the triangle to the square in exact rational arithmetic; and
//! anti-aliased drawing, which blends each pixel by that coverage.

use crate::common;

use common::{Rule, exact_plane, reference_covers};
use embedded_graphics::{prelude::*, primitives::Rectangle};
use proptest::prelude::*;
use trirast::{Triangle, coverage::for_each_coverage_run};

/// How far a coverage may be from the exact area: 1/256 (the documented bound; the worst
/// case of the arithmetic is 1/341, and 30,000 random triangles stay within 1/1024), plus
/// rounding to 1/255.
const BOUND: f64 = 1.0 / 256.0 + 0.5 / 255.0;

/// An exact rational with a positive denominator, kept reduced.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
struct Q(i128, i128);

fn gcd(mut a: i128, mut b: i128) -> i128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.abs().max(1)
}

impl Q {
    fn new(n: i128, d: i128) -> Q {
        let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
        let g = gcd(n, d);
        Q(n / g, d / g)
    }
    fn int(n: i64) -> Q {
        Q(i128::from(n), 1)
    }
    fn add(self, o: Q) -> Q {
        Q::new(self.0 * o.1 + o.0 * self.1, self.1 * o.1)
    }
    fn sub(self, o: Q) -> Q {
        Q::new(self.0 * o.1 - o.0 * self.1, self.1 * o.1)
    }
    fn mul(self, o: Q) -> Q {
        Q::new(self.0 * o.0, self.1 * o.1)
    }
    fn div(self, o: Q) -> Q {
        Q::new(self.0 * o.1, self.1 * o.0)
    }
    fn ge(self, o: Q) -> bool {
        self.0 * o.1 >= o.0 * self.1
    }
    fn to_f64(self) -> f64 {
        self.0 as f64 / self.1 as f64
    }
}

/// The exact area of pixel `p`'s square (side 1, centred on `p`) inside triangle `v`.
fn exact_coverage(v: [Point; 3], p: Point) -> f64 {
    exact_coverage_in(v.map(|q| (i64::from(q.x), i64::from(q.y))), 1, p)
}

/// [`exact_coverage`] for vertices in units of `1 / scale` pixel.
fn exact_coverage_in(v: [(i64, i64); 3], scale: i64, p: Point) -> f64 {
    // Doubled coordinates from the pixel's centre (areas do not change when moved): vertices
    // and the square's sides are small integers, so the rationals stay within i128 for
    // vertices millions of pixels out. Areas are (2 scale)^2 times the pixels'.
    let (cx, cy) = (scale * i64::from(p.x), scale * i64::from(p.y));
    let mut polygon: Vec<(Q, Q)> = v
        .iter()
        .map(|&(x, y)| (Q::int(2 * (x - cx)), Q::int(2 * (y - cy))))
        .collect();
    let (x0, x1, y0, y1) = (-scale, scale, -scale, scale);
    // Keep the side where (coordinate - bound) * sign >= 0.
    for (on_x, bound, sign) in [
        (true, x0, 1),
        (true, x1, -1),
        (false, y0, 1),
        (false, y1, -1),
    ] {
        let bound = Q::int(bound);
        let coordinate = |pt: &(Q, Q)| if on_x { pt.0 } else { pt.1 };
        let keeps = |pt: &(Q, Q)| {
            let c = coordinate(pt);
            if sign > 0 { c.ge(bound) } else { bound.ge(c) }
        };
        let mut next = Vec::new();
        for i in 0..polygon.len() {
            let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
            if keeps(&a) {
                next.push(a);
            }
            if keeps(&a) != keeps(&b) {
                let t = bound
                    .sub(coordinate(&a))
                    .div(coordinate(&b).sub(coordinate(&a)));
                let along = |s: Q, e: Q| s.add(t.mul(e.sub(s)));
                next.push((along(a.0, b.0), along(a.1, b.1)));
            }
        }
        polygon = next;
        if polygon.is_empty() {
            return 0.0;
        }
    }
    let mut twice_area = Q::int(0);
    for i in 0..polygon.len() {
        let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
        twice_area = twice_area.add(a.0.mul(b.1).sub(b.0.mul(a.1)));
    }
    // Twice the area in doubled coordinates: 8 scale^2 times the area in pixels.
    (twice_area.to_f64() / (8 * scale * scale) as f64).abs()
}

/// Coverage (0 to 255) of every pixel of `clip`, row-major, checking that each is emitted at
/// most once and inside the clip.
fn coverages(v: [Point; 3], clip: Rectangle) -> Vec<u8> {
    let (w, h) = (clip.size.width as i32, clip.size.height as i32);
    let mut out = vec![0u8; (w * h) as usize];
    let mut seen = vec![false; (w * h) as usize];
    let triangle = Triangle::new(v[0], v[1], v[2]);
    for_each_coverage_run(&triangle, &clip, |span, coverage| {
        assert!(span.len >= 1 && coverage >= 1);
        for k in 0..span.len as i32 {
            let (x, y) = (span.x + k - clip.top_left.x, span.y - clip.top_left.y);
            assert!(
                x >= 0 && x < w && y >= 0 && y < h,
                "{span:?} outside {clip:?}"
            );
            let i = (y * w + x) as usize;
            assert!(!seen[i], "pixel ({}, {}) twice", span.x + k, span.y);
            seen[i] = true;
            out[i] = coverage;
        }
        Ok::<(), ()>(())
    })
    .unwrap();
    out
}

/// Checks every pixel of `clip` against the exact area; returns the largest error.
fn check_against_exact(v: [Point; 3], clip: Rectangle) -> f64 {
    let got = coverages(v, clip);
    let mut worst = 0.0f64;
    for (i, &alpha) in got.iter().enumerate() {
        let p = clip.top_left
            + Point::new(
                i as i32 % clip.size.width as i32,
                i as i32 / clip.size.width as i32,
            );
        let exact = exact_coverage(v, p);
        let error = (f64::from(alpha) / 255.0 - exact).abs();
        worst = worst.max(error);
        assert!(
            error <= BOUND,
            "triangle {v:?}, pixel {p:?}: coverage {alpha}/255, exact {exact:.5}"
        );
        if exact == 1.0 {
            assert_eq!(alpha, 255, "triangle {v:?}, pixel {p:?} is fully inside");
        }
        // A pixel covered by more than half (beyond the bound) has its centre inside: the
        // aliased top-left rule draws it.
        if f64::from(alpha) / 255.0 > 0.5 + BOUND {
            assert!(
                reference_covers(v, p, Rule::TopLeft),
                "triangle {v:?}, pixel {p:?}: coverage {alpha}/255 but the centre is outside"
            );
        }
    }
    worst
}

fn point(range: std::ops::RangeInclusive<i32>) -> impl Strategy<Value = Point> {
    (range.clone(), range).prop_map(|(x, y)| Point::new(x, y))
}

/// Triangles of every kind around a 24 x 24 clip at the origin: small, tiny, slivers, large
/// and reaching far off it, flat-topped, degenerate.
fn triangle() -> impl Strategy<Value = [Point; 3]> {
    prop_oneof![
        4 => [point(-6..=30), point(-6..=30), point(-6..=30)],
        3 => (point(-2..=26), point(-3..=3), point(-3..=3))
            .prop_map(|(a, d, e)| [a, a + d, a + e]),
        2 => [point(-300..=300), point(-300..=300), point(-300..=300)],
        2 => (point(-4..=28), point(-40..=40), point(-1..=1))
            .prop_map(|(a, d, e)| [a, a + d, a + d * 2 + e]),
        1 => (point(-6..=30), point(-6..=30), -30..30i32)
            .prop_map(|(a, b, dx)| [a, Point::new(a.x + dx, a.y), b]),
        1 => (point(-6..=30), point(-6..=30)).prop_map(|(a, b)| [a, b, a + (b - a) * 2]),
        // Far vertices (beyond 65,536 pixels of the clip, which the walk takes in 64-bit
        // arithmetic), edges crossing the clip.
        2 => [point(-120_000..=120_000), point(-6..=30), point(-120_000..=120_000)],
    ]
}

fn clip() -> Rectangle {
    Rectangle::new(Point::zero(), Size::new(24, 24))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn coverage_is_the_exact_area_within_the_bound(v in triangle()) {
        check_against_exact(v, clip());
    }

    /// The same anywhere a clip can be: triangles and clip moved together up to four million
    /// pixels (the walk counts from the clip's corner), far vertices included.
    #[test]
    fn coverage_is_exact_wherever_the_clip_is(v in triangle(), offset in point(-4_000_000..=4_000_000)) {
        check_against_exact(v.map(|p| p + offset), Rectangle::new(offset, clip().size));
    }
}

#[test]
fn coverage_examples() {
    // A square's two halves: the diagonal pixels are half covered by each.
    let worst = [
        [Point::new(2, 2), Point::new(20, 2), Point::new(2, 20)],
        [Point::new(20, 2), Point::new(20, 20), Point::new(2, 20)],
        [Point::new(3, 1), Point::new(21, 9), Point::new(7, 22)],
        [Point::new(0, 0), Point::new(1, 0), Point::new(0, 1)],
        [Point::new(-100, 5), Point::new(200, 6), Point::new(50, 7)],
    ]
    .map(|v| check_against_exact(v, clip()))
    .into_iter()
    .fold(0.0, f64::max);
    println!("largest error on the examples: {worst:.5}");
}

#[test]
fn shared_edges_add_up_to_the_whole_pixel() {
    let (a, b, c, d) = (
        Point::new(1, 2),
        Point::new(22, 5),
        Point::new(19, 21),
        Point::new(3, 17),
    );
    let first = coverages([a, b, c], clip());
    let second = coverages([a, c, d], clip());
    for (i, (&s, &t)) in first.iter().zip(&second).enumerate() {
        let p = Point::new(i as i32 % 24, i as i32 / 24);
        let exact = exact_coverage([a, b, c], p) + exact_coverage([a, c, d], p);
        let sum = (f64::from(s) + f64::from(t)) / 255.0;
        assert!((sum - exact).abs() <= 2.0 * BOUND, "{p:?}: {s} + {t}");
    }
}

#[test]
fn any_vertices_are_safe() {
    // Vertices anywhere in i32, clips anywhere: nothing outside the clip, nothing twice
    // (`coverages` checks both), no overflow.
    let extremes = [i32::MIN, i32::MIN + 1, -1, 0, 1, i32::MAX - 1, i32::MAX];
    let clips = [
        clip(),
        Rectangle::new(Point::new(i32::MAX - 30, i32::MIN), Size::new(30, 30)),
        Rectangle::new(Point::new(i32::MIN, i32::MAX - 30), Size::new(30, 30)),
    ];
    for &x0 in &extremes {
        for &y1 in &extremes {
            for clip in clips {
                let v = [
                    Point::new(x0, i32::MIN),
                    Point::new(i32::MAX, y1),
                    Point::new(5, 7),
                ];
                coverages(v, clip);
            }
        }
    }
    // Huge triangles over a small clip, against the exact area.
    let huge = [
        [
            Point::new(-1_000_000, -999_983),
            Point::new(1_000_003, 3),
            Point::new(7, 1_000_000),
        ],
        [
            Point::new(-3_000_000, 11),
            Point::new(2_999_999, 13),
            Point::new(5, 20),
        ],
    ];
    for v in huge {
        check_against_exact(v, clip());
        assert!(coverages(v, clip()).contains(&255));
    }
}

/// Sub-pixel triangles (vertices in 1/256 pixel) around the clip: small, slivers, large
/// (hundreds of pixels out: the rational reference overflows i128 much beyond), on whole
/// pixels or not. The walk's 64-bit case is the integer triangles' (far vertices, above); a
/// sub-pixel triangle on whole pixels draws what the integer one does (`tests/subpixel.rs`).
fn subpixel_triangle() -> impl Strategy<Value = [(i32, i32); 3]> {
    let near = || (-6 * 256..=30 * 256, -6 * 256..=30 * 256);
    let far = || (-200_000..=200_000, -200_000..=200_000);
    prop_oneof![
        4 => [near(), near(), near()],
        3 => (near(), (-800..=800, -800..=800), (-800..=800, -800..=800))
            .prop_map(|(a, d, e)| [a, (a.0 + d.0, a.1 + d.1), (a.0 + e.0, a.1 + e.1)]),
        2 => [far(), near(), far()],
        1 => [near(), near(), near()].prop_map(|v| v.map(|(x, y)| (x & !255, y & !255))),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// Anti-aliased sub-pixel triangles: white over black in `Gray8` is the coverage itself,
    /// which is the exact area of each pixel's square within the bound.
    #[test]
    fn subpixel_coverage_is_the_exact_area_within_the_bound(v in subpixel_triangle()) {
        use embedded_graphics::pixelcolor::{Gray8, GrayColor};
        use fixed::types::I24F8;
        use trirast::{geometry::{SubPixelTriangle, SubPoint}, target::BlendTarget, FlatStyle};
        let point = |(x, y): (i32, i32)| SubPoint::new(I24F8::from_bits(x), I24F8::from_bits(y));
        let t = SubPixelTriangle::new(point(v[0]), point(v[1]), point(v[2]));
        let got = frame_after(0, |frame| {
            frame.draw_anti_aliased(&t, &FlatStyle::new(Gray8::WHITE)).unwrap();
        });
        let units = v.map(|(x, y)| (i64::from(x), i64::from(y)));
        for (i, &luma) in got.iter().enumerate() {
            let p = Point::new(i as i32 % 24, i as i32 / 24);
            let exact = exact_coverage_in(units, 256, p);
            prop_assert!((f64::from(luma) / 255.0 - exact).abs() <= BOUND,
                "{v:?} at {p:?}: {luma}/255, exact {exact:.5}");
            if exact == 1.0 {
                prop_assert_eq!(luma, 255);
            }
        }
    }
}

/// A 24 x 24 `Gray8` frame over `background`, with `draw` applied, as luma values.
fn frame_after(
    background: u8,
    draw: impl FnOnce(&mut trirast::Framebuffer<'_, embedded_graphics::pixelcolor::Gray8>),
) -> Vec<u8> {
    use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    let mut pixels = vec![Gray8::new(background); 24 * 24];
    let mut frame = trirast::Framebuffer::new(&mut pixels, 24, 24).unwrap();
    draw(&mut frame);
    pixels.iter().map(|p| p.luma()).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Each pixel is the colour blended over the background by the exact area, within the
    /// coverage bound and a level of rounding.
    #[test]
    fn anti_aliased_flat_blends_by_the_exact_area(v in triangle(), color in 0..=255u8, background in 0..=255u8) {
        use embedded_graphics::pixelcolor::Gray8;
        use trirast::{target::BlendTarget, FlatStyle};
        let t = Triangle::new(v[0], v[1], v[2]);
        let got = frame_after(background, |frame| {
            frame.draw_anti_aliased(&t, &FlatStyle::new(Gray8::new(color))).unwrap();
        });
        for (i, &luma) in got.iter().enumerate() {
            let p = Point::new(i as i32 % 24, i as i32 / 24);
            let area = exact_coverage(v, p);
            let exact = f64::from(color) * area + f64::from(background) * (1.0 - area);
            let allowed = (f64::from(color) - f64::from(background)).abs() * BOUND + 1.0;
            prop_assert!((f64::from(luma) - exact).abs() <= allowed,
                "{v:?} at {p:?}: {luma}, exact {exact:.2}");
            if area == 1.0 {
                prop_assert_eq!(luma, color);
            }
        }
    }

    /// Gouraud colours stay within the vertices' range on edge pixels whose centres lie
    /// outside the triangle (where interpolation extrapolates), and fully covered pixels
    /// have the interpolated colour within a level, as plain drawing does.
    #[test]
    fn anti_aliased_gouraud_stays_in_range(v in triangle(), colors in [0..=255u8, 0..=255u8, 0..=255u8], dither: bool) {
        use embedded_graphics::pixelcolor::Gray8;
        use trirast::{target::BlendTarget, GouraudStyle};
        let t = Triangle::new(v[0], v[1], v[2]);
        let style = GouraudStyle::new(colors.map(Gray8::new)).with_dither(dither);
        let (low, high) = (*colors.iter().min().unwrap(), *colors.iter().max().unwrap());
        // Over a background at the range's low end, nothing may go below it or above the top.
        let got = frame_after(low, |frame| frame.draw_anti_aliased(&t, &style).unwrap());
        for (i, &luma) in got.iter().enumerate() {
            let p = Point::new(i as i32 % 24, i as i32 / 24);
            prop_assert!(luma >= low && luma <= high, "{v:?} at {p:?}: {luma} outside {low}..={high}");
            if !dither && exact_coverage(v, p) == 1.0 {
                let (num, den) = exact_plane(v, colors.map(i64::from), p).unwrap();
                let exact = num as f64 / den as f64;
                prop_assert!((f64::from(luma) - exact).abs() <= 1.0, "{v:?} at {p:?}: {luma}, exact {exact:.2}");
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Anti-aliased `Rgb565` Gouraud, rounded or dithered (both from packed lanes): every
    /// channel stays within the vertices' range, and fully covered pixels are what plain
    /// drawing gives them, bit for bit (the same span loops paint both).
    #[test]
    fn anti_aliased_rgb565_gouraud_matches_plain_drawing_inside(v in triangle(), colors in [[0..=31u8, 0..=63u8, 0..=31u8], [0..=31u8, 0..=63u8, 0..=31u8], [0..=31u8, 0..=63u8, 0..=31u8]], dither: bool) {
        use embedded_graphics::pixelcolor::Rgb565;
        use trirast::{shading::ChannelColor, target::BlendTarget, GouraudStyle};
        let t = Triangle::new(v[0], v[1], v[2]);
        let style = GouraudStyle::new(colors.map(|[r, g, b]| Rgb565::new(r, g, b))).with_dither(dither);
        let low: [u8; 3] = core::array::from_fn(|k| colors.iter().map(|c| c[k]).min().unwrap());
        let high: [u8; 3] = core::array::from_fn(|k| colors.iter().map(|c| c[k]).max().unwrap());
        let background = Rgb565::new(low[0], low[1], low[2]);
        let frame = |draw: &dyn Fn(&mut trirast::Framebuffer<'_, Rgb565>)| {
            let mut pixels = vec![background; 24 * 24];
            draw(&mut trirast::Framebuffer::new(&mut pixels, 24, 24).unwrap());
            pixels
        };
        let got = frame(&|f| f.draw_anti_aliased(&t, &style).unwrap());
        let plain = frame(&|f| t.into_styled(style).draw(f).unwrap());
        for (i, (c, reference)) in got.iter().zip(&plain).enumerate() {
            let p = Point::new(i as i32 % 24, i as i32 / 24);
            let channels = c.channels();
            for k in 0..3 {
                prop_assert!(channels[k] >= low[k] && channels[k] <= high[k], "{v:?} at {p:?}: channel {k} {channels:?} outside {low:?}..={high:?}");
            }
            if exact_coverage(v, p) == 1.0 {
                prop_assert_eq!(c, reference, "{:?} at {:?}", v, p);
            }
        }
    }
}

#[test]
fn anti_aliased_textures_match_plain_drawing_inside() {
    use embedded_graphics::pixelcolor::Gray8;
    use fixed::types::I16F16;
    use trirast::{
        TextureStyle,
        target::BlendTarget,
        texture::{Filter, Texels, Wrap},
    };
    let texels: Vec<Gray8> = (0..16).map(|i| Gray8::new(i * 16 + 7)).collect();
    let texture = Texels::new(&texels, 4, 4).unwrap();
    let uv = |u: i32, v: i32| [I16F16::from_num(u), I16F16::from_num(v)];
    let v = [Point::new(2, 1), Point::new(22, 6), Point::new(5, 21)];
    let t = Triangle::new(v[0], v[1], v[2]);
    for filter in [Filter::Nearest, Filter::Bilinear] {
        for wrap in [Wrap::Clamp, Wrap::Repeat] {
            let style = TextureStyle::new(texture, [uv(0, 0), uv(9, 1), uv(2, 7)])
                .with_filter(filter)
                .with_wrap(wrap);
            let got = frame_after(0, |frame| frame.draw_anti_aliased(&t, &style).unwrap());
            let plain = frame_after(0, |frame| t.into_styled(style).draw(frame).unwrap());
            let mut edges = 0;
            for (i, (&luma, &reference)) in got.iter().zip(&plain).enumerate() {
                let p = Point::new(i as i32 % 24, i as i32 / 24);
                let area = exact_coverage(v, p);
                if area == 1.0 {
                    assert_eq!(luma, reference, "{filter:?} {wrap:?} at {p:?}");
                } else if area > 0.0 {
                    edges += 1;
                } else {
                    assert_eq!(luma, 0, "{filter:?} {wrap:?} at {p:?}");
                }
            }
            assert!(edges > 20);
        }
    }
}

#[test]
fn opacities_combine_on_every_blend_target() {
    use embedded_graphics::{
        mock_display::MockDisplay,
        pixelcolor::{Gray8, GrayColor},
    };
    use trirast::{
        FlatStyle,
        target::{BlendTarget, OverBackground, blend},
    };
    let v = [Point::new(3, 2), Point::new(40, 9), Point::new(12, 50)];
    let t = Triangle::new(v[0], v[1], v[2]);
    let style = FlatStyle::new(Gray8::WHITE);
    let clip = Rectangle::new(Point::zero(), Size::new(64, 64));
    let mut coverage = vec![0u8; 64 * 64];
    for_each_coverage_run(&t, &clip, |span, c| {
        for k in 0..span.len as i32 {
            coverage[(span.y * 64 + span.x + k) as usize] = c;
        }
        Ok::<(), ()>(())
    })
    .unwrap();
    let combined = |a: u8, b: u8| ((u32::from(a) * u32::from(b) + 127) / 255) as u8;
    // A display that cannot be read, over a known black background, at opacity 128. The mock
    // display also checks that no pixel is drawn twice.
    let mut display = MockDisplay::<Gray8>::new();
    OverBackground::new(&mut display, Gray8::BLACK, 128)
        .draw_anti_aliased(&t, &style)
        .unwrap();
    // A framebuffer drawn through `translucent(128)`.
    let mut pixels = vec![Gray8::BLACK; 64 * 64];
    let mut frame = trirast::Framebuffer::new(&mut pixels, 64, 64).unwrap();
    frame
        .translucent(128)
        .draw_anti_aliased(&t, &style)
        .unwrap();
    for (i, &c) in coverage.iter().enumerate() {
        let p = Point::new(i as i32 % 64, i as i32 / 64);
        let expected = blend(Gray8::WHITE, Gray8::BLACK, combined(c, 128));
        assert_eq!(pixels[i], expected, "{p:?}");
        let shown = display.get_pixel(p);
        if c == 0 {
            assert_eq!(shown, None, "{p:?}");
        } else {
            assert_eq!(shown, Some(expected), "{p:?}");
        }
    }
}
