//! The checks of the tracer's three exercises, one file each, and what they share: a world that
//! writes down every ray it is asked about.

mod dielectric;
mod direct_light;
mod trace;

use std::sync::Mutex;

use common::Ray;
use common::geometry::SurfaceHit;
use common::scene::{Camera, CameraFrame, FilmSettings, Scene, SceneBuilder};
use glam::Vec3;

use crate::world::World;

/// A ray the tracer asked the world about, and which question it asked.
#[derive(Clone, Copy, Debug)]
struct Asked {
    ray: Ray,
    /// `true` for a shadow ray (`occluded`), `false` for `intersect`.
    shadow: bool,
}

/// A world that answers from its scene and writes down every ray it is asked about, so a check
/// can say what a ray did wrong (its time, its origin, where it stops). It refuses to answer
/// more than `limit` questions, so that a recursion without end fails with a message instead
/// of overflowing the stack.
struct Recording {
    scene: Scene,
    asked: Mutex<Vec<Asked>>,
    limit: usize,
}

impl Recording {
    fn new(scene: Scene) -> Self {
        Self {
            scene,
            asked: Mutex::new(Vec::new()),
            limit: 100_000,
        }
    }

    /// The rays asked about since the last call, and forgets them.
    fn take(&self) -> Vec<Asked> {
        std::mem::take(&mut *self.asked.lock().unwrap())
    }

    fn record(&self, ray: &Ray, shadow: bool) {
        let mut asked = self.asked.lock().unwrap();
        asked.push(Asked { ray: *ray, shadow });
        if asked.len() > self.limit {
            let count = asked.len();
            drop(asked);
            panic!(
                "{count} rays for one camera ray, and still going: does every reflected or \
                 refracted ray go one segment deeper (depth + 1), and does the depth limit stop \
                 the recursion?"
            );
        }
    }
}

/// Whether `ray` goes somewhere: a finite origin and a finite, non-zero direction. A ray that
/// does not is written down (the check says what made it) but never reaches the geometry.
fn goes_somewhere(ray: &Ray) -> bool {
    ray.origin.is_finite() && ray.dir.is_finite() && ray.dir != Vec3::ZERO
}

impl World for Recording {
    fn scene(&self) -> &Scene {
        &self.scene
    }

    fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        self.record(ray, false);
        goes_somewhere(ray)
            .then(|| self.scene.geometry.intersect(ray))
            .flatten()
    }

    fn occluded(&self, ray: &Ray) -> bool {
        self.record(ray, true);
        goes_somewhere(ray) && self.scene.geometry.occluded(ray)
    }
}

/// `builder`'s scene seen by a pinhole at `origin` looking at `target` on a `width x height`
/// film, limited to `max_depth` segments.
fn build(
    builder: SceneBuilder,
    origin: Vec3,
    target: Vec3,
    (width, height): (u32, u32),
    max_depth: u32,
) -> Scene {
    let frame = CameraFrame::look_at(origin, target, Vec3::Y).expect("a valid frame");
    builder.build(
        Camera::pinhole(frame, 50.0),
        FilmSettings::new(width, height),
        max_depth,
    )
}

/// Whether `a` and `b` agree to a relative `tolerance` in every channel.
fn close(a: Vec3, b: Vec3, tolerance: f32) -> bool {
    ((a - b).abs() - tolerance * a.abs().max(b.abs())).max_element() <= 1e-7
}
