//! Straight lines: with the steering at 0, every shipped car drives straight in speed mode,
//! in torque mode and under full braking, on low, medium and high ground friction, each run as
//! long as its scenario (`accel-speed` and `accel-torque` until 1 s after 100 km/h).
//!
//! A symmetric car on symmetric commands has no reason to turn, but some runs pass through a
//! yaw-unstable phase that amplifies any asymmetry some 10⁵-fold or more: driven wheels that
//! spin (speed mode's ramp beyond the grip: the TeslaModel3's, on friction 0.5, for 9 s), a
//! torque launch beyond the grip (where, before the driven wheels carried their engine's
//! inertia, the Webots driver library's wheel-acceleration limiter switched the torque on and
//! off every few steps; now they spin up past the grip, the TeslaModel3's on 0.5 for its whole
//! run: [`BURNOUT`]), or, with Webots' brakes (the same torque on every wheel), rear wheels
//! that lock while the front ones roll.
//! Spinning and locked wheels keep little side grip, so a real car turns there too; what it
//! turns on is a real asymmetry, never the order of a computation.
//!
//! The cast car is mirror-exact: its mass properties are summed in f64 with mirror-image
//! wheels cancelling, each wheel's impulse is applied whole, the contact solve treats an axle
//! as one block, and every wheel's record sees all four spin reactions. A mirror-symmetric
//! car's heading then stays exactly 0 through every unstable phase, and every run is held to
//! the bounds: |y| ≤ 0.2 % of the distance and |yaw| ≤ 0.01 rad. Two models are not
//! mirror-symmetric in Webots' data. The C-Zero's centre of mass lies 2 mm right of the centre
//! line: it yaws a few mrad, within the bounds. The ToyotaPrius' `inertiaMatrix` has a
//! product `I₁₂ = −300 kg·m²` across the plane of symmetry, coupling roll and pitch: its torque
//! launch on friction 0.5 drifts 0.34 % of its 403 m sideways, so its unstable runs are held
//! to the heading bound only, and the same car with that product removed is held to both.
//!
//! On joints, rapier's f32 multibody and contact solver are not mirror-exact: as the tread's
//! core went from 3 µm to 1 mm the RangeRover's stop on friction 0.5 with Webots' brakes ended
//! anywhere between −0.03 and +0.38 rad. There, runs through spinning wheels or rear wheels
//! locked first are held to no heading, and torque launches beyond the grip to 0.05 rad. The
//! same stops with the brake torque proportioned to the front (`BrakeBalance::Proportioned`,
//! as real cars share it for this reason) are held to the bounds on both mountings.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::common;

use sim::Simulation;
use sim::TyreChoice;
use vehicle_model::{
    AutoShiftParams, BrakeBalance, CarParams, Model, TyreModel, Wheel, WheelDrive,
};

/// How a run drives.
#[derive(Debug, Clone, Copy)]
enum Drive {
    /// Cruise control to 100 km/h (speed mode), as the `accel-speed` scenario: until 1 s
    /// after the speed reaches 99 km/h.
    Speed,
    /// Full throttle with the automatic gearbox (torque mode), as the `accel-torque`
    /// scenario: until 1 s after the speed reaches 100 km/h.
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
    /// Driven wheels spinning at more than twice the ground speed.
    Spinning,
}

/// Drives `model` with `params` on ground friction `mu` and returns (distance along x, y, yaw,
/// the unstable phase it went through).
fn drive(model: Model, params: CarParams<f64>, mu: f64, drive: Drive) -> (f64, f64, f64, Unstable) {
    let tyre = TyreChoice::of_model(model);
    let (mut sim, id) = common::settled_car(params, mu, &tyre, 10);
    let t0100 = sim.driver(id).unwrap().params().time_0_to_100;
    // Long enough for every model to reach 100 km/h on the lowest friction.
    let limit = 3.0 * t0100 + 10.0;
    let unstable = match drive {
        Drive::Speed => {
            sim.driver_mut(id).unwrap().set_cruising_speed(100.0);
            if common::accelerate(&mut sim, id, 99.0, limit).1 {
                Unstable::Spinning
            } else {
                Unstable::No
            }
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
            let (_, spun) = common::accelerate(&mut sim, id, 100.0, limit);
            match (spins, spun) {
                (true, _) => Unstable::Launch,
                (false, true) => Unstable::Spinning,
                (false, false) => Unstable::No,
            }
        }
        Drive::Brake(balance) => {
            sim.driver_mut(id).unwrap().set_cruising_speed(60.0);
            common::run(&mut sim, 0.6 * t0100 + 3.0);
            let d = sim.driver_mut(id).unwrap();
            d.set_brake_balance(balance).unwrap();
            let (_, rear_first) = common::brake_to_rest(&mut sim, id, 20.0);
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

/// The model whose Webots data turn it sideways beyond the bounds through an unstable phase
/// (see the module docs; the C-Zero's asymmetry stays within them).
const ASYMMETRIC: Model = Model::ToyotaPrius;

fn check(model: Model) {
    check_params(model, model.params(), model == ASYMMETRIC);
}

/// Drives `model` with `params` (`asymmetric`: not mirror-symmetric) and checks each run.
fn check_params(model: Model, params: CarParams<f64>, asymmetric: bool) {
    let drives = [
        Drive::Speed,
        Drive::Torque,
        Drive::Brake(BrakeBalance::Equal),
        Drive::Brake(BrakeBalance::Proportioned),
    ];
    let exact = crate::MOUNTING == sim::Mounting::Cast;
    for mu in [0.5, 1.0, 1.5] {
        for d in drives {
            let (x, y, yaw, unstable) = drive(model, params.clone(), mu, d);
            println!(
                "{model} {d:?} mu {mu}: x {x:.1} m, y {y:.2e} m, yaw {yaw:.2e} rad, {unstable:?}"
            );
            assert!(x > 10.0, "{model} {d:?} mu {mu}: moved only {x} m");
            let proportioned = matches!(d, Drive::Brake(BrakeBalance::Proportioned));
            let unstable = if (model, mu) == BURNOUT && matches!(d, Drive::Torque) {
                Unstable::Spinning
            } else {
                unstable
            };
            let amplified = match unstable {
                Unstable::No => false,
                Unstable::RearLockedFirst => !proportioned,
                Unstable::Launch | Unstable::Spinning => true,
            };
            let yaw_bound = match (amplified, exact, unstable) {
                (false, _, _) | (true, true, _) => 0.01,
                (true, false, Unstable::Launch) => 0.05,
                (true, false, _) => continue,
            };
            assert!(
                yaw.abs() <= yaw_bound,
                "{model} {d:?} mu {mu}: yaw {yaw} rad"
            );
            if !(amplified && (asymmetric || !exact)) {
                assert!(
                    y.abs() <= 0.002 * x,
                    "{model} {d:?} mu {mu}: y {y} m after {x} m"
                );
            }
        }
    }
}

/// The torque launch that spins its driven wheels past their grip for the whole run: the
/// TeslaModel3 on friction 0.5. With its machine's inertia on its rear wheels (issue #35,
/// `Commands::driveline`), they no longer chatter under the driver library's limiter but spin
/// up at under its 50 rad/s² to a power-limited burnout (slip ratio 12 at 1 s, still 1.4 at
/// 14 s, at 10 ms), as its speed ramp there does; so it is held as that ramp is
/// (`Spinning`): exactly straight on cast, to no heading on joints, where it turns 0.21 rad
/// by 100 km/h (0.05 rad at 12 s; before, chattering, 0.007).
const BURNOUT: (Model, f64) = (Model::TeslaModel3, 0.5);

/// The ToyotaPrius without its product of inertia across the plane of symmetry is held to both
/// bounds on every run: that product is what turns it (on the mirror-exact cast car).
#[test]
fn mirrored_prius_drives_straight() {
    let mut params = Model::ToyotaPrius.params();
    let inertia = params.body.inertia.as_mut().unwrap();
    assert_eq!(inertia[3], -300.0, "I₁₂ of the Webots data");
    inertia[3] = 0.0;
    check_params(Model::ToyotaPrius, params, false);
}

model_tests! {
    check;
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
