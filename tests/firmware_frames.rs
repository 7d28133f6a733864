//! The host twin of `examples/firmware.rs`: renders every mode and scene with the same code
//! (`examples/common/modes.rs`) and checks the frame checksums the firmware checks on
//! Cortex-M0 and Cortex-M4 under QEMU. Equal checksums mean bit-identical frames on all three.

#[path = "../examples/common/modes.rs"]
mod modes;
#[path = "../examples/common/scenes.rs"]
mod scenes;

use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
use modes::{
    BAND_LEN, DisplayList, FRAME_LEN, MAX_TRIANGLES, Mode, SETUP_SLOTS, TEXTURE_SIDE, Workspace,
};
use scenes::{HEIGHT, Scene, WIDTH};
use trirast::{Framebuffer, band::SetupSlot, texture::Texels};

#[test]
fn frames_match_the_firmware_checksums() {
    let texels: Vec<Rgb565> = (0..TEXTURE_SIDE * TEXTURE_SIDE)
        .map(|i| modes::texel(i, TEXTURE_SIDE))
        .collect();
    let mut depths = vec![0u16; FRAME_LEN];
    let mut band = vec![Rgb565::BLACK; BAND_LEN];
    let mut depth_band = vec![0u16; BAND_LEN];
    let screen =
        embedded_graphics::primitives::Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
    let mut list: Box<DisplayList<MAX_TRIANGLES>> = Box::new(DisplayList::new(screen));
    let setups = [SetupSlot::EMPTY; SETUP_SLOTS];
    let mut work = Workspace {
        texture: Texels::new(&texels, TEXTURE_SIDE, TEXTURE_SIDE).unwrap(),
        depths: &mut depths,
        band: &mut band,
        depth_band: &mut depth_band,
        list: &mut list,
        setups: &setups,
    };
    let mut pixels = vec![Rgb565::BLACK; FRAME_LEN];
    let mut mismatches = Vec::new();
    for mode in Mode::ALL {
        for scene in Scene::ALL {
            let mut triangles = Vec::new();
            scene.for_each(|t| triangles.push(t));
            pixels.fill(Rgb565::BLACK);
            let mut frame = Framebuffer::new(&mut pixels, WIDTH, HEIGHT).unwrap();
            modes::draw(mode, &triangles, &mut frame, &mut work);
            let sum = modes::fnv1a(&pixels);
            println!("{:<12} {:<8} checksum={sum:08x}", mode.name(), scene.name());
            if sum != modes::expected(mode, scene) {
                mismatches.push(format!("({mode:?}, Scene::{scene:?}, {sum:#010x})"));
            }
        }
    }
    assert!(
        mismatches.is_empty(),
        "checksums differ from modes::EXPECTED:\n{}",
        mismatches.join("\n")
    );
}
