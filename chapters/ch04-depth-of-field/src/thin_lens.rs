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
    #[inline]
    pub fn generate_ray<S: Sampler>(&self, p_film: Vec2, sampler: &mut S) -> Ray {
        if self.lens.is_pinhole() {
            return self.pinhole.generate_ray(p_film);
        }
        let u_lens = sampler.get_2d();
        self.generate_ray_through(p_film, u_lens)
    }
    // ANCHOR_END: generate_ray

    /// The camera ray through film position `p_film` from the lens point that `u_lens` picks.
    pub fn generate_ray_through(&self, p_film: Vec2, u_lens: Vec2) -> Ray {
        let lens_point = self.lens.sample_point(u_lens);
        let pinhole_dir = self.pinhole.camera_direction(p_film);
        let (origin, dir) = thin_lens_ray(pinhole_dir, lens_point, self.lens.focus_distance);
        // Start at the near plane, as the pinhole does (Mitsuba adds `near_clip / d.z` times
        // the unit direction; with `dir.z = focus_distance` that is this).
        let start = origin + dir * (self.pinhole.near_clip / dir.z);
        let frame = &self.pinhole.frame;
        Ray::new(
            frame.origin + frame.to_world(start),
            frame.to_world(dir.normalize()),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
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
    /// in words; `None` if it is right.
    fn thin_lens_mistake(
        pinhole_dir: Vec3,
        lens_point: Vec2,
        focus: f32,
        (origin, dir): (Vec3, Vec3),
    ) -> Option<String> {
        let lens = lens_point.extend(0.0);
        // Where the pinhole ray crosses the focal plane z = focus.
        let focus_point = pinhole_dir * (focus / pinhole_dir.z);
        let close = |a: Vec3, b: Vec3| (a - b).length() <= 1e-5 * b.length().max(1.0);
        if close(origin, lens) && close(dir, focus_point - lens) {
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
            let crossing = origin + dir * (focus / dir.z);
            if close(crossing, focus_point + lens) {
                "the ray runs parallel to the pinhole ray, shifted by the lens point: it must \
                 meet the pinhole ray in the focal plane, or nothing is ever in focus"
                    .to_string()
            } else if (dir.z - focus).abs() > 1e-4 * focus && close(crossing, focus_point) {
                format!(
                    "the ray goes the right way, but its direction has z = {}, not the focus \
                     distance {focus}: the direction asked for is P_f - P_l",
                    dir.z
                )
            } else {
                format!(
                    "the ray crosses the focal plane z = {focus} at {crossing}; it should cross \
                     where the pinhole ray does, at {focus_point}"
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

    #[test]
    fn every_lens_ray_of_a_film_position_meets_at_the_focus_point() {
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
            assert_relative_eq!(ray.dir.length(), 1.0, epsilon = 1e-6);
            assert_relative_eq!(ray.at(t_focus(&ray)), focus_point, epsilon = 1e-5);
            // It starts on the near plane, near_clip in front of the lens plane.
            assert_relative_eq!(ray.origin.z, 5.0 - camera.pinhole.near_clip, epsilon = 1e-6);
        }
    }

    #[test]
    fn lens_points_lie_in_the_lens_plane_left_and_up() {
        // Camera +x is the image's left; the lens sample (1, 1/2) of the concentric map is the
        // point (R, 0) of camera space, so the ray starts R to the camera's left.
        let camera = ThinLensCamera::new(pinhole(), Lens::new(0.5, 3.0).unwrap());
        let ray = camera.generate_ray_through(Vec2::new(32.0, 24.0), Vec2::new(1.0 - 1e-7, 0.5));
        let left = camera.pinhole.frame.left;
        let start = ray.origin - camera.pinhole.frame.origin;
        assert_relative_eq!(start.dot(left), 0.5 * (1.0 - 0.01 / 3.0), epsilon = 1e-4);
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
    fn extreme_lenses_give_finite_rays() {
        for (radius, focus) in [(1e3, 1e-4), (1e3, 1e8), (1e-6, 1e-4), (0.5, 1e8)] {
            let camera = ThinLensCamera::new(pinhole(), Lens::new(radius, focus).unwrap());
            for p in [Vec2::ZERO, Vec2::new(64.0, 48.0), Vec2::new(17.2, 3.9)] {
                for u in [Vec2::ZERO, Vec2::splat(0.5), Vec2::splat(1.0 - 1e-7)] {
                    let ray = camera.generate_ray_through(p, u);
                    assert!(
                        ray.origin.is_finite() && ray.dir.is_finite(),
                        "R {radius}, d_f {focus}: {ray:?}"
                    );
                    assert_relative_eq!(ray.dir.length(), 1.0, epsilon = 1e-5);
                }
            }
        }
    }
}
