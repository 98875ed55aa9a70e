//! The devices' readings in a recorded run's `devices.csv`: the rows are the values
//! `Simulation::devices` gave, at the devices' own sample times, bit for bit; a disabled device
//! writes nothing.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::collections::BTreeMap;

use sim::devices::Reading;
use sim::{Simulation, world_file};

const WORLD: &str = r#"
[vehicle]
model = "BmwX5"
name = "car"
seed = 7
[[vehicle.device]]
type = "GPS"
slot = "top"
accuracy = 0.5
[[vehicle.device]]
type = "Gyro"
slot = "top"
"#;

#[test]
fn gps_rows_are_the_readings_bit_for_bit_and_a_disabled_device_writes_nothing() {
    let description = world_file::parse_str("recording.toml", WORLD).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    // A period that is not the step (10 ms): the rows must follow the device's own times.
    sim.enable_device(id, 0, 30).unwrap();
    sim.driver_mut(id).unwrap().set_cruising_speed(20.0);
    sim.driver_mut(id).unwrap().set_steering_angle(0.15);
    sim.record("circle");
    // Expected rows: the GPS reading after each step whose time is a whole number of periods.
    let mut expected: BTreeMap<u64, [f64; 7]> = BTreeMap::new();
    for _ in 0..400 {
        sim.step().unwrap();
        let t = sim.world().time_ms();
        if t % 30 == 0 {
            let Reading::Gps(g) = sim.devices(id).unwrap()[0].reading().clone() else {
                panic!("device 0 is the GPS");
            };
            let v = g.speed_vector;
            let p = g.position;
            expected.insert(t, [p.x, p.y, p.z, g.speed, v.x, v.y, v.z]);
        }
    }
    let dir = std::env::temp_dir().join(format!("sim-device-recording-{}", std::process::id()));
    let written = sim.save("recording.toml", &[], &dir).unwrap();
    let path = dir.join("devices.csv");
    assert!(written.contains(&path), "{written:?}");

    let mut reader = csv::Reader::from_path(&path).unwrap();
    assert_eq!(
        reader.headers().unwrap(),
        vec!["time", "car", "device", "quantity", "value"]
    );
    let names = [
        "x",
        "y",
        "z",
        "speed",
        "speed_vector_x",
        "speed_vector_y",
        "speed_vector_z",
    ];
    let mut found: BTreeMap<u64, [Option<f64>; 7]> = BTreeMap::new();
    for record in reader.records() {
        let r = record.unwrap();
        assert_eq!(&r[1], "car");
        // The gyro is never enabled: it has no row.
        assert_eq!(&r[2], "gps", "{r:?}");
        let time: f64 = r[0].parse().unwrap();
        let ms = (time * 1000.0).round() as u64;
        let k = names.iter().position(|n| *n == &r[3]).unwrap();
        let slot = &mut found.entry(ms).or_default()[k];
        assert!(slot.is_none(), "two rows of {} at {ms} ms", &r[3]);
        *slot = Some(r[4].parse().unwrap());
    }
    assert_eq!(
        found.keys().collect::<Vec<_>>(),
        expected.keys().collect::<Vec<_>>()
    );
    for (ms, values) in &expected {
        for (k, v) in values.iter().enumerate() {
            let got = found[ms][k].unwrap();
            assert_eq!(got.to_bits(), v.to_bits(), "{} at {ms} ms", names[k]);
        }
    }
    // 4 s at one sample every 30 ms: 133 samples.
    assert_eq!(expected.len(), 133);
    std::fs::remove_dir_all(&dir).unwrap();
}
