//! What a car's tyre stands on: the friction coefficient of the surface it touches, at the
//! point it touches it, in f64 as the world's configuration gives it.
//!
//! rapier keeps a friction on every collider (f32, combined by multiplication) for its own
//! contacts, and keeps it: a chassis sliding on a wall, a box on a ramp. The tyre solve does
//! not read it back. It would get the configured value rounded to f32 (0.7 as 0.699999988),
//! and each mounting would need its own rule for a collider without one. The world builds a
//! [`Ground`] from its [`WorldConfig`](crate::WorldConfig) instead: one entry per collider a
//! wheel can stand on, each a [`Surface`] that answers for a point on it.
//!
//! # The rule for what is not a registered surface
//!
//! Entries: the flat ground (`ground_friction`), each static obstacle (its own `friction`,
//! else the ground's) and each dynamic box (its own `friction`, else
//! [`DEFAULT_FRICTION`](crate::DEFAULT_FRICTION), as rapier has it). Anything else a wheel
//! touches, another car's chassis or wheel or a robot, has the ground's friction, as an
//! obstacle without its own has: those colliders' rapier frictions (1 for a chassis, 0 for a
//! joints car's wheel) are settings for rapier's contacts, not surfaces to drive on. The
//! shape-cast wheels of a cast car meet only static surfaces; the wheel bodies of a car on
//! joints meet everything.
//!
//! A road's lanes each have their own friction: the world makes each lane of each lane
//! section a collider of its own, registered as a uniform surface, so the wheels' code asks
//! [`Ground::friction_at`] and does not change. A surface whose friction changed within one
//! collider would be another [`Surface`] variant answering for the point.

use proto_geom::nalgebra::Point3;
use rapier3d::prelude::ColliderHandle;

/// One surface a tyre can stand on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Surface {
    /// The same friction coefficient (dimensionless, ≥ 0) everywhere on it.
    Uniform(f64),
}

impl Surface {
    /// The friction coefficient (dimensionless) at `_point` (m, world) on this surface. Every
    /// surface so far is uniform; the point is what a surface with lanes will answer for.
    fn friction_at(&self, _point: &Point3<f64>) -> f64 {
        match *self {
            Surface::Uniform(mu) => mu,
        }
    }
}

/// The surfaces of a world, keyed by their rapier colliders, and the ground's friction for
/// anything else.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Ground {
    /// The flat ground's friction coefficient (dimensionless): also that of anything touched
    /// that is not registered.
    ground: f64,
    /// The registered surfaces, sorted by the collider's index (a binary search per wheel and
    /// step, whatever the number of obstacles).
    surfaces: Vec<(ColliderHandle, Surface)>,
}

impl Ground {
    /// A world whose flat ground has the friction coefficient `ground_friction`
    /// (dimensionless, validated ≥ 0 by the world's configuration); no surface registered yet.
    pub(crate) fn new(ground_friction: f64) -> Ground {
        Ground {
            ground: ground_friction,
            surfaces: Vec::new(),
        }
    }

    /// Registers the collider `collider` as `surface`, replacing what it was.
    pub(crate) fn add(&mut self, collider: ColliderHandle, surface: Surface) {
        match self.search(collider) {
            Ok(i) => self.surfaces[i] = (collider, surface),
            Err(i) => self.surfaces.insert(i, (collider, surface)),
        }
    }

    /// The friction coefficient (dimensionless) at `point` (m, world) of the collider
    /// `collider` a tyre touches: its surface's there if registered, else the ground's (see
    /// the module documentation).
    pub(crate) fn friction_at(&self, collider: ColliderHandle, point: &Point3<f64>) -> f64 {
        match self.search(collider) {
            Ok(i) => self.surfaces[i].1.friction_at(point),
            Err(_) => self.ground,
        }
    }

    /// Where `collider` is in `surfaces` (`Ok`) or would go (`Err`). A handle with the index
    /// of a registered one and another generation (a removed collider's slot reused) is not
    /// that surface: it goes beside it.
    fn search(&self, collider: ColliderHandle) -> Result<usize, usize> {
        let key = collider.into_raw_parts();
        self.surfaces
            .binary_search_by_key(&key, |(h, _)| h.into_raw_parts())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn handle(index: u32) -> ColliderHandle {
        ColliderHandle::from_raw_parts(index, 0)
    }

    #[test]
    fn a_registered_surface_has_its_own_friction_kept_in_f64() {
        let mut g = Ground::new(1.0);
        g.add(handle(3), Surface::Uniform(0.7));
        g.add(handle(1), Surface::Uniform(0.3));
        let p = Point3::new(12.0, -4.0, 0.0);
        // Exactly the configured f64, not its f32 rounding (0.699999988079071).
        assert_eq!(g.friction_at(handle(3), &p), 0.7);
        assert_eq!(g.friction_at(handle(1), &p), 0.3);
        assert_ne!(f64::from(0.7_f32), 0.7);
    }

    #[test]
    fn anything_not_registered_has_the_grounds_friction() {
        let mut g = Ground::new(0.45);
        g.add(handle(0), Surface::Uniform(0.45));
        g.add(handle(2), Surface::Uniform(0.9));
        let p = Point3::origin();
        // Another car's collider, a robot's: not surfaces.
        assert_eq!(g.friction_at(handle(1), &p), 0.45);
        assert_eq!(g.friction_at(handle(7), &p), 0.45);
        assert_eq!(g.friction_at(ColliderHandle::invalid(), &p), 0.45);
        // The same index in another generation is another collider.
        let reused = ColliderHandle::from_raw_parts(2, 1);
        assert_eq!(g.friction_at(reused, &p), 0.45);
    }

    #[test]
    fn registering_a_collider_again_replaces_its_surface() {
        let mut g = Ground::new(1.0);
        g.add(handle(4), Surface::Uniform(0.5));
        g.add(handle(4), Surface::Uniform(0.25));
        assert_eq!(g.friction_at(handle(4), &Point3::origin()), 0.25);
        assert_eq!(g.surfaces.len(), 1);
    }
}
