//! Pearson's statistic, with the bins that expect too little pooled.

use super::MIN_EXPECTED_COUNT;

/// The sum of Pearson's terms after pooling, with the number of bins that entered it.
#[derive(Debug, PartialEq)]
pub(super) struct Pearson {
    /// `Σ (O - E)² / E` over the kept bins, the pool counting as one.
    pub(super) statistic: f64,
    /// The bins in the sum, the pool included.
    pub(super) kept_bins: usize,
    /// The bins that went into the pool.
    pub(super) pooled_bins: usize,
}

/// Pearson's `X²` with the bins expecting fewer than [`MIN_EXPECTED_COUNT`] samples pooled
/// into a single bin. Bins expecting nothing and observing nothing carry no information and
/// are skipped. (A bin expecting nothing but observing something never gets here: that
/// sample is impossible and fails the test before any statistics.)
///
/// A bin may expect a tiny count merely because its edge touches the domain: the row of bins
/// just below the hemisphere's horizon has a nonzero density on its top edge `cos θ = 0`, and
/// nowhere else. Such bins land in the pool, where they change nothing.
pub(super) fn pearson_with_pooling(observed: &[u64], expected: &[f64]) -> Pearson {
    let term = |o: f64, e: f64| (o - e) * (o - e) / e;
    let mut result = Pearson {
        statistic: 0.0,
        kept_bins: 0,
        pooled_bins: 0,
    };
    let (mut pooled_observed, mut pooled_expected) = (0.0, 0.0);
    for (&o, &e) in observed.iter().zip(expected) {
        if e == 0.0 && o == 0 {
            continue;
        }
        if e < MIN_EXPECTED_COUNT {
            pooled_observed += o as f64;
            pooled_expected += e;
            result.pooled_bins += 1;
        } else {
            result.statistic += term(o as f64, e);
            result.kept_bins += 1;
        }
    }
    if result.pooled_bins > 0 {
        result.statistic += term(pooled_observed, pooled_expected);
        result.kept_bins += 1;
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn small_bins_are_pooled() {
        let observed = [10, 3, 1, 0, 0];
        let expected = [10.0, 2.0, 2.0, 0.5, 0.0];
        let pearson = pearson_with_pooling(&observed, &expected);
        // The bin expecting 10 is kept; three are pooled into one expecting 4.5 and
        // observing 4; the empty bin expecting nothing is skipped.
        assert_eq!(pearson.kept_bins, 2);
        assert_eq!(pearson.pooled_bins, 3);
        assert_relative_eq!(pearson.statistic, 0.25 / 4.5);
    }
}
