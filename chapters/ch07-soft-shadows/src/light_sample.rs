//! A point chosen on a light, with the density it was chosen with and the shadow ray to it.
//!
//! A Monte Carlo estimator divides by the density of what it sampled, so a sampled point is
//! worthless without its density. Two measures appear in this chapter: points chosen
//! *uniformly by area* have a density per unit area of the light, `1 / A`; points chosen by
//! *direction* (a sphere's cone, [`crate::solid_angle`]) have a density per unit solid angle
//! seen from the receiver. A [`LightSample`] always carries the first and, when it was chosen
//! by direction, the second too, so the estimator can use the one it was drawn with.
//!
//! A shadow ray joins two surfaces, the receiver and the light, and both ends are computed
//! points that lie a little off their surfaces. [`LightSample::shadow_ray`] offsets *both*
//! ends by their floating-point error bounds, as `common`'s `SurfaceHit::spawn_ray_to_hit`
//! does, so the ray neither hits the receiver it leaves nor the light it aims at, at any
//! scene scale, with no epsilon that depends on the scene's size.

use common::Ray;
use common::geometry::SurfaceHit;
use glam::{Vec2, Vec3};

/// A point on a light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// The point.
    pub p: Vec3,
    /// A conservative bound, per axis, on how far `p` is from the exact surface point.
    pub p_error: Vec3,
    /// The light's unit geometric normal at `p` (its front side; outward for a sphere).
    pub n: Vec3,
    /// The density with which `p` was chosen, per unit area of the light.
    pub pdf: f32,
    /// The density per unit solid angle, seen from the receiver, when the point was chosen by
    /// its direction (a sphere's cone); `None` when it was chosen by area.
    pub pdf_solid_angle: Option<f32>,
}

impl LightSample {
    /// A point chosen by area with density `pdf` per unit area, or `None` when the density is
    /// not a positive finite number: a light of zero area has no point to offer.
    pub fn by_area(p: Vec3, p_error: Vec3, n: Vec3, pdf: f32) -> Option<Self> {
        let valid = pdf.is_finite() && pdf > 0.0 && p.is_finite();
        valid.then_some(Self {
            p,
            p_error,
            n,
            pdf,
            pdf_solid_angle: None,
        })
    }

    /// The point as a `SurfaceHit` of the light, for `common`'s ray spawning (its `t`, `uv`
    /// and `shape` mean nothing here and are 0).
    pub fn surface_hit(&self) -> SurfaceHit {
        SurfaceHit {
            t: 0.0,
            p: self.p,
            p_error: self.p_error,
            n: self.n,
            shading_n: self.n,
            uv: Vec2::ZERO,
            shape: 0,
        }
    }

    /// The shadow ray from `receiver` to this point at shutter time `time`: both ends offset
    /// off their surfaces, `dir` not normalised, so the light point is at `t ≈ 1` and the ray
    /// stops at `t_max = 1 - SHADOW_EPSILON`. Any hit with `t < t_max` is a blocker.
    pub fn shadow_ray(&self, receiver: &SurfaceHit, time: f32) -> Ray {
        receiver.spawn_ray_to_hit(&self.surface_hit(), time)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::area_lights::{AreaLight, LightShape};
    use crate::disc_warp::DiscWarp;
    use crate::strategy::LightSampling;
    use crate::test_support::uniform_points;
    use common::geometry::{Disc, Parallelogram, Shape, Sphere};

    /// The floor `y = 0` as a shape and a receiver hit on it at `(x, 0, z)`, found by a ray.
    fn floor_hit(scale: f32, offset: Vec3, at: Vec2) -> (Shape, SurfaceHit) {
        let floor = Parallelogram::new(
            offset + scale * Vec3::new(-5.0, 0.0, -5.0),
            scale * 10.0 * Vec3::Z,
            scale * 10.0 * Vec3::X,
        );
        let target = offset + scale * Vec3::new(at.x, 0.0, at.y);
        let origin = target + scale * Vec3::new(0.3, 2.0, 0.1);
        let hit = floor
            .intersect(&Ray::new(origin, target - origin))
            .expect("the ray hits the floor");
        (floor.into(), hit)
    }

    #[test]
    fn shadow_rays_hit_neither_the_light_nor_the_receiver_at_any_scale() {
        for scale in [1e-4f32, 1.0, 1e5] {
            let offset = scale * Vec3::new(3.0, -2.0, 7.0);
            let lights: [(Shape, LightShape); 3] = [
                {
                    // A ceiling panel facing down, and a panel standing on the floor.
                    let q = Parallelogram::new(
                        offset + scale * Vec3::new(-0.5, 1.0, -0.5),
                        scale * Vec3::X,
                        scale * Vec3::Z,
                    );
                    (q.into(), q.into())
                },
                {
                    let d = Disc::new(
                        offset + scale * Vec3::new(0.0, 0.5, -1.0),
                        Vec3::new(0.0, 0.0, 1.0),
                        0.5 * scale,
                    );
                    (d.into(), d.into())
                },
                {
                    let s = Sphere::new(offset + scale * Vec3::new(0.5, 0.6, 0.2), 0.5 * scale);
                    (s.into(), s.into())
                },
            ];
            for (shape, light_shape) in lights {
                let light = AreaLight::new(light_shape, Vec3::ONE);
                for (i, u) in uniform_points(200, 1).into_iter().enumerate() {
                    let at = Vec2::new(i as f32 / 200.0 - 0.5, 0.3);
                    let (floor, receiver) = floor_hit(scale, offset, at);
                    for sampling in [
                        LightSampling::area(DiscWarp::Concentric),
                        LightSampling::solid_angle(),
                    ] {
                        let sample = light.sample(receiver.p, u, sampling).unwrap();
                        let ray = sample.shadow_ray(&receiver, 0.0);
                        assert_eq!(
                            floor.intersect(&ray),
                            None,
                            "scale {scale}: the receiver blocks"
                        );
                        // A light seen from its front must not shadow itself; from behind, a
                        // sphere's far side may.
                        if light.emitted(sample.n, receiver.p - sample.p) != Vec3::ZERO {
                            assert_eq!(
                                shape.intersect(&ray),
                                None,
                                "scale {scale}: {sample:?} shadows itself"
                            );
                        }
                    }
                }
            }
        }
    }
}
