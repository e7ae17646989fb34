//! Sampling a direction from the BSDF and the guide at once: a mixture.
//!
//! The guide knows where light comes from but not what the surface does with it; the BSDF
//! knows the surface but not the light. Müller et al. draw from one or the other, the BSDF
//! with probability `α` (the *BSDF fraction*) and the guide otherwise, and weigh the sample
//! by the density of the mixture, `α p_bsdf + (1 - α) p_guide`, the one density with which
//! the direction could have been drawn. The estimate stays unbiased wherever either
//! technique can draw a direction the integrand needs (the BSDF draws every one it scatters
//! to), and its variance is that of the better technique where the guide has learnt well.
//!
//! [`GuidedBsdf`] is that mixture dressed as a BSDF: chapter 08's light sample and BSDF step
//! take it as they take any [`SurfaceBsdf`], and its density is the one their MIS weights then
//! use, so light found by a guided direction and light sampled directly are combined as in
//! chapter 08. A surface with no guide, or one whose scattering is a delta (a mirror, smooth
//! glass), is sampled by its BSDF alone and draws no number more.

use crate::directions::{direction_of, point_of, solid_angle_pdf};
use crate::quadtree::DirectionTree;
use ch08_path_tracing::{BsdfSample, SurfaceBsdf};
use common::geometry::SurfaceHit;
use common::sampler::Sampler;
use glam::{Vec2, Vec3};

/// The BSDF fraction of Müller et al.'s first paper: half the directions from the BSDF, half
/// from the guide (each region learns its own otherwise, [`crate::selection`]).
pub const BSDF_FRACTION: f32 = 0.5;

/// A surface's BSDF and the guide of its region, sampled as a mixture.
pub struct GuidedBsdf<'a, B> {
    /// The surface's own BSDF.
    pub bsdf: B,
    /// The guide's distribution, when there is one to sample (something learnt, and a
    /// surface that is not a delta).
    pub guide: Option<&'a DirectionTree>,
    /// The probability of drawing from the BSDF.
    pub bsdf_fraction: f32,
}

impl<'a, B: SurfaceBsdf> GuidedBsdf<'a, B> {
    /// `bsdf` mixed with `guide`, if the guide has learnt anything and the surface scatters
    /// other than in a delta; else `bsdf` alone.
    pub fn new(bsdf: B, guide: Option<&'a DirectionTree>, bsdf_fraction: f32) -> Self {
        let guide = guide.filter(|g| g.total() > 0.0 && !bsdf.is_delta());
        Self {
            bsdf,
            guide,
            bsdf_fraction,
        }
    }

    /// A direction drawn from the mixture ([`SurfaceBsdf::sample`]), with what the mixture
    /// worked out about it on the way: a training path records the direction's point and learns
    /// the fraction from the two densities, and need not work them out again.
    pub fn sample_mixture<S: Sampler>(&self, wo: Vec3, sampler: &mut S) -> Option<MixtureSample> {
        let Some(guide) = self.guide else {
            let sample = self.bsdf.sample(wo, sampler)?;
            return Some(MixtureSample {
                sample,
                mixed: None,
            });
        };
        let alpha = self.bsdf_fraction;
        if sampler.get_1d() < alpha {
            let sample = self.bsdf.sample(wo, sampler)?;
            if sample.is_delta() {
                return Some(MixtureSample {
                    sample: BsdfSample {
                        weight: sample.weight / alpha,
                        ..sample
                    },
                    mixed: None,
                });
            }
            let mixed = Mixed::at(guide, point_of(sample.wi), sample.pdf);
            let f_cos = sample.weight * sample.pdf;
            let pdf = mixed.pdf(alpha);
            return Some(MixtureSample {
                sample: BsdfSample {
                    weight: f_cos / pdf,
                    pdf,
                    ..sample
                },
                mixed: Some(mixed),
            });
        }
        // The guide's density is that of the point drawn: no need to find the point of the
        // direction again.
        let point = guide.sample(sampler.get_2d())?;
        let wi = direction_of(point);
        let f_cos = self.bsdf.eval(wo, wi);
        let mixed = Mixed::at(guide, point, self.bsdf.pdf(wo, wi));
        let pdf = mixed.pdf(alpha);
        if f_cos == Vec3::ZERO || pdf.is_nan() || pdf <= 0.0 {
            return None;
        }
        // The radiance scaling of a refraction is the BSDF's to know; the guide's direction
        // is taken as scaling nothing, which only the roulette reads.
        Some(MixtureSample {
            sample: BsdfSample {
                wi,
                weight: f_cos / pdf,
                pdf,
                eta_scale: 1.0,
            },
            mixed: Some(mixed),
        })
    }
}

/// A direction drawn from a [`GuidedBsdf`], and what the mixture knew of it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MixtureSample {
    /// The direction and its weight, as any BSDF's sample.
    pub sample: BsdfSample,
    /// Where the guide was mixed in and the direction is not a delta lobe's: its point and
    /// both densities.
    pub mixed: Option<Mixed>,
}

/// A direction of a mixture seen by both techniques.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mixed {
    /// The direction as a point of the unit square ([`crate::directions`]).
    pub point: Vec2,
    /// The BSDF's density of the direction per unit solid angle.
    pub bsdf_pdf: f32,
    /// The guide's.
    pub guide_pdf: f32,
}

impl Mixed {
    /// The direction at `point` of the square, with the BSDF's density `bsdf_pdf` there and
    /// `guide`'s, both per unit solid angle.
    pub fn at(guide: &DirectionTree, point: Vec2, bsdf_pdf: f32) -> Self {
        Self {
            point,
            bsdf_pdf,
            guide_pdf: solid_angle_pdf(guide.pdf(point)),
        }
    }

    /// The mixture's density, the BSDF drawn from with probability `bsdf_fraction`.
    pub fn pdf(&self, bsdf_fraction: f32) -> f32 {
        bsdf_fraction * self.bsdf_pdf + (1.0 - bsdf_fraction) * self.guide_pdf
    }
}

impl<B: SurfaceBsdf> SurfaceBsdf for GuidedBsdf<'_, B> {
    fn hit(&self) -> &SurfaceHit {
        self.bsdf.hit()
    }

    fn is_delta(&self) -> bool {
        self.bsdf.is_delta()
    }

    /// From the BSDF with probability `bsdf_fraction`, else from the guide; the weight is
    /// `f cos θ` over the mixture's density. A delta lobe the BSDF picks (a smooth coating,
    /// say) no guide can draw: its weight is the BSDF's over the chance of asking the BSDF.
    /// Draws one number for the choice, then the BSDF's numbers or the guide's two.
    fn sample<S: Sampler>(&self, wo: Vec3, sampler: &mut S) -> Option<BsdfSample> {
        self.sample_mixture(wo, sampler).map(|drawn| drawn.sample)
    }

    fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        self.bsdf.eval(wo, wi)
    }

    /// The mixture's density: what the light sample's MIS weight compares with.
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        let bsdf_pdf = self.bsdf.pdf(wo, wi);
        match self.guide {
            None => bsdf_pdf,
            Some(guide) => Mixed::at(guide, point_of(wi), bsdf_pdf).pdf(self.bsdf_fraction),
        }
    }
}
