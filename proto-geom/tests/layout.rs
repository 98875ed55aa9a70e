//! Wheel placement, joint axes and sensor slots (spec §4.3, §4.5).
// Test helpers outside #[test] functions unwrap too: a failed lookup is a failed test.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::f64::consts::PI;

use ackermann::{PerWheel, Wheel};

use proto_geom::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use proto_geom::{
    AckermannField, SensorSlot, SensorSlots, ShippedVehicle, VehicleDimensions, VehicleLayout,
    WheelParams, WheelSide,
};

fn close(a: Vector3<f64>, b: Vector3<f64>) -> bool {
    (a - b).norm() < 1e-12
}

#[test]
fn bmw_x5_wheel_centres() {
    let layout = ShippedVehicle::BmwX5.layout::<f64>();
    // (L, ∓Tf/2, 0) and (0, ∓Tr/2, 0) with L = 2.995 m, Tf = Tr = 1.628 m.
    let expected = PerWheel::new(
        Point3::new(2.995, -0.814, 0.0),
        Point3::new(2.995, 0.814, 0.0),
        Point3::new(0.0, -0.814, 0.0),
        Point3::new(0.0, 0.814, 0.0),
    );
    for w in Wheel::ALL {
        assert_eq!(layout.frame(w).centre(), expected[w], "{w:?}");
        assert_eq!(layout.frame(w).wheel, w);
    }
    assert_eq!(layout.engine_speaker(), Point3::new(2.995, 0.0, 0.0));
}

#[test]
fn joint_axes_and_sign_conventions() {
    for v in ShippedVehicle::ALL {
        let layout = v.layout::<f64>();
        for w in Wheel::ALL {
            let f = layout.frame(w);
            // Spin axis: the lateral axis +y on every wheel, and it is what Webots' local axis
            // (±1, 0, 0) becomes through the wheel rotation.
            assert_eq!(*f.spin_axis, Vector3::y());
            assert!(
                close(f.pose * *f.webots_spin_axis(), Vector3::y()),
                "{v:?} {w:?}"
            );
            assert_eq!(*f.suspension_axis, Vector3::z());
            // Steering axis on the front wheels only, world −z, as Webots' local (0, 0, −1).
            assert_eq!(f.steering_axis.is_some(), w.is_front(), "{v:?} {w:?}");
            if let (Some(axis), Some(local)) = (f.steering_axis, f.webots_steering_axis()) {
                assert_eq!(*axis, -Vector3::z());
                assert!(close(f.pose * *local, *axis));
            }
            // The rim face (local −x) points away from the car.
            let outward = f.pose * -Vector3::x();
            assert!(close(
                outward,
                if w.is_right() {
                    -Vector3::y()
                } else {
                    Vector3::y()
                }
            ));
            // wheelSide TRUE on the left: the tyre is turned by π about the local z axis.
            assert_eq!(f.side, WheelSide::of(w));
            let tyre_axle = f.tyre_pose * Vector3::x();
            let axle = f.pose * Vector3::x();
            let expected = if w.is_right() { axle } else { -axle };
            assert!(close(tyre_axle, expected), "{v:?} {w:?}");
            // …and that is the same as `pose` followed by π about the local z axis.
            let turned = f.pose * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), PI);
            let d = f.tyre_pose.inverse() * if w.is_right() { f.pose } else { turned };
            assert!(d.translation.vector.norm() < 1e-12 && d.rotation.angle() < 1e-12);
            assert_eq!(f.tyre_pose.translation, f.pose.translation);
        }
    }
}

#[test]
fn positive_spin_drives_forward_and_positive_steering_turns_right() {
    let f = *ShippedVehicle::ToyotaPrius
        .layout::<f64>()
        .frame(Wheel::FrontLeft);
    // Contact point below the centre: velocity of the ground contact = ω × (−r·z); the car
    // moves opposite to it, i.e. along ω × (r·z) = y × z = +x for ω along +y.
    let forward = f.spin_axis.cross(&Vector3::z());
    assert_eq!(forward, Vector3::x());
    // Steering by +0.3 rad about −z turns the rolling direction towards −y (right).
    let steer = UnitQuaternion::from_axis_angle(&f.steering_axis.unwrap(), 0.3);
    let heading = steer * forward;
    assert!((heading.x - 0.3_f64.cos()).abs() < 1e-12 && (heading.y + 0.3_f64.sin()).abs() < 1e-12);
}

#[test]
fn dimension_validation() {
    let (layout, warnings) = VehicleLayout::new(
        VehicleDimensions {
            wheelbase: -2.0,
            track_front: f64::NAN,
            track_rear: 1.5,
        },
        PerWheel::from_fn(|w| WheelParams::default().in_slot(w)),
    );
    let d = layout.dimensions();
    assert_eq!((d.wheelbase, d.track_front, d.track_rear), (4.0, 1.7, 1.5));
    let fields: Vec<_> = warnings.dimensions.iter().map(|w| w.field).collect();
    assert_eq!(
        fields,
        [AckermannField::Wheelbase, AckermannField::TrackFront]
    );
    assert_eq!(
        warnings.dimensions[0].to_string(),
        "'wheelbase' must be strictly positive. Value reset to 4."
    );
    assert!(warnings.wheels.iter().all(|w| w.is_empty()));
    // A bad wheel is reported for its slot.
    let mut wheels = PerWheel::splat(WheelParams::<f64>::default());
    wheels[Wheel::RearLeft].subdivision = 3;
    let (_, warnings) = VehicleLayout::new(VehicleDimensions::default(), wheels);
    assert_eq!(warnings.wheels[Wheel::RearLeft].len(), 1);
    assert!(warnings.wheels[Wheel::FrontRight].is_empty() && !warnings.is_empty());
}

#[test]
fn geometry_for_the_car_library() {
    let g = ShippedVehicle::BmwX5.layout::<f64>().geometry().unwrap();
    assert_eq!(
        (g.wheelbase(), g.radius_front(), g.radius_rear()),
        (2.995, 0.374, 0.374)
    );
    // The C-Zero's rear wheels (175/55 R15) are larger than its front ones (145/65 R15), in both
    // rear slots (Webots' PROTO has a front wheel in the rear-right one: a bug, fixed).
    let czero = ShippedVehicle::CitroenCZero.layout::<f64>();
    let g = czero.geometry().unwrap();
    assert_eq!((g.radius_front(), g.radius_rear()), (0.28475, 0.28675));
    for rear in [Wheel::RearLeft, Wheel::RearRight] {
        assert_eq!(czero.wheel(rear).params().tire_radius, 0.28675);
        assert_eq!(czero.wheel(rear).params().thickness, 0.175);
        assert_eq!(czero.wheel(rear).mass(), Some(6.0));
    }
    assert_eq!(czero.dimensions().track_rear, 1.27);
    assert_eq!(czero.wheel(Wheel::FrontRight).mass(), Some(5.0));
}

#[test]
fn shipped_wheels_are_named_and_sided_like_the_car_protos() {
    let p = ShippedVehicle::Bus.wheel_params::<f64>();
    assert_eq!(p[Wheel::FrontLeft].name, "front left wheel");
    assert_eq!(p[Wheel::RearRight].side, WheelSide::Right);
    assert_eq!(p[Wheel::RearLeft].side, WheelSide::Left);
    assert_eq!(p[Wheel::RearLeft].tire_radius, 0.56);
    for v in ShippedVehicle::ALL {
        assert_eq!(ShippedVehicle::from_proto_name(v.proto_name()), Some(v));
    }
}

#[test]
fn sensor_slots() {
    let s = SensorSlots::<f64>::for_model("BmwX5").unwrap();
    let at = |t: Translation3<f64>| t.vector;
    assert_eq!(at(s.front.translation), Vector3::new(3.85, 0.0, 0.45));
    assert_eq!(
        at(s.get(SensorSlot::Top).translation),
        Vector3::new(1.0, 0.0, 1.45)
    );
    assert_eq!(at(s.rear.translation), Vector3::new(-1.0, 0.0, 0.3));
    // The front and top slots face forward, the rear slot backward (π about z).
    assert_eq!(s.front.rotation.angle(), 0.0);
    assert_eq!(s.top.rotation.angle(), 0.0);
    assert!(close(s.rear * Vector3::x(), -Vector3::x()));
    assert!((s.rear.rotation.angle() - PI).abs() < 1e-15);
    assert_eq!(s.centre, Isometry3::identity());
    // Y-up figures converted with FLU = (z, x, y): C-Zero front (0, 0.05, 3.075) → (3.075, 0, 0.05).
    let c = SensorSlots::<f64>::for_model("CitroenCZero").unwrap();
    assert_eq!(at(c.front.translation), Vector3::new(3.075, 0.0, 0.05));
    let l = SensorSlots::<f64>::for_model("LincolnMKZ").unwrap();
    assert_eq!(at(l.top.translation), Vector3::new(1.11, 0.0, 1.16));
    assert!(SensorSlots::<f64>::for_model("Tractor").is_none());
    assert!(SensorSlots::<f64>::for_model("Batmobile").is_none());
    assert_eq!(SensorSlot::Centre.webots_name(), "sensorsSlotCenter");
}

#[test]
fn f32_layout_is_the_same() {
    let layout = ShippedVehicle::Truck.layout::<f32>();
    assert_eq!(
        layout.frame(Wheel::FrontRight).centre(),
        Point3::new(5.25, -1.1, 0.0)
    );
}
