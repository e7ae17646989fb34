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

/// What is wrong with `got = strata_grid(spp)`, in words; `None` if right.
fn strata_grid_mistake(spp: u64, got: Option<(u32, u32)>) -> Option<String> {
    // The squarest grid: the largest divisor not above the square root gives the rows.
    let expected = (spp > 0)
        .then(|| {
            let rows = (1..=spp.isqrt())
                .rev()
                .find(|&r| spp.is_multiple_of(r))
                .unwrap();
            Some((u32::try_from(spp / rows).ok()?, u32::try_from(rows).ok()?))
        })
        .flatten();
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
             allows: the rows are the largest divisor of {spp} not above its square root"
        ),
    };
    Some(format!(
        "{mistake}.\n  strata_grid({spp}) gave {got:?}, expected {expected:?}"
    ))
}

#[test]
fn exercise_strata_grid_is_as_square_as_the_count_allows() {
    let counts = [
        1,
        2,
        4,
        8,
        12,
        7,
        18,
        64,
        4096,
        1_000_000_000,
        // Squares of large primes, where a square root off by one finds no divisor near it.
        67_108_859u64 * 67_108_859,
        4_294_967_291u64 * 4_294_967_291,
        // The smallest prime above u32::MAX: a single row too long to count in u32.
        4_294_967_311,
        0,
    ];
    for spp in counts {
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
        if let Some(mistake) = strata_grid_mistake(spp, got) {
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

/// The radical inverse written out by hand: `digits` of `index` in `base`, lowest first.
fn mirrored(base: u64, digits: &[u64]) -> f64 {
    let mut value = 0.0;
    let mut scale = 1.0 / base as f64;
    for &digit in digits {
        value += digit as f64 * scale;
        scale /= base as f64;
    }
    value
}

/// The digits of `index` in `base`, lowest first.
fn digits_of(base: u64, mut index: u64) -> Vec<u64> {
    let mut digits = Vec::new();
    while index > 0 {
        digits.push(index % base);
        index /= base;
    }
    digits
}

/// What is wrong with `got = radical_inverse(base, index)`, in words; `None` if right.
fn radical_inverse_mistake(base: u32, index: u64, got: f64) -> Option<String> {
    let b = u64::from(base);
    let digits = digits_of(b, index);
    let expected = mirrored(b, &digits);
    if (got - expected).abs() <= 1e-12 {
        return None;
    }
    let written = digits.iter().rev().map(u64::to_string).collect::<String>();
    let not_mirrored = {
        let mut highest_first = digits.clone();
        highest_first.reverse();
        mirrored(b, &highest_first)
    };
    let mistake = if !got.is_finite() {
        "the value is not a number".to_string()
    } else if (got - digits.iter().sum::<u64>() as f64 / b as f64).abs() <= 1e-12 {
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
    // First a few indices of several digits, on which the usual slips all differ.
    let mut cases: Vec<(u32, u64)> = vec![(2, 11), (3, 7), (5, 38), (2, 6)];
    for base in [2, 3, 5, 7] {
        cases.extend((0..30).map(|index| (base, index)));
    }
    cases.extend([
        (2, 1 << 40),
        (3, 3u64.pow(20) + 5),
        (2, u64::MAX),
        (3, u64::MAX),
    ]);
    for (base, index) in cases {
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
                            digits_of(u64::from(base), index).len()
                        )
                    } else {
                        String::new()
                    }
                )
            });
        if let Some(mistake) = radical_inverse_mistake(base, index, got) {
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

/// What is wrong with `got = halton_position(index, shift)`, in words; `None` if right.
fn halton_position_mistake(index: u64, shift: Vec2, got: Vec2) -> Option<String> {
    let unit = |v: f64| (v as f32).min(ONE_MINUS_EPSILON);
    let point = Vec2::new(
        unit(radical_inverse(2, index)),
        unit(radical_inverse(3, index)),
    );
    let wrap = |s: f32| if s >= 1.0 { s - 1.0 } else { s };
    let expected = Vec2::new(wrap(point.x + shift.x), wrap(point.y + shift.y));
    let inside = got.cmpge(Vec2::ZERO).all() && got.cmplt(Vec2::ONE).all();
    if inside && (got - expected).abs().max_element() <= 1e-6 {
        return None;
    }
    let near = |a: Vec2, b: Vec2| (a - b).abs().max_element() <= 1e-6;
    let swapped = Vec2::new(wrap(point.y + shift.x), wrap(point.x + shift.y));
    let base_2_twice = Vec2::new(point.x, point.x) + shift;
    let base_3_twice = Vec2::new(point.y, point.y) + shift;
    let wrap2 = |p: Vec2| Vec2::new(wrap(p.x), wrap(p.y));
    let rounded = Vec2::new(
        radical_inverse(2, index) as f32,
        radical_inverse(3, index) as f32,
    );
    let mistake = if !got.is_finite() {
        "the position is not a number"
    } else if got.x == 1.0
        || got.y == 1.0
        || (rounded != point && near(got, wrap2(rounded + shift)))
    {
        "a radical inverse just below 1 can round up to 1 in f32, which is the edge of the next \
         pixel (or, wrapped, the opposite edge of this one): a position must stay below 1"
    } else if near(got, point + shift) {
        "the shifted point leaves the pixel: the shift moves the points around the pixel as on \
         a torus, so what passes 1 comes back in at 0"
    } else if near(got, point) && shift != Vec2::ZERO {
        "the pixel's shift is not applied: every pixel would get the same points, and the image \
         their pattern"
    } else if near(got, swapped) && index > 0 {
        "the bases are swapped: base 2 gives x, base 3 gives y"
    } else if near(got, wrap2(base_2_twice)) || near(got, wrap2(base_3_twice)) {
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
    let mut cases: Vec<(u64, Vec2)> = (0..12).map(|i| (i, Vec2::ZERO)).collect();
    cases.extend([
        (1, Vec2::new(0.75, 0.8)),
        (3, Vec2::new(0.1, 0.95)),
        (5, Vec2::new(0.6, 0.3)),
        (7, Vec2::splat(ONE_MINUS_EPSILON)),
        (0, Vec2::new(0.3, 0.7)),
        // The largest f32 below 1 in x: the radical inverse 1 - 2^-25 rounds up in f32.
        ((1 << 25) - 1, Vec2::ZERO),
    ]);
    for (index, shift) in cases {
        let got = halton_position(index, shift);
        if let Some(mistake) = halton_position_mistake(index, shift, got) {
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
