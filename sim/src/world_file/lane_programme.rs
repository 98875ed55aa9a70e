//! The lane follower's keys of `[[vehicle.programme]]` steps ([`crate::lane_following`]):
//! `follow_lane = true | false`, `lane = <id>`, `lane_change_time = <s>`,
//! `max_lateral_acceleration = <m/s²>`. A step with any of them but `follow_lane = false`
//! makes the car follow (a later `lane` changes lanes).
//!
//! What the file alone shows wrong is an error here: following in a world without roads,
//! a `lane` no road of the world has, a car's lanes of both travel directions (a lane change
//! does not cross the centre line), values out of range. Where the car is when it starts
//! following is known only at run time (off every road: [`crate::lane_following`]).

use proto_geom::plausible::Compact;

use crate::lane_following::{FollowCommand, FollowLane};
use crate::programme::{Programme, Step};
use crate::road::{RoadNetwork, travel_direction};

use super::error::{WorldFileError, WorldFileErrorKind};
use super::programme::{step_keys, steps};
use super::read::Section;

/// The key that starts (`true`) or stops (`false`) following.
const FOLLOW_LANE: &str = "follow_lane";
/// The key of the lane to follow.
const LANE: &str = "lane";
/// The key of a lane change's duration (s).
const LANE_CHANGE_TIME: &str = "lane_change_time";
/// The key of the largest lateral acceleration in curves (m/s²).
const MAX_LATERAL_ACCELERATION: &str = "max_lateral_acceleration";

/// The lane follower's keys of a programme step.
pub(crate) const FOLLOW_KEYS: [&str; 4] = [
    FOLLOW_LANE,
    LANE,
    LANE_CHANGE_TIME,
    MAX_LATERAL_ACCELERATION,
];

/// Reads the lane follower's commands of car section `s` on the world's `roads`.
pub(crate) fn read_lane_programme(
    s: &Section<'_, '_>,
    roads: &RoadNetwork,
) -> Result<Programme<FollowCommand>, WorldFileError> {
    let keys = step_keys();
    let mut out = Vec::new();
    let mut direction: Option<f64> = None;
    for (at, step) in steps(s, &keys)? {
        if !FOLLOW_KEYS.iter().any(|k| step.value(k).is_some()) {
            continue;
        }
        if roads.is_empty() {
            let key = FOLLOW_KEYS
                .into_iter()
                .find(|k| step.value(k).is_some())
                .unwrap_or(FOLLOW_LANE);
            return Err(step.error(
                key,
                WorldFileErrorKind::InvalidValue(
                    "the world has no road to follow a lane on (add a [[road]])".to_string(),
                ),
            ));
        }
        if step.boolean(FOLLOW_LANE)? == Some(false) {
            if let Some(k) = FOLLOW_KEYS[1..].iter().find(|k| step.value(k).is_some()) {
                return Err(step.error(
                    k,
                    WorldFileErrorKind::InvalidValue(
                        "follow_lane = false stops following: it takes no lane settings"
                            .to_string(),
                    ),
                ));
            }
            out.push(Step {
                at,
                commands: vec![FollowCommand::Stop],
            });
            continue;
        }
        let mut request = FollowLane::default();
        if let Some(v) = step.number(LANE)? {
            let lane = lane_id(&step, v, roads)?;
            let dir = travel_direction(lane);
            if direction.is_some_and(|d| d != dir) {
                return Err(step.error(
                    LANE,
                    WorldFileErrorKind::InvalidValue(format!(
                        "{lane}: the car's programme also follows a lane of the other travel \
                         direction; a lane change does not cross the centre line (right lanes \
                         −1, −2, … drive along the road, left lanes 1, 2, … against it)"
                    )),
                ));
            }
            direction = Some(dir);
            request.lane = Some(lane);
        }
        if let Some(v) = step.number(LANE_CHANGE_TIME)? {
            request.change_time = v;
        }
        if let Some(v) = step.number(MAX_LATERAL_ACCELERATION)? {
            request.max_lateral_acceleration = v;
        }
        request.validate().map_err(|e| {
            step.error(
                e.field,
                WorldFileErrorKind::InvalidValue(format!(
                    "{}: must be {}",
                    Compact(e.value),
                    e.rule
                )),
            )
        })?;
        out.push(Step {
            at,
            commands: vec![FollowCommand::Follow(request)],
        });
    }
    Ok(Programme::new(out))
}

/// The lane id `v` of `step`: a non-zero integer that some road of `roads` has.
fn lane_id(step: &Section<'_, '_>, v: f64, roads: &RoadNetwork) -> Result<i32, WorldFileError> {
    let ids: Vec<i32> = {
        let mut ids: Vec<i32> = roads
            .roads
            .iter()
            .flat_map(|r| r.sections.iter().flat_map(|sec| sec.lanes().map(|l| l.id)))
            .collect();
        ids.sort_unstable();
        ids.dedup();
        ids
    };
    if v.fract() == 0.0 && v.abs() <= f64::from(i32::MAX) && ids.contains(&(v as i32)) {
        return Ok(v as i32);
    }
    let list: Vec<String> = ids.iter().map(i32::to_string).collect();
    Err(step.error(
        LANE,
        WorldFileErrorKind::InvalidValue(format!(
            "{}: no road of the world has this lane (lanes: {}; −1, −2, … right of the \
             reference line, 1, 2, … left)",
            Compact(v),
            list.join(", ")
        )),
    ))
}
