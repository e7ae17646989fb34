//! Random numbers, and the trade-off between how fast and how *even* they are.
//!
//! Monte Carlo integration is only as good as its random numbers. This module collects four
//! generators ([`Generator`]) from a broken one to a modern one, and the tests that tell them
//! apart:
//!
//! | question | tool |
//! |---|---|
//! | are single numbers spread evenly? | [`uniformity_chi2`] |
//! | are consecutive triples spread evenly? | [`triples_chi2`] and [`serial_chi2_3d`] (coarse), [`randu_plane_index`] (sharp) |
//! | how fast? | [`numbers_per_second`], and the benchmark `benches/generators.rs` |
//!
//! All generators implement rand's [`rand::Rng`] trait; a number in `[0, 1)` is made from a
//! 32-bit word by `common::sampler::unit_f32` (24 bits, for rendering) or by [`unit_f64`]
//! (all 32 bits, for tests that must see every bit).

mod generator;
mod lattice;
mod minstd;
mod randu;
mod speed;
mod uniformity;

pub use generator::{Generator, Source};
pub use lattice::{consecutive_triples, fraction_on_randu_planes, randu_plane_index};
pub use minstd::{MINSTD_MODULUS, MINSTD_MULTIPLIER, Minstd};
pub use randu::{RANDU_MULTIPLIER, Randu};
pub use speed::numbers_per_second;
pub use uniformity::{
    ChiSquareOutcome, serial_chi2_3d, serial_threshold, triples_chi2, uniformity_chi2,
};

/// Maps a 32-bit word to `word / 2^32` in `[0, 1)`, keeping all 32 bits.
///
/// Every such value is exact in an `f64`. RANDU's and MINSTD's words are their 31-bit states
/// shifted left by one, so this gives exactly their textbook numbers `x / 2^31`.
pub fn unit_f64(word: u32) -> f64 {
    f64::from(word) / 4_294_967_296.0
}
