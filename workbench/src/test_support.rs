//! Helpers for the chapters' own tests: running a chapter's binary on bad input, the pictures
//! of a failing check, the written diagrams, and the text summary of a tiny render that
//! snapshot tests store.
//!
//! Nothing here is used by a renderer; it lives in the workbench so that every chapter's tests
//! ask the same questions in the same way.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use common::image::Image;
use glam::Vec2;

pub mod mesh_files;

/// Runs `binary` (a path such as `env!("CARGO_BIN_EXE_ch01-whitted")`) with `args`.
pub fn run_binary(binary: &str, args: &[&str]) -> Output {
    Command::new(binary)
        .args(args)
        .output()
        .unwrap_or_else(|e| panic!("cannot run {binary}: {e}"))
}

/// Asserts that `binary` refuses `args`: it exits non-zero, does not panic, and its error
/// message contains `expected`.
pub fn assert_refused(binary: &str, args: &[&str], expected: &str) {
    let out = run_binary(binary, args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{args:?} succeeded");
    assert!(!stderr.contains("panicked"), "{args:?} panicked: {stderr}");
    assert!(
        stderr.contains(expected),
        "{args:?}: expected `{expected}` in: {stderr}"
    );
}

/// Runs `f` and returns what it gives, or the message of its panic: a check that calls the
/// student's code on an edge case (no values, `n = 0`, a light on the point) then says in words
/// what that case needs, instead of failing with the panic of an index or an `unwrap`.
///
/// A stub reached on the way ("this check needs NAME (not written yet)") is passed on, not
/// caught: there is no edge case to explain, only an exercise to write.
pub fn catch_panic<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).map_err(|payload| {
        let payload = common::exercise::resume_if_not_written(payload);
        payload
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_else(|| "a panic without a message".to_string())
    })
}

/// Where a failing exercise check writes its pictures:
/// `target/exercises/<exercise>/<test>/` of the build the test runs from (found from the test
/// binary's own place, `target/<profile>/deps/`), created if missing.
///
/// `<test>` is the name of the test that calls it ([`test_name`]), so that two failing tests of
/// one exercise do not overwrite each other's pictures.
pub fn exercise_output_dir(exercise: &str) -> PathBuf {
    let exe = std::env::current_exe().unwrap_or_default();
    let target = exe
        .ancestors()
        .find(|dir| dir.file_name().is_some_and(|name| name == "target"))
        .map(PathBuf::from)
        .or_else(|| exe.ancestors().nth(3).map(PathBuf::from))
        .unwrap_or_else(|| PathBuf::from("target"));
    let dir = target.join("exercises").join(exercise).join(test_name());
    // A check that cannot write its picture still reports its finding in words.
    let _ = std::fs::create_dir_all(&dir);
    dir
}

/// The name of the running test, from the name of its thread: libtest names each test's thread
/// after the test's path (`tracer::tests::exercise_trace_renders`), and this is its last part
/// (`exercise_trace_renders`). A test that runs its check on a thread of its own gives that
/// thread its own name. Outside a named thread (a test run on the main thread), `test`.
pub fn test_name() -> String {
    let thread = std::thread::current();
    match thread.name() {
        Some(name) if name != "main" && !name.is_empty() => {
            let last = name.rsplit("::").next().unwrap_or(name);
            // Only what a folder's name may hold on every system.
            last.chars()
                .map(|c| {
                    if c.is_ascii_alphanumeric() || c == '_' || c == '-' {
                        c
                    } else {
                        '_'
                    }
                })
                .collect()
        }
        _ => "test".to_string(),
    }
}

/// The failure message of a warp that is not uniform over its shape, after drawing the
/// picture that shows where: a histogram of `points` (the student's warp of a regular grid)
/// against the uniform `density` over `domain`, written under
/// `target/exercises/<exercise>/<test>/` ([`exercise_output_dir`]).
pub fn not_uniform(
    exercise: &str,
    function: &str,
    shape: &str,
    p_value: f64,
    points: &[glam::Vec2],
    density: &dyn Fn(glam::Vec2) -> f64,
    domain: [glam::Vec2; 2],
) -> String {
    let path = exercise_output_dir(exercise).join("histogram.png");
    // Short enough to fit above the two panels.
    let title = format!("your {function}");
    let picture = match crate::output::figures::histogram_vs_pdf(
        &path, &title, points, density, domain, 32,
    ) {
        Ok(()) => format!(
            "see {} (your points against the uniform density)",
            path.display()
        ),
        Err(error) => format!("(the picture could not be written: {error})"),
    };
    format!(
        "{function}: the points are not uniform over the {shape} (chi-square test, p = \
         {p_value:.2e}): some regions get more than their share of the area; {picture}"
    )
}

/// Writes the pictures a failing image check shows the student: `mine.png`, `expected.png` and
/// `difference.png` (the absolute difference, scaled so that its largest channel is white)
/// under `target/exercises/<exercise>/<test>/` ([`exercise_output_dir`]), and returns the
/// sentence that points at them.
///
/// A check renders tiny pictures, to be quick; each is enlarged by a whole factor, every pixel
/// a square block ([`enlarged`]), so that the long side has at least [`PICTURE_SIZE`] pixels
/// and the student sees each pixel crisp.
///
/// A check calls it only once it has found, in words, what is wrong; the pictures show where.
pub fn image_comparison(exercise: &str, mine: &Image, expected: &Image) -> String {
    let dir = exercise_output_dir(exercise);
    let difference = difference_image(mine, expected);
    let written = [
        ("mine.png", mine),
        ("expected.png", expected),
        ("difference.png", &difference),
    ]
    .into_iter()
    .try_for_each(|(name, image)| {
        crate::output::write_image(&dir.join(name), &enlarged(image, PICTURE_SIZE))
    });
    match written {
        Ok(()) => format!(
            "see {} (mine.png, expected.png and difference.png, brightest where they differ most)",
            dir.display()
        ),
        Err(error) => format!("(the pictures could not be written: {error})"),
    }
}

/// The fewest pixels on the long side of a picture a failing check writes.
pub const PICTURE_SIZE: u32 = 256;

/// `image` enlarged by the smallest whole factor that gives its long side at least `size`
/// pixels, each pixel copied into a square block (nearest neighbour, so edges stay sharp); as
/// it is when it is that large already.
pub fn enlarged(image: &Image, size: u32) -> Image {
    let long_side = image.width.max(image.height).max(1);
    let factor = size.div_ceil(long_side).max(1);
    if factor == 1 {
        return image.clone();
    }
    let mut large = Image::new(image.width * factor, image.height * factor);
    for y in 0..large.height {
        for x in 0..large.width {
            large.set(x, y, image.get(x / factor, y / factor));
        }
    }
    large
}

/// `|mine - expected|` per channel, divided by its largest value so the worst pixel is white;
/// pixels outside the smaller image, and non-finite values, are drawn red.
fn difference_image(mine: &Image, expected: &Image) -> Image {
    let width = mine.width.max(expected.width);
    let height = mine.height.max(expected.height);
    let mut difference = Image::new(width, height);
    let red = glam::Vec3::new(1.0, 0.0, 0.0);
    let inside = |image: &Image, x: u32, y: u32| x < image.width && y < image.height;
    let mut largest = 0.0f32;
    for y in 0..height {
        for x in 0..width {
            let value = if inside(mine, x, y) && inside(expected, x, y) {
                (mine.get(x, y) - expected.get(x, y)).abs()
            } else {
                glam::Vec3::NAN
            };
            if value.is_finite() {
                largest = largest.max(value.max_element());
            }
            difference.set(x, y, value);
        }
    }
    let scale = if largest > 0.0 { 1.0 / largest } else { 1.0 };
    for pixel in &mut difference.pixels {
        *pixel = if pixel.is_finite() {
            *pixel * scale
        } else {
            red
        };
    }
    difference
}

/// Compares a snapshot with the stored one, allowing what floating-point error may change, and
/// falls back to `insta` (its diff, its `.snap.new` for review) when they differ by more.
///
/// A student's correct answer to an exercise may differ from the reference in its last bits;
/// the snapshots of later code must not fail for that, or they would test the spelling of an
/// answer rather than its meaning. See [`snapshot_close_enough`] for what counts as close.
#[macro_export]
macro_rules! assert_close_snapshot {
    ($name:literal, $value:expr) => {{
        let value: String = $value;
        let stored = $crate::test_support::stored_snapshot(
            env!("CARGO_MANIFEST_DIR"),
            module_path!(),
            $name,
        );
        if !stored
            .as_deref()
            .is_some_and(|stored| $crate::test_support::snapshot_close_enough(stored, &value))
        {
            insta::assert_snapshot!($name, value);
        }
    }};
}

/// The body of the snapshot `name` that `insta` stored for the integration test `module`
/// (`tests/snapshots/<module>__<name>.snap` of the package at `manifest_dir`), if there is one.
pub fn stored_snapshot(manifest_dir: &str, module: &str, name: &str) -> Option<String> {
    let file = format!("{}__{name}.snap", module.replace("::", "__"));
    let path = std::path::Path::new(manifest_dir)
        .join("tests")
        .join("snapshots")
        .join(file);
    let text = std::fs::read_to_string(path).ok()?;
    // A header between two `---` lines, then the body.
    let mut lines = text.lines();
    (lines.next()? == "---").then_some(())?;
    lines.by_ref().find(|line| *line == "---")?;
    Some(lines.collect::<Vec<_>>().join("\n"))
}

/// Whether the snapshot text `actual` matches `stored` up to floating-point noise:
/// - the same lines, and in each line the same words;
/// - numbers within 1e-3 of their size or three units of the last digit printed, whichever is
///   larger (a path that ends one bounce sooner changes a ray count or a mean a little);
/// - luminance pictures ([`image_summary`]) where a character may be one level off, in at most
///   2 % of the pixels (a pixel near a level's edge).
pub fn snapshot_close_enough(stored: &str, actual: &str) -> bool {
    let stored: Vec<&str> = stored.trim_end().lines().map(str::trim_end).collect();
    let actual: Vec<&str> = actual.trim_end().lines().map(str::trim_end).collect();
    if stored.len() != actual.len() {
        return false;
    }
    let (mut picture_chars, mut picture_flips) = (0usize, 0usize);
    for (want, got) in stored.iter().zip(&actual) {
        if want == got {
            picture_chars += want.len();
            continue;
        }
        if is_picture_row(want) && is_picture_row(got) && want.len() == got.len() {
            for (a, b) in want.bytes().zip(got.bytes()) {
                picture_chars += 1;
                let level = |c: u8| RAMP.iter().position(|&r| r == c).unwrap_or(0) as i64;
                match (level(a) - level(b)).abs() {
                    0 => {}
                    1 => picture_flips += 1,
                    _ => return false,
                }
            }
            continue;
        }
        if !words_close(want, got) {
            return false;
        }
    }
    picture_flips * 50 <= picture_chars.max(50)
}

/// A row of an [`image_summary`] picture: ramp characters only.
fn is_picture_row(line: &str) -> bool {
    !line.is_empty() && line.bytes().all(|c| RAMP.contains(&c))
}

/// The same words, numbers within their tolerance.
fn words_close(want: &str, got: &str) -> bool {
    let split = |line| -> Vec<&str> {
        let words = str::split(line, |c: char| c.is_whitespace() || c == ',');
        words.filter(|word| !word.is_empty()).collect()
    };
    let (want, got) = (split(want), split(got));
    want.len() == got.len()
        && want.iter().zip(&got).all(|(a, b)| {
            a == b
                || match (a.parse::<f64>(), b.parse::<f64>()) {
                    (Ok(x), Ok(y)) => {
                        let decimals = match a.split_once('.') {
                            Some((_, fraction)) if !a.contains(['e', 'E']) => fraction.len(),
                            _ => 0,
                        };
                        let unit = 10f64.powi(-(decimals as i32));
                        let unit = if a.contains(['e', 'E']) { 0.0 } else { unit };
                        (x - y).abs() <= (1e-3 * x.abs().max(y.abs())).max(3.0 * unit)
                    }
                    _ => false,
                }
        })
}

/// Characters from dark to bright, for [`image_summary`].
const RAMP: &[u8] = b" .:-=+*#%@";

/// The text a snapshot test stores for a tiny render: a picture of its luminance in 10 levels
/// (which catches moved or missing geometry, shadows, reflections), its mean colour to four
/// decimals and its ray count (which catch changes of shading and recursion).
///
/// The levels are of the sRGB-like value `L^(1/2.2)`, rounded, so that tiny floating-point
/// changes flip a character only where they cross a level.
pub fn image_summary(image: &Image, rays: u64) -> String {
    let mut text = String::new();
    for y in 0..image.height {
        for x in 0..image.width {
            let p = image.get(x, y);
            let luminance = 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
            let level = (luminance.clamp(0.0, 1.0).powf(1.0 / 2.2) * (RAMP.len() - 1) as f32)
                .round() as usize;
            text.push(RAMP[level] as char);
        }
        text.push('\n');
    }
    let n = image.pixels.len() as f64;
    let mean = image.pixels.iter().fold([0.0f64; 3], |acc, p| {
        [
            acc[0] + f64::from(p.x) / n,
            acc[1] + f64::from(p.y) / n,
            acc[2] + f64::from(p.z) / n,
        ]
    });
    text.push_str(&format!(
        "mean rgb: {:.4} {:.4} {:.4}\nrays: {rays}\n",
        mean[0], mean[1], mean[2]
    ));
    text
}

/// Runs `binary`'s `render` on the scene file `scene` at 16 x 12 pixels and 2 samples per
/// pixel on one thread, writing its image and statistics into the folder `out`; `Err` with
/// the message if it refuses the file. A panic or a non-finite sample fails the test.
pub fn render_tiny(binary: &str, scene: &Path, out: &Path) -> Result<Image, String> {
    let image = out.join("image.pfm");
    let stats = out.join("stats.json");
    let output = run_binary(
        binary,
        &[
            "render",
            "--scene",
            scene.to_str().unwrap(),
            "--width",
            "16",
            "--height",
            "12",
            "--spp",
            "2",
            "--threads",
            "1",
            "--out",
            image.to_str().unwrap(),
            "--stats",
            stats.to_str().unwrap(),
        ],
    );
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert!(
        !stderr.contains("panicked"),
        "{}: {stderr}",
        scene.display()
    );
    if !output.status.success() {
        return Err(stderr);
    }
    let stats: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    assert_eq!(
        stats["nonfinite_samples"],
        0,
        "{}: {stderr}",
        scene.display()
    );
    Ok(crate::output::read_image(&image).unwrap())
}

/// The image `binary`'s `render` makes of the scene file `text` (written to a temporary
/// folder), at the file's own size and sample count. A refusal fails the test with its
/// message.
pub fn render_text(binary: &str, text: &str) -> Image {
    let folder = tempfile::tempdir().unwrap();
    let file = folder.path().join("scene.xml");
    std::fs::write(&file, text).unwrap();
    let image = folder.path().join("image.pfm");
    let output = run_binary(
        binary,
        &[
            "render",
            "--scene",
            file.to_str().unwrap(),
            "--out",
            image.to_str().unwrap(),
        ],
    );
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    crate::output::read_image(&image).unwrap()
}

/// A `k x k` grid of film positions over a `width x height` image, each a pixel's centre.
pub fn pixel_centre_grid(width: u32, height: u32, k: u32) -> Vec<Vec2> {
    let mut points = Vec::new();
    for j in 0..k {
        for i in 0..k {
            points.push(Vec2::new(
                ((i * width / k) as f32 + 0.5).min(width as f32 - 0.5),
                ((j * height / k) as f32 + 0.5).min(height as f32 - 0.5),
            ));
        }
    }
    points
}

/// Writes a chapter's diagrams with `write_all` into a fresh folder and gives the description
/// of each of `files` (the `<title>` a screen reader reads, which the page's alt text says
/// again), after checking that each is an SVG document with a description that is not empty.
/// With `DIAGRAMS_OUT` set to a folder, the diagrams are written there too, to look at.
pub fn written_diagrams(
    write_all: impl Fn(&Path) -> anyhow::Result<()>,
    files: &[&str],
) -> Vec<String> {
    let dir = tempfile::tempdir().expect("a temporary folder");
    write_all(dir.path()).expect("the diagrams are written");
    let descriptions = files
        .iter()
        .map(|file| {
            let path = dir.path().join(file);
            let svg = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("{file} was not written: {e}"));
            let document = roxmltree::Document::parse(&svg)
                .unwrap_or_else(|e| panic!("{file} is not well-formed XML: {e}"));
            assert_eq!(document.root_element().tag_name().name(), "svg", "{file}");
            let title = document
                .descendants()
                .find(|node| node.has_tag_name("title"))
                .and_then(|node| node.text())
                .unwrap_or_default();
            assert!(!title.trim().is_empty(), "{file} has no description");
            title.to_owned()
        })
        .collect();
    if let Some(out) = std::env::var_os("DIAGRAMS_OUT") {
        write_all(Path::new(&out)).expect("the diagrams are written to DIAGRAMS_OUT");
    }
    descriptions
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn the_summary_draws_luminance_and_states_the_mean() {
        let mut image = Image::new(3, 1);
        image.set(1, 0, Vec3::splat(0.25));
        image.set(2, 0, Vec3::ONE);
        let text = image_summary(&image, 7);
        // 0.25^(1/2.2) * 9 = 4.8 rounds to level 5, '+'.
        assert_eq!(text, " +@\nmean rgb: 0.4167 0.4167 0.4167\nrays: 7\n");
    }

    #[test]
    fn the_difference_is_scaled_to_its_largest_value_and_marks_missing_pixels_red() {
        let mine = Image::filled(2, 1, Vec3::new(0.5, 0.5, 0.5));
        let mut expected = Image::filled(3, 1, Vec3::new(0.5, 0.5, 0.5));
        expected.set(1, 0, Vec3::new(0.25, 0.5, 0.0));
        let difference = difference_image(&mine, &expected);
        assert_eq!(difference.get(0, 0), Vec3::ZERO);
        assert_eq!(difference.get(1, 0), Vec3::new(0.5, 0.0, 1.0));
        assert_eq!(difference.get(2, 0), Vec3::new(1.0, 0.0, 0.0));
    }

    #[test]
    fn a_panic_becomes_its_message() {
        assert_eq!(catch_panic(|| 3), Ok(3));
        let empty: Vec<f64> = Vec::new();
        let message = catch_panic(|| empty[0]).unwrap_err();
        assert!(message.contains("index out of bounds"), "{message}");
        assert_eq!(
            catch_panic(|| -> () { panic!("no {}", "values") }),
            Err("no values".to_string())
        );
    }

    #[test]
    fn small_pictures_are_enlarged_by_a_whole_factor_with_square_pixels() {
        let mut image = Image::new(24, 18);
        image.set(3, 2, Vec3::ONE);
        let large = enlarged(&image, PICTURE_SIZE);
        // 256 / 24 rounds up to 11: 264 x 198.
        assert_eq!((large.width, large.height), (264, 198));
        for y in 0..large.height {
            for x in 0..large.width {
                let inside = (33..44).contains(&x) && (22..33).contains(&y);
                assert_eq!(large.get(x, y), Vec3::splat(f32::from(u8::from(inside))));
            }
        }
        // Large enough already: kept as it is.
        let big = Image::new(300, 10);
        assert_eq!(enlarged(&big, PICTURE_SIZE), big);
    }

    #[test]
    fn each_test_writes_its_pictures_into_its_own_folder() {
        // libtest runs this on a thread named after the test's path.
        let dir = exercise_output_dir("test-support-example");
        assert_eq!(
            dir.file_name().and_then(|name| name.to_str()),
            Some("each_test_writes_its_pictures_into_its_own_folder")
        );
        assert!(dir.ends_with(
            "exercises/test-support-example/each_test_writes_its_pictures_into_its_own_folder"
        ));
        assert!(dir.is_dir());
        // A thread of a check's own carries the name it is given.
        let named = std::thread::Builder::new()
            .name("chapter::tests::exercise_other".to_string())
            .spawn(test_name)
            .unwrap()
            .join()
            .unwrap();
        assert_eq!(named, "exercise_other");
        let _ = std::fs::remove_dir_all(dir.parent().unwrap());
    }

    #[test]
    fn snapshots_allow_float_noise_but_not_a_change() {
        let stored =
            "..::\n.:-=\nmean rgb: 0.2995 0.2886 0.2481\nrays: 27954\nx,y\n0.20176762,0.4911644";
        // One pixel one level off, the means a unit off, a few rays more, a float step.
        let noisy =
            "..::\n.:--\nmean rgb: 0.2996 0.2886 0.2480\nrays: 27960\nx,y\n0.20176764,0.4911644";
        assert!(snapshot_close_enough(stored, noisy));
        for changed in [
            "..::\n.:-@\nmean rgb: 0.2995 0.2886 0.2481\nrays: 27954\nx,y\n0.20176762,0.4911644",
            "..::\n.:-=\nmean rgb: 0.3095 0.2886 0.2481\nrays: 27954\nx,y\n0.20176762,0.4911644",
            "..::\n.:-=\nmean rgb: 0.2995 0.2886 0.2481\nrays: 29954\nx,y\n0.20176762,0.4911644",
            "..::\n.:-=\nmean rgb: 0.2995 0.2886 0.2481\nrays: 27954\nx,y\n0.2027,0.4911644",
            "..::\n.:-=\nmean rgb: 0.2995 0.2886 0.2481\nrays: 27954\nx,z\n0.20176762,0.4911644",
            "..::\n.:-=\nmean rgb: 0.2995 0.2886 0.2481\nrays: 27954",
        ] {
            assert!(!snapshot_close_enough(stored, changed), "{changed}");
        }
        // Many pixels a level off is a change, not noise.
        assert!(!snapshot_close_enough("....\n....", "::::\n::::"));
    }
}
