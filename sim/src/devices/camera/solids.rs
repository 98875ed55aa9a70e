//! The world as a camera sees it: every box, ramp, dynamic box, car body and robot as a convex
//! solid of flat triangles in its own frame, with its pose, colour and recognition fields. The
//! ground is no solid: the rasteriser draws the plane z = 0 itself. The roads are patches of
//! triangles ([`super::roads`]), built once and shared.

use std::sync::Arc;

use proto_geom::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};

use super::roads::Patch;
use crate::appearance::{
    Appearance, Appearances, BODY_COLOR, OBSTACLE_COLOR, PALETTE, SceneObject,
};
use crate::config::{Obstacle, ramp_corners};
use crate::vehicle::VehicleId;
use crate::world::World;

/// Facets around a robot's cylinder.
const ROBOT_FACETS: usize = 16;

/// A convex solid of the world.
#[derive(Debug, Clone)]
pub(crate) struct Solid {
    /// Recognition id: 1 + its index in the world's list of things (obstacles, then dynamic
    /// boxes, cars and robots, each in the world's order).
    pub id: i32,
    /// The car it is the body of, so that the car's own cameras do not see it.
    pub owner: Option<VehicleId>,
    /// Solid frame → world (m).
    pub pose: Isometry3<f64>,
    /// Centre of its bounding box (m, solid frame).
    pub centre: Point3<f64>,
    /// Half sizes of its bounding box (m, solid frame).
    pub half: Vector3<f64>,
    /// Triangles (m, solid frame), each with its outward unit normal.
    pub triangles: Vec<([Point3<f64>; 3], Vector3<f64>)>,
    /// Its look.
    pub appearance: Appearance,
}

/// The solids of a world at one instant.
#[derive(Debug, Clone, Default)]
pub(crate) struct Solids {
    pub all: Vec<Solid>,
    /// The roads' surfaces and lines.
    pub roads: Arc<[Patch]>,
}

impl Solids {
    /// The solids of `world` as it is now, looking as `looks` says (defaults for the rest:
    /// [`crate::appearance`]), with the roads' patches `roads`.
    pub(crate) fn of(world: &World, looks: &Appearances, roads: Arc<[Patch]>) -> Solids {
        let mut all = Vec::new();
        let mut push = |object: SceneObject,
                        default: [f64; 3],
                        owner: Option<VehicleId>,
                        pose: Isometry3<f64>,
                        corners: Vec<Point3<f64>>,
                        faces: Vec<Vec<usize>>| {
            let id = i32::try_from(all.len() + 1).unwrap_or(i32::MAX);
            let appearance = looks
                .explicit(object)
                .cloned()
                .unwrap_or_else(|| Appearance::of_color(default));
            all.push(solid(id, owner, pose, &corners, &faces, appearance));
        };
        let config = world.config();
        for (i, o) in config.obstacles.iter().enumerate() {
            let (at, yaw) = o.placement();
            let (corners, faces) = match *o {
                Obstacle::Box { half_extents, .. } => cuboid(Point3::origin(), half_extents),
                Obstacle::Ramp {
                    length,
                    width,
                    height,
                    ..
                } => wedge(length, width, height),
                Obstacle::Cone { ref cone, .. } => cone.polyhedron(),
            };
            let default = match o {
                Obstacle::Cone { cone, .. } => cone.color,
                _ => OBSTACLE_COLOR,
            };
            let pose = Isometry3::from_parts(
                Translation3::from(at.coords),
                UnitQuaternion::from_euler_angles(0.0, 0.0, yaw),
            );
            push(
                SceneObject::Obstacle(i),
                default,
                None,
                pose,
                corners,
                faces,
            );
        }
        for (i, (spec, pose)) in config.bodies.iter().zip(world.bodies()).enumerate() {
            let (corners, faces) = cuboid(Point3::origin(), spec.size / 2.0);
            let pose =
                Isometry3::from_parts(Translation3::from(pose.position.coords), pose.rotation);
            push(SceneObject::Body(i), BODY_COLOR, None, pose, corners, faces);
        }
        let vehicles = world.vehicles();
        for (i, v) in vehicles.iter().enumerate() {
            let chassis = &v.spec().chassis;
            let (corners, faces) = cuboid(chassis.box_center, chassis.box_half_extents);
            let s = v.state();
            let pose = Isometry3::from_parts(Translation3::from(s.position.coords), s.orientation);
            push(
                SceneObject::Car(i),
                PALETTE[i % PALETTE.len()],
                Some(v.id()),
                pose,
                corners,
                faces,
            );
        }
        for (i, r) in world.robots().iter().enumerate() {
            let p = r.params();
            let (corners, faces) = prism(p.axle_length / 2.0, p.wheel_radius);
            let pose = r.pose();
            let pose = Isometry3::from_parts(
                Translation3::from(pose.position.coords),
                UnitQuaternion::from_euler_angles(0.0, 0.0, pose.heading),
            );
            let colour = PALETTE[(vehicles.len() + i) % PALETTE.len()];
            push(SceneObject::Robot(i), colour, None, pose, corners, faces);
        }
        Solids { all, roads }
    }
}

/// A solid of the convex polyhedron `corners` with `faces` (corner indices in order around
/// each face): triangle fans, each normal pointed away from the centroid.
fn solid(
    id: i32,
    owner: Option<VehicleId>,
    pose: Isometry3<f64>,
    corners: &[Point3<f64>],
    faces: &[Vec<usize>],
    appearance: Appearance,
) -> Solid {
    let (mut lo, mut hi) = (
        Vector3::repeat(f64::INFINITY),
        Vector3::repeat(-f64::INFINITY),
    );
    for p in corners {
        lo = lo.inf(&p.coords);
        hi = hi.sup(&p.coords);
    }
    let centroid =
        corners.iter().fold(Vector3::zeros(), |s, p| s + p.coords) / corners.len() as f64;
    let mut triangles = Vec::new();
    for face in faces {
        let Some(a) = face.first().and_then(|&k| corners.get(k)) else {
            continue;
        };
        for pair in face[1..].windows(2) {
            let (Some(b), Some(c)) = (corners.get(pair[0]), corners.get(pair[1])) else {
                continue;
            };
            let Some(n) = (b - a).cross(&(c - a)).try_normalize(1e-12) else {
                continue;
            };
            // Convex: the outward side is the one away from the centroid.
            let n = if n.dot(&(a.coords - centroid)) < 0.0 {
                -n
            } else {
                n
            };
            triangles.push(([*a, *b, *c], n));
        }
    }
    Solid {
        id,
        owner,
        pose,
        centre: Point3::from((lo + hi) / 2.0),
        half: (hi - lo) / 2.0,
        triangles,
        appearance,
    }
}

type Polyhedron = (Vec<Point3<f64>>, Vec<Vec<usize>>);

/// A box of centre `c` and half sizes `h` (m).
fn cuboid(c: Point3<f64>, h: Vector3<f64>) -> Polyhedron {
    let corners = (0..8)
        .map(|k| {
            let s = |bit: usize| if k & bit == 0 { -1.0 } else { 1.0 };
            c + Vector3::new(s(1) * h.x, s(2) * h.y, s(4) * h.z)
        })
        .collect();
    // Corner k has x from bit 0, y from bit 1, z from bit 2.
    let faces = vec![
        vec![0, 2, 6, 4],
        vec![1, 3, 7, 5],
        vec![0, 1, 5, 4],
        vec![2, 3, 7, 6],
        vec![0, 1, 3, 2],
        vec![4, 5, 7, 6],
    ];
    (corners, faces)
}

/// A ramp's wedge ([`ramp_corners`]).
fn wedge(length: f64, width: f64, height: f64) -> Polyhedron {
    let corners = ramp_corners(length, width, height)
        .iter()
        .map(|&p| Point3::from(p))
        .collect();
    // Low edge 0 1, back foot 2 3, back top 4 5 (right, left).
    let faces = vec![
        vec![0, 1, 3, 2],
        vec![2, 3, 5, 4],
        vec![0, 1, 5, 4],
        vec![0, 2, 4],
        vec![1, 3, 5],
    ];
    (corners, faces)
}

/// A robot's upright cylinder of radius `radius` and height `height` centred at height
/// `height` (m), as a prism of [`ROBOT_FACETS`] sides: the replay's robot body.
fn prism(radius: f64, height: f64) -> Polyhedron {
    let n = ROBOT_FACETS;
    let corners = (0..2 * n)
        .map(|k| {
            let a = core::f64::consts::TAU * (k % n) as f64 / n as f64;
            let z = if k < n { height / 2.0 } else { 1.5 * height };
            Point3::new(radius * a.cos(), radius * a.sin(), z)
        })
        .collect();
    let mut faces: Vec<Vec<usize>> = (0..n)
        .map(|k| vec![k, (k + 1) % n, n + (k + 1) % n, n + k])
        .collect();
    faces.push((0..n).collect());
    faces.push((n..2 * n).collect());
    (corners, faces)
}
