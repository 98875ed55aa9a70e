//! Field paths: a `Car` field, or a `VehicleWheel` field of one wheel slot or of all four,
//! parsed once from its Webots name (`"trackFront"`, `"wheelRearLeft.tireRadius"`,
//! `"wheels.mass"`) and then handled as enums.

use core::fmt;

use ackermann::Wheel;
use proto_geom::WheelField;

use super::field::{CarField, FieldKind};

/// The Webots `Car` field that holds the wheel of slot `wheel` (`"wheelFrontRight"`, …).
pub const fn wheel_slot_name(wheel: Wheel) -> &'static str {
    match wheel {
        Wheel::FrontRight => "wheelFrontRight",
        Wheel::FrontLeft => "wheelFrontLeft",
        Wheel::RearRight => "wheelRearRight",
        Wheel::RearLeft => "wheelRearLeft",
    }
}

/// The wheel slot prefix of a wheel field path: one `Car` wheel slot, or `wheels` for all four.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum WheelSlot {
    /// One slot (`wheelFrontRight`, …, see [`wheel_slot_name`]).
    One(Wheel),
    /// All four slots at once (`wheels`, not a Webots field).
    All,
}

impl WheelSlot {
    /// Every prefix: the four slots in wheel order, then `wheels`.
    pub const ALL: [WheelSlot; 5] = [
        WheelSlot::One(Wheel::FrontRight),
        WheelSlot::One(Wheel::FrontLeft),
        WheelSlot::One(Wheel::RearRight),
        WheelSlot::One(Wheel::RearLeft),
        WheelSlot::All,
    ];

    /// The prefix as written (`"wheelFrontRight"`, …, `"wheels"`).
    pub const fn webots_name(self) -> &'static str {
        match self {
            WheelSlot::One(wheel) => wheel_slot_name(wheel),
            WheelSlot::All => "wheels",
        }
    }

    /// The prefix written `name` (exact, case-sensitive), or `None`.
    pub fn from_webots_name(name: &str) -> Option<WheelSlot> {
        WheelSlot::ALL.into_iter().find(|s| s.webots_name() == name)
    }
}

impl fmt::Display for WheelSlot {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}

/// A numeric `VehicleWheel` field that can be set after a [`WheelSlot`]: every
/// [`WheelField`] but `physics`, whose `Physics` node is set by its `mass` or its `density`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum WheelSetting {
    /// The field itself (lengths in m; `subdivision`, `edgeSubdivision` and `rimBeamNumber`
    /// take integers). `Field(WheelField::Physics)` is not a setting: [`WheelSetting::ALL`]
    /// and the parsers never give it, and setting it is refused as an unknown field.
    Field(WheelField),
    /// `mass` of the wheel's `Physics` node (kg).
    Mass,
    /// `density` of the wheel's `Physics` node (kg/m³).
    Density,
}

impl WheelSetting {
    /// Every setting, in the order of [`CarParams::WHEEL_FIELD_NAMES`](super::CarParams::WHEEL_FIELD_NAMES).
    pub const ALL: [WheelSetting; 14] = {
        use WheelField as F;
        use WheelSetting::Field;
        [
            Field(F::Thickness),
            Field(F::TireRadius),
            Field(F::Subdivision),
            Field(F::CurvatureFactor),
            Field(F::EdgeSubdivision),
            Field(F::RimRadius),
            Field(F::RimBeamNumber),
            Field(F::RimBeamWidth),
            Field(F::CentralInnerRadius),
            Field(F::CentralOuterRadius),
            Field(F::RimBeamThickness),
            Field(F::RimBeamOffset),
            WheelSetting::Mass,
            WheelSetting::Density,
        ]
    };

    /// The name after the slot prefix (`"tireRadius"`, …, `"mass"`, `"density"`).
    pub const fn webots_name(self) -> &'static str {
        match self {
            WheelSetting::Field(field) => field.webots_name(),
            WheelSetting::Mass => "mass",
            WheelSetting::Density => "density",
        }
    }

    /// The setting named `name` (exact, case-sensitive), or `None`.
    pub fn from_webots_name(name: &str) -> Option<WheelSetting> {
        WheelSetting::ALL
            .into_iter()
            .find(|s| s.webots_name() == name)
    }

    /// The `VehicleWheel` field it sets (`physics` for `mass` and `density`), as validation
    /// warnings name it.
    pub const fn field(self) -> WheelField {
        match self {
            WheelSetting::Field(field) => field,
            WheelSetting::Mass | WheelSetting::Density => WheelField::Physics,
        }
    }
}

impl fmt::Display for WheelSetting {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}

/// A field [`CarParams::set`](super::CarParams::set) sets, parsed from its Webots name.
///
/// ```
/// use vehicle_model::{CarField, FieldKind, FieldPath, Wheel, WheelSetting, WheelSlot};
/// assert_eq!(FieldPath::parse("trackFront"), Some(FieldPath::Car(CarField::TrackFront)));
/// let mass = FieldPath::parse("wheelRearLeft.mass").unwrap();
/// assert_eq!(mass, FieldPath::Wheel(WheelSlot::One(Wheel::RearLeft), WheelSetting::Mass));
/// assert_eq!((mass.kind(), mass.to_string().as_str()), (FieldKind::Number, "wheelRearLeft.mass"));
/// assert_eq!(FieldPath::parse("wheels.physics"), None);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FieldPath {
    /// A field of the car ([`CarParams::FIELD_NAMES`](super::CarParams::FIELD_NAMES)).
    Car(CarField),
    /// A wheel field, `<slot>.<setting>`.
    Wheel(WheelSlot, WheelSetting),
}

impl FieldPath {
    /// The path written `name`: a [`CarField`] name, or `<slot>.<setting>` with a
    /// [`WheelSlot`] and a [`WheelSetting`] name (exact, case-sensitive); `None` otherwise.
    pub fn parse(name: &str) -> Option<FieldPath> {
        match name.split_once('.') {
            Some((slot, setting)) => Some(FieldPath::Wheel(
                WheelSlot::from_webots_name(slot)?,
                WheelSetting::from_webots_name(setting)?,
            )),
            None => CarField::from_webots_name(name).map(FieldPath::Car),
        }
    }

    /// The kind of value the field takes (one number for every wheel field).
    pub const fn kind(self) -> FieldKind {
        match self {
            FieldPath::Car(field) => field.kind(),
            FieldPath::Wheel(..) => FieldKind::Number,
        }
    }
}

impl fmt::Display for FieldPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FieldPath::Car(field) => f.write_str(field.webots_name()),
            FieldPath::Wheel(slot, setting) => write!(f, "{slot}.{setting}"),
        }
    }
}
