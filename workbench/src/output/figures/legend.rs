//! Where the legend goes: into the corner the curves leave empty.
//!
//! A legend in a fixed corner sooner or later hides the very curve it explains (convergence
//! curves fall towards the lower right, Fresnel curves rise towards the upper right). So we
//! look at where the data is and pick the emptiest corner.

use plotters::chart::SeriesLabelPosition;

/// A curve in *unit* coordinates: `(0, 0)` is the plot's lower-left corner, `(1, 1)` its upper
/// right.
pub(super) struct UnitCurve {
    /// The points, in order.
    pub points: Vec<(f64, f64)>,
    /// Are consecutive points joined by a line (which can cross a corner between points)?
    pub joined: bool,
}

/// Corners in order of preference, used when several are equally empty.
const CORNERS: [SeriesLabelPosition; 4] = [
    SeriesLabelPosition::UpperRight,
    SeriesLabelPosition::UpperLeft,
    SeriesLabelPosition::LowerLeft,
    SeriesLabelPosition::LowerRight,
];

/// Points checked along each line segment.
const STEPS_PER_SEGMENT: usize = 16;

/// The corner whose legend-sized box, `(width, height)` as fractions of the plot, covers the
/// fewest points of the curves.
pub(super) fn emptiest_corner(
    curves: &[UnitCurve],
    (width, height): (f64, f64),
) -> SeriesLabelPosition {
    // A little extra room, so a curve running just along the box's edge also counts.
    let (width, height) = (width + 0.03, height + 0.03);
    let mut samples = Vec::new();
    for curve in curves {
        samples.extend_from_slice(&curve.points);
        if curve.joined {
            for pair in curve.points.windows(2) {
                let ((x0, y0), (x1, y1)) = (pair[0], pair[1]);
                samples.extend((1..STEPS_PER_SEGMENT).map(|step| {
                    let t = step as f64 / STEPS_PER_SEGMENT as f64;
                    (x0 + t * (x1 - x0), y0 + t * (y1 - y0))
                }));
            }
        }
    }
    let covered = |corner: &SeriesLabelPosition| {
        let in_box = |&(x, y): &(f64, f64)| {
            let x_in = match corner {
                SeriesLabelPosition::UpperLeft | SeriesLabelPosition::LowerLeft => x <= width,
                _ => x >= 1.0 - width,
            };
            let y_in = match corner {
                SeriesLabelPosition::UpperLeft | SeriesLabelPosition::UpperRight => {
                    y >= 1.0 - height
                }
                _ => y <= height,
            };
            x_in && y_in
        };
        samples.iter().filter(|point| in_box(point)).count()
    };
    CORNERS
        .into_iter()
        .min_by_key(covered)
        .expect("there are four corners")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn corner_for(points: Vec<(f64, f64)>, joined: bool) -> SeriesLabelPosition {
        emptiest_corner(&[UnitCurve { points, joined }], (0.3, 0.2))
    }

    #[test]
    fn a_falling_curve_leaves_the_upper_right_free() {
        let falling = vec![(0.0, 1.0), (0.5, 0.5), (1.0, 0.0)];
        assert!(matches!(
            corner_for(falling, true),
            SeriesLabelPosition::UpperRight
        ));
    }

    #[test]
    fn a_rising_curve_pushes_the_legend_to_the_upper_left() {
        let rising = vec![(0.0, 0.0), (0.7, 0.1), (1.0, 1.0)];
        assert!(matches!(
            corner_for(rising, true),
            SeriesLabelPosition::UpperLeft
        ));
    }

    #[test]
    fn segments_count_even_between_their_points() {
        // The only points are far apart, but the line between them crosses the upper right.
        let crossing = vec![(0.5, 1.0), (1.0, 0.5)];
        assert!(matches!(
            corner_for(crossing.clone(), true),
            SeriesLabelPosition::UpperLeft
        ));
        assert!(matches!(
            corner_for(crossing, false),
            SeriesLabelPosition::UpperRight
        ));
    }
}
