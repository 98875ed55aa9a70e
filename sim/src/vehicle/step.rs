//! A car's step, once for both mountings: the chassis and the steering of the step, each
//! wheel's row and its contact on the ground, the solve, the wheels' ends of step, and the
//! hand-back to rapier. What the mountings do differently is a [`Mount`]: how the steering
//! moves (`steer`), how the chassis' motion is read (`chassis`), where a wheel touches the
//! ground (`find`) and how the solved step reaches rapier (`hand_back`). The ground's friction
//! under a wheel is the world's [`Ground`]'s, for the collider the wheel touches, on both.

use ackermann::Wheel;
use rapier3d::prelude::{ColliderHandle, PhysicsWorld, RigidBodyHandle, Vector};

use super::contact::{Body, Contact, Support, WheelRow};
use super::wheels::Footing;
use super::{Frame, Vehicle};
use crate::geom;
use crate::ground::Ground;

/// What the two wheel mountings ([`Mounting`](super::Mounting)) do differently in a step.
pub(super) trait Mount {
    /// True if the solve carries the wheels' loads (the cast car: its springs are rows of the
    /// solve); false if rapier does (on joints: the loads are given, its last contacts'
    /// impulses).
    const CARRIES_LOAD: bool;

    /// True if a rigid contact's forward impulse starts from the last step's (the cast car),
    /// false if from zero: on joints, the carried-over share of a longitudinal force between
    /// four stuck wheels acts as a stiff spring between car and ground
    /// ([`WheelRow::cold_start_rigid_forward`]).
    const WARM_RIGID_FORWARD: bool;

    /// Moves the steering for the step of `dt` seconds.
    fn steer(&self, car: &mut Vehicle, world: &mut PhysicsWorld, dt: f64);

    /// The chassis for a step of `dt` seconds: its frame and its motion as the solve's body,
    /// gravity's change of velocity over the step added. `None` if the chassis is gone (the
    /// step then does nothing).
    fn chassis(&self, world: &PhysicsWorld, dt: f64) -> Option<(Frame, Body)>;

    /// Wheel `w`'s spin axis and ground contact, with arms from the centre of mass of `frame`;
    /// `None` if the wheel's body is gone.
    fn find(&self, car: &Vehicle, world: &PhysicsWorld, w: Wheel, frame: &Frame) -> Option<Found>;

    /// Hands the solved step of `dt` seconds to rapier.
    fn hand_back(&self, car: &mut Vehicle, world: &mut PhysicsWorld, solved: &Solved, dt: f64);
}

/// A wheel as [`Mount::find`] finds it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Found {
    /// Its spin axis (unit, world).
    pub axis: Vector,
    /// Its ground contact; `None` in the air.
    pub touch: Option<Touch>,
}

/// A wheel's contact with what it stands on.
#[derive(Debug, Clone, Copy)]
pub(super) struct Touch {
    /// The contact for the solve.
    pub contact: Contact,
    /// The collider the tyre touches: the ground's friction is looked up by it and the
    /// contact point ([`Ground::friction_at`]).
    pub collider: ColliderHandle,
    /// The normal impulse (N·s, ≥ 0) rapier's contact carried over the last step, where
    /// rapier carries the load (on joints); `None` where the solve does (cast).
    pub given_impulse: Option<f32>,
    /// The body of what the tyre stands on, if it is dynamic: it takes the tyre force's
    /// reaction.
    pub ground_body: Option<RigidBodyHandle>,
}

impl Touch {
    /// The friction coefficient (dimensionless) of the ground at the contact point, `frame`
    /// being the chassis' of the step (the contact's arms start at its centre of mass).
    fn friction(&self, ground: &Ground, frame: &Frame) -> f64 {
        let point = geom::to_point(frame.com + self.contact.contact_arm);
        ground.friction_at(self.collider, &point)
    }
}

/// A step as solved, for [`Mount::hand_back`].
pub(super) struct Solved {
    /// The chassis' frame of the step.
    pub frame: Frame,
    /// The chassis' motion after the solve.
    pub body: Body,
    /// Each wheel's row after the solve (its contact, in the air `None`, and impulses).
    pub rows: [WheelRow; 4],
    /// Each wheel's spin axis (unit, world; zero for a wheel whose body is gone).
    pub axes: [Vector; 4],
    /// Each wheel's change of angular momentum about its axis over the step (N·m·s).
    pub spin_changes: [f64; 4],
    /// The dynamic body under each wheel, if any.
    pub ground_bodies: [Option<RigidBodyHandle>; 4],
}

impl Vehicle {
    /// The step of `dt` seconds on the mounting `mount`, the ground's friction read from
    /// `ground`: the steering and the chassis, each wheel's row and contact, the solve of the
    /// tyres, brakes and spins (with the suspension where the solve carries the load), the
    /// wheels' ends of step, and the hand-back to rapier.
    pub(super) fn step_on<M: Mount>(
        &mut self,
        mount: &M,
        world: &mut PhysicsWorld,
        ground: &Ground,
        dt: f64,
    ) {
        mount.steer(self, world, dt);
        let Some((frame, body)) = mount.chassis(world, dt) else {
            return;
        };
        // Built where it is handed back, so that the rows are not copied for the hand-back.
        let mut s = Solved {
            frame,
            body,
            rows: [WheelRow::idle(); 4],
            axes: [Vector::ZERO; 4],
            spin_changes: [0.0; 4],
            ground_bodies: [None; 4],
        };
        let mut imposed = [0.0; 4];
        let mut roads = [0.0; 4];
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            imposed[i] = self.start_row(w, &mut s.rows[i], dt);
            let Some(found) = mount.find(self, world, w, &s.frame) else {
                continue;
            };
            s.axes[i] = found.axis;
            let Some(touch) = found.touch else {
                continue;
            };
            let road = touch.friction(ground, &s.frame);
            let load = match touch.given_impulse {
                Some(impulse) => {
                    // rapier carried the load: the row's normal impulse is given.
                    s.rows[i].impulses.normal = impulse;
                    f64::from(impulse) / dt
                }
                None => self.tyre_load(w, &touch.contact, dt),
            };
            roads[i] = road;
            s.ground_bodies[i] = touch.ground_body;
            let footing = Footing { road, load };
            self.set_up_contact(w, &mut s.rows[i], touch.contact, &s.body, footing, dt);
        }
        self.divide_axles(&mut s.rows);
        if !M::WARM_RIGID_FORWARD {
            for row in &mut s.rows {
                row.cold_start_rigid_forward();
            }
        }
        // Where the solve carries the load, the braked wheels' sub-steps take its mean too.
        self.solve_contacts(&mut s.body, &mut s.rows, M::CARRIES_LOAD, dt);
        s.spin_changes = self.finish_wheels(&mut s.body, &s.rows, imposed, s.axes, roads, dt);
        mount.hand_back(self, world, &s, dt);
    }

    /// The load (N) wheel `w`'s tyre coefficients are taken at on `contact` where the solve
    /// carries the load: the last step's, or the spring's at the current compression for a
    /// wheel that just landed.
    fn tyre_load(&self, w: Wheel, contact: &Contact, dt: f64) -> f64 {
        let previous = f64::from(self.impulses[w].normal) / dt;
        match contact.support {
            Support::Spring(s) if previous <= 0.0 => f64::from(s.stiffness * s.compression),
            _ => previous,
        }
    }
}

#[cfg(test)]
impl Vehicle {
    /// The ground's friction coefficient (dimensionless) under each wheel as the next step
    /// will read it (`None` in the air), for the tests that both mountings read alike.
    pub(crate) fn ground_frictions(
        &self,
        world: &PhysicsWorld,
        ground: &Ground,
    ) -> [Option<f64>; 4] {
        match &self.parts {
            super::Parts::Cast(p) => self.frictions_on(p, world, ground),
            super::Parts::Joints(p) => self.frictions_on(p, world, ground),
        }
    }

    fn frictions_on<M: Mount>(
        &self,
        mount: &M,
        world: &PhysicsWorld,
        ground: &Ground,
    ) -> [Option<f64>; 4] {
        let Some((frame, _)) = mount.chassis(world, 0.0) else {
            return [None; 4];
        };
        Wheel::ALL.map(|w| {
            let touch = mount.find(self, world, w, &frame)?.touch?;
            Some(touch.friction(ground, &frame))
        })
    }
}
