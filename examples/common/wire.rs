//! What reaches an SPI display: a recording SPI bus and data/command pin for the real
//! `mipidsi` driver, and a decoder that plays the recorded bytes into a model of the display
//! controller's memory (column and page windows, memory writes), as an ST7789 or ILI9341 would.
//! Shared by `examples/display_wire.rs` and `tests/display_wire.rs`.
#![allow(dead_code)]

use std::{cell::RefCell, convert::Infallible, rc::Rc};

use embedded_graphics::pixelcolor::{raw::RawU16, Rgb565};
use embedded_hal::{
    delay::DelayNs,
    digital::{ErrorType as PinErrorType, OutputPin},
    spi::{ErrorKind, ErrorType, Operation, SpiDevice},
};

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
