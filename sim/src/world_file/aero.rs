//! `[vehicle] aero`: the air on a car's body. `aero = true` gives the model's coefficients
//! ([`Model::aero`]), a table `[vehicle.aero]` the same with any of them overridden, and
//! `aero = false` or no key no air at all (Webots' cars have none).

use proto_geom::plausible::Compact;
use toml::de::DeValue;
use vehicle_model::{Aero, Model};

use super::error::{WorldFileError, WorldFileErrorKind};
use super::read::{Section, describe};

/// The key in `[vehicle]`.
pub(crate) const KEY: &str = "aero";
/// The keys of `[vehicle.aero]`, as [`vehicle_model::AeroError::field`] names them.
const TABLE_KEYS: [&str; 5] = [
    "drag_coefficient",
    "frontal_area",
    "lift_coefficient_front",
    "lift_coefficient_rear",
    "air_density",
];

/// Reads `aero` of `[vehicle]` (a boolean or a table) for a car of `model`.
pub(crate) fn read_aero(
    vehicle: &Section<'_, '_>,
    model: Model,
) -> Result<Option<Aero<f64>>, WorldFileError> {
    match vehicle.value(KEY) {
        None => return Ok(None),
        Some(DeValue::Boolean(on)) => return Ok(on.then(|| model.aero())),
        Some(DeValue::Table(_)) => {}
        Some(v) => {
            return Err(vehicle.error(
                KEY,
                WorldFileErrorKind::WrongType {
                    expected: format!("true, false or a table [vehicle.{KEY}]"),
                    found: describe(v),
                },
            ));
        }
    }
    let Some(t) = vehicle.table(KEY)? else {
        return Ok(None);
    };
    t.check_keys(&TABLE_KEYS)?;
    let mut aero = model.aero::<f64>();
    let fields = [
        &mut aero.drag_coefficient,
        &mut aero.frontal_area,
        &mut aero.lift_coefficient_front,
        &mut aero.lift_coefficient_rear,
        &mut aero.air_density,
    ];
    for (key, field) in TABLE_KEYS.into_iter().zip(fields) {
        if let Some(v) = t.number(key)? {
            *field = v;
        }
    }
    aero.validated().map(Some).map_err(|e| {
        // The key written, or the table itself when a model default is at fault (none is).
        let kind =
            WorldFileErrorKind::InvalidValue(format!("{}: must be {}", Compact(e.value), e.rule));
        if t.key_span(e.field).is_some() {
            t.error(e.field, kind)
        } else {
            vehicle.error(KEY, kind)
        }
    })
}
