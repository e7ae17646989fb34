//! The lecture's gotcha: a perturbed ray that goes below the surface.
//!
//! Spreading the mirror direction of a ray that arrives at a grazing angle tilts some of the
//! new directions through the surface: a "reflected" ray that points into the object. The
//! lecture says to check the sign of its dot product with the normal, and to ignore such rays.
//! What exactly "ignore" means changes the image, and whether energy is kept:
//!
//! - [`BelowSurface::Drop`]: the sample contributes nothing. The lobe's share below the
//!   surface is lost, so a rough surface seen at a grazing angle reflects less than it
//!   receives. This is the unbiased estimate of the model as written (a lobe cut off at the
//!   surface), and the default.
//! - [`BelowSurface::Resample`]: draw again until a direction stays above. The lobe is then
//!   renormalised over the directions above the surface: energy is kept, but the lobe is no
//!   longer the one the material describes, and each retry costs two more random numbers.
//!   After [`MAX_RESAMPLES`] failures the sample is dropped (so an impossible case, a lobe
//!   entirely below, cannot loop forever).
//! - [`BelowSurface::Reflect`]: mirror the stray direction back through the surface plane.
//!   Energy is kept too, and the lost part of the lobe piles up just above the horizon.
//!
//! The chapter's energy test measures all three at every angle of incidence.

use common::sampler::Sampler;
use glam::{Vec2, Vec3};

/// What to do with a sampled direction on the wrong side of the surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum BelowSurface {
    /// Ignore the sample: it carries no light.
    Drop,
    /// Draw another direction, up to [`MAX_RESAMPLES`] times.
    Resample,
    /// Mirror the direction back through the surface plane.
    Reflect,
}

/// How many directions [`BelowSurface::Resample`] draws before it gives up.
pub const MAX_RESAMPLES: u32 = 16;

impl BelowSurface {
    /// The three policies, the default first.
    pub const ALL: [BelowSurface; 3] = [
        BelowSurface::Drop,
        BelowSurface::Resample,
        BelowSurface::Reflect,
    ];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            BelowSurface::Drop => "drop",
            BelowSurface::Resample => "resample",
            BelowSurface::Reflect => "reflect",
        }
    }

    // ANCHOR: scatter
    /// A direction from `draw` that leaves on the side `side` points to (the surface normal
    /// for reflection, its negative for refraction), handled by this policy; `None` when the
    /// sample carries no light.
    ///
    /// `draw` turns two uniform numbers into a direction; it is called with the sampler's next
    /// two dimensions, once, or again for each resample. A direction exactly in the surface
    /// plane counts as below: it would run along the surface and light nothing.
    pub fn scatter<S: Sampler>(
        self,
        side: Vec3,
        sampler: &mut S,
        draw: impl Fn(Vec2) -> Vec3,
    ) -> Option<Vec3> {
        let above = |d: Vec3| d.dot(side) > 0.0;
        let d = draw(sampler.get_2d());
        if above(d) {
            return Some(d);
        }
        match self {
            BelowSurface::Drop => None,
            BelowSurface::Resample => (1..MAX_RESAMPLES)
                .map(|_| draw(sampler.get_2d()))
                .find(|&d| above(d)),
            BelowSurface::Reflect => Some(mirror_through_plane(d, side)).filter(|&d| above(d)),
        }
    }
    // ANCHOR_END: scatter
}

/// `d` mirrored through the plane with unit normal `n`: the part along `n` changes sign.
pub fn mirror_through_plane(d: Vec3, n: Vec3) -> Vec3 {
    d - 2.0 * d.dot(n) * n
}

#[cfg(test)]
mod tests {
    use super::*;
    use common::sampler::IndependentSampler;
    use glam::UVec2;

    fn sampler() -> IndependentSampler {
        let mut s = IndependentSampler::new(2);
        s.start_pixel_sample(UVec2::ZERO, 0);
        s
    }

    #[test]
    fn a_direction_above_is_kept_by_every_policy() {
        for policy in BelowSurface::ALL {
            let d = Vec3::new(0.3, 0.1, 0.9).normalize();
            assert_eq!(policy.scatter(Vec3::Z, &mut sampler(), |_| d), Some(d));
        }
    }

    #[test]
    fn a_direction_below_is_dropped_or_mirrored() {
        let below = Vec3::new(0.6, 0.0, -0.8);
        assert_eq!(
            BelowSurface::Drop.scatter(Vec3::Z, &mut sampler(), |_| below),
            None
        );
        assert_eq!(
            BelowSurface::Reflect.scatter(Vec3::Z, &mut sampler(), |_| below),
            Some(Vec3::new(0.6, 0.0, 0.8))
        );
        // A lobe entirely below: resampling gives up instead of looping.
        assert_eq!(
            BelowSurface::Resample.scatter(Vec3::Z, &mut sampler(), |_| below),
            None
        );
    }

    #[test]
    fn resampling_draws_until_a_direction_is_above() {
        // Directions below for u.x < 0.9: resampling finds one above within its retries
        // almost always (0.9^16 = 18 %), and every one it returns is above.
        let draw = |u: Vec2| {
            if u.x < 0.9 {
                -Vec3::Z
            } else {
                Vec3::new(u.y, 0.0, 1.0).normalize()
            }
        };
        let mut s = IndependentSampler::new(9);
        let mut found = 0;
        for i in 0..1000 {
            s.start_pixel_sample(UVec2::ZERO, i);
            if let Some(d) = BelowSurface::Resample.scatter(Vec3::Z, &mut s, draw) {
                assert!(d.z > 0.0);
                found += 1;
            }
        }
        // Expected 1000 (1 - 0.9^16) = 815, binomial standard deviation 12.
        assert!((found as f64 - 814.7).abs() < 60.0, "{found}");
    }

    #[test]
    fn a_direction_in_the_plane_carries_nothing() {
        for policy in BelowSurface::ALL {
            assert_eq!(policy.scatter(Vec3::Z, &mut sampler(), |_| Vec3::X), None);
        }
    }
}
