//! Stability on the slip-based tyre: stops alike at every step size, step steers that must
//! not spin a shipped model (on the throttle and in speed mode), and braking within the grip
//! that follows the brake torque. The single-track comparisons are in `tyre_handling.rs`.

use super::tyre_handling::body_slip;
use crate::common;

use sim::Simulation;
use sim::TyreChoice;
use vehicle_model::{AutoShiftParams, BrakeBalance, Model, TyreModel, Wheel};

/// Stopping distance (m) of `model` on its tyres on friction 1 braking at intensity 1 with
/// `balance` from 60 km/h, with a `dt_ms` step.
fn stopping_distance(model: Model, balance: BrakeBalance<f64>, dt_ms: u32) -> f64 {
    let tyre = TyreChoice::of_model(model);
    let (mut sim, id) = common::settled_with_step(model, 1.0, &tyre, dt_ms);
    let d = sim.driver_mut(id).unwrap();
    d.set_brake_balance(balance).unwrap();
    d.set_cruising_speed(60.0);
    common::run_until(&mut sim, 60.0, |s| {
        s.telemetry(id).unwrap().speed >= 59.0 / 3.6
    })
    .unwrap();
    common::run(&mut sim, 3.0);
    let x0 = sim.telemetry(id).unwrap().state.position.x;
    common::brake_to_rest(&mut sim, id, 10.0).0.unwrap();
    sim.telemetry(id).unwrap().state.position.x - x0
}

/// Every pair of 1, 10 and 32 ms steps stops within 3 % of each other, with both brake
/// balances. The 1-to-32 ms spread is mostly rapier's semi-implicit Euler, which shortens a
/// stop by about v₀·dt/2 (0.27 m at 32 ms from 60 km/h, 1.5 % of the TeslaModel3's 18 m).
fn stops_alike_at_every_step(model: Model) {
    for balance in [BrakeBalance::Equal, BrakeBalance::Proportioned] {
        let d = [1, 10, 32].map(|dt| stopping_distance(model, balance, dt));
        println!(
            "{model} {balance:?}: {:.3} / {:.3} / {:.3} m at 1 / 10 / 32 ms",
            d[0], d[1], d[2]
        );
        let (shortest, longest) = (
            d.iter().copied().fold(f64::MAX, f64::min),
            d.iter().copied().fold(0.0, f64::max),
        );
        assert!(
            longest / shortest - 1.0 < 0.03,
            "{model} {balance:?}: {d:?} m"
        );
    }
}

model_tests! {
    stops_alike_at_every_step;
    car_stops_alike_at_every_step => Car,
    bmw_x5_stops_alike_at_every_step => BmwX5,
    citroen_c_zero_stops_alike_at_every_step => CitroenCZero,
    toyota_prius_stops_alike_at_every_step => ToyotaPrius,
    lincoln_mkz_stops_alike_at_every_step => LincolnMKZ,
    range_rover_stops_alike_at_every_step => RangeRoverSportSVR,
    tesla_model_3_stops_alike_at_every_step => TeslaModel3,
    sprinter_stops_alike_at_every_step => MercedesBenzSprinter,
    ev_star_stops_alike_at_every_step => GreenPowerEVStar,
    bus_stops_alike_at_every_step => Bus,
    truck_stops_alike_at_every_step => Truck,
    tractor_stops_alike_at_every_step => Tractor,
}

/// How a step-steer run holds its speed.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Hold {
    /// Speed mode: Webots' cruise control, whose 1e8 N·m motors pin the driven wheels at the
    /// target speed whatever the tyres can carry.
    Cruise,
    /// Torque mode with the automatic gearbox, the throttle set each step by a driver holding
    /// 20 m/s ([`ThrottleDriver`]): the engine's torque, not an ideal motor.
    Throttle,
    /// As [`Hold::Throttle`] up to the step, then the throttle kept where it was: an open-loop
    /// test, the driver correcting neither the steering nor the throttle.
    OpenLoop,
}

/// The driver of [`Hold::Throttle`]: a proportional-integral throttle on the speed error to
/// 20 m/s (0.5 per m/s, and 0.2 per m of distance lost), the integral frozen while the throttle
/// is saturated so that it does not wind up during the launch.
#[derive(Debug, Default)]
struct ThrottleDriver {
    /// The integral of the speed error (m).
    integral: f64,
}

impl ThrottleDriver {
    /// The throttle (0 to 1) at speed `v` (m/s) after a step of `dt` (s).
    fn throttle(&mut self, v: f64, dt: f64) -> f64 {
        let error = 20.0 - v;
        let unclamped = 0.5 * error + 0.2 * (self.integral + error * dt);
        if (0.0..=1.0).contains(&unclamped) {
            self.integral += error * dt;
        }
        unclamped.clamp(0.0, 1.0)
    }
}

/// The largest body slip angle (rad) of `model` on its tyres over 15 s after a step steer of
/// `delta` (rad) at 20 m/s, the speed held by `hold`: long enough for the slow divergence of a
/// car that is only just stable to show.
fn step_steer_body_slip(model: Model, delta: f64, hold: Hold) -> f64 {
    let (mut sim, id) = common::settled_car(model.params(), 1.0, &TyreChoice::of_model(model), 10);
    let mut driver = ThrottleDriver::default();
    let mut throttle = |sim: &mut Simulation, stepped: bool| {
        if hold == Hold::Throttle || (hold == Hold::OpenLoop && !stepped) {
            let v = sim.telemetry(id).unwrap().speed;
            let t = driver.throttle(v, sim.world().dt());
            sim.driver_mut(id).unwrap().set_throttle(t);
        }
    };
    let d = sim.driver_mut(id).unwrap();
    match hold {
        Hold::Cruise => {
            d.set_cruising_speed(72.0);
        }
        Hold::Throttle | Hold::OpenLoop => {
            let auto = AutoShiftParams::for_engine(d.powertrain().engine());
            // A car without an engine model to shift for stays in first gear.
            let _ = d.set_automatic_gearbox(Some(auto));
            d.set_gear(1);
        }
    }
    // The Bus and the Truck take about 30 s to reach it. Within 1 %: in speed mode the driven
    // tyres slip by a few per mille to hold the speed.
    for _ in 0..6000 {
        if sim.telemetry(id).unwrap().speed >= 19.8 {
            break;
        }
        throttle(&mut sim, false);
        sim.step().unwrap();
    }
    let v = sim.telemetry(id).unwrap().speed;
    assert!(v >= 19.8, "{model:?} reaches only {v} m/s ({hold:?})");
    for _ in 0..200 {
        throttle(&mut sim, false);
        sim.step().unwrap();
    }
    sim.driver_mut(id).unwrap().set_steering_angle(delta);
    let mut worst: f64 = 0.0;
    for _ in 0..1500 {
        throttle(&mut sim, true);
        sim.step().unwrap();
        worst = worst.max(body_slip(&sim.telemetry(id).unwrap().state).abs());
    }
    worst
}

/// [`step_steer_body_slip`], checked not to spin: a car that spins turns past 45° of body
/// slip (π rad within the 15 s).
fn settles(model: Model, delta: f64, hold: Hold) -> f64 {
    let worst = step_steer_body_slip(model, delta, hold);
    println!("{model:?}, {delta} rad ({hold:?}): largest body slip angle {worst:.4} rad");
    assert!(
        worst < std::f64::consts::FRAC_PI_4,
        "{model:?} spun: body slip {worst} rad"
    );
    worst
}

/// Rear-heavy, rear-driven models that oversteer on their equal tyres (next tests).
const OVERSTEERING: [Model; 2] = [Model::CitroenCZero, Model::TeslaModel3];

#[test]
fn step_steers_do_not_spin_any_shipped_model() {
    // 0.05 rad at 20 m/s with the models' own wheelsDampingConstant, open loop as in ISO 7401's
    // step steer: the throttle that held 20 m/s straight ahead is kept through the turn, and
    // the car slows by its cornering drag. Measured on the cast car (joints within 5 % of
    // it): the passenger cars settle between 0.031 and 0.059 rad (the C-Zero), the Tractor
    // (asked for more than its grip) ploughs on at 0.068, and on their commercial tyres the
    // van settles at 0.083 and the minibus at 0.116.
    for model in Model::ALL {
        settles(model, 0.05, Hold::OpenLoop);
    }
}

#[test]
fn step_steers_held_at_speed_on_the_throttle_spin_only_the_c_zero_on_joints() {
    // The same step with a driver who keeps 20 m/s on the throttle ([`ThrottleDriver`]):
    // every model ends the 15 s at 20 m/s but the EV Star, whose motor leaves it at 19.1. The
    // extra drive goes to the rear wheels of the rear-driven cars, and Webots' limited-slip
    // differential (an integrator that saturates in a steady turn) sends most of it to the
    // inner, least loaded one. The passenger cars settle under 0.08 rad, the van, the minibus
    // and the Tractor under 0.11; the C-Zero, asked for v²·δ/L = 7.8 m/s², oversteering, is
    // at its limit: it settles at 0.07 rad on the cast car, twice the other passenger cars,
    // and on joints (whose wheels are bodies of their own, loaded through rapier's contacts,
    // with about 5 % more load transfer) it spins, either way, from 0.05 rad, while 0.045 rad
    // settles there at 0.06 rad. Held by Webots' speed-mode motors instead, the C-Zero, the
    // Tesla and the Tractor spin (next tests).
    for model in Model::ALL {
        let edge = model == Model::CitroenCZero && crate::MOUNTING == sim::Mounting::Joints;
        let delta = if edge {
            let full = step_steer_body_slip(model, 0.05, Hold::Throttle);
            assert!(full > std::f64::consts::FRAC_PI_4, "{model:?}: {full} rad");
            0.045
        } else {
            0.05
        };
        settles(model, delta, Hold::Throttle);
    }
}

#[test]
fn speed_mode_step_steers_spin_only_the_cars_they_overdrive() {
    // The same step with the speed held by Webots' cruise control. The passenger cars settle
    // under 0.1 rad; the van on its commercial tyres (0.8 μ, 10 F_z per rad) at 0.15 rad, and
    // the minibus keeps sliding between about 0.12 and 0.23 rad.
    for model in Model::ALL {
        if OVERSTEERING.contains(&model) {
            continue;
        }
        // The Tractor (1.76 m wheelbase) is asked for v²·δ/L = 11.4 m/s² on tyres whose side
        // friction gives at most 0.7·g = 6.9 m/s²: driven beyond its grip, its wheels pinned at
        // the cruising speed, it slides and spins (on the throttle it ploughs on, above).
        if model == Model::Tractor {
            let asked = 20.0 * 20.0 * 0.05 / model.params::<f64>().wheelbase;
            let grip = model.tyre_class().params(0.6, 5000.0).lateral.peak_friction * 9.81;
            assert!(asked > 1.5 * grip, "{asked} m/s² vs {grip} m/s²");
            assert!(step_steer_body_slip(model, 0.05, Hold::Cruise) > std::f64::consts::FRAC_PI_4);
            continue;
        }
        settles(model, 0.05, Hold::Cruise);
    }
}

#[test]
fn rear_heavy_rear_driven_cars_spin_in_speed_mode_only_near_their_grip() {
    // The C-Zero (2.55 m wheelbase) and the TeslaModel3 (2.875 m) carry 54 % and 56 % of their
    // weight on the driven rear axle, on the same tyre front and rear and (as in Webots) with
    // no anti-roll bars. Load sensitivity then gives the heavier axle less grip per newton:
    // they oversteer (the Tesla turns 5.6 % tighter than L/tan δ at 3.6 m/s²). In speed mode
    // the rear tyres also carry whatever drive holds the wheels at the cruising speed, against
    // the wheel damping (the Tesla's 3 N·m·s/rad costs 480 N per wheel at 20 m/s) and the
    // cornering drag. Asked for v²·δ/L = 7.8 and 7.0 m/s² by a 0.05 rad step at 20 m/s, their
    // rear tyres run out of grip and they spin: the C-Zero within 5 s, the Tesla after about
    // 12 s of slow divergence. Half the step is well within their grip and they settle; on the
    // throttle the full step settles too (above).
    for model in OVERSTEERING {
        let half = step_steer_body_slip(model, 0.025, Hold::Cruise);
        println!("{model:?}, 0.025 rad: largest body slip angle {half:.4} rad");
        assert!(half < 0.1, "{model:?}: {half}");
        let full = step_steer_body_slip(model, 0.05, Hold::Cruise);
        println!("{model:?}, 0.05 rad: largest body slip angle {full:.4} rad");
        assert!(full > std::f64::consts::FRAC_PI_4, "{model:?}: {full}");
    }
}

#[test]
fn braking_within_the_grip_follows_the_brake_torque() {
    // BmwX5 from 100 km/h at brake intensity 1 on friction 1.5 (the brakes, not the tyres, are
    // the limit). The deceleration is the brake force 4·brakeCoefficient/r, plus the tyres'
    // rolling resistance and the wheels' viscous damping c·ω/r, over the mass plus the wheels'
    // spin inertia I/r²: a = (A + B·v)/M, and the car stops in
    // d = v₀/B' − (A'/B'²)·ln(1 + B'·v₀/A') with A' = A/M, B' = B/M.
    for tyre in [TyreChoice::of_model(Model::BmwX5), common::webots_tyre()] {
        let (mut sim, id) = common::settled_car(Model::BmwX5.params(), common::GRIPPY, &tyre, 10);
        sim.driver_mut(id).unwrap().set_cruising_speed(100.0);
        common::run_until(&mut sim, 20.0, |s| {
            s.telemetry(id).unwrap().speed >= 99.0 / 3.6
        })
        .unwrap();
        let spec = *sim.world().vehicle(id).unwrap().spec();
        let p = sim.driver(id).unwrap().params().clone();
        let loads = spec.static_wheel_loads();
        let (mut m, mut a, mut b) = (spec.chassis.mass, 0.0, 0.0);
        for w in Wheel::ALL {
            let s = spec.wheels[w];
            m += s.mass + s.spin_inertia() / (s.radius * s.radius);
            a += p.brake_coefficient / s.radius;
            if let TyreModel::MagicFormula(t) = spec.tyres.of(w) {
                a += t.params().rolling_resistance * loads[w];
            }
            b += p.wheels_damping_constant / (s.radius * s.radius);
        }
        let (a, b) = (a / m, b / m);
        let s0 = sim.telemetry(id).unwrap();
        let (v0, x0) = (s0.speed, s0.state.position.x);
        let d = sim.driver_mut(id).unwrap();
        d.set_throttle(0.0);
        d.set_brake_intensity(1.0);
        common::run_until(&mut sim, 10.0, |s| s.telemetry(id).unwrap().speed < 0.01).unwrap();
        let distance = sim.telemetry(id).unwrap().state.position.x - x0;
        let expected = v0 / b - a / (b * b) * (1.0 + b * v0 / a).ln();
        println!(
            "{tyre:?}: stopped from {v0:.2} m/s in {distance:.2} m (expected {expected:.2} m; \
             brakes alone over the mass: {:.2} m)",
            v0 * v0 / (2.0 * 4.0 * p.brake_coefficient / 0.374 / m)
        );
        assert!(
            (distance / expected - 1.0).abs() < 0.03,
            "{distance} vs {expected}"
        );
    }
}
