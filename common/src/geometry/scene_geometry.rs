//! The scene's shapes together with the BVH over them.

use super::aabb::Aabb;
use super::bvh::Bvh;
use super::hit::SurfaceHit;
use super::shapes::{Corners, Crossing, RaySpace, Shape};
use crate::Ray;

/// All the shapes of a scene and the BVH that finds which one a ray meets first.
///
/// Materials and lights are not here: a hit reports the index of its shape
/// ([`SurfaceHit::shape`]), and the chapters keep whatever they attach to shapes in vectors
/// indexed the same way.
#[derive(Clone, Debug, Default)]
pub struct Geometry {
    shapes: Vec<Shape>,
    bvh: Bvh,
    /// What the ray tests need of the shapes in the BVH, in its leaf order: a leaf's shapes
    /// lie side by side, and a triangle's three vertices are all a test reads of it.
    tests: Vec<ShapeTest>,
    /// Whether any shape is a triangle: the walk then works out each ray's [`RaySpace`].
    has_triangles: bool,
}

/// A shape as the walk of the BVH tests it.
#[derive(Clone, Copy, Debug)]
enum ShapeTest {
    /// A triangle with area: its vertices, axis by axis, and its index in `shapes`.
    Triangle { corners: Corners, shape: u32 },
    /// Any other shape, tested as `shapes[shape]`.
    Other { shape: u32 },
}

impl ShapeTest {
    fn shape(&self) -> usize {
        match *self {
            ShapeTest::Triangle { shape, .. } | ShapeTest::Other { shape } => shape as usize,
        }
    }
}

impl Geometry {
    /// Takes ownership of the shapes and builds the BVH over them.
    pub fn new(shapes: Vec<Shape>) -> Self {
        // A triangle without area (or with a NaN vertex) is never hit: its box is left empty,
        // so the BVH leaves it out, and the walk tests the others without asking.
        let has_area = |triangle: &super::Triangle| triangle.area() > 0.0; // false for NaN
        let bounds: Vec<Aabb> = shapes
            .iter()
            .map(|shape| match shape {
                Shape::Triangle(triangle) if !has_area(triangle) => Aabb::empty(),
                _ => shape.bounds(),
            })
            .collect();
        let bvh = Bvh::build(&bounds);
        let tests = bvh
            .leaf_order()
            .iter()
            .map(|&index| match &shapes[index as usize] {
                Shape::Triangle(triangle) => ShapeTest::Triangle {
                    corners: Corners::new(&triangle.p),
                    shape: index,
                },
                _ => ShapeTest::Other { shape: index },
            })
            .collect();
        let has_triangles = shapes
            .iter()
            .any(|shape| matches!(shape, Shape::Triangle(_)));
        Self {
            shapes,
            bvh,
            tests,
            has_triangles,
        }
    }

    /// Where the ray crosses the shape at `position` in the BVH's leaf order. `space` is the
    /// ray's [`RaySpace`] ([`ray_space`](Self::ray_space)).
    #[inline]
    fn crossing(&self, position: usize, ray: &Ray, space: Option<&RaySpace>) -> Option<Crossing> {
        match &self.tests[position] {
            ShapeTest::Triangle { corners, .. } => space?.crossing(corners, ray.t_max),
            ShapeTest::Other { shape } => self.shapes[*shape as usize].crossing(ray),
        }
    }

    /// The ray's [`RaySpace`], worked out once per ray for all the triangles it meets: none
    /// for a zero direction, which crosses no triangle, or where there are no triangles.
    fn ray_space(&self, ray: &Ray) -> Option<RaySpace> {
        if self.has_triangles {
            RaySpace::new(ray)
        } else {
            None
        }
    }

    /// The nearest hit with `0 < t < ray.t_max`; its `shape` is an index into
    /// [`shapes`](Self::shapes).
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        // Every closer crossing replaces the last; the record is built for the nearest only.
        let mut nearest: Option<(usize, Crossing)> = None;
        let space = self.ray_space(ray);
        self.bvh.intersect_in_leaf_order(ray, |position, t_max| {
            let crossing = self.crossing(position, &Ray { t_max, ..*ray }, space.as_ref())?;
            nearest = Some((position, crossing));
            Some(crossing.t)
        });
        let (position, crossing) = nearest?;
        let index = self.tests[position].shape();
        Some(SurfaceHit {
            shape: index as u32,
            ..self.shapes[index].surface_hit(crossing)
        })
    }

    /// Whether anything lies on the ray before `ray.t_max` (a shadow test). Cheaper than
    /// [`intersect`](Self::intersect): it stops at the first hit found, nearest or not.
    pub fn occluded(&self, ray: &Ray) -> bool {
        let space = self.ray_space(ray);
        self.bvh.any_hit_in_leaf_order(ray, |position| {
            self.crossing(position, ray, space.as_ref()).is_some()
        })
    }

    /// The shapes, in the order given to [`new`](Self::new).
    pub fn shapes(&self) -> &[Shape] {
        &self.shapes
    }

    /// A box around every shape ([`Aabb::empty`] for an empty scene).
    pub fn bounds(&self) -> Aabb {
        self.bvh.bounds()
    }

    /// The bytes the geometry takes: its shapes, its BVH and the walk's copy of them.
    pub fn memory_bytes(&self) -> usize {
        std::mem::size_of_val(self.shapes.as_slice())
            + self.bvh.memory_bytes()
            + std::mem::size_of_val(self.tests.as_slice())
    }

    /// The BVH, for statistics.
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }
}
