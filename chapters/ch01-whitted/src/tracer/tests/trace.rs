//! `trace`, the capstone: a tiny picture of a small scene with every kind of surface (a
//! checkered floor, a matte ball, a mirror ball, a glass ball, a mirror seen from behind and one
//! of chapter 06's glossy balls), rendered with your `trace` and with the reference written out
//! below, at several depth limits. When they differ, the reference is rendered again with the
//! usual slips, alone and up to three at a time, to name the ones your picture matches; when
//! none does, the check says where the camera sees what differs.

use common::Ray;
use common::geometry::{Parallelogram, Shape, Sphere};
use common::image::Image;
use common::scene::{Checkerboard, Material, PointLight, Scene, SceneBuilder, Texture};
use glam::{Vec2, Vec3};
use workbench::test_support::image_comparison;

use super::{Asked, Recording, build, close};
use crate::camera::PinholeCamera;
use crate::optics::reflect;
use crate::tracer::{dielectric, direct_light, trace};
use crate::world::World;

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

/// The scene's shapes, in the order [`scene`] builds them, as a message names them.
const SHAPES: [&str; 6] = [
    "the checkered floor",
    "the matte ball",
    "the mirror ball",
    "the glass ball",
    "the mirror seen from behind",
    "chapter 06's glossy ball (its material reflects nothing in this chapter)",
];

/// Where the depth limit is applied, and how.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Depth {
    Right,
    LimitBeforeTheHit,
    OneSegmentMore,
    OneSegmentLess,
}

/// What glass does.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Glass {
    Right,
    IndicesSwapped,
    /// Reflects everything, like a mirror, on both sides.
    AsMirror,
    /// Sends nothing on.
    Black,
}

/// The usual slips in writing `trace`, one choice per part of it; the reference below makes
/// them on purpose.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Slips {
    black_environment: bool,
    depth: Depth,
    mirror_from_behind: bool,
    mirror_without_reflectance: bool,
    /// The mirror's reflected ray is traced at the same depth, not one segment deeper.
    mirror_same_depth: bool,
    glass: Glass,
    checkerboard_ignored: bool,
    /// Chapter 06's glossy material reflects as a mirror.
    glossy_as_mirror: bool,
}

impl Slips {
    const NONE: Slips = Slips {
        black_environment: false,
        depth: Depth::Right,
        mirror_from_behind: false,
        mirror_without_reflectance: false,
        mirror_same_depth: false,
        glass: Glass::Right,
        checkerboard_ignored: false,
        glossy_as_mirror: false,
    };

    /// Every combination of at most `most` slips, the fewest first.
    fn combinations(most: usize) -> Vec<Slips> {
        let mut all = Vec::new();
        for black_environment in [false, true] {
            for depth in [
                Depth::Right,
                Depth::LimitBeforeTheHit,
                Depth::OneSegmentMore,
                Depth::OneSegmentLess,
            ] {
                for mirror_from_behind in [false, true] {
                    for mirror_without_reflectance in [false, true] {
                        for mirror_same_depth in [false, true] {
                            for glass in [
                                Glass::Right,
                                Glass::IndicesSwapped,
                                Glass::AsMirror,
                                Glass::Black,
                            ] {
                                for checkerboard_ignored in [false, true] {
                                    for glossy_as_mirror in [false, true] {
                                        all.push(Slips {
                                            black_environment,
                                            depth,
                                            mirror_from_behind,
                                            mirror_without_reflectance,
                                            mirror_same_depth,
                                            glass,
                                            checkerboard_ignored,
                                            glossy_as_mirror,
                                        });
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
        all.retain(|slips| (1..=most).contains(&slips.words().len()));
        all.sort_by_key(|slips| slips.words().len());
        all
    }

    /// What each slip made here does wrong, in words.
    fn words(self) -> Vec<&'static str> {
        let mut words = Vec::new();
        if self.black_environment {
            words.push(
                "a ray that hits nothing leaves the scene and brings back the environment's \
                 radiance (scene.environment), not black",
            );
        }
        match self.depth {
            Depth::Right => {}
            Depth::LimitBeforeTheHit => words.push(
                "the depth limit is applied before the ray is traced: a ray on its last segment \
                 still sees the environment if it leaves the scene; only a surface it hits has \
                 no segment left to send light back (with max_depth = 1 the camera sees the \
                 background)",
            ),
            Depth::OneSegmentMore => words.push(
                "the depth limit lets one segment more through than max_depth allows: depth \
                 counts segments with the camera ray as 1, and a surface hit on segment \
                 max_depth has no segment left for its light (not even a shadow ray)",
            ),
            Depth::OneSegmentLess => words.push(
                "the depth limit stops one segment early: a surface hit on segment \
                 max_depth - 1 still has one segment left (the shadow ray, or one more bounce)",
            ),
        }
        if self.mirror_from_behind {
            words.push(
                "the mirror seen from behind reflects: mirrors reflect on their front side only \
                 (the side hit.n points to, as in Mitsuba), and the back is black",
            );
        }
        if self.mirror_without_reflectance {
            words.push(
                "the mirror reflects everything: the reflected radiance is weighted by the \
                 mirror's reflectance, colour by colour",
            );
        }
        if self.mirror_same_depth {
            words.push(
                "the mirror's reflected ray is traced at the same depth as the ray that arrived: \
                 every reflected or refracted ray is one segment deeper (depth + 1)",
            );
        }
        match self.glass {
            Glass::Right => {}
            Glass::IndicesSwapped => words.push(
                "the glass looks like a bubble of air in glass: int_ior is the index inside \
                 the glass and ext_ior the one outside; dielectric takes them in that order",
            ),
            Glass::AsMirror => words.push(
                "the glass reflects everything, like a mirror: glass shares the light between a \
                 reflected and a refracted ray, which dielectric sends on",
            ),
            Glass::Black => words.push(
                "the glass is black: glass sends on a reflected and a refracted ray (your \
                 dielectric does it), each one segment deeper",
            ),
        }
        if self.checkerboard_ignored {
            words.push(
                "the checkered floor has one colour: its albedo at the hit is \
                 scene.albedo(texture, hit.uv)",
            );
        }
        if self.glossy_as_mirror {
            words.push(
                "chapter 06's glossy ball reflects like a mirror: the materials of later \
                 chapters reflect nothing here",
            );
        }
        words
    }
}

/// Whitted's recursion as the chapter tells it, with `slips` made on purpose.
fn reference<W: World>(world: &W, ray: &Ray, depth: u32, slips: Slips) -> Vec3 {
    let scene = world.scene();
    if slips.depth == Depth::LimitBeforeTheHit && depth >= scene.max_depth {
        return Vec3::ZERO;
    }
    let Some(hit) = world.intersect(ray) else {
        return if slips.black_environment {
            Vec3::ZERO
        } else {
            scene.environment
        };
    };
    let out_of_segments = match slips.depth {
        Depth::OneSegmentMore => depth > scene.max_depth,
        Depth::OneSegmentLess => depth + 1 >= scene.max_depth,
        Depth::Right | Depth::LimitBeforeTheHit => depth >= scene.max_depth,
    };
    if out_of_segments {
        return Vec3::ZERO;
    }
    let mirror = |weight: Vec3, from_behind: bool, deeper: u32| {
        if !hit.front_face(ray.dir) && !from_behind {
            return Vec3::ZERO;
        }
        let reflected = hit.spawn_ray(reflect(ray.dir, hit.n), ray.time);
        weight * reference(world, &reflected, depth + deeper, slips)
    };
    match scene.surface(hit.shape).material {
        Material::Diffuse { albedo, two_sided } => {
            direct_light(world, ray, &hit, albedo, two_sided)
        }
        Material::TexturedDiffuse { texture, two_sided } => {
            let albedo = match texture {
                Texture::Checkerboard(checkerboard) if slips.checkerboard_ignored => {
                    checkerboard.colour0
                }
                _ => scene.albedo(texture, hit.uv),
            };
            direct_light(world, ray, &hit, albedo, two_sided)
        }
        Material::Mirror { reflectance } => {
            let weight = if slips.mirror_without_reflectance {
                Vec3::ONE
            } else {
                reflectance
            };
            let deeper = u32::from(!slips.mirror_same_depth);
            mirror(weight, slips.mirror_from_behind, deeper)
        }
        Material::Dielectric { int_ior, ext_ior } => match slips.glass {
            Glass::AsMirror => mirror(Vec3::ONE, true, 1),
            Glass::Black => Vec3::ZERO,
            Glass::Right | Glass::IndicesSwapped => {
                let (inside, outside) = if slips.glass == Glass::IndicesSwapped {
                    (ext_ior, int_ior)
                } else {
                    (int_ior, ext_ior)
                };
                dielectric(ray, &hit, inside, outside, &mut |next| {
                    reference(world, next, depth + 1, slips)
                })
            }
        },
        Material::Glossy(glossy) if slips.glossy_as_mirror => mirror(glossy.reflectance, false, 1),
        Material::Glossy(_)
        | Material::RoughGlass(_)
        | Material::Conductor(_)
        | Material::ThinDielectric { .. }
        | Material::Plastic(_)
        | Material::Mask(_)
        | Material::TintedGlass(_) => Vec3::ZERO,
    }
}

/// The camera ray through the centre of pixel `(x, y)`, at [`TIME`].
fn camera_ray(world: &Recording, x: u32, y: u32) -> Ray {
    let camera = PinholeCamera::of(&world.scene.camera, SIZE.0, SIZE.1);
    let p_film = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
    camera.generate_ray(p_film).with_time(TIME)
}

/// The picture `radiance` makes of `world` (one ray through each pixel centre, at [`TIME`]),
/// and the rays it asked the world about.
fn render(world: &Recording, mut radiance: impl FnMut(&Ray) -> Vec3) -> (Image, u64) {
    let mut image = Image::new(SIZE.0, SIZE.1);
    let mut rays = 0;
    for y in 0..SIZE.1 {
        for x in 0..SIZE.0 {
            let ray = camera_ray(world, x, y);
            image.set(x, y, radiance(&ray));
            let asked = world.take();
            rays += asked.len() as u64;
            if let Some(late) = asked.iter().find(|a| a.ray.time != TIME) {
                panic!(
                    "trace: a ray of the path through pixel ({x}, {y}) travels at shutter time \
                     {}, the camera ray at {TIME}: every ray spawned keeps ray.time (chapter \
                     05 moves objects with it)",
                    late.ray.time
                );
            }
            if let Some(nowhere) = asked.iter().find(|a| !super::goes_somewhere(&a.ray)) {
                panic!(
                    "trace: a ray of the path through pixel ({x}, {y}) goes from {} along {}, \
                     which goes nowhere: every ray it spawns leaves from the hit \
                     (hit.spawn_ray) along a unit direction",
                    nowhere.ray.origin, nowhere.ray.dir
                );
            }
        }
    }
    (image, rays)
}

/// Whether `a` and `b` agree at the pixels `at` picks.
fn same_where(a: &Image, b: &Image, at: impl Fn(usize) -> bool) -> bool {
    a.pixels
        .iter()
        .zip(&b.pixels)
        .enumerate()
        .all(|(i, (p, q))| !at(i) || close(*p, *q, 1e-3))
}

/// The reference's picture with `slips`.
fn slipped(world: &Recording, slips: Slips) -> Image {
    render(world, |ray| reference(world, ray, 1, slips)).0
}

/// The words for slips `found`: each set's, joined by "or else".
fn looks_as_if(found: &[Slips]) -> String {
    let each: Vec<String> = found
        .iter()
        .map(|slips| format!("it looks as if {}", slips.words().join(";\n  and ")))
        .collect();
    each.join(";\n  or else ")
}

/// What your picture `mine` gets wrong against `expected`, in words: the slips that make the
/// reference draw exactly your picture, or else, for each part of the scene the camera sees
/// where they differ, what your pixels there look like and the slips that explain that part
/// (when one set of them alone does).
fn what_differs(world: &Recording, mine: &Image, expected: &Image) -> String {
    let combinations = Slips::combinations(3);
    // The fewest slips that draw `mine` where `at` says; when several sets of as many do, each.
    let explain = |at: &dyn Fn(usize) -> bool| {
        let mut found: Vec<Slips> = Vec::new();
        for &slips in &combinations {
            if found
                .first()
                .is_some_and(|first| first.words().len() < slips.words().len())
            {
                break;
            }
            if same_where(mine, &slipped(world, slips), at) {
                found.push(slips);
            }
        }
        found
    };
    let everywhere = explain(&|_| true);
    if !everywhere.is_empty() {
        return looks_as_if(&everywhere);
    }
    // What the camera sees first through each pixel.
    let seen: Vec<Option<usize>> = (0..SIZE.1)
        .flat_map(|y| (0..SIZE.0).map(move |x| (x, y)))
        .map(|(x, y)| {
            let ray = camera_ray(world, x, y);
            world
                .scene
                .geometry
                .intersect(&ray)
                .map(|hit| hit.shape as usize)
        })
        .collect();
    let mut parts = Vec::new();
    for part in std::iter::once(None).chain((0..SHAPES.len()).map(Some)) {
        let here = |i: usize| seen[i] == part;
        let pixels = (0..seen.len()).filter(|&i| here(i)).count();
        let differ: Vec<usize> = (0..seen.len())
            .filter(|&i| here(i) && !close(mine.pixels[i], expected.pixels[i], 1e-3))
            .collect();
        let Some(&first) = differ.first() else {
            continue;
        };
        let (x, y) = (first as u32 % SIZE.0, first as u32 / SIZE.0);
        let name = part.map_or("the environment", |shape| SHAPES[shape]);
        let black = if differ.iter().all(|&i| mine.pixels[i] == Vec3::ZERO) {
            ", and all of yours are black"
        } else {
            ""
        };
        let found = explain(&here);
        let why = if found.len() == 1 {
            format!(": {}", looks_as_if(&found))
        } else {
            String::new()
        };
        parts.push(format!(
            "where the camera sees {name}, {} of its {pixels} pixels differ{black} (pixel \
             ({x}, {y}): yours {}, expected {}){why}",
            differ.len(),
            mine.pixels[first],
            expected.pixels[first]
        ));
    }
    format!(
        "the picture differs from the reference, and no usual slip explains all of it:\n  {}",
        parts.join(";\n  ")
    )
}

/// The first ray of `asked` that starts exactly at a point where another ray of `asked` hits a
/// surface, in words.
fn starts_on_a_surface(world: &Recording, asked: &[Asked]) -> Option<String> {
    let hits: Vec<Vec3> = asked
        .iter()
        .filter(|a| !a.shadow && super::goes_somewhere(&a.ray))
        .filter_map(|a| world.scene.geometry.intersect(&a.ray))
        .map(|hit| hit.p)
        .collect();
    asked
        .iter()
        .filter(|a| !a.shadow)
        .find(|a| hits.contains(&a.ray.origin))
        .map(|a| {
            format!(
                "a ray it sent on from a surface, along {}, starts exactly at the hit point {}, \
                 which rounding can leave a hair on the wrong side of the surface, so that the \
                 ray hits its own surface (black specks; this scene happens not to show them): \
                 every secondary ray leaves by hit.spawn_ray, which moves its origin off the \
                 surface",
                a.ray.dir, a.ray.origin
            )
        })
}

/// Renders the scene at `max_depth` with your `trace` and with the reference; fails naming the
/// slips it sees.
fn check_at_depth(max_depth: u32) {
    let mut world = Recording::new(scene(max_depth));
    world.limit = 5_000;
    // Your picture, with every ray your trace asked the world about.
    let mut on_a_surface = None;
    let (mine, my_rays) = render(&world, |ray| {
        let radiance = trace(&world, ray, 1);
        let asked = world.take();
        on_a_surface = on_a_surface
            .take()
            .or_else(|| starts_on_a_surface(&world, &asked));
        // Put back for `render`'s own checks.
        world.asked.lock().unwrap().extend(asked);
        radiance
    });
    let (expected, rays) = render(&world, |ray| reference(&world, ray, 1, Slips::NONE));
    let exercise = "ch01-trace";
    if let Some(p) = mine.pixels.iter().find(|p| !p.is_finite()) {
        panic!(
            "trace, max_depth = {max_depth}: a pixel is {p}, not a finite colour; {}",
            image_comparison(exercise, &mine, &expected)
        );
    }
    if !same_where(&mine, &expected, |_| true) {
        panic!(
            "trace, max_depth = {max_depth}: {}.\n  {}",
            what_differs(&world, &mine, &expected),
            image_comparison(exercise, &mine, &expected)
        );
    }
    if let Some(on_a_surface) = on_a_surface {
        panic!("trace, max_depth = {max_depth}: the picture is right, but {on_a_surface}");
    }
    // The rays your trace traced, against the reference's.
    assert!(
        my_rays == rays,
        "trace, max_depth = {max_depth}: the picture is right, but your trace traced {} rays \
         (shadow rays included) where Whitted's recursion traces {rays} for it: {}",
        my_rays,
        if my_rays > rays {
            "some of yours cannot change the picture. Does every reflected or refracted ray go \
             one segment deeper (depth + 1), and does a ray whose share is zero stay untraced?"
        } else {
            "some rays that can change a picture were not traced"
        }
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
