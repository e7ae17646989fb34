//! Turning a shape description into the renderer's shapes, in world space.
//!
//! Every chapter needs this step and none of them teaches it, so it lives here. Mitsuba 3
//! defines each shape in object space (the rectangle is `[-1, 1]^2` at z = 0 with normal +z, the
//! disc the unit disc, the cube `[-1, 1]^3`) and maps it with `to_world`; normals transform with
//! the inverse transpose, which is what keeps them perpendicular under non-uniform scaling.

use super::{ShapeDescription, ShapeGeometry};
use common::geometry::{Disc, Parallelogram, Shape, Sphere, TriangleMesh};
use glam::{Mat3, Mat4, Vec3};

/// The world-space shapes of one description: one for a sphere, rectangle or disc, six
/// parallelograms for a cube, one triangle per triangle of an OBJ, PLY or serialized mesh. Any linear map makes a
/// rectangle a parallelogram and a disc an ellipse, as in Mitsuba; a sphere under a transform
/// that does not keep it round, or a mesh that cannot be read, is refused with a message
/// saying why.
pub fn world_shapes(shape: &ShapeDescription) -> Result<Vec<Shape>, String> {
    let m = shape.to_world;
    match &shape.geometry {
        ShapeGeometry::Sphere { center, radius } => {
            let scale = uniform_scale(m).ok_or("a sphere under a non-uniform scale is an ellipsoid, which Mitsuba 3 refuses too (its to_world may not scale a sphere unevenly)")?;
            // Its uv turn with to_world, as Mitsuba's do: the linear part without its scale.
            let rotation = Mat3::from_mat4(m) / scale;
            let sphere = Sphere::new(m.transform_point3(*center), radius * scale).turned(rotation);
            Ok(vec![Shape::Sphere(if shape.flip_normals {
                sphere.flipped()
            } else {
                sphere
            })])
        }
        ShapeGeometry::Rectangle => Ok(vec![square_face(m, Mat4::IDENTITY, shape.flip_normals)]),
        ShapeGeometry::Disc => {
            let mut normal = world_normal(m, Vec3::Z);
            if !normal.is_finite() {
                return Err("its to_world flattens the disk to a line (a scale of 0)".into());
            }
            if shape.flip_normals {
                normal = -normal;
            }
            let center = m.transform_point3(Vec3::ZERO);
            if uniform_scale(m).is_some() {
                // A circle whose uv follow to_world's x and y, as Mitsuba's do.
                let (x, y) = (m.transform_vector3(Vec3::X), m.transform_vector3(Vec3::Y));
                return Ok(vec![Shape::Disc(Disc::ellipse(center, normal, x, y))]);
            }
            // Under any other linear map the unit circle becomes an ellipse, as in Mitsuba.
            let (axis_t, axis_b) =
                principal_axes(m.transform_vector3(Vec3::X), m.transform_vector3(Vec3::Y));
            let (rt, rb) = (axis_t.length(), axis_b.length());
            Ok(vec![Shape::Disc(if (rt - rb).abs() <= 1e-6 * rt {
                // Round after all (say `<scale x="0.4" y="0.4"/>`, whose z does not matter).
                Disc::new(center, normal, rt)
            } else {
                Disc::ellipse(center, normal, axis_t, axis_b)
            })])
        }
        ShapeGeometry::Cube => {
            // The six faces of [-1, 1]^3, each the unit rectangle moved onto the face: its x
            // and y go where Mitsuba's cube mesh has u and v grow (measured with Mitsuba 3:
            // they turn clockwise about the outward normal), its z along the outward normal.
            let face = |u: Vec3, v: Vec3, outward: Vec3| {
                Mat4::from_cols(
                    u.extend(0.0),
                    v.extend(0.0),
                    outward.extend(0.0),
                    outward.extend(1.0),
                )
            };
            let faces = [
                face(Vec3::Y, Vec3::X, Vec3::Z),
                face(-Vec3::Y, Vec3::X, -Vec3::Z),
                face(Vec3::Y, -Vec3::Z, Vec3::X),
                face(Vec3::Y, Vec3::Z, -Vec3::X),
                face(-Vec3::X, -Vec3::Z, Vec3::Y),
                face(Vec3::Z, Vec3::X, -Vec3::Y),
            ];
            Ok(faces
                .iter()
                .map(|&face| square_face(m, face, shape.flip_normals))
                .collect())
        }
        ShapeGeometry::Obj {
            filename,
            face_normals,
        } => Ok(placed_mesh(
            super::load_obj(filename)?,
            shape,
            *face_normals,
        )),
        ShapeGeometry::Ply {
            filename,
            face_normals,
            flip_tex_coords,
        } => {
            let mut mesh = super::load_ply(filename)?;
            if *flip_tex_coords {
                for uv in mesh.uvs.iter_mut().flatten() {
                    uv.y = 1.0 - uv.y;
                }
            }
            Ok(placed_mesh(mesh, shape, *face_normals))
        }
        ShapeGeometry::Serialized {
            filename,
            shape_index,
            face_normals,
        } => {
            let mesh = super::load_serialized(filename, *shape_index)?;
            Ok(placed_mesh(mesh, shape, *face_normals))
        }
    }
}

/// The triangles of a mesh file's `mesh` placed by the shape's `to_world`, with Mitsuba's
/// treatment of normals: the file's normals transformed (and flipped with `flip_normals`),
/// none with `face_normals`, and smooth ones computed in world space when the file has none.
fn placed_mesh(mut mesh: TriangleMesh, shape: &ShapeDescription, face_normals: bool) -> Vec<Shape> {
    let m = shape.to_world;
    mesh.positions = mesh
        .positions
        .iter()
        .map(|&p| m.transform_point3(p))
        .collect();
    let normal_matrix = m.inverse().transpose();
    if let Some(normals) = mesh.normals.as_mut() {
        for n in normals {
            let world = normal_matrix.transform_vector3(*n).normalize_or_zero();
            *n = if shape.flip_normals { -world } else { world };
        }
    }
    // A mesh's geometric normal is its world-space winding's, `(p1 - p0) × (p2 - p0)`, as in
    // Mitsuba 3 (checked against 3.9.1): so a mirroring `to_world` turns it over, unlike a
    // rectangle's or a disc's, which are transformed normals. `flip_normals` turns it over
    // once more, by reversing the winding.
    if shape.flip_normals {
        for corners in &mut mesh.indices {
            corners.swap(1, 2);
        }
    }
    if face_normals {
        mesh.normals = None;
    } else if mesh.normals.is_none() {
        // In world space, as Mitsuba does: angle weights change under a non-uniform scale, so
        // computing them before the transform would give other normals.
        mesh.recompute_vertex_normals();
    }
    // Reversing the winding swaps a triangle's barycentrics b1 and b2; a mesh without texture
    // coordinates takes its uv from them, which Mitsuba's flipped mesh does not swap. These
    // corner uvs swap them back.
    let barycentric_uvs = (shape.flip_normals && mesh.uvs.is_none()).then_some([
        glam::Vec2::ZERO,
        glam::Vec2::Y,
        glam::Vec2::X,
    ]);
    mesh.triangles()
        .map(|t| match barycentric_uvs {
            Some(uvs) => Shape::Triangle(t.with_uvs(uvs)),
            None => Shape::Triangle(t),
        })
        .collect()
}

/// The rectangle `[-1, 1]^2` (normal +z) placed by `to_world * face` as a parallelogram whose
/// normal `e1 x e2` is the transformed normal (flipped if asked).
fn square_face(to_world: Mat4, face: Mat4, flip: bool) -> Shape {
    let m = to_world * face;
    let corner = m.transform_point3(Vec3::new(-1.0, -1.0, 0.0));
    let e1 = m.transform_point3(Vec3::new(1.0, -1.0, 0.0)) - corner;
    let e2 = m.transform_point3(Vec3::new(-1.0, 1.0, 0.0)) - corner;
    // A mirroring transform turns e1 x e2 against the true normal; the parallelogram is then
    // flipped, which keeps its uv where Mitsuba has them. Flipping the normal is the same once
    // more.
    let want = if flip {
        -world_normal(m, Vec3::Z)
    } else {
        world_normal(m, Vec3::Z)
    };
    let parallelogram = Parallelogram::new(corner, e1, e2);
    if e1.cross(e2).dot(want) < 0.0 {
        Shape::Parallelogram(parallelogram.flipped())
    } else {
        Shape::Parallelogram(parallelogram)
    }
}

/// The principal semi-axes of the ellipse `{cos θ a + sin θ b}`: two perpendicular vectors,
/// the longest and the shortest radius, found by turning `(a, b)` by the angle that
/// diagonalises their Gram matrix, `tan 2θ = 2 a·b / (a·a − b·b)`.
fn principal_axes(a: Vec3, b: Vec3) -> (Vec3, Vec3) {
    let theta = 0.5 * (2.0 * a.dot(b)).atan2(a.dot(a) - b.dot(b));
    let (sin, cos) = theta.sin_cos();
    (cos * a + sin * b, cos * b - sin * a)
}

/// A normal mapped by the inverse transpose of `m`.
fn world_normal(m: Mat4, n: Vec3) -> Vec3 {
    m.inverse().transpose().transform_vector3(n).normalize()
}

/// The common length factor of `m`, if it scales every direction alike (up to 1e-4).
fn uniform_scale(m: Mat4) -> Option<f32> {
    let axes = [
        m.x_axis.truncate(),
        m.y_axis.truncate(),
        m.z_axis.truncate(),
    ];
    let lengths = axes.map(Vec3::length);
    let scale = lengths[0];
    let orthogonal =
        axes[0].dot(axes[1]).abs() + axes[1].dot(axes[2]).abs() + axes[0].dot(axes[2]).abs();
    let same = lengths.iter().all(|l| (l - scale).abs() <= 1e-4 * scale);
    (scale > 0.0 && same && orthogonal <= 1e-4 * scale * scale).then_some(scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene_file::description::mitsuba_default_material;
    use common::Ray;

    fn description(geometry: ShapeGeometry, to_world: Mat4) -> ShapeDescription {
        ShapeDescription {
            geometry,
            to_world,
            to_world_keyframes: Vec::new(),
            material: mitsuba_default_material(),
            emitter: None,
            flip_normals: false,
            position: Default::default(),
        }
    }

    fn hit_normal(shapes: &[Shape], ray: Ray) -> Option<Vec3> {
        shapes
            .iter()
            .filter_map(|s| s.intersect(&ray))
            .min_by(|a, b| a.t.total_cmp(&b.t))
            .map(|h| h.n)
    }

    #[test]
    fn the_cornell_floor_faces_up_at_y_minus_one() {
        // <rotate x="1" angle="-90"/><translate y="-1"/>
        let m =
            Mat4::from_translation(-Vec3::Y) * Mat4::from_rotation_x(-std::f32::consts::FRAC_PI_2);
        let shapes = world_shapes(&description(ShapeGeometry::Rectangle, m)).unwrap();
        let n = hit_normal(&shapes, Ray::new(Vec3::new(0.3, 0.0, 0.2), -Vec3::Y)).unwrap();
        assert!((n - Vec3::Y).length() < 1e-5, "{n}");
    }

    #[test]
    fn mirroring_keeps_the_transformed_normal() {
        let m = Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0));
        let shapes = world_shapes(&description(ShapeGeometry::Rectangle, m)).unwrap();
        let n = hit_normal(&shapes, Ray::new(Vec3::new(0.1, 0.1, 1.0), -Vec3::Z)).unwrap();
        assert!((n - Vec3::Z).length() < 1e-5, "{n}");
        let mut flipped = description(ShapeGeometry::Rectangle, m);
        flipped.flip_normals = true;
        let n = hit_normal(
            &world_shapes(&flipped).unwrap(),
            Ray::new(Vec3::new(0.1, 0.1, 1.0), -Vec3::Z),
        )
        .unwrap();
        assert!((n + Vec3::Z).length() < 1e-5, "{n}");
    }

    #[test]
    fn cube_faces_point_outwards() {
        let shapes = world_shapes(&description(
            ShapeGeometry::Cube,
            Mat4::from_scale(Vec3::splat(2.0)),
        ))
        .unwrap();
        assert_eq!(shapes.len(), 6);
        for axis in [Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y, -Vec3::Z] {
            let n = hit_normal(&shapes, Ray::new(axis * 5.0 + Vec3::splat(0.01), -axis)).unwrap();
            assert!((n - axis).length() < 1e-5, "{axis}: {n}");
        }
    }

    #[test]
    fn obj_meshes_are_placed_and_keep_their_facing() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("square.obj");
        std::fs::write(&path, "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n").unwrap();
        let obj = ShapeGeometry::Obj {
            filename: path,
            face_normals: true,
        };
        // Mirrored in x and lifted by 2: two triangles at z = 2, now wound clockwise seen from
        // +z, so facing -z, as in Mitsuba 3 (3.9.1 gives a mirrored OBJ or PLY triangle the
        // normal -z, and +z with flip_normals).
        let m = Mat4::from_translation(2.0 * Vec3::Z) * Mat4::from_scale(Vec3::new(-3.0, 3.0, 3.0));
        let shapes = world_shapes(&description(obj.clone(), m)).unwrap();
        assert_eq!(shapes.len(), 2);
        let ray = Ray::new(Vec3::new(0.5, 0.25, 5.0), -Vec3::Z);
        let hit = shapes
            .iter()
            .find_map(|s| s.intersect(&ray))
            .expect("the square is hit");
        assert!(
            (hit.p.z - 2.0).abs() < 1e-6 && (hit.n + Vec3::Z).length() < 1e-5,
            "{hit:?}"
        );
        let mut flipped = description(obj, m);
        flipped.flip_normals = true;
        let n = hit_normal(&world_shapes(&flipped).unwrap(), ray).unwrap();
        assert!((n - Vec3::Z).length() < 1e-5, "{n}");
        let missing = ShapeGeometry::Obj {
            filename: "missing.obj".into(),
            face_normals: false,
        };
        assert!(
            world_shapes(&description(missing, Mat4::IDENTITY))
                .unwrap_err()
                .contains("missing.obj")
        );
    }

    #[test]
    fn spheres_need_uniform_scales_and_discs_become_ellipses() {
        let sphere = ShapeGeometry::Sphere {
            center: Vec3::X,
            radius: 0.5,
        };
        let shapes = world_shapes(&description(
            sphere.clone(),
            Mat4::from_scale(Vec3::splat(3.0)),
        ))
        .unwrap();
        match &shapes[0] {
            Shape::Sphere(s) => {
                assert!((s.center - Vec3::new(3.0, 0.0, 0.0)).length() < 1e-6);
                assert!((s.radius - 1.5).abs() < 1e-6);
            }
            other => panic!("{other:?}"),
        }
        let mut flipped = description(sphere.clone(), Mat4::IDENTITY);
        flipped.flip_normals = true;
        match &world_shapes(&flipped).unwrap()[0] {
            Shape::Sphere(s) => assert!(s.inward, "flip_normals turns a sphere's normals in"),
            other => panic!("{other:?}"),
        }
        let squash = Mat4::from_scale(Vec3::new(1.0, 2.0, 1.0));
        assert!(
            world_shapes(&description(sphere, squash))
                .unwrap_err()
                .contains("ellipsoid")
        );
        // A disk under the same squash is an ellipse, 1 along x and 2 along y.
        let shapes = world_shapes(&description(ShapeGeometry::Disc, squash)).unwrap();
        let Shape::Disc(ellipse) = shapes[0] else {
            panic!("{shapes:?}");
        };
        assert!(!ellipse.is_circle());
        assert!((ellipse.area() - 2.0 * std::f32::consts::PI).abs() < 1e-5);
        let down = |x: f32, y: f32| Ray::new(Vec3::new(x, y, 1.0), -Vec3::Z);
        assert!(ellipse.intersect(&down(0.0, 1.9)).is_some());
        assert!(ellipse.intersect(&down(1.1, 0.0)).is_none());
        // Sheared, then scaled in its plane but not along z: still a disc's shapes.
        let shear = Mat4::from_cols_array(&[
            1.0, 0.0, 0.0, 0.0, 0.8, 0.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        ]);
        let sheared = world_shapes(&description(ShapeGeometry::Disc, shear)).unwrap();
        let Shape::Disc(sheared) = sheared[0] else {
            unreachable!()
        };
        // |det| of the map in the plane: the area is π times it.
        assert!(
            (sheared.area() - 0.5 * std::f32::consts::PI).abs() < 1e-5,
            "{sheared:?}"
        );
        let round = Mat4::from_scale(Vec3::new(0.4, 0.4, 1.0));
        let round = world_shapes(&description(ShapeGeometry::Disc, round)).unwrap();
        assert!(matches!(round[0], Shape::Disc(d) if d.is_circle() && d.radii().x == 0.4));
    }
}
