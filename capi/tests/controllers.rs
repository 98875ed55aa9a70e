//! Several controllers over one world (the project's extension `car::controllers`, used by the
//! ROS node): each controller's getters read its own car, its devices are its own, and a step
//! of any controller advances the one world once.
//!
//! One test function: the session is the process's, so the steps below must not interleave
//! with another test's (each integration test file is a process of its own).

// Test helpers report failures by panicking.
#![allow(clippy::unwrap_used, clippy::expect_used)]
// `wb_robot_get_device` takes a C string, and the world is chosen through the environment.
#![allow(unsafe_code)]

use car::controllers::{self, WorldCar};
use car::supervisor::{self, NodeRef};

/// The world of this test (two free cars and a programmed one).
fn world() -> String {
    format!("{}/tests/worlds/two_cars.toml", env!("CARGO_MANIFEST_DIR"))
}

/// The tag of device `name` of the current controller's car.
fn device(name: &str) -> u16 {
    let name = std::ffi::CString::new(name).unwrap();
    // SAFETY: a NUL-terminated string that outlives the call.
    unsafe { car::wb_robot_get_device(name.as_ptr()) }
}

/// Car `name`'s placement (supervisor).
fn placement(name: &str) -> sim::Placement {
    let node = supervisor::node_from_def(name).unwrap();
    assert!(matches!(node, NodeRef::Car(_)));
    supervisor::placement(node).unwrap()
}

#[test]
fn two_controllers_drive_their_own_cars_in_one_world() {
    // SAFETY: the only test of this process; nothing else reads the environment meanwhile.
    unsafe { std::env::set_var(car::WORLD_VARIABLE, world()) };

    // Before anything is loaded: the file's cars, nothing current.
    let car = |name: &str, programmed| WorldCar {
        name: name.to_string(),
        programmed,
    };
    let cars = vec![car("alpha", false), car("beta", false), car("gamma", true)];
    assert_eq!(controllers::cars().unwrap(), cars);
    assert_eq!(controllers::current(), None);
    let unknown = controllers::select("delta").unwrap_err();
    assert!(
        unknown.contains("no car named \"delta\"") && unknown.contains("alpha, beta, gamma"),
        "{unknown}"
    );
    assert_eq!(controllers::current(), None, "a refused name loads nothing");

    // Each controller has its own device table: alpha's GPS comes after its gyro.
    controllers::select("alpha").unwrap();
    assert_eq!(controllers::current().as_deref(), Some("alpha"));
    car::vehicle_capi_driver_init();
    let alpha_gps = device("gps");
    assert!(alpha_gps != 0 && device("gyro") == alpha_gps - 1);
    car::wb_gps_enable(alpha_gps, 10);
    car::vehicle_capi_driver_set_cruising_speed(20.0); // km/h
    car::vehicle_capi_driver_set_steering_angle(0.1); // rad, right

    controllers::select("beta").unwrap();
    assert_eq!(controllers::current().as_deref(), Some("beta"));
    // Beta's driver library is its own: not initialised yet, so its getters warn and give
    // the neutral value, while alpha's target is 20 km/h.
    assert_eq!(car::vehicle_capi_driver_get_target_cruising_speed(), 0.0);
    car::vehicle_capi_driver_init();
    let beta_gps = device("gps");
    assert_eq!(device("gyro"), 0, "beta has no gyro");
    assert_eq!(beta_gps, alpha_gps - 1, "beta's GPS is its first sensor");
    car::wb_gps_enable(beta_gps, 10);
    car::vehicle_capi_driver_set_cruising_speed(10.0);
    car::vehicle_capi_driver_set_steering_angle(-0.05); // left

    // Gamma runs its programme (20 km/h) while no controller drives it.
    assert_eq!(
        controllers::cars().unwrap(),
        cars,
        "the loaded world's cars"
    );

    // One step per call, whichever controller is current: 500 calls are 5 s.
    for _ in 0..500 {
        assert_eq!(car::vehicle_capi_driver_step(), 0);
    }
    assert!((car::wb_robot_get_time() - 5.0).abs() < 1e-9);

    // Each controller reads its own car. The cruise control settles within 1 km/h of its
    // target in 5 s (the ROS test's 0.5 km/h after a longer run; the crate doctest's 3 s to
    // 20 km/h on a straight road).
    let speed = car::vehicle_capi_driver_get_current_speed();
    assert!((speed - 10.0).abs() < 1.0, "beta: {speed} km/h");
    assert_eq!(car::vehicle_capi_driver_get_target_cruising_speed(), 10.0);
    // The steering getter is the mean of the two measured wheel angles: the Ackermann pair's
    // mean differs from the commanded angle by its second-order term (1e-5 rad here).
    let steering = car::vehicle_capi_driver_get_steering_angle();
    assert!((steering + 0.05).abs() < 1e-4, "beta: {steering} rad");
    let [_, y_beta, _] = car::values::wb_gps_get_values(beta_gps).unwrap();
    controllers::select("alpha").unwrap();
    let speed = car::vehicle_capi_driver_get_current_speed();
    assert!((speed - 20.0).abs() < 1.0, "alpha: {speed} km/h");
    assert_eq!(car::vehicle_capi_driver_get_target_cruising_speed(), 20.0);
    let steering = car::vehicle_capi_driver_get_steering_angle();
    assert!((steering - 0.1).abs() < 1e-3, "alpha: {steering} rad");
    let [_, y_alpha, _] = car::values::wb_gps_get_values(alpha_gps).unwrap();

    // The GPS of each reads its own car: each within a car length of its car's origin.
    let (alpha, beta) = (placement("alpha"), placement("beta"));
    assert!(
        (y_alpha - alpha.position.y).abs() < 3.0,
        "{y_alpha} {alpha:?}"
    );
    assert!((y_beta - beta.position.y).abs() < 3.0, "{y_beta} {beta:?}");
    assert!(y_beta - y_alpha > 5.0, "beta started 10 m left of alpha");
    // Right steering turns clockwise (the heading falls), left counter-clockwise; both
    // started heading along x (yaw 0).
    let yaw = |p: &sim::Placement| p.rotation.euler_angles().2;
    assert!(yaw(&alpha) < -0.1, "{alpha:?}");
    assert!(yaw(&beta) > 0.05, "{beta:?}");
    // Gamma cruised off on its programme (20 km/h is 5.6 m/s).
    let gamma = placement("gamma");
    assert!(gamma.velocity.norm() > 4.0, "{gamma:?}");

    // Taking gamma: its programme stops, its controller starts like any other.
    controllers::select("gamma").unwrap();
    car::vehicle_capi_driver_init();
    car::vehicle_capi_driver_set_cruising_speed(0.0);
    car::vehicle_capi_driver_set_brake_intensity(1.0);
    for _ in 0..300 {
        assert_eq!(car::vehicle_capi_driver_step(), 0);
    }
    let gamma = placement("gamma");
    assert!(
        gamma.velocity.norm() < 0.1,
        "gamma brakes to a stop: {gamma:?}"
    );
    // The others drive on.
    assert!(placement("beta").velocity.norm() > 2.0);

    // Cleanup frees the world and every controller.
    car::vehicle_capi_driver_cleanup();
    assert_eq!(controllers::current(), None);
}
