//! Gives the shared library the soname `libcar.so`, the name `libdriver.so` records as
//! DT_NEEDED: a process that loads both (Webots' Python binding opens them one by one) then
//! holds a single copy of the simulator state.

fn main() {
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let elf = !matches!(os.as_str(), "macos" | "ios" | "windows");
    if elf {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libcar.so");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
