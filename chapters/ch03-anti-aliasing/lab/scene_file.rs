//! What a scene file says about anti-aliasing: its `<rfilter>` and its `<sampler>`.
//!
//! Chapter 01 renders everything Whitted's method can and averages each pixel's own samples.
//! This chapter renders the same scenes but honours the film's filter, and picks the pixel
//! sampler closest to the file's.

use crate::filters::{FilterKind, ReconstructionFilter};
use crate::pixel_samplers::{PixelSampler, PixelSamplerKind};
use common::render::RenderSettings;
use common::scene::{FilmFilter, Scene};
use std::path::Path;
use workbench::agreement::AGREEMENT_SPP;
use workbench::capabilities::Capabilities;
use workbench::cli::{CliError, print_note, read_scene_file};
use workbench::driver::FromSceneFile;
use workbench::scene_file::load_scene_file;

/// What this chapter reads from a scene file's film and sampler; the sampler's sample count
/// is the render's budget, which the render driver reads with `--spp`.
#[derive(Clone, Debug)]
pub struct FilmSide {
    /// The film's reconstruction filter.
    pub filter: ReconstructionFilter,
    /// The pixel sampler closest to the file's `<sampler>` type.
    pub sampler: PixelSamplerKind,
    /// What the choices change, to print.
    pub notes: Vec<String>,
}

/// The film side of `scene`, or why its filter makes no sense.
pub fn film_side(scene: &Scene) -> Result<FilmSide, String> {
    let filter = filter_of(scene.film.filter)?;
    let (sampler, note) = sampler_of(&scene.sampler.type_name);
    Ok(FilmSide {
        filter,
        sampler,
        notes: note.into_iter().collect(),
    })
}

/// A scene file for a chapter's `render`: read with the `-D` overrides and checked against
/// the chapter's `capabilities` ([`read_scene_file`]), its film side read; every note printed.
impl FromSceneFile for FilmSide {
    fn read(
        path: &Path,
        defines: &[(String, String)],
        capabilities: &Capabilities,
    ) -> Result<(Scene, FilmSide), CliError> {
        let scene = read_scene_file(path, defines, capabilities)?;
        let film = film_side(&scene).map_err(|message| CliError::Unrenderable {
            file: path.to_path_buf(),
            message,
        })?;
        for note in &film.notes {
            print_note(note);
        }
        Ok((scene, film))
    }
}

/// A scene file as a chapter checks it against Mitsuba 3: loaded, checked against the
/// chapter's `capabilities`, with its film side, the settings of a render at
/// [`AGREEMENT_SPP`] samples per pixel at the file's size, and the file's pixel sampler for
/// that count. Errors name the file.
pub fn for_agreement(
    path: &Path,
    capabilities: &Capabilities,
) -> Result<(Scene, FilmSide, RenderSettings, PixelSampler), String> {
    let in_file = |e: String| format!("{}: {e}", path.display());
    let mut scene = load_scene_file(path, &[]).map_err(|e| e.to_string())?.scene;
    capabilities.check(&scene).map_err(in_file)?;
    capabilities.put_in_stand_ins(&mut scene);
    let film = film_side(&scene).map_err(in_file)?;
    let settings = RenderSettings::new(scene.film.width, scene.film.height, AGREEMENT_SPP);
    let sampler = PixelSampler::new(film.sampler, AGREEMENT_SPP, 0).map_err(|e| e.to_string())?;
    Ok((scene, film, settings, sampler))
}

/// The chapter's sampler for a Mitsuba `<sampler>` type, and a note when it is only the
/// closest one: Mitsuba's `independent` is our random sampler, its `stratified` and
/// `multijitter` ours, each placing every dimension, its `ldsampler` our Sobol sampler (both
/// draw Owen-scrambled points of the same (0, 2)-sequence); its `orthogonal` (orthogonal
/// arrays, which stratify every 2D projection) is rendered with our multi-jittered sampler,
/// which stratifies the pairs a sample draws together.
pub fn sampler_of(type_name: &str) -> (PixelSamplerKind, Option<String>) {
    let closest = |kind: PixelSamplerKind| {
        let note = format!(
            "the file's `{type_name}` sampler is rendered with the closest of this chapter's, `{}`",
            kind.name()
        );
        (kind, Some(note))
    };
    match type_name {
        "independent" => (PixelSamplerKind::Random, None),
        "stratified" => (PixelSamplerKind::Stratified, None),
        "multijitter" => (PixelSamplerKind::MultiJitter, None),
        "ldsampler" => (PixelSamplerKind::Sobol, None),
        "orthogonal" => closest(PixelSamplerKind::MultiJitter),
        _ => closest(PixelSamplerKind::Stratified),
    }
}

/// The chapter's filter for a file's `<rfilter>`, with Mitsuba's parameters.
pub fn filter_of(filter: FilmFilter) -> Result<ReconstructionFilter, String> {
    let in_file = |e: String| format!("the film's rfilter: {e}");
    match filter {
        FilmFilter::Box => ReconstructionFilter::new(FilterKind::Box, None),
        FilmFilter::Tent { radius } => {
            ReconstructionFilter::new(FilterKind::Tent, Some(radius)).map_err(in_file)
        }
        FilmFilter::Gaussian { stddev } => {
            ReconstructionFilter::new(FilterKind::Gaussian, Some(4.0 * stddev)).map_err(in_file)
        }
        FilmFilter::Mitchell { b, c } => {
            if !(b.is_finite() && c.is_finite()) {
                return Err(in_file(format!("B {b} and C {c} must be numbers")));
            }
            Ok(ReconstructionFilter::Mitchell { radius: 2.0, b, c })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use workbench::scene_file::parse_scene;

    /// A one-sphere scene whose film has the filter `rfilter` (XML) or none (Mitsuba's default).
    fn scene_with(rfilter: &str) -> Scene {
        let text = format!(
            r#"<scene version="3.0.0">
                <integrator type="direct"/>
                <sensor type="perspective"><float name="fov" value="40"/>
                    <sampler type="independent"><integer name="sample_count" value="9"/></sampler>
                    <film type="hdrfilm">
                        <integer name="width" value="8"/><integer name="height" value="6"/>
                        {rfilter}
                    </film>
                </sensor>
                <shape type="sphere"><bsdf type="diffuse"/></shape>
                <emitter type="point"><point name="position" x="0" y="0" z="-4"/></emitter>
            </scene>"#
        );
        parse_scene(&text, Path::new("test.xml"), &[])
            .unwrap()
            .scene
    }

    #[test]
    fn the_files_filter_becomes_the_chapters_filter() {
        let cases = [
            (r#"<rfilter type="box"/>"#, FilterKind::Box, 0.5),
            (
                r#"<rfilter type="tent"><float name="radius" value="1.5"/></rfilter>"#,
                FilterKind::Tent,
                1.5,
            ),
            (
                r#"<rfilter type="gaussian"><float name="stddev" value="0.25"/></rfilter>"#,
                FilterKind::Gaussian,
                1.0,
            ),
            // Mitsuba's default film filter is the Gaussian of standard deviation 1/2.
            ("", FilterKind::Gaussian, 2.0),
        ];
        for (rfilter, kind, radius) in cases {
            let scene = scene_with(rfilter);
            let filter = filter_of(scene.film.filter).unwrap();
            assert_eq!(filter.kind(), kind, "{rfilter}");
            assert_eq!(filter.half_width(), radius, "{rfilter}");
            let notes = crate::lab::CAPABILITIES.check(&scene).unwrap();
            assert!(
                notes.iter().all(|n| !n.contains("filter")),
                "chapter 03 uses the filter, it does not note it away: {notes:?}"
            );
        }
    }

    #[test]
    fn an_unusable_filter_radius_is_refused_naming_the_rfilter() {
        let scene =
            scene_with(r#"<rfilter type="tent"><float name="radius" value="40"/></rfilter>"#);
        let err = filter_of(scene.film.filter).expect_err("radius 40 is refused");
        assert!(err.contains("rfilter") && err.contains("40"), "{err}");
    }
}
