//! Sobol points, Owen-scrambled: low discrepancy in every dimension, at any sample count.
//!
//! The first two dimensions of Sobol's sequence form a *(0, 2)-sequence* in base 2: every
//! aligned block of `2^k` consecutive points puts exactly one point into every box of area
//! `2^-k` whose sides are powers of two, wide and flat, square or tall alike. That is
//! stratification in the grid, in each axis and in every shape between at once, for every
//! power-of-two prefix, without fixing the count in advance as a grid must. Its first
//! coordinate is the radical inverse in base 2 (the Halton sequence's); its second comes from
//! the same bits through another generator matrix.
//!
//! Used as they are, the points would be the same in every pixel and every dimension. *Owen
//! scrambling* randomises them while keeping the boxes: it flips each binary digit of a
//! coordinate with a coin chosen by the digits before it, so a point moves within every box
//! it occupies, at every scale. Burley's hashed form ("Practical Hash-based Owen Scrambling",
//! 2020) does it with a few multiplications keyed by a hash. Scrambling the *index* the same
//! way shuffles which point each sample takes, so that each dimension of a pixel draws its own
//! block of the sequence: the dimensions are as unrelated as the stratified sampler's shuffled
//! strata, and each is still a (0, 2)-net over the pixel's first `2^k` samples.

use super::dimension_keys::DimensionKeys;
use common::sampler::{Sampler, mix, unit_f32};
use glam::{UVec2, Vec2};

// ANCHOR: sobol_2d
/// Point `index` of the first two dimensions of Sobol's sequence, as 32-bit fractions (the
/// value `bits / 2^32`): the radical inverse of `index` in base 2, and the same bits through
/// the generator matrix of Sobol's second dimension (Pascal's triangle modulo 2).
pub fn sobol_2d(index: u32) -> (u32, u32) {
    let first = index.reverse_bits();
    let mut second = 0u32;
    let mut column = 1u32 << 31;
    let mut bits = index;
    while bits != 0 {
        if bits & 1 == 1 {
            second ^= column;
        }
        bits >>= 1;
        column ^= column >> 1;
    }
    (first, second)
}
// ANCHOR_END: sobol_2d

// ANCHOR: owen_scramble
/// The 32-bit fraction `bits` (the value `bits / 2^32`) Owen-scrambled by `seed`: each binary
/// digit flipped or not by a coin that depends on the digits before it (and the seed) only,
/// with Burley's hash of Laine and Karras's form.
pub fn owen_scramble(bits: u32, seed: u32) -> u32 {
    // Read backwards, the digits before a digit are the bits below it; `x ^= x * even`
    // flips each bit by a function of the bits below it, and so does adding the seed.
    let mut x = bits.reverse_bits();
    x = x.wrapping_add(seed);
    x ^= x.wrapping_mul(0x6c50_b47c);
    x ^= x.wrapping_mul(0xb82f_1e52);
    x ^= x.wrapping_mul(0xc7af_e638);
    x ^= x.wrapping_mul(0x8d22_f6e6);
    x.reverse_bits()
}
// ANCHOR_END: owen_scramble

/// The point of the Sobol sampler, in `[0, 1)^2`, that sample `index` of a pixel takes in a
/// dimension keyed by `key`: the index shuffled by Owen-scrambling it, that point of the
/// sequence, each coordinate scrambled with a seed of its own.
pub fn scrambled_sobol_2d(index: u32, key: u32) -> Vec2 {
    let seed = |salt: u64| mix(u64::from(key) ^ salt) as u32;
    // The index scrambled as if it were a fraction: each bit flips by the bits above it, so
    // the first 2^k indices, whose higher bits are all zero, become one aligned block of 2^k
    // points of the sequence in a new order, and such a block is a (0, 2)-net.
    let shuffled = owen_scramble(index, seed(1));
    let (x, y) = sobol_2d(shuffled);
    Vec2::new(
        unit_f32(owen_scramble(x, seed(2))),
        unit_f32(owen_scramble(y, seed(3))),
    )
}

/// Owen-scrambled Sobol points in every dimension (the low-discrepancy sampler; Mitsuba 3's
/// `ldsampler` draws from the same (0, 2)-sequence). It needs no sample count: a render
/// stopped by a time budget keeps its low discrepancy at every power of two. Indices beyond
/// `2^32` start the sequence again.
#[derive(Clone, Debug)]
pub struct SobolSampler {
    index: u32,
    keys: DimensionKeys,
}

impl SobolSampler {
    /// Scrambles fixed by `seed`, each pixel's and each dimension's its own.
    pub fn new(seed: u64) -> Self {
        Self {
            index: 0,
            keys: DimensionKeys::new(seed),
        }
    }
}

impl Sampler for SobolSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.index = sample_index as u32;
        self.keys.start(pixel);
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        self.get_2d()
    }

    /// The first coordinate of a dimension's own point.
    fn get_1d(&mut self) -> f32 {
        scrambled_sobol_2d(self.index, self.keys.next_key()).x
    }

    fn get_2d(&mut self) -> Vec2 {
        scrambled_sobol_2d(self.index, self.keys.next_key())
    }
}
