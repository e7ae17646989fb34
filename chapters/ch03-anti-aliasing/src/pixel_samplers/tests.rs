use super::radical_inverse_values::RADICAL_INVERSES;
use super::*;
use common::sampler::IndependentSampler;

const ALL_KINDS: [PixelSamplerKind; 6] = PixelSamplerKind::ALL;

/// What is wrong with `p = jittered(index, columns, rows, xi)`, which should be `expected`,
/// in words; `None` if right.
fn jittered_mistake(
    (index, columns, rows, xi): (u64, u32, u32, Vec2),
    expected: Vec2,
    p: Vec2,
) -> Option<String> {
    let strata = u64::from(columns) * u64::from(rows);
    // The stratum the expected position lies in.
    let (column, row) = (
        (expected.x * columns as f32).floor() as u64,
        (expected.y * rows as f32).floor() as u64,
    );
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
        "the sample lands on 1.0, which is the edge of the next pixel: in f32, with a ξ just \
         below 1 the last stratum's position can round up to 1, and a sample must stay below 1"
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
    // (sample index, columns, rows, ξ) and the position expected, worked out beforehand in
    // f32. Strata are visited row by row, and start again after the last one.
    let mut cases: Vec<((u64, u32, u32, Vec2), Vec2)> = [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75)]
        .into_iter()
        .chain([(0.75, 0.75), (0.25, 0.25)])
        .enumerate()
        .map(|(i, (x, y))| ((i as u64, 2, 2, Vec2::splat(0.5)), Vec2::new(x, y)))
        .collect();
    // Wide and tall grids; jitter at the stratum's corners.
    cases.extend([
        ((2, 3, 1, Vec2::ZERO), Vec2::new(0.6666667, 0.0)),
        ((1, 3, 1, Vec2::new(0.5, 0.25)), Vec2::new(0.5, 0.25)),
        ((5, 2, 3, Vec2::new(0.1, 0.9)), Vec2::new(0.55, 0.9666667)),
        ((7, 4, 2, Vec2::new(0.3, 0.6)), Vec2::new(0.825, 0.8)),
    ]);
    // ξ just below 1 in the last stratum stays inside the pixel.
    cases.push((
        (8, 3, 3, Vec2::splat(ONE_MINUS_EPSILON)),
        Vec2::splat(ONE_MINUS_EPSILON),
    ));
    for (case @ (index, columns, rows, xi), expected) in cases {
        let p = jittered(index, columns, rows, xi);
        if let Some(mistake) = jittered_mistake(case, expected, p) {
            panic!("jittered: {mistake}");
        }
    }
}

/// What is wrong with `got = strata_grid(spp)`, which should be `expected`, in words; `None`
/// if right.
fn strata_grid_mistake(
    spp: u64,
    expected: Option<(u32, u32)>,
    got: Option<(u32, u32)>,
) -> Option<String> {
    if got == expected {
        return None;
    }
    let mistake = match got {
        None => format!("{spp} samples can be laid out as a grid"),
        Some(_) if spp == 0 => "no samples make no grid: the answer for 0 is None".to_string(),
        Some(_) if expected.is_none() => format!(
            "{spp} is prime and above u32::MAX: its only grid is a single row of {spp} columns, \
             too many to count in u32, and the answer is None (a cast with `as` would wrap \
             around)"
        ),
        Some((columns, rows)) if u64::from(columns) * u64::from(rows) != spp => format!(
            "a grid of {columns} x {rows} has {} cells, not {spp}: every sample needs its own \
             stratum, and every stratum a sample",
            u64::from(columns) * u64::from(rows)
        ),
        Some((columns, rows)) if Some((rows, columns)) == expected => {
            "the grid is taller than wide: the larger of the two is the number of columns"
                .to_string()
        }
        Some((columns, rows)) => format!(
            "{columns} x {rows} has the right number of cells but is not as square as {spp} \
             allows: a grid of {spp} cells with rows and columns closer together exists"
        ),
    };
    Some(format!(
        "{mistake}.\n  strata_grid({spp}) gave {got:?}, expected {expected:?}"
    ))
}

#[test]
fn exercise_strata_grid_is_as_square_as_the_count_allows() {
    // Each count and its squarest grid, (columns, rows), worked out beforehand by trying
    // every divisor.
    let counts = [
        (1, Some((1, 1))),
        (2, Some((2, 1))),
        (4, Some((2, 2))),
        (8, Some((4, 2))),
        (12, Some((4, 3))),
        (7, Some((7, 1))),
        (18, Some((6, 3))),
        (64, Some((8, 8))),
        (4096, Some((64, 64))),
        (1_000_000_000, Some((32_000, 31_250))),
        // Squares of large primes, where a square root off by one finds no divisor near it.
        (67_108_859u64 * 67_108_859, Some((67_108_859, 67_108_859))),
        (
            4_294_967_291u64 * 4_294_967_291,
            Some((4_294_967_291, 4_294_967_291)),
        ),
        // The smallest prime above u32::MAX: a single row too long to count in u32.
        (4_294_967_311, None),
        (0, None),
    ];
    for (spp, expected) in counts {
        let got =
            workbench::test_support::catch_panic(|| strata_grid(spp)).unwrap_or_else(|message| {
                panic!(
                    "strata_grid({spp}) panicked ({message}){}",
                    if spp == 0 {
                        ": no samples make no grid, and the answer for 0 is None"
                    } else {
                        ""
                    }
                )
            });
        if let Some(mistake) = strata_grid_mistake(spp, expected, got) {
            panic!("strata_grid: {mistake}");
        }
    }
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
    // The samplers that place the pixel position only; the others place every dimension
    // (every_dimension_tests.rs).
    for (kind, skipped) in [
        // A random position uses the first two numbers of the stream; the centre and Halton
        // positions use none of them.
        (PixelSamplerKind::Random, 2),
        (PixelSamplerKind::Centre, 0),
        (PixelSamplerKind::Halton, 0),
    ] {
        let mut s = PixelSampler::new(kind, 16, 11).unwrap();
        s.start_pixel_sample(pixel, index);
        s.get_pixel_2d();
        let next: Vec<f32> = (0..3).map(|_| s.get_1d()).collect();
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

/// What is wrong with `got = radical_inverse(base, index)`, which should be `expected`, in
/// words; `None` if right. `not_mirrored` is what the digits give in their written order, and
/// `written` the index written in the base.
fn radical_inverse_mistake(
    (base, index, expected, not_mirrored, written): (u32, u64, f64, f64, &str),
    got: f64,
) -> Option<String> {
    if (got - expected).abs() <= 1e-12 {
        return None;
    }
    let digit_sum: u32 = written.chars().filter_map(|c| c.to_digit(10)).sum();
    let mistake = if !got.is_finite() {
        "the value is not a number".to_string()
    } else if (got - f64::from(digit_sum) / f64::from(base)).abs() <= 1e-12 {
        "every digit is worth 1/base: each place after the point is worth 1/base of the place \
         before it"
            .to_string()
    } else if !(0.0..1.0).contains(&got) {
        "the radical inverse is a fraction in [0, 1): each digit's place after the point must \
         be worth a base smaller than the one before"
            .to_string()
    } else if (got - not_mirrored).abs() <= 1e-12 {
        format!(
            "the digits are not mirrored: {index} is {written} in base {base}, and its lowest \
             digit must become the first digit after the point (you read the digits in their \
             written order)"
        )
    } else if (got - expected).abs() < 1e-6 {
        "close, but the digits lose precision: each is worth exactly a power of 1/base".to_string()
    } else {
        format!("{index} is {written} in base {base}; mirrored around the point it is {expected}")
    };
    Some(format!(
        "{mistake}.\n  radical_inverse({base}, {index}) gave {got}, expected {expected}"
    ))
}

#[test]
fn exercise_radical_inverse_mirrors_the_digits() {
    // First a few indices of several digits, on which the usual slips all differ; then the
    // first 30 indices in bases 2, 3, 5 and 7; then indices too large for a power of the base
    // to fit in a u64.
    for case @ (base, index, _, _, written) in RADICAL_INVERSES {
        let got = workbench::test_support::catch_panic(|| radical_inverse(base, index))
            .unwrap_or_else(|message| {
                panic!(
                    "radical_inverse({base}, {index}) panicked ({message}): every u64 index has \
                     an answer{}",
                    if message.contains("overflow") {
                        format!(
                            ". {index} has {} digits in base {base}, and a power of the base that \
                             large does not fit in a u64; a digit's place value can be kept as \
                             an f64, which only grows smaller",
                            written.len()
                        )
                    } else {
                        String::new()
                    }
                )
            });
        if let Some(mistake) = radical_inverse_mistake(case, got) {
            panic!("radical_inverse: {mistake}");
        }
    }
}

#[test]
fn exercise_radical_inverse_fills_every_interval_once() {
    // The first base^k values fall one into each interval [j, j + 1) / base^k: the property
    // that makes the sequence even at every prefix.
    for (base, k) in [(2u32, 4u32), (3, 3), (5, 2)] {
        let n = u64::from(base).pow(k);
        let mut hits = vec![0; n as usize];
        for index in 0..n {
            let value = radical_inverse(base, index);
            let cell = (value * n as f64 + 1e-9).floor();
            if (0.0..n as f64).contains(&cell) {
                hits[cell as usize] += 1;
            }
        }
        let empty: Vec<usize> = (0..n as usize).filter(|&j| hits[j] != 1).collect();
        assert!(
            empty.is_empty(),
            "radical_inverse: the first {n} values in base {base} should fall one into each of \
             the {n} intervals of width 1/{n}; intervals {empty:?} got {:?} values",
            empty.iter().map(|&j| hits[j]).collect::<Vec<_>>()
        );
    }
}

/// Halton points of a pixel without a shift, `(index, position)`, and shifted ones, `(index,
/// shift, position)`, worked out beforehand in f32 (the largest index's x is the f32 just
/// below 1: its radical inverse, 1 - 2^-25, would round up to 1).
#[rustfmt::skip]
const HALTON_POINTS: [(u64, Vec2); 13] = [
    (0, Vec2::new(0.0, 0.0)), (1, Vec2::new(0.5, 0.33333334)),
    (2, Vec2::new(0.25, 0.6666667)), (3, Vec2::new(0.75, 0.11111111)),
    (4, Vec2::new(0.125, 0.44444445)), (5, Vec2::new(0.625, 0.7777778)),
    (6, Vec2::new(0.375, 0.22222222)), (7, Vec2::new(0.875, 0.5555556)),
    (8, Vec2::new(0.0625, 0.8888889)), (9, Vec2::new(0.5625, 0.037037037)),
    (10, Vec2::new(0.3125, 0.37037036)), (11, Vec2::new(0.8125, 0.7037037)),
    ((1 << 25) - 1, Vec2::new(0.99999994, 0.40842927)),
];
#[rustfmt::skip]
const SHIFTED_HALTON_POINTS: [(u64, Vec2, Vec2); 5] = [
    (1, Vec2::new(0.75, 0.8), Vec2::new(0.25, 0.13333333)),
    (3, Vec2::new(0.1, 0.95), Vec2::new(0.85, 0.061111093)),
    (5, Vec2::new(0.6, 0.3), Vec2::new(0.22500002, 0.07777786)),
    (7, Vec2::splat(ONE_MINUS_EPSILON), Vec2::new(0.875, 0.5555556)),
    (0, Vec2::new(0.3, 0.7), Vec2::new(0.3, 0.7)),
];

/// What is wrong with `got = halton_position(index, shift)`, which should be `expected`, in
/// words; `None` if right.
fn halton_position_mistake(index: u64, shift: Vec2, expected: Vec2, got: Vec2) -> Option<String> {
    let inside = got.cmpge(Vec2::ZERO).all() && got.cmplt(Vec2::ONE).all();
    if inside && (got - expected).abs().max_element() <= 1e-6 {
        return None;
    }
    let near = |a: Vec2, b: Vec2| (a - b).abs().max_element() <= 1e-6;
    // The same index's point without a shift.
    let point = HALTON_POINTS
        .iter()
        .find(|&&(i, _)| i == index)
        .map(|&(_, p)| p)
        .expect("every index checked has its unshifted point in the table");
    let unshifted = shift == Vec2::ZERO;
    // A coordinate a whole pixel away from the right one, yet inside: one that reached 1 and
    // was wrapped to the opposite edge.
    let wrapped_from_one = ((got - expected).abs() - Vec2::ONE).abs().min_element() < 1e-6;
    let rounded_up = "a radical inverse just below 1 can round up to 1 in f32, which is the edge \
                      of the next pixel (or, wrapped, the opposite edge of this one): a position \
                      must stay below 1";
    let mistake = if !got.is_finite() {
        "the position is not a number"
    } else if got.x == 1.0 || got.y == 1.0 {
        rounded_up
    } else if near(got, point + shift) {
        "the shifted point leaves the pixel: the shift moves the points around the pixel as on \
         a torus, so what passes 1 comes back in at 0"
    } else if inside && wrapped_from_one {
        rounded_up
    } else if near(got, point) && !unshifted {
        "the pixel's shift is not applied: every pixel would get the same points, and the image \
         their pattern"
    } else if unshifted && near(got, Vec2::new(point.y, point.x)) && index > 0 {
        "the bases are swapped: base 2 gives x, base 3 gives y"
    } else if unshifted
        && (got.x - got.y).abs() <= 1e-6
        && (near(got, Vec2::splat(point.x)) || near(got, Vec2::splat(point.y)))
    {
        "both coordinates use the same base, so every point lies on the diagonal: x and y need \
         different bases (2 for x, 3 for y)"
    } else if !inside {
        "the position must stay in [0, 1)^2, inside the pixel"
    } else {
        "the position should be point `index` of the Halton sequence (bases 2 and 3), moved by \
         the shift and wrapped into [0, 1)"
    };
    Some(format!(
        "{mistake}.\n  halton_position({index}, shift {shift}) gave {got}, expected {expected}"
    ))
}

#[test]
fn exercise_halton_position_is_the_shifted_sequence() {
    let unshifted = HALTON_POINTS.map(|(index, p)| (index, Vec2::ZERO, p));
    for (index, shift, expected) in unshifted.into_iter().chain(SHIFTED_HALTON_POINTS) {
        let got = halton_position(index, shift);
        if let Some(mistake) = halton_position_mistake(index, shift, expected, got) {
            panic!("halton_position: {mistake}");
        }
    }
}

#[test]
fn exercise_halton_position_stratifies_the_pixel() {
    // The first 6 points fall one into each cell of a 2 x 3 grid, the first 36 one into each
    // cell of 4 x 9; a shift moves the grid but keeps one point per cell.
    for shift in [Vec2::ZERO, Vec2::new(0.37, 0.81)] {
        for (columns, rows) in [(2u32, 3u32), (4, 9)] {
            let n = columns * rows;
            let mut hits = vec![0; n as usize];
            for index in 0..u64::from(n) {
                let p = halton_position(index, shift);
                // Undo the shift on the torus before finding the cell.
                let q = (p - shift + Vec2::ONE).fract();
                let column = ((q.x * columns as f32 + 1e-4) as u32).min(columns - 1);
                let row = ((q.y * rows as f32 + 1e-4) as u32).min(rows - 1);
                hits[(row * columns + column) as usize] += 1;
            }
            assert!(
                hits.iter().all(|&h| h == 1),
                "halton_position: the first {n} points (shift {shift}) should fall one into each \
                 cell of a {columns} x {rows} grid, but the cells, row by row, got {hits:?}"
            );
        }
    }
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
fn the_halton_points_of_a_pixel_are_its_shifted_sequence() {
    let pixel = UVec2::new(2, 7);
    let shift = HaltonSampler::pixel_shift(3, pixel);
    let mut s = PixelSampler::new(PixelSamplerKind::Halton, 8, 3).unwrap();
    for (i, p) in s.positions(pixel, 8).into_iter().enumerate() {
        assert_eq!(p, halton_position(i as u64, shift));
    }
}
