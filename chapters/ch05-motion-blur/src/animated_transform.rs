//! Transforms that change with time: keyframes, interpolated the way pbrt's
//! `AnimatedTransform` does.
//!
//! Lerping two matrices does not give a transform in between: halfway between a rotation by
//! 0 and one by 90 degrees, the lerped matrix is the rotation by 45 degrees times a squash that
//! shrinks the object by `cos 45° = 1/√2` across the axis and leaves it as it is along the
//! axis (a non-uniform scale, not a shear). So every keyframe matrix is split into a
//! translation `T`, a rotation `R` and a scale `S` (`M = T R S`, a polar decomposition), and
//! the parts are interpolated each in its own way ([`interpolate`]), so that the object moves
//! along a straight line, turns about a fixed axis at constant speed and changes its size
//! evenly.
//!
//! The rotation's interpolation takes the shorter way round, so two neighbouring keyframes
//! must differ by less than half a turn; a spin by one turn or more is written as several
//! keyframes (see [`AnimatedTransform::spin`]).

use glam::{DMat3, Mat3, Mat4, Quat, Vec3};
use std::fmt;

/// A matrix split into translation, rotation and scale: `M = T R S`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Decomposed {
    /// The translation `T`.
    pub translation: Vec3,
    /// The rotation `R`, a unit quaternion.
    pub rotation: Quat,
    /// What is left, `S = R^-1 M`: symmetric, a scale along some axes (and a reflection when
    /// the determinant is negative).
    pub scale: Mat3,
}

impl Decomposed {
    /// Splits `m` (invertible, affine). The rotation comes from the polar decomposition,
    /// iterated as in pbrt: `R ← (R + R^-T) / 2` converges to the orthogonal factor.
    pub fn new(m: Mat4) -> Self {
        let m3: DMat3 = Mat3::from_mat4(m).as_dmat3();
        let mut r = m3;
        for _ in 0..100 {
            let next = 0.5 * (r + r.inverse().transpose());
            let change = (0..3)
                .map(|i| (next.col(i) - r.col(i)).abs().element_sum())
                .fold(0.0, f64::max);
            r = next;
            if change < 1e-12 {
                break;
            }
        }
        // A reflection is an orthogonal matrix with determinant -1, which no quaternion
        // describes; moving the sign into the scale keeps `R` a rotation and `R S` unchanged.
        if r.determinant() < 0.0 {
            r = -r;
        }
        let scale = r.transpose() * m3;
        Self {
            translation: m.w_axis.truncate(),
            rotation: Quat::from_mat3(&r.as_mat3()).normalize(),
            scale: scale.as_mat3(),
        }
    }

    /// The matrix `T R S`.
    pub fn matrix(&self) -> Mat4 {
        Mat4::from_translation(self.translation)
            * Mat4::from_quat(self.rotation)
            * Mat4::from_mat3(self.scale)
    }

    /// Its inverse `S^-1 R^-1 T^-1`, from the parts: a 3 x 3 inverse and a transposed
    /// rotation instead of a general 4 x 4 inverse, once per ray.
    pub fn inverse_matrix(&self) -> Mat4 {
        Mat4::from_mat3(self.scale.inverse())
            * Mat4::from_quat(self.rotation.conjugate())
            * Mat4::from_translation(-self.translation)
    }
}

/// One keyframe: the matrix at a time, and its parts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Keyframe {
    /// When.
    pub time: f32,
    /// Object to world at that time, exactly as given.
    pub matrix: Mat4,
    /// Its inverse, world to object.
    pub inverse: Mat4,
    /// Its parts.
    pub parts: Decomposed,
}

/// Why keyframes are refused.
#[derive(Clone, Debug, PartialEq)]
pub enum MotionError {
    /// No keyframe at all.
    NoKeyframes,
    /// Times must be finite and strictly increasing.
    TimesNotIncreasing {
        /// The offending time.
        time: f32,
    },
    /// A matrix that cannot be inverted (or is not finite).
    Degenerate {
        /// The keyframe's time.
        time: f32,
    },
    /// Two neighbours half a turn apart: the shorter way round is not defined.
    HalfTurn {
        /// The later keyframe's time.
        time: f32,
    },
}

impl fmt::Display for MotionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MotionError::NoKeyframes => write!(f, "a motion needs at least one keyframe"),
            MotionError::TimesNotIncreasing { time } => write!(
                f,
                "keyframe times must be finite and increasing (time {time})"
            ),
            MotionError::Degenerate { time } => {
                write!(f, "the keyframe at time {time} is not invertible")
            }
            MotionError::HalfTurn { time } => write!(
                f,
                "the keyframe at time {time} is turned half a turn from the one before: \
                 the way round is ambiguous; add a keyframe in between"
            ),
        }
    }
}

impl std::error::Error for MotionError {}

/// A transform given at keyframes and interpolated in between; constant before the first
/// keyframe and after the last.
#[derive(Clone, Debug, PartialEq)]
pub struct AnimatedTransform {
    keyframes: Vec<Keyframe>,
}

impl AnimatedTransform {
    /// A transform that does not move.
    pub fn fixed(matrix: Mat4) -> Self {
        Self::new(&[(0.0, matrix)]).expect("one invertible keyframe")
    }

    /// Keyframes `(time, matrix)`: times strictly increasing, matrices invertible, neighbours
    /// less than half a turn apart.
    pub fn new(keyframes: &[(f32, Mat4)]) -> Result<Self, MotionError> {
        if keyframes.is_empty() {
            return Err(MotionError::NoKeyframes);
        }
        let mut out: Vec<Keyframe> = Vec::with_capacity(keyframes.len());
        for &(time, matrix) in keyframes {
            let later = out.last().is_none_or(|previous| time > previous.time);
            if !time.is_finite() || !later {
                return Err(MotionError::TimesNotIncreasing { time });
            }
            let determinant = matrix.determinant();
            if !matrix.is_finite() || !determinant.is_finite() || determinant == 0.0 {
                return Err(MotionError::Degenerate { time });
            }
            let parts = Decomposed::new(matrix);
            if let Some(previous) = out.last() {
                // |dot| = cos(angle / 2): near 0 means near half a turn.
                if previous.parts.rotation.dot(parts.rotation).abs() < 1e-3 {
                    return Err(MotionError::HalfTurn { time });
                }
            }
            out.push(Keyframe {
                time,
                matrix,
                inverse: matrix.inverse(),
                parts,
            });
        }
        Ok(Self { keyframes: out })
    }

    /// A spin by `turns` full turns (any number, negative for the other way) about the unit
    /// `axis` through the origin, from `start` to `end`, followed by `then` (a placement).
    /// Written with a keyframe every quarter turn, so the rotation's interpolation never has to guess the way round.
    pub fn spin(axis: Vec3, turns: f32, start: f32, end: f32, then: Mat4) -> Self {
        let quarters = (turns.abs() * 4.0).ceil().max(1.0) as usize;
        let keyframes: Vec<(f32, Mat4)> = (0..=quarters)
            .map(|i| {
                let s = i as f32 / quarters as f32;
                let angle = turns * std::f32::consts::TAU * s;
                (
                    start + s * (end - start),
                    then * Mat4::from_axis_angle(axis, angle),
                )
            })
            .collect();
        Self::new(&keyframes).expect("quarter-turn keyframes are valid")
    }

    /// The keyframes.
    pub fn keyframes(&self) -> &[Keyframe] {
        &self.keyframes
    }

    /// Whether the transform changes at all.
    pub fn is_moving(&self) -> bool {
        self.keyframes
            .windows(2)
            .any(|pair| pair[0].matrix != pair[1].matrix)
    }

    /// The keyframe segment that `time` falls in, and how far along it (`0..1`); `None`
    /// outside the keyframes' span, where the transform is constant.
    pub fn segment_at(&self, time: f32) -> Option<(usize, f32)> {
        let i = self.keyframes.partition_point(|k| k.time <= time);
        if i == 0 || i == self.keyframes.len() {
            return None;
        }
        let (a, b) = (&self.keyframes[i - 1], &self.keyframes[i]);
        Some((i - 1, (time - a.time) / (b.time - a.time)))
    }

    /// Object to world at `time`. At a keyframe's time this is the keyframe's own matrix,
    /// exactly; in between, the interpolated parts recombined.
    pub fn at(&self, time: f32) -> Mat4 {
        self.at_with_inverse(time).0
    }

    // ANCHOR: at_with_inverse
    /// Object to world at `time` and its inverse, world to object: held at the first
    /// keyframe's before it (and for a time that is not a number), at the last one's after it,
    /// exactly a keyframe's own matrices at its time, and the two keyframes around `time`
    /// interpolated in between (see [`segment_at`](Self::segment_at) and [`interpolate`]).
    pub fn at_with_inverse(&self, time: f32) -> (Mat4, Mat4) {
        // BEGIN SOLUTION
        let first = &self.keyframes[0];
        let last = &self.keyframes[self.keyframes.len() - 1];
        let exact = |k: &Keyframe| (k.matrix, k.inverse);
        if time.is_nan() || time <= first.time {
            return exact(first);
        }
        if time >= last.time {
            return exact(last);
        }
        let Some((i, u)) = self.segment_at(time) else {
            return exact(first);
        };
        if u == 0.0 {
            return exact(&self.keyframes[i]);
        }
        let parts = interpolate(&self.keyframes[i].parts, &self.keyframes[i + 1].parts, u);
        (parts.matrix(), parts.inverse_matrix())
        // END SOLUTION
    }
    // ANCHOR_END: at_with_inverse
}

// ANCHOR: interpolate
/// The transform a fraction `u` of the way from `a` to `b`, each part in its own way: the
/// object moves along a straight line at constant speed, turns about a fixed axis at constant
/// angular speed, the shorter way round, and its scale changes evenly.
pub fn interpolate(a: &Decomposed, b: &Decomposed, u: f32) -> Decomposed {
    // BEGIN SOLUTION
    Decomposed {
        translation: a.translation.lerp(b.translation, u),
        rotation: a.rotation.slerp(b.rotation, u),
        scale: a.scale * (1.0 - u) + b.scale * u,
    }
    // END SOLUTION
}
// ANCHOR_END: interpolate

#[cfg(test)]
mod tests {
    use super::*;
    use std::f32::consts::{FRAC_PI_2, PI};
    use std::panic::{AssertUnwindSafe, catch_unwind};

    fn close_mat3(a: Mat3, b: Mat3, tolerance: f32) -> bool {
        (0..3).all(|i| (a.col(i) - b.col(i)).abs().max_element() <= tolerance)
    }

    /// Whether two unit quaternions are the same rotation (`q` and `-q` are).
    fn same_rotation(a: Quat, b: Quat, tolerance: f32) -> bool {
        a.dot(b).abs() >= 1.0 - tolerance
    }

    #[test]
    fn exercise_interpolate_moves_turns_and_scales_evenly() {
        let axis = Vec3::new(1.0, -2.0, 0.5).normalize();
        let a = Decomposed {
            translation: Vec3::new(1.0, 2.0, 3.0),
            rotation: Quat::from_axis_angle(axis, 0.2),
            scale: Mat3::from_diagonal(Vec3::new(1.0, 2.0, 1.0)),
        };
        // 160 degrees from a's rotation: far enough for an uneven turn to show.
        let turn = 160f32.to_radians();
        let b = Decomposed {
            translation: Vec3::new(-3.0, 0.0, 5.0),
            rotation: Quat::from_axis_angle(axis, 0.2 + turn),
            scale: Mat3::from_diagonal(Vec3::new(3.0, 1.0, 0.5)),
        };
        // Where the object should be and how large, a fraction u of the way from a to b: for
        // each u, the translation and the scale's diagonal, worked out beforehand from a's and
        // b's.
        #[rustfmt::skip]
        let table: [(f32, Vec3, Vec3); 7] = [
            (0.0, Vec3::new(1.0, 2.0, 3.0), Vec3::new(1.0, 2.0, 1.0)),
            (0.2, Vec3::new(0.2, 1.6, 3.4), Vec3::new(1.4, 1.8, 0.9)),
            (0.25, Vec3::new(0.0, 1.5, 3.5), Vec3::new(1.5, 1.75, 0.875)),
            (0.5, Vec3::new(-1.0, 1.0, 4.0), Vec3::new(2.0, 1.5, 0.75)),
            (0.75, Vec3::new(-2.0, 0.5, 4.5), Vec3::new(2.5, 1.25, 0.625)),
            (0.8, Vec3::new(-2.2, 0.4, 4.6), Vec3::new(2.6, 1.2, 0.6)),
            (1.0, Vec3::new(-3.0, 0.0, 5.0), Vec3::new(3.0, 1.0, 0.5)),
        ];
        let expected_at = |u: f32| {
            let row = table.iter().find(|row| (row.0 - u).abs() < 1e-6);
            let row = row.expect("u in the table");
            (row.1, Mat3::from_diagonal(row.2))
        };
        for u in [0.0f32, 0.25, 0.5, 0.8, 1.0] {
            let got = interpolate(&a, &b, u);
            let at = format!("interpolate: a fraction u = {u} of the way");
            // Running from b to a puts the object where a fraction 1 - u would.
            let (translation, scale) = expected_at(u);
            let (backwards_translation, backwards_scale) = expected_at(1.0 - u);
            assert!(
                got.translation.abs_diff_eq(translation, 1e-5),
                "{at}, the translation should be {translation}, and yours is {}: {}",
                got.translation,
                if got.translation.abs_diff_eq(backwards_translation, 1e-5) {
                    "it runs from b to a, backwards (u = 0 is a)"
                } else {
                    "the object moves along the straight line from a to b at constant speed"
                }
            );
            if !close_mat3(got.scale, scale, 1e-4) {
                let lerped_matrices = a.matrix() * (1.0 - u) + b.matrix() * u;
                let why = if close_mat3(got.scale, Decomposed::new(lerped_matrices).scale, 1e-4) {
                    "it is what lerping the two matrices gives: a blend of two rotations is no \
                     rotation, and the object shrinks across the axis on the way; interpolate the \
                     parts each in its own way"
                } else if close_mat3(got.scale, backwards_scale, 1e-4) {
                    "it runs from b's scale to a's, backwards (u = 0 is a)"
                } else {
                    "the scale changes evenly from a's to b's"
                };
                panic!(
                    "{at}, the scale should be {scale}, and yours is {}: {why}",
                    got.scale
                );
            }
            let length = got.rotation.length();
            assert!(
                (length - 1.0).abs() < 1e-4,
                "{at}, the rotation is a quaternion of length {length}: a rotation is a unit \
                 quaternion (a blend of two unit quaternions is shorter than 1)"
            );
            // About the one axis, turned by the share u of the whole turn.
            let turned_by = |share: f32| Quat::from_axis_angle(axis, 0.2 + share * turn);
            let rotation = turned_by(u);
            if !same_rotation(got.rotation, rotation, 1e-5) {
                let turned = (a.rotation.inverse() * got.rotation).to_axis_angle().1;
                let why = if same_rotation(got.rotation, a.rotation.lerp(b.rotation, u), 1e-5) {
                    "blending the quaternions and normalising follows the right great circle, \
                     but not at constant speed: the object turns slowly at the ends and fast in \
                     the middle"
                } else if same_rotation(got.rotation, turned_by(1.0 - u), 1e-5) {
                    "it turns from b's rotation to a's, backwards (u = 0 is a)"
                } else {
                    "the object turns about one axis at constant angular speed, the shorter way"
                };
                panic!(
                    "{at}, the rotation should have turned {:.1} degrees from a's, and yours \
                     turned {:.1}: {why}",
                    (u * turn).to_degrees(),
                    turned.to_degrees()
                );
            }
        }
    }

    /// A motion whose parts are linear in time: `T(t) R(t) S(t)`, with the rotation's angle
    /// linear in time, so that interpolating between any of its keyframes gives `f(t)` itself.
    fn linear_motion(time: f32) -> Mat4 {
        let axis = Vec3::new(0.3, 1.0, -0.2).normalize();
        Mat4::from_translation(Vec3::new(-2.0, 1.0, 0.5) + time * Vec3::new(1.5, -0.5, 2.0))
            * Mat4::from_axis_angle(axis, 1.2 * time)
            * Mat4::from_scale(Vec3::new(1.0 + 0.5 * time, 2.0 - 0.3 * time, 1.0))
    }

    #[test]
    fn exercise_at_with_inverse_interpolates_between_the_right_keyframes() {
        let times = [1.0f32, 3.0, 3.5];
        let keyframes: Vec<(f32, Mat4)> = times.iter().map(|&t| (t, linear_motion(t))).collect();
        let motion = AnimatedTransform::new(&keyframes).unwrap();
        let points = [Vec3::ZERO, Vec3::X, Vec3::new(0.5, -1.0, 2.0)];
        let cases = [
            (-5.0, 1.0),
            (0.0, 1.0),
            (1.0, 1.0),
            (1.5, 1.5),
            (2.0, 2.0),
            (2.9, 2.9),
            (3.0, 3.0),
            (3.2, 3.2),
            (3.5, 3.5),
            (4.0, 3.5),
            (100.0, 3.5),
            (f32::NAN, 1.0),
        ];
        for (time, held) in cases {
            let at = format!(
                "AnimatedTransform::at_with_inverse: keyframes at times 1, 3 and 3.5, at time \
                 {time}"
            );
            let caught = catch_unwind(AssertUnwindSafe(|| motion.at_with_inverse(time)))
                .map_err(common::exercise::resume_if_not_written);
            let (m, inverse) = match caught {
                Ok(matrices) => matrices,
                Err(_) => panic!(
                    "{at}, your code panicked (its message is above): {}",
                    if time.is_nan() {
                        "a time that is not a number falls in no segment; it is held at the \
                         first keyframe"
                    } else if time < times[0] || time > times[2] {
                        "a time outside the keyframes has no segment (segment_at gives None, and \
                         a search for the keyframe after it finds none before the first or \
                         after the last); the object is held there"
                    } else {
                        "a time inside the keyframes lies in one segment: which keyframes are \
                         the two around it?"
                    }
                ),
            };
            let expected = linear_motion(held);
            let agrees = |m: Mat4| {
                points.iter().all(|&x| {
                    m.transform_point3(x)
                        .abs_diff_eq(expected.transform_point3(x), 1e-4)
                })
            };
            if !agrees(m) {
                let segment = times.windows(2).find(|w| w[0] <= time && time < w[1]);
                let why = if time.is_nan() {
                    "a time that is not a number is held at the first keyframe".to_string()
                } else if time < times[0] {
                    "before the first keyframe the object stays where the first one puts it"
                        .to_string()
                } else if time > times[2] {
                    "after the last keyframe the object stays where the last one puts it"
                        .to_string()
                } else if let Some(w) = segment {
                    let (ka, kb) = (Decomposed::new(linear_motion(w[0])), linear_motion(w[1]));
                    let (_, u) = motion.segment_at(time).expect("time inside the keyframes");
                    let lerped = linear_motion(w[0]) * (1.0 - u) + kb * u;
                    let unscaled = interpolate(&ka, &Decomposed::new(kb), time - w[0]).matrix();
                    let backwards = interpolate(&Decomposed::new(kb), &ka, u).matrix();
                    if lerped.abs_diff_eq(m, 1e-4) {
                        "the keyframe matrices were blended entry by entry: the object is \
                         distorted between them; interpolate their parts"
                            .to_string()
                    } else if unscaled.abs_diff_eq(m, 1e-4) {
                        format!(
                            "the fraction given to interpolate is {}, the time since the \
                             keyframe; it is the fraction of the way from one keyframe to the \
                             next, from 0 at the first to 1 at the second",
                            time - w[0]
                        )
                    } else if backwards.abs_diff_eq(m, 1e-4) {
                        format!(
                            "the segment runs backwards, from the keyframe at time {} to the one \
                             at time {}: the fraction 0 is the earlier keyframe",
                            w[1], w[0]
                        )
                    } else {
                        format!(
                            "the object lies between the keyframes at times {} and {}",
                            w[0], w[1]
                        )
                    }
                } else {
                    "at a keyframe's time the object is where that keyframe puts it".to_string()
                };
                panic!("{at}, the object is not where it should be: {why}");
            }
            let round_trip = inverse * m;
            assert!(
                round_trip.abs_diff_eq(Mat4::IDENTITY, 1e-4),
                "{at}, the second matrix does not undo the first: it takes world space back to \
                 object space, the inverse of the first (their product is {round_trip})"
            );
        }
    }

    #[test]
    fn decomposing_and_recombining_gives_the_matrix_back() {
        let matrices = [
            Mat4::from_scale_rotation_translation(
                Vec3::new(2.0, 0.5, 1.5),
                Quat::from_axis_angle(Vec3::new(1.0, 2.0, 3.0).normalize(), 1.1),
                Vec3::new(-3.0, 4.0, 0.5),
            ),
            // Scale after rotation: a scale along turned axes in T R S form, kept in the symmetric S.
            Mat4::from_scale(Vec3::new(3.0, 1.0, 1.0)) * Mat4::from_rotation_z(0.6),
            // A mirror.
            Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0)) * Mat4::from_rotation_y(0.3),
        ];
        for m in matrices {
            let parts = Decomposed::new(m);
            assert!(
                parts.matrix().abs_diff_eq(m, 1e-5),
                "{m} vs {}",
                parts.matrix()
            );
            assert!((parts.rotation.length() - 1.0).abs() < 1e-6);
            let s = parts.scale;
            assert!(s.abs_diff_eq(s.transpose(), 1e-5), "S symmetric: {s}");
        }
    }

    #[test]
    fn halfway_through_a_quarter_turn_is_an_eighth_turn_not_a_shrunken_matrix() {
        let motion = AnimatedTransform::new(&[
            (0.0, Mat4::IDENTITY),
            (1.0, Mat4::from_rotation_z(FRAC_PI_2)),
        ])
        .unwrap();
        let halfway = motion.at(0.5);
        assert!(halfway.abs_diff_eq(Mat4::from_rotation_z(FRAC_PI_2 / 2.0), 1e-6));
        // Lerping the matrices would have shrunk the point to length cos(45°).
        let lerped = Mat4::IDENTITY * 0.5 + Mat4::from_rotation_z(FRAC_PI_2) * 0.5;
        assert!((lerped.transform_point3(Vec3::X).length() - 0.5f32.sqrt()).abs() < 1e-6);
        assert!((halfway.transform_point3(Vec3::X).length() - 1.0).abs() < 1e-6);
    }

    #[test]
    fn keyframes_are_exact_and_the_ends_hold() {
        let a = Mat4::from_translation(Vec3::X) * Mat4::from_rotation_y(0.3);
        let b = Mat4::from_translation(Vec3::Y) * Mat4::from_scale(Vec3::splat(2.0));
        let motion = AnimatedTransform::new(&[(1.0, a), (3.0, b)]).unwrap();
        assert_eq!(motion.at(1.0), a);
        assert_eq!(motion.at(3.0), b);
        assert_eq!(motion.at(-5.0), a);
        assert_eq!(motion.at(7.0), b);
        assert_eq!(motion.at(f32::NAN), a);
        let middle = motion.at(2.0).transform_point3(Vec3::ZERO);
        assert!(
            middle.abs_diff_eq(Vec3::new(0.5, 0.5, 0.0), 1e-6),
            "{middle}"
        );
    }

    #[test]
    fn a_spin_of_more_than_a_turn_turns_all_the_way() {
        // 1.25 turns about y: at each time the point (1, 0, 0) is where one rotation puts it.
        let motion = AnimatedTransform::spin(Vec3::Y, 1.25, 0.0, 1.0, Mat4::IDENTITY);
        assert_eq!(motion.keyframes().len(), 6);
        for i in 0..=40 {
            let time = i as f32 / 40.0;
            let angle = 1.25 * 2.0 * PI * time;
            let expected = Mat4::from_rotation_y(angle).transform_point3(Vec3::X);
            let got = motion.at(time).transform_point3(Vec3::X);
            assert!(
                got.abs_diff_eq(expected, 1e-5),
                "time {time}: {got} vs {expected}"
            );
            assert!(got.is_finite());
        }
    }

    #[test]
    fn bad_keyframes_are_refused() {
        let m = Mat4::IDENTITY;
        assert_eq!(AnimatedTransform::new(&[]), Err(MotionError::NoKeyframes));
        assert!(matches!(
            AnimatedTransform::new(&[(0.0, m), (0.0, m)]),
            Err(MotionError::TimesNotIncreasing { .. })
        ));
        assert!(matches!(
            AnimatedTransform::new(&[(0.0, m), (1.0, Mat4::from_scale(Vec3::new(1.0, 0.0, 1.0)))]),
            Err(MotionError::Degenerate { .. })
        ));
        assert!(matches!(
            AnimatedTransform::new(&[(0.0, m), (1.0, Mat4::from_rotation_x(PI))]),
            Err(MotionError::HalfTurn { .. })
        ));
    }
}
