//! `[vehicle]`: a car model and overrides of its `Car` / `AckermannVehicle` fields by their
//! Webots names.

use core::ops::Range;

use proto_geom::WheelField;
use proto_geom::plausible::Compact;
use toml::de::DeValue;
use vehicle_model::energy::EnergyParams;
use vehicle_model::{
    Aero, BrakeBalance, CarParams, FieldError, FieldKind, FieldPath, FieldValue, Model,
    ParamWarning, RoadLoad, Wheel, WheelSetting, WheelSlot,
};

use super::cycle_programme::read_cycle;
use super::devices::{DEVICE, read_devices};
use super::energy::WebotsBattery;
use super::error::{
    NameSet, WorldFileError, WorldFileErrorKind, WorldWarning, closest, model_names,
};
use super::lane_programme::read_lane_programme;
use super::programme::{PROGRAMME, read_car_keys, read_car_programme, step_keys};
use super::read::{Section, as_f64, describe};
use super::{aero, energy, losses, transmission, tyre};
use crate::devices::DeviceSpec;
use crate::error::ParamError;
use crate::keyboard::KeyPress;
use crate::lane_following::FollowCommand;
use crate::programme::Programme;
use crate::road::RoadNetwork;
use crate::scenario::CycleCommand;
use crate::vehicle::{Mounting, TyreChoice, VehicleSpec};

/// The key of a vehicle's name in `[vehicle]` and `[differential_wheels]`.
pub(crate) const NAME: &str = "name";

/// The key of the wheel mounting in `[vehicle]`, and its names.
const MOUNTING: &str = "mounting";
const MOUNTINGS: [(&str, Mounting); 2] = [("cast", Mounting::Cast), ("joints", Mounting::Joints)];

/// The key of the brake balance in `[vehicle]`, and its names (a number is a front share).
const BRAKE_BALANCE: &str = "brake_balance";
const BRAKE_BALANCES: [(&str, BrakeBalance<f64>); 2] = [
    ("equal", BrakeBalance::Equal),
    ("proportioned", BrakeBalance::Proportioned),
];

/// The keys of `[vehicle]` that are neither Webots fields nor wheel slots.
const OWN_KEYS: [&str; 17] = [
    "model",
    aero::KEY,
    losses::KEY,
    transmission::KEY,
    energy::ENERGY,
    energy::BATTERY,
    energy::MOTOR,
    "color",
    "recognitionColors",
    "tyre",
    MOUNTING,
    BRAKE_BALANCE,
    NAME,
    PROGRAMME,
    DEVICE,
    SEED,
    RADAR_CROSS_SECTION,
];

/// The key of the car solid's `radarCrossSection` (m²) in `[vehicle]`.
const RADAR_CROSS_SECTION: &str = "radarCrossSection";

/// The key of the seed of the car's device noise in `[vehicle]`.
const SEED: &str = "seed";

/// A car as a world file describes it: inputs only. [`CarBuilder::from`](crate::CarBuilder)
/// takes all of it to [`Simulation::add_car`](crate::Simulation::add_car), which builds the
/// car (the loader built it once already, so that a car that cannot be built is an error of
/// the file).
#[derive(Debug, Clone, PartialEq)]
pub struct CarDescription {
    /// The model the parameters start from (`model`; the plain `Car` when absent).
    pub model: Model,
    /// The model's parameters with the file's overrides, validated: every invalid value was
    /// replaced by its default and reported in [`WorldDescription::warnings`](
    /// super::WorldDescription::warnings).
    pub params: CarParams<f64>,
    /// The tyres (`tyre`, `[vehicle.tyre]`): by default the slip-based tyre of the model's
    /// class ([`Model::tyre_class`]) without overrides, fitted to each axle's radius and load
    /// when the car is built.
    pub tyre: TyreChoice,
    /// How the wheels hang on the chassis (`mounting`: `"cast"`, the default, or `"joints"`).
    pub mounting: Mounting,
    /// How the brake torque is shared between the axles (`brake_balance`: `"equal"`, Webots'
    /// and the default; `"proportioned"`; or the front axle's share, a number in [0, 1]).
    pub brake_balance: BrakeBalance<f64>,
    /// The car's name in telemetry, plots and metrics (`name`; by default the model's name,
    /// numbered `-1`, `-2`… when several cars share a model).
    pub name: String,
    /// Its timed driver commands (`[[vehicle.programme]]`), empty if none.
    pub programme: Programme,
    /// Its lane follower's commands (`follow_lane`, `lane` … in `[[vehicle.programme]]`),
    /// empty if none.
    pub lanes: Programme<FollowCommand>,
    /// The drive cycle its programme follows (`cycle`, `cycle_file` in
    /// `[[vehicle.programme]]`), if any.
    pub cycle: Option<CycleCommand>,
    /// The keys its programme presses for the controller's keyboard (`key`).
    pub keys: Vec<KeyPress>,
    /// Its sensor devices (`[[vehicle.device]]`), in file order, empty if none.
    pub devices: Vec<DeviceSpec>,
    /// The seed of its devices' noise (`seed`, default 0).
    pub seed: u64,
    /// Its `radarCrossSection` (m², ≥ 0; default 0 as in Webots: radars do not see it).
    pub radar_cross_section: f64,
    /// The air on its body (`aero = true` for the model's coefficients, or `[vehicle.aero]`);
    /// `None` (the default, as in Webots): no air.
    pub aero: Option<Aero<f64>>,
    /// Its wheels' road-load losses (`losses = "road-load"` or `[vehicle.losses]`); `None`
    /// (the default, `losses = "webots"`): Webots' `wheelsDampingConstant` alone.
    pub road_load: Option<RoadLoad<f64>>,
    /// Its energy accounting (`energy = true`: the defaults of its `engineType`,
    /// `EnergyParams::of_engine`, its battery full; `[vehicle.battery]`, `[vehicle.motor]`
    /// and Webots' `battery` field override them); `None` (the default): none.
    pub energy: Option<EnergyParams<f64>>,
    /// Its battery's starting state of charge (dimensionless, in [0, 1]; 1 unless
    /// `[vehicle.battery] state_of_charge` or Webots' `battery` field says otherwise).
    pub state_of_charge: f64,
    /// Webots' Robot `battery` field (`battery = [energy, maxEnergy, chargingRate]`), if
    /// given: the traction battery then powers the controller, which Webots stops when
    /// the energy reaches 0.
    pub webots_battery: Option<WebotsBattery>,
}

impl CarDescription {
    /// True when its programme gives commands: driver commands, the lane follower's or a
    /// drive cycle.
    pub fn has_programme(&self) -> bool {
        !self.programme.is_empty() || !self.lanes.is_empty() || self.cycle.is_some()
    }

    /// The validated parameters of `model` on the tyres of its class, and the messages of
    /// its validation (none for the shipped models).
    ///
    /// # Errors
    /// The [`ParamError`] of a car that cannot be built (no shipped model).
    pub fn of_model(model: Model) -> Result<(Self, Vec<String>), ParamError> {
        let (params, report) = model.params::<f64>().validated();
        let messages = report.iter().map(message).collect();
        let tyre = TyreChoice::of_model(model);
        VehicleSpec::from_car_with(&params, &tyre)?;
        Ok((
            CarDescription {
                model,
                params,
                tyre,
                mounting: Mounting::default(),
                brake_balance: BrakeBalance::Equal,
                name: model.webots_name().to_string(),
                programme: Programme::default(),
                lanes: Programme::default(),
                cycle: None,
                keys: Vec::new(),
                devices: Vec::new(),
                seed: 0,
                radar_cross_section: 0.0,
                aero: None,
                road_load: None,
                energy: None,
                state_of_charge: 1.0,
                webots_battery: None,
            },
            messages,
        ))
    }
}

/// The text of a validation warning without Webots' `Warning: ` prefix (the caller labels it).
fn message(w: &ParamWarning) -> String {
    let text = w.to_string();
    text.strip_prefix("Warning: ").unwrap_or(&text).to_string()
}

/// Every key of `[vehicle]` that is not a wheel slot.
fn top_keys() -> impl Iterator<Item = &'static str> {
    OWN_KEYS.into_iter().chain(CarParams::<f64>::FIELD_NAMES)
}

/// Reads `[vehicle]`, appending the validation warnings to `warnings`.
pub(crate) fn read_vehicle(
    s: &Section<'_, '_>,
    roads: &RoadNetwork,
    warnings: &mut Vec<WorldWarning>,
) -> Result<CarDescription, WorldFileError> {
    let model = match s.string("model")? {
        None => Model::Car,
        Some(name) => Model::from_name(name).ok_or_else(|| {
            s.error(
                "model",
                WorldFileErrorKind::UnknownModel {
                    name: name.to_string(),
                    suggestions: closest(name, model_names()),
                },
            )
        })?,
    };
    let tyre = tyre::read_tyre(s, model, warnings)?;
    let road_load = losses::read_losses(s, model)?;
    // The road-load set is the realistic car, air included, unless `aero` says otherwise.
    let aero = match aero::read_aero(s, model)? {
        None if road_load.is_some() && s.value(aero::KEY).is_none() => Some(model.aero()),
        other => other,
    };
    let mounting = match s.string(MOUNTING)? {
        None => Mounting::default(),
        Some(name) => MOUNTINGS
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(_, m)| m)
            .ok_or_else(|| {
                let names = MOUNTINGS.map(|(n, _)| n);
                s.unknown_name(MOUNTING, NameSet::Mounting, name, &names)
            })?,
    };
    let mut params = model.params::<f64>();
    if let Some(ratios) = transmission::read_transmission(s, model)? {
        params.gear_ratios = ratios;
    }
    let brake_balance = read_brake_balance(s)?;
    for (key, value, key_span, _) in s.entries() {
        if OWN_KEYS.contains(&key) {
            continue;
        }
        if let Some(slot) = WheelSlot::from_webots_name(key) {
            if !matches!(value, DeValue::Table(_)) {
                return Err(s.error_at(
                    key,
                    key_span,
                    WorldFileErrorKind::WrongType {
                        expected: "a table of VehicleWheel fields".to_string(),
                        found: describe(value),
                    },
                ));
            }
            read_wheel_slot(s, slot, &mut params)?;
            continue;
        }
        let Some(path) = FieldPath::parse(key) else {
            let candidates: Vec<&str> = top_keys()
                .chain(CarParams::<f64>::WHEEL_SLOT_NAMES)
                .collect();
            return Err(s.error_at(
                key,
                key_span,
                WorldFileErrorKind::UnknownKey {
                    suggestions: closest(key, candidates),
                },
            ));
        };
        set(s, key, path, value, key_span, &mut params)?;
    }
    let report = params.validate();
    for w in &report {
        let (key, span) = match *w {
            ParamWarning::Wheel { slot, warning } => locate_wheel_field(s, slot, warning.field),
            _ => match w.field() {
                Some(field) => {
                    let name = field.webots_name();
                    (Some(s.key_path(name)), s.key_span(name))
                }
                None => (None, None),
            },
        };
        // Webots accepts the invalid values it has a fallback for (so do we, with its
        // warning); an implausible one is a mistake in the file, refused before it runs.
        if w.is_implausible() {
            let refusal = w.refusal().to_string();
            return Err(s
                .src
                .error(span, key, WorldFileErrorKind::InvalidValue(refusal)));
        }
        warnings.push(s.src.warning(span, key, message(w)));
    }
    if report.dropped() > 0 {
        warnings.push(s.src.warning(
            s.span(),
            None,
            format!(
                "{} more invalid vehicle fields were replaced by their defaults",
                report.dropped()
            ),
        ));
    }
    // Fields that are each plausible may still make a car that cannot be built (a 33 m tyre
    // of the default density weighs more than 1e6 kg): a world that loads must build.
    let mut spec = VehicleSpec::from_car_with(&params, &tyre).map_err(|e| {
        s.src.error(
            s.span(),
            Some("vehicle".to_string()),
            WorldFileErrorKind::InvalidValue(format!("this car cannot be built: {e}")),
        )
    })?;
    // A wheel the mounting cannot build (a joints wheel wider than its diameter) is blamed
    // on the key that made it so: its tireRadius, else its thickness, else the mounting.
    spec.mounting = mounting;
    spec.check_mounting().map_err(|(wheel, e)| {
        let (key, span) = [WheelField::TireRadius, WheelField::Thickness]
            .into_iter()
            .map(|field| locate_wheel_field(s, wheel, field))
            .find(|(_, span)| span.is_some())
            .unwrap_or_else(|| (Some(s.key_path(MOUNTING)), s.key_span(MOUNTING)));
        s.src.error(
            span,
            key,
            WorldFileErrorKind::InvalidValue(format!(
                "tireRadius {} m with thickness {} m: tireRadius must be {}",
                Compact(e.value),
                Compact(spec.wheels[wheel].width),
                e.rule
            )),
        )
    })?;
    let name = s.string(NAME)?.unwrap_or("").to_string();
    let gears = i32::try_from(params.gear_ratios.len().saturating_sub(1)).unwrap_or(i32::MAX);
    let programme = read_car_programme(s, gears)?;
    let lanes = read_lane_programme(s, roads)?;
    let cycle = read_cycle(s, &step_keys())?;
    let keys = read_car_keys(s)?;
    let devices = read_devices(s, model)?;
    let seed = s.unsigned(SEED)?.unwrap_or(0);
    let energy = energy::read_energy(s, model, &params.engine, road_load.is_some())?;
    let radar_cross_section = s.number(RADAR_CROSS_SECTION)?.unwrap_or(0.0);
    ParamError::non_negative(RADAR_CROSS_SECTION, radar_cross_section).map_err(|e| {
        s.error(
            RADAR_CROSS_SECTION,
            WorldFileErrorKind::InvalidValue(format!("{}: must be {}", Compact(e.value), e.rule)),
        )
    })?;
    Ok(CarDescription {
        model,
        params,
        tyre,
        mounting,
        brake_balance,
        name,
        programme,
        lanes,
        cycle,
        keys,
        devices,
        seed,
        radar_cross_section,
        aero,
        road_load,
        energy: energy.map(|e| e.params),
        state_of_charge: energy.map_or(1.0, |e| e.soc),
        webots_battery: energy.and_then(|e| e.webots),
    })
}

/// Reads `brake_balance`: a name of [`BRAKE_BALANCES`] or a front share in [0, 1].
fn read_brake_balance(s: &Section<'_, '_>) -> Result<BrakeBalance<f64>, WorldFileError> {
    let Some(value) = s.value(BRAKE_BALANCE) else {
        return Ok(BrakeBalance::Equal);
    };
    if let DeValue::String(name) = value {
        return BRAKE_BALANCES
            .iter()
            .find(|(n, _)| *n == name.as_ref() as &str)
            .map(|&(_, b)| b)
            .ok_or_else(|| {
                let names = BRAKE_BALANCES.map(|(n, _)| n);
                s.unknown_name(BRAKE_BALANCE, NameSet::BrakeBalance, name, &names)
            });
    }
    let Some(share) = as_f64(value) else {
        return Err(s.error(
            BRAKE_BALANCE,
            WorldFileErrorKind::WrongType {
                expected: "\"equal\", \"proportioned\" or a front share in [0, 1]".to_string(),
                found: describe(value),
            },
        ));
    };
    if (0.0..=1.0).contains(&share) {
        Ok(BrakeBalance::FrontShare(share))
    } else {
        Err(s.error(
            BRAKE_BALANCE,
            WorldFileErrorKind::InvalidValue(format!(
                "the front axle's share of the brake torque must be in [0, 1], not {}",
                Compact(share)
            )),
        ))
    }
}

/// Reads the `VehicleWheel` fields of the sub-table `[vehicle.<slot>]`.
fn read_wheel_slot(
    s: &Section<'_, '_>,
    slot: WheelSlot,
    params: &mut CarParams<f64>,
) -> Result<(), WorldFileError> {
    let Some(t) = s.table(slot.webots_name())? else {
        return Ok(());
    };
    for (field, value, key_span, _) in t.entries() {
        let Some(setting) = WheelSetting::from_webots_name(field) else {
            let names = CarParams::<f64>::WHEEL_FIELD_NAMES;
            return Err(t.error_at(
                field,
                key_span,
                WorldFileErrorKind::UnknownKey {
                    suggestions: closest(field, names),
                },
            ));
        };
        set(
            &t,
            field,
            FieldPath::Wheel(slot, setting),
            value,
            key_span,
            params,
        )?;
    }
    Ok(())
}

/// Sets the field at `path` from the TOML `value` found at `key` of `s`.
fn set(
    s: &Section<'_, '_>,
    key: &str,
    path: FieldPath,
    value: &DeValue<'_>,
    key_span: Range<usize>,
    params: &mut CarParams<f64>,
) -> Result<(), WorldFileError> {
    let kind = path.kind();
    let wrong = |expected: String| {
        s.error_at(
            key,
            key_span.clone(),
            WorldFileErrorKind::WrongType {
                expected,
                found: describe(value),
            },
        )
    };
    let numbers: Vec<f64>;
    let field_value = match (kind, value) {
        (FieldKind::Number, v) => {
            FieldValue::Number(as_f64(v).ok_or_else(|| wrong(kind.to_string()))?)
        }
        (FieldKind::Numbers { .. }, DeValue::Array(items)) => {
            let mut values = Vec::with_capacity(items.len());
            for (i, item) in items.iter().enumerate() {
                let Some(v) = as_f64(item.get_ref()) else {
                    // Name the element that is not a number, not the list's length.
                    return Err(s.error_at(
                        key,
                        key_span.clone(),
                        WorldFileErrorKind::WrongType {
                            expected: format!("a number at element {}", i + 1),
                            found: describe(item.get_ref()),
                        },
                    ));
                };
                values.push(v);
            }
            numbers = values;
            FieldValue::Numbers(&numbers)
        }
        (FieldKind::Text, DeValue::String(text)) => FieldValue::Text(text.as_ref()),
        _ => return Err(wrong(kind.to_string())),
    };
    params.set(path, field_value).map_err(|e| match e {
        FieldError::WrongKind { expected, .. } | FieldError::WrongLength { expected, .. } => {
            wrong(expected.to_string())
        }
        FieldError::InvalidText { rule, .. } => s.error_at(
            key,
            key_span.clone(),
            WorldFileErrorKind::InvalidValue(format!("{} {rule}", describe_value(value))),
        ),
        FieldError::NotAnInteger { value, .. } => s.error_at(
            key,
            key_span.clone(),
            WorldFileErrorKind::InvalidValue(format!("{}: must be an integer", Compact(value))),
        ),
        _ => s.error_at(
            key,
            key_span.clone(),
            WorldFileErrorKind::UnknownKey {
                suggestions: Vec::new(),
            },
        ),
    })
}

/// A short rendering of a string value for messages.
fn describe_value(v: &DeValue<'_>) -> String {
    match v {
        DeValue::String(s) => format!("\"{s}\""),
        other => describe(other),
    }
}

/// The dotted key and span of the entry that set wheel field `field` of `slot` (by any of
/// its [`WheelSetting`] names): `[vehicle.<slot>]` or `slot.field`, then the same for
/// `wheels` (all four); the key `vehicle.<slot>` without a span when the file did not set it.
fn locate_wheel_field(
    s: &Section<'_, '_>,
    slot: Wheel,
    field: WheelField,
) -> (Option<String>, Option<Range<usize>>) {
    let names: Vec<&str> = WheelSetting::ALL
        .into_iter()
        .filter(|setting| setting.field() == field)
        .map(WheelSetting::webots_name)
        .collect();
    for table in [WheelSlot::One(slot), WheelSlot::All].map(WheelSlot::webots_name) {
        if let Ok(Some(t)) = s.table(table) {
            for f in &names {
                if let Some(span) = t.key_span(f) {
                    return (Some(t.key_path(f)), Some(span));
                }
            }
        }
        for f in &names {
            let quoted = format!("{table}.{f}");
            if let Some(span) = s.key_span(&quoted) {
                return (Some(s.key_path(&quoted)), Some(span));
            }
        }
    }
    (Some(s.key_path(WheelSlot::One(slot).webots_name())), None)
}
