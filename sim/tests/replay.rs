//! `replay.glb` read back with the `gltf` crate: one animation per scenario, keyframe times,
//! the chassis' last pose against the telemetry, lights, several cars, size.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use gltf::animation::util::ReadOutputs;
use sim::replay::{self, MAX_KEYFRAME_RATE, Part, Recorder};
use sim::scenario::{self, RunReport, Scenario};
use sim::world_file::{self, WorldDescription};
use sim::{Simulation, VehiclePlacement, World, WorldConfig};
use vehicle_model::{IndicatorState, Model};

/// One channel read back: target node name, property, keyframe times (s) and values.
struct Track {
    node: String,
    property: &'static str,
    times: Vec<f32>,
    values: Vec<Vec<f32>>,
}

/// Every animation of a .glb: its name and its channels.
fn animations(glb: &[u8]) -> Vec<(String, Vec<Track>)> {
    let doc = gltf::Gltf::from_slice(glb).expect("valid glTF");
    let blob = doc.blob.clone().expect("binary chunk");
    doc.animations()
        .map(|a| {
            let tracks = a
                .channels()
                .map(|c| {
                    let reader = c.reader(|_| Some(&blob));
                    let times: Vec<f32> = reader.read_inputs().unwrap().collect();
                    let (property, values): (_, Vec<Vec<f32>>) =
                        match reader.read_outputs().unwrap() {
                            ReadOutputs::Translations(v) => {
                                ("translation", v.map(|x| x.to_vec()).collect())
                            }
                            ReadOutputs::Rotations(r) => {
                                ("rotation", r.into_f32().map(|x| x.to_vec()).collect())
                            }
                            ReadOutputs::Scales(v) => ("scale", v.map(|x| x.to_vec()).collect()),
                            ReadOutputs::MorphTargetWeights(_) => panic!("no morph targets"),
                        };
                    Track {
                        node: c.target().node().name().unwrap().to_string(),
                        property,
                        times,
                        values,
                    }
                })
                .collect();
            (a.name().unwrap().to_string(), tracks)
        })
        .collect()
}

fn track<'a>(tracks: &'a [Track], node: &str, property: &str) -> &'a Track {
    tracks
        .iter()
        .find(|t| t.node == node && t.property == property)
        .unwrap_or_else(|| panic!("no {property} track of {node}"))
}

fn world(name: &str) -> WorldDescription {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("worlds")
        .join(name);
    world_file::load_file(&path).unwrap()
}

fn run(world: &WorldDescription, scenario: Scenario) -> RunReport {
    scenario::run(world, scenario, &mut |_| {}).unwrap()
}

/// The checks of the issue on a run: one animation per scenario named after it, times from 0
/// strictly increasing, at most `MAX_KEYFRAME_RATE` per second, ending at the scenario's
/// simulated duration, and the vehicle's last translation at the telemetry's last position.
fn check_run(report: &RunReport, vehicle_node: &str, step_s: f64) {
    let glb = replay::to_glb(&report.replay_parts()).unwrap();
    let anims = animations(&glb);
    let names: Vec<&str> = anims.iter().map(|a| a.0.as_str()).collect();
    let expected: Vec<&str> = report.results.iter().map(|r| r.name.as_str()).collect();
    assert_eq!(names, expected);
    for ((_, tracks), result) in anims.iter().zip(&report.results) {
        let moved = track(tracks, vehicle_node, "translation");
        let t = &moved.times;
        assert_eq!(t[0], 0.0);
        // The recorder keeps every n-th step, n the fewest steps spanning 1/60 s; the last
        // interval (up to the run's last step) may be shorter.
        let period = (1.0 / MAX_KEYFRAME_RATE / step_s).ceil() * step_s;
        for w in t[..t.len() - 1].windows(2) {
            // f32 times of up to a few hundred seconds: 1e-4 s of rounding.
            assert!((f64::from(w[1] - w[0]) - period).abs() < 1e-4, "{w:?}");
        }
        let last = *t.last().unwrap();
        assert!(last > t[t.len() - 2]);
        // The scenario's duration in f32 (6e-5 s resolution at 360 s).
        assert!(
            (f64::from(last) - result.sim_seconds).abs() < 1e-4,
            "{}: last keyframe {last} s, run {} s",
            result.name,
            result.sim_seconds
        );
        // The telemetry's last pose: its last sample is the last step's.
        let sample = result.telemetry[0].samples.last().unwrap();
        assert_eq!(sample.time, result.sim_seconds);
        let p = moved.values.last().unwrap();
        let error = (f64::from(p[0]) - sample.x).hypot(f64::from(p[1]) - sample.y);
        // 1 cm, the bound; f32 positions of a few hundred metres round to 0.03 mm.
        assert!(error < 0.01, "{}: {error} m", result.name);
    }
}

#[test]
fn test_track_replay_has_one_animation_per_scenario_ending_at_the_telemetry() {
    let w = world("obstacles.toml");
    let report = run(&w, Scenario::TestTrack);
    // The car's node is named after the world file's car (its model, unnamed).
    assert_eq!(w.vehicle_names(), ["TeslaModel3"]);
    check_run(&report, "TeslaModel3", w.config.dt());

    let glb = replay::to_glb(&report.replay_parts()).unwrap();
    let anims = animations(&glb);
    // Brake lights: off at the start of the brake scenario, on once it brakes.
    let (_, brake) = anims.iter().find(|a| a.0 == "brake").unwrap();
    let lights = track(brake, "brake_lights", "scale");
    assert_eq!(lights.values[0], [0.0; 3]);
    assert!(lights.values.iter().any(|v| v == &[1.0; 3]));
    // Each animation shows its own scenario's group (trajectory, cones) and hides the others.
    let (_, lane) = anims.iter().find(|a| a.0 == "lane-change").unwrap();
    assert_eq!(
        track(lane, "scenario_lane-change", "scale").values,
        [[1.0; 3]]
    );
    assert_eq!(track(lane, "scenario_brake", "scale").values, [[0.0; 3]]);

    // The scene: the ground, the box and the ramp, the car with the wheels of a TeslaModel3,
    // the lane change's cones.
    let doc = gltf::Gltf::from_slice(&glb).unwrap();
    let names: Vec<&str> = doc.nodes().filter_map(|n| n.name()).collect();
    for n in [
        "ground",
        "grid",
        "box_0",
        "ramp_1",
        "TeslaModel3",
        "front_left_wheel",
        "cone_0",
    ] {
        assert!(names.contains(&n), "no node {n}");
    }
    let root = doc.default_scene().unwrap().nodes().next().unwrap();
    assert_eq!(root.name(), Some("webots_to_gltf"));
}

#[test]
fn steering_turns_the_front_wheels_in_the_replay() {
    let w = world("bmw-x5.toml");
    let report = run(&w, Scenario::Circle);
    check_run(&report, w.vehicle_names()[0], w.config.dt());
    let glb = replay::to_glb(&report.replay_parts()).unwrap();
    let anims = animations(&glb);
    let (_, circle) = &anims[0];
    // The wheel rotation is the steering about −z after the spin about the axle (y) after
    // the rest pose: its rotated axle (rest: local x → car +y) is turned by the steering, so
    // its x component is sin(δ) for a right turn of δ on the right wheel.
    let q = track(circle, "front_right_wheel", "rotation")
        .values
        .last()
        .unwrap()
        .clone();
    let (x, y, z, w) = (q[0], q[1], q[2], q[3]);
    // Rotated local x axis, first column of the rotation matrix.
    let axle = [
        1.0 - 2.0 * (y * y + z * z),
        2.0 * (x * y + w * z),
        2.0 * (x * z - w * y),
    ];
    let steering = report.results[0].telemetry[0]
        .samples
        .last()
        .unwrap()
        .steering
        .unwrap();
    // The mean of both wheels' angles (Ackermann: the right wheel turns more in a right turn):
    // within 0.03 rad of it.
    let right = f64::from(axle[0]).atan2(f64::from(axle[1]));
    assert!((right - steering).abs() < 0.03, "{right} vs {steering}");
    assert!(right > 0.15);
    // The rear wheels do not steer: their axle stays along the car's y axis.
    let q = track(circle, "rear_right_wheel", "rotation")
        .values
        .last()
        .unwrap()
        .clone();
    let (x, y, z, w) = (q[0], q[1], q[2], q[3]);
    assert!((2.0 * (x * y + w * z) - 1.0).abs() < 1e-5);
}

#[test]
fn robot_replay_moves_the_robot_and_turns_its_wheels() {
    let w = world("e-puck.toml");
    let report = run(&w, Scenario::Square);
    check_run(&report, w.vehicle_names()[0], w.config.dt());
    let glb = replay::to_glb(&report.replay_parts()).unwrap();
    let anims = animations(&glb);
    assert_eq!(anims.len(), 1);
    let wheel = track(&anims[0].1, "left_wheel", "rotation");
    assert_ne!(wheel.values[0], *wheel.values.last().unwrap());
    let doc = gltf::Gltf::from_slice(&glb).unwrap();
    // The robot's wheels are VehicleWheels scaled to its 2.05 cm radius.
    let tyre = doc.meshes().find(|m| m.name() == Some("tyre")).unwrap();
    let max = tyre.primitives().next().unwrap().bounding_box().max;
    assert!((max[1].hypot(max[2]) - 0.0205 * std::f32::consts::SQRT_2).abs() < 1e-3);
}

#[test]
fn two_cars_and_their_indicators_in_one_replay() {
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let (a, _) = sim
        .add_car(sim::CarBuilder::new(Model::BmwX5.params()).placement(VehiclePlacement::default()))
        .unwrap();
    let beside = VehiclePlacement {
        y: 5.0,
        ..VehiclePlacement::default()
    };
    let (b, _) = sim
        .add_car(sim::CarBuilder::new(Model::ToyotaPrius.params()).placement(beside))
        .unwrap();
    sim.driver_mut(a).unwrap().set_cruising_speed(20.0);
    sim.driver_mut(b).unwrap().set_cruising_speed(10.0);
    sim.driver_mut(b)
        .unwrap()
        .set_indicator(IndicatorState::Left);
    let mut recorder = Recorder::for_simulation(&sim);
    for _ in 0..300 {
        sim.step().unwrap();
        recorder.sample(sim.world());
    }
    let recording = recorder.finish(sim.world());
    assert_eq!(recording.cars.len(), 2);
    let part = Part {
        name: "drive",
        recording: &recording,
        guides: &[],
    };
    let glb = replay::scene(&[part]).unwrap().to_glb().unwrap();
    let anims = animations(&glb);
    let tracks = &anims[0].1;
    // Unnamed cars of a simulation: `Car`, then `Car-2`.
    let ends: Vec<f32> = ["Car", "Car-2"]
        .iter()
        .map(|car| track(tracks, car, "translation").values.last().unwrap()[0])
        .collect();
    for (id, end) in [a, b].into_iter().zip(&ends) {
        let x = sim.world().vehicle(id).unwrap().state().position.x;
        assert!((f64::from(*end) - x).abs() < 1e-4, "{end} vs {x}");
    }
    assert!(ends[0] > ends[1]);
    // Car 1's left indicators blink (Webots' default period, 1 s: on and off each half
    // second), its right ones and car 0's stay off. Both cars have such nodes: the second
    // car's come second in the channel list.
    let blinks: Vec<&Track> = tracks
        .iter()
        .filter(|t| t.node == "left_indicators")
        .collect();
    assert_eq!(blinks.len(), 2);
    assert_eq!(blinks[0].values, [[0.0; 3]]);
    let on = blinks[1].values.iter().filter(|v| *v == &[1.0; 3]).count();
    assert!(on >= 2, "{:?}", blinks[1].times);
}

#[test]
fn a_minute_of_driving_at_the_highest_keyframe_rate_stays_under_2_mb() {
    // 1 ms steps: a keyframe every 17 steps, 58.8 per second, the most the recorder keeps.
    let config = WorldConfig {
        basic_time_step_ms: 1,
        ..WorldConfig::default()
    };
    let mut sim = Simulation::new(World::new(config).unwrap());
    let (car, _) = sim
        .add_car(sim::CarBuilder::new(Model::BmwX5.params()).placement(VehiclePlacement::default()))
        .unwrap();
    sim.driver_mut(car).unwrap().set_cruising_speed(50.0);
    sim.driver_mut(car).unwrap().set_steering_angle(0.1);
    let mut recorder = Recorder::for_simulation(&sim);
    for _ in 0..60_000 {
        sim.step().unwrap();
        recorder.sample(sim.world());
    }
    let recording = recorder.finish(sim.world());
    assert_eq!(recording.frames.len(), 60_000 / 17 + 2);
    let part = Part {
        name: "minute",
        recording: &recording,
        guides: &[],
    };
    let glb = replay::scene(&[part]).unwrap().to_glb().unwrap();
    assert!(glb.len() < 2_000_000, "{} bytes", glb.len());
}

#[test]
fn write_outputs_writes_the_replay() {
    let w = world("e-puck.toml");
    let report = run(&w, Scenario::Spin);
    let dir = std::env::temp_dir().join(format!("sim-replay-test-{}", std::process::id()));
    let written = sim::report::write_outputs(&report, &[], &dir).unwrap();
    let glb = dir.join("replay.glb");
    assert!(written.contains(&glb));
    let bytes = std::fs::read(&glb).unwrap();
    assert_eq!(&bytes[..4], b"glTF");
    assert_eq!(animations(&bytes)[0].0, "spin");
    std::fs::remove_dir_all(&dir).unwrap();
}
