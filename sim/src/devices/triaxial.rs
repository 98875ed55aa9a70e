//! Webots' three-axis sensors (spec §5): `Gyro` (angular velocity, rad/s), `Accelerometer`
//! (specific force, m/s²) and `Compass` (north direction, unitless), each in the device frame,
//! through a lookup table per component.

use proto_geom::nalgebra::Vector3;

use crate::error::ParamError;
use crate::rng::SplitMix64;

use super::lookup::LookupTable;
use super::noise::discretize;
use super::{Axes, DevicePoint, check_resolution};

/// The fields shared by `Gyro`, `Accelerometer` and `Compass`, with Webots' defaults
/// ([`Default`]).
#[derive(Debug, Clone, PartialEq)]
pub struct TriaxialSettings {
    /// `lookupTable` (default empty: the measured value, no noise), applied to each component.
    pub lookup_table: LookupTable,
    /// `xAxis`, `yAxis`, `zAxis` (default all true): a disabled axis reads NaN.
    pub axes: Axes,
    /// `resolution` (the output's unit, −1 or > 0; default −1: none).
    pub resolution: f64,
}

impl Default for TriaxialSettings {
    fn default() -> Self {
        TriaxialSettings {
            lookup_table: LookupTable::default(),
            axes: Axes::default(),
            resolution: -1.0,
        }
    }
}

impl TriaxialSettings {
    /// Checks `resolution` (the lookup table was checked when it was made).
    ///
    /// # Errors
    /// A [`ParamError`] naming `resolution` and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        check_resolution("resolution", self.resolution)
    }
}

/// What a three-axis sensor measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Quantity {
    /// Angular velocity (rad/s) of the body, device axes.
    AngularVelocity,
    /// Specific force (m/s²) of the device point, device axes: `Rᵀ·(−g + Δv/Δt)`.
    SpecificForce,
    /// The unit vector towards north, world +y (ENU), device axes.
    North,
}

/// The accelerometer's velocity at its previous sample (m/s, world axes); 0 before the first,
/// as in Webots, so that the first sample of a moving car includes `v/Δt`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct PreviousVelocity(Vector3<f64>);

/// The physical vector of `quantity` at `point` in device axes, `dt` s after the previous
/// sample.
pub(crate) fn physical(
    quantity: Quantity,
    point: &DevicePoint,
    dt: f64,
    previous: &mut PreviousVelocity,
) -> Vector3<f64> {
    let to_device = point.rotation.inverse();
    match quantity {
        Quantity::AngularVelocity => to_device * point.angular_velocity,
        Quantity::SpecificForce => {
            let acceleration = (point.velocity - previous.0) / dt;
            previous.0 = point.velocity;
            to_device * (acceleration - point.gravity)
        }
        Quantity::North => (to_device * Vector3::y()).normalize(),
    }
}

/// The sample of `settings` for the physical vector `v`: the lookup table per component, NaN
/// on a disabled axis, then `resolution`.
pub(crate) fn respond(
    settings: &TriaxialSettings,
    v: &Vector3<f64>,
    rng: &mut SplitMix64,
) -> Vector3<f64> {
    let enabled = [settings.axes.x, settings.axes.y, settings.axes.z];
    Vector3::from_fn(|i, _| {
        let value = if enabled[i] {
            settings.lookup_table.apply(v[i], rng)
        } else {
            f64::NAN
        };
        discretize(value, settings.resolution)
    })
}
