//! The command-line options of this chapter that every later chapter's `render` keeps: which
//! pixel sampler places the samples and which filter reconstructs the pixels.
//!
//! Later chapters flatten [`AntiAliasingArgs`] into their own `render` command, so the options
//! mean the same everywhere and are checked in one place.

use crate::filters::{FilterKind, ReconstructionFilter, check_radius};
use crate::lab::scene_file::FilmSide;
use crate::pixel_samplers::{PixelSampler, PixelSamplerKind};
use common::render::Budget;

/// The film side of a render, settled from the command line and the scene file.
#[derive(Clone, Debug)]
pub struct FilmSetup {
    /// The reconstruction filter.
    pub filter: ReconstructionFilter,
    /// The pixel sampler's kind.
    pub sampler_kind: PixelSamplerKind,
    /// The pixel sampler itself.
    pub pixel_sampler: PixelSampler,
}

impl FilmSetup {
    /// Adds the film side to a render's statistics (a JSON object).
    pub fn record_stats(&self, stats: &mut serde_json::Value) {
        stats["sampler"] = self.sampler_kind.name().into();
        stats["filter"] = self.filter.kind().name().into();
        stats["filter_radius"] = self.filter.half_width().into();
    }
}

/// `--sampler`, `--filter` and `--filter-radius`.
#[derive(clap::Args, Clone, Debug, Default)]
pub struct AntiAliasingArgs {
    /// Where the samples of a pixel go [default: the closest to the scene file's sampler, or
    /// stratified].
    #[arg(long, value_enum)]
    pub sampler: Option<PixelSamplerKind>,
    /// How samples are weighted into pixels [default: the scene file's rfilter, or box].
    #[arg(long, value_enum)]
    pub filter: Option<FilterKind>,
    /// Half-width of the filter in pixels, in (0, 16] [default: the filter's own; for the
    /// Gaussian, four standard deviations].
    #[arg(long, value_name = "PIXELS", value_parser = parse_radius, allow_hyphen_values = true)]
    pub filter_radius: Option<f32>,
}

impl AntiAliasingArgs {
    /// The film side of a render of `budget` and `seed`: the filter and the pixel sampler (the
    /// flags, else the scene file's `film`, else the box and stratified).
    pub fn film_setup(
        &self,
        film: Option<&FilmSide>,
        budget: &Budget,
        seed: u64,
    ) -> anyhow::Result<FilmSetup> {
        let filter = self.filter(film.map(|film| film.filter))?;
        let sampler_kind = self.sampler_kind(film.map(|film| film.sampler));
        let pixel_sampler = self.pixel_sampler(sampler_kind, budget, seed)?;
        Ok(FilmSetup {
            filter,
            sampler_kind,
            pixel_sampler,
        })
    }

    /// The sampler asked for: the flag, else the scene file's, else stratified.
    pub fn sampler_kind(&self, from_file: Option<PixelSamplerKind>) -> PixelSamplerKind {
        self.sampler
            .or(from_file)
            .unwrap_or(PixelSamplerKind::Stratified)
    }

    /// The pixel sampler for a render with `budget`. A stratified sampler lays out its strata
    /// for a known sample count, so it refuses a time budget.
    pub fn pixel_sampler(
        &self,
        kind: PixelSamplerKind,
        budget: &Budget,
        seed: u64,
    ) -> anyhow::Result<PixelSampler> {
        let spp = match *budget {
            Budget::Samples(spp) => spp,
            Budget::Seconds(_) if kind.needs_sample_count() => anyhow::bail!(
                "--sampler {} lays out a fixed number of strata, so it needs --spp, not --time (random, halton and sobol work with --time)",
                kind.name()
            ),
            // The other samplers do not need to know the count in advance.
            Budget::Seconds(_) => 1,
        };
        PixelSampler::new(kind, spp, seed)
            .map_err(|e| anyhow::anyhow!("--sampler {}: {e}", kind.name()))
    }

    /// The filter asked for: the flag, else the scene file's, else the box; `--filter-radius`
    /// resizes whichever it is.
    pub fn filter(
        &self,
        from_file: Option<ReconstructionFilter>,
    ) -> anyhow::Result<ReconstructionFilter> {
        match (self.filter, from_file) {
            (Some(kind), _) => ReconstructionFilter::new(kind, self.filter_radius),
            (None, Some(from_file)) => match self.filter_radius {
                Some(radius) => ReconstructionFilter::new(from_file.kind(), Some(radius)),
                None => Ok(from_file),
            },
            (None, None) => ReconstructionFilter::new(FilterKind::Box, self.filter_radius),
        }
        .map_err(|e| anyhow::anyhow!("--filter-radius: {e}"))
    }
}

/// Reads `--filter-radius`, refusing what no filter accepts with the reason.
fn parse_radius(text: &str) -> Result<f32, String> {
    let radius: f32 = text
        .parse()
        .map_err(|_| format!("`{text}` is not a number of pixels"))?;
    check_radius(radius)?;
    Ok(radius)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flags_win_over_the_file_and_the_file_over_the_defaults() {
        let none = AntiAliasingArgs::default();
        assert_eq!(none.sampler_kind(None), PixelSamplerKind::Stratified);
        assert_eq!(
            none.sampler_kind(Some(PixelSamplerKind::Random)),
            PixelSamplerKind::Random
        );
        let halton = AntiAliasingArgs {
            sampler: Some(PixelSamplerKind::Halton),
            ..Default::default()
        };
        assert_eq!(
            halton.sampler_kind(Some(PixelSamplerKind::Random)),
            PixelSamplerKind::Halton
        );

        let tent = ReconstructionFilter::new(FilterKind::Tent, Some(1.5)).unwrap();
        assert_eq!(none.filter(None).unwrap().kind(), FilterKind::Box);
        assert_eq!(none.filter(Some(tent)).unwrap(), tent);
        let wider = AntiAliasingArgs {
            filter_radius: Some(3.0),
            ..Default::default()
        };
        let resized = wider.filter(Some(tent)).unwrap();
        assert_eq!(
            (resized.kind(), resized.half_width()),
            (FilterKind::Tent, 3.0)
        );
    }

    #[test]
    fn a_stratified_sampler_needs_a_sample_count() {
        let args = AntiAliasingArgs::default();
        let timed = Budget::Seconds(1.0);
        let error = args
            .pixel_sampler(PixelSamplerKind::Stratified, &timed, 0)
            .unwrap_err();
        assert!(error.to_string().contains("needs --spp"), "{error}");
        assert!(
            args.pixel_sampler(PixelSamplerKind::Random, &timed, 0)
                .is_ok()
        );
        assert!(parse_radius("0").is_err() && parse_radius("abc").is_err());
        assert_eq!(parse_radius("2.5"), Ok(2.5));
    }
}
