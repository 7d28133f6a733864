//! Breakout, drawn with trirast: a 5x16 brick wall, a paddle, a ball, five lives.
//!
//! ```text
//! cargo run --release --example breakout --features sdl        # play in an SDL window
//! cargo run --release --example breakout                       # headless: the autopilot plays
//! cargo run --release --example breakout -- --headless "serve right*20 auto*4000"
//! ```
//!
//! In the window: Left/Right or the mouse move the paddle, Space or a click serves (and starts
//! a new game when one is over), A hands the paddle to the autopilot, Escape quits.
//!
//! Headless, a script of inputs (see `parse_script` in `examples/common/breakout.rs`; the
//! default is the autopilot until the game ends) is played frame by frame; it prints every
//! life lost and the end, and writes a PNG every 600 frames and of the last frame to
//! `target/breakout/`. `tests/breakout.rs` runs scripted games to check the rules.

#[path = "common/breakout.rs"]
mod breakout;
#[cfg(feature = "sdl")]
#[path = "common/demo_window.rs"]
mod demo_window;

use std::path::Path;

use breakout::{Game, HEIGHT, State, WIDTH};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};
use trirast::Framebuffer;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let headless = args.first().is_some_and(|a| a == "--headless");
    if headless || !cfg!(feature = "sdl") {
        let script = args.get(1).map_or("auto*100000", String::as_str);
        run_headless(script);
    } else {
        #[cfg(feature = "sdl")]
        window::run();
    }
}

/// Renders the game into an `Rgb565` framebuffer and copies it to a simulator display.
fn render(game: &Game, pixels: &mut [Rgb565], display: &mut SimulatorDisplay<Rgb565>) {
    let mut framebuffer = Framebuffer::new(pixels, WIDTH as u32, HEIGHT as u32).unwrap();
    game.draw(&mut framebuffer).unwrap();
    let area = Rectangle::new(Point::zero(), Size::new(WIDTH as u32, HEIGHT as u32));
    display
        .fill_contiguous(&area, pixels.iter().copied())
        .unwrap();
}

fn run_headless(script: &str) {
    let commands = breakout::parse_script(script).unwrap_or_else(|e| {
        eprintln!("{e}");
        std::process::exit(2)
    });
    let dir = Path::new("target/breakout");
    std::fs::create_dir_all(dir).expect("cannot create target/breakout");
    let mut pixels = vec![Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
    let mut display = SimulatorDisplay::new(Size::new(WIDTH as u32, HEIGHT as u32));
    let settings = OutputSettingsBuilder::new().scale(2).build();
    let mut save = |game: &Game, name: String| {
        render(game, &mut pixels, &mut display);
        let path = dir.join(name);
        display
            .to_rgb_output_image(&settings)
            .save_png(&path)
            .expect("cannot write the PNG");
        println!("  wrote {}", path.display());
    };
    let mut game = Game::new();
    println!("headless Breakout, {} scripted frames", commands.len());
    for command in commands {
        let lives = game.lives();
        game.play(command);
        if game.lives() < lives {
            println!(
                "frame {:>6}: life lost, {} left, score {}",
                game.frames(),
                game.lives(),
                game.score()
            );
        }
        if game.frames().is_multiple_of(600) && game.state() == State::Playing {
            save(&game, format!("frame_{:06}.png", game.frames()));
        }
        if matches!(game.state(), State::Won | State::Lost) {
            break;
        }
    }
    println!(
        "end: {:?} after {} frames, score {}, {} bricks left, {} lives",
        game.state(),
        game.frames(),
        game.score(),
        game.bricks_left(),
        game.lives()
    );
    save(&game, "final.png".to_string());
}

#[cfg(feature = "sdl")]
mod window {
    use super::{demo_window, *};
    use breakout::Input;
    use embedded_graphics_simulator::{SimulatorEvent, Window, sdl2::Keycode};

    pub fn run() {
        let mut pixels = vec![Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
        let mut display = SimulatorDisplay::new(Size::new(WIDTH as u32, HEIGHT as u32));
        let mut window = Window::new(
            "trirast Breakout",
            &OutputSettingsBuilder::new().scale(3).build(),
        );
        window.set_max_fps(60);
        let mut game = Game::new();
        let (mut left, mut right, mut autopilot) = (false, false, false);
        let mut mouse: Option<i32> = None;
        loop {
            render(&game, &mut pixels, &mut display);
            // With EG_SIMULATOR_DUMP set this writes the first frame and exits (a smoke test).
            window.update(&display);
            let mut launch = false;
            for event in window.events() {
                match event {
                    e if demo_window::is_quit(&e) => return,
                    SimulatorEvent::KeyDown { keycode, .. } => match keycode {
                        Keycode::Left => (left, mouse) = (true, None),
                        Keycode::Right => (right, mouse) = (true, None),
                        Keycode::Space => launch = true,
                        Keycode::A => autopilot = !autopilot,
                        _ => {}
                    },
                    SimulatorEvent::KeyUp { keycode, .. } => match keycode {
                        Keycode::Left => left = false,
                        Keycode::Right => right = false,
                        _ => {}
                    },
                    SimulatorEvent::MouseMove { point } => mouse = Some(point.x),
                    SimulatorEvent::MouseButtonDown { .. } => launch = true,
                    _ => {}
                }
            }
            let mut input = Input {
                left,
                right,
                launch,
                paddle_centre: mouse,
            };
            if autopilot && !matches!(game.state(), State::Won | State::Lost) {
                input = game.autopilot();
            }
            game.step(input);
        }
    }
}
