//! Chapter 10's demo: the light reaching what the camera sees straight from the lights, one
//! light sample and one BSDF sample per pixel sample, combined by the balance or the power
//! heuristic or by the optimal weights solved per pixel (directly, or progressively); on the
//! chapter's glossy floor, whose roughness and light size move where each technique is good,
//! and on its plane under the sky, where the optimal weights leave no noise at all.
//!
//! The optimal weights belong to a pixel, not to a sample: a pixel's value is solved from the
//! sums of all its samples so far, and changes as each sample arrives. The page's film
//! averages the values it is given, so at a pixel's `n`-th sample the picture hands it
//! `n E_n − (n − 1) E_(n−1)`, where `E_n` is the pixel's estimate from its first `n` samples:
//! the film's average is then `E_n` itself. The estimates are the chapter's own (its sums, its
//! solve, its progressive iterations of 4, 8, 16 ... samples), so the demo at `N` samples per
//! pixel shows the chapter's `render_direct` at `N`, pixel for pixel.

use std::cell::{Cell, RefCell};

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{CameraRays, MotionScene};
use ch06_fuzzy_reflections::FuzzMethod;
use ch07_soft_shadows::scenes::{Builder, camera, floor, matte};
use ch07_soft_shadows::{AreaLights, LightSampling};
use ch08_path_tracing::{MisHeuristic, PathOptions, PathTracer, SceneLights};
use ch09_materials::SceneMaterials;
use ch10_optimal_mis::pixel::{Combination, FIRST_ITERATION, heuristic_estimate};
use ch10_optimal_mis::techniques::draw_techniques;
use ch10_optimal_mis::{OptimalSums, ProgressiveOptimal};
use common::geometry::{Parallelogram, Shape, Sphere};
use common::image::Image;
use common::metrics::{mean, rmse};
use common::render::trace_pixel_sample;
use common::sampler::IndependentSampler;
use common::scene::{Conductor, Material, Microfacet, MicrofacetDistribution};
use glam::{UVec2, Vec2, Vec3};

use crate::demo::{Claim, Control, Demo, Picture, Values};
use crate::progressive::render_demo;

/// The demo (`data-demo="optimal-mis"`).
pub struct OptimalMisDemo;

/// The scenes, as the page names them.
const SCENES: &[&str] = &["glossy floor", "plane under the sky"];

/// The combinations, as the page names them, in the order of [`COMBINATIONS`].
const COMBINATION_NAMES: &[&str] = &["optimal", "progressive optimal", "power", "balance"];

/// The chapter's combinations, in the page's order.
const COMBINATIONS: [Combination; 4] = [
    Combination::Optimal,
    Combination::Progressive,
    Combination::Heuristic(MisHeuristic::Power),
    Combination::Heuristic(MisHeuristic::Balance),
];

/// The seed of every picture, and the claims' reference's own.
const SEED: u64 = 10;
const REFERENCE_SEED: u64 = 1_010;

/// The plane's albedo and the sky's radiance: every pixel of the plane is their product.
const PLANE_ALBEDO: Vec3 = Vec3::new(0.5, 0.25, 0.125);
const SKY: f32 = 2.0;

/// The chapter's `scenes/glossy-floor.xml`, written out with chapter 07's builder (the
/// scene-file reader belongs to the workbench): a sphere light over a rough mirror-metal floor
/// (Mitsuba's default `roughconductor`, Beckmann) with a matte box on it, the light out of view.
/// The floor's roughness and the light's radius are the controls'.
fn glossy_floor(alpha: f32, light_radius: f32) -> MotionScene {
    let metal = Material::Conductor(Conductor {
        eta: Vec3::ZERO,
        k: Vec3::ONE,
        specular_reflectance: Vec3::ONE,
        specular_texture: None,
        two_sided: false,
        roughness: Some(Microfacet::isotropic(
            MicrofacetDistribution::Beckmann,
            alpha,
        )),
    });
    Builder::new()
        .shape(floor(4.0), metal)
        .block(
            Vec3::new(-1.5, 0.0, -0.5),
            Vec3::new(-0.5, 1.0, 0.5),
            matte(Vec3::splat(0.6)),
        )
        .area_light(
            Shape::Sphere(Sphere::new(Vec3::new(0.5, 2.0, 0.0), light_radius)),
            Vec3::splat(10.0),
        )
        .build(camera(Vec3::new(0.0, 3.0, 6.0), Vec3::ZERO, 45.0), 1)
}

/// The chapter's `scenes/plane-under-sky.xml`: a matte plane 40 wide facing the camera, filling
/// its view, under a constant sky, nothing in between.
fn plane_under_sky() -> MotionScene {
    let plane = Shape::Parallelogram(Parallelogram::new(
        Vec3::new(-20.0, -20.0, 0.0),
        40.0 * Vec3::X,
        40.0 * Vec3::Y,
    ));
    let mut world = Builder::new()
        .shape(plane, matte(PLANE_ALBEDO))
        .build(camera(Vec3::new(0.0, 1.0, 5.0), Vec3::ZERO, 40.0), 1);
    world.scene.environment = Vec3::splat(SKY);
    world
}

/// What one pixel has gathered from its samples so far.
#[derive(Clone, Copy, Default)]
struct PixelSums {
    /// Samples taken.
    samples: u64,
    /// The sum of what needs no combining ([`SurfaceDraws::certain`]).
    ///
    /// [`SurfaceDraws::certain`]: ch10_optimal_mis::techniques::SurfaceDraws::certain
    certain: Vec3,
    /// The direct estimator's sums.
    optimal: OptimalSums,
    /// The progressive variant, and where its current iteration ends.
    progressive: ProgressiveOptimal,
    iteration_size: u64,
    iteration_end: u64,
    /// The estimate the film's average holds for the pixel.
    shown: Vec3,
}

impl PixelSums {
    fn new() -> Self {
        Self {
            iteration_size: FIRST_ITERATION,
            iteration_end: FIRST_ITERATION,
            ..Self::default()
        }
    }

    /// The pixel's estimate from its samples so far, as the chapter's `pixel_value` makes it
    /// from that many: the progressive variant's last iteration cut where the samples end.
    fn estimate(&self, combination: Combination) -> Vec3 {
        let n = self.samples.max(1) as f32;
        match combination {
            Combination::Heuristic(_) => self.shown,
            Combination::Optimal => self.certain / n + self.optimal.estimate(),
            Combination::Progressive => {
                let mut cut = self.progressive;
                cut.end_iteration();
                self.certain / n + cut.estimate()
            }
        }
    }
}

/// The picture: the scene, its lights and materials, the camera rays, the combination, and
/// every pixel's sums.
struct OptimalMis {
    world: MotionScene,
    area_lights: AreaLights,
    materials: SceneMaterials,
    camera_rays: CameraRays,
    combination: Combination,
    sampler: IndependentSampler,
    width: u32,
    pixels: RefCell<Vec<PixelSums>>,
}

impl Picture for OptimalMis {
    /// Sample `index` of each pixel: its draws join the pixel's sums, and the film gets what
    /// moves its average to the pixel's new estimate (see the module's opening). The page
    /// traces a pixel's samples in order; sample 0 starts the pixel afresh.
    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
        let tracer = PathTracer {
            world: &self.world,
            lights: SceneLights::of(&self.world, &self.area_lights, LightSampling::solid_angle()),
            options: PathOptions::default(),
            materials: self.materials.clone(),
        };
        let mut sampler = self.sampler.clone();
        let mut sums = self.pixels.borrow_mut();
        for &pixel in pixels {
            let Some(state) = sums.get_mut((pixel.y * self.width + pixel.x) as usize) else {
                continue;
            };
            if index == 0 {
                *state = PixelSums::new();
            }
            // The chapter's draws at the sample, taken as the render loop takes a sample.
            let drawn = Cell::new(None);
            let (p_film, _) = trace_pixel_sample(&mut sampler, pixel, index, &|p_film, s| {
                let ray = self.camera_rays.generate(&self.world, p_film, s);
                drawn.set(Some(draw_techniques(&tracer, &ray, s)));
                Vec3::ZERO
            });
            let Some(draws) = drawn.get() else {
                continue;
            };
            let value = match self.combination {
                Combination::Heuristic(heuristic) => {
                    draws.certain + heuristic_estimate(&draws, heuristic)
                }
                combination => {
                    state.samples += 1;
                    state.certain += draws.certain;
                    if combination == Combination::Optimal {
                        state.optimal.add(&draws);
                    } else {
                        state.progressive.add(&draws);
                        if state.samples == state.iteration_end {
                            state.progressive.end_iteration();
                            state.iteration_size *= 2;
                            state.iteration_end += state.iteration_size;
                        }
                    }
                    let (before, now) = (state.shown, state.estimate(combination));
                    state.shown = now;
                    let n = state.samples as f32;
                    n * now - (n - 1.0) * before
                }
            };
            add(p_film, value);
        }
    }
}

/// The picture of `values` at `width x height`, its numbers drawn from `seed`.
fn picture(values: &Values, seed: u64, width: u32, height: u32) -> OptimalMis {
    let world = match values.index("scene") {
        0 => glossy_floor(values.f32("alpha"), values.f32("light-radius")),
        _ => plane_under_sky(),
    };
    let combination = COMBINATIONS[values.index("combination").min(COMBINATIONS.len() - 1)];
    OptimalMis {
        area_lights: AreaLights::of(&world.scene),
        materials: SceneMaterials::of(&world.scene, FuzzMethod::Lobe),
        camera_rays: CameraRays::new(&world, &Lens::PINHOLE, width, height),
        combination,
        sampler: IndependentSampler::new(seed),
        width,
        pixels: RefCell::new(vec![PixelSums::new(); width as usize * height as usize]),
        world,
    }
}

impl Demo for OptimalMisDemo {
    fn name(&self) -> &'static str {
        "optimal-mis"
    }

    /// The scene comes last: the site's check moves the controls in this order, and would
    /// find the floor's roughness and the light's radius hidden once the scene is the plane.
    fn controls(&self) -> Vec<Control> {
        vec![
            Control::choice("combination", "combination", COMBINATION_NAMES, 0),
            Control::range("alpha", "floor roughness α", 0.02, 0.6, 0.01, 0.15).when("scene", 0.0),
            Control::range("light-radius", "light radius", 0.05, 1.0, 0.05, 0.4).when("scene", 0.0),
            Control::choice("scene", "scene", SCENES, 0),
        ]
    }

    /// The chapter's films are 96 x 64.
    fn size(&self) -> (u32, u32) {
        (144, 96)
    }

    fn picture(
        &self,
        values: &Values,
        _view: usize,
        width: u32,
        height: u32,
    ) -> Result<Box<dyn Picture>, String> {
        Ok(Box::new(picture(values, SEED, width, height)))
    }

    fn claims(&self) -> Vec<Claim> {
        vec![
            Claim {
                says: "on the plane under the sky the optimal weights make every pixel exact \
                       from 4 samples, where the balance heuristic is still noisy",
                check: |demo| {
                    let plane = Values::defaults(&demo.controls()).with("scene", 1.0);
                    let exact = PLANE_ALBEDO * SKY;
                    let worst = |combination: f64| -> Result<f32, String> {
                        let image =
                            render(demo, &plane.clone().with("combination", combination), 4)?;
                        Ok(image
                            .pixels
                            .iter()
                            .map(|p| ((*p - exact) / exact).abs().max_element())
                            .fold(0.0, f32::max))
                    };
                    let (optimal, balance) = (worst(0.0)?, worst(3.0)?);
                    if optimal > 1e-3 || balance < 0.05 {
                        return Err(format!(
                            "the worst pixel is off the exact value by {:.3} % with the optimal \
                             weights and by {:.1} % with the balance heuristic",
                            100.0 * optimal,
                            100.0 * balance
                        ));
                    }
                    Ok(())
                },
            },
            Claim {
                says: "every combination estimates the same image: on the glossy floor they \
                       agree on average",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    let average = |combination: f64| -> Result<glam::DVec3, String> {
                        let values = defaults.clone().with("combination", combination);
                        Ok(mean(&render(demo, &values, 16)?))
                    };
                    let expected = average(2.0)?;
                    for (index, name) in COMBINATION_NAMES.iter().enumerate() {
                        let got = average(index as f64)?;
                        let gap = (got - expected).abs().max_element() / expected.max_element();
                        if gap > 0.03 {
                            return Err(format!(
                                "the image's mean is {got:.4} with {name} weights and \
                                 {expected:.4} with the power heuristic"
                            ));
                        }
                    }
                    Ok(())
                },
            },
            Claim {
                says: "on the glossy floor the optimal weights are less noisy than the balance \
                       heuristic",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    let reference = still(
                        &defaults.clone().with("combination", 2.0),
                        REFERENCE_SEED,
                        256,
                    );
                    let error = |combination: f64| -> Result<f64, String> {
                        let values = defaults.clone().with("combination", combination);
                        Ok(rmse(&render(demo, &values, 16)?, &reference))
                    };
                    let (optimal, balance) = (error(0.0)?, error(3.0)?);
                    if optimal >= balance {
                        return Err(format!(
                            "the error against a long render is {optimal:.4} with the optimal \
                             weights and {balance:.4} with the balance heuristic"
                        ));
                    }
                    Ok(())
                },
            },
            Claim {
                says: "a rougher floor spreads the light's reflection: a dimmer highlight on the floor",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    let peak = |alpha: f64| -> Result<f32, String> {
                        let image = render(demo, &defaults.clone().with("alpha", alpha), 16)?;
                        Ok(floor_pixels(&image)
                            .map(|p| p.max_element())
                            .fold(0.0, f32::max))
                    };
                    let (sharp, rough) = (peak(0.05)?, peak(0.5)?);
                    if rough >= sharp {
                        return Err(format!(
                            "the brightest pixel is {rough:.2} at α = 0.5, not dimmer than \
                             {sharp:.2} at α = 0.05"
                        ));
                    }
                    Ok(())
                },
            },
        ]
    }
}

/// The size of the claims' renders.
const CLAIM_SIZE: UVec2 = UVec2::new(48, 32);

/// The demo's picture of `values`, rendered small at `spp`.
fn render(demo: &dyn Demo, values: &Values, spp: u64) -> Result<Image, String> {
    render_demo(demo, values, CLAIM_SIZE, spp)
}

/// The pixels of the glossy floor's lower two thirds, all floor: the light itself shows at
/// the top.
fn floor_pixels(image: &Image) -> impl Iterator<Item = Vec3> + '_ {
    let first_row = image.height as usize / 3;
    image.pixels[first_row * image.width as usize..]
        .iter()
        .copied()
}

/// The picture of `values` at the claims' size from `seed`, at `spp`.
fn still(values: &Values, seed: u64, spp: u64) -> Image {
    let picture = picture(values, seed, CLAIM_SIZE.x, CLAIM_SIZE.y);
    crate::progressive::render_still(Box::new(picture), CLAIM_SIZE.x, CLAIM_SIZE.y, spp)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ch10_optimal_mis::render_direct_with;
    use common::render::RenderSettings;

    /// The demo refined a slice at a time shows the chapter's own render, pixel for pixel,
    /// for every combination: the film's average is the pixel's estimate.
    #[test]
    fn the_demo_is_the_chapters_render_direct() {
        let (width, height, spp) = (12, 8, 9);
        for (index, &combination) in COMBINATIONS.iter().enumerate() {
            let values =
                Values::defaults(&OptimalMisDemo.controls()).with("combination", index as f64);
            let mut session = crate::progressive::Session::new(
                Box::new(picture(&values, SEED, width, height)),
                width,
                height,
                spp,
            );
            while !session.is_done() {
                session.advance(17);
            }
            let ours = session.image();
            let world = glossy_floor(0.15, 0.4);
            let settings = RenderSettings::new(width, height, spp);
            let theirs = render_direct_with(
                &world,
                SceneMaterials::of(&world.scene, FuzzMethod::Lobe),
                PathOptions::default(),
                &Lens::PINHOLE,
                &settings,
                &IndependentSampler::new(SEED),
                combination,
            )
            .image;
            for (i, (a, b)) in ours.pixels.iter().zip(&theirs.pixels).enumerate() {
                let gap = (*a - *b).abs().max_element();
                assert!(
                    gap <= 1e-4 * (1.0 + b.max_element()),
                    "{}: pixel {i} is {a} in the demo and {b} in the chapter's render",
                    combination.name()
                );
            }
        }
    }

    #[test]
    fn the_combinations_are_the_chapters_four() {
        for combination in Combination::ALL {
            assert!(
                COMBINATIONS.contains(&combination),
                "{}",
                combination.name()
            );
        }
        assert_eq!(COMBINATIONS.len(), COMBINATION_NAMES.len());
    }
}
