//! The chapter's diagram: a directional quadtree, drawn from the chapter's own tree.
//!
//! A [`DirectionTree`] is taught, over a few training iterations as the renderer teaches it,
//! the light arriving from three places: a small bright lamp, a narrow gap, and a broad dim
//! wall, over a faint light from everywhere. The diagram draws its leaves over the unit
//! square of [`crate::directions`], each shaded by the density the tree gives it, with points
//! the tree draws: the cells are small where the light is bright and concentrated, large where
//! there is little, and the points fall where the density is.

use crate::quadtree::{DirectionTree, SPLIT_FRACTION};
use glam::Vec2;
use std::path::Path;
use workbench::output::figures::{Anchor, Diagram, Ink};

/// Writes every diagram of the chapter into `out` (the figures' `diagrams` folder).
pub fn write_all(out: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out)?;
    quadtree_cells().save(&out.join("quadtree.svg"))?;
    Ok(())
}

/// The light arriving in the diagram, as places on the square: each a centre, a half-width
/// and the share of the records it receives. What is left of the records falls anywhere.
const SOURCES: [(Vec2, f32, f32); 3] = [
    // A small bright lamp overhead.
    (Vec2::new(0.88, 0.3), 0.02, 0.45),
    // A narrow gap to the side.
    (Vec2::new(0.52, 0.72), 0.012, 0.25),
    // A broad dim wall.
    (Vec2::new(0.3, 0.2), 0.12, 0.2),
];

/// The training iterations, each recording this many more records than the last.
const ITERATIONS: u32 = 5;

/// The records of the first iteration.
const FIRST_RECORDS: u32 = 2_000;

/// A tree taught [`SOURCES`] the way the renderer teaches its guides: each iteration records
/// into the shape [`DirectionTree::refined`] made from the one before, then builds it.
fn taught_tree() -> DirectionTree {
    // A small fixed generator: the diagram is the same at every build.
    let mut state = 0x2545_f491_u32;
    let mut unit = move || {
        state = state.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
        (state >> 8) as f32 / (1u32 << 24) as f32
    };
    let mut tree = DirectionTree::new();
    for iteration in 0..ITERATIONS {
        let mut next = tree.refined(SPLIT_FRACTION);
        for _ in 0..FIRST_RECORDS << iteration {
            let (pick, jitter) = (unit(), Vec2::new(unit(), unit()) * 2.0 - Vec2::ONE);
            let mut point = Vec2::new(unit(), unit());
            let mut below = 0.0;
            for (centre, half_width, share) in SOURCES {
                if (below..below + share).contains(&pick) {
                    point = centre + half_width * jitter;
                }
                below += share;
            }
            next.record(point.clamp(Vec2::ZERO, Vec2::splat(0.999_999)), 1.0);
        }
        next.build(|sum, _| sum);
        tree = next;
    }
    tree
}

/// Every leaf of `tree`: its lower left corner and its side.
fn leaves(tree: &DirectionTree) -> Vec<(Vec2, f32)> {
    let mut out = Vec::new();
    let mut stack = vec![(0usize, Vec2::ZERO, 1.0f32)];
    while let Some((node, origin, size)) = stack.pop() {
        let half = 0.5 * size;
        for q in 0..4 {
            let corner = origin + half * Vec2::new((q & 1) as f32, (q >> 1) as f32);
            match tree.nodes[node].children[q] {
                0 => out.push((corner, half)),
                child => stack.push((child as usize, corner, half)),
            }
        }
    }
    out
}

/// The quadtree's leaves over the unit square, shaded by density, with points drawn from it.
fn quadtree_cells() -> Diagram {
    let tree = taught_tree();
    let cells = leaves(&tree);
    let mut d = Diagram::new(
        "The unit square of directions, the height cos theta = 2u - 1 across and the turn \
         phi = 2 pi v up, divided into the leaves of a directional quadtree taught light from \
         a small bright lamp, a narrow gap and a broad dim wall over a faint light from \
         everywhere. Each leaf is shaded by the density the tree gives it: the leaves are \
         small and dark where the light is bright and concentrated, and large and pale where \
         little arrives. Blue dots, points the tree draws, gather in the small dark leaves.",
        (-0.12, 1.3),
        (-0.14, 1.08),
        640,
    );
    let densities: Vec<f32> = cells
        .iter()
        .map(|&(corner, size)| tree.pdf(corner + Vec2::splat(0.5 * size)))
        .collect();
    let densest = densities.iter().copied().fold(0.0f32, f32::max);
    let faintest = densities
        .iter()
        .copied()
        .filter(|&d| d > 0.0)
        .fold(densest, f32::min);
    // Shaded on a log scale from the faintest leaf to the densest: densities span several
    // powers of ten.
    let span = (densest / faintest).ln().max(f32::EPSILON);
    for (&(corner, size), &density) in cells.iter().zip(&densities) {
        let (x, y, s) = (f64::from(corner.x), f64::from(corner.y), f64::from(size));
        let square = vec![(x, y), (x + s, y), (x + s, y + s), (x, y + s), (x, y)];
        if densest > 0.0 && density > 0.0 {
            let shade = (density / faintest).ln() / span;
            d.area(square.clone(), Ink::Light, 0.1 + 0.85 * f64::from(shade));
        }
        d.polyline(square, Ink::Guide);
    }
    let mut state = 0x9e37_79b9_u32;
    let mut unit = move || {
        state = state.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
        (state >> 8) as f32 / (1u32 << 24) as f32
    };
    for _ in 0..100 {
        if let Some(p) = tree.sample(Vec2::new(unit(), unit())) {
            d.dot((f64::from(p.x), f64::from(p.y)), Ink::Ray);
        }
    }
    d.label(
        (0.5, -0.03),
        "u (height, cos θ = 2u − 1)",
        Anchor::Below,
        Ink::Surface,
    );
    d.label((-0.02, 0.5), "v", Anchor::Right, Ink::Surface);
    d.label((-0.02, 0.0), "0", Anchor::Right, Ink::Guide);
    d.label((-0.02, 1.0), "1", Anchor::Right, Ink::Guide);
    d.label((1.0, -0.03), "1", Anchor::Below, Ink::Guide);
    for (text, (centre, _, _)) in ["lamp", "gap", "wall"].iter().zip(SOURCES) {
        d.label((1.04, f64::from(centre.y)), text, Anchor::Left, Ink::Light);
        d.line(
            (f64::from(centre.x), f64::from(centre.y)),
            (1.03, f64::from(centre.y)),
            Ink::Guide,
        );
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The diagram shows what it says: the tree split where the light is, so the lamp's leaf
    /// is far smaller than a leaf where only the faint light arrives, and its density higher.
    #[test]
    fn the_quadtree_is_finest_where_the_light_is() {
        let tree = taught_tree();
        let cells = leaves(&tree);
        let leaf_at = |p: Vec2| {
            cells
                .iter()
                .find(|(corner, size)| {
                    p.cmpge(*corner).all() && p.cmplt(*corner + Vec2::splat(*size)).all()
                })
                .map(|&(_, size)| size)
                .expect("the leaves cover the square")
        };
        let (lamp, faint) = (SOURCES[0].0, Vec2::new(0.1, 0.9));
        assert!(
            leaf_at(lamp) * 8.0 <= leaf_at(faint),
            "the lamp's leaf {} against {} where the light is faint",
            leaf_at(lamp),
            leaf_at(faint)
        );
        let area: f32 = cells.iter().map(|(_, size)| size * size).sum();
        assert!((area - 1.0).abs() < 1e-5, "the leaves cover {area}");
        let svg = quadtree_cells().to_svg();
        assert!(svg.contains("lamp") && svg.contains("gap"));
    }
}
