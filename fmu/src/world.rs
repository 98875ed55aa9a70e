//! The world an instance runs: read from the FMU's resources with the parameters at their
//! keys, built, with the car the FMU drives and the traffic around it.
//!
//! The FMU drives one car: the only car, or of several the one without a programme; the
//! others run their `[[vehicle.programme]]` as they do under a C or Python controller
//! ([`sim::traffic`], the same code). A world with a DifferentialWheels robot is refused.

use std::path::Path;

use sim::traffic::{Traffic, driven_car};
use sim::world_file::{self, KeyPath, WorldDescription};
use sim::{Simulation, VehicleId};
use toml::de::{DeTable, DeValue};

use crate::devices;
use crate::instance::Refused;
use crate::variables::{self, Kind, TYRE_MODEL};

/// A built world.
pub struct Built {
    /// What the world file says, with the parameters set.
    pub description: WorldDescription,
    /// The running world.
    pub simulation: Simulation,
    /// The car the FMU drives.
    pub car: VehicleId,
    /// Its position among the world's cars.
    pub driven: usize,
    /// The other cars, running their programmes.
    pub traffic: Traffic,
}

/// The world of `text` at `path`.
///
/// # Errors
/// What the world reader says, as a sentence.
pub fn parse(path: &Path, text: &str) -> Result<WorldDescription, Refused> {
    world_file::parse_str(&path.display().to_string(), text).map_err(|e| e.to_string())
}

/// The world of `text` at `path` with `parameters` (value reference, value) set at their
/// keys for the car at position `driven` (`vehicle.mass` is `vehicle[k].mass` in a world of
/// several cars).
///
/// # Errors
/// A value the world reader refuses (its error names the key), or a tyre model integer that
/// names no model.
pub fn with_parameters(
    path: &Path,
    text: &str,
    parameters: &[(u32, f64)],
    driven: usize,
) -> Result<WorldDescription, Refused> {
    let several = car_tables(text) > 1;
    let mut settings = Vec::with_capacity(parameters.len());
    for &(reference, value) in parameters {
        let mut name = variables::find(reference, Kind::Real)
            .or_else(|| variables::find(reference, Kind::Integer))
            .map_or("", |v| v.name)
            .to_string();
        // `tyre = "webots"` names the model without a table: the name replaces it there.
        if reference == TYRE_MODEL && tyre_is_a_name(text, driven) {
            name = "vehicle.tyre".to_string();
        }
        if several && let Some(rest) = name.strip_prefix("vehicle.") {
            name = format!("vehicle[{driven}].{rest}");
        }
        let key = KeyPath::parse(&name).map_err(|e| e.to_string())?;
        settings.push((key, variables::setting(reference, value)?));
    }
    world_file::parse_with_settings(&path.display().to_string(), text, &settings)
        .map_err(|e| e.to_string())
}

/// Builds `description`: its driven car with its devices enabled ([`devices::enable`]) and
/// the traffic.
///
/// # Errors
/// A world the FMU cannot drive ([`driven_car`]) or cannot build, as a sentence.
pub fn build(description: WorldDescription) -> Result<Built, Refused> {
    let driven = driven_car(&description)?;
    let (mut simulation, _) =
        Simulation::from_description(&description).map_err(|e| e.to_string())?;
    let ids: Vec<VehicleId> = simulation.car_ids().collect();
    let car = *ids
        .get(driven)
        .ok_or_else(|| "the world has no car".to_string())?;
    let period_ms = simulation.world().config().basic_time_step_ms;
    devices::enable(&mut simulation, car, period_ms)?;
    let traffic = Traffic::new(&description, &ids, driven);
    Ok(Built {
        description,
        simulation,
        car,
        driven,
        traffic,
    })
}

/// The world text's car tables (`[vehicle]`, or each `[[vehicle]]`), read with `f`; `f`
/// gets nothing when the text cannot be read (the reader's error comes later, with its
/// location).
fn with_cars<R>(text: &str, f: impl FnOnce(&[&DeTable<'_>]) -> R) -> R {
    let Ok(doc) = DeTable::parse(text) else {
        return f(&[]);
    };
    let cars: Vec<&DeTable<'_>> = match doc.get_ref().get("vehicle").map(|v| v.get_ref()) {
        Some(DeValue::Table(t)) => vec![t],
        Some(DeValue::Array(cars)) => cars
            .iter()
            .filter_map(|c| match c.get_ref() {
                DeValue::Table(t) => Some(t),
                _ => None,
            })
            .collect(),
        _ => Vec::new(),
    };
    f(&cars)
}

/// The `[vehicle]` / `[[vehicle]]` tables of the world's text.
fn car_tables(text: &str) -> usize {
    with_cars(text, |cars| cars.len())
}

/// True if car `driven` names its tyre model by a string (`tyre = "webots"`) rather than a
/// `[vehicle.tyre]` table.
fn tyre_is_a_name(text: &str, driven: usize) -> bool {
    with_cars(text, |cars| {
        cars.get(driven)
            .and_then(|t| t.get("tyre"))
            .is_some_and(|tyre| matches!(tyre.get_ref(), DeValue::String(_)))
    })
}
