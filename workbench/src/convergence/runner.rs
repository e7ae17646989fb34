//! Judging techniques at equal *time*: render at growing budgets, time each render, measure
//! its error.
//!
//! A technique that halves the error at equal sample count but takes four times as long per
//! sample is worse, not better: with the same time, plain sampling could have taken four times
//! the samples and halved its error too. So every chapter records, for each technique and
//! budget, both the wall-clock time and the error, and plots error against time.

use std::time::Instant;

use common::image::Image;
use common::metrics::{ConvergenceRecord, relmse, rmse};

/// A named way of rendering the scene, as a function from samples per pixel to an image.
///
/// The closure may borrow the scene (hence the lifetime `'a`) and must be `Sync` so that it can
/// render in parallel inside.
pub struct Technique<'a> {
    /// Name in tables and legends, e.g. `"stratified"`.
    pub name: String,
    /// Renders the scene with the given samples per pixel.
    pub render: Box<dyn Fn(u64) -> Image + Sync + 'a>,
}

impl<'a> Technique<'a> {
    /// A technique from its name and its render function.
    pub fn new(name: impl Into<String>, render: impl Fn(u64) -> Image + Sync + 'a) -> Self {
        Self {
            name: name.into(),
            render: Box::new(render),
        }
    }
}

/// Renders every technique at every budget (samples per pixel), timing each render, and records
/// its errors against `reference`: one record per technique and budget, technique by technique,
/// budgets in the order given. Each RMSE is also [noted](crate::figure_set::note_rmse) for the
/// figure being made, whose quality it measures.
///
/// Times are wall-clock ([`Instant`]), since wall-clock time is what a user waits for; they
/// include everything the render function does, so setup it repeats on every call counts
/// against it. On a busy machine times are noisy: compare techniques measured in the same run.
///
/// # Panics
///
/// If a technique returns an image of a different size than the reference (see [`rmse`]).
pub fn run_convergence(
    techniques: &[Technique],
    budgets: &[u64],
    reference: &Image,
) -> Vec<ConvergenceRecord> {
    let mut records = Vec::with_capacity(techniques.len() * budgets.len());
    for technique in techniques {
        for &spp in budgets {
            let start = Instant::now();
            let image = (technique.render)(spp);
            let seconds = start.elapsed().as_secs_f64();
            let error = rmse(&image, reference);
            crate::figure_set::note_rmse(error);
            records.push(ConvergenceRecord {
                technique: technique.name.clone(),
                spp,
                seconds,
                rmse: error,
                relmse: relmse(&image, reference),
            });
        }
    }
    records
}

/// The records as a Markdown table for a page, one row per technique and budget, so that the
/// numbers printed beside an error-against-time plot are the run's own. `budget` names the
/// samples column as the chapter counts them ("camera rays per pixel").
pub fn convergence_markdown(records: &[ConvergenceRecord], budget: &str) -> String {
    let mut table = format!("| technique | {budget} | seconds | RMSE |\n|---|---:|---:|---:|\n");
    for record in records {
        table.push_str(&format!(
            "| {} | {} | {:.3} | {:.2e} |\n",
            record.technique, record.spp, record.seconds, record.rmse
        ));
    }
    table
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_markdown_table_has_a_row_per_record_under_the_chapter_s_heading() {
        let record = |technique: &str, spp| super::ConvergenceRecord {
            technique: technique.to_string(),
            spp,
            seconds: 0.5,
            rmse: 0.25,
            relmse: 0.0625,
        };
        let table = super::convergence_markdown(
            &[record("pixel centre", 1), record("regular grid", 4)],
            "camera rays per pixel",
        );
        let lines: Vec<&str> = table.lines().collect();
        assert_eq!(lines.len(), 4, "{table}");
        assert_eq!(
            lines[0],
            "| technique | camera rays per pixel | seconds | RMSE |"
        );
        assert_eq!(lines[3], "| regular grid | 4 | 0.500 | 2.50e-1 |");
    }

    use super::*;
    use approx::assert_relative_eq;
    use glam::Vec3;

    /// A fake technique whose image is the reference shifted by `scale / sqrt(spp)` in every
    /// channel: its RMSE is exactly that shift.
    fn offset_technique<'a>(name: &str, reference: &'a Image, scale: f32) -> Technique<'a> {
        Technique::new(name, move |spp| {
            let offset = scale / (spp as f32).sqrt();
            Image {
                pixels: reference.pixels.iter().map(|p| *p + offset).collect(),
                ..reference.clone()
            }
        })
    }

    #[test]
    fn records_every_technique_at_every_budget() {
        let reference = Image::filled(4, 3, Vec3::new(0.5, 1.0, 2.0));
        let techniques = [
            offset_technique("plain", &reference, 1.0),
            offset_technique("better", &reference, 0.25),
        ];
        let budgets = [1, 4, 16];
        let records = run_convergence(&techniques, &budgets, &reference);

        assert_eq!(records.len(), 6);
        for (record, (name, spp)) in records.iter().zip([
            ("plain", 1),
            ("plain", 4),
            ("plain", 16),
            ("better", 1),
            ("better", 4),
            ("better", 16),
        ]) {
            assert_eq!((record.technique.as_str(), record.spp), (name, spp));
            let scale = if name == "plain" { 1.0 } else { 0.25 };
            let offset = scale / (spp as f64).sqrt();
            assert_relative_eq!(record.rmse, offset, max_relative = 1e-5);
            assert!(record.relmse > 0.0);
            assert!(record.seconds >= 0.0 && record.seconds < 10.0);
        }
        // RMSE halves whenever the budget quadruples.
        assert_relative_eq!(records[0].rmse / records[1].rmse, 2.0, max_relative = 1e-5);
    }

    #[test]
    fn the_errors_measured_inside_a_figure_are_noted_for_its_line_of_costs() {
        let reference = Image::filled(4, 3, Vec3::new(0.5, 1.0, 2.0));
        let dir = tempfile::tempdir().unwrap();
        let mut figures = crate::figure_set::FigureSet::start("ch00", dir.path(), true).unwrap();
        figures
            .make("the error-against-time figure", |_| {
                let techniques = [offset_technique("plain", &reference, 1.0)];
                run_convergence(&techniques, &[1, 4, 16], &reference);
                Ok(())
            })
            .unwrap();
        figures.finish().unwrap();
        let costs = crate::figure_set::read_times(dir.path()).unwrap();
        // The smallest error, at 16 samples: 1 / sqrt(16).
        assert_relative_eq!(costs[0].rmse.unwrap(), 0.25, max_relative = 1e-3);
    }

    #[test]
    fn the_time_of_a_slow_technique_is_measured() {
        let reference = Image::new(1, 1);
        let slow = Technique::new("slow", |_| {
            std::thread::sleep(std::time::Duration::from_millis(30));
            Image::new(1, 1)
        });
        let records = run_convergence(&[slow], &[1], &reference);
        assert!(records[0].seconds >= 0.03, "{}", records[0].seconds);
        assert_eq!(records[0].rmse, 0.0);
    }
}
