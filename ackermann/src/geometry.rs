//! The vehicle dimensions every other computation of this crate is based on.

use core::fmt;

use crate::real::Real;

/// Right and left front-wheel steering angles (rad, positive = wheel turned to the right, i.e. a
/// rotation about −z).
///
/// Webots stores these as the car library's right/left wheel angles (set by
/// `wbu_driver_set_steering_angle` through the Ackermann formula, or directly by
/// `wbu_car_set_right_steering_angle` / `wbu_car_set_left_steering_angle`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelAngles<T: Real> {
    /// Front-right wheel steering angle (rad).
    pub right: T,
    /// Front-left wheel steering angle (rad).
    pub left: T,
}

impl<T: Real> WheelAngles<T> {
    /// Both wheels straight ahead (0 rad).
    pub const STRAIGHT: Self = WheelAngles {
        right: T::ZERO,
        left: T::ZERO,
    };

    /// Builds from the right and left angles (rad).
    #[inline]
    pub const fn new(right: T, left: T) -> Self {
        WheelAngles { right, left }
    }

    /// The mean `(right + left) / 2` (rad): what Webots' `wbu_driver_get_steering_angle`
    /// returns (from the measured angles).
    #[inline]
    pub fn mean(self) -> T {
        (self.right + self.left) * T::HALF
    }

    /// The left/right mirror image: a right turn becomes the same left turn
    /// (`right' = −left`, `left' = −right`).
    #[inline]
    pub fn mirrored(self) -> Self {
        WheelAngles {
            right: -self.left,
            left: -self.right,
        }
    }
}

/// Which dimension of a [`Geometry`] was rejected.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GeometryField {
    /// Distance between the front and rear axles (m); Webots field `wheelbase`.
    Wheelbase,
    /// Distance between the two front wheel centres (m); Webots field `trackFront`.
    TrackFront,
    /// Distance between the two rear wheel centres (m); Webots field `trackRear`.
    TrackRear,
    /// Front tyre radius (m); Webots: the front `VehicleWheel`'s `tireRadius`.
    RadiusFront,
    /// Rear tyre radius (m); Webots: the rear `VehicleWheel`'s `tireRadius`.
    RadiusRear,
}

impl GeometryField {
    /// The Rust parameter name (`"wheelbase"`, `"track_front"`, …).
    pub const fn name(self) -> &'static str {
        match self {
            GeometryField::Wheelbase => "wheelbase",
            GeometryField::TrackFront => "track_front",
            GeometryField::TrackRear => "track_rear",
            GeometryField::RadiusFront => "radius_front",
            GeometryField::RadiusRear => "radius_rear",
        }
    }
}

impl fmt::Display for GeometryField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A [`Geometry`] dimension was not finite or not strictly positive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GeometryError {
    /// The rejected dimension.
    pub field: GeometryField,
    /// The rejected value (m), widened to `f64` (exact for `f32`).
    pub value: f64,
}

impl fmt::Display for GeometryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "invalid {}: {} m (must be finite and > 0)",
            self.field, self.value
        )
    }
}

impl core::error::Error for GeometryError {}

/// The dimensions of an Ackermann vehicle (all in m, all finite and > 0).
///
/// Webots: the `wheelbase`, `trackFront`, `trackRear` fields of `AckermannVehicle` and the front
/// and rear tyre radii, as passed to the car library through `customData`
/// (`wbu_car_get_wheelbase`, `wbu_car_get_track_front`, …).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Geometry<T: Real> {
    wheelbase: T,
    track_front: T,
    track_rear: T,
    radius_front: T,
    radius_rear: T,
}

/// The Webots `Car` PROTO defaults: wheelbase 4 m, both tracks 1.7 m and, as
/// `AckermannVehicle`'s default `VehicleWheel`, tyre radii of 0.4 m.
impl<T: Real> Default for Geometry<T> {
    fn default() -> Self {
        let f = T::from_f64;
        Geometry {
            wheelbase: f(4.0),
            track_front: f(1.7),
            track_rear: f(1.7),
            radius_front: f(0.4),
            radius_rear: f(0.4),
        }
    }
}

impl<T: Real> Geometry<T> {
    /// Validates and builds a geometry from the wheelbase `L`, the front and rear tracks `Tf`,
    /// `Tr` and the front and rear tyre radii `rf`, `rr` (all m).
    ///
    /// # Errors
    /// [`GeometryError`] naming the first dimension (in argument order) that is NaN, infinite,
    /// zero or negative. (Webots uses a radius of −1 for "not found by the PROTO"; such a
    /// geometry is rejected here.)
    pub fn new(
        wheelbase: T,
        track_front: T,
        track_rear: T,
        radius_front: T,
        radius_rear: T,
    ) -> Result<Self, GeometryError> {
        let check = |field, value: T| {
            if value.is_finite() && value > T::ZERO {
                Ok(value)
            } else {
                Err(GeometryError {
                    field,
                    value: value.to_f64(),
                })
            }
        };
        Ok(Geometry {
            wheelbase: check(GeometryField::Wheelbase, wheelbase)?,
            track_front: check(GeometryField::TrackFront, track_front)?,
            track_rear: check(GeometryField::TrackRear, track_rear)?,
            radius_front: check(GeometryField::RadiusFront, radius_front)?,
            radius_rear: check(GeometryField::RadiusRear, radius_rear)?,
        })
    }

    /// Distance between the front and rear axles `L` (m).
    #[inline]
    pub fn wheelbase(&self) -> T {
        self.wheelbase
    }

    /// Distance between the front wheel centres `Tf` (m).
    #[inline]
    pub fn track_front(&self) -> T {
        self.track_front
    }

    /// Distance between the rear wheel centres `Tr` (m).
    #[inline]
    pub fn track_rear(&self) -> T {
        self.track_rear
    }

    /// Front tyre radius `rf` (m).
    #[inline]
    pub fn radius_front(&self) -> T {
        self.radius_front
    }

    /// Rear tyre radius `rr` (m).
    #[inline]
    pub fn radius_rear(&self) -> T {
        self.radius_rear
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::string::ToString;

    use super::{Geometry, GeometryError, GeometryField, WheelAngles};

    #[test]
    fn default_is_the_valid_car_proto_geometry() {
        let expected = Geometry::new(4.0_f32, 1.7, 1.7, 0.4, 0.4).unwrap();
        assert_eq!(Geometry::<f32>::default(), expected);
    }

    #[test]
    fn accepts_positive_finite_dimensions() {
        let g = Geometry::new(2.995_f64, 1.628, 1.6, 0.374, 0.38).unwrap();
        assert_eq!(
            [
                g.wheelbase(),
                g.track_front(),
                g.track_rear(),
                g.radius_front(),
                g.radius_rear()
            ],
            [2.995, 1.628, 1.6, 0.374, 0.38]
        );
    }

    #[test]
    fn rejects_the_first_bad_dimension_with_its_value() {
        let err = Geometry::new(2.0_f32, 1.5, -1.0, 0.0, f32::NAN).unwrap_err();
        assert_eq!(
            err,
            GeometryError {
                field: GeometryField::TrackRear,
                value: -1.0
            }
        );
        assert_eq!(
            err.to_string(),
            "invalid track_rear: -1 m (must be finite and > 0)"
        );
        let err = Geometry::new(2.0_f64, 1.5, 1.5, 0.3, f64::INFINITY).unwrap_err();
        assert_eq!(err.field, GeometryField::RadiusRear);
        assert_eq!(err.value, f64::INFINITY);
        let err = Geometry::new(f64::NAN, 1.5, 1.5, 0.3, 0.3).unwrap_err();
        assert_eq!(err.field, GeometryField::Wheelbase);
        assert!(err.value.is_nan());
        let err = Geometry::new(1.0, 0.0_f64, 1.5, 0.3, 0.3).unwrap_err();
        assert_eq!(err.field, GeometryField::TrackFront);
        let err = Geometry::new(1.0, 1.0_f64, 1.5, -0.0, 0.3).unwrap_err();
        assert_eq!(err.field, GeometryField::RadiusFront);
    }

    #[test]
    fn wheel_angles_helpers() {
        let a = WheelAngles::new(0.3_f64, 0.2);
        assert!((a.mean() - 0.25).abs() < 1e-15);
        assert_eq!(a.mirrored(), WheelAngles::new(-0.2, -0.3));
        assert_eq!(WheelAngles::<f32>::default(), WheelAngles::STRAIGHT);
    }
}
