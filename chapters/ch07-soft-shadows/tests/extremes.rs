//! The extremes the chapter must survive: no area light at all (chapter 06's image, bit for
//! bit), a light shrinking to a point (the point light's image), a light touching its
//! receiver, a huge light, scenes at scales 1e-4 and 1e5, and every option together.

mod support;

use ch04_depth_of_field::Lens;
use ch06_fuzzy_reflections::scenes::Builtin as FuzzyBuiltin;
use ch06_fuzzy_reflections::{PointLights, TraceOptions};
use ch07_soft_shadows::scenes::{Builder, Builtin, camera, floor, matte};
use ch07_soft_shadows::{DiscWarp, LightOptions, LightStrata, Strategy};
use common::Ray;
use common::film::PixelBoxFilter;
use common::geometry::{Parallelogram, Shape, Sphere};
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use glam::Vec3;
use support::{
    ALBEDO, assert_finite, mean_radiance, panel, relative_rmse, render, scene_with_light,
};

/// Every combination of the light options, with 1, 2 (a Latin hypercube) and 4 (a grid) rays.
fn all_options() -> Vec<LightOptions> {
    let mut all = Vec::new();
    for samples in [1, 2, 4] {
        for strata in [LightStrata::Stratified, LightStrata::Independent] {
            for strategy in [Strategy::Area, Strategy::SolidAngle] {
                for warp in DiscWarp::ALL {
                    all.push(
                        LightOptions::with_samples(samples)
                            .with_strata(strata)
                            .with_strategy(strategy)
                            .with_disc_warp(warp),
                    );
                }
            }
        }
    }
    all
}

#[test]
fn without_area_lights_the_render_is_chapter_06s_bit_for_bit() {
    let settings = RenderSettings::new(32, 24, 4);
    for builtin in [FuzzyBuiltin::Floor, FuzzyBuiltin::Frosted] {
        let build = || builtin.build(12, builtin.default_exponent());
        let theirs = ch06_fuzzy_reflections::render_with(
            &build(),
            &PointLights,
            TraceOptions::default(),
            &Lens::PINHOLE,
            &settings,
            &IndependentSampler::new(3),
            &PixelBoxFilter,
        );
        let scene = build();
        for options in [
            LightOptions::default(),
            LightOptions::with_samples(16).with_strata(LightStrata::Independent),
        ] {
            let ours = ch07_soft_shadows::render_with(
                &scene,
                options,
                TraceOptions::default(),
                &Lens::PINHOLE,
                &settings,
                &IndependentSampler::new(3),
                &PixelBoxFilter,
            );
            assert_eq!(ours.image.pixels, theirs.image.pixels, "{builtin:?}");
            assert_eq!(ours.stats.rays, theirs.stats.rays, "{builtin:?}");
        }
    }
}

/// A sphere light of radius `r` and radiance `I / (π r²)` sends `π L (r/d)² cos θ = I cos θ / d²`
/// to an unoccluded receiver, exactly the point light of intensity `I`: only the penumbra
/// differs, and it shrinks with the sphere.
#[test]
fn a_shrinking_light_converges_to_the_point_light_image() {
    let intensity = Vec3::splat(6.0);
    let point = render(
        &scene_with_light(1.0, None, Some(intensity)),
        LightOptions::default(),
        64,
        48,
        8,
        1,
    );
    let mut errors = Vec::new();
    for radius in [0.3f32, 0.1, 0.01, 1e-3] {
        let light = Shape::Sphere(Sphere::new(Vec3::new(0.0, 2.0, 0.0), radius));
        let radiance = intensity / (std::f32::consts::PI * radius * radius);
        let scene = scene_with_light(1.0, Some((light, radiance)), None);
        let out = render(&scene, LightOptions::default(), 64, 48, 8, 1);
        assert_finite(&out, "shrinking light");
        errors.push(relative_rmse(&out.image, &point.image));
    }
    assert!(
        errors.windows(2).all(|w| w[1] < w[0]),
        "the error must fall as the light shrinks: {errors:?}"
    );
    assert!(errors[3] < 0.01, "radius 1e-3: {errors:?}");
    assert!(
        errors[0] > 0.05,
        "radius 0.3 should show a penumbra: {errors:?}"
    );
}

#[test]
fn a_light_touching_its_receiver_stays_finite() {
    // A sphere light resting on the floor, and a panel standing on it (its lower edge on the
    // floor, facing the camera): receivers at distance 0 from the light.
    let lights = [
        (
            Shape::Sphere(Sphere::new(Vec3::new(1.5, 0.3, 0.5), 0.3)),
            Vec3::splat(5.0),
        ),
        (
            Shape::Parallelogram(Parallelogram::new(
                Vec3::new(-1.5, 0.0, -0.5),
                Vec3::X,
                Vec3::Y,
            )),
            Vec3::splat(5.0),
        ),
    ];
    for light in lights {
        let scene = scene_with_light(1.0, Some(light), None);
        for options in all_options() {
            let out = render(&scene, options, 32, 24, 2, 0);
            assert_finite(&out, &format!("{light:?} {options:?}"));
        }
    }
}

#[test]
fn a_huge_light_lights_like_the_sky() {
    // A sphere 1e4 in radius just above the scene covers nearly the whole sky: the floor far
    // from the blockers receives E = π L (R/d)², and reflects ρ L (R/d)².
    let radius = 1e4f32;
    let radiance = Vec3::splat(2.0);
    let light = Shape::Sphere(Sphere::new(Vec3::new(0.0, radius + 3.0, 0.0), radius));
    let scene = scene_with_light(1.0, Some((light, radiance)), None);
    let ray = Ray::new(Vec3::new(3.5, 1.0, 3.5), -Vec3::Y);
    let (mean, se) = mean_radiance(&scene, LightOptions::default(), &ray, 4000, 5);
    let s = f64::from(radius) / f64::from(radius + 3.0);
    let expected = f64::from(ALBEDO) * 2.0 * s * s;
    assert!(
        (mean - expected).abs() < 5.0 * se + 2e-3 * expected,
        "{mean} ± {se}, expected {expected}"
    );
    for options in all_options() {
        assert_finite(&render(&scene, options, 16, 12, 2, 0), "huge sphere");
    }
    // A panel 1000 wide, 1 above the floor: area sampling is hopelessly noisy, but finite.
    let panel = Shape::Parallelogram(Parallelogram::new(
        Vec3::new(-500.0, 1.0, -500.0),
        1000.0 * Vec3::X,
        1000.0 * Vec3::Z,
    ));
    let scene = scene_with_light(1.0, Some((panel, radiance)), None);
    for options in all_options() {
        assert_finite(&render(&scene, options, 16, 12, 2, 0), "huge panel");
    }
}

#[test]
fn scenes_at_1e_minus_4_and_1e5_render_the_same_image() {
    let build = |scale: f32| {
        scene_with_light(
            scale,
            Some((panel(scale, 1.0), Vec3::splat(3.0))),
            Some(Vec3::splat(2.0)),
        )
    };
    let options = LightOptions::with_samples(4);
    let unit = render(&build(1.0), options, 64, 48, 4, 2);
    for scale in [1e-4f32, 1e5] {
        let out = render(&build(scale), options, 64, 48, 4, 2);
        assert_finite(&out, &format!("scale {scale}"));
        let error = relative_rmse(&out.image, &unit.image);
        let mean_ratio = common::metrics::mean(&out.image).y / common::metrics::mean(&unit.image).y;
        assert!(error < 0.02, "scale {scale}: relative RMSE {error}");
        assert!(
            (mean_ratio - 1.0).abs() < 2e-3,
            "scale {scale}: mean ratio {mean_ratio}"
        );
    }
}

#[test]
fn every_builtin_with_every_option_is_finite() {
    for builtin in Builtin::ALL {
        for scale in [0.01, 1.0, 5.0] {
            let scene = builtin.build(6, scale);
            for options in all_options() {
                let out = render(&scene, options, 12, 9, 1, 0);
                assert_finite(&out, &format!("{builtin:?} x{scale} {options:?}"));
            }
        }
    }
}

#[test]
fn a_light_is_seen_from_its_front_only_and_black_from_behind() {
    // A panel facing down, seen from below (bright) and from above (black), by camera rays.
    let light = panel(1.0, 1.0);
    let scene = Builder::new()
        .shape(floor(4.0), matte(Vec3::splat(0.5)))
        .area_light(light, Vec3::splat(7.0))
        .build(camera(Vec3::new(0.0, 5.0, 1.0), Vec3::ZERO, 40.0), 12);
    let from_below = Ray::new(Vec3::new(0.1, 1.0, 0.1), Vec3::Y);
    let from_above = Ray::new(Vec3::new(0.1, 4.0, 0.1), -Vec3::Y);
    let (below, _) = mean_radiance(&scene, LightOptions::default(), &from_below, 4, 0);
    let (above, _) = mean_radiance(&scene, LightOptions::default(), &from_above, 4, 0);
    assert_eq!(below, 7.0);
    assert_eq!(above, 0.0);
}
