//! MINSTD, Park and Miller's "minimal standard" generator (1988): a decent classic LCG.
//!
//! ```text
//! x_{k+1} = 16807 x_k  mod (2^31 - 1),       1 <= x_0 < 2^31 - 1.
//! ```
//!
//! Two choices make it respectable where RANDU is not. The modulus `2^31 - 1` is prime, so
//! every state from 1 to `2^31 - 2` lies on one cycle (the full period), and no bit of the
//! output is simpler than the others, unlike the low bits of a power-of-two modulus. And the
//! multiplier 16807 = 7^5 was chosen because its lattice passes the spectral test: triples
//! still lie on planes (every LCG's do, by Marsaglia's theorem) but on thousands of closely
//! spaced ones, not on 15.
//!
//! Its limits show today: a period of only `2^31` (a 4K image at 256 samples per pixel
//! draws more numbers than that), 31 bits of resolution, and a modulo per number.

use std::convert::Infallible;

use rand::TryRng;
use rand::rand_core::utils::{fill_bytes_via_next_word, next_u64_via_u32};

/// MINSTD's multiplier, `7^5`.
pub const MINSTD_MULTIPLIER: u64 = 16_807;

/// MINSTD's modulus, the Mersenne prime `2^31 - 1`.
pub const MINSTD_MODULUS: u64 = (1 << 31) - 1;

/// The state of MINSTD: the last output, in `1..2^31 - 1`.
///
/// Like [`super::Randu`] it implements rand's [`rand::Rng`] and hands out its 31-bit state
/// shifted into the high bits of a 32-bit word, so `word / 2^32 = x / 2^31`. (Park and Miller
/// divide by `2^31 - 1` instead; the two differ by less than one part in `2^31`.)
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Minstd {
    state: u32,
}

impl Minstd {
    /// MINSTD started from `seed` reduced modulo `2^31 - 1`; a seed that reduces to 0 becomes 1.
    ///
    /// 0 is the one state a multiplicative generator can never leave, so it is not allowed.
    pub fn new(seed: u32) -> Self {
        let state = (u64::from(seed) % MINSTD_MODULUS) as u32;
        Self {
            state: state.max(1),
        }
    }

    /// Advances one step and returns the new state `x_{k+1}`.
    ///
    /// The product of a 31-bit state and 16807 needs 46 bits, so it is formed in 64-bit
    /// arithmetic. (In the 1980s, without 64-bit integers, Schrage's method did the same with
    /// 32-bit operations.)
    pub fn next_state(&mut self) -> u32 {
        self.state = (u64::from(self.state) * MINSTD_MULTIPLIER % MINSTD_MODULUS) as u32;
        self.state
    }
}

impl TryRng for Minstd {
    type Error = Infallible;

    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        Ok(self.next_state() << 1)
    }

    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        next_u64_via_u32(self)
    }

    fn try_fill_bytes(&mut self, destination: &mut [u8]) -> Result<(), Infallible> {
        fill_bytes_via_next_word(destination, || self.try_next_u32())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn passes_park_and_millers_check() {
        // Park and Miller's published check: from x_0 = 1, x_10000 = 1043618065.
        let mut minstd = Minstd::new(1);
        let last = (0..10_000).map(|_| minstd.next_state()).last();
        assert_eq!(last, Some(1_043_618_065));
    }

    #[test]
    fn forbidden_seeds_are_replaced() {
        assert_eq!(Minstd::new(0), Minstd::new(1));
        assert_eq!(Minstd::new((1 << 31) - 1), Minstd::new(1));
        let mut minstd = Minstd::new(u32::MAX);
        for _ in 0..1000 {
            let state = u64::from(minstd.next_state());
            assert!((1..MINSTD_MODULUS).contains(&state));
        }
    }
}
