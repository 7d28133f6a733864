//! Barycentric coordinates of a point: the public point query.

use embedded_graphics::geometry::Point;
use fixed::types::{I16F16, I32F32};

use crate::{FillRule, Triangle};

/// Where a point lies relative to a triangle, decided exactly.
///
/// # Examples
///
/// ```
/// use embedded_graphics::prelude::*;
/// use trirast::{interpolate::Location, Triangle};
///
/// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
/// let at = |x, y| t.barycentric(Point::new(x, y)).unwrap().location;
/// assert_eq!(at(2, 2), Location::Inside);
/// assert_eq!(at(4, 4), Location::OnEdge);
/// assert_eq!(at(8, 0), Location::OnVertex);
/// assert_eq!(at(9, 9), Location::Outside);
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Location {
    /// Strictly inside: every fill rule draws it.
    Inside,
    /// On an edge, between its vertices: the inclusive rule draws it, the top-left rule only
    /// if the edge is a top or left edge.
    OnEdge,
    /// On a vertex: the inclusive rule draws it, the top-left rule only if both edges through
    /// it are top or left edges.
    OnVertex,
    /// Strictly outside: no fill rule draws it.
    Outside,
}

/// Barycentric coordinates of a point with respect to a triangle, in fixed point.
///
/// `weights[i]` belongs to `triangle.vertices[i]`; each is the exact rational weight rounded to
/// the nearest multiple of 2^-32 (`I32F32`), saturating for points so far away that a weight
/// leaves the `I32F32` range. The weights sum to one within one least significant bit, and are
/// exact wherever the rational weight is a multiple of 2^-32 (vertices, edge midpoints, ...).
///
/// # Examples
///
/// A worked example: the point (2, 2) in the triangle (0, 0), (8, 0), (0, 8) has weights
/// 1/2, 1/4 and 1/4, and an attribute of 0, 100 and 200 at the vertices interpolates to
/// 0 / 2 + 100 / 4 + 200 / 4 = 75.
///
/// ```
/// use embedded_graphics::prelude::*;
/// use fixed::types::{I16F16, I32F32};
/// use trirast::{interpolate::Location, Triangle};
///
/// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
/// let b = t.barycentric(Point::new(2, 2)).unwrap();
/// assert_eq!(b.weights, [I32F32::from_num(0.5), I32F32::from_num(0.25), I32F32::from_num(0.25)]);
/// assert_eq!(b.location, Location::Inside);
///
/// let brightness = [I16F16::from_num(0), I16F16::from_num(100), I16F16::from_num(200)];
/// assert_eq!(b.interpolate(brightness), I16F16::from_num(75));
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Barycentric {
    /// The weight of each vertex, in the triangle's vertex order.
    pub weights: [I32F32; 3],
    /// Where the point lies, decided exactly (not from the rounded weights).
    pub location: Location,
}

impl Barycentric {
    /// Interpolates one value per vertex at the point: `sum(weights[i] * values[i])`, rounded
    /// to the nearest `I16F16` and saturating.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use fixed::types::I16F16;
    /// use trirast::Triangle;
    ///
    /// let t = Triangle::new(Point::new(0, 0), Point::new(4, 0), Point::new(0, 4));
    /// let midpoint = t.barycentric(Point::new(2, 0)).unwrap();
    /// let v = midpoint.interpolate([I16F16::from_num(-1), I16F16::from_num(3), I16F16::ZERO]);
    /// assert_eq!(v, I16F16::from_num(1));
    /// ```
    #[must_use]
    pub fn interpolate(&self, values: [I16F16; 3]) -> I16F16 {
        // Weights carry 32 fraction bits and values 16: the sum carries 48.
        let sum: i128 = self
            .weights
            .iter()
            .zip(values)
            .map(|(w, v)| i128::from(w.to_bits()) * i128::from(v.to_bits()))
            .sum();
        let rounded = (sum + (1 << 31)) >> 32;
        I16F16::from_bits(rounded.clamp(i128::from(i32::MIN), i128::from(i32::MAX)) as i32)
    }

    /// True when `rule` draws the point: the same exact decision as [`Triangle::covers`].
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::{FillRule, Triangle};
    ///
    /// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
    /// let on_hypotenuse = t.barycentric(Point::new(4, 4)).unwrap();
    /// assert!(on_hypotenuse.is_drawn_by(&t, Point::new(4, 4), FillRule::Inclusive));
    /// assert!(!on_hypotenuse.is_drawn_by(&t, Point::new(4, 4), FillRule::TopLeft));
    /// ```
    #[must_use]
    pub fn is_drawn_by(&self, triangle: &Triangle, point: Point, rule: FillRule) -> bool {
        match self.location {
            Location::Inside => true,
            Location::Outside => false,
            Location::OnEdge | Location::OnVertex => triangle.covers(point, rule),
        }
    }
}

impl Triangle {
    /// Barycentric coordinates of `point`, or `None` for a degenerate triangle. Exact for any
    /// `i32` coordinates (the weights saturate for points far outside).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use fixed::types::I32F32;
    /// use trirast::Triangle;
    ///
    /// let t = Triangle::new(Point::new(0, 0), Point::new(10, 0), Point::new(0, 10));
    /// assert_eq!(t.barycentric(Point::new(10, 0)).unwrap().weights[1], I32F32::ONE);
    /// assert!(Triangle::new(Point::zero(), Point::zero(), Point::new(1, 1)).barycentric(Point::zero()).is_none());
    /// ```
    #[must_use]
    pub fn barycentric(&self, point: Point) -> Option<Barycentric> {
        let v = self.vertices.map(|p| (i128::from(p.x), i128::from(p.y)));
        let p = (i128::from(point.x), i128::from(point.y));
        // The weight of vertex i is the edge function of the opposite edge at the point,
        // divided by its value at vertex i (twice the signed area).
        let edge = |a: (i128, i128), b: (i128, i128), q: (i128, i128)| {
            (b.0 - a.0) * (q.1 - a.1) - (b.1 - a.1) * (q.0 - a.0)
        };
        let area = edge(v[1], v[2], v[0]);
        if area == 0 {
            return None;
        }
        let numerators = [
            edge(v[1], v[2], p),
            edge(v[2], v[0], p),
            edge(v[0], v[1], p),
        ];
        // Signs relative to the orientation: positive inside.
        let signs = numerators.map(|n| (n * area.signum()).signum());
        let location = if signs.contains(&-1) {
            Location::Outside
        } else {
            match signs.iter().filter(|&&s| s == 0).count() {
                0 => Location::Inside,
                1 => Location::OnEdge,
                _ => Location::OnVertex,
            }
        };
        let weights = numerators.map(|n| {
            // Rounded half up; |n| < 2^66, so n * 2^33 fits.
            let (num, den) = if area < 0 { (-n, -area) } else { (n, area) };
            let w = ((num << 33) + den).div_euclid(den << 1);
            I32F32::from_bits(w.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64)
        });
        Some(Barycentric { weights, location })
    }
}
