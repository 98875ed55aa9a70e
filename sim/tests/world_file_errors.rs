//! World-file errors: every kind of error and refusal with its file, line, key and
//! suggestions, and the located warnings of invalid car values.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::world_file::{self, Location, WorldFileError, WorldFileErrorKind, parse_str};
use vehicle_model::Model;

fn err(text: &str) -> WorldFileError {
    parse_str("w.toml", text).expect_err("the world should be rejected")
}

fn at(line: u32, column: u32) -> Option<Location> {
    Some(Location { line, column })
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
        text.starts_with("'Nope' is neither a world file, a shipped world nor a vehicle model"),
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
fn brake_balance_names_shares_and_refusals() {
    use vehicle_model::BrakeBalance;
    let read = |value: &str| {
        let w = parse_str("w.toml", &format!("[vehicle]\nbrake_balance = {value}\n")).unwrap();
        w.cars[0].brake_balance
    };
    assert_eq!(
        parse_str("w.toml", "[vehicle]\n").unwrap().cars[0].brake_balance,
        BrakeBalance::Equal
    );
    assert_eq!(read("\"equal\""), BrakeBalance::Equal);
    assert_eq!(read("\"proportioned\""), BrakeBalance::Proportioned);
    assert_eq!(read("0.65"), BrakeBalance::FrontShare(0.65));
    assert_eq!(read("1"), BrakeBalance::FrontShare(1.0));
    let e = err("[vehicle]\nbrake_balance = \"propotioned\"\n");
    assert_eq!(
        (e.location, e.key.as_deref()),
        (at(2, 1), Some("vehicle.brake_balance"))
    );
    assert_eq!(e.suggestions(), ["proportioned"]);
    let e = err("[vehicle]\nbrake_balance = 1.2\n");
    assert_eq!(e.key.as_deref(), Some("vehicle.brake_balance"));
    assert!(e.to_string().contains("in [0, 1], not 1.2"), "{e}");
    let e = err("[vehicle]\nbrake_balance = true\n");
    assert!(
        matches!(e.kind, WorldFileErrorKind::WrongType { .. }),
        "{e}"
    );
    // A misspelt key suggests it.
    let e = err("[vehicle]\nbrake_balanc = 0.6\n");
    assert_eq!(e.suggestions(), ["brake_balance"]);
    // The simulator's driver brakes with it.
    let w = parse_str("w.toml", "[vehicle]\nbrake_balance = 0.7\n").unwrap();
    let mut sim = sim::Simulation::new(sim::World::new(w.config.clone()).unwrap());
    let (id, _) = sim.add_car(sim::CarBuilder::from(&w.cars[0])).unwrap();
    assert_eq!(sim.driver(id).unwrap().brake_front_share(), 0.7);
}

/// The world-file reproducers of issue #37 ("Hardening round 3"), refused with their file,
/// line and key; the values at the bounds load.
mod hardening_round_3 {
    use super::*;
    use sim::{CarBuilder, Mounting, ParamError, Rule, SimError, Simulation, World};

    const JOINTS_BMW: &str = "[vehicle]\nmodel = \"BmwX5\"\nmounting = \"joints\"\n";

    #[test]
    fn a_joints_wheel_wider_than_its_diameter_is_refused_by_the_key_that_made_it() {
        // It panicked in parry's cylinder (exit 101).
        let e = err(&format!("{JOINTS_BMW}wheels.tireRadius = 0.1\n"));
        assert_eq!(e.location, at(4, 8));
        assert_eq!(e.key.as_deref(), Some("vehicle.wheels.tireRadius"));
        assert_eq!(
            e.to_string(),
            "w.toml:4:8: invalid 'vehicle.wheels.tireRadius': tireRadius 0.1 m with thickness \
             0.25 m: tireRadius must be at least 0.125 m, half the wheel's thickness: the \
             joints mounting rounds the tread across the whole width (use mounting = \"cast\" \
             for a wheel wider than its diameter)"
        );
        let e = err(&format!(
            "{JOINTS_BMW}[vehicle.wheelRearLeft]\nthickness = 1\n"
        ));
        assert_eq!(e.location, at(5, 1));
        assert_eq!(e.key.as_deref(), Some("vehicle.wheelRearLeft.thickness"));
        // Half the thickness exactly builds.
        let w = parse_str(
            "w.toml",
            &format!("{JOINTS_BMW}wheels.tireRadius = 0.125\n"),
        );
        let (mut sim, _) = Simulation::from_description(&w.unwrap()).unwrap();
        for _ in 0..10 {
            sim.step().unwrap();
        }
    }

    #[test]
    fn the_cast_mounting_honours_a_wheel_wider_than_its_diameter() {
        let text = "[vehicle]\nmodel = \"BmwX5\"\nwheels.tireRadius = 0.1\n";
        let w = parse_str("w.toml", text).unwrap();
        assert_eq!(w.cars[0].mounting, Mounting::Cast);
        let (mut sim, _) = Simulation::from_description(&w).unwrap();
        let id = sim.car_ids().next().unwrap();
        for _ in 0..100 {
            sim.step().unwrap();
        }
        let state = *sim.world().vehicle(id).unwrap().state();
        assert!(
            state.position.z.is_finite() && state.position.z > 0.0,
            "{state:?}"
        );
        // The same car on joints, added from Rust: the typed error naming the field.
        let mut car = w.cars[0].clone();
        car.mounting = Mounting::Joints;
        let mut sim = Simulation::new(World::new(w.config.clone()).unwrap());
        let e = sim.add_car(CarBuilder::from(&car)).unwrap_err();
        let SimError::Param(ParamError { field, value, rule }) = e else {
            panic!("{e:?}");
        };
        assert_eq!((field, value), ("tireRadius", 0.1));
        assert!(
            matches!(rule, Rule::AtLeast { bound, .. } if bound == 0.125),
            "{rule:?}"
        );
        assert_eq!(sim.car_ids().count(), 0);
    }

    #[test]
    fn durations_and_programme_times_past_a_day_are_refused() {
        let e = err("duration = 1e9\n[vehicle]\n");
        assert_eq!(
            e.to_string(),
            "w.toml:1:1: invalid 'duration': 1000000000 s: must be finite, > 0 and at most 86400 s \
             (a day)"
        );
        let e = err("[vehicle]\n[[vehicle.programme]]\nat = 1e9\nthrottle = 1\n");
        assert_eq!(
            e.to_string(),
            "w.toml:3:1: invalid 'vehicle.programme[1].at': 1000000000 s: must be from 0 to 86400 s \
             (a day, the longest run)"
        );
        let e = err(
            "[differential_wheels]\n[[differential_wheels.programme]]\nat = 1e300\n\
             speed = [1, 1]\n",
        );
        assert_eq!(
            e.key.as_deref(),
            Some("differential_wheels.programme[1].at")
        );
        assert_eq!(e.location, at(3, 1));
        let w = parse_str(
            "w.toml",
            "duration = 86400\n[vehicle]\n[[vehicle.programme]]\nat = 86400\nthrottle = 1\n",
        )
        .unwrap();
        assert_eq!(w.duration, Some(sim::MAX_DURATION));
        // From Rust, the same bound.
        let mut sim = Simulation::new(World::new(w.config.clone()).unwrap());
        let e = sim.set_duration(Some(1e9)).unwrap_err();
        assert_eq!((e.field, e.value), ("duration", 1e9));
        assert_eq!(sim.duration(), None);
        sim.set_duration(Some(86_400.0)).unwrap();
    }

    #[test]
    fn frictions_the_physics_cannot_honour_are_refused() {
        // 1e39 is past f32::MAX: rapier's friction became infinite and the tyre gripped
        // nothing (0.0108 km/h after 60 s of full throttle).
        let e = err("[vehicle]\n[ground]\nfriction = 1e39\n");
        assert_eq!(
            e.to_string(),
            "w.toml:3:1: invalid 'ground.friction': 1e39: must be within 0 to 100"
        );
        let e = err(
            "[vehicle]\n[[ramp]]\nstart = [5, 0]\nlength = 5\nwidth = 3\nheight = 1\n\
                     friction = 101\n",
        );
        assert_eq!(e.key.as_deref(), Some("ramp[1].friction"));
        assert_eq!(e.location, at(7, 1));
        let e = err(
            "[vehicle]\n[[box]]\ntranslation = [9, 0, 1]\nsize = [1, 1, 1]\n\
                     friction = 1e300\n",
        );
        assert_eq!(e.key.as_deref(), Some("box[1].friction"));
        let e = err(
            "[vehicle]\n[[body]]\ntranslation = [9, 0, 1]\nsize = [1, 1, 1]\n\
                     mass = 10\nfriction = 1e39\n",
        );
        assert_eq!(
            e.to_string(),
            "w.toml:6:1: invalid 'body[1].friction': 1e39: must be within 0 to 100"
        );
        // Negative frictions keep their message; the bound itself loads.
        let e = err("[vehicle]\n[ground]\nfriction = -1\n");
        assert_eq!(
            e.message().to_string(),
            "invalid 'ground.friction': -1: must be finite and >= 0"
        );
        let w = parse_str("w.toml", "[vehicle]\n[ground]\nfriction = 100\n").unwrap();
        assert_eq!(w.config.ground_friction, 100.0);
    }

    #[test]
    fn numbers_in_messages_are_compact() {
        let e = err("[vehicle]\n[[vehicle.programme]]\nat = 0\ngear = 1e300\n");
        assert_eq!(
            e.to_string(),
            "w.toml:4:1: invalid 'vehicle.programme[1].gear': 1e300: must be from -1 to 5"
        );
        let e = err(
            "[differential_wheels]\nspeedUnit = 1e-300\n[[differential_wheels.programme]]\n\
             at = 0\nspeed = [1e302, 0]\n",
        );
        let m = e.to_string();
        assert!(m.len() < 200, "{} characters: {m}", m.len());
        assert!(m.ends_with("invalid 'differential_wheels.programme[1].speed': 1e302: each \
                             wheel speed must be within ±9.999999999999999e300 speed units (maxSpeed / \
                             speedUnit)"),
            "{m}");
    }

    #[cfg(unix)]
    #[test]
    fn an_endless_file_is_read_no_further_than_the_bound() {
        // It read /dev/zero until memory ran out (2.1 GB).
        let e = world_file::load("/dev/zero").unwrap_err();
        assert_eq!(
            e.to_string(),
            "/dev/zero: cannot read the world file: it is longer than 16 MiB, the most a world \
             or sweep file may hold"
        );
        assert_eq!(world_file::MAX_FILE_BYTES, 16 * 1024 * 1024);
    }
}
