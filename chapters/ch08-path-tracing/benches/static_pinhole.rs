//! Does the path tracer's general machinery cost anything on a scene that needs none of it?
//!
//! Run with `cargo bench -p ch08-path-tracing --bench static_pinhole`. Chapter 01's Cornell box
//! (one point light, static, pinhole) is rendered by chapter 01's Whitted tracer through the
//! film (as chapter 03 rendered it before its pixels were gathered) and by this chapter's path
//! tracer, at the same size, samples and seed, on one thread.
//!
//! The two tracers do the same work only where the scene asks for the same work:
//! - `direct`: the box with its mirror and glass spheres made matte, at `max_depth` 2. Both
//!   trace one camera ray and one shadow ray to the one light per sample, and the path tracer
//!   draws no number but the pixel's (see `tests/dimensions.rs`); `tests/point_lights.rs`
//!   checks that the two compute the same image. The ratio of the two times is the overhead
//!   of the path tracer's generality: the camera's checks for a lens and a shutter, the BSDF's
//!   match over every material, the path's state kept between segments.
//! - `full`: the box as it is, at `max_depth` 8. Whitted's tracer follows both rays at glass
//!   and stops at matte surfaces; the path tracer follows one ray and bounces on, so the
//!   times differ by design. It is reported so that the difference is seen, not hidden.

use ch01_whitted::scenes::Builtin;
use ch05_motion_blur::MotionScene;
use ch08_path_tracing::{Method, PathOptions};
use common::film::PixelBoxFilter;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use common::scene::Material;
use common::scene::Scene;
use divan::Bencher;
use divan::counter::ItemsCount;
use glam::Vec3;

fn main() {
    divan::main();
}

/// Image side and samples per pixel: a few tenths of a second per render.
const SIDE: u32 = 128;
const SPP: u64 = 4;

/// One thread, so that the ratio measures the tracers and not the scheduler.
fn settings() -> RenderSettings {
    RenderSettings {
        threads: Some(1),
        ..RenderSettings::new(SIDE, SIDE, SPP)
    }
}

/// Chapter 01's Cornell box at `max_depth`; with `matte`, its spheres are matte white.
fn cornell(max_depth: u32, matte: bool) -> Scene {
    let mut scene = Builtin::Cornell.build(max_depth);
    if matte {
        for surface in &mut scene.surfaces {
            if matches!(
                surface.material,
                Material::Mirror { .. } | Material::Dielectric { .. }
            ) {
                surface.material = Material::diffuse(Vec3::splat(0.73));
            }
        }
    }
    scene
}

/// The same scene as chapter 08 renders it: no motion, no area lights, smooth materials.
fn for_path_tracer(scene: Scene) -> MotionScene {
    MotionScene::still(scene)
}

fn whitted(bencher: Bencher, max_depth: u32, matte: bool) {
    let scene = cornell(max_depth, matte);
    let settings = settings();
    bencher
        .counter(ItemsCount::new(u64::from(SIDE * SIDE) * SPP))
        .bench(|| ch08_path_tracing::lab::figures::whitted_through_the_film(&scene, &settings));
}

fn path_traced(bencher: Bencher, max_depth: u32, matte: bool) {
    let scene = for_path_tracer(cornell(max_depth, matte));
    let settings = settings();
    let method = Method::new(PathOptions::with_depth(max_depth));
    bencher
        .counter(ItemsCount::new(u64::from(SIDE * SIDE) * SPP))
        .bench(|| {
            ch08_path_tracing::render_with(
                &scene,
                method,
                &ch04_depth_of_field::Lens::PINHOLE,
                &settings,
                &IndependentSampler::new(1),
                &PixelBoxFilter,
            )
        });
}

/// Matte box, direct light only: the same work for both.
mod direct {
    use super::*;

    #[divan::bench(sample_count = 20)]
    fn chapter_03_whitted(bencher: Bencher) {
        whitted(bencher, 2, true);
    }

    #[divan::bench(sample_count = 20)]
    fn chapter_08_path(bencher: Bencher) {
        path_traced(bencher, 2, true);
    }
}

/// The box with its mirror and glass: different work by design.
mod full {
    use super::*;

    #[divan::bench(sample_count = 10)]
    fn chapter_03_whitted(bencher: Bencher) {
        whitted(bencher, 8, false);
    }

    #[divan::bench(sample_count = 10)]
    fn chapter_08_path(bencher: Bencher) {
        path_traced(bencher, 8, false);
    }
}
