//! Traffic cones (`[[cone]]`) against analytic geometry: a lidar reads the range to the
//! cone's surface on its layers, a camera sees the cone's colour at the pixels the pinhole
//! model predicts, a radar reports it with the power its cross-section gives, and bad values
//! are refused at their file, line and key.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::f64::consts::PI;

use sim::devices::{DeviceSettings, Reading};
use sim::nalgebra::{Isometry3, Point3, Translation3, Vector3};
use sim::{Obstacle, Simulation, VehicleId, world_file};

/// The simulation of world `text` and its one car.
fn world(text: &str) -> (Simulation, VehicleId) {
    let description = world_file::parse_str("cones.toml", text).unwrap();
    let (sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    (sim, id)
}

/// Device `k` of car `id` enabled every `period_ms`, the world stepped `steps` times; the
/// device's world pose then (device frame → world).
fn sample(
    sim: &mut Simulation,
    id: VehicleId,
    k: usize,
    period_ms: u32,
    steps: u32,
) -> Isometry3<f64> {
    sim.enable_device(id, k, period_ms).unwrap();
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let s = sim.world().vehicle(id).unwrap().state();
    let car = Isometry3::from_parts(Translation3::from(s.position.coords), s.orientation);
    car * sim.devices(id).unwrap()[k].mount()
}

/// The distance along the ray `o + t·d` (`d` unit) to the first point of the upright cone of
/// base centre `b`, height `h` and base radius `r` (its sides and its base), if any: the
/// cone's surface is (x − bx)² + (y − by)² = (r/h)² (h − (z − bz))², for bz ≤ z ≤ bz + h.
fn ray_cone(o: &Point3<f64>, d: &Vector3<f64>, b: &Point3<f64>, h: f64, r: f64) -> Option<f64> {
    let k = r / h;
    let p = o - b;
    // With w = h − z (local): x² + y² − k² w² = 0, w = h − p.z − t·d.z.
    let w0 = h - p.z;
    let a = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
    let bq = 2.0 * (p.x * d.x + p.y * d.y + k * k * w0 * d.z);
    let c = p.x * p.x + p.y * p.y - k * k * w0 * w0;
    let mut hits = Vec::new();
    let disc = bq * bq - 4.0 * a * c;
    if a.abs() > 1e-12 && disc >= 0.0 {
        let s = disc.sqrt();
        hits.extend([(-bq - s) / (2.0 * a), (-bq + s) / (2.0 * a)]);
    }
    // The base disc z = bz.
    if d.z.abs() > 1e-12 {
        let t = -p.z / d.z;
        let q = p + d * t;
        if q.x * q.x + q.y * q.y <= r * r {
            hits.push(t);
        }
    }
    hits.into_iter()
        .filter(|&t| {
            let z = p.z + t * d.z;
            t > 0.0 && (-1e-12..=h + 1e-12).contains(&z)
        })
        .min_by(f64::total_cmp)
}

const CONE_AHEAD: &str = r#"
[vehicle]
model = "BmwX5"
[[vehicle.device]]
type = "Lidar"
horizontalResolution = 128
fieldOfView = 0.4
maxRange = 30

[[cone]]
translation = [6, 0.2, 0]
height = 1.0
radius = 0.3
"#;

#[test]
fn a_lidar_reads_the_range_to_the_cones_surface_on_its_layers() {
    let (mut sim, id) = world(CONE_AHEAD);
    let pose = sample(&mut sim, id, 0, 20, 50);
    let DeviceSettings::Lidar(s) = sim.devices(id).unwrap()[0].settings().clone() else {
        panic!()
    };
    let Reading::Lidar(image) = sim.devices(id).unwrap()[0].reading().clone() else {
        panic!()
    };
    let (base, h, r) = (Point3::new(6.0, 0.2, 0.0), 1.0, 0.3);
    let o = Point3::from(pose.translation.vector);
    let mut on_cone = vec![0; s.number_of_layers as usize];
    for i in 0..s.number_of_layers {
        for j in 0..s.horizontal_resolution {
            let d = pose.rotation * s.direction(i, j);
            let ground = if d.z < 0.0 { -o.z / d.z } else { f64::INFINITY };
            let cone = ray_cone(&o, &d, &base, h, r).unwrap_or(f64::INFINITY);
            if cone < ground {
                on_cone[i as usize] += 1;
            }
            let t = cone.min(ground);
            let expected = if t > s.max_range { f64::INFINITY } else { t };
            let got = f64::from(image.range_image[(i * s.horizontal_resolution + j) as usize]);
            // Tolerance: rapier casts in f32 (~1e-6 relative at 6 m) and parry finds a ray's
            // hit on a cone, a support-map shape, by GJK iterations that stop within about
            // 1e-4 m; 1 mm holds both with margin.
            assert!(
                got == expected || (got - expected).abs() < 1e-3,
                "layer {i} ray {j}: {got} vs {expected}"
            );
        }
    }
    // The comparison above covered cone returns: the lidar's 4 layers over ±0.1 rad, from the
    // car's origin, cross the 1 m cone at several heights ([2, 15, 27, 0] rays per layer:
    // the lowest meets the ground first on most rays, the highest passes over the apex).
    assert!(
        on_cone.iter().filter(|&&n| n >= 10).count() >= 2,
        "{on_cone:?}"
    );
}

/// The RGB of pixel (`i`, `j`) of a BGRA `image` `width` pixels wide.
fn rgb(image: &[u8], width: usize, i: usize, j: usize) -> [u8; 3] {
    let k = 4 * (j * width + i);
    [image[k + 2], image[k + 1], image[k]]
}

#[test]
fn a_camera_sees_the_cones_colour_where_the_pinhole_puts_it() {
    let color = [0.9, 0.4, 0.1];
    let text = format!(
        "[vehicle]\nmodel = \"BmwX5\"\n[[vehicle.device]]\ntype = \"Camera\"\ntranslation = [4.5, 0, 0.6]\n\
         width = 128\nheight = 64\nfieldOfView = 1.0\n\
         [[cone]]\ntranslation = [10, 0.3, 0]\nheight = 1.2\nradius = 0.35\ncolor = {color:?}\n"
    );
    let (mut sim, id) = world(&text);
    let pose = sample(&mut sim, id, 0, 50, 5);
    let (w, hgt, fov) = (128.0, 64.0, 1.0);
    let f = w / 2.0 / (fov / 2.0_f64).tan();
    let o = Point3::from(pose.translation.vector);
    let base = Point3::new(10.0, 0.3, 0.0);
    // Webots' planar pinhole, u = w/2 − f·y/x, v = h/2 − f·z/x: the ray of image point (u, v).
    let hits = |u: f64, v: f64| {
        let d =
            (pose.rotation * Vector3::new(1.0, (w / 2.0 - u) / f, (hgt / 2.0 - v) / f)).normalize();
        ray_cone(&o, &d, &base, 1.2, 0.35).is_some()
    };
    let image = sim.devices(id).unwrap()[0].camera().unwrap().image();
    let is_cone = |px: [u8; 3]| {
        // Flat shading scales the colour by a brightness s in [0.5, 1] (ambient half to full
        // light): some s must give all three channels to the byte's rounding.
        (50..=100).any(|s| {
            let s = f64::from(s) / 100.0;
            px.iter()
                .zip(color)
                .all(|(&p, c)| (f64::from(p) - c * s * 255.0).abs() <= 1.5)
        })
    };
    let (mut inside, mut outside) = (0, 0);
    for j in 0..64 {
        for i in 0..128 {
            let (u, v) = (i as f64 + 0.5, j as f64 + 0.5);
            // A pixel is predicted inside (outside) when its centre and the points 1 px from
            // it all see (miss) the true cone: the drawn cone is a 24-sided pyramid whose
            // silhouette is within 0.9 % of the radius (0.03 px here) of the true one, and the
            // car settles by millimetres.
            let around = [(0.0, 0.0), (1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)]
                .map(|(du, dv)| hits(u + du, v + dv));
            let px = rgb(image, 128, i, j);
            if around.iter().all(|&h| h) {
                assert!(is_cone(px), "pixel ({i}, {j}) inside the cone: {px:?}");
                inside += 1;
            } else if around.iter().all(|&h| !h) {
                assert!(!is_cone(px), "pixel ({i}, {j}) outside the cone: {px:?}");
                outside += 1;
            }
        }
    }
    // 1.2 m high, 0.7 m wide at the foot at 5.5 m with f = 117 px: a triangle of ~25 × 15 px.
    assert!(inside > 100, "{inside}");
    assert!(outside > 7000, "{outside}");
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
fn a_radar_reports_a_cone_with_its_cross_sections_power() {
    // Two cones ahead: one of 0.5 m² at 20 m, one 30 m ahead and 2 m left with the default
    // cross-section (0.1 m²). A target's place is the cone's base centre (its solid's origin).
    let text = "[vehicle]\nmodel = \"BmwX5\"\n[[vehicle.device]]\ntype = \"Radar\"\n\
                [[cone]]\ntranslation = [20, 0, 0]\nradarCrossSection = 0.5\n\
                [[cone]]\ntranslation = [30, 2, 0]\n";
    let (mut sim, id) = world(text);
    let pose = sample(&mut sim, id, 0, 10, 100);
    let Reading::Radar(Some(mut t)) = sim.devices(id).unwrap()[0].reading().clone() else {
        panic!()
    };
    assert_eq!(t.len(), 2, "{t:?}");
    t.sort_by(|a, b| a.distance.total_cmp(&b.distance));
    let o = Point3::from(pose.translation.vector);
    for (target, (at, rcs)) in t.iter().zip([
        (Point3::new(20.0, 0.0, 0.0), 0.5),
        (Point3::new(30.0, 2.0, 0.0), sim::DEFAULT_CONE_RCS),
    ]) {
        // Tolerance: the same f64 arithmetic on the same positions.
        assert!(
            (target.distance - (at - o).norm()).abs() < 1e-9,
            "{target:?}"
        );
        assert!((target.received_power - default_power_dbm(rcs, target.distance)).abs() < 1e-9);
    }
}

#[test]
fn a_line_of_cones_is_count_cones_spacing_apart() {
    let text = "[vehicle]\nmodel = \"BmwX5\"\n\
                [[cone]]\ntranslation = [10, -1, 0]\ncount = 4\nspacing = [12, 0.5]\ncolor = [0, 0, 1]\n";
    let d = world_file::parse_str("w.toml", text).unwrap();
    let cones: Vec<_> = d
        .config
        .obstacles
        .iter()
        .map(|o| match o {
            Obstacle::Cone { cone, .. } => cone.clone(),
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(cones.len(), 4);
    for (k, c) in cones.iter().enumerate() {
        let k = k as f64;
        assert_eq!(c.base, Point3::new(10.0 + 12.0 * k, -1.0 + 0.5 * k, 0.0));
        assert_eq!((c.height, c.radius, c.color), (0.5, 0.15, [0.0, 0.0, 1.0]));
    }
}

#[test]
fn bad_cones_are_refused_at_their_file_line_and_key() {
    for (body, key, says) in [
        (
            "translation = [1, 0, 0]\nheight = 3\n",
            "cone[1].height",
            "3",
        ),
        (
            "translation = [1, 0, 0]\nradius = -0.2\n",
            "cone[1].radius",
            "-0.2",
        ),
        (
            "translation = [1, 0, 0]\ncolor = [2, 0, 0]\n",
            "cone[1].color",
            "2",
        ),
        (
            "translation = [1, 0, 0]\nradarCrossSection = -1\n",
            "cone[1].radarCrossSection",
            "-1",
        ),
        (
            "translation = [1, 0, 0]\ncount = 0\nspacing = [1, 0]\n",
            "cone[1].count",
            "0",
        ),
        (
            "translation = [1, 0, 0]\ncount = 3\n",
            "cone[1].spacing",
            "missing",
        ),
        (
            "translation = [1, 0, 0]\ncount = 3\nspacing = [0.2, 0]\n",
            "cone[1].spacing",
            "overlap",
        ),
        (
            "translation = [9000, 0, 0]\ncount = 3\nspacing = [1000, 0]\n",
            "cone[1].spacing",
            "11000",
        ),
        ("height = 1\n", "cone[1].translation", "missing"),
        (
            "translation = [1, 0, 0]\nsize = 1\n",
            "cone[1].size",
            "size",
        ),
    ] {
        let text = format!("[vehicle]\nmodel = \"BmwX5\"\n\n[[cone]]\n{body}");
        let e = world_file::parse_str("w.toml", &text).expect_err(body);
        let shown = e.to_string();
        assert_eq!(e.key.as_deref(), Some(key), "{shown}");
        assert_eq!(e.file, "w.toml");
        assert!(e.location.is_some_and(|l| l.line >= 4), "{shown}");
        assert!(shown.contains(says), "{body}: {shown}");
    }
}

#[test]
fn the_double_lane_change_world_lays_the_scenarios_course_in_cones() {
    use sim::scenario::{self, Scenario, double_lane_change};
    let w = world_file::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/worlds/double-lane-change.toml"
    ))
    .unwrap();
    let bases: Vec<Point3<f64>> = w
        .config
        .obstacles
        .iter()
        .filter_map(|o| match o {
            Obstacle::Cone { cone, .. } => Some(cone.base),
            _ => None,
        })
        .collect();
    // Each gate's two edges, cones at both ends and at most 5 m apart (the scenario's plot),
    // the track's entry 20 m ahead of the car; the file's y to 4 decimals.
    let mut expected = Vec::new();
    for g in double_lane_change(1.878, 3.5) {
        let n = ((g.end - g.start) / 5.0).ceil() as usize;
        for side in [-0.5, 0.5] {
            for k in 0..=n {
                let x = 20.0 + g.start + (g.end - g.start) * k as f64 / n as f64;
                expected.push(Point3::new(x, g.center + side * g.width, 0.0));
            }
        }
    }
    assert_eq!(bases.len(), expected.len());
    for (b, e) in bases.iter().zip(&expected) {
        assert!((b - e).norm() < 1e-4, "{b} vs {e}");
    }
    // Its programme drives straight through the entry and exit gates, touching no cone: a
    // touch would push the car sideways.
    let r = scenario::run(&w, Scenario::default_for(&w), &mut |_| {}).unwrap();
    let samples = &r.results[0].telemetry[0].samples;
    assert!(
        samples.last().unwrap().x > 20.0 + 125.0,
        "{:?}",
        samples.last()
    );
    assert!(samples.iter().all(|s| s.y.abs() < 0.05));
    assert!(!r.results[0].devices.is_empty());
}
