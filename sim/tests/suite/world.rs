//! Building worlds and cars: parameters, errors, obstacles, ramps and kinematic wipers.

// Helpers outside `#[test]` functions unwrap too: clippy.toml only exempts test bodies.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::common;

use ackermann::Wheel;
use sim::nalgebra::{Point2, Point3, Vector3};
use sim::{
    Obstacle, ParamError, Rule, SimError, Simulation, VehicleId, VehiclePlacement, World,
    WorldConfig,
};
use vehicle_model::{Driver, Model, WiperCommand};

#[test]
fn bmw_x5_spec_from_its_parameters() {
    let spec = common::spec(&Model::BmwX5.params());
    // Wheel centres at (L, ∓Tf/2, 0) and (0, ∓Tr/2, 0): L = 2.995, Tf = Tr = 1.628.
    let fr = spec.wheels[Wheel::FrontRight];
    assert_eq!(fr.position, Point3::new(2.995, -0.814, 0.0));
    assert_eq!(
        spec.wheels[Wheel::RearLeft].position,
        Point3::new(0.0, 0.814, 0.0)
    );
    assert_eq!((fr.radius, fr.width, fr.mass), (0.374, 0.25, 30.0));
    assert_eq!(spec.chassis.mass, 2000.0);
    assert_eq!(spec.chassis.center_of_mass, Point3::new(1.2975, 0.0, 0.1));
    assert_eq!(
        spec.chassis.inertia,
        [1125.07, 4473.54, 4346.1, 0.0, 846.89, 0.0]
    );
    assert_eq!(spec.front_suspension.stiffness, 100_000.0);
    assert_eq!(spec.wheels_damping, 2.0);
    assert_eq!(spec.wiper_range, Some([0.0, 1.6]));
    // Box: from −r to L + r, the track wide, 0.75·track high.
    assert_eq!(
        spec.chassis.box_half_extents[0],
        (2.995 + 0.374 + 0.374) / 2.0
    );
}

#[test]
fn invalid_parameters_name_the_field() {
    let mut spec = common::spec(&Model::Car.params());
    spec.wheels[Wheel::RearLeft].radius = -0.3;
    let mut world = World::new(WorldConfig::default()).unwrap();
    let err = world
        .add_vehicle(spec, VehiclePlacement::default())
        .unwrap_err();
    assert_eq!(
        err,
        SimError::Param(ParamError {
            field: "tireRadius",
            value: -0.3,
            rule: Rule::Within(proto_geom::plausible::LENGTH)
        })
    );
    assert_eq!(
        err.to_string(),
        "invalid tireRadius = -0.3: must be within 0.001 to 1000 m"
    );
    assert!(world.vehicles().is_empty());
    let mut spec = common::spec(&Model::Car.params());
    spec.chassis.inertia = [1.0, 1.0, 1.0, 2.0, 0.0, 0.0];
    let err = world.add_vehicle(spec, VehiclePlacement::default());
    assert!(matches!(
        err,
        Err(SimError::Param(ParamError {
            field: "physics.inertiaMatrix",
            ..
        }))
    ));
    let cfg = WorldConfig {
        gravity: Vector3::new(0.0, 0.0, f64::NAN),
        ..WorldConfig::default()
    };
    assert!(matches!(
        World::new(cfg),
        Err(SimError::Param(ParamError {
            field: "gravity",
            ..
        }))
    ));
}

#[test]
fn unknown_handles_are_errors() {
    let mut a = World::new(WorldConfig::default()).unwrap();
    let b_id = {
        let mut b = World::new(WorldConfig::default()).unwrap();
        b.add_vehicle(
            common::spec(&Model::Car.params()),
            VehiclePlacement::default(),
        )
        .unwrap()
    };
    assert_eq!(a.vehicle(b_id).unwrap_err(), SimError::UnknownVehicle(0));
    assert!(a.vehicle_mut(b_id).is_err());
    let sim = Simulation::new(a);
    assert!(sim.telemetry(b_id).is_err());
}

fn world_with(obstacles: Vec<Obstacle>) -> (Simulation, VehicleId) {
    let world = World::new(WorldConfig {
        obstacles,
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let (id, _) = sim
        .add_car(
            sim::CarBuilder::new(Model::ToyotaPrius.params())
                .tyre(sim::TyreChoice::default().clone())
                .mounting(crate::MOUNTING)
                .placement(VehiclePlacement::default()),
        )
        .unwrap();
    common::run(&mut sim, 1.0);
    (sim, id)
}

#[test]
fn a_wall_stops_the_car() {
    // A 1 m thick wall whose near face is at x = 12 m; the Prius' nose (box to L + r = 3.117 m
    // ahead of its origin) meets it when the origin reaches x ≈ 8.9 m.
    let wall = Obstacle::Box {
        center: Point3::new(12.5, 0.0, 1.0),
        half_extents: Vector3::new(0.5, 5.0, 1.0),
        yaw: 0.0,
        friction: None,
        radar_cross_section: 0.0,
    };
    let (mut sim, id) = world_with(vec![wall]);
    sim.driver_mut(id).unwrap().set_cruising_speed(20.0);
    common::run(&mut sim, 5.0);
    let t = sim.telemetry(id).unwrap();
    let x = t.state.position.x;
    assert!(x < 12.0 - 2.8 && x > 7.0, "{t:?}");
    // Without the wall it would be ~25 m further.
    assert!(t.state.position.iter().all(|v| v.is_finite()));
}

#[test]
fn the_car_climbs_a_ramp() {
    // A 10 m ramp rising 1 m, starting 5 m ahead.
    let ramp = Obstacle::Ramp {
        start: Point2::new(5.0, 0.0),
        yaw: 0.0,
        length: 10.0,
        width: 4.0,
        height: 1.0,
        friction: None,
        radar_cross_section: 0.0,
    };
    let (mut sim, id) = world_with(vec![ramp]);
    let z0 = sim.telemetry(id).unwrap().state.position.z;
    sim.driver_mut(id).unwrap().set_cruising_speed(10.0);
    let climbed = common::run_until(&mut sim, 8.0, |s| {
        s.telemetry(id).unwrap().state.position.z > z0 + 0.4
    });
    assert!(climbed.is_some());
    // Pitched nose up on the 5.7° slope (atan 0.1): pitch about −0.1 rad (nose up is
    // negative about +y).
    let pitch = sim.telemetry(id).unwrap().state.roll_pitch_yaw.pitch;
    assert!(pitch < -0.05, "{pitch}");
}

#[test]
fn wipers_follow_the_position_controller_at_the_commanded_velocity() {
    let params = Model::BmwX5.params();
    let (driver, _) = Driver::new(params.clone(), 10);
    let mut commands = *driver.commands();
    commands.cockpit.wipers = Some(WiperCommand {
        target: 1.6,
        velocity: 2.0,
    });
    let mut world = World::new(WorldConfig::default()).unwrap();
    let id = world
        .add_vehicle(common::spec(&params), VehiclePlacement::default())
        .unwrap();
    world.vehicle_mut(id).unwrap().set_commands(&commands);
    for _ in 0..50 {
        world.step().unwrap();
    }
    // min(10·error, 2 rad/s): 2 rad/s while the error exceeds 0.2 rad, so 50 × 0.02 rad.
    let wiper = world.vehicle(id).unwrap().state().wiper.unwrap();
    assert!((wiper - 1.0).abs() < 1e-9, "{wiper}");
    for _ in 0..200 {
        world.step().unwrap();
    }
    let wiper = world.vehicle(id).unwrap().state().wiper.unwrap();
    assert!((wiper - 1.6).abs() < 1e-6, "{wiper}");
    assert_eq!(world.vehicle(id).unwrap().sensors(2.5).wiper, Some(wiper));
}

#[test]
fn steering_follows_the_webots_position_controller() {
    let params = Model::BmwX5.params();
    let (driver, _) = Driver::new(params.clone(), 10);
    let mut commands = *driver.commands();
    commands.steering = ackermann::WheelAngles::new(0.3, 0.25);
    let mut world = World::new(WorldConfig::default()).unwrap();
    let id = world
        .add_vehicle(common::spec(&params), VehiclePlacement::default())
        .unwrap();
    for _ in 0..50 {
        world.step().unwrap();
    }
    world.vehicle_mut(id).unwrap().set_commands(&commands);
    // The first step moves at min(10·0.3, 10) = 3 rad/s: 0.03 rad.
    world.step().unwrap();
    let s = world.vehicle(id).unwrap().state().steering;
    assert!((s.right - 0.03).abs() < 0.003, "{s:?}");
    for _ in 0..100 {
        world.step().unwrap();
    }
    // Then an exponential approach with time constant 1/10 s: within 1e-3 after 1 s.
    let s = world.vehicle(id).unwrap().state().steering;
    assert!(
        (s.right - 0.3).abs() < 2e-3 && (s.left - 0.25).abs() < 2e-3,
        "{s:?}"
    );
}

#[test]
fn a_wheel_torque_in_the_air_turns_the_chassis_the_other_way() {
    let params = Model::BmwX5.params();
    let (driver, _) = Driver::new(params.clone(), 10);
    let mut commands = *driver.commands();
    commands.drive = ackermann::PerWheel::splat(vehicle_model::WheelDrive::Torque(100.0));
    commands.brake_torque = ackermann::PerWheel::splat(0.0);
    let mut world = World::new(WorldConfig::default()).unwrap();
    let placement = VehiclePlacement {
        z: Some(5.0),
        ..VehiclePlacement::default()
    };
    let spec = common::spec(&params);
    let id = world.add_vehicle(spec, placement).unwrap();
    world.vehicle_mut(id).unwrap().set_commands(&commands);
    for _ in 0..10 {
        world.step().unwrap();
    }
    let s = world.vehicle(id).unwrap().state();
    // Free fall: 100 N·m on each I = 2.098 kg·m² wheel against its damping c = 2 N·m·s/rad
    // spins it up to (τ/c)·(1 − e^(−c·t/I)) = 4.545 rad/s in 0.1 s ...
    let i: f64 = 0.5 * 30.0 * 0.374 * 0.374;
    let spin = 100.0 / 2.0 * (1.0 - (-2.0 * 0.1 / i).exp());
    for w in Wheel::ALL {
        assert!(
            (s.wheel_speeds[w] / spin - 1.0).abs() < 0.01,
            "{:?} vs {spin}",
            s.wheel_speeds
        );
    }
    // ... and the opposite torques, 4 × 100 N·m about −y less the damping, pitch the chassis
    // nose up (negative): after step k the pitch rate is about −400·k·dt/Iyy, so the pitch
    // after 10 steps is about −400·55·dt²/Iyy = −2.2/Iyy (4 % less with the damping), with Iyy
    // about 4500 to 5000 kg·m² for the body and wheels.
    let pitch = s.roll_pitch_yaw.pitch;
    assert!(pitch < -2.2 / 5200.0 && pitch > -2.2 / 4400.0, "{pitch}");
}
