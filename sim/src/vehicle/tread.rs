//! One solver contact per wheel on the road for a joints car.
//!
//! rapier's contact between a wheel's round-treaded cylinder and the ground holds two points
//! 2 mm apart across the tread (the ends of the flat core the round cylinder needs). Two
//! normal rows on one spot give the multibody solver twice the work for the same support, so
//! where the wheel touches a body that does not move (the road, a ramp, a step) this hook
//! keeps one: the two points' midpoint, on the wheel's mid-plane, at their mean depth (a
//! manifold of another size keeps its deepest point). Contacts with dynamic bodies and
//! between wheels stay as rapier finds them.
//!
//! Keeping the deeper of the two, as this hook did before 2026-11-29, broke the car's mirror
//! symmetry: on a level wheel round-off decides which is deeper, and the left and right
//! wheels, whose colliders face the same way, chose the point on the same world side, so the
//! car stood 1 mm off its mid-plane on both sides at once. That was the joints mounting's
//! steady left–right bias (issue #35): a symmetric car's full-throttle launch yawed about
//! 1·10⁻⁵ rad in 14 s, always the same way; with the midpoint, 3·10⁻⁷ to 1·10⁻⁶ rad
//! (ARCHITECTURE.md, "Launch chatter").

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
        let one = match m.solver_contacts.as_slice() {
            // The two ends of the flat core: their midpoint, on the wheel's mid-plane.
            [a, b] => {
                let mut mid = *a;
                mid.anchor1 = (a.anchor1 + b.anchor1) * 0.5;
                mid.anchor2 = (a.anchor2 + b.anchor2) * 0.5;
                mid.dist = (a.dist + b.dist) * 0.5;
                mid
            }
            contacts => {
                let Some(deepest) = contacts
                    .iter()
                    .min_by(|a, b| a.dist.total_cmp(&b.dist))
                    .copied()
                else {
                    return;
                };
                deepest
            }
        };
        m.solver_contacts.clear();
        m.solver_contacts.push(one);
    }
}
