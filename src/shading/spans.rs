//! The span sink that shades pixel by pixel, shared by every interpolating style.

use embedded_graphics::{draw_target::DrawTarget, geometry::Point};

use crate::{
    coverage::{walk, FillRule, Span, SpanSink},
    interpolate::Planes,
    Triangle,
};

/// Draws `triangle` with `N` interpolated values per pixel, raw 16.16 (`values` per vertex, in
/// the triangle's vertex order, `bias` added to all), coloured by `shade(position, values)`.
///
/// Each span costs one plane evaluation and one `fill_contiguous` call whose colours step by
/// additions only.
#[inline(always)]
pub(crate) fn draw_shaded<D, const N: usize, F>(
    triangle: &Triangle,
    rule: FillRule,
    values: [[i64; N]; 3],
    bias: i64,
    target: &mut D,
    shade: F,
) -> Result<(), D::Error>
where
    D: DrawTarget,
    F: Fn(Point, [u32; N]) -> D::Color,
{
    let clip = target.bounding_box();
    let Some(planes) = Planes::new(triangle.vertices, values, bias, clip.top_left) else {
        return Ok(());
    };
    let mut sink = ShadeSpans {
        target,
        planes,
        shade,
    };
    walk(triangle, rule, &clip, &mut sink)
}

struct ShadeSpans<'a, D, const N: usize, F> {
    target: &'a mut D,
    planes: Planes<N>,
    shade: F,
}

impl<D, const N: usize, F> SpanSink for ShadeSpans<'_, D, N, F>
where
    D: DrawTarget,
    F: Fn(Point, [u32; N]) -> D::Color,
{
    type Error = D::Error;

    #[inline(always)]
    fn span(&mut self, span: Span) -> Result<(), D::Error> {
        let mut values = self.planes.at(span.x, span.y);
        let step = self.planes.step;
        let shade = &self.shade;
        let mut position = Point::new(span.x, span.y);
        let colors = (0..span.len).map(move |_| {
            let color = shade(position, values);
            position.x = position.x.wrapping_add(1);
            for (value, step) in values.iter_mut().zip(step) {
                *value = value.wrapping_add(step);
            }
            color
        });
        self.target.fill_contiguous(&span.rectangle(), colors)
    }
}
