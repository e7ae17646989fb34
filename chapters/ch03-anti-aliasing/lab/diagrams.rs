//! The chapter's diagrams: which pixels one sample counts for, and with what weight.
//!
//! Every weight drawn is the chapter's own filter evaluated at the offset between the sample
//! and a pixel centre ([`ReconstructionFilter::evaluate_1d`] and the film's `evaluate`), and
//! every pixel drawn as reached is one the film adds the sample to; only the grid and the
//! sample's position are chosen here.

use crate::filters::{FilterKind, ReconstructionFilter};
use common::film::Filter;
use glam::Vec2;
use std::path::Path;
use workbench::output::figures::{Anchor, Diagram, Ink, Point};

/// The filters the diagrams show: the plain average, the tent and the cubic with negative
/// lobes, at their default radii.
const SHOWN: [FilterKind; 3] = [FilterKind::Box, FilterKind::Tent, FilterKind::Mitchell];

/// The footprint diagram's film: `COLUMNS x ROWS` pixels.
const COLUMNS: u32 = 6;
const ROWS: u32 = 5;
/// Where its sample lands, in film pixels.
const FOOTPRINT_SAMPLE: Vec2 = Vec2::new(2.8, 2.6);

/// The weights diagram's row of pixels, and where its sample lands along it.
const ROW_PIXELS: u32 = 8;
const ROW_SAMPLE: f32 = 4.3;
/// World units per unit of weight in the weights diagram.
const WEIGHT_SCALE: f64 = 1.4;

/// Writes every diagram of the chapter into `out_dir`.
pub fn write_all(out_dir: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out_dir)?;
    filter_footprint().save(&out_dir.join("filter-footprint.svg"))?;
    filter_weights().save(&out_dir.join("filter-weights.svg"))?;
    Ok(())
}

/// The filter's name as the page writes it.
fn display_name(kind: FilterKind) -> &'static str {
    match kind {
        FilterKind::Mitchell => "Mitchell",
        other => other.name(),
    }
}

/// The default filter `kind`.
fn filter(kind: FilterKind) -> ReconstructionFilter {
    ReconstructionFilter::new(kind, None).expect("the default filter")
}

/// The centre of pixel `i` along one axis.
fn centre(i: u32) -> f32 {
    i as f32 + 0.5
}

/// The pixels `(x, y)` of the footprint film whose sums the sample at `sample` changes: those
/// whose centre gets a weight that is not zero.
fn reached(filter: &ReconstructionFilter, sample: Vec2) -> Vec<(u32, u32)> {
    (0..ROWS)
        .flat_map(|y| (0..COLUMNS).map(move |x| (x, y)))
        .filter(|&(x, y)| filter.evaluate(sample - Vec2::new(centre(x), centre(y))) != 0.0)
        .collect()
}

/// What the footprint diagram says.
const FOOTPRINT: &str = "One sample on a grid of pixels, drawn three times: the square of the \
    box filter's support around it holds one pixel centre, the tent's (radius 1) four, and \
    Mitchell's (radius 2) sixteen. The sample counts for exactly the pixels whose centres lie \
    in that square.";

/// One sample and the squares of the box's, the tent's and Mitchell's support around it, one
/// panel each, with the pixel centres inside marked: the pixels the sample counts for.
fn filter_footprint() -> Diagram {
    let gap = 1.6;
    let panel = f64::from(COLUMNS) + gap;
    let width = panel * SHOWN.len() as f64 - gap;
    let mut diagram = Diagram::new(
        FOOTPRINT,
        (-0.4, width + 0.4),
        (-1.6, f64::from(ROWS) + 0.4),
        720,
    );
    for (k, kind) in SHOWN.into_iter().enumerate() {
        let x0 = k as f64 * panel;
        // Film y grows downwards, the diagram's upwards.
        let at = |p: Vec2| -> Point { (x0 + f64::from(p.x), f64::from(ROWS as f32 - p.y)) };
        let f = filter(kind);
        let r = f.half_width();
        let square: Vec<Point> = [(-r, -r), (r, -r), (r, r), (-r, r)]
            .into_iter()
            .map(|(dx, dy)| at(FOOTPRINT_SAMPLE + Vec2::new(dx, dy)))
            .collect();
        diagram.area(square.clone(), Ink::Light, 0.18);
        let mut outline = square;
        outline.push(outline[0]);
        diagram.polyline(outline, Ink::Light);
        for i in 0..=COLUMNS {
            let x = i as f32;
            diagram.line(
                at(Vec2::new(x, 0.0)),
                at(Vec2::new(x, ROWS as f32)),
                Ink::Guide,
            );
        }
        for j in 0..=ROWS {
            let y = j as f32;
            diagram.line(
                at(Vec2::new(0.0, y)),
                at(Vec2::new(COLUMNS as f32, y)),
                Ink::Guide,
            );
        }
        let hits = reached(&f, FOOTPRINT_SAMPLE);
        for y in 0..ROWS {
            for x in 0..COLUMNS {
                let ink = if hits.contains(&(x, y)) {
                    Ink::Ray
                } else {
                    Ink::Guide
                };
                diagram.dot(at(Vec2::new(centre(x), centre(y))), ink);
            }
        }
        diagram.dot(at(FOOTPRINT_SAMPLE), Ink::OtherRay);
        let count = hits.len();
        let pixels = if count == 1 { "pixel" } else { "pixels" };
        diagram.label(
            (x0 + f64::from(COLUMNS) / 2.0, -0.35),
            &format!("{}, radius {}", display_name(kind), radius_text(r)),
            Anchor::Above,
            Ink::Surface,
        );
        diagram.label(
            (x0 + f64::from(COLUMNS) / 2.0, -1.0),
            &format!("{count} {pixels} reached"),
            Anchor::Above,
            Ink::Ray,
        );
    }
    diagram
}

/// A radius as the page writes it.
fn radius_text(r: f32) -> String {
    if r == 0.5 {
        "½".to_string()
    } else {
        format!("{r}")
    }
}

/// One stem of the weights diagram: a pixel centre along the row and the filter's profile at
/// its offset from the sample.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Stem {
    /// The pixel's index along the row.
    pixel: u32,
    /// `f(centre - sample)`, the one-dimensional profile.
    weight: f32,
}

/// The pixel centres of the row whose weight for the sample at `ROW_SAMPLE` is not zero.
fn stems(filter: &ReconstructionFilter) -> Vec<Stem> {
    (0..ROW_PIXELS)
        .map(|pixel| Stem {
            pixel,
            weight: filter.evaluate_1d(centre(pixel) - ROW_SAMPLE),
        })
        .filter(|stem| stem.weight != 0.0)
        .collect()
}

/// What the weights diagram says.
const WEIGHTS: &str = "A row of pixels and one sample, with the profile of the box, the tent and \
    Mitchell's filter centred on the sample. Each pixel centre under the profile gets the \
    profile's height there as the sample's weight: the box gives one pixel the weight 1, the \
    tent shares the sample between the two nearest centres, and Mitchell's cubic gives four \
    pixels a weight, the two outer ones slightly negative.";

/// The filters' profiles centred on one sample over a row of pixels, with the weight each
/// pixel centre gets drawn as a stem and written beside it.
fn filter_weights() -> Diagram {
    let band = 2.3;
    let top = band * SHOWN.len() as f64;
    let mut diagram = Diagram::new(
        WEIGHTS,
        (-2.2, f64::from(ROW_PIXELS) + 0.3),
        (-0.6, top + 0.2),
        720,
    );
    let sample = f64::from(ROW_SAMPLE);
    diagram.line((sample, -0.2), (sample, top - 0.2), Ink::Guide);
    diagram.label((sample, -0.25), "sample", Anchor::Above, Ink::OtherRay);
    for (k, kind) in SHOWN.into_iter().enumerate() {
        let base = top - band * (k as f64 + 1.0) + 0.55;
        let f = filter(kind);
        let r = f.half_width();
        // The pixels of the row, as cells on the baseline.
        diagram.line((0.0, base), (f64::from(ROW_PIXELS), base), Ink::Surface);
        for i in 0..=ROW_PIXELS {
            let x = f64::from(i);
            diagram.line((x, base - 0.12), (x, base + 0.12), Ink::Surface);
        }
        for i in 0..ROW_PIXELS {
            diagram.dot((f64::from(centre(i)), base), Ink::Guide);
        }
        // The profile over its support, sampled finely.
        let steps = 200;
        let profile: Vec<Point> = (0..=steps)
            .map(|i| {
                let dx = -r + 2.0 * r * i as f32 / steps as f32;
                (
                    sample + f64::from(dx),
                    base + WEIGHT_SCALE * f64::from(f.evaluate_1d(dx)),
                )
            })
            .collect();
        let mut filled = profile.clone();
        filled.push((sample + f64::from(r), base));
        filled.insert(0, (sample - f64::from(r), base));
        diagram.area(filled.clone(), Ink::Light, 0.25);
        diagram.polyline(filled, Ink::Light);
        for stem in stems(&f) {
            let x = f64::from(centre(stem.pixel));
            let tip = base + WEIGHT_SCALE * f64::from(stem.weight);
            let ink = if stem.weight < 0.0 {
                Ink::Warning
            } else {
                Ink::Ray
            };
            diagram.line((x, base), (x, tip), ink).dot((x, tip), ink);
            let (at, anchor) = if stem.weight < 0.0 {
                ((x, base - 0.15), Anchor::Above)
            } else {
                ((x + 0.08, tip + 0.12), Anchor::Below)
            };
            diagram.label(at, &weight_text(stem.weight), anchor, ink);
        }
        diagram.dot((sample, base), Ink::OtherRay);
        diagram.label(
            (-0.2, base + 0.5),
            &format!("{}, r = {}", display_name(kind), radius_text(r)),
            Anchor::Right,
            Ink::Surface,
        );
    }
    diagram
}

/// A weight to two decimals, with a true minus sign.
fn weight_text(weight: f32) -> String {
    format!("{weight:.2}").replace('-', "−")
}

#[cfg(test)]
mod tests {
    use super::*;
    use common::film::{Film, PixelRect};
    use glam::{UVec2, Vec3};
    use workbench::test_support::written_diagrams;

    /// The pixels whose sums the film changes when it takes `sample` through `filter`.
    fn film_reached(filter: &ReconstructionFilter, sample: Vec2, (w, h): (u32, u32)) -> Film {
        let mut film = Film::new(w, h);
        let whole = PixelRect {
            min: UVec2::ZERO,
            max: UVec2::new(w, h),
        };
        let mut tile = film.tile(whole, filter);
        tile.add_sample(sample, Vec3::ONE, filter);
        film.merge(&tile);
        film
    }

    #[test]
    fn the_footprint_marks_exactly_the_pixels_the_film_adds_the_sample_to() {
        let mut counts = Vec::new();
        for kind in SHOWN {
            let f = filter(kind);
            let film = film_reached(&f, FOOTPRINT_SAMPLE, (COLUMNS, ROWS));
            let by_film: Vec<(u32, u32)> = (0..ROWS)
                .flat_map(|y| (0..COLUMNS).map(move |x| (x, y)))
                .filter(|&(x, y)| film.pixel(x, y).weight != 0.0)
                .collect();
            let drawn = reached(&f, FOOTPRINT_SAMPLE);
            assert_eq!(drawn, by_film, "{kind:?}");
            // And they are the centres inside the support's square around the sample.
            let r = f.half_width();
            for &(x, y) in &drawn {
                let offset = FOOTPRINT_SAMPLE - Vec2::new(centre(x), centre(y));
                assert!(offset.abs().max_element() < r, "{kind:?} ({x}, {y})");
            }
            counts.push(drawn.len());
        }
        // What the description says: one, four and sixteen pixels.
        assert_eq!(counts, [1, 4, 16]);
    }

    #[test]
    fn the_stems_are_the_weights_the_film_gives_along_the_row() {
        let mut stem_counts = Vec::new();
        for kind in SHOWN {
            let f = filter(kind);
            // On the row of centres, the 2-D weight is the profile times its value at 0.
            let sample = Vec2::new(ROW_SAMPLE, 0.5);
            let film = film_reached(&f, sample, (ROW_PIXELS, 1));
            let drawn = stems(&f);
            for pixel in 0..ROW_PIXELS {
                let weight = film.pixel(pixel, 0).weight;
                match drawn.iter().find(|stem| stem.pixel == pixel) {
                    Some(stem) => {
                        let expected = f64::from(stem.weight * f.evaluate_1d(0.0));
                        assert!(
                            (weight - expected).abs() <= 1e-6,
                            "{kind:?} pixel {pixel}: film {weight}, drawn {expected}"
                        );
                    }
                    None => assert_eq!(weight, 0.0, "{kind:?} pixel {pixel}"),
                }
            }
            stem_counts.push(drawn.len());
        }
        assert_eq!(stem_counts, [1, 2, 4]);
        // The box gives its one pixel the full weight; Mitchell's outer two are negative.
        assert_eq!(stems(&filter(FilterKind::Box))[0].weight, 1.0);
        let mitchell = stems(&filter(FilterKind::Mitchell));
        let negative: Vec<u32> = mitchell
            .iter()
            .filter(|s| s.weight < 0.0)
            .map(|s| s.pixel)
            .collect();
        assert_eq!(negative, [2, 5]);
    }

    #[test]
    fn write_all_writes_each_diagram_as_svg_with_its_description() {
        written_diagrams(write_all, &["filter-footprint.svg", "filter-weights.svg"]);
    }
}
