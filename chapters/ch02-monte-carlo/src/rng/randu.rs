//! RANDU, IBM's generator of the 1960s: a cautionary tale in one multiplication.
//!
//! RANDU is the linear congruential generator
//!
//! ```text
//! x_{k+1} = 65539 x_k  mod 2^31,        x_0 odd,
//! ```
//!
//! and its numbers are `x_k / 2^31`. It was chosen because `65539 = 2^16 + 3` makes the
//! multiplication a shift and two additions. That same choice ruins it. Squaring the multiplier,
//!
//! ```text
//! 65539^2 = (2^16 + 3)^2 = 2^32 + 6 * 2^16 + 9 ≡ 6 * 65539 - 9  (mod 2^31),
//! ```
//!
//! so every three consecutive outputs satisfy `x_{k+2} = 6 x_{k+1} - 9 x_k (mod 2^31)`. Divided
//! by `2^31`, `9 x - 6 y + z` is an *integer* for every triple `(x, y, z)`, and since each
//! coordinate lies in `[0, 1)` that integer is one of -5, ..., 9: all triples lie on just 15
//! parallel planes of the unit cube. A renderer that draws three numbers per sample (a pixel
//! position and a time, say) would see the planes as structured artefacts, not as noise.
//! [`super::randu_plane_index`] measures it.
//!
//! In one dimension RANDU looks fine: its numbers are spread evenly over `[0, 1)`, which is why
//! it survived for years. Evenness in 1D says nothing about independence of neighbours.

use std::convert::Infallible;

use rand::TryRng;
use rand::rand_core::utils::{fill_bytes_via_next_word, next_u64_via_u32};

/// RANDU's multiplier, `2^16 + 3`.
pub const RANDU_MULTIPLIER: u32 = 65_539;

/// Keeps the low 31 bits: reduction modulo `2^31` is a mask, the other "cheap" choice of RANDU.
const MOD_2_31_MASK: u32 = (1 << 31) - 1;

/// The state of RANDU: the last 31-bit output, always odd.
///
/// It implements rand's [`rand::Rng`] (through [`TryRng`] with an error that cannot happen),
/// so it can stand in for any other generator of this chapter. Each 32-bit word it hands out is
/// its 31-bit state shifted left by one: the high bits, which every conversion to a float reads,
/// carry the whole state, and `word / 2^32` is exactly RANDU's `x / 2^31`. The lowest bit of a
/// word is therefore always 0 (and the next one always 1, since the state is odd): never use
/// the low bits of an LCG.
///
/// Timing it times the step, not a function call: the optimised builds link with ThinLTO,
/// which inlines the step into code of another crate (the benchmark, a renderer), as rand's
/// generators get by marking theirs `#[inline]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Randu {
    state: u32,
}

impl Randu {
    /// RANDU started from `seed`, made odd (`seed | 1`) and reduced to 31 bits.
    ///
    /// An even state would lose a factor of two at every step and soon reach 0, where an LCG
    /// without increment stays forever; odd states keep the (already short) period of `2^29`.
    pub fn new(seed: u32) -> Self {
        Self {
            state: (seed | 1) & MOD_2_31_MASK,
        }
    }

    /// Advances one step and returns the new 31-bit state `x_{k+1}`.
    pub fn next_state(&mut self) -> u32 {
        self.state = self.state.wrapping_mul(RANDU_MULTIPLIER) & MOD_2_31_MASK;
        self.state
    }
}

impl TryRng for Randu {
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
    use rand::Rng;

    #[test]
    fn follows_the_published_sequence() {
        // The first values from x_0 = 1, as listed in the literature on RANDU.
        let mut randu = Randu::new(1);
        let states: Vec<u32> = (0..5).map(|_| randu.next_state()).collect();
        assert_eq!(states, [65_539, 393_225, 1_769_499, 7_077_969, 26_542_323]);
    }

    #[test]
    fn seeds_are_made_odd_and_states_stay_odd() {
        assert_eq!(Randu::new(0), Randu::new(1));
        assert_eq!(Randu::new(6), Randu::new(7));
        let mut randu = Randu::new(u32::MAX);
        for _ in 0..1000 {
            let state = randu.next_state();
            assert_eq!(state % 2, 1);
            assert!(state < 1 << 31);
        }
    }

    #[test]
    fn words_are_the_state_shifted_into_the_high_bits() {
        let mut words = Randu::new(12_345);
        let mut states = Randu::new(12_345);
        for _ in 0..100 {
            assert_eq!(words.next_u32(), states.next_state() << 1);
        }
    }

    #[test]
    fn consecutive_states_obey_the_three_term_recurrence() {
        let mut randu = Randu::new(987_654_321);
        let (mut x, mut y) = (randu.next_state(), randu.next_state());
        for _ in 0..1000 {
            let z = randu.next_state();
            let predicted = 6u32.wrapping_mul(y).wrapping_sub(9u32.wrapping_mul(x)) & MOD_2_31_MASK;
            assert_eq!(z, predicted);
            (x, y) = (y, z);
        }
    }
}
