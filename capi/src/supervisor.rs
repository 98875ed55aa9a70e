//! Webots' Supervisor subset for the controller's bindings (the Python `controller.Supervisor`):
//! nodes found by DEF name, their pose and velocity read and set, their physics reset, and the
//! simulation reset. Rust functions, not C entry points: the C headers have no supervisor
//! (COMPATIBILITY.md). The placement itself is the engine's ([`sim::World`]'s supervisor
//! functions).
//!
//! DEF names: each car's `name` (as the world file or its default gives it), and
//! `body[1]`, `body[2]`, … for the world file's `[[body]]` tables in order (they have no
//! name), as the world-file messages number them.

use sim::nalgebra::{Point3, Vector3};
use sim::{Placement, SimError, VehicleId};

use crate::robot::{CONTROLLER_RUN, Controller, Robot};
use crate::session::with_robot;

/// A node a supervisor can move.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NodeRef {
    /// A car, by its index in the world.
    Car(usize),
    /// A dynamic body (`[[body]]`), by its index from 0.
    Body(usize),
}

/// The node whose DEF name is `def` (see the module docs), if any.
pub fn node_from_def(def: &str) -> Option<NodeRef> {
    with_robot(|robot| {
        let sim = &robot.simulation;
        if let Some(id) = sim
            .car_ids()
            .find(|&id| sim.car_name(id).is_ok_and(|n| n == def))
        {
            return Some(NodeRef::Car(id.index()));
        }
        let index: usize = def.strip_prefix("body[")?.strip_suffix(']')?.parse().ok()?;
        (1..=sim.world().body_count())
            .contains(&index)
            .then_some(NodeRef::Body(index - 1))
    })
}

/// The car of index `i` in `robot`'s world.
fn car(robot: &Robot, i: usize) -> Result<VehicleId, SimError> {
    robot
        .simulation
        .car_ids()
        .find(|id| id.index() == i)
        .ok_or(SimError::UnknownVehicle(i))
}

/// Where `node` is and how it moves.
///
/// # Errors
/// The [`SimError`] of a node that is no longer in the world.
pub fn placement(node: NodeRef) -> Result<Placement, SimError> {
    with_robot(|robot| match node {
        NodeRef::Car(i) => robot.simulation.world().vehicle_placement(car(robot, i)?),
        NodeRef::Body(i) => robot.simulation.world().body_placement(i),
    })
}

/// Puts `node` at `translation` (m) turned by Webots `rotation` (axis, angle in rad).
///
/// # Errors
/// [`SimError::Param`] for a value out of range (nothing moves).
pub fn set_pose(node: NodeRef, translation: [f64; 3], rotation: [f64; 4]) -> Result<(), SimError> {
    let q = sim::rotation_from_axis_angle(rotation)?;
    let at = Point3::from(translation);
    with_robot(|robot| match node {
        NodeRef::Car(i) => {
            let id = car(robot, i)?;
            robot.simulation.world_mut().set_vehicle_pose(id, &at, &q)
        }
        NodeRef::Body(i) => robot.simulation.world_mut().set_body_pose(i, &at, &q),
    })
}

/// Gives `node` the velocity `linear` (m/s) and angular velocity `angular` (rad/s), world.
///
/// # Errors
/// [`SimError::Param`] for a value out of range (nothing changes).
pub fn set_velocity(node: NodeRef, linear: [f64; 3], angular: [f64; 3]) -> Result<(), SimError> {
    let (l, a) = (Vector3::from(linear), Vector3::from(angular));
    with_robot(|robot| match node {
        NodeRef::Car(i) => {
            let id = car(robot, i)?;
            robot
                .simulation
                .world_mut()
                .set_vehicle_velocity(id, &l, &a)
        }
        NodeRef::Body(i) => robot.simulation.world_mut().set_body_velocity(i, &l, &a),
    })
}

/// Puts the world back as loaded (Webots: `wb_supervisor_simulation_reset`): time 0, every car
/// and body where the world file put it, the other cars' programmes from their start. The
/// controller goes on (as in Webots): its car's devices keep the sampling periods it gave
/// them (their next sample one period after the reset); a run recorded for `VEHICLE_OUT`
/// starts again from the reset.
///
/// # Errors
/// The engine's refusal, as text (none for a world loaded from a file).
pub fn simulation_reset() -> Result<(), String> {
    with_robot(|robot| {
        // Every controller's car (the process's one, or each car a front-end serves).
        let periods: Vec<(VehicleId, Vec<u32>)> = robot
            .controllers()
            .iter()
            .filter_map(Controller::car)
            .filter_map(|id| {
                let devices = robot.simulation.devices(id).ok()?;
                Some((id, devices.iter().map(|d| d.period_ms()).collect()))
            })
            .collect();
        let recording = robot.simulation.is_recording();
        robot
            .simulation
            .simulation_reset()
            .map_err(|e| e.to_string())?;
        // A run recorded for `VEHICLE_OUT` records on from the reset (its outputs are the
        // run since then).
        if recording {
            robot.simulation.record(CONTROLLER_RUN);
        }
        robot.simulation.disable_devices();
        for (id, ps) in periods {
            for (index, period) in ps.into_iter().enumerate() {
                if period > 0 {
                    robot
                        .simulation
                        .enable_device(id, index, period)
                        .map_err(|e| e.to_string())?;
                }
            }
        }
        robot.rewind_programmes();
        Ok(())
    })
}
