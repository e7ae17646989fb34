use super::*;
use common::film::{Film, PixelRect};
use glam::{UVec2, Vec3};

#[test]
fn defaults_are_mitsubas() {
    let new = |kind| ReconstructionFilter::new(kind, None).unwrap();
    assert_eq!(
        new(FilterKind::Box),
        ReconstructionFilter::Box { radius: 0.5 }
    );
    assert_eq!(
        new(FilterKind::Tent),
        ReconstructionFilter::Tent { radius: 1.0 }
    );
    assert_eq!(
        new(FilterKind::Gaussian),
        ReconstructionFilter::Gaussian {
            stddev: 0.5,
            radius: 2.0
        }
    );
    assert_eq!(
        new(FilterKind::Mitchell),
        ReconstructionFilter::Mitchell {
            radius: 2.0,
            b: 1.0 / 3.0,
            c: 1.0 / 3.0
        }
    );
    assert_eq!(
        ReconstructionFilter::new(FilterKind::Gaussian, Some(1.0)).unwrap(),
        ReconstructionFilter::Gaussian {
            stddev: 0.25,
            radius: 1.0
        }
    );
}

#[test]
fn bad_radii_are_refused_with_the_value() {
    for kind in FilterKind::ALL {
        for bad in [0.0, -1.0, f32::NAN, f32::INFINITY, 16.5, 1e30] {
            let err = ReconstructionFilter::new(kind, Some(bad)).unwrap_err();
            assert!(
                err.contains("radius") && err.contains(&bad.to_string()),
                "{err}"
            );
        }
        for good in [1e-3, 0.5, 16.0] {
            let filter = ReconstructionFilter::new(kind, Some(good)).unwrap();
            assert_eq!(filter.half_width(), good);
        }
    }
}

#[test]
fn exercise_tent_filter() {
    for (x, radius, expected) in [
        (0.0f32, 1.0f32, 1.0f32),
        (0.5, 1.0, 0.5),
        (-0.5, 1.0, 0.5),
        (0.5, 2.0, 0.75),
        (1.0, 1.0, 0.0),
        (1.5, 1.0, 0.0),
        (-3.0, 2.0, 0.0),
    ] {
        let got = tent_1d(x, radius);
        if (got - expected).abs() <= 1e-6 {
            continue;
        }
        let mistake = if x.abs() >= radius && got < 0.0 {
            "beyond the radius the tent must be 0: the straight line goes on below zero there, \
             and a negative weight is another filter"
        } else if x < 0.0 && (got - tent_1d(-x, radius)).abs() > 1e-6 {
            "the tent is symmetric: a sample left of the pixel centre weighs what one as far to \
             the right does"
        } else if radius != 1.0 && (got - tent_1d(x, 1.0)).abs() <= 1e-6 {
            // The same value as a tent of radius 1 gives at this x: the radius changed nothing.
            "the slope ignores the radius: the tent falls from 1 at the centre to 0 at the radius"
        } else {
            "the tent is 1 at the centre and falls in a straight line to 0 at the radius"
        };
        panic!(
            "tent_1d: {mistake}.\n  tent_1d({x}, radius {radius}) gave {got}, expected {expected}"
        );
    }
}

/// `∫ f(x) dx` over `[-radius, radius]` by the midpoint rule.
fn integral(f: impl Fn(f32) -> f32, radius: f32) -> f64 {
    let n = 100_000;
    let h = 2.0 * f64::from(radius) / n as f64;
    (0..n)
        .map(|i| f64::from(f((-f64::from(radius) + (i as f64 + 0.5) * h) as f32)) * h)
        .sum()
}

/// Parameters `B` and `C`, and the cubic's value at 13 points `x`.
type MitchellValues = (f32, f32, [(f32, f64); 13]);

#[test]
fn exercise_mitchell() {
    // The paper's cubic at a few points, for three choices of (B, C), worked out beforehand.
    let third = 1.0f32 / 3.0;
    #[rustfmt::skip]
    let table: [MitchellValues; 3] = [
        (third, third, [(0.0, 0.888888886), (0.3, 0.740388877), (0.7, 0.309055571), (-0.7, 0.309055571), (0.999, 0.0560570496), (1.0, 0.0555555572), (1.2, -0.0142222328), (1.5, -0.0347222233), (-1.5, -0.0347222233), (1.9, -0.00294444584), (2.0, 0.0), (2.5, 0.0), (-3.0, 0.0)]),
        (1.0, 0.0, [(0.0, 0.666666667), (0.3, 0.590166661), (0.7, 0.348166675), (-0.7, 0.348166675), (0.999, 0.16716716), (1.0, 0.166666667), (1.2, 0.0853333181), (1.5, 0.0208333333), (-1.5, 0.0208333333), (1.9, 0.000166666786), (2.0, 0.0), (2.5, 0.0), (-3.0, 0.0)]),
        (0.0, 0.5, [(0.0, 1.0), (0.3, 0.815499987), (0.7, 0.289500015), (-0.7, 0.289500015), (0.999, 0.000501992011), (1.0, 0.0), (1.2, -0.0640000076), (1.5, -0.0625), (-1.5, -0.0625), (1.9, -0.00450000203), (2.0, 0.0), (2.5, 0.0), (-3.0, 0.0)]),
    ];
    for (b, c, points) in table {
        for (x, expected) in points {
            let got = f64::from(mitchell_1d(x, b, c));
            if (got - expected).abs() <= 1e-5 {
                continue;
            }
            let mirrored = f64::from(mitchell_1d(-x, b, c));
            let mistake = if x.abs() >= 2.0 {
                "beyond |x| = 2 the filter is 0: its support is [-2, 2]"
            } else if expected != 0.0 && (got - 6.0 * expected).abs() <= 1e-4 {
                "it is six times the cubic: the whole polynomial of each piece is divided by 6"
            } else if x < 0.0 && (mirrored - got).abs() > 1e-6 {
                "the filter is symmetric: take |x| before choosing the piece"
            } else if x.abs() < 1.0 {
                "the inner piece (|x| < 1) is off: at x = 0 it is (6 - 2B) / 6"
            } else {
                "the outer piece (1 ≤ |x| < 2) is off: at x = 1 it is B / 6, and between \
                 1 and 2 the recommended B = C = 1/3 dips below 0"
            };
            panic!(
                "mitchell_1d: {mistake}.\n  mitchell_1d({x}, B = {b}, C = {c}) gave {got}, the \
                 paper's cubic gives {expected:.6}"
            );
        }
    }
    // The weights of a constant sum to one.
    let area = integral(|x| mitchell_1d(x, third, third), 2.0);
    assert!(
        (area - 1.0).abs() < 1e-4,
        "mitchell_1d: the filter's integral over [-2, 2] is {area}, not 1"
    );
}

/// What is wrong with `got = filter.evaluate_1d(x)`, which should be `expected`, in words;
/// `None` if right.
fn filter_profile_mistake(
    filter: ReconstructionFilter,
    x: f32,
    expected: f32,
    got: f32,
) -> Option<String> {
    if (got - expected).abs() <= 1e-6 {
        return None;
    }
    let near = |v: f32| (got - v).abs() <= 1e-6;
    let mistake = match filter {
        ReconstructionFilter::Mitchell { radius, b, c } if near(mitchell_1d(x, b, c)) => format!(
            "the Mitchell–Netravali cubic is used on its own support [-2, 2], whatever the \
             filter's radius ({radius}): x has to be stretched so that the radius lands where \
             the cubic ends"
        ),
        ReconstructionFilter::Mitchell { radius, b, c }
            if near(mitchell_1d(x * radius / 2.0, b, c)) =>
        {
            format!(
                "the Mitchell–Netravali cubic is stretched the wrong way: at x = {radius}, the \
                 filter's radius, the cubic should be at the end of its support, 2"
            )
        }
        ReconstructionFilter::Gaussian { stddev, radius }
            if near(gaussian_1d(x, radius, stddev)) =>
        {
            "the Gaussian's standard deviation and radius are swapped".to_string()
        }
        _ => {
            format!("this filter's profile is its own kernel with its own parameters ({filter:?})")
        }
    };
    Some(format!(
        "{mistake}.\n  {filter:?}.evaluate_1d({x}) gave {got}, expected {expected}"
    ))
}

#[test]
fn exercise_filter_profile() {
    let third = 1.0 / 3.0;
    let filters = [
        ReconstructionFilter::Box { radius: 0.7 },
        ReconstructionFilter::Tent { radius: 1.5 },
        ReconstructionFilter::Gaussian {
            stddev: 0.3,
            radius: 1.2,
        },
        ReconstructionFilter::Mitchell {
            radius: 1.0,
            b: third,
            c: third,
        },
        ReconstructionFilter::Mitchell {
            radius: 3.0,
            b: 1.0,
            c: 0.0,
        },
        ReconstructionFilter::Mitchell {
            radius: 2.0,
            b: 0.0,
            c: 0.5,
        },
    ];
    let xs = [
        0.0, 0.3, -0.3, 0.69, 0.71, -0.9, 1.0, 1.1, 1.4, 2.0, 2.5, -2.9, 3.1,
    ];
    // Each filter's profile at those x, worked out beforehand from the kernels and the
    // filters' parameters.
    #[rustfmt::skip]
    let profiles: [[f32; 13]; 6] = [
        [1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [1.0, 0.8, 0.8, 0.53999996, 0.52666664, 0.40000004, 0.3333333, 0.26666665, 0.06666666, 0.0, 0.0, 0.0, 0.0],
        [0.99966455, 0.6061952, 0.6061952, 0.07066989, 0.060440846, 0.01077354, 0.0035304583, 0.0008683973, 0.0, 0.0, 0.0, 0.0, 0.0],
        [0.8888889, 0.4208889, 0.4208889, -0.035450142, -0.03625663, -0.010222276, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [0.6666667, 0.6306667, 0.6306667, 0.50373465, 0.4956461, 0.41466665, 0.3703703, 0.3260741, 0.20207413, 0.049382847, 0.006172816, 4.9432118e-5, 0.0],
        [1.0, 0.8155, 0.8155, 0.3025135, 0.27661648, 0.06849996, 0.0, -0.040500004, -0.07199987, 0.0, 0.0, 0.0, 0.0],
    ];
    for (filter, profile) in filters.into_iter().zip(profiles) {
        for (x, expected) in xs.into_iter().zip(profile) {
            let got = filter.evaluate_1d(x);
            if let Some(mistake) = filter_profile_mistake(filter, x, expected, got) {
                panic!("evaluate_1d: {mistake}");
            }
        }
    }
}

#[test]
fn weights_vanish_outside_the_radius() {
    for kind in FilterKind::ALL {
        for radius in [1e-3, 0.5, 1.0, 2.0, 16.0] {
            let f = ReconstructionFilter::new(kind, Some(radius)).unwrap();
            let beyond = radius * 1.001 + 1e-6;
            for offset in [
                Vec2::new(beyond, 0.0),
                Vec2::new(0.0, -beyond),
                Vec2::splat(beyond),
            ] {
                assert_eq!(f.evaluate(offset), 0.0, "{f:?} at {offset}");
            }
            assert!(f.evaluate(Vec2::ZERO) > 0.0, "{f:?}");
        }
    }
}

#[test]
fn weights_are_multiples_of_the_quantum() {
    let mitchell = ReconstructionFilter::new(FilterKind::Mitchell, None).unwrap();
    for i in 0..1000 {
        let offset = Vec2::new(i as f32 * 0.0037 - 1.9, 1.3 - i as f32 * 0.0029);
        let w = mitchell.evaluate(offset);
        assert_eq!((w / WEIGHT_QUANTUM).fract(), 0.0, "{w}");
    }
}

fn whole(film: &Film) -> PixelRect {
    PixelRect {
        min: UVec2::ZERO,
        max: UVec2::new(film.width(), film.height()),
    }
}

/// Splats `count` pseudo-random samples of radiance `radiance(i)` into a `w x h` film.
fn splat(
    filter: &ReconstructionFilter,
    (width, height): (u32, u32),
    count: u32,
    radiance: impl Fn(u32) -> Vec3,
) -> Film {
    let mut film = Film::new(width, height);
    let mut tile = film.tile(whole(&film), filter);
    let mut state = 12345u64;
    let mut next = || {
        state = common::sampler::mix(state);
        common::sampler::unit_f32(state as u32)
    };
    for i in 0..count {
        let p = Vec2::new(next() * width as f32, next() * height as f32);
        tile.add_sample(p, radiance(i), filter);
    }
    film.merge(&tile);
    film
}

#[test]
fn the_weighted_average_of_a_constant_is_exactly_that_constant() {
    let constant = Vec3::new(0.7, 0.25, 3.0);
    for kind in FilterKind::ALL {
        for radius in [None, Some(1.5), Some(4.0)] {
            let filter = ReconstructionFilter::new(kind, radius).unwrap();
            let film = splat(&filter, (6, 5), 400, |_| constant);
            for y in 0..5 {
                for x in 0..6 {
                    let sum = film.pixel(x, y);
                    assert_ne!(
                        sum.weight, 0.0,
                        "{filter:?}: pixel ({x}, {y}) got no sample"
                    );
                    assert_eq!(sum.value().as_vec3(), constant, "{filter:?} ({x}, {y})");
                }
            }
        }
    }
}

#[test]
fn tiny_filters_stay_finite_and_leave_unreached_pixels_black() {
    for kind in FilterKind::ALL {
        let filter = ReconstructionFilter::new(kind, Some(1e-3)).unwrap();
        let film = splat(&filter, (8, 8), 64, |i| Vec3::splat(i as f32));
        let image = film.image();
        assert!(image.pixels.iter().all(|p| p.is_finite()), "{filter:?}");
        for y in 0..8 {
            for x in 0..8 {
                if film.pixel(x, y).weight == 0.0 {
                    assert_eq!(image.get(x, y), Vec3::ZERO);
                }
            }
        }
        // Random samples hardly ever land within 1/1000 of a pixel centre.
        let reached = (0..64).filter(|i| film.pixel(i % 8, i / 8).weight != 0.0);
        assert!(reached.count() < 4, "{filter:?}");
    }
}

#[test]
fn cancelling_mitchell_weights_give_black_or_a_bounded_value_never_infinity() {
    // Two samples whose Mitchell weights nearly cancel: one in the negative lobe, one where
    // the profile, falling from the centre, has the opposite value (found by bisection).
    let filter = ReconstructionFilter::new(FilterKind::Mitchell, None).unwrap();
    let negative = Vec2::new(1.4, 0.0);
    let target = -filter.evaluate_1d(negative.x);
    let (mut lo, mut hi) = (0.0f32, negative.x); // the profile falls all the way on [0, 1.4]
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if filter.evaluate_1d(mid) > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let mut worst = 0.0f64;
    for (i, x) in [lo, hi, 0.5 * (lo + hi)].into_iter().enumerate() {
        let mut film = Film::new(1, 1);
        let mut tile = film.tile(whole(&film), &filter);
        let centre = Vec2::splat(0.5);
        tile.add_sample(centre + negative, Vec3::splat(1e4), &filter);
        tile.add_sample(
            centre + Vec2::new(x, 0.0),
            Vec3::splat(1.0 + i as f32),
            &filter,
        );
        film.merge(&tile);
        let sum = film.pixel(0, 0);
        assert!(
            sum.weight.abs() < 1e-3,
            "the weights nearly cancel: {}",
            sum.weight
        );
        let value = film.image().get(0, 0);
        assert!(value.is_finite(), "{value}");
        if sum.weight != 0.0 {
            assert!(
                sum.weight.abs() >= f64::from(WEIGHT_QUANTUM),
                "{}",
                sum.weight
            );
        }
        worst = worst.max(f64::from(value.abs().max_element()));
    }
    // |Σ f L| <= 2 * 1e4 and |Σ f| >= 2^-20: the worst value is at most about 2e10.
    assert!(worst <= 2e4 * f64::from(1u32 << 20), "{worst}");
}
