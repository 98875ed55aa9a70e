//! The car tests, compiled once per wheel mounting (`cast.rs`, `joints.rs`): the same tests
//! with the same tolerances, the mounting chosen by the including crate's `MOUNTING`.

/// One `#[test]` per shipped model: `name => Model` runs `$run(Model::Model)`.
macro_rules! model_tests {
    ($run:expr; $($name:ident => $model:ident),* $(,)?) => {
        $(
            #[test]
            fn $name() {
                ($run)(vehicle_model::Model::$model);
            }
        )*
    };
}

mod car_dynamics;
mod large_steps;
mod speed_mode;
mod test_track;
mod tyre_handling;
mod tyre_stability;
mod tyre_straight;
mod wheel_contact;
mod wheel_transient;
mod world;
