//! An SSD0323 OLED controller (128 x 80 pixels of 4-bit grey in its RAM; the Pictiva panel
//! QEMU models shows the top 64 rows) as an embedded-graphics `DrawTarget`, and the scene the
//! `ssd0323` example draws on it. No allocation: the firmware, the host example and the tests
//! share this file.
//!
//! The controller's RAM is written, never read: two pixels per byte, the left one in the high
//! nibble, through a window (`0x15` columns in bytes, `0x75` rows) that data bytes fill row by
//! row. So the target takes whole byte-aligned areas (`fill_contiguous`, `fill_solid`: what
//! `band::Bands` sends, one window per band) and refuses single pixels, which it could only
//! place by knowing the neighbouring nibble.
#![allow(dead_code)]

use embedded_graphics::{
    pixelcolor::{Gray4, GrayColor},
    prelude::*,
    primitives::Rectangle,
};
use trirast::{
    GouraudStyle, Triangle,
    band::{Scene, SceneStyle},
    mesh::{Cull, MeshVertex},
};

// The includer declares `cube` (examples/common/cube.rs) beside this module.
use crate::cube;

/// Visible columns.
pub const WIDTH: u32 = 128;
/// Visible rows (the controller's RAM has 80).
pub const HEIGHT: u32 = 64;
/// Rows of the controller's RAM.
pub const RAM_ROWS: u32 = 80;

/// Set the column window: start and end column, in bytes (two pixels each).
pub const SET_COLUMNS: u8 = 0x15;
/// Set the row window: start and end row.
pub const SET_ROWS: u8 = 0x75;

/// Whether bytes on the wire are commands or display data (the D/C pin).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Mode {
    /// D/C low.
    Command,
    /// D/C high: pixels for the current window.
    Data,
}

/// What carries bytes to the controller: the SSI port and D/C pin in firmware, a recording
/// on the host.
pub trait Wire {
    /// What a transfer can fail with.
    type Error;
    /// Sends `bytes` with D/C set for `mode`.
    fn send(&mut self, mode: Mode, bytes: &[u8]) -> Result<(), Self::Error>;
}

/// Why the controller refused a drawing call.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum OledError<E> {
    /// The wire failed.
    Wire(E),
    /// The area does not start and end on a byte (even columns), or lies outside the RAM:
    /// the controller cannot be read, so it cannot merge half a byte.
    Unaligned(Rectangle),
}

/// Power-on settings: the Pictiva 128x64 panel with the rows of RAM mapped in order.
const INIT: [u8; 22] = [
    0xAE, // display off
    0x81, 0x33, // contrast
    0x86, // full current range
    0xA0, 0x52, // remap: split odd/even rows, nibbles left-high (horizontal addressing)
    0xA1, 0x00, // display start line
    0xA2, 0x00, // display offset
    0xA4, // normal display
    0xA8, 0x3F, // multiplex ratio: 64 rows
    0xB2, 0x23, // row period
    0xB3, 0xE2, // display clock
    0xBC, 0x20, // pre-charge voltage
    0xBE, 0x1B, // VCOMH
    0xAF, // display on
];

/// The controller on `W`, counting what it sends.
#[derive(Debug)]
pub struct Ssd0323<W> {
    wire: W,
    /// Windows opened so far.
    pub windows: u32,
    /// Bytes sent so far (commands and data).
    pub bytes: u32,
}

impl<W: Wire> Ssd0323<W> {
    /// Sends the power-on settings.
    pub fn new(mut wire: W) -> Result<Self, W::Error> {
        wire.send(Mode::Command, &INIT)?;
        Ok(Self {
            wire,
            windows: 0,
            bytes: INIT.len() as u32,
        })
    }

    /// The wire back.
    pub fn release(self) -> W {
        self.wire
    }

    fn send(&mut self, mode: Mode, bytes: &[u8]) -> Result<(), OledError<W::Error>> {
        self.bytes += bytes.len() as u32;
        self.wire.send(mode, bytes).map_err(OledError::Wire)
    }

    /// Opens the window `area`, whose columns must be byte-aligned and inside the RAM.
    fn window(&mut self, area: &Rectangle) -> Result<(), OledError<W::Error>> {
        let (x, y) = (area.top_left.x, area.top_left.y);
        let (w, h) = (area.size.width as i32, area.size.height as i32);
        let inside = x >= 0 && y >= 0 && x + w <= WIDTH as i32 && y + h <= RAM_ROWS as i32;
        if !inside || x % 2 != 0 || w % 2 != 0 || area.is_zero_sized() {
            return Err(OledError::Unaligned(*area));
        }
        let (first, last) = ((x / 2) as u8, ((x + w) / 2 - 1) as u8);
        let (top, bottom) = (y as u8, (y + h - 1) as u8);
        self.windows += 1;
        self.send(
            Mode::Command,
            &[SET_COLUMNS, first, last, SET_ROWS, top, bottom],
        )
    }
}

impl<W> OriginDimensions for Ssd0323<W> {
    fn size(&self) -> Size {
        Size::new(WIDTH, HEIGHT)
    }
}

impl<W: Wire> DrawTarget for Ssd0323<W> {
    type Color = Gray4;
    type Error = OledError<W::Error>;

    /// Single pixels would need the other half of their byte, which cannot be read back.
    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Gray4>>,
    {
        match pixels.into_iter().next() {
            None => Ok(()),
            Some(Pixel(at, _)) => Err(OledError::Unaligned(Rectangle::new(at, Size::new(1, 1)))),
        }
    }

    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Gray4>,
    {
        if area.is_zero_sized() {
            return Ok(());
        }
        self.window(area)?;
        // Pack pixel pairs, left in the high nibble, and send them 64 bytes at a time.
        let mut chunk = [0u8; 64];
        let mut len = 0;
        let mut colors = colors.into_iter();
        let pixels = area.size.width * area.size.height;
        for _ in 0..pixels / 2 {
            let left = colors.next().map_or(0, |c| c.luma());
            let right = colors.next().map_or(0, |c| c.luma());
            chunk[len] = (left << 4) | right;
            len += 1;
            if len == chunk.len() {
                self.send(Mode::Data, &chunk)?;
                len = 0;
            }
        }
        if len > 0 {
            self.send(Mode::Data, &chunk[..len])?;
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Gray4) -> Result<(), Self::Error> {
        self.fill_contiguous(area, core::iter::repeat(color))
    }
}

/// The screen the scene covers.
pub fn screen() -> Rectangle {
    Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT))
}

/// What is behind the scene where nothing is drawn (the gradient covers the whole screen).
pub const BACKGROUND: Gray4 = Gray4::BLACK;

/// The frame of the cube's turn the example shows (three faces in view), out of [`FRAMES`].
pub const FRAME: u32 = 12;
/// Frames in one turn of the cube.
pub const FRAMES: u32 = 96;

/// Most triangles the scene holds: two for the backdrop, at most six front faces' worth.
pub const CAPACITY: usize = 16;

/// Brightest grey of each face of the cube (front, back, right, left, top, bottom).
const FACE_SHADES: [u16; 6] = [15, 10, 12, 8, 14, 6];

/// The OLED scene, frame `frame` of `frames`: a dithered grey backdrop, then the spinning cube
/// (front faces only, depth-tested), lit per vertex with dithered Gouraud shading.
pub fn scene(frame: u32, frames: u32) -> Scene<'static, Gray4, CAPACITY> {
    let mut scene = Scene::new(screen());
    let (w, h) = (WIDTH as i32, HEIGHT as i32);
    let (top, bottom) = (Gray4::new(5), Gray4::new(0));
    let corners = [
        Point::new(0, 0),
        Point::new(w, 0),
        Point::new(w, h),
        Point::new(0, h),
    ];
    let backdrop = [
        ([corners[0], corners[1], corners[2]], [top, top, bottom]),
        ([corners[0], corners[2], corners[3]], [top, bottom, bottom]),
    ];
    for (vertices, colors) in backdrop {
        let style = GouraudStyle::new(colors).with_dither(true);
        // Capacity is enough for the whole scene.
        let [a, b, c] = vertices;
        let _ = scene.push(Triangle::new(a, b, c), SceneStyle::Gouraud(style));
    }
    let vertices = cube::vertices(frame, frames, screen());
    for (index, [a, b, c]) in cube::TRIANGLES.into_iter().enumerate() {
        let corners = [a, b, c].map(|i| vertices[usize::from(i)]);
        let [a, b, c] = corners.map(|v| v.position());
        let triangle = Triangle::new(a, b, c);
        if Cull::Clockwise.skips(triangle.orientation()) {
            continue;
        }
        // Each face its own shade, so that edges show on 16 greys; light scales it.
        let shade = FACE_SHADES[index / 2];
        let colors = corners.map(|v| Gray4::new((u16::from(v.light) * shade / 255) as u8));
        let style = GouraudStyle::new(colors).with_dither(true);
        let _ = scene.push_with_depth(
            triangle,
            corners.map(|v| v.depth()),
            SceneStyle::Gouraud(style),
        );
    }
    scene
}

/// The reference: frame [`FRAME`] of the scene drawn whole into a framebuffer, the plain
/// triangles straight and the depth-tested ones through a depth buffer (no bands).
#[cfg(not(target_os = "none"))]
pub fn render() -> Vec<Gray4> {
    use trirast::{
        Framebuffer,
        depth::{DepthBuffer, DepthTarget},
    };

    let scene = scene(FRAME, FRAMES);
    let mut pixels = vec![BACKGROUND; (WIDTH * HEIGHT) as usize];
    let mut depths = vec![u16::MAX; (WIDTH * HEIGHT) as usize];
    let mut frame = Framebuffer::new(&mut pixels, WIDTH, HEIGHT).expect("sizes match");
    let style = |t: &trirast::band::SceneTriangle<Gray4, _>| match t.style {
        SceneStyle::Gouraud(style) => style,
        _ => unreachable!("the OLED scene is Gouraud-shaded throughout"),
    };
    let (plain, tested): (Vec<_>, Vec<_>) =
        scene.triangles().iter().partition(|t| t.depths.is_none());
    for t in plain {
        let _ = t.triangle.into_styled(style(t)).draw(&mut frame);
    }
    let mut zbuffer = DepthBuffer::new(&mut depths, WIDTH, HEIGHT).expect("sizes match");
    let mut target = DepthTarget::new(&mut frame, &mut zbuffer).expect("sizes match");
    for t in tested {
        let depths = t.depths.expect("partitioned on depths");
        let _ = target.draw(&t.triangle, depths, &style(t));
    }
    pixels
}
