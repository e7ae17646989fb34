//! Chapter 11's demo: the door-gap room path-traced by chapter 08's path, unguided or guided
//! by what the chapter's training learns (towards the light arriving, or towards the pixel's
//! variance); and, as a second thing to show, the guide the training has learnt so far at the
//! point the image's centre sees, the unit square of directions drawn as an image.
//!
//! The training runs in the page's own passes. The chapter's budget rule (`trains_next`)
//! splits the samples per pixel into iterations of 1, 2, 4 ... and a final pass; pass `i` of
//! the page is sample `i` of every pixel, so it belongs to one of them. The paths of a
//! training iteration record what they saw, and the records go into the guides being built
//! after every slice; when the last pixel of an iteration's last pass is done, the guides are
//! rebuilt from what they learnt, as the chapter's training rebuilds them, and the next
//! iteration samples from them. Each iteration's image is its own (the chapter keeps only the
//! final pass's), so the picture shows the mean of the current iteration's samples and
//! starts afresh with each one: the page's film averages the values it is given, so at a
//! pixel's `n`-th sample of an iteration it gets `n E_n − (n − 1) E_(n−1)`, `E_n` the mean
//! of those `n`.

use std::cell::RefCell;

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{CameraRays, MotionScene};
use ch06_fuzzy_reflections::FuzzMethod;
use ch07_soft_shadows::scenes::{Builder, camera, matte};
use ch07_soft_shadows::{AreaLights, LightSampling};
use ch08_path_tracing::{PathOptions, PathTracer, SceneLights};
use ch09_materials::SceneMaterials;
use ch11_path_guiding::path::{GuideRecord, Learning};
use ch11_path_guiding::selection::{LearntFraction, loss_of};
use ch11_path_guiding::spatial::SpatialTree;
use ch11_path_guiding::target::pixel_estimates;
use ch11_path_guiding::training::{learn, trains_next};
use ch11_path_guiding::{GuidedPathTracer, GuidingOptions, GuidingTarget};
use common::geometry::{Parallelogram, Shape};
use common::image::Image;
use common::render::{Budget, trace_pixel_sample};
use common::sampler::IndependentSampler;
use glam::{UVec2, Vec2, Vec3};

use crate::demo::{Claim, Control, Demo, Picture, Values};
use crate::progressive::render_demo;

/// The demo (`data-demo="path-guiding"`).
pub struct PathGuidingDemo;

/// The `guiding` control's options: off, then the chapter's two targets.
const GUIDING: &[&str] = &[
    "off",
    "towards the light (radiance)",
    "towards the variance",
];

/// The `show` control's options.
const SHOW: &[&str] = &["the image", "the guide at the centre"];

/// The seed of every picture.
const SEED: u64 = 11;

/// The samples per pixel the page refines to: the chapter's rule trains 1, 2, 4, 8 and 16 of
/// them (31) and leaves 33 to the final pass.
const TARGET_SPP: u64 = 64;

/// The room is dark (its pixels' mean is about 0.003): the image is shown this many times
/// brighter, five stops.
const EXPOSURE: f32 = 32.0;

/// The chapter's `scenes/door-gap.xml`, written out with chapter 07's builder (the scene-file
/// reader belongs to the workbench): two rooms and a door ajar between them, the lamp in the
/// far room facing away from the gap, the camera in the near room, dark, looking at the corner
/// the gap lights.
fn door_gap() -> MotionScene {
    // Mitsuba's cube scaled by `half` and moved to `centre`.
    let slab = |builder: Builder, centre: Vec3, half: Vec3, albedo: Vec3| {
        builder.block(centre - half, centre + half, matte(albedo))
    };
    let near = Vec3::splat(0.2);
    let far = Vec3::splat(0.3);
    let mut builder = Builder::new();
    for (centre, half, albedo) in [
        // The camera's room: x from -2 to 2, 2.5 high, z from -2 to 2.
        (
            Vec3::new(0.0, -0.05, 0.0),
            Vec3::new(2.0, 0.05, 2.0),
            Vec3::new(0.35, 0.28, 0.2),
        ),
        (Vec3::new(0.0, 2.55, 0.0), Vec3::new(2.0, 0.05, 2.0), near),
        (Vec3::new(-2.05, 1.25, 0.0), Vec3::new(0.05, 1.3, 2.0), near),
        (Vec3::new(0.0, 1.25, -2.05), Vec3::new(2.0, 1.3, 0.05), near),
        (Vec3::new(0.0, 1.25, 2.05), Vec3::new(2.0, 1.3, 0.05), near),
        // The wall between the rooms, with a gap 0.2 wide and 2 high.
        (
            Vec3::new(2.05, 1.25, -1.05),
            Vec3::new(0.05, 1.3, 0.95),
            near,
        ),
        (
            Vec3::new(2.05, 1.25, 1.05),
            Vec3::new(0.05, 1.3, 0.95),
            near,
        ),
        (Vec3::new(2.05, 2.25, 0.0), Vec3::new(0.05, 0.3, 0.1), near),
        // The far room: x from 2.1 to 4.
        (Vec3::new(3.05, -0.05, 0.0), Vec3::new(0.95, 0.05, 2.0), far),
        (Vec3::new(3.05, 2.55, 0.0), Vec3::new(0.95, 0.05, 2.0), far),
        (Vec3::new(4.05, 1.25, 0.0), Vec3::new(0.05, 1.3, 2.0), far),
        (
            Vec3::new(3.05, 1.25, -2.05),
            Vec3::new(0.95, 1.3, 0.05),
            far,
        ),
        (Vec3::new(3.05, 1.25, 2.05), Vec3::new(0.95, 1.3, 0.05), far),
    ] {
        builder = slab(builder, centre, half, albedo);
    }
    // The lamp, a square of side 1 on the far room's side of the wall, facing the far room's
    // end wall (`e1 × e2 = y × z = x`).
    let lamp = Shape::Parallelogram(Parallelogram::new(
        Vec3::new(2.11, 0.8, -1.8),
        Vec3::Y,
        Vec3::Z,
    ));
    builder
        .area_light(lamp, Vec3::splat(200.0))
        .shape(
            Shape::Sphere(common::geometry::Sphere::new(
                Vec3::new(0.0, 0.5, -0.8),
                0.5,
            )),
            matte(near),
        )
        .build(
            camera(Vec3::new(1.7, 1.3, 1.7), Vec3::new(-1.2, 0.7, -1.0), 70.0),
            8,
        )
}

/// The path's options: the scene file's depth, chapter 08's defaults otherwise.
fn path_options() -> PathOptions {
    PathOptions::with_depth(8)
}

/// The training iterations' sizes for a render of `spp` samples per pixel, by the chapter's
/// rule; the final pass gets the rest.
fn iterations(spp: u64) -> Vec<u64> {
    let (mut sizes, mut spent, mut next) = (Vec::new(), 0, 1);
    while trains_next(Budget::Samples(spp), spent, next, 0.0, 0.0) {
        sizes.push(next);
        spent += next;
        next *= 2;
    }
    sizes
}

/// The phase pass `index` belongs to: its training iteration (`None` for the final pass), its
/// first pass and its last.
fn phase_of(sizes: &[u64], index: u64) -> (Option<usize>, u64, u64) {
    let mut first = 0;
    for (k, &size) in sizes.iter().enumerate() {
        if index < first + size {
            return (Some(k), first, first + size - 1);
        }
        first += size;
    }
    (None, first, u64::MAX)
}

/// What a pixel has gathered in the current phase.
#[derive(Clone, Copy, Default)]
struct PixelMean {
    sum: Vec3,
    samples: u64,
    /// The value the film's average holds for the pixel.
    shown: Vec3,
}

/// What the training has learnt so far, and the estimates of the pixels from the iteration
/// before (for the variance-aware target).
struct Learnt {
    guides: SpatialTree,
    estimates: Option<Vec<f32>>,
    pixels: Vec<PixelMean>,
    /// The records of the current slice.
    records: Vec<GuideRecord>,
    /// The guides' BSDF fractions being learnt in the current iteration; the paths read the
    /// guides' own, fixed for the iteration, as in the chapter's training.
    fractions: Option<Vec<LearntFraction>>,
}

/// The picture: the room, its lights and materials, the camera rays, how it is guided and
/// what it shows, and what it has learnt.
struct PathGuiding {
    world: MotionScene,
    area_lights: AreaLights,
    materials: SceneMaterials,
    camera_rays: CameraRays,
    guiding: Option<GuidingOptions>,
    show_guide: bool,
    sampler: IndependentSampler,
    size: UVec2,
    iterations: Vec<u64>,
    /// The point the centre of the image sees, whose guide the second display shows.
    centre: Option<Vec3>,
    learnt: RefCell<Learnt>,
}

impl PathGuiding {
    /// The guide's density at the unit square's point under `pixel` (the pixel's column the
    /// height `cos θ` along `z`, its row the turn around `z`), over 4 so that a flat guide is
    /// a quarter grey; 0 before anything was learnt.
    fn guide_density(&self, guides: &SpatialTree, pixel: UVec2) -> Vec3 {
        let Some(p) = self.centre else {
            return Vec3::ZERO;
        };
        let guide = &guides.guides[guides.guide_of(p) as usize];
        let point = (pixel.as_vec2() + 0.5) / self.size.as_vec2();
        Vec3::splat(0.25 * guide.sampling.pdf(point))
    }
}

impl Picture for PathGuiding {
    /// Sample `index` of each pixel, guided by what the iterations before learnt and, while
    /// training, recording; the film gets what moves its average to what the pixel shows
    /// (see the module's opening). The page traces every pixel's sample `i` before any
    /// pixel's sample `i + 1`.
    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
        let tracer = PathTracer {
            world: &self.world,
            lights: SceneLights::of(&self.world, &self.area_lights, LightSampling::solid_angle()),
            options: path_options(),
            materials: self.materials.clone(),
        };
        let (iteration, first_pass, last_pass) = phase_of(&self.iterations, index);
        let training = self.guiding.filter(|_| iteration.is_some());
        let mut learnt = self.learnt.borrow_mut();
        let Learnt {
            guides,
            estimates,
            pixels: means,
            records,
            fractions,
        } = &mut *learnt;
        let guided = GuidedPathTracer {
            tracer: &tracer,
            guides,
            bsdf_fraction: self.guiding.and_then(|g| g.bsdf_fraction),
        };
        let mut sampler = self.sampler.clone();
        let (mut last_done, pixel_count) = (false, means.len());
        for &pixel in pixels {
            let at = (pixel.y * self.size.x + pixel.x) as usize;
            let Some(mean) = means.get_mut(at) else {
                continue;
            };
            last_done |= at + 1 == pixel_count;
            if index == first_pass {
                *mean = PixelMean::default();
            }
            let pending = RefCell::new(std::mem::take(records));
            let (p_film, radiance) =
                trace_pixel_sample(&mut sampler, pixel, index, &|p_film, sampler| {
                    let ray = self.camera_rays.generate(&self.world, p_film, sampler);
                    match (self.guiding, training) {
                        (None, _) => tracer.radiance(&ray, sampler),
                        (Some(_), None) => guided.radiance(&ray, sampler, None),
                        (Some(_), Some(options)) => {
                            let mut pending = pending.borrow_mut();
                            let learning = Learning {
                                target: options.target,
                                pixel_estimate: estimates.as_ref().map_or(1.0, |e| e[at]),
                                records: &mut pending,
                            };
                            guided.radiance(&ray, sampler, Some(learning))
                        }
                    }
                });
            *records = pending.into_inner();
            if radiance.is_finite() {
                mean.sum += radiance;
                mean.samples += 1;
            }
            let now = if self.show_guide {
                self.guide_density(guides, pixel)
            } else {
                EXPOSURE * mean.sum / mean.samples.max(1) as f32
            };
            let n = (index - first_pass + 1) as f32;
            add(p_film, n * now - (n - 1.0) * mean.shown);
            mean.shown = now;
        }
        // The slice's records go to the guides being built.
        for record in records.drain(..) {
            let guide = &mut guides.guides[record.guide as usize];
            guide.building.record(record.point, record.value);
            guide.records += 1;
            if let (Some(sample), Some(options)) = (&record.fraction, training) {
                let fractions = fractions
                    .get_or_insert_with(|| guides.guides.iter().map(|g| g.fraction).collect());
                fractions[record.guide as usize].learn(sample, loss_of(options.target));
            }
        }
        if let (Some(options), Some(k), true) =
            (training, iteration, last_done && index == last_pass)
        {
            let mut image = Image::new(self.size.x, self.size.y);
            for (pixel, m) in image.pixels.iter_mut().zip(means.iter()) {
                *pixel = m.sum / m.samples.max(1) as f32;
            }
            *estimates = Some(pixel_estimates(&image));
            if let Some(fractions) = fractions.take() {
                for (guide, fraction) in guides.guides.iter_mut().zip(fractions) {
                    guide.fraction = fraction;
                }
            }
            learn(guides, options, self.iterations[k]);
        }
    }
}

/// The picture of `values` at `width x height`, its numbers drawn from `seed`.
fn picture(values: &Values, seed: u64, width: u32, height: u32) -> PathGuiding {
    picture_with(values, seed, width, height, None)
}

/// [`picture`] with the guides' BSDF fraction pinned to `bsdf_fraction` (`None`: learnt).
fn picture_with(
    values: &Values,
    seed: u64,
    width: u32,
    height: u32,
    bsdf_fraction: Option<f32>,
) -> PathGuiding {
    let world = door_gap();
    let target = match values.index("guiding") {
        0 => None,
        1 => Some(GuidingTarget::Radiance),
        _ => Some(GuidingTarget::Variance),
    };
    let pixels = u64::from(width) * u64::from(height);
    let guiding = target.map(|target| GuidingOptions {
        bsdf_fraction,
        ..GuidingOptions::for_image(target, pixels)
    });
    let camera_rays = CameraRays::new(&world, &Lens::PINHOLE, width, height);
    let centre = {
        let mut sampler = IndependentSampler::new(0);
        let middle = Vec2::new(width as f32, height as f32) * 0.5;
        let ray = camera_rays.generate(&world, middle, &mut sampler);
        world.scene.geometry.intersect(&ray).map(|hit| hit.p)
    };
    PathGuiding {
        area_lights: AreaLights::of(&world.scene),
        materials: SceneMaterials::of(&world.scene, FuzzMethod::Lobe),
        camera_rays,
        guiding,
        show_guide: values.index("show") == 1,
        sampler: IndependentSampler::new(seed),
        size: UVec2::new(width.max(1), height.max(1)),
        iterations: if guiding.is_some() {
            iterations(TARGET_SPP)
        } else {
            Vec::new()
        },
        centre,
        learnt: RefCell::new(Learnt {
            guides: SpatialTree::new(world.scene.geometry.bounds()),
            estimates: None,
            pixels: vec![PixelMean::default(); pixels as usize],
            records: Vec::new(),
            fractions: None,
        }),
        world,
    }
}

impl Demo for PathGuidingDemo {
    fn name(&self) -> &'static str {
        "path-guiding"
    }

    fn controls(&self) -> Vec<Control> {
        vec![
            Control::choice("guiding", "guiding", GUIDING, 1),
            Control::choice("show", "show", SHOW, 0),
        ]
    }

    fn target_spp(&self, _values: &Values) -> u64 {
        TARGET_SPP
    }

    /// The chapter's film is 96 x 72.
    fn size(&self) -> (u32, u32) {
        (96, 72)
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
        vec![Claim {
            says: "unguided, nothing is learnt and the guide is black; guided, the guide at \
                   the centre learns where the light comes from: a tenth of the directions \
                   hold at least two fifths of it, four times their share",
            check: |demo| {
                let shown = Values::defaults(&demo.controls()).with("show", 1.0);
                let off = render(demo, &shown.clone().with("guiding", 0.0))?;
                if off.pixels.iter().any(|p| *p != Vec3::ZERO) {
                    return Err("the guide is not black with guiding off".to_string());
                }
                for (guiding, name) in [(1.0, "radiance"), (2.0, "variance")] {
                    let image = render(demo, &shown.clone().with("guiding", guiding))?;
                    let mut densities: Vec<f32> = image.pixels.iter().map(|p| p.x).collect();
                    densities.sort_by(|a, b| b.total_cmp(a));
                    let total: f32 = densities.iter().sum();
                    let top: f32 = densities[..densities.len() / 10].iter().sum();
                    if total.is_nan() || total <= 0.0 || top < 0.4 * total {
                        return Err(format!(
                            "guided towards {name}, the densest tenth of the directions holds \
                             {:.0} % of the guide",
                            100.0 * top / total.max(f32::MIN_POSITIVE)
                        ));
                    }
                }
                Ok(())
            },
        }]
    }
}

/// The size of the claims' renders.
const CLAIM_SIZE: UVec2 = UVec2::new(32, 24);

/// The demo's picture of `values`, rendered small to its target.
fn render(demo: &dyn Demo, values: &Values) -> Result<Image, String> {
    render_demo(demo, values, CLAIM_SIZE, TARGET_SPP)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ch11_path_guiding::render_guided;
    use common::film::PixelBoxFilter;
    use common::render::RenderSettings;

    #[test]
    fn the_budget_is_split_by_the_chapters_rule() {
        assert_eq!(iterations(TARGET_SPP), [1, 2, 4, 8, 16]);
        assert_eq!(phase_of(&[1, 2, 4], 0), (Some(0), 0, 0));
        assert_eq!(phase_of(&[1, 2, 4], 2), (Some(1), 1, 2));
        assert_eq!(phase_of(&[1, 2, 4], 7), (None, 7, u64::MAX));
    }

    /// Unguided, the demo is chapter 08's render pixel for pixel (to the rounding of its
    /// exposure). Guided, it learns the chapter's guides: the same spatial leaves and
    /// quadtrees, their sums equal up to the order in which the records were added (the
    /// chapter's training adds a pixel's samples together, the page a pass of every pixel at
    /// a time). Its final pass is then not the chapter's pixel for pixel: a rounding in a sum
    /// moves a guided direction a little, and a path that moves may find other light.
    #[test]
    fn the_demo_learns_and_renders_as_the_chapter_does() {
        let (width, height) = (16, 12);
        let all: Vec<UVec2> = (0..height)
            .flat_map(|y| (0..width).map(move |x| UVec2::new(x, y)))
            .collect();
        for (index, target) in [
            None,
            Some(GuidingTarget::Radiance),
            Some(GuidingTarget::Variance),
        ]
        .into_iter()
        .enumerate()
        {
            let values =
                Values::defaults(&PathGuidingDemo.controls()).with("guiding", index as f64);
            // The fraction pinned: learnt, it moves with every record in the order records
            // arrive, which is the page's slices here and the chapter's tiles there.
            let ours = picture_with(&values, SEED, width, height, Some(0.5));
            let mut film = common::film::Film::new(width, height);
            for pass in 0..TARGET_SPP {
                let mut tile = film.tile(
                    common::film::PixelRect {
                        min: UVec2::ZERO,
                        max: UVec2::new(width, height),
                    },
                    &PixelBoxFilter,
                );
                ours.trace(&all, pass, &mut |p_film, l| {
                    tile.add_sample(p_film, l, &PixelBoxFilter)
                });
                film.merge(&tile);
            }
            // The film holds the image as the page shows it, brighter.
            let mut image = film.image();
            for pixel in &mut image.pixels {
                *pixel /= EXPOSURE;
            }
            let world = door_gap();
            let theirs = render_guided(
                &world,
                SceneMaterials::of(&world.scene, FuzzMethod::Lobe),
                path_options(),
                target.map(|t| GuidingOptions {
                    bsdf_fraction: Some(0.5),
                    ..GuidingOptions::for_image(t, u64::from(width * height))
                }),
                &Lens::PINHOLE,
                &RenderSettings::new(width, height, TARGET_SPP),
                &IndependentSampler::new(SEED),
                &PixelBoxFilter,
            );
            let Some(trained) = theirs.training else {
                for (a, b) in image.pixels.iter().zip(&theirs.output.image.pixels) {
                    assert!((*a - *b).abs().max_element() <= 1e-5 * (1.0 + b.max_element()));
                }
                continue;
            };
            let learnt = &ours.learnt.borrow().guides;
            assert_eq!(
                learnt.nodes, trained.guides.nodes,
                "{index}: the spatial tree"
            );
            for (a, b) in learnt.guides.iter().zip(&trained.guides.guides) {
                assert_eq!(a.sampling.nodes.len(), b.sampling.nodes.len());
                let (a, b) = (a.sampling.total(), b.sampling.total());
                assert!(
                    (a - b).abs() <= 1e-4 * b.abs(),
                    "{index}: a guide's total {a} / {b}"
                );
            }
        }
    }
}
