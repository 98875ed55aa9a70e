//! Tyre contact: free and coasting wheels roll at the kinematic rate of the chassis at every
//! step, whatever the car's heading.
//!
//! The first car model (a rapier multibody) got this wrong: rapier solves a multibody
//! contact's friction one world axis at a time, and a wheel pointing away from the world axes
//! chattered between 7.5 and 21 rad/s at 20 km/h. The tyre solve works in each tyre's own
//! frame; these tests keep it honest.

// Helpers outside `#[test]` functions unwrap too: clippy.toml only exempts test bodies.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::common;

use sim::TyreChoice;

use ackermann::Wheel;
use sim::{Simulation, VehicleId, VehiclePlacement, World, WorldConfig};
use vehicle_model::Model;

/// The spin rate (rad/s) at which wheel `w` rolls without slip: the forward speed of its hub,
/// `v − ω·y` (y of the wheel in the car frame, positive left; ω the yaw rate), over its radius.
fn rolling_rate(sim: &Simulation, id: VehicleId, w: Wheel) -> f64 {
    let v = sim.world().vehicle(id).unwrap();
    let s = v.state();
    let spec = &v.spec().wheels[w];
    (s.forward_speed - s.yaw_rate * spec.position.y) / spec.radius
}

/// Steps `sim` for `seconds` and returns the largest relative deviation of `wheels` from their
/// rolling rate over all those steps.
fn worst_deviation(sim: &mut Simulation, id: VehicleId, seconds: f64, wheels: &[Wheel]) -> f64 {
    let steps = (seconds / sim.world().dt()).round() as usize;
    let mut worst = (0.0_f64, 0.0, 0.0, 0.0);
    for _ in 0..steps {
        sim.step().unwrap();
        for &w in wheels {
            let expected = rolling_rate(sim, id, w);
            let got = sim.world().vehicle(id).unwrap().state().wheel_speeds[w];
            let e = (got / expected - 1.0).abs();
            if e > worst.0 {
                worst = (e, got, expected, sim.world().time());
            }
        }
    }
    println!(
        "worst deviation {:.4}: {:.3} rad/s against {:.3} rad/s at {:.2} s",
        worst.0, worst.1, worst.2, worst.3
    );
    worst.0
}

const REAR: [Wheel; 2] = [Wheel::RearRight, Wheel::RearLeft];

/// BmwX5 (front drive) in cruise control at 20 km/h with the steering at 0.2 rad: once the
/// turn is steady (v ≈ 5.1 m/s, yaw rate ≈ −0.37 rad/s, the heading sweeping 1.9 rad in the
/// 5 s measured), each free rear wheel turns at (v − ω·y)/r, about 13.7 rad/s (right, inside)
/// and 15.2 rad/s (left), within 2 % at every step (measured: 0.9 %, as the body rolls in the
/// turn the rigid cylinder's contact moves toward its outer tread edge; the multibody model
/// with one friction sweep gave 65 %).
#[test]
fn bmw_x5_free_rear_wheels_roll_smoothly_in_a_turn() {
    for tyre in [TyreChoice::of_model(Model::BmwX5), common::webots_tyre()] {
        let (mut sim, id) = common::settled_on(Model::BmwX5, 1.0, &tyre);
        let d = sim.driver_mut(id).unwrap();
        d.set_cruising_speed(20.0);
        d.set_steering_angle(0.2);
        common::run(&mut sim, 5.0);
        let e = worst_deviation(&mut sim, id, 5.0, &REAR);
        assert!(e < 0.02, "rear wheel off its rolling rate by {e}");
    }
}

#[test]
/// BmwX5 cruising straight at 20 km/h heading 45° from the world x axis (the worst heading
/// for a world-axis friction solve): the free rear wheels roll at v/r = 5.556/0.374 =
/// 14.85 rad/s within 0.5 % at every step.
fn bmw_x5_free_wheels_roll_smoothly_at_45_degrees() {
    for tyre in [TyreChoice::of_model(Model::BmwX5), common::webots_tyre()] {
        let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
        let placement = VehiclePlacement {
            yaw: std::f64::consts::FRAC_PI_4,
            ..VehiclePlacement::default()
        };
        let (id, _) = sim
            .add_car(
                sim::CarBuilder::new(Model::BmwX5.params())
                    .tyre(tyre.clone())
                    .mounting(crate::MOUNTING)
                    .placement(placement),
            )
            .unwrap();
        common::run(&mut sim, 1.0);
        sim.driver_mut(id).unwrap().set_cruising_speed(20.0);
        common::run(&mut sim, 3.0);
        let e = worst_deviation(&mut sim, id, 3.0, &REAR);
        assert!(e < 0.005, "rear wheel off its rolling rate by {e}");
        let v = sim.telemetry(id).unwrap().speed;
        assert!((v - 20.0 / 3.6).abs() < 0.02, "{v} m/s");
    }
}

/// TeslaModel3 (rear drive) as in the C API's torque test: first gear at throttle 0.15 for
/// 3 s, a 0.25 rad turn for 1 s, straight for 1 s, then neutral. Coasting (no torque on any
/// wheel), all four wheels roll at (v − ω·y)/r within 2 % at every step, and the car
/// decelerates smoothly.
#[test]
fn tesla_model_3_wheels_roll_smoothly_when_coasting() {
    for tyre in [
        TyreChoice::of_model(Model::TeslaModel3),
        common::webots_tyre(),
    ] {
        let (mut sim, id) = common::settled_on(Model::TeslaModel3, 1.0, &tyre);
        let d = sim.driver_mut(id).unwrap();
        d.set_gear(1);
        d.set_throttle(0.15);
        common::run(&mut sim, 3.0);
        sim.driver_mut(id).unwrap().set_steering_angle(0.25);
        common::run(&mut sim, 1.0);
        sim.driver_mut(id).unwrap().set_steering_angle(0.0);
        common::run(&mut sim, 1.0);
        sim.driver_mut(id).unwrap().set_gear(0);
        common::run(&mut sim, 0.5);
        let v0 = sim.telemetry(id).unwrap().speed;
        let e = worst_deviation(&mut sim, id, 2.0, &Wheel::ALL);
        assert!(e < 0.02, "wheel off its rolling rate by {e}");
        let v1 = sim.telemetry(id).unwrap().speed;
        // Coasting against the wheel damping only: slower, but still well under way.
        assert!(v1 < v0 && v1 > 0.8 * v0, "{v0} -> {v1} m/s");
    }
}
