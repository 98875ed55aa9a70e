//! `[[road]]` and `[[junction]]`: roads in Webots' Road vocabulary (segments, lanes, lines,
//! borders), and the top-level `road = "file.xodr"` that imports an OpenDRIVE file.

use proto_geom::nalgebra::Point2;
use proto_geom::plausible::Compact;

use super::error::{NameSet, WorldFileError, WorldFileErrorKind, WorldWarning};
use super::read::{Section, missing};
use super::shipped;
use crate::road::{
    ContactPoint, Cubic, Curve, Junction, JunctionConnection, Lane, LaneKind, LaneSection,
    LineStyle, Profile, Road, RoadLink, RoadMark, RoadNetwork, Segment, chain,
};

/// Keys of each `[[road]]`.
pub(crate) const ROAD_KEYS: [&str; 19] = [
    "id",
    "start",
    "startingAngle",
    "elevation",
    "numberOfLanes",
    "numberOfForwardLanes",
    "width",
    "laneWidths",
    "friction",
    "laneFriction",
    "leftBorder",
    "rightBorder",
    "roadBorderWidth",
    "closed",
    "predecessor",
    "successor",
    "junction",
    "line",
    "segment",
];
/// Keys of each `[[road.segment]]`.
const SEGMENT_KEYS: [&str; 8] = [
    "type",
    "length",
    "radius",
    "angle",
    "curvatureStart",
    "curvatureEnd",
    "grade",
    "banking",
];
/// Keys of each `[[road.line]]`.
const LINE_KEYS: [&str; 3] = ["color", "type", "width"];
/// Keys of each `[[junction]]` and of each of its `[[junction.connection]]`.
const JUNCTION_KEYS: [&str; 2] = ["id", "connection"];
const CONNECTION_KEYS: [&str; 3] = ["incoming", "connecting", "contactPoint"];
/// Segment types.
const SEGMENT_TYPES: [&str; 3] = ["straight", "arc", "clothoid"];
/// Line types: Webots' RoadLine `type` values.
const LINE_TYPES: [&str; 4] = ["continuous", "dashed", "double", "none"];
/// Most lanes a `[[road]]` may have.
const MAX_LANES: u64 = 16;
/// Steepest grade (rise per metre): 100 %.
const MAX_GRADE: f64 = 1.0;
/// How closely a `closed` road's end must meet its start: 1 cm and 1 mrad.
const CLOSE_TOLERANCE: (f64, f64) = (0.01, 1e-3);

/// Reads every `[[road]]` and `[[junction]]`, and the top-level `road` (an OpenDRIVE file
/// relative to the world file `file`), into a validated network.
pub(crate) fn read_roads(
    root: &Section<'_, '_>,
    file: &str,
    warnings: &mut Vec<WorldWarning>,
) -> Result<RoadNetwork, WorldFileError> {
    let mut network = RoadNetwork::default();
    let sections = match root.value("road") {
        Some(toml::de::DeValue::String(_)) => {
            let name = root.string("road")?.unwrap_or_default();
            let path = shipped::include_path(file, name);
            // A shipped world's includes are embedded with it.
            let imported = match shipped::included(&path) {
                Some(text) => crate::road::opendrive::parse_str(&path.display().to_string(), text),
                None => crate::road::opendrive::load(&path),
            }
            .map_err(|e| root.error("road", WorldFileErrorKind::InvalidValue(e.to_string())))?;
            for w in imported.warnings {
                warnings.push(root.src.warning(
                    root.key_span("road"),
                    Some("road".into()),
                    w.to_string(),
                ));
            }
            network = imported.network;
            Vec::new()
        }
        _ => root.tables("road")?,
    };
    for r in &sections {
        let road = read_road(r)?;
        if network.road(&road.id).is_some() {
            return Err(r.error(
                "id",
                WorldFileErrorKind::InvalidValue(format!(
                    "\"{}\": another road has this id",
                    road.id
                )),
            ));
        }
        network.roads.push(road);
    }
    for j in root.tables("junction")? {
        j.check_keys(&JUNCTION_KEYS)?;
        let id = j.string("id")?.ok_or_else(|| missing(&j, "id"))?.to_owned();
        let mut connections = Vec::new();
        for c in j.tables("connection")? {
            c.check_keys(&CONNECTION_KEYS)?;
            let mut ids = [String::new(), String::new()];
            for (out, key) in ids.iter_mut().zip(["incoming", "connecting"]) {
                let name = c.string(key)?.ok_or_else(|| missing(&c, key))?;
                if network.road(name).is_none() {
                    return Err(c.error(
                        key,
                        WorldFileErrorKind::InvalidValue(format!(
                            "\"{name}\": no road has this id"
                        )),
                    ));
                }
                name.clone_into(out);
            }
            let [incoming, connecting] = ids;
            let contact = contact_point(&c, "contactPoint")?.unwrap_or(ContactPoint::Start);
            connections.push(JunctionConnection {
                incoming,
                connecting,
                contact,
            });
        }
        network.junctions.push(Junction { id, connections });
    }
    // Link errors (a gap between linked ends) are the road's: blame its section.
    network.validate().map_err(|e| {
        let at = sections
            .iter()
            .find(|s| s.string("id").ok().flatten() == Some(e.road.as_str()));
        match at {
            Some(s) => s.error(
                if e.field == "predecessor" || e.field == "successor" {
                    e.field.as_str()
                } else {
                    "id"
                },
                WorldFileErrorKind::InvalidValue(e.to_string()),
            ),
            None => root.error("road", WorldFileErrorKind::InvalidValue(e.to_string())),
        }
    })?;
    Ok(network)
}

/// `key`'s `"start"` or `"end"`, if present.
fn contact_point(s: &Section<'_, '_>, key: &str) -> Result<Option<ContactPoint>, WorldFileError> {
    s.string(key)?
        .map(|name| match name {
            "start" => Ok(ContactPoint::Start),
            "end" => Ok(ContactPoint::End),
            other => Err(s.unknown_name(key, NameSet::ContactPoint, other, &["start", "end"])),
        })
        .transpose()
}

/// A number at `key` (default `default`) that `ok` accepts, else an error saying `rule`.
fn checked(
    s: &Section<'_, '_>,
    key: &str,
    default: f64,
    rule: &str,
    ok: impl Fn(f64) -> bool,
) -> Result<f64, WorldFileError> {
    let v = s.number(key)?.unwrap_or(default);
    if v.is_finite() && ok(v) {
        Ok(v)
    } else {
        Err(s.error(
            key,
            WorldFileErrorKind::InvalidValue(format!("{}: must be {rule}", Compact(v))),
        ))
    }
}

fn read_road(r: &Section<'_, '_>) -> Result<Road, WorldFileError> {
    r.check_keys(&ROAD_KEYS)?;
    let id = r.string("id")?.ok_or_else(|| missing(r, "id"))?.to_owned();
    let start = r.array::<2>("start")?.unwrap_or([0.0, 0.0]);
    if !start.iter().all(|c| c.is_finite() && c.abs() <= 1e6) {
        return Err(r.error(
            "start",
            WorldFileErrorKind::InvalidValue("must be finite, within ±1000 km".into()),
        ));
    }
    let heading = checked(r, "startingAngle", 0.0, "finite (rad)", |_| true)?;
    let z0 = checked(
        r,
        "elevation",
        0.0,
        "from 0 to 10000 m (the road stands on or above the ground)",
        |z| (0.0..=1e4).contains(&z),
    )?;
    let lanes = match r.unsigned("numberOfLanes")? {
        None => 2,
        Some(n) if (1..=MAX_LANES).contains(&n) => n as usize,
        Some(n) => {
            return Err(r.error(
                "numberOfLanes",
                WorldFileErrorKind::InvalidValue(format!("{n}: must be from 1 to {MAX_LANES}")),
            ));
        }
    };
    let forward = match r.unsigned("numberOfForwardLanes")? {
        None => lanes.div_ceil(2),
        Some(n) if n as usize <= lanes => n as usize,
        Some(n) => {
            return Err(r.error(
                "numberOfForwardLanes",
                WorldFileErrorKind::InvalidValue(format!(
                    "{n}: must be at most numberOfLanes ({lanes})"
                )),
            ));
        }
    };
    let widths = match r.numbers("laneWidths", 1..=MAX_LANES as usize)? {
        Some(w) if w.len() != lanes => {
            return Err(r.error(
                "laneWidths",
                WorldFileErrorKind::InvalidValue(format!(
                    "{} widths: must be one per lane ({lanes})",
                    w.len()
                )),
            ));
        }
        Some(w) => {
            if r.number("width")?.is_some() {
                return Err(r.error(
                    "width",
                    WorldFileErrorKind::InvalidValue("give width or laneWidths, not both".into()),
                ));
            }
            w
        }
        None => vec![
            checked(r, "width", 7.0, "from 1 to 100 m", |w| (1.0..=100.0)
                .contains(&w))?
                / lanes as f64;
            lanes
        ],
    };
    if let Some(w) = widths
        .iter()
        .find(|w| !(w.is_finite() && (0.5..=20.0).contains(*w)))
    {
        return Err(r.error(
            "laneWidths",
            WorldFileErrorKind::InvalidValue(format!(
                "{} m: each lane must be from 0.5 to 20 m wide",
                Compact(*w)
            )),
        ));
    }
    let friction = match r.number("friction")? {
        Some(_) => Some(checked(r, "friction", 1.0, "from 0 to 100", |m| {
            (0.0..=100.0).contains(&m)
        })?),
        None => None,
    };
    let lane_friction = r.numbers("laneFriction", lanes..=lanes)?;
    if let Some(m) = lane_friction
        .iter()
        .flatten()
        .find(|m| !(m.is_finite() && (0.0..=100.0).contains(*m)))
    {
        return Err(r.error(
            "laneFriction",
            WorldFileErrorKind::InvalidValue(format!(
                "{}: each must be from 0 to 100",
                Compact(*m)
            )),
        ));
    }
    // Lanes from the rightmost to the leftmost: the forward ones (right of the reference
    // line, ids −forward … −1), then the others (ids 1 …).
    let id_of = |i: usize| {
        if i < forward {
            -((forward - i) as i32)
        } else {
            (i - forward + 1) as i32
        }
    };
    let mut right = Vec::new();
    let mut left = Vec::new();
    for i in 0..lanes {
        let lane = Lane {
            id: id_of(i),
            kind: LaneKind::Driving,
            width: Profile::constant(widths[i]),
            friction: lane_friction.as_ref().map(|m| m[i]),
            marks: Vec::new(),
        };
        if lane.id < 0 {
            right.insert(0, lane)
        } else {
            left.push(lane)
        }
    }
    let mut centre_marks = Vec::new();
    let line_sections = r.tables("line")?;
    if !line_sections.is_empty() && line_sections.len() != lanes - 1 {
        return Err(r.error("line", WorldFileErrorKind::InvalidValue(format!("{} lines: a road of {lanes} lanes has {} lines between them, listed from the right", line_sections.len(), lanes - 1))));
    }
    for b in 0..lanes.saturating_sub(1) {
        let mark = match line_sections.get(b) {
            Some(l) => read_line(l)?,
            None => Some(RoadMark {
                s_offset: 0.0,
                style: LineStyle::Dashed,
                colour: [1.0; 3],
                width: 0.15,
            }),
        };
        let Some(mark) = mark else { continue };
        // Line b separates lanes b and b + 1 (from the right): the outer edge of the inner
        // one of the two, or the reference line between the directions.
        let (lo, hi) = (id_of(b), id_of(b + 1));
        let target = if hi < 0 {
            Some(hi)
        } else if lo > 0 {
            Some(lo)
        } else {
            None
        };
        match target {
            None => centre_marks.push(mark),
            Some(id) => {
                if let Some(l) = right.iter_mut().chain(left.iter_mut()).find(|l| l.id == id) {
                    l.marks.push(mark);
                }
            }
        }
    }
    let border = checked(r, "roadBorderWidth", 0.8, "from 0.1 to 10 m", |w| {
        (0.1..=10.0).contains(&w)
    })?;
    for (key, side) in [("rightBorder", &mut right), ("leftBorder", &mut left)] {
        if r.boolean(key)?.unwrap_or(false) {
            let id = (side.len() as i32 + 1) * if key == "rightBorder" { -1 } else { 1 };
            side.push(Lane {
                id,
                kind: LaneKind::Border,
                width: Profile::constant(border),
                friction: None,
                marks: Vec::new(),
            });
        }
    }
    let (parts, elevation, banking) = read_segments(r, z0)?;
    let segments: Vec<Segment> = chain(Point2::from(start), heading, &parts);
    let mut road = Road {
        id: id.clone(),
        segments,
        elevation,
        superelevation: banking,
        lane_offset: Profile::default(),
        sections: vec![LaneSection {
            s: 0.0,
            left,
            centre_marks,
            right,
        }],
        friction: friction.unwrap_or(crate::DEFAULT_FRICTION),
        predecessor: link(r, "predecessor")?,
        successor: link(r, "successor")?,
        junction: r.string("junction")?.map(str::to_owned),
    };
    if r.boolean("closed")?.unwrap_or(false) {
        let (a, b) = (road.plan_at(0.0), road.plan_at(road.length()));
        let gap = (a.point - b.point).norm();
        let turn = (b.heading - a.heading)
            .sin()
            .abs()
            .max(((b.heading - a.heading).cos() - 1.0).abs());
        if gap > CLOSE_TOLERANCE.0 || turn > CLOSE_TOLERANCE.1 {
            return Err(r.error("closed", WorldFileErrorKind::InvalidValue(format!(
                "the last segment ends {gap:.3} m and {turn:.4} rad from the start: a closed road must end within {} m and {} rad of where it starts",
                CLOSE_TOLERANCE.0, CLOSE_TOLERANCE.1))));
        }
        road.predecessor = Some(RoadLink::Road {
            id: id.clone(),
            contact: ContactPoint::End,
        });
        road.successor = Some(RoadLink::Road {
            id,
            contact: ContactPoint::Start,
        });
    }
    road.validate()
        .map_err(|e| r.error("segment", WorldFileErrorKind::InvalidValue(e.to_string())))?;
    Ok(road)
}

/// `"id"` or `"id:start"`/`"id:end"` at `key` (the other road's end; its start for a
/// successor and its end for a predecessor by default).
fn link(r: &Section<'_, '_>, key: &str) -> Result<Option<RoadLink>, WorldFileError> {
    Ok(r.string(key)?.map(|v| {
        let (id, contact) = match v.rsplit_once(':') {
            Some((id, "end")) => (id, ContactPoint::End),
            Some((id, "start")) => (id, ContactPoint::Start),
            _ if key == "successor" => (v, ContactPoint::Start),
            _ => (v, ContactPoint::End),
        };
        RoadLink::Road {
            id: id.to_owned(),
            contact,
        }
    }))
}

/// A `[[road.line]]`: its mark, or `None` for `type = "none"`.
fn read_line(l: &Section<'_, '_>) -> Result<Option<RoadMark>, WorldFileError> {
    l.check_keys(&LINE_KEYS)?;
    let style = match l.string("type")?.unwrap_or("dashed") {
        "continuous" => LineStyle::Solid,
        "dashed" => LineStyle::Dashed,
        "double" => LineStyle::DoubleSolid,
        "none" => return Ok(None),
        other => return Err(l.unknown_name("type", NameSet::LineType, other, &LINE_TYPES)),
    };
    // Webots' RoadLine default colour: a light yellow.
    let colour = l.array::<3>("color")?.unwrap_or([0.85, 0.75, 0.3]);
    if !colour.iter().all(|c| (0.0..=1.0).contains(c)) {
        return Err(l.error(
            "color",
            WorldFileErrorKind::InvalidValue("each component must be from 0 to 1".into()),
        ));
    }
    let width = checked(l, "width", 0.15, "from 0.01 to 2 m", |w| {
        (0.01..=2.0).contains(&w)
    })?;
    Ok(Some(RoadMark {
        s_offset: 0.0,
        style,
        colour,
        width,
    }))
}

/// The segments of `[[road.segment]]` with the elevation (from `z0`, m) and banking profiles
/// their `grade` and `banking` give.
#[allow(clippy::type_complexity)]
fn read_segments(
    r: &Section<'_, '_>,
    z0: f64,
) -> Result<(Vec<(f64, Curve)>, Profile, Profile), WorldFileError> {
    let sections = r.tables("segment")?;
    if sections.is_empty() {
        return Err(missing(r, "segment"));
    }
    let (mut parts, mut heights, mut banks) = (Vec::new(), Vec::new(), Vec::new());
    let (mut s, mut z, mut grade, mut bank) = (0.0, z0, 0.0, 0.0);
    for g in &sections {
        g.check_keys(&SEGMENT_KEYS)?;
        let kind = g.string("type")?.ok_or_else(|| missing(g, "type"))?;
        let positive = |key: &str| -> Result<f64, WorldFileError> {
            let v = g.number(key)?.ok_or_else(|| missing(g, key))?;
            if v.is_finite() && v > 0.0 && v <= 1e5 {
                Ok(v)
            } else {
                Err(g.error(
                    key,
                    WorldFileErrorKind::InvalidValue(format!(
                        "{}: must be > 0 and at most 100 km",
                        Compact(v)
                    )),
                ))
            }
        };
        let curvature = |key: &str| {
            checked(
                g,
                key,
                0.0,
                "within ±2 1/m (a radius of 0.5 m or more)",
                |k| k.abs() <= 2.0,
            )
        };
        let (length, curve) = match kind {
            "straight" => (positive("length")?, Curve::Line),
            "arc" => {
                let radius = positive("radius")?;
                if radius < 0.5 {
                    return Err(g.error(
                        "radius",
                        WorldFileErrorKind::InvalidValue(format!(
                            "{} m: must be at least 0.5 m",
                            Compact(radius)
                        )),
                    ));
                }
                let angle = checked(
                    g,
                    "angle",
                    f64::NAN,
                    "finite and not 0 (rad, positive turning left)",
                    |a| a != 0.0,
                )?;
                (
                    radius * angle.abs(),
                    Curve::Arc {
                        curvature: angle.signum() / radius,
                    },
                )
            }
            "clothoid" => (
                positive("length")?,
                Curve::Spiral {
                    curvature_start: curvature("curvatureStart")?,
                    curvature_end: curvature("curvatureEnd")?,
                },
            ),
            other => {
                return Err(g.unknown_name("type", NameSet::SegmentType, other, &SEGMENT_TYPES));
            }
        };
        let g1 = checked(g, "grade", grade, "within ±1 (rise per metre)", |v| {
            v.abs() <= MAX_GRADE
        })?;
        let b1 = checked(g, "banking", bank, "within ±1.047 rad (60°)", |v| {
            v.abs() <= crate::road::MAX_SUPERELEVATION
        })?;
        // The grade changes linearly along the segment: a vertical parabola.
        let c = (g1 - grade) / (2.0 * length);
        heights.push(Cubic {
            s,
            coefficients: [z, grade, c, 0.0],
        });
        banks.push(Cubic {
            s,
            coefficients: [bank, (b1 - bank) / length, 0.0, 0.0],
        });
        z += grade * length + c * length * length;
        if z < 0.0 {
            return Err(g.error("grade", WorldFileErrorKind::InvalidValue(format!(
                "the road ends this segment {} m below the ground: a road stands on or above it", Compact(-z)))));
        }
        (grade, bank, s) = (g1, b1, s + length);
        parts.push((length, curve));
    }
    Ok((parts, Profile::new(heights), Profile::new(banks)))
}
