//! The cast car (`mounting = "cast"`): its chassis body, its shape-cast wheel contacts and its
//! step (see the [`vehicle`](super) module docs).

use ackermann::Wheel;
use rapier3d::parry::query::ShapeCastOptions;
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, Cylinder, Mat3, PhysicsWorld, Pose, QueryFilter,
    RigidBodyBuilder, RigidBodyHandle, Rotation, Vector,
};

use rapier3d::parry::query::details::local_ray_intersection_with_triangle;
use rapier3d::parry::shape::SupportMap;
use rapier3d::prelude::{
    ColliderHandle, Group, InteractionGroups, InteractionTestMode, Ray, RayIntersection,
};
use std::cell::Cell;

use super::contact::{Body, Contact, Spring, Support};
use super::inertia::mass_properties;
use super::spec::VehicleSpec;
use super::step::{Found, Mount, Solved, Touch};
use super::{Frame, MIN_GROUND_COSINE, Vehicle};
use crate::geom::{self, G_CAR_BODY, G_ROAD};

/// The rapier side of one car: its single rigid body.
#[derive(Debug, Clone)]
pub(crate) struct Parts {
    pub chassis: RigidBodyHandle,
    /// 1/total mass (1/kg).
    pub inv_mass: f32,
    /// Inverse inertia tensor of the whole car about its centre of mass, in the car frame
    /// (1/(kg·m²)).
    pub inv_inertia: Mat3,
}

/// Creates the chassis of `spec` with the car origin at `origin`: one dynamic body with the
/// whole car's mass properties, whose frame is the car frame, and the collision box. Gravity
/// is applied by the tyre solve (the body's gravity scale is 0), so that the suspension and
/// tyres answer it within the same step.
pub(crate) fn build(world: &mut PhysicsWorld, spec: &VehicleSpec, origin: Pose) -> Parts {
    let mass_properties = mass_properties(spec);
    let chassis = world.insert_body(
        RigidBodyBuilder::dynamic()
            .pose(origin)
            .additional_mass_properties(mass_properties)
            .gravity_scale(0.0)
            .can_sleep(false),
    );
    let half = geom::vector(&spec.chassis.box_half_extents);
    world.insert_collider(
        ColliderBuilder::cuboid(half.x, half.y, half.z)
            .translation(geom::point(&spec.chassis.box_center))
            .density(0.0)
            .friction(1.0)
            .friction_combine_rule(CoefficientCombineRule::Multiply)
            .collision_groups(geom::groups(G_CAR_BODY)),
        Some(chassis),
    );
    Parts {
        chassis,
        inv_mass: mass_properties.inv_mass,
        inv_inertia: mass_properties.reconstruct_inverse_inertia_matrix(),
    }
}

/// Wheel `w`'s ground contact: the tyre (turned by `steer`, spin axis `axis` in world axes)
/// swept down the suspension axis from one radius above its hard point to the hard point (the
/// unloaded spring length); the first static surface it meets, unless too steep to stand on.
fn find_contact(
    world: &PhysicsWorld,
    spec: &VehicleSpec,
    last_road: &Cell<Option<RoadHit>>,
    w: Wheel,
    frame: &Frame,
    steer: Rotation,
    axis: Vector,
) -> Option<Touch> {
    let s = spec.wheels[w];
    let suspension = if w.is_front() {
        spec.front_suspension
    } else {
        spec.rear_suspension
    };
    let (up, q) = (frame.up, frame.pose.rotation);
    let radius = s.radius as f32;
    let hard_point = frame.pose.transform_point(geom::point(&s.position));
    let start = Pose::from_parts(hard_point + up * radius, q * steer);
    let tyre = Cylinder::new((0.5 * s.width) as f32, radius);
    let options = ShapeCastOptions {
        max_time_of_impact: radius,
        target_distance: 0.0,
        stop_at_penetration: true,
        compute_impact_geometry_on_penetration: true,
    };
    // Everything static but the roads by the shape cast; the roads by `road_contact`; the
    // nearer of the two is the ground.
    let others = QueryFilter::exclude_dynamic().groups(InteractionGroups::new(
        Group::ALL,
        !G_ROAD,
        InteractionTestMode::And,
    ));
    let cast = world
        .cast_shape(&start, -up, &tyre, options, others)
        .map(|(c, hit)| (c, hit.time_of_impact, hit.normal1));
    let road = road_contact(world, &start, up, &tyre, radius, last_road);
    let (collider, toi, n) = match (cast, road) {
        (Some(a), Some(b)) => {
            if b.1 <= a.1 {
                b
            } else {
                a
            }
        }
        (a, b) => a.or(b)?,
    };
    if n.dot(up) < MIN_GROUND_COSINE {
        return None;
    }
    let compression = radius - toi;
    let centre = hard_point + up * compression;
    let spring = Spring {
        hardpoint_arm: hard_point - frame.com,
        up,
        compression,
        stiffness: suspension.stiffness as f32,
        damping: suspension.damping as f32,
    };
    let contact = Contact::on_ground(Support::Spring(spring), n, axis, centre, radius, frame.com)?;
    Some(Touch {
        contact,
        collider,
        given_impulse: None,
        // The cast meets static surfaces only.
        ground_body: None,
    })
}

/// The cast car's step: the steering is this crate's; the suspension, tyres, brakes and spins
/// are solved together on the chassis, whose velocity goes to rapier.
impl Mount for Parts {
    const CARRIES_LOAD: bool = true;
    const WARM_RIGID_FORWARD: bool = true;

    fn steer(&self, car: &mut Vehicle, _world: &mut PhysicsWorld, dt: f64) {
        car.steer(dt);
    }

    fn chassis(&self, world: &PhysicsWorld, dt: f64) -> Option<(Frame, Body)> {
        let chassis = world.bodies.get(self.chassis)?;
        let frame = Frame::of(chassis);
        let body = Body::new(
            chassis.linvel() + world.gravity * dt as f32,
            chassis.angvel(),
            self.inv_mass,
            self.inv_inertia,
            frame.pose.rotation,
        );
        Some((frame, body))
    }

    fn find(&self, car: &Vehicle, world: &PhysicsWorld, w: Wheel, frame: &Frame) -> Option<Found> {
        let (steer, axis) = car.wheel_axis(w, frame);
        let touch = find_contact(
            world,
            &car.spec,
            &car.road_hits.0[w as usize],
            w,
            frame,
            steer,
            axis,
        );
        Some(Found { axis, touch })
    }

    fn hand_back(&self, _car: &mut Vehicle, world: &mut PhysicsWorld, solved: &Solved, _dt: f64) {
        if let Some(chassis) = world.bodies.get_mut(self.chassis) {
            chassis.set_linvel(solved.body.linvel, true);
            chassis.set_angvel(solved.body.angvel, true);
        }
    }
}

impl Vehicle {
    /// The rotation of wheel `w` by its steering angle, and its spin axis in world axes (the
    /// chassis' y turned by the steering).
    fn wheel_axis(&self, w: Wheel, frame: &Frame) -> (Rotation, Vector) {
        let delta = match w {
            Wheel::FrontRight => self.state.steering.right,
            Wheel::FrontLeft => self.state.steering.left,
            Wheel::RearRight | Wheel::RearLeft => 0.0,
        };
        // Positive steering turns right: the wheel (its axis, car y) turned by −δ about z.
        let steer = Rotation::from_rotation_z(-delta as f32);
        (steer, frame.pose.rotation * (steer * Vector::Y))
    }
}

/// The lane triangle a wheel's road ray hit: its road collider and the triangle's index in
/// that collider's mesh.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct RoadHit {
    collider: ColliderHandle,
    triangle: u32,
}

/// The road triangle under each wheel at its last ground query, indexed as [`Wheel`], kept
/// from one step to the next.
///
/// Casting the ray into the road through rapier's query pipeline walks two bounding-volume
/// trees (the colliders', then the lane mesh's triangles): 2.3 µs a wheel, as much as half a
/// cast car's step. A wheel moves less than a triangle in a step (10 cm at 10 m/s in 10 ms;
/// a lane's triangles are up to 1 m long), so the ray is first tested against that triangle
/// and its neighbours along the lane's strip, each one ray–triangle test. A hit inside one
/// of them is the hit the full cast would have returned (the same triangle, tested by the
/// same parry function), unless another road's surface lies within the ray's reach above
/// it, where roads overlap (a junction's connecting roads): there the wheel stays on the
/// surface it was on while that surface is under it. No hit, or a hit within [`EDGE`] of a
/// triangle's edge (where a neighbour, or the next lane's triangle, is crossed too): the full
/// cast, whose triangle is kept.
#[derive(Debug, Clone, Default)]
pub(crate) struct RoadHits(pub(crate) [Cell<Option<RoadHit>>; 4]);

/// The smallest barycentric coordinate (dimensionless) of a hit on a kept triangle that is
/// taken as inside it: nearer an edge, the full query decides. A lane's triangle is about
/// 1 m by a lane's width: 1e-3 is a band of 1 mm to a few mm along its edges.
const EDGE: f32 = 1e-3;

/// How many triangles before and after the last one along the lane's strip are tried (the
/// strip has two triangles per cross-section: ±4 reaches the next two cross-sections).
const NEIGHBOURS: i64 = 4;

/// The road under the tyre `tyre` at `start` swept down `up` by at most `max` (m): the road
/// collider, the sweep's length to the touch (0 to `max`) and the road's normal there;
/// `last` is the triangle the wheel's ray hit at its last query, updated.
///
/// A shape cast of the cylinder against a road's triangle mesh runs a GJK sweep per nearby
/// triangle, ten times the cost of the cast on the flat ground. A road is locally a plane:
/// one ray down from the tyre's lowest point finds the triangle and its plane, and the sweep
/// to that plane is closed-form (the tyre's support point along −n reaches it after
/// `(s − q)·n / (up·n)`). The ray starts `max` above that point, so that a tyre sunk into
/// the road (the shape cast's penetration) is found with a sweep of 0.
fn road_contact(
    world: &PhysicsWorld,
    start: &Pose,
    up: Vector,
    tyre: &Cylinder,
    max: f32,
    last: &Cell<Option<RoadHit>>,
) -> Option<(ColliderHandle, f32, Vector)> {
    let local =
        |d: Vector| start.transform_point(tyre.local_support_point(start.rotation.inverse() * d));
    let low = local(-up);
    let ray = Ray::new(low + up * max, -up);
    let roads = QueryFilter::exclude_dynamic().groups(InteractionGroups::new(
        Group::ALL,
        G_ROAD,
        InteractionTestMode::And,
    ));
    let found = last
        .get()
        .and_then(|h| near(world, h, &ray, 2.0 * max))
        .or_else(|| world.cast_ray_and_get_normal(&ray, 2.0 * max, false, roads));
    let Some((collider, hit)) = found else {
        last.set(None);
        return None;
    };
    last.set(Some(RoadHit {
        collider,
        triangle: hit.subshape,
    }));
    let q = ray.point_at(hit.time_of_impact);
    // The mesh is not oriented: its normal may come out of either face.
    let n = if hit.normal.dot(up) < 0.0 {
        -hit.normal
    } else {
        hit.normal
    };
    let cos = n.dot(up);
    if cos < MIN_GROUND_COSINE {
        return None;
    }
    let toi = (local(-n) - q).dot(n) / cos;
    (toi <= max).then_some((collider, toi.max(0.0), n))
}

/// The ray `ray` (world) within `reach` (m) against the triangle of `last` and its
/// neighbours along the lane's strip, the nearest first: the collider and the hit of the
/// first one it crosses, with that triangle's index as its sub-shape (as rapier's cast into
/// the whole mesh gives it). `None` if it crosses none of them, crosses the first near one
/// of its edges ([`EDGE`]), or the collider is gone.
fn near(
    world: &PhysicsWorld,
    last: RoadHit,
    ray: &Ray,
    reach: f32,
) -> Option<(ColliderHandle, RayIntersection)> {
    let collider = world.colliders.get(last.collider)?;
    let mesh = collider.shape().as_trimesh()?;
    let count = i64::try_from(mesh.num_triangles()).ok()?;
    let pose = collider.position();
    let ray = ray.inverse_transform_by(pose);
    // Each candidate: `None` if the ray misses it, `Some(None)` if it crosses it near an edge
    // (another triangle, of this mesh or another, may be crossed there too, and the full
    // query's choice between them is the nearer by rounding: it decides), else the hit.
    let test = |i: i64| {
        let i = u32::try_from(i).ok().filter(|_| i < count)?;
        let t = mesh.triangle(i);
        let (hit, barycentric) = local_ray_intersection_with_triangle(t.a, t.b, t.c, &ray)
            .filter(|(hit, _)| hit.time_of_impact <= reach)?;
        Some((barycentric.min_element() > EDGE).then(|| hit.transform_by(pose).with_subshape(i)))
    };
    let from = i64::from(last.triangle);
    let hit = test(from)
        .or_else(|| (1..=NEIGHBOURS).find_map(|d| test(from + d).or_else(|| test(from - d))))??;
    Some((last.collider, hit))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::road::{Cubic, Curve, Profile, Road};
    use proto_geom::nalgebra::Point2;
    use rapier3d::prelude::TriMeshFlags;

    /// A physics world holding the lanes of `road` as the world builds them.
    fn world_of(road: &Road) -> PhysicsWorld {
        let mut world = PhysicsWorld::new();
        for mesh in road.lane_meshes(crate::ROAD_LIFT) {
            let vertices = mesh.vertices.iter().map(geom::point).collect();
            let builder = ColliderBuilder::trimesh_with_flags(
                vertices,
                mesh.triangles,
                TriMeshFlags::FIX_INTERNAL_EDGES,
            )
            .unwrap()
            .collision_groups(geom::groups(G_ROAD));
            world.insert_collider(builder, None);
        }
        // The query pipeline sees the colliders once the broad phase has run.
        world.step();
        world
    }

    #[test]
    fn the_kept_triangle_gives_exactly_what_the_full_query_gives() {
        // A curve on a 6 % grade with a 4 % bank, driven along and across both lanes: at every
        // point, the contact found through the kept triangle is the full query's, bit for bit
        // (near an edge, where two triangles are crossed, the full query is what answers).
        let segments = [(40.0, Curve::Line), (80.0, Curve::Arc { curvature: 0.02 })];
        let mut road = Road::two_way("r", Point2::origin(), 0.0, &segments, 3.5).unwrap();
        road.elevation = Profile::new(vec![Cubic {
            s: 0.0,
            coefficients: [0.0, 0.06, 0.0, 0.0],
        }]);
        road.superelevation = Profile::new(vec![Cubic {
            s: 0.0,
            coefficients: [0.04, 0.0, 0.0, 0.0],
        }]);
        let world = world_of(&road);
        let tyre = Cylinder::new(0.12, 0.4);
        let kept = Cell::new(None);
        let (mut hits, mut found) = (0, 0);
        for k in 0..1100 {
            // 10 cm a step (10 m/s in 10 ms), weaving from t = −3 to +3 m and back.
            let s = 0.1 * f64::from(k);
            let t = 3.0 * (0.02 * f64::from(k)).sin();
            let p = road.surface_point(s, t);
            let heading = road.plan_at(s).heading as f32;
            let start = Pose::from_parts(
                geom::point(&p) + Vector::Z * 0.45,
                Rotation::from_rotation_z(heading),
            );
            let fresh = road_contact(&world, &start, Vector::Z, &tyre, 0.4, &Cell::new(None));
            let before = kept.get();
            let with_cache = road_contact(&world, &start, Vector::Z, &tyre, 0.4, &kept);
            assert_eq!(with_cache, fresh, "s = {s} m, t = {t} m");
            found += usize::from(fresh.is_some());
            // The tyre's lowest point is under its centre (no roll): the ray starts at the
            // centre, as `road_contact` starts it a radius above that point.
            let ray = Ray::new(start.translation, -Vector::Z);
            hits += usize::from(before.is_some_and(|h| near(&world, h, &ray, 0.8).is_some()));
        }
        // The tyre stands on the road at every point (its lowest point 5 cm above it).
        assert_eq!(found, 1100);
        // Most answers came from the kept triangles (the rest: lane changes and edges).
        assert!(hits > 1000, "{hits}");
    }
}
