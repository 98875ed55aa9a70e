//! The wheels shipped with Webots, looked up by PROTO name.

use ackermann::Real;

use super::params::{PbrAppearance, WheelParams, WheelPhysics, WheelShape};

/// A wheel shipped with Webots (or one of the two `VehicleWheel` defaults).
///
/// [`WheelPreset::params`] gives the fields as the shipped *car* uses the wheel: the wheel PROTOs
/// themselves default to `physics NULL`, and each car gives its wheels a `Physics` node, whose
/// mass is reproduced here (spec §5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum WheelPreset {
    /// `VehicleWheel {}` with its R2023b defaults (used by `MercedesBenzSprinter` and
    /// `AckermannVehicle`): r 0.4 m, `Physics {}` (1000 kg/m³ → 150.8 kg).
    VehicleWheel,
    /// `AutomobileWheel {}` with the 2014-manual defaults (subdivision 24, edgeSubdivision 1).
    AutomobileWheel,
    /// `BmwX5Wheel` (r 0.374 m, 30 kg as set by `BmwX5`).
    BmwX5Wheel,
    /// `ToyotaPriusWheel` (195/65 R15, r 0.317 m, 8 kg as set by `ToyotaPrius`).
    ToyotaPriusWheel,
    /// `CitroenCZeroFrontWheel` (145/65 R15, r 0.28475 m, 5 kg as set by `CitroenCZero`).
    CitroenCZeroFrontWheel,
    /// `CitroenCZeroRearWheel` (175/55 R15, r 0.28675 m, 6 kg as set by `CitroenCZero`).
    CitroenCZeroRearWheel,
    /// `BusWheel` (r 0.56 m, 80 kg as set by `Bus`).
    BusWheel,
    /// `TruckWheel` (r 0.5 m, 100 kg as set by `Truck`).
    TruckWheel,
    /// The inline `VehicleWheel` of `LincolnMKZ` (r 0.358 m, `Physics {}`). Not a PROTO of its
    /// own: looked up as `"LincolnMKZWheel"`.
    LincolnMKZWheel,
    /// The inline `VehicleWheel` of `RangeRoverSportSVR` (r 0.358 m, `Physics {}`). Not a PROTO
    /// of its own: looked up as `"RangeRoverSportSVRWheel"`.
    RangeRoverSportSVRWheel,
    /// `GreenPowerEVStarFrontWheel`: a custom mesh, not a `VehicleWheel`; bounding cylinder
    /// r 0.4445 m × 0.215 m, 10 kg.
    GreenPowerEVStarFrontWheel,
    /// `GreenPowerEVStarRearWheel`: twin custom meshes, not a `VehicleWheel`; bounding cylinder
    /// r 0.4445 m × 0.43 m, 20 kg.
    GreenPowerEVStarRearWheel,
    /// `TeslaModel3Wheel`: a custom mesh, not a `VehicleWheel`; bounding cylinder r 0.36 m ×
    /// 0.23 m, 10.4 kg as set by `TeslaModel3`. Webots offsets that cylinder by 0.04 m along the
    /// axle (R2019b revision); it is centred here.
    TeslaModel3Wheel,
    /// `TractorFrontWheel`: a plain cylinder r 0.38 m × 0.19 m (subdivision 24), 30 kg.
    TractorFrontWheel,
    /// `TractorRearWheel`: a plain cylinder r 0.6 m × 0.37 m (subdivision 24), 60 kg.
    TractorRearWheel,
}

impl WheelPreset {
    /// Every preset, in declaration order.
    pub const ALL: [WheelPreset; 15] = [
        WheelPreset::VehicleWheel,
        WheelPreset::AutomobileWheel,
        WheelPreset::BmwX5Wheel,
        WheelPreset::ToyotaPriusWheel,
        WheelPreset::CitroenCZeroFrontWheel,
        WheelPreset::CitroenCZeroRearWheel,
        WheelPreset::BusWheel,
        WheelPreset::TruckWheel,
        WheelPreset::LincolnMKZWheel,
        WheelPreset::RangeRoverSportSVRWheel,
        WheelPreset::GreenPowerEVStarFrontWheel,
        WheelPreset::GreenPowerEVStarRearWheel,
        WheelPreset::TeslaModel3Wheel,
        WheelPreset::TractorFrontWheel,
        WheelPreset::TractorRearWheel,
    ];

    /// The Webots PROTO name (`"BmwX5Wheel"`, …; the two inline wheels use
    /// `"LincolnMKZWheel"` and `"RangeRoverSportSVRWheel"`).
    pub const fn proto_name(self) -> &'static str {
        match self {
            WheelPreset::VehicleWheel => "VehicleWheel",
            WheelPreset::AutomobileWheel => "AutomobileWheel",
            WheelPreset::BmwX5Wheel => "BmwX5Wheel",
            WheelPreset::ToyotaPriusWheel => "ToyotaPriusWheel",
            WheelPreset::CitroenCZeroFrontWheel => "CitroenCZeroFrontWheel",
            WheelPreset::CitroenCZeroRearWheel => "CitroenCZeroRearWheel",
            WheelPreset::BusWheel => "BusWheel",
            WheelPreset::TruckWheel => "TruckWheel",
            WheelPreset::LincolnMKZWheel => "LincolnMKZWheel",
            WheelPreset::RangeRoverSportSVRWheel => "RangeRoverSportSVRWheel",
            WheelPreset::GreenPowerEVStarFrontWheel => "GreenPowerEVStarFrontWheel",
            WheelPreset::GreenPowerEVStarRearWheel => "GreenPowerEVStarRearWheel",
            WheelPreset::TeslaModel3Wheel => "TeslaModel3Wheel",
            WheelPreset::TractorFrontWheel => "TractorFrontWheel",
            WheelPreset::TractorRearWheel => "TractorRearWheel",
        }
    }

    /// The preset with Webots PROTO name `name` (exact, case-sensitive, as in a world file).
    pub fn from_proto_name(name: &str) -> Option<WheelPreset> {
        WheelPreset::ALL
            .into_iter()
            .find(|p| p.proto_name() == name)
    }

    /// What the wheel is in Webots.
    pub const fn shape(self) -> WheelShape {
        match self {
            WheelPreset::GreenPowerEVStarFrontWheel
            | WheelPreset::GreenPowerEVStarRearWheel
            | WheelPreset::TeslaModel3Wheel => WheelShape::CustomMesh,
            WheelPreset::TractorFrontWheel | WheelPreset::TractorRearWheel => WheelShape::Cylinder,
            _ => WheelShape::VehicleWheel,
        }
    }

    /// True if Webots builds this wheel from `VehicleWheel` (so its meshes are reproduced).
    #[inline]
    pub const fn is_vehicle_wheel(self) -> bool {
        matches!(self.shape(), WheelShape::VehicleWheel)
    }

    /// The wheel's fields (lengths in m, mass in kg), as the shipped car uses it, right side.
    ///
    /// For the wheels that are not `VehicleWheel`s, `tire_radius` and `thickness` are the
    /// bounding cylinder's radius and height and the rim fields (unused) are set to values that
    /// pass validation; `shape` says what the wheel really is. Every preset validates without
    /// warnings.
    pub fn params<T: Real>(self) -> WheelParams<T> {
        let f = T::from_f64;
        let d = WheelParams::<T>::default();
        match self {
            WheelPreset::VehicleWheel => d,
            WheelPreset::AutomobileWheel => WheelParams::automobile_wheel_2014(),
            WheelPreset::BmwX5Wheel => WheelParams {
                name: "BMW X5 wheel",
                thickness: f(0.25),
                tire_radius: f(0.374),
                rim_radius: f(0.255),
                rim_beam_width: f(0.07),
                central_inner_radius: f(0.08),
                central_outer_radius: f(0.12),
                rim_beam_thickness: f(0.08),
                rim_beam_offset: f(0.065),
                rim_appearance: PbrAppearance::new([0.7, 0.7, 0.7], 0.5, 1.0),
                physics: WheelPhysics::Mass(f(30.0)),
                ..d
            },
            WheelPreset::ToyotaPriusWheel => WheelParams {
                name: "Toyota Prius wheel",
                thickness: f(0.195),
                tire_radius: f(0.317),
                edge_subdivision: 2,
                rim_radius: f(0.21),
                rim_beam_number: 6,
                rim_beam_width: f(0.06),
                central_inner_radius: f(0.06),
                central_outer_radius: f(0.07),
                rim_beam_thickness: f(0.1),
                rim_beam_offset: f(0.047),
                contact_material: "ToyotaPriusWheels",
                physics: WheelPhysics::Mass(f(8.0)),
                ..d
            },
            WheelPreset::CitroenCZeroFrontWheel | WheelPreset::CitroenCZeroRearWheel => {
                let front = self == WheelPreset::CitroenCZeroFrontWheel;
                WheelParams {
                    name: if front {
                        "Citroen C-Zero front wheel"
                    } else {
                        "Citroen C-Zero rear wheel"
                    },
                    thickness: f(if front { 0.145 } else { 0.175 }),
                    tire_radius: f(if front { 0.28475 } else { 0.28675 }),
                    curvature_factor: f(0.5),
                    edge_subdivision: 2,
                    rim_radius: f(0.1905),
                    rim_beam_number: 7,
                    rim_beam_width: f(0.07),
                    central_inner_radius: f(0.06),
                    central_outer_radius: f(0.11),
                    rim_beam_thickness: f(0.1),
                    rim_beam_offset: f(0.022),
                    contact_material: "CitroenCZeroWheels",
                    physics: WheelPhysics::Mass(f(if front { 5.0 } else { 6.0 })),
                    ..d
                }
            }
            WheelPreset::BusWheel => WheelParams {
                name: "bus wheel",
                thickness: f(0.28),
                tire_radius: f(0.56),
                rim_radius: f(0.34),
                rim_beam_number: 7,
                rim_beam_width: f(0.12),
                central_inner_radius: f(0.1),
                central_outer_radius: f(0.17),
                contact_material: "BusWheels",
                physics: WheelPhysics::Mass(f(80.0)),
                ..d
            },
            WheelPreset::TruckWheel => WheelParams {
                name: "truck wheel",
                thickness: f(0.4),
                tire_radius: f(0.5),
                rim_radius: f(0.35),
                rim_beam_number: 6,
                rim_beam_width: f(0.15),
                central_inner_radius: f(0.14),
                central_outer_radius: f(0.2),
                rim_beam_thickness: f(0.3),
                contact_material: "TruckWheels",
                physics: WheelPhysics::Mass(f(100.0)),
                ..d
            },
            WheelPreset::LincolnMKZWheel | WheelPreset::RangeRoverSportSVRWheel => {
                let lincoln = self == WheelPreset::LincolnMKZWheel;
                WheelParams {
                    thickness: f(0.22),
                    tire_radius: f(0.358),
                    rim_radius: f(if lincoln { 0.255 } else { 0.285 }),
                    rim_beam_width: f(0.07),
                    central_inner_radius: f(0.08),
                    central_outer_radius: f(0.12),
                    rim_beam_thickness: f(0.08),
                    rim_beam_offset: f(0.065),
                    contact_material: if lincoln {
                        "LincolnMKZWheels"
                    } else {
                        "RangeRoverSportSVRWheels"
                    },
                    ..d
                }
            }
            WheelPreset::GreenPowerEVStarFrontWheel => stand_in(
                d,
                "front wheel",
                0.4445,
                0.215,
                10.0,
                WheelShape::CustomMesh,
            ),
            WheelPreset::GreenPowerEVStarRearWheel => {
                stand_in(d, "rear wheel", 0.4445, 0.43, 20.0, WheelShape::CustomMesh)
            }
            WheelPreset::TeslaModel3Wheel => {
                stand_in(d, "wheel", 0.36, 0.23, 10.4, WheelShape::CustomMesh)
            }
            WheelPreset::TractorFrontWheel => WheelParams {
                subdivision: 24,
                curvature_factor: T::ZERO,
                ..stand_in(
                    d,
                    "tractor front wheel",
                    0.38,
                    0.19,
                    30.0,
                    WheelShape::Cylinder,
                )
            },
            WheelPreset::TractorRearWheel => WheelParams {
                subdivision: 24,
                curvature_factor: T::ZERO,
                ..stand_in(
                    d,
                    "tractor rear wheel",
                    0.6,
                    0.37,
                    60.0,
                    WheelShape::Cylinder,
                )
            },
        }
    }
}

/// A non-`VehicleWheel` wheel: its real radius, width and mass, and rim fields that are unused
/// but valid (beams half the width, centred).
fn stand_in<T: Real>(
    d: WheelParams<T>,
    name: &'static str,
    radius: f64,
    width: f64,
    mass: f64,
    shape: WheelShape,
) -> WheelParams<T> {
    WheelParams {
        name,
        tire_radius: T::from_f64(radius),
        thickness: T::from_f64(width),
        rim_beam_thickness: T::from_f64(width * 0.5),
        rim_beam_offset: T::ZERO,
        physics: WheelPhysics::Mass(T::from_f64(mass)),
        shape,
        ..d
    }
}
