//! The shutter: open at `open`, closed at `close`, and every time in between equally likely.
//!
//! A camera ray gets the time `open + u (close - open)` for a uniform `u`; every ray of its
//! path (reflections, refractions, shadow rays) keeps that time, so a whole path sees the
//! world at one instant. Averaging many instants is the motion blur.

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
    /// The time a uniform `u` in `[0, 1)` picks: uniform over the interval, so the image is the
    /// average over the time the shutter is open. Stays inside `[open, close]` for any `u` in
    /// `[0, 1]`, even when rounding would carry `open + u * length` past `close`.
    pub fn time_at(&self, u: f32) -> f32 {
        (self.open + u * self.length()).clamp(self.open, self.close)
    }
    // ANCHOR_END: time_at
}

#[cfg(test)]
mod tests {
    use super::*;

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
