//! Errors and warnings of the world-file loader, located by file, line, column and key.

use core::fmt;

use vehicle_model::Model;

/// A position in a world file (1-based line and column, counted in characters).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Location {
    /// Line number, 1 for the first line.
    pub line: u32,
    /// Column number, 1 for the first character of the line.
    pub column: u32,
}

impl Location {
    /// The location of byte offset `offset` in `text` (clamped to the text's end).
    pub fn of_offset(text: &str, offset: usize) -> Location {
        let mut end = offset.min(text.len());
        while !text.is_char_boundary(end) {
            end -= 1;
        }
        let before = &text[..end];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let column = before[line_start..].chars().count() + 1;
        let clamp = |n: usize| u32::try_from(n).unwrap_or(u32::MAX);
        Location {
            line: clamp(line),
            column: clamp(column),
        }
    }
}

/// What is wrong with a world file.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum WorldFileErrorKind {
    /// The file could not be read (missing, unreadable, not UTF-8): the system's message.
    Io(String),
    /// The text is not valid TOML: the parser's message.
    Syntax(String),
    /// A key that the section does not have; `suggestions` are the closest valid names
    /// (by edit distance), best first, possibly none.
    UnknownKey {
        /// Closest valid names.
        suggestions: Vec<String>,
    },
    /// A value of the wrong TOML type or shape.
    WrongType {
        /// What the key takes, e.g. `"a number"`, `"a list of 3 numbers"`.
        expected: String,
        /// What was found, e.g. `"string"`, `"a list of 2 values"`.
        found: String,
    },
    /// `model` names no shipped model; `suggestions` are the closest model names.
    UnknownModel {
        /// The name given.
        name: String,
        /// Closest shipped model names, best first.
        suggestions: Vec<String>,
    },
    /// A name outside a small closed set, e.g. `tyre = "pacejka"`; `suggestions` are the
    /// closest valid names or, when none is close, every valid name (the sets are small
    /// enough to list).
    UnknownName {
        /// Which set.
        what: NameSet,
        /// The name given.
        name: String,
        /// Valid names, best first.
        suggestions: Vec<String>,
    },
    /// `--world` (or `VEHICLE_WORLD`) named neither an existing file, a shipped model nor a
    /// shipped world; the message lists every shipped world and model.
    NeitherFileNorModel {
        /// The name given.
        name: String,
        /// The closest model, world and world-file names, best first (possibly none).
        suggestions: Vec<String>,
    },
    /// A value of the right type that the simulator refuses, e.g. `basicTimeStep = 0`.
    InvalidValue(String),
    /// A required key or section is absent, or two sections exclude each other.
    Structure(String),
}

/// A small closed set of names that a world-file (or sweep-file) key chooses from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum NameSet {
    /// `tyre` / `[vehicle.tyre] model`: `magic-formula`, `webots`.
    TyreModel,
    /// `[vehicle.tyre] class`: `passenger-car`, `commercial`, `tractor`.
    TyreClass,
    /// `[vehicle] mounting`: `cast`, `joints`.
    Mounting,
    /// `[vehicle] brake_balance`: `equal`, `proportioned` (or a number).
    BrakeBalance,
    /// A programme's `indicator`: `off`, `right`, `left`.
    Indicator,
    /// A programme's `wiper_mode`: `down`, `slow`, `normal`, `fast`.
    WiperMode,
    /// A sweep file's `scenario`: the `vehicle-sim` scenarios.
    Scenario,
    /// A sweep file's `combine`: `product`, `zip`.
    Combine,
    /// `[[vehicle.device]] type`: `GPS`, `InertialUnit`, `Gyro`, `Accelerometer`, `Compass`,
    /// `DistanceSensor`, `Radar`, `Lidar`.
    DeviceType,
    /// `[[vehicle.device]] slot`: `front`, `top`, `rear`, `center`.
    SensorSlot,
    /// `[[vehicle.device]] preset`: the real devices of a `Radar` or `Lidar`.
    DevicePreset,
    /// A `DistanceSensor`'s `type`: `generic`, `infra-red`, `sonar`, `laser`.
    DistanceSensorType,
    /// A `Lidar`'s `type` (key `sensorType`): `fixed`, `rotating`.
    LidarType,
    /// `gpsCoordinateSystem`: `local`, `WGS84`.
    GpsCoordinateSystem,
    /// A `Lidar`'s `projection`: `cylindrical`, `planar`.
    LidarProjection,
    /// `[[road.segment]] type`: `straight`, `arc`, `clothoid`.
    SegmentType,
    /// `[[road.line]] type`: `continuous`, `dashed`, `double`, `none`.
    LineType,
    /// A junction connection's `contactPoint`: `start`, `end`.
    ContactPoint,
    /// `[vehicle] losses`: `webots`, `road-load`.
    Losses,
    /// `[vehicle] transmission`: `webots`, `epa`.
    Transmission,
    /// A programme's `cycle`: the shipped drive cycles.
    DriveCycle,
    /// A programme's `cycle_unit`: `km/h`, `mph`, `m/s`.
    SpeedUnit,
}

impl fmt::Display for NameSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            NameSet::TyreModel => "tyre model",
            NameSet::TyreClass => "tyre class",
            NameSet::Mounting => "wheel mounting",
            NameSet::BrakeBalance => "brake balance",
            NameSet::Indicator => "indicator state",
            NameSet::WiperMode => "wiper mode",
            NameSet::Scenario => "scenario",
            NameSet::Combine => "way to combine the axes",
            NameSet::DeviceType => "device type",
            NameSet::SensorSlot => "sensor slot",
            NameSet::DevicePreset => "device preset",
            NameSet::DistanceSensorType => "distance sensor type",
            NameSet::LidarType => "lidar type",
            NameSet::GpsCoordinateSystem => "GPS coordinate system",
            NameSet::LidarProjection => "lidar projection",
            NameSet::SegmentType => "road segment type",
            NameSet::LineType => "road line type",
            NameSet::ContactPoint => "contact point",
            NameSet::Losses => "wheel loss set",
            NameSet::Transmission => "transmission",
            NameSet::DriveCycle => "drive cycle",
            NameSet::SpeedUnit => "speed unit",
        })
    }
}

/// A world file that could not be loaded: the file, where in it, which key, and why.
///
/// `Display` prints one line in the usual compiler form, e.g.
/// `world.toml:4:1: unknown key 'vehicle.time0to100'; did you mean 'time0To100'?`.
#[derive(Debug, Clone, PartialEq)]
pub struct WorldFileError {
    /// The file path as given, or a description of a built-in world (e.g. `<default world>`).
    pub file: String,
    /// Where the problem is, when it is in the text.
    pub location: Option<Location>,
    /// The dotted key the problem is about (e.g. `vehicle.gearRatio`), if any.
    pub key: Option<String>,
    /// What is wrong.
    pub kind: WorldFileErrorKind,
}

impl WorldFileError {
    /// What is wrong, naming the key, without the file and location that `Display` puts
    /// first: e.g. `invalid 'ground.friction': -0.5: must be finite and >= 0`. A sweep's
    /// results name the key this way, the case's values being in the row.
    pub fn message(&self) -> impl fmt::Display + '_ {
        Message(self)
    }

    /// The closest valid names offered with an unknown key or model (empty otherwise).
    pub fn suggestions(&self) -> &[String] {
        match &self.kind {
            WorldFileErrorKind::UnknownKey { suggestions }
            | WorldFileErrorKind::UnknownModel { suggestions, .. }
            | WorldFileErrorKind::UnknownName { suggestions, .. }
            | WorldFileErrorKind::NeitherFileNorModel { suggestions, .. } => suggestions,
            _ => &[],
        }
    }
}

/// Writes ` did you mean 'a', 'b' or 'c'?` for non-empty `names`.
fn write_suggestions(f: &mut fmt::Formatter<'_>, names: &[String]) -> fmt::Result {
    let Some((last, rest)) = names.split_last() else {
        return Ok(());
    };
    f.write_str("; did you mean ")?;
    for (i, n) in rest.iter().enumerate() {
        if i > 0 {
            f.write_str(", ")?;
        }
        write!(f, "'{n}'")?;
    }
    if !rest.is_empty() {
        f.write_str(" or ")?;
    }
    write!(f, "'{last}'?")
}

impl fmt::Display for WorldFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // A name that is no file has no file to point at: the message names it.
        if !matches!(self.kind, WorldFileErrorKind::NeitherFileNorModel { .. }) {
            f.write_str(&self.file)?;
            if let Some(l) = self.location {
                write!(f, ":{}:{}", l.line, l.column)?;
            }
            f.write_str(": ")?;
        }
        write!(f, "{}", self.message())
    }
}

/// [`WorldFileError::message`].
struct Message<'a>(&'a WorldFileError);

impl fmt::Display for Message<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let e = self.0;
        let key = e.key.as_deref().unwrap_or("");
        match &e.kind {
            WorldFileErrorKind::Io(m) => write!(f, "cannot read the world file: {m}"),
            WorldFileErrorKind::Syntax(m) => write!(f, "invalid TOML: {m}"),
            WorldFileErrorKind::UnknownKey { suggestions } => {
                write!(f, "unknown key '{key}'")?;
                write_suggestions(f, suggestions)
            }
            WorldFileErrorKind::WrongType { expected, found } => {
                write!(f, "'{key}' takes {expected}, found {found}")
            }
            WorldFileErrorKind::UnknownModel { name, suggestions } => {
                write!(f, "unknown vehicle model '{name}'")?;
                write_suggestions(f, suggestions)
            }
            WorldFileErrorKind::UnknownName {
                what,
                name,
                suggestions,
            } => {
                write!(f, "unknown {what} '{name}'")?;
                write_suggestions(f, suggestions)
            }
            WorldFileErrorKind::NeitherFileNorModel { name, suggestions } => {
                write!(
                    f,
                    "'{name}' is neither a world file, a shipped world nor a vehicle model"
                )?;
                write_suggestions(f, suggestions)?;
                let worlds: Vec<&str> = super::shipped::worlds().map(|w| w.name).collect();
                let models: Vec<&str> = model_names().collect();
                write!(
                    f,
                    " (worlds: {}; models: {})",
                    worlds.join(", "),
                    models.join(", ")
                )
            }
            WorldFileErrorKind::InvalidValue(m) => {
                if key.is_empty() {
                    f.write_str(m)
                } else {
                    write!(f, "invalid '{key}': {m}")
                }
            }
            WorldFileErrorKind::Structure(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for WorldFileError {}

/// A value the loader accepted but the model replaced or ignored, as Webots prints it
/// (e.g. a non-positive `wheelbase` replaced by the default), located in the file when the
/// world file set that key.
#[derive(Debug, Clone, PartialEq)]
pub struct WorldWarning {
    /// The file path as given, or a description of a built-in world.
    pub file: String,
    /// Where the key that caused it is, if the file set it.
    pub location: Option<Location>,
    /// The dotted key, e.g. `vehicle.wheelbase`, if the warning is about one.
    pub key: Option<String>,
    /// The message (from `vehicle-model` for car fields).
    pub message: String,
}

impl fmt::Display for WorldWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.file)?;
        if let Some(l) = self.location {
            write!(f, ":{}:{}", l.line, l.column)?;
        }
        write!(f, ": {}", self.message)
    }
}

/// The Levenshtein distance between `a` and `b` (in characters, by `strsim`), ignoring ASCII
/// case (a user who typed `time0to100` meant `time0To100`).
fn edit_distance(a: &str, b: &str) -> usize {
    strsim::levenshtein(&a.to_ascii_lowercase(), &b.to_ascii_lowercase())
}

/// The names of `candidates` close to `name`, best first: at most 3, each within a third of
/// the longer name's length (at least 2 edits), or a candidate that contains `name` or is
/// contained in it (case-insensitively).
pub(crate) fn closest<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Vec<String> {
    let lower = name.to_ascii_lowercase();
    let mut scored: Vec<(usize, &str)> = candidates
        .into_iter()
        .filter_map(|c| {
            let d = edit_distance(name, c);
            let limit = (name.chars().count().max(c.chars().count()) / 3).max(2);
            let c_lower = c.to_ascii_lowercase();
            let related =
                lower.len() >= 3 && (c_lower.contains(&lower) || lower.contains(&c_lower));
            (d <= limit || related).then_some((d, c))
        })
        .collect();
    scored.sort_by(|a, b| a.0.cmp(&b.0).then_with(|| a.1.cmp(b.1)));
    scored.dedup_by(|a, b| a.1 == b.1);
    scored
        .into_iter()
        .take(3)
        .map(|(_, c)| c.to_string())
        .collect()
}

/// The names of every shipped model, for suggestions.
pub(crate) fn model_names() -> impl Iterator<Item = &'static str> {
    Model::ALL.into_iter().map(Model::webots_name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances() {
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(edit_distance("time0to100", "time0To100"), 0);
        assert_eq!(edit_distance("timeTo100", "time0To100"), 1);
    }

    #[test]
    fn closest_names() {
        let names = [
            "time0To100",
            "maxVelocity",
            "trackFront",
            "trackRear",
            "wheelbase",
        ];
        assert_eq!(closest("timeTo100", names), vec!["time0To100"]);
        assert_eq!(closest("trackfrnt", names)[0], "trackFront");
        assert!(closest("zzzzzz", names).is_empty());
        assert_eq!(closest("track", names), vec!["trackRear", "trackFront"]);
    }

    #[test]
    fn locations_are_one_based() {
        let t = "a = 1\nbé = 2\n";
        assert_eq!(Location::of_offset(t, 0), Location { line: 1, column: 1 });
        // Line 2 starts at byte 6; 'é' is two bytes, so '=' is at byte 10, character 4.
        assert_eq!(Location::of_offset(t, 10), Location { line: 2, column: 4 });
        assert_eq!(Location::of_offset(t, 999), Location { line: 3, column: 1 });
    }

    #[test]
    fn display_lists_suggestions() {
        let e = WorldFileError {
            file: "w.toml".into(),
            location: Some(Location { line: 4, column: 1 }),
            key: Some("vehicle.timeTo100".into()),
            kind: WorldFileErrorKind::UnknownKey {
                suggestions: vec!["time0To100".into(), "a".into()],
            },
        };
        assert_eq!(
            e.to_string(),
            "w.toml:4:1: unknown key 'vehicle.timeTo100'; did you mean 'time0To100' or 'a'?"
        );
        assert_eq!(
            e.message().to_string(),
            "unknown key 'vehicle.timeTo100'; did you mean 'time0To100' or 'a'?"
        );
    }
}
