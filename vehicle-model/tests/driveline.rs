//! The driveline model (issue #35): the engine's inertia the driven wheels carry in
//! `DrivelineModel::Inertial`, from Wong's mass factor, and Webots' limiter in the default
//! `DrivelineModel::Webots`.

mod common;

use common::golden::{close, driver};
use vehicle_model::{
    DrivelineModel, Driver, Gear, Model, PerWheel, Sensors, Wheel, WheelAngles, WheelDrive,
};

/// Readings at `t` (s) with every encoder at `angle` (rad).
fn encoders_at(t: f64, angle: f64) -> Sensors<f64> {
    Sensors {
        time: t,
        wheel_angles: PerWheel::splat(angle),
        steering: WheelAngles::STRAIGHT,
        wiper: None,
    }
}

/// Full throttle in first gear; three steps at 10 ms with the encoders at 0, 0 and 0.01 rad:
/// a speed of 1 rad/s from rest, an acceleration of 1000·(1 − 0)/10 = 100 rad/s², which
/// Webots' limiter answers with a factor 50/100.
fn launch(model: Model, driveline: DrivelineModel) -> Driver<f64> {
    let mut d = driver(model);
    d.set_driveline_model(driveline);
    d.set_gear(1);
    d.set_throttle(1.0);
    for (k, angle) in [0.0, 0.0, 0.0, 0.01].into_iter().enumerate() {
        d.step(&encoders_at(k as f64 * 0.01, angle));
    }
    d
}

#[test]
fn inertial_driven_wheels_carry_the_engine_by_wongs_mass_factor() {
    for model in [Model::BmwX5, Model::Bus, Model::Truck, Model::TeslaModel3] {
        let d = launch(model, DrivelineModel::Inertial);
        let p = d.params();
        let driven: Vec<Wheel> = Wheel::ALL
            .into_iter()
            .filter(|&w| p.drive_type.drives(w))
            .collect();
        let r = if p.drive_type.rear_driven() {
            p.radius_rear()
        } else {
            p.radius_front()
        };
        let xi = d.powertrain().gearbox().ratio(Gear::FIRST);
        let c = d.commands();
        // Wong (Theory of Ground Vehicles §3.1): the engine side of the mass factor is
        // 0.0025·ξ², i.e. the driven wheels' added inertia over r² is 0.0025·ξ²·m.
        let added: f64 = driven.iter().map(|&w| c.driveline_inertia[w]).sum();
        let equivalent_mass = added / (r * r);
        assert!(
            close(equivalent_mass, 0.0025 * xi * xi * p.body.mass, 1e-12),
            "{model}: {equivalent_mass} kg"
        );
        // Shared equally; the wheels that are not driven carry none.
        for w in Wheel::ALL {
            let expected = if driven.contains(&w) {
                added / driven.len() as f64
            } else {
                0.0
            };
            assert!(
                close(c.driveline_inertia[w], expected, 1e-12),
                "{model} {w:?}"
            );
        }
    }
}

#[test]
fn inertial_leaves_the_limiter_out_and_webots_keeps_it() {
    let webots = launch(Model::BmwX5, DrivelineModel::Webots);
    let inertial = launch(Model::BmwX5, DrivelineModel::Inertial);
    assert_eq!(webots.driveline_model(), DrivelineModel::Webots);
    assert_eq!(
        webots.commands().driveline_inertia,
        PerWheel::splat(0.0),
        "Webots' motors take no inertia"
    );
    let torque = |d: &Driver<f64>| -> f64 {
        Wheel::ALL
            .into_iter()
            .filter_map(|w| match d.commands().drive[w] {
                WheelDrive::Torque(t) => Some(t),
                _ => None,
            })
            .sum()
    };
    // Same engine speed, same throttle: only the limiter's factor 50/100 differs.
    assert!(close(torque(&webots), 0.5 * torque(&inertial), 1e-12));
    assert!(torque(&inertial) > 0.0);
}

#[test]
fn no_inertia_in_neutral_or_speed_mode() {
    let mut d = launch(Model::BmwX5, DrivelineModel::Inertial);
    d.set_gear(0);
    d.step(&encoders_at(0.04, 0.02));
    assert_eq!(d.commands().driveline_inertia, PerWheel::splat(0.0));
    d.set_cruising_speed(20.0);
    d.step(&encoders_at(0.05, 0.03));
    assert_eq!(d.commands().driveline_inertia, PerWheel::splat(0.0));
}

#[test]
fn f32_driver_gives_the_same_inertia() {
    let (mut d, report) = Driver::<f32>::new(Model::BmwX5.params(), 10);
    assert!(report.is_empty());
    d.set_driveline_model(DrivelineModel::Inertial);
    d.set_gear(1);
    d.set_throttle(1.0);
    d.step(&Sensors::unsampled(0.0));
    let f64_inertia = launch(Model::BmwX5, DrivelineModel::Inertial)
        .commands()
        .driveline_inertia;
    for w in Wheel::ALL {
        let (a, b) = (f64::from(d.commands().driveline_inertia[w]), f64_inertia[w]);
        // f32 carries about 7 significant digits.
        assert!((a - b).abs() <= 1e-6 * b.max(1.0), "{w:?}: {a} against {b}");
    }
}
