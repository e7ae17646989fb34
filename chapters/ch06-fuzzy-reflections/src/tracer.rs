//! The fuzzy tracer: chapter 01's recursion, with random choices at mirrors and glass.
//!
//! A ray finds the nearest surface, as before. Matte surfaces are lit by the lights they see
//! (asked through [`Lighting`]); a perfect mirror sends its one reflected ray. What changes is
//! everything else:
//!
//! - glass follows both rays or one chosen at random, by the render's [`GlassStrategy`];
//! - a glossy surface sends one ray into its `cos^n` lobe around the mirror direction (or the
//!   empirical disc's spread), and shows the point lights as highlights;
//! - frosted glass does both: it picks reflection or refraction, then spreads the chosen ray;
//! - a spread ray that ends on the wrong side of the surface is handled by the render's
//!   [`BelowSurface`] policy.
//!
//! Random numbers are drawn per bounce, after the camera's: a choice at glass takes one, a
//! spread direction two (two more per resample). A smooth scene draws none, and renders as
//! chapter 05 does.

use crate::below_surface::BelowSurface;
use crate::fuzz::FuzzMethod;
use crate::glass_choice::GlassStrategy;
use crate::highlights::Lobe;
use crate::lighting::Lighting;
use ch01_whitted::optics::reflect;
use ch01_whitted::world::World;
use ch05_motion_blur::MotionScene;
use common::Ray;
use common::geometry::SurfaceHit;
use common::sampler::Sampler;
use common::scene::{Glossy, Material};
use glam::Vec3;

/// The render's choices at mirrors and glass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TraceOptions {
    /// Which ray to trace at glass.
    pub glass: GlassStrategy,
    /// How fuzzy surfaces spread their directions.
    pub fuzz: FuzzMethod,
    /// What to do with a spread direction below the surface.
    pub below: BelowSurface,
}

impl Default for TraceOptions {
    /// One ray chosen by the Fresnel term, the `cos^n` lobe, stray rays dropped.
    fn default() -> Self {
        Self {
            glass: GlassStrategy::Fresnel,
            fuzz: FuzzMethod::Lobe,
            below: BelowSurface::Drop,
        }
    }
}

/// What one call of the tracer needs besides the ray: the scene, its lights, the options.
#[derive(Clone, Copy)]
pub struct Tracer<'a, L: Lighting> {
    /// The scene, with its motion.
    pub world: &'a MotionScene,
    /// How surfaces are lit directly.
    pub lighting: &'a L,
    /// Choices at mirrors and glass.
    pub options: TraceOptions,
}

impl<L: Lighting> Tracer<'_, L> {
    // ANCHOR: trace
    /// The radiance arriving along `ray`, segment number `depth` of its path (the camera ray
    /// is segment 1). Every ray it spawns keeps the ray's shutter `time`.
    pub fn trace<S: Sampler>(&self, ray: &Ray, depth: u32, sampler: &mut S) -> Vec3 {
        let world = self.world;
        let Some(hit) = world.intersect(ray) else {
            return world.background(ray.dir);
        };
        let emitted = self.lighting.emitted(&hit, ray);
        if depth >= world.scene.max_depth {
            return emitted; // no segment left to carry reflected light
        }
        // The material with its texture read at the hit: a textured matte surface comes back
        // as a matte one of the colour there.
        let scattered = match *world.material_at(&hit) {
            Material::Diffuse { albedo, two_sided } => self
                .lighting
                .matte(world, ray, &hit, albedo, two_sided, sampler),
            Material::Mirror { reflectance } => {
                if !hit.front_face(ray.dir) {
                    return emitted; // mirrors reflect on their front side only
                }
                let reflected = hit.spawn_ray(reflect(ray.dir, hit.n), ray.time);
                reflectance * self.trace(&reflected, depth + 1, sampler)
            }
            Material::Dielectric { int_ior, ext_ior } => {
                self.glass(ray, &hit, int_ior, ext_ior, f32::INFINITY, depth, sampler)
            }
            Material::Glossy(glossy) => self.glossy(ray, &hit, &glossy, depth, sampler),
            Material::RoughGlass(glass) => self.glass(
                ray,
                &hit,
                glass.int_ior,
                glass.ext_ior,
                glass.exponent,
                depth,
                sampler,
            ),
            // The materials beyond the lecture (ch09-materials): the capability check refuses
            // them or puts the lecture's stand-in (a mirror or a lobe for a metal) in their place.
            Material::Conductor(_)
            | Material::TexturedDiffuse { .. }
            | Material::ThinDielectric { .. }
            | Material::Plastic(_)
            | Material::Mask(_)
            | Material::TintedGlass(_) => Vec3::ZERO,
        };
        emitted + scattered
    }
    // ANCHOR_END: trace

    // ANCHOR: glossy
    /// A fuzzy mirror: the radiance leaving `hit` back along `ray` from the point lights'
    /// highlights ([`point_light_highlights`](crate::highlights::point_light_highlights)) and
    /// one ray into the lobe of the material's exponent around the mirror direction
    /// ([`spread`](Self::spread)), on the side the ray arrives from, about the shading normal
    /// `hit.shading_n` turned to that side. The back of a one-sided surface is black.
    ///
    /// The lobe is the material's own distribution of directions: sampling it, what is left
    /// to weight the ray's light by?
    fn glossy<S: Sampler>(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        glossy: &Glossy,
        depth: u32,
        sampler: &mut S,
    ) -> Vec3 {
        // BEGIN SOLUTION
        use crate::highlights::point_light_highlights;
        let normal = if hit.front_face(ray.dir) {
            hit.shading_n
        } else if glossy.two_sided {
            -hit.shading_n
        } else {
            return Vec3::ZERO; // the back of a one-sided surface is black
        };
        let lobe = Lobe {
            center: reflect(ray.dir, normal),
            exponent: glossy.exponent,
            side: normal,
            method: self.options.fuzz,
        };
        let highlights = point_light_highlights(self.world, hit, &lobe, ray.time);
        let spread = self.spread(ray, hit, &lobe, depth, sampler);
        glossy.reflectance * (highlights + spread)
        // END SOLUTION
    }
    // ANCHOR_END: glossy

    // ANCHOR: spread
    /// The radiance arriving at `hit` along one direction drawn from `lobe` (for the ray
    /// `ray`, segment `depth` of its path), the render's below-surface policy deciding what a
    /// direction on the wrong side becomes; 0 when the policy drops it. A smooth lobe (an
    /// infinite exponent) is its centre alone, and draws no numbers. The light is carried back
    /// by the path's next segment.
    ///
    /// Which ray carries that light back, from where, and at what time?
    pub fn spread<S: Sampler>(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        lobe: &Lobe,
        depth: u32,
        sampler: &mut S,
    ) -> Vec3 {
        // BEGIN SOLUTION
        let direction = if lobe.exponent.is_finite() {
            self.options.below.scatter(lobe.side, sampler, |u| {
                lobe.method.sample(lobe.center, lobe.exponent, u)
            })
        } else {
            Some(lobe.center) // smooth: the ideal direction itself, no numbers drawn
        };
        match direction {
            Some(direction) => {
                let next = hit.spawn_ray(direction, ray.time);
                self.trace(&next, depth + 1, sampler)
            }
            None => Vec3::ZERO,
        }
        // END SOLUTION
    }
    // ANCHOR_END: spread

    // ANCHOR: glass
    /// Glass, smooth (`exponent` infinite) or frosted: the radiance leaving `hit` back along
    /// `ray`, which the Fresnel equations split between a reflection lobe and a refraction
    /// lobe (that one of exponent [`transmission_exponent`]), each with the point lights'
    /// highlights ([`point_light_highlights`](crate::highlights::point_light_highlights)) and
    /// one ray spread into it ([`spread`](Self::spread)); the render's [`GlassStrategy`] says
    /// whether to follow both or one chosen at random (`choose_half`, `choose_fresnel`, with the
    /// sampler's next number). Following both draws no number for a choice. The surface's
    /// geometric normal `hit.n` separates the two sides.
    ///
    /// Which side of the surface is the ray on, and what does that change? What must a branch
    /// taken at random be weighted by, and what happens to radiance that crosses into another
    /// medium (chapter 01)?
    #[allow(clippy::too_many_arguments)]
    fn glass<S: Sampler>(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        int_ior: f32,
        ext_ior: f32,
        exponent: f32,
        depth: u32,
        sampler: &mut S,
    ) -> Vec3 {
        // BEGIN SOLUTION
        use crate::glass_choice::{choose_fresnel, choose_half};
        use crate::highlights::point_light_highlights;
        use ch01_whitted::optics::{fresnel_dielectric, refract};

        // The side the ray arrives on: the normal facing it, and the ratio of the indices.
        let (normal, eta) = if hit.front_face(ray.dir) {
            (hit.n, ext_ior / int_ior)
        } else {
            (-hit.n, int_ior / ext_ior)
        };
        let reflectance = fresnel_dielectric(-ray.dir.dot(normal), eta);
        let method = self.options.fuzz;
        let reflection = Lobe {
            center: reflect(ray.dir, normal),
            exponent,
            side: normal,
            method,
        };
        // `None` under total internal reflection, where the reflectance is 1.
        let refraction = refract(ray.dir, normal, eta).map(|center| Lobe {
            center,
            exponent: transmission_exponent(exponent, eta),
            side: -normal,
            method,
        });
        // The light of one branch, highlights of the point lights included.
        let branch = |lobe: &Lobe, sampler: &mut S| {
            point_light_highlights(self.world, hit, lobe, ray.time)
                + self.spread(ray, hit, lobe, depth, sampler)
        };
        match self.options.glass {
            GlassStrategy::Both => {
                let mut radiance = Vec3::ZERO;
                if reflectance > 0.0 {
                    radiance += reflectance * branch(&reflection, sampler);
                }
                if let Some(refraction) = refraction.filter(|_| reflectance < 1.0) {
                    // Written as chapter 01 writes it, so a smooth scene rounds the same way.
                    radiance += (1.0 - reflectance) * eta * eta * branch(&refraction, sampler);
                }
                radiance
            }
            strategy => {
                let u = sampler.get_1d();
                let choice = if strategy == GlassStrategy::Half {
                    choose_half(u, reflectance)
                } else {
                    choose_fresnel(u, reflectance)
                };
                if choice.weight == 0.0 {
                    return Vec3::ZERO; // a branch that carries no light: nothing to trace
                }
                if choice.reflect {
                    choice.weight * branch(&reflection, sampler)
                } else {
                    match refraction {
                        Some(refraction) => {
                            choice.weight * eta * eta * branch(&refraction, sampler)
                        }
                        None => Vec3::ZERO, // unreachable: no refraction means F = 1
                    }
                }
            }
        }
        // END SOLUTION
    }
    // ANCHOR_END: glass
}

/// The exponent of frosted glass's refraction lobe, from the exponent of its reflection lobe
/// and the relative index `eta = eta_i / eta_t`.
///
/// Roughness is a tilt of the surface's tiny facets. Tilting a facet by a small angle `δ`
/// turns the reflected ray by `2δ`, but the refracted ray only by about `|1 - eta| δ` (at
/// normal incidence): refraction is the less sensitive, and at `eta = 1` a rough boundary
/// between equal media bends no ray at all, so glass of index 1 vanishes however frosted.
/// A lobe's width goes as `1/√n`, so the refraction lobe's exponent is the reflection's
/// times `(2 / |1 - eta|)²`. For glass of index 1.5 in air that is 36 on the way in
/// (`eta = 1/1.5`, `|1 - eta| = 1/3`) but 16 on the way out (`eta = 1.5`, `|1 - eta| = 1/2`).
pub fn transmission_exponent(exponent: f32, eta: f32) -> f32 {
    let sensitivity = (1.0 - eta).abs() / 2.0;
    if sensitivity == 0.0 {
        return f32::INFINITY;
    }
    exponent / (sensitivity * sensitivity)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::highlights::point_light_highlights;
    use ch01_whitted::optics::fresnel_dielectric;
    use common::geometry::{Parallelogram, Shape, Sphere};
    use common::render::counting_rays;
    use common::sampler::IndependentSampler;
    use common::scene::{Camera, CameraFrame, FilmSettings, Material, PointLight, SceneBuilder};
    use glam::{Mat4, UVec2};

    const RED: Vec3 = Vec3::new(1.0, 0.0, 0.0);
    const BLUE: Vec3 = Vec3::new(0.0, 0.0, 1.0);

    /// Lights for the checks: the shapes listed glow with their radiance, seen from either
    /// side; matte surfaces reflect nothing.
    struct Glow(Vec<Vec3>);

    impl Lighting for Glow {
        fn emitted(&self, hit: &SurfaceHit, _ray: &Ray) -> Vec3 {
            self.0
                .get(hit.shape as usize)
                .copied()
                .unwrap_or(Vec3::ZERO)
        }

        fn matte<W: World, S: Sampler>(
            &self,
            _world: &W,
            _ray: &Ray,
            _hit: &SurfaceHit,
            _albedo: Vec3,
            _two_sided: bool,
            _sampler: &mut S,
        ) -> Vec3 {
            Vec3::ZERO
        }
    }

    /// A plane of `material` at y = 0 (normal +y) between a ceiling at y = 3 and a floor at
    /// y = -3 (shapes 1 and 2, black matte), with `more` builder steps, in a black world.
    fn between_ceiling_and_floor(
        material: Material,
        more: impl FnOnce(SceneBuilder) -> SceneBuilder,
    ) -> MotionScene {
        let plane = |y: f32, e1: Vec3, e2: Vec3| {
            Shape::Parallelogram(Parallelogram::new(Vec3::new(-50.0, y, -50.0), e1, e2))
        };
        let (x, z) = (100.0 * Vec3::X, 100.0 * Vec3::Z);
        let builder = SceneBuilder::new()
            .environment(Vec3::ZERO)
            .shape(plane(0.0, z, x), material)
            .shape(plane(3.0, x, z), Material::diffuse(Vec3::ZERO))
            .shape(plane(-3.0, z, x), Material::diffuse(Vec3::ZERO));
        let frame = CameraFrame::look_at(Vec3::new(0.0, 2.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap();
        // The shutter open from 0 to 1, so that the moving shapes are bounded over it.
        let camera = Camera {
            shutter_close: 1.0,
            ..Camera::pinhole(frame, 40.0)
        };
        let scene = more(builder).build(camera, FilmSettings::new(8, 8), 8);
        MotionScene::new(scene).unwrap()
    }

    /// A ray that meets the plane y = 0 at the origin at `degrees` from its normal, from above
    /// (`from_above`) or from below.
    fn towards_origin(degrees: f32, from_above: bool) -> Ray {
        let theta = degrees.to_radians();
        let sign = if from_above { -1.0 } else { 1.0 };
        let dir = Vec3::new(theta.sin(), sign * theta.cos(), 0.0);
        Ray::new(-dir / theta.cos(), dir)
    }

    /// The mean radiance along `ray` over `n` samples, with its standard error per channel,
    /// and whether some sample lit both red and blue.
    fn mean_of(
        world: &MotionScene,
        lighting: &Glow,
        options: TraceOptions,
        ray: &Ray,
        n: u64,
    ) -> (Vec3, Vec3, bool) {
        let tracer = Tracer {
            world,
            lighting,
            options,
        };
        let mut sampler = IndependentSampler::new(5);
        let (mut sum, mut sum2, mut both) = (glam::DVec3::ZERO, glam::DVec3::ZERO, false);
        for i in 0..n {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            let l = tracer.trace(ray, 1, &mut sampler);
            both |= l.x > 0.0 && l.z > 0.0;
            sum += l.as_dvec3();
            sum2 += l.as_dvec3() * l.as_dvec3();
        }
        let mean = sum / n as f64;
        let variance = (sum2 / n as f64 - mean * mean).max(glam::DVec3::ZERO);
        (
            mean.as_vec3(),
            (variance / n as f64).as_vec3().powf(0.5),
            both,
        )
    }

    fn options(glass: GlassStrategy) -> TraceOptions {
        TraceOptions {
            glass,
            ..TraceOptions::default()
        }
    }

    /// Whitted's radiance at the smooth glass plane of index 1.5: the reflected ray sees
    /// the side the ray came from, the refracted one the other.
    fn whitted(degrees: f32, from_above: bool) -> (Vec3, f32, f32) {
        let eta = if from_above { 1.0 / 1.5 } else { 1.5 };
        let f = fresnel_dielectric(degrees.to_radians().cos(), eta);
        let (near, far) = if from_above { (RED, BLUE) } else { (BLUE, RED) };
        (f * near + (1.0 - f) * eta * eta * far, f, eta)
    }

    /// Words for what `got` looks like, against Whitted's radiance for the ray.
    fn smooth_glass_mistake(got: Vec3, degrees: f32, from_above: bool) -> Option<String> {
        let (expected, f, eta) = whitted(degrees, from_above);
        let close = |a: Vec3| (got - a).abs().max_element() <= 2e-4;
        if close(expected) {
            return None;
        }
        let (near, far) = if from_above { (RED, BLUE) } else { (BLUE, RED) };
        let side = if from_above {
            "from the air"
        } else {
            "from inside the glass"
        };
        let why = if f >= 1.0 && got.dot(far) > 0.0 {
            "past the critical angle there is no refracted ray: all the light is reflected"
                .to_string()
        } else if close(f * near + (1.0 - f) * far) {
            format!(
                "the refracted light lacks the factor (eta_i / eta_t)^2 = {:.3}: radiance that \
                 crosses into another medium is squeezed into a narrower cone, or spread into \
                 a wider one",
                eta * eta
            )
        } else if close((1.0 - f) * near + f * eta * eta * far) {
            "the reflected and the refracted light have each other's Fresnel shares".to_string()
        } else if close(f * eta * eta * near + (1.0 - f) * eta * eta * far) {
            "the reflected light was scaled by (eta_i / eta_t)^2 too: only radiance that \
             crosses into the other medium changes its cone"
                .to_string()
        } else if from_above && close(f * near + (1.0 - f) / (eta * eta) * far) {
            "the ratio of the indices is upside down: refract and the factor (eta_i / eta_t)^2 \
             take the index on the ray's side over the index on the other side, ext_ior / \
             int_ior for a ray arriving from outside"
                .to_string()
        } else if !from_above {
            "from inside, the ray meets the back of the surface: the normal facing it is -n, \
             and the ratio of the indices is the other way up"
                .to_string()
        } else {
            "reflection and refraction should get their Fresnel shares F and 1 - F".to_string()
        };
        Some(format!(
            "a ray {side} at {degrees}° from the normal (Fresnel F = {f:.4}) should see \
             {expected} (the reflected ray sees {near}, the refracted one {far}), and yours \
             saw {got}: {why}"
        ))
    }

    /// A sampler that counts the numbers drawn from it.
    #[derive(Clone)]
    struct Counting {
        inner: IndependentSampler,
        drawn: u32,
    }

    impl Sampler for Counting {
        fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
            self.inner.start_pixel_sample(pixel, sample_index);
        }
        fn get_pixel_2d(&mut self) -> glam::Vec2 {
            self.inner.get_pixel_2d()
        }
        fn get_1d(&mut self) -> f32 {
            self.drawn += 1;
            self.inner.get_1d()
        }
    }

    /// The glossy floor of [`between_ceiling_and_floor`] with point lights at `lights`
    /// (intensity 1 each, in the red channel), a still ball hiding the last one from the
    /// origin, and a ball that moves between the first one and the origin at time 0.5 and
    /// stays there.
    fn floor_with_lights(lights: &[Vec3]) -> MotionScene {
        floor_of_with_lights(Material::glossy(Vec3::ONE, 20.0), lights)
    }

    /// [`floor_with_lights`] with a floor of `material`.
    fn floor_of_with_lights(material: Material, lights: &[Vec3]) -> MotionScene {
        floor_of_with_lights_seen_at(material, lights, Vec3::ZERO)
    }

    /// [`floor_of_with_lights`] with the balls halfway between the lights and the floor's
    /// point `at` instead of its origin.
    fn floor_of_with_lights_seen_at(material: Material, lights: &[Vec3], at: Vec3) -> MotionScene {
        let last = at + 0.5 * (lights[lights.len() - 1] - at);
        let first = at + 0.5 * (lights[0] - at);
        let ball = |at: Vec3| Shape::Sphere(Sphere::new(at, 0.04));
        let lights = lights.to_vec();
        between_ceiling_and_floor(material, move |b| {
            let b = lights.iter().fold(b, |b, &position| {
                b.light(PointLight {
                    position,
                    intensity: Vec3::new(1.0, 0.0, 0.0),
                })
            });
            b.shape(ball(last), Material::diffuse(Vec3::ZERO)).moving(
                ball(Vec3::ZERO),
                vec![
                    (0.0, Mat4::from_translation(Vec3::new(40.0, 1.0, 0.0))),
                    (0.5, Mat4::from_translation(first)),
                    (1.0, Mat4::from_translation(first)),
                ],
                Material::diffuse(Vec3::ZERO),
            )
        })
    }

    /// For each light of [`exercise_highlights_add_each_light_the_lobe_sees`], per method
    /// (lobe, disc): the red light the floor's lobe sends back from it (intensity 1); the same
    /// with the lobe's density taken at the angle from the normal; and with the light seen from
    /// the scene's origin instead of the hit point. Worked out beforehand from the highlight
    /// the exercise derives, to 8 digits; a light the lobe cannot reflect gives 0.
    const HIGHLIGHT_TERMS: [[[f32; 3]; 5]; 2] = [
        [
            [2.066649e-1, 2.878977e-4, 2.132706e-1],
            [8.355635e-1, 4.046319e-3, 4.441542e-1],
            [2.005664e-3, 1.149003e-9, 6.187571e-4],
            [0.0, 0.0, 5.365881e-23],
            [6.887929e-1, 1.354097e-2, 1.955808e-1],
        ],
        [
            [2.220522e-1, 0.0, 1.857953e-1],
            [4.575705e-1, 0.0, 3.656879e-1],
            [0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0],
            [9.128527e-1, 0.0, 0.0],
        ],
    ];

    #[test]
    fn exercise_highlights_add_each_light_the_lobe_sees() {
        // Lights around the mirror direction of a ray at 40° that meets the floor at `seen`,
        // off its origin (the first light hidden at time 0.8 by the moving ball, the last
        // always by the still one), one below the floor. They are red: intensity (1, 0, 0).
        let seen = Vec3::new(0.4, 0.0, -0.3);
        let ray = Ray {
            origin: seen + towards_origin(40.0, true).origin,
            ..towards_origin(40.0, true)
        };
        let mirror = reflect(ray.dir, Vec3::Y);
        let lights = [
            3.0 * (mirror + Vec3::new(0.1, 0.0, 0.25)).normalize(),
            2.0 * mirror,
            Vec3::new(2.0, 1.0, -1.5),
            Vec3::new(1.0, -1.0, 0.0),
            1.5 * (mirror + Vec3::new(0.0, 0.15, -0.3)).normalize(),
        ]
        .map(|offset| seen + offset);
        let world = floor_of_with_lights_seen_at(Material::glossy(Vec3::ONE, 20.0), &lights, seen);
        let hit = world.intersect(&ray).expect("the ray meets the floor");
        assert!(
            (hit.p - seen).length() < 1e-5,
            "the floor at {seen}: {hit:?}"
        );
        for method in [FuzzMethod::Lobe, FuzzMethod::Disc] {
            for time in [0.2f32, 0.8] {
                let lobe = Lobe {
                    center: mirror,
                    exponent: 20.0,
                    side: Vec3::Y,
                    method,
                };
                let (got_rgb, rays) =
                    counting_rays(|| point_light_highlights(&world, &hit, &lobe, time));
                let got = got_rgb.x;
                // The lobe's density towards the light at `at`.
                let density = |at: Vec3| method.pdf((at - seen).normalize().dot(mirror), 20.0);
                let terms = &HIGHLIGHT_TERMS[match method {
                    FuzzMethod::Lobe => 0,
                    FuzzMethod::Disc => 1,
                }];
                let sum = |column: usize, which: &[usize]| -> f32 {
                    which.iter().map(|&i| terms[i][column]).sum()
                };
                // At time 0.2 the moving ball is still far off.
                let above: Vec<usize> = (0..lights.len()).filter(|&i| lights[i].y > 0.0).collect();
                let visible: Vec<usize> = above
                    .iter()
                    .copied()
                    .filter(|&i| i != lights.len() - 1 && (i != 0 || time < 0.5))
                    .collect();
                let expected = sum(0, &visible);
                let at = format!(
                    "point_light_highlights: a glossy floor's {method:?} lobe of exponent 20 \
                     around the mirror direction {mirror} at {seen}, at time {time}, with five \
                     red lights of intensity (1, 0, 0) (one below the floor, one always hidden \
                     by a ball, one hidden by a moving ball from time 0.5 on)"
                );
                if (got - expected).abs() > 1e-3 * expected.max(1e-3) {
                    let all_above = sum(0, &above);
                    let unblocked_now = expected + if time > 0.5 { terms[0][0] } else { 0.0 };
                    let no_falloff: f32 = visible.iter().map(|&i| density(lights[i])).sum();
                    let around_normal = sum(1, &visible);
                    let from_origin = sum(2, &visible);
                    let why = if got == 0.0 {
                        "no light got through: does each shadow ray stop at its light? One that \
                         goes on past the light meets whatever lies behind it (here a ceiling)"
                            .to_string()
                    } else if (got - from_origin).abs() <= 1e-3 * from_origin {
                        "the lights were seen from the scene's origin: the direction and the \
                         distance to a light are measured from the hit point, hit.p"
                            .to_string()
                    } else if (got - around_normal).abs() <= 1e-3 * around_normal {
                        "the density was taken at the angle from the surface's normal; the lobe \
                         is centred on its mirror direction, lobe.center"
                            .to_string()
                    } else if (got - all_above).abs() <= 1e-3 * all_above {
                        "a light hidden by another object shows no highlight: is a shadow ray \
                         traced to each light?"
                            .to_string()
                    } else if (got - unblocked_now).abs() <= 1e-3 * unblocked_now {
                        "the moving ball hides the first light at the ray's time; the shadow \
                         ray lost the ray's shutter time"
                            .to_string()
                    } else if (got - no_falloff).abs() <= 1e-3 * no_falloff {
                        "the light a point light sends falls off with the square of the distance"
                            .to_string()
                    } else if got > expected {
                        "a light below the surface cannot be seen in it".to_string()
                    } else {
                        "how much of each light's intensity arrives, and what share of it does \
                         the lobe send back along the ray?"
                            .to_string()
                    };
                    panic!("{at} should show {expected} in red, and yours gave {got}: {why}");
                }
                assert!(
                    got_rgb.y == 0.0 && got_rgb.z == 0.0,
                    "{at} should show no green or blue, and yours gave {got_rgb}: a highlight is \
                     the light's own intensity, colour and all, times what the lobe sends back"
                );
                let shadow_rays = lights
                    .iter()
                    .filter(|&&at| at.y > 0.0 && density(at) > 0.0)
                    .count() as u64;
                assert!(
                    rays == shadow_rays,
                    "{at} traced {rays} ray(s), and {shadow_rays} shadow rays are needed: one per \
                     light above the surface that the lobe can reflect (none for a light \
                     outside the lobe)"
                );
            }
        }
    }

    #[test]
    fn exercise_highlights_never_from_below_the_surface() {
        // A grazing ray: its lobe reaches below the floor, where a light shines up at the
        // floor's underside.
        let ray = towards_origin(80.0, true);
        let mirror = reflect(ray.dir, Vec3::Y);
        let above = 3.0 * (mirror + Vec3::new(0.0, 0.2, 0.0)).normalize();
        let below = Vec3::new(2.0, -0.1, 0.0);
        let world = floor_with_lights(&[above, below, Vec3::new(0.0, 5.0, -40.0)]);
        let hit = world.intersect(&ray).expect("the ray meets the floor");
        let lobe = Lobe {
            center: mirror,
            exponent: 20.0,
            side: Vec3::Y,
            method: FuzzMethod::Lobe,
        };
        // Worked out beforehand from the highlight the exercise derives, to 7 digits: what the
        // light above sends back, and what the one below would if it were counted.
        let (expected, from_below) = (2.601_479e-1f32, 5.013_752e-1f32);
        let got = point_light_highlights(&world, &hit, &lobe, 0.2).x;
        assert!(
            (got - expected).abs() <= 1e-3 * expected,
            "point_light_highlights: a lobe around the grazing mirror direction {mirror}, a light \
             above the floor and one just below it (inside the lobe's cone, but under the \
             surface), should show {expected}, and yours gave {got}{}",
            if (got - expected - from_below).abs() <= 1e-3 * got {
                ": a light below the surface cannot be seen in it"
            } else if got == 0.0 {
                ": no light got through; does each shadow ray stop at its light?"
            } else {
                ""
            }
        );
    }

    #[test]
    fn exercise_highlights_none_in_a_mirror() {
        let ray = towards_origin(40.0, true);
        let mirror = reflect(ray.dir, Vec3::Y);
        let world = floor_with_lights(&[2.0 * mirror, Vec3::new(0.0, 2.0, 1.0)]);
        let hit = world.intersect(&ray).expect("the ray meets the floor");
        let lobe = Lobe {
            center: mirror,
            exponent: f32::INFINITY,
            side: Vec3::Y,
            method: FuzzMethod::Lobe,
        };
        let (got, rays) = counting_rays(|| point_light_highlights(&world, &hit, &lobe, 0.2));
        assert!(
            got == Vec3::ZERO && rays == 0,
            "point_light_highlights: a smooth lobe (an infinite exponent) is a mirror, which \
             shows no point light however well placed, and needs no shadow ray; yours gave \
             {got} and traced {rays} ray(s)"
        );
    }

    /// A glossy floor of `reflectance`, `exponent` and sides, between the red ceiling and the
    /// blue floor below it, seen at `degrees` from above or from below.
    fn glossy_sees(
        reflectance: f32,
        exponent: f32,
        two_sided: bool,
        degrees: f32,
        from_above: bool,
    ) -> Vec3 {
        let material = Material::Glossy(Glossy {
            reflectance: Vec3::splat(reflectance),
            exponent,
            two_sided,
            stands_in_for: None,
        });
        let world = between_ceiling_and_floor(material, |b| b);
        let lighting = Glow(vec![Vec3::ZERO, RED, BLUE]);
        let ray = towards_origin(degrees, from_above);
        mean_of(&world, &lighting, TraceOptions::default(), &ray, 50).0
    }

    #[test]
    fn exercise_glossy_reflects_its_share_on_its_side() {
        for (exponent, degrees) in [(f32::INFINITY, 30.0), (200.0, 30.0), (200.0, 60.0)] {
            let got = glossy_sees(0.5, exponent, false, degrees, true);
            assert!(
                got.abs_diff_eq(0.5 * RED, 1e-4),
                "glossy: a fuzzy mirror of reflectance 0.5 and exponent {exponent} under a \
                 ceiling glowing {RED}, seen from above at {degrees}°, should show {}, and yours \
                 showed {got}: {}",
                0.5 * RED,
                if got.abs_diff_eq(RED, 1e-4) {
                    "twice too bright: a ray drawn from the material's own lobe still carries \
                     only the material's share of the light"
                } else if got.x < 0.25 {
                    "is the lobe centred on the mirror direction, on the side the ray comes from?"
                } else {
                    "the ceiling fills the whole lobe, so every ray sees it"
                }
            );
        }
        let got = glossy_sees(0.5, 200.0, false, 30.0, false);
        assert!(
            got == Vec3::ZERO,
            "glossy: a one-sided fuzzy mirror seen from behind should be black, and yours \
             showed {got}"
        );
        let got = glossy_sees(0.5, 200.0, true, 30.0, false);
        assert!(
            got.abs_diff_eq(0.5 * BLUE, 1e-4),
            "glossy: a two-sided fuzzy mirror seen from below should reflect the glowing floor \
             below it, {}, and yours showed {got}: from behind, the normal facing the ray is -n",
            0.5 * BLUE
        );
    }

    #[test]
    fn exercise_glossy_shows_the_lights_it_sees_at_the_rays_time() {
        // The floor of exponent 20 of the highlights check, of reflectance 0.5: at time 0.8 the
        // moving ball hides the first light.
        let ray = towards_origin(40.0, true).with_time(0.8);
        let mirror = reflect(ray.dir, Vec3::Y);
        let lights = [
            3.0 * (mirror + Vec3::new(0.1, 0.0, 0.25)).normalize(),
            2.0 * mirror,
        ];
        let world = floor_of_with_lights(
            Material::glossy(Vec3::splat(0.5), 20.0),
            &[lights[0], lights[1], Vec3::new(0.0, 5.0, 40.0)],
        );
        // The highlights are chapter 06's own (its highlights exercise), at the ray's time and
        // at a time when the moving ball is still far off, and for a lobe around the normal.
        let hit = world.intersect(&ray).expect("the ray meets the floor");
        let highlights = |center: Vec3, time: f32| {
            let lobe = Lobe {
                center,
                exponent: 20.0,
                side: Vec3::Y,
                method: FuzzMethod::Lobe,
            };
            point_light_highlights(&world, &hit, &lobe, time).x
        };
        let expected = 0.5 * highlights(mirror, 0.8);
        let unhidden = 0.5 * highlights(mirror, 0.2);
        let around_normal = 0.5 * highlights(Vec3::Y, 0.8);
        // The spread rays find the black ceiling: only the highlights remain.
        let (got, _, _) = mean_of(&world, &Glow(Vec::new()), TraceOptions::default(), &ray, 20);
        assert!(
            (got.x - expected).abs() <= 1e-3 * expected,
            "glossy: a fuzzy mirror of exponent 20 and reflectance 0.5 at time 0.8, with a light \
             near its mirror direction and another hidden at that time by a moving ball, should \
             show the highlight {expected}, and yours showed {}: {}",
            got.x,
            if (got.x - 2.0 * expected).abs() <= 1e-3 * expected {
                "the highlight is not weighted by the reflectance: the material reflects only \
                 its share of the light arriving from the lamp too"
            } else if (got.x - unhidden).abs() <= 1e-3 * expected {
                "the hidden light shows: the highlights' shadow rays lost the ray's shutter time"
            } else if (got.x - around_normal).abs() <= 1e-3 * around_normal {
                "is the lobe centred on the mirror direction? Yours is centred on the normal"
            } else if got.x == 0.0 {
                "a fuzzy mirror shows the point lights its lobe sees, as highlights"
            } else {
                "a fuzzy mirror shows the highlights its lobe finds, as much of them as the \
                 material reflects"
            }
        );
    }

    /// The radiance `spread` brings back to where `ray` meets `world`, from a lobe around the
    /// mirror direction of a floor of normal +y, averaged over `n` samples, with its standard
    /// error and the numbers drawn from the sampler.
    fn spread_from_floor<L: Lighting>(
        world: &MotionScene,
        lighting: &L,
        options: TraceOptions,
        ray: &Ray,
        exponent: f32,
        n: u64,
    ) -> (f64, f64, u32) {
        let tracer = Tracer {
            world,
            lighting,
            options,
        };
        let hit = world.intersect(ray).expect("the ray meets the floor");
        let lobe = Lobe {
            center: reflect(ray.dir, Vec3::Y),
            exponent,
            side: Vec3::Y,
            method: FuzzMethod::Lobe,
        };
        let mut sampler = Counting {
            inner: IndependentSampler::new(3),
            drawn: 0,
        };
        let (mut sum, mut sum2) = (0.0f64, 0.0f64);
        for i in 0..n {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            let l = tracer.spread(ray, &hit, &lobe, 1, &mut sampler);
            let x = f64::from(l.element_sum());
            sum += x;
            sum2 += x * x;
        }
        let mean = sum / n as f64;
        let variance = (sum2 / n as f64 - mean * mean).max(0.0);
        (mean, (variance / n as f64).sqrt(), sampler.drawn)
    }

    #[test]
    fn exercise_spread_keeps_the_rays_shutter_time() {
        // A glowing ball over the floor's mirror direction from time 0.5 on, far away before.
        let ball = Shape::Sphere(Sphere::new(Vec3::ZERO, 0.5));
        let far = Mat4::from_translation(Vec3::new(40.0, 1.5, 0.0));
        let there = Mat4::from_translation(Vec3::new(1.5, 1.5, 0.0));
        let lighting = Glow(vec![Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::Y]);
        let world = between_ceiling_and_floor(Material::diffuse(Vec3::ZERO), |b| {
            b.moving(
                ball,
                vec![(0.0, far), (0.5, there), (1.0, there)],
                Material::diffuse(Vec3::ZERO),
            )
        });
        let ray = towards_origin(45.0, true).with_time(0.8);
        for exponent in [f32::INFINITY, 1e6] {
            let (got, _, _) = spread_from_floor(
                &world,
                &lighting,
                TraceOptions::default(),
                &ray,
                exponent,
                20,
            );
            assert!(
                (got - 1.0).abs() < 1e-4,
                "spread: a lobe of exponent {exponent} around a floor's mirror direction, which \
                 meets a ball glowing 1 at the camera ray's time 0.8 (and misses it at time 0), \
                 should bring back 1, and yours brought {got}{}",
                if got == 0.0 {
                    ": the spread ray lost the ray's shutter time; every ray of a path sees the \
                     world at the camera ray's instant"
                } else {
                    ""
                }
            );
        }
    }

    #[test]
    fn exercise_spread_draws_nothing_for_a_smooth_lobe() {
        let world = between_ceiling_and_floor(Material::diffuse(Vec3::ZERO), |b| b);
        let lighting = Glow(vec![Vec3::ZERO, RED, BLUE]);
        let ray = towards_origin(30.0, true);
        let options = TraceOptions::default();
        let (got, _, drawn) = spread_from_floor(&world, &lighting, options, &ray, f32::INFINITY, 1);
        assert!(
            (got - 1.0).abs() < 1e-5 && drawn == 0,
            "spread: a smooth lobe (an infinite exponent) around a floor's mirror direction \
             should bring back the ceiling's {RED} exactly, drawing no numbers, and yours \
             brought {got} (summed over the channels) and drew {drawn}: a smooth lobe is its \
             centre alone, and a number drawn for it shifts every later dimension"
        );
    }

    #[test]
    fn exercise_spread_is_the_next_segment_of_the_path() {
        // The plane at y = 0 glows blue; a mirror ceiling sends its smooth lobe's ray back down
        // to it. With at most 2 segments, the spread ray (segment 2) is the last: it finds what
        // the mirror emits (nothing), and no third segment brings the blue back.
        let plane = |y: f32, e1: Vec3, e2: Vec3| {
            Shape::Parallelogram(Parallelogram::new(Vec3::new(-50.0, y, -50.0), e1, e2))
        };
        let (x, z) = (100.0 * Vec3::X, 100.0 * Vec3::Z);
        let frame = CameraFrame::look_at(Vec3::new(0.0, 2.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap();
        let scene = SceneBuilder::new()
            .environment(Vec3::ZERO)
            .shape(plane(0.0, z, x), Material::diffuse(Vec3::ZERO))
            .shape(
                plane(3.0, x, z),
                Material::Mirror {
                    reflectance: Vec3::ONE,
                },
            )
            .build(Camera::pinhole(frame, 40.0), FilmSettings::new(8, 8), 2);
        let world = MotionScene::still(scene);
        let lighting = Glow(vec![BLUE]);
        let ray = towards_origin(30.0, true);
        let options = TraceOptions::default();
        let (got, _, _) = spread_from_floor(&world, &lighting, options, &ray, f32::INFINITY, 1);
        assert!(
            got == 0.0,
            "spread: at most 2 segments per path, a smooth lobe from a glowing plane (the \
             camera ray, segment 1, met it) towards a mirror ceiling that sends it back down \
             should bring back nothing: the spread ray is segment 2, the last, and finds only \
             what the mirror emits. Yours brought back {got} (summed over the channels): is \
             the spread ray traced as the next segment of the path, depth + 1?"
        );
    }

    #[test]
    fn exercise_spread_follows_the_below_surface_policy() {
        // A floor in a world that glows 1 everywhere, met at 80° from the normal: much of a
        // lobe of exponent 1 around the mirror direction is below the floor.
        let floor = Parallelogram::new(Vec3::new(-1e3, 0.0, -1e3), 2e3 * Vec3::Z, 2e3 * Vec3::X);
        let world = crate::furnace::scene_of(
            vec![(Shape::Parallelogram(floor), Material::diffuse(Vec3::ZERO))],
            Vec3::splat(1.0 / 3.0),
            Vec3::new(0.0, 2.0, 5.0),
            Vec3::ZERO,
            4,
        );
        let ray = crate::furnace::incoming(80.0);
        for below in BelowSurface::ALL {
            let options = TraceOptions {
                below,
                ..TraceOptions::default()
            };
            let (mean, se, _) = spread_from_floor(
                &world,
                &crate::lighting::PointLights,
                options,
                &ray,
                1.0,
                2000,
            );
            let keeps_energy = below != BelowSurface::Drop;
            let ok = if keeps_energy {
                (mean - 1.0).abs() <= 5.0 * se + 1e-6
            } else {
                mean < 0.9
            };
            assert!(
                ok,
                "spread: a lobe of exponent 1 around a floor's mirror direction at 80° from the \
                 normal, in a world that glows 1 everywhere, with the {below:?} policy brings \
                 back {mean:.3} (± {se:.3}): {}",
                if keeps_energy {
                    "this policy never loses a sample, so 1 should come back; is the render's \
                     below-surface policy (self.options.below) the one used?"
                } else {
                    "dropping the directions below the surface loses part of the lobe, so well \
                     under 1 should come back; a direction below that is kept leaks light \
                     through the surface"
                }
            );
        }
    }

    #[test]
    fn exercise_glass_following_both_rays_is_whitted() {
        let world = between_ceiling_and_floor(Material::glass(1.5), |b| b);
        let lighting = Glow(vec![Vec3::ZERO, RED, BLUE]);
        for (degrees, from_above) in [
            (0.0, true),
            (45.0, true),
            (80.0, true),
            (20.0, false),
            (35.0, false),
            (60.0, false),
        ] {
            let ray = towards_origin(degrees, from_above);
            let (got, _, _) = mean_of(&world, &lighting, options(GlassStrategy::Both), &ray, 1);
            if let Some(mistake) = smooth_glass_mistake(got, degrees, from_above) {
                panic!("glass, following both rays: {mistake}");
            }
        }
        // Nothing to choose and nothing to spread: no number is drawn.
        let tracer = Tracer {
            world: &world,
            lighting: &lighting,
            options: options(GlassStrategy::Both),
        };
        let mut sampler = Counting {
            inner: IndependentSampler::new(5),
            drawn: 0,
        };
        sampler.start_pixel_sample(UVec2::ZERO, 0);
        let ray = towards_origin(45.0, true);
        tracer.trace(&ray, 1, &mut sampler);
        assert!(
            sampler.drawn == 0,
            "glass, following both rays: smooth glass drew {} number(s) from the sampler; \
             following both rays chooses nothing, and a smooth lobe spreads nothing, so no \
             number is drawn (one drawn shifts every later dimension of the sample)",
            sampler.drawn
        );
    }

    #[test]
    fn exercise_glass_one_ray_chosen_at_random_is_unbiased() {
        let world = between_ceiling_and_floor(Material::glass(1.5), |b| b);
        let lighting = Glow(vec![Vec3::ZERO, RED, BLUE]);
        for strategy in [GlassStrategy::Half, GlassStrategy::Fresnel] {
            for (degrees, from_above) in [(45.0, true), (75.0, true), (30.0, false)] {
                let ray = towards_origin(degrees, from_above);
                let (mean, se, both) = mean_of(&world, &lighting, options(strategy), &ray, 4000);
                let (expected, f, eta) = whitted(degrees, from_above);
                let at = format!(
                    "glass, one ray chosen by {strategy:?}: a ray {} at {degrees}° (Fresnel F = \
                     {f:.4})",
                    if from_above {
                        "from the air"
                    } else {
                        "from inside"
                    }
                );
                assert!(
                    !both,
                    "{at} lit some samples both red and blue: with this strategy one ray is \
                     followed, either the reflected or the refracted one"
                );
                let within = |a: Vec3| ((mean - a).abs() - 5.0 * se).max_element() <= 1e-6;
                if within(expected) {
                    continue;
                }
                let (near, far) = if from_above { (RED, BLUE) } else { (BLUE, RED) };
                let why = if within(0.5 * expected) {
                    "half of it: a branch taken only half the time has to count for more when \
                     it is taken"
                } else if within(0.5 * near + 0.5 * eta * eta * far) {
                    "the chosen branch's light was not weighted: each branch is taken with \
                     some probability, and its light has to be weighted both for that chance and \
                     for its Fresnel share"
                } else if within(f * f * near + (1.0 - f) * (1.0 - f) * eta * eta * far) {
                    "the Fresnel share was applied twice: the choice's weight already holds the \
                     branch's share, divided by the probability of choosing it"
                } else {
                    "the probability of taking a branch and its weight do not match: on \
                     average the two branches have to give Whitted's F L_r + (1 - F) L_t"
                };
                panic!(
                    "{at} should see {expected} on average, and yours saw {mean} (± {se} \
                     standard error): biased, {why}"
                );
            }
        }
    }

    #[test]
    fn exercise_glass_frosted_shows_highlights_through_both_lobes() {
        // Frosted glass between two point lights; nothing glows and the world is black, so all
        // the light is the two highlights (following both rays makes it exact).
        let above = Vec3::new(1.5, 1.2, 0.3);
        let below = Vec3::new(0.4, -2.0, -0.2);
        let world = between_ceiling_and_floor(Material::rough_glass(1.5, 30.0), |b| {
            b.light(PointLight {
                position: above,
                intensity: Vec3::new(5.0, 0.0, 0.0),
            })
            .light(PointLight {
                position: below,
                intensity: Vec3::new(0.0, 0.0, 5.0),
            })
        });
        let lighting = Glow(vec![Vec3::ZERO; 3]);
        for (degrees, from_above) in [(30.0, true), (20.0, false)] {
            let ray = towards_origin(degrees, from_above);
            let (got, _, _) = mean_of(&world, &lighting, options(GlassStrategy::Both), &ray, 1);
            let (_, f, eta) = whitted(degrees, from_above);
            let normal = if from_above { Vec3::Y } else { -Vec3::Y };
            let mirror = reflect(ray.dir, normal);
            let refracted = ch01_whitted::optics::refract(ray.dir, normal, eta).unwrap();
            // Each lobe's highlights are chapter 06's own (its highlights exercise): one light
            // on each side, each of one colour, so the channels add up to its highlight.
            let hit = world.intersect(&ray).expect("the ray meets the glass");
            let highlight = |center: Vec3, exponent: f32, side: Vec3| {
                let lobe = Lobe {
                    center,
                    exponent,
                    side,
                    method: FuzzMethod::Lobe,
                };
                point_light_highlights(&world, &hit, &lobe, ray.time).element_sum()
            };
            let reflected = f * highlight(mirror, 30.0, normal);
            let exponent = transmission_exponent(30.0, eta);
            let transmitted = (1.0 - f) * eta * eta * highlight(refracted, exponent, -normal);
            let (reflected_got, transmitted_got) = if from_above {
                (got.x, got.z)
            } else {
                (got.z, got.x)
            };
            let at = format!(
                "frosted glass (exponent 30), a ray {} at {degrees}°, a point light on each side",
                if from_above {
                    "from the air"
                } else {
                    "from inside"
                }
            );
            let near_enough = |a: f32, b: f32| (a - b).abs() <= 1e-3 * b.abs().max(1e-3);
            assert!(
                near_enough(reflected_got, reflected),
                "{at}: the light on the ray's side should show as a highlight of {reflected} \
                 through the reflection lobe (times F = {f:.4}), and yours gave {reflected_got}{}",
                if reflected_got == 0.0 {
                    ": are the point lights' highlights added to each branch?"
                } else {
                    ""
                }
            );
            if !near_enough(transmitted_got, transmitted) {
                let with_reflection_exponent =
                    (1.0 - f) * eta * eta * highlight(refracted, 30.0, -normal);
                panic!(
                    "{at}: the light on the other side should show as a highlight of \
                     {transmitted} through the refraction lobe, and yours gave \
                     {transmitted_got}{}",
                    if near_enough(transmitted_got, with_reflection_exponent) {
                        ": the refraction lobe has the reflection's exponent; refraction is \
                         less sensitive to the surface's roughness (transmission_exponent)"
                    } else if transmitted_got == 0.0 {
                        ": are the point lights' highlights added to each branch?"
                    } else {
                        ""
                    }
                );
            }
        }
    }

    #[test]
    fn exercise_glass_frosted_shows_the_lights_it_sees_at_the_rays_time() {
        // Frosted glass with two lights near its mirror direction, the first hidden by a
        // moving ball from time 0.5 on; the spread rays find a black world.
        let ray = towards_origin(40.0, true).with_time(0.8);
        let mirror = reflect(ray.dir, Vec3::Y);
        let lights = [
            3.0 * (mirror + Vec3::new(0.1, 0.0, 0.25)).normalize(),
            2.0 * mirror,
        ];
        let glass = Material::rough_glass(1.5, 20.0);
        let world = floor_of_with_lights(glass, &[lights[0], lights[1], Vec3::new(0.0, 5.0, 40.0)]);
        let (_, f, _) = whitted(40.0, true);
        // The highlights are chapter 06's own (its highlights exercise), at the ray's time and
        // at a time when the moving ball is still far off.
        let hit = world.intersect(&ray).expect("the ray meets the glass");
        let highlights = |time: f32| {
            let lobe = Lobe {
                center: mirror,
                exponent: 20.0,
                side: Vec3::Y,
                method: FuzzMethod::Lobe,
            };
            f * point_light_highlights(&world, &hit, &lobe, time).x
        };
        let expected = highlights(0.8);
        let (got, _, _) = mean_of(
            &world,
            &Glow(Vec::new()),
            options(GlassStrategy::Both),
            &ray,
            5,
        );
        assert!(
            (got.x - expected).abs() <= 1e-3 * expected,
            "glass: frosted glass (exponent 20) at time 0.8, following both rays, with a light \
             near its mirror direction and another hidden at that time by a moving ball, should \
             show the highlight {expected} (times F = {f:.4}), and yours showed {}{}",
            got.x,
            if (got.x - highlights(0.2)).abs() <= 1e-3 * expected {
                ": the hidden light shows; the highlights' shadow rays lost the ray's shutter time"
            } else {
                ""
            }
        );
    }

    #[test]
    fn exercise_glass_frosted_spreads_its_rays() {
        // A red strip on the ceiling where the smooth mirror ray lands, and a green one beside
        // it: frosted glass sees both, smooth glass the red one only.
        let strip = |x0: f32, width: f32| {
            Shape::Parallelogram(Parallelogram::new(
                Vec3::new(x0, 2.9, -50.0),
                width * Vec3::X,
                100.0 * Vec3::Z,
            ))
        };
        let green = Vec3::new(0.0, 1.0, 0.0);
        let lighting = Glow(vec![Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, RED, green]);
        let ray = towards_origin(45.0, true);
        for (exponent, spreads) in [(f32::INFINITY, false), (40.0, true)] {
            let world = between_ceiling_and_floor(Material::rough_glass(1.5, exponent), |b| {
                b.shape(strip(2.6, 0.6), Material::diffuse(Vec3::ZERO))
                    .shape(strip(3.2, 5.0), Material::diffuse(Vec3::ZERO))
            });
            let (mean, _, _) = mean_of(
                &world,
                &lighting,
                options(GlassStrategy::Fresnel),
                &ray,
                2000,
            );
            let saw_green = mean.y > 0.0;
            assert!(
                saw_green == spreads,
                "glass with exponent {exponent}, a ray from the air at 45°: {}",
                if spreads {
                    "frosted glass never reflected a ray beside the mirror direction: each \
                     branch spreads its ray into its lobe"
                } else {
                    "smooth glass reflected rays beside the mirror direction: an infinite \
                     exponent is the mirror itself"
                }
            );
        }
    }

    #[test]
    fn refraction_lobes_are_narrower_and_vanish_at_index_one() {
        assert_eq!(transmission_exponent(10.0, 1.0), f32::INFINITY);
        approx::assert_relative_eq!(
            transmission_exponent(10.0, 1.0 / 1.5),
            360.0,
            max_relative = 1e-5
        );
        approx::assert_relative_eq!(transmission_exponent(10.0, 1.5), 160.0, max_relative = 1e-5);
        assert_eq!(transmission_exponent(0.0, 1.5), 0.0);
    }
}
