//! The sub-stepped tyre of a free wheel (`MagicFormula::begin_spinning`, `linearise_spun`,
//! `relax_spinning`) against the same wheel integrated in fine steps with the plain
//! linearisation, on a chassis held at a constant speed: a BmwX5-sized front wheel hit by a
//! sudden brake torque above what its grip can hold.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use vehicle_model::{
    ContactVelocity, FreeSpin, Linearised, MagicFormula, PerWheel, SpinStep, TransientSlip,
    TyreClass,
};

/// Wheel radius (m), spin inertia (kg·m²), load (N), chassis speed (m/s), brake torque (N·m).
const RADIUS: f64 = 0.374;
const INERTIA: f64 = 1.6;
const LOAD: f64 = 6000.0;
const SPEED: f64 = 60.0 / 3.6;
/// Above the grip's μ·F_z·r = 1.0·6000·0.374 = 2244 N·m: the wheel goes on to lock.
const BRAKE: f64 = 2600.0;

fn tyre() -> MagicFormula<f64> {
    TyreClass::PassengerCar
        .params(RADIUS, LOAD)
        .validate()
        .unwrap()
}

fn velocity(omega: f64) -> ContactVelocity<f64> {
    ContactVelocity {
        forward: SPEED,
        slip: [SPEED - omega * RADIUS, 0.0],
    }
}

/// The wheel's end spin (rad/s) over a step of `dt` (s) from `omega` under the line `lin`,
/// with the brake as Coulomb friction on the spin, and the longitudinal force (N) it took:
/// `I·(ω' − ω) = −r·F_z·f(v − ω'·r)·dt + b`, `|b| ≤ BRAKE·dt` against the spin.
fn solve(lin: &Linearised<f64>, omega: f64, dt: f64) -> (f64, f64) {
    let gain = RADIUS * LOAD * dt / INERTIA;
    let k = lin.damping[0];
    // f(u) = force + k·(slip_velocity − u) with u = v − ω'·r: linear in ω'.
    let f_at = |next: f64| lin.at([SPEED - next * RADIUS, 0.0])[0];
    let stiff = 1.0 + gain * k * RADIUS;
    let free =
        omega - gain * (lin.force[0] + k * (lin.slip_velocity[0] - SPEED + omega * RADIUS)) / stiff;
    // The brake stops the wheel if it can (against the effective inertia I·stiff).
    let reach = BRAKE * dt / (INERTIA * stiff);
    let mut next = free - free.clamp(-reach, reach);
    let mut f = f_at(next);
    let limit = lin.friction[0];
    if f.abs() > limit {
        f = limit * f.signum();
        let free = omega - gain * f;
        let reach = BRAKE * dt / INERTIA;
        next = free - free.clamp(-reach, reach);
    }
    (next, f * LOAD)
}

/// Fine reference: `steps` steps of `h` (s) with the plain linearisation. Returns the spin
/// after each `every` steps and the impulse (N·s) over the first `every`.
fn reference(h: f64, every: usize, outputs: usize) -> (Vec<f64>, f64) {
    let t = tyre();
    let mut slip = TransientSlip::default();
    let mut omega = SPEED / RADIUS;
    let (mut spins, mut impulse) = (Vec::new(), 0.0);
    for k in 0..every * outputs {
        let lin = t.linearise(&slip, &velocity(omega), LOAD, 1.0, h);
        let (next, f) = solve(&lin, omega, h);
        omega = next;
        t.relax(&mut slip, &velocity(omega), LOAD, 1.0, h);
        if k < every {
            impulse += f * h;
        }
        if (k + 1) % every == 0 {
            spins.push(omega);
        }
    }
    (spins, impulse)
}

/// `outputs` steps of `dt` (s), sub-stepped if `spun`, else with the plain linearisation.
fn coarse(dt: f64, outputs: usize, spun: bool) -> (Vec<f64>, f64) {
    let t = tyre();
    let mut slip = TransientSlip::default();
    let mut omega = SPEED / RADIUS;
    let (mut spins, mut impulse) = (Vec::new(), 0.0);
    for k in 0..outputs {
        let v = velocity(omega);
        let wheel = FreeSpin {
            inertia: INERTIA,
            radius: RADIUS,
            spin: omega,
            drive: 0.0,
            brake: BRAKE * dt,
            chassis: 0.0,
        };
        let (lin, prediction) = if spun {
            let step = t.begin_spinning(&slip, &v, &wheel, LOAD, 1.0, dt).unwrap();
            t.linearise_spun(&step, true)
        } else {
            (t.linearise(&slip, &v, LOAD, 1.0, dt), None)
        };
        let (next, f) = solve(&lin, omega, dt);
        omega = next;
        match prediction {
            Some(p) => t.relax_spinning(&mut slip, &p, &velocity(omega), LOAD, 1.0, dt),
            None => t.relax(&mut slip, &velocity(omega), LOAD, 1.0, dt),
        }
        if k == 0 {
            impulse = f * dt;
        }
        spins.push(omega);
    }
    (spins, impulse)
}

#[test]
fn a_braked_wheel_follows_the_fine_solution_at_10_ms() {
    // 0.1 ms steps resolve the tyre's build-up (its relaxation length over 16.7 m/s takes
    // about 9 ms) to well under 1 %.
    let (fine, fine_impulse) = reference(1e-4, 100, 8);
    let (spun, spun_impulse) = coarse(1e-2, 8, true);
    let (plain, plain_impulse) = coarse(1e-2, 8, false);
    let (milli, milli_impulse) = reference(1e-3, 10, 8);
    println!("1 ms plain: impulse {milli_impulse:.2}, spins {milli:.3?}");
    println!(
        "first 10 ms impulse: fine {fine_impulse:.2}, sub-stepped {spun_impulse:.2}, plain {plain_impulse:.2} N·s"
    );
    for k in 0..8 {
        println!(
            "{} ms: spin fine {:.3}, sub-stepped {:.3}, plain {:.3} rad/s",
            10 * (k + 1),
            fine[k],
            spun[k],
            plain[k]
        );
    }
    // One 10 ms step divided into 1 ms sub-steps is ten 1 ms steps: the chassis is held here
    // as the sub-steps hold it.
    assert!((spun_impulse - milli_impulse).abs() < 1e-6 * milli_impulse.abs());
    for k in 0..8 {
        assert!(
            (spun[k] - milli[k]).abs() < 1e-6 * fine[0],
            "{k}: {} vs {}",
            spun[k],
            milli[k]
        );
    }
    // 1 ms steps are within 10 % of the fine solution's first-10 ms impulse (the scheme is first
    // order: 8.8 % here) and within 4 % of the rolling spin (44.6 rad/s) all the way to lock
    // (3.6 % at 80 ms, nearest the lock).
    let rolling = SPEED / RADIUS;
    assert!((milli_impulse / fine_impulse - 1.0).abs() < 0.1);
    for k in 0..8 {
        assert!(
            (milli[k] - fine[k]).abs() < 0.04 * rolling,
            "{k}: {} vs {}",
            milli[k],
            fine[k]
        );
    }
    // The undivided 10 ms step takes the end-of-step force over the whole first step: 56 %
    // too much impulse, and the wheel is 9.7 rad/s (22 % of its rolling spin) behind the fine
    // solution after 70 ms.
    assert!(plain_impulse / fine_impulse > 1.5);
    assert!(plain[6] - fine[6] > 0.2 * rolling);
}

/// A 10 ms step of a wheel locked by a brake that holds it, sliding at the chassis speed,
/// with its transient slip settled at −1 (the kinematic slip of a locked wheel).
fn held(t: &MagicFormula<f64>) -> SpinStep<f64> {
    let slip = TransientSlip {
        ratio: -1.0,
        angle_tan: 0.0,
    };
    let wheel = FreeSpin {
        inertia: INERTIA,
        radius: RADIUS,
        spin: 0.0,
        drive: 0.0,
        brake: BRAKE * 0.01,
        chassis: 0.0,
    };
    t.begin_spinning(&slip, &velocity(0.0), &wheel, LOAD, 1.0, 0.01)
        .unwrap()
}

/// A 10 ms step of a wheel rolling at the chassis speed with no transient slip, under a brake
/// torque `brake` (N·m).
fn rolling(t: &MagicFormula<f64>, brake: f64) -> SpinStep<f64> {
    let omega = SPEED / RADIUS;
    let wheel = FreeSpin {
        inertia: INERTIA,
        radius: RADIUS,
        spin: omega,
        drive: 0.0,
        brake: brake * 0.01,
        chassis: 0.0,
    };
    let slip = TransientSlip::default();
    t.begin_spinning(&slip, &velocity(omega), &wheel, LOAD, 1.0, 0.01)
        .unwrap()
}

#[test]
fn only_a_wheel_its_brake_holds_still_is_steady() {
    let t = tyre();
    // Locked and sliding: the brake (2600 N·m) holds it against the tyre's μ·F_z·r, the slip
    // stays −1 and the force with it; the step is taken whole.
    assert!(held(&t).is_steady());
    // Rolling freely at the chassis speed, no brake: its force stays at 0 over the step, yet
    // it is divided, because near the curve's peak a flat force can hide a slip that runs
    // through it.
    assert!(!rolling(&t, 0.0).is_steady());
}

#[test]
fn invalid_wheels_and_steps_are_refused() {
    let t = tyre();
    let slip = TransientSlip::default();
    let good = FreeSpin {
        inertia: INERTIA,
        radius: RADIUS,
        spin: 40.0,
        drive: 0.0,
        brake: 1.0,
        chassis: 0.0,
    };
    let v = velocity(40.0);
    assert!(
        t.begin_spinning(&slip, &v, &good, LOAD, 1.0, 0.01)
            .is_some()
    );
    for bad in [
        FreeSpin {
            inertia: 0.0,
            ..good
        },
        FreeSpin {
            radius: -1.0,
            ..good
        },
        FreeSpin {
            spin: f64::NAN,
            ..good
        },
        FreeSpin {
            drive: f64::INFINITY,
            ..good
        },
        FreeSpin {
            brake: f64::NAN,
            ..good
        },
        FreeSpin {
            chassis: f64::NAN,
            ..good
        },
    ] {
        assert!(
            t.begin_spinning(&slip, &v, &bad, LOAD, 1.0, 0.01).is_none(),
            "{bad:?}"
        );
    }
    for dt in [0.0, -0.01, f64::NAN] {
        assert!(
            t.begin_spinning(&slip, &v, &good, LOAD, 1.0, dt).is_none(),
            "{dt}"
        );
    }
}

#[test]
fn both_wheels_of_an_axle_are_divided_alike() {
    let t = tyre();
    let (braked, held) = (rolling(&t, BRAKE), held(&t));
    assert!(held.is_steady() && !braked.is_steady());
    // Front right braked while rolling, front left held: both divided. Rear: one held, one
    // without a sub-stepped tyre: neither.
    let steps = PerWheel::new(Some(braked), Some(held), None, Some(held));
    let divide = SpinStep::to_divide(&steps);
    assert_eq!(*divide.as_array(), [true, true, false, false]);
}
