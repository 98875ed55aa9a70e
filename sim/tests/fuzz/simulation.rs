//! The simulation fuzz harness: a world built from a description, then any sequence of driver
//! calls (the control loop's [`Op`]s, a step being a simulation step) on a car, or of
//! DifferentialWheels calls on a robot, checked after every call.
//!
//! Shared by the property tests of this directory and the coverage-guided targets
//! `fuzz/fuzz_targets/simulation.rs` and `world_file.rs` (which include this file by path).
//! Invariants: nothing panics; a world that loaded builds; every step succeeds and leaves the
//! car's or robot's state and the driver finite; a robot's commanded speeds stay finite and
//! its warnings are typed.

use sim::world_file::WorldDescription;
use sim::{RobotId, RobotWarning, SimError, Simulation, VehicleId, VehicleState, World};

use crate::control_loop::{Op, apply, check_state};

/// A call on a DifferentialWheels robot (Webots `wb_differential_wheels_*`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RobotOp {
    /// `set_speed(left, right)` (speed units).
    SetSpeed(f64, f64),
    /// `enable_encoders(period)` (ms).
    EnableEncoders(i32),
    /// `disable_encoders()`.
    DisableEncoders,
    /// `set_encoders(left, right)` (increments).
    SetEncoders(f64, f64),
    /// One simulation step.
    Step,
}

/// The simulation of a world description, with its car or robot.
pub struct Built {
    /// The simulation.
    pub sim: Simulation,
    /// The car, if the world has one.
    pub car: Option<VehicleId>,
    /// The robot, if the world has one.
    pub robot: Option<RobotId>,
}

/// Builds the world of `description` as the C API does (its cars on the world's tyres and
/// mounting, or its robot).
///
/// # Errors
/// The [`SimError`] of a description the simulator refuses.
pub fn build(description: &WorldDescription) -> Result<Built, SimError> {
    let mut sim = Simulation::new(World::new(description.config.clone())?);
    let mut car = None;
    for c in &description.cars {
        let (id, _) = sim.add_car(sim::CarBuilder::from(c))?;
        car = car.or(Some(id));
    }
    let robot = match &description.robot {
        Some(r) => Some(
            sim.world_mut()
                .add_differential_wheels(r.params, r.mode, r.placement)?,
        ),
        None => None,
    };
    Ok(Built { sim, car, robot })
}

/// Builds `description`, then runs the car `ops` (a car world) or the robot `robot_ops` (a
/// robot world), checking the invariants of the module documentation.
///
/// # Errors
/// The first broken invariant.
pub fn run(
    description: &WorldDescription,
    ops: &[Op],
    robot_ops: &[RobotOp],
) -> Result<(), String> {
    let name = description.vehicles_label();
    let mut b =
        build(description).map_err(|e| format!("{name}: a loaded world does not build: {e}"))?;
    if let Some(car) = b.car {
        for (i, op) in ops.iter().enumerate() {
            car_call(&mut b.sim, car, op).map_err(|e| format!("{name}, call {i} {op:?}: {e}"))?;
        }
    }
    if let Some(robot) = b.robot {
        for (i, op) in robot_ops.iter().enumerate() {
            robot_call(&mut b.sim, robot, *op)
                .map_err(|e| format!("{name}, call {i} {op:?}: {e}"))?;
        }
    }
    Ok(())
}

/// One step of the simulation; an error is a broken invariant.
pub fn step(sim: &mut Simulation) -> Result<(), String> {
    sim.step().map_err(|e| format!("step failed: {e} ({e:?})"))
}

/// Performs `op` on the car's driver (a step is a simulation step) and checks the car.
fn car_call(sim: &mut Simulation, car: VehicleId, op: &Op) -> Result<(), String> {
    let err = |e: SimError| e.to_string();
    if let Op::Step { .. } = op {
        step(sim)?;
        let state = sim.world().vehicle(car).map_err(err)?.state();
        finite_state(state)?;
        let t = sim.telemetry(car).map_err(err)?;
        if !(t.estimated_speed_kmh.is_finite() && t.rpm.is_none_or(f64::is_finite)) {
            return Err(format!("telemetry {t:?}"));
        }
    } else {
        apply(sim.driver_mut(car).map_err(err)?, op)?;
    }
    check_state(sim.driver(car).map_err(err)?)
}

/// Every number of a car's state is finite.
fn finite_state(s: &VehicleState) -> Result<(), String> {
    let a = s.roll_pitch_yaw;
    let mut numbers: Vec<f64> = s.position.iter().chain(&s.velocity).copied().collect();
    numbers.extend([
        a.roll,
        a.pitch,
        a.yaw,
        s.forward_speed,
        s.yaw_rate,
        s.longitudinal_acceleration,
        s.lateral_acceleration,
        s.steering.right,
        s.steering.left,
    ]);
    for w in s
        .wheel_speeds
        .iter()
        .chain(&s.wheel_angles)
        .chain(&s.suspension)
    {
        numbers.push(*w);
    }
    for t in s.tyres.iter() {
        numbers.extend([t.slip_ratio, t.slip_angle, t.fx, t.fy, t.fz, t.friction_use]);
    }
    numbers.extend(s.wiper);
    if numbers.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(format!("non-finite car state {s:?}"))
    }
}

/// Performs `op` on the robot and checks its warning and state.
fn robot_call(sim: &mut Simulation, id: RobotId, op: RobotOp) -> Result<(), String> {
    let err = |e: SimError| e.to_string();
    if op == RobotOp::Step {
        step(sim)?;
    } else {
        let robot = sim.world_mut().robot_mut(id).map_err(err)?;
        let before = [robot.left_speed(), robot.right_speed()];
        let warning = match op {
            RobotOp::SetSpeed(l, r) => robot.set_speed(l, r),
            RobotOp::EnableEncoders(p) => robot.enable_encoders(p),
            RobotOp::DisableEncoders => {
                robot.disable_encoders();
                None
            }
            RobotOp::SetEncoders(l, r) => robot.set_encoders(l, r),
            RobotOp::Step => None,
        };
        let after = [robot.left_speed(), robot.right_speed()];
        match (op, warning) {
            // A refused speed leaves the command as it was.
            (
                RobotOp::SetSpeed(..),
                Some(RobotWarning::InvalidNan { .. } | RobotWarning::Infinite { .. }),
            ) if after == before || after.iter().all(|s| s.is_nan()) => {}
            (RobotOp::SetSpeed(l, r), None | Some(RobotWarning::SpeedOverflow { .. }))
                if l.is_finite() && r.is_finite() => {}
            (RobotOp::SetSpeed(..), w) => return Err(format!("warning {w:?}, speeds {after:?}")),
            (RobotOp::EnableEncoders(p), Some(RobotWarning::NegativePeriod { .. })) if p < 0 => {}
            (RobotOp::EnableEncoders(p), None) if p >= 0 => {}
            (RobotOp::SetEncoders(l, r), None) if l.is_finite() && r.is_finite() => {}
            (RobotOp::SetEncoders(l, r), Some(_)) if !(l.is_finite() && r.is_finite()) => {}
            (RobotOp::DisableEncoders, None) => {}
            (op, w) => return Err(format!("{op:?} gave {w:?}")),
        }
    }
    let robot = sim.world().robot(id).map_err(err)?;
    let pose = robot.pose();
    let mut numbers = vec![pose.heading];
    numbers.extend(pose.position.iter());
    numbers.extend(robot.wheel_speeds());
    numbers.extend(robot.wheel_angles());
    numbers.extend(robot.raw_encoders());
    numbers.extend(robot.targets());
    if !numbers.iter().all(|x| x.is_finite()) {
        return Err(format!("non-finite robot state {numbers:?}"));
    }
    // Before the first command the speeds are NaN (Webots); after one, finite.
    let speeds = [robot.left_speed(), robot.right_speed()];
    if !(speeds.iter().all(|s| s.is_finite()) || speeds.iter().all(|s| s.is_nan())) {
        return Err(format!("commanded speeds {speeds:?}"));
    }
    Ok(())
}
