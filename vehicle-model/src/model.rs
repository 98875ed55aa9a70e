//! The car models shipped with Webots, as parameter presets (spec §5).
//!
//! Dimensions, wheels and sensor slots come from [`proto_geom::ShippedVehicle`]; the engine,
//! driving and body parameters are here. Every figure is in the car frame (x forward, y left,
//! z up, origin at the rear-axle centre); those read from older Y-up PROTO revisions
//! (x = left, y = up, z = forward) are converted with FLU = (z, x, y), inertia included
//! (`[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]_FLU = [Izz, Ixx, Iyy, Ixz, Iyz, Ixy]_Y-up`).

use core::fmt;

use ackermann::{DriveType, Real};
use powertrain::{EngineParams, EngineType};
use proto_geom::ShippedVehicle;

use crate::params::{BodyPhysics, CarParams, EngineSound, gear_ratios};
use crate::tyre::TyreClass;
use crate::wipers::WiperRange;

/// A car model: the plain Webots `Car` or one of the models shipped with Webots.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Model {
    /// The plain `Car` PROTO with its defaults (`CarParams::default()`).
    Car,
    /// `BmwX5` (R2022b): front-wheel drive, combustion, wipers.
    BmwX5,
    /// `CitroenCZero` (R2021b, Y-up): rear-wheel drive, electric.
    CitroenCZero,
    /// `ToyotaPrius` (R2023b): front-wheel drive, power-split hybrid.
    ToyotaPrius,
    /// `LincolnMKZ` (R2020a / R2019b, Y-up): 4x4, combustion.
    LincolnMKZ,
    /// `RangeRoverSportSVR` (R2020a / R2019b, Y-up): 4x4, combustion.
    RangeRoverSportSVR,
    /// `TeslaModel3` (R2021c): rear-wheel drive, electric.
    TeslaModel3,
    /// `MercedesBenzSprinter` (R2022b): front-wheel drive van.
    MercedesBenzSprinter,
    /// `GreenPowerEVStar` (R2020a, Y-up): front-wheel drive electric minibus.
    GreenPowerEVStar,
    /// `Bus` (R2023b): front-wheel drive.
    Bus,
    /// `Truck` (R2021c): 4x4, with its default `wheelbase` 5.25 m and `mass` 8000 kg.
    Truck,
    /// `Tractor` (R2022b): 4x4 with different front and rear tyres.
    Tractor,
}

impl Model {
    /// Every model, the plain `Car` first.
    pub const ALL: [Model; 12] = [
        Model::Car,
        Model::BmwX5,
        Model::CitroenCZero,
        Model::ToyotaPrius,
        Model::LincolnMKZ,
        Model::RangeRoverSportSVR,
        Model::TeslaModel3,
        Model::MercedesBenzSprinter,
        Model::GreenPowerEVStar,
        Model::Bus,
        Model::Truck,
        Model::Tractor,
    ];

    /// The Webots PROTO name (`"Car"`, `"BmwX5"`, …).
    pub const fn webots_name(self) -> &'static str {
        match self.shipped() {
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
        Some(match self {
            Model::Car => return None,
            Model::BmwX5 => ShippedVehicle::BmwX5,
            Model::CitroenCZero => ShippedVehicle::CitroenCZero,
            Model::ToyotaPrius => ShippedVehicle::ToyotaPrius,
            Model::LincolnMKZ => ShippedVehicle::LincolnMKZ,
            Model::RangeRoverSportSVR => ShippedVehicle::RangeRoverSportSVR,
            Model::TeslaModel3 => ShippedVehicle::TeslaModel3,
            Model::MercedesBenzSprinter => ShippedVehicle::MercedesBenzSprinter,
            Model::GreenPowerEVStar => ShippedVehicle::GreenPowerEVStar,
            Model::Bus => ShippedVehicle::Bus,
            Model::Truck => ShippedVehicle::Truck,
            Model::Tractor => ShippedVehicle::Tractor,
        })
    }

    /// The kind of tyre the model rolls on, for its default [`crate::TyreParams`]: the vans,
    /// buses and trucks get [`TyreClass::Commercial`], the tractor [`TyreClass::Tractor`],
    /// every other model [`TyreClass::PassengerCar`].
    pub const fn tyre_class(self) -> TyreClass {
        match self {
            Model::MercedesBenzSprinter | Model::GreenPowerEVStar | Model::Bus | Model::Truck => {
                TyreClass::Commercial
            }
            Model::Tractor => TyreClass::Tractor,
            _ => TyreClass::PassengerCar,
        }
    }

    /// The model's parameters (spec §5). Unlisted fields keep the `Car` defaults.
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
    pub fn params<T: Real>(self) -> CarParams<T> {
        let f = T::from_f64;
        let mut p = CarParams::<T>::default();
        let Some(shipped) = self.shipped() else {
            return p;
        };
        let d = shipped.dimensions::<T>();
        p.wheelbase = d.wheelbase;
        p.track_front = d.track_front;
        p.track_rear = d.track_rear;
        p.wheels = shipped.wheel_params();
        p.sensor_slots = shipped.sensor_slots();
        let body = |mass: f64, com: [f64; 3], inertia: Option<[f64; 6]>| BodyPhysics {
            mass: f(mass),
            center_of_mass: com.map(f),
            inertia: inertia.map(|m| m.map(f)),
        };
        let engine =
            |engine_type, max_torque, max_power, min_rpm, max_rpm, coefficients| EngineParams {
                engine_type,
                max_torque: f(max_torque),
                max_power: f(max_power),
                min_rpm: f(min_rpm),
                max_rpm: f(max_rpm),
                function_coefficients: <[f64; 3]>::map(coefficients, f),
                ..EngineParams::default()
            };
        const DEF_COEFFICIENTS: [f64; 3] = [150.0, 0.1, 0.0];
        const BUS_COEFFICIENTS: [f64; 3] = [-600.0, 5.45, -0.0023];
        use EngineType::{Combustion, Electric, PowerSplitHybrid};

        match self {
            Model::Car => {}
            Model::BmwX5 => {
                p.time_0_to_100 = f(7.0);
                p.engine = engine(
                    Combustion,
                    250.0,
                    50_000.0,
                    1000.0,
                    6500.0,
                    [34.11, 0.136, -0.000_014_61],
                );
                p.gear_ratios = gear_ratios(&[-12.5, 12.5, 8.0, 5.35, 4.3, 4.0]);
                p.brake_coefficient = f(1800.0);
                p.wheels_damping_constant = f(2.0);
                p.body = body(
                    2000.0,
                    [1.2975, 0.0, 0.1],
                    Some([1125.07, 4473.54, 4346.1, 0.0, 846.89, 0.0]),
                );
                p.wipers = Some(WiperRange::bmw_x5());
            }
            Model::CitroenCZero => {
                p.drive_type = DriveType::Propulsion;
                p.time_0_to_100 = f(17.5);
                p.engine = engine(Electric, 150.0, 75_000.0, 1000.0, 8000.0, DEF_COEFFICIENTS);
                p.gear_ratios = gear_ratios(&[-6.2329, 6.2329]);
                p.brake_coefficient = f(580.0);
                p.min_steering_angle = f(-0.631);
                p.max_steering_angle = f(0.631);
                p.suspension_front_spring_constant = f(30_000.0);
                p.suspension_front_damping_constant = f(5000.0);
                p.suspension_rear_spring_constant = f(30_000.0);
                p.suspension_rear_damping_constant = f(5000.0);
                p.wheels_damping_constant = f(1.55);
                p.engine_sound = EngineSound::none();
                // The rear-right slot's front wheel with the rear wheels' 6 kg comes from
                // `ShippedVehicle::wheel_params`.
                // Y-up (-0.002, 0.248, 1.180) and [2645 2534 200 / 0 0 0].
                p.body = body(
                    1200.0,
                    [1.180, -0.002, 0.248],
                    Some([200.0, 2645.0, 2534.0, 0.0, 0.0, 0.0]),
                );
            }
            Model::ToyotaPrius => {
                p.time_0_to_100 = f(10.7);
                p.engine = EngineParams {
                    hybrid_power_split_ratio: f(0.2778),
                    hybrid_power_split_rpm: f(3000.0),
                    ..engine(
                        PowerSplitHybrid,
                        350.0,
                        33_000.0,
                        1200.0,
                        6500.0,
                        [65.0, 0.0225, -0.000_002_5],
                    )
                };
                p.gear_ratios = gear_ratios(&[-6.0, 6.0]);
                p.wheels_damping_constant = f(1.0);
                p.body = body(
                    1805.0,
                    [1.2975, 0.0, 0.1],
                    Some([1125.07, 4473.54, 4346.1, -300.0, 0.0, 0.0]),
                );
            }
            Model::LincolnMKZ => {
                p.drive_type = DriveType::FourByFour;
                p.time_0_to_100 = f(4.97);
                p.engine = engine(
                    Combustion,
                    250.0,
                    298_000.0,
                    1000.0,
                    5500.0,
                    DEF_COEFFICIENTS,
                );
                p.gear_ratios = gear_ratios(&[-2.94, 4.58, 2.96, 1.91, 1.45, 1.00, 0.75]);
                p.brake_coefficient = f(1400.0);
                p.wheels_damping_constant = f(2.0);
                // Y-up (0, 0.2, 1.6).
                p.body = body(1950.0, [1.6, 0.0, 0.2], None);
            }
            Model::RangeRoverSportSVR => {
                p.drive_type = DriveType::FourByFour;
                p.time_0_to_100 = f(4.7);
                p.engine = engine(
                    Combustion,
                    680.0,
                    50_000.0,
                    1000.0,
                    5500.0,
                    DEF_COEFFICIENTS,
                );
                p.gear_ratios =
                    gear_ratios(&[-3.0, 4.696, 3.130, 2.104, 1.667, 1.285, 1.000, 0.839, 0.667]);
                p.brake_coefficient = f(1000.0);
                // Y-up (0, 0.2, 1.6).
                p.body = body(2700.0, [1.6, 0.0, 0.2], None);
            }
            Model::TeslaModel3 => {
                p.drive_type = DriveType::Propulsion;
                p.time_0_to_100 = f(4.0);
                p.engine = engine(
                    Electric,
                    639.0,
                    147_000.0,
                    1000.0,
                    25_000.0,
                    DEF_COEFFICIENTS,
                );
                p.gear_ratios = gear_ratios(&[-6.3, 9.0]);
                p.brake_coefficient = f(2000.0);
                p.suspension_front_spring_constant = f(60_000.0);
                p.suspension_front_damping_constant = f(10_000.0);
                p.suspension_rear_spring_constant = f(60_000.0);
                p.suspension_rear_damping_constant = f(10_000.0);
                p.wheels_damping_constant = f(3.0);
                p.engine_sound = EngineSound::none();
                p.body = body(
                    1847.0,
                    [1.27, 0.0, 0.0],
                    Some([
                        4466.54,
                        26_116.9,
                        25_854.0,
                        0.000_158_947,
                        -3204.91,
                        2.330_23e-5,
                    ]),
                );
            }
            Model::MercedesBenzSprinter => {
                p.time_0_to_100 = f(14.0);
                p.engine = engine(
                    Combustion,
                    250.0,
                    50_000.0,
                    800.0,
                    4000.0,
                    [600.0, 0.2, 0.0],
                );
                p.brake_coefficient = f(3500.0);
                p.max_velocity = f(29.18);
                p.suspension_front_spring_constant = f(200_000.0);
                p.suspension_front_damping_constant = f(5000.0);
                p.suspension_rear_spring_constant = f(600_000.0);
                p.suspension_rear_damping_constant = f(5000.0);
                p.max_steering_torque = f(13_000.0);
                p.translation = [T::ZERO, T::ZERO, f(0.4445)];
                p.body = body(4500.0, [1.5, 0.0, 0.0], None);
            }
            Model::GreenPowerEVStar => {
                p.time_0_to_100 = f(24.0);
                p.engine = engine(
                    Electric,
                    1200.0,
                    150_000.0,
                    1200.0,
                    4000.0,
                    DEF_COEFFICIENTS,
                );
                p.gear_ratios = gear_ratios(&[-2.0, 2.0]);
                p.brake_coefficient = f(3500.0);
                p.max_velocity = f(40.0);
                p.suspension_front_spring_constant = f(200_000.0);
                p.suspension_front_damping_constant = f(6000.0);
                p.suspension_rear_spring_constant = f(750_000.0);
                p.suspension_rear_damping_constant = f(6000.0);
                p.max_steering_torque = f(15_000.0);
                // Y-up translation (0, 0.4445, 0) and centre of mass (0, 0, 1.5).
                p.translation = [T::ZERO, T::ZERO, f(0.4445)];
                p.body = body(6500.0, [1.5, 0.0, 0.0], None);
            }
            Model::Bus => {
                p.time_0_to_100 = f(25.0);
                p.engine = engine(Combustion, 250.0, 50_000.0, 700.0, 2250.0, BUS_COEFFICIENTS);
                p.gear_ratios = gear_ratios(&[-14.0, 16.0, 11.0, 7.0, 4.5, 3.0, 1.9, 1.2]);
                p.brake_coefficient = f(3500.0);
                p.min_steering_angle = f(-0.4);
                p.max_steering_angle = f(0.4);
                p.suspension_front_spring_constant = f(1.0e6);
                p.suspension_front_damping_constant = f(10_000.0);
                p.suspension_rear_spring_constant = f(1.0e6);
                p.suspension_rear_damping_constant = f(10_000.0);
                p.wheels_damping_constant = f(20.0);
                p.translation = [T::ZERO, T::ZERO, f(0.55)];
                p.body = body(8000.0, [2.25, 0.0, 0.1], None);
            }
            Model::Truck => {
                p.drive_type = DriveType::FourByFour;
                // 25 s is the PROTO's value with its trailer (18 s without).
                p.time_0_to_100 = f(25.0);
                p.engine = engine(Combustion, 250.0, 50_000.0, 700.0, 2250.0, BUS_COEFFICIENTS);
                p.gear_ratios = gear_ratios(&[
                    -14.77, 16.0, 13.0, 11.0, 9.0, 7.0, 6.0, 4.5, 3.7, 3.0, 2.4, 1.9, 1.5, 1.2, 1.0,
                ]);
                p.brake_coefficient = f(5000.0);
                p.min_steering_angle = f(-0.4);
                p.max_steering_angle = f(0.4);
                p.suspension_front_spring_constant = f(1.0e6);
                p.suspension_front_damping_constant = f(10_000.0);
                p.suspension_rear_spring_constant = f(1.0e6);
                p.suspension_rear_damping_constant = f(10_000.0);
                p.wheels_damping_constant = f(30.0);
                p.translation = [T::ZERO, T::ZERO, f(0.5)];
                // Centre of mass (wheelbase − 0.75, 0, 0.1).
                p.body = body(8000.0, [5.25 - 0.75, 0.0, 0.1], None);
            }
            Model::Tractor => {
                p.drive_type = DriveType::FourByFour;
                p.time_0_to_100 = f(20.0);
                p.min_steering_angle = f(-0.94);
                p.max_steering_angle = f(0.94);
                p.suspension_front_spring_constant = f(200_000.0);
                p.suspension_rear_spring_constant = f(30_000.0);
                p.suspension_rear_damping_constant = f(2000.0);
                p.translation = [T::ZERO, T::ZERO, f(0.6)];
                // The PROTO's default rotation really is 0.13 rad about y.
                p.rotation = [T::ZERO, T::ONE, T::ZERO, f(0.13)];
                p.body = body(
                    1000.0,
                    [0.945_069_02, 0.0, 0.460_817_86],
                    Some([634.258_55, 3004.5628, 2557.88, 0.0, -792.289_08, 0.0]),
                );
            }
        }
        p
    }
}

impl fmt::Display for Model {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}
