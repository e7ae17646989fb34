//! Furnace tests: closed glass and mirror objects under a uniform white sky, with no lights,
//! must look exactly as bright as the sky, never brighter. Energy is never created, and none is
//! lost but to the recursion limit.
//!
//! Chapters 01 to 04 have no rough surfaces: Whitted's matte surfaces see only point lights,
//! so the objects that can be put in a furnace are the smooth mirror and glass ones. Grazing
//! views are included (a glass slab and a mirror floor seen at half a degree), where the
//! Fresnel reflectance approaches 1.
//!
//! Chapter 08's path tracer sees the same objects under the same sky. Chapters 07 and 08 are
//! also put in a box whose walls are area lights of the sky's radiance: a white matte ball,
//! a mirror and glass inside must look as bright as the walls, and glossy and frosted balls
//! no brighter, whether the walls are found by light samples, by BSDF samples, or both
//! weighted by multiple importance sampling. Their estimates are noisy; the tolerance is
//! measured from the spread of the pixels (see [`assert_as_bright_as_the_sky`]).

use ch01_whitted::{PixelPattern, render};
use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::lens::Lens;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::TraceOptions;
use ch07_soft_shadows::LightOptions;
use ch07_soft_shadows::scenes::{Builder, matte};
use ch08_path_tracing::{Method, MisHeuristic, PathOptions};
use common::geometry::{Parallelogram, Shape, Sphere, TriangleMesh};
use common::render::{RenderOutput, RenderSettings};
use common::scene::{Camera, CameraFrame, FilmSettings, Material, Scene, SceneBuilder};
use glam::Vec3;
use workbook_tests::octahedron;

const SKY: f32 = 1.0;
/// Float rounding allowed above the sky: sums of a few dozen products in `f32`.
const ROUNDING: f32 = 1e-5;
const SIZE: u32 = 24;

/// A pinhole at `origin` looking at `target`, and the square film of the tests.
fn camera(origin: Vec3, target: Vec3, fov: f32) -> (Camera, FilmSettings) {
    let frame = CameraFrame::look_at(origin, target, Vec3::Y).unwrap();
    (Camera::pinhole(frame, fov), FilmSettings::new(SIZE, SIZE))
}

/// One object at a time, so that the rays leaving it see only the sky: Whitted's tracer
/// follows both the reflected and the refracted ray at every glass surface, and between
/// several objects that tree grows exponentially with the recursion limit.
#[derive(Clone, Copy, Debug)]
enum Object {
    /// A glass sphere of this index: 1 is invisible, 1.5 window glass, 2.4 diamond, 4 beyond.
    GlassSphere(f32),
    /// A perfect mirror sphere.
    MirrorSphere,
    /// A glass octahedron: flat faces, where total internal reflection traps light for many
    /// bounces.
    GlassOctahedron,
}

const OBJECTS: [Object; 7] = [
    Object::GlassSphere(1.0),
    Object::GlassSphere(1.33),
    Object::GlassSphere(1.5),
    Object::GlassSphere(2.4),
    Object::GlassSphere(4.0),
    Object::MirrorSphere,
    Object::GlassOctahedron,
];

/// `object` alone under the sky, filling most of the view.
fn in_the_furnace(object: Object, max_depth: u32) -> Scene {
    let builder = SceneBuilder::new().environment(Vec3::splat(SKY));
    let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0));
    let builder = match object {
        Object::GlassSphere(ior) => builder.shape(sphere, Material::glass(ior)),
        Object::MirrorSphere => builder.shape(sphere, Material::mirror()),
        Object::GlassOctahedron => {
            // Faceted: without vertex normals, its faces bend light about their own normals.
            // Glass that bends it about interpolated normals (chapter 08, as Mitsuba) is not
            // energy-conserving, a known cost of shading normals, and no furnace for it.
            let faceted = TriangleMesh {
                normals: None,
                ..octahedron(Vec3::ZERO, 1.2)
            };
            builder.mesh(&faceted, Material::glass(1.5))
        }
    };
    let (camera, film) = camera(Vec3::new(0.3, 0.5, 4.0), Vec3::ZERO, 40.0);
    builder.build(camera, film, max_depth)
}

/// A glass slab (two parallel parallelograms, facing out) and, beside it, a mirror floor, both seen
/// from half a degree above their planes.
fn grazing_views(max_depth: u32) -> Scene {
    let slab_top = Parallelogram::new(
        Vec3::new(-50.0, 0.0, 50.0),
        50.0 * Vec3::X,
        -100.0 * Vec3::Z,
    );
    let slab_bottom = Parallelogram::new(
        Vec3::new(-50.0, -0.3, -50.0),
        50.0 * Vec3::X,
        100.0 * Vec3::Z,
    );
    let mirror = Parallelogram::new(Vec3::new(0.0, 0.0, 50.0), 50.0 * Vec3::X, -100.0 * Vec3::Z);
    let grazing = 0.5f32.to_radians();
    let origin = Vec3::new(0.0, 0.2, 10.0);
    let target = origin + Vec3::new(0.0, -grazing.tan(), -1.0);
    let (camera, film) = camera(origin, target, 20.0);
    SceneBuilder::new()
        .environment(Vec3::splat(SKY))
        .shape(Shape::Parallelogram(slab_top), Material::glass(1.5))
        .shape(Shape::Parallelogram(slab_bottom), Material::glass(1.5))
        .shape(Shape::Parallelogram(mirror), Material::mirror())
        .build(camera, film, max_depth)
}

/// Checks that no pixel is brighter than the sky, and returns the darkest one.
fn darkest_pixel(what: &str, out: &RenderOutput) -> f32 {
    assert_eq!(out.stats.nonfinite_samples, 0, "{what}");
    let pixels = &out.image.pixels;
    let brightest = pixels.iter().map(|p| p.max_element()).fold(0.0, f32::max);
    assert!(
        brightest <= SKY + ROUNDING,
        "{what}: a pixel of {brightest} under a sky of {SKY}: energy was created"
    );
    pixels
        .iter()
        .map(|p| p.min_element())
        .fold(f32::INFINITY, f32::min)
}

fn settings(spp: u64) -> RenderSettings {
    RenderSettings::new(SIZE, SIZE, spp)
}

#[test]
fn closed_glass_and_mirrors_look_like_the_sky() {
    for object in OBJECTS {
        let scene = in_the_furnace(object, 64);
        let out = render(&scene, &settings(4), PixelPattern::Grid, 0).unwrap();
        let darkest = darkest_pixel(&format!("ch01 {object:?}"), &out);
        // What is missing is light still trapped inside after 64 segments.
        assert!(
            darkest > 0.99,
            "ch01 {object:?}: a pixel of {darkest} is too dark"
        );
    }
}

#[test]
fn the_recursion_limit_only_ever_removes_light() {
    // Fewer segments lose more of the light inside the glass, and never add any.
    for object in [Object::GlassSphere(4.0), Object::GlassOctahedron] {
        let mut previous = Vec::<Vec3>::new();
        for max_depth in [1, 2, 3, 5, 8, 16, 32] {
            let scene = in_the_furnace(object, max_depth);
            let out = render(&scene, &settings(1), PixelPattern::Centre, 0).unwrap();
            let what = format!("{object:?} max_depth {max_depth}");
            darkest_pixel(&what, &out);
            for (now, before) in out.image.pixels.iter().zip(&previous) {
                assert!(
                    now.cmpge(*before - ROUNDING).all(),
                    "{what}: {now} is darker than {before} with fewer segments"
                );
            }
            previous = out.image.pixels;
        }
    }
}

#[test]
fn grazing_views_of_glass_and_mirrors_create_no_energy() {
    let out = render(&grazing_views(64), &settings(4), PixelPattern::Grid, 0).unwrap();
    let darkest = darkest_pixel("ch01 grazing", &out);
    // The slab is open at its far sides: light refracted into it and leaving through a side
    // sees the sky without the n^2 gain of a glass-to-air exit, so it may look darker; the
    // mirror and the glass it shows are exact.
    assert!(darkest > 0.2, "ch01 grazing: a pixel of {darkest}");
}

#[test]
fn filters_and_lenses_create_no_energy_either() {
    let scene = in_the_furnace(Object::GlassSphere(2.4), 64);
    // Filters without negative lobes average samples with positive weights: never above the
    // brightest sample. (Mitchell's negative lobes may ring above it, by design.)
    for kind in [FilterKind::Box, FilterKind::Tent, FilterKind::Gaussian] {
        let filter = ReconstructionFilter::new(kind, None).unwrap();
        let sampler = PixelSampler::new(PixelSamplerKind::Halton, 4, 0).unwrap();
        let out = ch03_anti_aliasing::render_with(&scene, &settings(4), &sampler, &filter);
        darkest_pixel(&format!("ch03 {}", kind.name()), &out);
    }
    let filter = ReconstructionFilter::new(FilterKind::Gaussian, None).unwrap();
    let sampler = PixelSampler::new(PixelSamplerKind::Random, 8, 0).unwrap();
    for lens in [Lens::new(0.3, 4.0).unwrap(), Lens::new(3.0, 2.0).unwrap()] {
        let out = ch04_depth_of_field::render_with(&scene, &lens, &settings(8), &sampler, &filter);
        let darkest = darkest_pixel(&format!("ch04 {lens:?}"), &out);
        assert!(darkest > 0.99, "ch04 {lens:?}: a pixel of {darkest}");
    }
}

/// Half the side of the glowing box of [`in_a_glowing_box`].
const BOX: f32 = 3.0;

/// `object` alone inside a closed box whose six black walls glow with radiance [`SKY`] inwards:
/// chapter 07's area lights as the furnace. Everything inside then receives the same radiance
/// from every direction, through area-light sampling (a light sample) as much as through
/// rays that hit a wall (a BSDF sample), so an object that absorbs nothing looks exactly as
/// bright as the walls.
fn in_a_glowing_box(object: Shape, material: Material, max_depth: u32) -> MotionScene {
    let (min, d) = (Vec3::splat(-BOX), 2.0 * BOX);
    let (dx, dy, dz) = (d * Vec3::X, d * Vec3::Y, d * Vec3::Z);
    let max = Vec3::splat(BOX);
    // Each wall's normal, e1 x e2, points into the box.
    let walls = [
        Parallelogram::new(Vec3::new(min.x, min.y, max.z), dy, dx),
        Parallelogram::new(min, dx, dy),
        Parallelogram::new(Vec3::new(max.x, min.y, min.z), dz, dy),
        Parallelogram::new(min, dy, dz),
        Parallelogram::new(Vec3::new(min.x, max.y, min.z), dx, dz),
        Parallelogram::new(min, dz, dx),
    ];
    let frame = CameraFrame::look_at(Vec3::new(0.3, 0.5, 2.6), Vec3::ZERO, Vec3::Y).unwrap();
    let camera = (Camera::pinhole(frame, 60.0), FilmSettings::new(SIZE, SIZE));
    walls
        .into_iter()
        .fold(Builder::new(), |builder, wall| {
            builder.area_light(Shape::Parallelogram(wall), Vec3::splat(SKY))
        })
        .shape(object, material)
        .build(camera, max_depth)
}

/// The objects of the glowing box, and whether they absorb nothing: a white lobe loses the
/// directions that fall below its surface (they are dropped).
fn box_objects() -> [(&'static str, Material, bool); 5] {
    [
        ("white matte", matte(Vec3::ONE), true),
        ("mirror", Material::mirror(), true),
        ("glass", Material::glass(1.5), true),
        ("white glossy", Material::glossy(Vec3::ONE, 20.0), false),
        ("frosted glass", Material::rough_glass(1.5, 50.0), false),
    ]
}

/// Checks that `out`, a render of a furnace, is on average no brighter than the sky (the
/// walls), and if `absorbs_nothing`, no darker either.
///
/// Random estimators may put single pixels above the sky, so it is their mean that is
/// checked: in a furnace every pixel of an object that absorbs nothing has the sky as its
/// expected value, so the spread of the pixels measures the noise, and the mean must lie
/// within 5 standard errors of the sky. (Where the object loses light depending on the view,
/// the spread also holds that variation, and the bound is looser.) A smooth object's paths
/// are exact: there the standard error is 0 and only float rounding is allowed.
fn assert_as_bright_as_the_sky(what: &str, out: &RenderOutput, absorbs_nothing: bool) {
    assert_eq!(out.stats.nonfinite_samples, 0, "{what}");
    let values: Vec<f64> = out
        .image
        .pixels
        .iter()
        .map(|p| f64::from(p.element_sum()) / 3.0)
        .collect();
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    let allowed = 5.0 * (variance / n).sqrt() + f64::from(ROUNDING);
    let sky = f64::from(SKY);
    assert!(
        mean <= sky + allowed,
        "{what}: a mean of {mean} under a sky of {SKY} (± {allowed}): energy was created"
    );
    assert!(
        !absorbs_nothing || mean >= sky - allowed,
        "{what}: a mean of {mean} under a sky of {SKY} (± {allowed}): energy was lost"
    );
}

/// Samples per pixel of the path-traced and area-lit furnaces.
const NOISY_SPP: u64 = 64;

/// Chapter 08's render of `scene`: random pixel positions, a box filter.
fn path_traced(scene: &MotionScene, options: PathOptions) -> RenderOutput {
    let sampler = PixelSampler::new(PixelSamplerKind::Random, NOISY_SPP, 3).unwrap();
    let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
    ch08_path_tracing::render_with(
        scene,
        Method::new(options),
        &Lens::PINHOLE,
        &settings(NOISY_SPP),
        &sampler,
        &filter,
    )
}

/// Chapter 08's path tracer on chapter 01's objects. A path follows one ray at glass, chosen
/// by the Fresnel term with weight 1, so without Russian roulette every sample is the sky or,
/// if still inside after 64 segments, nothing: no pixel may be brighter than the sky. With
/// roulette (Mitsuba's, from segment 5) a surviving path is divided by its chance to survive,
/// so a sample may be brighter than the sky, and only the mean must match it.
#[test]
fn closed_glass_and_mirrors_look_like_the_sky_to_the_path_tracer() {
    for object in OBJECTS {
        let scene = MotionScene::still(in_the_furnace(object, 64));
        let exact = PathOptions {
            rr_depth: None,
            ..PathOptions::with_depth(64)
        };
        let what = format!("ch08 {object:?}");
        let darkest = darkest_pixel(&what, &path_traced(&scene, exact));
        assert!(darkest > 0.99, "{what}: a pixel of {darkest} is too dark");
        let out = path_traced(&scene, PathOptions::with_depth(64));
        assert_as_bright_as_the_sky(&format!("{what} with roulette"), &out, true);
    }
}

/// Chapters 07 and 08 in the glowing box: chapter 07's direct light (one point on each wall
/// per matte hit), and chapter 08's paths with next-event estimation off, and on with each
/// way of weighting a light sample against a BSDF sample that finds the same wall.
#[test]
fn objects_in_a_glowing_box_look_like_its_walls() {
    let ball = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0));
    let base = PathOptions::with_depth(64);
    let mut estimators = vec![PathOptions { nee: false, ..base }];
    estimators.extend(MisHeuristic::ALL.map(|mis| PathOptions { mis, ..base }));
    for (name, material, absorbs_nothing) in box_objects() {
        let scene = in_a_glowing_box(ball, material, 64);
        let sampler = PixelSampler::new(PixelSamplerKind::Random, NOISY_SPP, 3).unwrap();
        let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
        let out = ch07_soft_shadows::render_with(
            &scene,
            LightOptions::default(),
            TraceOptions::default(),
            &Lens::PINHOLE,
            &settings(NOISY_SPP),
            &sampler,
            &filter,
        );
        assert_as_bright_as_the_sky(&format!("ch07 {name}"), &out, absorbs_nothing);
        for options in &estimators {
            let what = format!("ch08 {name} {options:?}");
            assert_as_bright_as_the_sky(&what, &path_traced(&scene, *options), absorbs_nothing);
        }
    }
}
