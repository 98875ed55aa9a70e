//! DifferentialWheels: analytic poses in kinematics mode (exact) and physics mode (within 5 %),
//! encoders, sampling, speed clamping and seeded noise.

// Helpers outside `#[test]` functions unwrap too: clippy.toml only exempts test bodies.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::{
    DifferentialWheelsParams, RobotBody, RobotId, RobotMode, RobotPlacement, RobotWarning, World,
    WorldConfig,
};

fn noiseless() -> DifferentialWheelsParams {
    DifferentialWheelsParams {
        slip_noise: 0.0,
        encoder_noise: 0.0,
        encoder_resolution: 100.0,
        ..DifferentialWheelsParams::default()
    }
}

fn world_with(params: DifferentialWheelsParams, mode: RobotMode) -> (World, RobotId) {
    let mut w = World::new(WorldConfig::default()).unwrap();
    let id = w
        .add_differential_wheels(params, mode, RobotPlacement::default())
        .unwrap();
    (w, id)
}

/// Sum over `steps` steps of the acceleration-limited speed min(a·dt·k, v) (rad/s): the
/// kinematics ramp seen from rest, times dt gives the wheel rotation (rad).
fn ramp_rotation(v: f64, a: f64, dt: f64, steps: usize) -> f64 {
    let mut actual = 0.0_f64;
    let mut sum = 0.0;
    for _ in 0..steps {
        actual = (actual + a * dt).min(v);
        sum += actual * dt;
    }
    sum
}

#[test]
fn kinematics_straight_line_is_exact() {
    let (mut w, id) = world_with(noiseless(), RobotMode::Kinematics);
    w.robot_mut(id).unwrap().set_speed(5.0, 5.0);
    for _ in 0..200 {
        w.step().unwrap();
    }
    // 50 ramp steps of +0.1 rad/s then 150 steps at 5 rad/s:
    // Σ speed·dt = 0.01·(0.1·1275 + 150·5) = 8.775 rad of wheel rotation.
    let turned = ramp_rotation(5.0, 10.0, 0.01, 200);
    assert!((turned - 8.775).abs() < 1e-12);
    let r = w.robot(id).unwrap();
    let pose = r.pose();
    // Distance = rotation × wheelRadius 0.01 = 0.08775 m, straight along +x.
    assert!((pose.position.x - 0.08775).abs() < 1e-12, "{pose:?}");
    assert_eq!(pose.position.y, 0.0);
    assert_eq!(pose.heading, 0.0);
    // encoderResolution 100 per rad: 877.5 increments on each wheel.
    for e in r.raw_encoders() {
        assert!((e - 877.5).abs() < 1e-9, "{e}");
    }
    assert_eq!(r.wheel_angles(), [turned, turned]);
}

#[test]
fn kinematics_spin_in_place_is_exact() {
    let (mut w, id) = world_with(noiseless(), RobotMode::Kinematics);
    w.robot_mut(id).unwrap().set_speed(-3.0, 3.0);
    for _ in 0..300 {
        w.step().unwrap();
    }
    // Heading rate (n_R − n_L)·r/axle: total = 2·rotation·0.01/0.1.
    let turned = ramp_rotation(3.0, 10.0, 0.01, 300);
    let pose = w.robot(id).unwrap().pose();
    assert!((pose.heading - 2.0 * turned * 0.01 / 0.1).abs() < 1e-12);
    assert_eq!((pose.position.x, pose.position.y), (0.0, 0.0));
    let [l, r] = w.robot(id).unwrap().raw_encoders();
    assert!((l + 100.0 * turned).abs() < 1e-9 && (r - 100.0 * turned).abs() < 1e-9);
}

#[test]
fn kinematics_arc_ends_on_the_analytic_circle() {
    // Constant wheel speeds from the start (huge acceleration): a circle of radius
    // R = axle/2·(n_R + n_L)/(n_R − n_L) = 0.05·(4 + 2)/(4 − 2) = 0.15 m, turning at
    // ω = (n_R − n_L)·r/axle = 0.2 rad/s. Midpoint integration moves each step along the
    // chord direction by the arc length 2RΔ instead of the chord 2R·sin Δ (Δ = 0.001 rad):
    // the error after 1000 steps is about 1000·R·Δ³/3 = 5e-8 m.
    let params = DifferentialWheelsParams {
        max_acceleration: 1e9,
        ..noiseless()
    };
    let (mut w, id) = world_with(params, RobotMode::Kinematics);
    w.robot_mut(id).unwrap().set_speed(2.0, 4.0);
    for _ in 0..1000 {
        w.step().unwrap();
    }
    let pose = w.robot(id).unwrap().pose();
    let theta = 0.2 * 10.0;
    assert!((pose.heading - theta).abs() < 1e-12);
    // Centre at (0, R): position = (R sin θ, R (1 − cos θ)).
    assert!(
        (pose.position.x - 0.15 * theta.sin()).abs() < 1e-7,
        "{pose:?}"
    );
    assert!((pose.position.y - 0.15 * (1.0 - theta.cos())).abs() < 1e-7);
}

#[test]
fn speed_commands_clamp_and_warn_like_webots() {
    let (mut w, id) = world_with(noiseless(), RobotMode::Kinematics);
    let r = w.robot_mut(id).unwrap();
    assert!(r.left_speed().is_nan());
    assert_eq!(
        r.set_speed(f64::NAN, 1.0),
        Some(RobotWarning::InvalidNan {
            function: "wb_differential_wheels_set_speed"
        })
    );
    assert!(r.left_speed().is_nan());
    // ±∞ is refused like NaN (as the driver library's setters refuse it), naming the argument.
    let warning = r.set_speed(1.0, f64::NEG_INFINITY).unwrap();
    assert_eq!(
        warning.to_string(),
        "wb_differential_wheels_set_speed() called with an invalid 'right' argument (-inf)"
    );
    assert!(r.left_speed().is_nan() && r.right_speed().is_nan());
    assert!(r.set_encoders(f64::INFINITY, 0.0).is_some());
    let warning = r.set_speed(20.0, -30.0).unwrap();
    assert_eq!(
        warning.to_string(),
        "wb_differential_wheels_set_speed(20,-30) overflows maxSpeed/speedUnit: 10/1=10."
    );
    assert_eq!((r.left_speed(), r.right_speed()), (20.0, -30.0));
    // Only the positive side is checked, as in Webots.
    assert_eq!(r.set_speed(-30.0, 10.0), None);
    r.set_speed(20.0, -30.0);
    w.step().unwrap();
    assert_eq!(w.robot(id).unwrap().targets(), [10.0, -10.0]);
}

#[test]
fn speed_unit_scales_commands() {
    let params = DifferentialWheelsParams {
        speed_unit: 0.1,
        ..noiseless()
    };
    let (mut w, id) = world_with(params, RobotMode::Kinematics);
    w.robot_mut(id).unwrap().set_speed(30.0, -50.0);
    w.step().unwrap();
    // 30·0.1 = 3 rad/s, −50·0.1 = −5 rad/s.
    assert_eq!(w.robot(id).unwrap().targets(), [3.0, -5.0]);
    assert_eq!(w.robot(id).unwrap().speed_unit(), 0.1);
}

#[test]
fn encoders_are_sampled_at_their_period() {
    let (mut w, id) = world_with(noiseless(), RobotMode::Kinematics);
    let r = w.robot_mut(id).unwrap();
    r.set_speed(1.0, 1.0);
    assert_eq!(
        r.enable_encoders(-5),
        Some(RobotWarning::NegativePeriod { period_ms: -5 })
    );
    assert_eq!(r.encoders_sampling_period(), 0);
    assert_eq!(r.enable_encoders(50), None);
    assert_eq!(r.encoders_sampling_period(), 50);
    for step in 1..=12 {
        w.step().unwrap();
        let r = w.robot(id).unwrap();
        // Samples at 50 ms and 100 ms only.
        let expected = if step < 5 {
            0.0
        } else if step < 10 {
            ramp_rotation(1.0, 10.0, 0.01, 5) * 100.0
        } else {
            ramp_rotation(1.0, 10.0, 0.01, 10) * 100.0
        };
        assert!((r.left_encoder() - expected).abs() < 1e-9, "step {step}");
    }
    let r = w.robot_mut(id).unwrap();
    r.disable_encoders();
    assert_eq!(r.encoders_sampling_period(), 0);
    assert!(r.set_encoders(f64::NAN, 0.0).is_some());
    assert_eq!(r.set_encoders(-7.0, 3.0), None);
    w.step().unwrap();
    let r = w.robot(id).unwrap();
    // The overwrite happens before this step's increment: 1 rad/s·0.01 s·100 = 1.
    assert!((r.raw_encoders()[0] - (-7.0 + 1.0)).abs() < 1e-12);
    assert!((r.raw_encoders()[1] - (3.0 + 1.0)).abs() < 1e-12);
}

#[test]
fn no_encoders_when_encoder_noise_is_minus_one() {
    let params = DifferentialWheelsParams {
        encoder_noise: -1.0,
        ..noiseless()
    };
    let (mut w, id) = world_with(params, RobotMode::Kinematics);
    w.robot_mut(id).unwrap().set_speed(5.0, 5.0);
    w.step().unwrap();
    assert_eq!(w.robot(id).unwrap().raw_encoders(), [0.0, 0.0]);
}

#[test]
fn slip_noise_is_bounded_and_seeded() {
    let run = |seed: u64| {
        let params = DifferentialWheelsParams {
            slip_noise: 0.1,
            encoder_noise: 0.05,
            seed,
            max_acceleration: 1e9,
            ..noiseless()
        };
        let (mut w, id) = world_with(params, RobotMode::Kinematics);
        w.robot_mut(id).unwrap().set_speed(5.0, 5.0);
        for _ in 0..100 {
            w.step().unwrap();
        }
        let r = w.robot(id).unwrap();
        (r.pose(), r.raw_encoders())
    };
    let (a, ea) = run(1);
    let (b, eb) = run(1);
    let (c, _) = run(2);
    assert_eq!((a, ea), (b, eb));
    assert_ne!(a, c);
    // Noiseless distance 5 rad/s·1 s·0.01 m = 0.05 m; each step's speed is within ±10 %.
    let d = a.position.x.hypot(a.position.y);
    assert!((0.045..0.055).contains(&d), "{d}");
    assert!(a.heading != 0.0);
    // Encoders: rotation 5 rad·100 within ±(10 % slip)·(5 % encoder noise).
    for e in ea {
        assert!((500.0 * 0.9 * 0.95..500.0 * 1.1 * 1.05).contains(&e), "{e}");
    }
}

fn physics_robot() -> (DifferentialWheelsParams, RobotMode) {
    let params = DifferentialWheelsParams {
        wheel_radius: 0.05,
        axle_length: 0.3,
        max_force: 2.0,
        ..noiseless()
    };
    let body = RobotBody {
        body_mass: 2.0,
        wheel_mass: 0.2,
        wheel_width: 0.03,
    };
    (params, RobotMode::Physics(body))
}

#[test]
fn physics_straight_line_within_5_percent() {
    let (params, mode) = physics_robot();
    let (mut w, id) = world_with(params, mode);
    for _ in 0..20 {
        w.step().unwrap(); // settle on the ground
    }
    let start = w.robot(id).unwrap().pose();
    w.robot_mut(id).unwrap().set_speed(4.0, 4.0);
    for _ in 0..300 {
        w.step().unwrap();
    }
    let r = w.robot(id).unwrap();
    let pose = r.pose();
    // v = ω·r = 4·0.05 = 0.2 m/s for 3 s: 0.6 m along +x.
    let dx = pose.position.x - start.position.x;
    assert!((dx - 0.6).abs() < 0.03, "{dx}");
    assert!((pose.position.y - start.position.y).abs() < 0.03);
    assert!((pose.heading - start.heading).abs() < 0.05);
    // Encoders count 100 per radian of hinge rotation: 4 rad/s·3 s = 12 rad → 1200.
    for (e, a) in r.raw_encoders().into_iter().zip(r.wheel_angles()) {
        assert!((e - 100.0 * a).abs() < 1e-6);
        assert!((e - 1200.0).abs() < 60.0, "{e}");
    }
    assert!((r.wheel_speeds()[0] - 4.0).abs() < 0.01);
}

#[test]
fn physics_spin_in_place_within_5_percent() {
    let (params, mode) = physics_robot();
    let (mut w, id) = world_with(params, mode);
    for _ in 0..20 {
        w.step().unwrap();
    }
    let start = w.robot(id).unwrap().pose();
    w.robot_mut(id).unwrap().set_speed(-2.0, 2.0);
    for _ in 0..300 {
        w.step().unwrap();
    }
    let pose = w.robot(id).unwrap().pose();
    // Yaw rate (n_R − n_L)·r/axle = 4·0.05/0.3 = 0.6667 rad/s for 3 s: 2 rad.
    let turned = pose.heading - start.heading;
    assert!((turned - 2.0).abs() < 0.1, "{turned}");
    let moved = (pose.position.x - start.position.x).hypot(pose.position.y - start.position.y);
    assert!(moved < 0.01, "{moved}");
}

#[test]
fn physics_with_webots_default_fields_moves_forward() {
    // Webots defaults: 1 cm wheels 10 cm apart, maxForce 0.3 N·m.
    let (mut w, id) = world_with(noiseless(), RobotMode::Physics(RobotBody::default()));
    for _ in 0..20 {
        w.step().unwrap();
    }
    let x0 = w.robot(id).unwrap().pose().position.x;
    w.robot_mut(id).unwrap().set_speed(10.0, 10.0);
    for _ in 0..100 {
        w.step().unwrap();
    }
    // 10 rad/s·0.01 m·1 s = 0.1 m.
    let dx = w.robot(id).unwrap().pose().position.x - x0;
    assert!((dx - 0.1).abs() < 0.005, "{dx}");
}
