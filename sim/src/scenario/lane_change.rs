//! The `lane-change` scenario: an ISO 3888-1-like double lane change at 60 km/h between
//! cones, driven by a pure-pursuit driver; and the cone layout and hit test the ISO 3888-2
//! course shares.

use proto_geom::nalgebra::Point3;
use vehicle_model::{CarParams, IndicatorState, Wheel};

use super::car::{CarRig, KMH};
use super::car_programmes::{Progress, steady};
use super::lane::{LaneSection, TRACK_LENGTH, double_lane_change, reference_y};
use super::metrics::ACCEL_WINDOW;
use super::{Metric, Scenario, ScenarioError, ScenarioResult};

/// Speed of the lane-change scenario (km/h).
const LANE_CHANGE_SPEED_KMH: f64 = 60.0;
/// Lateral offset of the lane-change's middle lane (m, to the left).
const LANE_OFFSET: f64 = 3.5;
/// How far ahead the lane-change driver aims (s of travel). A pure-pursuit driver that aims
/// closer than about three times the car's lag between steering command and yaw (the steering
/// servo's 0.1 s and the yaw response's 0.2–0.3 s on slipping tyres: 0.8 s at least)
/// overshoots each lane and oscillates; one that aims further than about 0.9 s (15 m at
/// 60 km/h) cuts the corners of the 25–30 m lane sections. Driver models preview 0.5–1.5 s.
pub(super) const PREVIEW_TIME: f64 = 0.85;
/// Shortest look-ahead of the lane-change driver (m), at walking pace.
pub(super) const MIN_LOOKAHEAD: f64 = 4.0;
/// Longest look-ahead of the lane-change driver (m): beyond it the driver would cut the
/// 25–30 m lane sections.
const MAX_LOOKAHEAD: f64 = 25.0;
/// Largest distance between two cones along a lane edge of the lane change (m), as ISO
/// 3888-1 courses are laid out.
const CONE_SPACING: f64 = 5.0;
/// Radius of a cone's base (m): a 0.3 m square base (EN 13422 traffic cones of 0.5 m) as a
/// circle of the same half-width. A gate's width is measured between its cones' inner base
/// edges, so each cone's centre stands this far outside the lane edge, and the car hits it
/// when its footprint comes this close to the centre: when it reaches the lane edge beside a
/// cone. Crossing the edge between two cones hits nothing.
pub(super) const CONE_BASE_RADIUS: f64 = 0.15;

/// The cones of the lane change (track frame from the entry, m): both edges of every gate,
/// at both ends and at most [`CONE_SPACING`] apart between, `outset` (m) outside the edge
/// (0: on the edge, as drawn; [`CONE_BASE_RADIUS`]: the bases' centres).
pub(super) fn cone_layout(gates: &[LaneSection], outset: f64) -> Vec<[f64; 2]> {
    let mut cones = Vec::new();
    for g in gates {
        for side in [-0.5, 0.5] {
            let y = g.center + side * (g.width + 2.0 * outset);
            let n = ((g.end - g.start) / CONE_SPACING).ceil().max(1.0) as usize;
            for k in 0..=n {
                cones.push([g.start + (g.end - g.start) * k as f64 / n as f64, y]);
            }
        }
    }
    cones
}

/// True when the cone at `cone` touches the footprint of a car whose rear-axle centre is at
/// `(x, y)` heading `yaw` (rad) (all in the track frame, m): the cone's base (a disc of
/// [`CONE_BASE_RADIUS`]) meets the rectangle from the rear to the front axle, `width` wide.
pub(super) fn hits_cone(
    cone: [f64; 2],
    x: f64,
    y: f64,
    yaw: f64,
    wheelbase: f64,
    width: f64,
) -> bool {
    let (s, c) = yaw.sin_cos();
    let (dx, dy) = (cone[0] - x, cone[1] - y);
    let (along, across) = (c * dx + s * dy, -s * dx + c * dy);
    // Distance from the cone's centre to the rectangle, per axis.
    let out_along = (-along).max(along - wheelbase).max(0.0);
    let out_across = (across.abs() - 0.5 * width).max(0.0);
    out_along.hypot(out_across) <= CONE_BASE_RADIUS
}
/// Pure-pursuit steering (rad, Webots sign: positive = right) that takes the rear-axle centre
/// at `(x, y)` with heading `yaw` (track frame) towards the point `lookahead` metres ahead on
/// the reference path of a track entered at `entry` (track x).
fn pure_pursuit(x: f64, y: f64, yaw: f64, lookahead: f64, entry: f64, wheelbase: f64) -> f64 {
    let target_x = x + lookahead;
    let target_y = reference_y(target_x - entry, LANE_OFFSET);
    let alpha = (target_y - y).atan2(target_x - x) - yaw;
    let distance = (target_x - x).hypot(target_y - y);
    -(2.0 * wheelbase * alpha.sin() / distance).atan()
}

/// How far before the end of a gate the lane-change driver starts signalling towards the next
/// lane (m): about 0.6 s at 60 km/h.
const SIGNAL_AHEAD: f64 = 10.0;

/// The indicator a driver sets at `x` along the track (m from its entry): towards the next
/// gate's lane from [`SIGNAL_AHEAD`] before the end of a gate until the next gate starts, off
/// elsewhere. Lights act on nothing physical; the replay shows them.
fn lane_signal(gates: &[LaneSection], x: f64) -> IndicatorState {
    for pair in gates.windows(2) {
        let [a, b] = [pair[0], pair[1]];
        if x >= a.end - SIGNAL_AHEAD && x < b.start {
            if b.center > a.center {
                return IndicatorState::Left;
            }
            if b.center < a.center {
                return IndicatorState::Right;
            }
        }
    }
    IndicatorState::Off
}

/// A car's width over its tyres (m), the width the cone courses are laid out for: the wider
/// track plus the widest tyre.
pub(super) fn car_width(p: &CarParams<f64>) -> f64 {
    p.track_front.max(p.track_rear)
        + Wheel::ALL
            .iter()
            .map(|&w| p.wheels[w].thickness)
            .fold(0.0, f64::max)
}

pub(super) fn run(
    mut rig: CarRig,
    progress: Progress<'_>,
) -> Result<ScenarioResult, ScenarioError> {
    let p = rig.driver()?.params();
    let wheelbase = p.wheelbase;
    let width = car_width(p);
    let gates = double_lane_change(width, LANE_OFFSET);
    // The track frame: origin at the start, x along the starting heading.
    let origin = rig.state().position;
    let rig_yaw0 = rig.yaw();
    let (s, c) = (-rig_yaw0).sin_cos();
    let to_track = |p: Point3<f64>| {
        let (dx, dy) = (p.x - origin.x, p.y - origin.y);
        [c * dx - s * dy, s * dx + c * dy]
    };
    let v = LANE_CHANGE_SPEED_KMH / KMH;
    let lookahead = (PREVIEW_TIME * v).clamp(MIN_LOOKAHEAD, MAX_LOOKAHEAD);
    rig.driver_mut()?.set_cruising_speed(LANE_CHANGE_SPEED_KMH);
    // Run-in: the track starts 20 m after the speed has settled.
    let mut entry: Option<f64> = None;
    let mut max_lateral: f64 = 0.0;
    let mut max_excursion: f64 = 0.0;
    let mut max_steering: f64 = 0.0;
    let cones = cone_layout(&gates, CONE_BASE_RADIUS);
    let mut hit = vec![false; cones.len()];
    let window = (ACCEL_WINDOW / rig.time_step()).round().max(1.0) as usize;
    let mut recent: Vec<f64> = Vec::with_capacity(window);
    let mut signalled = IndicatorState::Off;
    while rig.running() {
        let [x, y] = to_track(rig.state().position);
        let yaw = rig.yaw() + s.atan2(c);
        let steering = pure_pursuit(
            x,
            y,
            yaw,
            lookahead,
            entry.unwrap_or(f64::INFINITY),
            wheelbase,
        );
        rig.driver_mut()?.set_steering_angle(steering);
        let signal = entry.map_or(IndicatorState::Off, |e| lane_signal(&gates, x - e));
        if signal != signalled {
            rig.driver_mut()?.set_indicator(signal);
            signalled = signal;
        }
        rig.step(progress)?;
        let [x, y] = to_track(rig.state().position);
        let yaw = rig.yaw() + s.atan2(c);
        match entry {
            None => {
                if steady(&rig, v) {
                    entry = Some(x + 20.0);
                }
            }
            Some(e) if x >= e => {
                if recent.len() == window {
                    recent.remove(0);
                }
                recent.push(rig.state().lateral_acceleration);
                let mean = recent.iter().sum::<f64>() / recent.len() as f64;
                max_lateral = max_lateral.max(mean.abs());
                max_steering = max_steering.max(rig.driver()?.commanded_steering_angle().abs());
                // The footprint's corners: rear and front axle, ± half the width.
                let (sy, cy) = yaw.sin_cos();
                for axle in [0.0, wheelbase] {
                    for side in [-0.5 * width, 0.5 * width] {
                        let cx = x + axle * cy - side * sy - e;
                        let cyy = y + axle * sy + side * cy;
                        for g in &gates {
                            max_excursion = max_excursion.max(g.excursion(cx, cyy));
                        }
                    }
                }
                for (cone, hit) in cones.iter().zip(&mut hit) {
                    *hit |= hits_cone(*cone, x - e, y, yaw, wheelbase, width);
                }
                if x >= e + TRACK_LENGTH + 10.0 {
                    break;
                }
            }
            Some(_) => {}
        }
    }
    if let Some(e) = entry {
        // The cone lines, back in the world frame.
        let (sw, cw) = rig_yaw0.sin_cos();
        let to_world = |x: f64, y: f64| {
            [
                origin[0] + cw * (x + e) - sw * y,
                origin[1] + sw * (x + e) + cw * y,
            ]
        };
        for g in &gates {
            for side in [-0.5, 0.5] {
                let y = g.center + side * g.width;
                rig.guide(vec![to_world(g.start, y), to_world(g.end, y)]);
            }
        }
        for [x, y] in cone_layout(&gates, 0.0) {
            rig.cone(to_world(x, y));
        }
    }
    let completed = entry.is_some_and(|e| to_track(rig.state().position)[0] >= e + TRACK_LENGTH);
    let unfinished = (!completed).then(|| {
        let where_ = match entry {
            None => "before the speed had settled for the track's entry".to_string(),
            Some(e) => format!(
                "{:.0} m into the {:.0} m track",
                (to_track(rig.state().position)[0] - e).max(0.0),
                TRACK_LENGTH
            ),
        };
        format!(
            "the car did not complete the lane-change track: the run ended at {:.1} s, {where_}",
            rig.time()
        )
    });
    let cones_hit = hit.iter().filter(|&&h| h).count();
    let metrics = vec![
        Metric::maybe(
            "max_lateral_accel_mps2",
            "peak lateral acceleration (0.1 s mean)",
            "m/s^2",
            completed.then_some(max_lateral),
        ),
        Metric::maybe_flag(
            "left_track",
            "hit a cone (left the lanes)",
            completed.then_some(cones_hit > 0),
        ),
        Metric::maybe(
            "cones_hit",
            "cones hit",
            "",
            completed.then_some(cones_hit as f64),
        ),
        Metric::maybe(
            "max_lane_excursion_m",
            "largest excursion past the cones",
            "m",
            completed.then_some(max_excursion),
        ),
        Metric::maybe(
            "max_steering_rad",
            "largest steering angle",
            "rad",
            completed.then_some(max_steering),
        ),
    ];
    let mut result = rig.finish(Scenario::LaneChange, metrics);
    result.unfinished = unfinished;
    Ok(result)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cone_is_hit_when_the_footprint_reaches_its_base() {
        // A 2 m wide car, 3 m between the axles, its rear axle at the origin heading +x.
        let hit = |cone: [f64; 2], yaw: f64| hits_cone(cone, 0.0, 0.0, yaw, 3.0, 2.0);
        let r = CONE_BASE_RADIUS;
        // Beside the car: touching at 1 m + r from the centre line, clear 1 cm further.
        assert!(hit([1.5, 1.0 + r], 0.0));
        assert!(!hit([1.5, 1.01 + r], 0.0));
        // Ahead of the front axle and behind the rear one.
        assert!(hit([3.0 + r, 0.0], 0.0) && !hit([3.01 + r, 0.0], 0.0));
        assert!(hit([-r, 0.5], 0.0) && !hit([-0.01 - r, 0.5], 0.0));
        // Off a corner: the base is round (0.1 m along and across is 0.141 m away).
        assert!(hit([3.1, 1.1], 0.0) && !hit([3.11, 1.11], 0.0));
        // Turned a quarter left, the car's front is +y.
        let quarter = core::f64::consts::FRAC_PI_2;
        assert!(hit([0.0, 3.0 + r - 1e-9], quarter) && !hit([1.5, 1.5], quarter));
        // The bases' centres stand r outside each gate's edges.
        let gates = double_lane_change(2.0, 3.5);
        let on_edge = cone_layout(&gates, 0.0);
        let centres = cone_layout(&gates, r);
        assert_eq!(on_edge.len(), centres.len());
        for (e, c) in on_edge.iter().zip(&centres) {
            assert_eq!(e[0], c[0]);
            assert!(((c[1] - e[1]).abs() - r).abs() < 1e-12);
        }
    }
}
