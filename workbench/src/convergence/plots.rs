//! The two convergence plots every chapter draws: error against time and against samples.

use std::path::Path;

use super::ConvergenceRecord;
use crate::output::OutputError;
use crate::output::figures::{Axes, Series, SeriesStyle, line_plot};

/// Saves a log-log plot of RMSE against wall-clock seconds, one line per technique: the plot
/// that decides which technique is better, since it compares them at equal time.
///
/// Records with zero time or zero error cannot sit on log axes and are skipped.
pub fn plot_error_vs_time(
    path: &Path,
    title: &str,
    records: &[ConvergenceRecord],
) -> Result<(), OutputError> {
    let axes = Axes::log_log("wall-clock time (s)", "RMSE");
    line_plot(
        path,
        title,
        &axes,
        &series_by_technique(records, |r| r.seconds),
    )
}

/// Saves a log-log plot of RMSE against samples per pixel, one line per technique: its slope
/// is the convergence rate (-1/2 for plain Monte Carlo).
///
/// Records with zero error are skipped.
pub fn plot_error_vs_spp(
    path: &Path,
    title: &str,
    records: &[ConvergenceRecord],
) -> Result<(), OutputError> {
    let axes = Axes::log_log("samples per pixel", "RMSE");
    line_plot(
        path,
        title,
        &axes,
        &series_by_technique(records, |r| r.spp as f64),
    )
}

/// One series per technique, in order of first appearance, its points `(x(record), rmse)`
/// sorted by x so the line runs left to right. Chapters use it to add series of their own
/// (a reference slope, say) to the same plot.
pub fn series_by_technique(
    records: &[ConvergenceRecord],
    x: impl Fn(&ConvergenceRecord) -> f64,
) -> Vec<Series> {
    let mut series: Vec<Series> = Vec::new();
    for record in records {
        let point = (x(record), record.rmse);
        match series.iter_mut().find(|s| s.label == record.technique) {
            Some(existing) => existing.points.push(point),
            None => series.push(Series::new(
                record.technique.clone(),
                vec![point],
                SeriesStyle::LineAndPoints,
            )),
        }
    }
    for one in &mut series {
        one.points.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    series
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(technique: &str, spp: u64, seconds: f64, rmse: f64) -> ConvergenceRecord {
        ConvergenceRecord {
            technique: technique.into(),
            spp,
            seconds,
            rmse,
            relmse: rmse,
        }
    }

    fn records() -> Vec<ConvergenceRecord> {
        let mut records = Vec::new();
        for spp in [1u64, 4, 16, 64, 256] {
            let n = spp as f64;
            records.push(record("independent", spp, 0.01 * n, 0.4 / n.sqrt()));
            records.push(record("stratified", spp, 0.012 * n, 0.4 / n.powf(0.75)));
        }
        records.push(record("stratified", 1024, 0.0, 0.0)); // not drawable on log axes
        records
    }

    #[test]
    fn groups_records_by_technique_in_order() {
        let mut shuffled = records();
        shuffled.swap(0, 1); // stratified first
        shuffled.swap(2, 8); // independent at 256 spp before 4 spp
        let series = series_by_technique(&shuffled, |r| r.spp as f64);
        let labels: Vec<&str> = series.iter().map(|s| s.label.as_str()).collect();
        assert_eq!(labels, ["stratified", "independent"]);
        let xs: Vec<f64> = series[1].points.iter().map(|p| p.0).collect();
        assert_eq!(xs, [1.0, 4.0, 16.0, 64.0, 256.0]);
    }

    #[test]
    fn draws_both_plots() {
        let directory = tempfile::tempdir().unwrap();
        for (name, plot) in [
            (
                "time.png",
                plot_error_vs_time as fn(&Path, &str, &[ConvergenceRecord]) -> _,
            ),
            ("spp.png", plot_error_vs_spp),
        ] {
            let path = directory.path().join(name);
            plot(&path, "Convergence", &records()).unwrap();
            let decoded = image::open(&path).unwrap().to_rgb8();
            assert_eq!(decoded.dimensions(), (800, 600));
        }
    }

    #[test]
    fn no_records_is_an_error() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("time.png");
        assert!(plot_error_vs_time(&path, "t", &[]).is_err());
        assert!(!path.exists());
    }
}
