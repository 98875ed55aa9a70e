//! The control-loop fuzz harness: a [`Driver`] built from edited car parameters, then any
//! sequence of setter calls and steps with any arguments (NaN, ±∞, 1e300, subnormals, any
//! integer), checked after every call.
//!
//! Shared by the property tests of this directory and the coverage-guided target
//! `fuzz/fuzz_targets/control_loop.rs` (which includes this file by path), so both check the
//! same invariants:
//!
//! * nothing panics;
//! * a setter's warning is the one its documentation promises for that argument (refused
//!   non-finite values, Webots' clamps, gear limits, enum values), with a short message;
//! * the parameters left by [`Driver::new`] are finite and plausible (validating them again
//!   finds at most a Webots wheel-shape rule, see [`wheel_shape_rule`]);
//! * the stored controls stay in range and every getter and every command stays finite.

use proto_geom::WheelRule;
use vehicle_model::{
    CarParams, Driver, FieldValue, IndicatorState, Model, ParamWarning, PerWheel, Real, Sensors,
    Warning, Wheel, WheelAngles, WiperMode, wheel_from_webots_index,
};

/// Longest acceptable warning text (characters): a number is printed in compact form, never
/// with hundreds of digits.
pub const MAX_MESSAGE_LEN: usize = 200;

/// One edit of the car parameters before the driver is built: the field with index `field` in
/// [`field_names`] (modulo its length) set to `values` (one value: a number, else a list).
#[derive(Debug, Clone, PartialEq)]
pub struct FieldEdit {
    /// Index into [`field_names`], taken modulo its length.
    pub field: usize,
    /// The value or list of values.
    pub values: Vec<f64>,
}

/// One call on the driver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Op {
    /// `set_steering_angle` (rad).
    SteeringAngle(f64),
    /// `set_cruising_speed` (km/h).
    CruisingSpeed(f64),
    /// `set_throttle` (dimensionless).
    Throttle(f64),
    /// `set_brake_intensity` (dimensionless).
    BrakeIntensity(f64),
    /// `set_gear`.
    Gear(i32),
    /// `set_indicator` with a raw Webots value.
    Indicator(i32),
    /// `set_hazard_flashers`.
    HazardFlashers(bool),
    /// `set_indicator_period` (s).
    IndicatorPeriod(f64),
    /// `set_right_steering_angle` (rad).
    RightSteeringAngle(f64),
    /// `set_left_steering_angle` (rad).
    LeftSteeringAngle(f64),
    /// `enable_limited_slip_differential`.
    LimitedSlip(bool),
    /// `set_wiper_mode` with a raw Webots value.
    WiperMode(i32),
    /// `set_dipped_beams`.
    DippedBeams(bool),
    /// `set_antifog_lights`.
    AntifogLights(bool),
    /// `enable_indicator_auto_disabling`.
    IndicatorAutoDisabling(bool),
    /// Every getter, the per-wheel ones with this raw Webots wheel index.
    Read(i64),
    /// `step` with these sensor readings: time (s), four wheel angles (rad, Webots wheel
    /// order), the right and left steering angles (rad) and the wiper angle (rad).
    Step {
        /// Simulation time (s).
        time: f64,
        /// Wheel encoder angles (rad).
        wheel_angles: [f64; 4],
        /// Right and left steering angles (rad).
        steering: [f64; 2],
        /// Wiper angle (rad), if the car reports one.
        wiper: Option<f64>,
    },
}

/// Every name [`CarParams::set_field`] accepts: the Car fields, then `<slot>.<field>` for every
/// wheel slot and numeric VehicleWheel field.
pub fn field_names() -> Vec<String> {
    let mut names: Vec<String> = CarParams::<f64>::FIELD_NAMES
        .iter()
        .map(|n| (*n).to_string())
        .collect();
    for slot in CarParams::<f64>::WHEEL_SLOT_NAMES {
        for field in CarParams::<f64>::WHEEL_FIELD_NAMES {
            names.push(format!("{slot}.{field}"));
        }
    }
    names
}

/// Builds a driver for `model` with `edits` applied and runs `ops` on it in scalar `T`,
/// checking every invariant of the module documentation after each call.
///
/// # Errors
/// The first broken invariant, naming the model, the call and what was wrong.
pub fn run<T: Real>(
    model: Model,
    basic_time_step_ms: u32,
    edits: &[FieldEdit],
    ops: &[Op],
) -> Result<(), String> {
    let names = field_names();
    let mut params = model.params::<T>();
    for edit in edits {
        let name = &names[edit.field % names.len()];
        let values: Vec<T> = edit.values.iter().map(|&v| T::from_f64(v)).collect();
        let value = match values.as_slice() {
            [one] => FieldValue::Number(*one),
            list => FieldValue::Numbers(list),
        };
        // A value of the wrong form is refused with a typed error and changes nothing.
        let _ = params.set_field(name, value);
    }
    let (mut driver, report) = Driver::new(params, basic_time_step_ms);
    for w in report.iter() {
        short(&w.to_string()).map_err(|e| format!("{model}: parameter warning {e}"))?;
    }
    // Like Webots, a VehicleWheel fallback is not re-checked by the shape rule that replaced
    // it (a `rimBeamThickness` reset to 0.2 may still exceed a thin `thickness`), so a second
    // validation may report wheel-shape rules again; every value is finite and plausible.
    let mut again = driver.params().clone();
    let repeated = again.validate();
    if let Some(w) = repeated.iter().find(|w| !wheel_shape_rule(w)) {
        return Err(format!(
            "{model}: validated parameters still give {w:?} ({w})"
        ));
    }
    check_state(&driver).map_err(|e| format!("{model}, new: {e}"))?;
    for (i, op) in ops.iter().enumerate() {
        apply(&mut driver, op).map_err(|e| format!("{model}, call {i} {op:?}: {e}"))?;
        check_state(&driver).map_err(|e| format!("{model}, after call {i} {op:?}: {e}"))?;
    }
    Ok(())
}

/// A warning about the relation between two VehicleWheel fields (rim inside the tyre, hub
/// inside the rim…), not about a non-finite, non-positive or implausible value.
fn wheel_shape_rule(w: &ParamWarning) -> bool {
    matches!(
        w,
        ParamWarning::Wheel { warning, .. }
            if !matches!(
                warning.rule,
                WheelRule::NotFinite | WheelRule::NotPositive | WheelRule::Implausible
            )
    )
}

/// `Err` if a message is too long to be a one-line message with compact numbers.
fn short(message: &str) -> Result<(), String> {
    if message.chars().count() <= MAX_MESSAGE_LEN {
        Ok(())
    } else {
        Err(format!(
            "too long ({} characters): {message}",
            message.len()
        ))
    }
}

/// The same value or both NaN.
fn same(a: f64, b: f64) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

/// Checks that `got` is `expected` (a warning is compared by its kind and value) and short.
fn expect(got: Option<Warning>, expected: Option<Warning>) -> Result<(), String> {
    let equal = match (got, expected) {
        (
            Some(Warning::InvalidArgument {
                function: f1,
                argument: a1,
                value: v1,
            }),
            Some(Warning::InvalidArgument {
                function: f2,
                argument: a2,
                value: v2,
            }),
        ) => f1 == f2 && a1 == a2 && same(v1, v2),
        (got, expected) => got == expected,
    };
    if !equal {
        return Err(format!("warning {got:?}, expected {expected:?}"));
    }
    got.map_or(Ok(()), |w| short(&w.to_string()))
}

/// The warning of a setter that refuses a non-finite `x` and accepts any finite one.
fn refused_unless_finite<T: Real>(
    x: T,
    function: &'static str,
    argument: &'static str,
) -> Option<Warning> {
    (!x.is_finite()).then_some(Warning::InvalidArgument {
        function,
        argument,
        value: x.to_f64(),
    })
}

/// The warning of Webots' [0, 1] clamp of `argument` (throttle, brake intensity).
fn unit_clamp<T: Real>(x: T, function: &'static str, argument: &'static str) -> Option<Warning> {
    if x.is_nan() {
        Some(Warning::InvalidArgument {
            function,
            argument,
            value: x.to_f64(),
        })
    } else if x < T::ZERO {
        Some(Warning::ClampedToZero { argument })
    } else if x > T::ONE {
        Some(Warning::ClampedToOne { argument })
    } else {
        None
    }
}

/// Performs `op` on `d` and checks the warning it returns.
pub fn apply<T: Real>(d: &mut Driver<T>, op: &Op) -> Result<(), String> {
    let f = T::from_f64;
    match *op {
        Op::SteeringAngle(x) => expect(
            d.set_steering_angle(f(x)),
            refused_unless_finite(f(x), "wbu_driver_set_steering_angle", "steering_angle"),
        ),
        Op::CruisingSpeed(x) => expect(
            d.set_cruising_speed(f(x)),
            refused_unless_finite(f(x), "wbu_driver_set_cruising_speed", "speed"),
        ),
        Op::Throttle(x) => expect(
            d.set_throttle(f(x)),
            unit_clamp(f(x), "wbu_driver_set_throttle", "throttle"),
        ),
        Op::BrakeIntensity(x) => expect(
            d.set_brake_intensity(f(x)),
            unit_clamp(f(x), "wbu_driver_set_brake_intensity", "intensity"),
        ),
        Op::Gear(g) => {
            let gear_number = d.gear_number();
            let expected = if g < -1 {
                Some(Warning::MinimumGear)
            } else if usize::try_from(g).is_ok_and(|g| g >= gear_number) {
                Some(Warning::TooManyGears { gear_number })
            } else {
                None
            };
            expect(d.set_gear(g), expected)
        }
        Op::Indicator(raw) => match IndicatorState::try_from_webots_value(raw) {
            Ok(s) if (0..=2).contains(&raw) => {
                d.set_indicator(s);
                Ok(())
            }
            Ok(s) => Err(format!("raw indicator {raw} accepted as {s:?}")),
            Err(w) if (0..=2).contains(&raw) => Err(format!("raw indicator {raw} refused: {w}")),
            Err(w) => short(&w.to_string()),
        },
        Op::WiperMode(raw) => match WiperMode::try_from_webots_value(raw) {
            Ok(m) if (0..=3).contains(&raw) => {
                d.set_wiper_mode(m);
                Ok(())
            }
            Ok(m) => Err(format!("raw wiper mode {raw} accepted as {m:?}")),
            Err(w) if (0..=3).contains(&raw) => Err(format!("raw wiper mode {raw} refused: {w}")),
            Err(w) => short(&w.to_string()),
        },
        Op::HazardFlashers(on) => {
            d.set_hazard_flashers(on);
            Ok(())
        }
        Op::IndicatorPeriod(x) => {
            let p = f(x);
            let expected = (!(p.is_finite() && p > T::ZERO)).then_some(Warning::InvalidArgument {
                function: "wbu_car_set_indicator_period",
                argument: "period",
                value: p.to_f64(),
            });
            expect(d.set_indicator_period(p), expected)
        }
        Op::RightSteeringAngle(x) => expect(
            d.set_right_steering_angle(f(x)),
            refused_unless_finite(f(x), "wbu_car_set_right_steering_angle", "angle"),
        ),
        Op::LeftSteeringAngle(x) => expect(
            d.set_left_steering_angle(f(x)),
            refused_unless_finite(f(x), "wbu_car_set_left_steering_angle", "angle"),
        ),
        Op::LimitedSlip(on) => {
            d.enable_limited_slip_differential(on);
            Ok(())
        }
        Op::DippedBeams(on) => {
            d.set_dipped_beams(on);
            Ok(())
        }
        Op::AntifogLights(on) => {
            d.set_antifog_lights(on);
            Ok(())
        }
        Op::IndicatorAutoDisabling(on) => {
            d.enable_indicator_auto_disabling(on);
            Ok(())
        }
        Op::Read(index) => read(d, index),
        Op::Step {
            time,
            wheel_angles,
            steering,
            wiper,
        } => {
            let sensors = Sensors {
                time: f(time),
                wheel_angles: PerWheel::from_fn(|w| f(wheel_angles[w as usize])),
                steering: WheelAngles::new(f(steering[0]), f(steering[1])),
                wiper: wiper.map(f),
            };
            if d.step(&sensors).is_finite() {
                Ok(())
            } else {
                Err(format!("non-finite commands {:?}", d.commands()))
            }
        }
    }
}

/// Calls every getter; the per-wheel ones with the raw Webots wheel `index`.
fn read<T: Real>(d: &Driver<T>, index: i64) -> Result<(), String> {
    match (wheel_from_webots_index(index), (0..4).contains(&index)) {
        (Ok(w), true) => {
            let (e, s) = (d.wheel_encoder(w), d.wheel_speed(w));
            if !(e.is_finite() && s.is_finite()) {
                return Err(format!("wheel {w:?}: encoder {e:?}, speed {s:?}"));
            }
        }
        (Err(Warning::WheelIndex { index: i }), false) if i == index => {}
        (got, _) => return Err(format!("wheel index {index} gave {got:?}")),
    }
    match d.rpm() {
        Ok(rpm) if !(rpm.is_finite() && rpm >= T::ZERO) => return Err(format!("rpm {rpm:?}")),
        Ok(_) | Err(Warning::NoEngineModel) => {}
        Err(w) => return Err(format!("rpm warning {w:?}")),
    }
    match d.gear() {
        Ok(_) | Err(Warning::NoGearModel) => {}
        Err(w) => return Err(format!("gear warning {w:?}")),
    }
    let geometry = [
        d.track_front(),
        d.track_rear(),
        d.wheelbase(),
        d.front_wheel_radius(),
        d.rear_wheel_radius(),
    ];
    if !geometry.iter().all(|x| x.is_finite() && *x > T::ZERO) {
        return Err(format!("geometry {geometry:?}"));
    }
    let angles = [
        d.right_steering_angle(),
        d.left_steering_angle(),
        d.commanded_wheel_angles().right,
        d.commanded_wheel_angles().left,
    ];
    if !angles.iter().all(|x| x.is_finite()) {
        return Err(format!("steering angles {angles:?}"));
    }
    Ok(())
}

/// The state invariants that hold after every call.
pub fn check_state<T: Real>(d: &Driver<T>) -> Result<(), String> {
    let unit = |x: T| x >= T::ZERO && x <= T::ONE;
    if !(unit(d.throttle()) && unit(d.brake_intensity())) {
        return Err(format!(
            "throttle {:?}, brake {:?} outside [0, 1]",
            d.throttle(),
            d.brake_intensity()
        ));
    }
    let p = d.indicator_period();
    if !(p.is_finite() && p > T::ZERO) {
        return Err(format!("indicator period {p:?}"));
    }
    let values = [
        d.commanded_steering_angle(),
        d.target_cruising_speed(),
        d.current_speed(),
        d.steering_angle(),
    ];
    if !values.iter().all(|x| x.is_finite()) {
        return Err(format!(
            "commanded steering, target speed, speed, steering {values:?}"
        ));
    }
    if !Wheel::ALL
        .iter()
        .all(|&w| d.wheel_speed(w).is_finite() && d.wheel_encoder(w).is_finite())
    {
        return Err("a wheel speed or encoder is not finite".to_string());
    }
    if d.limited_slip().front().abs() > T::ONE {
        return Err(format!("limited slip {:?}", d.limited_slip().front()));
    }
    if !d.commands().is_finite() {
        return Err(format!("non-finite commands {:?}", d.commands()));
    }
    Ok(())
}
