//! The car's sensors as FMU outputs: the description lists one output per scalar quantity of
//! each device, and each output equals the engine's own reading of the same run, bit for bit.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::Path;

use sim::Simulation;
use sim::world_file;
use vehicle_fmu::devices::{self, FIRST_REFERENCE};
use vehicle_fmu::instance::{Instance, Version};
use vehicle_fmu::package::{self, World};
use vehicle_fmu::variables::{CONTROL_MODE, CRUISING_SPEED, Kind, TIME};

const SENSORS: &str = include_str!("../../sim/worlds/sensors.toml");

#[test]
fn every_device_quantity_is_an_output_equal_to_the_engine_reading() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fmu-devices");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("world.toml"), SENSORS).unwrap();
    let mut fmu = Instance::new("devices", &dir, Version::Fmi3).unwrap();
    fmu.enter_initialisation().unwrap();
    fmu.exit_initialisation().unwrap();
    fmu.set(CONTROL_MODE, Kind::Integer, 0.0).unwrap();
    fmu.set(CRUISING_SPEED, Kind::Real, 5.0).unwrap();

    // The same world natively: the world's samplingPeriod keys enable every device but the
    // display, which has no output (the FMU enables nothing more).
    let description = world_file::parse_str("sensors.toml", SENSORS).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    sim.driver_mut(id).unwrap().set_cruising_speed(5.0 * 3.6);
    let outputs = devices::outputs(sim.devices(id).unwrap());

    // Names: `<device>.<quantity>`, the radar's first targets, value references from 2000.
    let names: Vec<&str> = outputs.iter().map(|o| o.name.as_str()).collect();
    for expected in [
        "gps.x",
        "gps.speed",
        "inertial unit.qw",
        "rear compass.z",
        "distance sensor.value",
        "radar.targets",
        "radar.target3.azimuth",
        "lidar.closest",
        "road sensor.lateral_offset",
    ] {
        assert!(names.contains(&expected), "{expected} in {names:?}");
    }
    assert!(outputs.iter().all(|o| o.reference >= FIRST_REFERENCE));
    assert!(
        !names
            .iter()
            .any(|n| n.starts_with("camera") || n.starts_with("display"))
    );

    for k in 1..=20 {
        fmu.do_step(f64::from(k - 1) * 0.05, 0.05).unwrap();
        for _ in 0..5 {
            sim.step().unwrap();
        }
        let readings = sim.devices(id).unwrap();
        for o in &outputs {
            let native = devices::value(readings, o);
            let served = fmu.get(o.reference, Kind::Real).unwrap();
            assert_eq!(served.to_bits(), native.to_bits(), "{} at step {k}", o.name);
        }
    }
    assert!((fmu.get(TIME, Kind::Real).unwrap() - 1.0).abs() < 1e-9);
    // The car moved, so the GPS reads a speed; the red box is in the radar's and lidar's view.
    let gps_speed = outputs.iter().find(|o| o.name == "gps.speed").unwrap();
    assert!(fmu.get(gps_speed.reference, Kind::Real).unwrap() > 1.0);
    let closest = outputs.iter().find(|o| o.name == "lidar.closest").unwrap();
    assert!(fmu.get(closest.reference, Kind::Real).unwrap().is_finite());
    // An output cannot be set.
    assert!(fmu.set(gps_speed.reference, Kind::Real, 1.0).is_err());

    // The packaged description lists the same outputs.
    let world = World {
        name: "sensors".into(),
        text: SENSORS.into(),
        directory: None,
    };
    let (_, description) = package::describe(&world).unwrap();
    assert_eq!(description.devices, outputs);
}
