//! The car suite (`suite/`) on the cast mounting: one rigid chassis on four shape-cast wheels.

// Helpers outside `#[test]` functions unwrap too: clippy.toml only exempts test bodies.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;
mod suite;

/// The mounting every car of the suite is built on.
const MOUNTING: sim::Mounting = sim::Mounting::Cast;
