//! The car scenarios: each drives a fresh car through the driver library and measures it.

use proto_geom::nalgebra::Point3;
use vehicle_model::{AutoShiftParams, Driver, TyreModel, Wheel, axle_brake_factor};

use crate::vehicle::VehicleSpec;

use crate::world_file::{CarDescription, WorldDescription};

use super::car::{CarRig, KMH};
use super::{Metric, Scenario, ScenarioError, ScenarioResult, fit_circle, limit};
use super::{drive_cycles, iso_3888, lane_change, manoeuvres, split_mu};

/// 100 km/h in m/s.
const V100: f64 = 100.0 / KMH;
/// How far below 100 km/h the cruise-control scenario counts 100 km/h as reached (km/h): a
/// tyre that transmits a drive force creeps, so a car whose wheels turn at exactly 100 km/h
/// settles a few tenths of a km/h below it and would never cross 100.
const CRUISE_TOLERANCE_KMH: f64 = 1.0;
/// The car counts as stopped below this ground speed (m/s): the brake and split-μ scenarios'.
pub(super) const STOPPED: f64 = 0.01;
/// Largest drift (m) over the half second before the end of the brake scenario for the car
/// to count as at rest: 2 cm/s on average.
const REST_DRIFT: f64 = 0.01;
/// Steering angle of the circle scenario (rad, to the right).
const CIRCLE_STEERING: f64 = 0.2;
/// Speed of the circle scenario (km/h).
const CIRCLE_SPEED_KMH: f64 = 10.0;
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
        Scenario::LaneChange => (lane_change::run, 0.6 * t0100 + 12.0),
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
