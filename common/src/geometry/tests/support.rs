//! What the whole-module tests share: where a test scene is placed, and random numbers.

use glam::Vec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg32;

/// A fixed-seed generator: every run of the tests sees the same "random" rays.
pub fn rng(seed: u64) -> Pcg32 {
    Pcg32::seed_from_u64(seed)
}

/// Where a test configuration, designed around the origin at unit size, is put: scaled by
/// `scale`, then moved by `translation`.
#[derive(Clone, Copy, Debug)]
pub struct Placement {
    pub scale: f32,
    pub translation: Vec3,
}

impl Placement {
    /// Micrometre, metre and 100 km scenes, each at the origin and 10⁵ away from it.
    pub fn all() -> Vec<Placement> {
        let mut placements = Vec::new();
        for translation in [Vec3::ZERO, Vec3::new(1e5, -1e5, 1e5)] {
            for scale in [1e-4, 1.0, 1e5] {
                placements.push(Placement { scale, translation });
            }
        }
        placements
    }

    /// The placed point.
    pub fn point(&self, v: Vec3) -> Vec3 {
        self.translation + self.scale * v
    }

    /// The placed vector (not moved).
    pub fn vector(&self, v: Vec3) -> Vec3 {
        self.scale * v
    }

    /// Whether a unit-sized configuration spans many floats here.
    ///
    /// At scale 10⁻⁴, 10⁵ away from the origin, the spacing of floats (about 0.008) is larger
    /// than the whole configuration: every vertex rounds to one of a handful of points. Such
    /// configurations can still be checked for self-intersection, but not be expected to be
    /// hit, or to be watertight.
    pub fn resolves_shapes(&self) -> bool {
        let spacing = self.translation.abs().max_element() * f32::EPSILON;
        self.scale > 100.0 * spacing
    }
}

/// A uniformly distributed unit vector.
pub fn random_unit_vector(rng: &mut Pcg32) -> Vec3 {
    loop {
        let v = Vec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let length_squared = v.length_squared();
        if length_squared > 1e-4 && length_squared <= 1.0 {
            return v / length_squared.sqrt();
        }
    }
}

/// A unit direction on the side of the unit vector `n` (`dot > 0`), with the angle to the
/// surface spread over many orders of magnitude so that near-grazing directions are common.
pub fn random_direction_on_side(rng: &mut Pcg32, n: Vec3) -> Vec3 {
    loop {
        let cos_theta: f32 = if rng.random::<bool>() {
            rng.random_range(0.01..1.0)
        } else {
            10f32.powf(-rng.random_range(2.0..5.0))
        };
        let w =
            (cos_theta * n + (1.0 - cos_theta * cos_theta).sqrt() * tangent_to(rng, n)).normalize();
        // Rounding must not have pushed a grazing direction to the other side.
        if w.dot(n) > 0.0 {
            return w;
        }
    }
}

/// A random unit vector perpendicular to the unit vector `n`, to within rounding.
fn tangent_to(rng: &mut Pcg32, n: Vec3) -> Vec3 {
    loop {
        let t = random_unit_vector(rng).reject_from_normalized(n);
        if t.length_squared() > 0.1 {
            // Project a second time: the first projection's rounding error, magnified by the
            // normalisation, would otherwise tilt nearly grazing directions by up to 1e-6.
            let t = t.normalize();
            return (t - t.dot(n) * n).normalize();
        }
    }
}

/// A log-uniform number between `low` and `high`.
pub fn log_uniform(rng: &mut Pcg32, low: f32, high: f32) -> f32 {
    (rng.random_range(low.ln()..high.ln())).exp()
}
