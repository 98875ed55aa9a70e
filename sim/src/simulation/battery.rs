//! Webots' Robot battery on a car: the battery sensor of its controller
//! ([`crate::battery_sensor`]) and the controller stopped when the battery empties.

use super::{EnergyMeter, Simulation};
use crate::battery_sensor::BatterySensor;
use crate::error::SimError;
use crate::vehicle::VehicleId;

impl Simulation {
    /// Car `id`'s battery sensor: its period and last reading (J).
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`].
    pub fn battery_sensor(&self, id: VehicleId) -> Result<&BatterySensor, SimError> {
        self.car(id).map(|c| &c.battery_sensor)
    }

    /// Enables car `id`'s battery sensor with a period of `period_ms` ms (0 disables)
    /// (Webots: `wb_robot_battery_sensor_enable`, `…_disable`).
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`].
    pub fn enable_battery_sensor(&mut self, id: VehicleId, period_ms: u32) -> Result<(), SimError> {
        let now_ms = self.world.time_ms();
        self.car_mut(id)?.battery_sensor.enable(period_ms, now_ms);
        Ok(())
    }

    /// True once car `id`'s controller is stopped: its traction battery is Webots' Robot
    /// battery ([`CarBuilder::battery_powers_controller`](crate::CarBuilder::battery_powers_controller),
    /// the world file's `battery = [energy, maxEnergy, chargingRate]`) and it is empty.
    /// From the step end it empties, its driver no longer runs, its wheels get no drive
    /// torque (the steering and brakes keep their last commands), and its sensors, the
    /// battery sensor included, are not refreshed, as Webots powers the robot off.
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`].
    pub fn controller_stopped(&self, id: VehicleId) -> Result<bool, SimError> {
        Ok(self
            .car(id)?
            .energy
            .as_ref()
            .is_some_and(EnergyMeter::powered_off))
    }
}
