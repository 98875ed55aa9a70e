//! `samplingPeriod` on `[[vehicle.device]]`: read and refused with file, line and key; the
//! device sampling from the start of a run without a controller; a `programme` run
//! (`vehicle-sim`'s) writing its readings to `devices.csv` as `Simulation::devices` gives them.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::collections::BTreeMap;

use sim::devices::Reading;
use sim::scenario::{self, Scenario};
use sim::{Simulation, report, world_file};

/// A BmwX5 driving off at 36 km/h with a noisy GPS sampled every 32 ms from the start, on a
/// 16 ms step (the period a whole number of steps, so samples fall at 32, 64, … ms), and a
/// gyro left disabled.
const WORLD: &str = r#"basicTimeStep = 16
duration = 1.0
[vehicle]
model = "BmwX5"
name = "car"
seed = 3
[[vehicle.programme]]
at = 0.0
cruising_speed = 36
[[vehicle.device]]
type = "GPS"
slot = "top"
accuracy = 0.2
samplingPeriod = 32
[[vehicle.device]]
type = "Gyro"
"#;

/// The line, key and message of the error of `text`.
fn refused(text: &str) -> (u32, String, String) {
    let e = world_file::parse_str("w.toml", text).expect_err("the world should be refused");
    let line = e.location.map_or(0, |l| l.line);
    (line, e.key.clone().unwrap_or_default(), e.to_string())
}

#[test]
fn the_key_is_read_and_bad_periods_are_refused_at_their_key() {
    let d = world_file::parse_str("w.toml", WORLD).unwrap();
    let devices = &d.cars[0].devices;
    assert_eq!(devices[0].sampling_period_ms, Some(32));
    assert_eq!(devices[1].sampling_period_ms, None);
    let (mut sim, _) = Simulation::from_description(&d).unwrap();
    let id = sim.car_ids().next().unwrap();
    assert_eq!(sim.devices(id).unwrap()[0].period_ms(), 32);
    assert_eq!(sim.devices(id).unwrap()[1].period_ms(), 0);
    // A controller's devices start disabled, as in Webots (the C and Python controllers).
    sim.disable_devices();
    assert_eq!(sim.devices(id).unwrap()[0].period_ms(), 0);

    // Webots' periods are whole ms sent as u16; 0 (disabled) is what leaving the key out says.
    for (value, why) in [
        ("0", "from 1 to 65535"),
        ("-32", "from 1 to 65535"),
        ("32.5", "whole number"),
        ("65536", "from 1 to 65535"),
        ("nan", "whole number"),
        ("\"32\"", "a number"),
    ] {
        let text =
            format!("[vehicle]\n[[vehicle.device]]\ntype = \"GPS\"\nsamplingPeriod = {value}\n");
        let (line, key, message) = refused(&text);
        assert_eq!(line, 4, "{value}: {message}");
        assert_eq!(key, "vehicle.device[1].samplingPeriod", "{value}");
        assert!(
            message.contains("w.toml") && message.contains(why),
            "{value}: {message}"
        );
    }
    // The bound itself is a period.
    let text = "[vehicle]\n[[vehicle.device]]\ntype = \"GPS\"\nsamplingPeriod = 65535\n";
    assert!(world_file::parse_str("w.toml", text).is_ok());
}

#[test]
fn a_programme_run_writes_the_readings_simulation_devices_gives() {
    let description = world_file::parse_str("gps.toml", WORLD).unwrap();
    // The same world through the API, its driver given the programme's one command: the GPS
    // readings after each step, by time (ms).
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    sim.driver_mut(id).unwrap().set_cruising_speed(36.0);
    let mut expected: BTreeMap<u64, [f64; 7]> = BTreeMap::new();
    let mut unsampled = 0;
    while !sim.is_over() {
        sim.step().unwrap();
        let t = sim.world().time_ms();
        let Reading::Gps(g) = sim.devices(id).unwrap()[0].reading().clone() else {
            panic!("device 0 is the GPS");
        };
        if g.position.x.is_nan() {
            unsampled += 1;
            continue;
        }
        // A sample every whole period; between them the device keeps its last one.
        if t % 32 == 0 {
            let (p, v) = (g.position, g.speed_vector);
            expected.insert(t, [p.x, p.y, p.z, g.speed, v.x, v.y, v.z]);
        }
    }
    // NaN until the first sample at 32 ms: one step of 16 ms.
    assert_eq!(unsampled, 1);

    let run = scenario::run(&description, Scenario::Programme, &mut |_| {}).unwrap();
    let dir = std::env::temp_dir().join(format!("sim-sampling-period-{}", std::process::id()));
    let written = report::write_data(&run, &[], &dir).unwrap();
    let path = dir.join("devices.csv");
    assert_eq!(written[1], path, "{written:?}");
    let metrics = std::fs::read_to_string(dir.join("metrics.json")).unwrap();
    assert!(metrics.contains("\"devices.csv\""), "{metrics}");

    let names = [
        "x",
        "y",
        "z",
        "speed",
        "speed_vector_x",
        "speed_vector_y",
        "speed_vector_z",
    ];
    let mut found: BTreeMap<u64, [f64; 7]> = BTreeMap::new();
    for record in csv::Reader::from_path(&path).unwrap().records() {
        let r = record.unwrap();
        assert_eq!(
            (&r[1], &r[2]),
            ("car", "gps"),
            "the disabled gyro writes nothing"
        );
        let ms = (r[0].parse::<f64>().unwrap() * 1000.0).round() as u64;
        let k = names.iter().position(|n| *n == &r[3]).unwrap();
        found.entry(ms).or_insert([f64::NAN; 7])[k] = r[4].parse().unwrap();
    }
    // Samples every 32 ms from 32 ms to the end (1 s): 31 of them.
    let times: Vec<u64> = found.keys().copied().collect();
    assert_eq!(times, (1..=31).map(|k| 32 * k).collect::<Vec<u64>>());
    // Bit for bit: the same world, seed and commands, and values written in Rust's shortest
    // round-trip form.
    for (t, values) in &found {
        let e = expected
            .get(t)
            .unwrap_or_else(|| panic!("no reading at {t} ms"));
        for (k, (a, b)) in values.iter().zip(e).enumerate() {
            assert_eq!(
                a.to_bits(),
                b.to_bits(),
                "{} at {t} ms: {a} vs {b}",
                names[k]
            );
        }
    }
    assert_eq!(found.len(), expected.len());
    std::fs::remove_dir_all(&dir).unwrap();
}
