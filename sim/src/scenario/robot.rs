//! The DifferentialWheels scenarios, driven through `wb_differential_wheels_set_speed`.

use core::f64::consts::{FRAC_PI_2, TAU};

use crate::diff_wheels::RobotId;
use crate::replay::Recorder;
use crate::telemetry::{Sample, Telemetry, VehicleKind};
use crate::world::World;
use crate::world_file::{RobotDescription, WorldDescription};

use super::{Metric, Scenario, ScenarioError, ScenarioResult, limit, motion_metrics};

/// Fraction of `maxSpeed` the scenarios drive the wheels at.
const SPEED_FRACTION: f64 = 0.5;
/// Side of the square, in axle lengths.
const SQUARE_SIDE_AXLES: f64 = 10.0;

struct RobotRig {
    world: World,
    id: RobotId,
    name: String,
    samples: Vec<Sample>,
    recorder: Recorder,
    limit: f64,
    expected: f64,
    next_progress: f64,
}

impl RobotRig {
    fn new(
        desc: &WorldDescription,
        robot: &RobotDescription,
        limit: f64,
    ) -> Result<Self, ScenarioError> {
        let mut world = World::new(desc.config.clone())?;
        let id = world.add_differential_wheels(robot.params, robot.mode, robot.placement)?;
        let samples = vec![Sample::of_robot(&world, id)?];
        Ok(RobotRig {
            recorder: Recorder::for_world(&world).with_robot_names([robot.name.clone()]),
            world,
            id,
            name: robot.name.clone(),
            samples,
            limit,
            expected: limit,
            next_progress: 0.0,
        })
    }

    fn time(&self) -> f64 {
        self.world.time()
    }

    /// `wb_differential_wheels_set_speed(left, right)` with speeds in rad/s.
    fn set_wheel_speeds(&mut self, left: f64, right: f64) -> Result<(), ScenarioError> {
        let robot = self.world.robot_mut(self.id)?;
        let unit = robot.speed_unit();
        // The speeds stay within maxSpeed, so no overflow warning can arise.
        let _ = robot.set_speed(left / unit, right / unit);
        Ok(())
    }

    /// Runs `steps` world steps, stopping early at the time limit.
    fn run_steps(
        &mut self,
        steps: u64,
        progress: &mut dyn FnMut(f64, f64),
    ) -> Result<(), ScenarioError> {
        for _ in 0..steps {
            if self.time() >= self.limit - 1e-9 {
                break;
            }
            self.world.step()?;
            self.recorder.sample(&self.world);
            self.samples.push(Sample::of_robot(&self.world, self.id)?);
            if self.time() >= self.next_progress {
                progress(self.time(), self.expected);
                self.next_progress = self.time() + 0.5;
            }
        }
        Ok(())
    }

    /// Turns the left and right wheels by `angles` (rad) at up to `omega` (rad/s), then
    /// stops them.
    ///
    /// Open loop, yet exact without noise: the command lasts a whole number of steps at the
    /// speed that turns the wheels by exactly the angle in that time, and that speed is low
    /// enough for the wheels to reach it within the command (at most √(angle·maxAcceleration)),
    /// so that the ramp down after the command gains, step for step, what the ramp up lost.
    /// The pause lets the ramp down finish.
    fn turn_wheels(
        &mut self,
        angles: [f64; 2],
        omega: f64,
        progress: &mut dyn FnMut(f64, f64),
    ) -> Result<(), ScenarioError> {
        let dt = self.world.dt();
        let accel = self.world.robot(self.id)?.params().max_acceleration;
        let angle = angles[0].abs().max(angles[1].abs());
        if angle.is_nan() || angle <= 0.0 {
            return Ok(());
        }
        let speed = omega.min((angle * accel).sqrt());
        let steps = (angle / speed / dt - 1e-9).ceil().max(1.0);
        let scale = 1.0 / (steps * dt);
        self.set_wheel_speeds(angles[0] * scale, angles[1] * scale)?;
        self.run_steps(steps as u64, progress)?;
        self.set_wheel_speeds(0.0, 0.0)?;
        self.run_steps((speed / accel / dt).ceil() as u64 + 1, progress)
    }

    fn finish(
        self,
        scenario: Scenario,
        mut metrics: Vec<Metric>,
    ) -> Result<ScenarioResult, ScenarioError> {
        let telemetry = Telemetry {
            scenario: scenario.name().to_string(),
            vehicle: self.name,
            kind: VehicleKind::Robot,
            samples: self.samples,
        };
        metrics.extend(motion_metrics(&telemetry));
        Ok(ScenarioResult {
            name: scenario.name().to_string(),
            metrics,
            sim_seconds: self.world.time(),
            telemetry: vec![telemetry],
            replay: self.recorder.finish(&self.world),
            ..ScenarioResult::default()
        })
    }
}

/// Runs the single robot scenario `scenario` on a fresh world.
pub(crate) fn run(
    world: &WorldDescription,
    robot: &RobotDescription,
    scenario: Scenario,
    progress: &mut dyn FnMut(f64, f64),
) -> Result<ScenarioResult, ScenarioError> {
    let mut rig = RobotRig::new(world, robot, limit(scenario, world))?;
    let p = robot.params;
    let omega = SPEED_FRACTION * p.max_speed;
    let ramp = omega / p.max_acceleration;
    let start = robot.placement;
    let dt = world.config.dt();
    match scenario {
        Scenario::Spin => {
            let duration = rig.limit;
            rig.expected = duration;
            rig.set_wheel_speeds(-omega, omega)?;
            rig.run_steps((duration / dt).round() as u64, progress)?;
            let turned = rig.world.robot(rig.id)?.pose().heading - start.heading;
            let yaw_rate = 2.0 * omega * p.wheel_radius / p.axle_length;
            let drift = {
                let q = rig.world.robot(rig.id)?.pose().position;
                (q.x - start.x).hypot(q.y - start.y)
            };
            // The wheels ramp up from rest: half a ramp's worth of turning is lost.
            let expected_turns = yaw_rate * (rig.time() - ramp / 2.0) / TAU;
            let metrics = vec![
                Metric::number("turns", "turns made", "", turned / TAU),
                Metric::number("turns_expected", "turns without noise", "", expected_turns),
                Metric::number("position_drift_m", "drift of the axle midpoint", "m", drift),
            ];
            rig.finish(Scenario::Spin, metrics)
        }
        Scenario::AccelSpeed
        | Scenario::AccelTorque
        | Scenario::Brake
        | Scenario::Circle
        | Scenario::LaneChange
        | Scenario::StepSteer
        | Scenario::ConstantRadius
        | Scenario::SineWithDwell
        | Scenario::SplitMu
        | Scenario::Iso3888
        | Scenario::TestTrack
        | Scenario::Ftp75
        | Scenario::Hwfet
        | Scenario::Wltc
        | Scenario::Programme => Err(ScenarioError::WrongVehicle {
            scenario,
            vehicle: world.vehicles_label(),
        }),
        Scenario::Square => {
            let side = SQUARE_SIDE_AXLES * p.axle_length;
            let straight = side / p.wheel_radius;
            let turn = FRAC_PI_2 * p.axle_length / (2.0 * p.wheel_radius);
            rig.expected = 4.0 * (straight + turn) / omega + 8.0 * ramp;
            for _ in 0..4 {
                rig.turn_wheels([straight, straight], omega, progress)?;
                rig.turn_wheels([-turn, turn], omega, progress)?;
            }
            let pose = rig.world.robot(rig.id)?.pose();
            let closure = (pose.position.x - start.x).hypot(pose.position.y - start.y);
            let metrics = vec![
                Metric::number("side_m", "side of the square", "m", side),
                Metric::number(
                    "closure_error_m",
                    "distance from the start at the end",
                    "m",
                    closure,
                ),
            ];
            rig.finish(Scenario::Square, metrics)
        }
    }
}
