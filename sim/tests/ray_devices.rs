//! The ray devices against geometry: a radar and its targets (distance, radar-equation power,
//! radial speed, azimuth; field of view, occlusion, cells), a lidar before a wall (every
//! layer's range, `+∞` beyond `maxRange`, the point cloud), distance sensors and their
//! lookup tables.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::f64::consts::PI;

use sim::devices::{Device, LidarReading, RadarSettings, RadarTarget, Reading};
use sim::nalgebra::{Point3, UnitQuaternion, Vector3};
use sim::{Simulation, VehicleId, world_file};

/// The simulation of world `text` and its cars, in file order.
fn world(text: &str) -> (Simulation, Vec<VehicleId>) {
    let description = world_file::parse_str("rays.toml", text).unwrap();
    let (sim, _) = Simulation::from_description(&description).unwrap();
    let ids = sim.car_ids().collect();
    (sim, ids)
}

fn device<'a>(sim: &'a Simulation, id: VehicleId, name: &str) -> (usize, &'a Device) {
    let devices = sim.devices(id).unwrap();
    let i = devices.iter().position(|d| d.name() == name).unwrap();
    (i, &devices[i])
}

fn enable(sim: &mut Simulation, id: VehicleId, name: &str, period_ms: u32) {
    let (i, _) = device(sim, id, name);
    sim.enable_device(id, i, period_ms).unwrap();
}

fn targets(sim: &Simulation, id: VehicleId, name: &str) -> Vec<RadarTarget> {
    match device(sim, id, name).1.reading() {
        Reading::Radar(Some(t)) => t.clone(),
        other => panic!("{name}: {other:?}"),
    }
}

fn lidar(sim: &Simulation, id: VehicleId, name: &str) -> LidarReading {
    match device(sim, id, name).1.reading() {
        Reading::Lidar(r) => r.clone(),
        other => panic!("{name}: {other:?}"),
    }
}

fn distance(sim: &Simulation, id: VehicleId, name: &str) -> f64 {
    match device(sim, id, name).1.reading() {
        Reading::Distance(v) => *v,
        other => panic!("{name}: {other:?}"),
    }
}

/// Where the device of car `id` mounted at the car's origin is and how it is turned.
fn origin(sim: &Simulation, id: VehicleId) -> (Point3<f64>, UnitQuaternion<f64>) {
    let s = sim.world().vehicle(id).unwrap().state();
    (s.position, s.orientation)
}

/// What a radar at the origin of car `from` sees of the origin of car `to`: distance (m),
/// radial speed (m/s) and azimuth (rad, > 0 right), exactly.
fn truth(sim: &Simulation, from: VehicleId, to: VehicleId) -> (f64, f64, f64) {
    let a = sim.world().vehicle(from).unwrap().state();
    let b = sim.world().vehicle(to).unwrap().state();
    let line = b.position - a.position;
    let local = a.orientation.inverse() * line;
    let unit = line.normalize();
    (
        line.norm(),
        unit.dot(&(b.velocity - a.velocity)),
        -local.y.atan2(local.x),
    )
}

/// The radar equation in dBm for the default radar (20 dBm, 20 dBi, 24 GHz) and `rcs` m² at
/// `d` m, written out from the spec.
fn default_power_dbm(rcs: f64, d: f64) -> f64 {
    let pt = 10f64.powf(20.0 / 10.0) / 1000.0; // W
    let g = 10f64.powf(20.0 / 10.0);
    let lambda = 0.299_792_458 / 24.0; // m
    let pr = pt * g * g * lambda * lambda * rcs / ((4.0 * PI).powi(3) * d.powi(4));
    10.0 * (pr / 0.001).log10()
}

#[test]
fn radar_reads_a_closing_lead_car() {
    // A follower at 20 m/s and a lead car at 15 m/s, both from rest: after 10 s both cruise
    // and close at 5 m/s. One radar without noise, one Delphi ESR (long range) with its noise.
    let (mut sim, ids) = world(
        r#"
[[vehicle]]
model = "BmwX5"
name = "follower"
[[vehicle.device]]
type = "Radar"
name = "exact"
maxRange = 150
[[vehicle.device]]
type = "Radar"
name = "esr"
preset = "DelphiEsrLongRange"
[[vehicle]]
model = "BmwX5"
name = "lead"
translation = [65, 0, 0]
radarCrossSection = 10
"#,
    );
    let (follower, lead) = (ids[0], ids[1]);
    sim.driver_mut(follower).unwrap().set_cruising_speed(72.0);
    sim.driver_mut(lead).unwrap().set_cruising_speed(54.0);
    enable(&mut sim, follower, "exact", 10);
    enable(&mut sim, follower, "esr", 10);
    for _ in 0..1000 {
        sim.step().unwrap();
    }
    let (d, s, a) = truth(&sim, follower, lead);
    // The scenario: some 40 m, closing at 5 m/s (the cruise control holds within 0.3 m/s).
    assert!((30.0..60.0).contains(&d), "{d}");
    assert!((s + 5.0).abs() < 0.3, "{s}");
    let exact = targets(&sim, follower, "exact");
    assert_eq!(exact.len(), 1);
    let t = exact[0];
    // Tolerances: the world runs in f32 (positions to ~1e-5 m at 100 m).
    assert!((t.distance - d).abs() < 1e-9, "{t:?} vs {d}");
    assert!((t.speed - s).abs() < 1e-9, "{t:?} vs {s}");
    assert!(
        (t.azimuth - a).abs() < 1e-9 && a.abs() < 0.01,
        "{t:?} vs {a}"
    );
    assert!((t.received_power - default_power_dbm(10.0, d)).abs() < 1e-9);
    // The ESR's noise: 0.5 m, 0.12 m/s, 0.00873 rad standard deviations; 5 of them.
    let esr = targets(&sim, follower, "esr");
    assert_eq!(esr.len(), 1);
    assert!((esr[0].distance - d).abs() < 5.0 * 0.5);
    assert!((esr[0].speed - s).abs() < 5.0 * 0.12);
    assert!((esr[0].azimuth - a).abs() < 5.0 * 0.00873);
}

/// A radar on car 0 and parked cars at `positions` (m), each of cross-section 10 m².
fn radar_world(radar: &str, positions: &[[f64; 2]], extra: &str) -> (Simulation, Vec<VehicleId>) {
    let mut text =
        format!("[[vehicle]]\nmodel = \"BmwX5\"\n[[vehicle.device]]\ntype = \"Radar\"\n{radar}\n");
    for [x, y] in positions {
        text += &format!(
            "[[vehicle]]\nmodel = \"BmwX5\"\ntranslation = [{x}, {y}, 0]\nradarCrossSection = 10\n"
        );
    }
    text += extra;
    let (mut sim, ids) = world(&text);
    enable(&mut sim, ids[0], "radar", 10);
    for _ in 0..100 {
        sim.step().unwrap();
    }
    (sim, ids)
}

#[test]
fn radar_field_of_view() {
    // A target is a candidate when the sphere around its collision box meets the field of
    // view (±0.39 rad by default): its centre within 0.39 rad plus the angle the sphere
    // subtends. Centres 0.01 rad inside that edge (left at 40 m, right at 20 m) are seen,
    // 0.01 rad outside (30 m) not; at different ranges so that the cars stand apart. The
    // cars settle by a few mrad: 0.01 rad is well above that.
    let spec = sim::VehicleSpec::from_car(&vehicle_model::Model::BmwX5.params())
        .unwrap()
        .chassis;
    let (radius, bx) = (spec.box_half_extents.norm(), spec.box_center.x);
    let at = |r: f64, side: f64, inside: bool| {
        let edge = 0.39 + (radius / r).asin();
        let angle = side * if inside { edge - 0.01 } else { edge + 0.01 };
        // The car's origin, so that its box centre is at `r`, `angle`.
        [r * angle.cos() - bx, r * angle.sin()]
    };
    let places = [
        at(40.0, 1.0, true),
        at(30.0, 1.0, false),
        at(20.0, -1.0, true),
        at(30.0, -1.0, false),
    ];
    let (sim, ids) = radar_world("", &places, "");
    let t = targets(&sim, ids[0], "radar");
    assert_eq!(t.len(), 2, "{t:?}");
    // In scene order; the azimuth of the target's origin, clamped to the field of view.
    let (left, right) = (truth(&sim, ids[0], ids[1]), truth(&sim, ids[0], ids[3]));
    assert!(
        (t[0].azimuth - left.2.clamp(-0.39, 0.39)).abs() < 1e-9,
        "{t:?} {left:?}"
    );
    assert!(
        (t[1].azimuth - right.2.clamp(-0.39, 0.39)).abs() < 1e-9,
        "{t:?} {right:?}"
    );
    assert!((t[0].distance - left.0).abs() < 1e-9);
    // Beyond maxRange (50 m by default, the sphere's near side) nothing is seen.
    let (sim, ids) = radar_world("", &[[51.0 + radius - bx, 0.0]], "");
    assert!(targets(&sim, ids[0], "radar").is_empty());
}

#[test]
fn radar_occlusion() {
    // A wall between the radar and the target: reported without occlusion, not with it.
    let wall = "[[box]]\ntranslation = [20, 0, 1]\nsize = [0.5, 6, 2]\n";
    let (sim, ids) = radar_world("occlusion = true", &[[40.0, 0.0]], wall);
    assert!(targets(&sim, ids[0], "radar").is_empty());
    let (sim, ids) = radar_world("occlusion = false", &[[40.0, 0.0]], wall);
    assert_eq!(targets(&sim, ids[0], "radar").len(), 1);
    // Without the wall the occluding radar sees the target (its own body does not hide it).
    let (sim, ids) = radar_world("occlusion = true", &[[40.0, 0.0]], "");
    assert_eq!(targets(&sim, ids[0], "radar").len(), 1);
}

#[test]
fn radar_cells_merge() {
    // Two cars side by side 40 m ahead: their distances differ by well under 1 m.
    let pair = [[40.0, 2.5], [40.0, -2.5]];
    let (sim, ids) = radar_world("", &pair, "");
    let apart = targets(&sim, ids[0], "radar");
    assert_eq!(apart.len(), 2);
    let (sim, ids) = radar_world("cellDistance = 1", &pair, "");
    let merged = targets(&sim, ids[0], "radar");
    assert_eq!(merged.len(), 1);
    // Power-weighted means and the summed power (W), from the separate targets.
    let w = |t: &RadarTarget| 10f64.powf(t.received_power / 10.0) / 1000.0;
    let (wa, wb) = (w(&apart[0]), w(&apart[1]));
    let mean = |a: f64, b: f64| (a * wa + b * wb) / (wa + wb);
    let m = merged[0];
    // Tolerance: dB ↔ W round trips in f64.
    assert!((m.distance - mean(apart[0].distance, apart[1].distance)).abs() < 1e-9);
    assert!((m.azimuth - mean(apart[0].azimuth, apart[1].azimuth)).abs() < 1e-9);
    assert!((w(&m) - (wa + wb)).abs() < 1e-9 * (wa + wb));
    // A weak signal is not detected: −100 dBm needs σ/d⁴ above a bound; raise the threshold
    // to just above the target's power.
    let threshold = format!("minDetectableSignal = {}", apart[0].received_power + 0.01);
    let (sim, ids) = radar_world(&threshold, &[[40.0, 2.5]], "");
    assert!(targets(&sim, ids[0], "radar").is_empty());
    let preset = RadarSettings::delphi_esr();
    assert_eq!(preset.max_range, 60.0);
}

/// A car with a lidar and distance sensors at its origin, facing a wall whose near face is at
/// world x = `WALL_X`.
const WALL_X: f64 = 4.0;

fn wall_world(devices: &str) -> (Simulation, VehicleId) {
    let text = format!(
        "[vehicle]\nmodel = \"BmwX5\"\n{devices}\n[[box]]\ntranslation = [{}, 0, 2]\nsize = [1, 20, 4]\n",
        WALL_X + 0.5
    );
    let (sim, ids) = world(&text);
    (sim, ids[0])
}

#[test]
fn lidar_sees_the_wall_on_every_layer() {
    // 4 layers over 0.2 rad, 64 rays over 1.2 rad, from 0.3 m above the ground: the lowest
    // layer (−0.1 rad) meets the ground some 3 m ahead, before the wall on its outer rays.
    let (mut sim, id) = wall_world(
        "[[vehicle.device]]\ntype = \"Lidar\"\nhorizontalResolution = 64\nfieldOfView = 1.2\nmaxRange = 30\n\
         [[vehicle.device]]\ntype = \"Lidar\"\nname = \"short\"\nmaxRange = 2\n\
         [[vehicle.device]]\ntype = \"Lidar\"\nname = \"planar\"\nprojection = \"planar\"\nmaxRange = 30\nhorizontalResolution = 16\n",
    );
    for name in ["lidar", "short", "planar"] {
        enable(&mut sim, id, name, 20);
    }
    let (i, _) = device(&sim, id, "lidar");
    sim.enable_point_cloud(id, i, true).unwrap();
    for _ in 0..50 {
        sim.step().unwrap();
    }
    let (p, q) = origin(&sim, id);
    for name in ["lidar", "planar"] {
        let (_, d) = device(&sim, id, name);
        let sim::devices::DeviceSettings::Lidar(s) = d.settings() else {
            panic!()
        };
        let image = lidar(&sim, id, name);
        assert_eq!(image.range_image.len(), s.number_of_points());
        assert_eq!(image.time, 0.5); // s: the 25th sample, 50 steps of 10 ms
        for i in 0..s.number_of_layers {
            for j in 0..s.horizontal_resolution {
                let dir = s.direction(i, j);
                let world = q * dir;
                // The ray meets the wall's plane x = WALL_X, or first the ground z = 0.
                let wall = (WALL_X - p.x) / world.x;
                let ground = if world.z < 0.0 {
                    -p.z / world.z
                } else {
                    f64::INFINITY
                };
                let t = wall.min(ground);
                let expected = match name {
                    "planar" => t * dir.x,
                    _ => t,
                };
                let got = f64::from(image.range_image[(i * s.horizontal_resolution + j) as usize]);
                // Tolerance: f32 ray casts and f32 storage, ~1e-6 relative at 4 m.
                assert!(
                    (got - expected).abs() < 1e-4,
                    "{name} layer {i} ray {j}: {got} vs {expected}"
                );
            }
        }
    }
    // Nothing within 2 m: every value +∞ (Webots' value for no return).
    assert!(
        lidar(&sim, id, "short")
            .range_image
            .iter()
            .all(|r| *r == f32::INFINITY)
    );
    // The point cloud is the range image converted.
    let (_, d) = device(&sim, id, "lidar");
    let sim::devices::DeviceSettings::Lidar(s) = d.settings() else {
        panic!()
    };
    let image = lidar(&sim, id, "lidar");
    let cloud = d.point_cloud().unwrap();
    assert_eq!(cloud.len(), image.range_image.len());
    for (k, point) in cloud.iter().enumerate() {
        let (i, j) = (
            k as u32 / s.horizontal_resolution,
            k as u32 % s.horizontal_resolution,
        );
        let v = s.direction(i, j) * f64::from(image.range_image[k]);
        assert_eq!(point.layer_id, i as i32);
        assert_eq!(
            [point.x, point.y, point.z],
            [v.x as f32, v.y as f32, v.z as f32]
        );
        // time − j·period/hres (s).
        let time = image.time - f64::from(j) * 0.02 / f64::from(s.horizontal_resolution);
        assert_eq!(point.time, time as f32);
    }
    // No cloud from the lidars whose cloud is disabled.
    assert!(device(&sim, id, "short").1.point_cloud().is_none());
}

#[test]
fn distance_sensors_and_their_lookup_tables() {
    // A 2 m generic sensor reading 0 at 0 m and 1000 at 2 m, one facing the wall, one facing
    // back (no hit: the last row), a laser of the same table, and a sonar.
    let table = "lookupTable = [[0, 0, 0], [2, 1000, 0]]";
    let (mut sim, id) = wall_world(&format!(
        "[[vehicle.device]]\ntype = \"DistanceSensor\"\nname = \"front\"\ntranslation = [2.5, 0, 0]\n{table}\n\
         [[vehicle.device]]\ntype = \"DistanceSensor\"\nname = \"back\"\ntranslation = [2.5, 0, 0]\nrotation = [0, 0, 1, 3.14159]\n{table}\n\
         [[vehicle.device]]\ntype = \"DistanceSensor\"\nname = \"laser\"\nsensorType = \"laser\"\ntranslation = [2.5, 0, 0]\n{table}\n"
    ));
    let _ = &mut sim;
    for name in ["front", "back", "laser"] {
        enable(&mut sim, id, name, 20);
    }
    sim.step().unwrap();
    assert!(
        distance(&sim, id, "front").is_nan(),
        "NaN before the first sample"
    );
    for _ in 0..49 {
        sim.step().unwrap();
    }
    let (p, q) = origin(&sim, id);
    let at = p + q * Vector3::new(2.5, 0.0, 0.0);
    let axis = q * Vector3::x();
    let d = (WALL_X - at.x) / axis.x;
    // Linear table: 1000·d/2. Tolerance: f32 rays, 1e-4 m → 0.05.
    assert!((distance(&sim, id, "front") - 500.0 * d).abs() < 0.05);
    assert!((distance(&sim, id, "laser") - 500.0 * d).abs() < 0.05);
    assert_eq!(distance(&sim, id, "back"), 1000.0);
}

#[test]
fn sonar_hears_only_surfaces_it_meets_square_on() {
    // Two rays at ±aperture/2 about +z, in the x–y plane, towards the wall (normal −x): they
    // meet it at an incidence of aperture/2. A sonar hears the nearer of those within π/8
    // (0.39 rad): with an aperture of 0.6 (0.3 rad) it reads the rays' distance, with 1.0
    // (0.5 rad) nothing (the table's last row). A generic sensor of the same two rays reads
    // their weighted mean (equal weights, same distance).
    let table = "lookupTable = [[0, 0, 0], [4, 4, 0]]"; // m → m
    let sensor = |name: &str, kind: &str, aperture: f64| {
        format!(
            "[[vehicle.device]]\ntype = \"DistanceSensor\"\nname = \"{name}\"\nsensorType = \"{kind}\"\n\
             numberOfRays = 2\naperture = {aperture}\ntranslation = [2.5, 0, 0]\n{table}\n"
        )
    };
    let devices = [
        sensor("narrow sonar", "sonar", 0.6),
        sensor("wide sonar", "sonar", 1.0),
        sensor("narrow generic", "generic", 0.6),
    ]
    .concat();
    let (mut sim, id) = wall_world(&devices);
    for name in ["narrow sonar", "wide sonar", "narrow generic"] {
        enable(&mut sim, id, name, 20);
    }
    for _ in 0..50 {
        sim.step().unwrap();
    }
    let (p, q) = origin(&sim, id);
    let at = p + q * Vector3::new(2.5, 0.0, 0.0);
    let along = |theta: f64| {
        let dir = q * Vector3::new(theta.cos(), theta.sin(), 0.0);
        (WALL_X - at.x) / dir.x
    };
    let expected = along(0.3).min(along(-0.3));
    // Tolerance: f32 rays, 1e-4 m.
    assert!((distance(&sim, id, "narrow sonar") - expected).abs() < 1e-4);
    assert_eq!(distance(&sim, id, "wide sonar"), 4.0);
    let mean = 0.5 * (along(0.3) + along(-0.3));
    assert!((distance(&sim, id, "narrow generic") - mean).abs() < 1e-4);
}

/// The error of a world that must be refused: its key and text.
fn refused(text: &str) -> (String, String) {
    let e = world_file::parse_str("w.toml", text).expect_err("the world should be refused");
    (e.key.clone().unwrap_or_default(), e.to_string())
}

#[test]
fn ray_device_fields_are_read_and_checked() {
    use sim::devices::{DeviceSettings, DistanceSensorType, LidarSettings};
    let d = world_file::parse_str(
        "w.toml",
        "[vehicle]\nmodel = \"BmwX5\"\nradarCrossSection = 8.5\n\
         [[vehicle.device]]\ntype = \"Lidar\"\npreset = \"VelodyneVlp16\"\nhorizontalResolution = 1800\n\
         [[vehicle.device]]\ntype = \"Radar\"\npreset = \"DelphiEsr\"\nmaxRange = 80\n\
         [[vehicle.device]]\ntype = \"DistanceSensor\"\nsensorType = \"sonar\"\nnumberOfRays = 4\n",
    )
    .unwrap();
    let car = &d.cars[0];
    assert_eq!(car.radar_cross_section, 8.5);
    // A preset, then the fields given after it.
    let DeviceSettings::Lidar(l) = &car.devices[0].settings else {
        panic!()
    };
    assert_eq!(
        *l,
        LidarSettings {
            horizontal_resolution: 1800,
            ..LidarSettings::velodyne_vlp16()
        }
    );
    let DeviceSettings::Radar(r) = &car.devices[1].settings else {
        panic!()
    };
    assert_eq!((r.max_range, r.frequency), (80.0, 76.5));
    let DeviceSettings::DistanceSensor(s) = &car.devices[2].settings else {
        panic!()
    };
    assert_eq!(
        (s.sensor_type, s.number_of_rays),
        (DistanceSensorType::Sonar, 4)
    );
    assert_eq!(car.devices[2].device_name(), "distance sensor");

    let head = "[vehicle]\nmodel = \"BmwX5\"\n[[vehicle.device]]\n";
    let (key, text) = refused(&format!(
        "{head}type = \"DistanceSensor\"\nsensorType = \"ultrasound\"\n"
    ));
    assert_eq!(key, "vehicle.device[1].sensorType");
    assert!(text.contains("infra-red"), "{text}");
    let (key, text) = refused(&format!("{head}type = \"Lidar\"\npreset = \"SickLms29\"\n"));
    assert_eq!(key, "vehicle.device[1].preset");
    assert!(text.contains("SickLms291"), "{text}");
    let (key, _) = refused(&format!(
        "{head}type = \"Radar\"\nminRange = 10\nmaxRange = 5\n"
    ));
    assert_eq!(key, "vehicle.device[1].maxRange");
    let (key, _) = refused(&format!(
        "{head}type = \"Lidar\"\nnear = 0.5\nminRange = 0.1\n"
    ));
    assert_eq!(key, "vehicle.device[1].minRange");
    let (key, _) = refused(&format!(
        "{head}type = \"Lidar\"\nhorizontalResolution = 0\n"
    ));
    assert_eq!(key, "vehicle.device[1].horizontalResolution");
    let (key, _) = refused("[vehicle]\nradarCrossSection = -1\n");
    assert_eq!(key, "vehicle.radarCrossSection");
}

#[test]
fn radar_sees_boxes_with_a_cross_section() {
    // A 1 m box of 2 m² 20 m ahead is a target at its centre; one of 0 m² (the default) at
    // 30 m is not (its ray still occludes nothing here: occlusion is off).
    let boxes = "[[body]]\ntranslation = [20, 0, 0.5]\nsize = [1, 1, 1]\nmass = 100\nradarCrossSection = 2\n\
                 [[body]]\ntranslation = [30, 3, 0.5]\nsize = [1, 1, 1]\nmass = 100\n";
    let (sim, ids) = radar_world("", &[], boxes);
    let t = targets(&sim, ids[0], "radar");
    assert_eq!(t.len(), 1, "{t:?}");
    let (p, _) = origin(&sim, ids[0]);
    let centre = sim.world().bodies()[0].position;
    // Tolerance: the same f64 arithmetic on the same positions.
    assert!((t[0].distance - (centre - p).norm()).abs() < 1e-9);
    assert!((t[0].received_power - default_power_dbm(2.0, t[0].distance)).abs() < 1e-9);
    // A negative cross-section is refused at its key.
    let (key, _) = refused(&format!(
        "{}radarCrossSection = -2\n",
        &boxes[..boxes.find("radarCrossSection").unwrap()]
    ));
    assert_eq!(key, "body[1].radarCrossSection");
}

#[test]
fn radar_sees_static_boxes_and_ramps_with_a_cross_section() {
    // A static 1 m box of 3 m² 25 m ahead is a target at its centre, a ramp of 4 m² whose low
    // edge is 40 m ahead (2 m left) one at that edge's middle (its solid's origin); a box of
    // 0 m² (the default, as in Webots) at 15 m is not, and (occlusion off) hides nothing.
    let statics = "[[box]]\ntranslation = [25, 0, 0.5]\nsize = [1, 1, 1]\nradarCrossSection = 3\n\
                   [[ramp]]\nstart = [40, 2]\nlength = 4\nwidth = 2\nheight = 0.5\nradarCrossSection = 4\n\
                   [[box]]\ntranslation = [15, -3, 0.5]\nsize = [1, 1, 1]\n";
    let (sim, ids) = radar_world("", &[], statics);
    let mut t = targets(&sim, ids[0], "radar");
    assert_eq!(t.len(), 2, "{t:?}");
    t.sort_by(|a, b| a.distance.total_cmp(&b.distance));
    let (p, _) = origin(&sim, ids[0]);
    for (target, (at, rcs)) in t.iter().zip([
        (Point3::new(25.0, 0.0, 0.5), 3.0),
        (Point3::new(40.0, 2.0, 0.0), 4.0),
    ]) {
        // Tolerance: the same f64 arithmetic on the same positions.
        assert!(
            (target.distance - (at - p).norm()).abs() < 1e-9,
            "{target:?}"
        );
        assert!((target.received_power - default_power_dbm(rcs, target.distance)).abs() < 1e-9);
        // Static: its radial speed is the car's own closing speed along the line (at rest).
        assert!(target.speed.abs() < 0.05, "{target:?}");
    }
    // A negative cross-section is refused at its key, on its line.
    for (table, key) in [
        ("box", "box[1].radarCrossSection"),
        ("ramp", "ramp[1].radarCrossSection"),
    ] {
        let text = if table == "box" {
            "[[box]]\ntranslation = [5, 0, 0.5]\nsize = [1, 1, 1]\nradarCrossSection = -1\n"
        } else {
            "[[ramp]]\nstart = [5, 0]\nlength = 4\nwidth = 2\nheight = 0.5\nradarCrossSection = -1\n"
        };
        let e = world_file::parse_str("w.toml", text).expect_err("refused");
        assert_eq!(e.key.as_deref(), Some(key), "{e}");
        assert!(e.to_string().contains("w.toml"), "{e}");
    }
}

#[test]
fn radar_sees_a_robot_with_a_cross_section() {
    // A DifferentialWheels robot at rest 12 m ahead (kinematics mode), 1.5 m²: a target at its
    // origin (the ground projection of its axle's middle).
    let robot = "[differential_wheels]\ntranslation = [12, 1, 0]\nradarCrossSection = 1.5\n";
    let (sim, ids) = radar_world("", &[], robot);
    let t = targets(&sim, ids[0], "radar");
    assert_eq!(t.len(), 1, "{t:?}");
    let (p, _) = origin(&sim, ids[0]);
    let at = sim.world().robots()[0].pose().position;
    // Tolerance: the same f64 arithmetic on the same positions.
    assert!((t[0].distance - (at - p).norm()).abs() < 1e-9, "{t:?}");
    assert!((t[0].received_power - default_power_dbm(1.5, t[0].distance)).abs() < 1e-9);
    let e = world_file::parse_str(
        "w.toml",
        "[differential_wheels]\nradarCrossSection = -0.5\n",
    )
    .expect_err("refused");
    assert_eq!(
        e.key.as_deref(),
        Some("differential_wheels.radarCrossSection"),
        "{e}"
    );
}
