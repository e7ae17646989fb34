//! Chapter 05's demo: the `street` scene through the chapter's camera rays and tracer, with
//! the shutter's length and the shape of its opening, the red ball's speed, and a camera that
//! slides while the shutter is open.
//!
//! The shutter is centred on the middle of the scene's motion, so that a longer shutter
//! stretches the smear both ways and the red ball stays in the frame. The times are the
//! chapter's stratified ones; a shutter that opens over a while warps them through the
//! chapter's trapezoid ([`OpeningTime`]).

use ch04_depth_of_field::Lens;
use ch05_motion_blur::path::trace_in_motion;
use ch05_motion_blur::scenes::{Builtin, DEFAULT_MAX_DEPTH, FAST_SPHERE_PATH};
use ch05_motion_blur::shutter_opening::sample_trapezoid_opening;
use ch05_motion_blur::{CameraRays, MotionScene, Shutter, StratifiedTime, TimeSampler};
use common::image::Image;
use common::sampler::{IndependentSampler, Sampler};
use common::scene::{CameraFrame, Material, Scene};
use glam::{Mat4, UVec2, Vec2, Vec3};

use crate::demo::{Claim, Control, Demo, Picture, Values, trace_each};
use crate::progressive::render_still;

/// The demo (`data-demo="motion-blur"`).
pub struct MotionBlurDemo;

/// The seed of every random number the demo draws.
const SEED: u64 = 5;

/// The samples per pixel the page refines to, and the strata of the shutter they cover.
const TARGET_SPP: u64 = 16;

/// The options of the opening's shape.
const OPENINGS: &[&str] = &[
    "opens and closes at once (the lecture's box)",
    "opens and closes over a while (trapezoid)",
];

/// A time sampler whose times follow a shutter that takes the share `ramp` of the exposure to
/// open and as long to close: the inner sampler's time number, warped by the chapter's
/// [`sample_trapezoid_opening`]. Every other dimension is the inner sampler's.
#[derive(Clone, Debug)]
struct OpeningTime<S> {
    inner: S,
    /// `None` for the lecture's box, whose times the inner sampler gives as they are.
    ramp: Option<f32>,
}

impl<S: Sampler> Sampler for OpeningTime<S> {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.inner.start_pixel_sample(pixel, sample_index);
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        self.inner.get_pixel_2d()
    }

    fn get_1d(&mut self) -> f32 {
        self.inner.get_1d()
    }

    fn get_2d(&mut self) -> Vec2 {
        self.inner.get_2d()
    }
}

impl<S: TimeSampler> TimeSampler for OpeningTime<S> {
    fn get_time_1d(&mut self) -> f32 {
        let u = self.inner.get_time_1d();
        match self.ramp {
            Some(ramp) => sample_trapezoid_opening(u, ramp),
            None => u,
        }
    }
}

/// The picture: the scene in motion, the chapter's camera rays and its tracer.
struct MotionBlur {
    world: MotionScene,
    camera_rays: CameraRays,
    sampler: OpeningTime<StratifiedTime<IndependentSampler>>,
}

impl Picture for MotionBlur {
    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
        trace_each(&self.sampler, pixels, index, add, |p_film, sampler| {
            let ray = self.camera_rays.generate(&self.world, p_film, sampler);
            trace_in_motion(&self.world, &ray, 1)
        });
    }
}

/// The shutter of the values: as long as they say, centred on the middle of the scene's
/// motion (which runs from time 0 to 1).
fn shutter(values: &Values) -> Shutter {
    let half = 0.5 * values.f32("shutter");
    Shutter {
        open: 0.5 - half,
        close: 0.5 + half,
    }
}

/// The chapter's `street` with the demo's values: seen through their shutter, the red ball
/// crossing at their speed (scene units per unit of time, through the middle of its path),
/// and the camera sliding sideways by their amount over the motion.
fn scene(values: &Values) -> Scene {
    let mut scene = Builtin::Street.scene(DEFAULT_MAX_DEPTH, shutter(values));
    let red = red_ball(&scene);
    let ball = &mut scene.moving[red];
    let middle = 0.5 * (FAST_SPHERE_PATH.0 + FAST_SPHERE_PATH.1);
    let along = (FAST_SPHERE_PATH.1 - FAST_SPHERE_PATH.0).normalize();
    let speed = values.f32("speed");
    ball.keyframes = vec![
        (0.0, Mat4::from_translation(middle - 0.5 * speed * along)),
        (1.0, Mat4::from_translation(middle + 0.5 * speed * along)),
    ];
    let slide = values.f32("camera");
    if slide > 0.0 {
        let frame = scene.camera.frame;
        let at = |offset: f32| {
            let shift = offset * slide * frame.left;
            let moved = CameraFrame::look_at(
                frame.origin + shift,
                frame.origin + frame.forward + shift,
                frame.up,
            )
            .expect("a camera moved sideways looks along the same direction");
            moved.to_matrix()
        };
        scene.camera.keyframes = vec![(0.0, at(-0.5)), (1.0, at(0.5))];
    }
    scene
}

/// Which of the street's moving shapes is the red ball: the one that starts where
/// `FAST_SPHERE_PATH` does.
fn red_ball(street: &Scene) -> usize {
    let start = Mat4::from_translation(FAST_SPHERE_PATH.0);
    street
        .moving
        .iter()
        .position(|moving| moving.keyframes.first().is_some_and(|k| k.1 == start))
        .expect("the street has its red ball, which starts at FAST_SPHERE_PATH's start")
}

/// The picture of `scene` with the opening of `values` at `width x height`, its times
/// stratified over `spp` samples.
fn picture_of(scene: Scene, values: &Values, width: u32, height: u32, spp: u64) -> MotionBlur {
    let world = MotionScene::still(scene);
    let camera_rays = CameraRays::new(&world, &Lens::PINHOLE, width, height);
    let ramp = (values.index("opening") == 1).then(|| values.f32("ramp"));
    MotionBlur {
        camera_rays,
        sampler: OpeningTime {
            inner: StratifiedTime::new(IndependentSampler::new(SEED), spp, SEED),
            ramp,
        },
        world,
    }
}

impl Demo for MotionBlurDemo {
    fn name(&self) -> &'static str {
        "motion-blur"
    }

    fn controls(&self) -> Vec<Control> {
        vec![
            Control::range("shutter", "shutter open for", 0.0, 1.0, 0.05, 0.3),
            Control::choice("opening", "the shutter", OPENINGS, 0),
            Control::range(
                "ramp",
                "share of the exposure spent opening",
                0.05,
                0.5,
                0.05,
                0.25,
            )
            .when("opening", 1.0),
            Control::range("speed", "red ball's speed", 0.0, 8.0, 0.25, 3.0),
            Control::range("camera", "camera's speed sideways", 0.0, 2.0, 0.1, 0.0),
        ]
    }

    fn target_spp(&self, _: &Values) -> u64 {
        TARGET_SPP
    }

    fn size(&self) -> (u32, u32) {
        (160, 100)
    }

    fn picture(
        &self,
        values: &Values,
        _view: usize,
        width: u32,
        height: u32,
    ) -> Result<Box<dyn Picture>, String> {
        Ok(Box::new(picture_of(
            scene(values),
            values,
            width,
            height,
            TARGET_SPP,
        )))
    }

    fn claims(&self) -> Vec<Claim> {
        vec![
            Claim {
                says: "a longer shutter stretches the red ball's smear over more pixels",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    smear_grows(
                        defaults.clone().with("shutter", 0.1),
                        defaults.with("shutter", 1.0),
                    )
                },
            },
            Claim {
                says: "a faster ball smears over more pixels; a still one is as sharp as at an \
                       instant",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    smear_grows(
                        defaults.clone().with("speed", 0.0),
                        defaults.clone().with("speed", 6.0),
                    )?;
                    let still = smear(&defaults.clone().with("speed", 0.0));
                    let instant = smear(&defaults.with("shutter", 0.0));
                    if still > instant {
                        return Err(format!(
                            "the still ball covers {still} pixels with the shutter open, more \
                             than the {instant} it covers at an instant"
                        ));
                    }
                    Ok(())
                },
            },
            Claim {
                says: "a shutter that takes a while to open and close shows the ball more in the \
                       middle of its path and fades the ends of its streak",
                check: |demo| {
                    let open = Values::defaults(&demo.controls()).with("shutter", 1.0);
                    let at_once = middle_share(&open.clone().with("opening", 0.0));
                    let gradual = middle_share(&open.with("opening", 1.0).with("ramp", 0.5));
                    if gradual > 1.1 * at_once {
                        Ok(())
                    } else {
                        Err(format!(
                            "the middle fifth of the picture holds {at_once} of the ball's \
                             showing with a shutter that opens at once, and {gradual} with one \
                             that opens over half the exposure: it should hold clearly more"
                        ))
                    }
                },
            },
            Claim {
                says: "a sliding camera blurs the still floor too",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    let still = floor_sharpness(&defaults.clone().with("camera", 0.0));
                    let sliding = floor_sharpness(&defaults.with("camera", 2.0));
                    if sliding < 0.5 * still {
                        Ok(())
                    } else {
                        Err(format!(
                            "the floor's mean squared gradient went from {still} to {sliding} when the \
                             camera slid: its checkers should have blurred"
                        ))
                    }
                },
            },
        ]
    }
}

/// The size of the claims' renders, and their samples per pixel.
const CLAIM_SIZE: UVec2 = UVec2::new(64, 40);
const CLAIM_SPP: u64 = 8;

/// Renders `scene` with the opening of `values` at the claims' size.
fn render(scene: Scene, values: &Values) -> Image {
    let picture = picture_of(scene, values, CLAIM_SIZE.x, CLAIM_SIZE.y, CLAIM_SPP);
    render_still(Box::new(picture), CLAIM_SIZE.x, CLAIM_SIZE.y, CLAIM_SPP)
}

/// How much the red ball shows in each pixel, seen directly or in the mirror at any time the
/// shutter is open: how much the pixel changes when the ball's colour does. The two renders
/// draw the same numbers, so nothing else changes (the ball's shadow does not depend on its
/// colour).
fn ball_showing(values: &Values) -> Vec<f32> {
    let ball = red_ball(&Builtin::Street.scene(DEFAULT_MAX_DEPTH, Shutter::INSTANT));
    let mut scene = scene(values);
    let shown = render(scene.clone(), values);
    // Moving shapes come after the still ones.
    let shape = scene.geometry.shapes().len() + ball;
    let surface = scene.surface_of_shape[shape] as usize;
    scene.surfaces[surface].material = Material::diffuse(Vec3::new(0.1, 0.9, 0.9));
    let recoloured = render(scene, values);
    shown
        .pixels
        .iter()
        .zip(&recoloured.pixels)
        .map(|(a, b)| (*a - *b).abs().element_sum())
        .collect()
}

/// The pixels the red ball shows in.
fn smear(values: &Values) -> usize {
    ball_showing(values).iter().filter(|&&d| d > 0.0).count()
}

/// The share of the red ball's showing (see [`ball_showing`]) in the middle fifth of the
/// picture's columns, where the middle of its path is, directly and in the mirror.
fn middle_share(values: &Values) -> f32 {
    let showing = ball_showing(values);
    let width = CLAIM_SIZE.x as usize;
    let middle = 2 * width / 5..3 * width / 5;
    let in_middle: f32 = (showing.iter().enumerate())
        .filter(|(i, _)| middle.contains(&(i % width)))
        .map(|(_, d)| d)
        .sum();
    in_middle / showing.iter().sum::<f32>()
}

/// Checks that the red ball covers more pixels with `more` than with `less`.
fn smear_grows(less: Values, more: Values) -> Result<(), String> {
    let (few, many) = (smear(&less), smear(&more));
    if many > few + few / 4 {
        Ok(())
    } else {
        Err(format!(
            "the red ball covered {few} pixels, then {many}: its smear should have grown"
        ))
    }
}

/// The mean squared difference between horizontal neighbours in the bottom quarter of the
/// picture, where the camera sees the near floor and its checkers: what blurs when the camera
/// moves. Squared, since a blur keeps the sum of a step's absolute differences and only
/// spreads it over more pixels.
fn floor_sharpness(values: &Values) -> f32 {
    let image = render(scene(values), values);
    let rows = 3 * CLAIM_SIZE.y / 4..CLAIM_SIZE.y;
    let mut sum = 0.0;
    let mut count = 0;
    for y in rows {
        for x in 1..CLAIM_SIZE.x {
            sum += (image.get(x, y) - image.get(x - 1, y)).length_squared();
            count += 1;
        }
    }
    sum / count as f32
}
