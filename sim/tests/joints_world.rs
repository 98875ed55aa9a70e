//! What only the joints mounting can show: wheels that meet steps and other cars, a steering
//! hinge that holds its command, and the two mountings driving `test-track` alike.

// Helpers outside `#[test]` functions unwrap too: clippy.toml only exempts test bodies.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use ackermann::Wheel;
use sim::nalgebra::{Point3, Vector3};
use sim::scenario::{self, Scenario, Value};
use sim::world_file;
use sim::{
    BodySpec, Mounting, Obstacle, Simulation, TyreChoice, VehicleId, VehiclePlacement, World,
    WorldConfig,
};
use vehicle_model::{BrakeBalance, Model};

mod common;

/// The mounting of the shared car helpers (`common`).
const MOUNTING: Mounting = Mounting::Joints;

/// A BmwX5 on joints at `placement` in `sim`.
fn add_x5(sim: &mut Simulation, placement: VehiclePlacement) -> VehicleId {
    let tyre = TyreChoice::of_model(Model::BmwX5);
    let (id, _) = sim
        .add_car(
            sim::CarBuilder::new(Model::BmwX5.params())
                .tyre(tyre.clone())
                .mounting(MOUNTING)
                .placement(placement),
        )
        .unwrap();
    id
}

#[test]
fn the_steering_holds_its_command_at_rest() {
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let id = add_x5(&mut sim, VehiclePlacement::default());
    common::run(&mut sim, 1.0);
    sim.driver_mut(id).unwrap().set_steering_angle(0.3);
    common::run(&mut sim, 2.0);
    // The Ackermann angles of a 0.3 rad command on the X5 (L 2.995 m, track 1.628 m):
    // atan(L/(L/tan 0.3 ∓ T/2)), the inner (right) wheel steered more.
    let (l, t) = (2.995_f64, 1.628_f64);
    let radius = l / 0.3_f64.tan();
    let right = (l / (radius - t / 2.0)).atan();
    let left = (l / (radius + t / 2.0)).atan();
    for _ in 0..100 {
        sim.step().unwrap();
        let s = sim.telemetry(id).unwrap().state.steering;
        assert!(
            (s.right - right).abs() < 0.005,
            "right {} vs {right}",
            s.right
        );
        assert!((s.left - left).abs() < 0.005, "left {} vs {left}", s.left);
    }
}

#[test]
fn a_car_drives_up_a_ten_centimetre_step_on_its_wheels() {
    // A 10 cm step up onto a raised road from x = 5 m (the X5's front tyres touch its edge
    // at once: 2.995 + 0.374 m ahead of the rear axle); the tyres (0.374 m radius) meet the
    // edge below their centres and climb it.
    let step = Obstacle::Box {
        center: Point3::new(55.0, 0.0, 0.05),
        half_extents: Vector3::new(50.0, 5.0, 0.05),
        yaw: 0.0,
        friction: None,
        radar_cross_section: 0.0,
    };
    let mut sim = Simulation::new(
        World::new(WorldConfig {
            obstacles: vec![step],
            ..WorldConfig::default()
        })
        .unwrap(),
    );
    let id = add_x5(&mut sim, VehiclePlacement::default());
    common::run(&mut sim, 1.0);
    let z0 = sim.telemetry(id).unwrap().state.position.z;
    sim.driver_mut(id).unwrap().set_cruising_speed(10.0);
    let mut lost = 0;
    for _ in 0..1500 {
        sim.step().unwrap();
        let s = sim.telemetry(id).unwrap().state;
        if s.position.x > 1.0 && s.tyres.iter().any(|t| t.fz <= 0.0) {
            lost += 1;
        }
    }
    let s = sim.telemetry(id).unwrap().state;
    // All four wheels on the step: the car 10 cm higher, still rolling straight.
    assert!(s.position.x > 8.0, "stuck at x = {} m", s.position.x);
    assert!(
        (s.position.z - z0 - 0.1).abs() < 0.01,
        "ride height {} m, {} m before the step",
        s.position.z,
        z0
    );
    // Straight on: the kerb's square edge meets both front tyres in the same step, but
    // rapier solves the two contacts one after the other, so the car may leave the edge
    // turned by up to 0.02 rad; the lateral offset follows from that heading.
    assert!(s.roll_pitch_yaw.yaw.abs() < 0.02, "{s:?}");
    assert!(s.position.y.abs() < 0.02 * s.position.x, "{s:?}");
    // A wheel may leave the ground for a step or two as it hops onto the edge (the
    // suspension is soft, the edge square): at most 0.1 s in all.
    assert!(lost <= 10, "wheels off the ground for {lost} steps");
    assert!(s.tyres[Wheel::RearLeft].fz > 0.0);
}

#[test]
fn two_cars_meeting_head_on_do_not_interpenetrate() {
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let a = add_x5(&mut sim, VehiclePlacement::default());
    let b = add_x5(
        &mut sim,
        VehiclePlacement {
            x: 20.0,
            yaw: std::f64::consts::PI,
            ..VehiclePlacement::default()
        },
    );
    common::run(&mut sim, 1.0);
    for id in [a, b] {
        sim.driver_mut(id).unwrap().set_cruising_speed(20.0);
    }
    // Each car's front (its tyres' and its box's front) is L + r = 3.369 m ahead of its origin.
    let reach = 2.995 + 0.374;
    let mut closest = f64::INFINITY;
    let mut met = None;
    let mut settled_overlap: f64 = 0.0;
    for k in 0..600 {
        sim.step().unwrap();
        let xa = sim.telemetry(a).unwrap().state.position.x;
        let xb = sim.telemetry(b).unwrap().state.position.x;
        let gap = (xb - reach) - (xa + reach);
        closest = closest.min(gap);
        if gap < 0.0 && met.is_none() {
            met = Some(k);
        }
        if met.is_some_and(|m| k > m + 50) {
            settled_overlap = settled_overlap.max(-gap);
        }
    }
    assert!(met.is_some(), "the cars never met: gap {closest} m");
    // rapier finds contacts at the start of a step, within its prediction distance (2 cm), and
    // does not sweep (no CCD): cars 2 cm + ε apart close a whole step's approach,
    // 2 × 20/3.6 m/s × 10 ms = 0.111 m, before their contact exists, so they may overlap by
    // 0.111 − 0.02 m, plus rapier's allowed linear error (5 mm).
    let one_step = 2.0 * 20.0 / 3.6 * 0.01;
    let bound = one_step - 0.02 + 0.005;
    assert!(closest > -bound, "the cars overlap by {} m", -closest);
    // Then the contact holds them apart, still pushing, within rapier's allowed linear error
    // (5 mm).
    assert!(
        settled_overlap < 0.005,
        "the cars overlap by {settled_overlap} m 0.5 s after meeting"
    );
}

#[test]
fn a_car_pushes_a_200_kg_box_with_its_front_wheels() {
    // A 200 kg box 0.3 m high: below the chassis box (which starts at the wheel centres,
    // 0.32 m up at rest), so only the front tyres reach it. Its near face 1 m ahead of the
    // X5's front tyres. Sliding it takes μ·m·g = 1 × 200 × 9.81 = 1.96 kN; pushed at its top
    // edge (0.3 m) that is a moment of 589 N·m about its front bottom edge, above its weight's
    // 200 × 9.81 × 0.25 = 491 N·m: the box tilts forward onto that edge as it slides.
    let front = 2.995 + 0.374;
    let size = Vector3::new(0.5, 3.0, 0.3);
    let near = front + 1.0;
    let body = BodySpec {
        center: Point3::new(near + size.x / 2.0, 0.0, size.z / 2.0),
        size,
        yaw: 0.0,
        mass: 200.0,
        friction: None,
        radar_cross_section: 0.0,
    };
    let mut sim = Simulation::new(
        World::new(WorldConfig {
            bodies: vec![body],
            ..WorldConfig::default()
        })
        .unwrap(),
    );
    let id = add_x5(&mut sim, VehiclePlacement::default());
    common::run(&mut sim, 1.0);
    sim.driver_mut(id).unwrap().set_cruising_speed(5.0);
    common::run(&mut sim, 10.0);
    let car = sim.telemetry(id).unwrap().state;
    let b = sim.world().bodies()[0];
    // 1.96 kN is well within the X5's drive: the car keeps pushing, its front tyres against
    // the box's near face (measured along the ground: the tilt moves the face by under 3 cm).
    let gap = (b.position.x - size.x / 2.0) - (car.position.x + front);
    assert!(b.position.x > near + 5.0, "box at {:?}", b.position);
    assert!(gap.abs() < 0.05, "tyres {gap} m from the box");
    // The tyres, not the chassis, push: the box stays on the ground, tilted forward (pitch
    // about +y, nose down) but not turned over, and on the car's line.
    let (roll, pitch) = (b.roll_pitch_yaw.roll, b.roll_pitch_yaw.pitch);
    assert!(b.position.z < size.z, "{b:?}");
    assert!(pitch > 0.0 && pitch < 0.3 && roll.abs() < 0.02, "{b:?}");
    assert!(b.position.y.abs() < 0.2, "{b:?}");
}

/// Every numeric metric of `test-track` on one mounting, by scenario and name, the brake torque
/// proportioned to the front.
///
/// With Webots' equal brakes the BmwX5 on friction 1 locks its rear wheels before its front ones
/// in the `brake` stop, which is yaw-unstable: its heading change is the step's rounding
/// amplified some 10⁵-fold (exactly 0 on the cast car, whose solve is mirror-exact; on joints
/// anywhere between −0.12 and +0.04 rad as the tread's core went from 3 µm to 1 mm), a figure
/// two models cannot agree on. Proportioned, neither axle locks and the stop is the physics'.
/// No other scenario brakes.
fn test_track(mounting: Mounting) -> Vec<(String, String, f64)> {
    let mut world = world_file::default_world();
    for car in &mut world.cars {
        car.mounting = mounting;
        car.brake_balance = BrakeBalance::Proportioned;
    }
    let report = scenario::run(&world, Scenario::TestTrack, &mut |_| {}).unwrap();
    report
        .results
        .iter()
        .flat_map(|r| {
            r.metrics.iter().filter_map(move |m| match m.value {
                Value::Number(v) => Some((r.name.clone(), m.key.to_string(), v)),
                _ => None,
            })
        })
        .collect()
}

#[test]
fn test_track_agrees_between_the_mountings_within_5_percent() {
    let cast = test_track(Mounting::Cast);
    let joints = test_track(Mounting::Joints);
    assert_eq!(cast.len(), joints.len());
    let mut off = Vec::new();
    for ((s, name, c), (_, _, j)) in cast.iter().zip(&joints) {
        // Metrics near zero (lateral offsets, residuals) are compared on an absolute scale of
        // 5 % of 1 (their unit: m, rad, m/s²), percentages in percentage points.
        let scale = if name.ends_with("_percent") {
            100.0
        } else {
            c.abs().max(1.0)
        };
        println!("{s} {name}: cast {c:.4}, joints {j:.4}");
        if (c - j).abs() > 0.05 * scale {
            off.push(format!("{s} {name}: cast {c}, joints {j}"));
        }
    }
    assert!(off.is_empty(), "{off:#?}");
}
