//! Gouraud shading against exact rational interpolation, computed in `i128` here: every channel
//! within one level of the exact value rounded, exact for constant colours and at vertices, the
//! same coverage as flat filling, watertight meshes, and dithering that follows the exact value.
#![allow(clippy::needless_range_loop)] // parallel channel arrays read best indexed

use crate::common;

use common::{
    CountingTarget, Offset, Recorder, Rng, Rule, exact_plane, reference_covers, reference_pixels,
    round_half_up, window_points,
};
use embedded_graphics::{
    pixelcolor::{
        Bgr555, Bgr565, Bgr666, BinaryColor, Gray2, Gray4, Gray8, GrayColor, Rgb555, Rgb565,
        Rgb666, Rgb888, RgbColor,
    },
    prelude::*,
    primitives::Rectangle,
};
use proptest::prelude::*;
use trirast::{FillRule, FlatStyle, GouraudStyle, Triangle, shading::ChannelColor};

/// Exact channel value at `p`, rounded half up.
fn exact_channel(v: [Point; 3], channel: [u8; 3], p: Point) -> i128 {
    let (num, den) = exact_plane(v, channel.map(i64::from), p).unwrap();
    round_half_up(num, den)
}

/// Draws with Gouraud shading into a recorder over `window` and checks every pixel: drawn
/// exactly where the reference says, once, each channel within `tolerance` of exact.
fn check_gouraud<C>(
    v: [Point; 3],
    colors: [C; 3],
    window: Rectangle,
    rule: Rule,
    tolerance: i128,
) -> Result<(), TestCaseError>
where
    C: ChannelColor<Channels = [u8; 3]> + core::fmt::Debug,
{
    let mut target = Recorder::<C>::new(window);
    Triangle { vertices: v }
        .into_styled(GouraudStyle::new(colors).with_fill_rule(rule.to_crate()))
        .draw(&mut target)
        .unwrap();
    prop_assert_eq!(target.outside_writes, 0);
    let channels = colors.map(|c| c.channels());
    for p in window_points(&window) {
        let covered = reference_covers(v, p, rule);
        prop_assert_eq!(
            target.writes_at(p),
            u32::from(covered),
            "coverage at {:?}",
            p
        );
        if let Some(c) = target.get(p) {
            let got = c.channels();
            for k in 0..3 {
                let want = exact_channel(v, [channels[0][k], channels[1][k], channels[2][k]], p);
                let diff = (i128::from(got[k]) - want).abs();
                prop_assert!(
                    diff <= tolerance,
                    "channel {} at {:?}: got {}, exact {} ({:?}, {:?})",
                    k,
                    p,
                    got[k],
                    want,
                    v,
                    colors
                );
            }
        }
    }
    Ok(())
}

fn rgb888() -> impl Strategy<Value = Rgb888> {
    any::<[u8; 3]>().prop_map(|[r, g, b]| Rgb888::new(r, g, b))
}

fn rgb565() -> impl Strategy<Value = Rgb565> {
    (0..32u8, 0..64u8, 0..32u8).prop_map(|(r, g, b)| Rgb565::new(r, g, b))
}

/// Triangles up to 320x240 and beyond, often reaching past the window.
fn triangle() -> impl Strategy<Value = [Point; 3]> {
    let coord = prop_oneof![
        3 => (-40..360i32, -40..280i32),
        1 => (-3000..3000i32, -3000..3000i32),
        1 => (0..24i32, 0..24i32),
    ];
    [coord.clone(), coord.clone(), coord].prop_map(|c| c.map(|(x, y)| Point::new(x, y)))
}

/// Triangles within a 5x5 square, often of a doubled area of 1 or 2: the smallest set-ups,
/// whose one or two pixels are vertices (on Cortex-M0 a doubled area of 1 once lost its
/// gradients; `TRIRAST_EMULATE=cortex-m0` runs this on the host).
fn tiny_triangle() -> impl Strategy<Value = [Point; 3]> {
    let offset = || (-2..=2i32, -2..=2i32);
    ((-40..360i32, -40..280i32), [offset(), offset(), offset()])
        .prop_map(|((x, y), offsets)| offsets.map(|(dx, dy)| Point::new(x + dx, y + dy)))
}

fn window() -> impl Strategy<Value = Rectangle> {
    (-20..300i32, -20..220i32, 1..48u32, 1..40u32)
        .prop_map(|(x, y, w, h)| Rectangle::new(Point::new(x, y), Size::new(w, h)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(5_000))]

    /// 8-bit channels: within one level of the exact rational value, rounded.
    #[test]
    fn rgb888_within_one_level_of_exact(v in triangle(), colors in [rgb888(), rgb888(), rgb888()], window in window()) {
        check_gouraud(v, colors, window, Rule::TopLeft, 1)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1_500))]

    /// 5- and 6-bit channels, each in its own range.
    #[test]
    fn rgb565_within_one_level_of_exact(v in triangle(), colors in [rgb565(), rgb565(), rgb565()], window in window(),
                                        inclusive in any::<bool>()) {
        let rule = if inclusive { Rule::Inclusive } else { Rule::TopLeft };
        check_gouraud(v, colors, window, rule, 1)?;
    }

    /// The other colour types whose channels are stepped packed, two to a word (each lane's
    /// place in its word is its own): every channel within one level of exact.
    #[test]
    fn packed_colour_types_within_one_level_of_exact(v in triangle(), c in [any::<[u8; 3]>(), any::<[u8; 3]>(), any::<[u8; 3]>()],
                                                     window in window(), kind in 0..5u8) {
        let fit = |max: [u8; 3]| c.map(|c| [0, 1, 2].map(|k| c[k] % (max[k] + 1)));
        match kind {
            0 => check_gouraud(v, fit([63; 3]).map(|[r, g, b]| Rgb666::new(r, g, b)), window, Rule::TopLeft, 1)?,
            1 => check_gouraud(v, fit([63; 3]).map(|[r, g, b]| Bgr666::new(r, g, b)), window, Rule::TopLeft, 1)?,
            2 => check_gouraud(v, fit([31; 3]).map(|[r, g, b]| Rgb555::new(r, g, b)), window, Rule::TopLeft, 1)?,
            3 => check_gouraud(v, fit([31; 3]).map(|[r, g, b]| Bgr555::new(r, g, b)), window, Rule::TopLeft, 1)?,
            _ => check_gouraud(v, fit([31, 63, 31]).map(|[r, g, b]| Bgr565::new(r, g, b)), window, Rule::TopLeft, 1)?,
        }
    }

    /// One colour at all vertices: exactly that colour everywhere, for every colour type.
    #[test]
    fn constant_colour_is_exact(v in triangle(), c in rgb888(), luma in any::<u8>(), window in window()) {
        let covered = reference_pixels(v, &window, Rule::TopLeft);
        let mut rgb = Recorder::<Rgb888>::new(window);
        Triangle { vertices: v }.into_styled(GouraudStyle::new([c; 3])).draw(&mut rgb).unwrap();
        let c565 = Rgb565::new(c.r() >> 3, c.g() >> 2, c.b() >> 3);
        let mut rgb565 = Recorder::<Rgb565>::new(window);
        Triangle { vertices: v }.into_styled(GouraudStyle::new([c565; 3])).draw(&mut rgb565).unwrap();
        let mut gray = Recorder::<Gray8>::new(window);
        Triangle { vertices: v }.into_styled(GouraudStyle::new([Gray8::new(luma); 3])).draw(&mut gray).unwrap();
        let mut gray2 = Recorder::<Gray2>::new(window);
        Triangle { vertices: v }.into_styled(GouraudStyle::new([Gray2::new(luma & 3); 3])).draw(&mut gray2).unwrap();
        let on = if luma & 1 == 1 { BinaryColor::On } else { BinaryColor::Off };
        let mut binary = Recorder::<BinaryColor>::new(window);
        Triangle { vertices: v }.into_styled(GouraudStyle::new([on; 3]).with_dither(true)).draw(&mut binary).unwrap();
        for p in covered {
            prop_assert_eq!(rgb.get(p), Some(c));
            prop_assert_eq!(rgb565.get(p), Some(c565));
            prop_assert_eq!(gray.get(p), Some(Gray8::new(luma)));
            prop_assert_eq!(gray2.get(p), Some(Gray2::new(luma & 3)));
            prop_assert_eq!(binary.get(p), Some(on));
        }
    }

    /// A vertex pixel gets exactly its vertex's colour (the inclusive rule draws all three).
    #[test]
    fn vertices_get_their_colour(v in prop_oneof![triangle(), tiny_triangle()], colors in [rgb888(), rgb888(), rgb888()]) {
        // Degenerate triangles (the exact plane has no area: about one in ten of the tiny
        // ones) draw nothing; checked here rather than rejected, so that any number of cases
        // stays within proptest's limit on rejections.
        let degenerate = exact_plane(v, [0; 3], v[0]).is_none();
        for (i, &vertex) in v.iter().enumerate() {
            let window = Rectangle::new(vertex - Point::new(1, 1), Size::new(3, 3));
            let mut target = Recorder::<Rgb888>::new(window);
            Triangle { vertices: v }
                .into_styled(GouraudStyle::new(colors).with_fill_rule(FillRule::Inclusive))
                .draw(&mut target)
                .unwrap();
            let want = (!degenerate).then_some(colors[i]);
            prop_assert_eq!(target.get(vertex), want, "vertex {} of {:?}", i, v);
        }
    }

    /// Gray types interpolate their single channel in its own range.
    #[test]
    fn gray_within_one_level(v in triangle(), l in [any::<u8>(), any::<u8>(), any::<u8>()], window in window()) {
        let mut g8 = Recorder::<Gray8>::new(window);
        Triangle { vertices: v }.into_styled(GouraudStyle::new(l.map(Gray8::new))).draw(&mut g8).unwrap();
        let l4 = l.map(|x| x >> 4);
        let mut g4 = Recorder::<Gray4>::new(window);
        Triangle { vertices: v }.into_styled(GouraudStyle::new(l4.map(Gray4::new))).draw(&mut g4).unwrap();
        for p in window_points(&window) {
            if let Some(c) = g8.get(p) {
                prop_assert!((i128::from(c.luma()) - exact_channel(v, l, p)).abs() <= 1);
            }
            if let Some(c) = g4.get(p) {
                prop_assert!((i128::from(c.luma()) - exact_channel(v, l4, p)).abs() <= 1);
            }
        }
    }

    /// Dithering: each pixel is on exactly when the exact value plus its Bayer threshold
    /// reaches one, except where the two are within rounding distance.
    #[test]
    fn dither_follows_the_exact_value(v in triangle(), on in [any::<bool>(), any::<bool>(), any::<bool>()], window in window()) {
        let colors = on.map(|b| if b { BinaryColor::On } else { BinaryColor::Off });
        let mut target = Recorder::<BinaryColor>::new(window);
        Triangle { vertices: v }.into_styled(GouraudStyle::new(colors).with_dither(true)).draw(&mut target).unwrap();
        const BAYER: [[i128; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];
        for p in window_points(&window) {
            let Some(c) = target.get(p) else { continue };
            let (num, den) = exact_plane(v, on.map(i64::from), p).unwrap();
            // value + (2t + 1) / 32 >= 1  <=>  32 num + (2t + 1) den >= 32 den
            let t = BAYER[(p.y & 3) as usize][(p.x & 3) as usize];
            let margin = 32 * num + (2 * t + 1) * den - 32 * den;
            if margin.abs() * 1024 > 32 * den {
                prop_assert_eq!(c == BinaryColor::On, margin >= 0, "{:?} at {:?}", v, p);
            }
        }
    }

    /// Dithering in every channel of `Rgb565`: each is the exact value plus its Bayer
    /// threshold, rounded down, except within rounding distance of a level (the packed lanes':
    /// 1/64 + 2^-15 of a level, under 1/63).
    #[test]
    fn dither_follows_the_exact_value_in_every_channel(v in triangle(), colors in [rgb565(), rgb565(), rgb565()], window in window()) {
        let mut target = Recorder::<Rgb565>::new(window);
        Triangle { vertices: v }.into_styled(GouraudStyle::new(colors).with_dither(true)).draw(&mut target).unwrap();
        const BAYER: [[i128; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];
        let channels = colors.map(|c| c.channels());
        for p in window_points(&window) {
            let Some(c) = target.get(p) else { continue };
            let t = BAYER[(p.y & 3) as usize][(p.x & 3) as usize];
            for k in 0..3 {
                let (num, den) = exact_plane(v, [0, 1, 2].map(|i| i64::from(channels[i][k])), p).unwrap();
                // floor(num / den + (2t + 1) / 32) = floor((32 num + (2t + 1) den) / (32 den))
                let scaled = 32 * num + (2 * t + 1) * den;
                let want = scaled.div_euclid(32 * den);
                let margin = scaled.rem_euclid(32 * den).min(32 * den - scaled.rem_euclid(32 * den));
                if margin * 63 > 32 * den {
                    prop_assert_eq!(i128::from(c.channels()[k]), want, "channel {} of {:?} at {:?}", k, v, p);
                }
            }
        }
    }

    /// The mean of each dithered 4x4 block (aligned to the pattern) is the exact mean there,
    /// within the documented bound: 1/32 of a level plus 1.5 times the channel's change
    /// across and down one pixel, plus 1/256 for the planes' rounding and, for the packed
    /// lanes of `Rgb565`, 1/64 + 2^-15 for theirs.
    #[test]
    fn dithered_blocks_average_the_exact_value(v in triangle(), colors in [rgb565(), rgb565(), rgb565()], gray in [0..16u8, 0..16u8, 0..16u8]) {
        let window = Rectangle::new(Point::new(0, 0), Size::new(48, 40));
        let mut rgb = Recorder::<Rgb565>::new(window);
        Triangle { vertices: v }.into_styled(GouraudStyle::new(colors).with_dither(true)).draw(&mut rgb).unwrap();
        let mut g4 = Recorder::<Gray4>::new(window);
        let grays = gray.map(Gray4::new);
        Triangle { vertices: v }.into_styled(GouraudStyle::new(grays).with_dither(true)).draw(&mut g4).unwrap();
        let rgb_channels = colors.map(|c| c.channels());
        let check = |a: [i64; 3], lanes: bool, got: &dyn Fn(Point) -> Option<u8>| -> Result<(), TestCaseError> {
            for by in 0..10 {
                for bx in 0..12 {
                    let block: Vec<Point> = (0..16).map(|i| Point::new(bx * 4 + i % 4, by * 4 + i / 4)).collect();
                    let values: Vec<u8> = block.iter().filter_map(|&p| got(p)).collect();
                    if values.len() < 16 {
                        continue;
                    }
                    // Exact mean: the plane at the block's centre (the mean of a linear function
                    // over a symmetric block), as 2 * num / (2 * den) with the centre at +1.5.
                    let (n0, den) = exact_plane(v, a, block[0]).unwrap();
                    let (n1, _) = exact_plane(v, a, block[0] + Point::new(1, 0)).unwrap();
                    let (n2, _) = exact_plane(v, a, block[0] + Point::new(0, 1)).unwrap();
                    let (gx, gy) = (n1 - n0, n2 - n0);
                    // mean = (n0 + 1.5 gx + 1.5 gy) / den; in units of 1/(32 * 256 * den):
                    let unit = 32 * 256;
                    let exact = unit * (2 * n0 + 3 * gx + 3 * gy) / 2;
                    let sum: i128 = values.iter().map(|&c| i128::from(c)).sum();
                    let mean = unit * sum * den / 16;
                    // 1/64 + 2^-15 of a level is 128.25 units of den.
                    let lanes_bound = if lanes { 129 * den } else { 0 };
                    let bound = 256 * den + unit * 3 * (gx.abs() + gy.abs()) / 2 + 32 * den + lanes_bound;
                    prop_assert!((mean - exact).abs() <= bound, "block ({}, {}) of {:?}: mean {} exact {} bound {}", bx, by, v, mean, exact, bound);
                }
            }
            Ok(())
        };
        for k in 0..3 {
            check([0, 1, 2].map(|i| i64::from(rgb_channels[i][k])), true, &|p| rgb.get(p).map(|c| c.channels()[k]))?;
        }
        check(gray.map(i64::from), false, &|p| g4.get(p).map(|c| c.luma()))?;
    }

    /// Shading changes colours, never coverage.
    #[test]
    fn same_coverage_as_flat(v in triangle(), window in window(), inclusive in any::<bool>()) {
        let rule = if inclusive { FillRule::Inclusive } else { FillRule::TopLeft };
        let mut flat = Recorder::<Rgb565>::new(window);
        Triangle { vertices: v }.into_styled(FlatStyle::new(Rgb565::RED).with_fill_rule(rule)).draw(&mut flat).unwrap();
        let mut shaded = Recorder::<Rgb565>::new(window);
        let colors = [Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE];
        Triangle { vertices: v }.into_styled(GouraudStyle::new(colors).with_fill_rule(rule).with_dither(inclusive)).draw(&mut shaded).unwrap();
        prop_assert_eq!(&flat.writes, &shaded.writes);
    }
}

/// A shaded mesh still covers every pixel exactly once.
#[test]
fn shaded_mesh_is_watertight() {
    let mut rng = Rng(99);
    let window = Rectangle::new(Point::new(0, 0), Size::new(120, 90));
    for _ in 0..30 {
        let (nx, ny) = (rng.range(2, 10), rng.range(2, 9));
        let mut pts = Vec::new();
        for j in 0..=ny {
            for i in 0..=nx {
                let jitter = |r: &mut Rng, edge: bool| if edge { 0 } else { r.range(-2, 2) };
                pts.push(Point::new(
                    120 * i / nx + jitter(&mut rng, i == 0 || i == nx),
                    90 * j / ny + jitter(&mut rng, j == 0 || j == ny),
                ));
            }
        }
        let at = |i: i32, j: i32| pts[(j * (nx + 1) + i) as usize];
        let mut target = Offset(CountingTarget::new(window));
        let mut colors = Recorder::<Rgb888>::new(window);
        for j in 0..ny {
            for i in 0..nx {
                for t in [
                    [at(i, j), at(i + 1, j), at(i + 1, j + 1)],
                    [at(i, j), at(i + 1, j + 1), at(i, j + 1)],
                ] {
                    let style = GouraudStyle::new([Rgb888::RED, Rgb888::GREEN, Rgb888::BLUE]);
                    Triangle { vertices: t }
                        .into_styled(style)
                        .draw(&mut colors)
                        .unwrap();
                    Triangle { vertices: t }
                        .into_styled(GouraudStyle::new([
                            BinaryColor::On,
                            BinaryColor::Off,
                            BinaryColor::On,
                        ]))
                        .draw(&mut target)
                        .unwrap();
                }
            }
        }
        assert!(target.0.hits.iter().all(|&h| h == 1), "every pixel once");
        assert!(colors.writes.iter().all(|&h| h == 1), "every pixel once");
    }
}

/// The hand-checked example from the docs, on a 64x64 display.
#[test]
fn documented_gradient() {
    let mut rec = Recorder::<Rgb565>::new(Rectangle::new(Point::zero(), Size::new(64, 64)));
    Triangle::new(Point::new(0, 0), Point::new(63, 0), Point::new(0, 63))
        .into_styled(GouraudStyle::new([
            Rgb565::RED,
            Rgb565::GREEN,
            Rgb565::BLUE,
        ]))
        .draw(&mut rec)
        .unwrap();
    // Halfway along the top edge: half red (31 -> 15.5 -> 16?), half green (63 -> 31.5).
    // Exact: r = 31 * 32/63 = 15.746 -> 16; g = 63 * 31/63 = 31; at x = 31.
    assert_eq!(rec.get(Point::new(31, 0)), Some(Rgb565::new(16, 31, 0)));
    assert_eq!(rec.get(Point::new(0, 0)), Some(Rgb565::RED));
}

/// A target as large as `area` that keeps only the pixels inside `probe`: spans elsewhere are
/// not even shaded (their colours are never pulled), so that windows thousands of pixels across
/// can be checked where it matters.
struct Probe<C> {
    area: Rectangle,
    probe: Recorder<C>,
}

impl<C: PixelColor> Dimensions for Probe<C> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<C: PixelColor> DrawTarget for Probe<C> {
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        let probe = self.probe.area;
        self.probe
            .draw_iter(pixels.into_iter().filter(|Pixel(p, _)| probe.contains(*p)))
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        let probe = self.probe.area;
        if area.intersection(&probe).is_zero_sized() {
            return Ok(());
        }
        let pixels = area
            .points()
            .zip(colors)
            .filter(|(p, _)| probe.contains(*p));
        self.probe.draw_iter(pixels.map(|(p, c)| Pixel(p, c)))
    }
}

/// A Gouraud triangle drawn, rounded or dithered, into a window `side` pixels square at a
/// random place, recording only a 16x16 probe in the window's far quarter: the first vertex
/// lies near the window's other corner or off the window (where the lanes are anchored), the
/// legs are three windows long (the window lies inside, the probe covered), and each vertex
/// colour is `make` of random channels up to `max`.
fn wide_window_case<C: ChannelColor<Channels = [u8; 3]> + core::fmt::Debug>(
    rng: &mut Rng,
    side: i32,
    make: impl Fn([u8; 3]) -> C,
    max: [u8; 3],
    dither: bool,
) -> ([Point; 3], [C; 3], Probe<C>) {
    let corner = Point::new(rng.range(-5000, 5000), rng.range(-5000, 5000));
    let area = Rectangle::new(corner, Size::new(side as u32, side as u32));
    let probe_at = corner
        + Point::new(
            rng.range(side * 3 / 4, side - 16),
            rng.range(side * 3 / 4, side - 16),
        );
    let probe = Rectangle::new(probe_at, Size::new(16, 16));
    let first = corner + Point::new(rng.range(-300, 40), rng.range(-300, 40));
    let v = [
        first,
        corner + Point::new(3 * side, rng.range(-300, 40)),
        corner + Point::new(rng.range(-300, 40), 3 * side),
    ];
    let colors = [(); 3]
        .map(|()| make([0, 1, 2].map(|k| (rng.range(0, 255) % (i32::from(max[k]) + 1)) as u8)));
    let mut target = Probe {
        area,
        probe: Recorder::new(probe),
    };
    Triangle { vertices: v }
        .into_styled(GouraudStyle::new(colors).with_dither(dither))
        .draw(&mut target)
        .unwrap();
    (v, colors, target)
}

/// Packed channels keep their accuracy across the widest windows they are used in (4096 pixels
/// for lanes of 16 fraction bits, 2048 for `Rgb666`'s of 15: beyond, the 16.16 path): pixels as
/// far as can be from where the lanes are anchored (the first vertex, or the window's corner when
/// that vertex lies off the window) are within one level of exact.
#[test]
fn packed_channels_hold_across_the_widest_windows() {
    fn check<C: ChannelColor<Channels = [u8; 3]> + core::fmt::Debug>(
        rng: &mut Rng,
        side: i32,
        make: impl Fn([u8; 3]) -> C,
        max: [u8; 3],
    ) -> usize {
        let (v, colors, target) = wide_window_case(rng, side, make, max, false);
        let probe = target.probe.area;
        let channels = colors.map(|c| c.channels());
        let mut checked = 0;
        for p in window_points(&probe) {
            let covered = reference_covers(v, p, Rule::TopLeft);
            assert_eq!(
                target.probe.writes_at(p),
                u32::from(covered),
                "coverage at {p:?}"
            );
            if let Some(c) = target.probe.get(p) {
                checked += 1;
                let got = c.channels();
                for k in 0..3 {
                    let want =
                        exact_channel(v, [channels[0][k], channels[1][k], channels[2][k]], p);
                    assert!(
                        (i128::from(got[k]) - want).abs() <= 1,
                        "channel {k} at {p:?}: got {}, exact {want} ({v:?}, {colors:?})",
                        got[k]
                    );
                }
            }
        }
        checked
    }
    let mut rng = Rng(0x5EED_1A7E);
    let mut checked = 0;
    for _ in 0..150 {
        checked += check(
            &mut rng,
            4096,
            |[r, g, b]| Rgb565::new(r, g, b),
            [31, 63, 31],
        );
        checked += check(
            &mut rng,
            4096,
            |[r, g, b]| Rgb555::new(r, g, b),
            [31, 31, 31],
        );
        checked += check(
            &mut rng,
            2048,
            |[r, g, b]| Rgb666::new(r, g, b),
            [63, 63, 63],
        );
    }
    // Every probe lies inside its triangle.
    assert_eq!(checked, 3 * 150 * 256);
}

/// Dithered packed channels keep their accuracy across the widest windows they are used in (512
/// pixels for lanes of 16 fraction bits, 256 for `Rgb666`'s 15): every channel is the exact
/// value plus its Bayer threshold, rounded down, except within 1/63 of a level of a step.
/// Windows eight times as wide must take the 16.16 path, whose 2^-16 steps drift by up to 1/16
/// of a level over 4,096 pixels (lanes there would drift by up to 1/7): the same except within
/// 1/15 of a level.
#[test]
fn dithered_packed_channels_hold_across_the_widest_windows() {
    const BAYER: [[i128; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];
    fn check<C: ChannelColor<Channels = [u8; 3]> + core::fmt::Debug>(
        rng: &mut Rng,
        side: i32,
        make: impl Fn([u8; 3]) -> C,
        max: [u8; 3],
    ) -> usize {
        let (v, colors, target) = wide_window_case(rng, side, make, max, true);
        let probe = target.probe.area;
        let channels = colors.map(|c| c.channels());
        let mut checked = 0;
        for p in window_points(&probe) {
            let Some(c) = target.probe.get(p) else {
                continue;
            };
            checked += 1;
            let t = BAYER[p.y.rem_euclid(4) as usize][p.x.rem_euclid(4) as usize];
            for k in 0..3 {
                let a = [0, 1, 2].map(|i| i64::from(channels[i][k]));
                let (num, den) = exact_plane(v, a, p).unwrap();
                let scaled = 32 * num + (2 * t + 1) * den;
                let want = scaled.div_euclid(32 * den);
                let rest = scaled.rem_euclid(32 * den);
                let within = if side >= 2048 { 15 } else { 63 };
                if rest.min(32 * den - rest) * within > 32 * den {
                    assert_eq!(
                        i128::from(c.channels()[k]),
                        want,
                        "channel {k} at {p:?} ({v:?}, {colors:?}, window {side})"
                    );
                }
            }
        }
        checked
    }
    let mut rng = Rng(0xD1_7E4E);
    let mut checked = 0;
    for _ in 0..60 {
        for wide in [1, 8] {
            checked += check(
                &mut rng,
                512 * wide,
                |[r, g, b]| Rgb565::new(r, g, b),
                [31, 63, 31],
            );
            checked += check(
                &mut rng,
                512 * wide,
                |[r, g, b]| Rgb555::new(r, g, b),
                [31, 31, 31],
            );
            checked += check(
                &mut rng,
                256 * wide,
                |[r, g, b]| Rgb666::new(r, g, b),
                [63, 63, 63],
            );
        }
    }
    // Every probe lies inside its triangle.
    assert_eq!(checked, 6 * 60 * 256);
}
