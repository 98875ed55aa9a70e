//! Cars driven through the Webots driver library: steady circle, braking, torque mode top
//! speed, determinism and robustness under abusive command sequences.

// Helpers outside `#[test]` functions unwrap too: clippy.toml only exempts test bodies.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::common;

use sim::TyreChoice;

use sim::Simulation;
use vehicle_model::Model;

/// Least-squares circle through `points` (Kåsa fit): minimises Σ(x² + y² + D·x + E·y + F)²;
/// returns the radius (m).
fn fit_circle(points: &[[f64; 2]]) -> f64 {
    // Normal equations of the linear problem [x y 1]·[D E F]ᵀ = −(x² + y²).
    let mut a = [[0.0_f64; 3]; 3];
    let mut b = [0.0_f64; 3];
    for &[x, y] in points {
        let row = [x, y, 1.0];
        let rhs = -(x * x + y * y);
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] += row[i] * row[j];
            }
            b[i] += row[i] * rhs;
        }
    }
    // Cramer's rule on the 3×3 system.
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(a);
    let solve = |k: usize| {
        let mut m = a;
        for (row, v) in m.iter_mut().zip(b) {
            row[k] = v;
        }
        det(m) / d
    };
    let (cd, ce, cf) = (solve(0), solve(1), solve(2));
    (cd * cd / 4.0 + ce * ce / 4.0 - cf).sqrt()
}

#[test]
fn circle_fit_recovers_a_known_circle() {
    let pts: Vec<[f64; 2]> = (0..50)
        .map(|i| {
            let a = 0.03 * f64::from(i);
            [3.0 + 7.0 * a.cos(), -2.0 + 7.0 * a.sin()]
        })
        .collect();
    assert!((fit_circle(&pts) - 7.0).abs() < 1e-9);
}

#[test]
fn every_model_circles_at_10_kmh_on_the_ackermann_radius() {
    // The rear-axle centre of a kinematic bicycle turns on L/tan δ (BmwX5: 2.995/tan 0.2 =
    // 14.775 m). At 10 km/h on 0.2 rad the lateral acceleration is at most 0.9 m/s² (the
    // Tractor's 8.7 m), so the slip angles are a few mrad and the radius is within 3 %.
    for model in Model::ALL {
        for tyre in [TyreChoice::of_model(model), common::webots_tyre()] {
            let (mut sim, id) = common::settled_on(model, 1.0, &tyre);
            let d = sim.driver_mut(id).unwrap();
            d.set_steering_angle(0.2);
            d.set_cruising_speed(10.0);
            common::run(&mut sim, 6.0);
            let mut pts = Vec::new();
            for _ in 0..1000 {
                sim.step().unwrap();
                let p = sim.telemetry(id).unwrap().state.position;
                pts.push([p[0], p[1]]);
            }
            let wheelbase = sim.driver(id).unwrap().params().wheelbase;
            let expected = wheelbase / 0.2_f64.tan();
            let r = fit_circle(&pts);
            println!("{model:?} {tyre:?}: circle radius {r:.3} m (Ackermann {expected:.3} m)");
            assert!(
                (r / expected - 1.0).abs() < 0.03,
                "{model:?} {tyre:?}: {r} vs {expected}"
            );
            // Positive steering turns right: clockwise, negative yaw rate.
            assert!(sim.telemetry(id).unwrap().state.yaw_rate < 0.0);
        }
    }
}

/// Speed mode up to 100 km/h on grippy ground, on the model's slip-based tyres.
fn at_100_kmh(model: Model) -> (Simulation, sim::VehicleId) {
    at_100_kmh_on(model, &TyreChoice::of_model(model))
}

/// Speed mode up to 100 km/h on grippy ground, on `tyre`.
fn at_100_kmh_on(model: Model, tyre: &TyreChoice) -> (Simulation, sim::VehicleId) {
    let (mut sim, id) = common::settled_on(model, common::GRIPPY, tyre);
    sim.driver_mut(id).unwrap().set_cruising_speed(110.0);
    let limit = 1.5 * sim.driver(id).unwrap().params().time_0_to_100 + 2.0;
    common::run_until(&mut sim, limit, |s| {
        s.telemetry(id).unwrap().speed >= 100.0 / 3.6
    })
    .unwrap();
    (sim, id)
}

/// BmwX5 braking with brake 1 from 100 km/h in neutral on `tyre`: four brakes of
/// brakeCoefficient 1800 N·m on 0.374 m tyres stop 2000 + 4×30 kg at
/// 4·1800/0.374/2120 = 9.08 m/s² (the grip, 1.5·g, is not the limit): from 27.78 m/s that is
/// 27.78²/(2·9.08) = 42.5 m in 3.06 s; wheel damping adds a little. The last few cm/s fade
/// slowly (the suspension rocks the car as it stops), so the time is only bounded below. 3 s
/// later the car is at rest where it stopped.
fn brakes_from_100_kmh_to_rest_and_stays_there(tyre: &TyreChoice) {
    let (mut sim, id) = at_100_kmh_on(Model::BmwX5, tyre);
    let start = sim.telemetry(id).unwrap().state.position;
    let d = sim.driver_mut(id).unwrap();
    d.set_throttle(0.0); // torque mode, neutral: no engine torque
    d.set_brake_intensity(1.0);
    let t = common::run_until(&mut sim, 10.0, |s| {
        s.telemetry(id).unwrap().speed.abs() < 0.01
    })
    .unwrap();
    let stop = sim.telemetry(id).unwrap().state.position;
    let distance = (stop.x - start.x).hypot(stop.y - start.y);
    println!("stopping distance {distance:.2} m in {t:.2} s");
    assert!((distance / 42.5 - 1.0).abs() < 0.08, "{distance}");
    assert!(t > 0.95 * 3.06 && t < 5.0, "{t}");
    common::run(&mut sim, 3.0);
    let rest = sim.telemetry(id).unwrap();
    let drift = (rest.state.position.x - stop.x).hypot(rest.state.position.y - stop.y);
    assert!(rest.speed.abs() < 0.01 && drift < 0.02, "{rest:?}");
}

#[test]
fn bmw_x5_brakes_from_100_kmh_to_rest_and_stays_there() {
    brakes_from_100_kmh_to_rest_and_stays_there(&TyreChoice::of_model(Model::BmwX5));
}

#[test]
fn bmw_x5_brakes_from_100_kmh_to_rest_and_stays_there_on_webots_contact() {
    brakes_from_100_kmh_to_rest_and_stays_there(&common::webots_tyre());
}

#[test]
fn torque_mode_in_first_gear_settles_where_the_engine_reaches_max_rpm() {
    for tyre in [TyreChoice::of_model(Model::BmwX5), common::webots_tyre()] {
        let (mut sim, id) = common::settled_on(Model::BmwX5, common::GRIPPY, &tyre);
        let d = sim.driver_mut(id).unwrap();
        d.set_gear(1);
        d.set_throttle(1.0);
        common::run(&mut sim, 15.0);
        let p = sim.driver(id).unwrap().params().clone();
        let ratio = p.gear_ratios[1];
        // engineMaxRPM 6500 → 680.68 rad/s at the engine, /12.5 = 54.45 rad/s at the wheels,
        // ×0.374 m = 20.37 m/s.
        let v_max = p.engine.max_rpm * core::f64::consts::TAU / 60.0 / ratio * p.radius_front();
        let tl = sim.telemetry(id).unwrap();
        println!(
            "top speed in gear 1: {:.2} m/s (engine limit {v_max:.2} m/s), rpm {:?}",
            tl.speed, tl.rpm
        );
        assert!(
            (tl.speed / v_max - 1.0).abs() < 0.03,
            "{} vs {v_max}",
            tl.speed
        );
        let rpm = tl.rpm.unwrap();
        assert!(
            rpm > 0.95 * p.engine.max_rpm && rpm <= p.engine.max_rpm,
            "{rpm}"
        );
    }
}

/// A drive with steering, speed changes and braking; returns the telemetry of every step.
fn scenario() -> Vec<String> {
    let (mut sim, id) = common::settled(Model::ToyotaPrius, 1.0);
    let mut log = Vec::new();
    for step in 0..600 {
        let d = sim.driver_mut(id).unwrap();
        match step {
            0 => {
                d.set_cruising_speed(50.0);
            }
            200 => {
                d.set_steering_angle(-0.15);
            }
            400 => {
                d.set_throttle(0.0);
                d.set_brake_intensity(0.7);
            }
            _ => {}
        }
        sim.step().unwrap();
        log.push(format!("{:?}", sim.telemetry(id).unwrap()));
    }
    log
}

#[test]
fn the_same_scenario_gives_bit_identical_telemetry() {
    let a = scenario();
    let b = scenario();
    assert_eq!(a.len(), 600);
    assert!(a == b, "telemetry differs");
}

/// Asserts the car's state is finite and sane (on the ground, below 100 m/s).
fn assert_sane(sim: &Simulation, id: sim::VehicleId) {
    let s = sim.telemetry(id).unwrap().state;
    let finite = s.position.iter().chain(&s.velocity).all(|x| x.is_finite())
        && s.wheel_speeds.iter().all(|x| x.is_finite());
    assert!(finite, "{s:?}");
    assert!(s.position.z.abs() < 10.0, "{s:?}");
    let v = s.velocity.iter().map(|x| x * x).sum::<f64>().sqrt();
    assert!(v < 100.0, "{s:?}");
}

#[test]
fn full_reverse_throttle_at_100_kmh_stays_finite() {
    let (mut sim, id) = at_100_kmh(Model::BmwX5);
    let d = sim.driver_mut(id).unwrap();
    d.set_gear(-1);
    d.set_throttle(1.0);
    for _ in 0..500 {
        sim.step().unwrap();
        assert_sane(&sim, id);
    }
    // The engine braked the car and drives it backwards.
    assert!(sim.telemetry(id).unwrap().speed < 27.0);
}

#[test]
fn reverse_cruise_at_100_kmh_stays_finite() {
    let (mut sim, id) = at_100_kmh(Model::TeslaModel3);
    sim.driver_mut(id).unwrap().set_cruising_speed(-50.0);
    for _ in 0..800 {
        sim.step().unwrap();
        assert_sane(&sim, id);
    }
    let v = sim.telemetry(id).unwrap().speed;
    assert!(v < 0.0, "{v}");
}

#[test]
fn full_lock_at_180_kmh_stays_finite() {
    let (mut sim, id) = common::settled(Model::BmwX5, common::GRIPPY);
    sim.driver_mut(id).unwrap().set_cruising_speed(180.0);
    // 180 km/h (the 50 m/s maxVelocity) after 7 s × 1.8 = 12.6 s.
    common::run(&mut sim, 14.0);
    assert!(sim.telemetry(id).unwrap().speed > 49.0);
    // A wheel at 134 rad/s turns 1.34 rad per 10 ms step; car wheels are shape casts with their own
    // spin, not rapier bodies, so the world still takes one rapier step.
    assert_eq!(sim.world().last_substeps(), 1);
    sim.driver_mut(id).unwrap().set_steering_angle(1.0);
    for _ in 0..500 {
        sim.step().unwrap();
        assert_sane(&sim, id);
    }
}

#[test]
fn gear_changes_under_full_throttle_stay_finite() {
    let (mut sim, id) = common::settled(Model::LincolnMKZ, 1.0);
    sim.driver_mut(id).unwrap().set_throttle(1.0);
    for (i, gear) in [1, 2, 3, 4, 5, 6, -1, 0, 1, -1, 3, 0]
        .into_iter()
        .enumerate()
    {
        sim.driver_mut(id).unwrap().set_gear(gear);
        if i % 3 == 2 {
            sim.driver_mut(id).unwrap().set_brake_intensity(1.0);
        } else {
            sim.driver_mut(id).unwrap().set_brake_intensity(0.0);
        }
        for _ in 0..60 {
            sim.step().unwrap();
            assert_sane(&sim, id);
        }
    }
}

#[test]
fn the_telemetry_velocity_is_the_one_the_step_moved_the_car_with() {
    // A step moves the car by its end-of-step velocity × dt (semi-implicit Euler), so the
    // distance of a step over dt is the speed the step reports. A speed read one step late
    // (rapier keeps a multibody link's own velocity from the start of its last step) lags by
    // a·dt: 0.03 m/s for this launch at about 3 m/s². The bound, 2 mm/s, is the f32 rounding
    // of 10 m positions (about 1e-6 m) over 10 ms, with margin.
    let (mut sim, id) = common::settled(Model::BmwX5, 1.0);
    sim.driver_mut(id).unwrap().set_cruising_speed(100.0);
    common::run(&mut sim, 0.5);
    let dt = sim.world().dt();
    let mut x0 = sim.telemetry(id).unwrap().state.position.x;
    let mut lag: f64 = 0.0;
    let mut speed_change: f64 = 0.0;
    for _ in 0..100 {
        let v0 = sim.telemetry(id).unwrap().state.velocity.x;
        sim.step().unwrap();
        let s = sim.telemetry(id).unwrap().state;
        lag = lag.max(((s.position.x - x0) / dt - s.velocity.x).abs());
        speed_change = speed_change.max(s.velocity.x - v0);
        x0 = s.position.x;
    }
    assert!(
        speed_change > 0.02,
        "the launch gained only {speed_change} m/s per step"
    );
    assert!(
        lag < 2e-3,
        "the reported speed is {lag} m/s off the step's motion"
    );
}
