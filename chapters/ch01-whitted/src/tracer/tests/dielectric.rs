//! `dielectric`: one interface `z = 0` between air (above) and glass (below), with a stand-in
//! for the rest of the path that says which way each ray went: rays going up bring back red,
//! rays going down green. The colour that comes back is then the weight of each ray.

use std::panic::{AssertUnwindSafe, catch_unwind};

use common::Ray;
use common::geometry::SurfaceHit;
use glam::{Vec2, Vec3};

use super::close;
use crate::optics::{critical_angle, fresnel_dielectric, reflect, refract};
use crate::tracer::dielectric;

const GLASS: f32 = 1.5;
const TIME: f32 = 0.35;
const UP: Vec3 = Vec3::Z;

/// The point of the interface the rays hit: its normal points up, out of the glass.
fn interface_hit() -> SurfaceHit {
    SurfaceHit {
        t: 2.0,
        p: Vec3::new(0.2, -0.1, 0.0),
        p_error: Vec3::splat(1e-5),
        n: UP,
        shading_n: UP,
        uv: Vec2::ZERO,
        shape: 0,
    }
}

/// A ray arriving at the interface at `theta` from the normal: from above (in the air) or
/// from below (inside the glass).
fn arriving(theta: f32, from_above: bool) -> Ray {
    let d = Vec3::new(theta.sin(), 0.0, theta.cos());
    let d = if from_above {
        Vec3::new(d.x, d.y, -d.z)
    } else {
        d
    };
    Ray::new(interface_hit().p - 2.0 * d, d).with_time(TIME)
}

/// What `dielectric` gives for `ray` (red: the weight of the ray that went up, green: of the
/// ray that went down) and the rays it traced; `Err` with the panic's message if it panicked.
fn weights(ray: &Ray, int_ior: f32, ext_ior: f32) -> Result<(Vec3, Vec<Ray>), String> {
    let mut traced = Vec::new();
    let mut trace_next = |next: &Ray| {
        traced.push(*next);
        if next.dir.z > 0.0 { Vec3::X } else { Vec3::Y }
    };
    let hit = interface_hit();
    let result = catch_unwind(AssertUnwindSafe(|| {
        dielectric(ray, &hit, int_ior, ext_ior, &mut trace_next)
    }))
    .map_err(common::exercise::resume_if_not_written);
    match result {
        Ok(radiance) => Ok((radiance, traced)),
        Err(payload) => Err(payload
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default()),
    }
}

/// The right weights for `ray`: (reflected, refracted) and the directions, from the earlier
/// exercises.
fn expected(ray: &Ray, int_ior: f32, ext_ior: f32) -> (f32, f32, Vec3, Option<Vec3>) {
    let from_above = ray.dir.z < 0.0;
    let (normal, eta) = if from_above {
        (UP, ext_ior / int_ior)
    } else {
        (-UP, int_ior / ext_ior)
    };
    let cos_i = -ray.dir.dot(normal);
    let f = fresnel_dielectric(cos_i, eta);
    let refracted = refract(ray.dir, normal, eta);
    let t = if refracted.is_some() {
        (1.0 - f) * eta * eta
    } else {
        0.0
    };
    (f, t, reflect(ray.dir, normal), refracted)
}

/// Checks `dielectric` on `ray`, naming the mistake it sees.
fn check(ray: &Ray, int_ior: f32, ext_ior: f32, case: &str) {
    let from_above = ray.dir.z < 0.0;
    let (mine, traced) = match weights(ray, int_ior, ext_ior) {
        Ok(answer) => answer,
        Err(message) => panic!(
            "dielectric ({case}): it panicked ({message}). {}",
            if expected(ray, int_ior, ext_ior).3.is_none() {
                "Here the ray is beyond the critical angle: refract finds no refracted ray \
                 (None) and all the light is reflected (total internal reflection); only the \
                 reflected ray is traced"
            } else {
                "There is a reflected and a refracted ray here"
            }
        ),
    };
    let (f, t, reflected_dir, refracted_dir) = expected(ray, int_ior, ext_ior);
    // Red is the ray going up, green the ray going down.
    let (reflected_weight, refracted_weight) = if from_above {
        (mine.x, mine.y)
    } else {
        (mine.y, mine.x)
    };
    for traced in &traced {
        let along = |dir: Vec3| (traced.dir - dir).length() <= 1e-4;
        if !traced.dir.is_finite() {
            panic!(
                "dielectric ({case}): a ray it spawned goes along {}, not a finite direction: do \
                 the checks of reflect and refract pass?",
                traced.dir
            );
        }
        if !along(reflected_dir) && !refracted_dir.is_some_and(along) {
            panic!(
                "dielectric ({case}): a ray it spawned goes along {}, which is neither the \
                 mirror direction {reflected_dir} nor the refracted one{}: the normal must \
                 face the ray, for reflect as for refract (flip hit.n when it does not, \
                 front_face tells), and refract's eta is eta_i / eta_t, the index the ray leaves \
                 over the one it enters",
                traced.dir,
                refracted_dir.map_or(" (there is none here)".to_string(), |dir| format!(" {dir}"))
            );
        }
        if traced.time != TIME {
            panic!(
                "dielectric ({case}): a ray it spawned travels at shutter time {}, the ray \
                 that arrived at {TIME}: every ray of a path keeps the camera ray's time \
                 (chapter 05 moves objects with it)",
                traced.time
            );
        }
        let p = interface_hit().p;
        if traced.origin == p {
            panic!(
                "dielectric ({case}): a spawned ray starts exactly at hit.p, which rounding can \
                 leave a hair on the wrong side of the surface: move it off by the error \
                 bound, towards the side the ray leaves to (hit.spawn_ray does)"
            );
        }
        if (traced.origin.z > p.z) != (traced.dir.z > 0.0) {
            panic!(
                "dielectric ({case}): the ray spawned along {} starts on the other side of \
                 the surface ({}): its origin must be moved towards the side it leaves to",
                traced.dir, traced.origin
            );
        }
    }
    let going = |up: bool| traced.iter().find(|r| (r.dir.z > 0.0) == up);
    let reflected = going(from_above);
    let refracted = going(!from_above);
    // The reflectance a solution with the indices the wrong way round would give.
    let eta_swapped = {
        let (normal, eta) = if from_above {
            (UP, int_ior / ext_ior)
        } else {
            (-UP, ext_ior / int_ior)
        };
        fresnel_dielectric(-ray.dir.dot(normal), eta)
    };
    let problem = if !mine.is_finite() {
        Some(format!("the radiance {mine} is not finite"))
    } else if close(
        Vec3::new(reflected_weight, refracted_weight, 0.0),
        Vec3::new(f, t, 0.0),
        1e-4,
    ) {
        None
    } else if !from_above && traced.len() == 1 && reflected_weight > 0.99 && t > 0.0 {
        Some(
            "from inside the glass everything came back as reflection, as at grazing \
             incidence: the normal must face the ray (flip hit.n when it does not, front_face \
             tells), for cos(theta_i) as for refract, and then the indices swap"
                .to_string(),
        )
    } else if (reflected_weight - eta_swapped).abs() < 1e-4 && (f - eta_swapped).abs() > 1e-4 {
        Some(
            "the reflectance is that of the indices swapped: eta is the index the ray comes \
             from over the one it enters, and from inside the glass that is int_ior / ext_ior"
                .to_string(),
        )
    } else if (reflected_weight - 1.0).abs() < 1e-4 && f < 0.99 && reflected.is_some() {
        Some(format!(
            "the reflected ray carries everything, as at grazing incidence, where its Fresnel \
             share is {f}: is cos(theta_i) measured from the normal that faces the ray, so \
             that it is positive?"
        ))
    } else if (reflected_weight - f).abs() > 1e-4 {
        Some(format!(
            "the reflected ray carries {reflected_weight}, its Fresnel share is {f}"
        ))
    } else if t > 0.0 && refracted.is_none() {
        Some(
            "no refracted ray was traced, but here there is one: sin(theta_t) = \
             eta sin(theta_i) is below 1, with eta = eta_i / eta_t, the index the ray leaves \
             over the one it enters (and refract wants the normal on the side the ray comes \
             from)"
                .to_string(),
        )
    } else if t > 0.0 && (refracted_weight - (1.0 - f)).abs() < 1e-4 {
        Some(
            "the refracted ray carries 1 - F without the change of radiance across the \
             interface: radiance entering a denser medium is squeezed into a narrower cone of \
             directions, so it changes by the square of the ratio of the indices"
                .to_string(),
        )
    } else if t > 0.0 {
        // t = (1 - F) eta^2: the mistake weighs the refracted ray by (1 - F) / eta^2.
        let eta_squared = t / (1.0 - f);
        if (refracted_weight - (1.0 - f) / eta_squared).abs() < 1e-4 {
            Some(format!(
                "the refracted ray is scaled by the squared ratio of the indices upside down: \
                 seen from the side the ray comes from, eta = eta_i / eta_t is squared{}",
                if from_above {
                    ""
                } else {
                    " (or eta itself is upside down: from inside the glass it is \
                     int_ior / ext_ior)"
                }
            ))
        } else if (refracted_weight - (1.0 - f) * eta_squared.sqrt()).abs() < 1e-4 {
            Some(
                "the refracted ray is scaled by the ratio of the indices, not by its square: \
                 radiance is squeezed into a narrower cone in both directions across the \
                 surface, so it changes by eta^2"
                    .to_string(),
            )
        } else {
            Some(format!(
                "the refracted ray carries {refracted_weight}, expected {t}"
            ))
        }
    } else {
        Some(format!(
            "beyond the critical angle there is no refracted ray, yet something went {} with \
             weight {refracted_weight}",
            if from_above { "down" } else { "up" }
        ))
    };
    if let Some(problem) = problem {
        panic!(
            "dielectric ({case}): {problem}.\n  Your dielectric gave weight {reflected_weight} \
             to the reflected ray and {refracted_weight} to the refracted one; they should be \
             {f} and {t}"
        );
    }
    if let Some(r) = reflected
        && (r.dir - reflected_dir).length() > 1e-4
    {
        panic!(
            "dielectric ({case}): the reflected ray goes along {}, the mirror direction is \
             {reflected_dir}",
            r.dir
        );
    }
    match (refracted, refracted_dir) {
        (Some(r), Some(dir)) if (r.dir - dir).length() > 1e-4 => panic!(
            "dielectric ({case}): the refracted ray goes along {}, Snell's law gives {dir}: \
             refract wants the normal on the side the ray comes from, and eta = eta_i / eta_t",
            r.dir
        ),
        (Some(r), None) => panic!(
            "dielectric ({case}): beyond the critical angle there is no refracted ray, yet a \
             ray went along {}",
            r.dir
        ),
        _ => {}
    }
    if f == 0.0 && reflected.is_some() {
        panic!(
            "dielectric ({case}): the reflected ray carries nothing here (F = 0), yet it was \
             traced: a ray whose share is zero is not traced"
        );
    }
}

#[test]
fn exercise_dielectric_from_the_air() {
    for theta in [0.0f32, 0.4, 0.9, 1.3] {
        check(
            &arriving(theta, true),
            GLASS,
            1.0,
            &format!("from the air into glass, {theta} rad from the normal"),
        );
    }
}

#[test]
fn exercise_dielectric_from_inside_the_glass() {
    let critical = critical_angle(GLASS, 1.0).unwrap();
    for theta in [0.0f32, 0.3, critical - 0.05] {
        check(
            &arriving(theta, false),
            GLASS,
            1.0,
            &format!("from inside the glass out into the air, {theta} rad from the normal"),
        );
    }
}

#[test]
fn exercise_dielectric_total_internal_reflection() {
    let critical = critical_angle(GLASS, 1.0).unwrap();
    for theta in [critical + 0.05, 1.2] {
        check(
            &arriving(theta, false),
            GLASS,
            1.0,
            &format!(
                "from inside the glass at {theta} rad, beyond the critical angle {critical:.3}"
            ),
        );
    }
}

#[test]
fn exercise_dielectric_between_other_media() {
    // Glass under water, from both sides, and an interface that is no interface at all.
    check(&arriving(0.6, true), GLASS, 1.33, "from water into glass");
    check(
        &arriving(0.5, false),
        GLASS,
        1.33,
        "from glass out into water",
    );
    check(&arriving(0.7, true), 1.0, 1.0, "index 1 on both sides");
}
