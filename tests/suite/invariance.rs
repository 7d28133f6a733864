//! Coverage does not depend on vertex order, winding, or where on the integer grid the triangle
//! sits (including moves from the 32-bit fast path to the 64-bit wide path).

use embedded_graphics::{prelude::*, primitives::Rectangle};
use proptest::prelude::*;
use trirast::{FAST_LIMIT, FillRule, Triangle, coverage::Span, coverage::for_each_span};

fn spans(v: [Point; 3], rule: FillRule, window: &Rectangle) -> Vec<Span> {
    let mut out = Vec::new();
    for_each_span(&Triangle { vertices: v }, rule, window, |s| {
        out.push(s);
        Ok::<(), ()>(())
    })
    .unwrap();
    out
}

fn pt() -> impl Strategy<Value = Point> {
    (-60..100i32, -60..100i32).prop_map(|(x, y)| Point::new(x, y))
}

fn rule() -> impl Strategy<Value = FillRule> {
    prop_oneof![Just(FillRule::TopLeft), Just(FillRule::Inclusive)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2_000))]

    #[test]
    fn vertex_order_and_winding_do_not_matter(a in pt(), b in pt(), c in pt(), rule in rule()) {
        let window = Rectangle::new(Point::new(-10, -10), Size::new(100, 100));
        let base = spans([a, b, c], rule, &window);
        for order in [[b, c, a], [c, a, b], [c, b, a], [b, a, c], [a, c, b]] {
            prop_assert_eq!(&spans(order, rule, &window), &base);
        }
    }

    #[test]
    fn translation_moves_coverage(a in pt(), b in pt(), c in pt(), rule in rule(),
                                  by in prop_oneof![
                                      (-1000..1000i32, -1000..1000i32),
                                      // Onto the wide path and to the ends of the i32 range.
                                      Just((FAST_LIMIT, -FAST_LIMIT)),
                                      Just((i32::MAX - 200, i32::MIN + 200)),
                                      Just((i32::MIN + 100, i32::MAX - 150)),
                                  ]) {
        let window = Rectangle::new(Point::new(-10, -10), Size::new(100, 100));
        let by = Point::new(by.0, by.1);
        let moved = spans([a + by, b + by, c + by], rule, &Rectangle::new(window.top_left + by, window.size));
        let expected: Vec<Span> = spans([a, b, c], rule, &window)
            .into_iter()
            .map(|s| Span { x: s.x + by.x, y: s.y + by.y, ..s })
            .collect();
        prop_assert_eq!(moved, expected);
    }
}
