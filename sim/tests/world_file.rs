//! World-file loading: the default world, overrides, the DifferentialWheels section, obstacles,
//! files on disk and the shipped example worlds (the errors: `world_file_errors.rs`).

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::nalgebra::{Point2, Point3, Vector3};
use sim::world_file::{self, DEFAULT_WORLD, WorldFileError, parse_str};
use sim::{Obstacle, RobotMode};
use vehicle_model::{DriveType, Model};

fn err(text: &str) -> WorldFileError {
    parse_str("w.toml", text).expect_err("the world should be rejected")
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
                radar_cross_section: 0.0,
            },
            Obstacle::Ramp {
                start: Point2::new(30.0, 0.0),
                yaw: 0.0,
                length: 10.0,
                width: 4.0,
                height: 1.0,
                friction: Some(0.6),
                radar_cross_section: 0.0,
            },
        ]
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
