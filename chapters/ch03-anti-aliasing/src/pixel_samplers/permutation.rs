//! A random order of `0..n` without building it: how each dimension deals out its strata.
//!
//! A sampler that stratifies every dimension of a sample must not give sample `k` stratum `k`
//! in all of them: the lens point, the time and the light point of one sample would then sit
//! in the same corner of their squares together, and the samples would lie along the diagonal
//! of the cube of all dimensions instead of filling it. Each dimension therefore hands its
//! strata to the pixel's samples in an order of its own, a permutation chosen by a key.

/// Element `i` of a random permutation of `0..n` chosen by `key`, without building the
/// permutation (Kensler's hash-based permutation, as in pbrt-v4's `PermutationElement`).
///
/// `i` must be below `n`: the walk below only ends for an element of the order, so any other
/// `i` is refused rather than left to loop.
pub fn permutation_element(i: u32, n: u32, key: u32) -> u32 {
    assert!(
        i < n.max(1),
        "permutation_element: there is no element {i} in an order of 0..{n}; the index must be below n"
    );
    let p = key;
    let mut w = n.max(1) - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    let mut i = i;
    loop {
        i ^= p;
        i = i.wrapping_mul(0xe170_893d);
        i ^= p >> 16;
        i ^= (i & w) >> 4;
        i ^= p >> 8;
        i = i.wrapping_mul(0x0929_eb3f);
        i ^= p >> 23;
        i ^= (i & w) >> 1;
        i = i.wrapping_mul(1 | (p >> 27));
        i = i.wrapping_mul(0x6935_fa69);
        i ^= (i & w) >> 11;
        i = i.wrapping_mul(0x74dc_b303);
        i ^= (i & w) >> 2;
        i = i.wrapping_mul(0x9e50_1cc3);
        i ^= (i & w) >> 2;
        i = i.wrapping_mul(0xc860_a3df);
        i &= w;
        i ^= i >> 5;
        if i < n {
            break;
        }
    }
    i.wrapping_add(p) % n.max(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn permutations_are_permutations_and_differ_by_key() {
        for n in [1u32, 2, 5, 16, 33] {
            for key in [0u32, 1, 0xdead_beef] {
                let mut seen: Vec<u32> = (0..n).map(|i| permutation_element(i, n, key)).collect();
                seen.sort();
                assert_eq!(seen, (0..n).collect::<Vec<_>>(), "n {n} key {key}");
            }
        }
        let a: Vec<u32> = (0..16).map(|i| permutation_element(i, 16, 1)).collect();
        let b: Vec<u32> = (0..16).map(|i| permutation_element(i, 16, 2)).collect();
        assert_ne!(a, b);
    }
}
