//! Fuzzing the control loop: property tests of random parameter edits and setter/step sequences
//! with hostile values on every model in f32 and f64 (the invariants are those of
//! `control_loop.rs`, shared with the coverage-guided target `fuzz/fuzz_targets/control_loop.rs`),
//! and the inputs the hardening review found as regression tests.
//!
//! Few cases by default so that `cargo test` stays quick; a long run sets proptest's own
//! variable, e.g. `PROPTEST_CASES=20000 cargo test --release -p vehicle-model --test fuzz`
//! (see `fuzz/README.md`).

// A failed property reports through proptest's panic.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod control_loop;

use control_loop::{FieldEdit, Op, field_names, run};
use proptest::prelude::*;
use proptest::test_runner::Config;
use vehicle_model::{CarField, CarParams, Driver, FieldValue, Model, ParamWarning, Warning};

/// Cases per property unless `PROPTEST_CASES` is set (each case runs up to 64 calls on one
/// driver, a fraction of a millisecond).
const DEFAULT_CASES: u32 = 96;

/// proptest's configuration with [`DEFAULT_CASES`] unless `PROPTEST_CASES` asks for more.
fn config() -> Config {
    let mut config = Config::default();
    if std::env::var_os("PROPTEST_CASES").is_none() {
        config.cases = DEFAULT_CASES;
    }
    config
}

/// Any f64, weighted towards the values that broke things before: NaN, ±∞, the extremes,
/// zeros of both signs, subnormals and a few ordinary values.
fn hostile() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => prop::sample::select(vec![
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            1e300,
            -1e300,
            f64::MAX,
            f64::MIN,
            -1e308,
            3.5e38,
            -0.0,
            0.0,
            f64::MIN_POSITIVE,
            1e-300,
            5e-324,
            0.5,
            1.0,
            -1.0,
            30.0,
            -7.0,
        ]),
        2 => -100.0..100.0f64,
        1 => any::<f64>(),
    ]
}

/// Any i32, weighted towards the edges of the gears, enum values and wheel indices.
fn hostile_int() -> impl Strategy<Value = i32> {
    prop_oneof![
        3 => -3..8i32,
        1 => prop::sample::select(vec![i32::MIN, i32::MAX, -1_000_000, 1 << 30]),
        1 => any::<i32>(),
    ]
}

/// One driver call.
fn op() -> impl Strategy<Value = Op> {
    prop_oneof![
        1 => hostile().prop_map(Op::SteeringAngle),
        1 => hostile().prop_map(Op::CruisingSpeed),
        1 => hostile().prop_map(Op::Throttle),
        1 => hostile().prop_map(Op::BrakeIntensity),
        1 => hostile_int().prop_map(Op::Gear),
        1 => hostile_int().prop_map(Op::Indicator),
        1 => any::<bool>().prop_map(Op::HazardFlashers),
        1 => hostile().prop_map(Op::IndicatorPeriod),
        1 => hostile().prop_map(Op::RightSteeringAngle),
        1 => hostile().prop_map(Op::LeftSteeringAngle),
        1 => any::<bool>().prop_map(Op::LimitedSlip),
        1 => hostile_int().prop_map(Op::WiperMode),
        1 => any::<bool>().prop_map(Op::DippedBeams),
        1 => any::<bool>().prop_map(Op::AntifogLights),
        1 => any::<bool>().prop_map(Op::IndicatorAutoDisabling),
        1 => prop_oneof![-2..6i64, any::<i64>()].prop_map(Op::Read),
        4 => (
            hostile(),
            prop::array::uniform4(hostile()),
            prop::array::uniform2(hostile()),
            prop::option::of(hostile()),
        )
            .prop_map(|(time, wheel_angles, steering, wiper)| Op::Step {
                time,
                wheel_angles,
                steering,
                wiper,
            }),
    ]
}

/// A parameter edit: any settable field with one to seven hostile values.
fn edit() -> impl Strategy<Value = FieldEdit> {
    (
        0..field_names().len(),
        prop::collection::vec(hostile(), 1..=7),
    )
        .prop_map(|(field, values)| FieldEdit { field, values })
}

/// The basic time step (ms): usual values, 0 (refused, the default used) and extremes.
fn basic_time_step() -> impl Strategy<Value = u32> {
    prop_oneof![
        3 => prop::sample::select(vec![1, 8, 10, 16, 20, 32, 100]),
        1 => any::<u32>(),
    ]
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn random_calls_keep_the_state_finite_in_f64(
        model in prop::sample::select(Model::ALL.to_vec()),
        step in basic_time_step(),
        edits in prop::collection::vec(edit(), 0..4),
        ops in prop::collection::vec(op(), 0..64),
    ) {
        run::<f64>(model, step, &edits, &ops).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn random_calls_keep_the_state_finite_in_f32(
        model in prop::sample::select(Model::ALL.to_vec()),
        step in basic_time_step(),
        edits in prop::collection::vec(edit(), 0..4),
        ops in prop::collection::vec(op(), 0..64),
    ) {
        run::<f32>(model, step, &edits, &ops).map_err(TestCaseError::fail)?;
    }
}

/// The warning `CarParams::validate` gives for `name` set to `value` on a BmwX5, as text.
fn implausible(name: &str, value: FieldValue<'_, f64>) -> (ParamWarning, String) {
    let mut p = Model::BmwX5.params::<f64>();
    p.set_field(name, value).unwrap();
    let report = p.validate();
    assert_eq!(report.len(), 1, "{name}: {:?}", report.as_slice());
    let w = report.as_slice()[0];
    assert!(w.is_implausible(), "{name}: {w:?}");
    (w, w.to_string())
}

#[test]
fn corpus_indicator_period_minus_1e308_is_refused_in_one_short_line() {
    // Printed with 309 digits before numbers went compact.
    let (mut d, _) = Driver::<f64>::new(Model::BmwX5.params(), 10);
    let w = d.set_indicator_period(-1e308).unwrap();
    assert_eq!(
        w.to_string(),
        "Warning: wbu_car_set_indicator_period() called with an invalid 'period' argument \
         (-1e308)"
    );
    assert_eq!(d.indicator_period(), 0.34);
}

#[test]
fn corpus_non_finite_driver_arguments_are_refused() {
    // The C ABI's differential-wheels setter accepted ±∞ while these refused it; the driver
    // side stays as it was: every non-finite steering angle, speed and period is refused.
    let (mut d, _) = Driver::<f64>::new(Model::BmwX5.params(), 10);
    for x in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
        assert!(matches!(
            d.set_cruising_speed(x),
            Some(Warning::InvalidArgument {
                argument: "speed",
                ..
            })
        ));
        assert!(d.set_steering_angle(x).is_some());
        assert!(d.set_left_steering_angle(x).is_some());
        assert!(d.set_right_steering_angle(x).is_some());
    }
    assert_eq!(d.target_cruising_speed(), 0.0);
    assert_eq!(d.commanded_steering_angle(), 0.0);
}

#[test]
fn corpus_centre_of_mass_1e300() {
    let (w, text) = implausible("centerOfMass", FieldValue::Numbers(&[1e300, 0.0, 0.0]));
    assert_eq!(w.field(), Some(CarField::CenterOfMass));
    assert_eq!(
        text,
        "Warning: implausible 'centerOfMass' element 0 value 1e300 (must be within -1000 to 1000 \
         m), used the default instead."
    );
}

#[test]
fn corpus_wheelbase_and_track_1e300() {
    let (w, text) = implausible("wheelbase", FieldValue::Number(1e300));
    assert_eq!(
        w,
        ParamWarning::Implausible {
            field: CarField::Wheelbase,
            value: 1e300,
            used: 4.0
        }
    );
    assert_eq!(
        text,
        "Warning: implausible 'wheelbase' value 1e300 (must be within 0.001 to 1000 m), used 4 \
         instead."
    );
    let (w, _) = implausible("trackFront", FieldValue::Number(1e300));
    assert_eq!(w.field(), Some(CarField::TrackFront));
}

#[test]
fn corpus_wheelbase_1e_9() {
    let (w, _) = implausible("wheelbase", FieldValue::Number(1e-9));
    assert_eq!(
        w,
        ParamWarning::Implausible {
            field: CarField::Wheelbase,
            value: 1e-9,
            used: 4.0
        }
    );
}

#[test]
fn corpus_mass_1e300_and_1e_300() {
    for m in [1e300, 1e-300] {
        let (w, text) = implausible("mass", FieldValue::Number(m));
        assert_eq!(w.field(), Some(CarField::Mass), "{m}");
        assert!(
            text.contains("(must be within 0.001 to 1000000 kg)"),
            "{text}"
        );
    }
}

#[test]
fn corpus_inertia_matrix_1e300() {
    let (w, text) = implausible(
        "inertiaMatrix",
        FieldValue::Numbers(&[1e300, 1e300, 1e300, 0.0, 0.0, 0.0]),
    );
    assert_eq!(w.field(), Some(CarField::InertiaMatrix));
    assert!(text.contains("kg·m²"), "{text}");
}

#[test]
fn corpus_wheel_tyre_radius_and_mass_1e300() {
    for name in ["wheelFrontLeft.tireRadius", "wheels.mass"] {
        let mut p = Model::BmwX5.params::<f64>();
        p.set_field(name, FieldValue::Number(1e300)).unwrap();
        let report = p.validate();
        assert!(!report.is_empty(), "{name}");
        assert!(
            report.iter().all(ParamWarning::is_implausible),
            "{name}: {:?}",
            report.as_slice()
        );
        // The replacement drives: a few closed-loop steps stay finite.
        let (mut d, _) = Driver::new(p, 10);
        d.set_cruising_speed(50.0);
        for k in 0..10 {
            let c = d.step(&vehicle_model::Sensors::unsampled(f64::from(k) * 0.01));
            assert!(c.is_finite(), "{name}");
        }
    }
}

#[test]
fn corpus_spring_1e300() {
    let (w, text) = implausible("suspensionFrontSpringConstant", FieldValue::Number(1e300));
    assert_eq!(w.field(), Some(CarField::SuspensionFrontSpringConstant));
    assert!(text.contains("N/m"), "{text}");
}

#[test]
fn corpus_gear_ratio_minus_12_5_and_1e6() {
    let (w, text) = implausible("gearRatio", FieldValue::Numbers(&[-12.5, 1e6]));
    assert_eq!(w.field(), Some(CarField::GearRatio));
    assert_eq!(
        text,
        "Warning: implausible 'gearRatio' element 1 value 1000000 (its magnitude must be within \
         0.1 to 100), used the default instead."
    );
    // The default table replaces the whole list: the BmwX5's reverse and forward gears.
    let mut p = Model::BmwX5.params::<f64>();
    p.set_field("gearRatio", FieldValue::Numbers(&[-12.5, 1e6]))
        .unwrap();
    p.validate();
    assert!(p.gear_ratios.len() > 2);
    assert!(
        p.gear_ratios
            .iter()
            .all(|r| (0.1..=100.0).contains(&r.abs()))
    );
}

#[test]
fn corpus_every_field_name_is_fuzzed() {
    // The structure-aware inputs reach every Car field and every wheel slot's fields.
    let names = field_names();
    assert_eq!(
        names.len(),
        CarParams::<f64>::FIELD_NAMES.len()
            + CarParams::<f64>::WHEEL_SLOT_NAMES.len() * CarParams::<f64>::WHEEL_FIELD_NAMES.len()
    );
    assert!(names.iter().any(|n| n == "wheels.tireRadius"));
    for name in &names {
        let mut p = Model::Car.params::<f64>();
        // Every name is known: only the form of the value may be refused.
        let e = p.set_field(name, FieldValue::Number(1.0));
        assert!(
            !matches!(e, Err(vehicle_model::FieldError::UnknownField)),
            "{name}"
        );
    }
}
