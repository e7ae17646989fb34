//! Chapter 09's demo: one ball of Mitsuba's rough materials (a named metal, plastic, glass)
//! on a matte floor under a panel and a small bright sphere, path-traced by chapter 08's loop
//! with chapter 09's materials; its roughness, its microfacet distribution and the metal.

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{CameraRays, MotionScene};
use ch06_fuzzy_reflections::FuzzMethod;
use ch07_soft_shadows::scenes::{Builder, camera, ceiling_panel, floor, matte};
use ch07_soft_shadows::{AreaLights, LightSampling};
use ch08_path_tracing::{PathOptions, PathTracer, SceneLights};
use ch09_materials::SceneMaterials;
use common::geometry::{Shape, Sphere};
use common::image::Image;
use common::sampler::IndependentSampler;
use common::scene::{
    Conductor, Material, Microfacet, MicrofacetDistribution, Plastic, RoughGlass, named_metal,
};
use glam::{UVec2, Vec2, Vec3};

use crate::demo::{Claim, Control, Demo, Picture, Values, trace_each};
use crate::progressive::render_demo;

/// The demo (`data-demo="materials"`).
pub struct MaterialsDemo;

/// The materials the ball can be made of.
const MATERIALS: &[&str] = &["rough metal", "rough plastic", "rough glass"];

/// The metals, as the page names them, and as Mitsuba does (in the same order).
const METAL_NAMES: &[&str] = &["gold (Au)", "copper (Cu)", "silver (Ag)", "aluminium (Al)"];
const METALS: &[&str] = &["Au", "Cu", "Ag", "Al"];

/// The microfacet distributions, as the page names them.
const DISTRIBUTIONS: &[&str] = &["GGX", "Beckmann"];

/// Where the ball is, and its radius.
const BALL: (Vec3, f32) = (Vec3::new(0.0, 0.75, 0.0), 0.75);

/// The picture: the scene with its lights and materials, and chapter 05's camera rays.
struct Materials {
    world: MotionScene,
    area_lights: AreaLights,
    materials: SceneMaterials,
    camera_rays: CameraRays,
    sampler: IndependentSampler,
}

impl Picture for Materials {
    fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
        let tracer = PathTracer {
            world: &self.world,
            lights: SceneLights::of(&self.world, &self.area_lights, LightSampling::solid_angle()),
            options: PathOptions {
                max_depth: self.world.scene.max_depth,
                ..PathOptions::default()
            },
            materials: self.materials.clone(),
        };
        trace_each(&self.sampler, pixels, index, add, |p_film, sampler| {
            let ray = self.camera_rays.generate(&self.world, p_film, sampler);
            tracer.radiance(&ray, sampler)
        });
    }
}

/// The ball's material for these values.
fn ball(values: &Values) -> Material {
    let distribution = match values.index("distribution") {
        0 => MicrofacetDistribution::Ggx,
        _ => MicrofacetDistribution::Beckmann,
    };
    let roughness = Microfacet::isotropic(distribution, values.f32("alpha"));
    match values.index("material") {
        0 => {
            let name = METALS[values.index("metal").min(METALS.len() - 1)];
            let (eta, k) = named_metal(name).expect("the demo's metals are Mitsuba's");
            Material::Conductor(Conductor {
                eta,
                k,
                specular_reflectance: Vec3::ONE,
                specular_texture: None,
                two_sided: false,
                roughness: Some(roughness),
            })
        }
        1 => Material::Plastic(Plastic {
            diffuse_reflectance: Vec3::new(0.1, 0.25, 0.6),
            specular_reflectance: Vec3::ONE,
            diffuse_texture: None,
            specular_texture: None,
            int_ior: 1.5,
            ext_ior: 1.0,
            nonlinear: false,
            two_sided: false,
            roughness: Some(roughness),
        }),
        _ => Material::RoughGlass(RoughGlass {
            int_ior: 1.5,
            ext_ior: 1.0,
            exponent: roughness.lobe_exponent(),
            stands_in_for: Some(roughness),
        }),
    }
}

/// The scene: the ball on a floor, a panel above and a small bright sphere beside it, under a
/// dim sky.
fn world(values: &Values) -> MotionScene {
    let (centre, radius) = BALL;
    let mut world = Builder::new()
        .shape(floor(6.0), matte(Vec3::new(0.45, 0.45, 0.42)))
        .shape(Shape::Sphere(Sphere::new(centre, radius)), ball(values))
        .area_light(
            ceiling_panel(Vec3::new(-1.5, 3.5, 1.0), 1.2),
            Vec3::splat(6.0),
        )
        .area_light(
            Shape::Sphere(Sphere::new(Vec3::new(1.6, 1.9, 1.4), 0.2)),
            Vec3::new(40.0, 36.0, 30.0),
        )
        .build(
            camera(Vec3::new(0.0, 1.4, 3.6), Vec3::new(0.0, 0.7, 0.0), 42.0),
            6,
        );
    world.scene.environment = Vec3::new(0.18, 0.22, 0.3);
    world
}

impl Demo for MaterialsDemo {
    fn name(&self) -> &'static str {
        "materials"
    }

    fn controls(&self) -> Vec<Control> {
        vec![
            Control::choice("material", "material", MATERIALS, 0),
            Control::choice("metal", "metal", METAL_NAMES, 0).when("material", 0.0),
            Control::choice("distribution", "distribution", DISTRIBUTIONS, 0),
            Control::range("alpha", "roughness α", 0.02, 0.8, 0.01, 0.15),
        ]
    }

    fn picture(
        &self,
        values: &Values,
        _view: usize,
        width: u32,
        height: u32,
    ) -> Result<Box<dyn Picture>, String> {
        let world = world(values);
        let area_lights = AreaLights::of(&world.scene);
        let materials = SceneMaterials::of(&world.scene, FuzzMethod::Lobe);
        let camera_rays = CameraRays::new(&world, &Lens::PINHOLE, width, height);
        Ok(Box::new(Materials {
            world,
            area_lights,
            materials,
            camera_rays,
            sampler: IndependentSampler::new(9),
        }))
    }

    fn claims(&self) -> Vec<Claim> {
        vec![
            Claim {
                says: "a rougher metal spreads the small light's highlight: a wider, dimmer spot",
                check: |demo| {
                    let sharp = render(demo, &[("alpha", 0.05)])?;
                    let rough = render(demo, &[("alpha", 0.5)])?;
                    let (peak_sharp, peak_rough) = (brightest(&sharp), brightest(&rough));
                    if peak_rough >= peak_sharp {
                        return Err(format!(
                            "the brightest pixel of the ball is {peak_rough:.2} at α = 0.5, \
                             not dimmer than {peak_sharp:.2} at α = 0.05"
                        ));
                    }
                    Ok(())
                },
            },
            Claim {
                says: "gold reflects more red than blue, silver nearly as much of each",
                check: |demo| {
                    let ratio = |metal: f64| -> Result<f32, String> {
                        let image = render(demo, &[("metal", metal), ("alpha", 0.3)])?;
                        let mean = ball_mean(&image);
                        Ok(mean.x / mean.z.max(1e-6))
                    };
                    let (gold, silver) = (ratio(0.0)?, ratio(2.0)?);
                    if !(gold > 1.5 * silver && silver < 1.3) {
                        return Err(format!(
                            "the ball's red over blue is {gold:.2} for gold and {silver:.2} \
                             for silver"
                        ));
                    }
                    Ok(())
                },
            },
            Claim {
                says: "at the same α, GGX's longer tails light more of the ball around the \
                       highlight than Beckmann's",
                check: |demo| {
                    let lit = |distribution: f64| -> Result<usize, String> {
                        let image =
                            render(demo, &[("distribution", distribution), ("alpha", 0.1)])?;
                        let peak = brightest(&image);
                        Ok(ball_pixels(&image)
                            .filter(|l| l.max_element() > 0.05 * peak)
                            .count())
                    };
                    let (ggx, beckmann) = (lit(0.0)?, lit(1.0)?);
                    if ggx <= beckmann {
                        return Err(format!(
                            "{ggx} pixels of the ball are above a twentieth of its peak with \
                             GGX, {beckmann} with Beckmann"
                        ));
                    }
                    Ok(())
                },
            },
        ]
    }
}

/// The size and samples per pixel of the claims' renders.
const CLAIM_SIZE: UVec2 = UVec2::new(48, 48);
const CLAIM_SPP: u64 = 16;

/// The demo rendered small with its default values but `changes`.
fn render(demo: &dyn Demo, changes: &[(&str, f64)]) -> Result<Image, String> {
    let values = changes.iter().fold(
        Values::defaults(&demo.controls()),
        |values, (name, value)| values.with(name, *value),
    );
    render_demo(demo, &values, CLAIM_SIZE, CLAIM_SPP)
}

/// The pixels whose centre's camera ray hits the ball first.
fn ball_pixels(image: &Image) -> impl Iterator<Item = Vec3> + '_ {
    let world = world(&Values::defaults(&MaterialsDemo.controls()));
    let camera_rays = CameraRays::new(&world, &Lens::PINHOLE, image.width, image.height);
    let mut sampler = IndependentSampler::new(0);
    let mut on_ball = Vec::new();
    for y in 0..image.height {
        for x in 0..image.width {
            let ray = camera_rays.generate(
                &world,
                Vec2::new(x as f32 + 0.5, y as f32 + 0.5),
                &mut sampler,
            );
            let hit = world.scene.geometry.intersect(&ray);
            if hit.is_some_and(|hit| (hit.p - BALL.0).length() < BALL.1 * 1.01) {
                on_ball.push(image.get(x, y));
            }
        }
    }
    on_ball.into_iter()
}

/// The brightest channel of the brightest pixel on the ball.
fn brightest(image: &Image) -> f32 {
    ball_pixels(image)
        .map(|l| l.max_element())
        .fold(0.0, f32::max)
}

/// The ball's mean colour.
fn ball_mean(image: &Image) -> Vec3 {
    let (sum, count) = ball_pixels(image).fold((Vec3::ZERO, 0), |(s, n), l| (s + l, n + 1));
    sum / count.max(1) as f32
}
