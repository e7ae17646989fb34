//! How much to render: a sample count, or a wall-clock time.

use std::time::Duration;

/// The budget of a render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Budget {
    /// Exactly this many samples per pixel.
    Samples(u64),
    /// Keep adding passes until this many seconds have passed (at least one pass).
    Seconds(f64),
}

/// The largest pass, in samples per pixel. Passes end with a merge, a progress update and a
/// chance to stop; capping them keeps those frequent on long renders.
const MAX_PASS: u64 = 256;

impl Budget {
    /// The size of the next pass, given the samples per pixel done so far and the time
    /// spent, or `None` when the budget is spent.
    ///
    /// Passes double (1, 2, 4, ... up to a cap), so a short render is not slowed by
    /// bookkeeping and a timed render overshoots its time by at most about one pass.
    pub fn next_pass(&self, done_spp: u64, elapsed: Duration) -> Option<u64> {
        let doubling = done_spp.clamp(1, MAX_PASS);
        match *self {
            Budget::Samples(total) => (done_spp < total).then(|| doubling.min(total - done_spp)),
            Budget::Seconds(seconds) => {
                if done_spp == 0 {
                    return Some(1);
                }
                let left = seconds - elapsed.as_secs_f64();
                // A NaN budget too is spent after its first pass, rather than never.
                if left.is_nan() || left <= 0.0 {
                    return None;
                }
                // Estimate the pass that fits in the time left from the rate so far.
                let per_spp = elapsed.as_secs_f64() / done_spp as f64;
                let fits = if per_spp > 0.0 {
                    (left / per_spp).floor() as u64
                } else {
                    doubling
                };
                Some(fits.clamp(1, doubling))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sample_budgets_are_met_exactly() {
        for total in [1, 2, 3, 7, 64, 1000, 4096] {
            let mut done = 0;
            let mut passes = 0;
            while let Some(p) = Budget::Samples(total).next_pass(done, Duration::ZERO) {
                assert!(p >= 1);
                done += p;
                passes += 1;
            }
            assert_eq!(done, total);
            assert!(
                passes <= 1 + 8 + total / MAX_PASS + 1,
                "{total}: {passes} passes"
            );
        }
    }

    #[test]
    fn time_budgets_stop_when_time_is_up() {
        let b = Budget::Seconds(1.0);
        assert_eq!(b.next_pass(0, Duration::from_secs(5)), Some(1));
        assert_eq!(b.next_pass(4, Duration::from_secs(1)), None);
        // Half the time used for 4 spp: the next pass may hold 4 more.
        assert_eq!(b.next_pass(4, Duration::from_millis(500)), Some(4));
        // A tenth of it used: doubling caps the pass at the samples done so far.
        assert_eq!(b.next_pass(4, Duration::from_millis(100)), Some(4));
    }

    #[test]
    fn a_budget_of_no_number_renders_one_pass() {
        for seconds in [f64::NAN, -1.0, 0.0] {
            let b = Budget::Seconds(seconds);
            assert_eq!(b.next_pass(0, Duration::ZERO), Some(1));
            assert_eq!(b.next_pass(1, Duration::from_millis(1)), None, "{seconds}");
        }
    }
}
