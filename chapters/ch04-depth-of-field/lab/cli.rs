//! The lens options of `render`, shared with the later chapters that keep the lens.
//!
//! Later chapters flatten [`LensArgs`] into their own `render` command, so a lens is asked
//! for the same way everywhere and checked in one place.

use crate::aperture::{Aperture, LensWarp};
use crate::lens::Lens;
use workbench::cli::parse_number;

/// The shapes `--aperture` accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ApertureShape {
    /// A round hole.
    Disc,
    /// A regular polygon, one corner per diaphragm blade (see --blades).
    Polygon,
}

/// Where a pinhole scene focuses when the command line opens an aperture without saying where
/// (`--focus-distance`): about the depth of the later chapters' built-in scenes.
pub const PINHOLE_SCENE_FOCUS: f32 = 5.0;

/// `--aperture-radius` or `--f-number` with `--focal-length`, `--focus-distance`, and the
/// aperture's shape and sampling.
#[derive(clap::Args, Clone, Debug, Default)]
pub struct LensArgs {
    /// Radius of the lens aperture in scene units; 0 is a pinhole
    /// [default: the scene file's, or the built-in scene's].
    #[arg(long, value_name = "R", allow_negative_numbers = true, value_parser = parse_number,
          conflicts_with = "f_number")]
    pub aperture_radius: Option<f32>,
    /// The f-number N: the aperture's diameter is the focal length over N (needs --focal-length).
    #[arg(long, value_name = "N", allow_negative_numbers = true, value_parser = parse_number,
          requires = "focal_length")]
    pub f_number: Option<f32>,
    /// Focal length in scene units, for --f-number (the field of view stays the scene's).
    #[arg(long, value_name = "F", allow_negative_numbers = true, value_parser = parse_number,
          requires = "f_number")]
    pub focal_length: Option<f32>,
    /// Distance of the plane in focus along the viewing axis, in scene units
    /// [default: the scene file's, or the built-in scene's].
    #[arg(long, value_name = "D", allow_negative_numbers = true, value_parser = parse_number)]
    pub focus_distance: Option<f32>,
    /// Shape of the aperture [default: disc, or polygon when --blades is given].
    #[arg(long, value_enum)]
    pub aperture: Option<ApertureShape>,
    /// Blades of a polygonal aperture: its number of corners, 3 to 64 [default: 6].
    #[arg(long, allow_negative_numbers = true, value_parser = parse_blades)]
    pub blades: Option<u32>,
    /// Rotation of a polygonal aperture in degrees.
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true, value_parser = parse_number)]
    pub aperture_rotation: Option<f32>,
    /// How a point of a disc aperture is drawn; `naive` is the wrong one, for comparison.
    #[arg(long, value_enum)]
    pub lens_warp: Option<LensWarp>,
}

impl LensArgs {
    /// The lens these options ask for, starting from the scene's own: the options given
    /// replace its parts, and each is checked with the reason it is refused.
    pub fn lens(&self, scene_lens: Lens) -> anyhow::Result<Lens> {
        let radius = match (self.aperture_radius, self.f_number, self.focal_length) {
            (Some(radius), _, _) => {
                Lens::new(radius, 1.0).map_err(|e| anyhow::anyhow!("--aperture-radius: {e}"))?;
                radius
            }
            (None, Some(n), Some(f)) => {
                Lens::from_f_number(f, n, 1.0)
                    .map_err(|e| anyhow::anyhow!("--f-number and --focal-length: {e}"))?
                    .aperture_radius
            }
            _ => scene_lens.aperture_radius,
        };
        let focus = self.focus_distance.unwrap_or(scene_lens.focus_distance);
        let mut lens =
            Lens::new(radius, focus).map_err(|e| anyhow::anyhow!("--focus-distance: {e}"))?;
        let shape = self.aperture.unwrap_or(if self.blades.is_some() {
            ApertureShape::Polygon
        } else {
            ApertureShape::Disc
        });
        match shape {
            ApertureShape::Disc => {
                if self.blades.is_some() || self.aperture_rotation.is_some() {
                    anyhow::bail!(
                        "--blades and --aperture-rotation shape a polygonal aperture; they need --aperture polygon, not disc"
                    );
                }
                lens = lens.with_aperture(Aperture::Disc);
            }
            ApertureShape::Polygon => {
                if self.lens_warp.is_some() {
                    anyhow::bail!(
                        "--lens-warp chooses how a disc is sampled; a polygonal aperture is always sampled uniformly by its triangles"
                    );
                }
                let degrees = self.aperture_rotation.unwrap_or(0.0);
                let aperture = Aperture::polygon(self.blades.unwrap_or(6), degrees.to_radians())
                    .map_err(|e| anyhow::anyhow!("--aperture-rotation: {e}"))?;
                lens = lens.with_aperture(aperture);
            }
        }
        if let Some(warp) = self.lens_warp {
            lens = lens.with_warp(warp);
        }
        Ok(lens)
    }

    /// [`lens`](Self::lens) for the later chapters, whose scenes often have no lens: a
    /// pinhole scene given an aperture on the command line focuses
    /// [`PINHOLE_SCENE_FOCUS`] away unless `--focus-distance` says otherwise.
    pub fn lens_or_pinhole(&self, scene_lens: Lens) -> anyhow::Result<Lens> {
        let scene_lens = if scene_lens.is_pinhole() {
            Lens {
                focus_distance: PINHOLE_SCENE_FOCUS,
                ..scene_lens
            }
        } else {
            scene_lens
        };
        self.lens(scene_lens)
    }
}

fn parse_blades(text: &str) -> Result<u32, String> {
    let blades: i64 = text
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a whole number of blades"))?;
    let max = crate::aperture::MAX_BLADES;
    if (3..=i64::from(max)).contains(&blades) {
        Ok(blades as u32)
    } else {
        Err(format!(
            "an aperture polygon needs between 3 and {max} blades, not {blades}"
        ))
    }
}
