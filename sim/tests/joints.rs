//! The car suite (`suite/`) on the joints mounting: wheels as rapier bodies on suspension,
//! steering and spin joints.

// Helpers outside `#[test]` functions unwrap too: clippy.toml only exempts test bodies.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

/// A suite test that the joints mounting does not pass yet, with the reason: ignored here with
/// that reason (`cargo test --test joints -- --ignored` runs them), an ordinary test on the cast
/// mounting.
macro_rules! known_joints_gap {
    ($why:literal, $(#[$m:meta])* fn $name:ident() $body:block) => {
        #[test]
        #[ignore = $why]
        $(#[$m])*
        fn $name() $body
    };
}

mod common;
mod suite;

/// The mounting every car of the suite is built on.
const MOUNTING: sim::Mounting = sim::Mounting::Joints;
