//! `iso-3888`: the ISO 3888-2 obstacle-avoidance (severe) lane change, its cone layout set for
//! the car's width; pass/fail (no cone hit) and the entry speed.
//!
//! The track (ISO 3888-2:2011, table 1; 61 m long): section 1, 12 m long and `1.1·w + 0.25` m
//! wide; section 2, a 13.5 m transition; section 3, 11 m long and `w + 1` m wide, its right
//! edge 1 m to the left of section 1's left edge; section 4, a 12.5 m transition; section 5,
//! 12 m long and `1.3·w + 0.25` m wide (at least 3 m), its right edge on section 1's. `w` is
//! the car's width, taken as the wider track plus a tyre's width, as in `lane-change`.

use core::f64::consts::PI;

use proto_geom::nalgebra::Point3;

use super::car::{CarRig, KMH};
use super::car_programmes::{Progress, steady};
use super::lane::LaneSection;
use super::lane_change::{
    CONE_BASE_RADIUS, MIN_LOOKAHEAD, PREVIEW_TIME, car_width, cone_layout, hits_cone,
};
use super::{Metric, Scenario, ScenarioError, ScenarioResult};

/// Lengths of the five sections (m).
const SECTIONS: [f64; 5] = [12.0, 13.5, 11.0, 12.5, 12.0];
/// Entry speed (km/h): the car is driven at it, then the throttle is released at the entry.
const ENTRY_SPEED_KMH: f64 = 60.0;
/// Longest look-ahead of the driver (m): the lanes are 11–12 m long, a longer look-ahead
/// cuts them.
const MAX_LOOKAHEAD: f64 = 12.0;
/// Distance driven after the speed settles before the entry (m).
const RUN_IN: f64 = 20.0;

/// The three lanes of ISO 3888-2 for a car `width` (m) wide, in the track frame (x from the
/// entry, y to the left of the entry lane's centre).
pub fn obstacle_avoidance(width: f64) -> [LaneSection; 3] {
    let [s1, s2, s3, s4, s5] = SECTIONS;
    let w1 = 1.1 * width + 0.25;
    let w3 = width + 1.0;
    let w5 = (1.3 * width + 0.25).max(3.0);
    [
        LaneSection {
            start: 0.0,
            end: s1,
            center: 0.0,
            width: w1,
        },
        LaneSection {
            start: s1 + s2,
            end: s1 + s2 + s3,
            center: 0.5 * w1 + 1.0 + 0.5 * w3,
            width: w3,
        },
        LaneSection {
            start: s1 + s2 + s3 + s4,
            end: s1 + s2 + s3 + s4 + s5,
            center: -0.5 * w1 + 0.5 * w5,
            width: w5,
        },
    ]
}

/// The track's length (m).
const TRACK_LENGTH: f64 = SECTIONS[0] + SECTIONS[1] + SECTIONS[2] + SECTIONS[3] + SECTIONS[4];

/// The driver's path: the lane centres joined by half-cosines over the transitions.
fn reference_y(x: f64, lanes: &[LaneSection; 3]) -> f64 {
    let blend = |u: f64| 0.5 * (1.0 - (PI * u.clamp(0.0, 1.0)).cos());
    let [a, b, c] = lanes;
    if x < b.start {
        a.center + (b.center - a.center) * blend((x - a.end) / (b.start - a.end))
    } else {
        b.center + (c.center - b.center) * blend((x - b.end) / (c.start - b.end))
    }
}

/// Drives the car through the track entered at 60 km/h.
pub(super) fn run(
    mut rig: CarRig,
    progress: Progress<'_>,
) -> Result<ScenarioResult, ScenarioError> {
    let p = rig.driver()?.params();
    let wheelbase = p.wheelbase;
    let width = car_width(p);
    let lanes = obstacle_avoidance(width);
    let origin = rig.state().position;
    let yaw0 = rig.yaw();
    let (s, c) = yaw0.sin_cos();
    let to_track = |p: Point3<f64>| {
        let (dx, dy) = (p.x - origin.x, p.y - origin.y);
        [c * dx + s * dy, -s * dx + c * dy]
    };
    let v = ENTRY_SPEED_KMH / KMH;
    let lookahead = (PREVIEW_TIME * v).clamp(MIN_LOOKAHEAD, MAX_LOOKAHEAD);
    rig.driver_mut()?.set_cruising_speed(ENTRY_SPEED_KMH);
    let cones = cone_layout(&lanes, CONE_BASE_RADIUS);
    let mut hit = vec![false; cones.len()];
    let mut entry: Option<f64> = None;
    let mut entry_speed = None;
    let mut exit_speed = None;
    while rig.running() && exit_speed.is_none() {
        let [x, y] = to_track(rig.state().position);
        let yaw = rig.yaw() - yaw0;
        let e = entry.unwrap_or(f64::INFINITY);
        let target_x = x + lookahead;
        let target_y = if target_x - e < 0.0 {
            0.0
        } else {
            reference_y(target_x - e, &lanes)
        };
        let alpha = (target_y - y).atan2(target_x - x) - yaw;
        let steer = (2.0 * wheelbase * alpha.sin() / (target_x - x).hypot(target_y - y)).atan();
        rig.driver_mut()?.set_steering_angle(-steer);
        rig.step(progress)?;
        let [x, y] = to_track(rig.state().position);
        let yaw = rig.yaw() - yaw0;
        match entry {
            None => {
                if steady(&rig, v) {
                    entry = Some(x + RUN_IN);
                }
            }
            Some(e) if x >= e => {
                if entry_speed.is_none() {
                    entry_speed = Some(rig.speed());
                    rig.driver_mut()?.set_throttle(0.0);
                }
                for (cone, hit) in cones.iter().zip(&mut hit) {
                    *hit |= hits_cone(*cone, x - e, y, yaw, wheelbase, width);
                }
                if x - e >= TRACK_LENGTH {
                    exit_speed = Some(rig.speed());
                }
            }
            Some(_) => {}
        }
    }
    if let Some(e) = entry {
        let to_world = |x: f64, y: f64| {
            [
                origin.x + c * (x + e) - s * y,
                origin.y + s * (x + e) + c * y,
            ]
        };
        for g in &lanes {
            for side in [-0.5, 0.5] {
                let y = g.center + side * g.width;
                rig.guide(vec![to_world(g.start, y), to_world(g.end, y)]);
            }
        }
        for [x, y] in cone_layout(&lanes, 0.0) {
            rig.cone(to_world(x, y));
        }
    }
    let cones_hit = hit.iter().filter(|&&h| h).count();
    let completed = exit_speed.is_some();
    let metrics = vec![
        Metric::maybe(
            "entry_speed_kmh",
            "speed at the entry",
            "km/h",
            entry_speed.map(|v| v * KMH),
        ),
        Metric::maybe(
            "exit_speed_kmh",
            "speed at the exit",
            "km/h",
            exit_speed.map(|v| v * KMH),
        ),
        Metric::maybe_flag(
            "passed",
            "through without hitting a cone",
            completed.then_some(cones_hit == 0),
        ),
        Metric::number("cones_hit", "cones hit", "", cones_hit as f64),
        Metric::number(
            "vehicle_width_m",
            "car width the cones are set for",
            "m",
            width,
        ),
    ];
    let end = rig.time();
    let mut result = rig.finish(Scenario::Iso3888, metrics);
    if !completed {
        result.unfinished = Some(format!(
            "the car did not reach the track's exit before the run ended at {:.1} s",
            end
        ));
    }
    Ok(result)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_for_a_car_width() {
        // w = 1.8 m: 2.23 m, 2.8 m and 2.59 m → 3 m wide lanes; 61 m long.
        let [a, b, c] = obstacle_avoidance(1.8);
        assert!((a.width - 2.23).abs() < 1e-12 && (b.width - 2.8).abs() < 1e-12);
        assert!((c.width - 3.0).abs() < 1e-12);
        assert_eq!(TRACK_LENGTH, 61.0);
        assert_eq!((b.start, b.end, c.start, c.end), (25.5, 36.5, 49.0, 61.0));
        // Lane 3's right edge 1 m left of lane 1's left edge; lane 5's right edge on lane 1's.
        assert!(((b.center - 0.5 * b.width) - (a.center + 0.5 * a.width) - 1.0).abs() < 1e-12);
        assert!(((c.center - 0.5 * c.width) - (a.center - 0.5 * a.width)).abs() < 1e-12);
        // The path runs through each lane's centre.
        for g in [a, b, c] {
            assert!((reference_y(0.5 * (g.start + g.end), &[a, b, c]) - g.center).abs() < 1e-12);
        }
    }
}
