//! What every chapter's `figures` command shares, so that a chapter's `figures.rs` reads as
//! the list of its experiments: the two quality levels, the output folder, the time each
//! figure took, and the comparison with Mitsuba 3.
//!
//! A chapter's `write_all` starts a [`FigureSet`], picks its sizes and budgets for the
//! [`Level`], and makes each figure with [`FigureSet::make`]: the figure's failure is reported
//! with its name, and its time is kept. [`FigureSet::finish`] writes those times to
//! `figure-times.csv` beside the figures, so that what a figure costs is on record, together
//! with the figure's quality where it is measured: the smallest RMSE against a reference that
//! an error-against-time run of the figure found (see [`note_rmse`]). A figure made cheaper
//! at equal quality shows the same RMSE there for less time.

use crate::agreement::AgreementSet;
use crate::cli::prepare_output_dir;
use crate::output::write_text;
use anyhow::Context;
use common::render::RenderSettings;
use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The file beside a chapter's figures with each figure's name, seconds and smallest RMSE.
pub const TIMES_FILE: &str = "figure-times.csv";

/// One figure's line of `figure-times.csv`: what it cost and, where the figure measures it,
/// how close its renders came to their reference.
#[derive(Clone, Debug, PartialEq)]
pub struct FigureCost {
    /// The figure's name, as given to [`FigureSet::make`].
    pub figure: String,
    /// Wall-clock seconds it took.
    pub seconds: f64,
    /// The smallest RMSE against a reference noted while it was made (see [`note_rmse`]);
    /// `None` for a figure that noted none (a gallery, a plot of samples).
    pub rmse: Option<f64>,
}

/// The costs [`FigureSet::finish`] wrote into `dir`, in the order the figures were made. A line
/// that is not `figure,seconds,rmse` (the RMSE may be empty) is named by file and line.
pub fn read_times(dir: &Path) -> anyhow::Result<Vec<FigureCost>> {
    let path = dir.join(TIMES_FILE);
    let csv = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    csv.lines()
        .enumerate()
        .skip(1)
        .map(|(number, line)| {
            parse_cost(line).with_context(|| {
                format!(
                    "{}:{}: not `figure,seconds,rmse`",
                    path.display(),
                    number + 1
                )
            })
        })
        .collect()
}

/// One line of `figure-times.csv`, or `None` if it is malformed.
fn parse_cost(line: &str) -> Option<FigureCost> {
    let (rest, rmse) = line.rsplit_once(',')?;
    let (figure, seconds) = rest.rsplit_once(',')?;
    let rmse = match rmse {
        "" => None,
        number => Some(number.parse().ok()?),
    };
    Some(FigureCost {
        figure: figure.to_string(),
        seconds: seconds.parse().ok()?,
        rmse,
    })
}

thread_local! {
    /// The RMSEs noted on this thread by the figure being made, or `None` between figures.
    static NOTED_RMSE: RefCell<Option<Vec<f64>>> = const { RefCell::new(None) };
}

/// Notes an RMSE measured against a reference while a figure is being made, so that the
/// figure's line in `figure-times.csv` records its quality beside its time.
/// [`run_convergence`](crate::convergence::run_convergence) notes every error it measures; outside
/// [`FigureSet::make`] (in a test, say) nothing is kept.
pub fn note_rmse(rmse: f64) {
    NOTED_RMSE.with(|noted| {
        if let Some(noted) = noted.borrow_mut().as_mut() {
            noted.push(rmse);
        }
    });
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
    costs: Vec<FigureCost>,
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
            costs: Vec::new(),
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

    /// Makes one figure: runs `figure` with the output folder, keeps how long it took and the
    /// smallest RMSE it [noted](note_rmse), and names the figure (`what`, e.g. "the shutter
    /// series") in its error.
    pub fn make(
        &mut self,
        what: &'static str,
        figure: impl FnOnce(&Path) -> anyhow::Result<()>,
    ) -> anyhow::Result<()> {
        let started = Instant::now();
        NOTED_RMSE.with(|noted| *noted.borrow_mut() = Some(Vec::new()));
        let made = figure(&self.out);
        let noted = NOTED_RMSE
            .with(|noted| noted.borrow_mut().take())
            .unwrap_or_default();
        made.with_context(|| format!("{} figures: {what}", self.chapter))?;
        self.costs.push(FigureCost {
            figure: what.to_string(),
            seconds: started.elapsed().as_secs_f64(),
            rmse: noted.into_iter().reduce(f64::min),
        });
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

    /// Writes `figure-times.csv` (each figure's name, seconds and smallest RMSE) and says where
    /// the figures are and how long they took.
    pub fn finish(self) -> anyhow::Result<()> {
        let mut csv = String::from("figure,seconds,rmse\n");
        for cost in &self.costs {
            let rmse = cost
                .rmse
                .map(|rmse| format!("{rmse:.4e}"))
                .unwrap_or_default();
            csv.push_str(&format!(
                "{},{:.3},{rmse}\n",
                cost.figure.replace(',', ";"),
                cost.seconds
            ));
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
        assert_eq!(read[0].figure, "a plot; with a comma");
        assert!(read[0].seconds >= 0.0);
        assert_eq!(read[0].rmse, None, "a plot measures no error");
    }

    #[test]
    fn a_figure_records_the_smallest_rmse_it_noted_and_only_its_own() {
        let dir = tempfile::tempdir().unwrap();
        note_rmse(1e-9); // outside a figure: kept nowhere
        let mut figures = FigureSet::start("ch00", dir.path(), true).unwrap();
        figures
            .make("the error-against-time figure", |_| {
                for rmse in [0.5, 0.125, 0.25] {
                    note_rmse(rmse);
                }
                Ok(())
            })
            .unwrap();
        figures.make("the gallery", |_| Ok(())).unwrap();
        // A failing figure's notes do not leak into the next one.
        let _ = figures.make("the broken figure", |_| {
            note_rmse(1e-6);
            anyhow::bail!("no data")
        });
        figures.make("the plot", |_| Ok(())).unwrap();
        figures.finish().unwrap();
        let read = read_times(dir.path()).unwrap();
        let rmse: Vec<_> = read
            .iter()
            .map(|cost| (cost.figure.as_str(), cost.rmse))
            .collect();
        assert_eq!(
            rmse,
            [
                ("the error-against-time figure", Some(0.125)),
                ("the gallery", None),
                ("the plot", None)
            ]
        );
    }

    #[test]
    fn a_malformed_line_of_times_is_named_with_its_file_and_line() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(
            dir.path().join(TIMES_FILE),
            "figure,seconds,rmse\na,1,\nb,2,0.5\nc;3\n",
        )
        .unwrap();
        let error = format!("{:#}", read_times(dir.path()).unwrap_err());
        assert!(
            error.contains(TIMES_FILE) && error.contains(":4:"),
            "{error}"
        );
    }
}
