//! A car to add to a [`Simulation`](crate::Simulation): its Webots parameters and every other
//! choice a world file makes about it (tyre, wheel mounting, brake balance, start placement,
//! name, sensor devices and their noise seed), so that a car added from Rust, the C API,
//! Python or a world file is the same car.

use proto_geom::SensorSlots;
use vehicle_model::energy::EnergyParams;
use vehicle_model::{
    Aero, BrakeBalance, CarParams, Driver, Model, ParamReport, RoadLoad, TyreField,
};

use crate::devices::{CarDevices, DeviceSpec};
use crate::keyboard::{KeyPress, Keyboard};

use crate::error::{ParamError, Rule, SimError};
use crate::placement::car_placement;
use crate::vehicle::{Mounting, TyreChoice, VehiclePlacement, VehicleSpec};
use crate::world_file::CarDescription;

/// Everything that makes a car, before it is built: a builder in rapier's style.
///
/// [`CarBuilder::of_model`] is what a world file's `[vehicle] model = "…"` gives with nothing
/// else said; [`CarBuilder::from`] a world file's car as described; [`CarBuilder::new`] any
/// parameters. Nothing is derived until [`Simulation::add_car`](crate::Simulation::add_car)
/// builds the car, so the parameters and what is built from them cannot drift apart.
///
/// ```
/// use sim::{CarBuilder, Mounting, Simulation, TyreChoice, World, WorldConfig};
/// use vehicle_model::{BrakeBalance, Model, WebotsContact};
/// let mut sim = Simulation::new(World::new(WorldConfig::default())?);
/// let car = CarBuilder::of_model(Model::BmwX5)
///     .tyre(TyreChoice::Webots(WebotsContact::default()))
///     .mounting(Mounting::Joints)
///     .brake_balance(BrakeBalance::Proportioned)
///     .name("ego");
/// let (id, report) = sim.add_car(car)?;
/// assert!(report.is_empty());
/// assert_eq!(sim.world().vehicle(id)?.spec().mounting, Mounting::Joints);
/// assert_eq!(sim.car_name(id)?, "ego");
/// # Ok::<(), sim::SimError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CarBuilder {
    params: CarParams<f64>,
    tyre: TyreChoice,
    mounting: Mounting,
    brake_balance: BrakeBalance<f64>,
    placement: Option<VehiclePlacement>,
    name: Option<String>,
    /// The name a car gets when none is set (numbered if taken).
    default_name: &'static str,
    /// Its sensor devices, in the order they were added.
    devices: Vec<DeviceSpec>,
    /// The seed of its devices' noise.
    seed: u64,
    /// Its `radarCrossSection` (m²).
    radar_cross_section: f64,
    /// The frames of its model's sensor slots, `None` for a model without them.
    slots: Option<SensorSlots<f64>>,
    /// The keys pressed for its controller's keyboard.
    keys: Vec<KeyPress>,
    /// Its body's aerodynamic coefficients, `None` for no air (Webots').
    aero: Option<Aero<f64>>,
    /// Its wheels' road-load losses, `None` for Webots' wheel damping alone.
    road_load: Option<RoadLoad<f64>>,
    /// Its energy accounting and its battery's starting charge, `None` for none.
    energy: Option<(EnergyParams<f64>, f64)>,
    /// True if its battery is Webots' Robot battery: the controller stops when it is empty.
    powers_controller: bool,
}

/// A car built from a [`CarBuilder`]: its driver, its body and where it starts.
pub(crate) struct BuiltCar {
    pub driver: Driver<f64>,
    pub report: ParamReport,
    pub spec: VehicleSpec,
    pub placement: VehiclePlacement,
    pub name: Option<String>,
    pub default_name: &'static str,
    pub devices: CarDevices,
    pub keyboard: Keyboard,
    pub radar_cross_section: f64,
    pub energy: Option<(EnergyParams<f64>, f64)>,
    pub powers_controller: bool,
}

impl CarBuilder {
    /// A car of `params` (any `Car` / `AckermannVehicle` fields) on the passenger-car
    /// slip-based tyre ([`TyreChoice::default`]), its wheels cast ([`Mounting::Cast`]), Webots'
    /// equal brakes, starting where its `translation` and `rotation` fields say
    /// ([`car_placement`]), named `Car` (numbered if taken).
    pub fn new(params: CarParams<f64>) -> Self {
        CarBuilder {
            params,
            tyre: TyreChoice::default(),
            mounting: Mounting::default(),
            brake_balance: BrakeBalance::Equal,
            placement: None,
            name: None,
            default_name: Model::Car.webots_name(),
            devices: Vec::new(),
            seed: 0,
            radar_cross_section: 0.0,
            slots: None,
            keys: Vec::new(),
            aero: None,
            road_load: None,
            energy: None,
            powers_controller: false,
        }
    }

    /// The shipped `model` as a world file gives it with nothing else said: its parameters on
    /// the slip-based tyre of its class ([`TyreChoice::of_model`]), named after it, with its
    /// sensor slots for devices.
    pub fn of_model(model: Model) -> Self {
        CarBuilder {
            tyre: TyreChoice::of_model(model),
            default_name: model.webots_name(),
            slots: slots_of(model),
            ..CarBuilder::new(model.params())
        }
    }

    /// The keys its controller's keyboard reads, each at its time ([`crate::keyboard`]).
    #[must_use]
    pub fn key_presses(mut self, keys: Vec<KeyPress>) -> Self {
        self.keys = keys;
        self
    }

    /// The tyres it rolls on.
    #[must_use]
    pub fn tyre(mut self, tyre: TyreChoice) -> Self {
        self.tyre = tyre;
        self
    }

    /// How its wheels hang on the chassis.
    #[must_use]
    pub fn mounting(mut self, mounting: Mounting) -> Self {
        self.mounting = mounting;
        self
    }

    /// How the brake torque is shared between the axles (checked when the car is added).
    #[must_use]
    pub fn brake_balance(mut self, balance: BrakeBalance<f64>) -> Self {
        self.brake_balance = balance;
        self
    }

    /// Where it starts, instead of its `translation` and `rotation` fields.
    #[must_use]
    pub fn placement(mut self, placement: VehiclePlacement) -> Self {
        self.placement = Some(placement);
        self
    }

    /// Its name in telemetry, metrics and messages (unique in a simulation).
    #[must_use]
    pub fn name(mut self, name: impl Into<String>) -> Self {
        self.name = Some(name.into());
        self
    }

    /// Adds a sensor device (checked when the car is added). Devices keep the order they are
    /// added in: the C API's tags and each device's noise stream follow it.
    #[must_use]
    pub fn device(mut self, device: DeviceSpec) -> Self {
        self.devices.push(device);
        self
    }

    /// The seed of its devices' noise (default 0): the same seed gives the same noise.
    #[must_use]
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// Its `radarCrossSection` (m², finite and ≥ 0, checked when the car is added; default 0
    /// as in Webots: radars do not see it).
    #[must_use]
    pub fn radar_cross_section(mut self, rcs: f64) -> Self {
        self.radar_cross_section = rcs;
        self
    }

    /// Its body's aerodynamic drag and lift ([`Aero`]; e.g. [`Model::aero`]), relative to the
    /// world's wind; `None` (the default, Webots'): no air. Checked when the car is added.
    #[must_use]
    pub fn aero(mut self, aero: Option<Aero<f64>>) -> Self {
        self.aero = aero;
        self
    }

    /// Its wheels' road-load losses ([`RoadLoad`]; e.g. [`Model::road_load`]), which replace
    /// the `wheelsDampingConstant`; `None` (the default, Webots'): that damping alone. Checked
    /// when the car is added.
    #[must_use]
    pub fn road_load(mut self, road_load: Option<RoadLoad<f64>>) -> Self {
        self.road_load = road_load;
        self
    }

    /// Its energy accounting ([`EnergyParams`]; e.g. `EnergyParams::of_engine` of its
    /// engine) with its battery charged to `soc` (dimensionless, in [0, 1]): read with
    /// [`Simulation::energy`](crate::Simulation::energy); an electric car whose battery
    /// empties gets no more drive torque. `None` (the default, Webots'): no accounting.
    /// Checked when the car is added.
    #[must_use]
    pub fn energy(mut self, energy: Option<EnergyParams<f64>>, soc: f64) -> Self {
        self.energy = energy.map(|e| (e, soc));
        self
    }

    /// Whether its traction battery ([`CarBuilder::energy`]) is Webots' Robot battery (the
    /// world file's `battery = [energy, maxEnergy, chargingRate]`): when its energy reaches
    /// 0 the controller is stopped ([`Simulation::controller_stopped`](
    /// crate::Simulation::controller_stopped)) and the drive gives no more torque. Default
    /// `false`. Checked when the car is added: it needs a battery.
    #[must_use]
    pub fn battery_powers_controller(mut self, on: bool) -> Self {
        self.powers_controller = on;
        self
    }

    /// The sensor-slot frames its devices may sit in (those of a shipped model by default;
    /// none for [`CarBuilder::new`]).
    #[must_use]
    pub fn sensor_slots(mut self, slots: Option<SensorSlots<f64>>) -> Self {
        self.slots = slots;
        self
    }

    /// The sensor devices, in order.
    pub fn devices(&self) -> &[DeviceSpec] {
        &self.devices
    }

    /// The parameters as given (validated when the car is added).
    pub fn params(&self) -> &CarParams<f64> {
        &self.params
    }

    /// The parameters, to change fields before the car is added.
    pub fn params_mut(&mut self) -> &mut CarParams<f64> {
        &mut self.params
    }

    /// The tyre choice.
    pub fn tyre_choice(&self) -> &TyreChoice {
        &self.tyre
    }

    /// The wheel mounting.
    pub fn wheel_mounting(&self) -> Mounting {
        self.mounting
    }

    /// The brake balance.
    pub fn balance(&self) -> BrakeBalance<f64> {
        self.brake_balance
    }

    /// The start placement: the one set, else that of the `translation` and `rotation` fields.
    pub fn start(&self) -> VehiclePlacement {
        self.placement
            .unwrap_or_else(|| car_placement(&self.params))
    }

    /// Validates the parameters (an invalid field takes its Webots default and is reported,
    /// as `Driver::new` does) and builds the driver, at `step_ms` (Webots' `basicTimeStep`),
    /// and the body.
    ///
    /// # Errors
    /// [`SimError::Param`] naming a tyre coefficient or body field the car cannot be built
    /// with, [`SimError::BrakeBalance`] for a front share outside [0, 1], [`SimError::Device`]
    /// for a device that cannot be built.
    pub(crate) fn build(self, step_ms: u32) -> Result<BuiltCar, SimError> {
        let placement = self.start();
        ParamError::non_negative("radarCrossSection", self.radar_cross_section)?;
        if self.powers_controller
            && self
                .energy
                .as_ref()
                .is_none_or(|(e, _)| e.battery.is_none())
        {
            return Err(ParamError {
                field: "battery",
                value: 0.0,
                rule: Rule::Text("a traction battery to power the controller"),
            }
            .into());
        }
        if let Some((energy, soc)) = &self.energy {
            check_energy(energy, *soc)?;
        }
        let devices = CarDevices::build(&self.devices, self.slots.as_ref(), self.seed)?;
        let tyre = self.tyre_with_road_load();
        let (mut driver, report) = Driver::new(self.params, step_ms);
        driver
            .set_brake_balance(self.brake_balance)
            .map_err(SimError::BrakeBalance)?;
        let mut spec = VehicleSpec::from_car_with(driver.params(), &tyre)?;
        spec.mounting = self.mounting;
        spec.aero = self.aero;
        spec.road_load = self.road_load;
        spec.validate()?;
        Ok(BuiltCar {
            driver,
            report,
            spec,
            placement,
            name: self.name,
            default_name: self.default_name,
            devices,
            keyboard: Keyboard::new(self.keys),
            radar_cross_section: self.radar_cross_section,
            energy: self.energy,
            powers_controller: self.powers_controller,
        })
    }
}

impl CarBuilder {
    /// The tyre with the road-load set's rolling resistance ([`RoadLoad::rolling_resistance`])
    /// when it carries one: applied before the tyre's own coefficients, so a rolling
    /// resistance written for the tyre (`[vehicle.tyre]`, its property file) keeps the last
    /// word. Webots' contact has no rolling resistance to replace.
    fn tyre_with_road_load(&self) -> TyreChoice {
        let mut tyre = self.tyre.clone();
        let rolling = self.road_load.and_then(|r| r.rolling_resistance);
        if let (Some(c), TyreChoice::MagicFormula { overrides, .. }) = (rolling, &mut tyre) {
            overrides.insert(0, (TyreField::RollingResistance, c));
        }
        tyre
    }
}

impl From<&CarDescription> for CarBuilder {
    /// The car of a world file as it is described: its parameters, tyre, mounting, brake
    /// balance, name, devices and seed; it starts where its `translation` and `rotation` say.
    fn from(car: &CarDescription) -> Self {
        CarBuilder {
            params: car.params.clone(),
            tyre: car.tyre.clone(),
            mounting: car.mounting,
            brake_balance: car.brake_balance,
            placement: None,
            name: Some(car.name.clone()),
            default_name: car.model.webots_name(),
            devices: car.devices.clone(),
            seed: car.seed,
            radar_cross_section: car.radar_cross_section,
            slots: slots_of(car.model),
            keys: car.keys.clone(),
            aero: car.aero,
            road_load: car.road_load,
            energy: car.energy.map(|e| (e, car.state_of_charge)),
            powers_controller: car.webots_battery.is_some(),
        }
    }
}

/// Checks the battery and machine of `energy` and the starting charge `soc`.
fn check_energy(energy: &EnergyParams<f64>, soc: f64) -> Result<(), ParamError> {
    if !(0.0..=1.0).contains(&soc) {
        return Err(ParamError {
            field: "state_of_charge",
            value: soc,
            rule: Rule::Text("within [0, 1]"),
        });
    }
    if let Some(battery) = energy.battery {
        battery.validated().map_err(|e| ParamError {
            field: e.field,
            value: e.value,
            rule: Rule::Text(e.rule),
        })?;
    }
    if let Some(motor) = energy.motor {
        motor.validated().map_err(|e| ParamError {
            field: e.field,
            value: e.value,
            rule: Rule::Text("finite and >= 0"),
        })?;
    }
    Ok(())
}

/// The sensor-slot frames of `model`, `None` for the plain `Car` and the models without them.
fn slots_of(model: Model) -> Option<SensorSlots<f64>> {
    model.shipped().and_then(|v| v.sensor_slots())
}
