//! The implicit solve of one step: the four tyres' force laws at the end-of-step slip
//! velocities, the free wheels' spins and brakes, and the planar body they push.

use ackermann::PerWheel;
use vehicle_model::actuator::coulomb_torque;

use super::SWEEPS;
use vehicle_model::{Linearised, SpinPrediction};

/// How a wheel's spin takes part in the solve.
#[derive(Debug, Clone, Copy)]
pub(super) enum Spin {
    /// Imposed by a velocity motor of unlimited torque: the tyre cannot change it.
    Imposed,
    /// Turned by the tyre and the brake.
    Free {
        /// Spin inertia (kg·m², > 0).
        inertia: f32,
        /// The most the brake and the rolling resistance can deliver this step (N·m·s).
        capacity: f32,
    },
}

/// The body in the solve: the centre of mass's velocity and the yaw rate, in the axes the body
/// has at the end of the step, and how impulses change them.
#[derive(Debug, Clone, Copy)]
pub(super) struct Body {
    /// Forward and leftward velocity (m/s), yaw rate (rad/s).
    pub(super) velocity: [f32; 3],
    /// Velocity change per unit impulse: forward (1/kg, drag included), leftward (1/kg), and
    /// yaw rate change per unit angular impulse (1/(kg·m²)).
    pub(super) inverse: [f32; 3],
}

impl Body {
    /// Applies `impulse` (N·s, body axes) at `arm` (m from the centre of mass).
    pub(super) fn push(&mut self, arm: [f32; 2], [px, py]: [f32; 2]) {
        let [u, v, r] = &mut self.velocity;
        let [mu, mv, mr] = self.inverse;
        *u += px * mu;
        *v += py * mv;
        *r += (arm[0] * py - arm[1] * px) * mr;
    }

    /// The velocity change (m/s) along a wheel's `heading` and along its axis (to the left of
    /// the heading) at `arm`, per unit impulse along each: the inverse effective mass (1/kg),
    /// a symmetric 2×2 matrix `[k_hh, k_ha, k_aa]`.
    pub(super) fn coupling(&self, [hx, hy]: [f32; 2], [x, y]: [f32; 2]) -> [f32; 3] {
        let [mu, mv, mr] = self.inverse;
        // Moment arms (m) of a unit impulse along the heading and along the axis.
        let (lever_h, lever_a) = (x * hy - y * hx, x * hx + y * hy);
        [
            hx * hx * mu + hy * hy * mv + lever_h * lever_h * mr,
            hx * hy * (mv - mu) + lever_h * lever_a * mr,
            hy * hy * mu + hx * hx * mv + lever_a * lever_a * mr,
        ]
    }
}

/// One wheel in the solve of a step.
#[derive(Debug, Clone, Copy)]
pub(super) struct Row {
    /// Rolling direction in body axes (unit): `[cos θ, sin θ]`, θ counter-clockwise.
    pub(super) heading: [f32; 2],
    /// Contact point − centre of mass, body axes (m).
    pub(super) arm: [f32; 2],
    /// Tyre radius (m).
    pub(super) radius: f32,
    pub(super) spin: Spin,
    /// Spin rate (rad/s, positive = rolling forward) with the impulses so far.
    pub(super) omega: f32,
    /// Brake impulse on a free wheel's spin (N·m·s, positive = forward).
    pub(super) brake: f32,
    /// Load on the tyre (N).
    pub(super) load: f32,
    /// Load × dt (N·s): the normal impulse that the tyre's force per unit load multiplies.
    pub(super) normal: f32,
    /// The tyre's force law per unit load over the step.
    pub(super) law: Linearised<f32>,
    /// What the sub-stepped tyre predicted for the end of the step, for its relaxation.
    pub(super) prediction: Option<SpinPrediction<f32>>,
    /// Tyre impulse along the heading and the axis (N·s).
    pub(super) impulse: [f32; 2],
}

impl Row {
    /// Velocity of the contact point (m/s) along the heading and the axis.
    pub(super) fn contact(&self, body: &Body) -> [f32; 2] {
        to_wheel(self.heading, point_velocity(body.velocity, self.arm))
    }

    /// Applies the last step's tyre force, kept within this step's friction ellipse.
    pub(super) fn warm_start(&mut self, body: &mut Body) {
        let guess = self.law.clamp_to_ellipse(self.impulse, self.normal);
        self.impulse = [0.0; 2];
        self.apply(body, guess);
    }

    /// Solves this wheel's tyre impulse and brake given the body's velocity and the other
    /// wheels' impulses.
    pub(super) fn solve(&mut self, body: &mut Body) {
        let Spin::Free { inertia, capacity } = self.spin else {
            let impulse = self.tyre_impulse(body, self.omega, 0.0);
            self.apply(body, impulse);
            return;
        };
        // The spin the wheel would have without its brake.
        let unbraked = self.omega - self.brake / inertia;
        // First as a stopped wheel, held by the brake if the brake can.
        let held = self.tyre_impulse(body, 0.0, 0.0);
        let to_stop = self.radius * (held[0] - self.impulse[0]) - inertia * unbraked;
        self.brake = coulomb_torque(to_stop, capacity);
        if to_stop.abs() <= capacity {
            self.apply(body, held);
            self.omega = 0.0;
            return;
        }
        // Else the brake slips at its capacity, and the tyre turns the wheel too.
        self.omega = unbraked + self.brake / inertia;
        let impulse = self.tyre_impulse(body, self.omega, self.radius * self.radius / inertia);
        self.apply(body, impulse);
    }

    /// The tyre impulse (N·s) at which the force law holds at the end of the step, kept
    /// within the friction ellipse, for a wheel spinning at `omega` (rad/s) plus `compliance`
    /// (1/kg) times the change of its forward impulse (a free spin's inverse inertia seen at
    /// the contact; 0 for a spin that stays).
    pub(super) fn tyre_impulse(&self, body: &Body, omega: f32, compliance: f32) -> [f32; 2] {
        let [forward, lateral] = self.contact(body);
        let n = self.normal;
        let [fx, fy] = self.law.at([forward - omega * self.radius, lateral]);
        let [p0, p1] = self.impulse;
        let [r0, r1] = [n * fx - p0, n * fy - p1];
        // impulse + Δ = n·f(slip + K·Δ), f falling by D per m/s: (1 + n·D·K)·Δ = n·f − impulse.
        // K is positive semi-definite, so the determinant is at least 1.
        let [b0, b1] = self.law.damping.map(|d| n * d);
        let [k_hh, k_ha, k_aa] = body.coupling(self.heading, self.arm);
        let [a00, a01] = [1.0 + b0 * (k_hh + compliance), b0 * k_ha];
        let [a10, a11] = [b1 * k_ha, 1.0 + b1 * k_aa];
        let det = a00 * a11 - a01 * a10;
        let next = [
            p0 + (r0 * a11 - a01 * r1) / det,
            p1 + (a00 * r1 - a10 * r0) / det,
        ];
        if next.iter().all(|p| p.is_finite()) {
            self.law.clamp_to_ellipse(next, n)
        } else {
            self.impulse
        }
    }

    /// Sets the tyre impulse to `impulse` (N·s), moving the body and a free wheel's spin.
    pub(super) fn apply(&mut self, body: &mut Body, impulse: [f32; 2]) {
        let [d0, d1] = [impulse[0] - self.impulse[0], impulse[1] - self.impulse[1]];
        let [hx, hy] = self.heading;
        body.push(self.arm, [hx * d0 - hy * d1, hy * d0 + hx * d1]);
        if let Spin::Free { inertia, .. } = self.spin {
            self.omega -= self.radius * d0 / inertia;
        }
        self.impulse = impulse;
    }
}

/// Velocity (m/s, body axes) of the point at `arm` (m from the centre of mass) of a body
/// moving at `velocity` (centre of mass m/s, yaw rate rad/s).
pub(super) fn point_velocity([u, v, r]: [f32; 3], [x, y]: [f32; 2]) -> [f32; 2] {
    [u - r * y, v + r * x]
}

/// `velocity` (body axes) along a wheel's `heading` and its axis to the left.
pub(super) fn to_wheel([hx, hy]: [f32; 2], [x, y]: [f32; 2]) -> [f32; 2] {
    [hx * x + hy * y, hx * y - hy * x]
}

/// The implicit solve of a step: the last step's tyre forces as a warm start, then block
/// Gauss–Seidel sweeps over the wheels.
pub(super) fn solve_step(body: &mut Body, rows: &mut PerWheel<Row>) {
    for row in rows.iter_mut() {
        row.warm_start(body);
    }
    for _ in 0..SWEEPS {
        for row in rows.iter_mut() {
            row.solve(body);
        }
    }
}
