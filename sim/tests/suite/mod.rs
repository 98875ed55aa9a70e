//! The car tests, compiled once per wheel mounting (`cast.rs`, `joints.rs`): the same tests
//! with the same tolerances, the mounting chosen by the including crate's `MOUNTING`.

mod car_dynamics;
mod large_steps;
mod speed_mode;
mod test_track;
mod tyre_handling;
mod tyre_straight;
mod wheel_contact;
mod wheel_transient;
mod world;
