//! No NaN or ∞ out of any public function for any input, the documented handling of NaN, ∞ and
//! |δ| ≥ π/2, mirror symmetry, and f32/f64 agreement.

#![allow(clippy::unwrap_used)] // test helpers may unwrap

use ackermann::{
    DifferentialRatios, DriveType, Geometry, Odometry, PerWheel, Real, SpeedSource, Turning, Wheel,
    WheelAngles, effective_steering_angle,
};
use core::f64::consts::{FRAC_PI_2, PI};

/// Awkward values of `T`: zeros, subnormals, tiny, ordinary, around π/2 and π, huge, ±∞, NaN.
fn specials<T: Real>() -> Vec<T> {
    let mut v: Vec<T> = [
        0.0, 1e-320, 1e-310, 1e-300, 1e-45, 1e-40, 1e-38, 1e-30, 1e-9, 0.1, 0.5, 1.0, 1.3,
        FRAC_PI_2, 1.6, 2.0, PI, 10.0, 1e10, 1e30, 1e38, 1e300,
    ]
    .into_iter()
    .map(T::from_f64)
    .collect();
    let eps = T::EPSILON;
    v.extend([
        T::FRAC_PI_2 * (T::ONE - eps),
        T::FRAC_PI_2 * (T::ONE + eps),
        T::MAX,
        T::INFINITY,
    ]);
    let negatives: Vec<T> = v.iter().map(|&x| -x).collect();
    v.extend(negatives);
    v.push(T::from_f64(f64::NAN));
    v
}

/// BMW X5, then extreme but valid geometries.
fn geometries<T: Real>() -> Vec<Geometry<T>> {
    let f = T::from_f64;
    let tiny = f(1e-30);
    let huge = T::MAX;
    [
        (f(2.995), f(1.628), f(1.628), f(0.374), f(0.374)),
        (tiny, tiny, tiny, tiny, tiny),
        (huge, huge, huge, huge, huge),
        (tiny, huge, huge, tiny, huge),
        (huge, tiny, tiny, huge, tiny),
        (f(1.0), f(100.0), f(0.01), f(1e-20), f(1e20)),
    ]
    .into_iter()
    .map(|(l, tf, tr, rf, rr)| Geometry::new(l, tf, tr, rf, rr).unwrap())
    .collect()
}

fn finite<T: Real>(x: T, what: &str) {
    assert!(x.is_finite(), "{what} = {x}");
}

fn all_finite_for<T: Real>() {
    let values = specials::<T>();
    for g in geometries::<T>() {
        for &delta in &values {
            let ctx = |s: &str| format!("{s} for δ = {delta}, {g:?}");
            let a = g.wheel_angles(delta);
            finite(a.right, &ctx("right angle"));
            finite(a.left, &ctx("left angle"));
            assert!(
                a.right.abs() <= T::PI && a.left.abs() <= T::PI,
                "{}",
                ctx("angle range")
            );
            finite(effective_steering_angle(delta), &ctx("effective angle"));
            finite(g.central_angle_from_right(delta), &ctx("inverse right"));
            finite(g.central_angle_from_left(delta), &ctx("inverse left"));
            finite(
                g.steering_angle_for_curvature(delta),
                &ctx("curvature angle"),
            );
            finite(g.central_angle_from_wheel_angles(a), &ctx("inverse both"));
            match g.turning(delta) {
                Turning::Straight => {}
                Turning::Circle(r) => {
                    finite(r.rear_axle, &ctx("R"));
                    finite(r.front_virtual, &ctx("Rf"));
                    for w in r.wheels {
                        finite(w, &ctx("wheel radius"));
                    }
                    if let Some(k) = r.curvature() {
                        finite(k, &ctx("curvature"));
                    }
                }
            }
            let r = g.ackermann_ratios(delta);
            for x in [r.front, r.rear, r.central] {
                finite(x, &ctx("ratio"));
            }
            for &other in values.iter().step_by(3) {
                let r = g.differential_ratios(delta, WheelAngles::new(other, delta));
                for x in [r.front, r.rear, r.central] {
                    finite(x, &ctx("ratio with stored angles"));
                }
            }
        }
        let mut ratio_sets = vec![DifferentialRatios::EVEN];
        for &x in values.iter().step_by(2) {
            ratio_sets.push(DifferentialRatios::new(x, -x, x));
        }
        for &speed in &values {
            for &ratios in &ratio_sets {
                for drive in DriveType::ALL {
                    let t = g.wheel_speed_targets(speed, drive, ratios);
                    for w in Wheel::ALL {
                        assert_eq!(t[w].is_some(), drive.drives(w));
                        if let Some(omega) = t[w] {
                            finite(omega, &format!("target for v = {speed}, {ratios:?}"));
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn every_output_is_finite_f64() {
    all_finite_for::<f64>();
}

#[test]
fn every_output_is_finite_f32() {
    all_finite_for::<f32>();
}

fn odometry_state_stays_finite<T: Real>() {
    let values = specials::<T>();
    for g in geometries::<T>() {
        for source in [SpeedSource::RearWheels, SpeedSource::FrontWheels] {
            let mut odo = Odometry::new(g, source);
            for (i, &speed) in values.iter().enumerate() {
                for &steering in values.iter().step_by(2) {
                    let dt = values[(i * 7) % values.len()];
                    let _ = odo.update(PerWheel::splat(speed), steering, dt);
                    let p = odo.pose();
                    assert!(p.is_finite(), "{p:?}");
                    assert!(p.yaw > -T::PI && p.yaw <= T::PI, "{p:?}");
                    assert!(odo.distance().is_finite() && odo.distance() >= T::ZERO);
                    let v = odo.velocity();
                    assert!(v.forward.is_finite() && v.yaw_rate.is_finite());
                }
            }
        }
    }
}

#[test]
fn odometry_state_stays_finite_f64() {
    odometry_state_stays_finite::<f64>();
}

#[test]
fn odometry_state_stays_finite_f32() {
    odometry_state_stays_finite::<f32>();
}

fn bmw<T: Real>() -> Geometry<T> {
    let f = T::from_f64;
    Geometry::new(f(2.995), f(1.628), f(1.628), f(0.374), f(0.374)).unwrap()
}

#[test]
fn nan_steering_means_straight() {
    let g = bmw::<f64>();
    assert_eq!(g.wheel_angles(f64::NAN), WheelAngles::STRAIGHT);
    assert_eq!(g.turning(f64::NAN), Turning::Straight);
    assert_eq!(
        g.differential_ratios(f64::NAN, WheelAngles::new(0.3, 0.2)),
        DifferentialRatios::EVEN
    );
    assert_eq!(g.central_angle_from_right(f64::NAN), 0.0);
    assert_eq!(g.central_angle_from_left(f32::NAN as f64), 0.0);
    assert_eq!(g.steering_angle_for_curvature(f64::NAN), 0.0);
}

#[test]
fn steering_beyond_a_quarter_turn_is_the_pivot() {
    let g = bmw::<f64>();
    let pivot = g.wheel_angles(FRAC_PI_2);
    for delta in [1.6, 3.0, 1e10, f64::MAX, f64::INFINITY] {
        assert_eq!(g.wheel_angles(delta), pivot);
        assert_eq!(g.wheel_angles(-delta), pivot.mirrored());
        assert_eq!(g.ackermann_ratios(delta), g.ackermann_ratios(FRAC_PI_2));
    }
    // Pivot about the rear-axle centre: R = 0, the rear wheels at ∓Tr/2 = ∓0.814 m,
    // the front virtual wheel at L = 2.995 m, the front wheels at √(L² + 0.814²) = 3.103646404 m.
    let Turning::Circle(r) = g.turning(f64::INFINITY) else {
        panic!()
    };
    assert_eq!(r.rear_axle, 0.0);
    assert_eq!(r.curvature(), None);
    assert_eq!(r.front_virtual, 2.995);
    assert_eq!(r.wheels[Wheel::RearRight], -0.814);
    assert_eq!(r.wheels[Wheel::RearLeft], 0.814);
    assert!((r.wheels[Wheel::FrontRight] - 3.103_646_404).abs() < 1e-9);
    assert_eq!(r.wheels[Wheel::FrontRight], r.wheels[Wheel::FrontLeft]);
    // Rl + Rr = 0 at the pivot: the rear ratio is the documented 0.5; central = q/(1 + 0) = 1.
    let ratios = g.ackermann_ratios(FRAC_PI_2);
    assert_eq!(ratios.rear, 0.5);
    assert_eq!(ratios.central, 1.0);
    // f32's FRAC_PI_2 lies above π/2; it must still be the pivot, not a tiny left turn.
    let Turning::Circle(r32) = bmw::<f32>().turning(core::f32::consts::FRAC_PI_2) else {
        panic!()
    };
    assert_eq!(r32.rear_axle, 0.0);
    assert!(r32.wheels[Wheel::FrontRight] > 0.0);
}

#[test]
fn inverse_saturates_outside_the_reachable_range() {
    let g = bmw::<f64>();
    assert_eq!(g.central_angle_from_right(f64::INFINITY), FRAC_PI_2);
    assert_eq!(g.central_angle_from_left(f64::NEG_INFINITY), -FRAC_PI_2);
    // Outer-wheel lock is ±atan(2L/Tf) = ±1.305420 rad; beyond it there is no central angle.
    assert_eq!(g.central_angle_from_right(-1.5), -FRAC_PI_2);
    assert_eq!(g.central_angle_from_left(1.5), FRAC_PI_2);
    // Inner wheel max is π − 1.305420 = 1.836172 rad.
    assert_eq!(g.central_angle_from_right(2.5), FRAC_PI_2);
    // Round trip over the whole reachable range, including past the Webots flip.
    for i in -1570..=1570 {
        let delta = f64::from(i) * 1e-3;
        let a = g.wheel_angles(delta);
        assert!((g.central_angle_from_right(a.right) - delta).abs() < 1e-14);
        assert!((g.central_angle_from_left(a.left) - delta).abs() < 1e-14);
    }
}

#[test]
fn curvature_inverse() {
    let g = bmw::<f64>();
    assert_eq!(g.steering_angle_for_curvature(0.0), 0.0);
    assert_eq!(g.steering_angle_for_curvature(f64::INFINITY), FRAC_PI_2);
    assert_eq!(g.steering_angle_for_curvature(-f64::INFINITY), -FRAC_PI_2);
    for delta in [-1.2, -0.5, -0.01, 0.01, 0.2, 1.5] {
        let k = g.turning(delta).curvature().unwrap();
        assert!((g.steering_angle_for_curvature(k) - delta).abs() < 1e-15);
    }
}

#[test]
fn degenerate_front_ratio_is_even() {
    let g = bmw::<f64>();
    // Stored angles set directly to 0 while the driver's δ ≠ 0: Webots computes ∞/∞.
    assert_eq!(g.differential_ratios(0.3, WheelAngles::STRAIGHT).front, 0.5);
    // Toed wheels: Rl + Rr = 0.
    assert_eq!(
        g.differential_ratios(0.3, WheelAngles::new(0.1, -0.1))
            .front,
        0.5
    );
    assert_eq!(
        g.differential_ratios(0.3, WheelAngles::new(f64::NAN, 0.1))
            .front,
        0.5
    );
    // One straight wheel: Rr = ∞, so Rr/(Rl + Rr) → 1 (Webots: NaN).
    assert_eq!(
        g.differential_ratios(0.3, WheelAngles::new(0.0, 0.2)).front,
        1.0
    );
    // δ = 0 wins over the stored angles, as in Webots.
    assert_eq!(
        g.differential_ratios(0.0, WheelAngles::new(0.3, 0.2)),
        DifferentialRatios::EVEN
    );
}

#[test]
fn non_finite_targets_inputs() {
    let g = bmw::<f64>();
    let t = g.wheel_speed_targets(f64::NAN, DriveType::FourByFour, DifferentialRatios::EVEN);
    assert_eq!(t, PerWheel::splat(Some(0.0)));
    let t = g.wheel_speed_targets(f64::INFINITY, DriveType::Traction, DifferentialRatios::EVEN);
    assert_eq!(t[Wheel::FrontRight], Some(f64::MAX));
    let t = g.wheel_speed_targets(-f64::MAX, DriveType::Propulsion, DifferentialRatios::EVEN);
    assert_eq!(t[Wheel::RearLeft], Some(-f64::MAX));
    // NaN ratios count as 0.5: 2 · 1 m/s · 0.5 / 0.374 m = 2.673797 rad/s.
    let nan = DifferentialRatios::new(f64::NAN, f64::NAN, f64::NAN);
    let t = g.wheel_speed_targets(1.0, DriveType::FourByFour, nan);
    for w in Wheel::ALL {
        assert!((t[w].unwrap() - 1.0 / 0.374).abs() < 1e-12);
    }
}

#[test]
fn mirror_symmetry() {
    let g = bmw::<f64>();
    for i in -1700..=1700 {
        let delta = f64::from(i) * 1e-3;
        let (a, m) = (g.wheel_angles(delta), g.wheel_angles(-delta));
        assert_eq!(m, a.mirrored(), "δ = {delta}");

        match (g.turning(delta), g.turning(-delta)) {
            (Turning::Straight, Turning::Straight) => assert_eq!(delta, 0.0),
            (Turning::Circle(p), Turning::Circle(n)) => {
                assert_eq!(n.rear_axle, -p.rear_axle);
                assert_eq!(n.front_virtual, -p.front_virtual);
                for w in Wheel::ALL {
                    assert_eq!(n.wheels[w], -p.wheels[w.mirror()], "δ = {delta}, {w:?}");
                }
            }
            other => panic!("asymmetric {other:?}"),
        }

        let (r, s) = (g.ackermann_ratios(delta), g.ackermann_ratios(-delta));
        if delta.abs() < 1.5 {
            assert!((s.front - (1.0 - r.front)).abs() < 1e-14, "δ = {delta}");
            assert!((s.rear - (1.0 - r.rear)).abs() < 1e-14, "δ = {delta}");
        }
        assert_eq!(s.central, r.central);

        for drive in DriveType::ALL {
            let t = g.wheel_speed_targets(5.0, drive, r);
            let u = g.wheel_speed_targets(5.0, drive, s);
            for w in Wheel::ALL {
                if delta.abs() < 1.5 {
                    let (x, y) = (t[w].unwrap_or(0.0), u[w.mirror()].unwrap_or(0.0));
                    assert!((x - y).abs() < 1e-12, "δ = {delta}, {drive:?}, {w:?}");
                }
                assert_eq!(t[w].is_some(), u[w.mirror()].is_some());
            }
        }
    }
}

#[test]
fn f32_agrees_with_f64() {
    let (g32, g64) = (bmw::<f32>(), bmw::<f64>());
    for i in -2000..=2000 {
        let d32 = i as f32 * 1e-3;
        let d64 = f64::from(d32);
        let (a, b) = (g32.wheel_angles(d32), g64.wheel_angles(d64));
        assert!((f64::from(a.right) - b.right).abs() < 1e-5, "δ = {d64}");
        assert!((f64::from(a.left) - b.left).abs() < 1e-5, "δ = {d64}");
        let back = g32.central_angle_from_right(a.right);
        assert!((f64::from(back) - d64.clamp(-FRAC_PI_2, FRAC_PI_2)).abs() < 1e-5);
        if d64.abs() <= 1.2 {
            let (r, s) = (g32.ackermann_ratios(d32), g64.ackermann_ratios(d64));
            assert!((f64::from(r.front) - s.front).abs() < 1e-5, "δ = {d64}");
            assert!((f64::from(r.rear) - s.rear).abs() < 1e-5, "δ = {d64}");
            assert!((f64::from(r.central) - s.central).abs() < 1e-5, "δ = {d64}");
        }
    }
}

#[test]
fn ackermann_steering_matches_the_separate_calls() {
    // The one-pass evaluation takes sin δR, sin δL from the atan2 arguments; the angles must be
    // bit-identical to `wheel_angles` and the ratios equal to `differential_ratios` of those
    // angles to rounding (rear and central use the same sin δ, cos δ: bit-identical).
    let g = bmw::<f64>();
    for i in -1600..=1600 {
        let delta = f64::from(i) * 1e-3;
        let (angles, r) = g.ackermann_steering(delta);
        assert_eq!(angles, g.wheel_angles(delta), "δ = {delta}");
        let slow = g.differential_ratios(delta, angles);
        assert!((r.front - slow.front).abs() < 4e-16, "δ = {delta}");
        assert_eq!(
            (r.rear, r.central),
            (slow.rear, slow.central),
            "δ = {delta}"
        );
        assert_eq!(g.ackermann_ratios(delta), r);
    }
    let g32 = bmw::<f32>();
    for i in -1600..=1600 {
        let delta = i as f32 * 1e-3;
        let (angles, r) = g32.ackermann_steering(delta);
        assert_eq!(angles, g32.wheel_angles(delta), "δ = {delta}");
        let slow = g32.differential_ratios(delta, angles);
        assert!((r.front - slow.front).abs() < 2e-7, "δ = {delta}");
        assert_eq!(
            (r.rear, r.central),
            (slow.rear, slow.central),
            "δ = {delta}"
        );
    }
    // Degenerate inputs behave as the separate calls: NaN and 0 steer straight with an even
    // split, ±∞ is the pivot.
    for delta in [
        0.0,
        -0.0,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        1e-300,
    ] {
        let (angles, r) = g.ackermann_steering(delta);
        assert_eq!(angles, g.wheel_angles(delta));
        assert_eq!(r, g.differential_ratios(delta, angles), "δ = {delta}");
    }
    // A track 10¹⁰ wheelbases wide: at δ = 0.3, k·sin δ overflows the fast root and the sines
    // of the angles are used, as in `differential_ratios`.
    let wide = Geometry::new(1e-300_f64, 1e10, 1.0, 0.3, 0.3).unwrap();
    for delta in [0.3, -1.0] {
        let (angles, r) = wide.ackermann_steering(delta);
        assert_eq!(r, wide.differential_ratios(delta, angles), "δ = {delta}");
    }
    // At δ = 1e-300, k·sin δ = 1e10·1e-300/2e-300 = 5e9: the inner wheel's angle rounds to π,
    // whose sine (1.2e-16) is not the 2e-310 of the geometry, so only the one-pass form gives
    // the true split (5e9 − 1)/((5e9 − 1) + (5e9 + 1)) = 0.4999999999.
    let (_, r) = wide.ackermann_steering(1e-300);
    assert!((r.front - 0.499_999_999_9).abs() < 1e-14, "{r:?}");
}
