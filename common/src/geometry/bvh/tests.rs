//! The shape of the tree: every primitive in exactly one small leaf, every box containing what
//! is below it, bounded depth whatever the input.

use glam::Vec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg32;

use super::build::MAX_DEPTH;
use super::traverse::{SHALLOW_STACK, stack_needed};
use super::*;
use crate::Ray;

/// Checks the invariants of the subtree of the node at `index`, whose box is `bounds`;
/// returns the primitives below it.
fn check_subtree(bvh: &Bvh, boxes: &[Aabb], index: usize, bounds: Aabb, depth: usize) -> Vec<u32> {
    assert!(depth <= bvh.depth());
    let node = bvh.nodes[index];
    let mut below = Vec::new();
    let mut children = 0;
    for lane in 0..wide::WIDTH {
        let child_bounds = node.bounds(lane);
        match node.child(lane) {
            None => {
                assert!(
                    child_bounds.is_empty(),
                    "a lane without a child has an empty box"
                );
                continue;
            }
            Some(_) => assert!(bounds.contains_box(&child_bounds)),
        }
        children += 1;
        match node.child(lane).unwrap() {
            wide::Child::Leaf { first, count } => {
                assert!((1..=MAX_PRIMITIVES_PER_LEAF as u32).contains(&count));
                assert_eq!(first as usize % LEAF_BLOCK, 0, "a leaf starts a block");
                let block_end = (first as usize + LEAF_BLOCK).min(bvh.primitive_indices.len());
                assert!(
                    bvh.primitive_indices[(first + count) as usize..block_end]
                        .iter()
                        .all(|&slot| slot == EMPTY_SLOT),
                    "the rest of a leaf's block is empty"
                );
                let primitives = &bvh.primitive_indices[first as usize..(first + count) as usize];
                for &p in primitives {
                    assert!(child_bounds.contains_box(&boxes[p as usize]));
                }
                below.extend_from_slice(primitives);
            }
            wide::Child::Node(child) => {
                assert!(child as usize > index, "children come after their parent");
                below.extend(check_subtree(
                    bvh,
                    boxes,
                    child as usize,
                    child_bounds,
                    depth + 1,
                ));
            }
        }
    }
    assert!(children >= 1, "node {index} has no child");
    below
}

/// Builds a BVH and checks that it is a well-formed tree holding every non-empty box once.
fn build_and_check(boxes: &[Aabb]) -> Bvh {
    let bvh = Bvh::build(boxes);
    assert!(bvh.depth() <= MAX_DEPTH);
    let mut held = if bvh.node_count() == 0 {
        Vec::new()
    } else {
        check_subtree(&bvh, boxes, 0, bvh.bounds(), 1)
    };
    held.sort_unstable();
    let occupied = bvh
        .leaf_order()
        .iter()
        .filter(|&&i| i != EMPTY_SLOT)
        .count();
    assert_eq!(
        occupied,
        held.len(),
        "every position outside a leaf is an empty slot"
    );
    let expected: Vec<u32> = (0..boxes.len() as u32)
        .filter(|&i| !boxes[i as usize].is_empty())
        .collect();
    assert_eq!(held, expected);
    bvh
}

fn cube_at(center: Vec3, half_size: f32) -> Aabb {
    Aabb::from_points(center - half_size, center + half_size)
}

#[test]
fn no_boxes_and_one_box() {
    let empty = build_and_check(&[]);
    assert_eq!((empty.node_count(), empty.depth()), (0, 0));
    assert!(empty.bounds().is_empty());
    let ray = Ray::new(Vec3::ZERO, Vec3::X);
    assert_eq!(empty.intersect(&ray, |_, _| Some(1.0)), None);
    assert!(!empty.any_hit(&ray, |_| true));

    let one = build_and_check(&[cube_at(Vec3::X * 3.0, 1.0)]);
    assert_eq!((one.node_count(), one.depth()), (1, 1));
    let hit = one.intersect(&ray, |i, _| (i == 0).then_some(2.0));
    assert_eq!(
        hit,
        Some(BvhHit {
            primitive: 0,
            t: 2.0
        })
    );
}

#[test]
fn random_boxes_make_a_shallow_tree() {
    let mut rng = Pcg32::seed_from_u64(1);
    let boxes: Vec<Aabb> = (0..1000)
        .map(|_| {
            let c = Vec3::new(rng.random(), rng.random(), rng.random()) * 100.0;
            cube_at(c, rng.random_range(0.1..2.0))
        })
        .collect();
    let bvh = build_and_check(&boxes);
    assert!(bvh.depth() < 30, "depth {}", bvh.depth());
    assert!(bvh.node_count() < 2 * boxes.len());

    // Collapsing into nodes of four keeps the leaves and roughly halves the depth: up to three
    // binary inner nodes fit in one wide node (fewer near the leaves, where a subtree may
    // hold only two or three leaves).
    let binary = build::BinaryTree::build(&boxes, &[]);
    let leaves = |kind: &build::NodeKind| matches!(kind, build::NodeKind::Leaf { .. });
    let binary_inner = binary.nodes.iter().filter(|n| !leaves(&n.kind)).count();
    assert!(
        2 * bvh.node_count() <= binary_inner,
        "{} wide nodes for {binary_inner} binary inner nodes",
        bvh.node_count()
    );
    assert!(
        bvh.depth() <= binary.depth / 2 + 1,
        "depth {} from a binary depth of {}",
        bvh.depth(),
        binary.depth
    );
}

#[test]
fn degenerate_inputs_do_not_break_the_build() {
    let p = Vec3::new(1.0, 2.0, 3.0);
    let point = Aabb::from_points(p, p);
    let flat = Aabb::from_points(p, p + Vec3::new(1.0, 0.0, 1.0));
    build_and_check(&vec![point; 100]);
    build_and_check(&vec![flat; 100]);
    // Zero-size boxes along a line: the surface area of every node is zero.
    let on_a_line: Vec<Aabb> = (0..100).map(|k| cube_at(Vec3::X * k as f32, 0.0)).collect();
    build_and_check(&on_a_line);
    // Empty and NaN boxes are left out.
    let nan = Aabb {
        min: Vec3::NAN,
        max: Vec3::ONE,
    };
    let bvh = build_and_check(&[point, Aabb::empty(), nan, flat]);
    let held: Vec<u32> = bvh
        .leaf_order()
        .iter()
        .copied()
        .filter(|&i| i != EMPTY_SLOT)
        .collect();
    assert_eq!(held.len(), 2);
}

#[test]
fn exponentially_spaced_boxes_cannot_make_the_tree_too_deep() {
    // The SAH splits off one box at a time here; the depth limit must kick in.
    let boxes: Vec<Aabb> = (0..120)
        .map(|k| cube_at(Vec3::X * 1.3f32.powi(k), 0.5))
        .collect();
    let bvh = build_and_check(&boxes);
    assert!(bvh.depth() <= MAX_DEPTH);
}

/// A ray parallel to a face, starting in that face's plane, computes `0 × ∞` for that axis:
/// the walk must count it as inside the slab, whichever axis it is, and not lose the box.
#[test]
fn rays_along_a_face_find_the_box() {
    let boxes: Vec<Aabb> = (0..9)
        .map(|k| cube_at(Vec3::new(0.5 + 3.0 * k as f32, 0.5, 0.5), 0.5))
        .collect();
    let bvh = Bvh::build(&boxes);
    for axis in 0..3 {
        for side in [0.0, 1.0] {
            // Along the next axis, from outside the unit cube, in its face `axis = side`.
            let along = (axis + 1) % 3;
            let mut origin = Vec3::splat(0.5);
            origin[axis] = side;
            origin[along] = -1.0;
            let mut dir = Vec3::ZERO;
            dir[along] = 1.0;
            let ray = Ray::new(origin, dir);
            assert!(
                bvh.any_hit(&ray, |k| k == 0),
                "axis {axis}, side {side}: the cube was lost"
            );
            let nearest = bvh.intersect(&ray, |k, _| (k == 0).then_some(1.0));
            assert_eq!(nearest.map(|hit| hit.primitive), Some(0), "axis {axis}");
        }
    }
}

/// A ray that enters every box of a row fills the walk's stack as far as it goes: at each
/// level three children wait, and the deepest node puts all four of its children on the stack
/// at once. Trees of every depth are walked whole, on whichever stack their depth picks.
#[test]
fn rays_entering_every_box_are_walked_whole() {
    for count in [2, 5, 8, 16, 17, 64, 65, 300] {
        let boxes: Vec<Aabb> = (0..count)
            .map(|k| cube_at(Vec3::X * 2.0 * k as f32, 0.5))
            .collect();
        let bvh = Bvh::build(&boxes);
        let ray = Ray::new(Vec3::new(-1.0, 0.0, 0.0), Vec3::X);
        let mut visited = vec![0; count];
        assert!(!bvh.any_hit(&ray, |k| {
            visited[k] += 1;
            false
        }));
        assert!(
            visited.iter().all(|&n| n == 1),
            "{count} boxes: {visited:?}"
        );
        let mut visited = vec![0; count];
        let nearest = bvh.intersect(&ray, |k, _| {
            visited[k] += 1;
            None
        });
        assert_eq!(nearest, None);
        assert!(
            visited.iter().all(|&n| n == 1),
            "{count} boxes: {visited:?}"
        );
    }
}

/// A tree deeper than the short stack of shallow trees is walked with the long one: every
/// box along the ray is visited once, whichever end the ray starts from, and nothing
/// overflows.
#[test]
fn deep_trees_are_walked_whole() {
    let boxes: Vec<Aabb> = (0..120)
        .map(|k| cube_at(Vec3::X * 1.3f32.powi(k), 0.5))
        .collect();
    let bvh = Bvh::build(&boxes);
    assert!(
        stack_needed(bvh.depth()) > SHALLOW_STACK,
        "depth {}",
        bvh.depth()
    );
    for (origin, dir) in [(-1.0, Vec3::X), (1e15, -Vec3::X)] {
        let ray = Ray::new(Vec3::new(origin, 0.0, 0.0), dir);
        let mut visited = vec![0; boxes.len()];
        assert!(!bvh.any_hit(&ray, |k| {
            visited[k] += 1;
            false
        }));
        assert!(visited.iter().all(|&n| n == 1), "{visited:?}");
        let nearest = bvh.intersect(&ray, |k, _| Some((1.3f32.powi(k as i32) - origin).abs()));
        let expected = if dir.x > 0.0 { 0 } else { 119 };
        assert_eq!(nearest.map(|hit| hit.primitive), Some(expected));
    }
}

#[test]
fn intersect_keeps_the_nearest_and_ignores_answers_beyond_t_max() {
    let boxes: Vec<Aabb> = (0..50).map(|k| cube_at(Vec3::X * k as f32, 0.4)).collect();
    let bvh = Bvh::build(&boxes);
    let ray = Ray::new(Vec3::new(-1.0, 0.0, 0.0), Vec3::X);
    // Primitive k is "hit" at its distance from the origin, except that 10 lies about being
    // beyond t_max and 3 answers NaN.
    let hit = bvh.intersect(&ray, |k, t_max| match k {
        10 => Some(t_max),
        3 => Some(f32::NAN),
        _ => Some(k as f32 + 0.6),
    });
    assert_eq!(
        hit,
        Some(BvhHit {
            primitive: 0,
            t: 0.6
        })
    );
    let hit = bvh.intersect(&ray, |k, _| (k >= 20).then_some(k as f32 + 0.6));
    assert_eq!(
        hit,
        Some(BvhHit {
            primitive: 20,
            t: 20.6
        })
    );
}

#[test]
fn near_children_first_culls_most_of_the_tree() {
    let boxes: Vec<Aabb> = (0..256).map(|k| cube_at(Vec3::X * k as f32, 0.4)).collect();
    let bvh = Bvh::build(&boxes);
    for (origin, dir) in [(-1.0, Vec3::X), (300.0, -Vec3::X)] {
        let ray = Ray::new(Vec3::new(origin, 0.0, 0.0), dir);
        let mut tested = 0;
        let hit = bvh.intersect(&ray, |k, _| {
            tested += 1;
            Some((k as f32 - origin).abs() - 0.4)
        });
        let expected = if dir.x > 0.0 { 0 } else { 255 };
        assert_eq!(hit.unwrap().primitive, expected);
        assert!(
            tested <= 2 * MAX_PRIMITIVES_PER_LEAF,
            "tested {tested} primitives"
        );
    }
}

#[test]
fn any_hit_stops_at_the_first_hit() {
    let boxes: Vec<Aabb> = (0..100).map(|k| cube_at(Vec3::X * k as f32, 0.4)).collect();
    let bvh = Bvh::build(&boxes);
    let ray = Ray::new(Vec3::new(-1.0, 0.0, 0.0), Vec3::X);
    let mut tested = 0;
    assert!(bvh.any_hit(&ray, |_| {
        tested += 1;
        true
    }));
    assert_eq!(tested, 1);
    assert!(!bvh.any_hit(&ray, |_| false));
    let short = Ray { t_max: 0.5, ..ray };
    assert!(
        !bvh.any_hit(&short, |_| true),
        "boxes beyond t_max are not visited"
    );
}
