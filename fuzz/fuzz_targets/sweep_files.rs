//! Sweeps: the first byte picks the check; the rest is either a sweep file's text (lossily
//! decoded UTF-8) through the sweep loader, or a damage to a shard's output files (which file,
//! where to cut it, which byte to overwrite) through `sweep-merge` and `sweep --resume`.
//! Invariants are those of the property tests (`sim/tests/fuzz/sweep_files.rs`, included here).

#![no_main]

#[path = "../../sim/tests/fuzz/sweep_files.rs"]
mod sweep_files;

use libfuzzer_sys::arbitrary::Unstructured;
use libfuzzer_sys::fuzz_target;
use sweep_files::{Damage, check_damage, check_text};

fuzz_target!(|data: &[u8]| {
    let Some((&mode, rest)) = data.split_first() else {
        return;
    };
    let checked = if mode % 2 == 0 {
        check_text(&String::from_utf8_lossy(rest))
    } else {
        let mut u = Unstructured::new(rest);
        let damage = Damage {
            timings: u.arbitrary().unwrap_or(false),
            cut: u.arbitrary().unwrap_or(None),
            byte: u.arbitrary().unwrap_or(None),
        };
        check_damage(damage)
    };
    if let Err(e) = checked {
        panic!("{e}");
    }
});
