//! `vehicle-sim`: drives a Webots-style car (or DifferentialWheels robot) on rapier3d physics
//! through a scenario and reports metrics, telemetry CSV and SVG plots. See `--help` and
//! `sim/README.md`.

fn main() {
    std::process::exit(sim::cli::run_process());
}
