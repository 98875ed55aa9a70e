//! Energy flows of a car's powertrain, for every host (no heap, f32 or f64): the electric
//! machine's losses ([`MotorLosses`]), the traction battery ([`Battery`]), regenerative
//! braking blended with the friction brakes ([`RegenBlend`]) and a combustion engine's fuel
//! ([`FuelModel`]), and how a step's wheel power flows through them for each engine type
//! ([`EnergyParams::flow`]). Webots has none of them (its robots' `battery` field only counts down a
//! motor's torque × `consumptionFactor`).

mod battery;
mod drive_cap;
mod flow;
mod fuel;
mod motor;
mod regen;

pub use battery::{Battery, BatteryError, BatteryStep, OCV_POINTS};
pub use drive_cap::DriveCap;
pub use flow::{DriveState, EnergyParams, PowerFlow, SUSTAIN_BELOW};
pub use fuel::{FuelModel, PETROL_DENSITY, PETROL_LHV};
pub use motor::{MotorError, MotorLosses};
pub use regen::{BrakeSplit, RegenBlend};
