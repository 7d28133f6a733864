//! Sub-pixel triangles: coverage equals the exact half-space reference (the sample points
//! scaled by 256, vertices in 1/256 pixel) for random triangles of every kind; whole-pixel
//! vertices give exactly what `Triangle` gives; meshes with shared sub-pixel vertices cover
//! every pixel once; and a triangle sliding by 1/256 pixel changes each pixel at most once.

mod common;

use common::{jittered_grid, reference_covers, Rng, Rule};
use embedded_graphics::{prelude::*, primitives::Rectangle};
use fixed::types::I24F8;
use proptest::prelude::*;
use trirast::{
    coverage::{for_each_span, for_each_subpixel_span},
    geometry::{SubPixelTriangle, SubPoint},
    Triangle,
};

/// Vertex coordinates in 1/256 pixel, the type's whole range.
const LIMIT: i32 = i32::MAX;

fn sub(raw: [(i32, i32); 3]) -> SubPixelTriangle {
    let p = |(x, y): (i32, i32)| SubPoint::new(I24F8::from_bits(x), I24F8::from_bits(y));
    SubPixelTriangle::new(p(raw[0]), p(raw[1]), p(raw[2]))
}

/// Pixels of `window` the walk covers, row-major, checking each is emitted once and inside.
fn covered(t: &SubPixelTriangle, rule: Rule, window: &Rectangle) -> Vec<bool> {
    let (w, h) = (window.size.width as i64, window.size.height as i64);
    let mut out = vec![false; (w * h) as usize];
    for_each_subpixel_span(t, rule.to_crate(), window, |span| {
        assert!(span.len > 0);
        for k in 0..i64::from(span.len) {
            let x = i64::from(span.x) + k - i64::from(window.top_left.x);
            let y = i64::from(span.y) - i64::from(window.top_left.y);
            assert!(
                x >= 0 && x < w && y >= 0 && y < h,
                "{span:?} outside {window:?}"
            );
            let i = (y * w + x) as usize;
            assert!(!out[i], "pixel twice");
            out[i] = true;
        }
        Ok::<(), ()>(())
    })
    .unwrap();
    out
}

/// Every pixel of `window` against the exact reference: the sample point scaled by 256 in the
/// half-space test of the raw vertices.
fn check(raw: [(i32, i32); 3], rule: Rule, window: Rectangle) -> Result<(), TestCaseError> {
    let t = sub(raw);
    let got = covered(&t, rule, &window);
    let v = raw.map(|(x, y)| Point::new(x, y));
    for (i, &hit) in got.iter().enumerate() {
        let p = window.top_left
            + Point::new(
                i as i32 % window.size.width as i32,
                i as i32 / window.size.width as i32,
            );
        let sample = Point::new(p.x * 256, p.y * 256);
        prop_assert_eq!(
            hit,
            reference_covers(v, sample, rule),
            "{:?} {:?} at {:?}",
            raw,
            rule,
            p
        );
    }
    Ok(())
}

/// A window of up to 40 x 40 pixels near the origin or far out (its samples, scaled by 256,
/// must fit `i32`).
fn window() -> impl Strategy<Value = Rectangle> {
    let far = (1 << 23) - 60;
    let origin = prop_oneof![
        4 => (-30..30i32, -30..30i32),
        1 => (-far..far, -far..far),
        1 => (prop_oneof![Just(-far), Just(far)], prop_oneof![Just(-far), Just(far)]),
    ];
    (origin, 1..40u32, 1..40u32)
        .prop_map(|((x, y), w, h)| Rectangle::new(Point::new(x, y), Size::new(w, h)))
}

/// Random sub-pixel triangles around `window`: over it, tiny, slivers, huge and reaching the
/// range's ends, flat-topped, degenerate, on whole or half pixels.
fn triangle_for(window: Rectangle) -> impl Strategy<Value = [(i32, i32); 3]> {
    let c = window.center();
    let (cx, cy) = (i64::from(c.x) * 256, i64::from(c.y) * 256);
    let clamp = |v: i64| v.clamp(-i64::from(LIMIT), i64::from(LIMIT)) as i32;
    let local = move |spread: i64| {
        (-spread..=spread, -spread..=spread)
            .prop_map(move |(dx, dy)| (clamp(cx + dx), clamp(cy + dy)))
            .boxed()
    };
    let any_point = (any::<i32>(), any::<i32>()).boxed();
    prop_oneof![
        6 => [local(25 * 256), local(25 * 256), local(25 * 256)],
        3 => [local(400 * 256), local(400 * 256), local(400 * 256)],
        3 => (local(25 * 256), -800..800i32, -800..800i32, -800..800i32, -800..800i32)
            .prop_map(|(a, dx1, dy1, dx2, dy2)| [a, (a.0.saturating_add(dx1), a.1.saturating_add(dy1)), (a.0.saturating_add(dx2), a.1.saturating_add(dy2))]),
        2 => [any_point.clone(), any_point.clone(), local(30 * 256)],
        1 => [any_point.clone(), any_point.clone(), any_point],
        2 => (local(30 * 256), local(30 * 256), -40 * 256..40 * 256i32)
            .prop_map(|(a, b, dx)| [a, (a.0.saturating_add(dx), a.1), b]),
        2 => (local(30 * 256), -15_000..15_000i32, -15_000..15_000i32, -300..300i32)
            .prop_map(|(a, dx, dy, e)| [a, (a.0.saturating_add(dx), a.1.saturating_add(dy)), (a.0.saturating_add(2 * dx + e), a.1.saturating_add(2 * dy))]),
        2 => [local(20 * 256), local(20 * 256), local(20 * 256)]
            .prop_map(|v| v.map(|(x, y)| (x & !127, y & !127))),
    ]
}

fn case() -> impl Strategy<Value = (Rectangle, [(i32, i32); 3], Rule)> {
    window().prop_flat_map(|w| {
        (
            Just(w),
            triangle_for(w),
            prop_oneof![Just(Rule::TopLeft), Just(Rule::Inclusive)],
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn coverage_is_the_exact_half_space_test((window, raw, rule) in case()) {
        check(raw, rule, window)?;
    }

    /// Whole-pixel vertices: the spans of the integer walk, one for one.
    #[test]
    fn whole_pixels_draw_what_triangle_draws(
        (window, raw, rule) in case(),
    ) {
        let v = raw.map(|(x, y)| Point::new(x >> 8, y >> 8));
        let whole = Triangle::new(v[0], v[1], v[2]);
        let t = SubPixelTriangle::from(whole);
        let mut a = Vec::new();
        let mut b = Vec::new();
        for_each_span(&whole, rule.to_crate(), &window, |s| { a.push(s); Ok::<(), ()>(()) }).unwrap();
        for_each_subpixel_span(&t, rule.to_crate(), &window, |s| { b.push(s); Ok::<(), ()>(()) }).unwrap();
        prop_assert_eq!(a, b);
    }
}

#[test]
fn ends_of_the_range() {
    let ends = [i32::MIN, i32::MIN + 1, -1, 0, 1, i32::MAX - 1, i32::MAX];
    let far = (1 << 23) - 41;
    let windows = [
        Rectangle::new(Point::new(-20, -20), Size::new(40, 40)),
        Rectangle::new(Point::new(far, -far - 1), Size::new(40, 40)),
        Rectangle::new(Point::new(-far - 1, far), Size::new(40, 40)),
    ];
    for &a in &ends {
        for &b in &ends {
            for window in windows {
                for rule in [Rule::TopLeft, Rule::Inclusive] {
                    check([(a, i32::MIN), (i32::MAX, b), (1000, -300)], rule, window).unwrap();
                    check([(a, b), (b, a), (-a.saturating_add(7), 13)], rule, window).unwrap();
                }
            }
        }
    }
}

/// A mesh of sub-pixel triangles sharing vertices covers every pixel of its area once.
#[test]
fn meshes_are_watertight() {
    let mut rng = Rng(0x5EB0_1234);
    for round in 0..40 {
        let area = Rectangle::new(Point::new(-3 + round % 5, 2 - round % 7), Size::new(48, 40));
        // The grid in 1/256 pixel: inner vertices jittered by fractions of a pixel.
        let raw_area = Rectangle::new(area.top_left * 256, area.size * 256);
        let cells = (2 + round % 7, 2 + round % 5);
        let mut hits = vec![0u32; (48 * 40) as usize];
        for [a, b, c] in jittered_grid(raw_area, cells.0, cells.1, &mut rng) {
            let t = sub([(a.x, a.y), (b.x, b.y), (c.x, c.y)]);
            for_each_subpixel_span(&t, trirast::FillRule::TopLeft, &area, |s| {
                for k in 0..s.len as i32 {
                    let (x, y) = (s.x + k - area.top_left.x, s.y - area.top_left.y);
                    hits[(y * 48 + x) as usize] += 1;
                }
                Ok::<(), ()>(())
            })
            .unwrap();
        }
        assert!(
            hits.iter().all(|&h| h == 1),
            "round {round}: {:?}",
            hits.iter().filter(|&&h| h != 1).count()
        );
    }
}

/// Sliding a triangle right by 1/256 pixel at a time over a whole pixel: no pixel flickers.
/// Each pixel's sample moves along a line through the (convex) triangle, so it is covered for
/// one stretch of the sweep at most: it changes once (entering or leaving), or twice where
/// the triangle is under a pixel wide (entering, then leaving), never more. The last step is
/// the first triangle moved by one pixel.
#[test]
fn motion_is_monotonic() {
    let mut rng = Rng(77);
    let window = Rectangle::new(Point::new(-4, -4), Size::new(40, 40));
    for _ in 0..60 {
        let raw: [(i32, i32); 3] =
            [(); 3].map(|()| (rng.range(0, 30 * 256), rng.range(0, 30 * 256)));
        let frames: Vec<Vec<bool>> = (0..=256)
            .map(|d| {
                let moved = raw.map(|(x, y)| (x + d, y));
                covered(&sub(moved), Rule::TopLeft, &window)
            })
            .collect();
        for i in 0..frames[0].len() {
            let flips = frames.windows(2).filter(|f| f[0][i] != f[1][i]).count();
            let (first, last) = (frames[0][i], frames[256][i]);
            assert!(
                flips <= 1 || (flips == 2 && !first && !last),
                "{raw:?}: pixel {i} flips {flips} times"
            );
        }
        // One pixel right: the same coverage, shifted.
        for (i, &hit) in frames[256].iter().enumerate() {
            let x = i % 40;
            let before = if x == 0 { false } else { frames[0][i - 1] };
            if x > 0 {
                assert_eq!(hit, before, "{raw:?}: pixel {i}");
            }
        }
    }
}
