//! Meshes under the top-left rule: every pixel inside is drawn exactly once, nothing outside,
//! whatever the winding of each triangle.

use crate::common;

use common::{CountingTarget, Offset, Rng, Rule, jittered_grid, reference_covers, window_points};
use embedded_graphics::{
    mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*, primitives::Rectangle,
};
use proptest::prelude::*;
use trirast::{FlatStyle, Orientation, Triangle};

/// Draws with random vertex rotation and winding per triangle.
fn draw_all<D: DrawTarget<Color = BinaryColor>>(
    triangles: &[[Point; 3]],
    target: &mut D,
    rng: &mut Rng,
) where
    D::Error: core::fmt::Debug,
{
    for &[a, b, c] in triangles {
        let order = match rng.range(0, 5) {
            0 => [a, b, c],
            1 => [b, c, a],
            2 => [c, a, b],
            3 => [c, b, a],
            4 => [b, a, c],
            _ => [a, c, b],
        };
        Triangle { vertices: order }
            .into_styled(FlatStyle::new(BinaryColor::On))
            .draw(target)
            .unwrap();
    }
}

/// A fan around `center` through points at increasing angles (a star-shaped polygon).
fn fan(center: Point, rng: &mut Rng, spokes: usize, radius: i32) -> Vec<[Point; 3]> {
    // Angles in 1/4096 turns: spokes strictly increasing, each step below half a turn (evenly
    // spaced, each moved by up to a quarter of the spacing).
    let spacing = 4096 / spokes as i32;
    let jitter = spacing / 4 - 1;
    let angles: Vec<i64> = (0..spokes as i32)
        .map(|i| i64::from(i * spacing + rng.range(-jitter, jitter)))
        .collect();
    let ring: Vec<Point> = angles
        .iter()
        .map(|&a| {
            let t = a as f64 / 4096.0 * std::f64::consts::TAU;
            let r = f64::from(rng.range(radius / 3, radius));
            Point::new(
                center.x + (r * t.cos()).round() as i32,
                center.y + (r * t.sin()).round() as i32,
            )
        })
        .collect();
    let triangles = |ring: &[Point]| -> Vec<[Point; 3]> {
        (0..ring.len())
            .map(|i| [center, ring[i], ring[(i + 1) % ring.len()]])
            .collect()
    };
    // Rounding to whole pixels folds some fans (a spoke on or past the next one): drop the
    // spokes that fold, so that few cases are thrown away (at radius 6 with 40 spokes most
    // fans folded, which made proptest give up under large case counts).
    let mut ring = ring;
    while ring.len() >= 3 {
        let tris = triangles(&ring);
        match tris
            .iter()
            .position(|t| Triangle { vertices: *t }.orientation() != Orientation::Clockwise)
        {
            Some(i) => {
                ring.remove((i + 1) % ring.len());
            }
            None => return tris,
        }
    }
    triangles(&ring)
}

/// False when rounding folded the fan (a step of half a turn or more, or a degenerate triangle);
/// such cases are skipped.
fn fan_is_simple(tris: &[[Point; 3]]) -> bool {
    tris.iter()
        .all(|t| Triangle { vertices: *t }.orientation() == Orientation::Clockwise)
}

/// True when `p` lies on the closed segment `a`-`b`.
fn on_segment(p: Point, a: Point, b: Point) -> bool {
    let cross =
        i64::from(b.x - a.x) * i64::from(p.y - a.y) - i64::from(b.y - a.y) * i64::from(p.x - a.x);
    cross == 0
        && p.x >= a.x.min(b.x)
        && p.x <= a.x.max(b.x)
        && p.y >= a.y.min(b.y)
        && p.y <= a.y.max(b.y)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn jittered_grids_cover_each_pixel_once(seed in any::<u64>(), nx in 1..12i32, ny in 1..12i32,
                                            x0 in -20..10i32, y0 in -20..10i32, cw in 4..14i32, ch in 4..14i32) {
        let mut rng = Rng(seed);
        let area = Rectangle::new(Point::new(x0, y0), Size::new((nx * cw) as u32, (ny * ch) as u32));
        let tris = jittered_grid(area, nx, ny, &mut rng);
        // The target is a window that cuts through the grid on some sides.
        let window = Rectangle::new(Point::new(-8, -8), Size::new(120, 110));
        let mut target = Offset(CountingTarget::new(window));
        draw_all(&tris, &mut target, &mut rng);
        prop_assert_eq!(target.0.outside_writes, 0);
        // Under the top-left rule the union of the mesh is the half-open rectangle.
        for p in window_points(&window) {
            let inside = p.x >= area.top_left.x && p.x < area.top_left.x + area.size.width as i32
                && p.y >= area.top_left.y && p.y < area.top_left.y + area.size.height as i32;
            prop_assert_eq!(target.0.count(p), u32::from(inside), "pixel {:?}", p);
        }
    }

    #[test]
    fn fans_cover_each_inner_pixel_once(seed in any::<u64>(), spokes in 3..40usize, radius in 6..60i32,
                                        cx in 0..100i32, cy in 0..100i32) {
        let mut rng = Rng(seed);
        let center = Point::new(cx, cy);
        let tris = fan(center, &mut rng, spokes, radius);
        prop_assume!(fan_is_simple(&tris));
        let window = Rectangle::new(Point::new(0, 0), Size::new(100, 100));
        let mut target = Offset(CountingTarget::new(window));
        draw_all(&tris, &mut target, &mut rng);
        prop_assert_eq!(target.0.outside_writes, 0);
        prop_assert!(target.0.max_hits() <= 1);
        for p in window_points(&window) {
            let in_closed = tris.iter().any(|t| reference_covers(*t, p, Rule::Inclusive));
            let on_rim = tris.iter().any(|t| on_segment(p, t[1], t[2]));
            let hits = target.0.count(p);
            if !in_closed {
                prop_assert_eq!(hits, 0, "outside pixel {:?} drawn", p);
            } else if !on_rim {
                prop_assert_eq!(hits, 1, "inner pixel {:?} drawn {} times", p, hits);
            }
        }
        prop_assert_eq!(target.0.count(center), 1, "the shared centre belongs to exactly one triangle");
    }
}

/// The same on `MockDisplay`, which panics on any overdraw or out-of-bounds write.
#[test]
fn mock_display_meshes_have_no_overdraw() {
    let mut rng = Rng(7);
    for _ in 0..200 {
        let (nx, ny) = (rng.range(1, 8), rng.range(1, 8));
        let (cw, ch) = (rng.range(4, 8), rng.range(4, 8));
        let area = Rectangle::new(
            Point::new(rng.range(-6, 4), rng.range(-6, 4)),
            Size::new((nx * cw) as u32, (ny * ch) as u32),
        );
        let tris = jittered_grid(area, nx, ny, &mut rng);
        let mut display: MockDisplay<BinaryColor> = MockDisplay::new();
        draw_all(&tris, &mut display, &mut rng);
        let expected = area.intersection(&display.bounding_box());
        assert_eq!(display.affected_area(), expected);
        let drawn = window_points(&display.bounding_box())
            .filter(|&p| display.get_pixel(p).is_some())
            .count();
        assert_eq!(drawn as u32, expected.size.width * expected.size.height);
    }
}

/// A hexagon fan with its centre on a pixel, in every rotation and winding.
#[test]
fn mock_display_fan_centre_drawn_once() {
    let c = Point::new(30, 30);
    let ring = [
        Point::new(50, 30),
        Point::new(40, 48),
        Point::new(20, 48),
        Point::new(10, 30),
        Point::new(20, 12),
        Point::new(40, 12),
    ];
    for seed in 0..20 {
        let mut rng = Rng(seed);
        let tris: Vec<[Point; 3]> = (0..6).map(|i| [c, ring[i], ring[(i + 1) % 6]]).collect();
        let mut display: MockDisplay<BinaryColor> = MockDisplay::new();
        draw_all(&tris, &mut display, &mut rng);
        assert_eq!(display.get_pixel(c), Some(BinaryColor::On));
    }
}
