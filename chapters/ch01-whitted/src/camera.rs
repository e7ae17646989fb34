//! The pinhole camera: one ray through each film position.
//!
//! The conventions are Mitsuba 3's, so that a scene renders the same here and there: camera
//! space looks down +z with +y up and **+x to the image's left**; the field of view is
//! horizontal; film position `(0, 0)` is the top-left corner of the image.

use common::Ray;
use common::scene::{Camera, CameraFrame};
use glam::{Vec2, Vec3};

// ANCHOR: pinhole
/// An ideal pinhole: every ray starts at the eye and passes through a point of the film.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PinholeCamera {
    /// Position and orientation.
    pub frame: CameraFrame,
    /// `tan(fov_x / 2)`: half the film width at distance 1.
    pub tan_half_fov_x: f32,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Rays start this far along the viewing axis (Mitsuba's `near_clip`).
    pub near_clip: f32,
    /// Where the image's centre sits off the viewing axis, in fractions of the image's width
    /// and height (Mitsuba's `principal_point_offset`; zero for the usual camera).
    pub principal_point_offset: Vec2,
}

impl PinholeCamera {
    /// A camera with horizontal field of view `fov_x_degrees` on a `width x height` film.
    pub fn new(frame: CameraFrame, fov_x_degrees: f32, width: u32, height: u32) -> Self {
        Self {
            frame,
            tan_half_fov_x: (0.5 * fov_x_degrees.to_radians()).tan(),
            width,
            height,
            near_clip: 0.01,
            principal_point_offset: Vec2::ZERO,
        }
    }

    /// The pinhole of the scene's `camera` (its frame at rest, its field of view, near clip
    /// and principal point) on a `width x height` film.
    pub fn of(camera: &Camera, width: u32, height: u32) -> Self {
        Self {
            near_clip: camera.near_clip,
            principal_point_offset: camera.principal_point_offset,
            ..Self::new(camera.frame, camera.fov_x_degrees, width, height)
        }
    }

    /// The same camera on a film of another size (the field of view stays horizontal).
    pub fn with_size(self, width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            ..self
        }
    }

    /// The direction, in camera space and not normalised, through film position `p_film`
    /// (in pixels, `(0, 0)` at the top-left corner).
    pub fn camera_direction(&self, p_film: Vec2) -> Vec3 {
        let u = p_film.x / self.width as f32 + self.principal_point_offset.x;
        let v = p_film.y / self.height as f32 + self.principal_point_offset.y;
        let aspect = self.width as f32 / self.height as f32;
        Vec3::new(
            (1.0 - 2.0 * u) * self.tan_half_fov_x,
            (1.0 - 2.0 * v) * self.tan_half_fov_x / aspect,
            1.0,
        )
    }

    /// The camera ray through `p_film`.
    pub fn generate_ray(&self, p_film: Vec2) -> Ray {
        let d_camera = self.camera_direction(p_film).normalize();
        let dir = self.frame.to_world(d_camera);
        // Start at the near plane, as Mitsuba does: z = near_clip in camera space.
        let origin = self.frame.origin + dir * (self.near_clip / d_camera.z);
        Ray::new(origin, dir)
    }
}
// ANCHOR_END: pinhole

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn camera() -> PinholeCamera {
        let frame = CameraFrame::look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap();
        PinholeCamera::new(frame, 90.0, 200, 100)
    }

    #[test]
    fn the_image_centre_looks_at_the_target() {
        let ray = camera().generate_ray(Vec2::new(100.0, 50.0));
        assert_relative_eq!(ray.dir, Vec3::NEG_Z, epsilon = 1e-6);
        assert_relative_eq!(ray.origin, Vec3::new(0.0, 0.0, 4.99), epsilon = 1e-6);
    }

    #[test]
    fn left_of_the_image_is_camera_plus_x_and_the_top_is_up() {
        let cam = camera();
        // Looking down -z with +y up, the image's left is world -x.
        let left_edge = cam.generate_ray(Vec2::new(0.0, 50.0));
        assert!(left_edge.dir.x < 0.0);
        // 90 degrees horizontally: the left edge is 45 degrees off axis.
        assert_relative_eq!(left_edge.dir.x, -left_edge.dir.z.abs(), epsilon = 1e-6);
        let top = cam.generate_ray(Vec2::new(100.0, 0.0));
        assert!(top.dir.y > 0.0);
        // The vertical half-extent is tan(45°) / aspect = 0.5.
        assert_relative_eq!(top.dir.y / -top.dir.z, 0.5, epsilon = 1e-6);
    }

    #[test]
    fn a_principal_point_offset_moves_the_image_as_in_mitsuba() {
        // Mitsuba 3's ray through the film's centre for fov 40 on a 300 x 200 film with
        // principal_point_offset (0.1, 0.2), in camera space.
        let camera = PinholeCamera {
            principal_point_offset: Vec2::new(0.1, 0.2),
            ..PinholeCamera::new(
                CameraFrame::look_at(Vec3::ZERO, Vec3::Z, Vec3::Y).unwrap(),
                40.0,
                300,
                200,
            )
        };
        let ray = camera.generate_ray(Vec2::new(150.0, 100.0));
        // The camera's frame is the world's: camera space is world space here.
        let mitsuba = Vec3::new(-0.072_264_1, -0.096_352_2, 0.992_721);
        assert_relative_eq!(ray.dir, mitsuba, epsilon = 1e-5);
    }
}
