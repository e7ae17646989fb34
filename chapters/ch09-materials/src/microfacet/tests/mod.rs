//! The microfacet models' properties: what each distribution integrates to, what its
//! samplers and its BSDFs promise each other, energy, reciprocity and extreme inputs.
//! (The chi-square tests of the samplers are in `tests/microfacet_sampling`.)

mod bsdfs;
mod distribution;
mod exercises;

use super::NormalDistribution;
use common::scene::MicrofacetDistribution;
use glam::Vec3;

/// Both distributions at roughnesses from sharp to very rough, and one anisotropic.
fn distributions() -> Vec<NormalDistribution> {
    let mut all = Vec::new();
    for kind in [
        MicrofacetDistribution::Beckmann,
        MicrofacetDistribution::Ggx,
    ] {
        for (au, av) in [(0.01, 0.01), (0.1, 0.1), (0.5, 0.5), (1.0, 1.0), (0.1, 0.6)] {
            all.push(NormalDistribution::new(kind, au, av));
        }
    }
    all
}

/// The unit direction at `degrees` from the normal, at the azimuth `phi_degrees`.
fn direction(degrees: f32, phi_degrees: f32) -> Vec3 {
    let (sin, cos) = degrees.to_radians().sin_cos();
    let (sin_phi, cos_phi) = phi_degrees.to_radians().sin_cos();
    Vec3::new(sin * cos_phi, sin * sin_phi, cos)
}
