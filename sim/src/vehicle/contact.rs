//! The wheel–ground contact solve of a car: suspension, tyre forces, brakes and wheel spins for
//! one step, as velocity-level rows between the chassis and the four wheel spins.
//!
//! Each wheel on the ground contributes three rows, solved by projected block Gauss–Seidel
//! sweeps with impulses accumulated (and warm-started from the previous step):
//!
//! * **suspension** (along the chassis' up axis at the wheel's hard point): the spring-damper
//!   force `k·x + c·ẋ`, integrated implicitly (`x` taken at the end of the step), so any stiffness
//!   is stable at any `basicTimeStep`. The ground cannot pull: the impulse is at least 0;
//! * **tyre** (forward and lateral in the ground plane, at the contact point), by the car's
//!   tyre model ([`Grip`]):
//!   * slip-based: the force per unit load is an affine function of the contact's slip
//!     velocity at the end of the step (`vehicle_model::MagicFormula::linearise`), times the
//!     wheel's current suspension impulse, kept within the friction ellipse;
//!   * Webots: no slip (or ODE's force-dependent slip, a compliance) up to `μ·N` along each
//!     tyre axis separately, the friction pyramid of ODE's contact;
//! * **brake** (on the spin only): a Coulomb torque of at most the brake torque (plus the
//!   tyre's rolling resistance) that opposes the rotation and holds a stopped wheel.
//!
//! The two wheels of an axle are solved together (a 2×2 suspension block and, for slip-based
//! tyres, a 4×4 tyre block) so that neither side is favoured by the order of the solve: a
//! symmetric car on symmetric commands gets mirror-image forces, to the last bit. Webots'
//! rigid contact leaves the split of a lateral load between an axle's wheels undetermined;
//! its tyre rows are solved a wheel at a time, alternating which wheel goes first. The spin of each wheel is a coordinate relative to the
//! chassis: a torque between wheel and chassis (motor, brake, damping) acts on the spin alone,
//! and a tyre force acts on the chassis at the contact point and on the spin through the
//! radius. The inertial coupling between a wheel's spin and the chassis' rotation is left out
//! of the solve (a wheel's spin inertia is under 0.1 % of a car's pitch inertia); the caller
//! applies its effect, the reaction `−I·Δω` of each wheel's change of spin, afterwards. In
//! velocity control the spin is imposed (a Webots motor with a practically unlimited
//! `maxTorque`), so the tyre force acts on the chassis alone.

use rapier3d::prelude::{Mat3, Vector};
use vehicle_model::Linearised;
use vehicle_model::actuator::coulomb_torque;

/// Most block Gauss–Seidel sweeps per step. With warm starting, 8 sweeps leave residual slip
/// velocities under 1 mm/s on every shipped car with the rigid Webots contact (the chassis
/// couples the two axles; each sweep solves one axle exactly given the other).
pub(crate) const SWEEPS: usize = 8;

/// The sweeps stop early once the last one moved no impulse by more than this fraction of
/// the largest suspension impulse (a cruising car settles in two or three sweeps).
const SETTLED: f32 = 1e-5;

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
    /// The chassis at velocities `linvel` (m/s, of the centre of mass) and `angvel` (rad/s),
    /// with inverse mass `inv_mass` (1/kg) and the inverse inertia tensor `inv_inertia` of the
    /// body frame (1/(kg·m²)), turned into world axes by the body's rotation `rotation`.
    pub fn new(
        linvel: Vector,
        angvel: Vector,
        inv_mass: f32,
        inv_inertia: Mat3,
        rotation: rapier3d::prelude::Rotation,
    ) -> Body {
        let r = Mat3::from_quat(rotation);
        Body {
            linvel,
            angvel,
            inv_mass,
            inv_inertia: r * inv_inertia * r.transpose(),
        }
    }

    /// Velocity (m/s) of the chassis point at `arm` (m) from the centre of mass.
    pub fn velocity_at(&self, arm: Vector) -> Vector {
        self.linvel + self.angvel.cross(arm)
    }

    /// Applies `impulse` (N·s) at `arm` (m) from the centre of mass.
    fn apply(&mut self, arm: Vector, impulse: Vector) {
        self.linvel += impulse * self.inv_mass;
        self.angvel += self.inv_inertia * arm.cross(impulse);
    }

    /// `d1ᵀ·M⁻¹·d2` for a unit impulse along `d2` at `arm2` seen along `d1` at `arm1`: the
    /// inverse effective mass (1/kg) coupling two rows.
    fn coupling(&self, arm1: Vector, d1: Vector, arm2: Vector, d2: Vector) -> f32 {
        d1.dot(d2) * self.inv_mass + arm1.cross(d1).dot(self.inv_inertia * arm2.cross(d2))
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
        /// (Brake torque + rolling resistance) × dt (N·m·s, ≥ 0).
        brake_impulse: f32,
    },
}

impl Spin {
    fn inv_inertia(self) -> f32 {
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
    /// joint): the wheel row's normal impulse is given, and acts along `normal` (the ground's
    /// unit normal) at the contact point.
    Given {
        /// The ground's normal at the contact (unit, out of the ground).
        normal: Vector,
    },
}

/// A suspension spring-damper between the chassis and a wheel that is no body.
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
        let lateral = (axis - normal * normal.dot(axis)).normalize_or_zero();
        (lateral != Vector::ZERO).then(|| Contact {
            support,
            contact_arm: centre - normal * radius - com,
            forward: lateral.cross(normal),
            lateral,
            radius,
        })
    }

    /// The spring of a wheel with its own suspension row.
    fn spring(&self) -> Option<&Spring> {
        match &self.support {
            Support::Spring(s) => Some(s),
            Support::Given { .. } => None,
        }
    }

    /// Applies the normal impulse `p` (N·s) of this contact to `body`.
    fn apply_normal(&self, body: &mut Body, p: f32) {
        match self.support {
            Support::Spring(s) => body.apply(s.hardpoint_arm, s.up * p),
            Support::Given { normal } => body.apply(self.contact_arm, normal * p),
        }
    }
    /// The slip velocity `[forward, lateral]` (m/s) of the contact point over the ground for a
    /// wheel spinning at `omega` (rad/s).
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
    fn clamp(&self, x: f32, y: f32, normal: f32) -> [f32; 2] {
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
    fn row(&self, i: usize, normal: f32, current: f32) -> (f32, f32, f32) {
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
    /// Suspension impulse along the chassis up axis (N·s, ≥ 0): load × dt.
    pub normal: f32,
    /// Tyre impulse along the rolling direction (N·s).
    pub forward: f32,
    /// Tyre impulse along the wheel axis (N·s).
    pub lateral: f32,
    /// Brake impulse on the spin (N·m·s).
    pub brake: f32,
}

/// The per-step constants of one axle (wheels `2·a` and `2·a + 1`).
#[derive(Debug, Clone, Copy)]
struct Axle {
    /// Suspension rows' inverse effective masses (1/kg), 2×2.
    k_normal: [[f32; 2]; 2],
    /// `dt·k·x` (N·s) per wheel: the spring's impulse at the current compression.
    spring_impulse: [f32; 2],
    /// `dt·(k·dt + c)` (kg) per wheel: the implicit spring-damper's impulse per m/s of
    /// compression rate.
    softness: [f32; 2],
    /// Tyre rows' inverse effective masses (1/kg), 4×4 in the order forward 0, lateral 0,
    /// forward 1, lateral 1, with each free wheel's spin on its forward diagonal.
    k_tyre: [[f32; 4]; 4],
}

impl Axle {
    fn new(body: &Body, wheels: &[WheelRow], dt: f32) -> Axle {
        let contacts = [wheels[0].contact, wheels[1].contact];
        let mut axle = Axle {
            k_normal: [[0.0; 2]; 2],
            spring_impulse: [0.0; 2],
            softness: [0.0; 2],
            k_tyre: [[0.0; 4]; 4],
        };
        for (i, ci) in contacts.iter().enumerate() {
            let Some(ci) = ci else { continue };
            if let Some(si) = ci.spring() {
                axle.spring_impulse[i] = dt * si.stiffness * si.compression;
                axle.softness[i] = dt * (si.stiffness * dt + si.damping);
            }
            for (j, cj) in contacts.iter().enumerate() {
                let Some(cj) = cj else { continue };
                if let (Some(si), Some(sj)) = (ci.spring(), cj.spring()) {
                    axle.k_normal[i][j] =
                        body.coupling(si.hardpoint_arm, si.up, sj.hardpoint_arm, sj.up);
                }
                for (m, dm) in [ci.forward, ci.lateral].into_iter().enumerate() {
                    for (n, dn) in [cj.forward, cj.lateral].into_iter().enumerate() {
                        axle.k_tyre[2 * i + m][2 * j + n] =
                            body.coupling(ci.contact_arm, dm, cj.contact_arm, dn);
                    }
                }
            }
            axle.k_tyre[2 * i][2 * i] += ci.radius * ci.radius * wheels[i].spin.inv_inertia();
        }
        axle
    }
}

/// Solves one step of `dt` seconds: updates the chassis velocities, the wheel spins and the
/// accumulated impulses.
///
/// Every wheel's `impulses` must hold its warm start (the previous step's solution, or zeros);
/// they are clamped to this step's limits before use.
pub(crate) fn solve(body: &mut Body, wheels: &mut [WheelRow; 4], dt: f32) {
    warm_start(body, wheels);
    let axles = [
        Axle::new(body, &wheels[0..2], dt),
        Axle::new(body, &wheels[2..4], dt),
    ];
    for sweep in 0..SWEEPS {
        let before = wheels.map(|w| w.impulses);
        for (a, axle) in axles.iter().enumerate() {
            let pair = &mut wheels[2 * a..2 * a + 2];
            for w in pair.iter_mut() {
                brake_row(w);
            }
            suspension_block(body, pair, axle);
            tyre_block(body, pair, axle, sweep);
        }
        if settled(&before, wheels) {
            break;
        }
    }
}

/// True when no impulse moved by more than [`SETTLED`] of the largest suspension impulse
/// in the last sweep: a further sweep would change the forces by less than that.
fn settled(before: &[Impulses; 4], wheels: &[WheelRow; 4]) -> bool {
    let scale = wheels
        .iter()
        .map(|w| w.impulses.normal)
        .fold(0.0_f32, f32::max);
    let change = before
        .iter()
        .zip(wheels)
        .map(|(b, w)| {
            let a = w.impulses;
            (a.normal - b.normal)
                .abs()
                .max((a.forward - b.forward).abs())
                .max((a.lateral - b.lateral).abs())
        })
        .fold(0.0_f32, f32::max);
    scale > 0.0 && change <= SETTLED * scale
}

/// Applies the previous step's impulses, clamped to this step's limits.
fn warm_start(body: &mut Body, wheels: &mut [WheelRow; 4]) {
    for w in wheels.iter_mut() {
        let Some(c) = w.contact else {
            w.impulses = Impulses {
                brake: w.impulses.brake,
                ..Impulses::default()
            };
            continue;
        };
        let i = &mut w.impulses;
        i.normal = i.normal.max(0.0);
        [i.forward, i.lateral] = w.grip.clamp(i.forward, i.lateral, i.normal);
        c.apply_normal(body, i.normal);
        body.apply(c.contact_arm, c.forward * i.forward + c.lateral * i.lateral);
        w.omega -= c.radius * i.forward * w.spin.inv_inertia();
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
    // The Coulomb rule on impulses: the impulse that stops the wheel, within the capacity.
    let new = coulomb_torque(old - w.omega / inv_inertia, brake_impulse);
    w.impulses.brake = new;
    w.omega += (new - old) * inv_inertia;
}

/// The implicit spring-dampers of an axle: `P = dt·k·x + dt·(k·dt + c)·ẋ` for each wheel with
/// `ẋ` the compression rate after both impulses, `P ≥ 0`.
fn suspension_block(body: &mut Body, pair: &mut [WheelRow], axle: &Axle) {
    let springs = [0, 1].map(|i| pair[i].contact.and_then(|c| c.spring().copied()));
    let mut m = [[1.0, 0.0], [0.0, 1.0]];
    let mut rhs = [0.0; 2];
    for i in 0..2 {
        let Some(c) = springs[i] else { continue };
        let rate = -c.up.dot(body.velocity_at(c.hardpoint_arm));
        let s = axle.softness[i];
        for (j, (out, k)) in m[i].iter_mut().zip(axle.k_normal[i]).enumerate() {
            *out = f32::from(u8::from(i == j)) + s * k;
        }
        rhs[i] = axle.spring_impulse[i] + s * rate - pair[i].impulses.normal;
    }
    let Some(delta) = solve2(m, rhs) else { return };
    for (i, c) in springs.iter().enumerate() {
        let Some(c) = c else { continue };
        let old = pair[i].impulses.normal;
        let new = (old + delta[i]).max(0.0);
        pair[i].impulses.normal = new;
        body.apply(c.hardpoint_arm, c.up * (new - old));
    }
}

/// The tyres of an axle in sweep number `sweep`.
///
/// Slip-based tyres: each direction's force law at the end-of-step slip velocities of both
/// wheels, solved together, then each wheel's force kept within its friction ellipse. The
/// tyres' compliance determines how the two wheels share a lateral load; Webots' rigid contact
/// leaves that undetermined (two lateral rows on one line of a rigid chassis), so its wheels
/// are solved one at a time, as ODE's solver does, alternating which goes first.
fn tyre_block(body: &mut Body, pair: &mut [WheelRow], axle: &Axle, sweep: usize) {
    if pair.iter().any(|w| matches!(w.grip, Grip::Coulomb { .. })) {
        let order = if sweep.is_multiple_of(2) {
            [0, 1]
        } else {
            [1, 0]
        };
        for i in order {
            wheel_tyre(body, &mut pair[i], axle, i);
        }
        return;
    }
    let mut m = [[0.0_f32; 4]; 4];
    let mut rhs = [0.0_f32; 4];
    for (i, w) in pair.iter().enumerate() {
        let Some(rows) = tyre_rows(body, w) else {
            m[2 * i][2 * i] = 1.0;
            m[2 * i + 1][2 * i + 1] = 1.0;
            continue;
        };
        for (d, (alpha, beta, b)) in rows.into_iter().enumerate() {
            let r = 2 * i + d;
            for (col, k) in axle.k_tyre[r].iter().enumerate() {
                m[r][col] = beta * k;
            }
            m[r][r] += alpha;
            rhs[r] = b;
        }
    }
    let Some(delta) = solve_mirrored(&m, &rhs) else {
        return;
    };
    for (i, w) in pair.iter_mut().enumerate() {
        apply_tyre(body, w, [delta[2 * i], delta[2 * i + 1]]);
    }
}

/// Wheel `i` of an axle's tyre rows alone, the other wheel's impulses held.
fn wheel_tyre(body: &mut Body, w: &mut WheelRow, axle: &Axle, i: usize) {
    let Some(rows) = tyre_rows(body, w) else {
        return;
    };
    let mut m = [[0.0_f32; 2]; 2];
    let mut rhs = [0.0_f32; 2];
    for (d, (alpha, beta, b)) in rows.into_iter().enumerate() {
        for (e, out) in m[d].iter_mut().enumerate() {
            *out = beta * axle.k_tyre[2 * i + d][2 * i + e];
        }
        m[d][d] += alpha;
        rhs[d] = b;
    }
    if let Some(delta) = solve2(m, rhs) {
        apply_tyre(body, w, delta);
    }
}

/// The forward and lateral tyre rows of a wheel on the ground, `α·ΔP + β·(K·ΔP) = b` as
/// `(α, β, b)` with the current slip velocities; `None` in the air.
fn tyre_rows(body: &Body, w: &WheelRow) -> Option<[(f32, f32, f32); 2]> {
    let c = w.contact?;
    let v = c.slip_velocity(body, w.omega);
    let current = [w.impulses.forward, w.impulses.lateral];
    Some([0, 1].map(|d| {
        let (alpha, beta, c0) = w.grip.row(d, w.impulses.normal, current[d]);
        (alpha, beta, c0 - beta * v[d])
    }))
}

/// Adds `delta` (N·s, forward and lateral) to the wheel's tyre impulses within its friction
/// limits, and applies what was added to the chassis and the spin.
fn apply_tyre(body: &mut Body, w: &mut WheelRow, delta: [f32; 2]) {
    let Some(c) = w.contact else { return };
    let (f0, l0) = (w.impulses.forward, w.impulses.lateral);
    let [f, l] = w
        .grip
        .clamp(f0 + delta[0], l0 + delta[1], w.impulses.normal);
    w.impulses.forward = f;
    w.impulses.lateral = l;
    body.apply(c.contact_arm, c.forward * (f - f0) + c.lateral * (l - l0));
    w.omega -= c.radius * (f - f0) * w.spin.inv_inertia();
}

/// Solves an axle's tyre block `m·x = rhs` (unknowns: forward and lateral of one wheel, then
/// of its mirror image) in the wheels' mirror-symmetric and antisymmetric parts: for an axle in
/// a mirror-symmetric state the two parts decouple exactly, so the solution is the mirror image
/// of itself to the last bit and round-off cannot start a turn that the car would amplify (a
/// car whose driven wheels slide is yaw-unstable). Any other state is solved all the same:
/// the change of variables is exact and invertible.
fn solve_mirrored(m: &[[f32; 4]; 4], rhs: &[f32; 4]) -> Option<[f32; 4]> {
    // Symmetric forward, symmetric lateral, antisymmetric forward, antisymmetric lateral parts
    // of a row (or a column) ordered forward 0, lateral 0, forward 1, lateral 1; the mirror
    // image of a lateral force is its negative. Each part adds two terms, so a value plus its
    // exact mirror image gives exactly 0.
    let parts = |v: [f32; 4]| [v[0] + v[2], v[1] - v[3], v[0] - v[2], v[1] + v[3]];
    // m·T, where x = T·y maps the parts y back to the forces x.
    let mt = m.map(parts);
    let mut reduced = [[0.0_f32; 4]; 4];
    for c in 0..4 {
        let column = parts([mt[0][c], mt[1][c], mt[2][c], mt[3][c]]);
        for (row, value) in reduced.iter_mut().zip(column) {
            row[c] = value;
        }
    }
    let [sf, sl, af, al] = solve4(reduced, parts(*rhs))?;
    Some([sf + af, sl + al, sf - af, al - sl])
}

/// Solves the 2×2 system `m·x = rhs`; `None` if singular.
fn solve2(m: [[f32; 2]; 2], rhs: [f32; 2]) -> Option<[f32; 2]> {
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    if !(det.is_finite() && det.abs() > f32::MIN_POSITIVE) {
        return None;
    }
    let x = [
        (rhs[0] * m[1][1] - m[0][1] * rhs[1]) / det,
        (m[0][0] * rhs[1] - m[1][0] * rhs[0]) / det,
    ];
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Solves the 4×4 system `m·x = rhs` by Gaussian elimination with partial pivoting; `None` if
/// singular.
fn solve4(mut m: [[f32; 4]; 4], mut rhs: [f32; 4]) -> Option<[f32; 4]> {
    for col in 0..4 {
        let pivot = (col..4).max_by(|&a, &b| m[a][col].abs().total_cmp(&m[b][col].abs()))?;
        if m[pivot][col].abs() <= f32::MIN_POSITIVE || m[pivot][col].is_nan() {
            return None;
        }
        m.swap(col, pivot);
        rhs.swap(col, pivot);
        let pivot_row = m[col];
        for row in col + 1..4 {
            let factor = m[row][col] / pivot_row[col];
            for (value, p) in m[row].iter_mut().zip(pivot_row).skip(col) {
                *value -= factor * p;
            }
            rhs[row] -= factor * rhs[col];
        }
    }
    let mut x = [0.0_f32; 4];
    for row in (0..4).rev() {
        let tail: f32 = (row + 1..4).map(|k| m[row][k] * x[k]).sum();
        x[row] = (rhs[row] - tail) / m[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

#[cfg(test)]
mod tests;
