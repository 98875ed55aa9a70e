//! Loading a sweep file: its base world, its axes checked against that world, its cases and
//! its result columns.

use std::path::Path;

use vehicle_model::Model;

use super::{
    Axis, AxisValue, AxisValues, ColorBy, Columns, Fingerprint, MAX_COLOURS, NO_COLOR, Sweep,
    SweepError, axis, cases, file, read_world, row,
};
use crate::scenario::{self, Scenario};
use crate::world_file::read::Source;
use crate::world_file::{
    self, DEFAULT_WORLD, DEFAULT_WORLD_NAME, KeyPath, WorldDescription, WorldFileError,
    WorldFileErrorKind,
};

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
}
