//! Bad input, every entry point: each chapter binary refuses each bad input of this table with
//! a message naming the problem and a non-zero exit, never panics, and leaves no file behind
//! (neither the output nor a temporary file).
//!
//! The table is the record of what has been tried: a new flag or a new way to fail gets a row.
//! In the arguments, `{out}` is `out.png` in a fresh empty directory `{dir}`, in which `{file}`
//! is an existing regular file (to put a directory where a file is); `{bad}` is the directory
//! of broken scene files next to this crate, `{ch04}` chapter 04's scene directory.
//!
//! Chapter 08 renders only scene files, so a row about anything else would be refused for the
//! missing scene alone: a `render` row that names no `--scene` runs it with the suite's tiny
//! scene ([`scene_args`]), and is refused for its own bad input. The `bare` rows run exactly as
//! written: they are about the missing scene.

use std::path::{Path, PathBuf};
use workbook_tests::binaries::{CHAPTERS, RENDERING_CHAPTERS, files_in, run_chapter, scene_args};

/// One bad input: the chapters it is tried on, the arguments, and a fragment the error
/// message must contain.
struct Case {
    chapters: &'static [&'static str],
    args: &'static [&'static str],
    expected: &'static str,
    /// Whether a chapter without built-in scenes is given one (see the top of the file).
    with_scene: bool,
}

const ALL: &[&str] = CHAPTERS;
const RENDERING: &[&str] = RENDERING_CHAPTERS;
/// The rendering chapters with built-in scenes (`--builtin`): all but chapter 08 and the
/// renderer of real scene files.
const BUILTIN: &[&str] = &[
    "ch01-whitted",
    "ch03-anti-aliasing",
    "ch04-depth-of-field",
    "ch05-motion-blur",
    "ch06-fuzzy-reflections",
    "ch07-soft-shadows",
];
/// The chapters with chapter 03's pixel samplers and filters.
const ANTI_ALIASED: &[&str] = &[
    "ch03-anti-aliasing",
    "ch04-depth-of-field",
    "ch05-motion-blur",
    "ch06-fuzzy-reflections",
    "ch07-soft-shadows",
    "ch08-path-tracing",
    "ch09-materials",
];
/// The chapters with chapter 04's lens options.
const WITH_LENS: &[&str] = &[
    "ch04-depth-of-field",
    "ch05-motion-blur",
    "ch06-fuzzy-reflections",
    "ch07-soft-shadows",
    "ch08-path-tracing",
    "ch09-materials",
];
const CH05: &[&str] = &["ch05-motion-blur"];
/// The chapters with chapter 05's shutter and motion.
const WITH_MOTION: &[&str] = &[
    "ch05-motion-blur",
    "ch06-fuzzy-reflections",
    "ch07-soft-shadows",
    "ch08-path-tracing",
    "ch09-materials",
];
/// The chapters with chapter 06's lobes and choices at glass.
const FUZZY: &[&str] = &[
    "ch06-fuzzy-reflections",
    "ch07-soft-shadows",
    "ch08-path-tracing",
    "ch09-materials",
];
const CH07: &[&str] = &["ch07-soft-shadows"];
/// The chapters with chapter 07's area lights and their sampling options.
const AREA_LIGHTS: &[&str] = &["ch07-soft-shadows", "ch08-path-tracing", "ch09-materials"];
/// Chapter 08's path options, which the renderer of real scene files shares.
const CH08: &[&str] = &["ch08-path-tracing", "ch09-materials"];
const CH01: &[&str] = &["ch01-whitted"];
const CH02: &[&str] = &["ch02-monte-carlo"];
/// The chapters before chapter 04, which have no lens.
const BEFORE_CH04: &[&str] = &["ch01-whitted", "ch03-anti-aliasing"];
/// The chapters that render scene files but no environment map (Mitsuba's `envmap`).
const BEFORE_CH08: &[&str] = &[
    "ch01-whitted",
    "ch03-anti-aliasing",
    "ch04-depth-of-field",
    "ch05-motion-blur",
    "ch06-fuzzy-reflections",
    "ch07-soft-shadows",
];

const fn case(
    chapters: &'static [&'static str],
    args: &'static [&'static str],
    expected: &'static str,
) -> Case {
    Case {
        chapters,
        args,
        expected,
        with_scene: true,
    }
}

/// A row run exactly as written, even by chapter 08 and ch09: a row about a missing scene.
const fn bare(
    chapters: &'static [&'static str],
    args: &'static [&'static str],
    expected: &'static str,
) -> Case {
    Case {
        with_scene: false,
        ..case(chapters, args, expected)
    }
}

/// Every bad input tried, and the message it must give.
#[rustfmt::skip]
const CASES: &[Case] = &[
    // The command line itself.
    case(ALL, &[], "Usage"),
    case(ALL, &["paint"], "paint"),
    case(RENDERING, &["render", "--no-such-flag"], "--no-such-flag"),
    case(RENDERING, &["render"], "--out"),
    case(ALL, &["figures"], "--out"),
    case(ALL, &["figures", "--out", "{dir}", "--no-such-flag"], "--no-such-flag"),
    case(CH02, &["render"], "renders no scene"),
    // Sample counts and budgets.
    case(RENDERING, &["render", "--out", "{out}", "--spp", "0"], "--spp"),
    case(RENDERING, &["render", "--out", "{out}", "--spp", "-3"], "invalid value '-3' for '--spp"),
    case(RENDERING, &["render", "--out", "{out}", "--spp", "1000000001"], "--spp"),
    case(RENDERING, &["render", "--out", "{out}", "--spp", "many"], "many"),
    case(RENDERING, &["render", "--out", "{out}", "--time", "0"], "time budget"),
    case(RENDERING, &["render", "--out", "{out}", "--time", "-1"], "time budget"),
    case(RENDERING, &["render", "--out", "{out}", "--time", "nan"], "time budget"),
    case(RENDERING, &["render", "--out", "{out}", "--time", "inf"], "time budget"),
    case(RENDERING, &["render", "--out", "{out}", "--spp", "4", "--time", "1"], "cannot be used with"),
    case(RENDERING, &["render", "--out", "{out}", "--threads", "0"], "--threads"),
    case(RENDERING, &["render", "--out", "{out}", "--seed", "-1"], "invalid value '-1' for '--seed"),
    case(RENDERING, &["render", "--out", "{out}", "--threads", "-2"], "invalid value '-2' for '--threads"),
    case(RENDERING, &["render", "--out", "{out}", "--max-depth", "0"], "--max-depth"),
    case(RENDERING, &["render", "--out", "{out}", "--max-depth", "1001"], "--max-depth"),
    // Image sizes: none, negative, a side too long, and too many pixels for memory (refused
    // before any allocation, with the memory it would need).
    case(RENDERING, &["render", "--out", "{out}", "--width", "0"], "--width"),
    case(RENDERING, &["render", "--out", "{out}", "--height", "-5"], "invalid value '-5' for '--height"),
    case(RENDERING, &["render", "--out", "{out}", "--width", "65537"], "--width"),
    case(RENDERING, &["render", "--out", "{out}", "--width", "65536", "--height", "65536"], "needs 229376 MiB"),
    case(RENDERING, &["render", "--out", "{out}", "--width", "20000", "--height", "10000"], "the limit is 4096 MiB"),
    // Output paths.
    case(RENDERING, &["render", "--out", "{dir}/out.jpg"], ".png, .exr or .pfm"),
    case(RENDERING, &["render", "--out", "{dir}/out"], ".png, .exr or .pfm"),
    case(RENDERING, &["render", "--out", "{dir}"], ".png, .exr or .pfm"),
    case(RENDERING, &["render", "--out", "{dir}/sub.png/"], "names a directory, not a file"),
    case(RENDERING, &["render", "--out", "{dir}/"], ".png, .exr or .pfm"),
    case(RENDERING, &["render", "--out", "{file}/out.png"], "cannot create the directory"),
    case(RENDERING, &["render", "--out", "{out}", "--stats", "{dir}/stats.txt"], ".json"),
    case(RENDERING, &["render", "--out", "{out}", "--stats", "{file}/stats.json"], "cannot create the directory"),
    case(ALL, &["figures", "--out", "{file}/figures"], "cannot create the output directory"),
    // Scenes: built-in names, scene files missing, malformed or beyond the chapter.
    case(BUILTIN, &["render", "--out", "{out}", "--builtin", "teapot"], "teapot"),
    bare(RENDERING, &["render", "--out", "{out}", "-D", "spp=4"], "--scene"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/empty.xml", "-D", "spp"], "NAME=VALUE"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{dir}/no-such-scene.xml"], "no-such-scene.xml"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/empty.xml"], "empty.xml"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/not-xml.xml"], "not-xml.xml"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/malformed.xml"], "malformed XML"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/unknown-shape.xml"], "unknown shape type \"torus\""),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/no-sensor.xml"], "no <sensor>"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/fov-180.xml"], "fov must be between 0 and 180"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/nan-radius.xml"], "expected a finite number, found \"nan\""),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/negative-radius.xml"], "radius must be positive"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/missing-mesh.xml"], "cannot read the mesh"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/broken-mesh.xml"], "broken.obj:3: face corner `3` refers to vertex 3"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/self-default.xml"], "found \"$spp\""),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/undefined-parameter.xml"], "unknown parameter \"$undefined\""),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/zero-spp.xml"], "sample_count must be an integer of at least 1"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/huge-film.xml"], "needs 534058 MiB"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/zero-spp.xml", "-D", "=3"], "NAME=VALUE"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/bdpt.xml"], "the integrator type \"bdpt\" is not one the workbook renders"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/negative-depth.xml"], "max_depth must be -1 (unlimited) or 1 or more (0 would render a black image), found -2"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/zero-depth.xml"], "max_depth must be -1 (unlimited) or 1 or more (0 would render a black image), found 0"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/zero-rr-depth.xml"], "rr_depth must be 1 or more, found 0"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/negative-point-light.xml"], "a point light's intensity must be finite and not negative"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/negative-sky.xml"], "a constant emitter's radiance must be finite and not negative"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/integrator-child.xml"], "<bsdf> is not allowed inside <integrator>"),
    case(RENDERING, &["render", "--out", "{out}", "--scene", "{bad}/envmap.xml"], "envmap.xml:7:5: cannot read the image"),
    case(BEFORE_CH08, &["render", "--out", "{out}", "--scene", "{bad}/envmap-before-08.xml"], "line 6, column 3: an environment map (envmap); light from an image around the scene comes in chapter 08 (ch08-path-tracing)"),
    case(BEFORE_CH04, &["render", "--out", "{out}", "--scene", "{ch04}/thinlens-spheres.xml"], "thinlens"),
    // Chapter 01's pixel pattern.
    case(CH01, &["render", "--out", "{out}", "--pixel", "grid", "--spp", "8"], "square"),
    case(CH01, &["render", "--out", "{out}", "--pixel", "grid", "--time", "1"], "--time"),
    case(CH01, &["render", "--out", "{out}", "--pixel", "jitter"], "jitter"),
    // Chapter 03's samplers and filters (chapter 04 has them too).
    case(ANTI_ALIASED, &["render", "--out", "{out}", "--sampler", "blue-noise"], "blue-noise"),
    case(ANTI_ALIASED, &["render", "--out", "{out}", "--sampler", "stratified", "--time", "1"], "--spp"),
    case(ANTI_ALIASED, &["render", "--out", "{out}", "--filter", "lanczos"], "lanczos"),
    case(ANTI_ALIASED, &["render", "--out", "{out}", "--filter-radius", "0"], "radius"),
    case(ANTI_ALIASED, &["render", "--out", "{out}", "--filter-radius", "-1"], "radius"),
    case(ANTI_ALIASED, &["render", "--out", "{out}", "--filter-radius", "nan"], "radius"),
    case(ANTI_ALIASED, &["render", "--out", "{out}", "--filter-radius", "17"], "radius"),
    // Chapter 05's shutter (the later chapters read it from scene files).
    case(CH05, &["render", "--out", "{out}", "--shutter-open", "1", "--shutter-close", "0.5"], "must close at or after the time it opens"),
    case(CH05, &["render", "--out", "{out}", "--shutter-open", "nan"], "shutter times must be finite"),
    case(CH05, &["render", "--out", "{out}", "--shutter-close", "inf"], "shutter times must be finite"),
    case(CH05, &["render", "--out", "{out}", "--shutter-close", "soon"], "`soon` is not a number"),
    case(CH05, &["render", "--out", "{out}", "--stretches", "0"], "--stretches"),
    case(CH05, &["render", "--out", "{out}", "--time-sampling", "sobol"], "sobol"),
    case(WITH_MOTION, &["render", "--out", "{out}", "--scene", "{bad}/shutter-backwards.xml"], "the shutter must open before it closes"),
    // Chapter 06's lobes and choices at glass (chapters 07 and 08 have them too).
    case(FUZZY, &["render", "--out", "{out}", "--exponent", "-1"], "the lobe exponent must be a finite number >= 0"),
    case(FUZZY, &["render", "--out", "{out}", "--exponent", "nan"], "the lobe exponent must be a finite number >= 0"),
    case(FUZZY, &["render", "--out", "{out}", "--exponent", "inf"], "the lobe exponent must be a finite number >= 0"),
    case(FUZZY, &["render", "--out", "{out}", "--exponent", "shiny"], "`shiny` is not a number"),
    case(FUZZY, &["render", "--out", "{out}", "--glass", "neither"], "neither"),
    case(FUZZY, &["render", "--out", "{out}", "--fuzz", "gaussian"], "gaussian"),
    case(FUZZY, &["render", "--out", "{out}", "--below-surface", "clamp"], "clamp"),
    case(FUZZY, &["render", "--out", "{out}", "--scene", "{bad}/unknown-bsdf.xml"], "unknown bsdf type \"pplastic\""),
    case(FUZZY, &["render", "--out", "{out}", "--scene", "{bad}/rough-typo.xml"], "roughconductor bsdf has no property `alhpa`"),
    // Chapter 07's area lights (chapter 08 has them too).
    case(AREA_LIGHTS, &["render", "--out", "{out}", "--light-samples", "0"], "--light-samples"),
    case(AREA_LIGHTS, &["render", "--out", "{out}", "--light-samples", "-4"], "invalid value '-4' for '--light-samples"),
    case(AREA_LIGHTS, &["render", "--out", "{out}", "--light-samples", "4097"], "--light-samples"),
    case(AREA_LIGHTS, &["render", "--out", "{out}", "--light-strata", "sobol"], "sobol"),
    case(AREA_LIGHTS, &["render", "--out", "{out}", "--light-sampling", "importance"], "importance"),
    case(AREA_LIGHTS, &["render", "--out", "{out}", "--disc-warp", "square"], "square"),
    case(CH07, &["render", "--out", "{out}", "--light-scale", "0"], "--light-scale must be a number from 1e-4 to 1e4"),
    case(CH07, &["render", "--out", "{out}", "--light-scale", "nan"], "--light-scale must be a number from 1e-4 to 1e4"),
    case(CH07, &["render", "--out", "{out}", "--light-scale", "1e9"], "--light-scale must be a number from 1e-4 to 1e4"),
    case(AREA_LIGHTS, &["render", "--out", "{out}", "--scene", "{bad}/moving-light.xml"], "an area light that moves (shape 1); no chapter samples lights that move"),
    case(AREA_LIGHTS, &["render", "--out", "{out}", "--scene", "{bad}/negative-light.xml"], "an area light's radiance must be finite and not negative"),
    // Chapter 08's path tracer: a scene file is needed, and the estimator's options must be
    // known and in range; chapter 06's and 07's options a path has no use for are refused.
    bare(CH08, &["render", "--out", "{out}"], "render needs a scene: --scene FILE.xml"),
    case(CH08, &["render", "--out", "{out}", "--builtin", "cornell-box"], "unexpected argument '--builtin'"),
    case(CH08, &["render", "--out", "{out}", "--light-scale", "2"], "unexpected argument '--light-scale'"),
    case(CH08, &["render", "--out", "{out}", "--mis", "sometimes"], "invalid value 'sometimes' for '--mis"),
    case(CH08, &["render", "--out", "{out}", "--no-nee=yes"], "--no-nee"),
    case(CH08, &["render", "--out", "{out}", "--no-nee", "--mis", "balance"], "the argument '--no-nee' cannot be used with '--mis <MIS>'"),
    case(CH08, &["render", "--out", "{out}", "--rr-depth", "0"], "`0` is neither a depth from 1 to 1000 nor `off`"),
    case(CH08, &["render", "--out", "{out}", "--rr-depth", "1001"], "`1001` is neither a depth from 1 to 1000 nor `off`"),
    case(CH08, &["render", "--out", "{out}", "--rr-depth", "2.5"], "`2.5` is neither a depth"),
    case(CH08, &["render", "--out", "{out}", "--rr-depth", "nan"], "`nan` is neither a depth"),
    case(CH08, &["render", "--out", "{out}", "--rr-depth", "-1"], "'-1'"),
    case(CH08, &["render", "--out", "{out}", "--light-samples", "2"], "the path tracer sends one light sample per bounce"),
    case(CH08, &["render", "--out", "{out}", "--glass", "both"], "--glass both: a path follows one ray per bounce"),
    case(CH08, &["render", "--out", "{out}", "--glass", "half"], "only --glass fresnel applies"),
    case(CH08, &["render", "--out", "{out}", "--below-surface", "resample"], "only --below-surface drop applies"),
    case(CH08, &["render", "--out", "{out}", "--below-surface", "reflect"], "only --below-surface drop applies"),
    // Chapter 04's lens (chapter 05 has it too).
    case(WITH_LENS, &["render", "--out", "{out}", "--f-number", "0", "--focal-length", "0.05"], "f-number"),
    case(WITH_LENS, &["render", "--out", "{out}", "--f-number", "-2", "--focal-length", "0.05"], "f-number"),
    case(WITH_LENS, &["render", "--out", "{out}", "--f-number", "2", "--focal-length", "0"], "focal length"),
    case(WITH_LENS, &["render", "--out", "{out}", "--f-number", "2"], "--focal-length"),
    case(WITH_LENS, &["render", "--out", "{out}", "--aperture-radius", "0.1", "--f-number", "2", "--focal-length", "0.05"], "cannot be used with"),
    case(WITH_LENS, &["render", "--out", "{out}", "--aperture-radius", "-1"], "--aperture-radius"),
    case(WITH_LENS, &["render", "--out", "{out}", "--aperture-radius", "nan"], "--aperture-radius"),
    case(WITH_LENS, &["render", "--out", "{out}", "--aperture-radius", "inf"], "--aperture-radius"),
    case(WITH_LENS, &["render", "--out", "{out}", "--focus-distance", "0"], "--focus-distance"),
    case(WITH_LENS, &["render", "--out", "{out}", "--focus-distance", "-3"], "--focus-distance"),
    case(WITH_LENS, &["render", "--out", "{out}", "--focus-distance", "nan"], "--focus-distance"),
    case(WITH_LENS, &["render", "--out", "{out}", "--blades", "2"], "blades"),
    case(WITH_LENS, &["render", "--out", "{out}", "--blades", "65"], "blades"),
    case(WITH_LENS, &["render", "--out", "{out}", "--aperture", "disc", "--blades", "6"], "polygon"),
    case(WITH_LENS, &["render", "--out", "{out}", "--aperture", "polygon", "--lens-warp", "naive"], "--lens-warp"),
    case(WITH_LENS, &["render", "--out", "{out}", "--aperture-rotation", "nan", "--aperture", "polygon"], "rotation"),
];

/// The arguments `chapter` is run with for `case`: the row's, with the chapter's scene after
/// `render` if it needs one and the row names none (see the top of the file).
fn arguments(case: &Case, chapter: &str) -> Vec<&'static str> {
    let mut args = case.args.to_vec();
    if case.with_scene && args.first() == Some(&"render") && !args.contains(&"--scene") {
        args.splice(1..1, scene_args(chapter).iter().copied());
    }
    args
}

/// `args` with the placeholders filled in.
fn fill(args: &[&str], dir: &Path, file: &Path) -> Vec<String> {
    let bad = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/bad");
    let ch04 = Path::new(env!("CARGO_MANIFEST_DIR")).join("../chapters/ch04-depth-of-field/scenes");
    let show = |p: PathBuf| p.to_string_lossy().into_owned();
    args.iter()
        .map(|arg| {
            arg.replace("{out}", &show(dir.join("out.png")))
                .replace("{dir}", &show(dir.to_path_buf()))
                .replace("{file}", &show(file.to_path_buf()))
                .replace("{bad}", &show(bad.clone()))
                .replace("{ch04}", &show(ch04.clone()))
        })
        .collect()
}

/// Runs `chapter` on `case` in a fresh directory; `None` if it was refused properly, else
/// what went wrong.
fn failure(case: &Case, chapter: &str) -> Option<String> {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("a-file");
    std::fs::write(&file, b"in the way").unwrap();
    let args = fill(&arguments(case, chapter), dir.path(), &file);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = run_chapter(chapter, &args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let left = files_in(dir.path());
    let problem = if out.status.success() {
        "exited 0"
    } else if stderr.contains("panicked") {
        "panicked"
    } else if !stderr.contains(case.expected) {
        "gave another message"
    } else if left != ["a-file"] {
        "left files behind"
    } else {
        return None;
    };
    Some(format!(
        "{chapter} {args:?} {problem} (expected `{}`; files {left:?}):\n{stderr}",
        case.expected
    ))
}

/// Tries every chapter of every row of `cases`, four at a time (each run is a short process
/// start, mostly waiting), and fails with the list of the runs that were not refused properly.
fn assert_refused(cases: &[Case]) {
    let runs: Vec<(&Case, &str)> = cases
        .iter()
        .flat_map(|case| case.chapters.iter().map(move |chapter| (case, *chapter)))
        .collect();
    let failures: Vec<String> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..4)
            .map(|k| {
                let runs = &runs;
                scope.spawn(move || {
                    runs.iter()
                        .skip(k)
                        .step_by(4)
                        .filter_map(|(case, chapter)| failure(case, chapter))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().expect("a worker"))
            .collect()
    });
    assert!(
        failures.is_empty(),
        "{} of {} bad inputs were not refused properly:\n{}",
        failures.len(),
        runs.len(),
        failures.join("\n")
    );
}

#[test]
fn every_bad_input_is_refused_clearly_and_writes_nothing() {
    assert_refused(CASES);
}
