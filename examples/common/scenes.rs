//! Seeded, deterministic benchmark and demo scenes at 320x240 (shared by the examples).
#![allow(dead_code)]

use embedded_graphics::{pixelcolor::Rgb565, prelude::*};

/// Screen size of every scene.
pub const WIDTH: u32 = 320;
/// Screen size of every scene.
pub const HEIGHT: u32 = 240;

/// A triangle with a flat colour and per-vertex colours (later modes use both).
#[derive(Copy, Clone, Debug)]
pub struct SceneTriangle {
    pub vertices: [Point; 3],
    pub color: Rgb565,
    pub vertex_colors: [Rgb565; 3],
}

/// splitmix64: tiny, fast, and the same on every platform.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `lo..=hi`.
    pub fn range(&mut self, lo: i32, hi: i32) -> i32 {
        let span = (i64::from(hi) - i64::from(lo) + 1) as u64;
        (i64::from(lo) + (self.next_u64() % span) as i64) as i32
    }

    pub fn color(&mut self) -> Rgb565 {
        let v = self.next_u64();
        Rgb565::new(
            (v & 31) as u8,
            ((v >> 8) & 63) as u8,
            ((v >> 16) & 31) as u8,
        )
    }
}

fn triangle(rng: &mut Rng, vertices: [Point; 3]) -> SceneTriangle {
    SceneTriangle {
        vertices,
        color: rng.color(),
        vertex_colors: [rng.color(), rng.color(), rng.color()],
    }
}

/// The scenes, by name.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Scene {
    /// 40 triangles of thousands of pixels each.
    Big,
    /// 5,000 triangles of about six pixels each.
    Small,
    /// A watertight 2,000-triangle mesh covering the whole screen exactly once.
    Mesh,
}

impl Scene {
    pub const ALL: [Scene; 3] = [Scene::Big, Scene::Small, Scene::Mesh];

    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "big" => Some(Scene::Big),
            "small" => Some(Scene::Small),
            "mesh" => Some(Scene::Mesh),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Scene::Big => "big",
            Scene::Small => "small",
            Scene::Mesh => "mesh",
        }
    }

    pub fn build(self) -> Vec<SceneTriangle> {
        match self {
            Scene::Big => big(),
            Scene::Small => small(),
            Scene::Mesh => mesh(40, 25),
        }
    }
}

fn big() -> Vec<SceneTriangle> {
    let mut rng = Rng(0xB16);
    (0..40)
        .map(|_| {
            let c = Point::new(rng.range(40, 280), rng.range(30, 210));
            let mut p = || Point::new(c.x + rng.range(-140, 140), c.y + rng.range(-110, 110));
            let v = [p(), p(), p()];
            triangle(&mut rng, v)
        })
        .collect()
}

fn small() -> Vec<SceneTriangle> {
    let mut rng = Rng(0x5A11);
    (0..5000)
        .map(|_| {
            let p = Point::new(
                rng.range(0, WIDTH as i32 - 5),
                rng.range(0, HEIGHT as i32 - 5),
            );
            let v = [
                p,
                p + Point::new(rng.range(3, 4), rng.range(0, 1)),
                p + Point::new(rng.range(0, 1), rng.range(3, 4)),
            ];
            triangle(&mut rng, v)
        })
        .collect()
}

/// A jittered `nx` x `ny` grid, each cell split along a random diagonal; border points slide
/// only along the border, so the union is exactly the screen.
pub fn mesh(nx: i32, ny: i32) -> Vec<SceneTriangle> {
    let mut rng = Rng(0x3E54);
    let (w, h) = (WIDTH as i32, HEIGHT as i32);
    let mut pts = Vec::new();
    for j in 0..=ny {
        for i in 0..=nx {
            let mut x = w * i / nx;
            let mut y = h * j / ny;
            if i != 0 && i != nx {
                x += rng.range(-(w / nx) / 4, (w / nx) / 4);
            }
            if j != 0 && j != ny {
                y += rng.range(-(h / ny) / 4, (h / ny) / 4);
            }
            pts.push(Point::new(x, y));
        }
    }
    let at = |i: i32, j: i32| pts[(j * (nx + 1) + i) as usize];
    let mut out = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if rng.range(0, 1) == 0 {
                out.push(triangle(&mut rng, [a, b, c]));
                out.push(triangle(&mut rng, [a, c, d]));
            } else {
                out.push(triangle(&mut rng, [a, b, d]));
                out.push(triangle(&mut rng, [b, c, d]));
            }
        }
    }
    out
}
