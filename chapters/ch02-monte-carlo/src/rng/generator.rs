//! The four generators of the chapter, by name, behind one type.
//!
//! Two historical linear congruential generators and two modern ones, chosen to show the whole
//! range: [`Generator::Randu`] (fast and broken), [`Generator::Minstd`] (the classic decent
//! LCG), [`Generator::Mt19937`] (the Mersenne Twister, the default of many libraries for
//! two decades) and [`Generator::Pcg32`] (what the renderer uses: small, fast, statistically
//! excellent).

use std::convert::Infallible;
use std::fmt;

use rand::{SeedableRng, TryRng};
use rand_mt::Mt;
use rand_pcg::Pcg32;

use super::{Minstd, Randu};

/// Which random number generator: a name for the command line, figures and tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum Generator {
    /// IBM's RANDU: `x <- 65539 x mod 2^31`. Its triples lie on 15 planes.
    #[cfg_attr(feature = "lab", value(name = "randu"))]
    Randu,
    /// Park and Miller's MINSTD: `x <- 16807 x mod (2^31 - 1)`.
    #[cfg_attr(feature = "lab", value(name = "minstd"))]
    Minstd,
    /// The 32-bit Mersenne Twister, MT19937.
    #[cfg_attr(feature = "lab", value(name = "mt19937"))]
    Mt19937,
    /// O'Neill's PCG32 (XSH RR output on a 64-bit LCG), as in the renderer's sampler.
    #[cfg_attr(feature = "lab", value(name = "pcg32"))]
    Pcg32,
}

impl Generator {
    /// Every generator, from the oldest to the newest.
    pub const ALL: [Generator; 4] = [
        Generator::Randu,
        Generator::Minstd,
        Generator::Mt19937,
        Generator::Pcg32,
    ];

    /// The generator's name in lower case, as typed on the command line: `randu`, `minstd`,
    /// `mt19937` or `pcg32`.
    pub fn name(self) -> &'static str {
        match self {
            Generator::Randu => "randu",
            Generator::Minstd => "minstd",
            Generator::Mt19937 => "mt19937",
            Generator::Pcg32 => "pcg32",
        }
    }

    /// A generator of this kind started from `seed`.
    ///
    /// The three 32-bit-state generators take the seed folded to 32 bits (`seed ^ seed >> 32`),
    /// so the classic test values hold: MT19937 seeded with 5489 starts with 3499211612, RANDU
    /// seeded with 1 with 65539. PCG32 takes all 64 bits through rand's `seed_from_u64`.
    pub fn new_source(self, seed: u64) -> Source {
        let seed_32 = (seed ^ (seed >> 32)) as u32;
        match self {
            Generator::Randu => Source::Randu(Randu::new(seed_32)),
            Generator::Minstd => Source::Minstd(Minstd::new(seed_32)),
            Generator::Mt19937 => Source::Mt19937(Box::new(Mt::new(seed_32))),
            Generator::Pcg32 => Source::Pcg32(Pcg32::seed_from_u64(seed)),
        }
    }
}

impl fmt::Display for Generator {
    fn fmt(&self, formatter: &mut fmt::Formatter<'_>) -> fmt::Result {
        formatter.write_str(self.name())
    }
}

/// A running generator of any of the four kinds: enum dispatch, as for the renderer's shapes.
///
/// It implements rand's [`rand::Rng`], so code that asks for `&mut impl Rng` takes any of them.
/// We use rand's trait rather than one of our own because implementing it for our two LCGs
/// costs three short functions each, and in exchange every generator works with everything
/// that accepts a random number generator.
///
/// The Mersenne Twister is boxed: its state is 2.5 KB, the others' 4 to 16 bytes.
#[derive(Clone, Debug)]
pub enum Source {
    /// RANDU's state.
    Randu(Randu),
    /// MINSTD's state.
    Minstd(Minstd),
    /// The Mersenne Twister's state of 624 words.
    Mt19937(Box<Mt>),
    /// PCG32's state and stream.
    Pcg32(Pcg32),
}

impl TryRng for Source {
    type Error = Infallible;

    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        match self {
            Source::Randu(rng) => rng.try_next_u32(),
            Source::Minstd(rng) => rng.try_next_u32(),
            Source::Mt19937(rng) => Ok(rng.next_u32()),
            Source::Pcg32(rng) => rng.try_next_u32(),
        }
    }

    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        match self {
            Source::Randu(rng) => rng.try_next_u64(),
            Source::Minstd(rng) => rng.try_next_u64(),
            Source::Mt19937(rng) => Ok(rng.next_u64()),
            Source::Pcg32(rng) => rng.try_next_u64(),
        }
    }

    fn try_fill_bytes(&mut self, destination: &mut [u8]) -> Result<(), Infallible> {
        match self {
            Source::Randu(rng) => rng.try_fill_bytes(destination),
            Source::Minstd(rng) => rng.try_fill_bytes(destination),
            Source::Mt19937(rng) => {
                rng.fill_bytes(destination);
                Ok(())
            }
            Source::Pcg32(rng) => rng.try_fill_bytes(destination),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(feature = "lab")]
    use clap::ValueEnum;
    use rand::Rng;

    #[test]
    #[cfg(feature = "lab")]
    fn names_round_trip_through_the_command_line_parser() {
        for generator in Generator::ALL {
            assert_eq!(
                Generator::from_str(generator.name(), false),
                Ok(generator),
                "{generator}"
            );
            assert_eq!(generator.to_string(), generator.name());
        }
    }

    #[test]
    fn known_first_outputs() {
        // MT19937's reference output for its default seed 5489.
        assert_eq!(
            Generator::Mt19937.new_source(5489).next_u32(),
            3_499_211_612
        );
        // RANDU's first state from 1, in the high 31 bits of the word.
        assert_eq!(Generator::Randu.new_source(1).next_u32(), 65_539 << 1);
        // MINSTD's first state from 1 is the multiplier.
        assert_eq!(Generator::Minstd.new_source(1).next_u32(), 16_807 << 1);
    }

    #[test]
    fn equal_seeds_repeat_and_different_seeds_differ() {
        for generator in Generator::ALL {
            let numbers = |seed| -> Vec<u32> {
                let mut s = generator.new_source(seed);
                (0..8).map(|_| s.next_u32()).collect()
            };
            assert_eq!(numbers(42), numbers(42), "{generator}");
            // (Not 42 and 43: RANDU makes every seed odd, so those two are the same seed.)
            assert_ne!(numbers(42), numbers(1000), "{generator}");
        }
    }
}
