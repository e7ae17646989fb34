//! What the path tracer does at each bounce: the switches that the chapter compares.

use crate::mis::MisHeuristic;
use common::scene::DirectSamples;

/// The path tracer's choices, Mitsuba 3's `path` integrator's by default.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PathOptions {
    /// Next-event estimation: at every non-delta surface, one shadow ray to one light picked
    /// uniformly. Off, light is found only by paths that happen to hit it, and point lights,
    /// which no path can hit, are lost.
    pub nee: bool,
    /// How a light sample and a BSDF sample that can both find the same light share it.
    /// Only matters with `nee`.
    pub mis: MisHeuristic,
    /// The segment number from which Russian roulette may end a path; `None` switches it off.
    pub rr_depth: Option<u32>,
    /// The longest path in segments, counting the camera ray (Mitsuba's `max_depth`): 1 sees
    /// only what glows, 2 adds direct light, each further step one bounce more.
    pub max_depth: u32,
    /// Mitsuba's `hide_emitters`: the camera ray passes through shapes that emit and its own
    /// segment finds no emission (no light source, no environment); light still reaches
    /// what it sees.
    pub hide_emitters: bool,
    /// Mitsuba's `direct` integrator with sample counts other than one of each, which
    /// [`PathTracer::direct`](crate::PathTracer::direct) renders; `None` for the path (and
    /// for `direct` with one of each, which is the path cut after one bounce).
    pub direct: Option<DirectSamples>,
}

/// Mitsuba's default `rr_depth`.
pub const MITSUBA_RR_DEPTH: u32 = 5;

impl Default for PathOptions {
    /// Mitsuba 3's `path`: NEE, the power heuristic, roulette from segment 5, depth 12.
    fn default() -> Self {
        Self {
            nee: true,
            mis: MisHeuristic::Power,
            rr_depth: Some(MITSUBA_RR_DEPTH),
            max_depth: 12,
            hide_emitters: false,
            direct: None,
        }
    }
}

impl PathOptions {
    /// The defaults with `max_depth` segments.
    pub fn with_depth(max_depth: u32) -> Self {
        Self {
            max_depth,
            ..Self::default()
        }
    }
}
