//! `[[vehicle.programme]]` and `[[differential_wheels.programme]]`: the timed commands of a
//! car or robot (see [`crate::programme`]).

use vehicle_model::{IndicatorState, WiperMode};

use proto_geom::plausible::Compact;

use crate::keyboard::{KeyPress, check_code, parse_key};
use crate::programme::{DriverCommand, Programme, Step, WheelSpeeds};
use crate::simulation::MAX_DURATION;

use super::cycle_programme::CYCLE_KEYS;
use super::error::{NameSet, WorldFileError, WorldFileErrorKind};
use super::lane_programme::FOLLOW_KEYS;
use super::read::Section;

/// The key of a programme in `[vehicle]` and `[differential_wheels]`.
pub(crate) const PROGRAMME: &str = "programme";
/// The key of a step's time.
pub(crate) const AT: &str = "at";
/// The key of a step's key press (the controller's keyboard).
pub(crate) const KEY: &str = "key";

const INDICATORS: [(&str, IndicatorState); 3] = [
    ("off", IndicatorState::Off),
    ("right", IndicatorState::Right),
    ("left", IndicatorState::Left),
];
const WIPER_MODES: [(&str, WiperMode); 4] = [
    ("down", WiperMode::Down),
    ("slow", WiperMode::Slow),
    ("normal", WiperMode::Normal),
    ("fast", WiperMode::Fast),
];

/// The steps of `[[<s>.programme]]`, each with its `at` and at least one other key.
pub(crate) fn steps<'a, 'i>(
    s: &Section<'a, 'i>,
    keys: &[&str],
) -> Result<Vec<(f64, Section<'a, 'i>)>, WorldFileError> {
    let mut out = Vec::new();
    for step in s.tables(PROGRAMME)? {
        step.check_keys(keys)?;
        let at = step.number(AT)?.ok_or_else(|| {
            step.src.error(
                step.span(),
                Some(step.key_path(AT)),
                WorldFileErrorKind::Structure(format!("missing key '{}'", step.key_path(AT))),
            )
        })?;
        // A step after a day never comes: the run could not last that long.
        if !(0.0..=MAX_DURATION).contains(&at) {
            return Err(step.error(
                AT,
                WorldFileErrorKind::InvalidValue(format!(
                    "{} s: must be from 0 to {MAX_DURATION} s (a day, the longest run)",
                    Compact(at)
                )),
            ));
        }
        if step.entries().len() < 2 {
            let names: Vec<&str> = keys.iter().copied().filter(|k| *k != AT).collect();
            return Err(step.src.error(
                step.span(),
                Some(step.path().to_string()),
                WorldFileErrorKind::Structure(format!(
                    "the step at {} s of '{}' has no command (one of: {})",
                    Compact(at),
                    step.path(),
                    names.join(", ")
                )),
            ));
        }
        out.push((at, step));
    }
    Ok(out)
}

/// A number at `key` of `step` within `[lo, hi]`.
fn number_in(step: &Section<'_, '_>, key: &str, lo: f64, hi: f64) -> Result<f64, WorldFileError> {
    let v = step.number(key)?.unwrap_or(f64::NAN);
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        let rule = if lo == f64::MIN {
            "must be finite".to_string()
        } else {
            format!("must be from {} to {}", Compact(lo), Compact(hi))
        };
        Err(step.error(
            key,
            WorldFileErrorKind::InvalidValue(format!("{}: {rule}", Compact(v))),
        ))
    }
}

/// A name of `names` at `key` of `step`.
fn name_of<T: Copy>(
    step: &Section<'_, '_>,
    key: &str,
    what: NameSet,
    names: &[(&str, T)],
) -> Result<T, WorldFileError> {
    let name = step.string(key)?.unwrap_or("");
    names
        .iter()
        .find(|(n, _)| *n == name)
        .map(|&(_, v)| v)
        .ok_or_else(|| {
            let all: Vec<&str> = names.iter().map(|(n, _)| *n).collect();
            step.unknown_name(key, what, name, &all)
        })
}

/// A boolean at `key` of `step` (present: the caller found the key).
fn flag(step: &Section<'_, '_>, key: &str) -> Result<bool, WorldFileError> {
    Ok(step.boolean(key)?.unwrap_or(false))
}

/// Every key a car's programme step may have.
pub(crate) fn step_keys() -> Vec<&'static str> {
    [AT, KEY]
        .into_iter()
        .chain(DriverCommand::KEYS)
        .chain(FOLLOW_KEYS)
        .chain(CYCLE_KEYS)
        .collect()
}

/// Reads the programme of a car section `s`; `gears` is the car's highest forward gear, for
/// the range of `gear`.
pub(crate) fn read_car_programme(
    s: &Section<'_, '_>,
    gears: i32,
) -> Result<Programme<DriverCommand>, WorldFileError> {
    let keys = step_keys();
    let mut out = Vec::new();
    for (at, step) in steps(s, &keys)? {
        let mut commands = Vec::new();
        for (key, ..) in step.entries() {
            let command = match key {
                AT | KEY => continue,
                k if FOLLOW_KEYS.contains(&k) || CYCLE_KEYS.contains(&k) => continue,
                "cruising_speed" => {
                    DriverCommand::CruisingSpeed(number_in(&step, key, f64::MIN, f64::MAX)?)
                }
                "steering_angle" => {
                    DriverCommand::SteeringAngle(number_in(&step, key, f64::MIN, f64::MAX)?)
                }
                "throttle" => DriverCommand::Throttle(number_in(&step, key, 0.0, 1.0)?),
                "brake_intensity" => {
                    DriverCommand::BrakeIntensity(number_in(&step, key, 0.0, 1.0)?)
                }
                "gear" => {
                    let g = number_in(&step, key, -1.0, f64::from(gears))?;
                    if g.fract() != 0.0 {
                        return Err(step.error(
                            key,
                            WorldFileErrorKind::InvalidValue(format!(
                                "{}: must be an integer",
                                Compact(g)
                            )),
                        ));
                    }
                    DriverCommand::Gear(g as i32)
                }
                "indicator" => {
                    DriverCommand::Indicator(name_of(&step, key, NameSet::Indicator, &INDICATORS)?)
                }
                "hazard_flashers" => DriverCommand::HazardFlashers(flag(&step, key)?),
                "dipped_beams" => DriverCommand::DippedBeams(flag(&step, key)?),
                "antifog_lights" => DriverCommand::AntifogLights(flag(&step, key)?),
                _ => {
                    DriverCommand::WiperMode(name_of(&step, key, NameSet::WiperMode, &WIPER_MODES)?)
                }
            };
            commands.push(command);
        }
        // A step that only presses a key drives nothing.
        if !commands.is_empty() {
            out.push(Step { at, commands });
        }
    }
    Ok(Programme::new(out))
}

/// The keys the programme of car section `s` presses (`key = "A"`, `"CONTROL+UP"` … or a
/// Webots key code), in file order.
pub(crate) fn read_car_keys(s: &Section<'_, '_>) -> Result<Vec<KeyPress>, WorldFileError> {
    let keys = step_keys();
    let mut out = Vec::new();
    for (at, step) in steps(s, &keys)? {
        let code = match (step.string(KEY), step.number(KEY)) {
            (Ok(None), _) => continue,
            (Ok(Some(text)), _) => parse_key(text).ok_or_else(|| {
                step.error(
                    KEY,
                    WorldFileErrorKind::InvalidValue(format!(
                        "\"{text}\": must be one printable character, or a key name (UP, DOWN, \
                         LEFT, RIGHT, HOME, END, PAGEUP, PAGEDOWN, NUMPAD_…), after any of \
                         SHIFT+, CONTROL+, ALT+"
                    )),
                )
            })?,
            (Err(_), Ok(Some(n))) if n.fract() == 0.0 => check_code(n as i64).map_err(|e| {
                step.error(
                    KEY,
                    WorldFileErrorKind::InvalidValue(format!("{}: must be {}", Compact(n), e.rule)),
                )
            })?,
            (Err(e), _) => return Err(e),
        };
        // `at` is from 0 to a day (checked by `steps`): whole ms fit.
        out.push(KeyPress {
            at_ms: (at * 1000.0).round() as u64,
            code,
        });
    }
    Ok(out)
}

/// Reads the programme of the robot section `s`: `speed = [left, right]` in speed units,
/// each within `maxSpeed / speedUnit`.
pub(crate) fn read_robot_programme(
    s: &Section<'_, '_>,
    max_speed_units: f64,
) -> Result<Programme<WheelSpeeds>, WorldFileError> {
    let mut out = Vec::new();
    for (at, step) in steps(s, &[AT, "speed"])? {
        let [left, right] = step.array::<2>("speed")?.unwrap_or([f64::NAN; 2]);
        if let Some(bad) = [left, right]
            .into_iter()
            .find(|v| !(v.is_finite() && v.abs() <= max_speed_units * (1.0 + 1e-12)))
        {
            return Err(step.error(
                "speed",
                WorldFileErrorKind::InvalidValue(format!(
                    "{}: each wheel speed must be within ±{} speed units (maxSpeed / \
                     speedUnit)",
                    Compact(bad),
                    Compact(max_speed_units)
                )),
            ));
        }
        out.push(Step {
            at,
            commands: vec![WheelSpeeds { left, right }],
        });
    }
    Ok(Programme::new(out))
}
