//! The shipped cars' consumption on the WLTC class 3b against their published WLTP figures.
//!
//! **Ignored: the model misses.** The TeslaModel3 (its air and EPA-derived road-load set,
//! energy accounting, 20 ms steps) draws 186.1 Wh/km from its battery against the published
//! 143 Wh/km (+30 %). The wheels are not the cause: they do the work the real car's EPA road
//! load asks, 146.6 Wh/km, within 0.2 % (`tests/drive_cycles.rs`). The battery's energy is
//! the wheels' plus the electric machine's losses less what regeneration took back, and
//! there the model is far from a real drive unit: the machine loses 63 Wh/km
//! (`vehicle_model::energy::MotorLosses::rated`, 0.92 at the rated point by an assumed
//! split of its losses, much lower at the WLTC's part load, where the speed-dependent and
//! constant losses dominate), where a drive unit averaging 85–90 % over the cycle (an
//! estimate, not a published figure) would lose some 15–25 Wh/km; and regeneration takes back 23 Wh/km of the 52 Wh/km the
//! trace's decelerations offer (the rest goes to the friction brakes and the machine). The
//! fix belongs to the energy model's machine map and brake blending (fitted to a published
//! efficiency map), not to a constant tuned here. No combustion car is compared: no WLTP
//! figure for the shipped variants (BMW X5 xDrive40i G05, fourth-generation Toyota Prius,
//! Range Rover Sport SVR, the MKZ 3.0 V6, never sold in the EU) was found in a citable
//! source where this was written, only their NEDC figures, which belong to another cycle.
//!
//! Run: `cargo test -p sim --test published_consumption -- --ignored` (a WLTC takes about
//! 20 to 30 s in a debug build).
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
#[ignore = "the model draws +30 % (the machine's part-load losses, regeneration): see the file's documentation"]
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
