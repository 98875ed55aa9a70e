//! Odometry against analytic lines and circles.

#![allow(clippy::unwrap_used)] // test helpers may unwrap

use ackermann::{
    DriveType, Geometry, Odometry, OdometryWarning, PerWheel, Pose, SpeedSource, Velocity, Wheel,
};
use core::f64::consts::{FRAC_PI_2, PI, TAU};

const L: f64 = 2.995;
const TRACK: f64 = 1.628;
const RADIUS: f64 = 0.374;

fn bmw_x5() -> Geometry<f64> {
    Geometry::new(L, TRACK, TRACK, RADIUS, RADIUS).unwrap()
}

/// No-slip wheel angular speeds (rad/s) for rear-axle speed `v` (m/s) and central angle δ
/// (rad, δ ≠ 0, |δ| < π/2), from first principles: the centre is at (0, −R), R = L/tan δ, every
/// point moves at v·(its distance)/R.
fn kinematic_wheel_speeds(v: f64, delta: f64) -> PerWheel<f64> {
    let r = L / delta.tan();
    let h = TRACK / 2.0;
    let front = |y: f64| delta.signum() * (L * L + (r + y) * (r + y)).sqrt();
    PerWheel::new(front(-h), front(h), r - h, r + h).map(|radius| v * radius / r / RADIUS)
}

/// Pose after driving `s` metres (signed) from the origin at central angle δ (rad).
fn analytic_pose(s: f64, delta: f64) -> Pose<f64> {
    let r = L / delta.tan();
    let phi = s / r; // clockwise angle swept about (0, −R)
    Pose::new(r * phi.sin(), -r * (1.0 - phi.cos()), wrap(-phi))
}

fn wrap(a: f64) -> f64 {
    let r = a % TAU;
    if r > PI {
        r - TAU
    } else if r <= -PI {
        r + TAU
    } else {
        r
    }
}

#[track_caller]
fn pose_close(p: Pose<f64>, q: Pose<f64>, tol: f64) {
    let dyaw = wrap(p.yaw - q.yaw).abs();
    assert!(
        (p.x - q.x).abs() < tol && (p.y - q.y).abs() < tol && dyaw < tol,
        "{p:?} vs {q:?}"
    );
}

#[test]
fn straight_line() {
    // 100 steps of 0.01 s at 12 rad/s on a 0.374 m tyre: 12·0.374 = 4.488 m/s for 1 s.
    for source in [SpeedSource::RearWheels, SpeedSource::FrontWheels] {
        let mut odo = Odometry::new(bmw_x5(), source);
        for _ in 0..100 {
            odo.update(PerWheel::splat(12.0), 0.0, 0.01).unwrap();
        }
        pose_close(odo.pose(), Pose::new(4.488, 0.0, 0.0), 1e-12);
        assert!((odo.distance() - 4.488).abs() < 1e-12);
        assert_eq!(odo.velocity(), Velocity::new(12.0 * RADIUS, 0.0));
    }
}

#[test]
fn line_from_a_rotated_start() {
    // Heading 3π/4 at (1, 2), 2 m/s for 3 s: (1 − 6/√2, 2 + 6/√2) = (−3.242641, 6.242641).
    let mut odo = Odometry::new(bmw_x5(), SpeedSource::RearWheels);
    odo.reset(Pose::new(1.0, 2.0, 0.75 * PI)).unwrap();
    odo.update(PerWheel::splat(2.0 / RADIUS), 0.0, 3.0).unwrap();
    pose_close(
        odo.pose(),
        Pose::new(-3.242_640_687_119_285, 6.242_640_687_119_285, 0.75 * PI),
        1e-12,
    );
}

#[test]
fn circles_close_and_follow_the_analytic_arc() {
    // δ = ±0.5 rad: R = 2.995/tan 0.5 = 5.482311 m; at v = 5 m/s one lap takes
    // 2π·5.482311/5 = 6.889292 s. Any step size must land exactly on the circle.
    for source in [SpeedSource::RearWheels, SpeedSource::FrontWheels] {
        for delta in [0.5_f64, -0.5, 0.05, -1.2] {
            for v in [5.0_f64, -3.0] {
                let r = L / f64::tan(delta);
                let lap = TAU * r.abs() / v.abs();
                for steps in [1_u32, 3, 7, 100, 1000] {
                    let dt = lap / f64::from(steps);
                    let mut odo = Odometry::new(bmw_x5(), source);
                    let speeds = kinematic_wheel_speeds(v, delta);
                    for i in 1..=steps {
                        odo.update(speeds, delta, dt).unwrap();
                        let expected = analytic_pose(v * dt * f64::from(i), delta);
                        pose_close(odo.pose(), expected, 1e-9 * r.abs().max(1.0));
                    }
                    pose_close(odo.pose(), Pose::ORIGIN, 1e-9 * r.abs().max(1.0));
                    assert!((odo.distance() - TAU * r.abs()).abs() < 1e-9 * r.abs());
                    let yaw_rate = -v * delta.tan() / L;
                    assert!((odo.velocity().yaw_rate - yaw_rate).abs() < 1e-12);
                    assert!((odo.velocity().forward - v).abs() < 1e-12);
                }
            }
        }
    }
}

#[test]
fn right_turn_goes_right() {
    // Quarter lap at δ = 0.5: from the origin to (R, −R) = (5.482311, −5.482311), yaw −π/2.
    let r = L / 0.5_f64.tan();
    let mut odo = Odometry::new(bmw_x5(), SpeedSource::RearWheels);
    let quarter = FRAC_PI_2 * r / 5.0;
    odo.update(kinematic_wheel_speeds(5.0, 0.5), 0.5, quarter)
        .unwrap();
    pose_close(odo.pose(), Pose::new(r, -r, -FRAC_PI_2), 1e-12);
    assert!((r - 5.482_310_726_528_794).abs() < 1e-12);
}

#[test]
fn pivot_turns_on_the_spot() {
    // δ = π/2: the rear-axle centre stays put; a front wheel at √(L² + (Tr/2)²) = 3.103646 m
    // from it rolling at 1 m/s turns the car clockwise at 1/3.103646 rad/s.
    let front = (L * L + 0.814 * 0.814_f64).sqrt();
    let yaw_rate = -1.0 / front;
    let rear = 0.814 / front; // rear wheels' ground speed (m/s), opposite directions
    let speeds = PerWheel::new(1.0, 1.0, -rear, rear).map(|v| v / RADIUS);
    for source in [SpeedSource::RearWheels, SpeedSource::FrontWheels] {
        let mut odo = Odometry::new(bmw_x5(), source);
        odo.update(speeds, FRAC_PI_2, 1.0).unwrap();
        let v = odo.velocity();
        assert!(v.forward.abs() < 1e-15, "{source:?} {v:?}");
        assert!((v.yaw_rate - yaw_rate).abs() < 1e-15, "{source:?} {v:?}");
        pose_close(odo.pose(), Pose::new(0.0, 0.0, yaw_rate), 1e-15);
    }
}

#[test]
fn yaw_stays_wrapped() {
    let mut odo = Odometry::new(bmw_x5(), SpeedSource::RearWheels);
    let speeds = kinematic_wheel_speeds(10.0, -1.0);
    for _ in 0..10_000 {
        let p = odo.update(speeds, -1.0, 0.1).unwrap();
        assert!(p.yaw > -PI && p.yaw <= PI);
    }
    // 10 000 steps · 0.1 s · yaw rate 10·tan(1)/L = 5.199922 rad/s = 5199.922 rad in total.
    let total: f64 = 10.0 * 1.0_f64.tan() / L * 1000.0;
    assert!((odo.pose().yaw - wrap(total)).abs() < 1e-9);
}

#[test]
fn bad_steps_are_ignored() {
    let mut odo = Odometry::new(bmw_x5(), SpeedSource::RearWheels);
    odo.update(PerWheel::splat(1.0), 0.1, 0.5).unwrap();
    let before = odo;
    let mut nan_rear = PerWheel::splat(1.0);
    nan_rear[Wheel::RearLeft] = f64::NAN;
    assert!(matches!(
        odo.update(nan_rear, 0.1, 0.1),
        Err(OdometryWarning::NonFiniteWheelSpeed { wheel: Wheel::RearLeft, value }) if value.is_nan()
    ));
    assert_eq!(
        odo.update(PerWheel::splat(1.0), f64::INFINITY, 0.1),
        Err(OdometryWarning::NonFiniteSteering {
            value: f64::INFINITY
        })
    );
    assert_eq!(
        odo.update(PerWheel::splat(1.0), 0.1, -0.1),
        Err(OdometryWarning::InvalidTimeStep { value: -0.1 })
    );
    assert_eq!(
        odo.update(PerWheel::splat(f64::MAX), 0.0, f64::MAX),
        Err(OdometryWarning::Overflow)
    );
    assert!(matches!(
        odo.integrate(Velocity::new(f64::NAN, 0.0), 0.1),
        Err(OdometryWarning::NonFiniteVelocity { .. })
    ));
    assert_eq!(
        odo.reset(Pose::new(f64::NAN, 0.0, 0.0)),
        Err(OdometryWarning::Overflow)
    );
    assert_eq!(odo, before);
    // A NaN on a wheel the source does not read is irrelevant.
    let mut nan_front = PerWheel::splat(1.0);
    nan_front[Wheel::FrontRight] = f64::NAN;
    odo.update(nan_front, 0.0, 0.0).unwrap();
    assert_eq!(odo.pose(), before.pose());
}

#[test]
fn source_for_drive_is_the_undriven_axle() {
    assert_eq!(
        SpeedSource::for_drive(DriveType::Traction),
        SpeedSource::RearWheels
    );
    assert_eq!(
        SpeedSource::for_drive(DriveType::Propulsion),
        SpeedSource::FrontWheels
    );
    assert_eq!(
        SpeedSource::for_drive(DriveType::FourByFour),
        SpeedSource::RearWheels
    );
}

#[test]
fn f32_circle_closes() {
    // Same lap as above in f32, 1000 steps: rounding only, well under a millimetre.
    let g = Geometry::new(2.995_f32, 1.628, 1.628, 0.374, 0.374).unwrap();
    let mut odo = Odometry::new(g, SpeedSource::RearWheels);
    let speeds = kinematic_wheel_speeds(5.0, 0.5).map(|w| w as f32);
    let lap = (TAU * (L / 0.5_f64.tan()) / 5.0) as f32;
    for _ in 0..1000 {
        odo.update(speeds, 0.5, lap / 1000.0).unwrap();
    }
    let p = odo.pose();
    assert!(
        p.x.abs() < 1e-3 && p.y.abs() < 1e-3 && p.yaw.abs() < 1e-3,
        "{p:?}"
    );
}
