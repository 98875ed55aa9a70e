//! Webots' `InertialUnit` (spec §4): the device's orientation in the world, as a quaternion and
//! as roll, pitch and yaw.

use proto_geom::nalgebra::{Quaternion, Unit, UnitQuaternion, Vector3};

use crate::attitude::RollPitchYaw;
use crate::error::ParamError;
use crate::rng::SplitMix64;

use super::noise::{discretize, gaussian};
use super::{Axes, DevicePoint, check_resolution};

/// The fields of an `InertialUnit` node, with Webots' defaults ([`Default`]). The deprecated
/// `lookupTable` is not held.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InertialUnitSettings {
    /// `noise` (in [0, 1); default 0): each sample is turned by roll, pitch and yaw angles of
    /// standard deviation `noise·π` rad (Webots' code; its manual says π/2 at 1).
    pub noise: f64,
    /// `xAxis`, `yAxis`, `zAxis` (default all true).
    pub axes: Axes,
    /// `resolution` (−1 or > 0; default −1: none), applied to each quaternion component.
    pub resolution: f64,
}

impl Default for InertialUnitSettings {
    fn default() -> Self {
        InertialUnitSettings {
            noise: 0.0,
            axes: Axes::default(),
            resolution: -1.0,
        }
    }
}

impl InertialUnitSettings {
    /// Checks every field against Webots' range.
    ///
    /// # Errors
    /// A [`ParamError`] naming the Webots field and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::check("noise", self.noise, "in [0, 1)", |n| {
            (0.0..1.0).contains(&n)
        })?;
        check_resolution("resolution", self.resolution)
    }
}

/// An inertial-unit sample: the quaternion the simulator sends (`[x, y, z, w]`, NaN before the
/// first sample), from which the library computes roll, pitch and yaw.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InertialUnitReading {
    /// The device-to-world rotation after noise, disabled axes and `resolution` (so not always
    /// of unit norm). Webots: `wb_inertial_unit_get_quaternion`.
    pub quaternion: Quaternion<f64>,
}

impl InertialUnitReading {
    /// The reading before the first sample: NaN (Webots returns uninitialised memory).
    pub(crate) fn unsampled() -> Self {
        InertialUnitReading {
            quaternion: Quaternion::new(f64::NAN, f64::NAN, f64::NAN, f64::NAN),
        }
    }

    /// Roll, pitch and yaw (rad) by the Webots library's conversion for an ENU world
    /// (`R = Rz(yaw)·Ry(pitch)·Rx(roll)`): yaw 0 with the device's x axis east (world +x),
    /// π/2 north (world +y); pitch > 0 with the x axis below the horizon; roll and yaw in
    /// [−π, π], pitch in [−π/2, π/2]. Webots: `wb_inertial_unit_get_roll_pitch_yaw`.
    pub fn roll_pitch_yaw(&self) -> RollPitchYaw {
        let q = self.quaternion;
        let (x, y, z, w) = (q.i, q.j, q.k, q.w);
        RollPitchYaw {
            roll: (2.0 * (w * x + y * z)).atan2(1.0 - 2.0 * (x * x + y * y)),
            pitch: (2.0 * (w * y - z * x)).clamp(-1.0, 1.0).asin(),
            yaw: (2.0 * (w * z + x * y)).atan2(1.0 - 2.0 * (y * y + z * z)),
        }
    }
}

/// Measures the inertial unit's orientation at `point`.
pub(crate) fn measure(
    settings: &InertialUnitSettings,
    point: &DevicePoint,
    rng: &mut SplitMix64,
) -> InertialUnitReading {
    let mut rotation = point.rotation;
    if settings.noise != 0.0 {
        let sigma = settings.noise * core::f64::consts::PI;
        let [e1, e2, e3] = [(); 3].map(|()| sigma * gaussian(rng));
        rotation *= UnitQuaternion::from_euler_angles(e1, e2, e3);
    }
    if !settings.axes.all() {
        rotation = without_axes(rotation, settings.axes);
    }
    let q = rotation.into_inner();
    InertialUnitReading {
        quaternion: Quaternion::from(q.coords.map(|c| discretize(c, settings.resolution))),
    }
}

/// Webots' disabled axes of an inertial unit: the axis–angle of the rotation with one axis
/// component zeroed and the axis renormalised. Its code names the axes as in its old
/// north-up-east frame: `xAxis` false zeroes x, `yAxis` false zeroes **z**, `zAxis` false
/// zeroes **y** (its manual says the angles become NaN). An axis left with no component (or a
/// rotation of angle 0) gives no rotation.
fn without_axes(rotation: UnitQuaternion<f64>, axes: Axes) -> UnitQuaternion<f64> {
    let Some((axis, angle)) = rotation.axis_angle() else {
        return rotation;
    };
    let mut a: Vector3<f64> = axis.into_inner();
    if !axes.x {
        a.x = 0.0;
    }
    if !axes.y {
        a.z = 0.0;
    }
    if !axes.z {
        a.y = 0.0;
    }
    Unit::try_new(a, 0.0).map_or_else(UnitQuaternion::identity, |axis| {
        UnitQuaternion::from_axis_angle(&axis, angle)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roll_pitch_yaw_of_known_rotations() {
        // Tolerance 1e-12: a few trigonometric evaluations in f64.
        let (roll, pitch, yaw) = (0.1, -0.2, 2.5);
        let q = UnitQuaternion::from_euler_angles(roll, pitch, yaw).into_inner();
        let rpy = InertialUnitReading { quaternion: q }.roll_pitch_yaw();
        assert!((rpy.roll - roll).abs() < 1e-12, "{rpy:?}");
        assert!((rpy.pitch - pitch).abs() < 1e-12, "{rpy:?}");
        assert!((rpy.yaw - yaw).abs() < 1e-12, "{rpy:?}");
        assert!(
            InertialUnitReading::unsampled()
                .roll_pitch_yaw()
                .yaw
                .is_nan()
        );
    }

    #[test]
    fn disabled_axes_follow_webots_code() {
        // A turn of 0.5 rad about world z: zAxis false zeroes the axis' y component (no
        // change), yAxis false zeroes z (no rotation left).
        let r = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.5);
        let no_z = Axes {
            z: false,
            ..Axes::default()
        };
        assert!((without_axes(r, no_z).angle() - 0.5).abs() < 1e-12);
        let no_y = Axes {
            y: false,
            ..Axes::default()
        };
        assert_eq!(without_axes(r, no_y), UnitQuaternion::identity());
    }
}
