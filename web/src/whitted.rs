//! Chapter 01's demo: Whitted's scene through the chapter's own pinhole camera and recursive
//! tracer, with its depth limit, the glass's index of refraction and the main light's place.
//!
//! Whitted's tracer is deterministic: one ray through each pixel centre is the whole image, so
//! the demo stops at one sample per pixel.

use ch01_whitted::camera::PinholeCamera;
use ch01_whitted::pixel::CentreSampler;
use ch01_whitted::scenes::Builtin;
use ch01_whitted::tracer;
use common::image::Image;
use common::scene::{Material, Scene};
use glam::{UVec2, Vec2, Vec3};

use crate::demo::{Claim, Control, Demo, Picture, Values, trace_each};
use crate::progressive::render_demo;

/// The demo (`data-demo="whitted"`).
pub struct WhittedDemo;

/// The picture: the chapter's scene, its camera and centre samples.
struct Whitted {
    scene: Scene,
    camera: PinholeCamera,
    sampler: CentreSampler,
}

impl Picture for Whitted {
    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
        trace_each(&self.sampler, pixels, index, add, |p_film, _| {
            tracer::trace(&self.scene, &self.camera.generate_ray(p_film), 1)
        });
    }
}

/// Chapter 01's `spheres` scene with the demo's values: its depth limit, its glass ball's
/// index of refraction, its first light moved.
fn scene(values: &Values) -> Scene {
    let mut scene = Builtin::Spheres.build(values.index("max-depth") as u32);
    for surface in &mut scene.surfaces {
        if let Material::Dielectric { int_ior, .. } = &mut surface.material {
            *int_ior = values.f32("ior");
        }
    }
    let light = &mut scene.point_lights[0];
    light.position = Vec3::new(values.f32("light-x"), values.f32("light-height"), 4.0);
    scene
}

impl Demo for WhittedDemo {
    fn name(&self) -> &'static str {
        "whitted"
    }

    fn controls(&self) -> Vec<Control> {
        vec![
            Control::range("max-depth", "max depth", 1.0, 12.0, 1.0, 5.0),
            Control::range("ior", "glass's index of refraction", 1.0, 2.5, 0.05, 1.5),
            Control::range("light-x", "light left–right", -6.0, 6.0, 0.25, -3.0),
            Control::range("light-height", "light height", 0.5, 10.0, 0.25, 6.0),
        ]
    }

    fn target_spp(&self, _: &Values) -> u64 {
        1
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
        let scene = scene(values);
        let camera = PinholeCamera::of(&scene.camera, width, height);
        Ok(Box::new(Whitted {
            scene,
            camera,
            sampler: CentreSampler::new(1),
        }))
    }

    fn claims(&self) -> Vec<Claim> {
        vec![
            Claim {
                says: "the depth limit changes what the mirror and the glass show, and no matte \
                       surface seen directly",
                check: |demo| {
                    changes_only(demo, ("max-depth", 2.0), ("max-depth", 6.0), |m| {
                        matches!(m, Material::Mirror { .. } | Material::Dielectric { .. })
                    })
                },
            },
            Claim {
                says: "the index of refraction changes what is seen through and in the glass, \
                       and no matte surface seen directly",
                check: |demo| {
                    changes_only(demo, ("ior", 1.0), ("ior", 2.0), |m| {
                        matches!(m, Material::Mirror { .. } | Material::Dielectric { .. })
                    })
                },
            },
            Claim {
                says: "moving the light changes how the surfaces are lit, and not the sky",
                check: |demo| changes_only(demo, ("light-x", -5.0), ("light-x", 5.0), |_| true),
            },
        ]
    }
}

/// The size of the claims' renders.
const CLAIM_SIZE: UVec2 = UVec2::new(48, 36);

/// Renders the demo with its default values but `a`, then but `b`, and checks that the image
/// changes in some pixel whose camera ray first hits a material that `may_change` accepts, and
/// in no other pixel (the sky's among them).
fn changes_only(
    demo: &dyn Demo,
    a: (&str, f64),
    b: (&str, f64),
    may_change: fn(&Material) -> bool,
) -> Result<(), String> {
    let defaults = Values::defaults(&demo.controls());
    let render = |values: &Values| -> Result<(Image, Scene), String> {
        Ok((render_demo(demo, values, CLAIM_SIZE, 1)?, scene(values)))
    };
    let (first, scene_a) = render(&defaults.clone().with(a.0, a.1))?;
    let (second, _) = render(&defaults.with(b.0, b.1))?;
    let camera = PinholeCamera::of(&scene_a.camera, CLAIM_SIZE.x, CLAIM_SIZE.y);
    let mut changed_where_allowed = 0;
    for y in 0..CLAIM_SIZE.y {
        for x in 0..CLAIM_SIZE.x {
            let ray = camera.generate_ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
            let allowed = scene_a
                .geometry
                .intersect(&ray)
                .is_some_and(|hit| may_change(&scene_a.surface(hit.shape).material));
            let changed = first.get(x, y) != second.get(x, y);
            if changed && !allowed {
                return Err(format!(
                    "pixel ({x}, {y}) changed from {} = {} to {} = {}, and it should not have",
                    a.0, a.1, b.0, b.1
                ));
            }
            changed_where_allowed += usize::from(changed && allowed);
        }
    }
    if changed_where_allowed == 0 {
        return Err(format!(
            "no pixel changed from {} = {} to {} = {}",
            a.0, a.1, b.0, b.1
        ));
    }
    Ok(())
}
