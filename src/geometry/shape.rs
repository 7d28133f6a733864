//! What the styles draw: whole-pixel and sub-pixel triangles, through one interface.

use embedded_graphics::{geometry::Point, primitives::Rectangle};

use super::{SubPixelTriangle, Triangle};
use crate::{
    coverage::{
        CoverageSink, FillRule, KeptWalk, SpanSink, walk, walk_coverage, walk_erased,
        walk_kept_erased, walk_subpixel, walk_subpixel_coverage,
    },
    interpolate::{AreaMemo, Planes},
};

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Triangle {}
    impl Sealed for super::SubPixelTriangle {}
    impl<G: super::Shape, K: crate::band::SetupCache> Sealed for crate::band::Cached<'_, G, K> {}
}

/// A triangle the crate's styles draw: [`Triangle`] (whole-pixel vertices) or
/// [`SubPixelTriangle`] (vertices in 1/256 pixel). Every style draws either through
/// `into_styled`, and through [`DepthTarget::draw`](crate::depth::DepthTarget::draw) and
/// [`BlendTarget::draw_anti_aliased`](crate::target::BlendTarget::draw_anti_aliased); the
/// code for each is built only for the shapes a program draws.
///
/// # Examples
///
/// ```
/// use embedded_graphics::prelude::*;
/// use trirast::geometry::{Shape, SubPixelTriangle};
/// use trirast::Triangle;
///
/// fn draws<S: Shape>(_: &S) {}
/// let t = Triangle::new(Point::new(0, 0), Point::new(4, 0), Point::new(0, 4));
/// draws(&t);
/// draws(&SubPixelTriangle::from(t));
/// ```
pub trait Shape: sealed::Sealed {
    /// Feeds the covered spans inside `clip` to `sink`, row by row.
    #[doc(hidden)]
    fn walk_spans<K: SpanSink + ?Sized>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        sink: &mut K,
    ) -> Result<(), K::Error>;

    /// [`Shape::walk_spans`] for a sink behind `dyn`.
    #[doc(hidden)]
    fn walk_spans_erased<E>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        sink: &mut dyn SpanSink<Error = E>,
    ) -> Result<(), E>;

    /// [`Shape::walk_spans_erased`] window after window down the screen (bands): going on
    /// from the walk `kept` left at `clip`'s first row, and leaving the walk at its last for
    /// the window below when `later`. Shapes without such a walk start again in every window.
    #[doc(hidden)]
    #[inline(always)]
    fn walk_spans_erased_kept<E>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        sink: &mut dyn SpanSink<Error = E>,
        kept: &KeptWalk,
        later: bool,
    ) -> Result<(), E> {
        let _ = (kept, later);
        self.walk_spans_erased(rule, clip, sink)
    }

    /// Feeds the area coverage inside `clip` to `sink`.
    #[doc(hidden)]
    fn walk_area<K: CoverageSink>(&self, clip: &Rectangle, sink: &mut K) -> Result<(), K::Error>;

    /// The pixel rows the triangle can cover, with or without anti-aliasing, first and last
    /// (both included). Degenerate triangles have rows too (they cover none of them): telling
    /// them apart takes two 64-bit products per triangle, where drawing rejects them anyway.
    #[doc(hidden)]
    fn sample_rows(&self) -> (i64, i64);

    /// Planes of per-vertex `values` (with `bias`) evaluated from `reference`, the area's
    /// reciprocal through `memo` when there is one (shared by the set-ups of one triangle:
    /// its colours, then its depth).
    #[doc(hidden)]
    fn planes<const N: usize, const SETUP: u32>(
        &self,
        values: [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>>;

    /// [`Shape::planes`] of the values `values` gives, computed only where the planes
    /// are made (band rendering may have them already; the rare exact set-up takes them
    /// through memory, where the common one need not). Every value is whole and below
    /// `2^WHOLE_BITS` in magnitude (0 when nothing is known; colour channels:
    /// `CHANNEL_BITS`, depths: `DEPTH_BITS`).
    #[doc(hidden)]
    #[inline(always)]
    fn planes_with<const N: usize, const SETUP: u32, const WHOLE_BITS: u32>(
        &self,
        values: impl Fn() -> [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>> {
        self.planes(values(), bias, reference, memo)
    }

    /// [`Shape::planes_with`]'s planes as `adjust` leaves them: set-ups derived from planes,
    /// which band rendering keeps between bands in their stead.
    #[doc(hidden)]
    #[inline(always)]
    fn planes_adjusted<const N: usize, const SETUP: u32, const WHOLE_BITS: u32>(
        &self,
        values: impl Fn() -> [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
        adjust: impl FnOnce(&mut Planes<N, SETUP>),
    ) -> Option<Planes<N, SETUP>> {
        let mut planes = self.planes_with::<N, SETUP, WHOLE_BITS>(values, bias, reference, memo)?;
        adjust(&mut planes);
        Some(planes)
    }

    /// Planes of per-vertex `values` with their reference kept within `window`, the area's
    /// reciprocal through `memo` (see [`Shape::planes`]).
    #[doc(hidden)]
    fn planes_in<const N: usize, const SETUP: u32>(
        &self,
        values: [[i64; N]; 3],
        bias: i64,
        window: &Rectangle,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>>;
}

impl Shape for Triangle {
    #[inline]
    fn sample_rows(&self) -> (i64, i64) {
        let ys = self.vertices.map(|p| i64::from(p.y));
        (ys[0].min(ys[1]).min(ys[2]), ys[0].max(ys[1]).max(ys[2]))
    }

    #[inline(always)]
    fn walk_spans<K: SpanSink + ?Sized>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        sink: &mut K,
    ) -> Result<(), K::Error> {
        walk(self, rule, clip, sink)
    }

    #[inline(always)]
    fn walk_spans_erased<E>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        sink: &mut dyn SpanSink<Error = E>,
    ) -> Result<(), E> {
        walk_erased(self, rule, clip, sink)
    }

    #[inline(always)]
    fn walk_spans_erased_kept<E>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        sink: &mut dyn SpanSink<Error = E>,
        kept: &KeptWalk,
        later: bool,
    ) -> Result<(), E> {
        walk_kept_erased(self, rule, clip, sink, kept, later)
    }

    #[inline(always)]
    fn walk_area<K: CoverageSink>(&self, clip: &Rectangle, sink: &mut K) -> Result<(), K::Error> {
        walk_coverage(self, clip, sink)
    }

    #[inline(always)]
    fn planes<const N: usize, const SETUP: u32>(
        &self,
        values: [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>> {
        Planes::new(self.vertices, values, bias, reference, memo)
    }

    #[inline(always)]
    fn planes_with<const N: usize, const SETUP: u32, const WHOLE_BITS: u32>(
        &self,
        values: impl Fn() -> [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>> {
        // Values made in the branch that sets up, where the set-up is inline (the exact one
        // then no longer makes the small one store them first: Gouraud -3% per small triangle
        // on Cortex-M4F and x86-64); on Cortex-M0 both set-ups are calls that take them through
        // memory, and made there they measured 1% more per small depth-tested triangle.
        if crate::arch::DIVIDES {
            Planes::new_with::<WHOLE_BITS>(self.vertices, values, bias, reference, memo)
        } else {
            Planes::new_whole::<WHOLE_BITS>(self.vertices, values(), bias, reference, memo)
        }
    }

    #[inline(always)]
    fn planes_in<const N: usize, const SETUP: u32>(
        &self,
        values: [[i64; N]; 3],
        bias: i64,
        window: &Rectangle,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>> {
        Planes::new_in(self.vertices, values, bias, window, memo)
    }
}

impl SubPixelTriangle {
    /// The same triangle with whole-pixel vertices, when every vertex is on a whole pixel:
    /// its planes are then set up as that [`Triangle`]'s, so that it draws exactly what the
    /// `Triangle` draws.
    #[inline(always)]
    fn whole(&self) -> Option<Triangle> {
        let [a, b, c] = self.vertices.map(|p| (p.x.to_bits(), p.y.to_bits()));
        if (a.0 | a.1 | b.0 | b.1 | c.0 | c.1) & 0xFF != 0 {
            return None;
        }
        let point = |(x, y): (i32, i32)| Point::new(x >> 8, y >> 8);
        Some(Triangle::new(point(a), point(b), point(c)))
    }
}

impl Shape for SubPixelTriangle {
    #[inline]
    fn sample_rows(&self) -> (i64, i64) {
        let ys = self.vertices.map(|p| i64::from(p.y.to_bits()));
        let (top, bottom) = (ys[0].min(ys[1]).min(ys[2]), ys[0].max(ys[1]).max(ys[2]));
        // Rows whose pixel squares (half a pixel either side of the samples) the vertices
        // reach: anti-aliasing covers those.
        ((top - 128) >> 8, (bottom + 128) >> 8)
    }

    #[inline(always)]
    fn walk_spans<K: SpanSink + ?Sized>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        sink: &mut K,
    ) -> Result<(), K::Error> {
        // Whole-pixel vertices cover what the whole-pixel walk covers (tests/suite/subpixel.rs):
        // one walk is built, not both.
        walk_subpixel(self, rule, clip, sink)
    }

    #[inline(never)]
    fn walk_spans_erased<E>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        sink: &mut dyn SpanSink<Error = E>,
    ) -> Result<(), E> {
        walk_subpixel(self, rule, clip, sink)
    }

    #[inline(always)]
    fn walk_area<K: CoverageSink>(&self, clip: &Rectangle, sink: &mut K) -> Result<(), K::Error> {
        walk_subpixel_coverage(self, clip, sink)
    }

    #[inline(always)]
    fn planes<const N: usize, const SETUP: u32>(
        &self,
        values: [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>> {
        if let Some(whole) = self.whole() {
            return whole.planes(values, bias, reference, memo);
        }
        let raw = self.vertices.map(|p| (p.x.to_bits(), p.y.to_bits()));
        Planes::new_subpixel(raw, values, bias, reference, memo)
    }

    #[inline(always)]
    fn planes_with<const N: usize, const SETUP: u32, const WHOLE_BITS: u32>(
        &self,
        values: impl Fn() -> [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>> {
        // As the whole-pixel triangle's.
        if let Some(whole) = self.whole() {
            return whole.planes_with::<N, SETUP, WHOLE_BITS>(values, bias, reference, memo);
        }
        if !crate::arch::DIVIDES {
            let raw = self.vertices.map(|p| (p.x.to_bits(), p.y.to_bits()));
            let values = values();
            return Planes::new_subpixel_whole::<WHOLE_BITS>(raw, values, bias, reference, memo);
        }
        let raw = self.vertices.map(|p| (p.x.to_bits(), p.y.to_bits()));
        Planes::new_subpixel_with::<WHOLE_BITS>(raw, values, bias, reference, memo)
    }

    #[inline(always)]
    fn planes_in<const N: usize, const SETUP: u32>(
        &self,
        values: [[i64; N]; 3],
        bias: i64,
        window: &Rectangle,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>> {
        if let Some(whole) = self.whole() {
            return whole.planes_in(values, bias, window, memo);
        }
        let raw = self.vertices.map(|p| (p.x.to_bits(), p.y.to_bits()));
        Planes::new_subpixel_in(raw, values, bias, window, memo)
    }
}
