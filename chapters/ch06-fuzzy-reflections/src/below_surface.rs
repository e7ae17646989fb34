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
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
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
    /// two dimensions, once, or again for each resample, at most [`MAX_RESAMPLES`] times in
    /// all. A direction exactly in the surface plane counts as below: it would run along the
    /// surface and light nothing. What does each policy do with a direction below, and what
    /// must never come back from this function?
    pub fn scatter<S: Sampler>(
        self,
        side: Vec3,
        sampler: &mut S,
        draw: impl Fn(Vec2) -> Vec3,
    ) -> Option<Vec3> {
        // BEGIN SOLUTION
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
            BelowSurface::Reflect => {
                Some(ch01_whitted::optics::reflect(d, side)).filter(|&d| above(d))
            }
        }
        // END SOLUTION
    }
    // ANCHOR_END: scatter
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

    use std::cell::RefCell;

    /// `policy.scatter(side, ..)` with `draw` giving the directions of `lobe` in turn (the last
    /// one again when they run out): the result, and the numbers each draw was given.
    fn scatter_with(policy: BelowSurface, side: Vec3, lobe: &[Vec3]) -> (Option<Vec3>, Vec<Vec2>) {
        let given = RefCell::new(Vec::new());
        let draw = |u: Vec2| {
            let mut given = given.borrow_mut();
            given.push(u);
            lobe[(given.len() - 1).min(lobe.len() - 1)]
        };
        let result = policy.scatter(side, &mut sampler(), draw);
        (result, given.into_inner())
    }

    /// Runs `f` on its own thread and gives up after a few seconds, so that a policy which
    /// never stops drawing fails the check instead of hanging it. A panic of `f` is the
    /// check's panic, with its own message (the thread keeps the test's name).
    fn within_seconds<T: Send + 'static>(what: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
        use std::sync::mpsc::RecvTimeoutError;
        let (sender, receiver) = std::sync::mpsc::channel();
        let name = std::thread::current()
            .name()
            .unwrap_or("scatter")
            .to_owned();
        let worker = std::thread::Builder::new()
            .name(name)
            .spawn(move || {
                let _ = sender.send(f());
            })
            .expect("a thread for the check");
        match receiver.recv_timeout(std::time::Duration::from_secs(10)) {
            Ok(value) => value,
            Err(RecvTimeoutError::Disconnected) => match worker.join() {
                Err(panic) => std::panic::resume_unwind(panic),
                Ok(()) => unreachable!("the thread sends before it ends"),
            },
            Err(RecvTimeoutError::Timeout) => panic!(
                "BelowSurface::scatter: {what} never returned in 10 seconds: does resampling \
                 give up after MAX_RESAMPLES directions in all?"
            ),
        }
    }

    #[test]
    fn exercise_scatter_keeps_directions_above_the_surface() {
        let above = Vec3::new(0.3, 0.1, 0.9).normalize();
        for policy in BelowSurface::ALL {
            for side in [Vec3::Z, -Vec3::Z] {
                let d = if side.z > 0.0 { above } else { -above };
                let (got, given) = scatter_with(policy, side, &[d]);
                assert!(
                    got == Some(d) && given.len() == 1,
                    "BelowSurface::scatter: {policy:?} with the side {side} and a first direction \
                     {d} that leaves on that side gave {got:?} after {} draw(s): a direction \
                     above the surface is kept as it is, after one draw",
                    given.len()
                );
            }
        }
    }

    #[test]
    fn exercise_scatter_never_lets_light_through_the_surface() {
        let below = Vec3::new(0.6, 0.0, -0.8);
        for policy in BelowSurface::ALL {
            for side in [Vec3::Z, -Vec3::Z] {
                for d in [below * side.z, Vec3::X] {
                    let (got, given) =
                        within_seconds("a lobe entirely below the surface", move || {
                            scatter_with(policy, side, &[d])
                        });
                    if let Some(got) = got.filter(|g| g.dot(side) <= 0.0) {
                        panic!(
                            "BelowSurface::scatter: {policy:?} on the side {side} gave {got}, \
                             {}: a ray that leaves on the wrong side goes into the object, and \
                             light would leak through the surface",
                            if got.dot(side) == 0.0 {
                                "in the surface plane (it counts as below: it runs along the \
                                 surface and lights nothing)"
                            } else {
                                "below the surface"
                            }
                        );
                    }
                    let expected_draws = if policy == BelowSurface::Resample {
                        MAX_RESAMPLES as usize
                    } else {
                        1
                    };
                    assert!(
                        given.len() == expected_draws,
                        "BelowSurface::scatter: {policy:?} with every direction below drew {} \
                         direction(s); it draws {expected_draws} in all (MAX_RESAMPLES \
                         directions in all when resampling), and each draw takes two numbers",
                        given.len()
                    );
                }
            }
        }
        // Drop: the sample carries nothing.
        let (got, _) = scatter_with(BelowSurface::Drop, Vec3::Z, &[below]);
        assert!(
            got.is_none(),
            "BelowSurface::scatter: Drop gave {got:?} for a direction below: the sample carries \
             no light"
        );
        // Reflect: only the part along the normal changes sign.
        let (got, _) = scatter_with(BelowSurface::Reflect, Vec3::Z, &[below]);
        let mirrored = Vec3::new(0.6, 0.0, 0.8);
        assert!(
            got.is_some_and(|g| g.abs_diff_eq(mirrored, 1e-6)),
            "BelowSurface::Reflect: {below} below the surface z = 0 gave {got:?}, and the \
             mirror image through the surface plane is {mirrored}: only the part along the \
             normal changes sign{}",
            if got.is_some_and(|g| g.abs_diff_eq(-below, 1e-6)) {
                " (yours turned the whole direction round)"
            } else {
                ""
            }
        );
    }

    #[test]
    fn exercise_scatter_resamples_with_fresh_numbers() {
        let above = Vec3::new(0.2, -0.3, 0.9).normalize();
        for below_count in [1, 3, MAX_RESAMPLES as usize - 1] {
            let mut lobe = vec![-Vec3::Z; below_count];
            lobe.push(above);
            let (got, given) = scatter_with(BelowSurface::Resample, Vec3::Z, &lobe);
            assert!(
                got == Some(above) && given.len() == below_count + 1,
                "BelowSurface::Resample: {below_count} direction(s) below, then one above, gave \
                 {got:?} after {} draw(s): resampling draws until a direction is above, and \
                 keeps that one",
                given.len()
            );
            let mut distinct = given.clone();
            distinct.dedup();
            assert!(
                distinct.len() == given.len(),
                "BelowSurface::Resample: the draws were given the numbers {given:?}: each \
                 resample takes the sampler's next two numbers, or it draws the same direction \
                 again"
            );
        }
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
