//! The car suite (`suite/`) on the cast mounting: one rigid chassis on four shape-cast wheels.

// Helpers outside `#[test]` functions unwrap too: clippy.toml only exempts test bodies.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

/// A suite test that the joints mounting does not pass yet, with the reason: an ordinary test
/// here (see `joints.rs`).
macro_rules! known_joints_gap {
    ($why:literal, $(#[$m:meta])* fn $name:ident() $body:block) => {
        #[test]
        #[doc = $why]
        $(#[$m])*
        fn $name() $body
    };
}

mod common;
mod suite;

/// The mounting every car of the suite is built on.
const MOUNTING: sim::Mounting = sim::Mounting::Cast;
