#![no_std]
#![forbid(unsafe_code)]
//! The Webots automobile stack's "ECU": the `Car` / `AckermannVehicle` parameters, the car
//! models shipped with Webots, and the driver and car controller libraries (`libdriver`,
//! `libcar`) as one allocation-free, panic-free state machine, generic over `f32` (firmware)
//! and `f64` (Webots parity).
//!
//! * [`CarParams`]: every `Car`, `AckermannVehicle` and `VehicleWheel` field with its Webots
//!   default and validation ([`CarParams::validate`]: invalid → default + [`ParamWarning`]),
//!   settable by Webots name ([`CarParams::set_field`]).
//! * [`Model`]: the plain `Car` and the models shipped with Webots (`Model::BmwX5`, …, the
//!   vehicles of [`proto_geom::ShippedVehicle`]; [`Model::ALL`], [`Model::from_name`],
//!   [`Model::params`]).
//! * [`Driver`]: the control loop. Setters take the driver's commands and return the
//!   [`Warning`] Webots would print; [`Driver::step`] takes the [`Sensors`] and returns the
//!   actuator [`Commands`] (steering targets, per-wheel [`WheelDrive`] and brake torque,
//!   [`Lights`], [`Cockpit`], [`Sounds`]).
//! * [`actuator`]: the Webots motor rules a host applies those commands with, defined once for
//!   every host (the `sim` crate, firmware plant models): the speed-mode
//!   [`actuator::VelocityRamp`], the position controller [`actuator::PositionServo`], the
//!   steering motor [`actuator::SteeringMotor`] (within `maxSteeringTorque`), the torque-mode
//!   and free wheel spin [`actuator::WheelSpin`] (`wheelsDampingConstant`) and the dry-friction
//!   brake rule [`actuator::coulomb_torque`].
//!
//! The steering geometry and the engine, gearbox, differential and brake models are those of
//! the [`ackermann`] and [`powertrain`] crates; wheels and sensor slots come from
//! [`proto_geom`].
//!
//! Frame and units: x forward, y left, z up, origin at the rear-axle centre; rad, rad/s, m,
//! m/s, N·m, W, rpm, s. The Webots-named speed functions use km/h as Webots does
//! ([`Driver::set_cruising_speed`], [`Driver::current_speed`]). Positive steering turns right.
//! Wheel order FR, FL, RR, RL.
//!
//! # A complete control loop
//!
//! The host (a simulator, or firmware reading real sensors) calls [`Driver::step`] once per
//! `basicTimeStep` with the readings at the start of the step and applies the returned commands
//! while it advances by one step. Here a toy plant stands in for the physics: each wheel
//! follows its velocity command through the motor's ramp limit, and the steering motors reach
//! their targets within the step.
//!
//! ```
//! use vehicle_model::{Driver, Model, PerWheel, Sensors, WheelAngles, WheelDrive};
//!
//! let (mut driver, report) = Driver::<f32>::new(Model::BmwX5.params(), 10);
//! assert!(report.is_empty());
//! let dt = 0.010_f32; // s
//!
//! driver.set_cruising_speed(20.0); // km/h
//! driver.set_steering_angle(0.2); // rad, to the right
//!
//! let mut wheel_angle = PerWheel::splat(0.0_f32); // rad
//! let mut wheel_speed = PerWheel::splat(0.0_f32); // rad/s
//! let mut steering = WheelAngles::new(0.0_f32, 0.0);
//! for k in 0..300 {
//!     let sensors = Sensors {
//!         time: k as f32 * dt,
//!         wheel_angles: wheel_angle,
//!         steering,
//!         wiper: None,
//!     };
//!     let commands = driver.step(&sensors);
//!     // The plant: apply the commands for one step.
//!     for (i, drive) in commands.drive.iter().enumerate() {
//!         if let WheelDrive::Velocity { target, acceleration, max_velocity } = *drive {
//!             let target = target.clamp(-max_velocity, max_velocity);
//!             let dv = (target - wheel_speed.0[i]).clamp(-acceleration * dt, acceleration * dt);
//!             wheel_speed.0[i] += dv;
//!         }
//!         wheel_angle.0[i] += wheel_speed.0[i] * dt;
//!     }
//!     steering = commands.steering;
//! }
//! // After 3 s the car cruises at 20 km/h (measured one step behind).
//! assert!((driver.current_speed() - 20.0).abs() < 0.01);
//! assert!((driver.steering_angle() - 0.2).abs() < 0.01); // mean of the wheel angles
//! ```
//!
//! # Webots function table
//!
//! Every function of Webots' `driver.h` and `car.h` and its Rust counterpart. Functions marked
//! *C layer* concern the singleton or the C types and are for a C API to implement on top.
//!
//! | Webots | Rust |
//! |---|---|
//! | `wbu_driver_init` (+ `wbu_car_init`) | [`Driver::new`] |
//! | `wbu_driver_cleanup`, `wbu_car_cleanup` | drop the [`Driver`] (*C layer*) |
//! | `wbu_driver_initialization_is_possible` | *C layer* (always possible here) |
//! | `wbu_driver_step` | [`Driver::step`] |
//! | `wbu_driver_set_steering_angle` | [`Driver::set_steering_angle`] |
//! | `wbu_driver_get_steering_angle` | [`Driver::steering_angle`] |
//! | `wbu_driver_set_cruising_speed` | [`Driver::set_cruising_speed`] |
//! | `wbu_driver_get_target_cruising_speed` | [`Driver::target_cruising_speed`] |
//! | `wbu_driver_get_current_speed` | [`Driver::current_speed`] |
//! | `wbu_driver_set_throttle` | [`Driver::set_throttle`] |
//! | `wbu_driver_get_throttle` | [`Driver::throttle`] |
//! | `wbu_driver_set_brake_intensity` | [`Driver::set_brake_intensity`] |
//! | `wbu_driver_get_brake_intensity` | [`Driver::brake_intensity`] |
//! | `wbu_driver_set_brake` / `wbu_driver_get_brake` (deprecated) | the two above + [`Warning::Deprecated`] |
//! | `wbu_driver_set_indicator` | [`Driver::set_indicator`] ([`IndicatorState::try_from_webots_value`]) |
//! | `wbu_driver_get_indicator` | [`Driver::indicator`] |
//! | `wbu_driver_set_hazard_flashers` | [`Driver::set_hazard_flashers`] |
//! | `wbu_driver_get_hazard_flashers` | [`Driver::hazard_flashers`] |
//! | `wbu_driver_set_dipped_beams` | [`Driver::set_dipped_beams`] |
//! | `wbu_driver_get_dipped_beams` | [`Driver::dipped_beams`] |
//! | `wbu_driver_set_antifog_lights` | [`Driver::set_antifog_lights`] |
//! | `wbu_driver_get_antifog_lights` | [`Driver::antifog_lights`] |
//! | `wbu_driver_get_rpm` | [`Driver::rpm`] |
//! | `wbu_driver_set_gear` | [`Driver::set_gear`] |
//! | `wbu_driver_get_gear` | [`Driver::gear`] |
//! | `wbu_driver_get_gear_number` | [`Driver::gear_number`] |
//! | `wbu_driver_get_control_mode` | [`Driver::control_mode`] |
//! | `wbu_driver_set_wiper_mode` (`..._wipers_mode`) | [`Driver::set_wiper_mode`] ([`WiperMode::try_from_webots_value`]) |
//! | `wbu_driver_get_wiper_mode` (`..._wipers_mode`) | [`Driver::wiper_mode`] |
//! | `wbu_car_get_type` | [`Driver::drive_type`] |
//! | `wbu_car_get_engine_type` | [`Driver::engine_type`] |
//! | `wbu_car_set_indicator_period` | [`Driver::set_indicator_period`] |
//! | `wbu_car_get_indicator_period` | [`Driver::indicator_period`] |
//! | `wbu_car_get_backwards_lights` | [`Driver::backwards_lights`] |
//! | `wbu_car_get_brake_lights` | [`Driver::brake_lights`] |
//! | `wbu_car_get_track_front` / `_track_rear` | [`Driver::track_front`] / [`Driver::track_rear`] |
//! | `wbu_car_get_wheelbase` | [`Driver::wheelbase`] |
//! | `wbu_car_get_front_wheel_radius` / `_rear_` | [`Driver::front_wheel_radius`] / [`Driver::rear_wheel_radius`] |
//! | `wbu_car_get_wheel_encoder` | [`Driver::wheel_encoder`] ([`wheel_from_webots_index`]) |
//! | `wbu_car_get_wheel_speed` | [`Driver::wheel_speed`] ([`wheel_from_webots_index`]) |
//! | `wbu_car_set_right_steering_angle` / `_left_` | [`Driver::set_right_steering_angle`] / [`Driver::set_left_steering_angle`] |
//! | `wbu_car_get_right_steering_angle` / `_left_` | [`Driver::right_steering_angle`] / [`Driver::left_steering_angle`] |
//! | `wbu_car_enable_limited_slip_differential` | [`Driver::enable_limited_slip_differential`] |
//! | `wbu_car_enable_indicator_auto_disabling` | [`Driver::enable_indicator_auto_disabling`] |
//!
//! Extensions (not in Webots): [`Driver::set_automatic_gearbox`], [`Driver::commanded_steering_angle`],
//! [`Driver::commanded_wheel_angles`], [`Driver::limited_slip`], [`Driver::warning_count`],
//! [`Driver::set_brake_balance`] and [`Driver::brake_front_share`].
//!
//! # Differences from Webots
//!
//! Listed in `COMPATIBILITY.md` (section `vehicle-model`): `set_gear(gear_number)` engages the
//! highest real gear; no NaN ever leaves the library (speeds, encoders and steering read-back
//! are 0 until measured); braking is a friction torque that holds a stopped wheel; the
//! speed-mode engine-sound volume uses `min` as intended; NaN/∞ arguments, non-positive
//! indicator periods and out-of-range enum values are refused with a warning.

/// The README's example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

pub mod actuator;
mod aero;
mod brake_balance;
mod driveline;
mod driver;
pub mod energy;
mod io;
mod lights;
mod mode;
mod model;
mod params;
mod pure_pursuit;
mod road_load;
mod sound;
pub mod tyre;
mod warning;
mod wipers;

pub use aero::{Aero, AeroError, AeroForces, SEA_LEVEL_AIR_DENSITY};
pub use brake_balance::{
    BrakeBalance, BrakeBalanceError, axle_brake_factor, proportioned_front_share,
};
pub use driveline::{Driveline, ENGINE_MASS_FACTOR};
pub use driver::{
    DEFAULT_BASIC_TIME_STEP_MS, Driver, INDICATOR_AUTO_DISABLING_THRESHOLD, wheel_from_webots_index,
};
pub use io::{Cockpit, Commands, Sensors, WheelDrive};
pub use lights::{DEFAULT_INDICATOR_PERIOD, Lights, blink_on};
pub use mode::{ControlMode, IndicatorState, WiperMode};
pub use model::{EpaTestCar, EpaTransmission, Model};
pub use params::{
    BODY_HEIGHT_PER_TRACK, BODY_LENGTH_PER_WHEELBASE, BodyPhysics, CarField, CarParams,
    DEFAULT_BODY_MASS, DEFAULT_GEAR_RATIOS, EngineSound, FieldError, FieldKind, FieldPath,
    FieldValue, GearRatios, MAX_PARAM_WARNINGS, NumberRule, ParamReport, ParamWarning, Refusal,
    WheelMotor, WheelSetting, WheelSlot, is_physical_inertia, wheel_slot_name,
};
pub use pure_pursuit::{LOOKAHEAD_TIME, MIN_LOOKAHEAD, PurePursuit, PurePursuitError};
pub use road_load::{RoadLoad, RoadLoadError};
pub use sound::{BLINKER_SOUND_FILE, SoundCommand, Sounds};
pub use tyre::{
    ContactVelocity, Direction, FreeSpin, Linearised, MagicFormula, SlipCurve, SpinPrediction,
    SpinStep, TirError, TirErrorKind, TirFile, TransientSlip, TyreClass, TyreError, TyreField,
    TyreModel, TyreParams, WebotsContact,
};
pub use warning::{EnumKind, Warning};
pub use wipers::{
    WIPER_END_TOLERANCE, WIPER_FAST_VELOCITY, WIPER_SLOW_VELOCITY, WiperCommand, WiperRange,
};

pub use ackermann::{DriveType, Geometry, PerWheel, Real, Wheel, WheelAngles};

/// km/h per m/s: the factor between the Webots API's speeds (km/h) and the SI ones.
pub const KMH_PER_MS: f64 = 3.6;
/// rad/s per rpm (`π/30`): Webots gives engine speeds in rpm, the model works in rad/s.
pub const RAD_PER_S_PER_RPM: f64 = core::f64::consts::PI / 30.0;
pub use powertrain::{AutoShiftParams, EngineParams, EngineType, Gear};
pub use proto_geom::{DEFAULT_WHEEL_DENSITY, SensorSlots, WheelParams, WheelPhysics};
