//! World-file loading: the default world, overrides, the DifferentialWheels section, obstacles,
//! and every kind of error with its file, line, key and suggestions.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::nalgebra::{Point2, Point3, Vector3};
use sim::world_file::{
    self, DEFAULT_WORLD, Location, WorldFileError, WorldFileErrorKind, parse_str,
};
use sim::{Obstacle, RobotMode};
use vehicle_model::{DriveType, Model};

fn err(text: &str) -> WorldFileError {
    parse_str("w.toml", text).expect_err("the world should be rejected")
}

fn at(line: u32, column: u32) -> Option<Location> {
    Some(Location { line, column })
}

#[test]
fn default_world_is_a_bmw_x5_on_flat_ground() {
    let w = world_file::default_world();
    assert_eq!(w.config.basic_time_step_ms, 10);
    assert_eq!(w.config.ground_friction, 1.0);
    assert!(w.config.obstacles.is_empty());
    assert_eq!(w.duration, None);
    let car = w.car().unwrap();
    assert_eq!(car.model, Model::BmwX5);
    assert_eq!(car.params, Model::BmwX5.params::<f64>());
    assert!(w.warnings.is_empty());
    // The embedded text parses to the same world.
    let parsed = parse_str("d.toml", DEFAULT_WORLD).unwrap();
    assert_eq!((parsed.config, parsed.cars), (w.config, w.cars));
}

#[test]
fn gravity_must_point_down_and_stay_below_100() {
    for g in ["-9.81", "1e300"] {
        let e = err(&format!("gravity = {g}\n[vehicle]\nmodel = \"BmwX5\"\n"));
        // Numbers in compact form: `1e300`, not 301 digits.
        assert_eq!(
            e.to_string(),
            format!(
                "w.toml:1:1: invalid 'gravity': {g} m/s²: must be from 0 to 100 (the magnitude \
                 of a gravity pointing down)"
            )
        );
    }
    // Built in Rust: the vector's size and direction.
    let up = sim::WorldConfig {
        gravity: Vector3::new(0.0, 0.0, 9.81),
        ..sim::WorldConfig::default()
    };
    assert_eq!(up.validate().unwrap_err().field, "gravity");
    assert!(sim::World::new(up).is_err());
}

#[test]
fn an_empty_spec_is_the_default_world() {
    // As an empty VEHICLE_WORLD is in the C API, so `vehicle-sim --world ''` is.
    for spec in ["", "  "] {
        let w = world_file::load(spec).unwrap();
        assert_eq!(w.car().unwrap().model, Model::BmwX5);
        assert_eq!(w.source, world_file::default_world().source);
    }
}

#[test]
fn a_list_element_of_the_wrong_type_is_named() {
    let e = err("[vehicle]\nmodel = \"BmwX5\"\ngearRatio = [1, \"a\"]\n");
    assert_eq!(
        e.to_string(),
        "w.toml:3:1: 'vehicle.gearRatio' takes a number at element 2, found a string"
    );
}

#[test]
fn a_model_name_is_the_default_world_with_that_car() {
    let w = world_file::load("ToyotaPrius").unwrap();
    let car = w.car().unwrap();
    assert_eq!(car.model, Model::ToyotaPrius);
    assert_eq!(car.params.wheelbase, 2.8);
    assert_eq!(w.config.basic_time_step_ms, 10);
    assert_eq!(w.source, "<default world with ToyotaPrius>");
}

#[test]
fn overrides_reach_the_car_params() {
    let w = parse_str(
        "w.toml",
        r#"
basicTimeStep = 16
duration = 12.5
gravity = 9.8
[vehicle]
model = "BmwX5"
time0To100 = 7.5
gearRatio = [-12.5, 12.5, 8, 5.35, 4.3, 4]
type = "4x4"
wheels.mass = 25
[vehicle.wheelRearLeft]
tireRadius = 0.38
[ground]
friction = 0.8
"#,
    )
    .unwrap();
    assert_eq!(w.config.basic_time_step_ms, 16);
    assert_eq!(w.duration, Some(12.5));
    assert_eq!(w.config.gravity, Vector3::new(0.0, 0.0, -9.8));
    assert_eq!(w.config.ground_friction, 0.8);
    let p = &w.car().unwrap().params;
    assert_eq!(p.time_0_to_100, 7.5);
    assert_eq!(&p.gear_ratios[..], &[-12.5, 12.5, 8.0, 5.35, 4.3, 4.0]);
    assert_eq!(p.drive_type, DriveType::FourByFour);
    assert_eq!(p.wheels.0[3].tire_radius, 0.38);
    assert_eq!(p.wheels.0[0].tire_radius, 0.374);
    for wheel in p.wheels.iter() {
        assert_eq!(wheel.physics, vehicle_model::WheelPhysics::Mass(25.0));
    }
    assert!(w.warnings.is_empty(), "{:?}", w.warnings);
}

#[test]
fn vehicle_without_model_is_the_plain_car() {
    let w = parse_str("w.toml", "[vehicle]\ntime0To100 = 7\n").unwrap();
    let car = w.car().unwrap();
    assert_eq!(car.model, Model::Car);
    assert_eq!(car.params.wheelbase, 4.0);
    assert_eq!(car.params.time_0_to_100, 7.0);
}

#[test]
fn differential_wheels_section() {
    let w = parse_str(
        "robot.toml",
        r#"
basicTimeStep = 32
[differential_wheels]
axleLength = 0.052
wheelRadius = 0.0205
maxSpeed = 6.28
speedUnit = 0.00628
slipNoise = 0
encoderNoise = 0.01
encoderResolution = 159.23
physics = true
seed = 42
wheelMass = 0.02
translation = [1, 2, 0]
rotation = [0, 0, -1, 0.75]
"#,
    )
    .unwrap();
    assert!(w.cars.is_empty());
    let r = w.robot().unwrap();
    assert_eq!(w.config.basic_time_step_ms, 32);
    assert_eq!(r.params.axle_length, 0.052);
    assert_eq!(r.params.wheel_radius, 0.0205);
    assert_eq!(r.params.speed_unit, 0.00628);
    assert_eq!(r.params.slip_noise, 0.0);
    assert_eq!(r.params.encoder_resolution, 159.23);
    assert_eq!(r.params.seed, 42);
    assert_eq!(r.params.max_acceleration, 10.0); // Webots default kept
    let RobotMode::Physics(body) = r.mode else {
        panic!("expected physics mode");
    };
    assert_eq!(body.wheel_mass, 0.02);
    assert_eq!(body.body_mass, 0.5);
    assert_eq!(
        (r.placement.x, r.placement.y, r.placement.heading),
        (1.0, 2.0, -0.75)
    );
    assert_eq!(w.vehicles_label(), "DifferentialWheels");
    // Kinematics by default.
    let k = parse_str("r.toml", "[differential_wheels]\n").unwrap();
    assert_eq!(k.robot().unwrap().mode, RobotMode::Kinematics);
}

#[test]
fn boxes_and_ramps() {
    let w = parse_str(
        "w.toml",
        r#"
[vehicle]
model = "BmwX5"
[[box]]
translation = [20, 5, 0.5]
size = [2, 4, 1]
rotation = [0, 0, 1, 0.3]
[[ramp]]
start = [30, 0]
length = 10
width = 4
height = 1
friction = 0.6
"#,
    )
    .unwrap();
    assert_eq!(
        w.config.obstacles,
        vec![
            Obstacle::Box {
                center: Point3::new(20.0, 5.0, 0.5),
                half_extents: Vector3::new(1.0, 2.0, 0.5),
                yaw: 0.3,
                friction: None,
            },
            Obstacle::Ramp {
                start: Point2::new(30.0, 0.0),
                yaw: 0.0,
                length: 10.0,
                width: 4.0,
                height: 1.0,
                friction: Some(0.6),
            },
        ]
    );
}

#[test]
fn unknown_key_names_file_line_key_and_closest_names() {
    let e = err("basicTimeStep = 10\n[vehicle]\nmodel = \"BmwX5\"\ntimeTo100 = 7.0\n");
    assert_eq!(e.file, "w.toml");
    assert_eq!(e.location, at(4, 1));
    assert_eq!(e.key.as_deref(), Some("vehicle.timeTo100"));
    assert_eq!(e.suggestions(), ["time0To100"]);
    assert_eq!(
        e.to_string(),
        "w.toml:4:1: unknown key 'vehicle.timeTo100'; did you mean 'time0To100'?"
    );
    // Top level, case slip.
    let e = err("basictimestep = 10\n");
    assert_eq!(e.location, at(1, 1));
    assert_eq!(e.suggestions(), ["basicTimeStep"]);
    // A wheel field.
    let e = err("[vehicle]\n[vehicle.wheels]\ntireRadus = 0.3\n");
    assert_eq!(e.location, at(3, 1));
    assert_eq!(e.key.as_deref(), Some("vehicle.wheels.tireRadus"));
    assert_eq!(e.suggestions()[0], "tireRadius");
    // A DifferentialWheels field.
    let e = err("[differential_wheels]\naxelLength = 0.1\n");
    assert_eq!(e.suggestions(), ["axleLength"]);
    // Nothing close: no suggestion.
    let e = err("[ground]\nzzzzzzzz = 1\n");
    assert!(e.suggestions().is_empty());
    assert_eq!(e.to_string(), "w.toml:2:1: unknown key 'ground.zzzzzzzz'");
    // A box.
    let e = err(
        "[vehicle]\n[[box]]\ntranslation = [0, 0, 0]\nsize = [1, 1, 1]\nrotaton = [0, 0, 1, 0]\n",
    );
    assert_eq!(e.key.as_deref(), Some("box[1].rotaton"));
    assert_eq!(e.location, at(5, 1));
}

#[test]
fn wrong_types() {
    let e = err("basicTimeStep = \"10\"\n[vehicle]\n");
    assert_eq!(e.location, at(1, 1));
    assert_eq!(
        e.kind,
        WorldFileErrorKind::WrongType {
            expected: "a number".into(),
            found: "a string".into()
        }
    );
    assert_eq!(
        e.to_string(),
        "w.toml:1:1: 'basicTimeStep' takes a number, found a string"
    );
    let e = err("[vehicle]\ngearRatio = 4\n");
    assert_eq!(e.location, at(2, 1));
    assert!(
        e.to_string()
            .contains("'vehicle.gearRatio' takes a list of 2 to 16 numbers, found an integer"),
        "{e}"
    );
    let e = err("[vehicle]\ntranslation = [0, 0]\n");
    assert!(
        e.to_string()
            .contains("takes a list of 3 numbers, found a list of 2 values"),
        "{e}"
    );
    let e = err("[vehicle]\nmodel = 5\n");
    assert_eq!(e.key.as_deref(), Some("vehicle.model"));
    let e = err("[differential_wheels]\nphysics = 1\n");
    assert!(e.to_string().contains("takes true or false"), "{e}");
    let e = err("vehicle = 3\n");
    assert!(e.to_string().contains("'vehicle' takes a table"), "{e}");
    let e = err("[vehicle]\ntype = \"6x6\"\n");
    assert!(matches!(e.kind, WorldFileErrorKind::InvalidValue(_)), "{e}");
    assert!(e.to_string().contains("\"6x6\""), "{e}");
}

#[test]
fn malformed_toml_is_located() {
    let e = err("basicTimeStep = 10\n[vehicle\nmodel = \"BmwX5\"\n");
    assert!(matches!(e.kind, WorldFileErrorKind::Syntax(_)), "{e:?}");
    assert_eq!(e.location.map(|l| l.line), Some(2));
    assert!(e.to_string().starts_with("w.toml:2:"), "{e}");
    let e = err("a = 1\na = 2\n");
    assert_eq!(e.location.map(|l| l.line), Some(2));
}

#[test]
fn unknown_model_suggests_shipped_models() {
    let e = err("[vehicle]\nmodel = \"BMWX5\"\n");
    assert_eq!(e.location, at(2, 1));
    assert_eq!(
        e.kind,
        WorldFileErrorKind::UnknownModel {
            name: "BMWX5".into(),
            suggestions: vec!["BmwX5".into()],
        }
    );
    assert_eq!(
        e.to_string(),
        "w.toml:2:1: unknown vehicle model 'BMWX5'; did you mean 'BmwX5'?"
    );
    // `--world` with a misspelt model name.
    let e = world_file::load("ToyotaPrious").unwrap_err();
    assert_eq!(e.suggestions(), ["ToyotaPrius"]);
}

#[test]
fn a_name_that_is_neither_file_nor_model_lists_the_models() {
    // Before: "Nope: cannot read the world file: No such file or directory".
    let e = world_file::load("Nope").unwrap_err();
    let WorldFileErrorKind::NeitherFileNorModel { name, .. } = &e.kind else {
        panic!("{e:?}");
    };
    assert_eq!(name, "Nope");
    let text = e.to_string();
    for m in Model::ALL {
        assert!(text.contains(m.webots_name()), "{text}");
    }
    assert!(
        text.starts_with("'Nope' is neither a world file nor a vehicle model"),
        "{text}"
    );
    assert!(
        text.contains("BmwX5") && text.contains("ToyotaPrius"),
        "{text}"
    );
    // A path is a path: the system's message.
    let e = world_file::load("missing/w.toml").unwrap_err();
    assert!(matches!(e.kind, WorldFileErrorKind::Io(_)), "{e:?}");
}

#[test]
fn invalid_values() {
    // Rejected by the simulator: errors naming the key.
    let e = err("basicTimeStep = 0\n[vehicle]\n");
    assert_eq!(
        (e.location, e.key.as_deref()),
        (at(1, 1), Some("basicTimeStep"))
    );
    let e = err("basicTimeStep = 2.5\n[vehicle]\n");
    assert!(
        e.to_string().contains("whole number of milliseconds"),
        "{e}"
    );
    let e = err("duration = -1\n[vehicle]\n");
    assert_eq!(e.key.as_deref(), Some("duration"));
    let e = err("[vehicle]\n[ground]\nfriction = -0.5\n");
    assert_eq!(
        (e.location, e.key.as_deref()),
        (at(3, 1), Some("ground.friction"))
    );
    let e = err("[vehicle]\n[[ramp]]\nstart = [0, 0]\nlength = 5\nwidth = 3\nheight = -1\n");
    assert_eq!(
        (e.location, e.key.as_deref()),
        (at(6, 1), Some("ramp[1].height"))
    );
    let e = err("[vehicle]\n[[box]]\ntranslation = [0, 0, 0]\nsize = [1, 0, 1]\n");
    assert_eq!(e.key.as_deref(), Some("box[1].size"));
    let e = err(
        "[vehicle]\n[[box]]\ntranslation = [0, 0, 0]\nsize = [1, 1, 1]\nrotation = [1, 0, 0, 0.5]\n",
    );
    assert!(e.to_string().contains("vertical axis"), "{e}");
    let e = err("[vehicle]\n[[ramp]]\nstart = [0, 0]\nlength = 5\nwidth = 3\n");
    assert!(
        e.to_string().contains("missing key 'ramp[1].height'"),
        "{e}"
    );
    let e = err("[differential_wheels]\naxleLength = -0.1\n");
    assert_eq!(
        (e.location, e.key.as_deref()),
        (at(2, 1), Some("differential_wheels.axleLength"))
    );
    let e = err("[differential_wheels]\nseed = -3\n");
    assert_eq!(e.key.as_deref(), Some("differential_wheels.seed"));
    let e = err("[differential_wheels]\nbodyMass = 2\n");
    assert!(
        e.to_string().contains("only applies with physics = true"),
        "{e}"
    );
    // Structure.
    let e = err("basicTimeStep = 10\n");
    assert!(
        e.to_string()
            .contains("no [vehicle], [[vehicle]] or [differential_wheels]"),
        "{e}"
    );
    // A car and the robot share a world (before: "not both"); names must differ.
    let w = parse_str("w.toml", "[vehicle]\n[differential_wheels]\n").unwrap();
    assert_eq!(w.vehicle_names(), ["Car", "DifferentialWheels"]);
    let e = err("[vehicle]\nname = \"x\"\n[differential_wheels]\nname = \"x\"\n");
    assert_eq!(
        (e.location, e.key.as_deref()),
        (at(4, 1), Some("differential_wheels.name"))
    );
}

#[test]
fn invalid_car_values_are_replaced_with_located_warnings() {
    // As Webots: an invalid car field falls back to the model's default with a warning.
    let w = parse_str(
        "w.toml",
        "[vehicle]\nmodel = \"BmwX5\"\n\nwheelbase = -2\n[vehicle.wheelFrontLeft]\nthickness = 0\n",
    )
    .unwrap();
    let p = &w.car().unwrap().params;
    assert!(p.wheelbase > 0.0);
    assert!(w.warnings.len() >= 2, "{:?}", w.warnings);
    let wb = &w.warnings[0];
    assert_eq!(wb.location, at(4, 1));
    assert_eq!(wb.key.as_deref(), Some("vehicle.wheelbase"));
    assert!(wb.to_string().starts_with("w.toml:4:1: "), "{wb}");
    assert!(wb.message.contains("wheelbase"), "{wb}");
    let wheel = w
        .warnings
        .iter()
        .find(|w| w.key.as_deref() == Some("vehicle.wheelFrontLeft.thickness"))
        .expect("a warning for the front-left wheel's thickness");
    assert_eq!(wheel.location, at(6, 1));
    assert!(wheel.message.contains("thickness"), "{wheel}");
    // Set for all four wheels at once with a dotted key: located at its last part.
    let w = parse_str("w.toml", "[vehicle]\nwheels.tireRadius = -1\n").unwrap();
    assert!(!w.warnings.is_empty());
    for warning in &w.warnings {
        assert_eq!(warning.location, at(2, 8), "{warning}");
        assert_eq!(warning.key.as_deref(), Some("vehicle.wheels.tireRadius"));
    }
}

#[test]
fn implausible_values_are_refused_with_file_line_and_key() {
    // Webots loads these and fails at the first step (or reports a negative stop distance);
    // a world file refuses them before anything runs.
    let cases = [
        (
            "mass = 1e300",
            "vehicle.mass",
            at(3, 1),
            "implausible 'mass' value 1e300 (must be within 0.001 to 1000000 kg)",
        ),
        ("mass = 1e-300", "vehicle.mass", at(3, 1), "value 1e-300"),
        (
            "wheelbase = 1e-9",
            "vehicle.wheelbase",
            at(3, 1),
            "must be within 0.001 to 1000 m",
        ),
        (
            "trackFront = 1e300",
            "vehicle.trackFront",
            at(3, 1),
            "trackFront",
        ),
        (
            "centerOfMass = [1e300, 0, 0]",
            "vehicle.centerOfMass",
            at(3, 1),
            "element 0 value 1e300",
        ),
        (
            "translation = [1e300, 0, 0]",
            "vehicle.translation",
            at(3, 1),
            "within -10000 to 10000 m",
        ),
        (
            "suspensionFrontSpringConstant = 1e300",
            "vehicle.suspensionFrontSpringConstant",
            at(3, 1),
            "N/m",
        ),
        (
            "gearRatio = [-12.5, 1e6]",
            "vehicle.gearRatio",
            at(3, 1),
            "its magnitude must be within 0.1 to 100",
        ),
        (
            "inertiaMatrix = [1e300, 1e300, 1e300, 0, 0, 0]",
            "vehicle.inertiaMatrix",
            at(3, 1),
            "kg·m²",
        ),
        (
            "wheelFrontLeft.tireRadius = 1e300",
            "vehicle.wheelFrontLeft.tireRadius",
            at(3, 16),
            "'tireRadius' must be within 0.001 to 1000 m (value 1e300)",
        ),
        (
            "wheels.mass = 1e9",
            "vehicle.wheels.mass",
            at(3, 8),
            "'physics' must have a mass of 0.001 to 1000000 kg",
        ),
    ];
    for (line, key, location, text) in cases {
        let e = err(&format!("[vehicle]\nmodel = \"BmwX5\"\n{line}\n"));
        assert_eq!(
            (e.key.as_deref(), e.location),
            (Some(key), location),
            "{line}: {e}"
        );
        assert!(
            matches!(e.kind, WorldFileErrorKind::InvalidValue(_)),
            "{line}: {e}"
        );
        assert!(e.to_string().contains(text), "{line}: {e}");
    }
    // The robot, the boxes and the ramps likewise.
    for (text, key, message) in [
        (
            "[differential_wheels]\nwheelRadius = 1e300\n",
            "differential_wheels.wheelRadius",
            "1e300: must be within 0.001 to 1000 m",
        ),
        (
            "[differential_wheels]\naxleLength = 1e-9\n",
            "differential_wheels.axleLength",
            "1e-9: must be within 0.001 to 1000 m",
        ),
        (
            "[differential_wheels]\nmaxSpeed = 1e300\n",
            "differential_wheels.maxSpeed",
            "maxSpeed × wheelRadius is at most 1000 m/s",
        ),
        (
            "[vehicle]\n[[box]]\ntranslation = [1e300, 0, 0]\nsize = [1, 1, 1]\n",
            "box[1].translation",
            "1e300: must be within -10000 to 10000 m",
        ),
        (
            "[vehicle]\n[[ramp]]\nstart = [0, 0]\nlength = 1e300\nwidth = 3\nheight = 1\n",
            "ramp[1].length",
            "within 0.001 to 1000 m",
        ),
    ] {
        let e = err(text);
        assert_eq!(e.key.as_deref(), Some(key), "{e}");
        assert!(e.to_string().contains(message), "{e}");
    }
    // The bounds are inclusive: the largest plausible mass loads.
    let w = parse_str("w.toml", "[vehicle]\nmass = 1e6\n").unwrap();
    assert_eq!(w.car().unwrap().params.body.mass, 1e6);
}

#[test]
fn missing_file() {
    let e = world_file::load("/nonexistent/dir/world.toml").unwrap_err();
    assert_eq!(e.file, "/nonexistent/dir/world.toml");
    assert!(matches!(e.kind, WorldFileErrorKind::Io(_)), "{e:?}");
    assert!(
        e.to_string()
            .starts_with("/nonexistent/dir/world.toml: cannot read the world file:")
    );
}

#[test]
fn a_file_on_disk_is_loaded_by_path() {
    let dir = std::env::temp_dir().join(format!("sim-world-file-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("prius.toml");
    std::fs::write(
        &path,
        "[vehicle]\nmodel = \"ToyotaPrius\"\nbrakeCoefficient = 900\n",
    )
    .unwrap();
    let w = world_file::load(path.to_str().unwrap()).unwrap();
    assert_eq!(w.source, path.display().to_string());
    assert_eq!(w.car().unwrap().params.brake_coefficient, 900.0);
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "[vehicle]\nbrakeCoeficient = 900\n").unwrap();
    let e = world_file::load(bad.to_str().unwrap()).unwrap_err();
    assert!(
        e.to_string()
            .starts_with(&format!("{}:2:1: unknown key", bad.display())),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn shipped_example_worlds_load() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("worlds");
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let w = world_file::load(path.to_str().unwrap()).unwrap_or_else(|e| panic!("{e}"));
            assert!(
                w.warnings.is_empty(),
                "{}: {:?}",
                path.display(),
                w.warnings
            );
            n += 1;
        }
    }
    assert!(n >= 3, "example worlds found: {n}");
}
