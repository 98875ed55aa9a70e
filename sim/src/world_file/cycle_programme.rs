//! The drive-cycle keys of `[[vehicle.programme]]` steps ([`CycleCommand`]): `cycle =
//! "hwfet"` (or `"ftp75"`, `"udds"`), or `cycle_file = "<path>"` with `cycle_unit = "km/h"`
//! (`"mph"`, `"m/s"`) for a user's 1 Hz table of `time speed` lines, relative to the world
//! file.
//!
//! What the file alone shows wrong is an error here, at its key: an unknown cycle, a table
//! that does not read (its path, line and reason in the message), a second cycle in one car's
//! programme, and a pedal or gear command (`throttle`, `brake_intensity`, `cruising_speed`,
//! `gear`) while the cycle drives the pedals, which the driver would overwrite at once.

use proto_geom::plausible::Compact;

use crate::scenario::{Cycle, CycleCommand, CycleSource, MS_PER_MPH, Trace};
use crate::simulation::MAX_DURATION;

use super::error::{NameSet, WorldFileError, WorldFileErrorKind};
use super::programme::steps;
use super::read::Section;
use super::shipped;

/// The key of a shipped cycle.
const CYCLE: &str = "cycle";
/// The key of a user's trace file.
const CYCLE_FILE: &str = "cycle_file";
/// The key of the unit of a user's trace file's speeds.
const CYCLE_UNIT: &str = "cycle_unit";

/// The drive-cycle keys of a programme step.
pub(crate) const CYCLE_KEYS: [&str; 3] = [CYCLE, CYCLE_FILE, CYCLE_UNIT];

/// The commands the cycle driver gives while it drives: a step with one of them inside the
/// cycle would be overwritten at the next step.
const PEDAL_KEYS: [&str; 4] = ["throttle", "brake_intensity", "cruising_speed", "gear"];

/// The speed units of a trace file, and their m/s.
const UNITS: [(&str, f64); 3] = [
    ("km/h", 1.0 / vehicle_model::KMH_PER_MS),
    ("mph", MS_PER_MPH),
    ("m/s", 1.0),
];

/// Highest speed of a user's trace (m/s): 360 km/h, above every road car's top speed; a
/// faster trace is a wrong unit (m/s read as km/h is 3.6 times too fast, mph as km/h 1.6).
const MAX_TRACE_SPEED: f64 = 100.0;

/// Reads the cycle of car section `s`, if a step has one; `keys` are every key a step may
/// have.
pub(crate) fn read_cycle(
    s: &Section<'_, '_>,
    keys: &[&str],
) -> Result<Option<CycleCommand>, WorldFileError> {
    let all = steps(s, keys)?;
    let mut found: Option<CycleCommand> = None;
    for (at, step) in &all {
        let Some(key) = CYCLE_KEYS.into_iter().find(|k| step.value(k).is_some()) else {
            continue;
        };
        if let Some(first) = &found {
            return Err(step.error(
                key,
                WorldFileErrorKind::InvalidValue(format!(
                    "the car already follows {} from {} s: one cycle per car (a longer drive \
                     is one longer cycle_file)",
                    first.label(),
                    Compact(first.at)
                )),
            ));
        }
        let (source, trace) = read_trace(step)?;
        let command = CycleCommand {
            at: *at,
            source,
            trace,
        };
        if command.end() > MAX_DURATION {
            return Err(step.error(
                key,
                WorldFileErrorKind::InvalidValue(format!(
                    "{}: the cycle would end at {} s, after a day ({MAX_DURATION} s, the \
                     longest run)",
                    command.label(),
                    Compact(command.end())
                )),
            ));
        }
        found = Some(command);
    }
    if let Some(c) = &found {
        for (at, step) in &all {
            let inside = *at >= c.at && *at < c.end();
            if let Some(k) = PEDAL_KEYS.iter().find(|k| step.value(k).is_some())
                && inside
            {
                return Err(step.error(
                    k,
                    WorldFileErrorKind::InvalidValue(format!(
                        "at {} s the car follows {} (from {} s to {} s), whose driver sets the \
                         throttle, brake and gear every step; give it after {} s",
                        Compact(*at),
                        c.label(),
                        Compact(c.at),
                        Compact(c.end()),
                        Compact(c.end())
                    )),
                ));
            }
        }
    }
    Ok(found)
}

/// The trace a step names: a shipped cycle, or a file with its unit.
fn read_trace(step: &Section<'_, '_>) -> Result<(CycleSource, Trace), WorldFileError> {
    let name = step.string(CYCLE)?;
    let file = step.string(CYCLE_FILE)?;
    let unit = step.string(CYCLE_UNIT)?;
    let refuse =
        |key: &str, why: &str| step.error(key, WorldFileErrorKind::InvalidValue(why.to_string()));
    match (name, file) {
        (Some(_), Some(_)) => Err(refuse(
            CYCLE_FILE,
            "a step follows a shipped cycle or a file, not both",
        )),
        (Some(name), None) => {
            if unit.is_some() {
                return Err(refuse(
                    CYCLE_UNIT,
                    "a shipped cycle has its own unit: cycle_unit is for a cycle_file",
                ));
            }
            let names = Cycle::ALL.map(Cycle::name);
            let cycle = Cycle::from_name(name)
                .ok_or_else(|| step.unknown_name(CYCLE, NameSet::DriveCycle, name, &names))?;
            Ok((CycleSource::Shipped(cycle), cycle.trace()))
        }
        (None, Some(path)) => {
            let Some(unit) = unit else {
                return Err(refuse(
                    CYCLE_FILE,
                    "the unit of the file's speeds is missing: cycle_unit = \"km/h\", \"mph\" \
                     or \"m/s\"",
                ));
            };
            let names = UNITS.map(|(n, _)| n);
            let scale = UNITS
                .iter()
                .find(|(n, _)| *n == unit)
                .map(|&(_, s)| s)
                .ok_or_else(|| step.unknown_name(CYCLE_UNIT, NameSet::SpeedUnit, unit, &names))?;
            read_file(step, path, scale).map(|t| (CycleSource::File(path.to_string()), t))
        }
        // The step's cycle key is `cycle_unit` alone.
        (None, None) => Err(refuse(
            CYCLE_UNIT,
            "cycle_unit without a cycle_file to apply it to",
        )),
    }
}

/// The trace in the file `name` (relative to the world file) of speeds in units of `scale`
/// m/s.
fn read_file(step: &Section<'_, '_>, name: &str, scale: f64) -> Result<Trace, WorldFileError> {
    let path = shipped::include_path(step.src.file, name);
    let shown = path.display().to_string();
    let fail = |message: String| step.error(CYCLE_FILE, WorldFileErrorKind::InvalidValue(message));
    // A shipped world's includes are embedded with it.
    let text = shipped::read_included(&path).map_err(|e| fail(format!("{shown}: {e}")))?;
    let trace = Trace::from_table(&text, scale).map_err(|e| fail(format!("{shown}: {e}")))?;
    if let Some((second, v)) = trace
        .speeds()
        .iter()
        .enumerate()
        .find(|(_, v)| **v > MAX_TRACE_SPEED)
    {
        return Err(fail(format!(
            "{shown}: {} at {second} s is {} km/h, faster than any road car ({} km/h at \
             most): is cycle_unit right?",
            Compact(*v / scale),
            Compact(*v * vehicle_model::KMH_PER_MS),
            Compact(MAX_TRACE_SPEED * vehicle_model::KMH_PER_MS)
        )));
    }
    Ok(trace)
}
