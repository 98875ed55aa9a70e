//! The vehicles shipped with Webots: dimensions, wheels and sensor slots (spec §4.5, §5), one
//! row of [`SHIPPED`] each.

use ackermann::{PerWheel, Real, Wheel};
use nalgebra::Point3;

use crate::layout::{VehicleDimensions, VehicleLayout};
use crate::sensors::SensorSlots;
use crate::wheel::{WheelParams, WheelPreset};

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

/// A shipped vehicle's geometry as its PROTO gives it (lengths in m, masses in kg), converted
/// to the scalar type on use.
struct Geometry {
    vehicle: ShippedVehicle,
    /// The PROTO name.
    name: &'static str,
    /// `wheelbase`, `trackFront`, `trackRear` (m).
    dimensions: [f64; 3],
    /// The wheel in each slot.
    wheels: PerWheel<WheelPreset>,
    /// Front, top and rear sensor-slot positions (m), `None` without the four slots. The
    /// figures of the Y-up PROTO revisions (x, y = up, z = forward) are converted with
    /// FLU = (z, x, y).
    sensor_slots: Option<[[f64; 3]; 3]>,
}

/// One row per shipped vehicle, in declaration order (checked at compile time below).
///
/// References to rows, each its own constant: a lookup with a constant vehicle compiles to
/// that row alone, and a firmware image keeps only the rows it uses.
const SHIPPED: [&Geometry; 11] = {
    use ShippedVehicle as V;
    use WheelPreset as W;
    let same = PerWheel::splat;
    [
        &Geometry {
            vehicle: V::BmwX5,
            name: "BmwX5",
            dimensions: [2.995, 1.628, 1.628],
            wheels: same(W::BmwX5Wheel),
            sensor_slots: Some([[3.85, 0.0, 0.45], [1.0, 0.0, 1.45], [-1.0, 0.0, 0.3]]),
        },
        &Geometry {
            vehicle: V::CitroenCZero,
            name: "CitroenCZero",
            dimensions: [2.55, 1.31, 1.27],
            // Webots' PROTO puts a front wheel in the rear-right slot (a bug, fixed here: see
            // `ShippedVehicle::wheel_presets`).
            wheels: PerWheel::new(
                W::CitroenCZeroFrontWheel,
                W::CitroenCZeroFrontWheel,
                W::CitroenCZeroRearWheel,
                W::CitroenCZeroRearWheel,
            ),
            sensor_slots: Some([[3.075, 0.0, 0.05], [1.075, 0.0, 1.35], [-0.425, 0.0, 0.3]]),
        },
        &Geometry {
            vehicle: V::ToyotaPrius,
            name: "ToyotaPrius",
            dimensions: [2.8, 1.628, 1.628],
            wheels: same(W::ToyotaPriusWheel),
            sensor_slots: Some([[3.635, 0.0, 0.4], [1.1, 0.0, 1.3], [-0.85, 0.0, 0.3]]),
        },
        &Geometry {
            vehicle: V::LincolnMKZ,
            name: "LincolnMKZ",
            dimensions: [2.94, 1.64, 1.64],
            wheels: same(W::LincolnMKZWheel),
            sensor_slots: Some([[3.944, 0.0, 0.142], [1.11, 0.0, 1.16], [-1.06, 0.0, 0.33]]),
        },
        &Geometry {
            vehicle: V::RangeRoverSportSVR,
            name: "RangeRoverSportSVR",
            dimensions: [2.71, 1.64, 1.64],
            wheels: same(W::RangeRoverSportSVRWheel),
            sensor_slots: Some([[3.5, 0.0, 0.5], [1.4, 0.0, 1.3], [-1.06, 0.0, 0.33]]),
        },
        &Geometry {
            vehicle: V::TeslaModel3,
            name: "TeslaModel3",
            dimensions: [2.94, 1.72, 1.72],
            wheels: same(W::TeslaModel3Wheel),
            sensor_slots: Some([[3.79, 0.0, 0.142], [1.11, 0.0, 1.16], [-1.05, 0.0, 0.2]]),
        },
        &Geometry {
            vehicle: V::MercedesBenzSprinter,
            name: "MercedesBenzSprinter",
            dimensions: [4.325, 1.7, 1.7],
            wheels: same(W::VehicleWheel),
            sensor_slots: Some([[5.31, 0.0, 0.47], [2.99, 0.0, 2.3], [-1.62, 0.0, 0.19]]),
        },
        &Geometry {
            vehicle: V::GreenPowerEVStar,
            name: "GreenPowerEVStar",
            dimensions: [4.325, 1.7, 1.5],
            wheels: axles(W::GreenPowerEVStarFrontWheel, W::GreenPowerEVStarRearWheel),
            sensor_slots: None,
        },
        &Geometry {
            vehicle: V::Bus,
            name: "Bus",
            dimensions: [4.5, 2.5, 2.5],
            wheels: same(W::BusWheel),
            sensor_slots: Some([[11.5, 0.0, 0.2], [2.5, 0.0, 5.3], [-6.2, 0.0, 1.0]]),
        },
        &Geometry {
            vehicle: V::Truck,
            name: "Truck",
            dimensions: [5.25, 2.2, 2.2],
            wheels: same(W::TruckWheel),
            sensor_slots: Some([[6.75, 0.0, 1.1], [4.3, 0.0, 4.15], [-7.3, 0.0, 2.7]]),
        },
        &Geometry {
            vehicle: V::Tractor,
            name: "Tractor",
            dimensions: [1.76, 1.4, 1.4],
            wheels: axles(W::TractorFrontWheel, W::TractorRearWheel),
            sensor_slots: None,
        },
    ]
};

/// The same wheel on each axle.
const fn axles(front: WheelPreset, rear: WheelPreset) -> PerWheel<WheelPreset> {
    PerWheel::new(front, front, rear, rear)
}

// `ShippedVehicle::geometry` indexes the table by discriminant.
const _: () = {
    let mut i = 0;
    while i < SHIPPED.len() {
        assert!(
            SHIPPED[i].vehicle as usize == i,
            "SHIPPED is not in declaration order"
        );
        i += 1;
    }
};

impl ShippedVehicle {
    /// Every shipped vehicle, in declaration order.
    pub const ALL: [ShippedVehicle; SHIPPED.len()] = {
        let mut all = [ShippedVehicle::BmwX5; SHIPPED.len()];
        let mut i = 0;
        while i < all.len() {
            all[i] = SHIPPED[i].vehicle;
            i += 1;
        }
        all
    };

    const fn geometry(self) -> &'static Geometry {
        SHIPPED[self as usize]
    }

    /// The Webots PROTO name (`"BmwX5"`, …).
    pub const fn proto_name(self) -> &'static str {
        self.geometry().name
    }

    /// The vehicle with PROTO name `name` (exact, case-sensitive).
    pub fn from_proto_name(name: &str) -> Option<ShippedVehicle> {
        ShippedVehicle::ALL
            .into_iter()
            .find(|v| v.proto_name() == name)
    }

    /// `wheelbase`, `trackFront`, `trackRear` (m).
    pub fn dimensions<T: Real>(self) -> VehicleDimensions<T> {
        let [wheelbase, track_front, track_rear] = self.geometry().dimensions.map(T::from_f64);
        VehicleDimensions {
            wheelbase,
            track_front,
            track_rear,
        }
    }

    /// The wheel in each slot.
    ///
    /// `CitroenCZero` has its rear wheel (0.28675 m) in both rear slots. Webots' PROTO puts a
    /// *front* wheel (0.28475 m, with the rear wheels' 6 kg) in the rear-right slot, so that
    /// car pulls to one side on mismatched tyres and its library reads a rear radius of
    /// 0.28475 m: a bug, fixed here (`COMPATIBILITY.md`).
    pub const fn wheel_presets(self) -> PerWheel<WheelPreset> {
        self.geometry().wheels
    }

    /// The wheels' fields as placed in their slots (name and `wheelSide` set per slot, see
    /// [`WheelParams::in_slot`]).
    pub fn wheel_params<T: Real>(self) -> PerWheel<WheelParams<T>> {
        self.geometry()
            .wheels
            .map_with_wheel(|w: Wheel, p: WheelPreset| p.params().in_slot(w))
    }

    /// The wheel layout. Every shipped value is valid, so no warning is produced.
    pub fn layout<T: Real>(self) -> VehicleLayout<T> {
        VehicleLayout::new(self.dimensions(), self.wheel_params()).0
    }

    /// The sensor slots (spec §4.5), or `None` for `GreenPowerEVStar` and `Tractor`, which do
    /// not have the four slots.
    pub fn sensor_slots<T: Real>(self) -> Option<SensorSlots<T>> {
        let [front, top, rear] = self
            .geometry()
            .sensor_slots?
            .map(|p| Point3::from(p.map(T::from_f64)));
        Some(SensorSlots::new(front, top, rear))
    }
}
