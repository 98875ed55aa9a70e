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
    use vehicle_model::Model;
    let (mut sim, id) = common::settled(Model::BmwX5, 0.5);
    sim.driver_mut(id).unwrap().set_cruising_speed(100.0);
    let (reached, spun) = common::accelerate(&mut sim, id, 99.0, 30.0);
    assert!(reached.is_some() && spun);
    let s = sim.telemetry(id).unwrap().state;
    assert_eq!((s.position.y, s.roll_pitch_yaw.yaw), (0.0, 0.0));

    let (mut sim, id) = common::settled(Model::BmwX5, 1.0);
    sim.driver_mut(id).unwrap().set_cruising_speed(60.0);
    common::run(&mut sim, 10.0);
    let (stopped, rear_first) = common::brake_to_rest(&mut sim, id, 10.0);
    assert!(stopped.is_some() && rear_first);
    let s = sim.telemetry(id).unwrap().state;
    assert!(s.position.x > 20.0);
    assert_eq!((s.position.y, s.roll_pitch_yaw.yaw), (0.0, 0.0));
}
