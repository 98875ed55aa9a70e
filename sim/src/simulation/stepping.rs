//! A simulation's step: the drivers with the sensor readings, the commands in force (the
//! steering commanded since, the energy meter's limits), the world's physics step, then the
//! devices, the energy accounting and the recording.

use vehicle_model::{Sensors, Wheel};

use super::Simulation;
use super::energy::{EnergyMeter, drive_ratio};
use crate::error::SimError;
use crate::vehicle::VehicleId;

impl Simulation {
    /// Runs every driver with the current sensor readings, applies their commands and advances
    /// the world by one `basicTimeStep` (Webots: `wbu_driver_step`). It steps even past the
    /// `duration` ([`Simulation::is_over`] is the caller's to check, as a controller checks
    /// for -1).
    ///
    /// # Errors
    /// The [`SimError`] of a physics failure, then the same error at every step.
    pub fn step(&mut self) -> Result<(), SimError> {
        self.run_drivers(|_| true)?;
        self.step_physics()
    }

    /// Runs the drivers of every car but `own`, then advances the world by one
    /// `basicTimeStep`: a `wb_robot_step` of the controller of car `own` (whose driver does
    /// not run) in a world whose other cars are driven.
    ///
    /// # Errors
    /// As [`Simulation::step`].
    pub fn step_others(&mut self, own: VehicleId) -> Result<(), SimError> {
        self.run_drivers(|id| id != own)?;
        self.step_physics()
    }

    /// Runs the drivers of every car not in `held`, then advances the world by one
    /// `basicTimeStep`: a step of a process whose controllers drive the cars of `held`
    /// without the driver library (their commands hold), while the other cars' drivers run.
    /// With `held` empty it is [`Simulation::step`], with one car [`Simulation::step_others`].
    ///
    /// # Errors
    /// As [`Simulation::step`].
    pub fn step_except(&mut self, held: &[VehicleId]) -> Result<(), SimError> {
        self.run_drivers(|id| !held.contains(&id))?;
        self.step_physics()
    }

    /// Runs the drivers of the cars `which` selects with the current sensor readings and
    /// puts their commands in force (the energy meter's limits on them are
    /// [`Simulation::step_physics`]'s).
    fn run_drivers(&mut self, which: impl Fn(VehicleId) -> bool) -> Result<(), SimError> {
        let t = self.world.time();
        for car in self.cars.iter_mut().filter(|c| which(c.id)) {
            // A stopped controller runs no more: the commands in force hold, without drive.
            if car.energy.as_ref().is_some_and(EnergyMeter::powered_off) {
                continue;
            }
            let sensors = if car.sampled {
                self.world.vehicle(car.id)?.sensors(t)
            } else {
                // Webots sensors deliver their first sample after the first step.
                Sensors::unsampled(t)
            };
            car.sampled = true;
            if let Some(follower) = &mut car.follower {
                let state = self.world.vehicle(car.id)?.state();
                follower.drive(&self.world.config().roads, state, t, &mut car.driver);
            }
            // The energy meter's limits are put on in `step_physics`, which follows every
            // driver step and applies them to the driver's commands each physics step.
            let commands = *car.driver.step(&sensors);
            self.world.vehicle_mut(car.id)?.set_commands(&commands);
        }
        Ok(())
    }

    /// Advances the world by one `basicTimeStep` with the commands in force, without running
    /// the drivers (Webots: `wb_robot_step` in a controller that does not call
    /// `wbu_driver_step`).
    ///
    /// # Errors
    /// As [`Simulation::step`].
    pub fn step_physics(&mut self) -> Result<(), SimError> {
        // Webots' steering setters call `wb_motor_set_position` at once: the steering
        // commanded since the last driver step acts on this step too. After a driver step the
        // angles are those its commands already hold. A car without commands yet (no driver
        // step, no car library) has its motors untouched, as in Webots.
        //
        // A car with an energy meter gets the driver's own drive commands each step with the
        // meter's limits on them: none from a drained battery or a stopped controller
        // (`EnergyMeter::limit`), and capped to what the battery of an electric car or a
        // hybrid can feed at the wheels' spin now (`EnergyMeter::cap_drive`), so that a cap
        // of one step does not stay once the spin allows more.
        let dt = self.world.dt();
        for car in &mut self.cars {
            let vehicle = self.world.vehicle_mut(car.id)?;
            let Some(&in_force) = vehicle.commands() else {
                continue;
            };
            let mut commands = in_force;
            commands.steering = car.driver.commanded_wheel_angles();
            if let Some(meter) = &mut car.energy {
                commands.drive = car.driver.commands().drive;
                meter.limit(&mut commands);
                let spin = vehicle.state().wheel_speeds;
                meter.cap_drive(&mut commands, &spin, drive_ratio(&car.driver), dt);
            }
            if commands != in_force {
                vehicle.set_commands(&commands);
            }
        }
        let result = self.world.step();
        if result.is_ok() {
            let now_ms = self.world.time_ms();
            for car in &mut self.cars {
                car.keyboard.refresh(now_ms);
            }
            self.refresh_devices()?;
            self.meter_energy()?;
            for car in &mut self.cars {
                // Webots refreshes no sensor of a robot whose battery is empty.
                let meter = car.energy.as_ref();
                if !meter.is_some_and(EnergyMeter::powered_off) {
                    let stored = meter.and_then(EnergyMeter::stored_energy);
                    car.battery_sensor.refresh(now_ms, stored);
                }
            }
            if let Some(mut recording) = self.recording.take() {
                recording.sample(self);
                self.recording = Some(recording);
            }
        }
        result
    }

    /// Accounts the last step's energy of every car with a meter.
    fn meter_energy(&mut self) -> Result<(), SimError> {
        let dt = self.world.dt();
        for car in &mut self.cars {
            let Some(meter) = &mut car.energy else {
                continue;
            };
            let vehicle = self.world.vehicle(car.id)?;
            let Some(commands) = vehicle.commands() else {
                continue;
            };
            let ratio = drive_ratio(&car.driver);
            let radii = Wheel::ALL.map(|w| vehicle.spec().wheels[w].radius);
            meter.step(commands, vehicle.state(), radii, ratio, dt);
            if meter.powered_off() {
                let mut commands = *commands;
                meter.limit(&mut commands);
                self.world.vehicle_mut(car.id)?.set_commands(&commands);
            }
        }
        Ok(())
    }
}
