//! Curves on linear or logarithmic axes: convergence plots, above all.
//!
//! On log-log axes a power law `error = c * n^k` is a straight line of slope `k`, which is why
//! convergence is always plotted that way: the Monte Carlo rate `n^(-1/2)` and a stratified
//! sampler's faster rate are told apart by their slopes, and a [`SeriesStyle::Dashed`] reference
//! line of the expected slope makes the comparison explicit.

use std::error::Error;
use std::path::Path;

use plotters::chart::{ChartContext, SeriesAnno};
use plotters::coord::cartesian::Cartesian2d;
use plotters::prelude::{
    BitMapBackend, ChartBuilder, Circle, DashedLineSeries, DrawingBackend, EmptyElement,
    LineSeries, PathElement, SeriesLabelPosition,
};
use plotters::style::{BLACK, Color, RGBColor, WHITE};

use super::axis::Axis;
use super::canvas::{Area, DrawResult, draw_figure, draw_title, figure_error, require_png_path};
use super::fonts::{LABEL_SIZE, label_style, tick_style};
use super::legend::{UnitCurve, emptiest_corner};
use super::palette::series_colour;
use crate::output::OutputError;

/// Size of a line plot, in pixels.
const SIZE: (u32, u32) = (800, 600);
const TITLE_AREA: u32 = 50;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SeriesStyle {
    /// A solid line through the points.
    Line,
    /// A dot at each point: measurements that should not suggest a trend between them.
    Points,
    /// A line with a dot at each point: measurements at a few sample counts or times.
    LineAndPoints,
    /// A dashed line: a reference, such as the slope `1/sqrt(n)`, not a measurement.
    Dashed,
}

/// One named curve of a [`line_plot`].
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Name in the legend.
    pub label: String,
    /// `(x, y)` points, drawn in the order given.
    pub points: Vec<(f64, f64)>,
    /// How it is drawn.
    pub style: SeriesStyle,
}

impl Series {
    /// A series from its parts.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: SeriesStyle) -> Self {
        Self {
            label: label.into(),
            points,
            style,
        }
    }
}

/// The axes of a [`line_plot`]: their descriptions and whether they are logarithmic.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Axes {
    /// Description of the horizontal axis, with its unit, e.g. `"time (s)"`.
    pub x_label: String,
    /// Description of the vertical axis.
    pub y_label: String,
    /// Logarithmic horizontal axis?
    pub log_x: bool,
    /// Logarithmic vertical axis?
    pub log_y: bool,
}

impl Axes {
    /// Two linear axes.
    pub fn linear(x_label: impl Into<String>, y_label: impl Into<String>) -> Self {
        Self {
            x_label: x_label.into(),
            y_label: y_label.into(),
            log_x: false,
            log_y: false,
        }
    }

    /// Two logarithmic axes, as for convergence plots.
    pub fn log_log(x_label: impl Into<String>, y_label: impl Into<String>) -> Self {
        Self {
            log_x: true,
            log_y: true,
            ..Self::linear(x_label, y_label)
        }
    }
}

/// Saves a plot of `series` as a PNG: one colour per series, a legend, and axes that fit all
/// the points.
///
/// Points a log axis cannot show (zero or negative) and non-finite points are skipped, not
/// fatal: a run whose error reached exactly zero still gets its plot. If nothing is left to
/// show, or all points coincide, the axes fall back to a sensible range. An empty list of
/// series is an error.
pub fn line_plot(
    path: &Path,
    title: &str,
    axes: &Axes,
    series: &[Series],
) -> Result<(), OutputError> {
    require_png_path(path)?;
    if series.is_empty() {
        return Err(figure_error(path, "there are no series to plot"));
    }
    // Every series' points, in plot positions, with the undrawable ones dropped.
    let positioned: Vec<Vec<(f64, f64)>> = series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .filter_map(|&(x, y)| {
                    Some((
                        Axis::position_on(axes.log_x, x)?,
                        Axis::position_on(axes.log_y, y)?,
                    ))
                })
                .collect()
        })
        .collect();
    let all = || positioned.iter().flatten();
    let x_axis = Axis::fit_positions(axes.log_x, all().map(|p| p.0));
    let y_axis = Axis::fit_positions(axes.log_y, all().map(|p| p.1));

    draw_figure(path, SIZE, |root| {
        let (title_area, body) = root.split_vertically(TITLE_AREA);
        draw_title(&title_area, title)?;
        draw_chart(&body, axes, (x_axis, y_axis), series, &positioned)
    })
}

/// The chart below the title: axes, grid, curves and legend.
fn draw_chart(
    area: &Area,
    axes: &Axes,
    (x_axis, y_axis): (Axis, Axis),
    series: &[Series],
    positioned: &[Vec<(f64, f64)>],
) -> DrawResult {
    let mut chart = ChartBuilder::on(area)
        .margin(16)
        .margin_right(30)
        .x_label_area_size(60)
        .y_label_area_size(100)
        .build_cartesian_2d(x_axis, y_axis)?;
    chart
        .configure_mesh()
        .x_desc(axes.x_label.as_str())
        .y_desc(axes.y_label.as_str())
        .x_label_formatter(&|p| x_axis.label(*p))
        .y_label_formatter(&|p| y_axis.label(*p))
        .label_style(tick_style())
        .axis_desc_style(label_style())
        .bold_line_style(BLACK.mix(0.15))
        .light_line_style(BLACK.mix(0.05))
        .draw()?;

    for (index, (series, points)) in series.iter().zip(positioned).enumerate() {
        let colour = series_colour(index);
        let line = colour.stroke_width(2);
        let dot = colour.filled();
        let annotation = match series.style {
            SeriesStyle::Line | SeriesStyle::LineAndPoints => {
                chart.draw_series(LineSeries::new(points.iter().copied(), line))?
            }
            SeriesStyle::Dashed => {
                chart.draw_series(DashedLineSeries::new(points.iter().copied(), 10, 6, line))?
            }
            SeriesStyle::Points => {
                chart.draw_series(points.iter().map(|&p| Circle::new(p, 4, dot)))?
            }
        };
        annotation.label(series.label.as_str());
        add_legend_sample(annotation, series.style, colour);
        if series.style == SeriesStyle::LineAndPoints {
            chart.draw_series(points.iter().map(|&p| Circle::new(p, 4, dot)))?;
        }
    }

    let corner = legend_corner(area, &chart, (x_axis, y_axis), series, positioned)?;
    chart
        .configure_series_labels()
        .position(corner)
        .label_font(label_style())
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .margin(12)
        .draw()?;
    Ok(())
}

/// The corner of the plot where the legend hides the fewest points.
fn legend_corner(
    area: &Area,
    chart: &ChartContext<BitMapBackend, Cartesian2d<Axis, Axis>>,
    (x_axis, y_axis): (Axis, Axis),
    series: &[Series],
    positioned: &[Vec<(f64, f64)>],
) -> Result<SeriesLabelPosition, Box<dyn Error>> {
    let mut widest_label = 0;
    for one in series {
        widest_label = widest_label.max(area.estimate_text_size(&one.label, &label_style())?.0);
    }
    // The legend's box: a sample, the label and margins across; a row per series down.
    let legend_width = f64::from(widest_label) + 70.0;
    let legend_height = series.len() as f64 * LABEL_SIZE * 1.3 + 24.0;
    let (plot_width, plot_height) = chart.plotting_area().dim_in_pixel();
    let to_unit = |(x, y): (f64, f64)| {
        (
            (x - x_axis.start) / (x_axis.end - x_axis.start),
            (y - y_axis.start) / (y_axis.end - y_axis.start),
        )
    };
    let curves: Vec<UnitCurve> = series
        .iter()
        .zip(positioned)
        .map(|(one, points)| UnitCurve {
            points: points.iter().copied().map(to_unit).collect(),
            joined: one.style != SeriesStyle::Points,
        })
        .collect();
    let size = (
        legend_width / f64::from(plot_width.max(1)),
        legend_height / f64::from(plot_height.max(1)),
    );
    Ok(emptiest_corner(&curves, size))
}

/// Gives a series its sample in the legend: a short stretch of line, a dot, or both, in the
/// series' colour and style. `(x, y)` is the sample's left middle, in pixels.
fn add_legend_sample<'a, Backend: DrawingBackend + 'a>(
    annotation: &mut SeriesAnno<'a, Backend>,
    style: SeriesStyle,
    colour: RGBColor,
) {
    let line = colour.stroke_width(2);
    let dot = colour.filled();
    match style {
        SeriesStyle::Line => {
            annotation.legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], line))
        }
        SeriesStyle::Points => annotation.legend(move |(x, y)| Circle::new((x + 12, y), 4, dot)),
        SeriesStyle::LineAndPoints => annotation.legend(move |(x, y)| {
            EmptyElement::at((x, y))
                + PathElement::new(vec![(0, 0), (24, 0)], line)
                + Circle::new((12, 0), 4, dot)
        }),
        SeriesStyle::Dashed => annotation.legend(move |(x, y)| {
            EmptyElement::at((x, y))
                + PathElement::new(vec![(0, 0), (9, 0)], line)
                + PathElement::new(vec![(15, 0), (24, 0)], line)
        }),
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::figures::canvas::assert_figure;

    fn convergence(label: &str, slope: f64, style: SeriesStyle) -> Series {
        let points = (0..8)
            .map(|k| {
                let n = 4f64.powi(k);
                (n, 0.3 * n.powf(slope))
            })
            .collect();
        Series::new(label, points, style)
    }

    #[test]
    fn draws_a_log_log_plot_with_every_style() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("convergence.png");
        let mut with_zero = convergence("points (one is zero)", -0.75, SeriesStyle::Points);
        with_zero.points.push((5.0, 0.0));
        with_zero.points.push((-1.0, 0.1));
        let series = [
            convergence("independent", -0.5, SeriesStyle::LineAndPoints),
            convergence("stratified", -0.9, SeriesStyle::Line),
            with_zero,
            convergence("1/sqrt(n)", -0.5, SeriesStyle::Dashed),
        ];
        let axes = Axes::log_log("samples per pixel", "RMSE");
        line_plot(&path, "Error against samples", &axes, &series).unwrap();
        assert_figure(&path, SIZE.0, SIZE.1);
    }

    #[test]
    fn degenerate_data_still_gives_a_plot() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("degenerate.png");
        let cases = [
            (Axes::log_log("x", "y"), vec![(0.0, 0.0), (-1.0, 5.0)]),
            (Axes::linear("x", "y"), vec![(2.0, 3.0), (2.0, 3.0)]),
            (Axes::linear("x", "y"), vec![(f64::NAN, 1.0)]),
            (Axes::linear("x", "y"), vec![]),
        ];
        for (axes, points) in cases {
            let series = [Series::new("s", points, SeriesStyle::LineAndPoints)];
            line_plot(&path, "degenerate", &axes, &series).unwrap();
            assert_figure(&path, SIZE.0, SIZE.1);
        }
    }

    #[test]
    fn no_series_is_an_error() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("empty.png");
        let error = line_plot(&path, "t", &Axes::linear("x", "y"), &[]).unwrap_err();
        assert!(matches!(error, OutputError::Figure { .. }));
        assert!(!path.exists());
    }
}
