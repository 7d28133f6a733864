//! Instruction counting on emulated Cortex-M, shared by the firmware benchmarks
//! (`examples/firmware.rs`, `benches/peers-firmware`): SysTick under QEMU's `-icount shift=3`,
//! where one tick is five instructions, exact and the same on every run.
#![allow(dead_code)]

use core::sync::atomic::{AtomicU32, Ordering};

use cortex_m::peripheral::{SYST, syst::SystClkSource};
use cortex_m_rt::exception;

/// Instructions per SysTick tick under `-icount shift=3` with a 25 MHz SysTick.
const INSTRUCTIONS_PER_TICK: u64 = 5;

/// SysTick reload: the counter wraps (and the exception counts a wrap) every 2^24 ticks.
const RELOAD: u32 = 0x00FF_FFFF;

/// SysTick wraps so far (only the exception handler writes it).
static WRAPS: AtomicU32 = AtomicU32::new(0);

#[exception]
fn SysTick() {
    WRAPS.store(WRAPS.load(Ordering::Relaxed) + 1, Ordering::Relaxed);
}

/// Starts SysTick counting from the core clock, wrapping every 2^24 ticks.
pub fn start(syst: &mut SYST) {
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(RELOAD);
    syst.clear_current();
    syst.enable_interrupt();
    syst.enable_counter();
}

/// Ticks since the counter started. The exception runs as soon as the counter wraps, so an
/// unchanged wrap count around the read means the two agree.
fn ticks() -> u64 {
    loop {
        let wraps = WRAPS.load(Ordering::Relaxed);
        let current = SYST::get_current();
        if WRAPS.load(Ordering::Relaxed) == wraps {
            return u64::from(wraps) * (u64::from(RELOAD) + 1) + u64::from(RELOAD - current);
        }
    }
}

/// Instructions spent in `f`.
pub fn count(f: impl FnOnce()) -> u64 {
    let start = ticks();
    f();
    (ticks() - start) * INSTRUCTIONS_PER_TICK
}

/// `value / divisor` with two decimals, for printing without floats.
pub struct Ratio(pub u64, pub u64);

impl core::fmt::Display for Ratio {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let (hundredths, _) = div_rem(self.0 * 100, self.1.max(1));
        let (whole, cents) = div_rem(hundredths, 100);
        let cents = cents as u32;
        write!(f, "{}.{}{}", Decimal(whole), cents / 10, cents % 10)
    }
}

/// A `u64` printed in decimal without the 64-bit library division, which `u64`'s own
/// `Display` calls: on Cortex-M0 the harness would otherwise link it (about 1.1 KB) into a
/// firmware whose modes do not.
pub struct Decimal(pub u64);

impl core::fmt::Display for Decimal {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let (rest, digit) = div_rem(self.0, 10);
        if rest > 0 {
            Decimal(rest).fmt(f)?;
        }
        core::fmt::Write::write_char(f, char::from(b'0' + digit as u8))
    }
}

/// `(n / d, n % d)` by shift and subtract, for `d > 0`: see [`Decimal`]. Out of line: one copy.
#[inline(never)]
pub fn div_rem(n: u64, d: u64) -> (u64, u64) {
    // The dividend's bits move out at the top as the quotient's move in at the bottom.
    let (mut bits, mut rest) = (n, 0u64);
    for _ in 0..64 {
        rest = (rest << 1) | (bits >> 63);
        bits <<= 1;
        if rest >= d {
            rest -= d;
            bits |= 1;
        }
    }
    (bits, rest)
}
