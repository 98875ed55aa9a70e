//! Supervisor placement: a car given 20 m/s rolls on as rolling resistance predicts, a car put
//! at a pose is there after a step, a body moves where it is put, `simulation_reset` gives the
//! world as loaded; both mountings.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use proto_geom::nalgebra::{Point3, UnitQuaternion, Vector3};
use sim::{SimError, Simulation, VehicleId, world_file};

/// Rolling-resistance coefficient of the test car's tyres (dimensionless).
const C_RR: f64 = 0.015;

/// A BmwX5 (wheel damping 5 N·m·s/rad) with tyres of rolling resistance `C_RR`, and a
/// 100 kg box.
fn world(mounting: &str) -> String {
    format!(
        r#"[vehicle]
model = "BmwX5"
mounting = "{mounting}"
[vehicle.tyre]
rolling_resistance = {C_RR}
[[body]]
translation = [0, 20, 0.5]
size = [1, 1, 1]
mass = 100
"#
    )
}

/// The simulation of `world(mounting)` after 1 s standing (its springs settled), with no
/// driver running (the wheels free, no brake).
fn settled(mounting: &str) -> (Simulation, VehicleId) {
    let description = world_file::parse_str("supervisor.toml", &world(mounting)).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    for _ in 0..100 {
        sim.step_physics().unwrap();
    }
    (sim, id)
}

/// A car rolling freely on flat ground: each tyre's rolling resistance is a torque `c_rr·F_z·r`
/// against its spin and each axle's damping a torque `c·ω`, with ω = v/r (no slip); the four
/// loads add up to the weight `m·g`, and the wheels' spin inertia rolls with the car. So
/// `M·dv/dt = −(c_rr·m·g + Σ c/r²·v)` with `M = m + Σ I/r²`: `dv/dt = −(A + B·v)`, whose
/// solution from `v₀` is `v(t) = (v₀ + A/B)·e^(−B·t) − A/B`.
fn rolls_on(mounting: &str) {
    let (mut sim, id) = settled(mounting);
    let spec = *sim.world().vehicle(id).unwrap().spec();
    let forward = Vector3::new(20.0, 0.0, 0.0);
    sim.world_mut()
        .set_vehicle_velocity(id, &forward, &Vector3::zeros())
        .unwrap();
    // The wheels spin at free rolling at once: v / r, v along each wheel's heading, which
    // the settled car's pitch and toe turn from x by well under 0.01 rad (cos > 1 − 5·10⁻⁵).
    let state = *sim.world().vehicle(id).unwrap().state();
    for (w, omega) in state.wheel_speeds.0.iter().enumerate() {
        let r = spec.wheels.0[w].radius;
        assert!(
            (omega * r / 20.0 - 1.0).abs() < 5e-5,
            "wheel {w}: {omega} rad/s"
        );
    }
    let before = state.suspension;
    sim.step_physics().unwrap();
    let after = sim.world().vehicle(id).unwrap().state().suspension;
    for w in 0..4 {
        // No spring motion starts: a settled spring moves less than 1 mm in a step.
        assert!(
            (after.0[w] - before.0[w]).abs() < 1e-3,
            "wheel {w}: suspension {} → {} m",
            before.0[w],
            after.0[w]
        );
    }
    for _ in 0..99 {
        sim.step_physics().unwrap();
    }
    let m = spec.chassis.mass + spec.wheels.0.iter().map(|w| w.mass).sum::<f64>();
    let rolling: f64 = spec
        .wheels
        .0
        .iter()
        .map(|w| w.spin_inertia() / (w.radius * w.radius))
        .sum();
    let g = 9.81;
    let damping: f64 = spec
        .wheels
        .0
        .iter()
        .map(|w| spec.wheels_damping / (w.radius * w.radius))
        .sum();
    let (a, b) = (C_RR * m * g / (m + rolling), damping / (m + rolling));
    let predicted = (20.0 + a / b) * (-b * 1.0).exp() - a / b;
    let loss = 20.0 - predicted;
    let speed = sim.telemetry(id).unwrap().speed;
    // 2 % of the predicted loss (about 3 cm/s): the loads swing as the car pitches on its
    // springs under the braking torques, and the tyres roll with a small slip, not none.
    assert!(
        (speed - predicted).abs() < 0.02 * loss,
        "{mounting}: {speed} m/s after 1 s, predicted {predicted} m/s"
    );
}

#[test]
fn a_cast_car_set_at_20_m_s_rolls_on() {
    rolls_on("cast");
}

#[test]
fn a_joints_car_set_at_20_m_s_rolls_on() {
    rolls_on("joints");
}

/// A settled car put 50 m east and 30 m north, turned to 1 rad, at the height it stood at, is
/// there after one step: it moves no more in that step than it did in the step before the move
/// (its springs' settling), plus `slack` (m).
fn stays_where_put(mounting: &str, slack: f64) {
    let (mut sim, id) = settled(mounting);
    let p0 = sim.world().vehicle_placement(id).unwrap().position;
    sim.step_physics().unwrap();
    let p1 = sim.world().vehicle_placement(id).unwrap().position;
    let settle = (p1 - p0).norm();
    let target = Point3::new(50.0, 30.0, p1.z);
    let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 1.0);
    sim.world_mut()
        .set_vehicle_pose(id, &target, &turn)
        .unwrap();
    let read = sim.world().vehicle_placement(id).unwrap();
    assert!((read.position - target).norm() < 1e-5);
    sim.step_physics().unwrap();
    let after = sim.world().vehicle_placement(id).unwrap();
    let moved = (after.position - target).norm();
    assert!(
        moved <= settle + slack,
        "{mounting}: moved {moved} m in the step after the move, {settle} m before it"
    );
    let yaw = sim.world().vehicle(id).unwrap().state().roll_pitch_yaw.yaw;
    assert!((yaw - 1.0).abs() < 1e-4, "{mounting}: yaw {yaw}");
}

#[test]
fn a_cast_car_put_at_a_pose_stays_there() {
    // f32's resolution at 60 m (about 4 µm).
    stays_where_put("cast", 1e-5);
}

#[test]
fn a_joints_car_put_at_a_pose_stays_there() {
    // 1 mm: the joints car's first step after the move solves its tyres on rapier's contacts
    // of the step before, found where the wheels stood then (the ground keeps its contact
    // points in world axes); the next collision detection finds them under the wheels again.
    stays_where_put("joints", 1e-3);
}

#[test]
fn reset_physics_stops_a_car() {
    let (mut sim, id) = settled("cast");
    let world = sim.world_mut();
    world
        .set_vehicle_velocity(id, &Vector3::new(10.0, 0.0, 0.0), &Vector3::zeros())
        .unwrap();
    world.reset_vehicle_physics(id).unwrap();
    let s = world.vehicle(id).unwrap().state();
    assert_eq!(s.velocity, Vector3::zeros());
    assert!(s.wheel_speeds.0.iter().all(|&w| w == 0.0));
}

#[test]
fn a_body_goes_where_it_is_put() {
    let (mut sim, _) = settled("cast");
    let world = sim.world_mut();
    assert_eq!(world.body_count(), 1);
    let target = Point3::new(5.0, -5.0, 3.0);
    world
        .set_body_pose(0, &target, &UnitQuaternion::identity())
        .unwrap();
    world
        .set_body_velocity(0, &Vector3::new(1.0, 0.0, 0.0), &Vector3::zeros())
        .unwrap();
    let p = world.body_placement(0).unwrap();
    assert!((p.position - target).norm() < 1e-6);
    assert_eq!(p.velocity, Vector3::new(1.0, 0.0, 0.0));
    sim.step_physics().unwrap();
    // One 10 ms step of free flight: x += 1 m/s · 0.01 s, z falls by g·dt² (rapier's
    // symplectic Euler: the velocity changes first).
    let p = sim.world().body_placement(0).unwrap();
    assert!((p.position.x - 5.01).abs() < 1e-5, "{}", p.position.x);
    assert!(
        (p.position.z - (3.0 - 9.81 * 0.01 * 0.01)).abs() < 1e-5,
        "{}",
        p.position.z
    );
    assert!(matches!(
        sim.world().body_placement(1),
        Err(SimError::UnknownBody(1))
    ));
}

#[test]
fn implausible_placements_are_refused() {
    let (mut sim, id) = settled("cast");
    let world = sim.world_mut();
    let far = Point3::new(2e4, 0.0, 0.5);
    let e = world
        .set_vehicle_pose(id, &far, &UnitQuaternion::identity())
        .unwrap_err();
    assert!(e.to_string().contains("translation.x"), "{e}");
    let e = world
        .set_vehicle_velocity(id, &Vector3::new(f64::NAN, 0.0, 0.0), &Vector3::zeros())
        .unwrap_err();
    assert!(e.to_string().contains("velocity.x"), "{e}");
}

#[test]
fn simulation_reset_gives_the_world_as_loaded() {
    for mounting in ["cast", "joints"] {
        let description = world_file::parse_str("supervisor.toml", &world(mounting)).unwrap();
        let (mut sim, _) = Simulation::from_description(&description).unwrap();
        let id = sim.car_ids().next().unwrap();
        let start = sim.world().vehicle_placement(id).unwrap();
        let mut first = Vec::new();
        for _ in 0..30 {
            sim.step().unwrap();
            first.push(sim.world().vehicle_placement(id).unwrap());
        }
        sim.world_mut()
            .set_vehicle_pose(id, &Point3::new(9.0, 9.0, 1.0), &UnitQuaternion::identity())
            .unwrap();
        sim.simulation_reset().unwrap();
        assert_eq!(sim.world().time_ms(), 0);
        assert_eq!(sim.world().vehicle_placement(id).unwrap(), start);
        for (i, expected) in first.iter().enumerate() {
            sim.step().unwrap();
            assert_eq!(
                sim.world().vehicle_placement(id).unwrap(),
                *expected,
                "step {i}"
            );
        }
    }
}
