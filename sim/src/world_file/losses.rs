//! `[vehicle] losses`: what slows a car's wheels besides the tyres' rolling resistance.
//! `losses = "webots"` (the default) keeps Webots' viscous `wheelsDampingConstant`;
//! `losses = "road-load"` replaces it with the model's road-load set ([`Model::road_load`]: a
//! constant and a viscous drag per wheel, and for the cars the US EPA tested the tyres'
//! rolling resistance from its coast-down coefficients) and, unless `aero` is written, turns
//! the air on; a table `[vehicle.losses]` is `"road-load"` with any of its values overridden.

use proto_geom::plausible::Compact;
use toml::de::DeValue;
use vehicle_model::{Model, RoadLoad};

use super::error::{NameSet, WorldFileError, WorldFileErrorKind};
use super::read::{Section, describe};

/// The key in `[vehicle]`.
pub(crate) const KEY: &str = "losses";
/// The names `losses` takes.
const NAMES: [&str; 2] = ["webots", "road-load"];
/// The keys of `[vehicle.losses]`, as [`vehicle_model::RoadLoadError::field`] names them.
const TABLE_KEYS: [&str; 3] = ["drag_torque", "viscous_drag", "rolling_resistance"];

/// Reads `losses` of `[vehicle]` (a name or a table): `None` for Webots' damping, else the
/// road-load set of `model`.
pub(crate) fn read_losses(
    vehicle: &Section<'_, '_>,
    model: Model,
) -> Result<Option<RoadLoad<f64>>, WorldFileError> {
    match vehicle.value(KEY) {
        None => return Ok(None),
        Some(DeValue::String(name)) => {
            return match name.as_ref() {
                "webots" => Ok(None),
                "road-load" => Ok(Some(model.road_load())),
                other => Err(vehicle.unknown_name(KEY, NameSet::Losses, other, &NAMES)),
            };
        }
        Some(DeValue::Table(_)) => {}
        Some(v) => {
            return Err(vehicle.error(
                KEY,
                WorldFileErrorKind::WrongType {
                    expected: format!("\"webots\", \"road-load\" or a table [vehicle.{KEY}]"),
                    found: describe(v),
                },
            ));
        }
    }
    let Some(t) = vehicle.table(KEY)? else {
        return Ok(None);
    };
    t.check_keys(&TABLE_KEYS)?;
    let mut losses = model.road_load::<f64>();
    let fields = [&mut losses.drag_torque, &mut losses.viscous_drag];
    for (key, field) in TABLE_KEYS.into_iter().zip(fields) {
        if let Some(v) = t.number(key)? {
            *field = v;
        }
    }
    if let Some(v) = t.number(TABLE_KEYS[2])? {
        losses.rolling_resistance = Some(v);
    }
    losses.validated().map(Some).map_err(|e| {
        // The key written, or the table itself when a default is at fault (none is).
        let kind =
            WorldFileErrorKind::InvalidValue(format!("{}: must be {}", Compact(e.value), e.rule));
        if t.key_span(e.field).is_some() {
            t.error(e.field, kind)
        } else {
            vehicle.error(KEY, kind)
        }
    })
}
