//! The car scenarios: each drives a fresh car through the driver library and measures it.

use proto_geom::nalgebra::Point3;
use vehicle_model::{AutoShiftParams, Driver, IndicatorState, TyreModel, Wheel, axle_brake_factor};

use crate::vehicle::VehicleSpec;

use crate::world_file::{CarDescription, WorldDescription};

use super::car::{CarRig, KMH};
use super::lane::{LaneSection, TRACK_LENGTH, double_lane_change, reference_y};
use super::{Metric, Scenario, ScenarioError, ScenarioResult, fit_circle, limit};
use super::{drive_cycles, iso_3888, manoeuvres, split_mu};

/// 100 km/h in m/s.
const V100: f64 = 100.0 / KMH;
/// How far below 100 km/h the cruise-control scenario counts 100 km/h as reached (km/h): a
/// tyre that transmits a drive force creeps, so a car whose wheels turn at exactly 100 km/h
/// settles a few tenths of a km/h below it and would never cross 100.
const CRUISE_TOLERANCE_KMH: f64 = 1.0;
/// The car counts as stopped below this speed (m/s).
const STOPPED: f64 = 0.01;
/// Largest drift (m) over the half second before the end of the brake scenario for the car
/// to count as at rest: 2 cm/s on average.
const REST_DRIFT: f64 = 0.01;
/// Steering angle of the circle scenario (rad, to the right).
const CIRCLE_STEERING: f64 = 0.2;
/// Speed of the circle scenario (km/h).
const CIRCLE_SPEED_KMH: f64 = 10.0;
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
/// Window of the moving average applied to the lateral acceleration (s): the body's
/// acceleration is a finite difference of the solver's velocities, whose step-to-step jitter
/// is not a vehicle behaviour.
const ACCEL_WINDOW: f64 = 0.1;

pub(super) type Progress<'a> = &'a mut dyn FnMut(f64, f64);

/// Runs the single car scenario `scenario` on a fresh world.
pub(crate) fn run(
    world: &WorldDescription,
    car: &CarDescription,
    scenario: Scenario,
    progress: Progress<'_>,
) -> Result<ScenarioResult, ScenarioError> {
    if scenario == Scenario::SplitMu {
        // Its own world: the ground with a low-friction strip.
        return split_mu::run(world, car, progress);
    }
    if let Some(cycle) = drive_cycles::cycle_of(scenario) {
        // Its own world: the car's energy accounted.
        return drive_cycles::run(world, car, scenario, cycle, progress);
    }
    let t0100 = car.params.time_0_to_100;
    // Each programme and the simulated time it expects (s), for the progress bar;
    // `test-track` is run as its parts, and the robot programmes are not for a car.
    type Programme = fn(CarRig, Progress<'_>) -> Result<ScenarioResult, ScenarioError>;
    let (programme, expected): (Programme, f64) = match scenario {
        Scenario::AccelSpeed => (accel_speed, t0100 + 1.5),
        Scenario::AccelTorque => (accel_torque, t0100 + 1.5),
        Scenario::Brake => (brake, t0100 + 8.0),
        Scenario::Circle => (circle, 40.0),
        Scenario::LaneChange => (lane_change, 0.6 * t0100 + 12.0),
        Scenario::StepSteer => (manoeuvres::step_steer, 2.0 * t0100 + 10.0),
        Scenario::ConstantRadius => (manoeuvres::constant_radius, 70.0),
        Scenario::SineWithDwell => (manoeuvres::sine_with_dwell, 2.0 * t0100 + 12.0),
        Scenario::Iso3888 => (iso_3888::run, 0.6 * t0100 + 10.0),
        Scenario::SplitMu
        | Scenario::Ftp75
        | Scenario::Hwfet
        | Scenario::Wltc
        | Scenario::TestTrack
        | Scenario::Square
        | Scenario::Spin
        | Scenario::Programme => {
            return Err(ScenarioError::WrongVehicle {
                scenario,
                vehicle: world.vehicles_label(),
            });
        }
    };
    let rig = CarRig::new(world, car, limit(scenario, world), expected)?;
    programme(rig, progress)
}

/// The time (s) at which the speed first reached `target` (m/s), interpolated between the
/// last two samples, if it just did.
fn crossing(rig: &CarRig, target: f64) -> Option<f64> {
    let s = rig.samples();
    let (prev, now) = (s.get(s.len().checked_sub(2)?)?, s.last()?);
    let (v0, v1) = (prev.speed_kmh / KMH, now.speed_kmh / KMH);
    (v0 < target && v1 >= target)
        .then(|| prev.time + (now.time - prev.time) * (target - v0) / (v1 - v0))
}

/// Runs until the speed crosses `target` (m/s; then one more second), returning the crossing
/// time; gives up when the speed has settled below it.
fn time_to(
    rig: &mut CarRig,
    target: f64,
    progress: Progress<'_>,
) -> Result<Option<f64>, ScenarioError> {
    let mut reached = None;
    while rig.running() {
        rig.step(progress)?;
        if reached.is_none() {
            reached = crossing(rig, target);
            if reached.is_none() && steady(rig, 0.0) && rig.speed() > 1.0 {
                break;
            }
        }
        if reached.is_some_and(|t| rig.time() >= t + 1.0) {
            break;
        }
    }
    Ok(reached)
}

fn accel_speed(mut rig: CarRig, progress: Progress<'_>) -> Result<ScenarioResult, ScenarioError> {
    rig.driver_mut()?.set_cruising_speed(100.0);
    let t = time_to(&mut rig, V100 - CRUISE_TOLERANCE_KMH / KMH, progress)?;
    let nominal = rig.driver()?.params().time_0_to_100;
    let top = rig
        .samples()
        .iter()
        .map(|s| s.speed_kmh)
        .fold(0.0, f64::max);
    let metrics = vec![
        Metric::maybe(
            "time_0_100_s",
            "0-100 km/h (cruise control, 99 km/h)",
            "s",
            t,
        ),
        Metric::number(
            "time_0_100_nominal_s",
            "0-100 km/h nominal (time0To100)",
            "s",
            nominal,
        ),
        Metric::number("max_speed_kmh", "highest speed reached", "km/h", top),
    ];
    Ok(rig.finish(Scenario::AccelSpeed, metrics))
}

fn accel_torque(mut rig: CarRig, progress: Progress<'_>) -> Result<ScenarioResult, ScenarioError> {
    let auto = AutoShiftParams::for_engine(rig.driver()?.powertrain().engine());
    let refused = rig.driver_mut()?.set_automatic_gearbox(Some(auto));
    if let Err(e) = refused {
        rig.note(format!("automatic gearbox refused ({e}): first gear only"));
    }
    rig.driver_mut()?.set_gear(1);
    rig.driver_mut()?.set_throttle(1.0);
    let t = time_to(&mut rig, V100, progress)?;
    let samples = rig.samples();
    let top_gear = samples.iter().filter_map(|s| s.gear).max().unwrap_or(0);
    let max_rpm = samples.iter().filter_map(|s| s.rpm).fold(0.0, f64::max);
    let metrics = vec![
        Metric::maybe("time_0_100_s", "0-100 km/h (full throttle)", "s", t),
        Metric::number("top_gear", "highest gear engaged", "", f64::from(top_gear)),
        Metric::number("max_rpm", "highest engine speed", "rpm", max_rpm),
    ];
    Ok(rig.finish(Scenario::AccelTorque, metrics))
}

/// The deceleration (m/s²) the brakes alone give the rig's car ([`brake_deceleration`]).
pub(super) fn expected_deceleration(rig: &CarRig) -> Result<f64, ScenarioError> {
    Ok(brake_deceleration(rig.spec(), rig.driver()?, rig.ground()))
}

/// The deceleration (m/s²) the brakes alone give a car built as `spec` driven by `driver`
/// on a ground of `(friction, gravity)` (dimensionless, m/s²), limited by the grip:
/// `min(Σ T_w/r_w / m, μ·g)` with `T_w` each wheel's brake torque at intensity 1
/// (`brakeCoefficient`, times its axle's factor under a brake balance other than Webots'), `m`
/// the whole car's mass and μ the ground's friction times the slip-based tyre's longitudinal
/// peak friction (1 for Webots' contact).
pub(super) fn brake_deceleration(
    spec: &VehicleSpec,
    driver: &Driver<f64>,
    (friction, gravity): (f64, f64),
) -> f64 {
    let mass = spec.chassis.mass + Wheel::ALL.iter().map(|&w| spec.wheels[w].mass).sum::<f64>();
    let (p, share) = (driver.params(), driver.brake_front_share());
    let force: f64 = Wheel::ALL
        .iter()
        .map(|&w| p.brake_coefficient * axle_brake_factor(share, w) / p.axle_radius(w))
        .sum();
    let tyre = match spec.tyres.of(Wheel::FrontRight) {
        TyreModel::MagicFormula(t) => t.params().longitudinal.peak_friction,
        TyreModel::Webots(_) => 1.0,
    };
    (force / mass).min(friction * tyre * gravity)
}

/// True once the speed has reached 90 % of `target` (m/s) and changed by less than 0.1 km/h
/// over the last second: the cruise control has settled (the car's steady speed may differ
/// from the target by the tyres' slip).
pub(super) fn steady(rig: &CarRig, target: f64) -> bool {
    let samples = rig.samples();
    let (Some(now), Some(dt)) = (samples.last(), Some(rig.time_step())) else {
        return false;
    };
    let back = (1.0 / dt).round() as usize;
    let Some(before) = samples
        .len()
        .checked_sub(back + 1)
        .and_then(|i| samples.get(i))
    else {
        return false;
    };
    now.speed_kmh >= 0.9 * target * KMH && (now.speed_kmh - before.speed_kmh).abs() < 0.1
}

/// Cruises at `target` (m/s) until the speed is steady, for at most `max_time` (s).
pub(super) fn cruise_until_steady(
    rig: &mut CarRig,
    target: f64,
    max_time: f64,
    progress: Progress<'_>,
) -> Result<(), ScenarioError> {
    rig.driver_mut()?.set_cruising_speed(target * KMH);
    while rig.running() && rig.time() < max_time && !steady(rig, target) {
        rig.step(progress)?;
    }
    Ok(())
}

fn brake(mut rig: CarRig, progress: Progress<'_>) -> Result<ScenarioResult, ScenarioError> {
    let run_up = 2.0 * rig.driver()?.params().time_0_to_100 + 10.0;
    cruise_until_steady(&mut rig, V100, run_up, progress)?;
    if !rig.running() {
        // The run's duration ended during the run-up: nothing of the braking was measured,
        // and nothing is reported as if it had been.
        let why = format!(
            "braking never started: the run ended at {:.1} s while the car was reaching \
             {:.0} km/h (at {:.1} km/h); a longer --duration (or world duration) lets it brake",
            rig.time(),
            V100 * KMH,
            rig.speed() * KMH
        );
        let mut result = rig.finish(Scenario::Brake, brake_metrics(None));
        result.unfinished = Some(why);
        return Ok(result);
    }
    // Off the cruise control (its wheel motors would overpower the brakes), brake fully.
    rig.driver_mut()?.set_throttle(0.0);
    rig.driver_mut()?.set_brake_intensity(1.0);
    let (t0, v0, yaw0) = (rig.time(), rig.speed(), rig.yaw());
    let mut travelled = 0.0;
    let mut last = rig.state().position;
    // (time, distance) when the speed first fell below STOPPED.
    let mut stopped: Option<(f64, f64)> = None;
    // Where the car was half a second after stopping: the body still rocks on its springs
    // before that, which moves the reference point back and forth by millimetres.
    let mut settled_at: Option<Point3<f64>> = None;
    let mut at_rest = false;
    while rig.running() {
        rig.step(progress)?;
        let p = rig.state().position;
        travelled += (p.x - last.x).hypot(p.y - last.y);
        last = p;
        match stopped {
            // The ground speed, not the forward speed: a car that spins while it brakes
            // (locked rear wheels) passes through zero forward speed while sliding sideways.
            None if rig.state().velocity.x.hypot(rig.state().velocity.y) < STOPPED => {
                stopped = Some((rig.time(), travelled))
            }
            None => {}
            Some((ts, _)) => {
                if rig.time() >= ts + 0.5 {
                    let q = *settled_at.get_or_insert(p);
                    at_rest = (p.x - q.x).hypot(p.y - q.y) < REST_DRIFT;
                }
                if rig.time() >= ts + 1.0 {
                    break;
                }
            }
        }
    }
    let yaw_change = (rig.yaw() - yaw0 + core::f64::consts::PI).rem_euclid(core::f64::consts::TAU)
        - core::f64::consts::PI;
    let decel = expected_deceleration(&rig)?;
    let unfinished = stopped.is_none().then(|| {
        format!(
            "the car had not stopped when the run ended at {:.1} s ({:.1} km/h left): no \
             stopping distance or time",
            rig.time(),
            rig.speed() * KMH
        )
    });
    let braking = Braking {
        v0,
        stopped: stopped.map(|(t, d)| (t - t0, d)),
        expected: v0 * v0 / (2.0 * decel),
        yaw_change,
        at_rest: at_rest && stopped.is_some_and(|(ts, _)| rig.time() >= ts + 1.0 - 1e-9),
    };
    let mut result = rig.finish(Scenario::Brake, brake_metrics(Some(&braking)));
    result.unfinished = unfinished;
    Ok(result)
}

/// What the brake test measured once it braked.
struct Braking {
    /// Speed when braking started (m/s).
    v0: f64,
    /// Time (s) and path length (m) from braking to the stop, if the car stopped.
    stopped: Option<(f64, f64)>,
    /// Stopping distance from the brake torque, v0²/2a (m).
    expected: f64,
    /// Heading change while braking (rad).
    yaw_change: f64,
    /// At rest 1 s after stopping.
    at_rest: bool,
}

/// The brake test's metrics, every one [`Value::Missing`](super::Value::Missing) when it
/// never braked (`None`): the same keys either way, so a sweep's columns do not depend on
/// its cases.
fn brake_metrics(b: Option<&Braking>) -> Vec<Metric> {
    let stopped = b.and_then(|b| b.stopped);
    vec![
        Metric::maybe(
            "initial_speed_kmh",
            "speed when braking starts",
            "km/h",
            b.map(|b| b.v0 * KMH),
        ),
        Metric::maybe(
            "stop_distance_m",
            "stopping distance",
            "m",
            stopped.map(|(_, d)| d),
        ),
        Metric::maybe("stop_time_s", "stopping time", "s", stopped.map(|(t, _)| t)),
        Metric::maybe(
            "stop_distance_expected_m",
            "stopping distance from brake torque, v0^2/2a",
            "m",
            b.map(|b| b.expected),
        ),
        Metric::maybe(
            "yaw_change_rad",
            "heading change while braking",
            "rad",
            b.map(|b| b.yaw_change),
        ),
        Metric::maybe_flag(
            "at_rest",
            "at rest 1 s after stopping",
            b.filter(|b| b.stopped.is_some()).map(|b| b.at_rest),
        ),
    ]
}

fn circle(mut rig: CarRig, progress: Progress<'_>) -> Result<ScenarioResult, ScenarioError> {
    rig.driver_mut()?.set_steering_angle(CIRCLE_STEERING);
    rig.driver_mut()?.set_cruising_speed(CIRCLE_SPEED_KMH);
    let wheelbase = rig.driver()?.params().wheelbase;
    let expected_radius = wheelbase / CIRCLE_STEERING.tan();
    // Settle (speed ramp, steering, body roll), then record one lap of the expected circle.
    let settle = 5.0 + 0.1 * rig.driver()?.params().time_0_to_100;
    let lap = 2.0 * core::f64::consts::PI * expected_radius / (CIRCLE_SPEED_KMH / KMH);
    let end = settle + lap;
    rig.expected = end;
    let mut points = Vec::new();
    while rig.running() && rig.time() < end {
        rig.step(progress)?;
        if rig.time() >= settle {
            let p = rig.state().position;
            points.push([p.x, p.y]);
        }
    }
    let fit = fit_circle(&points);
    let radius = fit.map(|c| c.radius);
    let metrics = vec![
        Metric::maybe(
            "turn_radius_m",
            "turn radius of the rear-axle centre",
            "m",
            radius,
        ),
        Metric::number(
            "turn_radius_expected_m",
            "expected radius L/tan(delta)",
            "m",
            expected_radius,
        ),
        Metric::maybe(
            "turn_radius_error_percent",
            "radius error",
            "%",
            radius.map(|r| 100.0 * (r - expected_radius) / expected_radius),
        ),
        Metric::maybe(
            "circle_fit_rms_m",
            "circle fit RMS residual",
            "m",
            fit.map(|c| c.rms_residual),
        ),
    ];
    Ok(rig.finish(Scenario::Circle, metrics))
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

fn lane_change(mut rig: CarRig, progress: Progress<'_>) -> Result<ScenarioResult, ScenarioError> {
    let p = rig.driver()?.params();
    let wheelbase = p.wheelbase;
    let width = p.track_front.max(p.track_rear)
        + Wheel::ALL
            .iter()
            .map(|&w| p.wheels[w].thickness)
            .fold(0.0, f64::max);
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
