//! What reaches a display: a recording SPI bus and data/command pin for the real `mipidsi`
//! driver and a recording I2C bus for the real `ssd1306` driver, and decoders that play the
//! recorded bytes into models of the controllers' memories: an ST7789's (column and page
//! windows, memory writes of `Rgb565`) and an SSD1306's (1-bit pages, horizontal addressing).
//! Shared by `examples/display_wire.rs` and `tests/display_wire.rs`, which both also include
//! `examples/common/scenes.rs` as `scenes`.
#![allow(dead_code)]

use std::{cell::RefCell, convert::Infallible, rc::Rc};

use embedded_graphics::{
    pixelcolor::{BinaryColor, Rgb565, raw::RawU16},
    prelude::{Point, Size},
    primitives::Rectangle,
};
use embedded_hal::{
    delay::DelayNs,
    digital::{ErrorType as PinErrorType, OutputPin},
    i2c::{self, I2c},
    spi::{ErrorKind, ErrorType, Operation, SpiDevice},
};

/// Side of the ST7789 panel the SPI examples draw to.
pub const SIDE: u32 = 240;

/// The panel's screen.
pub fn screen() -> Rectangle {
    Rectangle::new(Point::zero(), Size::new(SIDE, SIDE))
}

/// An ST7789 `SIDE` x `SIDE` through the real `mipidsi` driver over a recording bus.
pub type Panel<'b> = mipidsi::Display<
    mipidsi::interface::SpiInterface<'b, RecordingSpi, DcPin>,
    mipidsi::models::ST7789,
    mipidsi::NoResetPin,
>;

/// An initialised [`Panel`] with `buffer` as the driver's pixel buffer, and its recording,
/// cleared after the initialisation so that it holds the frame only.
pub fn panel(buffer: &mut [u8]) -> (Panel<'_>, Recording) {
    let recording = Rc::new(RefCell::new(Wire::default()));
    let interface = mipidsi::interface::SpiInterface::new(
        RecordingSpi(recording.clone()),
        DcPin(recording.clone()),
        buffer,
    );
    let display = mipidsi::Builder::new(mipidsi::models::ST7789, interface)
        .display_size(SIDE as u16, SIDE as u16)
        .init(&mut NoDelay)
        .expect("the recording bus does not fail");
    *recording.borrow_mut() = Wire::default();
    (display, recording)
}

/// The SPI scene: the benchmark's `scene200`, Gouraud-shaded, in drawing order.
pub fn scene200() -> Vec<(trirast::Triangle, trirast::GouraudStyle<Rgb565>)> {
    let mut out = Vec::new();
    crate::scenes::Scene::Scene200.for_each(|t| {
        let [a, b, c] = t.vertices;
        out.push((
            trirast::Triangle::new(a, b, c),
            trirast::GouraudStyle::new(t.vertex_colors),
        ));
    });
    out
}

/// [`scene200`] as a band scene on [`screen`].
pub fn band_scene() -> Box<trirast::band::Scene<'static, Rgb565, 256>> {
    let mut scene = Box::new(trirast::band::Scene::new(screen()));
    for (triangle, style) in scene200() {
        scene
            .push(triangle, trirast::band::SceneStyle::Gouraud(style))
            .expect("256 triangles fit");
    }
    scene
}

/// Column address set, page address set, memory write (MIPI DCS).
pub const CASET: u8 = 0x2A;
pub const RASET: u8 = 0x2B;
pub const RAMWR: u8 = 0x2C;

/// Everything sent: each chip-select transaction's bytes, with the data/command line's level.
#[derive(Default, Debug)]
pub struct Wire {
    /// `(data, bytes)` per write: `data` false for a command byte.
    pub writes: Vec<(bool, Vec<u8>)>,
    /// Chip-select transactions (one per `SpiDevice` call).
    pub transactions: u64,
    /// The data/command line: high for data.
    dc_high: bool,
    /// Transactions still allowed before the bus fails (`None`: never).
    pub fail_after: Option<u64>,
}

impl Wire {
    /// Bytes sent, commands and data.
    pub fn bytes(&self) -> u64 {
        self.writes.iter().map(|(_, b)| b.len() as u64).sum()
    }

    /// How many times command `code` was sent.
    pub fn commands(&self, code: u8) -> u64 {
        self.writes
            .iter()
            .filter(|(data, bytes)| !data && bytes.first() == Some(&code))
            .count() as u64
    }
}

/// A shared recording.
pub type Recording = Rc<RefCell<Wire>>;

/// An SPI device (bus plus chip select) that records every write.
pub struct RecordingSpi(pub Recording);

/// The bus error of [`RecordingSpi`] once its allowance of transactions is spent.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BusFailed;

impl embedded_hal::spi::Error for BusFailed {
    fn kind(&self) -> ErrorKind {
        ErrorKind::Other
    }
}

impl ErrorType for RecordingSpi {
    type Error = BusFailed;
}

impl SpiDevice for RecordingSpi {
    fn transaction(&mut self, operations: &mut [Operation<'_, u8>]) -> Result<(), BusFailed> {
        let mut wire = self.0.borrow_mut();
        if let Some(left) = wire.fail_after.as_mut() {
            if *left == 0 {
                return Err(BusFailed);
            }
            *left -= 1;
        }
        wire.transactions += 1;
        let data = wire.dc_high;
        for op in operations {
            if let Operation::Write(bytes) = op {
                wire.writes.push((data, bytes.to_vec()));
            }
        }
        Ok(())
    }
}

/// The data/command pin, recorded with the bus.
pub struct DcPin(pub Recording);

impl PinErrorType for DcPin {
    type Error = Infallible;
}

impl OutputPin for DcPin {
    fn set_low(&mut self) -> Result<(), Infallible> {
        self.0.borrow_mut().dc_high = false;
        Ok(())
    }

    fn set_high(&mut self) -> Result<(), Infallible> {
        self.0.borrow_mut().dc_high = true;
        Ok(())
    }
}

/// Delays that take no time (the recording has no clock).
pub struct NoDelay;

impl DelayNs for NoDelay {
    fn delay_ns(&mut self, _ns: u32) {}
}

/// The display controller's frame memory, played from a recording: `CASET` and `RASET` set the
/// window, `RAMWR` starts writing at its top-left corner, each two data bytes (big-endian
/// `Rgb565`) fill the next pixel, left to right, then down, wrapping inside the window.
/// Other commands (initialisation) change nothing here.
pub struct Controller {
    pub width: u16,
    pub height: u16,
    pub pixels: Vec<Rgb565>,
    columns: (u16, u16),
    rows: (u16, u16),
    cursor: (u16, u16),
    command: u8,
    args: Vec<u8>,
    /// Pixels written outside the panel (a driver bug if not zero).
    pub outside: u64,
}

impl Controller {
    /// A `width` x `height` panel, black.
    pub fn new(width: u16, height: u16, background: Rgb565) -> Self {
        Self {
            width,
            height,
            pixels: vec![background; usize::from(width) * usize::from(height)],
            columns: (0, width - 1),
            rows: (0, height - 1),
            cursor: (0, 0),
            command: 0,
            args: Vec::new(),
            outside: 0,
        }
    }

    /// Plays `wire` into the frame memory.
    pub fn play(&mut self, wire: &Wire) {
        for (data, bytes) in &wire.writes {
            if *data {
                for &b in bytes {
                    self.data(b);
                }
            } else {
                for &b in bytes {
                    self.command = b;
                    self.args.clear();
                    if b == RAMWR {
                        self.cursor = (self.columns.0, self.rows.0);
                    }
                }
            }
        }
    }

    fn data(&mut self, byte: u8) {
        self.args.push(byte);
        let word = |a: &[u8], i: usize| u16::from_be_bytes([a[i], a[i + 1]]);
        match self.command {
            CASET if self.args.len() == 4 => {
                self.columns = (word(&self.args, 0), word(&self.args, 2))
            }
            RASET if self.args.len() == 4 => self.rows = (word(&self.args, 0), word(&self.args, 2)),
            RAMWR if self.args.len() == 2 => {
                let color = Rgb565::from(RawU16::new(word(&self.args, 0)));
                self.args.clear();
                let (x, y) = self.cursor;
                if x < self.width && y < self.height {
                    self.pixels[usize::from(y) * usize::from(self.width) + usize::from(x)] = color;
                } else {
                    self.outside += 1;
                }
                self.cursor = if x >= self.columns.1 {
                    let y = if y >= self.rows.1 { self.rows.0 } else { y + 1 };
                    (self.columns.0, y)
                } else {
                    (x + 1, y)
                };
            }
            _ => {}
        }
    }
}

/// An I2C bus that records every write (the first byte of each is the SSD1306's control byte:
/// `0x00` before a command, `0x40` before data).
pub struct RecordingI2c(pub Recording);

impl i2c::Error for BusFailed {
    fn kind(&self) -> i2c::ErrorKind {
        i2c::ErrorKind::Other
    }
}

impl i2c::ErrorType for RecordingI2c {
    type Error = BusFailed;
}

impl I2c for RecordingI2c {
    fn transaction(
        &mut self,
        _address: u8,
        operations: &mut [i2c::Operation<'_>],
    ) -> Result<(), BusFailed> {
        let mut wire = self.0.borrow_mut();
        if let Some(left) = wire.fail_after.as_mut() {
            if *left == 0 {
                return Err(BusFailed);
            }
            *left -= 1;
        }
        wire.transactions += 1;
        for op in operations {
            if let i2c::Operation::Write(bytes) = op {
                let data = bytes.first() == Some(&0x40);
                wire.writes.push((data, bytes.to_vec()));
            }
        }
        Ok(())
    }
}

/// An SSD1306's display memory (`width` columns, 8 pages of 8 rows, one bit per pixel, the top
/// row in bit 0), played from a recording in horizontal addressing mode: `0x21` and `0x22` set
/// the column and page windows and move the pointer to their start, each data byte fills one
/// column of one page, left to right, then the next page. The segment and COM remapping the
/// driver sets only orient this memory on the glass; it is decoded as the driver's image.
pub struct Gddram {
    pub width: u8,
    pub pages: Vec<u8>,
    columns: (u8, u8),
    page_window: (u8, u8),
    cursor: (u8, u8),
}

impl Gddram {
    /// A blank `width` x 64 memory.
    pub fn new(width: u8) -> Self {
        Self {
            width,
            pages: vec![0; usize::from(width) * 8],
            columns: (0, width - 1),
            page_window: (0, 7),
            cursor: (0, 0),
        }
    }

    /// Plays `wire` (writes of an I2C recording) into the memory.
    pub fn play(&mut self, wire: &Wire) {
        for (data, bytes) in &wire.writes {
            let payload = &bytes[1..];
            if *data {
                for &b in payload {
                    self.write(b);
                }
            } else {
                // Each command write holds one command and its arguments.
                match payload {
                    [0x21, start, end] => {
                        self.columns = (*start, *end);
                        self.cursor.0 = *start;
                    }
                    [0x22, start, end] => {
                        self.page_window = (start & 7, end & 7);
                        self.cursor.1 = start & 7;
                    }
                    _ => {}
                }
            }
        }
    }

    fn write(&mut self, byte: u8) {
        let (column, page) = self.cursor;
        if column < self.width {
            self.pages[usize::from(page) * usize::from(self.width) + usize::from(column)] = byte;
        }
        self.cursor = if column >= self.columns.1 {
            let page = if page >= self.page_window.1 {
                self.page_window.0
            } else {
                page + 1
            };
            (self.columns.0, page)
        } else {
            (column + 1, page)
        };
    }

    /// The pixel at column `x`, row `y`.
    pub fn pixel(&self, x: u8, y: u8) -> BinaryColor {
        let byte = self.pages[usize::from(y / 8) * usize::from(self.width) + usize::from(x)];
        if byte >> (y % 8) & 1 == 1 {
            BinaryColor::On
        } else {
            BinaryColor::Off
        }
    }
}

/// An SSD1306 128 x 64 through the real `ssd1306` driver in buffered graphics mode over a
/// recording I2C bus.
pub type Oled = ssd1306::Ssd1306<
    ssd1306::prelude::I2CInterface<RecordingI2c>,
    ssd1306::size::DisplaySize128x64,
    ssd1306::mode::BufferedGraphicsMode<ssd1306::size::DisplaySize128x64>,
>;

/// An initialised [`Oled`] and its recording, cleared after the initialisation.
pub fn oled() -> (Oled, Recording) {
    use ssd1306::prelude::*;
    let recording = Rc::new(RefCell::new(Wire::default()));
    let interface = ssd1306::I2CDisplayInterface::new(RecordingI2c(recording.clone()));
    let mut display = ssd1306::Ssd1306::new(interface, DisplaySize128x64, DisplayRotation::Rotate0)
        .into_buffered_graphics_mode();
    display.init().expect("the recording bus does not fail");
    *recording.borrow_mut() = Wire::default();
    (display, recording)
}

/// The OLED scene: a dithered fade across a 128 x 64 panel under a fan of dithered Gouraud
/// triangles (a gauge), as `(triangle, style)` pairs in drawing order.
pub fn oled_scene() -> Vec<(trirast::Triangle, trirast::GouraudStyle<BinaryColor>)> {
    use embedded_graphics::prelude::Point;
    use trirast::{GouraudStyle, Triangle};
    let (on, off) = (BinaryColor::On, BinaryColor::Off);
    let p = Point::new;
    let mut scene = vec![
        (
            Triangle::new(p(0, 0), p(128, 0), p(0, 64)),
            GouraudStyle::new([off, off, on]).with_dither(true),
        ),
        (
            Triangle::new(p(128, 0), p(128, 64), p(0, 64)),
            GouraudStyle::new([off, on, on]).with_dither(true),
        ),
    ];
    // Rim points of a half circle of radius 30 around (64, 44), from a table of integer sines.
    let rim = [
        (-30, 0),
        (-29, -9),
        (-24, -18),
        (-18, -24),
        (-9, -29),
        (0, -30),
        (9, -29),
        (18, -24),
        (24, -18),
        (29, -9),
        (30, 0),
    ];
    let center = p(64, 44);
    for (k, pair) in rim.windows(2).enumerate() {
        let (a, b) = (pair[0], pair[1]);
        let colors = if k % 2 == 0 {
            [on, off, on]
        } else {
            [off, on, off]
        };
        scene.push((
            Triangle::new(center, center + p(a.0, a.1), center + p(b.0, b.1)),
            GouraudStyle::new(colors).with_dither(true),
        ));
    }
    scene
}
