//! One pixel's value, gathered: the lecture's weighted average written out for a single pixel,
//! and the chapter's render, which draws every pixel of its images with it.
//!
//! A pixel's value is the weighted average of the radiance of the samples near it, each weighted
//! by the reconstruction filter. With the box of radius 1/2 only the pixel's own samples count;
//! a wider filter also takes in samples that its neighbours drew. The film (`common::film`),
//! which the later chapters render through, computes the same sums the other way round: each
//! sample, as soon as it is traced, is *scattered* into every pixel its filter reaches. Here one
//! pixel *gathers* the samples that reach it, which is the formula as the lecture writes it, and
//! [`render`] makes every image of this chapter that way; both give the same image.

use common::film::Filter;
use common::render::{GatherPixel, RenderOutput, RenderSettings, render_gathered};
use common::sampler::Sampler;
use glam::{UVec2, Vec2, Vec3};

// ANCHOR: filtered_pixel
/// The value of `pixel` in an image of `image_size` pixels (pixel `(i, j)` covers
/// `[i, i+1) x [j, j+1)` of the film; pixels outside the image take no samples) when every
/// pixel takes `spp` samples, numbered `0..spp`, placed by `sampler`, and `filter`
/// reconstructs: the weighted average of the radiance of every sample, of this pixel or of a
/// neighbour, that the filter reaches. Each sample is drawn as the render draws it: started
/// with `sampler.start_pixel_sample(q, k)`, its pixel position its first number, then whatever
/// `radiance` draws.
///
/// `radiance(p_film, sampler)` is the radiance seen through film position `p_film`; it may
/// draw the sample's further numbers (a lens point, a time) from `sampler`. A pixel that no
/// sample reaches with any weight is black, and so is one whose weights sum to exactly zero
/// (the film's rule; the weights are rounded so that such a sum is exact).
///
/// Where is a pixel's centre, which pixels' samples can the filter reach from it, and where in
/// the film does sample `k` of pixel `q` lie? What must the weighted sum be divided by?
pub fn filtered_pixel<S: Sampler>(
    pixel: UVec2,
    image_size: UVec2,
    spp: u64,
    sampler: &mut S,
    filter: &dyn Filter,
    radiance: impl FnMut(Vec2, &mut S) -> Vec3,
) -> Vec3 {
    // BEGIN SOLUTION
    use glam::DVec3;
    let mut radiance = radiance;
    // Offsets are measured from the pixel's centre, half a pixel from its corner.
    let centre = pixel.as_vec2() + Vec2::splat(0.5);
    // A sample of pixel q lies in [q, q + 1): it can be within the radius of the centre only if
    // q + 1 > centre - radius and q <= centre + radius. Pixels outside the image take no
    // samples.
    let radius = filter.radius();
    let first = (centre - radius - Vec2::ONE).floor().max(Vec2::ZERO);
    let last = (centre + radius)
        .floor()
        .min(image_size.as_vec2() - Vec2::ONE);
    // The two sums of the lecture's weighted average, in f64 as the film keeps them.
    let mut weighted_radiance = DVec3::ZERO;
    let mut weight_sum = 0.0f64;
    for y in first.y as u32..=last.y as u32 {
        for x in first.x as u32..=last.x as u32 {
            let neighbour = UVec2::new(x, y);
            for index in 0..spp {
                // Sample `index` of the neighbour, where the neighbour's render puts it.
                sampler.start_pixel_sample(neighbour, index);
                let p_film = neighbour.as_vec2() + sampler.get_pixel_2d();
                let weight = f64::from(filter.evaluate(p_film - centre));
                if weight == 0.0 {
                    continue;
                }
                let sample = radiance(p_film, sampler).as_dvec3();
                weighted_radiance += weight * sample;
                weight_sum += weight;
            }
        }
    }
    // Dividing by the sum of the weights makes them sum to one, whatever the samples were.
    if weight_sum == 0.0 {
        Vec3::ZERO
    } else {
        (weighted_radiance / weight_sum).as_vec3()
    }
    // END SOLUTION
}
// ANCHOR_END: filtered_pixel

// ANCHOR: render_gathered
/// Renders an image in which every pixel is [`filtered_pixel`] of the samples around it: the
/// chapter's images are the lecture's weighted average, gathered pixel by pixel. Takes and
/// returns what `common::render::render` does, which scatters each sample into the film
/// instead; both give the same image. The tiles, the budget and the tracing of each sample
/// once are `common::render::render_gathered`'s.
pub fn render<S, F>(
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
    radiance: F,
) -> RenderOutput
where
    S: Sampler,
    F: Fn(Vec2, &mut S) -> Vec3 + Sync,
{
    render_gathered(settings, sampler, filter, radiance, &FilteredPixel)
}
// ANCHOR_END: render_gathered

/// [`filtered_pixel`] as the pixel the gathering render asks for.
struct FilteredPixel;

impl GatherPixel for FilteredPixel {
    fn pixel<S: Sampler>(
        &self,
        pixel: UVec2,
        image_size: UVec2,
        spp: u64,
        sampler: &mut S,
        filter: &dyn Filter,
        radiance: &mut dyn FnMut(Vec2, &mut S) -> Vec3,
    ) -> Vec3 {
        filtered_pixel(pixel, image_size, spp, sampler, filter, radiance)
    }
}

#[cfg(test)]
mod tests;
