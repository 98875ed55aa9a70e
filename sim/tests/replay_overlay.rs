//! The radar overlay of `replay.glb` (`replayOverlay`), read back with the `gltf` crate: the
//! markers sit where the radar's targets are in the world, from their distance and azimuth and
//! the radar's pose; without the key the file holds no marker.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::collections::BTreeMap;

use gltf::animation::util::ReadOutputs;
use sim::devices::Reading;
use sim::nalgebra::{Isometry3, Point3, Translation3};
use sim::replay::overlay::MAX_TARGET_MARKERS;
use sim::{Simulation, world_file};

/// The ACC world (a lead car driving off 50 m ahead of a parked follower with a long-range
/// radar), the radar sampled every 40 ms: a whole number of the replay's 20 ms keyframes
/// (60 Hz at most on 10 ms steps), so each sample falls on a keyframe.
fn world(overlay: bool) -> String {
    let acc =
        include_str!("../worlds/acc.toml").replace("samplingPeriod = 50", "samplingPeriod = 40");
    format!("replayOverlay = {overlay}\n{acc}")
}

/// Runs 2 s of `text` recorded; returns the glb and, per radar sample time (ms), the targets'
/// world positions computed here from distance, azimuth and the radar's pose.
fn run(text: &str) -> (Vec<u8>, BTreeMap<u64, Vec<Point3<f64>>>) {
    let description = world_file::parse_str("acc.toml", text).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let follower = sim.car_ids().nth(1).unwrap();
    sim.record("acc");
    let mut expected = BTreeMap::new();
    for _ in 0..200 {
        sim.step().unwrap();
        let t = sim.world().time_ms();
        if t % 40 != 0 {
            continue;
        }
        let radar = &sim.devices(follower).unwrap()[0];
        let Reading::Radar(Some(targets)) = radar.reading() else {
            panic!("the radar sampled at {t} ms");
        };
        let s = sim.world().vehicle(follower).unwrap().state();
        let pose = Isometry3::from_parts(Translation3::from(s.position.coords), s.orientation)
            * radar.mount();
        // Azimuth > 0 to the right (−y of the radar), in the radar's horizontal plane.
        let points = targets
            .iter()
            .map(|t| {
                pose * Point3::new(
                    t.distance * t.azimuth.cos(),
                    -t.distance * t.azimuth.sin(),
                    0.0,
                )
            })
            .collect();
        expected.insert(t, points);
    }
    let report = sim.report("acc.toml").unwrap().unwrap();
    let glb = sim::replay::to_glb(&report.replay_parts()).unwrap();
    (glb, expected)
}

/// Per marker node name: (keyframe times, translations, scales).
type Tracks = BTreeMap<String, (Vec<f32>, Vec<[f32; 3]>, Vec<[f32; 3]>)>;

fn marker_tracks(glb: &[u8]) -> Tracks {
    let doc = gltf::Gltf::from_slice(glb).expect("valid glTF");
    let blob = doc.blob.clone().unwrap();
    let mut out = Tracks::new();
    for a in doc.animations() {
        for c in a.channels() {
            let name = c.target().node().name().unwrap_or_default().to_string();
            if !name.contains("target") {
                continue;
            }
            let reader = c.reader(|_| Some(&blob));
            let times: Vec<f32> = reader.read_inputs().unwrap().collect();
            let entry = out.entry(name).or_default();
            entry.0 = times;
            match reader.read_outputs().unwrap() {
                ReadOutputs::Translations(v) => entry.1 = v.collect(),
                ReadOutputs::Scales(v) => entry.2 = v.collect(),
                _ => panic!("markers only move and scale"),
            }
        }
    }
    out
}

#[test]
fn markers_sit_at_the_radar_targets_and_hide_beyond_them() {
    let (glb, expected) = run(&world(true));
    let tracks = marker_tracks(&glb);
    assert_eq!(tracks.len(), MAX_TARGET_MARKERS, "{:?}", tracks.keys());
    let mut checked = 0;
    for (k, name) in (0..MAX_TARGET_MARKERS).map(|k| (k, format!("follower/radar target {k}"))) {
        let (times, at, scale) = &tracks[&name];
        for (t, targets) in &expected {
            // The keyframe at this sample (times from the recording's start, 0).
            let i = times
                .iter()
                .position(|&s| (f64::from(s) * 1000.0 - *t as f64).abs() < 0.5)
                .unwrap_or_else(|| panic!("no keyframe at {t} ms"));
            match targets.get(k) {
                Some(p) => {
                    assert_eq!(scale[i], [1.0; 3], "{name} at {t} ms");
                    // 1 mm: the file's f32 at some 100 m is good to 8 µm.
                    let d = Point3::new(
                        f64::from(at[i][0]),
                        f64::from(at[i][1]),
                        f64::from(at[i][2]),
                    ) - p;
                    assert!(d.norm() < 1e-3, "{name} at {t} ms: {:?} vs {p}", at[i]);
                    checked += 1;
                }
                None => assert_eq!(scale[i], [0.0; 3], "{name} at {t} ms"),
            }
        }
    }
    // The lead car is in view all along: one target at each of the 50 samples.
    assert_eq!(checked, expected.len());
    assert_eq!(expected.len(), 50);
}

#[test]
fn without_the_key_the_replay_has_no_marker() {
    let (with_false, _) = run(&world(false));
    let acc =
        include_str!("../worlds/acc.toml").replace("samplingPeriod = 50", "samplingPeriod = 40");
    let (without, _) = run(&acc);
    assert_eq!(with_false, without);
    assert!(marker_tracks(&without).is_empty());
    let doc = gltf::Gltf::from_slice(&without).unwrap();
    assert!(
        doc.nodes()
            .all(|n| !n.name().unwrap_or_default().contains("target"))
    );
    assert!(doc.materials().all(|m| m.name() != Some("radar target")));
}
