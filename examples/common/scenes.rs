//! Seeded, deterministic benchmark and demo scenes at 320x240, generated without allocation so
//! that the firmware example renders the very same triangles as the host.
#![allow(dead_code)]

use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};

/// Screen width of every scene.
pub const WIDTH: u32 = 320;
/// Screen height of every scene.
pub const HEIGHT: u32 = 240;

/// A triangle with a flat colour, per-vertex colours and texture coordinates (modes use what
/// they need).
#[derive(Copy, Clone, Debug)]
pub struct SceneTriangle {
    pub vertices: [Point; 3],
    pub color: Rgb565,
    pub vertex_colors: [Rgb565; 3],
    /// [`stretched_coordinates`], computed with the scene: its divisions are the benchmark's,
    /// not drawing. Raw `I16F16` bits, so that the scenes need no fixed-point crate.
    pub coordinates: [[i32; 2]; 3],
    /// [`subpixel_vertices`]: the sub-pixel modes' vertices, raw `I24F8` bits.
    pub subpixel: [[i32; 2]; 3],
}

/// splitmix64: tiny, fast, and the same on every platform.
pub struct Rng(pub u64);

/// `x % m`, for `m > 0`: below 2^16 in 32-bit divisions by 16-bit digits, so that Cortex-M0
/// firmware built with these scenes does not link the 64-bit library division for them. Out of
/// line: one copy.
#[inline(never)]
fn remainder(x: u64, m: u64) -> u64 {
    match u32::try_from(m) {
        Ok(m @ 1..=0xFFFF) => {
            let high = (x >> 32) as u32 % m;
            let middle = ((high << 16) | (x >> 16) as u32 & 0xFFFF) % m;
            u64::from(((middle << 16) | x as u32 & 0xFFFF) % m)
        }
        _ => x % m,
    }
}

impl Rng {
    /// Out of line: inlined into each scene it was about 2 KB of the Cortex-M0 firmware (its
    /// 64-bit multiplies are library calls there), harness code that no user's firmware has.
    #[inline(never)]
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `lo..=hi` (up to a negligible bias).
    pub fn range(&mut self, lo: i32, hi: i32) -> i32 {
        let span = (i64::from(hi) - i64::from(lo) + 1) as u64;
        (i64::from(lo) + remainder(self.next_u64(), span) as i64) as i32
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
        coordinates: stretched_coordinates(vertices),
        subpixel: subpixel_vertices(vertices),
    }
}

/// Each vertex moved by a fraction of a pixel in each axis, from a hash of its coordinates
/// (the same vertex always moves alike, so meshes stay meshes), as raw `I24F8` bits: computed
/// with the scene, as a projection would give them, not counted as drawing.
pub fn subpixel_vertices(vertices: [Point; 3]) -> [[i32; 2]; 3] {
    vertices.map(|p| {
        let hash = (p.x as u32).wrapping_mul(0x9E37_79B1) ^ (p.y as u32).wrapping_mul(0x85EB_CA77);
        let hash = hash ^ (hash >> 15);
        let fraction = |bits: u32| (bits & 0xFF) as i32;
        [p.x * 256 + fraction(hash), p.y * 256 + fraction(hash >> 8)]
    })
}

/// Texture coordinates stretching the texture's texel centres 0..=63 over the triangle's
/// bounding box, as raw `I16F16` bits.
pub fn stretched_coordinates(vertices: [Point; 3]) -> [[i32; 2]; 3] {
    let xs = vertices.map(|p| p.x);
    let ys = vertices.map(|p| p.y);
    let (x0, x1) = (xs.iter().min().unwrap(), xs.iter().max().unwrap());
    let (y0, y1) = (ys.iter().min().unwrap(), ys.iter().max().unwrap());
    let along = |t: i32, t0: i32, t1: i32| (((t - t0) * 63) << 16) / (t1 - t0).max(1);
    vertices.map(|p| [along(p.x, *x0, *x1), along(p.y, *y0, *y1)])
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
    /// 200 overlapping triangles of a few hundred to a few thousand pixels each, as a 3D
    /// scene of small objects gives (the band-rendering benchmark).
    Scene200,
    /// 3,000 triangles of a doubled area of 1 or 2 (half-pixel and one-pixel triangles,
    /// slivers among them), their vertices in every order: the smallest set-ups' edge cases,
    /// where the area's reciprocal is largest.
    Tiny,
}

impl Scene {
    pub const ALL: [Scene; 5] = [
        Scene::Big,
        Scene::Small,
        Scene::Mesh,
        Scene::Scene200,
        Scene::Tiny,
    ];

    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "big" => Some(Scene::Big),
            "small" => Some(Scene::Small),
            "mesh" => Some(Scene::Mesh),
            "scene200" => Some(Scene::Scene200),
            "tiny" => Some(Scene::Tiny),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Scene::Big => "big",
            Scene::Small => "small",
            Scene::Mesh => "mesh",
            Scene::Scene200 => "scene200",
            Scene::Tiny => "tiny",
        }
    }

    /// Calls `f` with every triangle of the scene, in drawing order.
    pub fn for_each(self, f: impl FnMut(SceneTriangle)) {
        match self {
            Scene::Big => big(f),
            Scene::Small => small(f),
            Scene::Mesh => mesh(40, 25, f),
            Scene::Scene200 => scene200(f),
            Scene::Tiny => tiny(f),
        }
    }
}

fn big(mut f: impl FnMut(SceneTriangle)) {
    let mut rng = Rng(0xB16);
    for _ in 0..40 {
        let c = Point::new(rng.range(40, 280), rng.range(30, 210));
        let mut p = || Point::new(c.x + rng.range(-140, 140), c.y + rng.range(-110, 110));
        let v = [p(), p(), p()];
        f(triangle(&mut rng, v));
    }
}

fn scene200(mut f: impl FnMut(SceneTriangle)) {
    let mut rng = Rng(0x200);
    for _ in 0..200 {
        let c = Point::new(rng.range(0, WIDTH as i32), rng.range(0, HEIGHT as i32));
        let mut p = || Point::new(c.x + rng.range(-45, 45), c.y + rng.range(-45, 45));
        let v = [p(), p(), p()];
        f(triangle(&mut rng, v));
    }
}

fn small(mut f: impl FnMut(SceneTriangle)) {
    let mut rng = Rng(0x5A11);
    for _ in 0..5000 {
        let p = Point::new(
            rng.range(0, WIDTH as i32 - 5),
            rng.range(0, HEIGHT as i32 - 5),
        );
        let v = [
            p,
            p + Point::new(rng.range(3, 4), rng.range(0, 1)),
            p + Point::new(rng.range(0, 1), rng.range(3, 4)),
        ];
        f(triangle(&mut rng, v));
    }
}

fn tiny(mut f: impl FnMut(SceneTriangle)) {
    let mut rng = Rng(0x71E);
    for _ in 0..3000 {
        let p = Point::new(
            rng.range(4, WIDTH as i32 - 5),
            rng.range(4, HEIGHT as i32 - 5),
        );
        // (0, 0), (w, 0), (k, 1): a doubled area of w, a sliver when k is far from 0.
        let (w, k) = (rng.range(1, 2), rng.range(-3, 3));
        let (sx, sy) = (2 * rng.range(0, 1) - 1, 2 * rng.range(0, 1) - 1);
        let corner = |x: i32, y: i32| p + Point::new(sx * x, sy * y);
        let v = [corner(0, 0), corner(w, 0), corner(k, 1)];
        let first = rng.range(0, 2) as usize;
        f(triangle(
            &mut rng,
            [v[first], v[(first + 1) % 3], v[(first + 2) % 3]],
        ));
    }
}

/// Grid point (i, j) of an `nx` x `ny` mesh over the screen: inner points jittered by a hash of
/// their position (so any point can be computed alone), border points sliding only along the
/// border, so the union of the mesh is exactly the screen.
fn mesh_point(nx: i32, ny: i32, i: i32, j: i32) -> Point {
    let (w, h) = (WIDTH as i32, HEIGHT as i32);
    let mut hash = Rng(0x3E54 ^ ((i as u64) << 32) ^ j as u64);
    let mut x = w * i / nx;
    let mut y = h * j / ny;
    if i != 0 && i != nx {
        x += hash.range(-(w / nx) / 4, (w / nx) / 4);
    }
    if j != 0 && j != ny {
        y += hash.range(-(h / ny) / 4, (h / ny) / 4);
    }
    Point::new(x, y)
}

/// A jittered `nx` x `ny` grid, each cell split along a pseudo-random diagonal.
pub fn mesh(nx: i32, ny: i32, mut f: impl FnMut(SceneTriangle)) {
    let mut rng = Rng(0x3E54);
    let at = |i, j| mesh_point(nx, ny, i, j);
    for j in 0..ny {
        for i in 0..nx {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if rng.range(0, 1) == 0 {
                f(triangle(&mut rng, [a, b, c]));
                f(triangle(&mut rng, [a, c, d]));
            } else {
                f(triangle(&mut rng, [a, b, d]));
                f(triangle(&mut rng, [b, c, d]));
            }
        }
    }
}

/// Pixels the exact rasterizer covers in `triangles` (trirast's coverage walk): what the
/// benchmarks divide by for per-pixel figures, whoever draws.
pub fn covered_pixels(triangles: &[SceneTriangle]) -> u32 {
    let screen = Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
    let mut total = 0;
    for t in triangles {
        let [a, b, c] = t.vertices;
        let _ = trirast::coverage::for_each_span(
            &trirast::Triangle::new(a, b, c),
            trirast::FillRule::TopLeft,
            &screen,
            |s| {
                total += s.len;
                Ok::<(), ()>(())
            },
        );
    }
    total
}
