//! What reaches the wire: the benchmark's 200-triangle scene drawn to an ST7789 240x240 display
//! through the real `mipidsi` driver over a recording SPI bus, three ways, and each recording
//! decoded back into an image (as the display controller would apply it) and written as PNG.
//!
//! ```text
//! cargo run --release --example display_wire     # tables, and target/display-wire/*.png
//! ```
//!
//! - **direct**: every span straight to the driver, which opens a window (`CASET`, `RASET`,
//!   `RAMWR`) for each: no frame memory, many small transactions.
//! - **framebuffer**: the frame drawn into trirast's `Framebuffer`, then sent as one window.
//! - **bands**: `band::Bands`, 16 rows at a time, one window per band.
//!
//! Then a dithered Gouraud scene to an SSD1306 128x64 OLED through the real `ssd1306` driver in
//! buffered graphics mode over a recording I2C bus, decoded from the display memory the bytes
//! fill.

#[path = "common/scenes.rs"]
mod scenes;
#[path = "common/wire.rs"]
mod wire;

use std::path::PathBuf;

use embedded_graphics::{
    pixelcolor::{BinaryColor, Rgb565},
    prelude::*,
};
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};
use trirast::{Framebuffer, band::Bands};
use wire::{CASET, Controller, Gddram, SIDE};

/// Bytes of the driver's pixel buffer (`SpiInterface`): one SPI write per 512 bytes of pixels.
const DRIVER_BUFFER: usize = 512;
/// Rows per band.
const BAND_ROWS: u32 = 16;
/// The RP2040's fastest SPI clock.
const SPI_HZ: u64 = 62_500_000;

fn main() {
    let scene = wire::scene200();
    let dir = PathBuf::from("target/display-wire");
    std::fs::create_dir_all(&dir).expect("cannot create target/display-wire");
    println!(
        "{} Gouraud triangles (scene200) to an ST7789 {SIDE}x{SIDE} through mipidsi 0.10, {DRIVER_BUFFER}-byte driver buffer, SPI at {:.1} MHz",
        scene.len(),
        SPI_HZ as f64 / 1e6
    );
    println!(
        "| Way | pixel memory (bytes) | bytes on the wire | SPI transactions | windows | bits on the wire at 62.5 MHz |"
    );
    println!("| --- | --- | --- | --- | --- | --- |");
    let ways: [(&str, u64); 3] = [
        ("direct", 0),
        ("framebuffer", u64::from(SIDE * SIDE * 2)),
        ("bands", u64::from(SIDE * BAND_ROWS * 2)),
    ];
    for (name, memory) in ways {
        let mut buffer = [0u8; DRIVER_BUFFER];
        let (mut display, recording) = wire::panel(&mut buffer);
        match name {
            "direct" => {
                for (triangle, style) in &scene {
                    triangle.into_styled(*style).draw(&mut display).unwrap();
                }
            }
            "framebuffer" => {
                let mut pixels = vec![Rgb565::BLACK; (SIDE * SIDE) as usize];
                let mut frame = Framebuffer::new(&mut pixels, SIDE, SIDE).unwrap();
                for (triangle, style) in &scene {
                    triangle.into_styled(*style).draw(&mut frame).unwrap();
                }
                display
                    .fill_contiguous(&wire::screen(), pixels.iter().copied())
                    .unwrap();
            }
            _ => {
                let mut band = vec![Rgb565::BLACK; (SIDE * BAND_ROWS) as usize];
                Bands::new(&mut band, SIDE, BAND_ROWS)
                    .unwrap()
                    .render(&wire::band_scene(), Rgb565::BLACK, &mut display)
                    .unwrap();
            }
        }
        let wire = recording.borrow();
        let bytes = wire.bytes();
        println!(
            "| {name} | {memory} | {bytes} | {} | {} | {:.1} ms |",
            wire.transactions,
            wire.commands(CASET),
            bytes as f64 * 8.0 / SPI_HZ as f64 * 1e3
        );
        // What the panel shows, decoded from the bytes alone.
        let mut panel = Controller::new(SIDE as u16, SIDE as u16, Rgb565::BLACK);
        panel.play(&wire);
        let mut image = SimulatorDisplay::<Rgb565>::new(Size::new(SIDE, SIDE));
        for (i, c) in panel.pixels.iter().enumerate() {
            let p = Point::new((i as u32 % SIDE) as i32, (i as u32 / SIDE) as i32);
            Pixel(p, *c).draw(&mut image).unwrap();
        }
        let path = dir.join(format!("{name}.png"));
        image
            .to_rgb_output_image(&OutputSettingsBuilder::new().build())
            .save_png(&path)
            .expect("cannot write the PNG");
    }
    println!(
        "decoded images: {}/{{direct,framebuffer,bands}}.png",
        dir.display()
    );
    oled(&dir);
}

/// The OLED: one frame in the driver's buffered graphics mode (a 1 KB buffer), flushed.
fn oled(dir: &std::path::Path) {
    let (mut display, recording) = wire::oled();
    for (triangle, style) in wire::oled_scene() {
        triangle.into_styled(style).draw(&mut display).unwrap();
    }
    display.flush().unwrap();
    let wire = recording.borrow();
    // Each I2C transaction is a start, the address byte, the payload, a stop: 9 bits a byte.
    let bits = (wire.bytes() + wire.transactions) * 9;
    println!(
        "SSD1306 128x64 over I2C (ssd1306 0.10, buffered graphics mode): {} bytes in {} transactions a frame; {:.1} ms at 400 kHz, {:.1} ms at 1 MHz",
        wire.bytes(),
        wire.transactions,
        bits as f64 / 400e3 * 1e3,
        bits as f64 / 1e6 * 1e3
    );
    let mut memory = Gddram::new(128);
    memory.play(&wire);
    let mut image = SimulatorDisplay::<BinaryColor>::new(Size::new(128, 64));
    for y in 0..64u8 {
        for x in 0..128u8 {
            Pixel(Point::new(x.into(), y.into()), memory.pixel(x, y))
                .draw(&mut image)
                .unwrap();
        }
    }
    let path = dir.join("oled.png");
    image
        .to_rgb_output_image(&OutputSettingsBuilder::new().scale(2).build())
        .save_png(&path)
        .expect("cannot write the PNG");
    println!("decoded OLED image: {}", path.display());
}
