//! What a surface is made of: every material the workbook renders, as parameters.
//!
//! Chapter 01 renders the smooth ones (matte, mirror, glass); chapter 06 adds the fuzzy ones,
//! whose reflection is spread by a `cos^n` lobe. Chapter 08 renders three more that a scene
//! file may ask for and the lecture does not teach: metals with a complex index of refraction
//! ([`Conductor`]), thin panes of glass and plastic (a matte base under a clear coat); earlier
//! chapters render the lecture's nearest material in their place ([`Material::lecture_stand_in`])
//! or refuse them. How each is traced or sampled is the chapters' business; here they are only
//! data.

use super::Texture;
use glam::Vec3;

/// How a surface scatters light.
#[derive(Clone, Debug, PartialEq)]
pub enum Material {
    /// Matte: reflects `albedo / pi` of the incident irradiance into every direction.
    Diffuse {
        /// Share of the incident light reflected, per colour channel.
        albedo: Vec3,
        /// Whether the back face reflects too. Mitsuba's `diffuse` is one-sided (black
        /// from behind); its `twosided` wrapper makes both sides reflect.
        two_sided: bool,
    },
    /// Matte with an albedo that varies over the surface: Whitted's checkered floor, a scene
    /// file's `diffuse` with a `<texture>` as its `reflectance`.
    TexturedDiffuse {
        /// The albedo at each point of the surface, read by
        /// [`Scene::albedo`](super::Scene::albedo).
        texture: Texture,
        /// Whether the back face reflects too.
        two_sided: bool,
    },
    /// A perfect mirror reflecting `reflectance` of the light. Like Mitsuba's, it is a mirror on
    /// its front side only, the side its normal points to; seen from behind it is black.
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
    /// A fuzzy mirror: the share `reflectance` of the light arriving from directions spread
    /// by a `cos^n` lobe around the mirror direction (chapter 06).
    Glossy(Glossy),
    /// Frosted glass: smooth glass's Fresnel split into a reflected and a refracted ray, each
    /// spread by a `cos^n` lobe around its ideal direction (chapter 06).
    RoughGlass(RoughGlass),
    /// A metal: a mirror (or, rough, a lobe) whose reflectance follows the Fresnel equations
    /// of a complex index of refraction `eta + i k`, so that gold is yellow and brighter at
    /// grazing angles (Mitsuba's `conductor` and `roughconductor`).
    Conductor(Conductor),
    /// A pane of glass too thin to shift the light through it: a Fresnel share reflected
    /// (the light bouncing inside the pane included), the rest passing straight on
    /// (Mitsuba's `thindielectric`).
    ThinDielectric {
        /// Index of refraction of the pane.
        int_ior: f32,
        /// Index of refraction around it.
        ext_ior: f32,
    },
    /// A matte base under a smooth dielectric coat (Mitsuba's `plastic` and `roughplastic`).
    Plastic(Plastic),
    /// A cut-out: the nested material where the surface is opaque, nothing where it is not
    /// (Mitsuba's `mask`), as for a leaf cut out of a card by a texture.
    Mask(Mask),
    /// Glass whose reflection and transmission are scaled by factors against physics, or by
    /// textures (Mitsuba's `specular_reflectance` and `specular_transmittance` on
    /// `dielectric` and `roughdielectric`); glass without them is [`Material::Dielectric`]
    /// or, rough, [`Material::RoughGlass`].
    TintedGlass(TintedGlass),
}

/// The parameters of glass with factors on its two lobes, as Mitsuba 3's `dielectric` and
/// `roughdielectric` take them: the Fresnel split is unchanged (and so is how a direction is
/// chosen), then the reflected light is multiplied by `specular_reflectance` and the
/// transmitted light by `specular_transmittance`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TintedGlass {
    /// Index of refraction inside (where the normal points away from).
    pub int_ior: f32,
    /// Index of refraction outside.
    pub ext_ior: f32,
    /// A factor on the reflected light, per colour channel.
    pub specular_reflectance: Vec3,
    /// A factor on the transmitted light, per colour channel.
    pub specular_transmittance: Vec3,
    /// A texture that multiplies `specular_reflectance` point by point, read at a hit by
    /// [`Scene::material_at`](super::Scene::material_at).
    pub reflectance_texture: Option<Texture>,
    /// A texture that multiplies `specular_transmittance` point by point, read the same way.
    pub transmittance_texture: Option<Texture>,
    /// The microfacet roughness of a `roughdielectric`; `None` for smooth glass.
    pub roughness: Option<Microfacet>,
}

/// Mitsuba 3's `mask`: at each point the surface is there with probability `opacity` (and
/// scatters as `nested`) and absent otherwise (light passes straight on). The nested material
/// is boxed because a mask may wrap any material, which is why [`Material`] is `Clone` and
/// not `Copy`.
#[derive(Clone, Debug, PartialEq)]
pub struct Mask {
    /// How opaque the surface is, from 0 (invisible) to 1 (the nested material alone).
    pub opacity: Opacity,
    /// The material where the surface is opaque.
    pub nested: Box<Material>,
}

/// A mask's opacity: one number, or a texture read as one number per point, as Mitsuba reads
/// a texture for a single value (`eval_1`): a colour's mean, an image's luminance. Values
/// outside [0, 1] are clamped, as Mitsuba clamps them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Opacity {
    /// The same opacity everywhere.
    Uniform(f32),
    /// An opacity that varies over the surface (a checkerboard, an image).
    Texture(Texture),
}

/// A metal's parameters, as Mitsuba 3's `conductor` takes them.
///
/// Mitsuba's default `material="none"` is a perfect mirror: the loader makes that a
/// [`Material::Mirror`] when it is smooth, and a conductor of `eta = 0`, `k = 1` (whose
/// Fresnel reflectance is 1 at every angle) when it is rough.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conductor {
    /// Real part of the index of refraction, per colour channel.
    pub eta: Vec3,
    /// Imaginary part (the extinction coefficient), per colour channel.
    pub k: Vec3,
    /// A factor on the reflection, per colour channel (1 for a physical metal).
    pub specular_reflectance: Vec3,
    /// A texture that multiplies `specular_reflectance` point by point (a scene file's
    /// `<texture name="specular_reflectance">`); [`Scene::material_at`](super::Scene::material_at)
    /// reads it at a hit.
    pub specular_texture: Option<Texture>,
    /// Whether the back face reflects too (Mitsuba's `twosided`); else it is black.
    pub two_sided: bool,
    /// The microfacet roughness of a `roughconductor`; `None` for a smooth metal.
    pub roughness: Option<Microfacet>,
}

/// Plastic's parameters, as Mitsuba 3's `plastic` takes them: light is reflected by the
/// coat's Fresnel share, the rest enters, scatters at the matte base (and between base and
/// coat) and leaves through the coat.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plastic {
    /// The base's albedo, per colour channel.
    pub diffuse_reflectance: Vec3,
    /// A factor on the coat's reflection (1 for a physical coat).
    pub specular_reflectance: Vec3,
    /// A texture that multiplies `diffuse_reflectance` point by point; read at a hit by
    /// [`Scene::material_at`](super::Scene::material_at).
    pub diffuse_texture: Option<Texture>,
    /// A texture that multiplies `specular_reflectance` point by point, read the same way.
    pub specular_texture: Option<Texture>,
    /// Index of refraction of the coat.
    pub int_ior: f32,
    /// Index of refraction outside.
    pub ext_ior: f32,
    /// Whether the light bouncing between base and coat darkens and saturates the colour
    /// (Mitsuba's `nonlinear`); when false the base's albedo keeps its hue.
    pub nonlinear: bool,
    /// Whether the back face reflects too (Mitsuba's `twosided`); else it is black.
    pub two_sided: bool,
    /// The coat's microfacet roughness for a `roughplastic`; `None` for a smooth coat.
    pub roughness: Option<Microfacet>,
}

impl Conductor {
    /// The Fresnel reflectance at normal incidence, `((eta - 1)² + k²) / ((eta + 1)² + k²)`
    /// per channel: the colour a metal shows when looked at square on.
    pub fn normal_incidence_fresnel(&self) -> Vec3 {
        let one = Vec3::ONE;
        let k2 = self.k * self.k;
        ((self.eta - one) * (self.eta - one) + k2) / ((self.eta + one) * (self.eta + one) + k2)
    }
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
    /// The microfacet roughness of a scene file's `roughconductor` this lobe stands in for.
    pub stands_in_for: Option<Microfacet>,
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
    /// The microfacet roughness of a scene file's `roughdielectric` these lobes stand in for.
    pub stands_in_for: Option<Microfacet>,
}

/// A microfacet roughness as Mitsuba 3's rough BSDFs give it: a surface of tiny mirror
/// facets whose slopes are spread by a width `alpha_u` along the surface's tangent and
/// `alpha_v` across it (equal for an isotropic roughness, Mitsuba's `alpha`).
///
/// Chapter 08 renders it as Mitsuba's microfacet model. Chapters 06 and 07 render it as a
/// `cos^n` lobe of about the same width, `n = 2 / alpha² - 2` (the correspondence for the
/// Beckmann distribution: Walter et al. 2007, "Microfacet models for refraction through rough
/// surfaces"): the lobes' shapes, their brightness at grazing angles and their Fresnel
/// colouring differ from Mitsuba's, and a lobe is round, so an anisotropic roughness becomes
/// the round lobe of [`alpha`](Self::alpha).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Microfacet {
    /// The slopes' distribution.
    pub distribution: MicrofacetDistribution,
    /// The width of the slopes' distribution along the tangent (Mitsuba's `alpha_u`).
    pub alpha_u: f32,
    /// The width across it, along the bitangent (Mitsuba's `alpha_v`).
    pub alpha_v: f32,
    /// Widths that vary over the surface, when a scene file gives `alpha`, `alpha_u` or
    /// `alpha_v` as a texture; [`Scene::material_at`](super::Scene::material_at) reads them
    /// at a hit into `alpha_u` and `alpha_v`, and chapters before 08 refuse them.
    pub alpha_texture: Option<AlphaTexture>,
    /// The tangent `alpha_u` runs along at a hit: the shape's `dp/du` there
    /// ([`Shape::dp_du`](crate::geometry::Shape::dp_du)), made perpendicular to the shading
    /// normal where the frame is built, as Mitsuba builds its shading frame.
    /// [`Scene::material_at`](super::Scene::material_at) fills it in where the widths differ;
    /// zero in a material as written, and then the frame is built from the normal alone (as
    /// Mitsuba's is where `dp/du` vanishes), which for a round roughness changes nothing.
    pub dp_du: Vec3,
}

/// A rough surface's widths as textures, each read as Mitsuba reads one number from a
/// texture ([`Scene::texture_value`](super::Scene::texture_value)); a width without a texture
/// keeps its number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlphaTexture {
    /// The width along the tangent.
    pub u: Option<Texture>,
    /// The width across it.
    pub v: Option<Texture>,
}

/// Mitsuba 3's two microfacet distributions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MicrofacetDistribution {
    /// Beckmann's Gaussian slopes.
    Beckmann,
    /// GGX (Trowbridge–Reitz), with longer tails.
    Ggx,
}

impl Microfacet {
    /// The same width `alpha` in every direction (Mitsuba's `alpha`).
    pub fn isotropic(distribution: MicrofacetDistribution, alpha: f32) -> Self {
        Self {
            distribution,
            alpha_u: alpha,
            alpha_v: alpha,
            alpha_texture: None,
            dp_du: Vec3::ZERO,
        }
    }

    /// Width `alpha_u` along the surface's tangent and `alpha_v` across it (Mitsuba's
    /// `alpha_u` and `alpha_v`).
    pub fn anisotropic(distribution: MicrofacetDistribution, alpha_u: f32, alpha_v: f32) -> Self {
        Self {
            alpha_u,
            alpha_v,
            ..Self::isotropic(distribution, alpha_u)
        }
    }

    /// Whether the width differs along and across the tangent.
    pub fn is_anisotropic(&self) -> bool {
        self.alpha_u != self.alpha_v
    }

    /// One width for what can only be round: `sqrt(alpha_u alpha_v)`, the width of the round
    /// distribution whose facets cover the same solid angle (`D` at the normal is
    /// `1 / (π alpha_u alpha_v)` for both distributions); `alpha` itself when isotropic.
    pub fn alpha(&self) -> f32 {
        if self.is_anisotropic() {
            (self.alpha_u * self.alpha_v).sqrt()
        } else {
            self.alpha_u
        }
    }

    /// The `cos^n` exponent whose lobe is about as wide as this roughness:
    /// `n = 2 / alpha² - 2` of [`alpha`](Self::alpha), never below 0 (alpha above 1 is rougher
    /// than any lobe).
    pub fn lobe_exponent(&self) -> f32 {
        let alpha = self.alpha();
        (2.0 / (alpha * alpha) - 2.0).max(0.0)
    }
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

    /// A one-sided fuzzy mirror.
    pub fn glossy(reflectance: Vec3, exponent: f32) -> Self {
        Material::Glossy(Glossy {
            reflectance,
            exponent,
            two_sided: false,
            stands_in_for: None,
        })
    }

    /// Frosted glass of index `ior` in air.
    pub fn rough_glass(ior: f32, exponent: f32) -> Self {
        Material::RoughGlass(RoughGlass {
            int_ior: ior,
            ext_ior: 1.0,
            exponent,
            stands_in_for: None,
        })
    }

    /// The lecture's material that chapters 01 to 07 render in place of one of chapter 08's,
    /// with what the replacement changes, in words for a note; `None` for the lecture's own
    /// materials and for those with no honest replacement (a thin pane, plastic), which those
    /// chapters refuse.
    ///
    /// A metal becomes a mirror (a `cos^n` lobe when rough, standing in for its roughness as
    /// chapter 06's rough materials do) whose reflectance is its Fresnel reflectance at normal
    /// incidence: its colour seen square on, without the brightening towards grazing angles.
    /// A metal of reflectance 1 at every angle (Mitsuba's `material="none"`) is that mirror
    /// exactly.
    pub fn lecture_stand_in(&self) -> Option<(Material, &'static str)> {
        let Material::Conductor(conductor) = self else {
            return None;
        };
        let reflectance = conductor.specular_reflectance * conductor.normal_incidence_fresnel();
        let stand_in = match conductor.roughness {
            None => Material::Mirror { reflectance },
            Some(microfacet) => Material::Glossy(Glossy {
                reflectance,
                exponent: microfacet.lobe_exponent(),
                two_sided: conductor.two_sided,
                stands_in_for: Some(microfacet),
            }),
        };
        Some((
            stand_in,
            "its reflectance at normal incidence at every angle (no brightening towards \
             grazing angles)",
        ))
    }

    /// The material without its mask: the nested material of a [`Material::Mask`] (through
    /// any number of masks), the material itself otherwise.
    pub fn unmasked(&self) -> &Material {
        match self {
            Material::Mask(mask) => mask.nested.unmasked(),
            other => other,
        }
    }

    /// The first parameter, other than a matte surface's albedo, that a texture varies over
    /// the surface, in a scene file's words ("a metal's specular_reflectance"); `None` when
    /// there is none. Chapter 08 reads these textures; the chapters before it refuse them.
    pub fn textured_beyond_albedo(&self) -> Option<&'static str> {
        match self {
            Material::Conductor(c) if c.specular_texture.is_some() => {
                Some("a metal's specular_reflectance")
            }
            Material::Plastic(p) if p.diffuse_texture.is_some() => {
                Some("plastic's diffuse_reflectance")
            }
            Material::Plastic(p) if p.specular_texture.is_some() => {
                Some("plastic's specular_reflectance")
            }
            Material::TintedGlass(g) if g.reflectance_texture.is_some() => {
                Some("glass's specular_reflectance")
            }
            Material::TintedGlass(g) if g.transmittance_texture.is_some() => {
                Some("glass's specular_transmittance")
            }
            Material::Mask(mask) => mask.nested.textured_beyond_albedo(),
            Material::Conductor(Conductor {
                roughness: Some(m), ..
            })
            | Material::RoughGlass(RoughGlass {
                stands_in_for: Some(m),
                ..
            })
            | Material::TintedGlass(TintedGlass {
                roughness: Some(m), ..
            }) if m.alpha_texture.is_some() => Some("a rough bsdf's alpha"),
            _ => None,
        }
    }

    /// Whether the material scatters with a lobe (chapter 06's materials).
    pub fn is_fuzzy(&self) -> bool {
        matches!(self, Material::Glossy(_) | Material::RoughGlass(_))
    }

    /// The same material with its lobe exponent replaced by `exponent` (smooth materials stay
    /// as they are); the lobe then stands in for no microfacet roughness.
    pub fn with_exponent(self, exponent: f32) -> Self {
        match self {
            Material::Glossy(g) => Material::Glossy(Glossy {
                exponent,
                stands_in_for: None,
                ..g
            }),
            Material::RoughGlass(g) => Material::RoughGlass(RoughGlass {
                exponent,
                stands_in_for: None,
                ..g
            }),
            Material::Mask(mask) => Material::Mask(Mask {
                nested: Box::new(mask.nested.with_exponent(exponent)),
                ..mask
            }),
            smooth => smooth,
        }
    }
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
        assert!(!Material::mirror().is_fuzzy());
        assert!(Material::glossy(Vec3::ONE, 10.0).is_fuzzy());
        assert!(Material::rough_glass(1.5, 10.0).is_fuzzy());
        assert_eq!(
            Material::glossy(Vec3::ONE, 10.0).with_exponent(3.0),
            Material::glossy(Vec3::ONE, 3.0)
        );
    }

    #[test]
    fn beckmann_roughness_maps_to_lobe_exponents() {
        let exponent =
            |alpha| Microfacet::isotropic(MicrofacetDistribution::Beckmann, alpha).lobe_exponent();
        approx::assert_relative_eq!(exponent(0.1), 198.0, max_relative = 1e-5);
        approx::assert_relative_eq!(exponent(1e-3), 2e6 - 2.0, max_relative = 1e-5);
        assert_eq!(exponent(1.0), 0.0);
        assert_eq!(exponent(3.0), 0.0);
    }
}
