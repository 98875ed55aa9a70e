//! A coast-down on flat ground, shared by the road-load tests (`tests/road_load.rs`,
//! `tests/epa_road_load.rs`): the car cruises at a speed, then rolls free, and its effective
//! mass turns the measured deceleration into the resisting force.

use sim::{Simulation, VehicleId};

/// How long the car cruises before it coasts (s): the slowest car checked (the Range Rover's
/// 50 kW) reaches 120 km/h in about 15 s and its cruise settles well within this.
const CRUISE_SECONDS: f64 = 25.0;

/// Cruises at `start_kmh` (km/h), then rolls free in torque mode (throttle 0, no brake) until
/// it is below `end_kmh` (km/h); returns the speeds (m/s), one per step from the release.
pub fn coast(sim: &mut Simulation, id: VehicleId, start_kmh: f64, end_kmh: f64) -> Vec<f64> {
    sim.driver_mut(id).unwrap().set_cruising_speed(start_kmh);
    let dt = sim.world().dt();
    for _ in 0..(CRUISE_SECONDS / dt) as usize {
        sim.step().unwrap();
    }
    sim.driver_mut(id).unwrap().set_throttle(0.0);
    let end = end_kmh / 3.6;
    let mut speeds = vec![sim.telemetry(id).unwrap().speed];
    while speeds[speeds.len() - 1] > end {
        sim.step().unwrap();
        speeds.push(sim.telemetry(id).unwrap().speed);
    }
    speeds
}

/// The deceleration (m/s²) where `speeds` (m/s, one per step of `dt` s) first falls below
/// `speed` (m/s): the speed lost over `half_window` s either side, over the window's length.
pub fn deceleration_at(speeds: &[f64], dt: f64, speed: f64, half_window: f64) -> f64 {
    let k = (half_window / dt).round() as usize;
    let i = speeds.iter().position(|&s| s < speed).unwrap();
    assert!(
        i >= k && i + k < speeds.len(),
        "{speed} m/s too near an end"
    );
    (speeds[i - k] - speeds[i + k]) / (2.0 * k as f64 * dt)
}
