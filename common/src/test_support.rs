//! Helpers for the chapters' own tests: running a chapter's binary on bad input, and the text
//! summary of a tiny render that snapshot tests store.
//!
//! Nothing here is used by a renderer; it lives in `common` so that every chapter's tests ask
//! the same questions in the same way.

use std::path::PathBuf;
use std::process::{Command, Output};

use crate::image::Image;

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

/// Where a failing exercise check writes its pictures: `target/exercises/<exercise>/` of the
/// build the test runs from (found from the test binary's own place,
/// `target/<profile>/deps/`), created if missing.
pub fn exercise_output_dir(exercise: &str) -> PathBuf {
    let exe = std::env::current_exe().unwrap_or_default();
    let target = exe
        .ancestors()
        .find(|dir| dir.file_name().is_some_and(|name| name == "target"))
        .map(PathBuf::from)
        .or_else(|| exe.ancestors().nth(3).map(PathBuf::from))
        .unwrap_or_else(|| PathBuf::from("target"));
    let dir = target.join("exercises").join(exercise);
    // A check that cannot write its picture still reports its finding in words.
    let _ = std::fs::create_dir_all(&dir);
    dir
}

/// The failure message of a warp that is not uniform over its shape, after drawing the
/// picture that shows where: a histogram of `points` (the student's warp of a regular grid)
/// against the uniform `density` over `domain`, written under `target/exercises/<exercise>/`.
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
/// under `target/exercises/<exercise>/`, and returns the sentence that points at them.
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
    .try_for_each(|(name, image)| crate::output::write_image(&dir.join(name), image));
    match written {
        Ok(()) => format!(
            "see {} (mine.png, expected.png and difference.png, brightest where they differ most)",
            dir.display()
        ),
        Err(error) => format!("(the pictures could not be written: {error})"),
    }
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
}
