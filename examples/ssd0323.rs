//! An emulated display controller, end to end: firmware for QEMU's `lm3s6965evb` board (a
//! Cortex-M3 whose SSI port drives an SSD0323 4-bit grey OLED) renders a scene in bands of 16
//! rows into the controller's RAM, and QEMU's own model of the controller shows it. The host
//! build of this example renders the same scene into a framebuffer and compares it, pixel for
//! pixel, with QEMU's screen dump.
//!
//! ```text
//! bash examples/ssd0323.sh   # builds, runs under QEMU, screendumps, compares: target/ssd0323/
//! ```
//!
//! The script builds this file for `thumbv7m-none-eabi` (the board has 64 KB of RAM, so it
//! moves the stack top there: see the script), runs it with the monitor on stdin, waits for
//! the firmware's "frame sent" over semihosting, asks the monitor for `screendump`, and runs
//! the host build: `cargo run --release --example ssd0323 -- target/ssd0323/screen.ppm`.
//!
//! The display target is in `examples/common/ssd0323.rs`; the registers are below. They follow
//! QEMU's model of the board (SSI0 with chip select on GPIO D0, D/C on GPIO C7); a real
//! LM3S6965 evaluation board also wants its OLED power switched on before the first command.
#![cfg_attr(target_os = "none", no_std, no_main)]

#[path = "common/cube.rs"]
mod cube;
#[path = "common/ssd0323.rs"]
mod ssd0323;

#[cfg(target_os = "none")]
mod firmware {
    use cortex_m_rt::entry;
    use cortex_m_semihosting::hprintln;
    use embedded_graphics::{pixelcolor::Gray4, prelude::*, primitives::Rectangle};
    use panic_halt as _;
    use trirast::band::Bands;

    use super::ssd0323::{self, Mode, RAM_ROWS, Ssd0323, WIDTH, Wire};
    /// Rows per band: 2 KB of pixels and 4 KB of depths.
    const BAND_ROWS: u32 = 16;

    /// System control: clock gating for the SSI port and the GPIO ports.
    const RCGC1: usize = 0x400F_E104;
    const RCGC2: usize = 0x400F_E108;
    /// GPIO ports A, C and D (PL061). A data write at `base + (mask << 2)` changes only the
    /// pins in `mask`.
    const GPIO_A: usize = 0x4000_4000;
    const GPIO_C: usize = 0x4000_6000;
    const GPIO_D: usize = 0x4000_7000;
    const GPIO_DIR: usize = 0x400;
    const GPIO_AFSEL: usize = 0x420;
    const GPIO_DEN: usize = 0x51C;
    /// The D/C pin, C7.
    const DATA_COMMAND: usize = 1 << 7;
    /// SSI0 (PL022) and its registers.
    const SSI0: usize = 0x4000_8000;
    const SSI_CR0: usize = 0x00;
    const SSI_CR1: usize = 0x04;
    const SSI_DR: usize = 0x08;
    const SSI_SR: usize = 0x0C;
    const SSI_CPSR: usize = 0x10;
    /// Status: transmit FIFO not full, receive FIFO not empty, busy.
    const SR_TNF: u32 = 1 << 1;
    const SR_RNE: u32 = 1 << 2;
    const SR_BSY: u32 = 1 << 4;

    fn write(address: usize, value: u32) {
        // SAFETY: a memory-mapped register of the LM3S6965, written with a volatile store.
        unsafe { core::ptr::write_volatile(address as *mut u32, value) }
    }

    fn read(address: usize) -> u32 {
        // SAFETY: a memory-mapped register of the LM3S6965, read with a volatile load.
        unsafe { core::ptr::read_volatile(address as *const u32) }
    }

    fn set_bits(address: usize, bits: u32) {
        write(address, read(address) | bits);
    }

    /// SSI0 in SPI mode 3, 8-bit frames, with D/C on C7 and the OLED selected.
    struct Ssi {
        mode: Option<Mode>,
    }

    impl Ssi {
        fn new() -> Self {
            set_bits(RCGC1, 1 << 4); // SSI0
            set_bits(RCGC2, 0b1101); // GPIO A, C, D
            // A2 clock, A3 frame select, A5 transmit: the SSI's own pins.
            set_bits(GPIO_A + GPIO_AFSEL, 0b10_1100);
            set_bits(GPIO_A + GPIO_DEN, 0b10_1100);
            // C7 (D/C) and D0 (chip select, high) are outputs.
            set_bits(GPIO_C + GPIO_DIR, DATA_COMMAND as u32);
            set_bits(GPIO_C + GPIO_DEN, DATA_COMMAND as u32);
            set_bits(GPIO_D + GPIO_DIR, 1);
            set_bits(GPIO_D + GPIO_DEN, 1);
            write(GPIO_D + (1 << 2), 1);
            write(SSI0 + SSI_CR1, 0); // disabled while configured
            write(SSI0 + SSI_CPSR, 2);
            write(SSI0 + SSI_CR0, 0xC7); // SPO = SPH = 1 (mode 3), Motorola, 8 bits
            write(SSI0 + SSI_CR1, 1 << 1); // enabled, master
            Self { mode: None }
        }

        /// Waits until every byte has left, emptying what came back.
        fn flush(&self) {
            while read(SSI0 + SSI_SR) & SR_BSY != 0 {}
            while read(SSI0 + SSI_SR) & SR_RNE != 0 {
                read(SSI0 + SSI_DR);
            }
        }
    }

    impl Wire for Ssi {
        type Error = core::convert::Infallible;

        fn send(&mut self, mode: Mode, bytes: &[u8]) -> Result<(), Self::Error> {
            if self.mode != Some(mode) {
                // D/C may change only once the bytes of the other kind are out.
                self.flush();
                let level = if mode == Mode::Data { DATA_COMMAND } else { 0 };
                write(GPIO_C + (DATA_COMMAND << 2), level as u32);
                self.mode = Some(mode);
            }
            for &byte in bytes {
                while read(SSI0 + SSI_SR) & SR_TNF == 0 {}
                write(SSI0 + SSI_DR, u32::from(byte));
                // The receive FIFO fills as we send; a full one stalls the port.
                while read(SSI0 + SSI_SR) & SR_RNE != 0 {
                    read(SSI0 + SSI_DR);
                }
            }
            Ok(())
        }
    }

    #[entry]
    fn main() -> ! {
        let Ok(mut oled) = Ssd0323::new(Ssi::new());
        // The whole RAM, the rows the panel does not show included, starts black.
        let ram = Rectangle::new(Point::zero(), Size::new(WIDTH, RAM_ROWS));
        let _ = oled.fill_solid(&ram, Gray4::BLACK);
        let scene = ssd0323::scene(ssd0323::FRAME, ssd0323::FRAMES);
        let mut pixels = [0u8; (WIDTH * BAND_ROWS) as usize];
        let mut depths = [0u16; (WIDTH * BAND_ROWS) as usize];
        let bands = Bands::<Gray4, u8>::new(&mut pixels, WIDTH, BAND_ROWS)
            .and_then(|bands| bands.with_depth(&mut depths));
        let (windows, bytes) = (oled.windows, oled.bytes);
        let result = match bands {
            Ok(mut bands) => bands.render(&scene, ssd0323::BACKGROUND, &mut oled),
            Err(e) => Err(trirast::band::BandError::Setup(e)),
        };
        match result {
            Ok(()) => hprintln!(
                "ssd0323: frame sent: {} triangles in bands of {} rows, {} windows, {} bytes",
                scene.triangles().len(),
                BAND_ROWS,
                oled.windows - windows,
                oled.bytes - bytes
            ),
            Err(e) => hprintln!("ssd0323: error: {:?}", e),
        }
        // Stay up: the monitor takes the screen dump, then quits.
        loop {
            cortex_m::asm::wfi();
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {
    host::main();
}

#[cfg(not(target_os = "none"))]
mod host {
    use std::path::Path;

    use embedded_graphics::{pixelcolor::Gray4, prelude::*};
    use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};

    use super::ssd0323::{self, HEIGHT, WIDTH};
    /// QEMU draws each controller pixel as a 4 x 4 block.
    const MAGNIFY: usize = 4;

    /// What a binary PPM (`P6`, 8 bits) of QEMU's magnified screen shows, per controller pixel:
    /// `None` where a 4 x 4 block is not one grey of the 16.
    fn read_screendump(path: &Path) -> Result<Vec<Option<Gray4>>, String> {
        let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
        // Header: "P6", width, height, maxval, each followed by one whitespace byte.
        let mut fields = Vec::new();
        let mut at = 0;
        while fields.len() < 4 {
            while at < bytes.len() && bytes[at].is_ascii_whitespace() {
                at += 1;
            }
            let start = at;
            while at < bytes.len() && !bytes[at].is_ascii_whitespace() {
                at += 1;
            }
            fields.push(String::from_utf8_lossy(&bytes[start..at]).into_owned());
        }
        let pixels = &bytes[at + 1..];
        let (w, h) = (WIDTH as usize * MAGNIFY, HEIGHT as usize * MAGNIFY);
        let expected = ["P6".to_string(), w.to_string(), h.to_string(), "255".into()];
        if fields != expected || pixels.len() != w * h * 3 {
            return Err(format!(
                "{}: expected a {w}x{h} P6 image, found header {fields:?} and {} bytes",
                path.display(),
                pixels.len()
            ));
        }
        let rgb = |x: usize, y: usize| {
            let i = (y * w + x) * 3;
            [pixels[i], pixels[i + 1], pixels[i + 2]]
        };
        let mut shown = Vec::with_capacity((WIDTH * HEIGHT) as usize);
        for y in 0..HEIGHT as usize {
            for x in 0..WIDTH as usize {
                let first = rgb(x * MAGNIFY, y * MAGNIFY);
                let uniform = (0..MAGNIFY * MAGNIFY)
                    .all(|k| rgb(x * MAGNIFY + k % MAGNIFY, y * MAGNIFY + k / MAGNIFY) == first);
                // QEMU shows level l as grey l * 17 (0x00, 0x11, ... 0xFF).
                let grey = first[0];
                let level = (uniform && first == [grey; 3] && grey % 17 == 0)
                    .then(|| Gray4::new(grey / 17));
                shown.push(level);
            }
        }
        Ok(shown)
    }

    fn save_png(pixels: &[Gray4], path: &Path) {
        let mut display = SimulatorDisplay::<Gray4>::new(Size::new(WIDTH, HEIGHT));
        for (i, &color) in pixels.iter().enumerate() {
            let at = Point::new((i as u32 % WIDTH) as i32, (i as u32 / WIDTH) as i32);
            let _ = Pixel(at, color).draw(&mut display);
        }
        let settings = OutputSettingsBuilder::new().scale(MAGNIFY as u32).build();
        display
            .to_rgb_output_image(&settings)
            .save_png(path)
            .unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
    }

    pub fn main() {
        let dir = Path::new("target/ssd0323");
        std::fs::create_dir_all(dir).expect("cannot create target/ssd0323");
        let host = ssd0323::render();
        save_png(&host, &dir.join("host.png"));
        let Some(dump) = std::env::args().nth(1) else {
            println!(
                "host render: target/ssd0323/host.png (run examples/ssd0323.sh to compare it with QEMU's display)"
            );
            return;
        };
        let shown = read_screendump(Path::new(&dump)).unwrap_or_else(|e| {
            eprintln!("ssd0323: {e}");
            std::process::exit(1)
        });
        let screen: Vec<Gray4> = shown.iter().map(|p| p.unwrap_or(Gray4::WHITE)).collect();
        save_png(&screen, &dir.join("screen.png"));
        let differing: Vec<usize> = (0..host.len())
            .filter(|&i| shown[i] != Some(host[i]))
            .collect();
        if let Some(&first) = differing.first() {
            let (x, y) = (first as u32 % WIDTH, first as u32 / WIDTH);
            eprintln!(
                "ssd0323: {} of {} pixels differ from the host render; first at ({x}, {y}): QEMU shows {:?}, host drew {:?}",
                differing.len(),
                host.len(),
                shown[first],
                host[first]
            );
            std::process::exit(1);
        }
        println!(
            "ssd0323: QEMU's display shows the host render exactly ({} of {} pixels, 4-bit grey); target/ssd0323/{{screen,host}}.png",
            host.len(),
            host.len()
        );
    }
}
