//! The cast car (`mounting = "cast"`): its chassis body, its shape-cast wheel contacts and its
//! step (see the [`vehicle`](super) module docs).

use ackermann::Wheel;
use rapier3d::parry::query::ShapeCastOptions;
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, Cylinder, Mat3, PhysicsWorld, Pose, QueryFilter,
    RigidBodyBuilder, RigidBodyHandle, Rotation, Vector,
};

use rapier3d::parry::shape::SupportMap;
use rapier3d::prelude::{ColliderHandle, Group, InteractionGroups, InteractionTestMode, Ray};

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
    let road = road_contact(world, &start, up, &tyre, radius);
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
        let touch = find_contact(world, &car.spec, w, frame, steer, axis);
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

/// The road under the tyre `tyre` at `start` swept down `up` by at most `max` (m): the road
/// collider, the sweep's length to the touch (0 to `max`) and the road's normal there.
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
) -> Option<(ColliderHandle, f32, Vector)> {
    let roads = QueryFilter::exclude_dynamic().groups(InteractionGroups::new(
        Group::ALL,
        G_ROAD,
        InteractionTestMode::And,
    ));
    let local =
        |d: Vector| start.transform_point(tyre.local_support_point(start.rotation.inverse() * d));
    let low = local(-up);
    let ray = Ray::new(low + up * max, -up);
    let (collider, hit) = world.cast_ray_and_get_normal(&ray, 2.0 * max, false, roads)?;
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
