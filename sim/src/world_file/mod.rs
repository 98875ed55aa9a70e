//! World files: a TOML description of a world in Webots vocabulary (time step, ground,
//! obstacles, dynamic boxes, cars on their tyres with their driving programmes, a
//! DifferentialWheels robot), and the built-in default world.
//!
//! ```toml
//! basicTimeStep = 10          # ms
//! duration = 60.0             # s, optional
//! [vehicle]
//! model = "BmwX5"
//! time0To100 = 7.0            # any Car / AckermannVehicle field by its Webots name
//! tyre = "magic-formula"      # or "webots", or a table [vehicle.tyre]
//! [ground]
//! friction = 1.0
//! ```
//!
//! [`load`] takes a path or a shipped model name (the default world with that car), as the
//! `vehicle-sim --world` option and the C API's `VEHICLE_WORLD` variable do. Every error names
//! the file, the line and column, the key, and for a misspelt key the closest valid names;
//! nothing panics. See `sim/README.md` for the full reference.
//!
//! ```
//! let w = sim::world_file::parse_str("w.toml", "basicTimeStep = 16\n[vehicle]\nmodel = \"ToyotaPrius\"\n")?;
//! assert_eq!(w.config.basic_time_step_ms, 16);
//! let car = w.car().unwrap();
//! assert_eq!(car.params.wheelbase, 2.8);
//!
//! let e = sim::world_file::parse_str("w.toml", "[vehicle]\ntimeTo100 = 7\n").unwrap_err();
//! assert_eq!(e.to_string(), "w.toml:2:1: unknown key 'vehicle.timeTo100'; did you mean 'time0To100'?");
//! # Ok::<(), sim::world_file::WorldFileError>(())
//! ```

mod aero;
mod bodies;
mod cone;
mod cycle_programme;
mod devices;
pub mod diagnostics;
mod energy;
mod error;
mod lane_programme;
mod looks;
mod losses;
mod numbers;
mod overrides;
mod programme;
mod ray_devices;
pub(crate) mod read;
mod roads;
mod robot;
pub mod shipped;
mod statics;
mod transmission;
mod tyre;
mod tyre_file;
mod vehicle;

use std::io::Read;
use std::path::Path;

use proto_geom::plausible::Compact;
use toml::de::{DeTable, DeValue};
use vehicle_model::Model;

use crate::appearance::Appearances;
use crate::config::WorldConfig;
use crate::devices::{GpsCoordinateSystem, GpsFrame};
use crate::simulation::{DURATION_RULE, is_duration};

pub use diagnostics::{WorldFileErrors, parse_all};
pub use energy::WebotsBattery;
pub(crate) use energy::default_params as default_energy_params;
pub use error::{Location, NameSet, WorldFileError, WorldFileErrorKind, WorldWarning};
pub use numbers::{Setting, parse_with_numbers, parse_with_settings};
pub use overrides::KeyPath;
pub use robot::RobotDescription;
pub use vehicle::CarDescription;

pub(crate) use error::closest;
use read::{Section, Source};

/// The text of the built-in default world: a BmwX5 on flat ground, `basicTimeStep` 10 ms.
pub const DEFAULT_WORLD: &str = "\
# The built-in default world of vehicle-sim.
basicTimeStep = 10   # ms

[vehicle]
model = \"BmwX5\"

[ground]
friction = 1.0
";

/// The name under which the default world appears in messages.
pub const DEFAULT_WORLD_NAME: &str = "<default world>";

/// The text of the default world with the car `model`: what [`with_model`] describes, as a
/// world file.
pub fn model_world_text(model: Model) -> String {
    DEFAULT_WORLD.replace(
        "model = \"BmwX5\"",
        &format!("model = \"{}\"", model.webots_name()),
    )
}

/// Top-level keys of a world file.
const ROOT_KEYS: [&str; 16] = [
    "basicTimeStep",
    GPS_COORDINATE_SYSTEM,
    GPS_REFERENCE,
    "duration",
    REPLAY_OVERLAY,
    "gravity",
    statics::WIND,
    "vehicle",
    "differential_wheels",
    "ground",
    "box",
    "ramp",
    "cone",
    "body",
    "road",
    "junction",
];

/// Webots' `WorldInfo.gpsCoordinateSystem`: `"local"` or `"WGS84"`.
const GPS_COORDINATE_SYSTEM: &str = "gpsCoordinateSystem";
/// Webots' `WorldInfo.gpsReference` (m in local mode; latitude °, longitude °, altitude m in
/// WGS84 mode).
const GPS_REFERENCE: &str = "gpsReference";

/// The key that draws the radars' targets in `replay.glb` ([`crate::replay::overlay`]).
const REPLAY_OVERLAY: &str = "replayOverlay";

/// A loaded world: everything needed to build a [`World`](crate::World) and put its cars and
/// robot in it.
#[derive(Debug, Clone, PartialEq)]
pub struct WorldDescription {
    /// Where it came from: the path as given, or [`DEFAULT_WORLD_NAME`] (with the model name
    /// when one was asked for).
    pub source: String,
    /// Time step, gravity, ground, obstacles and dynamic boxes (validated).
    pub config: WorldConfig,
    /// Simulated time after which stepping reports the end of the simulation (s, > 0 and at
    /// most [`MAX_DURATION`](crate::MAX_DURATION)), if set.
    pub duration: Option<f64>,
    /// The cars (`[vehicle]`, or every `[[vehicle]]` in file order), each with a unique name.
    pub cars: Vec<CarDescription>,
    /// The DifferentialWheels robot (`[differential_wheels]`), if any.
    pub robot: Option<RobotDescription>,
    /// The colours, recognition colours and models the file gives its boxes, ramps, dynamic
    /// boxes, cars and robot (`color`, `recognitionColors`, `model`).
    pub appearances: Appearances,
    /// Values that were accepted with a warning (e.g. an invalid car field replaced by its
    /// default, as Webots does), in file order.
    pub warnings: Vec<WorldWarning>,
    /// `replayOverlay` (default false): `replay.glb` shows the radars' targets
    /// ([`crate::replay::overlay`]); a project extension.
    pub replay_overlay: bool,
    /// `gpsCoordinateSystem` and `gpsReference` (Webots' `WorldInfo` fields; default local,
    /// `[0, 0, 0]`): the frame the GPS devices report in.
    pub gps: GpsFrame,
}

impl WorldDescription {
    /// The first car, if the world has one.
    pub fn car(&self) -> Option<&CarDescription> {
        self.cars.first()
    }

    /// The DifferentialWheels robot, if the world has one.
    pub fn robot(&self) -> Option<&RobotDescription> {
        self.robot.as_ref()
    }

    /// The names of the cars, then of the robot.
    pub fn vehicle_names(&self) -> Vec<&str> {
        self.cars
            .iter()
            .map(|c| c.name.as_str())
            .chain(self.robot.iter().map(|r| r.name.as_str()))
            .collect()
    }

    /// What drives in this world, for messages: the car model's Webots name or
    /// `DifferentialWheels` for a single vehicle, else `"3 vehicles (a, b, c)"` by name.
    pub fn vehicles_label(&self) -> String {
        let single = match (self.cars.as_slice(), &self.robot) {
            ([car], None) => Some(car.model.webots_name()),
            ([], Some(_)) => Some(robot::ROBOT_NAME),
            _ => None,
        };
        single.map_or_else(
            || {
                let names = self.vehicle_names();
                format!("{} vehicles ({})", names.len(), names.join(", "))
            },
            str::to_string,
        )
    }

    /// True when a car or the robot has a programme.
    pub fn has_programme(&self) -> bool {
        self.cars.iter().any(CarDescription::has_programme)
            || self.robot.as_ref().is_some_and(|r| !r.programme.is_empty())
    }
}

/// The built-in default world (a BmwX5 on flat ground, `basicTimeStep` 10 ms).
pub fn default_world() -> WorldDescription {
    with_model(Model::BmwX5)
}

/// The default world with the car `model` instead of the BmwX5.
pub fn with_model(model: Model) -> WorldDescription {
    let source = if model == Model::BmwX5 {
        DEFAULT_WORLD_NAME.to_string()
    } else {
        format!("<default world with {}>", model.webots_name())
    };
    // Every shipped model builds (a test says so); were one not to, the world would hold no
    // car and say why.
    let (cars, messages) = match CarDescription::of_model(model) {
        Ok((car, messages)) => (vec![car], messages),
        Err(e) => (Vec::new(), vec![format!("this car cannot be built: {e}")]),
    };
    let warnings = messages
        .into_iter()
        .map(|message| WorldWarning {
            file: source.clone(),
            location: None,
            key: None,
            message,
        })
        .collect();
    WorldDescription {
        source,
        config: WorldConfig::default(),
        duration: None,
        cars,
        robot: None,
        appearances: Appearances::default(),
        warnings,
        replay_overlay: false,
        gps: GpsFrame::default(),
    }
}

/// Loads a world from `spec`: the path of a world file, the Webots name of a shipped car
/// model (e.g. `ToyotaPrius`: the default world with that car), or the name of a shipped world
/// ([`shipped`], e.g. `two-cars` or `two-cars.toml`). An existing file wins over a model or
/// shipped world of the same name; an empty `spec` is the default world.
///
/// This is what `vehicle-sim --world` and the C API's `VEHICLE_WORLD` accept.
///
/// # Errors
/// A [`WorldFileError`] naming the file, line, column and key: unreadable file (or one longer
/// than [`MAX_FILE_BYTES`]), invalid TOML,
/// unknown key (with the closest valid names), wrong type, unknown model, invalid value, or a
/// `spec` that is neither a file, a model nor a shipped world.
pub fn load(spec: &str) -> Result<WorldDescription, WorldFileError> {
    match resolve(spec)? {
        Resolved::Model(model) => Ok(with_model(model)),
        Resolved::Text { source, text } => parse_str(&source, &text),
    }
}

/// Loads a world as [`load`] does, but a world file's errors are every one of them, in file
/// order, with their lines ([`diagnostics`]): what `vehicle-sim --world` and the C API print.
///
/// # Errors
/// As [`load`], with every error of the file.
pub fn load_all(spec: &str) -> Result<WorldDescription, WorldFileErrors> {
    match resolve(spec)? {
        Resolved::Model(model) => Ok(with_model(model)),
        Resolved::Text { source, text } => parse_all(&source, &text),
    }
}

/// What a `--world` spec names: a built-in world, or the text of a file to read.
enum Resolved {
    /// The default world with a model (the BmwX5: the default world).
    Model(Model),
    /// A world file's text (from disk, or a shipped world's) and the name that messages
    /// give it.
    Text { source: String, text: String },
}

/// Resolves `spec` as [`load`] describes, reading the file it names.
fn resolve(spec: &str) -> Result<Resolved, WorldFileError> {
    if spec.trim().is_empty() {
        return Ok(Resolved::Model(Model::BmwX5));
    }
    let path = Path::new(spec);
    if !path.exists() {
        if let Some(model) = Model::from_name(spec) {
            return Ok(Resolved::Model(model));
        }
        if let Some(world) = shipped::world(spec) {
            return Ok(Resolved::Text {
                source: world.source(),
                text: world.text.to_string(),
            });
        }
        let looks_like_path = spec.contains(['/', '\\']);
        if !looks_like_path {
            let candidates = error::model_names().chain(shipped::names());
            return Err(WorldFileError {
                file: spec.to_string(),
                location: None,
                key: None,
                kind: WorldFileErrorKind::NeitherFileNorModel {
                    name: spec.to_string(),
                    suggestions: closest(spec, candidates),
                },
            });
        }
    }
    let source = path.display().to_string();
    let text = read_text(path).map_err(|m| WorldFileError {
        file: source.clone(),
        location: None,
        key: None,
        kind: WorldFileErrorKind::Io(m),
    })?;
    Ok(Resolved::Text { source, text })
}

/// Largest world or sweep file read (bytes): 16 MiB. The shipped worlds and sweeps are a few
/// kB, and a world of ten thousand obstacles is about 1 MiB; the bound keeps a path to a
/// device or an endless stream (`--world /dev/zero`) from being read until memory runs out.
pub const MAX_FILE_BYTES: u64 = 16 << 20;

/// The text of the file at `path`, at most [`MAX_FILE_BYTES`] long, or what is wrong (the
/// system's message, or the file's size).
pub(crate) fn read_text(path: &Path) -> Result<String, String> {
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let mut bytes = Vec::new();
    // One byte past the bound tells a file of exactly the bound from a longer one.
    file.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| e.to_string())?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(format!(
            "it is longer than {} MiB, the most a world or sweep file may hold",
            MAX_FILE_BYTES >> 20
        ));
    }
    String::from_utf8(bytes).map_err(|_| "stream did not contain valid UTF-8".to_string())
}

/// Loads the world file at `path` (at most [`MAX_FILE_BYTES`] long).
///
/// # Errors
/// As [`load`].
pub fn load_file(path: &Path) -> Result<WorldDescription, WorldFileError> {
    let name = path.display().to_string();
    let text = read_text(path).map_err(|m| WorldFileError {
        file: name.clone(),
        location: None,
        key: None,
        kind: WorldFileErrorKind::Io(m),
    })?;
    parse_str(&name, &text)
}

/// Parses world-file text; `file` names it in messages.
///
/// # Errors
/// As [`load`], except for reading the file.
pub fn parse_str(file: &str, text: &str) -> Result<WorldDescription, WorldFileError> {
    parse_with(file, text, Vec::new())
}

/// Parses world-file text with `overrides` set in its document first (each value replacing
/// what the text has at its key, the tables on the way created), then read as any world file:
/// an invalid value gets the error (or warning) of that key. A sweep makes each case's world
/// this way. An error that the text does not locate (a new key) has no location.
///
/// # Errors
/// As [`parse_str`]; an override whose path leads through something that is not a table (or
/// past the file's `[[…]]` tables) is a [`WorldFileErrorKind::Structure`] error at its key.
pub(crate) fn parse_with(
    file: &str,
    text: &str,
    overrides: Vec<(&KeyPath, DeValue<'_>)>,
) -> Result<WorldDescription, WorldFileError> {
    let src = Source { file, text };
    let mut doc = DeTable::parse(text).map_err(|e| {
        src.error(
            e.span(),
            None,
            WorldFileErrorKind::Syntax(e.message().to_string()),
        )
    })?;
    for (path, value) in overrides {
        overrides::set(doc.get_mut(), path, value).map_err(|m| {
            src.error(
                None,
                Some(path.to_string()),
                WorldFileErrorKind::Structure(m),
            )
        })?;
    }
    let root = Section::root(src, doc.get_ref());
    root.check_keys(&ROOT_KEYS)?;
    let mut config = statics::read_world(&root)?;
    let mut warnings = Vec::new();
    config.roads = roads::read_roads(&root, file, &mut warnings)?;
    let duration = match root.number("duration")? {
        Some(d) if !is_duration(d) => {
            return Err(root.error(
                "duration",
                WorldFileErrorKind::InvalidValue(format!(
                    "{} s: must be {DURATION_RULE}",
                    Compact(d)
                )),
            ));
        }
        d => d,
    };
    let car_sections = match root.value("vehicle") {
        Some(DeValue::Array(_)) => root.tables("vehicle")?,
        _ => root.table("vehicle")?.into_iter().collect(),
    };
    let mut cars = Vec::with_capacity(car_sections.len());
    for c in &car_sections {
        cars.push(vehicle::read_vehicle(c, &config.roads, &mut warnings)?);
    }
    let robot_section = root.table("differential_wheels")?;
    let robot = robot_section.as_ref().map(robot::read_robot).transpose()?;
    let appearances = looks::read_looks(&root, &car_sections, robot_section.as_ref())?;
    if cars.is_empty() && robot.is_none() {
        return Err(src.error(
            None,
            None,
            WorldFileErrorKind::Structure(
                "the world has no [vehicle], [[vehicle]] or [differential_wheels] section"
                    .to_string(),
            ),
        ));
    }
    name_cars(&mut cars);
    let sections = car_sections.iter().chain(robot_section.as_ref());
    let names = cars
        .iter()
        .map(|c| c.name.as_str())
        .chain(robot.iter().map(|r| r.name.as_str()));
    let mut seen: Vec<&str> = Vec::new();
    for (name, section) in names.zip(sections) {
        if seen.contains(&name) {
            return Err(section.error(
                vehicle::NAME,
                WorldFileErrorKind::InvalidValue(format!(
                    "\"{name}\": another vehicle of the world has this name"
                )),
            ));
        }
        seen.push(name);
    }
    Ok(WorldDescription {
        source: file.to_string(),
        config,
        duration,
        cars,
        robot,
        appearances,
        warnings,
        replay_overlay: root.boolean(REPLAY_OVERLAY)?.unwrap_or(false),
        gps: read_gps_frame(&root)?,
    })
}

/// `gpsCoordinateSystem` and `gpsReference`, checked.
fn read_gps_frame(root: &Section<'_, '_>) -> Result<GpsFrame, WorldFileError> {
    let systems = [GpsCoordinateSystem::Local, GpsCoordinateSystem::Wgs84];
    let system = match root.string(GPS_COORDINATE_SYSTEM)? {
        None => GpsCoordinateSystem::Local,
        Some(name) => systems
            .into_iter()
            .find(|s| s.webots_name() == name)
            .ok_or_else(|| {
                let names = systems.map(GpsCoordinateSystem::webots_name);
                root.unknown_name(
                    GPS_COORDINATE_SYSTEM,
                    NameSet::GpsCoordinateSystem,
                    name,
                    &names,
                )
            })?,
    };
    let frame = GpsFrame {
        system,
        reference: root.array::<3>(GPS_REFERENCE)?.unwrap_or([0.0; 3]),
    };
    frame.validate().map_err(|e| devices::invalid(root, &e))?;
    Ok(frame)
}

/// Gives every car without a `name` its model's name, numbered `-1`, `-2`… (in file order)
/// when several unnamed cars share a model.
fn name_cars(cars: &mut [CarDescription]) {
    let models: Vec<(Model, bool)> = cars.iter().map(|c| (c.model, c.name.is_empty())).collect();
    let mut counts: Vec<(Model, usize)> = Vec::new();
    for car in cars.iter_mut().filter(|c| c.name.is_empty()) {
        let shared = models
            .iter()
            .filter(|&&(m, unnamed)| unnamed && m == car.model)
            .count()
            > 1;
        let base = car.model.webots_name();
        car.name = if shared {
            let n = match counts.iter_mut().find(|(m, _)| *m == car.model) {
                Some((_, n)) => {
                    *n += 1;
                    *n
                }
                None => {
                    counts.push((car.model, 1));
                    1
                }
            };
            format!("{base}-{n}")
        } else {
            base.to_string()
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_default_world_matches_default_world() {
        let parsed = parse_str(DEFAULT_WORLD_NAME, DEFAULT_WORLD).unwrap();
        assert_eq!(parsed, default_world());
        for model in Model::ALL {
            let expected = with_model(model);
            let parsed = parse_str(&expected.source, &model_world_text(model)).unwrap();
            assert_eq!(parsed, expected, "{model:?}");
        }
    }

    #[test]
    fn overrides_are_read_as_the_file_would_be() {
        let path = KeyPath::parse("ground.friction").unwrap();
        fn value(t: &str) -> DeValue<'_> {
            DeValue::parse(t).unwrap().into_inner()
        }
        let w = parse_with("w", DEFAULT_WORLD, vec![(&path, value("0.5"))]).unwrap();
        assert_eq!(w.config.ground_friction, 0.5);
        let e = parse_with("w", DEFAULT_WORLD, vec![(&path, value("-0.5"))]).unwrap_err();
        assert_eq!(
            e.message().to_string(),
            "invalid 'ground.friction': -0.5: must be finite and >= 0"
        );
        let path = KeyPath::parse("vehicle.model.name").unwrap();
        let e = parse_with("w", DEFAULT_WORLD, vec![(&path, value("1"))]).unwrap_err();
        assert_eq!(e.key.as_deref(), Some("vehicle.model.name"));
    }

    #[test]
    fn every_shipped_model_builds_its_default_world() {
        for model in Model::ALL {
            let world = with_model(model);
            assert_eq!(world.cars.len(), 1, "{model:?}: {:?}", world.warnings);
            assert!(world.warnings.is_empty(), "{model:?}: {:?}", world.warnings);
            let car = &world.cars[0];
            assert!(crate::VehicleSpec::from_car_with(&car.params, &car.tyre).is_ok());
            assert_eq!(car.mounting, crate::Mounting::Cast, "{model:?}");
        }
    }
}
