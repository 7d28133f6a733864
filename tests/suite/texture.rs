//! Texture mapping against exact rational texture coordinates computed in `i128` here:
//! nearest takes exactly the texel containing the exact coordinate (half up), bilinear is
//! within one level of the exact blend and between its four texels, constant textures and
//! identity mappings are reproduced exactly, and bad input neither panics nor strays.
#![allow(clippy::needless_range_loop)] // parallel channel arrays read best indexed

use crate::common;

use common::{Recorder, Rng, Rule, exact_plane, reference_covers, window_points};
use embedded_graphics::{
    image::ImageRaw,
    pixelcolor::{
        BinaryColor, Gray4, Gray8, IntoStorage, Rgb565, Rgb888, RgbColor,
        raw::{BigEndian, LittleEndian},
    },
    prelude::*,
    primitives::Rectangle,
};
use fixed::types::I16F16;
use proptest::prelude::*;
use trirast::{
    FillRule, Framebuffer, TextureStyle, Triangle,
    shading::ChannelColor,
    texture::{Filter, ImageTexels, RawTexels, Texels, Wrap},
};

/// Exact texture coordinates at `p`: `(u, v, d)` with the coordinates `u / d`, `v / d` texels.
fn exact_uv(v: [Point; 3], uv: [[I16F16; 2]; 3], p: Point) -> (i128, i128, i128) {
    let axis = |k: usize| exact_plane(v, uv.map(|c| i64::from(c[k].to_bits())), p).unwrap();
    let ((nu, d), (nv, d2)) = (axis(0), axis(1));
    assert_eq!(d, d2);
    (nu, nv, d << 16)
}

/// The texel index along a side of `size` for integer texel position `t`.
fn address(t: i128, size: u32, wrap: Wrap) -> u32 {
    match wrap {
        Wrap::Repeat => t.rem_euclid(i128::from(size)) as u32,
        Wrap::Clamp => t.clamp(0, i128::from(size) - 1) as u32,
    }
}

/// A random texture of `w` x `h` texels.
fn texels<C: ChannelColor<Channels = [u8; N]>, const N: usize>(
    rng: &mut Rng,
    w: u32,
    h: u32,
) -> Vec<C> {
    (0..w * h)
        .map(|_| {
            C::from_channels(core::array::from_fn(|k| {
                (rng.next_u64() % (u64::from(C::MAX_CHANNELS[k]) + 1)) as u8
            }))
        })
        .collect()
}

/// A random texture coordinate within `range` texels: a quarter whole, a quarter halves
/// (ties for nearest), half with random fractions.
fn coordinate(rng: &mut Rng, range: i32) -> I16F16 {
    let whole = rng.range(-range, range);
    let fraction = match rng.range(0, 3) {
        0 => 0,
        1 => 1 << 15,
        _ => rng.range(0, 0xFFFF),
    };
    I16F16::from_bits((whole << 16) | fraction)
}

struct Case<C> {
    vertices: [Point; 3],
    uv: [[I16F16; 2]; 3],
    texels: Vec<C>,
    size: (u32, u32),
    filter: Filter,
    wrap: Wrap,
    window: Rectangle,
}

/// Draws `case` into a recorder and checks coverage against the reference and every pixel
/// with `check(p, colour, exact u, v, d)`.
fn draw_and_check<C, F, const N: usize>(case: &Case<C>, mut check: F) -> Result<(), TestCaseError>
where
    C: ChannelColor<Channels = [u8; N]> + core::fmt::Debug,
    F: FnMut(Point, C, (i128, i128, i128)) -> Result<(), TestCaseError>,
{
    let texture = Texels::new(&case.texels, case.size.0, case.size.1).unwrap();
    let style = TextureStyle::new(texture, case.uv)
        .with_filter(case.filter)
        .with_wrap(case.wrap);
    let triangle = Triangle {
        vertices: case.vertices,
    };
    let mut target = Recorder::<C>::new(case.window);
    triangle.into_styled(style).draw(&mut target).unwrap();
    prop_assert_eq!(target.outside_writes, 0);
    for p in window_points(&case.window) {
        let covered = reference_covers(case.vertices, p, Rule::TopLeft);
        prop_assert_eq!(
            target.writes_at(p),
            u32::from(covered),
            "coverage at {:?}",
            p
        );
        if let Some(c) = target.get(p) {
            check(p, c, exact_uv(case.vertices, case.uv, p))?;
        }
    }
    Ok(())
}

fn random_case<C: ChannelColor<Channels = [u8; N]>, const N: usize>(
    seed: u64,
    window: Rectangle,
    reach: i32,
) -> Case<C> {
    let mut rng = Rng(seed);
    // 131: a side of 32-bit nearest coordinates; 600: too large for them (`SCALED_SIDE`).
    let sizes = [1, 2, 3, 4, 5, 7, 8, 16, 131, 600];
    let size = (
        sizes[rng.range(0, 9) as usize],
        sizes[rng.range(0, 9) as usize],
    );
    let tl = window.top_left;
    let (w, h) = (window.size.width as i32, window.size.height as i32);
    let vertices = loop {
        let v = [(); 3].map(|()| {
            Point::new(
                rng.range(tl.x - reach, tl.x + w + reach),
                rng.range(tl.y - reach, tl.y + h + reach),
            )
        });
        if !(Triangle { vertices: v }).is_degenerate() {
            break v;
        }
    };
    let span = rng.range(1, 40);
    Case {
        vertices,
        uv: [(); 3].map(|()| [coordinate(&mut rng, span), coordinate(&mut rng, span)]),
        texels: texels(&mut rng, size.0, size.1),
        size,
        filter: if rng.range(0, 1) == 0 {
            Filter::Nearest
        } else {
            Filter::Bilinear
        },
        wrap: if rng.range(0, 1) == 0 {
            Wrap::Clamp
        } else {
            Wrap::Repeat
        },
        window,
    }
}

/// The longest texture side whose nearest runs step 32-bit coordinates with 22 fraction bits,
/// started up to the run's length in 2^-22 texel above the 64-bit ones (the documented bound).
const SCALED_SIDE: u32 = 512;

/// How far above the exact coordinate, in 2^-46 texel, nearest may sample (documented): the
/// planes' rounding, (2w + h + 4) units, and for textures up to `SCALED_SIDE` a side the 32-bit
/// runs' lift, up to a window's width in 2^-22 texel.
fn nearest_slack(case: &Case<impl Sized>) -> i128 {
    let (w, h) = (
        i128::from(case.window.size.width),
        i128::from(case.window.size.height),
    );
    let scaled = if case.size.0.max(case.size.1) <= SCALED_SIDE {
        w << 24
    } else {
        0
    };
    2 * w + h + 4 + scaled
}

/// Whether the documented exactness bound for nearest holds: slack * 2 * area < 2^30 (the
/// slack below the distance from any exact coordinate to a texel boundary it is not on).
fn nearest_is_exact(case: &Case<impl Sized>) -> bool {
    let area = Triangle {
        vertices: case.vertices,
    }
    .doubled_signed_area()
    .unsigned_abs();
    nearest_slack(case) as u128 * area < 1 << 30
}

/// Checks nearest sampling: the texel at floor(exact + 1/2) on both axes, exactly when the
/// bound holds, else allowing the coordinate to be up to the slack high.
fn check_nearest<C, const N: usize>(case: &Case<C>) -> Result<(), TestCaseError>
where
    C: ChannelColor<Channels = [u8; N]> + core::fmt::Debug,
{
    let exact = nearest_is_exact(case);
    let slack = nearest_slack(case);
    let texel = |t: i128, d: i128, size: u32| {
        // floor(t / d + 1/2), or the texel past a boundary within the slack.
        let low = (2 * t + d).div_euclid(2 * d);
        let high = (((2 * t + d) << 46) + 2 * slack * d).div_euclid((2 * d) << 46);
        (
            address(low, size, case.wrap),
            address(high, size, case.wrap),
        )
    };
    draw_and_check(case, |p, c, (u, v, d)| {
        let (x, x_high) = texel(u, d, case.size.0);
        let (y, y_high) = texel(v, d, case.size.1);
        let want = case.texels[(y * case.size.0 + x) as usize];
        if exact || c != case.texels[(y_high * case.size.0 + x_high) as usize] {
            prop_assert_eq!(c, want, "at {:?}: u {}/{} v {}/{}", p, u, d, v, d);
        }
        Ok(())
    })
}

/// Checks bilinear sampling channel by channel: between the four texels' extremes and within
/// one level of the exact blend.
fn check_bilinear<C, const N: usize>(case: &Case<C>) -> Result<(), TestCaseError>
where
    C: ChannelColor<Channels = [u8; N]> + core::fmt::Debug,
{
    draw_and_check(case, |p, c, (u, v, d)| {
        let (i, j) = (u.div_euclid(d), v.div_euclid(d));
        let (fx, fy) = (u - i * d, v - j * d);
        let xs = [
            address(i, case.size.0, case.wrap),
            address(i + 1, case.size.0, case.wrap),
        ];
        let ys = [
            address(j, case.size.1, case.wrap),
            address(j + 1, case.size.1, case.wrap),
        ];
        let corners = [
            (xs[0], ys[0]),
            (xs[1], ys[0]),
            (xs[0], ys[1]),
            (xs[1], ys[1]),
        ]
        .map(|(x, y)| case.texels[(y * case.size.0 + x) as usize].channels());
        let weights = [(d - fx) * (d - fy), fx * (d - fy), (d - fx) * fy, fx * fy];
        let got = c.channels();
        for k in 0..N {
            let values = corners.map(|t| i128::from(t[k]));
            let num: i128 = (0..4).map(|q| values[q] * weights[q]).sum();
            let g = i128::from(got[k]);
            prop_assert!(
                (g * d * d - num).abs() <= d * d,
                "channel {} at {:?}: got {}, exact {}",
                k,
                p,
                g,
                num as f64 / (d * d) as f64
            );
            let (lo, hi) = (*values.iter().min().unwrap(), *values.iter().max().unwrap());
            prop_assert!(
                lo <= g && g <= hi,
                "channel {} at {:?}: {} outside {}..={}",
                k,
                p,
                g,
                lo,
                hi
            );
        }
        Ok(())
    })
}

fn check_case<C, const N: usize>(case: &Case<C>) -> Result<(), TestCaseError>
where
    C: ChannelColor<Channels = [u8; N]> + core::fmt::Debug,
{
    match case.filter {
        Filter::Nearest => check_nearest(case),
        Filter::Bilinear => check_bilinear(case),
    }
}

fn small_window() -> Rectangle {
    Rectangle::new(Point::new(-7, 5), Size::new(48, 40))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn rgb565_matches_exact_sampling(seed in any::<u64>()) {
        check_case(&random_case::<Rgb565, 3>(seed, small_window(), 30))?;
    }

    #[test]
    fn rgb888_matches_exact_sampling(seed in any::<u64>()) {
        check_case(&random_case::<Rgb888, 3>(seed, small_window(), 30))?;
    }

    #[test]
    fn gray4_matches_exact_sampling(seed in any::<u64>()) {
        check_case(&random_case::<Gray4, 1>(seed, small_window(), 30))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    /// Screen-sized targets with triangles reaching far beyond them.
    #[test]
    fn big_triangles_on_a_screen(seed in any::<u64>()) {
        let window = Rectangle::new(Point::zero(), Size::new(320, 240));
        let reach = [0, 100, 2000, 40_000][(seed % 4) as usize];
        check_case(&random_case::<Rgb565, 3>(seed, window, reach))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Coordinates that are linear functions with inexact gradients (thirds, sevenths, ...)
    /// and exact half-texel values at many pixels: ties must round up, every one.
    #[test]
    fn nearest_ties_round_up(seed in any::<u64>()) {
        let mut rng = Rng(seed);
        let q = [3, 5, 6, 7, 9, 11][rng.range(0, 5) as usize];
        let window = small_window();
        let vertices = loop {
            let v = [(); 3].map(|()| Point::new(q * rng.range(-2, 6), q * rng.range(0, 5)));
            if !(Triangle { vertices: v }).is_degenerate() {
                break v;
            }
        };
        // u = (a x + b y) / q + 1/2 and v likewise: whole multiples of 1/q at the vertices.
        let (a, b, c, d) = (rng.range(-3, 3), rng.range(-3, 3), rng.range(-3, 3), rng.range(-3, 3));
        let at = |p: Point, a: i32, b: i32| I16F16::from_bits((((a * p.x + b * p.y) / q) << 16) + (1 << 15));
        let mut case = random_case::<Rgb565, 3>(seed, window, 0);
        case.vertices = vertices;
        case.uv = vertices.map(|p| [at(p, a, b), at(p, c, d)]);
        case.filter = Filter::Nearest;
        check_case(&case)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Every vertex's coordinates within a few raw units of the texture's edges (zero, and the
    /// last coordinate each filter samples inside), or inside: triangles mapped just within
    /// their texture, whose runs the painter may leave untested, and triangles a unit beyond.
    #[test]
    fn coordinates_at_the_texture_edges(seed in any::<u64>()) {
        let mut rng = Rng(seed);
        let mut case = random_case::<Rgb565, 3>(seed, small_window(), 10);
        let bilinear = case.filter == Filter::Bilinear;
        let mut near_edge = |side: u32| {
            // Nearest samples floor(u + 1/2): inside below side - 1/2; bilinear reads the
            // next texel too: inside below side - 1 (1/512 texel of bias).
            let last = if bilinear { (side as i32 - 1) << 16 } else { ((side as i32) << 16) - (1 << 15) };
            let offset = rng.range(-3, 3) * [1, 64, 512, 4096][rng.range(0, 3) as usize];
            let bits = match rng.range(0, 3) {
                0 => -(1 << 15) + offset,
                1 => offset,
                2 => last + offset,
                _ => rng.range(0, last.max(0)),
            };
            I16F16::from_bits(bits)
        };
        let (w, h) = case.size;
        case.uv = [(); 3].map(|()| [near_edge(w), near_edge(h)]);
        check_case(&case)?;
    }
}

/// A constant texture draws exactly its colour, whatever the coordinates, filter and wrap.
#[test]
fn constant_texture_is_exact() {
    let mut rng = Rng(7);
    let color = Rgb888::new(201, 13, 99);
    let data = vec![color; 5 * 3];
    let texture = Texels::new(&data, 5, 3).unwrap();
    let window = Rectangle::new(Point::zero(), Size::new(64, 64));
    for _ in 0..500 {
        let v = [(); 3].map(|()| Point::new(rng.range(-40, 100), rng.range(-40, 100)));
        let range = [2, 100, 32_767][rng.range(0, 2) as usize];
        let uv = [(); 3].map(|()| [coordinate(&mut rng, range), coordinate(&mut rng, range)]);
        for filter in [Filter::Nearest, Filter::Bilinear] {
            for wrap in [Wrap::Clamp, Wrap::Repeat] {
                let mut target = Recorder::<Rgb888>::new(window);
                Triangle { vertices: v }
                    .into_styled(
                        TextureStyle::new(texture, uv)
                            .with_filter(filter)
                            .with_wrap(wrap),
                    )
                    .draw(&mut target)
                    .unwrap();
                assert!(target.colors.iter().flatten().all(|&c| c == color));
            }
        }
    }
}

/// A texture mapped onto a same-size rectangle as two triangles comes out bit for bit, every
/// pixel drawn once (no seam on the diagonal), for every filter, wrap and position.
#[test]
fn identity_mapping_reproduces_the_image() {
    let mut rng = Rng(11);
    for (w, h) in [(1, 1), (2, 2), (7, 5), (16, 16), (33, 20), (64, 64)] {
        let data: Vec<Rgb565> = texels(&mut rng, w, h);
        let texture = Texels::new(&data, w, h).unwrap();
        for offset in [Point::zero(), Point::new(3, 9)] {
            for filter in [Filter::Nearest, Filter::Bilinear] {
                for wrap in [Wrap::Clamp, Wrap::Repeat] {
                    let window = Rectangle::new(Point::zero(), Size::new(80, 80));
                    let mut target = Recorder::<Rgb565>::new(window);
                    let (wi, hi) = (w as i32, h as i32);
                    let corners =
                        [(0, 0), (wi, 0), (wi, hi), (0, hi)].map(|(x, y)| Point::new(x, y));
                    for [a, b, c] in [[0, 1, 2], [0, 2, 3]] {
                        let uv =
                            [a, b, c].map(|i| [corners[i].x, corners[i].y].map(I16F16::from_num));
                        let v = [a, b, c].map(|i| corners[i] + offset);
                        Triangle { vertices: v }
                            .into_styled(
                                TextureStyle::new(texture, uv)
                                    .with_filter(filter)
                                    .with_wrap(wrap),
                            )
                            .draw(&mut target)
                            .unwrap();
                    }
                    for p in window_points(&window) {
                        let q = p - offset;
                        let inside = q.x >= 0 && q.y >= 0 && q.x < wi && q.y < hi;
                        assert_eq!(target.writes_at(p), u32::from(inside), "{w}x{h} {p:?}");
                        if inside {
                            let want = data[(q.y * wi + q.x) as usize];
                            assert_eq!(
                                target.get(p),
                                Some(want),
                                "{w}x{h} {filter:?} {wrap:?} {q:?}"
                            );
                        }
                    }
                }
            }
        }
    }
}

/// Extreme coordinates, huge triangles and tiny textures: no panic, nothing outside the
/// target, coverage as the reference says.
#[test]
fn extreme_input_is_safe() {
    let extremes = [i32::MIN, i32::MIN + 1, -1, 0, 1, i32::MAX - 1, i32::MAX];
    let coords = [
        I16F16::MIN,
        I16F16::MAX,
        I16F16::ZERO,
        I16F16::from_bits(-1),
    ];
    let data = [Gray8::new(3), Gray8::new(200)];
    let mut rng = Rng(3);
    for (w, h) in [(1, 1), (2, 1), (1, 2)] {
        let texture = Texels::new(&data[..(w * h) as usize], w, h).unwrap();
        for _ in 0..400 {
            let v = [(); 3].map(|()| {
                let mut c = || match rng.range(0, 2) {
                    0 => extremes[rng.range(0, 6) as usize],
                    1 => rng.range(-100, 100),
                    _ => rng.range(i32::MIN, i32::MAX),
                };
                Point::new(c(), c())
            });
            let uv = [(); 3].map(|()| {
                [
                    coords[rng.range(0, 3) as usize],
                    coordinate(&mut rng, 32_767),
                ]
            });
            let window = Rectangle::new(Point::new(-20, -20), Size::new(40, 40));
            for filter in [Filter::Nearest, Filter::Bilinear] {
                for wrap in [Wrap::Clamp, Wrap::Repeat] {
                    let mut target = Recorder::<Gray8>::new(window);
                    Triangle { vertices: v }
                        .into_styled(
                            TextureStyle::new(texture, uv)
                                .with_filter(filter)
                                .with_wrap(wrap),
                        )
                        .draw(&mut target)
                        .unwrap();
                    assert_eq!(target.outside_writes, 0);
                    for p in window_points(&window) {
                        let covered = reference_covers(v, p, Rule::TopLeft);
                        assert_eq!(target.writes_at(p), u32::from(covered), "{v:?} {p:?}");
                        if let Some(c) = target.get(p) {
                            assert!(
                                data[..(w * h) as usize].contains(&c) || filter == Filter::Bilinear
                            );
                        }
                    }
                }
            }
        }
    }
}

/// Texels read through raw bytes (either byte order) and through `ImageRaw` draw exactly as
/// texels from a slice.
#[test]
fn all_sources_draw_alike() {
    let mut rng = Rng(5);
    let (w, h) = (6, 4);
    let data: Vec<Rgb565> = texels(&mut rng, w, h);
    let le: Vec<u8> = data
        .iter()
        .flat_map(|c| c.into_storage().to_le_bytes())
        .collect();
    let be: Vec<u8> = data
        .iter()
        .flat_map(|c| c.into_storage().to_be_bytes())
        .collect();
    let image = ImageRaw::<Rgb565, BigEndian>::new(&be, w);
    let window = Rectangle::new(Point::zero(), Size::new(40, 40));
    let v = [Point::new(1, 2), Point::new(38, 9), Point::new(12, 37)];
    let uv = [[-1.5, 0.25], [9.0, -3.0], [2.0, 7.5]].map(|c| c.map(I16F16::from_num));
    for filter in [Filter::Nearest, Filter::Bilinear] {
        for wrap in [Wrap::Clamp, Wrap::Repeat] {
            let draw_with = |texture: &dyn Fn(&mut Recorder<Rgb565>)| {
                let mut target = Recorder::<Rgb565>::new(window);
                texture(&mut target);
                target.colors
            };
            macro_rules! drawn {
                ($texture:expr) => {
                    draw_with(&|target: &mut Recorder<Rgb565>| {
                        Triangle { vertices: v }
                            .into_styled(
                                TextureStyle::new($texture, uv)
                                    .with_filter(filter)
                                    .with_wrap(wrap),
                            )
                            .draw(target)
                            .unwrap()
                    })
                };
            }
            let slice = drawn!(Texels::new(&data, w, h).unwrap());
            assert!(slice.iter().flatten().count() > 300);
            assert_eq!(
                drawn!(RawTexels::<Rgb565, LittleEndian>::new(&le, w, h).unwrap()),
                slice
            );
            assert_eq!(
                drawn!(RawTexels::<Rgb565, BigEndian>::new(&be, w, h).unwrap()),
                slice
            );
            assert_eq!(drawn!(ImageTexels::new(&image).unwrap()), slice);
        }
    }
}

/// Modulating a white texture is Gouraud shading: every channel within one level of the exact
/// interpolated colour; a black tint gives black.
#[test]
fn modulation_of_white_is_gouraud() {
    let white = [Rgb565::WHITE; 4];
    let texture = Texels::new(&white, 2, 2).unwrap();
    let mut rng = Rng(9);
    let window = Rectangle::new(Point::zero(), Size::new(64, 64));
    for _ in 0..300 {
        let v = [(); 3].map(|()| Point::new(rng.range(-20, 80), rng.range(-20, 80)));
        if (Triangle { vertices: v }).is_degenerate() {
            continue;
        }
        let colors: [Rgb565; 3] = core::array::from_fn(|_| {
            let r = rng.next_u64();
            Rgb565::new((r & 31) as u8, (r >> 8 & 63) as u8, (r >> 16 & 31) as u8)
        });
        let uv = [[I16F16::ZERO; 2]; 3];
        for filter in [Filter::Nearest, Filter::Bilinear] {
            let mut target = Recorder::<Rgb565>::new(window);
            Triangle { vertices: v }
                .into_styled(
                    TextureStyle::new(texture, uv)
                        .with_filter(filter)
                        .with_modulation(colors),
                )
                .draw(&mut target)
                .unwrap();
            for p in window_points(&window) {
                let Some(c) = target.get(p) else { continue };
                for k in 0..3 {
                    let a = colors.map(|c| i64::from(c.channels()[k]));
                    let (num, den) = exact_plane(v, a, p).unwrap();
                    let got = i128::from(c.channels()[k]);
                    assert!(
                        (got * den - num).abs() <= den,
                        "{v:?} {p:?} channel {k}: {got} vs {num}/{den}"
                    );
                }
            }
            let mut target = Recorder::<Rgb565>::new(window);
            Triangle { vertices: v }
                .into_styled(
                    TextureStyle::new(texture, uv)
                        .with_filter(filter)
                        .with_modulation([Rgb565::BLACK; 3]),
                )
                .draw(&mut target)
                .unwrap();
            assert!(target.colors.iter().flatten().all(|&c| c == Rgb565::BLACK));
        }
    }
}

/// Monochrome textures work end to end, into the crate's framebuffer and with the inclusive
/// rule.
#[test]
fn binary_texture_into_framebuffer() {
    let checker: Vec<BinaryColor> = (0..64)
        .map(|i| {
            if (i % 8 + i / 8) % 2 == 0 {
                BinaryColor::On
            } else {
                BinaryColor::Off
            }
        })
        .collect();
    let texture = Texels::new(&checker, 8, 8).unwrap();
    let mut pixels = [BinaryColor::Off; 16 * 16];
    let mut display = Framebuffer::new(&mut pixels, 16, 16).unwrap();
    let (a, b, c) = (Point::new(0, 0), Point::new(16, 0), Point::new(0, 16));
    let style = TextureStyle::from_points(
        texture,
        [Point::new(0, 0), Point::new(8, 0), Point::new(0, 8)],
    )
    .with_fill_rule(FillRule::Inclusive);
    Triangle::new(a, b, c)
        .into_styled(style)
        .draw(&mut display)
        .unwrap();
    // Pixel (2k, 0) samples texel k exactly; (2k+1, 0) samples k + 1/2, which rounds up.
    for x in 0..8 {
        assert_eq!(
            display.pixel(Point::new(2 * x, 0)),
            Some(checker[x as usize])
        );
        let next = (x as usize + 1).min(7);
        assert_eq!(display.pixel(Point::new(2 * x + 1, 0)), Some(checker[next]));
    }
}
