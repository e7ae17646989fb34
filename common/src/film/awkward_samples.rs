//! A sample a wrong answer placed or weighed (a film position that is NaN, infinite or far off
//! the image, a filter of any radius whose weights are NaN, infinite or negative, a radiance
//! that is not finite) is added without a panic, and no NaN or infinity reaches a pixel.

use glam::{UVec2, Vec2, Vec3};
use proptest::prelude::*;

use super::{Film, Filter, PixelRect};
use crate::geometry::awkward::{self, number, vec2, vec3};

/// A filter of radius `radius` whose weight is `weight` wherever it reaches.
struct Broken {
    radius: Vec2,
    weight: f32,
}

impl Filter for Broken {
    fn radius(&self) -> Vec2 {
        self.radius
    }

    fn evaluate(&self, offset: Vec2) -> f32 {
        if offset.abs().cmple(self.radius).all() {
            self.weight
        } else {
            0.0
        }
    }
}

proptest! {
    #![proptest_config(awkward::config(256))]

    #[test]
    fn any_sample_keeps_every_pixel_finite(
        radius in vec2(),
        weight in number(),
        samples in prop::collection::vec((vec2(), vec3()), 1..8),
        near in prop::collection::vec((0.0f32..40.0, 0.0f32..24.0), 0..8),
    ) {
        let filter = Broken { radius, weight };
        let mut film = Film::new(40, 24);
        for (min, max) in [(UVec2::ZERO, UVec2::new(16, 16)), (UVec2::new(32, 16), UVec2::new(40, 24))] {
            let mut tile = film.tile(PixelRect { min, max }, &filter);
            for &(p_film, radiance) in &samples {
                tile.add_sample(p_film, radiance, &filter);
            }
            for &(x, y) in &near {
                tile.add_sample(Vec2::new(x, y), Vec3::new(x, 1.0, 1e30), &filter);
            }
            film.merge(&tile);
        }
        let image = film.image();
        prop_assert!(image.pixels.iter().all(|p| p.is_finite()));
    }
}

/// Weights of opposite signs that nearly cancel (a negative lobe's, as Mitchell–Netravali's)
/// under the largest radiance: the average is beyond what an `f32` holds, and it is clamped.
#[test]
fn an_average_beyond_f32_is_clamped_not_infinite() {
    struct Lobes;
    impl Filter for Lobes {
        fn radius(&self) -> Vec2 {
            Vec2::ONE
        }
        fn evaluate(&self, offset: Vec2) -> f32 {
            if offset.x >= 0.0 {
                1.0
            } else {
                -(1.0 - 1.0 / 1024.0)
            }
        }
    }
    let mut film = Film::new(1, 1);
    let whole = PixelRect {
        min: UVec2::ZERO,
        max: UVec2::ONE,
    };
    let mut tile = film.tile(whole, &Lobes);
    tile.add_sample(Vec2::new(0.75, 0.5), Vec3::splat(f32::MAX), &Lobes);
    tile.add_sample(Vec2::new(0.25, 0.5), Vec3::ZERO, &Lobes);
    film.merge(&tile);
    assert!(film.pixel(0, 0).value().x > f64::from(f32::MAX));
    assert_eq!(film.image().get(0, 0), Vec3::splat(f32::MAX));
}
