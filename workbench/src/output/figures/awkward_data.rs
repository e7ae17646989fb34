//! Data a wrong answer computed (NaN, infinities, zeros, numbers at the ends of `f64`, a
//! domain of any numbers) makes every figure either draw or say in words why it cannot, never
//! panic or hang: a chapter's figure of a broken sampler is where a student looks first.

use glam::Vec2;
use proptest::prelude::*;

use super::{Axes, Series, SeriesStyle, bar_chart, histogram_vs_pdf, line_plot, scatter_plot};
use crate::output::OutputError;
use common::geometry::awkward::{self, number_f64, vec2};

/// Drawn, or refused with the error a figure gives: anything else fails the case.
fn drawn_or_refused(result: Result<(), OutputError>) -> Result<(), TestCaseError> {
    match result {
        Ok(()) | Err(OutputError::Figure { .. }) => Ok(()),
        Err(other) => Err(TestCaseError::fail(other.to_string())),
    }
}

fn points() -> impl Strategy<Value = Vec<(f64, f64)>> {
    prop::collection::vec((number_f64(), number_f64()), 0..6)
}

proptest! {
    #![proptest_config(awkward::config(32))]

    #[test]
    fn a_line_plot_of_any_points(
        first in points(),
        second in points(),
        log_x: bool,
        log_y: bool,
    ) {
        let dir = tempfile::tempdir().unwrap();
        let axes = Axes { log_x, log_y, ..Axes::linear("x", "y") };
        let series = [
            Series::new("first", first, SeriesStyle::LineAndPoints),
            Series::new("second", second, SeriesStyle::Dashed),
        ];
        drawn_or_refused(line_plot(&dir.path().join("line.png"), "t", &axes, &series))?;
    }

    #[test]
    fn a_scatter_plot_of_any_points_over_any_domain(
        points in prop::collection::vec(vec2(), 0..12),
        low in vec2(),
        high in vec2(),
        unit: bool,
    ) {
        let dir = tempfile::tempdir().unwrap();
        let domain = if unit { [Vec2::ZERO, Vec2::ONE] } else { [low, high] };
        let sets = [("set".to_string(), points)];
        drawn_or_refused(scatter_plot(&dir.path().join("scatter.png"), "t", &sets, domain))?;
    }

    #[test]
    fn a_bar_chart_of_any_values(
        values in prop::collection::vec(number_f64(), 1..6),
        log_y: bool,
    ) {
        let dir = tempfile::tempdir().unwrap();
        let bars: Vec<(String, f64)> =
            values.iter().enumerate().map(|(i, &v)| (format!("bar {i}"), v)).collect();
        drawn_or_refused(bar_chart(&dir.path().join("bars.png"), "t", "y", &bars, log_y))?;
    }

    #[test]
    fn a_histogram_of_any_points_against_any_density(
        points in prop::collection::vec(vec2(), 0..12),
        density in number_f64(),
        low in vec2(),
        high in vec2(),
        unit: bool,
        bins in 0u32..12,
    ) {
        let dir = tempfile::tempdir().unwrap();
        let domain = if unit { [Vec2::ZERO, Vec2::ONE] } else { [low, high] };
        let pdf = |p: Vec2| if p.x < 0.5 { density } else { f64::from(p.y) };
        drawn_or_refused(histogram_vs_pdf(
            &dir.path().join("histogram.png"), "t", &points, &pdf, domain, bins,
        ))?;
    }
}

/// The numbers' kinds one at a time, each alone in a plot: the cases a random draw may miss.
#[test]
fn every_kind_of_number_alone_on_every_axis() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("line.png");
    let kinds = [f64::NAN, f64::INFINITY, 0.0, 5e-324, 1e300, f64::MAX];
    for (log_x, log_y) in [(false, false), (true, true)] {
        let axes = Axes {
            log_x,
            log_y,
            ..Axes::linear("x", "y")
        };
        for &a in &kinds {
            for &b in &kinds {
                let points = vec![(a, b), (b, a), (1.0, a)];
                let series = [Series::new("s", points, SeriesStyle::Points)];
                drawn_or_refused(line_plot(&path, "t", &axes, &series))
                    .unwrap_or_else(|e| panic!("{a} {b}: {e}"));
            }
        }
    }
}
