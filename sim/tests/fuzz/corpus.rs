//! The committed seed worlds of `fuzz/seeds/world_file` (the hardening review's reproducers and
//! a few valid worlds) as regression tests: each has its exact outcome here, every seed has
//! one, and each passes the fuzz invariants.

use std::path::PathBuf;

use sim::world_file::{self, WorldFileErrorKind, parse_str};
use sim::{DifferentialWheels, RobotWarning};

use crate::simulation::{build, step};

/// The seed directory shared with the coverage-guided `world_file` target.
fn seeds() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../fuzz/seeds/world_file")
}

/// Each seed and what loading it gives: `None` for a world that loads, else the whole error
/// message (the file name, line and column, key and value in compact form).
const OUTCOMES: [(&str, Option<&str>); 34] = [
    ("basic_time_step_100_truck.toml", None),
    ("basic_time_step_100_truck_joints.toml", None),
    (
        "center_of_mass_1e300.toml",
        Some(
            "center_of_mass_1e300.toml:3:1: invalid 'vehicle.centerOfMass': implausible \
             'centerOfMass' element 0 value 1e300 (must be within -1000 to 1000 m)",
        ),
    ),
    ("default_world.toml", None),
    (
        "gear_ratio_1e6.toml",
        Some(
            "gear_ratio_1e6.toml:3:1: invalid 'vehicle.gearRatio': implausible 'gearRatio' \
             element 1 value 1000000 (its magnitude must be within 0.1 to 100)",
        ),
    ),
    (
        "gear_ratio_string.toml",
        Some(
            "gear_ratio_string.toml:3:1: 'vehicle.gearRatio' takes a number at element 2, found \
             a string",
        ),
    ),
    (
        "gravity_1e300.toml",
        Some(
            "gravity_1e300.toml:1:1: invalid 'gravity': 1e300 m/s²: must be from 0 to 100 (the \
             magnitude of a gravity pointing down)",
        ),
    ),
    (
        "gravity_upward.toml",
        Some(
            "gravity_upward.toml:1:1: invalid 'gravity': -9.81 m/s²: must be from 0 to 100 (the \
             magnitude of a gravity pointing down)",
        ),
    ),
    (
        "inertia_matrix_1e300.toml",
        Some(
            "inertia_matrix_1e300.toml:3:1: invalid 'vehicle.inertiaMatrix': implausible \
             'inertiaMatrix' element 0 value 1e300 (must be within -1000000000000 to \
             1000000000000 kg·m²)",
        ),
    ),
    (
        "mass_1e-300.toml",
        Some(
            "mass_1e-300.toml:3:1: invalid 'vehicle.mass': implausible 'mass' value 1e-300 (must \
             be within 0.001 to 1000000 kg)",
        ),
    ),
    // Found by fuzzing: the heaviest plausible car and the largest and smallest plausible tyres
    // loaded but could not be built (their derived default tyre was out of range).
    ("mass_1e6.toml", None),
    (
        "mass_1e300.toml",
        Some(
            "mass_1e300.toml:3:1: invalid 'vehicle.mass': implausible 'mass' value 1e300 (must \
             be within 0.001 to 1000000 kg)",
        ),
    ),
    (
        "robot_axle_length_1e300.toml",
        Some(
            "robot_axle_length_1e300.toml:2:1: invalid 'differential_wheels.axleLength': 1e300: \
             must be within 0.001 to 1000 m",
        ),
    ),
    ("robot_physics.toml", None),
    // Found by fuzzing: only finiteness was checked, and the world then could not be built.
    (
        "robot_translation_1e133.toml",
        Some(
            "robot_translation_1e133.toml:2:1: invalid 'differential_wheels.translation': \
             -1e133: every coordinate must be within -10000 to 10000 m",
        ),
    ),
    (
        "robot_wheel_radius_1e300.toml",
        Some(
            "robot_wheel_radius_1e300.toml:2:1: invalid 'differential_wheels.wheelRadius': \
             1e300: must be within 0.001 to 1000 m",
        ),
    ),
    (
        "spring_1e300.toml",
        Some(
            "spring_1e300.toml:3:1: invalid 'vehicle.suspensionFrontSpringConstant': implausible \
             'suspensionFrontSpringConstant' value 1e300 (must be within 0 to 100000000 N/m)",
        ),
    ),
    (
        "tire_radius_1e300.toml",
        Some(
            "tire_radius_1e300.toml:3:16: invalid 'vehicle.wheelFrontLeft.tireRadius': \
             wheelFrontLeft: 'tireRadius' must be within 0.001 to 1000 m (value 1e300).",
        ),
    ),
    ("tire_radius_11.toml", None),
    ("tire_radius_1mm.toml", None),
    // Found by fuzzing: a plausible 33 m tyre of the default density weighs more than the
    // plausible 1e6 kg; the world loaded and then could not be built.
    (
        "tire_radius_33.toml",
        Some(
            "tire_radius_33.toml:1:1: invalid 'vehicle': this car cannot be built: invalid \
             wheel.mass = 1026358.3199277855: must be within 0.001 to 1000000 kg",
        ),
    ),
    (
        "track_front_1e300.toml",
        Some(
            "track_front_1e300.toml:3:1: invalid 'vehicle.trackFront': implausible 'trackFront' \
             value 1e300 (must be within 0.001 to 1000 m)",
        ),
    ),
    (
        "translation_1e300.toml",
        Some(
            "translation_1e300.toml:3:1: invalid 'vehicle.translation': implausible \
             'translation' element 0 value 1e300 (must be within -10000 to 10000 m)",
        ),
    ),
    (
        "wheel_mass_1e300.toml",
        Some(
            "wheel_mass_1e300.toml:3:8: invalid 'vehicle.wheels.mass': wheelFrontRight: \
             'physics' must have a mass of 0.001 to 1000000 kg or a density of 1 to 100000 \
             kg/m³ (value 1e300).",
        ),
    ),
    // Issue #37 ("Hardening round 3"): a joints wheel wider than its diameter panicked in
    // parry; a day-long-plus duration or programme step ran forever; a friction past f32::MAX
    // gripped nothing; a gear of 1e300 printed 301 digits. The cast mounting takes the wheel.
    ("cast_tire_radius_100mm.toml", None),
    (
        "duration_1e9.toml",
        Some(
            "duration_1e9.toml:1:1: invalid 'duration': 1000000000 s: must be finite, > 0 and at \
             most 86400 s (a day)",
        ),
    ),
    (
        "ground_friction_1e39.toml",
        Some(
            "ground_friction_1e39.toml:4:1: invalid 'ground.friction': 1e39: must be within 0 to 100",
        ),
    ),
    (
        "joints_thickness_1.toml",
        Some(
            "joints_thickness_1.toml:4:8: invalid 'vehicle.wheels.thickness': tireRadius 0.374 m \
             with thickness 1 m: tireRadius must be at least 0.5 m, half the wheel's thickness: \
             the joints mounting rounds the tread across the whole width (use mounting = \
             \"cast\" for a wheel wider than its diameter)",
        ),
    ),
    (
        "joints_tire_radius_100mm.toml",
        Some(
            "joints_tire_radius_100mm.toml:4:8: invalid 'vehicle.wheels.tireRadius': tireRadius \
             0.1 m with thickness 0.25 m: tireRadius must be at least 0.125 m, half the wheel's \
             thickness: the joints mounting rounds the tread across the whole width (use \
             mounting = \"cast\" for a wheel wider than its diameter)",
        ),
    ),
    (
        "programme_at_1e9.toml",
        Some(
            "programme_at_1e9.toml:4:1: invalid 'vehicle.programme[1].at': 1000000000 s: must be \
             from 0 to 86400 s (a day, the longest run)",
        ),
    ),
    (
        "programme_gear_1e300.toml",
        Some(
            "programme_gear_1e300.toml:5:1: invalid 'vehicle.programme[1].gear': 1e300: must be \
             from -1 to 5",
        ),
    ),
    (
        "robot_programme_at_1e300.toml",
        Some(
            "robot_programme_at_1e300.toml:3:1: invalid 'differential_wheels.programme[1].at': \
             1e300 s: must be from 0 to 86400 s (a day, the longest run)",
        ),
    ),
    (
        "wheelbase_1e-9.toml",
        Some(
            "wheelbase_1e-9.toml:3:1: invalid 'vehicle.wheelbase': implausible 'wheelbase' value \
             1e-9 (must be within 0.001 to 1000 m)",
        ),
    ),
    (
        "wheelbase_1e300.toml",
        Some(
            "wheelbase_1e300.toml:3:1: invalid 'vehicle.wheelbase': implausible 'wheelbase' \
             value 1e300 (must be within 0.001 to 1000 m)",
        ),
    ),
];

fn read(name: &str) -> String {
    std::fs::read_to_string(seeds().join(name)).unwrap()
}

#[test]
fn every_seed_world_has_its_exact_outcome() {
    let mut names: Vec<String> = std::fs::read_dir(seeds())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    let mut listed: Vec<&str> = OUTCOMES.iter().map(|(n, _)| *n).collect();
    listed.sort_unstable();
    assert_eq!(
        names, listed,
        "a seed without an outcome, or an outcome without a seed"
    );
    for (name, outcome) in OUTCOMES {
        let text = read(name);
        match (parse_str(name, &text), outcome) {
            (Ok(_), None) => {}
            (Err(e), Some(message)) => {
                assert_eq!(e.to_string(), message);
                // Every refusal is at load time, about a value, with its key.
                assert!(e.key.is_some() && e.location.is_some(), "{e:?}");
                assert!(
                    matches!(
                        e.kind,
                        WorldFileErrorKind::InvalidValue(_) | WorldFileErrorKind::WrongType { .. }
                    ),
                    "{e:?}"
                );
            }
            (got, _) => panic!("{name}: {got:?}"),
        }
        crate::world_file::check(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
    }
}

/// The car's height (m) after 3 s of standing in the world of seed `name`.
fn ride_height(name: &str, basic_time_step_ms: Option<u32>) -> f64 {
    let mut world = parse_str(name, &read(name)).unwrap();
    if let Some(ms) = basic_time_step_ms {
        world.config.basic_time_step_ms = ms;
    }
    let mut b = build(&world).unwrap();
    let car = b.car.unwrap();
    let steps = 3000 / world.config.basic_time_step_ms;
    for _ in 0..steps {
        step(&mut b.sim).unwrap();
    }
    b.sim.telemetry(car).unwrap().state.position.z
}

#[test]
fn a_truck_at_100_ms_stands_at_its_ride_height() {
    // The review's Truck sank to −2.0 m at basicTimeStep 100 ms. Within 1 cm of its height at
    // 10 ms on both mountings: the springs hold the same weight, only the accuracy changes.
    for name in [
        "basic_time_step_100_truck.toml",
        "basic_time_step_100_truck_joints.toml",
    ] {
        let (z100, z10) = (ride_height(name, None), ride_height(name, Some(10)));
        assert!(
            z100 > 0.0 && (z100 - z10).abs() < 0.01,
            "{name}: {z100} m vs {z10} m"
        );
    }
}

#[test]
fn an_empty_world_spec_is_the_default_world() {
    // `--world ''` failed while an empty VEHICLE_WORLD meant the default world.
    let w = world_file::load("").unwrap();
    assert_eq!(w, world_file::default_world());
}

#[test]
fn an_infinite_robot_speed_is_refused_like_the_driver_s() {
    // `wb_differential_wheels_set_speed(inf, 0)` was accepted and the getters returned ±inf.
    let world = parse_str("robot.toml", &read("robot_physics.toml")).unwrap();
    let mut b = build(&world).unwrap();
    let robot: &mut DifferentialWheels = b.sim.world_mut().robot_mut(b.robot.unwrap()).unwrap();
    assert_eq!(robot.set_speed(1.0, 2.0), None);
    for (l, r, argument, value) in [
        (f64::INFINITY, 0.0, "left", f64::INFINITY),
        (0.0, f64::NEG_INFINITY, "right", f64::NEG_INFINITY),
    ] {
        let w = robot.set_speed(l, r).unwrap();
        assert_eq!(
            w,
            RobotWarning::Infinite {
                function: "wb_differential_wheels_set_speed",
                argument,
                value
            }
        );
        assert_eq!((robot.left_speed(), robot.right_speed()), (1.0, 2.0));
    }
    for _ in 0..10 {
        step(&mut b.sim).unwrap();
    }
}

#[test]
fn the_fuzz_dictionary_has_every_car_key() {
    // The coverage-guided `world_file` target finds structure through this dictionary: a Car
    // field added without its entry would be fuzzed only by chance.
    let dict = std::fs::read_to_string(seeds().join("../../world_file.dict")).unwrap();
    let mut keys: Vec<String> = vehicle_model::CarParams::<f64>::FIELD_NAMES
        .map(String::from)
        .to_vec();
    for slot in vehicle_model::CarParams::<f64>::WHEEL_SLOT_NAMES {
        for field in vehicle_model::CarParams::<f64>::WHEEL_FIELD_NAMES {
            keys.push(format!("{slot}.{field}"));
        }
    }
    for key in keys {
        assert!(dict.lines().any(|l| l == format!("\"{key}\"")), "{key}");
    }
}

#[test]
fn the_coverage_guided_target_s_crashes_pass_the_invariants() {
    // Inputs on which `cargo fuzz run world_file` once panicked, byte for byte (both were
    // annotate-snippets 0.11 overflowing while an error was rendered). Each passes every
    // invariant of the target now, its rendering included.
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz/crashes");
    let mut count = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let text = String::from_utf8_lossy(&std::fs::read(&path).unwrap()).into_owned();
        crate::world_file::check(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        count += 1;
    }
    assert!(count >= 2, "the crash inputs are missing");
}
