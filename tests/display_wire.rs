//! What reaches a display through real drivers, decoded as the controller applies it: through
//! `mipidsi` over SPI, every way of drawing (spans straight to the driver, a framebuffer sent as
//! one window, bands of any height) shows the full-frame render bit for bit, each sends the
//! windows it should, and a failing bus stops drawing with the bus's error; through `ssd1306`
//! over I2C, a dithered frame arrives whole in one flush.

#[path = "../examples/common/scenes.rs"]
mod scenes;
#[path = "../examples/common/wire.rs"]
mod wire;

use embedded_graphics::{
    pixelcolor::{BinaryColor, Rgb565},
    prelude::*,
};
use mipidsi::interface::SpiError;
use trirast::{
    FillRule, Framebuffer,
    band::{BandError, Bands},
    coverage::for_each_span,
};
use wire::{
    BusFailed, CASET, Controller, Gddram, Panel, RAMWR, RASET, SIDE, Wire, band_scene, panel,
    scene200, screen,
};

/// The reference: the scene drawn into a framebuffer.
fn full_frame() -> Vec<Rgb565> {
    let mut pixels = vec![Rgb565::BLACK; (SIDE * SIDE) as usize];
    let mut frame = Framebuffer::new(&mut pixels, SIDE, SIDE).unwrap();
    for (t, s) in scene200() {
        t.into_styled(s).draw(&mut frame).unwrap();
    }
    pixels
}

/// What the panel shows after `wire`, over black.
fn decoded(wire: &Wire) -> Vec<Rgb565> {
    let mut controller = Controller::new(SIDE as u16, SIDE as u16, Rgb565::BLACK);
    controller.play(wire);
    assert_eq!(controller.outside, 0, "pixels written outside the panel");
    controller.pixels
}

fn banded(
    rows: u32,
    display: &mut Panel<'_>,
) -> Result<(), BandError<SpiError<BusFailed, core::convert::Infallible>>> {
    let mut band = vec![Rgb565::BLACK; (SIDE * rows) as usize];
    Bands::new(&mut band, SIDE, rows)
        .unwrap()
        .render(&band_scene(), Rgb565::BLACK, display)
}

#[test]
fn spans_straight_to_the_driver_show_the_frame() {
    let mut buffer = [0u8; 512];
    let (mut display, recording) = panel(&mut buffer);
    for (t, s) in scene200() {
        t.into_styled(s).draw(&mut display).unwrap();
    }
    let wire = recording.borrow();
    assert!(decoded(&wire) == full_frame());
    // One window per span: as many as the spans inside the screen.
    let mut spans = 0;
    for (t, _) in scene200() {
        for_each_span(&t, FillRule::TopLeft, &screen(), |_| {
            spans += 1;
            Ok::<(), ()>(())
        })
        .unwrap();
    }
    for command in [CASET, RASET, RAMWR] {
        assert_eq!(wire.commands(command), spans);
    }
}

#[test]
fn a_framebuffer_goes_as_one_window() {
    let mut buffer = [0u8; 512];
    let (mut display, recording) = panel(&mut buffer);
    let pixels = full_frame();
    display
        .fill_contiguous(&screen(), pixels.iter().copied())
        .unwrap();
    let wire = recording.borrow();
    assert!(decoded(&wire) == pixels);
    assert_eq!(
        (
            wire.commands(CASET),
            wire.commands(RASET),
            wire.commands(RAMWR)
        ),
        (1, 1, 1)
    );
    // Eleven command and address bytes, then two bytes per pixel.
    assert_eq!(wire.bytes(), 11 + u64::from(SIDE * SIDE * 2));
}

#[test]
fn bands_of_any_height_show_the_frame_one_window_each() {
    let want = full_frame();
    for rows in [1, 8, 16, 7, SIDE] {
        let mut buffer = [0u8; 512];
        let (mut display, recording) = panel(&mut buffer);
        banded(rows, &mut display).unwrap();
        let wire = recording.borrow();
        assert!(decoded(&wire) == want, "band height {rows}");
        let bands = u64::from(SIDE.div_ceil(rows));
        for command in [CASET, RASET, RAMWR] {
            assert_eq!(wire.commands(command), bands, "band height {rows}");
        }
        assert_eq!(wire.bytes(), 11 * bands + u64::from(SIDE * SIDE * 2));
    }
}

#[test]
fn a_failing_bus_stops_drawing_with_its_error() {
    for allowed in [0, 1, 5, 40, 300] {
        // Bands: the first failing write ends the render.
        let mut buffer = [0u8; 512];
        let (mut display, recording) = panel(&mut buffer);
        recording.borrow_mut().fail_after = Some(allowed);
        let result = banded(16, &mut display);
        assert!(
            matches!(result, Err(BandError::Target(SpiError::Spi(BusFailed)))),
            "{result:?}"
        );
        assert_eq!(recording.borrow().transactions, allowed);

        // Spans straight to the driver: the triangle's draw returns the error at once.
        let mut buffer = [0u8; 512];
        let (mut display, recording) = panel(&mut buffer);
        recording.borrow_mut().fail_after = Some(allowed);
        let error = scene200()
            .into_iter()
            .find_map(|(t, s)| t.into_styled(s).draw(&mut display).err());
        assert!(matches!(error, Some(SpiError::Spi(BusFailed))));
        assert_eq!(recording.borrow().transactions, allowed);
    }
}

#[test]
fn an_oled_frame_arrives_whole_in_one_flush() {
    let (mut display, recording) = wire::oled();
    let mut pixels = [BinaryColor::Off; 128 * 64];
    let mut frame = Framebuffer::new(&mut pixels, 128, 64).unwrap();
    for (triangle, style) in wire::oled_scene() {
        triangle.into_styled(style).draw(&mut display).unwrap();
        triangle.into_styled(style).draw(&mut frame).unwrap();
    }
    display.flush().unwrap();
    let wire = recording.borrow();
    let mut memory = Gddram::new(128);
    memory.play(&wire);
    for y in 0..64u8 {
        for x in 0..128u8 {
            let want = frame.pixel(Point::new(x.into(), y.into())).unwrap();
            assert_eq!(memory.pixel(x, y), want, "({x}, {y})");
        }
    }
    // The whole memory (1,024 bytes) in 16-byte writes behind a control byte, after the
    // column and page windows (a control byte and three command bytes each).
    assert_eq!(wire.bytes(), 64 * 17 + 2 * 4);
    assert_eq!(wire.transactions, 66);
}
