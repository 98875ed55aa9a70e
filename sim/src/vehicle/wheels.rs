//! Each wheel's part in a step's contact solve: its row set up before the solve (the spin, the
//! warm start, its contact and the tyre's force law on its footing), the reaction of its change
//! of spin on the chassis, and its record after the solve (telemetry, transient slip).

use ackermann::Wheel;
use rapier3d::prelude::Vector;
use vehicle_model::tyre::LOW_SPEED;
use vehicle_model::{
    ContactVelocity, FreeSpin, Linearised, Real, SpinStep, TransientSlip, TyreModel,
};

use super::contact::{self, Body, Contact, Grip, Spin, Support, WheelRow};
use super::{TyreTelemetry, Vehicle};

impl Vehicle {
    /// Sets up wheel `w`'s row for the step (spin, warm start), in the air until a contact is
    /// found; returns the spin rate a velocity command imposes (rad/s).
    pub(super) fn start_row(&mut self, w: Wheel, row: &mut WheelRow, dt: f64) -> f64 {
        let (spin, omega) = self.spin(w, dt);
        row.spin = spin;
        row.omega = omega as f32;
        row.impulses = self.impulses[w];
        omega
    }

    /// Puts wheel `w` on the ground at `contact`, on `footing`, for the step: its tyre's law is
    /// the slip-based tyre linearised at the velocities before the solve, with its rolling
    /// resistance added to the wheel's brake, or Webots' contact.
    pub(super) fn set_up_contact(
        &mut self,
        w: Wheel,
        row: &mut WheelRow,
        contact: Contact,
        body: &Body,
        footing: Footing,
        dt: f64,
    ) {
        let Footing { road, load } = footing;
        self.predictions[w] = None;
        self.spin_steps[w] = None;
        row.grip = match *self.spec.tyres.of(w) {
            TyreModel::Webots(c) => {
                if let Spin::Free { brake_impulse, .. } = &mut row.spin {
                    *brake_impulse += (self.constant_wheel_drag() * dt) as f32;
                }
                Grip::Coulomb {
                    compliance: c.force_dependent_slip.map(|fds| (fds / dt) as f32),
                    friction: road as f32,
                }
            }
            TyreModel::MagicFormula(tyre) => {
                let lin = match &mut row.spin {
                    Spin::Imposed => {
                        let v = contact_velocity(&contact, body, row.omega);
                        tyre.linearise(&self.slips[w], &v, load, road, dt)
                    }
                    Spin::Free { brake_impulse, .. } => {
                        // Only a braked wheel is sub-stepped: its spin changes faster than its
                        // tyre relaxes, the case the sub-steps are for. A driven wheel takes
                        // the whole step: without its engine's inertia the driver library's
                        // wheel-acceleration limiter switched the torque of a wheel spinning
                        // past its grip on and off every step, and a sub-stepped wheel rang
                        // under that switching. With it, sub-stepping driven wheels too was
                        // measured (issue #35, ARCHITECTURE.md "Launch chatter"): it took out
                        // sub-rpm wiggles of the engine speed but added early slip flips.
                        let braked = *brake_impulse > 0.0;
                        // The rolling resistance and the road-load set's constant drag resist
                        // the spin as the brake does, after the choice above: they do not
                        // make a rolling wheel a braked one.
                        let rolling = tyre
                            .rolling_resistance_torque(load, f64::from(contact.radius))
                            + self.constant_wheel_drag();
                        *brake_impulse += (rolling * dt) as f32;
                        // The spin the wheel starts the step with; the drive torque's spin-up
                        // (already in `row.omega`) and the brake act within the sub-steps.
                        let spin = self.state.wheel_speeds[w];
                        let v = contact_velocity(&contact, body, spin as f32);
                        let wheel = FreeSpin {
                            inertia: self.spin_inertia(w),
                            radius: f64::from(contact.radius),
                            spin,
                            drive: f64::from(row.omega) - spin,
                            brake: f64::from(*brake_impulse),
                            chassis: 0.0,
                        };
                        let slip = &self.slips[w];
                        let step = braked
                            .then(|| tyre.begin_spinning(slip, &v, &wheel, load, road, dt))
                            .flatten();
                        match step {
                            // Taken whole for now: `divide_axles` divides it if its axle needs.
                            Some(step) => {
                                let (lin, prediction) = tyre.linearise_spun(&step, false);
                                self.spin_steps[w] = Some(step);
                                self.predictions[w] = prediction;
                                lin
                            }
                            None => tyre.linearise(slip, &v, load, road, dt),
                        }
                    }
                };
                Grip::Slip(f32_line(&lin))
            }
        };
        row.contact = Some(contact);
    }

    /// Divides the step of the sub-stepped tyres (set up by
    /// [`set_up_contact`](Self::set_up_contact)) of every axle on which one is not steady
    /// over the step taken whole: both wheels of an axle take the same path, so that a
    /// mirror-image pair gets mirror-image forces.
    pub(super) fn divide_axles(&mut self, rows: &mut [WheelRow; 4]) {
        self.set_spun_lines(rows, false);
    }

    /// Sets the line and the prediction of the sub-stepped tyres in `rows`, divided as
    /// [`SpinStep::to_divide`] says: of those it divides, or, with `every`, of all of them.
    fn set_spun_lines(&mut self, rows: &mut [WheelRow; 4], every: bool) {
        let divide = SpinStep::to_divide(&self.spin_steps);
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            let (Some(step), TyreModel::MagicFormula(tyre)) =
                (self.spin_steps[w], self.spec.tyres.of(w))
            else {
                continue;
            };
            if !(every || divide[w]) {
                continue;
            }
            let (lin, prediction) = tyre.linearise_spun(&step, divide[w]);
            self.predictions[w] = prediction;
            if let Grip::Slip(line) = &mut rows[i].grip {
                *line = f32_line(&lin);
            }
        }
    }

    /// Solves the step's contacts (`rows`, set up and divided, on `body`). A braking step is
    /// solved twice: its braked wheels' sub-stepped tyres held the chassis and the load at the
    /// step's start, so they are begun again with what the first solve found
    /// ([`respin_braked`](Self::respin_braked)) and the step is solved again from where it
    /// started. `carries_load`: the solve carries the wheels' loads (the cast car; on joints
    /// rapier does).
    pub(super) fn solve_contacts(
        &mut self,
        body: &mut Body,
        rows: &mut [WheelRow; 4],
        carries_load: bool,
        dt: f64,
    ) {
        // Wheels their brakes hold still (a parked car, a locked stop) are steady: nothing to
        // correct, and nothing to keep for a second solve.
        if !SpinStep::to_divide(&self.spin_steps).iter().any(|&d| d) {
            contact::solve(body, rows, dt as f32);
            return;
        }
        let (start_body, mut again) = (*body, *rows);
        contact::solve(body, rows, dt as f32);
        let loads = carries_load.then(|| rows.map(|r| r.impulses.normal));
        self.respin_braked(&mut again, &start_body, body, loads, dt);
        (*body, *rows) = (start_body, again);
        contact::solve(body, rows, dt as f32);
    }

    /// Begins the braked wheels' sub-stepped tyres again with what the first solve of the step
    /// found, and sets up their lines in `rows` (the rows as they were before that solve): the
    /// chassis' change of forward speed at each contact over the step (`start` before the
    /// solve, `end` after it), and, where the solve carries the load (`end_loads`, its normal
    /// impulses, N·s; `None` on joints, where rapier carries it), the mean of the step's start
    /// and end loads. The sub-steps held both at the step's start; under a sudden brake the
    /// load moving to the front within a 32 ms step is a tenth of the wheel's. Called only when
    /// a braked wheel is not steady ([`SpinStep::is_steady`]).
    fn respin_braked(
        &mut self,
        rows: &mut [WheelRow; 4],
        start: &Body,
        end: &Body,
        end_loads: Option<[f32; 4]>,
        dt: f64,
    ) {
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            let (Some(step), TyreModel::MagicFormula(tyre), Some(contact)) =
                (self.spin_steps[w], self.spec.tyres.of(w), rows[i].contact)
            else {
                continue;
            };
            let forward = |body: &Body| contact.forward.dot(body.velocity_at(contact.contact_arm));
            let change = f64::from(forward(end) - forward(start));
            let load =
                end_loads.map_or(step.load(), |n| 0.5 * (step.load() + f64::from(n[i]) / dt));
            // A step that cannot be begun again keeps the first one's line (taken whole).
            match tyre.respin(&step, change, load) {
                Some(again) => self.spin_steps[w] = Some(again),
                None => {
                    self.spin_steps[w] = None;
                    self.predictions[w] = None;
                }
            }
        }
        self.set_spun_lines(rows, true);
    }

    /// The end of a step's solve: each wheel's spin (`imposed` for a velocity-controlled one),
    /// the reactions of all four spin changes on `body` (each about its wheel's spin `axes`),
    /// then each wheel's record on the chassis with all four reactions. Taken wheel by wheel
    /// between the reactions, the second wheel of an axle would see another chassis than the
    /// first, and a straight car would start to turn on round-off. Returns each wheel's change
    /// of angular momentum about its axis (N·m·s).
    pub(super) fn finish_wheels(
        &mut self,
        body: &mut Body,
        rows: &[WheelRow; 4],
        imposed: [f64; 4],
        axes: [Vector; 4],
        roads: [f64; 4],
        dt: f64,
    ) -> [f64; 4] {
        let omegas: [f64; 4] = core::array::from_fn(|i| rows[i].solved_spin(imposed[i]));
        let mut spin_changes = [0.0; 4];
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            spin_changes[i] = self.react_to_spin(body, w, axes[i], omegas[i]);
        }
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            self.finish_wheel(w, &rows[i], body, roads[i], omegas[i], dt);
        }
        spin_changes
    }

    /// The reaction of wheel `w`'s angular acceleration on the chassis. The solve puts the
    /// tyre force at the contact point, which carries the reaction of the torque that the tyre
    /// balances; this adds the part that spun the wheel up or down (I·Δω), so a motor, brake
    /// or damper turning a wheel in the air, or a speed ramp, also turns the chassis the other
    /// way. A torque-driven wheel's `I` includes its share of the engine's momentum
    /// ([`spin_momentum_inertia`](Self::spin_momentum_inertia)). Returns that change of angular
    /// momentum about `axis` (N·m·s).
    fn react_to_spin(&self, body: &mut Body, w: Wheel, axis: Vector, omega: f64) -> f64 {
        let spin_change = self.spin_momentum_inertia(w) * (omega - self.state.wheel_speeds[w]);
        body.angvel -= body.inv_inertia * (axis * spin_change as f32);
        spin_change
    }

    /// Records wheel `w`'s end of step (spin `omega`, rad/s) and advances its tyre's transient
    /// slip.
    fn finish_wheel(
        &mut self,
        w: Wheel,
        row: &WheelRow,
        body: &Body,
        road: f64,
        omega: f64,
        dt: f64,
    ) {
        self.impulses[w] = row.impulses;
        self.state.wheel_speeds[w] = omega;
        let prediction = self.predictions[w].take();
        let Some(contact) = row.contact else {
            self.state.suspension[w] = 0.0;
            self.state.tyres[w] = TyreTelemetry::default();
            // An unloaded tyre springs back.
            self.slips[w] = TransientSlip::default();
            return;
        };
        if let Support::Spring(s) = contact.support {
            self.state.suspension[w] = f64::from(s.compression);
        }
        let i = row.impulses;
        let [fx, fy, fz] = [i.forward, i.lateral, i.normal].map(|p| f64::from(p) / dt);
        let v = contact_velocity(&contact, body, omega as f32);
        if let TyreModel::MagicFormula(tyre) = self.spec.tyres.of(w) {
            match prediction {
                Some(p) => tyre.relax_spinning(&mut self.slips[w], &p, &v, fz, road, dt),
                None => tyre.relax(&mut self.slips[w], &v, fz, road, dt),
            }
        }
        let reference = v.forward.abs().max(LOW_SPEED);
        let friction_use = match row.grip {
            Grip::Slip(law) if fz > 0.0 => {
                let [ax, ay] = law.friction.map(|mu| f64::from(mu) * fz);
                (fx / ax).hypot(fy / ay)
            }
            Grip::Coulomb { friction, .. } if fz > 0.0 => {
                fx.abs().max(fy.abs()) / (f64::from(friction) * fz)
            }
            _ => 0.0,
        };
        self.state.tyres[w] = TyreTelemetry {
            slip_ratio: -v.slip[0] / reference,
            slip_angle: (-v.slip[1]).atan2(reference),
            fx,
            fy,
            fz,
            friction_use: Real::finite_or(friction_use.min(1.0), 0.0),
        };
    }
}

/// The ground under a tyre for one step.
#[derive(Debug, Clone, Copy)]
pub(super) struct Footing {
    /// The ground's friction coefficient (dimensionless).
    pub(super) road: f64,
    /// The tyre's load (N).
    pub(super) load: f64,
}

/// `lin` in the solve's precision.
fn f32_line(lin: &Linearised<f64>) -> Linearised<f32> {
    let f32s = |v: [f64; 2]| v.map(|x| x as f32);
    Linearised {
        force: f32s(lin.force),
        damping: f32s(lin.damping),
        slip_velocity: f32s(lin.slip_velocity),
        friction: f32s(lin.friction),
    }
}

/// The velocities of `contact` (m/s) on `body` for a wheel spinning at `omega` (rad/s).
fn contact_velocity(contact: &Contact, body: &Body, omega: f32) -> ContactVelocity<f64> {
    let v = body.velocity_at(contact.contact_arm);
    ContactVelocity {
        forward: f64::from(contact.forward.dot(v)),
        slip: contact.slip_velocity(body, omega).map(f64::from),
    }
}
