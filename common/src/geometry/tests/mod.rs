//! Tests of the module as a whole: the robustness promises of `spawn.rs` and the BVH's promise
//! to find exactly what a brute-force search would.

mod bvh_matches_brute_force;
mod light_leaks;
mod non_finite_rays;
mod self_intersection;
mod support;
mod watertight;
