//! Firmware for emulated Cortex-M (QEMU's MPS2 boards): renders the benchmark scenes into a RAM
//! framebuffer with each drawing mode, prints a checksum of each frame and the instructions per
//! drawn pixel, and exits.
//!
//! ```text
//! ../shared/embedded/xcargo thumbv6m-none-eabi run --release --example firmware --features firmware
//! ```
//!
//! Instruction counts come from SysTick under `qemu -icount shift=3`, where one tick is five
//! instructions: exact to five instructions per measured frame, and the same on every run.
#![no_std]
#![no_main]

#[path = "common/scenes.rs"]
mod scenes;

use cortex_m::peripheral::{syst::SystClkSource, SYST};
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
use panic_halt as _;
use scenes::{Scene, HEIGHT, WIDTH};
use trirast::{coverage::for_each_span, FillRule, FlatStyle, Framebuffer, GouraudStyle, Triangle};

/// Instructions per SysTick tick under `-icount shift=3` with a 25 MHz SysTick.
const INSTRUCTIONS_PER_TICK: u32 = 5;

#[derive(Copy, Clone)]
enum Mode {
    Flat,
    Gouraud,
}

impl Mode {
    fn name(self) -> &'static str {
        match self {
            Mode::Flat => "flat",
            Mode::Gouraud => "gouraud",
        }
    }
}

fn draw(mode: Mode, scene: Scene, fb: &mut Framebuffer<'_, Rgb565>) {
    scene.for_each(|t| {
        let [a, b, c] = t.vertices;
        let triangle = Triangle::new(a, b, c);
        let _ = match mode {
            Mode::Flat => triangle.into_styled(FlatStyle::new(t.color)).draw(fb),
            Mode::Gouraud => triangle
                .into_styled(GouraudStyle::new(t.vertex_colors))
                .draw(fb),
        };
    });
}

/// Pixels a scene covers, from the coverage walk (not timed).
fn pixels(scene: Scene) -> u32 {
    let screen = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
    let mut total = 0;
    scene.for_each(|t| {
        let [a, b, c] = t.vertices;
        let _ = for_each_span(&Triangle::new(a, b, c), FillRule::TopLeft, &screen, |s| {
            total += s.len;
            Ok::<(), ()>(())
        });
    });
    total
}

/// FNV-1a over the frame's raw little-endian bytes.
fn fnv1a(pixels: &[Rgb565]) -> u32 {
    let mut h: u32 = 0x811C_9DC5;
    for p in pixels {
        for b in p.into_storage().to_le_bytes() {
            h = (h ^ u32::from(b)).wrapping_mul(0x0100_0193);
        }
    }
    h
}

/// Instructions spent in `f`, counted by SysTick (24 bits: up to 83 million instructions).
fn count(syst: &mut SYST, f: impl FnOnce()) -> u32 {
    syst.clear_current();
    let start = SYST::get_current();
    f();
    let end = SYST::get_current();
    (start.wrapping_sub(end) & 0x00FF_FFFF) * INSTRUCTIONS_PER_TICK
}

#[entry]
fn main() -> ! {
    let mut core = cortex_m::Peripherals::take().unwrap();
    let syst = &mut core.SYST;
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(0x00FF_FFFF);
    syst.enable_counter();

    let mut pixels_buf = [Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
    // `FW_ONLY=mode:scene` at build time renders one combination, for profiling under QEMU.
    let only = option_env!("FW_ONLY");
    for mode in [Mode::Flat, Mode::Gouraud] {
        for scene in Scene::ALL {
            if let Some(only) = only {
                if only.split_once(':') != Some((mode.name(), scene.name())) {
                    continue;
                }
            }
            let mut fb = Framebuffer::new(&mut pixels_buf, WIDTH, HEIGHT).unwrap();
            let _ = fb.clear(Rgb565::BLACK);
            let spent = count(syst, || draw(mode, scene, &mut fb));
            let drawn = pixels(scene);
            let hundredths = u64::from(spent) * 100 / u64::from(drawn.max(1));
            hprintln!(
                "{:8} {:6} checksum={:08x} instructions={} pixels={} per_pixel={}.{:02}",
                mode.name(),
                scene.name(),
                fnv1a(fb.pixels()),
                spent,
                drawn,
                hundredths / 100,
                hundredths % 100
            );
        }
    }
    debug::exit(debug::EXIT_SUCCESS);
    loop {}
}
