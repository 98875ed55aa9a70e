//! The `vehicle-sim` command: argument parsing, the run, the progress bar and the outputs.
//!
//! [`main`] is the whole program with its streams and exit code passed in, so tests run it
//! in-process.

use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use vehicle_model::Model;

use crate::report;
use crate::scenario::{self, Progress, Scenario};
use crate::world_file::{self, WorldDescription};

/// Exit code of a successful run.
pub const EXIT_OK: i32 = 0;
/// Exit code when the world cannot be loaded, the simulation fails or the outputs cannot be
/// written.
pub const EXIT_FAILURE: i32 = 1;
/// Exit code of a command-line usage error (unknown option, missing value, unknown scenario).
pub const EXIT_USAGE: i32 = 2;

/// The default output directory.
pub const DEFAULT_OUT_DIR: &str = "vehicle-sim-out";

/// What the command line asks for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Options {
    /// `--world`: a world file or a shipped model name; `None` for the default world.
    pub world: Option<String>,
    /// `--scenario`; `None` for the world's default (`test-track` or `square`).
    pub scenario: Option<Scenario>,
    /// `--out`: where the CSV, JSON and plots go.
    pub out: PathBuf,
    /// `--json`: print the metrics as one JSON object on stdout instead of the table.
    pub json: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            world: None,
            scenario: None,
            out: PathBuf::from(DEFAULT_OUT_DIR),
            json: false,
        }
    }
}

/// What to do.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Command {
    /// Print the help text.
    Help,
    /// Run a scenario.
    Run(Options),
}

/// The help text.
pub fn help() -> String {
    let scenarios: String = Scenario::ALL
        .iter()
        .map(|s| format!("  {:<14}{}\n", s.name(), s.description()))
        .collect();
    let mut models = String::from("Models:");
    let mut line_len = models.len();
    for (i, m) in Model::ALL.iter().map(|m| m.webots_name()).enumerate() {
        let sep = if i + 1 == Model::ALL.len() { "" } else { "," };
        if line_len + m.len() + 2 > 80 {
            models.push_str("\n       ");
            line_len = 7;
        }
        models.push(' ');
        models.push_str(m);
        models.push_str(sep);
        line_len += m.len() + 1 + sep.len();
    }
    format!(
        "vehicle-sim: drive a Webots-style car (or DifferentialWheels robot) on rapier3d physics\n\
         and report metrics, telemetry CSV and SVG plots.\n\n\
         Usage: vehicle-sim [--world FILE|MODEL] [--scenario NAME] [--out DIR] [--json]\n\n\
         Options:\n\
         \x20 --world FILE|MODEL  a TOML world file, or a shipped model name for the default\n\
         \x20                     world with that car (default: BmwX5 on flat ground, 10 ms)\n\
         \x20 --scenario NAME     the driving programme (default: test-track for a car,\n\
         \x20                     square for a DifferentialWheels robot)\n\
         \x20 --out DIR           output directory (default: {DEFAULT_OUT_DIR})\n\
         \x20 --json              print the metrics as one JSON object on stdout\n\
         \x20 -h, --help          print this help\n\n\
         Scenarios:\n{scenarios}\n\
         {models}\n\n\
         Exit status: 0 success, 1 world or simulation error, 2 usage error.\n\
         World file reference: sim/README.md.\n"
    )
}

/// Parses the arguments (without the program name).
///
/// # Errors
/// A message for an unknown option, a missing or repeated value, or an unknown scenario.
pub fn parse_args<I, S>(args: I) -> Result<Command, String>
where
    I: IntoIterator<Item = S>,
    S: Into<String>,
{
    let mut o = Options::default();
    let mut seen: Vec<&'static str> = Vec::new();
    let mut args = args.into_iter().map(Into::into);
    while let Some(arg) = args.next() {
        let (name, inline) = match arg.split_once('=') {
            Some((n, v)) if n.starts_with("--") => (n.to_string(), Some(v.to_string())),
            _ => (arg.clone(), None),
        };
        let option: &'static str = match name.as_str() {
            "-h" | "--help" => return Ok(Command::Help),
            "--json" => {
                if inline.is_some() {
                    return Err("option '--json' takes no value".to_string());
                }
                o.json = true;
                continue;
            }
            "--world" => "--world",
            "--scenario" => "--scenario",
            "--out" => "--out",
            other if other.starts_with('-') => {
                return Err(format!("unknown option '{other}'"));
            }
            other => return Err(format!("unexpected argument '{other}'")),
        };
        if seen.contains(&option) {
            return Err(format!("option '{option}' given twice"));
        }
        seen.push(option);
        let value = match inline {
            Some(v) => v,
            None => args
                .next()
                .filter(|v| !v.starts_with("--"))
                .ok_or_else(|| format!("option '{option}' needs a value"))?,
        };
        match option {
            "--world" => o.world = Some(value),
            "--out" => o.out = PathBuf::from(value),
            _ => {
                let s = Scenario::from_name(&value).ok_or_else(|| {
                    let names: Vec<&str> = Scenario::ALL.iter().map(|s| s.name()).collect();
                    format!("unknown scenario '{value}' (one of: {})", names.join(", "))
                })?;
                o.scenario = Some(s);
            }
        }
    }
    Ok(Command::Run(o))
}

/// A progress bar on stderr, drawn only on a terminal and once the run has lasted a second.
struct ProgressBar {
    enabled: bool,
    start: Instant,
    drawn: bool,
}

impl ProgressBar {
    const WIDTH: usize = 30;

    fn new(enabled: bool) -> Self {
        ProgressBar {
            enabled,
            start: Instant::now(),
            drawn: false,
        }
    }

    fn update(&mut self, err: &mut dyn Write, p: Progress) {
        if !self.enabled || self.start.elapsed() < Duration::from_secs(1) {
            return;
        }
        let filled = ((p.fraction * Self::WIDTH as f64).round() as usize).min(Self::WIDTH);
        let _ = write!(
            err,
            "\r[{}{}] {:3.0}%  {} ({}/{}) t = {:.1} s   ",
            "#".repeat(filled),
            "-".repeat(Self::WIDTH - filled),
            100.0 * p.fraction,
            p.scenario,
            p.index + 1,
            p.count,
            p.time
        );
        let _ = err.flush();
        self.drawn = true;
    }

    fn clear(&mut self, err: &mut dyn Write) {
        if self.drawn {
            let _ = write!(err, "\r{}\r", " ".repeat(Self::WIDTH + 60));
            let _ = err.flush();
            self.drawn = false;
        }
    }
}

/// Loads the world of `--world`, or the default world.
fn load_world(spec: Option<&str>) -> Result<WorldDescription, world_file::WorldFileError> {
    match spec {
        Some(s) => world_file::load(s),
        None => Ok(world_file::default_world()),
    }
}

/// The whole `vehicle-sim` program: parses `args` (without the program name), runs, writes
/// the outputs and the report to `out`, messages to `err`, and returns the exit code. A
/// progress bar is drawn on `err` when `err_is_terminal`.
pub fn main(
    args: impl IntoIterator<Item = String>,
    out: &mut dyn Write,
    err: &mut dyn Write,
    err_is_terminal: bool,
) -> i32 {
    let options = match parse_args(args) {
        Ok(Command::Help) => {
            let _ = out.write_all(help().as_bytes());
            return EXIT_OK;
        }
        Ok(Command::Run(o)) => o,
        Err(e) => {
            let _ = writeln!(err, "vehicle-sim: error: {e}\nTry 'vehicle-sim --help'.");
            return EXIT_USAGE;
        }
    };
    let world = match load_world(options.world.as_deref()) {
        Ok(w) => w,
        Err(e) => {
            let _ = writeln!(err, "vehicle-sim: error: {e}");
            return EXIT_FAILURE;
        }
    };
    let warnings: Vec<String> = world.warnings.iter().map(ToString::to_string).collect();
    for w in &warnings {
        let _ = writeln!(err, "vehicle-sim: warning: {w}");
    }
    let scenario = options
        .scenario
        .unwrap_or_else(|| Scenario::default_for(&world));
    let mut bar = ProgressBar::new(err_is_terminal);
    let result = scenario::run(&world, scenario, &mut |p| bar.update(err, p));
    bar.clear(err);
    let report = match result {
        Ok(r) => r,
        Err(e) => {
            let _ = writeln!(err, "vehicle-sim: error: {e}");
            return EXIT_FAILURE;
        }
    };
    for note in report.results.iter().flat_map(|r| &r.notes) {
        let _ = writeln!(err, "vehicle-sim: note: {note}");
    }
    let written = match report::write_outputs(&report, &warnings, &options.out) {
        Ok(w) => w,
        Err(e) => {
            let _ = writeln!(err, "vehicle-sim: error: cannot write the outputs: {e}");
            return EXIT_FAILURE;
        }
    };
    let text = if options.json {
        report::to_json(&report, &warnings) + "\n"
    } else {
        let names: Vec<String> = written
            .iter()
            .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
            .collect();
        format!(
            "{}outputs in {}: {}\n",
            report::summary_table(&report),
            options.out.display(),
            names.join(", ")
        )
    };
    if out.write_all(text.as_bytes()).is_err() {
        return EXIT_FAILURE;
    }
    EXIT_OK
}

/// Runs [`main`] on the process's arguments and standard streams.
pub fn run_process() -> i32 {
    let stderr = std::io::stderr();
    let terminal = stderr.is_terminal();
    main(
        std::env::args().skip(1),
        &mut std::io::stdout().lock(),
        &mut stderr.lock(),
        terminal,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_every_option() {
        let c = parse_args([
            "--world",
            "w.toml",
            "--scenario=brake",
            "--out",
            "o",
            "--json",
        ])
        .unwrap();
        assert_eq!(
            c,
            Command::Run(Options {
                world: Some("w.toml".into()),
                scenario: Some(Scenario::Brake),
                out: PathBuf::from("o"),
                json: true,
            })
        );
        assert_eq!(parse_args(["-h"]).unwrap(), Command::Help);
        assert_eq!(
            parse_args(Vec::<String>::new()).unwrap(),
            Command::Run(Options::default())
        );
    }

    #[test]
    fn usage_errors() {
        assert_eq!(
            parse_args(["--fast"]).unwrap_err(),
            "unknown option '--fast'"
        );
        assert_eq!(
            parse_args(["--world"]).unwrap_err(),
            "option '--world' needs a value"
        );
        assert_eq!(
            parse_args(["--out", "--json"]).unwrap_err(),
            "option '--out' needs a value"
        );
        assert!(
            parse_args(["--scenario", "drift"])
                .unwrap_err()
                .contains("unknown scenario 'drift'")
        );
        assert_eq!(parse_args(["x"]).unwrap_err(), "unexpected argument 'x'");
        assert_eq!(
            parse_args(["--out", "a", "--out", "b"]).unwrap_err(),
            "option '--out' given twice"
        );
        assert_eq!(
            parse_args(["--json=1"]).unwrap_err(),
            "option '--json' takes no value"
        );
    }
}
