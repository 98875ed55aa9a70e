use rapier3d::prelude::{Mat3, Vector};
use vehicle_model::Linearised;

use super::linear::{solve2, solve4};
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
fn contact(compression: f32) -> Contact {
    Contact {
        support: Support::Spring(Spring {
            hardpoint_arm: Vector::ZERO,
            up: Vector::Z,
            compression,
            stiffness: 1e5,
            damping: 0.0,
        }),
        contact_arm: Vector::ZERO,
        normal: Vector::Z,
        forward: Vector::X,
        lateral: Vector::Y,
        radius: 0.5,
    }
}

/// Webots' rigid contact with friction `mu`.
fn rigid(mu: f32) -> Grip {
    Grip::Coulomb {
        compliance: [0.0; 2],
        friction: mu,
    }
}

fn wheel(contact: Option<Contact>, grip: Grip, spin: Spin, omega: f32) -> WheelRow {
    WheelRow {
        contact,
        grip,
        spin,
        omega,
        impulses: Impulses::default(),
    }
}

fn airborne() -> WheelRow {
    wheel(None, rigid(0.0), Spin::Imposed, 0.0)
}

fn one(w: WheelRow) -> [WheelRow; 4] {
    [w, airborne(), airborne(), airborne()]
}

#[test]
fn implicit_spring_impulse() {
    // One wheel, body at rest, x = 0.01 m, k = 1e5 N/m, c = 0, dt = 0.01 s:
    // P = dt·k·(x + dt·ẋ') with ẋ' = −P/m: P = 10/(1 + 1e5·1e-4·1e-3) = 10/1.01 N·s.
    let mut b = body();
    let mut w = one(wheel(Some(contact(0.01)), rigid(0.0), Spin::Imposed, 0.0));
    solve(&mut b, &mut w, 0.01);
    let p = w[0].impulses.normal;
    assert!((p - 10.0 / 1.01).abs() < 1e-4, "{p}");
    assert!((b.linvel.z - p * 1e-3).abs() < 1e-7);
}

/// One frictionless wheel under a chassis pitched by `theta` (rad) on flat ground, x = 0.01 m,
/// k = 1e5 N/m, damping `c` (N·s/m), the body moving forward at `speed` (m/s), solved over
/// 10 ms: the body after the step and the normal impulse (N·s).
fn pitched(theta: f32, c: f32, speed: f32) -> (Body, f32) {
    let mut contact = contact(0.01);
    if let Support::Spring(s) = &mut contact.support {
        s.up = Vector::new(theta.sin(), 0.0, theta.cos());
        s.damping = c;
    }
    let mut b = body();
    b.linvel.x = speed;
    let mut w = one(wheel(Some(contact), rigid(0.0), Spin::Imposed, 0.0));
    solve(&mut b, &mut w, 0.01);
    (b, w[0].impulses.normal)
}

#[test]
fn a_tilted_suspension_pushes_along_the_ground_normal() {
    // The chassis pitched by θ = 0.1 rad on flat ground, no friction: the spring along the
    // tilted axis carries N·cos θ, and the body gets the ground's normal force only, no push
    // along the ground. N·cos θ = dt·k·(x + dt·ẋ'), the hard point rising N/m off the ground
    // and so compressing at ẋ' = −N/(m·cos θ): N = 10/(cos θ + 0.01/cos θ).
    let theta = 0.1_f32;
    let (b, p) = pitched(theta, 0.0, 0.0);
    assert!(
        (p - 10.0 / (theta.cos() + 0.01 / theta.cos())).abs() < 1e-4,
        "{p}"
    );
    assert_eq!(b.linvel.x, 0.0);
    assert!((b.linvel.z - p * 1e-3).abs() < 1e-7);
}

#[test]
fn a_pitched_chassis_moving_along_the_ground_does_not_work_its_damper() {
    // Pitched by θ = 0.1 rad and sliding along flat ground at 20 m/s (no friction): the hard
    // point keeps its height over the ground, so the damper (c = 4000 N·s/m) only answers the
    // rate N itself causes, as in the test above: with dt·(k·dt + c) = 50 kg,
    // N·cos θ = 10 − 50·N/(m·cos θ). A rate read along the tilted axis, 20·sin θ = 2 m/s of
    // extension, would take c·2·dt = 80 N·s more off it.
    let theta = 0.1_f32;
    let (_, p) = pitched(theta, 4000.0, 20.0);
    let n = 10.0 / (theta.cos() + 0.05 / theta.cos());
    assert!((p - n).abs() < 1e-4, "{p} vs {n}");
}

#[test]
fn stretched_spring_does_not_pull() {
    let mut b = body();
    b.linvel.z = 1.0; // leaving the ground
    let mut w = one(wheel(Some(contact(0.001)), rigid(1.0), Spin::Imposed, 0.0));
    solve(&mut b, &mut w, 0.01);
    assert_eq!(w[0].impulses.normal, 0.0);
    assert_eq!(b.linvel.z, 1.0);
}

#[test]
fn imposed_spin_drags_the_body_to_the_rim_speed() {
    // Wheel imposed at 0.4 rad/s, radius 0.5: rim 0.2 m/s, 200 N·s for 1000 kg, within the
    // 10 × 99 N·s the grip allows: the body reaches it.
    let mut b = body();
    let mut w = one(wheel(Some(contact(0.1)), rigid(10.0), Spin::Imposed, 0.4));
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
    let mut w = one(wheel(Some(contact(0.01)), rigid(0.5), Spin::Imposed, 0.0));
    solve(&mut b, &mut w, 0.01);
    let i = w[0].impulses;
    let limit = 0.5 * i.normal;
    assert!((limit - 0.5 * 10.0 / 1.01).abs() < 1e-3, "{limit}");
    // Each direction saturated, opposite to its slip.
    assert!((i.forward - limit).abs() < 1e-4 && (i.lateral + limit).abs() < 1e-4);
}

#[test]
fn force_dependent_slip_is_a_compliance() {
    // ODE's FDS: slip velocity = fds·F. Body at 1 m/s sideways over a non-spinning wheel with
    // fds = 1e-4 m/s per N along the axis: F·dt = m·(1 − v) and v = fds·F give
    // v = 1/(1 + dt/(m·fds)) = 1/(1 + 0.01/(1000·1e-4)) = 1/1.1 m/s.
    let mut b = body();
    b.linvel.y = 1.0;
    let grip = Grip::Coulomb {
        compliance: [0.0, 1e-4 / 0.01],
        friction: 100.0,
    };
    let mut w = one(wheel(Some(contact(0.1)), grip, Spin::Imposed, 0.0));
    solve(&mut b, &mut w, 0.01);
    assert!((b.linvel.y - 1.0 / 1.1).abs() < 1e-5, "{}", b.linvel.y);
}

#[test]
fn slip_law_is_solved_at_the_end_of_the_step() {
    // A slip law with no force at zero slip velocity and a slope of 0.5 per m/s per unit
    // load; the body slides sideways at 1 m/s over a wheel that does not spin.
    let mut b = body();
    b.linvel.y = 1.0;
    let grip = Grip::Slip(Linearised {
        force: [0.0, 0.0],
        damping: [0.0, 0.5],
        slip_velocity: [0.0, 0.0],
        friction: [10.0, 10.0],
    });
    let mut w = one(wheel(Some(contact(0.01)), grip, Spin::Imposed, 0.0));
    solve(&mut b, &mut w, 0.01);
    // P = −0.5·N·v and m·(v − 1) = P: v = m/(m + 0.5·N) with N the suspension impulse.
    let n = w[0].impulses.normal;
    let v = 1000.0 / (1000.0 + 0.5 * n);
    assert!((b.linvel.y - v).abs() < 1e-5, "{} vs {v}", b.linvel.y);
    assert!((w[0].impulses.lateral + 0.5 * n * v).abs() < 1e-3);
}

#[test]
fn slip_force_stays_in_its_ellipse() {
    let mut b = body();
    b.linvel = Vector::new(-30.0, 40.0, 0.0);
    let grip = Grip::Slip(Linearised {
        force: [0.0, 0.0],
        damping: [100.0, 100.0],
        slip_velocity: [0.0, 0.0],
        friction: [1.0, 0.5],
    });
    let mut w = one(wheel(Some(contact(0.01)), grip, Spin::Imposed, 0.0));
    solve(&mut b, &mut w, 0.01);
    let i = w[0].impulses;
    let r = (i.forward / i.normal).hypot(i.lateral / (0.5 * i.normal));
    assert!((r - 1.0).abs() < 1e-5, "{r}");
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
    let mut w = one(wheel(Some(contact(0.1)), rigid(10.0), free, 0.0));
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
        wheel(None, rigid(0.0), brake(1.0), 10.0),
        wheel(None, rigid(0.0), brake(5.0), 10.0),
        airborne(),
        airborne(),
    ];
    solve(&mut body(), &mut w, 0.01);
    assert!((w[0].omega - 6.0).abs() < 1e-5, "{}", w[0].omega);
    assert_eq!(w[1].omega, 0.0);
}

#[test]
fn an_axle_is_solved_without_favouring_a_side() {
    // Two mirrored wheels 0.8 m either side of the centre of mass, the body sliding forward
    // and yawing: the forces are mirror images (x equal, y opposite), whichever wheel comes
    // first in the arrays.
    let side = |y: f32| Contact {
        support: Support::Spring(Spring {
            hardpoint_arm: Vector::new(0.0, y, 0.0),
            up: Vector::Z,
            compression: 0.02,
            stiffness: 1e5,
            damping: 0.0,
        }),
        contact_arm: Vector::new(0.0, y, -0.3),
        ..contact(0.02)
    };
    let grip = Grip::Slip(Linearised {
        force: [0.0, 0.0],
        damping: [2.0, 2.0],
        slip_velocity: [0.0, 0.0],
        friction: [1.0, 0.9],
    });
    let run = |first: f32| {
        let mut b = body();
        b.linvel.x = 5.0;
        let mut w = [
            wheel(Some(side(first)), grip, Spin::Imposed, 0.0),
            wheel(Some(side(-first)), grip, Spin::Imposed, 0.0),
            airborne(),
            airborne(),
        ];
        solve(&mut b, &mut w, 0.01);
        (b, w)
    };
    let (b, w) = run(-0.8);
    let (b2, w2) = run(0.8);
    // Exactly: the axle is solved in its mirror-symmetric and antisymmetric parts.
    let (r, l) = (w[0].impulses, w[1].impulses);
    assert_eq!(r.forward, l.forward, "{r:?} {l:?}");
    assert_eq!(r.lateral, -l.lateral);
    assert_eq!(r.normal, l.normal);
    assert_eq!((b.linvel.y, b.angvel.z), (0.0, 0.0), "{:?}", b.angvel);
    // The same forces with the wheels swapped in the arrays.
    assert!((w2[1].impulses.forward - r.forward).abs() < 1e-4 * r.forward.abs());
    assert!((b2.linvel.x - b.linvel.x).abs() < 1e-6);
}

#[test]
fn small_systems() {
    assert_eq!(
        solve2([[2.0, 0.0], [0.0, 4.0]], [2.0, 2.0]),
        Some([1.0, 0.5])
    );
    assert_eq!(solve2([[1.0, 1.0], [1.0, 1.0]], [1.0, 1.0]), None);
    // Needs a row swap: the first pivot is 0.
    let m = [
        [0.0, 1.0, 0.0, 0.0],
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 0.0, 2.0, 1.0],
        [0.0, 0.0, 1.0, 2.0],
    ];
    let x = solve4(m, [1.0, 2.0, 3.0, 3.0]).unwrap();
    for (a, b) in x.iter().zip([2.0, 1.0, 1.0, 1.0]) {
        assert!((a - b).abs() < 1e-6, "{x:?}");
    }
    assert_eq!(solve4([[0.0; 4]; 4], [1.0; 4]), None);
}

#[test]
fn friction_cannot_wedge_a_leaning_suspension() {
    // A chassis rolled by φ = 0.6 rad (its suspension axis leaning toward +y) slides toward +y
    // at 5 m/s on a rigid tyre with μ = 10: the friction impulse −μ·N·y loads the spring along
    // the axis, `N·cos φ − μ·N·sin φ = P_spring`, a factor cos φ − μ·sin φ = −4.8 < 0: a rigid
    // slider with friction has no bounded solution (issue #37 threw a rolled BmwX5 76 m up).
    // With the friction's share of the spring load limited to a gain of
    // MAX_FRICTION_FEEDBACK = 0.5, `N ≤ P_spring / ((1 − 0.5)·cos φ)`, P_spring at most the
    // spring's static impulse `dt·k·x` (the normal impulse lifts the chassis, which only
    // unloads the spring).
    let phi: f32 = 0.6;
    let mut c = contact(0.01);
    if let Support::Spring(s) = &mut c.support {
        s.up = Vector::new(0.0, phi.sin(), phi.cos());
    }
    let mut b = body();
    b.linvel = Vector::new(0.0, 5.0, 0.0);
    let mut w = one(wheel(Some(c), rigid(10.0), Spin::Imposed, 0.0));
    solve(&mut b, &mut w, 0.01);
    let n = w[0].impulses.normal;
    let bound = 0.01 * 1e5 * 0.01 / ((1.0 - axle::MAX_FRICTION_FEEDBACK) * phi.cos());
    assert!(
        n > 0.0 && n <= bound * 1.0001,
        "N = {n} N·s, bound {bound} N·s"
    );
    // The friction stays within μ·N.
    assert!(w[0].impulses.lateral.abs() <= 10.0 * n * 1.0001);

    // Upright (φ = 5°, μ = 1: a gain of 0.087), the spring carries the whole tyre share:
    // `N·cos φ + P_lat·sin φ` equals the spring's impulse as before the limit.
    let phi: f32 = 5f32.to_radians();
    let mut c = contact(0.01);
    if let Support::Spring(s) = &mut c.support {
        s.up = Vector::new(0.0, phi.sin(), phi.cos());
    }
    let mut b = body();
    b.linvel = Vector::new(0.0, 0.5, 0.0);
    let mut w = one(wheel(Some(c), rigid(1.0), Spin::Imposed, 0.0));
    solve(&mut b, &mut w, 0.01);
    let i = w[0].impulses;
    let carried = i.normal * phi.cos() + i.lateral * phi.sin();
    // The implicit spring at the end-of-step compression rate: P = dt·k·(x + dt·ẋ).
    let rate = -Vector::new(0.0, 0.0, 1.0 / phi.cos()).dot(b.linvel);
    let spring = 0.01 * 1e5 * (0.01 + 0.01 * rate);
    assert!(
        (carried - spring).abs() < 1e-3 * spring,
        "{carried} vs {spring}"
    );
}
