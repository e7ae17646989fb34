//! A thin pane of glass (Mitsuba's `thindielectric`): light is reflected or passes straight
//! through, never bent, because the pane's two faces are parallel and close.
//!
//! One face reflects `R = F(cos θ)`, the dielectric Fresnel share. Light that enters bounces
//! between the faces, so the pane reflects `R' = R + T² R + T² R³ + ... = R + T² R / (1 - R²)`
//! with `T = 1 - R`, which is `2R / (1 + R)`, and lets `1 - R'` through (no absorption).
//! The sample picks reflection with probability `R'`, so each branch has weight 1; both are
//! deltas, and the pane scales no radiance (it leaves the light in the medium it came from).

use ch01_whitted::optics::{fresnel_dielectric, reflect};
use ch08_path_tracing::bsdf::BsdfSample;
use common::geometry::SurfaceHit;
use glam::Vec3;

/// The pane's reflectance `R' = 2R / (1 + R)` for light arriving at `cos_i` (in `[0, 1]`),
/// the inside bounces included; `eta` is the pane's index over the surroundings'.
pub fn reflectance(cos_i: f32, eta: f32) -> f32 {
    let single = fresnel_dielectric(cos_i, 1.0 / eta);
    2.0 * single / (1.0 + single)
}

/// The mirror direction with probability `R'`, else `-wo` (straight on), with the number `u`.
pub fn sample(hit: &SurfaceHit, wo: Vec3, int_ior: f32, ext_ior: f32, u: f32) -> BsdfSample {
    // About the shading normal, as Mitsuba's shading frame has it.
    let cos_o = wo.dot(hit.shading_n);
    let normal = if cos_o >= 0.0 {
        hit.shading_n
    } else {
        -hit.shading_n
    };
    let wi = if u < reflectance(cos_o.abs().min(1.0), int_ior / ext_ior) {
        reflect(-wo, normal)
    } else {
        -wo
    };
    BsdfSample {
        wi,
        weight: Vec3::ONE,
        pdf: f32::INFINITY,
        eta_scale: 1.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_inside_bounces_add_up_to_two_r_over_one_plus_r() {
        for cos in [1.0, 0.6, 0.2] {
            let r = fresnel_dielectric(cos, 1.0 / 1.5);
            let t = 1.0 - r;
            // The geometric series, summed term by term.
            let mut series = r;
            let mut inside = t * t * r;
            for _ in 0..50 {
                series += inside;
                inside *= r * r;
            }
            assert!((reflectance(cos, 1.5) - series).abs() < 1e-6, "cos {cos}");
        }
        // Glass of 1.5 square on: R = 0.04, R' = 0.08 / 1.04.
        assert!((reflectance(1.0, 1.5) - 0.08 / 1.04).abs() < 1e-6);
        // No interface, no reflection; grazing light is reflected whole.
        assert_eq!(reflectance(0.7, 1.0), 0.0);
        assert!((reflectance(0.0, 1.5) - 1.0).abs() < 1e-6);
    }
}
