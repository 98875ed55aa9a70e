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
mod load;
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

use toml::de::DeValue;

use crate::error::panic_message;
use crate::scenario::{self, Scenario};
use crate::world_file::{
    self, KeyPath, WorldDescription, WorldFileError, WorldFileErrorKind, WorldWarning,
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
pub use runner::{Ended, MAX_THREADS, RunError, RunFrom, WINDOW_PER_THREAD, run, run_from};
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

impl Sweep {
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
