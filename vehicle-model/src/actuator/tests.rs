use super::*;

fn r<T: Real>(v: f64) -> T {
    T::from_f64(v)
}

fn ramp_rules<T: Real>() {
    let mut ramp = VelocityRamp::<T>::default();
    assert_eq!(ramp.command(), r(0.0));
    // 4 rad/s² × 0.25 s = 1 rad/s per step toward 2.5 rad/s: 1, 2, then 2.5 exactly.
    assert_eq!(ramp.step(r(2.5), r(4.0), r(100.0), r(0.25)), r(1.0));
    assert_eq!(ramp.step(r(2.5), r(4.0), r(100.0), r(0.25)), r(2.0));
    assert_eq!(ramp.step(r(2.5), r(4.0), r(100.0), r(0.25)), r(2.5));
    assert_eq!(ramp.step(r(2.5), r(4.0), r(100.0), r(0.25)), r(2.5));
    // Down toward −2.5, clamped first to ±|−1.5| = ±1.5: 2.5 → 1.5 → 0.5 → −0.5 → −1.5.
    for expected in [1.5, 0.5, -0.5, -1.5, -1.5] {
        assert_eq!(ramp.step(r(-2.5), r(4.0), r(-1.5), r(0.25)), r(expected));
    }
    assert_eq!(ramp.command(), r(-1.5));
}

fn ramp_bad_input<T: Real>() {
    let nan = r::<T>(f64::NAN);
    let inf = T::INFINITY;
    let mut ramp = VelocityRamp::starting_at(r::<T>(3.0));
    // A non-finite target keeps the command.
    assert_eq!(ramp.step(nan, r(1.0), r(10.0), r(0.5)), r(3.0));
    assert_eq!(ramp.step(inf, r(1.0), r(10.0), r(0.5)), r(3.0));
    assert_eq!(ramp.step(-inf, r(1.0), r(10.0), r(0.5)), r(3.0));
    // Non-positive or non-finite acceleration: no limit.
    assert_eq!(ramp.step(r(7.0), r(-1.0), r(10.0), r(0.5)), r(7.0));
    assert_eq!(ramp.step(r(-6.0), r(0.0), r(10.0), r(0.5)), r(-6.0));
    assert_eq!(ramp.step(r(8.0), nan, r(10.0), r(0.5)), r(8.0));
    assert_eq!(ramp.step(r(9.0), inf, r(10.0), r(0.5)), r(9.0));
    // Non-finite max_velocity: no clamp.
    assert_eq!(ramp.step(r(40.0), r(-1.0), inf, r(0.5)), r(40.0));
    assert_eq!(ramp.step(r(-40.0), r(-1.0), nan, r(0.5)), r(-40.0));
    // A NaN or non-positive dt cannot limit the step: the target is reached.
    assert_eq!(ramp.step(r(1.0), r(2.0), r(10.0), nan), r(1.0));
    assert_eq!(ramp.step(r(2.0), r(2.0), r(10.0), r(0.0)), r(2.0));
    assert_eq!(ramp.command(), r(2.0));
    // −MAX − MAX overflows to −∞, and so does a step of MAX·2: the target is taken.
    let mut huge = VelocityRamp::starting_at(T::MAX);
    assert_eq!(huge.step(-T::MAX, T::MAX, inf, r(2.0)), -T::MAX);
}

fn servo_rules<T: Real>() {
    let servo = PositionServo::<T>::steering(r(-0.5), r(0.25));
    assert_eq!(servo.gain, r(10.0));
    assert_eq!(servo.max_velocity, r(10.0));
    // 10·(0.125 − 0) = 1.25 rad/s.
    assert_eq!(servo.velocity(r(0.125), r(0.0)), r(1.25));
    // Target clamped to 0.25: 10·(0.25 − 0.5) = −2.5 rad/s.
    assert_eq!(servo.velocity(r(3.0), r(0.5)), r(-2.5));
    // 10·(−0.5 − 1) = −15, capped at −10 rad/s.
    assert_eq!(servo.velocity(r(-1.0), r(1.0)), r(-10.0));
    assert_eq!(servo.clamp_target(r(-2.0), r(0.0)), r(-0.5));
    assert_eq!(servo.clamp_target(r(0.125), r(0.0)), r(0.125));
}

fn servo_bad_input<T: Real>() {
    let servo = PositionServo::<T>::steering(r(-0.5), r(0.5));
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        // Hold: the target becomes the position, and the command is 0.
        assert_eq!(servo.clamp_target(r(bad), r(0.375)), r(0.375));
        assert_eq!(servo.velocity(r(bad), r(0.375)), r(0.0));
    }
    // An infinite gain times a zero error is NaN: no command.
    let wild = PositionServo {
        gain: T::INFINITY,
        ..servo
    };
    assert_eq!(wild.velocity(r(0.25), r(0.25)), r(0.0));
    assert_eq!(wild.velocity(r(0.25), r(0.0)), r(0.0));
}

fn steering_rules<T: Real>() {
    // 10 N·m on 4 kg·m², 0.125 s steps: the rate changes by at most 0.3125 rad/s a step.
    let motor = SteeringMotor {
        servo: PositionServo::<T>::steering(r(-0.5), r(0.5)),
        max_torque: r(10.0),
        inertia: r(4.0),
    };
    let dt = r::<T>(0.125);
    // Command 10·(0.25 − 0) = 2.5 rad/s; rate 0 → 0.3125; angle 0.3125·0.125 = 0.0390625.
    let s = motor.step(SteeringState::default(), r(0.25), dt);
    assert_eq!(
        s,
        SteeringState {
            angle: r(0.0390625),
            rate: r(0.3125)
        }
    );
    // Unlimited torque: the rate is the command, 10·(0.25 − 0.0390625) = 2.109375 rad/s,
    // and the angle 0.0390625 + 2.109375·0.125 = 0.302734375 overshoots nothing.
    let strong = SteeringMotor {
        max_torque: T::INFINITY,
        ..motor
    };
    let s = strong.step(s, r(0.25), dt);
    assert_eq!(s.rate, r(2.109375));
    assert_eq!(s.angle, r(0.302734375));
    // At 0.375 rad turning at 2 rad/s toward 0.5: command 10·0.125 = 1.25, reached;
    // 0.375 + 1.25·0.125 = 0.53125 passes the 0.5 stop: clamped, rate 0.
    let s = strong.step(
        SteeringState {
            angle: r(0.375),
            rate: r(2.0),
        },
        r(1.0),
        dt,
    );
    assert_eq!(
        s,
        SteeringState {
            angle: r(0.5),
            rate: r(0.0)
        }
    );
    // Turning left at 8 rad/s from 0.5 rad with the target reached (command 0): the
    // 0.3125 rad/s limit still binds, −7.6875 rad/s; 0.5 − 7.6875·0.125 = −0.4609375 rad.
    let s = motor.step(
        SteeringState {
            angle: r(0.5),
            rate: r(-8.0),
        },
        r(0.5),
        dt,
    );
    assert_eq!(
        s,
        SteeringState {
            angle: r(-0.4609375),
            rate: r(-7.6875)
        }
    );
}

fn steering_bad_input<T: Real>() {
    let motor = SteeringMotor {
        servo: PositionServo::<T>::steering(r(-0.5), r(0.5)),
        max_torque: r(10.0),
        inertia: r(4.0),
    };
    let start = SteeringState {
        angle: r(0.25),
        rate: r(0.0),
    };
    // A non-finite target holds the angle.
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(motor.step(start, r(bad), r(0.125)), start);
    }
    // Bad dt: nothing moves.
    for bad in [f64::NAN, f64::INFINITY, 0.0, -0.125] {
        assert_eq!(motor.step(start, r(0.0), r(bad)), start);
    }
    // 0 N·m on a massless wheel is 0/0: the rate cannot change, the wheel stays.
    let stuck = SteeringMotor {
        max_torque: r(0.0),
        inertia: r(0.0),
        ..motor
    };
    assert_eq!(stuck.step(start, r(-0.5), r(0.125)), start);
    // A negative torque limit counts as 0 too.
    let negative = SteeringMotor {
        max_torque: r(-10.0),
        ..motor
    };
    assert_eq!(negative.step(start, r(-0.5), r(0.125)), start);
    // A positive torque on a massless wheel is unlimited: rate 10·(0 − 0.25) = −2.5 rad/s.
    let massless = SteeringMotor {
        inertia: r(0.0),
        ..motor
    };
    assert_eq!(
        massless.step(start, r(0.0), r(0.125)),
        SteeringState {
            angle: r(-0.0625),
            rate: r(-2.5)
        }
    );
}

fn spin_rules<T: Real>() {
    let wheel = WheelSpin {
        inertia: r::<T>(2.0),
        damping: r(4.0),
    };
    // (10 + 8·0.5/2) / (1 + 4·0.5/2) = 6 rad/s.
    assert_eq!(wheel.step(r(10.0), r(8.0), r(0.5)), r(6.0));
    // Free: (−6 + 0) / 2 = −3 rad/s; damping never reverses the spin.
    assert_eq!(wheel.step(r(-6.0), r(0.0), r(0.5)), r(-3.0));
    // Undamped: 1 + 100·0.25/2 = 13.5 rad/s.
    let bare = WheelSpin {
        damping: r(0.0),
        ..wheel
    };
    assert_eq!(bare.step(r(1.0), r(100.0), r(0.25)), r(13.5));
    // The drive torque is clamped to 1e8 N·m: 1e8·0.5/5e7 = 1 rad/s.
    let heavy = WheelSpin {
        inertia: r::<T>(5e7),
        damping: r(0.0),
    };
    assert_eq!(heavy.step(r(0.0), r(1e12), r(0.5)), r(1.0));
    assert_eq!(heavy.step(r(0.0), r(-1e12), r(0.5)), r(-1.0));
}

fn spin_bad_input<T: Real>() {
    let wheel = WheelSpin {
        inertia: r::<T>(2.0),
        damping: r(4.0),
    };
    // A non-finite torque counts as 0: (6 + 0) / 2 = 3 rad/s.
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(wheel.step(r(6.0), r(bad), r(0.5)), r(3.0));
    }
    // Bad dt: the spin is kept.
    for bad in [f64::NAN, f64::INFINITY, 0.0, -0.5] {
        assert_eq!(wheel.step(r(6.0), r(8.0), r(bad)), r(6.0));
    }
    // Bad inertia: kept.
    for bad in [f64::NAN, 0.0, -2.0] {
        let w = WheelSpin {
            inertia: r(bad),
            ..wheel
        };
        assert_eq!(w.step(r(6.0), r(8.0), r(0.5)), r(6.0));
    }
    // Negative or NaN damping counts as 0: 6 + 8·0.5/2 = 8 rad/s.
    for bad in [f64::NAN, -4.0] {
        let w = WheelSpin {
            damping: r(bad),
            ..wheel
        };
        assert_eq!(w.step(r(6.0), r(8.0), r(0.5)), r(8.0));
    }
    // Infinite damping stops the wheel: 8 / ∞ = 0.
    let locked = WheelSpin {
        damping: T::INFINITY,
        ..wheel
    };
    assert_eq!(locked.step(r(6.0), r(8.0), r(0.5)), r(0.0));
    // An overflowing result keeps the spin: 1e8·MAX overflows to ∞.
    let bare = WheelSpin {
        damping: r(0.0),
        ..wheel
    };
    assert_eq!(bare.step(r(1.0), r(1e8), T::MAX), r(1.0));
}

fn coulomb_rules<T: Real>() {
    // Needs −5000 N·m to stop, holds 900: −900 N·m.
    assert_eq!(coulomb_torque(r::<T>(-5000.0), r(900.0)), r(-900.0));
    assert_eq!(coulomb_torque(r::<T>(5000.0), r(900.0)), r(900.0));
    // Within the capacity: exactly what stops the wheel.
    assert_eq!(coulomb_torque(r::<T>(-300.0), r(900.0)), r(-300.0));
    // NaN → 0; ±∞ → ±capacity.
    assert_eq!(coulomb_torque(r::<T>(f64::NAN), r(900.0)), r(0.0));
    assert_eq!(coulomb_torque(T::INFINITY, r(900.0)), r(900.0));
    assert_eq!(coulomb_torque(-T::INFINITY, r(900.0)), r(-900.0));
    // Negative or NaN capacity: no friction.
    assert_eq!(coulomb_torque(r::<T>(-300.0), r(-900.0)), r(0.0));
    assert_eq!(coulomb_torque(r::<T>(-300.0), r(f64::NAN)), r(0.0));
    // Infinite capacity holds anything finite, and at most the largest finite torque.
    assert_eq!(coulomb_torque(r::<T>(-300.0), T::INFINITY), r(-300.0));
    assert_eq!(coulomb_torque(-T::INFINITY, T::INFINITY), -T::MAX);
}

#[test]
fn ramp_f32_f64() {
    ramp_rules::<f32>();
    ramp_rules::<f64>();
    ramp_bad_input::<f32>();
    ramp_bad_input::<f64>();
}

#[test]
fn ramp_reaches_target_without_overshoot() {
    let mut r = VelocityRamp::default();
    // 10.61 rad/s² (BmwX5) × 0.01 s = 0.1061 rad/s per step.
    let a = 27.777_777_777_777_78 / 7.0 / 0.374;
    let target = 100.0 / 3.6 / 0.374; // 74.27 rad/s
    let mut steps = 0;
    while r.command() < target {
        r.step(target, a, 133.69, 0.01);
        steps += 1;
        assert!(r.command() <= target);
    }
    // 74.27 / 0.1061 = 700.0 steps: 7 s.
    assert!((699..=701).contains(&steps), "{steps}");
    assert_eq!(r.command(), target);
}

#[test]
fn ramp_ignores_nan_and_goes_down() {
    let mut r = VelocityRamp::starting_at(5.0);
    assert_eq!(r.step(f64::NAN, 1.0, 10.0, 0.1), 5.0);
    assert_eq!(r.step(-5.0, 10.0, 10.0, 0.1), 4.0);
    assert_eq!(r.step(-20.0, f64::INFINITY, 10.0, 0.1), -10.0);
}

#[test]
fn servo_clamps_and_holds_on_nan() {
    let s = PositionServo::steering(-0.6, 0.4);
    assert_eq!(s.velocity(f64::NAN, 0.3), 0.0);
    // Target clamped to −0.6: 10·(−0.6 − 0) = −6 rad/s.
    assert_eq!(s.velocity(-2.0, 0.0), -6.0);
    assert_eq!(s.clamp_target(0.5, 0.0), 0.4);
}

#[test]
fn servo_f32_f64() {
    servo_rules::<f32>();
    servo_rules::<f64>();
    servo_bad_input::<f32>();
    servo_bad_input::<f64>();
}

#[test]
fn steering_f32_f64() {
    steering_rules::<f32>();
    steering_rules::<f64>();
    steering_bad_input::<f32>();
    steering_bad_input::<f64>();
}

#[test]
fn spin_f32_f64() {
    spin_rules::<f32>();
    spin_rules::<f64>();
    spin_bad_input::<f32>();
    spin_bad_input::<f64>();
}

#[test]
fn coulomb_f32_f64() {
    coulomb_rules::<f32>();
    coulomb_rules::<f64>();
}
