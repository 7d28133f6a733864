//! What the core computes in hardware, which picks between arithmetic paths that give the same
//! results bit for bit: Cortex-M0/M0+ have neither a 32-bit divide nor a 32 x 32 -> 64-bit
//! multiply (each a library call there), Cortex-M3 and up have both, and 64-bit hosts divide
//! and multiply 64 bits in hardware.
//!
//! Every path is exact, so the property tests hold for each; they run on the host, which would
//! take only its own. Building with `--cfg trirast_emulate="cortex-m0"` (or `"cortex-m4"`)
//! takes that core's paths on any host, so that the tests check them too:
//!
//! ```sh
//! RUSTFLAGS='--cfg trirast_emulate="cortex-m0"' cargo test --lib --tests --target-dir target/emulate-cortex-m0
//! ```
//!
//! Only the choice of path changes: code layout and inlining stay the host's.

/// Whether a 32-bit division and a 32 x 32 -> 64-bit multiply are instructions: every core
/// but Cortex-M0/M0+ (and others without atomic compare-and-swap, which is what
/// `target_has_atomic` tells apart).
pub(crate) const DIVIDES: bool =
    cfg!(target_has_atomic = "32") && !cfg!(trirast_emulate = "cortex-m0");

/// Whether the core is an Arm Cortex-M (32-bit, no 64-bit division instruction): paths
/// written for those (reciprocals from tables and 32-bit digits) instead of the 64-bit
/// host's division.
pub(crate) const ARM: bool = cfg!(target_arch = "arm")
    || cfg!(trirast_emulate = "cortex-m0")
    || cfg!(trirast_emulate = "cortex-m4");

/// Whether registers hold 64 bits: 64-bit hosts, unless emulating a Cortex-M.
pub(crate) const WORD_64: bool = cfg!(target_pointer_width = "64") && !ARM;
