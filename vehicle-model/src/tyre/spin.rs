//! The slip-based tyre over one step on a wheel that spins freely: the wheel's spin and the
//! tyre's transient slip ratio advanced together in sub-steps.
//!
//! [`MagicFormula::linearise`] takes the force of the transient slip at the end of the step
//! over the whole step. When a brake or a drive torque changes the spin faster than the tyre
//! relaxes, that over-states the step's impulse: under a sudden full brake the tyre's force
//! builds up within the first step, and the end-of-step force spins the wheel back up (a
//! BmwX5 at 60 km/h, 10 ms step: about 40 N·s where the build-up gives 25), so the wheel's
//! slip excursion shrank with the step (first order in the step).
//!
//! Here the spin and the slip ratio are advanced in sub-steps of at most [`MAX_SUBSTEP`] (the
//! load and the lateral slip velocity stay those given for the step, the chassis' change of
//! speed is ramped in, below), each the step's own scheme in miniature (the chord law in the sub-step's end slip
//! velocity, the brake as Coulomb friction on the spin), so each is stable however stiff the
//! tyre. The solver gets the mean force over the sub-steps at the
//! slip velocity they end with, with the chord's slope over the whole step: the chassis and
//! the spin still meet the tyre's force at the end of the step, which keeps the step stable.
//! The slip angle is as in [`MagicFormula::linearise`] (its slip velocity is the chassis').
//!
//! The chassis' own change of speed at the wheel over the step ([`FreeSpin::chassis`]) is ramped
//! in over the sub-steps, and the load is the caller's: over a long step, holding both at the
//! step's start misses the load that braking moves to the front and the chassis' slowing, and
//! a wheel dives toward lock early (a BmwX5's fronts at 0.26 s at 32 ms against 0.43 s at
//! 1 ms). The `sim` crate and the firmware example's plant solve a braking step once with them
//! held, then begin the steps again ([`MagicFormula::respin`]) with the chassis' change and the
//! mean load that solve found, and solve again.
//!
//! Both sub-step braked wheels only, the case this is for: the Webots driver library's
//! wheel-acceleration limiter switches the torque of a driven wheel spinning past its grip on
//! and off every step, and a sub-stepped wheel rings under that switching. The two wheels of an
//! axle are divided alike ([`SpinStep::to_divide`]); only a wheel its brake holds still is
//! taken whole ([`SpinStep::is_steady`]). `tests/free_spin.rs` checks one braked wheel against
//! a fine solution.

use ackermann::{PerWheel, Real, Wheel};

use super::{AtLoad, ContactVelocity, LOW_SPEED, Linearised, MagicFormula, TransientSlip};

/// Longest sub-step (s): the wheel's slip transient under a full brake lasts about 30 ms on a
/// passenger car (measured on a BmwX5); a 1 ms step resolves its peak to within 0.05 of slip.
const MAX_SUBSTEP: f64 = 1e-3;

/// Most sub-steps in one step: bounds the cost of long steps (beyond 32 ms the sub-steps
/// grow past [`MAX_SUBSTEP`]).
const MAX_SUBSTEPS: i32 = 32;

/// A free wheel's spin over one step, without its tyre: what [`MagicFormula::linearise_spun`]
/// needs to advance it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FreeSpin<T> {
    /// Spin inertia about the axle (kg·m², > 0).
    pub inertia: T,
    /// Rolling radius (m, > 0): the slip velocity falls by `radius` m/s per rad/s of spin.
    pub radius: T,
    /// Spin at the start of the step (rad/s, positive rolling forward), the one the contact
    /// velocities were taken with.
    pub spin: T,
    /// Change of spin over the step from the drive torque and the joint's damping (rad/s).
    pub drive: T,
    /// Most the brake can deliver over the step, brake and rolling-resistance torque × dt
    /// (N·m·s, ≥ 0): it turns against the spin and cannot reverse it.
    pub brake: T,
    /// Change of the wheel centre's forward speed over the step (m/s): the chassis' own
    /// motion, which the sub-steps ramp in.
    pub chassis: T,
}

/// What [`MagicFormula::linearise_spun`] predicted for the end of the step, for
/// [`MagicFormula::relax_spinning`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SpinPrediction<T> {
    /// The transient slip ratio at the end of the sub-steps (dimensionless).
    ratio: T,
    /// The longitudinal slip velocity the sub-steps ended with (m/s).
    slip_velocity: T,
    /// Change of transient slip ratio per m/s less of end-of-step slip velocity (s/m).
    rate: T,
}

/// The change of the longitudinal force per unit load over one step below which the step of a
/// wheel its brake holds still is not divided: the mean force then lies within this of the
/// end-of-step force.
const STEADY: f64 = 0.01;

/// A free wheel's step begun by [`MagicFormula::begin_spinning`], for
/// [`MagicFormula::linearise_spun`].
#[derive(Debug, Clone, Copy)]
pub struct SpinStep<T> {
    run: Run<T>,
    /// The transient slip at the start of the step.
    slip: TransientSlip<T>,
    /// The contact velocities at the start of the step (m/s).
    v: ContactVelocity<T>,
    /// The road's friction (dimensionless).
    road: T,
    /// The step advanced in one sub-step.
    one: Pass<T>,
    /// The brake held the wheel still over `one`, and its longitudinal force per unit load
    /// changed by at most [`STEADY`] ([`SpinStep::is_steady`]).
    steady: bool,
}

impl<T: Copy> SpinStep<T> {
    /// The load the step was begun with (N).
    pub fn load(&self) -> T {
        self.run.load
    }
}

impl<T> SpinStep<T> {
    /// True if the wheel's brake holds it still over the step taken whole and its
    /// longitudinal force per unit load changes by at most 0.01: dividing it would not change
    /// the mean force (it lies between the two ends). A rolling wheel is never steady: near the
    /// curve's peak its force can stay flat while its slip runs through the peak. The two
    /// wheels of an axle should be divided alike, so that a mirror-image pair gets mirror-image
    /// forces.
    pub fn is_steady(&self) -> bool {
        self.steady
    }

    /// Which of the four wheels' steps to divide into sub-steps
    /// ([`MagicFormula::linearise_spun`] with `divide`): each begun step whose axle holds one
    /// that is not steady ([`SpinStep::is_steady`]). Both wheels of an axle take the same
    /// path, so that a mirror-image pair gets mirror-image forces.
    pub fn to_divide(steps: &PerWheel<Option<Self>>) -> PerWheel<bool> {
        let steady = |w: Wheel| steps[w].as_ref().is_none_or(SpinStep::is_steady);
        PerWheel::from_fn(|w| steps[w].is_some() && !(steady(w) && steady(w.mirror())))
    }
}

/// The fixed inputs of the sub-steps of one step.
#[derive(Debug, Clone, Copy)]
struct Run<T> {
    c: AtLoad<T>,
    /// Wheel centre's speed along the heading (m/s, ≥ 0).
    speed: T,
    /// Peak slip ratio.
    peak: T,
    /// Carcass damping per unit secant stiffness `[x, y]` (s/m).
    carcass: [T; 2],
    /// The slip angle's tangent over the step.
    angle: T,
    /// The lateral slip velocity (m/s).
    lateral_slip: T,
    wheel: FreeSpin<T>,
    /// Load (N).
    load: T,
    /// Step (s, > 0).
    dt: T,
}

/// Where the sub-steps of a step ended.
#[derive(Debug, Clone, Copy)]
struct Pass<T> {
    /// Longitudinal slip velocity (m/s).
    v_slip: T,
    /// Transient slip ratio.
    ratio: T,
    /// Sum of the sub-steps' forces per unit load `[x, y]`.
    sum: [T; 2],
    /// Number of sub-steps.
    count: T,
}

/// The number of sub-steps of a step of `dt` (s, ≥ 0): at least one, each at most
/// [`MAX_SUBSTEP`], at most [`MAX_SUBSTEPS`].
fn substeps<T: Real>(dt: T) -> i32 {
    let mut n = 1;
    while n < MAX_SUBSTEPS && dt > T::from_f64(MAX_SUBSTEP) * T::from_i32(n) {
        n += 1;
    }
    n
}

impl<T: Real> MagicFormula<T> {
    /// Begins a step of [`linearise_spun`](Self::linearise_spun) for a tyre on the free wheel
    /// `wheel`: the step's fixed inputs, with the spin and the transient slip ratio advanced
    /// over it in one sub-step (see the module docs), and whether it is steady
    /// ([`SpinStep::is_steady`]). `None` for a wheel without a positive finite inertia and
    /// radius, finite spin, drive, brake and chassis change, or a step that is not positive: such a tyre takes
    /// [`linearise`](Self::linearise).
    pub fn begin_spinning(
        &self,
        slip: &TransientSlip<T>,
        v: &ContactVelocity<T>,
        wheel: &FreeSpin<T>,
        load: T,
        road: T,
        dt: T,
    ) -> Option<SpinStep<T>> {
        let FreeSpin {
            inertia,
            radius,
            spin,
            drive,
            brake,
            chassis,
        } = *wheel;
        let valid = inertia > T::ZERO
            && radius > T::ZERO
            && inertia.is_finite()
            && radius.is_finite()
            && spin.is_finite()
            && drive.is_finite()
            && brake.is_finite()
            && chassis.is_finite()
            && dt > T::ZERO
            && dt.is_finite()
            && load.is_finite()
            && v.forward.is_finite()
            && v.slip[0].is_finite()
            && v.slip[1].is_finite();
        if !valid {
            return None;
        }
        let c = self.at_load(load, road);
        let speed = v.forward.abs();
        let curves = self.curves();
        // The carcass damper per unit secant stiffness, as in `linearise`.
        let fade = (T::ONE - speed / T::from_f64(LOW_SPEED)).max(T::ZERO);
        let carcass =
            [0, 1].map(|i| self.params.low_speed_damping / curves[i].relaxation_length * fade);
        let (whole, _) = self.advance(slip.get(), v, &c, dt);
        let run = Run {
            c,
            speed,
            peak: self.peaks(&c)[0],
            carcass,
            angle: whole[1],
            lateral_slip: v.slip[1],
            wheel: *wheel,
            load,
            dt,
        };
        // One sub-step first: for a wheel its brake holds still whose force changes little
        // over it, more would not change the mean (it lies between the two ends).
        let one = self.spin_pass(&run, (slip.ratio, v.slip[0]), 1);
        let (first, _) = self.force_and_secant([slip.ratio, run.angle], &c);
        let (last, _) = self.force_and_secant([one.ratio, run.angle], &c);
        Some(SpinStep {
            run,
            slip: *slip,
            v: *v,
            road,
            one,
            // Only a wheel its brake holds still is left whole: a rolling one can have a flat
            // force near the curve's peak while its slip runs through it.
            steady: spin == T::ZERO
                && one.v_slip == v.slip[0] + chassis
                && (last[0] - first[0]).abs() <= T::from_f64(STEADY),
        })
    }

    /// As [`linearise`](Self::linearise), for the step `step` begun by
    /// [`begin_spinning`](Self::begin_spinning): the line is the mean force over the step at
    /// the slip velocity the sub-steps end with (`slip_velocity`), with the chord's slope; the
    /// step is divided into sub-steps of at most 1 ms (at most 32 of them) if `divide`, else
    /// taken as the one sub-step already advanced. Also returns what
    /// [`relax_spinning`](Self::relax_spinning) needs after the solve (`None`, with the line of
    /// [`linearise`](Self::linearise), if the sub-steps did not stay finite).
    pub fn linearise_spun(
        &self,
        step: &SpinStep<T>,
        divide: bool,
    ) -> (Linearised<T>, Option<SpinPrediction<T>>) {
        let SpinStep {
            run,
            slip,
            v,
            road,
            one,
            ..
        } = step;
        let (c, dt) = (&run.c, run.dt);
        let pass = if divide {
            self.spin_pass(run, (slip.ratio, v.slip[0]), substeps(dt))
        } else {
            *one
        };
        let (v_slip, ratio, sum, count) = (pass.v_slip, pass.ratio, pass.sum, pass.count);
        if !(ratio.is_finite() && v_slip.is_finite()) {
            return (self.linearise(slip, v, run.load, *road, dt), None);
        }
        let (_, secant) = self.force_and_secant([ratio, run.angle], c);
        let end = ContactVelocity {
            forward: v.forward,
            slip: [v_slip, v.slip[1]],
        };
        let (_, rate) = self.advance(slip.get(), &end, c, dt);
        let mut out = Linearised {
            friction: c.mu,
            slip_velocity: end.slip,
            ..Linearised::default()
        };
        for i in 0..2 {
            out.force[i] = (sum[i] / count).finite_or(T::ZERO);
            out.damping[i] = (secant[i] * (rate[i] + run.carcass[i])).finite_or(T::ZERO);
        }
        let prediction = SpinPrediction {
            ratio,
            slip_velocity: v_slip,
            rate: rate[0],
        };
        (out, Some(prediction))
    }

    /// `step` begun again ([`begin_spinning`](Self::begin_spinning)) with the chassis' change
    /// of forward speed at the wheel over the step `chassis` (m/s) and the load `load` (N),
    /// e.g. what a first solve of the step found.
    pub fn respin(&self, step: &SpinStep<T>, chassis: T, load: T) -> Option<SpinStep<T>> {
        let wheel = FreeSpin {
            chassis,
            ..step.run.wheel
        };
        self.begin_spinning(&step.slip, &step.v, &wheel, load, step.road, step.run.dt)
    }

    /// The spin and slip ratio of `run` advanced from `(ratio, slip velocity)` over its step
    /// in `n` sub-steps.
    fn spin_pass(&self, run: &Run<T>, (ratio, v_slip): (T, T), n: i32) -> Pass<T> {
        let FreeSpin {
            inertia,
            radius,
            spin,
            drive,
            brake,
            ..
        } = run.wheel;
        let (c, speed, peak, carcass, angle) =
            (&run.c, run.speed, run.peak, run.carcass, run.angle);
        let count = T::from_i32(n);
        let h = run.dt / count;
        let (drive, brake) = (drive / count, brake.max(T::ZERO) / count);
        // Spin change (rad/s) per unit of force per unit load over a sub-step.
        let gain = radius * run.load.max(T::ZERO) * h / inertia;
        let [mu_x, mu_y] = c.mu;
        let (mut omega, mut v_slip, mut ratio) = (spin, v_slip, ratio);
        let mut sum = [T::ZERO; 2];
        for _ in 0..n {
            let (start, rate) = self.advance_axis(0, ratio, speed, v_slip, peak, h);
            let (force, secant) = self.force_and_secant([start, angle], c);
            // The sub-step's law per unit load in its end slip velocity u = v_slip − r·Δω:
            // f = fx + k·(v_slip − u) = fx + k·r·Δω, within the friction ellipse.
            let fx = force[0] - carcass[0] * secant[0] * v_slip;
            let fy = force[1] - carcass[1] * secant[1] * run.lateral_slip;
            let k = secant[0] * (rate + carcass[0]);
            let limit = if mu_y > T::ZERO {
                let share = fy / mu_y;
                mu_x * (T::ONE - share * share).max(T::ZERO).sqrt()
            } else {
                T::ZERO
            };
            // I·Δω = I·drive − r·F_z·h·f + b, the brake's impulse b within ±brake against the
            // spin: first with the tyre's law, then, if that leaves the ellipse, its edge.
            let stiff = T::ONE + gain * k * radius;
            let free = omega + (drive - gain * fx) / stiff;
            let mut next = free + stop(free, inertia * stiff, brake);
            let mut f = fx + k * radius * (next - omega);
            if f.abs() > limit {
                f = limit * f.sign();
                let free = omega + drive - gain * f;
                next = free + stop(free, inertia, brake);
            }
            let v_next = v_slip - radius * (next - omega) + run.wheel.chassis / count;
            ratio = self.advance_axis(0, ratio, speed, v_next, peak, h).0;
            sum[0] += f;
            sum[1] += fy;
            (omega, v_slip) = (next, v_next);
        }
        Pass {
            v_slip,
            ratio,
            sum,
            count,
        }
    }

    /// As [`relax`](Self::relax), after a step linearised by
    /// [`linearise_spun`](Self::linearise_spun) that made `prediction`: the slip ratio
    /// is the predicted one moved along the chord's rate by how far the step's end slip
    /// velocity missed the predicted one, within the same limits as in `relax`.
    pub fn relax_spinning(
        &self,
        slip: &mut TransientSlip<T>,
        prediction: &SpinPrediction<T>,
        v: &ContactVelocity<T>,
        load: T,
        road: T,
        dt: T,
    ) {
        let c = self.at_load(load, road);
        let ([_, angle_tan], _) = self.advance(slip.get(), v, &c, dt);
        let kinematic = v.slip[0].abs() / v.forward.abs().max(T::from_f64(LOW_SPEED));
        let cap = kinematic.max(self.peaks(&c)[0]);
        let ratio = prediction.ratio + prediction.rate * (prediction.slip_velocity - v.slip[0]);
        let ratio = ratio.max(-cap).min(cap).finite_or(T::ZERO);
        *slip = TransientSlip { ratio, angle_tan };
    }
}

/// The change of spin (rad/s) a brake delivering at most `brake` (N·m·s, ≥ 0) gives a wheel
/// that would otherwise spin at `free` (rad/s), with effective inertia `inertia` (kg·m²): what
/// stops it, within the brake's reach.
fn stop<T: Real>(free: T, inertia: T, brake: T) -> T {
    (-free * inertia).clamp(-brake, brake) / inertia
}
