//! The path tracer's options of `render`: `--no-nee`, `--mis`, `--rr-depth`.

use crate::mis::MisHeuristic;
use crate::options::PathOptions;

/// How paths are traced.
#[derive(clap::Args, Clone, Debug)]
pub struct PathArgs {
    /// Switch next-event estimation off: light is found only by paths that hit it (point
    /// lights, which no path can hit, then go dark).
    #[arg(long)]
    pub no_nee: bool,
    /// How light samples and BSDF samples are combined. Without next-event estimation there
    /// are no light samples to combine, so it cannot be given with `--no-nee`.
    #[arg(long, value_enum, default_value_t = MisHeuristic::Power, conflicts_with = "no_nee")]
    pub mis: MisHeuristic,
    /// The segment from which Russian roulette may end a path, or `off`
    /// [default: the scene file's, or 5].
    #[arg(long, value_name = "N|off", value_parser = parse_rr_depth, allow_hyphen_values = true)]
    pub rr_depth: Option<RrDepth>,
}

/// `--rr-depth`: a depth, or off.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RrDepth(pub Option<u32>);

/// A depth from 1 to 1000, or `off`.
pub fn parse_rr_depth(text: &str) -> Result<RrDepth, String> {
    if text.trim() == "off" {
        return Ok(RrDepth(None));
    }
    match text.trim().parse::<u32>() {
        Ok(depth) if (1..=1000).contains(&depth) => Ok(RrDepth(Some(depth))),
        _ => Err(format!(
            "`{text}` is neither a depth from 1 to 1000 nor `off`"
        )),
    }
}

impl PathArgs {
    /// `file` (the scene's options) with these arguments applied.
    pub fn options(&self, file: PathOptions) -> PathOptions {
        PathOptions {
            nee: !self.no_nee,
            mis: self.mis,
            rr_depth: self.rr_depth.map_or(file.rr_depth, |d| d.0),
            ..file
        }
    }
}
