//! Gives the shared library the soname `libcar.so`, the name `libdriver.so` records as
//! DT_NEEDED: a process that loads both (Webots' Python binding opens them one by one) then
//! holds a single copy of the simulator state.
//!
//! `rustc-link-arg` rather than `rustc-cdylib-link-arg`: Cargo hands the latter to every cdylib
//! that depends on this crate too, so the Python extension module (python/) would be named
//! libcar.so and taken for the C library by a libdriver.so loaded into the same process. The
//! former stays in this package (where the test and example executables ignore the soname).

fn main() {
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let elf = !matches!(os.as_str(), "macos" | "ios" | "windows");
    if elf {
        println!("cargo:rustc-link-arg=-Wl,-soname,libcar.so");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
