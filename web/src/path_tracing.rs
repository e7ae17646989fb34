//! Chapter 08's demo: the chapter's Cornell box path-traced as its `render_with` traces it, with
//! the depth limit, next-event estimation, the MIS heuristic and where Russian roulette starts;
//! beside it Cook's branching tracer (the chapter's [`DistributionTracer`], `k = m = 2`, with
//! indirect diffuse light), given the same time.
//!
//! Both views compute the same light to the same depth, so they converge to the same image: at
//! equal time, the one with less noise is the better use of it.

use ch01_whitted::world::World;
use ch04_depth_of_field::Lens;
use ch05_motion_blur::{CameraRays, MotionScene};
use ch07_soft_shadows::AreaLights;
use ch07_soft_shadows::scenes::{Builder, camera, ceiling_panel, floor, matte};
use ch08_path_tracing::{
    DistributionOptions, DistributionTracer, LectureMaterials, Method, MisHeuristic, PathOptions,
    PathTracer, SceneLights,
};
use common::geometry::{Parallelogram, Shape, Sphere};
use common::image::Image;
use common::metrics::{mean, rmse};
use common::sampler::{IndependentSampler, Sampler};
use common::scene::Material;
use glam::{UVec2, Vec2, Vec3};

use crate::demo::{Claim, Control, Demo, Picture, Values, trace_each};
use crate::progressive::render_still;

/// The demo (`data-demo="path-tracing"`).
pub struct PathTracingDemo;

/// The seed of every picture: the same values always give the same image.
const SEED: u64 = 11;

/// The seed of the claims' reference, so that it shares no samples with the renders it judges.
const REFERENCE_SEED: u64 = 12;

/// The tree's samples per effect at every hit (`k = m`), as in the chapter's figure of the
/// tree against the path.
const BRANCHING: u32 = 2;

/// The `nee` control's options.
const NEE: &[&str] = &["on", "off"];

/// The `mis` control's options, in the order of [`MisHeuristic::ALL`].
const MIS: &[&str] = &["none", "balance", "power"];

/// The two views.
const VIEWS: &[&str] = &["path", "Cook's tree"];

/// The Cornell box of the chapter's `scenes/cornell-box.xml`: a room 2 wide and 2 high, open
/// towards the camera, with a red and a green wall, a mirror ball and a glass ball, lit by a
/// panel 0.8 wide just under the ceiling. Written out with chapter 07's builder: the scene-file
/// reader belongs to the workbench, which the browser does not get.
fn cornell_box() -> MotionScene {
    let wall =
        |corner: Vec3, e1: Vec3, e2: Vec3| Shape::Parallelogram(Parallelogram::new(corner, e1, e2));
    let white = matte(Vec3::splat(0.75));
    Builder::new()
        .shape(floor(1.0), white.clone())
        .shape(ceiling_panel(Vec3::new(0.0, 2.0, 0.0), 2.0), white.clone())
        // Each wall's `e1 × e2` faces into the room.
        .shape(
            wall(Vec3::new(-1.0, 0.0, -1.0), 2.0 * Vec3::X, 2.0 * Vec3::Y),
            white,
        )
        .shape(
            wall(Vec3::new(-1.0, 0.0, 1.0), -2.0 * Vec3::Z, 2.0 * Vec3::Y),
            matte(Vec3::new(0.65, 0.08, 0.06)),
        )
        .shape(
            wall(Vec3::new(1.0, 0.0, -1.0), 2.0 * Vec3::Z, 2.0 * Vec3::Y),
            matte(Vec3::new(0.12, 0.55, 0.1)),
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(-0.45, 0.35, -0.35), 0.35)),
            Material::mirror(),
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(0.45, 0.35, 0.2), 0.35)),
            Material::glass(1.5),
        )
        .area_light(
            ceiling_panel(Vec3::new(0.0, 1.99, 0.0), 0.8),
            Vec3::splat(6.0),
        )
        // The scene's own depth limit goes unused: both tracers take theirs from the values.
        .build(
            camera(Vec3::new(0.0, 1.0, 3.8), Vec3::new(0.0, 1.0, 0.0), 40.0),
            8,
        )
}

/// The path tracer's options of the demo's values.
fn path_options(values: &Values) -> PathOptions {
    let mis = MisHeuristic::ALL[values.index("mis").min(MisHeuristic::ALL.len() - 1)];
    PathOptions {
        nee: NEE.get(values.index("nee")) == Some(&"on"),
        mis,
        rr_depth: Some(values.index("roulette") as u32),
        ..PathOptions::with_depth(values.index("max-depth") as u32)
    }
}

/// Which of the two tracers a picture runs.
#[derive(Clone, Copy)]
enum Technique {
    Path(Method),
    Tree(DistributionOptions),
}

/// The picture: the box, its lights, chapter 05's pinhole camera rays, one of the two tracers,
/// and chapter 01's independent sampler (Mitsuba's, which the chapter's scene file names).
struct PathTracing {
    world: MotionScene,
    area_lights: AreaLights,
    technique: Technique,
    camera: CameraRays,
    sampler: IndependentSampler,
}

impl Picture for PathTracing {
    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
        let (world, camera) = (&self.world, &self.camera);
        match self.technique {
            Technique::Path(method) => {
                let tracer = PathTracer {
                    world,
                    lights: SceneLights::of(world, &self.area_lights, method.light_sampling),
                    options: method.options,
                    materials: LectureMaterials { fuzz: method.fuzz },
                };
                trace_each(&self.sampler, pixels, index, add, |p_film, sampler| {
                    tracer.radiance(&camera.generate(world, p_film, sampler), sampler)
                });
            }
            Technique::Tree(options) => {
                let tracer = DistributionTracer::new(world, &self.area_lights, options);
                trace_each(&self.sampler, pixels, index, add, |p_film, sampler| {
                    tracer.radiance(&camera.generate(world, p_film, sampler), sampler)
                });
            }
        }
    }
}

/// View `view` of `values` at `width x height` (0 the path, 1 the tree), its numbers drawn from
/// `seed`.
fn picture(values: &Values, view: usize, seed: u64, width: u32, height: u32) -> PathTracing {
    let world = cornell_box();
    let options = path_options(values);
    let technique = match view {
        0 => Technique::Path(Method::new(options)),
        _ => Technique::Tree(DistributionOptions::branching(
            BRANCHING,
            options.max_depth,
            true,
        )),
    };
    PathTracing {
        area_lights: AreaLights::of(&world.scene),
        technique,
        camera: CameraRays::new(&world, &Lens::PINHOLE, width, height),
        sampler: IndependentSampler::new(seed),
        world,
    }
}

impl Demo for PathTracingDemo {
    fn name(&self) -> &'static str {
        "path-tracing"
    }

    /// The MIS heuristic comes before NEE, which it needs: the site's check moves the controls
    /// in this order, and would find the heuristic hidden once NEE is off. The depth starts at
    /// 3, one below the chapter's figure: the tree's rays double with every level, and its
    /// first pass must stay quick.
    fn controls(&self) -> Vec<Control> {
        vec![
            Control::range("max-depth", "max depth", 1.0, 6.0, 1.0, 3.0),
            Control::range(
                "roulette",
                "Russian roulette from segment",
                1.0,
                6.0,
                1.0,
                3.0,
            ),
            Control::choice("mis", "MIS heuristic", MIS, 2).when("nee", 0.0),
            Control::choice("nee", "next-event estimation", NEE, 0),
        ]
    }

    fn views(&self) -> &'static [&'static str] {
        VIEWS
    }

    fn picture(
        &self,
        values: &Values,
        view: usize,
        width: u32,
        height: u32,
    ) -> Result<Box<dyn Picture>, String> {
        Ok(Box::new(picture(values, view, SEED, width, height)))
    }

    fn claims(&self) -> Vec<Claim> {
        vec![
            Claim {
                says: "with max depth 1 the camera sees only the light",
                check: only_the_light_at_depth_1,
            },
            Claim {
                says: "next-event estimation lowers the error at equal samples per pixel",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    let reference = still_from(&defaults, 0, REFERENCE_SEED, 128);
                    let on = rmse(&still(&defaults, 0, 4), &reference);
                    let off = rmse(&still(&defaults.clone().with("nee", 1.0), 0, 4), &reference);
                    if on < off {
                        Ok(())
                    } else {
                        Err(format!(
                            "the error against the reference is {on:.4} with NEE and {off:.4} \
                             without"
                        ))
                    }
                },
            },
            Claim {
                says: "the MIS heuristic and where roulette starts change the noise, not the \
                       image on average",
                check: |demo| {
                    let defaults = Values::defaults(&demo.controls());
                    let average = |values: &Values| mean(&still(values, 0, 32));
                    let expected = average(&defaults);
                    for (name, value) in [
                        ("mis", 0.0),
                        ("mis", 1.0),
                        ("roulette", 1.0),
                        ("roulette", 6.0),
                    ] {
                        let got = average(&defaults.clone().with(name, value));
                        let gap = (got - expected).abs().max_element() / expected.max_element();
                        if gap > 0.03 {
                            return Err(format!(
                                "the image's mean is {got:.4} with {name} = {value}, and \
                                 {expected:.4} with the defaults"
                            ));
                        }
                    }
                    Ok(())
                },
            },
            Claim {
                says: "the path and Cook's tree converge to the same image",
                check: |demo| {
                    let values = Values::defaults(&demo.controls()).with("max-depth", 3.0);
                    let path = mean(&still(&values, 0, 64));
                    let tree = mean(&still(&values, 1, 16));
                    let gap = (path - tree).abs().max_element() / path.max_element();
                    if gap < 0.03 {
                        Ok(())
                    } else {
                        Err(format!(
                            "the image's mean is {path:.4} by the path and {tree:.4} by the tree"
                        ))
                    }
                },
            },
        ]
    }
}

/// The size of the claims' renders.
const CLAIM_SIZE: UVec2 = UVec2::new(32, 32);

/// View `view` of `values` at the claims' size and `spp` samples per pixel.
fn still(values: &Values, view: usize, spp: u64) -> Image {
    still_from(values, view, SEED, spp)
}

/// View `view` of `values` at the claims' size, `spp` samples per pixel drawn from `seed`.
fn still_from(values: &Values, view: usize, seed: u64, spp: u64) -> Image {
    let picture = picture(values, view, seed, CLAIM_SIZE.x, CLAIM_SIZE.y);
    render_still(Box::new(picture), CLAIM_SIZE.x, CLAIM_SIZE.y, spp)
}

/// At max depth 1 a pixel is lit exactly when one of its camera rays hits the light: the
/// camera rays are drawn again, number for number, as the picture drew them. And at max depth
/// 2 most of the pixels the light left black are lit (the claim says something).
fn only_the_light_at_depth_1(demo: &dyn Demo) -> Result<(), String> {
    let spp = 4;
    let values = Values::defaults(&demo.controls()).with("max-depth", 1.0);
    let image = still(&values, 0, spp);
    let direct = still(&values.clone().with("max-depth", 2.0), 0, spp);
    let picture = picture(&values, 0, SEED, CLAIM_SIZE.x, CLAIM_SIZE.y);
    let mut sampler = picture.sampler.clone();
    let (mut seen, mut newly_lit, mut black) = (0, 0, 0);
    for y in 0..CLAIM_SIZE.y {
        for x in 0..CLAIM_SIZE.x {
            let pixel = UVec2::new(x, y);
            let mut rays_on_light = 0;
            for index in 0..spp {
                sampler.start_pixel_sample(pixel, index);
                let p_film = pixel.as_vec2() + sampler.get_pixel_2d();
                let ray = picture
                    .camera
                    .generate(&picture.world, p_film, &mut sampler);
                let on_light = picture.world.intersect(&ray).is_some_and(|hit| {
                    picture.area_lights.light_of_shape[hit.shape as usize].is_some()
                });
                rays_on_light += u32::from(on_light);
            }
            let lit = image.get(x, y).max_element() > 0.0;
            if lit != (rays_on_light > 0) {
                return Err(format!(
                    "pixel ({x}, {y}) is {} at max depth 1, and {rays_on_light} of its {spp} \
                     camera rays hit the light",
                    if lit { "lit" } else { "black" }
                ));
            }
            seen += usize::from(lit);
            if !lit {
                black += 1;
                newly_lit += usize::from(direct.get(x, y).max_element() > 0.0);
            }
        }
    }
    if seen == 0 {
        return Err("the camera sees no light at max depth 1".to_string());
    }
    if 2 * newly_lit <= black {
        return Err(format!(
            "of the {black} pixels black at max depth 1, only {newly_lit} are lit at max depth 2"
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_mis_options_are_the_chapters_heuristics_in_order() {
        let names: Vec<&str> = MisHeuristic::ALL.iter().map(|m| m.name()).collect();
        assert_eq!(MIS, names);
    }

    #[test]
    fn the_options_reach_the_path_tracer() {
        let values = Values::defaults(&PathTracingDemo.controls())
            .with("max-depth", 5.0)
            .with("roulette", 2.0)
            .with("mis", 1.0);
        let options = path_options(&values);
        assert_eq!(
            (
                options.max_depth,
                options.rr_depth,
                options.mis,
                options.nee
            ),
            (5, Some(2), MisHeuristic::Balance, true)
        );
        assert!(!path_options(&values.with("nee", 1.0)).nee);
    }
}
