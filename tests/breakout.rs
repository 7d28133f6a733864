//! Breakout's rules, checked by scripted games run headless (the game of
//! `examples/breakout.rs`, logic in `examples/common/breakout.rs`).

#[path = "../examples/common/breakout.rs"]
mod breakout;

use breakout::*;
use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
use trirast::Framebuffer;

fn play(game: &mut Game, script: &str) {
    for command in parse_script(script).unwrap() {
        game.play(command);
    }
}

/// The bricks still standing (`standing`) or already broken, as (row, column).
fn bricks(game: &Game, standing: bool) -> Vec<(usize, usize)> {
    (0..ROWS)
        .flat_map(|r| (0..COLUMNS).map(move |c| (r, c)))
        .filter(|&(r, c)| game.brick(r, c) == standing)
        .collect()
}

/// Keeps the paddle as far from the ball as it can, so every serve is lost.
fn dodge(game: &Game) -> Input {
    let away = if game.ball().x < WIDTH / 2 { WIDTH } else { 0 };
    Input {
        paddle_centre: Some(away),
        ..Input::default()
    }
}

#[test]
fn a_new_game_has_a_full_wall_five_lives_and_waits_for_the_serve() {
    let mut game = Game::new();
    assert_eq!(game.bricks_left(), 80);
    assert_eq!(bricks(&game, true).len(), ROWS * COLUMNS);
    assert_eq!((game.score(), game.lives()), (0, 5));
    assert_eq!(game.state(), State::Serving);
    let resting = game.ball();
    play(&mut game, "wait*500");
    assert_eq!(game.state(), State::Serving);
    assert_eq!(game.ball(), resting, "the ball waits on the paddle");
    // The ball rides on the paddle while serving.
    play(&mut game, "right*5");
    assert_eq!(game.ball().x, resting.x + 5 * PADDLE_SPEED);
    assert_eq!(game.ball().y, PADDLE_Y - BALL);
}

#[test]
fn the_paddle_stays_on_the_field() {
    let mut game = Game::new();
    play(&mut game, "left*100");
    assert_eq!(game.paddle_x(), 0);
    play(&mut game, "right*100");
    assert_eq!(game.paddle_x(), WIDTH - PADDLE_WIDTH);
    play(&mut game, "at=100");
    assert_eq!(game.paddle_x(), 100 - PADDLE_WIDTH / 2);
    play(&mut game, "at=-50");
    assert_eq!(game.paddle_x(), 0);
}

#[test]
fn the_serve_breaks_the_brick_in_its_straight_path_for_one_point() {
    // Served from the centre at (1.5, -3) px per frame, the ball's box (BALL wide) starts at
    // x0, y0 and after k frames is at x0 + 1.5k, y0 - 3k: it first reaches the bottom row
    // (bottom edge WALL_TOP + 5 * BRICK_HEIGHT) on the first k with y0 - 3k <= that - 1.
    let x0 = (WIDTH - PADDLE_WIDTH) / 2 + (PADDLE_WIDTH - BALL) / 2;
    let y0 = PADDLE_Y - BALL;
    let wall_bottom = WALL_TOP + ROWS as i32 * BRICK_HEIGHT;
    let k = (1..).find(|k| y0 - 3 * k < wall_bottom).unwrap();
    let x = x0 + 3 * k / 2;
    assert_eq!(
        x / BRICK_WIDTH,
        (x + BALL - 1) / BRICK_WIDTH,
        "one brick, by design"
    );
    let column = (x / BRICK_WIDTH) as usize;

    let mut game = Game::new();
    play(&mut game, "serve");
    assert_eq!(game.state(), State::Playing);
    play(&mut game, &format!("wait*{}", k - 1));
    assert_eq!((game.score(), game.bricks_left()), (0, 80));
    play(&mut game, "wait");
    assert!(!game.brick(ROWS - 1, column), "brick (4, {column}) broken");
    assert_eq!(bricks(&game, true).len(), 79, "only that brick");
    assert_eq!(game.score(), 1);
    assert!(game.velocity().1 > 0, "the ball bounced back down");
}

const UP: (i32, i32) = (0, -3 * 256);

#[test]
fn the_ball_breaks_exactly_the_bricks_it_touches() {
    let wall_bottom = WALL_TOP + ROWS as i32 * BRICK_HEIGHT;
    // Its box ends on the last pixel of column 0: one brick.
    let mut game = Game::with_ball(Point::new(BRICK_WIDTH - BALL, wall_bottom + 1), UP);
    game.step(Input::default());
    assert_eq!(bricks(&game, true).len(), 79);
    assert!(!game.brick(ROWS - 1, 0));
    assert_eq!(game.score(), 1);
    assert_eq!(game.velocity(), (0, 3 * 256), "bounced");
    assert_eq!(game.ball().y, wall_bottom + 1, "and did not enter the wall");
    // One pixel further right it straddles columns 0 and 1: both break.
    let mut game = Game::with_ball(Point::new(BRICK_WIDTH - BALL + 1, wall_bottom + 1), UP);
    game.step(Input::default());
    assert!(!game.brick(ROWS - 1, 0) && !game.brick(ROWS - 1, 1));
    assert_eq!((game.score(), game.bricks_left()), (2, 78));
    // Still one pixel short of the wall: nothing.
    let mut game = Game::with_ball(Point::new(40, wall_bottom + 3), UP);
    game.step(Input::default());
    assert_eq!((game.score(), game.ball().y), (0, wall_bottom));
}

#[test]
fn the_ball_bounces_off_the_ceiling_and_the_side_walls() {
    let mut game = Game::with_ball(Point::new(100, CEILING + 2), (0, -3 * 256));
    game.step(Input::default());
    assert_eq!(
        (game.ball().y, game.velocity()),
        (CEILING + 2, (0, 3 * 256))
    );
    let mut game = Game::with_ball(Point::new(100, CEILING + 3), (0, -3 * 256));
    game.step(Input::default());
    assert_eq!(game.ball().y, CEILING, "reaches the ceiling exactly");
    let mut game = Game::with_ball(Point::new(1, 150), (-2 * 256, 256));
    game.step(Input::default());
    assert_eq!((game.ball().x, game.velocity().0), (1, 2 * 256));
    let mut game = Game::with_ball(Point::new(WIDTH - BALL - 1, 150), (2 * 256, 256));
    game.step(Input::default());
    assert_eq!(
        (game.ball().x, game.velocity().0),
        (WIDTH - BALL - 1, -2 * 256)
    );
}

#[test]
fn a_missed_ball_costs_a_life_and_five_end_the_game() {
    let mut game = Game::new();
    for lives_left in (0..LIVES).rev() {
        play(&mut game, "serve");
        let mut frames = 0;
        while game.state() == State::Playing {
            let score = game.score();
            game.step(dodge(&game));
            assert!(game.score() >= score);
            frames += 1;
            assert!(frames < 10_000, "the ball never came down");
        }
        assert_eq!(game.lives(), lives_left);
        assert_eq!(game.score() + game.bricks_left(), 80);
        if lives_left > 0 {
            assert_eq!(game.state(), State::Serving);
            assert_eq!(
                game.ball().y,
                PADDLE_Y - BALL,
                "the ball is back on the paddle"
            );
        }
    }
    assert_eq!(game.state(), State::Lost);
    // Over is over: nothing moves until the player starts again.
    let over = game;
    play(&mut game, "wait*100 left*20 at=3");
    assert_eq!(game, over);
    play(&mut game, "serve");
    assert_eq!(game, Game::new());
}

#[test]
fn the_paddle_returns_the_ball_with_english() {
    let mut game = Game::new();
    play(&mut game, "serve");
    // Play on until the ball first comes down onto the paddle.
    let mut falling = false;
    for _ in 0..2_000 {
        let before = game.velocity();
        game.play(Command::Auto);
        falling |= before.1 > 0;
        if falling && before.1 > 0 && game.velocity().1 < 0 && game.ball().y == PADDLE_Y - BALL {
            let hit = game.ball().x + BALL / 2 - (game.paddle_x() + PADDLE_WIDTH / 2);
            // Off-centre to the right sends it right, to the left sends it left.
            assert_eq!(game.velocity().0.signum(), hit.signum(), "hit at {hit}");
            assert_eq!(game.lives(), LIVES);
            return;
        }
    }
    panic!("the autopilot never returned the ball");
}

#[test]
fn the_autopilot_clears_the_wall_and_wins() {
    let mut game = Game::new();
    play(&mut game, "auto*30000");
    assert_eq!(game.state(), State::Won, "after {} frames", game.frames());
    assert_eq!((game.score(), game.bricks_left()), (80, 0));
    assert!(game.lives() > 0);
    let won = game;
    play(&mut game, "wait*10 right*10");
    assert_eq!(game, won, "a finished game stays finished");
    play(&mut game, "serve");
    assert_eq!(game, Game::new());
}

#[test]
fn random_play_keeps_the_rules() {
    // A tiny LCG drives random inputs; every frame the invariants must hold.
    let mut seed = 0x2545_f491_u32;
    let mut next = move || {
        seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        seed >> 16
    };
    for _game in 0..40 {
        let mut game = Game::new();
        for _ in 0..3_000 {
            let r = next();
            let input = Input {
                left: r & 1 != 0,
                right: r & 2 != 0,
                launch: r & 0x3c == 0,
                paddle_centre: (r & 0x40 != 0).then_some((r >> 7) as i32 % 400 - 40),
            };
            let (score, lives, state) = (game.score(), game.lives(), game.state());
            game.step(input);
            if game == Game::new() {
                continue; // restarted after the end
            }
            assert!(game.score() >= score && game.lives() <= lives);
            assert_eq!(game.score() + game.bricks_left(), 80);
            assert!((0..=WIDTH - PADDLE_WIDTH).contains(&game.paddle_x()));
            let ball = game.ball();
            assert!((0..=WIDTH - BALL).contains(&ball.x), "{ball:?}");
            assert!(ball.y >= CEILING, "{ball:?}");
            if state == State::Playing && game.lives() < lives {
                assert!(matches!(game.state(), State::Serving | State::Lost));
            }
        }
    }
}

#[test]
fn broken_bricks_disappear_from_the_picture() {
    let render = |game: &Game| {
        let mut pixels = vec![Rgb565::BLACK; (WIDTH * HEIGHT) as usize];
        let mut fb = Framebuffer::new(&mut pixels, WIDTH as u32, HEIGHT as u32).unwrap();
        game.draw(&mut fb).unwrap();
        pixels
    };
    let at = |pixels: &[Rgb565], x: i32, y: i32| pixels[(y * WIDTH + x) as usize];
    let mut game = Game::new();
    let before = render(&game);
    play(&mut game, "serve wait*60");
    let after = render(&game);
    let broken = bricks(&game, false);
    assert!(!broken.is_empty());
    for (row, column) in broken {
        // The gap at x = 0 between bricks shows the background of that row.
        let y = WALL_TOP + row as i32 * BRICK_HEIGHT + BRICK_HEIGHT / 2;
        let x = column as i32 * BRICK_WIDTH + BRICK_WIDTH / 2;
        assert_ne!(at(&before, x, y), at(&before, 0, y));
        assert_eq!(at(&after, x, y), at(&after, 0, y));
    }
}
