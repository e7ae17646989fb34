//! Where a light whose radiance is a texture is bright: a density over its surface parameters
//! for its light samples, worked out once per scene, when it is built.
//!
//! Picking a point of such a light by area alone wastes most samples on its dark parts: on a
//! panel with a few bright spots, nearly all the light comes from a tenth of it. Mitsuba 3
//! picks the point by the texture instead (a bitmap by its brightness). The workbook does the
//! same on parallelograms, the shape of panels, windows and screens, whose `uv` are uniform by
//! area: over a grid of [`EMISSION_GRID`]² cells of `uv`, each cell weighs as the brightest of
//! its corners and its centre, and a share [`UNIFORM_SHARE`] of the samples stays uniform, so
//! that every point that glows can be chosen (a bright detail smaller than a cell included)
//! and the estimate stays unbiased. Other shapes keep their own sampling (by area, or by solid
//! angle on a sphere).

use super::environment_sampling::luminance;
use super::grid_distribution::GridDistribution;
use super::{AreaEmitter, Scene};
use crate::geometry::Shape;
use glam::Vec2;

/// Cells of the grid along each side of the `uv` square.
pub const EMISSION_GRID: usize = 128;

/// The share of a textured light's samples spread uniformly over it.
pub const UNIFORM_SHARE: f32 = 0.03;

impl Scene {
    /// The density over `[0, 1]²` of `uv` with which shape number `shape` is sampled as a
    /// light: `Some` for a still parallelogram whose emitter's radiance is a texture with some
    /// light in it, `None` for every other shape (sampled as its shape says).
    pub fn emission_grid(&self, shape: u32) -> Option<&GridDistribution> {
        // Most lights have no texture: they are answered without a search.
        self.surface(shape).emitter?.texture?;
        self.emission_grids
            .iter()
            .find(|(textured, _)| *textured == shape)
            .map(|(_, grid)| grid)
    }

    /// Works out the density of every textured light ([`emission_grid`](Self::emission_grid)).
    ///
    /// [`SceneBuilder::build`](super::SceneBuilder::build) calls it, so a scene is ready to
    /// sample when it is made and a render never builds a table behind the renderer's back;
    /// code that gives a built scene's surfaces other emitters calls it again.
    pub fn prepare_emission_grids(&mut self) {
        self.emission_grids = (0..self.shape_count() as u32)
            .filter_map(|shape| Some((shape, self.build_emission_grid(shape)?)))
            .collect();
    }

    fn build_emission_grid(&self, shape: u32) -> Option<GridDistribution> {
        let Some(Shape::Parallelogram(_)) = self.geometry.shapes().get(shape as usize) else {
            return None;
        };
        let Some(AreaEmitter {
            radiance,
            texture: Some(texture),
            ..
        }) = self.surface(shape).emitter
        else {
            return None;
        };
        let n = EMISSION_GRID;
        let brightness =
            |u: f32, v: f32| luminance(radiance * self.albedo(texture, Vec2::new(u, v))).abs();
        let corners: Vec<f32> = (0..=n)
            .flat_map(|j| (0..=n).map(move |i| (i, j)))
            .map(|(i, j)| brightness(i as f32 / n as f32, j as f32 / n as f32))
            .collect();
        let mut weights = Vec::with_capacity(n * n);
        for j in 0..n {
            for i in 0..n {
                let centre = brightness((i as f32 + 0.5) / n as f32, (j as f32 + 0.5) / n as f32);
                let corner = |di: usize, dj: usize| corners[(j + dj) * (n + 1) + i + di];
                let brightest = [corner(0, 0), corner(1, 0), corner(0, 1), corner(1, 1)]
                    .into_iter()
                    .fold(centre, f32::max);
                weights.push(brightest);
            }
        }
        let total: f32 = weights.iter().sum();
        if !(total > 0.0 && total.is_finite()) {
            return None;
        }
        let uniform = UNIFORM_SHARE * total / (n * n) as f32;
        for w in &mut weights {
            *w = (1.0 - UNIFORM_SHARE) * *w + uniform;
        }
        GridDistribution::new(n, n, &weights)
    }
}
