//! Straight lines: with the steering at 0, every shipped car drives straight in speed mode,
//! in torque mode and under full braking, on low, medium and high ground friction.
//!
//! A symmetric car on symmetric commands has no reason to turn: the two wheels of an axle get
//! mirror-image forces (the contact solve treats an axle as one block). What is left is round-off
//! growing through a car whose driven wheels slide (spinning or locked wheels keep little side
//! grip, so the car is yaw-unstable there, as a real one is), and it must stay below 0.2 % of the
//! distance sideways and 0.01 rad of heading. The C-Zero's centre of mass, 2 mm right of the
//! centre line, is a real asymmetry: on four locked wheels its more loaded right tyres have the
//! lower sliding friction (load sensitivity), and it yaws about 3 mrad left over a 180 m stop,
//! within the bound.
//!
//! Every stop is driven twice. With Webots' brakes (the same torque on every wheel), a car
//! whose load moves far enough forward locks its rear wheels while the front ones still roll:
//! yaw-unstable, the yaw growing about five-fold every half second, so its heading at the end is
//! whatever asymmetry the step's rounding left, amplified some 10⁵-fold. The cast car's solve is
//! mirror-exact and keeps such stops straight, held to the bounds above; on joints, rapier's f32
//! multibody is not, and as the tread's core went from 3 µm to 1 mm the RangeRover's stop on
//! friction 0.5 ended anywhere between −0.03 and +0.38 rad, so there those stops are held to no
//! heading. On both mountings, the same stop with the brake torque proportioned to the front
//! (`BrakeBalance::Proportioned`, as real cars share it for this reason) must stop straight, on
//! every model and ground.
//!
//! Some launches are held to another check, for reasons outside the plant. In torque mode, a car
//! whose first-gear torque at standstill exceeds its driven tyres' grip spins them at launch,
//! and the Webots driver library's wheel-acceleration limiter and limited-slip integrator then
//! switch the torque on and off every few steps: a limit cycle that amplifies round-off between
//! the left and right wheels. Those launches are held to a heading within 0.05 rad only, and
//! the cases that miss even that are listed in `UNSTABLE_LAUNCHES`.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::common;

use sim::Simulation;
use vehicle_model::{AutoShiftParams, BrakeBalance, Model, TyreModel, Wheel, WheelDrive};

/// Torque-mode launches that leave even the 0.05 rad bound (see the module docs), with the
/// ground friction: the driver library's limit cycle grows into a turn.
const UNSTABLE_LAUNCHES: [(Model, f64); 1] = [(Model::Bus, 1.5)];

/// How a run drives.
#[derive(Debug, Clone, Copy)]
enum Drive {
    /// Cruise control to 100 km/h (speed mode), for `time0To100` + 3 s.
    Speed,
    /// Full throttle with the automatic gearbox (torque mode), for `time0To100` + 3 s.
    Torque,
    /// Cruise to 60 km/h, then brake intensity 1 with this balance until 1 s after the car
    /// stops.
    Brake(BrakeBalance<f64>),
}

/// A yaw-unstable phase a run went through.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Unstable {
    /// None.
    No,
    /// A launch torque above the driven tyres' grip.
    Launch,
    /// Rear wheels locked while the front ones still rolled.
    RearLockedFirst,
}

/// Drives `model` on ground friction `mu` and returns (distance along x, y, yaw, the unstable
/// phase it went through).
fn drive(model: Model, mu: f64, drive: Drive) -> (f64, f64, f64, Unstable) {
    let (mut sim, id) = common::settled(model, mu);
    let t0100 = sim.driver(id).unwrap().params().time_0_to_100;
    let unstable = match drive {
        Drive::Speed => {
            sim.driver_mut(id).unwrap().set_cruising_speed(100.0);
            common::run(&mut sim, t0100 + 3.0);
            Unstable::No
        }
        Drive::Torque => {
            let d = sim.driver_mut(id).unwrap();
            let auto = AutoShiftParams::for_engine(d.powertrain().engine());
            // A car without an engine model to shift for stays in first gear.
            let _ = d.set_automatic_gearbox(Some(auto));
            d.set_gear(1);
            d.set_throttle(1.0);
            sim.step().unwrap();
            let spins = launch_exceeds_grip(&sim, id, mu);
            common::run(&mut sim, t0100 + 3.0);
            if spins {
                Unstable::Launch
            } else {
                Unstable::No
            }
        }
        Drive::Brake(balance) => {
            sim.driver_mut(id).unwrap().set_cruising_speed(60.0);
            common::run(&mut sim, 0.6 * t0100 + 3.0);
            let d = sim.driver_mut(id).unwrap();
            d.set_brake_balance(balance).unwrap();
            d.set_throttle(0.0);
            d.set_brake_intensity(1.0);
            let mut rear_first = false;
            common::run_until(&mut sim, 20.0, |s| {
                let t = s.telemetry(id).unwrap();
                let locked = |w: Wheel| t.state.tyres[w].slip_ratio < -0.5;
                rear_first |= locked(Wheel::RearRight) && !locked(Wheel::FrontRight);
                t.speed.abs() < 0.01
            });
            common::run(&mut sim, 1.0);
            if rear_first {
                Unstable::RearLockedFirst
            } else {
                Unstable::No
            }
        }
    };
    let s = sim.telemetry(id).unwrap().state;
    (s.position.x, s.position.y, s.roll_pitch_yaw.yaw, unstable)
}

/// True if a wheel's commanded torque exceeds what its tyre can carry at rest: the peak
/// friction × the ground's × its load × its radius.
fn launch_exceeds_grip(sim: &Simulation, id: sim::VehicleId, mu: f64) -> bool {
    let vehicle = sim.world().vehicle(id).unwrap();
    let spec = vehicle.spec();
    let loads = spec.static_wheel_loads();
    let commands = vehicle.commands().unwrap();
    Wheel::ALL.into_iter().any(|w| {
        let WheelDrive::Torque(t) = commands.drive[w] else {
            return false;
        };
        let TyreModel::MagicFormula(tyre) = spec.tyres.of(w) else {
            return false;
        };
        let grip = mu * tyre.params().longitudinal.peak_friction * loads[w] * spec.wheels[w].radius;
        t.abs() > grip
    })
}

fn check(model: Model) {
    let drives = [
        Drive::Speed,
        Drive::Torque,
        Drive::Brake(BrakeBalance::Equal),
        Drive::Brake(BrakeBalance::Proportioned),
    ];
    for mu in [0.5, 1.0, 1.5] {
        for d in drives {
            let (x, y, yaw, unstable) = drive(model, mu, d);
            println!(
                "{model:?} {d:?} mu {mu}: x {x:.1} m, y {y:.2e} m, yaw {yaw:.2e} rad, {unstable:?}"
            );
            assert!(x > 10.0, "{model:?} {d:?} mu {mu}: moved only {x} m");
            let proportioned = matches!(d, Drive::Brake(BrakeBalance::Proportioned));
            // A stop on locked rear wheels: amplified rounding, held straight only by a
            // mirror-exact solve.
            if unstable == Unstable::RearLockedFirst
                && !proportioned
                && crate::MOUNTING == sim::Mounting::Joints
            {
                continue;
            }
            if unstable == Unstable::Launch {
                if UNSTABLE_LAUNCHES.contains(&(model, mu)) {
                    continue;
                }
                assert!(yaw.abs() <= 0.05, "{model:?} {d:?} mu {mu}: yaw {yaw} rad");
            } else {
                assert!(
                    y.abs() <= 0.002 * x,
                    "{model:?} {d:?} mu {mu}: y {y} m after {x} m"
                );
                assert!(yaw.abs() <= 0.01, "{model:?} {d:?} mu {mu}: yaw {yaw} rad");
            }
        }
    }
}

macro_rules! straight_tests {
    ($($name:ident => $model:ident),* $(,)?) => {
        $(
            #[test]
            fn $name() {
                check(Model::$model);
            }
        )*
    };
}

straight_tests! {
    car_drives_straight => Car,
    bmw_x5_drives_straight => BmwX5,
    citroen_c_zero_drives_straight => CitroenCZero,
    toyota_prius_drives_straight => ToyotaPrius,
    lincoln_mkz_drives_straight => LincolnMKZ,
    tesla_model_3_drives_straight => TeslaModel3,
    sprinter_drives_straight => MercedesBenzSprinter,
    bus_drives_straight => Bus,
    truck_drives_straight => Truck,
    tractor_drives_straight => Tractor,
}

#[test]
fn range_rover_drives_straight() {
    check(Model::RangeRoverSportSVR);
}

#[test]
fn ev_star_drives_straight() {
    check(Model::GreenPowerEVStar);
}
