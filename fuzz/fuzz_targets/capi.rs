//! The C ABI: the bytes choose a world and a sequence of entry-point calls with any values;
//! the invariants are those of the property tests (`capi/tests/fuzz/entry_points.rs`,
//! included here). Run with `-close_fd_mask=2`: the library prints Webots' warnings on
//! stderr for most hostile calls.

#![no_main]
#![allow(unsafe_code)]

#[path = "../../capi/tests/fuzz/entry_points.rs"]
#[allow(dead_code)]
mod entry_points;
mod values;

use entry_points::{Call, run};
use libfuzzer_sys::arbitrary::{Result, Unstructured};
use libfuzzer_sys::fuzz_target;
use values::{hostile, hostile_int};

/// At most this many calls per input.
const MAX_CALLS: usize = 64;

fn call(u: &mut Unstructured<'_>) -> Result<Call> {
    let i: usize = u.int_in_range(0..=63)?;
    Ok(match u.int_in_range(0..=11u8)? {
        0 => Call::F64Setter(i, hostile(u)?),
        1 => Call::F64PairSetter(i, hostile(u)?, hostile(u)?),
        2 => Call::IntSetter(i, hostile_int(u)?),
        3 => Call::BoolSetter(i, u.arbitrary()?),
        4 => Call::F64Getter(i),
        5 => Call::WheelGetter(i, hostile_int(u)?),
        6 => Call::IntGetter(i),
        7 => Call::BoolGetter(i),
        8 => Call::Action(i),
        9 => Call::Init(i),
        10 => Call::RobotStep(hostile_int(u)?),
        _ => Call::Device(if u.arbitrary()? { Some(i) } else { None }),
    })
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok(world) = u.int_in_range(0..=3usize) else { return };
    let mut calls = Vec::new();
    while !u.is_empty() && calls.len() < MAX_CALLS {
        match call(&mut u) {
            Ok(c) => calls.push(c),
            Err(_) => break,
        }
    }
    if let Err(e) = run(world, &calls) {
        panic!("{e}");
    }
});
