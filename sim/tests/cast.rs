//! The car suite (`suite/`) on the cast mounting: one rigid chassis on four shape-cast wheels.

// Helpers outside `#[test]` functions unwrap too: clippy.toml only exempts test bodies.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;
mod suite;

/// The mounting every car of the suite is built on.
const MOUNTING: sim::Mounting = sim::Mounting::Cast;

/// The cast car is mirror-exact (see `suite/tyre_straight.rs`): a mirror-symmetric BmwX5 (its
/// only product of inertia, `I₁₃`, lies in the plane of symmetry) stays exactly on its line
/// through its speed ramp on friction 0.5, which spins its front wheels at more than twice the
/// ground speed, and through a stop with Webots' equal brakes on friction 1, which locks its
/// rear wheels first: both yaw-unstable, so any left-right round-off would show.
#[test]
fn a_mirror_symmetric_car_stays_exactly_on_its_line() {
    use vehicle_model::{Model, Wheel};
    let (mut sim, id) = common::settled(Model::BmwX5, 0.5);
    sim.driver_mut(id).unwrap().set_cruising_speed(100.0);
    let mut spun = false;
    common::run_until(&mut sim, 30.0, |s| {
        let t = s.telemetry(id).unwrap();
        spun |= t.state.tyres[Wheel::FrontLeft].slip_ratio > 1.0;
        t.speed * 3.6 >= 99.0
    })
    .unwrap();
    assert!(spun);
    let s = sim.telemetry(id).unwrap().state;
    assert_eq!((s.position.y, s.roll_pitch_yaw.yaw), (0.0, 0.0));

    let (mut sim, id) = common::settled(Model::BmwX5, 1.0);
    sim.driver_mut(id).unwrap().set_cruising_speed(60.0);
    common::run(&mut sim, 10.0);
    let d = sim.driver_mut(id).unwrap();
    d.set_cruising_speed(0.0);
    // Torque mode: the speed-mode motors would overpower the brakes.
    d.set_throttle(0.0);
    d.set_brake_intensity(1.0);
    let mut rear_first = false;
    common::run_until(&mut sim, 10.0, |s| {
        let t = s.telemetry(id).unwrap();
        let locked = |w: Wheel| t.state.tyres[w].slip_ratio < -0.5;
        rear_first |= locked(Wheel::RearLeft) && !locked(Wheel::FrontLeft);
        t.speed < 0.01
    })
    .unwrap();
    assert!(rear_first);
    let s = sim.telemetry(id).unwrap().state;
    assert!(s.position.x > 20.0);
    assert_eq!((s.position.y, s.roll_pitch_yaw.yaw), (0.0, 0.0));
}
