//! Several controllers in one process, one per car of the world: the **project's extension**
//! (no Webots counterpart) that lets one front-end serve every car of a world, as the ROS node
//! `vehicle-ros` does. Rust functions for the bindings (the Python package's
//! `webots_vehicle.controllers`), not C entry points.
//!
//! In Webots each car runs its own controller process. Here a process holds one world; a C
//! controller drives the car Webots' rule gives (the only car, or the one without a
//! programme) and never sees this module. A front-end instead calls [`select`] with a car's
//! name: the process gets a controller for that car (its own device tags, buffers and
//! libraries; the car stops running its world-file programme) and every `wb_*`/`wbu_*`
//! function acts on it until the next [`select`]. A step (`wbu_driver_step`, `wb_robot_step`)
//! of any controller advances the one world once, running the driver of every controller that
//! initialised the driver library, so a front-end steps once per world step, not once per car.

use sim::world_file::WorldDescription;

use crate::robot;
use crate::session;

/// A car of the world, as a front-end chooses the cars it serves.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WorldCar {
    /// Its name (the world file's `name`, else its model's, numbered when several cars share
    /// it): Webots' robot name and DEF name.
    pub name: String,
    /// True if it has a `[[vehicle.programme]]` (timed commands or lane following).
    pub programmed: bool,
}

/// The cars of `description` in file order.
pub(crate) fn world_cars(description: &WorldDescription) -> Vec<WorldCar> {
    description
        .cars
        .iter()
        .map(|car| WorldCar {
            name: car.name.clone(),
            programmed: !car.programme.is_empty() || !car.lanes.is_empty(),
        })
        .collect()
}

/// The world's cars in file order: the loaded world's, or, before any is loaded, those of
/// the world `VEHICLE_WORLD` names (read, not loaded: its warnings are printed when it is
/// loaded). Empty for a DifferentialWheels world.
///
/// # Errors
/// What is wrong with the world file, one line per error, as `wb_robot_init` prints it.
pub fn cars() -> Result<Vec<WorldCar>, String> {
    if let Some(cars) = session::with_loaded(|robot| robot.cars().to_vec()) {
        return Ok(cars);
    }
    robot::description_from_environment().map(|d| world_cars(&d))
}

/// Makes the controller of car `name` the current one: every entry point acts on it until the
/// next call. The first call loads the world named by `VEHICLE_WORLD` for that car (instead
/// of the car Webots' rule gives); a later one adds a controller for a car that has none yet
/// (no library initialised, its devices disabled, its programme no longer run, with a
/// warning if it had one) or returns to the car's existing one.
///
/// # Errors
/// What is wrong with the world (as [`crate::load_world`]), or a name no car of it has (the
/// message lists the world's car names).
pub fn select(name: &str) -> Result<(), String> {
    session::select(name)
}

/// The name of the car the current controller drives; `None` before a world is loaded or for
/// a DifferentialWheels robot.
pub fn current() -> Option<String> {
    session::with_loaded(|robot| robot.current_car().map(str::to_string)).flatten()
}
