//! The numbers of one sample, handed to chapter 02's point sets.
//!
//! The shadow rays' points come from [`light_samples`](crate::shadow_rays::light_samples), which stratifies
//! them with chapter 02's jittered grids and Latin hypercubes, written for any `rand`
//! generator. A render must instead draw every number from the sample's own stream (the
//! `Sampler`), in a fixed order, so that the image depends on the seed, the pixel and the
//! sample index only, whatever thread renders it. [`SampleStream`] is the bridge: a `rand`
//! generator whose every output is the sampler's next dimension.
//!
//! A dimension is a float `k / 2^24` ([`unit_f32`](common::sampler::unit_f32)'s 24 bits). It is
//! handed out as the 32-bit word `k << 8`, which chapter 02's `unit_f32(bits)` (and `rand`'s
//! own float conversion) turn back into exactly the same float, so an independent point drawn
//! through the stream *is* the sampler's `get_2d`, bit for bit.

use common::sampler::Sampler;
use rand::TryRng;
use std::convert::Infallible;

/// A `rand` generator that draws from a sampler, one dimension per 32-bit word.
pub struct SampleStream<'a, S: Sampler>(pub &'a mut S);

impl<S: Sampler> SampleStream<'_, S> {
    /// The next dimension's 24 random bits, in the high bits of a word.
    fn word(&mut self) -> u32 {
        ((self.0.get_1d() * (1u32 << 24) as f32) as u32) << 8
    }
}

impl<S: Sampler> TryRng for SampleStream<'_, S> {
    type Error = Infallible;

    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        Ok(self.word())
    }

    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        let high = u64::from(self.word());
        Ok((high << 32) | u64::from(self.word()))
    }

    /// Three random bytes per dimension: a word's low byte is always zero.
    fn try_fill_bytes(&mut self, dst: &mut [u8]) -> Result<(), Infallible> {
        for chunk in dst.chunks_mut(3) {
            let bytes = (self.word() >> 8).to_le_bytes();
            chunk.copy_from_slice(&bytes[..chunk.len()]);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ch02_monte_carlo::stratified::independent_2d;
    use common::sampler::IndependentSampler;
    use glam::UVec2;

    #[test]
    fn independent_points_through_the_stream_are_the_samplers_own() {
        let mut a = IndependentSampler::new(3);
        let mut b = IndependentSampler::new(3);
        a.start_pixel_sample(UVec2::new(4, 2), 9);
        b.start_pixel_sample(UVec2::new(4, 2), 9);
        let through_stream = independent_2d(20, &mut SampleStream(&mut a));
        let direct: Vec<_> = (0..20).map(|_| b.get_2d()).collect();
        assert_eq!(through_stream, direct);
    }

    #[test]
    fn bytes_are_never_all_zero() {
        let mut s = IndependentSampler::new(1);
        s.start_pixel_sample(UVec2::ZERO, 0);
        let mut bytes = [0u8; 64];
        rand::Rng::fill_bytes(&mut SampleStream(&mut s), &mut bytes);
        assert!(bytes.iter().filter(|&&b| b != 0).count() > 50);
    }
}
