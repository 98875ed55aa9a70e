//! The ground's friction (`crate::ground`) as a world builds it and as the wheels of both
//! mountings read it.

use super::*;
use crate::body::BodySpec;
use crate::vehicle::Mounting;
use proto_geom::nalgebra::{Point2, Point3, Vector3};
use vehicle_model::Model;

/// A BmwX5 on each mounting, 3 m right (cast) and 3 m left (joints) of the x axis, with
/// its rear axle at `x` (m) and its origin `z` (m) high.
fn add_both_cars(world: &mut World, x: f64, z: f64) {
    for (y, mounting) in [(-3.0, Mounting::Cast), (3.0, Mounting::Joints)] {
        let mut spec = VehicleSpec::from_car(&Model::BmwX5.params()).unwrap();
        spec.mounting = mounting;
        let placement = VehiclePlacement {
            x,
            y,
            z: Some(z),
            ..VehiclePlacement::default()
        };
        world.add_vehicle(spec, placement).unwrap();
    }
}

#[test]
fn both_mountings_read_a_ramps_own_friction_in_f64() {
    // A gentle ramp (0.4 m over 40 m) of friction 0.7 on ground of friction 0.5, both cars
    // on it: every wheel of both reads 0.7 exactly, not the ground's 0.5 nor rapier's f32
    // rounding of 0.7 (0.699999988).
    let ramp = Obstacle::Ramp {
        start: Point2::new(-20.0, 0.0),
        yaw: 0.0,
        length: 40.0,
        width: 12.0,
        height: 0.4,
        friction: Some(0.7),
        radar_cross_section: 0.0,
    };
    let config = WorldConfig {
        ground_friction: 0.5,
        obstacles: vec![ramp],
        ..WorldConfig::default()
    };
    let mut world = World::new(config).unwrap();
    // Rear axle at x = −1.5, 0.185 m up the ramp: dropped from 4 cm above it.
    add_both_cars(&mut world, -1.5, 0.374 + 0.185 + 0.04);
    for _ in 0..50 {
        world.step().unwrap();
    }
    for v in &world.vehicles {
        let z = v.state().position.z;
        // On the ramp: the rear axle 0.185 m up, less the springs' static sag (about 5 cm).
        let on_ramp = 0.374 + 0.185 - 0.05;
        eprintln!(
            "{:?} z = {z} x = {}",
            v.spec().mounting,
            v.state().position.x
        );
        assert!(
            (z - on_ramp).abs() < 0.02,
            "{:?} at z = {z}",
            v.spec().mounting
        );
        let frictions = v.ground_frictions(&world.physics, &world.ground);
        assert_eq!(frictions, [Some(0.7); 4], "{:?}", v.spec().mounting);
    }
}

#[test]
fn both_mountings_read_the_grounds_friction_in_f64() {
    let config = WorldConfig {
        ground_friction: 0.3,
        ..WorldConfig::default()
    };
    let mut world = World::new(config).unwrap();
    add_both_cars(&mut world, 0.0, 0.374);
    for _ in 0..50 {
        world.step().unwrap();
    }
    for v in &world.vehicles {
        let frictions = v.ground_frictions(&world.physics, &world.ground);
        assert_eq!(frictions, [Some(0.3); 4], "{:?}", v.spec().mounting);
    }
}

#[test]
fn a_box_has_its_own_friction_and_a_car_the_grounds() {
    // The rule for what is not a static surface: a dynamic box's own friction (or the
    // default 1), anything else (a car's chassis or wheel) the ground's.
    let cube = |x: f64, friction: Option<f64>| BodySpec {
        center: Point3::new(x, -20.0, 0.5),
        size: Vector3::repeat(1.0),
        yaw: 0.0,
        mass: 200.0,
        friction,
        radar_cross_section: 0.0,
    };
    let config = WorldConfig {
        ground_friction: 0.45,
        bodies: vec![cube(0.0, Some(0.7)), cube(5.0, None)],
        ..WorldConfig::default()
    };
    let mut world = World::new(config).unwrap();
    add_both_cars(&mut world, 0.0, 0.374);
    let p = Point3::origin();
    let friction_of = |world: &World, body: RigidBodyHandle| {
        let collider = world.physics.bodies[body].colliders()[0];
        world.ground.friction_at(collider, &p)
    };
    assert_eq!(friction_of(&world, world.bodies[0]), 0.7);
    assert_eq!(friction_of(&world, world.bodies[1]), 1.0);
    for v in &world.vehicles {
        for body in v.bodies() {
            assert_eq!(friction_of(&world, body), 0.45, "{:?}", v.spec().mounting);
        }
    }
}
