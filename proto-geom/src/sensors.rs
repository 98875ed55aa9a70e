//! The sensor slots of the shipped car models (spec §4.5).

use ackermann::Real;

use nalgebra::{Isometry3, Point3};

use crate::glue::{identity, isometry, no_rotation, rotation, z_axis};

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

/// The frames of the four sensor slots of a car: each maps the slot's coordinates to the
/// vehicle frame (x forward, y left, z up, origin at the rear-axle centre; translations in m,
/// rotations in rad).
///
/// Figures read from older Y-up PROTO revisions (x = left, y = up, z = forward) are converted
/// with FLU = (z, x, y). Every rear slot faces backward: rotated by exactly π about z (the FLU
/// PROTOs write 3.14159 or 3.1415; the Y-up ones instead turn their front, top and centre slots
/// by π about y, because Y-up devices look along −z — converted, the meaning is the same).
#[derive(Debug, Clone, Copy)]
pub struct SensorSlots<T: Real> {
    /// `sensorsSlotFront` (translation in m, facing forward).
    pub front: Isometry3<T>,
    /// `sensorsSlotTop` (translation in m, facing forward).
    pub top: Isometry3<T>,
    /// `sensorsSlotRear` (translation in m, rotated π rad about z: facing backward).
    pub rear: Isometry3<T>,
    /// `sensorsSlotCenter` (the identity).
    pub centre: Isometry3<T>,
}

impl<T: Real> SensorSlots<T> {
    /// Slots at the given front, top and rear positions (m, vehicle frame), the front and top
    /// ones facing forward, the rear one facing backward (π rad about z) and the centre one at
    /// the origin.
    pub fn new(front: Point3<T>, top: Point3<T>, rear: Point3<T>) -> Self {
        SensorSlots {
            front: isometry(front.coords, no_rotation()),
            top: isometry(top.coords, no_rotation()),
            rear: isometry(rear.coords, rotation(&z_axis(), T::PI)),
            centre: identity(),
        }
    }

    /// The frame of `slot` (translation in m).
    pub fn get(&self, slot: SensorSlot) -> Isometry3<T> {
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

// By hand: nalgebra compares isometries only for `T: RealField`, a bound `Real` does not carry.
// Equal slots have equal translations (m) and rotations (a unit quaternion and its negation are
// the same rotation, as nalgebra's `UnitQuaternion` equality says).
impl<T: Real> PartialEq for SensorSlots<T> {
    fn eq(&self, other: &Self) -> bool {
        SensorSlot::ALL.into_iter().all(|slot| {
            let (a, b) = (self.get(slot), other.get(slot));
            a.translation == b.translation && a.rotation == b.rotation
        })
    }
}
