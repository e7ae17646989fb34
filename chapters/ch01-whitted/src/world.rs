//! What the tracer asks of the world.
//!
//! The scene itself is the workbook's one scene model, [`common::scene::Scene`]: shapes with
//! their surfaces, point lights, the environment, the camera. This chapter adds the two
//! questions its tracer asks of the shapes.

use common::Ray;
use common::geometry::SurfaceHit;
use common::render::count_ray;
use common::scene::Scene;

// ANCHOR: world
/// What the tracer asks of the world: the nearest surface on a ray, and whether a shadow ray
/// is blocked. Surfaces, lights and the environment come from [`World::scene`].
///
/// The scene answers from its still geometry. A later chapter adds what it needs behind the
/// same two questions (chapter 05: objects that move with the ray's `time`) and reuses the
/// tracer as it is. A hit's `shape` indexes the scene's `surfaces`. Each answer is one ray
/// cast, which the world counts for the render's statistics
/// ([`count_ray`](common::render::count_ray)), so the tracers that ask need not.
pub trait World: Sync {
    /// The surfaces, lights, environment and depth limit.
    fn scene(&self) -> &Scene;
    /// The nearest hit with `0 < t < ray.t_max`.
    fn intersect(&self, ray: &Ray) -> Option<SurfaceHit>;
    /// Whether anything lies on the ray before `ray.t_max`.
    fn occluded(&self, ray: &Ray) -> bool;
}
// ANCHOR_END: world

/// The scene's still shapes (moving ones are chapter 05's: a scene with them is refused by
/// the capability check before it reaches this chapter's tracer).
impl World for Scene {
    fn scene(&self) -> &Scene {
        self
    }

    fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        count_ray();
        self.geometry.intersect(ray)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        count_ray();
        self.geometry.occluded(ray)
    }
}
