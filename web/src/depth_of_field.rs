//! Chapter 04's demo: the chapter's bokeh scene (spheres at three depths, a floor running away,
//! a dark wall with small holes of bright sky) through the chapter's thin-lens camera, with
//! chapter 01's tracer behind it.
//!
//! The lens is set as a photographer sets it, by focal length and f-number (the aperture's
//! radius is `f / 2N`, [`Lens::from_f_number`]); the field of view stays the scene's, as in
//! Mitsuba's `thinlens` sensor, so the focal length only changes how wide the aperture is. The
//! holes of the wall are the point lights whose blur draws the aperture: a disc or a polygon,
//! and, with the naive warp, a disc brighter in its middle.

use ch01_whitted::camera::PinholeCamera;
use ch01_whitted::tracer;
use ch04_depth_of_field::scenes::{
    BOKEH_SPHERE_DEPTHS, BOKEH_WALL_DEPTH, Builtin, DEFAULT_MAX_DEPTH,
};
use ch04_depth_of_field::{Aperture, Lens, LensWarp, ThinLensCamera};
use common::image::Image;
use common::sampler::IndependentSampler;
use common::scene::Scene;
use glam::{UVec2, Vec2, Vec3};

use crate::contrast::rms_neighbour_difference;
use crate::demo::{Claim, Control, Demo, Picture, Values, trace_each};
use crate::progressive::render_demo;

/// The demo (`data-demo="depth-of-field"`).
pub struct DepthOfFieldDemo;

/// The seed of the demo's samples: the same values always give the same picture.
const SEED: u64 = 4;

/// The disc warps, in the order of [`LensWarp::ALL`].
const WARPS: &[&str] = &["concentric", "polar", "naive (r = ξ)"];

/// The aperture's shapes; the polygon's blades are a control of their own.
const SHAPES: &[&str] = &["disc", "polygon"];

/// The picture: the bokeh scene and the thin-lens camera; the pixel position and the lens
/// point are the sample's first dimensions, as in the chapter's render.
struct ThroughTheLens {
    scene: Scene,
    camera: ThinLensCamera,
    sampler: IndependentSampler,
}

impl Picture for ThroughTheLens {
    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
        trace_each(&self.sampler, pixels, index, add, |p_film, sampler| {
            tracer::trace(&self.scene, &self.camera.generate_ray(p_film, sampler), 1)
        });
    }
}

/// The lens the values describe.
fn lens(values: &Values) -> Result<Lens, String> {
    let lens = Lens::from_f_number(
        values.f32("focal-length"),
        values.f32("f-number"),
        values.f32("focus"),
    )?;
    let warp = *LensWarp::ALL
        .get(values.index("warp"))
        .ok_or("no such warp")?;
    let aperture = match values.index("aperture") {
        0 => Aperture::Disc,
        _ => Aperture::polygon(values.index("blades") as u32, 0.0)?,
    };
    Ok(lens.with_warp(warp).with_aperture(aperture))
}

impl Demo for DepthOfFieldDemo {
    fn name(&self) -> &'static str {
        "depth-of-field"
    }

    fn controls(&self) -> Vec<Control> {
        vec![
            Control::range("f-number", "f-number", 1.4, 16.0, 0.1, 2.0),
            Control::range(
                "focal-length",
                "focal length (scene units)",
                0.1,
                1.0,
                0.05,
                0.5,
            ),
            Control::range(
                "focus",
                "focus distance",
                2.0,
                f64::from(BOKEH_WALL_DEPTH),
                0.25,
                f64::from(BOKEH_SPHERE_DEPTHS[1]),
            ),
            Control::choice("warp", "disc warp", WARPS, 0).when("aperture", 0.0),
            Control::choice("aperture", "aperture shape", SHAPES, 0),
            Control::range("blades", "blades", 3.0, 8.0, 1.0, 5.0).when("aperture", 1.0),
        ]
    }

    fn target_spp(&self, _: &Values) -> u64 {
        // A blurred light is a handful of bright samples spread over dozens of pixels: its
        // shape (a disc, a polygon, a bright core) shows only once each pixel has many.
        64
    }

    fn size(&self) -> (u32, u32) {
        // The chapter's scene is framed 3:2.
        (180, 120)
    }

    fn picture(
        &self,
        values: &Values,
        _view: usize,
        width: u32,
        height: u32,
    ) -> Result<Box<dyn Picture>, String> {
        let scene = Builtin::Bokeh.build(DEFAULT_MAX_DEPTH);
        let pinhole = PinholeCamera::of(&scene.camera, width, height);
        Ok(Box::new(ThroughTheLens {
            scene,
            camera: ThinLensCamera::new(pinhole, lens(values)?),
            sampler: IndependentSampler::new(SEED),
        }))
    }

    fn claims(&self) -> Vec<Claim> {
        vec![
            Claim {
                says: "a wider aperture blurs what is off the focal plane, and not what is on it",
                check: |demo| {
                    let values = |f_number| defaults(demo).with("f-number", f_number);
                    let (narrow, wide) =
                        (render(demo, &values(16.0))?, render(demo, &values(1.4))?);
                    let depths = depths();
                    let focus = defaults(demo).f32("focus");
                    let far = |image: &Image| sharpness(image, &depths, |d| d > FAR);
                    let on = |image: &Image| sharpness(image, &depths, |d| (d - focus).abs() < 0.5);
                    if far(&wide) > 0.7 * far(&narrow) {
                        return Err(format!(
                            "beyond the focal plane, f/1.4 is as sharp as f/16 ({:.4} against \
                             {:.4})",
                            far(&wide),
                            far(&narrow)
                        ));
                    }
                    if on(&wide) < 0.85 * on(&narrow) {
                        return Err(format!(
                            "on the focal plane, f/1.4 is blurred: {:.4} against {:.4} at f/16",
                            on(&wide),
                            on(&narrow)
                        ));
                    }
                    Ok(())
                },
            },
            Claim {
                says: "focusing near sharpens the near things and blurs the far ones, focusing \
                       far the other way round",
                check: |demo| {
                    let [near_sphere, _, far_sphere] = BOKEH_SPHERE_DEPTHS.map(f64::from);
                    let at = |focus| render(demo, &defaults(demo).with("focus", focus));
                    let (near_focus, far_focus) = (at(near_sphere)?, at(far_sphere)?);
                    let depths = depths();
                    let near = |image: &Image| sharpness(image, &depths, |d| d < NEAR);
                    let far = |image: &Image| sharpness(image, &depths, |d| d > FAR);
                    if near(&near_focus) < 1.3 * near(&far_focus) {
                        return Err(format!(
                            "the near things are not clearly sharper focused at {near_sphere} \
                             than at {far_sphere} ({:.4} against {:.4})",
                            near(&near_focus),
                            near(&far_focus)
                        ));
                    }
                    if far(&far_focus) < 1.3 * far(&near_focus) {
                        return Err(format!(
                            "the far things are not clearly sharper focused at {far_sphere} \
                             than at {near_sphere} ({:.4} against {:.4})",
                            far(&far_focus),
                            far(&near_focus)
                        ));
                    }
                    Ok(())
                },
            },
            Claim {
                says: "the naive warp's bokeh is brighter in its middle than the correct one's",
                check: |demo| {
                    let holes = holes();
                    let middles = |warp| -> Result<f64, String> {
                        let values = defaults(demo)
                            .with("focus", f64::from(BOKEH_SPHERE_DEPTHS[0]))
                            .with("f-number", 1.4)
                            .with("warp", warp);
                        Ok(mean_where(&render(demo, &values)?, &holes))
                    };
                    let (concentric, naive) = (middles(0.0)?, middles(2.0)?);
                    if naive < 2.0 * concentric {
                        return Err(format!(
                            "where the holes' bokeh is centred the naive warp gives {naive:.3}, \
                             not clearly more than the concentric warp's {concentric:.3}"
                        ));
                    }
                    Ok(())
                },
            },
        ]
    }
}

/// The size of the claims' renders (the scene's 3:2) and their samples per pixel.
const CLAIM_SIZE: UVec2 = UVec2::new(72, 48);
const CLAIM_SPP: u64 = 32;

/// Depths nearer than this are the near things (the near sphere, the floor before it), farther
/// than [`FAR`] the far ones (the far sphere, the floor behind it, the wall and its lights): the
/// middle sphere, where the demo starts focused, lies between.
const NEAR: f32 = 5.0;
/// See [`NEAR`].
const FAR: f32 = 10.0;

/// The demo's starting values.
fn defaults(demo: &dyn Demo) -> Values {
    Values::defaults(&demo.controls())
}

/// The demo with `values`, rendered whole at the claims' size.
fn render(demo: &dyn Demo, values: &Values) -> Result<Image, String> {
    render_demo(demo, values, CLAIM_SIZE, CLAIM_SPP)
}

/// The depth, along the camera's axis, of what the pinhole sees through the centre of each
/// pixel of the claims' renders, row by row (infinite where it sees the sky).
fn depths() -> Vec<f32> {
    let scene = Builtin::Bokeh.build(DEFAULT_MAX_DEPTH);
    let camera = PinholeCamera::of(&scene.camera, CLAIM_SIZE.x, CLAIM_SIZE.y);
    let axis = camera.frame.to_world(Vec3::Z);
    let mut depths = Vec::new();
    for y in 0..CLAIM_SIZE.y {
        for x in 0..CLAIM_SIZE.x {
            let ray = camera.generate_ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
            let depth = scene
                .geometry
                .intersect(&ray)
                .map_or(f32::INFINITY, |hit| (hit.p - camera.frame.origin).dot(axis));
            depths.push(depth);
        }
    }
    depths
}

/// How sharp `image` is where the depth is one that `chosen` accepts.
fn sharpness(image: &Image, depths: &[f32], chosen: impl Fn(f32) -> bool) -> f64 {
    rms_neighbour_difference(image, |x, y| chosen(depths[(y * image.width + x) as usize]))
}

/// Whether the pinhole sees the sky, through a hole of the far wall, somewhere in each pixel of
/// the claims' renders (a grid of 4 x 4 rays per pixel; a hole is about a pixel wide there), row
/// by row: where a blurred hole's bokeh has its middle.
fn holes() -> Vec<bool> {
    let scene = Builtin::Bokeh.build(DEFAULT_MAX_DEPTH);
    let camera = PinholeCamera::of(&scene.camera, CLAIM_SIZE.x, CLAIM_SIZE.y);
    let mut holes = Vec::new();
    for y in 0..CLAIM_SIZE.y {
        for x in 0..CLAIM_SIZE.x {
            let sees_sky = (0..16).any(|k| {
                let offset = Vec2::new((k % 4) as f32 + 0.5, (k / 4) as f32 + 0.5) / 4.0;
                let ray = camera.generate_ray(Vec2::new(x as f32, y as f32) + offset);
                scene.geometry.intersect(&ray).is_none()
            });
            holes.push(sees_sky);
        }
    }
    holes
}

/// The mean value (of the three channels) of the pixels of `image` that `chosen` marks.
fn mean_where(image: &Image, chosen: &[bool]) -> f64 {
    let (sum, count) = image
        .pixels
        .iter()
        .zip(chosen)
        .filter(|(_, chosen)| **chosen)
        .fold((0.0, 0u32), |(sum, count), (p, _)| {
            (sum + f64::from(p.element_sum()) / 3.0, count + 1)
        });
    sum / f64::from(count.max(1))
}
