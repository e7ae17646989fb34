//! How large a point at depth `d` appears when the lens focuses at `d_f`: the circle of
//! confusion.
//!
//! **In Mitsuba's terms** (aperture radius `R`, focus distance `d_f`, no focal length): the
//! rays through one film position leave the lens disc of radius `R` and all meet at the focus
//! point on the plane `z = d_f`. Look at it the other way round: which film positions see a
//! point `Q` at depth `d`? A ray from lens point `P_l` through `Q` goes on to the focal plane
//! and meets it at some point `P_f`: where, by similar triangles? As `P_l` runs over the
//! lens disc, `P_f` runs over a disc on the focal plane: of which radius? The film sees the
//! focal plane through the pinhole at scale `1 / d_f` (tangent units, the pinhole's `z = 1`
//! plane), so the point's image is a disc whose diameter, in tangent units, is the exercise
//! below (times `W / (2 tan(fov_x / 2))` in pixels).
//!
//! **In a photographer's terms** (focal length `f`, aperture diameter `D = f / F`, film at
//! `v = f d_f / (d_f - f)` behind the lens by the thin lens equation): the blur disc on the
//! film ([`circle_of_confusion_on_film`]) covers the same angle as the diameter above with
//! `D = 2R`, so it is that diameter times `v`: the two models agree, and Mitsuba's only drops
//! the focal length, which affects nothing but the film's distance (and that the field of view
//! already fixes). The chapter's thin-lens diagram traces the rays through the lens to the film
//! and checks that similar triangles give the same disc.
//!
//! The blur grows without bound in front of the focal plane (as `d → 0`) but tends to a finite
//! limit behind it (as `d → ∞`): a distant background is never blurred more than that, which is
//! why a far focus keeps everything behind it nearly sharp (the hyperfocal trick).

use crate::thin_lens::ThinLensCamera;
use ch01_whitted::camera::PinholeCamera;
use common::geometry::Sphere;

// ANCHOR: circle_of_confusion
/// The diameter of the circle of confusion of a point at depth `depth` (along the camera's
/// axis), for a lens of radius `aperture_radius` focused at `focus_distance`, in the tangent
/// units of the pinhole's `z = 1` plane: the width of the patch of that plane the point's
/// image spreads over.
pub fn circle_of_confusion(aperture_radius: f32, focus_distance: f32, depth: f32) -> f32 {
    // BEGIN SOLUTION
    2.0 * aperture_radius * (depth - focus_distance).abs() / (depth * focus_distance)
    // END SOLUTION
}
// ANCHOR_END: circle_of_confusion

/// The same diameter in pixels of `camera`'s film: one pixel spans `2 tan(fov_x / 2) / W`
/// tangent units.
pub fn circle_of_confusion_pixels(
    camera: &PinholeCamera,
    aperture_radius: f32,
    focus_distance: f32,
    depth: f32,
) -> f32 {
    let pixels_per_tangent_unit = camera.width as f32 / (2.0 * camera.tan_half_fov_x);
    circle_of_confusion(aperture_radius, focus_distance, depth) * pixels_per_tangent_unit
}

/// The photographer's version: the blur disc's diameter *on the film*, for focal length
/// `focal_length`, aperture diameter `aperture_diameter` (`D = f / F`), focused at
/// `focus_distance`: the angle [`circle_of_confusion`] measures, at the film's distance behind
/// the lens. NaN when the focus distance does not exceed the focal length (no real image).
pub fn circle_of_confusion_on_film(
    focal_length: f32,
    aperture_diameter: f32,
    focus_distance: f32,
    depth: f32,
) -> f32 {
    let film_distance =
        crate::lens::image_distance(focal_length, focus_distance).unwrap_or(f32::NAN);
    circle_of_confusion(aperture_diameter / 2.0, focus_distance, depth) * film_distance
}

// ANCHOR: measured_blur
/// The width, in pixels, of the band of film positions along the image's middle row from
/// which at least one lens ray hits `sphere`, measured to a small fraction of a pixel.
///
/// This measures the circle of confusion without the formula: for a small `sphere` on the
/// camera's axis the band is the blur circle widened by the sphere's own image. The sphere
/// may be tiny (a radius of 0.003 at a lens radius of 0.15): every film position that sees it
/// through some point of the lens counts, however narrow the strip of lens points it is seen
/// through. The chapter's page gives a method.
///
/// Which points of the lens can send a ray from the middle row to a sphere on the axis, and
/// how do you pick exactly those with a lens sample? A film position either sees the sphere
/// or not: how do you find, to a tiny fraction of a pixel, where the band ends on each side,
/// without trying every position?
///
/// # Panics
///
/// If the middle of the row does not see the sphere at all (it is not on the axis).
pub fn measured_blur_width(camera: &ThinLensCamera, sphere: &Sphere) -> f32 {
    // BEGIN SOLUTION
    use crate::aperture::LensWarp;
    use glam::Vec2;
    let row = camera.pinhole.height as f32 / 2.0;
    // The sphere sits on the axis and the film positions on the middle row, so the rays
    // that can hit it leave from the lens's horizontal diameter: sample it densely (the
    // polar warp's u = (0, r^2) and (1/2, r^2) are its two halves), rim included.
    let lens_samples: Vec<Vec2> = (0..=2000)
        .flat_map(|i| {
            let r = (i as f32 / 2000.0).min(1.0 - 1e-7);
            [Vec2::new(0.0, r * r), Vec2::new(0.5, r * r)]
        })
        .collect();
    let camera = ThinLensCamera {
        lens: camera.lens.with_warp(LensWarp::Polar),
        ..*camera
    };
    let sees = |x: f32| {
        lens_samples.iter().any(|&u| {
            sphere
                .intersect(&camera.generate_ray_through(Vec2::new(x, row), u))
                .is_some()
        })
    };
    let centre = camera.pinhole.width as f32 / 2.0;
    assert!(sees(centre), "the sphere straight ahead is seen");
    let edge = |outside: f32| {
        let (mut inside, mut outside) = (centre, outside);
        for _ in 0..40 {
            let middle = 0.5 * (inside + outside);
            if sees(middle) {
                inside = middle;
            } else {
                outside = middle;
            }
        }
        inside
    };
    edge(camera.pinhole.width as f32) - edge(0.0)
    // END SOLUTION
}
// ANCHOR_END: measured_blur

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lens::Lens;
    use common::scene::CameraFrame;
    use glam::Vec3;

    #[test]
    fn exercise_circle_of_confusion_is_sharp_at_the_focus_and_bounded_far_behind_it() {
        let at_focus = circle_of_confusion(0.3, 4.0, 4.0);
        assert!(
            at_focus == 0.0,
            "circle_of_confusion: a point at the focus distance is imaged sharply, so its circle \
             has diameter 0, not {at_focus}"
        );
        let far = circle_of_confusion(0.3, 4.0, 1e9);
        // The limit for a lens of radius 0.3 focused at 4, worked out beforehand.
        let limit = 0.15;
        assert!(
            (far - limit).abs() < 1e-6,
            "circle_of_confusion: far behind the focus the rays from a point are almost \
             parallel, and the circle tends to the lens's diameter seen from the focus \
             distance, {limit} for a lens of radius 0.3 focused at 4; yours is {far} at depth \
             1e9{}",
            if (2.0 * far - limit).abs() < 1e-6 {
                " (half: the circle's diameter is asked, not its radius)"
            } else {
                ""
            }
        );
        let (front, behind) = (
            circle_of_confusion(0.3, 4.0, 2.0),
            circle_of_confusion(0.3, 4.0, 8.0),
        );
        assert!(
            front > 0.0 && behind > 0.0,
            "circle_of_confusion: a diameter is never negative, in front of the focus (depth 2: \
             {front}) or behind it (depth 8: {behind})"
        );
        let near = circle_of_confusion(0.3, 4.0, 0.1);
        assert!(
            near > 1.0,
            "circle_of_confusion: a point close in front of the lens is badly out of focus, its \
             circle very wide; yours is {near} at depth 0.1 (focus 4, radius 0.3)"
        );
    }

    fn blur_camera() -> ThinLensCamera {
        let frame = CameraFrame::look_at(Vec3::ZERO, Vec3::Z, Vec3::Y).unwrap();
        let pinhole = PinholeCamera::new(frame, 40.0, 200, 60);
        ThinLensCamera::new(pinhole, Lens::new(0.15, 4.0).unwrap())
    }

    /// For each depth of the measured-blur check's sphere on the axis: the band's width in
    /// pixels seen through the whole lens, through its centre alone, and for a sphere twenty
    /// times larger; and the share of the lens's diameter from which the middle film position
    /// sees the sphere. Worked out beforehand by a slow scan of the middle row (film positions a
    /// quarter pixel apart, then 1/200 of a pixel around each end, each tried through 1201
    /// points of the lens's horizontal diameter) and a bisection along the diameter.
    #[rustfmt::skip]
    const SCANNED_BLUR: [(f32, f32, f32, f32, f32); 3] = [
        (1.5, 35.440002, 1.0899963, 56.53, 0.03199997),
        (4.0, 0.41000366, 0.41000366, 8.25, 1.0),
        (10.0, 12.520004, 0.16000366, 15.660004, 0.0133332135),
    ];

    #[test]
    fn exercise_measured_blur_agrees_with_a_slow_scan() {
        let camera = blur_camera();
        let r = camera.lens.aperture_radius;
        let rho = 0.003;
        for (depth, expected, pinhole_only, big_expected, share) in SCANNED_BLUR {
            let sphere = Sphere::new(Vec3::new(0.0, 0.0, depth), rho);
            let too_sparse = format!(
                "Through one film position, the rays that hit a sphere of radius {rho} at depth \
                 {depth} leave from a strip of the lens only {:.4} wide, 1/{:.0} of its \
                 diameter: lens points farther apart than that can all miss it, and then the \
                 film positions between the centre's own band and the true ends look blind to \
                 the search. Space the lens points closer than that (more than {:.0} across \
                 the diameter, rim included; the slow scan uses 1201)",
                share * 2.0 * r,
                1.0 / share,
                (1.0 / share).ceil() + 1.0
            );
            let got =
                workbench::test_support::catch_panic(|| measured_blur_width(&camera, &sphere))
                    .unwrap_or_else(|message| {
                        panic!(
                            "measured_blur_width panicked ({message}) for a sphere of radius {rho} \
                         on the axis at depth {depth}, which the middle of the row sees through \
                         the lens centre and through every lens point near it. Do your lens \
                         points include the centre, or come close enough to it? {too_sparse}"
                        )
                    });
            if (got - expected).abs() <= 0.03 + 0.003 * expected {
                continue;
            }
            let mistake = if !got.is_finite() {
                "the width is not a number".to_string()
            } else if (got - pinhole_only).abs() < 0.05 && (expected - pinhole_only).abs() > 0.5 {
                // The lens centre alone, or lens points too sparse for so small a sphere? A
                // sphere twenty times larger tells: sparse points catch it, the centre does not.
                let big = Sphere::new(Vec3::new(0.0, 0.0, depth), 20.0 * rho);
                let big_got =
                    workbench::test_support::catch_panic(|| measured_blur_width(&camera, &big));
                match big_got {
                    Ok(big_got)
                        if (big_got - big_expected).abs() <= 0.05 + 0.005 * big_expected =>
                    {
                        format!(
                            "your band is only as wide as the lens centre alone sees, yet for a \
                             sphere twenty times larger your width is right ({big_got:.3} px): \
                             your lens points are too far apart for so small a sphere. \
                             {too_sparse}"
                        )
                    }
                    _ => "only the lens centre sends rays: a film position sees the sphere when \
                          a ray from any point of the lens hits it, and the lens's rim reaches \
                          farthest"
                        .to_string(),
                }
            } else if (2.0 * got - expected).abs() <= 0.06 + 0.006 * expected {
                "that is half the band: it has two ends, one on each side of the centre".to_string()
            } else if got < expected {
                format!(
                    "the band is narrower than traced rays find: do your lens points reach the \
                     rim of the lens on both sides, are they close enough together, and does \
                     each end converge on the last position that sees the sphere? On closeness: \
                     {too_sparse}"
                )
            } else {
                "the band is wider than traced rays find: does each end converge on the last \
                 position that still sees the sphere?"
                    .to_string()
            };
            panic!(
                "measured_blur_width: {mistake}.\n  a sphere of radius {rho} at depth {depth} \
                 (lens radius 0.15, focus 4, 200 pixels across): yours measures {got:.3} px, a \
                 slow scan of the row finds {expected:.3} px"
            );
        }
    }

    #[test]
    fn exercise_circle_of_confusion_matches_traced_rays() {
        let frame = CameraFrame::look_at(Vec3::ZERO, Vec3::Z, Vec3::Y).unwrap();
        let pinhole = PinholeCamera::new(frame, 40.0, 400, 100);
        let (radius, focus) = (0.15, 4.0);
        let camera = ThinLensCamera::new(pinhole, Lens::new(radius, focus).unwrap());
        let rho = 0.003;
        for depth in [1.5f32, 3.0, 4.0, 6.0, 20.0] {
            let sphere = Sphere::new(Vec3::new(0.0, 0.0, depth), rho);
            let measured = measured_blur_width(&camera, &sphere);
            let predicted = circle_of_confusion_pixels(&pinhole, radius, focus, depth);
            // The sphere's own image, 2 rho / d in tangent units, widens the band.
            let pixels_per_tangent_unit = 400.0 / (2.0 * pinhole.tan_half_fov_x);
            let own_size = 2.0 * rho / depth * pixels_per_tangent_unit;
            let expected = predicted + own_size;
            assert!(
                (measured - expected).abs() < 0.01 * expected + 0.05,
                "circle_of_confusion: a small sphere at depth {depth} (focus {focus}, lens radius \
                 {radius}) blurs over {measured:.2} px in a traced image; your circle of \
                 confusion predicts {predicted:.2} px (plus {own_size:.2} px for the sphere's own \
                 size), {:.3} times the traced blur without the sphere's size",
                predicted / (measured - own_size)
            );
        }
    }
}
