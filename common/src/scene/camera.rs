//! The camera as data: where it is, what it sees, its lens, its shutter and its motion.
//!
//! The conventions are Mitsuba 3's: camera space looks down +z with +y up and **+x to the
//! image's left**; the field of view is horizontal. How a ray leaves the camera is the
//! chapters' business: chapter 01's pinhole, chapter 04's thin lens, chapter 05's shutter.

use glam::{Mat4, Vec2, Vec3};

/// Where the camera is and which way it looks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraFrame {
    /// The eye point.
    pub origin: Vec3,
    /// Unit vector to the image's left.
    pub left: Vec3,
    /// Unit vector up in the image.
    pub up: Vec3,
    /// Unit viewing direction.
    pub forward: Vec3,
}

impl CameraFrame {
    /// A camera at `origin` looking at `target`, with `up` roughly up. `None` if the view
    /// direction is zero or parallel to `up`, where no frame exists.
    pub fn look_at(origin: Vec3, target: Vec3, up: Vec3) -> Option<Self> {
        let forward = (target - origin).try_normalize()?;
        let left = up.cross(forward).try_normalize()?;
        let up = forward.cross(left);
        Some(Self {
            origin,
            left,
            up,
            forward,
        })
    }

    /// The frame of a camera-to-world matrix (Mitsuba's columns: left, up, forward, origin).
    pub fn from_matrix(m: &Mat4) -> Self {
        Self {
            origin: m.w_axis.truncate(),
            left: m.x_axis.truncate().normalize(),
            up: m.y_axis.truncate().normalize(),
            forward: m.z_axis.truncate().normalize(),
        }
    }

    /// The camera-to-world matrix of the frame: the inverse of [`from_matrix`](Self::from_matrix).
    pub fn to_matrix(&self) -> Mat4 {
        Mat4::from_cols(
            self.left.extend(0.0),
            self.up.extend(0.0),
            self.forward.extend(0.0),
            self.origin.extend(1.0),
        )
    }

    /// A camera-space direction in world space.
    pub fn to_world(&self, v: Vec3) -> Vec3 {
        v.x * self.left + v.y * self.up + v.z * self.forward
    }
}

/// Pinhole or thin lens.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CameraModel {
    /// Mitsuba's `perspective`: every ray through one point.
    Pinhole,
    /// Mitsuba's `thinlens`: a lens of radius `aperture_radius` in the camera's z = 0 plane,
    /// focused on the plane `z = focus_distance` (chapter 04). Radius 0 is a pinhole.
    ThinLens {
        /// Radius of the lens disc in camera space.
        aperture_radius: f32,
        /// Distance along the camera's +z axis of the plane in focus.
        focus_distance: f32,
    },
}

/// A camera: its place (and motion), its field of view, its lens and its shutter.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    /// Position and orientation; for a moving camera, at its first keyframe.
    pub frame: CameraFrame,
    /// The horizontal field of view in degrees.
    pub fov_x_degrees: f32,
    /// The image's centre moved off the camera's axis by these fractions of the image's width
    /// and height (Mitsuba's `principal_point_offset_x` and `_y`); zero for the usual camera.
    pub principal_point_offset: Vec2,
    /// Rays start this far along the camera axis (Mitsuba's `near_clip`, default 0.01).
    pub near_clip: f32,
    /// Pinhole or thin lens.
    pub model: CameraModel,
    /// Start of the shutter interval.
    pub shutter_open: f32,
    /// End of the shutter interval; equal to `shutter_open` for an instant.
    pub shutter_close: f32,
    /// A moving camera's `(time, camera to world)` keyframes (chapter 05); empty for a camera
    /// that stays at `frame`.
    pub keyframes: Vec<(f32, Mat4)>,
}

impl Camera {
    /// A still pinhole camera at `frame` with a horizontal field of view of `fov_x_degrees`,
    /// and a shutter that opens and closes at time 0.
    pub fn pinhole(frame: CameraFrame, fov_x_degrees: f32) -> Self {
        Self {
            frame,
            fov_x_degrees,
            principal_point_offset: Vec2::ZERO,
            near_clip: 0.01,
            model: CameraModel::Pinhole,
            shutter_open: 0.0,
            shutter_close: 0.0,
            keyframes: Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_frame_when_looking_along_up() {
        assert!(CameraFrame::look_at(Vec3::ZERO, Vec3::Y, Vec3::Y).is_none());
        assert!(CameraFrame::look_at(Vec3::ZERO, Vec3::ZERO, Vec3::Y).is_none());
    }

    #[test]
    fn a_frame_survives_its_matrix() {
        let frame = CameraFrame::look_at(Vec3::new(1.0, 2.0, 3.0), Vec3::ZERO, Vec3::Y).unwrap();
        let back = CameraFrame::from_matrix(&frame.to_matrix());
        assert!((back.origin - frame.origin).length() < 1e-6);
        assert!((back.forward - frame.forward).length() < 1e-6);
        assert!((back.left - frame.left).length() < 1e-6);
    }
}
