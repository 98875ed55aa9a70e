//! Each wheel's part in a step's contact solve: its row set up before the solve (the spin, the
//! warm start, its contact and the tyre's force law on its footing), the reaction of its change
//! of spin on the chassis, and its record after the solve (telemetry, transient slip).

use ackermann::Wheel;
use rapier3d::prelude::Vector;
use vehicle_model::tyre::LOW_SPEED;
use vehicle_model::{ContactVelocity, Linearised, Real, TransientSlip, TyreModel};

use super::contact::{Body, Contact, Grip, Spin, Support, WheelRow};
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
        &self,
        w: Wheel,
        row: &mut WheelRow,
        contact: Contact,
        body: &Body,
        footing: Footing,
        dt: f64,
    ) {
        let Footing { road, load } = footing;
        row.grip = match self.spec.tyres.of(w) {
            TyreModel::Webots(c) => Grip::Coulomb {
                compliance: c.force_dependent_slip.map(|fds| (fds / dt) as f32),
                friction: road as f32,
            },
            TyreModel::MagicFormula(tyre) => {
                // Linearised at the spin the wheel starts the step with: the drive torque's
                // spin-up is part of the solve (a free spin is a row coordinate), and a
                // point near the step's solution keeps the linearisation accurate when a
                // large torque would spin the wheel far into sliding before the tyre acts.
                let omega = match row.spin {
                    Spin::Imposed => row.omega,
                    Spin::Free { .. } => self.state.wheel_speeds[w] as f32,
                };
                let v = contact_velocity(&contact, body, omega);
                let lin = tyre.linearise(&self.slips[w], &v, load, road, dt);
                if let Spin::Free { brake_impulse, .. } = &mut row.spin {
                    let rolling = tyre.rolling_resistance_torque(load, f64::from(contact.radius));
                    *brake_impulse += (rolling * dt) as f32;
                }
                let f32s = |v: [f64; 2]| v.map(|x| x as f32);
                Grip::Slip(Linearised {
                    force: f32s(lin.force),
                    damping: f32s(lin.damping),
                    slip_velocity: f32s(lin.slip_velocity),
                    friction: f32s(lin.friction),
                })
            }
        };
        row.contact = Some(contact);
    }

    /// The reaction of wheel `w`'s angular acceleration on the chassis. The solve puts the
    /// tyre force at the contact point, which carries the reaction of the torque that the tyre
    /// balances; this adds the part that spun the wheel up or down (I·Δω), so a motor, brake
    /// or damper turning a wheel in the air, or a speed ramp, also turns the chassis the other
    /// way. Returns that change of the wheel's angular momentum about `axis` (N·m·s).
    pub(super) fn react_to_spin(&self, body: &mut Body, w: Wheel, axis: Vector, omega: f64) -> f64 {
        let spin_change = self.spec.wheels[w].spin_inertia() * (omega - self.state.wheel_speeds[w]);
        body.angvel -= body.inv_inertia * (axis * spin_change as f32);
        spin_change
    }

    /// Records wheel `w`'s end of step (spin `omega`, rad/s) and advances its tyre's transient
    /// slip.
    pub(super) fn finish_wheel(
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
            tyre.relax(&mut self.slips[w], &v, fz, road, dt);
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

/// The velocities of `contact` (m/s) on `body` for a wheel spinning at `omega` (rad/s).
fn contact_velocity(contact: &Contact, body: &Body, omega: f32) -> ContactVelocity<f64> {
    let v = body.velocity_at(contact.contact_arm);
    ContactVelocity {
        forward: f64::from(contact.forward.dot(v)),
        slip: contact.slip_velocity(body, omega).map(f64::from),
    }
}
