//! The barycentric point query against exact rational arithmetic, and its consistency with
//! coverage; the user shader's interpolated attributes against the exact plane.
#![allow(clippy::needless_range_loop)] // parallel channel arrays read best indexed

use crate::common;

use common::{Recorder, Rule, exact_plane, reference_covers, round_half_up, window_points};
use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use fixed::types::{I16F16, I32F32};
use proptest::prelude::*;
use trirast::{
    FillRule, FlatStyle, ShaderStyle, Triangle, interpolate::Location, shading::Fragment,
};

fn pt(range: std::ops::Range<i32>) -> impl Strategy<Value = Point> {
    (range.clone(), range).prop_map(|(x, y)| Point::new(x, y))
}

fn any_point() -> impl Strategy<Value = Point> {
    prop_oneof![
        4 => pt(-50..50),
        1 => pt(-100_000..100_000),
        1 => (any::<i32>(), any::<i32>()).prop_map(|(x, y)| Point::new(x, y)),
    ]
}

/// The exact weight of each vertex, as a rational with a positive denominator.
fn exact_weights(v: [Point; 3], p: Point) -> Option<[(i128, i128); 3]> {
    let mut out = [(0, 1); 3];
    for (i, w) in out.iter_mut().enumerate() {
        let mut unit = [0; 3];
        unit[i] = 1;
        *w = exact_plane(v, unit, p)?;
    }
    Some(out)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(10_000))]

    #[test]
    fn weights_are_exact_rationals_rounded(a in any_point(), b in any_point(), c in any_point(), p in any_point()) {
        let v = [a, b, c];
        let got = Triangle { vertices: v }.barycentric(p);
        let Some(exact) = exact_weights(v, p) else {
            prop_assert!(got.is_none(), "degenerate triangles have no coordinates");
            return Ok(());
        };
        let got = got.unwrap();
        let mut sum: i128 = 0;
        let mut saturated = false;
        for i in 0..3 {
            let (num, den) = exact[i];
            let want = round_half_up(num << 32, den);
            let bits = i128::from(got.weights[i].to_bits());
            if want > i128::from(i64::MAX) || want < i128::from(i64::MIN) {
                saturated = true;
                prop_assert!(bits == i128::from(i64::MAX) || bits == i128::from(i64::MIN));
            } else {
                prop_assert_eq!(bits, want, "weight {}", i);
            }
            sum += bits;
        }
        if !saturated {
            prop_assert!((sum - (1i128 << 32)).abs() <= 1, "weights sum to one within one LSB: {}", sum);
        }
        // Location from exact signs of the numerators.
        let signs = exact.map(|(n, _)| n.signum());
        let want = if signs.contains(&-1) {
            Location::Outside
        } else {
            match signs.iter().filter(|&&s| s == 0).count() {
                0 => Location::Inside,
                1 => Location::OnEdge,
                _ => Location::OnVertex,
            }
        };
        prop_assert_eq!(got.location, want);
        // Consistent with the fill rules.
        let t = Triangle { vertices: v };
        for rule in [Rule::TopLeft, Rule::Inclusive] {
            prop_assert_eq!(got.is_drawn_by(&t, p, rule.to_crate()), reference_covers(v, p, rule));
        }
    }

    /// Every pixel drawn is classified inside or on the boundary, never outside.
    #[test]
    fn drawn_pixels_are_never_outside(a in pt(-10..50), b in pt(-10..50), c in pt(-10..50)) {
        let window = Rectangle::new(Point::new(0, 0), Size::new(40, 40));
        for rule in [FillRule::TopLeft, FillRule::Inclusive] {
            let mut target = Recorder::<Rgb888>::new(window);
            let t = Triangle::new(a, b, c);
            t.into_styled(FlatStyle::new(Rgb888::WHITE).with_fill_rule(rule)).draw(&mut target).unwrap();
            for p in window_points(&window) {
                if target.get(p).is_some() {
                    let location = t.barycentric(p).unwrap().location;
                    prop_assert_ne!(location, Location::Outside);
                    if rule == FillRule::TopLeft && location != Location::Inside {
                        prop_assert!(t.covers(p, rule));
                    }
                }
            }
        }
    }

    /// A user shader sees each attribute within (1 + k/2) LSB of its exact value, k pixels from
    /// the start of its span (the start is exact; each step adds the gradient rounded to the
    /// nearest 2^-16).
    #[test]
    fn shader_attributes_match_exact_planes(a in pt(-30..70), b in pt(-30..70), c in pt(-30..70),
                                            attrs in prop::array::uniform3(prop::array::uniform2(-(1i32 << 20)..(1 << 20)))) {
        let window = Rectangle::new(Point::new(0, 0), Size::new(40, 40));
        let v = [a, b, c];
        let attributes = attrs.map(|a| a.map(I16F16::from_bits));
        let seen = core::cell::RefCell::new(Vec::new());
        let style = ShaderStyle::new(attributes, |f: Fragment<2>| {
            seen.borrow_mut().push(f);
            Rgb888::BLACK
        });
        let mut target = Recorder::<Rgb888>::new(window);
        Triangle { vertices: v }.into_styled(style).draw(&mut target).unwrap();
        let seen = seen.into_inner();
        let covered: Vec<Point> = window_points(&window).filter(|&p| reference_covers(v, p, Rule::TopLeft)).collect();
        prop_assert_eq!(seen.len(), covered.len());
        for f in seen {
            prop_assert!(covered.contains(&f.position));
            let span_start = covered.iter().filter(|q| q.y == f.position.y).map(|q| q.x).min().unwrap();
            let steps = i128::from(f.position.x - span_start);
            for k in 0..2 {
                let (num, den) = exact_plane(v, [0, 1, 2].map(|i| i64::from(attrs[i][k])), f.position).unwrap();
                let exact = round_half_up(num, den);
                let got = i128::from(f.values[k].to_bits());
                prop_assert!(2 * (got - exact).abs() <= 2 + steps, "attribute {} at {:?}: {} vs {} after {} steps", k, f.position, got, exact, steps);
            }
        }
    }
}

#[test]
fn vertices_and_midpoints_are_exact() {
    let v = [Point::new(-6, 2), Point::new(10, -4), Point::new(4, 12)];
    let t = Triangle { vertices: v };
    for (i, &p) in v.iter().enumerate() {
        let b = t.barycentric(p).unwrap();
        let mut want = [I32F32::ZERO; 3];
        want[i] = I32F32::ONE;
        assert_eq!(b.weights, want);
        assert_eq!(b.location, Location::OnVertex);
    }
    for (i, j, k) in [(0, 1, 2), (1, 2, 0), (2, 0, 1)] {
        let mid = Point::new((v[i].x + v[j].x) / 2, (v[i].y + v[j].y) / 2);
        let b = t.barycentric(mid).unwrap();
        assert_eq!(b.weights[i], I32F32::from_num(0.5));
        assert_eq!(b.weights[j], I32F32::from_num(0.5));
        assert_eq!(b.weights[k], I32F32::ZERO);
        assert_eq!(b.location, Location::OnEdge);
    }
}
