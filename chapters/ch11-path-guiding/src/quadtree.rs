//! The directional quadtree: a distribution over the directions of the sphere, learnt from
//! the light that paths bring back, that refines itself where the light is.
//!
//! Müller, Gross and Novák (*Practical Path Guiding for Efficient Light-Transport
//! Simulation*, EGSR 2017) store the light arriving at a region of space as a quadtree over
//! the unit square of [`crate::directions`]. Each node splits its square into four quadrants
//! and keeps, for each, the sum of what was recorded there; a quadrant is either a leaf or a
//! node of its own. Sampling walks down from the root choosing quadrants in proportion to
//! their sums, then picks a point uniformly in the leaf it ends in; the density is what that
//! walk gives a point. After each training iteration the tree is rebuilt: a quadrant that
//! holds more than a small fraction of the whole is split, one that holds less is merged, so
//! that the cells are small where the light is bright and narrow, and large elsewhere.
//!
//! Quadrant `q` of a node is its left (`q & 1 == 0`) or right half along `x`, and its lower
//! (`q & 2 == 0`) or upper half along `y`.

use glam::Vec2;

/// The deepest a quadrant may be split: cells of `2^-20` of the square's side, far below
/// anything a training iteration can resolve.
pub const MAX_DEPTH: u32 = 20;

/// The share of the whole above which a quadrant is split when the tree is rebuilt: the
/// value Müller et al. use (`ρ = 0.01`).
pub const SPLIT_FRACTION: f32 = 0.01;

/// One node: four quadrants, each with its sum and its child (`0` for a leaf: the root, node
/// 0, is no one's child).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct QuadNode {
    /// What was recorded in each quadrant (after [`DirectionTree::build`], the sum over the
    /// quadrant's leaves).
    pub sums: [f32; 4],
    /// Each quadrant's child node, or `0` for a leaf.
    pub children: [u32; 4],
}

impl QuadNode {
    /// The sum of the four quadrants.
    pub fn total(&self) -> f32 {
        self.sums.iter().sum()
    }
}

/// The quadrant of `point` (in its node's square scaled to `[0, 1)²`) and the point in that
/// quadrant's square, scaled the same way.
pub fn quadrant_of(point: Vec2) -> (usize, Vec2) {
    let right = point.x >= 0.5;
    let upper = point.y >= 0.5;
    let corner = Vec2::new(f32::from(u8::from(right)), f32::from(u8::from(upper)));
    let q = usize::from(right) + 2 * usize::from(upper);
    (
        q,
        (point * 2.0 - corner).clamp(Vec2::ZERO, Vec2::splat(1.0)),
    )
}

/// A distribution over the unit square, as a quadtree of sums.
#[derive(Clone, Debug, PartialEq)]
pub struct DirectionTree {
    /// The nodes, the root first.
    pub nodes: Vec<QuadNode>,
}

impl Default for DirectionTree {
    fn default() -> Self {
        Self::new()
    }
}

impl DirectionTree {
    /// A tree of one node, four empty leaves: nothing learnt.
    pub fn new() -> Self {
        Self {
            nodes: vec![QuadNode::default()],
        }
    }

    /// The sum over the whole square.
    pub fn total(&self) -> f32 {
        self.nodes[0].total()
    }

    /// The bytes the tree's nodes take.
    pub fn memory_bytes(&self) -> usize {
        std::mem::size_of_val(self.nodes.as_slice())
    }

    /// Adds `value` to the leaf that holds `point`. A value that is negative or not finite is
    /// a bug upstream and is left out rather than spoiling the whole tree.
    pub fn record(&mut self, point: Vec2, value: f32) {
        if !(value.is_finite() && value > 0.0) {
            return;
        }
        let (mut node, mut point) = (0, point);
        loop {
            let (q, inner) = quadrant_of(point);
            let child = self.nodes[node].children[q];
            if child == 0 {
                self.nodes[node].sums[q] += value;
                return;
            }
            (node, point) = (child as usize, inner);
        }
    }

    /// Makes every node's sums the sums over its quadrants' leaves, after `leaf_weight(sum,
    /// area)` has turned each leaf's recorded sum into its weight (`area`: the leaf's share of
    /// the square). Sampling then picks a leaf in proportion to its weight.
    pub fn build(&mut self, leaf_weight: impl Fn(f32, f32) -> f32 + Copy) {
        self.build_node(0, 1.0, leaf_weight);
    }

    /// [`build`](Self::build) below node `node`, whose square has area `area`; returns its total.
    fn build_node(
        &mut self,
        node: usize,
        area: f32,
        leaf_weight: impl Fn(f32, f32) -> f32 + Copy,
    ) -> f32 {
        let quarter = 0.25 * area;
        for q in 0..4 {
            let child = self.nodes[node].children[q];
            self.nodes[node].sums[q] = if child == 0 {
                leaf_weight(self.nodes[node].sums[q], quarter)
            } else {
                self.build_node(child as usize, quarter, leaf_weight)
            };
        }
        self.nodes[node].total()
    }

    /// The shape of the next iteration's tree, its sums all 0: a quadrant of this (built) tree
    /// holding more than `split_fraction` of the total is split, where it was a leaf too (its
    /// sum then shared evenly by its four quadrants when deciding below it), down to
    /// [`MAX_DEPTH`]; every other quadrant is a leaf, so what held little is merged.
    pub fn refined(&self, split_fraction: f32) -> Self {
        let mut out = Self::new();
        let total = self.total();
        if !(total > 0.0 && total.is_finite()) {
            return out;
        }
        // A node of `out` to fill in, the node of `self` at the same place (if any), the sums
        // its quadrants had, and its depth (the root's is 1).
        let mut stack = vec![(0usize, Some(0usize), self.nodes[0].sums, 1u32)];
        while let Some((new, old, sums, depth)) = stack.pop() {
            for (q, &sum) in sums.iter().enumerate() {
                if depth >= MAX_DEPTH || sum.is_nan() || sum <= split_fraction * total {
                    continue;
                }
                let child = out.nodes.len();
                out.nodes.push(QuadNode::default());
                out.nodes[new].children[q] = child as u32;
                let old_child = old
                    .map(|o| self.nodes[o].children[q])
                    .filter(|&c| c != 0)
                    .map(|c| c as usize);
                let child_sums = match old_child {
                    Some(c) => self.nodes[c].sums,
                    None => [0.25 * sum; 4],
                };
                stack.push((child, old_child, child_sums, depth + 1));
            }
        }
        out
    }

    // ANCHOR: pdf
    /// The density on the unit square with which [`sample`](Self::sample) picks `point`:
    /// 0 where nothing was recorded, or everywhere when the tree is empty.
    ///
    /// A walk down the tree picks a quadrant in proportion to its sum, then the next, until a
    /// leaf, then a point uniformly in the leaf. What is the chance of each step, and over how
    /// much of the square is the leaf's share spread? Density times area must add up to 1
    /// over the square.
    pub fn pdf(&self, point: Vec2) -> f32 {
        // BEGIN SOLUTION
        let (mut node, mut point, mut density) = (0usize, point, 1.0f32);
        loop {
            let total = self.nodes[node].total();
            if total.is_nan() || total <= 0.0 {
                return 0.0;
            }
            let (q, inner) = quadrant_of(point);
            // The quadrant's share of its node, spread over a quarter of the node's area.
            density *= 4.0 * self.nodes[node].sums[q] / total;
            let child = self.nodes[node].children[q];
            if child == 0 {
                return density;
            }
            (node, point) = (child as usize, inner);
        }
        // END SOLUTION
    }
    // ANCHOR_END: pdf

    // ANCHOR: sample
    /// A point of the unit square drawn from the tree with the 2D number `u`, with the density
    /// [`pdf`](Self::pdf); `None` when nothing was recorded (a tree to sample from needs a
    /// positive total).
    ///
    /// One 2D number is enough for the whole walk: at each node, which part of `u` says left
    /// or right, which says lower or upper, and what is left of `u` for the next level once a
    /// quadrant is chosen? The point in the leaf is the last of it.
    pub fn sample(&self, u: Vec2) -> Option<Vec2> {
        // BEGIN SOLUTION
        if self.total().is_nan() || self.total() <= 0.0 {
            return None;
        }
        /// The largest number below 1, so that a rescaled number stays in `[0, 1)`.
        const BELOW_ONE: f32 = 1.0 - f32::EPSILON / 2.0;
        let (mut node, mut u) = (0usize, u);
        let (mut origin, mut size) = (Vec2::ZERO, 1.0f32);
        loop {
            let s = self.nodes[node].sums;
            // Left or right, by the columns' sums; then lower or upper inside the column.
            let left = s[0] + s[2];
            let left_share = left / (left + s[1] + s[3]);
            let right = u.x >= left_share;
            u.x = if right {
                (u.x - left_share) / (1.0 - left_share)
            } else {
                u.x / left_share
            };
            let column = usize::from(right);
            let lower_share = s[column] / (s[column] + s[column + 2]);
            let upper = u.y >= lower_share;
            u.y = if upper {
                (u.y - lower_share) / (1.0 - lower_share)
            } else {
                u.y / lower_share
            };
            u = u.clamp(Vec2::ZERO, Vec2::splat(BELOW_ONE));
            let q = column + 2 * usize::from(upper);
            size *= 0.5;
            origin += size * Vec2::new(f32::from(u8::from(right)), f32::from(u8::from(upper)));
            let child = self.nodes[node].children[q];
            if child == 0 {
                return Some(origin + u * size);
            }
            node = child as usize;
        }
        // END SOLUTION
    }
    // ANCHOR_END: sample
}

#[cfg(test)]
mod tests {
    use super::*;
    use ch02_monte_carlo::chi2::chi2_test_density;
    use ch02_monte_carlo::warps::{Domain, WarpPoint};

    /// A tree taught a lopsided distribution: most of its records in one small corner, the
    /// rest spread, rebuilt twice so that it has split where the records are.
    fn taught_tree() -> DirectionTree {
        let mut tree = DirectionTree::new();
        for _ in 0..3 {
            let mut next = tree.refined(SPLIT_FRACTION);
            let mut state = 7u32;
            let mut unit = || {
                state = state.wrapping_mul(747796405).wrapping_add(2891336453);
                (state >> 8) as f32 / (1u32 << 24) as f32
            };
            for i in 0..20_000 {
                let p = Vec2::new(unit(), unit());
                // Three records in four in the corner [0.6, 0.7) x [0.1, 0.15).
                let p = if i % 4 == 0 {
                    p
                } else {
                    Vec2::new(0.6 + 0.1 * p.x, 0.1 + 0.05 * p.y)
                };
                next.record(p, 1.0);
            }
            next.build(|sum, _| sum);
            tree = next;
        }
        tree
    }

    fn plane() -> Domain {
        Domain::Plane {
            min: Vec2::ZERO,
            max: Vec2::ONE,
        }
    }

    #[test]
    fn a_taught_tree_splits_where_its_records_are() {
        let tree = taught_tree();
        assert!(
            tree.nodes.len() > 8,
            "the tree split: {} nodes",
            tree.nodes.len()
        );
        let inside = tree.pdf(Vec2::new(0.65, 0.12));
        let outside = tree.pdf(Vec2::new(0.2, 0.8));
        // Three quarters of the records on 0.005 of the square, a quarter on the rest.
        assert!(
            inside > 50.0 && outside < 0.5,
            "pdf {inside} in the corner, {outside} away"
        );
    }

    /// A tree small enough to work out by hand. The root's quadrants hold 6, 1, 1 and 0;
    /// the first (lower left) is split, its quadrants holding 3, 1, 1 and 1. A walk takes the
    /// root's lower left quadrant with chance 6/8, then the child's with chance 3/6, 1/6, 1/6
    /// and 1/6; the other quadrants of the root with 1/8, 1/8 and 0.
    fn tree_by_hand() -> DirectionTree {
        DirectionTree {
            nodes: vec![
                QuadNode {
                    sums: [6.0, 1.0, 1.0, 0.0],
                    children: [1, 0, 0, 0],
                },
                QuadNode {
                    sums: [3.0, 1.0, 1.0, 1.0],
                    children: [0; 4],
                },
            ],
        }
    }

    /// Points of [`tree_by_hand`], with their density worked out beforehand: a leaf's chance
    /// over its area (a sixteenth of the square below the root's first quadrant, a quarter
    /// elsewhere).
    const POINTS_BY_HAND: [(Vec2, f32); 4] = [
        // 3/8 over 1/16.
        (Vec2::new(0.1, 0.1), 6.0),
        // 1/8 over 1/16: the right half of the root's first quadrant.
        (Vec2::new(0.3, 0.1), 2.0),
        // 1/8 over 1/4.
        (Vec2::new(0.7, 0.2), 0.5),
        // Nothing recorded there.
        (Vec2::new(0.8, 0.8), 0.0),
    ];

    #[test]
    fn exercise_quadtree_pdf_of_a_tree_worked_out_by_hand() {
        let tree = tree_by_hand();
        let got: Vec<f32> = POINTS_BY_HAND.iter().map(|&(p, _)| tree.pdf(p)).collect();
        let quarter_pi = 0.25 * std::f32::consts::FRAC_1_PI;
        // What the usual mistakes give at the same points.
        let mistakes: [([f32; 3], &str); 5] = [
            (
                [0.375, 0.125, 0.125],
                "that is each leaf's chance, not its density: the chance is spread over the \
                 leaf's area, a quarter of its node's at every level",
            ),
            (
                [1.5, 0.5, 0.5],
                "the chance was spread over a quarter of the square whatever the leaf's depth: \
                 each level down quarters the area again",
            ),
            (
                [6.0 * quarter_pi, 2.0 * quarter_pi, 0.5 * quarter_pi],
                "that is a density per unit solid angle: pdf is the density on the unit square \
                 (directions::solid_angle_pdf turns it into one on the sphere)",
            ),
            (
                [8.0, 8.0 / 3.0, 0.5],
                "only the last node's share was counted: the chance of a leaf is the product of \
                 the shares of every quadrant on the way down",
            ),
            (
                [6.0, 6.0, 0.5],
                "the point was not rescaled into its quadrant before going down: below the \
                 root, (0.3, 0.1) is in the right half of the first quadrant",
            ),
        ];
        let why = mistakes
            .iter()
            .find(|(wrong, _)| {
                wrong
                    .iter()
                    .zip(&got)
                    .all(|(w, g)| (w - g).abs() < 1e-4 * w.abs().max(1.0))
            })
            .map_or(
                "what chance does the walk give the leaf, and over what area?",
                |m| m.1,
            );
        for (&(point, expected), got) in POINTS_BY_HAND.iter().zip(&got) {
            assert!(
                (got - expected).abs() < 1e-4 * expected.max(1.0),
                "pdf: at {point} a tree whose root holds 6, 1, 1, 0 and whose first quadrant \
                 is split into 3, 1, 1, 1 has density {expected}, not {got}: {why}"
            );
        }
        let empty = DirectionTree::new().pdf(Vec2::splat(0.3));
        assert!(
            empty == 0.0,
            "pdf: a tree with nothing recorded draws nothing, so its density is 0 everywhere, \
             not {empty}"
        );
    }

    #[test]
    fn exercise_quadtree_pdf_adds_up_to_one_over_the_square() {
        let tree = taught_tree();
        let n = 512;
        let mut integral = 0.0f64;
        for i in 0..n {
            for j in 0..n {
                let p = Vec2::new((i as f32 + 0.5) / n as f32, (j as f32 + 0.5) / n as f32);
                integral += f64::from(tree.pdf(p));
            }
        }
        integral /= (n * n) as f64;
        assert!(
            (integral - 1.0).abs() < 0.02,
            "pdf: the density integrates to {integral} over the unit square, not 1"
        );
        assert_eq!(DirectionTree::new().pdf(Vec2::splat(0.3)), 0.0);
    }

    /// The leaf of [`tree_by_hand`] that holds `p`: 0 to 3 the split quadrant's, 4 to 6 the
    /// root's other three.
    fn leaf_by_hand(p: Vec2) -> usize {
        let (q, inner) = quadrant_of(p);
        if q == 0 { quadrant_of(inner).0 } else { 3 + q }
    }

    #[test]
    fn exercise_quadtree_sample_follows_a_tree_worked_out_by_hand() {
        let tree = tree_by_hand();
        // Numbers u on a grid, so that each leaf's share is exact to a row of the grid.
        let n = 64;
        let mut points = Vec::new();
        for i in 0..n {
            for j in 0..n {
                let u = Vec2::new((i as f32 + 0.5) / n as f32, (j as f32 + 0.5) / n as f32);
                match tree.sample(u) {
                    Some(p) => points.push(p),
                    None => panic!("sample: the tree holds 10, yet sample({u}) drew nothing"),
                }
            }
        }
        if let Some(p) = points
            .iter()
            .find(|p| !(p.is_finite() && p.cmpge(Vec2::ZERO).all() && p.cmplt(Vec2::ONE).all()))
        {
            panic!(
                "sample: drew {p}, outside the unit square: is the point in the leaf scaled to \
                 the leaf's size and put at its corner?"
            );
        }
        let mut shares = [0.0f32; 7];
        for &p in &points {
            shares[leaf_by_hand(p)] += 1.0 / points.len() as f32;
        }
        let root = [shares[..4].iter().sum(), shares[4], shares[5], shares[6]];
        let near = |got: &[f32], expected: &[f32]| {
            got.iter().zip(expected).all(|(g, e)| (g - e).abs() < 0.01)
        };
        if root[3] > 0.0 {
            let why = if near(&root, &[0.25; 4]) {
                "the quadrants were drawn with equal chance, not in proportion to their sums"
            } else {
                "are the quadrants drawn in proportion to their sums, lower or upper by the sums \
                 of the column already chosen?"
            };
            panic!(
                "sample: the root's upper right quadrant holds nothing, yet it drew {:.3} of the \
                 points: {why}",
                root[3]
            );
        }
        assert!(
            near(&root, &[0.75, 0.125, 0.125, 0.0]),
            "sample: the root's quadrants hold 6, 1, 1, 0 and drew shares {root:.3?} of the \
             points, not 6/8, 1/8, 1/8, 0: is lower or upper chosen by the sums of the column \
             already chosen, and the number rescaled to [0, 1) within the part it fell in?"
        );
        let below: Vec<f32> = shares[..4].iter().map(|s| s / root[0]).collect();
        assert!(
            near(&below, &[0.5, 1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0]),
            "sample: the root's quadrants come out right, but below the first the quadrants \
             holding 3, 1, 1, 1 drew shares {below:.3?} of its points, not 3/6, 1/6, 1/6, 1/6: \
             was the 2D number rescaled to [0, 1) within the quadrant chosen before choosing \
             the next?"
        );
        // The leaf [0.5, 1) x [0, 0.5): its points spread evenly over a 4 x 4 grid of it.
        let mut cells = [0usize; 16];
        let mut in_leaf = 0;
        for p in points.iter().filter(|&&p| leaf_by_hand(p) == 4) {
            let cell = ((*p - Vec2::new(0.5, 0.0)) * 8.0)
                .as_uvec2()
                .min(glam::UVec2::splat(3));
            cells[(cell.y * 4 + cell.x) as usize] += 1;
            in_leaf += 1;
        }
        let even = in_leaf as f32 / 16.0;
        assert!(
            cells.iter().all(|&c| (c as f32 - even).abs() <= 0.2 * even),
            "sample: the {in_leaf} points in the leaf [0.5, 1) x [0, 0.5) are not spread evenly \
             over it (a 4 x 4 grid of it holds {cells:?}): what is left of the 2D number once \
             the leaf is chosen, rescaled to [0, 1), is the point in the leaf"
        );
    }

    #[test]
    fn exercise_quadtree_sample_draws_its_density() {
        let tree = taught_tree();
        // The χ² test integrates pdf over its bins, and a density that is not a number would
        // keep its integration refining: pdf's own check is the place to name that mistake.
        let n = 256;
        for i in 0..n * n {
            let p = Vec2::new(
                ((i % n) as f32 + 0.5) / n as f32,
                ((i / n) as f32 + 0.5) / n as f32,
            );
            let density = tree.pdf(p);
            assert!(
                density.is_finite(),
                "sample: pdf gives {density} at {p} of a tree that holds something, so the \
                 points drawn cannot be tested against it: check pdf first (exercise \
                 ch11-quadtree-pdf)"
            );
        }
        let result = chi2_test_density(
            plane(),
            200_000,
            3,
            (64, 64),
            |u| WarpPoint::Plane(tree.sample(u).unwrap_or(Vec2::splat(f32::NAN))),
            |point| match point {
                WarpPoint::Plane(p) => Some(tree.pdf(p)).filter(|d| d.is_finite()).unwrap_or(0.0),
                WarpPoint::Direction(_) => 0.0,
            },
        );
        assert!(
            result.p_value > 0.01,
            "sample: the points drawn do not follow the density pdf gives them: chi-square \
             {:.1} on {} degrees of freedom, p = {:.2e} ({} impossible samples)",
            result.statistic,
            result.dof,
            result.p_value,
            result.impossible_samples
        );
        assert_eq!(DirectionTree::new().sample(Vec2::splat(0.5)), None);
    }
}
