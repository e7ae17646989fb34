//! The materials tested, each from a direction where it shows what it does: a share of a wide
//! lobe lost below the surface, a narrow lobe near grazing, glass that transmits and glass
//! that reflects totally. The lobes are found as the BSDFs find them (mirror and refracted
//! directions); they only place the bins, the density compared is always `Bsdf::pdf`.

use crate::chart::{Chart, Lobe};
use crate::check::{Case, floor_hit};
use ch01_whitted::optics::{reflect, refract};
use ch06_fuzzy_reflections::FuzzMethod;
use ch06_fuzzy_reflections::tracer::transmission_exponent;
use ch08_path_tracing::bsdf::dielectric::side;
use common::scene::Material as Smooth;
use common::scene::Material;
use common::scene::{Conductor, Glossy, Microfacet, MicrofacetDistribution, Plastic, RoughGlass};
use glam::Vec3;

/// Matte cases.
pub const DIFFUSE: usize = 2;
/// Glossy `cos^n` lobe cases.
pub const GLOSSY: usize = 5;
/// Glossy cases spread by chapter 06's empirical disc.
pub const DISC: usize = 2;
/// Frosted glass cases.
pub const ROUGH_GLASS: usize = 5;
/// Rough plastic cases (Mitsuba's `roughplastic`: the microfacet coat over the matte base).
pub const ROUGH_PLASTIC: usize = 2;
/// Microfacet metals and glass placed at the hit (`bsdf::microfacet`).
pub const MICROFACET: usize = 4;
/// Every chi-square test of the file, for Šidák's correction.
pub const TESTS: usize = DIFFUSE + GLOSSY + DISC + ROUGH_GLASS + ROUGH_PLASTIC + MICROFACET;

/// The unit direction at `degrees` from the normal +y, above the floor or below it.
fn at(degrees: f32, above: bool) -> Vec3 {
    let (sin, cos) = degrees.to_radians().sin_cos();
    Vec3::new(sin, if above { cos } else { -cos }, 0.0)
}

/// The normal on `wo`'s side.
fn facing(wo: Vec3) -> Vec3 {
    if wo.y > 0.0 { Vec3::Y } else { -Vec3::Y }
}

fn case(name: String, material: Material, fuzz: FuzzMethod, wo: Vec3, lobes: Vec<Lobe>) -> Case {
    Case {
        name,
        material,
        fuzz,
        wo,
        chart: Chart::new(lobes),
    }
}

/// The cosine lobe around the normal.
pub fn diffuse() -> [Case; DIFFUSE] {
    let matte = |material: Material, wo: Vec3, name: &str| {
        let lobe = Lobe {
            axis: facing(wo),
            side: facing(wo),
            exponent: 1.0,
        };
        case(name.into(), material, FuzzMethod::Lobe, wo, vec![lobe])
    };
    [
        matte(
            Smooth::diffuse(Vec3::splat(0.8)),
            at(60.0, true),
            "diffuse, 60°",
        ),
        matte(
            Smooth::two_sided_diffuse(Vec3::splat(0.5)),
            at(30.0, false),
            "two-sided diffuse from below, 30°",
        ),
    ]
}

/// A glossy lobe of `exponent` seen from `wo`, its lobe around the mirror direction.
fn glossy_case(fuzz: FuzzMethod, exponent: f32, two_sided: bool, wo: Vec3, name: String) -> Case {
    let material = Material::Glossy(Glossy {
        reflectance: Vec3::splat(0.9),
        exponent,
        two_sided,
        stands_in_for: None,
    });
    let normal = facing(wo);
    let lobe = Lobe {
        axis: reflect(-wo, normal),
        side: normal,
        exponent,
    };
    case(name, material, fuzz, wo, vec![lobe])
}

/// `cos^n` lobes from wide (over a third lost below the surface at 70°) to a hundredth of a
/// radian (`n = 10⁴`).
pub fn glossy() -> [Case; GLOSSY] {
    let lobe = |n: f32| {
        glossy_case(
            FuzzMethod::Lobe,
            n,
            false,
            at(70.0, true),
            format!("glossy n = {n}, 70°"),
        )
    };
    [
        lobe(0.0),
        lobe(1.0),
        lobe(100.0),
        lobe(1e4),
        glossy_case(
            FuzzMethod::Lobe,
            20.0,
            true,
            at(50.0, false),
            "two-sided glossy n = 20 from below, 50°".into(),
        ),
    ]
}

/// Chapter 06's disc: a cone of directions, its edge cut by the surface at `n = 1`.
pub fn disc() -> [Case; DISC] {
    [1.0, 100.0].map(|n| {
        glossy_case(
            FuzzMethod::Disc,
            n,
            false,
            at(70.0, true),
            format!("disc n = {n}, 70°"),
        )
    })
}

/// Frosted glass of index 1.5 and `exponent`: the reflection lobe on `wo`'s side and, unless
/// the reflection is total, the narrower transmission lobe on the other.
fn glass_case(exponent: f32, wo: Vec3, name: &str) -> Case {
    let (normal, eta) = side(&floor_hit(), wo, 1.5, 1.0);
    let mut lobes = vec![Lobe {
        axis: reflect(-wo, normal),
        side: normal,
        exponent,
    }];
    if let Some(refracted) = refract(-wo, normal, eta) {
        lobes.push(Lobe {
            axis: refracted,
            side: -normal,
            exponent: transmission_exponent(exponent, eta),
        });
    }
    let name = format!("frosted glass n = {exponent}, {name}");
    case(
        name,
        Material::rough_glass(1.5, exponent),
        FuzzMethod::Lobe,
        wo,
        lobes,
    )
}

/// Both sides of the surface, both lobes, and total internal reflection.
pub fn rough_glass() -> [Case; ROUGH_GLASS] {
    [
        glass_case(0.0, at(45.0, true), "from outside, 45°"),
        glass_case(1.0, at(5.0, true), "from outside, 5°"),
        glass_case(10.0, at(45.0, true), "from outside, 45°"),
        glass_case(1000.0, at(20.0, false), "from inside, 20°"),
        glass_case(10.0, at(60.0, false), "from inside, 60° (total reflection)"),
    ]
}

/// Rough plastic of coat roughness `alpha` seen from `wo`: the base's cosine lobe and, around
/// the mirror direction, the microfacet coat's reflection.
fn plastic_case(alpha: f32, two_sided: bool, chart: f32, wo: Vec3, name: &str) -> Case {
    let roughness = Microfacet::isotropic(MicrofacetDistribution::Beckmann, alpha);
    let material = Material::Plastic(Plastic {
        diffuse_reflectance: Vec3::new(0.2, 0.5, 0.8),
        specular_reflectance: Vec3::ONE,
        diffuse_texture: None,
        specular_texture: None,
        int_ior: 1.49,
        ext_ior: 1.0,
        nonlinear: false,
        two_sided,
        roughness: Some(roughness),
    });
    // One strip (a chart's lobes lie on different sides): around the mirror direction, as for
    // a lobe of exponent `chart`, wider than the coat's, so that the base's cosine lobe
    // spreads over the strip too.
    let normal = facing(wo);
    let lobes = vec![Lobe {
        axis: reflect(-wo, normal),
        side: normal,
        exponent: chart,
    }];
    let name = format!("roughplastic alpha = {alpha}, {name}");
    case(name, material, FuzzMethod::Lobe, wo, lobes)
}

/// Near grazing, where the coat reflects most, and from below a two-sided one.
pub fn rough_plastic() -> [Case; ROUGH_PLASTIC] {
    [
        plastic_case(0.3, false, 5.0, at(75.0, true), "75°"),
        plastic_case(0.1, true, 8.0, at(40.0, false), "two-sided from below, 40°"),
    ]
}

/// A rough metal of widths `alpha_u`, `alpha_v` seen from `wo`, its strip around the mirror
/// direction as wide as a lobe of exponent `chart`.
fn metal_case(roughness: Microfacet, two_sided: bool, chart: f32, wo: Vec3, name: &str) -> Case {
    let material = Material::Conductor(Conductor {
        eta: Vec3::new(0.2, 0.9, 1.1),
        k: Vec3::new(3.9, 2.4, 2.1),
        specular_reflectance: Vec3::ONE,
        specular_texture: None,
        two_sided,
        roughness: Some(roughness),
    });
    let normal = facing(wo);
    let lobes = vec![Lobe {
        axis: reflect(-wo, normal),
        side: normal,
        exponent: chart,
    }];
    let name = format!(
        "roughconductor alpha_u = {}, alpha_v = {}, {name}",
        roughness.alpha_u, roughness.alpha_v
    );
    case(name, material, FuzzMethod::Lobe, wo, lobes)
}

/// Mitsuba's `roughdielectric` of roughness `alpha` (GGX) seen from `wo`: a strip around the
/// mirror direction and one around the refracted direction.
fn microfacet_glass_case(alpha: f32, chart: f32, wo: Vec3, name: &str) -> Case {
    let roughness = Microfacet::isotropic(MicrofacetDistribution::Ggx, alpha);
    let glass = RoughGlass {
        int_ior: 1.5,
        ext_ior: 1.0,
        exponent: roughness.lobe_exponent(),
        stands_in_for: Some(roughness),
    };
    let hit = floor_hit();
    let (normal, eta) = side(&hit, wo, glass.int_ior, glass.ext_ior);
    let mut lobes = vec![Lobe {
        axis: reflect(-wo, normal),
        side: normal,
        exponent: chart,
    }];
    if let Some(refracted) = refract(-wo, normal, eta) {
        lobes.push(Lobe {
            axis: refracted,
            side: -normal,
            exponent: chart,
        });
    }
    let name = format!("roughdielectric GGX alpha = {alpha}, {name}");
    case(
        name,
        Material::RoughGlass(glass),
        FuzzMethod::Lobe,
        wo,
        lobes,
    )
}

/// The microfacet models through `Bsdf`: an anisotropic metal from above and, two-sided, from
/// below (its frame's `z` turned round), and rough glass from both sides.
pub fn microfacet() -> [Case; MICROFACET] {
    let stretched = Microfacet::anisotropic(MicrofacetDistribution::Beckmann, 0.05, 0.3);
    [
        metal_case(stretched, false, 8.0, at(50.0, true), "50°"),
        metal_case(
            stretched,
            true,
            8.0,
            at(30.0, false),
            "two-sided from below, 30°",
        ),
        microfacet_glass_case(0.2, 8.0, at(40.0, true), "from outside, 40°"),
        microfacet_glass_case(0.1, 20.0, at(30.0, false), "from inside, 30°"),
    ]
}
