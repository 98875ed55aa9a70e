//! A car's energy accounting in `[vehicle]`: `energy = true` (the defaults of its
//! `engineType`, [`EnergyParams::of_engine`]), the model's tables `[vehicle.battery]` and
//! `[vehicle.motor]` overriding any of those defaults, and Webots' Robot `battery` field
//! `battery = [energy, maxEnergy, chargingRate]` (J, J, W) on the default pack.
//!
//! `battery` is one key in TOML, so it is either Webots' three numbers or the model's table,
//! never both: Webots' field scales the default pack (capacity and current limits alike,
//! its C-rates kept) so that it holds `maxEnergy` J full ([`Battery::energy`] at a state of
//! charge of 1), and charges it to `energy` J; the table sets the pack's own values. Either
//! form, and `[vehicle.motor]`, turns the accounting on; with `energy = false`, or on a
//! combustion car (no machine, no traction battery), they are refused rather than ignored.

use proto_geom::plausible::Compact;
use toml::de::DeValue;
use vehicle_model::energy::{Battery, EnergyParams, MotorLosses, OCV_POINTS, RegenBlend};
use vehicle_model::{EngineParams, EngineType, Model};

use super::error::{WorldFileError, WorldFileErrorKind};
use super::read::{Section, describe};

/// The key of the accounting switch in `[vehicle]` (a boolean).
pub(crate) const ENERGY: &str = "energy";
/// The key of the battery in `[vehicle]`: Webots' field or the model's table.
pub(crate) const BATTERY: &str = "battery";
/// The key of the machine's table in `[vehicle]`.
pub(crate) const MOTOR: &str = "motor";

/// The keys of `[vehicle.battery]` (as [`vehicle_model::energy::BatteryError::field`] names
/// them, and the starting charge).
const BATTERY_KEYS: [&str; 7] = [
    "capacity",
    "ocv",
    "resistance",
    "max_discharge_current",
    "max_charge_current",
    STATE_OF_CHARGE,
    SUSTAIN_BELOW,
];
/// The starting state of charge in `[vehicle.battery]` (dimensionless, in [0, 1]).
const STATE_OF_CHARGE: &str = "state_of_charge";
/// The state of charge below which a power-split hybrid's engine charges the pack, in
/// `[vehicle.battery]` (dimensionless, in [0, 1]; 0: never; `EnergyParams::sustain_below`).
const SUSTAIN_BELOW: &str = "sustain_below";
/// The keys of `[vehicle.motor]`: the loss coefficients and the regenerative limits.
const MOTOR_KEYS: [&str; 7] = [
    "copper",
    "iron",
    "windage",
    "constant",
    "regen_max_share",
    "regen_max_power",
    "regen_fade_speed",
];

/// Webots' Robot `battery` field as a world file gives it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WebotsBattery {
    /// The energy at the start (J, in [0, `max_energy`]).
    pub energy: f64,
    /// The energy held full (J, > 0).
    pub max_energy: f64,
    /// The charging rate (W, ≥ 0): Webots charges only at a `Charger` node, which this
    /// simulator has not, so it is kept and reported but charges nothing (as in a Webots
    /// world without chargers).
    pub charging_rate: f64,
}

/// A car's energy accounting as read from `[vehicle]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct EnergySetting {
    /// The parts.
    pub(crate) params: EnergyParams<f64>,
    /// The battery's starting state of charge (dimensionless, in [0, 1]).
    pub(crate) soc: f64,
    /// Webots' field, if the file gave it.
    pub(crate) webots: Option<WebotsBattery>,
}

/// The energy accounting's defaults for a car of `model` with `engine`
/// ([`EnergyParams::of_engine_displacing`] with the model's real engine displacement,
/// [`Model::engine_displacement`]), without the machine's spin losses on a road-load set
/// (`road_load`), whose drag holds them ([`EnergyParams::with_spin_losses_in_road_load`]).
pub(crate) fn default_params(
    model: Model,
    engine: &EngineParams<f64>,
    road_load: bool,
) -> EnergyParams<f64> {
    let params = EnergyParams::of_engine_displacing(engine, model.engine_displacement());
    if road_load {
        params.with_spin_losses_in_road_load()
    } else {
        params
    }
}

/// Reads `energy`, `battery` and `motor` of `[vehicle]` for a car of `engine`; `None` when
/// the car's energy is not accounted. On a road-load set (`road_load`) the default machine
/// has no spin losses ([`EnergyParams::with_spin_losses_in_road_load`]); a `[vehicle.motor]`
/// table's `iron` and `windage` are taken as given.
pub(crate) fn read_energy(
    s: &Section<'_, '_>,
    model: Model,
    engine: &EngineParams<f64>,
    road_load: bool,
) -> Result<Option<EnergySetting>, WorldFileError> {
    let switch = s.boolean(ENERGY)?;
    let given: Vec<&str> = [BATTERY, MOTOR]
        .into_iter()
        .filter(|k| s.value(k).is_some())
        .collect();
    if let Some(first) = given.first() {
        let refusal = if switch == Some(false) {
            Some(format!(
                "'{}' needs the energy accounting that energy = false turns off",
                s.key_path(first)
            ))
        } else if !engine.engine_type.has_electric() {
            Some(format!(
                "'{}' needs an electric machine: engineType \"{}\" has none",
                s.key_path(first),
                engine.engine_type.webots_name()
            ))
        } else {
            None
        };
        if let Some(text) = refusal {
            return Err(s.error(first, WorldFileErrorKind::Structure(text)));
        }
    } else if switch != Some(true) {
        return Ok(None);
    }
    let mut params = default_params(model, engine, road_load);
    let mut soc = 1.0;
    let mut webots = None;
    match s.value(BATTERY) {
        None => {}
        Some(DeValue::Array(_)) => {
            let w = read_webots_battery(s)?;
            if let Some(pack) = &mut params.battery {
                (*pack, soc) = scaled(pack, &w);
            }
            webots = Some(w);
        }
        Some(DeValue::Table(_)) => {
            if let (Some(t), Some(pack)) = (s.table(BATTERY)?, &mut params.battery) {
                soc = read_battery_table(&t, pack)?;
                if let Some(v) = t.number(SUSTAIN_BELOW)? {
                    if engine.engine_type != EngineType::PowerSplitHybrid {
                        return Err(t.error(
                            SUSTAIN_BELOW,
                            WorldFileErrorKind::Structure(format!(
                                "'{}' needs a power-split hybrid's engine to charge the pack: \
                                 engineType \"{}\" has none",
                                t.key_path(SUSTAIN_BELOW),
                                engine.engine_type.webots_name()
                            )),
                        ));
                    }
                    if !(0.0..=1.0).contains(&v) {
                        return Err(invalid(&t, SUSTAIN_BELOW, v, "within [0, 1] (0: never)"));
                    }
                    params.sustain_below = Some(v);
                }
            }
        }
        Some(v) => {
            return Err(s.error(
                BATTERY,
                WorldFileErrorKind::WrongType {
                    expected: "Webots' [energy, maxEnergy, chargingRate] (J, J, W) or a table \
                               [vehicle.battery]"
                        .to_string(),
                    found: describe(v),
                },
            ));
        }
    }
    if let (Some(t), Some(motor), Some(regen)) =
        (s.table(MOTOR)?, &mut params.motor, &mut params.regen)
    {
        read_motor_table(&t, motor, regen)?;
    }
    Ok(Some(EnergySetting {
        params,
        soc,
        webots,
    }))
}

/// An error at `key` of `t`: `value` must be `rule`.
fn invalid(t: &Section<'_, '_>, key: &str, value: f64, rule: &str) -> WorldFileError {
    t.error(
        key,
        WorldFileErrorKind::InvalidValue(format!("{}: must be {rule}", Compact(value))),
    )
}

/// Reads Webots' `battery = [energy, maxEnergy, chargingRate]`.
fn read_webots_battery(s: &Section<'_, '_>) -> Result<WebotsBattery, WorldFileError> {
    let Some([energy, max_energy, charging_rate]) = s.array::<3>(BATTERY)? else {
        return Err(s.error(
            BATTERY,
            WorldFileErrorKind::Structure("'battery' must be given".to_string()),
        ));
    };
    // A pack of more than 1 TJ (about 280 MWh) is no car's, nor one of less than 1 J (a
    // capacity that small would underflow): unit mistakes.
    if !(1.0..=1e12).contains(&max_energy) {
        return Err(invalid(
            s,
            BATTERY,
            max_energy,
            "a maxEnergy in [1, 1e12] J",
        ));
    }
    if !(energy.is_finite() && (0.0..=max_energy).contains(&energy)) {
        return Err(invalid(
            s,
            BATTERY,
            energy,
            &format!("an energy in [0, maxEnergy = {}] J", Compact(max_energy)),
        ));
    }
    if !(charging_rate.is_finite() && charging_rate >= 0.0) {
        return Err(invalid(
            s,
            BATTERY,
            charging_rate,
            "a chargingRate finite and >= 0 W",
        ));
    }
    Ok(WebotsBattery {
        energy,
        max_energy,
        charging_rate,
    })
}

/// `pack` scaled to hold `w.max_energy` J full, and the state of charge at which it holds
/// `w.energy` J.
fn scaled(pack: &Battery<f64>, w: &WebotsBattery) -> (Battery<f64>, f64) {
    // The stored energy is proportional to the capacity; the current limits keep their
    // C-rates.
    let k = w.max_energy / pack.energy(1.0);
    let pack = Battery {
        capacity: pack.capacity * k,
        max_discharge_current: pack.max_discharge_current * k,
        max_charge_current: pack.max_charge_current * k,
        ..*pack
    };
    (pack, soc_of_energy(&pack, w.energy))
}

/// The state of charge at which `pack` holds `energy` J (in [0, its full energy]): the
/// stored energy increases strictly with the charge (every voltage is > 0), so bisection
/// finds it; 60 halvings reach the resolution of an f64 in [0, 1].
pub(crate) fn soc_of_energy(pack: &Battery<f64>, energy: f64) -> f64 {
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if pack.energy(mid) < energy {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Reads `[vehicle.battery]` over `pack`; returns the starting state of charge.
fn read_battery_table(t: &Section<'_, '_>, pack: &mut Battery<f64>) -> Result<f64, WorldFileError> {
    t.check_keys(&BATTERY_KEYS)?;
    if let Some(ocv) = t.array::<OCV_POINTS>("ocv")? {
        pack.ocv = ocv;
    }
    for (key, field) in [
        ("capacity", &mut pack.capacity),
        ("resistance", &mut pack.resistance),
        ("max_discharge_current", &mut pack.max_discharge_current),
        ("max_charge_current", &mut pack.max_charge_current),
    ] {
        if let Some(v) = t.number(key)? {
            *field = v;
        }
    }
    *pack = pack
        .validated()
        .map_err(|e| invalid(t, e.field, e.value, e.rule))?;
    let soc = t.number(STATE_OF_CHARGE)?.unwrap_or(1.0);
    if !(0.0..=1.0).contains(&soc) {
        return Err(invalid(t, STATE_OF_CHARGE, soc, "within [0, 1]"));
    }
    Ok(soc)
}

/// Reads `[vehicle.motor]` over `motor` and `regen`.
fn read_motor_table(
    t: &Section<'_, '_>,
    motor: &mut MotorLosses<f64>,
    regen: &mut RegenBlend<f64>,
) -> Result<(), WorldFileError> {
    t.check_keys(&MOTOR_KEYS)?;
    for (key, field) in [
        ("copper", &mut motor.copper),
        ("iron", &mut motor.iron),
        ("windage", &mut motor.windage),
        ("constant", &mut motor.constant),
    ] {
        if let Some(v) = t.number(key)? {
            *field = v;
        }
    }
    *motor = motor
        .validated()
        .map_err(|e| invalid(t, e.field, e.value, "finite and >= 0"))?;
    if let Some(v) = t.number("regen_max_share")? {
        if !(0.0..=1.0).contains(&v) {
            return Err(invalid(t, "regen_max_share", v, "within [0, 1]"));
        }
        regen.max_share = v;
    }
    if let Some(v) = t.number("regen_max_power")? {
        if !(v.is_finite() && v >= 0.0) {
            return Err(invalid(t, "regen_max_power", v, "finite and >= 0 W"));
        }
        regen.max_power = v;
    }
    if let Some(v) = t.number("regen_fade_speed")? {
        if !(v.is_finite() && v > 0.0) {
            return Err(invalid(t, "regen_fade_speed", v, "finite and > 0 m/s"));
        }
        regen.fade_speed = v;
    }
    Ok(())
}
