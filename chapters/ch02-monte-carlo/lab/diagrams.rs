//! The chapter's diagrams: what the disc warps do to equal cells of the unit square, and
//! Malley's method, uniform disc points lifted onto the hemisphere.
//!
//! Every point drawn is one the chapter's warps returned (`sample_disc_naive`,
//! `sample_uniform_disc_polar`, `sample_uniform_disc_concentric`, `sample_cosine_hemisphere`),
//! so the diagrams are as exact as the code. Each diagram's marks are computed first, as data
//! the tests check, and then drawn.

use crate::warps::{
    invert_uniform_disc_concentric, sample_cosine_hemisphere, sample_disc_naive,
    sample_uniform_disc_concentric, sample_uniform_disc_polar,
};
use glam::Vec2;
use std::path::Path;
use workbench::output::figures::{Anchor, Diagram, Ink, Point};

/// The page's description (and the SVG's title) of the disc-cells diagram.
const DISC_CELLS: &str = "The unit square cut into 8 columns (the angle, ξ1) and 4 rows (the \
    radius, ξ2) of equal cells, shaded like a checkerboard, and the same cells mapped onto the \
    unit disc by three warps. The naive polar warp makes rings of equal width, so its inner \
    cells are far smaller than its outer ones although each receives the same share of the \
    samples; the corrected polar warp and the concentric map give every cell the same area.";

/// The page's description of the Malley diagram.
const MALLEY: &str = "Malley's method seen from the side: the unit disc is cut into 5 rings of \
    equal area, and each ring's edge is lifted straight up onto the hemisphere above it. Each \
    band of the hemisphere between two lifted edges receives a fifth of the samples, but the \
    bands near the horizon cover much more solid angle than those near the pole, so directions \
    are denser near the normal.";

/// Writes the chapter's diagrams into `out_dir` (the figures' `diagrams` folder).
pub fn write_all(out_dir: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out_dir)?;
    disc_cells_diagram().save(&out_dir.join("disc-cells.svg"))?;
    malley_diagram().save(&out_dir.join("malley.svg"))?;
    Ok(())
}

/// The grid of the unit square: columns along `ξ1`, rows along `ξ2`.
const COLUMNS: usize = 8;
const ROWS: usize = 4;
/// Points along each edge of a cell's outline: enough for its image's arcs to look round
/// and to have the arcs' area within a fraction of a percent.
const EDGE_STEPS: usize = 24;

/// The outline of cell `(column, row)` of the grid, in `u`, counter-clockwise.
fn cell_outline(column: usize, row: usize) -> Vec<Vec2> {
    let (u0, v0) = (column as f32 / COLUMNS as f32, row as f32 / ROWS as f32);
    let (u1, v1) = (
        (column + 1) as f32 / COLUMNS as f32,
        (row + 1) as f32 / ROWS as f32,
    );
    let corners = [
        Vec2::new(u0, v0),
        Vec2::new(u1, v0),
        Vec2::new(u1, v1),
        Vec2::new(u0, v1),
    ];
    (0..4)
        .flat_map(|edge| {
            let (a, b) = (corners[edge], corners[(edge + 1) % 4]);
            (0..EDGE_STEPS).map(move |k| a.lerp(b, k as f32 / EDGE_STEPS as f32))
        })
        .collect()
}

/// A warp of the diagram: its label and the map.
type Warp = (&'static str, fn(Vec2) -> Vec2);

/// The square itself (drawn as `[-1, 1]²`, the disc's size), then the three disc warps.
fn panels() -> [Warp; 4] {
    [
        ("unit square", |u| 2.0 * u - Vec2::ONE),
        ("naive polar", sample_disc_naive),
        ("corrected polar", sample_uniform_disc_polar),
        ("concentric", sample_uniform_disc_concentric),
    ]
}

/// Every cell of the grid through `warp`: its outline, its column and its row.
fn warped_cells(warp: fn(Vec2) -> Vec2) -> Vec<(Vec<Vec2>, usize, usize)> {
    (0..ROWS)
        .flat_map(|row| (0..COLUMNS).map(move |column| (column, row)))
        .map(|(column, row)| {
            let outline = cell_outline(column, row).into_iter().map(warp).collect();
            (outline, column, row)
        })
        .collect()
}

/// How far apart the panels' centres are, in the diagram's units (a disc is 2 wide).
const PITCH: f64 = 2.55;

fn disc_cells_diagram() -> Diagram {
    let width = PITCH * 3.0 + 2.0 + 0.3;
    let mut diagram = Diagram::new(DISC_CELLS, (-1.15, width - 1.15), (-1.55, 1.08), 760);
    for (index, (name, warp)) in panels().into_iter().enumerate() {
        let cx = PITCH * index as f64;
        let at = |p: Vec2| (cx + f64::from(p.x), f64::from(p.y));
        for (outline, column, row) in warped_cells(warp) {
            let opacity = if (column + row) % 2 == 0 { 0.6 } else { 0.15 };
            diagram.area(outline.into_iter().map(at).collect(), Ink::Ray, opacity);
        }
        if index == 0 {
            diagram.polyline(
                vec![
                    (cx - 1.0, -1.0),
                    (cx + 1.0, -1.0),
                    (cx + 1.0, 1.0),
                    (cx - 1.0, 1.0),
                    (cx - 1.0, -1.0),
                ],
                Ink::Surface,
            );
        } else {
            diagram.circle((cx, 0.0), 1.0, Ink::Surface);
        }
        diagram.label((cx, -1.18), name, Anchor::Above, Ink::Surface);
    }
    diagram
}

/// The rings of Malley's diagram.
const RINGS: usize = 5;

/// The radii of the disc's `RINGS` rings of equal area, from the centre out: the radii the
/// uniform polar warp gives the rows' edges `ξ2 = i / RINGS`.
fn equal_area_radii() -> Vec<f32> {
    (0..=RINGS)
        .map(|i| sample_uniform_disc_polar(Vec2::new(0.0, i as f32 / RINGS as f32)).length())
        .collect()
}

/// A disc point `(x, 0)` and the direction Malley's method lifts it to, `(x, z)` in the
/// plane `y = 0`: the `u` the concentric map sends to the point, through the chapter's
/// cosine-weighted warp.
fn lifted(x: f32) -> (f32, Point) {
    let d = sample_cosine_hemisphere(invert_uniform_disc_concentric(Vec2::new(x, 0.0)));
    (x, (f64::from(d.x), f64::from(d.z)))
}

/// The lifted ring edges on both sides, from the left horizon over the pole to the right one.
fn lifted_edges() -> Vec<(f32, Point)> {
    let radii = equal_area_radii();
    radii
        .iter()
        .rev()
        .map(|&r| -r)
        .chain(radii.iter().skip(1).copied())
        .map(lifted)
        .collect()
}

fn malley_diagram() -> Diagram {
    let mut diagram = Diagram::new(MALLEY, (-1.45, 1.45), (-0.26, 1.15), 720);
    let edges = lifted_edges();
    // The bands of the hemisphere, told apart by alternating inks, and the rings of the disc
    // under them in the same inks.
    for (k, pair) in edges.windows(2).enumerate() {
        // Ring number, from the centre out, on either side of it.
        let ring = if k < RINGS { RINGS - 1 - k } else { k - RINGS };
        let ink = if ring % 2 == 0 {
            Ink::OtherRay
        } else {
            Ink::Light
        };
        let (a, b) = (pair[0].1, pair[1].1);
        let (from, to) = (a.1.atan2(a.0), b.1.atan2(b.0));
        diagram.arc((0.0, 0.0), 1.0, from, to, ink);
        let (x0, x1) = (f64::from(pair[0].0), f64::from(pair[1].0));
        diagram.area(
            vec![(x0, -0.02), (x1, -0.02), (x1, -0.07), (x0, -0.07)],
            ink,
            0.9,
        );
    }
    diagram.line((-1.0, 0.0), (1.0, 0.0), Ink::Surface);
    for &(x, top) in &edges {
        let foot = (f64::from(x), 0.0);
        diagram.dot(top, Ink::Ray);
        if x.abs() < 1.0 {
            // The rim is lifted to the horizon, where the directions meet the disc.
            diagram.line(foot, top, Ink::Guide);
            diagram.arrow((0.0, 0.0), top, Ink::Ray);
        }
    }
    diagram.label((0.0, 1.05), "n̂", Anchor::Below, Ink::Normal);
    // The angle θ of one direction from the normal.
    let (_, shown) = edges[edges.len() - 2];
    let theta_to = shown.1.atan2(shown.0);
    diagram.arc(
        (0.0, 0.0),
        0.3,
        theta_to,
        std::f64::consts::FRAC_PI_2,
        Ink::Guide,
    );
    let half = (theta_to + std::f64::consts::FRAC_PI_2) / 2.0;
    diagram.label(
        (0.38 * half.cos(), 0.38 * half.sin()),
        "θ",
        Anchor::Centre,
        Ink::Surface,
    );
    diagram.label(
        (0.0, -0.12),
        "unit disc: 5 rings of equal area",
        Anchor::Above,
        Ink::Surface,
    );
    diagram.label((-1.42, 0.95), "each band holds", Anchor::Left, Ink::Surface);
    diagram.label(
        (-1.42, 0.83),
        "1/5 of the samples",
        Anchor::Left,
        Ink::Surface,
    );
    diagram
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::warps::cosine_hemisphere_pdf;
    use std::f64::consts::{PI, TAU};
    use workbench::test_support::written_diagrams;

    /// The area of a closed outline (the shoelace formula).
    fn area(outline: &[Vec2]) -> f64 {
        let twice: f64 = outline
            .iter()
            .zip(outline.iter().cycle().skip(1))
            .map(|(a, b)| f64::from(a.x) * f64::from(b.y) - f64::from(b.x) * f64::from(a.y))
            .sum();
        (twice / 2.0).abs()
    }

    #[test]
    fn equal_cells_keep_equal_areas_only_under_the_uniform_warps() {
        let cells = COLUMNS * ROWS;
        for (name, warp) in panels() {
            let areas: Vec<f64> = warped_cells(warp)
                .iter()
                .map(|(outline, _, _)| area(outline))
                .collect();
            let (smallest, largest) = areas.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &a| {
                (lo.min(a), hi.max(a))
            });
            match name {
                "naive polar" => {
                    // Rings of equal width: the outer row's cells are 7 times the inner row's.
                    assert!((largest / smallest - 7.0).abs() < 0.05, "{name}: {areas:?}");
                }
                "unit square" => {
                    for a in &areas {
                        assert!((a - 4.0 / cells as f64).abs() < 1e-6, "{name}: {a}");
                    }
                }
                _ => {
                    // Every cell gets its share of the disc's area: π / 32.
                    for a in &areas {
                        let share = a / (PI / cells as f64);
                        assert!((share - 1.0).abs() < 0.005, "{name}: {share}");
                    }
                }
            }
            // The cells tile their domain: nothing lost, nothing doubled.
            let total: f64 = areas.iter().sum();
            let domain = if name == "unit square" { 4.0 } else { PI };
            assert!((total / domain - 1.0).abs() < 0.005, "{name}: {total}");
        }
    }

    #[test]
    fn each_lifted_band_holds_its_rings_share_of_the_cosine_density() {
        let edges = lifted_edges();
        assert_eq!(edges.len(), 2 * RINGS + 1);
        for &(x, (dx, dz)) in &edges {
            // Straight above its disc point, on the unit hemisphere.
            assert!((dx - f64::from(x)).abs() < 1e-5);
            assert!(dz >= 0.0 && (dx.hypot(dz) - 1.0).abs() < 1e-5);
        }
        // From the pole to the right horizon: the bands between consecutive edges.
        let right = &edges[RINGS..];
        let mut solid_angles = Vec::new();
        for pair in right.windows(2) {
            let theta = |p: Point| p.0.atan2(p.1);
            let (a, b) = (theta(pair[0].1), theta(pair[1].1));
            // The band's probability: the cosine density over its solid angle, 2π sin θ dθ.
            let steps = 2000;
            let h = (b - a) / f64::from(steps);
            let probability: f64 = (0..steps)
                .map(|k| {
                    let t = a + h * (f64::from(k) + 0.5);
                    f64::from(cosine_hemisphere_pdf(t.cos() as f32)) * TAU * t.sin() * h
                })
                .sum();
            assert!(
                (probability - 1.0 / RINGS as f64).abs() < 1e-4,
                "band {a}..{b}: {probability}"
            );
            solid_angles.push(TAU * (a.cos() - b.cos()));
        }
        // Equal shares, but ever more solid angle towards the horizon.
        assert!(
            solid_angles.windows(2).all(|w| w[1] > w[0]),
            "{solid_angles:?}"
        );
    }

    #[test]
    fn write_all_writes_each_diagram_as_svg_with_its_description() {
        assert_eq!(
            written_diagrams(write_all, &["disc-cells.svg", "malley.svg"]),
            [DISC_CELLS, MALLEY]
        );
    }
}
