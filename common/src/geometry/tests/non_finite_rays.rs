//! A ray a student's wrong answer computed (a NaN or infinite origin, direction or `t_max`, a
//! zero or huge direction) gets an answer from every query, never a panic: the chapter's own
//! check can then say in words what is wrong with it.
//!
//! The promise: a ray that goes nowhere (an origin or a direction with a NaN or infinite
//! component, a zero direction) or whose `t_max` is NaN hits nothing, and is occluded by
//! nothing; any other ray gets the hits it always gets, each with `0 < t < t_max`.

use std::sync::LazyLock;

use glam::{Vec2, Vec3};
use proptest::prelude::*;

use crate::Ray;
use crate::geometry::awkward::{self, number, vec2, vec3};
use crate::geometry::{
    Aabb, Bvh, Disc, Geometry, Parallelogram, Shape, Sphere, SurfaceHit, Triangle, TriangleMesh,
    offset_ray_origin,
};

/// One of every shape kind alone, a few hundred shapes (so that the BVH has inner nodes with
/// lanes left empty, the lanes whose child index a NaN ray once followed out of the tree), a
/// mesh (whose leaves are tested four triangles at once), and no shape at all.
static SCENES: LazyLock<Vec<Geometry>> = LazyLock::new(|| {
    let sphere: Shape = Sphere::new(Vec3::new(0.0, 0.0, 3.0), 1.0).into();
    let triangle: Shape = Triangle::new(Vec3::ZERO, Vec3::X, Vec3::Y).into();
    let parallelogram: Shape = Parallelogram::new(Vec3::ZERO, Vec3::X, Vec3::Y).into();
    let disc: Shape = Disc::new(Vec3::ZERO, Vec3::Z, 1.0).into();
    let many: Vec<Shape> = (0..300)
        .map(|k| {
            let at = Vec3::new((k % 7) as f32, (k % 11) as f32, (k % 13) as f32);
            match k % 4 {
                0 => Sphere::new(at, 0.3).into(),
                1 => Triangle::new(at, at + Vec3::X, at + Vec3::Y).into(),
                2 => Parallelogram::new(at, 0.5 * Vec3::X, 0.5 * Vec3::Z).into(),
                _ => Disc::new(at, Vec3::Y, 0.4).into(),
            }
        })
        .collect();
    let mesh: Vec<Shape> = TriangleMesh::bumpy_sphere(500)
        .triangles()
        .map(Shape::from)
        .collect();
    vec![
        Geometry::new(Vec::new()),
        Geometry::new(vec![sphere]),
        Geometry::new(vec![triangle]),
        Geometry::new(vec![parallelogram]),
        Geometry::new(vec![disc]),
        Geometry::new(many),
        Geometry::new(mesh),
    ]
});

/// Whether the ray can hit nothing, by the promise above.
fn goes_nowhere(ray: &Ray) -> bool {
    !(ray.origin.is_finite() && ray.dir.is_finite()) || ray.dir == Vec3::ZERO || ray.t_max.is_nan()
}

/// Asks `geometry` every question about `ray`; the first answer that breaks the promise is
/// the error.
fn check_every_query(geometry: &Geometry, ray: &Ray) -> Result<(), String> {
    let nowhere = goes_nowhere(ray);
    let nearest = geometry.intersect(ray);
    let (counted, count) = geometry.intersect_counted(ray);
    let occluded = geometry.occluded(ray);
    let bvh_nearest = geometry.bvh().intersect(ray, |_, _| Some(0.5));
    let bvh_any = geometry.bvh().any_hit(ray, |_| true);
    if counted != nearest {
        return Err(format!(
            "intersect_counted {counted:?}, intersect {nearest:?}"
        ));
    }
    if nowhere {
        if nearest.is_some() || occluded || bvh_nearest.is_some() || bvh_any || count.nodes > 0 {
            return Err(format!(
                "a ray that goes nowhere: {nearest:?}, occluded {occluded}, the walk {count:?}, \
                 the BVH's {bvh_nearest:?} and {bvh_any}"
            ));
        }
        for shape in geometry.shapes().iter().take(8) {
            if let Some(hit) = shape.intersect(ray) {
                return Err(format!("a ray that goes nowhere hit {shape:?} at {hit:?}"));
            }
        }
    }
    if let Some(hit) = nearest
        && !(hit.t > 0.0 && hit.t < ray.t_max && hit.p.is_finite())
    {
        return Err(format!(
            "{hit:?} is not within the ray's (0, {})",
            ray.t_max
        ));
    }
    if nearest.is_some() && !occluded {
        return Err(format!(
            "{nearest:?} is a hit, yet nothing occludes the ray"
        ));
    }
    Ok(())
}

#[test]
fn a_ray_that_goes_nowhere_hits_nothing() {
    // The reported crash: chapter 01's shadow ray towards a light at the shaded point itself
    // has the direction `normalize(0)`, NaN. The walk indexed the tree at `u32::MAX`.
    let nan = Vec3::splat(f32::NAN);
    let good = Ray::new(Vec3::new(0.2, 0.3, -5.0), Vec3::Z);
    let broken = [
        Ray { dir: nan, ..good },
        Ray {
            origin: nan,
            ..good
        },
        Ray {
            dir: Vec3::new(0.0, f32::NAN, 1.0),
            ..good
        },
        Ray {
            origin: Vec3::new(f32::INFINITY, 0.3, -5.0),
            ..good
        },
        Ray {
            dir: Vec3::splat(f32::INFINITY),
            ..good
        },
        Ray {
            dir: Vec3::ZERO,
            ..good
        },
        Ray {
            dir: -Vec3::ZERO,
            ..good
        },
        Ray {
            t_max: f32::NAN,
            ..good
        },
    ];
    for geometry in SCENES.iter() {
        for ray in &broken {
            assert!(goes_nowhere(ray));
            check_every_query(geometry, ray).unwrap_or_else(|e| panic!("{ray:?}: {e}"));
        }
        if geometry.shapes().len() == 1 {
            assert!(
                geometry.intersect(&good).is_some(),
                "the good ray hits {:?}",
                geometry.shapes()[0]
            );
        }
    }
}

#[test]
fn an_empty_box_is_never_entered() {
    let nan = Vec3::splat(f32::NAN);
    let good = Ray::new(Vec3::new(0.2, 0.3, -5.0), Vec3::Z);
    for ray in [
        good,
        Ray { dir: nan, ..good },
        Ray {
            origin: nan,
            ..good
        },
    ] {
        assert_eq!(Aabb::empty().intersect(&ray), None, "{ray:?}");
    }
    let unit = Aabb::from_points(Vec3::ZERO, Vec3::ONE);
    assert_eq!(unit.intersect(&Ray { dir: nan, ..good }), None);
    assert!(
        unit.intersect(&Ray::new(Vec3::new(0.5, 0.5, -5.0), Vec3::Z))
            .is_some()
    );
}

/// A ray of [`awkward`] numbers in every place.
fn ray() -> impl Strategy<Value = Ray> {
    (vec3(), vec3(), number(), number()).prop_map(|(origin, dir, t_max, time)| Ray {
        origin,
        dir,
        t_max,
        time,
    })
}

/// A ray from near the scenes, in a direction of awkward numbers: the rays that reach the
/// shapes' own tests.
fn aimed_ray() -> impl Strategy<Value = Ray> {
    let near = (-2.0f32..8.0, -2.0f32..12.0, -2.0f32..14.0);
    (near, vec3(), prop_oneof![Just(f32::INFINITY), number()]).prop_map(
        |((x, y, z), dir, t_max)| Ray {
            origin: Vec3::new(x, y, z),
            dir,
            t_max,
            time: 0.0,
        },
    )
}

/// A shape of awkward numbers.
fn shape() -> impl Strategy<Value = Shape> {
    prop_oneof![
        (vec3(), number()).prop_map(|(c, r)| Sphere::new(c, r).into()),
        (vec3(), vec3(), vec3()).prop_map(|(a, b, c)| Triangle::new(a, b, c).into()),
        (vec3(), vec3(), vec3()).prop_map(|(a, b, c)| Parallelogram::new(a, b, c).into()),
        (vec3(), vec3(), number()).prop_map(|(c, n, r)| Disc::new(c, n, r).into()),
        (vec3(), vec3(), vec3(), vec3()).prop_map(|(c, n, a, b)| Disc::ellipse(c, n, a, b).into()),
    ]
}

proptest! {
    #![proptest_config(awkward::config(512))]

    #[test]
    fn any_ray_gets_an_answer_from_every_query(ray in prop_oneof![ray(), aimed_ray()]) {
        for geometry in SCENES.iter() {
            check_every_query(geometry, &ray).map_err(TestCaseError::fail)?;
        }
    }

    #[test]
    fn shapes_of_any_numbers_answer_any_ray(
        shapes in prop::collection::vec(shape(), 1..12),
        rays in prop::collection::vec(prop_oneof![ray(), aimed_ray()], 8),
        uv in vec2(),
    ) {
        let geometry = Geometry::new(shapes);
        for ray in &rays {
            check_every_query(&geometry, ray).map_err(TestCaseError::fail)?;
        }
        for shape in geometry.shapes() {
            let _ = (shape.bounds(), shape.area(), shape.dp_du(uv));
            match shape {
                Shape::Parallelogram(p) => {
                    let _ = (p.point_at(uv.x, uv.y), p.uv_of(rays[0].origin));
                }
                Shape::Disc(d) => {
                    let _ = d.point_at(uv.x, uv.y);
                }
                _ => {}
            }
        }
    }

    #[test]
    fn secondary_rays_from_any_hit_get_an_answer(
        p in vec3(), p_error in vec3(), n in vec3(), dir in vec3(), target in vec3(),
    ) {
        let hit = SurfaceHit {
            t: 1.0,
            p,
            p_error,
            n,
            shading_n: n,
            uv: Vec2::ZERO,
            shape: 0,
        };
        let other = SurfaceHit { p: target, ..hit };
        let _ = offset_ray_origin(p, p_error, n, dir);
        for ray in [
            hit.spawn_ray(dir, 0.0),
            hit.spawn_ray_to(target, 0.0),
            hit.spawn_ray_to_hit(&other, 0.0),
        ] {
            for geometry in SCENES.iter() {
                check_every_query(geometry, &ray).map_err(TestCaseError::fail)?;
            }
        }
    }

    #[test]
    fn a_tree_over_any_boxes_answers_any_ray(
        corners in prop::collection::vec((vec3(), vec3()), 1..40),
        ray in prop_oneof![ray(), aimed_ray()],
    ) {
        let boxes: Vec<Aabb> = corners.iter().map(|&(a, b)| Aabb { min: a, max: b }).collect();
        let bvh = Bvh::build(&boxes);
        let nearest = bvh.intersect(&ray, |_, t_max| Some(0.5 * t_max));
        let any = bvh.any_hit(&ray, |_| true);
        if goes_nowhere(&ray) {
            prop_assert!(nearest.is_none() && !any);
        }
    }
}
