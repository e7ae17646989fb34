//! The three materials of a Whitted ray tracer.

use glam::Vec3;

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
