//! The scene's shapes together with the BVH over them.

use super::aabb::Aabb;
use super::bvh::Bvh;
use super::hit::SurfaceHit;
use super::shapes::{Crossing, Shape};
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
}

impl Geometry {
    /// Takes ownership of the shapes and builds the BVH over them.
    pub fn new(shapes: Vec<Shape>) -> Self {
        let bounds: Vec<Aabb> = shapes.iter().map(Shape::bounds).collect();
        let bvh = Bvh::build(&bounds);
        Self { shapes, bvh }
    }

    /// The nearest hit with `0 < t < ray.t_max`; its `shape` is an index into
    /// [`shapes`](Self::shapes).
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        // Every closer crossing replaces the last; the record is built for the nearest only.
        let mut nearest: Option<(usize, Crossing)> = None;
        self.bvh.intersect(ray, |index, t_max| {
            let crossing = self.shapes[index].crossing(&Ray { t_max, ..*ray })?;
            nearest = Some((index, crossing));
            Some(crossing.t)
        });
        let (index, crossing) = nearest?;
        Some(SurfaceHit {
            shape: index as u32,
            ..self.shapes[index].surface_hit(crossing)
        })
    }

    /// Whether anything lies on the ray before `ray.t_max` (a shadow test). Cheaper than
    /// [`intersect`](Self::intersect): it stops at the first hit found, nearest or not.
    pub fn occluded(&self, ray: &Ray) -> bool {
        self.bvh
            .any_hit(ray, |index| self.shapes[index].crossing(ray).is_some())
    }

    /// The shapes, in the order given to [`new`](Self::new).
    pub fn shapes(&self) -> &[Shape] {
        &self.shapes
    }

    /// A box around every shape ([`Aabb::empty`] for an empty scene).
    pub fn bounds(&self) -> Aabb {
        self.bvh.bounds()
    }

    /// The BVH, for statistics.
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }
}
