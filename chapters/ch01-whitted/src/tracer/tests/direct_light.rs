//! `direct_light`: a matte floor under point lights, against the radiance worked out here by
//! hand; shadows, lights behind the surface, the back side, and what the shadow rays look like.

use std::f32::consts::PI;

use common::Ray;
use common::geometry::{Parallelogram, Shape, Sphere, SurfaceHit};
use common::scene::{Material, PointLight, SceneBuilder};
use glam::{Vec2, Vec3};

use super::{Asked, Recording, build, close};
use crate::tracer::direct_light;

const ALBEDO: Vec3 = Vec3::new(0.8, 0.5, 0.2);
const INTENSITY: Vec3 = Vec3::new(10.0, 6.0, 3.0);
/// The shutter time of the rays that arrive at the floor: shadow rays must keep it.
const TIME: f32 = 0.7;
/// Where the rays come from, and the point of the floor they look at.
const EYE: Vec3 = Vec3::new(0.0, 3.0, 3.0);
const TARGET: Vec3 = Vec3::new(0.3, 0.0, -0.2);

/// The floor `y = 0`, its normal `+y`, with the point lights at `lights` (offsets from
/// [`TARGET`]) and `blockers` (matte spheres, centre offset from `TARGET` and radius).
fn floor_world(lights: &[Vec3], blockers: &[(Vec3, f32)], two_sided: bool) -> Recording {
    let floor = Parallelogram::new(Vec3::new(-5.0, 0.0, 5.0), 10.0 * Vec3::X, -10.0 * Vec3::Z);
    let material = Material::Diffuse {
        albedo: ALBEDO,
        two_sided,
    };
    let mut builder = SceneBuilder::new().shape(Shape::Parallelogram(floor), material);
    for &(centre, radius) in blockers {
        builder = builder.shape(
            Shape::Sphere(Sphere::new(TARGET + centre, radius)),
            Material::diffuse(Vec3::ONE),
        );
    }
    for &offset in lights {
        builder = builder.light(PointLight {
            position: TARGET + offset,
            intensity: INTENSITY,
        });
    }
    Recording::new(build(builder, EYE, TARGET, (8, 8), 5))
}

/// What `direct_light` answers for the ray from `from` to [`TARGET`], and the hit it lit.
fn light_floor(world: &Recording, from: Vec3, two_sided: bool) -> (Vec3, SurfaceHit) {
    let ray = Ray::new(from, (TARGET - from).normalize()).with_time(TIME);
    let hit = world
        .scene
        .geometry
        .intersect(&ray)
        .expect("the ray sees the floor");
    let radiance = direct_light(world, &ray, &hit, ALBEDO, two_sided);
    (radiance, hit)
}

/// What a light at `light` with normal `normal` gives at `p`, as the lecture has it.
fn expected_from(light: Vec3, p: Vec3, normal: Vec3) -> Vec3 {
    let to_light = light - p;
    let r2 = to_light.length_squared();
    let cos_theta = normal.dot(to_light) / r2.sqrt();
    ALBEDO / PI * INTENSITY * cos_theta / r2
}

/// What is wrong with `mine`, the radiance from one light at `light` onto `p` (normal
/// `normal`), in words; `None` if it is right. `asked` are the rays `direct_light` asked
/// `world` about, which tell why a lit point came out black.
fn one_light_mistake(
    world: &Recording,
    asked: &[Asked],
    mine: Vec3,
    light: Vec3,
    p: Vec3,
    normal: Vec3,
) -> Option<String> {
    let expected = expected_from(light, p, normal);
    if close(mine, expected, 1e-4) {
        return None;
    }
    let to_light = light - p;
    let (r2, r) = (to_light.length_squared(), to_light.length());
    let cos_theta = normal.dot(to_light) / r;
    let looks_like = |factor: f32| close(mine, expected * factor, 1e-3);
    let mistake = if !mine.is_finite() {
        "it is not a finite colour".to_string()
    } else if mine == Vec3::ZERO {
        black_but_lit(world, asked)
    } else if looks_like(PI) {
        "it is pi times too bright: a matte surface reflects albedo / pi of the irradiance per \
         unit solid angle (so that all it reflects over the hemisphere adds up to the albedo)"
            .to_string()
    } else if looks_like(1.0 / cos_theta) {
        "cos(theta) is missing: light arriving at a slant spreads over more area, so the \
         irradiance is I cos(theta) / r^2"
            .to_string()
    } else if looks_like(r2) {
        "1 / r^2 is missing: a point light's irradiance falls off with the square of the \
         distance"
            .to_string()
    } else if looks_like(r) {
        "it is divided by r, not r^2: the irradiance falls off with the square of the \
         distance (and cos(theta) needs the unit direction to the light)"
            .to_string()
    } else if looks_like(1.0 / r) {
        "it is divided by r^3: cos(theta) is the dot product of two unit vectors, and the \
         irradiance falls off with r^2"
            .to_string()
    } else if close(mine, ALBEDO * INTENSITY * cos_theta / r2, 1e-3)
        || close(mine, INTENSITY * cos_theta / (PI * r2), 1e-3)
    {
        "the albedo or the light's intensity is not in it, colour by colour".to_string()
    } else {
        "it is not albedo / pi times the irradiance I cos(theta) / r^2".to_string()
    };
    Some(format!(
        "{mistake}.\n  Light {INTENSITY} at distance {r:.3}, cos(theta) = {cos_theta:.3}: your \
         direct_light gave {mine}, the lecture's formula gives {expected}"
    ))
}

/// Why a point that one light shines on, with nothing in the way, came out black, from the
/// rays `direct_light` asked `world` about.
fn black_but_lit(world: &Recording, asked: &[Asked]) -> String {
    let shadow: Vec<&Ray> = asked.iter().filter(|a| a.shadow).map(|a| &a.ray).collect();
    let Some(ray) = shadow.first() else {
        return "it is black and traced no shadow ray, but the light shines on this point \
                (cos(theta) > 0) and nothing is in the way: such a light is counted"
            .to_string();
    };
    if !super::goes_somewhere(ray) {
        format!(
            "it is black, and its shadow ray goes nowhere (from {} along {}): a shadow ray goes \
             from the point towards the light, hit.spawn_ray_to(light.position, ray.time)",
            ray.origin, ray.dir
        )
    } else if world.scene.geometry.occluded(ray) {
        "it is black, but the light shines on this point and nothing is in the way: its shadow \
         ray was blocked by something it should not see (the surface itself, or what lies \
         beyond the light)"
            .to_string()
    } else {
        "it is black, although nothing blocked its shadow ray (world.occluded answered \
         false): occluded is true when something is in the way, and a light whose shadow ray is \
         not blocked counts"
            .to_string()
    }
}

/// The first ray `direct_light` asked about that goes nowhere (a direction that is NaN or
/// zero), in words.
fn ray_to_nowhere(asked: &[Asked]) -> Option<String> {
    asked
        .iter()
        .find(|a| !super::goes_somewhere(&a.ray))
        .map(|a| {
            format!(
                "it traced a shadow ray from {} along {}, which goes nowhere",
                a.ray.origin, a.ray.dir
            )
        })
}

/// Why a light below a floor lit from above needs no shadow ray.
const BEHIND: &str = "a light behind the surface (cos(theta) <= 0) cannot light it, so it needs \
                      no shadow ray";

/// The rays `direct_light` asked about (`asked`), checked: shadow rays only, each going
/// somewhere, at the arriving ray's time, and `needed` of them; `why_none` says why the others
/// need none.
fn check_shadow_rays(asked: &[Asked], needed: usize, case: &str, why_none: &str) {
    let shadow: Vec<_> = asked.iter().filter(|a| a.shadow).collect();
    if let Some(nowhere) = ray_to_nowhere(asked) {
        panic!(
            "direct_light ({case}): {nowhere}: a shadow ray goes from the point towards the \
             light, hit.spawn_ray_to(light.position, ray.time)"
        );
    }
    if let Some(first) = asked.iter().find(|a| !a.shadow) {
        panic!(
            "direct_light ({case}): it asked the world for the nearest hit along {:?}; a shadow \
             ray only needs to know whether anything is in the way (world.occluded)",
            first.ray
        );
    }
    if let Some(wrong) = shadow.iter().find(|a| a.ray.time != TIME) {
        panic!(
            "direct_light ({case}): a shadow ray travels at shutter time {}, but the ray that \
             arrived here travels at {TIME}: every ray of a path keeps the camera ray's time \
             (chapter 05 moves objects with it)",
            wrong.ray.time
        );
    }
    if shadow.len() > needed {
        panic!(
            "direct_light ({case}): it traced {} shadow rays where {needed} can change the \
             answer: {why_none}",
            shadow.len()
        );
    }
    if shadow.len() < needed {
        panic!(
            "direct_light ({case}): it traced {} shadow rays, but {needed} lights shine on the \
             point: each needs its own shadow ray",
            shadow.len()
        );
    }
}

#[test]
fn exercise_direct_light_of_one_light() {
    let light = Vec3::new(1.0, 2.0, 0.5);
    let world = floor_world(&[light], &[], false);
    let (mine, hit) = light_floor(&world, EYE, false);
    let asked = world.take();
    if let Some(mistake) = one_light_mistake(&world, &asked, mine, TARGET + light, hit.p, Vec3::Y) {
        panic!("direct_light, one light above the floor: {mistake}");
    }
    check_shadow_rays(&asked, 1, "one light above the floor", BEHIND);
}

#[test]
fn exercise_direct_light_adds_every_light() {
    let lights = [Vec3::new(1.0, 2.0, 0.5), Vec3::new(-2.0, 1.0, -1.0)];
    let world = floor_world(&lights, &[], false);
    let (mine, hit) = light_floor(&world, EYE, false);
    let each = lights.map(|l| expected_from(TARGET + l, hit.p, Vec3::Y));
    let expected = each[0] + each[1];
    let asked = world.take();
    assert!(
        close(mine, expected, 1e-4),
        "direct_light, two lights above the floor: it gave {mine}; the lights give {} and {} on \
         their own, and together their sum {expected}{}",
        each[0],
        each[1],
        if close(mine, each[0], 1e-4) || close(mine, each[1], 1e-4) {
            ": only one of them was counted".to_string()
        } else if mine == Vec3::ZERO {
            format!(": {}", black_but_lit(&world, &asked))
        } else {
            String::new()
        }
    );
    check_shadow_rays(&asked, 2, "two lights above the floor", BEHIND);
}

#[test]
fn exercise_direct_light_ignores_lights_behind_the_surface() {
    let above = Vec3::new(1.0, 2.0, 0.5);
    let world = floor_world(&[Vec3::new(0.5, -1.0, 0.0), above], &[], false);
    let (mine, hit) = light_floor(&world, EYE, false);
    let expected = expected_from(TARGET + above, hit.p, Vec3::Y);
    let asked = world.take();
    if !close(mine, expected, 1e-4) {
        let behind = expected_from(TARGET + Vec3::new(0.5, -1.0, 0.0), hit.p, Vec3::Y);
        panic!(
            "direct_light, one light above the floor and one below it: it gave {mine}, where \
             only the light above shines on the floor ({expected}){}",
            if close(mine, expected + behind, 1e-3) {
                ". The light below added its negative cos(theta): a light behind the surface \
                 gives nothing, it does not take light away"
                    .to_string()
            } else if close(mine, expected - behind, 1e-3) {
                ". The light below was counted with |cos(theta)|: it is behind the surface and \
                 gives nothing"
                    .to_string()
            } else if mine == Vec3::ZERO {
                format!(": {}", black_but_lit(&world, &asked))
            } else {
                String::new()
            }
        );
    }
    check_shadow_rays(&asked, 1, "a light below the floor", BEHIND);
}

#[test]
fn exercise_direct_light_casts_shadows() {
    let light = Vec3::new(1.0, 2.0, 0.5);
    // A ball halfway to the light.
    let world = floor_world(&[light], &[(0.5 * light, 0.3)], false);
    let (mine, _) = light_floor(&world, EYE, false);
    let asked = world.take();
    if mine != Vec3::ZERO {
        let answered_blocked = asked.iter().any(|a| {
            a.shadow && super::goes_somewhere(&a.ray) && world.scene.geometry.occluded(&a.ray)
        });
        panic!(
            "direct_light: a ball hangs between the floor and the only light, so the point is in \
             its shadow and black, but it gave {mine}: {}",
            if answered_blocked {
                "world.occluded answered true for its shadow ray (the ball is in the way), yet \
                 the light was counted: a light counts only when its shadow ray is not blocked"
            } else {
                "ask world.occluded whether a shadow ray towards the light is blocked"
            }
        );
    }
    check_shadow_rays(&asked, 1, "a ball between the floor and the light", BEHIND);

    // A ball beyond the light, on the same line: it must not cast a shadow.
    let world = floor_world(&[light], &[(2.5 * light, 1.0)], false);
    let (mine, hit) = light_floor(&world, EYE, false);
    let asked = world.take();
    let past = asked.iter().filter(|a| a.shadow).find(|a| {
        let reach = a.ray.t_max * a.ray.dir.length();
        reach > (TARGET + light - a.ray.origin).length() * 1.001
    });
    if let Some(past) = past.filter(|_| mine == Vec3::ZERO) {
        panic!(
            "direct_light: the point is black, because its shadow ray goes past the light and \
             hits a ball behind it (t_max = {}, dir = {}). A shadow ray asks only about what \
             lies between the point and the light: hit.spawn_ray_to(target, time) makes one \
             that stops just short of its target.",
            past.ray.t_max, past.ray.dir
        );
    }
    if let Some(mistake) = one_light_mistake(&world, &asked, mine, TARGET + light, hit.p, Vec3::Y) {
        panic!("direct_light, with a ball beyond the light: {mistake}");
    }
}

#[test]
fn exercise_direct_light_leaves_its_own_surface() {
    // A point of a ball that rounding left a hair inside it, as computed hit points can be: its
    // error bound says how far off it may be. The light is straight out along the normal.
    let centre = TARGET + Vec3::new(0.0, 1.5, 0.0);
    let radius = 0.8;
    let n = Vec3::new(0.3, 1.0, 0.2).normalize();
    let ball = Sphere::new(centre, radius);
    let light = centre + 5.0 * n;
    let world = Recording::new(build(
        SceneBuilder::new()
            .shape(
                Shape::Sphere(ball),
                Material::Diffuse {
                    albedo: ALBEDO,
                    two_sided: false,
                },
            )
            .light(PointLight {
                position: light,
                intensity: INTENSITY,
            }),
        EYE,
        TARGET,
        (8, 8),
        5,
    ));
    let hit = SurfaceHit {
        t: 1.0,
        p: centre + (radius - 1e-4) * n,
        p_error: Vec3::splat(2e-4),
        n,
        shading_n: n,
        uv: Vec2::ZERO,
        shape: 0,
    };
    let ray = Ray::new(hit.p + n, -n).with_time(TIME);
    let mine = direct_light(&world, &ray, &hit, ALBEDO, false);
    let asked = world.take();
    let starts_on_the_point = asked.iter().any(|a| a.shadow && a.ray.origin == hit.p);
    if mine == Vec3::ZERO && starts_on_the_point {
        panic!(
            "direct_light: a ball lit straight from outside came out black. Its shadow ray \
             starts exactly at hit.p, which rounding can leave a hair inside the ball, so the \
             ray hits the ball itself (shadow acne). Move the origin off the surface by its \
             error bound: hit.spawn_ray_to(target, time) does that."
        );
    }
    if let Some(mistake) = one_light_mistake(&world, &asked, mine, light, hit.p, n) {
        panic!("direct_light, a ball lit from outside: {mistake}");
    }
}

#[test]
fn exercise_direct_light_on_the_back_side() {
    let below = Vec3::new(0.5, -1.5, 0.3);
    let above = Vec3::new(1.0, 2.0, 0.5);
    let under_the_floor = Vec3::new(0.0, -3.0, 3.0);
    // One-sided: the back is black, whatever shines on it, and no shadow ray is needed.
    let world = floor_world(&[below, above], &[], false);
    let (mine, _) = light_floor(&world, under_the_floor, false);
    assert!(
        mine == Vec3::ZERO,
        "direct_light: seen from below, a one-sided floor is black (Mitsuba's diffuse reflects \
         on its front side only), but it gave {mine}"
    );
    check_shadow_rays(
        &world.take(),
        0,
        "the back of a one-sided floor",
        "the back of a one-sided surface is black whatever shines on it, so no light there needs \
         a shadow ray",
    );
    // Two-sided: the back is matte too, lit by the light on its side.
    let world = floor_world(&[below, above], &[], true);
    let (mine, hit) = light_floor(&world, under_the_floor, true);
    let asked = world.take();
    let case = "the back of a two-sided floor, lit from below";
    let shadow: Vec<&Ray> = asked.iter().filter(|a| a.shadow).map(|a| &a.ray).collect();
    if mine == Vec3::ZERO && shadow.is_empty() {
        panic!(
            "direct_light, {case}: it is black and traced no shadow ray, but a two_sided surface \
             is matte on its back too, lit by the lights on that side"
        );
    }
    if let Some(wrong_side) = shadow.iter().find(|ray| ray.dir.y > 0.0) {
        panic!(
            "direct_light, {case}: it sent a shadow ray up, along {}, towards the light above \
             the floor, which shines on the other side. Seen from below, that light is behind \
             the surface: cos(theta), measured from the normal turned towards the ray (-n \
             here), is negative, and the light gives nothing",
            wrong_side.dir
        );
    }
    if let Some(mistake) = one_light_mistake(&world, &asked, mine, TARGET + below, hit.p, -Vec3::Y)
    {
        panic!("direct_light, {case}: {mistake}");
    }
    check_shadow_rays(
        &asked,
        1,
        "the back of a two-sided floor",
        "the light above shines on the other side, so it needs no shadow ray",
    );
}

#[test]
fn exercise_direct_light_uses_the_shading_normal() {
    // A mesh with vertex normals: the shading normal leans away from the geometric one.
    let light = Vec3::new(1.0, 2.0, 0.5);
    let world = floor_world(&[light], &[], false);
    let shading_n = Vec3::new(0.4, 1.0, -0.2).normalize();
    let hit = SurfaceHit {
        t: 1.0,
        p: TARGET,
        p_error: Vec3::ZERO,
        n: Vec3::Y,
        shading_n,
        uv: Vec2::ZERO,
        shape: 0,
    };
    let ray = Ray::new(EYE, (TARGET - EYE).normalize()).with_time(TIME);
    let mine = direct_light(&world, &ray, &hit, ALBEDO, false);
    let expected = expected_from(TARGET + light, TARGET, shading_n);
    if close(mine, expected_from(TARGET + light, TARGET, Vec3::Y), 1e-4) {
        panic!(
            "direct_light: on a mesh with smooth normals, cos(theta) is measured from the \
             shading normal hit.shading_n, not the geometric hit.n. It gave {mine}, which is what \
             the geometric normal gives, where the shading normal gives {expected}"
        );
    }
    let asked = world.take();
    if let Some(mistake) =
        one_light_mistake(&world, &asked, mine, TARGET + light, TARGET, shading_n)
    {
        panic!(
            "direct_light, on a mesh whose shading normal hit.shading_n leans away from its \
             geometric normal hit.n (cos(theta) is measured from the shading normal): {mistake}"
        );
    }
}

#[test]
fn exercise_direct_light_of_a_light_on_the_surface() {
    // A light exactly at the lit point: no direction to it, so it lights nothing.
    let world = floor_world(&[Vec3::ZERO], &[], false);
    let ray = Ray::new(EYE, (TARGET - EYE).normalize()).with_time(TIME);
    let hit = SurfaceHit {
        t: 1.0,
        p: TARGET,
        p_error: Vec3::ZERO,
        n: Vec3::Y,
        shading_n: Vec3::Y,
        uv: Vec2::ZERO,
        shape: 0,
    };
    let mine = direct_light(&world, &ray, &hit, ALBEDO, false);
    let asked = world.take();
    let why = "A light exactly at the lit point (distance 0) has no direction from it: \
               to_light / |to_light| is 0 / 0, which is NaN, and so is cos(theta); a test \
               cos(theta) <= 0 lets a NaN through, since every comparison with NaN is false";
    if let Some(nowhere) = ray_to_nowhere(&asked) {
        panic!(
            "direct_light, a light exactly at the lit point: {nowhere}, and it gave {mine}. \
             {why}. Such a light lights nothing and needs no shadow ray"
        );
    }
    assert!(
        mine == Vec3::ZERO,
        "direct_light, a light exactly at the lit point: it gave {mine}, where such a light \
         lights nothing. {why}"
    );
}
