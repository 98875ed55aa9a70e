//! One controller of the process: the car (or DifferentialWheels robot) it drives, the
//! libraries it initialised, its devices and the buffers their results live in.
//!
//! Webots runs one controller per robot, each in a process of its own. Here a C controller is
//! the process's one controller; a front-end that serves several cars of one world (the ROS
//! node, through the [`crate::controllers`] extension) holds one `Controller` per car over the
//! same [`crate::robot::Robot`] world, so each car keeps its own device tags, buffers and
//! library state.

use sim::battery_sensor::BatterySensor;
use sim::keyboard::Keyboard;
use sim::{RobotId, Simulation, VehicleId};

use crate::abi::WbDeviceTag;
use crate::devices::{self, CAR_TAGS, DeviceEntry};
use crate::display_api::Images;
use crate::sensor::Buffers;

/// Which of the two libraries a controller has initialised on a car, in initialisation order
/// (the driver library includes the car library).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Libraries {
    /// Neither: `wbu_car_*` and `wbu_driver_*` functions warn and return neutral values.
    None,
    /// `wbu_car_init()` only.
    Car,
    /// `wbu_driver_init()` (which initialises the car library too).
    Driver,
}

/// What a controller drives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Body {
    /// A car, driven through the driver library of the [`Simulation`].
    Car {
        /// The car in the simulation.
        id: VehicleId,
        /// The libraries initialised so far.
        libraries: Libraries,
    },
    /// A DifferentialWheels robot.
    DifferentialWheels(RobotId),
}

/// A controller's own state (Webots: what a controller process holds of its robot).
pub(crate) struct Controller {
    /// The car or robot it drives.
    pub(crate) body: Body,
    /// Its devices in tag order (tag = index + 1), `None` for a car-library device the model
    /// lacks.
    devices: Vec<Option<DeviceEntry>>,
    /// Where the sensor functions' `const double *` results live.
    pub(crate) buffers: Buffers,
    /// The keyboard of a DifferentialWheels robot's controller: no programme presses its keys
    /// (a car's keyboard is the simulation's).
    pub(crate) robot_keyboard: Keyboard,
    /// The battery sensor of a DifferentialWheels robot's controller: its period only (the
    /// robot has no battery here; a car's sensor is the simulation's).
    pub(crate) robot_battery: BatterySensor,
    /// The images of `wb_display_image_*`, by handle.
    pub(crate) images: Images,
}

impl Controller {
    /// The controller of `body` in `simulation`, no library initialised, with the device
    /// table of the car (its model's car-library devices, then its world-file sensors) or of
    /// the robot.
    ///
    /// # Errors
    /// A car the simulation does not hold, as text.
    pub(crate) fn new(simulation: &Simulation, body: Body) -> Result<Controller, String> {
        let (devices, buffers) = match body {
            Body::Car { id, .. } => {
                let sensors = simulation.devices(id).map_err(|e| e.to_string())?;
                let params = simulation.driver(id).map_err(|e| e.to_string())?.params();
                let named = sensors.iter().map(|d| (d.name().to_string(), d.kind()));
                (devices::car_table(params, named), Buffers::new(sensors))
            }
            Body::DifferentialWheels(_) => {
                (devices::differential_wheels_table(), Buffers::new(&[]))
            }
        };
        Ok(Controller {
            body,
            devices,
            buffers,
            robot_keyboard: Keyboard::default(),
            robot_battery: BatterySensor::default(),
            images: Images::default(),
        })
    }

    /// The car it drives, `None` for a DifferentialWheels robot.
    pub(crate) fn car(&self) -> Option<VehicleId> {
        match self.body {
            Body::Car { id, .. } => Some(id),
            Body::DifferentialWheels(_) => None,
        }
    }

    /// The libraries initialised (`None` for a DifferentialWheels robot too).
    pub(crate) fn libraries(&self) -> Libraries {
        match self.body {
            Body::Car { libraries, .. } => libraries,
            Body::DifferentialWheels(_) => Libraries::None,
        }
    }

    /// The tag of the device `name`, 0 if the robot has none.
    pub(crate) fn device(&self, name: &str) -> WbDeviceTag {
        devices::tag_of(&self.devices, name)
    }

    /// The number of tags (the robot's own, 0, excluded).
    pub(crate) fn device_count(&self) -> usize {
        self.devices.len()
    }

    /// The device of `tag`, `None` for 0, a tag past the last or a hole of the car's table.
    pub(crate) fn device_entry(&self, tag: WbDeviceTag) -> Option<&DeviceEntry> {
        let index = usize::from(tag).checked_sub(1)?;
        self.devices.get(index)?.as_ref()
    }

    /// The car and the index among its sensors of the sensor with `tag`, if it is one.
    pub(crate) fn sensor_of(&self, tag: WbDeviceTag) -> Option<(VehicleId, usize)> {
        let id = self.car()?;
        let index = usize::from(tag).checked_sub(CAR_TAGS + 1)?;
        (index < self.devices.len() - CAR_TAGS).then_some((id, index))
    }
}
