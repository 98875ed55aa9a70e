//! `ftp75`, `hwfet` and `wltc`: the car follows a regulatory drive cycle's speed trace with the
//! built-in [`CycleDriver`] (torque control, automatic gearbox), and the run reports how
//! closely it tracked the trace and what it consumed per km.
//!
//! The scenario turns the car's energy accounting on (`[vehicle] energy = true`, battery
//! full) when the world has not, and says so; the losses stay as the world sets them, so a
//! car on Webots' `wheelsDampingConstant` (the default) consumes what that damping costs, far
//! more than a real car (see `losses = "road-load"`).

use vehicle_model::energy::EnergyParams;
use vehicle_model::{AutoShiftParams, EngineType};

use crate::simulation::EnergyReport;
use crate::world_file::{CarDescription, WorldDescription};

use super::car::{CarRig, KMH};
use super::car_programmes::{Progress, expected_deceleration};
use super::cycle_driver::{BandMeter, CycleDriver, PedalAuthority};
use super::cycle_trace::Cycle;
use super::{Metric, Scenario, ScenarioError, ScenarioResult, limit};

/// Density of petrol (kg/l): 0.745, the middle of EN 228's 0.720–0.775 kg/l at 15 °C.
pub const FUEL_DENSITY: f64 = 0.745;
/// J per Wh.
const J_PER_WH: f64 = 3600.0;

/// The cycle a scenario drives, if it is a drive cycle.
pub(super) fn cycle_of(scenario: Scenario) -> Option<Cycle> {
    match scenario {
        Scenario::Ftp75 => Some(Cycle::Ftp75),
        Scenario::Hwfet => Some(Cycle::Hwfet),
        Scenario::Wltc => Some(Cycle::Wltc),
        _ => None,
    }
}

/// The scenario of `cycle`.
fn scenario_of(cycle: Cycle) -> Scenario {
    match cycle {
        Cycle::Ftp75 => Scenario::Ftp75,
        Cycle::Hwfet => Scenario::Hwfet,
        Cycle::Wltc => Scenario::Wltc,
    }
}

/// Drives `cycle` with `car` on `world`.
pub(super) fn run(
    world: &WorldDescription,
    car: &CarDescription,
    cycle: Cycle,
    progress: Progress<'_>,
) -> Result<ScenarioResult, ScenarioError> {
    let scenario = scenario_of(cycle);
    let mut world = world.clone();
    let mut notes = Vec::new();
    if let Some(c) = world.cars.iter_mut().find(|c| c.name == car.name)
        && c.energy.is_none()
    {
        c.energy = Some(EnergyParams::of_engine(&c.params.engine));
        notes.push(format!(
            "{}: energy accounting turned on for the drive cycle (the defaults of its engine \
             type, battery full)",
            car.name
        ));
    }
    if car.road_load.is_none() {
        notes.push(format!(
            "{}: Webots' wheelsDampingConstant is its only driveline loss: the consumption \
             includes what that damping costs (losses = \"road-load\" for a real car's)",
            car.name
        ));
    }
    let trace = cycle.trace();
    let duration = trace.duration();
    let mut rig = CarRig::new(&world, car, limit(scenario, &world), duration)?;
    for n in notes {
        rig.note(n);
    }
    let authority = PedalAuthority {
        full_throttle: 100.0 / KMH / car.params.time_0_to_100,
        full_brake: expected_deceleration(&rig)?,
    };
    let mut driver = CycleDriver::new(trace, authority)?;
    let auto = AutoShiftParams::for_engine(rig.driver()?.powertrain().engine());
    if let Err(e) = rig.driver_mut()?.set_automatic_gearbox(Some(auto)) {
        rig.note(format!("automatic gearbox refused ({e}): first gear only"));
    }
    rig.driver_mut()?.set_gear(1);
    let start = rig.energy()?.unwrap_or_default();
    let mut band = BandMeter::default();
    let dt = rig.time_step();
    while rig.running() && rig.time() < duration - 1e-9 {
        let (t, v) = (rig.time(), rig.speed());
        let pedals = driver.pedals(t, v, dt);
        let d = rig.driver_mut()?;
        d.set_throttle(pedals.throttle);
        d.set_brake_intensity(pedals.brake);
        rig.step(progress)?;
        band.sample(
            driver.trace(),
            rig.time(),
            rig.speed(),
            dt,
            cycle.time_tolerance(),
            cycle.speed_tolerance(),
        );
    }
    let end = rig.energy()?.unwrap_or_default();
    let finished = rig.time() >= duration - 1e-9;
    let metrics = metrics(cycle, car, &band, &start, &end, driver.trace().distance());
    let mut result = rig.finish(scenario, metrics);
    if !finished {
        result.unfinished = Some(format!(
            "the run ended at {:.1} s, before the {duration} s of {cycle}",
            result.sim_seconds
        ));
    }
    Ok(result)
}

/// The cycle's metrics from the tracking and the energy at its start and end.
fn metrics(
    cycle: Cycle,
    car: &CarDescription,
    band: &BandMeter,
    start: &EnergyReport,
    end: &EnergyReport,
    trace_distance: f64,
) -> Vec<Metric> {
    let distance = end.distance - start.distance;
    let km = distance / 1000.0;
    let per_km = |x: f64| if km > 0.0 { Some(x / km) } else { None };
    let engine = car.params.engine.engine_type;
    let mut m = vec![
        Metric::number("distance_km", "distance driven", "km", km),
        Metric::number(
            "trace_distance_km",
            "distance of the trace",
            "km",
            trace_distance / 1000.0,
        ),
        Metric::number(
            "time_outside_band_s",
            match cycle {
                Cycle::Ftp75 | Cycle::Hwfet => "time outside the tolerance band (±2 mph, ±1 s)",
                Cycle::Wltc => "time outside the tolerance band (±2 km/h, ±1 s)",
            },
            "s",
            band.outside,
        ),
        Metric::number(
            "longest_excursion_s",
            "longest excursion outside the band",
            "s",
            band.longest,
        ),
        Metric::number(
            "max_speed_error_kmh",
            "largest speed error",
            "km/h",
            band.max_error * KMH,
        ),
    ];
    if engine != EngineType::Combustion {
        let battery = (end.battery_energy - start.battery_energy) / J_PER_WH;
        m.push(Metric::maybe(
            "battery_wh_per_km",
            "battery energy per km (net of regeneration)",
            "Wh/km",
            per_km(battery),
        ));
        m.push(Metric::number(
            "battery_wh",
            "energy the battery gave at its terminals (net)",
            "Wh",
            battery,
        ));
        m.push(Metric::number(
            "motor_loss_wh",
            "electric machine losses",
            "Wh",
            (end.motor_loss - start.motor_loss) / J_PER_WH,
        ));
        m.push(Metric::number(
            "regenerated_wh",
            "energy regenerative braking took back at the wheels",
            "Wh",
            (end.regenerated - start.regenerated) / J_PER_WH,
        ));
        m.push(Metric::number(
            "soc_start",
            "state of charge at the start",
            "",
            start.soc,
        ));
        m.push(Metric::number(
            "soc_end",
            "state of charge at the end",
            "",
            end.soc,
        ));
    }
    if engine != EngineType::Electric {
        let litres = (end.fuel - start.fuel) / FUEL_DENSITY;
        m.push(Metric::maybe(
            "fuel_l_per_100km",
            "fuel per 100 km (petrol, 0.745 kg/l)",
            "l/100 km",
            per_km(100.0 * litres),
        ));
    }
    let wheel = (end.wheel_energy - start.wheel_energy) / J_PER_WH;
    m.push(Metric::number(
        "wheel_wh",
        "energy at the driven wheels",
        "Wh",
        wheel,
    ));
    m.push(Metric::number(
        "wheel_wh_per_km",
        "energy at the driven wheels per km",
        "Wh/km",
        per_km(wheel).unwrap_or(0.0),
    ));
    m
}
