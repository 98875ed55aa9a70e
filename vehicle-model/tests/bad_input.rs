//! Bad input on every entry point: the state stays valid and every output finite.

mod common;
#[path = "fuzz/special.rs"]
mod special;

use common::{Plant, all_finite};
use vehicle_model::{
    CarField, CarParams, ControlMode, Driver, EnumKind, IndicatorState, Model, ParamWarning,
    PerWheel, Sensors, Warning, Wheel, WheelAngles, WiperMode, wheel_from_webots_index,
};

fn bmw() -> Driver<f64> {
    Driver::new(Model::BmwX5.params(), 10).0
}

fn invalid(function: &'static str, argument: &'static str, value: f64) -> Warning {
    Warning::InvalidArgument {
        function,
        argument,
        value,
    }
}

#[test]
fn nan_and_infinite_arguments_are_refused() {
    let mut d = bmw();
    d.set_cruising_speed(10.0);
    d.set_steering_angle(0.1);
    let before = d.step(&Sensors::unsampled(0.0)).drive;
    for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let w = d.set_steering_angle(x).unwrap();
        assert!(matches!(
            w,
            Warning::InvalidArgument {
                function: "wbu_driver_set_steering_angle",
                argument: "steering_angle",
                ..
            }
        ));
        assert_eq!(
            d.set_cruising_speed(x).map(|w| w.to_string()),
            Some(invalid("wbu_driver_set_cruising_speed", "speed", x).to_string())
        );
        assert!(d.set_right_steering_angle(x).is_some());
        assert!(d.set_left_steering_angle(x).is_some());
        assert!(d.set_indicator_period(x).is_some());
    }
    // Nothing changed.
    assert_eq!(d.commanded_steering_angle(), 0.1);
    assert_eq!(d.target_cruising_speed(), 10.0);
    assert_eq!(d.indicator_period(), 0.34);
    assert_eq!(d.step(&Sensors::unsampled(0.01)).drive, before);
    assert_eq!(d.warning_count(), 15);
    // NaN throttle and brake are refused; the mode does not change.
    assert_eq!(
        d.set_throttle(f64::NAN).unwrap().to_string(),
        "Warning: wbu_driver_set_throttle() called with an invalid 'throttle' argument (NaN)"
    );
    assert_eq!(d.control_mode(), ControlMode::Speed);
    assert!(d.set_brake_intensity(f64::NAN).is_some());
    assert_eq!((d.throttle(), d.brake_intensity()), (0.0, 0.0));
    assert!(!d.brake_lights());
}

#[test]
fn clamped_arguments_apply_with_webots_warnings() {
    let mut d = bmw();
    for (x, expected, warning) in [
        (
            -0.5,
            0.0,
            Some(Warning::ClampedToZero {
                argument: "throttle",
            }),
        ),
        (
            f64::NEG_INFINITY,
            0.0,
            Some(Warning::ClampedToZero {
                argument: "throttle",
            }),
        ),
        (
            1.5,
            1.0,
            Some(Warning::ClampedToOne {
                argument: "throttle",
            }),
        ),
        (
            f64::INFINITY,
            1.0,
            Some(Warning::ClampedToOne {
                argument: "throttle",
            }),
        ),
        (
            1e300,
            1.0,
            Some(Warning::ClampedToOne {
                argument: "throttle",
            }),
        ),
        (0.25, 0.25, None),
    ] {
        assert_eq!(d.set_throttle(x), warning, "{x}");
        assert_eq!(d.throttle(), expected);
        assert_eq!(d.control_mode(), ControlMode::Torque);
    }
    assert_eq!(
        d.set_brake_intensity(2.0),
        Some(Warning::ClampedToOne {
            argument: "intensity"
        })
    );
    assert_eq!(d.brake_intensity(), 1.0);
    assert_eq!(
        d.set_brake_intensity(-1.0).unwrap().to_string(),
        "Warning: 'intensity' should be bigger or equal to 0, used 0 instead."
    );
    assert!(!d.brake_lights());
}

#[test]
fn indicator_period_must_be_positive() {
    let mut d = bmw();
    for p in [0.0, -0.0, -1.0] {
        assert_eq!(
            d.set_indicator_period(p),
            Some(invalid("wbu_car_set_indicator_period", "period", p))
        );
    }
    assert_eq!(
        d.set_indicator_period(0.0).unwrap().to_string(),
        "Warning: wbu_car_set_indicator_period() called with an invalid 'period' argument (0)"
    );
    assert_eq!(d.indicator_period(), 0.34);
    // A tiny positive period is accepted; the blink clock stays well defined.
    assert_eq!(d.set_indicator_period(f64::MIN_POSITIVE), None);
    d.set_hazard_flashers(true);
    assert!(all_finite(d.step(&Sensors::unsampled(1.0))));
}

#[test]
fn raw_enum_values_and_wheel_indices() {
    assert_eq!(
        IndicatorState::try_from_webots_value(3),
        Err(Warning::InvalidEnumValue {
            kind: EnumKind::IndicatorState,
            value: 3
        })
    );
    assert_eq!(
        IndicatorState::try_from_webots_value(-1)
            .unwrap_err()
            .to_string(),
        "Warning: wbu_driver_set_indicator() called with an invalid 'state' argument (-1)"
    );
    assert_eq!(WiperMode::try_from_webots_value(2), Ok(WiperMode::Normal));
    assert!(WiperMode::try_from_webots_value(4).is_err());
    assert_eq!(wheel_from_webots_index(3), Ok(Wheel::RearLeft));
    for i in [4, 5, -1, i64::MIN, i64::MAX] {
        assert_eq!(
            wheel_from_webots_index(i),
            Err(Warning::WheelIndex { index: i })
        );
    }
    assert_eq!(
        wheel_from_webots_index(4).unwrap_err().to_string(),
        "Warning: maximum wheel index is 4."
    );
}

#[test]
fn huge_finite_commands_stay_finite() {
    for model in Model::ALL {
        let (mut d, _) = Driver::<f64>::new(model.params(), 10);
        let mut plant = Plant::new(&d);
        for x in special::SPECIAL.into_iter().filter(|x| x.is_finite()) {
            d.set_steering_angle(x);
            d.set_cruising_speed(x);
            plant.run(&mut d);
            assert!(all_finite(d.commands()), "{model}: speed {x}");
            d.set_right_steering_angle(x);
            d.set_left_steering_angle(-x);
            d.set_cruising_speed(-x);
            plant.run(&mut d);
            assert!(all_finite(d.commands()), "{model}: angles {x}");
            d.set_throttle(x);
            d.set_gear(-1);
            plant.run(&mut d);
            assert!(all_finite(d.commands()), "{model}: torque {x}");
        }
        assert!(d.current_speed().is_finite());
        assert!(d.rpm().is_ok_and(f64::is_finite));
    }
}

#[test]
fn steps_before_any_valid_sensor_data() {
    for model in Model::ALL {
        let (mut d, _) = Driver::<f32>::new(model.params(), 16);
        d.set_throttle(1.0);
        d.set_gear(1);
        d.set_brake_intensity(0.3);
        d.set_wiper_mode(WiperMode::Fast);
        for k in 0..50 {
            let c = d.step(&Sensors::unsampled(k as f32 * 0.016));
            assert!(all_finite(c), "{model}");
        }
        assert_eq!(d.current_speed(), 0.0);
        assert_eq!(d.rpm(), Ok(0.0));
        assert_eq!(d.steering_angle(), 0.0);
        assert_eq!(d.wheel_encoder(Wheel::FrontLeft), 0.0);
        assert_eq!(d.wheel_speed(Wheel::RearRight), 0.0);
        d.set_cruising_speed(30.0);
        let c = d.step(&Sensors::unsampled(f32::NAN));
        assert!(all_finite(c));
    }
}

#[test]
fn garbage_sensor_readings() {
    let mut d = bmw();
    d.set_throttle(1.0);
    d.set_gear(1);
    let readings = [
        f64::NAN,
        f64::INFINITY,
        -1e300,
        1e300,
        f64::MAX,
        0.0,
        f64::NEG_INFINITY,
        1e-300,
    ];
    for (k, &x) in readings.iter().enumerate() {
        let s = Sensors {
            time: x,
            wheel_angles: PerWheel::new(x, -x, x * 0.5, 0.0),
            steering: WheelAngles::new(x, -x),
            wiper: Some(x),
        };
        let c = d.step(&s);
        assert!(all_finite(c), "reading {k}: {x}");
        assert!(d.current_speed().is_finite());
        assert!(d.steering_angle().is_finite());
        for w in Wheel::ALL {
            assert!(d.wheel_speed(w).is_finite() && d.wheel_encoder(w).is_finite());
        }
    }
}

/// A fixed-seed pseudo-random sequence of every setter with wild values, interleaved with
/// steps with wild sensors, for every model in f32 and f64.
#[test]
fn random_command_sequences_never_break_the_state() {
    struct Lcg(u64);
    impl Lcg {
        fn next(&mut self) -> u64 {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            self.0 >> 33
        }
        fn value(&mut self) -> f64 {
            const POOL: [f64; 14] = [
                f64::NAN,
                f64::INFINITY,
                f64::NEG_INFINITY,
                1e300,
                -1e300,
                0.0,
                -0.0,
                1.0,
                -1.0,
                0.5,
                30.0,
                -7.0,
                1e-300,
                3.0e38,
            ];
            POOL[(self.next() % POOL.len() as u64) as usize]
        }
    }
    fn run<T: vehicle_model::Real>(model: Model, rng: &mut Lcg) {
        let (mut d, _) = Driver::<T>::new(model.params(), 8);
        let f = T::from_f64;
        let mut t = 0.0;
        for _ in 0..400 {
            let x = f(rng.value());
            match rng.next() % 16 {
                0 => {
                    let _ = d.set_steering_angle(x);
                }
                1 => {
                    let _ = d.set_cruising_speed(x);
                }
                2 => {
                    let _ = d.set_throttle(x);
                }
                3 => {
                    let _ = d.set_brake_intensity(x);
                }
                4 => {
                    let _ = d.set_gear((rng.next() as i32).wrapping_sub(1 << 30));
                }
                5 => {
                    if let Ok(s) = IndicatorState::try_from_webots_value(rng.next() as i32 % 4) {
                        d.set_indicator(s);
                    }
                }
                6 => d.set_hazard_flashers(rng.next().is_multiple_of(2)),
                7 => {
                    let _ = d.set_indicator_period(x);
                }
                8 => {
                    let _ = d.set_right_steering_angle(x);
                }
                9 => {
                    let _ = d.set_left_steering_angle(x);
                }
                10 => d.enable_limited_slip_differential(rng.next().is_multiple_of(2)),
                11 => {
                    if let Ok(m) = WiperMode::try_from_webots_value(rng.next() as i32 % 5) {
                        d.set_wiper_mode(m);
                    }
                }
                12 => {
                    let _ = d.rpm();
                }
                _ => {
                    t += 0.008;
                    let y = f(rng.value());
                    let s = Sensors {
                        time: if rng.next().is_multiple_of(5) {
                            y
                        } else {
                            f(t)
                        },
                        wheel_angles: PerWheel::from_fn(|_| f(rng.value())),
                        steering: WheelAngles::new(y, f(rng.value())),
                        wiper: Some(f(rng.value())),
                    };
                    assert!(all_finite(d.step(&s)), "{model}");
                }
            }
            assert!(d.throttle() >= T::ZERO && d.throttle() <= T::ONE);
            assert!(d.brake_intensity() >= T::ZERO && d.brake_intensity() <= T::ONE);
            assert!(d.indicator_period() > T::ZERO && d.indicator_period().is_finite());
            assert!(d.commanded_steering_angle().is_finite());
            assert!(d.target_cruising_speed().is_finite());
            assert!(d.current_speed().is_finite() && d.steering_angle().is_finite());
            assert!(d.limited_slip().front().abs() <= T::ONE);
        }
    }
    let mut rng = Lcg(0x5eed);
    for model in Model::ALL {
        run::<f64>(model, &mut rng);
        run::<f32>(model, &mut rng);
    }
}

#[test]
fn invalid_params_fall_back_to_defaults() {
    let mut p = CarParams::<f64> {
        wheelbase: f64::NAN,
        ..CarParams::default()
    };
    p.engine.max_rpm = -3.0;
    p.gear_ratios.clear();
    let (d, report) = Driver::new(p, 0);
    assert_eq!(d.wheelbase(), 4.0);
    assert_eq!(d.powertrain().engine().max_rpm(), 4500.0);
    assert_eq!(d.gear_number(), 6);
    assert_eq!(d.basic_time_step_ms(), 32);
    assert_eq!(report.len(), 4);
}

#[test]
fn implausible_params_are_replaced_and_keep_the_motor_limits_finite() {
    // Positive and finite, but outside the plausible ranges (0–100 km/h in 0.1 s or more, at
    // most 1000 m/s): the derived limits would overflow f32, (1000/36)/1e-38/0.374 ≈ 7.4e39
    // and 3e38/0.374 ≈ 8.0e38 > f32::MAX ≈ 3.4e38. Validation replaces both by the defaults.
    let mut p = Model::BmwX5.params::<f32>();
    p.time_0_to_100 = 1e-38;
    p.max_velocity = 3e38;
    let (mut d, report) = Driver::new(p, 10);
    assert_eq!(
        report.as_slice(),
        &[
            ParamWarning::Implausible {
                field: CarField::Time0To100,
                value: f64::from(1e-38_f32),
                used: 10.0
            },
            ParamWarning::Implausible {
                field: CarField::MaxVelocity,
                value: f64::from(3e38_f32),
                used: 50.0
            },
        ]
    );
    assert!(report.as_slice().iter().all(ParamWarning::is_implausible));
    assert_eq!(
        report.as_slice()[1].to_string(),
        "Warning: implausible 'maxVelocity' value 3.0000000054977558e38 (must be within 0 to \
         1000 m/s), used 50 instead."
    );
    // The default 10 s and 50 m/s on the 0.374 m BmwX5 tyre: (1000/36)/10/0.374 rad/s² and
    // 50/0.374 rad/s.
    let m = d.params().wheel_motor(Wheel::FrontLeft);
    let r = d.params().wheels[Wheel::FrontLeft].tire_radius;
    assert!((m.acceleration - 1000.0 / 36.0 / 10.0 / r).abs() < 1e-4);
    assert!((m.max_velocity - 50.0 / r).abs() < 1e-3);
    let mut plant = Plant::new(&d);
    d.set_cruising_speed(50.0);
    for _ in 0..5 {
        plant.run(&mut d);
        assert!(all_finite(d.commands()), "{:?}", d.commands().drive);
    }
    // A 1e-38 m tyre is refused too: the wheel falls back to the VehicleWheel default 0.4 m.
    let mut p = Model::TeslaModel3.params::<f32>();
    for w in Wheel::ALL {
        p.wheels[w].tire_radius = 1e-38;
    }
    let (d, report) = Driver::new(p, 10);
    assert_eq!(report.len(), 4);
    assert!(report.as_slice().iter().all(ParamWarning::is_implausible));
    assert!(
        Wheel::ALL
            .iter()
            .all(|&w| d.params().wheels[w].tire_radius == 0.4)
    );
}

#[test]
fn commands_is_finite_sees_every_number() {
    let mut d = bmw();
    d.set_cruising_speed(20.0);
    let good = *d.step(&Sensors::unsampled(0.0));
    assert!(good.is_finite());
    let poisoned: [fn(&mut vehicle_model::Commands<f64>); 7] = [
        |c| c.steering.left = f64::NAN,
        |c| {
            c.drive[Wheel::FrontRight] = vehicle_model::WheelDrive::Velocity {
                target: 1.0,
                acceleration: f64::INFINITY,
                max_velocity: 1.0,
            }
        },
        |c| c.drive[Wheel::RearLeft] = vehicle_model::WheelDrive::Torque(f64::NAN),
        |c| c.brake_torque[Wheel::RearRight] = f64::INFINITY,
        |c| c.cockpit.speed_needle = f64::NAN,
        |c| c.cockpit.wipers.as_mut().unwrap().target = f64::NEG_INFINITY,
        |c| c.sound.engine.pitch = f64::NAN,
    ];
    for (i, poison) in poisoned.iter().enumerate() {
        let mut c = good;
        poison(&mut c);
        assert!(!c.is_finite(), "case {i}");
    }
}
