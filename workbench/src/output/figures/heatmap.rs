//! Does a sampling routine really produce the density it claims? Two heat maps answer it.
//!
//! Left: a histogram of the generated points, scaled to a density (count divided by the number
//! of points and by the bin's area). Right: the claimed pdf, averaged over each bin. Both use
//! the same colour scale, so if the sampler and its pdf agree the two pictures look alike, up
//! to the histogram's noise; a factor of two, a swapped axis or a missing Jacobian shows at a
//! glance.

use std::path::Path;

use glam::{DVec2, Vec2};
use plotters::prelude::{ChartBuilder, Rectangle};
use plotters::style::Color;

use super::axis::Axis;
use super::canvas::{Area, DrawResult, draw_figure, draw_title, figure_error, require_png_path};
use super::fonts::{label_style, tick_style};
use super::palette::viridis;
use crate::output::OutputError;

/// The figure is two square panels and a colour bar.
const SIZE: (u32, u32) = (900, 450);
const TITLE_AREA: u32 = 50;
const PANEL_WIDTH: u32 = 380;
const MARGIN: u32 = 12;
/// The pdf is averaged over this many points per side of each bin.
const PDF_SUBSAMPLES: u32 = 4;
/// The most bins a side: more than the panel has pixels (and `bins²` still fits a `u32`).
const MAX_BINS: u32 = 1024;

/// Saves two heat maps side by side, sharing one colour scale: the density of `points` binned
/// into `bins x bins` cells over `domain = [min, max]`, and `pdf` averaged over the same cells
/// (at 4 x 4 midpoints each).
///
/// The histogram divides by the number of *all* points, so points falling outside the domain
/// show up as missing density rather than being silently renormalised away. Errors: no points,
/// `bins == 0` or over 1024, or a domain without area.
pub fn histogram_vs_pdf(
    path: &Path,
    title: &str,
    points: &[Vec2],
    pdf: &dyn Fn(Vec2) -> f64,
    domain: [Vec2; 2],
    bins: u32,
) -> Result<(), OutputError> {
    require_png_path(path)?;
    if points.is_empty() {
        return Err(figure_error(
            path,
            "there are no points to make a histogram of",
        ));
    }
    if bins == 0 || bins > MAX_BINS {
        return Err(figure_error(
            path,
            format!("the histogram needs 1 to {MAX_BINS} bins a side, not {bins}"),
        ));
    }
    let [low, high] = domain;
    if !(low.cmplt(high).all() && low.is_finite() && high.is_finite()) {
        return Err(figure_error(
            path,
            format!("the domain [{low}, {high}] must be finite with min < max on both axes"),
        ));
    }

    let bins = Bins {
        low: low.as_dvec2(),
        high: high.as_dvec2(),
        count: bins,
    };
    let histogram = bins.histogram_density(points);
    let averaged_pdf = bins.averaged_pdf(pdf);
    let largest = histogram
        .iter()
        .chain(&averaged_pdf)
        .copied()
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    let colour_max = if largest > 0.0 { largest } else { 1.0 };

    draw_figure(path, SIZE, |root| {
        let (title_area, body) = root.split_vertically(TITLE_AREA);
        draw_title(&title_area, title)?;
        let (left, rest) = body.split_horizontally(PANEL_WIDTH);
        let (right, colour_bar) = rest.split_horizontally(PANEL_WIDTH);
        let caption = format!("histogram of {} points", points.len());
        draw_heat_map(&left, &caption, &bins, &histogram, colour_max)?;
        draw_heat_map(
            &right,
            "pdf, averaged over each bin",
            &bins,
            &averaged_pdf,
            colour_max,
        )?;
        draw_colour_bar(&colour_bar, colour_max)
    })
}

/// A square grid of `count x count` bins over `[low, high]`; bin `(i, j)` is column `i` from
/// the left and row `j` from the bottom, stored at index `j * count + i`.
struct Bins {
    low: DVec2,
    high: DVec2,
    count: u32,
}

impl Bins {
    fn size(&self) -> DVec2 {
        (self.high - self.low) / f64::from(self.count)
    }

    /// The bin holding `point`, if it lies in the domain (the top and right edges included).
    fn index_of(&self, point: Vec2) -> Option<usize> {
        let point = point.as_dvec2();
        if !(point.cmpge(self.low).all() && point.cmple(self.high).all()) {
            return None; // also rejects NaN
        }
        let last = f64::from(self.count - 1);
        let cell = ((point - self.low) / self.size())
            .floor()
            .min(DVec2::splat(last));
        Some(cell.y as usize * self.count as usize + cell.x as usize)
    }

    /// Points per unit area in each bin, as a fraction of all points: an estimate of the
    /// density the points were drawn from.
    fn histogram_density(&self, points: &[Vec2]) -> Vec<f64> {
        let mut counts = vec![0u64; (self.count * self.count) as usize];
        for index in points.iter().filter_map(|p| self.index_of(*p)) {
            counts[index] += 1;
        }
        let bin_area = self.size().x * self.size().y;
        let normaliser = points.len() as f64 * bin_area;
        counts
            .iter()
            .map(|&count| count as f64 / normaliser)
            .collect()
    }

    /// The pdf averaged over each bin, from a 4 x 4 grid of midpoints: comparable with the
    /// histogram even where the pdf changes quickly within a bin.
    fn averaged_pdf(&self, pdf: &dyn Fn(Vec2) -> f64) -> Vec<f64> {
        let per_side = f64::from(PDF_SUBSAMPLES);
        let mut averages = Vec::with_capacity((self.count * self.count) as usize);
        for row in 0..self.count {
            for column in 0..self.count {
                let corner = self.low + DVec2::new(f64::from(column), f64::from(row)) * self.size();
                let mut sum = 0.0;
                for sy in 0..PDF_SUBSAMPLES {
                    for sx in 0..PDF_SUBSAMPLES {
                        let offset = (DVec2::new(f64::from(sx), f64::from(sy)) + 0.5) / per_side;
                        sum += pdf((corner + offset * self.size()).as_vec2());
                    }
                }
                averages.push(sum / (per_side * per_side));
            }
        }
        averages
    }
}

/// One heat map: a coloured rectangle per bin.
fn draw_heat_map(
    area: &Area,
    caption: &str,
    bins: &Bins,
    values: &[f64],
    colour_max: f64,
) -> DrawResult {
    let x_axis = Axis::exact(bins.low.x, bins.high.x);
    let y_axis = Axis::exact(bins.low.y, bins.high.y);
    let mut chart = ChartBuilder::on(area)
        .caption(caption, label_style())
        .margin(MARGIN)
        .x_label_area_size(34)
        .y_label_area_size(52)
        .build_cartesian_2d(x_axis, y_axis)?;
    chart
        .configure_mesh()
        .disable_x_mesh()
        .disable_y_mesh()
        .x_label_formatter(&|p| x_axis.label(*p))
        .y_label_formatter(&|p| y_axis.label(*p))
        .label_style(tick_style())
        .draw()?;
    let size = bins.size();
    let cells = values.iter().enumerate().map(|(index, value)| {
        let (column, row) = (index as u32 % bins.count, index as u32 / bins.count);
        let corner = bins.low + DVec2::new(f64::from(column), f64::from(row)) * size;
        let colour = viridis(value / colour_max);
        Rectangle::new(
            [(corner.x, corner.y), (corner.x + size.x, corner.y + size.y)],
            colour.filled(),
        )
    });
    chart.draw_series(cells)?;
    Ok(())
}

/// The key to the colours: a vertical strip from 0 to `colour_max`, numbered on its right.
fn draw_colour_bar(area: &Area, colour_max: f64) -> DrawResult {
    const STRIPS: u32 = 200;
    let value_axis = Axis::exact(0.0, colour_max);
    let mut chart = ChartBuilder::on(area)
        .caption("density", label_style())
        .margin(MARGIN)
        .margin_left(20)
        .x_label_area_size(34)
        .right_y_label_area_size(60)
        .build_cartesian_2d(0.0..1.0, value_axis)?;
    let strip = colour_max / f64::from(STRIPS);
    chart.draw_series((0..STRIPS).map(|i| {
        let bottom = f64::from(i) * strip;
        let colour = viridis((f64::from(i) + 0.5) / f64::from(STRIPS));
        Rectangle::new([(0.0, bottom), (1.0, bottom + strip)], colour.filled())
    }))?;
    // The numbers go on last, so that nothing covers them.
    chart
        .configure_mesh()
        .disable_x_mesh()
        .disable_y_mesh()
        .disable_x_axis()
        .y_label_formatter(&|p| value_axis.label(*p))
        .label_style(tick_style())
        .draw()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::figures::canvas::assert_figure;

    fn unit_bins(count: u32) -> Bins {
        Bins {
            low: DVec2::ZERO,
            high: DVec2::ONE,
            count,
        }
    }

    #[test]
    fn the_histogram_of_a_uniform_grid_is_the_uniform_density() {
        // 16 x 16 evenly spread points in 4 x 4 bins: 16 points per bin of area 1/16.
        let points: Vec<Vec2> = (0..256)
            .map(|i| (Vec2::new((i % 16) as f32, (i / 16) as f32) + 0.5) / 16.0)
            .collect();
        let density = unit_bins(4).histogram_density(&points);
        assert!(
            density.iter().all(|d| (d - 1.0).abs() < 1e-12),
            "{density:?}"
        );
    }

    #[test]
    fn bins_count_rows_from_the_bottom_and_keep_the_top_edge() {
        let bins = unit_bins(2);
        assert_eq!(bins.index_of(Vec2::new(0.9, 0.1)), Some(1));
        assert_eq!(bins.index_of(Vec2::new(0.1, 0.9)), Some(2));
        assert_eq!(bins.index_of(Vec2::ONE), Some(3));
        assert_eq!(bins.index_of(Vec2::new(1.5, 0.5)), None);
        assert_eq!(bins.index_of(Vec2::NAN), None);
    }

    #[test]
    fn points_outside_the_domain_count_as_missing_mass() {
        let density = unit_bins(1).histogram_density(&[Vec2::splat(0.5), Vec2::splat(2.0)]);
        assert_eq!(density, [0.5]);
    }

    #[test]
    fn the_pdf_is_averaged_over_each_bin() {
        // pdf(x, y) = 2x integrates to 1; over the left half of [0,1] its mean is 0.5.
        let averaged = unit_bins(2).averaged_pdf(&|p| 2.0 * f64::from(p.x));
        let expected = [0.5, 1.5, 0.5, 1.5];
        for (got, want) in averaged.iter().zip(expected) {
            assert!((got - want).abs() < 1e-6, "{averaged:?}");
        }
    }

    #[test]
    fn draws_two_maps_and_a_colour_bar() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("histogram.png");
        let points: Vec<Vec2> = (0..1000)
            .map(|i| {
                Vec2::new(
                    ((i * 37) % 1000) as f32 / 1000.0,
                    (i as f32 / 1000.0).sqrt(),
                )
            })
            .collect();
        let domain = [Vec2::ZERO, Vec2::ONE];
        histogram_vs_pdf(
            &path,
            "sqrt warp",
            &points,
            &|p| 2.0 * f64::from(p.y),
            domain,
            16,
        )
        .unwrap();
        assert_figure(&path, SIZE.0, SIZE.1);
    }

    #[test]
    fn bad_input_is_an_error_not_a_panic() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("histogram.png");
        let uniform = |_: Vec2| 1.0;
        let unit = [Vec2::ZERO, Vec2::ONE];
        let flat = [Vec2::ZERO, Vec2::new(1.0, 0.0)];
        let some = [Vec2::splat(0.5)];
        for (points, domain, bins) in [
            (&[][..], unit, 8),
            (&some[..], unit, 0),
            (&some[..], unit, 70_000),
            (&some[..], flat, 8),
        ] {
            let error = histogram_vs_pdf(&path, "t", points, &uniform, domain, bins).unwrap_err();
            assert!(matches!(error, OutputError::Figure { .. }), "{error}");
        }
        assert!(!path.exists());
    }
}
