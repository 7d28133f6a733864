//! The smallest useful firmware: a flat and a Gouraud triangle drawn into a RAM framebuffer,
//! whose checksum is printed over semihosting. A template for your own, and the build that
//! `benches/firmware-size.sh` measures the library's flash cost with (built once as is and
//! once with `FW_BASELINE=1`, which leaves the drawing out).
//!
//! ```text
//! cargo run --release --target thumbv6m-none-eabi --example firmware_minimal --features firmware
//! ```
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
use panic_halt as _;
use trirast::{FlatStyle, Framebuffer, GouraudStyle, Triangle};

const WIDTH: u32 = 320;
const HEIGHT: u32 = 240;

#[entry]
fn main() -> ! {
    let mut pixels = [Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
    if option_env!("FW_BASELINE").is_none() {
        // In firmware this would be your display driver's DrawTarget (mipidsi, ssd1306, ...).
        let mut display = Framebuffer::new(&mut pixels, WIDTH, HEIGHT).unwrap();
        let (a, b, c) = (Point::new(10, 10), Point::new(300, 40), Point::new(60, 220));
        let _ = Triangle::new(a, b, c)
            .into_styled(FlatStyle::new(Rgb565::CSS_ORANGE))
            .draw(&mut display);
        let colors = [Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE];
        let _ = Triangle::new(Point::new(160, 0), Point::new(319, 239), Point::new(0, 200))
            .into_styled(GouraudStyle::new(colors))
            .draw(&mut display);
    }
    let mut sum: u32 = 0x811C_9DC5;
    for p in pixels {
        for byte in p.into_storage().to_le_bytes() {
            sum = (sum ^ u32::from(byte)).wrapping_mul(0x0100_0193);
        }
    }
    hprintln!("checksum={:08x}", sum);
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
