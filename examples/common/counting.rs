//! A pass-through `DrawTarget` that counts the pixels each call writes inside the target and how
//! often each pixel is written (for pixel counts, overdraw and gaps).
#![allow(dead_code)]

use embedded_graphics::{Pixel, prelude::*, primitives::Rectangle};

pub struct Counting<'a, D> {
    pub inner: &'a mut D,
    pub hits: Vec<u8>,
    pub width: usize,
}

impl<'a, D: DrawTarget + OriginDimensions> Counting<'a, D> {
    pub fn new(inner: &'a mut D) -> Self {
        let size = inner.size();
        Self {
            hits: vec![0; (size.width * size.height) as usize],
            width: size.width as usize,
            inner,
        }
    }

    fn hit(&mut self, p: Point) {
        let size = self.inner.size();
        if p.x >= 0 && p.y >= 0 && (p.x as u32) < size.width && (p.y as u32) < size.height {
            let i = p.y as usize * self.width + p.x as usize;
            self.hits[i] = self.hits[i].saturating_add(1);
        }
    }

    /// Pixel writes inside the target.
    pub fn pixels(&self) -> u64 {
        self.hits.iter().map(|&h| u64::from(h)).sum()
    }

    /// Writes beyond the first, over all pixels.
    pub fn overdraw(&self) -> u64 {
        self.hits
            .iter()
            .map(|&h| u64::from(h.saturating_sub(1)))
            .sum()
    }

    /// Pixels never written.
    pub fn gaps(&self) -> u64 {
        self.hits.iter().filter(|&&h| h == 0).count() as u64
    }
}

impl<D: DrawTarget + OriginDimensions> OriginDimensions for Counting<'_, D> {
    fn size(&self) -> Size {
        self.inner.size()
    }
}

impl<D: DrawTarget + OriginDimensions> DrawTarget for Counting<'_, D> {
    type Color = D::Color;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<D::Color>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), D::Error> {
        let pixels: Vec<_> = pixels.into_iter().collect();
        for Pixel(p, _) in &pixels {
            self.hit(*p);
        }
        self.inner.draw_iter(pixels)
    }

    fn fill_contiguous<I: IntoIterator<Item = D::Color>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), D::Error> {
        for p in area.points() {
            self.hit(p);
        }
        self.inner.fill_contiguous(area, colors)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: D::Color) -> Result<(), D::Error> {
        for p in area.points() {
            self.hit(p);
        }
        self.inner.fill_solid(area, color)
    }
}
