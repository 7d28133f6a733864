//! What the SDL window demos share (feature `sdl`).

use embedded_graphics_simulator::{SimulatorEvent, sdl2::Keycode};

/// Closing the window or pressing Escape.
pub fn is_quit(event: &SimulatorEvent) -> bool {
    matches!(
        event,
        SimulatorEvent::Quit
            | SimulatorEvent::KeyDown {
                keycode: Keycode::Escape,
                ..
            }
    )
}
