//! The preset table: one row per model of every `Car` field its PROTO sets (spec §5).
//!
//! Every figure is in the car frame (x forward, y left, z up, origin at the rear-axle centre);
//! those read from older Y-up PROTO revisions (x = left, y = up, z = forward) are converted
//! with FLU = (z, x, y), inertia included
//! (`[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]_FLU = [Izz, Ixx, Iyy, Ixz, Iyz, Ixy]_Y-up`). The figures
//! are `f64`, as written in the PROTOs, and converted to the scalar type on use, so an `f32`
//! car gets the nearest `f32` of each.

use ackermann::DriveType;
use powertrain::{EngineParams, EngineType};
use proto_geom::ShippedVehicle;

use crate::params::{BodyPhysics, DEFAULT_BODY_MASS, DEFAULT_GEAR_RATIOS, EngineSound};
use crate::tyre::TyreClass;
use crate::wipers::WiperRange;

/// A model's fields, named as in [`CarParams`](crate::CarParams) (units there). The dimensions,
/// wheels and sensor slots are those of its [`ShippedVehicle`].
pub(super) struct Preset {
    /// The model's vehicle in `proto-geom`, `None` for the plain `Car`.
    pub shipped: Option<ShippedVehicle>,
    pub tyre_class: TyreClass,
    pub translation: [f64; 3],
    pub rotation: [f64; 4],
    pub min_steering_angle: f64,
    pub max_steering_angle: f64,
    pub suspension_front_spring_constant: f64,
    pub suspension_front_damping_constant: f64,
    pub suspension_rear_spring_constant: f64,
    pub suspension_rear_damping_constant: f64,
    pub wheels_damping_constant: f64,
    pub max_steering_torque: f64,
    pub drive_type: DriveType,
    pub engine: EngineParams<f64>,
    /// The `engineSound` file name (`"none"` for no sound).
    pub engine_sound: &'static str,
    pub engine_sound_rpm_reference: f64,
    pub brake_coefficient: f64,
    pub time_0_to_100: f64,
    pub max_velocity: f64,
    pub gear_ratios: &'static [f64],
    pub body: BodyPhysics<f64>,
    pub wipers: Option<WiperRange<f64>>,
}

/// The plain Webots `Car` PROTO (R2022b) with default `VehicleWheel`s and no wipers. The `Car`
/// has `physics NULL`; the body here is [`DEFAULT_BODY_MASS`] at mid-wheelbase with the
/// derived box inertia. Every other row starts from it.
const CAR: Preset = Preset {
    shipped: None,
    tyre_class: TyreClass::PassengerCar,
    translation: [0.0, 0.0, 0.4],
    rotation: [0.0, 0.0, 1.0, 0.0],
    min_steering_angle: -1.0,
    max_steering_angle: 1.0,
    suspension_front_spring_constant: 100_000.0,
    suspension_front_damping_constant: 4000.0,
    suspension_rear_spring_constant: 100_000.0,
    suspension_rear_damping_constant: 4000.0,
    wheels_damping_constant: 5.0,
    max_steering_torque: 10_000.0,
    drive_type: DriveType::Traction,
    engine: EngineParams::DEFAULT,
    engine_sound: EngineSound::DEFAULT_FILE,
    engine_sound_rpm_reference: 1000.0,
    brake_coefficient: 700.0,
    time_0_to_100: 10.0,
    max_velocity: 50.0,
    gear_ratios: &DEFAULT_GEAR_RATIOS,
    body: BodyPhysics {
        mass: DEFAULT_BODY_MASS,
        center_of_mass: [2.0, 0.0, 0.0],
        inertia: None,
    },
    wipers: None,
};

/// An engine of `engine_type` with the given limits (N·m, W, rpm, rpm) and torque curve
/// coefficients; the hybrid split keeps the `Car` defaults.
const fn engine(
    engine_type: EngineType,
    [max_torque, max_power, min_rpm, max_rpm]: [f64; 4],
    function_coefficients: [f64; 3],
) -> EngineParams<f64> {
    EngineParams {
        engine_type,
        max_torque,
        max_power,
        min_rpm,
        max_rpm,
        function_coefficients,
        ..EngineParams::DEFAULT
    }
}

/// A body of `mass` (kg) with its centre of mass (m) and, if the PROTO gives it, its inertia
/// `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` (kg·m²).
const fn body(mass: f64, center_of_mass: [f64; 3], inertia: Option<[f64; 6]>) -> BodyPhysics<f64> {
    BodyPhysics {
        mass,
        center_of_mass,
        inertia,
    }
}

/// The `Car` default torque curve `150 + 0.1·rpm` (N·m).
const DEFAULT_COEFFICIENTS: [f64; 3] = EngineParams::DEFAULT.function_coefficients;
/// The torque curve of the `Bus` and `Truck` (N·m, N·m/rpm, N·m/rpm²).
const BUS_COEFFICIENTS: [f64; 3] = [-600.0, 5.45, -0.0023];

use DriveType::{FourByFour, Propulsion};
use EngineType::{Combustion, Electric, PowerSplitHybrid};
use ShippedVehicle as V;

/// Every model: the plain `Car`, then the shipped vehicles in declaration order.
///
/// References to rows, each its own constant: a lookup with a constant model compiles to that
/// row alone, and a firmware image keeps only the rows it uses.
pub(super) const PRESETS: [&Preset; 1 + ShippedVehicle::ALL.len()] = [
    &CAR,
    &Preset {
        shipped: Some(V::BmwX5),
        time_0_to_100: 7.0,
        engine: engine(
            Combustion,
            [250.0, 50_000.0, 1000.0, 6500.0],
            [34.11, 0.136, -0.000_014_61],
        ),
        gear_ratios: &[-12.5, 12.5, 8.0, 5.35, 4.3, 4.0],
        brake_coefficient: 1800.0,
        wheels_damping_constant: 2.0,
        body: body(
            2000.0,
            [1.2975, 0.0, 0.1],
            Some([1125.07, 4473.54, 4346.1, 0.0, 846.89, 0.0]),
        ),
        wipers: Some(WiperRange { min: 0.0, max: 1.6 }),
        ..CAR
    },
    &Preset {
        shipped: Some(V::CitroenCZero),
        drive_type: Propulsion,
        time_0_to_100: 17.5,
        engine: engine(
            Electric,
            [150.0, 75_000.0, 1000.0, 8000.0],
            DEFAULT_COEFFICIENTS,
        ),
        gear_ratios: &[-6.2329, 6.2329],
        brake_coefficient: 580.0,
        min_steering_angle: -0.631,
        max_steering_angle: 0.631,
        suspension_front_spring_constant: 30_000.0,
        suspension_front_damping_constant: 5000.0,
        suspension_rear_spring_constant: 30_000.0,
        suspension_rear_damping_constant: 5000.0,
        wheels_damping_constant: 1.55,
        engine_sound: EngineSound::NONE,
        // Y-up (-0.002, 0.248, 1.180) and [2645 2534 200 / 0 0 0].
        body: body(
            1200.0,
            [1.180, -0.002, 0.248],
            Some([200.0, 2645.0, 2534.0, 0.0, 0.0, 0.0]),
        ),
        ..CAR
    },
    &Preset {
        shipped: Some(V::ToyotaPrius),
        time_0_to_100: 10.7,
        engine: EngineParams {
            hybrid_power_split_ratio: 0.2778,
            hybrid_power_split_rpm: 3000.0,
            ..engine(
                PowerSplitHybrid,
                [350.0, 33_000.0, 1200.0, 6500.0],
                [65.0, 0.0225, -0.000_002_5],
            )
        },
        gear_ratios: &[-6.0, 6.0],
        wheels_damping_constant: 1.0,
        body: body(
            1805.0,
            [1.2975, 0.0, 0.1],
            Some([1125.07, 4473.54, 4346.1, -300.0, 0.0, 0.0]),
        ),
        ..CAR
    },
    &Preset {
        shipped: Some(V::LincolnMKZ),
        drive_type: FourByFour,
        time_0_to_100: 4.97,
        engine: engine(
            Combustion,
            [250.0, 298_000.0, 1000.0, 5500.0],
            DEFAULT_COEFFICIENTS,
        ),
        gear_ratios: &[-2.94, 4.58, 2.96, 1.91, 1.45, 1.00, 0.75],
        brake_coefficient: 1400.0,
        wheels_damping_constant: 2.0,
        // Y-up (0, 0.2, 1.6).
        body: body(1950.0, [1.6, 0.0, 0.2], None),
        ..CAR
    },
    &Preset {
        shipped: Some(V::RangeRoverSportSVR),
        drive_type: FourByFour,
        time_0_to_100: 4.7,
        engine: engine(
            Combustion,
            [680.0, 50_000.0, 1000.0, 5500.0],
            DEFAULT_COEFFICIENTS,
        ),
        gear_ratios: &[-3.0, 4.696, 3.130, 2.104, 1.667, 1.285, 1.000, 0.839, 0.667],
        brake_coefficient: 1000.0,
        // Y-up (0, 0.2, 1.6).
        body: body(2700.0, [1.6, 0.0, 0.2], None),
        ..CAR
    },
    &Preset {
        shipped: Some(V::TeslaModel3),
        drive_type: Propulsion,
        time_0_to_100: 4.0,
        engine: engine(
            Electric,
            [639.0, 147_000.0, 1000.0, 25_000.0],
            DEFAULT_COEFFICIENTS,
        ),
        gear_ratios: &[-6.3, 9.0],
        brake_coefficient: 2000.0,
        suspension_front_spring_constant: 60_000.0,
        suspension_front_damping_constant: 10_000.0,
        suspension_rear_spring_constant: 60_000.0,
        suspension_rear_damping_constant: 10_000.0,
        wheels_damping_constant: 3.0,
        engine_sound: EngineSound::NONE,
        body: body(
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
        ),
        ..CAR
    },
    &Preset {
        shipped: Some(V::MercedesBenzSprinter),
        tyre_class: TyreClass::Commercial,
        time_0_to_100: 14.0,
        engine: engine(
            Combustion,
            [250.0, 50_000.0, 800.0, 4000.0],
            [600.0, 0.2, 0.0],
        ),
        brake_coefficient: 3500.0,
        max_velocity: 29.18,
        suspension_front_spring_constant: 200_000.0,
        suspension_front_damping_constant: 5000.0,
        suspension_rear_spring_constant: 600_000.0,
        suspension_rear_damping_constant: 5000.0,
        max_steering_torque: 13_000.0,
        translation: [0.0, 0.0, 0.4445],
        body: body(4500.0, [1.5, 0.0, 0.0], None),
        ..CAR
    },
    &Preset {
        shipped: Some(V::GreenPowerEVStar),
        tyre_class: TyreClass::Commercial,
        time_0_to_100: 24.0,
        engine: engine(
            Electric,
            [1200.0, 150_000.0, 1200.0, 4000.0],
            DEFAULT_COEFFICIENTS,
        ),
        gear_ratios: &[-2.0, 2.0],
        brake_coefficient: 3500.0,
        max_velocity: 40.0,
        suspension_front_spring_constant: 200_000.0,
        suspension_front_damping_constant: 6000.0,
        suspension_rear_spring_constant: 750_000.0,
        suspension_rear_damping_constant: 6000.0,
        max_steering_torque: 15_000.0,
        // Y-up translation (0, 0.4445, 0) and centre of mass (0, 0, 1.5).
        translation: [0.0, 0.0, 0.4445],
        body: body(6500.0, [1.5, 0.0, 0.0], None),
        ..CAR
    },
    &Preset {
        shipped: Some(V::Bus),
        tyre_class: TyreClass::Commercial,
        time_0_to_100: 25.0,
        engine: engine(
            Combustion,
            [250.0, 50_000.0, 700.0, 2250.0],
            BUS_COEFFICIENTS,
        ),
        gear_ratios: &[-14.0, 16.0, 11.0, 7.0, 4.5, 3.0, 1.9, 1.2],
        brake_coefficient: 3500.0,
        min_steering_angle: -0.4,
        max_steering_angle: 0.4,
        suspension_front_spring_constant: 1.0e6,
        suspension_front_damping_constant: 10_000.0,
        suspension_rear_spring_constant: 1.0e6,
        suspension_rear_damping_constant: 10_000.0,
        wheels_damping_constant: 20.0,
        translation: [0.0, 0.0, 0.55],
        body: body(8000.0, [2.25, 0.0, 0.1], None),
        ..CAR
    },
    &Preset {
        shipped: Some(V::Truck),
        tyre_class: TyreClass::Commercial,
        drive_type: FourByFour,
        // 25 s is the PROTO's value with its trailer (18 s without).
        time_0_to_100: 25.0,
        engine: engine(
            Combustion,
            [250.0, 50_000.0, 700.0, 2250.0],
            BUS_COEFFICIENTS,
        ),
        gear_ratios: &[
            -14.77, 16.0, 13.0, 11.0, 9.0, 7.0, 6.0, 4.5, 3.7, 3.0, 2.4, 1.9, 1.5, 1.2, 1.0,
        ],
        brake_coefficient: 5000.0,
        min_steering_angle: -0.4,
        max_steering_angle: 0.4,
        suspension_front_spring_constant: 1.0e6,
        suspension_front_damping_constant: 10_000.0,
        suspension_rear_spring_constant: 1.0e6,
        suspension_rear_damping_constant: 10_000.0,
        wheels_damping_constant: 30.0,
        translation: [0.0, 0.0, 0.5],
        // Centre of mass (wheelbase − 0.75, 0, 0.1).
        body: body(8000.0, [5.25 - 0.75, 0.0, 0.1], None),
        ..CAR
    },
    &Preset {
        shipped: Some(V::Tractor),
        tyre_class: TyreClass::Tractor,
        drive_type: FourByFour,
        time_0_to_100: 20.0,
        min_steering_angle: -0.94,
        max_steering_angle: 0.94,
        suspension_front_spring_constant: 200_000.0,
        suspension_rear_spring_constant: 30_000.0,
        suspension_rear_damping_constant: 2000.0,
        translation: [0.0, 0.0, 0.6],
        // The PROTO's default rotation really is 0.13 rad about y.
        rotation: [0.0, 1.0, 0.0, 0.13],
        body: body(
            1000.0,
            [0.945_069_02, 0.0, 0.460_817_86],
            Some([634.258_55, 3004.5628, 2557.88, 0.0, -792.289_08, 0.0]),
        ),
        ..CAR
    },
];

// `Model::preset` indexes the rows by discriminant after the plain `Car`.
const _: () = {
    assert!(PRESETS[0].shipped.is_none(), "the plain Car comes first");
    let mut i = 1;
    while i < PRESETS.len() {
        match PRESETS[i].shipped {
            Some(v) => assert!(v as usize + 1 == i, "PRESETS is not in declaration order"),
            None => panic!("only the first row is the plain Car"),
        }
        i += 1;
    }
};
