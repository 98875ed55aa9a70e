//! Whether and how far apart two cars are: their collision shapes' distance and rapier's
//! contacts between them.

use rapier3d::parry::query::distance;
use rapier3d::prelude::ColliderHandle;

use super::World;
use crate::error::SimError;
use crate::vehicle::VehicleId;

impl World {
    /// The colliders of car `id`'s bodies.
    fn vehicle_colliders(&self, id: VehicleId) -> Result<Vec<ColliderHandle>, SimError> {
        Ok(self
            .vehicle(id)?
            .bodies()
            .into_iter()
            .filter_map(|h| self.physics.bodies.get(h))
            .flat_map(|b| b.colliders().iter().copied())
            .collect())
    }

    /// The smallest distance (m) between the collision shapes of cars `a` and `b` (the chassis
    /// boxes, and the wheels of a car on joints) after the last step; 0 when they touch or
    /// overlap.
    pub fn vehicle_gap(&self, a: VehicleId, b: VehicleId) -> Result<f64, SimError> {
        let (ca, cb) = (self.vehicle_colliders(a)?, self.vehicle_colliders(b)?);
        let mut gap = f64::INFINITY;
        for x in ca.iter().filter_map(|&h| self.physics.colliders.get(h)) {
            for y in cb.iter().filter_map(|&h| self.physics.colliders.get(h)) {
                // Every shape of a car is convex (boxes, cylinders): parry supports each pair.
                if let Ok(d) = distance(x.position(), x.shape(), y.position(), y.shape()) {
                    gap = gap.min(f64::from(d.distance));
                }
            }
        }
        Ok(gap)
    }

    /// True when rapier found an active contact between a collider of car `a` and one of car
    /// `b` in the last step: the cars touched.
    pub fn vehicles_in_contact(&self, a: VehicleId, b: VehicleId) -> Result<bool, SimError> {
        let cb = self.vehicle_colliders(b)?;
        Ok(self.vehicle_colliders(a)?.into_iter().any(|x| {
            cb.iter().any(|&y| {
                self.physics
                    .contact_pair(x, y)
                    .is_some_and(|p| p.has_any_active_contact())
            })
        }))
    }
}
