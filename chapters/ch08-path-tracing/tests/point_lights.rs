//! Point lights are deltas: next-event estimation connects every one of them through its own
//! shadow ray and draws no number for them. So at `max_depth` 2 (camera ray, then direct
//! light) a matte scene under point lights alone is exactly what chapter 03's Whitted tracer
//! renders from the same pixel positions: no noise to average, nothing picked, nothing
//! left out.

use ch01_whitted::scenes::Builtin;
use ch05_motion_blur::MotionScene;
use ch08_path_tracing::{Method, PathOptions};
use common::film::PixelBoxFilter;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use common::scene::Material;
use common::scene::PointLight;
use common::scene::Scene;
use glam::Vec3;

/// Chapter 01's Cornell box with its spheres made matte and two more point lights of other
/// colours: three lights, some of them hidden from some points.
fn matte_box_under_three_lights() -> Scene {
    let mut scene = Builtin::Cornell.build(2);
    for surface in &mut scene.surfaces {
        if matches!(
            surface.material,
            Material::Mirror { .. } | Material::Dielectric { .. }
        ) {
            surface.material = Material::diffuse(Vec3::splat(0.6));
        }
    }
    let first = scene.point_lights[0];
    scene.point_lights.push(PointLight {
        position: first.position + Vec3::new(0.4, -0.3, 0.2) * first.position.length().max(1.0),
        intensity: first.intensity * Vec3::new(0.2, 0.5, 1.0),
    });
    scene.point_lights.push(PointLight {
        position: first.position * 0.5,
        intensity: first.intensity * Vec3::new(1.0, 0.3, 0.1),
    });
    scene
}

#[test]
fn point_lights_alone_give_chapter_03s_direct_light() {
    let scene = matte_box_under_three_lights();
    let settings = RenderSettings::new(32, 32, 2);
    let sampler = IndependentSampler::new(7);
    let whitted = ch03_anti_aliasing::render_with(&scene, &settings, &sampler, &PixelBoxFilter);
    let still = MotionScene::still(scene);
    let path = ch08_path_tracing::render_with(
        &still,
        Method::new(PathOptions::with_depth(2)),
        &ch04_depth_of_field::Lens::PINHOLE,
        &settings,
        &sampler,
        &PixelBoxFilter,
    );
    assert_eq!(path.stats.rays, whitted.stats.rays, "the same shadow rays");
    let brightest = whitted
        .image
        .pixels
        .iter()
        .map(|p| p.max_element())
        .fold(0.0, f32::max);
    assert!(brightest > 0.0, "the box is lit");
    for (i, (a, b)) in whitted
        .image
        .pixels
        .iter()
        .zip(&path.image.pixels)
        .enumerate()
    {
        // The same terms summed in another order: equal to rounding.
        assert!(
            (*a - *b).abs().max_element() <= 1e-5 * brightest,
            "pixel {i}: chapter 03 {a}, chapter 08 {b}"
        );
    }
}
