use super::*;
use common::sampler::IndependentSampler;

const ALL_KINDS: [PixelSamplerKind; 4] = PixelSamplerKind::ALL;

/// What is wrong with `p = jittered(index, columns, rows, xi)`, in words; `None` if right.
fn jittered_mistake(index: u64, columns: u32, rows: u32, xi: Vec2, p: Vec2) -> Option<String> {
    let strata = u64::from(columns) * u64::from(rows);
    let stratum = index % strata;
    let (column, row) = (stratum % u64::from(columns), stratum / u64::from(columns));
    let expected = Vec2::new(
        (column as f32 + xi.x) / columns as f32,
        (row as f32 + xi.y) / rows as f32,
    )
    .min(Vec2::splat(ONE_MINUS_EPSILON));
    if p == expected
        || (p.is_finite() && (p - expected).abs().max_element() < 1e-6 && p.max_element() < 1.0)
    {
        return None;
    }
    let landed = (
        (p.x * columns as f32).floor() as i64,
        (p.y * rows as f32).floor() as i64,
    );
    let mistake = if !p.is_finite() {
        "the position is not a number".to_string()
    } else if p.x == 1.0 || p.y == 1.0 {
        "the sample lands on 1.0, which is the edge of the next pixel: in f32, (k + ξ) / n can \
         round up to 1 in the last stratum, and a sample must stay below 1"
            .to_string()
    } else if p.min_element() < 0.0 || p.max_element() > 1.0 {
        if index >= strata {
            format!(
                "sample {index} of a pixel with {strata} strata lands outside the pixel: after \
                 the last stratum the order starts again from the first"
            )
        } else {
            "the sample lands outside the pixel: the jitter ξ spans one stratum, not the whole \
             pixel"
                .to_string()
        }
    } else if landed == (row as i64, column as i64) && row != column {
        format!(
            "sample {index} went to column {}, row {}: strata are counted row by row from the \
             top left, so it belongs in column {column}, row {row}",
            landed.0, landed.1
        )
    } else if landed != (column as i64, row as i64) {
        let again = if index >= strata {
            format!(
                ": with {strata} strata, after the last one the order starts again from the first"
            )
        } else {
            String::new()
        };
        format!(
            "sample {index} should land in the stratum in column {column}, row {row} (counted \
             row by row from the top left), not in column {}, row {}{again}",
            landed.0, landed.1
        )
    } else {
        "the sample is in its stratum but not where ξ puts it: ξ = (0, 0) is the stratum's top \
         left corner, ξ near (1, 1) its bottom right"
            .to_string()
    };
    Some(format!(
        "{mistake}.\n  jittered({index}, {columns}, {rows}, ξ = {xi}) gave {p}, expected {expected}"
    ))
}

#[test]
fn exercise_jittered() {
    let mut cases: Vec<(u64, u32, u32, Vec2)> = Vec::new();
    // Strata are visited row by row, and start again after the last one.
    cases.extend((0..5).map(|i| (i, 2, 2, Vec2::splat(0.5))));
    // Wide and tall grids; jitter at the stratum's corners.
    cases.extend([
        (2, 3, 1, Vec2::ZERO),
        (1, 3, 1, Vec2::new(0.5, 0.25)),
        (5, 2, 3, Vec2::new(0.1, 0.9)),
        (7, 4, 2, Vec2::new(0.3, 0.6)),
    ]);
    // ξ just below 1 in the last stratum stays inside the pixel.
    cases.push((8, 3, 3, Vec2::splat(ONE_MINUS_EPSILON)));
    for (index, columns, rows, xi) in cases {
        let p = jittered(index, columns, rows, xi);
        if let Some(mistake) = jittered_mistake(index, columns, rows, xi, p) {
            panic!("jittered: {mistake}");
        }
    }
}

#[test]
fn strata_grids_are_as_square_as_the_count_allows() {
    let cases = [
        (1, (1, 1)),
        (2, (2, 1)),
        (4, (2, 2)),
        (8, (4, 2)),
        (12, (4, 3)),
        (7, (7, 1)),
        (64, (8, 8)),
        (4096, (64, 64)),
        (1_000_000_000, (31_250, 32_000)),
    ];
    for (spp, _) in cases {
        let (columns, rows) = strata_grid(spp).unwrap();
        assert_eq!(u64::from(columns) * u64::from(rows), spp);
    }
    for (spp, expected) in cases.into_iter().take(8) {
        assert_eq!(strata_grid(spp), Some(expected), "spp {spp}");
    }
    assert_eq!(strata_grid(0), None);
}

#[test]
fn zero_samples_are_refused_with_the_reason() {
    for kind in ALL_KINDS {
        let err = PixelSampler::new(kind, 0, 1).unwrap_err();
        assert!(err.contains("spp 0"), "{err}");
    }
}

#[test]
fn every_position_is_inside_its_pixel_and_deterministic() {
    for kind in ALL_KINDS {
        for spp in [1, 3, 16, 100] {
            let mut a = PixelSampler::new(kind, spp, 5).unwrap();
            let mut b = PixelSampler::new(kind, spp, 5).unwrap();
            // Visit another pixel first: positions depend on (seed, pixel, index) only.
            b.positions(UVec2::new(9, 2), 7);
            let pixel = UVec2::new(3, 4);
            let pa = a.positions(pixel, spp);
            assert_eq!(pa, b.positions(pixel, spp), "{kind:?}");
            for p in pa {
                assert!(p.cmpge(Vec2::ZERO).all() && p.cmplt(Vec2::ONE).all(), "{p}");
            }
        }
    }
}

#[test]
fn the_centre_sampler_is_chapter_01s() {
    let mut s = PixelSampler::new(PixelSamplerKind::Centre, 4, 0).unwrap();
    assert!(
        s.positions(UVec2::new(1, 1), 4)
            .iter()
            .all(|&p| p == Vec2::splat(0.5))
    );
}

#[test]
fn other_dimensions_come_from_the_independent_stream_after_the_pixel() {
    let pixel = UVec2::new(6, 1);
    let index = 3;
    let mut reference = IndependentSampler::new(11);
    reference.start_pixel_sample(pixel, index);
    let stream: Vec<f32> = (0..6).map(|_| reference.get_1d()).collect();
    for kind in ALL_KINDS {
        let mut s = PixelSampler::new(kind, 16, 11).unwrap();
        s.start_pixel_sample(pixel, index);
        s.get_pixel_2d();
        let next: Vec<f32> = (0..3).map(|_| s.get_1d()).collect();
        // Random and stratified positions use the first two numbers of the stream; the centre
        // and Halton positions use none of them.
        let skipped = match kind {
            PixelSamplerKind::Random | PixelSamplerKind::Stratified => 2,
            PixelSamplerKind::Centre | PixelSamplerKind::Halton => 0,
        };
        assert_eq!(next, stream[skipped..skipped + 3], "{kind:?}");
    }
}

#[test]
fn stratified_samples_fill_every_stratum_once() {
    for spp in [1u64, 6, 16, 25, 7] {
        let (columns, rows) = strata_grid(spp).unwrap();
        let mut s = PixelSampler::new(PixelSamplerKind::Stratified, spp, 2).unwrap();
        let mut hits = vec![0; spp as usize];
        for p in s.positions(UVec2::new(4, 4), spp) {
            let column = (p.x * columns as f32) as usize;
            let row = (p.y * rows as f32) as usize;
            hits[row * columns as usize + column] += 1;
        }
        assert!(hits.iter().all(|&h| h == 1), "spp {spp}: {hits:?}");
    }
}

#[test]
fn radical_inverse_mirrors_the_digits() {
    let base2: Vec<f64> = (0..8).map(|i| radical_inverse(2, i)).collect();
    assert_eq!(base2, [0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875]);
    let base3: Vec<f64> = (0..5).map(|i| radical_inverse(3, i)).collect();
    let expected = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0 / 9.0, 4.0 / 9.0];
    for (got, want) in base3.iter().zip(expected) {
        assert!((got - want).abs() < 1e-15, "{got} vs {want}");
    }
    assert!(radical_inverse(3, u64::MAX) < 1.0);
}

#[test]
fn neighbouring_pixels_get_different_halton_shifts() {
    let shifts: Vec<Vec2> = [(0, 0), (1, 0), (0, 1), (1, 1)]
        .into_iter()
        .map(|(x, y)| HaltonSampler::pixel_shift(0, UVec2::new(x, y)))
        .collect();
    for i in 0..shifts.len() {
        for j in i + 1..shifts.len() {
            assert!(
                (shifts[i] - shifts[j]).abs().min_element() > 1e-3,
                "{shifts:?}"
            );
        }
    }
    assert_ne!(
        HaltonSampler::pixel_shift(0, UVec2::ZERO),
        HaltonSampler::pixel_shift(1, UVec2::ZERO)
    );
}

#[test]
fn the_halton_points_of_a_pixel_are_the_rotated_sequence() {
    let pixel = UVec2::new(2, 7);
    let shift = HaltonSampler::pixel_shift(3, pixel);
    let mut s = PixelSampler::new(PixelSamplerKind::Halton, 8, 3).unwrap();
    for (i, p) in s.positions(pixel, 8).into_iter().enumerate() {
        let expected = halton::halton_2d(i as u64) + shift;
        let wrapped = expected - expected.floor();
        assert!((p - wrapped).abs().max_element() < 1e-6, "{p} vs {wrapped}");
    }
    // Wrapping keeps values in [0, 1) even at the top.
    let top = halton::rotate(
        Vec2::splat(ONE_MINUS_EPSILON),
        Vec2::splat(ONE_MINUS_EPSILON),
    );
    assert!(top.cmplt(Vec2::ONE).all() && top.cmpge(Vec2::ZERO).all());
}
