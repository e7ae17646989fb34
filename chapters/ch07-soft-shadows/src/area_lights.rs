//! Area lights: shapes of finite size that glow.
//!
//! An area light is one of `common`'s shapes with a radiance `L` (per colour channel, in
//! W m⁻² sr⁻¹): every point of its surface sends `L` in every direction of its front
//! hemisphere. This is Mitsuba 3's `area` emitter, and its conventions are kept so that scenes
//! can be compared with Mitsuba:
//!
//! - a planar light (parallelogram, triangle, disc) emits only on the side its geometric
//!   normal points to; seen from behind it is black. A lamp is usually a panel against a
//!   ceiling, and a two-sided panel would light the ceiling as brightly as the room;
//! - a sphere emits outwards, its normal being the outward one.
//!
//! A Lambertian emitter sends `L cos θ` per unit area and solid angle, and `∫ cos θ dω = π`
//! over the hemisphere, so its power is `Φ = π L A`. Holding `Φ` (or `L A`) fixed while the
//! area shrinks leads to a point light: [`crate::estimator`]'s tests check that limit.
//!
//! A scene's lights are found among its shapes ([`AreaLights::of`]), and a light's geometry
//! is not stored twice. The scene marks which shapes glow (a
//! [`Surface`](common::scene::Surface)'s emitter), and a light's shape is read from the
//! scene's own geometry, so the surface the camera sees and the surface the shadow rays aim
//! at cannot disagree.

use std::f32::consts::PI;
use std::ops::Range;

use common::geometry::{Disc, Parallelogram, Shape, Sphere, Triangle};
use common::scene::Scene;
use glam::Vec3;

/// The shape of an area light: one of `common`'s shapes that has a surface to sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightShape {
    /// A parallelogram `corner + u e1 + v e2`, emitting towards `e1 × e2`.
    Parallelogram(Parallelogram),
    /// A triangle, emitting towards `(p1 - p0) × (p2 - p0)` (counter-clockwise from the front).
    Triangle(Triangle),
    /// A disc, emitting towards its normal.
    Disc(Disc),
    /// A sphere, emitting outwards.
    Sphere(Sphere),
}

impl LightShape {
    /// The surface area, and 0 for a shape that has none: parallel edges, a zero or negative
    /// radius, non-finite vertices. A light of zero area is allowed and simply emits nothing.
    pub fn area(&self) -> f32 {
        let area = match self {
            LightShape::Parallelogram(q) => q.area(),
            LightShape::Triangle(t) => t.area(),
            LightShape::Disc(d) if d.radii().min_element() > 0.0 && d.normal() != Vec3::ZERO => {
                d.area()
            }
            LightShape::Sphere(s) if s.radius > 0.0 => s.area(),
            LightShape::Disc(_) | LightShape::Sphere(_) => 0.0,
        };
        if area.is_finite() && area > 0.0 {
            area
        } else {
            0.0
        }
    }
}

impl From<Parallelogram> for LightShape {
    fn from(q: Parallelogram) -> Self {
        LightShape::Parallelogram(q)
    }
}

impl From<Triangle> for LightShape {
    fn from(t: Triangle) -> Self {
        LightShape::Triangle(t)
    }
}

impl From<Disc> for LightShape {
    fn from(d: Disc) -> Self {
        LightShape::Disc(d)
    }
}

impl From<Sphere> for LightShape {
    fn from(s: Sphere) -> Self {
        LightShape::Sphere(s)
    }
}

/// A shape that emits the radiance `radiance` from every point of its front side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaLight {
    /// Where the light is.
    pub shape: LightShape,
    /// The radiance `L` of its front side, per colour channel.
    pub radiance: Vec3,
}

impl AreaLight {
    /// The light of `shape` with front-side radiance `radiance`.
    pub fn new(shape: impl Into<LightShape>, radiance: Vec3) -> Self {
        Self {
            shape: shape.into(),
            radiance,
        }
    }

    /// The radiance leaving a point of the light whose geometric normal is `n`, towards a
    /// viewer in the direction `towards_viewer` (from the light to the viewer, any length):
    /// `L` on the front side, 0 behind and exactly edge-on.
    pub fn emitted(&self, n: Vec3, towards_viewer: Vec3) -> Vec3 {
        if n.dot(towards_viewer) > 0.0 {
            self.radiance
        } else {
            Vec3::ZERO
        }
    }

    /// The surface area of the light (0 for a degenerate shape).
    pub fn area(&self) -> f32 {
        self.shape.area()
    }

    /// The total power `Φ = π L A` the light sends out: radiance `L` over the area `A` and the
    /// front hemisphere, where `∫ cos θ dω = π`.
    pub fn power(&self) -> Vec3 {
        self.radiance * (PI * self.area())
    }
}

/// The area lights of a scene, and which shape each one is.
#[derive(Clone, Debug, Default)]
pub struct AreaLights {
    /// The area lights, in the order of their shapes.
    pub lights: Vec<AreaLight>,
    /// For every shape of the scene, the index of the light it is, if any.
    pub light_of_shape: Vec<Option<u32>>,
    /// For every light, the number of its shape: where its emitter (and a texture on its
    /// radiance, which chapter 08 reads) is found in the scene.
    pub shape_of_light: Vec<u32>,
    /// The lights grouped by the shape of the scene they are pieces of (the shapes that share
    /// one surface, such as a mesh's triangles or a cube's faces): Mitsuba 3's emitters, each
    /// the range of its lights in [`lights`](Self::lights). Chapter 08 picks a light sample's
    /// emitter among these, then the piece by its area, as Mitsuba does.
    pub emitters: Vec<Range<usize>>,
    /// For every light, the share of its emitter's area covered by the pieces up to and
    /// including it: 1 for an emitter's last piece (and for a light in one piece).
    pub area_cdf: Vec<f32>,
    /// For every light, its share of its emitter's area: the chance that a pick by area among
    /// the emitter's pieces chooses it.
    pub area_share: Vec<f32>,
    /// For every emitter, the sum of the sampling weights (Mitsuba 3's `sampling_weight`,
    /// usually 1: how often chapter 08 picks an emitter, relative to the others) of the
    /// emitters up to and including it.
    pub emitter_weight_sum: Vec<f32>,
    /// For every light, the sampling weight of its emitter.
    pub weight_of_light: Vec<f32>,
}

/// The light shape of a world shape: every shape of `common` has a surface to sample.
pub fn light_shape(shape: &Shape) -> LightShape {
    match *shape {
        Shape::Sphere(s) => LightShape::Sphere(s),
        Shape::Triangle(t) => LightShape::Triangle(t),
        Shape::Parallelogram(q) => LightShape::Parallelogram(q),
        Shape::Disc(d) => LightShape::Disc(d),
    }
}

impl AreaLights {
    /// The lights of `scene`: every still shape that glows. (A glowing shape that moves is
    /// refused by every chapter's capability check before it gets here.)
    pub fn of(scene: &Scene) -> Self {
        let mut light_of_shape = vec![None; scene.shape_count()];
        let mut lights = Vec::new();
        let mut shape_of_light = Vec::new();
        for (index, shape) in scene.geometry.shapes().iter().enumerate() {
            if let Some(emitter) = scene.surface(index as u32).emitter {
                light_of_shape[index] = Some(lights.len() as u32);
                shape_of_light.push(index as u32);
                lights.push(AreaLight::new(light_shape(shape), emitter.radiance));
            }
        }
        let emitters = emitters_of(scene, &shape_of_light);
        let weight = |light: usize| {
            let emitter = scene.surface(shape_of_light[light]).emitter;
            emitter.map_or(1.0, |e| e.sampling_weight)
        };
        let emitter_weight_sum = emitters
            .iter()
            .scan(0.0, |sum, e| {
                *sum += weight(e.start);
                Some(*sum)
            })
            .collect();
        let weight_of_light = (0..lights.len()).map(weight).collect();
        let (mut area_share, mut area_cdf) = (Vec::new(), Vec::new());
        for emitter in &emitters {
            for (share, cdf) in area_shares(&lights[emitter.clone()]) {
                area_share.push(share);
                area_cdf.push(cdf);
            }
        }
        Self {
            lights,
            light_of_shape,
            shape_of_light,
            emitters,
            area_cdf,
            area_share,
            emitter_weight_sum,
            weight_of_light,
        }
    }
}

/// The runs of consecutive lights whose shapes share one surface of `scene`: the pieces of one
/// shape of a scene file (a scene builds each shape's pieces one after another).
fn emitters_of(scene: &Scene, shape_of_light: &[u32]) -> Vec<Range<usize>> {
    let surface = |light: usize| scene.surface_of_shape[shape_of_light[light] as usize];
    let mut emitters: Vec<Range<usize>> = Vec::new();
    for light in 0..shape_of_light.len() {
        match emitters.last_mut() {
            Some(run) if surface(run.start) == surface(light) => run.end = light + 1,
            _ => emitters.push(light..light + 1),
        }
    }
    emitters
}

/// Each of `pieces`' share of their total area, and the running sum of the shares up to and
/// including it, which ends at exactly 1; pieces of no area at all share evenly.
fn area_shares(pieces: &[AreaLight]) -> Vec<(f32, f32)> {
    let areas: Vec<f64> = pieces.iter().map(|p| f64::from(p.area())).collect();
    let total: f64 = areas.iter().sum();
    let even = 1.0 / pieces.len() as f64;
    let mut running = 0.0;
    let mut shares: Vec<(f32, f32)> = areas
        .iter()
        .map(|area| {
            let share = if total > 0.0 { area / total } else { even };
            running += share;
            (share as f32, running as f32)
        })
        .collect();
    if let Some(last) = shares.last_mut() {
        last.1 = 1.0;
    }
    shares
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn planar_lights_shine_on_their_front_side_only() {
        let light = AreaLight::new(Parallelogram::new(Vec3::ZERO, Vec3::X, Vec3::Z), Vec3::ONE);
        // X × Z = -Y: the parallelogram faces down.
        assert_eq!(
            light.emitted(-Vec3::Y, Vec3::new(0.3, -1.0, 0.2)),
            Vec3::ONE
        );
        assert_eq!(
            light.emitted(-Vec3::Y, Vec3::new(0.3, 1.0, 0.2)),
            Vec3::ZERO
        );
        assert_eq!(light.emitted(-Vec3::Y, Vec3::X), Vec3::ZERO);
    }

    #[test]
    fn power_is_pi_radiance_area() {
        let light = AreaLight::new(Sphere::new(Vec3::ZERO, 2.0), Vec3::new(1.0, 2.0, 3.0));
        assert_relative_eq!(light.power(), Vec3::new(1.0, 2.0, 3.0) * 16.0 * PI * PI);
        let disc = AreaLight::new(Disc::new(Vec3::ZERO, Vec3::Y, 1.0), Vec3::ONE);
        assert_relative_eq!(disc.power(), Vec3::splat(PI * PI));
    }

    #[test]
    fn degenerate_shapes_have_no_area() {
        let shapes: [LightShape; 6] = [
            Parallelogram::new(Vec3::ZERO, Vec3::X, 2.0 * Vec3::X).into(),
            Triangle::new(Vec3::ZERO, Vec3::X, Vec3::X).into(),
            Triangle::new(Vec3::ZERO, Vec3::X, Vec3::NAN).into(),
            Disc::new(Vec3::ZERO, Vec3::Y, 0.0).into(),
            Disc::new(Vec3::ZERO, Vec3::Y, -1.0).into(),
            Sphere::new(Vec3::ZERO, 0.0).into(),
        ];
        for shape in shapes {
            assert_eq!(shape.area(), 0.0, "{shape:?}");
            assert_eq!(AreaLight::new(shape, Vec3::ONE).power(), Vec3::ZERO);
        }
    }
}
