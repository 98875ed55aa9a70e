use super::*;
use crate::vehicle::Mounting;
use ackermann::Wheel;
use vehicle_model::Model;

/// A world with a cast car and, 10 m to its left, a car on joints.
fn two_cars() -> World {
    let mut world = World::new(WorldConfig::default()).unwrap();
    for (i, mounting) in [Mounting::Cast, Mounting::Joints].into_iter().enumerate() {
        let mut spec = VehicleSpec::from_car(&Model::BmwX5.params()).unwrap();
        spec.mounting = mounting;
        let placement = VehiclePlacement {
            y: 10.0 * i as f64,
            ..VehiclePlacement::default()
        };
        world.add_vehicle(spec, placement).unwrap();
    }
    world
}

#[test]
fn a_panic_in_a_step_is_an_error_naming_the_car_and_ends_the_world() {
    // A negative tyre width, past the validation, makes parry's cylinder assert in the
    // cast car's wheel query: the step returns the error instead of unwinding.
    let mut world = two_cars();
    world.step().unwrap();
    world.vehicles[0].spec_mut().wheels[Wheel::FrontRight].width = -0.2;
    let err = world.step().unwrap_err();
    let SimError::Panic {
        owner,
        time_ms,
        ref message,
    } = err
    else {
        panic!("{err:?}");
    };
    assert_eq!((owner, time_ms), (BodyOwner::Vehicle(0), 10));
    assert!(message.contains("assertion failed"), "{message}");
    assert!(
        err.to_string()
            .starts_with("the step at t = 10 ms failed in car 1's part of it (a bug): "),
        "{err}"
    );
    // The world is failed for good: the same error, no more time.
    assert_eq!(world.step().unwrap_err(), err);
    assert_eq!(world.time_ms(), 10);
    assert_eq!(world.failure(), Some(&err));
}

#[test]
fn a_diverged_body_is_named_by_its_car_and_part() {
    // A NaN velocity written into the second car's rear-left wheel: rapier quarantines the
    // body at the start of the step, and the error names that car and wheel.
    let mut world = two_cars();
    world.step().unwrap();
    let rear_left = Some(BodyPart::Wheel(Wheel::RearLeft));
    let wheel = world
        .physics
        .bodies
        .iter()
        .map(|(h, _)| h)
        .find(|h| world.vehicles[1].part_of(*h) == rear_left)
        .unwrap();
    world.physics.bodies[wheel].set_linvel(Vector::new(f32::NAN, 0.0, 0.0), true);
    let err = world.step().unwrap_err();
    assert_eq!(
        err,
        SimError::NonFinite {
            owner: BodyOwner::Vehicle(1),
            part: BodyPart::Wheel(Wheel::RearLeft),
            time_ms: 20,
        }
    );
    assert_eq!(
        err.to_string(),
        "the simulation diverged at t = 20 ms: the pose or velocity of the rear-left wheel \
         of car 2 stopped being finite"
    );
}
