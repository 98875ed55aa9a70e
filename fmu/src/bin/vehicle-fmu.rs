//! `vehicle-fmu`: packages the car of a world as an FMI 2.0 or 3.0 co-simulation FMU.
//!
//! ```text
//! vehicle-fmu [--world WORLD] [--fmi 2|3] [--library PATH] -o car.fmu
//! ```
//! WORLD is a world file, a vehicle model (e.g. `TeslaModel3`) or absent for the default
//! world; PATH is the FMU's shared library, by default the one beside this executable (both
//! are built by `cargo build --release -p vehicle-fmu`).
//!
//! Why no argument-parsing crate: four options, and the crate's library (the FMU itself)
//! must stay free of command-line dependencies, which Cargo cannot give to a binary alone.

use std::path::PathBuf;
use std::process::ExitCode;

use vehicle_fmu::instance::Version;
use vehicle_fmu::package::{self, World};

const USAGE: &str = "usage: vehicle-fmu [--world WORLD] [--fmi 2|3] [--library PATH] -o OUT.fmu\n\
    WORLD: a world file, a vehicle model (e.g. TeslaModel3), or absent for the default world\n\
    --fmi: the FMI version of the model description (default 2)\n\
    PATH: the FMU's shared library (default: the one beside this executable)";

fn main() -> ExitCode {
    match run(std::env::args().skip(1).collect()) {
        Ok(message) => {
            println!("{message}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("vehicle-fmu: {e}");
            ExitCode::from(2)
        }
    }
}

fn run(args: Vec<String>) -> Result<String, String> {
    let (mut world, mut library, mut out) = (String::new(), None, None);
    let mut version = Version::Fmi2;
    let mut args = args.into_iter();
    while let Some(arg) = args.next() {
        let mut value = || {
            args.next()
                .ok_or_else(|| format!("{arg} needs a value\n{USAGE}"))
        };
        match arg.as_str() {
            "--world" => world = value()?,
            "--library" => library = Some(PathBuf::from(value()?)),
            "--fmi" => {
                version = match value()?.as_str() {
                    "2" | "2.0" => Version::Fmi2,
                    "3" | "3.0" => Version::Fmi3,
                    other => return Err(format!("--fmi {other}: 2 or 3\n{USAGE}")),
                }
            }
            "-o" | "--output" => out = Some(PathBuf::from(value()?)),
            "-h" | "--help" => return Ok(USAGE.to_string()),
            other => return Err(format!("unknown argument {other}\n{USAGE}")),
        }
    }
    let out = out.ok_or_else(|| format!("-o OUT.fmu is required\n{USAGE}"))?;
    let library = match library {
        Some(path) => path,
        None => std::env::current_exe()
            .map_err(|e| format!("cannot find this executable: {e}"))?
            .with_file_name(package::library_file_name()),
    };
    let world = World::named(&world)?;
    package::write_fmu(&world, &library, &out, version)?;
    Ok(format!(
        "wrote {} (FMI {}, the car of {})",
        out.display(),
        if version == Version::Fmi3 {
            "3.0"
        } else {
            "2.0"
        },
        world.name
    ))
}
