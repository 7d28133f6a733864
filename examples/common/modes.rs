//! Drawing modes shared by the benchmarks, the firmware example and its host twin
//! (`tests/firmware_frames.rs`): the same code renders the same frames on x86-64 and Cortex-M,
//! without allocation.
#![allow(dead_code)]

use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::StyledDrawable};
use fixed::types::{I16F16, I24F8};
use trirast::{
    FlatStyle, Framebuffer, GouraudStyle, TextureStyle, Triangle,
    band::{Bands, Scene as BandScene, SceneStyle, SetupCache, SetupSlot},
    depth::{DepthBuffer, DepthTarget},
    geometry::{Shape, SubPixelTriangle, SubPoint},
    target::BlendTarget,
    texture::{Filter, NoTexture, Perspective, Texels},
};

use crate::scenes::{HEIGHT, Scene, SceneTriangle, WIDTH};

/// Side of the benchmark texture.
pub const TEXTURE_SIDE: u32 = 64;

/// Rows per band in the band mode.
pub const BAND_ROWS: u32 = 16;

/// Band memory: one band of pixels or depths.
pub const BAND_LEN: usize = (WIDTH * BAND_ROWS) as usize;

/// Pixels in a frame.
pub const FRAME_LEN: usize = (WIDTH * HEIGHT) as usize;

/// Triangles in the largest scene (`small`).
pub const MAX_TRIANGLES: usize = 5000;

/// Set-up slots of `BandCache`: one per triangle of the largest scene (192 bytes each on
/// Cortex-M; `scene200` would need 200, 38,400 bytes).
pub const SETUP_SLOTS: usize = MAX_TRIANGLES;

/// The modes the firmware runs, in order.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Mode {
    /// One colour per triangle.
    Flat,
    /// Gouraud-shaded `Rgb565`.
    Gouraud,
    /// Gouraud through a 16-bit depth buffer, cleared first; every pixel passes.
    GouraudZ,
    /// The texture stretched over each triangle's bounding box, nearest texel.
    TexNearest,
    /// The same, bilinear.
    TexBilinear,
    /// The `GouraudZ` frame as a scene rendered in 16-row bands with a depth band.
    Band,
    /// `Band` keeping each triangle's set-up between bands (`Bands::with_setup_cache`, one
    /// slot per triangle up to [`SETUP_SLOTS`]).
    BandCache,
    /// Gouraud at half opacity over the frame (`Framebuffer::translucent`): every pixel read,
    /// blended and written. Minus `Gouraud`, what translucency costs.
    Translucent,
    /// Gouraud with ordered dithering (`GouraudStyle::with_dither`). Minus `Gouraud`, what
    /// dithering costs.
    GouraudDither,
    /// Flat at half opacity over the frame (`Framebuffer::translucent`): every pixel read and
    /// written, blended where it differs from the pixel before it (a scene of flat
    /// triangles leaves runs of equal pixels). Minus `Flat`, what a translucent fill costs.
    TranslucentFlat,
    /// Flat with anti-aliased edges (`BlendTarget::draw_anti_aliased`): edge pixels blended by
    /// their exact coverage. Minus `Flat`, what anti-aliasing costs.
    AntiAliased,
    /// `Flat`, `Gouraud`, `GouraudZ`, `TexNearest` and `AntiAliased` with sub-pixel vertices
    /// (`SubPixelTriangle`): each vertex moved by a fraction of a pixel (see [`subpixel`]).
    FlatSub,
    GouraudSub,
    GouraudZSub,
    TexNearestSub,
    AntiAliasedSub,
    /// `TexNearest` and `TexBilinear` perspective-correct (`TextureStyle::with_perspective`,
    /// 16-pixel sub-spans), with `w` from 1 at the top of the screen to 4 at the bottom (see
    /// [`receding_w`]). Over the affine modes, what perspective costs.
    PerspNearest,
    PerspBilinear,
}

impl Mode {
    /// Every mode.
    pub const ALL: [Mode; 18] = [
        Mode::Flat,
        Mode::Gouraud,
        Mode::GouraudZ,
        Mode::TexNearest,
        Mode::TexBilinear,
        Mode::Band,
        Mode::Translucent,
        Mode::GouraudDither,
        Mode::AntiAliased,
        Mode::FlatSub,
        Mode::GouraudSub,
        Mode::GouraudZSub,
        Mode::TexNearestSub,
        Mode::PerspNearest,
        Mode::PerspBilinear,
        Mode::BandCache,
        Mode::AntiAliasedSub,
        Mode::TranslucentFlat,
    ];

    /// The name `examples/perf.rs` uses for the mode.
    pub const fn name(self) -> &'static str {
        match self {
            Mode::Flat => "flat",
            Mode::Gouraud => "gouraud",
            Mode::GouraudZ => "gouraud-z",
            Mode::TexNearest => "tex-nearest",
            Mode::TexBilinear => "tex-bilinear",
            Mode::Band => "band",
            Mode::BandCache => "band-cache",
            Mode::Translucent => "translucent",
            Mode::GouraudDither => "gouraud-dither",
            Mode::TranslucentFlat => "translucent-flat",
            Mode::AntiAliased => "aa-flat",
            Mode::FlatSub => "flat-sub",
            Mode::GouraudSub => "gouraud-sub",
            Mode::GouraudZSub => "gouraud-z-sub",
            Mode::TexNearestSub => "nearest-sub",
            Mode::AntiAliasedSub => "aa-flat-sub",
            Mode::PerspNearest => "persp-nearest",
            Mode::PerspBilinear => "persp-bilinear",
        }
    }

    /// Whether the firmware is built with this mode: every mode, or those `FW_MODES` (read at
    /// build time, names separated by commas) lists. Fewer modes make a smaller firmware, for
    /// `benches/firmware-size.sh`; a mode left out draws nothing and is compiled out.
    pub const fn built(self) -> bool {
        let Some(list) = option_env!("FW_MODES") else {
            return true;
        };
        let (list, name) = (list.as_bytes(), self.name().as_bytes());
        let mut start = 0;
        while start <= list.len() {
            let mut end = start;
            while end < list.len() && list[end] != b',' {
                end += 1;
            }
            if end - start == name.len() {
                let mut k = 0;
                while k < name.len() && list[start + k] == name[k] {
                    k += 1;
                }
                if k == name.len() {
                    return true;
                }
            }
            start = end + 1;
        }
        false
    }

    /// Whether the firmware is built with a sub-pixel mode.
    pub const fn any_subpixel_built() -> bool {
        let mut k = 0;
        while k < Self::ALL.len() {
            if Self::ALL[k].built() && Self::ALL[k].subpixel() {
                return true;
            }
            k += 1;
        }
        false
    }

    /// Whether the mode draws sub-pixel triangles.
    pub const fn subpixel(self) -> bool {
        matches!(
            self,
            Mode::FlatSub
                | Mode::GouraudSub
                | Mode::GouraudZSub
                | Mode::TexNearestSub
                | Mode::AntiAliasedSub
        )
    }
}

/// Checksums (FNV-1a of the frame's little-endian bytes, drawn on black) of every mode and
/// scene: x86-64 (`tests/firmware_frames.rs`), Cortex-M0 and Cortex-M4 must all give these.
/// `GouraudZ`, `Band` and `BandCache` draw the `Gouraud` image: each triangle is nearer than those before.
pub const EXPECTED: [(Mode, Scene, u32); 90] = [
    (Mode::Flat, Scene::Big, 0x43168cbe),
    (Mode::Flat, Scene::Small, 0xbc014761),
    (Mode::Flat, Scene::Mesh, 0xf6e627c5),
    (Mode::Flat, Scene::Scene200, 0x2b441a14),
    (Mode::Gouraud, Scene::Big, 0x1de4e258),
    (Mode::Gouraud, Scene::Small, 0xdbdc1b96),
    (Mode::Gouraud, Scene::Mesh, 0x931dcdf1),
    (Mode::Gouraud, Scene::Scene200, 0x9a668a65),
    (Mode::GouraudZ, Scene::Big, 0x1de4e258),
    (Mode::GouraudZ, Scene::Small, 0xdbdc1b96),
    (Mode::GouraudZ, Scene::Mesh, 0x931dcdf1),
    (Mode::GouraudZ, Scene::Scene200, 0x9a668a65),
    (Mode::TexNearest, Scene::Big, 0x1c7cd106),
    (Mode::TexNearest, Scene::Small, 0xb81f01e8),
    (Mode::TexNearest, Scene::Mesh, 0x4b861b38),
    (Mode::TexNearest, Scene::Scene200, 0x18b363e9),
    (Mode::TexBilinear, Scene::Big, 0x76245bf7),
    (Mode::TexBilinear, Scene::Small, 0x8badc068),
    (Mode::TexBilinear, Scene::Mesh, 0xc46c39de),
    (Mode::TexBilinear, Scene::Scene200, 0xbf16723b),
    (Mode::Band, Scene::Big, 0x1de4e258),
    (Mode::Band, Scene::Small, 0xdbdc1b96),
    (Mode::Band, Scene::Mesh, 0x931dcdf1),
    (Mode::Band, Scene::Scene200, 0x9a668a65),
    (Mode::BandCache, Scene::Big, 0x1de4e258),
    (Mode::BandCache, Scene::Small, 0xdbdc1b96),
    (Mode::BandCache, Scene::Mesh, 0x931dcdf1),
    (Mode::BandCache, Scene::Scene200, 0x9a668a65),
    (Mode::Translucent, Scene::Big, 0x015202a8),
    (Mode::Translucent, Scene::Small, 0x03f7e8d6),
    (Mode::Translucent, Scene::Mesh, 0x0498c9cc),
    (Mode::Translucent, Scene::Scene200, 0xd133b3ab),
    (Mode::TranslucentFlat, Scene::Big, 0x5c7845a1),
    (Mode::TranslucentFlat, Scene::Small, 0xb557e273),
    (Mode::TranslucentFlat, Scene::Mesh, 0x8af941fa),
    (Mode::TranslucentFlat, Scene::Scene200, 0xdcb9d70f),
    (Mode::GouraudDither, Scene::Big, 0x95b2c7e6),
    (Mode::GouraudDither, Scene::Small, 0x11095c64),
    (Mode::GouraudDither, Scene::Mesh, 0x62317d17),
    (Mode::GouraudDither, Scene::Scene200, 0x47a0a8ae),
    (Mode::AntiAliased, Scene::Big, 0x20e2740a),
    (Mode::AntiAliased, Scene::Small, 0x38f9dd57),
    (Mode::AntiAliased, Scene::Mesh, 0x42e5edd8),
    (Mode::AntiAliased, Scene::Scene200, 0x2a4362ac),
    (Mode::FlatSub, Scene::Big, 0x6196aa16),
    (Mode::FlatSub, Scene::Small, 0x52875fac),
    (Mode::FlatSub, Scene::Mesh, 0xd9c24915),
    (Mode::FlatSub, Scene::Scene200, 0xc7456144),
    (Mode::GouraudSub, Scene::Big, 0x5eb8edb2),
    (Mode::GouraudSub, Scene::Small, 0xb0670ca0),
    (Mode::GouraudSub, Scene::Mesh, 0xf02ab082),
    (Mode::GouraudSub, Scene::Scene200, 0x343eb495),
    (Mode::GouraudZSub, Scene::Big, 0x5eb8edb2),
    (Mode::GouraudZSub, Scene::Small, 0xb0670ca0),
    (Mode::GouraudZSub, Scene::Mesh, 0xf02ab082),
    (Mode::GouraudZSub, Scene::Scene200, 0x343eb495),
    (Mode::TexNearestSub, Scene::Big, 0x4abbba93),
    (Mode::TexNearestSub, Scene::Small, 0x33439920),
    (Mode::TexNearestSub, Scene::Mesh, 0x0a47a102),
    (Mode::TexNearestSub, Scene::Scene200, 0xf6c6fc4a),
    (Mode::PerspNearest, Scene::Big, 0x3607b290),
    (Mode::PerspNearest, Scene::Small, 0x5e654372),
    (Mode::PerspNearest, Scene::Mesh, 0x54b4164f),
    (Mode::PerspNearest, Scene::Scene200, 0xaf922b06),
    (Mode::PerspBilinear, Scene::Big, 0xfcc977df),
    (Mode::PerspBilinear, Scene::Small, 0x60802120),
    (Mode::PerspBilinear, Scene::Mesh, 0x847fc5a5),
    (Mode::PerspBilinear, Scene::Scene200, 0x6c05629d),
    (Mode::AntiAliasedSub, Scene::Big, 0x620d8839),
    (Mode::AntiAliasedSub, Scene::Small, 0x827ee315),
    (Mode::AntiAliasedSub, Scene::Mesh, 0xd8b81fd5),
    (Mode::AntiAliasedSub, Scene::Scene200, 0x8b7f45fd),
    (Mode::Flat, Scene::Tiny, 0xf8c15fbf),
    (Mode::Gouraud, Scene::Tiny, 0xeb994206),
    (Mode::GouraudZ, Scene::Tiny, 0xeb994206),
    (Mode::TexNearest, Scene::Tiny, 0x08b44776),
    (Mode::TexBilinear, Scene::Tiny, 0xfeb1bdb6),
    (Mode::Band, Scene::Tiny, 0xeb994206),
    (Mode::Translucent, Scene::Tiny, 0x711565dd),
    (Mode::GouraudDither, Scene::Tiny, 0xc46900f2),
    (Mode::AntiAliased, Scene::Tiny, 0x43cbdbb1),
    (Mode::FlatSub, Scene::Tiny, 0x6924323e),
    (Mode::GouraudSub, Scene::Tiny, 0x7c689dd7),
    (Mode::GouraudZSub, Scene::Tiny, 0x7c689dd7),
    (Mode::TexNearestSub, Scene::Tiny, 0xc8f49661),
    (Mode::PerspNearest, Scene::Tiny, 0x788886de),
    (Mode::PerspBilinear, Scene::Tiny, 0xfeb1bdb6),
    (Mode::BandCache, Scene::Tiny, 0xeb994206),
    (Mode::AntiAliasedSub, Scene::Tiny, 0xd655c96c),
    (Mode::TranslucentFlat, Scene::Tiny, 0xf91e692e),
];

/// The expected checksum of `mode` on `scene`.
pub fn expected(mode: Mode, scene: Scene) -> u32 {
    EXPECTED
        .iter()
        .find(|&&(m, s, _)| m == mode && s == scene)
        .map_or(0, |&(_, _, sum)| sum)
}

/// Texel `i` (row-major) of the `side` x `side` benchmark texture: a checkerboard of 8 x 8
/// cells over smooth gradients.
pub fn texel(i: u32, side: u32) -> Rgb565 {
    let (x, y) = (i % side, i / side);
    let cell = ((x / 8 + y / 8) % 2) as u8;
    Rgb565::new(
        (x % 32) as u8,
        (y as u8 % 64) | cell,
        (cell * 31) ^ ((x + y) % 32) as u8,
    )
}

/// The scene's texture coordinates of `t`, as `I16F16`.
pub fn coordinates(t: &SceneTriangle) -> [[I16F16; 2]; 3] {
    t.coordinates.map(|uv| uv.map(I16F16::from_bits))
}

/// Depths of triangle `k` of `count` in the depth modes: each triangle nearer than those
/// before, depths falling by `gap` from one triangle to the next and by less across each.
pub fn layered_depths(k: usize, count: usize) -> [u16; 3] {
    Layers::new(count).depths(k)
}

/// [`layered_depths`] with its divisions made once per frame: per triangle they were library
/// calls on Cortex-M0, counted as drawing (and hoisted out of the loop or not, as the
/// compiler chose for each build).
#[derive(Copy, Clone)]
pub struct Layers {
    gap: u32,
    third: u32,
    two_thirds: u32,
}

impl Layers {
    pub fn new(count: usize) -> Self {
        let gap = (60_000 / count.max(1)).max(1) as u32;
        Self {
            gap,
            third: gap / 3,
            two_thirds: gap * 2 / 3,
        }
    }

    pub fn depths(&self, k: usize) -> [u16; 3] {
        let near = 60_000u32.saturating_sub(k as u32 * self.gap);
        [
            near,
            near.saturating_sub(self.third),
            near.saturating_sub(self.two_thirds),
        ]
        .map(|d| d as u16)
    }
}

/// Everything a frame draws with besides the frame itself.
pub struct Workspace<'a, const N: usize> {
    /// The benchmark texture.
    pub texture: Texels<'a, Rgb565>,
    /// A full-frame depth buffer (for `GouraudZ`).
    pub depths: &'a mut [u16],
    /// The band buffer and depth band (for `Band`).
    pub band: &'a mut [Rgb565],
    /// The depth band.
    pub depth_band: &'a mut [u16],
    /// The display list (for `Band`).
    pub list: &'a mut DisplayList<N>,
    /// Set-ups kept between bands (for `BandCache`).
    pub setups: &'a [SetupSlot],
}

/// The band mode's display list: flat and Gouraud triangles only. `NoTexture` leaves texture
/// mapping out of the band renderer (measured in `benches/firmware-size.sh`).
pub type DisplayList<const N: usize> = BandScene<'static, Rgb565, N, NoTexture<Rgb565>>;

/// Draws `triangles` in `mode` into `frame` (320 x 240). Each mode is a function of its own,
/// out of line, so that what is measured is compiled as a caller of the library would compile
/// it, whatever else the program holds.
pub fn draw<const N: usize>(
    mode: Mode,
    triangles: &[SceneTriangle],
    frame: &mut Framebuffer<'_, Rgb565>,
    work: &mut Workspace<'_, N>,
) {
    match mode {
        Mode::Flat if const { Mode::Flat.built() } => draw_flat(triangles, frame, whole),
        Mode::Gouraud if const { Mode::Gouraud.built() } => {
            draw_gouraud(triangles, frame, whole, false)
        }
        Mode::GouraudZ if const { Mode::GouraudZ.built() } => {
            draw_gouraud_z(triangles, frame, work.depths, whole)
        }
        Mode::TexNearest if const { Mode::TexNearest.built() } => {
            draw_textured(triangles, frame, work.texture, Filter::Nearest, whole)
        }
        Mode::TexBilinear if const { Mode::TexBilinear.built() } => {
            draw_textured(triangles, frame, work.texture, Filter::Bilinear, whole)
        }
        Mode::Band if const { Mode::Band.built() } => {
            draw_bands(triangles, frame, work, |bands| bands)
        }
        Mode::BandCache if const { Mode::BandCache.built() } => {
            let setups = work.setups;
            draw_bands(triangles, frame, work, |bands| {
                bands.with_setup_cache(setups)
            })
        }
        Mode::Translucent if const { Mode::Translucent.built() } => {
            draw_translucent(triangles, frame)
        }
        Mode::TranslucentFlat if const { Mode::TranslucentFlat.built() } => {
            draw_translucent_flat(triangles, frame)
        }
        Mode::GouraudDither if const { Mode::GouraudDither.built() } => {
            draw_gouraud(triangles, frame, whole, true)
        }
        Mode::AntiAliased if const { Mode::AntiAliased.built() } => {
            draw_anti_aliased(triangles, frame, whole)
        }
        Mode::AntiAliasedSub if const { Mode::AntiAliasedSub.built() } => {
            draw_anti_aliased(triangles, frame, subpixel_triangle)
        }
        Mode::FlatSub if const { Mode::FlatSub.built() } => {
            draw_flat(triangles, frame, subpixel_triangle)
        }
        Mode::GouraudSub if const { Mode::GouraudSub.built() } => {
            draw_gouraud(triangles, frame, subpixel_triangle, false)
        }
        Mode::GouraudZSub if const { Mode::GouraudZSub.built() } => {
            draw_gouraud_z(triangles, frame, work.depths, subpixel_triangle)
        }
        Mode::TexNearestSub if const { Mode::TexNearestSub.built() } => draw_textured(
            triangles,
            frame,
            work.texture,
            Filter::Nearest,
            subpixel_triangle,
        ),
        Mode::PerspNearest if const { Mode::PerspNearest.built() } => {
            draw_perspective(triangles, frame, work.texture, Filter::Nearest)
        }
        Mode::PerspBilinear if const { Mode::PerspBilinear.built() } => {
            draw_perspective(triangles, frame, work.texture, Filter::Bilinear)
        }
        _ => {}
    }
}

/// A scene triangle at its whole-pixel vertices.
pub fn whole(t: &SceneTriangle) -> Triangle {
    let [a, b, c] = t.vertices;
    Triangle::new(a, b, c)
}

/// A scene triangle at its sub-pixel vertices.
pub fn subpixel_triangle(t: &SceneTriangle) -> SubPixelTriangle {
    let [a, b, c] = t
        .subpixel
        .map(|[x, y]| SubPoint::new(I24F8::from_bits(x), I24F8::from_bits(y)));
    SubPixelTriangle::new(a, b, c)
}

/// Pixels `mode` covers in `triangles` (sub-pixel modes at their sub-pixel vertices).
pub fn covered_pixels(mode: Mode, triangles: &[SceneTriangle]) -> u32 {
    if !const { Mode::any_subpixel_built() } || !mode.subpixel() {
        return crate::scenes::covered_pixels(triangles);
    }
    let screen =
        embedded_graphics::primitives::Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT));
    let mut total = 0;
    for t in triangles {
        let _ = trirast::coverage::for_each_subpixel_span(
            &subpixel_triangle(t),
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

/// Flat with anti-aliased edges, each edge pixel blended over what the frame holds.
#[inline(never)]
fn draw_anti_aliased<G: Shape>(
    triangles: &[SceneTriangle],
    frame: &mut Framebuffer<'_, Rgb565>,
    shape: fn(&SceneTriangle) -> G,
) {
    for t in triangles {
        let _ = frame.draw_anti_aliased(&shape(t), &FlatStyle::new(t.color));
    }
}

/// Gouraud at half opacity: each pixel blended over what the frame holds.
#[inline(never)]
fn draw_translucent(triangles: &[SceneTriangle], frame: &mut Framebuffer<'_, Rgb565>) {
    let mut translucent = frame.translucent(128);
    for t in triangles {
        let [a, b, c] = t.vertices;
        let style = GouraudStyle::new(t.vertex_colors);
        let _ = Triangle::new(a, b, c)
            .into_styled(style)
            .draw(&mut translucent);
    }
}

fn draw_translucent_flat(triangles: &[SceneTriangle], frame: &mut Framebuffer<'_, Rgb565>) {
    let mut translucent = frame.translucent(128);
    for t in triangles {
        let [a, b, c] = t.vertices;
        let _ = Triangle::new(a, b, c)
            .into_styled(FlatStyle::new(t.color))
            .draw(&mut translucent);
    }
}

fn draw_flat<G>(
    triangles: &[SceneTriangle],
    frame: &mut Framebuffer<'_, Rgb565>,
    shape: fn(&SceneTriangle) -> G,
) where
    G: Shape + StyledDrawable<FlatStyle<Rgb565>, Color = Rgb565, Output = ()>,
{
    draw_each(triangles, frame, shape, |t| FlatStyle::new(t.color));
}

/// Gouraud, dithered or not: one function for both, so that adding the dithered mode does not
/// change how the plain one is compiled.
fn draw_gouraud<G>(
    triangles: &[SceneTriangle],
    frame: &mut Framebuffer<'_, Rgb565>,
    shape: fn(&SceneTriangle) -> G,
    dither: bool,
) where
    G: Shape + StyledDrawable<GouraudStyle<Rgb565>, Color = Rgb565, Output = ()>,
{
    draw_each(triangles, frame, shape, |t| {
        GouraudStyle::new(t.vertex_colors).with_dither(dither)
    });
}

/// Draws each triangle, as `shape` builds it, with the style `style_of` gives it: one
/// function per shape and style.
#[inline(never)]
fn draw_each<G, S>(
    triangles: &[SceneTriangle],
    frame: &mut Framebuffer<'_, Rgb565>,
    shape: fn(&SceneTriangle) -> G,
    style_of: impl Fn(&SceneTriangle) -> S,
) where
    G: Shape + StyledDrawable<S, Color = Rgb565, Output = ()>,
{
    for t in triangles {
        let _ = shape(t).draw_styled(&style_of(t), frame);
    }
}

#[inline(never)]
fn draw_gouraud_z<G: Shape>(
    triangles: &[SceneTriangle],
    frame: &mut Framebuffer<'_, Rgb565>,
    depths: &mut [u16],
    shape: fn(&SceneTriangle) -> G,
) {
    let layers = core::hint::black_box(Layers::new(triangles.len()));
    let Ok(mut zbuffer) = DepthBuffer::new(depths, WIDTH, HEIGHT) else {
        return;
    };
    zbuffer.clear(u16::MAX);
    let Ok(mut layered) = DepthTarget::new(frame, &mut zbuffer) else {
        return;
    };
    for (k, t) in triangles.iter().enumerate() {
        let style = GouraudStyle::new(t.vertex_colors);
        let _ = layered.draw(&shape(t), layers.depths(k), &style);
    }
}

/// The texture stretched over each triangle's bounding box.
#[inline(never)]
fn draw_textured<'t, G>(
    triangles: &[SceneTriangle],
    frame: &mut Framebuffer<'_, Rgb565>,
    texture: Texels<'t, Rgb565>,
    filter: Filter,
    shape: fn(&SceneTriangle) -> G,
) where
    G: Shape + StyledDrawable<TextureStyle<Texels<'t, Rgb565>>, Color = Rgb565, Output = ()>,
{
    for t in triangles {
        let style = TextureStyle::new(texture, coordinates(t)).with_filter(filter);
        let _ = shape(t).draw_styled(&style, frame);
    }
}

/// `draw_textured` perspective-correct, with [`receding_w`].
#[inline(never)]
fn draw_perspective(
    triangles: &[SceneTriangle],
    frame: &mut Framebuffer<'_, Rgb565>,
    texture: Texels<'_, Rgb565>,
    filter: Filter,
) {
    for t in triangles {
        let style = TextureStyle::new(texture, coordinates(t))
            .with_filter(filter)
            .with_perspective(Perspective::new(receding_w(t.vertices)));
        let _ = Triangle {
            vertices: t.vertices,
        }
        .draw_styled(&style, frame);
    }
}

/// `w` growing from 1 at the screen's top to 4 at its bottom (1 + y / 80, by a multiply: a
/// division here would be counted as drawing), as on a plane tilted away: every triangle not
/// flat in y has different `w` at its vertices.
pub fn receding_w(vertices: [Point; 3]) -> [I16F16; 3] {
    let height = HEIGHT as i32;
    vertices.map(|p| I16F16::from_bits((1 << 16) + 819 * p.y.clamp(0, height)))
}

/// `GouraudZ` in bands, configured by `configure` (a set-up cache, say).
#[inline(never)]
fn draw_bands<'w, const N: usize, K: SetupCache>(
    triangles: &[SceneTriangle],
    frame: &mut Framebuffer<'_, Rgb565>,
    work: &'w mut Workspace<'_, N>,
    configure: impl FnOnce(Bands<'w, Rgb565>) -> Bands<'w, Rgb565, Rgb565, K>,
) {
    let layers = core::hint::black_box(Layers::new(triangles.len()));
    let list = &mut *work.list;
    list.clear();
    for (k, t) in triangles.iter().enumerate() {
        let [a, b, c] = t.vertices;
        let style = SceneStyle::Gouraud(GouraudStyle::new(t.vertex_colors));
        let _ = list.push_with_depth(Triangle::new(a, b, c), layers.depths(k), style);
    }
    let bands = Bands::new(work.band, WIDTH, BAND_ROWS)
        .and_then(|bands| bands.with_depth(work.depth_band))
        .map(configure);
    if let Ok(mut bands) = bands {
        // Each band is whole rows of the frame, stored as the frame stores them: copied as one
        // run (`render` would draw it through the frame's `DrawTarget`, a pixel at a time).
        let width = frame.size().width as usize;
        let _ = bands.render_with(list, Rgb565::BLACK, |area, pixels| {
            let start = area.top_left.y as usize * width;
            match frame.pixels_mut().get_mut(start..start + pixels.len()) {
                Some(rows) => {
                    rows.copy_from_slice(pixels);
                    Ok(())
                }
                None => Err(()),
            }
        });
    }
}

/// FNV-1a over the frame's raw little-endian bytes.
pub fn fnv1a(pixels: &[Rgb565]) -> u32 {
    let mut h: u32 = 0x811C_9DC5;
    for p in pixels {
        for b in p.into_storage().to_le_bytes() {
            h = (h ^ u32::from(b)).wrapping_mul(0x0100_0193);
        }
    }
    h
}
