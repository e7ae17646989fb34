//! The samplers that place every dimension: each dimension stratified over a pixel's samples,
//! the dimensions unrelated to one another, the estimate unbiased and less noisy.

use super::*;

#[test]
fn exercise_shuffled_stratum() {
    let order = |strata: u32, key: u32, round: u64| -> Vec<u32> {
        (0..u64::from(strata))
            .map(|i| shuffled_stratum(round * u64::from(strata) + i, strata, key))
            .collect()
    };
    for strata in [1u32, 2, 7, 16, 64] {
        for key in [1u32, 0xdead_beef] {
            for round in 0..3 {
                let taken = order(strata, key, round);
                let mut sorted = taken.clone();
                sorted.sort();
                let every_once: Vec<u32> = (0..strata).collect();
                assert!(
                    sorted == every_once,
                    "shuffled_stratum: samples {} to {} of a pixel are round {round} of {strata} \
                     strata and must take every stratum once; they took {taken:?}{}",
                    round * u64::from(strata),
                    (round + 1) * u64::from(strata) - 1,
                    if taken.iter().any(|&s| s >= strata) {
                        ": a stratum past the last, so the index given to the permutation is not \
                         the sample's place within its round"
                    } else {
                        ""
                    }
                );
            }
        }
    }
    let identity: Vec<u32> = (0..16).collect();
    let first = order(16, 1, 0);
    assert!(
        first != identity,
        "shuffled_stratum: 16 samples took the strata 0, 1, 2, ... in order: in every dimension \
         sample k would sit in stratum k, and the samples would lie along the diagonal of the \
         cube of all dimensions; the strata must be dealt in a random order"
    );
    assert!(
        order(16, 2, 0) != first,
        "shuffled_stratum: keys 1 and 2 dealt the 16 strata in the same order {first:?}: each \
         dimension has a key, and its order must be its own, or two dimensions of a sample would \
         always take the same stratum"
    );
    assert!(
        order(16, 1, 1) != first,
        "shuffled_stratum: samples 16 to 31 took the strata in the same order as samples 0 to 15, \
         {first:?}: each round of samples must deal them in a new order (mix the round into the \
         key), or sample k and sample k + 16 would always share a stratum in every dimension"
    );
}

/// The samplers that place every dimension, with sample counts they lay out exactly.
const PLACING: [(PixelSamplerKind, &[u64]); 3] = [
    (PixelSamplerKind::Stratified, &[1, 7, 12, 16, 64]),
    (PixelSamplerKind::MultiJitter, &[1, 7, 12, 16, 64]),
    (PixelSamplerKind::Sobol, &[1, 2, 16, 64]),
];

/// The draws of one sample, in a fixed order: a 1D, a 2D, a 1D, a 2D (after the pixel).
fn draws(s: &mut PixelSampler, pixel: UVec2, index: u64) -> (Vec2, [f32; 2], [Vec2; 2]) {
    s.start_pixel_sample(pixel, index);
    let p = s.get_pixel_2d();
    let a = s.get_1d();
    let u = s.get_2d();
    let b = s.get_1d();
    let v = s.get_2d();
    (p, [a, b], [u, v])
}

#[test]
fn every_dimension_covers_its_strata_once_per_pixel() {
    for (kind, counts) in PLACING {
        for &spp in counts {
            let (columns, rows) = strata_grid(spp).unwrap();
            for pixel in [UVec2::new(0, 0), UVec2::new(13, 7)] {
                let mut s = PixelSampler::new(kind, spp, 5).unwrap();
                let mut one_d = [vec![0u32; spp as usize], vec![0u32; spp as usize]];
                let mut two_d = [vec![0u32; spp as usize], vec![0u32; spp as usize]];
                for index in 0..spp {
                    let (_, numbers, points) = draws(&mut s, pixel, index);
                    for (hits, u) in one_d.iter_mut().zip(numbers) {
                        assert!((0.0..1.0).contains(&u), "{kind:?}: {u}");
                        hits[(u * spp as f32) as usize] += 1;
                    }
                    for (hits, p) in two_d.iter_mut().zip(points) {
                        assert!(p.cmpge(Vec2::ZERO).all() && p.cmplt(Vec2::ONE).all());
                        // Sobol's nets are not a columns x rows grid for every count; their
                        // boxes are checked apart.
                        if kind != PixelSamplerKind::Sobol {
                            let cell = (p.y * rows as f32) as u32 * columns
                                + (p.x * columns as f32) as u32;
                            hits[cell as usize] += 1;
                        }
                    }
                }
                for hits in &one_d {
                    assert!(
                        hits.iter().all(|&h| h == 1),
                        "{kind:?}, {spp} spp: a 1D dimension must put one sample into each of \
                         its {spp} strata, found {hits:?}"
                    );
                }
                if kind != PixelSamplerKind::Sobol {
                    for hits in &two_d {
                        assert!(
                            hits.iter().all(|&h| h == 1),
                            "{kind:?}, {spp} spp: a 2D dimension must put one sample into each \
                             cell of the {columns} x {rows} grid, found {hits:?}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn multi_jittered_points_cover_every_interval_of_each_axis() {
    for (columns, rows) in [(4, 4), (4, 2), (7, 1), (5, 3)] {
        let n = columns * rows;
        for key in [0u32, 1, 0xdead_beef] {
            let mut x_hits = vec![0; n as usize];
            let mut y_hits = vec![0; n as usize];
            let mut cells = vec![0; n as usize];
            for cell in 0..n {
                let p = multi_jittered(cell, columns, rows, key, Vec2::splat(0.5));
                x_hits[(p.x * n as f32) as usize] += 1;
                y_hits[(p.y * n as f32) as usize] += 1;
                cells[((p.y * rows as f32) as u32 * columns + (p.x * columns as f32) as u32)
                    as usize] += 1;
            }
            for (what, hits) in [("x", &x_hits), ("y", &y_hits), ("cells", &cells)] {
                assert!(
                    hits.iter().all(|&h| h == 1),
                    "{columns} x {rows}, key {key}: {what} {hits:?}"
                );
            }
        }
    }
}

/// Whether the first `2^m` points hold one point in every box `2^-a` wide and `2^-(m-a)` tall.
fn is_02_net(points: &[Vec2]) -> bool {
    let m = points.len().trailing_zeros();
    (0..=m).all(|a| {
        let (wide, tall) = (1u32 << a, 1u32 << (m - a));
        let mut hits = vec![0; points.len()];
        for p in points {
            let box_index = (p.y * tall as f32) as u32 * wide + (p.x * wide as f32) as u32;
            hits[box_index as usize] += 1;
        }
        hits.iter().all(|&h| h == 1)
    })
}

#[test]
fn sobol_points_are_02_nets_scrambled_or_not() {
    let to_unit = |bits: u32| common::sampler::unit_f32(bits);
    // The first points: the radical inverse in base 2, and Sobol's second dimension.
    let first: Vec<(u32, u32)> = (0..8).map(sobol_2d).collect();
    let eighths = |v: &[(u32, u32)], second: bool| -> Vec<u32> {
        v.iter()
            .map(|&(x, y)| if second { y } else { x } >> 29)
            .collect()
    };
    assert_eq!(eighths(&first, false), [0, 4, 2, 6, 1, 5, 3, 7]);
    assert_eq!(eighths(&first, true), [0, 4, 6, 2, 5, 1, 3, 7]);
    for m in [2u32, 4, 6] {
        let n = 1u32 << m;
        let plain: Vec<Vec2> = (0..n)
            .map(|i| {
                let (x, y) = sobol_2d(i);
                Vec2::new(to_unit(x), to_unit(y))
            })
            .collect();
        assert!(is_02_net(&plain), "{n} Sobol points");
        for key in [0u32, 7, 0xdead_beef] {
            let scrambled: Vec<Vec2> = (0..n).map(|i| scrambled_sobol_2d(i, key)).collect();
            assert!(is_02_net(&scrambled), "{n} scrambled points, key {key}");
            assert_ne!(scrambled, plain);
        }
        // The sampler: the first 2^m samples of a pixel, in every 2D dimension.
        let mut s = PixelSampler::new(PixelSamplerKind::Sobol, u64::from(n), 3).unwrap();
        let samples: Vec<_> = (0..u64::from(n))
            .map(|i| draws(&mut s, UVec2::new(2, 9), i))
            .collect();
        let pixel: Vec<Vec2> = samples.iter().map(|d| d.0).collect();
        let later: Vec<Vec2> = samples.iter().map(|d| d.2[1]).collect();
        assert!(
            is_02_net(&pixel) && is_02_net(&later),
            "{n} samples of a pixel"
        );
    }
}

#[test]
fn owen_scrambling_the_index_keeps_a_power_of_two_block_together() {
    for key in [1u32, 99, 0x1234_5678] {
        let shuffled: Vec<u32> = (0..16).map(|i| owen_scramble(i, key)).collect();
        let block = shuffled[0] / 16;
        assert!(shuffled.iter().all(|&i| i / 16 == block), "{shuffled:?}");
        let mut sorted = shuffled.clone();
        sorted.sort();
        sorted.dedup();
        assert_eq!(sorted.len(), 16);
    }
}

#[test]
fn dimensions_take_their_strata_in_orders_of_their_own() {
    for (kind, _) in PLACING {
        let spp = 16;
        let mut s = PixelSampler::new(kind, spp, 8).unwrap();
        let strata: Vec<[u32; 2]> = (0..spp)
            .map(|index| {
                let (_, [a, b], _) = draws(&mut s, UVec2::new(3, 3), index);
                [(a * 16.0) as u32, (b * 16.0) as u32]
            })
            .collect();
        let same = strata.iter().filter(|[a, b]| a == b).count();
        assert!(
            same < 8,
            "{kind:?}: two dimensions gave {same} of 16 samples the same stratum: each \
             dimension must shuffle its strata with a key of its own"
        );
    }
}

/// The mean of `u * v` over the samples of many pixels, `u` and `v` two 1D dimensions of the
/// same sample: 1/4 if they are independent.
fn mean_product(kind: PixelSamplerKind, spp: u64, pixels: u32) -> (f64, u64) {
    let mut s = PixelSampler::new(kind, spp, 21).unwrap();
    let mut sum = 0.0;
    let mut n = 0;
    for y in 0..pixels {
        for index in 0..spp {
            let (_, [a, b], _) = draws(&mut s, UVec2::new(y % 64, y / 64), index);
            sum += f64::from(a) * f64::from(b);
            n += 1;
        }
    }
    (sum / n as f64, n)
}

#[test]
fn two_dimensions_of_a_sample_are_independent_on_average() {
    for (kind, _) in PLACING {
        let (mean, n) = mean_product(kind, 16, 4096);
        // Independent uniforms: Var(uv) = 1/9 - 1/16 = 7/144; stratification only lowers it.
        let sigma = (7.0 / 144.0 / n as f64).sqrt();
        assert!(
            (mean - 0.25).abs() < 5.0 * sigma,
            "{kind:?}: the mean of u * v over two dimensions is {mean}, not 1/4 (within \
             {:.5}): the dimensions are correlated (1/3 if every dimension took the same \
             stratum)",
            5.0 * sigma
        );
    }
}

/// The mean squared error, over pixels, of the estimate at `spp` of a smooth integral over the
/// pixel position, one 1D and one 2D dimension, a sum of a term for each (whose exact value is
/// 3): what stratifying each dimension on its own can make almost exact, and what a sampler
/// that leaves a dimension independent cannot.
fn smooth_integral_mse(kind: PixelSamplerKind, spp: u64) -> f64 {
    let mut s = PixelSampler::new(kind, spp, 4).unwrap();
    let f = |p: Vec2, a: f32, u: Vec2| {
        // Each term integrates to 1 over its dimension.
        let g = |x: f32| 1.0 + (std::f32::consts::TAU * x).sin() * 0.9;
        f64::from(g(p.x) * g(p.y) + g(a) + 2.0 * u.x * g(u.y))
    };
    let pixels = 1024;
    let mut squared = 0.0;
    for k in 0..pixels {
        let pixel = UVec2::new(k % 32, k / 32);
        let estimate: f64 = (0..spp)
            .map(|index| {
                let (p, [a, _], [u, _]) = draws(&mut s, pixel, index);
                f(p, a, u)
            })
            .sum::<f64>()
            / spp as f64;
        squared += (estimate - 3.0).powi(2);
    }
    squared / f64::from(pixels)
}

#[test]
fn placing_every_dimension_lowers_the_error_of_a_smooth_integral() {
    let random = smooth_integral_mse(PixelSamplerKind::Random, 64);
    for (kind, _) in PLACING {
        let placed = smooth_integral_mse(kind, 64);
        assert!(
            placed < 0.05 * random,
            "{kind:?}: mean squared error {placed:.3e} at 64 spp, against {random:.3e} for \
             independent numbers: each dimension placed over the pixel's samples should make \
             it at least 20 times smaller"
        );
    }
}

#[test]
fn numbers_depend_on_seed_pixel_and_index_only() {
    for (kind, _) in PLACING {
        let mut a = PixelSampler::new(kind, 16, 9).unwrap();
        let mut b = PixelSampler::new(kind, 16, 9).unwrap();
        draws(&mut b, UVec2::new(8, 8), 5);
        assert_eq!(
            draws(&mut a, UVec2::new(1, 2), 3),
            draws(&mut b, UVec2::new(1, 2), 3),
            "{kind:?}"
        );
        assert_ne!(
            draws(&mut a, UVec2::new(1, 2), 3),
            draws(&mut b, UVec2::new(2, 1), 3),
            "{kind:?}"
        );
    }
}
