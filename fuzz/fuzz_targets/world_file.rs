//! The world-file loader: the bytes as text (lossily decoded UTF-8), run through the loader; a
//! world that loads is built and driven for a few steps. Invariants are those of the property
//! tests (`sim/tests/fuzz/world_file.rs`, included here); structure comes from the seed worlds
//! (`fuzz/seeds/world_file`) and the dictionary of key names (`fuzz/world_file.dict`).

#![no_main]

#[path = "../../vehicle-model/tests/fuzz/control_loop.rs"]
#[allow(dead_code)]
mod control_loop;
#[path = "../../sim/tests/fuzz/simulation.rs"]
#[allow(dead_code)]
mod simulation;
#[path = "../../sim/tests/fuzz/world_file.rs"]
mod world_file;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Err(e) = world_file::check(&text) {
        panic!("{e}\n--- input ---\n{text}");
    }
});
