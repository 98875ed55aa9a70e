//! Webots' Robot battery on a car (`battery = [energy, maxEnergy, chargingRate]`): the
//! battery sensor reads the traction battery's stored energy at its sample times, samples as
//! every device does, and the controller is stopped when the energy reaches 0.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::world_file::parse_str;
use sim::{Simulation, VehicleId};
use vehicle_model::energy::Battery;
use vehicle_model::{Wheel, WheelDrive};

/// A TeslaModel3 whose Webots battery holds `energy` J of `max` J, in gear 1 at full
/// throttle, and its pack.
fn tesla(energy: f64, max: f64) -> (Simulation, VehicleId, Battery<f64>) {
    let text = format!("[vehicle]\nmodel = \"TeslaModel3\"\nbattery = [{energy}, {max}, 0]\n");
    let w = parse_str("w.toml", &text).unwrap();
    let pack = w.car().unwrap().energy.unwrap().battery.unwrap();
    let (mut sim, _) = Simulation::from_description(&w).unwrap();
    let id = sim.car_ids().next().unwrap();
    let d = sim.driver_mut(id).unwrap();
    d.set_gear(1);
    d.set_throttle(1.0);
    (sim, id, pack)
}

/// The battery's stored energy (J) now, from the engine's state of charge.
fn stored(sim: &Simulation, id: VehicleId, pack: &Battery<f64>) -> f64 {
    pack.energy(sim.energy(id).unwrap().unwrap().soc)
}

#[test]
fn the_reading_is_the_battery_energy_at_each_sample_time() {
    let (mut sim, id, pack) = tesla(3.0e6, 3.6e6);
    let step = sim.world().time_ms();
    assert_eq!(step, 0);
    sim.enable_battery_sensor(id, 30).unwrap();
    assert_eq!(sim.battery_sensor(id).unwrap().period_ms(), 30);
    let mut last = f64::NAN;
    let mut samples = 0;
    for _ in 0..100 {
        sim.step().unwrap();
        let now = sim.world().time_ms();
        let value = sim.battery_sensor(id).unwrap().value();
        if now % 30 == 0 {
            // A sample: exactly the engine's stored energy at this step end (the same
            // function of the same state of charge).
            assert_eq!(value, stored(&sim, id, &pack), "at {now} ms");
            samples += 1;
            last = value;
        } else if now < 30 {
            assert!(
                value.is_nan(),
                "no sample before a full period: {value} at {now} ms"
            );
        } else {
            // Between samples the last reading holds while the battery's energy moves.
            assert_eq!(value, last, "at {now} ms");
        }
    }
    assert_eq!(samples, 33);
    // The car drew energy: the field's 3 MJ went down.
    assert!(last < 3.0e6, "{last}");
    // Disabled: the reading stays.
    sim.enable_battery_sensor(id, 0).unwrap();
    sim.step().unwrap();
    sim.step().unwrap();
    sim.step().unwrap();
    assert_eq!(sim.battery_sensor(id).unwrap().value(), last);
}

#[test]
fn the_controller_stops_when_the_energy_reaches_zero() {
    // 20 kJ: a few seconds of full throttle from standstill.
    let (mut sim, id, pack) = tesla(2.0e4, 3.6e6);
    sim.enable_battery_sensor(id, 10).unwrap();
    let mut steps = 0;
    while !sim.controller_stopped(id).unwrap() {
        assert!(steps < 2000, "the battery never emptied");
        sim.step().unwrap();
        steps += 1;
    }
    let r = sim.energy(id).unwrap().unwrap();
    assert_eq!((r.soc, stored(&sim, id, &pack)), (0.0, 0.0));
    // The last sample was the step before: no refresh once empty.
    let reading = sim.battery_sensor(id).unwrap().value();
    assert!(reading > 0.0 && reading < 2.0e4, "{reading}");
    // No drive torque from then on, whatever the driver asks.
    let speed = |sim: &Simulation| sim.world().vehicle(id).unwrap().state().forward_speed;
    let v0 = speed(&sim);
    assert!(v0 > 1.0, "{v0} m/s");
    sim.driver_mut(id).unwrap().set_throttle(1.0);
    for _ in 0..100 {
        sim.step().unwrap();
        let commands = sim.world().vehicle(id).unwrap().commands().unwrap();
        for w in Wheel::ALL {
            assert_eq!(commands.drive[w], WheelDrive::Torque(0.0));
        }
    }
    // Coasting on flat ground: only losses act, the car slows.
    assert!(speed(&sim) < v0, "{} vs {v0}", speed(&sim));
    assert!(sim.controller_stopped(id).unwrap());
    assert_eq!(sim.battery_sensor(id).unwrap().value(), reading);
}

#[test]
fn without_webots_field_an_empty_battery_stops_no_controller() {
    let text = "[vehicle]\nmodel = \"TeslaModel3\"\n[vehicle.battery]\nstate_of_charge = 0\n";
    let w = parse_str("w.toml", text).unwrap();
    let (mut sim, _) = Simulation::from_description(&w).unwrap();
    let id = sim.car_ids().next().unwrap();
    sim.enable_battery_sensor(id, 10).unwrap();
    sim.step().unwrap();
    assert!(!sim.controller_stopped(id).unwrap());
    assert_eq!(sim.battery_sensor(id).unwrap().value(), 0.0);
    // A car without energy accounting reads NaN.
    let w = parse_str("w.toml", "[vehicle]\nmodel = \"TeslaModel3\"\n").unwrap();
    let (mut sim, _) = Simulation::from_description(&w).unwrap();
    let id = sim.car_ids().next().unwrap();
    sim.enable_battery_sensor(id, 10).unwrap();
    sim.step().unwrap();
    assert!(sim.battery_sensor(id).unwrap().value().is_nan());
}
