//! The infra-red distance sensor (spec §6) against boxes of known colours: its distance is the
//! rays' weighted mean `d̄`, lengthened to `d̄ + (d̄/F − d̄)·redColorSensitivity` with
//! `F = Σ wᵢ(0.2 + 0.8·redᵢ)` (1 for a miss), computed here from the geometry.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::devices::{DeviceSettings, DistanceSensorType, Reading};
use sim::nalgebra::Vector3;
use sim::{Simulation, VehicleId, world_file};

/// The near face of the wall (world x, m).
const WALL_X: f64 = 4.0;
/// The table maps 0–20 m to 0–20: the value is the distance (m), up to the rays' length.
const TABLE: &str = "lookupTable = [[0, 0, 0], [20, 20, 0]]";

/// A car whose sensors `devices` face a 20 m wide wall of colour `color` at `WALL_X`.
fn wall(color: [f64; 3], devices: &str) -> (Simulation, VehicleId) {
    let text = format!(
        "[vehicle]\nmodel = \"BmwX5\"\n{devices}\n[[box]]\ntranslation = [{}, 0, 2]\nsize = [1, 20, 4]\ncolor = {color:?}\n",
        WALL_X + 0.5
    );
    let description = world_file::parse_str("ir.toml", &text).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    for i in 0..sim.devices(id).unwrap().len() {
        sim.enable_device(id, i, 20).unwrap();
    }
    for _ in 0..50 {
        sim.step().unwrap();
    }
    (sim, id)
}

fn sensor(name: &str, rays: u32, aperture: f64, sensitivity: f64) -> String {
    format!(
        "[[vehicle.device]]\ntype = \"DistanceSensor\"\nname = \"{name}\"\nsensorType = \"infra-red\"\n\
         numberOfRays = {rays}\naperture = {aperture}\nredColorSensitivity = {sensitivity}\n\
         translation = [2.5, 0, 0]\n{TABLE}\n"
    )
}

fn value(sim: &Simulation, id: VehicleId, name: &str) -> f64 {
    let d = sim.devices(id).unwrap();
    match d.iter().find(|d| d.name() == name).unwrap().reading() {
        Reading::Distance(v) => *v,
        other => panic!("{name}: {other:?}"),
    }
}

/// The distance (m) from the sensor to the wall's plane along `dir` (device axes).
fn along(sim: &Simulation, id: VehicleId, dir: Vector3<f64>) -> f64 {
    let s = sim.world().vehicle(id).unwrap().state();
    let at = s.position + s.orientation * Vector3::new(2.5, 0.0, 0.0);
    (WALL_X - at.x) / (s.orientation * dir).x
}

/// The spec's formula for rays of weights `w` and distances `d`, all hitting red `red`.
fn infra_red(w: &[f64], d: &[f64], red: f64, sensitivity: f64) -> f64 {
    let mean: f64 = w.iter().zip(d).map(|(w, d)| w * d).sum();
    let factor: f64 = w.iter().map(|w| w * (0.2 + 0.8 * red)).sum();
    mean + (mean / factor - mean) * sensitivity
}

#[test]
fn white_black_and_red_walls_on_one_ray() {
    let devices = [sensor("one", 1, 1.0, 1.0), sensor("half", 1, 1.0, 0.5)].concat();
    for (color, red) in [
        ([1.0, 1.0, 1.0], 1.0),
        ([0.0, 0.0, 0.0], 0.0),
        ([1.0, 0.0, 0.0], 1.0),
        ([0.25, 0.9, 0.9], 0.25),
    ] {
        let (sim, id) = wall(color, &devices);
        let d = along(&sim, id, Vector3::x());
        for (name, sensitivity) in [("one", 1.0), ("half", 0.5)] {
            let expected = infra_red(&[1.0], &[d], red, sensitivity);
            let got = value(&sim, id, name);
            // Tolerance: f32 ray casts, 1e-5 m at 1.5 m, times at most 1/F = 5 on black.
            assert!(
                (got - expected).abs() < 1e-4,
                "{color:?} {name}: {got} vs {expected}"
            );
        }
    }
    // White reads the true distance, black five times it (F = 0.2), red as white: only the
    // red channel counts.
    let d = {
        let (sim, id) = wall([1.0, 1.0, 1.0], &devices);
        along(&sim, id, Vector3::x())
    };
    let (black, id) = wall([0.0; 3], &devices);
    assert!((value(&black, id, "one") - 5.0 * d).abs() < 5e-4);
}

#[test]
fn four_rays_weigh_their_distances_and_reds() {
    // Four rays: one along +x (θ = 0, weight ∝ 1), three at θ = aperture/2 around it at
    // α = 0, ±2π/3 (weight ∝ exp(−(½/gaussianWidth)²) = e^{−1/4}), spec §6.
    let aperture = 0.6;
    let devices = sensor("four", 4, aperture, 1.0);
    let theta: f64 = aperture / 2.0;
    let e = (-0.25f64).exp();
    let total = 1.0 + 3.0 * e;
    let w = [1.0 / total, e / total, e / total, e / total];
    let dirs: Vec<Vector3<f64>> = [None, Some(0.0), Some(2.0 * std::f64::consts::PI / 3.0)]
        .into_iter()
        .chain([Some(-2.0 * std::f64::consts::PI / 3.0)])
        .map(|alpha| match alpha {
            None => Vector3::x(),
            Some(a) => {
                let a: f64 = a + std::f64::consts::FRAC_PI_2;
                Vector3::new(theta.cos(), -theta.sin() * a.cos(), theta.sin() * a.sin())
            }
        })
        .collect();
    for (color, red) in [
        ([1.0, 1.0, 1.0], 1.0),
        ([0.0; 3], 0.0),
        ([0.6, 0.1, 0.1], 0.6),
    ] {
        let (sim, id) = wall(color, &devices);
        let d: Vec<f64> = dirs.iter().map(|&dir| along(&sim, id, dir)).collect();
        let expected = infra_red(&w, &d, red, 1.0);
        let got = value(&sim, id, "four");
        // Tolerance: f32 ray casts (1e-5 m) times at most 1/F = 5.
        assert!(
            (got - expected).abs() < 1e-4,
            "{color:?}: {got} vs {expected}"
        );
    }
}

#[test]
fn a_miss_counts_as_the_range_with_a_factor_of_one() {
    // Facing away from the wall: nothing within 20 m, d̄ = 20 and F = 1, whatever the colours.
    let text = format!(
        "[vehicle]\nmodel = \"BmwX5\"\n{}rotation = [0, 0, 1, 3.14159]\n",
        sensor("back", 1, 1.0, 1.0)
    );
    let description = world_file::parse_str("ir.toml", &text).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    sim.enable_device(id, 0, 10).unwrap();
    sim.step().unwrap();
    assert_eq!(value(&sim, id, "back"), 20.0);
}

#[test]
fn infra_red_fields_are_read_and_checked() {
    let head = "[vehicle]\nmodel = \"BmwX5\"\n[[vehicle.device]]\ntype = \"DistanceSensor\"\n";
    let d = world_file::parse_str(
        "w.toml",
        &format!("{head}sensorType = \"infrared\"\nredColorSensitivity = 2.5\n"),
    )
    .unwrap();
    let DeviceSettings::DistanceSensor(s) = &d.cars[0].devices[0].settings else {
        panic!()
    };
    assert_eq!(
        (s.sensor_type, s.red_color_sensitivity),
        (DistanceSensorType::InfraRed, 2.5)
    );
    assert_eq!(s.sensor_type.webots_value(), 1);
    let e = world_file::parse_str(
        "w.toml",
        &format!("{head}sensorType = \"infra-red\"\nredColorSensitivity = -1\n"),
    )
    .expect_err("a negative sensitivity is refused");
    assert_eq!(
        e.key.as_deref(),
        Some("vehicle.device[1].redColorSensitivity")
    );
}

#[test]
fn a_cone_is_seen_in_its_own_colour_unless_the_world_sets_one() {
    // A generic sensor beside each infra-red one reads the distance itself (its table is the
    // identity), so the infra-red value follows from the formula with the cone's red.
    let generic = "[[vehicle.device]]\ntype = \"DistanceSensor\"\nname = \"plain\"\n\
                   translation = [2.5, 0, 0]\nlookupTable = [[0, 0, 0], [20, 20, 0]]\n";
    let devices = [sensor("ir", 1, 1.0, 1.0), generic.to_string()].concat();
    for (look, red) in [("", sim::CONE_COLOR[0]), ("color = [0.1, 0.5, 0.5]\n", 0.1)] {
        let text = format!(
            "[[cone]]\ntranslation = [{WALL_X}, 0, 0]\nheight = 1.5\nradius = 0.3\n{look}\
             [vehicle]\nmodel = \"BmwX5\"\n{devices}"
        );
        let description = world_file::parse_str("ir.toml", &text).unwrap();
        let (mut sim, _) = Simulation::from_description(&description).unwrap();
        let id = sim.car_ids().next().unwrap();
        for i in 0..sim.devices(id).unwrap().len() {
            sim.enable_device(id, i, 20).unwrap();
        }
        for _ in 0..50 {
            sim.step().unwrap();
        }
        let d = value(&sim, id, "plain");
        assert!(d > 0.1 && d < 5.0, "the cone is in range: {d}");
        let expected = infra_red(&[1.0], &[d], red, 1.0);
        let got = value(&sim, id, "ir");
        // Tolerance: as on the walls, f32 ray casts times at most 1/F = 5.
        assert!(
            (got - expected).abs() < 1e-4,
            "{look:?}: {got} vs {expected}"
        );
    }
}
