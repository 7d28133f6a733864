//! The fast walk's rows: two edge steppers carried down the triangle, in at most two stretches
//! (above and below the middle vertex). A walk stopped at its window's last row can go on in
//! the window below, which is how bands walk a triangle once per frame rather than once per
//! band ([`Bands::with_setup_cache`](crate::band::Bands::with_setup_cache)).

use core::cell::Cell;

use embedded_graphics::geometry::Point;

use super::{
    FillRule, RowPlan, SpanSink,
    edge::{EdgeStepper, Rounding},
    emit,
};
use crate::setup::Clip;

/// A fast walk between two rows: its edges' bounds on the next row, the rows it emits in the
/// window, and what it needs to go on below it (the lower short edge's vertices for the turn at
/// the middle one).
#[derive(Copy, Clone, Debug)]
pub(crate) struct RowWalk {
    left: EdgeStepper<i32>,
    right: EdgeStepper<i32>,
    /// The next row to emit.
    row: i32,
    /// The end of the current stretch, in the window: the middle vertex's row or the end.
    stop: i32,
    /// The end of the rows in the window.
    end: i32,
    /// The row the lower short edge takes over; `i32::MAX` once it has, or with a flat bottom
    /// (no row reaches it).
    switch: i32,
    /// The end of the triangle's rows, wherever the window ends.
    triangle_end: i32,
    middle: (i32, i32),
    bottom: (i32, i32),
    short_rounding: Rounding,
    long_left: bool,
}

/// Where a triangle's walk stopped at a window's bottom, kept for the window below: 72 bytes
/// (a [`RowWalk`] without what each window sets again, its flags in a byte).
#[derive(Debug)]
pub struct KeptWalk {
    /// The row the kept walk goes on from.
    row: Cell<i32>,
    /// [`KeptWalk::HELD`], [`KeptWalk::LONG_LEFT`], [`KeptWalk::FLOOR_PLUS_ONE`].
    flags: Cell<u8>,
    edges: Cell<KeptEdges>,
}

/// The part of a [`RowWalk`] a window does not set again.
#[derive(Copy, Clone, Debug)]
struct KeptEdges {
    left: EdgeStepper<i32>,
    right: EdgeStepper<i32>,
    switch: i32,
    triangle_end: i32,
    middle: (i32, i32),
    bottom: (i32, i32),
}

impl KeptWalk {
    /// A walk is kept.
    const HELD: u8 = 1;
    /// Its long edge bounds the left.
    const LONG_LEFT: u8 = 2;
    /// Its short edges round as [`Rounding::FloorPlusOne`].
    const FLOOR_PLUS_ONE: u8 = 4;

    /// Nothing kept.
    // A constant, for `SetupSlot::EMPTY` (itself a constant for arrays of slots); every use is
    // a fresh one.
    #[allow(clippy::declare_interior_mutable_const)]
    pub(crate) const NONE: Self = Self {
        row: Cell::new(0),
        flags: Cell::new(0),
        // All zeros (never read unless a walk is kept): slots start as zeroed memory.
        edges: Cell::new(KeptEdges {
            left: EdgeStepper::from_parts(0, 0, (0, 0), 0),
            right: EdgeStepper::from_parts(0, 0, (0, 0), 0),
            switch: 0,
            triangle_end: 0,
            middle: (0, 0),
            bottom: (0, 0),
        }),
    };

    /// Whether a walk is kept.
    #[inline(always)]
    pub(crate) fn holds(&self) -> bool {
        self.flags.get() & Self::HELD != 0
    }

    /// Forgets the kept walk.
    #[inline(always)]
    pub(crate) fn forget(&self) {
        self.flags.set(0);
    }

    /// The walk kept for the window `clip` (which starts at the row it stopped above), on to
    /// that window's end.
    #[inline(always)]
    pub(super) fn resume(&self, clip: &Clip<i32>) -> Option<RowWalk> {
        let flags = self.flags.get();
        if flags & Self::HELD == 0 || self.row.get() != clip.y0 {
            return None;
        }
        let edges = self.edges.get();
        let end = edges.triangle_end.min(clip.y1);
        Some(RowWalk {
            left: edges.left,
            right: edges.right,
            row: clip.y0,
            stop: edges.switch.min(end),
            end,
            switch: edges.switch,
            triangle_end: edges.triangle_end,
            middle: edges.middle,
            bottom: edges.bottom,
            short_rounding: if flags & Self::FLOOR_PLUS_ONE != 0 {
                Rounding::FloorPlusOne
            } else {
                Rounding::Ceil
            },
            long_left: flags & Self::LONG_LEFT != 0,
        })
    }

    #[inline(always)]
    fn keep(&self, walk: RowWalk) {
        let mut flags = Self::HELD;
        if walk.long_left {
            flags |= Self::LONG_LEFT;
        }
        if walk.short_rounding == Rounding::FloorPlusOne {
            flags |= Self::FLOOR_PLUS_ONE;
        }
        self.row.set(walk.row);
        self.flags.set(flags);
        self.edges.set(KeptEdges {
            left: walk.left,
            right: walk.right,
            switch: walk.switch,
            triangle_end: walk.triangle_end,
            middle: walk.middle,
            bottom: walk.bottom,
        });
    }
}

impl RowWalk {
    /// The walk of the triangle `sorted` (by `sort_top_to_bottom`, every coordinate in the fast
    /// range) at its first row inside `clip`; `None` when it covers no row there (or is
    /// degenerate).
    #[inline(always)]
    pub(super) fn start(sorted: [Point; 3], rule: FillRule, clip: Clip<i32>) -> Option<Self> {
        let plan = RowPlan::<i32>::new(sorted, rule, clip)?;
        let [top, middle, bottom] = plan.triangle.sorted;
        let row = plan.first;
        // Edges start at `row`; after a skipped apex, from the vertex and one step down, which
        // needs no division.
        let start = |upper: (i32, i32), lower: (i32, i32), rounding: Rounding, below_apex: bool| {
            if below_apex {
                let mut edge = EdgeStepper::start(upper, lower, rounding, upper.1);
                edge.advance();
                edge
            } else {
                EdgeStepper::start(upper, lower, rounding, row)
            }
        };
        let upper_half = row < plan.switch;
        let long = start(top, bottom, plan.long_rounding, plan.skip_apex);
        let short = if upper_half {
            start(top, middle, plan.short_rounding, plan.skip_apex)
        } else {
            start(middle, bottom, plan.short_rounding, false)
        };
        let long_left = plan.triangle.long_edge_left;
        let (left, right) = if long_left {
            (long, short)
        } else {
            (short, long)
        };
        Some(Self {
            left,
            right,
            row,
            // Rows run in at most two stretches, above and below the middle vertex, so each
            // row tests one bound only.
            stop: if upper_half {
                plan.switch.min(plan.end)
            } else {
                plan.end
            },
            end: plan.end,
            // With a flat bottom (which only the inclusive rule reaches) the upper short edge
            // serves every row, the middle one too, where it ends exactly.
            switch: if upper_half && middle.1 < bottom.1 {
                middle.1
            } else {
                i32::MAX
            },
            triangle_end: plan.rows_end,
            middle,
            bottom,
            short_rounding: plan.short_rounding,
            long_left,
        })
    }

    /// Emits the rows from the walk's to its end in the window. When the window ends before
    /// the triangle and `kept` is given, the walk is left there at the row below, for the
    /// window below.
    #[inline(always)]
    pub(super) fn run<K: SpanSink + ?Sized>(
        self,
        clip: &Clip<i32>,
        sink: &mut K,
        kept: Option<&KeptWalk>,
    ) -> Result<(), K::Error> {
        let Self {
            mut left,
            mut right,
            mut row,
            mut stop,
            end,
            mut switch,
            ..
        } = self;
        loop {
            loop {
                emit(clip, left.x(), right.x(), row, sink)?;
                row += 1;
                if row == stop {
                    break;
                }
                left.advance();
                right.advance();
            }
            if row == end {
                if let Some(kept) = kept {
                    if row < self.triangle_end {
                        let mut rest = Self {
                            left,
                            right,
                            row,
                            switch,
                            ..self
                        };
                        if row == switch {
                            rest.turn();
                        } else {
                            rest.left.advance();
                            rest.right.advance();
                        }
                        kept.keep(rest);
                    }
                }
                return Ok(());
            }
            stop = end;
            switch = i32::MAX;
            let mut rest = Self {
                left,
                right,
                row,
                ..self
            };
            rest.turn();
            (left, right) = (rest.left, rest.right);
        }
    }

    /// The short edge turns at the middle vertex, where its bound needs no division; the long
    /// edge steps on.
    #[inline(always)]
    fn turn(&mut self) {
        let lower = EdgeStepper::start(self.middle, self.bottom, self.short_rounding, self.row);
        if self.long_left {
            self.left.advance();
            self.right = lower;
        } else {
            self.right.advance();
            self.left = lower;
        }
        self.switch = i32::MAX;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{
        Triangle,
        coverage::{Span, walk, walk_kept_erased},
    };
    use embedded_graphics::{geometry::Size, primitives::Rectangle};
    use heapless::Vec;

    /// Spans of one walk: at most one a row of the 37-row screen.
    type Spans = Vec<Span, 40>;

    /// Spans of `triangle` walked band by band, `rows` rows each, down `screen`, keeping the
    /// walk between bands as a band renderer does (`later` while the triangle reaches below).
    fn banded(triangle: &Triangle, rule: FillRule, screen: Rectangle, rows: u32) -> Spans {
        let kept = KeptWalk::NONE;
        let mut spans = Spans::new();
        let bottom = screen.top_left.y + screen.size.height as i32;
        let last_row = triangle.vertices.iter().map(|p| p.y).max().unwrap();
        let mut top = screen.top_left.y;
        while top < bottom {
            let height = (bottom - top).min(rows as i32) as u32;
            let band = Rectangle::new(
                Point::new(screen.top_left.x, top),
                Size::new(screen.size.width, height),
            );
            let later = last_row >= top + height as i32;
            let mut sink = |span: Span| spans.push(span).map_err(|_| ());
            walk_kept_erased(triangle, rule, &band, &mut sink, &kept, later).unwrap();
            top += height as i32;
        }
        spans
    }

    /// Walking band by band, going on from each band's kept walk, gives the whole walk's spans
    /// (which `tests/suite/coverage_reference.rs` checks against exact half-space tests): upper and
    /// lower stretches, turns on a band's first row and below its last, flat tops and bottoms,
    /// both rules, bands of one row and more, windows cutting columns.
    #[test]
    fn banded_walks_are_the_whole_walk() {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = |range: i32| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % range as u64) as i32
        };
        let screen = Rectangle::new(Point::new(-3, -5), Size::new(40, 37));
        let mut compared = 0;
        for case in 0..20_000 {
            let mut point = || Point::new(next(56) - 10, next(56) - 12);
            let mut vertices = [point(), point(), point()];
            // Flat tops and bottoms often, and every vertex on a band's edge sometimes.
            match case % 4 {
                0 => vertices[1].y = vertices[0].y,
                1 => vertices[2].y = vertices[1].y,
                _ => {}
            }
            let triangle = Triangle::new(vertices[0], vertices[1], vertices[2]);
            for rule in [FillRule::TopLeft, FillRule::Inclusive] {
                let rows = 1 + next(7) as u32;
                let mut whole = Spans::new();
                walk(&triangle, rule, &screen, &mut |span: Span| {
                    whole.push(span).map_err(|_| ())
                })
                .unwrap();
                assert_eq!(
                    banded(&triangle, rule, screen, rows),
                    whole,
                    "{triangle:?} {rule:?} bands of {rows}"
                );
                compared += whole.len();
            }
        }
        assert!(compared > 100_000, "{compared} spans");
    }
}
