//! The vehicles shipped with Webots: dimensions, wheels and sensor slots (spec §4.5, §5).

use ackermann::{PerWheel, Real, Wheel};
use nalgebra::Point3;

use crate::layout::{VehicleDimensions, VehicleLayout};
use crate::sensors::SensorSlots;
use crate::wheel::{WheelParams, WheelPhysics, WheelPreset};

/// A vehicle model shipped with Webots, for its geometry (the engine and driving parameters
/// belong to `vehicle-model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ShippedVehicle {
    /// `BmwX5` (R2022b).
    BmwX5,
    /// `CitroenCZero` (R2021b).
    CitroenCZero,
    /// `ToyotaPrius` (R2023b).
    ToyotaPrius,
    /// `LincolnMKZ` (R2020a / R2019b).
    LincolnMKZ,
    /// `RangeRoverSportSVR` (R2020a / R2019b).
    RangeRoverSportSVR,
    /// `TeslaModel3` (R2021c).
    TeslaModel3,
    /// `MercedesBenzSprinter` (R2022b).
    MercedesBenzSprinter,
    /// `GreenPowerEVStar` (R2020a).
    GreenPowerEVStar,
    /// `Bus` (R2023b).
    Bus,
    /// `Truck` (R2021c), with its default `wheelbase` 5.25 m.
    Truck,
    /// `Tractor` (R2022b).
    Tractor,
}

impl ShippedVehicle {
    /// Every shipped vehicle.
    pub const ALL: [ShippedVehicle; 11] = [
        ShippedVehicle::BmwX5,
        ShippedVehicle::CitroenCZero,
        ShippedVehicle::ToyotaPrius,
        ShippedVehicle::LincolnMKZ,
        ShippedVehicle::RangeRoverSportSVR,
        ShippedVehicle::TeslaModel3,
        ShippedVehicle::MercedesBenzSprinter,
        ShippedVehicle::GreenPowerEVStar,
        ShippedVehicle::Bus,
        ShippedVehicle::Truck,
        ShippedVehicle::Tractor,
    ];

    /// The Webots PROTO name (`"BmwX5"`, …).
    pub const fn proto_name(self) -> &'static str {
        match self {
            ShippedVehicle::BmwX5 => "BmwX5",
            ShippedVehicle::CitroenCZero => "CitroenCZero",
            ShippedVehicle::ToyotaPrius => "ToyotaPrius",
            ShippedVehicle::LincolnMKZ => "LincolnMKZ",
            ShippedVehicle::RangeRoverSportSVR => "RangeRoverSportSVR",
            ShippedVehicle::TeslaModel3 => "TeslaModel3",
            ShippedVehicle::MercedesBenzSprinter => "MercedesBenzSprinter",
            ShippedVehicle::GreenPowerEVStar => "GreenPowerEVStar",
            ShippedVehicle::Bus => "Bus",
            ShippedVehicle::Truck => "Truck",
            ShippedVehicle::Tractor => "Tractor",
        }
    }

    /// The vehicle with PROTO name `name` (exact, case-sensitive).
    pub fn from_proto_name(name: &str) -> Option<ShippedVehicle> {
        ShippedVehicle::ALL
            .into_iter()
            .find(|v| v.proto_name() == name)
    }

    /// `wheelbase`, `trackFront`, `trackRear` (m).
    pub fn dimensions<T: Real>(self) -> VehicleDimensions<T> {
        let (l, tf, tr) = match self {
            ShippedVehicle::BmwX5 => (2.995, 1.628, 1.628),
            ShippedVehicle::CitroenCZero => (2.55, 1.31, 1.27),
            ShippedVehicle::ToyotaPrius => (2.8, 1.628, 1.628),
            ShippedVehicle::LincolnMKZ => (2.94, 1.64, 1.64),
            ShippedVehicle::RangeRoverSportSVR => (2.71, 1.64, 1.64),
            ShippedVehicle::TeslaModel3 => (2.94, 1.72, 1.72),
            ShippedVehicle::MercedesBenzSprinter => (4.325, 1.7, 1.7),
            ShippedVehicle::GreenPowerEVStar => (4.325, 1.7, 1.5),
            ShippedVehicle::Bus => (4.5, 2.5, 2.5),
            ShippedVehicle::Truck => (5.25, 2.2, 2.2),
            ShippedVehicle::Tractor => (1.76, 1.4, 1.4),
        };
        VehicleDimensions {
            wheelbase: T::from_f64(l),
            track_front: T::from_f64(tf),
            track_rear: T::from_f64(tr),
        }
    }

    /// The wheel in each slot.
    ///
    /// `CitroenCZero` reproduces a quirk of its PROTO: the rear-right slot holds a *front*
    /// wheel (so the rear radius the car library reads is 0.28475 m), the rear-left a rear one
    /// ([`ShippedVehicle::wheel_params`] gives that front wheel the rear wheels' 6 kg).
    pub const fn wheel_presets(self) -> PerWheel<WheelPreset> {
        let same = PerWheel::splat;
        match self {
            ShippedVehicle::BmwX5 => same(WheelPreset::BmwX5Wheel),
            ShippedVehicle::CitroenCZero => PerWheel::new(
                WheelPreset::CitroenCZeroFrontWheel,
                WheelPreset::CitroenCZeroFrontWheel,
                WheelPreset::CitroenCZeroFrontWheel,
                WheelPreset::CitroenCZeroRearWheel,
            ),
            ShippedVehicle::ToyotaPrius => same(WheelPreset::ToyotaPriusWheel),
            ShippedVehicle::LincolnMKZ => same(WheelPreset::LincolnMKZWheel),
            ShippedVehicle::RangeRoverSportSVR => same(WheelPreset::RangeRoverSportSVRWheel),
            ShippedVehicle::TeslaModel3 => same(WheelPreset::TeslaModel3Wheel),
            ShippedVehicle::MercedesBenzSprinter => same(WheelPreset::VehicleWheel),
            ShippedVehicle::GreenPowerEVStar => PerWheel::new(
                WheelPreset::GreenPowerEVStarFrontWheel,
                WheelPreset::GreenPowerEVStarFrontWheel,
                WheelPreset::GreenPowerEVStarRearWheel,
                WheelPreset::GreenPowerEVStarRearWheel,
            ),
            ShippedVehicle::Bus => same(WheelPreset::BusWheel),
            ShippedVehicle::Truck => same(WheelPreset::TruckWheel),
            ShippedVehicle::Tractor => PerWheel::new(
                WheelPreset::TractorFrontWheel,
                WheelPreset::TractorFrontWheel,
                WheelPreset::TractorRearWheel,
                WheelPreset::TractorRearWheel,
            ),
        }
    }

    /// The wheels' fields as placed in their slots (name and `wheelSide` set per slot, see
    /// [`WheelParams::in_slot`]).
    ///
    /// `CitroenCZero`'s rear-right front wheel gets the rear wheels' `Physics` node (6 kg), as in
    /// its PROTO.
    pub fn wheel_params<T: Real>(self) -> PerWheel<WheelParams<T>> {
        let mut wheels = self
            .wheel_presets()
            .map_with_wheel(|w: Wheel, p: WheelPreset| p.params().in_slot(w));
        if self == ShippedVehicle::CitroenCZero {
            wheels[Wheel::RearRight].physics = WheelPhysics::Mass(T::from_f64(6.0));
        }
        wheels
    }

    /// The wheel layout. Every shipped value is valid, so no warning is produced.
    pub fn layout<T: Real>(self) -> VehicleLayout<T> {
        VehicleLayout::new(self.dimensions(), self.wheel_params()).0
    }

    /// The sensor slots (spec §4.5), or `None` for `GreenPowerEVStar` and `Tractor`, which do
    /// not have the four slots.
    pub fn sensor_slots<T: Real>(self) -> Option<SensorSlots<T>> {
        let p = |[x, y, z]: [f64; 3]| Point3::new(T::from_f64(x), T::from_f64(y), T::from_f64(z));
        let s = |front, top, rear| SensorSlots::new(p(front), p(top), p(rear));
        Some(match self {
            ShippedVehicle::BmwX5 => s([3.85, 0.0, 0.45], [1.0, 0.0, 1.45], [-1.0, 0.0, 0.3]),
            ShippedVehicle::ToyotaPrius => s([3.635, 0.0, 0.4], [1.1, 0.0, 1.3], [-0.85, 0.0, 0.3]),
            ShippedVehicle::TeslaModel3 => {
                s([3.79, 0.0, 0.142], [1.11, 0.0, 1.16], [-1.05, 0.0, 0.2])
            }
            ShippedVehicle::MercedesBenzSprinter => {
                s([5.31, 0.0, 0.47], [2.99, 0.0, 2.3], [-1.62, 0.0, 0.19])
            }
            ShippedVehicle::Bus => s([11.5, 0.0, 0.2], [2.5, 0.0, 5.3], [-6.2, 0.0, 1.0]),
            ShippedVehicle::Truck => s([6.75, 0.0, 1.1], [4.3, 0.0, 4.15], [-7.3, 0.0, 2.7]),
            // Y-up figures (x, y = up, z = forward) converted with FLU = (z, x, y).
            ShippedVehicle::CitroenCZero => {
                s([3.075, 0.0, 0.05], [1.075, 0.0, 1.35], [-0.425, 0.0, 0.3])
            }
            ShippedVehicle::LincolnMKZ => {
                s([3.944, 0.0, 0.142], [1.11, 0.0, 1.16], [-1.06, 0.0, 0.33])
            }
            ShippedVehicle::RangeRoverSportSVR => {
                s([3.5, 0.0, 0.5], [1.4, 0.0, 1.3], [-1.06, 0.0, 0.33])
            }
            ShippedVehicle::GreenPowerEVStar | ShippedVehicle::Tractor => return None,
        })
    }
}
