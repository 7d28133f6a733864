//! Firmware for emulated Cortex-M (QEMU's MPS2 boards): renders the benchmark scenes into a RAM
//! framebuffer with every drawing mode (flat, Gouraud, Gouraud with depth, nearest and
//! bilinear textures, 16-row bands with a depth band, with and without set-ups kept between
//! bands, ...), checks each frame's checksum against
//! the host's (`examples/common/modes.rs`, checked on x86-64 by `tests/firmware_frames.rs`),
//! prints the instructions per drawn pixel and per triangle, and exits with success only if
//! every frame matches.
//!
//! ```text
//! cargo run --profile measure --target thumbv6m-none-eabi --example firmware --features firmware
//! ../shared/embedded/xcargo thumbv6m-none-eabi run --profile measure --example firmware --features firmware
//! ```
//!
//! The `measure` profile (one codegen unit) is the one the published figures use. Set at build
//! time, `FW_ONLY=mode:scene` renders one combination (for profiling) and `FW_MODES=flat,gouraud`
//! builds in only the modes named (the rest compiled out: a smaller firmware, as
//! `benches/firmware-size.sh` measures for the six modes its 64 KB budget was set for).
//! Instruction counts come from SysTick under `qemu -icount shift=3`, where one tick is five
//! instructions: exact to five instructions per measured frame, and the same on every run.
//! Only drawing is counted: the scene's triangles are generated before, and the frame cleared
//! (what that costs is printed first, for comparing full frames with bands, which clear theirs).
#![no_std]
#![no_main]

#[path = "common/modes.rs"]
mod modes;
#[path = "common/scenes.rs"]
mod scenes;
#[path = "common/systick.rs"]
mod systick;

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
use heapless::Vec;
use modes::{
    BAND_LEN, DisplayList, FRAME_LEN, MAX_TRIANGLES, Mode, SETUP_SLOTS, TEXTURE_SIDE, Workspace,
};
use panic_halt as _;
use scenes::{HEIGHT, Scene, SceneTriangle, WIDTH};
use trirast::{Framebuffer, band::SetupSlot, texture::Texels};

/// A buffer made over sizes this program chose, which always match: a mismatch stops it
/// without `unwrap`, whose message would link the error's `Debug` formatting (about 1 KB of
/// flash that no caller of the library needs).
fn sized<T>(made: Result<T, trirast::Error>) -> T {
    match made {
        Ok(value) => value,
        Err(_) => panic!("buffer sizes"),
    }
}

/// `text` left-aligned in `width` columns, written without `Formatter::pad` (whose character
/// counting is about 1.6 KB of flash).
struct Padded(&'static str, usize);

impl core::fmt::Display for Padded {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.0)?;
        for _ in self.0.len()..self.1 {
            f.write_str(" ")?;
        }
        Ok(())
    }
}

/// A value aligned to 8 bytes.
#[repr(C, align(8))]
struct Aligned<T>(T);

#[entry]
fn main() -> ! {
    let mut core = cortex_m::Peripherals::take().unwrap();
    systick::start(&mut core.SYST);

    // All of it on the stack (QEMU's boards have 4 MiB of RAM): the frame and depth buffer
    // (150 KB each), a 5,000-triangle scene and its display list for the band mode. The
    // buffers word-aligned whatever the stack frame holds: fills and blends of two pixels a
    // word take a different path otherwise, and a change elsewhere in the program moved a
    // mode's count by up to 4.6% (translucent flat on Cortex-M0).
    let mut pixels = Aligned([Rgb565::BLACK; FRAME_LEN]);
    let mut depths = Aligned([0u16; FRAME_LEN]);
    let mut band = Aligned([Rgb565::BLACK; BAND_LEN]);
    let mut depth_band = Aligned([0u16; BAND_LEN]);
    let mut texels = Aligned([Rgb565::BLACK; (TEXTURE_SIDE * TEXTURE_SIDE) as usize]);
    for (i, t) in texels.0.iter_mut().enumerate() {
        *t = modes::texel(i as u32, TEXTURE_SIDE);
    }
    let screen = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
    let mut list: DisplayList<MAX_TRIANGLES> = DisplayList::new(screen);
    let setups = [SetupSlot::EMPTY; SETUP_SLOTS];
    let mut work = Workspace {
        texture: sized(Texels::new(&texels.0, TEXTURE_SIDE, TEXTURE_SIDE)),
        depths: &mut depths.0,
        band: &mut band.0,
        depth_band: &mut depth_band.0,
        list: &mut list,
        setups: &setups,
    };
    let mut triangles: Vec<SceneTriangle, MAX_TRIANGLES> = Vec::new();

    // `FW_ONLY=mode:scene` at build time renders one combination, for profiling under QEMU.
    let only = option_env!("FW_ONLY");
    let mut failures = 0;
    hprintln!(
        "trirast firmware: {}x{} Rgb565, instructions counted by SysTick",
        WIDTH,
        HEIGHT
    );
    // What clearing the whole frame costs, which the modes below do before counting: a band
    // renderer clears each band to the background inside its count, so a full frame compares
    // with it only with this added.
    let cleared = {
        let mut frame = sized(Framebuffer::new(&mut pixels.0, WIDTH, HEIGHT));
        systick::count(|| {
            let _ = frame.clear(core::hint::black_box(Rgb565::BLACK));
        })
    };
    hprintln!(
        "frame clear (Framebuffer::clear) instructions={}",
        systick::Decimal(cleared)
    );
    for mode in Mode::ALL {
        if !mode.built() {
            continue;
        }
        for scene in Scene::ALL {
            if let Some(only) = only {
                if only.split_once(':') != Some((mode.name(), scene.name())) {
                    continue;
                }
            }
            triangles.clear();
            scene.for_each(|t| {
                let _ = triangles.push(t);
            });
            let drawn = modes::covered_pixels(mode, &triangles);
            pixels.0.fill(Rgb565::BLACK);
            let mut frame = sized(Framebuffer::new(&mut pixels.0, WIDTH, HEIGHT));
            let spent = systick::count(|| modes::draw(mode, &triangles, &mut frame, &mut work));
            let sum = modes::fnv1a(&pixels.0);
            let verdict = if sum == modes::expected(mode, scene) {
                "ok"
            } else {
                failures += 1;
                "MISMATCH"
            };
            hprintln!(
                "{} {} checksum={:08x} {} instructions={} pixels={} triangles={} per_pixel={} per_triangle={}",
                Padded(mode.name(), 12),
                Padded(scene.name(), 8),
                sum,
                Padded(verdict, 0),
                systick::Decimal(spent),
                drawn,
                triangles.len(),
                systick::Ratio(spent, u64::from(drawn)),
                systick::Ratio(spent, triangles.len() as u64)
            );
        }
    }
    if failures == 0 {
        hprintln!("all frames match the host");
        debug::exit(debug::EXIT_SUCCESS);
    } else {
        hprintln!("{} frames differ from the host", failures);
        debug::exit(debug::EXIT_FAILURE);
    }
    loop {
        cortex_m::asm::wfi();
    }
}
