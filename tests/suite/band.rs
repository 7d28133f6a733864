//! Band rendering gives, for any band height, the very image full-frame rendering gives
//! (whole-pixel and sub-pixel scenes, vertices anywhere in their types' ranges, with and
//! without kept set-ups); each band reaches the display as one `fill_contiguous` call; misuse
//! is reported.

use crate::common;

use common::{CountingTarget, Offset, Rng};
use embedded_graphics::{
    pixelcolor::{BinaryColor, Rgb565},
    prelude::*,
    primitives::{Rectangle, StyledDrawable},
};
use fixed::types::{I16F16, I24F8};
use proptest::prelude::*;
use trirast::{
    Error, FlatStyle, Framebuffer, GouraudStyle, TextureStyle, Triangle,
    band::{BandError, Bands, Scene, SceneStyle, SetupCache, SetupSlot},
    depth::{DepthBuffer, DepthTarget, DepthTest},
    geometry::{Shape, SubPixelTriangle, SubPoint},
    target::BlendTarget,
    texture::{Filter, Texels, Wrap},
};

const W: u32 = 48;
const H: u32 = 37;

fn color(rng: &mut Rng) -> Rgb565 {
    Rgb565::new(
        rng.range(0, 31) as u8,
        rng.range(0, 63) as u8,
        rng.range(0, 31) as u8,
    )
}

/// A triangle type the scenes hold, made from vertex coordinates in its own units.
trait SceneShape:
    Shape
    + Copy
    + Primitive
    + StyledDrawable<FlatStyle<Rgb565>, Color = Rgb565, Output = ()>
    + StyledDrawable<GouraudStyle<Rgb565>, Color = Rgb565, Output = ()>
    + for<'a> StyledDrawable<TextureStyle<Texels<'a, Rgb565>>, Color = Rgb565, Output = ()>
{
    /// Units per pixel.
    const UNIT: i32;

    fn from_units(v: [(i32, i32); 3]) -> Self;
}

impl SceneShape for Triangle {
    const UNIT: i32 = 1;

    fn from_units(v: [(i32, i32); 3]) -> Self {
        Triangle {
            vertices: v.map(|(x, y)| Point::new(x, y)),
        }
    }
}

impl SceneShape for SubPixelTriangle {
    const UNIT: i32 = 256;

    fn from_units(v: [(i32, i32); 3]) -> Self {
        let [a, b, c] = v.map(|(x, y)| SubPoint::new(I24F8::from_bits(x), I24F8::from_bits(y)));
        SubPixelTriangle::new(a, b, c)
    }
}

type TestScene<'a, G> = Scene<'a, Rgb565, 64, Texels<'a, Rgb565>, G>;

/// A random scene of 1 to 40 triangles of every kind, some depth-tested, some reaching far off
/// screen (one coordinate in five at either end of the `i32` range or of the fast walks'),
/// some degenerate.
fn random_scene<'a, G: SceneShape>(
    rng: &mut Rng,
    texture: Texels<'a, Rgb565>,
    test: DepthTest,
    origin: Point,
) -> TestScene<'a, G> {
    let mut scene = Scene::new(Rectangle::new(origin, Size::new(W, H))).with_depth_test(test);
    let far = [
        i32::MIN,
        i32::MIN + 1,
        -(1 << 30) - 1,
        -(1 << 30),
        1 << 30,
        (1 << 30) + 1,
        i32::MAX - 1,
        i32::MAX,
    ];
    for _ in 0..rng.range(1, 40) {
        let reach = [5, 30, 3000][rng.range(0, 2) as usize];
        let mut coordinate = |start: i32, size: u32| {
            if rng.range(0, 4) == 0 {
                far[rng.range(0, 7) as usize]
            } else {
                let pixels = i64::from(start) + i64::from(rng.range(-reach, size as i32 + reach));
                let units = pixels * i64::from(G::UNIT) + i64::from(rng.range(0, G::UNIT - 1));
                units.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
            }
        };
        let mut v = [(); 3].map(|()| (coordinate(origin.x, W), coordinate(origin.y, H)));
        // Some degenerate: a vertex on the line through the other two, or on another.
        if rng.range(0, 7) == 0 {
            let k = rng.range(-2, 2);
            let on_line = |a: i32, b: i32| a.wrapping_add(b.wrapping_sub(a).wrapping_mul(k));
            v[2] = (on_line(v[0].0, v[1].0), on_line(v[0].1, v[1].1));
        }
        let triangle = G::from_units(v);
        let style = match rng.range(0, 3) {
            0 => SceneStyle::Flat(FlatStyle::new(color(rng))),
            1 => SceneStyle::Gouraud(
                GouraudStyle::new([color(rng), color(rng), color(rng)])
                    .with_dither(rng.range(0, 1) == 1),
            ),
            2 => {
                let uv = [(); 3].map(|()| {
                    [
                        I16F16::from_bits(rng.range(-900_000, 900_000)),
                        I16F16::from_bits(rng.range(-900_000, 900_000)),
                    ]
                });
                let filter = if rng.range(0, 1) == 0 {
                    Filter::Nearest
                } else {
                    Filter::Bilinear
                };
                let wrap = if rng.range(0, 1) == 0 {
                    Wrap::Clamp
                } else {
                    Wrap::Repeat
                };
                SceneStyle::Texture(
                    TextureStyle::new(texture, uv)
                        .with_filter(filter)
                        .with_wrap(wrap),
                )
            }
            _ => {
                let uv = [(); 3].map(|()| [I16F16::from_bits(rng.range(0, 500_000)); 2]);
                SceneStyle::Texture(TextureStyle::new(texture, uv).with_modulation([
                    color(rng),
                    color(rng),
                    color(rng),
                ]))
            }
        };
        // Translucent and anti-aliased triangles only on screens at the origin: the reference
        // blends into an untranslated framebuffer.
        let blends = if origin == Point::zero() { 4 } else { 2 };
        match rng.range(0, blends) {
            0 => scene.push(triangle, style).unwrap(),
            1 | 2 => {
                let depths = [(); 3].map(|()| rng.range(0, 65535) as u16);
                scene.push_with_depth(triangle, depths, style).unwrap();
            }
            3 => {
                let opacity = rng.range(0, 255) as u8;
                scene.push_translucent(triangle, style, opacity).unwrap();
            }
            _ => {
                let opacity = [255, rng.range(0, 255) as u8][rng.range(0, 1) as usize];
                scene.push_anti_aliased(triangle, style, opacity).unwrap();
            }
        }
    }
    scene
}

/// The reference: every triangle drawn in order into a full frame and depth buffer (through
/// embedded-graphics' translation when the scene's screen is not at the origin).
fn full_frame<G: SceneShape>(
    scene: &TestScene<'_, G>,
    background: Rgb565,
    far: u16,
) -> Vec<Rgb565> {
    let mut pixels = vec![background; (W * H) as usize];
    let mut depths = vec![far; (W * H) as usize];
    let mut screen = Framebuffer::new(&mut pixels, W, H).unwrap();
    let mut zbuffer = DepthBuffer::new(&mut depths, W, H).unwrap();
    for item in scene.triangles() {
        if item.opacity < u8::MAX || item.anti_aliased {
            // Blending: at the origin (see `random_scene`), into the framebuffer itself.
            let mut blended = screen.translucent(item.opacity);
            let t = &item.triangle;
            match (&item.style, item.anti_aliased) {
                (SceneStyle::Flat(s), true) => blended.draw_anti_aliased(t, s),
                (SceneStyle::Gouraud(s), true) => blended.draw_anti_aliased(t, s),
                (SceneStyle::Texture(s), true) => blended.draw_anti_aliased(t, s),
                (SceneStyle::Flat(s), false) => t.into_styled(*s).draw(&mut blended),
                (SceneStyle::Gouraud(s), false) => t.into_styled(*s).draw(&mut blended),
                (SceneStyle::Texture(s), false) => t.into_styled(*s).draw(&mut blended),
            }
            .unwrap();
            continue;
        }
        let mut frame = screen.translated(Point::zero() - scene.screen().top_left);
        match item.depths {
            Some(d) => {
                let mut layered = DepthTarget::new(&mut frame, &mut zbuffer)
                    .unwrap()
                    .with_test(scene.depth_test());
                match &item.style {
                    SceneStyle::Flat(s) => layered.draw(&item.triangle, d, s),
                    SceneStyle::Gouraud(s) => layered.draw(&item.triangle, d, s),
                    SceneStyle::Texture(s) => layered.draw(&item.triangle, d, s),
                }
                .unwrap();
            }
            None => match &item.style {
                SceneStyle::Flat(s) => item.triangle.into_styled(*s).draw(&mut frame),
                SceneStyle::Gouraud(s) => item.triangle.into_styled(*s).draw(&mut frame),
                SceneStyle::Texture(s) => item.triangle.into_styled(*s).draw(&mut frame),
            }
            .unwrap(),
        }
    }
    pixels
}

/// Bands of `rows` rows over `band` and `depth_band`, cleared to depth `far`.
fn depth_bands<'b>(
    band: &'b mut [Rgb565],
    depth_band: &'b mut [u16],
    rows: u32,
    far: u16,
) -> Bands<'b, Rgb565> {
    Bands::new(band, W, rows)
        .unwrap()
        .with_depth(depth_band)
        .unwrap()
        .with_far_depth(far)
}

/// The scene rendered in bands of `rows` rows, keeping set-ups in `setups` if given (rendered
/// twice then: the second frame must not use the first's set-ups wrongly).
fn banded<G: SceneShape>(
    scene: &TestScene<'_, G>,
    rows: u32,
    background: Rgb565,
    far: u16,
    setups: Option<&[SetupSlot]>,
) -> Vec<Rgb565> {
    let mut band = vec![Rgb565::BLACK; (W * rows) as usize];
    let mut depth_band = vec![0u16; (W * rows) as usize];
    let mut bands = depth_bands(&mut band, &mut depth_band, rows, far);
    match setups {
        None => render_into(&mut bands, scene, background),
        Some(slots) => {
            let mut bands = bands.with_setup_cache(slots);
            let first = render_into(&mut bands, scene, background);
            let second = render_into(&mut bands, scene, background);
            assert!(first == second, "the second frame differs");
            second
        }
    }
}

/// Whether `scene` holds translucent or anti-aliased triangles, which plain rendering refuses.
fn blends<G: SceneShape>(scene: &TestScene<'_, G>) -> bool {
    scene
        .triangles()
        .iter()
        .any(|t| t.anti_aliased || t.opacity < u8::MAX)
}

fn render_into<K: SetupCache, G: SceneShape>(
    bands: &mut Bands<'_, Rgb565, Rgb565, K>,
    scene: &TestScene<'_, G>,
    background: Rgb565,
) -> Vec<Rgb565> {
    let mut pixels = vec![Rgb565::new(1, 2, 3); (W * H) as usize];
    let mut frame = Framebuffer::new(&mut pixels, W, H).unwrap();
    let mut frame = frame.translated(Point::zero() - scene.screen().top_left);
    if blends(scene) {
        // Plain rendering refuses blending, and leaves the display untouched.
        let refused = bands.render(scene, background, &mut frame);
        assert_eq!(refused, Err(BandError::Setup(Error::BandBlending)));
        assert!(pixels.iter().all(|&p| p == Rgb565::new(1, 2, 3)));
        let mut frame = Framebuffer::new(&mut pixels, W, H).unwrap();
        let mut frame = frame.translated(Point::zero() - scene.screen().top_left);
        bands.render_blended(scene, background, &mut frame).unwrap();
    } else {
        bands.render(scene, background, &mut frame).unwrap();
    }
    pixels
}

/// The scene rendered in bands of `rows` rows handed over raw (`Bands::render_with`, or
/// `render_blended_with`), each copied into the frame where its area says: the areas must
/// follow one another down the screen, as wide as it.
fn flushed<G: SceneShape>(
    scene: &TestScene<'_, G>,
    rows: u32,
    background: Rgb565,
    far: u16,
) -> Vec<Rgb565> {
    let mut band = vec![Rgb565::BLACK; (W * rows) as usize];
    let mut depth_band = vec![0u16; (W * rows) as usize];
    let mut bands = depth_bands(&mut band, &mut depth_band, rows, far);
    let screen = scene.screen();
    let mut pixels = Vec::new();
    let mut flush = |area: &Rectangle, band: &[Rgb565]| {
        let next = screen.top_left + Point::new(0, (pixels.len() as u32 / W) as i32);
        assert_eq!(area.top_left, next);
        assert!(area.size.width == W && area.size.height <= rows);
        assert_eq!(
            band.len(),
            area.size.width as usize * area.size.height as usize
        );
        pixels.extend_from_slice(band);
        Ok::<(), ()>(())
    };
    if blends(scene) {
        let refused = bands.render_with(scene, background, &mut flush);
        assert_eq!(refused, Err(BandError::Setup(Error::BandBlending)));
        bands
            .render_blended_with(scene, background, &mut flush)
            .unwrap();
    } else {
        bands.render_with(scene, background, &mut flush).unwrap();
    }
    assert_eq!(pixels.len(), (W * H) as usize);
    pixels
}

/// Renders a random scene of `G` triangles in bands of several heights, with and without kept
/// set-ups, and checks each image against the full frame.
fn bands_match_the_full_frame<G: SceneShape>(seed: u64) -> Result<(), TestCaseError> {
    let mut rng = Rng(seed);
    let texels: Vec<Rgb565> = (0..6 * 5).map(|_| color(&mut rng)).collect();
    let texture = Texels::new(&texels, 6, 5).unwrap();
    let test =
        [DepthTest::Less, DepthTest::LessOrEqual, DepthTest::Greater][rng.range(0, 2) as usize];
    let far = if test == DepthTest::Greater {
        0
    } else {
        u16::MAX
    };
    // Screens at the origin and off it (bands then draw at an offset in both axes).
    let origin = [Point::zero(), Point::new(-13, 21), Point::new(40, -7)][rng.range(0, 2) as usize];
    let scene = random_scene::<G>(&mut rng, texture, test, origin);
    let background = color(&mut rng);
    let want = full_frame(&scene, background, far);
    for rows in [1, 7, 16, H, H + 5] {
        let got = banded(&scene, rows, background, far, None);
        prop_assert!(got == want, "band height {} differs", rows);
    }
    prop_assert!(
        flushed(&scene, 7, background, far) == want,
        "flushed bands differ"
    );
    // Kept set-ups: a slot for every triangle, for some, for none; the slots used for
    // another scene first, whose set-ups must not be taken for this one's, then for a
    // scene of no triangles (each frame forgets only the slots its own scene reads).
    let slots: Vec<SetupSlot> = (0..64).map(|_| SetupSlot::EMPTY).collect();
    let count = [64, rng.range(1, 8) as usize, 0][rng.range(0, 2) as usize];
    let other = random_scene::<G>(&mut rng, texture, test, origin);
    let empty: TestScene<G> = Scene::new(scene.screen()).with_depth_test(test);
    for rows in [1, 7, H] {
        let _ = banded(&other, rows, background, far, Some(&slots[..count]));
        let _ = banded(&empty, rows, background, far, Some(&slots[..count]));
        let got = banded(&scene, rows, background, far, Some(&slots[..count]));
        prop_assert!(
            got == want,
            "band height {} with {} set-up slots differs",
            rows,
            count
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn bands_give_the_full_frame_image(seed in any::<u64>()) {
        bands_match_the_full_frame::<Triangle>(seed)?;
    }

    #[test]
    fn subpixel_bands_give_the_full_frame_image(seed in any::<u64>()) {
        bands_match_the_full_frame::<SubPixelTriangle>(seed)?;
    }
}

/// Each band is one `fill_contiguous` call covering its rows, top to bottom.
#[test]
fn one_call_per_band() {
    let mut scene: Scene<BinaryColor, 4> =
        Scene::new(Rectangle::new(Point::new(0, 0), Size::new(20, 30)));
    scene
        .push(
            Triangle::new(Point::new(0, 0), Point::new(19, 3), Point::new(4, 29)),
            SceneStyle::Flat(FlatStyle::new(BinaryColor::On)),
        )
        .unwrap();
    let mut band = [BinaryColor::Off; 20 * 8];
    let mut bands = Bands::new(&mut band, 20, 8).unwrap();
    let mut target = Offset(CountingTarget::new(Rectangle::new(
        Point::zero(),
        Size::new(20, 30),
    )));
    bands.render(&scene, BinaryColor::Off, &mut target).unwrap();
    assert_eq!(target.0.fill_contiguous_calls, 4); // 8 + 8 + 8 + 6 rows
    assert_eq!(
        target.0.fill_solid_calls.len() + target.0.draw_iter_calls,
        0
    );
    assert!(target.0.hits.iter().all(|&n| n == 1));
}

/// A flush's error ends the render: no band after it is rendered or handed over.
#[test]
fn a_flush_error_stops_the_render() {
    let mut scene: Scene<BinaryColor, 1> =
        Scene::new(Rectangle::new(Point::new(0, 0), Size::new(6, 20)));
    let t = Triangle::new(Point::new(0, 0), Point::new(6, 0), Point::new(0, 20));
    scene
        .push(t, SceneStyle::Flat(FlatStyle::new(BinaryColor::On)))
        .unwrap();
    let mut band = [BinaryColor::Off; 6 * 4];
    let mut bands = Bands::new(&mut band, 6, 4).unwrap();
    let mut tops = Vec::new();
    let result = bands.render_with(&scene, BinaryColor::Off, |area, _| {
        tops.push(area.top_left.y);
        if tops.len() == 2 {
            Err("bus fault")
        } else {
            Ok(())
        }
    });
    assert_eq!(result, Err(BandError::Target("bus fault")));
    assert_eq!(tops, [0, 4]);
}

#[test]
fn misuse_is_reported() {
    let screen = Rectangle::new(Point::zero(), Size::new(W, H));
    let mut scene: Scene<Rgb565, 2> = Scene::new(screen);
    let t = Triangle::new(Point::new(1, 1), Point::new(20, 2), Point::new(3, 30));
    let style = SceneStyle::Flat(FlatStyle::new(Rgb565::RED));
    scene.push(t, style).unwrap();
    scene.push_with_depth(t, [1, 2, 3], style).unwrap();
    assert_eq!(scene.push(t, style), Err(Error::SceneFull { capacity: 2 }));
    assert_eq!(scene.triangles().len(), 2);

    let mut band = vec![Rgb565::BLACK; (W * 4) as usize];
    assert_eq!(
        Bands::<Rgb565>::new(&mut band, W, 0).unwrap_err(),
        Error::BandHeight
    );
    assert!(matches!(
        Bands::<Rgb565>::new(&mut band, W, 5),
        Err(Error::BufferLength { .. })
    ));
    let mut frame_pixels = vec![Rgb565::BLACK; (W * H) as usize];
    let mut frame = Framebuffer::new(&mut frame_pixels, W, H).unwrap();
    // Depth-tested triangles need a depth band.
    let mut bands = Bands::new(&mut band, W, 4).unwrap();
    assert_eq!(
        bands.render(&scene, Rgb565::BLACK, &mut frame),
        Err(BandError::Setup(Error::BandDepth))
    );
    let mut short = vec![0u16; 7];
    assert!(matches!(
        Bands::<Rgb565>::new(&mut band, W, 4)
            .unwrap()
            .with_depth(&mut short),
        Err(Error::BufferLength { .. })
    ));
    // Bands must be as wide as the screen.
    let mut narrow = vec![Rgb565::BLACK; 10 * 4];
    let mut bands = Bands::new(&mut narrow, 10, 4).unwrap();
    assert_eq!(
        bands.render(&scene, Rgb565::BLACK, &mut frame),
        Err(BandError::Setup(Error::BandWidth {
            band: 10,
            screen: W
        }))
    );
}

/// Memory a 320 x 240 `Rgb565` set-up pays for, as documented in the `band` module.
#[test]
fn scene_sizes() {
    let triangle =
        core::mem::size_of::<trirast::band::SceneTriangle<Rgb565, Texels<'static, Rgb565>>>();
    println!(
        "SceneTriangle<Rgb565>: {triangle} bytes; 200 triangles: {} bytes",
        200 * triangle
    );
    println!(
        "16-row Rgb565 band: {} bytes, and as much again for its depth band",
        320 * 16 * 2
    );
    // 128 bytes on 64-bit hosts (the texture's slice reference is 16 of them, a texture
    // style's perspective 16 more); 112 on 32-bit Cortex-M.
    assert!(triangle <= 128, "{triangle} bytes per scene triangle");
    // What `SetupSlot`'s documentation promises, on hosts and on Cortex-M alike (no pointers).
    assert_eq!(core::mem::size_of::<SetupSlot>(), 192);
}
