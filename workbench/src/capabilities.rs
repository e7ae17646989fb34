//! What a chapter can render, and one check that refuses the rest.
//!
//! Every chapter renders the same [`Scene`], but each knows only the features the chapters up
//! to it have brought: chapter 01 knows point lights and smooth materials, chapter 04 adds a
//! lens with an aperture, chapter 07 area lights, and so on. A chapter's [`Capabilities`] name
//! the chapter (so it renders every [`Feature`] that it or a chapter before it brings) and the
//! features it renders in a way of its own; [`Capabilities::check`] finds every feature a
//! scene uses ([`features`]) and
//!
//! - refuses a feature the chapter cannot render, naming where the scene file writes it and
//!   the chapter that brings it ("line 32, column 5: an area light (shape 3); soft shadows
//!   from lights with an area come in chapter 07 (ch07-soft-shadows); ...");
//! - notes light the chapter leaves out (indirect light before chapter 08), and settings it
//!   ignores (a film's filter in chapter 01), each from the same declaration.

use common::scene::{
    Camera, CameraModel, DirectSamples, FilmFilter, Integrator, Material, Scene, TextPosition,
};
use std::fmt;

/// A chapter of the workbook, named in messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Chapter {
    /// Its number, from 1.
    pub number: u32,
    /// Its package, such as `ch07-soft-shadows`.
    pub package: &'static str,
}

impl fmt::Display for Chapter {
    /// `chapter 07 (ch07-soft-shadows)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "chapter {:02} ({})", self.number, self.package)
    }
}

impl Chapter {
    /// Whitted ray tracing.
    pub const WHITTED: Chapter = Chapter {
        number: 1,
        package: "ch01-whitted",
    };
    /// Anti-aliasing.
    pub const ANTI_ALIASING: Chapter = Chapter {
        number: 3,
        package: "ch03-anti-aliasing",
    };
    /// Depth of field.
    pub const DEPTH_OF_FIELD: Chapter = Chapter {
        number: 4,
        package: "ch04-depth-of-field",
    };
    /// Motion blur.
    pub const MOTION_BLUR: Chapter = Chapter {
        number: 5,
        package: "ch05-motion-blur",
    };
    /// Fuzzy reflections and refractions.
    pub const FUZZY_REFLECTIONS: Chapter = Chapter {
        number: 6,
        package: "ch06-fuzzy-reflections",
    };
    /// Soft shadows.
    pub const SOFT_SHADOWS: Chapter = Chapter {
        number: 7,
        package: "ch07-soft-shadows",
    };
    /// The path tracer.
    pub const PATH_TRACING: Chapter = Chapter {
        number: 8,
        package: "ch08-path-tracing",
    };
    /// Beyond the lecture: Mitsuba's materials over chapter 08's path loop.
    pub const MATERIALS: Chapter = Chapter {
        number: 9,
        package: "ch09-materials",
    };
    /// The lecture's recent advances: optimal multiple importance sampling.
    pub const OPTIMAL_MIS: Chapter = Chapter {
        number: 10,
        package: "ch10-optimal-mis",
    };
    /// The lecture's recent advances: path guiding.
    pub const PATH_GUIDING: Chapter = Chapter {
        number: 11,
        package: "ch11-path-guiding",
    };
}

/// Something a scene may use that not every chapter renders.
///
/// What every chapter renders (point lights, matte surfaces, mirrors, glass, a pinhole, an
/// environment seen directly) is not a feature.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Feature {
    /// A reconstruction filter wider than a pixel's box.
    FilmFilter,
    /// A lens with an aperture.
    Aperture,
    /// A shape that moves.
    MovingShape,
    /// A camera that moves.
    MovingCamera,
    /// A glossy or frosted material: a `cos^n` lobe.
    FuzzyMaterial,
    /// A lobe that stands in for a scene file's microfacet roughness (`roughconductor`,
    /// `roughdielectric`): the same chapter renders it, in a way of its own.
    MicrofacetMaterial,
    /// A shape that glows.
    AreaLight,
    /// A glowing shape that moves.
    MovingAreaLight,
    /// Light that reaches a matte surface from other surfaces, asked for by a `path`
    /// integrator of more than two segments.
    IndirectLight,
    /// The environment lighting matte surfaces (not only seen directly or in mirrors).
    EnvironmentLight,
    /// Light from an image around the scene (Mitsuba's `envmap`).
    EnvironmentMap,
    /// A light infinitely far away that shines one way (Mitsuba's `directional`).
    DirectionalLight,
    /// Emitters hidden from camera rays (Mitsuba's `hide_emitters`).
    HiddenEmitters,
    /// A `direct` integrator's sample counts other than one light and one BSDF sample.
    DirectSampleCounts,
    /// A metal whose reflectance changes with the angle (a complex index of refraction);
    /// chapters before 08 render the lecture's mirror or lobe in its place
    /// ([`Material::lecture_stand_in`]).
    MetalFresnel,
    /// A pane of thin glass (Mitsuba's `thindielectric`).
    ThinDielectric,
    /// A matte base under a clear coat (Mitsuba's `plastic`, `roughplastic`).
    Plastic,
    /// A cut-out surface that light passes through where it is not opaque (Mitsuba's
    /// `mask`): only a path tracer picks, at random, whether a ray meets it or passes on.
    Mask,
    /// A texture on a material's parameter other than a matte surface's albedo (a metal's
    /// `specular_reflectance`, plastic's `diffuse_reflectance`, ...).
    TexturedMaterial,
    /// An area light whose radiance is a texture, so that it varies over the light.
    TexturedAreaLight,
    /// Glass whose reflection or transmission is scaled (Mitsuba's `specular_reflectance`,
    /// `specular_transmittance` on `dielectric` and `roughdielectric`).
    TintedGlass,
}

/// What a chapter that does not render a feature does with a scene that uses it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum WhenMissing {
    /// The scene is refused.
    Refuse,
    /// The scene is rendered without the feature, with this note.
    Note(&'static str),
    /// The scene is rendered with the lecture's stand-in, which the use's detail describes.
    StandIn,
}

impl Feature {
    /// The chapter that brings the feature; `None` for what no chapter renders.
    pub fn brought_by(self) -> Option<Chapter> {
        match self {
            Feature::FilmFilter => Some(Chapter::ANTI_ALIASING),
            Feature::Aperture => Some(Chapter::DEPTH_OF_FIELD),
            Feature::MovingShape | Feature::MovingCamera => Some(Chapter::MOTION_BLUR),
            Feature::FuzzyMaterial | Feature::MicrofacetMaterial => {
                Some(Chapter::FUZZY_REFLECTIONS)
            }
            Feature::AreaLight => Some(Chapter::SOFT_SHADOWS),
            Feature::IndirectLight
            | Feature::EnvironmentLight
            | Feature::EnvironmentMap
            | Feature::DirectionalLight
            | Feature::HiddenEmitters
            | Feature::DirectSampleCounts
            | Feature::TexturedAreaLight => Some(Chapter::PATH_TRACING),
            Feature::MetalFresnel
            | Feature::ThinDielectric
            | Feature::Plastic
            | Feature::Mask
            | Feature::TexturedMaterial
            | Feature::TintedGlass => Some(Chapter::MATERIALS),
            Feature::MovingAreaLight => None,
        }
    }

    /// What the feature is, as a message names it.
    fn what(self) -> &'static str {
        match self {
            Feature::FilmFilter => "a reconstruction filter",
            Feature::Aperture => "a lens with an aperture",
            Feature::MovingShape => "a shape that moves",
            Feature::MovingCamera => "a camera that moves",
            Feature::FuzzyMaterial => "a glossy or frosted material",
            Feature::MicrofacetMaterial => "a microfacet roughness",
            Feature::AreaLight => "an area light",
            Feature::MovingAreaLight => "an area light that moves",
            Feature::IndirectLight => "indirect light",
            Feature::EnvironmentLight => "an environment",
            Feature::EnvironmentMap => "an environment map (envmap)",
            Feature::DirectionalLight => "a directional light",
            Feature::HiddenEmitters => "emitters hidden from the camera",
            Feature::DirectSampleCounts => "the direct integrator's sample counts",
            Feature::MetalFresnel => "a metal",
            Feature::ThinDielectric => "a thin pane of glass (thindielectric)",
            Feature::Plastic => "plastic",
            Feature::Mask => "a cut-out (mask)",
            Feature::TexturedMaterial => "a texture",
            Feature::TexturedAreaLight => "an area light whose radiance is a texture",
            Feature::TintedGlass => "glass with a specular_reflectance or specular_transmittance",
        }
    }

    /// The lesson the feature belongs to, as in "soft shadows come in chapter 07".
    fn lesson(self) -> &'static str {
        match self {
            Feature::FilmFilter => "reconstruction filters come",
            Feature::Aperture => "depth of field comes",
            Feature::MovingShape | Feature::MovingCamera => "motion blur comes",
            Feature::FuzzyMaterial | Feature::MicrofacetMaterial => {
                "fuzzy reflections and refractions come"
            }
            Feature::AreaLight => "soft shadows from lights with an area come",
            Feature::MovingAreaLight => "no chapter samples lights that move",
            Feature::IndirectLight => "indirect light comes",
            Feature::EnvironmentLight => "the environment lights matte surfaces",
            Feature::EnvironmentMap => "light from an image around the scene comes",
            Feature::DirectionalLight => "light from infinitely far away comes",
            Feature::HiddenEmitters => "the integrator's hide_emitters comes",
            Feature::DirectSampleCounts => "emitter_samples and bsdf_samples are taken as given",
            Feature::MetalFresnel => "metals' reflectance by angle comes",
            Feature::ThinDielectric | Feature::Plastic | Feature::TintedGlass => {
                "materials beyond the lecture's are rendered"
            }
            Feature::Mask => "surfaces that light may pass through at random are rendered",
            Feature::TexturedMaterial => {
                "textures on other parameters than a matte surface's reflectance are read"
            }
            Feature::TexturedAreaLight => "lights that vary over their surface are sampled",
        }
    }

    fn when_missing(self) -> WhenMissing {
        match self {
            Feature::FilmFilter => WhenMissing::Note(
                "the film's reconstruction filter is ignored: this chapter averages each pixel's own samples (a box filter)",
            ),
            Feature::IndirectLight => WhenMissing::Note(
                "this chapter leaves out indirect light (light that reaches a matte surface from other surfaces), which Mitsuba's path integrator includes",
            ),
            Feature::EnvironmentLight => WhenMissing::Note(
                "the constant environment is seen directly and in mirrors and glass, but it does not light matte surfaces here",
            ),
            Feature::DirectSampleCounts => WhenMissing::Note(
                "the direct integrator's emitter_samples and bsdf_samples are not followed: this chapter lights each surface as its lesson does, the same image on average with other noise",
            ),
            Feature::MetalFresnel => WhenMissing::StandIn,
            _ => WhenMissing::Refuse,
        }
    }
}

/// One use of a feature in a scene: where it is written, and what it is there.
#[derive(Clone, Debug, PartialEq)]
pub struct FeatureUse {
    /// The feature.
    pub feature: Feature,
    /// Where the scene file writes it; `None` for a built-in scene.
    pub origin: Option<TextPosition>,
    /// What it is in this scene, such as "shape 3 (a sphere)"; may be empty.
    pub detail: String,
}

impl FeatureUse {
    /// `line 32, column 5: an area light (shape 3)`.
    fn describe(&self) -> String {
        let mut text = String::new();
        if let Some(origin) = &self.origin {
            text.push_str(&format!("{origin}: "));
        }
        text.push_str(self.feature.what());
        if !self.detail.is_empty() {
            text.push_str(&format!(" ({})", self.detail));
        }
        text
    }
}

/// What a chapter renders: every feature it or a chapter before it brings, some of them in a
/// way of its own, each of those with its note.
#[derive(Clone, Copy, Debug)]
pub struct Capabilities {
    /// The chapter.
    pub chapter: Chapter,
    /// Features it renders in a way of its own, with the note that says how.
    pub approximates: &'static [(Feature, &'static str)],
}

impl Capabilities {
    /// Whether the chapter renders `feature`: whether it or a chapter before it brings it.
    pub fn renders(&self, feature: Feature) -> bool {
        feature
            .brought_by()
            .is_some_and(|chapter| chapter.number <= self.chapter.number)
    }

    /// Checks that the chapter can render `scene`: the notes to print (light left out,
    /// settings ignored, approximations), or a refusal naming where the first feature it
    /// cannot render is written and the chapter that brings it.
    pub fn check(&self, scene: &Scene) -> Result<Vec<String>, String> {
        let mut notes: Vec<String> = Vec::new();
        let mut note = |text: String| {
            if !notes.contains(&text) {
                notes.push(text);
            }
        };
        for usage in features(scene) {
            let feature = usage.feature;
            if self.renders(feature) {
                if let Some((_, how)) = self.approximates.iter().find(|(f, _)| *f == feature) {
                    note(format!("{}: {how}", usage.describe()));
                }
                continue;
            }
            let brought_by = match feature.brought_by() {
                Some(chapter) => format!(" in {chapter}"),
                None => String::new(),
            };
            match feature.when_missing() {
                WhenMissing::Note(text) => {
                    note(format!("{text}; {}{brought_by}", feature.lesson()))
                }
                WhenMissing::StandIn => note(format!(
                    "{}; {}{brought_by}",
                    usage.describe(),
                    feature.lesson()
                )),
                WhenMissing::Refuse => {
                    return Err(format!(
                        "{}; {}{brought_by}; {} renders {}",
                        usage.describe(),
                        feature.lesson(),
                        self.chapter,
                        self.known()
                    ));
                }
            }
        }
        Ok(notes)
    }

    /// Replaces, in a chapter that does not render metals (the lecture's chapters), every
    /// material with a lecture stand-in by it ([`Material::lecture_stand_in`]), so that the
    /// chapter's tracer meets only the lecture's materials; [`check`](Self::check) writes the
    /// notes that say so. The chapter that renders the materials themselves leaves the scene
    /// as it is.
    pub fn put_in_stand_ins(&self, scene: &mut Scene) {
        if self.renders(Feature::MetalFresnel) {
            return;
        }
        for surface in &mut scene.surfaces {
            if let Some((stand_in, _)) = surface.material.lecture_stand_in() {
                surface.material = stand_in;
            }
        }
    }

    /// What the chapter renders, in words, for a refusal.
    fn known(&self) -> String {
        let mut known = vec!["point lights, matte surfaces, mirrors and glass"];
        for (feature, words) in [
            (Feature::FilmFilter, "reconstruction filters"),
            (Feature::Aperture, "lenses"),
            (Feature::MovingShape, "motion"),
            (Feature::FuzzyMaterial, "glossy and frosted materials"),
            (Feature::AreaLight, "area lights"),
            (Feature::IndirectLight, "indirect light"),
        ] {
            if self.renders(feature) {
                known.push(words);
            }
        }
        match known.split_last() {
            Some((last, [])) => (*last).to_string(),
            Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
            None => String::new(),
        }
    }
}

/// Every use of a [`Feature`] in `scene`, in the order the file writes them: the
/// integrator, the sensor (lens, motion, filter), the shapes, the environment.
pub fn features(scene: &Scene) -> Vec<FeatureUse> {
    let mut uses = Vec::new();
    let mut add = |feature, origin, detail: String| {
        uses.push(FeatureUse {
            feature,
            origin,
            detail,
        })
    };
    if let Integrator::Direct(samples) = scene.integrator
        && samples != DirectSamples::ONE_EACH
    {
        add(
            Feature::DirectSampleCounts,
            scene.origins.integrator.clone(),
            format!(
                "emitter_samples {}, bsdf_samples {}",
                samples.emitter, samples.bsdf
            ),
        );
    }
    if matches!(scene.integrator, Integrator::Path { .. }) && scene.max_depth > 2 {
        add(
            Feature::IndirectLight,
            scene.origins.integrator.clone(),
            "the path integrator's max_depth".to_string(),
        );
    }
    let Camera {
        model, keyframes, ..
    } = &scene.camera;
    if let CameraModel::ThinLens {
        aperture_radius, ..
    } = *model
        && aperture_radius > 0.0
    {
        add(
            Feature::Aperture,
            scene.origins.sensor.clone(),
            format!("aperture radius {aperture_radius}"),
        );
    }
    if !keyframes.is_empty() {
        add(
            Feature::MovingCamera,
            scene.origins.sensor.clone(),
            "an <animation> of the sensor's to_world".to_string(),
        );
    }
    if scene.film.filter != FilmFilter::Box {
        add(
            Feature::FilmFilter,
            scene
                .origins
                .filter
                .clone()
                .or(scene.origins.sensor.clone()),
            format!("{:?}", scene.film.filter).to_lowercase(),
        );
    }
    let still = scene.geometry.shapes().len();
    // Each surface once, named by the first shape made of it (surfaces are numbered in
    // that order); the pieces of one shape of a file all stand still or all move.
    let mut first_shape = vec![None; scene.surfaces.len()];
    for (shape, &surface) in scene.surface_of_shape.iter().enumerate() {
        first_shape[surface as usize].get_or_insert(shape);
    }
    for (surface, first_shape) in scene.surfaces.iter().zip(first_shape) {
        let Some(index) = first_shape else { continue };
        let name = format!("shape {}", index + 1);
        let moves = index >= still;
        if moves {
            add(Feature::MovingShape, surface.origin.clone(), name.clone());
        }
        if surface.emitter.is_some() {
            let feature = if moves {
                Feature::MovingAreaLight
            } else {
                Feature::AreaLight
            };
            add(feature, surface.origin.clone(), name.clone());
        }
        if let Material::Mask(_) = surface.material {
            add(Feature::Mask, surface.origin.clone(), name.clone());
        }
        // What the mask lets be seen is checked as any other material.
        let material = surface.material.unmasked();
        if let Some((stand_in, how)) = material.lecture_stand_in()
            && let Material::Conductor(conductor) = material
            && conductor.eta != glam::Vec3::ZERO
        {
            add(
                Feature::MetalFresnel,
                surface.origin.clone(),
                format!(
                    "{name}: rendered as {}, {how}",
                    describe_stand_in(&stand_in)
                ),
            );
        }
        match material {
            Material::ThinDielectric { .. } => add(
                Feature::ThinDielectric,
                surface.origin.clone(),
                name.clone(),
            ),
            Material::Plastic(_) => add(Feature::Plastic, surface.origin.clone(), name.clone()),
            Material::TintedGlass(_) => {
                add(Feature::TintedGlass, surface.origin.clone(), name.clone())
            }
            _ => {}
        }
        if let Some(parameter) = material.textured_beyond_albedo() {
            add(
                Feature::TexturedMaterial,
                surface.origin.clone(),
                format!("{name}: {parameter}"),
            );
        }
        if surface.emitter.is_some_and(|e| e.texture.is_some()) {
            add(
                Feature::TexturedAreaLight,
                surface.origin.clone(),
                name.clone(),
            );
        }
        if let Some((detail, stands_in)) = fuzzy_detail(material) {
            let feature = if stands_in {
                Feature::MicrofacetMaterial
            } else {
                Feature::FuzzyMaterial
            };
            add(feature, surface.origin.clone(), format!("{name}: {detail}"));
        }
    }
    if scene.environment != glam::Vec3::ZERO {
        add(
            Feature::EnvironmentLight,
            scene.origins.environment.clone(),
            String::new(),
        );
    }
    if scene.environment_map.is_some() {
        add(
            Feature::EnvironmentMap,
            scene.origins.environment_map.clone(),
            String::new(),
        );
    }
    if !scene.directional_lights.is_empty() {
        add(
            Feature::DirectionalLight,
            scene.origins.directional_light.clone(),
            String::new(),
        );
    }
    let something_glows = scene.environment != glam::Vec3::ZERO
        || scene.environment_map.is_some()
        || scene
            .surfaces
            .iter()
            .any(|surface| surface.emitter.is_some());
    if scene.hide_emitters && something_glows {
        add(
            Feature::HiddenEmitters,
            scene.origins.integrator.clone(),
            "hide_emitters".to_string(),
        );
    }
    uses
}

/// A stand-in material in words, for a note: "a mirror of reflectance (0.95, 0.64, 0.54)".
fn describe_stand_in(material: &Material) -> String {
    let rgb = |c: glam::Vec3| format!("({:.3}, {:.3}, {:.3})", c.x, c.y, c.z);
    match material {
        Material::Mirror { reflectance } => {
            format!("a mirror of reflectance {}", rgb(*reflectance))
        }
        Material::Glossy(g) => format!("a lobe of reflectance {}", rgb(g.reflectance)),
        other => format!("{other:?}"),
    }
}

/// What a fuzzy material is, for messages, and whether it stands in for a microfacet
/// roughness; `None` for a smooth one.
fn fuzzy_detail(material: &Material) -> Option<(String, bool)> {
    let (kind, exponent, stands_in_for) = match material {
        Material::Glossy(g) => ("roughconductor", g.exponent, g.stands_in_for),
        Material::RoughGlass(g) => ("roughdielectric", g.exponent, g.stands_in_for),
        // A metal of eta 0 reflects everything at every angle; any other keeps its colour
        // square on at every angle of the lobe, as the lecture's stand-in does.
        Material::Conductor(c) => {
            let microfacet = c.roughness?;
            (
                if c.eta == glam::Vec3::ZERO {
                    "roughconductor"
                } else {
                    "roughconductor of its reflectance at normal incidence"
                },
                microfacet.lobe_exponent(),
                Some(microfacet),
            )
        }
        Material::Plastic(p) => {
            let microfacet = p.roughness?;
            (
                "roughplastic (its coat)",
                microfacet.lobe_exponent(),
                Some(microfacet),
            )
        }
        _ => return None,
    };
    Some(match stands_in_for {
        Some(microfacet) => (
            format!(
                "{kind} with {} as a cos^n lobe of exponent {exponent:.1}",
                describe_alpha(microfacet)
            ),
            true,
        ),
        None => (format!("a cos^n lobe of exponent {exponent}"), false),
    })
}

/// A roughness in a note's words: `alpha 0.2`, or `alpha_u 0.1, alpha_v 0.4 (a round lobe of
/// alpha 0.2)` where the lobe cannot follow the two widths.
fn describe_alpha(microfacet: common::scene::Microfacet) -> String {
    if microfacet.is_anisotropic() {
        format!(
            "alpha_u {}, alpha_v {} (a round lobe of alpha {})",
            microfacet.alpha_u,
            microfacet.alpha_v,
            microfacet.alpha()
        )
    } else {
        format!("alpha {}", microfacet.alpha_u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use common::geometry::{Shape, Sphere};
    use common::scene::{CameraFrame, FilmSettings, SceneBuilder};
    use glam::{Mat4, Vec3};

    const WHITTED: Capabilities = Capabilities {
        chapter: Chapter::WHITTED,
        approximates: &[],
    };

    const SOFT_SHADOWS: Capabilities = Capabilities {
        chapter: Chapter::SOFT_SHADOWS,
        approximates: &[(Feature::MicrofacetMaterial, "rendered as a lobe")],
    };

    fn sphere() -> Shape {
        Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0))
    }

    fn scene(builder: SceneBuilder) -> Scene {
        let frame = CameraFrame::look_at(Vec3::Z * 5.0, Vec3::ZERO, Vec3::Y).unwrap();
        builder.build(
            common::scene::Camera::pinhole(frame, 40.0),
            FilmSettings::new(4, 4),
            2,
        )
    }

    #[test]
    fn a_feature_of_a_later_chapter_is_refused_with_where_and_who() {
        let mut lit = scene(SceneBuilder::new().area_light(
            sphere(),
            Material::diffuse(Vec3::ONE),
            Vec3::ONE,
        ));
        lit.surfaces[0].origin = Some(TextPosition {
            line: 32,
            column: 5,
            file: None,
        });
        let refusal = WHITTED.check(&lit).unwrap_err();
        assert!(
            refusal.starts_with("line 32, column 5: an area light (shape 1); soft shadows")
                && refusal.contains("chapter 07 (ch07-soft-shadows)")
                && refusal.contains("chapter 01 (ch01-whitted) renders point lights"),
            "{refusal}"
        );
        assert_eq!(SOFT_SHADOWS.check(&lit), Ok(Vec::new()));
    }

    #[test]
    fn a_directional_light_waits_for_chapter_08() {
        let sunlit = scene(
            SceneBuilder::new()
                .shape(sphere(), Material::diffuse(Vec3::ONE))
                .directional_light(common::scene::DirectionalLight {
                    direction: -Vec3::Y,
                    irradiance: Vec3::ONE,
                }),
        );
        let refusal = SOFT_SHADOWS.check(&sunlit).unwrap_err();
        assert!(
            refusal.contains("a directional light") && refusal.contains("chapter 08"),
            "{refusal}"
        );
        let path_tracing = Capabilities {
            chapter: Chapter::PATH_TRACING,
            approximates: &[],
        };
        assert_eq!(path_tracing.check(&sunlit), Ok(Vec::new()));
    }

    #[test]
    fn light_left_out_is_noted_and_approximations_say_how() {
        let rough = Material::Glossy(common::scene::Glossy {
            stands_in_for: Some(common::scene::Microfacet::isotropic(
                common::scene::MicrofacetDistribution::Beckmann,
                0.5,
            )),
            ..match Material::glossy(Vec3::ONE, 6.0) {
                Material::Glossy(g) => g,
                _ => unreachable!(),
            }
        });
        let mut glossy = scene(
            SceneBuilder::new()
                .shape(sphere(), Material::glossy(Vec3::ONE, 10.0))
                .shape(sphere(), rough)
                .environment(Vec3::ONE),
        );
        glossy.max_depth = 8;
        let notes = SOFT_SHADOWS.check(&glossy).unwrap();
        assert_eq!(notes.len(), 3, "{notes:?}");
        assert!(notes[0].contains("leaves out indirect light") && notes[0].contains("chapter 08"));
        // The lobe of shape 1 is the chapter's own; shape 2's stands in for a roughness.
        assert!(
            notes[1].contains("(shape 2: roughconductor with alpha 0.5 as a cos^n lobe of exponent 6.0): rendered as a lobe"),
            "{notes:?}"
        );
        assert!(notes[2].contains("does not light matte surfaces"));
        // Direct light only: nothing indirect to leave out.
        glossy.max_depth = 2;
        assert_eq!(SOFT_SHADOWS.check(&glossy).unwrap().len(), 2);
        let refusal = WHITTED.check(&glossy).unwrap_err();
        assert!(
            refusal.contains("a glossy or frosted material (shape 1")
                && refusal.contains("chapter 06"),
            "{refusal}"
        );
    }

    #[test]
    fn metals_get_the_lectures_stand_in_before_chapter_09_and_thin_glass_and_plastic_wait() {
        const PATH_TRACING: Capabilities = Capabilities {
            chapter: Chapter::PATH_TRACING,
            approximates: &[],
        };
        const MATERIALS: Capabilities = Capabilities {
            chapter: Chapter::MATERIALS,
            approximates: &[],
        };
        let gold = common::scene::Conductor {
            eta: Vec3::new(0.143, 0.375, 1.442),
            k: Vec3::new(3.983, 2.386, 1.603),
            specular_reflectance: Vec3::ONE,
            specular_texture: None,
            two_sided: false,
            roughness: None,
        };
        let mut metal = scene(SceneBuilder::new().shape(sphere(), Material::Conductor(gold)));
        let notes = WHITTED.check(&metal).unwrap();
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(
            notes[0].starts_with("a metal (shape 1: rendered as a mirror of reflectance (0.967")
                && notes[0].contains("normal incidence")
                && notes[0].contains("chapter 09"),
            "{notes:?}"
        );
        // Chapter 08, the last of the lecture, stands in as the chapters before it do.
        assert_eq!(PATH_TRACING.check(&metal).unwrap(), notes);
        assert_eq!(MATERIALS.check(&metal), Ok(Vec::new()));
        MATERIALS.put_in_stand_ins(&mut metal);
        assert_eq!(metal.surfaces[0].material, Material::Conductor(gold));
        PATH_TRACING.put_in_stand_ins(&mut metal);
        assert!(
            matches!(metal.surfaces[0].material, Material::Mirror { reflectance } if reflectance.z < 0.5)
        );

        // Rough: a lobe, which needs chapter 06; eta 0 reflects everything, so no note on
        // its colour.
        let rough = Material::Conductor(common::scene::Conductor {
            eta: Vec3::ZERO,
            k: Vec3::ONE,
            roughness: Some(common::scene::Microfacet::isotropic(
                common::scene::MicrofacetDistribution::Beckmann,
                0.5,
            )),
            ..gold
        });
        let rough = scene(SceneBuilder::new().shape(sphere(), rough));
        assert!(
            WHITTED
                .check(&rough)
                .unwrap_err()
                .contains("microfacet roughness")
        );
        let notes = SOFT_SHADOWS.check(&rough).unwrap();
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(
            notes[0].contains("roughconductor with alpha 0.5"),
            "{notes:?}"
        );

        for (material, words) in [
            (
                Material::ThinDielectric {
                    int_ior: 1.5,
                    ext_ior: 1.0,
                },
                "a thin pane of glass (thindielectric) (shape 1)",
            ),
            (
                Material::Plastic(common::scene::Plastic {
                    diffuse_reflectance: Vec3::splat(0.5),
                    specular_reflectance: Vec3::ONE,
                    diffuse_texture: None,
                    specular_texture: None,
                    int_ior: 1.49,
                    ext_ior: 1.0,
                    nonlinear: false,
                    two_sided: false,
                    roughness: None,
                }),
                "plastic (shape 1)",
            ),
            (
                Material::Mask(common::scene::Mask {
                    opacity: common::scene::Opacity::Uniform(0.5),
                    nested: Box::new(Material::diffuse(Vec3::ONE)),
                }),
                "a cut-out (mask) (shape 1)",
            ),
        ] {
            let beyond = scene(SceneBuilder::new().shape(sphere(), material));
            let refusal = SOFT_SHADOWS.check(&beyond).unwrap_err();
            assert!(
                refusal.starts_with(words) && refusal.contains("chapter 09 (ch09-materials)"),
                "{refusal}"
            );
            let refusal = PATH_TRACING.check(&beyond).unwrap_err();
            assert!(
                refusal.starts_with(words) && refusal.contains("chapter 09 (ch09-materials)"),
                "{refusal}"
            );
            assert_eq!(MATERIALS.check(&beyond), Ok(Vec::new()));
        }
    }

    #[test]
    fn a_moving_light_is_refused_by_every_chapter() {
        let keyframes = vec![
            (0.0, Mat4::IDENTITY),
            (1.0, Mat4::from_translation(Vec3::X)),
        ];
        let mut moving =
            scene(SceneBuilder::new().moving(sphere(), keyframes, Material::diffuse(Vec3::ONE)));
        moving.surfaces[0].emitter = Some(common::scene::AreaEmitter::uniform(Vec3::ONE));
        let refusal = SOFT_SHADOWS.check(&moving).unwrap_err();
        assert!(
            refusal.contains("an area light that moves (shape 1); no chapter samples"),
            "{refusal}"
        );
    }
}
