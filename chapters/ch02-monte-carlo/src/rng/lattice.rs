//! RANDU's 15 planes, found with one line of arithmetic.
//!
//! For RANDU every three consecutive numbers `(x, y, z)` satisfy `9x - 6y + z = integer` (see
//! [`super::Randu`] for why). For a good generator `9x - 6y + z` is just some real number
//! between -6 and 10, and landing within `10^-6` of an integer happens about once in half a
//! million triples. So a few hundred triples are enough to tell RANDU apart: a much sharper
//! test than any chi-square on cells (see [`super::serial_chi2_3d`]).

use rand::Rng;

use super::unit_f64;

/// `9x - 6y + z` for a triple of consecutive numbers: an integer in `-5..=9` for every RANDU
/// triple, so the value names the plane the triple lies on; continuous for a good generator.
pub fn randu_plane_index(triple: [f64; 3]) -> f64 {
    let [x, y, z] = triple;
    9.0 * x - 6.0 * y + z
}

/// `count` consecutive non-overlapping triples of numbers `word / 2^32` from `source`.
///
/// The full 32 bits are kept (not the 24 of an `f32`), so RANDU's numbers `x / 2^31` come out
/// exactly and its plane indices are exact integers, not merely close to them.
pub fn consecutive_triples<R: Rng + ?Sized>(source: &mut R, count: usize) -> Vec<[f64; 3]> {
    (0..count)
        .map(|_| {
            let x = unit_f64(source.next_u32());
            let y = unit_f64(source.next_u32());
            let z = unit_f64(source.next_u32());
            [x, y, z]
        })
        .collect()
}

/// The share of `triples` whose [`randu_plane_index`] lies within `tolerance` of an integer:
/// 1 for RANDU, about `2 * tolerance` for a good generator.
pub fn fraction_on_randu_planes(triples: &[[f64; 3]], tolerance: f64) -> f64 {
    if triples.is_empty() {
        return 0.0;
    }
    let on_a_plane = triples
        .iter()
        .filter(|&&triple| {
            let index = randu_plane_index(triple);
            (index - index.round()).abs() <= tolerance
        })
        .count();
    on_a_plane as f64 / triples.len() as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Generator;
    use std::collections::BTreeSet;

    #[test]
    fn randu_triples_lie_on_at_most_15_planes() {
        let triples = consecutive_triples(&mut Generator::Randu.new_source(12_345), 100_000);
        assert_eq!(
            fraction_on_randu_planes(&triples, 0.0),
            1.0,
            "exact integers"
        );
        let planes: BTreeSet<i64> = triples
            .iter()
            .map(|&triple| randu_plane_index(triple) as i64)
            .collect();
        assert!(planes.len() <= 15, "{planes:?}");
        assert!(
            planes.iter().all(|plane| (-5..=9).contains(plane)),
            "{planes:?}"
        );
    }

    #[test]
    fn good_generators_fill_the_space_between_the_planes() {
        for generator in [Generator::Minstd, Generator::Mt19937, Generator::Pcg32] {
            let triples = consecutive_triples(&mut generator.new_source(12_345), 100_000);
            let fraction = fraction_on_randu_planes(&triples, 1e-6);
            assert!(fraction < 0.01, "{generator}: {fraction}");
        }
    }

    #[test]
    fn the_index_of_a_chosen_point() {
        assert_eq!(randu_plane_index([0.5, 0.25, 0.0]), 3.0);
        assert_eq!(fraction_on_randu_planes(&[], 0.1), 0.0);
    }
}
