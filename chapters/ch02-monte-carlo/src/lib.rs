//! # Chapter 02: Monte Carlo integration and stochastic sampling
//!
//! The lecture's "very short intro" to stochastic sampling, and the statistical backbone of
//! every later chapter: the Monte Carlo estimator, the random numbers it eats, the warps that
//! turn uniform numbers into points on discs, triangles and spheres with a known density, and
//! the chi-square test that proves a warp delivers the density it claims.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod chi2;
pub mod estimator;
pub mod rng;
pub mod samples;
pub mod stratified;
pub mod warps;

#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;
