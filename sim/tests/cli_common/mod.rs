//! What the tests of the `vehicle-sim` binary share: running it, a scratch directory, its
//! output as text.

// Each test file uses what it needs of these.
#![allow(dead_code, clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;
use std::process::{Command, Output};

/// Runs `vehicle-sim` with `args`.
pub fn vehicle_sim(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vehicle-sim"))
        .args(args)
        .output()
        .expect("vehicle-sim runs")
}

/// A fresh scratch directory for one test.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("vehicle-sim-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `bytes` (a process' output) as text.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}
