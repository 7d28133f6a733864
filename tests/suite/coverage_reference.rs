//! Coverage equals the exact half-space reference, pixel for pixel, for random triangles of every
//! kind: small, huge, off-screen, slivers, flat-topped and flat-bottomed, degenerate, and with
//! vertices anywhere in the `i32` range, on targets placed anywhere.

use crate::common;

use common::{
    CountingTarget, Offset, Rule, reference_covers, reference_pixels, window_contains,
    window_points,
};
use embedded_graphics::primitives::PointsIter;
use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
use proptest::prelude::*;
use trirast::{FAST_LIMIT, FlatStyle, Triangle, coverage::Span, coverage::for_each_span};

/// A target window: anywhere near the origin, or far out, up to 40x40.
fn window() -> impl Strategy<Value = Rectangle> {
    let origin = prop_oneof![
        4 => (-30..30i32, -30..30i32),
        1 => (any::<i32>(), any::<i32>()).prop_map(|(x, y)| (x / 2, y / 2)),
        1 => (prop_oneof![Just(i32::MIN), Just(i32::MAX - 40), Just(FAST_LIMIT - 20), Just(-FAST_LIMIT - 20)],
              prop_oneof![Just(i32::MIN), Just(i32::MAX - 40), Just(FAST_LIMIT - 20), Just(-FAST_LIMIT - 20)]),
    ];
    (origin, 1..40u32, 1..40u32)
        .prop_map(|((x, y), w, h)| Rectangle::new(Point::new(x, y), Size::new(w, h)))
}

fn point(range: std::ops::RangeInclusive<i32>) -> impl Strategy<Value = Point> {
    (range.clone(), range).prop_map(|(x, y)| Point::new(x, y))
}

/// Coordinates near a value, saturating at the `i32` range.
fn near(center: i32, spread: i32) -> impl Strategy<Value = i32> {
    (-spread..=spread).prop_map(move |d| center.saturating_add(d))
}

/// Random triangles of every kind, placed relative to `window`.
fn triangle_for(window: Rectangle) -> impl Strategy<Value = [Point; 3]> {
    let c = window.center();
    let local = move |spread: i32| {
        let lo = |v: i32| v.saturating_sub(spread);
        let hi = |v: i32| v.saturating_add(spread);
        (lo(c.x)..=hi(c.x), lo(c.y)..=hi(c.y))
            .prop_map(|(x, y)| Point::new(x, y))
            .boxed()
    };
    let extremes = prop_oneof![
        Just(i32::MIN),
        Just(i32::MAX),
        Just(FAST_LIMIT),
        Just(-FAST_LIMIT),
        Just(FAST_LIMIT + 1),
        Just(-FAST_LIMIT - 1)
    ];
    let edge_coord = (extremes, -3..=3i32).prop_map(|(v, d)| v.saturating_add(d));
    let any_point = (any::<i32>(), any::<i32>())
        .prop_map(|(x, y)| Point::new(x, y))
        .boxed();
    let extreme_point = prop_oneof![
        (edge_coord.clone(), edge_coord.clone()).prop_map(|(x, y)| Point::new(x, y)),
        (edge_coord.clone(), near(c.y, 40)).prop_map(|(x, y)| Point::new(x, y)),
        (near(c.x, 40), edge_coord).prop_map(|(x, y)| Point::new(x, y)),
    ]
    .boxed();
    prop_oneof![
        // Small and medium triangles over the window.
        6 => [local(25), local(25), local(25)],
        3 => [local(400), local(400), local(400)],
        // Tiny ones: a few pixels.
        3 => (local(25), point(-3..=3), point(-3..=3)).prop_map(|(a, d1, d2)| [a, sat_add(a, d1), sat_add(a, d2)]),
        // Huge: anywhere in i32, or with vertices at and around the extremes and the fast limit.
        2 => [any_point.clone(), any_point.clone(), any_point],
        3 => [extreme_point.clone(), extreme_point.clone(), local(30)],
        2 => [extreme_point.clone(), extreme_point.clone(), extreme_point],
        // Off-screen: near the window, shifted well away.
        1 => ([local(20), local(20), local(20)], prop_oneof![Just(Point::new(100, 0)), Just(Point::new(0, -100)), Just(Point::new(-60, 70))])
            .prop_map(|(t, d)| t.map(|p| sat_add(p, d))),
        // Flat top and flat bottom.
        2 => (local(30), local(30), -40..40i32).prop_map(|(a, b, dx)| [a, Point::new(a.x.saturating_add(dx), a.y), b]),
        // Slivers: almost collinear, or long and one pixel wide.
        2 => (local(30), point(-60..=60), 2..8i32, point(-1..=1)).prop_map(|(a, d, k, e)| {
            [a, sat_add(a, d), sat_add(sat_add(a, Point::new(d.x.saturating_mul(k), d.y.saturating_mul(k))), e)]
        }),
        // Degenerate: collinear or coincident.
        1 => (local(30), point(-20..=20), -5..5i32, -5..5i32).prop_map(|(a, d, k1, k2)| {
            [a, sat_add(a, Point::new(d.x * k1, d.y * k1)), sat_add(a, Point::new(d.x * k2, d.y * k2))]
        }),
    ]
}

fn sat_add(a: Point, b: Point) -> Point {
    Point::new(a.x.saturating_add(b.x), a.y.saturating_add(b.y))
}

fn case() -> impl Strategy<Value = (Rectangle, [Point; 3])> {
    window().prop_flat_map(|w| (Just(w), triangle_for(w)))
}

fn spans_of(v: [Point; 3], window: &Rectangle, rule: Rule) -> Vec<Span> {
    let mut spans = Vec::new();
    for_each_span(&Triangle { vertices: v }, rule.to_crate(), window, |s| {
        spans.push(s);
        Ok::<(), ()>(())
    })
    .unwrap();
    spans
}

fn check_case(window: Rectangle, v: [Point; 3]) -> Result<(), TestCaseError> {
    for rule in [Rule::TopLeft, Rule::Inclusive] {
        let want = reference_pixels(v, &window, rule);

        // Spans: well formed, one per row at most, top to bottom, inside the window.
        let spans = spans_of(v, &window, rule);
        for pair in spans.windows(2) {
            prop_assert!(pair[0].y < pair[1].y, "spans out of order: {spans:?}");
        }
        let mut got = Vec::new();
        for s in &spans {
            prop_assert!(s.len >= 1);
            for i in 0..s.len {
                let p = Point::new(s.x + i as i32, s.y);
                prop_assert!(
                    window_contains(&window, p),
                    "span pixel {p:?} outside window {window:?}"
                );
                got.push(p);
            }
        }
        prop_assert_eq!(
            &got,
            &want,
            "rule {:?}, triangle {:?}, window {:?}",
            rule,
            v,
            window
        );

        // The same rows through a window spanning every column but the last (2^32 - 1 wide,
        // from i32::MIN): the spans, cut to the window's columns, give the same pixels.
        let wide = Rectangle::new(
            Point::new(i32::MIN, window.top_left.y),
            Size::new(u32::MAX, window.size.height),
        );
        let (x0, x1) = (
            i64::from(window.top_left.x),
            i64::from(window.top_left.x) + i64::from(window.size.width),
        );
        let mut got_wide = Vec::new();
        for s in spans_of(v, &wide, rule) {
            let (from, to) = (i64::from(s.x), i64::from(s.x) + i64::from(s.len));
            got_wide.extend((from.max(x0)..to.min(x1)).map(|x| Point::new(x as i32, s.y)));
        }
        // Such a window ends (exclusively) at column i32::MAX, which it leaves out.
        let want_wide: Vec<Point> = want.iter().copied().filter(|p| p.x != i32::MAX).collect();
        prop_assert_eq!(
            &got_wide,
            &want_wide,
            "rule {:?}, triangle {:?}, every column",
            rule,
            v
        );

        // Through `Drawable` into a target placed at the window: same pixels, each once.
        let mut target = Offset(CountingTarget::new(window));
        let style = FlatStyle::new(BinaryColor::On).with_fill_rule(rule.to_crate());
        Triangle { vertices: v }
            .into_styled(style)
            .draw(&mut target)
            .unwrap();
        prop_assert_eq!(target.0.outside_writes, 0);
        prop_assert!(target.0.max_hits() <= 1);
        prop_assert_eq!(target.0.covered(), want.clone());
        prop_assert_eq!(target.0.fill_solid_calls.len(), spans.len());
        prop_assert_eq!(target.0.draw_iter_calls + target.0.fill_contiguous_calls, 0);

        // The public point query agrees with the reference too.
        let t = Triangle { vertices: v };
        for p in window_points(&window).step_by(7) {
            prop_assert_eq!(
                t.covers(p, rule.to_crate()),
                reference_covers(v, p, rule),
                "covers({:?})",
                p
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 10_000, max_shrink_iters: 10_000, ..ProptestConfig::default() })]

    #[test]
    fn coverage_matches_exact_reference((window, v) in case()) {
        check_case(window, v)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// `Triangle::points` (embedded-graphics' `PointsIter`) of triangles within 40 pixels of
    /// the origin: every pixel the top-left rule covers, row by row, left to right.
    #[test]
    fn points_are_the_covered_pixels(v in [point(-40..=40), point(-40..=40), point(-40..=40)]) {
        let window = Rectangle::new(Point::new(-41, -41), Size::new(83, 83));
        let want = reference_pixels(v, &window, Rule::TopLeft);
        let got: Vec<Point> = Triangle { vertices: v }.points().collect();
        prop_assert_eq!(got, want, "triangle {:?}", v);
    }

    /// Triangles anywhere in the `i32` plane, up to its ends, a few thousand rows tall (the
    /// iterator visits every row between the top and bottom vertex, empty ones too): the first
    /// points are covered pixels, in order, with nothing covered just before the first.
    #[test]
    fn points_anywhere_come_in_order(
        corner in (any::<i32>(), any::<i32>()),
        offsets in [(-2000..2000i32, -2000..2000i32), (-2000..2000i32, -2000..2000i32)],
    ) {
        let a = Point::new(corner.0, corner.1);
        let at = |(dx, dy): (i32, i32)| Point::new(a.x.saturating_add(dx), a.y.saturating_add(dy));
        check_points(&[a, at(offsets[0]), at(offsets[1])])?;
    }
}

/// The first points of `v` are covered pixels in row-major order, and the pixels just before
/// the first (left of it in its row, and in the three rows above) are not covered.
fn check_points(v: &[Point; 3]) -> Result<(), TestCaseError> {
    let v = *v;
    let got: Vec<Point> = Triangle { vertices: v }.points().take(300).collect();
    for p in &got {
        prop_assert!(reference_covers(v, *p, Rule::TopLeft), "{:?} in {:?}", p, v);
    }
    for pair in got.windows(2) {
        prop_assert!(
            (pair[0].y, pair[0].x) < (pair[1].y, pair[1].x),
            "{:?}",
            pair
        );
    }
    if let Some(first) = got.first() {
        let row = Rectangle::new(
            Point::new(first.x.saturating_sub(20), first.y),
            Size::new(20, 1),
        );
        let above = Rectangle::new(
            Point::new(first.x.saturating_sub(10), first.y.saturating_sub(3)),
            Size::new(21, 3),
        );
        for p in window_points(&row).chain(window_points(&above)) {
            if (p.y, p.x) < (first.y, first.x) {
                prop_assert!(
                    !reference_covers(v, p, Rule::TopLeft),
                    "{:?} before {:?} in {:?}",
                    p,
                    first,
                    v
                );
            }
        }
    }
    Ok(())
}

/// A window covering the whole `i32` plane (wider than `i32::MAX`): a small triangle's pixels,
/// all of them.
#[test]
fn a_window_over_the_whole_plane() {
    let everything = Rectangle::new(
        Point::new(i32::MIN, i32::MIN),
        Size::new(u32::MAX, u32::MAX),
    );
    let v = [Point::new(0, 0), Point::new(8, 0), Point::new(0, 8)];
    let around = Rectangle::new(Point::new(-1, -1), Size::new(10, 10));
    for rule in [Rule::TopLeft, Rule::Inclusive] {
        let mut got = Vec::new();
        for s in spans_of(v, &everything, rule) {
            got.extend((0..s.len).map(|i| Point::new(s.x + i as i32, s.y)));
        }
        assert_eq!(got, reference_pixels(v, &around, rule), "{rule:?}");
    }
}

/// The points of triangles reaching the ends of `i32` (not slivers: their rows fill quickly).
#[test]
fn points_at_the_ends_of_the_range() {
    let (lo, hi) = (i32::MIN, i32::MAX);
    for v in [
        [Point::new(lo, lo), Point::new(hi, lo), Point::new(lo, hi)],
        [Point::new(hi, hi), Point::new(lo, hi), Point::new(hi, lo)],
        [Point::new(0, lo), Point::new(hi, hi), Point::new(lo, hi)],
        [Point::new(lo, 0), Point::new(hi, -5), Point::new(hi, 5)],
    ] {
        check_points(&v).unwrap();
        assert_eq!(
            Triangle { vertices: v }.points().take(300).count(),
            300,
            "{v:?}"
        );
    }
    // Degenerate: nothing.
    let line = [Point::new(lo, lo), Point::new(0, 0), Point::new(hi, hi)];
    assert_eq!(Triangle { vertices: line }.points().next(), None);
}

/// Hand-picked cases around the edges of the algorithm, checked the same way.
#[test]
fn fixed_cases_match_reference() {
    let p = Point::new;
    let w = |x, y, wd, ht| Rectangle::new(p(x, y), Size::new(wd, ht));
    let cases = [
        (w(0, 0, 40, 40), [p(0, 0), p(30, 0), p(0, 30)]),
        (w(0, 0, 40, 40), [p(5, 1), p(30, 17), p(2, 35)]),
        (w(-5, -5, 20, 20), [p(-100, -100), p(100, -99), p(0, 100)]),
        // Clipped at the top in the middle of both short edges.
        (w(0, 10, 40, 10), [p(20, 0), p(39, 15), p(1, 30)]),
        // Fast path limit straddled.
        (
            w(0, 0, 30, 30),
            [p(-FAST_LIMIT, 5), p(FAST_LIMIT, 6), p(3, 29)],
        ),
        (
            w(0, 0, 30, 30),
            [p(-FAST_LIMIT - 1, 5), p(FAST_LIMIT + 1, 6), p(3, 29)],
        ),
        // Whole i32 range.
        (
            w(-20, -20, 40, 40),
            [
                p(i32::MIN, i32::MIN),
                p(i32::MAX, i32::MIN + 1),
                p(i32::MIN + 1, i32::MAX),
            ],
        ),
        (
            w(i32::MAX - 39, i32::MAX - 39, 40, 40),
            [
                p(i32::MIN, i32::MAX),
                p(i32::MAX, i32::MIN),
                p(i32::MAX, i32::MAX),
            ],
        ),
        (
            w(i32::MIN, i32::MIN, 40, 40),
            [
                p(i32::MIN, i32::MIN),
                p(i32::MAX, i32::MIN),
                p(i32::MIN, i32::MAX),
            ],
        ),
        // A one-pixel-high sliver and a tall needle.
        (w(0, 0, 40, 40), [p(0, 10), p(39, 10), p(20, 11)]),
        (w(0, 0, 40, 40), [p(10, 0), p(11, 39), p(10, 39)]),
    ];
    for (window, v) in cases {
        check_case(window, v).unwrap();
    }
}

/// A sink's first error stops the walk and comes back, on the fast path and on the wide ones
/// (whole-pixel and sub-pixel vertices beyond the 32-bit range), after exactly the spans
/// before it.
#[test]
fn the_first_error_stops_every_walk() {
    use fixed::types::I24F8;
    use trirast::{
        FillRule,
        coverage::for_each_subpixel_span,
        geometry::{SubPixelTriangle, SubPoint},
    };
    let window = Rectangle::new(Point::zero(), Size::new(64, 64));
    let far = FAST_LIMIT + 1000;
    let whole = [
        Triangle::new(Point::new(0, 0), Point::new(60, 10), Point::new(5, 60)),
        Triangle::new(
            Point::new(-far, -far),
            Point::new(far, 0),
            Point::new(0, far),
        ),
    ];
    // Counts the spans a walk hands on, failing at the third: the walk must return that error
    // and hand on nothing after it.
    type Sink<'a> = dyn FnMut(Span) -> Result<(), u32> + 'a;
    let stops_at_third = |walk: &mut dyn FnMut(&mut Sink) -> Result<(), u32>| {
        let mut seen = 0;
        let result = walk(&mut |_| {
            seen += 1;
            if seen == 3 { Err(seen) } else { Ok(()) }
        });
        (result, seen)
    };
    for triangle in whole {
        let spans =
            stops_at_third(&mut |sink| for_each_span(&triangle, FillRule::TopLeft, &window, sink));
        assert_eq!(spans, (Err(3), 3), "{triangle:?}");
    }
    let at = |x: i32, y: i32| SubPoint::new(I24F8::from_bits(x), I24F8::from_bits(y));
    let big = i32::MAX / 2;
    let subpixel = [
        SubPixelTriangle::new(at(0, 0), at(60 << 8, 10 << 8), at(5 << 8, 60 << 8)),
        SubPixelTriangle::new(at(-big, -big), at(big, 0), at(0, big)),
    ];
    for triangle in subpixel {
        let spans = stops_at_third(&mut |sink| {
            for_each_subpixel_span(&triangle, FillRule::TopLeft, &window, sink)
        });
        assert_eq!(spans, (Err(3), 3), "{triangle:?}");
    }
}
