//! The `vehicle-sim` command: its options (clap), the run with its progress bar (indicatif),
//! and the outputs; its sweeps are the subcommands `sweep` and `sweep-merge` ([`SweepOptions`],
//! [`MergeOptions`]).
//!
//! [`main`] is the whole program with its streams and exit code passed in, so tests run it
//! in-process.

mod plot;
mod sweep;

use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use clap::builder::PossibleValue;
use clap::error::ErrorKind;
use clap::{Parser, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use vehicle_model::Model;

use crate::report;
use crate::scenario::{self, Progress, Scenario};
use crate::simulation::is_duration;
use crate::world_file::{self, WorldDescription};

pub use plot::PlotOptions;
pub use sweep::{DEFAULT_SWEEP_DIR, MergeOptions, ShardChoice, SweepOptions};

/// Exit code of a successful run.
pub const EXIT_OK: i32 = 0;
/// Exit code when the world cannot be loaded, the simulation fails or the outputs cannot be
/// written.
pub const EXIT_FAILURE: i32 = 1;
/// Exit code of a command-line usage error (unknown option, missing or invalid value, unknown
/// scenario, a scenario the world cannot run).
pub const EXIT_USAGE: i32 = 2;
/// Exit code of a run whose scenario could not run to its end (e.g. `--duration` ended before
/// the brake test braked): the outputs are written, the metrics of what never happened are
/// missing, and stderr says why.
pub const EXIT_UNFINISHED: i32 = 3;

/// The default output directory.
pub const DEFAULT_OUT_DIR: &str = "vehicle-sim-out";

/// How long a run goes before it draws a progress bar (on a terminal): shorter runs finish
/// before a bar would be readable.
pub const PROGRESS_DELAY: Duration = Duration::from_millis(300);

impl ValueEnum for Scenario {
    fn value_variants<'a>() -> &'a [Self] {
        &Scenario::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.name()).help(self.description()))
    }
}

/// A simulated duration (s): > 0 and at most [`MAX_DURATION`](crate::MAX_DURATION).
fn seconds(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(s) if is_duration(s) => Ok(s),
        _ => Err(format!(
            "'{text}' is not a number of seconds > 0 and at most 86400 (a day)"
        )),
    }
}

/// The shipped models, wrapped at 80 columns, for the help.
fn models_help() -> String {
    let mut out = String::from("Models:");
    let mut line_len = out.len();
    for (i, m) in Model::ALL.iter().map(|m| m.webots_name()).enumerate() {
        let sep = if i + 1 == Model::ALL.len() { "" } else { "," };
        if line_len + m.len() + 2 > 80 {
            out.push_str("\n       ");
            line_len = 7;
        }
        out.push(' ');
        out.push_str(m);
        out.push_str(sep);
        line_len += m.len() + 1 + sep.len();
    }
    out
}

/// What the command line asks for.
#[derive(Debug, Clone, PartialEq, Parser)]
#[command(
    name = "vehicle-sim",
    version,
    about = "Drive Webots-style cars and a DifferentialWheels robot on rapier3d physics and \
             report metrics, telemetry CSV and SVG plots.",
    after_help = after_help(),
    args_conflicts_with_subcommands = true
)]
pub struct Options {
    /// A sweep instead of one run
    #[command(subcommand)]
    pub command: Option<Command>,
    /// A TOML world file, a shipped world by name (`vehicle-sim worlds` lists them), or a
    /// shipped model name for the default world with that car (default: BmwX5 on flat
    /// ground, 10 ms)
    #[arg(long, value_name = "FILE|WORLD|MODEL")]
    pub world: Option<String>,
    /// The driving programme (default: `programme` when the world has one or holds several
    /// vehicles, else `test-track` for a car, `square` for a robot)
    #[arg(long, value_name = "NAME")]
    pub scenario: Option<Scenario>,
    /// Output directory
    #[arg(long, value_name = "DIR", default_value = DEFAULT_OUT_DIR)]
    pub out: PathBuf,
    /// Print the metrics as one JSON object on stdout instead of the table
    #[arg(long)]
    pub json: bool,
    /// Write no files (no telemetry, metrics or plots)
    #[arg(long)]
    pub no_files: bool,
    /// Print nothing but errors (and the JSON of --json): no table, progress, warnings or
    /// notes
    #[arg(short, long)]
    pub quiet: bool,
    /// Simulated time (s) of the run, instead of the world's `duration`: caps each built-in
    /// scenario, sets the length of a programme
    #[arg(long, value_name = "SECONDS", value_parser = seconds)]
    pub duration: Option<f64>,
    /// Seed of the DifferentialWheels robot's slip and encoder noise, instead of the world's
    /// `seed` (cars have no noise)
    #[arg(long, value_name = "N")]
    pub seed: Option<u64>,
    /// Draw the radars' targets in replay.glb, as the world's `replayOverlay = true` does
    #[arg(long)]
    pub replay_overlay: bool,
}

/// The subcommands: sweeps, and plots of a run written elsewhere.
#[derive(Debug, Clone, PartialEq, Eq, Subcommand)]
pub enum Command {
    /// Run one scenario on every case of a sweep file (axes over world-file keys) on every
    /// core, or one shard of the cases; a row of metrics per case in results.csv
    Sweep(SweepOptions),
    /// Merge the output directories of a sweep's shards into one results.csv in case order
    SweepMerge(MergeOptions),
    /// Draw the SVG plots of a run from its telemetry.csv (a controller run under
    /// VEHICLE_OUT, a Python Simulation.save, ...), into the same directory
    Plot(PlotOptions),
    /// List the worlds shipped in the binary, which `--world NAME` runs: name and what it is
    Worlds,
}

/// Where the world-file reference is: the crate's README in the repository, which an
/// installed binary does not carry.
const WORLD_REFERENCE: &str = concat!(env!("CARGO_PKG_REPOSITORY"), "/blob/main/sim/README.md");

fn after_help() -> String {
    format!(
        "{}\n\nExit status: 0 success, 1 world, simulation or output error, 2 usage error, 3 a \
         scenario that could not run to its end (outputs written, stderr says why).\n\
         Shipped worlds: vehicle-sim worlds. World file reference: {WORLD_REFERENCE}",
        models_help()
    )
}

/// `vehicle-sim worlds`: every shipped world's name and first comment line, aligned.
fn worlds_main(out: &mut dyn Write) -> i32 {
    let worlds: Vec<_> = world_file::shipped::worlds().collect();
    let width = worlds.iter().map(|w| w.name.len()).max().unwrap_or(0);
    let mut text = String::new();
    for w in &worlds {
        text.push_str(&format!("{:width$}  {}\n", w.name, w.summary()));
    }
    text.push_str("Run one with: vehicle-sim --world NAME\n");
    if out.write_all(text.as_bytes()).is_err() {
        return EXIT_FAILURE;
    }
    EXIT_OK
}

/// A progress bar on stderr, drawn only on a terminal once the run has lasted
/// [`PROGRESS_DELAY`].
struct Bar {
    enabled: bool,
    start: Instant,
    bar: Option<ProgressBar>,
}

impl Bar {
    /// Per-mille steps of the bar.
    const LENGTH: u64 = 1000;

    fn new(enabled: bool) -> Self {
        Bar {
            enabled,
            start: Instant::now(),
            bar: None,
        }
    }

    fn update(&mut self, p: Progress) {
        if !self.enabled || self.start.elapsed() < PROGRESS_DELAY {
            return;
        }
        let bar = self.bar.get_or_insert_with(|| {
            let bar =
                ProgressBar::with_draw_target(Some(Self::LENGTH), ProgressDrawTarget::stderr());
            if let Ok(style) = ProgressStyle::with_template("[{bar:30}] {percent:>3}%  {msg}") {
                bar.set_style(style.progress_chars("#>-"));
            }
            bar
        });
        bar.set_position((p.fraction.clamp(0.0, 1.0) * Self::LENGTH as f64) as u64);
        bar.set_message(format!(
            "{} ({}/{}) t = {:.1} s",
            p.scenario,
            p.index + 1,
            p.count,
            p.time
        ));
    }

    fn clear(&mut self) {
        if let Some(bar) = self.bar.take() {
            bar.finish_and_clear();
        }
    }
}

/// Loads the world of `--world` (or the default world) with the overrides of `--duration`,
/// `--seed` and `--replay-overlay` (which only turns the overlay on: without it the world's
/// `replayOverlay` stands).
fn load_world(options: &Options) -> Result<WorldDescription, world_file::WorldFileErrors> {
    let mut world = match options.world.as_deref() {
        Some(s) => world_file::load_all(s)?,
        None => world_file::default_world(),
    };
    if let Some(d) = options.duration {
        world.duration = Some(d);
    }
    if let (Some(seed), Some(robot)) = (options.seed, world.robot.as_mut()) {
        robot.params.seed = seed;
    }
    if options.replay_overlay {
        world.replay_overlay = true;
    }
    Ok(world)
}

/// The whole `vehicle-sim` program: parses `args` (without the program name), runs, writes
/// the outputs and the report to `out`, messages to `err`, and returns the exit code. When
/// `err_is_terminal`, a progress bar is drawn on the process's stderr.
pub fn main(
    args: impl IntoIterator<Item = String>,
    out: &mut dyn Write,
    err: &mut dyn Write,
    err_is_terminal: bool,
) -> i32 {
    let args = std::iter::once("vehicle-sim".to_string()).chain(args);
    let options = match Options::try_parse_from(args) {
        Ok(o) => o,
        Err(e) if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) => {
            let _ = write!(out, "{}", e.render());
            return EXIT_OK;
        }
        Err(e) => {
            let _ = write!(err, "{}", e.render());
            return EXIT_USAGE;
        }
    };
    match &options.command {
        Some(Command::Sweep(o)) => return sweep::sweep_main(o, out, err, err_is_terminal),
        Some(Command::SweepMerge(o)) => return sweep::merge_main(o, out, err),
        Some(Command::Plot(o)) => return plot::plot_main(o, out, err),
        Some(Command::Worlds) => return worlds_main(out),
        None => {}
    }
    let world = match load_world(&options) {
        Ok(w) => w,
        Err(e) => {
            // Every error of the file, each with its line (each starts with "error: ").
            let _ = writeln!(err, "vehicle-sim: {e}");
            return EXIT_FAILURE;
        }
    };
    let warnings: Vec<String> = world.warnings.iter().map(ToString::to_string).collect();
    if !options.quiet {
        for w in &warnings {
            let _ = writeln!(err, "vehicle-sim: warning: {w}");
        }
    }
    let scenario = options
        .scenario
        .unwrap_or_else(|| Scenario::default_for(&world));
    if let Err(e) = scenario.check(&world) {
        let _ = writeln!(
            err,
            "vehicle-sim: error: {e}\nFor more information, try '--help'."
        );
        return EXIT_USAGE;
    }
    let mut bar = Bar::new(err_is_terminal && !options.quiet);
    let result = scenario::run(&world, scenario, &mut |p| bar.update(p));
    bar.clear();
    let report = match result {
        Ok(r) => r,
        Err(e) => {
            let _ = writeln!(err, "vehicle-sim: error: {e}");
            return EXIT_FAILURE;
        }
    };
    if !options.quiet {
        for note in report.results.iter().flat_map(|r| &r.notes) {
            let _ = writeln!(err, "vehicle-sim: note: {note}");
        }
    }
    let names = if options.no_files {
        Vec::new()
    } else {
        match report::write_outputs(&report, &warnings, &options.out) {
            Ok(_) => report::output_names(&report),
            Err(e) => {
                let _ = writeln!(err, "vehicle-sim: error: cannot write the outputs: {e}");
                return EXIT_FAILURE;
            }
        }
    };
    let text = if options.json {
        report::to_json(&report, &warnings, &names) + "\n"
    } else if options.quiet {
        String::new()
    } else if options.no_files {
        format!(
            "{}no files written (--no-files)\n",
            report::summary_table(&report)
        )
    } else {
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
    let mut code = EXIT_OK;
    for r in &report.results {
        if let Some(why) = &r.unfinished {
            let _ = writeln!(
                err,
                "vehicle-sim: error: scenario {} did not run to its end: {why}",
                r.name
            );
            code = EXIT_UNFINISHED;
        }
    }
    code
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

    fn parse(args: &[&str]) -> Result<Options, clap::Error> {
        Options::try_parse_from(std::iter::once("vehicle-sim").chain(args.iter().copied()))
    }

    #[test]
    fn parses_every_option() {
        let o = parse(&[
            "--world",
            "w.toml",
            "--scenario=brake",
            "--out",
            "o",
            "--json",
            "--no-files",
            "-q",
            "--duration",
            "2.5",
            "--seed",
            "7",
            "--replay-overlay",
        ])
        .unwrap();
        assert_eq!(
            o,
            Options {
                command: None,
                world: Some("w.toml".into()),
                scenario: Some(Scenario::Brake),
                out: PathBuf::from("o"),
                json: true,
                no_files: true,
                quiet: true,
                duration: Some(2.5),
                seed: Some(7),
                replay_overlay: true,
            }
        );
        let d = parse(&[]).unwrap();
        assert_eq!(d.out, PathBuf::from(DEFAULT_OUT_DIR));
        assert_eq!((d.world, d.scenario, d.json), (None, None, false));
        assert!(!d.replay_overlay);
        assert_eq!(
            parse(&["--scenario", "programme"]).unwrap().scenario,
            Some(Scenario::Programme)
        );
    }

    #[test]
    fn parses_the_sweep_subcommands() {
        let o = parse(&[
            "sweep",
            "s.toml",
            "--out",
            "o",
            "--threads",
            "2",
            "--shard",
            "auto",
            "--shards",
            "4",
        ])
        .unwrap();
        assert_eq!(
            o.command,
            Some(Command::Sweep(SweepOptions {
                file: "s.toml".into(),
                out: "o".into(),
                threads: Some(2),
                shard: Some(ShardChoice::Auto),
                shards: Some(4),
                resume: false,
                quiet: false,
            }))
        );
        let o = parse(&["sweep", "s.toml", "--shard", "1/3", "--resume", "-q"]).unwrap();
        let Some(Command::Sweep(s)) = o.command else {
            panic!("{o:?}")
        };
        assert_eq!(s.shard, Some(ShardChoice::Fixed("1/3".parse().unwrap())));
        assert_eq!(s.out, PathBuf::from(DEFAULT_SWEEP_DIR));
        assert!(s.resume && s.quiet);
        let o = parse(&["sweep-merge", "a", "b", "--out", "m"]).unwrap();
        assert_eq!(
            o.command,
            Some(Command::SweepMerge(MergeOptions {
                dirs: vec!["a".into(), "b".into()],
                out: "m".into(),
                quiet: false,
            }))
        );
    }

    #[test]
    fn usage_errors() {
        let kind = |args: &[&str]| parse(args).unwrap_err().kind();
        assert_eq!(kind(&["--fast"]), ErrorKind::UnknownArgument);
        assert_eq!(kind(&["--world"]), ErrorKind::InvalidValue);
        assert_eq!(kind(&["--scenario", "drift"]), ErrorKind::InvalidValue);
        assert_eq!(kind(&["x"]), ErrorKind::InvalidSubcommand);
        assert_eq!(
            kind(&["--out", "a", "--out", "b"]),
            ErrorKind::ArgumentConflict
        );
        assert_eq!(kind(&["--duration=-1"]), ErrorKind::ValueValidation);
        assert_eq!(kind(&["--duration", "inf"]), ErrorKind::ValueValidation);
        assert_eq!(kind(&["--seed", "x"]), ErrorKind::ValueValidation);
        assert_eq!(kind(&["--help"]), ErrorKind::DisplayHelp);
        assert_eq!(kind(&["--version"]), ErrorKind::DisplayVersion);
        assert_eq!(kind(&["sweep"]), ErrorKind::MissingRequiredArgument);
        assert_eq!(
            kind(&["--world", "w.toml", "sweep", "s.toml"]),
            ErrorKind::ArgumentConflict
        );
        assert_eq!(
            kind(&["sweep", "s.toml", "--threads", "0"]),
            ErrorKind::ValueValidation
        );
        assert_eq!(
            kind(&["sweep", "s.toml", "--shard", "3/3"]),
            ErrorKind::ValueValidation
        );
        assert_eq!(
            kind(&["sweep", "s.toml", "--shards", "3"]),
            ErrorKind::MissingRequiredArgument
        );
        assert_eq!(
            kind(&["sweep-merge", "a"]),
            ErrorKind::MissingRequiredArgument
        );
        // A misspelt scenario gets a suggestion.
        let e = parse(&["--scenario", "brak"]).unwrap_err().to_string();
        assert!(e.contains("brake"), "{e}");
    }
}
