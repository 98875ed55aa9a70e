//! Every shipped model validates without warnings and matches the spec §5 tables.

use proto_geom::nalgebra::{Translation3, Vector3};
use vehicle_model::{
    CarParams, DriveType, Driver, EngineType, Model, Wheel, WheelPhysics, is_physical_inertia,
};

/// One row of spec §5 (`None` = the `Car` default applies and is checked elsewhere).
struct Row {
    model: Model,
    drive: DriveType,
    engine: EngineType,
    time0to100: f64,
    torque: f64,
    power: f64,
    rpm: (f64, f64),
    gears: &'static [f64],
    brake: f64,
    tracks: (f64, f64),
    wheelbase: f64,
    steering: f64,
    wheels_damping: f64,
    max_velocity: f64,
    radii: (f64, f64),
    body_mass: f64,
    com: [f64; 3],
    sound: bool,
}

const DEF_GEARS: &[f64] = &[-12.0, 10.0, 6.5, 4.5, 3.5, 2.75];

#[rustfmt::skip]
fn table() -> Vec<Row> {
    use DriveType::{FourByFour as X4, Propulsion as P, Traction as T};
    use EngineType::{Combustion as C, Electric as E, PowerSplitHybrid as S};
    vec![
        Row { model: Model::BmwX5, drive: T, engine: C, time0to100: 7.0, torque: 250.0, power: 50_000.0, rpm: (1000.0, 6500.0), gears: &[-12.5, 12.5, 8.0, 5.35, 4.3, 4.0], brake: 1800.0, tracks: (1.628, 1.628), wheelbase: 2.995, steering: 1.0, wheels_damping: 2.0, max_velocity: 50.0, radii: (0.374, 0.374), body_mass: 2000.0, com: [1.2975, 0.0, 0.1], sound: true },
        Row { model: Model::CitroenCZero, drive: P, engine: E, time0to100: 17.5, torque: 150.0, power: 75_000.0, rpm: (1000.0, 8000.0), gears: &[-6.2329, 6.2329], brake: 580.0, tracks: (1.31, 1.27), wheelbase: 2.55, steering: 0.631, wheels_damping: 1.55, max_velocity: 50.0, radii: (0.28475, 0.28675), body_mass: 1200.0, com: [1.180, -0.002, 0.248], sound: false },
        Row { model: Model::ToyotaPrius, drive: T, engine: S, time0to100: 10.7, torque: 350.0, power: 33_000.0, rpm: (1200.0, 6500.0), gears: &[-6.0, 6.0], brake: 700.0, tracks: (1.628, 1.628), wheelbase: 2.8, steering: 1.0, wheels_damping: 1.0, max_velocity: 50.0, radii: (0.317, 0.317), body_mass: 1805.0, com: [1.2975, 0.0, 0.1], sound: true },
        Row { model: Model::LincolnMKZ, drive: X4, engine: C, time0to100: 4.97, torque: 250.0, power: 298_000.0, rpm: (1000.0, 5500.0), gears: &[-2.94, 4.58, 2.96, 1.91, 1.45, 1.00, 0.75], brake: 1400.0, tracks: (1.64, 1.64), wheelbase: 2.94, steering: 1.0, wheels_damping: 2.0, max_velocity: 50.0, radii: (0.358, 0.358), body_mass: 1950.0, com: [1.6, 0.0, 0.2], sound: true },
        Row { model: Model::RangeRoverSportSVR, drive: X4, engine: C, time0to100: 4.7, torque: 680.0, power: 50_000.0, rpm: (1000.0, 5500.0), gears: &[-3.0, 4.696, 3.130, 2.104, 1.667, 1.285, 1.000, 0.839, 0.667], brake: 1000.0, tracks: (1.64, 1.64), wheelbase: 2.71, steering: 1.0, wheels_damping: 5.0, max_velocity: 50.0, radii: (0.358, 0.358), body_mass: 2700.0, com: [1.6, 0.0, 0.2], sound: true },
        Row { model: Model::TeslaModel3, drive: P, engine: E, time0to100: 4.0, torque: 639.0, power: 147_000.0, rpm: (1000.0, 25_000.0), gears: &[-6.3, 9.0], brake: 2000.0, tracks: (1.72, 1.72), wheelbase: 2.94, steering: 1.0, wheels_damping: 3.0, max_velocity: 50.0, radii: (0.36, 0.36), body_mass: 1847.0, com: [1.27, 0.0, 0.0], sound: false },
        Row { model: Model::MercedesBenzSprinter, drive: T, engine: C, time0to100: 14.0, torque: 250.0, power: 50_000.0, rpm: (800.0, 4000.0), gears: DEF_GEARS, brake: 3500.0, tracks: (1.7, 1.7), wheelbase: 4.325, steering: 1.0, wheels_damping: 5.0, max_velocity: 29.18, radii: (0.4, 0.4), body_mass: 4500.0, com: [1.5, 0.0, 0.0], sound: true },
        Row { model: Model::GreenPowerEVStar, drive: T, engine: E, time0to100: 24.0, torque: 1200.0, power: 150_000.0, rpm: (1200.0, 4000.0), gears: &[-2.0, 2.0], brake: 3500.0, tracks: (1.7, 1.5), wheelbase: 4.325, steering: 1.0, wheels_damping: 5.0, max_velocity: 40.0, radii: (0.4445, 0.4445), body_mass: 6500.0, com: [1.5, 0.0, 0.0], sound: true },
        Row { model: Model::Bus, drive: T, engine: C, time0to100: 25.0, torque: 250.0, power: 50_000.0, rpm: (700.0, 2250.0), gears: &[-14.0, 16.0, 11.0, 7.0, 4.5, 3.0, 1.9, 1.2], brake: 3500.0, tracks: (2.5, 2.5), wheelbase: 4.5, steering: 0.4, wheels_damping: 20.0, max_velocity: 50.0, radii: (0.56, 0.56), body_mass: 8000.0, com: [2.25, 0.0, 0.1], sound: true },
        Row { model: Model::Truck, drive: X4, engine: C, time0to100: 25.0, torque: 250.0, power: 50_000.0, rpm: (700.0, 2250.0), gears: &[-14.77, 16.0, 13.0, 11.0, 9.0, 7.0, 6.0, 4.5, 3.7, 3.0, 2.4, 1.9, 1.5, 1.2, 1.0], brake: 5000.0, tracks: (2.2, 2.2), wheelbase: 5.25, steering: 0.4, wheels_damping: 30.0, max_velocity: 50.0, radii: (0.5, 0.5), body_mass: 8000.0, com: [4.5, 0.0, 0.1], sound: true },
        Row { model: Model::Tractor, drive: X4, engine: C, time0to100: 20.0, torque: 250.0, power: 50_000.0, rpm: (1000.0, 4500.0), gears: DEF_GEARS, brake: 700.0, tracks: (1.4, 1.4), wheelbase: 1.76, steering: 0.94, wheels_damping: 5.0, max_velocity: 50.0, radii: (0.38, 0.6), body_mass: 1000.0, com: [0.945_069_02, 0.0, 0.460_817_86], sound: true },
    ]
}

#[test]
fn every_model_validates_without_warnings() {
    for model in Model::ALL {
        let (p, report) = model.params::<f64>().validated();
        assert!(report.is_empty(), "{model}: {:?}", report.as_slice());
        assert_eq!(p, model.params(), "{model}: validation changed nothing");
        assert!(p.geometry().is_ok() && p.engine().is_ok() && p.gearbox().is_ok());
        let (_, report) = Driver::new(model.params::<f32>(), 16);
        assert!(report.is_empty(), "{model} in f32: {:?}", report.as_slice());
        assert!(is_physical_inertia(&p.body_inertia()), "{model}");
    }
}

#[test]
fn models_match_the_spec_tables() {
    let rows = table();
    assert_eq!(rows.len(), Model::ALL.len() - 1);
    for r in rows {
        let p = r.model.params::<f64>();
        let m = r.model;
        assert_eq!(p.drive_type, r.drive, "{m}");
        assert_eq!(p.engine.engine_type, r.engine, "{m}");
        assert_eq!(p.time_0_to_100, r.time0to100, "{m}");
        assert_eq!(
            (p.engine.max_torque, p.engine.max_power),
            (r.torque, r.power),
            "{m}"
        );
        assert_eq!((p.engine.min_rpm, p.engine.max_rpm), r.rpm, "{m}");
        assert_eq!(p.gear_ratios.as_slice(), r.gears, "{m}");
        assert_eq!(p.brake_coefficient, r.brake, "{m}");
        assert_eq!((p.track_front, p.track_rear), r.tracks, "{m}");
        assert_eq!(p.wheelbase, r.wheelbase, "{m}");
        assert_eq!(
            (p.min_steering_angle, p.max_steering_angle),
            (-r.steering, r.steering)
        );
        assert_eq!(p.wheels_damping_constant, r.wheels_damping, "{m}");
        assert_eq!(p.max_velocity, r.max_velocity, "{m}");
        assert_eq!((p.radius_front(), p.radius_rear()), r.radii, "{m}");
        assert_eq!(p.body.mass, r.body_mass, "{m}");
        assert_eq!(p.body.center_of_mass, r.com, "{m}");
        assert_eq!(!p.engine_sound.is_none(), r.sound, "{m}");
        assert_eq!(Model::from_name(m.webots_name()), Some(m));
    }
}

#[test]
fn derived_wheel_motor_values() {
    // Spec §5 "derived acc / vmax": (1000/36)/time0To100/r and maxVelocity/r. The C-Zero's use
    // its rear tyre's r = 0.28675 m (the spec's 5.574 and 175.59 are for Webots' front
    // tyre in the rear-right slot, a bug fixed here).
    for (model, acc, vmax) in [
        (Model::BmwX5, 10.61, 133.69),
        (Model::CitroenCZero, 5.5355, 174.37),
        (Model::ToyotaPrius, 8.189, 157.73),
        (Model::LincolnMKZ, 15.61, 139.66),
        (Model::RangeRoverSportSVR, 16.51, 139.66),
        (Model::TeslaModel3, 19.29, 138.89),
    ] {
        let p = model.params::<f64>();
        let wheel = if p.drive_type.front_driven() {
            Wheel::FrontLeft
        } else {
            Wheel::RearLeft
        };
        let m = p.wheel_motor(wheel);
        assert!(
            (m.acceleration - acc).abs() < 0.006,
            "{model}: {}",
            m.acceleration
        );
        assert!(
            (m.max_velocity - vmax).abs() < 0.006,
            "{model}: {}",
            m.max_velocity
        );
    }
    // The Tractor's axles differ: front 3.655, rear 2.315 rad/s².
    let t = Model::Tractor.params::<f64>().wheel_motors();
    assert!((t[Wheel::FrontRight].unwrap().acceleration - 3.655).abs() < 1e-3);
    assert!((t[Wheel::RearRight].unwrap().acceleration - 2.315).abs() < 1e-3);
    // Only driven wheels have motors.
    let bmw = Model::BmwX5.params::<f64>().wheel_motors();
    assert!(bmw[Wheel::FrontRight].is_some() && bmw[Wheel::RearLeft].is_none());
}

#[test]
fn engines_curves_and_inertias() {
    let bmw = Model::BmwX5.params::<f64>();
    assert_eq!(
        bmw.engine.function_coefficients,
        [34.11, 0.136, -0.000_014_61]
    );
    assert_eq!(
        bmw.body.inertia,
        Some([1125.07, 4473.54, 4346.1, 0.0, 846.89, 0.0])
    );
    assert_eq!(bmw.wipers.map(|w| (w.min, w.max)), Some((0.0, 1.6)));
    assert_eq!(
        bmw.wheels[Wheel::RearLeft].physics,
        WheelPhysics::Mass(30.0)
    );

    let prius = Model::ToyotaPrius.params::<f64>();
    assert_eq!(
        prius.engine.function_coefficients,
        [65.0, 0.0225, -0.000_002_5]
    );
    assert_eq!(
        (
            prius.engine.hybrid_power_split_ratio,
            prius.engine.hybrid_power_split_rpm
        ),
        (0.2778, 3000.0)
    );
    assert_eq!(prius.body.inertia.unwrap()[3], -300.0);
    assert_eq!(prius.wipers, None);

    // C-Zero, read from a Y-up file: inertia [2645 2534 200] (x left, y up, z forward)
    // becomes [200, 2645, 2534] in x forward, y left, z up.
    let czero = Model::CitroenCZero.params::<f64>();
    assert_eq!(
        czero.body.inertia,
        Some([200.0, 2645.0, 2534.0, 0.0, 0.0, 0.0])
    );
    assert_eq!(
        (
            czero.suspension_front_spring_constant,
            czero.suspension_rear_damping_constant
        ),
        (30_000.0, 5000.0)
    );
    // Both rear slots hold the rear wheel (Webots' PROTO: a front wheel in the rear-right one).
    for rear in [Wheel::RearLeft, Wheel::RearRight] {
        assert_eq!(czero.wheels[rear].tire_radius, 0.28675);
        assert_eq!(czero.wheels[rear].physics, WheelPhysics::Mass(6.0));
    }

    let tesla = Model::TeslaModel3.params::<f64>();
    assert_eq!(tesla.body.inertia.unwrap()[4], -3204.91);
    let tractor = Model::Tractor.params::<f64>();
    assert_eq!(tractor.body.inertia.unwrap()[4], -792.289_08);
    assert_eq!(tractor.rotation, [0.0, 1.0, 0.0, 0.13]);
    assert_eq!(tractor.translation, [0.0, 0.0, 0.6]);
    for m in [Model::Bus, Model::Truck] {
        assert_eq!(
            m.params::<f64>().engine.function_coefficients,
            [-600.0, 5.45, -0.0023]
        );
    }
    let sprinter = Model::MercedesBenzSprinter.params::<f64>();
    assert_eq!(sprinter.engine.function_coefficients, [600.0, 0.2, 0.0]);
    assert_eq!(sprinter.max_steering_torque, 13_000.0);
    assert_eq!(
        Model::GreenPowerEVStar.params::<f64>().max_steering_torque,
        15_000.0
    );
}

#[test]
fn derived_inertia_for_models_without_one() {
    // LincolnMKZ: 1950 kg box of l = 1.6·2.94 = 4.704, w = 1.64, h = 1.23:
    // Ixx = 1950/12·(1.64² + 1.23²) = 683.4 kg·m², Izz = 1950/12·(4.704² + 1.64²) = 4032.7.
    let p = Model::LincolnMKZ.params::<f64>();
    assert_eq!(p.body.inertia, None);
    let i = p.body_inertia();
    assert!((i[0] - 1950.0 / 12.0 * (1.64_f64.powi(2) + 1.23_f64.powi(2))).abs() < 1e-9);
    assert!((i[2] - 1950.0 / 12.0 * (4.704_f64.powi(2) + 1.64_f64.powi(2))).abs() < 1e-9);
    // Webots' default Physics {}: density 1000 over the 0.358 × 0.22 m cylinder (88.58 kg).
    assert_eq!(
        p.wheels[Wheel::FrontLeft].physics,
        WheelPhysics::Density(1000.0)
    );
}

#[test]
fn sensor_slots_and_plain_car() {
    let bmw = Model::BmwX5.params::<f64>();
    let slots = bmw.sensor_slots.unwrap();
    assert_eq!(
        slots.front.translation.vector,
        Vector3::new(3.85, 0.0, 0.45)
    );
    // Y-up (0, 1.35, 1.075) → (1.075, 0, 1.35).
    let czero = Model::CitroenCZero.params::<f64>().sensor_slots.unwrap();
    assert_eq!(czero.top.translation.vector, Vector3::new(1.075, 0.0, 1.35));
    assert_eq!(Model::Tractor.params::<f64>().sensor_slots, None);

    let car = Model::Car.params::<f64>();
    assert_eq!(car, CarParams::default());
    assert_eq!(Model::from_name("Car"), Some(Model::Car));
    assert_eq!(
        (car.wheelbase, car.track_front, car.radius_front()),
        (4.0, 1.7, 0.4)
    );
    assert_eq!(car.gear_ratios.as_slice(), DEF_GEARS);
    assert_eq!(car.brake_coefficient, 700.0);
    assert_eq!(car.engine_sound.as_str(), "sounds/engine.wav");
    assert_eq!(Model::from_name("Sedan"), None);
    assert_eq!(Model::ALL.len(), 12);
}

#[test]
fn wheel_masses_of_every_model() {
    // Spec §5 "wheel mass" rows (kg), per slot FR, FL, RR, RL; `None` = Webots' default
    // `Physics {}` (density 1000 kg/m³ over the bounding cylinder).
    let mass = |m: f64| WheelPhysics::Mass(m);
    let density = WheelPhysics::Density(1000.0);
    for (model, expected) in [
        (Model::BmwX5, [mass(30.0); 4]),
        // The rear-right slot holds a front wheel with the rear wheels' Physics node.
        (
            Model::CitroenCZero,
            [mass(5.0), mass(5.0), mass(6.0), mass(6.0)],
        ),
        (Model::ToyotaPrius, [mass(8.0); 4]),
        (Model::LincolnMKZ, [density; 4]),
        (Model::RangeRoverSportSVR, [density; 4]),
        (Model::TeslaModel3, [mass(10.4); 4]),
        (Model::MercedesBenzSprinter, [density; 4]),
        (
            Model::GreenPowerEVStar,
            [mass(10.0), mass(10.0), mass(20.0), mass(20.0)],
        ),
        (Model::Bus, [mass(80.0); 4]),
        (Model::Truck, [mass(100.0); 4]),
        (
            Model::Tractor,
            [mass(30.0), mass(30.0), mass(60.0), mass(60.0)],
        ),
    ] {
        let p = model.params::<f64>();
        for (w, e) in Wheel::ALL.into_iter().zip(expected) {
            assert_eq!(p.wheels[w].physics, e, "{model} {w:?}");
        }
    }
    // Wheel geometry of the per-axle wheels: EVStar tyres 0.4445 m, Tractor front 0.38 m ×
    // 0.19 m and rear 0.6 m × 0.37 m.
    let ev = Model::GreenPowerEVStar.params::<f64>();
    assert_eq!((ev.radius_front(), ev.radius_rear()), (0.4445, 0.4445));
    let tractor = Model::Tractor.params::<f64>();
    let (front, rear) = (
        tractor.wheels[Wheel::FrontLeft],
        tractor.wheels[Wheel::RearLeft],
    );
    assert_eq!((front.tire_radius, front.thickness), (0.38, 0.19));
    assert_eq!((rear.tire_radius, rear.thickness), (0.6, 0.37));
}

#[test]
fn suspensions_steering_torques_and_translations_of_every_model() {
    // (front spring N/m, front damping N·s/m, rear spring, rear damping, maxSteeringTorque
    // N·m, translation z m) from spec §5; the Car defaults are 100000 / 4000 / 10000 / 0.4.
    #[rustfmt::skip]
    let rows = [
        (Model::Car,                  100_000.0,  4000.0, 100_000.0,  4000.0, 10_000.0, 0.4),
        (Model::BmwX5,                100_000.0,  4000.0, 100_000.0,  4000.0, 10_000.0, 0.4),
        (Model::CitroenCZero,          30_000.0,  5000.0,  30_000.0,  5000.0, 10_000.0, 0.4),
        (Model::ToyotaPrius,          100_000.0,  4000.0, 100_000.0,  4000.0, 10_000.0, 0.4),
        (Model::LincolnMKZ,           100_000.0,  4000.0, 100_000.0,  4000.0, 10_000.0, 0.4),
        (Model::RangeRoverSportSVR,   100_000.0,  4000.0, 100_000.0,  4000.0, 10_000.0, 0.4),
        (Model::TeslaModel3,           60_000.0, 10_000.0,  60_000.0, 10_000.0, 10_000.0, 0.4),
        (Model::MercedesBenzSprinter, 200_000.0,  5000.0, 600_000.0,  5000.0, 13_000.0, 0.4445),
        // Y-up translation (0, 0.4445, 0).
        (Model::GreenPowerEVStar,     200_000.0,  6000.0, 750_000.0,  6000.0, 15_000.0, 0.4445),
        (Model::Bus,                    1.0e6,   10_000.0,   1.0e6,  10_000.0, 10_000.0, 0.55),
        (Model::Truck,                  1.0e6,   10_000.0,   1.0e6,  10_000.0, 10_000.0, 0.5),
        (Model::Tractor,              200_000.0,  4000.0,  30_000.0,  2000.0, 10_000.0, 0.6),
    ];
    assert_eq!(rows.len(), Model::ALL.len());
    for (model, fs, fd, rs, rd, torque, z) in rows {
        let p = model.params::<f64>();
        assert_eq!(
            (
                p.suspension_front_spring_constant,
                p.suspension_front_damping_constant,
                p.suspension_rear_spring_constant,
                p.suspension_rear_damping_constant,
            ),
            (fs, fd, rs, rd),
            "{model}"
        );
        assert_eq!(p.max_steering_torque, torque, "{model}");
        assert_eq!(p.translation, [0.0, 0.0, z], "{model}");
    }
}

#[test]
fn sensor_slots_of_every_model() {
    // Spec §4.5; the Y-up figures (x left, y up, z forward) read as FLU = (z, x, y).
    /// Model, front, top and rear slot positions (m).
    type Row = (Model, [f64; 3], [f64; 3], [f64; 3]);
    #[rustfmt::skip]
    let rows: [Row; 9] = [
        (Model::BmwX5, [3.85, 0.0, 0.45], [1.0, 0.0, 1.45], [-1.0, 0.0, 0.3]),
        (Model::ToyotaPrius, [3.635, 0.0, 0.4], [1.1, 0.0, 1.3], [-0.85, 0.0, 0.3]),
        (Model::TeslaModel3, [3.79, 0.0, 0.142], [1.11, 0.0, 1.16], [-1.05, 0.0, 0.2]),
        (Model::MercedesBenzSprinter, [5.31, 0.0, 0.47], [2.99, 0.0, 2.3], [-1.62, 0.0, 0.19]),
        (Model::Bus, [11.5, 0.0, 0.2], [2.5, 0.0, 5.3], [-6.2, 0.0, 1.0]),
        (Model::Truck, [6.75, 0.0, 1.1], [4.3, 0.0, 4.15], [-7.3, 0.0, 2.7]),
        // Y-up (0, 0.05, 3.075) / (0, 1.35, 1.075) / (0, 0.3, −0.425).
        (Model::CitroenCZero, [3.075, 0.0, 0.05], [1.075, 0.0, 1.35], [-0.425, 0.0, 0.3]),
        // Y-up (0, 0.142, 3.944) / (0, 1.16, 1.11) / (0, 0.33, −1.06).
        (Model::LincolnMKZ, [3.944, 0.0, 0.142], [1.11, 0.0, 1.16], [-1.06, 0.0, 0.33]),
        // Y-up (0, 0.5, 3.5) / (0, 1.3, 1.4) / (0, 0.33, −1.06).
        (Model::RangeRoverSportSVR, [3.5, 0.0, 0.5], [1.4, 0.0, 1.3], [-1.06, 0.0, 0.33]),
    ];
    for (model, front, top, rear) in rows {
        let s = model.params::<f64>().sensor_slots.unwrap();
        let at = |t: Translation3<f64>| -> [f64; 3] { t.vector.into() };
        assert_eq!(at(s.front.translation), front, "{model}");
        assert_eq!(at(s.top.translation), top, "{model}");
        assert_eq!(at(s.rear.translation), rear, "{model}");
        assert_eq!(at(s.centre.translation), [0.0; 3], "{model}");
        // The front and top slots face forward, the rear slot backward: +x maps to −x.
        assert_eq!(s.front.rotation.angle(), 0.0, "{model}");
        assert_eq!(s.top.rotation.angle(), 0.0, "{model}");
        let back = s.rear.rotation * Vector3::x();
        assert!(
            (back.x + 1.0).abs() < 1e-12 && back.y.abs() < 1e-12 && back.z.abs() < 1e-12,
            "{model}: {back:?}"
        );
    }
    for model in [Model::Car, Model::GreenPowerEVStar, Model::Tractor] {
        assert_eq!(model.params::<f64>().sensor_slots, None, "{model}");
    }
}

#[test]
fn models_are_the_plain_car_then_the_shipped_vehicles() {
    use proto_geom::ShippedVehicle;
    assert_eq!(Model::ALL[0], Model::Car);
    assert_eq!(Model::Car.shipped(), None);
    assert_eq!(Model::ALL.len(), 1 + ShippedVehicle::ALL.len());
    for (model, vehicle) in Model::ALL[1..].iter().zip(ShippedVehicle::ALL) {
        assert_eq!(model.shipped(), Some(vehicle));
        assert_eq!(Model::from(vehicle), *model);
        assert_eq!(model.webots_name(), vehicle.proto_name());
        // Debug prints the constant's name, as it did when `Model` was an enum.
        assert_eq!(format!("{model:?}"), vehicle.proto_name());
        assert_eq!(model.to_string(), vehicle.proto_name());
    }
    // The constants are patterns.
    let commercial = |m: Model| matches!(m, Model::Bus | Model::Truck);
    assert!(commercial(Model::Truck) && !commercial(Model::Tractor));
}
