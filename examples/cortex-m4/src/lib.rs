//! The plant model of the Cortex-M4F example, as a library: the firmware (`src/main.rs`) drives
//! it, and its tests run on the host (`cargo test --target x86_64-unknown-linux-gnu`), which
//! the firmware binary itself cannot.

#![no_std]

pub mod plant;
