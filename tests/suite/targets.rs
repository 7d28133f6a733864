//! How drawing talks to targets: one `fill_solid` per covered row, errors passed through, and
//! the same pixels on the simulator's display as in the crate's framebuffer.

use crate::common;

use common::{CountingTarget, Failed, FailingTarget, Offset, Rng};
use embedded_graphics::{
    pixelcolor::{BinaryColor, Rgb565},
    prelude::*,
    primitives::Rectangle,
};
use embedded_graphics_simulator::SimulatorDisplay;
use trirast::{FlatStyle, Framebuffer, Triangle};

#[test]
fn one_fill_solid_per_row() {
    let window = Rectangle::new(Point::new(0, 0), Size::new(64, 64));
    let mut target = Offset(CountingTarget::new(window));
    let t = Triangle::new(Point::new(3, 2), Point::new(60, 20), Point::new(10, 50));
    t.into_styled(FlatStyle::new(BinaryColor::On))
        .draw(&mut target)
        .unwrap();
    let calls = &target.0.fill_solid_calls;
    // Rows 3..50: the apex row 2 holds only the vertex, which lies on the (excluded) right edge.
    assert_eq!(calls.len(), 47);
    for (row, rect) in (3..).zip(calls) {
        assert_eq!(rect.top_left.y, row);
        assert_eq!(rect.size.height, 1);
        assert!(rect.size.width >= 1);
    }
    assert_eq!(target.0.draw_iter_calls + target.0.fill_contiguous_calls, 0);
}

#[test]
fn target_errors_stop_drawing_and_propagate() {
    let t = Triangle::new(Point::new(0, 0), Point::new(30, 5), Point::new(5, 30));
    for fail_at in 1..5 {
        let mut target = FailingTarget::<Rgb565>::new(Size::new(32, 32), fail_at);
        let result = t.into_styled(FlatStyle::new(Rgb565::RED)).draw(&mut target);
        assert_eq!(result, Err(Failed(fail_at)));
        assert_eq!(target.calls, fail_at, "no call after the error");
    }
    let mut target = FailingTarget::<Rgb565>::new(Size::new(32, 32), 1000);
    assert_eq!(
        t.into_styled(FlatStyle::new(Rgb565::RED)).draw(&mut target),
        Ok(())
    );
}

#[test]
fn simulator_display_and_framebuffer_agree() {
    let mut rng = Rng(42);
    let mut sim = SimulatorDisplay::<Rgb565>::new(Size::new(96, 64));
    let mut pixels = vec![Rgb565::BLACK; 96 * 64];
    let mut fb = Framebuffer::new(&mut pixels, 96, 64).unwrap();
    for i in 0..300 {
        let p = |rng: &mut Rng| Point::new(rng.range(-40, 136), rng.range(-40, 104));
        let t = Triangle::new(p(&mut rng), p(&mut rng), p(&mut rng));
        let color = Rgb565::new((i % 32) as u8, (i * 7 % 64) as u8, (i * 3 % 32) as u8);
        t.into_styled(FlatStyle::new(color)).draw(&mut sim).unwrap();
        t.into_styled(FlatStyle::new(color)).draw(&mut fb).unwrap();
    }
    let mut differing = 0;
    for y in 0..64 {
        for x in 0..96 {
            let p = Point::new(x, y);
            if Some(sim.get_pixel(p)) != fb.pixel(p) {
                differing += 1;
            }
        }
    }
    assert_eq!(differing, 0);
    assert!(
        fb.pixels().iter().filter(|&&c| c != Rgb565::BLACK).count() > 96 * 64 / 2,
        "scene drew little"
    );
}

#[test]
fn raw_framebuffer_matches_typed_framebuffer() {
    let t = Triangle::new(Point::new(-5, 3), Point::new(40, -2), Point::new(17, 33));
    let mut typed = [Rgb565::BLACK; 32 * 32];
    let mut raw = [0u16; 32 * 32];
    {
        let mut fb = Framebuffer::new(&mut typed, 32, 32).unwrap();
        t.into_styled(FlatStyle::new(Rgb565::new(20, 40, 10)))
            .draw(&mut fb)
            .unwrap();
    }
    {
        let mut fb: Framebuffer<Rgb565, u16> = Framebuffer::new(&mut raw, 32, 32).unwrap();
        t.into_styled(FlatStyle::new(Rgb565::new(20, 40, 10)))
            .draw(&mut fb)
            .unwrap();
    }
    let expected: Vec<u16> = typed.iter().map(|c| c.into_storage()).collect();
    assert_eq!(raw.to_vec(), expected);
    assert!(raw.iter().any(|&v| v != 0));
}
