//! A wheel's slip transient under a sudden full brake, at every step: what an ABS controller
//! acts on. A braked wheel's spin and slip ratio advance in sub-steps of at most 1 ms within
//! the step (with the chassis' motion and the load of a first solve of the step), so the wheel
//! dives toward lock about as deep at 10 and 32 ms as at 1 ms; before, the step's end force
//! taken over the whole first step spun it back up, and the dive was first order in the
//! step.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::common;

use sim::TyreChoice;
use vehicle_model::{BrakeBalance, Model, Wheel};

/// A BmwX5 with proportioned brakes on friction 1 braking at intensity 1 from `kmh` (km/h)
/// with a `dt_ms` step: its stopping distance (m) and when its front-left wheel locks (s after
/// the brake, `None` if it never does before the car is down to 1 m/s).
fn sudden_brake(kmh: f64, dt_ms: u32) -> (f64, Option<f64>) {
    let tyre = TyreChoice::of_model(Model::BmwX5);
    let (mut sim, id) = common::settled_with_step(Model::BmwX5, 1.0, &tyre, dt_ms);
    let d = sim.driver_mut(id).unwrap();
    d.set_brake_balance(BrakeBalance::Proportioned).unwrap();
    d.set_cruising_speed(kmh);
    common::run_until(&mut sim, 30.0, |s| {
        s.telemetry(id).unwrap().speed >= (kmh - 1.0) / 3.6
    })
    .unwrap();
    common::run(&mut sim, 2.0);
    let x0 = sim.telemetry(id).unwrap().state.position.x;
    let d = sim.driver_mut(id).unwrap();
    d.set_cruising_speed(0.0);
    d.set_throttle(0.0);
    d.set_brake_intensity(1.0);
    let dt = f64::from(dt_ms) / 1000.0;
    let mut lock = None;
    for k in 1..=(20.0 / dt) as usize {
        sim.step().unwrap();
        let t = sim.telemetry(id).unwrap();
        // A wheel at rest while the car still moves at over 1 m/s is locked.
        if lock.is_none() && t.state.wheel_speeds[Wheel::FrontLeft].abs() < 0.01 && t.speed > 1.0 {
            lock = Some(k as f64 * dt);
        }
        if t.speed < 0.01 {
            break;
        }
    }
    (sim.telemetry(id).unwrap().state.position.x - x0, lock)
}

#[test]
fn a_sudden_full_brake_locks_the_front_wheels_at_every_step() {
    // Proportioned brakes set for 1 g ask the X5's tyres on friction 1 for 93 % of their grip
    // on both axles; the first dip of the front slip after the brake goes past the tyre's peak
    // and the fronts lock, 0.44 s after the brake at 1 ms (0.54 s on joints). How deep that
    // dip goes decides it, and the stop takes about 2 s: a wheel that rides the dip out locks
    // only as the car comes to rest (1.8 s). Before the sub-steps that happened from 3 ms up,
    // and the car stopped 11 % shorter at 10 ms, on rolling wheels (14.9 m against 16.9 m).
    let (reference, reference_lock) = sudden_brake(60.0, 1);
    for dt in [1, 5, 10, 32] {
        let (d, lock) = if dt == 1 {
            (reference, reference_lock)
        } else {
            sudden_brake(60.0, dt)
        };
        println!("{dt} ms: {d:.3} m, fronts lock at {lock:?} s");
        // Within the 3 % that #11 asks of basicTimeStep 1, 10 and 32 ms.
        assert!(
            (d / reference - 1.0).abs() < 0.03,
            "{dt} ms: {d} m vs {reference} m"
        );
        // In the first dive: within the first 0.6 s of the 2 s stop. The lock time itself is
        // not compared across steps: it is where the dip crosses the peak, a knife-edge (cast:
        // 0.46, 0.45 and 0.35 s at 5, 10 and 32 ms; joints: 0.41, 0.36 and 0.32 s).
        let lock = lock.unwrap_or_else(|| panic!("{dt} ms: the fronts never lock"));
        assert!(lock < 0.6, "{dt} ms: the fronts lock at {lock} s");
    }
}

#[test]
fn a_full_brake_that_does_not_lock_at_1_ms_does_not_lock_at_32_ms() {
    // The same car from 100 km/h: at 1 ms the front slip's first dip stays short of the peak
    // and no wheel locks (40.9 m). A step's sub-steps take the chassis' slowing and the load
    // moving forward over the step from a first solve of it: holding them at the step's start,
    // 32 ms steps under-stated the front load by a tenth in the first steps, the fronts
    // locked and the car stopped 12 % longer.
    let (reference, reference_lock) = sudden_brake(100.0, 1);
    assert_eq!(reference_lock, None);
    for dt in [10, 32] {
        let (d, lock) = sudden_brake(100.0, dt);
        println!("{dt} ms: {d:.3} m (1 ms: {reference:.3} m), fronts lock at {lock:?} s");
        assert_eq!(lock, None, "{dt} ms");
        // The 3 % of #11, as above.
        assert!(
            (d / reference - 1.0).abs() < 0.03,
            "{dt} ms: {d} m vs {reference} m"
        );
    }
}
