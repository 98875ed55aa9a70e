//! Sweeps: one scenario run on many variants of a world, on every core of a machine or split
//! over the tasks of a batch engine, with one row of metrics per variant.
//!
//! A sweep file (TOML) names a base world (a world file, relative to the sweep file, or a
//! shipped model or world name, as `vehicle-sim --world` takes it), a scenario, settings for every
//! case (`[set]`) and axes over any world-file key by its dotted path: explicit lists, linear
//! ranges and seeded random draws. The cases are every combination of the axes' values
//! (`combine = "product"`, the default) or their values side by side (`"zip"`).
//!
//! ```toml
//! world = "BmwX5"
//! scenario = "brake"
//! [axes]
//! "ground.friction" = [0.6, 0.8, 1.0]
//! "vehicle.brakeCoefficient" = { from = 1000, to = 2000, steps = 5 }
//! ```
//!
//! Each case's world is the base world's document with the case's values set at their keys,
//! read by the world-file reader ([`crate::world_file`]): a value the world file refuses is
//! that case's error, naming the key, and the other cases run. A random draw is a function of
//! the axis's seed, its key and the draw's index only (see the `draw` module), so a case is
//! the same on any shard, thread or Python worker.
//!
//! ```
//! use sim::sweep::Sweep;
//!
//! let text = "world = \"BmwX5\"\nscenario = \"brake\"\n[set]\nduration = 1\n[axes]\n\
//!             \"ground.friction\" = [0.5, -1]\n";
//! let sweep = Sweep::parse("s.toml", text, std::path::Path::new("."))?;
//! assert_eq!(sweep.len(), 2);
//! let row = sweep.run_case(1)?;
//! assert_eq!(
//!     row.error.map(|e| e.to_string()).as_deref(),
//!     Some("invalid 'ground.friction': -1: must be finite and >= 0")
//! );
//! assert_eq!(sweep.columns().names()[..3], ["case", "ground.friction", "initial_speed_kmh"]);
//! # Ok::<(), sim::sweep::SweepError>(())
//! ```
//!
//! With the `app` feature (default), `run` runs a shard's cases on a rayon pool and hands
//! their rows over in case order; `write_sweep` writes them into `results.csv` (with
//! `timings.csv`, the manifest `sweep.json` and the plots: a scatter per numeric axis, a box
//! and strip per value of a categorical one, the cases coloured by the axis `color_by` names,
//! see the `plots` module); `merge` puts shards' outputs back together. Without it, the cases run one at a time by index ([`Sweep::run_case`]).

mod axis;
mod cases;
mod color;
mod draw;
mod error;
mod file;
mod manifest;
#[cfg(feature = "app")]
mod merge;
#[cfg(feature = "app")]
mod output;
#[cfg(feature = "app")]
mod plots;
#[cfg(feature = "app")]
mod resume;
mod row;
#[cfg(feature = "app")]
mod runner;
mod shard;
mod value;

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

use toml::de::DeValue;
use vehicle_model::Model;

use crate::error::panic_message;
use crate::scenario::{self, Scenario};
use crate::world_file::read::Source;
use crate::world_file::{
    self, DEFAULT_WORLD, DEFAULT_WORLD_NAME, KeyPath, WorldDescription, WorldFileError,
    WorldFileErrorKind, WorldWarning,
};

pub use axis::{Axis, AxisValues};
pub use cases::Combine;
pub use color::{ColorBy, MAX_COLOURS, NO_COLOR};
#[cfg(feature = "app")]
pub use error::OutputError;
pub use error::SweepError;
pub use manifest::{Fingerprint, MANIFEST_JSON, Manifest};
#[cfg(feature = "app")]
pub use merge::{LISTED_MISSING, MergeError, MergeSummary, STAGING_PREFIX, merge};
#[cfg(feature = "app")]
pub use output::{PLOTS_DIR, RESULTS_CSV, RunSummary, TIMINGS_CSV, WriteOptions, write_sweep};
#[cfg(feature = "app")]
pub use plots::{MAX_CATEGORIES, write_plots};
pub use row::{
    CASE_COLUMN, CHECKSUM_COLUMN, CaseError, Cell, Columns, ERROR_COLUMN, NOTES_COLUMN, Row,
    checksum, checksum_matches,
};
#[cfg(feature = "app")]
pub(crate) use runner::thread_count;
#[cfg(feature = "app")]
pub use runner::{Ended, MAX_THREADS, RunError, RunFrom, run, run_from};
pub use shard::{MAX_SHARDS, Shard, ShardError};
pub use value::AxisValue;

/// One case: its index, its axis values and its world.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// Its index, from 0.
    pub index: usize,
    /// Its value of each axis, in the axes' order.
    pub values: Vec<AxisValue>,
    /// The base world with the case's values, or why that world is invalid.
    pub world: Result<WorldDescription, CaseError>,
}

/// A loaded sweep: the base world, the scenario, the axes and the columns of its results.
#[derive(Debug, Clone)]
pub struct Sweep {
    file: String,
    text: String,
    world_source: String,
    world_text: String,
    base: WorldDescription,
    scenario: Scenario,
    combine: Combine,
    set: Vec<(KeyPath, AxisValue)>,
    axes: Vec<Axis>,
    columns: Columns,
    cases: usize,
    fingerprint: Fingerprint,
    color_by: ColorBy,
}

/// The sweep file's `color_by = key` (at `span`): [`NO_COLOR`], or one of `axes` of at most
/// [`MAX_COLOURS`] distinct values.
fn color_by(
    src: Source<'_>,
    key: &str,
    span: &core::ops::Range<usize>,
    axes: &[Axis],
) -> Result<ColorBy, SweepError> {
    let refuse = |message: String| {
        SweepError::file(src.error(
            Some(span.clone()),
            Some("color_by".to_string()),
            WorldFileErrorKind::InvalidValue(message),
        ))
    };
    if key == NO_COLOR {
        return Ok(ColorBy::Off);
    }
    let Some(axis) = axes.iter().find(|a| a.key().as_str() == key) else {
        let names: Vec<&str> = axes.iter().map(|a| a.key().as_str()).collect();
        return Err(refuse(format!(
            "'{key}' is not an axis of this sweep (its axes: {}; or \"{NO_COLOR}\")",
            names.join(", ")
        )));
    };
    // Distinct values, counted until one too many (a range of 10⁹ steps stops at 8).
    let mut distinct: Vec<AxisValue> = Vec::new();
    for v in (0..axis.len()).map_while(|k| axis.value(k)) {
        if !distinct.contains(&v) {
            distinct.push(v);
            if distinct.len() > MAX_COLOURS {
                return Err(refuse(format!(
                    "'{key}' has more than {MAX_COLOURS} distinct values, one colour each"
                )));
            }
        }
    }
    Ok(ColorBy::Axis(key.to_string()))
}

/// Where the base world comes from: its name in messages and its text.
fn base_world(
    src: Source<'_>,
    spec: Option<&(String, core::ops::Range<usize>)>,
    dir: &Path,
) -> Result<(String, String), SweepError> {
    let Some((name, span)) = spec.filter(|(n, _)| !n.trim().is_empty()) else {
        return Ok((DEFAULT_WORLD_NAME.to_string(), DEFAULT_WORLD.to_string()));
    };
    let path = dir.join(name);
    if !path.exists() {
        if let Some(model) = Model::from_name(name) {
            let source = world_file::with_model(model).source;
            return Ok((source, world_file::model_world_text(model)));
        }
        if let Some(world) = world_file::shipped::world(name) {
            return Ok((world.source(), world.text.to_string()));
        }
        let looks_like_path = name.contains(['/', '\\']) || name.ends_with(".toml");
        if !looks_like_path {
            let names = Model::ALL
                .map(Model::webots_name)
                .into_iter()
                .chain(world_file::shipped::worlds().flat_map(|w| [w.name, w.file_name]));
            return Err(SweepError::file(src.error(
                Some(span.clone()),
                Some("world".to_string()),
                WorldFileErrorKind::NeitherFileNorModel {
                    name: name.clone(),
                    suggestions: world_file::closest(name, names),
                },
            )));
        }
    }
    let source = path.display().to_string();
    match world_file::read_text(&path) {
        Ok(text) => Ok((source, text)),
        Err(message) => Err(SweepError::world(WorldFileError {
            file: source,
            location: None,
            key: None,
            kind: WorldFileErrorKind::Io(message),
        })),
    }
}

/// Checks the axis `a` of the sweep file `src` against the base world (`text` with `set`):
/// every value of a list, the first of a range or draw (the others differ only in number). A
/// key the world does not have (located at the axis's key), or a value of a type or name it
/// does not take (at the value), is the sweep file's error; a value the world refuses is not:
/// it is its cases' error.
fn check_axis(
    src: Source<'_>,
    a: &axis::ReadAxis,
    source: &str,
    text: &str,
    set: &[(KeyPath, AxisValue)],
) -> Result<(), SweepError> {
    let checked: Vec<(AxisValue, &core::ops::Range<usize>)> = match a.axis.values() {
        AxisValues::List(values) => values.iter().cloned().zip(&a.value_spans).collect(),
        _ => a
            .axis
            .value(0)
            .into_iter()
            .map(|v| (v, &a.key_span))
            .collect(),
    };
    for (value, span) in checked {
        let one = [(a.axis.key().clone(), value)];
        let Err(e) = read_world(source, text, set, &one) else {
            continue;
        };
        let at = match e.kind {
            WorldFileErrorKind::InvalidValue(_) => continue,
            WorldFileErrorKind::UnknownKey { .. } | WorldFileErrorKind::Structure(_) => &a.key_span,
            _ => span,
        };
        return Err(SweepError::file(src.error(Some(at.clone()), e.key, e.kind)));
    }
    Ok(())
}

/// The metric columns of `scenario` on `world`: its metrics on a run of one step (every
/// scenario reports the same keys however long it runs, a metric not reached being empty).
fn metric_columns(
    world: &WorldDescription,
    scenario: Scenario,
) -> Result<Vec<String>, scenario::ScenarioError> {
    let mut probe = world.clone();
    probe.duration = Some(f64::from(world.config.basic_time_step_ms) / 1000.0);
    let report = scenario::run(&probe, scenario, &mut |_| {})?;
    Ok(row::metric_cells(&report)
        .into_iter()
        .map(|(name, _)| name)
        .collect())
}

impl Sweep {
    /// Loads the sweep file at `path`; a relative `world` path is relative to its directory.
    ///
    /// # Errors
    /// See [`Sweep::parse`]; [`SweepError::Io`] when the file cannot be read or is longer
    /// than [`world_file::MAX_FILE_BYTES`].
    pub fn load(path: impl AsRef<Path>) -> Result<Sweep, SweepError> {
        let path = path.as_ref();
        let file = path.display().to_string();
        let text = world_file::read_text(path).map_err(|message| SweepError::Io {
            file: file.clone(),
            message,
        })?;
        let dir = path.parent().unwrap_or(Path::new(""));
        Sweep::parse(&file, &text, dir)
    }

    /// Loads the sweep file at `path` as [`Sweep::load`] does, with every error of the sweep
    /// file itself in one report, in file order, each with its line
    /// ([`world_file::diagnostics::collect`]); an error that is not the sweep file's (it cannot
    /// be read, its base world is invalid) is reported alone, without its line.
    ///
    /// # Errors
    /// As [`Sweep::load`], every error of the file.
    pub fn load_all(path: impl AsRef<Path>) -> Result<Sweep, world_file::WorldFileErrors> {
        let path = path.as_ref();
        let file = path.display().to_string();
        let unlocated = |e: SweepError| match e {
            SweepError::File(e) => *e,
            SweepError::World(e) => WorldFileError {
                location: None,
                ..*e
            },
            other => WorldFileError {
                file: file.clone(),
                location: None,
                key: None,
                kind: WorldFileErrorKind::Structure(other.to_string()),
            },
        };
        let text = world_file::read_text(path).map_err(|message| WorldFileError {
            file: file.clone(),
            location: None,
            key: None,
            kind: WorldFileErrorKind::Structure(format!("cannot read the sweep file: {message}")),
        })?;
        let dir = path.parent().unwrap_or(Path::new(""));
        world_file::diagnostics::collect(&text, |t| Sweep::parse(&file, t, dir).map_err(&unlocated))
    }

    /// Parses sweep-file `text` (`file` names it in messages; a relative `world` path is
    /// relative to `dir`), loads the base world with `[set]`, checks each axis's key and
    /// values' type against it, and finds the metric columns (the scenario's metrics on the
    /// base world, from a run of one step).
    ///
    /// # Errors
    /// [`SweepError::File`] at the sweep file's line and key: invalid TOML, an unknown key, a
    /// bad axis shape, a `world` that is neither a file nor a model, a `[set]` value or an
    /// axis value of a type the world file refuses (an unknown world-file key, a string for a
    /// number), a scenario the base world cannot run, zipped axes of different lengths.
    /// [`SweepError::World`] when the base world itself cannot be loaded.
    pub fn parse(file: &str, text: &str, dir: &Path) -> Result<Sweep, SweepError> {
        let src = Source { file, text };
        let spec = file::read(src).map_err(SweepError::file)?;
        let (world_source, world_text) = base_world(src, spec.world.as_ref(), dir)?;
        let located = |span: &core::ops::Range<usize>, e: WorldFileError| {
            SweepError::file(src.error(Some(span.clone()), e.key, e.kind))
        };
        let set: Vec<(KeyPath, AxisValue)> = spec
            .set
            .iter()
            .map(|s| (s.key.clone(), s.value.clone()))
            .collect();
        let base = read_world(&world_source, &world_text, &set, &[]).map_err(|e| {
            match spec
                .set
                .iter()
                .find(|s| e.key.as_deref().is_some_and(|k| s.key.covers(k)))
            {
                Some(s) => located(&s.span, e),
                None => SweepError::world(e),
            }
        })?;
        if let Some((w, s)) = base.warnings.iter().find_map(|w| {
            let key = w.key.as_deref()?;
            spec.set.iter().find(|s| s.key.covers(key)).map(|s| (w, s))
        }) {
            return Err(located(
                &s.span,
                WorldFileError {
                    file: file.to_string(),
                    location: None,
                    key: w.key.clone(),
                    kind: WorldFileErrorKind::InvalidValue(format!(
                        "a world file would replace the value: {}",
                        w.message
                    )),
                },
            ));
        }
        let world_span = spec.world.as_ref().map_or(0..0, |(_, s)| s.clone());
        let (scenario, scenario_span) = spec
            .scenario
            .clone()
            .unwrap_or_else(|| (Scenario::default_for(&base), world_span.clone()));
        scenario.check(&base).map_err(|e| {
            located(
                &scenario_span,
                WorldFileError {
                    file: file.to_string(),
                    location: None,
                    key: Some("scenario".to_string()),
                    kind: WorldFileErrorKind::InvalidValue(e.to_string()),
                },
            )
        })?;
        for a in &spec.axes {
            check_axis(src, a, &world_source, &world_text, &set)?;
        }
        let axes: Vec<Axis> = spec.axes.into_iter().map(|a| a.axis).collect();
        let (combine, combine_span) = spec.combine;
        let cases = cases::count(&axes, combine).map_err(|e| {
            let message = match e {
                cases::CountError::TooMany => "the axes make more cases than fit a usize".into(),
                cases::CountError::Lengths([(a, n), (b, m)]) => {
                    format!("zip needs axes of one length: '{a}' has {n} values, '{b}' has {m}")
                }
            };
            SweepError::file(src.error(
                combine_span,
                Some("combine".to_string()),
                WorldFileErrorKind::InvalidValue(message),
            ))
        })?;
        let metrics = metric_columns(&base, scenario).map_err(|e| {
            SweepError::file(src.error(
                Some(world_span.clone()),
                Some("world".to_string()),
                WorldFileErrorKind::InvalidValue(format!(
                    "the base world cannot run '{scenario}': {e}"
                )),
            ))
        })?;
        let columns = Columns {
            axes: axes.iter().map(|a| a.key().to_string()).collect(),
            metrics,
        };
        let color_by = match &spec.color_by {
            None => ColorBy::Auto,
            Some((key, span)) => color_by(src, key, span, &axes)?,
        };
        let fingerprint = Fingerprint::of(text, &world_text);
        Ok(Sweep {
            file: file.to_string(),
            text: text.to_string(),
            world_source,
            world_text,
            base,
            scenario,
            combine,
            set,
            axes,
            columns,
            cases,
            fingerprint,
            color_by,
        })
    }

    /// The sweep file, as given.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// The sweep file's text.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Where the base world comes from: its path, or the default world's name.
    pub fn world_source(&self) -> &str {
        &self.world_source
    }

    /// The base world with `[set]` (every case's world but for its axis values).
    pub fn base(&self) -> &WorldDescription {
        &self.base
    }

    /// The base world's warnings (values it replaced by their defaults, as Webots does).
    pub fn warnings(&self) -> &[WorldWarning] {
        &self.base.warnings
    }

    /// The scenario each case runs.
    pub fn scenario(&self) -> Scenario {
        self.scenario
    }

    /// How the axes combine into cases.
    pub fn combine(&self) -> Combine {
        self.combine
    }

    /// The axis the plots colour the cases by (`color_by`).
    pub fn color_by(&self) -> &ColorBy {
        &self.color_by
    }

    /// The axes, in the sweep file's order.
    pub fn axes(&self) -> &[Axis] {
        &self.axes
    }

    /// The columns of the results.
    pub fn columns(&self) -> &Columns {
        &self.columns
    }

    /// The number of cases.
    pub fn len(&self) -> usize {
        self.cases
    }

    /// True for a sweep without cases (never: a sweep without axes has one case, the base
    /// world).
    pub fn is_empty(&self) -> bool {
        self.cases == 0
    }

    /// A fingerprint of the sweep file's text, the base world's text and this program's
    /// version: shards of one sweep have the same.
    pub fn fingerprint(&self) -> Fingerprint {
        self.fingerprint
    }

    /// Case `index`: its axis values and its world.
    ///
    /// # Errors
    /// [`SweepError::NoSuchCase`] past the last case.
    pub fn case(&self, index: usize) -> Result<Case, SweepError> {
        let values = self.values(index)?;
        let overrides: Vec<(KeyPath, AxisValue)> = self
            .axes
            .iter()
            .map(|a| a.key().clone())
            .zip(values.iter().cloned())
            .collect();
        let world = read_world(&self.world_source, &self.world_text, &self.set, &overrides)
            .map_err(CaseError::World)
            .and_then(|w| self.own_warning(&w, &overrides).map_or(Ok(w), Err));
        Ok(Case {
            index,
            values,
            world,
        })
    }

    /// Case `index`'s axis values.
    ///
    /// # Errors
    /// [`SweepError::NoSuchCase`] past the last case.
    pub fn values(&self, index: usize) -> Result<Vec<AxisValue>, SweepError> {
        if index >= self.cases {
            return Err(SweepError::NoSuchCase {
                index,
                cases: self.cases,
            });
        }
        Ok(cases::positions(&self.axes, self.combine, index)
            .into_iter()
            .zip(&self.axes)
            .filter_map(|(k, a)| a.value(k))
            .collect())
    }

    /// The first warning of `world` (a case's) that is about one of the case's values or
    /// that the base world does not have: a value the world file replaced.
    fn own_warning(
        &self,
        world: &WorldDescription,
        overrides: &[(KeyPath, AxisValue)],
    ) -> Option<CaseError> {
        let keys: Vec<&KeyPath> = self.set.iter().chain(overrides).map(|(k, _)| k).collect();
        world
            .warnings
            .iter()
            .find(|w| {
                let about_value = w
                    .key
                    .as_deref()
                    .is_some_and(|k| keys.iter().any(|p| p.covers(k)));
                let new = !self
                    .base
                    .warnings
                    .iter()
                    .any(|b| b.key == w.key && b.message == w.message);
                about_value || new
            })
            .map(|w| CaseError::Replaced {
                key: w.key.clone().unwrap_or_else(|| "vehicle".to_string()),
                message: w.message.clone(),
            })
    }

    /// Runs case `index` and returns its row: its metrics, or the error that stopped it
    /// (an invalid world, a scenario the world cannot run, a failed simulation; even a
    /// panic, reported as a bug). Takes as long as the scenario (milliseconds for `brake`).
    ///
    /// # Errors
    /// [`SweepError::NoSuchCase`] past the last case.
    pub fn run_case(&self, index: usize) -> Result<Row, SweepError> {
        let case = self.case(index)?;
        let values = case.values.clone();
        let run = catch_unwind(AssertUnwindSafe(|| self.run(case)));
        Ok(run.unwrap_or_else(|payload| {
            let message = panic_message(payload.as_ref());
            Row::failed(index, values, &self.columns, CaseError::Panic(message))
        }))
    }

    /// The row of `case`, run.
    fn run(&self, case: Case) -> Row {
        match case.world {
            Err(e) => Row::failed(case.index, case.values, &self.columns, e),
            Ok(world) => match scenario::run(&world, self.scenario, &mut |_| {}) {
                Ok(report) => Row::of_report(case.index, case.values, &self.columns, &report),
                Err(e) => Row::failed(
                    case.index,
                    case.values,
                    &self.columns,
                    CaseError::Scenario(e),
                ),
            },
        }
    }
}

/// The world of `text` with `set` and `values` set at their keys.
fn read_world(
    source: &str,
    text: &str,
    set: &[(KeyPath, AxisValue)],
    values: &[(KeyPath, AxisValue)],
) -> Result<WorldDescription, WorldFileError> {
    let all: Vec<&(KeyPath, AxisValue)> = set.iter().chain(values).collect();
    let literals: Vec<String> = all.iter().map(|(_, v)| v.toml_literal()).collect();
    let mut overrides = Vec::with_capacity(all.len());
    for ((key, _), literal) in all.iter().zip(&literals) {
        // A literal written by `toml_literal` is valid TOML.
        let value = DeValue::parse(literal).map_err(|e| WorldFileError {
            file: source.to_string(),
            location: None,
            key: Some(key.to_string()),
            kind: WorldFileErrorKind::Syntax(e.message().to_string()),
        })?;
        overrides.push((key, value.into_inner()));
    }
    world_file::parse_with(source, text, overrides)
}
