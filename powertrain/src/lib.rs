#![no_std]
#![forbid(unsafe_code)]
//! The powertrain of the Webots automobile stack, in `no_std` Rust generic over
//! [`ackermann::Real`] (`f32` for firmware, `f64` for Webots parity): everything between the
//! throttle pedal and the wheel torques.
//!
//! * [`Engine`]: the four Webots engine models (combustion, electric, parallel and power-split
//!   hybrid), engine-side torque (N·m) as a function of engine speed (rpm);
//! * [`Gearbox`] and [`Gear`]: the total-ratio table (reverse first) and Webots' gear
//!   selection rules, with typed [`GearWarning`]s;
//! * [`Powertrain`]: the engine-speed estimate from the wheel speeds, the wheel-side output
//!   torque with Webots' 50 rad/s² wheel-acceleration limiter, per-gear top speeds and the
//!   speed-mode engine-sound "virtual gear";
//! * [`split_torque`] and [`LimitedSlip`]: torque distribution to the driven wheels with the
//!   geometric differential ratios and Webots' limited-slip integrators;
//! * [`Brake`]: the wheel brakes as friction torques, by the dry-friction rule
//!   [`coulomb_torque`];
//! * [`AutoShift`]: an opt-in automatic gearbox (Webots has none).
//!
//! Units: rad/s for wheel speeds, rad/s² for wheel accelerations, rpm (rev/min) for engine
//! speeds, N·m for torques, W for power, s for time. Wheel order is Webots' (0 FR, 1 FL, 2 RR,
//! 3 RL; [`ackermann::PerWheel`]).
//!
//! Nothing here allocates or panics: constructors validate their parameters and return a
//! [`PowertrainError`] naming the Webots field and the value; the runtime functions accept any
//! input, NaN and ±∞ included, and never return NaN or ±∞.
//! Deliberate differences from Webots are listed in the workspace's `COMPATIBILITY.md`.
//!
//! # Example: one torque-mode step of a Toyota Prius
//!
//! ```
//! use ackermann::{DifferentialRatios, DriveType, PerWheel};
//! use powertrain::{Engine, EngineParams, EngineType, Gear, Gearbox, LimitedSlip, Powertrain,
//!                  split_torque, max_signed_acceleration};
//!
//! let engine = Engine::new(EngineParams {
//!     engine_type: EngineType::PowerSplitHybrid,
//!     max_torque: 350.0_f64,
//!     max_power: 33_000.0,
//!     min_rpm: 1200.0,
//!     max_rpm: 6500.0,
//!     function_coefficients: [65.0, 0.0225, -0.000_002_5],
//!     hybrid_power_split_ratio: 0.2778,
//!     hybrid_power_split_rpm: 3000.0,
//! })?;
//! let powertrain = Powertrain::new(engine, Gearbox::new(&[-6.0, 6.0])?);
//! let mut lsd = LimitedSlip::new();
//!
//! // Inputs of this step: measured wheel speeds (rad/s) and accelerations (rad/s²).
//! let speeds = PerWheel::new(20.0, 20.0, 20.0, 20.0);
//! let accelerations = PerWheel::new(1.0, 1.0, 0.5, 0.5);
//!
//! let gear = Gear::FIRST;
//! let rpm = powertrain.rpm(&speeds, gear); // 20·60/(2π)·6 = 1145.9 rpm
//! lsd.update(DriveType::Traction, &speeds);
//! let out = powertrain.output_torque(rpm, 0.8, gear, max_signed_acceleration(&accelerations));
//! let ratios = lsd.apply(&DifferentialRatios::EVEN); // driving straight
//! let torques = split_torque(out, DriveType::Traction, &ratios);
//!
//! // Below 1200 rpm only the electric motor pulls: 33 000·60/(2π·1145.9) = 275 N·m,
//! // × 0.8 throttle × 6 = 1320 N·m, half on each front wheel.
//! assert!((torques.as_array()[0] - 660.0).abs() < 1e-9);
//! assert_eq!(torques.as_array()[2], 0.0);
//! # Ok::<(), powertrain::PowertrainError>(())
//! ```

mod auto_shift;
mod brake;
mod engine;
mod error;
mod gearbox;
mod limited_slip;
mod powertrain;
mod split;

pub use auto_shift::{AutoShift, AutoShiftParams};
pub use brake::{Brake, DEFAULT_BRAKE_COEFFICIENT, coulomb_torque};
pub use engine::{Engine, EngineParams, EngineType};
pub use error::{Field, PowertrainError};
pub use gearbox::{Gear, GearSelection, GearWarning, Gearbox};

/// Most ratios a [`Gearbox`] holds, reverse included (the Webots Truck, the largest shipped
/// table, has 15). Fixed so that a gearbox needs no heap: 16 ratios of `f64` take 128 bytes.
/// (Here, not in `gearbox`, because the errors name it too.)
pub const MAX_GEAR_RATIOS: usize = 16;
pub use limited_slip::LimitedSlip;
pub use powertrain::{
    Powertrain, VirtualGear, WHEEL_ACCELERATION_LIMIT, acceleration_limit_factor,
    max_signed_acceleration, mean_wheel_speed,
};
pub use split::split_torque;

// Compiles and runs the README example as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
