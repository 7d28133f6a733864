//! Plane equations of per-vertex attributes, in fixed point.

use core::cell::Cell;

use embedded_graphics::{geometry::Point, primitives::Rectangle};

use crate::setup::lane::{
    div_rem_u64, floor_div_rem_i128, mul_16_by_32, mul_count, mul_u32, shl64, shr64, widening_mul,
};
use crate::setup::reciprocal::{divide_by_inverse, normalise, reciprocal};

/// Values step along spans with 16 fraction bits (in [`Planes::step`]).
const STEP_BITS: u32 = 16;

/// Fixed-point planes of `N` per-vertex attributes over one triangle, evaluated with `SETUP`
/// fraction bits (32 by default; texture coordinates use 46, keeping 18 integer bits).
///
/// Attribute values are 16.16 fixed point, handled as raw two's complement bits with wrapping
/// arithmetic, so signed (`I16F16`) and unsigned (`U16F16`) attributes share the code: only the
/// true value of an attribute inside the triangle must fit 32 bits, not the intermediate terms.
///
/// [`Planes::at`] evaluates every plane at a pixel directly from the reference point, with the
/// gradients rounded to 2^-SETUP per pixel, so rows never accumulate error. Along a span the values
/// then step by [`Planes::step`] (2^-16 per pixel), additions only.
#[derive(Copy, Clone, Debug)]
pub struct Planes<const N: usize, const SETUP: u32 = 32> {
    origin: Point,
    /// Values at `origin`, in 2^-SETUP units.
    pub(crate) base: [i64; N],
    /// d/dx and d/dy in 2^-SETUP units per pixel (wrapping: only sums are meaningful).
    pub(crate) dx: [i64; N],
    pub(crate) dy: [i64; N],
    /// d/dx in 2^-16 units per pixel, for stepping along a span.
    pub(crate) step: [u32; N],
}

/// The reciprocal of the last area a triangle's plane set-ups divided by, kept for the next
/// set-up of the same triangle: a depth-tested triangle sets up its colours, then its depth,
/// over the same area, and the reciprocal is the costliest part of a small set-up on
/// Cortex-M0 (about 200 instructions, no divider). Keyed by the divisor and by which
/// reciprocal it was (whole-pixel or sub-pixel: small areas' divisors are below 2^31, so the
/// top bit tells them apart), so a stale entry is never used.
#[derive(Debug, Default)]
pub struct AreaMemo {
    /// The divisor, with the top bit set for a sub-pixel one; 0 (no area divides by it) when
    /// empty.
    key: Cell<u64>,
    reciprocal: Cell<u64>,
}

impl AreaMemo {
    /// Nothing kept yet.
    #[inline(always)]
    pub(crate) const fn new() -> Self {
        Self {
            key: Cell::new(0),
            reciprocal: Cell::new(0),
        }
    }

    /// `reciprocal(divisor)`, from the memo when it holds it for the same kind of area, else
    /// computed and kept.
    #[inline(always)]
    fn get(&self, divisor: u64, subpixel: bool, reciprocal: fn(u64) -> u64) -> u64 {
        let key = divisor | u64::from(subpixel) << 63;
        if self.key.get() == key {
            return self.reciprocal.get();
        }
        let value = reciprocal(divisor);
        self.key.set(key);
        self.reciprocal.set(value);
        value
    }
}

/// `reciprocal(divisor)` through `memo` when there is one, on cores without a divider
/// (Cortex-M0/M0+: see [`crate::arch::DIVIDES`]). With one, a small area's reciprocal
/// is three divisions, and keeping it cost more than it saved (measured: +0.4% per small
/// depth-tested triangle on Cortex-M4F, the memo made for every triangle).
#[inline(always)]
fn remembered(
    memo: Option<&AreaMemo>,
    divisor: u64,
    subpixel: bool,
    reciprocal: fn(u64) -> u64,
) -> u64 {
    match memo {
        Some(memo) if !crate::arch::DIVIDES => memo.get(divisor, subpixel, reciprocal),
        _ => reciprocal(divisor),
    }
}

impl<const N: usize, const SETUP: u32> Planes<N, SETUP> {
    /// Plane equations through `values` (raw 16.16, one array per vertex) at `vertices`, with
    /// `bias` (raw 16.16) added to every value; `None` for degenerate triangles.
    ///
    /// `reference` is the point the evaluation distances are measured from: any pixel near the
    /// area drawn (the clip window's corner, say). Triangles no larger than 2^15 pixels across
    /// use their first vertex instead, which costs no division; larger ones evaluate the planes
    /// exactly at the reference, so precision never depends on how far the vertices lie.
    #[inline(always)]
    pub(crate) fn new(
        vertices: [Point; 3],
        values: [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        Self::new_whole::<0>(vertices, values, bias, reference, memo)
    }

    /// [`Planes::new`] of values known to be whole and below `2^WHOLE_BITS` in magnitude
    /// (0 when nothing is known: see [`CHANNEL_BITS`]).
    #[inline(always)]
    pub(crate) fn new_whole<const WHOLE_BITS: u32>(
        vertices: [Point; 3],
        values: [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        match edges_within(vertices.map(wide), SMALL_BITS) {
            Some(e) => Self::new_small::<WHOLE_BITS>(vertices[0], values, bias, e, memo),
            None => Self::new_exact(vertices, values, bias, reference),
        }
    }

    /// [`Planes::new`] of the values `values` gives, made in the branch that sets up: the
    /// rare exact set-up takes them through memory, which should not make the common one
    /// store them first. (`Planes::new` is not written through this: on Cortex-M0, where
    /// both set-ups are calls, that measured 1% more per small depth-tested triangle.)
    #[inline(always)]
    pub(crate) fn new_with<const WHOLE_BITS: u32>(
        vertices: [Point; 3],
        values: impl Fn() -> [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        match edges_within(vertices.map(wide), SMALL_BITS) {
            Some(e) => Self::new_small::<WHOLE_BITS>(vertices[0], values(), bias, e, memo),
            None => Self::new_exact(vertices, values(), bias, reference),
        }
    }

    /// Plane equations as [`Planes::new`], with the reference kept within `window`: the first
    /// vertex when it lies inside and the triangle is small, else the window's top-left corner.
    /// Every pixel of the window then lies within the window's width and height of the
    /// reference, which bounds the rounding error of [`Planes::at_exact`] whatever the
    /// triangle's size.
    #[inline(always)]
    pub(crate) fn new_in(
        vertices: [Point; 3],
        values: [[i64; N]; 3],
        bias: i64,
        window: &Rectangle,
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        // A triangle crossing the window's edge may have its first vertex outside: it starts
        // from another vertex, inside, when there is one (the same plane and the same
        // gradients, the exact ones rounded; a mesh's border triangles on Cortex-M4F then
        // cost 2% less on average).
        let (vertices, values) = if contains(window, vertices[0]) {
            (vertices, values)
        } else {
            match rotate_into(vertices, values, |p| contains(window, p)) {
                Some(rotated) => rotated,
                None => return Self::new_exact(vertices, values, bias, window.top_left),
            }
        };
        match edges_within(vertices.map(wide), SMALL_BITS) {
            Some(e) => Self::new_small::<0>(vertices[0], values, bias, e, memo),
            None => Self::new_exact(vertices, values, bias, window.top_left),
        }
    }

    /// Plane equations as [`Planes::new`] for vertices in 1/256 pixel (a
    /// [`SubPixelTriangle`](crate::geometry::SubPixelTriangle)'s): gradients per pixel rounded
    /// as for whole-pixel vertices, the reference a whole pixel.
    #[inline(always)]
    pub(crate) fn new_subpixel(
        vertices: [(i32, i32); 3],
        values: [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        Self::new_subpixel_whole::<0>(vertices, values, bias, reference, memo)
    }

    /// [`Planes::new_subpixel`] of values known to be whole and below `2^WHOLE_BITS` in
    /// magnitude, as [`Planes::new_whole`].
    #[inline(always)]
    pub(crate) fn new_subpixel_whole<const WHOLE_BITS: u32>(
        vertices: [(i32, i32); 3],
        values: [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        let wide = vertices.map(|(x, y)| (i64::from(x), i64::from(y)));
        match edges_within(wide, SMALL_BITS) {
            Some(e) => Self::new_small_subpixel::<WHOLE_BITS>(wide[0], values, bias, e, memo),
            None => Self::new_large_subpixel(vertices, values, bias, reference),
        }
    }

    /// [`Planes::new_subpixel`] of the values `values` gives, made in the branch that sets up,
    /// as [`Planes::new_with`].
    #[inline(always)]
    pub(crate) fn new_subpixel_with<const WHOLE_BITS: u32>(
        vertices: [(i32, i32); 3],
        values: impl Fn() -> [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        let wide = vertices.map(|(x, y)| (i64::from(x), i64::from(y)));
        match edges_within(wide, SMALL_BITS) {
            Some(e) => Self::new_small_subpixel::<WHOLE_BITS>(wide[0], values(), bias, e, memo),
            None => Self::new_large_subpixel(vertices, values(), bias, reference),
        }
    }

    /// [`Planes::new_in`] for vertices in 1/256 pixel: see [`Planes::new_subpixel`].
    #[inline(always)]
    pub(crate) fn new_subpixel_in(
        vertices: [(i32, i32); 3],
        values: [[i64; N]; 3],
        bias: i64,
        window: &Rectangle,
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        // From a vertex whose pixel lies in the window, as `new_in`.
        let pixel = |(x, y): (i32, i32)| Point::new(x >> 8, y >> 8);
        let (vertices, values) = if window.contains(pixel(vertices[0])) {
            (vertices, values)
        } else {
            match rotate_into(vertices, values, |v| window.contains(pixel(v))) {
                Some(rotated) => rotated,
                None => return Self::new_large_subpixel(vertices, values, bias, window.top_left),
            }
        };
        let wide = vertices.map(|(x, y)| (i64::from(x), i64::from(y)));
        match edges_within(wide, SMALL_BITS) {
            Some(e) => Self::new_small_subpixel::<0>(wide[0], values, bias, e, memo),
            None => Self::new_large_subpixel(vertices, values, bias, window.top_left),
        }
    }

    /// [`Planes::new_small`] for vertices in 1/256 pixel under 2^15 units (128 pixels) apart:
    /// the gradients per 1/256 pixel scaled to per pixel in the same rounding, and the values
    /// moved from the first vertex to the whole pixel at or above-left of it. Inline on every
    /// core: out of line on Cortex-M0 (as `new_small` is) it measured 1 KB less flash in the
    /// every-mode firmware but 3% more instructions per small sub-pixel triangle.
    #[inline(always)]
    fn new_small_subpixel<const WHOLE_BITS: u32>(
        first: (i64, i64),
        values: [[i64; N]; 3],
        bias: i64,
        e: [i64; 4],
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        let [ex1, ey1, ex2, ey2] = e;
        let area = i64::from(ex1 as i32 * ey2 as i32 - ex2 as i32 * ey1 as i32);
        if area == 0 {
            return None;
        }
        let divisor = area.unsigned_abs();
        let reciprocal = remembered(memo, divisor, true, reciprocal_2_62_subpixel);
        // As in `new_small`, and 8 bits less of shift: 256 units to a pixel.
        let shift = 62 - (SETUP - STEP_BITS) - 8;
        let origin = Point::new((first.0 >> 8) as i32, (first.1 >> 8) as i32);
        let (fx, fy) = (first.0 & 255, first.1 & 255);
        let mut base = values[0].map(|a0| (a0 + bias) << (SETUP - STEP_BITS));
        // Ones rather than zeros, as in `new_small`: no `memclr` calls at `opt-level = "s"`.
        let (mut dx, mut dy) = ([1; N], [1; N]);
        let e = [ex1, ey1, ex2, ey2].map(|d| d as i32);
        for k in 0..N {
            let (a0, a1, a2) = (values[0][k], values[1][k], values[2][k]);
            let (da1, da2) = (a1 - a0, a2 - a0);
            // As in `new_small` (written out in both: one helper for the two measured 1.8% more
            // instructions per small Gouraud triangle on Cortex-M0).
            let whole = if crate::arch::DIVIDES {
                None
            } else {
                whole_numerators_of::<WHOLE_BITS>(da1, da2, e)
            };
            if let Some(gradients) =
                depth_gradients::<WHOLE_BITS>(da1, da2, e, reciprocal, area < 0, shift)
            {
                [dx[k], dy[k]] = gradients;
            } else if let Some([wx, wy]) = whole {
                dx[k] = scale_whole(wx, reciprocal, area < 0, shift);
                dy[k] = scale_whole(wy, reciprocal, area < 0, shift);
            } else if let Some(gradients) =
                level_gradients::<WHOLE_BITS>(da1, da2, e, reciprocal, area < 0, shift)
            {
                [dx[k], dy[k]] = gradients;
            } else {
                [dx[k], dy[k]] =
                    fractional_gradients::<SETUP, 8>(da1, da2, e, reciprocal, area < 0);
            }
            // The origin lies (fx, fy) / 256 pixel up and left of the vertex.
            base[k] = base[k]
                .wrapping_sub(fraction_of(dx[k], fx))
                .wrapping_sub(fraction_of(dy[k], fy));
        }
        Some(Self::from_parts(origin, base, dx, dy))
    }

    /// Setup for sub-pixel triangles too large for [`Planes::new_small_subpixel`]: by
    /// [`medium_plane`] under 2^19 units (2,048 pixels) across, beyond by
    /// [`exact_plane_subpixel`] ([`Planes::new_exact`] for vertices in 1/256 pixel, values
    /// evaluated at `reference`). Out of line: big triangles only.
    #[cold]
    #[inline(never)]
    fn new_large_subpixel(
        vertices: [(i32, i32); 3],
        values: [[i64; N]; 3],
        bias: i64,
        reference: Point,
    ) -> Option<Self> {
        let large = medium_setup(vertices, SETUP - STEP_BITS);
        let origin = match &large {
            Large::Medium(medium) => medium.origin,
            Large::Degenerate => return None,
            Large::Exact => reference,
        };
        let (mut base, mut dx, mut dy) = ([0; N], [0; N], [0; N]);
        for k in 0..N {
            let values = [values[0][k], values[1][k], values[2][k]];
            (base[k], dx[k], dy[k]) = match &large {
                Large::Medium(medium) => {
                    let at_vertex = (values[0] + bias) << (SETUP - STEP_BITS);
                    medium_plane(values, at_vertex, medium)
                }
                _ => exact_plane_subpixel(vertices, values, bias, reference, SETUP - STEP_BITS)?,
            };
        }
        Some(Self::from_parts(origin, base, dx, dy))
    }

    /// Setup for triangles under 2^15 pixels across: one division (a reciprocal of the area)
    /// for all gradients, and the first vertex as reference, where values are exact.
    ///
    /// Out of line on cores without a 64-bit multiply (Cortex-M0/M0+), where flash is
    /// scarcest: one copy per number of planes instead of one per style and target, 25 KB
    /// less in the every-mode firmware for 1 to 7% more instructions per small interpolated
    /// triangle (the depth plane then computes the area's reciprocal again). Inline elsewhere:
    /// out of line it measured 11 to 15% more per small interpolated triangle on Cortex-M4F,
    /// for 11 KB. Values that are not whole take [`fractional_gradients`], a call on
    /// Cortex-M0 shared by every number of planes (firmware 0.9 to 2.2 KB smaller,
    /// Gouraud 1% faster per small triangle, texture mapping 0.5% and perspective 2% slower).
    /// Values known to be whole (`WHOLE_BITS`, see [`whole_numerators_of`]) never take it: on
    /// Cortex-M0 colour set-ups have a copy of their own, which links none of it.
    #[cfg_attr(not(target_has_atomic = "32"), inline(never))]
    #[cfg_attr(target_has_atomic = "32", inline(always))]
    fn new_small<const WHOLE_BITS: u32>(
        origin: Point,
        values: [[i64; N]; 3],
        bias: i64,
        e: [i64; 4],
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        let [ex1, ey1, ex2, ey2] = e;
        // |deltas| < 2^15: doubled area below 2^31, numerators below 2^49. The area in 32-bit
        // arithmetic: on Cortex-M0 a 64-bit multiply is a library call.
        let area = i64::from(ex1 as i32 * ey2 as i32 - ex2 as i32 * ey1 as i32);
        if area == 0 {
            return None;
        }
        // Gradient = numerator / area, to 2^-SETUP: numerator * 2^(SETUP - 16) (raw values
        // carry 2^-16) times 2^62 / |area|, shifted down by 62 - (SETUP - 16). The reciprocal
        // is below 2^62 and the products below 2^111.
        let divisor = area.unsigned_abs();
        let reciprocal = remembered(memo, divisor, false, reciprocal_2_62);
        let shift = 62 - (SETUP - STEP_BITS);
        // Local arrays, then one struct: filling a zeroed struct field by field left the
        // zeroing (a library call) in place. The values at the vertex by `map`, after the loop:
        // a third array zeroed and filled in it cost Cortex-M0 40 instructions per Gouraud set-up.
        // Filled with ones, not zeros: every element is overwritten below, and at `opt-level =
        // "s"` (where the loop stays a loop) a zeroed array is a `memclr` call of about 90
        // instructions each, a filled one a few stores.
        let (mut dx, mut dy) = ([1; N], [1; N]);
        let e = [ex1, ey1, ex2, ey2].map(|d| d as i32);
        for k in 0..N {
            let (a0, a1, a2) = (values[0][k], values[1][k], values[2][k]);
            let (da1, da2) = (a1 - a0, a2 - a0);
            // Whole values (colours, depths) take 64-bit arithmetic (see `scale_whole`) on
            // cores without a 64-bit multiply. Elsewhere, where this setup is inline in every
            // style and target, colours (known whole and below 2^8) take 32-bit numerators and
            // one 32 x 64-bit product each (`scale_levels`: Cortex-M4F -6% per small Gouraud
            // triangle, -3.6% with depth), on Arm depths (below 2^16) the same from 33-bit
            // numerators (`scale_wide_levels`: -4.9% more with depth; x86-64, whose 64 x 64-bit
            // product is one instruction, +1.3%), everything else the 64 x 64-bit one
            // (the Cortex-M0 path there measured -5 to -6% beside it for 5.3 KB more in the
            // every-mode firmware, and alone +9%). Every path gives the same gradients, bit for
            // bit.
            let whole = if crate::arch::DIVIDES {
                None
            } else {
                whole_numerators_of::<WHOLE_BITS>(da1, da2, e)
            };
            if let Some(gradients) =
                depth_gradients::<WHOLE_BITS>(da1, da2, e, reciprocal, area < 0, shift)
            {
                [dx[k], dy[k]] = gradients;
            } else if let Some([wx, wy]) = whole {
                dx[k] = scale_whole(wx, reciprocal, area < 0, shift);
                dy[k] = scale_whole(wy, reciprocal, area < 0, shift);
            } else if let Some(gradients) =
                level_gradients::<WHOLE_BITS>(da1, da2, e, reciprocal, area < 0, shift)
            {
                [dx[k], dy[k]] = gradients;
            } else {
                [dx[k], dy[k]] =
                    fractional_gradients::<SETUP, 0>(da1, da2, e, reciprocal, area < 0);
            }
        }
        let base = values[0].map(|a0| (a0 + bias) << (SETUP - STEP_BITS));
        Some(Self::from_parts(origin, base, dx, dy))
    }

    /// Setup for any triangle: exact 128-bit arithmetic, values evaluated at `reference`.
    #[cold]
    #[inline(never)]
    fn new_exact(
        vertices: [Point; 3],
        values: [[i64; N]; 3],
        bias: i64,
        reference: Point,
    ) -> Option<Self> {
        let mut planes = Self::empty(reference);
        for k in 0..N {
            let values = [values[0][k], values[1][k], values[2][k]];
            let (base, dx, dy) = exact_plane(vertices, values, bias, reference, SETUP - STEP_BITS)?;
            planes.base[k] = base;
            planes.dx[k] = dx;
            planes.dy[k] = dy;
        }
        planes.finish();
        Some(planes)
    }

    /// Words [`Planes::store`] writes: the origin, then each plane's value and gradients
    /// (the steps follow from the gradients).
    pub(crate) const WORDS: usize = 1 + 3 * N;

    /// Writes the planes to `words` (at least [`Planes::WORDS`] long; nothing otherwise), for
    /// [`Planes::load`] to read back bit for bit: band rendering keeps set-ups between bands.
    #[inline]
    pub(crate) fn store(&self, words: &[Cell<i64>]) {
        let Some(words) = words.get(..Self::WORDS) else {
            return;
        };
        let (x, y) = (self.origin.x as u32, self.origin.y as u32);
        words[0].set((u64::from(x) | u64::from(y) << 32) as i64);
        for (k, plane) in words[1..].chunks_exact(3).enumerate().take(N) {
            plane[0].set(self.base[k]);
            plane[1].set(self.dx[k]);
            plane[2].set(self.dy[k]);
        }
    }

    /// The planes [`Planes::store`] wrote to `words`; `None` if they are too short.
    #[inline]
    pub(crate) fn load(words: &[Cell<i64>]) -> Option<Self> {
        let words = words.get(..Self::WORDS)?;
        let origin = words[0].get() as u64;
        let origin = Point::new(origin as u32 as i32, (origin >> 32) as u32 as i32);
        let (mut base, mut dx, mut dy) = ([0; N], [0; N], [0; N]);
        for (k, plane) in words[1..].chunks_exact(3).enumerate().take(N) {
            (base[k], dx[k], dy[k]) = (plane[0].get(), plane[1].get(), plane[2].get());
        }
        Some(Self::from_parts(origin, base, dx, dy))
    }

    /// Planes that are zero everywhere: a placeholder.
    #[inline(always)]
    pub(crate) fn zero() -> Self {
        Self::empty(Point::zero())
    }

    #[inline(always)]
    fn empty(origin: Point) -> Self {
        Self {
            origin,
            base: [0; N],
            dx: [0; N],
            dy: [0; N],
            step: [0; N],
        }
    }

    /// Makes these planes' first of value `base` and gradients `dx`, `dy` (wrapping) from the
    /// same origin, for [`TrackedPlanes::first_at`], whose user reads nothing else (its own
    /// step along a span included). The rest stays as it was: zeroing it cost 15 to 60
    /// instructions per triangle (Cortex-M0 and M4F Gouraud, measured 2026-12-05).
    #[inline(always)]
    pub(crate) fn keep_first(&mut self, base: i64, dx: i64, dy: i64) {
        self.base[0] = base;
        self.dx[0] = dx;
        self.dy[0] = dy;
    }

    /// Where the planes are evaluated from: their values there are [`Planes::base`].
    #[inline(always)]
    pub(crate) fn origin(&self) -> Point {
        self.origin
    }

    /// Planes from their values at `origin` and gradients, with the steps derived.
    #[inline(always)]
    fn from_parts(origin: Point, base: [i64; N], dx: [i64; N], dy: [i64; N]) -> Self {
        let mut planes = Self {
            origin,
            base,
            dx,
            dy,
            step: [0; N],
        };
        planes.finish();
        planes
    }

    /// Derives the per-pixel steps from the gradients.
    #[inline(always)]
    fn finish(&mut self) {
        let half = 1i64 << (SETUP - STEP_BITS - 1);
        for k in 0..N {
            self.step[k] = (self.dx[k].wrapping_add(half) >> (SETUP - STEP_BITS)) as u32;
        }
    }

    /// All values at pixel `(x, y)` in 2^-SETUP units (bias included).
    #[inline(always)]
    pub(crate) fn at_exact(&self, x: i32, y: i32) -> [i64; N] {
        let ddx = i64::from(x) - i64::from(self.origin.x);
        let ddy = i64::from(y) - i64::from(self.origin.y);
        let mut out = [0; N];
        for k in 0..N {
            out[k] = self.base[k]
                .wrapping_add(self.dx[k].wrapping_mul(ddx))
                .wrapping_add(self.dy[k].wrapping_mul(ddy));
        }
        out
    }

    /// Raw 16.16 values for stepping, from values in 2^-SETUP units.
    #[inline(always)]
    pub(crate) fn to_step_units(values: &[i64; N]) -> [u32; N] {
        values.map(|v| (v >> (SETUP - STEP_BITS)) as u32)
    }

    /// All values at pixel `(x, y)`, raw 16.16 (bias included).
    #[inline(always)]
    pub(crate) fn at(&self, x: i32, y: i32) -> [u32; N] {
        Self::to_step_units(&self.at_exact(x, y))
    }
}

/// What set-ups of colour channels (`u8`, as raw 16.16) know of their values: whole, and
/// below 2^8. A set-up's `WHOLE_BITS` (0 when nothing is known, as for texture coordinates
/// and shader attributes) lets it take the whole-valued gradients only (see
/// [`whole_numerators_of`]).
pub(crate) const CHANNEL_BITS: u32 = 8;

/// What depth set-ups (`u16`, as raw 16.16) know of their values: whole, and below 2^16 (see
/// [`depth_gradients`]).
pub(crate) const DEPTH_BITS: u32 = 16;

/// Deltas below which a triangle takes the small set-up (vertices under 2^15 units apart).
const SMALL_BITS: u32 = 15;

/// A point's coordinates as `i64`.
#[inline(always)]
fn wide(p: Point) -> (i64, i64) {
    (i64::from(p.x), i64::from(p.y))
}

/// The gradients `[dx, dy]` (2^-`SETUP` units per pixel) of a small triangle's plane with
/// value deltas `da1`, `da2` along edges `e` (in 2^-`SUBPIXEL_BITS` pixel: 0 for whole-pixel
/// vertices, 8 for sub-pixel ones), through the doubled area's `reciprocal`, for the values
/// [`whole_numerators`] does not take (texture coordinates, depths far apart): see
/// [`Planes::new_small`]. Out of line on Cortex-M0, one copy per set-up precision: inline,
/// each number of planes had its own (2 KB each).
#[cfg_attr(not(target_has_atomic = "32"), inline(never))]
#[cfg_attr(target_has_atomic = "32", inline(always))]
fn fractional_gradients<const SETUP: u32, const SUBPIXEL_BITS: u32>(
    da1: i64,
    da2: i64,
    e: [i32; 4],
    reciprocal: u64,
    negative: bool,
) -> [i64; 2] {
    let shift = 62 - (SETUP - STEP_BITS) - SUBPIXEL_BITS;
    // Each written out, not by `map`: as a loop, the two constant shifts of `scale_split`
    // became one variable shift, library calls on Cortex-M0.
    let [nx, ny] = numerators(da1, da2, e);
    [
        scale(nx, reciprocal, negative, shift),
        scale(ny, reciprocal, negative, shift),
    ]
}

/// The edges from the first vertex to the others, `[ex1, ey1, ex2, ey2]`, when every delta is
/// below `2^bits` in magnitude; `None` otherwise.
#[inline(always)]
fn edges_within([p0, p1, p2]: [(i64, i64); 3], bits: u32) -> Option<[i64; 4]> {
    let e = [p1.0 - p0.0, p1.1 - p0.1, p2.0 - p0.0, p2.1 - p0.1];
    // The bound is a power of two: the magnitudes' OR is below it exactly when each is. One
    // test instead of four.
    let magnitudes = e.iter().fold(0, |all, d| all | d.unsigned_abs());
    (magnitudes < 1 << bits).then_some(e)
}

/// The vertices and their values taken in turn from the second or third vertex, whichever
/// first is `inside` (the window); `None` when neither is. Out of line: only triangles
/// crossing the window's edges come here.
#[inline(never)]
fn rotate_into<V: Copy, const N: usize>(
    vertices: [V; 3],
    values: [[i64; N]; 3],
    inside: impl Fn(V) -> bool,
) -> Option<([V; 3], [[i64; N]; 3])> {
    let first = (1..3).find(|&k| inside(vertices[k]))?;
    let turn = |k: usize| (first + k) % 3;
    Some((
        [0, 1, 2].map(|k| vertices[turn(k)]),
        [0, 1, 2].map(|k| values[turn(k)]),
    ))
}

/// `floor(2^62 / divisor)`, for `0 < divisor < 2^31` (a doubled area under 2^15-pixel
/// deltas). On Arm, divisors below 2^16 (triangles under 32,768 pixels, the common case) take
/// [`reciprocal_small`]: no division on Cortex-M0, three hardware divides from Cortex-M3 up.
/// Larger ones shift and subtract ([`div_rem_u64`], some 800 instructions on Cortex-M0, under
/// 1% of drawing such a triangle), so that neither the ~1 KB 64-bit division routine nor
/// [`reciprocal_by_correction`] is in every mode's flash. x86-64 divides 64 bits in hardware.
/// Out of line on Arm: one copy serves every plane setup.
#[cfg_attr(target_arch = "arm", inline(never))]
#[cfg_attr(not(target_arch = "arm"), inline(always))]
fn reciprocal_2_62(divisor: u64) -> u64 {
    if crate::arch::ARM {
        match u32::try_from(divisor) {
            Ok(d @ 1..=0xFFFF) => reciprocal_small(d),
            _ => div_rem_u64(1 << 62, divisor).0,
        }
    } else {
        (1u64 << 62) / divisor.max(1)
    }
}

/// [`reciprocal_2_62`] for sub-pixel triangles, whose doubled areas in 1/65,536 pixel units
/// are mostly 2^16 or more (where the whole-pixel path's shift and subtract would be slow): on
/// Arm without the 64-bit library division either, by [`reciprocal_by_halves`] below 2^24 on
/// Cortex-M0 and by [`reciprocal_by_correction`] above. Out of line on Arm, as
/// [`reciprocal_2_62`].
#[cfg_attr(target_arch = "arm", inline(never))]
#[cfg_attr(not(target_arch = "arm"), inline(always))]
fn reciprocal_2_62_subpixel(divisor: u64) -> u64 {
    // Where 32-bit division is an instruction, areas under 2^24 (triangles under 128 pixels²,
    // most small ones) by five of them: 80 instructions less per setup on Cortex-M4F.
    let divides = crate::arch::ARM && crate::arch::DIVIDES;
    match u32::try_from(divisor) {
        Ok(d @ 1..=0xFFFF) if crate::arch::ARM => reciprocal_small(d),
        Ok(d @ 0x1_0000..=0xFF_FFFF) if divides => reciprocal_by_digits::<8>(d),
        Ok(d @ 0x1_0000..=0xFF_FFFF) if crate::arch::ARM => reciprocal_by_halves(d),
        Ok(d @ 0x1_0000..=0x7FFF_FFFF) if crate::arch::ARM => reciprocal_by_correction(d),
        _ => (1u64 << 62) / divisor.max(1),
    }
}

/// Whether `window` holds pixel `p`, as embedded-graphics' `Rectangle::contains` says, inline:
/// that one is not marked `#[inline]`, so at `opt-level = "s"` it stayed a call into the other
/// crate in every whole-pixel set-up (the sub-pixel one keeps it: there this measured 0.4 to
/// 0.75% more per nearest triangle on Cortex-M0 at `opt-level = 3`). A column right of the
/// corner is inside when its distance, which fits `u32`, is below the width; rows likewise.
#[inline(always)]
fn contains(window: &Rectangle, p: Point) -> bool {
    let corner = window.top_left;
    p.x >= corner.x
        && p.y >= corner.y
        && (p.x.wrapping_sub(corner.x) as u32) < window.size.width
        && (p.y.wrapping_sub(corner.y) as u32) < window.size.height
}

/// Sub-pixel triangles with every vertex delta below 2^`MEDIUM_BITS` units take
/// [`medium_plane`] when too large for the small setup.
const MEDIUM_BITS: u32 = 19;

/// How a sub-pixel triangle too large for the small setup sets its planes up.
enum Large {
    Medium(Medium),
    Degenerate,
    Exact,
}

/// What every plane of a sub-pixel triangle under 2^19 units across shares: the gradient
/// scaling `numerator * ±reciprocal / 2^shift`, the first vertex's whole pixel and its
/// fraction / 256 pixel right of and below it, and the deltas to the other vertices.
struct Medium {
    reciprocal: u64,
    negative: bool,
    shift: u32,
    origin: Point,
    fraction: (i64, i64),
    e: [i32; 4],
}

/// [`Medium`] for `vertices` when under 2^19 units across, with values carrying
/// `scale_bits` fraction bits beyond raw 16.16. Not generic: one copy.
#[inline(never)]
fn medium_setup(vertices: [(i32, i32); 3], scale_bits: u32) -> Large {
    let wide = vertices.map(|(x, y)| (i64::from(x), i64::from(y)));
    let Some(e) = edges_within(wide, MEDIUM_BITS) else {
        return Large::Exact;
    };
    let [ex1, ey1, ex2, ey2] = e;
    let p0 = wide[0];
    // |deltas| < 2^19: the doubled area below 2^39.
    let area = ex1 * ey2 - ex2 * ey1;
    if area == 0 {
        return Large::Degenerate;
    }
    let (reciprocal, bits) = reciprocal_normalised(area.unsigned_abs());
    Large::Medium(Medium {
        reciprocal,
        negative: area < 0,
        // Gradient per pixel in 2^-(16 + scale_bits) units: numerator * 2^(scale_bits + 8)
        // / area.
        shift: 61 + bits - scale_bits - 8,
        origin: Point::new((p0.0 >> 8) as i32, (p0.1 >> 8) as i32),
        fraction: (p0.0 & 255, p0.1 & 255),
        e: e.map(|d| d as i32),
    })
}

/// One plane of a [`Medium`] triangle, from the first vertex's value `at_vertex` (in the
/// setup's units): the value at the first vertex's whole pixel and the gradients per pixel.
///
/// The reciprocal carries 61 significant bits ([`reciprocal_normalised`]: some 700
/// instructions on Cortex-M0 where the exact setup's 128-bit divisions take some 20,000), so
/// each gradient is within one unit of 2^-SETUP plus 2^-60 of its size, and a value `D`
/// pixels from the first vertex within `D` units plus 2^-59 of the plane's change over `D`
/// along both axes. That change is at most 2^38 times the values' spread (an area of one
/// unit² over 2^19-unit deltas): the error stays below 2^-21 of the spread, 2^-5 of a level
/// for 16-bit values. Not generic: one copy for every plane count and precision.
#[inline(never)]
fn medium_plane(values: [i64; 3], at_vertex: i64, medium: &Medium) -> (i64, i64, i64) {
    let scale = |numerator: i64, extra: u32| {
        scale_by(
            numerator,
            medium.reciprocal,
            medium.negative,
            medium.shift + extra,
        )
    };
    // Values below 2^33 and deltas below 2^19: numerators below 2^53.
    let [nx, ny] = numerators_wide(values[1] - values[0], values[2] - values[0], medium.e);
    // The whole pixel lies (fx, fy) / 256 pixel up and left of the vertex: the change from
    // the numerators (below 2^62 with the fractions), not from the gradients, which wrap for
    // slivers.
    let (fx, fy) = medium.fraction;
    let offset = scale(nx * fx + ny * fy, 8);
    (at_vertex.wrapping_sub(offset), scale(nx, 0), scale(ny, 0))
}

/// `(floor(2^(61 + b) / d), b)` for a `b`-bit `d` (`0 < d < 2^63`): a reciprocal with 61
/// significant bits, in `(2^61, 2^62]`, by 63 steps of shift and subtract. Out of line, one
/// copy.
#[inline(never)]
fn reciprocal_normalised(divisor: u64) -> (u64, u32) {
    let bits = 64 - divisor.leading_zeros();
    // The dividend's bits above the quotient's 63: 2^(61 + b) >> 62.
    let mut rest = 1u64 << (bits - 1);
    // A marker bit shifted up with the quotient's bits ends the loop after 63 of them (a
    // loop LLVM does not unroll: 470 bytes less on Cortex-M0).
    let mut quotient = 1u64;
    while quotient < 1 << 63 {
        let bit = rest >= divisor;
        if bit {
            rest -= divisor;
        }
        quotient = (quotient << 1) | u64::from(bit);
        rest <<= 1;
    }
    (quotient - (1 << 63), bits)
}

/// `numerator * ±reciprocal / 2^shift` rounded half up, as wrapping `i64`, for any `shift`
/// in `1..=127`: [`scale`] for [`medium_plane`]'s varying shifts. Magnitudes
/// below 2^63 and 2^62 keep the product within 128 bits. Out of line, one copy.
#[inline(never)]
fn scale_by(numerator: i64, reciprocal: u64, negative: bool, shift: u32) -> i64 {
    let product = wide_product(numerator.unsigned_abs(), reciprocal) as i128;
    let signed = if (numerator < 0) == negative {
        product
    } else {
        -product
    };
    ((signed + (1 << (shift - 1))) >> shift) as i64
}

/// `floor(2^62 / d)` for `0 < d < 2^16` on Arm: by [`reciprocal_by_digits`] where 32-bit
/// division is an instruction; on Cortex-M0, where each division is a library call of about
/// 140 instructions (measured: three of them were 15% of a small Gouraud triangle), from
/// [`TINY_RECIPROCALS`] below 128 and by [`reciprocal_by_inverse`] above.
#[inline(always)]
fn reciprocal_small(d: u32) -> u64 {
    if crate::arch::DIVIDES {
        reciprocal_by_digits::<16>(d)
    } else if let Some(&reciprocal) = TINY_RECIPROCALS.get(d as usize) {
        reciprocal
    } else {
        reciprocal_by_inverse(d)
    }
}

/// `floor(2^62 / d)` for the doubled areas of triangles under 64 pixels (`d` below 128;
/// entry 0 unused), computed at compile time: on Cortex-M0 [`reciprocal_by_inverse`] costs
/// about 190 instructions, a ninth of a small Gouraud triangle, and meshes on small displays
/// are mostly such triangles. 1 KB of flash, only where there is no divider.
const TINY_RECIPROCALS: [u64; 128] = {
    let mut table = [0; 128];
    let mut d = 1;
    while d < 128 {
        table[d] = (1u64 << 62) / d as u64;
        d += 1;
    }
    table
};

/// [`reciprocal_by_digits`] without a division: each base-2^16 digit of the quotient is
/// estimated by a multiplication with `2^32 / d` (from [`reciprocal`]'s table and Newton
/// steps, within 2^-26 relatively), a few units off at most, and corrected by comparing with
/// `d`. Exact: the corrections leave each digit's remainder in `0..d`.
#[inline(always)]
fn reciprocal_by_inverse(d: u32) -> u64 {
    // 2^62 is the digits 0x4000, 0, 0, 0.
    divide_by_inverse([0x4000, 0, 0, 0], d)
}

/// `floor(2^62 / d)` for `2^16 <= d < 2^31` without a division: `2^63 / (d 2^shift)` from
/// [`reciprocal`] (within 2^-26), scaled to about `2^62 / d`; one correction by the exact
/// remainder `2^62 - q d` (below 2^37 in magnitude) times that reciprocal; then the last few
/// units by comparing the remainder with `d`. Out of line: one copy for every setup.
#[inline(never)]
fn reciprocal_by_correction(d: u32) -> u64 {
    let (normal, shift) = normalise(d);
    let inverse = reciprocal(normal);
    let remainder = |q: u64| (1u64 << 62).wrapping_sub(mul_low(q, d)) as i64;
    // About 2^(63 - shift) / d * 2^(shift - 1); shift is 1 to 15. Shifted in 32-bit halves: a
    // variable 64-bit shift is a library call on Cortex-M0 (`>> 1 >> (32 - shift)` is defined
    // for a zero shift too).
    let up = shift - 1;
    let mut q = (u64::from(inverse >> 1 >> (32 - shift)) << 32) | u64::from(inverse << up);
    let error = remainder(q);
    // error / d as error * inverse / 2^(63 - shift), from the error's halves: within 3.
    let magnitude = error.unsigned_abs();
    let (high, low) = ((magnitude >> 32) as u32, magnitude as u32);
    // The upper word is below 2^5: two 16-bit products on Cortex-M0, not four.
    let high_product = if crate::arch::DIVIDES {
        mul_u32(high, inverse)
    } else {
        mul_16_by_32(high & 0xFFFF, inverse)
    };
    let step = (high_product >> (31 - shift)) + (mul_u32(low, inverse) >> (63 - shift));
    q = if error < 0 { q - step } else { q + step };
    let (mut rest, d) = (remainder(q), i64::from(d));
    while rest < 0 {
        q -= 1;
        rest += d;
    }
    while rest >= d {
        q += 1;
        rest -= d;
    }
    q
}

/// `floor(2^62 / d)` for `2^16 <= d < 2^24` (small sub-pixel triangles' doubled areas)
/// without a division, as two 32-bit words whose remainders fit 32 bits: the upper word
/// `floor(2^30 / d)` and the lower `floor(r 2^32 / d)` (`r = 2^30 mod d`), each estimated
/// from [`reciprocal`] made a little smaller, so that every estimate is low, and corrected
/// upwards: the upper word by at most 1, the lower by a second estimate of its remainder's
/// quotient (below 194) in one 16-bit product, then by at most a few units. About 100
/// instructions fewer than [`reciprocal_by_correction`] on Cortex-M0 (whose remainders are
/// 64-bit): 4% of a small sub-pixel Gouraud triangle. Out of line: one copy.
#[inline(never)]
fn reciprocal_by_halves(d: u32) -> u64 {
    debug_assert!((1 << 16..1 << 24).contains(&d));
    // d << shift in [2^31, 2^32), shift in 8..=15: three steps from 8 ([`normalise`] takes
    // five from 0, the first two of which never apply here).
    let (mut normal, mut shift) = (d << 8, 8);
    for step in [4, 2, 1] {
        if normal < 1 << (32 - step) {
            normal <<= step;
            shift += step;
        }
    }
    // Within 2^-26 of 2^63 / normal = 2^(63 - shift) / d; less 2^-25 of itself, below it and
    // within 3 * 2^-26.
    let inverse = reciprocal(normal);
    let inverse = inverse - (inverse >> 25);
    // 2^30 / d = inverse 2^(shift - 33), below 2^14: the estimate at most 1 low.
    let mut high = inverse >> (33 - shift);
    let mut rest = (1u32 << 30) - high * d;
    if rest >= d {
        high += 1;
        rest -= d;
    }
    // rest 2^32 / d = rest inverse 2^(shift - 31), below 2^32: at most 3 * 2^6 + 1 low, so
    // that its remainder, below 194 d < 2^32, is the low word of -low d.
    let product = mul_u32(rest, inverse);
    let (upper, lower) = ((product >> 32) as u32, product as u32);
    let mut low = (upper << (1 + shift)) | (lower >> (31 - shift));
    let mut rest = 0u32.wrapping_sub(low.wrapping_mul(d));
    // rest / d from the top 16 bits of each (d >= 2^16: within 3 below).
    let more = ((rest >> 16) * (inverse >> 16)) >> (31 - shift);
    low += more;
    rest -= more * d;
    while rest >= d {
        low += 1;
        rest -= d;
    }
    (u64::from(high) << 32) | u64::from(low)
}

/// The low 64 bits of `q * d`: two 32-bit products.
#[inline(always)]
fn mul_low(q: u64, d: u32) -> u64 {
    let (high, low) = ((q >> 32) as u32, q as u32);
    mul_u32(low, d).wrapping_add(u64::from(high.wrapping_mul(d)) << 32)
}

/// `floor(2^62 / d)` for `0 < d < 2^(32 - DIGIT)`, by long division of 2^62 = 2^30 * 2^32:
/// 2^30 in one 32-bit divide, then `32 / DIGIT` zero digits of base 2^`DIGIT`. Each partial
/// remainder is below `d`, so each later dividend fits 32 bits: three divides in all for
/// 16-bit digits (`d` under 2^16), five for 8-bit ones (`d` under 2^24).
#[inline(always)]
fn reciprocal_by_digits<const DIGIT: u32>(d: u32) -> u64 {
    let top = 1u32 << 30;
    let mut quotient = u64::from(top / d);
    let mut remainder = top % d;
    for _ in 0..32 / DIGIT {
        let dividend = remainder << DIGIT;
        quotient = (quotient << DIGIT) | u64::from(dividend / d);
        remainder = dividend % d;
    }
    quotient
}

/// `numerator * ±reciprocal / 2^shift`, rounded half up (negative when `negative` says), as
/// wrapping `i64`: only the low 64 bits of a gradient matter. `reciprocal` is below 2^62,
/// `numerator` below 2^62 in magnitude and `shift` at least 17. One 64 x 64 -> 128-bit
/// product, a few multiply instructions on cores with a 32 x 32 -> 64-bit multiply.
#[inline(always)]
fn scale_wide(numerator: i64, reciprocal: u64, negative: bool, shift: u32) -> i64 {
    let reciprocal = signed(reciprocal, negative);
    ((i128::from(numerator) * i128::from(reciprocal) + (1 << (shift - 1))) >> shift) as i64
}

/// `reciprocal` (below 2^62) as `i64`, negated when `negative`: the factor of
/// [`scale_wide`] and [`scale_levels`].
#[inline(always)]
fn signed(reciprocal: u64, negative: bool) -> i64 {
    if negative {
        -(reciprocal as i64)
    } else {
        reciprocal as i64
    }
}

/// [`scale_wide`], bit for bit, for small cores (Cortex-M0/M0+: see [`crate::arch::DIVIDES`]),
/// where a 64-bit multiply is a library call and a 128-bit product six or seven of them.
/// Numerators that are whole multiples of 2^16 (colours and depths, whose values are integers
/// in 16.16) drop those bits and the shift with them; numerators below 2^32 then take two
/// 32 x 32 -> 64-bit products. On Cortex-M4 the branches cost more than they save (measured:
/// +40% per small Gouraud triangle), so it keeps [`scale_wide`].
#[inline(always)]
fn scale_split(numerator: i64, reciprocal: u64, negative: bool, shift: u32) -> i64 {
    // The magnitude of the product, below 2^112.
    let product = |magnitude: u64| -> i128 {
        let product = if magnitude < 1 << 32 {
            let low = widening_mul(magnitude as u32, reciprocal as u32);
            let high = widening_mul(magnitude as u32, (reciprocal >> 32) as u32);
            u128::from(low) + (u128::from(high) << 32)
        } else {
            wide_product(magnitude, reciprocal)
        };
        product as i128
    };
    let sign = |product: i128| {
        if (numerator < 0) == negative {
            product
        } else {
            -product
        }
    };
    // Two branches, so that each shift is a constant once inlined: a variable 128-bit shift
    // is long code.
    #[allow(clippy::verbose_bit_mask)] // One AND; counting zeros is a library call on M0.
    if numerator & 0xFFFF == 0 {
        let scaled = sign(product((numerator >> 16).unsigned_abs()));
        ((scaled + (1 << (shift - 17))) >> (shift - 16)) as i64
    } else {
        let scaled = sign(product(numerator.unsigned_abs()));
        ((scaled + (1 << (shift - 1))) >> shift) as i64
    }
}

/// `magnitude * reciprocal` in full for [`scale_split`]'s wide numerators (perspective planes'):
/// four 32 x 32-bit products, where a 128-bit one is several 64-bit library multiplies. Out of
/// line, so that the common setup stays small enough to inline.
#[inline(never)]
fn wide_product(magnitude: u64, reciprocal: u64) -> u128 {
    let (upper, lower) = ((magnitude >> 32) as u32, magnitude as u32);
    let (reciprocal_high, reciprocal_low) = ((reciprocal >> 32) as u32, reciprocal as u32);
    let middle = u128::from(widening_mul(lower, reciprocal_high))
        + u128::from(widening_mul(upper, reciprocal_low));
    u128::from(widening_mul(lower, reciprocal_low))
        + (middle << 32)
        + (u128::from(widening_mul(upper, reciprocal_high)) << 64)
}

/// The gradient numerators of [`numerators`] divided by 2^16, in 32-bit products, when both
/// value deltas are whole (multiples of 2^16, as colours and depths are) and below 2^15 in
/// magnitude (every colour channel; depths less than half their range apart): each product
/// is then below 2^30 in magnitude and their difference below 2^31. `None` otherwise.
#[inline(always)]
fn whole_numerators(da1: i64, da2: i64, e: [i32; 4]) -> Option<[i32; 2]> {
    // Whole and below 2^15 in magnitude: a multiple of 2^16 that fits 32 bits, but i32::MIN
    // (compared in 32-bit words: 64-bit shifts and negation are long code on Cortex-M0).
    #[allow(clippy::verbose_bit_mask)] // One AND; counting zeros is a library call on M0.
    let small = |d: i64| {
        let t = d as i32;
        i64::from(t) == d && t & 0xFFFF == 0 && t != i32::MIN
    };
    if !small(da1) || !small(da2) {
        return None;
    }
    Some(level_numerators(da1, da2, e))
}

/// [`whole_numerators`]'s numerators, untested: deltas whole and below 2^15 levels (2^31
/// raw), so that each product is below 2^30 in magnitude. (Depths, up to 2^16 levels apart,
/// take [`wide_whole_gradients`], whose differences need 64 bits.)
#[inline(always)]
fn level_numerators(da1: i64, da2: i64, e: [i32; 4]) -> [i32; 2] {
    let [ex1, ey1, ex2, ey2] = e;
    let (l1, l2) = (da1 as i32 >> 16, da2 as i32 >> 16);
    [l1 * ey2 - l2 * ey1, l2 * ex1 - l1 * ex2]
}

/// [`whole_numerators`] for values known to be whole and below `2^WHOLE_BITS` in magnitude
/// (0: nothing known): for `WHOLE_BITS` from 1 to 15, every product is below 2^30 and the
/// numerators are taken without testing, always `Some`. The set-ups' fallback for other
/// values, [`fractional_gradients`], is then never called, so colours link none of it (1.7 KB
/// of a Gouraud firmware on Cortex-M0), and the test is saved (3% of a small Gouraud triangle
/// there).
#[inline(always)]
fn whole_numerators_of<const WHOLE_BITS: u32>(da1: i64, da2: i64, e: [i32; 4]) -> Option<[i32; 2]> {
    if WHOLE_BITS == 0 || WHOLE_BITS > 15 {
        // Depths take `depth_gradients` first.
        return whole_numerators(da1, da2, e);
    }
    debug_assert!(
        whole_numerators(da1, da2, e).is_some()
            && da1.unsigned_abs() < 1 << (16 + WHOLE_BITS)
            && da2.unsigned_abs() < 1 << (16 + WHOLE_BITS),
        "{da1} {da2}"
    );
    Some(level_numerators(da1, da2, e))
}

/// The gradients `[dx, dy]` of a small triangle's depth plane (values whole and below
/// `2^DEPTH_BITS`), on cores without a 64-bit multiply: `None` elsewhere, and for other
/// values. Each numerator product is below 2^31 in magnitude (deltas below 2^16, edges below
/// 2^15), their differences below 2^32 ([`scale_whole_wide`]): depths take no test and, as
/// colours, link no [`fractional_gradients`] (which took depths more than 32,767 apart).
#[inline(always)]
fn depth_gradients<const WHOLE_BITS: u32>(
    da1: i64,
    da2: i64,
    e: [i32; 4],
    reciprocal: u64,
    negative: bool,
    shift: u32,
) -> Option<[i64; 2]> {
    if crate::arch::DIVIDES || WHOLE_BITS != DEPTH_BITS {
        return None;
    }
    Some(wide_whole_gradients(
        da1, da2, e, reciprocal, negative, shift,
    ))
}

/// [`depth_gradients`] on any core.
#[inline(always)]
fn wide_whole_gradients(
    da1: i64,
    da2: i64,
    e: [i32; 4],
    reciprocal: u64,
    negative: bool,
    shift: u32,
) -> [i64; 2] {
    debug_assert!(
        da1.trailing_zeros() >= 16
            && da2.trailing_zeros() >= 16
            && da1.unsigned_abs() < 1 << (16 + DEPTH_BITS)
            && da2.unsigned_abs() < 1 << (16 + DEPTH_BITS),
        "{da1} {da2}"
    );
    let [nx, ny] = wide_level_numerators(da1, da2, e);
    [
        scale_whole_wide(nx, reciprocal, negative, shift),
        scale_whole_wide(ny, reciprocal, negative, shift),
    ]
}

/// [`scale_split`] of the numerator `whole * 2^16`, bit for bit, in 64-bit arithmetic, for
/// shifts of 17 to 48 (every setup precision, whole-pixel and sub-pixel) and reciprocals up
/// to 2^62 (a doubled area of 1; `reciprocal_2_62`'s largest): the magnitude times
/// the reciprocal is `A * 2^32 + B` from 32 x 32 -> 64-bit products, and with `s = shift - 16`
/// (1 to 32) `floor((A * 2^32 + B + c) / 2^s)` is `A * 2^(32 - s) + floor((B + c) / 2^s)`,
/// of which only the low 64 bits matter. Rounding half up of a negative product `-P` is
/// `-floor((P + 2^(s - 1) - 1) / 2^s)`. On Cortex-M0 the 128-bit sums, negation and shift it
/// replaces cost about 100 instructions per gradient.
#[inline(always)]
fn scale_whole(whole: i32, reciprocal: u64, negative: bool, shift: u32) -> i64 {
    scale_magnitude(whole.unsigned_abs(), whole < 0, reciprocal, negative, shift)
}

/// The gradients `[dx, dy]` of whole values below `2^WHOLE_BITS` (colours: 8, depths: 16) on
/// cores with a 64-bit multiply, from 32-bit numerators and one 32 x 64-bit product each
/// ([`scale_levels`], [`scale_wide_levels`]; depths on Arm only: x86-64's 64 x 64-bit product
/// is one instruction): `None` elsewhere and for other values, which take
/// [`fractional_gradients`]. Bit for bit its gradients.
#[inline(always)]
fn level_gradients<const WHOLE_BITS: u32>(
    da1: i64,
    da2: i64,
    e: [i32; 4],
    reciprocal: u64,
    negative: bool,
    shift: u32,
) -> Option<[i64; 2]> {
    if crate::arch::DIVIDES && WHOLE_BITS >= 1 && WHOLE_BITS <= 8 {
        let [nx, ny] = level_numerators(da1, da2, e);
        Some([
            scale_levels(nx, reciprocal, negative, shift),
            scale_levels(ny, reciprocal, negative, shift),
        ])
    } else if crate::arch::DIVIDES && crate::arch::ARM && WHOLE_BITS > 8 && WHOLE_BITS <= 16 {
        let [nx, ny] = wide_level_numerators(da1, da2, e);
        Some([
            scale_wide_levels(nx, reciprocal, negative, shift),
            scale_wide_levels(ny, reciprocal, negative, shift),
        ])
    } else {
        None
    }
}

/// [`scale_wide`] of the numerator `levels * 2^16` (below 2^24 in magnitude: whole values
/// below 2^8), bit for bit: one 32 x 64-bit product, where the 64 x 64-bit one is six
/// multiplies. For cores with a 64-bit multiply.
#[inline(always)]
fn scale_levels(levels: i32, reciprocal: u64, negative: bool, shift: u32) -> i64 {
    let reciprocal = signed(reciprocal, negative);
    ((i128::from(levels) * i128::from(reciprocal) + (1 << (shift - 17))) >> (shift - 16)) as i64
}

/// The numerators of [`level_numerators`] for whole values below 2^16 (depths, on every core:
/// [`wide_whole_gradients`], [`level_gradients`]): each product below 2^31, their differences
/// below 2^32 in magnitude.
#[inline(always)]
fn wide_level_numerators(da1: i64, da2: i64, e: [i32; 4]) -> [i64; 2] {
    let [ex1, ey1, ex2, ey2] = e;
    let (l1, l2) = ((da1 >> 16) as i32, (da2 >> 16) as i32);
    let product = |a: i32, b: i32| i64::from(a * b);
    [
        product(l1, ey2) - product(l2, ey1),
        product(l2, ex1) - product(l1, ex2),
    ]
}

/// [`scale_levels`] of a numerator below 2^32 in magnitude (depths'): one 32 x 64-bit product
/// of its magnitude, then its sign. (Colours keep `scale_levels`: this one for them measured
/// 3% more per small Gouraud triangle on Cortex-M4F.)
#[inline(always)]
fn scale_wide_levels(levels: i64, reciprocal: u64, negative: bool, shift: u32) -> i64 {
    debug_assert!(levels.unsigned_abs() < 1 << 32);
    let magnitude = u64::from(levels.unsigned_abs() as u32);
    let product = (u128::from(magnitude) * u128::from(reciprocal)) as i128;
    let product = if (levels < 0) == negative {
        product
    } else {
        -product
    };
    ((product + (1 << (shift - 17))) >> (shift - 16)) as i64
}

/// [`scale_whole`] of a numerator below 2^32 in magnitude (a depth plane's, see
/// [`depth_gradients`]), bit for bit [`scale_split`]'s.
#[inline(always)]
fn scale_whole_wide(whole: i64, reciprocal: u64, negative: bool, shift: u32) -> i64 {
    debug_assert!(whole.unsigned_abs() < 1 << 32);
    let magnitude = whole.unsigned_abs() as u32;
    scale_magnitude(magnitude, whole < 0, reciprocal, negative, shift)
}

/// [`scale_whole`] of the numerator of `magnitude`, negative when `below_zero`.
#[inline(always)]
fn scale_magnitude(
    magnitude: u32,
    below_zero: bool,
    reciprocal: u64,
    negative: bool,
    shift: u32,
) -> i64 {
    let s = shift - 16;
    // `A * 2^(32 - s)` from the reciprocal's upper word (at most 2^30) shifted first: shifting
    // the 64-bit product became a 64-bit multiply, a library call on Cortex-M0. Shifted by 0
    // or 1 it fits 32 bits; further, its part above 32 bits only reaches the result's upper
    // word, through a 32-bit product (by 2, it is 2^32 itself for the reciprocal 2^62 of a
    // doubled area of 1).
    let upper = shl64(reciprocal >> 32, 32 - s);
    // On Cortex-M0 small triangles' numerators are below 2^16: two 16-bit multiplies per
    // product, not four.
    let product = |b: u32| {
        if !crate::arch::DIVIDES && magnitude < 1 << 16 {
            mul_16_by_32(magnitude, b)
        } else {
            mul_u32(magnitude, b)
        }
    };
    let high = if s > 30 {
        product(upper as u32)
    } else {
        product(upper as u32)
            .wrapping_add(u64::from(magnitude.wrapping_mul((upper >> 32) as u32)) << 32)
    };
    let low = product(reciprocal as u32);
    let below = below_zero != negative;
    let half = shl64(1, s - 1);
    let rounding = if below { half - 1 } else { half };
    // `low` is at most (2^32 - 1)^2: adding half a unit (below 2^32) cannot carry out.
    let quotient = high.wrapping_add(shr64(low + rounding, s));
    if below {
        quotient.wrapping_neg() as i64
    } else {
        quotient as i64
    }
}

/// `floor(g * f / 256)` for `0 <= f < 256`, wrapping, without a wider product: on cores
/// without a 64-bit multiply (Cortex-M0, where it is a library call of about forty
/// instructions, twelve per small sub-pixel Gouraud triangle) from 32-bit multiplies.
#[inline(always)]
fn fraction_of(g: i64, f: i64) -> i64 {
    if crate::arch::DIVIDES {
        (g >> 8).wrapping_mul(f).wrapping_add(((g & 255) * f) >> 8)
    } else {
        fraction_of_split(g, f)
    }
}

/// [`fraction_of`] from 32-bit multiplies.
#[inline(always)]
fn fraction_of_split(g: i64, f: i64) -> i64 {
    let rest = ((g & 255) as u32 * f as u32) >> 8;
    let (whole, f) = ((g >> 8) as u64, f as u32);
    let (high, low) = ((whole >> 32) as u32, whole as u32);
    let product = (u64::from(high.wrapping_mul(f)) << 32).wrapping_add(widening_mul(low, f));
    product.wrapping_add(u64::from(rest)) as i64
}

/// `numerator * ±reciprocal / 2^shift`, rounded half up: [`scale_wide`] where a 64-bit
/// multiply is an instruction, [`scale_split`] where it is not (see [`crate::arch`]).
#[inline(always)]
fn scale(numerator: i64, reciprocal: u64, negative: bool, shift: u32) -> i64 {
    if crate::arch::DIVIDES {
        scale_wide(numerator, reciprocal, negative, shift)
    } else {
        scale_split(numerator, reciprocal, negative, shift)
    }
}

/// The gradient numerators `[da1 * ey2 - da2 * ey1, da2 * ex1 - da1 * ex2]` of a plane with
/// value deltas `da1`, `da2` along edges `e = [ex1, ey1, ex2, ey2]` (each below 2^15).
///
/// On cores without a 64-bit multiply (as [`scale_split`]), value deltas below 2^32 (every
/// attribute the crate interpolates) are split into 16-bit halves, so that every product is a
/// 32-bit multiply: on Cortex-M0 a 64-bit one is a library call, twelve per Gouraud triangle.
/// Bit for bit the 64-bit result.
#[inline(always)]
fn numerators(da1: i64, da2: i64, e: [i32; 4]) -> [i64; 2] {
    // Cores with a 64-bit multiply (see `scale_wide`) keep the plain products.
    if !crate::arch::DIVIDES && da1.unsigned_abs() < 1 << 32 && da2.unsigned_abs() < 1 << 32 {
        numerators_split(da1, da2, e)
    } else {
        numerators_wide(da1, da2, e)
    }
}

/// [`numerators`] in 64-bit products. Out of line on cores without a 64-bit multiply, where
/// each product is a library call: inline, the optimiser computed these speculatively next to
/// the 32-bit ones and kept whichever the test chose (measured: four calls per depth plane).
#[cfg_attr(not(target_has_atomic = "32"), inline(never))]
#[cfg_attr(target_has_atomic = "32", inline(always))]
fn numerators_wide(da1: i64, da2: i64, e: [i32; 4]) -> [i64; 2] {
    // Not `e.map(i64::from)`: at `opt-level = "s"` that stayed a call per plane.
    let [ex1, ey1, ex2, ey2] = e;
    let (ex1, ey1, ex2, ey2) = (
        i64::from(ex1),
        i64::from(ey1),
        i64::from(ex2),
        i64::from(ey2),
    );
    [da1 * ey2 - da2 * ey1, da2 * ex1 - da1 * ex2]
}

/// [`numerators`] for value deltas below 2^32, in 32-bit multiplies.
#[inline(always)]
fn numerators_split(da1: i64, da2: i64, e: [i32; 4]) -> [i64; 2] {
    let [ex1, ey1, ex2, ey2] = e;
    let cross = |a: i64, b: i32, c: i64, d: i32| -> i64 {
        // a = high * 2^16 + low, with |high| <= 2^16 and 0 <= low < 2^16: each product below
        // 2^31 in magnitude.
        let (a_high, a_low) = ((a >> 16) as i32, (a & 0xFFFF) as i32);
        let (c_high, c_low) = ((c >> 16) as i32, (c & 0xFFFF) as i32);
        let high = i64::from(a_high * b) - i64::from(c_high * d);
        let low = i64::from(a_low * b) - i64::from(c_low * d);
        (high << 16) + low
    };
    [cross(da1, ey2, da2, ey1), cross(da2, ex1, da1, ex2)]
}

/// [`Planes`] that remember their last evaluation and reach the next one by additions when it
/// is near: the start of the next span is usually one row down and as many columns across as
/// the left edge steps, and each gradient added is cheaper than the multiplications of a
/// direct evaluation (two 64-bit multiplies per plane, library calls on Cortex-M0). A move one
/// row down adds the sum of the last such move, give or take one column: an edge steps the
/// same columns every row, or one more. The result is the direct evaluation's, bit for bit:
/// both are sums in wrapping 64-bit arithmetic.
#[derive(Clone, Debug)]
pub(crate) struct TrackedPlanes<const N: usize, const SETUP: u32 = 32> {
    /// The last point evaluated; at first the planes' origin. The planes are kept from there:
    /// the point and the values replace the origin and its values (no copy of either).
    last: Cell<(i32, i32)>,
    /// The values there, each updated in place.
    values: [Cell<i64>; N],
    /// d/dx in 2^-SETUP units per pixel ([`Planes::dx`]).
    pub(crate) dx: [i64; N],
    /// d/dy in 2^-SETUP units per pixel.
    dy: [i64; N],
    /// d/dx in 2^-16 units per pixel ([`Planes::step`]).
    pub(crate) step: [u32; N],
    /// The last move one row down, in columns: spans start where the left edge steps, which
    /// moves the same number of columns each row, or one more.
    row_move: Cell<i32>,
    /// What that move adds to each value.
    row_sum: [Cell<i64>; N],
}

impl<const N: usize, const SETUP: u32> TrackedPlanes<N, SETUP> {
    /// Furthest horizontal move along a row reached by additions; further ones multiply.
    const NEAR: i32 = 4;

    #[inline(always)]
    pub(crate) fn new(planes: Planes<N, SETUP>) -> Self {
        Self {
            last: Cell::new((planes.origin.x, planes.origin.y)),
            values: planes.base.map(Cell::new),
            dx: planes.dx,
            dy: planes.dy,
            step: planes.step,
            row_move: Cell::new(0),
            row_sum: planes.dy.map(Cell::new),
        }
    }

    /// Moves the tracked values to pixel `(x, y)`, in place, so that a span's start costs a
    /// few loads, additions and stores per value. One or two planes (the depth pass's, once
    /// per span before the painter's own move, and texture coordinates) move inline: out of
    /// line the call and its frame cost more than the move (measured: Gouraud + depth -2.0%
    /// per `small` and -2.9% per `mesh` triangle on Cortex-M4F, M0 -0.7% and -0.9%; nearest
    /// textures -2.2 to -5.2% on M4F and -0.8 to -3.9% on M0, bilinear -0.3 to -2% on M4F).
    /// Gouraud's three stay out of line: inline they cost M4F 1 to 1.8% and translucent
    /// Gouraud on M0 up to 6.8% (the span loops' registers).
    #[inline(always)]
    fn track(&self, x: i32, y: i32) {
        if N <= 2 {
            self.move_to::<N>(x, y);
        } else {
            self.move_to_out_of_line(x, y);
        }
    }

    /// [`TrackedPlanes::move_to`] out of line: once per span, and one copy serves every loop
    /// that starts spans.
    #[inline(never)]
    fn move_to_out_of_line(&self, x: i32, y: i32) {
        self.move_to::<N>(x, y);
    }

    /// See [`TrackedPlanes::track`]: the first `M` values (`M <= N`) move, the others stay.
    #[inline(always)]
    fn move_to<const M: usize>(&self, x: i32, y: i32) {
        let (last_x, last_y) = self.last.get();
        self.last.set((x, y));
        let (dx, dy) = (x.wrapping_sub(last_x), y.wrapping_sub(last_y));
        if dy == 1 {
            // One row down: the last such move's sum, give or take a column; a new move
            // multiplies once per plane.
            let sum = |k: usize| self.row_sum[k].get();
            match dx.wrapping_sub(self.row_move.get()) {
                0 => (0..M).for_each(|k| self.add(k, sum(k))),
                1 => (0..M).for_each(|k| self.add(k, sum(k).wrapping_add(self.dx[k]))),
                -1 => {
                    (0..M).for_each(|k| self.add(k, sum(k).wrapping_sub(self.dx[k])));
                }
                _ => {
                    let columns = i64::from(dx);
                    for k in 0..M {
                        let product = match i16::try_from(dx) {
                            Ok(columns) => mul_count(self.dx[k], columns),
                            Err(_) => self.dx[k].wrapping_mul(columns),
                        };
                        let sum = self.dy[k].wrapping_add(product);
                        self.row_sum[k].set(sum);
                        self.add(k, sum);
                    }
                    self.row_move.set(dx);
                }
            }
        } else if dy == 0 && (-Self::NEAR..=Self::NEAR).contains(&dx) {
            for k in 0..M {
                let step = if dx < 0 {
                    self.dx[k].wrapping_neg()
                } else {
                    self.dx[k]
                };
                for _ in 0..dx.unsigned_abs() {
                    self.add(k, step);
                }
            }
        } else {
            let columns = i64::from(x) - i64::from(last_x);
            let rows = i64::from(y) - i64::from(last_y);
            if crate::arch::DIVIDES {
                // One multiply per product: inline, as the other moves.
                (0..M).for_each(|k| self.add(k, self.product(k, columns, rows)));
            } else {
                self.move_far(M, columns, rows);
            }
        }
    }

    /// Adds `value` to value `k` (wrapping).
    #[inline(always)]
    fn add(&self, k: usize, value: i64) {
        self.values[k].set(self.values[k].get().wrapping_add(value));
    }

    /// What a move of `columns` and `rows` adds to value `k` (wrapping).
    #[inline(always)]
    fn product(&self, k: usize, columns: i64, rows: i64) -> i64 {
        self.dx[k]
            .wrapping_mul(columns)
            .wrapping_add(self.dy[k].wrapping_mul(rows))
    }

    /// [`TrackedPlanes::track`] to a point more than a row away on cores without a 64-bit
    /// multiply (Cortex-M0): a triangle's first span, and a band's triangles in every band
    /// after their first: the move of `columns` and `rows` from the last point, as
    /// [`Planes::at_exact`] would evaluate it, by [`mul_count`] where the moves fit (in
    /// `at_exact`, inline in every span loop's set-up, that measured slower). Out of line, so
    /// that the near moves keep their registers. The first `moved` values move: a count, not
    /// a constant, so that every count shares one copy per number of planes.
    #[inline(never)]
    fn move_far(&self, moved: usize, columns: i64, rows: i64) {
        match (i16::try_from(columns), i16::try_from(rows)) {
            (Ok(columns), Ok(rows)) => (0..moved.min(N)).for_each(|k| {
                let sum = mul_count(self.dx[k], columns).wrapping_add(mul_count(self.dy[k], rows));
                self.add(k, sum);
            }),
            _ => (0..moved.min(N)).for_each(|k| self.add(k, self.product(k, columns, rows))),
        }
    }

    /// The first value at pixel `(x, y)` in 2^-SETUP units, the others left behind: for
    /// planes whose first carries all a painter steps (a Gouraud triangle's packed lanes).
    /// Planes moved so are read this way only: the others fall out of step (their values and
    /// row sums stay where they were). Inline, as one plane's moves are.
    #[inline(always)]
    pub(crate) fn first_at(&self, x: i32, y: i32) -> i64 {
        self.move_to::<1>(x, y);
        self.values[0].get()
    }

    /// The first two values at pixel `(x, y)` in 2^-SETUP units, the others left behind (see
    /// [`TrackedPlanes::first_at`]): packed lanes with a depth plane carried beside them
    /// ([`TrackedPlanes::adopt`]), one move for both.
    #[inline(always)]
    pub(crate) fn first_two_at(&self, x: i32, y: i32) -> (i64, i64) {
        self.move_to::<2>(x, y);
        (self.values[0].get(), self.values[1].get())
    }

    /// The first value where the planes were last moved, in 2^-SETUP units: for a span loop
    /// whose caller has just moved them to its start ([`TrackedPlanes::first_two_at`]).
    #[inline(always)]
    pub(crate) fn first_here(&self) -> i64 {
        self.values[0].get()
    }

    /// Takes `plane` as value `k`, to move with the others: for a plane whose origin is where
    /// the planes are, with no row move kept (so as made, before any span: the values are
    /// there and each row sum is the row gradient). Returns whether it did: nothing changes
    /// otherwise.
    #[inline(always)]
    pub(crate) fn adopt(&mut self, k: usize, plane: &Planes<1, SETUP>) -> bool {
        let origin = plane.origin();
        let fresh = self.last.get() == (origin.x, origin.y) && self.row_move.get() == 0;
        if !fresh || k >= N {
            return false;
        }
        self.values[k].set(plane.base[0]);
        self.dx[k] = plane.dx[0];
        self.dy[k] = plane.dy[0];
        self.step[k] = plane.step[0];
        self.row_sum[k].set(plane.dy[0]);
        true
    }

    /// A value in 2^-SETUP units as raw 16.16, as [`TrackedPlanes::at`] gives it.
    #[inline(always)]
    pub(crate) fn to_step_units(value: i64) -> u32 {
        Planes::<1, SETUP>::to_step_units(&[value])[0]
    }

    /// All values at pixel `(x, y)` in 2^-SETUP units (bias included): [`Planes::at_exact`].
    #[inline(always)]
    pub(crate) fn at_exact(&self, x: i32, y: i32) -> [i64; N] {
        self.track(x, y);
        core::array::from_fn(|k| self.values[k].get())
    }

    /// All values at pixel `(x, y)`, raw 16.16 (bias included): [`Planes::at`].
    #[inline(always)]
    pub(crate) fn at(&self, x: i32, y: i32) -> [u32; N] {
        Planes::<N, SETUP>::to_step_units(&self.at_exact(x, y))
    }
}

/// One plane of [`Planes::new_exact`]: value at `reference` and gradients, in units of
/// 2^-(16 + `scale_bits`), by exact 128-bit arithmetic; `None` for degenerate triangles. Not
/// generic, so that every plane count and precision shares one copy of the 128-bit code.
#[inline(never)]
fn exact_plane(
    vertices: [Point; 3],
    values: [i64; 3],
    bias: i64,
    reference: Point,
    scale_bits: u32,
) -> Option<(i64, i64, i64)> {
    let [p0, p1, p2] = vertices.map(|p| (i128::from(p.x), i128::from(p.y)));
    let (ex1, ey1) = (p1.0 - p0.0, p1.1 - p0.1);
    let (ex2, ey2) = (p2.0 - p0.0, p2.1 - p0.1);
    // Deltas below 2^33, raw values below 2^34: every product below 2^100.
    let area = mul(ex1, ey2) - mul(ex2, ey1);
    if area == 0 {
        return None;
    }
    let (rx, ry) = (
        i128::from(reference.x) - p0.0,
        i128::from(reference.y) - p0.1,
    );
    let [a0, a1, a2] = values.map(i128::from);
    let (da1, da2) = (a1 - a0, a2 - a0);
    let (nx, ny) = (mul(da1, ey2) - mul(da2, ey1), mul(da2, ex1) - mul(da1, ex2));
    let dx = div_round(nx << scale_bits, area) as i64;
    let dy = div_round(ny << scale_bits, area) as i64;
    let offset = div_round((mul(nx, rx) + mul(ny, ry)) << scale_bits, area);
    let base = (((a0 + i128::from(bias)) << scale_bits) + offset) as i64;
    Some((base, dx, dy))
}

/// [`exact_plane`] for vertices in 1/256 pixel, gradients per pixel and the value at the
/// whole pixel `reference`. Vertices up to 2^31 units and values to 2^34 keep every product
/// within 128 bits; the value at a far reference is split into a quotient and a remainder of
/// the area, so that its scaling cannot overflow (only its low 64 bits are kept anyway).
#[inline(never)]
fn exact_plane_subpixel(
    vertices: [(i32, i32); 3],
    values: [i64; 3],
    bias: i64,
    reference: Point,
    scale_bits: u32,
) -> Option<(i64, i64, i64)> {
    let [p0, p1, p2] = vertices.map(|(x, y)| (i128::from(x), i128::from(y)));
    let (ex1, ey1) = (p1.0 - p0.0, p1.1 - p0.1);
    let (ex2, ey2) = (p2.0 - p0.0, p2.1 - p0.1);
    let area = mul(ex1, ey2) - mul(ex2, ey1);
    if area == 0 {
        return None;
    }
    let (rx, ry) = (
        256 * i128::from(reference.x) - p0.0,
        256 * i128::from(reference.y) - p0.1,
    );
    let [a0, a1, a2] = values.map(i128::from);
    let (da1, da2) = (a1 - a0, a2 - a0);
    let (nx, ny) = (mul(da1, ey2) - mul(da2, ey1), mul(da2, ex1) - mul(da1, ex2));
    let dx = div_round(nx << (scale_bits + 8), area) as i64;
    let dy = div_round(ny << (scale_bits + 8), area) as i64;
    let (t, a) = if area < 0 {
        (-(mul(nx, rx) + mul(ny, ry)), -area)
    } else {
        (mul(nx, rx) + mul(ny, ry), area)
    };
    let (q, r) = floor_div_rem_i128(t, a);
    let offset = (q << scale_bits).wrapping_add(div_round(r << scale_bits, a));
    let base = ((a0 + i128::from(bias)) << scale_bits).wrapping_add(offset) as i64;
    Some((base, dx, dy))
}

/// `a * b` in 128 bits (wrapping). One copy: on 32-bit cores each 128-bit product inlines a
/// dozen 32 x 32 multiplies (64-bit multiply calls on Cortex-M0), and the exact setups have
/// ten of them.
#[inline(never)]
fn mul(a: i128, b: i128) -> i128 {
    a.wrapping_mul(b)
}

/// `numerator / denominator` rounded half up, for any signs. Out of line: one copy of the
/// sign handling.
#[inline(never)]
fn div_round(numerator: i128, denominator: i128) -> i128 {
    let (n, d) = if denominator < 0 {
        (-numerator, -denominator)
    } else {
        (numerator, denominator)
    };
    // floor((2n + d) / 2d); `d` is never zero (areas are checked first).
    floor_div_rem_i128(2 * n + d, 2 * d).0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The inline window test says what embedded-graphics says, wherever that one's corner
    /// arithmetic does not overflow `i32`: random windows and points near their edges, and
    /// empty windows.
    #[test]
    fn window_test_is_embedded_graphics_one() {
        use embedded_graphics::geometry::Size;
        let mut rng = crate::test_rng::XorShift(0x77C0_11A1_5EED_0001);
        let mut next = |range: u64| (rng.next_u64() % range) as i64;
        for _ in 0..200_000 {
            let corner = Point::new(next(2001) as i32 - 1000, next(2001) as i32 - 1000);
            let size = Size::new(next(40) as u32, next(40) as u32);
            let window = Rectangle::new(corner, size);
            let p = Point::new(
                corner.x + next(50) as i32 - 5,
                corner.y + next(50) as i32 - 5,
            );
            assert_eq!(contains(&window, p), window.contains(p), "{window:?} {p:?}");
        }
        // Where embedded-graphics' corner arithmetic panics ("width is too large"): exact.
        let far = Rectangle::new(Point::new(i32::MIN, i32::MIN), Size::new(1 << 31, 1 << 31));
        assert!(contains(&far, Point::new(i32::MIN, i32::MIN)));
        assert!(contains(&far, Point::new(-1, -1)));
        assert!(!contains(&far, Point::new(0, -1)));
        assert!(!contains(&far, Point::new(-1, i32::MAX)));
    }

    /// Exact value of the plane through three (x, y, a) points at (x, y), as a rational
    /// `(numerator, positive denominator)`.
    fn exact(v: [(i64, i64); 3], a: [i64; 3], x: i64, y: i64) -> (i128, i128) {
        let v = v.map(|(x, y)| (i128::from(x), i128::from(y)));
        let (x0, y0) = v[0];
        let (ex1, ey1, ex2, ey2) = (v[1].0 - x0, v[1].1 - y0, v[2].0 - x0, v[2].1 - y0);
        let area = ex1 * ey2 - ex2 * ey1;
        let (da1, da2) = (i128::from(a[1] - a[0]), i128::from(a[2] - a[0]));
        let nx = da1 * ey2 - da2 * ey1;
        let ny = da2 * ex1 - da1 * ex2;
        let num = i128::from(a[0]) * area + nx * (i128::from(x) - x0) + ny * (i128::from(y) - y0);
        if area < 0 { (-num, -area) } else { (num, area) }
    }

    /// `got` (raw units) within one unit of `num / den`.
    fn close(got: u32, (num, den): (i128, i128)) -> bool {
        (i128::from(got as i32) * den - num).abs() <= den
    }

    #[test]
    fn small_and_exact_setups_agree_with_the_plane() {
        type Case = ([(i32, i32); 3], [i64; 3]);
        let cases: [Case; 4] = [
            ([(0, 0), (10, 0), (0, 10)], [0, 255 << 16, 100 << 16]),
            ([(3, 7), (200, 40), (50, 230)], [31 << 16, 0, 17 << 16]),
            (
                [(-5, 2), (9, -30), (14, 22)],
                [-(3 << 16), 20_000 << 16, 1 << 15],
            ),
            ([(0, 0), (30_000, 1), (1, 30_000)], [0, 30_000 << 16, 0]),
        ];
        for (v, a) in cases {
            let vertices = v.map(|(x, y)| Point::new(x, y));
            let values = a.map(|a| [a]);
            let small = Planes::<1>::new(vertices, values, 0, Point::zero(), None).unwrap();
            let exact_setup =
                Planes::<1>::new_exact(vertices, values, 0, Point::new(7, 9)).unwrap();
            let vf = v.map(|(x, y)| (i64::from(x), i64::from(y)));
            for (x, y) in [(0, 0), (5, 5), (40, 20), (100, 100), (-3, 8)] {
                let want = exact(vf, a, x, y);
                for planes in [small, exact_setup] {
                    let got = planes.at(x as i32, y as i32)[0];
                    assert!(close(got, want), "{v:?} at ({x},{y}): {got} vs {want:?}");
                }
            }
        }
    }

    /// A small triangle whose first vertex lies outside the window starts from a vertex
    /// inside: exactly its value there, and the gradients of the setup from the first vertex.
    #[test]
    fn setups_in_a_window_start_from_a_vertex_inside() {
        let window = Rectangle::new(
            Point::new(0, 0),
            embedded_graphics::geometry::Size::new(100, 80),
        );
        let values = [
            [5 << 16, -(7 << 16)],
            [200 << 16, 3 << 16],
            [-(40 << 16), 1 << 20],
        ];
        let triangles = [
            [(-20, 10), (50, 30), (10, 70)],
            [(30, -5), (120, 40), (60, 60)],
            [(150, 10), (110, 90), (20, 40)],
            [(-30_000, 5), (10, 7), (-5, 70)],
        ];
        for v in triangles {
            let vertices = v.map(|(x, y)| Point::new(x, y));
            let inside = (0..3).find(|&k| window.contains(vertices[k])).unwrap();
            assert_ne!(inside, 0, "{v:?}");
            let from_first =
                Planes::<2, 46>::new(vertices, values, 3, Point::zero(), None).unwrap();
            let planes = Planes::<2, 46>::new_in(vertices, values, 3, &window, None).unwrap();
            let reference = vertices[inside];
            let at = planes.at_exact(reference.x, reference.y);
            for k in 0..2 {
                assert_eq!(at[k], (values[inside][k] + 3) << 30, "{v:?}");
                assert_eq!(planes.dx[k], from_first.dx[k], "{v:?}");
                assert_eq!(planes.dy[k], from_first.dy[k], "{v:?}");
            }
            // The same in 1/256 pixel, a fraction off each whole pixel: the plane at the
            // vertex inside within a few units of 2^-46, the gradients those from the first
            // vertex.
            let raw = v.map(|(x, y)| (x * 256 + 37, y * 256 + 201));
            let from_first =
                Planes::<2, 46>::new_subpixel(raw, values, 3, Point::zero(), None).unwrap();
            let planes = Planes::<2, 46>::new_subpixel_in(raw, values, 3, &window, None).unwrap();
            let at = planes.at_exact(reference.x, reference.y);
            // The vertex's pixel is 37/256 left of it and 201/256 up.
            for k in 0..2 {
                let exact = i128::from((values[inside][k] + 3) << 30)
                    - (i128::from(from_first.dx[k]) * 37 + i128::from(from_first.dy[k]) * 201)
                        / 256;
                assert!(
                    (i128::from(at[k]) - exact).abs() <= 16,
                    "{v:?}: {} {exact}",
                    at[k]
                );
                assert_eq!(planes.dx[k], from_first.dx[k], "{v:?}");
                assert_eq!(planes.dy[k], from_first.dy[k], "{v:?}");
            }
        }
    }

    /// Sub-pixel triangles up to 2^19 units across, slivers included: the medium setup's
    /// values at pixels over the triangle within one raw unit (plus the documented 2^-21 of
    /// the values' spread) of the exact plane, for both precisions; the gradients within a
    /// unit of the exact setup's.
    #[test]
    fn medium_subpixel_setups_agree_with_the_plane() {
        let mut rng = crate::test_rng::XorShift(0x5EED_0019);
        let mut range = |lo: i64, hi: i64| lo + (rng.next_u64() % (hi - lo + 1) as u64) as i64;
        let mut medium = 0;
        for case in 0..3000 {
            let reach = [1 << 16, 1 << 18, (1 << 19) - 1][case % 3];
            let mut points = [(0i64, 0i64); 3];
            for p in &mut points {
                *p = (range(-reach / 2, reach / 2), range(-reach / 2, reach / 2));
            }
            if case % 4 == 0 {
                // A sliver: the third vertex levels few units off the line through the others.
                let along = range(0, 256);
                points[2] = (
                    points[0].0 + (points[1].0 - points[0].0) * along / 256 + range(-3, 3),
                    points[0].1 + (points[1].1 - points[0].1) * along / 256 + range(-3, 3),
                );
            }
            let deltas = [
                points[1].0 - points[0].0,
                points[1].1 - points[0].1,
                points[2].0 - points[0].0,
                points[2].1 - points[0].1,
            ];
            let within = |bits: u32| deltas.iter().all(|d| d.unsigned_abs() < 1 << bits);
            if within(15) || !within(MEDIUM_BITS) {
                continue;
            }
            let area = deltas[0] * deltas[3] - deltas[2] * deltas[1];
            if area == 0 {
                continue;
            }
            medium += 1;
            let spread = range(0, 0xFFFF_FFFF);
            let levels = [0, 0, 0].map(|_| range(-spread / 2, spread / 2));
            let raw = points.map(|(x, y)| (x as i32, y as i32));
            let values = levels.map(|levels| [levels, -levels]);
            let planes16 =
                Planes::<2, 32>::new_subpixel(raw, values, 0, Point::zero(), None).unwrap();
            let planes46 =
                Planes::<2, 46>::new_subpixel(raw, values, 0, Point::zero(), None).unwrap();
            let exact16 = |k: usize| {
                let values = [values[0][k], values[1][k], values[2][k]];
                exact_plane_subpixel(raw, values, 0, Point::zero(), 16).unwrap()
            };
            // Within levels unit plus 2^-60 of the gradient (the exact ones wrap as these do).
            let near = |got: i64, want: i64| {
                got.wrapping_sub(want).unsigned_abs() <= 1 + (want.unsigned_abs() >> 60)
            };
            for k in 0..2 {
                let (_, dx, dy) = exact16(k);
                assert!(near(planes16.dx[k], dx), "{points:?} {levels:?}");
                assert!(near(planes16.dy[k], dy), "{points:?} {levels:?}");
            }
            let tolerance = 1 + i128::from(spread >> 21);
            for _ in 0..8 {
                // A pixel near the triangle: levels vertex's, or between two vertices.
                let (i, j) = (range(0, 2) as usize, range(0, 2) as usize);
                let along = range(0, 16);
                let x = (points[i].0 + (points[j].0 - points[i].0) * along / 16) >> 8;
                let y = (points[i].1 + (points[j].1 - points[i].1) * along / 16) >> 8;
                let (num, den) = exact(points, levels, x * 256, y * 256);
                // Only values inside the vertices' range must fit (pixels whose square the
                // triangle crosses may lie outside it, where levels sliver's plane runs off).
                let (low, high) = (levels.iter().min().unwrap(), levels.iter().max().unwrap());
                if num < i128::from(*low) * den || num > i128::from(*high) * den {
                    continue;
                }
                let got16 = i128::from(planes16.at(x as i32, y as i32)[0] as i32);
                assert!(
                    (got16 * den - num).abs() <= tolerance * den,
                    "{points:?} {levels:?} at ({x}, {y}): {got16} vs {}",
                    num / den
                );
                let got46 = planes46.at_exact(x as i32, y as i32)[0] >> 30;
                assert!(
                    (i128::from(got46 as i32) * den - num).abs() <= (tolerance + 1) * den,
                    "{points:?} {levels:?} at ({x}, {y}): {got46} vs {}",
                    num / den
                );
            }
        }
        assert!(medium > 1000, "{medium}");
    }

    #[test]
    fn normalised_reciprocals_are_the_128_bit_division() {
        let mut rng = crate::test_rng::XorShift(0x0123_4567_89AB_CDEF);
        let check = |d: u64| {
            let bits = 64 - d.leading_zeros();
            let want = ((1u128 << (61 + bits)) / u128::from(d)) as u64;
            assert_eq!(reciprocal_normalised(d), (want, bits), "{d}");
        };
        for d in 1..5000 {
            check(d);
        }
        for shift in 1..63 {
            for d in [(1u64 << shift) - 1, 1 << shift, (1 << shift) + 1] {
                check(d);
            }
        }
        for _ in 0..20_000 {
            let d = rng.next_u64() >> (rng.next_u64() % 63);
            check(d.max(1) >> 1 | 1);
        }
    }

    #[test]
    fn variable_scaling_is_the_128_bit_product() {
        let mut rng = crate::test_rng::XorShift(0xFEED_BEEF_0000_0001);
        for _ in 0..20_000 {
            let n = (rng.next_u64() >> (rng.next_u64() % 53 + 11)) as i64;
            let n = if rng.next_u64() & 1 == 0 { n } else { -n };
            let r = (rng.next_u64() >> 2).max(1);
            let negative = rng.next_u64() & 1 == 0;
            let shift = 1 + (rng.next_u64() % 127) as u32;
            let signed = if negative {
                -i128::from(r)
            } else {
                i128::from(r)
            };
            let want = (i128::from(n) * signed + (1i128 << (shift - 1))) >> shift;
            assert_eq!(
                scale_by(n, r, negative, shift),
                want as i64,
                "{n} {r} {shift}"
            );
        }
    }

    #[test]
    fn huge_triangles_evaluate_exactly_at_the_reference() {
        let vertices = [
            Point::new(i32::MIN, i32::MIN),
            Point::new(i32::MAX, 0),
            Point::new(0, i32::MAX),
        ];
        let values = [[0], [200 << 16], [100 << 16]];
        let planes = Planes::<1>::new(vertices, values, 0, Point::new(10, 10), None).unwrap();
        let v = vertices.map(|p| (i64::from(p.x), i64::from(p.y)));
        for (x, y) in [(10, 10), (11, 10), (300, 200)] {
            let want = exact(v, [0, 200 << 16, 100 << 16], x, y);
            let got = planes.at(x as i32, y as i32)[0];
            assert!(close(got, want), "({x},{y}): {got} vs {want:?}");
        }
    }

    #[test]
    fn tracked_evaluation_is_the_direct_one() {
        let v = [Point::new(-3, 2), Point::new(40, 9), Point::new(7, 31)];
        let values = [
            [0x12_3456, -0x7_0000],
            [0xFF_0000, 0x2_8000],
            [-0x40_0000, 0x33_3333],
        ];
        let planes = Planes::<2>::new(v, values, 1 << 15, Point::new(-5, -5), None).unwrap();
        let tracked = TrackedPlanes::new(planes);
        // Next rows a few pixels across, same row, far jumps, back up, repeats.
        let path = [
            (0, 0),
            (1, 1),
            (-1, 2),
            (3, 3),
            (3, 3),
            (7, 3),
            (2, 4),
            (40, 5),
            (-9, 6),
            (-4, 7),
            (0, 2),
            (0, 3),
            (4, 4),
            (0, 5),
            (-4, 6),
            (20, 30),
            (21, 31),
        ];
        for (x, y) in path {
            assert_eq!(
                tracked.at_exact(x, y),
                planes.at_exact(x, y),
                "at ({x}, {y})"
            );
            assert_eq!(tracked.at(x, y), planes.at(x, y));
        }
    }

    #[test]
    fn tracked_evaluation_follows_any_path() {
        let v = [
            Point::new(-30, 12),
            Point::new(400, 90),
            Point::new(70, 310),
        ];
        let values = [
            [0x12_3456, -0x7_0000, 3],
            [-0xFF_0000, 0x2_8000, 1 << 30],
            [0x40_0000, 0x33_3333, -5],
        ];
        let planes = Planes::<3>::new(v, values, 0, Point::new(0, 0), None).unwrap();
        let tracked = TrackedPlanes::new(planes);
        // Rows down with edge-like steps (the same columns each row, or one more), other moves
        // down, restarts, jumps anywhere (a linear congruential walk).
        let (mut x, mut y, mut seed, mut slope) = (0i32, 0i32, 12345u64, 0i32);
        for _ in 0..20_000 {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let r = (seed >> 33) as i32;
            match r & 7 {
                0 => (x, y, slope) = (r >> 3, r >> 12, (r >> 20) % 40),
                1 => x = x.wrapping_add(r >> 8),
                2..=4 => {
                    x = x.wrapping_add(slope + ((r >> 4) & 1));
                    y = y.wrapping_add(1);
                }
                _ => {
                    x = x.wrapping_add((r >> 3) % 9 - 4 + (r & 16));
                    y = y.wrapping_add(1);
                }
            }
            assert_eq!(
                tracked.at_exact(x, y),
                planes.at_exact(x, y),
                "at ({x}, {y})"
            );
        }
    }

    #[test]
    fn scaling_is_the_128_bit_product() {
        let numerators = [
            0i64,
            1,
            -1,
            3 << 16,
            -(255 << 16) * 40_000,
            0xFFFF_FFFF,
            -0xFFFF_FFFF,
            1 << 32,
            (1 << 49) - 1,
            -(1 << 49) + 12_345,
            0x1_2345_0000,
            -0x7FFF_0000,
        ];
        let reciprocals = [
            1u64,
            3,
            (1 << 62) / 7,
            (1 << 62) / 65_535,
            1 << 61,
            (1 << 62) / ((1 << 31) - 1),
        ];
        for &n in &numerators {
            for &r in &reciprocals {
                for negative in [false, true] {
                    for shift in [17, 30, 32, 46] {
                        let signed = if negative {
                            -i128::from(r)
                        } else {
                            i128::from(r)
                        };
                        let want = ((i128::from(n) * signed + (1 << (shift - 1))) >> shift) as i64;
                        assert_eq!(
                            scale(n, r, negative, shift),
                            want,
                            "{n} {r} {negative} {shift}"
                        );
                    }
                }
            }
        }
    }

    /// The memo gives what the reciprocal gives: computed on a miss (another divisor, or the
    /// same divisor of the other kind), kept and reused on a hit.
    #[test]
    fn the_area_memo_is_the_reciprocal() {
        let calls = Cell::new(0);
        let memo = AreaMemo::new();
        let through = |d: u64, subpixel: bool| {
            let f: fn(u64) -> u64 = if subpixel {
                reciprocal_2_62_subpixel
            } else {
                reciprocal_2_62
            };
            let before = memo.key.get();
            let got = memo.get(d, subpixel, f);
            calls.set(calls.get() + u32::from(before != memo.key.get()));
            assert_eq!(got, (1u64 << 62) / d, "{d}");
        };
        for (d, subpixel) in [
            (14, false),
            (14, false),
            (15, false),
            (14, false),
            (14, true),
            (14, false),
        ] {
            through(d, subpixel);
        }
        // Computed for the first, the third, the fourth, the fifth and the last.
        assert_eq!(calls.get(), 5);
        assert_eq!(memo.key.get(), 14);
    }

    #[test]
    fn reciprocals_by_halves_are_the_64_bit_division_for_every_divisor() {
        for d in 1u32 << 16..1 << 24 {
            assert_eq!(reciprocal_by_halves(d), (1u64 << 62) / u64::from(d), "{d}");
        }
    }

    #[test]
    fn reciprocals_are_the_64_bit_division() {
        let check = |d: u64| {
            assert_eq!(reciprocal_2_62(d), (1u64 << 62) / d, "{d}");
            assert_eq!(reciprocal_2_62_subpixel(d), (1u64 << 62) / d, "{d}");
            // The shift and subtract Arm takes for divisors of 2^16 and more.
            assert_eq!(div_rem_u64(1 << 62, d).0, (1u64 << 62) / d, "{d}");
            if let Ok(wide @ 0x1_0000..=0x7FFF_FFFF) = u32::try_from(d) {
                assert_eq!(reciprocal_by_correction(wide), (1u64 << 62) / d, "{d}");
            }
            if let Ok(medium @ 0x1_0000..=0xFF_FFFF) = u32::try_from(d) {
                assert_eq!(reciprocal_by_digits::<8>(medium), (1u64 << 62) / d, "{d}");
                assert_eq!(reciprocal_by_halves(medium), (1u64 << 62) / d, "{d}");
            }
            if let Ok(small @ 1..=0xFFFF) = u32::try_from(d) {
                assert_eq!(reciprocal_by_digits::<16>(small), (1u64 << 62) / d, "{d}");
                assert_eq!(reciprocal_by_digits::<8>(small), (1u64 << 62) / d, "{d}");
                assert_eq!(reciprocal_by_inverse(small), (1u64 << 62) / d, "{d}");
            }
            // Cortex-M0's table, against the division done another way.
            if let Some(&tabled) = TINY_RECIPROCALS.get(d as usize) {
                assert_eq!(tabled, reciprocal_by_inverse(d as u32), "{d}");
            }
        };
        for d in 1..=70_000 {
            check(d);
        }
        let mut rng = crate::test_rng::XorShift(0x9E37_79B9_7F4A_7C15);
        for _ in 0..100_000 {
            check(1 + rng.next_u64() % ((1 << 31) - 1));
        }
        for d in [
            (1 << 16) - 1,
            1 << 16,
            (1 << 31) - 1,
            1 << 30,
            (1 << 30) + 1,
            3 << 29,
        ] {
            check(d);
        }
        for shift in 0..31 {
            for d in [(1u64 << shift) - 1, 1 << shift, (1 << shift) + 1] {
                if (1..1 << 31).contains(&d) {
                    check(d);
                }
            }
        }
    }

    #[test]
    fn fractions_of_gradients_are_the_wide_product() {
        let mut rng = crate::test_rng::XorShift(0xF4AC_7100_0000_0256);
        for k in 0..50_000 {
            let g = match k % 4 {
                0 => rng.next_u64() as i64,
                1 => (rng.next_u64() as i64) >> 20,
                2 => -((rng.next_u64() >> 30) as i64),
                _ => [0, 1, -1, 255, -256, i64::MAX, i64::MIN][k % 7],
            };
            let f = (rng.next_u64() % 256) as i64;
            let want = ((i128::from(g) * i128::from(f)) >> 8) as i64;
            assert_eq!(fraction_of(g, f), want, "{g} {f}");
            assert_eq!(fraction_of_split(g, f), want, "{g} {f}");
        }
    }

    #[test]
    fn widening_products_are_exact() {
        let values = [
            0u32,
            1,
            0xFFFF,
            0x1_0000,
            0x1234_5678,
            0x8000_0000,
            0xFFFF_FFFE,
            u32::MAX,
        ];
        for a in values {
            for b in values {
                assert_eq!(widening_mul(a, b), u64::from(a) * u64::from(b), "{a} x {b}");
            }
        }
    }

    #[test]
    fn split_scaling_is_the_128_bit_one() {
        // Numerators below 2^62 in magnitude (multiples of 2^16 and not), reciprocals below
        // 2^62, shifts of every setup precision.
        let mut rng = crate::test_rng::XorShift(0x2545_F491_4F6C_DD1D);
        let mut next = || rng.next_u64();
        for _ in 0..200_000 {
            let bits = next() % 62;
            let mut numerator = (next() >> (64 - bits).min(63)) as i64;
            if next() & 1 == 0 {
                numerator &= !0xFFFF;
            }
            if next() & 1 == 0 {
                numerator = -numerator;
            }
            let reciprocal = next() >> (2 + next() % 40);
            let negative = next() & 1 == 0;
            for shift in [17, 24, 32, 38, 46] {
                assert_eq!(
                    scale_split(numerator, reciprocal, negative, shift),
                    scale_wide(numerator, reciprocal, negative, shift),
                    "{numerator} {reciprocal} {negative} {shift}"
                );
            }
        }
        // Words at their largest, where the low product plus the rounding carries into the
        // middle word, and exact halves.
        let words = [
            (1 << 32) - 1,
            1 << 62,
            (1 << 62) - 1,
            (1 << 48) + (1 << 32) - 1,
            ((1 << 30) - 1) << 32,
            1 << 45,
            3 << 31,
        ];
        for &m in &words {
            for &r in &words {
                for numerator in [m as i64, -(m as i64), (m as i64) & !0xFFFF] {
                    for negative in [false, true] {
                        for shift in [17, 24, 31, 32, 33, 38, 46, 48] {
                            assert_eq!(
                                scale_split(numerator, r, negative, shift),
                                scale_wide(numerator, r, negative, shift),
                                "{numerator} {r} {negative} {shift}"
                            );
                        }
                    }
                }
            }
        }
    }

    /// Runs `check` over the scaling tests' cases: whole numerators (one of `edges` every fourth
    /// round, else random below `2^bits` in magnitude), reciprocals (one of `reciprocals` every
    /// third round, else random below 2^62), both signs, and shifts of every setup precision
    /// (46 and 32 are SETUP 32 and 46 for whole-pixel vertices, 38 and 24 for sub-pixel ones).
    fn for_each_scaling_case(
        seed: u64,
        edges: &[i64],
        reciprocals: &[u64],
        bits: u64,
        mut check: impl FnMut(i64, u64, bool, u32),
    ) {
        let mut rng = crate::test_rng::XorShift(seed);
        let mut next = || rng.next_u64();
        for round in 0..200_000 {
            let whole = match round % 4 {
                0 => edges[(next() % edges.len() as u64) as usize],
                _ => {
                    (next() >> (64 - bits + next() % bits)) as i64
                        * if next() & 1 == 0 { 1 } else { -1 }
                }
            };
            let reciprocal = match round % 3 {
                0 => reciprocals[(next() % reciprocals.len() as u64) as usize],
                _ => next() >> (2 + next() % 40),
            };
            let negative = next() & 1 == 0;
            for shift in [17, 24, 30, 32, 38, 45, 46, 47, 48] {
                check(whole, reciprocal, negative, shift);
            }
        }
    }

    #[test]
    fn whole_scaling_is_the_128_bit_one() {
        // Whole numerators (as `whole_numerators` gives: below 2^31 in magnitude), reciprocals
        // up to 2^62.
        let edges = [0, 1, -1, i32::MAX, -i32::MAX, 255 * 32767, -255 * 32767].map(i64::from);
        // Products exactly half a unit above a multiple (2^0 to 2^31 times an odd whole)
        // tell rounding half up of negative products from rounding away.
        let reciprocals = [
            0,
            1,
            (1 << 32) - 1,
            1 << 32,
            1 << 62,
            (1 << 62) - 1,
            1 << 61,
            1 << 7,
            1 << 15,
            1 << 21,
            1 << 29,
            1 << 30,
            1 << 31,
            (5 << 40) + (1 << 29),
            (7 << 50) + (1 << 15),
        ];
        for_each_scaling_case(
            0x9E37_79B9_7F4A_7C15,
            &edges,
            &reciprocals,
            31,
            |whole, reciprocal, negative, shift| {
                let expected = scale_wide(whole << 16, reciprocal, negative, shift);
                let whole = whole as i32; // below 2^31 in magnitude
                assert_eq!(
                    scale_whole(whole, reciprocal, negative, shift),
                    expected,
                    "{whole} {reciprocal} {negative} {shift}"
                );
                assert_eq!(
                    scale_levels(whole, reciprocal, negative, shift),
                    expected,
                    "levels: {whole} {reciprocal} {negative} {shift}"
                );
            },
        );
    }

    #[test]
    fn wide_whole_scaling_is_the_128_bit_one() {
        // Numerators of depth planes: whole, below 2^32 in magnitude, whose low products
        // reach (2^32 - 1)^2.
        let edges = [
            0i64,
            1,
            -1,
            (1 << 32) - 1,
            -(1 << 32) + 1,
            1 << 31,
            -(1 << 31),
        ];
        let reciprocals = [
            0,
            1,
            (1 << 32) - 1,
            1 << 32,
            1 << 62,
            (1 << 62) - 1,
            1 << 61,
        ];
        for_each_scaling_case(
            0x6A09_E667_F3BC_C908,
            &edges,
            &reciprocals,
            32,
            |whole, reciprocal, negative, shift| {
                let expected = scale_wide(whole << 16, reciprocal, negative, shift);
                assert_eq!(
                    scale_whole_wide(whole, reciprocal, negative, shift),
                    expected,
                    "{whole} {reciprocal} {negative} {shift}"
                );
                assert_eq!(
                    scale_wide_levels(whole, reciprocal, negative, shift),
                    expected,
                    "levels: {whole} {reciprocal} {negative} {shift}"
                );
            },
        );
    }

    #[test]
    fn depth_gradients_are_the_fractional_ones() {
        // Depth deltas over the whole u16 range, edges of small set-ups (whole-pixel and
        // sub-pixel), each area's own reciprocal.
        let mut rng = crate::test_rng::XorShift(0xBB67_AE85_84CA_A73B);
        let mut next = || rng.next_u64();
        let deltas = [0i64, 1, -1, 0x7FFF, 0x8000, -0x8000, 0xFFFF, -0xFFFF];
        let sides = [1i32, -1, 2, (1 << 15) - 1, -(1 << 15) + 1, 1 << 14, 300];
        let mut pick = |n: usize| (next() % n as u64) as usize;
        for round in 0..100_000 {
            let delta = |k: usize| match round % 2 {
                0 => deltas[k],
                _ => (k as i64 * 7919 + round) % 0x1_0000 - 0x8000,
            };
            let (da1, da2) = (
                delta(pick(deltas.len())) << 16,
                delta(pick(deltas.len())) << 16,
            );
            let mut side = || match pick(3) {
                0 => sides[pick(sides.len())],
                _ => (pick((1 << 15) - 1) as i32 - (1 << 14)) * 2 + 1,
            };
            let e = [side(), side(), side(), side()];
            let area = i64::from(e[0]) * i64::from(e[3]) - i64::from(e[2]) * i64::from(e[1]);
            if area == 0 || area.unsigned_abs() >= 1 << 31 {
                continue;
            }
            let reciprocal = (1u64 << 62) / area.unsigned_abs();
            let negative = area < 0;
            assert_eq!(
                wide_whole_gradients(da1, da2, e, reciprocal, negative, 46),
                fractional_gradients::<32, 0>(da1, da2, e, reciprocal, negative),
                "{da1} {da2} {e:?}"
            );
            assert_eq!(
                wide_whole_gradients(da1, da2, e, reciprocal, negative, 38),
                fractional_gradients::<32, 8>(da1, da2, e, reciprocal, negative),
                "{da1} {da2} {e:?}"
            );
            // Cores with a 64-bit multiply.
            let [nx, ny] = wide_level_numerators(da1, da2, e);
            for (shift, expected) in [
                (
                    46,
                    fractional_gradients::<32, 0>(da1, da2, e, reciprocal, negative),
                ),
                (
                    38,
                    fractional_gradients::<32, 8>(da1, da2, e, reciprocal, negative),
                ),
            ] {
                assert_eq!(
                    [nx, ny].map(|n| scale_wide_levels(n, reciprocal, negative, shift)),
                    expected,
                    "levels: {da1} {da2} {e:?}"
                );
            }
        }
    }

    #[test]
    fn whole_numerators_are_the_64_bit_ones_shifted() {
        let whole = [0i64, 1, -1, 255, -255, 0x7FFF, -0x7FFF];
        let other = [0x8000i64 << 16, -0x8000 << 16, 1, 0xFFFF, 1 << 40];
        let sides = [0i32, 1, -1, 7, -300, (1 << 15) - 1, -(1 << 15) + 1];
        for e in [
            [sides[5], sides[6], sides[3], sides[4]],
            [sides[1], sides[0], sides[2], sides[5]],
            [sides[6], sides[6], sides[5], sides[5]],
            [sides[5], sides[5], sides[6], sides[6]],
        ] {
            for &l1 in &whole {
                for &l2 in &whole {
                    let (da1, da2) = (l1 << 16, l2 << 16);
                    let want = numerators_wide(da1, da2, e).map(|n| n >> 16);
                    let got = whole_numerators(da1, da2, e).map(|n| n.map(i64::from));
                    assert_eq!(got, Some(want), "{l1} {l2} {e:?}");
                }
                for &d in &other {
                    assert_eq!(whole_numerators(l1 << 16, d, e), None, "{l1} {d}");
                    assert_eq!(whole_numerators(d, l1 << 16, e), None, "{d} {l1}");
                }
            }
        }
    }

    #[test]
    fn known_whole_numerators_are_the_tested_ones() {
        // Every pair of colour-channel deltas (as raw 16.16) along edges at the ends of the
        // small set-up's range: the untested numerators are the tested ones.
        let sides = [0i32, 1, -1, 7, -300, (1 << 15) - 1, -(1 << 15) + 1];
        for e in [
            [sides[5], sides[6], sides[3], sides[4]],
            [sides[1], sides[0], sides[2], sides[5]],
            [sides[6], sides[6], sides[5], sides[5]],
            [sides[5], sides[5], sides[6], sides[6]],
        ] {
            for l1 in -255i64..=255 {
                for l2 in [-255i64, -128, -1, 0, 1, 77, 255] {
                    let (da1, da2) = (l1 << 16, l2 << 16);
                    let want = whole_numerators(da1, da2, e);
                    assert!(want.is_some());
                    assert_eq!(whole_numerators_of::<CHANNEL_BITS>(da1, da2, e), want);
                    assert_eq!(whole_numerators_of::<0>(da1, da2, e), want);
                }
            }
        }
        // Nothing known: values that are not whole are not taken.
        assert_eq!(whole_numerators_of::<0>(1, 0, [1, 0, 0, 1]), None);
    }

    #[test]
    fn split_numerators_are_the_64_bit_ones() {
        let deltas = [
            0i64,
            1,
            -1,
            0xFFFF,
            0x1_0000,
            -0x1_0000,
            255 << 16,
            -(255 << 16),
            (1 << 32) - 1,
            -(1 << 32) + 1,
            1 << 32,
            -(1 << 33),
            0x1234_5678,
            -0x7654_3210,
        ];
        let sides = [0i32, 1, -1, 7, -300, (1 << 15) - 1, -(1 << 15) + 1];
        for &da1 in &deltas {
            for &da2 in &deltas {
                for e in [
                    [sides[5], sides[6], sides[3], sides[4]],
                    [sides[1], sides[0], sides[2], sides[5]],
                    [sides[6], sides[6], sides[5], sides[5]],
                ] {
                    let [ex1, ey1, ex2, ey2] = e.map(i64::from);
                    let want = [da1 * ey2 - da2 * ey1, da2 * ex1 - da1 * ex2];
                    assert_eq!(numerators(da1, da2, e), want, "{da1} {da2} {e:?}");
                    if da1.unsigned_abs() < 1 << 32 && da2.unsigned_abs() < 1 << 32 {
                        assert_eq!(numerators_split(da1, da2, e), want, "{da1} {da2} {e:?}");
                    }
                }
            }
        }
    }

    /// Planes stored to words and loaded back are the same planes, steps included; too few
    /// words store and load nothing.
    #[test]
    fn stored_planes_load_back() {
        let mut rng = crate::test_rng::XorShift(0x0DDC_0FFE_E15B_AD5E);
        for _ in 0..2_000 {
            let mut coordinate = || (rng.next_u64() % 4001) as i32 - 2000;
            let vertices = [(); 3].map(|()| Point::new(coordinate(), coordinate()));
            let values = [(); 3].map(|()| [(); 3].map(|()| (rng.next_u64() >> 20) as i64));
            let reference = Point::new(-7, 11);
            let Some(planes) = Planes::<3, 32>::new(vertices, values, 1 << 15, reference, None)
            else {
                continue;
            };
            let words: [Cell<i64>; 10] = Default::default();
            planes.store(&words);
            let loaded = Planes::<3, 32>::load(&words).unwrap();
            assert_eq!(loaded.origin, planes.origin);
            assert_eq!(
                (loaded.base, loaded.dx, loaded.dy, loaded.step),
                (planes.base, planes.dx, planes.dy, planes.step)
            );
            assert!(Planes::<3, 32>::load(&words[..9]).is_none());
            let short: [Cell<i64>; 9] = Default::default();
            planes.store(&short);
            assert!(short.iter().all(|w| w.get() == 0));
        }
    }

    #[test]
    fn degenerate_is_none() {
        let v = [Point::new(0, 0), Point::new(5, 5), Point::new(10, 10)];
        assert!(Planes::<2>::new(v, [[0, 0], [1, 1], [2, 2]], 0, Point::zero(), None).is_none());
        let far = [
            Point::new(0, 0),
            Point::new(1 << 20, 1 << 20),
            Point::new(1 << 21, 1 << 21),
        ];
        assert!(Planes::<1>::new(far, [[0], [1], [2]], 0, Point::zero(), None).is_none());
    }
}
