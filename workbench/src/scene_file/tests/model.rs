//! What the loader makes of a file: the scene model, its shapes in order, its materials, and
//! the refusals of what no chapter renders.

use std::path::Path;

use glam::Vec3;

use super::super::parse_scene;
use super::scene_with;
use common::scene::{Integrator, Material, MicrofacetDistribution, Scene};

const CORNELL: &str = include_str!("../../../tests/scenes/cornell.xml");

fn scene(text: &str) -> Result<Scene, String> {
    parse_scene(text, Path::new("test.xml"), &[])
        .map(|loaded| loaded.scene)
        .map_err(|e| e.to_string())
}

#[test]
fn cornell_box_becomes_eight_surfaces_one_of_which_glows() {
    let scene = parse_scene(CORNELL, Path::new("cornell.xml"), &[])
        .expect("loads")
        .scene;
    assert_eq!(scene.shape_count(), 8);
    assert_eq!(scene.geometry.shapes().len(), 8);
    let lights: Vec<_> = scene
        .surfaces
        .iter()
        .filter(|s| s.emitter.is_some())
        .collect();
    assert_eq!(lights.len(), 1);
    assert_eq!(lights[0].material, Material::diffuse(Vec3::ZERO));
    assert!(lights[0].origin.as_ref().is_some_and(|p| p.line > 0));
    assert_eq!(scene.integrator, Integrator::Path { rr_depth: 1000 });
    assert_eq!(scene.max_depth, 8);
    assert_eq!((scene.film.width, scene.film.height), (256, 256));
    assert_eq!(scene.sampler.sample_count, 64);
    assert!(scene.origins.sensor.is_some() && scene.origins.integrator.is_some());
}

#[test]
fn still_shapes_come_first_then_moving_ones_each_piece_with_its_surface() {
    let text = scene_with(
        r#"<shape type="cube"><animation name="to_world">
             <transform time="0"/><transform time="1"><translate x="1"/></transform>
           </animation><bsdf type="conductor"/></shape>
           <shape type="cube"><bsdf type="dielectric"/></shape>"#,
    );
    let scene = scene(&text).unwrap();
    assert_eq!(scene.geometry.shapes().len(), 6, "the still cube's faces");
    assert_eq!(scene.moving.len(), 6, "the moving cube's faces");
    assert!(matches!(
        scene.surface(0).material,
        Material::Dielectric { .. }
    ));
    assert_eq!(scene.surface(6).material, Material::mirror());
    assert_eq!(scene.surface(6).origin.as_ref().unwrap().line, 2);
    assert_eq!(scene.moving[0].keyframes.len(), 2);
    // Each cube's faces share its one surface, numbered in the order of the shapes.
    assert_eq!(scene.surfaces.len(), 2);
    assert_eq!(scene.surface_of_shape, [0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1]);
}

#[test]
fn rough_materials_keep_their_roughness_or_become_lobes_that_remember_it() {
    let rough = scene(&scene_with(
        r#"<shape type="sphere"><bsdf type="twosided"><bsdf type="roughconductor">
             <float name="alpha" value="0.1"/><string name="distribution" value="ggx"/>
           </bsdf></bsdf></shape>
           <shape type="sphere"><bsdf type="roughdielectric"><string name="int_ior" value="water"/>
             <float name="alpha" value="0.05"/></bsdf></shape>"#,
    ))
    .unwrap();
    let Material::Conductor(metal) = rough.surfaces[0].material else {
        panic!("{:?}", rough.surfaces[0]);
    };
    // Mitsuba's material="none": eta 0, k 1, which reflects everything.
    assert_eq!((metal.eta, metal.k), (Vec3::ZERO, Vec3::ONE));
    assert!(metal.two_sided);
    assert_eq!(metal.roughness.unwrap().alpha(), 0.1);
    // Chapters 06 and 07 render chapter 06's lobe in its place.
    let Some((Material::Glossy(glossy), _)) = rough.surfaces[0].material.lecture_stand_in() else {
        panic!("{:?}", rough.surfaces[0]);
    };
    assert!(glossy.two_sided);
    assert_eq!(glossy.reflectance, Vec3::ONE);
    approx::assert_relative_eq!(glossy.exponent, 198.0, max_relative = 1e-4);
    let microfacet = glossy.stands_in_for.unwrap();
    assert_eq!(microfacet.distribution, MicrofacetDistribution::Ggx);
    assert!(matches!(rough.surfaces[1].material, Material::RoughGlass(g) if g.int_ior == 1.333));
}

#[test]
fn what_no_chapter_renders_is_refused_where_it_is_written() {
    for (body, expected) in [
        (
            r#"<shape type="sphere"><bsdf type="measured"/></shape>"#,
            "test.xml:2:22: unknown bsdf type \"measured\": the workbook renders diffuse,",
        ),
        (
            r#"<shape type="sphere"><bsdf type="conductor"><string name="material" value="Unobtainium"/></bsdf></shape>"#,
            "unknown material \"Unobtainium\"",
        ),
        (
            r#"<shape type="sphere"><bsdf type="roughconductor"><float name="alpha" value="-0.1"/></bsdf></shape>"#,
            "alpha must be a positive number",
        ),
        (
            r#"<shape type="sphere"><bsdf type="roughconductor"><string name="distribution" value="phong"/></bsdf></shape>"#,
            "unknown microfacet distribution",
        ),
        (
            r#"<shape type="sphere"><bsdf type="roughconductor"><float name="alpha_u" value="0.1"/></bsdf></shape>"#,
            "test.xml:2:50: alpha_u and alpha_v go together",
        ),
        (
            r#"<shape type="sphere"><bsdf type="roughdielectric"><float name="alpha" value="0.1"/><float name="alpha_u" value="0.1"/><float name="alpha_v" value="0.2"/></bsdf></shape>"#,
            "give either alpha or alpha_u and alpha_v",
        ),
        (
            r#"<shape type="sphere"><bsdf type="roughplastic"><float name="alpha_u" value="0.1"/><float name="alpha_v" value="0.2"/></bsdf></shape>"#,
            "roughplastic has one roughness in Mitsuba 3",
        ),
        (
            r#"<shape type="sphere"><bsdf type="roughconductor"><float name="alpha_u" value="0.1"/><float name="alpha_v" value="0"/></bsdf></shape>"#,
            "alpha_v must be a positive number, found 0",
        ),
        (
            r#"<shape type="sphere"><bsdf type="phong"><float name="exponent" value="-3"/></bsdf></shape>"#,
            "lobe exponent",
        ),
        (
            r#"<shape type="sphere"><bsdf type="roughconductor"><float name="alpah" value="0.1"/></bsdf></shape>"#,
            "test.xml:2:50: the roughconductor bsdf has no property `alpah`",
        ),
        (
            r#"<shape type="sphere"><transform name="to_world"><scale x="2"/></transform></shape>"#,
            "ellipsoid",
        ),
        (
            r#"<integrator type="ptracer"/>"#,
            "the integrator type \"ptracer\"",
        ),
    ] {
        let error = scene(&scene_with(body)).expect_err(body);
        assert!(error.contains(expected), "{body}: {error}");
    }
    let backwards = r#"<scene version="3.0.0"><sensor type="perspective"><float name="fov" value="40"/>
        <float name="shutter_open" value="1"/><float name="shutter_close" value="0.5"/></sensor></scene>"#;
    let error = scene(backwards).unwrap_err();
    assert!(
        error.contains("shutter_close 0.5 is before its shutter_open 1"),
        "{error}"
    );
}

#[test]
fn an_anisotropic_roughness_keeps_both_widths_and_its_lobe_takes_their_mean() {
    let rough = scene(&scene_with(
        r#"<shape type="sphere"><bsdf type="roughconductor">
             <float name="alpha_u" value="0.05"/><float name="alpha_v" value="0.2"/>
           </bsdf></shape>"#,
    ))
    .unwrap();
    let Material::Conductor(metal) = rough.surfaces[0].material else {
        panic!("{:?}", rough.surfaces[0]);
    };
    let roughness = metal.roughness.unwrap();
    assert_eq!((roughness.alpha_u, roughness.alpha_v), (0.05, 0.2));
    assert!(roughness.is_anisotropic());
    // The round lobe of chapters 06 and 07: alpha = sqrt(0.05 * 0.2) = 0.1, n = 2 / 0.01 - 2.
    approx::assert_relative_eq!(roughness.alpha(), 0.1, max_relative = 1e-6);
    approx::assert_relative_eq!(roughness.lobe_exponent(), 198.0, max_relative = 1e-4);
}

#[test]
fn the_volumetric_path_tracers_are_the_path_tracer_where_there_are_no_media() {
    let with = |integrator: &str| {
        scene(&scene_with(&format!(
            r#"<integrator type="{integrator}"><integer name="max_depth" value="7"/>
                 <integer name="rr_depth" value="3"/><boolean name="hide_emitters" value="true"/>
               </integrator>"#
        )))
        .unwrap_or_else(|e| panic!("{integrator}: {e}"))
    };
    let path = with("path");
    for integrator in ["volpath", "volpathmis"] {
        let volumetric = with(integrator);
        assert_eq!(volumetric.integrator, path.integrator, "{integrator}");
        assert_eq!(volumetric.max_depth, path.max_depth, "{integrator}");
        assert!(volumetric.hide_emitters, "{integrator}");
    }
}

#[test]
fn a_directional_light_shines_along_its_direction_or_its_to_worlds_z() {
    let light = |body: &str| {
        let scene = scene(&scene_with(body)).unwrap_or_else(|e| panic!("{body}: {e}"));
        assert_eq!(scene.directional_lights.len(), 1, "{body}");
        scene.directional_lights[0]
    };
    let given = light(
        r#"<emitter type="directional"><vector name="direction" x="0" y="-2" z="0"/>
             <rgb name="irradiance" value="3, 2, 1"/></emitter>"#,
    );
    assert_eq!(given.direction, Vec3::new(0.0, -1.0, 0.0));
    assert_eq!(given.irradiance, Vec3::new(3.0, 2.0, 1.0));
    let turned = light(
        r#"<emitter type="directional"><transform name="to_world"><rotate x="1" angle="90"/></transform></emitter>"#,
    );
    assert!(
        (turned.direction - Vec3::new(0.0, -1.0, 0.0)).length() < 1e-6,
        "{turned:?}"
    );
    assert_eq!(turned.irradiance, Vec3::ONE, "Mitsuba's default irradiance");
    assert_eq!(light(r#"<emitter type="directional"/>"#).direction, Vec3::Z);
    for (body, says) in [
        (
            r#"<emitter type="directional"><vector name="direction" x="0" y="0" z="0"/></emitter>"#,
            "needs a direction",
        ),
        (
            r#"<emitter type="directional"><vector name="direction" x="0" y="0" z="1"/>
                 <transform name="to_world"><rotate x="1" angle="90"/></transform></emitter>"#,
            "a directional emitter takes \"direction\" or \"to_world\", not both",
        ),
        (
            r#"<emitter type="point"><point name="position" x="0" y="0" z="1"/>
                 <transform name="to_world"><translate x="1"/></transform></emitter>"#,
            "a point emitter takes \"position\" or \"to_world\", not both",
        ),
        (
            r#"<emitter type="directional"><rgb name="irradiance" value="-1"/></emitter>"#,
            "irradiance must be finite and not negative",
        ),
    ] {
        let error = scene(&scene_with(body)).expect_err(body);
        assert!(error.contains(says), "{body}: {error}");
    }
}

#[test]
fn mitchell_and_catmull_rom_filters_are_read_with_mitsubas_parameters() {
    let filter = |rfilter: &str| {
        let text = format!(
            r#"<scene version="3.0.0"><sensor type="perspective"><float name="fov" value="40"/>
                 <film type="hdrfilm">{rfilter}</film></sensor></scene>"#
        );
        scene(&text).map(|scene| scene.film.filter)
    };
    use common::scene::FilmFilter;
    assert_eq!(
        filter(r#"<rfilter type="mitchell"/>"#),
        Ok(FilmFilter::Mitchell {
            b: 1.0 / 3.0,
            c: 1.0 / 3.0
        })
    );
    assert_eq!(
        filter(
            r#"<rfilter type="mitchell"><float name="B" value="0.5"/><float name="C" value="0.25"/></rfilter>"#
        ),
        Ok(FilmFilter::Mitchell { b: 0.5, c: 0.25 })
    );
    assert_eq!(
        filter(r#"<rfilter type="catmullrom"/>"#),
        Ok(FilmFilter::Mitchell { b: 0.0, c: 0.5 })
    );
    let error = filter(r#"<rfilter type="lanczos"/>"#).unwrap_err();
    assert!(
        error.contains("unknown rfilter type \"lanczos\""),
        "{error}"
    );
}

#[test]
fn a_thin_lens_without_a_focus_distance_focuses_where_mitsuba_does() {
    use common::scene::CameraModel;
    let thin_lens = |extra: &str| {
        let text = format!(
            "<scene version=\"3.0.0\">\n<sensor type=\"thinlens\"><float name=\"fov\" \
             value=\"40\"/><float name=\"aperture_radius\" value=\"0.1\"/>{extra}</sensor>\n\
             </scene>"
        );
        super::parse(&text).map(|loaded| loaded.scene.sensor.model)
    };
    // Mitsuba 3.9.1 focuses at the far clip plane: 10000 unless the file sets far_clip.
    let focus = |model| match model {
        Ok(CameraModel::ThinLens { focus_distance, .. }) => focus_distance,
        other => panic!("not a thin lens: {other:?}"),
    };
    assert_eq!(focus(thin_lens("")), 10_000.0);
    assert_eq!(
        focus(thin_lens("<float name=\"far_clip\" value=\"50\"/>")),
        50.0
    );
    assert_eq!(
        focus(thin_lens("<float name=\"focus_distance\" value=\"3\"/>")),
        3.0
    );
    // Mitsuba has no default aperture_radius either, and refuses the sensor without one.
    let text = "<scene version=\"3.0.0\">\n<sensor type=\"thinlens\"/>\n</scene>";
    let error = super::parse(text).expect_err("no aperture_radius");
    assert!(error.message.contains("aperture_radius"), "{error}");
}

#[test]
fn structured_samplers_take_the_sample_counts_mitsuba_takes() {
    let with_sampler = |type_name: &str, count: u32| {
        let text = format!(
            r#"<scene version="3.0.0">
    <sensor type="perspective">
        <sampler type="{type_name}">
            <integer name="sample_count" value="{count}"/>
        </sampler>
    </sensor>
</scene>"#
        );
        parse_scene(&text, Path::new("test.xml"), &[]).unwrap()
    };
    let independent = with_sampler("independent", 10);
    assert_eq!(independent.scene.sampler.sample_count, 10);
    assert!(independent.warnings.is_empty());
    for (type_name, count) in [
        ("stratified", 16),
        ("multijitter", 12),
        ("orthogonal", 25),
        ("ldsampler", 16),
    ] {
        let loaded = with_sampler(type_name, 10);
        assert_eq!(loaded.scene.sampler.sample_count, count, "{type_name}");
        assert_eq!(loaded.scene.sampler.type_name, type_name);
        let warning = &loaded.warnings[0];
        assert_eq!(warning.line, 3, "{warning:?}");
        assert!(
            warning.message.contains(&format!("takes {count} samples"))
                && warning.message.contains("asks for 10"),
            "{warning:?}"
        );
    }
    let huge = format!(
        r#"<scene version="3.0.0"><sensor type="perspective">
        <sampler type="stratified"><integer name="sample_count" value="{}"/></sampler>
    </sensor></scene>"#,
        u32::MAX
    );
    let error = parse_scene(&huge, Path::new("test.xml"), &[]).unwrap_err();
    assert!(error.to_string().contains("cannot lay out"), "{error}");
}
