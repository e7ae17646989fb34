//! How a light is sampled: by area or, for a sphere, by the cone of directions it subtends,
//! and with which disc warp; and the one function that picks the sampler for a light.
//!
//! It sits above the samplers it chooses between ([`crate::area_sampling`],
//! [`crate::solid_angle`]), which know nothing of the choice.

use glam::{Vec2, Vec3};

use crate::area_lights::{AreaLight, LightShape};
use crate::disc_warp::DiscWarp;
use crate::light_sample::LightSample;
use crate::solid_angle::sample_sphere_solid_angle;

/// How points are chosen on a sphere light.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum Strategy {
    /// Uniformly over the light's whole surface. Simple, and for a sphere wasteful: the half
    /// facing away from the receiver gets half the samples and contributes nothing.
    Area,
    /// Uniformly over the cone of directions the sphere subtends from the receiver: every
    /// sample lands on the visible side. Applies to spheres; planar lights, which have no
    /// simple solid-angle sampler here, are sampled by area. A receiver on or inside the
    /// sphere sees no cone and falls back to area sampling too.
    #[default]
    SolidAngle,
}

/// Everything that decides how a light is sampled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LightSampling {
    /// By area or by solid angle (spheres only).
    pub strategy: Strategy,
    /// The warp that puts points on disc lights.
    pub disc_warp: DiscWarp,
}

impl LightSampling {
    /// Uniform by area everywhere, discs by `disc_warp`.
    pub fn area(disc_warp: DiscWarp) -> Self {
        Self {
            strategy: Strategy::Area,
            disc_warp,
        }
    }

    /// Spheres by solid angle, everything else by area with the concentric disc.
    pub fn solid_angle() -> Self {
        Self {
            strategy: Strategy::SolidAngle,
            disc_warp: DiscWarp::Concentric,
        }
    }
}

impl Strategy {
    /// Both strategies, by area first.
    pub const ALL: [Strategy; 2] = [Strategy::Area, Strategy::SolidAngle];

    /// The name used on the command line and in figures.
    pub fn name(self) -> &'static str {
        match self {
            Strategy::Area => "area",
            Strategy::SolidAngle => "solid-angle",
        }
    }
}

impl AreaLight {
    /// A point of the light for the receiver at `x`, from the uniform `u` in `[0, 1)^2`, chosen
    /// as `sampling` says: a sphere by solid angle (its cone seen from `x`) or by area,
    /// everything else by area (discs with `sampling.disc_warp`). `None` when the light has no
    /// area, or subtends too small a cone to describe in `f32`.
    pub fn sample(&self, x: Vec3, u: Vec2, sampling: LightSampling) -> Option<LightSample> {
        let sample = match (self.shape, sampling.strategy) {
            (LightShape::Sphere(sphere), Strategy::SolidAngle) => {
                sample_sphere_solid_angle(&sphere, x, u)
            }
            (shape, _) => shape.sample_area(u, sampling.disc_warp),
        }?;
        // The samplers put the outward normal on a sphere; a flipped sphere's front faces in.
        Some(match self.shape {
            LightShape::Sphere(sphere) => LightSample {
                n: sphere.oriented(sample.n),
                ..sample
            },
            _ => sample,
        })
    }
}
