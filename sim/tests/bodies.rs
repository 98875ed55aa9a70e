//! `[[body]]` dynamic boxes: world-file errors, a box dropped on the ground, a box pushed by a
//! car.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::nalgebra::{Point3, Vector3};
use sim::world_file::{WorldFileErrorKind, parse_str};
use sim::{BodySpec, Simulation, VehiclePlacement, World, WorldConfig};
use vehicle_model::Model;

const CAR: &str = "[vehicle]\nmodel = \"BmwX5\"\n";

fn error(body: &str) -> sim::world_file::WorldFileError {
    parse_str("w.toml", &format!("{CAR}[[body]]\n{body}")).unwrap_err()
}

#[test]
fn world_file_reads_bodies() {
    let w = parse_str(
        "w.toml",
        &format!(
            "{CAR}[[body]]\nsize = [1.0, 2.0, 0.5]\nmass = 200.0\ntranslation = [5.0, 0.0, 0.25]\n\
             rotation = [0, 0, 1, 0.3]\nfriction = 0.8\n[[body]]\nsize = [1, 1, 1]\nmass = 1\n\
             translation = [0, 9, 0.5]\n"
        ),
    )
    .unwrap();
    assert_eq!(
        w.config.bodies,
        [
            BodySpec {
                center: Point3::new(5.0, 0.0, 0.25),
                size: Vector3::new(1.0, 2.0, 0.5),
                yaw: 0.3,
                mass: 200.0,
                friction: Some(0.8),
                radar_cross_section: 0.0,
            },
            BodySpec {
                center: Point3::new(0.0, 9.0, 0.5),
                size: Vector3::repeat(1.0),
                yaw: 0.0,
                mass: 1.0,
                friction: None,
                radar_cross_section: 0.0,
            },
        ]
    );
}

#[test]
fn world_file_errors_name_file_line_and_key() {
    // Lines 1-2 are the car, 3 is [[body]], the body's keys start on line 4.
    let e = error("size = [1, 1, 1]\nmass = -5\ntranslation = [0, 0, 1]\n");
    assert_eq!(e.file, "w.toml");
    assert_eq!(e.location.map(|l| l.line), Some(5));
    assert_eq!(e.key.as_deref(), Some("body[1].mass"));
    assert_eq!(
        e.to_string(),
        "w.toml:5:1: invalid 'body[1].mass': -5: must be within 0.001 to 1000000 kg"
    );

    let e = error("size = [1, 2000, 1]\nmass = 5\ntranslation = [0, 0, 1]\n");
    assert_eq!(e.location.map(|l| l.line), Some(4));
    assert_eq!(e.key.as_deref(), Some("body[1].size"));
    assert!(matches!(e.kind, WorldFileErrorKind::InvalidValue(_)), "{e}");

    let e = error("size = [1, 1, 1]\nmass = 5\ntranslation = [0, nan, 1]\n");
    assert_eq!(e.location.map(|l| l.line), Some(6));
    assert_eq!(e.key.as_deref(), Some("body[1].translation"));

    let e = error("size = [1, 1, 1]\nmass = 5\ntranslation = [0, 0, 1]\nrotation = [1, 0, 0, 1]\n");
    assert_eq!(e.location.map(|l| l.line), Some(7));
    assert_eq!(e.key.as_deref(), Some("body[1].rotation"));

    let e = error("size = [1, 1, 1]\nmas = 5\ntranslation = [0, 0, 1]\n");
    assert_eq!(e.location.map(|l| l.line), Some(5));
    assert_eq!(e.suggestions(), ["mass"]);

    let e = error("size = [1, 1, 1]\ntranslation = [0, 0, 1]\n");
    assert_eq!(e.key.as_deref(), Some("body[1].mass"));
    assert!(matches!(e.kind, WorldFileErrorKind::Structure(_)), "{e}");

    let e = error("size = [1, 1]\nmass = 5\ntranslation = [0, 0, 1]\n");
    assert_eq!(e.location.map(|l| l.line), Some(4));
    assert!(
        matches!(e.kind, WorldFileErrorKind::WrongType { .. }),
        "{e}"
    );
}

#[test]
fn world_rejects_bad_bodies_without_panicking() {
    let bad = BodySpec {
        center: Point3::new(0.0, 0.0, 1.0),
        size: Vector3::repeat(1.0),
        yaw: 0.0,
        mass: f64::INFINITY,
        friction: None,
        radar_cross_section: 0.0,
    };
    let Err(sim::SimError::Param(e)) = World::new(WorldConfig {
        bodies: vec![bad],
        ..WorldConfig::default()
    }) else {
        panic!("an infinite mass was accepted");
    };
    assert_eq!((e.field, e.value), ("body.mass", f64::INFINITY));
}

#[test]
fn dropped_box_falls_freely_then_rests_on_the_ground() {
    // A 1 m, 200 kg cube whose bottom starts 0.5 m above the ground.
    let cube = BodySpec {
        center: Point3::new(0.0, 0.0, 1.0),
        size: Vector3::repeat(1.0),
        yaw: 0.0,
        mass: 200.0,
        friction: None,
        radar_cross_section: 0.0,
    };
    let mut world = World::new(WorldConfig {
        bodies: vec![cube],
        ..WorldConfig::default()
    })
    .unwrap();
    // Free fall, integrated by rapier's symplectic Euler (v += g·dt, then z += v·dt): after n
    // steps z = z0 − g·dt²·n(n+1)/2. 25 steps of 10 ms: 1 − 9.81·1e-4·325 = 0.681175 m, still
    // 0.18 m above touching. f32 state: 1e-5 m.
    for _ in 0..25 {
        world.step().unwrap();
    }
    let z = world.bodies()[0].position.z;
    assert!((z - 0.681_175).abs() < 1e-5, "{z}");
    for _ in 0..175 {
        world.step().unwrap();
    }
    let p = world.bodies()[0];
    // At rest on its face: centre at half its height. rapier lets a resting contact sink by its
    // allowed linear error (1 mm at length unit 1) plus the soft contact's static deflection
    // (g/ω², 0.07 mm at 60 Hz), so 2 mm.
    assert!((p.position.z - 0.5).abs() < 2e-3, "{p:?}");
    // A flat landing has no reason to move sideways, but rapier solves the four corner
    // contacts of the 3.1 m/s impact one after the other, and the box skids a few mm (7 mm
    // measured): 1 cm.
    assert!(p.position.x.hypot(p.position.y) < 1e-2, "{p:?}");
    let speed = p.velocity.norm();
    assert!(speed < 1e-2, "{p:?}");
    // It landed flat and stayed so.
    let a = p.roll_pitch_yaw;
    assert!(
        [a.roll, a.pitch, a.yaw].iter().all(|a| a.abs() < 1e-3),
        "{p:?}"
    );
}

#[test]
fn car_pushes_a_box_ahead_of_it() {
    // A 1 m, 200 kg cube 10 m ahead of a BmwX5 (2.3 t) holding 10 km/h in a straight line. The
    // car's wheels only see static geometry: it is the chassis collision box that pushes.
    let cube = BodySpec {
        center: Point3::new(10.0, 0.0, 0.5),
        size: Vector3::repeat(1.0),
        yaw: 0.0,
        mass: 200.0,
        friction: Some(0.8),
        radar_cross_section: 0.0,
    };
    let world = World::new(WorldConfig {
        bodies: vec![cube],
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let (id, _) = sim
        .add_car(sim::CarBuilder::new(Model::BmwX5.params()).placement(VehiclePlacement::default()))
        .unwrap();
    let chassis = sim.world().vehicle(id).unwrap().spec().chassis;
    // The front face of the chassis box, ahead of the car origin (rear axle).
    let front = chassis.box_center[0] + chassis.box_half_extents[0];
    assert!(
        chassis.box_center[2] - chassis.box_half_extents[2] < 1.0,
        "{chassis:?}"
    );
    sim.driver_mut(id).unwrap().set_cruising_speed(10.0);
    let mut touched_at = None;
    for step in 0..1500 {
        sim.step().unwrap();
        let car_x = sim.telemetry(id).unwrap().state.position.x;
        let b = sim.world().bodies()[0];
        if touched_at.is_none() && b.position.x > 10.0 + 1e-3 {
            touched_at = Some((step, car_x));
        }
    }
    // Before the chassis reaches it the box stays put: the first contact happens with the
    // chassis front at the box's rear face (9.5 m), within one step of travel (2.8 cm) plus
    // contact margins.
    let (step, car_x) = touched_at.expect("the box never moved");
    assert!(step > 100, "moved at step {step}");
    assert!((car_x + front - 9.5).abs() < 0.05, "{car_x} + {front}");
    // Afterwards the car keeps pushing it: over 15 s at 2.78 m/s the car covers about 40 m, so
    // the box ends tens of metres from its start, just ahead of the chassis (touching, within
    // 5 cm), still upright on its face and near the line of travel.
    let t = sim.telemetry(id).unwrap();
    let b = sim.world().bodies()[0];
    assert!(b.position.x > 30.0, "{b:?}");
    let gap = b.position.x - 0.5 - (t.state.position.x + front);
    assert!(gap.abs() < 0.05, "gap {gap}, {b:?}");
    assert!(b.position.y.abs() < 0.5, "{b:?}");
    assert!((b.position.z - 0.5).abs() < 2e-3, "{b:?}");
    assert!((t.speed - 10.0 / 3.6).abs() < 0.3, "{}", t.speed);
}
