//! Every light of a scene, for next-event estimation: the area lights (chapter 07), the point
//! lights (chapter 01) and the environment (the scene's background: a constant radiance, an
//! image around the scene, or both; [`EnvironmentLight`]).
//!
//! The two kinds are treated differently. A point light is a delta: no BSDF sample can find
//! it and there is no point on it to choose, so next-event estimation connects **every**
//! point light through its own shadow ray, as chapters 01 to 07 do
//! ([`crate::nee::point_lights`]), and draws no number for it; so is a directional light
//! ([`crate::nee::directional_lights`]), a delta in direction. The lights a ray *can* find,
//! the area lights and the environment, are *sampled*: one of them is **picked uniformly**
//! and divided by the chance `1/N`, so a bounce sends one shadow ray to them whatever their
//! number, which keeps a path a path. (Sampling every one would make each bounce cost `N`
//! shadow rays; picking by power would favour bright lights.)
//!
//! What is picked is an *emitter*: a glowing shape of the scene, whole. A mesh's triangles or
//! a cube's faces are area lights of their own here, but together one emitter, picked with
//! the chance `1/N` of any other, and then one of its pieces by area
//! ([`SceneLights::pick`]), so that a point on it is uniform over the whole shape, as in
//! Mitsuba 3. Picking among the pieces would give a lamp modelled as a thousand triangles a
//! thousand times the samples of a small sphere beside it.
//!
//! Mitsuba 3's `path` integrator picks uniformly among *all* its emitters, point lights
//! included. The expected image is the same; ours is less noisy where a scene has point
//! lights, and a scene without area lights or environment pays for no pick and no light
//! sample at all.
//!
//! An area light's radiance may be a texture (Mitsuba's `<texture name="radiance">`): then
//! what it sends depends on the point, read at the point's surface parameters both where a
//! ray hits the light ([`SceneLights::emitted`]) and at the point a light sample picks. On a
//! parallelogram (a panel, a window, a screen) the point is picked where the texture is
//! bright (`Scene::emission_grid`), as Mitsuba 3 picks it by the texture: a panel with a few
//! bright spots would otherwise spend most samples on its dark parts. On other shapes it is
//! still picked by area (or, on a sphere, by solid angle): the same mean, more noise where
//! the texture has bright spots.

use crate::environment::EnvironmentLight;
use ch05_motion_blur::MotionScene;
use ch07_soft_shadows::area_lights::LightShape;
use ch07_soft_shadows::area_sampling::parallelogram_point_error;
use ch07_soft_shadows::light_sample::LightSample;
use ch07_soft_shadows::solid_angle::{pdf_area_to_solid_angle, sphere_solid_angle_pdf};
use ch07_soft_shadows::{AreaLight, AreaLights, LightSampling, Strategy};
use common::Ray;
use common::geometry::{Parallelogram, SurfaceHit};
#[cfg(test)]
use common::scene::luminance;
use common::scene::{AreaEmitter, DirectionalLight, GridDistribution, PointLight, Scene};
use glam::{Vec2, Vec3};
use std::ops::Range;

/// One of the lights a light sample picks from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightRef {
    /// An area light, by its index in the scene's list.
    Area(usize),
    /// The environment: constant, an image, or both.
    Environment,
}

/// A light sampled from a receiver: where the light comes from and how much.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightDirection {
    /// The unit direction from the receiver to the light.
    pub wi: Vec3,
    /// The radiance arriving along `wi` if nothing blocks it.
    pub radiance: Vec3,
    /// The density per unit solid angle of `wi`, the pick's `1/N` included.
    pub pdf: f32,
    /// Where the shadow ray goes; [`shadow_ray`](Self::shadow_ray) builds it.
    target: ShadowTarget,
}

/// Where a light sample's shadow ray goes. Kept rather than the ray itself, so that offsetting
/// the ray's ends is paid only for a sample that carries something.
#[derive(Clone, Copy, Debug, PartialEq)]
enum ShadowTarget {
    /// A point on an area light: the ray is offset at both ends and stops short of it.
    Surface(LightSample),
    /// The environment, in a direction: nothing ends the ray.
    Direction(Vec3),
}

impl LightDirection {
    /// The shadow ray from `receiver` at shutter time `time`: what must be unblocked for the
    /// light to arrive.
    pub fn shadow_ray(&self, receiver: &SurfaceHit, time: f32) -> Ray {
        match self.target {
            ShadowTarget::Surface(sample) => sample.shadow_ray(receiver, time),
            ShadowTarget::Direction(wi) => receiver.spawn_ray(wi, time),
        }
    }
}

/// The scene's lights, borrowed.
#[derive(Clone, Copy, Debug)]
pub struct SceneLights<'a> {
    /// Area lights, in the scene's order.
    pub area: &'a [AreaLight],
    /// For every shape, the area light it is.
    pub light_of_shape: &'a [Option<u32>],
    /// For every area light, its shape.
    shape_of_light: &'a [u32],
    /// The area lights grouped into the scene's emitting shapes (a mesh's triangles, a cube's
    /// faces): a light sample picks one of these, then a piece of it by area.
    emitters: &'a [Range<usize>],
    /// For every area light, the running share of its emitter's area up to and including it.
    area_cdf: &'a [f32],
    /// For every area light, its share of its emitter's area.
    area_share: &'a [f32],
    /// For every emitting shape, the sum of the sampling weights up to and including it.
    emitter_weight_sum: &'a [f32],
    /// For every area light, its shape's sampling weight.
    weight_of_light: &'a [f32],
    /// Whether every sampling weight is 1, so that the pick is a plain uniform one.
    uniform_weights: bool,
    /// The scene, for the textures of lights whose radiance varies.
    scene: &'a Scene,
    /// Point lights.
    pub points: &'a [PointLight],
    /// Lights infinitely far away that shine one way: deltas, connected like point lights.
    pub directionals: &'a [DirectionalLight],
    /// The light from outside the scene.
    pub environment: EnvironmentLight<'a>,
    /// How area lights are sampled (chapter 07).
    pub sampling: LightSampling,
    /// How many lights a light sample may end on (area lights and the environment), counted
    /// once: every bounce asks.
    count: usize,
    /// The chance of picking an emitter of sampling weight 1 (an emitting shape, or the
    /// environment): one over the sum of their weights, which is their number unless a scene
    /// file gives weights (1 without any emitter), computed once for the same reason.
    pick_probability: f32,
}

impl<'a> SceneLights<'a> {
    /// The lights of `world`, its area lights `area_lights` sampled as `sampling` says.
    pub fn of(
        world: &'a MotionScene,
        area_lights: &'a AreaLights,
        sampling: LightSampling,
    ) -> Self {
        let scene = &world.scene;
        let mut lights = Self {
            area: &area_lights.lights,
            light_of_shape: &area_lights.light_of_shape,
            shape_of_light: &area_lights.shape_of_light,
            emitters: &area_lights.emitters,
            area_cdf: &area_lights.area_cdf,
            area_share: &area_lights.area_share,
            emitter_weight_sum: &area_lights.emitter_weight_sum,
            weight_of_light: &area_lights.weight_of_light,
            uniform_weights: area_lights.weight_of_light.iter().all(|&w| w == 1.0),
            scene,
            points: &scene.point_lights,
            directionals: &scene.directional_lights,
            environment: EnvironmentLight::of(scene),
            sampling,
            count: 0,
            pick_probability: 1.0,
        };
        let environment = usize::from(lights.has_environment());
        lights.count = lights.area.len() + environment;
        let shapes_weight = lights.emitter_weight_sum.last().copied().unwrap_or(0.0);
        let total_weight = shapes_weight + environment as f32;
        lights.pick_probability = if total_weight > 0.0 {
            1.0 / total_weight
        } else {
            1.0
        };
        lights
    }

    /// How many lights a light sample may end on: the area lights and the environment (point
    /// lights are not picked, see the module's introduction). With more than one, the pick
    /// draws a number.
    pub fn count(&self) -> usize {
        self.count
    }

    /// Whether a ray can find a light by hitting it: an area light or the environment (a
    /// point light it never can). Without, a path's last segment would find nothing. These
    /// are exactly the lights a light sample picks from.
    pub fn can_be_hit(&self) -> bool {
        self.count > 0
    }

    /// Whether the scene has point lights or directional lights: deltas, which no ray can
    /// hit and every bounce connects through a shadow ray of its own.
    pub fn has_delta_lights(&self) -> bool {
        !self.points.is_empty() || !self.directionals.is_empty()
    }

    /// Whether the scene has area lights, which a ray may hit and must then count.
    pub fn has_area_lights(&self) -> bool {
        !self.area.is_empty()
    }

    /// Whether the scene has a (non-black) environment.
    pub fn has_environment(&self) -> bool {
        !self.environment.is_black()
    }

    /// The chance of picking an emitter of sampling weight 1: an emitting shape of the scene
    /// (all the pieces of a mesh together) or the environment. Without weights in the scene
    /// file, every emitter's chance.
    pub fn pick_probability(&self) -> f32 {
        self.pick_probability
    }

    /// The chance that [`pick`](Self::pick) chooses area light `i`: its emitter's chance (its
    /// sampling weight over all of theirs) times its share of the emitter's area.
    pub fn area_pick_probability(&self, i: usize) -> f32 {
        self.pick_probability * self.weight_of_light[i] * self.area_share[i]
    }

    /// The light picked by `u` in `[0, 1)`, as Mitsuba 3 picks it: one of the emitters (the
    /// emitting shapes, then the environment) uniformly, or in proportion to their sampling
    /// weights when a scene file gives them, then, for a shape made of pieces, one of its
    /// pieces by area, with what `u` has left. `None` when there is no light.
    ///
    /// Picking among the pieces themselves would give a mesh of a thousand triangles a
    /// thousand times the samples of a sphere beside it, and its small triangles as many as
    /// its large ones: the same mean, but the lights that matter go unsampled.
    pub fn pick(&self, u: f32) -> Option<LightRef> {
        self.pick_with_rest(u).map(|(light, _)| light)
    }

    /// [`pick`](Self::pick), and what is left of `u` within the share of the light picked,
    /// uniform in `[0, 1)` again: a light sample places its point with it, as Mitsuba 3 reuses
    /// the first coordinate of its 2D sample, so that picking draws no number of its own and
    /// a sampler that places its 2D draws (chapter 03) places the pick and the point together.
    pub fn pick_with_rest(&self, u: f32) -> Option<(LightRef, f32)> {
        let n = self.emitters.len() + usize::from(self.has_environment());
        if n == 0 {
            return None;
        }
        let below_one = |x: f32| x.clamp(0.0, 1.0 - f32::EPSILON / 2.0);
        let (k, rest) = self.pick_emitter(u, n);
        let Some(emitter) = self.emitters.get(k) else {
            return Some((LightRef::Environment, below_one(rest)));
        };
        let pieces = &self.area_cdf[emitter.clone()];
        let piece = pieces
            .partition_point(|&cdf| cdf <= rest)
            .min(pieces.len() - 1);
        let before = if piece == 0 { 0.0 } else { pieces[piece - 1] };
        let width = pieces[piece] - before;
        let rest = if width > 0.0 {
            (rest - before) / width
        } else {
            0.5
        };
        Some((LightRef::Area(emitter.start + piece), below_one(rest)))
    }

    /// The emitter `u` picks among the `n` (the emitting shapes, then the environment, of
    /// weight 1), and what is left of `u` within its share, again uniform in `[0, 1)`.
    fn pick_emitter(&self, u: f32, n: usize) -> (usize, f32) {
        if self.uniform_weights {
            let scaled = u * n as f32;
            let k = (scaled as usize).min(n - 1);
            return (k, (scaled - k as f32).clamp(0.0, 1.0));
        }
        // The running sums of the shapes' weights, then the environment's 1.
        let sums = self.emitter_weight_sum;
        let shapes_weight = sums.last().copied().unwrap_or(0.0);
        let target = u / self.pick_probability;
        if target >= shapes_weight && n > sums.len() {
            return (sums.len(), (target - shapes_weight).clamp(0.0, 1.0));
        }
        let k = sums
            .partition_point(|&sum| sum <= target)
            .min(sums.len() - 1);
        let before = if k == 0 { 0.0 } else { sums[k - 1] };
        let rest = (target - before) / (sums[k] - before);
        (k, rest.clamp(0.0, 1.0))
    }

    /// The area light that world shape `shape` is, if any.
    pub fn area_light_of(&self, shape: u32) -> Option<&AreaLight> {
        let index = (*self.light_of_shape.get(shape as usize)?)?;
        self.area.get(index as usize)
    }

    /// The radiance the area light `light`, which is shape number `shape`, sends from its
    /// point of normal `n` and surface parameters `uv` towards `towards_viewer`: its
    /// radiance on the front side, times its texture at `uv` if it has one.
    pub fn emitted(
        &self,
        light: &AreaLight,
        shape: u32,
        n: Vec3,
        uv: impl FnOnce() -> Option<Vec2>,
        towards_viewer: Vec3,
    ) -> Vec3 {
        let front = light.emitted(n, towards_viewer);
        if front == Vec3::ZERO {
            return front;
        }
        match self.scene.surface(shape).emitter {
            Some(AreaEmitter {
                texture: Some(texture),
                ..
            }) => match uv() {
                Some(uv) => front * self.scene.albedo(texture, uv),
                None => Vec3::ZERO,
            },
            _ => front,
        }
    }

    /// The surface parameters of the point `p` of shape number `shape`, seen from `x`: those
    /// of the hit of the ray from `x` towards `p` on that shape alone, so that they follow
    /// the shape's own `uv` exactly as a hit there would. `None` if the ray misses it (a
    /// point on the very edge, by rounding), which then sends nothing: a set of no area.
    fn uv_of(&self, shape: u32, x: Vec3, p: Vec3) -> Option<Vec2> {
        let shape = self.scene.still_shape(shape)?;
        let to_p = p - x;
        let distance = to_p.length();
        let mut ray = Ray::new(x, to_p / distance);
        ray.t_max = distance * (1.0 + 1e-3);
        shape.intersect(&ray).map(|hit| hit.uv)
    }

    /// A direction to `light` from `receiver` with the numbers `u`, or `None` when the light
    /// offers nothing there (no area, a degenerate sample).
    pub fn sample(
        &self,
        light: LightRef,
        receiver: &SurfaceHit,
        u: Vec2,
    ) -> Option<LightDirection> {
        let x = receiver.p;
        let found = match light {
            LightRef::Area(i) => {
                let pick = self.area_pick_probability(i);
                let light = &self.area[i];
                let shape = self.shape_of_light[i];
                let sample = match self.textured_panel(light, shape) {
                    Some((quad, grid)) => {
                        let (uv, density) = grid.sample(u);
                        let error = parallelogram_point_error(&quad, uv);
                        let p = quad.point_at(uv.x, uv.y);
                        LightSample::by_area(p, error, quad.normal(), density / quad.area())?
                    }
                    None => light.sample(x, u, self.sampling)?,
                };
                let to_light = sample.p - x;
                let d2 = to_light.length_squared();
                let wi = to_light / d2.sqrt();
                let pdf = sample
                    .pdf_solid_angle
                    .unwrap_or_else(|| pdf_area_to_solid_angle(sample.pdf, d2, sample.n.dot(wi)));
                let uv = || self.uv_of(shape, x, sample.p);
                LightDirection {
                    wi,
                    radiance: self.emitted(light, shape, sample.n, uv, -wi),
                    pdf: pick * pdf,
                    target: ShadowTarget::Surface(sample),
                }
            }
            LightRef::Environment => {
                let pick = self.pick_probability();
                let (wi, pdf) = self.environment.sample(u)?;
                LightDirection {
                    wi,
                    radiance: self.environment.radiance(wi),
                    pdf: pick * pdf,
                    target: ShadowTarget::Direction(wi),
                }
            }
        };
        let usable = found.wi.is_finite() && found.radiance.is_finite() && !found.pdf.is_nan();
        (usable && found.pdf > 0.0).then_some(found)
    }

    /// The density per unit solid angle with which [`sample`](Self::sample) (pick included)
    /// would have chosen the point `y` (normal `n_y`) of `light` from `x`: what a BSDF sample
    /// that hit the light needs for its MIS weight.
    pub fn area_pdf(&self, light: &AreaLight, x: Vec3, y: Vec3, n_y: Vec3) -> f32 {
        let to_light = y - x;
        let index = self.index_of(light);
        let pick = index.map_or(self.pick_probability(), |i| self.area_pick_probability(i));
        if let Some((quad, grid)) =
            index.and_then(|i| self.textured_panel(light, self.shape_of_light[i]))
        {
            let d2 = to_light.length_squared();
            let density = grid.density(quad.uv_of(y)) / quad.area();
            return pick * pdf_area_to_solid_angle(density, d2, n_y.dot(to_light / d2.sqrt()));
        }
        let pdf = match (light.shape, self.sampling.strategy) {
            (LightShape::Sphere(sphere), Strategy::SolidAngle) => {
                sphere_solid_angle_pdf(&sphere, x, to_light)
            }
            _ => None,
        };
        let pdf = pdf.unwrap_or_else(|| {
            let d2 = to_light.length_squared();
            pdf_area_to_solid_angle(light.shape.pdf_area(), d2, n_y.dot(to_light / d2.sqrt()))
        });
        pick * pdf
    }

    /// The parallelogram of `light` (shape number `shape`) and the density over its `uv` its
    /// light samples are drawn with, when its radiance is a texture; `None` for every other
    /// light.
    fn textured_panel(
        &self,
        light: &AreaLight,
        shape: u32,
    ) -> Option<(Parallelogram, &'a GridDistribution)> {
        match light.shape {
            LightShape::Parallelogram(quad) => Some((quad, self.scene.emission_grid(shape)?)),
            _ => None,
        }
    }

    /// The index in [`area`](Self::area) of `light`, a reference into it (as
    /// [`area_light_of`](Self::area_light_of) gives), found by its place in memory.
    fn index_of(&self, light: &AreaLight) -> Option<usize> {
        let offset =
            (light as *const AreaLight as usize).checked_sub(self.area.as_ptr() as usize)?;
        let index = offset / std::mem::size_of::<AreaLight>();
        self.area
            .get(index)
            .filter(|candidate| std::ptr::eq(*candidate, light))
            .map(|_| index)
    }

    /// The density with which the environment is sampled in `direction`, pick included.
    pub fn environment_pdf(&self, direction: Vec3) -> f32 {
        self.pick_probability() * self.environment.pdf(direction)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ch07_soft_shadows::LightSampling;
    use workbench::scene_file::parse_scene;

    /// A matte floor under two emitters: a lamp of two triangles (areas 3 and 1, as a mesh
    /// gives its pieces) and a small sphere, each one shape of the scene.
    fn mesh_and_sphere_world() -> MotionScene {
        mesh_and_sphere_world_weighted(1.0)
    }

    /// [`mesh_and_sphere_world`] with the sphere's sampling weight `weight` (the lamp's is 1).
    fn mesh_and_sphere_world_weighted(weight: f32) -> MotionScene {
        use common::geometry::{Parallelogram, Shape, Sphere, Triangle};
        use common::scene::{
            AreaEmitter, Camera, CameraFrame, FilmSettings, Material, SceneBuilder, Surface,
        };
        let floor = Parallelogram::new(Vec3::new(-5.0, 0.0, -5.0), 10.0 * Vec3::Z, 10.0 * Vec3::X);
        // Facing down: (p1 - p0) × (p2 - p0) is -y.
        let (a, b) = (Vec3::new(-1.0, 2.0, 0.0), Vec3::new(1.0, 2.0, 0.0));
        let big = Triangle::new(a, b, Vec3::new(0.0, 2.0, 3.0));
        let small = Triangle::new(a, b, Vec3::new(0.0, 2.0, 1.0));
        let lamp = Surface {
            material: Material::diffuse(Vec3::ZERO),
            emitter: Some(AreaEmitter::uniform(Vec3::splat(2.0))),
            origin: None,
        };
        let scene = SceneBuilder::new()
            .shape(
                Shape::Parallelogram(floor),
                Material::diffuse(Vec3::splat(0.5)),
            )
            .shared_surface([Shape::Triangle(big), Shape::Triangle(small)], lamp)
            .surface(
                Shape::Sphere(Sphere::new(Vec3::new(2.0, 1.0, 0.0), 0.05)),
                Surface {
                    material: Material::diffuse(Vec3::ZERO),
                    emitter: Some(AreaEmitter {
                        sampling_weight: weight,
                        ..AreaEmitter::uniform(Vec3::splat(100.0))
                    }),
                    origin: None,
                },
            )
            .build(
                Camera::pinhole(
                    CameraFrame::look_at(Vec3::new(0.0, 1.0, 4.0), Vec3::ZERO, Vec3::Y).unwrap(),
                    40.0,
                ),
                FilmSettings::new(8, 8),
                2,
            );
        MotionScene::still(scene)
    }

    /// Picks with 8000 evenly spread numbers and checks that area light `i` gets the share
    /// `expected[i]` of them, and that its pick probability says so.
    fn assert_pick_shares(lights: &SceneLights, expected: [f32; 3]) {
        let n = 8000;
        let mut picked = [0usize; 3];
        for k in 0..n {
            let u = (k as f32 + 0.5) / n as f32;
            match lights.pick(u) {
                Some(LightRef::Area(i)) => picked[i] += 1,
                other => panic!("picked {other:?}"),
            }
        }
        for i in 0..3 {
            let share = picked[i] as f32 / n as f32;
            assert!(
                (share - expected[i]).abs() < 2e-3,
                "light {i} picked {share}, expected {}",
                expected[i]
            );
            assert!((lights.area_pick_probability(i) - expected[i]).abs() < 1e-6);
        }
    }

    /// A light sample picks an emitting shape as Mitsuba 3 does, each with the same chance
    /// however many pieces it is made of, and then a piece of it by area: the lamp's two
    /// triangles together get half the samples (3/8 and 1/8), the sphere the other half. Picked
    /// among the pieces, the sphere would get a third.
    #[test]
    fn a_light_sample_picks_emitting_shapes_evenly_and_their_pieces_by_area() {
        let world = mesh_and_sphere_world();
        let area_lights = AreaLights::of(&world.scene);
        let lights = SceneLights::of(&world, &area_lights, LightSampling::solid_angle());
        assert_eq!(lights.area.len(), 3, "two triangles and a sphere");
        assert_eq!(lights.count(), 3, "a sample may end on any of the three");
        let expected = [3.0 / 8.0, 1.0 / 8.0, 0.5];
        assert_pick_shares(&lights, expected);
    }

    /// A scene file's `sampling_weight` makes an emitter picked in proportion to it, as in
    /// Mitsuba 3: the sphere of weight 3 beside the lamp of weight 1 gets three quarters of
    /// the samples, and every density says so.
    #[test]
    fn sampling_weights_share_the_picks_in_proportion() {
        let world = mesh_and_sphere_world_weighted(3.0);
        let area_lights = AreaLights::of(&world.scene);
        let lights = SceneLights::of(&world, &area_lights, LightSampling::solid_angle());
        let expected = [3.0 / 16.0, 1.0 / 16.0, 0.75];
        assert_pick_shares(&lights, expected);
        let receiver = world
            .scene
            .geometry
            .intersect(&Ray::new(Vec3::new(0.3, 1.0, 0.4), -Vec3::Y))
            .unwrap();
        for i in 0..3 {
            let sample = lights
                .sample(LightRef::Area(i), &receiver, Vec2::new(0.3, 0.6))
                .unwrap();
            let ShadowTarget::Surface(point) = sample.target else {
                panic!("an area light's sample has a point")
            };
            let pdf = lights.area_pdf(&lights.area[i], receiver.p, point.p, point.n);
            assert!((pdf - sample.pdf).abs() <= 1e-4 * sample.pdf);
        }
    }

    /// The density a light sample reports for a point of a piece is the one `area_pdf` gives
    /// for the same point (which MIS needs), and for a shape of pieces it is uniform over the
    /// whole shape's area: the pick by area times the piece's own `1 / area`.
    #[test]
    fn a_piece_of_an_emitting_shape_has_the_density_of_the_whole_shape() {
        let world = mesh_and_sphere_world();
        let area_lights = AreaLights::of(&world.scene);
        let lights = SceneLights::of(&world, &area_lights, LightSampling::solid_angle());
        let receiver = world
            .scene
            .geometry
            .intersect(&Ray::new(Vec3::new(0.3, 1.0, 0.4), -Vec3::Y))
            .unwrap();
        let whole_area = lights.area[0].area() + lights.area[1].area();
        for i in 0..2 {
            for k in 0..16 {
                let u = Vec2::new((k % 4) as f32 + 0.5, (k / 4) as f32 + 0.5) / 4.0;
                let sample = lights.sample(LightRef::Area(i), &receiver, u).unwrap();
                let ShadowTarget::Surface(point) = sample.target else {
                    panic!("an area light's sample has a point")
                };
                let pdf = lights.area_pdf(&lights.area[i], receiver.p, point.p, point.n);
                assert!((pdf - sample.pdf).abs() <= 1e-4 * sample.pdf);
                let to_light = point.p - receiver.p;
                let d2 = to_light.length_squared();
                let uniform = 0.5 / whole_area * d2 / point.n.dot(to_light).abs() * d2.sqrt();
                assert!(
                    (sample.pdf - uniform).abs() <= 1e-4 * uniform,
                    "piece {i}: density {} per steradian, uniform over the shape is {uniform}",
                    sample.pdf
                );
            }
        }
    }

    /// A tiny, very bright sphere light straight above a floor point, seen from the point
    /// under the angle `R / d`: the light samples' mean of `L cos θ / p` is the irradiance
    /// `π L (R / d)²`, and `area_pdf` gives each sample's own density. With `1 - cos θ_max`
    /// computed as `1 - sqrt(1 - s²)` in `f32` (Mitsuba 3.9.1's sphere does so for its
    /// density), the density is off by the rounding of `cos θ_max` to the floats near 1:
    /// +7 % at `R / d = 6.7·10⁻⁴`, and no light at all below about `2.4·10⁻⁴`.
    #[test]
    fn a_tiny_sphere_light_gives_its_irradiance_to_the_last_digits() {
        use common::geometry::{Parallelogram, Shape, Sphere};
        use common::sampler::{IndependentSampler, Sampler};
        use common::scene::{Camera, CameraFrame, FilmSettings, Material, SceneBuilder};
        for (radius, d) in [(0.01f32, 15.0f32), (1e-3, 15.0), (1e-4, 15.0)] {
            let floor =
                Parallelogram::new(Vec3::new(-5.0, 0.0, -5.0), 10.0 * Vec3::Z, 10.0 * Vec3::X);
            let scene = SceneBuilder::new()
                .shape(Shape::Parallelogram(floor), Material::diffuse(Vec3::ONE))
                .area_light(
                    Shape::Sphere(Sphere::new(Vec3::new(0.0, d, 0.0), radius)),
                    Material::diffuse(Vec3::ZERO),
                    Vec3::ONE,
                )
                .build(
                    Camera::pinhole(
                        CameraFrame::look_at(Vec3::new(0.0, 1.0, 4.0), Vec3::ZERO, Vec3::Y)
                            .unwrap(),
                        40.0,
                    ),
                    FilmSettings::new(8, 8),
                    2,
                );
            let world = MotionScene::still(scene);
            let area_lights = AreaLights::of(&world.scene);
            let lights = SceneLights::of(&world, &area_lights, LightSampling::solid_angle());
            let receiver = world
                .scene
                .geometry
                .intersect(&Ray::new(Vec3::new(0.0, 1.0, 0.0), -Vec3::Y))
                .unwrap();
            let s = f64::from(radius) / f64::from(d);
            let exact = std::f64::consts::PI * s * s;
            let mut sampler = IndependentSampler::new(5);
            let (n, mut sum) = (4000, 0.0f64);
            for i in 0..n {
                sampler.start_pixel_sample(glam::UVec2::ZERO, i);
                let sample = lights
                    .sample(LightRef::Area(0), &receiver, sampler.get_2d())
                    .expect("the light is in view");
                let ShadowTarget::Surface(point) = sample.target else {
                    panic!("an area light's sample has a point")
                };
                let pdf = lights.area_pdf(&lights.area[0], receiver.p, point.p, point.n);
                assert!(
                    (pdf - sample.pdf).abs() <= 1e-3 * sample.pdf,
                    "R/d = {s:e}: sampled with {} but area_pdf says {pdf}",
                    sample.pdf
                );
                let cos = f64::from(sample.wi.y);
                sum += f64::from(sample.radiance.y) * cos / f64::from(sample.pdf);
            }
            let mean = sum / n as f64;
            assert!(
                (mean / exact - 1.0).abs() < 1e-3,
                "R/d = {s:e}: irradiance {mean:e}, exactly {exact:e}"
            );
            // The subtraction in f32 would be off by far more than the test allows (in f64 it
            // keeps ten digits and more at these sizes).
            let s2 = (radius / d).powi(2);
            let in_f32 = 1.0 - (1.0 - s2).sqrt();
            let in_f64 = 1.0 - (1.0 - s * s).sqrt();
            assert!((f64::from(in_f32) / in_f64 - 1.0).abs() > 0.05);
        }
    }

    /// The chapter's scene with a textured panel light.
    fn textured_light_world() -> MotionScene {
        let file = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/textured-light.xml");
        let text = std::fs::read_to_string(file).unwrap();
        let loaded = parse_scene(&text, std::path::Path::new(file), &[]).unwrap();
        MotionScene::new(loaded.scene).unwrap()
    }

    /// A light sample's density is the one `area_pdf` gives for the point it picked, or MIS
    /// would weigh the two ways of finding the light wrongly; and the samples gather where
    /// the image is bright.
    #[test]
    fn a_textured_panel_is_sampled_where_it_is_bright_with_the_density_area_pdf_gives() {
        let world = textured_light_world();
        let area_lights = AreaLights::of(&world.scene);
        let lights = SceneLights::of(&world, &area_lights, LightSampling::solid_angle());
        let (index, light) = lights
            .area
            .iter()
            .enumerate()
            .find(|(_, light)| matches!(light.shape, LightShape::Parallelogram(_)))
            .unwrap();
        assert!(
            lights
                .textured_panel(light, lights.shape_of_light[index])
                .is_some()
        );
        let receiver = world
            .scene
            .geometry
            .intersect(&Ray::new(
                Vec3::new(1.5, 1.0, 1.5),
                Vec3::new(0.0, -1.0, 0.0),
            ))
            .unwrap();
        // The numbers on a 64 x 64 grid over the square.
        let (mut bright, n) = (0, 64 * 64);
        for k in 0..n {
            let u = Vec2::new((k % 64) as f32 + 0.5, (k / 64) as f32 + 0.5) / 64.0;
            let Some(sample) = lights.sample(LightRef::Area(index), &receiver, u) else {
                continue;
            };
            let ShadowTarget::Surface(point) = sample.target else {
                panic!("an area light's sample has a point")
            };
            let pdf = lights.area_pdf(light, receiver.p, point.p, point.n);
            assert!(
                (pdf - sample.pdf).abs() <= 1e-4 * sample.pdf,
                "sampled with {} but area_pdf says {pdf}",
                sample.pdf
            );
            if luminance(sample.radiance) > 1.0 {
                bright += 1;
            }
        }
        // The bright patches are under a tenth of the panel; picked by area, a tenth of the
        // samples would land there.
        assert!(
            bright > n * 8 / 10,
            "only {bright} of {n} samples on the bright patches"
        );
    }
}
