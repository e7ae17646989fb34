//! Metals, thin glass and plastic as the loader reads them: Mitsuba 3's names, defaults and
//! refusals.

use std::path::Path;

use glam::Vec3;

use super::super::{named_ior, named_ior_names, parse_scene};
use super::scene_with;
use common::scene::{Conductor, Material, Plastic};

/// The material of the only shape of a scene whose body is a sphere with `bsdf`.
fn material(bsdf: &str) -> Result<Material, String> {
    let text = scene_with(&format!(r#"<shape type="sphere">{bsdf}</shape>"#));
    parse_scene(&text, Path::new("test.xml"), &[])
        .map(|loaded| loaded.scene.surfaces[0].material.clone())
        .map_err(|e| e.to_string())
}

fn conductor(bsdf: &str) -> Conductor {
    match material(bsdf) {
        Ok(Material::Conductor(c)) => c,
        other => panic!("{bsdf}: {other:?}"),
    }
}

#[test]
fn a_named_metal_is_mitsubas_rgb_index() {
    let gold = conductor(r#"<bsdf type="conductor"><string name="material" value="Au"/></bsdf>"#);
    assert_eq!(gold.eta, Vec3::new(0.14303598, 0.37530708, 1.4420453));
    assert_eq!(gold.k, Vec3::new(3.982997, 2.3855565, 1.6033592));
    assert_eq!(gold.specular_reflectance, Vec3::ONE);
    assert_eq!(gold.roughness, None);
    assert!(!gold.two_sided);
    let rough = conductor(
        r#"<bsdf type="roughconductor"><string name="material" value="Al"/>
           <float name="alpha" value="0.2"/></bsdf>"#,
    );
    assert_eq!(rough.eta.x, 1.6575009);
    assert_eq!(rough.roughness.unwrap().alpha(), 0.2);
    let both_sides = conductor(
        r#"<bsdf type="twosided"><bsdf type="conductor"><string name="material" value="Cu"/></bsdf></bsdf>"#,
    );
    assert!(both_sides.two_sided);
}

#[test]
fn eta_and_k_may_be_given_as_colours_or_numbers_with_mitsubas_defaults() {
    let rgb = conductor(
        r#"<bsdf type="conductor"><rgb name="eta" value="0.2, 0.9, 1.1"/>
           <rgb name="k" value="3.9, 2.4, 2.1"/><rgb name="specular_reflectance" value="0.5"/></bsdf>"#,
    );
    assert_eq!(rgb.eta, Vec3::new(0.2, 0.9, 1.1));
    assert_eq!(rgb.k, Vec3::new(3.9, 2.4, 2.1));
    assert_eq!(rgb.specular_reflectance, Vec3::splat(0.5));
    // Mitsuba's defaults for the one left out: eta 0, k 1.
    let eta_only = conductor(r#"<bsdf type="conductor"><float name="eta" value="1.5"/></bsdf>"#);
    assert_eq!((eta_only.eta, eta_only.k), (Vec3::splat(1.5), Vec3::ONE));
    let k_only = conductor(r#"<bsdf type="conductor"><float name="k" value="2"/></bsdf>"#);
    assert_eq!((k_only.eta, k_only.k), (Vec3::ZERO, Vec3::splat(2.0)));
}

#[test]
fn the_default_conductor_is_the_perfect_mirror() {
    assert_eq!(
        material(r#"<bsdf type="conductor"/>"#),
        Ok(Material::mirror())
    );
    assert_eq!(
        material(
            r#"<bsdf type="conductor"><string name="material" value="none"/>
               <rgb name="specular_reflectance" value="0.9"/></bsdf>"#
        ),
        Ok(Material::Mirror {
            reflectance: Vec3::splat(0.9)
        })
    );
    // Rough, it stays a conductor (the microfacet model needs its index): eta 0, k 1.
    let rough = conductor(r#"<bsdf type="roughconductor"/>"#);
    assert_eq!((rough.eta, rough.k), (Vec3::ZERO, Vec3::ONE));
    assert_eq!(rough.normal_incidence_fresnel(), Vec3::ONE);
}

#[test]
fn metals_named_wrongly_or_twice_are_refused_with_the_list() {
    let unknown =
        material(r#"<bsdf type="conductor"><string name="material" value="gold"/></bsdf>"#)
            .unwrap_err();
    assert!(
        unknown.contains("test.xml:2:45: conductor: unknown material \"gold\"")
            && unknown.contains("none (a perfect mirror) and a-C, Ag, Al")
            && unknown.contains("Au"),
        "{unknown}"
    );
    // Mitsuba's names are file names: case matters.
    assert!(
        material(r#"<bsdf type="conductor"><string name="material" value="au"/></bsdf>"#).is_err()
    );
    let both = material(
        r#"<bsdf type="roughconductor"><string name="material" value="Au"/>
           <float name="eta" value="1.5"/></bsdf>"#,
    )
    .unwrap_err();
    assert!(
        both.contains("either a named material or eta and k"),
        "{both}"
    );
    let negative =
        material(r#"<bsdf type="conductor"><float name="k" value="-1"/></bsdf>"#).unwrap_err();
    assert!(
        negative.contains("k must be finite and not negative"),
        "{negative}"
    );
}

#[test]
fn every_index_mitsuba_names_is_known_in_any_case() {
    let names = named_ior_names();
    assert_eq!(names.len(), 23);
    for (name, ior) in [
        ("vacuum", 1.0),
        ("helium", 1.000036),
        ("carbon dioxide", 1.00045),
        ("silicone oil", 1.52045),
        ("water ice", 1.31),
        ("acrylic glass", 1.49),
        ("polypropylene", 1.49),
        ("bk7", 1.5046),
        ("pet", 1.575),
        ("diamond", 2.419),
    ] {
        assert_eq!(named_ior(name), Some(ior), "{name}");
    }
    assert_eq!(named_ior("BK7"), Some(1.5046));
    assert_eq!(named_ior("Fused Quartz"), Some(1.458));
    assert_eq!(named_ior("glass"), None);
    let glass = material(
        r#"<bsdf type="dielectric"><string name="int_ior" value="Diamond"/>
           <string name="ext_ior" value="water"/></bsdf>"#,
    );
    assert_eq!(
        glass,
        Ok(Material::Dielectric {
            int_ior: 2.419,
            ext_ior: 1.333
        })
    );
    let unknown =
        material(r#"<bsdf type="dielectric"><string name="int_ior" value="glass"/></bsdf>"#)
            .unwrap_err();
    assert!(
        unknown.contains("unknown material \"glass\"") && unknown.contains("sodium chloride"),
        "{unknown}"
    );
}

#[test]
fn thin_glass_defaults_to_bk7_in_air() {
    assert_eq!(
        material(r#"<bsdf type="thindielectric"/>"#),
        Ok(Material::ThinDielectric {
            int_ior: 1.5046,
            ext_ior: 1.000277
        })
    );
    assert_eq!(
        material(r#"<bsdf type="thindielectric"><string name="int_ior" value="pyrex"/></bsdf>"#),
        Ok(Material::ThinDielectric {
            int_ior: 1.47,
            ext_ior: 1.000277
        })
    );
    let tinted = material(
        r#"<bsdf type="thindielectric"><rgb name="specular_transmittance" value="0.5"/></bsdf>"#,
    )
    .unwrap_err();
    assert!(tinted.contains("`specular_transmittance`"), "{tinted}");
}

#[test]
fn plastic_has_mitsubas_defaults_and_reads_every_parameter() {
    assert_eq!(
        material(r#"<bsdf type="plastic"/>"#),
        Ok(Material::Plastic(Plastic {
            diffuse_reflectance: Vec3::splat(0.5),
            specular_reflectance: Vec3::ONE,
            diffuse_texture: None,
            specular_texture: None,
            int_ior: 1.49,
            ext_ior: 1.000277,
            nonlinear: false,
            two_sided: false,
            roughness: None,
        }))
    );
    let Ok(Material::Plastic(shiny)) = material(
        r#"<bsdf type="twosided"><bsdf type="roughplastic">
             <rgb name="diffuse_reflectance" value="0.1, 0.27, 0.36"/>
             <float name="int_ior" value="1.9"/><boolean name="nonlinear" value="true"/>
             <float name="alpha" value="0.3"/><string name="distribution" value="ggx"/>
           </bsdf></bsdf>"#,
    ) else {
        panic!("roughplastic");
    };
    assert_eq!(shiny.diffuse_reflectance, Vec3::new(0.1, 0.27, 0.36));
    assert_eq!(shiny.int_ior, 1.9);
    assert!(shiny.nonlinear && shiny.two_sided);
    assert_eq!(shiny.roughness.unwrap().alpha(), 0.3);
    let typo =
        material(r#"<bsdf type="plastic"><float name="intior" value="1.5"/></bsdf>"#).unwrap_err();
    assert!(typo.contains("has no property `intior`"), "{typo}");
}

#[test]
fn the_lectures_stand_in_for_a_metal_is_its_normal_incidence_colour() {
    let gold =
        material(r#"<bsdf type="conductor"><string name="material" value="Au"/></bsdf>"#).unwrap();
    let Some((Material::Mirror { reflectance }, how)) = gold.lecture_stand_in() else {
        panic!("{gold:?}");
    };
    // ((n - 1)² + k²) / ((n + 1)² + k²) of the red channel, worked by hand.
    let (n, k) = (0.14303598f32, 3.982997f32);
    let red = ((n - 1.0).powi(2) + k * k) / ((n + 1.0).powi(2) + k * k);
    assert!(
        (reflectance.x - red).abs() < 1e-6 && reflectance.z < 0.5,
        "{reflectance}"
    );
    assert!(how.contains("normal incidence"));
    // The lecture's own materials and those with no stand-in have none.
    assert_eq!(Material::mirror().lecture_stand_in(), None);
    assert_eq!(
        material(r#"<bsdf type="plastic"/>"#)
            .unwrap()
            .lecture_stand_in(),
        None
    );
}
