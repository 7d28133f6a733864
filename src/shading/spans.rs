//! The span driver shared by every per-pixel style: Gouraud, user shaders, textures.

use embedded_graphics::{draw_target::DrawTarget, geometry::Point, pixelcolor::PixelColor};

use super::paint::stored;
use crate::{
    coverage::Span,
    geometry::Shape,
    interpolate::{AreaMemo, Planes},
    unroll::per_channel,
};

/// Computes colours pixel by pixel along a span, by additions.
pub(crate) trait PixelShader {
    type Color: PixelColor;
    /// What changes from one pixel to the next.
    type State: Copy;

    /// The state at pixel `(x, y)`, the first of a span: computed exactly, not carried over
    /// from the previous row.
    fn start(&self, x: i32, y: i32) -> Self::State;

    /// The current pixel's colour; then moves the state one pixel right.
    fn next(&self, state: &mut Self::State) -> Self::Color;

    /// Whether spans are shaded into a small buffer first: for shaders too big to be inlined
    /// into the target's fill loop (measured: bilinear filtering), which would otherwise cost
    /// a call and a trip through memory per pixel.
    const BUFFERED: bool = false;
}

/// A borrowed shader shades as the shader does.
impl<T: PixelShader + ?Sized> PixelShader for &T {
    type Color = T::Color;
    type State = T::State;
    const BUFFERED: bool = T::BUFFERED;

    #[inline(always)]
    fn start(&self, x: i32, y: i32) -> Self::State {
        (**self).start(x, y)
    }

    #[inline(always)]
    fn next(&self, state: &mut Self::State) -> Self::Color {
        (**self).next(state)
    }
}

/// Shades one span with `shader` into `target`, whose pixel `(x, y)` is the screen's
/// `(x, y) + offset` (see [`stored`]). The shader is taken by value, so that the colours'
/// iterator owns it: borrowed, it had to be stored to memory for every span, even where the
/// span loop keeps what it reads in registers.
#[inline(always)]
pub(crate) fn shade_span<D, S>(
    shader: S,
    span: Span,
    offset: Point,
    target: &mut D,
) -> Result<(), D::Error>
where
    D: DrawTarget,
    S: PixelShader<Color = D::Color>,
{
    let mut state = shader.start(span.x, span.y);
    if !S::BUFFERED {
        let colors = (0..span.len).map(move |_| shader.next(&mut state));
        return target.fill_contiguous(&stored(span, offset), colors);
    }
    // Shaders too big to be inlined into the target's fill loop through a closure run in
    // their own loop, filling a small buffer that the target then copies.
    let mut x = span.x;
    let mut remaining = span.len;
    while remaining > 0 {
        let first = shader.next(&mut state);
        let mut buffer = [first; CHUNK];
        let len = (remaining as usize).min(CHUNK);
        for slot in &mut buffer[1..len] {
            *slot = shader.next(&mut state);
        }
        let run = Span {
            x,
            y: span.y,
            len: len as u32,
        };
        let area = stored(run, offset);
        target.fill_contiguous(&area, buffer[..len].iter().copied())?;
        x = x.wrapping_add(len as i32);
        remaining -= len as u32;
    }
    Ok(())
}

/// Pixels per buffered chunk.
const CHUNK: usize = 32;

/// A shader of `N` interpolated values, coloured by `shade(position, values)`: the machinery
/// behind Gouraud shading and user shaders.
pub(crate) struct PlanesShader<const N: usize, F> {
    pub(crate) planes: Planes<N>,
    pub(crate) shade: F,
}

impl<const N: usize, F> PlanesShader<N, F> {
    /// Planes through `values` (raw 16.16, one array per vertex, in the triangle's vertex
    /// order, `bias` added to all) for drawing into a window at `origin`, the area's
    /// reciprocal through `memo`; `None` for degenerate triangles.
    #[inline(always)]
    pub(crate) fn new<G: Shape>(
        triangle: &G,
        values: [[i64; N]; 3],
        bias: i64,
        origin: Point,
        memo: Option<&AreaMemo>,
        shade: F,
    ) -> Option<Self> {
        Some(Self {
            planes: triangle.planes(values, bias, origin, memo)?,
            shade,
        })
    }
}

impl<C, const N: usize, F> PixelShader for PlanesShader<N, F>
where
    C: PixelColor,
    F: Fn(Point, [u32; N]) -> C,
{
    type Color = C;
    /// Position, values and their steps: the steps are copied into the state so the span
    /// loop keeps them in registers (read through `&self` they get reloaded every pixel).
    type State = (Point, [u32; N], [u32; N]);

    #[inline(always)]
    fn start(&self, x: i32, y: i32) -> Self::State {
        (Point::new(x, y), self.planes.at(x, y), self.planes.step)
    }

    #[inline(always)]
    fn next(&self, state: &mut Self::State) -> C {
        next_linear(&self.shade, state)
    }
}

/// The colour `shade` gives the current pixel of a linear state (position, values, their
/// steps); then the state one pixel right.
#[inline(always)]
fn next_linear<C, const N: usize, F>(
    shade: &F,
    (position, values, step): &mut (Point, [u32; N], [u32; N]),
) -> C
where
    F: Fn(Point, [u32; N]) -> C,
{
    let color = shade(*position, *values);
    position.x = position.x.wrapping_add(1);
    *values = per_channel!(N, |k| values[k].wrapping_add(step[k]));
    color
}

/// A shader of `N` values stepping linearly from `start` by `steps` (raw 16.16) from the first
/// pixel of the span it shades, coloured by `shade(position, values)`: a perspective-correct
/// sub-span of a user shader.
pub(crate) struct SteppedShader<const N: usize, F> {
    pub(crate) start: [i32; N],
    pub(crate) steps: [i32; N],
    pub(crate) shade: F,
}

impl<C, const N: usize, F> PixelShader for SteppedShader<N, F>
where
    C: PixelColor,
    F: Fn(Point, [u32; N]) -> C,
{
    type Color = C;
    type State = (Point, [u32; N], [u32; N]);

    #[inline(always)]
    fn start(&self, x: i32, y: i32) -> Self::State {
        let as_raw = |v: [i32; N]| v.map(|v| v as u32);
        (Point::new(x, y), as_raw(self.start), as_raw(self.steps))
    }

    #[inline(always)]
    fn next(&self, state: &mut Self::State) -> C {
        next_linear(&self.shade, state)
    }
}
