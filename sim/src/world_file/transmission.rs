//! `[vehicle] transmission`: which overall gear ratios a car has. `transmission = "webots"`
//! (the default) keeps the model's `gearRatio`; `transmission = "epa"` gives it the
//! transmission of the car the US EPA tested ([`Model::epa_transmission`]: the real gearbox's
//! ratios times the test vehicle's axle ratio), the one the published consumption was
//! measured on. Webots' LincolnMKZ and RangeRoverSportSVR have their gearboxes' ratios
//! without the final drive, on which their engines turn about three times too slowly to
//! follow a drive cycle.

use toml::de::DeValue;
use vehicle_model::{GearRatios, Model};

use super::error::{NameSet, WorldFileError, WorldFileErrorKind};
use super::read::{Section, describe};

/// The key in `[vehicle]`.
pub(crate) const KEY: &str = "transmission";
/// The names `transmission` takes.
const NAMES: [&str; 2] = ["webots", "epa"];
/// Webots' field the EPA transmission replaces.
const GEAR_RATIO: &str = "gearRatio";

/// Reads `transmission` of `[vehicle]`: `None` for the model's own ratios, else the EPA test
/// vehicle's overall ratios. Refused for a model without one, and alongside `gearRatio`
/// (two sets of ratios for one car).
pub(crate) fn read_transmission(
    vehicle: &Section<'_, '_>,
    model: Model,
) -> Result<Option<GearRatios<f64>>, WorldFileError> {
    let name = match vehicle.value(KEY) {
        None => return Ok(None),
        Some(DeValue::String(name)) => name.as_ref(),
        Some(v) => {
            return Err(vehicle.error(
                KEY,
                WorldFileErrorKind::WrongType {
                    expected: "\"webots\" or \"epa\"".to_string(),
                    found: describe(v),
                },
            ));
        }
    };
    match name {
        "webots" => Ok(None),
        "epa" => {
            let Some(transmission) = model.epa_transmission() else {
                let with: Vec<&str> = Model::ALL
                    .into_iter()
                    .filter(|m| m.epa_transmission().is_some())
                    .map(Model::webots_name)
                    .collect();
                return Err(vehicle.error(
                    KEY,
                    WorldFileErrorKind::InvalidValue(format!(
                        "\"epa\": the model {} has no EPA test vehicle transmission (the \
                         models with one: {})",
                        model.webots_name(),
                        with.join(", ")
                    )),
                ));
            };
            if vehicle.value(GEAR_RATIO).is_some() {
                return Err(vehicle.error(
                    GEAR_RATIO,
                    WorldFileErrorKind::Structure(format!(
                        "'{}' and transmission = \"epa\" both give the gear ratios: keep one",
                        vehicle.key_path(GEAR_RATIO)
                    )),
                ));
            }
            Ok(Some(transmission.overall()))
        }
        other => Err(vehicle.unknown_name(KEY, NameSet::Transmission, other, &NAMES)),
    }
}
