//! The cast car (`mounting = "cast"`): its chassis body, its shape-cast wheel contacts and its
//! step (see the [`vehicle`](super) module docs).

use ackermann::Wheel;
use rapier3d::parry::query::ShapeCastOptions;
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, Cylinder, Mat3, PhysicsWorld, Pose, QueryFilter,
    RigidBodyBuilder, RigidBodyHandle, Rotation, Vector,
};

use super::contact::{Body, Contact, Spring, Support, WheelRow};
use super::inertia::mass_properties;
use super::spec::VehicleSpec;
use super::wheels::Footing;
use super::{Frame, MIN_GROUND_COSINE, Vehicle};
use crate::geom::{self, G_CAR_BODY};

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

/// Wheel `w`'s ground contact and the ground's friction: the tyre (turned by `steer`, spin
/// axis `axis` in world axes) swept down the suspension axis from one radius above its hard
/// point to the hard point (the unloaded spring length); the first static surface it meets,
/// unless too steep to stand on.
pub(crate) fn find_contact(
    world: &PhysicsWorld,
    spec: &VehicleSpec,
    w: Wheel,
    frame: &Frame,
    steer: Rotation,
    axis: Vector,
) -> Option<(Contact, f32)> {
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
    let (collider, hit) =
        world.cast_shape(&start, -up, &tyre, options, QueryFilter::exclude_dynamic())?;
    let n = hit.normal1;
    if n.dot(up) < MIN_GROUND_COSINE {
        return None;
    }
    let compression = radius - hit.time_of_impact;
    let centre = hard_point + up * compression;
    let friction = world.colliders.get(collider).map_or(1.0, |c| c.friction());
    let spring = Spring {
        hardpoint_arm: hard_point - frame.com,
        up,
        compression,
        stiffness: suspension.stiffness as f32,
        damping: suspension.damping as f32,
    };
    let contact = Contact::on_ground(Support::Spring(spring), n, axis, centre, radius, frame.com)?;
    Some((contact, friction))
}

impl Vehicle {
    /// The cast car's step of `dt` seconds: the steering is this crate's; the suspension,
    /// tyres, brakes and spins are solved together on the chassis, whose velocity goes to
    /// rapier.
    pub(super) fn pre_step_cast(&mut self, world: &mut PhysicsWorld, parts: &Parts, dt: f64) {
        self.steer(dt);
        let Some(chassis) = world.bodies.get(parts.chassis) else {
            return;
        };
        let frame = Frame::of(chassis);
        let mut body = Body::new(
            chassis.linvel() + world.gravity * dt as f32,
            chassis.angvel(),
            parts.inv_mass,
            parts.inv_inertia,
            frame.pose.rotation,
        );
        let mut rows = [WheelRow::idle(); 4];
        let mut imposed = [0.0; 4];
        let mut axes = [Vector::ZERO; 4];
        let mut roads = [0.0; 4];
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            let (steer, axis) = self.wheel_axis(w, &frame);
            axes[i] = axis;
            imposed[i] = self.start_row(w, &mut rows[i], dt);
            if let Some((contact, road)) = find_contact(world, &self.spec, w, &frame, steer, axis) {
                roads[i] = road;
                let footing = Footing {
                    road: f64::from(road),
                    load: self.tyre_load(w, &contact, dt),
                };
                self.set_up_contact(w, &mut rows[i], contact, &body, footing, dt);
            }
        }
        self.divide_axles(&mut rows);
        // The solve carries the load here: the braked wheels' sub-steps take its mean too.
        self.solve_contacts(&mut body, &mut rows, true, dt);
        self.finish_wheels(&mut body, &rows, imposed, axes, roads, dt);
        if let Some(chassis) = world.bodies.get_mut(parts.chassis) {
            chassis.set_linvel(body.linvel, true);
            chassis.set_angvel(body.angvel, true);
        }
    }

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

    /// The load (N) wheel `w`'s tyre coefficients are taken at on `contact`: the last step's,
    /// or the spring's at the current compression for a wheel that just landed.
    fn tyre_load(&self, w: Wheel, contact: &Contact, dt: f64) -> f64 {
        let previous = f64::from(self.impulses[w].normal) / dt;
        match contact.support {
            Support::Spring(s) if previous <= 0.0 => f64::from(s.stiffness * s.compression),
            _ => previous,
        }
    }
}
