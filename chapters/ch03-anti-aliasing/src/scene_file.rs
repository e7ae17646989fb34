//! What a scene file says about anti-aliasing: its `<rfilter>` and its `<sampler>`.
//!
//! Chapter 01 renders everything Whitted's method can and averages each pixel's own samples.
//! This chapter renders the same scenes but honours the film's filter, and picks the pixel
//! sampler closest to the file's.

use crate::filters::{FilterKind, ReconstructionFilter};
use crate::pixel_samplers::PixelSamplerKind;

use common::scene::FilmFilter;

/// The chapter's pixel sampler for a Mitsuba `<sampler>` type, and a note when it is only the
/// closest one: Mitsuba's `independent` is our random sampler and its `stratified` our
/// stratified one; its `multijitter` and `orthogonal` are refinements of stratification, and
/// its `ldsampler` a low-discrepancy sequence like our Halton points.
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
        "multijitter" | "orthogonal" => closest(PixelSamplerKind::Stratified),
        "ldsampler" => closest(PixelSamplerKind::Halton),
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
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use common::scene::Scene;
    use common::scene_file::parse_scene;
    use std::path::Path;

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
            let notes = crate::CAPABILITIES.check(&scene).unwrap();
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
