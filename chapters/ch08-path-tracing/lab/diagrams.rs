//! The chapter's diagrams: Cook's ray tree beside one path, and the densities a light sample
//! and a BSDF sample have at one vertex.
//!
//! Every point drawn comes from the chapter's code. The ray tree is walked over a small scene
//! in the plane `z = 0` (a glass sphere, a mirror, a matte floor and a point light), where
//! mirrors and glass keep every ray in that plane: at each hit the walk asks the chapter's
//! [`Bsdf`] for its direction, as [`DistributionTracer`](crate::DistributionTracer) does, and the tests check that the
//! walk casts exactly as many rays as the tracer itself does with the same random numbers.
//! The densities come from [`SceneLights::sample`] and [`SurfaceBsdf::pdf`].

use crate::bsdf::{Bsdf, SurfaceBsdf};
use crate::distribution_tracer::DistributionOptions;
use crate::lights::{LightRef, SceneLights};
use ch01_whitted::world::World;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::FuzzMethod;
use ch07_soft_shadows::{AreaLights, LightOptions};
use common::Ray;
use common::geometry::{Parallelogram, Shape, Sphere, SurfaceHit};
use common::sampler::Sampler;
use common::scene::{Camera, CameraFrame, FilmSettings, Material, PointLight, SceneBuilder};
use glam::{UVec2, Vec2, Vec3};
use std::path::Path;
use workbench::output::figures::{Anchor, Diagram, Ink, Point};

/// Writes every diagram of the chapter into `out` (the figures' `diagrams` folder).
pub fn write_all(out: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out)?;
    ray_tree_against_path().save(&out.join("ray-tree-against-path.svg"))?;
    light_sample_densities().save(&out.join("light-sample-densities.svg"))?;
    Ok(())
}

// ---------------------------------------------------------------------------------------
// The ray tree against a path
// ---------------------------------------------------------------------------------------

/// The longest chain of rays drawn, counting the camera ray.
const TREE_DEPTH: u32 = 5;
/// `k` and `m` of the tree.
const BRANCHING: u32 = 2;
/// Where the eye of the camera ray is, and the point it aims at.
const EYE: Vec3 = Vec3::new(-4.6, 1.7, 0.0);
const AIM: Vec3 = Vec3::new(-1.0, 1.45, 0.0);
/// The point light.
const LAMP: Vec3 = Vec3::new(-2.6, 4.0, 0.0);
/// The window each panel shows (x, y), in the scene's units.
const PANEL_X: (f32, f32) = (-4.9, 3.3);
const PANEL_Y: (f32, f32) = (-0.15, 4.4);

/// A matte floor at `y = 0`, a mirror standing at `x = 3` and a glass sphere resting on the
/// floor, lit by one point light, everything cut through by the plane `z = 0`.
fn tree_scene(max_depth: u32) -> MotionScene {
    let floor = Parallelogram::new(Vec3::new(-6.0, 0.0, -3.0), 6.0 * Vec3::Z, 9.0 * Vec3::X);
    let mirror = Parallelogram::new(Vec3::new(3.0, 0.0, -3.0), 6.0 * Vec3::Z, 4.5 * Vec3::Y);
    let glass = Sphere::new(Vec3::new(0.0, 1.0, 0.0), 1.0);
    let frame = CameraFrame::look_at(EYE, AIM, Vec3::Y).expect("a valid camera");
    let scene = SceneBuilder::new()
        .shape(
            Shape::Parallelogram(floor),
            Material::diffuse(Vec3::splat(0.6)),
        )
        .shape(Shape::Parallelogram(mirror), Material::mirror())
        .shape(Shape::Sphere(glass), Material::glass(1.5))
        .light(PointLight {
            position: LAMP,
            intensity: Vec3::splat(10.0),
        })
        .build(
            Camera::pinhole(frame, 40.0),
            FilmSettings::new(16, 16),
            max_depth,
        );
    MotionScene::still(scene)
}

/// One ray the tracer casts: a secondary ray (`shadow` false) of depth `depth`, or a shadow
/// ray sent from the hit of a ray of depth `depth`.
#[derive(Clone, Copy, Debug)]
struct Segment {
    from: Vec3,
    to: Vec3,
    depth: u32,
    shadow: bool,
}

/// What a walk of the tree found: the rays, and every random number it drew, in order.
#[derive(Default, Debug)]
struct Walk {
    segments: Vec<Segment>,
    numbers: Vec<f32>,
}

impl Walk {
    /// Rays and shadow rays of each depth `1..=max_depth`.
    fn counts(&self, max_depth: u32) -> Vec<(u32, usize, usize)> {
        (1..=max_depth)
            .map(|d| {
                let of = |shadow| {
                    self.segments
                        .iter()
                        .filter(|s| s.depth == d && s.shadow == shadow)
                        .count()
                };
                (d, of(false), of(true))
            })
            .collect()
    }
}

/// A sampler that hands out one number and counts how many it handed out.
#[derive(Clone)]
struct Fixed {
    value: f32,
    drawn: usize,
}

impl Sampler for Fixed {
    fn start_pixel_sample(&mut self, _: UVec2, _: u64) {}
    fn get_pixel_2d(&mut self) -> Vec2 {
        Vec2::splat(self.get_1d())
    }
    fn get_1d(&mut self) -> f32 {
        self.drawn += 1;
        self.value
    }
}

/// Walks the tree that [`DistributionTracer`](crate::DistributionTracer) grows from `ray` at depth `depth`, in its
/// order: at a matte surface one shadow ray to each point light above it (the scene has no
/// area lights and Cook's tracer gathers no indirect diffuse light), at a mirror one ray, at
/// glass `k` rays, branch `b` drawing its Fresnel choice from `choice(b)`.
fn walk(
    world: &MotionScene,
    ray: &Ray,
    depth: u32,
    options: DistributionOptions,
    choice: &dyn Fn(u32) -> f32,
    out: &mut Walk,
) {
    let Some(hit) = world.intersect(ray) else {
        let far = clip_to_panel(ray.origin, ray.dir);
        out.segments.push(Segment {
            from: ray.origin,
            to: far,
            depth,
            shadow: false,
        });
        return;
    };
    out.segments.push(Segment {
        from: ray.origin,
        to: hit.p,
        depth,
        shadow: false,
    });
    if depth >= options.max_depth {
        return;
    }
    let material = world.material_at(&hit);
    let bsdf = Bsdf {
        material: &material,
        hit: &hit,
        fuzz: FuzzMethod::Lobe,
    };
    let wo = -ray.dir.normalize();
    match *bsdf.material {
        Material::Diffuse { albedo, .. } => {
            if albedo == Vec3::ZERO || !hit.front_face(ray.dir) {
                return;
            }
            for light in &world.scene.point_lights {
                if hit.shading_n.dot(light.position - hit.p) > 0.0 {
                    out.segments.push(Segment {
                        from: hit.p,
                        to: light.position,
                        depth,
                        shadow: true,
                    });
                }
            }
        }
        Material::Mirror { .. } | Material::Dielectric { .. } => {
            assert!(bsdf.is_delta(), "the tree's scene has only smooth surfaces");
            let k = if matches!(*bsdf.material, Material::Mirror { .. }) {
                1
            } else {
                options.material_samples
            };
            for b in 0..k {
                let mut numbers = Fixed {
                    value: choice(b),
                    drawn: 0,
                };
                let sample = bsdf.sample(wo, &mut numbers);
                out.numbers
                    .extend(std::iter::repeat_n(numbers.value, numbers.drawn));
                if let Some(sample) = sample {
                    let next = hit.spawn_ray(sample.wi, ray.time);
                    walk(world, &next, depth + 1, options, choice, out);
                }
            }
        }
        _ => panic!("the tree's scene has matte, mirror and glass surfaces only"),
    }
}

/// Where a ray from `origin` along `dir` leaves the panel's window.
fn clip_to_panel(origin: Vec3, dir: Vec3) -> Vec3 {
    let exit = |o: f32, d: f32, (low, high): (f32, f32)| {
        if d > 0.0 {
            (high - o) / d
        } else if d < 0.0 {
            (low - o) / d
        } else {
            f32::INFINITY
        }
    };
    let t = exit(origin.x, dir.x, PANEL_X).min(exit(origin.y, dir.y, PANEL_Y));
    origin + t.max(0.0) * dir
}

/// The tree (`k = m = 2`) and the path (`k = m = 1`) of Cook's tracer, each with its walk.
fn tree_and_path() -> (Walk, Walk) {
    let camera_ray = Ray::new(EYE, (AIM - EYE).normalize());
    let world = tree_scene(TREE_DEPTH);
    let tree_options = DistributionOptions::branching(BRANCHING, TREE_DEPTH, false);
    let path_options = DistributionOptions::cook(TREE_DEPTH);
    // The tree's two branches at glass: the reflected ray, then the refracted one (a choice
    // below the reflectance reflects). The path refracts at every glass hit.
    let mut tree = Walk::default();
    walk(
        &world,
        &camera_ray,
        1,
        tree_options,
        &|b| if b == 0 { 0.001 } else { 0.999 },
        &mut tree,
    );
    let mut path = Walk::default();
    walk(&world, &camera_ray, 1, path_options, &|_| 0.999, &mut path);
    (tree, path)
}

/// Cook's ray tree beside one path, with the rays each casts per depth.
fn ray_tree_against_path() -> Diagram {
    let (tree, path) = tree_and_path();
    let width = PANEL_X.1 - PANEL_X.0;
    let offset = f64::from(width) + 0.6;
    let mut d = Diagram::new(
        "Left: Cook's distribution ray tracer with two samples per effect grows a tree at a \
         glass sphere: every glass hit sends a reflected and a refracted ray, the mirror sends \
         one, and each hit on the matte floor sends a shadow ray to the lamp, so the rays \
         multiply wherever they meet glass. Right: the same tracer with one sample per effect \
         follows a single path, one ray per depth, plus a shadow ray where it reaches the \
         floor, where Cook's tracer ends it. The rays cast at each depth are written under \
         each picture.",
        (
            f64::from(PANEL_X.0) - 0.1,
            f64::from(PANEL_X.1) + offset + 0.1,
        ),
        (-4.2, f64::from(PANEL_Y.1) + 0.6),
        720,
    );
    for (panel, walk, ray_ink, title) in [
        (0.0, &tree, Ink::Ray, "Cook's tree, k = m = 2"),
        (offset, &path, Ink::OtherRay, "one path, k = m = 1"),
    ] {
        draw_tree_scene(&mut d, panel);
        let at = |p: Vec3| (f64::from(p.x) + panel, f64::from(p.y));
        for s in &walk.segments {
            let ink = if s.shadow { Ink::Light } else { ray_ink };
            d.arrow(at(s.from), at(s.to), ink);
        }
        d.label(
            (panel + f64::from(PANEL_X.0), -1.0),
            title,
            Anchor::Left,
            Ink::Surface,
        );
        for (row, (depth, rays, shadow)) in walk.counts(TREE_DEPTH).into_iter().enumerate() {
            let plural =
                |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
            let mut text = format!("depth {depth}: {}", plural(rays, "ray"));
            if rays == 0 && shadow == 0 {
                text = format!("depth {depth}: none, the path ended");
            }
            if shadow > 0 {
                text += &format!(" + {}", plural(shadow, "shadow ray"));
            }
            d.label(
                (panel + f64::from(PANEL_X.0), -1.6 - 0.55 * row as f64),
                &text,
                Anchor::Left,
                Ink::Surface,
            );
        }
    }
    d
}

/// The floor, the mirror, the sphere's outline and the lamp, `dx` to the right.
fn draw_tree_scene(d: &mut Diagram, dx: f64) {
    let x = |v: f32| f64::from(v) + dx;
    d.line((x(PANEL_X.0), 0.0), (x(3.0), 0.0), Ink::Surface);
    d.line((x(3.0), 0.0), (x(3.0), f64::from(PANEL_Y.1)), Ink::Surface);
    d.circle((x(0.0), 1.0), 1.0, Ink::Surface);
    d.dot((x(LAMP.x), f64::from(LAMP.y)), Ink::Light);
    d.label(
        (x(LAMP.x), f64::from(LAMP.y) + 0.12),
        "lamp",
        Anchor::Below,
        Ink::Light,
    );
    d.label((x(2.9), 3.9), "mirror", Anchor::Right, Ink::Surface);
    d.label((x(0.0), -0.1), "glass ball", Anchor::Above, Ink::Surface);
    d.label(
        (x(PANEL_X.0), -0.3),
        "matte floor",
        Anchor::Left,
        Ink::Surface,
    );
}

// ---------------------------------------------------------------------------------------
// The densities at one vertex
// ---------------------------------------------------------------------------------------

/// The glossy floor's exponent.
const GLOSSY_EXPONENT: f32 = 8.0;
/// The numbers of the light sample drawn: the middle of panel A in `z`, so in the plane.
const LIGHT_U: Vec2 = Vec2::new(0.3, 0.5);
/// Where the drawn BSDF direction meets panel A, as a fraction along its edge.
const BSDF_ALONG: f32 = 0.75;
/// The direction back towards where the path came from.
const WO: Vec3 = Vec3::new(-0.8, 0.6, 0.0);

/// Panel A (picked) and panel B, each a parallelogram `1` deep in `z` whose edge in the plane
/// `z = 0` runs from the first point to the second; their normals face down.
const PANEL_A: (Vec3, Vec3) = (Vec3::new(0.2, 3.0, -0.5), Vec3::new(2.0, 3.6, -0.5));
/// Panel A's number among the scene's shapes (the floor is 0).
const PANEL_A_SHAPE: u32 = 1;
const PANEL_B: (Vec3, Vec3) = (Vec3::new(-3.4, 2.2, -0.5), Vec3::new(-2.2, 3.0, -0.5));

fn panel(edge: (Vec3, Vec3)) -> Parallelogram {
    Parallelogram::new(edge.0, edge.1 - edge.0, Vec3::Z)
}

/// A glossy floor under two panel lights.
fn vertex_scene() -> MotionScene {
    let floor = Parallelogram::new(Vec3::new(-6.0, 0.0, -3.0), 6.0 * Vec3::Z, 12.0 * Vec3::X);
    let frame = CameraFrame::look_at(Vec3::new(-3.0, 2.0, 0.0), Vec3::ZERO, Vec3::Y)
        .expect("a valid camera");
    let scene = SceneBuilder::new()
        .shape(
            Shape::Parallelogram(floor),
            Material::glossy(Vec3::splat(0.8), GLOSSY_EXPONENT),
        )
        .area_light(
            Shape::Parallelogram(panel(PANEL_A)),
            Material::diffuse(Vec3::ZERO),
            Vec3::ONE,
        )
        .area_light(
            Shape::Parallelogram(panel(PANEL_B)),
            Material::diffuse(Vec3::ZERO),
            Vec3::ONE,
        )
        .build(Camera::pinhole(frame, 40.0), FilmSettings::new(16, 16), 2);
    MotionScene::still(scene)
}

/// What the diagram of the densities draws, all of it from the chapter's code.
struct Vertex {
    /// The receiver.
    x: Vec3,
    /// The light sample's point on panel A and the light's normal there.
    y: Vec3,
    n_y: Vec3,
    /// The panel's area, the chance of picking it, and the light sample's density per unit
    /// solid angle (`SceneLights::sample`, the pick included).
    area: f32,
    pick: f32,
    light_pdf: f32,
    /// The BSDF's density in the light sample's direction.
    light_dir_bsdf_pdf: f32,
    /// The point where the drawn BSDF direction meets panel A, and the two densities there.
    y2: Vec3,
    bsdf_pdf: f32,
    bsdf_dir_light_pdf: f32,
    /// The shape the BSDF direction's ray hits.
    bsdf_ray_hits: Option<u32>,
}

fn vertex() -> Vertex {
    let world = vertex_scene();
    let area_lights = AreaLights::of(&world.scene);
    let lights = SceneLights::of(&world, &area_lights, LightOptions::default().sampling);
    let down = Ray::new(Vec3::new(0.0, 1.0, 0.0), -Vec3::Y);
    let hit: SurfaceHit = world.intersect(&down).expect("the floor");
    let material = world.material_at(&hit);
    let bsdf = Bsdf {
        material: &material,
        hit: &hit,
        fuzz: FuzzMethod::Lobe,
    };
    let wo = WO.normalize();
    let sample = lights
        .sample(LightRef::Area(0), &hit, LIGHT_U)
        .expect("panel A faces the floor");
    let to_y = sample.wi;
    let y = hit.p
        + to_y
            * world
                .intersect(&hit.spawn_ray(to_y, 0.0))
                .map(|h| (h.p - hit.p).length())
                .expect("the light sample's ray meets panel A");
    let quad = panel(PANEL_A);
    let y2 = PANEL_A.0 + BSDF_ALONG * (PANEL_A.1 - PANEL_A.0) + 0.5 * Vec3::Z;
    let to_y2 = (y2 - hit.p).normalize();
    let light_a = &lights.area[0];
    Vertex {
        x: hit.p,
        y,
        n_y: quad.normal(),
        area: quad.area(),
        pick: lights.pick_probability(),
        light_pdf: sample.pdf,
        light_dir_bsdf_pdf: bsdf.pdf(wo, to_y),
        y2,
        bsdf_pdf: bsdf.pdf(wo, to_y2),
        bsdf_dir_light_pdf: lights.area_pdf(light_a, hit.p, y2, quad.normal()),
        bsdf_ray_hits: world.intersect(&hit.spawn_ray(to_y2, 0.0)).map(|h| h.shape),
    }
}

fn pt(p: Vec3) -> Point {
    (f64::from(p.x), f64::from(p.y))
}

/// The light sample and a BSDF sample that both reach panel A, with their densities per unit
/// solid angle, and how the light's density per unit area becomes one per solid angle.
fn light_sample_densities() -> Diagram {
    let v = vertex();
    let mut d = Diagram::new(
        "A glossy floor point x lit by two panel lights. The light sample picks panel A with \
         probability one half and a point y on it with density one over its area; seen from x \
         that point's density per unit solid angle is the pick's probability times the area \
         density times r squared over the cosine of the angle theta prime between the light's \
         normal and the direction back to x. A direction the BSDF draws can reach the same \
         panel; each of the two directions is labelled with both densities, the light's and \
         the BSDF's, which multiple importance sampling compares.",
        (-4.2, 4.6),
        (-0.6, 5.3),
        720,
    );
    d.line((-4.2, 0.0), (4.6, 0.0), Ink::Surface);
    d.label((-4.1, -0.3), "glossy floor", Anchor::Left, Ink::Surface);
    for (edge, name) in [(PANEL_A, "A"), (PANEL_B, "B")] {
        let (a, b) = (pt(edge.0), pt(edge.1));
        d.line(a, b, Ink::Light);
        let mid = ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
        d.label(
            (mid.0 - 0.1, mid.1 + 0.15),
            &format!("panel {name}"),
            Anchor::Below,
            Ink::Light,
        );
    }
    let x = pt(v.x);
    d.dot(x, Ink::Surface);
    d.label((x.0, x.1 - 0.1), "x", Anchor::Above, Ink::Surface);
    let wo = WO.normalize();
    d.arrow(pt(v.x + 2.2 * wo), x, Ink::Guide);
    d.label(
        pt(v.x + 2.3 * wo),
        "from the path",
        Anchor::Right,
        Ink::Guide,
    );
    // The light sample, its normal and θ'.
    d.arrow(x, pt(v.y), Ink::Ray);
    d.dot(pt(v.y), Ink::Ray);
    d.label(
        (f64::from(v.y.x) - 0.12, f64::from(v.y.y) + 0.05),
        "y",
        Anchor::Right,
        Ink::Ray,
    );
    d.arrow(pt(v.y), pt(v.y + 0.9 * v.n_y), Ink::Normal);
    d.label(pt(v.y + 0.95 * v.n_y), "n̂′", Anchor::Left, Ink::Normal);
    let back = (v.x - v.y).normalize();
    let angle = |w: Vec3| f64::from(w.y.atan2(w.x));
    let (a0, a1) = (angle(v.n_y), angle(back));
    d.arc(pt(v.y), 0.45, a0.min(a1), a0.max(a1), Ink::Normal);
    let mid = v.y + 0.7 * (v.n_y + back).normalize();
    d.label(pt(mid), "θ′", Anchor::Centre, Ink::Normal);
    let r = (v.y - v.x).length();
    let cos = v.n_y.dot(back);
    let along = |p: Vec3, f: f32| pt(v.x + f * (p - v.x));
    let r_at = along(v.y, 0.7);
    d.label((r_at.0 - 0.12, r_at.1), "r", Anchor::Right, Ink::Ray);
    let light_at = along(v.y, 0.4);
    d.label(
        (light_at.0 - 0.15, light_at.1),
        "light sample",
        Anchor::Right,
        Ink::Ray,
    );
    // The BSDF direction that reaches the same panel.
    // Drawn as a warning if it missed the panel, which the tests forbid.
    let bsdf_ink = if v.bsdf_ray_hits == Some(PANEL_A_SHAPE) {
        Ink::OtherRay
    } else {
        Ink::Warning
    };
    d.arrow(x, pt(v.y2), bsdf_ink);
    d.dot(pt(v.y2), bsdf_ink);
    let bsdf_at = along(v.y2, 0.4);
    d.label(
        (bsdf_at.0 + 0.15, bsdf_at.1),
        "BSDF sample",
        Anchor::Left,
        Ink::OtherRay,
    );
    // The numbers.
    let lines = [
        (
            Ink::Ray,
            format!(
                "light sample: p_A = 1/A = {:.3}, r = {r:.2}, cos θ′ = {cos:.2}",
                1.0 / v.area
            ),
        ),
        (
            Ink::Ray,
            format!(
                "   p_light = {} · p_A · r²/cos θ′ = {:.3},  p_bsdf = {:.3}",
                if (v.pick - 0.5).abs() < 1e-6 {
                    "½".to_string()
                } else {
                    format!("{:.2}", v.pick)
                },
                v.light_pdf,
                v.light_dir_bsdf_pdf
            ),
        ),
        (
            Ink::OtherRay,
            format!(
                "BSDF sample: p_bsdf = {:.3},  p_light = {:.3}",
                v.bsdf_pdf, v.bsdf_dir_light_pdf
            ),
        ),
    ];
    for (row, (ink, text)) in lines.iter().enumerate() {
        d.label((-4.1, 5.05 - 0.45 * row as f64), text, Anchor::Left, *ink);
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::distribution_tracer::DistributionTracer;
    use common::render::counting_rays;
    use workbench::test_support::written_diagrams;

    /// A sampler that plays back the numbers a walk drew, and panics if asked for more.
    #[derive(Clone)]
    struct Script {
        numbers: Vec<f32>,
        next: usize,
    }

    impl Sampler for Script {
        fn start_pixel_sample(&mut self, _: UVec2, _: u64) {}
        fn get_pixel_2d(&mut self) -> Vec2 {
            self.get_2d()
        }
        fn get_1d(&mut self) -> f32 {
            let u = self.numbers[self.next];
            self.next += 1;
            u
        }
    }

    /// The rays the chapter's tracer casts from the camera ray with the numbers `numbers`,
    /// and how many of the numbers it drew.
    fn traced(options: DistributionOptions, numbers: &[f32]) -> (u64, usize) {
        let world = tree_scene(options.max_depth);
        let area_lights = AreaLights::of(&world.scene);
        let tracer = DistributionTracer::new(&world, &area_lights, options);
        let mut script = Script {
            numbers: numbers.to_vec(),
            next: 0,
        };
        let camera_ray = Ray::new(EYE, (AIM - EYE).normalize());
        let (_, rays) = counting_rays(|| tracer.radiance(&camera_ray, &mut script));
        (rays, script.next)
    }

    #[test]
    fn the_walks_cast_the_rays_the_tracer_casts_at_every_depth_limit() {
        let camera_ray = Ray::new(EYE, (AIM - EYE).normalize());
        for max_depth in 1..=TREE_DEPTH {
            let world = tree_scene(max_depth);
            let tree_choice = |b: u32| if b == 0 { 0.001f32 } else { 0.999 };
            let path_choice = |_: u32| 0.999f32;
            let cases: [(u32, &dyn Fn(u32) -> f32); 2] =
                [(BRANCHING, &tree_choice), (1, &path_choice)];
            for (k, choice) in cases {
                let options = DistributionOptions::branching(k, max_depth, false);
                let mut walked = Walk::default();
                walk(&world, &camera_ray, 1, options, choice, &mut walked);
                let (rays, drawn) = traced(options, &walked.numbers);
                assert_eq!(
                    walked.segments.len() as u64,
                    rays,
                    "k = {k}, max_depth {max_depth}: the walk drew {} rays, the tracer cast {rays}",
                    walked.segments.len()
                );
                assert_eq!(drawn, walked.numbers.len(), "the tracer drew other numbers");
            }
        }
    }

    #[test]
    fn the_tree_multiplies_its_rays_while_the_path_keeps_one_per_depth() {
        let (tree, path) = tree_and_path();
        let tree_counts = tree.counts(TREE_DEPTH);
        let path_counts = path.counts(TREE_DEPTH);
        // The path: one ray per depth until it takes its light sample on the matte floor,
        // where Cook's tracer ends it.
        let floor = path_counts
            .iter()
            .position(|c| c.2 == 1)
            .expect("the path reaches the floor and takes its light sample");
        assert!(
            floor >= 3,
            "the path meets glass and the mirror first: {path_counts:?}"
        );
        for (i, (depth, rays, shadow)) in path_counts.iter().enumerate() {
            let expected = if i <= floor { 1 } else { 0 };
            assert_eq!(
                *rays, expected,
                "path rays at depth {depth}: {path_counts:?}"
            );
            assert!(*shadow <= 1, "one light sample at most");
        }
        // The tree: the camera ray, its reflection and refraction at the glass, and at every
        // depth at least as many rays as the path, more than twice as many in all.
        assert_eq!((tree_counts[0].1, tree_counts[1].1), (1, 2));
        let total = |c: &[(u32, usize, usize)]| c.iter().map(|c| c.1 + c.2).sum::<usize>();
        assert!(
            tree_counts
                .iter()
                .zip(&path_counts)
                .all(|(t, p)| t.1 >= p.1),
            "{tree_counts:?} against {path_counts:?}"
        );
        assert!(total(&tree_counts) > 2 * total(&path_counts));
    }

    #[test]
    fn the_light_density_is_the_pick_times_the_area_density_converted_to_solid_angle() {
        let v = vertex();
        assert!((v.pick - 0.5).abs() < 1e-6, "two lights to pick from");
        assert!(
            v.y.z.abs() < 1e-4 && v.y2.z.abs() < 1e-6,
            "drawn in the plane"
        );
        let r2 = (v.y - v.x).length_squared();
        let cos = v.n_y.dot((v.x - v.y).normalize());
        let expected = v.pick * (1.0 / v.area) * r2 / cos;
        assert!(
            (v.light_pdf - expected).abs() < 1e-4 * expected,
            "{} against {expected}",
            v.light_pdf
        );
        // Without the pick, or per unit area, the density would be another number.
        assert!((v.light_pdf - expected / v.pick).abs() > 0.1 * expected);
        assert_eq!(
            v.bsdf_ray_hits,
            Some(PANEL_A_SHAPE),
            "the BSDF direction reaches panel A"
        );
        assert!(v.bsdf_pdf > 0.0 && v.bsdf_dir_light_pdf > 0.0 && v.light_dir_bsdf_pdf > 0.0);
    }

    #[test]
    fn write_all_writes_each_diagram_as_svg_with_its_description() {
        written_diagrams(
            write_all,
            &["ray-tree-against-path.svg", "light-sample-densities.svg"],
        );
    }
}
