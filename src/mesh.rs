//! Indexed triangle meshes: a vertex slice and a slice of index triples, drawn with per-triangle
//! styles, optional back-face culling and an optional depth test.

use embedded_graphics::{draw_target::DrawTarget, geometry::Point};
use fixed::types::{I16F16, I24F8};

use crate::{
    Error,
    depth::DepthTarget,
    geometry::{Orientation, Projected, Shape, SubPixelTriangle, SubPoint, Triangle},
    shading::TriangleStyle,
};

/// A mesh vertex: where it lands on screen and, for depth-tested drawing, its depth.
///
/// Implemented for `Point` and `SubPoint` (depth 0), for `(Point, u16)` and `(SubPoint, u16)`,
/// and for [`Projected`] (what [`Viewport::project_clip`](crate::geometry::Viewport::project_clip)
/// gives); implement it for your own vertex type
/// to carry colours, texture coordinates or normals alongside.
///
/// # Examples
///
/// ```
/// use embedded_graphics::prelude::*;
/// use trirast::mesh::MeshVertex;
///
/// struct Lit { at: Point, depth: u16, light: u8 }
/// impl MeshVertex for Lit {
///     fn position(&self) -> Point { self.at }
///     fn depth(&self) -> u16 { self.depth }
/// }
/// let v = Lit { at: Point::new(3, 4), depth: 9, light: 200 };
/// assert_eq!((v.position(), v.depth(), v.light), (Point::new(3, 4), 9, 200));
/// ```
pub trait MeshVertex {
    /// The vertex on screen.
    fn position(&self) -> Point;

    /// The vertex's depth (0 = nearest); 0 unless given.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::mesh::MeshVertex;
    ///
    /// assert_eq!((Point::new(1, 2), 77u16).depth(), 77);
    /// assert_eq!(Point::new(1, 2).depth(), 0);
    /// ```
    fn depth(&self) -> u16 {
        0
    }

    /// The vertex on screen to 1/256 pixel, for [`Mesh::draw_subpixel`] and
    /// [`Mesh::draw_with_depth_subpixel`]; [`MeshVertex::position`] unless given.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use fixed::types::{I16F16, I24F8};
    /// use trirast::{geometry::SubPoint, mesh::MeshVertex};
    ///
    /// assert_eq!(Point::new(1, 2).subpixel_position(), SubPoint::from(Point::new(1, 2)));
    /// let p = SubPoint::new(I24F8::from_num(1.5), I24F8::from_num(2.25));
    /// assert_eq!(p.subpixel_position(), p);
    /// assert_eq!(p.position(), Point::new(2, 2)); // nearest, halves up
    /// ```
    fn subpixel_position(&self) -> SubPoint {
        SubPoint::from_point(self.position())
    }

    /// The vertex's `w` (its distance along the view direction, from the projection), for
    /// perspective-correct textures ([`Perspective`](crate::texture::Perspective)); 1 unless
    /// given.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::Rectangle};
    /// use fixed::types::I16F16;
    /// use trirast::{geometry::Viewport, mesh::MeshVertex};
    ///
    /// assert_eq!(Point::new(1, 2).w(), I16F16::ONE);
    /// let viewport = Viewport::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
    /// let far = viewport.project_clip([0, 0, 0, 5].map(I16F16::from_num));
    /// assert_eq!(far.w(), I16F16::from_num(5));
    /// ```
    fn w(&self) -> I16F16 {
        I16F16::ONE
    }
}

impl MeshVertex for Projected {
    #[inline]
    fn position(&self) -> Point {
        self.position.position()
    }

    #[inline]
    fn depth(&self) -> u16 {
        self.depth
    }

    #[inline]
    fn subpixel_position(&self) -> SubPoint {
        self.position
    }

    #[inline]
    fn w(&self) -> I16F16 {
        self.w
    }
}

impl MeshVertex for SubPoint {
    /// The nearest pixel (halves up).
    #[inline]
    fn position(&self) -> Point {
        let round = |v: I24F8| (v.to_bits() >> 8) + ((v.to_bits() >> 7) & 1);
        Point::new(round(self.x), round(self.y))
    }

    #[inline]
    fn subpixel_position(&self) -> SubPoint {
        *self
    }
}

impl MeshVertex for (SubPoint, u16) {
    #[inline]
    fn position(&self) -> Point {
        self.0.position()
    }

    #[inline]
    fn depth(&self) -> u16 {
        self.1
    }

    #[inline]
    fn subpixel_position(&self) -> SubPoint {
        self.0
    }
}

impl MeshVertex for Point {
    #[inline]
    fn position(&self) -> Point {
        *self
    }
}

impl MeshVertex for (Point, u16) {
    #[inline]
    fn position(&self) -> Point {
        self.0
    }

    #[inline]
    fn depth(&self) -> u16 {
        self.1
    }
}

/// Which triangles a mesh skips by their winding as seen on screen, as
/// [`Triangle::orientation`] reports it.
///
/// [`Viewport`](crate::geometry::Viewport) keeps what you see: NDC y points up the screen, so
/// a triangle counter-clockwise in NDC (OpenGL's front faces) is counter-clockwise on screen
/// too. Cull [`Cull::Clockwise`] to skip the back faces of such meshes.
///
/// # Examples
///
/// ```
/// use trirast::mesh::Cull;
///
/// assert_eq!(Cull::default(), Cull::None);
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub enum Cull {
    /// Draw every triangle.
    #[default]
    None,
    /// Skip triangles that wind clockwise on screen.
    Clockwise,
    /// Skip triangles that wind counter-clockwise on screen.
    CounterClockwise,
}

impl Cull {
    /// Whether a triangle of this `orientation` is skipped (degenerate ones always are).
    ///
    /// # Examples
    ///
    /// ```
    /// use trirast::{mesh::Cull, Orientation};
    ///
    /// assert!(Cull::Clockwise.skips(Orientation::Clockwise));
    /// assert!(!Cull::Clockwise.skips(Orientation::CounterClockwise));
    /// assert!(Cull::None.skips(Orientation::Degenerate));
    /// ```
    #[must_use]
    pub fn skips(self, orientation: Orientation) -> bool {
        matches!(
            (self, orientation),
            (_, Orientation::Degenerate)
                | (Cull::Clockwise, Orientation::Clockwise)
                | (Cull::CounterClockwise, Orientation::CounterClockwise)
        )
    }
}

/// An indexed triangle list: vertices, and triangles as triples of indices into them.
///
/// Indices are checked once, in [`Mesh::new`]; drawing then cannot fail on bad data. Shared
/// edges stay watertight under the default top-left rule: each pixel along an edge two
/// triangles share belongs to exactly one of them.
///
/// # Examples
///
/// A square of two triangles, each with its own flat colour:
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use trirast::{mesh::{Cull, Mesh}, FlatStyle, Framebuffer};
///
/// let corners = [Point::new(0, 0), Point::new(8, 0), Point::new(8, 8), Point::new(0, 8)];
/// let mesh = Mesh::new(&corners, &[[0, 1, 2], [0, 2, 3]])?;
/// let mut pixels = [Rgb565::BLACK; 8 * 8];
/// let mut display = Framebuffer::new(&mut pixels, 8, 8)?;
/// let colors = [Rgb565::RED, Rgb565::GREEN];
/// mesh.draw(&mut display, Cull::None, |index, _| FlatStyle::new(colors[index])).unwrap();
/// assert!(display.pixels().iter().all(|&p| p != Rgb565::BLACK));
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Copy, Clone, Debug)]
pub struct Mesh<'a, V> {
    vertices: &'a [V],
    triangles: &'a [[u16; 3]],
}

impl<'a, V: MeshVertex> Mesh<'a, V> {
    /// A mesh of `triangles` over `vertices`.
    ///
    /// # Errors
    ///
    /// [`Error::MeshIndex`] for the first index that is not a vertex.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::{mesh::Mesh, Error};
    ///
    /// let points = [Point::zero(); 3];
    /// assert_eq!(
    ///     Mesh::new(&points, &[[0, 1, 3]]).unwrap_err(),
    ///     Error::MeshIndex { triangle: 0, index: 3 }
    /// );
    /// ```
    pub fn new(vertices: &'a [V], triangles: &'a [[u16; 3]]) -> Result<Self, Error> {
        for (triangle, indices) in triangles.iter().enumerate() {
            if let Some(&index) = indices.iter().find(|&&i| usize::from(i) >= vertices.len()) {
                return Err(Error::MeshIndex { triangle, index });
            }
        }
        Ok(Self {
            vertices,
            triangles,
        })
    }

    /// The vertices.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::mesh::Mesh;
    ///
    /// let points = [Point::new(1, 1); 3];
    /// assert_eq!(Mesh::new(&points, &[])?.vertices().len(), 3);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn vertices(&self) -> &'a [V] {
        self.vertices
    }

    /// The triangles, as index triples.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::mesh::Mesh;
    ///
    /// let points = [Point::new(1, 1); 3];
    /// assert_eq!(Mesh::new(&points, &[[0, 1, 2]])?.triangles(), &[[0, 1, 2]]);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn triangles(&self) -> &'a [[u16; 3]] {
        self.triangles
    }

    /// The drawable triangles: index, triangle (built by `shape` from the vertices, with its
    /// orientation) and vertices, culled triangles left out.
    fn visible<G>(
        &self,
        cull: Cull,
        shape: fn([&'a V; 3]) -> (G, Orientation),
    ) -> impl Iterator<Item = (usize, G, [&'a V; 3])> + use<'a, V, G> {
        let vertices = self.vertices;
        self.triangles
            .iter()
            .enumerate()
            .filter_map(move |(index, &[a, b, c])| {
                // Indices were checked in `new`: a triangle is never left out here. Not by
                // indexing, whose panic formats the bounds (about 2 KB of flash).
                let corners = [
                    vertices.get(usize::from(a))?,
                    vertices.get(usize::from(b))?,
                    vertices.get(usize::from(c))?,
                ];
                let (triangle, orientation) = shape(corners);
                (!cull.skips(orientation)).then_some((index, triangle, corners))
            })
    }

    /// Draws the triangles `shape` builds, not culled, with the style `style_of` gives.
    fn draw_shapes<G, D, S, F>(
        &self,
        target: &mut D,
        cull: Cull,
        shape: fn([&'a V; 3]) -> (G, Orientation),
        mut style_of: F,
    ) -> Result<(), D::Error>
    where
        G: Shape,
        D: DrawTarget,
        S: TriangleStyle<Color = D::Color>,
        F: FnMut(usize, [&V; 3]) -> S,
    {
        for (index, triangle, corners) in self.visible(cull, shape) {
            crate::shading::paint::draw_plain(&triangle, &style_of(index, corners), target)?;
        }
        Ok(())
    }

    /// Draws the triangles `shape` builds, not culled, through the depth test of `target`.
    fn draw_shapes_with_depth<G, D, S, F>(
        &self,
        target: &mut DepthTarget<'_, '_, D>,
        cull: Cull,
        shape: fn([&'a V; 3]) -> (G, Orientation),
        mut style_of: F,
    ) -> Result<(), D::Error>
    where
        G: Shape,
        D: DrawTarget,
        S: TriangleStyle<Color = D::Color>,
        F: FnMut(usize, [&V; 3]) -> S,
    {
        for (index, triangle, corners) in self.visible(cull, shape) {
            let depths = corners.map(MeshVertex::depth);
            target.draw(&triangle, depths, &style_of(index, corners))?;
        }
        Ok(())
    }

    /// The triangle at the vertices' whole-pixel positions.
    fn whole(corners: [&'a V; 3]) -> (Triangle, Orientation) {
        let triangle = Triangle {
            vertices: corners.map(MeshVertex::position),
        };
        (triangle, triangle.orientation())
    }

    /// The triangle at the vertices' sub-pixel positions.
    fn subpixel(corners: [&'a V; 3]) -> (SubPixelTriangle, Orientation) {
        let triangle = SubPixelTriangle {
            vertices: corners.map(MeshVertex::subpixel_position),
        };
        (triangle, triangle.orientation())
    }

    /// [`Mesh::draw`] at the vertices' sub-pixel positions
    /// ([`MeshVertex::subpixel_position`]): triangles move smoothly as their vertices do.
    ///
    /// # Errors
    ///
    /// The target's; drawing stops at the first.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use fixed::types::{I16F16, I24F8};
    /// use trirast::{geometry::SubPoint, mesh::{Cull, Mesh}, FlatStyle, Framebuffer};
    ///
    /// let at = |x: f32, y: f32| SubPoint::new(I24F8::from_num(x), I24F8::from_num(y));
    /// // A square a third of a pixel right of whole coordinates.
    /// let v = [at(0.33, 0.0), at(0.33, 4.0), at(4.33, 4.0), at(4.33, 0.0)];
    /// let mesh = Mesh::new(&v, &[[0, 1, 2], [0, 2, 3]])?;
    /// let mut pixels = [Gray8::BLACK; 25];
    /// let mut display = Framebuffer::new(&mut pixels, 5, 5)?;
    /// mesh.draw_subpixel(&mut display, Cull::None, |_, _| FlatStyle::new(Gray8::WHITE)).unwrap();
    /// // Columns 1 to 4: column 0's centres lie left of the square.
    /// assert_eq!(display.pixel(Point::new(0, 1)), Some(Gray8::BLACK));
    /// assert_eq!(display.pixel(Point::new(4, 1)), Some(Gray8::WHITE));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn draw_subpixel<D, S, F>(
        &self,
        target: &mut D,
        cull: Cull,
        style_of: F,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget,
        S: TriangleStyle<Color = D::Color>,
        F: FnMut(usize, [&V; 3]) -> S,
    {
        self.draw_shapes(target, cull, Self::subpixel, style_of)
    }

    /// [`Mesh::draw_with_depth`] at the vertices' sub-pixel positions.
    ///
    /// # Errors
    ///
    /// The target's; drawing stops at the first.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{depth::{DepthBuffer, DepthTarget}, geometry::SubPoint, mesh::{Cull, Mesh}, FlatStyle, Framebuffer};
    ///
    /// let p = |x, y| SubPoint::from(Point::new(x, y));
    /// let v = [(p(0, 0), 500), (p(6, 0), 500), (p(0, 6), 500)];
    /// let mesh = Mesh::new(&v, &[[0, 1, 2]])?;
    /// let (mut pixels, mut depths) = ([Gray8::BLACK; 64], [u16::MAX; 64]);
    /// let mut display = Framebuffer::new(&mut pixels, 8, 8)?;
    /// let mut zbuffer = DepthBuffer::new(&mut depths, 8, 8)?;
    /// let mut scene = DepthTarget::new(&mut display, &mut zbuffer)?;
    /// mesh.draw_with_depth_subpixel(&mut scene, Cull::None, |_, _| FlatStyle::new(Gray8::WHITE)).unwrap();
    /// assert_eq!(depths[8 + 1], 500);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn draw_with_depth_subpixel<D, S, F>(
        &self,
        target: &mut DepthTarget<'_, '_, D>,
        cull: Cull,
        style_of: F,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget,
        S: TriangleStyle<Color = D::Color>,
        F: FnMut(usize, [&V; 3]) -> S,
    {
        self.draw_shapes_with_depth(target, cull, Self::subpixel, style_of)
    }

    /// Draws every triangle not culled into `target`, each with the style `style_of` gives for
    /// its index and vertices.
    ///
    /// # Errors
    ///
    /// The target's; drawing stops at the first.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{mesh::{Cull, Mesh}, FlatStyle, Framebuffer};
    ///
    /// // A square as two triangles sharing a diagonal, both counter-clockwise on screen.
    /// let v = [Point::new(0, 0), Point::new(0, 4), Point::new(4, 4), Point::new(4, 0)];
    /// let mesh = Mesh::new(&v, &[[0, 1, 2], [0, 2, 3]])?;
    /// let mut pixels = [Gray8::BLACK; 16];
    /// let mut display = Framebuffer::new(&mut pixels, 4, 4)?;
    /// let shades = [Gray8::new(100), Gray8::new(200)];
    /// mesh.draw(&mut display, Cull::None, |i, _| FlatStyle::new(shades[i])).unwrap();
    /// assert!(pixels.iter().all(|&p| p != Gray8::BLACK)); // no gap on the diagonal
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn draw<D, S, F>(&self, target: &mut D, cull: Cull, style_of: F) -> Result<(), D::Error>
    where
        D: DrawTarget,
        S: TriangleStyle<Color = D::Color>,
        F: FnMut(usize, [&V; 3]) -> S,
    {
        self.draw_shapes(target, cull, Self::whole, style_of)
    }

    /// Draws every triangle not culled through the depth test of `target`, with each vertex's
    /// [`MeshVertex::depth`].
    ///
    /// # Errors
    ///
    /// The target's; drawing stops at the first.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{depth::{DepthBuffer, DepthTarget}, mesh::{Cull, Mesh}, FlatStyle, Framebuffer};
    ///
    /// // Two overlapping squares' worth of triangles; the second is nearer.
    /// let v = [(Point::new(0, 0), 500), (Point::new(6, 0), 500), (Point::new(0, 6), 500),
    ///          (Point::new(2, 2), 100), (Point::new(8, 2), 100), (Point::new(2, 8), 100)];
    /// let mesh = Mesh::new(&v, &[[3, 4, 5], [0, 1, 2]])?;
    /// let (mut pixels, mut depths) = ([Gray8::BLACK; 64], [u16::MAX; 64]);
    /// let mut display = Framebuffer::new(&mut pixels, 8, 8)?;
    /// let mut zbuffer = DepthBuffer::new(&mut depths, 8, 8)?;
    /// let mut scene = DepthTarget::new(&mut display, &mut zbuffer)?;
    /// let shades = [Gray8::new(255), Gray8::new(80)];
    /// mesh.draw_with_depth(&mut scene, Cull::None, |i, _| FlatStyle::new(shades[i])).unwrap();
    /// assert_eq!(display.pixel(Point::new(3, 3)), Some(Gray8::new(255))); // the near one
    /// assert_eq!(display.pixel(Point::new(1, 1)), Some(Gray8::new(80)));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn draw_with_depth<D, S, F>(
        &self,
        target: &mut DepthTarget<'_, '_, D>,
        cull: Cull,
        style_of: F,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget,
        S: TriangleStyle<Color = D::Color>,
        F: FnMut(usize, [&V; 3]) -> S,
    {
        self.draw_shapes_with_depth(target, cull, Self::whole, style_of)
    }
}
