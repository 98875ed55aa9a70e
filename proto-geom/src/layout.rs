//! Where an `AckermannVehicle` puts its wheels and how its joints are oriented.

use core::fmt;

use ackermann::{Geometry, GeometryError, PerWheel, Real, Wheel};

use crate::math::{Isometry, Rotation, Vec3};
use crate::wheel::{ValidWheel, WheelParams, WheelSide, WheelWarnings};

/// The `AckermannVehicle` dimensions (m). `Default` gives the PROTO defaults.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VehicleDimensions<T> {
    /// Distance from the rear axle to the front axle (m; Webots field `wheelbase`, default 4).
    pub wheelbase: T,
    /// Distance between the front wheel centres (m; Webots field `trackFront`, default 1.7).
    pub track_front: T,
    /// Distance between the rear wheel centres (m; Webots field `trackRear`, default 1.7).
    pub track_rear: T,
}

impl<T: Real> Default for VehicleDimensions<T> {
    fn default() -> Self {
        VehicleDimensions {
            wheelbase: T::from_f64(4.0),
            track_front: T::from_f64(1.7),
            track_rear: T::from_f64(1.7),
        }
    }
}

/// An `AckermannVehicle` dimension named in a [`LayoutWarning`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AckermannField {
    /// Webots field `wheelbase` (m).
    Wheelbase,
    /// Webots field `trackFront` (m).
    TrackFront,
    /// Webots field `trackRear` (m).
    TrackRear,
}

impl AckermannField {
    /// The Webots field name.
    pub const fn webots_name(self) -> &'static str {
        match self {
            AckermannField::Wheelbase => "wheelbase",
            AckermannField::TrackFront => "trackFront",
            AckermannField::TrackRear => "trackRear",
        }
    }
}

/// A dimension that was ≤ 0, NaN or infinite and was replaced by its default, as the
/// `AckermannVehicle` PROTO does (Webots: "≤ 0 → default"; non-finite values are an addition).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LayoutWarning {
    /// The field.
    pub field: AckermannField,
    /// The value given (m).
    pub value: f64,
    /// The default used instead (m).
    pub replacement: f64,
}

impl fmt::Display for LayoutWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "'{}' must be strictly positive. Value reset to {}.",
            self.field.webots_name(),
            self.replacement
        )
    }
}

/// Everything [`VehicleLayout::new`] corrected: the dimensions and each wheel's fields.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LayoutWarnings {
    /// Dimension warnings, in the order wheelbase, trackFront, trackRear.
    pub dimensions: heapless::Vec<LayoutWarning, 3>,
    /// Each wheel's validation warnings.
    pub wheels: PerWheel<WheelWarnings>,
}

impl LayoutWarnings {
    /// True if nothing was reported.
    pub fn is_empty(&self) -> bool {
        self.dimensions.is_empty() && self.wheels.iter().all(WheelWarnings::is_empty)
    }
}

impl<T: Real> VehicleDimensions<T> {
    /// Replaces each dimension that is not finite and > 0 by its default (4, 1.7, 1.7 m).
    pub fn validate(&self) -> (Self, heapless::Vec<LayoutWarning, 3>) {
        let d = Self::default();
        let mut out = *self;
        let mut warnings = heapless::Vec::new();
        let fields = [
            (AckermannField::Wheelbase, &mut out.wheelbase, d.wheelbase),
            (
                AckermannField::TrackFront,
                &mut out.track_front,
                d.track_front,
            ),
            (AckermannField::TrackRear, &mut out.track_rear, d.track_rear),
        ];
        for (field, value, default) in fields {
            if !(value.is_finite() && *value > T::ZERO) {
                // Three fields, capacity three: the push cannot fail.
                let _ = warnings.push(LayoutWarning {
                    field,
                    value: value.to_f64(),
                    replacement: default.to_f64(),
                });
                *value = default;
            }
        }
        (out, warnings)
    }
}

/// One wheel of a [`VehicleLayout`]: its frame and joint axes in the vehicle frame (x forward,
/// y left, z up, origin at the rear-axle centre at wheel-centre height).
///
/// Sign conventions (spec §4.3), which a simulator must keep to match Webots:
/// * `steering_axis` is −z for both front wheels: a **positive** steering angle turns the
///   wheel **right** (clockwise seen from above).
/// * `spin_axis` is +y for **every** wheel: a **positive** joint velocity rolls the car
///   **forward** (+x). Webots writes the spin axis as local (1, 0, 0) on right wheels and
///   (−1, 0, 0) on left wheels; both become +y through the wheel rotation.
/// * `suspension_axis` is +z (a linear spring-damper along it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelFrame<T: Real> {
    /// Which wheel.
    pub wheel: Wheel,
    /// The wheel frame (Webots `Transform`): translation to the wheel centre, (L, ∓Tf/2, 0) in
    /// front and (0, ∓Tr/2, 0) at the rear (m), rotation +π/2 about z on the right and −π/2 on
    /// the left (Webots writes ±1.5708). Rim, hub and bounding-cylinder meshes are in this frame;
    /// it maps the wheel's local axle (+x) to +y (inwards) on the right and −y on the left, so
    /// the rim face (local −x) points outwards on both sides.
    pub pose: Isometry<T>,
    /// The tyre mesh frame: `pose`, followed on left wheels (`wheelSide TRUE`) by a rotation
    /// of π about the local z axis (Webots writes 3.141578).
    pub tyre_pose: Isometry<T>,
    /// The wheel's `wheelSide`.
    pub side: WheelSide,
    /// Steering (Hinge2 axis 1) direction in the vehicle frame: `Some(−z)` for the front
    /// wheels, `None` for the rear wheels (plain hinge).
    pub steering_axis: Option<Vec3<T>>,
    /// Spin axis in the vehicle frame: +y for every wheel (positive velocity drives forward).
    pub spin_axis: Vec3<T>,
    /// Suspension axis in the vehicle frame: +z.
    pub suspension_axis: Vec3<T>,
}

impl<T: Real> WheelFrame<T> {
    /// Builds the frame of `wheel` for the given dimensions and side.
    pub fn new(wheel: Wheel, dimensions: &VehicleDimensions<T>, side: WheelSide) -> Self {
        let (x, track) = if wheel.is_front() {
            (dimensions.wheelbase, dimensions.track_front)
        } else {
            (T::ZERO, dimensions.track_rear)
        };
        let (y, angle) = if wheel.is_right() {
            (-track * T::HALF, T::FRAC_PI_2)
        } else {
            (track * T::HALF, -T::FRAC_PI_2)
        };
        let pose = Isometry::new(Vec3::new(x, y, T::ZERO), Rotation::about_z(angle));
        let tyre_pose = match side {
            WheelSide::Right => pose,
            WheelSide::Left => pose * Isometry::new(Vec3::ZERO, Rotation::about_z(T::PI)),
        };
        WheelFrame {
            wheel,
            pose,
            tyre_pose,
            side,
            steering_axis: wheel.is_front().then_some(-Vec3::Z),
            spin_axis: Vec3::Y,
            suspension_axis: Vec3::Z,
        }
    }

    /// The wheel centre (m, vehicle frame): the joint anchor.
    #[inline]
    pub fn centre(&self) -> Vec3<T> {
        self.pose.translation
    }

    /// The spin axis as Webots writes it in the wheel frame: (1, 0, 0) right, (−1, 0, 0) left.
    #[inline]
    pub fn webots_spin_axis(&self) -> Vec3<T> {
        if self.wheel.is_right() {
            Vec3::X
        } else {
            -Vec3::X
        }
    }

    /// The steering axis as Webots writes it in the wheel frame: (0, 0, −1), front wheels only.
    #[inline]
    pub fn webots_steering_axis(&self) -> Option<Vec3<T>> {
        self.wheel.is_front().then_some(-Vec3::Z)
    }
}

/// The wheel layout of an `AckermannVehicle`: validated dimensions, the four validated wheels
/// and their frames and joint axes, everything a simulator needs to build the wheel joints.
///
/// ```
/// use ackermann::Wheel;
/// use proto_geom::{ShippedVehicle, Vec3};
///
/// let layout = ShippedVehicle::BmwX5.layout::<f64>();
/// let fr = layout.frame(Wheel::FrontRight);
/// assert_eq!(fr.centre(), Vec3::new(2.995, -0.814, 0.0)); // (L, −Tf/2, 0) m
/// assert_eq!(fr.steering_axis, Some(Vec3::new(0.0, 0.0, -1.0)));
/// assert_eq!(fr.spin_axis, Vec3::new(0.0, 1.0, 0.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VehicleLayout<T: Real> {
    dimensions: VehicleDimensions<T>,
    wheels: PerWheel<ValidWheel<T>>,
    frames: PerWheel<WheelFrame<T>>,
}

impl<T: Real> VehicleLayout<T> {
    /// Validates the dimensions (≤ 0 or non-finite → default) and each wheel
    /// ([`WheelParams::validate`]), then places the wheels. Never fails.
    pub fn new(
        dimensions: VehicleDimensions<T>,
        wheels: PerWheel<WheelParams<T>>,
    ) -> (Self, LayoutWarnings) {
        let (dimensions, dimension_warnings) = dimensions.validate();
        let checked = wheels.map(|w| w.validate());
        let warnings = LayoutWarnings {
            dimensions: dimension_warnings,
            wheels: checked.clone().map(|(_, w)| w),
        };
        let valid = checked.map(|(v, _)| v);
        (Self::from_valid(dimensions, valid), warnings)
    }

    /// Places already-validated wheels. Dimensions that are not finite and > 0 are replaced by
    /// their defaults (use [`VehicleDimensions::validate`] first to get the warnings).
    pub fn from_valid(dimensions: VehicleDimensions<T>, wheels: PerWheel<ValidWheel<T>>) -> Self {
        let (dimensions, _) = dimensions.validate();
        let frames =
            PerWheel::from_fn(|w| WheelFrame::new(w, &dimensions, wheels[w].params().side));
        VehicleLayout {
            dimensions,
            wheels,
            frames,
        }
    }

    /// The validated dimensions (m).
    #[inline]
    pub const fn dimensions(&self) -> &VehicleDimensions<T> {
        &self.dimensions
    }

    /// The validated wheel in slot `wheel`.
    #[inline]
    pub fn wheel(&self, wheel: Wheel) -> &ValidWheel<T> {
        &self.wheels[wheel]
    }

    /// The four validated wheels.
    #[inline]
    pub const fn wheels(&self) -> &PerWheel<ValidWheel<T>> {
        &self.wheels
    }

    /// The frame and joint axes of `wheel`.
    #[inline]
    pub fn frame(&self, wheel: Wheel) -> &WheelFrame<T> {
        &self.frames[wheel]
    }

    /// The four wheel frames.
    #[inline]
    pub const fn frames(&self) -> &PerWheel<WheelFrame<T>> {
        &self.frames
    }

    /// Position of the engine speaker (Webots `Speaker "engine_speaker"`): (L, 0, 0) m.
    #[inline]
    pub fn engine_speaker(&self) -> Vec3<T> {
        Vec3::new(self.dimensions.wheelbase, T::ZERO, T::ZERO)
    }

    /// The Ackermann geometry the car library sees: wheelbase, tracks, and the `tireRadius` of
    /// the front-right and rear-right wheels as front and rear radii (Webots never inspects the
    /// left wheels).
    ///
    /// # Errors
    /// Never in practice (every value is validated > 0); the `Result` is [`Geometry::new`]'s.
    pub fn geometry(&self) -> Result<Geometry<T>, GeometryError> {
        let d = &self.dimensions;
        Geometry::new(
            d.wheelbase,
            d.track_front,
            d.track_rear,
            self.wheels[Wheel::FrontRight].params().tire_radius,
            self.wheels[Wheel::RearRight].params().tire_radius,
        )
    }
}
