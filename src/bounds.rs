//! Indexing whose panic (a bug: every index the crate takes this way is in range by
//! construction) has a constant message. An indexing panic formats its index and length,
//! which links about 2 KB of integer formatting into a firmware that prints nothing; these
//! pass the index and length to their panic anyway, unused, so that the code around them keeps
//! the shape (and, on Cortex-M0, the register allocation) it had with plain indexing.

/// Item `index` of `items`.
#[inline(always)]
pub(crate) fn at<T>(items: &[T], index: usize) -> &T {
    match items.get(index) {
        Some(item) => item,
        None => out_of_range(index, items.len()),
    }
}

/// [`at`], mutable.
#[inline(always)]
pub(crate) fn at_mut<T>(items: &mut [T], index: usize) -> &mut T {
    let len = items.len();
    match items.get_mut(index) {
        Some(item) => item,
        None => out_of_range(index, len),
    }
}

/// The first `count` of `items`.
#[inline(always)]
pub(crate) fn first<T>(items: &[T], count: usize) -> &[T] {
    match items.get(..count) {
        Some(part) => part,
        None => out_of_range(count, items.len()),
    }
}

/// The items of `items` from `from` on.
#[inline(always)]
pub(crate) fn from<T>(items: &[T], from: usize) -> &[T] {
    match items.get(from..) {
        Some(part) => part,
        None => out_of_range(from, items.len()),
    }
}

/// Items `from..to` of `items`, mutable.
#[inline(always)]
pub(crate) fn within_mut<T>(items: &mut [T], from: usize, to: usize) -> &mut [T] {
    let len = items.len();
    match items.get_mut(from..to) {
        Some(part) => part,
        None => out_of_range(to, len),
    }
}

/// The panic of [`at`] and its kin.
#[cold]
#[inline(never)]
pub(crate) fn out_of_range(_index: usize, _len: usize) -> ! {
    panic!("an index past what it counts")
}
