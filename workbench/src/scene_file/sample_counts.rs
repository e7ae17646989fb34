//! How many samples per pixel Mitsuba 3 really takes with each of its samplers.
//!
//! Mitsuba's structured samplers lay out their points for counts of a particular form, and
//! round any other count up to the next one, with a warning: a file asking for 10 samples of
//! the `stratified` sampler renders 16 in Mitsuba. The reader does the same, so that a render
//! of the file takes the samples Mitsuba takes and the two are compared at equal counts.
//! Measured with Mitsuba 3.9.1 (`mi.load_dict({"type": ..., "sample_count": n}).sample_count()`)
//! for n from 1 to 1000.

/// The count Mitsuba 3 renders when a `type_name` sampler is asked for `asked` samples; `None`
/// if that count does not fit in a `u32`.
pub fn mitsuba_sample_count(type_name: &str, asked: u32) -> Option<u32> {
    let asked = u64::from(asked.max(1));
    // The smallest integer whose square is at least `asked`.
    let side = {
        let mut side = (asked as f64).sqrt() as u64;
        while side * side < asked {
            side += 1;
        }
        while side > 1 && (side - 1) * (side - 1) >= asked {
            side -= 1;
        }
        side
    };
    let count = match type_name {
        // A square grid of strata.
        "stratified" => side * side,
        // A grid of `columns x rows`, the columns the floor of the square root.
        "multijitter" => {
            let mut columns = (asked as f64).sqrt() as u64;
            while columns * columns > asked {
                columns -= 1;
            }
            while (columns + 1) * (columns + 1) <= asked {
                columns += 1;
            }
            columns * asked.div_ceil(columns)
        }
        // The square of a prime: the Bose construction of an orthogonal array.
        "orthogonal" => {
            let mut p = side.max(2);
            while !is_prime(p) {
                p += 1;
            }
            p * p
        }
        // A power of four, at least 4.
        "ldsampler" => {
            let mut count = 4;
            while count < asked {
                count *= 4;
            }
            count
        }
        _ => asked,
    };
    u32::try_from(count).ok()
}

fn is_prime(n: u64) -> bool {
    n >= 2
        && (2..)
            .take_while(|d| d * d <= n)
            .all(|d| !n.is_multiple_of(d))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_are_rounded_as_mitsuba_3_rounds_them() {
        // Measured with Mitsuba 3.9.1, for the counts in the first row.
        let asked = [
            1, 2, 3, 4, 5, 7, 8, 10, 12, 16, 17, 32, 50, 64, 65, 100, 256, 257, 1000,
        ];
        let measured: [(&str, [u32; 19]); 5] = [
            (
                "independent",
                [
                    1, 2, 3, 4, 5, 7, 8, 10, 12, 16, 17, 32, 50, 64, 65, 100, 256, 257, 1000,
                ],
            ),
            (
                "stratified",
                [
                    1, 4, 4, 4, 9, 9, 9, 16, 16, 16, 25, 36, 64, 64, 81, 100, 256, 289, 1024,
                ],
            ),
            (
                "multijitter",
                [
                    1, 2, 3, 4, 6, 8, 8, 12, 12, 16, 20, 35, 56, 64, 72, 100, 256, 272, 1023,
                ],
            ),
            (
                "orthogonal",
                [
                    4, 4, 4, 4, 9, 9, 9, 25, 25, 25, 25, 49, 121, 121, 121, 121, 289, 289, 1369,
                ],
            ),
            (
                "ldsampler",
                [
                    4, 4, 4, 4, 16, 16, 16, 16, 16, 16, 64, 64, 64, 64, 256, 256, 256, 1024, 1024,
                ],
            ),
        ];
        for (type_name, counts) in measured {
            let ours: Vec<u32> = asked
                .iter()
                .map(|&n| mitsuba_sample_count(type_name, n).unwrap())
                .collect();
            assert_eq!(ours, counts, "{type_name}");
        }
        assert_eq!(mitsuba_sample_count("stratified", u32::MAX), None);
        assert_eq!(
            mitsuba_sample_count("independent", u32::MAX),
            Some(u32::MAX)
        );
    }
}
