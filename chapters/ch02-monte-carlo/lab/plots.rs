//! Convergence figures and tables, written to files.

use std::path::Path;

use workbench::convergence::{
    ConvergenceRecord, plot_error_vs_time, series_by_technique, write_convergence_csv,
};
use workbench::output::OutputError;
use workbench::output::figures::{Axes, Series, SeriesStyle, line_plot};

/// Saves a log-log plot of RMSE against the sample count `n`, one line per technique, with a
/// dashed reference line of slope `-1/2` (error `∝ 1/√n`).
///
/// The reference shows at a glance which techniques converge at the Monte Carlo rate (their
/// lines run parallel to it), which converge faster (steeper) and which have lower variance
/// (parallel, but lower). Records with zero error cannot sit on a log axis and are skipped,
/// like the exact cosine-weighted irradiance estimates.
pub fn plot_error_vs_n_with_slope(
    path: &Path,
    title: &str,
    records: &[ConvergenceRecord],
) -> Result<(), OutputError> {
    let mut series = series_by_technique(records, |r| r.spp as f64);
    series.extend(inverse_sqrt_reference(records));
    let axes = Axes::log_log("samples N", "RMSE");
    line_plot(path, title, &axes, &series)
}

/// The reference line `c / √n` over the records' range of `n`, through the first record that
/// has a positive error (so it starts on a measured point), drawn dashed; `None` if no record
/// has one.
pub fn inverse_sqrt_reference(records: &[ConvergenceRecord]) -> Option<Series> {
    let anchor = records.iter().find(|record| record.rmse > 0.0)?;
    let constant = anchor.rmse * (anchor.spp as f64).sqrt();
    let smallest = records.iter().map(|record| record.spp).min()?.max(1);
    let largest = records.iter().map(|record| record.spp).max()?.max(1);
    let points = [smallest, largest]
        .iter()
        .map(|&n| (n as f64, constant / (n as f64).sqrt()))
        .collect();
    Some(Series::new("1/√N", points, SeriesStyle::Dashed))
}

/// Writes the three outputs of a convergence experiment into `directory`: the table
/// `<stem>.csv`, and the plots `<stem>_error_vs_n.png` (with the `1/√n` reference) and
/// `<stem>_error_vs_time.png`.
pub fn save_convergence(
    directory: &Path,
    stem: &str,
    title: &str,
    records: &[ConvergenceRecord],
) -> Result<(), OutputError> {
    write_convergence_csv(&directory.join(format!("{stem}.csv")), records)?;
    plot_error_vs_n_with_slope(
        &directory.join(format!("{stem}_error_vs_n.png")),
        title,
        records,
    )?;
    plot_error_vs_time(
        &directory.join(format!("{stem}_error_vs_time.png")),
        title,
        records,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimator::log_log_slope;
    use approx::assert_relative_eq;

    fn record(technique: &str, spp: u64, rmse: f64) -> ConvergenceRecord {
        ConvergenceRecord {
            technique: technique.into(),
            spp,
            seconds: 1e-6 * spp as f64,
            rmse,
            relmse: rmse * rmse,
        }
    }

    #[test]
    fn the_reference_has_slope_minus_one_half_through_the_first_measured_point() {
        let records = [
            record("exact", 4, 0.0),
            record("plain", 16, 0.5),
            record("plain", 1024, 0.01),
            record("plain", 4, 2.0),
        ];
        let reference = inverse_sqrt_reference(&records).unwrap();
        assert_eq!(reference.style, SeriesStyle::Dashed);
        assert_eq!(reference.points.len(), 2);
        assert_relative_eq!(log_log_slope(reference.points.iter().copied()), -0.5);
        // Through (16, 0.5): at n = 4 it is 1.
        assert_eq!(reference.points[0].0, 4.0);
        assert_relative_eq!(reference.points[0].1, 1.0);
        assert!(inverse_sqrt_reference(&[record("exact", 4, 0.0)]).is_none());
    }

    #[test]
    fn series_are_grouped_and_sorted() {
        let records = [
            record("a", 16, 1.0),
            record("b", 4, 3.0),
            record("a", 4, 2.0),
        ];
        let series = series_by_technique(&records, |r| r.spp as f64);
        assert_eq!(series.len(), 2);
        assert_eq!(series[0].label, "a");
        assert_eq!(series[0].points, [(4.0, 2.0), (16.0, 1.0)]);
    }

    #[test]
    fn all_three_files_are_written() {
        let directory = tempfile::tempdir().unwrap();
        let records = [record("plain", 4, 0.5), record("plain", 16, 0.25)];
        save_convergence(directory.path(), "test", "Test", &records).unwrap();
        for name in ["test.csv", "test_error_vs_n.png", "test_error_vs_time.png"] {
            let path = directory.path().join(name);
            assert!(std::fs::metadata(&path).unwrap().len() > 0, "{name}");
        }
    }
}
