//! The world of the controller process, shared by every entry point of `libcar` and
//! `libdriver` (they are one shared object, so C, C++ and Python callers all see this state).
//!
//! Webots keeps one robot connection, one car and one driver per process as C globals; here
//! they live behind a mutex (entry points may be called from any thread, one at a time) and
//! every access goes through a function that checks the initialisation state first. The
//! entry points act on the world's current controller: the process's one controller, unless
//! a front-end added more with [`select`] (the project's extension, `crate::controllers`).

use std::sync::{Mutex, MutexGuard, PoisonError};

use sim::{DifferentialWheels, VehicleId, VehicleState};
use vehicle_model::Driver;

use crate::message;
use crate::robot::{Body, Libraries, Robot};

/// The loaded world and its controllers, `None` before `wb_robot_init` and after
/// `wb_robot_cleanup`.
static SESSION: Mutex<Option<Robot>> = Mutex::new(None);

/// The `wbu_driver_init()` name in "should be called before" warnings.
const DRIVER_INIT: &str = "wbu_driver_init()";

/// The `wbu_car_init()` name in "should be called before" warnings.
const CAR_INIT: &str = "wbu_car_init()";

/// Locks the session. A panic inside an entry point (caught at the boundary) may have poisoned
/// the lock; the state is still consistent enough to go on, so the poison is ignored.
fn lock() -> MutexGuard<'static, Option<Robot>> {
    SESSION.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Runs `f` on the robot, loading the world first if needed (Webots: `wb_robot_init`). A world
/// that cannot be loaded ends the process with status 1 after printing what is wrong, as
/// Webots ends a controller whose robot is invalid.
pub(crate) fn with_robot<R>(f: impl FnOnce(&mut Robot) -> R) -> R {
    let mut slot = lock();
    let robot = match &mut *slot {
        Some(robot) => robot,
        None => match Robot::from_environment(None) {
            Ok(robot) => slot.insert(robot),
            Err(problem) => {
                // One `Error: ` line per error of the world file.
                for line in problem.lines() {
                    message::error(line);
                }
                std::process::exit(1)
            }
        },
    };
    f(robot)
}

/// Loads the world named by `VEHICLE_WORLD` if no robot is loaded yet, as `wb_robot_init`
/// does, but hands back what is wrong with the world instead of ending the process: for
/// bindings (the Python package) that turn it into an exception. The world's warnings are
/// printed on stderr as `wb_robot_init` prints them. Does nothing if a robot is loaded.
///
/// # Errors
/// What is wrong with the world: one line per error of the world file, in file order, each
/// naming the file, line, key and value (the lines `wb_robot_init` prints after `Error: `).
pub fn load_world() -> Result<(), String> {
    let mut slot = lock();
    if slot.is_none() {
        *slot = Some(Robot::from_environment(None)?);
    }
    Ok(())
}

/// Makes the controller of the world's car `car` the current one (see `Robot::select`),
/// loading the world named by `VEHICLE_WORLD` for that car first if none is loaded (its
/// warnings printed as `wb_robot_init` prints them).
///
/// # Errors
/// What is wrong with the world (as [`load_world`]), or a name no car of it has.
pub(crate) fn select(car: &str) -> Result<(), String> {
    let mut slot = lock();
    match &mut *slot {
        Some(robot) => robot.select(car),
        None => {
            *slot = Some(Robot::from_environment(Some(car))?);
            Ok(())
        }
    }
}

/// Runs `f` on the loaded world, `None` if none is loaded (nothing is loaded).
pub(crate) fn with_loaded<R>(f: impl FnOnce(&Robot) -> R) -> Option<R> {
    lock().as_ref().map(f)
}

/// Frees the robot (Webots: `wb_robot_cleanup`, also reached from `wbu_car_cleanup` and
/// `wbu_driver_cleanup`); every library is uninitialised afterwards. Does nothing if no world
/// is loaded.
pub(crate) fn cleanup() {
    *lock() = None;
}

/// Initialises the car library (Webots: `wbu_car_init`): loads the world if needed, requires a
/// car (else prints Webots' error and exits with status 1) and holds its driven wheels at 0
/// rad/s. Does nothing if it is already initialised.
pub(crate) fn init_car() {
    with_robot(init_car_of);
}

/// [`init_car`] on a loaded robot; returns the car's id.
fn init_car_of(robot: &mut Robot) -> VehicleId {
    match robot.body() {
        Body::Car { id, libraries } => {
            if libraries == Libraries::None {
                robot.controller_mut().body = Body::Car {
                    id,
                    libraries: Libraries::Car,
                };
                // Webots' car library puts the driven wheels in velocity mode at 0 rad/s: the
                // car stands as if parked until a control mode is chosen. The id is the
                // simulation's own, so this cannot fail.
                let _ = robot.simulation.start_car_library(id);
            }
            id
        }
        Body::DifferentialWheels(_) => {
            message::error("Only nodes based on the 'Car' node can use the car library.");
            std::process::exit(1)
        }
    }
}

/// Initialises the driver library (Webots: `wbu_driver_init`), and the car library first.
/// Does nothing if it is already initialised.
pub(crate) fn init_driver() {
    with_robot(|robot| {
        let id = init_car_of(robot);
        robot.controller_mut().body = Body::Car {
            id,
            libraries: Libraries::Driver,
        };
    });
}

/// The robot and its car if `library` is initialised, else prints Webots' warning naming
/// `function`. Never loads the world.
fn initialised<'a>(
    slot: &'a mut Option<Robot>,
    library: Libraries,
    function: &'static str,
) -> Option<(&'a mut Robot, VehicleId)> {
    if let Some(robot) = slot
        && let Body::Car { id, libraries } = robot.body()
        && libraries >= library
    {
        return Some((robot, id));
    }
    let init = if library == Libraries::Driver {
        DRIVER_INIT
    } else {
        CAR_INIT
    };
    message::not_initialised(init, function);
    None
}

/// Runs `f` on the robot and the car if `library` is initialised; otherwise prints
/// `Warning: '<init>' should be called before to use '<function>'.` and returns `neutral`, as
/// does an `f` that finds nothing (`None`).
fn with_library<R>(
    library: Libraries,
    function: &'static str,
    neutral: R,
    f: impl FnOnce(&mut Robot, VehicleId) -> Option<R>,
) -> R {
    let mut slot = lock();
    initialised(&mut slot, library, function)
        .and_then(|(robot, id)| f(robot, id))
        .unwrap_or(neutral)
}

/// Runs `f` on the robot and the car once `wbu_driver_init()` has been called; otherwise
/// prints Webots' "should be called before" warning naming `function` and returns `neutral`.
pub(crate) fn with_driver_robot<R>(
    function: &'static str,
    neutral: R,
    f: impl FnOnce(&mut Robot, VehicleId) -> R,
) -> R {
    with_library(Libraries::Driver, function, neutral, |robot, id| {
        Some(f(robot, id))
    })
}

/// Runs `f` on the driver library's state once `wbu_driver_init()` has been called (see
/// [`with_driver_robot`]).
pub(crate) fn with_driver<R>(
    function: &'static str,
    neutral: R,
    f: impl FnOnce(&mut Driver<f64>) -> R,
) -> R {
    with_library(Libraries::Driver, function, neutral, |robot, id| {
        robot.simulation.driver_mut(id).ok().map(f)
    })
}

/// Runs `f` on the robot and the car once `wbu_car_init()` (or `wbu_driver_init()`) has been
/// called; otherwise prints Webots' "should be called before" warning naming `function` and
/// returns `neutral`.
pub(crate) fn with_car_robot<R>(
    function: &'static str,
    neutral: R,
    f: impl FnOnce(&mut Robot, VehicleId) -> R,
) -> R {
    with_library(Libraries::Car, function, neutral, |robot, id| {
        Some(f(robot, id))
    })
}

/// Runs `f` on the car library's state (the same `Driver`, which holds both libraries' state)
/// once the car library is initialised (see [`with_car_robot`]).
pub(crate) fn with_car<R>(
    function: &'static str,
    neutral: R,
    f: impl FnOnce(&mut Driver<f64>) -> R,
) -> R {
    with_library(Libraries::Car, function, neutral, |robot, id| {
        robot.simulation.driver_mut(id).ok().map(f)
    })
}

/// Runs `f` on the car's measured state (its position sensors after the last step) once the
/// car library is initialised (see [`with_car_robot`]).
pub(crate) fn with_car_state<R>(
    function: &'static str,
    neutral: R,
    f: impl FnOnce(&VehicleState) -> R,
) -> R {
    with_library(Libraries::Car, function, neutral, |robot, id| {
        robot
            .simulation
            .world()
            .vehicle(id)
            .ok()
            .map(|v| f(v.state()))
    })
}

/// Runs `f` on the DifferentialWheels robot, loading the world first if needed. In a world
/// whose robot is a car, prints an error naming `function` and returns `neutral`.
pub(crate) fn with_differential_wheels<R>(
    function: &'static str,
    neutral: R,
    f: impl FnOnce(&mut DifferentialWheels) -> R,
) -> R {
    with_robot(|robot| match robot.body() {
        Body::DifferentialWheels(id) => robot
            .simulation
            .world_mut()
            .robot_mut(id)
            .map_or(neutral, f),
        Body::Car { .. } => {
            message::error(format_args!(
                "{function} can only be used by a DifferentialWheels robot; this world's robot is a car."
            ));
            neutral
        }
    })
}
