//! A corpus of broken scene files: each must fail with a message that names the problem, on
//! the line where the problem is.

use std::path::Path;

use super::super::load_scene_file;
use super::{parse, scene_with};

/// What is parsed: a body wrapped by [`scene_with`] (starting on line 2), or a whole file.
enum Input {
    Body(&'static str),
    Whole(&'static str),
}

use Input::{Body, Whole};

/// One broken file: its name, its text, a fragment the message must contain, and the line.
struct Broken {
    name: &'static str,
    input: Input,
    fragment: &'static str,
    line: u32,
}

const CORPUS: &[Broken] = &[
    Broken {
        name: "malformed XML",
        input: Whole("<scene version=\"3.0.0\">\n<shape type=\"cube\"></shap>\n</scene>"),
        fragment: "malformed XML",
        line: 2,
    },
    Broken {
        name: "unknown shape type",
        input: Body("<shape type=\"torus\"/>"),
        fragment: "unknown shape type \"torus\"",
        line: 2,
    },
    Broken {
        name: "unknown element",
        input: Body("<medium type=\"homogeneous\"/>"),
        fragment: "unknown element <medium>",
        line: 2,
    },
    Broken {
        name: "unknown property element",
        input: Body("<shape type=\"cube\">\n<colour name=\"x\" value=\"1\"/></shape>"),
        fragment: "unknown element <colour>",
        line: 3,
    },
    Broken {
        name: "missing ref",
        input: Body("<shape type=\"cube\">\n<ref id=\"gold\"/></shape>"),
        fragment: "<ref id=\"gold\"> names nothing",
        line: 3,
    },
    Broken {
        name: "bad float",
        input: Body("<shape type=\"sphere\">\n<float name=\"radius\" value=\"1.0x\"/></shape>"),
        fragment: "expected a finite number, found \"1.0x\"",
        line: 3,
    },
    Broken {
        name: "wrong property kind",
        input: Body("<shape type=\"sphere\">\n<string name=\"radius\" value=\"big\"/></shape>"),
        fragment: "\"radius\" of the sphere shape must be a <float>, found a <string>",
        line: 3,
    },
    Broken {
        name: "zero radius",
        input: Body("<shape type=\"sphere\">\n<float name=\"radius\" value=\"0\"/></shape>"),
        fragment: "radius must be positive",
        line: 3,
    },
    Broken {
        name: "zero scale",
        input: Body(
            "<shape type=\"cube\"><transform name=\"to_world\">\n<scale x=\"0\"/></transform></shape>",
        ),
        fragment: "<scale> by zero",
        line: 3,
    },
    Broken {
        name: "singular matrix",
        input: Body(
            "<shape type=\"cube\"><transform name=\"to_world\">\n\
             <matrix value=\"1 0 0 0 1 0 0 0 0 0 0 0 0 0 0 1\"/></transform></shape>",
        ),
        fragment: "<matrix> is not invertible",
        line: 3,
    },
    Broken {
        name: "lookat origin equals target",
        input: Body(
            "<shape type=\"cube\"><transform name=\"to_world\">\n\
             <lookat origin=\"1, 1, 1\" target=\"1, 1, 1\" up=\"0, 1, 0\"/></transform></shape>",
        ),
        fragment: "origin equal to target",
        line: 3,
    },
    Broken {
        name: "lookat up along the view",
        input: Body(
            "<shape type=\"cube\"><transform name=\"to_world\">\n\
             <lookat origin=\"0, 0, 0\" target=\"0, 2, 0\" up=\"0, 1, 0\"/></transform></shape>",
        ),
        fragment: "parallel to the view direction",
        line: 3,
    },
    Broken {
        name: "unknown $name",
        input: Body("<shape type=\"sphere\">\n<float name=\"radius\" value=\"$r\"/></shape>"),
        fragment: "unknown parameter \"$r\"",
        line: 3,
    },
    Broken {
        name: "obj without filename",
        input: Body("<shape type=\"obj\"/>"),
        fragment: "needs <string name=\"filename\"",
        line: 2,
    },
    Broken {
        name: "zero film width",
        input: Whole(
            "<scene version=\"3.0.0\"><sensor type=\"perspective\"><float name=\"fov\" value=\"40\"/>\n\
             <film type=\"hdrfilm\"><integer name=\"width\" value=\"0\"/></film></sensor></scene>",
        ),
        fragment: "width must be a positive integer",
        line: 2,
    },
    Broken {
        name: "area emitter at top level",
        input: Body("<emitter type=\"area\"/>"),
        fragment: "must be inside the <shape>",
        line: 2,
    },
    Broken {
        name: "animation with one keyframe",
        input: Body(
            "<shape type=\"cube\">\n<animation name=\"to_world\">\
             <transform time=\"0\"><translate x=\"1\"/></transform></animation></shape>",
        ),
        fragment: "needs at least two <transform time=",
        line: 3,
    },
    Broken {
        name: "animation times not increasing",
        input: Body(
            "<shape type=\"cube\"><animation name=\"to_world\">\
             <transform time=\"0.5\"/>\n<transform time=\"0.5\"/></animation></shape>",
        ),
        fragment: "keyframe times must increase: time 0.5 follows time 0.5",
        line: 3,
    },
    Broken {
        name: "animation keyframe without time",
        input: Body(
            "<shape type=\"cube\"><animation name=\"to_world\"><transform time=\"0\"/>\n\
             <transform><translate x=\"1\"/></transform></animation></shape>",
        ),
        fragment: "needs a \"time\" attribute",
        line: 3,
    },
    Broken {
        name: "animation keyframe degenerate",
        input: Body(
            "<shape type=\"cube\"><animation name=\"to_world\"><transform time=\"0\"/>\
             <transform time=\"1\">\n<scale x=\"0\"/></transform></animation></shape>",
        ),
        fragment: "<scale> by zero",
        line: 3,
    },
    Broken {
        name: "animation keyframe singular matrix",
        input: Body(
            "<sensor type=\"perspective\"><float name=\"fov\" value=\"40\"/>\
             <animation name=\"to_world\"><transform time=\"0\"/><transform time=\"1\">\n\
             <matrix value=\"1 0 0 0 1 0 0 0 0 0 0 0 0 0 0 1\"/></transform></animation></sensor>",
        ),
        fragment: "<matrix> is not invertible",
        line: 3,
    },
    Broken {
        name: "animation with a stray element",
        input: Body(
            "<shape type=\"cube\"><animation name=\"to_world\">\n\
             <translate x=\"1\"/></animation></shape>",
        ),
        fragment: "<translate> is not allowed in an <animation>",
        line: 3,
    },
    Broken {
        name: "animation and transform both",
        input: Body(
            "<shape type=\"cube\"><transform name=\"to_world\"/>\n<animation name=\"to_world\">\
             <transform time=\"0\"/><transform time=\"1\"/></animation></shape>",
        ),
        fragment: "\"to_world\" of the cube shape is given twice",
        line: 3,
    },
    Broken {
        name: "animation where a float belongs",
        input: Body(
            "<shape type=\"sphere\">\n<animation name=\"radius\"><transform time=\"0\"/>\
             <transform time=\"1\"/></animation></shape>",
        ),
        fragment: "must be a <float>, found an <animation>",
        line: 3,
    },
    Broken {
        name: "no sensor",
        input: Whole("<scene version=\"3.0.0\"></scene>"),
        fragment: "no <sensor>",
        line: 0,
    },
];

#[test]
fn every_broken_file_fails_with_its_message_and_line() {
    for broken in CORPUS {
        let text = match broken.input {
            Body(body) => scene_with(body),
            Whole(text) => text.to_string(),
        };
        let name = broken.name;
        let error = match parse(&text) {
            Ok(_) => panic!("{name}: loaded, but should fail"),
            Err(error) => error,
        };
        assert!(
            error.message.contains(broken.fragment),
            "{name}: message {:?} lacks {:?}",
            error.message,
            broken.fragment
        );
        assert_eq!(error.line, broken.line, "{name}: {error}");
        assert_eq!(error.file, Path::new("test.xml"), "{name}");
    }
}

#[test]
fn errors_display_file_line_and_column() {
    let error = parse(&scene_with("<shape type=\"torus\"/>")).expect_err("unknown shape");
    assert!(
        error
            .to_string()
            .starts_with("test.xml:2:1: unknown shape type"),
        "{error}"
    );
}

#[test]
fn a_missing_file_is_an_error_naming_it() {
    let directory = tempfile::tempdir().expect("temporary directory");
    let path = directory.path().join("no-such-scene.xml");
    let error = load_scene_file(&path, &[]).expect_err("the file does not exist");
    assert_eq!(error.file, path);
    assert!(error.to_string().contains("no-such-scene.xml"), "{error}");
    assert!(error.message.contains("cannot read"), "{error}");
}

/// `depth` `<bsdf>`s inside a shape, one a line from line 3, closed on the last line.
fn nested_bsdfs(depth: usize) -> String {
    let mut body = String::from("<shape type=\"sphere\">");
    for _ in 0..depth {
        body.push_str("\n<bsdf type=\"diffuse\">");
    }
    body.push('\n');
    body.push_str(&"</bsdf>".repeat(depth));
    body.push_str("</shape>");
    scene_with(&body)
}

#[test]
fn a_file_nested_thousands_deep_is_refused_where_it_gets_too_deep() {
    // 20 000 levels overflowed the stack and aborted the process before the reader measured
    // the depth: the element tree is built and walked recursively.
    let error = parse(&nested_bsdfs(20_000)).expect_err("far too deep");
    assert!(
        error.message.contains("nest more than 100 levels"),
        "{error}"
    );
    // The scene is depth 0 and the shape 1, so the 100th <bsdf>, on line 102, is the first
    // element deeper than 100 levels.
    assert_eq!(error.line, 102, "{error}");
    assert_eq!(error.file, Path::new("test.xml"));
}

#[test]
fn a_file_nested_as_deep_as_allowed_is_read_past_the_depth_check() {
    let error = parse(&nested_bsdfs(99)).expect_err("a diffuse BSDF holds no BSDF");
    assert!(!error.message.contains("levels"), "{error}");
    assert!(error.message.contains("cannot contain <bsdf>"), "{error}");
}

#[test]
fn a_device_named_as_a_mesh_or_an_include_is_refused_not_read() {
    if !Path::new("/dev/zero").exists() {
        return;
    }
    // Read as an OBJ without a bound, /dev/zero took gigabytes within seconds.
    let directory = tempfile::tempdir().expect("temporary directory");
    for (body, what) in [
        (
            "<shape type=\"obj\"><string name=\"filename\" value=\"/dev/zero\"/></shape>",
            "the mesh /dev/zero is not a regular file",
        ),
        (
            "<shape type=\"ply\"><string name=\"filename\" value=\"/dev/urandom\"/></shape>",
            "the mesh /dev/urandom is not a regular file",
        ),
        (
            "<include filename=\"/dev/zero\"/>",
            "the included file /dev/zero is not a regular file",
        ),
    ] {
        let path = directory.path().join("scene.xml");
        std::fs::write(&path, scene_with(body)).expect("the scene file");
        let error = match load_scene_file(&path, &[]) {
            Ok(_) => panic!("{body}: loaded"),
            Err(error) => error,
        };
        assert!(error.message.contains(what), "{body}: {error}");
        assert_eq!(error.line, 2, "{body}: {error}");
    }
}

#[test]
fn includes_that_multiply_are_refused_at_the_bound_on_nodes() {
    // Each level includes the next 100 times: 100^4 copies of the last file's 10 000
    // comments, every file far below the size limit. Read whole, that would be 10^12 nodes.
    let directory = tempfile::tempdir().expect("temporary directory");
    let write = |name: &str, body: String| {
        std::fs::write(directory.path().join(name), body).expect("a level");
    };
    for level in 0..4 {
        let include = format!("<include filename=\"level{}.xml\"/>", level + 1);
        write(
            &format!("level{level}.xml"),
            format!("<scene version=\"3.0.0\">{}</scene>", include.repeat(100)),
        );
    }
    write(
        "level4.xml",
        format!(
            "<scene version=\"3.0.0\">{}</scene>",
            "<!-- a -->".repeat(10_000)
        ),
    );
    let path = directory.path().join("scene.xml");
    std::fs::write(&path, scene_with("<include filename=\"level0.xml\"/>")).expect("the scene");
    let error = load_scene_file(&path, &[]).expect_err("far too many nodes");
    assert!(
        error.message.contains("more than 4000000 XML nodes"),
        "{error}"
    );
    assert!(error.file.starts_with(directory.path()), "{error}");
    assert!(error.line >= 1, "{error}");
}

#[test]
fn includes_nested_too_deep_are_refused_naming_the_limit() {
    // A chain of 20 different files, each including the next: no loop, but too deep.
    let directory = tempfile::tempdir().expect("temporary directory");
    for level in 0..20 {
        std::fs::write(
            directory.path().join(format!("chain{level}.xml")),
            format!(
                "<scene version=\"3.0.0\">\n<include filename=\"chain{}.xml\"/></scene>",
                level + 1
            ),
        )
        .expect("a link");
    }
    std::fs::write(
        directory.path().join("chain20.xml"),
        "<scene version=\"3.0.0\"/>",
    )
    .expect("the end");
    let path = directory.path().join("scene.xml");
    std::fs::write(&path, scene_with("<include filename=\"chain0.xml\"/>")).expect("the scene");
    let error = load_scene_file(&path, &[]).expect_err("too deep");
    assert!(error.message.contains("more than 16 files deep"), "{error}");
    assert_eq!(error.line, 2, "{error}");
}

#[test]
fn a_scene_of_too_many_includes_is_refused_naming_the_limit() {
    let directory = tempfile::tempdir().expect("temporary directory");
    std::fs::write(
        directory.path().join("empty.xml"),
        "<scene version=\"3.0.0\"/>",
    )
    .expect("the empty file");
    let path = directory.path().join("scene.xml");
    let includes = "<include filename=\"empty.xml\"/>".repeat(10_001);
    std::fs::write(&path, scene_with(&includes)).expect("the scene");
    let error = load_scene_file(&path, &[]).expect_err("too many includes");
    assert!(error.message.contains("more than 10000 files"), "{error}");
    assert_eq!(error.line, 2, "{error}");
}
