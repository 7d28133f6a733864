//! Small cases checked by hand on `MockDisplay` (which also rejects overdraw and out-of-bounds
//! writes). The expected patterns were worked out on paper from the rule definitions.

use embedded_graphics::{
    mock_display::MockDisplay,
    pixelcolor::{BinaryColor, Rgb888},
    prelude::*,
};
use trirast::{FillRule, FlatStyle, Triangle};

/// Pads pattern rows to one width, as `MockDisplay` wants ('` `' is an undrawn pixel).
fn assert_pattern(display: &MockDisplay<BinaryColor>, rows: &[&str]) {
    let width = rows.iter().map(|r| r.len()).max().unwrap_or(0);
    let padded: Vec<String> = rows.iter().map(|r| format!("{r:<width$}")).collect();
    let refs: Vec<&str> = padded.iter().map(String::as_str).collect();
    display.assert_pattern(&refs);
}

fn draw(points: [(i32, i32); 3], rule: FillRule) -> MockDisplay<BinaryColor> {
    let [a, b, c] = points.map(|(x, y)| Point::new(x, y));
    let mut display = MockDisplay::new();
    Triangle::new(a, b, c)
        .into_styled(FlatStyle::new(BinaryColor::On).with_fill_rule(rule))
        .draw(&mut display)
        .unwrap();
    display
}

#[test]
fn right_triangle() {
    // Left edge x = 0 (in), top edge y = 0 (in), hypotenuse x + y = 4 (out under top-left).
    assert_pattern(
        &draw([(0, 0), (4, 0), (0, 4)], FillRule::TopLeft),
        &["####", "###", "##", "#"],
    );
    assert_pattern(
        &draw([(0, 0), (4, 0), (0, 4)], FillRule::Inclusive),
        &["#####", "####", "###", "##", "#"],
    );
}

#[test]
fn flat_top_isosceles() {
    // Rows y: x from y (left edge, in) to 6 - y (right edge, out); bottom apex row out.
    assert_pattern(
        &draw([(0, 0), (6, 0), (3, 3)], FillRule::TopLeft),
        &["######", " ####", "  ##"],
    );
    assert_pattern(
        &draw([(0, 0), (6, 0), (3, 3)], FillRule::Inclusive),
        &["#######", " #####", "  ###", "   #"],
    );
}

#[test]
fn flat_bottom() {
    // Apex (3, 0); rows 1..3 widen by one each side; the bottom edge row 3 is out.
    assert_pattern(
        &draw([(3, 0), (0, 3), (6, 3)], FillRule::TopLeft),
        &["", "  ##", " ####"],
    );
    assert_pattern(
        &draw([(3, 0), (0, 3), (6, 3)], FillRule::Inclusive),
        &["   #", "  ###", " #####", "#######"],
    );
}

#[test]
fn uneven_slopes() {
    // Sorted (0,0), (5,2), (1,4); left edge x = y/4, right edges x = 2.5y then x = 9 - 2y.
    // Top-left: row 1: x in [1, 2.5) ; row 2: [1, 5) ; row 3: [1, 3).
    assert_pattern(
        &draw([(0, 0), (5, 2), (1, 4)], FillRule::TopLeft),
        &["", " ##", " ####", " ##"],
    );
    // Inclusive: row 0: [0, 0]; 1: [1, 2.5]; 2: [1, 5]; 3: [1, 3]; 4: [1, 1].
    assert_pattern(
        &draw([(0, 0), (5, 2), (1, 4)], FillRule::Inclusive),
        &["#", " ##", " #####", " ###", " #"],
    );
}

#[test]
fn sliver() {
    // (0,0), (10,1), (0,2): only row 1 has width under top-left.
    assert_pattern(
        &draw([(0, 0), (10, 1), (0, 2)], FillRule::TopLeft),
        &["", "##########"],
    );
    assert_pattern(
        &draw([(0, 0), (10, 1), (0, 2)], FillRule::Inclusive),
        &["#", "###########", "#"],
    );
}

#[test]
fn clipped_at_the_display_edge() {
    // Right edge x = 2 - y; only the on-screen part is drawn (MockDisplay panics otherwise).
    assert_pattern(
        &draw([(-3, -3), (5, -3), (-3, 5)], FillRule::TopLeft),
        &["##", "#"],
    );
}

#[test]
fn degenerate_triangles_draw_nothing() {
    for rule in [FillRule::TopLeft, FillRule::Inclusive] {
        assert_pattern(&draw([(1, 1), (5, 5), (9, 9)], rule), &[]);
        assert_pattern(&draw([(4, 4), (4, 4), (4, 4)], rule), &[]);
        assert_pattern(&draw([(0, 3), (8, 3), (2, 3)], rule), &[]);
    }
}

#[test]
fn shared_diagonal_split_exactly() {
    // A square as two triangles: the diagonal x = y belongs to the upper-right one (its left
    // edge), the bottom row and right column to neither.
    let mut display = MockDisplay::new();
    let p = |x, y| Point::new(x, y);
    Triangle::new(p(0, 0), p(4, 0), p(4, 4))
        .into_styled(FlatStyle::new(Rgb888::RED))
        .draw(&mut display)
        .unwrap();
    Triangle::new(p(0, 0), p(4, 4), p(0, 4))
        .into_styled(FlatStyle::new(Rgb888::BLUE))
        .draw(&mut display)
        .unwrap();
    display.assert_pattern(&["RRRR", "BRRR", "BBRR", "BBBR"]);
}
