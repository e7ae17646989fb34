//! Furnace tests: closed glass and mirror objects under a uniform white sky, with no lights,
//! must look exactly as bright as the sky, never brighter. Energy is never created, and none is
//! lost but to the recursion limit.
//!
//! Chapters 01 to 04 have no rough surfaces: Whitted's matte surfaces see only point lights,
//! so the objects that can be put in a furnace are the smooth mirror and glass ones. Grazing
//! views are included (a glass slab and a mirror floor seen at half a degree), where the
//! Fresnel reflectance approaches 1.

use ch01_whitted::camera::{CameraFrame, PinholeCamera};
use ch01_whitted::material::Material;
use ch01_whitted::scene::{Scene, SceneBuilder};
use ch01_whitted::{PixelPattern, render};
use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::lens::Lens;
use common::geometry::{Quad, Shape, Sphere};
use common::render::{RenderOutput, RenderSettings};
use glam::Vec3;
use workbook_tests::octahedron;

const SKY: f32 = 1.0;
/// Float rounding allowed above the sky: sums of a few dozen products in `f32`.
const ROUNDING: f32 = 1e-5;
const SIZE: u32 = 24;

fn camera(origin: Vec3, target: Vec3, fov: f32) -> PinholeCamera {
    PinholeCamera::new(
        CameraFrame::look_at(origin, target, Vec3::Y).unwrap(),
        fov,
        SIZE,
        SIZE,
    )
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
    let builder = SceneBuilder::new().background(Vec3::splat(SKY));
    let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0));
    let builder = match object {
        Object::GlassSphere(ior) => builder.shape(sphere, Material::glass(ior)),
        Object::MirrorSphere => builder.shape(sphere, Material::mirror()),
        Object::GlassOctahedron => builder.mesh(&octahedron(Vec3::ZERO, 1.2), Material::glass(1.5)),
    };
    builder.build(
        camera(Vec3::new(0.3, 0.5, 4.0), Vec3::ZERO, 40.0),
        max_depth,
    )
}

/// A glass slab (two parallel quads, facing out) and, beside it, a mirror floor, both seen
/// from half a degree above their planes.
fn grazing_views(max_depth: u32) -> Scene {
    let slab_top = Quad::new(
        Vec3::new(-50.0, 0.0, 50.0),
        50.0 * Vec3::X,
        -100.0 * Vec3::Z,
    );
    let slab_bottom = Quad::new(
        Vec3::new(-50.0, -0.3, -50.0),
        50.0 * Vec3::X,
        100.0 * Vec3::Z,
    );
    let mirror = Quad::new(Vec3::new(0.0, 0.0, 50.0), 50.0 * Vec3::X, -100.0 * Vec3::Z);
    let grazing = 0.5f32.to_radians();
    let origin = Vec3::new(0.0, 0.2, 10.0);
    let target = origin + Vec3::new(0.0, -grazing.tan(), -1.0);
    SceneBuilder::new()
        .background(Vec3::splat(SKY))
        .shape(Shape::Quad(slab_top), Material::glass(1.5))
        .shape(Shape::Quad(slab_bottom), Material::glass(1.5))
        .shape(Shape::Quad(mirror), Material::mirror())
        .build(camera(origin, target, 20.0), max_depth)
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
