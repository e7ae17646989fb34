//! The scene's shapes together with the BVH over them.

use super::aabb::Aabb;
use super::bvh::{Bvh, EMPTY_SLOT, LEAF_BLOCK};
use super::hit::SurfaceHit;
use super::shapes::{Crossing, FourTriangles, RaySpace, Shape, TRIANGLE_LANES};
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
    /// What the ray tests need of each leaf of the BVH, one record per leaf block: a leaf's
    /// triangles are tested together, and their vertices are all a test reads of them.
    leaves: Vec<LeafTest>,
    /// The indices in `shapes` of each leaf's shapes, one record per leaf block; read for the
    /// hit alone, so kept apart from what every test reads.
    leaf_shapes: Vec<[u32; LEAF_BLOCK]>,
    /// Whether any leaf holds triangles: the walk then works out each ray's [`RaySpace`].
    has_triangles: bool,
}

/// What one nearest-hit query cost the structure ([`Geometry::intersect_counted`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WalkCount {
    /// BVH nodes the ray was tested against (each four boxes at once).
    pub nodes: usize,
    /// Leaves whose shapes were tested.
    pub leaves: usize,
}

/// The shapes of one leaf, as the walk of the BVH tests them.
#[derive(Clone, Copy, Debug)]
enum LeafTest {
    /// Triangles (each with area), one per lane: their vertices, tested four at once.
    Triangles(FourTriangles),
    /// Other shapes, or a mix, tested one by one.
    Shapes,
}

impl LeafTest {
    /// The record of the leaf whose shapes are `leaf`.
    fn new(leaf: &[u32], shapes: &[Shape]) -> Self {
        let vertices: Option<Vec<[glam::Vec3; 3]>> = leaf
            .iter()
            .map(|&i| match &shapes[i as usize] {
                Shape::Triangle(triangle) => Some(triangle.p),
                _ => None,
            })
            .collect();
        match vertices {
            Some(vertices) if leaf.len() <= TRIANGLE_LANES => {
                LeafTest::Triangles(FourTriangles::new(&vertices))
            }
            _ => LeafTest::Shapes,
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
        // Triangles are tested a leaf at a time (`FourTriangles`), every other shape alone.
        let batched: Vec<bool> = shapes
            .iter()
            .map(|shape| matches!(shape, Shape::Triangle(_)))
            .collect();
        let bvh = Bvh::build_batched(&bounds, &batched);
        let leaf_shapes: Vec<[u32; LEAF_BLOCK]> = bvh
            .leaf_order()
            .chunks(LEAF_BLOCK)
            .map(|block| std::array::from_fn(|k| block.get(k).copied().unwrap_or(EMPTY_SLOT)))
            .collect();
        let leaves: Vec<LeafTest> = leaf_shapes
            .iter()
            .map(|block| {
                let count = block.iter().take_while(|&&i| i != EMPTY_SLOT).count();
                LeafTest::new(&block[..count], &shapes)
            })
            .collect();
        let has_triangles = leaves
            .iter()
            .any(|leaf| matches!(leaf, LeafTest::Triangles(_)));
        Self {
            shapes,
            bvh,
            leaves,
            leaf_shapes,
            has_triangles,
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
    /// [`shapes`](Self::shapes). None for a ray that goes nowhere ([`Ray`] says which).
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        self.intersect_counted(ray).0
    }

    /// [`intersect`](Self::intersect), and what the query cost the structure: for measuring
    /// how the work grows with the scene ([`measure_bvh_cost`](super::measure_bvh_cost)).
    pub fn intersect_counted(&self, ray: &Ray) -> (Option<SurfaceHit>, WalkCount) {
        // Every closer crossing replaces the last; the record is built for the nearest only.
        let mut nearest: Option<(u32, Crossing)> = None;
        let mut leaves = 0;
        let space = self.ray_space(ray);
        let nodes = self.bvh.nearest_leaves(ray, |leaf, count, t_max| {
            leaves += 1;
            let (shape, crossing) = match &self.leaves[leaf] {
                LeafTest::Triangles(triangles) => {
                    let (lane, crossing) =
                        space.as_ref()?.nearest_crossing(triangles, count, t_max)?;
                    (self.leaf_shapes[leaf][lane], crossing)
                }
                LeafTest::Shapes => {
                    self.nearest_of(&self.leaf_shapes[leaf][..count], ray, t_max)?
                }
            };
            nearest = Some((shape, crossing));
            Some(crossing.t)
        });
        let hit = nearest.map(|(shape, crossing)| SurfaceHit {
            shape,
            ..self.shapes[shape as usize].surface_hit(crossing)
        });
        (hit, WalkCount { nodes, leaves })
    }

    /// The nearest crossing of the ray limited to `t < t_max` with one of `shapes`, tested in
    /// order, and that shape.
    fn nearest_of(&self, shapes: &[u32], ray: &Ray, mut t_max: f32) -> Option<(u32, Crossing)> {
        let mut nearest = None;
        for &shape in shapes {
            if let Some(crossing) = self.shapes[shape as usize].crossing(&Ray { t_max, ..*ray })
                && crossing.t < t_max
            {
                t_max = crossing.t;
                nearest = Some((shape, crossing));
            }
        }
        nearest
    }

    /// Whether anything lies on the ray before `ray.t_max` (a shadow test). Cheaper than
    /// [`intersect`](Self::intersect): it stops at the first hit found, nearest or not. False
    /// for a ray that goes nowhere ([`Ray`] says which).
    pub fn occluded(&self, ray: &Ray) -> bool {
        let space = self.ray_space(ray);
        self.bvh
            .any_leaf(ray, |leaf, count| match &self.leaves[leaf] {
                LeafTest::Triangles(triangles) => space
                    .as_ref()
                    .is_some_and(|space| space.any_crossing(triangles, count, ray.t_max)),
                LeafTest::Shapes => self.leaf_shapes[leaf][..count]
                    .iter()
                    .any(|&shape| self.shapes[shape as usize].crossing(ray).is_some()),
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
            + std::mem::size_of_val(self.leaves.as_slice())
            + std::mem::size_of_val(self.leaf_shapes.as_slice())
    }

    /// The BVH, for statistics.
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }
}
