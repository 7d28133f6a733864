//! Drag a triangle's vertices and watch its exact coverage, the cursor's barycentric
//! coordinates and the interpolated colour (SDL window).
//!
//! ```text
//! cargo run --release --example explorer --features sdl
//! ```
//!
//! The canvas is 64x48 real pixels, magnified 4x with a grid so each pixel shows; the white
//! lines are the exact triangle edges through the pixel sample points. Drag a vertex with the
//! mouse; F switches the fill rule (top-left / inclusive), R resets, Escape quits. The panel
//! shows, for the pixel under the cursor, where it lies (inside, on an edge or vertex,
//! outside), its barycentric weights, the colour interpolated from them and the colour the
//! rasterizer drew there.

#[path = "common/demo_window.rs"]
mod demo_window;

use embedded_graphics::{
    mono_font::{MonoTextStyle, ascii::FONT_6X10},
    pixelcolor::{Rgb565, Rgb888},
    prelude::*,
    primitives::{Line, PrimitiveStyle, Rectangle},
    text::Text,
};
use embedded_graphics_simulator::{
    OutputSettingsBuilder, SimulatorDisplay, SimulatorEvent, Window, sdl2::Keycode,
};
use fixed::types::I16F16;
use trirast::{FillRule, Framebuffer, GouraudStyle, Triangle};

/// Canvas size in real pixels, and its magnification in the window.
const CANVAS: Size = Size::new(64, 48);
const ZOOM: i32 = 4;
/// Height of the text panel below the canvas.
const PANEL: u32 = 62;
const COLORS: [Rgb565; 3] = [Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE];
const START: [Point; 3] = [Point::new(8, 6), Point::new(56, 18), Point::new(20, 42)];

fn main() {
    let (w, h) = (CANVAS.width as i32, CANVAS.height as i32);
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(
        CANVAS.width * ZOOM as u32,
        CANVAS.height * ZOOM as u32 + PANEL,
    ));
    let mut window = Window::new(
        "trirast: drag the vertices (F: fill rule, R: reset)",
        &OutputSettingsBuilder::new().scale(3).build(),
    );
    window.set_max_fps(60);
    let mut vertices = START;
    let mut rule = FillRule::TopLeft;
    let mut dragging: Option<usize> = None;
    let mut cursor = Point::new(w / 2, h / 2);
    let mut pixels = vec![Rgb565::BLACK; (w * h) as usize];
    loop {
        draw(&mut display, &mut pixels, vertices, rule, cursor);
        // With EG_SIMULATOR_DUMP set this writes the first frame and exits (a smoke test).
        window.update(&display);
        for event in window.events() {
            match event {
                e if demo_window::is_quit(&e) => return,
                SimulatorEvent::KeyDown {
                    keycode: Keycode::F,
                    ..
                } => {
                    rule = match rule {
                        FillRule::TopLeft => FillRule::Inclusive,
                        _ => FillRule::TopLeft,
                    }
                }
                SimulatorEvent::KeyDown {
                    keycode: Keycode::R,
                    ..
                } => vertices = START,
                SimulatorEvent::MouseButtonDown { point, .. } => {
                    let at = to_canvas(point);
                    dragging = (0..3)
                        .filter(|&i| {
                            let d = vertices[i] - at;
                            d.x.abs() <= 2 && d.y.abs() <= 2
                        })
                        .min_by_key(|&i| {
                            let d = vertices[i] - at;
                            d.x * d.x + d.y * d.y
                        });
                }
                SimulatorEvent::MouseButtonUp { .. } => dragging = None,
                SimulatorEvent::MouseMove { point } => {
                    cursor = to_canvas(point);
                    if let Some(i) = dragging {
                        // Vertices may leave the canvas (clipping is part of the show).
                        vertices[i] =
                            Point::new(cursor.x.clamp(-w, 2 * w), cursor.y.clamp(-h, 2 * h));
                    }
                }
                _ => {}
            }
        }
    }
}

/// The canvas pixel under a window point.
fn to_canvas(point: Point) -> Point {
    Point::new(point.x.div_euclid(ZOOM), point.y.div_euclid(ZOOM))
}

/// Centre of a canvas pixel in the magnified view.
fn magnified(p: Point) -> Point {
    p * ZOOM + Point::new(ZOOM / 2 - 1, ZOOM / 2 - 1)
}

fn draw(
    display: &mut SimulatorDisplay<Rgb888>,
    pixels: &mut [Rgb565],
    vertices: [Point; 3],
    rule: FillRule,
    cursor: Point,
) {
    let background = Rgb565::new(3, 6, 5);
    let mut canvas = Framebuffer::new(pixels, CANVAS.width, CANVAS.height).unwrap();
    canvas.clear(background).unwrap();
    let triangle = Triangle::new(vertices[0], vertices[1], vertices[2]);
    triangle
        .into_styled(GouraudStyle::new(COLORS).with_fill_rule(rule))
        .draw(&mut canvas)
        .unwrap();

    display.clear(Rgb888::new(16, 16, 16)).unwrap();
    // Each real pixel as a (ZOOM - 1)-square, leaving a one-pixel grid.
    let mut covered = 0;
    for (i, &c) in pixels.iter().enumerate() {
        let p = Point::new(
            i as i32 % CANVAS.width as i32,
            i as i32 / CANVAS.width as i32,
        );
        covered += usize::from(c != background);
        let cell = Rectangle::new(p * ZOOM, Size::new(ZOOM as u32 - 1, ZOOM as u32 - 1));
        display.fill_solid(&cell, c.into()).unwrap();
    }
    let edge = PrimitiveStyle::with_stroke(Rgb888::WHITE, 1);
    for i in 0..3 {
        Line::new(magnified(vertices[i]), magnified(vertices[(i + 1) % 3]))
            .into_styled(edge)
            .draw(display)
            .unwrap();
    }
    let outline = PrimitiveStyle::with_stroke(Rgb888::YELLOW, 1);
    Rectangle::new(
        cursor * ZOOM - Point::new(1, 1),
        Size::new(ZOOM as u32 + 1, ZOOM as u32 + 1),
    )
    .into_styled(outline)
    .draw(display)
    .unwrap();

    // The panel: what the exact query says about the cursor's pixel.
    let text = MonoTextStyle::new(&FONT_6X10, Rgb888::WHITE);
    let y0 = CANVAS.height as i32 * ZOOM + 10;
    let rule_name = match rule {
        FillRule::TopLeft => "top-left",
        _ => "inclusive",
    };
    let mut lines = vec![format!("{covered} px drawn, {rule_name} rule")];
    match triangle.barycentric(cursor) {
        None => lines.push("degenerate: nothing is drawn".to_string()),
        Some(b) => {
            let [a, bb, c] = b.weights.map(|w| w.to_num::<f64>());
            lines.push(format!(
                "pixel ({}, {}): {:?}",
                cursor.x, cursor.y, b.location
            ));
            lines.push(format!("weights {a:.3} {bb:.3} {c:.3}"));
            let channel = |f: fn(Rgb565) -> u8| {
                let v = b.interpolate(COLORS.map(|c| I16F16::from_num(f(c))));
                v.round().to_num::<i32>()
            };
            let (r, g, bl) = (channel(|c| c.r()), channel(|c| c.g()), channel(|c| c.b()));
            let drawn = canvas_pixel(pixels, cursor);
            let drawn = match drawn {
                Some(c) if triangle.covers(cursor, rule) => {
                    format!("drawn ({},{},{})", c.r(), c.g(), c.b())
                }
                _ => "not drawn".to_string(),
            };
            lines.push(format!("interpolated ({r},{g},{bl}), {drawn}"));
        }
    }
    lines.push("drag vertices; F rule, R reset, Esc".to_string());
    for (i, line) in lines.iter().enumerate() {
        Text::new(line, Point::new(4, y0 + 11 * i as i32), text)
            .draw(display)
            .unwrap();
    }
}

fn canvas_pixel(pixels: &[Rgb565], p: Point) -> Option<Rgb565> {
    let inside =
        (0..CANVAS.width as i32).contains(&p.x) && (0..CANVAS.height as i32).contains(&p.y);
    inside.then(|| pixels[(p.y * CANVAS.width as i32 + p.x) as usize])
}
