//! The `programme` scenario: every car of the world driven by its `[[vehicle.programme]]`
//! through the driver library, and the robot by its `[[differential_wheels.programme]]`, in
//! one world.

use crate::diff_wheels::RobotId;
use crate::programme::{Cursor, DriverCommand, WheelSpeeds};
use crate::simulation::Simulation;
use crate::telemetry::{Sample, Telemetry, VehicleKind};
use crate::vehicle::VehicleId;
use crate::world::World;
use crate::world_file::WorldDescription;

use super::{Metric, Scenario, ScenarioError, ScenarioResult, motion_metrics};

/// How long a programme runs past its last step when the world sets no `duration` (s): long
/// enough for a command to play out (a car braking from 100 km/h stops within 4 s, a cruise
/// control settles within 10 s).
pub const PROGRAMME_TAIL: f64 = 10.0;

/// Simulated time between two progress reports (s).
const PROGRESS_PERIOD: f64 = 0.5;

/// A car and where it is in its programme.
struct Car<'w> {
    id: VehicleId,
    name: &'w str,
    cursor: Cursor<'w, DriverCommand>,
    samples: Vec<Sample>,
}

/// The robot and where it is in its programme.
struct Robot<'w> {
    id: RobotId,
    name: &'w str,
    cursor: Cursor<'w, WheelSpeeds>,
    samples: Vec<Sample>,
}

/// The simulated time the programme of `world` runs (s): the world's `duration`, else the
/// last step of any programme plus [`PROGRAMME_TAIL`].
pub(crate) fn duration(world: &WorldDescription) -> f64 {
    world.duration.unwrap_or_else(|| {
        let last = world
            .cars
            .iter()
            .map(|c| c.programme.last_time())
            .chain(world.robot.iter().map(|r| r.programme.last_time()))
            .fold(0.0, f64::max);
        last + PROGRAMME_TAIL
    })
}

/// Runs the programmes of `world`.
pub(crate) fn run(
    world: &WorldDescription,
    progress: &mut dyn FnMut(f64, f64),
) -> Result<ScenarioResult, ScenarioError> {
    let mut sim = Simulation::new(World::new(world.config.clone())?);
    let mut cars = Vec::with_capacity(world.cars.len());
    for c in &world.cars {
        let (id, _) = sim.add_described_car(c)?;
        cars.push(Car {
            id,
            name: &c.name,
            cursor: c.programme.cursor(),
            samples: vec![Sample::of_car(&sim, id)?],
        });
    }
    let mut robot = match &world.robot {
        Some(r) => {
            let id = sim
                .world_mut()
                .add_differential_wheels(r.params, r.mode, r.placement)?;
            Some(Robot {
                id,
                name: &r.name,
                cursor: r.programme.cursor(),
                samples: vec![Sample::of_robot(sim.world(), id)?],
            })
        }
        None => None,
    };
    let end = duration(world);
    let steps = (end / sim.world().dt()).round() as u64;
    let mut notes = Vec::new();
    let mut min_gap = f64::INFINITY;
    let mut first_touch: Option<f64> = None;
    let mut next_progress = 0.0;
    for _ in 0..steps {
        let t = sim.world().time();
        for car in &mut cars {
            for (command, warning) in car.cursor.apply_due(t, sim.driver_mut(car.id)?) {
                notes.push(format!(
                    "{} at {t} s, {}: {warning}",
                    car.name,
                    command.key()
                ));
            }
        }
        if let Some(r) = &mut robot {
            let due: Vec<WheelSpeeds> = r.cursor.due(t).map(|(_, s)| *s).collect();
            let device = sim.world_mut().robot_mut(r.id)?;
            for s in due {
                if let Some(w) = device.set_speed(s.left, s.right) {
                    notes.push(format!("{} at {t} s, speed: {w}", r.name));
                }
            }
        }
        sim.step()?;
        for car in &mut cars {
            car.samples.push(Sample::of_car(&sim, car.id)?);
        }
        if let Some(r) = &mut robot {
            r.samples.push(Sample::of_robot(sim.world(), r.id)?);
        }
        for (i, a) in cars.iter().enumerate() {
            for b in cars.iter().skip(i + 1) {
                min_gap = min_gap.min(sim.world().vehicle_gap(a.id, b.id)?);
                if first_touch.is_none() && sim.world().vehicles_in_contact(a.id, b.id)? {
                    first_touch = Some(sim.world().time());
                }
            }
        }
        let now = sim.world().time();
        if now >= next_progress {
            progress(now, end);
            next_progress = now + PROGRESS_PERIOD;
        }
    }
    let name = Scenario::Programme.name();
    let telemetry: Vec<Telemetry> = cars
        .into_iter()
        .map(|c| (c.name, VehicleKind::Car, c.samples))
        .chain(robot.map(|r| (r.name, VehicleKind::Robot, r.samples)))
        .map(|(vehicle, kind, samples)| Telemetry {
            scenario: name.to_string(),
            vehicle: vehicle.to_string(),
            kind,
            samples,
        })
        .collect();
    let mut metrics: Vec<Metric> = telemetry
        .iter()
        .flat_map(|t| motion_metrics(t).into_iter().map(|m| m.of(&t.vehicle)))
        .collect();
    if world.cars.len() > 1 {
        metrics.extend([
            Metric::maybe(
                "min_gap_m",
                "smallest gap between two cars",
                "m",
                Some(min_gap),
            ),
            Metric::flag("touched", "two cars touched", first_touch.is_some()),
            Metric::maybe("first_touch_s", "first touch", "s", first_touch),
        ]);
    }
    Ok(ScenarioResult {
        name: name.to_string(),
        metrics,
        sim_seconds: sim.world().time(),
        telemetry,
        notes,
        ..ScenarioResult::default()
    })
}
