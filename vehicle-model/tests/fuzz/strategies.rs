//! proptest strategies for the control-loop harness (`control_loop.rs`): hostile numbers,
//! driver calls, parameter edits and time steps. Shared with the simulation's property tests
//! (`sim/tests/fuzz`, which include this file by path).

use proptest::prelude::*;

use crate::control_loop::{FieldEdit, Op, field_names};
use crate::special::SPECIAL;

/// Any f64, weighted towards the values that broke things before ([`SPECIAL`]).
pub fn hostile() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => prop::sample::select(SPECIAL.to_vec()),
        2 => -100.0..100.0f64,
        1 => any::<f64>(),
    ]
}

/// Any i32, weighted towards the edges of the gears, enum values and wheel indices.
pub fn hostile_int() -> impl Strategy<Value = i32> {
    prop_oneof![
        3 => -3..8i32,
        1 => prop::sample::select(vec![i32::MIN, i32::MAX, -1_000_000, 1 << 30]),
        1 => any::<i32>(),
    ]
}

/// One driver call.
pub fn op() -> impl Strategy<Value = Op> {
    prop_oneof![
        1 => hostile().prop_map(Op::SteeringAngle),
        1 => hostile().prop_map(Op::CruisingSpeed),
        1 => hostile().prop_map(Op::Throttle),
        1 => hostile().prop_map(Op::BrakeIntensity),
        1 => hostile_int().prop_map(Op::Gear),
        1 => hostile_int().prop_map(Op::Indicator),
        1 => any::<bool>().prop_map(Op::HazardFlashers),
        1 => hostile().prop_map(Op::IndicatorPeriod),
        1 => hostile().prop_map(Op::RightSteeringAngle),
        1 => hostile().prop_map(Op::LeftSteeringAngle),
        1 => any::<bool>().prop_map(Op::LimitedSlip),
        1 => hostile_int().prop_map(Op::WiperMode),
        1 => any::<bool>().prop_map(Op::DippedBeams),
        1 => any::<bool>().prop_map(Op::AntifogLights),
        1 => any::<bool>().prop_map(Op::IndicatorAutoDisabling),
        1 => prop_oneof![-2..6i64, any::<i64>()].prop_map(Op::Read),
        4 => (
            hostile(),
            prop::array::uniform4(hostile()),
            prop::array::uniform2(hostile()),
            prop::option::of(hostile()),
        )
            .prop_map(|(time, wheel_angles, steering, wiper)| Op::Step {
                time,
                wheel_angles,
                steering,
                wiper,
            }),
    ]
}

/// A parameter edit: any settable field with one to seven hostile values.
pub fn edit() -> impl Strategy<Value = FieldEdit> {
    (
        0..field_names().len(),
        prop::collection::vec(hostile(), 1..=7),
    )
        .prop_map(|(field, values)| FieldEdit { field, values })
}

/// The basic time step (ms): usual values, 0 (refused, the default used) and extremes.
pub fn basic_time_step() -> impl Strategy<Value = u32> {
    prop_oneof![
        3 => prop::sample::select(vec![1, 8, 10, 16, 20, 32, 100]),
        1 => any::<u32>(),
    ]
}
