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

// One concept per module: the chassis as the solve sees it (`body`), what each wheel brings
// to it (`rows`: contact, grip, spin and impulses), an axle's rows solved as blocks (`axle`),
// the small dense systems those blocks are (`linear`); this file holds the sweeps that tie
// them together. The functions the sweeps reach across these modules are `#[inline]`: a
// module is compiled apart from the others, and without the hint the split would cost the
// solve the inlining it had as one file (0.5 % more instructions per car step).
mod axle;
mod body;
mod linear;
mod rows;

use axle::{Axle, brake_row, suspension_block, tyre_block};
pub(crate) use body::Body;
pub(crate) use rows::{Contact, Grip, Impulses, Spin, Spring, Support, WheelRow};

/// Most block Gauss–Seidel sweeps per step. With warm starting, 8 sweeps leave residual slip
/// velocities under 1 mm/s on every shipped car with the rigid Webots contact (the chassis
/// couples the two axles; each sweep solves one axle exactly given the other).
pub(crate) const SWEEPS: usize = 8;

/// The sweeps stop early once the last one moved no impulse by more than this fraction of
/// the largest suspension impulse (a cruising car settles in two or three sweeps).
const SETTLED: f32 = 1e-5;

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
        // One impulse per wheel: applied as two, the second wheel of an axle would not undo
        // the first's roll and yaw exactly (((−a − b) + a) + b ≠ 0 in floating point), and a
        // straight car would start to turn on round-off.
        body.apply(
            c.contact_arm,
            c.normal * i.normal + c.forward * i.forward + c.lateral * i.lateral,
        );
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

#[cfg(test)]
mod tests;
