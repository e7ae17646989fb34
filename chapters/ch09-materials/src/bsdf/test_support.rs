//! A hit on the floor `y = 0` for the BSDF tests, and the check that sampling, `eval` and
//! `pdf` describe the same material.

use super::SceneBsdf;
use crate::microfacet::coating::Coatings;
use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::SurfaceBsdf;
use common::geometry::SurfaceHit;
use common::sampler::{IndependentSampler, Sampler};
use common::scene::Material;
use glam::{UVec2, Vec2, Vec3};

/// A hit at the origin of a surface with normal +y, known to within 1e-6 (so that a ray
/// spawned there starts off the surface).
pub fn floor_hit() -> SurfaceHit {
    SurfaceHit {
        t: 1.0,
        p: Vec3::ZERO,
        p_error: Vec3::splat(1e-6),
        n: Vec3::Y,
        shading_n: Vec3::Y,
        uv: Vec2::ZERO,
        shape: 0,
    }
}

/// Checks, over many samples from `wo`, that every non-delta sample's weight is
/// `eval / pdf` and its pdf is `pdf(wi)`, and returns the mean weight (the albedo the
/// material has for `wo`) and the share of delta samples.
pub fn check_consistent(material: &Material, wo: Vec3, n: u64) -> (Vec3, f32) {
    let hit = floor_hit();
    let bsdf = SceneBsdf {
        material,
        hit: &hit,
        fuzz: FuzzMethod::Lobe,
        coatings: &Coatings::of_materials([material]),
    };
    let mut sampler = IndependentSampler::new(3);
    let mut sum = Vec3::ZERO;
    let mut deltas = 0;
    for i in 0..n {
        sampler.start_pixel_sample(UVec2::ZERO, i);
        let Some(s) = bsdf.sample(wo, &mut sampler) else {
            continue;
        };
        assert!(s.weight.is_finite() && s.wi.is_finite(), "{s:?}");
        sum += s.weight;
        if s.is_delta() {
            deltas += 1;
            continue;
        }
        let pdf = bsdf.pdf(wo, s.wi);
        let f = bsdf.eval(wo, s.wi);
        assert!(
            (pdf - s.pdf).abs() <= 1e-3 * s.pdf,
            "{material:?}: pdf {pdf} vs {}",
            s.pdf
        );
        let ratio = f / pdf;
        assert!(
            (ratio - s.weight).abs().max_element() <= 1e-3 * s.weight.max_element(),
            "{material:?}: f/pdf {ratio} vs {}",
            s.weight
        );
    }
    (sum / n as f32, deltas as f32 / n as f32)
}
