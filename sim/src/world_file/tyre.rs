//! `[vehicle] tyre`: the tyre a car rolls on. Either a model name (`tyre = "webots"`) or a
//! table `[vehicle.tyre]` with the slip-based tyre's class and coefficients
//! (`[vehicle.tyre.longitudinal]`, `[vehicle.tyre.lateral]`) or Webots' contact slip.

use proto_geom::plausible::Compact;
use toml::de::DeValue;
use vehicle_model::{Direction, Model, TyreClass, TyreField, TyreParams, WebotsContact};

use crate::vehicle::TyreChoice;

use super::error::{NameSet, WorldFileError, WorldFileErrorKind, WorldWarning, closest};
use super::read::{Section, as_f64, describe};
use super::tyre_file;

/// The key in `[vehicle]`.
const KEY: &str = "tyre";
/// The slip-based tyre's name in world files.
const MAGIC_FORMULA: &str = "magic-formula";
/// Webots' contact's name in world files.
const WEBOTS: &str = "webots";
/// Every tyre model name.
const MODEL_NAMES: [&str; 2] = [MAGIC_FORMULA, WEBOTS];
/// The keys of `[vehicle.tyre]` other than the tyre-wide coefficients.
const TABLE_KEYS: [&str; 6] = [
    "model",
    tyre_file::FILE,
    "class",
    "force_dependent_slip",
    "longitudinal",
    "lateral",
];
/// The key of Webots' `ContactProperties.forceDependentSlip`.
const FORCE_DEPENDENT_SLIP: &str = "force_dependent_slip";
/// Radius of the tyre the coefficients are checked on (m): the ranges do not depend on the
/// size, and every class's defaults at this radius are in range.
const PROBE_RADIUS: f64 = 1.0;
/// Load of the tyre the coefficients are checked on (N), a passenger car's wheel.
const PROBE_LOAD: f64 = 4000.0;

/// Reads `tyre` of `[vehicle]` (a string or a table) for a car of `model`, appending the
/// warnings of a tyre property file to `warnings`.
pub(crate) fn read_tyre(
    vehicle: &Section<'_, '_>,
    model: Model,
    warnings: &mut Vec<WorldWarning>,
) -> Result<TyreChoice, WorldFileError> {
    match vehicle.value(KEY) {
        Some(DeValue::String(name)) => {
            return Ok(if is_webots(vehicle, KEY, name)? {
                TyreChoice::Webots(WebotsContact::default())
            } else {
                TyreChoice::of_model(model)
            });
        }
        Some(v) if !matches!(v, DeValue::Table(_)) => {
            return Err(vehicle.error(
                KEY,
                WorldFileErrorKind::WrongType {
                    expected: format!(
                        "\"{MAGIC_FORMULA}\", \"{WEBOTS}\" or a table [vehicle.{KEY}]"
                    ),
                    found: describe(v),
                },
            ));
        }
        _ => {}
    }
    let Some(t) = vehicle.table(KEY)? else {
        return Ok(TyreChoice::of_model(model));
    };
    check_tyre_keys(&t)?;
    let webots = match t.string("model")? {
        Some(name) => is_webots(&t, "model", name)?,
        None => false,
    };
    if webots {
        read_webots(&t)
    } else {
        read_magic_formula(&t, model, warnings)
    }
}

/// True for `"webots"`, false for `"magic-formula"`; an error at `key` of `s` for any other
/// name.
fn is_webots(s: &Section<'_, '_>, key: &str, name: &str) -> Result<bool, WorldFileError> {
    match name {
        WEBOTS => Ok(true),
        MAGIC_FORMULA => Ok(false),
        _ => Err(s.unknown_name(key, NameSet::TyreModel, name, &MODEL_NAMES)),
    }
}

/// Fails on the first key of `[vehicle.tyre]` it does not have; a curve coefficient there is
/// told where it belongs.
fn check_tyre_keys(t: &Section<'_, '_>) -> Result<(), WorldFileError> {
    let allowed = || TABLE_KEYS.into_iter().chain(TyreField::TYRE_NAMES);
    for (key, _, key_span, _) in t.entries() {
        if allowed().any(|k| k == key) {
            continue;
        }
        let kind = if TyreField::CURVE_NAMES.contains(&key) {
            WorldFileErrorKind::Structure(format!(
                "'{}' is a curve coefficient: set it in [{}.longitudinal] or [{}.lateral]",
                t.key_path(key),
                t.path(),
                t.path(),
            ))
        } else {
            WorldFileErrorKind::UnknownKey {
                suggestions: closest(key, allowed()),
            }
        };
        return Err(t.error_at(key, key_span, kind));
    }
    Ok(())
}

/// Reads `[vehicle.tyre]` with `model = "webots"`: only `force_dependent_slip` applies.
fn read_webots(t: &Section<'_, '_>) -> Result<TyreChoice, WorldFileError> {
    for (key, _, key_span, _) in t.entries() {
        if key != "model" && key != FORCE_DEPENDENT_SLIP {
            return Err(t.error_at(
                key,
                key_span,
                WorldFileErrorKind::Structure(format!(
                    "'{}' belongs to the {MAGIC_FORMULA} tyre; it does not apply with \
                     model = \"{WEBOTS}\"",
                    t.key_path(key)
                )),
            ));
        }
    }
    let Some(value) = t.value(FORCE_DEPENDENT_SLIP) else {
        return Ok(TyreChoice::Webots(WebotsContact::default()));
    };
    let numbers = as_f64(value).map(|x| vec![x]).or_else(|| match value {
        DeValue::Array(items) => items.iter().map(|i| as_f64(i.get_ref())).collect(),
        _ => None,
    });
    // One value is both directions, as in Webots' `forceDependentSlip`.
    let force_dependent_slip = match numbers.as_deref() {
        Some(&[x]) => [x, x],
        Some(&[along, across]) => [along, across],
        _ => {
            return Err(t.error(
                FORCE_DEPENDENT_SLIP,
                WorldFileErrorKind::WrongType {
                    expected: "a number or a list of 1 or 2 numbers (m/s per N)".to_string(),
                    found: describe(value),
                },
            ));
        }
    };
    WebotsContact {
        force_dependent_slip,
    }
    .validate()
    .map(TyreChoice::Webots)
    .map_err(|v| {
        t.error(
            FORCE_DEPENDENT_SLIP,
            WorldFileErrorKind::InvalidValue(format!(
                "{} m/s per N: must be finite and in [0, 1]",
                Compact(v)
            )),
        )
    })
}

/// Reads `[vehicle.tyre]` for the slip-based tyre: the class, the tyre property file's
/// coefficients (`file`), then the coefficients written in the table, which replace the
/// file's; each checked against its range where it is written, in file order.
fn read_magic_formula(
    t: &Section<'_, '_>,
    model: Model,
    warnings: &mut Vec<WorldWarning>,
) -> Result<TyreChoice, WorldFileError> {
    if t.key_span(FORCE_DEPENDENT_SLIP).is_some() {
        return Err(t.error(
            FORCE_DEPENDENT_SLIP,
            WorldFileErrorKind::Structure(format!(
                "'{}' belongs to the {WEBOTS} tyre (Webots' ContactProperties.forceDependentSlip); \
                 it applies only with model = \"{WEBOTS}\"",
                t.key_path(FORCE_DEPENDENT_SLIP)
            )),
        ));
    }
    let class = match t.string("class")? {
        None => model.tyre_class(),
        Some(name) => TyreClass::ALL
            .into_iter()
            .find(|c| c.name() == name)
            .ok_or_else(|| {
                let names = TyreClass::ALL.map(TyreClass::name);
                t.unknown_name("class", NameSet::TyreClass, name, &names)
            })?,
    };
    let mut probe = class.params(PROBE_RADIUS, PROBE_LOAD);
    let set = tyre_file::read_tyre_file(t, &mut probe, warnings)?;
    let mut overrides = Overrides { probe, set };
    for (key, _, _, _) in t.entries() {
        if let Some(field) = TyreField::from_name(key, None) {
            overrides.read(t, key, field)?;
        }
        for direction in [Direction::Longitudinal, Direction::Lateral] {
            if key == direction.name() {
                read_curve(t, direction, &mut overrides)?;
            }
        }
    }
    Ok(TyreChoice::MagicFormula {
        class,
        overrides: overrides.set,
    })
}

/// The coefficients read so far, and a tyre they are applied to so that each is checked as
/// it is read.
struct Overrides {
    probe: TyreParams<f64>,
    set: Vec<(TyreField, f64)>,
}

impl Overrides {
    /// Reads the number at `key` of `s` as the coefficient `field` and checks its range.
    fn read(
        &mut self,
        s: &Section<'_, '_>,
        key: &str,
        field: TyreField,
    ) -> Result<(), WorldFileError> {
        let Some(value) = s.number(key)? else {
            return Ok(());
        };
        self.probe.set(field, value);
        // The coefficients before this one were in range, so a failure is this one's.
        self.probe.validate().map_err(|e| {
            s.error(
                key,
                WorldFileErrorKind::InvalidValue(format!(
                    "{}: {}",
                    Compact(e.value),
                    e.field.rule()
                )),
            )
        })?;
        self.set.push((field, value));
        Ok(())
    }
}

/// Reads the curve sub-table `[vehicle.tyre.<direction>]`.
fn read_curve(
    t: &Section<'_, '_>,
    direction: Direction,
    overrides: &mut Overrides,
) -> Result<(), WorldFileError> {
    let Some(curve) = t.table(direction.name())? else {
        return Ok(());
    };
    for (key, _, key_span, _) in curve.entries() {
        match TyreField::from_name(key, Some(direction)) {
            Some(field) => overrides.read(&curve, key, field)?,
            None => {
                let kind = if TyreField::TYRE_NAMES.contains(&key) {
                    WorldFileErrorKind::Structure(format!(
                        "'{}' is a tyre-wide coefficient: set it in [{}]",
                        curve.key_path(key),
                        t.path(),
                    ))
                } else {
                    WorldFileErrorKind::UnknownKey {
                        suggestions: closest(key, TyreField::CURVE_NAMES),
                    }
                };
                return Err(curve.error_at(key, key_span, kind));
            }
        }
    }
    Ok(())
}
