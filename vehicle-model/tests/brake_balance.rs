//! The brake balance between the axles, an extension: Webots brakes every wheel alike
//! (`BrakeBalance::Equal`, the default), `Proportioned` shares the same total toward the front.
//! The golden shares are worked out with python3 from the formula of
//! `proportioned_front_share`.

mod common;

use common::golden::{driver, sensors_at};
use vehicle_model::{
    BrakeBalance, BrakeBalanceError, CarParams, Driver, Model, PerWheel, Wheel,
    proportioned_front_share,
};

#[test]
fn equal_is_the_default_and_webots_torque_on_every_wheel() {
    let mut d = driver(Model::BmwX5);
    assert_eq!(d.brake_balance(), BrakeBalance::Equal);
    assert_eq!(d.brake_front_share(), 0.5);
    d.set_brake_intensity(0.7);
    // 0.7 · 1800 N·m, bit for bit as Webots (the axle factor is exactly 1).
    assert_eq!(
        d.step(&sensors_at(0.0)).brake_torque,
        PerWheel::splat(0.7 * 1800.0)
    );
    let mut f = Driver::<f32>::new(Model::BmwX5.params(), 10).0;
    f.set_brake_intensity(0.7);
    let c = *f.step(&vehicle_model::Sensors::unsampled(0.0));
    assert_eq!(c.brake_torque, PerWheel::splat(0.7_f32 * 1800.0));
}

#[test]
fn proportioned_share_of_the_bmw_x5() {
    // Body 2000 kg at x 1.2975, z 0.1 (over the rear axle centre), four 30 kg wheels, r 0.374,
    // L 2.995: M = 2120 kg, l_r = (2000·1.2975 + 60·2.995)/2120 = 1.308821 m,
    // h = (2000·0.474 + 120·0.374)/2120 = 0.468340 m; the full brake torque 4·1800 N·m
    // decelerates at z = 7200/0.374/(2120·9.81) = 0.925670 g;
    // φ = (l_r + z·h)/L = 0.581752.
    let share = proportioned_front_share(&Model::BmwX5.params::<f64>());
    assert!((share - 0.581_752_430_9).abs() < 1e-9, "{share}");
    let mut d = driver(Model::BmwX5);
    d.set_brake_balance(BrakeBalance::Proportioned).unwrap();
    assert_eq!(d.brake_front_share(), share);
    d.set_brake_intensity(1.0);
    let c = *d.step(&sensors_at(0.0));
    for w in Wheel::ALL {
        let expected = if w.is_front() {
            2.0 * share * 1800.0
        } else {
            2.0 * (1.0 - share) * 1800.0
        };
        assert!((c.brake_torque[w] - expected).abs() < 1e-9, "{w:?}");
    }
    // The total is Webots' 4·brakeCoefficient.
    let total: f64 = Wheel::ALL.iter().map(|&w| c.brake_torque[w]).sum();
    assert!((total - 4.0 * 1800.0).abs() < 1e-9, "{total}");
}

#[test]
fn proportioned_share_with_unequal_tyres_solves_for_the_deceleration() {
    // The Tractor: r_f 0.38 m, r_r 0.6 m, so the deceleration of the full brake torque
    // depends on the share, z = k·(φ/r_f + (1 − φ)/r_r) with k = 4·brakeCoefficient/(M·g):
    // the share must be the load share (l_r + z·h)/L at its own deceleration.
    let p = Model::Tractor.params::<f64>();
    let share = proportioned_front_share(&p);
    let (m, x, h) = mass_and_centre(&p);
    let k = 4.0 * p.brake_coefficient / (m * 9.81);
    let z = k * (share / p.radius_front() + (1.0 - share) / p.radius_rear());
    assert!(z < 1.0, "{z}");
    assert!(((x + z * h) / p.wheelbase - share).abs() < 1e-12, "{share}");
}

#[test]
fn brakes_beyond_a_dry_road_are_shared_for_1_g() {
    // 20 000 N·m per wheel would stop a BmwX5 at 10 g: the share is the load share at 1 g,
    // (1.308821 + 0.468340)/2.995 = 0.593376, so both axles still get a brake that locks them.
    let mut p = Model::BmwX5.params::<f64>();
    p.brake_coefficient = 20_000.0;
    let share = proportioned_front_share(&p);
    assert!((share - 0.593_375_752).abs() < 1e-9, "{share}");
}

#[test]
fn a_share_that_is_not_its_own_load_share_falls_back_to_1_g() {
    // The Tractor (r_f 0.38 m, r_r 0.6 m) with its centre of mass 20 m up: L − h·b ≤ 0, so no
    // share is the load share at its own deceleration; the 1 g share (l_r + h)/L is beyond 1
    // (it would tip over first), so all the torque goes to the front.
    let mut p = Model::Tractor.params::<f64>();
    p.body.center_of_mass[2] = 20.0;
    let (_, x, h) = mass_and_centre(&p);
    let k = 4.0 * p.brake_coefficient / (mass_and_centre(&p).0 * 9.81);
    let b = k * (1.0 / p.radius_front() - 1.0 / p.radius_rear());
    assert!(p.wheelbase - h * b <= 0.0, "{}", p.wheelbase - h * b);
    assert!((x + h) / p.wheelbase > 1.0);
    assert_eq!(proportioned_front_share(&p), 1.0);
}

#[test]
fn every_shipped_model_brakes_harder_in_front_than_its_static_load_share() {
    for model in Model::ALL {
        let p = model.params::<f64>();
        let (_, x, _) = mass_and_centre(&p);
        let share = proportioned_front_share(&p);
        let f32_share = proportioned_front_share(&model.params::<f32>());
        println!(
            "{model:?}: static {:.4}, proportioned {share:.4}",
            x / p.wheelbase
        );
        assert!(share > x / p.wheelbase && share < 1.0, "{model:?}: {share}");
        assert!(
            (f64::from(f32_share) - share).abs() < 1e-5,
            "{model:?}: {f32_share}"
        );
    }
}

#[test]
fn a_front_share_outside_zero_to_one_is_refused_and_changes_nothing() {
    let mut d = driver(Model::BmwX5);
    d.set_brake_balance(BrakeBalance::FrontShare(0.7)).unwrap();
    for bad in [1.5, -0.1, f64::NAN, f64::INFINITY] {
        let e = d
            .set_brake_balance(BrakeBalance::FrontShare(bad))
            .unwrap_err();
        assert!(e.share == bad || (bad.is_nan() && e.share.is_nan()));
        assert!(e.to_string().contains("front share"), "{e}");
        assert_eq!(d.brake_front_share(), 0.7);
        assert_eq!(d.brake_balance(), BrakeBalance::FrontShare(0.7));
    }
    assert_eq!(
        BrakeBalance::<f64>::FrontShare(2.0).front_share(&Model::BmwX5.params()),
        Err(BrakeBalanceError { share: 2.0 })
    );
    // The ends are allowed: all on one axle.
    d.set_brake_balance(BrakeBalance::FrontShare(1.0)).unwrap();
    d.set_brake_intensity(0.5);
    let c = *d.step(&sensors_at(0.0));
    assert_eq!(c.brake_torque[Wheel::FrontLeft], 1800.0);
    assert_eq!(c.brake_torque[Wheel::RearRight], 0.0);
}

/// The whole car's mass (kg), its centre of mass' distance ahead of the rear axle (m) and its
/// height over the ground (m), wheels included at their axles (the formula's inputs, written
/// out again).
fn mass_and_centre(p: &CarParams<f64>) -> (f64, f64, f64) {
    let b = &p.body;
    let (mut m, mut mx, mut mz) = (
        b.mass,
        b.mass * b.center_of_mass[0],
        b.mass * (b.center_of_mass[2] + p.radius_rear()),
    );
    for w in Wheel::ALL {
        let wheel = &p.wheels[w];
        let mass = match wheel.physics {
            vehicle_model::WheelPhysics::None => 0.0,
            vehicle_model::WheelPhysics::Mass(m) => m,
            vehicle_model::WheelPhysics::Density(d) => {
                d * std::f64::consts::PI * wheel.tire_radius.powi(2) * wheel.thickness
            }
        };
        let (x, r) = if w.is_front() {
            (p.wheelbase, p.radius_front())
        } else {
            (0.0, p.radius_rear())
        };
        m += mass;
        mx += mass * x;
        mz += mass * r;
    }
    (m, mx / m, mz / m)
}
