//! The simulation: the bytes choose a model, a mounting, a time step and a sequence of driver
//! calls (a step being a simulation step), or a DifferentialWheels robot and its calls; the
//! invariants are those of the property tests (`sim/tests/fuzz/simulation.rs`, included here).

#![no_main]

#[path = "../../vehicle-model/tests/fuzz/control_loop.rs"]
#[allow(dead_code)]
mod control_loop;
#[path = "../../sim/tests/fuzz/simulation.rs"]
mod simulation;
mod values;

use control_loop::Op;
use libfuzzer_sys::arbitrary::{Result, Unstructured};
use libfuzzer_sys::fuzz_target;
use sim::world_file;
use sim::Mounting;
use simulation::{RobotOp, run};
use values::{hostile, hostile_int};
use vehicle_model::Model;

/// At most this many calls per input, so that an input runs in milliseconds.
const MAX_CALLS: usize = 64;

fn op(u: &mut Unstructured<'_>) -> Result<Op> {
    let step = Op::Step {
        time: 0.0,
        wheel_angles: [0.0; 4],
        steering: [0.0; 2],
        wiper: None,
    };
    Ok(match u.int_in_range(0..=11u8)? {
        0 => Op::SteeringAngle(hostile(u)?),
        1 => Op::CruisingSpeed(hostile(u)?),
        2 => Op::Throttle(hostile(u)?),
        3 => Op::BrakeIntensity(hostile(u)?),
        4 => Op::Gear(hostile_int(u)?),
        5 => Op::RightSteeringAngle(hostile(u)?),
        6 => Op::LeftSteeringAngle(hostile(u)?),
        7 => Op::LimitedSlip(u.arbitrary()?),
        8 => Op::WiperMode(hostile_int(u)?),
        _ => step,
    })
}

fn robot_op(u: &mut Unstructured<'_>) -> Result<RobotOp> {
    Ok(match u.int_in_range(0..=6u8)? {
        0 | 1 => RobotOp::SetSpeed(hostile(u)?, hostile(u)?),
        2 => RobotOp::EnableEncoders(hostile_int(u)?),
        3 => RobotOp::DisableEncoders,
        4 => RobotOp::SetEncoders(hostile(u)?, hostile(u)?),
        _ => RobotOp::Step,
    })
}

fn calls<T>(u: &mut Unstructured<'_>, f: fn(&mut Unstructured<'_>) -> Result<T>) -> Vec<T> {
    let mut v = Vec::new();
    while !u.is_empty() && v.len() < MAX_CALLS {
        match f(u) {
            Ok(x) => v.push(x),
            Err(_) => break,
        }
    }
    v
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok(robot) = u.ratio(1, 5) else { return };
    let result = if robot {
        let physics: bool = u.arbitrary().unwrap_or(true);
        let text = format!("[differential_wheels]\nphysics = {physics}\n");
        let Ok(world) = world_file::parse_str("robot.toml", &text) else {
            panic!("the robot world does not load")
        };
        run(&world, &[], &calls(&mut u, robot_op))
    } else {
        let Ok(model) = u.choose(&Model::ALL).copied() else { return };
        let joints: bool = u.arbitrary().unwrap_or(false);
        let step = *u.choose(&[8u32, 10, 16, 32, 100]).unwrap_or(&10);
        let mut world = world_file::with_model(model);
        world.config.basic_time_step_ms = step;
        for car in &mut world.cars {
            car.mounting = if joints { Mounting::Joints } else { Mounting::Cast };
        }
        run(&world, &calls(&mut u, op), &[])
    };
    if let Err(e) = result {
        panic!("{e}");
    }
});
