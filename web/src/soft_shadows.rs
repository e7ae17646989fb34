//! Chapter 07's demo: the lecture's ball and block under one area light, traced as the
//! chapter's `render_with` traces them (chapter 06's tracer lit by
//! [`AreaLighting`](ch07_soft_shadows::AreaLighting)), with the
//! light's shape and size, the shadow rays each light gets at a matte hit, and how a sphere
//! light is sampled.
//!
//! Every shape and size sends out the same light straight down (the chapter's scenes keep the
//! power as a light grows), so only the shadows change with them.

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{CameraRays, MotionScene};
use ch06_fuzzy_reflections::{TraceOptions, Tracer};
use ch07_soft_shadows::scenes::{Builder, camera, ceiling_panel, floor, matte};
use ch07_soft_shadows::{AreaLights, LightOptions, Strategy};
use common::geometry::{Disc, Parallelogram, Shape, Sphere, Triangle};
use common::image::Image;
use common::metrics::rmse;
use common::sampler::IndependentSampler;
use glam::{UVec2, Vec2, Vec3};

use crate::demo::{Claim, Control, Demo, Picture, Values, trace_each};
use crate::progressive::render_still;

/// The demo (`data-demo="soft-shadows"`).
pub struct SoftShadowsDemo;

/// The light shapes, in the order of the `light-shape` control's options. The sphere comes
/// second, so that the site's check, which moves each control to its next option in turn, finds
/// a sphere when it reaches the sampling control.
const SHAPES: &[&str] = &["square panel", "sphere", "triangle", "disc"];

/// The `sampling` control's options, in the order of [`Strategy::ALL`].
const SAMPLING: &[&str] = &["area", "solid angle"];

/// The `light-shape` option that is a sphere: the only shape the sampling strategy matters for.
const SPHERE: f64 = 1.0;

/// The seed of every picture: the same values always give the same image.
const SEED: u64 = 7;

/// The seed of the claims' references, so that no reference shares its first samples with the
/// render it judges.
const REFERENCE_SEED: u64 = 8;

/// The picture: the scene, its lights, chapter 05's pinhole camera rays and chapter 01's
/// independent sampler (a picture refined without end needs a sampler that takes any number of
/// samples).
struct SoftShadows {
    world: MotionScene,
    area_lights: AreaLights,
    lights: LightOptions,
    camera: CameraRays,
    sampler: IndependentSampler,
}

impl Picture for SoftShadows {
    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
        let lighting = self.area_lights.lighting(self.lights);
        let tracer = Tracer {
            world: &self.world,
            lighting: &lighting,
            options: TraceOptions::default(),
        };
        trace_each(&self.sampler, pixels, index, add, |p_film, sampler| {
            let ray = self.camera.generate(&self.world, p_film, sampler);
            tracer.trace(&ray, 1, sampler)
        });
    }
}

/// Where the light hangs: over the gap between the ball and the block, as in the chapter's
/// `small` and `large` scenes.
const LIGHT_CENTRE: Vec3 = Vec3::new(0.0, 3.0, 0.5);

/// The light of the demo's values: `size` across, facing down (a sphere glows all round).
fn light_shape(values: &Values) -> Shape {
    let size = values.f32("light-size");
    let half = 0.5 * size;
    let c = LIGHT_CENTRE;
    match SHAPES.get(values.index("light-shape")).copied() {
        Some("sphere") => Shape::Sphere(Sphere::new(c, half)),
        // Counter-clockwise seen from below, so that its front faces down.
        Some("triangle") => Shape::Triangle(Triangle::new(
            c + Vec3::new(0.0, 0.0, -half),
            c + Vec3::new(half, 0.0, half),
            c + Vec3::new(-half, 0.0, half),
        )),
        Some("disc") => Shape::Disc(Disc::new(c, -Vec3::Y, half)),
        _ => ceiling_panel(c, size),
    }
}

/// The chapter's `small` and `large` scene, a ball and a block on a floor before a wall, lit by
/// the light of the demo's values; without the ball and the block when `occluders` is false
/// (the floor fully lit, to measure shadows against).
fn scene(values: &Values, occluders: bool) -> MotionScene {
    let light = light_shape(values);
    // The area the floor far below sees: a sphere shows it its silhouette, a quarter of its
    // surface. Radiance times that area is the same for every shape and size, as in the
    // chapter's scenes, so only the shadows change.
    let seen_area = match light {
        Shape::Sphere(_) => 0.25 * light.area(),
        _ => light.area(),
    };
    let mut builder = Builder::new()
        .shape(floor(8.0), matte(Vec3::splat(0.7)))
        .shape(
            Shape::Parallelogram(Parallelogram::new(
                Vec3::new(-8.0, 0.0, -2.5),
                16.0 * Vec3::X,
                6.0 * Vec3::Y,
            )),
            matte(Vec3::splat(0.6)),
        );
    if occluders {
        builder = builder
            .shape(
                Shape::Sphere(Sphere::new(Vec3::new(-0.9, 0.6, 0.3), 0.6)),
                matte(Vec3::new(0.8, 0.2, 0.15)),
            )
            .block(
                Vec3::new(0.5, 0.0, -0.6),
                Vec3::new(1.4, 0.9, 0.3),
                matte(Vec3::new(0.2, 0.35, 0.8)),
            );
    }
    builder
        .area_light(light, Vec3::splat(10.0 / seen_area))
        .build(
            camera(Vec3::new(0.0, 2.0, 6.5), Vec3::new(0.0, 0.6, 0.0), 42.0),
            ch07_soft_shadows::scenes::DEFAULT_MAX_DEPTH,
        )
}

/// The shadow rays of the demo's values: how many per light, stratified as the chapter's
/// default, a sphere sampled by area or by solid angle.
fn light_options(values: &Values) -> LightOptions {
    let strategy = Strategy::ALL[values.index("sampling").min(Strategy::ALL.len() - 1)];
    LightOptions::with_samples(values.index("shadow-rays") as u32).with_strategy(strategy)
}

/// The picture of `values` at `width x height`, with or without the ball and the block, its
/// numbers drawn from `seed`.
fn picture(values: &Values, occluders: bool, seed: u64, width: u32, height: u32) -> SoftShadows {
    let world = scene(values, occluders);
    SoftShadows {
        area_lights: AreaLights::of(&world.scene),
        lights: light_options(values),
        camera: CameraRays::new(&world, &Lens::PINHOLE, width, height),
        sampler: IndependentSampler::new(seed),
        world,
    }
}

impl Demo for SoftShadowsDemo {
    fn name(&self) -> &'static str {
        "soft-shadows"
    }

    fn controls(&self) -> Vec<Control> {
        vec![
            Control::choice("light-shape", "light's shape", SHAPES, 0),
            Control::range("light-size", "light's size", 0.1, 2.5, 0.05, 1.0),
            Control::range("shadow-rays", "shadow rays per light", 1.0, 16.0, 1.0, 1.0),
            Control::choice("sampling", "sphere sampled by", SAMPLING, 1)
                .when("light-shape", SPHERE),
        ]
    }

    fn size(&self) -> (u32, u32) {
        (160, 120)
    }

    fn picture(
        &self,
        values: &Values,
        _view: usize,
        width: u32,
        height: u32,
    ) -> Result<Box<dyn Picture>, String> {
        Ok(Box::new(picture(values, true, SEED, width, height)))
    }

    fn claims(&self) -> Vec<Claim> {
        vec![
            Claim {
                says: "a larger light softens the shadows: more of the floor is partly lit",
                check: |demo| {
                    let small = partly_lit(demo, 0.25)?;
                    let large = partly_lit(demo, 2.5)?;
                    if large > small {
                        Ok(())
                    } else {
                        Err(format!(
                            "{large} pixels of the floor are partly lit under a light 2.5 wide, \
                             and {small} under one 0.25 wide"
                        ))
                    }
                },
            },
            Claim {
                says: "more shadow rays per light make the penumbrae less noisy at the same \
                       samples per pixel",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls()).with("light-size", 2.0);
                    let reference = reference(&defaults);
                    let error = |rays: f64| {
                        rmse(
                            &still(&defaults.clone().with("shadow-rays", rays), 2),
                            &reference,
                        )
                    };
                    let (one, sixteen) = (error(1.0), error(16.0));
                    less(sixteen, one, "16 shadow rays per light", "1")
                },
            },
            Claim {
                says: "a sphere light sampled by solid angle is less noisy than sampled by area",
                check: |demo| {
                    let sphere = Values::defaults(&demo.controls()).with("light-shape", SPHERE);
                    let reference = reference(&sphere);
                    let error = |strategy: Strategy| {
                        let index = Strategy::ALL.iter().position(|&s| s == strategy);
                        let values = sphere.clone().with("sampling", index.unwrap_or(0) as f64);
                        rmse(&still(&values, 4), &reference)
                    };
                    let (solid_angle, area) = (error(Strategy::SolidAngle), error(Strategy::Area));
                    less(solid_angle, area, "solid angle", "area")
                },
            },
        ]
    }
}

/// The size of the claims' renders.
const CLAIM_SIZE: UVec2 = UVec2::new(48, 36);

/// The demo's picture of `values` at the claims' size and `spp` samples per pixel.
fn still(values: &Values, spp: u64) -> Image {
    still_from(values, SEED, spp)
}

/// A reference for the claims: `values` with 16 shadow rays per light and 16 samples per pixel,
/// from other numbers than the renders it judges.
fn reference(values: &Values) -> Image {
    still_from(
        &values.clone().with("shadow-rays", 16.0),
        REFERENCE_SEED,
        16,
    )
}

/// The picture of `values` at the claims' size, `spp` samples per pixel drawn from `seed`.
fn still_from(values: &Values, seed: u64, spp: u64) -> Image {
    let picture = picture(values, true, seed, CLAIM_SIZE.x, CLAIM_SIZE.y);
    render_still(Box::new(picture), CLAIM_SIZE.x, CLAIM_SIZE.y, spp)
}

/// Ok when the error `ours` is below `theirs`, or what went wrong.
fn less(ours: f64, theirs: f64, what: &str, against: &str) -> Result<(), String> {
    if ours < theirs {
        Ok(())
    } else {
        Err(format!(
            "the error against the reference is {ours:.4} with {what}, and {theirs:.4} with \
             {against}"
        ))
    }
}

/// How many pixels of the floor and the wall are partly lit under a square panel `size` wide:
/// lit, but less than where the ball and the block are taken away.
///
/// Both renders draw the same numbers for a pixel whose samples all see the grey floor or wall,
/// so there the ratio of the two is exactly the share of the light's samples the shadow rays
/// found visible: 1 in full light, 0 in the umbra, in between only in a penumbra. The light is
/// white, so that share is the same in every colour channel; a pixel that sees the red ball or
/// the blue block in one render and the grey floor in the other has ratios that differ between
/// the channels, and is left out.
fn partly_lit(demo: &dyn Demo, size: f64) -> Result<usize, String> {
    let values = Values::defaults(&demo.controls())
        .with("light-shape", 0.0)
        .with("light-size", size)
        .with("shadow-rays", 16.0);
    let spp = 4;
    let render = |occluders| {
        let picture = picture(&values, occluders, SEED, CLAIM_SIZE.x, CLAIM_SIZE.y);
        render_still(Box::new(picture), CLAIM_SIZE.x, CLAIM_SIZE.y, spp)
    };
    let (shadowed, open) = (render(true), render(false));
    let mut grey = 0;
    let mut partly = 0;
    for (s, o) in shadowed.pixels.iter().zip(&open.pixels) {
        if o.min_element() <= 0.0 {
            continue;
        }
        let share = *s / *o;
        if share.max_element() - share.min_element() > 1e-4 {
            continue; // the ball or the block in one render only
        }
        grey += 1;
        partly += usize::from(share.x > 0.02 && share.x < 0.98);
    }
    if grey < CLAIM_SIZE.element_product() as usize / 2 {
        return Err(format!(
            "only {grey} pixels see the grey floor or wall alike with and without the ball \
             and the block under a panel {size} wide"
        ));
    }
    Ok(partly)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sampling_control_shows_for_the_sphere() {
        assert_eq!(SHAPES[SPHERE as usize], "sphere");
        let values = Values::defaults(&SoftShadowsDemo.controls()).with("light-shape", SPHERE);
        assert!(matches!(light_shape(&values), Shape::Sphere(_)));
    }

    #[test]
    fn the_sampling_options_are_the_chapters_strategies_in_order() {
        let names: Vec<String> = SAMPLING.iter().map(|o| o.replace(' ', "-")).collect();
        let strategies: Vec<&str> = Strategy::ALL.iter().map(|s| s.name()).collect();
        assert_eq!(names, strategies);
    }
}
