//! Point sets drawn as dots, one square panel each: where did the samples land?

use std::path::Path;

use glam::Vec2;
use plotters::prelude::{ChartBuilder, Circle};
use plotters::style::{BLACK, Color};

use super::axis::Axis;
use super::canvas::{Area, DrawResult, draw_figure, draw_title, figure_error, require_png_path};
use super::fonts::{label_style, tick_style};
use super::palette::series_colour;
use crate::output::OutputError;

/// Width of one panel, and so of its square plotting area plus the axis numbers.
const PANEL_WIDTH: u32 = 400;
/// Space for the axis numbers on the left of a panel.
const Y_LABEL_AREA: u32 = 52;
/// Space for the axis numbers below a panel.
const X_LABEL_AREA: u32 = 34;
/// Space for a panel's caption.
const CAPTION_AREA: u32 = 40;
/// Room around the plotting area.
const MARGIN: u32 = 12;
/// Space for the figure's title.
const TITLE_AREA: u32 = 50;
/// More panels than this start a new row.
const MAX_COLUMNS: usize = 4;

/// Saves one square scatter panel per point set, all with the same axes `domain = [min, max]`,
/// side by side (four to a row): for sample positions in a pixel, warps of the unit square, or
/// points on a lens.
///
/// Points outside the domain, or with a NaN coordinate, are not drawn. Dots shrink when a set
/// has thousands of points, so dense sets still show their structure. An empty list of sets is
/// an error; an empty set draws an empty panel. A degenerate domain (`min == max` on an axis)
/// is widened; one with `min > max` is an error.
pub fn scatter_plot(
    path: &Path,
    title: &str,
    sets: &[(String, Vec<Vec2>)],
    domain: [Vec2; 2],
) -> Result<(), OutputError> {
    require_png_path(path)?;
    if sets.is_empty() {
        return Err(figure_error(path, "there are no point sets to draw"));
    }
    let [low, high] = domain;
    if !(low.cmple(high).all() && low.is_finite() && high.is_finite()) {
        return Err(figure_error(
            path,
            format!("the domain [{low}, {high}] must be finite with min <= max"),
        ));
    }

    let columns = sets.len().min(MAX_COLUMNS);
    let rows = sets.len().div_ceil(MAX_COLUMNS);
    let plot_side = PANEL_WIDTH - Y_LABEL_AREA - 2 * MARGIN;
    let panel_height = plot_side + X_LABEL_AREA + CAPTION_AREA + 2 * MARGIN;
    let size = (
        columns as u32 * PANEL_WIDTH + MARGIN,
        rows as u32 * panel_height + TITLE_AREA,
    );

    draw_figure(path, size, |root| {
        let (title_area, panels_area) = root.split_vertically(TITLE_AREA);
        draw_title(&title_area, title)?;
        let (panels_area, _) = panels_area.split_horizontally(columns as u32 * PANEL_WIDTH);
        let panels = panels_area.split_evenly((rows, columns));
        for (index, ((label, points), panel)) in sets.iter().zip(&panels).enumerate() {
            draw_panel(panel, label, points, domain, index)?;
        }
        Ok(())
    })
}

/// One panel: a caption, axes over `domain`, and a dot per point.
fn draw_panel(
    panel: &Area,
    label: &str,
    points: &[Vec2],
    [low, high]: [Vec2; 2],
    index: usize,
) -> DrawResult {
    let x_axis = Axis::exact(f64::from(low.x), f64::from(high.x));
    let y_axis = Axis::exact(f64::from(low.y), f64::from(high.y));
    let mut chart = ChartBuilder::on(panel)
        .caption(label, label_style())
        .margin(MARGIN)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(Y_LABEL_AREA)
        .build_cartesian_2d(x_axis, y_axis)?;
    chart
        .configure_mesh()
        .x_label_formatter(&|p| x_axis.label(*p))
        .y_label_formatter(&|p| y_axis.label(*p))
        .label_style(tick_style())
        .bold_line_style(BLACK.mix(0.12))
        .light_line_style(BLACK.mix(0.04))
        .draw()?;

    let inside = |p: &&Vec2| {
        let (x, y) = (f64::from(p.x), f64::from(p.y));
        x >= x_axis.start && x <= x_axis.end && y >= y_axis.start && y <= y_axis.end
    };
    let radius = if points.len() > 2000 { 1 } else { 2 };
    let colour = series_colour(index);
    chart.draw_series(
        points
            .iter()
            .filter(inside)
            .map(|p| Circle::new((f64::from(p.x), f64::from(p.y)), radius, colour.filled())),
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::figures::canvas::assert_figure;

    fn grid_points(n: u32) -> Vec<Vec2> {
        (0..n * n)
            .map(|i| Vec2::new((i % n) as f32 + 0.5, (i / n) as f32 + 0.5) / n as f32)
            .collect()
    }

    #[test]
    fn draws_one_panel_per_set() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("scatter.png");
        let sets = vec![
            ("stratified".to_string(), grid_points(8)),
            (
                "outside and NaN".to_string(),
                vec![Vec2::splat(3.0), Vec2::NAN],
            ),
            ("empty".to_string(), Vec::new()),
        ];
        scatter_plot(&path, "Samples", &sets, [Vec2::ZERO, Vec2::ONE]).unwrap();
        let plot_side = PANEL_WIDTH - Y_LABEL_AREA - 2 * MARGIN;
        let height = plot_side + X_LABEL_AREA + CAPTION_AREA + 2 * MARGIN + TITLE_AREA;
        assert_figure(&path, 3 * PANEL_WIDTH + MARGIN, height);
    }

    #[test]
    fn no_sets_or_a_reversed_domain_is_an_error() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("scatter.png");
        let error = scatter_plot(&path, "t", &[], [Vec2::ZERO, Vec2::ONE]).unwrap_err();
        assert!(matches!(error, OutputError::Figure { .. }));
        let sets = vec![("a".to_string(), grid_points(2))];
        let error = scatter_plot(&path, "t", &sets, [Vec2::ONE, Vec2::ZERO]).unwrap_err();
        assert!(error.to_string().contains("domain"), "{error}");
        assert!(!path.exists());
    }

    #[test]
    fn a_degenerate_domain_still_draws() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("scatter.png");
        let sets = vec![("a point".to_string(), vec![Vec2::splat(0.5)])];
        scatter_plot(&path, "t", &sets, [Vec2::splat(0.5), Vec2::splat(0.5)]).unwrap();
        assert!(path.exists());
    }
}
