//! Chapter 03's demo: the chapter's scenes that alias, through chapter 01's camera and tracer,
//! with the chapter's own pixel samplers and reconstruction filters, at a chosen number of
//! samples per pixel.
//!
//! The number of samples is a control and also where refining stops: the stratified sampler
//! lays out its grid of strata for that number before the first sample is drawn. The page may
//! zoom on the pixels, since the staircases and the moiré are a matter of single pixels.

use ch01_whitted::camera::PinholeCamera;
use ch01_whitted::tracer;
use ch03_anti_aliasing::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use common::film::Filter;
use common::image::Image;
use common::metrics::rmse;
use common::scene::Scene;
use glam::{UVec2, Vec2, Vec3};

use crate::contrast::rms_neighbour_difference;
use crate::demo::{Claim, Control, Demo, Picture, Values, trace_each};
use crate::progressive::render_demo;

/// The demo (`data-demo="anti-aliasing"`).
pub struct AntiAliasingDemo;

/// The seed of every sampler of the demo: the same values always give the same picture.
const SEED: u64 = 3;

/// The samplers, in the order of [`PixelSamplerKind::ALL`] (the choice's index is the kind's).
const SAMPLERS: &[&str] = &[
    "centre",
    "random",
    "stratified",
    "halton",
    "multijitter",
    "sobol",
];

/// The filters, in the order of [`FilterKind::ALL`].
const FILTERS: &[&str] = &["box", "tent", "gaussian", "mitchell"];

/// The scenes, in the order of [`Builtin::ALL`].
const SCENES: &[&str] = &["edges", "checkerboard"];

/// The picture: a chapter 03 scene, its pinhole camera, the chosen sampler and filter.
struct AntiAliased {
    scene: Scene,
    camera: PinholeCamera,
    sampler: PixelSampler,
    filter: ReconstructionFilter,
}

impl Picture for AntiAliased {
    fn filter(&self) -> &dyn Filter {
        &self.filter
    }

    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
        trace_each(&self.sampler, pixels, index, add, |p_film, _| {
            tracer::trace(&self.scene, &self.camera.generate_ray(p_film), 1)
        });
    }
}

impl Demo for AntiAliasingDemo {
    fn name(&self) -> &'static str {
        "anti-aliasing"
    }

    fn controls(&self) -> Vec<Control> {
        vec![
            Control::choice("sampler", "pixel sampler", SAMPLERS, 1),
            Control::choice("filter", "reconstruction filter", FILTERS, 0),
            Control::range("radius", "filter radius (pixels)", 0.5, 3.0, 0.25, 0.5),
            Control::range("spp", "samples per pixel", 1.0, 64.0, 1.0, 16.0),
            Control::choice("scene", "scene", SCENES, 0),
        ]
    }

    fn target_spp(&self, values: &Values) -> u64 {
        values.index("spp").max(1) as u64
    }

    fn size(&self) -> (u32, u32) {
        // The chapter's scenes are framed 4:3.
        (160, 120)
    }

    fn zoom(&self) -> bool {
        true
    }

    fn picture(
        &self,
        values: &Values,
        _view: usize,
        width: u32,
        height: u32,
    ) -> Result<Box<dyn Picture>, String> {
        let kind = *PixelSamplerKind::ALL
            .get(values.index("sampler"))
            .ok_or("no such pixel sampler")?;
        let filter_kind = *FilterKind::ALL
            .get(values.index("filter"))
            .ok_or("no such filter")?;
        let builtin = *Builtin::ALL
            .get(values.index("scene"))
            .ok_or("no such scene")?;
        let scene = builtin.build(DEFAULT_MAX_DEPTH);
        let camera = PinholeCamera::of(&scene.camera, width, height);
        Ok(Box::new(AntiAliased {
            scene,
            camera,
            sampler: PixelSampler::new(kind, self.target_spp(values), SEED)?,
            filter: ReconstructionFilter::new(filter_kind, Some(values.f32("radius")))?,
        }))
    }

    fn claims(&self) -> Vec<Claim> {
        vec![
            Claim {
                says: "at equal samples per pixel, stratified samples err less than random ones \
                       on the edges",
                check: |demo| {
                    let reference = reference(demo)?;
                    let error = |sampler| -> Result<f64, String> {
                        let values = defaults(demo).with("sampler", sampler).with("spp", 16.0);
                        Ok(rmse(&render(demo, &values)?, &reference))
                    };
                    let (random, stratified) = (error(1.0)?, error(2.0)?);
                    at_most(stratified, 0.8 * random).map_err(|_| {
                        format!(
                            "at 16 samples per pixel, stratified samples err by {stratified:.4}, \
                             not clearly less than random ones ({random:.4})"
                        )
                    })
                },
            },
            Claim {
                says: "more samples per pixel err less",
                check: |demo| {
                    let reference = reference(demo)?;
                    let error = |spp| -> Result<f64, String> {
                        let values = defaults(demo).with("spp", spp);
                        Ok(rmse(&render(demo, &values)?, &reference))
                    };
                    let (few, many) = (error(2.0)?, error(32.0)?);
                    at_most(many, 0.5 * few).map_err(|_| {
                        format!(
                            "random samples err by {many:.4} at 32 per pixel, not clearly less \
                             than at 2 ({few:.4})"
                        )
                    })
                },
            },
            Claim {
                says: "a wider filter blurs the checkerboard: neighbouring pixels differ less",
                check: |demo| {
                    let sharpness = |radius| -> Result<f64, String> {
                        let values = defaults(demo)
                            .with("scene", 1.0)
                            .with("sampler", 2.0)
                            .with("spp", 64.0)
                            .with("filter", 1.0)
                            .with("radius", radius);
                        Ok(rms_neighbour_difference(&render(demo, &values)?, |_, _| {
                            true
                        }))
                    };
                    let (narrow, wide) = (sharpness(1.0)?, sharpness(3.0)?);
                    at_most(wide, 0.8 * narrow).map_err(|_| {
                        format!(
                            "with a tent of radius 3 neighbouring pixels differ by {wide:.4}, \
                             not clearly less than with radius 1 ({narrow:.4})"
                        )
                    })
                },
            },
        ]
    }
}

/// The size of the claims' renders (the scenes' 4:3).
const CLAIM_SIZE: UVec2 = UVec2::new(48, 36);

/// The demo's starting values.
fn defaults(demo: &dyn Demo) -> Values {
    Values::defaults(&demo.controls())
}

/// The demo with `values`, rendered whole at the claims' size and the values' samples.
fn render(demo: &dyn Demo, values: &Values) -> Result<Image, String> {
    render_demo(demo, values, CLAIM_SIZE, demo.target_spp(values))
}

/// The edges scene as the pixel box sees it, nearly exactly: Halton samples, far more of them
/// than the demo takes, averaged by the box filter of radius 1/2 (each pixel's own samples).
fn reference(demo: &dyn Demo) -> Result<Image, String> {
    let values = defaults(demo)
        .with("scene", 0.0)
        .with("filter", 0.0)
        .with("radius", 0.5)
        .with("sampler", 3.0);
    render_demo(demo, &values, CLAIM_SIZE, 256)
}

/// `Ok` if `value` is at most `bound`.
fn at_most(value: f64, bound: f64) -> Result<(), ()> {
    if value <= bound { Ok(()) } else { Err(()) }
}
