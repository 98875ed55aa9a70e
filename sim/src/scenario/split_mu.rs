//! `split-mu`: straight-line braking with the right wheels on a low-friction strip and the
//! left ones on the ground (ISO 14512's split-μ straight-line braking, steering held
//! straight).

use proto_geom::nalgebra::{Point3, Vector3};

use crate::config::Obstacle;
use crate::placement::heading_of_rotation;
use crate::world_file::{CarDescription, WorldDescription};

use super::car::{CarRig, KMH};
use super::car_programmes::{Progress, STOPPED};
use super::{Metric, Scenario, ScenarioError, ScenarioResult, limit};

/// Speed at which braking starts (km/h).
const SPEED_KMH: f64 = 80.0;
/// Friction of the low-μ strip (dimensionless): wet ice to packed snow's 0.1–0.3, the low
/// side of split-μ tests; the high side is the world's ground.
const LOW_FRICTION: f64 = 0.3;
/// Height of the strip's top over the ground (m): a painted surface, thin enough that the
/// right wheels stand 2 mm higher, a roll of under 0.1°.
const STRIP_HEIGHT: f64 = 0.002;
/// Width of the strip (m), from the car's centre line to the right.
const STRIP_WIDTH: f64 = 6.0;
/// Length of the strip (m), from 20 m behind the car's start: the run-up to 80 km/h and the
/// stop.
const STRIP_LENGTH: f64 = 1000.0;
/// Look-ahead of the run-up's line-keeping driver (m): pure pursuit on the start line.
const RUN_UP_LOOKAHEAD: f64 = 8.0;
/// Integral gain of the run-up's driver (rad per m·s): removes a steady offset in a few
/// seconds without oscillating at the pure pursuit's bandwidth.
const RUN_UP_INTEGRAL_GAIN: f64 = 0.002;
/// How close to 80 km/h the speed must stay for a second before braking (km/h): the tyres'
/// slip keeps the car a few tenths below the cruise control's target.
const STEADY_KMH: f64 = 1.0;

/// `world` with the low-friction strip under the right wheels of `car` from its start pose.
fn split_world(world: &WorldDescription, car: &CarDescription) -> WorldDescription {
    let mut world = world.clone();
    let [x, y, _] = car.params.translation;
    let yaw = heading_of_rotation(car.params.rotation);
    let (s, c) = yaw.sin_cos();
    let along = 0.5 * STRIP_LENGTH - 20.0;
    let right = 0.5 * STRIP_WIDTH;
    world.config.obstacles.push(Obstacle::Box {
        center: Point3::new(
            x + along * c + right * s,
            y + along * s - right * c,
            0.5 * STRIP_HEIGHT,
        ),
        half_extents: Vector3::new(0.5 * STRIP_LENGTH, 0.5 * STRIP_WIDTH, 0.5 * STRIP_HEIGHT),
        yaw,
        friction: Some(LOW_FRICTION),
        radar_cross_section: 0.0,
    });
    world
}

/// Cruises to 80 km/h on the split surface, then brakes fully with the steering straight.
pub(super) fn run(
    world: &WorldDescription,
    car: &CarDescription,
    progress: Progress<'_>,
) -> Result<ScenarioResult, ScenarioError> {
    let world = split_world(world, car);
    let expected = 2.0 * car.params.time_0_to_100 + 10.0;
    let mut rig = CarRig::new(&world, car, limit(Scenario::SplitMu, &world), expected)?;
    let v = SPEED_KMH / KMH;
    // The run-up's drive is split too: a driver keeps the car on its start line, so that it
    // brakes with its right wheels on the strip.
    let wheelbase = car.params.wheelbase;
    let (start, yaw_start) = (rig.state().position, rig.yaw());
    rig.driver_mut()?.set_cruising_speed(SPEED_KMH);
    let mut steady_since = None;
    // The integral of the offset (m·s): the drive pulls harder on the left, high-friction
    // side, a steady yaw moment that pure pursuit alone holds only with an offset.
    let mut offset_integral = 0.0;
    while rig.running() && rig.time() < expected {
        let p = rig.state().position;
        let lateral = -(p.x - start.x) * yaw_start.sin() + (p.y - start.y) * yaw_start.cos();
        offset_integral += lateral * rig.time_step();
        let alpha = (-lateral).atan2(RUN_UP_LOOKAHEAD) - (rig.yaw() - yaw_start);
        let steer = (2.0 * wheelbase * alpha.sin() / RUN_UP_LOOKAHEAD.hypot(lateral)).atan()
            - RUN_UP_INTEGRAL_GAIN * offset_integral;
        rig.driver_mut()?.set_steering_angle(-steer);
        rig.step(progress)?;
        if (rig.speed() - v).abs() * KMH < STEADY_KMH {
            let since = *steady_since.get_or_insert(rig.time());
            if rig.time() - since >= 1.0 {
                break;
            }
        } else {
            steady_since = None;
        }
    }
    // ISO 14512's fixed-steering variant: straight ahead from the start of braking.
    rig.driver_mut()?.set_steering_angle(0.0);
    let (t0, v0, yaw0, p0) = (rig.time(), rig.speed(), rig.yaw(), rig.state().position);
    let offset = -(p0.x - start.x) * yaw_start.sin() + (p0.y - start.y) * yaw_start.cos();
    rig.driver_mut()?.set_throttle(0.0);
    rig.driver_mut()?.set_brake_intensity(1.0);
    let mut stopped = None;
    let mut travelled = 0.0;
    let mut last = p0;
    while rig.running() && stopped.is_none() {
        rig.step(progress)?;
        let p = rig.state().position;
        travelled += (p.x - last.x).hypot(p.y - last.y);
        last = p;
        let velocity = rig.state().velocity;
        if velocity.x.hypot(velocity.y) < STOPPED {
            stopped = Some((rig.time() - t0, travelled));
        }
    }
    let heading = (rig.yaw() - yaw0 + core::f64::consts::PI).rem_euclid(core::f64::consts::TAU)
        - core::f64::consts::PI;
    let p = rig.state().position;
    let lateral = -(p.x - p0.x) * yaw0.sin() + (p.y - p0.y) * yaw0.cos();
    let metrics = vec![
        Metric::number(
            "initial_speed_kmh",
            "speed when braking started",
            "km/h",
            v0 * KMH,
        ),
        Metric::maybe(
            "stop_distance_m",
            "stopping distance",
            "m",
            stopped.map(|s| s.1),
        ),
        Metric::maybe("stop_time_s", "stopping time", "s", stopped.map(|s| s.0)),
        Metric::number(
            "heading_change_rad",
            "heading change (left positive)",
            "rad",
            heading,
        ),
        Metric::number(
            "lateral_deviation_m",
            "lateral deviation (left positive)",
            "m",
            lateral,
        ),
        Metric::number(
            "offset_at_braking_m",
            "car origin left of the strip's edge when braking started",
            "m",
            offset,
        ),
        Metric::number(
            "low_friction",
            "friction of the right-hand strip",
            "",
            LOW_FRICTION,
        ),
    ];
    let mut result = rig.finish(Scenario::SplitMu, metrics);
    if stopped.is_none() {
        result.unfinished = Some("the car had not stopped when the run ended".to_string());
    }
    Ok(result)
}
