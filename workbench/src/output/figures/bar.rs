//! One bar per category: counts that belong to named cases, such as rays per pixel against the
//! recursion depth.

use std::path::Path;

use std::ops::Range;

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;
use plotters::element::Text;
use plotters::prelude::{ChartBuilder, Rectangle};
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{BLACK, Color};

use super::axis::{Axis, format_number};
use super::canvas::{draw_figure, draw_title, figure_error, require_png_path};
use super::fonts::{TICK_SIZE, label_style, text_style, tick_style};
use super::palette::series_colour;
use crate::output::OutputError;

/// Size of a bar chart, in pixels.
const SIZE: (u32, u32) = (800, 600);
const TITLE_AREA: u32 = 50;
/// Width of a bar as a fraction of the space per category.
const BAR_WIDTH: f64 = 0.7;

/// Saves a bar chart: one bar per `(label, value)`, in the order given, its value written on
/// top.
///
/// With `log_y` the bars rise from the bottom of a logarithmic axis, which suits quantities that
/// multiply from one category to the next (rays per pixel grow geometrically with depth); a bar
/// of zero or a negative value cannot be drawn there and is left out, its label still shown. An
/// empty list of bars is an error.
pub fn bar_chart(
    path: &Path,
    title: &str,
    y_label: &str,
    bars: &[(String, f64)],
    log_y: bool,
) -> Result<(), OutputError> {
    require_png_path(path)?;
    if bars.is_empty() {
        return Err(figure_error(path, "there are no bars to draw"));
    }
    let values = bars.iter().map(|(_, value)| *value);
    // A linear axis starts at zero: a bar's length is only honest when measured from zero.
    let y_axis = if log_y {
        Axis::fit(true, values)
    } else {
        Axis::fit(false, values.chain([0.0]))
    };
    let categories = Categories { count: bars.len() };
    let label_of = |position: &f64| {
        let index = position.round();
        let on_a_bar = (position - index).abs() < 1e-6 && index >= 0.0;
        match bars.get(index as usize) {
            Some((label, _)) if on_a_bar => label.clone(),
            _ => String::new(),
        }
    };

    draw_figure(path, SIZE, |root| {
        let (title_area, body) = root.split_vertically(TITLE_AREA);
        draw_title(&title_area, title)?;
        let mut chart = ChartBuilder::on(&body)
            .margin(16)
            .margin_right(30)
            .x_label_area_size(50)
            .y_label_area_size(100)
            .build_cartesian_2d(categories, y_axis)?;
        chart
            .configure_mesh()
            .disable_x_mesh()
            .y_desc(y_label)
            .x_label_formatter(&label_of)
            .y_label_formatter(&|p| y_axis.label(*p))
            .x_label_style(label_style())
            .y_label_style(tick_style())
            .axis_desc_style(label_style())
            .bold_line_style(BLACK.mix(0.15))
            .light_line_style(BLACK.mix(0.05))
            .draw()?;

        let drawable = || {
            bars.iter().enumerate().filter_map(|(index, (_, value))| {
                Some((index as f64, *value, y_axis.position(*value)?))
            })
        };
        let colour = series_colour(0);
        chart.draw_series(drawable().map(|(centre, _, top)| {
            let half = BAR_WIDTH / 2.0;
            Rectangle::new(
                [(centre - half, y_axis.start), (centre + half, top)],
                colour.filled(),
            )
        }))?;
        let value_style = text_style(TICK_SIZE, BLACK).pos(Pos::new(HPos::Center, VPos::Bottom));
        chart.draw_series(drawable().map(|(centre, value, top)| {
            Text::new(format_number(value), (centre, top), value_style.clone())
        }))?;
        Ok(())
    })
}

/// The horizontal axis of a bar chart: bar `i` is centred at position `i`, and each bar's
/// centre carries its label.
#[derive(Clone, Copy)]
struct Categories {
    count: usize,
}

impl Ranged for Categories {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, position: &f64, pixel_limits: (i32, i32)) -> i32 {
        RangedCoordf64::from(self.range()).map(position, pixel_limits)
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            (0..self.count).map(|index| index as f64).collect()
        }
    }

    fn range(&self) -> Range<f64> {
        -0.5..self.count as f64 - 0.5
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::figures::canvas::assert_figure;

    fn rays_per_depth() -> Vec<(String, f64)> {
        (0..6)
            .map(|depth| (depth.to_string(), 3f64.powi(depth)))
            .collect()
    }

    #[test]
    fn draws_linear_and_log_charts() {
        let directory = tempfile::tempdir().unwrap();
        for log_y in [false, true] {
            let path = directory.path().join(format!("bars-{log_y}.png"));
            bar_chart(&path, "Rays per pixel", "rays", &rays_per_depth(), log_y).unwrap();
            assert_figure(&path, SIZE.0, SIZE.1);
        }
    }

    #[test]
    fn zero_and_negative_bars_do_not_break_a_log_chart() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("bars.png");
        let bars = vec![("none".to_string(), 0.0), ("minus".to_string(), -2.0)];
        bar_chart(&path, "t", "y", &bars, true).unwrap();
        bar_chart(&path, "t", "y", &bars, false).unwrap();
        assert_figure(&path, SIZE.0, SIZE.1);
    }

    #[test]
    fn no_bars_is_an_error() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("bars.png");
        let error = bar_chart(&path, "t", "y", &[], false).unwrap_err();
        assert!(matches!(error, OutputError::Figure { .. }));
        assert!(!path.exists());
    }
}
