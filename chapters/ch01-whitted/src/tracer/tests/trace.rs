//! `trace`, the capstone: a tiny picture of a small scene with every kind of surface (a
//! checkered floor, a matte ball, a mirror ball, a glass ball, a mirror seen from behind and one
//! of chapter 06's glossy balls), rendered with your `trace` and with the reference written out
//! below, at several depth limits. When they differ, the reference is rendered again with the
//! usual slips, one at a time, to name the one your picture matches.

use common::Ray;
use common::geometry::{Parallelogram, Shape, Sphere};
use common::image::Image;
use common::render::SampleCounters;
use common::scene::{Checkerboard, Material, PointLight, Scene, SceneBuilder, Texture};
use common::test_support::image_comparison;
use glam::{Vec2, Vec3};

use super::{Recording, build, close};
use crate::camera::PinholeCamera;
use crate::optics::reflect;
use crate::scene::World;
use crate::tracer::{dielectric, direct_light, trace};

/// The shutter time of every camera ray: every ray of its path must keep it.
const TIME: f32 = 0.4;
const SIZE: (u32, u32) = (24, 18);

fn scene(max_depth: u32) -> Scene {
    let checkerboard =
        Checkerboard::scaled(Vec3::splat(0.8), Vec3::new(0.2, 0.3, 0.2), Vec2::splat(2.0));
    let builder = SceneBuilder::new()
        .environment(Vec3::new(0.2, 0.3, 0.5))
        .shape(
            Shape::Parallelogram(Parallelogram::new(
                Vec3::new(-4.0, 0.0, 4.0),
                8.0 * Vec3::X,
                -8.0 * Vec3::Z,
            )),
            Material::TexturedDiffuse {
                texture: Texture::Checkerboard(checkerboard),
                two_sided: false,
            },
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(-1.3, 0.5, 0.0), 0.5)),
            Material::diffuse(Vec3::new(0.8, 0.3, 0.2)),
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(0.0, 0.6, -0.6), 0.6)),
            Material::Mirror {
                reflectance: Vec3::new(0.9, 0.8, 0.6),
            },
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(1.2, 0.5, 0.4), 0.5)),
            Material::glass(1.5),
        )
        .shape(
            // Its normal, e1 x e2 = -z, points away from the camera: we see its back.
            Shape::Parallelogram(Parallelogram::new(
                Vec3::new(-2.4, 1.2, -0.5),
                0.8 * Vec3::Y,
                0.9 * Vec3::X,
            )),
            Material::mirror(),
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(0.4, 0.2, 1.3), 0.2)),
            Material::glossy(Vec3::splat(0.9), 20.0),
        )
        .light(PointLight {
            position: Vec3::new(2.0, 4.0, 3.0),
            intensity: Vec3::splat(30.0),
        });
    build(
        builder,
        Vec3::new(0.0, 1.5, 5.0),
        Vec3::new(0.0, 0.6, 0.0),
        SIZE,
        max_depth,
    )
}

/// The usual slips in writing `trace`, each of which the reference below can make on purpose.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Slip {
    None,
    BlackEnvironment,
    LimitBeforeTheHit,
    OneSegmentMore,
    OneSegmentLess,
    MirrorFromBehind,
    MirrorWithoutReflectance,
    IndicesSwapped,
    CheckerboardIgnored,
}

impl Slip {
    const ALL: [Slip; 8] = [
        Slip::BlackEnvironment,
        Slip::LimitBeforeTheHit,
        Slip::OneSegmentMore,
        Slip::OneSegmentLess,
        Slip::MirrorFromBehind,
        Slip::MirrorWithoutReflectance,
        Slip::IndicesSwapped,
        Slip::CheckerboardIgnored,
    ];

    fn words(self) -> &'static str {
        match self {
            Slip::None => "",
            Slip::BlackEnvironment => {
                "a ray that hits nothing leaves the scene and brings back the environment's \
                 radiance (scene.environment), not black"
            }
            Slip::LimitBeforeTheHit => {
                "the depth limit is applied before the ray is traced: a ray on its last segment \
                 still sees the environment if it leaves the scene; only a surface it hits has \
                 no segment left to send light back (with max_depth = 1 the camera sees the \
                 background)"
            }
            Slip::OneSegmentMore => {
                "the depth limit lets one segment more through than max_depth allows: depth \
                 counts segments with the camera ray as 1, and a surface hit on segment \
                 max_depth has no segment left for its light (not even a shadow ray)"
            }
            Slip::OneSegmentLess => {
                "the depth limit stops one segment early: a surface hit on segment \
                 max_depth - 1 still has one segment left (the shadow ray, or one more bounce)"
            }
            Slip::MirrorFromBehind => {
                "the mirror seen from behind reflects: mirrors reflect on their front side only \
                 (as in Mitsuba), and the back is black"
            }
            Slip::MirrorWithoutReflectance => {
                "the mirror reflects everything: the reflected radiance is weighted by the \
                 mirror's reflectance, colour by colour"
            }
            Slip::IndicesSwapped => {
                "the glass looks like a bubble of air in glass: int_ior is the index inside \
                 the glass and ext_ior the one outside; dielectric takes them in that order"
            }
            Slip::CheckerboardIgnored => {
                "the checkered floor has one colour: its albedo at the hit is \
                 scene.albedo(texture, hit.uv)"
            }
        }
    }
}

/// Whitted's recursion as the chapter tells it, with `slip` made on purpose.
fn reference<W: World>(
    world: &W,
    ray: &Ray,
    depth: u32,
    slip: Slip,
    counters: &mut SampleCounters,
) -> Vec3 {
    counters.rays += 1;
    let scene = world.scene();
    if slip == Slip::LimitBeforeTheHit && depth >= scene.max_depth {
        return Vec3::ZERO;
    }
    let Some(hit) = world.intersect(ray) else {
        return match slip {
            Slip::BlackEnvironment => Vec3::ZERO,
            _ => scene.environment,
        };
    };
    let out_of_segments = match slip {
        Slip::OneSegmentMore => depth > scene.max_depth,
        Slip::OneSegmentLess => depth + 1 >= scene.max_depth,
        _ => depth >= scene.max_depth,
    };
    if out_of_segments {
        return Vec3::ZERO;
    }
    match scene.surface(hit.shape).material {
        Material::Diffuse { albedo, two_sided } => {
            direct_light(world, ray, &hit, albedo, two_sided, counters)
        }
        Material::TexturedDiffuse { texture, two_sided } => {
            let albedo = match (slip, texture) {
                (Slip::CheckerboardIgnored, Texture::Checkerboard(checkerboard)) => {
                    checkerboard.colour0
                }
                _ => scene.albedo(texture, hit.uv),
            };
            direct_light(world, ray, &hit, albedo, two_sided, counters)
        }
        Material::Mirror { reflectance } => {
            if !hit.front_face(ray.dir) && slip != Slip::MirrorFromBehind {
                return Vec3::ZERO;
            }
            let weight = match slip {
                Slip::MirrorWithoutReflectance => Vec3::ONE,
                _ => reflectance,
            };
            let reflected = hit.spawn_ray(reflect(ray.dir, hit.n), ray.time);
            weight * reference(world, &reflected, depth + 1, slip, counters)
        }
        Material::Dielectric { int_ior, ext_ior } => {
            let (inside, outside) = match slip {
                Slip::IndicesSwapped => (ext_ior, int_ior),
                _ => (int_ior, ext_ior),
            };
            dielectric(ray, &hit, inside, outside, &mut |next| {
                reference(world, next, depth + 1, slip, counters)
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
}

/// The picture `radiance` makes of `world` (one ray through each pixel centre, at [`TIME`]),
/// and the rays it counted.
fn render(
    world: &Recording,
    mut radiance: impl FnMut(&Ray, &mut SampleCounters) -> Vec3,
) -> (Image, u64) {
    let camera = PinholeCamera::of(&world.scene.camera, SIZE.0, SIZE.1);
    let mut image = Image::new(SIZE.0, SIZE.1);
    let mut counters = SampleCounters::default();
    for y in 0..SIZE.1 {
        for x in 0..SIZE.0 {
            let p_film = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            let ray = camera.generate_ray(p_film).with_time(TIME);
            image.set(x, y, radiance(&ray, &mut counters));
            if let Some(late) = world.take().iter().find(|a| a.ray.time != TIME) {
                panic!(
                    "trace: a ray of the path through pixel ({x}, {y}) travels at shutter time \
                     {}, the camera ray at {TIME}: every ray spawned keeps ray.time (chapter \
                     05 moves objects with it)",
                    late.ray.time
                );
            }
        }
    }
    (image, counters.rays)
}

fn same(a: &Image, b: &Image) -> bool {
    a.pixels
        .iter()
        .zip(&b.pixels)
        .all(|(p, q)| close(*p, *q, 1e-3))
}

/// Renders the scene at `max_depth` with your `trace` and with the reference; fails naming the
/// slip it sees.
fn check_at_depth(max_depth: u32) {
    let mut world = Recording::new(scene(max_depth));
    world.limit = 5_000;
    let (mine, my_rays) = render(&world, |ray, counters| trace(&world, ray, 1, counters));
    let (expected, rays) = render(&world, |ray, counters| {
        reference(&world, ray, 1, Slip::None, counters)
    });
    let exercise = "ch01-trace";
    if let Some(p) = mine.pixels.iter().find(|p| !p.is_finite()) {
        panic!(
            "trace, max_depth = {max_depth}: a pixel is {p}, not a finite colour; {}",
            image_comparison(exercise, &mine, &expected)
        );
    }
    if !same(&mine, &expected) {
        let slip = Slip::ALL.into_iter().find(|&slip| {
            let (slipped, _) = render(&world, |ray, counters| {
                reference(&world, ray, 1, slip, counters)
            });
            same(&mine, &slipped)
        });
        let what = match slip {
            Some(slip) => format!("it looks as if {}", slip.words()),
            None => "the picture differs from the reference".to_string(),
        };
        panic!(
            "trace, max_depth = {max_depth}: {what}.\n  {}",
            image_comparison(exercise, &mine, &expected)
        );
    }
    assert!(
        my_rays == rays,
        "trace, max_depth = {max_depth}: the picture is right, but counters.rays counted \
         {my_rays} rays where {rays} were traced: count every ray trace follows, once (the \
         shadow rays are counted by direct_light)"
    );
}

/// Runs `check` on a thread with a deep stack, so that a recursion that does not stop is
/// caught by the world's count of rays rather than by a stack overflow. The thread takes the
/// test's name, under which a failing check writes its pictures.
fn with_deep_stack(check: impl FnOnce() + Send + 'static) {
    let name = std::thread::current()
        .name()
        .unwrap_or("the check of trace")
        .to_string();
    let handle = std::thread::Builder::new()
        .name(name)
        .stack_size(256 << 20)
        .spawn(check)
        .expect("a thread for the check");
    if let Err(panic) = handle.join() {
        std::panic::resume_unwind(panic);
    }
}

#[test]
fn exercise_trace_renders_the_small_scene() {
    with_deep_stack(|| check_at_depth(6));
}

#[test]
fn exercise_trace_stops_at_the_depth_limit() {
    with_deep_stack(|| {
        for max_depth in [1, 2, 3] {
            check_at_depth(max_depth);
        }
    });
}
