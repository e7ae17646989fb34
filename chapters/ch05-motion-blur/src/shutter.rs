//! The shutter: open at `open`, closed at `close`, and every time in between equally likely.
//!
//! A camera ray gets the time a uniform `u` picks in the interval; the rays its path spawns
//! get theirs from the tracer ([`path`](crate::path)). Averaging many instants is the motion
//! blur.

use std::fmt;

/// The shutter interval `[open, close]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shutter {
    /// When the shutter opens.
    pub open: f32,
    /// When it closes; `close == open` is an instant, and no time is sampled.
    pub close: f32,
}

/// Why a shutter interval is refused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShutterError {
    /// A time is NaN or infinite.
    NotFinite,
    /// The shutter closes before it opens.
    ClosesBeforeOpening,
}

impl fmt::Display for ShutterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ShutterError::NotFinite => write!(f, "shutter times must be finite numbers"),
            ShutterError::ClosesBeforeOpening => {
                write!(f, "the shutter must close at or after the time it opens")
            }
        }
    }
}

impl std::error::Error for ShutterError {}

impl Shutter {
    /// An instant at time 0: no motion blur.
    pub const INSTANT: Shutter = Shutter {
        open: 0.0,
        close: 0.0,
    };

    /// The interval `[open, close]`, checked.
    pub fn new(open: f32, close: f32) -> Result<Self, ShutterError> {
        if !open.is_finite() || !close.is_finite() || !(close - open).is_finite() {
            return Err(ShutterError::NotFinite);
        }
        if close < open {
            return Err(ShutterError::ClosesBeforeOpening);
        }
        Ok(Self { open, close })
    }

    /// How long the shutter is open.
    pub fn length(&self) -> f32 {
        self.close - self.open
    }

    /// Whether the shutter is open for no time at all.
    pub fn is_instant(&self) -> bool {
        self.close <= self.open
    }

    // ANCHOR: time_at
    /// The time a uniform `u` in `[0, 1)` picks: uniform over the interval, so that the image
    /// is the average over the time the shutter is open, with `u = 0` the moment it opens.
    /// Never outside `[open, close]` for any `u` in `[0, 1]`, whatever float rounding does.
    pub fn time_at(&self, u: f32) -> f32 {
        // BEGIN SOLUTION
        (self.open + u * self.length()).clamp(self.open, self.close)
        // END SOLUTION
    }
    // ANCHOR_END: time_at
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What is wrong with `time = shutter.time_at(u)`, which should be `expected`, in words;
    /// `None` if it is right.
    fn time_at_mistake(shutter: &Shutter, u: f32, expected: f64, time: f32) -> Option<String> {
        let (open, close) = (f64::from(shutter.open), f64::from(shutter.close));
        let tolerance = 4.0 * f64::from(f32::EPSILON) * open.abs().max(close.abs()).max(1.0);
        let near = |x: f64| (f64::from(time) - x).abs() <= tolerance;
        if near(expected) {
            if time < shutter.open || time > shutter.close {
                return Some(format!(
                    "it is outside the interval [{open}, {close}]: no ray may see the world \
                     before the shutter opens or after it closes (float rounding can carry a \
                     sum one step past the end; what keeps the time inside?)"
                ));
            }
            return None;
        }
        let why = if near(f64::from(u)) {
            "u was given back as it is: u is a fraction of the shutter interval, not a time, \
             and has to be mapped onto [open, close]"
        } else if near(close - f64::from(u) * (close - open)) {
            "the interval is run backwards: u = 0 is the moment the shutter opens"
        } else if near(open + f64::from(u) * close) {
            "u was scaled by the closing time instead of the interval's length"
        } else if near(f64::from(u) * (close - open)) {
            "the interval starts at `open`, not at 0"
        } else {
            "u should pick the time that fraction of the way through the interval"
        };
        Some(format!("the time should be {expected}: {why}"))
    }

    /// Fails, saying what is wrong, if `time_at` of the shutter open from `open` to `close`
    /// is wrong at any of `us`, whose times should be `expected`.
    fn check_time_at(open: f32, close: f32, us: &[f32], expected: &[f64]) {
        let shutter = Shutter::new(open, close).unwrap();
        for (&u, &expected) in us.iter().zip(expected) {
            let time = shutter.time_at(u);
            if let Some(mistake) = time_at_mistake(&shutter, u, expected, time) {
                panic!(
                    "Shutter::time_at: the shutter open from {open} to {close} and u = {u} \
                     gave the time {time}, but {mistake}"
                );
            }
        }
    }

    #[test]
    fn exercise_time_at_maps_u_onto_the_interval() {
        // Each shutter interval and the times of u = 0, 0.1, 0.5, 0.75 and 0.999, worked out
        // beforehand in f64 from the f32 values.
        #[rustfmt::skip]
        let cases: [(f32, f32, [f64; 5]); 5] = [
            (2.0, 6.0, [2.0, 2.4000000059604645, 4.0, 5.0, 5.996000051498413]),
            (-1.5, 0.5, [-1.5, -1.2999999970197678, -0.5, 0.0, 0.49800002574920654]),
            (0.25, 0.75, [0.25, 0.30000000074505806, 0.5, 0.625, 0.7495000064373016]),
            (0.0, 1.0, [0.0, 0.10000000149011612, 0.5, 0.75, 0.9990000128746033]),
            (3.0, 3.0, [3.0; 5]),
        ];
        for (open, close, expected) in cases {
            check_time_at(open, close, &[0.0, 0.1, 0.5, 0.75, 0.999], &expected);
        }
    }

    #[test]
    fn exercise_time_at_never_leaves_the_interval() {
        // Intervals where float rounding can carry the time of u = 1 past `close` in f32, and
        // the times of u = 0, 0.3, just below 1 and 1, worked out beforehand in f64.
        #[rustfmt::skip]
        let cases: [(f32, f32, [f64; 4]); 4] = [
            (-421.926_57, -67.055_67, [-421.92657470703125, -315.4652995720994, -67.05569284384865, -67.05567169189453]),
            (-81_375_136.0, 3_248_766.0, [-81375136.0, -55987964.39120448, 3248760.956022382, 3248766.0]),
            (-1.989_266, 0.001_094_891_6, [-1.989266037940979, -1.3921577353597434, 0.0010947729385462068, 0.0010948915733024478]),
            (1e7, 1e7 + 3.0, [10000000.0, 10000000.900000036, 10000002.999999821, 10000003.0]),
        ];
        for (open, close, expected) in cases {
            check_time_at(
                open,
                close,
                &[0.0, 0.3, 1.0 - f32::EPSILON / 2.0, 1.0],
                &expected,
            );
        }
    }

    #[test]
    fn times_stay_inside_the_interval() {
        let shutter = Shutter::new(1e7, 1e7 + 3.0).unwrap();
        for u in [0.0, 0.3, 1.0 - 1e-7, 1.0] {
            let time = shutter.time_at(u);
            assert!(
                (shutter.open..=shutter.close).contains(&time),
                "{u}: {time}"
            );
        }
        assert_eq!(Shutter::new(0.5, 0.5).unwrap().time_at(0.7), 0.5);
    }

    #[test]
    fn bad_intervals_are_refused() {
        assert_eq!(
            Shutter::new(1.0, 0.5),
            Err(ShutterError::ClosesBeforeOpening)
        );
        assert_eq!(Shutter::new(f32::NAN, 0.5), Err(ShutterError::NotFinite));
        assert_eq!(
            Shutter::new(0.0, f32::INFINITY),
            Err(ShutterError::NotFinite)
        );
        assert_eq!(
            Shutter::new(-f32::MAX, f32::MAX),
            Err(ShutterError::NotFinite)
        );
        assert!(Shutter::new(0.0, 0.0).unwrap().is_instant());
    }
}
