//! The road-load loss set (`losses = "road-load"`): a car coasting down from 120 km/h on flat
//! ground slows, at each speed, by the sum of its air drag, its tyres' rolling resistance and
//! its wheels' constant and viscous driveline drag over its effective mass, on both wheel
//! mountings.
#![allow(clippy::unwrap_used)]

#[path = "support/resisting_force.rs"]
mod support;

use sim::{CarBuilder, Mounting, Simulation, VehicleId, VehicleSpec, World, WorldConfig};
use support::resisting_force;
use vehicle_model::{Model, RoadLoad, Wheel};

/// The speed the coast starts from (km/h).
const START_KMH: f64 = 120.0;
/// How long the car cruises before it coasts (s): the TeslaModel3 reaches 120 km/h in about
/// 8 s and its cruise settles well within this.
const CRUISE_SECONDS: f64 = 15.0;
/// The speeds the deceleration is checked at (km/h): the 50, 80 and 110.
const CHECK_KMH: [f64; 3] = [110.0, 80.0, 50.0];
/// Half the window the measured deceleration is averaged over (s): long enough that the
/// suspension's pitch after the lift-off is gone from the difference, short enough that the
/// losses change by under 0.5 % across it.
const HALF_WINDOW: f64 = 1.0;

/// A simulation of one `model` on `mounting` with its road-load set and its air.
fn car(model: Model, mounting: Mounting) -> (Simulation, VehicleId) {
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let builder = CarBuilder::of_model(model)
        .mounting(mounting)
        .aero(Some(model.aero()))
        .road_load(Some(RoadLoad::default()));
    let (id, _) = sim.add_car(builder).unwrap();
    (sim, id)
}

/// The car's mass as the road sees it when it slows down (kg): the chassis and wheels plus
/// each wheel's spin inertia over its radius squared.
fn effective_mass(spec: &VehicleSpec) -> f64 {
    spec.chassis.mass
        + Wheel::ALL
            .into_iter()
            .map(|w| {
                let s = &spec.wheels[w];
                s.mass + s.spin_inertia() / (s.radius * s.radius)
            })
            .sum::<f64>()
}

/// Cruises at [`START_KMH`], then rolls free in torque mode (throttle 0, no brake) until it
/// is below the lowest checked speed; returns the speeds (m/s), one per step.
fn coast(sim: &mut Simulation, id: VehicleId) -> Vec<f64> {
    sim.driver_mut(id).unwrap().set_cruising_speed(START_KMH);
    let dt = sim.world().dt();
    for _ in 0..(CRUISE_SECONDS / dt) as usize {
        sim.step().unwrap();
    }
    sim.driver_mut(id).unwrap().set_throttle(0.0);
    let end = (CHECK_KMH[2] - 5.0) / 3.6;
    let mut speeds = vec![sim.telemetry(id).unwrap().speed];
    while speeds[speeds.len() - 1] > end {
        sim.step().unwrap();
        speeds.push(sim.telemetry(id).unwrap().speed);
    }
    speeds
}

#[test]
fn a_coast_down_slows_by_drag_rolling_resistance_and_driveline_losses_over_the_mass() {
    let model = Model::TeslaModel3;
    for mounting in [Mounting::Cast, Mounting::Joints] {
        let (mut sim, id) = car(model, mounting);
        let speeds = coast(&mut sim, id);
        let dt = sim.world().dt();
        let spec = *sim.world().vehicle(id).unwrap().spec();
        let mass = effective_mass(&spec);
        let k = (HALF_WINDOW / dt).round() as usize;
        for kmh in CHECK_KMH {
            let v = kmh / 3.6;
            let i = speeds.iter().position(|&s| s < v).unwrap();
            assert!(i >= k && i + k < speeds.len(), "{kmh} km/h too near an end");
            let measured = (speeds[i - k] - speeds[i + k]) / (2.0 * k as f64 * dt);
            let expected =
                resisting_force(&spec, &model.aero(), &RoadLoad::default(), speeds[i]) / mass;
            // 2 %: the coast-down tolerance. What the formula leaves out is the
            // tyres' own slip losses (their slip is about 0.1 % while they carry the
            // resisting force) and the loads' shift from the static ones as the car pitches.
            assert!(
                (measured - expected).abs() <= 0.02 * expected,
                "{mounting:?} at {kmh} km/h: {measured:.5} m/s², the losses give {expected:.5}"
            );
        }
    }
}
