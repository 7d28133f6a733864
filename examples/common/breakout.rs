//! Breakout: the game logic and its drawing, shared by `examples/breakout.rs` (SDL window or
//! headless) and `tests/breakout.rs` (scripted games checking the rules).
//!
//! Integer only and deterministic: positions are in 1/256 pixel, one `step` is one frame, so a
//! script of inputs always plays the same game.

#![allow(dead_code)] // Each includer uses a different part.

use embedded_graphics::{
    mono_font::{MonoTextStyle, ascii::FONT_6X10},
    pixelcolor::Rgb565,
    prelude::*,
    text::{Alignment, Text},
};
use trirast::{GouraudStyle, Triangle};

/// Playfield size in pixels.
pub const WIDTH: i32 = 320;
/// Playfield height in pixels.
pub const HEIGHT: i32 = 240;
/// Brick wall: rows and columns.
pub const ROWS: usize = 5;
/// Bricks per row.
pub const COLUMNS: usize = 16;
/// Brick size in pixels (the wall spans the playfield's width).
pub const BRICK_WIDTH: i32 = WIDTH / COLUMNS as i32;
/// Brick height in pixels.
pub const BRICK_HEIGHT: i32 = 10;
/// Top of the wall; the score line sits above it.
pub const WALL_TOP: i32 = 40;
/// The ball bounces off this line (below the score line).
pub const CEILING: i32 = 14;
/// Paddle size and height above the bottom.
pub const PADDLE_WIDTH: i32 = 44;
/// Paddle thickness in pixels.
pub const PADDLE_HEIGHT: i32 = 6;
/// Top of the paddle.
pub const PADDLE_Y: i32 = HEIGHT - 18;
/// Paddle speed in pixels per frame (keyboard).
pub const PADDLE_SPEED: i32 = 6;
/// The ball is a square of this side (drawn as an octagon).
pub const BALL: i32 = 6;
/// Lives at the start.
pub const LIVES: u8 = 5;
/// Sub-pixel units per pixel.
const SUB: i32 = 256;
/// Serve velocity, in 1/256 pixel per frame.
const SERVE: (i32, i32) = (SUB * 3 / 2, -SUB * 3);
/// Largest horizontal speed after a paddle hit: steeper than 45 degrees, so the ball never
/// moves more than its own size in one frame on either axis.
const MAX_VX: i32 = SUB * 7 / 2;

/// One frame of player input.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Input {
    /// Move the paddle left.
    pub left: bool,
    /// Move the paddle right.
    pub right: bool,
    /// Serve the ball (or start a new game once this one is over).
    pub launch: bool,
    /// Put the paddle's centre here (mouse control); overrides left and right.
    pub paddle_centre: Option<i32>,
}

/// Where the game is.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum State {
    /// The ball rests on the paddle until the player serves.
    Serving,
    /// The ball is in play.
    Playing,
    /// Every brick is broken.
    Won,
    /// No lives left.
    Lost,
}

/// The whole game state: a few dozen bytes, `Copy`.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Game {
    /// One bit per standing brick, bit `c` of row `r` is column `c`.
    bricks: [u16; ROWS],
    /// Left edge of the paddle, pixels.
    paddle_x: i32,
    /// Top-left corner of the ball, 1/256 pixel.
    ball: (i32, i32),
    /// Ball velocity, 1/256 pixel per frame.
    velocity: (i32, i32),
    score: u32,
    lives: u8,
    state: State,
    frames: u32,
}

impl Default for Game {
    fn default() -> Self {
        Self::new()
    }
}

impl Game {
    /// A new game: full wall, five lives, ball on the centred paddle.
    pub fn new() -> Self {
        let mut game = Self {
            bricks: [u16::MAX; ROWS],
            paddle_x: (WIDTH - PADDLE_WIDTH) / 2,
            ball: (0, 0),
            velocity: (0, 0),
            score: 0,
            lives: LIVES,
            state: State::Serving,
            frames: 0,
        };
        game.rest_ball_on_paddle();
        game
    }

    /// A new game with the ball already in play at `position` (its top-left corner, pixels)
    /// with `velocity` (1/256 pixel per frame): for tests and replays of a situation.
    pub fn with_ball(position: Point, velocity: (i32, i32)) -> Self {
        Self {
            ball: (position.x * SUB, position.y * SUB),
            velocity,
            state: State::Playing,
            ..Self::new()
        }
    }

    /// Points: one per broken brick.
    pub fn score(&self) -> u32 {
        self.score
    }

    /// Lives left.
    pub fn lives(&self) -> u8 {
        self.lives
    }

    /// Where the game is.
    pub fn state(&self) -> State {
        self.state
    }

    /// Frames stepped since this game started.
    pub fn frames(&self) -> u32 {
        self.frames
    }

    /// Whether the brick in `row`, `column` still stands.
    pub fn brick(&self, row: usize, column: usize) -> bool {
        self.bricks[row] & (1 << column) != 0
    }

    /// Bricks still standing.
    pub fn bricks_left(&self) -> u32 {
        self.bricks.iter().map(|r| r.count_ones()).sum()
    }

    /// The ball's top-left corner in whole pixels.
    pub fn ball(&self) -> Point {
        Point::new(self.ball.0 / SUB, self.ball.1 / SUB)
    }

    /// The ball's velocity in 1/256 pixel per frame.
    pub fn velocity(&self) -> (i32, i32) {
        self.velocity
    }

    /// Left edge of the paddle in pixels.
    pub fn paddle_x(&self) -> i32 {
        self.paddle_x
    }

    /// Advances one frame.
    pub fn step(&mut self, input: Input) {
        match self.state {
            State::Won | State::Lost => {
                if input.launch {
                    *self = Self::new();
                }
                return;
            }
            State::Serving | State::Playing => {}
        }
        self.frames += 1;
        self.move_paddle(input);
        match self.state {
            State::Serving if input.launch => {
                self.state = State::Playing;
                self.velocity = SERVE;
            }
            State::Serving => self.rest_ball_on_paddle(),
            _ => self.move_ball(),
        }
    }

    /// What a decent player would press this frame: serve, then keep the paddle under the
    /// ball, hitting it off-centre by an amount that changes as bricks fall so the ball
    /// does not repeat one path forever.
    pub fn autopilot(&self) -> Input {
        match self.state {
            State::Serving => {
                return Input {
                    launch: true,
                    ..Input::default()
                };
            }
            State::Won | State::Lost => return Input::default(),
            State::Playing => {}
        }
        let aim = ((self.score * 7 + self.frames / 97) % 7) as i32 * 5 - 15;
        let target = self.ball.0 / SUB + BALL / 2 - aim;
        let centre = self.paddle_x + PADDLE_WIDTH / 2;
        Input {
            left: target < centre - 2,
            right: target > centre + 2,
            ..Input::default()
        }
    }

    fn rest_ball_on_paddle(&mut self) {
        self.velocity = (0, 0);
        self.ball = (
            (self.paddle_x + (PADDLE_WIDTH - BALL) / 2) * SUB,
            (PADDLE_Y - BALL) * SUB,
        );
    }

    fn move_paddle(&mut self, input: Input) {
        let x = match input.paddle_centre {
            Some(centre) => centre - PADDLE_WIDTH / 2,
            None => self.paddle_x + PADDLE_SPEED * (i32::from(input.right) - i32::from(input.left)),
        };
        self.paddle_x = x.clamp(0, WIDTH - PADDLE_WIDTH);
    }

    /// Moves the ball one axis at a time: a hit on the x move reverses vx, one on the y move
    /// reverses vy, and every brick the ball overlaps breaks (corner hits may take two).
    fn move_ball(&mut self) {
        // Horizontal.
        let (vx, vy) = self.velocity;
        self.ball.0 += vx;
        // A wall is checked first: bricks break only if the ball is still on the field.
        if self.ball.0 < 0 || self.ball.0 > (WIDTH - BALL) * SUB || self.break_bricks() {
            self.ball.0 -= vx;
            self.velocity.0 = -vx;
        }
        // Vertical.
        let bottom_before = self.ball.1 / SUB + BALL;
        self.ball.1 += vy;
        if self.ball.1 < CEILING * SUB || self.break_bricks() {
            self.ball.1 -= vy;
            self.velocity.1 = -vy;
        } else if vy > 0 && bottom_before <= PADDLE_Y && self.ball_overlaps_paddle() {
            self.ball.1 = (PADDLE_Y - BALL) * SUB;
            self.velocity.1 = -vy;
            // English: the farther from the centre, the flatter the bounce.
            let offset = (self.ball.0 + BALL * SUB / 2) - (self.paddle_x + PADDLE_WIDTH / 2) * SUB;
            self.velocity.0 = (offset * 3 / (PADDLE_WIDTH / 2)).clamp(-MAX_VX, MAX_VX);
        }
        if self.ball.1 >= HEIGHT * SUB {
            self.lives -= 1;
            if self.lives == 0 {
                self.state = State::Lost;
            } else {
                self.state = State::Serving;
                self.rest_ball_on_paddle();
            }
        }
        if self.bricks_left() == 0 {
            self.state = State::Won;
        }
    }

    fn ball_overlaps_paddle(&self) -> bool {
        let (x, y) = (self.ball.0 / SUB, self.ball.1 / SUB);
        x + BALL > self.paddle_x
            && x < self.paddle_x + PADDLE_WIDTH
            && y + BALL > PADDLE_Y
            && y < PADDLE_Y + PADDLE_HEIGHT
    }

    /// Breaks every standing brick the ball overlaps; true if there was one.
    fn break_bricks(&mut self) -> bool {
        let (x, y) = (self.ball.0 / SUB, self.ball.1 / SUB);
        let rows = (y - WALL_TOP).div_euclid(BRICK_HEIGHT)
            ..=(y + BALL - 1 - WALL_TOP).div_euclid(BRICK_HEIGHT);
        let columns = x.div_euclid(BRICK_WIDTH)..=(x + BALL - 1).div_euclid(BRICK_WIDTH);
        let mut hit = false;
        for row in rows.filter(|r| (0..ROWS as i32).contains(r)) {
            for column in columns.clone().filter(|c| (0..COLUMNS as i32).contains(c)) {
                let bit = 1u16 << column;
                if self.bricks[row as usize] & bit != 0 {
                    self.bricks[row as usize] &= !bit;
                    self.score += 1;
                    hit = true;
                }
            }
        }
        hit
    }

    /// Draws the frame with trirast: Gouraud background, bricks and paddle (two triangles per
    /// rectangle), an octagonal ball, and the score line in embedded-graphics text.
    pub fn draw<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = Rgb565>,
    {
        let p = Point::new;
        let (w, h) = (WIDTH, HEIGHT);
        let (top, bottom) = (Rgb565::new(2, 6, 10), Rgb565::new(6, 4, 14));
        rectangle(target, p(0, 0), p(w, h), [top, top, bottom, bottom])?;
        for (row, &[bright, dark]) in BRICK_COLORS.iter().enumerate() {
            for column in 0..COLUMNS {
                if self.brick(row, column) {
                    let x = column as i32 * BRICK_WIDTH;
                    let y = WALL_TOP + row as i32 * BRICK_HEIGHT;
                    rectangle(
                        target,
                        p(x + 1, y + 1),
                        p(x + BRICK_WIDTH - 1, y + BRICK_HEIGHT - 1),
                        [bright, bright, dark, dark],
                    )?;
                }
            }
        }
        let (light, shade) = (Rgb565::new(28, 58, 31), Rgb565::new(10, 24, 16));
        rectangle(
            target,
            p(self.paddle_x, PADDLE_Y),
            p(self.paddle_x + PADDLE_WIDTH, PADDLE_Y + PADDLE_HEIGHT),
            [light, light, shade, shade],
        )?;
        self.draw_ball(target)?;
        let text = MonoTextStyle::new(&FONT_6X10, Rgb565::WHITE);
        let status = format!("SCORE {:<4} LIVES {}", self.score, self.lives);
        Text::new(&status, p(4, 10), text).draw(target)?;
        let banner = match self.state {
            State::Serving => "SPACE or click to serve",
            State::Playing => "",
            State::Won => "YOU WIN! SPACE for a new game",
            State::Lost => "GAME OVER. SPACE for a new game",
        };
        Text::with_alignment(banner, p(w / 2, 150), text, Alignment::Center).draw(target)?;
        Ok(())
    }

    fn draw_ball<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = Rgb565>,
    {
        // Centre at twice the resolution would need sub-pixel vertices; the crate's vertices
        // are integers, so the octagon sits on the ball box's pixel grid.
        let Point { x, y } = self.ball();
        let c = Point::new(x + BALL / 2, y + BALL / 2);
        let r = BALL / 2 + 1;
        let d = r * 2 / 3;
        let rim = [
            (r, 0),
            (d, d),
            (0, r),
            (-d, d),
            (-r, 0),
            (-d, -d),
            (0, -r),
            (d, -d),
        ]
        .map(|(dx, dy)| c + Point::new(dx, dy));
        for i in 0..rim.len() {
            Triangle::new(c, rim[i], rim[(i + 1) % rim.len()])
                .into_styled(GouraudStyle::new([
                    Rgb565::WHITE,
                    Rgb565::new(20, 44, 24),
                    Rgb565::new(20, 44, 24),
                ]))
                .draw(target)?;
        }
        Ok(())
    }
}

/// Each row's bright (top) and dark (bottom) colour.
const BRICK_COLORS: [[Rgb565; 2]; ROWS] = [
    [Rgb565::new(31, 20, 20), Rgb565::new(20, 4, 4)],
    [Rgb565::new(31, 44, 10), Rgb565::new(22, 24, 0)],
    [Rgb565::new(31, 60, 10), Rgb565::new(20, 40, 0)],
    [Rgb565::new(12, 58, 12), Rgb565::new(2, 36, 4)],
    [Rgb565::new(12, 40, 31), Rgb565::new(2, 16, 22)],
];

/// A rectangle covering `[top_left, bottom_right)` as two Gouraud triangles; the top-left rule
/// makes the shared diagonal neither a gap nor drawn twice. Colours: top left, top right,
/// bottom left, bottom right.
fn rectangle<D>(
    target: &mut D,
    top_left: Point,
    bottom_right: Point,
    [tl, tr, bl, br]: [Rgb565; 4],
) -> Result<(), D::Error>
where
    D: DrawTarget<Color = Rgb565>,
{
    let (a, b) = (top_left, bottom_right);
    let (top_right, bottom_left) = (Point::new(b.x, a.y), Point::new(a.x, b.y));
    Triangle::new(a, top_right, b)
        .into_styled(GouraudStyle::new([tl, tr, br]))
        .draw(target)?;
    Triangle::new(a, b, bottom_left)
        .into_styled(GouraudStyle::new([tl, br, bl]))
        .draw(target)
}

/// One scripted command: an input held for some frames, or the autopilot.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Command {
    /// Press these buttons for one frame.
    Press(Input),
    /// Let `Game::autopilot` choose this frame's input.
    Auto,
}

/// Parses a script of whitespace-separated words, each optionally repeated with `*N`:
/// `serve`, `left`, `right`, `wait` (no input), `auto` (autopilot), `at=X` (paddle centre at
/// X, as the mouse does). Example: `"serve right*10 wait*200 auto*5000"`.
pub fn parse_script(script: &str) -> Result<Vec<Command>, String> {
    let mut commands = Vec::new();
    for word in script.split_whitespace() {
        let (name, count) = match word.split_once('*') {
            Some((name, n)) => (
                name,
                n.parse::<usize>()
                    .map_err(|_| format!("bad count in {word:?}"))?,
            ),
            None => (word, 1),
        };
        let mut input = Input::default();
        let command = match name {
            "serve" => {
                input.launch = true;
                Command::Press(input)
            }
            "left" => {
                input.left = true;
                Command::Press(input)
            }
            "right" => {
                input.right = true;
                Command::Press(input)
            }
            "wait" => Command::Press(input),
            "auto" => Command::Auto,
            _ => match name.strip_prefix("at=").map(str::parse::<i32>) {
                Some(Ok(x)) => {
                    input.paddle_centre = Some(x);
                    Command::Press(input)
                }
                _ => return Err(format!("unknown script word {word:?}")),
            },
        };
        commands.extend(std::iter::repeat_n(command, count));
    }
    Ok(commands)
}

impl Game {
    /// Plays one scripted command.
    pub fn play(&mut self, command: Command) {
        let input = match command {
            Command::Press(input) => input,
            Command::Auto => self.autopilot(),
        };
        self.step(input);
    }
}
