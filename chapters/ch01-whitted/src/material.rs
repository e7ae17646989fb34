//! The three materials of a Whitted ray tracer.

use glam::{Vec2, Vec3};

/// How a surface scatters light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// Matte: reflects `albedo / pi` of the incident irradiance into every direction. Lit
    /// only by the point lights it sees directly: Whitted's method has no indirect diffuse
    /// light.
    Diffuse {
        /// Share of the incident light reflected, per colour channel.
        albedo: Vec3,
        /// Whether the back face reflects too. Mitsuba's `diffuse` is one-sided (black
        /// from behind); its `twosided` wrapper makes both sides reflect.
        two_sided: bool,
    },
    /// Matte with a checkerboard albedo: Whitted's 1980 floor. Lit like [`Material::Diffuse`].
    CheckeredDiffuse {
        /// The albedo at each point of the surface.
        checkerboard: Checkerboard,
        /// Whether the back face reflects too.
        two_sided: bool,
    },
    /// A perfect mirror reflecting `reflectance` of the light.
    Mirror {
        /// Share reflected, per colour channel.
        reflectance: Vec3,
    },
    /// Smooth glass, water, diamond: reflects by the Fresnel equations, refracts the rest.
    Dielectric {
        /// Index of refraction on the side the normal points away from (inside).
        int_ior: f32,
        /// Index of refraction on the side the normal points to (outside).
        ext_ior: f32,
    },
}

impl Material {
    /// A one-sided matte surface.
    pub fn diffuse(albedo: Vec3) -> Self {
        Material::Diffuse {
            albedo,
            two_sided: false,
        }
    }

    /// A matte surface that reflects on both sides.
    pub fn two_sided_diffuse(albedo: Vec3) -> Self {
        Material::Diffuse {
            albedo,
            two_sided: true,
        }
    }

    /// A perfect mirror of reflectance 1.
    pub fn mirror() -> Self {
        Material::Mirror {
            reflectance: Vec3::ONE,
        }
    }

    /// Glass-like material of index `ior` in air.
    pub fn glass(ior: f32) -> Self {
        Material::Dielectric {
            int_ior: ior,
            ext_ior: 1.0,
        }
    }
}

/// Mitsuba 3's `checkerboard` texture: two colours alternating over the surface parameters.
///
/// With `uv' = scale * uv`, a point is in colour 0 where the fractional parts of `u'` and `v'`
/// are on the same side of 1/2, else in colour 1: one period of `uv'` holds 2 x 2 squares.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Checkerboard {
    /// Mitsuba's `color0`.
    pub colour0: Vec3,
    /// Mitsuba's `color1`.
    pub colour1: Vec3,
    /// Periods per unit of `u` and `v` (Mitsuba's `to_uv` scale).
    pub scale: Vec2,
}

impl Checkerboard {
    /// The colour at surface parameters `uv`.
    pub fn eval(&self, uv: Vec2) -> Vec3 {
        let scaled = self.scale * uv;
        let upper_half = |t: f32| t - t.floor() > 0.5;
        if upper_half(scaled.x) == upper_half(scaled.y) {
            self.colour0
        } else {
            self.colour1
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checkerboard_follows_mitsubas_convention() {
        let board = Checkerboard {
            colour0: Vec3::X,
            colour1: Vec3::Y,
            scale: Vec2::splat(2.0),
        };
        // uv' = (0.5, 0.5): both fractions at 1/2, not above: colour 0.
        assert_eq!(board.eval(Vec2::new(0.25, 0.25)), Vec3::X);
        assert_eq!(board.eval(Vec2::new(0.1, 0.1)), Vec3::X);
        assert_eq!(board.eval(Vec2::new(0.4, 0.1)), Vec3::Y); // uv' = (0.8, 0.2)
        assert_eq!(board.eval(Vec2::new(0.1, 0.4)), Vec3::Y);
        assert_eq!(board.eval(Vec2::new(0.4, 0.4)), Vec3::X);
        assert_eq!(board.eval(Vec2::new(0.6, 0.1)), Vec3::X); // next period
        assert_eq!(board.eval(Vec2::new(-0.1, 0.1)), Vec3::Y); // uv' = (-0.2, 0.2)
    }
}
