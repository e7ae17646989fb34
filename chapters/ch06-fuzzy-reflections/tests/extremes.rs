//! The extremes: lobes from a hemisphere (`n = 0`) to almost a mirror (`n = 1e6`), glass of
//! index 1, rays exactly at the critical angle and grazing the surface, and the chapter's
//! scenes rendered with every option: no NaN, no infinity, no negative radiance.

mod support;

use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch05_motion_blur::render_with as chapter05_render;
use ch06_fuzzy_reflections::furnace::{mean_radiance, scene_of};
use ch06_fuzzy_reflections::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch06_fuzzy_reflections::{BelowSurface, FuzzMethod, GlassStrategy, TraceOptions};
use common::Ray;
use common::film::PixelBoxFilter;
use common::geometry::{Parallelogram, Shape};
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use common::scene::Material;
use common::scene::Material as SmoothMaterial;
use glam::{Vec2, Vec3};
use support::{assert_finite, render};

fn every_option() -> Vec<TraceOptions> {
    let mut all = Vec::new();
    for glass in GlassStrategy::ALL {
        for fuzz in FuzzMethod::ALL {
            for below in BelowSurface::ALL {
                all.push(TraceOptions { glass, fuzz, below });
            }
        }
    }
    all
}

#[test]
fn every_scene_with_every_option_and_extreme_exponents_is_finite() {
    for builtin in Builtin::ALL {
        for exponent in [0.0f32, 1.0, 1e6] {
            let scene = builtin.build(DEFAULT_MAX_DEPTH, exponent);
            for options in every_option() {
                let out = render(&scene, options, 12, 9, 2, 1);
                assert_eq!(out.stats.nonfinite_samples, 0, "{builtin:?} n={exponent}");
                assert_finite(&out.image, &format!("{builtin:?} n={exponent} {options:?}"));
            }
        }
    }
}

#[test]
fn a_smooth_scene_traced_both_ways_is_chapter_05s_image_bit_for_bit() {
    let scene = Builtin::Panes.build(DEFAULT_MAX_DEPTH, 1.0);
    assert!(!scene.scene.surfaces.iter().any(|s| s.material.is_fuzzy()));
    let options = TraceOptions {
        glass: GlassStrategy::Both,
        ..TraceOptions::default()
    };
    let ours = render(&scene, options, 24, 18, 3, 5);
    let settings = RenderSettings::new(24, 18, 3);
    let theirs = chapter05_render(
        &scene,
        &Lens::PINHOLE,
        &settings,
        &IndependentSampler::new(5),
        &PixelBoxFilter,
    );
    assert_eq!(ours.image.pixels, theirs.image.pixels);
    assert_eq!(ours.stats.rays, theirs.stats.rays);
}

/// The floor scene with its floor made of `floor`, lit by its high lamp only.
///
/// The low lamp is left out: a mirror cannot show a point light's reflection at all (no ray
/// hits a point), while a lobe of any finite exponent shows it as a highlight whose energy
/// stays the same as the lobe narrows: a speck that the mirror image lacks however large `n`.
fn floor_scene(floor: Material) -> MotionScene {
    let mut world = Builtin::Floor.build(DEFAULT_MAX_DEPTH, 1.0);
    world.scene.surfaces[0].material = floor;
    world.scene.point_lights.truncate(1);
    world
}

#[test]
fn a_lobe_of_exponent_1e6_reflects_the_mirror_image() {
    let glossy = floor_scene(Material::glossy(Vec3::splat(0.8), 1e6));
    let mirror = floor_scene(SmoothMaterial::Mirror {
        reflectance: Vec3::splat(0.8),
    });
    let (w, h) = (64, 48);
    let a = render(&glossy, TraceOptions::default(), w, h, 8, 2).image;
    let b = render(&mirror, TraceOptions::default(), w, h, 8, 2).image;
    // The same pixel positions: only the lobe's tiny spread (a milliradian) and the lamp's
    // highlight (a speck the mirror cannot show) tell them apart.
    let differing = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .filter(|(p, q)| (**p - **q).abs().max_element() > 0.02)
        .count();
    assert!(
        differing <= a.pixels.len() / 100,
        "{differing} of {} pixels differ",
        a.pixels.len()
    );
    // A wide lobe does not: the test can fail.
    let blurred = render(
        &floor_scene(Material::glossy(Vec3::splat(0.8), 10.0)),
        TraceOptions::default(),
        w,
        h,
        8,
        2,
    )
    .image;
    let differing_wide = blurred
        .pixels
        .iter()
        .zip(&b.pixels)
        .filter(|(p, q)| (**p - **q).abs().max_element() > 0.02)
        .count();
    assert!(differing_wide > a.pixels.len() / 10, "{differing_wide}");
}

/// A checkered wall seen through a pane of `pane` (or no pane), lit from between them, so
/// that the pane casts no shadow on what is seen through it.
fn pane_scene(pane: Option<Material>) -> MotionScene {
    let checker = SmoothMaterial::TexturedDiffuse {
        texture: common::scene::Texture::Checkerboard(common::scene::Checkerboard::scaled(
            Vec3::splat(0.8),
            Vec3::new(0.2, 0.3, 0.6),
            Vec2::splat(6.0),
        )),
        two_sided: false,
    };
    let wall = Shape::Parallelogram(Parallelogram::new(
        Vec3::new(-3.0, -3.0, -3.0),
        6.0 * Vec3::X,
        6.0 * Vec3::Y,
    ));
    let mut shapes = vec![(wall, checker)];
    if let Some(pane) = pane {
        for face in ch06_fuzzy_reflections::scenes::box_faces(
            Vec3::new(-2.0, -2.0, 1.9),
            Vec3::new(2.0, 2.0, 2.0),
        ) {
            shapes.push((face, pane.clone()));
        }
    }
    let mut scene = scene_of(
        shapes,
        Vec3::splat(0.3),
        Vec3::new(0.0, 0.0, 4.0),
        Vec3::ZERO,
        DEFAULT_MAX_DEPTH,
    );
    scene.scene.point_lights.push(common::scene::PointLight {
        position: Vec3::new(0.0, 0.5, 0.0),
        intensity: Vec3::splat(4.0),
    });
    scene
}

#[test]
fn glass_of_index_one_vanishes_however_frosted() {
    let without = render(&pane_scene(None), TraceOptions::default(), 48, 36, 4, 3).image;
    for pane in [
        SmoothMaterial::Dielectric {
            int_ior: 1.0,
            ext_ior: 1.0,
        },
        Material::RoughGlass(common::scene::RoughGlass {
            int_ior: 1.0,
            ext_ior: 1.0,
            exponent: 0.0,
            stands_in_for: None,
        }),
        Material::RoughGlass(common::scene::RoughGlass {
            int_ior: 1.33,
            ext_ior: 1.33,
            exponent: 10.0,
            stands_in_for: None,
        }),
    ] {
        // `Half` vanishes only on average: it refracts half the time with weight 2 (F = 0)
        // and spends the other half on a reflection that carries nothing.
        for glass in [GlassStrategy::Both, GlassStrategy::Fresnel] {
            let options = TraceOptions {
                glass,
                ..TraceOptions::default()
            };
            let with = render(&pane_scene(Some(pane.clone())), options, 48, 36, 4, 3).image;
            // The rays cross the pane unbent; only where a re-spawned ray's last bit of
            // rounding flips a sample across a checker edge may a pixel differ.
            let differing = with
                .pixels
                .iter()
                .zip(&without.pixels)
                .filter(|(p, q)| (**p - **q).abs().max_element() > 1e-3)
                .count();
            assert!(
                differing <= with.pixels.len() / 200,
                "{pane:?} {glass:?}: {differing} pixels differ"
            );
        }
    }
    // Real glass does change the image: the test can fail.
    let real = render(
        &pane_scene(Some(Material::rough_glass(1.5, 10.0))),
        TraceOptions::default(),
        48,
        36,
        4,
        3,
    )
    .image;
    let differing = real
        .pixels
        .iter()
        .zip(&without.pixels)
        .filter(|(p, q)| (**p - **q).abs().max_element() > 1e-3)
        .count();
    assert!(differing > real.pixels.len() / 4, "{differing}");
}

#[test]
fn rays_at_and_around_the_critical_angle_stay_finite() {
    // Inside a slab of glass, rays meet its top face at the critical angle and at the
    // neighbouring floats on either side; and from outside, rays graze it.
    let critical = (1.0f32 / 1.5).asin();
    let top = Parallelogram::new(Vec3::new(-1e3, 0.0, -1e3), 2e3 * Vec3::Z, 2e3 * Vec3::X);
    let bottom = Parallelogram::new(Vec3::new(-1e3, -1.0, -1e3), 2e3 * Vec3::X, 2e3 * Vec3::Z);
    for material in [
        SmoothMaterial::glass(1.5),
        Material::rough_glass(1.5, 0.0),
        Material::rough_glass(1.5, 100.0),
        Material::rough_glass(1.5, 1e6),
    ] {
        let scene = scene_of(
            vec![
                (Shape::Parallelogram(top), material.clone()),
                (Shape::Parallelogram(bottom), material.clone()),
            ],
            Vec3::ONE,
            Vec3::new(0.0, 2.0, 5.0),
            Vec3::ZERO,
            64,
        );
        let mut angles = vec![critical, 0.0, std::f32::consts::FRAC_PI_2 - 1e-6];
        let mut below = critical;
        let mut above = critical;
        for _ in 0..8 {
            below = below.next_down();
            above = above.next_up();
            angles.push(below);
            angles.push(above);
        }
        for options in every_option() {
            for &theta in &angles {
                // From inside, upwards at theta from the normal.
                let inside = Ray::new(
                    Vec3::new(0.0, -0.5, 0.0),
                    Vec3::new(theta.sin(), theta.cos(), 0.0),
                );
                // From outside, downwards at theta.
                let outside = Ray::new(
                    Vec3::new(0.0, 0.5, 0.0),
                    Vec3::new(theta.sin(), -theta.cos(), 0.0),
                );
                for ray in [inside, outside] {
                    let samples = if options.glass == GlassStrategy::Both {
                        4
                    } else {
                        50
                    };
                    let (mean, _) = mean_radiance(&scene, options, &ray, samples);
                    assert!(
                        mean.is_finite() && mean >= 0.0,
                        "{material:?} {options:?} theta {theta}: {mean}"
                    );
                }
            }
        }
    }
}
