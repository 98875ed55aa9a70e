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

/// The rows of `devices.csv` in `dir`, as (time in ms, device, quantity, value).
fn rows(dir: &std::path::Path) -> Vec<(u64, String, String, f64)> {
    let mut reader = csv::Reader::from_path(dir.join("devices.csv")).unwrap();
    reader
        .records()
        .map(|r| {
            let r = r.unwrap();
            let time: f64 = r[0].parse().unwrap();
            (
                (time * 1000.0).round() as u64,
                r[2].to_string(),
                r[3].to_string(),
                r[4].parse().unwrap(),
            )
        })
        .collect()
}

#[test]
fn radar_rows_are_per_target_and_lidar_rows_summarise_the_range_image() {
    // The ACC world: the follower's radar sees the lead car 50 m ahead; a SICK LMS 291 on the
    // follower's front slot sees it too.
    let acc = include_str!("../worlds/acc.toml");
    let text = format!(
        "{acc}\n[[vehicle.device]]\ntype = \"Lidar\"\nname = \"sick\"\nslot = \"front\"\npreset = \"SickLms291\"\n"
    );
    let description = world_file::parse_str("acc.toml", &text).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let follower = sim.car_ids().nth(1).unwrap();
    sim.enable_device(follower, 0, 50).unwrap();
    sim.enable_device(follower, 1, 100).unwrap();
    sim.record("acc");
    // The readings after each sampling step, as the API gives them.
    let mut radar: Vec<(u64, Vec<sim::devices::RadarTarget>)> = Vec::new();
    let mut lidar: Vec<(u64, Vec<f32>)> = Vec::new();
    for _ in 0..50 {
        sim.step().unwrap();
        let t = sim.world().time_ms();
        let devices = sim.devices(follower).unwrap();
        if t % 50 == 0 {
            let Reading::Radar(Some(targets)) = devices[0].reading().clone() else {
                panic!("device 0 is the radar, sampled at {t} ms");
            };
            radar.push((t, targets));
        }
        if t % 100 == 0 {
            let Reading::Lidar(r) = devices[1].reading().clone() else {
                panic!("device 1 is the lidar");
            };
            lidar.push((t, r.range_image));
        }
    }
    let dir = std::env::temp_dir().join(format!("sim-device-recording-acc-{}", std::process::id()));
    sim.save("acc.toml", &[], &dir).unwrap();
    let rows = rows(&dir);

    let mut expected = Vec::new();
    for (t, targets) in &radar {
        expected.push((*t, "radar", "targets".to_string(), targets.len() as f64));
        for (k, target) in targets.iter().enumerate() {
            for (name, v) in [
                ("distance", target.distance),
                ("received_power", target.received_power),
                ("speed", target.speed),
                ("azimuth", target.azimuth),
            ] {
                expected.push((*t, "radar", format!("target{k}.{name}"), v));
            }
        }
    }
    for (t, image) in &lidar {
        let returns: Vec<f32> = image.iter().copied().filter(|r| r.is_finite()).collect();
        expected.push((*t, "sick", "returns".to_string(), returns.len() as f64));
        if let Some(closest) = returns.iter().copied().reduce(f32::min) {
            expected.push((*t, "sick", "closest".to_string(), f64::from(closest)));
        }
    }
    // The file is in time order, the devices of one time in the car's order.
    expected.sort_by_key(|(t, device, _, _)| (*t, *device == "sick"));
    let got: Vec<(u64, &str, &str, u64)> = rows
        .iter()
        .map(|(t, d, q, v)| (*t, d.as_str(), q.as_str(), v.to_bits()))
        .collect();
    let want: Vec<(u64, &str, &str, u64)> = expected
        .iter()
        .map(|(t, d, q, v)| (*t, *d, q.as_str(), v.to_bits()))
        .collect();
    assert_eq!(got, want);
    // The lead car is seen: one radar target from the first sample on, lidar returns.
    assert!(radar.iter().all(|(_, targets)| targets.len() == 1));
    assert!(
        rows.iter()
            .any(|(_, d, q, v)| d == "sick" && q == "returns" && *v > 0.0)
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
