//! The standard handling manoeuvres as car scenarios: ISO 7401 step steer (`step-steer`),
//! ISO 4138 steady-state circular driving on a constant radius (`constant-radius`) and FMVSS
//! 126 sine with dwell (`sine-with-dwell`). Each drives the car through the driver library
//! as the other car scenarios do; the metrics come from [`super::manoeuvre_metrics`].
//!
//! The steering input is the road-wheel angle the driver library commands (Webots has no
//! steering wheel): where a standard gives a steering-wheel rate, it is divided by a 16:1
//! steering ratio, a passenger car's.

use core::f64::consts::PI;

use super::car::{CarRig, KMH};
use super::car_programmes::{Progress, cruise_until_steady};
use super::manoeuvre_metrics::{StepResponse, sine_with_dwell, step_response, understeer_gradient};
use super::{Metric, Scenario, ScenarioError, ScenarioResult};

/// Test speed of the step steer and the sine with dwell (km/h): ISO 7401's 80 km/h, FMVSS
/// 126's 80 ± 2 km/h.
const TEST_SPEED_KMH: f64 = 80.0;
/// Steady lateral acceleration the step steer's amplitude is set for (m/s²), ISO 7401's.
const STEP_LATERAL_ACCEL: f64 = 4.0;
/// Time the step steer ramps the steering (s): ISO 7401 asks for 200–500 °/s at the steering
/// wheel, under 0.1 s for the amplitudes of 4 m/s².
const STEP_RAMP: f64 = 0.1;
/// How long the step is held after it (s), the last second being the steady state.
const STEP_HOLD: f64 = 4.0;
/// Window of the steady state (s).
const STEADY_WINDOW: f64 = 1.0;
/// Rate of the slowly increasing steer (rad/s of road-wheel angle): FMVSS 126's 13.5 °/s at
/// the steering wheel over a 16:1 steering ratio.
const SLOW_STEER_RATE: f64 = 13.5 / 16.0 * PI / 180.0;
/// Time the car drives straight between two phases (s), for its yaw to settle.
const STRAIGHTEN: f64 = 3.0;
/// Standard gravity (m/s²), FMVSS 126's `g` for 0.3 g.
const G: f64 = 9.806_65;
/// The sine with dwell's amplitude over the steer that gives 0.3 g in the slowly increasing
/// steer: FMVSS 126's largest multiple (S7.6: 1.5 to 6.5 in steps of 0.5).
const SWD_MULTIPLE: f64 = 6.5;
/// How long the sine with dwell records after the completion of steer (s): past 1.75 s.
const SWD_AFTER: f64 = 2.5;
/// Radius of the constant-radius test (m): ISO 4138's smallest recommended radius, 40 m.
const CIRCLE_RADIUS: f64 = 40.0;
/// Lateral accelerations of the constant-radius steady states (m/s²): from 0.5 to 4 m/s², the
/// linear range ISO 4138 reads the gradient in.
const CIRCLE_ACCELS: [f64; 8] = [0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0];
/// How long each steady state of the constant-radius test is held (s), the last
/// [`STEADY_WINDOW`] averaged.
const CIRCLE_HOLD: f64 = 8.0;
/// Preview time of the circle driver (s of travel), at least [`CIRCLE_MIN_LOOKAHEAD`].
const CIRCLE_PREVIEW: f64 = 0.8;
/// Shortest look-ahead of the circle driver (m).
const CIRCLE_MIN_LOOKAHEAD: f64 = 6.0;

/// Steers `left` rad to the left (the driver library's sign is positive to the right).
fn steer_left(rig: &mut CarRig, left: f64) -> Result<(), ScenarioError> {
    rig.driver_mut()?.set_steering_angle(-left);
    Ok(())
}

/// Steps for `duration` s, calling `each` after every step.
fn drive_for(
    rig: &mut CarRig,
    duration: f64,
    progress: Progress<'_>,
    mut each: impl FnMut(&mut CarRig) -> Result<(), ScenarioError>,
) -> Result<(), ScenarioError> {
    let end = rig.time() + duration;
    while rig.running() && rig.time() < end - 1e-9 {
        rig.step(progress)?;
        each(rig)?;
    }
    Ok(())
}

/// FMVSS 126's slowly increasing steer (to the left, at [`SLOW_STEER_RATE`]) until the
/// lateral acceleration `v·r` reaches `target` (m/s²); returns that steering angle (rad), then
/// drives straight for [`STRAIGHTEN`] s. `None` if the run ended first or the car could not
/// reach `target` within 0.3 rad.
fn steer_for(
    rig: &mut CarRig,
    target: f64,
    progress: Progress<'_>,
) -> Result<Option<f64>, ScenarioError> {
    let start = rig.time();
    let mut found = None;
    while rig.running() && found.is_none() {
        let angle = SLOW_STEER_RATE * (rig.time() - start);
        if angle > 0.3 {
            break;
        }
        steer_left(rig, angle)?;
        rig.step(progress)?;
        if rig.speed() * rig.state().yaw_rate >= target {
            found = Some(angle);
        }
    }
    steer_left(rig, 0.0)?;
    drive_for(rig, STRAIGHTEN, progress, |_| Ok(()))?;
    Ok(found)
}

/// Cruises up to [`TEST_SPEED_KMH`] and finds the steer for `ay` (m/s²); `Err` with the
/// unfinished result's reason when that fails.
fn prepare(
    rig: &mut CarRig,
    ay: f64,
    progress: Progress<'_>,
) -> Result<Result<f64, String>, ScenarioError> {
    let v = TEST_SPEED_KMH / KMH;
    let run_up = 2.0 * rig.driver()?.params().time_0_to_100 + 10.0;
    cruise_until_steady(rig, v, run_up, progress)?;
    Ok(steer_for(rig, ay, progress)?.ok_or_else(|| {
        format!(
            "the slowly increasing steer did not reach {ay:.2} m/s² (within 0.3 rad, or before \
             the run ended at {:.1} s)",
            rig.time()
        )
    }))
}

/// ISO 7401 step steer at 80 km/h to the steer that gives 4 m/s² steady.
pub(super) fn step_steer(
    mut rig: CarRig,
    progress: Progress<'_>,
) -> Result<ScenarioResult, ScenarioError> {
    let amplitude = match prepare(&mut rig, STEP_LATERAL_ACCEL, progress)? {
        Ok(a) => a,
        Err(why) => {
            let metrics = step_metrics(None, None, None);
            return Ok(unfinished(rig, Scenario::StepSteer, metrics, why));
        }
    };
    let t0 = rig.time();
    let mut samples = vec![(0.0, 0.0, rig.state().yaw_rate)];
    let mut ay = Vec::new();
    drive_for(&mut rig, STEP_RAMP + STEP_HOLD, progress, |rig| {
        let t = rig.time() - t0;
        let steer = amplitude * (t / STEP_RAMP).min(1.0);
        steer_left(rig, steer)?;
        samples.push((t, steer, rig.state().yaw_rate));
        if t >= STEP_RAMP + STEP_HOLD - STEADY_WINDOW {
            ay.push(rig.speed() * rig.state().yaw_rate);
        }
        Ok(())
    })?;
    // The command is set before each step: the step's sample holds the steering it drove
    // with, the one set at its start.
    let response = step_response(&samples, STEADY_WINDOW);
    let steady_ay = (!ay.is_empty()).then(|| ay.iter().sum::<f64>() / ay.len() as f64);
    let metrics = step_metrics(Some(amplitude), response, steady_ay);
    Ok(rig.finish(Scenario::StepSteer, metrics))
}

/// The steering (rad, to the left) that takes a car at `(x, y)` heading `yaw` (rad) toward
/// the point `lookahead` m ahead on the circle of `centre` and `radius` (m), driven
/// counter-clockwise: pure pursuit.
fn circle_steer(
    x: f64,
    y: f64,
    yaw: f64,
    centre: [f64; 2],
    radius: f64,
    lookahead: f64,
    wheelbase: f64,
) -> f64 {
    let theta = (y - centre[1]).atan2(x - centre[0]) + lookahead / radius;
    let (tx, ty) = (
        centre[0] + radius * theta.cos(),
        centre[1] + radius * theta.sin(),
    );
    let alpha = (ty - y).atan2(tx - x) - yaw;
    let distance = (tx - x).hypot(ty - y);
    (2.0 * wheelbase * alpha.sin() / distance).atan()
}

/// ISO 4138 steady-state circular driving on a 40 m radius: the speed raised in steps, the
/// steering measured in each steady state, the understeer gradient the slope of steering
/// against lateral acceleration.
pub(super) fn constant_radius(
    mut rig: CarRig,
    progress: Progress<'_>,
) -> Result<ScenarioResult, ScenarioError> {
    let wheelbase = rig.driver()?.params().wheelbase;
    let p = rig.state().position;
    let yaw = rig.yaw();
    let centre = [
        p.x - CIRCLE_RADIUS * yaw.sin(),
        p.y + CIRCLE_RADIUS * yaw.cos(),
    ];
    rig.guide(
        (0..=180)
            .map(|i| {
                let a = f64::from(i) * PI / 90.0;
                [
                    centre[0] + CIRCLE_RADIUS * a.cos(),
                    centre[1] + CIRCLE_RADIUS * a.sin(),
                ]
            })
            .collect(),
    );
    let mut states = Vec::new();
    for ay in CIRCLE_ACCELS {
        let v = (ay * CIRCLE_RADIUS).sqrt();
        rig.driver_mut()?.set_cruising_speed(v * KMH);
        let start = rig.time();
        let mut window = Vec::new();
        drive_for(&mut rig, CIRCLE_HOLD, progress, |rig| {
            let s = rig.state();
            let lookahead = (CIRCLE_PREVIEW * s.forward_speed).max(CIRCLE_MIN_LOOKAHEAD);
            let steer = circle_steer(
                s.position.x,
                s.position.y,
                s.roll_pitch_yaw.yaw,
                centre,
                CIRCLE_RADIUS,
                lookahead,
                wheelbase,
            );
            if rig.time() - start >= CIRCLE_HOLD - STEADY_WINDOW {
                let (speed, r) = (s.forward_speed, s.yaw_rate);
                // The measured road-wheel angle, the mean of the front wheels (positive right).
                let steering = -0.5 * (s.steering.right + s.steering.left);
                window.push((steering, speed * r, r / speed));
            }
            steer_left(rig, steer)
        })?;
        if !rig.running() || window.is_empty() {
            break;
        }
        let n = window.len() as f64;
        states.push(window.iter().fold((0.0, 0.0, 0.0), |a, w| {
            (a.0 + w.0 / n, a.1 + w.1 / n, a.2 + w.2 / n)
        }));
    }
    let gradient = understeer_gradient(&states, wheelbase);
    let max_ay = states.iter().map(|s| s.1).fold(f64::NAN, f64::max);
    let metrics = vec![
        Metric::maybe(
            "understeer_gradient_rad_per_mps2",
            "understeer gradient dδ/da_y (road wheel)",
            "rad/(m/s²)",
            gradient,
        ),
        Metric::maybe(
            "understeer_gradient_deg_per_g",
            "understeer gradient (road wheel)",
            "°/g",
            gradient.map(|k| k.to_degrees() * G),
        ),
        Metric::number(
            "steady_states",
            "steady states measured",
            "",
            states.len() as f64,
        ),
        Metric::maybe(
            "max_lateral_accel_mps2",
            "highest steady lateral acceleration",
            "m/s²",
            Some(max_ay),
        ),
        Metric::number("radius_m", "circle radius", "m", CIRCLE_RADIUS),
    ];
    let mut result = rig.finish(Scenario::ConstantRadius, metrics);
    if states.len() < CIRCLE_ACCELS.len() {
        result.unfinished = Some(format!(
            "{} of {} steady states measured before the run ended",
            states.len(),
            CIRCLE_ACCELS.len()
        ));
    }
    Ok(result)
}

/// FMVSS 126 sine with dwell at 80 km/h, left first, at 6.5 times the steer of 0.3 g, the
/// throttle released at the beginning of steer.
pub(super) fn sine_with_dwell(
    mut rig: CarRig,
    progress: Progress<'_>,
) -> Result<ScenarioResult, ScenarioError> {
    let base = match prepare(&mut rig, 0.3 * G, progress)? {
        Ok(a) => a,
        Err(why) => {
            let metrics = swd_metrics(None, None, None);
            return Ok(unfinished(rig, Scenario::SineWithDwell, metrics, why));
        }
    };
    let amplitude = SWD_MULTIPLE * base;
    rig.driver_mut()?.set_throttle(0.0);
    let (t0, p0, yaw0) = (rig.time(), rig.state().position, rig.yaw());
    let mut yaw_rates = vec![(0.0, rig.state().yaw_rate)];
    let mut displacement = None;
    let mut previous = (0.0, 0.0);
    drive_for(
        &mut rig,
        sine_with_dwell::completion() + SWD_AFTER,
        progress,
        |rig| {
            let t = rig.time() - t0;
            let p = rig.state().position;
            // Sideways from the heading at the beginning of steer (m, left positive).
            let lateral = -(p.x - p0.x) * yaw0.sin() + (p.y - p0.y) * yaw0.cos();
            if displacement.is_none() && t >= sine_with_dwell::DISPLACEMENT_TIME {
                let (tp, lp) = previous;
                displacement = Some(
                    lp + (lateral - lp) * (sine_with_dwell::DISPLACEMENT_TIME - tp) / (t - tp),
                );
            }
            previous = (t, lateral);
            yaw_rates.push((t, rig.state().yaw_rate));
            steer_left(rig, sine_with_dwell::steering(t, amplitude))
        },
    )?;
    let ratios = sine_with_dwell::yaw_ratios(&yaw_rates);
    let metrics = swd_metrics(Some(amplitude), ratios, displacement);
    Ok(rig.finish(Scenario::SineWithDwell, metrics))
}

/// The result of a manoeuvre that could not start, with `why` and its `metrics` (unmeasured).
fn unfinished(
    rig: CarRig,
    scenario: Scenario,
    metrics: Vec<Metric>,
    why: String,
) -> ScenarioResult {
    let mut result = rig.finish(scenario, metrics);
    result.unfinished = Some(why);
    result
}

/// The step steer's metrics (the same keys whether or not the step was driven, for sweeps).
fn step_metrics(
    amplitude: Option<f64>,
    response: Option<StepResponse>,
    steady_ay: Option<f64>,
) -> Vec<Metric> {
    vec![
        Metric::maybe(
            "steer_amplitude_rad",
            "road-wheel steer of the step",
            "rad",
            amplitude,
        ),
        Metric::maybe(
            "response_time_s",
            "yaw-rate response time (50 % steer to 90 %)",
            "s",
            response.map(|r| r.response_time),
        ),
        Metric::maybe(
            "peak_response_time_s",
            "yaw-rate peak response time",
            "s",
            response.map(|r| r.peak_response_time),
        ),
        Metric::maybe(
            "overshoot_percent",
            "yaw-rate overshoot",
            "%",
            response.map(|r| 100.0 * r.overshoot),
        ),
        Metric::maybe(
            "steady_yaw_gain_per_s",
            "steady yaw-rate gain (yaw rate / road-wheel steer)",
            "1/s",
            response.map(|r| r.steady_yaw_gain),
        ),
        Metric::maybe(
            "steady_lateral_accel_mps2",
            "steady lateral acceleration v·r",
            "m/s²",
            steady_ay,
        ),
    ]
}

/// The sine with dwell's metrics (the same keys whether or not it was driven, for sweeps).
fn swd_metrics(
    amplitude: Option<f64>,
    ratios: Option<(f64, f64)>,
    displacement: Option<f64>,
) -> Vec<Metric> {
    let passes = ratios
        .zip(displacement)
        .map(|(r, d)| sine_with_dwell::passes(r, d));
    vec![
        Metric::maybe(
            "steer_amplitude_rad",
            "road-wheel amplitude (6.5 × steer of 0.3 g)",
            "rad",
            amplitude,
        ),
        Metric::maybe(
            "yaw_ratio_1_0",
            "yaw-rate ratio 1.0 s after completion of steer (≤ 0.35)",
            "",
            ratios.map(|r| r.0),
        ),
        Metric::maybe(
            "yaw_ratio_1_75",
            "yaw-rate ratio 1.75 s after completion of steer (≤ 0.20)",
            "",
            ratios.map(|r| r.1),
        ),
        Metric::maybe(
            "lateral_displacement_m",
            "lateral displacement 1.07 s after beginning of steer (≥ 1.83 m)",
            "m",
            displacement,
        ),
        Metric::maybe_flag("passes_fmvss126", "passes FMVSS 126", passes),
    ]
}
