//! Chapter 06's demo: the chapter's fuzzy tracer on its glossy `floor` or its `frosted` pane,
//! with the exponent of the lobes, the lecture's disc against the `cos^n` lobe, what happens
//! to a direction spread below the surface, and at glass which ray to follow.
//!
//! The scenes are still, so chapter 05's camera rays draw no time; the pixel position comes
//! first, then the numbers of each bounce, as in the chapter's renders.

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{CameraRays, MotionScene};
use ch06_fuzzy_reflections::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch06_fuzzy_reflections::{
    BelowSurface, FuzzMethod, GlassStrategy, PointLights, TraceOptions, Tracer,
};
use common::geometry::SurfaceHit;
use common::image::Image;
use common::render::counting_rays;
use common::sampler::IndependentSampler;
use common::scene::Material;
use glam::{UVec2, Vec2, Vec3};

use crate::demo::{Claim, Control, Demo, Picture, Values, trace_each};
use crate::progressive::render_still;

/// The demo (`data-demo="fuzzy"`).
pub struct FuzzyDemo;

/// The seed of the page's pictures.
const SEED: u64 = 6;

/// The depth limit of the demo's paths: enough to go in and out of the pane and to see a
/// reflection of a reflection, and lower than the chapter's own (whose last segments, inside
/// the pane, add little): following both rays at glass costs a ray per segment per split.
const MAX_DEPTH: u32 = 5;

/// The scenes, in the order of the `scene` control.
const SCENES: [Builtin; 2] = [Builtin::Floor, Builtin::Frosted];

/// The policies below the surface, in the order of the `below` control.
const BELOW: [BelowSurface; 3] = [
    BelowSurface::Drop,
    BelowSurface::Resample,
    BelowSurface::Reflect,
];

/// The strategies at glass, in the order of the `glass` control.
const GLASS: [GlassStrategy; 3] = [
    GlassStrategy::Both,
    GlassStrategy::Half,
    GlassStrategy::Fresnel,
];

/// The picture: the scene, the chapter's camera rays and its tracer with the demo's options.
struct Fuzzy {
    world: MotionScene,
    camera_rays: CameraRays,
    options: TraceOptions,
    sampler: IndependentSampler,
}

impl Picture for Fuzzy {
    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
        let tracer = Tracer {
            world: &self.world,
            lighting: &PointLights,
            options: self.options,
        };
        trace_each(&self.sampler, pixels, index, add, |p_film, sampler| {
            let ray = self.camera_rays.generate(&self.world, p_film, sampler);
            tracer.trace(&ray, 1, sampler)
        });
    }
}

/// The lobes' exponent the values ask for: the slider gives its power of ten.
fn exponent(values: &Values) -> f32 {
    10f32.powf(values.f32("exponent"))
}

/// The tracer's options the values ask for.
fn options(values: &Values) -> TraceOptions {
    TraceOptions {
        glass: GLASS[values.index("glass")],
        fuzz: FuzzMethod::ALL[values.index("fuzz")],
        below: BELOW[values.index("below")],
    }
}

/// The chapter's scene the values ask for, with their exponent.
fn world(values: &Values) -> MotionScene {
    SCENES[values.index("scene")].build(MAX_DEPTH, exponent(values))
}

/// The picture of the values at `width x height`, its numbers drawn from `seed`.
fn picture_of(values: &Values, width: u32, height: u32, seed: u64) -> Fuzzy {
    let world = world(values);
    Fuzzy {
        camera_rays: CameraRays::new(&world, &Lens::PINHOLE, width, height),
        options: options(values),
        sampler: IndependentSampler::new(seed),
        world,
    }
}

impl Demo for FuzzyDemo {
    fn name(&self) -> &'static str {
        "fuzzy"
    }

    fn controls(&self) -> Vec<Control> {
        // The policy below the surface comes before the exponent: it shows on the floor where
        // the view grazes it, which a sharp lobe hardly ever leaves.
        vec![
            Control::choice(
                "fuzz",
                "directions spread by",
                &["the cos^n lobe", "the lecture's disc"],
                0,
            ),
            Control::choice(
                "below",
                "a direction below the surface is",
                &["dropped", "drawn again", "mirrored back above"],
                0,
            ),
            Control::range(
                "exponent",
                "exponent n of the lobe, as a power of ten",
                0.0,
                4.0,
                0.1,
                2.0,
            ),
            Control::choice("scene", "scene", &["glossy floor", "frosted glass pane"], 0),
            Control::choice(
                "glass",
                "at glass, follow",
                &[
                    "both rays",
                    "one ray, each at probability 1/2",
                    "one ray, reflection at probability F",
                ],
                2,
            )
            .when("scene", 1.0),
        ]
    }

    fn size(&self) -> (u32, u32) {
        (144, 108)
    }

    fn picture(
        &self,
        values: &Values,
        _view: usize,
        width: u32,
        height: u32,
    ) -> Result<Box<dyn Picture>, String> {
        Ok(Box::new(picture_of(values, width, height, SEED)))
    }

    fn claims(&self) -> Vec<Claim> {
        vec![
            Claim {
                says: "a larger exponent makes the floor's reflections sharper: nearer a \
                       mirror's",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    let mirror = render(&defaults.clone().with("exponent", 6.0), SEED);
                    let distance = |log_n: f64| {
                        mean_abs_difference(
                            &render(&defaults.clone().with("exponent", log_n), SEED),
                            &mirror,
                        )
                    };
                    let (rough, sharp) = (distance(1.0), distance(3.0));
                    if sharp < 0.75 * rough {
                        Ok(())
                    } else {
                        Err(format!(
                            "the floor at n = 10 is {rough} from a mirror's picture, and at \
                             n = 1000 {sharp}: the sharper lobe should be clearly nearer"
                        ))
                    }
                },
            },
            Claim {
                says: "the lecture's disc changes the floor's reflections and hardly the matte \
                       wall and balls seen directly",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    let lobe = render(&defaults.clone().with("fuzz", 0.0), SEED);
                    let disc = render(&defaults.with("fuzz", 1.0), SEED);
                    let floor = mean_difference(&lobe, &disc, |view| view.glossy);
                    let matte = mean_difference(&lobe, &disc, |view| view.matte);
                    // A pixel's samples spread over it: at a ball's edge some reach the floor.
                    if floor > 0.0 && matte < 0.02 * floor {
                        Ok(())
                    } else {
                        Err(format!(
                            "the disc changed the floor by {floor} on average, and the matte \
                             surfaces seen directly by {matte}"
                        ))
                    }
                },
            },
            Claim {
                says: "what happens below the surface changes the floor where the view grazes \
                       it, and hardly where the camera looks down on it",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    let dropped = render(&defaults.clone().with("below", 0.0), SEED);
                    let mirrored = render(&defaults.with("below", 2.0), SEED);
                    let floor_at = |grazing: bool| {
                        move |view: &ViewHit| {
                            view.glossy && (view.cos_to_normal < GRAZING_COS) == grazing
                        }
                    };
                    let far = mean_difference(&dropped, &mirrored, floor_at(true));
                    let near = mean_difference(&dropped, &mirrored, floor_at(false));
                    if far > 0.0 && near < 0.2 * far {
                        Ok(())
                    } else {
                        Err(format!(
                            "dropping or mirroring the directions below changed the grazed \
                             floor by {far} on average, and the floor seen from above by {near}"
                        ))
                    }
                },
            },
            Claim {
                says: "at the frosted pane, the three glass strategies agree on average; \
                       following both rays costs the most rays and is the least noisy",
                check: |demo| {
                    let frosted = Values::defaults(&demo.controls()).with("scene", 1.0);
                    strategies_agree(&frosted)
                },
            },
        ]
    }
}

/// The size of the claims' renders, and their samples per pixel.
const CLAIM_SIZE: UVec2 = UVec2::new(48, 36);
const CLAIM_SPP: u64 = 8;

/// The cosine between a camera ray and the floor's normal below which the view grazes the
/// floor (about ten degrees above it).
const GRAZING_COS: f32 = 0.17;

/// Renders the values at the claims' size with the numbers of `seed`.
fn render(values: &Values, seed: u64) -> Image {
    let picture = picture_of(values, CLAIM_SIZE.x, CLAIM_SIZE.y, seed);
    render_still(Box::new(picture), CLAIM_SIZE.x, CLAIM_SIZE.y, CLAIM_SPP)
}

/// What the camera ray through a pixel's centre sees first.
struct ViewHit {
    /// Whether it is a glossy surface.
    glossy: bool,
    /// Whether it is a matte one (its colour read from its texture).
    matte: bool,
    /// The cosine between the ray and the surface's normal.
    cos_to_normal: f32,
}

/// The mean absolute difference between `a` and `b` over all their pixels.
fn mean_abs_difference(a: &Image, b: &Image) -> f32 {
    let sum: f32 = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .map(|(a, b)| (*a - *b).abs().element_sum())
        .sum();
    sum / a.pixels.len() as f32
}

/// The mean absolute difference between `a` and `b` over the pixels whose first hit `which`
/// accepts (in the default scene at the claims' size).
fn mean_difference(a: &Image, b: &Image, which: impl Fn(&ViewHit) -> bool) -> f32 {
    let world = SCENES[0].build(DEFAULT_MAX_DEPTH, 1.0);
    let camera = world.camera_at(0.0, CLAIM_SIZE.x, CLAIM_SIZE.y);
    let (mut sum, mut count) = (0.0, 0);
    for y in 0..CLAIM_SIZE.y {
        for x in 0..CLAIM_SIZE.x {
            let ray = camera.generate_ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
            let hit: Option<SurfaceHit> = world.scene.geometry.intersect(&ray);
            let accepted = hit.is_some_and(|hit| {
                which(&ViewHit {
                    glossy: matches!(world.material_at(&hit).as_ref(), Material::Glossy(_)),
                    matte: matches!(world.material_at(&hit).as_ref(), Material::Diffuse { .. }),
                    cos_to_normal: ray.dir.dot(hit.n).abs(),
                })
            });
            if accepted {
                sum += (a.get(x, y) - b.get(x, y)).abs().element_sum();
                count += 1;
            }
        }
    }
    sum / count.max(1) as f32
}

/// Checks, on `values` (the frosted pane), that every glass strategy gives the same mean
/// picture within its noise, that following both rays casts the most rays, and that its
/// picture is the least noisy (two renders with different numbers differ the least).
fn strategies_agree(values: &Values) -> Result<(), String> {
    let mut results = Vec::new();
    for (index, strategy) in GLASS.iter().enumerate() {
        let values = values.clone().with("glass", index as f64);
        let ((first, second), rays) =
            counting_rays(|| (render(&values, SEED), render(&values, SEED + 1)));
        let mean = |image: &Image| -> f32 {
            image.pixels.iter().map(|p| p.element_sum()).sum::<f32>() / image.pixels.len() as f32
        };
        let noise = mean_abs_difference(&first, &second);
        results.push((
            strategy.name(),
            0.5 * (mean(&first) + mean(&second)),
            noise,
            rays,
        ));
    }
    let (both, mean_both, noise_both, rays_both) = results[0];
    for &(name, mean, noise, rays) in &results[1..] {
        if (mean - mean_both).abs() > 0.02 * mean_both {
            return Err(format!(
                "the picture's mean is {mean_both} with {both} and {mean} with {name}"
            ));
        }
        if rays >= rays_both {
            return Err(format!("{name} cast {rays} rays, {both} only {rays_both}"));
        }
        if noise <= noise_both {
            return Err(format!(
                "{name}'s two renders differ by {noise} on average, {both}'s by {noise_both}: \
                 following one ray should be the noisier"
            ));
        }
    }
    Ok(())
}
