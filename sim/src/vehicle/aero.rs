//! The air on a car body ([`VehicleSpec::aero`](super::VehicleSpec::aero)): drag and lift
//! from the chassis' velocity relative to the world's wind, handed to rapier as forces on the
//! chassis for the coming step.
//!
//! Why a rapier force rather than a row of the contact solve: the air force changes little
//! within a step (its time constant `m / (ρ·Cd·A·v)` is about a minute for a car at
//! highway speed), so the explicit force from the start-of-step velocity is accurate to
//! `dt / 60 s`, and one path serves both mountings: the cast car's chassis and the multibody's
//! chassis link both take rapier's user forces. Like gravity, the force acts on the whole car
//! through the chassis; the wheels' spin follows through the tyres.

use rapier3d::prelude::{PhysicsWorld, Pose, RigidBodyHandle, Vector};
use vehicle_model::Wheel;

use super::{Parts, Vehicle, joints};

impl Vehicle {
    /// Sets the aerodynamic force on the chassis for the coming rapier step(s), in `wind`
    /// (m/s, world frame). Does nothing for a car without [`VehicleSpec::aero`](
    /// super::VehicleSpec::aero), so a car without air stays exactly Webots'. Keeps the
    /// drag's magnitude for [`Vehicle::drag_force`].
    pub(super) fn apply_aero(&mut self, world: &mut PhysicsWorld, wind: Vector) {
        let Some(aero) = self.spec.aero else {
            return;
        };
        let Some((handle, pose)) = self.chassis_pose(world) else {
            return;
        };
        let Some(chassis) = world.bodies.get_mut(handle) else {
            return;
        };
        let front = &self.spec.wheels[Wheel::FrontRight];
        let rear = &self.spec.wheels[Wheel::RearRight];
        let wheelbase = front.position.x - rear.position.x;
        // SAE J1594's reference point: on the ground, midway between the axles; the lifts act
        // on the ground under each axle (car frame: origin at the rear-axle centre).
        let on_ground =
            |x: f64, radius: f64| pose.transform_point(Vector::new(x as f32, 0.0, -radius as f32));
        let reference = on_ground(rear.position.x + wheelbase / 2.0, rear.radius);
        let front_point = on_ground(front.position.x, front.radius);
        let rear_point = on_ground(rear.position.x, rear.radius);
        let air = pose
            .rotation
            .inverse()
            .mul_vec3(chassis.velocity_at_point(reference) - wind);
        let forces = aero.forces([f64::from(air.x), f64::from(air.y), f64::from(air.z)]);
        self.drag_force = Some(forces.drag.iter().map(|f| f * f).sum::<f64>().sqrt());
        let [dx, dy, dz] = forces.drag.map(|f| f as f32);
        let up = pose.rotation * Vector::Z;
        chassis.reset_forces(true);
        chassis.reset_torques(true);
        chassis.add_force_at_point(pose.rotation * Vector::new(dx, dy, dz), reference, true);
        chassis.add_force_at_point(up * forces.lift_front as f32, front_point, true);
        chassis.add_force_at_point(up * forces.lift_rear as f32, rear_point, true);
    }

    /// The magnitude of the air's drag on the body over the last step (N, ≥ 0), from the
    /// chassis' velocity relative to the wind at the step's start; `None` for a car without
    /// [`VehicleSpec::aero`](super::VehicleSpec::aero) or before its first step.
    pub fn drag_force(&self) -> Option<f64> {
        self.drag_force
    }

    /// The chassis body and the car frame's pose in the world; `None` if the body is gone.
    fn chassis_pose(&self, world: &PhysicsWorld) -> Option<(RigidBodyHandle, Pose)> {
        match &self.parts {
            Parts::Cast(p) => Some((p.chassis, *world.bodies.get(p.chassis)?.position())),
            Parts::Joints(p) => {
                let body = world.bodies.get(p.chassis)?;
                Some((p.chassis, joints::car_pose(body, p)))
            }
        }
    }
}
