//! How many random numbers per second does each generator of the chapter make?
//!
//! Run with `cargo bench -p ch02-monte-carlo --bench generators`. Divan reports the time of one
//! batch of [`BATCH`] numbers and, thanks to the items counter, the throughput in numbers per
//! second. Each generator runs as its own concrete type, so the loop measures the generator
//! and not an enum dispatch around it.
//!
//! Three ways of consuming the numbers, because the answer depends on it:
//! - `words`: every 32-bit word escapes on its own (through [`black_box`]), so each step must
//!   finish before the next starts. This measures the *latency* of one step, as a renderer sees
//!   it when it draws a number here and there.
//! - `floats`: the same for floats in `[0, 1)`, as the renderer consumes them; the conversion
//!   is a shift and a multiplication, nearly free.
//! - `summed_words`: the words are only summed. Now the compiler may reorganise the loop, and
//!   for an LCG it can: `x_{k+2} = a² x_k`, so it unrolls the loop into independent chains
//!   with jump-ahead multipliers. RANDU, a single 32-bit multiplication per step, becomes by
//!   far the fastest, which is exactly the speed that made it popular.

use std::hint::black_box;

use ch02_monte_carlo::rng::{Generator, Minstd, Randu};
use common::sampler::unit_f32;
use divan::Bencher;
use divan::counter::ItemsCount;
use rand::{Rng, SeedableRng};
use rand_mt::Mt;
use rand_pcg::Pcg32;

fn main() {
    divan::main();
}

/// Numbers drawn per measured batch: enough to hide the cost of starting the clock.
const BATCH: usize = 4096;

/// Any seed will do: speed does not depend on it.
const SEED: u32 = 0x5eed;

/// 32-bit words per second.
#[divan::bench(args = Generator::ALL)]
fn words(bencher: Bencher, generator: Generator) {
    match generator {
        Generator::Randu => bench_words(bencher, Randu::new(SEED)),
        Generator::Minstd => bench_words(bencher, Minstd::new(SEED)),
        Generator::Mt19937 => bench_words(bencher, Mt::new(SEED)),
        Generator::Pcg32 => bench_words(bencher, Pcg32::seed_from_u64(u64::from(SEED))),
    }
}

/// Floats in `[0, 1)` per second.
#[divan::bench(args = Generator::ALL)]
fn floats(bencher: Bencher, generator: Generator) {
    match generator {
        Generator::Randu => bench_floats(bencher, Randu::new(SEED)),
        Generator::Minstd => bench_floats(bencher, Minstd::new(SEED)),
        Generator::Mt19937 => bench_floats(bencher, Mt::new(SEED)),
        Generator::Pcg32 => bench_floats(bencher, Pcg32::seed_from_u64(u64::from(SEED))),
    }
}

/// Sums of 32-bit words per second: throughput when the compiler may interleave steps.
#[divan::bench(args = Generator::ALL)]
fn summed_words(bencher: Bencher, generator: Generator) {
    match generator {
        Generator::Randu => bench_summed_words(bencher, Randu::new(SEED)),
        Generator::Minstd => bench_summed_words(bencher, Minstd::new(SEED)),
        Generator::Mt19937 => bench_summed_words(bencher, Mt::new(SEED)),
        Generator::Pcg32 => bench_summed_words(bencher, Pcg32::seed_from_u64(u64::from(SEED))),
    }
}

/// Times batches of [`BATCH`] words from `rng`, each passed through [`black_box`].
fn bench_words(bencher: Bencher, mut rng: impl Rng) {
    bencher.counter(ItemsCount::new(BATCH)).bench_local(|| {
        for _ in 0..BATCH {
            black_box(rng.next_u32());
        }
    });
}

/// Times batches of [`BATCH`] floats from `rng`, each passed through [`black_box`].
fn bench_floats(bencher: Bencher, mut rng: impl Rng) {
    bencher.counter(ItemsCount::new(BATCH)).bench_local(|| {
        for _ in 0..BATCH {
            black_box(unit_f32(rng.next_u32()));
        }
    });
}

/// Times batches of [`BATCH`] words from `rng`, summed; only the sum escapes (divan passes the
/// closure's result through [`black_box`]).
fn bench_summed_words(bencher: Bencher, mut rng: impl Rng) {
    bencher.counter(ItemsCount::new(BATCH)).bench_local(|| {
        let mut sum = 0u32;
        for _ in 0..BATCH {
            sum = sum.wrapping_add(rng.next_u32());
        }
        sum
    });
}
