//! The SSD0323 display target of `examples/ssd0323.rs` (the firmware that draws on QEMU's
//! emulated OLED), on the host: what it sends, decoded as the controller applies it (column and
//! row windows, two pixels per byte, left in the high nibble), shows the full-frame render for
//! every band height, with one window per band; areas it cannot write are refused before
//! anything is sent; a failing wire stops rendering with the wire's error.

#[path = "../examples/common/cube.rs"]
mod cube;
#[path = "../examples/common/ssd0323.rs"]
mod ssd0323;

use embedded_graphics::{
    pixelcolor::{Gray4, GrayColor},
    prelude::*,
    primitives::Rectangle,
};
use ssd0323::{HEIGHT, Mode, OledError, RAM_ROWS, Ssd0323, WIDTH, Wire};
use trirast::band::{BandError, Bands};

/// What went over the wire, in order; fails once `budget` bytes have been sent, if set.
#[derive(Default)]
struct Recording {
    sent: Vec<(Mode, u8)>,
    budget: Option<usize>,
}

#[derive(Debug, PartialEq)]
struct WireFailed;

impl Wire for Recording {
    type Error = WireFailed;

    fn send(&mut self, mode: Mode, bytes: &[u8]) -> Result<(), WireFailed> {
        if self
            .budget
            .is_some_and(|b| self.sent.len() + bytes.len() > b)
        {
            return Err(WireFailed);
        }
        self.sent.extend(bytes.iter().map(|&b| (mode, b)));
        Ok(())
    }
}

/// The controller's RAM after `sent`, from all zeros, per the data sheet's horizontal address
/// increment: columns of the window first, then the next row, wrapping to the window's start.
fn decode(sent: &[(Mode, u8)]) -> Vec<Gray4> {
    let mut ram = vec![0u8; 64 * RAM_ROWS as usize];
    let (mut columns, mut rows) = ((0, 63), (0, RAM_ROWS as usize - 1));
    let (mut column, mut row) = (0, 0);
    let mut command: Vec<u8> = Vec::new();
    for &(mode, byte) in sent {
        match mode {
            Mode::Data => {
                ram[row * 64 + column] = byte;
                column += 1;
                if column > columns.1 {
                    column = columns.0;
                    row = if row >= rows.1 { rows.0 } else { row + 1 };
                }
            }
            Mode::Command => {
                command.push(byte);
                let arguments = match command[0] {
                    ssd0323::SET_COLUMNS | ssd0323::SET_ROWS | 0xA8 | 0xB2 | 0xB3 | 0xBC | 0xBE => {
                        2
                    }
                    0x81 | 0xA0 | 0xA1 | 0xA2 => 1,
                    _ => 0,
                };
                if command.len() < arguments + 1 {
                    continue;
                }
                // Both window commands take a first and a last address.
                let window = || (usize::from(command[1]), usize::from(command[2]));
                match command[0] {
                    ssd0323::SET_COLUMNS => {
                        columns = window();
                        column = columns.0;
                    }
                    ssd0323::SET_ROWS => {
                        rows = window();
                        row = rows.0;
                    }
                    _ => {}
                }
                command.clear();
            }
        }
    }
    (0..(WIDTH * HEIGHT) as usize)
        .map(|i| {
            let byte = ram[i / 2];
            Gray4::new(if i % 2 == 0 { byte >> 4 } else { byte & 15 })
        })
        .collect()
}

/// Renders the scene in bands of `rows` to a recording controller.
fn render_in_bands(
    rows: u32,
    wire: Recording,
) -> (
    Result<(), BandError<OledError<WireFailed>>>,
    Ssd0323<Recording>,
) {
    let mut oled = Ssd0323::new(wire).expect("the power-on settings fit the budget");
    let scene = ssd0323::scene(ssd0323::FRAME, ssd0323::FRAMES);
    let mut pixels = vec![0u8; (WIDTH * rows) as usize];
    let mut depths = vec![0u16; (WIDTH * rows) as usize];
    let mut bands = Bands::<Gray4, u8>::new(&mut pixels, WIDTH, rows)
        .unwrap()
        .with_depth(&mut depths)
        .unwrap();
    let result = bands.render(&scene, ssd0323::BACKGROUND, &mut oled);
    (result, oled)
}

#[test]
fn every_band_height_shows_the_full_frame_with_one_window_per_band() {
    let reference = ssd0323::render();
    // The scene is not blank: a test of copying zeros would pass anything.
    assert!(reference.iter().any(|c| c.luma() > 8) && reference.iter().any(|c| c.luma() < 2));
    for rows in [1, 2, 8, 16, 64] {
        let (result, oled) = render_in_bands(rows, Recording::default());
        result.unwrap();
        let bands = HEIGHT.div_ceil(rows);
        assert_eq!(oled.windows, bands, "{rows} rows per band");
        let (windows, bytes) = (oled.windows, oled.bytes);
        let sent = oled.release().sent;
        // Power-on settings, then per band 6 window bytes and the band's pixels, 2 per byte.
        assert_eq!(bytes as usize, sent.len());
        assert_eq!(
            sent.len(),
            22 + windows as usize * 6 + (WIDTH * HEIGHT / 2) as usize
        );
        assert!(decode(&sent) == reference, "{rows} rows per band");
    }
}

#[test]
fn areas_it_cannot_write_are_refused_before_anything_is_sent() {
    let mut oled = Ssd0323::new(Recording::default()).unwrap();
    let sent_at_start = oled.bytes;
    let refused = [
        Rectangle::new(Point::new(1, 0), Size::new(4, 1)), // odd first column
        Rectangle::new(Point::new(0, 0), Size::new(3, 1)), // odd width
        Rectangle::new(Point::new(126, 0), Size::new(4, 1)), // past the right edge
        Rectangle::new(Point::new(0, 79), Size::new(2, 2)), // past the RAM's last row
        Rectangle::new(Point::new(-2, 0), Size::new(4, 1)), // left of the screen
    ];
    for area in refused {
        assert_eq!(
            oled.fill_solid(&area, Gray4::WHITE),
            Err(OledError::Unaligned(area))
        );
    }
    let pixel = Pixel(Point::new(3, 3), Gray4::WHITE);
    assert!(matches!(
        oled.draw_iter([pixel]),
        Err(OledError::Unaligned(_))
    ));
    assert_eq!(oled.draw_iter(core::iter::empty()), Ok(()));
    assert_eq!(oled.bytes, sent_at_start);
    // The whole RAM, rows the panel does not show included, is one window.
    let ram = Rectangle::new(Point::zero(), Size::new(WIDTH, RAM_ROWS));
    oled.fill_solid(&ram, Gray4::new(9)).unwrap();
    assert_eq!(oled.windows, 1);
    assert!(
        decode(&oled.release().sent)
            .iter()
            .all(|&c| c == Gray4::new(9))
    );
}

#[test]
fn a_failing_wire_stops_rendering_with_its_error() {
    let (_, whole) = render_in_bands(16, Recording::default());
    let total = whole.bytes as usize;
    for budget in [22, 100, total / 2, total - 1] {
        let wire = Recording {
            budget: Some(budget),
            ..Recording::default()
        };
        let (result, oled) = render_in_bands(16, wire);
        assert_eq!(result, Err(BandError::Target(OledError::Wire(WireFailed))));
        assert!(oled.release().sent.len() <= budget);
    }
}
