//! The depth-tested span pass: spans are tested and written first, then their passing runs
//! painted.

use embedded_graphics::{draw_target::DrawTarget, geometry::Point, primitives::Rectangle};

use super::{DepthBuffer, DepthTest};
use crate::{
    coverage::{FillRule, Span, SpanSink},
    geometry::Shape,
    interpolate::{AreaMemo, DEPTH_BITS, TrackedPlanes},
    shading::paint::{PaintVisitor, Painter},
};

/// Receives a style's painter and walks the triangle through the depth test.
pub(super) struct DepthVisitor<'a, 'b, G, D> {
    pub(super) target: &'a mut D,
    pub(super) buffer: &'a mut DepthBuffer<'b>,
    pub(super) triangle: &'a G,
    pub(super) depths: [u16; 3],
    pub(super) rule: FillRule,
    /// Where spans are drawn (the target's box, which the buffer covers), in screen
    /// coordinates.
    pub(super) window: Rectangle,
    /// What interpolation is set up for (the whole screen when drawing a band of it).
    pub(super) setup: Rectangle,
    pub(super) test: DepthTest,
    pub(super) write: bool,
    /// The target's pixel `(x, y)` is the screen's `(x, y) + offset`.
    pub(super) offset: Point,
    /// The area's reciprocal from the style's set-up, for the depth plane's. Borrowed: the
    /// visitor moves by value, and with the memo's 64-bit words inside it was copied by
    /// `memcpy` (80 instructions per small triangle on Cortex-M0).
    pub(super) memo: Option<&'a AreaMemo>,
}

impl<G: Shape, D: DrawTarget> PaintVisitor<D::Color> for DepthVisitor<'_, '_, G, D> {
    type Output = Result<(), D::Error>;

    #[inline(always)]
    fn area_memo(&self) -> Option<&AreaMemo> {
        self.memo
    }

    #[inline(always)]
    fn visit<P: Painter<Color = D::Color>>(self, painter: P) -> Self::Output {
        // Depths as 16.16 with half a unit of bias: truncation rounds to nearest. Evaluated
        // from the first vertex when the triangle is small, wherever that vertex is (as colours
        // are): from a corner of the window instead, a band that does not hold the vertex
        // would set the plane up in 128-bit arithmetic.
        let values = || self.depths.map(|d| [i64::from(d) << 16]);
        let Some(depth) = self.triangle.planes_with::<1, 32, DEPTH_BITS>(
            values,
            1 << 15,
            self.setup.top_left,
            self.memo,
        ) else {
            return Ok(());
        };
        let (flip, slack) = self.test.comparison();
        let mut painter = painter;
        let carried = painter.carry_depth(&depth);
        let mut sink = DepthSpans {
            target: self.target,
            buffer: self.buffer,
            painter: &painter,
            depth: TrackedPlanes::new(depth),
            carried,
            origin: (self.window.top_left.x, self.window.top_left.y),
            flip,
            slack,
            // Written, nearer-wins tests (`flip` zero) only: the common case.
            short_spans: if flip == 0 && self.write {
                SHORT_SPAN
            } else {
                0
            },
            write: self.write,
            offset: self.offset,
        };
        self.triangle
            .walk_spans_erased(self.rule, &self.window, &mut sink)
    }
}

/// Tests, writes and paints each span.
struct DepthSpans<'a, 'b, 'p, D, P> {
    target: &'a mut D,
    buffer: &'a mut DepthBuffer<'b>,
    /// Borrowed where the style handed it over: the sink lives in memory for the type-erased
    /// walk, and holding the painter by value copied it in, word by word, for every triangle
    /// (and in bands for every band a triangle touches).
    painter: &'p P,
    /// The depth plane, moved from span to span unless the painter carries it with its own
    /// planes (`carried`), which costs one move per span instead of two.
    depth: TrackedPlanes<1>,
    carried: bool,
    /// The window's top-left corner: the buffer's (0, 0).
    origin: (i32, i32),
    /// The target's pixel `(x, y)` is the screen's `(x, y) + offset`.
    offset: Point,
    /// The test as `(depth ^ flip) < (stored ^ flip) + slack`.
    flip: u16,
    slack: u32,
    /// Spans up to this long are tested and written in one pass ([`SHORT_SPAN`], or 0 for
    /// tests and writes the one pass does not serve): one comparison per span.
    short_spans: u32,
    write: bool,
}

impl<D, P> SpanSink for DepthSpans<'_, '_, '_, D, P>
where
    D: DrawTarget,
    P: Painter<Color = D::Color>,
{
    type Error = D::Error;

    #[inline]
    fn span(&mut self, span: Span) -> Result<(), D::Error> {
        // Spans lie in the window, which the buffer covers: the offsets are in range.
        let x = span.x.wrapping_sub(self.origin.0) as u32;
        let y = span.y.wrapping_sub(self.origin.1) as u32;
        let Some(stored) = self.buffer.run_mut(x, y, span.len) else {
            return Ok(());
        };
        let carried = P::CARRIES_DEPTH && self.carried;
        let start = if carried {
            self.painter.carried_depth_at(span.x, span.y)
        } else {
            self.depth.at(span.x, span.y)[0]
        };
        let step = self.depth.step[0];
        let (flip, slack) = (i32::from(self.flip), self.slack as i32);

        if span.len <= self.short_spans {
            // Short spans (the rows of small and mesh triangles): tested and written in one
            // pass that stops at the first pixel failing, cheaper there than the two passes
            // below (measured: Gouraud + depth per `mesh` triangle -5% on Cortex-M0 and -6%
            // on M4F). Written, nearer-wins tests (`flip` zero) only: the common case.
            let (first_failing, depth) = pass_nearer(stored, start, step, slack);
            if first_failing < stored.len() {
                let run_start = (first_failing > 0).then_some(0);
                return self.paint_passing(span, first_failing, run_start, depth);
            }
        } else {
            // Depths are linear along the span, so their extremes lie at its ends (`last` is
            // the value the stepping below reaches, wrapping alike). When even the worst of
            // them passes against the best stored depth, all pixels pass: one reduction over
            // the stored depths decides it, and the span is written and painted without
            // per-pixel tests. This is the common case (a surface in front of what is there).
            let last = start.wrapping_add(step.wrapping_mul(span.len - 1));
            let worst = ((start >> 16) as i32 ^ flip).max((last >> 16) as i32 ^ flip);
            let all = all_stored_pass(stored, flip as u16, worst, slack) || {
                // Otherwise test every pixel, still without early exits (vectorised).
                let mut all = true;
                let mut depth = start;
                for &old in stored.iter() {
                    all &= passes((depth >> 16) as i32, old, flip, slack);
                    depth = depth.wrapping_add(step);
                }
                all
            };
            if !all {
                return self.paint_passing(span, 0, None, start);
            }
            if self.write {
                write_depths(stored, start, step);
            }
        }
        if carried {
            // The painter's planes are at the span's start already.
            return self.painter.paint_carried(span, self.offset, self.target);
        }
        self.painter.paint(span, self.offset, self.target)
    }
}

impl<D, P> DepthSpans<'_, '_, '_, D, P>
where
    D: DrawTarget,
    P: Painter<Color = D::Color>,
{
    /// The mixed case of [`SpanSink::span`]: tests and writes `span`'s pixels from `from` on,
    /// whose depth is `depth` (those before it passed, from `run_start` on), and paints each
    /// run of passing pixels. Out of line: the spans that pass whole keep their registers.
    #[inline(never)]
    fn paint_passing(
        &mut self,
        span: Span,
        from: usize,
        mut run_start: Option<usize>,
        mut depth: u32,
    ) -> Result<(), D::Error> {
        let x = span.x.wrapping_sub(self.origin.0) as u32;
        let y = span.y.wrapping_sub(self.origin.1) as u32;
        // The span's depths again: `span` borrowed them while it could still paint.
        let Some(stored) = self.buffer.run_mut(x, y, span.len) else {
            return Ok(());
        };
        let step = self.depth.step[0];
        let (flip, slack) = (i32::from(self.flip), self.slack as i32);
        // One more step past the last pixel ends the last run: one call into the painter.
        for i in from..=stored.len() {
            let value = (depth >> 16) as i32;
            depth = depth.wrapping_add(step);
            match stored.get_mut(i) {
                Some(old) if passes(value, *old, flip, slack) => {
                    if self.write {
                        *old = value as u16;
                    }
                    run_start.get_or_insert(i);
                }
                _ => {
                    if let Some(first) = run_start.take() {
                        let run = Span {
                            x: span.x.wrapping_add(first as i32),
                            y: span.y,
                            len: (i - first) as u32,
                        };
                        if P::CARRIES_DEPTH && self.carried {
                            // The carried plane moves with the painter's own: its move to
                            // the run's start then leaves the painter nothing to move.
                            move_carried(self.painter, run);
                        }
                        self.painter.paint(run, self.offset, self.target)?;
                    }
                }
            }
        }
        Ok(())
    }
}

/// Moves a painter's planes and the depth plane it carries to `run`'s start (see
/// [`Painter::carried_depth_at`]): out of line, as `DepthSpans::paint_passing` is, so
/// that the move's code does not grow the loop there (nor get copied with it).
#[inline(never)]
fn move_carried<P: Painter>(painter: &P, run: Span) {
    painter.carried_depth_at(run.x, run.y);
}

/// Whether `depth` passes the test `(depth ^ flip) < (old ^ flip) + slack` against the stored
/// `old`. In i32 the comparison needs no unsigned tricks: both sides stay below 2^17.
#[inline(always)]
fn passes(depth: i32, old: u16, flip: i32, slack: i32) -> bool {
    (depth ^ flip) < (i32::from(old) ^ flip) + slack
}

/// How many of `stored`'s depths, from the first, the span's depths (`start` stepping by
/// `step`, 16.16) pass in a row under a nearer-wins test (`depth < stored + slack`), each
/// written over the stored one; and the span's depth at the first that fails.
#[inline(always)]
fn pass_nearer(stored: &mut [u16], start: u32, step: u32, slack: i32) -> (usize, u32) {
    let mut depth = start;
    for (i, old) in stored.iter_mut().enumerate() {
        let value = (depth >> 16) as i32;
        if !passes(value, *old, 0, slack) {
            return (i, depth);
        }
        *old = value as u16;
        depth = depth.wrapping_add(step);
    }
    (stored.len(), depth)
}

/// Spans of at most this many pixels are tested and written in one pass (see
/// `DepthSpans::span`).
const SHORT_SPAN: u32 = 16;

/// Whether the (flipped) depth `worst` passes `worst < (old ^ flip) + slack` against every
/// stored depth `old`: the differences `worst - slack - (old ^ flip)`, combined by bitwise
/// and, are negative exactly when each is. A subtraction and an AND a pixel, without a branch;
/// the minimum of the stored depths it replaced took a comparison and a branch or conditional
/// move as well (measured on `big`: Gouraud + depth -2.5% on Cortex-M0, -5.2% on M4F).
#[inline(always)]
fn all_stored_pass(stored: &[u16], flip: u16, worst: i32, slack: i32) -> bool {
    // `flip` is 0 or all ones (`DepthTest::comparison`); with all ones `old ^ flip` is
    // `0xFFFF - old`. Every difference lies within ±2^17: no overflow.
    debug_assert!(flip == 0 || flip == u16::MAX);
    let threshold = worst - slack;
    if flip == 0 {
        stored
            .iter()
            .fold(-1, |all, &old| all & (threshold - i32::from(old)))
            < 0
    } else {
        let threshold = threshold - 0xFFFF;
        stored
            .iter()
            .fold(-1, |all, &old| all & (threshold + i32::from(old)))
            < 0
    }
}

/// Stores the depths of a span, `start` stepping by `step` (16.16), rounded down.
#[inline(always)]
fn write_depths(stored: &mut [u16], start: u32, step: u32) {
    let mut depth = start;
    for old in stored.iter_mut() {
        *old = (depth >> 16) as u16;
        depth = depth.wrapping_add(step);
    }
}
