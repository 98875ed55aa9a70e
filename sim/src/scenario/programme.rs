//! The `programme` scenario: every car of the world driven by its `[[vehicle.programme]]`
//! through the driver library, and the robot by its `[[differential_wheels.programme]]`, in
//! one world.

use crate::diff_wheels::RobotId;
use crate::lane_following::FollowStatus;
use crate::programme::{Cursor, DUE_TOLERANCE, WheelSpeeds};
use crate::simulation::Simulation;
use crate::traffic::{Traffic, TrafficNote};
use crate::vehicle::VehicleId;
use crate::world_file::WorldDescription;

use super::cycle_follow::{CycleCommand, CycleFollower, account_energy};
use super::{Metric, RunReport, Scenario, ScenarioError, ScenarioResult};

/// How long a programme runs past its last step when the world sets no `duration` (s): long
/// enough for a command to play out (a car braking from 100 km/h stops within 4 s, a cruise
/// control settles within 10 s).
pub const PROGRAMME_TAIL: f64 = 10.0;

/// Simulated time between two progress reports (s).
const PROGRESS_PERIOD: f64 = 0.5;

/// The robot and where it is in its programme.
struct RobotFollower<'w> {
    id: RobotId,
    name: &'w str,
    cursor: Cursor<'w, WheelSpeeds>,
}

/// A car's drive cycle: due at `command.at`, then followed.
struct CycleCursor<'w> {
    id: VehicleId,
    name: &'w str,
    command: &'w CycleCommand,
    follower: Option<CycleFollower>,
}

/// A car with lane-follower commands, and its follower's status at the last step, to report
/// each change once.
struct LaneStatus<'w> {
    id: VehicleId,
    name: &'w str,
    status: FollowStatus,
}

/// The simulated time the programme of `world` runs (s): the world's `duration`, else the
/// last step of any programme (or the end of a drive cycle) plus [`PROGRAMME_TAIL`].
pub(crate) fn duration(world: &WorldDescription) -> f64 {
    world.duration.unwrap_or_else(|| {
        let last = world
            .cars
            .iter()
            .map(|c| {
                let cycle_end = c.cycle.as_ref().map_or(0.0, CycleCommand::end);
                c.programme
                    .last_time()
                    .max(c.lanes.last_time())
                    .max(cycle_end)
            })
            .chain(world.robot.iter().map(|r| r.programme.last_time()))
            .fold(0.0, f64::max);
        last + PROGRAMME_TAIL
    })
}

/// The metrics of `car`'s cycle, and a note if it was cut short or never started.
fn cycle_metrics(
    sim: &Simulation,
    car: &CycleCursor<'_>,
    notes: &mut Vec<String>,
) -> Result<Vec<Metric>, ScenarioError> {
    let label = car.command.label();
    let Some(f) = &car.follower else {
        notes.push(format!(
            "{}: the run ended before {label} was due at {} s",
            car.name, car.command.at
        ));
        return Ok(Vec::new());
    };
    if !f.finished() {
        notes.push(format!(
            "{}: the run ended at {:.1} s, before the end of {label} at {} s: its metrics are \
             those of the part driven",
            car.name,
            sim.world().time(),
            car.command.end()
        ));
    }
    let engine = sim.driver(car.id)?.params().engine.engine_type;
    f.metrics(sim, car.id, engine)
}

/// Runs the programmes of `world`: the simulation of the world as described
/// ([`Simulation::from_description`]), recorded ([`Simulation::record`]), each car's
/// commands given to its driver and the robot's wheel speeds to the robot when they fall due.
pub(crate) fn run(
    world: &WorldDescription,
    progress: &mut dyn FnMut(f64, f64),
) -> Result<ScenarioResult, ScenarioError> {
    // A car that follows a cycle has its energy accounted, as in the drive-cycle scenarios.
    let mut accounted = world.clone();
    let mut notes = Vec::new();
    for car in world.cars.iter().filter(|c| c.cycle.is_some()) {
        notes.extend(account_energy(&mut accounted.cars, &car.name));
    }
    let (mut sim, _) = Simulation::from_description(&accounted)?;
    let name = Scenario::Programme.name();
    let mut cycles: Vec<CycleCursor<'_>> = world
        .cars
        .iter()
        .zip(sim.car_ids())
        .filter_map(|(c, id)| {
            c.cycle.as_ref().map(|command| CycleCursor {
                id,
                name: &c.name,
                command,
                follower: None,
            })
        })
        .collect();
    // The cars' programmes and lane commands are issued as every front-end issues a world's
    // traffic; the cycles, the robot and the lane followers' status are this scenario's own.
    let ids: Vec<VehicleId> = sim.car_ids().collect();
    let mut traffic = Traffic::every_car(world, &ids);
    let car_name = |id: VehicleId| {
        ids.iter()
            .position(|&i| i == id)
            .map_or("?", |k| world.cars[k].name.as_str())
    };
    let mut lanes: Vec<LaneStatus<'_>> = world
        .cars
        .iter()
        .zip(sim.car_ids())
        .filter(|(c, _)| !c.lanes.is_empty())
        .map(|(c, id)| LaneStatus {
            id,
            name: &c.name,
            status: FollowStatus::Following,
        })
        .collect();
    let mut robot: Option<RobotFollower<'_>> = world
        .robot
        .as_ref()
        .zip(sim.robot_ids().next())
        .map(|(r, id)| RobotFollower {
            id,
            name: &r.name,
            cursor: r.programme.cursor(),
        });
    sim.record(name);
    let end = duration(world);
    let steps = (end / sim.world().dt()).round() as u64;
    let mut next_progress = 0.0;
    for _ in 0..steps {
        let t = sim.world().time();
        for note in traffic.issue_due(&mut sim) {
            notes.push(match note {
                TrafficNote::Driver {
                    car,
                    command,
                    warning,
                } => format!("{} at {t} s, {command}: {warning}", car_name(car)),
                TrafficNote::FollowLane { car, error } => {
                    format!("{} at {t} s, follow_lane: {error}", car_name(car))
                }
            });
        }
        for car in &mut cycles {
            if car.follower.is_none() && car.command.at <= t + DUE_TOLERANCE {
                let trace = car.command.trace.clone();
                let band = car.command.band();
                let (follower, note) = CycleFollower::engage(&mut sim, car.id, trace, band)?;
                if let Some(n) = note {
                    notes.push(format!("{} at {t} s, cycle: {n}", car.name));
                }
                car.follower = Some(follower);
            }
            if let Some(f) = &mut car.follower {
                f.drive(&mut sim, car.id)?;
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
        for car in &mut cycles {
            if let Some(f) = &mut car.follower {
                f.measure(&sim, car.id)?;
            }
        }
        for car in &mut lanes {
            let status = sim
                .lane_follower(car.id)?
                .map_or(FollowStatus::Following, |f| f.status());
            if status != car.status {
                let now = sim.world().time();
                notes.push(match status {
                    FollowStatus::Following => format!("{} at {now} s: follows its lane again", car.name),
                    FollowStatus::OffRoad => format!(
                        "{} at {now} s, follow_lane: the car is off every road; it is not steered until it is back on one",
                        car.name
                    ),
                    FollowStatus::NoLane(l) => format!(
                        "{} at {now} s, follow_lane: the road under the car has no lane {l} here; it is not steered",
                        car.name
                    ),
                });
                car.status = status;
            }
        }
        let now = sim.world().time();
        if now >= next_progress {
            progress(now, end);
            next_progress = now + PROGRESS_PERIOD;
        }
    }
    let report = match sim.report(&world.source) {
        Some(r) => r.map_err(|e| ScenarioError::Record(e.to_string()))?,
        None => RunReport::default(),
    };
    let mut result = report.results.into_iter().next().unwrap_or_default();
    for car in &cycles {
        result.metrics.extend(
            cycle_metrics(&sim, car, &mut notes)?
                .into_iter()
                .map(|m| m.of(car.name)),
        );
    }
    result.devices = sim.take_device_readings();
    notes.append(&mut result.notes);
    result.notes = notes;
    Ok(result)
}
