//! The control loop: the bytes choose a model, a time step, parameter edits and a sequence of
//! driver calls with any values; the invariants are those of the property tests
//! (`vehicle-model/tests/fuzz/control_loop.rs`, included here), run in f64 and f32.

#![no_main]

#[path = "../../vehicle-model/tests/fuzz/control_loop.rs"]
#[allow(dead_code)]
mod control_loop;

mod values;

use control_loop::{FieldEdit, Op, run};
use libfuzzer_sys::arbitrary::{Result, Unstructured};
use libfuzzer_sys::fuzz_target;
use values::{hostile, hostile_int};
use vehicle_model::Model;

fn op(u: &mut Unstructured<'_>) -> Result<Op> {
    Ok(match u.int_in_range(0..=20u8)? {
        0 => Op::SteeringAngle(hostile(u)?),
        1 => Op::CruisingSpeed(hostile(u)?),
        2 => Op::Throttle(hostile(u)?),
        3 => Op::BrakeIntensity(hostile(u)?),
        4 => Op::Gear(hostile_int(u)?),
        5 => Op::Indicator(hostile_int(u)?),
        6 => Op::HazardFlashers(u.arbitrary()?),
        7 => Op::IndicatorPeriod(hostile(u)?),
        8 => Op::RightSteeringAngle(hostile(u)?),
        9 => Op::LeftSteeringAngle(hostile(u)?),
        10 => Op::LimitedSlip(u.arbitrary()?),
        11 => Op::WiperMode(hostile_int(u)?),
        12 => Op::DippedBeams(u.arbitrary()?),
        13 => Op::AntifogLights(u.arbitrary()?),
        14 => Op::IndicatorAutoDisabling(u.arbitrary()?),
        15 => Op::Read(u.arbitrary()?),
        _ => Op::Step {
            time: hostile(u)?,
            wheel_angles: [hostile(u)?, hostile(u)?, hostile(u)?, hostile(u)?],
            steering: [hostile(u)?, hostile(u)?],
            wiper: if u.arbitrary()? {
                Some(hostile(u)?)
            } else {
                None
            },
        },
    })
}

fn edit(u: &mut Unstructured<'_>) -> Result<FieldEdit> {
    let field = u.arbitrary()?;
    let n = u.int_in_range(1..=7usize)?;
    let values = (0..n).map(|_| hostile(u)).collect::<Result<_>>()?;
    Ok(FieldEdit { field, values })
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok(model) = u.choose(&Model::ALL).copied() else {
        return;
    };
    let step = u.int_in_range(0..=200u32).unwrap_or(10);
    let edits: Vec<FieldEdit> = (0..u.int_in_range(0..=3u8).unwrap_or(0))
        .map_while(|_| edit(&mut u).ok())
        .collect();
    let mut ops = Vec::new();
    while !u.is_empty() && ops.len() < 256 {
        match op(&mut u) {
            Ok(o) => ops.push(o),
            Err(_) => break,
        }
    }
    if let Err(e) = run::<f64>(model, step, &edits, &ops) {
        panic!("f64: {e}");
    }
    if let Err(e) = run::<f32>(model, step, &edits, &ops) {
        panic!("f32: {e}");
    }
});
