//! Perspective-correct texturing against exact rational perspective coordinates computed in
//! `i128` here: every pixel samples the texel its coordinate picks, where the coordinate is
//! the straight line between the exact perspective coordinates at its sub-span's ends (the
//! documented mapping), within the documented bounds; equal `w` draws exactly the affine
//! mapping; depth, bands and modulation work; bad input neither panics nor strays.

#![allow(clippy::needless_range_loop)] // the two coordinates, side by side, read best indexed

use crate::common;

use common::{Recorder, Rng, Rule, reference_covers, window_points};
use embedded_graphics::{
    pixelcolor::{Gray8, Rgb565, Rgb888, RgbColor},
    prelude::*,
    primitives::Rectangle,
};
use fixed::types::{I16F16, I24F8};
use proptest::prelude::*;
use trirast::{
    Framebuffer, ShaderStyle, TextureStyle, Triangle,
    band::{Bands, Scene, SceneStyle},
    depth::{DepthBuffer, DepthTarget},
    geometry::{SubPixelTriangle, SubPoint},
    shading::Fragment,
    target::BlendTarget,
    texture::{Filter, Perspective, SubSpan, Texels, Wrap},
};

/// Texture side, in texels: each texel a colour of its own.
const SIDE: u32 = 64;

/// A `SIDE` x `SIDE` texture whose texel `(i, j)` is `(4i, 4j, 0)`.
fn indexed_texels() -> Vec<Rgb888> {
    indexed_texels_of(SIDE)
}

/// A `side` x `side` texture (`side` at most 64) whose texel `(i, j)` is `(4i, 4j, 0)`.
fn indexed_texels_of(side: u32) -> Vec<Rgb888> {
    (0..side * side)
        .map(|n| Rgb888::new(((n % side) * 4) as u8, ((n / side) * 4) as u8, 0))
        .collect()
}

/// Exact perspective texture coordinates at `p`, in texels: the barycentric weights divided
/// by `w`, normalised. `None` where the weights' sum vanishes (never inside the triangle).
fn exact_uv(v: [Point; 3], uv: [[I16F16; 2]; 3], w: [I16F16; 3], p: Point) -> Option<[f64; 2]> {
    let v = v.map(|q| (i128::from(q.x), i128::from(q.y)));
    let (px, py) = (i128::from(p.x), i128::from(p.y));
    let edge =
        |s: (i128, i128), t: (i128, i128)| (t.0 - s.0) * (py - s.1) - (t.1 - s.1) * (px - s.0);
    let e = [edge(v[1], v[2]), edge(v[2], v[0]), edge(v[0], v[1])];
    let w = w.map(|w| i128::from(w.to_bits()));
    // 1 / w_i as the product of the other two, over the product of all three.
    let others = [w[1] * w[2], w[0] * w[2], w[0] * w[1]];
    let den: i128 = (0..3).map(|i| e[i] * others[i]).sum();
    if den == 0 {
        return None;
    }
    // The exact rational values, converted only at the end: 2^-40 texel off at most.
    Some([0, 1].map(|k| {
        let num: i128 = (0..3)
            .map(|i| e[i] * others[i] * i128::from(uv[i][k].to_bits()))
            .sum();
        let whole = num.div_euclid(den);
        let rest = num.rem_euclid(den);
        (whole as f64 + rest as f64 / den as f64) / 65536.0
    }))
}

#[derive(Debug)]
struct Case {
    vertices: [Point; 3],
    uv: [[I16F16; 2]; 3],
    w: [I16F16; 3],
    sub_span: SubSpan,
    wrap: Wrap,
    window: Rectangle,
    /// The texture's side: a power of two (repeated by masking) or not (by division).
    side: u32,
}

fn random_case(seed: u64) -> Case {
    let mut rng = Rng(seed);
    let window = Rectangle::new(Point::new(-8, 5), Size::new(96, 64));
    let tl = window.top_left;
    let reach = if rng.range(0, 3) == 0 { 200 } else { 20 };
    let vertices = loop {
        let v = [(); 3].map(|()| {
            Point::new(
                rng.range(tl.x - reach, tl.x + 96 + reach),
                rng.range(tl.y - reach, tl.y + 64 + reach),
            )
        });
        if !(Triangle { vertices: v }).is_degenerate() {
            break v;
        }
    };
    // w from 1/4 to 4 (ratios up to 1:16), with random fractions; sometimes two equal.
    let mut w = [(); 3].map(|()| I16F16::from_bits(rng.range(1 << 14, 1 << 18)));
    if rng.range(0, 4) == 0 {
        w[1] = w[0];
    }
    let coordinate = |rng: &mut Rng| I16F16::from_bits(rng.range(-8 << 16, 72 << 16));
    let sub_span =
        [SubSpan::Pixels8, SubSpan::Pixels16, SubSpan::Pixels32][rng.range(0, 2) as usize];
    Case {
        vertices,
        uv: [(); 3].map(|()| [coordinate(&mut rng), coordinate(&mut rng)]),
        w,
        sub_span,
        wrap: if rng.range(0, 1) == 0 {
            Wrap::Clamp
        } else {
            Wrap::Repeat
        },
        window,
        side: [SIDE, SIDE, 37, 48][rng.range(0, 3) as usize],
    }
}

/// The documented mapping at pixel `x` of row `y`, whose run is `first..=last`: the straight
/// line between the exact perspective coordinates at the ends of the pixel's sub-span (which
/// starts a multiple of the length after the run's first pixel and ends at the next such pixel
/// or the run's last), with the slack allowed (1/256 at the ends, plus under 1.5 x 2^-16 a
/// pixel of step rounding), and the sub-span's ends.
fn documented(case: &Case, y: i32, (first, last): (i32, i32), x: i32) -> ([f64; 2], f64, [i32; 2]) {
    let sub_span = case.sub_span.pixels() as i32;
    let start = first + (x - first) / sub_span * sub_span;
    let end = (start + sub_span).min(last);
    let exact = |x: i32| exact_uv(case.vertices, case.uv, case.w, Point::new(x, y)).unwrap();
    let (a, b) = (exact(start), exact(end));
    let t = if end == start {
        0.0
    } else {
        f64::from(x - start) / f64::from(end - start)
    };
    let slack = 1.0 / 256.0 + 1.5 * f64::from(x - start) / 65536.0 + 1e-9;
    let line = [0, 1].map(|k| a[k] + (b[k] - a[k]) * t);
    (line, slack, [start, end])
}

/// The texel index along a side for coordinate `t`, nearest (half up) and addressed.
fn texel(t: f64, wrap: Wrap, side: u32) -> i64 {
    let index = (t + 0.5).floor() as i64;
    match wrap {
        Wrap::Repeat => index.rem_euclid(i64::from(side)),
        Wrap::Clamp => index.clamp(0, i64::from(side) - 1),
    }
}

/// Draws `case` (nearest, into a recorder of its window) and checks coverage against the
/// reference and each pixel's texel against the straight line between the exact perspective
/// coordinates at the ends of its sub-span: within 1/256 texel at the ends, plus the per-pixel
/// step's rounding (under 1.5 x 2^-16 texel a pixel) between.
fn check_case(case: &Case) -> Result<(), TestCaseError> {
    let texels = indexed_texels_of(case.side);
    let texture = Texels::new(&texels, case.side, case.side).unwrap();
    let style = TextureStyle::new(texture, case.uv)
        .with_wrap(case.wrap)
        .with_perspective(Perspective::new(case.w).with_sub_span(case.sub_span));
    let triangle = Triangle {
        vertices: case.vertices,
    };
    let mut target = Recorder::<Rgb888>::new(case.window);
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
    }
    let (left, width) = (case.window.top_left.x, case.window.size.width as i32);
    for y in case.window.rows() {
        // The row's run: its covered pixels, which are contiguous.
        let covered: Vec<i32> = (left..left + width)
            .filter(|&x| target.get(Point::new(x, y)).is_some())
            .collect();
        let (Some(&first), Some(&last)) = (covered.first(), covered.last()) else {
            continue;
        };
        for x in first..=last {
            let (line, slack, [start, end]) = documented(case, y, (first, last), x);
            let color = target.get(Point::new(x, y)).unwrap();
            let got = [i64::from(color.r() / 4), i64::from(color.g() / 4)];
            for k in 0..2 {
                let candidates = [
                    texel(line[k] - slack, case.wrap, case.side),
                    texel(line[k] + slack, case.wrap, case.side),
                ];
                prop_assert!(
                    candidates.contains(&got[k]),
                    "({}, {}) axis {}: texel {} but the coordinate is {} (sub-span {}..={}, {:?})",
                    x,
                    y,
                    k,
                    got[k],
                    line[k],
                    start,
                    end,
                    case
                );
            }
        }
    }
    Ok(())
}

/// Draws `case` with a perspective-correct shader of the two coordinates and checks every
/// fragment's values against the straight line between the exact perspective values at the
/// ends of its sub-span (the same bound as for textures, in attribute units); with equal `w`,
/// the fragments are the affine shader's, bit for bit.
fn check_shader_case(case: &Case) -> Result<(), TestCaseError> {
    let record = |w: Option<[I16F16; 3]>| {
        let fragments = std::cell::RefCell::new(Vec::new());
        let style = ShaderStyle::new(case.uv, |f: Fragment<2>| {
            fragments.borrow_mut().push(f);
            Gray8::WHITE
        });
        let triangle = Triangle {
            vertices: case.vertices,
        };
        let mut target = Recorder::<Gray8>::new(case.window);
        match w {
            Some(w) => {
                let perspective = Perspective::new(w).with_sub_span(case.sub_span);
                triangle
                    .into_styled(style.with_perspective(perspective))
                    .draw(&mut target)
            }
            None => triangle.into_styled(style).draw(&mut target),
        }
        .unwrap();
        assert_eq!(target.outside_writes, 0);
        fragments.into_inner()
    };
    let fragments = record(Some(case.w));
    // Each row's run from its fragments (one run per row, left to right).
    let mut rows = std::collections::BTreeMap::<i32, (i32, i32)>::new();
    for f in &fragments {
        let e = rows
            .entry(f.position.y)
            .or_insert((f.position.x, f.position.x));
        e.0 = e.0.min(f.position.x);
        e.1 = e.1.max(f.position.x);
    }
    for f in &fragments {
        let (x, y) = (f.position.x, f.position.y);
        prop_assert!(reference_covers(case.vertices, f.position, Rule::TopLeft));
        let (line, slack, _) = documented(case, y, rows[&y], x);
        for k in 0..2 {
            let got = f.values[k].to_num::<f64>();
            prop_assert!(
                (got - line[k]).abs() <= slack,
                "({}, {}) {}: {} vs {}",
                x,
                y,
                k,
                got,
                line[k]
            );
        }
    }
    // Equal w: the affine shader's fragments.
    let w = case.w[0];
    prop_assert_eq!(record(Some([w; 3])), record(None));
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    #[test]
    fn shader_attributes_follow_the_exact_perspective(seed in any::<u64>()) {
        check_shader_case(&random_case(seed))?;
    }

    #[test]
    fn nearest_follows_the_exact_perspective(seed in any::<u64>()) {
        check_case(&random_case(seed))?;
    }

    #[test]
    fn equal_w_draws_the_affine_mapping(seed in any::<u64>()) {
        let case = random_case(seed);
        let mut rng = Rng(seed ^ 0x5EED);
        let texels: Vec<Gray8> = (0..37).map(|_| Gray8::new(rng.range(0, 255) as u8)).collect();
        let texture = Texels::new(&texels, 37, 1).unwrap();
        let w = case.w[0];
        for filter in [Filter::Nearest, Filter::Bilinear] {
            let affine = TextureStyle::new(texture, case.uv).with_filter(filter).with_wrap(case.wrap);
            let perspective = affine.with_perspective(Perspective::new([w; 3]));
            let triangle = Triangle { vertices: case.vertices };
            let (mut a, mut b) = (Recorder::<Gray8>::new(case.window), Recorder::<Gray8>::new(case.window));
            triangle.into_styled(affine).draw(&mut a).unwrap();
            triangle.into_styled(perspective).draw(&mut b).unwrap();
            prop_assert!(a.colors == b.colors, "{:?} {:?}", filter, case);
        }
    }
}

/// Vertices, texture coordinates and `w` of a triangle.
type FloorTriangle = ([Point; 3], [[I16F16; 2]; 3], [I16F16; 3]);

/// A floor quad receding from the viewer: near edge at `w` = 1, far edge at `w` = `far`,
/// as two triangles over a 64 x 64 screen.
fn floor(far: i32) -> [FloorTriangle; 2] {
    let uv = |u: i32, v: i32| [I16F16::from_num(u), I16F16::from_num(v)];
    let (near, far) = (I16F16::ONE, I16F16::from_num(far));
    // Far edge narrow and high, near edge wide and low.
    let (fl, fr, nr, nl) = (
        Point::new(24, 8),
        Point::new(40, 8),
        Point::new(64, 64),
        Point::new(0, 64),
    );
    [
        (
            [fl, fr, nr],
            [uv(0, 0), uv(64, 0), uv(64, 64)],
            [far, far, near],
        ),
        (
            [fl, nr, nl],
            [uv(0, 0), uv(64, 64), uv(0, 64)],
            [far, near, near],
        ),
    ]
}

#[test]
fn a_floor_recedes_as_a_camera_sees_it() {
    // Far edge 4 times as far as the near one (the quad is 64 wide, the far edge a quarter).
    let texels = indexed_texels();
    let texture = Texels::new(&texels, SIDE, SIDE).unwrap();
    let mut pixels = [Rgb888::BLACK; 64 * 64];
    let mut display = Framebuffer::new(&mut pixels, 64, 64).unwrap();
    for (vertices, uv, w) in floor(4) {
        let style = TextureStyle::new(texture, uv).with_perspective(Perspective::new(w));
        Triangle { vertices }
            .into_styled(style)
            .draw(&mut display)
            .unwrap();
    }
    // Halfway down the texture (v = 32) is where 1/w is halfway between 1/4 and 1:
    // t = (1/2 * 1/4) / ((1/2) 1/4 + (1/2) 1) = 1/5 of the way from the far edge, row 19.2.
    let row_of = |y: i32| i32::from(display.pixel(Point::new(32, y)).unwrap().g() / 4);
    assert!(
        row_of(18) < 32 && row_of(20) >= 32,
        "{} {}",
        row_of(18),
        row_of(20)
    );
    // The affine mapping puts it halfway, at row 36.
    let mut affine_pixels = [Rgb888::BLACK; 64 * 64];
    let mut affine = Framebuffer::new(&mut affine_pixels, 64, 64).unwrap();
    for (vertices, uv, _) in floor(4) {
        let style = TextureStyle::new(texture, uv);
        Triangle { vertices }
            .into_styled(style)
            .draw(&mut affine)
            .unwrap();
    }
    let affine_row = |y: i32| i32::from(affine.pixel(Point::new(32, y)).unwrap().g() / 4);
    assert!(affine_row(34) < 32 && affine_row(37) >= 32);
}

#[test]
fn depth_bands_and_modulation_draw_what_the_plain_path_draws() {
    let texels: Vec<Rgb565> = indexed_texels().into_iter().map(Rgb565::from).collect();
    let texture = Texels::new(&texels, SIDE, SIDE).unwrap();
    for filter in [Filter::Nearest, Filter::Bilinear] {
        for wrap in [Wrap::Clamp, Wrap::Repeat] {
            let styles = floor(7).map(|(vertices, uv, w)| {
                let style = TextureStyle::new(texture, uv)
                    .with_filter(filter)
                    .with_wrap(wrap)
                    .with_modulation([Rgb565::WHITE, Rgb565::YELLOW, Rgb565::CYAN])
                    .with_perspective(Perspective::new(w).with_sub_span(SubSpan::Pixels8));
                (Triangle { vertices }, style)
            });
            let mut plain_pixels = [Rgb565::BLACK; 64 * 64];
            let mut plain = Framebuffer::new(&mut plain_pixels, 64, 64).unwrap();
            for (triangle, style) in styles {
                triangle.into_styled(style).draw(&mut plain).unwrap();
            }
            // Through a depth test that every pixel passes.
            let mut pixels = [Rgb565::BLACK; 64 * 64];
            let mut depths = [u16::MAX; 64 * 64];
            let mut display = Framebuffer::new(&mut pixels, 64, 64).unwrap();
            let mut zbuffer = DepthBuffer::new(&mut depths, 64, 64).unwrap();
            let mut scene = DepthTarget::new(&mut display, &mut zbuffer).unwrap();
            for (triangle, style) in styles {
                scene.draw(&triangle, [100, 200, 300], &style).unwrap();
            }
            assert!(pixels == plain_pixels, "depth, {filter:?} {wrap:?}");
            // In bands of 16 rows.
            let screen = Rectangle::new(Point::zero(), Size::new(64, 64));
            let mut scene = Scene::<Rgb565, 4>::new(screen);
            for (triangle, style) in styles {
                scene.push(triangle, SceneStyle::Texture(style)).unwrap();
            }
            let mut band = [Rgb565::BLACK; 64 * 16];
            let mut banded = [Rgb565::BLACK; 64 * 64];
            let mut frame = Framebuffer::new(&mut banded, 64, 64).unwrap();
            Bands::new(&mut band, 64, 16)
                .unwrap()
                .render(&scene, Rgb565::BLACK, &mut frame)
                .unwrap();
            assert!(banded == plain_pixels, "bands, {filter:?} {wrap:?}");
        }
    }
}

#[test]
fn extreme_input_is_safe() {
    let texels = indexed_texels();
    let texture = Texels::new(&texels, SIDE, SIDE).unwrap();
    let window = Rectangle::new(Point::new(-3, -3), Size::new(40, 30));
    let weights = [
        [I16F16::ZERO, -I16F16::ONE, I16F16::MIN],
        [I16F16::DELTA, I16F16::MAX, I16F16::ONE],
        [I16F16::MAX, I16F16::MAX, I16F16::DELTA],
        [I16F16::DELTA; 3],
    ];
    let coordinates = [
        [[I16F16::MIN; 2], [I16F16::MAX; 2], [I16F16::ZERO; 2]],
        [
            [I16F16::MAX, I16F16::MIN],
            [I16F16::ZERO; 2],
            [I16F16::MIN, I16F16::MAX],
        ],
    ];
    let vertices = [
        [Point::new(0, 0), Point::new(30, 2), Point::new(5, 25)],
        [
            Point::new(i32::MIN, i32::MIN),
            Point::new(i32::MAX, 0),
            Point::new(0, i32::MAX),
        ],
        [
            Point::new(-5, -100_000),
            Point::new(36, 20),
            Point::new(-1_000_000, 27),
        ],
        [Point::new(0, 0), Point::new(1, 29), Point::new(2, 0)],
    ];
    for w in weights {
        for uv in coordinates {
            for v in vertices {
                for filter in [Filter::Nearest, Filter::Bilinear] {
                    for wrap in [Wrap::Clamp, Wrap::Repeat] {
                        for sub_span in [SubSpan::Pixels8, SubSpan::Pixels32] {
                            let style = TextureStyle::new(texture, uv)
                                .with_filter(filter)
                                .with_wrap(wrap)
                                .with_perspective(Perspective::new(w).with_sub_span(sub_span));
                            let mut target = Recorder::<Rgb888>::new(window);
                            Triangle { vertices: v }
                                .into_styled(style)
                                .draw(&mut target)
                                .unwrap();
                            assert_eq!(target.outside_writes, 0);
                            for p in window_points(&window) {
                                let covered = reference_covers(v, p, Rule::TopLeft);
                                assert_eq!(target.writes_at(p), u32::from(covered), "{p:?}");
                            }
                            // The same corners in 1/256 pixel, moved by a fraction (and
                            // saturated), and through a depth test and anti-aliasing.
                            let sub = v.map(|p| {
                                let at = |t: i32| {
                                    I24F8::from_bits(t.saturating_mul(256).saturating_add(77))
                                };
                                SubPoint::new(at(p.x), at(p.y))
                            });
                            let shape = SubPixelTriangle { vertices: sub };
                            let mut target = Recorder::<Rgb888>::new(window);
                            shape.into_styled(style).draw(&mut target).unwrap();
                            assert_eq!(target.outside_writes, 0);
                            let mut pixels = [Rgb888::BLACK; 40 * 30];
                            let mut depths = [u16::MAX; 40 * 30];
                            let mut frame = Framebuffer::new(&mut pixels, 40, 30).unwrap();
                            frame.draw_anti_aliased(&shape, &style).unwrap();
                            let mut zbuffer = DepthBuffer::new(&mut depths, 40, 30).unwrap();
                            let mut scene = DepthTarget::new(&mut frame, &mut zbuffer).unwrap();
                            scene.draw(&shape, [0, 30_000, u16::MAX], &style).unwrap();
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn anti_aliased_and_translucent_perspective_textures_draw() {
    let texels = indexed_texels();
    let texture = Texels::new(&texels, SIDE, SIDE).unwrap();
    for seed in 0..200u64 {
        let case = random_case(seed);
        let style = TextureStyle::new(texture, case.uv)
            .with_wrap(case.wrap)
            .with_perspective(Perspective::new(case.w));
        let triangle = Triangle {
            vertices: case.vertices,
        };
        let (w, h) = (96u32, 64u32);
        let mut plain_pixels = vec![Rgb888::BLACK; (w * h) as usize];
        let mut plain = Framebuffer::new(&mut plain_pixels, w, h).unwrap();
        triangle.into_styled(style).draw(&mut plain).unwrap();
        // Opaque through the translucent target: the plain frame.
        let mut pixels = vec![Rgb888::BLACK; (w * h) as usize];
        let mut frame = Framebuffer::new(&mut pixels, w, h).unwrap();
        triangle
            .into_styled(style)
            .draw(&mut frame.translucent(255))
            .unwrap();
        assert!(pixels == plain_pixels, "translucent, seed {seed}");
        // Anti-aliased: anti-aliasing paints the interior apart from the edge pixels, so its
        // runs, and the sub-spans counted from their first pixels, differ from the plain
        // draw's (each within the bounds checked above). Pixels whose whole square is covered
        // take texels of the triangle's coordinate range.
        let mut smooth_pixels = vec![Rgb888::BLACK; (w * h) as usize];
        let mut smooth = Framebuffer::new(&mut smooth_pixels, w, h).unwrap();
        smooth.draw_anti_aliased(&triangle, &style).unwrap();
        let inside = |x: i32, y: i32| {
            [(-1, -1), (1, -1), (-1, 1), (1, 1), (0, 0)]
                .iter()
                .all(|&(dx, dy)| {
                    let p = Point::new(x + dx, y + dy);
                    reference_covers(case.vertices, p, Rule::Inclusive)
                })
        };
        for y in 1..h as i32 - 1 {
            for x in 1..w as i32 - 1 {
                if inside(x, y) {
                    let i = (y as u32 * w + x as u32) as usize;
                    let texel = [smooth_pixels[i].r(), smooth_pixels[i].g()].map(|c| c / 4);
                    for k in 0..2 {
                        let range = case.uv.map(|c| c[k].to_num::<f64>());
                        let low = range.iter().copied().fold(f64::MAX, f64::min).floor() - 1.0;
                        let high = range.iter().copied().fold(f64::MIN, f64::max).ceil() + 1.0;
                        let (low, high) = (low.max(0.0), high.min(f64::from(SIDE - 1)));
                        let t = f64::from(texel[k]);
                        assert!(
                            case.wrap == Wrap::Repeat || (low..=high).contains(&t),
                            "({x}, {y}) seed {seed}: texel {t} outside {low}..={high}"
                        );
                    }
                }
            }
        }
    }
}
