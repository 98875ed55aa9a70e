//! The shipped cars' consumption on the cycles of their published figures: the TeslaModel3
//! on the WLTC class 3b against its WLTP figure, the combustion cars on FTP-75 and HWFET
//! against the US EPA's unadjusted dynamometer results for the test vehicles their road-load
//! sets come from.
//!
//! **TeslaModel3.** With its air and EPA-derived road-load set, energy accounting and 20 ms
//! steps it draws 140.1 Wh/km from its battery against the published 143 Wh/km (−2.0 %). Its
//! wheels do the work the real car's EPA road load and its effective mass ask, 161.4 Wh/km
//! (`tests/drive_cycles.rs`; the mass includes the machine's rotor through the gear,
//! `vehicle_model::Driveline`, Wong's passenger-car correlation taken as an assumption for an
//! electric machine); the battery gives that plus the electric machine's copper and
//! inverter losses (12.1 Wh/km) less what regeneration takes back (33.4 Wh/km). (Before the
//! rotor's inertia reached the wheels: 132.5 Wh/km, wheels 146.6.) The
//! machine's spin losses (iron, windage) are not charged on top: the coast-down the
//! road-load set comes from measured the car with its rotor turning
//! (`EnergyParams::with_spin_losses_in_road_load`). Charging them as well
//! (`MotorLosses::rated`'s iron term scaled linearly far above the machine's corner speed)
//! drew 186.1 Wh/km (+30 %), 63 Wh/km of it in the machine. The WLTC takes 20 to 45 s in a
//! debug build; the test runs with the suite.
//!
//! **Combustion cars.** No WLTP figure for the shipped variants (BMW X5 xDrive40i G05, Range
//! Rover Sport SVR, the MKZ 3.0 V6, never sold in the EU) was found in a citable source, but
//! the EPA's *Data on Cars Used for Testing Fuel Economy* (the test-car list whose
//! "Target Coef" the road-load sets derive from, `vehicle-model/README.md`) gives, on the
//! same rows, the fuel economy measured on the dynamometer ("RND_ADJ_FE", mpg, for the test
//! procedures "Federal fuel 2-day/3-day exhaust", the FTP-75, and "HWFE", the HWFET): the
//! unadjusted laboratory figure of exactly the cycles the `ftp75` and `hwfet` scenarios
//! drive, before the 5-cycle adjustment of the window label. The rows were read in
//! `22-testcar-2023-06-13.xlsx` and `19tstcar-2020-10-02.xlsx` as kept in the repository
//! ydpravinkumar/epa-vehicle-emissions-regression-part2 (`data/`, commit 5f6331d), the copy
//! the road-load rows were checked against; each constant below names its test number.
//!
//! Measured (release build, 20 ms, 2026-11-29, with the engine's inertia on the driven
//! wheels, `vehicle_model::Driveline`), l/100 km against the published, first on
//! the models' Webots `gearRatio`s, then on the EPA test vehicle's transmission:
//!
//! | car | FTP-75 | HWFET |
//! |---|---|---|
//! | BmwX5 | 10.79 vs 8.91 (+21 %) | 8.50 vs 6.55 (+30 %) |
//! | BmwX5, EPA transmission | 10.56 vs 8.91 (+19 %) | 7.69 vs 6.55 (+17 %) |
//! | LincolnMKZ | 12.64 vs 10.69 (+18 %; 69 s outside the band) | 9.28 vs 6.11 (+52 %; 4.4 s outside) |
//! | LincolnMKZ, EPA transmission | 14.44 vs 10.69 (+35 %) | 9.51 vs 6.11 (+56 %) |
//! | RangeRoverSportSVR | 15.29 vs 13.14 (+16 %; 240 s outside the band) | 12.03 vs 8.68 (+39 %; 16 s outside) |
//! | RangeRoverSportSVR, EPA transmission | 17.19 vs 13.14 (+31 %; 7.3 s outside) | 11.67 vs 8.68 (+34 %; 15.5 s outside) |
//!
//! (MKZ: HR600087, FTP HFMX91003143 22.0 mpg, HWFE HFMX91003142 38.5 mpg, 19tstcar-2020-10-02;
//! Range Rover: JA164790, FTP JJLX10051722 17.9 mpg, HWFE JJLX10051723 27.1 mpg,
//! 22-testcar-2023-06-13.)
//!
//! **The transmission.** Webots' BmwX5 has five overall ratios down to 4.0; the EPA's test
//! vehicle (same rows: 8 gears, "Axle Ratio" 3.38) has ZF's eight-speed 8HP, whose top gear
//! 0.6667 gives 2.25 overall. On HWFET the Webots car runs in its top gear at about 2200 rpm;
//! on the 8HP the gear rule (whose `n_min_drive` is 1666 rpm for this curve) keeps it in
//! sixth or seventh at 1700–1900 rpm, and the Willans line's friction
//! (`vehicle_model::energy::FuelModel::petrol`, 10 % of the curve's peak torque, growing
//! with the speed) costs less. [`EPA_BMW_X5_GEARS`] is that transmission: the 8HP's ratios times the row's axle
//! ratio; given as the world's `gearRatio`, everything else the shipped model's. On it the
//! BmwX5 is within the 20 % on both cycles, and those two comparisons are the tests
//! of the fuel model. On its Webots ratios it burns +21 % on FTP-75 and +30 % on HWFET: the
//! ratios are Webots' PROTO fields, kept for parity. (Before the engine's inertia reached the
//! wheels it was +15 % on FTP-75: on the Webots ratios' first gear of 12.5 the engine adds
//! 39 % to the mass the car accelerates, Wong's `0.0025·ξ²`, and the fuel cut on overrun and
//! the friction brakes do not give all of its energy back.)
//!
//! **The other combustion cars are not compared,** because their Webots engines are not
//! the test vehicles': the LincolnMKZ and the RangeRoverSportSVR both keep the Car PROTO's
//! default curve `150 + 0.1·rpm` N·m (Webots caps a combustion engine's torque by neither
//! `engineMaxTorque` nor `engineMaxPower`), a torque rising linearly to 700 N·m at their
//! 5500 rpm top speed, which no engine has, and the fuel model sizes an engine's friction
//! from its curve's peak (70 N·m for both). On the test vehicles' transmissions (the MKZ's
//! GM–Ford 6F six-speed, 4.484 … 0.742, Wikipedia "GM–Ford 6-speed automatic transmission",
//! with the row's axle 2.77; the Range Rover's ZF 8HP with its 3.31) the MKZ burns +35 % and
//! +56 %, its engine held at 1600–2100 rpm on HWFET by the gear rule, and the Range Rover
//! still leaves the EPA's band (7.3 s and 15.5 s outside). Matching them would mean
//! replacing Webots' engine data, which Webots users' controllers were tuned on; the BmwX5,
//! whose curve is a plausible small petrol engine's, is the check of the fuel
//! model. The hybrid ToyotaPrius is not compared: Webots' power split holds the engine at
//! `hybridPowerSplitRPM` whatever the load and has no charge-sustaining strategy (its
//! battery gives 67 Wh/km over FTP-75), where the EPA's figure is a charge-balanced one.
//!
//! Run: `cargo test --release -p sim --test published_consumption -- --include-ignored`, as
//! `.ci/run` does (each cycle
//! takes a minute or more in a debug build and under a second in a release build, so the
//! combustion tests are ignored in the debug suite).
#![allow(clippy::unwrap_used, clippy::panic)]

use sim::scenario::{self, RunReport, Scenario, Value};
use sim::world_file::parse_str;

/// l/100 km per mpg (US gallon): 100 km / (1.609 344 km/mi) · 3.785 411 784 l/gal.
const L_PER_100KM_MPG: f64 = 235.214_583;

/// One EPA test's published result.
struct Published {
    /// "Model Year", "Represented Test Veh Model", "Test Vehicle ID", "Test Veh
    /// Configuration #", "Test Number", the EPA file.
    source: &'static str,
    /// "RND_ADJ_FE" (mpg).
    mpg: f64,
}

impl Published {
    fn litres_per_100km(&self) -> f64 {
        L_PER_100KM_MPG / self.mpg
    }
}

/// The BMW X5 xDrive40i's FTP-75 ("Federal fuel 3-day exhaust").
const BMW_X5_FTP: Published = Published {
    source: "MY2022 X5 xDrive40i, LL66867 configuration 1, MBMX10065615, 22-testcar-2023-06-13.xlsx",
    mpg: 26.4,
};
/// The BMW X5 xDrive40i's HWFET ("HWFE").
const BMW_X5_HWFET: Published = Published {
    source: "MY2022 X5 xDrive40i, LL66867 configuration 1, MBMX10065616, 22-testcar-2023-06-13.xlsx",
    mpg: 35.9,
};

/// ZF's 8HP eight-speed automatic, first generation (8HP 70), gear ratios reverse then
/// first to eighth: Wikipedia, "ZF 8HP transmission", gear-ratio table (R −3.2968, 4.6957,
/// 3.1304, 2.1039, 1.6667, 1.2845, 1.0000, 0.8392, 0.6667).
const ZF_8HP: [f64; 9] = [
    -3.2968, 4.6957, 3.1304, 2.1039, 1.6667, 1.2845, 1.0, 0.8392, 0.6667,
];
/// The BMW X5 xDrive40i test vehicle's "Axle Ratio" (LL66867, the rows of [`BMW_X5_FTP`]).
const BMW_X5_AXLE: f64 = 3.38;
/// The X5 test vehicle's overall ratios (engine speed over wheel spin): [`ZF_8HP`] times
/// [`BMW_X5_AXLE`], as a world's `gearRatio`.
const EPA_BMW_X5_GEARS: [f64; 9] = {
    let mut g = ZF_8HP;
    let mut i = 0;
    while i < g.len() {
        g[i] *= BMW_X5_AXLE;
        i += 1;
    }
    g
};

/// `model` on `scenario` with its air, its road-load set and energy accounting, at 20 ms,
/// on the overall `gears` if given (a world's `gearRatio`), else the model's own.
fn drive(model: &str, scenario: Scenario, gears: Option<&[f64]>) -> RunReport {
    let gears = gears.map_or(String::new(), |g| format!("gearRatio = {g:?}\n"));
    let text = format!(
        "basicTimeStep = 20\n[vehicle]\nmodel = \"{model}\"\naero = true\n\
         losses = \"road-load\"\nenergy = true\n{gears}"
    );
    let w = parse_str("w.toml", &text).unwrap_or_else(|e| panic!("{e}"));
    scenario::run(&w, scenario, &mut |_| {}).unwrap()
}

fn number(r: &RunReport, key: &str) -> f64 {
    match r.results[0].metric(key) {
        Some(Value::Number(v)) => v,
        other => panic!("{key}: {other:?}"),
    }
}

/// Each run's fuel against its published figure, within the 20 %; the misses.
fn misses(runs: &[(&str, Scenario, Option<&[f64]>, Published)]) -> Vec<String> {
    let mut misses = Vec::new();
    for (model, scenario, gears, published) in runs {
        let r = drive(model, *scenario, *gears);
        // The run must be one the EPA accepts: no excursion outside its band of 2 s or more
        // (40 CFR 86.115-78(c)).
        assert!(
            number(&r, "longest_excursion_s") < 2.0,
            "{model} {scenario:?}: does not follow the trace"
        );
        let fuel = number(&r, "fuel_l_per_100km");
        let expected = published.litres_per_100km();
        // 20 %: the bound. The published figure includes FTP-75's cold start (its
        // first bag weighs 43 %) and this model has no temperatures: a model matching the
        // real engine would land a few % below it, inside the bound.
        if (fuel - expected).abs() > 0.2 * expected {
            misses.push(format!(
                "{model} {scenario:?}: {fuel:.2} l/100 km, {expected:.2} published ({})",
                published.source
            ));
        }
    }
    misses
}

#[test]
#[ignore = "a minute in a debug build each: cargo test --release -p sim --test published_consumption -- --include-ignored (CI does)"]
fn the_bmw_x5_on_its_epa_transmission_burns_within_20_percent_on_both_cycles() {
    let gears = Some(&EPA_BMW_X5_GEARS[..]);
    let misses = misses(&[
        ("BmwX5", Scenario::Ftp75, gears, BMW_X5_FTP),
        ("BmwX5", Scenario::Hwfet, gears, BMW_X5_HWFET),
    ]);
    assert!(misses.is_empty(), "{misses:#?}");
}

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
