//! The settings a scene carries besides its contents: the film, the sampler, the integrator,
//! and where each part was written in the scene file.

use std::fmt;
use std::path::Path;
use std::sync::Arc;

/// The image the camera records.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilmSettings {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// How a sample is spread over nearby pixels.
    pub filter: FilmFilter,
}

impl FilmSettings {
    /// A `width x height` film that averages each pixel's own samples (a box filter).
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            filter: FilmFilter::Box,
        }
    }
}

/// The reconstruction filter a scene asks for (Mitsuba's `rfilter`); chapter 03 renders it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FilmFilter {
    /// One pixel wide: a pixel is the mean of its own samples.
    Box,
    /// A tent of the given radius in pixels (default 1).
    Tent {
        /// Radius in pixels.
        radius: f32,
    },
    /// A Gaussian of the given standard deviation in pixels (default 0.5).
    Gaussian {
        /// Standard deviation in pixels.
        stddev: f32,
    },
    /// Mitchell and Netravali's cubic of radius 2 pixels with parameters `b` and `c` (Mitsuba's
    /// `mitchell`, `B = C = 1/3` by default; its `catmullrom` is `b = 0`, `c = 1/2`).
    Mitchell {
        /// The cubic's `B`: more blur.
        b: f32,
        /// The cubic's `C`: more ringing.
        c: f32,
    },
}

/// The sampler a scene asks for: any type is recorded; chapter 03 picks its closest.
#[derive(Clone, Debug, PartialEq)]
pub struct SamplerSettings {
    /// Mitsuba's sampler `type`, such as "independent".
    pub type_name: String,
    /// Samples per pixel.
    pub sample_count: u32,
    /// The seed.
    pub seed: u32,
}

impl Default for SamplerSettings {
    /// Mitsuba's defaults: `independent`, 4 samples per pixel, seed 0.
    fn default() -> Self {
        Self {
            type_name: "independent".to_string(),
            sample_count: 4,
            seed: 0,
        }
    }
}

/// The light transport a scene file asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Integrator {
    /// Mitsuba's `path`: unidirectional path tracing.
    Path {
        /// The depth from which Russian roulette may stop a path (Mitsuba's default 5).
        rr_depth: u32,
    },
    /// Mitsuba's `direct`: direct light only, from light samples and BSDF samples at the
    /// surface the camera sees.
    Direct(DirectSamples),
}

/// How many samples of each kind Mitsuba's `direct` integrator takes at every surface the
/// camera sees (its `emitter_samples` and `bsdf_samples`, both 1 by default, not both 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DirectSamples {
    /// Light samples: a light picked and a point on it, each with a shadow ray.
    pub emitter: u32,
    /// BSDF samples: a direction from the surface's BSDF, traced to find a light.
    pub bsdf: u32,
}

impl DirectSamples {
    /// One of each, Mitsuba's default: the path tracer's estimator cut after one bounce.
    pub const ONE_EACH: DirectSamples = DirectSamples {
        emitter: 1,
        bsdf: 1,
    };
}

/// Where the parts of a scene were written in its file, for messages that point at them.
/// Every entry is `None` for a built-in scene; a shape's own is on its
/// [`Surface`](super::Surface).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Origins {
    /// The `<integrator>` element (or `None` when the file has none).
    pub integrator: Option<TextPosition>,
    /// The `<sensor>` element.
    pub sensor: Option<TextPosition>,
    /// The film's `<rfilter>` element (or `None` when Mitsuba's default applies).
    pub filter: Option<TextPosition>,
    /// The `constant` `<emitter>` element, for a scene with an environment.
    pub environment: Option<TextPosition>,
    /// The `envmap` `<emitter>` element, for a scene with an environment map.
    pub environment_map: Option<TextPosition>,
    /// The first `directional` `<emitter>` element, for a scene with directional lights.
    pub directional_light: Option<TextPosition>,
}

/// A place in a scene file: 1-based line and column, as an editor shows them, and the file
/// when it is not the scene file itself but one it includes.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TextPosition {
    /// The line, counted from 1 (0: not known).
    pub line: u32,
    /// The column in characters, counted from 1 (0: not known).
    pub column: u32,
    /// The included file the place is in; `None` in the scene file.
    pub file: Option<Arc<Path>>,
}

impl fmt::Display for TextPosition {
    /// `line 12, column 5` (with `of parts/lights.xml` in an included file), for messages about
    /// an element that has already been read.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}, column {}", self.line, self.column)?;
        match &self.file {
            Some(file) => write!(f, " of {}", file.display()),
            None => Ok(()),
        }
    }
}
