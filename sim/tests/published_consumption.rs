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
//! the road-load rows were checked against; each constant below names its test number. The
//! X5's other tests on the same vehicle gave 25.0 and 25.4 mpg (FTP) and 34.8 and 35.5 mpg
//! (HWFET): repeat tests of one car spread by 3–5 %; the comparison takes the first.
//!
//! The cars run on the transmission of the car the EPA tested (`transmission = "epa"`,
//! `vehicle_model::Model::epa_transmission`: the gearbox's ratios times the row's "Axle
//! Ratio"), with everything else the shipped model's. Webots' LincolnMKZ and
//! RangeRoverSportSVR have their gearboxes' ratios without the final drive (first gears
//! of 4.58 and 4.696 overall), on which their engines turn about three times too slowly to
//! follow either cycle within the EPA's band; Webots' BmwX5 has five overall ratios of its
//! own down to 4.0 (the test vehicle's eight-speed reaches 2.25). The fuel model's friction
//! is sized from the test vehicle's displacement ("Test Veh Displacement (L)": 3.0, 3.0 and
//! 5.0 l; `vehicle_model::Model::energy_params`), since Webots' MKZ and Range Rover keep
//! the Car PROTO's default curve `150 + 0.1·rpm` N·m, which at their 5500 rpm top speed
//! implies a 7 l engine (`vehicle_model::energy::FuelModel::petrol`).
//!
//! Measured (release build, 20 ms, 2026-11-29), l/100 km against the published; the time
//! outside the EPA's band, where there is any, in brackets:
//!
//! | car | transmission | FTP-75 | HWFET |
//! |---|---|---|---|
//! | BmwX5 | EPA (ZF 8HP, axle 3.38) | 9.76 vs 8.91 (+9.5 %) | 7.29 vs 6.55 (+11.3 %) |
//! | LincolnMKZ | EPA (Ford 6F55, axle 2.77) | 9.24 vs 10.69 (−13.5 %) | 6.53 vs 6.11 (+6.9 %) |
//! | RangeRoverSportSVR | EPA (ZF 8HP, axle 3.31) | 14.12 vs 13.14 (+7.5 %) | 10.22 vs 8.68 (+17.7 %) |
//! | BmwX5 | Webots | 9.93 vs 8.91 (+11.4 %) | 7.96 vs 6.55 (+21.6 %) |
//! | LincolnMKZ | Webots | 8.35 (4.1 s outside) | 6.42 |
//! | RangeRoverSportSVR | Webots | 12.85 (109 s outside) | 10.46 (7.8 s outside) |
//!
//! (MKZ: HR600087, FTP HFMX91003143 22.0 mpg, HWFE HFMX91003142 38.5 mpg, 19tstcar-2020-10-02;
//! Range Rover: JA164790, FTP JJLX10051722 17.9 mpg, HWFE JJLX10051723 27.1 mpg,
//! 22-testcar-2023-06-13.) The MKZ test vehicle drove its front wheels ("2-Wheel Drive,
//! Front"); the shipped model is four-wheel driven.
//!
//! Before the friction came from the displacement (10 % of the curve's peak: 35 N·m for the
//! BmwX5, 70 N·m for the other two, against 29.8, 29.8 and 49.7 N·m now) and before the
//! cycle driver pushed the throttle by what the engaged gear gives (below), the same runs
//! gave the BmwX5 +19 %/+17 % on its EPA transmission and +21 %/+30 % on Webots', the MKZ
//! +35 %/+56 % and the Range Rover +31 %/+34 % with 7.3 s and 15.5 s outside the band on
//! theirs. The Range Rover left the band because its driver pushed the throttle by the mean
//! acceleration to 100 km/h (5.9 m/s²), where its seventh gear at 1650 rpm gives 0.7 m/s² at
//! full throttle on Webots' curve, and lagged up to 5.7 km/h behind the trace's
//! accelerations; the driver now takes the engine's torque at its speed through the engaged
//! gear (`sim::scenario` cycle follower).
//!
//! The hybrid ToyotaPrius is not compared: Webots' power split holds the engine at
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

/// The Lincoln MKZ 3.0 V6's FTP-75 ("Federal fuel 2-day exhaust (w/can load)").
const LINCOLN_MKZ_FTP: Published = Published {
    source: "MY2019 MKZ, HR600087, HFMX91003143, 19tstcar-2020-10-02.xlsx",
    mpg: 22.0,
};
/// The Lincoln MKZ 3.0 V6's HWFET ("HWFE").
const LINCOLN_MKZ_HWFET: Published = Published {
    source: "MY2019 MKZ, HR600087, HFMX91003142, 19tstcar-2020-10-02.xlsx",
    mpg: 38.5,
};
/// The Range Rover Sport SVR's FTP-75 ("Federal fuel 2-day exhaust (w/can load)").
const RANGE_ROVER_FTP: Published = Published {
    source: "MY2022 Range Rover Sport SVR, JA164790, JJLX10051722, 22-testcar-2023-06-13.xlsx",
    mpg: 17.9,
};
/// The Range Rover Sport SVR's HWFET ("HWFE").
const RANGE_ROVER_HWFET: Published = Published {
    source: "MY2022 Range Rover Sport SVR, JA164790, JJLX10051723, 22-testcar-2023-06-13.xlsx",
    mpg: 27.1,
};

/// `model` on `scenario` with its air, its road-load set, energy accounting and its EPA
/// test vehicle's transmission, at 20 ms.
fn drive(model: &str, scenario: Scenario) -> RunReport {
    let text = format!(
        "basicTimeStep = 20\n[vehicle]\nmodel = \"{model}\"\naero = true\n\
         losses = \"road-load\"\nenergy = true\ntransmission = \"epa\"\n"
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
fn misses(runs: &[(&str, Scenario, Published)]) -> Vec<String> {
    let mut misses = Vec::new();
    for (model, scenario, published) in runs {
        let r = drive(model, *scenario);
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
fn the_combustion_cars_on_their_epa_transmissions_burn_within_20_percent_on_both_cycles() {
    let misses = misses(&[
        ("BmwX5", Scenario::Ftp75, BMW_X5_FTP),
        ("BmwX5", Scenario::Hwfet, BMW_X5_HWFET),
        ("LincolnMKZ", Scenario::Ftp75, LINCOLN_MKZ_FTP),
        ("LincolnMKZ", Scenario::Hwfet, LINCOLN_MKZ_HWFET),
        ("RangeRoverSportSVR", Scenario::Ftp75, RANGE_ROVER_FTP),
        ("RangeRoverSportSVR", Scenario::Hwfet, RANGE_ROVER_HWFET),
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
