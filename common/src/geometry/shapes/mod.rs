//! The shapes a scene is made of.
//!
//! Each shape has the same three duties: report its nearest hit along a ray (with a
//! conservative bound on the error of the hit point), give a box that certainly contains it,
//! and know its area (for sampling area lights).

mod bumpy_sphere;
mod disc;
mod dp_du;
mod four_triangles;
mod mesh;
mod mesh_split;
mod parallelogram;
mod plane;
mod sphere;
mod triangle;

pub use disc::Disc;
pub(crate) use four_triangles::{FourTriangles, LANES as TRIANGLE_LANES, RaySpace};
pub use mesh::{MeshError, TriangleMesh};
pub use parallelogram::Parallelogram;
pub use sphere::Sphere;
pub use triangle::Triangle;

use crate::Ray;
use crate::geometry::aabb::Aabb;
use crate::geometry::hit::SurfaceHit;

/// Where a ray crosses a shape, before its hit record is built.
///
/// Finding a crossing is the test; building the record (the point and its error bound, the
/// normals, the texture coordinates, for a sphere an arc tangent and an arc cosine) is extra
/// work that only the *nearest* crossing of a ray needs, and a shadow ray, which asks only
/// whether there is one, never does. So a shape answers in two steps: [`Shape::crossing`],
/// then [`Shape::surface_hit`] for the one crossing that is kept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// The ray parameter of the crossing, `0 < t < ray.t_max`.
    pub t: f32,
    /// The shape's own coordinates of the point, which its record is built from: a parallelogram's
    /// `(u, v)`, a disc's offsets along its tangents, a triangle's barycentrics, the offset
    /// of a sphere's point from its centre.
    pub(crate) coords: [f32; 3],
}

/// Any one shape.
///
/// An enum rather than a trait object: the set of shapes is closed, a `match` is easy to read,
/// and a `Vec<Shape>` keeps the shapes contiguous in memory.
///
/// The geometric normal each shape reports: outward for spheres, `normalize(e1 × e2)` for
/// parallelograms, `(p1 - p0) × (p2 - p0)` (normalised) for triangles and the given normal for discs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// A sphere.
    Sphere(Sphere),
    /// A triangle.
    Triangle(Triangle),
    /// A parallelogram.
    Parallelogram(Parallelogram),
    /// A flat disc.
    Disc(Disc),
}

impl Shape {
    /// The nearest hit with `0 < t < ray.t_max`, with `shape` set to 0.
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        self.crossing(ray)
            .map(|crossing| self.surface_hit(crossing))
    }

    /// Where `ray` crosses the shape with `0 < t < ray.t_max`, without building the record:
    /// [`intersect`](Self::intersect) is this followed by [`surface_hit`](Self::surface_hit).
    #[inline]
    pub fn crossing(&self, ray: &Ray) -> Option<Crossing> {
        match self {
            Shape::Sphere(s) => s.crossing(ray),
            Shape::Triangle(s) => s.checked_crossing(ray),
            Shape::Parallelogram(s) => s.crossing(ray),
            Shape::Disc(s) => s.crossing(ray),
        }
    }

    /// The hit record of a crossing this shape reported.
    pub fn surface_hit(&self, crossing: Crossing) -> SurfaceHit {
        match self {
            Shape::Sphere(s) => s.surface_hit(crossing),
            Shape::Triangle(s) => s.surface_hit(crossing),
            Shape::Parallelogram(s) => s.surface_hit(crossing),
            Shape::Disc(s) => s.surface_hit(crossing),
        }
    }

    /// A box that certainly contains the shape.
    pub fn bounds(&self) -> Aabb {
        match self {
            Shape::Sphere(s) => s.bounds(),
            Shape::Triangle(s) => s.bounds(),
            Shape::Parallelogram(s) => s.bounds(),
            Shape::Disc(s) => s.bounds(),
        }
    }

    /// The surface area.
    pub fn area(&self) -> f32 {
        match self {
            Shape::Sphere(s) => s.area(),
            Shape::Triangle(s) => s.area(),
            Shape::Parallelogram(s) => s.area(),
            Shape::Disc(s) => s.area(),
        }
    }
}

impl From<Sphere> for Shape {
    fn from(s: Sphere) -> Self {
        Shape::Sphere(s)
    }
}

impl From<Triangle> for Shape {
    fn from(s: Triangle) -> Self {
        Shape::Triangle(s)
    }
}

impl From<Parallelogram> for Shape {
    fn from(s: Parallelogram) -> Self {
        Shape::Parallelogram(s)
    }
}

impl From<Disc> for Shape {
    fn from(s: Disc) -> Self {
        Shape::Disc(s)
    }
}
