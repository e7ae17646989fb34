//! Furnace tests: in a world that glows with radiance 1 in every direction, a white surface
//! can at most send back the 1 it receives. More would be energy created by the estimator.
//!
//! Each test traces many rays at one angle of incidence, from straight on to grazing, and
//! compares the mean radiance with 1, within five standard errors of the mean. What the
//! below-surface policies do shows up here as numbers: dropping the stray rays loses the
//! lobe's share below the surface (the model's own loss at grazing angles), resampling and
//! reflecting keep everything.

use ch06_fuzzy_reflections::furnace::{incoming, mean_radiance, scene_of, white_floor};
use ch06_fuzzy_reflections::{BelowSurface, FuzzMethod, GlassStrategy, TraceOptions};
use common::Ray;
use common::geometry::{Parallelogram, Shape, Sphere};
use common::scene::Material;
use common::scene::Material as SmoothMaterial;
use glam::Vec3;

const EXPONENTS: [f32; 7] = [0.0, 1.0, 10.0, 100.0, 1e3, 1e4, 1e6];
/// Angles of incidence from the normal, in degrees, up to a ray a hair from the surface.
const ANGLES: [f32; 7] = [0.0, 30.0, 60.0, 80.0, 85.0, 89.0, 89.999];
const SAMPLES: u64 = 4000;

fn options(fuzz: FuzzMethod, below: BelowSurface) -> TraceOptions {
    TraceOptions {
        glass: GlassStrategy::Fresnel,
        fuzz,
        below,
    }
}

#[test]
fn a_white_glossy_surface_never_reflects_more_than_it_receives() {
    for exponent in EXPONENTS {
        let scene = white_floor(exponent);
        for degrees in ANGLES {
            for fuzz in FuzzMethod::ALL {
                for below in BelowSurface::ALL {
                    let (mean, se) =
                        mean_radiance(&scene, options(fuzz, below), &incoming(degrees), SAMPLES);
                    assert!(
                        mean <= 1.0 + 5.0 * se + 1e-6,
                        "n={exponent} at {degrees} deg, {fuzz:?}/{below:?}: {mean} (se {se})"
                    );
                }
            }
        }
    }
}

#[test]
fn reflecting_or_resampling_stray_rays_keeps_the_energy_dropping_loses_it_at_grazing() {
    for exponent in [0.0f32, 1.0, 10.0] {
        let scene = white_floor(exponent);
        let at = |degrees: f32, below: BelowSurface| {
            mean_radiance(
                &scene,
                options(FuzzMethod::Lobe, below),
                &incoming(degrees),
                SAMPLES,
            )
            .0
        };
        // Mirroring a stray ray back keeps every sample at weight 1.
        for degrees in ANGLES {
            let kept = at(degrees, BelowSurface::Reflect);
            assert!(kept > 1.0 - 1e-6, "n={exponent} at {degrees}: {kept}");
            // Resampling fails only when 16 draws in a row go below.
            let resampled = at(degrees, BelowSurface::Resample);
            assert!(resampled > 0.99, "n={exponent} at {degrees}: {resampled}");
        }
        // Near grazing, about half of a wide lobe lies below the surface.
        let dropped = at(85.0, BelowSurface::Drop);
        assert!(dropped < 0.75, "n={exponent}: {dropped}");
        assert!(dropped > 0.3, "n={exponent}: {dropped}");
    }
    // A sharp lobe loses nothing until the mirror direction itself grazes the surface.
    let sharp = white_floor(1e6);
    let (kept, _) = mean_radiance(
        &sharp,
        options(FuzzMethod::Lobe, BelowSurface::Drop),
        &incoming(80.0),
        SAMPLES,
    );
    assert!(kept > 1.0 - 1e-6, "{kept}");
}

#[test]
fn a_white_glossy_sphere_in_the_furnace_at_every_impact_parameter() {
    let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0));
    for exponent in [0.0f32, 10.0, 1e6] {
        let scene = scene_of(
            vec![(sphere, Material::glossy(Vec3::ONE, exponent))],
            Vec3::ONE,
            Vec3::new(0.0, 0.0, 5.0),
            Vec3::ZERO,
            4,
        );
        // From the centre of the disc the sphere covers out to its rim.
        for offset in [0.0f32, 0.5, 0.9, 0.999, 0.999_999] {
            let ray = Ray::new(Vec3::new(offset, 0.0, 5.0), -Vec3::Z);
            for below in BelowSurface::ALL {
                let (mean, se) =
                    mean_radiance(&scene, options(FuzzMethod::Lobe, below), &ray, SAMPLES);
                assert!(
                    mean <= 1.0 + 5.0 * se + 1e-6,
                    "n={exponent} offset {offset} {below:?}: {mean}"
                );
            }
        }
    }
}

#[test]
fn glass_smooth_or_frosted_in_the_furnace_keeps_at_most_what_it_receives() {
    let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0));
    let materials = [
        SmoothMaterial::glass(1.5),
        Material::rough_glass(1.5, 0.0),
        Material::rough_glass(1.5, 10.0),
        Material::rough_glass(1.5, 1e6),
    ];
    for material in materials {
        let scene = scene_of(
            vec![(sphere, material.clone())],
            Vec3::ONE,
            Vec3::new(0.0, 0.0, 5.0),
            Vec3::ZERO,
            200,
        );
        for offset in [0.0f32, 0.6, 0.95, 0.999_999] {
            let ray = Ray::new(Vec3::new(offset, 0.0, 5.0), -Vec3::Z);
            for glass in GlassStrategy::ALL {
                for below in BelowSurface::ALL {
                    let options = TraceOptions {
                        glass,
                        fuzz: FuzzMethod::Lobe,
                        below,
                    };
                    let samples = if glass == GlassStrategy::Both {
                        200
                    } else {
                        SAMPLES
                    };
                    let (mean, se) = mean_radiance(&scene, options, &ray, samples);
                    assert!(
                        mean <= 1.0 + 5.0 * se + 1e-4,
                        "{material:?} offset {offset} {glass:?}/{below:?}: {mean} (se {se})"
                    );
                    if matches!(
                        material,
                        Material::Diffuse { .. }
                            | Material::TexturedDiffuse { .. }
                            | Material::Mirror { .. }
                            | Material::Dielectric { .. }
                    ) || below == BelowSurface::Reflect
                    {
                        // Nothing is dropped: all the light comes out again, up to what the
                        // depth limit cuts off inside.
                        assert!(
                            mean >= 1.0 - 5.0 * se - 1e-3,
                            "{material:?} offset {offset} {glass:?}/{below:?}: {mean} (se {se})"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn inter_reflections_between_rough_plates_never_create_energy() {
    // Two white glossy plates facing each other one unit apart, open to the furnace at their
    // ends: a ray at a grazing angle bounces between them many times before it escapes.
    let bottom = Parallelogram::new(
        Vec3::new(-50.0, 0.0, -50.0),
        100.0 * Vec3::Z,
        100.0 * Vec3::X,
    );
    let top = Parallelogram::new(
        Vec3::new(-50.0, 1.0, -50.0),
        100.0 * Vec3::X,
        100.0 * Vec3::Z,
    );
    for exponent in [10.0f32, 1e3] {
        for below in BelowSurface::ALL {
            let material = Material::glossy(Vec3::ONE, exponent);
            let scene = scene_of(
                vec![
                    (Shape::Parallelogram(bottom), material.clone()),
                    (Shape::Parallelogram(top), material.clone()),
                ],
                Vec3::ONE,
                Vec3::new(0.0, 0.5, 5.0),
                Vec3::ZERO,
                1000,
            );
            let ray = Ray::new(
                Vec3::new(0.0, 0.5, 0.0),
                Vec3::new(1.0, -0.05, 0.0).normalize(),
            );
            let (mean, se) = mean_radiance(&scene, options(FuzzMethod::Lobe, below), &ray, 1000);
            assert!(
                mean <= 1.0 + 5.0 * se + 1e-6,
                "n={exponent} {below:?}: {mean} (se {se})"
            );
            if below == BelowSurface::Reflect {
                assert!(mean > 0.99, "n={exponent}: {mean}");
            }
        }
    }
}
