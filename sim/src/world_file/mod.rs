//! World files: a TOML description of a world in Webots vocabulary (time step, ground,
//! obstacles, dynamic boxes, one car on its tyres or one DifferentialWheels robot), and the
//! built-in default world.
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

mod bodies;
mod error;
mod read;
mod robot;
mod statics;
mod tyre;
mod vehicle;

use std::path::Path;

use proto_geom::plausible::Compact;
use toml::de::DeTable;
use vehicle_model::Model;

use crate::config::WorldConfig;

pub use error::{Location, NameSet, WorldFileError, WorldFileErrorKind, WorldWarning};
pub use robot::RobotDescription;
pub use vehicle::CarDescription;

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

/// Top-level keys of a world file.
const ROOT_KEYS: [&str; 9] = [
    "basicTimeStep",
    "duration",
    "gravity",
    "vehicle",
    "differential_wheels",
    "ground",
    "box",
    "ramp",
    "body",
];

/// What moves in the world.
#[derive(Debug, Clone, PartialEq)]
pub enum WorldVehicle {
    /// A car (`[vehicle]`), boxed: its parameters are large.
    Car(Box<CarDescription>),
    /// A DifferentialWheels robot (`[differential_wheels]`).
    DifferentialWheels(RobotDescription),
}

/// A loaded world: everything needed to build a [`World`](crate::World) and put the vehicle
/// in it.
#[derive(Debug, Clone, PartialEq)]
pub struct WorldDescription {
    /// Where it came from: the path as given, or [`DEFAULT_WORLD_NAME`] (with the model name
    /// when one was asked for).
    pub source: String,
    /// Time step, gravity, ground, obstacles and dynamic boxes (validated).
    pub config: WorldConfig,
    /// Simulated time after which stepping reports the end of the simulation (s, > 0), if set.
    pub duration: Option<f64>,
    /// The car or robot.
    pub vehicle: WorldVehicle,
    /// Values that were accepted with a warning (e.g. an invalid car field replaced by its
    /// default, as Webots does), in file order.
    pub warnings: Vec<WorldWarning>,
}

impl WorldDescription {
    /// The car, if the world has one.
    pub fn car(&self) -> Option<&CarDescription> {
        match &self.vehicle {
            WorldVehicle::Car(c) => Some(c),
            WorldVehicle::DifferentialWheels(_) => None,
        }
    }

    /// The DifferentialWheels robot, if the world has one.
    pub fn robot(&self) -> Option<&RobotDescription> {
        match &self.vehicle {
            WorldVehicle::DifferentialWheels(r) => Some(r),
            WorldVehicle::Car(_) => None,
        }
    }

    /// A short name of what drives in this world: the car model's Webots name, or
    /// `DifferentialWheels`.
    pub fn vehicle_name(&self) -> &'static str {
        match &self.vehicle {
            WorldVehicle::Car(c) => c.model.webots_name(),
            WorldVehicle::DifferentialWheels(_) => "DifferentialWheels",
        }
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
    let (car, messages) = CarDescription::of_model(model);
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
        vehicle: WorldVehicle::Car(Box::new(car)),
        warnings,
    }
}

/// Loads a world from `spec`: the path of a world file, or the Webots name of a shipped car
/// model (e.g. `ToyotaPrius`: the default world with that car). An existing file wins over a
/// model of the same name; an empty `spec` is the default world.
///
/// This is what `vehicle-sim --world` and the C API's `VEHICLE_WORLD` accept.
///
/// # Errors
/// A [`WorldFileError`] naming the file, line, column and key: unreadable file, invalid TOML,
/// unknown key (with the closest valid names), wrong type, unknown model, invalid value, or a
/// `spec` that is neither a file nor a model name.
pub fn load(spec: &str) -> Result<WorldDescription, WorldFileError> {
    if spec.trim().is_empty() {
        return Ok(default_world());
    }
    let path = Path::new(spec);
    if !path.exists() {
        if let Some(model) = Model::from_name(spec) {
            return Ok(with_model(model));
        }
        let looks_like_path = spec.contains(['/', '\\']) || spec.ends_with(".toml");
        let suggestions = error::closest(spec, vehicle::model_names());
        if !looks_like_path && !suggestions.is_empty() {
            return Err(WorldFileError {
                file: spec.to_string(),
                location: None,
                key: None,
                kind: WorldFileErrorKind::UnknownModel {
                    name: spec.to_string(),
                    suggestions,
                },
            });
        }
    }
    load_file(path)
}

/// Loads the world file at `path`.
///
/// # Errors
/// As [`load`].
pub fn load_file(path: &Path) -> Result<WorldDescription, WorldFileError> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| WorldFileError {
        file: name.clone(),
        location: None,
        key: None,
        kind: WorldFileErrorKind::Io(e.to_string()),
    })?;
    parse_str(&name, &text)
}

/// Parses world-file text; `file` names it in messages.
///
/// # Errors
/// As [`load`], except for reading the file.
pub fn parse_str(file: &str, text: &str) -> Result<WorldDescription, WorldFileError> {
    let src = Source { file, text };
    let doc = DeTable::parse(text).map_err(|e| {
        src.error(
            e.span(),
            None,
            WorldFileErrorKind::Syntax(e.message().to_string()),
        )
    })?;
    let root = Section::root(src, doc.get_ref());
    root.check_keys(&ROOT_KEYS)?;
    let config = statics::read_world(&root)?;
    let duration = match root.number("duration")? {
        Some(d) if !(d.is_finite() && d > 0.0) => {
            return Err(root.error(
                "duration",
                WorldFileErrorKind::InvalidValue(format!(
                    "{} s: must be finite and > 0",
                    Compact(d)
                )),
            ));
        }
        d => d,
    };
    let mut warnings = Vec::new();
    let car = root.table("vehicle")?;
    let robot = root.table("differential_wheels")?;
    let vehicle = match (car, robot) {
        (Some(c), None) => WorldVehicle::Car(Box::new(vehicle::read_vehicle(&c, &mut warnings)?)),
        (None, Some(r)) => WorldVehicle::DifferentialWheels(robot::read_robot(&r)?),
        (Some(_), Some(r)) => {
            return Err(src.error(
                r.span(),
                Some("differential_wheels".to_string()),
                WorldFileErrorKind::Structure(
                    "a world holds either a [vehicle] or a [differential_wheels], not both"
                        .to_string(),
                ),
            ));
        }
        (None, None) => {
            return Err(src.error(
                None,
                None,
                WorldFileErrorKind::Structure(
                    "the world has no [vehicle] and no [differential_wheels] section".to_string(),
                ),
            ));
        }
    };
    Ok(WorldDescription {
        source: file.to_string(),
        config,
        duration,
        vehicle,
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_default_world_matches_default_world() {
        let parsed = parse_str(DEFAULT_WORLD_NAME, DEFAULT_WORLD).unwrap();
        assert_eq!(parsed, default_world());
    }
}
