//! What every chapter's `figures` command shares, so that a chapter's `figures.rs` reads as
//! the list of its experiments: the two quality levels, the output folder, the time each
//! figure took, and the comparison with Mitsuba 3.
//!
//! A chapter's `write_all` starts a [`FigureSet`], picks its sizes and budgets for the
//! [`Level`], and makes each figure with [`FigureSet::make`]: the figure's failure is reported
//! with its name, and its time is kept. [`FigureSet::finish`] writes those times to
//! `figure-times.csv` beside the figures, so that what a figure costs is on record.

use crate::cli::prepare_output_dir;
use crate::metrics::AgreementSet;
use crate::output::write_text;
use crate::render::RenderSettings;
use anyhow::Context;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The file beside a chapter's figures with each figure's name and seconds.
pub const TIMES_FILE: &str = "figure-times.csv";

/// The times [`FigureSet::finish`] wrote into `dir`: each figure's name and seconds, in the
/// order they were made. A line that is not `figure,seconds` is named by file and line.
pub fn read_times(dir: &Path) -> anyhow::Result<Vec<(String, f64)>> {
    let path = dir.join(TIMES_FILE);
    let csv = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    csv.lines()
        .enumerate()
        .skip(1)
        .map(|(number, line)| {
            line.rsplit_once(',')
                .and_then(|(figure, seconds)| Some((figure.to_string(), seconds.parse().ok()?)))
                .with_context(|| format!("{}:{}: not `figure,seconds`", path.display(), number + 1))
        })
        .collect()
}

/// How much work the figures get.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    /// Small, fast figures, for tests, CI and checking a page's layout.
    Quick,
    /// The book's figures.
    Book,
}

impl Level {
    /// The level of `figures --quick` (or without it).
    pub fn of(quick: bool) -> Self {
        if quick { Level::Quick } else { Level::Book }
    }

    /// `quick` at the quick level, `book` at the book's.
    pub fn pick<T>(self, quick: T, book: T) -> T {
        match self {
            Level::Quick => quick,
            Level::Book => book,
        }
    }

    /// Whether these are the quick figures.
    pub fn is_quick(self) -> bool {
        self == Level::Quick
    }
}

/// The size and sample counts of a chapter's rendered figures at one level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderQuality {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Samples per pixel of the gallery images.
    pub spp: u64,
    /// Sample counts of the error-against-time runs.
    pub budgets: &'static [u64],
    /// Samples per pixel of the converged reference they are measured against.
    pub reference_spp: u64,
}

impl RenderQuality {
    /// Settings for a render of this size at `spp` samples per pixel, with a progress bar.
    pub fn settings(&self, spp: u64) -> RenderSettings {
        RenderSettings {
            progress: true,
            ..RenderSettings::new(self.width, self.height, spp)
        }
    }

    /// Settings for a gallery image: [`spp`](Self::spp) samples per pixel.
    pub fn gallery(&self) -> RenderSettings {
        self.settings(self.spp)
    }
}

/// The figures of one chapter while they are being written.
#[derive(Debug)]
pub struct FigureSet {
    chapter: &'static str,
    out: PathBuf,
    level: Level,
    started: Instant,
    times: Vec<(&'static str, f64)>,
}

impl FigureSet {
    /// Starts the figures of `chapter` (`"ch05"`) in `out`, creating it; fails at once, with
    /// the folder's name, if it cannot be written.
    pub fn start(chapter: &'static str, out: &Path, quick: bool) -> anyhow::Result<Self> {
        prepare_output_dir(out)?;
        Ok(Self {
            chapter,
            out: out.to_path_buf(),
            level: Level::of(quick),
            started: Instant::now(),
            times: Vec::new(),
        })
    }

    /// The level the figures are made at.
    pub fn level(&self) -> Level {
        self.level
    }

    /// The folder the figures are written to.
    pub fn out(&self) -> &Path {
        &self.out
    }

    /// Makes one figure: runs `figure` with the output folder, keeps how long it took, and
    /// names the figure (`what`, e.g. "the shutter series") in its error.
    pub fn make(
        &mut self,
        what: &'static str,
        figure: impl FnOnce(&Path) -> anyhow::Result<()>,
    ) -> anyhow::Result<()> {
        let started = Instant::now();
        figure(&self.out).with_context(|| format!("{} figures: {what}", self.chapter))?;
        self.times.push((what, started.elapsed().as_secs_f64()));
        Ok(())
    }

    /// Makes the comparison with Mitsuba 3: ours next to Mitsuba's stored renders of the
    /// chapter's agreement scenes, with the table of their numbers. The renders are at the
    /// files' own sizes at every level: they are compared with stored renders.
    pub fn agreement(&mut self, set: &AgreementSet) -> anyhow::Result<()> {
        self.make("the comparison with Mitsuba 3", |out| {
            set.write_figures(out).map_err(anyhow::Error::msg)
        })
    }

    /// Writes `figure-times.csv` (each figure's name and seconds) and says where the figures
    /// are and how long they took.
    pub fn finish(self) -> anyhow::Result<()> {
        let mut csv = String::from("figure,seconds\n");
        for (what, seconds) in &self.times {
            csv.push_str(&format!("{},{seconds:.3}\n", what.replace(',', ";")));
        }
        write_text(&self.out.join(TIMES_FILE), &csv)?;
        eprintln!(
            "{} figures written to {} in {:.1} s",
            self.chapter,
            self.out.display(),
            self.started.elapsed().as_secs_f64()
        );
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_level_picks_its_own_value() {
        assert_eq!(Level::of(true).pick(1, 2), 1);
        assert_eq!(Level::of(false).pick(1, 2), 2);
        assert!(Level::Quick.is_quick() && !Level::Book.is_quick());
    }

    #[test]
    fn the_times_of_the_figures_are_written_and_a_failure_is_named() {
        let dir = tempfile::tempdir().unwrap();
        let mut figures = FigureSet::start("ch00", dir.path(), true).unwrap();
        figures
            .make("a plot, with a comma", |out| {
                write_text(&out.join("plot.txt"), "drawn")?;
                Ok(())
            })
            .unwrap();
        let error = figures
            .make("the broken figure", |_| anyhow::bail!("no data"))
            .unwrap_err();
        assert_eq!(format!("{error}"), "ch00 figures: the broken figure");
        assert_eq!(format!("{}", error.root_cause()), "no data");
        figures.finish().unwrap();
        let times = std::fs::read_to_string(dir.path().join("figure-times.csv")).unwrap();
        let lines: Vec<&str> = times.lines().collect();
        assert_eq!(lines.len(), 2, "{times}");
        assert!(lines[1].starts_with("a plot; with a comma,"), "{times}");
        assert!(dir.path().join("plot.txt").exists());
        let read = read_times(dir.path()).unwrap();
        assert_eq!(read.len(), 1);
        assert_eq!(read[0].0, "a plot; with a comma");
        assert!(read[0].1 >= 0.0);
    }

    #[test]
    fn a_malformed_line_of_times_is_named_with_its_file_and_line() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join(TIMES_FILE), "figure,seconds\na,1\nb;2\n").unwrap();
        let error = format!("{:#}", read_times(dir.path()).unwrap_err());
        assert!(
            error.contains(TIMES_FILE) && error.contains(":3:"),
            "{error}"
        );
    }
}
