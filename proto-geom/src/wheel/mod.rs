//! The Webots `VehicleWheel` PROTO: fields, validation, shipped wheels, collision and mass.

mod collision;
mod params;
mod preset;
mod validate;
mod warning;

pub use collision::{BoundingCylinder, MassProperties};
pub use params::{
    DEFAULT_WHEEL_DENSITY, PbrAppearance, WheelParams, WheelPhysics, WheelShape, WheelSide,
    slot_name,
};
pub use preset::WheelPreset;
pub use validate::{MAX_EDGE_SUBDIVISION, MAX_RIM_BEAM_NUMBER, MAX_SUBDIVISION, ValidWheel};
pub use warning::{
    MAX_WHEEL_WARNINGS, Requirement, WheelField, WheelRule, WheelWarning, WheelWarnings,
};
