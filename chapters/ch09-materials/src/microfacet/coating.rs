//! How much light gets through a rough dielectric coating, tabulated as Mitsuba 3's
//! `roughplastic` tabulates it, so the plastic's diffuse base is weighted as there.
//!
//! Light reaching the base must cross the rough interface twice. Mitsuba keeps single
//! scattering: the share of light from `cos θ` that refracts through a visible facet and is
//! not shadowed on the way in, `T(cos θ) = ∫ D_w(m) (1 - F(w·m)) G1(t, m) dm` (`t` the refracted
//! direction), tabulated at 64 evenly spaced `cos θ` and interpolated linearly. Light the base
//! scatters back up meets the interface from inside, where it is reflected with the
//! cosine-weighted mean `R_int = ∫ R(cos θ) 2 cos θ d(cos θ)` of the reflectance from inside,
//! so the base's albedo `ρ` becomes `ρ / (1 - R_int)` (or `ρ / (1 - ρ R_int)`, Mitsuba's
//! `nonlinear`).
//!
//! Both integrals run over the unit square of the visible-normal sampler's numbers with a
//! tensor Gauss–Legendre rule (32² points for `T`, 128² for `R` seen from inside, where total
//! internal reflection makes the integrand jump), and `R_int` is the mean over the same 64
//! cosines, all exactly as Mitsuba does, so that the tables agree to rounding.

use super::distribution::NormalDistribution;
use super::fresnel;
use super::gauss_legendre::nodes_and_weights;
use common::scene::{Material, MicrofacetDistribution, Scene};
use glam::Vec3;

/// Entries of the transmittance table, Mitsuba's `MI_ROUGH_TRANSMITTANCE_RES`.
pub const RESOLUTION: usize = 64;

/// The tabulated coating of one roughness and index.
#[derive(Clone, Debug, PartialEq)]
pub struct Coating {
    /// `T` at `cos θ = max(10⁻⁶, i / 63)`.
    transmittance: [f32; RESOLUTION],
    /// `R_int`, the cosine-weighted reflectance of the interface from inside.
    pub internal_reflectance: f32,
}

impl Coating {
    /// Tabulates the coating of facets `distribution` over a medium of relative index `eta`.
    /// The directions' integrals are computed side by side (some 10⁶ sampled normals in all)
    /// and summed in order, so the table is the same whatever the thread count.
    pub fn new(distribution: &NormalDistribution, eta: f32) -> Self {
        use rayon::prelude::*;
        let directions: Vec<Vec3> = (0..RESOLUTION)
            .map(|i| {
                let mu = (i as f32 / (RESOLUTION - 1) as f32).max(1e-6);
                Vec3::new((1.0 - mu * mu).sqrt(), 0.0, mu)
            })
            .collect();
        let integrals: Vec<(f64, f64)> = directions
            .par_iter()
            .map(|w| {
                (
                    transmitted(distribution, *w, eta),
                    reflected(distribution, *w, 1.0 / eta) * f64::from(w.z),
                )
            })
            .collect();
        let mut transmittance = [0.0; RESOLUTION];
        for (t, (transmitted, _)) in transmittance.iter_mut().zip(&integrals) {
            *t = *transmitted as f32;
        }
        let internal: f64 = integrals.iter().map(|(_, reflected)| reflected).sum();
        Self {
            transmittance,
            internal_reflectance: (2.0 * internal / RESOLUTION as f64) as f32,
        }
    }

    /// `T(cos θ)`, interpolated linearly between the entries (`cos θ` in `[0, 1]`).
    pub fn transmittance(&self, cos_theta: f32) -> f32 {
        let x = cos_theta * (RESOLUTION - 1) as f32;
        // Truncation as Mitsuba's integer conversion; a NaN or negative goes to entry 0.
        let index = (x.max(0.0) as usize).min(RESOLUTION - 2);
        let (t0, t1) = (self.transmittance[index], self.transmittance[index + 1]);
        t0 + (t1 - t0) * (x - index as f32)
    }
}

/// The coatings a render needs, each tabulated once before it starts: one per roughness and
/// index among a scene's rough plastics.
///
/// A rough plastic is made at every hit (its base's albedo may be a texture read there), so
/// its coating must already exist by then: a Beckmann table takes about a second in a debug
/// build, and a scene's plastics often share one. The tracer's constructor makes these
/// tables from the scene, side by side on the thread pool, and every hit borrows one;
/// nothing is filled in while the image renders, so no thread waits on another.
#[derive(Clone, Debug, Default)]
pub struct Coatings {
    tables: Vec<(CoatingKey, Coating)>,
}

/// A coating's roughness and index, compared bit for bit: two plastics share a table only when
/// their numbers are the same.
type CoatingKey = (MicrofacetDistribution, u32, u32, u32);

fn key(distribution: &NormalDistribution, eta: f32) -> CoatingKey {
    (
        distribution.kind,
        distribution.alpha_u.to_bits(),
        distribution.alpha_v.to_bits(),
        eta.to_bits(),
    )
}

impl Coatings {
    /// The coatings of every rough plastic in `scene`, masked ones included.
    pub fn of(scene: &Scene) -> Self {
        Self::of_materials(scene.surfaces.iter().map(|surface| &surface.material))
    }

    /// The coatings of the rough plastics among `materials`.
    pub fn of_materials<'m>(materials: impl IntoIterator<Item = &'m Material>) -> Self {
        use rayon::prelude::*;
        let mut wanted: Vec<(CoatingKey, NormalDistribution, f32)> = Vec::new();
        for material in materials {
            if let Some((distribution, eta)) = coating_of(material)
                && !wanted.iter().any(|w| w.0 == key(&distribution, eta))
            {
                wanted.push((key(&distribution, eta), distribution, eta));
            }
        }
        let tables = wanted
            .par_iter()
            .map(|(key, distribution, eta)| (*key, Coating::new(distribution, *eta)))
            .collect();
        Self { tables }
    }

    /// The coating of facets `distribution` over `eta`, if it was tabulated.
    pub fn get(&self, distribution: &NormalDistribution, eta: f32) -> Option<&Coating> {
        let key = key(distribution, eta);
        self.tables
            .iter()
            .find(|(known, _)| *known == key)
            .map(|(_, coating)| coating)
    }
}

/// The facets and the index of a rough plastic's coat, as
/// [`rough_plastic`](crate::bsdf::microfacet::rough_plastic) builds them; `None` for any other
/// material.
pub fn coating_of(material: &Material) -> Option<(NormalDistribution, f32)> {
    let Material::Plastic(plastic) = material.unmasked() else {
        return None;
    };
    let roughness = plastic.roughness?;
    Some((
        NormalDistribution::isotropic(roughness.distribution, roughness.alpha()),
        plastic.int_ior / plastic.ext_ior,
    ))
}

/// `∫ f(sampled normal) du` over the unit square by the tensor rule of `n²` points.
fn over_visible_normals(n: usize, mut f: impl FnMut(glam::Vec2) -> f64) -> f64 {
    let rule = nodes_and_weights(n);
    let mut sum = 0.0;
    for &(y, wy) in &rule {
        for &(x, wx) in &rule {
            let u = glam::Vec2::new((0.5 * x + 0.5) as f32, (0.5 * y + 0.5) as f32);
            sum += 0.25 * wx * wy * f(u);
        }
    }
    sum
}

/// The rule's size: finer where the integrand jumps at total internal reflection.
fn points(eta: f32) -> usize {
    if eta > 1.0 { 32 } else { 128 }
}

/// The share of light from `w` refracted into a medium of relative index `eta` (Mitsuba's
/// `eval_transmittance`).
fn transmitted(distribution: &NormalDistribution, w: Vec3, eta: f32) -> f64 {
    over_visible_normals(points(eta), |u| {
        let m = distribution.sample_visible_normal(w, u);
        let f = fresnel::DielectricFresnel::new(w.dot(m), eta);
        let t = fresnel::refract_away(w, m, &f);
        if t.z * w.z >= 0.0 {
            return 0.0;
        }
        f64::from(distribution.g1(t, m) * (1.0 - f.reflectance))
    })
}

/// The share of light from `w` reflected at an interface of relative index `eta` (Mitsuba's
/// `eval_reflectance`).
fn reflected(distribution: &NormalDistribution, w: Vec3, eta: f32) -> f64 {
    over_visible_normals(points(eta), |u| {
        let m = distribution.sample_visible_normal(w, u);
        let r = fresnel::reflect_away(w, m);
        if r.z <= 0.0 || w.z <= 0.0 {
            return 0.0;
        }
        let f = fresnel::DielectricFresnel::new(w.dot(m), eta).reflectance;
        f64::from(distribution.g1(r, m) * f)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `1 - F`, and `2 ∫ F(μ) μ dμ` from inside, of a smooth interface of index `eta`.
    fn smooth(eta: f32) -> (impl Fn(f32) -> f32, f64) {
        let n = 100_000;
        let inside: f64 = (0..n)
            .map(|i| {
                let mu = (i as f64 + 0.5) / n as f64;
                2.0 * mu
                    * f64::from(fresnel::DielectricFresnel::new(mu as f32, 1.0 / eta).reflectance)
            })
            .sum::<f64>()
            / n as f64;
        (
            move |mu| 1.0 - fresnel::DielectricFresnel::new(mu, eta).reflectance,
            inside,
        )
    }

    /// A nearly smooth coating is a smooth interface: it lets through `1 - F` and reflects
    /// back from inside the cosine-weighted mean of `F`.
    #[test]
    fn a_nearly_smooth_coating_is_a_smooth_interface() {
        let eta = 1.5;
        let (transmitted, inside) = smooth(eta);
        for kind in [
            MicrofacetDistribution::Beckmann,
            MicrofacetDistribution::Ggx,
        ] {
            let coating = Coating::new(&NormalDistribution::isotropic(kind, 0.01), eta);
            for i in 4..=20 {
                let mu = i as f32 / 20.0;
                let (t, expected) = (coating.transmittance(mu), transmitted(mu));
                assert!(
                    (t - expected).abs() < 1e-2,
                    "{kind:?} at {mu}: {t} vs {expected}"
                );
            }
            let r = f64::from(coating.internal_reflectance);
            // The mean over 64 cosines, Mitsuba's rule, is a coarse quadrature.
            assert!((r - inside).abs() < 1e-2, "{kind:?}: R_int {r} vs {inside}");
        }
    }

    /// A rougher coating lets less through at grazing incidence (shadowing) and everything
    /// stays a share.
    #[test]
    fn transmittance_is_a_share_that_falls_towards_grazing() {
        for kind in [
            MicrofacetDistribution::Beckmann,
            MicrofacetDistribution::Ggx,
        ] {
            let coating = Coating::new(&NormalDistribution::isotropic(kind, 0.5), 1.5);
            let values: Vec<f32> = (0..=20)
                .map(|i| coating.transmittance(i as f32 / 20.0))
                .collect();
            assert!(
                values.iter().all(|t| (0.0..=1.0).contains(t)),
                "{kind:?}: {values:?}"
            );
            assert!(values[2] < values[20], "{kind:?}: {values:?}");
            assert!((0.0..1.0).contains(&coating.internal_reflectance));
            // Out-of-range cosines never read past the table.
            assert!(coating.transmittance(1.5).is_finite());
            assert!(coating.transmittance(-0.5).is_finite());
        }
    }

    /// A rough plastic of width `alpha` with its coat of index `int_ior`.
    fn plastic(alpha: f32, int_ior: f32) -> Material {
        Material::Plastic(common::scene::Plastic {
            diffuse_reflectance: Vec3::splat(0.5),
            specular_reflectance: Vec3::ONE,
            diffuse_texture: None,
            specular_texture: None,
            int_ior,
            ext_ior: 1.0,
            nonlinear: false,
            two_sided: false,
            roughness: Some(common::scene::Microfacet::isotropic(
                MicrofacetDistribution::Beckmann,
                alpha,
            )),
        })
    }

    #[test]
    fn coatings_hold_one_table_for_each_roughness_and_index_of_the_materials() {
        let materials = [
            plastic(0.3, 1.5),
            Material::diffuse(Vec3::ONE),
            plastic(0.3, 1.5),
            plastic(0.3, 1.3),
        ];
        let coatings = Coatings::of_materials(&materials);
        assert_eq!(coatings.tables.len(), 2, "a table per roughness and index");
        let d = NormalDistribution::isotropic(MicrofacetDistribution::Beckmann, 0.3);
        assert_eq!(coatings.get(&d, 1.5), Some(&Coating::new(&d, 1.5)));
        assert_eq!(coatings.get(&d, 1.3), Some(&Coating::new(&d, 1.3)));
        assert_eq!(coatings.get(&d, 1.4), None, "no plastic of this index");
        assert!(Coatings::of_materials(&materials[1..2]).tables.is_empty());
    }
}
