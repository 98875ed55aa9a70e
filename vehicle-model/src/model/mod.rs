//! The car models shipped with Webots, as parameter presets (spec §5).
//!
//! The list of models is `proto-geom`'s [`ShippedVehicle`] (with their dimensions, wheels and
//! sensor slots), plus the plain `Car`; the engine, driving and body parameters are one row
//! each of the table in `table.rs`.

mod epa;
mod table;

pub use epa::{EpaTestCar, EpaTransmission};

use core::fmt;

use ackermann::{PerWheel, Real};
use proto_geom::{ShippedVehicle, VehicleDimensions, WheelParams};

use crate::params::{BodyPhysics, CarParams, EngineSound, gear_ratios};
use crate::tyre::TyreClass;
use crate::wipers::WiperRange;

use table::{PRESETS, Preset};

/// A car model: the plain Webots `Car` or one of the models shipped with Webots
/// ([`ShippedVehicle`]).
///
/// The models are the associated constants (`Model::BmwX5`, …), which `match` takes as
/// patterns (with a catch-all arm: constants are not checked for exhaustiveness);
/// [`Model::ALL`] lists them.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Model(Option<ShippedVehicle>);

// The constants keep the PROTO names, as the variants of `ShippedVehicle` do.
#[allow(non_upper_case_globals)]
impl Model {
    /// The plain `Car` PROTO with its defaults (`CarParams::default()`).
    pub const Car: Model = Model(None);
    /// `BmwX5` (R2022b): front-wheel drive, combustion, wipers.
    pub const BmwX5: Model = Model(Some(ShippedVehicle::BmwX5));
    /// `CitroenCZero` (R2021b, Y-up): rear-wheel drive, electric.
    pub const CitroenCZero: Model = Model(Some(ShippedVehicle::CitroenCZero));
    /// `ToyotaPrius` (R2023b): front-wheel drive, power-split hybrid.
    pub const ToyotaPrius: Model = Model(Some(ShippedVehicle::ToyotaPrius));
    /// `LincolnMKZ` (R2020a / R2019b, Y-up): 4x4, combustion.
    pub const LincolnMKZ: Model = Model(Some(ShippedVehicle::LincolnMKZ));
    /// `RangeRoverSportSVR` (R2020a / R2019b, Y-up): 4x4, combustion.
    pub const RangeRoverSportSVR: Model = Model(Some(ShippedVehicle::RangeRoverSportSVR));
    /// `TeslaModel3` (R2021c): rear-wheel drive, electric.
    pub const TeslaModel3: Model = Model(Some(ShippedVehicle::TeslaModel3));
    /// `MercedesBenzSprinter` (R2022b): front-wheel drive van.
    pub const MercedesBenzSprinter: Model = Model(Some(ShippedVehicle::MercedesBenzSprinter));
    /// `GreenPowerEVStar` (R2020a, Y-up): front-wheel drive electric minibus.
    pub const GreenPowerEVStar: Model = Model(Some(ShippedVehicle::GreenPowerEVStar));
    /// `Bus` (R2023b): front-wheel drive.
    pub const Bus: Model = Model(Some(ShippedVehicle::Bus));
    /// `Truck` (R2021c): 4x4, with its default `wheelbase` 5.25 m and `mass` 8000 kg.
    pub const Truck: Model = Model(Some(ShippedVehicle::Truck));
    /// `Tractor` (R2022b): 4x4 with different front and rear tyres.
    pub const Tractor: Model = Model(Some(ShippedVehicle::Tractor));
}

impl Model {
    /// Every model: the plain `Car`, then [`ShippedVehicle::ALL`] in its order.
    pub const ALL: [Model; 1 + ShippedVehicle::ALL.len()] = {
        let mut all = [Model::Car; 1 + ShippedVehicle::ALL.len()];
        let mut i = 0;
        while i < ShippedVehicle::ALL.len() {
            all[i + 1] = Model(Some(ShippedVehicle::ALL[i]));
            i += 1;
        }
        all
    };

    /// The Webots PROTO name (`"Car"`, `"BmwX5"`, …).
    pub const fn webots_name(self) -> &'static str {
        match self.0 {
            Some(v) => v.proto_name(),
            None => "Car",
        }
    }

    /// The model with Webots PROTO name `name` (exact, case-sensitive), or `None`.
    ///
    /// ```
    /// use vehicle_model::Model;
    /// assert_eq!(Model::from_name("BmwX5"), Some(Model::BmwX5));
    /// assert_eq!(Model::from_name("bmwx5"), None);
    /// ```
    pub fn from_name(name: &str) -> Option<Model> {
        Model::ALL.into_iter().find(|m| m.webots_name() == name)
    }

    /// The shipped vehicle of `proto-geom` (dimensions, wheels, sensor slots), `None` for the
    /// plain `Car`.
    pub const fn shipped(self) -> Option<ShippedVehicle> {
        self.0
    }

    /// The model's row of the preset table: the plain `Car` first, then the shipped vehicles
    /// by discriminant (the order `table.rs` checks at compile time).
    const fn preset(self) -> &'static Preset {
        match self.0 {
            None => PRESETS[0],
            Some(v) => PRESETS[v as usize + 1],
        }
    }

    /// The kind of tyre the model rolls on, for its default [`crate::TyreParams`]: the vans,
    /// buses and trucks get [`TyreClass::Commercial`], the tractor [`TyreClass::Tractor`],
    /// every other model [`TyreClass::PassengerCar`].
    pub const fn tyre_class(self) -> TyreClass {
        self.preset().tyre_class
    }

    /// The model's parameters (spec §5): its row of the preset table in scalar type `T`, on
    /// the dimensions, wheels and sensor slots of its [`ShippedVehicle`].
    ///
    /// Body inertia: given by BmwX5, CitroenCZero, ToyotaPrius, TeslaModel3 and Tractor; the
    /// others (and the plain `Car`, whose `physics` is `NULL`) use the box of
    /// [`BodyPhysics::box_inertia`]. Wheel masses are the models' `Physics` nodes; LincolnMKZ,
    /// RangeRoverSportSVR and MercedesBenzSprinter use Webots' default `Physics {}` (density
    /// 1000 kg/m³ over the bounding cylinder).
    ///
    /// ```
    /// use vehicle_model::Model;
    /// let bmw = Model::BmwX5.params::<f64>();
    /// assert_eq!(bmw.wheelbase, 2.995);
    /// assert_eq!(bmw.brake_coefficient, 1800.0);
    /// assert!(bmw.clone().validate().is_empty());
    /// ```
    // Always inlined: a call with a constant model (the usual one, and `CarParams::default`)
    // then reads only its own row, which keeps the rest of the table out of a firmware image.
    #[inline(always)]
    pub fn params<T: Real>(self) -> CarParams<T> {
        let f = T::from_f64;
        let p = self.preset();
        let (dimensions, wheels, sensor_slots) = match self.0 {
            Some(v) => (v.dimensions(), v.wheel_params(), v.sensor_slots()),
            None => (
                VehicleDimensions::default(),
                PerWheel::from_fn(|w| WheelParams::default().in_slot(w)),
                None,
            ),
        };
        CarParams {
            translation: p.translation.map(f),
            rotation: p.rotation.map(f),
            track_front: dimensions.track_front,
            track_rear: dimensions.track_rear,
            wheelbase: dimensions.wheelbase,
            min_steering_angle: f(p.min_steering_angle),
            max_steering_angle: f(p.max_steering_angle),
            suspension_front_spring_constant: f(p.suspension_front_spring_constant),
            suspension_front_damping_constant: f(p.suspension_front_damping_constant),
            suspension_rear_spring_constant: f(p.suspension_rear_spring_constant),
            suspension_rear_damping_constant: f(p.suspension_rear_damping_constant),
            wheels_damping_constant: f(p.wheels_damping_constant),
            max_steering_torque: f(p.max_steering_torque),
            wheels,
            drive_type: p.drive_type,
            engine: p.engine.cast(),
            // Every name in the table fits `EngineSound::MAX_LEN`.
            engine_sound: EngineSound::new(p.engine_sound).unwrap_or_default(),
            engine_sound_rpm_reference: f(p.engine_sound_rpm_reference),
            brake_coefficient: f(p.brake_coefficient),
            time_0_to_100: f(p.time_0_to_100),
            max_velocity: f(p.max_velocity),
            gear_ratios: gear_ratios(p.gear_ratios),
            body: BodyPhysics {
                mass: f(p.body.mass),
                center_of_mass: p.body.center_of_mass.map(f),
                inertia: p.body.inertia.map(|m| m.map(f)),
            },
            wipers: p.wipers.map(|w| WiperRange {
                min: f(w.min),
                max: f(w.max),
            }),
            sensor_slots,
        }
    }
}

impl From<ShippedVehicle> for Model {
    fn from(vehicle: ShippedVehicle) -> Self {
        Model(Some(vehicle))
    }
}

impl fmt::Debug for Model {
    /// The PROTO name, as the constant is named.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}

impl fmt::Display for Model {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}
