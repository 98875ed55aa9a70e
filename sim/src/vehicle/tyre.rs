//! The wheel–ground contact solve of a car: suspension, tyre friction and wheel spin for one
//! step, as velocity-level constraints between the chassis and the four wheel spins.
//!
//! Each wheel that touches the ground contributes three rows, solved by projected
//! Gauss–Seidel sweeps with impulses accumulated (and warm-started from the previous step):
//!
//! * **suspension** (along the chassis' up axis at the wheel's hard point): the spring-damper
//!   force `k·x + c·ẋ`, integrated implicitly (`x` taken at the end of the step), so any stiffness
//!   is stable at any `basicTimeStep`. The ground cannot pull: the impulse is at least 0;
//! * **tyre friction** (forward and lateral in the ground plane, at the contact point): no slip,
//!   coupled in one 2×2 solve, each direction's impulse limited to `μ·N·dt` of the wheel's
//!   suspension load `N`: the friction *pyramid* of ODE's default contact (what Webots uses),
//!   aligned with the tyre, so a spinning or locked wheel keeps its side grip;
//! * **brake** (on the spin only): a Coulomb torque of at most the brake torque that opposes
//!   the rotation and holds a stopped wheel.
//!
//! The spin of each wheel is a coordinate relative to the chassis (reduced coordinates, as
//! Webots' ODE joints or a rapier multibody): a torque between wheel and chassis (motor, brake,
//! damping) acts on the spin alone, and a tyre force acts on the chassis at the contact point
//! and on the spin through the radius. The inertial coupling between a wheel's spin and the
//! chassis' rotation is left out of the solve (a wheel's spin inertia is under 0.1 % of a car's
//! pitch inertia); the caller applies its effect, the reaction `−I·Δω` of each wheel's change
//! of spin, to the chassis afterwards. In velocity control the spin is imposed (a Webots motor
//! with a practically unlimited `maxTorque`), so the tyre force acts on the chassis alone.

use rapier3d::prelude::{Mat3, Vector};

/// Gauss–Seidel sweeps per step. With warm starting, 8 sweeps leave residual slip velocities
/// under 1 mm/s on every shipped car (the chassis couples the four contacts; each sweep solves
/// one contact exactly given the others).
pub(crate) const SWEEPS: usize = 8;

/// The chassis as the solve sees it: its velocities (changed in place) and inverse mass
/// properties in the world frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Body {
    /// Velocity of the centre of mass (m/s).
    pub linvel: Vector,
    /// Angular velocity (rad/s).
    pub angvel: Vector,
    /// 1/mass (1/kg).
    pub inv_mass: f32,
    /// Inverse inertia tensor about the centre of mass in world axes (1/(kg·m²)).
    pub inv_inertia: Mat3,
}

impl Body {
    /// Velocity (m/s) of the chassis point at `arm` (m) from the centre of mass.
    fn velocity_at(&self, arm: Vector) -> Vector {
        self.linvel + self.angvel.cross(arm)
    }

    /// Applies `impulse` (N·s) at `arm` (m) from the centre of mass.
    fn apply(&mut self, arm: Vector, impulse: Vector) {
        self.linvel += impulse * self.inv_mass;
        self.angvel += self.inv_inertia * arm.cross(impulse);
    }

    /// `d1ᵀ·M⁻¹·d2` for unit impulses along `d1` and `d2` at `arm`: the inverse effective mass
    /// (1/kg) coupling two directions at one point.
    fn inv_mass_along(&self, arm: Vector, d1: Vector, d2: Vector) -> f32 {
        d1.dot(d2) * self.inv_mass + arm.cross(d1).dot(self.inv_inertia * arm.cross(d2))
    }
}

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
        /// Brake torque × dt (N·m·s, ≥ 0).
        brake_impulse: f32,
    },
}

/// A wheel's ground contact for this step, in world axes, arms from the chassis' centre of
/// mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Contact {
    /// Hard point (the wheel centre at the unloaded spring length) − centre of mass (m).
    pub hardpoint_arm: Vector,
    /// The suspension axis, the chassis' up axis (unit).
    pub up: Vector,
    /// Spring compression from the unloaded length (m, > 0 = wheel pushed up).
    pub compression: f32,
    /// Contact point − centre of mass (m).
    pub contact_arm: Vector,
    /// Rolling direction in the ground plane (unit).
    pub forward: Vector,
    /// Wheel axis projected on the ground plane (unit, to the car's left for an unsteered wheel).
    pub lateral: Vector,
    /// Tyre radius (m).
    pub radius: f32,
    /// Friction coefficient of the tyre on this ground.
    pub friction: f32,
    /// Spring constant (N/m).
    pub stiffness: f32,
    /// Damping constant (N·s/m).
    pub damping: f32,
}

/// One wheel in the solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct WheelRow {
    /// The ground contact, `None` in the air.
    pub contact: Option<Contact>,
    /// How the spin is driven.
    pub spin: Spin,
    /// Spin rate relative to the chassis (rad/s, positive rolling forward), changed in place.
    pub omega: f32,
    /// Accumulated impulses of the step (warm start in, solution out): suspension (N·s),
    /// forward and lateral friction (N·s), brake (N·m·s).
    pub impulses: Impulses,
}

/// The impulses of one wheel's rows over a step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Impulses {
    /// Suspension impulse along the chassis up axis (N·s, ≥ 0): load × dt.
    pub normal: f32,
    /// Tyre impulse along the rolling direction (N·s).
    pub forward: f32,
    /// Tyre impulse along the wheel axis (N·s).
    pub lateral: f32,
    /// Brake impulse on the spin (N·m·s).
    pub brake: f32,
}

/// The per-step constants of one contact.
#[derive(Debug, Clone, Copy)]
struct Rows {
    /// Inverse effective mass of the suspension row (1/kg).
    k_normal: f32,
    /// `dt·k·x` (N·s): the spring's impulse at the current compression.
    spring_impulse: f32,
    /// `dt·(k·dt + c)` (N·s²/m... = kg): the implicit spring-damper's impulse per m/s of
    /// compression rate.
    softness: f32,
    /// Inverse of the 2×2 friction matrix `[[ff, fl], [fl, ll]]` (kg).
    inv_friction: [f32; 3],
    /// 1/spin inertia (0 when the spin is imposed).
    inv_spin: f32,
}

impl Rows {
    fn new(body: &Body, c: &Contact, spin: Spin, dt: f32) -> Option<Rows> {
        let inv_spin = match spin {
            Spin::Imposed => 0.0,
            Spin::Free { inv_inertia, .. } => inv_inertia,
        };
        let ff = body.inv_mass_along(c.contact_arm, c.forward, c.forward)
            + c.radius * c.radius * inv_spin;
        let fl = body.inv_mass_along(c.contact_arm, c.forward, c.lateral);
        let ll = body.inv_mass_along(c.contact_arm, c.lateral, c.lateral);
        let det = ff * ll - fl * fl;
        if !(det.is_finite() && det > 0.0) {
            return None;
        }
        Some(Rows {
            k_normal: body.inv_mass_along(c.hardpoint_arm, c.up, c.up),
            spring_impulse: dt * c.stiffness * c.compression,
            softness: dt * (c.stiffness * dt + c.damping),
            inv_friction: [ll / det, -fl / det, ff / det],
            inv_spin,
        })
    }
}

/// Solves one step of `dt` seconds: updates the chassis velocities, the wheel spins and the
/// accumulated impulses.
///
/// Every wheel's `impulses` must hold its warm start (the previous step's solution, or zeros);
/// they are clamped to this step's limits before use.
pub(crate) fn solve(body: &mut Body, wheels: &mut [WheelRow; 4], dt: f32) {
    let mut rows: [Option<Rows>; 4] = [None; 4];
    for (row, w) in rows.iter_mut().zip(wheels.iter_mut()) {
        *row = w.contact.and_then(|c| Rows::new(body, &c, w.spin, dt));
        let (Some(r), Some(c)) = (*row, w.contact) else {
            w.impulses = Impulses {
                brake: w.impulses.brake,
                ..Impulses::default()
            };
            continue;
        };
        // Warm start, within this step's limits.
        let i = &mut w.impulses;
        i.normal = i.normal.max(0.0);
        let (f, l) = clamp_to_box(i.forward, i.lateral, c.friction * i.normal);
        i.forward = f;
        i.lateral = l;
        body.apply(c.hardpoint_arm, c.up * i.normal);
        body.apply(c.contact_arm, c.forward * f + c.lateral * l);
        w.omega -= c.radius * f * r.inv_spin;
    }
    for w in wheels.iter_mut() {
        if let Spin::Free {
            inv_inertia,
            brake_impulse,
        } = w.spin
        {
            let b = w.impulses.brake.clamp(-brake_impulse, brake_impulse);
            w.impulses.brake = b;
            w.omega += b * inv_inertia;
        } else {
            w.impulses.brake = 0.0;
        }
    }

    // Gauss–Seidel favours the rows solved first; swapping the right and left wheels of each
    // axle every other sweep keeps a symmetric car from drifting to one side.
    const ORDERS: [[usize; 4]; 2] = [[0, 1, 2, 3], [1, 0, 3, 2]];
    for sweep in 0..SWEEPS {
        for i in ORDERS[sweep % 2] {
            let w = &mut wheels[i];
            brake_row(w);
            if let (Some(r), Some(c)) = (&rows[i], w.contact) {
                suspension_row(body, w, r, &c);
                friction_rows(body, w, r, &c);
            }
        }
    }
}

/// The brake: drives the spin toward 0 with an impulse within `±brake_impulse`.
fn brake_row(w: &mut WheelRow) {
    let Spin::Free {
        inv_inertia,
        brake_impulse,
    } = w.spin
    else {
        return;
    };
    if brake_impulse <= 0.0 || inv_inertia <= 0.0 {
        return;
    }
    let old = w.impulses.brake;
    let new = (old - w.omega / inv_inertia).clamp(-brake_impulse, brake_impulse);
    w.impulses.brake = new;
    w.omega += (new - old) * inv_inertia;
}

/// The implicit spring-damper: `P = dt·k·x + dt·(k·dt + c)·ẋ` with `ẋ` the compression rate
/// after the impulse, `P ≥ 0`.
fn suspension_row(body: &mut Body, w: &mut WheelRow, r: &Rows, c: &Contact) {
    let rate = -c.up.dot(body.velocity_at(c.hardpoint_arm));
    let old = w.impulses.normal;
    let residual = old - r.spring_impulse - r.softness * rate;
    let new = (old - residual / (1.0 + r.softness * r.k_normal)).max(0.0);
    w.impulses.normal = new;
    body.apply(c.hardpoint_arm, c.up * (new - old));
}

/// The tyre: removes the contact point's slip in the ground plane, each direction within the
/// friction limit of the current suspension impulse.
fn friction_rows(body: &mut Body, w: &mut WheelRow, r: &Rows, c: &Contact) {
    let v = body.velocity_at(c.contact_arm);
    let slip_f = c.forward.dot(v) - w.omega * c.radius;
    let slip_l = c.lateral.dot(v);
    let [a, b, d] = r.inv_friction;
    let (f0, l0) = (w.impulses.forward, w.impulses.lateral);
    let f = f0 - (a * slip_f + b * slip_l);
    let l = l0 - (b * slip_f + d * slip_l);
    let (f, l) = clamp_to_box(f, l, c.friction * w.impulses.normal);
    w.impulses.forward = f;
    w.impulses.lateral = l;
    body.apply(c.contact_arm, c.forward * (f - f0) + c.lateral * (l - l0));
    w.omega -= c.radius * (f - f0) * r.inv_spin;
}

/// `x` and `y` each clamped to `±limit` (a negative limit counts as 0).
fn clamp_to_box(x: f32, y: f32, limit: f32) -> (f32, f32) {
    let limit = limit.max(0.0);
    (x.clamp(-limit, limit), y.clamp(-limit, limit))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 1000 kg point-like body (inertia 1000 kg·m² about every axis) at rest.
    fn body() -> Body {
        Body {
            linvel: Vector::ZERO,
            angvel: Vector::ZERO,
            inv_mass: 1e-3,
            inv_inertia: Mat3::from_diagonal(Vector::splat(1e-3)),
        }
    }

    /// A contact straight below the centre of mass (no moment arms).
    fn contact(compression: f32, friction: f32) -> Contact {
        Contact {
            hardpoint_arm: Vector::ZERO,
            up: Vector::Z,
            compression,
            contact_arm: Vector::ZERO,
            forward: Vector::X,
            lateral: Vector::Y,
            radius: 0.5,
            friction,
            stiffness: 1e5,
            damping: 0.0,
        }
    }

    fn wheel(contact: Option<Contact>, spin: Spin, omega: f32) -> WheelRow {
        WheelRow {
            contact,
            spin,
            omega,
            impulses: Impulses::default(),
        }
    }

    fn airborne() -> WheelRow {
        wheel(None, Spin::Imposed, 0.0)
    }

    #[test]
    fn implicit_spring_impulse() {
        // One wheel, body at rest, x = 0.01 m, k = 1e5 N/m, c = 0, dt = 0.01 s:
        // P = dt·k·(x + dt·ẋ') with ẋ' = −P/m: P = 10/(1 + 1e5·1e-4·1e-3) = 10/1.01 N·s.
        let mut b = body();
        let mut w = [
            wheel(Some(contact(0.01, 0.0)), Spin::Imposed, 0.0),
            airborne(),
            airborne(),
            airborne(),
        ];
        solve(&mut b, &mut w, 0.01);
        let p = w[0].impulses.normal;
        assert!((p - 10.0 / 1.01).abs() < 1e-4, "{p}");
        assert!((b.linvel.z - p * 1e-3).abs() < 1e-7);
    }

    #[test]
    fn stretched_spring_does_not_pull() {
        let mut b = body();
        b.linvel.z = 1.0; // leaving the ground
        let mut w = [
            wheel(Some(contact(0.001, 1.0)), Spin::Imposed, 0.0),
            airborne(),
            airborne(),
            airborne(),
        ];
        solve(&mut b, &mut w, 0.01);
        assert_eq!(w[0].impulses.normal, 0.0);
        assert_eq!(b.linvel.z, 1.0);
    }

    #[test]
    fn imposed_spin_drags_the_body_to_the_rim_speed() {
        // Wheel imposed at 0.4 rad/s, radius 0.5: rim 0.2 m/s, 200 N·s for 1000 kg, within the
        // 10 × 99 N·s the grip allows: the body reaches it.
        let mut b = body();
        let mut w = [
            wheel(Some(contact(0.1, 10.0)), Spin::Imposed, 0.4),
            airborne(),
            airborne(),
            airborne(),
        ];
        solve(&mut b, &mut w, 0.01);
        assert!((b.linvel.x - 0.2).abs() < 1e-6, "{}", b.linvel.x);
        assert!(b.linvel.y.abs() < 1e-6);
        assert_eq!(w[0].omega, 0.4);
    }

    #[test]
    fn friction_pyramid_limits_each_direction() {
        // μ = 0.5 on the 9.9 N·s suspension impulse: at most 4.95 N·s along each tyre axis,
        // far below the 3000 and 4000 N·s that would stop the slip.
        let mut b = body();
        b.linvel = Vector::new(-3.0, 4.0, 0.0);
        let mut w = [
            wheel(Some(contact(0.01, 0.5)), Spin::Imposed, 0.0),
            airborne(),
            airborne(),
            airborne(),
        ];
        solve(&mut b, &mut w, 0.01);
        let i = w[0].impulses;
        let limit = 0.5 * i.normal;
        assert!((limit - 0.5 * 10.0 / 1.01).abs() < 1e-3, "{limit}");
        // Each direction saturated, opposite to its slip.
        assert!((i.forward - limit).abs() < 1e-4 && (i.lateral + limit).abs() < 1e-4);
    }

    #[test]
    fn free_wheel_spins_up_to_rolling_and_momentum_is_shared() {
        // Body at 1 m/s over a free wheel (inertia 0.25 kg·m², radius 0.5) at rest: the contact
        // ends without slip, v = ω·r, and the forward impulse F·dt takes m·Δv from the body and
        // gives I·ω/r to the wheel: 1000·(1 − v) = 0.25·(v/0.5)/0.5 → v = 1000/1001 m/s.
        let mut b = body();
        b.linvel.x = 1.0;
        let free = Spin::Free {
            inv_inertia: 4.0,
            brake_impulse: 0.0,
        };
        let mut w = [
            wheel(Some(contact(0.1, 10.0)), free, 0.0),
            airborne(),
            airborne(),
            airborne(),
        ];
        solve(&mut b, &mut w, 0.01);
        let v = 1000.0 / 1001.0;
        assert!((b.linvel.x - v).abs() < 1e-5, "{}", b.linvel.x);
        assert!((w[0].omega - v / 0.5).abs() < 1e-4, "{}", w[0].omega);
    }

    #[test]
    fn brake_holds_a_wheel_it_can_hold_and_slips_otherwise() {
        let brake = |brake_impulse| Spin::Free {
            inv_inertia: 4.0,
            brake_impulse,
        };
        // Airborne wheel at 10 rad/s: stopping needs 10/4 = 2.5 N·m·s; a 1 N·m·s brake takes
        // 4 rad/s off, a 5 N·m·s brake stops it.
        let mut w = [
            wheel(None, brake(1.0), 10.0),
            wheel(None, brake(5.0), 10.0),
            airborne(),
            airborne(),
        ];
        solve(&mut body(), &mut w, 0.01);
        assert!((w[0].omega - 6.0).abs() < 1e-5, "{}", w[0].omega);
        assert_eq!(w[1].omega, 0.0);
    }

    #[test]
    fn clamp_to_box_clamps_each_axis() {
        assert_eq!(clamp_to_box(3.0, -4.0, 10.0), (3.0, -4.0));
        assert_eq!(clamp_to_box(3.0, -4.0, 3.5), (3.0, -3.5));
        assert_eq!(clamp_to_box(3.0, 4.0, -1.0), (0.0, 0.0));
    }
}
