//! The cars a front-end does not drive, running their world-file programmes: the world's
//! traffic around the car a controller (C, C++, Python, Java) or an FMU drives.
//!
//! A world with several cars is driven through one of them: the only car, or the one without a
//! programme ([`driven_car`]); every other car issues its `[[vehicle.programme]]` commands and
//! its lane follower's at their times ([`Traffic::issue_due`], called before each step). One
//! implementation for every front-end, so a world's traffic behaves the same under a C
//! controller, in an FMU and in `vehicle-sim`'s `programme` scenario (which runs every car's
//! programme: [`Traffic::every_car`]).

use vehicle_model::Warning;

use crate::lane_following::FollowCommand;
use crate::programme::Programme;
use crate::world_file::WorldDescription;
use crate::{SimError, Simulation, VehicleId};

/// Refuses a world of which a car follows a drive cycle: the controller front-ends run the
/// other cars' programmes through [`Traffic`], which has no cycle driver (only
/// `vehicle-sim`'s `programme` scenario runs it), and a cycle is never dropped silently.
///
/// # Errors
/// The first such car, as a sentence naming the world.
pub fn refuse_cycles(description: &WorldDescription) -> Result<(), String> {
    match description.cars.iter().find(|c| c.cycle.is_some()) {
        Some(car) => Err(format!(
            "cannot drive the world {}: car {} follows a drive cycle (`cycle` in its \
             programme), which only vehicle-sim's programme scenario runs",
            description.source, car.name
        )),
        None => Ok(()),
    }
}

/// Which car of `description` a front-end drives: the only car, or of several the one
/// without a programme (the others run theirs).
///
/// # Errors
/// A world without cars, with a robot beside its cars, with several cars of which not
/// exactly one has no programme, or with a car whose programme follows a drive cycle (only
/// `vehicle-sim`'s `programme` scenario runs the cycle driver), as a sentence naming the
/// world.
pub fn driven_car(description: &WorldDescription) -> Result<usize, String> {
    refuse_cycles(description)?;
    let cars = &description.cars;
    if description.robot.is_some() || cars.is_empty() {
        return Err(format!(
            "cannot drive the world {}: it holds {}, and this front-end drives exactly one car",
            description.source,
            description.vehicles_label()
        ));
    }
    if cars.len() == 1 {
        return Ok(0);
    }
    let free: Vec<usize> = (0..cars.len())
        .filter(|&i| !cars[i].has_programme())
        .collect();
    match free[..] {
        [one] => Ok(one),
        _ => Err(format!(
            "cannot drive the world {}: of its {} cars {} have no programme, and a controller \
             drives the one car without a programme (the others run theirs)",
            description.source,
            cars.len(),
            free.len()
        )),
    }
}

/// Something a programmed car's command caused.
#[derive(Debug, Clone, PartialEq)]
pub enum TrafficNote {
    /// The driver library's warning for a command (a value it clamped, …).
    Driver {
        /// The car.
        car: VehicleId,
        /// The command's world-file key, e.g. `"cruising_speed"`.
        command: &'static str,
        /// The warning.
        warning: Warning,
    },
    /// A `follow_lane` command the engine refused (a lane the road does not have, …).
    FollowLane {
        /// The car.
        car: VehicleId,
        /// Why.
        error: SimError,
    },
}

/// One programmed car and where it is in its programmes.
#[derive(Debug, Clone)]
struct Programmed {
    id: VehicleId,
    programme: Programme,
    next: usize,
    lanes: Programme<FollowCommand>,
    lanes_next: usize,
}

/// The programmed cars of a world.
#[derive(Debug, Clone, Default)]
pub struct Traffic {
    cars: Vec<Programmed>,
}

/// Where each programmed car is in its programmes, for a snapshot of the front-end.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TrafficPosition(Vec<(usize, usize)>);

impl Traffic {
    /// Every car of `description` but car `driven`, built as `ids` (the simulation's car ids
    /// in the world's order).
    pub fn new(description: &WorldDescription, ids: &[VehicleId], driven: usize) -> Traffic {
        Traffic::except(description, ids, Some(driven))
    }

    /// Every car of `description`, built as `ids`: a world no front-end drives.
    pub fn every_car(description: &WorldDescription, ids: &[VehicleId]) -> Traffic {
        Traffic::except(description, ids, None)
    }

    fn except(description: &WorldDescription, ids: &[VehicleId], driven: Option<usize>) -> Traffic {
        let cars = ids
            .iter()
            .zip(&description.cars)
            .enumerate()
            .filter(|&(i, _)| Some(i) != driven)
            .map(|(_, (&id, car))| Programmed {
                id,
                programme: car.programme.clone(),
                next: 0,
                lanes: car.lanes.clone(),
                lanes_next: 0,
            })
            .collect();
        Traffic { cars }
    }

    /// True if there is no other car.
    pub fn is_empty(&self) -> bool {
        self.cars.is_empty()
    }

    /// Takes car `id` out of the traffic: its programmes no longer run (a front-end drives
    /// it). False if it was not in the traffic.
    pub fn release(&mut self, id: VehicleId) -> bool {
        let before = self.cars.len();
        self.cars.retain(|c| c.id != id);
        self.cars.len() != before
    }

    /// Gives the programmed cars' drivers and lane followers the commands due at the
    /// simulation's time; what those commands caused, in order.
    pub fn issue_due(&mut self, simulation: &mut Simulation) -> Vec<TrafficNote> {
        let t = simulation.world().time();
        let mut notes = Vec::new();
        for car in &mut self.cars {
            let mut cursor = car.programme.cursor_at(car.next);
            if let Ok(driver) = simulation.driver_mut(car.id) {
                notes.extend(
                    cursor
                        .apply_due(t, driver)
                        .into_iter()
                        .map(|(command, warning)| TrafficNote::Driver {
                            car: car.id,
                            command: command.key(),
                            warning,
                        }),
                );
            }
            car.next = cursor.position();
            let mut lanes = car.lanes.cursor_at(car.lanes_next);
            let due: Vec<FollowCommand> = lanes.due(t).map(|(_, c)| *c).collect();
            car.lanes_next = lanes.position();
            for command in due {
                let applied = match command {
                    FollowCommand::Follow(request) => simulation.follow_lane(car.id, request),
                    FollowCommand::Stop => simulation.stop_following_lane(car.id),
                };
                if let Err(error) = applied {
                    notes.push(TrafficNote::FollowLane { car: car.id, error });
                }
            }
        }
        notes
    }

    /// Where the cars are in their programmes.
    pub fn position(&self) -> TrafficPosition {
        TrafficPosition(self.cars.iter().map(|c| (c.next, c.lanes_next)).collect())
    }

    /// Back to `position` (of this traffic); a position of other traffic is ignored car by
    /// car beyond the shorter list.
    pub fn set_position(&mut self, position: &TrafficPosition) {
        for (car, &(next, lanes_next)) in self.cars.iter_mut().zip(&position.0) {
            car.next = next;
            car.lanes_next = lanes_next;
        }
    }

    /// Back to the programmes' start, for a simulation reset to time 0.
    pub fn rewind(&mut self) {
        for car in &mut self.cars {
            car.next = 0;
            car.lanes_next = 0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::world_file;

    const TWO: &str = "[[vehicle]]\nmodel = \"BmwX5\"\nname = \"lead\"\ntranslation = [30, 0, 0.5]\n\
        [[vehicle.programme]]\nat = 0.0\ncruising_speed = 36\n\
        [[vehicle.programme]]\nat = 1.0\nsteering_angle = 0.1\n\
        [[vehicle]]\nmodel = \"BmwX5\"\nname = \"ego\"\n";

    #[test]
    fn the_car_without_a_programme_is_driven_and_the_other_runs_its_own() {
        let description = world_file::parse_str("w", TWO).unwrap();
        assert_eq!(driven_car(&description), Ok(1));
        let (mut sim, _) = Simulation::from_description(&description).unwrap();
        let ids: Vec<_> = sim.car_ids().collect();
        let mut traffic = Traffic::new(&description, &ids, 1);
        let start = traffic.position();
        let mut warnings = Vec::new();
        for _ in 0..150 {
            warnings.extend(traffic.issue_due(&mut sim));
            sim.step().unwrap();
        }
        // The lead cruises off and, from 1 s, turns right; the free car stays; the world
        // file's commands are within the driver library's ranges, so nothing warns.
        let lead = sim.telemetry(ids[0]).unwrap();
        assert!(lead.speed > 3.0 && lead.state.yaw_rate < -0.01, "{lead:?}");
        assert!(sim.telemetry(ids[1]).unwrap().speed.abs() < 0.1);
        assert_eq!(warnings, []);
        assert_ne!(traffic.position(), start);
        traffic.rewind();
        assert_eq!(traffic.position(), start);
    }

    #[test]
    fn a_released_car_runs_its_programme_no_more() {
        let description = world_file::parse_str("w", TWO).unwrap();
        let (mut sim, _) = Simulation::from_description(&description).unwrap();
        let ids: Vec<_> = sim.car_ids().collect();
        let mut traffic = Traffic::new(&description, &ids, 1);
        assert!(traffic.release(ids[0]));
        assert!(!traffic.release(ids[0]), "released twice");
        assert!(traffic.is_empty());
        for _ in 0..100 {
            assert_eq!(traffic.issue_due(&mut sim), []);
            sim.step().unwrap();
        }
        // Its 36 km/h at 0 s was never issued: the lead stands (well under the 3 m/s it
        // reaches in 1.5 s when it runs its programme, above).
        assert!(sim.telemetry(ids[0]).unwrap().speed.abs() < 0.1);
    }

    #[test]
    fn a_world_with_a_drive_cycle_is_refused_not_dropped() {
        let cycle = TWO.replace(
            "cruising_speed = 36\n",
            "cruising_speed = 36\n[[vehicle.programme]]\nat = 2\ncycle = \"udds\"\n",
        );
        let description = world_file::parse_str("w", &cycle).unwrap();
        let e = driven_car(&description).unwrap_err();
        assert!(e.contains("car lead follows a drive cycle"), "{e}");
    }

    #[test]
    fn worlds_without_one_free_car_are_refused() {
        let both = TWO.replace(
            "name = \"ego\"\n",
            "name = \"ego\"\n[[vehicle.programme]]\nat = 0\nthrottle = 1\n",
        );
        let description = world_file::parse_str("w", &both).unwrap();
        let e = driven_car(&description).unwrap_err();
        assert!(e.contains("of its 2 cars 0 have no programme"), "{e}");
    }
}
