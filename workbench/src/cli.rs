//! Command-line pieces every chapter binary shares: the `render` and `figures` options, their
//! checks, and how errors are reported. The render driver ([`crate::driver`]) is what uses the
//! `render` options.
//!
//! Bad input must never panic or leave half a file behind: every option is checked before any
//! work starts, and the output path is tried for writing before a long render, not after it.

use crate::capabilities::Capabilities;
use crate::output::{self, OutputError};
use crate::scene_file::{SceneError, load_scene_file};
use common::film::PixelSum;
use common::render::{Budget, RenderOutput, RenderSettings, StopFlag};
use common::scene::Scene;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::OnceLock;

/// The largest image side we accept.
pub const MAX_IMAGE_SIDE: u32 = 1 << 16;

/// Memory the film and the image may take together.
pub const MAX_IMAGE_BYTES: u64 = 4 << 30;

/// Options of every chapter's `render` subcommand.
///
/// Negative numbers are accepted by the parser of every numeric option so that `--spp -3` is
/// refused by the option's own check, which names the option and its range, rather than
/// read as an unknown flag `-3`.
#[derive(clap::Args, Clone, Debug)]
pub struct RenderArgs {
    /// A scene in Mitsuba 3's XML format (the subset described in the book).
    #[arg(long, value_name = "FILE.xml")]
    pub scene: Option<PathBuf>,
    /// Sets a `<default>` parameter of the scene file, e.g. -D spp=16 (repeatable).
    #[arg(short = 'D', value_name = "NAME=VALUE", requires = "scene", value_parser = parse_define)]
    pub define: Vec<(String, String)>,
    /// Samples per pixel [default: the chapter's choice].
    #[arg(long, allow_negative_numbers = true, conflicts_with = "time",
          value_parser = clap::value_parser!(u64).range(1..=1_000_000_000))]
    pub spp: Option<u64>,
    /// Render for this many seconds instead of a fixed sample count (progressive passes).
    #[arg(long, value_name = "SECONDS", allow_negative_numbers = true, value_parser = parse_seconds)]
    pub time: Option<f64>,
    /// Image width in pixels [default: the scene's].
    #[arg(long, allow_negative_numbers = true, value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_IMAGE_SIDE)))]
    pub width: Option<u32>,
    /// Image height in pixels [default: the scene's].
    #[arg(long, allow_negative_numbers = true, value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_IMAGE_SIDE)))]
    pub height: Option<u32>,
    /// Longest path in segments, counting the camera ray (Mitsuba's max_depth): 1 shows only
    /// what the camera sees of the lights, 2 adds direct light, each step more one more bounce
    /// [default: the scene file's, or the built-in scene's].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub max_depth: Option<u32>,
    /// Seed of every random number of the render.
    #[arg(long, default_value_t = 0, allow_negative_numbers = true)]
    pub seed: u64,
    /// Worker threads [default: one per core]. The image does not depend on it.
    #[arg(long, allow_negative_numbers = true, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,
    /// Output image: .png (sRGB, 8-bit), .exr or .pfm (linear float).
    #[arg(long, value_name = "FILE")]
    pub out: PathBuf,
    /// Also write the render's statistics (time, samples, rays) as JSON.
    #[arg(long, value_name = "FILE.json")]
    pub stats: Option<PathBuf>,
}

/// Options of every chapter's `figures` subcommand.
#[derive(clap::Args, Clone, Debug)]
pub struct FiguresArgs {
    /// Directory the images, plots and CSV files are written to (created if missing).
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    /// Small, fast figures (for tests and CI) instead of the book's full-size ones.
    #[arg(long)]
    pub quick: bool,
}

/// Why a command cannot run.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// The image would not fit in memory.
    #[error(
        "a {width}x{height} image needs {needed_mib} MiB for its film and image; the limit is {} MiB",
        MAX_IMAGE_BYTES >> 20
    )]
    ImageTooLarge {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
        /// Memory it would need.
        needed_mib: u64,
    },
    /// An output could not be written.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// The scene file could not be read.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The scene file was read, but the chapter cannot render what it describes.
    #[error("{}: {message}", file.display())]
    Unrenderable {
        /// The scene file.
        file: PathBuf,
        /// Why, in the chapter's words (which chapter brings the feature, say).
        message: String,
    },
    /// Any other check that failed, with its explanation.
    #[error("{0}")]
    Invalid(String),
    /// The render was stopped (Ctrl-C) before its budget was spent.
    #[error("{}", describe_interrupt(written.as_deref(), *spp, *requested_spp))]
    Interrupted {
        /// The image written with the completed passes, if at least one completed.
        written: Option<PathBuf>,
        /// Samples per pixel the written image holds.
        spp: u64,
        /// Samples per pixel asked for; `None` for a time budget.
        requested_spp: Option<u64>,
    },
}

fn describe_interrupt(written: Option<&Path>, spp: u64, requested_spp: Option<u64>) -> String {
    let of = requested_spp.map_or(String::new(), |n| format!(" of {n}"));
    match written {
        Some(path) => format!(
            "interrupted: wrote {} with {spp}{of} samples per pixel",
            path.display()
        ),
        None => "interrupted before the first pass completed: nothing written".to_string(),
    }
}

/// A scene file read for a chapter's `render`: loaded with the `-D` overrides, the loader's
/// warnings printed, checked against what the chapter renders (a refusal is prefixed with the
/// file's name), and the notes of the check printed: the light the chapter's method leaves
/// out, the settings it ignores, the materials it renders its own way. Materials the chapter
/// renders through a lecture stand-in are replaced by it ([`Capabilities::put_in_stand_ins`]).
pub fn read_scene_file(
    path: &Path,
    defines: &[(String, String)],
    capabilities: &Capabilities,
) -> Result<Scene, CliError> {
    let mut loaded = load_scene_file(path, defines)?;
    for warning in &loaded.warnings {
        eprintln!("{warning}");
    }
    let notes = capabilities
        .check(&loaded.scene)
        .map_err(|message| CliError::Unrenderable {
            file: path.to_path_buf(),
            message,
        })?;
    for note in &notes {
        print_note(note);
    }
    capabilities.put_in_stand_ins(&mut loaded.scene);
    Ok(loaded.scene)
}

/// Any number, including NaN and infinities, for options whose own rule (finite, positive, in
/// a range) is checked where they are used, with the reason there.
pub fn parse_number(text: &str) -> Result<f32, String> {
    text.trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number"))
}

/// Prints a note about a render on standard error: what the method leaves out or changes.
pub fn print_note(note: &str) {
    eprintln!("note: {note}");
}

/// The stop flag of the process's renders, set by Ctrl-C (SIGINT).
///
/// The first call installs the handler; later calls return the same flag. A first Ctrl-C asks
/// the render to stop and write what it has; a second one quits at once, writing nothing (the
/// outputs are written atomically, so no half-written file is left either way).
pub fn ctrl_c_stop_flag() -> StopFlag {
    static FLAG: OnceLock<StopFlag> = OnceLock::new();
    FLAG.get_or_init(|| {
        let flag = StopFlag::new();
        let seen = flag.clone();
        let installed = ctrlc::set_handler(move || {
            if seen.is_requested() {
                eprintln!("\ninterrupted again: quitting without writing");
                std::process::exit(130);
            }
            seen.request();
            eprintln!(
                "\ninterrupted: finishing with the completed passes (Ctrl-C again quits without writing)"
            );
        });
        if let Err(error) = installed {
            // Rendering still works; only Ctrl-C keeps its default meaning (quit at once).
            eprintln!("warning: Ctrl-C will not save a partial render: {error}");
        }
        flag
    })
    .clone()
}

fn parse_define(text: &str) -> Result<(String, String), String> {
    match text.split_once('=') {
        Some((name, value)) if !name.trim().is_empty() => {
            Ok((name.trim().to_string(), value.to_string()))
        }
        _ => Err(format!("`{text}` is not NAME=VALUE")),
    }
}

fn parse_seconds(text: &str) -> Result<f64, String> {
    let seconds: f64 = text
        .parse()
        .map_err(|_| format!("`{text}` is not a number of seconds"))?;
    if seconds.is_finite() && seconds > 0.0 && seconds <= 1e7 {
        Ok(seconds)
    } else {
        Err(format!(
            "the time budget must be a positive number of seconds, at most 1e7; got {text}"
        ))
    }
}

impl RenderArgs {
    /// The render settings, filling what the command line left open with the scene's or
    /// chapter's defaults, and refusing images that cannot fit in memory.
    ///
    /// Only a binary calls this, so it is where Ctrl-C gets its meaning: the settings carry
    /// [`ctrl_c_stop_flag`], and [`RenderArgs::write_outputs`] then saves the completed passes.
    pub(crate) fn settings(
        &self,
        default_size: (u32, u32),
        default_spp: u64,
    ) -> Result<RenderSettings, CliError> {
        let width = self.width.unwrap_or(default_size.0);
        let height = self.height.unwrap_or(default_size.1);
        check_image_size(width, height)?;
        let budget = match (self.spp, self.time) {
            (_, Some(seconds)) => Budget::Seconds(seconds),
            (Some(spp), None) => Budget::Samples(spp),
            (None, None) => Budget::Samples(default_spp),
        };
        Ok(RenderSettings {
            width,
            height,
            budget,
            threads: self.threads.map(|t| t as usize),
            progress: true,
            stop: ctrl_c_stop_flag(),
        })
    }

    /// Checks, before rendering, that the image and the statistics can be written where asked.
    pub(crate) fn check_outputs(&self) -> Result<(), CliError> {
        output::check_image_path(&self.out)?;
        check_writable(&self.out)?;
        if let Some(stats) = &self.stats {
            if stats
                .extension()
                .and_then(|e| e.to_str())
                .map(str::to_ascii_lowercase)
                .as_deref()
                != Some("json")
            {
                return Err(CliError::Invalid(format!(
                    "--stats {}: the statistics file must end in .json",
                    stats.display()
                )));
            }
            check_writable(stats)?;
        }
        Ok(())
    }

    /// Writes the image, and the statistics if asked for, each file whole or not at all.
    /// `extra` adds chapter-specific fields to the statistics object.
    ///
    /// An interrupted render still writes the image of its completed passes (nothing if none
    /// completed) and then returns [`CliError::Interrupted`], so that the binary says what it
    /// wrote and exits non-zero.
    pub(crate) fn write_outputs(
        &self,
        rendered: &RenderOutput,
        extra: serde_json::Value,
    ) -> Result<(), CliError> {
        let stats = &rendered.stats;
        if stats.interrupted && stats.spp == 0 {
            return Err(CliError::Interrupted {
                written: None,
                spp: 0,
                requested_spp: stats.requested_spp,
            });
        }
        output::write_image(&self.out, &rendered.image)?;
        if let Some(path) = &self.stats {
            let mut json = serde_json::to_value(&rendered.stats).expect("statistics serialise");
            if let (Some(map), serde_json::Value::Object(more)) = (json.as_object_mut(), extra) {
                map.extend(more);
            }
            let text = serde_json::to_string_pretty(&json).expect("statistics serialise") + "\n";
            output::write_text(path, &text)?;
        }
        if stats.interrupted {
            return Err(CliError::Interrupted {
                written: Some(self.out.clone()),
                spp: stats.spp,
                requested_spp: stats.requested_spp,
            });
        }
        Ok(())
    }

    /// The scene file to render, if one was given. `-D` sets a parameter of a scene file, so
    /// it is refused without one. (The option's `requires = "scene"` is not enough: clap lets
    /// it through when a chapter's `--builtin`, which conflicts with `--scene`, is given.)
    pub(crate) fn scene_file(&self) -> Result<Option<&Path>, CliError> {
        if self.scene.is_none() && !self.define.is_empty() {
            return Err(CliError::Invalid(
                "-D sets a parameter of a scene file; it needs --scene FILE.xml".to_string(),
            ));
        }
        Ok(self.scene.as_deref())
    }

    /// Tells the user what [`write_outputs`](Self::write_outputs) wrote: the file, its size
    /// and samples, `detail` (what the chapter's options chose, such as ", glass fresnel";
    /// empty for nothing), the time and the ray rate; and warns when samples were not finite
    /// (they are left out of the image, and `--stats` counts them).
    pub(crate) fn report_written(&self, rendered: &RenderOutput, detail: &str) {
        let stats = &rendered.stats;
        eprintln!(
            "wrote {} ({}x{}, {} spp{detail}, {:.2} s, {:.0} rays/s)",
            self.out.display(),
            stats.width,
            stats.height,
            stats.spp,
            stats.seconds,
            stats.rays_per_second
        );
        if stats.nonfinite_samples > 0 {
            eprintln!(
                "warning: {} samples were not finite and were left out",
                stats.nonfinite_samples
            );
        }
    }
}

/// Refuses image sizes whose film would not fit in [`MAX_IMAGE_BYTES`].
pub fn check_image_size(width: u32, height: u32) -> Result<(), CliError> {
    let pixels = u64::from(width) * u64::from(height);
    let bytes_per_pixel =
        (std::mem::size_of::<PixelSum>() + 2 * std::mem::size_of::<glam::Vec3>()) as u64;
    let needed = pixels * bytes_per_pixel;
    if width == 0 || height == 0 {
        return Err(CliError::Invalid(format!(
            "an image of {width}x{height} pixels has no pixels"
        )));
    }
    if needed > MAX_IMAGE_BYTES {
        return Err(CliError::ImageTooLarge {
            width,
            height,
            needed_mib: needed.div_ceil(1 << 20),
        });
    }
    Ok(())
}

/// Creates the directory of `path` if needed and proves that a file can be created there,
/// so that a render fails in its first millisecond rather than after an hour.
pub fn check_writable(path: &Path) -> Result<(), CliError> {
    // `out.png/` has the parent and the extension of `out.png`, but no file can have its name.
    let text = path.as_os_str().to_string_lossy();
    if text.ends_with('/') || text.ends_with(std::path::MAIN_SEPARATOR) {
        return Err(CliError::Invalid(format!(
            "{} ends in a path separator: it names a directory, not a file",
            path.display()
        )));
    }
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    std::fs::create_dir_all(dir).map_err(|e| {
        CliError::Invalid(format!(
            "cannot create the directory {} for {}: {e}",
            dir.display(),
            path.display()
        ))
    })?;
    if path.is_dir() {
        return Err(CliError::Invalid(format!(
            "{} is a directory, not a file name",
            path.display()
        )));
    }
    tempfile::NamedTempFile::new_in(dir)
        .map_err(|e| CliError::Invalid(format!("cannot write to {}: {e}", dir.display())))?;
    Ok(())
}

/// Creates the output directory of `figures`, with a clear error if it cannot.
pub fn prepare_output_dir(dir: &Path) -> Result<(), CliError> {
    std::fs::create_dir_all(dir).map_err(|e| {
        CliError::Invalid(format!(
            "cannot create the output directory {}: {e}",
            dir.display()
        ))
    })?;
    tempfile::NamedTempFile::new_in(dir)
        .map_err(|e| CliError::Invalid(format!("cannot write to {}: {e}", dir.display())))?;
    Ok(())
}

/// Prints an error and the chain of its causes, the way every chapter binary reports
/// failure, and gives the exit code to return from `main`.
pub fn report_error(error: &(dyn std::error::Error + 'static)) -> ExitCode {
    eprintln!("error: {error}");
    let mut source = error.source();
    while let Some(cause) = source {
        eprintln!("  caused by: {cause}");
        source = cause.source();
    }
    ExitCode::FAILURE
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn huge_images_are_refused_with_the_memory_they_need() {
        let err = check_image_size(60_000, 60_000).unwrap_err().to_string();
        assert!(err.contains("60000x60000") && err.contains("MiB"), "{err}");
        assert!(check_image_size(1920, 1080).is_ok());
        assert!(check_image_size(0, 5).is_err());
    }

    #[test]
    fn interrupts_say_what_was_written() {
        let message = CliError::Interrupted {
            written: Some(PathBuf::from("out.png")),
            spp: 64,
            requested_spp: Some(1024),
        }
        .to_string();
        assert_eq!(
            message,
            "interrupted: wrote out.png with 64 of 1024 samples per pixel"
        );
        let timed = CliError::Interrupted {
            written: None,
            spp: 0,
            requested_spp: None,
        }
        .to_string();
        assert!(timed.contains("nothing written"), "{timed}");
    }

    #[test]
    fn defines_are_name_value_pairs() {
        assert_eq!(
            parse_define("spp=16"),
            Ok(("spp".to_string(), "16".to_string()))
        );
        assert_eq!(
            parse_define("name=a=b"),
            Ok(("name".to_string(), "a=b".to_string()))
        );
        assert!(parse_define("spp").is_err());
        assert!(parse_define("=3").is_err());
    }

    #[test]
    fn time_budgets_must_be_positive_and_finite() {
        for bad in ["0", "-1", "nan", "inf", "abc", "1e300"] {
            assert!(parse_seconds(bad).is_err(), "{bad}");
        }
        assert_eq!(parse_seconds("2.5"), Ok(2.5));
    }

    #[test]
    fn an_existing_directory_is_not_an_output_file() {
        let dir = tempfile::tempdir().unwrap();
        assert!(check_writable(dir.path()).is_err());
        assert!(check_writable(&dir.path().join("new/sub/img.png")).is_ok());
        let trailing = format!("{}/img.png/", dir.path().display());
        assert!(check_writable(Path::new(&trailing)).is_err());
    }
}

/// The [`ChapterBinary`] of the package it is written in: the package's name and description
/// (from its `Cargo.toml`), and what its `render` renders.
#[macro_export]
macro_rules! chapter_binary {
    ($render:expr) => {
        $crate::cli::ChapterBinary {
            name: env!("CARGO_PKG_NAME"),
            about: env!("CARGO_PKG_DESCRIPTION"),
            render: $render,
        }
    };
}

/// What a chapter binary's `--help` says: its name, what it is, and what its two commands do.
#[derive(Clone, Copy, Debug)]
pub struct ChapterBinary {
    /// The binary's (and package's) name, such as `ch07-soft-shadows`.
    pub name: &'static str,
    /// One line on the chapter (its package description).
    pub about: &'static str,
    /// What `render` renders.
    pub render: &'static str,
}

/// The command line of a chapter binary: `render` with the chapter's own options `R`, and
/// `figures`.
#[derive(clap::Parser, Debug)]
#[command(version)]
struct ChapterCli<R: clap::Args> {
    #[command(subcommand)]
    command: ChapterCommand<R>,
}

#[derive(clap::Subcommand, Debug)]
enum ChapterCommand<R: clap::Args> {
    /// Render an image.
    Render(Box<R>),
    /// Write the chapter's comparison images, plots, tables and error-against-time data.
    Figures(FiguresArgs),
}

impl ChapterBinary {
    /// The whole of a chapter binary's `main`: parses the command line (clap prints help and
    /// refuses bad flags), runs `render` with the chapter's options or `figures` with the
    /// output directory and the quick flag, and prints an error with its chain of causes,
    /// exiting non-zero.
    pub fn run<R: clap::Args + std::fmt::Debug>(
        &self,
        render: impl FnOnce(R) -> anyhow::Result<()>,
        figures: impl FnOnce(&Path, bool) -> anyhow::Result<()>,
    ) -> ExitCode {
        use clap::{CommandFactory, FromArgMatches};
        let command = ChapterCli::<R>::command()
            .name(self.name)
            .about(self.about)
            .mut_subcommand("render", |render| render.about(self.render));
        let cli = ChapterCli::<R>::from_arg_matches(&command.get_matches())
            .unwrap_or_else(|error| error.exit());
        let result = match cli.command {
            ChapterCommand::Render(options) => render(*options),
            ChapterCommand::Figures(args) => figures(&args.out, args.quick),
        };
        match result {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => report_error(error.as_ref()),
        }
    }
}
