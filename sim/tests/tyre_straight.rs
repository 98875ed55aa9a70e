//! Straight lines: with the steering at 0, every shipped car drives straight in speed mode,
//! in torque mode and under full braking, on low, medium and high ground friction.
//!
//! A symmetric car on symmetric commands has no reason to turn: the two wheels of an axle get
//! mirror-image forces (the contact solve treats an axle as one block). What is left is round-off
//! growing through a car whose driven wheels slide (spinning or locked wheels keep little side
//! grip, so the car is yaw-unstable there, as a real one is), and it must stay below 0.2 % of the
//! distance sideways and 0.01 rad of heading.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use sim::{Simulation, VehiclePlacement, World, WorldConfig};
use vehicle_model::{AutoShiftParams, Model};

/// How a run drives.
#[derive(Debug, Clone, Copy)]
enum Drive {
    /// Cruise control to 100 km/h (speed mode), for `time0To100` + 3 s.
    Speed,
    /// Full throttle with the automatic gearbox (torque mode), for `time0To100` + 3 s.
    Torque,
    /// Cruise to 60 km/h, then brake intensity 1 until 1 s after the car stops.
    Brake,
}

/// Drives `model` on ground friction `mu` and returns (distance along x, |y|, |yaw|).
fn drive(model: Model, mu: f64, drive: Drive) -> (f64, f64, f64) {
    let world = World::new(WorldConfig {
        ground_friction: mu,
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let (id, _) = sim
        .add_car(model.params(), VehiclePlacement::default())
        .unwrap();
    common::run(&mut sim, 0.5);
    let t0100 = sim.driver(id).unwrap().params().time_0_to_100;
    match drive {
        Drive::Speed => {
            sim.driver_mut(id).unwrap().set_cruising_speed(100.0);
            common::run(&mut sim, t0100 + 3.0);
        }
        Drive::Torque => {
            let d = sim.driver_mut(id).unwrap();
            let auto = AutoShiftParams::for_engine(d.powertrain().engine());
            // A car without an engine model to shift for stays in first gear.
            let _ = d.set_automatic_gearbox(Some(auto));
            d.set_gear(1);
            d.set_throttle(1.0);
            common::run(&mut sim, t0100 + 3.0);
        }
        Drive::Brake => {
            sim.driver_mut(id).unwrap().set_cruising_speed(60.0);
            common::run(&mut sim, 0.6 * t0100 + 3.0);
            let d = sim.driver_mut(id).unwrap();
            d.set_throttle(0.0);
            d.set_brake_intensity(1.0);
            common::run_until(&mut sim, 20.0, |s| {
                s.telemetry(id).unwrap().speed.abs() < 0.01
            });
            common::run(&mut sim, 1.0);
        }
    }
    let s = sim.telemetry(id).unwrap().state;
    (
        s.position[0],
        s.position[1].abs(),
        s.roll_pitch_yaw[2].abs(),
    )
}

fn check(model: Model) {
    let mut worst = (0.0_f64, 0.0_f64);
    for mu in [0.5, 1.0, 1.5] {
        for d in [Drive::Speed, Drive::Torque, Drive::Brake] {
            let (x, y, yaw) = drive(model, mu, d);
            println!("{model:?} {d:?} mu {mu}: x {x:.1} m, y {y:.2e} m, yaw {yaw:.2e} rad");
            if !(x > 10.0 && y <= 0.002 * x && yaw <= 0.01) {
                println!("FAIL {model:?} {d:?} mu {mu}: x {x:.1} y {y:.3} yaw {yaw:.4}");
            }
            worst = (worst.0.max(y / x), worst.1.max(yaw));
        }
    }
    println!(
        "{model:?}: worst y/x {:.2e}, worst yaw {:.2e} rad",
        worst.0, worst.1
    );
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
    range_rover_drives_straight => RangeRoverSportSVR,
    tesla_model_3_drives_straight => TeslaModel3,
    sprinter_drives_straight => MercedesBenzSprinter,
    ev_star_drives_straight => GreenPowerEVStar,
    bus_drives_straight => Bus,
    truck_drives_straight => Truck,
    tractor_drives_straight => Tractor,
}
