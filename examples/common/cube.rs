//! A spinning, lit cube in integer arithmetic only (no floating point, no allocation), shared
//! by the host examples and the firmware so that both render the very same frames.
//!
//! The 3D part (rotation, perspective, lighting) lives here, in the example: the crate takes
//! over at normalised device coordinates, through `Viewport`.
#![allow(dead_code)]

use embedded_graphics::{
    draw_target::DrawTarget,
    geometry::{Point, Size},
    pixelcolor::{Rgb565, Rgb888},
    primitives::Rectangle,
};
use fixed::types::I16F16;
use trirast::{
    Framebuffer, TextureStyle,
    depth::{DepthBuffer, DepthTarget},
    geometry::{SubPoint, Viewport},
    mesh::{Cull, Mesh, MeshVertex},
    texture::{Filter, Perspective, Texels},
};

/// The colour behind the cube.
pub const BACKGROUND: Rgb565 = Rgb565::new(3, 8, 12);

/// Clears `pixels` (`width` x `height`) to [`BACKGROUND`] and `depths` to the far plane, then
/// draws frame `frame` of `frames` over the whole of them with `texels` (see [`texels`]).
pub fn render(
    texels: &[Rgb565],
    pixels: &mut [Rgb565],
    depths: &mut [u16],
    (width, height): (u32, u32),
    frame: (u32, u32),
) {
    let side = TEXTURE as u32;
    let texture = Texels::new(texels, side, side).expect("texels() has TEXTURE x TEXTURE texels");
    let mut framebuffer = Framebuffer::new(pixels, width, height).expect("pixels fit the size");
    let _ = framebuffer.clear(BACKGROUND);
    let mut zbuffer = DepthBuffer::new(depths, width, height).expect("depths fit the size");
    zbuffer.clear(u16::MAX);
    let area = Rectangle::new(Point::zero(), Size::new(width, height));
    let mut scene = DepthTarget::new(&mut framebuffer, &mut zbuffer).expect("sizes match");
    // The framebuffer cannot fail.
    let _ = draw(&mut scene, area, texture, frame);
}

/// Draws frame `frame` of `frames` into `area` of `scene` (a target with its depth buffer):
/// back faces culled, each face `texture`d in perspective, filtered bilinearly and lit per
/// vertex.
pub fn draw<D>(
    scene: &mut DepthTarget<'_, '_, D>,
    area: Rectangle,
    texture: Texels<'_, Rgb565>,
    (frame, frames): (u32, u32),
) -> Result<(), D::Error>
where
    D: DrawTarget<Color = Rgb565>,
{
    let vertices = vertices(frame, frames, area);
    let mesh = Mesh::new(&vertices, &TRIANGLES).expect("the cube's indices are in range");
    mesh.draw_with_depth_subpixel(scene, Cull::Clockwise, |_, corners| {
        let gray = |l: u8| Rgb565::new(l >> 3, l >> 2, l >> 3);
        TextureStyle::new(texture, corners.map(|v| v.uv))
            .with_filter(Filter::Bilinear)
            .with_modulation(corners.map(|v| gray(v.light)))
            .with_perspective(Perspective::new(corners.map(MeshVertex::w)))
    })
}

/// Fixed point with 16 fraction bits, in `i64` so products need no care.
const ONE: i64 = 1 << 16;

/// One vertex as drawn: on screen (to 1/256 pixel, so the cube turns smoothly), with depth,
/// light (0..=255) and texture corner.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct CubeVertex {
    pub position: SubPoint,
    pub depth: u16,
    /// Distance along the view direction, for perspective-correct texturing.
    pub w: I16F16,
    pub light: u8,
    /// Texture coordinates in texels (the texture is `TEXTURE` x `TEXTURE`).
    pub uv: [I16F16; 2],
}

impl trirast::mesh::MeshVertex for CubeVertex {
    /// The nearest pixel, for whole-pixel drawing.
    fn position(&self) -> Point {
        MeshVertex::position(&self.position)
    }

    fn subpixel_position(&self) -> SubPoint {
        self.position
    }

    fn depth(&self) -> u16 {
        self.depth
    }

    fn w(&self) -> I16F16 {
        self.w
    }
}

/// Texture side the cube's texture coordinates assume.
pub const TEXTURE: i32 = 64;

/// Six faces, two triangles each, wound counter-clockwise seen from outside (so, on screen,
/// front faces wind counter-clockwise and back faces clockwise).
pub const TRIANGLES: [[u16; 3]; 12] = {
    let mut t = [[0; 3]; 12];
    let mut face = 0;
    while face < 6 {
        let base = (face * 4) as u16;
        t[face * 2] = [base, base + 1, base + 2];
        t[face * 2 + 1] = [base, base + 2, base + 3];
        face += 1;
    }
    t
};

/// Corners of each face (x, y, z in -1..=1), counter-clockwise seen from outside.
const FACES: [[[i64; 3]; 4]; 6] = [
    [[-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], // front (+z)
    [[1, -1, -1], [-1, -1, -1], [-1, 1, -1], [1, 1, -1]], // back (-z)
    [[1, -1, 1], [1, -1, -1], [1, 1, -1], [1, 1, 1]], // right (+x)
    [[-1, -1, -1], [-1, -1, 1], [-1, 1, 1], [-1, 1, -1]], // left (-x)
    [[-1, 1, 1], [1, 1, 1], [1, 1, -1], [-1, 1, -1]], // top (+y)
    [[-1, -1, -1], [1, -1, -1], [1, -1, 1], [-1, -1, 1]], // bottom (-y)
];

/// Texture corners of each face's four vertices.
const CORNERS: [[i32; 2]; 4] = [[0, TEXTURE], [TEXTURE, TEXTURE], [TEXTURE, 0], [0, 0]];

/// sin of `turn` / 65536 of a full turn, 16.16. Odd polynomial on a quarter turn, error below
/// 2^-16 (a 9th-order Taylor series in fixed point).
pub fn sin(turn: i64) -> i64 {
    let t = turn.rem_euclid(1 << 16);
    // Fold onto -quarter..=quarter, where the series converges fast.
    let t = if t > 3 << 14 { t - (1 << 16) } else { t };
    let t = if t > 1 << 14 { (1 << 15) - t } else { t };
    // x = t * 2π / 65536, in 16.16: 2π * 65536 = 411775.
    let x = (t * 411_775) >> 16;
    let x2 = (x * x) >> 16;
    // x (1 - x²/6 (1 - x²/20 (1 - x²/42 (1 - x²/72)))).
    let mut r = ONE - x2 / 72;
    r = ONE - ((x2 * r) >> 16) / 42;
    r = ONE - ((x2 * r) >> 16) / 20;
    r = ONE - ((x2 * r) >> 16) / 6;
    (x * r) >> 16
}

/// cos of `turn` / 65536 of a turn, 16.16.
pub fn cos(turn: i64) -> i64 {
    sin(turn + (1 << 14))
}

/// The cube's 24 vertices for frame `frame` of `frames` (one full turn about y, half a turn
/// about x), drawn into `area`.
pub fn vertices(frame: u32, frames: u32, area: Rectangle) -> [CubeVertex; 24] {
    let viewport = Viewport::new(area);
    let turn = i64::from(frame) * 65_536 / i64::from(frames.max(1));
    let (sa, ca) = (sin(turn), cos(turn));
    let (sb, cb) = (sin(turn / 2 + 3000), cos(turn / 2 + 3000));
    // Aspect ratio: NDC spans the area's width and height alike, so x shrinks by h / w.
    let aspect = i64::from(area.size.height) * ONE / i64::from(area.size.width.max(1));
    // A point light above, left and in front of the cube, in view space.
    let light = [-2 * ONE, 2 * ONE, -ONE];
    let mut out = [CubeVertex {
        position: SubPoint::default(),
        depth: 0,
        w: I16F16::ONE,
        light: 0,
        uv: [I16F16::ZERO; 2],
    }; 24];
    for (face, corners) in FACES.iter().enumerate() {
        for (k, corner) in corners.iter().enumerate() {
            // Rotate about y by a, then about x by b; the cube's half side is 0.8.
            let [x, y, z] = corner.map(|c| c * ONE * 4 / 5);
            let (x, z) = ((x * ca + z * sa) >> 16, (z * ca - x * sa) >> 16);
            let (y, z) = ((y * cb - z * sb) >> 16, (y * sb + z * cb) >> 16);
            // Camera 3.5 units away looking down -z; perspective with focal length 1.8: clip
            // coordinates, whose w is the view distance. The viewport divides by it.
            let depth = 7 * ONE / 2 - z;
            let clip_x = (((x * (ONE * 9 / 5)) >> 16) * aspect) >> 16;
            let clip_y = (y * (ONE * 9 / 5)) >> 16;
            // Linear depth: view distance 2 maps to NDC -1, distance 5 to 1.
            let clip_z = (((depth - 7 * ONE / 2) * 2 / 3) * depth) >> 16;
            let projected = viewport.project_clip([clip_x, clip_y, clip_z, depth].map(|v| {
                I16F16::from_bits(v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32)
            }));
            // Light falls off with the squared distance to the light.
            let d = [x - light[0], y - light[1], -z - light[2]];
            let d2 = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) >> 16;
            let level = (3200 * ONE / (d2 + ONE) - 100).clamp(40, 255);
            out[face * 4 + k] = CubeVertex {
                position: projected.position,
                depth: projected.depth,
                w: projected.w,
                light: level as u8,
                uv: CORNERS[k].map(|t| I16F16::from_bits(t << 16)),
            };
        }
    }
    out
}

/// The whole texture in `Rgb565`, row by row (8 KB, no allocation).
pub fn texels() -> [Rgb565; (TEXTURE * TEXTURE) as usize] {
    core::array::from_fn(|i| {
        let i = i as i32;
        let [r, g, b] = texel(i % TEXTURE, i / TEXTURE);
        Rgb888::new(r, g, b).into()
    })
}

/// A procedural `TEXTURE` x `TEXTURE` texture: framed checker tiles.
pub fn texel(x: i32, y: i32) -> [u8; 3] {
    let edge = x < 3 || y < 3 || x >= TEXTURE - 3 || y >= TEXTURE - 3;
    let check = ((x / 8) + (y / 8)) % 2 == 0;
    match (edge, check) {
        (true, _) => [40, 40, 48],
        (false, true) => [230, 180, 60],
        (false, false) => [200, 90, 40],
    }
}
