//! Chapter 02's generators in three dimensions: consecutive triples of a generator's numbers
//! as points of the unit cube, which the page turns to look at from any side, and the share of
//! them on RANDU's planes, from the chapter's own [`Generator`]s and lattice test.

use ch02_monte_carlo::rng::{Generator, consecutive_triples, fraction_on_randu_planes};

use crate::{buffers, outcome};

/// How close to one of RANDU's planes a triple must lie to count as on it: far below the
/// spacing of a good generator's values, far above the rounding of RANDU's exact ones.
const ON_A_PLANE: f64 = 1e-6;

/// How many generators there are.
#[unsafe(no_mangle)]
pub extern "C" fn generator_count() -> u32 {
    Generator::ALL.len() as u32
}

/// Puts the name of generator `index` in the text buffer; gives its length (0 out of range).
#[unsafe(no_mangle)]
pub extern "C" fn generator_name(index: u32) -> u32 {
    let name = Generator::ALL.get(index as usize).map_or("", |g| g.name());
    buffers::set_text(name)
}

/// Puts `count` consecutive triples of generator `index` started from `seed` in the number
/// buffer, `x, y, z` after each other, then the share of them on RANDU's planes as the last
/// number. Gives how many numbers there are, or `u32::MAX` for a generator that does not exist.
#[unsafe(no_mangle)]
pub extern "C" fn generator_triples(index: u32, count: u32, seed: u32) -> u32 {
    outcome::run(|| {
        let Some(generator) = Generator::ALL.get(index as usize) else {
            buffers::set_text("no such generator");
            return u32::MAX;
        };
        let triples = consecutive_triples(
            &mut generator.new_source(u64::from(seed)),
            count.min(1_000_000) as usize,
        );
        let mut numbers: Vec<f64> = triples.iter().flatten().copied().collect();
        numbers.push(fraction_on_randu_planes(&triples, ON_A_PLANE));
        buffers::set_numbers(numbers)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn index_of(name: &str) -> u32 {
        Generator::ALL
            .iter()
            .position(|g| g.name() == name)
            .unwrap() as u32
    }

    #[test]
    fn randu_lies_on_its_planes_and_pcg_does_not() {
        let share_on_planes = |name| {
            let length = generator_triples(index_of(name), 2000, 7);
            assert_eq!(length, 3 * 2000 + 1);
            *buffers::numbers().last().unwrap()
        };
        assert_eq!(share_on_planes("randu"), 1.0);
        assert!(share_on_planes("pcg32") < 0.01);
        assert!(share_on_planes("mt19937") < 0.01);
    }

    #[test]
    fn names_come_back_and_unknown_generators_are_refused() {
        for index in 0..generator_count() {
            generator_name(index);
            assert_eq!(buffers::text(), Generator::ALL[index as usize].name());
        }
        assert_eq!(generator_triples(99, 10, 1), u32::MAX);
        assert_eq!(generator_name(99), 0);
    }
}
