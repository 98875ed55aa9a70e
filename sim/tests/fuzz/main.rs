//! Fuzzing the world-file loader and the simulation: property tests of arbitrary text and of
//! structure-aware world files (built from the real key names), of random driver command
//! sequences on every model on both mountings, and of random DifferentialWheels commands; the
//! invariants are those of `world_file.rs` and `simulation.rs`, shared with the coverage-guided
//! targets of `fuzz/`. `corpus.rs` replays the committed seed worlds of `fuzz/seeds`, the
//! hardening review's reproducers, each with its exact outcome.
//!
//! Few cases by default so that `cargo test` stays quick; a long run sets proptest's own
//! variable, e.g. `PROPTEST_CASES=5000 cargo test --release -p sim --test fuzz` (see
//! `fuzz/README.md`).

// A failed property reports through proptest's panic.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[path = "../../../vehicle-model/tests/fuzz/control_loop.rs"]
#[allow(dead_code)] // the simulation uses the calls and checks, not `run`
mod control_loop;
#[path = "../../../vehicle-model/tests/fuzz/special.rs"]
mod special;
#[path = "../../../vehicle-model/tests/fuzz/strategies.rs"]
#[allow(dead_code)] // no parameter edits or time steps here
mod strategies;

mod corpus;
mod documents;
mod simulation;
// Sweep files are read by the application (`app` feature).
#[cfg(feature = "app")]
mod sweep_files;
mod world_file;

use proptest::prelude::*;
use proptest::test_runner::Config;
use sim::Mounting;
use sim::world_file as wf;
use vehicle_model::Model;

use simulation::RobotOp;
use strategies::{hostile, op};

/// proptest's configuration with `cases` cases unless `PROPTEST_CASES` asks otherwise.
fn config(cases: u32) -> Config {
    let mut config = Config::default();
    if std::env::var_os("PROPTEST_CASES").is_none() {
        config.cases = cases;
    }
    config
}

/// The default world with `model` (on its shipped tyres) on `mounting`.
fn car_world(model: Model, mounting: Mounting, basic_time_step_ms: u32) -> wf::WorldDescription {
    let mut world = wf::with_model(model);
    world.config.basic_time_step_ms = basic_time_step_ms;
    for car in &mut world.cars {
        car.mounting = mounting;
    }
    world
}

/// One DifferentialWheels call.
fn robot_op() -> impl Strategy<Value = RobotOp> {
    prop_oneof![
        3 => (hostile(), hostile()).prop_map(|(l, r)| RobotOp::SetSpeed(l, r)),
        1 => prop_oneof![-2..100i32, any::<i32>()].prop_map(RobotOp::EnableEncoders),
        1 => Just(RobotOp::DisableEncoders),
        1 => (hostile(), hostile()).prop_map(|(l, r)| RobotOp::SetEncoders(l, r)),
        4 => Just(RobotOp::Step),
    ]
}

proptest! {
    #![proptest_config(config(64))]

    #[test]
    fn any_text_loads_or_gives_a_located_error(text in any::<String>()) {
        world_file::check(&text).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn any_bytes_load_or_give_a_located_error(bytes in prop::collection::vec(any::<u8>(), 0..200)) {
        world_file::check(&String::from_utf8_lossy(&bytes)).map_err(TestCaseError::fail)?;
    }
}

proptest! {
    // Each loaded world is built and stepped: a few milliseconds per case.
    #![proptest_config(config(48))]

    #[test]
    fn structured_world_files_load_or_give_a_located_error(text in documents::document()) {
        world_file::check(&text).map_err(|e| TestCaseError::fail(format!("{e}\n{text}")))?;
    }
}

proptest! {
    // Every case builds a rapier world and runs up to 40 steps.
    #![proptest_config(config(16))]

    #[test]
    fn random_driver_commands_keep_every_car_finite(
        model in prop::sample::select(Model::ALL.to_vec()),
        joints in any::<bool>(),
        step in prop::sample::select(vec![8u32, 10, 16, 32, 100]),
        ops in prop::collection::vec(op(), 0..48),
    ) {
        let mounting = if joints { Mounting::Joints } else { Mounting::Cast };
        let world = car_world(model, mounting, step);
        simulation::run(&world, &ops, &[]).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn random_commands_keep_the_robot_finite(
        physics in any::<bool>(),
        ops in prop::collection::vec(robot_op(), 0..48),
    ) {
        let text = format!("[differential_wheels]\nphysics = {physics}\n");
        let world = wf::parse_str("robot.toml", &text).unwrap();
        simulation::run(&world, &[], &ops).map_err(TestCaseError::fail)?;
    }
}

/// The sweep files' properties: sweeps are the application's (`app` feature).
#[cfg(feature = "app")]
mod sweep_properties {
    use super::*;

    proptest! {
        #![proptest_config(config(64))]

        #[test]
        fn any_sweep_text_loads_or_gives_an_error_naming_the_file(text in any::<String>()) {
            let checked = sweep_files::check_text(&text);
            prop_assert!(checked.is_ok(), "{}", checked.unwrap_err());
        }
    }

    proptest! {
        // Each case copies two shard directories and resumes a shard: a few ms.
        #![proptest_config(config(24))]

        #[test]
        fn damaged_shard_files_never_merge_or_resume_into_wrong_rows(
            timings in any::<bool>(),
            cut in proptest::option::of(any::<usize>()),
            byte in proptest::option::of((any::<usize>(), any::<u8>())),
        ) {
            let damage = sweep_files::Damage { timings, cut, byte };
            let checked = sweep_files::check_damage(damage);
            prop_assert!(checked.is_ok(), "{damage:?}: {}", checked.unwrap_err());
        }
    }

    /// The damage the fuzz target found (fuzz/seeds/sweep_files/damage-newline-to-cr): a line's
    /// `\n` overwritten by `\r`, which the csv crate's default reader also takes as a line end,
    /// so a resume kept the file with the damaged byte. Every byte of both shard files (the files
    /// are under 600 bytes; the offset wraps) is overwritten with `\r` in turn.
    #[test]
    fn a_newline_damaged_into_a_carriage_return_is_not_resumed() {
        for timings in [false, true] {
            for at in 0..600 {
                let damage = sweep_files::Damage {
                    timings,
                    cut: None,
                    byte: Some((at, b'\r')),
                };
                let checked = sweep_files::check_damage(damage);
                assert!(checked.is_ok(), "{damage:?}: {}", checked.unwrap_err());
            }
        }
    }
}
