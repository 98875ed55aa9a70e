//! The tyre: the force between the road and a wheel, from how the wheel slips.
//!
//! Two models, chosen per car ([`TyreModel`]):
//!
//! * [`MagicFormula`] (the default): a slip-based tyre. The longitudinal force follows the
//!   slip ratio κ and the lateral force the slip angle α along Pacejka Magic Formula curves
//!   ([`SlipCurve`]) whose peak and stiffness depend on the load; the two combine through one
//!   curve variable (the force the slip stiffnesses alone would give, over the peak), so each
//!   axis keeps its stiffness below the limit, the force stays within a friction ellipse, and a
//!   locked or spinning wheel loses its side grip; past the peak the force falls toward a
//!   sliding value and turns against the sliding velocity. The slip is *transient*: it builds
//!   up over a relaxation length of rolling ([`TransientSlip`]),
//!   which gives the tyre's lag and, at walking pace and standstill, turns the tyre into a
//!   damped spring that holds the contact patch (no creep on a slope, no jitter);
//! * [`WebotsContact`]: what Webots' ODE contact does (`ContactProperties`): no slip up to
//!   `coulombFriction × load` along each tyre axis separately (a friction pyramid), plus ODE's
//!   `forceDependentSlip`, a slip velocity proportional to the force.
//!
//! # How a simulator uses the slip-based tyre
//!
//! Each step, for each wheel on the ground, with the contact's velocities at the start of the
//! step ([`ContactVelocity`]: the wheel centre's speed along its heading, and the slip velocity
//! of the contact point over the road along the heading and the axis):
//!
//! 1. [`MagicFormula::linearise`] gives the force per unit load as an affine function of the
//!    slip velocity at the *end* of the step ([`Linearised`]): `f(v) = force + damping·(v₀ − v)`.
//!    A solver that takes the force at the end of the step (implicit) stays stable at any step
//!    however stiff the tyre; multiplied by the load and clamped to the friction ellipse, it is
//!    the tyre's force;
//! 2. after the step, [`MagicFormula::relax`] advances the transient slip with the end-of-step
//!    velocities.
//!
//! Signs: x along the wheel's heading, y along its axis (to the left of an unsteered wheel).
//! The slip ratio is `κ = −v_sx/|v_x|` (> 0 driving, −1 locked) and `tan α = −v_sy/|v_x|`, with
//! `v_sx = v_x − ω·r` and `v_sy` the contact point's velocities over the road; forces are
//! positive along +x and +y.
//!
//! ```
//! use vehicle_model::{TyreClass, TransientSlip, ContactVelocity};
//! let tyre = TyreClass::PassengerCar.params(0.35_f64, 4000.0).validate().unwrap();
//! // Pure slip: the cornering stiffness at the nominal load is 18 F_z per rad.
//! let [_, fy] = tyre.force([0.0, 0.001], 4000.0, 1.0);
//! assert!((fy / 0.001 - 18.0 * 4000.0).abs() < 50.0);
//! // A locked wheel slides at 0.75 of the peak, its force straight against the sliding
//! // velocity (1, −tan α): only tan α = 0.1 of it sideways.
//! let [fx, fy] = tyre.force([-1.0, 0.1], 4000.0, 1.0);
//! assert!((fx / 4000.0 + 0.74).abs() < 0.02 && (fy / -fx - 0.1).abs() < 1e-12);
//! ```

mod curve;
mod params;
mod spin;
pub mod tir;

use ackermann::Real;

use curve::Shape;
pub use params::{Direction, SlipCurve, TyreClass, TyreError, TyreField, TyreParams};
pub use spin::{FreeSpin, SpinPrediction, SpinStep};
pub use tir::{TirError, TirErrorKind, TirFile};

/// Speed below which the tyre is at "walking pace" (m/s): its carcass damping
/// ([`TyreParams::low_speed_damping`]) fades in, and slip ratios are measured against this
/// speed rather than the vanishing rolling speed.
pub const LOW_SPEED: f64 = 1.0;

/// A car's tyre model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TyreModel<T> {
    /// The slip-based tyre (world files: `tyre = "magic-formula"`, the default).
    MagicFormula(MagicFormula<T>),
    /// Webots' ODE contact (world files: `tyre = "webots"`).
    Webots(WebotsContact<T>),
}

/// Webots' contact as ODE builds it from `ContactProperties`: Coulomb friction
/// (`coulombFriction`, the ground's friction here) limiting each tyre axis separately, and
/// `forceDependentSlip`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WebotsContact<T> {
    /// ODE's force-dependent slip `[fds1, fds2]` (m/s per N, ≥ 0) along the wheel's rolling
    /// direction and along its axis: the contact slides at `fds·F` under a friction force `F`.
    /// Webots: `ContactProperties.forceDependentSlip` (one value for both directions, or two).
    /// 0 (the default) is a rigid contact that does not slip below the friction limit.
    pub force_dependent_slip: [T; 2],
}

impl<T: Real> WebotsContact<T> {
    /// Checks that both slips are finite and in [0, 1] m/s per N.
    ///
    /// # Errors
    /// The offending value, for the field `forceDependentSlip`.
    pub fn validate(self) -> Result<Self, T> {
        for v in self.force_dependent_slip {
            if !(v.is_finite() && v >= T::ZERO && v <= T::ONE) {
                return Err(v);
            }
        }
        Ok(self)
    }
}

/// The velocities of a tyre's contact at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactVelocity<T> {
    /// Speed of the wheel centre along the wheel's heading in the road plane (m/s, signed).
    pub forward: T,
    /// Slip velocity of the contact point over the road `[v_sx, v_sy]` (m/s): along the
    /// heading, `v_x − ω·r`; along the axis, the contact point's lateral velocity.
    pub slip: [T; 2],
}

/// The tyre's transient slip: the slip its carcass deflection corresponds to, which lags the
/// wheel's kinematic slip by the relaxation length. Zero for a tyre at rest without load.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TransientSlip<T> {
    /// Transient slip ratio κ' (dimensionless).
    pub ratio: T,
    /// Tangent of the transient slip angle, tan α' (dimensionless).
    pub angle_tan: T,
}

impl<T: Real> TransientSlip<T> {
    fn get(&self) -> [T; 2] {
        [self.ratio, self.angle_tan]
    }
}

/// The tyre force per unit load over one step, as an affine function of the contact's slip
/// velocity at the end of the step: `f(v) = force + damping·(slip_velocity − v)` along each
/// tyre axis, then kept within the ellipse of semi-axes `friction`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Linearised<T> {
    /// Force per unit load at `slip_velocity` (dimensionless), `[x, y]`.
    pub force: [T; 2],
    /// Fall of the force per unit load per m/s of extra slip velocity (s/m, ≥ 0), `[x, y]`.
    pub damping: [T; 2],
    /// The slip velocity the linearisation was taken at (m/s), `[x, y]`.
    pub slip_velocity: [T; 2],
    /// Peak friction coefficients at this load and road (dimensionless, ≥ 0), `[x, y]`: the
    /// friction ellipse per unit load.
    pub friction: [T; 2],
}

impl<T: Real> Linearised<T> {
    /// The force per unit load at slip velocity `v` (m/s), before the friction ellipse.
    pub fn at(&self, v: [T; 2]) -> [T; 2] {
        [0, 1].map(|i| self.force[i] + self.damping[i] * (self.slip_velocity[i] - v[i]))
    }

    /// `f` (any unit) scaled down onto the friction ellipse of semi-axes `friction × load`
    /// when outside it.
    pub fn clamp_to_ellipse(&self, f: [T; 2], load: T) -> [T; 2] {
        let [ax, ay] = self.friction.map(|mu| mu * load.max(T::ZERO));
        if !(ax > T::ZERO && ay > T::ZERO) {
            return [T::ZERO; 2];
        }
        let (u, v) = (f[0] / ax, f[1] / ay);
        let r2 = u * u + v * v;
        if r2 > T::ONE && r2.is_finite() {
            let inv = T::ONE / r2.sqrt();
            f.map(|x| x * inv)
        } else if r2.is_finite() {
            f
        } else {
            [T::ZERO; 2]
        }
    }
}

/// The square of the curve variable below which `g(t) = t` to the last bit: `|g(t) − t| ≤ 3·t³`
/// for every accepted shape (`1 < C < 2`, `−10 ≤ E < 1`), under half an ulp of `t` for
/// `t² < ε/256`. (A square, so that the bound is a product of constants, folded at compile time.)
fn linear_limit_squared<T: Real>() -> T {
    T::EPSILON * T::from_f64(1.0 / 256.0)
}

/// The load-dependent coefficients of one evaluation.
#[derive(Debug, Clone, Copy)]
struct AtLoad<T> {
    /// Peak friction `[x, y]` (dimensionless).
    mu: [T; 2],
    /// `K/μ`, the curve variable `t` per unit slip, `[x, y]`: `gain/divisor`.
    scale: [T; 2],
    /// `scale` before the load law's division, `[x, y]`, without the lateral load law's factor
    /// `lateral` in `x` (the curve variable's `x` part is `(gain_x·κ)·lateral`).
    gain: [T; 2],
    /// The longitudinal gain's load factor (dimensionless, > 0).
    lateral: T,
    /// The load law's divisor (dimensionless, > 0), and its inverse.
    divisor: T,
    inv_divisor: T,
}

/// The slip-based tyre, validated ([`TyreParams::validate`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MagicFormula<T> {
    params: TyreParams<T>,
    shapes: [Shape<T>; 2],
    /// 1/F_z0 (1/N).
    inv_nominal: T,
    /// 1/(p₂·F_z0) (1/N).
    inv_saturation_load: T,
    /// `C·u_p` of each curve: where it peaks in its variable `t`.
    t_peak: [T; 2],
    /// The curve variable per unit slip at the nominal load on a road of friction 1, `K/μ`,
    /// the lateral one times `1 + z₀²` (z₀ = 1/p₂) for its load law.
    scale_gain: [T; 2],
}

impl<T: Real> MagicFormula<T> {
    pub(crate) fn new(params: TyreParams<T>) -> Option<Self> {
        let shapes = [
            Shape::new(params.longitudinal.shape, params.longitudinal.curvature)?,
            Shape::new(params.lateral.shape, params.lateral.curvature)?,
        ];
        let z0 = T::ONE / params.cornering_saturation;
        let curves = [&params.longitudinal, &params.lateral];
        let gain = [T::ONE, T::ONE + z0 * z0];
        Some(MagicFormula {
            params,
            shapes,
            inv_nominal: T::ONE / params.nominal_load,
            inv_saturation_load: T::ONE / (params.cornering_saturation * params.nominal_load),
            t_peak: shapes.map(|s| s.t_peak()),
            scale_gain: [0, 1].map(|i| curves[i].stiffness * gain[i] / curves[i].peak_friction),
        })
    }

    /// The coefficients.
    pub fn params(&self) -> &TyreParams<T> {
        &self.params
    }

    fn curves(&self) -> [&SlipCurve<T>; 2] {
        [&self.params.longitudinal, &self.params.lateral]
    }

    /// The coefficients at `load` (N) on a road of friction `road` (dimensionless); zero
    /// friction (no force) for a load or road that is not positive.
    #[inline(always)]
    fn at_load(&self, load: T, road: T) -> AtLoad<T> {
        let p = &self.params;
        if !(load > T::ZERO && road > T::ZERO && load.is_finite() && road.is_finite()) {
            return AtLoad {
                mu: [T::ZERO; 2],
                scale: [T::ONE; 2],
                gain: [T::ONE; 2],
                lateral: T::ONE,
                divisor: T::ONE,
                inv_divisor: T::ONE,
            };
        }
        let f = T::from_f64;
        let extra = load * self.inv_nominal - T::ONE;
        let factor = (T::ONE - p.load_sensitivity * extra).clamp(f(0.5), f(1.5));
        // The lateral stiffness per unit load falls as k·(1 + z₀²)/(1 + z²), z = F_z/(p₂·F_z0):
        // Pacejka's C_α ∝ sin(2·atan(z)) divided by the load (sin(2·atan z) = 2z/(1 + z²)).
        // The curve variable is t = K·x/μ (per unit load): one division for both axes.
        let z = load * self.inv_saturation_load;
        let lateral = T::ONE + z * z;
        // Grouped for latency: `factor` (through the clamp) is the last of the three ready.
        let divisor = (road * lateral) * factor;
        let inv_divisor = T::ONE / divisor;
        let mu = [p.longitudinal.peak_friction, p.lateral.peak_friction].map(|m| road * m * factor);
        AtLoad {
            mu,
            scale: [
                self.scale_gain[0] * (lateral * inv_divisor),
                self.scale_gain[1] * inv_divisor,
            ],
            gain: self.scale_gain,
            lateral,
            divisor,
            inv_divisor,
        }
    }

    /// The force per unit load at slips `[κ, tan α]` and each axis' secant stiffness
    /// `f_i/x_i` (per unit slip), which is the slip stiffness at zero slip and falls as the
    /// tyre saturates.
    ///
    /// Both axes share one curve variable `t = ‖(K_x·κ, K_y·tan α)/μ‖` (per unit load) and one
    /// shape, blended between the longitudinal and the lateral one by the direction; each curve
    /// has slope 1 at zero, so below the limit each axis keeps its own stiffness whatever the
    /// other's slip, and `(F_x/μ_x)² + (F_y/μ_y)² = g(t)² ≤ 1` at any slip. Below the peak the
    /// force points along `(K_x·κ, K_y·tan α)`; beyond it the patch slides and the force turns
    /// toward `(κ, tan α)`, against the sliding velocity, which it reaches at twice the peak.
    // Inlined into `force` and `linearise` (with `at_load`): as a call, its inputs and results
    // went through the stack, and the benches took 63 instead of 36 ns (`force`, f32) and 98
    // instead of 67 ns (`linearise`, f64). On bare metal (`target_os = "none"`, the firmware)
    // flash is the budget instead: one copy serves every caller, where each inlined one costs
    // about 1.4 KiB on a Cortex-M4.
    #[cfg_attr(not(target_os = "none"), inline(always))]
    #[cfg_attr(target_os = "none", inline(never))]
    fn force_and_secant(&self, slip: [T; 2], c: &AtLoad<T>) -> ([T; 2], [T; 2]) {
        // The evaluation is one chain of dependent operations (square root, arc tangent, arc
        // tangent, sine), so it is written for latency: t = (a, b)/divisor, and the square root
        // of a² + b², the load law's division and two more divisions all start at once; every
        // later quotient (the direction, the blend weight, u = t/C and 1/u) is a product.
        // The slip's product with its gain starts before the load law's `lateral` is known.
        let (a, b) = ((c.gain[0] * slip[0]) * c.lateral, c.gain[1] * slip[1]);
        let (a2, b2) = (a * a, b * b);
        let r2 = a2 + b2;
        let root = r2.sqrt();
        let norm = root * c.inv_divisor;
        // The tangent g(t) = t below the linear limit (and at zero slip, where each axis has its
        // own stiffness, μ·K/μ); r2 above ε⁴ keeps 1/r2 finite. No force for a non-finite norm.
        let eps2 = T::EPSILON * T::EPSILON;
        if !(norm * norm > linear_limit_squared() && r2 > eps2 * eps2 && norm.is_finite()) {
            let stiffness = [0, 1].map(|i| c.mu[i] * c.scale[i]);
            let force = if norm.is_finite() {
                [0, 1].map(|i| stiffness[i] * slip[i])
            } else {
                [T::ZERO; 2]
            };
            return (force, stiffness);
        }
        let inv_r2 = T::ONE / r2;
        // The shape's C blended by w = n_y² is q/r2 with q = C_x·a² + C_y·b².
        let q = self.shapes[0].c * a2 + self.shapes[1].c * b2;
        let inv_q = T::ONE / q;
        let w = b2 * inv_r2;
        let inv_root = root * inv_r2;
        let inv_norm = c.divisor * inv_root;
        let n = [a * inv_root, b * inv_root];
        let shape = self.shapes[0].blend(&self.shapes[1], w);
        // u = t/C = norm·r2/q and its inverse, and their squares from r2 and the quotients,
        // not from the square root: the first arc tangent's polynomial starts without it.
        // Grouped so that two products follow the last quotient: u² = (r2³/q)·(1/(q·divisor²))
        // and 1/u² = ((q·divisor)²/r2)·(1/r2²).
        let r2_q = r2 * inv_q;
        let r2_cubed = (r2 * r2) * r2;
        let u_sq = (r2_cubed * inv_q) * (inv_q * (c.inv_divisor * c.inv_divisor));
        let qd = q * c.divisor;
        let inv_u_sq = ((qd * qd) * inv_r2) * (inv_r2 * inv_r2);
        // r2/q is 1/C of the blended shape (C = q/r2) to a few ulp.
        let value = shape.at_u(norm * r2_q, shape.c * inv_norm, u_sq, inv_u_sq, r2_q);
        let secant = value * inv_norm;
        // μ·n before the curve's value is known: one product follows it.
        let adhesion = [0, 1].map(|i| (c.mu[i] * n[i]) * value);
        // Past the peak the patch slides: its force turns from the stiffness-weighted direction
        // toward the one opposing the sliding velocity, (κ, tan α), reached at twice the peak.
        let t_peak = self.t_peak[0] + (self.t_peak[1] - self.t_peak[0]) * w;
        let sliding = ((norm - t_peak) / t_peak).clamp(T::ZERO, T::ONE);
        if sliding <= T::ZERO || sliding.is_nan() {
            let stiffness = [0, 1].map(|i| c.mu[i] * c.scale[i] * secant);
            return (adhesion, stiffness);
        }
        let unit = |v: [T; 2]| {
            let l = (v[0] * v[0] + v[1] * v[1]).sqrt();
            v.map(|x| x / l)
        };
        let d_k = unit(adhesion);
        let d_s = unit(slip);
        let d = unit([0, 1].map(|i| d_k[i] + (d_s[i] - d_k[i]) * sliding));
        // The force's size along `d` on the friction ellipse scaled by the curve's value.
        let reach = value / ((d[0] / c.mu[0]).powi(2) + (d[1] / c.mu[1]).powi(2)).sqrt();
        let force = d.map(|x| x * reach);
        let stiffness = [0, 1].map(|i| {
            if slip[i].abs() > T::from_f64(1e-9) {
                force[i] / slip[i]
            } else {
                c.mu[i] * c.scale[i] * secant
            }
        });
        (force, stiffness)
    }

    /// The steady-state force (N) `[F_x, F_y]` at slip ratio κ and slip-angle tangent tan α
    /// (`slip = [κ, tan α]`), under `load` (N) on a road of friction `road`.
    ///
    /// In pure slip each component is its Magic Formula curve; combined, the two share one
    /// curve variable `t = ‖(K_x·κ, K_y·tan α)/μ‖` (per unit load), so each keeps its own
    /// stiffness below the limit and `(F_x/μ_x F_z)² + (F_y/μ_y F_z)² ≤ 1`. Non-finite input
    /// gives no force.
    pub fn force(&self, slip: [T; 2], load: T, road: T) -> [T; 2] {
        if !(slip[0].is_finite() && slip[1].is_finite() && load.is_finite()) {
            return [T::ZERO; 2];
        }
        // The friction per unit load times the load is the force per unit of the curve: the
        // evaluation then gives newtons, with no product after the curve's last one.
        let mut c = self.at_load(load, road);
        c.mu = c.mu.map(|m| m * load);
        let (f, _) = self.force_and_secant(slip, &c);
        f
    }

    /// The slips `[κ_p, tan α_p]` at which the pure-slip forces peak, at `load` (N) on a road
    /// of friction `road`.
    pub fn peak_slip(&self, load: T, road: T) -> [T; 2] {
        self.peaks(&self.at_load(load, road))
    }

    /// The slips `[κ_p, tan α_p]` at which the pure-slip forces of `c` peak.
    fn peaks(&self, c: &AtLoad<T>) -> [T; 2] {
        [0, 1].map(|i| self.t_peak[i] / c.scale[i])
    }

    /// The rolling-resistance torque (N·m, ≥ 0) of the tyre under `load` (N) with rolling
    /// `radius` (m): `c_rr·F_z·r`, a dry friction against the wheel's rotation.
    pub fn rolling_resistance_torque(&self, load: T, radius: T) -> T {
        (self.params.rolling_resistance * load * radius)
            .max(T::ZERO)
            .finite_or(T::ZERO)
    }

    /// The transient slip after a step of `dt` (s, a non-positive one counting as 0) from
    /// `slip` at the velocities `v` (m/s);
    /// each component is `(σ·x − dt·v_s)/(σ + dt·|v_x|)` (implicit Euler of
    /// `σ·dx/dt = −v_s − |v_x|·x`), then at most as large as the larger of the kinematic slip
    /// (measured against at least [`LOW_SPEED`]) and the peak slip: a sliding patch cannot
    /// deflect further, so a tyre that stops after sliding keeps no more than its peak force.
    ///
    /// Also returns, per axis, the new slip over the change of slip velocity that would bring
    /// it to zero (s/m): `dt/(σ + dt·|v_x|)` for the relaxing slip (less when held at the
    /// peak), `1/reference` for a sliding tyre, whose slip follows the slip velocity at once.
    fn advance(
        &self,
        slip: [T; 2],
        v: &ContactVelocity<T>,
        c: &AtLoad<T>,
        dt: T,
    ) -> ([T; 2], [T; 2]) {
        let dt = if dt > T::ZERO { dt } else { T::ZERO };
        let speed = v.forward.abs();
        let peaks = self.peaks(c);
        let mut next = [T::ZERO; 2];
        let mut rate = [T::ZERO; 2];
        for i in 0..2 {
            (next[i], rate[i]) = self.advance_axis(i, slip[i], speed, v.slip[i], peaks[i], dt);
        }
        (next, rate)
    }

    /// [`advance`](Self::advance) along axis `i` (0: x, 1: y) alone: the transient slip `x`
    /// after `dt` (s, ≥ 0) at wheel-centre speed `speed` (m/s, ≥ 0) and slip velocity `v_slip`
    /// (m/s), with `peak` the axis' peak slip; and the new slip per change of slip velocity
    /// (s/m).
    #[inline(always)]
    fn advance_axis(&self, i: usize, x: T, speed: T, v_slip: T, peak: T, dt: T) -> (T, T) {
        let reference = speed.max(T::from_f64(LOW_SPEED));
        let sigma = self.curves()[i].relaxation_length;
        let denominator = sigma + dt * speed;
        let free = (sigma * x - dt * v_slip) / denominator;
        let kinematic = v_slip.abs() / reference;
        let cap = kinematic.max(peak);
        let (next, rate) = if free.abs() <= cap {
            (free, dt / denominator)
        } else if kinematic > peak {
            // Sliding: the slip is the kinematic one, −v_s/reference, which vanishes
            // with the slip velocity.
            (cap * free.sign(), T::ONE / reference)
        } else {
            // Held at the peak slip: the deflection unwinds as in the free case.
            (cap * free.sign(), dt / denominator * cap / free.abs())
        };
        if next.is_finite() {
            (next, rate)
        } else {
            (T::ZERO, T::ZERO)
        }
    }

    /// The force per unit load over a step of `dt` (s) as an affine function of the slip
    /// velocity at the end of the step, from the transient `slip` and the velocities `v` (m/s)
    /// at its start, under `load` (N) on a road of friction `road`.
    ///
    /// The line goes through the force of the predicted transient slip and through zero force
    /// at the slip velocity that would leave no transient slip (a chord, not a tangent): its
    /// slope (`damping`) is the secant stiffness times the change of transient slip per m/s
    /// (`dt/(σ + dt·|v_x|)`), plus the carcass damper below [`LOW_SPEED`]. In the linear range
    /// the chord is the tangent; past the peak it keeps the force from overshooting through
    /// zero when a sliding wheel regains grip within a step (the chatter an explicit friction
    /// force would give).
    pub fn linearise(
        &self,
        slip: &TransientSlip<T>,
        v: &ContactVelocity<T>,
        load: T,
        road: T,
        dt: T,
    ) -> Linearised<T> {
        let c = self.at_load(load, road);
        let (predicted, rate) = self.advance(slip.get(), v, &c, dt);
        let (force, slope) = self.force_and_secant(predicted, &c);
        let fade = (T::ONE - v.forward.abs() / T::from_f64(LOW_SPEED)).max(T::ZERO);
        let curves = self.curves();
        let mut out = Linearised {
            friction: c.mu,
            slip_velocity: v.slip,
            ..Linearised::default()
        };
        for i in 0..2 {
            let carcass =
                self.params.low_speed_damping * slope[i] / curves[i].relaxation_length * fade;
            out.force[i] = (force[i] - carcass * v.slip[i]).finite_or(T::ZERO);
            out.damping[i] = (slope[i] * rate[i] + carcass).finite_or(T::ZERO);
        }
        out
    }

    /// Advances the transient `slip` over a step of `dt` (s) that ended with the velocities
    /// `v` (m/s), under `load` (N) on a road of friction `road`.
    pub fn relax(
        &self,
        slip: &mut TransientSlip<T>,
        v: &ContactVelocity<T>,
        load: T,
        road: T,
        dt: T,
    ) {
        let c = self.at_load(load, road);
        let ([ratio, angle_tan], _) = self.advance(slip.get(), v, &c, dt);
        *slip = TransientSlip { ratio, angle_tan };
    }
}

#[cfg(test)]
mod tests;
