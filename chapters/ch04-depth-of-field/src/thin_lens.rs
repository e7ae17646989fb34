//! The thin-lens camera: chapter 01's pinhole camera with a lens in front.
//!
//! The lecture's recipe, in Mitsuba 3's conventions (camera space: the lens in the `z = 0`
//! plane, looking down +z):
//!
//! 1. The ray through the lens centre is the pinhole ray. Where it meets the focal plane
//!    `z = d_f` is the focus point `P_f`. A thin lens sends every ray from a point of the
//!    focal plane through the same film point, so *every* ray of this film position passes
//!    through `P_f`.
//! 2. A lens sample picks the point `P_l` of the aperture the ray leaves from.
//! 3. The ray goes from `P_l` towards `P_f`.
//!
//! Rays start at the near clipping plane, `z = near_clip`, as in chapter 01 and in Mitsuba.
//! With a zero aperture all of this collapses onto the pinhole ray, and the camera then asks
//! the sampler for nothing: the image is chapter 01's, bit for bit.

use crate::lens::Lens;
use ch01_whitted::camera::PinholeCamera;
use common::Ray;
use common::sampler::Sampler;
use glam::{Vec2, Vec3};

// ANCHOR: thin_lens_ray
/// The thin-lens ray in camera space: it leaves the lens point `lens_point` (in the `z = 0`
/// plane) towards the focus point, where the pinhole direction `pinhole_dir` (any length,
/// `z > 0`) meets the focal plane `z = focus_distance`. Returns the origin and the direction,
/// `P_f - P_l`, not normalised: its `z` is `focus_distance`.
pub fn thin_lens_ray(pinhole_dir: Vec3, lens_point: Vec2, focus_distance: f32) -> (Vec3, Vec3) {
    // BEGIN SOLUTION
    // The pinhole ray t * pinhole_dir reaches z = focus_distance at t = focus_distance / z.
    let focus_point = pinhole_dir * (focus_distance / pinhole_dir.z);
    let origin = lens_point.extend(0.0);
    (origin, focus_point - origin)
    // END SOLUTION
}
// ANCHOR_END: thin_lens_ray

/// A pinhole camera with a thin lens: Mitsuba's `thinlens` sensor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThinLensCamera {
    /// Position, orientation, field of view, film size and near clip.
    pub pinhole: PinholeCamera,
    /// The lens.
    pub lens: Lens,
}

impl ThinLensCamera {
    /// The camera `pinhole` with `lens` in front of it.
    pub fn new(pinhole: PinholeCamera, lens: Lens) -> Self {
        Self { pinhole, lens }
    }

    /// The same camera on a film of another size.
    pub fn with_size(self, width: u32, height: u32) -> Self {
        Self {
            pinhole: self.pinhole.with_size(width, height),
            ..self
        }
    }

    // ANCHOR: generate_ray
    /// The camera ray through film position `p_film`. The lens is the sample's next
    /// dimension after the pixel (and, from chapter 05, the time); a pinhole lens draws none.
    pub fn generate_ray<S: Sampler>(&self, p_film: Vec2, sampler: &mut S) -> Ray {
        if self.lens.is_pinhole() {
            return self.pinhole.generate_ray(p_film);
        }
        let u_lens = sampler.get_2d();
        self.generate_ray_through(p_film, u_lens)
    }
    // ANCHOR_END: generate_ray

    // ANCHOR: thin_lens_camera
    /// The camera ray, in world space, through film position `p_film` (in pixels) from the
    /// point of the lens that the lens sample `u_lens` (in `[0, 1)^2`) picks: the lecture's
    /// recipe from the ray through the lens centre to the new origin and direction.
    ///
    /// Which point of the aperture does `u_lens` pick, given the lens's shape, its warp and its
    /// size? Where does this ray start, and in which space is each of your points and vectors?
    /// Whatever the lens, however wide or narrow and however near or far its focus, the ray has
    /// a finite origin and a direction of unit length.
    pub fn generate_ray_through(&self, p_film: Vec2, u_lens: Vec2) -> Ray {
        // BEGIN SOLUTION
        use crate::aperture::{Aperture, sample_uniform_regular_polygon};
        // The ray through the lens centre is the pinhole's: its direction in camera space.
        let pinhole_dir = self.pinhole.camera_direction(p_film);
        // The lens point: a uniform point of the aperture's shape at unit size (a disc by the
        // lens's warp, a polygon by its fan of triangles), then at the lens's own size.
        let unit_point = match self.lens.aperture {
            Aperture::Disc => self.lens.warp.sample(u_lens),
            Aperture::Polygon { blades, rotation } => {
                sample_uniform_regular_polygon(u_lens, blades, rotation)
            }
        };
        let lens_point = self.lens.aperture_radius * unit_point;
        // The ray leaves the lens point towards the focus point, where the pinhole ray meets
        // the focal plane, so every ray of this film position meets there.
        let (origin, dir) = thin_lens_ray(pinhole_dir, lens_point, self.lens.focus_distance);
        // It starts at the near clipping plane, as the pinhole's ray does (Mitsuba adds
        // `near_clip / d.z` times the unit direction; with `dir.z = focus_distance` that is
        // this).
        let start = origin + dir * (self.pinhole.near_clip / dir.z);
        // From camera space into the world, with a direction of unit length.
        let frame = &self.pinhole.frame;
        Ray::new(
            frame.origin + frame.to_world(start),
            frame.to_world(dir.normalize()),
        )
        // END SOLUTION
    }
    // ANCHOR_END: thin_lens_camera
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aperture::{Aperture, LensWarp, sample_uniform_regular_polygon};
    use common::sampler::IndependentSampler;
    use common::scene::CameraFrame;
    use glam::UVec2;

    fn pinhole() -> PinholeCamera {
        let frame =
            CameraFrame::look_at(Vec3::new(1.0, 2.0, 5.0), Vec3::new(1.0, 2.0, 0.0), Vec3::Y)
                .unwrap();
        PinholeCamera::new(frame, 60.0, 64, 48)
    }

    /// What is wrong with `(origin, dir) = thin_lens_ray(pinhole_dir, lens_point, focus)`,
    /// in words; `None` if it is right. Right means: it leaves the lens point, its direction's
    /// `z` is the focus distance, and so it reaches the focal plane at `origin + dir`, which
    /// must lie on the pinhole ray.
    fn thin_lens_mistake(
        pinhole_dir: Vec3,
        lens_point: Vec2,
        focus: f32,
        (origin, dir): (Vec3, Vec3),
    ) -> Option<String> {
        let lens = lens_point.extend(0.0);
        let close = |a: Vec3, b: Vec3| (a - b).length() <= 1e-5 * b.length().max(1.0);
        // Whether a point lies on the pinhole ray, ahead of the lens centre.
        let on_pinhole_ray = |p: Vec3| {
            let along = p.dot(pinhole_dir.normalize());
            along > 0.0 && close(p, pinhole_dir.normalize() * along)
        };
        let z_is_focus = (dir.z - focus).abs() <= 1e-5 * focus;
        if close(origin, lens) && z_is_focus && on_pinhole_ray(origin + dir) {
            return None;
        }
        let mistake = if !origin.is_finite() || !dir.is_finite() {
            "the ray is not finite".to_string()
        } else if !close(origin, lens) {
            if close(origin, Vec3::ZERO) {
                "the ray starts at the lens centre: it has to leave from the lens point, or \
                 every ray is the pinhole ray and nothing blurs"
                    .to_string()
            } else {
                format!("the ray has to start at the lens point {lens}")
            }
        } else if dir.z.abs() < 1e-6 {
            "the direction runs parallel to the lens: it should reach the focal plane".to_string()
        } else {
            // Where the ray, continued, crosses the focal plane.
            let crossing = origin + dir * (focus / dir.z);
            let parallel = close(dir.normalize(), pinhole_dir.normalize());
            if parallel && lens_point != Vec2::ZERO {
                "the ray runs parallel to the pinhole ray, shifted by the lens point: it must \
                 meet the pinhole ray in the focal plane, or nothing is ever in focus"
                    .to_string()
            } else if !z_is_focus && on_pinhole_ray(crossing) {
                format!(
                    "the ray goes the right way, but its direction has z = {}, not the focus \
                     distance {focus}: the direction asked for is P_f - P_l",
                    dir.z
                )
            } else {
                format!(
                    "the ray crosses the focal plane z = {focus} at {crossing}, off the pinhole \
                     ray: it should cross where the pinhole ray does"
                )
            }
        };
        Some(format!(
            "{mistake}.\n  pinhole direction {pinhole_dir}, lens point {lens_point}, focus \
             distance {focus}: your thin_lens_ray gave origin {origin}, direction {dir}"
        ))
    }

    fn check_thin_lens(pinhole_dir: Vec3, lens_point: Vec2, focus: f32) {
        let ray = thin_lens_ray(pinhole_dir, lens_point, focus);
        if let Some(mistake) = thin_lens_mistake(pinhole_dir, lens_point, focus, ray) {
            panic!("thin_lens_ray: {mistake}");
        }
    }

    #[test]
    fn exercise_thin_lens_ray_passes_through_the_focus_point() {
        check_thin_lens(Vec3::new(0.2, -0.1, 1.0), Vec2::new(0.3, -0.05), 4.0);
        check_thin_lens(Vec3::new(-0.4, 0.25, 1.0), Vec2::new(-0.1, 0.2), 0.5);
        check_thin_lens(Vec3::new(0.0, 0.0, 1.0), Vec2::new(0.05, 0.05), 100.0);
    }

    #[test]
    fn exercise_thin_lens_ray_accepts_a_pinhole_direction_of_any_length() {
        // The same pinhole ray, written with two lengths; and the lens centre.
        check_thin_lens(Vec3::new(0.1, 0.3, 1.0), Vec2::new(-0.2, 0.4), 2.0);
        check_thin_lens(Vec3::new(0.5, 1.5, 5.0), Vec2::new(-0.2, 0.4), 2.0);
        check_thin_lens(Vec3::new(0.06, 0.18, 0.6), Vec2::ZERO, 2.0);
    }

    /// The unit-size aperture point that `u` picks, by the lens's shape and warp.
    fn unit_aperture_point(lens: &Lens, u: Vec2) -> Vec2 {
        match lens.aperture {
            Aperture::Disc => lens.warp.sample(u),
            Aperture::Polygon { blades, rotation } => {
                sample_uniform_regular_polygon(u, blades, rotation)
            }
        }
    }

    /// `v` in the camera's own axes (x left, y up, z forward).
    fn to_camera(camera: &ThinLensCamera, v: Vec3) -> Vec3 {
        let frame = &camera.pinhole.frame;
        Vec3::new(v.dot(frame.left), v.dot(frame.up), v.dot(frame.forward))
    }

    /// Where `ray` crosses the lens plane z = 0, in camera space: the lens point it left from.
    fn lens_crossing(camera: &ThinLensCamera, ray: &Ray) -> Vec2 {
        let origin = to_camera(camera, ray.origin - camera.pinhole.frame.origin);
        let dir = to_camera(camera, ray.dir);
        (origin - dir * (origin.z / dir.z)).truncate()
    }

    /// The ray the lecture's recipe gives, worked out here step by step in camera space.
    fn recipe_ray(
        camera: &ThinLensCamera,
        p_film: Vec2,
        lens_point: Vec2,
        focus_point: Vec3,
    ) -> Ray {
        let frame = &camera.pinhole.frame;
        let origin = lens_point.extend(0.0);
        let dir = focus_point - origin;
        let start = origin + dir * (camera.pinhole.near_clip / dir.z);
        let _ = p_film;
        Ray::new(
            frame.origin + frame.to_world(start),
            frame.to_world(dir.normalize()),
        )
    }

    /// What is wrong with `ray = camera.generate_ray_through(p_film, u)`, in words; `None` if
    /// it is right.
    fn thin_lens_camera_mistake(
        camera: &ThinLensCamera,
        p_film: Vec2,
        u: Vec2,
        ray: &Ray,
    ) -> Option<String> {
        let lens = &camera.lens;
        let (radius, focus) = (lens.aperture_radius, lens.focus_distance);
        let pinhole_dir = camera.pinhole.camera_direction(p_film);
        // Where the pinhole ray meets the focal plane: the thin-lens ray from the lens centre
        // reaches it there.
        let focus_point = {
            let (centre, to_focus) = thin_lens_ray(pinhole_dir, Vec2::ZERO, focus);
            centre + to_focus
        };
        let unit = unit_aperture_point(lens, u);
        let expected = recipe_ray(camera, p_film, radius * unit, focus_point);
        let scale = 1.0 + radius + camera.pinhole.frame.origin.length();
        let near = |a: Vec3, b: Vec3, tolerance: f32| (a - b).length() <= tolerance;
        if near(ray.origin, expected.origin, 1e-5 * scale) && near(ray.dir, expected.dir, 1e-5) {
            return None;
        }
        let same_line = |other: &Ray| {
            near(
                lens_crossing(camera, ray).extend(0.0),
                lens_crossing(camera, other).extend(0.0),
                1e-4 * scale,
            ) && near(ray.dir.normalize(), other.dir, 1e-4)
        };
        // The same recipe with one step slipped.
        let with_lens_point = |p: Vec2| recipe_ray(camera, p_film, p, focus_point);
        let concentric = ch02_monte_carlo::warps::sample_uniform_disc_concentric(u);
        let naive = ch02_monte_carlo::warps::sample_disc_naive(u);
        let along_the_ray = pinhole_dir.normalize() * focus;
        let frame = &camera.pinhole.frame;
        let start_camera = to_camera(camera, expected.origin - frame.origin);
        let dir_camera = to_camera(camera, expected.dir);
        let mistake = if !ray.origin.is_finite() || !ray.dir.is_finite() {
            "the ray is not finite".to_string()
        } else if same_line(&expected) && (ray.dir.length() - 1.0).abs() > 1e-4 {
            format!(
                "the direction is not of unit length (its length is {}): normalise it",
                ray.dir.length()
            )
        } else if same_line(&expected) {
            let start = to_camera(camera, ray.origin - camera.pinhole.frame.origin);
            format!(
                "the ray runs along the right line but starts at camera-space z = {}: it should \
                 start at the near clipping plane, z = {}, as the pinhole's rays do",
                start.z, camera.pinhole.near_clip
            )
        } else if radius > 0.0 && same_line(&camera.pinhole.generate_ray(p_film)) {
            "the ray is the pinhole ray: the lens point is not used as the ray's origin, so \
             nothing blurs"
                .to_string()
        } else if radius > 0.0 && lens_crossing(camera, ray).length() < 1e-4 * scale {
            "the ray leaves from the lens centre: the lens point is not used as the ray's \
             origin"
                .to_string()
        } else if same_line(&with_lens_point(radius * Vec2::new(-unit.x, unit.y))) {
            "the lens point's x is mirrored: camera-space +x points to the image's left (as in \
             chapter 01 and Mitsuba), and the lens point's x is taken along it, the frame's \
             left vector"
                .to_string()
        } else if radius != 1.0 && same_line(&with_lens_point(unit)) {
            format!(
                "the lens point is not scaled by the aperture radius {radius}: the aperture \
                 shape is of unit size"
            )
        } else if same_line(&with_lens_point(2.0 * radius * unit)) {
            "the lens point is twice as far from the centre as it should be: the aperture \
             diameter was used as its radius"
                .to_string()
        } else if same_line(&with_lens_point(radius * naive)) && lens.warp != LensWarp::Naive {
            "the lens point comes from the naive disc warp, r = ξ, which is not uniform: too \
             many rays through the middle of the lens"
                .to_string()
        } else if same_line(&with_lens_point(radius * concentric)) {
            format!(
                "the lens point ignores the lens's aperture and warp ({:?}, {:?}): draw it with \
                 the lens's own warp, or its polygon",
                lens.aperture, lens.warp
            )
        } else if same_line(&recipe_ray(camera, p_film, radius * unit, along_the_ray)) {
            format!(
                "the ray does not meet the pinhole ray on the focal plane: the focus point was \
                 put at focus_distance {focus} along the pinhole ray, but the focal plane is \
                 z = {focus}, measured along the optical axis"
            )
        } else if near(ray.origin, start_camera, 1e-4 * scale)
            || near(ray.dir.normalize(), dir_camera, 1e-4)
        {
            "the ray is still in camera space: its origin and direction must be taken into the \
             world by the camera's frame"
                .to_string()
        } else if near(ray.origin + frame.origin, expected.origin, 1e-4 * scale) {
            "the ray's origin is taken into the world without the camera's position: add the \
             frame's origin"
                .to_string()
        } else {
            let crossing = lens_crossing(camera, ray);
            format!(
                "the ray should leave the lens point {} (camera space, lens plane z = 0) towards \
                 the focus point {focus_point}, where the pinhole ray meets the focal plane; \
                 yours crosses the lens plane at {crossing}",
                radius * unit
            )
        };
        Some(format!(
            "{mistake}.\n  lens radius {radius}, focus distance {focus}, {:?} aperture, {:?} \
             warp; film position {p_film}, lens sample {u}:\n  your ray {:?}\n  expected {:?}",
            lens.aperture, lens.warp, ray, expected
        ))
    }

    fn check_thin_lens_camera(camera: &ThinLensCamera, p_film: Vec2, u: Vec2) {
        let ray = camera.generate_ray_through(p_film, u);
        if let Some(mistake) = thin_lens_camera_mistake(camera, p_film, u, &ray) {
            panic!("generate_ray_through: {mistake}");
        }
    }

    /// A camera looking along a slanted axis, so that camera and world axes all differ.
    fn slanted() -> PinholeCamera {
        let frame = CameraFrame::look_at(
            Vec3::new(2.0, 1.0, -3.0),
            Vec3::new(-1.0, 0.5, 4.0),
            Vec3::Y,
        )
        .unwrap();
        PinholeCamera::new(frame, 45.0, 80, 60)
    }

    #[test]
    fn exercise_thin_lens_camera_follows_the_recipe() {
        let hexagon = Aperture::polygon(6, 0.3).unwrap();
        let lenses = [
            Lens::new(0.4, 3.0).unwrap(),
            Lens::new(0.25, 7.5).unwrap().with_warp(LensWarp::Polar),
            Lens::new(1.5, 2.0).unwrap().with_warp(LensWarp::Naive),
            Lens::new(0.6, 4.0).unwrap().with_aperture(hexagon),
        ];
        let samples = [
            Vec2::new(0.1, 0.9),
            Vec2::new(0.7, 0.2),
            Vec2::new(0.95, 0.6),
            Vec2::new(0.3, 0.35),
        ];
        for pinhole in [pinhole(), slanted()] {
            for lens in lenses {
                let camera = ThinLensCamera::new(pinhole, lens);
                for p_film in [Vec2::new(10.3, 40.7), Vec2::new(60.0, 5.5)] {
                    for u in samples {
                        check_thin_lens_camera(&camera, p_film, u);
                    }
                }
            }
        }
    }

    #[test]
    fn exercise_thin_lens_camera_rays_meet_at_the_focus_point() {
        let camera = ThinLensCamera::new(pinhole(), Lens::new(0.4, 3.0).unwrap());
        let p_film = Vec2::new(10.3, 40.7);
        let pinhole_ray = camera.pinhole.generate_ray(p_film);
        // The focal plane is 3 in front of the lens along the viewing axis (world -z here).
        let t_focus = |ray: &Ray| (ray.origin.z - (5.0 - 3.0)) / -ray.dir.z;
        let focus_point = pinhole_ray.at(t_focus(&pinhole_ray));
        for u in [
            Vec2::new(0.1, 0.9),
            Vec2::new(0.7, 0.2),
            Vec2::new(0.5, 0.5),
        ] {
            let ray = camera.generate_ray_through(p_film, u);
            let crossing = ray.at(t_focus(&ray));
            assert!(
                crossing.distance(focus_point) < 1e-4,
                "generate_ray_through: every ray of one film position must pass through the \
                 focus point {focus_point}, where the pinhole ray meets the focal plane (3 in \
                 front of the lens); the ray from lens sample {u} crosses that plane at \
                 {crossing}"
            );
        }
    }

    #[test]
    fn exercise_thin_lens_camera_lens_points_lie_left_and_up() {
        // Camera +x is the image's left; the lens sample (1, 1/2) of the concentric map is the
        // point (R, 0) of camera space, so the ray starts R to the camera's left.
        let camera = ThinLensCamera::new(pinhole(), Lens::new(0.5, 3.0).unwrap());
        let ray = camera.generate_ray_through(Vec2::new(32.0, 24.0), Vec2::new(1.0 - 1e-7, 0.5));
        let crossing = lens_crossing(&camera, &ray);
        assert!(
            (crossing - Vec2::new(0.5, 0.0)).length() < 1e-3,
            "generate_ray_through: the lens sample (1, 1/2) is the lens point 0.5 to the \
             camera's left (camera-space (R, 0) for a lens of radius R = 0.5), but your ray \
             leaves the lens plane at camera-space {crossing}"
        );
    }

    /// The chi-square test of the lens points of a camera with `lens` (read off its rays where
    /// they cross the lens plane) against the uniform density over the lens's aperture.
    fn lens_chi2(lens: Lens) -> ch02_monte_carlo::chi2::Chi2Result {
        use ch02_monte_carlo::warps::{Domain, WarpPoint};
        let camera = ThinLensCamera::new(slanted(), lens);
        let r = lens.aperture_radius;
        let area = lens.aperture.area() * r * r;
        let uniform = Lens {
            warp: LensWarp::Concentric,
            ..lens
        };
        ch02_monte_carlo::chi2::chi2_test_density(
            Domain::Plane {
                min: Vec2::splat(-r),
                max: Vec2::splat(r),
            },
            100_000,
            5,
            (16, 16),
            |u| {
                let ray = camera.generate_ray_through(Vec2::new(33.0, 21.0), u);
                WarpPoint::Plane(lens_crossing(&camera, &ray))
            },
            |point| match point {
                WarpPoint::Plane(p) if uniform.sample_point_pdf(p) > 0.0 => 1.0 / area,
                _ => 0.0,
            },
        )
    }

    #[test]
    fn exercise_thin_lens_camera_lens_points_are_uniform() {
        let level = ch02_monte_carlo::chi2::significance_level(3, 0.01);
        let disc = Lens::new(0.5, 2.0).unwrap();
        let hexagon = disc.with_aperture(Aperture::polygon(6, 0.3).unwrap());
        for lens in [disc, disc.with_warp(LensWarp::Polar), hexagon] {
            let result = lens_chi2(lens);
            if result.p_value > level {
                continue;
            }
            let camera = ThinLensCamera::new(slanted(), lens);
            let points: Vec<Vec2> = (0..300 * 300)
                .map(|i| {
                    let u = (Vec2::new((i % 300) as f32, (i / 300) as f32) + 0.5) / 300.0;
                    let ray = camera.generate_ray_through(Vec2::new(33.0, 21.0), u);
                    lens_crossing(&camera, &ray)
                })
                .collect();
            let r = lens.aperture_radius;
            panic!(
                "{} (a lens of radius {r}, {:?} aperture, {:?} warp: is every lens point drawn \
                 uniformly over the aperture, at the lens's size?)",
                workbench::test_support::not_uniform(
                    "ch04-thin-lens-camera",
                    "generate_ray_through",
                    "lens",
                    result.p_value,
                    &points,
                    &|p| {
                        let inside = lens.with_warp(LensWarp::Concentric).sample_point_pdf(p);
                        if inside > 0.0 {
                            f64::from(1.0 / (lens.aperture.area() * r * r))
                        } else {
                            0.0
                        }
                    },
                    [Vec2::splat(-r), Vec2::splat(r)],
                ),
                lens.aperture,
                lens.warp,
            );
        }
    }

    #[test]
    fn exercise_thin_lens_camera_mean_lens_radius_is_two_thirds_of_the_radius() {
        // For points uniform over a disc of radius R, r has density 2r / R², so E[r] = 2R/3
        // and Var[r] = R²/2 - 4R²/9 = R²/18.
        for warp in [LensWarp::Concentric, LensWarp::Polar] {
            let lens = Lens::new(0.8, 3.0).unwrap().with_warp(warp);
            let camera = ThinLensCamera::new(slanted(), lens);
            let n = 50_000u64;
            let mut sampler = IndependentSampler::new(11);
            let mean = (0..n)
                .map(|i| {
                    sampler.start_pixel_sample(UVec2::new(i as u32 % 97, 0), i);
                    let ray = camera.generate_ray_through(Vec2::new(20.0, 30.0), sampler.get_2d());
                    f64::from(lens_crossing(&camera, &ray).length())
                })
                .sum::<f64>()
                / n as f64;
            let r = 0.8f64;
            let z = (mean - 2.0 * r / 3.0) / (r * r / 18.0 / n as f64).sqrt();
            // 4 standard errors: a correct lens fails this one time in 15 000.
            assert!(
                z.abs() < 4.0,
                "generate_ray_through: the lens points of a lens of radius {r} ({warp:?} warp) \
                 lie on average {mean:.4} from its centre; points spread evenly over the disc \
                 lie on average two thirds of the radius away, {:.4} ({z:.1} standard errors \
                 off: too near the centre, or a lens of the wrong size?)",
                2.0 * r / 3.0
            );
        }
    }

    #[test]
    fn the_uniformity_test_refuses_the_naive_warp() {
        // The naive warp's points crowd the centre: the same test must see it.
        let naive = Lens::new(0.5, 2.0).unwrap().with_warp(LensWarp::Naive);
        let result = lens_chi2(naive);
        assert!(result.p_value < 1e-9, "{result:?}");
    }

    /// Counts how many dimensions a sampler hands out after the pixel.
    #[derive(Clone)]
    struct Counting {
        inner: IndependentSampler,
        draws: std::sync::Arc<std::sync::atomic::AtomicU64>,
    }

    impl Sampler for Counting {
        fn start_pixel_sample(&mut self, pixel: UVec2, index: u64) {
            self.inner.start_pixel_sample(pixel, index);
        }
        fn get_pixel_2d(&mut self) -> Vec2 {
            self.inner.get_pixel_2d()
        }
        fn get_1d(&mut self) -> f32 {
            self.draws
                .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            self.inner.get_1d()
        }
    }

    #[test]
    fn a_pinhole_lens_draws_no_lens_sample_and_a_real_one_draws_two_numbers() {
        let draws = std::sync::Arc::new(std::sync::atomic::AtomicU64::new(0));
        let mut sampler = Counting {
            inner: IndependentSampler::new(1),
            draws: draws.clone(),
        };
        sampler.start_pixel_sample(UVec2::ZERO, 0);
        let p = Vec2::new(3.5, 2.5);
        let ray = ThinLensCamera::new(pinhole(), Lens::PINHOLE).generate_ray(p, &mut sampler);
        assert_eq!(draws.load(std::sync::atomic::Ordering::Relaxed), 0);
        assert_eq!(ray, pinhole().generate_ray(p));
        ThinLensCamera::new(pinhole(), Lens::new(0.1, 2.0).unwrap()).generate_ray(p, &mut sampler);
        assert_eq!(draws.load(std::sync::atomic::Ordering::Relaxed), 2);
    }

    #[test]
    fn exercise_thin_lens_camera_extreme_lenses_give_finite_rays() {
        for (radius, focus) in [(1e3, 1e-4), (1e3, 1e8), (1e-6, 1e-4), (0.5, 1e8)] {
            let camera = ThinLensCamera::new(pinhole(), Lens::new(radius, focus).unwrap());
            for p in [Vec2::ZERO, Vec2::new(64.0, 48.0), Vec2::new(17.2, 3.9)] {
                for u in [Vec2::ZERO, Vec2::splat(0.5), Vec2::splat(1.0 - 1e-7)] {
                    let ray = camera.generate_ray_through(p, u);
                    assert!(
                        ray.origin.is_finite()
                            && ray.dir.is_finite()
                            && (ray.dir.length() - 1.0).abs() < 1e-5,
                        "generate_ray_through: a lens of radius {radius} focused at {focus} gave \
                         the ray {ray:?} (film position {p}, lens sample {u}): a camera ray \
                         has a finite origin and a direction of unit length, whatever the lens"
                    );
                }
            }
        }
    }
}
