//! The energy columns of the telemetry (`wheel_power_w`, `battery_power_w`, `soc_percent`,
//! `fuel_rate_gps`, `drag_force_n`) are the engine's own accounting, sampled after every
//! step: their integrals over a run are the energy report's totals, the drag is
//! ½·ρ·Cd·A·v², and `energy.svg` plots them.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::report::figures;
use sim::scenario::RunReport;
use sim::telemetry::{CSV_HEADER, Sample, read_csv, to_csv};
use sim::{CarBuilder, EnergyReport, Simulation, VehicleId, World, WorldConfig};
use vehicle_model::energy::EnergyParams;
use vehicle_model::{Model, RoadLoad};

/// A recorded world of one `model` with its air, road-load losses and energy accounting.
fn car(model: Model) -> (Simulation, VehicleId) {
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let params = model.params::<f64>();
    let builder = CarBuilder::of_model(model)
        .aero(Some(model.aero()))
        .road_load(Some(RoadLoad::default()))
        .energy(Some(EnergyParams::of_engine(&params.engine)), 1.0);
    let (id, _) = sim.add_car(builder).unwrap();
    sim.record("run");
    (sim, id)
}

/// Full throttle for `accelerate` s, then brake intensity 0.2 for `brake` s (torque
/// control, first gear; a brake gentle enough for regenerative braking to take it); the
/// run's report and the car's energy at its end.
fn drive(
    sim: &mut Simulation,
    id: VehicleId,
    accelerate: f64,
    brake: f64,
) -> (RunReport, EnergyReport) {
    let dt = sim.world().dt();
    let d = sim.driver_mut(id).unwrap();
    d.set_gear(1);
    d.set_throttle(1.0);
    for _ in 0..(accelerate / dt).round() as usize {
        sim.step().unwrap();
    }
    let d = sim.driver_mut(id).unwrap();
    d.set_throttle(0.0);
    d.set_brake_intensity(0.2);
    for _ in 0..(brake / dt).round() as usize {
        sim.step().unwrap();
    }
    let energy = sim.energy(id).unwrap().unwrap();
    (sim.report("w").unwrap().unwrap(), energy)
}

/// The samples of the run's one car, read back from its CSV (the file a run writes).
fn samples(report: &RunReport) -> Vec<Sample> {
    let csv = to_csv(&report.results[0].telemetry);
    assert!(csv.starts_with(CSV_HEADER));
    read_csv(csv.as_bytes()).unwrap().remove(0).samples
}

/// Σ f(row)·dt over the rows after the first: each row holds the step that ended at its time.
fn integral(samples: &[Sample], f: impl Fn(&Sample) -> Option<f64>) -> f64 {
    samples
        .windows(2)
        .map(|w| f(&w[1]).unwrap() * (w[1].time - w[0].time))
        .sum()
}

#[test]
fn battery_power_integrates_to_the_battery_energy() {
    let (mut sim, id) = car(Model::TeslaModel3);
    let (report, energy) = drive(&mut sim, id, 8.0, 3.0);
    let s = samples(&report);
    // The meter adds each step's terminal power times the step; the column holds that power
    // for the step ending at its row, so the sum over the rows is the same sum. 1e-6 relative:
    // the CSV rounds each cell to 1e-6 W (1e-8 J a step here) and each time to 1e-6 s, which
    // moves a step of 10 ms by 0.01 %, but only by a rounding that averages out over the run.
    let battery = integral(&s, |s| s.battery_power);
    assert!(
        (battery - energy.battery_energy).abs() <= 1e-6 * energy.battery_energy.abs(),
        "∫ battery power {battery} J, battery energy {} J",
        energy.battery_energy
    );
    let wheels = integral(&s, |s| s.wheel_power);
    assert!((wheels - energy.wheel_energy).abs() <= 1e-6 * energy.wheel_energy.abs());
    // Braking regenerates: the battery takes power back at the end, so the sum covers both
    // signs.
    assert!(s.last().unwrap().battery_power.unwrap() < 0.0);
    // The charge is the meter's, in %; an electric car burns no fuel (no column value).
    let last = s.last().unwrap();
    assert!((last.soc_percent.unwrap() - 100.0 * energy.soc).abs() < 1e-6);
    assert_eq!(s[0].soc_percent, Some(100.0));
    assert!(s.iter().all(|s| s.fuel_rate.is_none()));
}

#[test]
fn fuel_rate_integrates_to_the_fuel_burnt_and_drag_is_the_square_law() {
    let model = Model::BmwX5;
    let (mut sim, id) = car(model);
    let (report, energy) = drive(&mut sim, id, 12.0, 0.0);
    let s = &report.results[0].telemetry[0].samples;
    // g/s over the steps is the fuel burnt (kg): the same sum, in memory (no CSV rounding).
    let grams = integral(s, |s| s.fuel_rate);
    assert!(
        (grams - 1000.0 * energy.fuel).abs() <= 1e-9 * grams,
        "{grams} g, {} kg",
        energy.fuel
    );
    assert!(
        s.iter()
            .all(|s| s.battery_power.is_none() && s.soc_percent.is_none())
    );
    // The drag of each step is ½·ρ·Cd·A·v² of the air speed at the step's start: the previous
    // row's speed. 1 %: the air speed is taken at the body's reference point (on the ground
    // between the axles), whose velocity differs from the rear-axle centre's forward speed
    // by the body's pitch and heave on its springs as it accelerates, and by the sideways
    // slip; over 10 m/s they move the drag by up to 0.8 % here.
    let aero = model.aero::<f64>();
    assert_eq!(s[0].drag_force, None);
    let mut checked = 0;
    for w in s.windows(2) {
        let v = w[0].speed();
        if v > 10.0 {
            let expected = aero.drag_at(v);
            let drag = w[1].drag_force.unwrap();
            assert!(
                (drag - expected).abs() <= 0.01 * expected,
                "at {} s: {drag} N, ½ρCdAv² = {expected} N",
                w[1].time
            );
            checked += 1;
        }
    }
    assert!(checked > 100, "{checked} rows over 10 m/s");
}

#[test]
fn the_energy_plot_is_drawn_for_cars_with_energy_accounting_only() {
    let (mut sim, id) = car(Model::TeslaModel3);
    let (report, _) = drive(&mut sim, id, 1.0, 0.0);
    let energy = figures(&report)
        .into_iter()
        .find(|(name, _)| *name == "energy.svg")
        .expect("energy.svg")
        .1;
    let labels: Vec<&str> = energy.panels.iter().map(|p| p.y_label.as_str()).collect();
    // An electric car: power and charge, no fuel.
    assert_eq!(labels, ["power (kW)", "state of charge (%)"]);
    let mut plain = Simulation::new(World::new(WorldConfig::default()).unwrap());
    plain.add_car(CarBuilder::of_model(Model::BmwX5)).unwrap();
    plain.record("run");
    plain.step().unwrap();
    let report = plain.report("w").unwrap().unwrap();
    assert!(
        figures(&report)
            .iter()
            .all(|(name, _)| *name != "energy.svg")
    );
}
