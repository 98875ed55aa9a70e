//! A world plus one Webots driver library per car, stepped like a Webots controller calling
//! `wbu_driver_step()`.

use vehicle_model::{CarParams, ControlMode, Driver, Gear, ParamReport, Sensors};

use crate::error::SimError;
use crate::placement::car_placement;
use crate::vehicle::{
    Mounting, TyreChoice, VehicleId, VehiclePlacement, VehicleSpec, VehicleState,
};
use crate::world::World;
use crate::world_file::CarDescription;

/// One car's driver and whether it has had its first step.
struct Controlled {
    id: VehicleId,
    driver: Driver<f64>,
    sampled: bool,
}

/// What a data logger records of a driven car at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarTelemetry {
    /// Simulated time (s).
    pub time: f64,
    /// The physical state measured on the bodies (pose, velocities, wheels, steering).
    pub state: VehicleState,
    /// Chassis speed (m/s, signed, positive forward), from the rigid body: not the driver's
    /// wheel-based estimate.
    pub speed: f64,
    /// The driver library's own speed estimate from the driven wheels (km/h; 0 until the wheel
    /// speeds are measurable, where Webots returns NaN for two steps). Webots:
    /// `wbu_driver_get_current_speed`.
    pub estimated_speed_kmh: f64,
    /// Engine speed (rpm) in torque mode, `None` in the other modes (Webots warns there).
    pub rpm: Option<f64>,
    /// Engaged gear in torque mode, `None` in the other modes.
    pub gear: Option<Gear>,
    /// The control mode.
    pub control_mode: ControlMode,
    /// Throttle (0 to 1).
    pub throttle: f64,
    /// Brake intensity (0 to 1).
    pub brake: f64,
}

/// A [`World`] whose cars are each driven by a `vehicle_model::Driver<f64>`.
///
/// [`Simulation::step`] does what `wbu_driver_step()` does in a Webots controller: each driver
/// steps with the sensor readings at the current time `t` (the state after the previous
/// physics step; unsampled, i.e. NaN, at a car's first step), its commands are applied, then
/// the world advances by one `basicTimeStep`.
///
/// ```
/// use sim::{Simulation, VehiclePlacement, World, WorldConfig};
/// use vehicle_model::Model;
/// let mut sim = Simulation::new(World::new(WorldConfig::default())?);
/// let (id, report) = sim.add_car(Model::BmwX5.params(), VehiclePlacement::default())?;
/// assert!(report.is_empty());
/// sim.driver_mut(id)?.set_cruising_speed(20.0); // km/h, as in Webots
/// for _ in 0..100 {
///     sim.step()?;
/// }
/// assert!(sim.telemetry(id)?.speed > 0.5); // m/s after 1 s
/// # Ok::<(), sim::SimError>(())
/// ```
pub struct Simulation {
    world: World,
    cars: Vec<Controlled>,
}

impl Simulation {
    /// A simulation of `world` (which may already hold cars and robots; only cars added with
    /// [`Simulation::add_car`] have a driver).
    pub fn new(world: World) -> Self {
        Simulation {
            world,
            cars: Vec::new(),
        }
    }

    /// Validates `params` (invalid fields take their Webots default and are reported, as
    /// `Driver::new` does), builds the car at `placement` on passenger-car slip-based tyres
    /// ([`TyreChoice::default`]) and gives it a driver running at the world's
    /// `basicTimeStep`.
    pub fn add_car(
        &mut self,
        params: CarParams<f64>,
        placement: VehiclePlacement,
    ) -> Result<(VehicleId, ParamReport), SimError> {
        self.add_car_on(params, &TyreChoice::default(), placement)
    }

    /// As [`Simulation::add_car`], on the tyres of `tyre` (e.g. a world file's
    /// [`CarDescription::tyre`](crate::world_file::CarDescription::tyre)).
    ///
    /// # Errors
    /// [`SimError::Param`] naming a tyre coefficient out of range (e.g. `tyre.lateral.shape`)
    /// or an invalid body field.
    ///
    /// ```
    /// use sim::{Simulation, TyreChoice, VehiclePlacement, World, WorldConfig};
    /// use vehicle_model::{Model, TyreClass, TyreModel};
    /// let mut sim = Simulation::new(World::new(WorldConfig::default())?);
    /// let tyre = TyreChoice::MagicFormula { class: TyreClass::Commercial, overrides: Vec::new() };
    /// let (id, _) = sim.add_car_on(Model::Bus.params(), &tyre, VehiclePlacement::default())?;
    /// let TyreModel::MagicFormula(front) = sim.world().vehicle(id)?.spec().tyres.front else {
    ///     unreachable!()
    /// };
    /// assert_eq!(front.params().lateral.stiffness, 10.0); // per rad, per unit load
    /// # Ok::<(), sim::SimError>(())
    /// ```
    pub fn add_car_on(
        &mut self,
        params: CarParams<f64>,
        tyre: &TyreChoice,
        placement: VehiclePlacement,
    ) -> Result<(VehicleId, ParamReport), SimError> {
        self.add_car_with(params, tyre, Mounting::Cast, placement)
    }

    /// As [`Simulation::add_car_on`], with its wheels mounted as `mounting` says (a world
    /// file's `mounting`; [`Simulation::add_described_car`] adds a world file's car as it
    /// is described).
    ///
    /// ```
    /// use sim::{Mounting, Simulation, TyreChoice, VehiclePlacement, World, WorldConfig};
    /// use vehicle_model::Model;
    /// let mut sim = Simulation::new(World::new(WorldConfig::default())?);
    /// let tyre = TyreChoice::of_model(Model::BmwX5);
    /// let place = VehiclePlacement::default();
    /// let (id, _) = sim.add_car_with(Model::BmwX5.params(), &tyre, Mounting::Joints, place)?;
    /// assert_eq!(sim.world().vehicle(id)?.spec().mounting, Mounting::Joints);
    /// # Ok::<(), sim::SimError>(())
    /// ```
    pub fn add_car_with(
        &mut self,
        params: CarParams<f64>,
        tyre: &TyreChoice,
        mounting: Mounting,
        placement: VehiclePlacement,
    ) -> Result<(VehicleId, ParamReport), SimError> {
        let (driver, report) = Driver::new(params, self.world.config().basic_time_step_ms);
        let mut spec = VehicleSpec::from_car_with(driver.params(), tyre)?;
        spec.mounting = mounting;
        let id = self.drive(driver, spec, placement)?;
        Ok((id, report))
    }

    /// Adds the car of a world file (or of [`CarDescription::of_model`]) at its `translation`
    /// and `rotation` ([`car_placement`]): its driver from `car.params` (validated already:
    /// the report is empty unless they were changed since) with `car.brake_balance`, its body
    /// the `car.spec` the loader built.
    ///
    /// ```
    /// use sim::{Simulation, World, world_file};
    /// let description = world_file::default_world();
    /// let mut sim = Simulation::new(World::new(description.config.clone())?);
    /// let (id, report) = sim.add_described_car(&description.cars[0])?;
    /// assert!(report.is_empty());
    /// assert_eq!(sim.world().vehicle(id)?.spec(), &description.cars[0].spec);
    /// # Ok::<(), sim::SimError>(())
    /// ```
    pub fn add_described_car(
        &mut self,
        car: &CarDescription,
    ) -> Result<(VehicleId, ParamReport), SimError> {
        let step_ms = self.world.config().basic_time_step_ms;
        let (mut driver, report) = Driver::new(car.params.clone(), step_ms);
        driver
            .set_brake_balance(car.brake_balance)
            .map_err(SimError::BrakeBalance)?;
        let id = self.drive(driver, car.spec, car_placement(&car.params))?;
        Ok((id, report))
    }

    /// Puts the car of `spec` in the world at `placement`, driven by `driver`.
    fn drive(
        &mut self,
        driver: Driver<f64>,
        spec: VehicleSpec,
        placement: VehiclePlacement,
    ) -> Result<VehicleId, SimError> {
        let id = self.world.add_vehicle(spec, placement)?;
        self.cars.push(Controlled {
            id,
            driver,
            sampled: false,
        });
        Ok(id)
    }

    fn car(&self, id: VehicleId) -> Result<&Controlled, SimError> {
        self.cars
            .iter()
            .find(|c| c.id == id)
            .ok_or(SimError::UnknownVehicle(id.index()))
    }

    /// The driver of car `id`.
    pub fn driver(&self, id: VehicleId) -> Result<&Driver<f64>, SimError> {
        self.car(id).map(|c| &c.driver)
    }

    /// The driver of car `id`, to set throttle, steering, gear… (Webots: `wbu_driver_set_*`).
    pub fn driver_mut(&mut self, id: VehicleId) -> Result<&mut Driver<f64>, SimError> {
        self.cars
            .iter_mut()
            .find(|c| c.id == id)
            .map(|c| &mut c.driver)
            .ok_or(SimError::UnknownVehicle(id.index()))
    }

    /// The world.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The world, e.g. to command DifferentialWheels robots or cars without a driver.
    pub fn world_mut(&mut self) -> &mut World {
        &mut self.world
    }

    /// Runs every driver with the current sensor readings, applies their commands and advances
    /// the world by one `basicTimeStep`.
    pub fn step(&mut self) -> Result<(), SimError> {
        let t = self.world.time();
        for car in &mut self.cars {
            let sensors = if car.sampled {
                self.world.vehicle(car.id)?.sensors(t)
            } else {
                // Webots sensors deliver their first sample after the first step.
                Sensors::unsampled(t)
            };
            car.sampled = true;
            let commands = *car.driver.step(&sensors);
            self.world.vehicle_mut(car.id)?.set_commands(&commands);
        }
        self.world.step()
    }

    /// The telemetry of car `id` after the last step.
    pub fn telemetry(&self, id: VehicleId) -> Result<CarTelemetry, SimError> {
        let driver = &self.car(id)?.driver;
        let state = *self.world.vehicle(id)?.state();
        let torque = driver.control_mode() == ControlMode::Torque;
        Ok(CarTelemetry {
            time: self.world.time(),
            state,
            speed: state.forward_speed,
            estimated_speed_kmh: driver.current_speed(),
            rpm: if torque { driver.rpm().ok() } else { None },
            gear: if torque { driver.gear().ok() } else { None },
            control_mode: driver.control_mode(),
            throttle: driver.throttle(),
            brake: driver.brake_intensity(),
        })
    }
}
