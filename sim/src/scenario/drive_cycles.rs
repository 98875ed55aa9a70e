//! `ftp75`, `hwfet` and `wltc`: the car follows a regulatory drive cycle's speed trace with the
//! built-in [`CycleDriver`](super::CycleDriver) (torque control, automatic gearbox), and the
//! run reports how closely it tracked the trace and what it consumed per km
//! ([`CycleFollower`], which the programme's `cycle` command drives too).
//!
//! The scenario turns the car's energy accounting on (`[vehicle] energy = true`, battery
//! full) when the world has not, and says so; the losses stay as the world sets them, so a
//! car on Webots' `wheelsDampingConstant` (the default) consumes what that damping costs, far
//! more than a real car (see `losses = "road-load"`).

use crate::world_file::{CarDescription, WorldDescription};

use super::car::CarRig;
use super::car_programmes::Progress;
use super::cycle_follow::{CycleFollower, account_energy};
use super::cycle_trace::Cycle;
use super::{Scenario, ScenarioError, ScenarioResult, limit};

/// The cycle a scenario drives, if it is a drive cycle.
pub(super) fn cycle_of(scenario: Scenario) -> Option<Cycle> {
    match scenario {
        Scenario::Ftp75 => Some(Cycle::Ftp75),
        Scenario::Hwfet => Some(Cycle::Hwfet),
        Scenario::Wltc => Some(Cycle::Wltc),
        _ => None,
    }
}

/// Drives `cycle` with `car` on `world` as `scenario`.
pub(super) fn run(
    world: &WorldDescription,
    car: &CarDescription,
    scenario: Scenario,
    cycle: Cycle,
    progress: Progress<'_>,
) -> Result<ScenarioResult, ScenarioError> {
    let mut world = world.clone();
    let notes = account_energy(&mut world.cars, &car.name);
    let trace = cycle.trace();
    let duration = trace.duration();
    let mut rig = CarRig::new(&world, car, limit(scenario, &world), duration)?;
    for n in notes {
        rig.note(n);
    }
    let (sim, id) = rig.simulation_mut();
    let (mut follower, note) = CycleFollower::engage(sim, id, trace, cycle.band())?;
    if let Some(n) = note {
        rig.note(n);
    }
    while rig.running() && !follower.finished() {
        let (sim, id) = rig.simulation_mut();
        follower.drive(sim, id)?;
        rig.step(progress)?;
        let (sim, id) = rig.simulation();
        follower.measure(sim, id)?;
    }
    let (sim, id) = rig.simulation();
    let metrics = follower.metrics(sim, id, car.params.engine.engine_type)?;
    let finished = follower.finished();
    let mut result = rig.finish(scenario, metrics);
    if !finished {
        result.unfinished = Some(format!(
            "the run ended at {:.1} s, before the {duration} s of {cycle}",
            result.sim_seconds
        ));
    }
    Ok(result)
}
