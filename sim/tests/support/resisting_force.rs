//! The analytic road load that the coast-down (`tests/road_load.rs`) and the top speed
//! (`tests/drive_cycles.rs`) are checked against, in one place.

use sim::VehicleSpec;
use vehicle_model::{Aero, RoadLoad, TyreModel, Wheel};

/// The force slowing the car at `speed` (m/s) on flat ground through still air (N): the drag
/// plus each wheel's rolling resistance under its static load and its driveline drag: what a coast-down
/// (`tests/road_load.rs`) and the top speed (`tests/drive_cycles.rs`) are checked against.
pub fn resisting_force(
    spec: &VehicleSpec,
    aero: &Aero<f64>,
    losses: &RoadLoad<f64>,
    speed: f64,
) -> f64 {
    let loads = spec.static_wheel_loads();
    let rolling = |w: Wheel| match spec.tyres.of(w) {
        TyreModel::MagicFormula(t) => {
            let r = spec.wheels[w].radius;
            t.rolling_resistance_torque(loads[w], r) / r
        }
        TyreModel::Webots(_) => 0.0,
    };
    aero.drag_at(speed)
        + Wheel::ALL
            .into_iter()
            .map(|w| rolling(w) + losses.wheel_force(spec.wheels[w].radius, speed))
            .sum::<f64>()
}
