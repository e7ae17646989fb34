use super::*;
use common::film::{Film, PixelRect};
use glam::{UVec2, Vec3};

#[test]
fn defaults_are_mitsubas() {
    let new = |kind| ReconstructionFilter::new(kind, None).unwrap();
    assert_eq!(
        new(FilterKind::Box),
        ReconstructionFilter::Box { radius: 0.5 }
    );
    assert_eq!(
        new(FilterKind::Tent),
        ReconstructionFilter::Tent { radius: 1.0 }
    );
    assert_eq!(
        new(FilterKind::Gaussian),
        ReconstructionFilter::Gaussian {
            stddev: 0.5,
            radius: 2.0
        }
    );
    assert_eq!(
        new(FilterKind::Mitchell),
        ReconstructionFilter::Mitchell {
            radius: 2.0,
            b: 1.0 / 3.0,
            c: 1.0 / 3.0
        }
    );
    assert_eq!(
        ReconstructionFilter::new(FilterKind::Gaussian, Some(1.0)).unwrap(),
        ReconstructionFilter::Gaussian {
            stddev: 0.25,
            radius: 1.0
        }
    );
}

#[test]
fn bad_radii_are_refused_with_the_value() {
    for kind in FilterKind::ALL {
        for bad in [0.0, -1.0, f32::NAN, f32::INFINITY, 16.5, 1e30] {
            let err = ReconstructionFilter::new(kind, Some(bad)).unwrap_err();
            assert!(
                err.contains("radius") && err.contains(&bad.to_string()),
                "{err}"
            );
        }
        for good in [1e-3, 0.5, 16.0] {
            let filter = ReconstructionFilter::new(kind, Some(good)).unwrap();
            assert_eq!(filter.half_width(), good);
        }
    }
}

#[test]
fn exercise_tent_filter() {
    assert_eq!(tent_1d(0.0, 1.0), 1.0);
    assert_eq!(tent_1d(0.5, 1.0), 0.5);
    assert_eq!(tent_1d(-0.5, 1.0), 0.5);
    assert_eq!(tent_1d(0.5, 2.0), 0.75);
    assert_eq!(tent_1d(1.0, 1.0), 0.0);
    assert_eq!(tent_1d(1.5, 1.0), 0.0, "zero, not negative, outside");
    assert_eq!(tent_1d(-3.0, 2.0), 0.0);
}

/// `∫ f(x) dx` over `[-radius, radius]` by the midpoint rule.
fn integral(f: impl Fn(f32) -> f32, radius: f32) -> f64 {
    let n = 100_000;
    let h = 2.0 * f64::from(radius) / n as f64;
    (0..n)
        .map(|i| f64::from(f((-f64::from(radius) + (i as f64 + 0.5) * h) as f32)) * h)
        .sum()
}

#[test]
fn exercise_mitchell() {
    let third = 1.0 / 3.0;
    let m = |x| mitchell_1d(x, third, third);
    assert!((m(0.0) - 8.0 / 9.0).abs() < 1e-6, "peak (6 - 2B)/6 = 8/9");
    assert!((m(1.0) - 1.0 / 18.0).abs() < 1e-6, "(B + 6C)/6 at 1 = 1/18");
    assert!(m(2.0).abs() < 1e-6 && m(2.5) == 0.0 && m(-3.0) == 0.0);
    assert!(m(1.5) < 0.0, "the negative lobe");
    assert_eq!(m(0.7), m(-0.7), "symmetric");
    // Continuous where the pieces meet, and the weights of a constant sum to one.
    assert!((m(1.0 - 1e-4) - m(1.0 + 1e-4)).abs() < 1e-3);
    assert!((integral(m, 2.0) - 1.0).abs() < 1e-4);
    // B = 1, C = 0 is the cubic B-spline: 2/3 at the centre, 1/6 at 1.
    assert!((mitchell_1d(0.0, 1.0, 0.0) - 2.0 / 3.0).abs() < 1e-6);
    assert!((mitchell_1d(1.0, 1.0, 0.0) - 1.0 / 6.0).abs() < 1e-6);
}

#[test]
fn weights_vanish_outside_the_radius() {
    for kind in FilterKind::ALL {
        for radius in [1e-3, 0.5, 1.0, 2.0, 16.0] {
            let f = ReconstructionFilter::new(kind, Some(radius)).unwrap();
            let beyond = radius * 1.001 + 1e-6;
            for offset in [
                Vec2::new(beyond, 0.0),
                Vec2::new(0.0, -beyond),
                Vec2::splat(beyond),
            ] {
                assert_eq!(f.evaluate(offset), 0.0, "{f:?} at {offset}");
            }
            assert!(f.evaluate(Vec2::ZERO) > 0.0, "{f:?}");
        }
    }
}

#[test]
fn weights_are_multiples_of_the_quantum() {
    let mitchell = ReconstructionFilter::new(FilterKind::Mitchell, None).unwrap();
    for i in 0..1000 {
        let offset = Vec2::new(i as f32 * 0.0037 - 1.9, 1.3 - i as f32 * 0.0029);
        let w = mitchell.evaluate(offset);
        assert_eq!((w / WEIGHT_QUANTUM).fract(), 0.0, "{w}");
    }
}

fn whole(film: &Film) -> PixelRect {
    PixelRect {
        min: UVec2::ZERO,
        max: UVec2::new(film.width(), film.height()),
    }
}

/// Splats `count` pseudo-random samples of radiance `radiance(i)` into a `w x h` film.
fn splat(
    filter: &ReconstructionFilter,
    (width, height): (u32, u32),
    count: u32,
    radiance: impl Fn(u32) -> Vec3,
) -> Film {
    let mut film = Film::new(width, height);
    let mut tile = film.tile(whole(&film), filter);
    let mut state = 12345u64;
    let mut next = || {
        state = common::sampler::mix(state);
        common::sampler::unit_f32(state as u32)
    };
    for i in 0..count {
        let p = Vec2::new(next() * width as f32, next() * height as f32);
        tile.add_sample(p, radiance(i), filter);
    }
    film.merge(&tile);
    film
}

#[test]
fn the_weighted_average_of_a_constant_is_exactly_that_constant() {
    let constant = Vec3::new(0.7, 0.25, 3.0);
    for kind in FilterKind::ALL {
        for radius in [None, Some(1.5), Some(4.0)] {
            let filter = ReconstructionFilter::new(kind, radius).unwrap();
            let film = splat(&filter, (6, 5), 400, |_| constant);
            for y in 0..5 {
                for x in 0..6 {
                    let sum = film.pixel(x, y);
                    assert_ne!(
                        sum.weight, 0.0,
                        "{filter:?}: pixel ({x}, {y}) got no sample"
                    );
                    assert_eq!(sum.value().as_vec3(), constant, "{filter:?} ({x}, {y})");
                }
            }
        }
    }
}

#[test]
fn tiny_filters_stay_finite_and_leave_unreached_pixels_black() {
    for kind in FilterKind::ALL {
        let filter = ReconstructionFilter::new(kind, Some(1e-3)).unwrap();
        let film = splat(&filter, (8, 8), 64, |i| Vec3::splat(i as f32));
        let image = film.image();
        assert!(image.pixels.iter().all(|p| p.is_finite()), "{filter:?}");
        for y in 0..8 {
            for x in 0..8 {
                if film.pixel(x, y).weight == 0.0 {
                    assert_eq!(image.get(x, y), Vec3::ZERO);
                }
            }
        }
        // Random samples hardly ever land within 1/1000 of a pixel centre.
        let reached = (0..64).filter(|i| film.pixel(i % 8, i / 8).weight != 0.0);
        assert!(reached.count() < 4, "{filter:?}");
    }
}

#[test]
fn cancelling_mitchell_weights_give_black_or_a_bounded_value_never_infinity() {
    // Two samples whose Mitchell weights nearly cancel: one in the negative lobe, one where
    // the profile, falling from the centre, has the opposite value (found by bisection).
    let filter = ReconstructionFilter::new(FilterKind::Mitchell, None).unwrap();
    let negative = Vec2::new(1.4, 0.0);
    let target = -filter.evaluate_1d(negative.x);
    let (mut lo, mut hi) = (0.0f32, negative.x); // the profile falls all the way on [0, 1.4]
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if filter.evaluate_1d(mid) > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let mut worst = 0.0f64;
    for (i, x) in [lo, hi, 0.5 * (lo + hi)].into_iter().enumerate() {
        let mut film = Film::new(1, 1);
        let mut tile = film.tile(whole(&film), &filter);
        let centre = Vec2::splat(0.5);
        tile.add_sample(centre + negative, Vec3::splat(1e4), &filter);
        tile.add_sample(
            centre + Vec2::new(x, 0.0),
            Vec3::splat(1.0 + i as f32),
            &filter,
        );
        film.merge(&tile);
        let sum = film.pixel(0, 0);
        assert!(
            sum.weight.abs() < 1e-3,
            "the weights nearly cancel: {}",
            sum.weight
        );
        let value = film.image().get(0, 0);
        assert!(value.is_finite(), "{value}");
        if sum.weight != 0.0 {
            assert!(
                sum.weight.abs() >= f64::from(WEIGHT_QUANTUM),
                "{}",
                sum.weight
            );
        }
        worst = worst.max(f64::from(value.abs().max_element()));
    }
    // |Σ f L| <= 2 * 1e4 and |Σ f| >= 2^-20: the worst value is at most about 2e10.
    assert!(worst <= 2e4 * f64::from(1u32 << 20), "{worst}");
}
