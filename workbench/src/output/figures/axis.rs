//! Chart axes, linear or logarithmic, with tick marks a reader can read.
//!
//! On a log axis we do the logarithm ourselves: a value `v` is drawn at position `log10(v)` on
//! an ordinary linear chart. That way we choose the ticks (at 1, 10, 100, ..., or at 1, 2, 5
//! when the data spans less than a decade), label them with the value rather than its logarithm,
//! and can simply skip the values a log axis cannot show (zero and negatives) instead of
//! letting them turn into `-inf` somewhere inside the plotting library.

use std::ops::Range;

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;

/// About this many labelled ticks on a linear axis.
const TARGET_TICKS: f64 = 6.0;

/// One axis of a chart: the positions it spans and whether it is logarithmic.
///
/// Positions are in *plot space*: the value itself on a linear axis, its base-10 logarithm on a
/// log axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Axis {
    /// Logarithmic?
    pub log: bool,
    /// Lowest position shown.
    pub start: f64,
    /// Highest position shown.
    pub end: f64,
}

impl Axis {
    /// Where `value` is drawn on an axis of this kind, or `None` if it cannot be drawn there
    /// (not finite, or not positive on a log axis).
    pub fn position_on(log: bool, value: f64) -> Option<f64> {
        match (log, value) {
            (_, v) if !v.is_finite() => None,
            (true, v) if v <= 0.0 => None,
            (true, v) => Some(v.log10()),
            (false, v) => Some(v),
        }
    }

    /// Where `value` is drawn on this axis, as [`Axis::position_on`].
    pub fn position(&self, value: f64) -> Option<f64> {
        Self::position_on(self.log, value)
    }

    /// An axis exactly from `start` to `end` (values, not positions), with no padding.
    pub fn exact(start: f64, end: f64) -> Self {
        Self {
            log: false,
            start,
            end,
        }
        .widened_if_degenerate()
    }

    /// An axis that shows all the drawable `values` with a little room around them.
    ///
    /// With nothing to show it still spans a sensible range (0 to 1, or 1 to 10), so an empty or
    /// degenerate plot is still a valid picture rather than an error.
    pub fn fit(log: bool, values: impl IntoIterator<Item = f64>) -> Self {
        let positions = values
            .into_iter()
            .filter_map(|value| Self::position_on(log, value));
        Self::fit_positions(log, positions)
    }

    /// As [`Axis::fit`], for values already turned into positions.
    pub fn fit_positions(log: bool, positions: impl IntoIterator<Item = f64>) -> Self {
        let (low, high) = positions
            .into_iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p), hi.max(p))
            });
        if low > high {
            return Self {
                log,
                start: 0.0,
                end: 1.0,
            };
        }
        let padding = 0.05 * (high - low);
        let mut axis = Self {
            log,
            start: low - padding,
            end: high + padding,
        }
        .widened_if_degenerate();
        // Errors, counts and times are never negative: don't pad a linear axis below zero.
        if !log && low >= 0.0 && axis.start < 0.0 {
            axis.start = 0.0;
        }
        axis
    }

    /// A single value gives an axis of zero length; give it some room (half a decade either
    /// side on a log axis, 10 % or 1 on a linear one).
    fn widened_if_degenerate(mut self) -> Self {
        if self.end > self.start {
            return self;
        }
        let half_width = if self.log {
            0.5
        } else if self.start == 0.0 {
            1.0
        } else {
            0.1 * self.start.abs()
        };
        self.start -= half_width;
        self.end += half_width;
        self
    }

    /// The labelled tick positions and the positions of fainter unlabelled grid lines.
    pub fn ticks(&self) -> (Vec<f64>, Vec<f64>) {
        if self.log {
            self.log_ticks()
        } else {
            let step = self.linear_step();
            let labelled = multiples_within(step, self.start, self.end);
            let light = multiples_within(step / 2.0, self.start, self.end)
                .into_iter()
                .filter(|p| !labelled.iter().any(|l| (l - p).abs() < step * 1e-6))
                .collect();
            (labelled, light)
        }
    }

    /// A round step (1, 2 or 5 times a power of ten) giving about [`TARGET_TICKS`] ticks.
    fn linear_step(&self) -> f64 {
        let rough = (self.end - self.start) / TARGET_TICKS;
        let power = 10f64.powf(rough.log10().floor());
        [1.0, 2.0, 5.0, 10.0]
            .into_iter()
            .map(|mantissa| mantissa * power)
            .find(|step| *step >= rough)
            .unwrap_or(10.0 * power)
    }

    /// Ticks at powers of ten; at 1, 2, 5 (or every digit) times them if the axis spans less
    /// than about two decades; at round linear steps if even that gives fewer than three.
    /// Fainter lines mark the other digits when the decades are wide enough to show them.
    fn log_ticks(&self) -> (Vec<f64>, Vec<f64>) {
        let first_decade = self.start.floor() as i32;
        let last_decade = self.end.ceil() as i32;
        let within = |p: &f64| *p >= self.start - 1e-9 && *p <= self.end + 1e-9;
        let digits_times_powers = |digits: &[f64]| -> Vec<f64> {
            (first_decade..=last_decade)
                .flat_map(|decade| digits.iter().map(move |d| d.log10() + f64::from(decade)))
                .filter(within)
                .collect()
        };
        let every_digit = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0];
        let without = |all: Vec<f64>, labelled: &[f64]| -> Vec<f64> {
            all.into_iter()
                .filter(|p| !labelled.iter().any(|l| (l - p).abs() < 1e-9))
                .collect()
        };

        let powers = digits_times_powers(&[1.0]);
        if powers.len() >= 3 {
            // Many decades: label powers of ten, thinned so that at most about 8 remain; the
            // skipped ones (and, if there is room, the digits between) get faint lines.
            let stride = powers.len().div_ceil(8);
            let labelled: Vec<f64> = powers.iter().copied().step_by(stride).collect();
            let faint = if self.end - self.start <= 4.0 {
                digits_times_powers(&every_digit)
            } else {
                powers
            };
            let light = without(faint, &labelled);
            return (labelled, light);
        }
        for digits in [&[1.0, 2.0, 5.0][..], &every_digit] {
            let labelled = digits_times_powers(digits);
            if labelled.len() >= 3 {
                let light = without(digits_times_powers(&every_digit), &labelled);
                return (labelled, light);
            }
        }
        // Less than a digit's width: round steps of the values themselves.
        let (low, high) = (10f64.powf(self.start), 10f64.powf(self.end));
        let linear = Self {
            log: false,
            start: low,
            end: high,
        };
        let labelled = multiples_within(linear.linear_step(), low, high)
            .into_iter()
            .filter(|value| *value > 0.0)
            .map(f64::log10)
            .collect();
        (labelled, Vec::new())
    }

    /// Does this log axis reach so far that its powers of ten read better as `10ⁿ`?
    fn uses_power_notation(&self) -> bool {
        self.log
            && self
                .ticks()
                .0
                .iter()
                .any(|position| !(-3.0..=4.0).contains(&position.round()))
    }

    /// The text of the tick at `position`.
    pub fn label(&self, position: f64) -> String {
        if self.log {
            let exponent = position.round();
            let is_power_of_ten = (position - exponent).abs() < 1e-9;
            if is_power_of_ten && self.uses_power_notation() && !(0.0..=1.0).contains(&exponent) {
                // Every power of ten as 10ⁿ, so 10000 does not sit next to 10⁵.
                format!("10{}", superscript(exponent as i32))
            } else {
                format_number(10f64.powf(position))
            }
        } else {
            let step = self.linear_step();
            // A tick computed as -0.2 + 0.2 may land on -1e-17; show it as zero, not "-0.0".
            let position = if position.abs() < step * 1e-6 {
                0.0
            } else {
                position
            };
            let largest = self.start.abs().max(self.end.abs());
            if (1e-3..1e5).contains(&step) && largest < 1e5 {
                // As many decimals as the step needs: 0.2 -> 1 decimal, 5 -> none.
                let decimals = (-(step.log10() + 1e-9).floor()).max(0.0) as usize;
                format!("{position:.decimals$}")
            } else {
                format_number(position)
            }
        }
    }
}

/// Plotters draws an [`Axis`] like any linear coordinate, except that the ticks are ours: it
/// asks for the "bold" points (labelled, with darker grid lines) and the "light" ones.
impl Ranged for Axis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, position: &f64, pixel_limits: (i32, i32)) -> i32 {
        RangedCoordf64::from(self.start..self.end).map(position, pixel_limits)
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        let (labelled, light) = self.ticks();
        if hint.weight().allow_light_points() {
            light
        } else {
            labelled
        }
    }

    fn range(&self) -> Range<f64> {
        self.start..self.end
    }
}

/// The most ticks [`multiples_within`] gives; a round step gives about [`TARGET_TICKS`].
const MAX_TICKS: f64 = 100.0;

/// All multiples of `step` within `[start, end]`, computed as `k * step` so that rounding errors
/// don't pile up from tick to tick.
///
/// None where there would be more than [`MAX_TICKS`], or no step to count in: an axis so short
/// that a sixth of its length rounds to 0 (two data points a subnormal step apart), or so long
/// that its length overflows, gets a step of 0 or `∞`, and counting its multiples would not end.
fn multiples_within(step: f64, start: f64, end: f64) -> Vec<f64> {
    let first = (start / step - 1e-9).ceil();
    let last = (end / step + 1e-9).floor();
    // NaN or infinite for a step of 0 or `∞`, or an end that is not a number.
    let count = last - first;
    if count.is_nan() || count > MAX_TICKS {
        return Vec::new();
    }
    (first as i64..=last as i64)
        .map(|k| k as f64 * step)
        .collect()
}

/// A number in at most three significant digits: plainly between 0.001 and 99 999 (`0.02`,
/// `150`), as a power of ten otherwise (`10⁻⁵`, `2.5×10⁶`).
pub(super) fn format_number(value: f64) -> String {
    if value == 0.0 || !value.is_finite() {
        return format!("{value}");
    }
    // Rust's scientific formatting does the rounding for us, including 9.999 -> 1.00e1.
    let scientific = format!("{value:.2e}");
    let (mantissa, exponent) = scientific
        .split_once('e')
        .expect("`{:e}` formatting has an exponent");
    let exponent: i32 = exponent.parse().expect("the exponent is an integer");
    if (-3..=4).contains(&exponent) {
        let decimals = (2 - exponent).max(0) as usize;
        let rounded: f64 = scientific.parse().expect("formatted numbers parse");
        trim_decimal_zeros(format!("{rounded:.decimals$}"))
    } else {
        let mantissa = trim_decimal_zeros(mantissa.to_string());
        let power = format!("10{}", superscript(exponent));
        if mantissa == "1" {
            power
        } else {
            format!("{mantissa}×{power}")
        }
    }
}

/// `"2.50"` -> `"2.5"`, `"3.00"` -> `"3"`; integers are left alone.
fn trim_decimal_zeros(text: String) -> String {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// `-5` -> `"⁻⁵"`: exponents as a typesetter writes them (DejaVu has these glyphs).
fn superscript(exponent: i32) -> String {
    exponent
        .to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            '9' => '⁹',
            other => other,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labels(axis: &Axis) -> Vec<String> {
        axis.ticks().0.iter().map(|p| axis.label(*p)).collect()
    }

    #[test]
    fn numbers_read_naturally() {
        assert_eq!(format_number(0.02), "0.02");
        assert_eq!(format_number(150.0), "150");
        assert_eq!(format_number(1000.0), "1000");
        assert_eq!(format_number(0.001), "0.001");
        assert_eq!(format_number(1.0e-5), "10⁻⁵");
        assert_eq!(format_number(2.5e6), "2.5×10⁶");
        assert_eq!(format_number(9.9999e-6), "10⁻⁵");
        assert_eq!(format_number(-0.5), "-0.5");
    }

    #[test]
    fn log_axes_label_powers_of_ten() {
        let axis = Axis::fit(true, [0.001, 0.5, 20.0]);
        assert_eq!(labels(&axis), ["0.001", "0.01", "0.1", "1", "10"]);
        // Fainter lines at the digits between decades, while there is room for them.
        let axis = Axis::fit(true, [0.01, 20.0]);
        let (_, light) = axis.ticks();
        assert!(
            light.iter().any(|p| (p - 2f64.log10()).abs() < 1e-9),
            "{light:?}"
        );
        assert!(!light.contains(&0.0), "1 is labelled, not faint");
    }

    #[test]
    fn a_narrow_log_axis_still_gets_several_ticks() {
        let axis = Axis::fit(true, [3.0, 40.0]);
        assert_eq!(labels(&axis), ["5", "10", "20"]);
        let axis = Axis::fit(true, [3.0, 4.0]);
        assert_eq!(labels(&axis), ["3", "3.2", "3.4", "3.6", "3.8", "4"]);
        let axis = Axis::fit(true, [0.0100, 0.0195]);
        assert_eq!(
            labels(&axis),
            ["0.01", "0.012", "0.014", "0.016", "0.018", "0.02"]
        );
    }

    #[test]
    fn wide_log_axes_write_every_power_of_ten_alike() {
        let axis = Axis::fit(true, [1.0, 50_000.0]);
        assert_eq!(labels(&axis), ["1", "10", "100", "1000", "10000"]);
        let axis = Axis::fit(true, [0.5, 300_000.0]);
        assert_eq!(labels(&axis), ["1", "10", "10²", "10³", "10⁴", "10⁵"]);
    }

    #[test]
    fn many_decades_are_thinned() {
        let axis = Axis::fit(true, [1.0e-12, 1.0e6]);
        let (labelled, _) = axis.ticks();
        assert!(labelled.len() <= 9, "{labelled:?}");
        assert!(labelled.len() >= 5, "{labelled:?}");
    }

    #[test]
    fn non_positive_values_are_skipped_on_log_axes() {
        assert_eq!(Axis::position_on(true, 0.0), None);
        assert_eq!(Axis::position_on(true, -1.0), None);
        assert_eq!(Axis::position_on(false, -1.0), Some(-1.0));
        assert_eq!(Axis::position_on(false, f64::NAN), None);
        let axis = Axis::fit(true, [0.0, -3.0, 10.0, 100.0]);
        assert!(axis.start > 0.9 && axis.end < 2.1, "{axis:?}");
    }

    #[test]
    fn linear_axes_use_round_steps() {
        let axis = Axis::fit(false, [0.0, 0.93]);
        assert_eq!(axis.start, 0.0, "not padded below zero");
        assert_eq!(labels(&axis), ["0.0", "0.2", "0.4", "0.6", "0.8"]);
        let axis = Axis::exact(-1.0, 1.0);
        assert_eq!(labels(&axis), ["-1.0", "-0.5", "0.0", "0.5", "1.0"]);
        let axis = Axis::fit(false, [0.0, 480.0]);
        assert_eq!(labels(&axis), ["0", "100", "200", "300", "400", "500"]);
    }

    #[test]
    fn degenerate_and_empty_ranges_still_make_an_axis() {
        for axis in [
            Axis::fit(false, []),
            Axis::fit(true, []),
            Axis::fit(false, [5.0, 5.0]),
            Axis::fit(false, [0.0]),
            Axis::fit(true, [7.0]),
            Axis::fit(true, [0.0, -1.0]),
        ] {
            assert!(axis.end > axis.start, "{axis:?}");
            assert!(axis.ticks().0.len() >= 2, "{axis:?}: {:?}", axis.ticks());
        }
    }
}
