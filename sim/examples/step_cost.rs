//! Wall-clock cost of one `basicTimeStep` (10 ms) of BmwX5 cars driven through the Webots
//! driver library, at rest, at 50 km/h and at 100 km/h, for 1 and 8 cars.
//!
//! `cargo run --release -p sim --example step_cost [-- STEPS]`
//!
//! Each case settles the cars at their speed (grippy ground, μ = 1.5), then times `STEPS`
//! steps (default 400) in blocks of 50 and prints the fastest block's mean per step, which is
//! the least disturbed by other processes on a shared machine, plus the rapier steps taken.

use std::time::Instant;

use sim::{Simulation, VehicleId, VehiclePlacement, World, WorldConfig};
use vehicle_model::Model;

/// Steps per timed block.
const BLOCK: usize = 50;

fn scene(cars: usize, kmh: f64) -> Result<(Simulation, Vec<VehicleId>), sim::SimError> {
    let world = World::new(WorldConfig {
        ground_friction: 1.5,
        ..WorldConfig::default()
    })?;
    let mut sim = Simulation::new(world);
    let mut ids = Vec::new();
    for i in 0..cars {
        let placement = VehiclePlacement {
            y: 20.0 * i as f64,
            ..VehiclePlacement::default()
        };
        let (id, _) =
            sim.add_car(sim::CarBuilder::new(Model::BmwX5.params()).placement(placement))?;
        ids.push(id);
    }
    for _ in 0..100 {
        sim.step()?;
    }
    for id in &ids {
        sim.driver_mut(*id)?.set_cruising_speed(kmh);
    }
    // Ramp (7 s to 100 km/h) plus settling.
    for _ in 0..(100.0 + 7.0 * kmh) as usize {
        sim.step()?;
    }
    Ok((sim, ids))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let steps: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse())
        .transpose()?
        .unwrap_or(400);
    println!("cars  speed(km/h)  measured(km/h)  rapier steps  us/step  us/step/car");
    for cars in [1, 8] {
        for kmh in [0.0, 50.0, 100.0] {
            let (mut sim, ids) = scene(cars, kmh)?;
            let mut best = f64::INFINITY;
            let mut substeps = 0;
            for _ in 0..steps.div_ceil(BLOCK) {
                let t0 = Instant::now();
                for _ in 0..BLOCK {
                    sim.step()?;
                    substeps += sim.world().last_substeps();
                }
                best = best.min(t0.elapsed().as_secs_f64() / BLOCK as f64);
            }
            let v = sim.telemetry(ids[0])?.speed * 3.6;
            let us = best * 1e6;
            println!(
                "{cars:>4}  {kmh:>11.0}  {v:>14.2}  {:>12.2}  {us:>7.1}  {:>11.1}",
                substeps as f64 / (steps.div_ceil(BLOCK) * BLOCK) as f64,
                us / cars as f64
            );
        }
    }
    Ok(())
}
