//! Where an `AckermannVehicle` puts its wheels and how its joints are oriented.

use core::fmt;

use ackermann::{Geometry, GeometryError, PerWheel, Real, Wheel};

use nalgebra::{Isometry3, Point3, UnitVector3, Vector3};

use crate::glue::{flip, isometry, rotation, x_axis, y_axis, z_axis};
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
/// y left, z up, origin at the rear-axle centre at wheel-centre height; m and rad).
///
/// Sign conventions (spec §4.3), which a simulator must keep to match Webots:
/// * `steering_axis` is −z for both front wheels: a **positive** steering angle turns the
///   wheel **right** (clockwise seen from above).
/// * `spin_axis` is +y for **every** wheel: a **positive** joint velocity rolls the car
///   **forward** (+x). Webots writes the spin axis as local (1, 0, 0) on right wheels and
///   (−1, 0, 0) on left wheels; both become +y through the wheel rotation.
/// * `suspension_axis` is +z (a linear spring-damper along it).
#[derive(Debug, Clone, Copy)]
pub struct WheelFrame<T: Real> {
    /// Which wheel.
    pub wheel: Wheel,
    /// The wheel frame (Webots `Transform`), mapping wheel-frame coordinates to the vehicle
    /// frame: translation to the wheel centre, (L, ∓Tf/2, 0) in front and (0, ∓Tr/2, 0) at the
    /// rear (m), rotation +π/2 rad about z on the right and −π/2 rad on the left (Webots writes
    /// ±1.5708). Rim, hub and bounding-cylinder meshes are in this frame;
    /// it maps the wheel's local axle (+x) to +y (inwards) on the right and −y on the left, so
    /// the rim face (local −x) points outwards on both sides.
    pub pose: Isometry3<T>,
    /// The tyre mesh frame (translation in m): `pose`, followed on left wheels
    /// (`wheelSide TRUE`) by a rotation of π rad about the local z axis (Webots writes
    /// 3.141578).
    pub tyre_pose: Isometry3<T>,
    /// The wheel's `wheelSide`.
    pub side: WheelSide,
    /// Steering (Hinge2 axis 1) unit direction in the vehicle frame: `Some(−z)` for the front
    /// wheels, `None` for the rear wheels (plain hinge). A positive angle (rad) turns right.
    pub steering_axis: Option<UnitVector3<T>>,
    /// Spin axis, a unit direction in the vehicle frame: +y for every wheel (a positive
    /// velocity, rad/s, drives forward).
    pub spin_axis: UnitVector3<T>,
    /// Suspension axis, a unit direction in the vehicle frame: +z (travel in m along it).
    pub suspension_axis: UnitVector3<T>,
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
        let centre = Vector3::new(x, y, T::ZERO);
        let pose = isometry(centre, rotation(&z_axis(), angle));
        let tyre_pose = match side {
            WheelSide::Right => pose,
            // `pose` followed by π about the local z axis, which is the vehicle's z axis too:
            // one rotation of `angle + π` about z.
            WheelSide::Left => isometry(centre, rotation(&z_axis(), angle + T::PI)),
        };
        WheelFrame {
            wheel,
            pose,
            tyre_pose,
            side,
            steering_axis: wheel.is_front().then(|| flip(z_axis())),
            spin_axis: y_axis(),
            suspension_axis: z_axis(),
        }
    }

    /// The wheel centre (m, vehicle frame): the joint anchor.
    #[inline]
    pub fn centre(&self) -> Point3<T> {
        Point3::from(self.pose.translation.vector)
    }

    /// The spin axis as Webots writes it in the wheel frame (unit direction): (1, 0, 0) right,
    /// (−1, 0, 0) left.
    #[inline]
    pub fn webots_spin_axis(&self) -> UnitVector3<T> {
        if self.wheel.is_right() {
            x_axis()
        } else {
            flip(x_axis())
        }
    }

    /// The steering axis as Webots writes it in the wheel frame (unit direction): (0, 0, −1),
    /// front wheels only.
    #[inline]
    pub fn webots_steering_axis(&self) -> Option<UnitVector3<T>> {
        self.wheel.is_front().then(|| flip(z_axis()))
    }
}

// By hand: nalgebra compares isometries only for `T: RealField`, a bound `Real` does not carry.
// Equal frames have equal translations (m) and rotations (a unit quaternion and its negation are
// the same rotation, as nalgebra's `UnitQuaternion` equality says).
impl<T: Real> PartialEq for WheelFrame<T> {
    fn eq(&self, other: &Self) -> bool {
        let same = |a: &Isometry3<T>, b: &Isometry3<T>| {
            a.translation == b.translation && a.rotation == b.rotation
        };
        self.wheel == other.wheel
            && same(&self.pose, &other.pose)
            && same(&self.tyre_pose, &other.tyre_pose)
            && self.side == other.side
            && self.steering_axis == other.steering_axis
            && self.spin_axis == other.spin_axis
            && self.suspension_axis == other.suspension_axis
    }
}

/// The wheel layout of an `AckermannVehicle`: validated dimensions, the four validated wheels
/// and their frames and joint axes, everything a simulator needs to build the wheel joints.
///
/// ```
/// use ackermann::Wheel;
/// use proto_geom::ShippedVehicle;
/// use proto_geom::nalgebra::{Point3, Vector3};
///
/// let layout = ShippedVehicle::BmwX5.layout::<f64>();
/// let fr = layout.frame(Wheel::FrontRight);
/// assert_eq!(fr.centre(), Point3::new(2.995, -0.814, 0.0)); // (L, −Tf/2, 0) m
/// assert_eq!(fr.steering_axis.map(|a| a.into_inner()), Some(-Vector3::z()));
/// assert_eq!(*fr.spin_axis, Vector3::y());
/// // The wheel frame maps the wheel's axle (local +x) onto +y on the right side.
/// assert!((fr.pose * Vector3::x() - Vector3::y()).norm() < 1e-15);
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

    /// Position of the engine speaker (Webots `Speaker "engine_speaker"`): (L, 0, 0) m in the
    /// vehicle frame.
    #[inline]
    pub fn engine_speaker(&self) -> Point3<T> {
        Point3::new(self.dimensions.wheelbase, T::ZERO, T::ZERO)
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
