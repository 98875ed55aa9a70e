//! `vehicle-sim plot DIR`: the SVG plots of a run whose data files another front-end wrote (a
//! C, C++ or Python controller under `VEHICLE_OUT`, `webots_vehicle.Simulation.save`, or
//! `Simulation::save` in Rust), drawn from its `telemetry.csv` as `vehicle-sim` draws its own.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::Args;

use crate::report::{self, TELEMETRY_CSV};
use crate::scenario::{RunReport, ScenarioResult};
use crate::telemetry::{self, Telemetry};

use super::{EXIT_FAILURE, EXIT_OK};

/// `vehicle-sim plot`'s options.
#[derive(Debug, Clone, PartialEq, Eq, Args)]
pub struct PlotOptions {
    /// The run's output directory (holding telemetry.csv); the plots are written there
    #[arg(value_name = "DIR")]
    pub dir: PathBuf,
}

/// The run of `telemetry`: one result per scenario name, in order of appearance.
fn report_of(telemetry: Vec<Telemetry>) -> RunReport {
    let mut results: Vec<ScenarioResult> = Vec::new();
    for t in telemetry {
        match results.iter_mut().find(|r| r.name == t.scenario) {
            Some(r) => r.telemetry.push(t),
            None => results.push(ScenarioResult::new(&t.scenario.clone(), vec![t])),
        }
    }
    RunReport {
        results,
        ..RunReport::default()
    }
}

/// Reads `dir/telemetry.csv` and writes the plots of [`report::figures`] beside it.
fn plot(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let path = dir.join(TELEMETRY_CSV);
    let file = std::fs::File::open(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let telemetry = telemetry::read_csv(std::io::BufReader::new(file))
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let run = report_of(telemetry);
    let mut written = Vec::new();
    for (name, figure) in report::figures(&run) {
        let svg = figure.to_svg().map_err(|e| e.to_string())?;
        let out = dir.join(name);
        std::fs::write(&out, svg).map_err(|e| format!("{}: {e}", out.display()))?;
        written.push(out);
    }
    Ok(written)
}

/// Runs `vehicle-sim plot`.
pub(super) fn plot_main(o: &PlotOptions, out: &mut dyn Write, err: &mut dyn Write) -> i32 {
    match plot(&o.dir) {
        Ok(files) => {
            let names: Vec<String> = files
                .iter()
                .filter_map(|f| f.file_name().map(|n| n.to_string_lossy().into_owned()))
                .collect();
            let _ = writeln!(
                out,
                "vehicle-sim: plots in {}: {}",
                o.dir.display(),
                names.join(", ")
            );
            EXIT_OK
        }
        Err(e) => {
            let _ = writeln!(err, "vehicle-sim: error: {e}");
            EXIT_FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use vehicle_model::Model;

    use crate::{CarBuilder, Simulation, World, WorldConfig};

    #[test]
    fn a_saved_run_gets_the_plots_of_its_report() {
        let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
        let (id, _) = sim.add_car(CarBuilder::of_model(Model::BmwX5)).unwrap();
        sim.record("run");
        sim.driver_mut(id).unwrap().set_cruising_speed(30.0);
        for _ in 0..100 {
            sim.step().unwrap();
        }
        let dir = std::env::temp_dir().join(format!("sim-plot-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        sim.save("w", &[], &dir).unwrap();
        let (mut out, mut err) = (Vec::new(), Vec::new());
        let args = ["plot".to_string(), dir.display().to_string()];
        assert_eq!(super::super::main(args, &mut out, &mut err, false), 0);
        let report = sim.report("w").unwrap().unwrap();
        let expected: Vec<&str> = crate::report::figures(&report)
            .into_iter()
            .map(|(name, _)| name)
            .collect();
        assert!(expected.contains(&"speed.svg") && expected.contains(&"trajectory.svg"));
        for name in &expected {
            assert!(dir.join(name).is_file(), "{name}");
        }
        let text = String::from_utf8(out).unwrap();
        assert!(text.contains(&expected.join(", ")), "{text}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
