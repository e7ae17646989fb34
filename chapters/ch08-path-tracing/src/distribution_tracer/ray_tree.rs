//! Measuring the ray tree: how many rays one camera ray costs, and how much of the pixel the
//! rays of each depth carry.
//!
//! [`rays_by_depth`] counts the rays of the worst case, a closed room where every ray meets a
//! surface and every light is in view: the most that [`DistributionTracer`] can cast. The
//! other numbers come from renders, not formulas: the tree's real size depends on the scene
//! (a ray that leaves it, or meets a black surface, does not branch), and so does the light
//! each depth adds. A depth's share is measured by rendering with `max_depth = d` and
//! `d - 1` with the **same seed** and differencing the mean radiance: the two renders draw
//! the same numbers for the shallow part of every tree, so their difference is the light of
//! depth `d` alone, with little noise.

#[cfg(doc)]
use super::DistributionTracer;
use super::{DistributionOptions, render_distribution};
use ch03_anti_aliasing::{FilterKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use common::render::{RenderOutput, RenderSettings};
use common::sampler::IndependentSampler;

/// What every ray of the worst case meets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    /// Smooth glass (a dielectric with no roughness).
    Glass,
    /// A matte surface of nonzero albedo, seen from a side it reflects on.
    Matte,
}

/// The lights of the worst case, each in view of every hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LightCounts {
    /// Area lights (chapter 07's, with `light_samples` points each).
    pub area: u32,
    /// Point lights.
    pub point: u32,
}

/// The rays cast at one depth of the tree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RayCount {
    /// The segment of the branch, as the tracer counts it: the camera ray is depth 1.
    pub depth: u32,
    /// Rays of this depth (the camera ray, or rays that hits of the depth before sent on).
    pub rays: u64,
    /// Shadow rays sent from the hits of this depth's rays.
    pub shadow_rays: u64,
}

// ANCHOR: rays_by_depth
/// How many rays and how many shadow rays [`DistributionTracer`] casts from one camera ray at
/// each depth `1..=options.max_depth` (at least 1), in the worst case: every ray it casts,
/// the camera ray included, meets a surface of kind `surface`, and every light is in front
/// of every hit, so that no shadow ray is skipped.
///
/// Read `trace` and `branches`: at which hits does the tree branch, and into how many rays?
/// Which hits send shadow rays, and how many to each kind of light? What does a hit at the
/// last depth still do?
pub fn rays_by_depth(
    surface: Surface,
    options: DistributionOptions,
    lights: LightCounts,
) -> Vec<RayCount> {
    // BEGIN SOLUTION
    let k = u64::from(options.material_samples.max(1));
    let m = u64::from(options.light_samples.max(1));
    // What one hit sends on, and how many shadow rays it sends.
    let (branches, shadow_per_hit) = match surface {
        Surface::Glass => (k, 0),
        Surface::Matte => (
            if options.indirect_diffuse { k } else { 0 },
            m * u64::from(lights.area) + u64::from(lights.point),
        ),
    };
    let mut counts = Vec::new();
    let mut rays = 1;
    for depth in 1..=options.max_depth {
        let last = depth == options.max_depth;
        counts.push(RayCount {
            depth,
            rays,
            shadow_rays: if last { 0 } else { rays * shadow_per_hit },
        });
        rays *= branches;
    }
    counts
    // END SOLUTION
}
// ANCHOR_END: rays_by_depth

/// Every ray of `counts`, of either kind.
pub fn total_rays(counts: &[RayCount]) -> u64 {
    counts.iter().map(|c| c.rays + c.shadow_rays).sum()
}

/// A render of `scene` at `size` and `spp`, pinhole, box filter, independent samples.
pub fn render_small(
    scene: &MotionScene,
    options: DistributionOptions,
    size: (u32, u32),
    spp: u64,
    seed: u64,
) -> RenderOutput {
    let settings = RenderSettings::new(size.0, size.1, spp);
    let filter = ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter");
    render_distribution(
        scene,
        options,
        &Lens::PINHOLE,
        &settings,
        &IndependentSampler::new(seed),
        &filter,
    )
}

/// Rays of every kind (secondary and shadow rays, the camera ray itself) per camera ray.
pub fn rays_per_camera_ray(output: &RenderOutput) -> f64 {
    let stats = &output.stats;
    let camera_rays = u64::from(stats.width) * u64::from(stats.height) * stats.spp;
    stats.rays as f64 / camera_rays.max(1) as f64
}

/// The mean radiance (all channels averaged) of a render: what a depth's share is of.
pub fn mean_radiance(output: &RenderOutput) -> f64 {
    let mean = common::metrics::mean(&output.image);
    (mean.x + mean.y + mean.z) / 3.0
}

/// For `d = 1 ..= max_depth`: the share of the image's mean radiance carried by rays of depth
/// `d` (segment `d` of their branch), from renders that differ only in `max_depth`.
pub fn depth_shares(
    scene: &MotionScene,
    options: DistributionOptions,
    size: (u32, u32),
    spp: u64,
    seed: u64,
) -> Vec<(u32, f64)> {
    let means: Vec<f64> = (1..=options.max_depth)
        .map(|d| {
            let at_depth = DistributionOptions {
                max_depth: d,
                ..options
            };
            mean_radiance(&render_small(scene, at_depth, size, spp, seed))
        })
        .collect();
    let total = means.last().copied().unwrap_or(0.0).max(f64::MIN_POSITIVE);
    means
        .iter()
        .enumerate()
        .map(|(i, &mean)| {
            let previous = if i == 0 { 0.0 } else { means[i - 1] };
            (i as u32 + 1, (mean - previous) / total)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::distribution_tracer::DistributionTracer;
    use ch07_soft_shadows::AreaLights;
    use common::Ray;
    use common::geometry::{Shape, Sphere};
    use common::render::counting_rays;
    use common::sampler::Sampler;
    use common::scene::{Camera, CameraFrame, FilmSettings, Material, PointLight, SceneBuilder};
    use glam::{UVec2, Vec2, Vec3};

    /// A sampler that hands out the same number for everything the tree asks for.
    #[derive(Clone)]
    struct Constant(f32);

    impl Sampler for Constant {
        fn start_pixel_sample(&mut self, _: UVec2, _: u64) {}
        fn get_pixel_2d(&mut self) -> Vec2 {
            Vec2::splat(self.0)
        }
        fn get_1d(&mut self) -> f32 {
            self.0
        }
    }

    /// A closed room: the inside of a sphere of radius 10 of `surface`, with `lights` near
    /// its centre (small spheres for the area lights), where every ray meets the wall.
    fn room(surface: Surface, lights: LightCounts, max_depth: u32) -> MotionScene {
        let wall = match surface {
            Surface::Glass => Material::glass(1.5),
            Surface::Matte => Material::two_sided_diffuse(Vec3::splat(0.5)),
        };
        let frame = CameraFrame::look_at(Vec3::ZERO, Vec3::X, Vec3::Y).expect("a camera");
        let mut builder =
            SceneBuilder::new().shape(Shape::Sphere(Sphere::new(Vec3::ZERO, 10.0)), wall);
        for i in 0..lights.area {
            let center = Vec3::new(-0.3 * i as f32, -0.5, 0.4);
            builder = builder.area_light(
                Shape::Sphere(Sphere::new(center, 0.05)),
                Material::diffuse(Vec3::ZERO),
                Vec3::ONE,
            );
        }
        for i in 0..lights.point {
            builder = builder.light(PointLight {
                position: Vec3::new(0.3 * i as f32, 0.6, -0.4),
                intensity: Vec3::ONE,
            });
        }
        let scene = builder.build(
            Camera::pinhole(frame, 40.0),
            FilmSettings::new(4, 4),
            max_depth,
        );
        MotionScene::still(scene)
    }

    /// The rays the chapter's tracer casts from one camera ray in [`room`]. Every number
    /// drawn is the same: `0.01` at glass (below the reflectance, so every choice reflects and
    /// stays in the room), `0.3` at matte walls (a cosine direction that passes far from the
    /// lights, so that no branch ends on one).
    fn traced(surface: Surface, options: DistributionOptions, lights: LightCounts) -> u64 {
        let world = room(surface, lights, options.max_depth);
        let area_lights = AreaLights::of(&world.scene);
        let tracer = DistributionTracer::new(&world, &area_lights, options);
        let u = match surface {
            Surface::Glass => 0.01,
            Surface::Matte => 0.3,
        };
        let camera_ray = Ray::new(Vec3::ZERO, Vec3::new(1.0, 0.2, 0.1).normalize());
        counting_rays(|| tracer.radiance(&camera_ray, &mut Constant(u))).1
    }

    /// The rays and shadow rays of each depth, measured: the rays of depth `d` are what the
    /// tracer casts without lights at depth limit `d` and not at `d - 1`; the shadow rays
    /// are what the lights add, those of depth `d` appearing at limit `d + 1`.
    fn measured(
        surface: Surface,
        options: DistributionOptions,
        lights: LightCounts,
    ) -> Vec<RayCount> {
        let dark = LightCounts { area: 0, point: 0 };
        let at = |max_depth: u32, lights: LightCounts| {
            if max_depth == 0 {
                return 0;
            }
            traced(
                surface,
                DistributionOptions {
                    max_depth,
                    ..options
                },
                lights,
            )
        };
        let shadow = |max_depth: u32| at(max_depth, lights) - at(max_depth, dark);
        let depth = options.max_depth;
        let mut counts: Vec<RayCount> = (1..=depth)
            .map(|d| RayCount {
                depth: d,
                rays: at(d, dark) - at(d - 1, dark),
                shadow_rays: if d < depth {
                    shadow(d + 1) - shadow(d)
                } else {
                    0
                },
            })
            .collect();
        // What the full tree casts beyond the shadow rays of the shallower limits: those of
        // its own last depth.
        let listed: u64 = counts.iter().map(|c| c.shadow_rays).sum();
        counts[depth as usize - 1].shadow_rays = shadow(depth) - listed;
        counts
    }

    /// What the usual slips give, for naming the one that `got` matches; `right` is what the
    /// tracer was [`measured`] to cast.
    fn mistake(
        surface: Surface,
        options: DistributionOptions,
        lights: LightCounts,
        got: &[RayCount],
        right: &[RayCount],
    ) -> &'static str {
        let k = u64::from(options.material_samples.max(1));
        let m = u64::from(options.light_samples.max(1));
        let rays_right =
            got.len() == right.len() && got.iter().zip(right).all(|(g, r)| g.rays == r.rays);
        let shadows_right = got.len() == right.len()
            && got
                .iter()
                .zip(right)
                .all(|(g, r)| g.shadow_rays == r.shadow_rays);
        if got.len() == right.len() + 1 {
            return "one depth too many: the tracer stops at depth max_depth, counting the \
                    camera ray as depth 1";
        }
        if got.len() + 1 == right.len() {
            return "one depth too few: the camera ray is depth 1 and the last depth is \
                    max_depth";
        }
        if got.len() != right.len() {
            return "one entry per depth 1..=max_depth";
        }
        if got.iter().zip(1..).any(|(g, d)| g.depth != d) {
            return "the depths are numbered as the tracer numbers them: the camera ray is \
                    depth 1";
        }
        if !rays_right {
            if got[0].rays != 1 {
                return "the camera ray is depth 1, and it is one ray: the tree's first \
                        branches are at depth 2 (is the exponent one too high?)";
            }
            let branches = if right.len() > 1 { right[1].rays } else { 0 };
            if branches > 1 && got.iter().all(|g| g.rays == 1) {
                return "the tree branches: every hit that sends k rays multiplies the rays of \
                        the next depth by k";
            }
            if got
                .iter()
                .zip(0u64..)
                .all(|(g, i)| g.rays == 1 + i * branches)
            {
                return "the growth was added, not multiplied: each of the rays of a depth \
                        sends its own branches, so every depth multiplies the rays";
            }
            if surface == Surface::Matte
                && !options.indirect_diffuse
                && got.len() > 1
                && got[1].rays > 0
            {
                return "Cook's tracer (indirect_diffuse false) sends no rays on from a matte \
                        surface, only shadow rays";
            }
            return "the rays per depth differ from the tracer's";
        }
        if !shadows_right {
            let any_right = right.iter().any(|r| r.shadow_rays > 0);
            if any_right && got.iter().all(|g| g.shadow_rays == 0) {
                return "no shadow rays: every matte hit sends shadow rays to the lights, and \
                        they cost as much as any other ray";
            }
            if surface == Surface::Glass && got.iter().any(|g| g.shadow_rays > 0) {
                return "smooth glass sends no shadow rays (its highlights need none: the \
                        light's density and the glass's are both deltas)";
            }
            let last = got.len() - 1;
            if got[last].shadow_rays > 0
                && got[..last]
                    .iter()
                    .zip(right)
                    .all(|(g, r)| g.shadow_rays == r.shadow_rays)
            {
                return "shadow rays at the last depth: a hit of depth max_depth only adds \
                        what it emits, it gathers no light";
            }
            let per_hit = |g: &RayCount| g.shadow_rays.checked_div(g.rays);
            let wrong_lights = [
                m * u64::from(lights.area + lights.point),
                u64::from(lights.area + lights.point),
                m * u64::from(lights.area),
                u64::from(lights.point),
                k * u64::from(lights.area) + u64::from(lights.point),
            ];
            if let Some(p) = per_hit(&got[0])
                && wrong_lights.contains(&p)
            {
                return "the shadow rays of one hit: how many points does a hit draw on each \
                        area light, and how many on a point light?";
            }
            return "the shadow rays per depth differ from the tracer's";
        }
        "right"
    }

    #[test]
    fn exercise_rays_by_depth_counts_what_the_tracer_casts() {
        let lights = |area, point| LightCounts { area, point };
        let cases = [
            (Surface::Glass, 2, 1, 4, false, lights(0, 0)),
            (Surface::Glass, 3, 2, 3, false, lights(1, 1)),
            (Surface::Matte, 2, 2, 4, true, lights(1, 0)),
            (Surface::Matte, 3, 2, 3, true, lights(2, 1)),
            (Surface::Matte, 2, 3, 4, false, lights(1, 2)),
            (Surface::Matte, 1, 4, 5, true, lights(1, 1)),
            (Surface::Glass, 1, 1, 1, false, lights(0, 1)),
        ];
        for (surface, k, m, max_depth, indirect_diffuse, lights) in cases {
            let options = DistributionOptions {
                material_samples: k,
                light_samples: m,
                max_depth,
                indirect_diffuse,
            };
            let tracer = measured(surface, options, lights);
            let got = rays_by_depth(surface, options, lights);
            assert!(
                got == tracer,
                "rays_by_depth: {}.\n  {surface:?} room, k = {k}, m = {m}, max_depth = \
                 {max_depth}, indirect_diffuse = {indirect_diffuse}, {} area and {} point \
                 lights:\n  yours:      {}\n  the tracer: {}",
                mistake(surface, options, lights, &got, &tracer),
                lights.area,
                lights.point,
                show(&got),
                show(&tracer),
            );
        }
    }

    /// `depth: rays + shadow rays, ...`.
    fn show(counts: &[RayCount]) -> String {
        counts
            .iter()
            .map(|c| format!("{}: {} + {}", c.depth, c.rays, c.shadow_rays))
            .collect::<Vec<_>>()
            .join(", ")
    }

    #[test]
    fn the_measured_tree_names_no_mistake_on_itself() {
        let options = DistributionOptions::branching(2, 4, true);
        let lights = LightCounts { area: 1, point: 1 };
        let right = measured(Surface::Matte, options, lights);
        assert_eq!(
            mistake(Surface::Matte, options, lights, &right, &right),
            "right"
        );
        // Worked out beforehand for two branches per hit, four points on the area light and
        // one on the point light, depth 4: 15 rays and 21 shadow rays.
        assert_eq!(total_rays(&right), 36);
    }
}
