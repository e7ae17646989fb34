//! The samplers tested, each with the chart its lobes need: normals around the macro normal,
//! reflections around the mirror direction, refractions around the smooth refracted direction.
//! The charts only place the bins; the density compared is always the sampler's own.

use crate::slope_chart::{Lobe, SlopeChart as Chart};
use ch09_materials::microfacet::coating::Coating;
use ch09_materials::microfacet::fresnel;
use ch09_materials::microfacet::{
    LocalBsdf, NormalDistribution, RoughConductor, RoughDielectric, RoughPlastic,
    RoughPlasticParameters,
};
use common::sampler::{IndependentSampler, Sampler};
use common::scene::MicrofacetDistribution::{self, Beckmann, Ggx};
use glam::Vec3;

/// Draws one direction with the sampler's numbers, `None` for no direction.
type Draw = Box<dyn Fn(&mut IndependentSampler) -> Option<Vec3>>;
/// The density the sampler claims, per unit solid angle.
type Density = Box<dyn Fn(Vec3) -> f32>;

/// One sampler seen from one direction.
pub struct Case {
    /// What the report calls it.
    pub name: String,
    /// Where the bins go.
    pub chart: Chart,
    /// The sampler.
    pub sample: Draw,
    /// Its claimed density.
    pub pdf: Density,
    /// How far, relatively, the density may be from integrating to what it should: Beckmann's
    /// `G1` is Mitsuba's approximation, good to 0.35 %, so `D_w` integrates to 1 only that well.
    pub approximation: f64,
    /// Whether it may give no direction. A normal sampler never does, so whatever the
    /// quadrature of its density misses below 1 is no share of "no direction".
    pub drops: bool,
}

const KINDS: [MicrofacetDistribution; 2] = [Beckmann, Ggx];
/// `(alpha_u, alpha_v)` of the distribution cases.
const ROUGHNESS: [(f32, f32); 4] = [(0.02, 0.02), (0.3, 0.3), (1.0, 1.0), (0.1, 0.5)];
/// Angles of `w` from the normal for the visible normals.
const VIEWS: [f32; 3] = [0.0, 60.0, 89.0];

/// Every test of the file, for Šidák's correction.
pub const TESTS: usize = KINDS.len() * ROUGHNESS.len() * (VIEWS.len() + 1) // normals
    + KINDS.len() * 3 * 3 // conductors
    + KINDS.len() * 2 * 3 // glass
    + KINDS.len() * 2; // plastic

/// The unit direction at `degrees` from the normal, at the azimuth 30°.
fn at(degrees: f32) -> Vec3 {
    let (sin, cos) = degrees.to_radians().sin_cos();
    let (sin_phi, cos_phi) = 30f32.to_radians().sin_cos();
    Vec3::new(sin * cos_phi, sin * sin_phi, cos)
}

/// The width of the chart of normals of roughness `alpha`: `alpha` is about the spread of
/// their slopes, `tan θ_m`.
fn normals_width(alpha: f32) -> f32 {
    alpha.atan()
}

/// What [`Case::approximation`] allows a distribution.
fn approximation(kind: MicrofacetDistribution) -> f64 {
    match kind {
        Beckmann => 3.5e-3,
        Ggx => 0.0,
    }
}

/// Reflected directions spread twice as far as the normals.
fn reflection_width(alpha: f32) -> f32 {
    (2.0 * normals_width(alpha)).min(1.5)
}

fn normals_lobe(alpha_u: f32, alpha_v: f32) -> Vec<Lobe> {
    vec![Lobe {
        axis: Vec3::Z,
        side: Vec3::Z,
        width: normals_width((alpha_u * alpha_v).sqrt()),
    }]
}

/// Visible normals from three angles and plain normals, for every distribution.
pub fn visible_normals() -> Vec<Case> {
    let mut cases = Vec::new();
    for kind in KINDS {
        for (au, av) in ROUGHNESS {
            let d = NormalDistribution::new(kind, au, av);
            for view in VIEWS {
                let w = at(view);
                cases.push(Case {
                    name: format!("visible normals {kind:?} {au}/{av} from {view}°"),
                    chart: Chart::new(normals_lobe(au, av)),
                    sample: Box::new(move |s| Some(d.sample_visible_normal(w, s.get_2d()))),
                    pdf: Box::new(move |m| d.visible_normal_pdf(w, m)),
                    drops: false,
                    approximation: approximation(kind),
                });
            }
        }
    }
    cases
}

/// `D(m) cos θ_m`, for every distribution.
pub fn plain_normals() -> Vec<Case> {
    let mut cases = Vec::new();
    for kind in KINDS {
        for (au, av) in ROUGHNESS {
            let d = NormalDistribution::new(kind, au, av);
            cases.push(Case {
                name: format!("plain normals {kind:?} {au}/{av}"),
                chart: Chart::new(normals_lobe(au, av)),
                sample: Box::new(move |s| Some(d.sample_normal(s.get_2d()))),
                pdf: Box::new(move |m| d.normal_pdf(m)),
                drops: false,
                approximation: approximation(kind),
            });
        }
    }
    cases
}

/// A BSDF's case: its numbers drawn as the path tracer would draw them (the choice, then two).
fn bsdf_case<B: LocalBsdf + Clone + 'static>(
    kind: MicrofacetDistribution,
    name: String,
    bsdf: B,
    wo: Vec3,
    lobes: Vec<Lobe>,
) -> Case {
    let sampling = bsdf.clone();
    Case {
        name,
        chart: Chart::new(lobes),
        sample: Box::new(move |s| {
            let choice = s.get_1d();
            sampling.sample(wo, choice, s.get_2d()).map(|b| b.wi)
        }),
        pdf: Box::new(move |wi| bsdf.pdf(wo, wi)),
        drops: true,
        approximation: approximation(kind),
    }
}

/// The normal on `wo`'s side.
fn facing(wo: Vec3) -> Vec3 {
    if wo.z >= 0.0 { Vec3::Z } else { -Vec3::Z }
}

fn mirror(wo: Vec3) -> Vec3 {
    fresnel::reflect_away(wo, facing(wo))
}

/// Copper-like metal at two roughnesses and anisotropic, from the normal, at 70° and grazing.
pub fn conductors() -> Vec<Case> {
    let mut cases = Vec::new();
    for kind in KINDS {
        for (au, av) in [(0.05, 0.05), (0.5, 0.5), (0.1, 0.4)] {
            let bsdf = RoughConductor {
                distribution: NormalDistribution::new(kind, au, av),
                eta: Vec3::new(0.27, 0.68, 1.3),
                k: Vec3::new(3.6, 2.6, 2.3),
                specular_reflectance: Vec3::ONE,
            };
            for view in [0.0, 70.0, 88.0] {
                let wo = at(view);
                let lobe = Lobe {
                    axis: mirror(wo),
                    side: Vec3::Z,
                    width: reflection_width((au * av).sqrt()),
                };
                let name = format!("rough conductor {kind:?} {au}/{av} from {view}°");
                cases.push(bsdf_case(kind, name, bsdf, wo, vec![lobe]));
            }
        }
    }
    cases
}

/// Glass of index 1.5 from outside, from inside, and from inside beyond the critical angle.
pub fn glass() -> Vec<Case> {
    let mut cases = Vec::new();
    for kind in KINDS {
        for alpha in [0.05, 0.4] {
            let bsdf = RoughDielectric::new(NormalDistribution::isotropic(kind, alpha), 1.5, 1.0);
            for (wo, where_) in [
                (at(40.0), "outside, 40°"),
                (-at(20.0), "inside, 20°"),
                (-at(60.0), "inside, 60°"),
            ] {
                let side = facing(wo);
                let mut lobes = vec![Lobe {
                    axis: mirror(wo),
                    side,
                    width: reflection_width(alpha),
                }];
                // Rough facets refract even beyond the critical angle: straight through,
                // then, when no smooth refraction exists.
                let f = fresnel::DielectricFresnel::new(wo.z, 1.5);
                let axis = if f.reflectance < 1.0 {
                    fresnel::refract_away(wo, Vec3::Z, &f)
                } else {
                    -side
                };
                lobes.push(Lobe {
                    axis,
                    side: -side,
                    width: reflection_width(alpha),
                });
                let name = format!("rough glass {kind:?} {alpha} from {where_}");
                cases.push(bsdf_case(kind, name, bsdf, wo, lobes));
            }
        }
    }
    cases
}

/// Plastic with a sharp and a rough coating, at 50°; the chart is the coating's lobe, wide
/// enough that the base's cosine lobe is binned too.
pub fn plastic() -> Vec<Case> {
    let mut cases = Vec::new();
    for kind in KINDS {
        for alpha in [0.1, 0.6] {
            let parameters = RoughPlasticParameters {
                kind,
                alpha,
                eta: 1.49,
                diffuse_reflectance: Vec3::new(0.3, 0.5, 0.7),
                specular_reflectance: Vec3::ONE,
                nonlinear: false,
            };
            // Kept to the end of the test process: a case outlives the function that makes it.
            let coating: &'static Coating = Box::leak(Box::new(parameters.coating()));
            let bsdf = RoughPlastic::new(parameters, coating);
            let wo = at(50.0);
            let lobe = Lobe {
                axis: mirror(wo),
                side: Vec3::Z,
                width: reflection_width(alpha).max(0.5),
            };
            let name = format!("rough plastic {kind:?} {alpha} from 50°");
            cases.push(bsdf_case(kind, name, bsdf, wo, vec![lobe]));
        }
    }
    cases
}
