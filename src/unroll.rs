//! Loops over a few parallel values (colour channels, planes, texture axes) written out as
//! straight-line code with constant indices, whatever the optimisation level: with
//! `opt-level = "s"` or `"z"` loops over two to four items, `array::map`, `array::from_fn` and
//! closures called per item stay loops and calls, each value in memory (on Cortex-M0 and M4F
//! the span set-ups and per-pixel channel work cost 1.5 to 8 times `opt-level = 3`'s). At
//! `opt-level = 3` the code is what the optimiser made of the loops anyway.

/// Sets each element `$k` of the slice `$slots` to `$value`, an expression of `$k`: the first
/// four in straight-line code, any others in a loop. So the per-pixel channel work stays
/// unrolled at every optimisation level: with `opt-level = "s"` or `"z"` the loops of
/// `array::map`, `array::from_fn` and iterators stay loops (or calls), which on Cortex-M0 store
/// each channel to memory and reload it (measured: Gouraud's `big` pixels cost 5 times as
/// much, bilinear ones 2.4 times). A macro rather than a function taking a closure: at
/// `"z"` such a closure, called once per channel, stayed a call per channel and pixel, its
/// index a variable (Gouraud `big` on Cortex-M0 139 instructions a pixel). Constant indices
/// with `get_mut` fold away once the length is known; plain indexing would not compile for
/// shorter arrays (an out-of-bounds constant index is an error even where unreachable).
macro_rules! each_slot {
    ($slots:expr, |$k:ident| $value:expr) => {{
        let slots: &mut [_] = $slots;
        if let Some(slot) = slots.get_mut(0) {
            let $k: usize = 0;
            *slot = $value;
        }
        if let Some(slot) = slots.get_mut(1) {
            let $k: usize = 1;
            *slot = $value;
        }
        if let Some(slot) = slots.get_mut(2) {
            let $k: usize = 2;
            *slot = $value;
        }
        if let Some(slot) = slots.get_mut(3) {
            let $k: usize = 3;
            *slot = $value;
        }
        for $k in 4..slots.len() {
            slots[$k] = $value;
        }
    }};
}

/// `[value(0), value(1), ..., value($n - 1)]` for `$value` an expression of `$k`, written out
/// for up to four channels (see [`each_slot`]).
macro_rules! per_channel {
    ($n:expr, |$k:ident| $value:expr) => {{
        let mut out = [Default::default(); $n];
        $crate::unroll::each_slot!(&mut out[..], |$k| $value);
        out
    }};
}

pub(crate) use {each_slot, per_channel};
