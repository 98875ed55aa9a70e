//! One solver contact per wheel on the road for a joints car.
//!
//! rapier's contact between a wheel's round-treaded cylinder and the ground holds two points
//! 2 mm apart across the tread (the ends of the flat core the round cylinder needs). Two
//! normal rows on one spot give the multibody solver twice the work for the same support, so
//! this hook keeps the deeper one where the wheel touches a body that does not move (the
//! road, a ramp, a step). Contacts with dynamic bodies and between wheels stay as rapier
//! finds them.

use rapier3d::prelude::{ActiveHooks, ColliderHandle, ContactModificationContext, PhysicsHooks};

/// The hooks of a world with cars on joints: their wheels' road contacts.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct WheelRoadHooks;

/// What a joints car's wheel collider asks of rapier for its contacts to go through
/// [`WheelRoadHooks`].
pub(crate) const WHEEL_HOOKS: ActiveHooks = ActiveHooks::MODIFY_SOLVER_CONTACTS;

impl PhysicsHooks for WheelRoadHooks {
    fn modify_solver_contacts(&self, context: &mut ContactModificationContext<'_>) {
        let wheel = |h: ColliderHandle| {
            context
                .colliders
                .get(h)
                .is_some_and(|c| c.active_hooks().contains(WHEEL_HOOKS))
        };
        let other = match (wheel(context.collider1), wheel(context.collider2)) {
            (true, false) => context.rigid_body2,
            (false, true) => context.rigid_body1,
            _ => return,
        };
        if other
            .and_then(|h| context.bodies.get(h))
            .is_some_and(|b| b.is_dynamic())
        {
            return;
        }
        let Some(m) = context.rigid_mut() else {
            return;
        };
        let Some(deepest) = m
            .solver_contacts
            .iter()
            .min_by(|a, b| a.dist.total_cmp(&b.dist))
            .copied()
        else {
            return;
        };
        m.solver_contacts.clear();
        m.solver_contacts.push(deepest);
    }
}
