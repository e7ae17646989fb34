//! How fast is each generator? A rough stopwatch measurement for the chapter's table.
//!
//! The benchmark `benches/generators.rs` measures the same thing carefully (many runs, with
//! statistics); this function gives one number per generator for a figure or a CSV file,
//! from a program that has other things to do. Like every timing it depends on the machine
//! and on what else runs on it; compare generators measured in the same run only.
//!
//! It also depends on how the numbers are used. Here they are summed, which lets the compiler
//! run several steps of a linear congruential generator at once (`x_{k+2} = a² x_k`): RANDU
//! then makes billions of numbers per second, several times more than PCG32. When each number
//! is used on its own, one step after the other, RANDU loses that lead (see the benchmark's
//! `words` against its `summed_words`).

use std::hint::black_box;
use std::time::Instant;

use rand::{Rng, SeedableRng};
use rand_mt::Mt;
use rand_pcg::Pcg32;

use super::{Generator, Minstd, Randu};

/// Seed of the timed generators: any seed does, speed does not depend on it.
const TIMING_SEED: u32 = 0x5eed;

/// Draws `count` 32-bit numbers from `generator` and returns how many it draws per second.
///
/// Each generator is timed as its own concrete type, not through [`super::Source`], so that
/// the measurement is of the generator and not of the dispatch around it. The numbers are
/// summed and the sum passed through [`black_box`], so the compiler cannot skip the work.
pub fn numbers_per_second(generator: Generator, count: u64) -> f64 {
    match generator {
        Generator::Randu => time_draws(Randu::new(TIMING_SEED), count),
        Generator::Minstd => time_draws(Minstd::new(TIMING_SEED), count),
        Generator::Mt19937 => time_draws(Mt::new(TIMING_SEED), count),
        Generator::Pcg32 => time_draws(Pcg32::seed_from_u64(u64::from(TIMING_SEED)), count),
    }
}

/// Numbers per second of `count` draws from `rng`.
fn time_draws(mut rng: impl Rng, count: u64) -> f64 {
    let start = Instant::now();
    let mut sum = 0u32;
    for _ in 0..count {
        sum = sum.wrapping_add(rng.next_u32());
    }
    black_box(sum);
    let seconds = start.elapsed().as_secs_f64();
    // A clock too coarse to see the work (tiny counts) still gives a finite answer.
    count as f64 / seconds.max(1e-9)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_generator_reports_a_positive_finite_rate() {
        // Only the form of the answer is tested: times depend on the machine.
        for generator in Generator::ALL {
            let rate = numbers_per_second(generator, 10_000);
            assert!(rate.is_finite() && rate > 0.0, "{generator}: {rate}");
        }
    }
}
