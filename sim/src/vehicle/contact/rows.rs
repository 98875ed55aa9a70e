//! What each wheel brings to the contact solve: its ground contact and what carries its load,
//! its tyre's force law for the step, how its spin is driven, and the impulses it accumulates.

use rapier3d::prelude::Vector;
use vehicle_model::Linearised;

use super::body::Body;

/// How a wheel's spin takes part in the solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Spin {
    /// Imposed by a rigid velocity motor (Webots velocity control): the tyre cannot change it.
    Imposed,
    /// Free to turn, with spin inertia `1/inv_inertia` (kg·m²) and a brake that can deliver at
    /// most `brake_impulse` (N·m·s) this step.
    Free {
        /// 1/spin inertia (1/(kg·m²)).
        inv_inertia: f32,
        /// (Brake torque + rolling resistance) × dt (N·m·s, ≥ 0).
        brake_impulse: f32,
    },
}

impl Spin {
    #[inline]
    pub(super) fn inv_inertia(self) -> f32 {
        match self {
            Spin::Imposed => 0.0,
            Spin::Free { inv_inertia, .. } => inv_inertia,
        }
    }
}

/// A wheel's ground contact for this step, in world axes, arms from the chassis' centre of
/// mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Contact {
    /// What carries the wheel's load.
    pub support: Support,
    /// Contact point − centre of mass (m).
    pub contact_arm: Vector,
    /// The ground's normal at the contact (unit, out of the ground): the direction of the
    /// ground's normal force on the tyre.
    pub normal: Vector,
    /// Rolling direction in the ground plane (unit).
    pub forward: Vector,
    /// Wheel axis projected on the ground plane (unit, to the car's left for an unsteered wheel).
    pub lateral: Vector,
    /// Tyre radius (m).
    pub radius: f32,
}

/// What carries a wheel's load in the solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Support {
    /// The solve's own suspension row (the cast car: the wheel is no body).
    Spring(Spring),
    /// A contact that rapier solves (the car on joints: the wheel is a body on a suspension
    /// joint): the wheel row's normal impulse is given.
    Given,
}

/// A suspension spring-damper between the chassis and a wheel that is no body.
///
/// The spring pushes along the suspension axis; what reaches the chassis is the ground's
/// normal force at the contact point, carried through the wheel (taken as massless) by the
/// spring and, across the axis, by the rigid slider: the normal impulse `N` meets the
/// spring's `N·(n·up) + P_t·up = P_spring`, `P_t` the tyre's impulse: on a chassis leaning
/// in a turn the tyres' lateral forces push along the tilted axes, as on the car on joints.
/// (A force along the axis at the hard point instead would push a pitched or rolled chassis
/// along the ground with `N·sin(tilt)`, a force no friction gives: 180 N forward on a
/// nose-down BmwX5.)
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Spring {
    /// Hard point (the wheel centre at the unloaded spring length) − centre of mass (m).
    pub hardpoint_arm: Vector,
    /// The suspension axis, the chassis' up axis (unit).
    pub up: Vector,
    /// Spring compression from the unloaded length (m, > 0 = wheel pushed up).
    pub compression: f32,
    /// Spring constant (N/m).
    pub stiffness: f32,
    /// Damping constant (N·s/m).
    pub damping: f32,
}

impl Contact {
    /// The contact of a tyre of `radius` (m) whose centre is at `centre` (m, world) and spin
    /// axis `axis` (unit, world) on ground of unit normal `normal`, carried by `support`, with
    /// arms from the centre of mass `com` (m, world): the contact point is the lowest point of
    /// the tyre's centre plane, the lateral direction the wheel axis projected on the ground.
    /// `None` if the axis stands along the normal (a wheel lying flat rolls nowhere).
    pub fn on_ground(
        support: Support,
        normal: Vector,
        axis: Vector,
        centre: Vector,
        radius: f32,
        com: Vector,
    ) -> Option<Contact> {
        Contact::at_point(support, normal, axis, centre - normal * radius, radius, com)
    }

    /// As [`Contact::on_ground`], touching the ground at `point` (m, world) instead of right
    /// under the centre: where the ground's normal force acts on a wheel body whose tread is
    /// rounded, which moves across the tread as the wheel leans.
    pub fn at_point(
        support: Support,
        normal: Vector,
        axis: Vector,
        point: Vector,
        radius: f32,
        com: Vector,
    ) -> Option<Contact> {
        let lateral = (axis - normal * normal.dot(axis)).normalize_or_zero();
        (lateral != Vector::ZERO).then(|| Contact {
            support,
            contact_arm: point - com,
            normal,
            forward: lateral.cross(normal),
            lateral,
            radius,
        })
    }

    /// `n·up`: the cosine between the ground's normal and the suspension axis (1 on flat
    /// ground under a level chassis), the share of the normal impulse the spring carries.
    #[inline]
    pub(super) fn axis_cosine(&self, s: &Spring) -> f32 {
        self.normal.dot(s.up)
    }

    /// The spring of a wheel with its own suspension row.
    #[inline]
    pub(super) fn spring(&self) -> Option<&Spring> {
        match &self.support {
            Support::Spring(s) => Some(s),
            Support::Given => None,
        }
    }

    /// Applies the normal impulse `p` (N·s) of this contact to `body`: along the ground's
    /// normal at the contact point.
    #[inline]
    pub(super) fn apply_normal(&self, body: &mut Body, p: f32) {
        body.apply(self.contact_arm, self.normal * p);
    }
    /// The slip velocity `[forward, lateral]` (m/s) of the contact point over the ground for a
    /// wheel spinning at `omega` (rad/s).
    #[inline]
    pub fn slip_velocity(&self, body: &Body, omega: f32) -> [f32; 2] {
        let v = body.velocity_at(self.contact_arm);
        [
            self.forward.dot(v) - omega * self.radius,
            self.lateral.dot(v),
        ]
    }
}

/// The tyre's force law for one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Grip {
    /// Slip-based: per unit load (the suspension impulse), the tyre's law linearised over the
    /// step along `[forward, lateral]` at the end-of-step slip velocity, within its friction
    /// ellipse.
    Slip(Linearised<f32>),
    /// Webots' contact: slip velocity `−compliance·P` (0: none) while each axis' impulse is
    /// within `friction·N`.
    Coulomb {
        /// Force-dependent slip over dt, `[forward, lateral]` (m/s per N·s, ≥ 0).
        compliance: [f32; 2],
        /// Friction coefficient (dimensionless, ≥ 0).
        friction: f32,
    },
}

impl Grip {
    /// `[x, y]` within this step's friction limits for suspension impulse `normal` (N·s).
    #[inline]
    pub(super) fn clamp(&self, x: f32, y: f32, normal: f32) -> [f32; 2] {
        let normal = normal.max(0.0);
        match *self {
            Grip::Slip(law) => law.clamp_to_ellipse([x, y], normal),
            Grip::Coulomb { friction, .. } => {
                let limit = (friction * normal).max(0.0);
                [x.clamp(-limit, limit), y.clamp(-limit, limit)]
            }
        }
    }

    /// The row `α·ΔP + β·(K·ΔP) = c − β·v` of direction `i` (`v` the current slip velocity):
    /// the force law written so that no coefficient is infinite. `normal` is the current
    /// suspension impulse (N·s), `current` the direction's accumulated impulse (N·s).
    #[inline]
    pub(super) fn row(&self, i: usize, normal: f32, current: f32) -> (f32, f32, f32) {
        // Law: P = a − b·v (impulse against end-of-step slip velocity).
        let (a, b) = match *self {
            Grip::Slip(law) => {
                let n = normal.max(0.0);
                (
                    n * (law.force[i] + law.damping[i] * law.slip_velocity[i]),
                    n * law.damping[i],
                )
            }
            Grip::Coulomb { compliance, .. } => {
                if compliance[i] > 0.0 {
                    (0.0, 1.0 / compliance[i])
                } else {
                    (0.0, f32::INFINITY)
                }
            }
        };
        if b <= 1.0 {
            (1.0, b, a - current)
        } else if b.is_finite() {
            (1.0 / b, 1.0, (a - current) / b)
        } else {
            (0.0, 1.0, 0.0)
        }
    }
}

/// One wheel in the solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct WheelRow {
    /// The ground contact, `None` in the air.
    pub contact: Option<Contact>,
    /// The tyre's force law (unused in the air).
    pub grip: Grip,
    /// How the spin is driven.
    pub spin: Spin,
    /// Spin rate relative to the chassis (rad/s, positive rolling forward), changed in place.
    pub omega: f32,
    /// Accumulated impulses of the step (warm start in, solution out).
    pub impulses: Impulses,
}

impl WheelRow {
    /// Starts a rigid contact's forward impulse (Webots' contact without force-dependent
    /// slip) from zero instead of the last step's.
    ///
    /// How four wheels stuck to the ground share a longitudinal force is not unique with rigid
    /// contacts: the warm start carries the last step's share over. On the joints car, whose wheels are bodies of their own on rapier's joints,
    /// that carried-over force acts as a stiff spring between car and ground (measured: a
    /// BmwX5 stopped by its brakes rocked at 7 Hz, ±17 kN, for seconds); started from zero,
    /// the solve's sweeps find a share each step and the car settles.
    pub fn cold_start_rigid_forward(&mut self) {
        if let Grip::Coulomb { compliance, .. } = self.grip
            && compliance[0] <= 0.0
        {
            self.impulses.forward = 0.0;
        }
    }

    /// A wheel in the air with an imposed spin of 0 and no impulses: the start of a row.
    pub fn idle() -> WheelRow {
        WheelRow {
            contact: None,
            grip: Grip::Coulomb {
                compliance: [0.0; 2],
                friction: 0.0,
            },
            spin: Spin::Imposed,
            omega: 0.0,
            impulses: Impulses::default(),
        }
    }

    /// The wheel's spin rate after the solve (rad/s): the solved one if the spin is free,
    /// else `imposed`, the velocity command's rate in full precision.
    pub fn solved_spin(&self, imposed: f64) -> f64 {
        match self.spin {
            Spin::Imposed => imposed,
            Spin::Free { .. } => f64::from(self.omega),
        }
    }
}

/// The impulses of one wheel's rows over a step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Impulses {
    /// The ground's normal impulse along its normal (N·s, ≥ 0): load × dt.
    pub normal: f32,
    /// Tyre impulse along the rolling direction (N·s).
    pub forward: f32,
    /// Tyre impulse along the wheel axis (N·s).
    pub lateral: f32,
    /// Brake impulse on the spin (N·m·s).
    pub brake: f32,
}
