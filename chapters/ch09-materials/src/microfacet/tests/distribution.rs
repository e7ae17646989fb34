use super::{direction, distributions};
use crate::microfacet::albedo::over_normals;
use crate::microfacet::{MIN_ALPHA, NormalDistribution};
use common::scene::MicrofacetDistribution;
use glam::{DVec3, Vec2, Vec3};

/// The larger roughness: where the quadrature puts its nodes.
fn scale(d: &NormalDistribution) -> f32 {
    d.alpha_u.max(d.alpha_v)
}

/// Beckmann's `G1` is Mitsuba's rational approximation of the exact one, good to 0.35 %; the
/// integrals that hold exactly for the exact `G1` hold to that much.
fn g1_tolerance(d: &NormalDistribution) -> f64 {
    match d.kind {
        MicrofacetDistribution::Beckmann => 4e-3,
        MicrofacetDistribution::Ggx => 1e-3,
    }
}

#[test]
fn the_projected_area_of_the_facets_is_the_surface_s() {
    for d in distributions() {
        let area = over_normals(scale(&d), |m| DVec3::splat(f64::from(d.d(m) * m.z))).x;
        assert!((area - 1.0).abs() < 1e-3, "{d:?}: ∫ D cos θ_m = {area}");
    }
}

#[test]
fn the_visible_normals_are_a_density_from_every_direction() {
    for d in distributions() {
        for (theta, phi) in [(0.0, 0.0), (45.0, 30.0), (80.0, 90.0), (89.0, 10.0)] {
            let w = direction(theta, phi);
            let total = over_normals(scale(&d), |m| {
                DVec3::splat(f64::from(d.visible_normal_pdf(w, m)))
            })
            .x;
            assert!(
                (total - 1.0).abs() < g1_tolerance(&d),
                "{d:?} from {theta}°: ∫ D_w = {total}"
            );
        }
    }
}

#[test]
fn shadowing_is_a_share_that_vanishes_at_grazing_and_is_whole_at_normal_incidence() {
    for d in distributions() {
        let m = direction(10.0, 20.0);
        assert_eq!(d.g1(Vec3::Z, Vec3::Z), 1.0, "{d:?}");
        assert_eq!(d.g1(Vec3::Z, m), 1.0, "{d:?}");
        for theta in [0.0, 30.0, 60.0, 85.0, 89.9, 90.0] {
            let w = direction(theta, 45.0);
            let g = d.g1(w, m);
            assert!((0.0..=1.0).contains(&g), "{d:?}: G1({theta}°) = {g}");
        }
        assert_eq!(d.g1(direction(90.0, 45.0), m), 0.0, "{d:?}");
        // The back of a facet is never seen.
        assert_eq!(d.g1(Vec3::Z, -m), 0.0, "{d:?}");
    }
}

/// `G1` of Beckmann without the approximation: `2 / (1 + erf(a) + e^{-a²} / (a √π))`.
fn exact_beckmann_g1(alpha: f64, tan_theta: f64) -> f64 {
    let a = 1.0 / (alpha * tan_theta);
    let tail = (-a * a).exp() / (a * std::f64::consts::PI.sqrt());
    2.0 / (1.0 + statrs::function::erf::erf(a) + tail)
}

#[test]
fn beckmann_shadowing_is_within_mitsubas_stated_error_of_the_exact_one() {
    let d = NormalDistribution::isotropic(MicrofacetDistribution::Beckmann, 0.5);
    for i in 1..90 {
        let w = direction(i as f32, 0.0);
        let exact = exact_beckmann_g1(0.5, f64::from(w.x / w.z));
        let approx = f64::from(d.g1(w, Vec3::Z));
        assert!(
            (approx / exact - 1.0).abs() < 3.5e-3,
            "{i}°: {approx} vs {exact}"
        );
    }
}

#[test]
fn stiff_inputs_give_finite_values() {
    let directions = [
        Vec3::Z,
        direction(89.99, 0.0),
        Vec3::new(1.0, 0.0, 1e-6).normalize(),
        Vec3::new(0.0, 1.0, 1e-7).normalize(),
        direction(45.0, 45.0),
    ];
    let numbers = [0.0, 1e-7, 0.5, 1.0 - 1e-7, 0.999_999_94];
    for kind in [
        MicrofacetDistribution::Beckmann,
        MicrofacetDistribution::Ggx,
    ] {
        for (au, av) in [
            (MIN_ALPHA, MIN_ALPHA),
            (1.0, 1.0),
            (MIN_ALPHA, 1.0),
            (0.0, -1.0),
        ] {
            let d = NormalDistribution::new(kind, au, av);
            for w in directions {
                for &x in &numbers {
                    for &y in &numbers {
                        let u = Vec2::new(x, y);
                        let m = d.sample_visible_normal(w, u);
                        assert!(
                            m.is_finite() && (m.length() - 1.0).abs() < 1e-4 && m.z >= 0.0,
                            "{d:?} from {w}, u {u}: {m}"
                        );
                        let values = [d.d(m), d.g1(w, m), d.visible_normal_pdf(w, m)];
                        assert!(values.iter().all(|v| v.is_finite()), "{d:?}: {values:?}");
                        let plain = d.sample_normal(u);
                        assert!(
                            plain.is_finite() && d.normal_pdf(plain).is_finite(),
                            "{plain}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn a_distribution_of_no_roughness_is_clamped_as_mitsuba_clamps_it() {
    let d = NormalDistribution::new(MicrofacetDistribution::Ggx, 0.0, f32::NAN);
    assert_eq!((d.alpha_u, d.alpha_v), (MIN_ALPHA, MIN_ALPHA));
}
