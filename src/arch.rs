//! What the core computes in hardware, which picks between arithmetic paths that give the same
//! results bit for bit: Cortex-M0/M0+ have neither a 32-bit divide nor a 32 x 32 -> 64-bit
//! multiply (each a library call there), Cortex-M3 and up have both, and 64-bit hosts divide
//! and multiply 64 bits in hardware.
//!
//! Every path is exact, so the property tests hold for each; they run on the host, which would
//! take only its own. Built with the environment variable `TRIRAST_EMULATE` set to `cortex-m0`
//! or `cortex-m4`, the library takes that core's paths on any host, so that the tests check
//! them too (only the choice of path changes: code layout and inlining stay the host's):
//!
//! ```sh
//! TRIRAST_EMULATE=cortex-m0 cargo test --lib --tests
//! ```
//!
//! An environment variable rather than a `--cfg` in `RUSTFLAGS`: cargo rebuilds only this
//! crate and its tests when it changes, not every dependency.

/// The core whose arithmetic the host takes, if any (`TRIRAST_EMULATE`, read when building).
const EMULATED: Option<&str> = option_env!("TRIRAST_EMULATE");

/// Whether `TRIRAST_EMULATE` names `core`.
const fn emulates(core: &str) -> bool {
    let Some(emulated) = EMULATED else {
        return false;
    };
    let (a, b) = (emulated.as_bytes(), core.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

const _: () = assert!(
    EMULATED.is_none() || emulates("cortex-m0") || emulates("cortex-m4"),
    "TRIRAST_EMULATE must be cortex-m0 or cortex-m4 (or unset)"
);

/// Whether a 32-bit division and a 32 x 32 -> 64-bit multiply are instructions: every core
/// but Cortex-M0/M0+ (and others without atomic compare-and-swap, which is what
/// `target_has_atomic` tells apart).
pub(crate) const DIVIDES: bool = cfg!(target_has_atomic = "32") && !emulates("cortex-m0");

/// Whether the core is an Arm Cortex-M (32-bit, no 64-bit division instruction): paths
/// written for those (reciprocals from tables and 32-bit digits) instead of the 64-bit
/// host's division.
pub(crate) const ARM: bool = cfg!(target_arch = "arm") || EMULATED.is_some();

/// Whether registers hold 64 bits: 64-bit hosts, unless emulating a Cortex-M.
pub(crate) const WORD_64: bool = cfg!(target_pointer_width = "64") && !ARM;
