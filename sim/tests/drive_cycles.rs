//! The drive-cycle scenarios (`ftp75`, `hwfet`, `wltc`) on shipped cars: the built-in driver
//! keeps the car inside the cycle's tolerance band, the wheels do the work of the real car's
//! road load, the battery's energy closes against the wheels,
//! the machine's losses and regeneration over a whole cycle, and a car at full throttle
//! settles at the top speed where its resistances take all of its power.
//!
//! The cycles run at a 20 ms step (Webots' `basicTimeStep` of most of its car worlds is 16 to
//! 32 ms), which keeps the debug build at about a minute for the 1874 s FTP-75.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[path = "support/resisting_force.rs"]
mod support;
use sim::scenario::{self, Cycle, RunReport, Scenario, Value};
use sim::world_file::parse_str;
use sim::{CarBuilder, Simulation, World, WorldConfig};
use support::resisting_force;
use vehicle_model::{Driveline, Model, RoadLoad};

/// A world of one `model` with its air, road-load losses and energy accounting, at 20 ms.
fn world(model: &str) -> String {
    format!(
        "basicTimeStep = 20\n[vehicle]\nmodel = \"{model}\"\naero = true\n\
         losses = \"road-load\"\nenergy = true\n"
    )
}

fn run(text: &str, scenario: Scenario) -> RunReport {
    let w = parse_str("w.toml", text).unwrap_or_else(|e| panic!("{e}"));
    scenario::run(&w, scenario, &mut |_| {}).unwrap()
}

fn number(r: &RunReport, key: &str) -> f64 {
    match r.results[0].metric(key) {
        Some(Value::Number(v)) => v,
        other => panic!("{key}: {other:?}"),
    }
}

/// The run stays in the band: the EPA accepts excursions shorter than 2 s (40 CFR
/// 86.115-78(c), 40 CFR 600.109-08(b)(2)); the driver does better than that, under 1 s in
/// all, and its error never exceeds the cycle's speed tolerance (2 mph for the EPA's, 2 km/h
/// for the WLTC's). The distance is the trace's within 0.5 % (the band allows several % at
/// low speed).
fn assert_tracked(r: &RunReport, cycle: Cycle) {
    let longest = number(r, "longest_excursion_s");
    let outside = number(r, "time_outside_band_s");
    assert!(
        longest < 2.0 && outside < 1.0,
        "{cycle}: {longest} s, {outside} s out"
    );
    assert!(number(r, "max_speed_error_kmh") < cycle.speed_tolerance() * 3.6);
    let (d, trace) = (number(r, "distance_km"), number(r, "trace_distance_km"));
    assert!(
        (d - trace).abs() < 0.005 * trace,
        "{cycle}: {d} km of {trace}"
    );
    assert!(r.results[0].unfinished.is_none());
}

#[test]
fn an_electric_car_follows_the_ftp75_and_its_energy_balances() {
    let r = run(&world("TeslaModel3"), Scenario::Ftp75);
    assert_tracked(&r, Cycle::Ftp75);
    // The battery gives the wheels' energy and the machine's losses, less what braking took
    // back: the 0.5 % over the cycle.
    let battery = number(&r, "battery_wh");
    let expected =
        number(&r, "wheel_wh") + number(&r, "motor_loss_wh") - number(&r, "regenerated_wh");
    assert!(
        (battery - expected).abs() <= 0.005 * expected,
        "battery {battery} Wh, wheels + losses − regenerated {expected} Wh"
    );
    // The charge falls from full by the battery's energy over its capacity (it stays in
    // [0, 1]); a town cycle regenerates a good share of what it spends.
    let (start, end) = (number(&r, "soc_start"), number(&r, "soc_end"));
    assert_eq!(start, 1.0);
    assert!((0.0..1.0).contains(&end), "{end}");
    assert!(number(&r, "regenerated_wh") > 0.1 * number(&r, "wheel_wh"));
}

#[test]
fn an_electric_car_follows_the_wltc_and_its_wheels_do_the_epa_road_load_s_work() {
    let r = run(&world("TeslaModel3"), Scenario::Wltc);
    assert_tracked(&r, Cycle::Wltc);
    // The work the driven wheels do over the trace is what the real car's road load (the
    // EPA's published curve, which the model's road-load set is derived from) and the
    // model's effective mass ask of them: the positive part of (F(v) + m·a)·v each second of
    // the trace, mid-second speeds. 3 %: the driver's tracking error (under 1.5 km/h), the
    // tyres' slip (about 1 % of the drive power) and the coast-down's −2 % against the
    // curve (tests/epa_road_load.rs). The effective mass includes the machine's inertia
    // through the car's one gear, which the driven wheels spin up with the car
    // (`Commands::driveline`), as a mass at their rim.
    let model = Model::TeslaModel3;
    let curve = model.epa_test_car().unwrap();
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let (id, _) = sim.add_car(CarBuilder::of_model(model)).unwrap();
    let p = model.params::<f64>();
    assert_eq!(p.gear_ratios.len(), 2, "reverse and one forward gear");
    let machine = Driveline {
        engine_inertia: p.engine_inertia(),
        ratio: p.gear_ratios[1],
    };
    let mass = sim.world().vehicle(id).unwrap().spec().effective_mass()
        + machine.reflected_inertia() / (p.driven_radius() * p.driven_radius());
    let v = Cycle::Wltc.trace().speeds().to_vec();
    let work: f64 = v
        .windows(2)
        .map(|w| {
            let (speed, accel) = (0.5 * (w[0] + w[1]), w[1] - w[0]);
            let force = if speed > 0.0 { curve.force(speed) } else { 0.0 };
            ((force + mass * accel) * speed).max(0.0)
        })
        .sum();
    let expected = work / 3600.0;
    let wheel = number(&r, "wheel_wh");
    assert!(
        (wheel - expected).abs() <= 0.03 * expected,
        "wheels {wheel:.0} Wh, the EPA road load {expected:.0} Wh"
    );
}

#[test]
fn a_combustion_car_follows_the_hwfet_and_burns_fuel() {
    let r = run(&world("BmwX5"), Scenario::Hwfet);
    assert_tracked(&r, Cycle::Hwfet);
    // No battery metrics for a combustion car, and some fuel: the wheels' energy over the
    // fuel's (43 MJ/kg, 0.745 kg/l) gives an efficiency between 0.1 and 0.38, a petrol
    // engine's range from part load to its best point.
    assert!(r.results[0].metric("battery_wh_per_km").is_none());
    let litres_per_km = number(&r, "fuel_l_per_100km") / 100.0;
    let fuel_wh_per_km = litres_per_km * 0.745 * 43e6 / 3600.0;
    let efficiency = number(&r, "wheel_wh_per_km") / fuel_wh_per_km;
    assert!((0.1..0.38).contains(&efficiency), "{efficiency}");
}

#[test]
fn full_throttle_settles_where_the_resistances_take_the_maximum_power() {
    let model = Model::TeslaModel3;
    let (aero, losses) = (model.aero(), RoadLoad::default());
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let builder = CarBuilder::of_model(model)
        .aero(Some(aero))
        .road_load(Some(losses));
    let (id, _) = sim.add_car(builder).unwrap();
    let spec = *sim.world().vehicle(id).unwrap().spec();
    let params = model.params::<f64>();
    let power = params.engine.max_power;
    // Analytic: the electric machine gives engineMaxPower above its base speed, so the top
    // speed solves P = F(v)·v (bisection; F·v grows with v).
    let (mut lo, mut hi) = (1.0, 150.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if resisting_force(&spec, &aero, &losses, mid) * mid < power {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let analytic = 0.5 * (lo + hi);
    // The motor is still below its rev limit there, so power, not speed, limits the car.
    let ratio = params.gear_ratios[1];
    let motor_rpm = analytic / params.radius_rear() * ratio * 30.0 / core::f64::consts::PI;
    assert!(motor_rpm < params.engine.max_rpm, "{motor_rpm} rpm");
    let d = sim.driver_mut(id).unwrap();
    d.set_gear(1);
    d.set_throttle(1.0);
    // The speed approaches the top one with a time constant m/(dF/dv + P/v²) of about 25 s:
    // 170 s is almost seven of them. (Held longer, the car leaves its straight line: its yaw
    // rate doubles every 6 s from 140 s on, and at 200 s it spins. The model oversteers: the
    // constant-radius scenario measures an understeer gradient of -0.32 °/g at the road
    // wheels, whose single-track critical speed √(L/|K|) is 260 km/h, just under the 265 km/h
    // it reaches: sim/README.md, "the same balance shows at speed".)
    let dt = sim.world().dt();
    let mut speeds = Vec::new();
    for _ in 0..(170.0 / dt) as usize {
        sim.step().unwrap();
        speeds.push(sim.telemetry(id).unwrap().speed);
    }
    let top = speeds[speeds.len() - 1];
    let earlier = speeds[speeds.len() - 1 - (10.0 / dt) as usize];
    assert!(
        (top - earlier).abs() < 0.002 * top,
        "not settled: {earlier} → {top} m/s"
    );
    // 1 %: the tyres' longitudinal slip (about 1 % at the 2 kN of drive near the top speed)
    // costs that share of the power, which the analytic balance leaves out.
    assert!(
        (top - analytic).abs() < 0.01 * analytic,
        "simulated {:.2} km/h, analytic {:.2} km/h",
        top * 3.6,
        analytic * 3.6
    );
}
