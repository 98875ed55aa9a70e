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
mod special;
mod strategies;

use control_loop::{field_names, run};
use proptest::prelude::*;
use proptest::test_runner::Config;
use strategies::{basic_time_step, edit, op};
use vehicle_model::{
    CarField, CarParams, Driver, FieldValue, Model, ParamWarning, TyreClass, Warning,
};

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

#[test]
fn corpus_default_tyres_of_extreme_wheels_validate() {
    // Found by the world-file fuzzing: `tireRadius = 11` (plausible: up to 1000 m) loaded, but
    // the derived lateral relaxation length, 1.0·11 m, was outside [0.001, 10] m and the car
    // could not be built; a 1e6 kg car's wheel load, outside [1, 1e6] N, likewise. The derived
    // values now saturate at those bounds.
    for class in TyreClass::ALL {
        for (radius, load) in [(11.0, 4000.0), (1000.0, 2.5e6), (0.001, 0.5), (0.4, 1e9)] {
            let p = class.params::<f64>(radius, load);
            assert!(p.validate().is_ok(), "{class:?} {radius} m {load} N");
        }
    }
    let p = TyreClass::PassengerCar.params::<f64>(11.0, 2.5e6);
    assert_eq!(p.lateral.relaxation_length, 10.0);
    // 0.4·11 m is inside the range: unchanged (within rounding of the product).
    assert!((p.longitudinal.relaxation_length - 4.4).abs() < 1e-12);
    assert_eq!(p.nominal_load, 1e6);
    let p = TyreClass::PassengerCar.params::<f64>(0.001, 0.5);
    assert_eq!(p.longitudinal.relaxation_length, 0.001);
    assert_eq!(p.nominal_load, 1.0);
}
