//! The lidar part of the replay overlay (`replayOverlay`), read back with the `gltf` crate:
//! each drawn cloud is a `POINTS` mesh whose points are the lidar's point cloud placed by the
//! lidar's pose at its sample, shown from that sample's keyframe to the next drawn one;
//! without the key the file holds no cloud and is byte for byte the same.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::collections::BTreeMap;

use gltf::animation::util::ReadOutputs;
use sim::nalgebra::{Isometry3, Point3, Translation3};
use sim::{Simulation, world_file};

/// A parked BmwX5 whose SICK LMS 291 (roof) samples every 40 ms, a whole number of the
/// replay's 20 ms keyframes, before a wall and a cone; `head` goes first.
fn world(head: &str) -> String {
    format!(
        "{head}\n[vehicle]\nmodel = \"BmwX5\"\n[[vehicle.device]]\ntype = \"Lidar\"\nname = \"lidar\"\n\
         preset = \"SickLms291\"\nslot = \"front\"\nsamplingPeriod = 40\n\
         [[box]]\ntranslation = [25, 0, 1]\nsize = [1, 30, 2]\n\
         [[cone]]\ntranslation = [12, -1, 0]\nheight = 1.5\nradius = 0.4\n"
    )
}

/// Runs 1 s of `text` recorded; returns the glb and, per lidar sample time (ms), its
/// returns in the world computed here: the point cloud (device axes) placed by the lidar's
/// pose, rays without a return left out.
fn run(text: &str) -> (Vec<u8>, BTreeMap<u64, Vec<Point3<f64>>>) {
    let description = world_file::parse_str("lidar.toml", text).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let car = sim.car_ids().next().unwrap();
    sim.enable_point_cloud(car, 0, true).unwrap();
    sim.record("lidar");
    let mut expected = BTreeMap::new();
    for _ in 0..100 {
        sim.step().unwrap();
        let t = sim.world().time_ms();
        if t % 40 != 0 {
            continue;
        }
        let lidar = &sim.devices(car).unwrap()[0];
        let s = sim.world().vehicle(car).unwrap().state();
        let pose = Isometry3::from_parts(Translation3::from(s.position.coords), s.orientation)
            * lidar.mount();
        let points = lidar
            .point_cloud()
            .unwrap()
            .iter()
            .filter(|p| p.x.is_finite())
            .map(|p| pose * Point3::new(f64::from(p.x), f64::from(p.y), f64::from(p.z)))
            .collect();
        expected.insert(t, points);
    }
    let report = sim.report("lidar.toml").unwrap().unwrap();
    let glb = sim::replay::to_glb(&report.replay_parts()).unwrap();
    (glb, expected)
}

/// Per cloud node: the time (ms) from which its scale channel shows it, and its points.
fn clouds(glb: &[u8]) -> BTreeMap<u64, Vec<[f32; 3]>> {
    let doc = gltf::Gltf::from_slice(glb).expect("valid glTF");
    let blob = doc.blob.clone().unwrap();
    let mut out = BTreeMap::new();
    for a in doc.animations() {
        for c in a.channels() {
            let node = c.target().node();
            if !node
                .name()
                .unwrap_or_default()
                .starts_with("BmwX5/lidar cloud")
            {
                continue;
            }
            let reader = c.reader(|_| Some(&blob));
            let times: Vec<f32> = reader.read_inputs().unwrap().collect();
            let ReadOutputs::Scales(scales) = reader.read_outputs().unwrap() else {
                panic!("clouds only scale");
            };
            let scales: Vec<[f32; 3]> = scales.collect();
            // Hidden (if at all) until its sample, shown from it, hidden (if at all) at the next.
            let shown = scales.iter().position(|s| *s == [1.0; 3]).unwrap();
            assert!(scales[..shown].iter().all(|s| *s == [0.0; 3]));
            assert!(scales[shown + 1..].iter().all(|s| *s == [0.0; 3]));
            let primitive = node.mesh().unwrap().primitives().next().unwrap();
            assert_eq!(primitive.mode(), gltf::mesh::Mode::Points);
            let points: Vec<[f32; 3]> = primitive
                .reader(|_| Some(&blob))
                .read_positions()
                .unwrap()
                .collect();
            let ms = (f64::from(times[shown]) * 1000.0).round() as u64;
            assert!(out.insert(ms, points).is_none(), "two clouds at {ms} ms");
        }
    }
    out
}

#[test]
fn cloud_points_are_the_point_cloud_placed_by_the_lidars_pose() {
    let (glb, expected) = run(&world("replayOverlay = true"));
    let drawn = clouds(&glb);
    // One cloud per sample: 25 samples in 1 s, each falling on a keyframe.
    assert_eq!(
        drawn.keys().collect::<Vec<_>>(),
        expected.keys().collect::<Vec<_>>()
    );
    for (t, points) in &expected {
        let got = &drawn[t];
        // 180 rays over 180°: the 30 m wall 25 m ahead spans ±31°, some 62 returns, plus the
        // cone's; all kept (below the 4,096-point cap).
        assert!(points.len() > 60, "{t} ms: {}", points.len());
        assert_eq!(got.len(), points.len(), "{t} ms");
        for (g, p) in got.iter().zip(points) {
            // 1 mm: the file's f32 at some 25 m is good to 2 µm, and the cloud's f32 points
            // (device axes) to as little.
            let d = Point3::new(f64::from(g[0]), f64::from(g[1]), f64::from(g[2])) - p;
            assert!(d.norm() < 1e-3, "{t} ms: {g:?} vs {p}");
        }
    }
}

#[test]
fn without_the_key_the_replay_has_no_cloud_and_the_same_bytes() {
    let (with_false, _) = run(&world("replayOverlay = false"));
    let (without, _) = run(&world(""));
    assert_eq!(with_false, without);
    let doc = gltf::Gltf::from_slice(&without).unwrap();
    assert!(
        doc.nodes()
            .all(|n| !n.name().unwrap_or_default().contains("cloud"))
    );
    assert!(doc.materials().all(|m| m.name() != Some("lidar point")));
}
