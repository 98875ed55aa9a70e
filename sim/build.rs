//! Embeds every file of `worlds/` (the shipped world files and the files they include, such
//! as OpenDRIVE roads) in the library, so that an installed `vehicle-sim` reaches them by name
//! (`sim::world_file::shipped`). A world added to the directory is embedded without a list to
//! keep up to date.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::exit;

fn main() {
    // The manifest directory of this build, read when the script runs: `env!` would bake in
    // the directory the script was compiled for, and Cargo reuses one compiled script for
    // every checkout that shares a target directory (git worktrees), which then embedded
    // another checkout's worlds, or none once it was removed.
    let Some(manifest) = std::env::var_os("CARGO_MANIFEST_DIR") else {
        eprintln!("sim/build.rs: CARGO_MANIFEST_DIR is not set (run by Cargo)");
        exit(1);
    };
    let dir = PathBuf::from(manifest).join("worlds");
    println!("cargo:rerun-if-changed={}", dir.display());
    let entries = match std::fs::read_dir(&dir) {
        Ok(entries) => entries,
        Err(e) => {
            // Refused rather than an empty list: every world would be missing by name.
            eprintln!(
                "sim/build.rs: cannot read the shipped worlds in {}: {e}",
                dir.display()
            );
            exit(1);
        }
    };
    let mut names: Vec<String> = entries
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
        .filter_map(|e| e.file_name().into_string().ok())
        .collect();
    names.sort();
    let mut code = String::from("&[\n");
    for name in &names {
        let path = dir.join(name);
        let _ = writeln!(
            code,
            "    ({name:?}, include_str!({:?})),",
            path.display().to_string()
        );
    }
    code.push(']');
    let out = Path::new(&std::env::var("OUT_DIR").unwrap_or_default()).join("shipped_worlds.rs");
    if let Err(e) = std::fs::write(&out, code) {
        println!("cargo:warning=cannot write {}: {e}", out.display());
    }
}
