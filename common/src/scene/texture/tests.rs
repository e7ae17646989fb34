use super::*;

/// A 2 x 2 image: red, green on the top row; blue, white below.
fn quad(filter: BitmapFilter, wrap: WrapMode) -> Bitmap {
    let mut bitmap = Bitmap::new(2, 2, vec![Vec3::X, Vec3::Y, Vec3::Z, Vec3::ONE].into()).unwrap();
    bitmap.filter = filter;
    bitmap.wrap = wrap;
    bitmap
}

const POINTS: [(f32, f32); 7] = [
    (0.25, 0.25),
    (0.75, 0.25),
    (0.25, 0.75),
    (0.5, 0.5),
    (0.1, 0.6),
    (1.3, -0.2),
    (-0.4, 1.7),
];

/// Checks `bitmap` at [`POINTS`] against what Mitsuba 3.9.1 (`scalar_rgb`) gives for the same
/// image written to an EXR file, read by its `bitmap` texture with `raw` on
/// (`texture.eval(si)` with `si.uv` set).
fn agrees_with_mitsuba(bitmap: &Bitmap, mitsuba: [[f32; 3]; 7]) {
    for ((u, v), expected) in POINTS.into_iter().zip(mitsuba) {
        let ours = bitmap.eval(Vec2::new(u, v));
        assert!(
            ours.abs_diff_eq(Vec3::from(expected), 1e-5),
            "{:?} {:?} at ({u}, {v}): {ours} against Mitsuba's {expected:?}",
            bitmap.filter,
            bitmap.wrap
        );
    }
}

#[test]
fn nearest_lookups_agree_with_mitsuba() {
    let (r, g, b, w) = ([1., 0., 0.], [0., 1., 0.], [0., 0., 1.], [1., 1., 1.]);
    use BitmapFilter::Nearest;
    agrees_with_mitsuba(&quad(Nearest, WrapMode::Repeat), [r, g, b, w, b, b, w]);
    agrees_with_mitsuba(&quad(Nearest, WrapMode::Mirror), [r, g, b, w, b, g, r]);
    agrees_with_mitsuba(&quad(Nearest, WrapMode::Clamp), [r, g, b, w, b, g, b]);
}

#[test]
fn bilinear_lookups_agree_with_mitsuba() {
    let (r, g, b) = ([1., 0., 0.], [0., 1., 0.], [0., 0., 1.]);
    let grey = [0.5; 3];
    use BitmapFilter::Bilinear;
    agrees_with_mitsuba(
        &quad(Bilinear, WrapMode::Repeat),
        [
            r,
            g,
            b,
            grey,
            [0.42, 0.3, 0.7],
            [0.18, 0.1, 0.9],
            [0.66, 0.7, 0.9],
        ],
    );
    agrees_with_mitsuba(
        &quad(Bilinear, WrapMode::Mirror),
        [
            r,
            g,
            b,
            grey,
            [0.3, 0.0, 0.7],
            [0.1, 0.9, 0.0],
            [0.66, 0.3, 0.1],
        ],
    );
    agrees_with_mitsuba(
        &quad(Bilinear, WrapMode::Clamp),
        [r, g, b, grey, [0.3, 0.0, 0.7], g, b],
    );
}

#[test]
fn a_bitmap_needs_one_pixel_per_place() {
    assert!(Bitmap::new(2, 2, vec![Vec3::ONE; 3].into()).is_none());
    assert!(Bitmap::new(0, 0, Vec::new().into()).is_none());
    assert_eq!(
        Bitmap::new(3, 1, vec![Vec3::ONE; 3].into()).unwrap().size(),
        (3, 1)
    );
}

#[test]
fn lookups_far_away_or_not_finite_stay_in_the_image() {
    for wrap in [WrapMode::Repeat, WrapMode::Mirror, WrapMode::Clamp] {
        for filter in [BitmapFilter::Nearest, BitmapFilter::Bilinear] {
            let bitmap = quad(filter, wrap);
            for uv in [
                Vec2::new(-1e-9, 1e30),
                Vec2::new(-1e30, -1e-7),
                Vec2::splat(f32::NAN),
                Vec2::splat(f32::INFINITY),
            ] {
                assert!(bitmap.eval(uv).is_finite());
            }
        }
    }
}

#[test]
fn checkerboard_follows_mitsubas_convention() {
    let board = Checkerboard::scaled(Vec3::X, Vec3::Y, Vec2::splat(2.0));
    // uv' = (0.5, 0.5): both fractions at 1/2, not above: colour 0.
    assert_eq!(board.eval(Vec2::new(0.25, 0.25)), Vec3::X);
    assert_eq!(board.eval(Vec2::new(0.1, 0.1)), Vec3::X);
    assert_eq!(board.eval(Vec2::new(0.4, 0.1)), Vec3::Y); // uv' = (0.8, 0.2)
    assert_eq!(board.eval(Vec2::new(0.1, 0.4)), Vec3::Y);
    assert_eq!(board.eval(Vec2::new(0.4, 0.4)), Vec3::X);
    assert_eq!(board.eval(Vec2::new(0.6, 0.1)), Vec3::X); // next period
    assert_eq!(board.eval(Vec2::new(-0.1, 0.1)), Vec3::Y); // uv' = (-0.2, 0.2)
}

#[test]
fn checkerboard_applies_its_whole_to_uv() {
    // A shift by half a square swaps the colours.
    let board = Checkerboard {
        colour0: Vec3::X,
        colour1: Vec3::Y,
        to_uv: Affine2::from_translation(Vec2::new(0.5, 0.0)),
    };
    assert_eq!(board.eval(Vec2::new(0.1, 0.1)), Vec3::Y);
}
