//! The RoadSensor device (a project extension) against the road geometry: a car placed at a
//! known pose on a straight road and on an arc reads the offset, heading error, curvature,
//! line and edge distances the closed forms give; NaN before its first sample and off the
//! roads; its world-file fields.
#![allow(clippy::unwrap_used, clippy::panic)]

use core::f64::consts::PI;

use sim::devices::{DeviceKind, DeviceSettings, DeviceSpec, Reading, RoadSensorReading};
use sim::nalgebra::{Point2, Vector2};
use sim::road::{Curve, Road, RoadNetwork};
use sim::{CarBuilder, Simulation, VehicleId, VehiclePlacement, World, WorldConfig, world_file};
use vehicle_model::Model;

/// Offsets and distances agree within 1 cm, angles within 1 mrad: the car, placed with its
/// springs unloaded, settles by millimetres in its first step.
const LENGTH_TOL: f64 = 0.01;
const ANGLE_TOL: f64 = 1e-3;

/// A simulation of `road` with a BmwX5 whose origin (the rear-axle centre) is at (`x`, `y`)
/// heading `yaw`, carrying a road sensor at its origin, enabled every step.
fn car_with_sensor(road: Road, x: f64, y: f64, yaw: f64) -> (Simulation, VehicleId) {
    let world = World::new(WorldConfig {
        roads: RoadNetwork {
            roads: vec![road],
            junctions: Vec::new(),
        },
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let sensor = DeviceSpec::new(DeviceSettings::default_of(DeviceKind::RoadSensor));
    let (id, _) = sim
        .add_car(
            CarBuilder::of_model(Model::BmwX5)
                .placement(VehiclePlacement { x, y, yaw, z: None })
                .device(sensor),
        )
        .unwrap();
    sim.enable_device(id, 0, 10).unwrap();
    (sim, id)
}

fn road_reading(sim: &Simulation, id: VehicleId) -> RoadSensorReading {
    match sim.devices(id).unwrap()[0].reading() {
        Reading::Road(r) => *r,
        other => panic!("{other:?}"),
    }
}

fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!((a - b).abs() < tol, "{what}: {a} vs {b}");
}

#[test]
fn on_a_straight_road_the_reading_is_the_geometry() {
    // One 3.5 m lane each way along heading 0.4 rad from (3, 4); the car at s = 40 m,
    // t = −1.2 m (0.55 m left of the right lane's centre), pointing 0.05 rad left of it.
    let h = 0.4;
    let road = Road::two_way("s", Point2::new(3.0, 4.0), h, &[(200.0, Curve::Line)], 3.5).unwrap();
    let (s, t) = (40.0, -1.2);
    let p = Point2::new(3.0, 4.0)
        + Vector2::new(h.cos(), h.sin()) * s
        + Vector2::new(-h.sin(), h.cos()) * t;
    let (mut sim, id) = car_with_sensor(road, p.x, p.y, h + 0.05);
    assert!(road_reading(&sim, id).lateral_offset.is_nan());
    sim.step().unwrap();
    let r = road_reading(&sim, id);
    assert_eq!((r.road, r.lane), (Some(0), Some(-1)));
    close(r.s, s, LENGTH_TOL, "s");
    close(r.lateral_offset, t + 1.75, LENGTH_TOL, "offset");
    close(r.heading_error, 0.05, ANGLE_TOL, "heading error");
    close(r.left_line, -t, LENGTH_TOL, "left line");
    close(r.right_line, t + 3.5, LENGTH_TOL, "right line");
    close(r.left_edge, 3.5 - t, LENGTH_TOL, "left edge");
    close(r.right_edge, t + 3.5, LENGTH_TOL, "right edge");
    close(r.lane_width, 3.5, 1e-12, "lane width");
    close(r.curvature, 0.0, 1e-12, "curvature");
    close(r.curvature_ahead, 0.0, 1e-12, "curvature ahead");
}

#[test]
fn on_an_arc_the_reading_is_the_circle() {
    // A left arc of radius 50 m about (0, 50); the car at angle 0.6 rad, t = −1.0 m (radius
    // 51 m, 0.75 m left of the right lane's centre at 51.75 m), 0.02 rad right of the
    // tangent.
    let radius = 50.0;
    let road = Road::two_way(
        "a",
        Point2::origin(),
        0.0,
        &[(
            PI * radius,
            Curve::Arc {
                curvature: 1.0 / radius,
            },
        )],
        3.5,
    )
    .unwrap();
    let (theta, t) = (0.6_f64, -1.0);
    let p = Point2::new(0.0, radius) + Vector2::new(theta.sin(), -theta.cos()) * (radius - t);
    let (mut sim, id) = car_with_sensor(road, p.x, p.y, theta - 0.02);
    sim.step().unwrap();
    let r = road_reading(&sim, id);
    assert_eq!(r.lane, Some(-1));
    close(r.s, radius * theta, LENGTH_TOL, "s = R·θ");
    close(r.lateral_offset, 0.75, LENGTH_TOL, "offset");
    close(r.heading_error, -0.02, ANGLE_TOL, "heading error");
    close(
        r.curvature,
        1.0 / 51.75,
        1e-9,
        "the lane centre's curvature",
    );
    close(
        r.curvature_ahead,
        1.0 / 51.75,
        1e-9,
        "10 m ahead, still on the arc",
    );
    close(r.left_line, 1.0, LENGTH_TOL, "left line");
    close(r.right_line, 2.5, LENGTH_TOL, "right line");
}

#[test]
fn off_the_road_every_number_is_nan() {
    let road = Road::two_way("s", Point2::origin(), 0.0, &[(100.0, Curve::Line)], 3.5).unwrap();
    let (mut sim, id) = car_with_sensor(road, 50.0, 20.0, 0.0);
    sim.step().unwrap();
    let r = road_reading(&sim, id);
    assert_eq!((r.road, r.lane), (None, None));
    assert!(r.lateral_offset.is_nan() && r.s.is_nan());
}

#[test]
fn the_world_file_reads_a_road_sensor_and_refuses_a_bad_lookahead() {
    let text = |lookahead: &str| {
        format!(
            "[[road]]\nid = \"r\"\n[[road.segment]]\ntype = \"straight\"\nlength = 100\n\
             [vehicle]\nmodel = \"BmwX5\"\ntranslation = [10, -1.75, 0]\n\
             [[vehicle.device]]\ntype = \"RoadSensor\"\nname = \"lanes\"\n{lookahead}\n"
        )
    };
    let w = world_file::parse_str("w.toml", &text("lookahead = 25")).unwrap();
    let DeviceSettings::RoadSensor(s) = &w.cars[0].devices[0].settings else {
        panic!("{:?}", w.cars[0].devices);
    };
    assert_eq!(s.lookahead, 25.0);
    let w = world_file::parse_str("w.toml", &text("")).unwrap();
    assert_eq!(
        w.cars[0].devices[0].settings,
        DeviceSettings::RoadSensor(sim::devices::RoadSensorSettings { lookahead: 10.0 })
    );
    let e = world_file::parse_str("w.toml", &text("lookahead = -1"))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("w.toml:") && e.contains("lookahead") && e.contains("from 0 to 500 m"),
        "{e}"
    );
}
