//! The peer: rapier's own [`DynamicRayCastVehicleController`] car, the lightest vehicle model
//! of the Rust ecosystem (one rigid chassis, four ray-cast wheels, no wheel bodies or joints).
//!
//! It is built in this workspace's frame (x forward, y left, z up, flat ground at z = 0) with
//! the same time step as the simulation, so that one of its steps can be set beside one step
//! of a `sim` car: the ratio of the two is what `sim`'s car (on shape-cast wheels or, with
//! `mounting = "joints"`, on rapier joints) costs over the minimum.

use rapier3d::control::{DynamicRayCastVehicleController, WheelTuning};
use rapier3d::na::Unit;
use rapier3d::prelude::{
    ColliderBuilder, IntegrationParameters, PhysicsWorld, QueryFilter, RigidBodyBuilder,
    RigidBodyHandle, Vector,
};

/// Dimensions and tuning of the peer car. [`Default`] is a BMW X5-sized car (the Webots
/// `BmwX5` model's wheelbase, track and tyre radius) at `basicTimeStep` 10 ms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeerParams {
    /// Chassis mass (kg).
    pub mass: f32,
    /// Distance between the axles (m).
    pub wheelbase: f32,
    /// Distance between the left and right wheels of an axle (m).
    pub track: f32,
    /// Tyre radius (m).
    pub wheel_radius: f32,
    /// Suspension length at rest (m).
    pub suspension_rest_length: f32,
    /// Suspension stiffness per unit chassis mass (1/s²): rapier multiplies the spring force
    /// by the chassis mass, so the static compression is `g / (4·stiffness)` on four wheels.
    pub suspension_stiffness: f32,
    /// Suspension damping per unit chassis mass (1/s), in compression and in extension.
    pub suspension_damping: f32,
    /// Physics time step (s).
    pub dt: f32,
}

impl Default for PeerParams {
    /// 2000 kg, wheelbase 2.995 m, track 1.628 m, tyre radius 0.374 m, 0.3 m suspension with
    /// stiffness 40 s⁻² (static compression 9.81/160 = 0.0613 m) and damping 4 s⁻¹, dt 10 ms.
    fn default() -> Self {
        PeerParams {
            mass: 2000.0,
            wheelbase: 2.995,
            track: 1.628,
            wheel_radius: 0.374,
            suspension_rest_length: 0.3,
            suspension_stiffness: 40.0,
            suspension_damping: 4.0,
            dt: 0.01,
        }
    }
}

/// Height of the wheel hard points below the chassis centre (m).
const HARD_POINT_DROP: f32 = 0.2;
/// Chassis box half extents (m): length, width, height.
const CHASSIS_HALF_EXTENTS: [f32; 3] = [2.4, 0.95, 0.4];
/// Gain of the cruise controller (1/s): force = mass · gain · speed error.
const CRUISE_GAIN: f32 = 2.0;
/// Engine force cap per driven wheel (N).
const MAX_ENGINE_FORCE: f32 = 8000.0;
/// Wheel indices, in this workspace's order: front right, front left, rear right, rear left.
const FRONT: [usize; 2] = [0, 1];
const REAR: [usize; 2] = [2, 3];

/// One ray-cast car alone on a flat ground (a half-space at z = 0).
pub struct RayCastCar {
    world: PhysicsWorld,
    vehicle: DynamicRayCastVehicleController,
    chassis: RigidBodyHandle,
    mass: f32,
}

impl RayCastCar {
    /// Builds the car at rest position over the origin, its wheels just touching the ground.
    pub fn new(params: &PeerParams) -> RayCastCar {
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::new(0.0, 0.0, -9.81);
        world.integration_parameters = IntegrationParameters {
            dt: params.dt,
            ..IntegrationParameters::default()
        };
        world.insert_collider(
            ColliderBuilder::halfspace(Unit::new_unchecked(Vector::Z)),
            None,
        );

        // Chassis centre over the middle of the wheelbase, high enough that the suspension
        // starts at its rest length. It never sleeps: rapier keeps adding the wheel impulses
        // to a sleeping chassis' velocity, and a bench must not measure an idle island.
        let half_wheelbase = params.wheelbase / 2.0;
        let height = params.wheel_radius + params.suspension_rest_length + HARD_POINT_DROP;
        let [hx, hy, hz] = CHASSIS_HALF_EXTENTS;
        let (chassis, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(half_wheelbase, 0.0, height))
                .can_sleep(false),
            ColliderBuilder::cuboid(hx, hy, hz).mass(params.mass),
        );

        let tuning = WheelTuning {
            suspension_stiffness: params.suspension_stiffness,
            suspension_compression: params.suspension_damping,
            suspension_damping: params.suspension_damping,
            max_suspension_force: params.mass * 10.0,
            ..WheelTuning::default()
        };
        let mut vehicle = DynamicRayCastVehicleController::new(chassis);
        vehicle.index_up_axis = 2;
        vehicle.index_forward_axis = 0;
        let half_track = params.track / 2.0;
        for (x, y) in [
            (half_wheelbase, -half_track),
            (half_wheelbase, half_track),
            (-half_wheelbase, -half_track),
            (-half_wheelbase, half_track),
        ] {
            // The rolling direction is `contact normal × axle`: with the normal +z, an axle
            // along −y rolls the car towards +x.
            vehicle.add_wheel(
                Vector::new(x, y, -HARD_POINT_DROP),
                -Vector::Z,
                -Vector::Y,
                params.suspension_rest_length,
                params.wheel_radius,
                &tuning,
            );
        }
        RayCastCar {
            world,
            vehicle,
            chassis,
            mass: params.mass,
        }
    }

    /// One control and physics step: `engine_force` (N) on each rear wheel, `steering` (rad,
    /// rapier's sign: positive turns left) on both front wheels, then the wheels' ray casts
    /// and impulses, then one rapier step.
    pub fn step(&mut self, engine_force: f32, steering: f32) {
        let wheels = self.vehicle.wheels_mut();
        for i in FRONT {
            if let Some(w) = wheels.get_mut(i) {
                w.steering = steering;
            }
        }
        for i in REAR {
            if let Some(w) = wheels.get_mut(i) {
                w.engine_force = engine_force;
            }
        }
        let dt = self.world.integration_parameters.dt;
        let world = &mut self.world;
        let queries = world.broad_phase.as_query_pipeline_mut(
            world.narrow_phase.query_dispatcher(),
            &mut world.bodies,
            &mut world.colliders,
            QueryFilter::exclude_dynamic(),
        );
        self.vehicle.update_vehicle(dt, queries);
        self.world.step();
    }

    /// The engine force per rear wheel (N) of a proportional cruise controller holding
    /// `target_speed` (m/s): `mass · 2 s⁻¹ · error / 2 wheels`, capped at ±8000 N.
    pub fn cruise_force(&self, target_speed: f32) -> f32 {
        let error = target_speed - self.forward_speed();
        (self.mass * CRUISE_GAIN * error / 2.0).clamp(-MAX_ENGINE_FORCE, MAX_ENGINE_FORCE)
    }

    /// Chassis centre position (m) in the world frame.
    pub fn position(&self) -> [f32; 3] {
        self.world
            .bodies
            .get(self.chassis)
            .map_or([0.0; 3], |b| b.translation().to_array())
    }

    /// Signed speed along the chassis' forward axis (m/s), as rapier computes it.
    pub fn forward_speed(&self) -> f32 {
        self.vehicle.current_vehicle_speed
    }

    /// Yaw rate of the chassis about +z (rad/s, counter-clockwise positive).
    pub fn yaw_rate(&self) -> f32 {
        self.world
            .bodies
            .get(self.chassis)
            .map_or(0.0, |b| b.angvel().z)
    }

    /// Number of wheels whose ray touched the ground in the last step.
    pub fn wheels_in_contact(&self) -> usize {
        self.vehicle
            .wheels()
            .iter()
            .filter(|w| w.raycast_info().is_in_contact)
            .count()
    }

    /// Suspension length of each wheel in the last step (m), in wheel order FR, FL, RR, RL.
    pub fn suspension_lengths(&self) -> [f32; 4] {
        let mut out = [0.0; 4];
        for (o, w) in out.iter_mut().zip(self.vehicle.wheels()) {
            *o = w.raycast_info().suspension_length;
        }
        out
    }

    /// Suspension force of each wheel in the last step (N), in wheel order FR, FL, RR, RL.
    pub fn suspension_forces(&self) -> [f32; 4] {
        let mut out = [0.0; 4];
        for (o, w) in out.iter_mut().zip(self.vehicle.wheels()) {
            *o = w.wheel_suspension_force;
        }
        out
    }

    /// True if the chassis is asleep (a bench must never measure a sleeping island).
    pub fn is_sleeping(&self) -> bool {
        self.world
            .bodies
            .get(self.chassis)
            .is_none_or(|b| b.is_sleeping())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settles_at_the_static_suspension_compression() {
        let p = PeerParams::default();
        let mut car = RayCastCar::new(&p);
        for _ in 0..300 {
            car.step(0.0, 0.0);
        }
        assert_eq!(car.wheels_in_contact(), 4);
        // Each spring carries a quarter of the weight: 2000·9.81/4 = 4905 N.
        for f in car.suspension_forces() {
            assert!((f - 4905.0).abs() < 1.0, "suspension force {f}");
        }
        // The springs alone would settle at 4·k·Δ·m = m·g → Δ = 9.81/(4·40) = 0.0613 m. rapier
        // applies the wheel impulses outside its step, so the damper sees a residual sinking
        // speed of about 0.0368 m/s (= 0.375·g·dt) and takes 4·0.0368 = 0.147 m/s² of the
        // load: Δ = (9.81/4 − 0.147)/40 = 0.0576 m, suspension length 0.2424 m.
        for l in car.suspension_lengths() {
            assert!((l - 0.2424).abs() < 1e-3, "suspension length {l}");
        }
        // Chassis centre: ground + radius + suspension + hard-point drop
        // = 0.374 + 0.2424 + 0.2 = 0.8164 m.
        let [x, y, z] = car.position();
        assert!((z - 0.8164).abs() < 1e-3, "chassis height {z}");
        assert!(
            x.abs() < 1.6 && y.abs() < 1e-3,
            "no drift at rest: {x}, {y}"
        );
    }

    #[test]
    fn cruises_forward_and_turns_left_with_positive_steering() {
        let mut car = RayCastCar::new(&PeerParams::default());
        for _ in 0..500 {
            let f = car.cruise_force(10.0);
            car.step(f, 0.0);
        }
        // 5 s with a 2 s⁻¹ proportional controller: within a few % of 10 m/s, moving +x.
        let v = car.forward_speed();
        assert!((v - 10.0).abs() < 0.5, "speed {v}");
        assert!(car.position()[0] > 20.0);
        assert!(!car.is_sleeping());
        for _ in 0..100 {
            let f = car.cruise_force(10.0);
            car.step(f, 0.1);
        }
        // Steady turn: yaw rate ≈ v·tan(δ)/L = 10·0.1003/2.995 = 0.335 rad/s, counter-clockwise
        // (left); tyre slip makes it somewhat smaller.
        let r = car.yaw_rate();
        assert!(r > 0.15 && r < 0.4, "yaw rate {r}");
    }
}
