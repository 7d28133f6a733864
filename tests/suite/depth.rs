//! Depth testing against exact rational depths computed in `i128` here: interpolated depths
//! within one unit, vertices exact, the nearer surface winning every pixel where the exact
//! depths differ, equal depths following the test, every style agreeing with plain drawing,
//! and meshes staying watertight and culling by winding.

use crate::common;

use common::{Recorder, Rng, Rule, exact_plane, reference_covers, window_points};
use embedded_graphics::{
    pixelcolor::{Rgb565, Rgb888, RgbColor},
    prelude::*,
    primitives::Rectangle,
};
use fixed::types::I16F16;
use proptest::prelude::*;
use trirast::{
    Error, FlatStyle, GouraudStyle, Orientation, ShaderStyle, TextureStyle, Triangle,
    depth::{DepthBuffer, DepthTarget, DepthTest},
    geometry::Viewport,
    mesh::{Cull, Mesh},
    shading::{Fragment, TriangleStyle},
    texture::{Filter, Texels},
};

const TESTS: [DepthTest; 5] = [
    DepthTest::Less,
    DepthTest::LessOrEqual,
    DepthTest::Greater,
    DepthTest::GreaterOrEqual,
    DepthTest::Always,
];

fn window() -> Rectangle {
    Rectangle::new(Point::new(-6, 3), Size::new(40, 36))
}

fn random_triangle(rng: &mut Rng, window: &Rectangle, reach: i32) -> [Point; 3] {
    let tl = window.top_left;
    let (w, h) = (window.size.width as i32, window.size.height as i32);
    loop {
        let v = [(); 3].map(|()| {
            Point::new(
                rng.range(tl.x - reach, tl.x + w + reach),
                rng.range(tl.y - reach, tl.y + h + reach),
            )
        });
        if !(Triangle { vertices: v }).is_degenerate() {
            return v;
        }
    }
}

/// The exact depth at `p`: `(numerator, positive denominator)`.
fn exact_depth(v: [Point; 3], depths: [u16; 3], p: Point) -> (i128, i128) {
    exact_plane(v, depths.map(i64::from), p).unwrap()
}

/// Draws one triangle with `test` and writes on into a recorder and a buffer prefilled with
/// `stored`; returns both.
fn draw_one<S: TriangleStyle<Color = Rgb565>>(
    v: [Point; 3],
    depths: [u16; 3],
    style: &S,
    stored: &[u16],
    test: DepthTest,
    write: bool,
) -> (Recorder<Rgb565>, Vec<u16>) {
    let window = window();
    let mut target = Recorder::<Rgb565>::new(window);
    let mut memory = stored.to_vec();
    let mut zbuffer = DepthBuffer::new(&mut memory, window.size.width, window.size.height).unwrap();
    let mut scene = DepthTarget::new(&mut target, &mut zbuffer)
        .unwrap()
        .with_test(test)
        .with_write(write);
    scene
        .draw(&Triangle { vertices: v }, depths, style)
        .unwrap();
    (target, memory)
}

/// A colour of every `Rgb565` level, from `rng`.
fn random_rgb565(rng: &mut Rng) -> Rgb565 {
    Rgb565::new(
        rng.range(0, 31) as u8,
        rng.range(0, 63) as u8,
        rng.range(0, 31) as u8,
    )
}

/// A colour of every `Rgb888` level, from `rng`.
fn random_rgb888(rng: &mut Rng) -> Rgb888 {
    Rgb888::new(
        rng.range(0, 255) as u8,
        rng.range(0, 255) as u8,
        rng.range(0, 255) as u8,
    )
}

fn index(window: &Rectangle, p: Point) -> usize {
    ((p.y - window.top_left.y) * window.size.width as i32 + (p.x - window.top_left.x)) as usize
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// With `Always`, every covered pixel is written with its interpolated depth: within one
    /// unit of exact, exact at vertices; nothing else changes.
    #[test]
    fn depths_are_within_one_of_exact(seed in any::<u64>()) {
        let mut rng = Rng(seed);
        let window = window();
        let reach = [0, 20, 400][rng.range(0, 2) as usize];
        let v = random_triangle(&mut rng, &window, reach);
        let depths = [(); 3].map(|()| rng.range(0, 65535) as u16);
        let sentinel = vec![12_345u16; (window.size.width * window.size.height) as usize];
        let (target, stored) = draw_one(v, depths, &FlatStyle::new(Rgb565::RED), &sentinel, DepthTest::Always, true);
        prop_assert_eq!(target.outside_writes, 0);
        for p in window_points(&window) {
            let covered = reference_covers(v, p, Rule::TopLeft);
            prop_assert_eq!(target.writes_at(p), u32::from(covered), "coverage at {:?}", p);
            let got = i128::from(stored[index(&window, p)]);
            if covered {
                let (num, den) = exact_depth(v, depths, p);
                prop_assert!((got * den - num).abs() <= den, "{:?}: {} vs {}/{}", p, got, num, den);
                if let Some(k) = v.iter().position(|&q| q == p) {
                    prop_assert_eq!(got, i128::from(depths[k]), "vertex {}", k);
                }
            } else {
                prop_assert_eq!(got, 12_345);
            }
        }
    }

    /// Each test draws exactly the pixels whose depth passes against what is stored, writing
    /// depths only when asked; the fast (whole span) and slow (runs) paths agree with it.
    #[test]
    fn each_test_draws_exactly_the_passing_pixels(seed in any::<u64>()) {
        let mut rng = Rng(seed);
        let window = window();
        let v = random_triangle(&mut rng, &window, 10);
        let depths = [(); 3].map(|()| rng.range(0, 65535) as u16);
        let n = (window.size.width * window.size.height) as usize;
        // What the triangle's depths are, per pixel, from an `Always` draw.
        let (_, interpolated) = draw_one(v, depths, &FlatStyle::new(Rgb565::RED), &vec![0; n], DepthTest::Always, true);
        // Stored depths: a random plane-ish field, so that some spans pass whole, some fail
        // whole and some split.
        let (a, b, c) = (rng.range(-400, 400), rng.range(-400, 400), rng.range(0, 65535));
        let stored: Vec<u16> = (0..n)
            .map(|i| {
                let (x, y) = ((i % window.size.width as usize) as i32, (i / window.size.width as usize) as i32);
                (c + a * x + b * y).clamp(0, 65535) as u16
            })
            .collect();
        let test = TESTS[rng.range(0, 4) as usize];
        let write = rng.range(0, 1) == 1;
        let (target, after) = draw_one(v, depths, &FlatStyle::new(Rgb565::RED), &stored, test, write);
        // The same through a Gouraud style whose lanes carry the depth plane (`Rgb565`): the
        // same pixels pass, each with the colour plain drawing gives it.
        let colors = [(); 3].map(|()| random_rgb565(&mut rng));
        let gouraud = GouraudStyle::new(colors);
        let (shaded, shaded_after) = draw_one(v, depths, &gouraud, &stored, test, write);
        let mut plain = Recorder::<Rgb565>::new(window);
        Triangle { vertices: v }.into_styled(gouraud).draw(&mut plain).unwrap();
        for p in window_points(&window) {
            let i = index(&window, p);
            let covered = reference_covers(v, p, Rule::TopLeft);
            let passes = covered && test.passes(interpolated[i], stored[i]);
            prop_assert_eq!(target.writes_at(p), u32::from(passes), "{:?} {:?}", p, test);
            let want = if passes && write { interpolated[i] } else { stored[i] };
            prop_assert_eq!(after[i], want, "{:?}", p);
            prop_assert_eq!(shaded.writes_at(p), u32::from(passes), "Gouraud {:?} {:?}", p, test);
            if passes {
                prop_assert_eq!(shaded.get(p), plain.get(p), "Gouraud {:?}", p);
            }
            prop_assert_eq!(shaded_after[i], want, "Gouraud {:?}", p);
        }
    }

    /// Two triangles crossing in depth: see [`nearer_surface_wins`].
    #[test]
    fn the_nearer_surface_wins(seed in any::<u64>()) {
        nearer_surface_wins(seed)?;
    }
}

/// Two triangles crossing in depth: wherever their exact depths differ by two units or more the
/// nearer one shows, and the buffer holds its depth.
fn nearer_surface_wins(seed: u64) -> Result<(), TestCaseError> {
    let mut rng = Rng(seed);
    let window = window();
    let (va, vb) = (
        random_triangle(&mut rng, &window, 10),
        random_triangle(&mut rng, &window, 10),
    );
    let da = [(); 3].map(|()| rng.range(0, 65535) as u16);
    let db = [(); 3].map(|()| rng.range(0, 65535) as u16);
    let mut target = Recorder::<Rgb565>::new(window);
    let mut memory = vec![u16::MAX; (window.size.width * window.size.height) as usize];
    let mut zbuffer = DepthBuffer::new(&mut memory, window.size.width, window.size.height).unwrap();
    let mut scene = DepthTarget::new(&mut target, &mut zbuffer).unwrap();
    scene
        .draw(&Triangle { vertices: va }, da, &FlatStyle::new(Rgb565::RED))
        .unwrap();
    scene
        .draw(
            &Triangle { vertices: vb },
            db,
            &GouraudStyle::new([Rgb565::BLUE; 3]),
        )
        .unwrap();
    for p in window_points(&window) {
        let (ca, cb) = (
            reference_covers(va, p, Rule::TopLeft),
            reference_covers(vb, p, Rule::TopLeft),
        );
        let shown = target.get(p);
        let depth = i128::from(memory[index(&window, p)]);
        let near = |(num, den): (i128, i128)| (depth * den - num).abs() <= den;
        match (ca, cb) {
            (false, false) => prop_assert_eq!(shown, None),
            // Alone, a surface shows unless its depth rounds to the cleared 65,535, which
            // `Less` rejects: certain only where the exact depth is below 65,534 (the drawn
            // depth is within one unit of it).
            (true, false) | (false, true) => {
                let (exact, color) = if ca {
                    (exact_depth(va, da, p), Rgb565::RED)
                } else {
                    (exact_depth(vb, db, p), Rgb565::BLUE)
                };
                if exact.0 < 65_534 * exact.1 {
                    prop_assert_eq!(shown, Some(color), "{:?}", p);
                }
                if shown.is_some() {
                    prop_assert_eq!(shown, Some(color), "{:?}", p);
                    prop_assert!(near(exact));
                }
            }
            (true, true) => {
                let (a, b) = (exact_depth(va, da, p), exact_depth(vb, db, p));
                // a - b in units of 1 / (den_a * den_b).
                let diff = a.0 * b.1 - b.0 * a.1;
                let two = 2 * a.1 * b.1;
                if diff >= two {
                    prop_assert_eq!(shown, Some(Rgb565::BLUE), "{:?}", p);
                    prop_assert!(near(b));
                } else if -diff >= two {
                    prop_assert_eq!(shown, Some(Rgb565::RED), "{:?}", p);
                    prop_assert!(near(a));
                }
            }
        }
    }
    Ok(())
}

/// A seed that once failed: triangle A has a vertex of depth 65,535 alone on pixel (5, 18),
/// which `Less` against a buffer cleared to 65,535 rightly leaves undrawn.
#[test]
fn a_surface_at_the_cleared_depth_may_stay_hidden() {
    nearer_surface_wins(5_625_256_401_240_684_642).unwrap();
}

/// A surface drawn twice at the same depths: strict tests keep the first, the others let the
/// second through.
#[test]
fn equal_depths_follow_the_test() {
    let v = [Point::new(-3, 4), Point::new(30, 10), Point::new(5, 36)];
    let depths = [1000, 40_000, 20_000];
    let window = window();
    for (test, cleared, second_shows) in [
        (DepthTest::Less, u16::MAX, false),
        (DepthTest::LessOrEqual, u16::MAX, true),
        (DepthTest::Greater, 0, false),
        (DepthTest::GreaterOrEqual, 0, true),
        (DepthTest::Always, 0, true),
    ] {
        let mut target = Recorder::<Rgb565>::new(window);
        let mut memory = vec![cleared; (window.size.width * window.size.height) as usize];
        let mut zbuffer = DepthBuffer::new(&mut memory, 40, 36).unwrap();
        let mut scene = DepthTarget::new(&mut target, &mut zbuffer)
            .unwrap()
            .with_test(test);
        let t = Triangle { vertices: v };
        scene
            .draw(&t, depths, &FlatStyle::new(Rgb565::RED))
            .unwrap();
        scene
            .draw(&t, depths, &FlatStyle::new(Rgb565::GREEN))
            .unwrap();
        let want = if second_shows {
            Rgb565::GREEN
        } else {
            Rgb565::RED
        };
        let drawn: Vec<Rgb565> = target.colors.iter().flatten().copied().collect();
        assert!(drawn.len() > 300);
        assert!(drawn.iter().all(|&c| c == want), "{test:?}");
    }
}

/// Draws `style` plainly and through an all-passing depth test: the same pixels.
fn compare<S: TriangleStyle<Color = Rgb565> + Copy>(v: [Point; 3], style: S)
where
    Triangle: embedded_graphics::primitives::StyledDrawable<S, Color = Rgb565, Output = ()>,
{
    let mut plain = Recorder::<Rgb565>::new(window());
    Triangle { vertices: v }
        .into_styled(style)
        .draw(&mut plain)
        .unwrap();
    let (layered, _) = draw_one(
        v,
        [9, 900, 90],
        &style,
        &vec![u16::MAX; 40 * 36],
        DepthTest::Less,
        true,
    );
    assert_eq!(plain.colors, layered.colors, "{v:?}");
}

/// Every style draws through the depth test exactly as it draws without one when all pixels
/// pass.
#[test]
fn styles_draw_alike_with_and_without_depth() {
    let mut rng = Rng(42);
    let texels: Vec<Rgb565> = (0..64)
        .map(|i| Rgb565::new(i as u8 % 32, (i * 3) as u8 % 64, 31 - i as u8 % 32))
        .collect();
    let texture = Texels::new(&texels, 8, 8).unwrap();
    let window = window();
    for _ in 0..200 {
        let v = random_triangle(&mut rng, &window, 15);
        let colors = [(); 3].map(|()| random_rgb565(&mut rng));
        let uv = [(); 3].map(|()| {
            [
                I16F16::from_bits(rng.range(-600_000, 600_000)),
                I16F16::from_bits(rng.range(-600_000, 600_000)),
            ]
        });
        compare(v, FlatStyle::new(colors[0]));
        compare(v, GouraudStyle::new(colors));
        compare(v, GouraudStyle::new(colors).with_dither(true));
        compare(
            v,
            TextureStyle::new(texture, uv).with_filter(Filter::Bilinear),
        );
        compare(v, TextureStyle::new(texture, uv).with_modulation(colors));
        compare(
            v,
            ShaderStyle::new(
                [[I16F16::ONE], [I16F16::ZERO], [I16F16::from_num(0.5)]],
                |f: Fragment<1>| Rgb565::new(f.values[0].to_bits() as u8 & 31, 0, 0),
            ),
        );
    }
}

/// Colours of pixels in runs broken by the depth test stay within `tolerance` levels of the
/// same pixels drawn whole (each run restarts from exactly computed values).
fn broken_runs_keep_colours<C>(seed: u64, random_color: fn(&mut Rng) -> C, tolerance: u8)
where
    C: RgbColor + core::fmt::Debug,
    GouraudStyle<C>: TriangleStyle<Color = C>,
    Triangle:
        embedded_graphics::primitives::StyledDrawable<GouraudStyle<C>, Color = C, Output = ()>,
{
    let mut rng = Rng(seed);
    let window = window();
    for _ in 0..300 {
        let v = random_triangle(&mut rng, &window, 10);
        let colors = [(); 3].map(|()| random_color(&mut rng));
        let style = GouraudStyle::new(colors);
        let mut plain = Recorder::<C>::new(window);
        Triangle { vertices: v }
            .into_styled(style)
            .draw(&mut plain)
            .unwrap();
        // A checkered depth field: every span breaks into runs.
        let closed = |i: usize| (i % 40 + i / 40).is_multiple_of(3);
        let mut memory: Vec<u16> = (0..40 * 36)
            .map(|i| if closed(i) { 0 } else { u16::MAX })
            .collect();
        let mut zbuffer = DepthBuffer::new(&mut memory, 40, 36).unwrap();
        let mut layered = Recorder::<C>::new(window);
        DepthTarget::new(&mut layered, &mut zbuffer)
            .unwrap()
            .draw(&Triangle { vertices: v }, [500; 3], &style)
            .unwrap();
        let mut drawn = 0;
        for p in window_points(&window) {
            if let Some(c) = layered.get(p) {
                drawn += 1;
                let want = plain.get(p).unwrap();
                for (g, w) in [(c.r(), want.r()), (c.g(), want.g()), (c.b(), want.b())] {
                    assert!(g.abs_diff(w) <= tolerance, "{p:?}: {c:?} vs {want:?}");
                }
            }
        }
        // The pixels the checkers leave open are drawn, those they close are not.
        let open = window_points(&window)
            .filter(|&p| plain.get(p).is_some() && !closed(index(&window, p)))
            .count();
        assert_eq!(drawn, open, "{v:?}");
    }
}

#[test]
fn broken_runs_keep_their_colours() {
    broken_runs_keep_colours(7, random_rgb888, 1);
}

/// `Rgb565` Gouraud triangles step packed lanes, whose levels depend on the pixel alone: runs
/// broken by the depth test draw exactly the colours of the whole spans (the depth pass
/// carries its plane with the lanes, moved to each run's start).
#[test]
fn broken_runs_of_packed_lanes_keep_their_colours_exactly() {
    broken_runs_keep_colours(8, random_rgb565, 0);
}

#[test]
fn mismatched_buffers_are_errors() {
    let mut target = Recorder::<Rgb565>::new(window());
    let mut memory = vec![0u16; 40 * 35];
    assert!(matches!(
        DepthBuffer::new(&mut memory, 40, 36),
        Err(Error::BufferLength { .. })
    ));
    let mut zbuffer = DepthBuffer::new(&mut memory, 35, 40).unwrap();
    let Err(error) = DepthTarget::new(&mut target, &mut zbuffer) else {
        panic!("a 35x40 buffer accepted for a 40x36 target");
    };
    assert_eq!(
        error,
        Error::DepthBufferSize {
            buffer: Size::new(35, 40),
            target: Size::new(40, 36)
        }
    );
}

/// A jittered grid mesh at one depth, drawn through the depth test: every pixel exactly once.
/// Culling skips exactly the triangles of the culled winding.
#[test]
fn meshes_are_watertight_and_cull_by_winding() {
    let mut rng = Rng(3);
    let (nx, ny) = (8, 7);
    let window = window();
    let vertices: Vec<(Point, u16)> = (0..=ny)
        .flat_map(|j| (0..=nx).map(move |i| (i, j)))
        .map(|(i, j)| {
            let inner = i > 0 && i < nx && j > 0 && j < ny;
            let jitter = |r: &mut Rng| if inner { r.range(-1, 1) } else { 0 };
            let p = Point::new(
                window.top_left.x + i * 5 + jitter(&mut rng),
                window.top_left.y + j * 5 + jitter(&mut rng),
            );
            (p, 700)
        })
        .collect();
    let at = |i: i32, j: i32| (j * (nx + 1) + i) as u16;
    let mut triangles = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            // Alternate the diagonal and the winding.
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if (i + j) % 2 == 0 {
                triangles.push([a, b, c]);
                triangles.push([a, d, c]);
            } else {
                triangles.push([b, a, d]);
                triangles.push([b, c, d]);
            }
        }
    }
    let mesh = Mesh::new(&vertices, &triangles).unwrap();
    for cull in [Cull::None, Cull::Clockwise, Cull::CounterClockwise] {
        let mut target = Recorder::<Rgb565>::new(window);
        let mut memory = vec![u16::MAX; 40 * 36];
        let mut zbuffer = DepthBuffer::new(&mut memory, 40, 36).unwrap();
        let mut scene = DepthTarget::new(&mut target, &mut zbuffer)
            .unwrap()
            .with_test(DepthTest::LessOrEqual);
        mesh.draw_with_depth(&mut scene, cull, |_, _| FlatStyle::new(Rgb565::WHITE))
            .unwrap();
        let mut want = Recorder::<Rgb565>::new(window);
        for t in &triangles {
            let v = t.map(|i| vertices[i as usize].0);
            let orientation = Triangle { vertices: v }.orientation();
            if !cull.skips(orientation) {
                for p in window_points(&window).filter(|&p| reference_covers(v, p, Rule::TopLeft)) {
                    want.draw_iter([Pixel(p, Rgb565::WHITE)]).unwrap();
                }
            }
        }
        assert_eq!(target.writes, want.writes, "{cull:?}");
        if cull == Cull::None {
            let covered = (0..nx * 5).len() * (0..ny * 5).len();
            assert_eq!(target.writes.iter().filter(|&&n| n == 1).count(), covered);
            assert!(target.writes.iter().all(|&n| n <= 1));
        }
    }
    assert!(Cull::Clockwise.skips(Orientation::Clockwise));
    assert!(matches!(
        Mesh::new(&vertices, &[[0, 1, 999]]),
        Err(Error::MeshIndex {
            triangle: 0,
            index: 999
        })
    ));
}

/// A quad from NDC corners covers its viewport exactly; the centre maps to the middle pixel.
#[test]
fn ndc_quad_covers_the_viewport() {
    let window = window();
    let viewport = Viewport::new(window);
    let one = I16F16::ONE;
    let corners =
        [[-one, one], [one, one], [one, -one], [-one, -one]].map(|c| viewport.to_pixel(c));
    assert_eq!(corners[0], window.top_left);
    assert_eq!(corners[2], window.top_left + window.size);
    let mut target = Recorder::<Rgb565>::new(window);
    for [a, b, c] in [[0, 1, 2], [0, 2, 3]] {
        Triangle::new(corners[a], corners[b], corners[c])
            .into_styled(FlatStyle::new(Rgb565::WHITE))
            .draw(&mut target)
            .unwrap();
    }
    assert!(target.writes.iter().all(|&n| n == 1));
    assert_eq!(target.outside_writes, 0);
    // NDC 0 is the middle of the area's extent: left + width / 2.
    assert_eq!(
        viewport.to_pixel([I16F16::ZERO; 2]),
        window.top_left + window.size / 2
    );
}
