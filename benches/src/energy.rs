//! The energy benchmark's car (issue #36), shared by the criterion bench (`benches/energy.rs`)
//! and the instruction counts (`benches/callgrind/`): a TeslaModel3 at half throttle in first
//! gear as Webots has it, with the road-load losses and its air, and with those and the
//! energy accounting.

use sim::{CarBuilder, SimError, Simulation, World, WorldConfig};
use vehicle_model::energy::EnergyParams;
use vehicle_model::{Model, RoadLoad};

/// What a case adds to Webots' car.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EnergyCase {
    /// Webots' car: `wheelsDampingConstant`, no air, no accounting.
    Webots,
    /// With the road-load losses and the air (`CarBuilder::road_load`, `CarBuilder::aero`).
    RoadLoad,
    /// With those and the energy accounting (`CarBuilder::energy`, the pack at 0.9).
    Energy,
}

impl EnergyCase {
    /// Every case, Webots' first.
    pub const ALL: [EnergyCase; 3] = [EnergyCase::Webots, EnergyCase::RoadLoad, EnergyCase::Energy];

    /// The case's name in the benchmarks' ids.
    pub fn name(self) -> &'static str {
        match self {
            EnergyCase::Webots => "webots",
            EnergyCase::RoadLoad => "road_load_and_air",
            EnergyCase::Energy => "road_load_air_and_energy",
        }
    }
}

/// Steps (10 ms each) the car is driven before it is measured: 2 s.
pub const SETTLE_STEPS: usize = 200;

/// The car of `case` at half throttle in first gear, driven for `settle` steps.
///
/// # Errors
/// What `sim` rejects (never for these constants).
pub fn energy_scene(case: EnergyCase, settle: usize) -> Result<Simulation, SimError> {
    let model = Model::TeslaModel3;
    let mut sim = Simulation::new(World::new(WorldConfig::default())?);
    let mut car = CarBuilder::of_model(model);
    if case != EnergyCase::Webots {
        car = car
            .aero(Some(model.aero()))
            .road_load(Some(RoadLoad::default()));
    }
    if case == EnergyCase::Energy {
        let engine = model.params::<f64>().engine;
        car = car.energy(Some(EnergyParams::of_engine(&engine)), 0.9);
    }
    let (id, _) = sim.add_car(car)?;
    let d = sim.driver_mut(id)?;
    d.set_gear(1);
    d.set_throttle(0.5);
    for _ in 0..settle {
        sim.step()?;
    }
    Ok(sim)
}
