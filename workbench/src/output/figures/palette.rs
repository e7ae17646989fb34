//! Colours: one set for telling series apart, one scale for showing magnitudes.

use plotters::style::RGBColor;

/// Okabe and Ito's palette, chosen to stay distinguishable for colour-blind readers and in
/// greyscale print. Its yellow is left out: it vanishes on a white page.
const SERIES_COLOURS: [RGBColor; 7] = [
    RGBColor(0, 114, 178),   // blue
    RGBColor(213, 94, 0),    // vermillion
    RGBColor(0, 158, 115),   // bluish green
    RGBColor(204, 121, 167), // reddish purple
    RGBColor(230, 159, 0),   // orange
    RGBColor(86, 180, 233),  // sky blue
    RGBColor(0, 0, 0),       // black
];

/// The colour of the `index`-th series of a plot; after seven the colours repeat.
pub(super) fn series_colour(index: usize) -> RGBColor {
    SERIES_COLOURS[index % SERIES_COLOURS.len()]
}

/// Ten evenly spaced samples of matplotlib's *viridis* colour map, dark purple to yellow.
///
/// A rainbow scale invents edges where the data has none (its bright yellow and cyan bands
/// draw the eye); viridis grows steadily brighter, so equal steps in value look like equal steps
/// in colour, and it survives greyscale printing.
const VIRIDIS: [[u8; 3]; 10] = [
    [0x44, 0x01, 0x54],
    [0x48, 0x28, 0x78],
    [0x3E, 0x4A, 0x89],
    [0x31, 0x68, 0x8E],
    [0x26, 0x82, 0x8E],
    [0x1F, 0x9E, 0x89],
    [0x35, 0xB7, 0x79],
    [0x6D, 0xCD, 0x59],
    [0xB4, 0xDE, 0x2C],
    [0xFD, 0xE7, 0x25],
];

/// The viridis colour of `t` in `[0, 1]` (clamped; NaN counts as 0), interpolated between the
/// table's samples.
pub(super) fn viridis(t: f64) -> RGBColor {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let position = t * (VIRIDIS.len() - 1) as f64;
    let below = (position.floor() as usize).min(VIRIDIS.len() - 2);
    let fraction = position - below as f64;
    let mix = |channel: usize| {
        let a = f64::from(VIRIDIS[below][channel]);
        let b = f64::from(VIRIDIS[below + 1][channel]);
        (a + (b - a) * fraction).round() as u8
    };
    RGBColor(mix(0), mix(1), mix(2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn viridis_runs_from_purple_to_yellow_and_clamps() {
        assert_eq!(viridis(0.0), RGBColor(0x44, 0x01, 0x54));
        assert_eq!(viridis(1.0), RGBColor(0xFD, 0xE7, 0x25));
        assert_eq!(viridis(-3.0), viridis(0.0));
        assert_eq!(viridis(f64::NAN), viridis(0.0));
        assert_eq!(viridis(7.0), viridis(1.0));
    }

    #[test]
    fn viridis_grows_brighter() {
        let brightness =
            |c: RGBColor| 0.3 * f64::from(c.0) + 0.6 * f64::from(c.1) + 0.1 * f64::from(c.2);
        let mut previous = -1.0;
        for i in 0..=100 {
            let current = brightness(viridis(i as f64 / 100.0));
            assert!(current >= previous, "darker at {i}");
            previous = current;
        }
    }
}
