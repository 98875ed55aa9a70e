extern crate std;
use std::string::ToString;

use super::*;

const FZ0: f64 = 4000.0;

fn car() -> MagicFormula<f64> {
    TyreClass::PassengerCar
        .params(0.35, FZ0)
        .validate()
        .unwrap()
}

/// Pacejka's pure-slip formula with D = μ·F_z, B = K/(C·D).
fn pacejka(x: f64, k: f64, c: f64, mu: f64, e: f64, fz: f64) -> f64 {
    let d = mu * fz;
    let b = k * fz / (c * d);
    d * (c * (b * x - e * (b * x - (b * x).atan())).atan()).sin()
}

#[test]
fn pure_slip_is_the_magic_formula() {
    let t = car();
    for kappa in [-1.0, -0.3, -0.05, 0.01, 0.1, 0.2, 0.5, 2.0] {
        let [fx, fy] = t.force([kappa, 0.0], FZ0, 1.0);
        let expected = pacejka(kappa, 25.0, 1.65, 1.0, 0.7, FZ0);
        assert!(
            (fx - expected).abs() < 1e-6 * FZ0,
            "κ {kappa}: {fx} vs {expected}"
        );
        assert_eq!(fy, 0.0);
    }
    for alpha in [-0.5_f64, -0.1, 0.02, 0.15, 1.0] {
        let [fx, fy] = t.force([0.0, alpha.tan()], FZ0, 1.0);
        let expected = pacejka(alpha.tan(), 18.0, 1.3, 0.95, -0.5, FZ0);
        assert!(
            (fy - expected).abs() < 1e-6 * FZ0,
            "α {alpha}: {fy} vs {expected}"
        );
        assert_eq!(fx, 0.0);
    }
}

#[test]
fn stiffness_peak_and_sliding_at_nominal_load() {
    let t = car();
    // Slopes at the origin: 25 F_z per unit κ, 18 F_z per rad.
    let [fx, _] = t.force([1e-6, 0.0], FZ0, 1.0);
    assert!((fx / 1e-6 - 25.0 * FZ0).abs() < 1.0);
    let [_, fy] = t.force([0.0, 1e-6], FZ0, 1.0);
    assert!((fy / 1e-6 - 18.0 * FZ0).abs() < 1.0);
    // The longitudinal force peaks (μ·F_z) between 5 % and 20 % of slip.
    let [kp, ap] = t.peak_slip(FZ0, 1.0);
    assert!((0.05..=0.2).contains(&kp), "{kp}");
    assert!((0.08..=0.2).contains(&ap), "{ap}");
    assert!((t.force([kp, 0.0], FZ0, 1.0)[0] - FZ0).abs() < 1e-6);
    assert!(t.force([kp * 0.9, 0.0], FZ0, 1.0)[0] < FZ0);
    assert!(t.force([kp * 1.1, 0.0], FZ0, 1.0)[0] < FZ0);
    // Locked: 0.746 of the peak (Pacejka's formula at κ = −1), within 0.7–0.8.
    let locked = -t.force([-1.0, 0.0], FZ0, 1.0)[0] / FZ0;
    assert!((locked - 0.7461).abs() < 1e-3, "{locked}");
}

#[test]
fn road_friction_scales_the_peak_not_the_stiffness() {
    let t = car();
    let [fx, _] = t.force([1e-6, 0.0], FZ0, 0.5);
    assert!((fx / 1e-6 - 25.0 * FZ0).abs() < 1.0);
    let [kp, _] = t.peak_slip(FZ0, 0.5);
    assert!((t.force([kp, 0.0], FZ0, 0.5)[0] - 0.5 * FZ0).abs() < 1e-6);
    assert_eq!(t.force([0.1, 0.1], FZ0, 0.0), [0.0, 0.0]);
}

#[test]
fn load_sensitivity() {
    let t = car();
    let fz = 2.0 * FZ0;
    // μ(2·F_z0) = (1 − 0.1·1)·μ: peak 0.9·2·F_z0.
    let [kp, ap] = t.peak_slip(fz, 1.0);
    assert!((t.force([kp, 0.0], fz, 1.0)[0] - 0.9 * fz).abs() < 1e-6);
    assert!((t.force([0.0, ap], fz, 1.0)[1] - 0.9 * 0.95 * fz).abs() < 1e-6);
    // C_α(2·F_z0) = C_α0·sin(2·atan(1))/sin(2·atan(0.5)) = C_α0/0.8.
    let [_, fy] = t.force([0.0, 1e-7], fz, 1.0);
    assert!((fy / 1e-7 - 18.0 * FZ0 / 0.8).abs() < 1.0, "{}", fy / 1e-7);
    // Longitudinal stiffness proportional to load.
    let [fx, _] = t.force([1e-7, 0.0], fz, 1.0);
    assert!((fx / 1e-7 - 25.0 * fz).abs() < 1.0);
}

#[test]
fn combined_slip_stays_in_the_friction_ellipse() {
    let t = car();
    let (mx, my) = (FZ0, 0.95 * FZ0);
    let mut worst: f64 = 0.0;
    for i in -20..=20 {
        for j in -20..=20 {
            let slip = [f64::from(i) * 0.05, f64::from(j) * 0.05];
            let [fx, fy] = t.force(slip, FZ0, 1.0);
            let r = (fx / mx).hypot(fy / my);
            worst = worst.max(r);
            // The force opposes the slip velocity: it has the sign of each slip.
            assert!(fx * slip[0] >= 0.0 && fy * slip[1] >= 0.0);
        }
    }
    assert!(worst <= 1.0 + 1e-12 && worst > 0.999, "{worst}");
    // A locked wheel at 0.1 rad of slip angle keeps under a tenth of its side force.
    let side = t.force([0.0, 0.1_f64.tan()], FZ0, 1.0)[1];
    let [fx, fy] = t.force([-1.0, 0.1_f64.tan()], FZ0, 1.0);
    assert!(fy.abs() < 0.15 * side, "{fy} vs {side}");
    // Sliding (far past the peak), its force points straight against the sliding velocity
    // (1, −tan α): 0.1 rad from straight back.
    let angle = fy.atan2(-fx);
    assert!((angle - 0.1).abs() < 1e-12, "{angle}");
    // Below the peak it points along (K_x·κ, K_y·tan α), the stiffnesses' direction.
    let [fx, fy] = t.force([-0.02, 0.01], FZ0, 1.0);
    let angle = fy.atan2(-fx);
    assert!(
        (angle - (18.0 * 0.01 / (25.0 * 0.02)).atan()).abs() < 1e-9,
        "{angle}"
    );
}

#[test]
fn combined_slip_only_takes_grip_away() {
    // Below the limit each axis keeps its own stiffness whatever the other's slip, and more
    // slip along one axis never raises the force along the other.
    let t = car();
    for alpha in [0.002, 0.02, 0.1, 0.3_f64] {
        let mut previous = f64::INFINITY;
        for k in 0..=100 {
            let kappa = f64::from(k) * 0.01;
            let fy = t.force([kappa, alpha.tan()], FZ0, 1.0)[1];
            assert!(
                fy <= previous + 1e-9,
                "α {alpha}, κ {kappa}: {fy} > {previous}"
            );
            previous = fy;
        }
    }
    // The cornering stiffness at a slip ratio κ: 18 F_z per rad times the longitudinal curve's
    // secant g(t)/t at t = K_x·κ/μ = 25·κ (the shared curve bends away from its initial slope).
    let shape = Shape::new(1.65, 0.7).unwrap();
    let tiny = 1e-7;
    for kappa in [0.0, 0.001, 0.01, 0.05] {
        let [_, fy] = t.force([kappa, tiny], FZ0, 1.0);
        let secant = if kappa > 0.0 {
            shape.at(25.0 * kappa) / (25.0 * kappa)
        } else {
            1.0
        };
        let expected = 18.0 * FZ0 * secant;
        assert!(
            (fy / tiny / expected - 1.0).abs() < 1e-4,
            "κ {kappa}: {} vs {expected}",
            fy / tiny
        );
    }
}

#[test]
fn relaxation_lags_by_the_relaxation_length() {
    let t = car();
    // Lateral slip velocity −0.2 m/s at 20 m/s: tan α = 0.01. After rolling one relaxation
    // length (0.35 m, 17.5 ms) the transient slip is at 1 − 1/e of it (implicit Euler with
    // 0.1 ms steps, 0.57 % of the time constant each, decays 0.3 % slower than the exponential).
    let v = ContactVelocity {
        forward: 20.0,
        slip: [0.0, -0.2],
    };
    let mut s = TransientSlip::default();
    let dt = 1e-4;
    for _ in 0..175 {
        t.relax(&mut s, &v, FZ0, 1.0, dt);
    }
    let expected = 0.01 * (1.0 - (-1.0_f64).exp());
    assert!(
        (s.angle_tan - expected).abs() < 3e-3 * expected,
        "{}",
        s.angle_tan
    );
    for _ in 0..10_000 {
        t.relax(&mut s, &v, FZ0, 1.0, dt);
    }
    assert!((s.angle_tan - 0.01).abs() < 1e-12);
    assert_eq!(s.ratio, 0.0);
}

#[test]
fn at_standstill_the_tyre_is_a_spring_that_stops_at_its_peak() {
    let t = car();
    // The patch pushed 1 mm forward (v_sx = +0.1 m/s for 10 ms) at standstill: κ' = −1 mm/σ_x,
    // σ_x = 0.4·0.35 m; the force is the stiffness times that: a spring of 25·F_z/σ_x N/m.
    let mut s = TransientSlip::default();
    let v = ContactVelocity {
        forward: 0.0,
        slip: [0.1, 0.0],
    };
    t.relax(&mut s, &v, FZ0, 1.0, 0.01);
    assert!((s.ratio + 0.001 / 0.14).abs() < 1e-12, "{}", s.ratio);
    // Still, the deflection holds (no decay without rolling).
    let rest = ContactVelocity::default();
    let held = s;
    t.relax(&mut s, &rest, FZ0, 1.0, 0.01);
    assert_eq!(s, held);
    // Pushed on and on, it slides at its peak slip, never beyond.
    for _ in 0..1000 {
        t.relax(&mut s, &v, FZ0, 1.0, 0.01);
    }
    let [kp, _] = t.peak_slip(FZ0, 1.0);
    assert!((s.ratio + kp).abs() < 1e-12, "{}", s.ratio);
}

#[test]
fn linearisation_is_the_chord_to_zero_slip() {
    let t = car();
    let dt = 0.01;
    for (forward, slip, s) in [
        (15.0, [-0.3, 0.1], [0.02, -0.01]),
        (20.0, [20.0, -1.0], [-1.0, 0.05]),
        (0.2, [-2.0, 0.0], [0.5, 0.0]),
    ] {
        let s = TransientSlip {
            ratio: s[0],
            angle_tan: s[1],
        };
        let v0 = ContactVelocity { forward, slip };
        let lin = t.linearise(&s, &v0, FZ0, 1.0, dt);
        let mut next = s;
        t.relax(&mut next, &v0, FZ0, 1.0, dt);
        let exact = t
            .force([next.ratio, next.angle_tan], FZ0, 1.0)
            .map(|f| f / FZ0);
        // Through the force of the predicted transient slip (less the carcass damper below
        // walking pace)...
        let fade = (1.0 - forward / LOW_SPEED).max(0.0);
        if fade == 0.0 {
            for (at, exact) in lin.at(slip).into_iter().zip(exact) {
                assert!((at - exact).abs() < 1e-12, "{forward}");
            }
        }
        // ... and (above walking pace) through zero at the slip velocity σ·x/dt that leaves no
        // transient slip.
        if fade == 0.0 {
            let zero = [0, 1].map(|i| {
                let sigma = [0.14, 0.35][i];
                sigma * [s.ratio, s.angle_tan][i] / dt
            });
            let at = lin.at(zero);
            assert!(
                at[0].abs() < 1e-9 && at[1].abs() < 1e-9,
                "{forward}: {at:?}"
            );
        }
        assert!(lin.damping.iter().all(|d| *d > 0.0));
    }
    // In the linear range the chord is the tangent: 1 cm/s more slip velocity at 15 m/s
    // changes the force by the stiffness·dt/(σ + dt·v) within 1 %.
    let v0 = ContactVelocity {
        forward: 15.0,
        slip: [-0.05, 0.0],
    };
    let lin = t.linearise(&TransientSlip::default(), &v0, FZ0, 1.0, dt);
    let tangent = 25.0 * dt / (0.14 + dt * 15.0);
    assert!(
        (lin.damping[0] - tangent).abs() < 0.01 * tangent,
        "{:?}",
        lin.damping
    );
    // At standstill, unloaded patch: a spring of stiffness/σ integrated implicitly plus the
    // carcass damper of 0.02 s: 25·(0.01 + 0.02)/0.14 per m/s longitudinally (σ_x = 0.14 m),
    // 18·0.03/0.35 laterally (σ_y = 0.35 m).
    let lin = t.linearise(
        &TransientSlip::default(),
        &ContactVelocity::default(),
        FZ0,
        1.0,
        dt,
    );
    assert!(
        (lin.damping[0] - 25.0 * 0.03 / 0.14).abs() < 1e-9,
        "{:?}",
        lin.damping
    );
    assert!(
        (lin.damping[1] - 18.0 * 0.03 / 0.35).abs() < 1e-9,
        "{:?}",
        lin.damping
    );
    assert_eq!(lin.force, [0.0, 0.0]);
}

#[test]
fn bad_input_gives_no_force_and_keeps_state_finite() {
    let t = car();
    let mut s = TransientSlip::default();
    for bad in [f64::NAN, f64::INFINITY, -f64::INFINITY] {
        assert_eq!(t.force([bad, 0.1], FZ0, 1.0), [0.0, 0.0]);
        assert_eq!(t.force([0.1, 0.1], bad, 1.0), [0.0, 0.0]);
        assert_eq!(t.force([0.1, 0.1], FZ0, bad), [0.0, 0.0]);
        let v = ContactVelocity {
            forward: bad,
            slip: [bad, 1.0],
        };
        t.relax(&mut s, &v, FZ0, 1.0, 0.01);
        let lin = t.linearise(&s, &v, FZ0, 1.0, bad);
        assert!(s.ratio.is_finite() && s.angle_tan.is_finite());
        assert!(lin.force.iter().chain(&lin.damping).all(|x| x.is_finite()));
    }
}

#[test]
fn f32_agrees_with_f64() {
    let t32 = TyreClass::PassengerCar
        .params(0.35_f32, 4000.0)
        .validate()
        .unwrap();
    let t64 = car();
    for slip in [[0.05, 0.0], [-1.0, 0.1], [0.3, -0.2]] {
        let a = t32.force(slip.map(|v: f64| v as f32), 4000.0, 1.0);
        let b = t64.force(slip, FZ0, 1.0);
        for i in 0..2 {
            assert!((f64::from(a[i]) - b[i]).abs() < 1e-3 * FZ0);
        }
    }
}

#[test]
fn every_class_validates_and_fields_round_trip() {
    for class in TyreClass::ALL {
        let mut p = class.params(0.5_f64, 10_000.0);
        assert!(p.validate().is_ok(), "{class:?}");
        for field in TyreParams::<f64>::FIELDS {
            let name = field.name();
            assert_eq!(TyreField::from_name(name, field.direction()), Some(field));
            assert!(field.path().ends_with(name) && field.path().starts_with("tyre."));
            let v = p.get(field);
            p.set(field, f64::NAN);
            let e = p.validate().unwrap_err();
            assert_eq!(e.field, field);
            assert!(e.value.is_nan());
            p.set(field, v);
        }
    }
    let e = TyreError {
        field: TyreField::NominalLoad,
        value: -1.0,
    };
    assert_eq!(
        e.to_string(),
        "tyre.nominal_load = -1 must be in [1, 1e6] N"
    );
}

#[test]
fn webots_contact_validation() {
    let c = WebotsContact {
        force_dependent_slip: [0.0, 1e-4],
    };
    assert_eq!(c.validate(), Ok(c));
    let bad = WebotsContact {
        force_dependent_slip: [-1.0, 0.0],
    };
    assert_eq!(bad.validate(), Err(-1.0));
}
