//! The thin lens: how large its aperture is, where it focuses, and where on it a ray starts.
//!
//! A thin lens of focal length `f` brings the light leaving a point at distance `d` in front
//! of it to a point at distance `d'` behind it, with `1/d + 1/d' = 1/f` (the thin lens
//! equation). With the film fixed at one `d'`, exactly one distance is sharp: the *focus
//! distance* `d_f`, and the points at that distance form the *focal plane*. A point nearer or
//! farther focuses in front of or behind the film and is spread over a small disc there, its
//! circle of confusion ([`crate::circle_of_confusion`]).
//!
//! The photographer's controls are the focal length `f` and the f-number `N`: the aperture's
//! diameter is `f / N`. Mitsuba's `thinlens` sensor takes the aperture *radius* directly and
//! keeps the field of view as the only other lens parameter; both ways are accepted here and
//! both end in the same [`Lens`].

use crate::aperture::{Aperture, LensWarp, sample_aperture_pdf};
use glam::Vec2;

/// A thin lens in the camera's `z = 0` plane, its optical axis the camera's +z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lens {
    /// Radius of the aperture, in scene units; 0 is a pinhole.
    pub aperture_radius: f32,
    /// Distance of the focal plane `z = focus_distance` from the lens, in scene units.
    pub focus_distance: f32,
    /// The shape of the aperture.
    pub aperture: Aperture,
    /// How a point of a disc aperture is drawn.
    pub warp: LensWarp,
}

impl Lens {
    /// The pinhole: no aperture, every ray through the lens centre. (The focus distance is
    /// irrelevant without an aperture; 1 is a valid placeholder.)
    pub const PINHOLE: Lens = Lens {
        aperture_radius: 0.0,
        focus_distance: 1.0,
        aperture: Aperture::Disc,
        warp: LensWarp::Concentric,
    };

    /// A disc-shaped lens of radius `aperture_radius` focused at `focus_distance`, sampled
    /// with Mitsuba's concentric map; or why no such lens exists.
    pub fn new(aperture_radius: f32, focus_distance: f32) -> Result<Self, String> {
        if !(aperture_radius.is_finite() && aperture_radius >= 0.0) {
            return Err(format!(
                "the aperture radius must be a finite number of at least 0, not {aperture_radius}"
            ));
        }
        if !(focus_distance.is_finite() && focus_distance > 0.0) {
            return Err(format!(
                "the focus distance must be a finite positive distance, not {focus_distance}"
            ));
        }
        Ok(Lens {
            aperture_radius,
            focus_distance,
            ..Lens::PINHOLE
        })
    }

    /// The lens a photographer would name: focal length `focal_length` (in scene units) at
    /// f-number `f_number`, so the aperture's diameter is `focal_length / f_number`.
    pub fn from_f_number(
        focal_length: f32,
        f_number: f32,
        focus_distance: f32,
    ) -> Result<Self, String> {
        if !(focal_length.is_finite() && focal_length > 0.0) {
            return Err(format!(
                "the focal length must be a finite positive length, not {focal_length}"
            ));
        }
        if !(f_number.is_finite() && f_number > 0.0) {
            return Err(format!(
                "the f-number must be a finite positive number, not {f_number}"
            ));
        }
        Lens::new(aperture_radius_of(focal_length, f_number), focus_distance)
    }

    /// The same lens with another aperture shape.
    pub fn with_aperture(self, aperture: Aperture) -> Self {
        Self { aperture, ..self }
    }

    /// The same lens with another way of drawing disc points.
    pub fn with_warp(self, warp: LensWarp) -> Self {
        Self { warp, ..self }
    }

    /// Whether every ray goes through the lens centre: then no lens sample is drawn at all.
    pub fn is_pinhole(&self) -> bool {
        self.aperture_radius == 0.0
    }

    /// The density, per unit area of the lens, of the lens points the camera draws
    /// ([`crate::ThinLensCamera::generate_ray_through`]): the unit shape's density divided by
    /// the area factor `R²`.
    pub fn sample_point_pdf(&self, p: Vec2) -> f32 {
        let r = self.aperture_radius;
        sample_aperture_pdf(self.aperture, self.warp, p / r) / (r * r)
    }
}

/// The aperture radius of a lens of focal length `focal_length` at f-number `f_number`: the
/// diameter is `f / N`, so the radius is `f / (2N)`.
pub fn aperture_radius_of(focal_length: f32, f_number: f32) -> f32 {
    focal_length / (2.0 * f_number)
}

/// The film distance behind a thin lens of focal length `focal_length` that brings the focal
/// plane at `focus_distance` into focus: `1/d + 1/d' = 1/f` solved for `d'`. `None` when the
/// plane is not farther than the focal length (no real image).
pub fn image_distance(focal_length: f32, focus_distance: f32) -> Option<f32> {
    (focus_distance > focal_length)
        .then(|| focal_length * focus_distance / (focus_distance - focal_length))
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn the_f_number_divides_the_focal_length() {
        // A 50 mm lens at f/2 (in metres): a 25 mm hole, radius 12.5 mm.
        let lens = Lens::from_f_number(0.05, 2.0, 3.0).unwrap();
        assert_relative_eq!(lens.aperture_radius, 0.0125);
        assert_eq!(lens.focus_distance, 3.0);
    }

    #[test]
    fn impossible_lenses_are_refused_with_the_reason() {
        let cases: [(Result<Lens, String>, &str); 9] = [
            (Lens::new(-1.0, 1.0), "aperture radius"),
            (Lens::new(f32::NAN, 1.0), "aperture radius"),
            (Lens::new(f32::INFINITY, 1.0), "aperture radius"),
            (Lens::new(0.1, 0.0), "focus distance"),
            (Lens::new(0.1, f32::NAN), "focus distance"),
            (Lens::new(0.1, -2.0), "focus distance"),
            (Lens::from_f_number(0.05, 0.0, 1.0), "f-number"),
            (Lens::from_f_number(0.05, -2.0, 1.0), "f-number"),
            (Lens::from_f_number(0.0, 2.0, 1.0), "focal length"),
        ];
        for (result, expected) in cases {
            let message = result.unwrap_err();
            assert!(message.contains(expected), "{message}");
        }
        assert!(Lens::new(0.0, 1e-4).is_ok());
        assert!(Lens::new(1e3, 1e8).is_ok());
    }

    #[test]
    fn the_thin_lens_equation() {
        // Focused at infinity the film sits at f; at 2f it sits at 2f (unit magnification).
        assert_relative_eq!(image_distance(0.05, 1e9).unwrap(), 0.05, epsilon = 1e-6);
        assert_relative_eq!(image_distance(0.05, 0.1).unwrap(), 0.1, epsilon = 1e-6);
        assert!(image_distance(0.05, 0.05).is_none());
    }

    #[test]
    fn the_lens_density_is_spread_over_the_scaled_aperture() {
        let lens = Lens::new(2.0, 5.0).unwrap();
        assert_relative_eq!(
            lens.sample_point_pdf(Vec2::new(0.5, 0.5)),
            1.0 / (std::f32::consts::PI * 4.0),
            epsilon = 1e-7
        );
        assert_eq!(lens.sample_point_pdf(Vec2::new(2.5, 0.0)), 0.0);
    }
}
