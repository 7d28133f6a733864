//! Test support shared by the integration tests: an independent reference rasterizer and
//! instrumented draw targets. Nothing here calls the code under test.
#![allow(dead_code)]

use std::convert::Infallible;

use embedded_graphics::{
    Pixel,
    draw_target::DrawTarget,
    geometry::{Dimensions, OriginDimensions, Point, Size},
    pixelcolor::{BinaryColor, PixelColor},
    primitives::Rectangle,
};

/// The fill rules, restated here so the reference does not depend on the crate.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Rule {
    TopLeft,
    Inclusive,
}

impl Rule {
    pub fn to_crate(self) -> trirast::FillRule {
        match self {
            Rule::TopLeft => trirast::FillRule::TopLeft,
            Rule::Inclusive => trirast::FillRule::Inclusive,
        }
    }
}

/// Exact half-space test in `i128`, straight from the definitions:
///
/// - inclusive: the sample point lies in the closed triangle;
/// - top-left: the sample point moved by `(ε, ε²)` (right, then down by far less) lies strictly
///   inside. For an edge function `w = A x + B y + C` with the interior positive, that is the
///   lexicographic test `(w, A, B) > (0, 0, 0)`.
pub fn reference_covers(v: [Point; 3], p: Point, rule: Rule) -> bool {
    let v = v.map(|q| (i128::from(q.x), i128::from(q.y)));
    let (px, py) = (i128::from(p.x), i128::from(p.y));
    let area = (v[1].0 - v[0].0) * (v[2].1 - v[0].1) - (v[1].1 - v[0].1) * (v[2].0 - v[0].0);
    if area == 0 {
        return false;
    }
    let sign = area.signum();
    (0..3).all(|i| {
        let (a, b) = (v[i], v[(i + 1) % 3]);
        // w(p) = (b - a) x (p - a), times the orientation sign so the interior is positive.
        let coef_x = -(b.1 - a.1) * sign;
        let coef_y = (b.0 - a.0) * sign;
        let w = coef_x * (px - a.0) + coef_y * (py - a.1);
        match rule {
            Rule::Inclusive => w >= 0,
            Rule::TopLeft => (w, coef_x, coef_y) > (0, 0, 0),
        }
    })
}

/// All pixels of `window`, row-major. (embedded-graphics' own iterator and `contains` overflow
/// for windows touching `i32::MAX`.)
pub fn window_points(window: &Rectangle) -> impl Iterator<Item = Point> + '_ {
    let (x0, y0) = (i64::from(window.top_left.x), i64::from(window.top_left.y));
    let (w, h) = (i64::from(window.size.width), i64::from(window.size.height));
    (y0..y0 + h).flat_map(move |y| (x0..x0 + w).map(move |x| Point::new(x as i32, y as i32)))
}

/// True when `p` lies in `window`, without overflow.
pub fn window_contains(window: &Rectangle, p: Point) -> bool {
    let dx = i64::from(p.x) - i64::from(window.top_left.x);
    let dy = i64::from(p.y) - i64::from(window.top_left.y);
    (0..i64::from(window.size.width)).contains(&dx)
        && (0..i64::from(window.size.height)).contains(&dy)
}

/// All pixels of `window` the reference covers, row-major.
pub fn reference_pixels(v: [Point; 3], window: &Rectangle, rule: Rule) -> Vec<Point> {
    window_points(window)
        .filter(|&p| reference_covers(v, p, rule))
        .collect()
}

/// A target of any origin and size that counts how often each pixel is written, through
/// whichever `DrawTarget` method the caller uses, and records the calls.
pub struct CountingTarget {
    pub area: Rectangle,
    pub hits: Vec<u32>,
    pub fill_solid_calls: Vec<Rectangle>,
    pub fill_contiguous_calls: usize,
    pub draw_iter_calls: usize,
    pub outside_writes: usize,
}

impl CountingTarget {
    pub fn new(area: Rectangle) -> Self {
        let n = area.size.width as usize * area.size.height as usize;
        Self {
            area,
            hits: vec![0; n],
            fill_solid_calls: Vec::new(),
            fill_contiguous_calls: 0,
            draw_iter_calls: 0,
            outside_writes: 0,
        }
    }

    fn index(&self, p: Point) -> Option<usize> {
        window_contains(&self.area, p).then_some(())?;
        let x = i64::from(p.x) - i64::from(self.area.top_left.x);
        let y = i64::from(p.y) - i64::from(self.area.top_left.y);
        Some((y * i64::from(self.area.size.width) + x) as usize)
    }

    fn hit(&mut self, p: Point) {
        match self.index(p) {
            Some(i) => self.hits[i] += 1,
            None => self.outside_writes += 1,
        }
    }

    pub fn count(&self, p: Point) -> u32 {
        self.index(p).map_or(0, |i| self.hits[i])
    }

    /// Pixels hit at least once, row-major.
    pub fn covered(&self) -> Vec<Point> {
        window_points(&self.area)
            .filter(|&p| self.count(p) > 0)
            .collect()
    }

    pub fn max_hits(&self) -> u32 {
        self.hits.iter().copied().max().unwrap_or(0)
    }
}

impl OriginDimensions for CountingTarget {
    fn size(&self) -> Size {
        self.area.size
    }
}

/// `DrawTarget` with an arbitrary bounding box (not at the origin), to exercise clipping.
pub struct Offset<T>(pub T);

impl Dimensions for Offset<CountingTarget> {
    fn bounding_box(&self) -> Rectangle {
        self.0.area
    }
}

impl DrawTarget for Offset<CountingTarget> {
    type Color = BinaryColor;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        self.0.draw_iter_calls += 1;
        for Pixel(p, _) in pixels {
            self.0.hit(p);
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = BinaryColor>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        self.0.fill_contiguous_calls += 1;
        for (p, _) in window_points(area).zip(colors) {
            self.0.hit(p);
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, _color: BinaryColor) -> Result<(), Infallible> {
        self.0.fill_solid_calls.push(*area);
        for p in window_points(area) {
            self.0.hit(p);
        }
        Ok(())
    }
}

/// A target that fails on the `fail_at`-th call of any drawing method.
pub struct FailingTarget<C> {
    pub calls: usize,
    pub fail_at: usize,
    pub size: Size,
    pub color: std::marker::PhantomData<C>,
}

#[derive(Debug, PartialEq, Eq)]
pub struct Failed(pub usize);

impl<C> FailingTarget<C> {
    pub fn new(size: Size, fail_at: usize) -> Self {
        Self {
            calls: 0,
            fail_at,
            size,
            color: std::marker::PhantomData,
        }
    }

    fn call(&mut self) -> Result<(), Failed> {
        self.calls += 1;
        if self.calls == self.fail_at {
            Err(Failed(self.calls))
        } else {
            Ok(())
        }
    }
}

impl<C> OriginDimensions for FailingTarget<C> {
    fn size(&self) -> Size {
        self.size
    }
}

impl<C: PixelColor> DrawTarget for FailingTarget<C> {
    type Color = C;
    type Error = Failed;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, _pixels: I) -> Result<(), Failed> {
        self.call()
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(
        &mut self,
        _area: &Rectangle,
        _colors: I,
    ) -> Result<(), Failed> {
        self.call()
    }

    fn fill_solid(&mut self, _area: &Rectangle, _color: C) -> Result<(), Failed> {
        self.call()
    }
}

/// A small deterministic generator for scene construction in tests (splitmix64).
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `lo..=hi`.
    pub fn range(&mut self, lo: i32, hi: i32) -> i32 {
        let span = (i64::from(hi) - i64::from(lo) + 1) as u64;
        (i64::from(lo) + (self.next_u64() % span) as i64) as i32
    }
}

/// Exact rational interpolation: the value at `p` of the plane through `(v[i], a[i])`, as
/// `(numerator, denominator)` with a positive denominator.
pub fn exact_plane(v: [Point; 3], a: [i64; 3], p: Point) -> Option<(i128, i128)> {
    let v = v.map(|q| (i128::from(q.x), i128::from(q.y)));
    let (px, py) = (i128::from(p.x), i128::from(p.y));
    let edge =
        |s: (i128, i128), t: (i128, i128)| (t.0 - s.0) * (py - s.1) - (t.1 - s.1) * (px - s.0);
    let area = (v[2].0 - v[1].0) * (v[0].1 - v[1].1) - (v[2].1 - v[1].1) * (v[0].0 - v[1].0);
    if area == 0 {
        return None;
    }
    // Weight of vertex i: the edge function of the opposite edge, over the area.
    let w = [edge(v[1], v[2]), edge(v[2], v[0]), edge(v[0], v[1])];
    let num: i128 = (0..3).map(|i| w[i] * i128::from(a[i])).sum();
    Some(if area < 0 { (-num, -area) } else { (num, area) })
}

/// `num / den` rounded half up (den > 0).
pub fn round_half_up(num: i128, den: i128) -> i128 {
    (2 * num + den).div_euclid(2 * den)
}

/// A target of any origin and size that records the last colour of each pixel and how many
/// times it was written.
pub struct Recorder<C> {
    pub area: Rectangle,
    pub colors: Vec<Option<C>>,
    pub writes: Vec<u32>,
    pub outside_writes: usize,
}

impl<C: PixelColor> Recorder<C> {
    pub fn new(area: Rectangle) -> Self {
        let n = area.size.width as usize * area.size.height as usize;
        Self {
            area,
            colors: vec![None; n],
            writes: vec![0; n],
            outside_writes: 0,
        }
    }

    fn index(&self, p: Point) -> Option<usize> {
        window_contains(&self.area, p).then_some(())?;
        let x = i64::from(p.x) - i64::from(self.area.top_left.x);
        let y = i64::from(p.y) - i64::from(self.area.top_left.y);
        Some((y * i64::from(self.area.size.width) + x) as usize)
    }

    pub fn get(&self, p: Point) -> Option<C> {
        self.index(p).and_then(|i| self.colors[i])
    }

    pub fn writes_at(&self, p: Point) -> u32 {
        self.index(p).map_or(0, |i| self.writes[i])
    }

    fn put(&mut self, p: Point, c: C) {
        match self.index(p) {
            Some(i) => {
                self.colors[i] = Some(c);
                self.writes[i] += 1;
            }
            None => self.outside_writes += 1,
        }
    }
}

impl<C: PixelColor> Dimensions for Recorder<C> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<C: PixelColor> DrawTarget for Recorder<C> {
    type Color = C;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        for Pixel(p, c) in pixels {
            self.put(p, c);
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        for (p, c) in window_points(area).zip(colors) {
            self.put(p, c);
        }
        Ok(())
    }
}

/// A grid of `nx` x `ny` cells over `area`, inner points jittered, border points sliding along
/// the border only, each cell split along a random diagonal. The union is exactly `area`.
pub fn jittered_grid(area: Rectangle, nx: i32, ny: i32, rng: &mut Rng) -> Vec<[Point; 3]> {
    let (x0, y0) = (area.top_left.x, area.top_left.y);
    let (w, h) = (area.size.width as i32, area.size.height as i32);
    let mut pts = vec![Point::zero(); ((nx + 1) * (ny + 1)) as usize];
    for j in 0..=ny {
        for i in 0..=nx {
            let (cw, ch) = (w / nx, h / ny);
            let mut x = x0 + w * i / nx;
            let mut y = y0 + h * j / ny;
            // Jitter below a quarter cell keeps every quad convex.
            if i != 0 && i != nx {
                x += rng.range(-(cw - 1) / 4, (cw - 1) / 4);
            }
            if j != 0 && j != ny {
                y += rng.range(-(ch - 1) / 4, (ch - 1) / 4);
            }
            pts[(j * (nx + 1) + i) as usize] = Point::new(x, y);
        }
    }
    let at = |i: i32, j: i32| pts[(j * (nx + 1) + i) as usize];
    let mut tris = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if rng.range(0, 1) == 0 {
                tris.push([a, b, c]);
                tris.push([a, c, d]);
            } else {
                tris.push([a, b, d]);
                tris.push([b, c, d]);
            }
        }
    }
    // Every triangle keeps the winding of its cell (clockwise on screen): none folded over.
    for &[a, b, c] in &tris {
        let cross = i64::from(b.x - a.x) * i64::from(c.y - a.y)
            - i64::from(b.y - a.y) * i64::from(c.x - a.x);
        assert!(cross > 0, "grid folded: {:?}", [a, b, c]);
    }
    tris
}
