//! The tracer that draws this chapter's images: chapter 01's recursion through a world in
//! motion, where a path is one camera ray and every ray spawned after it.
//!
//! The world answers each ray at the ray's own time ([`MotionScene`]'s `World`). Which time a
//! ray carries is the tracer's business: the camera ray gets the time the sample drew, and
//! every ray the path spawns from a hit (a mirror's reflection, glass's reflection and
//! refraction, the shadow rays towards the lights) gets one too.

use crate::world::MotionScene;
use common::Ray;
use glam::Vec3;

// ANCHOR: trace_in_motion
/// The radiance arriving along `ray` through the world in motion, `ray` being segment number
/// `depth` of its path (the camera ray is segment 1, and a path has at most the scene's
/// `max_depth` segments). It is chapter 01's recursion: a ray that hits nothing brings back
/// the scene's `environment`; a matte surface (plain or textured) is lit by the point lights it
/// sees, through chapter 01's `direct_light`; a mirror reflects, on its front side only; glass
/// reflects and refracts through chapter 01's `dielectric`; the materials of later chapters
/// reflect nothing.
///
/// Every ray the path spawns from a hit needs a time, the rays that `direct_light` and
/// `dielectric` spawn included (they take it from the ray you hand them). Which time makes
/// the image the average of the world over the shutter, and which would show a mirror image
/// or a shadow that does not belong to the world the camera ray saw?
pub fn trace_in_motion(world: &MotionScene, ray: &Ray, depth: u32) -> Vec3 {
    // BEGIN SOLUTION
    use ch01_whitted::optics::reflect;
    use ch01_whitted::tracer::{dielectric, direct_light};
    use ch01_whitted::world::World;
    use common::scene::Material;

    let scene = world.scene();
    let Some(hit) = world.intersect(ray) else {
        return scene.environment;
    };
    if depth >= scene.max_depth {
        return Vec3::ZERO;
    }
    match scene.surface(hit.shape).material {
        Material::Diffuse { albedo, two_sided } => {
            direct_light(world, ray, &hit, albedo, two_sided)
        }
        Material::TexturedDiffuse { texture, two_sided } => {
            direct_light(world, ray, &hit, scene.albedo(texture, hit.uv), two_sided)
        }
        Material::Mirror { reflectance } => {
            if !hit.front_face(ray.dir) {
                return Vec3::ZERO;
            }
            // The path's one instant: the reflected ray sees the world when the camera ray did.
            let reflected = hit.spawn_ray(reflect(ray.dir, hit.n), ray.time);
            reflectance * trace_in_motion(world, &reflected, depth + 1)
        }
        Material::Dielectric { int_ior, ext_ior } => {
            dielectric(ray, &hit, int_ior, ext_ior, &mut |next| {
                trace_in_motion(world, next, depth + 1)
            })
        }
        Material::Glossy(_)
        | Material::RoughGlass(_)
        | Material::Conductor(_)
        | Material::ThinDielectric { .. }
        | Material::Plastic(_)
        | Material::Mask(_)
        | Material::TintedGlass(_) => Vec3::ZERO,
    }
    // END SOLUTION
}
// ANCHOR_END: trace_in_motion

#[cfg(test)]
mod tests {
    use super::*;
    use ch01_whitted::tracer::trace as still_trace;
    use common::geometry::{Parallelogram, Shape, Sphere};
    use common::scene::{Camera, CameraFrame, FilmSettings, Material, PointLight, SceneBuilder};
    use glam::Mat4;

    /// The shutter of every test scene: open from 1 to 2, so that neither 0 nor the opening
    /// is the time of a path in the middle of it.
    const OPEN: f32 = 1.0;
    const CLOSE: f32 = 2.0;

    /// The times a wrong answer may have given a spawned ray, with their names.
    const OTHER_TIMES: [(f32, &str); 4] = [
        (0.0, "the time 0"),
        (OPEN, "the shutter's opening time"),
        (CLOSE, "the shutter's closing time"),
        (0.5 * (OPEN + CLOSE), "the middle of the shutter"),
    ];

    /// The path times the checks trace at.
    const PATH_TIMES: [f32; 2] = [1.25, 1.75];

    /// A scene with the matte sphere of `radius` (lit by `light`) moving from `from` at time 0
    /// to `to` at time 2, or, with `frozen_at`, standing still where it is at that time;
    /// `others` are the still shapes.
    fn world(
        others: &[(Shape, Material)],
        light: Vec3,
        radius: f32,
        (from, to): (Vec3, Vec3),
        frozen_at: Option<f32>,
    ) -> MotionScene {
        let mut builder = SceneBuilder::new()
            .environment(Vec3::splat(0.2))
            .light(PointLight {
                position: light,
                intensity: Vec3::splat(80.0),
            });
        for (shape, material) in others {
            builder = builder.shape(*shape, material.clone());
        }
        let material = Material::diffuse(Vec3::new(0.9, 0.5, 0.2));
        builder = match frozen_at {
            Some(time) => builder.shape(
                Shape::Sphere(Sphere::new(from.lerp(to, time / 2.0), radius)),
                material,
            ),
            None => builder.moving(
                Shape::Sphere(Sphere::new(Vec3::ZERO, radius)),
                vec![
                    (0.0, Mat4::from_translation(from)),
                    (2.0, Mat4::from_translation(to)),
                ],
                material,
            ),
        };
        let frame = CameraFrame::look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap();
        let mut scene = builder.build(Camera::pinhole(frame, 40.0), FilmSettings::new(8, 8), 6);
        scene.camera.shutter_open = OPEN;
        scene.camera.shutter_close = CLOSE;
        MotionScene::new(scene).unwrap()
    }

    /// One of the checks' scenes: the moving object seen by one kind of spawned ray only.
    struct Case {
        /// The spawned ray that alone sees the moving sphere, as the message names it.
        ray_kind: &'static str,
        /// What that ray shows of the sphere.
        shows: &'static str,
        /// The scene, moving (`None`) or frozen at a time.
        world: fn(Option<f32>) -> MotionScene,
        /// The rays the check sends, at time 0 (each is given the path's time).
        rays: Vec<Ray>,
    }

    /// The mirror at z = -3 faces the rays; the sphere slides behind their origins, where only
    /// the reflected rays can see it.
    fn mirror_world(frozen_at: Option<f32>) -> MotionScene {
        let mirror = Shape::Parallelogram(Parallelogram::new(
            Vec3::new(-8.0, -8.0, -3.0),
            16.0 * Vec3::X,
            16.0 * Vec3::Y,
        ));
        let reflectance = Vec3::splat(0.9);
        world(
            &[(mirror, Material::Mirror { reflectance })],
            Vec3::new(0.0, 3.0, 0.0),
            0.8,
            (Vec3::new(-3.0, 0.0, 3.0), Vec3::new(3.0, 0.0, 3.0)),
            frozen_at,
        )
    }

    /// A floor seen from above; the sphere slides high over the rays' origins, where only the
    /// shadow rays towards the light above it can meet it.
    fn shadow_world(frozen_at: Option<f32>) -> MotionScene {
        let floor = Shape::Parallelogram(Parallelogram::new(
            Vec3::new(-8.0, 0.0, -8.0),
            16.0 * Vec3::Z,
            16.0 * Vec3::X,
        ));
        world(
            &[(floor, Material::diffuse(Vec3::splat(0.7)))],
            Vec3::new(0.0, 10.0, 0.0),
            1.0,
            (Vec3::new(-2.0, 5.0, 0.0), Vec3::new(2.0, 5.0, 0.0)),
            frozen_at,
        )
    }

    /// A glass ball in front of the rays; the sphere slides behind it, seen only through it.
    fn glass_world(frozen_at: Option<f32>) -> MotionScene {
        let ball = Shape::Sphere(Sphere::new(Vec3::new(0.0, 0.0, -3.0), 1.0));
        let glass = Material::Dielectric {
            int_ior: 1.5,
            ext_ior: 1.0,
        };
        world(
            &[(ball, glass)],
            Vec3::new(0.0, 4.0, -6.0),
            1.0,
            (Vec3::new(-2.5, 0.0, -7.5), Vec3::new(2.5, 0.0, -7.5)),
            frozen_at,
        )
    }

    /// Rays along `dir` from a grid of `n x n` origins `origin + i a + j b`.
    fn grid(origin: Vec3, a: Vec3, b: Vec3, n: usize, dir: Vec3) -> Vec<Ray> {
        let mut rays = Vec::new();
        for i in 0..n {
            for j in 0..n {
                let (u, v) = (i as f32 / (n - 1) as f32, j as f32 / (n - 1) as f32);
                rays.push(Ray::new(origin + u * a + v * b, dir));
            }
        }
        rays
    }

    /// The scenes, the shadow's first: the mirror and the glass scenes light their sphere too,
    /// so a shadow ray at another time would show there as well, under another name.
    fn cases() -> [Case; 3] {
        [
            Case {
                ray_kind: "the shadow rays towards the light",
                shows: "the shadow on the floor was cast by the sphere",
                world: shadow_world,
                rays: grid(
                    Vec3::new(-6.0, 3.0, -1.5),
                    12.0 * Vec3::X,
                    3.0 * Vec3::Z,
                    25,
                    -Vec3::Y,
                ),
            },
            Case {
                ray_kind: "the mirror's reflected ray",
                shows: "the mirror showed the sphere",
                world: mirror_world,
                rays: grid(
                    Vec3::new(-4.0, -1.0, 0.0),
                    8.0 * Vec3::X,
                    2.0 * Vec3::Y,
                    25,
                    -Vec3::Z,
                ),
            },
            Case {
                ray_kind: "the rays that glass reflects and refracts",
                shows: "the glass ball showed the sphere behind it",
                world: glass_world,
                rays: grid(
                    Vec3::new(-0.6, -0.6, 0.0),
                    1.2 * Vec3::X,
                    1.2 * Vec3::Y,
                    15,
                    -Vec3::Z,
                ),
            },
        ]
    }

    /// How many of `a` and `b` (radiance along the same rays) differ by more than rounding.
    fn differing(a: &[Vec3], b: &[Vec3]) -> usize {
        a.iter()
            .zip(b)
            .filter(|(x, y)| (**x - **y).abs().max_element() > 1e-3 * (1.0 + x.max_element()))
            .count()
    }

    /// The radiance chapter 01's tracer brings back along `rays` at `time` through `world`,
    /// where nothing moves.
    fn still_radiance(world: &MotionScene, rays: &[Ray], time: f32) -> Vec<Vec3> {
        rays.iter()
            .map(|ray| still_trace(world, &ray.with_time(time), 1))
            .collect()
    }

    /// What is wrong with `trace_in_motion` in `case` at the path time `time`, in words;
    /// `None` if it is right. A few rays that graze the sphere's outline may differ by
    /// rounding between the moving and the frozen sphere, so up to 2% of them may disagree.
    fn one_time_mistake(case: &Case, time: f32) -> Option<String> {
        let allowed = case.rays.len() / 50;
        let frozen = (case.world)(Some(time));
        let expected = still_radiance(&frozen, &case.rays, time);
        // The scene has to tell the path's time from every other: else the check could not fail.
        for (other, _) in OTHER_TIMES {
            let elsewhere = still_radiance(&(case.world)(Some(other)), &case.rays, other);
            let apart = differing(&expected, &elsewhere);
            assert!(
                apart > 4 * allowed,
                "the test's scene for {} cannot tell {time} from {other} ({apart} rays)",
                case.ray_kind
            );
        }
        let still: Vec<Vec3> = case
            .rays
            .iter()
            .map(|ray| trace_in_motion(&frozen, &ray.with_time(time), 1))
            .collect();
        let wrong = differing(&still, &expected);
        if wrong > allowed {
            return Some(format!(
                "in a world where nothing moves, {wrong} of {} rays brought back other radiance \
                 than chapter 01's tracer gives: before the time, the recursion itself is \
                 wrong (the materials, the depth limit, the mirror's front side)",
                case.rays.len()
            ));
        }
        let moving = (case.world)(None);
        let got: Vec<Vec3> = case
            .rays
            .iter()
            .map(|ray| trace_in_motion(&moving, &ray.with_time(time), 1))
            .collect();
        if differing(&got, &expected) <= allowed {
            return None;
        }
        let other = OTHER_TIMES.iter().find(|(other, _)| {
            differing(
                &got,
                &still_radiance(&(case.world)(Some(*other)), &case.rays, *other),
            ) <= allowed
        });
        let which = match other {
            Some((_, name)) => format!("{name} of its own"),
            None => "a time of its own".to_string(),
        };
        Some(format!(
            "{} got {which}, not the camera ray's time {time}: {} where it is at another \
             instant. A path sees the world at one instant: every ray spawned from a hit \
             keeps the time of the ray it continues, so that the image is the average over \
             the shutter of whole pictures of the world",
            case.ray_kind, case.shows
        ))
    }

    #[test]
    fn exercise_trace_in_motion_keeps_one_time_per_path() {
        for case in cases() {
            for time in PATH_TIMES {
                if let Some(mistake) = one_time_mistake(&case, time) {
                    panic!("trace_in_motion: {mistake}");
                }
            }
        }
    }

    #[test]
    fn without_motion_it_is_chapter_01_s_tracer_bit_for_bit() {
        let world = crate::scenes::Builtin::Pan.build(6, crate::Shutter::INSTANT);
        for ray in grid(
            Vec3::new(-1.0, 0.2, 6.0),
            2.0 * Vec3::X,
            1.5 * Vec3::Y,
            12,
            Vec3::new(0.0, -0.1, -1.0),
        ) {
            assert_eq!(
                trace_in_motion(&world, &ray, 1),
                still_trace(&world, &ray, 1)
            );
        }
    }
}
