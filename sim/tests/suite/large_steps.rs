//! Large steps: at basicTimeStep 100 ms every shipped car stands at its ride height, drives and
//! stops. (On the cast car the suspension is an implicit spring-damper and the tyre a
//! linearised implicit law, so the step size changes the accuracy, not the stability; a world
//! with a car on joints splits each step into rapier steps of at most 20 ms.)

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::common;

use sim::TyreChoice;

use sim::{Simulation, VehiclePlacement, World, WorldConfig};
use vehicle_model::Model;

/// `model` on its default tyres with a `dt_ms` step, settled for 3 s; returns the simulation,
/// the car and its ride height (m, the car origin above the ground).
fn settled(model: Model, dt_ms: u32) -> (Simulation, sim::VehicleId, f64) {
    let world = World::new(WorldConfig {
        basic_time_step_ms: dt_ms,
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let (id, _) = sim
        .add_car(
            sim::CarBuilder::new(model.params())
                .tyre(TyreChoice::of_model(model).clone())
                .mounting(crate::MOUNTING)
                .placement(VehiclePlacement::default()),
        )
        .unwrap();
    common::run(&mut sim, 3.0);
    let z = sim.telemetry(id).unwrap().state.position.z;
    (sim, id, z)
}

#[test]
fn every_model_stands_drives_and_stops_at_100_ms() {
    for model in Model::ALL {
        let (_, _, z10) = settled(model, 10);
        let (mut sim, id, z100) = settled(model, 100);
        // The same static deflection: the springs hold the same weight.
        assert!((z100 - z10).abs() < 0.01, "{model:?}: {z100} m vs {z10} m");
        sim.driver_mut(id).unwrap().set_cruising_speed(50.0);
        common::run(&mut sim, 20.0);
        let v = sim.telemetry(id).unwrap().speed;
        assert!(v > 10.0, "{model:?} at {v} m/s");
        let d = sim.driver_mut(id).unwrap();
        d.set_throttle(0.0);
        d.set_brake_intensity(1.0);
        let stopped = common::run_until(&mut sim, 20.0, |s| {
            s.telemetry(id).unwrap().speed.abs() < 0.01
        });
        let s = sim.telemetry(id).unwrap().state;
        assert!(stopped.is_some(), "{model:?} did not stop: {s:?}");
        assert!(
            (s.position.z - z100).abs() < 0.05,
            "{model:?} at {} m after the stop (ride height {z100} m)",
            s.position.z
        );
    }
}
