//! The sensor slots of the shipped car models (spec §4.5).

use ackermann::Real;

use crate::math::{Isometry, Rotation, Vec3};

/// One of the four sensor slots of a shipped car (`sensorsSlotFront`, …).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SensorSlot {
    /// Webots field `sensorsSlotFront`: at the front bumper, facing forward.
    Front,
    /// Webots field `sensorsSlotTop`: on the roof, facing forward.
    Top,
    /// Webots field `sensorsSlotRear`: at the rear bumper, rotated π about z (facing backward).
    Rear,
    /// Webots field `sensorsSlotCenter`: at the origin (rear-axle centre).
    Centre,
}

impl SensorSlot {
    /// All four slots.
    pub const ALL: [SensorSlot; 4] = [
        SensorSlot::Front,
        SensorSlot::Top,
        SensorSlot::Rear,
        SensorSlot::Centre,
    ];

    /// The Webots field name (`"sensorsSlotFront"`, …).
    pub const fn webots_name(self) -> &'static str {
        match self {
            SensorSlot::Front => "sensorsSlotFront",
            SensorSlot::Top => "sensorsSlotTop",
            SensorSlot::Rear => "sensorsSlotRear",
            SensorSlot::Centre => "sensorsSlotCenter",
        }
    }
}

/// The frames of the four sensor slots of a car, in the vehicle frame (x forward, y left, z up,
/// origin at the rear-axle centre; m).
///
/// Figures read from older Y-up PROTO revisions (x = left, y = up, z = forward) are converted
/// with FLU = (z, x, y). Every rear slot faces backward: rotated by exactly π about z (the FLU
/// PROTOs write 3.14159 or 3.1415; the Y-up ones instead turn their front, top and centre slots
/// by π about y, because Y-up devices look along −z — converted, the meaning is the same).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorSlots<T: Real> {
    /// `sensorsSlotFront`.
    pub front: Isometry<T>,
    /// `sensorsSlotTop`.
    pub top: Isometry<T>,
    /// `sensorsSlotRear` (facing backward).
    pub rear: Isometry<T>,
    /// `sensorsSlotCenter` (the identity).
    pub centre: Isometry<T>,
}

impl<T: Real> SensorSlots<T> {
    /// Slots at the given front, top and rear positions (m), the rear one facing backward and
    /// the centre one at the origin.
    pub fn new(front: [f64; 3], top: [f64; 3], rear: [f64; 3]) -> Self {
        let v = |a: [f64; 3]| Vec3::from_array(a.map(T::from_f64));
        SensorSlots {
            front: Isometry::from_translation(v(front)),
            top: Isometry::from_translation(v(top)),
            rear: Isometry::new(v(rear), Rotation::about_z(T::PI)),
            centre: Isometry::IDENTITY,
        }
    }

    /// The frame of `slot`.
    pub fn get(&self, slot: SensorSlot) -> Isometry<T> {
        match slot {
            SensorSlot::Front => self.front,
            SensorSlot::Top => self.top,
            SensorSlot::Rear => self.rear,
            SensorSlot::Centre => self.centre,
        }
    }

    /// The slots of the shipped model with PROTO name `model` (`"BmwX5"`, …), or `None` for an
    /// unknown model or one without the four slots (`GreenPowerEVStar`, `Tractor`).
    pub fn for_model(model: &str) -> Option<Self> {
        crate::ShippedVehicle::from_proto_name(model)?.sensor_slots()
    }
}
