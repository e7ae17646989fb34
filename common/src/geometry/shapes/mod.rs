//! The shapes a scene is made of.
//!
//! Each shape has the same three duties: report its nearest hit along a ray (with a
//! conservative bound on the error of the hit point), give a box that certainly contains it,
//! and know its area (for sampling area lights).

mod disc;
mod mesh;
mod plane;
mod quad;
mod sphere;
mod triangle;

pub use disc::Disc;
pub use mesh::{MeshError, TriangleMesh};
pub use quad::Quad;
pub use sphere::Sphere;
pub use triangle::Triangle;

use crate::Ray;
use crate::geometry::aabb::Aabb;
use crate::geometry::hit::SurfaceHit;

/// Any one shape.
///
/// An enum rather than a trait object: the set of shapes is closed, a `match` is easy to read,
/// and a `Vec<Shape>` keeps the shapes contiguous in memory.
///
/// The geometric normal each shape reports: outward for spheres, `normalize(e1 × e2)` for
/// quads, `(p1 - p0) × (p2 - p0)` (normalised) for triangles and the given normal for discs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// A sphere.
    Sphere(Sphere),
    /// A triangle.
    Triangle(Triangle),
    /// A parallelogram.
    Quad(Quad),
    /// A flat disc.
    Disc(Disc),
}

impl Shape {
    /// The nearest hit with `0 < t < ray.t_max`, with `shape` set to 0.
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        match self {
            Shape::Sphere(s) => s.intersect(ray),
            Shape::Triangle(s) => s.intersect(ray),
            Shape::Quad(s) => s.intersect(ray),
            Shape::Disc(s) => s.intersect(ray),
        }
    }

    /// A box that certainly contains the shape.
    pub fn bounds(&self) -> Aabb {
        match self {
            Shape::Sphere(s) => s.bounds(),
            Shape::Triangle(s) => s.bounds(),
            Shape::Quad(s) => s.bounds(),
            Shape::Disc(s) => s.bounds(),
        }
    }

    /// The surface area.
    pub fn area(&self) -> f32 {
        match self {
            Shape::Sphere(s) => s.area(),
            Shape::Triangle(s) => s.area(),
            Shape::Quad(s) => s.area(),
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

impl From<Quad> for Shape {
    fn from(s: Quad) -> Self {
        Shape::Quad(s)
    }
}

impl From<Disc> for Shape {
    fn from(s: Disc) -> Self {
        Shape::Disc(s)
    }
}
