//! The road-load loss set (`losses = "road-load"`): a car coasting down from 120 km/h on flat
//! ground slows, at each speed, by the sum of its air drag, its tyres' rolling resistance and
//! its wheels' constant and viscous driveline drag over its effective mass, on both wheel
//! mountings.
#![allow(clippy::unwrap_used)]

#[path = "support/coast_down.rs"]
mod coast_down;
#[path = "support/resisting_force.rs"]
mod support;

use coast_down::{coast, deceleration_at};
use sim::{CarBuilder, Mounting, Simulation, VehicleId, World, WorldConfig};
use support::resisting_force;
use vehicle_model::{Model, RoadLoad};

/// The speed the coast starts from (km/h).
const START_KMH: f64 = 120.0;
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

#[test]
fn a_coast_down_slows_by_drag_rolling_resistance_and_driveline_losses_over_the_mass() {
    let model = Model::TeslaModel3;
    for mounting in [Mounting::Cast, Mounting::Joints] {
        let (mut sim, id) = car(model, mounting);
        let speeds = coast(&mut sim, id, START_KMH, CHECK_KMH[2] - 5.0);
        let dt = sim.world().dt();
        let spec = *sim.world().vehicle(id).unwrap().spec();
        let mass = spec.effective_mass();
        for kmh in CHECK_KMH {
            let v = kmh / 3.6;
            let measured = deceleration_at(&speeds, dt, v, HALF_WINDOW);
            let expected = resisting_force(&spec, &model.aero(), &RoadLoad::default(), v) / mass;
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
