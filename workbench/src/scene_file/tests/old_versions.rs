//! Files written for Mitsuba 0.6 are upgraded as Mitsuba 3 upgrades them.

use std::path::Path;

use common::scene::Scene;

/// The scene of `text`, read from `dir/scene.xml`.
fn scene_of(dir: &Path, text: &str) -> Scene {
    super::super::parse_scene(text, &dir.join("scene.xml"), &[])
        .unwrap_or_else(|e| panic!("{e}"))
        .scene
}

/// What the scene of `text` renders, as text: everything but where its parts were written.
fn rendered_parts(scene: &Scene) -> String {
    let materials: Vec<_> = scene
        .surfaces
        .iter()
        .map(|s| (&s.material, &s.emitter))
        .collect();
    format!(
        "{:?}\n{:?}\n{:?}\n{:?}\n{:?}\n{:?} {} {}",
        materials,
        scene.geometry.shapes(),
        scene.camera,
        scene.film,
        scene.sampler,
        scene.integrator,
        scene.max_depth,
        scene.hide_emitters
    )
}

const WRITTEN_FOR_0_6: &str = r#"<scene version="0.6.0">
    <integrator type="path">
        <integer name="maxDepth" value="5"/>
        <integer name="rrDepth" value="3"/>
        <boolean name="hideEmitters" value="true"/>
    </integrator>
    <sensor type="perspective">
        <float name="fov" value="40"/>
        <string name="fovAxis" value="y"/>
        <transform name="toWorld"><lookat origin="0, 1, 6" target="0, 1, 0" up="0, 1, 0"/></transform>
        <sampler type="independent"><integer name="sampleCount" value="9"/></sampler>
        <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="24"/></film>
    </sensor>
    <bsdf type="diffuse" id="board">
        <texture type="checkerboard" name="diffuseReflectance">
            <float name="uscale" value="4"/><float name="voffset" value="0.25"/>
        </texture>
    </bsdf>
    <shape type="rectangle">
        <transform name="toWorld"><scale value="3"/><rotate x="1" angle="-90"/></transform>
        <ref id="board"/>
    </shape>
    <shape type="sphere">
        <float name="radius" value="0.5"/>
        <bsdf type="roughconductor"><float name="alphaU" value="0.1"/><float name="alphaV" value="0.3"/></bsdf>
    </shape>
    <shape type="sphere">
        <point name="center" x="1" y="0" z="0"/>
        <bsdf type="dielectric"><string name="intIOR" value="bk7"/><float name="extIOR" value="1.0"/></bsdf>
    </shape>
    <shape type="rectangle">
        <boolean name="flipNormals" value="true"/>
        <emitter type="area"><rgb name="radiance" value="5"/></emitter>
    </shape>
</scene>"#;

const WRITTEN_FOR_3: &str = r#"<scene version="3.0.0">
    <integrator type="path">
        <integer name="max_depth" value="5"/>
        <integer name="rr_depth" value="3"/>
        <boolean name="hide_emitters" value="true"/>
    </integrator>
    <sensor type="perspective">
        <float name="fov" value="40"/>
        <string name="fov_axis" value="y"/>
        <transform name="to_world"><lookat origin="0, 1, 6" target="0, 1, 0" up="0, 1, 0"/></transform>
        <sampler type="independent"><integer name="sample_count" value="9"/></sampler>
        <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="24"/></film>
    </sensor>
    <bsdf type="diffuse" id="board">
        <texture type="checkerboard" name="reflectance">
            <transform name="to_uv"><translate x="0" y="0.25"/><scale x="4" y="1"/></transform>
        </texture>
    </bsdf>
    <shape type="rectangle">
        <transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/></transform>
        <ref id="board"/>
    </shape>
    <shape type="sphere">
        <float name="radius" value="0.5"/>
        <bsdf type="roughconductor"><float name="alpha_u" value="0.1"/><float name="alpha_v" value="0.3"/></bsdf>
    </shape>
    <shape type="sphere">
        <point name="center" x="1" y="0" z="0"/>
        <bsdf type="dielectric"><string name="int_ior" value="bk7"/><float name="ext_ior" value="1.0"/></bsdf>
    </shape>
    <shape type="rectangle">
        <boolean name="flip_normals" value="true"/>
        <emitter type="area"><rgb name="radiance" value="5"/></emitter>
    </shape>
</scene>"#;

#[test]
fn a_file_for_mitsuba_0_6_reads_as_its_mitsuba_3_spelling() {
    let dir = tempfile::tempdir().unwrap();
    let old = rendered_parts(&scene_of(dir.path(), WRITTEN_FOR_0_6));
    let new = rendered_parts(&scene_of(dir.path(), WRITTEN_FOR_3));
    assert_eq!(old, new);
    // And the upgrade did something: read as a 3.0 file, the old spelling is not the same.
    let unupgraded = WRITTEN_FOR_0_6.replace("version=\"0.6.0\"", "version=\"3.0.0\"");
    let as_new = super::super::parse_scene(&unupgraded, &dir.path().join("scene.xml"), &[]);
    assert!(
        as_new.is_err() || rendered_parts(&as_new.unwrap().scene) != new,
        "the camel-case names were read without the upgrade"
    );
}

#[test]
fn each_file_keeps_its_own_version() {
    // A 3.0 file included by a 0.6 one is not upgraded: a name that only looks like camel
    // case to the upgrade would otherwise change. And the other way round.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("new.xml"),
        r#"<scene version="3.0.0"><shape type="sphere"><float name="radius" value="2"/></shape></scene>"#,
    )
    .unwrap();
    std::fs::write(
        dir.path().join("old.xml"),
        r#"<scene version="0.6.0"><shape type="sphere"><boolean name="flipNormals" value="true"/></shape></scene>"#,
    )
    .unwrap();
    let scene = scene_of(
        dir.path(),
        r#"<scene version="3.0.0">
            <include filename="old.xml"/><include filename="new.xml"/>
            <sensor type="perspective"><float name="fov" value="40"/></sensor>
        </scene>"#,
    );
    assert_eq!(scene.geometry.shapes().len(), 2);
}

#[test]
fn a_version_that_is_no_number_is_refused_with_its_place() {
    let dir = tempfile::tempdir().unwrap();
    let error = super::super::parse_scene(
        "<scene version=\"three\">\n</scene>",
        &dir.path().join("scene.xml"),
        &[],
    )
    .map(|_| ())
    .unwrap_err()
    .to_string();
    assert!(error.contains("scene.xml:1:1"), "{error}");
    assert!(
        error.contains("\"three\" is not a version number"),
        "{error}"
    );
}
