use super::*;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg32;
use std::f64::consts::PI;

/// A map of `width` x `height` pixels of colour `colour(x, y)`.
fn map(
    width: u32,
    height: u32,
    colour: impl Fn(u32, u32) -> Vec3,
) -> (Vec<Vec3>, EnvironmentSampling) {
    let mut pixels = Vec::new();
    for y in 0..height {
        for x in 0..width {
            pixels.push(colour(x, y));
        }
    }
    let sampling = EnvironmentSampling::new(width, height, &pixels);
    (pixels, sampling)
}

/// A sky brighter towards the top with a sun of 10⁴ in one pixel, on a 16 x 9 map.
fn sky_with_sun() -> EnvironmentSampling {
    map(16, 9, |x, y| {
        if (x, y) == (5, 3) {
            Vec3::new(1e4, 9e3, 8e3)
        } else {
            Vec3::new(0.2, 0.3, 0.9) * (1.0 + 0.3 * (9 - y) as f32)
        }
    })
    .1
}

fn numbers(seed: u64, n: usize) -> Vec<Vec2> {
    let mut rng = Pcg32::seed_from_u64(seed);
    (0..n)
        .map(|_| Vec2::new(rng.random(), rng.random()))
        .collect()
}

#[test]
fn a_sample_carries_the_density_that_pdf_gives_its_direction() {
    let sampling = sky_with_sun();
    let mut matches = 0;
    let samples = numbers(1, 20_000);
    for &u in &samples {
        let (d, pdf) = sampling
            .sample(u)
            .expect("a bright map always offers a sample");
        assert!((d.length() - 1.0).abs() < 1e-5 && pdf.is_finite() && pdf > 0.0);
        if (sampling.pdf(d) / pdf - 1.0).abs() < 1e-4 {
            matches += 1;
        }
    }
    // Only a direction that rounding puts on a cell's edge may be given its neighbour's.
    assert!(matches as f64 > 0.999 * samples.len() as f64, "{matches}");
}

/// Integrates `f` over the sphere on a midpoint grid uniform in `φ` and `cos θ` (uniform by
/// solid angle), `n` x `n` points.
fn integrate(n: usize, f: impl Fn(Vec3) -> f64) -> f64 {
    let mut sum = 0.0;
    for i in 0..n {
        for j in 0..n {
            let u = (i as f64 + 0.5) / n as f64;
            let z = 1.0 - 2.0 * (j as f64 + 0.5) / n as f64;
            sum += f(direction_of(u as f32, z as f32));
        }
    }
    sum * 4.0 * PI / (n * n) as f64
}

#[test]
fn the_density_integrates_to_one() {
    let total = integrate(600, |d| f64::from(sky_with_sun().pdf(d)));
    assert!((total - 1.0).abs() < 2e-2, "{total}");
}

#[test]
fn a_constant_map_is_sampled_uniformly_over_the_sphere() {
    // Every cell as bright as every other: the density must be 1/4π everywhere, however thin
    // the cells at the poles are. Weighing cells by their height in θ instead of their solid
    // angle (dropping sin θ) sends too many samples to the poles, which the histogram by
    // cos θ below sees.
    let (_, sampling) = map(8, 7, |_, _| Vec3::splat(0.5));
    for d in [Vec3::Y, Vec3::new(0.3, -0.8, 0.1), Vec3::new(1.0, 0.0, 0.0)] {
        let pdf = sampling.pdf(d);
        assert!((f64::from(pdf) * 4.0 * PI - 1.0).abs() < 1e-4, "{d}: {pdf}");
    }
    let bins = 20;
    let n = 40_000;
    let mut counts = vec![0u32; bins];
    for u in numbers(2, n) {
        let (d, _) = sampling.sample(u).unwrap();
        let bin = (((1.0 - d.y) / 2.0 * bins as f32) as usize).min(bins - 1);
        counts[bin] += 1;
    }
    let expected = n as f64 / bins as f64;
    let chi2: f64 = counts
        .iter()
        .map(|&c| (f64::from(c) - expected).powi(2) / expected)
        .sum();
    // χ² with 19 degrees of freedom: mean 19, standard deviation √38 ≈ 6.2.
    assert!(
        chi2 < 19.0 + 6.0 * 38f64.sqrt(),
        "χ² = {chi2}, counts by cos θ {counts:?}"
    );
}

#[test]
fn samples_follow_the_density_in_a_chi_square_test() {
    let sampling = sky_with_sun();
    let (phi_bins, z_bins) = (12, 10);
    let n = 100_000;
    let bin_of = |d: Vec3| {
        let u = direction_to_uv(d).x;
        let u = u - u.floor();
        let i = ((u * phi_bins as f32) as usize).min(phi_bins - 1);
        let j = (((1.0 - d.y) / 2.0 * z_bins as f32) as usize).min(z_bins - 1);
        j * phi_bins + i
    };
    let mut counts = vec![0f64; phi_bins * z_bins];
    for u in numbers(3, n) {
        counts[bin_of(sampling.sample(u).unwrap().0)] += 1.0;
    }
    // Expected counts: the density integrated over each bin.
    let mut expected = vec![0f64; phi_bins * z_bins];
    let grid = 720;
    for i in 0..grid {
        for j in 0..grid {
            let u = (i as f64 + 0.5) / grid as f64;
            let z = 1.0 - 2.0 * (j as f64 + 0.5) / grid as f64;
            let d = direction_of(u as f32, z as f32);
            expected[bin_of(d)] +=
                f64::from(sampling.pdf(d)) * 4.0 * PI / (grid * grid) as f64 * n as f64;
        }
    }
    let mut chi2 = 0.0;
    let mut dof = 0;
    for (&c, &e) in counts.iter().zip(&expected) {
        if e >= 5.0 {
            chi2 += (c - e).powi(2) / e;
            dof += 1;
        }
    }
    let dof = f64::from(dof - 1);
    assert!(
        chi2 < dof + 6.0 * (2.0 * dof).sqrt(),
        "χ² = {chi2} with {dof} degrees of freedom"
    );
}

#[test]
fn the_density_follows_the_brightness() {
    let sampling = sky_with_sun();
    // The sun's cells against a plain sky cell: its light is about 10⁴ times brighter.
    let sun = direction_of((5.5 + 0.5) / 16.0, (PI * 3.25 / 8.0).cos() as f32);
    let sky = direction_of(0.9, -0.5);
    assert!(sampling.pdf(sun) > 1000.0 * sampling.pdf(sky));
    // Per unit solid angle, a cell is as likely as its mean luminance over the integral.
    let integral = integrate(600, |d| f64::from(sampling.pdf(d)) * sampling.integral());
    assert!((integral / sampling.integral() - 1.0).abs() < 2e-2);
}

#[test]
fn black_maps_and_extreme_maps_never_give_nan() {
    let (_, black) = map(4, 3, |_, _| Vec3::ZERO);
    assert_eq!(black.sample(Vec2::new(0.5, 0.5)), None);
    assert_eq!(black.pdf(Vec3::Y), 0.0);
    assert_eq!(black.integral(), 0.0);
    let hot = map(32, 16, |x, y| {
        if (x, y) == (0, 0) {
            Vec3::splat(3e37)
        } else {
            Vec3::ZERO
        }
    })
    .1;
    let tiny = map(32, 16, |_, _| Vec3::splat(1e-40)).1;
    let single = map(1, 1, |_, _| Vec3::ONE).1;
    let negative = map(3, 2, |x, _| Vec3::new(-1.0, 0.0, x as f32)).1;
    for sampling in [&hot, &tiny, &single, &negative] {
        for u in numbers(4, 2000)
            .into_iter()
            .chain([Vec2::ZERO, Vec2::splat(0.99999994)])
        {
            if let Some((d, pdf)) = sampling.sample(u) {
                assert!(d.is_finite() && pdf.is_finite() && pdf > 0.0, "{d} {pdf}");
                assert!(sampling.pdf(d).is_finite());
            }
        }
        for d in [
            Vec3::Y,
            -Vec3::Y,
            Vec3::ZERO,
            Vec3::NAN,
            Vec3::new(1.0, 1e-8, 0.0),
        ] {
            let pdf = sampling.pdf(d);
            assert!(pdf.is_finite() && pdf >= 0.0, "{d}: {pdf}");
        }
    }
    // The hot pixel's light is all at the north pole's first cells; they must be chosen.
    let (d, _) = hot.sample(Vec2::new(0.3, 0.7)).unwrap();
    assert!(d.y > (PI / 15.0).cos() as f32 - 1e-4, "{d}");
    // A map whose only light is negative still offers samples where it is not zero.
    assert!(negative.sample(Vec2::new(0.5, 0.5)).is_some());
}

#[test]
fn near_a_sun_the_density_follows_the_light_inside_each_cell() {
    // The lookup's light over the density is nearly constant around a one-pixel sun, as with
    // Mitsuba's bilinear warp: a density constant per cell would swing it between 0 and 4.
    let (pixels, sampling) = map(16, 9, |x, y| {
        if (x, y) == (5, 4) {
            Vec3::splat(1e4)
        } else {
            Vec3::splat(0.01)
        }
    });
    let map = super::super::EnvironmentMap::new(16, 9, &pixels, 1.0, glam::Mat3::IDENTITY).unwrap();
    let mut rng = Pcg32::seed_from_u64(5);
    let mut checked = 0;
    for _ in 0..200 {
        // Within a pixel and a half of the sun's centre (u = 5.5 / 16, θ = π / 2).
        let u = (5.5 + 1.5 * (2.0 * rng.random::<f32>() - 1.0)) / 16.0;
        let theta = PI as f32 * (0.5 + 0.15 * (2.0 * rng.random::<f32>() - 1.0));
        let d = direction_of(u, theta.cos());
        let light = f64::from(luminance(map.radiance(d)));
        if light < 100.0 {
            continue; // too far from the sun for it to dominate
        }
        let ratio = f64::from(sampling.pdf(d)) * sampling.integral() / light;
        assert!(
            (0.8..1.25).contains(&ratio),
            "towards {d}: density / light = {ratio}"
        );
        checked += 1;
    }
    assert!(checked > 50, "{checked}");
}

proptest::proptest! {
    #![proptest_config(crate::geometry::awkward::config(256))]

    /// A light sample drawn with numbers outside `[0, 1)` (NaN among them) is still a unit
    /// direction of positive, finite density, and any direction a wrong answer computed (zero,
    /// NaN, infinite) gets a density and a radiance: finite numbers, never a panic.
    #[test]
    fn any_numbers_and_any_direction_get_finite_answers(
        u in crate::geometry::awkward::vec2(),
        d in crate::geometry::awkward::vec3(),
        uv in crate::geometry::awkward::vec2(),
    ) {
        let sampling = sky_with_sun();
        let (direction, pdf) = sampling.sample(u).expect("the sky is not black");
        proptest::prop_assert!((direction.length() - 1.0).abs() < 1e-3, "{direction}");
        proptest::prop_assert!(pdf > 0.0 && pdf.is_finite(), "{pdf}");
        let density = sampling.pdf(d);
        proptest::prop_assert!(density >= 0.0 && density.is_finite(), "{density} towards {d}");
        let (pixels, _) = map(5, 3, |x, y| Vec3::new(x as f32, y as f32, 1.0));
        let map = super::super::EnvironmentMap::new(5, 3, &pixels, 2.0, glam::Mat3::IDENTITY)
            .unwrap();
        proptest::prop_assert!(map.radiance(d).is_finite());
        proptest::prop_assert!(map.lookup(uv).is_finite());
        proptest::prop_assert!(map.sampling().pdf(d).is_finite());
    }
}
