//! The chapter's materials: chapter 01's smooth ones, and their fuzzy counterparts.

use glam::Vec3;

/// How a surface scatters light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// One of chapter 01's materials as it was: matte (lit by the point lights), the perfect
    /// mirror, smooth glass. Glass now picks its ray by the render's
    /// [`GlassStrategy`](crate::GlassStrategy).
    Smooth(ch01_whitted::material::Material),
    /// A fuzzy mirror: the share `reflectance` of the light arriving from directions spread
    /// by a `cos^n` lobe around the mirror direction.
    Glossy(Glossy),
    /// Frosted glass: smooth glass's Fresnel split into a reflected and a refracted ray, each
    /// spread by a `cos^n` lobe around its ideal direction.
    RoughGlass(RoughGlass),
}

/// A fuzzy mirror's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Glossy {
    /// Share of the light reflected, per colour channel.
    pub reflectance: Vec3,
    /// The lobe's exponent `n`: 0 is a hemisphere around the mirror direction, large is sharp.
    pub exponent: f32,
    /// Whether the back face reflects too (Mitsuba's `twosided`); else it is black.
    pub two_sided: bool,
}

/// Frosted glass's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughGlass {
    /// Index of refraction inside (where the normal points away from).
    pub int_ior: f32,
    /// Index of refraction outside.
    pub ext_ior: f32,
    /// The exponent of both lobes.
    pub exponent: f32,
}

/// Checks a lobe exponent: finite and not negative.
pub fn check_exponent(exponent: f32) -> Result<f32, String> {
    if exponent.is_finite() && exponent >= 0.0 {
        Ok(exponent)
    } else {
        Err(format!(
            "the lobe exponent must be a finite number >= 0 (0 is a hemisphere, 1e6 almost a mirror), not {exponent}"
        ))
    }
}

impl Material {
    /// A one-sided fuzzy mirror.
    pub fn glossy(reflectance: Vec3, exponent: f32) -> Self {
        Material::Glossy(Glossy {
            reflectance,
            exponent,
            two_sided: false,
        })
    }

    /// Frosted glass of index `ior` in air.
    pub fn rough_glass(ior: f32, exponent: f32) -> Self {
        Material::RoughGlass(RoughGlass {
            int_ior: ior,
            ext_ior: 1.0,
            exponent,
        })
    }

    /// Whether the material scatters with a lobe (and so draws random numbers per bounce).
    pub fn is_fuzzy(&self) -> bool {
        !matches!(self, Material::Smooth(_))
    }

    /// The same material with its lobe exponent replaced by `exponent` (smooth materials stay
    /// as they are).
    pub fn with_exponent(self, exponent: f32) -> Self {
        match self {
            Material::Smooth(_) => self,
            Material::Glossy(g) => Material::Glossy(Glossy { exponent, ..g }),
            Material::RoughGlass(g) => Material::RoughGlass(RoughGlass { exponent, ..g }),
        }
    }
}

impl From<ch01_whitted::material::Material> for Material {
    fn from(material: ch01_whitted::material::Material) -> Self {
        Material::Smooth(material)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponents_must_be_finite_and_not_negative() {
        assert_eq!(check_exponent(0.0), Ok(0.0));
        assert_eq!(check_exponent(1e6), Ok(1e6));
        for bad in [-1.0, f32::NAN, f32::INFINITY] {
            let message = check_exponent(bad).unwrap_err();
            assert!(message.contains("lobe exponent"), "{message}");
        }
    }

    #[test]
    fn only_lobed_materials_are_fuzzy() {
        assert!(!Material::from(ch01_whitted::material::Material::mirror()).is_fuzzy());
        assert!(Material::glossy(Vec3::ONE, 10.0).is_fuzzy());
        assert!(Material::rough_glass(1.5, 10.0).is_fuzzy());
        assert_eq!(
            Material::glossy(Vec3::ONE, 10.0).with_exponent(3.0),
            Material::glossy(Vec3::ONE, 3.0)
        );
    }
}
