//! The shipped cars' consumption on the WLTC class 3b against their published WLTP figures.
//!
//! The TeslaModel3 (its air and EPA-derived road-load set, energy accounting, 20 ms steps)
//! draws 132.5 Wh/km from its battery against the published 143 Wh/km (−7.3 %). Its wheels
//! do the work the real car's EPA road load asks, 146.6 Wh/km (`tests/drive_cycles.rs`); the
//! battery gives that plus the electric machine's copper and inverter losses (11.9 Wh/km)
//! less what regeneration takes back (26.0 Wh/km). The machine's spin losses (iron, windage)
//! are not charged on top: the coast-down the road-load set comes from measured the car with
//! its rotor turning (`EnergyParams::with_spin_losses_in_road_load`). Charging them as well
//! (`MotorLosses::rated`'s iron term scaled linearly far above the machine's corner speed)
//! drew 186.1 Wh/km (+30 %), 63 Wh/km of it in the machine. No combustion car is compared: no
//! WLTP figure for the shipped variants (BMW X5 xDrive40i G05, fourth-generation Toyota
//! Prius, Range Rover Sport SVR, the MKZ 3.0 V6, never sold in the EU) was found in a citable
//! source where this was written, only their NEDC figures, which belong to another cycle.
//!
//! A WLTC takes about 20 to 30 s in a debug build.
#![allow(clippy::unwrap_used, clippy::panic)]

use sim::scenario::{self, Scenario, Value};
use sim::world_file::parse_str;

/// The WLTP energy consumption of the Tesla Model 3 Standard Range Plus (the rear-drive
/// single-motor car of the shipped model), Wh/km: 14.3 kWh/100 km, the maker's figure as
/// pushevs.com lists it ("WLTP range and efficiency of electric cars", 23 September 2019:
/// 409 km, 14.3 kWh/100 km). WLTP's figure is the energy recharged from the mains per km,
/// charging losses included.
const TESLA_MODEL_3_SR_PLUS_WH_PER_KM: f64 = 143.0;

#[test]
fn the_tesla_on_the_wltc_draws_within_15_percent_of_its_published_consumption() {
    let text = "basicTimeStep = 20\n[vehicle]\nmodel = \"TeslaModel3\"\naero = true\n\
                losses = \"road-load\"\nenergy = true\n";
    let w = parse_str("w.toml", text).unwrap_or_else(|e| panic!("{e}"));
    let r = scenario::run(&w, Scenario::Wltc, &mut |_| {}).unwrap();
    let Some(Value::Number(battery)) = r.results[0].metric("battery_wh_per_km") else {
        panic!("no battery_wh_per_km");
    };
    // 15 %: the bound. The published figure is at the mains and the model's at the
    // battery's terminals: a car matching the real one lands 10–15 % below it (a charger's
    // losses), inside the bound.
    let published = TESLA_MODEL_3_SR_PLUS_WH_PER_KM;
    assert!(
        (battery - published).abs() <= 0.15 * published,
        "{battery:.1} Wh/km from the battery, {published} Wh/km published"
    );
}
