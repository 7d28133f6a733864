//! Interpolation set-ups kept between bands: a triangle drawn into several bands has its planes
//! set up in the first and read back, bit for bit, in the others.

use core::{cell::Cell, fmt};

use embedded_graphics::{geometry::Point, primitives::Rectangle};

use crate::{
    coverage::{CoverageSink, FillRule, KeptWalk, SpanSink},
    geometry::Shape,
    interpolate::{AreaMemo, Planes},
};

/// Words of set-up one slot holds: a Gouraud triangle's colour planes and depth plane (14),
/// a textured one's coordinate and depth planes (11), a perspective-correct one's (14).
/// Set-ups from the first that does not fit on (a modulated texture's tint, 10 words after its
/// coordinates' 7, and its depth) are made again in every band.
const SLOT_WORDS: usize = 14;

/// Room for one triangle's interpolation set-up between bands ([`Bands::with_setup_cache`]),
/// and for where its walk stopped at the last band's bottom, so that the next band goes on from
/// there instead of starting the triangle again: 192 bytes (120 of set-up, 72 of walk), on
/// 32-bit microcontrollers as on 64-bit hosts.
///
/// Slot `k` keeps the set-up of the scene's triangle `k` within one frame; each render
/// starts them afresh.
///
/// [`Bands::with_setup_cache`]: super::Bands::with_setup_cache
///
/// # Examples
///
/// ```
/// use trirast::band::SetupSlot;
///
/// // One slot per scene triangle: each is set up once per frame.
/// let cache = [SetupSlot::EMPTY; 200];
/// assert_eq!(cache.len(), 200);
/// ```
pub struct SetupSlot {
    /// Words written so far this frame, by the triangle whose index is the slot's.
    used: Cell<u32>,
    words: [Cell<i64>; SLOT_WORDS],
    /// Where the triangle's walk stopped at the last band's bottom, to go on from in the next.
    walk: KeptWalk,
}

impl SetupSlot {
    /// A slot holding nothing.
    ///
    /// # Examples
    ///
    /// ```
    /// use trirast::band::SetupSlot;
    ///
    /// let cache = [SetupSlot::EMPTY; 64];
    /// # let _ = cache;
    /// ```
    // A constant, so that arrays of slots can be written `[SetupSlot::EMPTY; N]` (the type is
    // not `Copy`); every use is a fresh slot.
    #[allow(clippy::declare_interior_mutable_const)]
    pub const EMPTY: Self = Self {
        used: Cell::new(0),
        words: [const { Cell::new(0) }; SLOT_WORDS],
        walk: KeptWalk::NONE,
    };

    /// Forgets what the slot holds (a new frame: the scene may have changed).
    #[inline]
    pub(super) fn clear(&self) {
        self.used.set(0);
        self.walk.forget();
    }
}

impl Default for SetupSlot {
    /// [`SetupSlot::EMPTY`].
    ///
    /// # Examples
    ///
    /// ```
    /// use trirast::band::SetupSlot;
    ///
    /// let slots: [SetupSlot; 4] = Default::default();
    /// # let _ = slots;
    /// ```
    fn default() -> Self {
        Self::EMPTY
    }
}

impl fmt::Debug for SetupSlot {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SetupSlot")
            .field("used", &self.used.get())
            .finish_non_exhaustive()
    }
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::NoSetupCache {}
    impl Sealed for &[super::SetupSlot] {}
}

/// Where [`Bands`](super::Bands) keep triangles' set-ups between bands: nowhere
/// ([`NoSetupCache`], the default) or slots of the caller's
/// ([`Bands::with_setup_cache`](super::Bands::with_setup_cache)). A type, not a run-time
/// choice, so that bands without a cache carry none of its code.
///
/// # Examples
///
/// ```
/// use trirast::band::{NoSetupCache, SetupCache, SetupSlot};
///
/// fn takes<K: SetupCache>(_: K) {}
/// takes(NoSetupCache);
/// takes(&[SetupSlot::EMPTY; 4][..]);
/// ```
pub trait SetupCache: sealed::Sealed + Copy {
    /// Whether set-ups are kept at all.
    #[doc(hidden)]
    const KEEPS: bool;

    /// The slot of the scene triangle at `index`, if any.
    #[doc(hidden)]
    fn slot(&self, index: usize) -> Option<&SetupSlot>;

    /// Forgets the set-ups of the slots of the first `triangles` scene triangles (a new
    /// frame: the scene may have changed). Only those are read this frame, and each frame
    /// forgets those its scene reads first.
    #[doc(hidden)]
    fn forget(&self, triangles: usize);
}

/// No set-ups kept: every triangle is set up again in each band it touches.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use trirast::band::{Bands, NoSetupCache};
///
/// let mut band = [Rgb565::default(); 320 * 16];
/// let _bands: Bands<Rgb565, Rgb565, NoSetupCache> = Bands::new(&mut band, 320, 16)?;
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct NoSetupCache;

impl SetupCache for NoSetupCache {
    const KEEPS: bool = false;

    #[inline(always)]
    fn slot(&self, _: usize) -> Option<&SetupSlot> {
        None
    }

    #[inline(always)]
    fn forget(&self, _: usize) {}
}

impl SetupCache for &[SetupSlot] {
    const KEEPS: bool = true;

    /// Slot `index`: triangles beyond the slots have none (sharing slots would cost a
    /// division per set-up on cores without a divider, and triangles that evict each other).
    #[inline(always)]
    fn slot(&self, index: usize) -> Option<&SetupSlot> {
        self.get(index)
    }

    fn forget(&self, triangles: usize) {
        for slot in self.iter().take(triangles) {
            slot.clear();
        }
    }
}

/// A scene triangle drawn into a band, whose plane set-ups go through its slot: made and
/// stored the first time, read back in the bands after. Its set-ups are asked for in the
/// same order in every band (the style's, then the depth's), so the slot holds them in that
/// order.
pub(crate) struct Cached<'a, G, Keep> {
    shape: &'a G,
    cache: Keep,
    index: usize,
    /// Whether the triangle reaches bands below this one: only then is a set-up worth
    /// keeping.
    later: bool,
    /// Words of the slot the set-ups asked for so far take.
    cursor: Cell<usize>,
}

impl<'a, G: Shape, Keep: SetupCache> Cached<'a, G, Keep> {
    /// The scene triangle `shape` at `index`, keeping its set-ups in `cache` when it reaches
    /// `later` bands.
    #[inline(always)]
    pub(super) fn new(shape: &'a G, cache: Keep, index: usize, later: bool) -> Self {
        Self {
            shape,
            cache,
            index,
            later,
            cursor: Cell::new(0),
        }
    }

    /// The triangle's slot, if the cache has one.
    #[inline(always)]
    fn slot(&self) -> Option<&SetupSlot> {
        self.cache.slot(self.index)
    }

    /// The next set-up, when this triangle stored it in an earlier band; else `Err` with where
    /// [`Cached::keep`] stores it once made.
    #[inline(always)]
    fn stored<const N: usize, const SETUP: u32>(&self) -> Result<Planes<N, SETUP>, usize> {
        let at = self.cursor.get();
        let end = at + Planes::<N, SETUP>::WORDS;
        self.cursor.set(end);
        match self.slot() {
            Some(slot) if end <= slot.used.get() as usize => {
                slot.words.get(at..end).and_then(Planes::load).ok_or(at)
            }
            _ => Err(at),
        }
    }

    /// The next set-up: read back when an earlier band stored it, else `make`'s, kept for the
    /// bands after.
    #[inline(always)]
    fn through_slot<const N: usize, const SETUP: u32>(
        &self,
        make: impl FnOnce() -> Option<Planes<N, SETUP>>,
    ) -> Option<Planes<N, SETUP>> {
        let at = match self.stored() {
            Ok(planes) => return Some(planes),
            Err(at) => at,
        };
        let planes = make()?;
        self.keep(&planes, at);
        Some(planes)
    }

    /// Stores `planes`, made for the set-up at word `at`, when it fits and follows what the
    /// slot holds (the set-ups before it stored too).
    #[inline(always)]
    fn keep<const N: usize, const SETUP: u32>(&self, planes: &Planes<N, SETUP>, at: usize) {
        if !self.later {
            return;
        }
        let Some(slot) = self.slot() else { return };
        let end = at + Planes::<N, SETUP>::WORDS;
        let Some(words) = slot.words.get(at..end) else {
            return;
        };
        if slot.used.get() as usize != at {
            return;
        }
        planes.store(words);
        slot.used.set(end as u32);
    }
}

impl<G: Shape, Keep: SetupCache> Shape for Cached<'_, G, Keep> {
    #[inline(always)]
    fn walk_spans<K: SpanSink + ?Sized>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        sink: &mut K,
    ) -> Result<(), K::Error> {
        self.shape.walk_spans(rule, clip, sink)
    }

    #[inline(always)]
    fn walk_spans_erased<E>(
        &self,
        rule: FillRule,
        clip: &Rectangle,
        sink: &mut dyn SpanSink<Error = E>,
    ) -> Result<(), E> {
        // Triangles within one band (most small ones) walk as in a frame.
        match self.slot() {
            Some(slot) if self.later || slot.walk.holds() => self
                .shape
                .walk_spans_erased_kept(rule, clip, sink, &slot.walk, self.later),
            _ => self.shape.walk_spans_erased(rule, clip, sink),
        }
    }

    #[inline(always)]
    fn walk_area<K: CoverageSink>(&self, clip: &Rectangle, sink: &mut K) -> Result<(), K::Error> {
        self.shape.walk_area(clip, sink)
    }

    #[inline(always)]
    fn sample_rows(&self) -> (i64, i64) {
        self.shape.sample_rows()
    }

    #[inline(always)]
    fn planes<const N: usize, const SETUP: u32>(
        &self,
        values: [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>> {
        self.through_slot(|| self.shape.planes(values, bias, reference, memo))
    }

    #[inline(always)]
    fn planes_with<const N: usize, const SETUP: u32, const WHOLE_BITS: u32>(
        &self,
        values: impl Fn() -> [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>> {
        self.through_slot(|| {
            self.shape
                .planes_with::<N, SETUP, WHOLE_BITS>(values, bias, reference, memo)
        })
    }

    #[inline(always)]
    fn planes_adjusted<const N: usize, const SETUP: u32, const WHOLE_BITS: u32>(
        &self,
        values: impl Fn() -> [[i64; N]; 3],
        bias: i64,
        reference: Point,
        memo: Option<&AreaMemo>,
        adjust: impl FnOnce(&mut Planes<N, SETUP>),
    ) -> Option<Planes<N, SETUP>> {
        self.through_slot(|| {
            self.shape
                .planes_adjusted::<N, SETUP, WHOLE_BITS>(values, bias, reference, memo, adjust)
        })
    }

    #[inline(always)]
    fn planes_in<const N: usize, const SETUP: u32>(
        &self,
        values: [[i64; N]; 3],
        bias: i64,
        window: &Rectangle,
        memo: Option<&AreaMemo>,
    ) -> Option<Planes<N, SETUP>> {
        self.through_slot(|| self.shape.planes_in(values, bias, window, memo))
    }
}
