//! The numbers a wrong answer produces, for the property tests that every entry point a
//! chapter calls with a computed value answers them in words or numbers, never with a panic.
//!
//! A student's reflection that forgets to normalise, a light sample on the shaded point itself,
//! a division by a zero `cos θ`: each gives NaN, an infinity, a zero or a huge number, and it
//! flows into `common` (a ray to trace, a `uv` to look a texture up at, a film position to add
//! a sample at). Ordinary numbers are drawn too, so that the special ones meet every path of
//! the code they are thrown at.

use glam::{Vec2, Vec3};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

/// The configuration of these property tests: `cases` cases from a fixed seed (a run is
/// repeatable, and CI never fails by the luck of the draw), no failure files written into the
/// source tree.
pub fn config(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(20_260_117),
        failure_persistence: None,
        ..Config::default()
    }
}

/// One number: NaN, an infinity, a zero of either sign, a huge or a subnormal number, a
/// number on the scale of a scene, or any float at all.
pub fn number() -> impl Strategy<Value = f32> + Clone {
    prop_oneof![
        prop::sample::select(vec![
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            0.0,
            -0.0,
            1e30,
            -1e30,
            f32::MAX,
            f32::MIN_POSITIVE,
            1e-40,
            -1e-45,
            1.0,
        ]),
        -10.0f32..10.0,
        any::<f32>(),
    ]
}

/// A number of the figures' and metrics' `f64`: the same kinds as [`number`], with the
/// extremes of `f64` (whose differences overflow, and whose smallest steps are subnormal).
pub fn number_f64() -> impl Strategy<Value = f64> + Clone {
    prop_oneof![
        prop::sample::select(vec![
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.0,
            -0.0,
            1e300,
            -1e300,
            f64::MAX,
            f64::MIN,
            5e-324,
            1e-310,
            1.0,
        ]),
        -10.0f64..10.0,
        number().prop_map(f64::from),
        any::<f64>(),
    ]
}

/// A pair of [`number`]s.
pub fn vec2() -> impl Strategy<Value = Vec2> + Clone {
    (number(), number()).prop_map(|(x, y)| Vec2::new(x, y))
}

/// A vector: three [`number`]s, or one of them in every component (a NaN vector, a zero one).
pub fn vec3() -> impl Strategy<Value = Vec3> + Clone {
    prop_oneof![
        (number(), number(), number()).prop_map(|(x, y, z)| Vec3::new(x, y, z)),
        number().prop_map(Vec3::splat),
    ]
}
