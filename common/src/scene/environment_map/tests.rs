use super::*;
use crate::scene::lat_long::{direction_of, direction_to_uv};
use std::f32::consts::PI;

/// The 4 x 3 map the Mitsuba values below were computed on: pixel (x, y) holds
/// `(1 + x, 10 (1 + y), (x + 1)(y + 1) / 2)`.
fn probe_pixels() -> Vec<Vec3> {
    let mut pixels = Vec::new();
    for y in 0..3 {
        for x in 0..4 {
            let (x, y) = (x as f32, y as f32);
            pixels.push(Vec3::new(
                1.0 + x,
                10.0 * (1.0 + y),
                0.5 * (x + 1.0) * (y + 1.0),
            ));
        }
    }
    pixels
}

/// Directions and the radiance Mitsuba 3.9.1 (`scalar_rgb`) gives for them with `scale` 2,
/// without a `to_world` and with `rotate y 90`.
const MITSUBA: [([f32; 3], [f32; 3], [f32; 3]); 6] = [
    ([0.0, 0.0, -1.0], [5.0, 40.0, 5.0], [3.0, 40.0, 3.0]),
    ([1.0, 0.0, 0.0], [3.0, 40.0, 3.0], [5.0, 40.0, 5.0]),
    (
        [0.486664, 0.811107, -0.324443],
        [2.25133, 27.9546, 1.57338],
        [4.25133, 27.9546, 2.97111],
    ),
    (
        [-0.86164, -0.123091, 0.492366],
        [6.339, 41.5712, 6.588],
        [6.98299, 41.5712, 7.25729],
    ),
    (
        [0.110264, -0.992372, 0.0551318],
        [3.59033, 58.4264, 5.24425],
        [5.59033, 58.4264, 8.16557],
    ),
    (
        [0.0, 0.196116, 0.980581],
        [5.0, 37.4867, 4.68583],
        [7.0, 37.4867, 6.56017],
    ),
];

#[test]
fn the_lookup_agrees_with_mitsuba_in_every_direction_and_rotation() {
    let pixels = probe_pixels();
    let plain = EnvironmentMap::new(4, 3, &pixels, 2.0, Mat3::IDENTITY).unwrap();
    let turned = Mat3::from_rotation_y(90f32.to_radians());
    let rotated = EnvironmentMap::new(4, 3, &pixels, 2.0, turned).unwrap();
    for (d, expected, expected_rotated) in MITSUBA {
        let d = Vec3::from(d);
        let ours = plain.radiance(d);
        assert!(
            ours.abs_diff_eq(Vec3::from(expected), 1e-3),
            "towards {d}: ours {ours}, Mitsuba {expected:?} (u = 0 looks along -z, +y is up)"
        );
        let ours = rotated.radiance(d);
        assert!(
            ours.abs_diff_eq(Vec3::from(expected_rotated), 1e-3),
            "towards {d} with to_world rotate y 90: ours {ours}, Mitsuba {expected_rotated:?}"
        );
        // The direction's length does not matter.
        assert!(plain.radiance(d * 1e4).abs_diff_eq(plain.radiance(d), 1e-3));
    }
}

#[test]
fn directions_and_coordinates_are_inverse() {
    for (u, cos_theta) in [(0.1, 0.3), (0.45, -0.9), (-0.3, 0.99), (0.0, 0.0)] {
        let d = direction_of(u, cos_theta);
        assert!((d.length() - 1.0).abs() < 1e-6);
        let uv = direction_to_uv(d);
        assert!((uv.x - u).abs() < 1e-5, "{u} {uv}");
        assert!(
            (uv.y - cos_theta.acos() / PI).abs() < 1e-5,
            "{cos_theta} {uv}"
        );
    }
}

#[test]
fn the_poles_read_the_top_and_bottom_rows() {
    let map = EnvironmentMap::new(4, 3, &probe_pixels(), 1.0, Mat3::IDENTITY).unwrap();
    assert_eq!(map.radiance(Vec3::Y).y, 10.0);
    assert_eq!(map.radiance(-Vec3::Y).y, 30.0);
}

#[test]
fn any_direction_and_any_map_size_give_a_finite_colour() {
    let one = EnvironmentMap::new(1, 1, &[Vec3::splat(2.0)], 1.0, Mat3::IDENTITY).unwrap();
    let map = EnvironmentMap::new(4, 3, &probe_pixels(), 1.0, Mat3::IDENTITY).unwrap();
    for d in [
        Vec3::ZERO,
        Vec3::NAN,
        Vec3::splat(f32::INFINITY),
        Vec3::new(0.0, -0.0, -0.0),
        Vec3::new(1e-30, 1.0, -1e-30),
        Vec3::new(-1e30, 1e30, 0.0),
    ] {
        assert!(map.radiance(d).is_finite(), "{d}");
        assert!(one.radiance(d).is_finite(), "{d}");
    }
    assert_eq!(one.radiance(Vec3::X), Vec3::splat(2.0));
}

#[test]
fn bad_maps_are_refused_in_words() {
    let pixels = probe_pixels();
    assert_eq!(
        EnvironmentMap::new(4, 2, &pixels, 1.0, Mat3::IDENTITY).unwrap_err(),
        EnvironmentMapError::Size
    );
    assert_eq!(
        EnvironmentMap::new(0, 0, &[], 1.0, Mat3::IDENTITY).unwrap_err(),
        EnvironmentMapError::Size
    );
    let mut bad = pixels.clone();
    bad[6] = Vec3::new(0.0, f32::NAN, 0.0);
    let error = EnvironmentMap::new(4, 3, &bad, 1.0, Mat3::IDENTITY).unwrap_err();
    assert_eq!(error, EnvironmentMapError::NotFinite { x: 2, y: 1 });
    assert!(error.to_string().contains("pixel (2, 1)"), "{error}");
    let overflow = EnvironmentMap::new(4, 3, &pixels, 1e38, Mat3::IDENTITY).unwrap_err();
    assert!(matches!(overflow, EnvironmentMapError::NotFinite { .. }));
    let stretched = Mat3::from_diagonal(Vec3::new(2.0, 1.0, 1.0));
    assert_eq!(
        EnvironmentMap::new(4, 3, &pixels, 1.0, stretched).unwrap_err(),
        EnvironmentMapError::NotRotation
    );
    let mirrored = Mat3::from_diagonal(Vec3::new(-1.0, 1.0, 1.0));
    assert!(EnvironmentMap::new(4, 3, &pixels, 1.0, mirrored).is_ok());
}
