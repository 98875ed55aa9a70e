//! Fuzzing the C ABI: property tests of random sequences of every entry point with hostile
//! values, before initialisation, after it and after cleanup, in car and robot worlds (the
//! invariants are those of `entry_points.rs`, shared with `fuzz/fuzz_targets/capi.rs`), and
//! the hardening review's C ABI inputs as regression tests.
//!
//! Few cases by default so that `cargo test` stays quick; a long run sets proptest's own
//! variable, e.g. `PROPTEST_CASES=2000 cargo test --release -p capi --test fuzz` (see
//! `fuzz/README.md`).

// `wb_robot_get_device` takes a C string and `VEHICLE_WORLD` is set in-process: both unsafe.
#![allow(unsafe_code)]
// A failed property reports through proptest's panic.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod entry_points;
#[path = "../../../vehicle-model/tests/fuzz/special.rs"]
mod special;

use special::SPECIAL;

use car::*;
use entry_points::{Call, run};
use proptest::prelude::*;
use proptest::test_runner::Config;

/// proptest's configuration with `cases` cases unless `PROPTEST_CASES` asks otherwise.
fn config(cases: u32) -> Config {
    let mut config = Config::default();
    if std::env::var_os("PROPTEST_CASES").is_none() {
        config.cases = cases;
    }
    config
}

/// Any f64, weighted towards the values that broke things before ([`SPECIAL`]).
fn hostile() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => prop::sample::select(SPECIAL.to_vec()),
        2 => -100.0..100.0f64,
        1 => any::<f64>(),
    ]
}

/// Any i32, weighted towards the edges of the enums, gears and wheel indices.
fn hostile_int() -> impl Strategy<Value = i32> {
    prop_oneof![3 => -3..8i32, 1 => any::<i32>()]
}

/// One entry-point call.
fn call() -> impl Strategy<Value = Call> {
    let index = || 0..64usize;
    prop_oneof![
        4 => (index(), hostile()).prop_map(|(i, x)| Call::F64Setter(i, x)),
        2 => (index(), hostile(), hostile()).prop_map(|(i, x, y)| Call::F64PairSetter(i, x, y)),
        2 => (index(), hostile_int()).prop_map(|(i, x)| Call::IntSetter(i, x)),
        1 => (index(), any::<u8>()).prop_map(|(i, x)| Call::BoolSetter(i, x)),
        3 => index().prop_map(Call::F64Getter),
        1 => (index(), hostile_int()).prop_map(|(i, w)| Call::WheelGetter(i, w)),
        3 => index().prop_map(Call::IntGetter),
        1 => index().prop_map(Call::BoolGetter),
        1 => index().prop_map(Call::Action),
        2 => index().prop_map(Call::Init),
        2 => prop_oneof![-20..200i32, any::<i32>()].prop_map(Call::RobotStep),
        1 => prop::option::of(index()).prop_map(Call::Device),
    ]
}

proptest! {
    // Each case loads a world (a rapier world and a car or robot) and steps it.
    #![proptest_config(config(24))]

    #[test]
    fn random_calls_never_panic_and_return_finite_values(
        world in 0..4usize,
        calls in prop::collection::vec(call(), 0..64),
    ) {
        run(world, &calls).map_err(TestCaseError::fail)?;
    }
}

#[test]
fn corpus_indicator_period_minus_1e308_is_refused() {
    // Printed a 309-digit number before numbers went compact; the message itself is checked
    // by vehicle-model's fuzz corpus. The period stays the default.
    entry_points::with_session(0, |_, _| {
        vehicle_capi_driver_init();
        wbu_car_set_indicator_period(-1e308);
        assert_eq!(wbu_car_get_indicator_period(), 0.34);
        Ok(())
    })
    .unwrap();
}

#[test]
fn corpus_infinite_differential_wheels_speed_is_refused() {
    // `wb_differential_wheels_set_speed(inf, 0)` was accepted and the getters returned ±inf.
    entry_points::with_session(3, |_, _| {
        wb_differential_wheels_set_speed(1.0, 2.0);
        wb_differential_wheels_set_speed(f64::INFINITY, 0.0);
        wb_differential_wheels_set_speed(0.0, f64::NEG_INFINITY);
        assert_eq!(
            (
                wb_differential_wheels_get_left_speed(),
                wb_differential_wheels_get_right_speed()
            ),
            (1.0, 2.0)
        );
        assert_eq!(wb_robot_step(100), 0);
        Ok(())
    })
    .unwrap();
}

#[test]
fn corpus_empty_vehicle_world_is_the_default_world() {
    // An empty VEHICLE_WORLD means the default world: a BmwX5 (wheelbase 2.995 m), 10 ms.
    entry_points::with_session(0, |_, _| {
        vehicle_capi_driver_init();
        assert_eq!(wbu_car_get_wheelbase(), 2.995);
        assert_eq!(wb_robot_get_basic_time_step(), 10.0);
        assert_eq!(vehicle_capi_driver_step(), 0);
        Ok(())
    })
    .unwrap();
}
