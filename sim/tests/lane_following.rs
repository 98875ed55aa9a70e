//! The built-in lane follower ([`sim::lane_following`]) on the shipped city loop and a
//! straight road: how close it keeps a car to its lane centre, and lane changes.
#![allow(clippy::unwrap_used, clippy::panic)]

use std::path::Path;

use sim::lane_following::{FollowLane, FollowStatus};
use sim::road::{RoadNetwork, lane_centre};
use sim::{CarBuilder, Mounting, Simulation, VehicleId, VehiclePlacement, World, WorldConfig};
use vehicle_model::Model;

/// The roads of the shipped world `name`.
fn shipped_roads(name: &str) -> RoadNetwork {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("worlds")
        .join(name);
    sim::world_file::load_file(&path).unwrap().config.roads
}

/// A simulation of `roads` with a `model` car on `mounting` on the centre of lane `lane` of
/// road 0 at station `s`, heading its lane's way.
fn car_in_lane(
    roads: RoadNetwork,
    model: Model,
    mounting: Mounting,
    lane: i32,
    s: f64,
) -> (Simulation, VehicleId) {
    let road = &roads.roads[0];
    let (t, _) = lane_centre(road, s, lane).unwrap();
    let p = road.surface_point(s, t);
    let heading = road.plan_at(s).heading + if lane > 0 { core::f64::consts::PI } else { 0.0 };
    let world = World::new(WorldConfig {
        roads,
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let placement = VehiclePlacement {
        x: p.x,
        y: p.y,
        yaw: heading,
        z: None,
    };
    let (id, _) = sim
        .add_car(
            CarBuilder::of_model(model)
                .mounting(mounting)
                .placement(placement),
        )
        .unwrap();
    (sim, id)
}

/// The car origin's (rear-axle centre's) lateral offset from the centre of lane `lane` of
/// road 0 (m), and its speed (m/s).
fn offset(sim: &Simulation, id: VehicleId, lane: i32) -> (f64, f64) {
    let s = sim.telemetry(id).unwrap();
    let p = sim::nalgebra::Point2::new(s.state.position.x, s.state.position.y);
    let at = sim
        .world()
        .config()
        .roads
        .track_lane(0, lane, &p, s.state.roll_pitch_yaw.yaw, 0.0)
        .unwrap();
    (at.lateral_offset, s.speed)
}

/// Drives a lap of the city loop (468 m of lane: two 100 m and two 50 m straights, four
/// quarter circles of 26.75 m radius) at a cruising speed of 50 km/h, slowed in the corners
/// to the follower's 3 m/s² of lateral acceleration (√(3 × 26.75) = 9.0 m/s), and returns
/// the largest lateral offset (m) once the car has reached 45 km/h, and the lowest speed
/// then (m/s).
fn city_lap(mounting: Mounting) -> (f64, f64) {
    let (mut sim, car) = car_in_lane(
        shipped_roads("city-loop.toml"),
        Model::ToyotaPrius,
        mounting,
        -1,
        20.0,
    );
    sim.follow_lane(car, FollowLane::default()).unwrap();
    sim.driver_mut(car).unwrap().set_cruising_speed(50.0);
    let (mut worst, mut slowest, mut cruising) = (0.0_f64, f64::INFINITY, false);
    // 45 s: about 8 s to reach 50 km/h, then a lap (468 m) in 34 s.
    for _ in 0..4500 {
        sim.step().unwrap();
        let (e, v) = offset(&sim, car, -1);
        cruising |= v > 45.0 / 3.6;
        if cruising {
            worst = worst.max(e.abs());
            slowest = slowest.min(v);
        }
        assert_eq!(
            sim.lane_follower(car).unwrap().unwrap().status(),
            FollowStatus::Following
        );
    }
    (worst, slowest)
}

#[test]
fn city_loop_lap_at_50_kmh_stays_within_0_3_m_cast() {
    let (worst, slowest) = city_lap(Mounting::Cast);
    eprintln!("cast: worst {worst} m, slowest {slowest} m/s");
    assert!(worst < 0.3, "{worst} m");
    // The corners' speed: 9.0 m/s for 3 m/s² on the lane's 26.75 m radius; the speed
    // control's ramp may undershoot it a little (5 %).
    assert!((8.5..9.2).contains(&slowest), "{slowest} m/s");
}

#[test]
fn city_loop_lap_at_50_kmh_stays_within_0_3_m_joints() {
    let (worst, _) = city_lap(Mounting::Joints);
    eprintln!("joints: worst {worst} m");
    assert!(worst < 0.3, "{worst} m");
}

#[test]
fn a_lane_change_ends_in_the_new_lane() {
    // The shipped highway's first 600 m are straight: three 3.75 m lanes right of the
    // reference line, centres at t = −1.875, −5.625, −9.375 m.
    let (mut sim, car) = car_in_lane(
        shipped_roads("highway.toml"),
        Model::BmwX5,
        Mounting::Cast,
        -2,
        50.0,
    );
    sim.follow_lane(car, FollowLane::default()).unwrap();
    sim.driver_mut(car).unwrap().set_cruising_speed(90.0);
    for _ in 0..500 {
        sim.step().unwrap();
    }
    assert!(offset(&sim, car, -2).0.abs() < 0.05);
    sim.follow_lane(
        car,
        FollowLane {
            lane: Some(-1),
            change_time: 4.0,
            ..FollowLane::default()
        },
    )
    .unwrap();
    assert_eq!(sim.lane_follower(car).unwrap().unwrap().lane(), Some(-1));
    // Half-way through the 4 s change the target is half-way across: the car is between
    // the two lanes' centres.
    for _ in 0..200 {
        sim.step().unwrap();
    }
    let mid = offset(&sim, car, -1).0;
    assert!(
        (-3.75..0.0).contains(&mid),
        "{mid} m from the new lane's centre"
    );
    // 4 s after the end of the change the car keeps the new lane's centre (5 cm: the
    // follower's settled error on a straight, well under the 0.3 m of the curves).
    for _ in 0..600 {
        sim.step().unwrap();
    }
    let (e, _) = offset(&sim, car, -1);
    assert!(e.abs() < 0.05, "{e} m");
}

#[test]
fn requests_out_of_range_and_across_the_centre_line_are_refused() {
    let (mut sim, car) = car_in_lane(
        shipped_roads("city-loop.toml"),
        Model::ToyotaPrius,
        Mounting::Cast,
        -1,
        20.0,
    );
    for bad in [
        FollowLane {
            change_time: 0.2,
            ..FollowLane::default()
        },
        FollowLane {
            lane: Some(0),
            ..FollowLane::default()
        },
        FollowLane {
            max_lateral_acceleration: f64::NAN,
            ..FollowLane::default()
        },
    ] {
        assert!(sim.follow_lane(car, bad).is_err(), "{bad:?}");
    }
    sim.follow_lane(car, FollowLane::default()).unwrap();
    sim.step().unwrap();
    let err = sim
        .follow_lane(
            car,
            FollowLane {
                lane: Some(1),
                ..FollowLane::default()
            },
        )
        .unwrap_err();
    assert!(err.to_string().contains("centre line"), "{err}");
}

#[test]
fn a_car_off_the_road_is_not_steered_and_says_so() {
    // The city loop moved 1 km east: the car at the origin is on no road.
    let mut roads = shipped_roads("city-loop.toml");
    for seg in &mut roads.roads[0].segments {
        seg.start.x += 1000.0;
    }
    let world = World::new(WorldConfig {
        roads,
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let (car, _) = sim
        .add_car(CarBuilder::of_model(Model::ToyotaPrius))
        .unwrap();
    sim.follow_lane(car, FollowLane::default()).unwrap();
    sim.step().unwrap();
    let follower = sim.lane_follower(car).unwrap().unwrap();
    assert_eq!(follower.status(), FollowStatus::OffRoad);
    assert_eq!(follower.lane(), None);
}

/// A world with a 200 m straight road (one lane each way) and a car whose programme step
/// at 0 s has the lines `step`.
fn follow_world(road: bool, step: &str) -> String {
    let road = if road {
        "[[road]]\nid = \"r\"\nnumberOfLanes = 2\nnumberOfForwardLanes = 1\nwidth = 7.0\n\
         [[road.segment]]\ntype = \"straight\"\nlength = 200\n"
    } else {
        ""
    };
    format!(
        "basicTimeStep = 10\n{road}\n[[vehicle]]\nmodel = \"BmwX5\"\ntranslation = [10, -1.75, 0]\n\
         [[vehicle.programme]]\nat = 0.0\ncruising_speed = 30\n{step}\n"
    )
}

fn world_error(text: &str) -> String {
    sim::world_file::parse_str("w.toml", text)
        .unwrap_err()
        .to_string()
}

#[test]
fn bad_follow_lane_steps_name_file_line_and_key() {
    let e = world_error(&follow_world(false, "follow_lane = true"));
    assert!(e.starts_with("w.toml:"), "{e}");
    assert!(e.contains("follow_lane") && e.contains("no road"), "{e}");
    let e = world_error(&follow_world(true, "follow_lane = true\nlane = -3"));
    assert!(
        e.contains("vehicle[1].programme[1].lane") && e.contains("lanes: -1, 1"),
        "{e}"
    );
    let e = world_error(&follow_world(true, "follow_lane = true\nlane = 0.5"));
    assert!(e.contains("programme[1].lane"), "{e}");
    let e = world_error(&follow_world(
        true,
        "follow_lane = true\nlane_change_time = 0.1",
    ));
    assert!(
        e.contains("lane_change_time") && e.contains("from 1 to 60 s"),
        "{e}"
    );
    let e = world_error(&follow_world(
        true,
        "lane = -1\n[[vehicle.programme]]\nat = 2.0\nlane = 1",
    ));
    assert!(
        e.contains("programme[2].lane") && e.contains("centre line"),
        "{e}"
    );
    let e = world_error(&follow_world(true, "follow_lane = false\nlane = -1"));
    assert!(
        e.contains("programme[1].lane") && e.contains("stops following"),
        "{e}"
    );
    // A good one: one follow step, the driver's command apart.
    let w =
        sim::world_file::parse_str("w.toml", &follow_world(true, "follow_lane = true")).unwrap();
    assert_eq!(w.cars[0].lanes.steps().len(), 1);
    assert_eq!(w.cars[0].programme.steps()[0].commands.len(), 1);
}

#[test]
fn the_programme_run_reports_a_lane_departure_with_its_time_and_side() {
    use sim::scenario::{self, Scenario, Value};
    // Following the right lane at 40 km/h, then at 5 s the follower lets go and the
    // programme steers 0.02 rad left: the car drifts over the centre line (t = 0).
    let text = follow_world(
        true,
        "follow_lane = true\n[[vehicle.programme]]\nat = 5.0\nfollow_lane = false\n\
         [[vehicle.programme]]\nat = 5.0\nsteering_angle = -0.02",
    )
    .replace("cruising_speed = 30", "cruising_speed = 40")
    .replace("basicTimeStep = 10", "basicTimeStep = 10\nduration = 12.0");
    let w = sim::world_file::parse_str("w.toml", &text).unwrap();
    let report = scenario::run(&w, Scenario::Programme, &mut |_| {}).unwrap();
    let r = &report.results[0];
    assert_eq!(r.metric("lane_departures"), Some(Value::Number(1.0)));
    assert_eq!(r.metric("lane_departures_left"), Some(Value::Number(1.0)));
    assert_eq!(r.metric("lane_departures_right"), Some(Value::Number(0.0)));
    let Some(Value::Number(t)) = r.metric("first_lane_departure_s") else {
        panic!("{:?}", r.metrics);
    };
    // The crossing is after the steering starts, and within the run.
    assert!((5.0..12.0).contains(&t), "{t} s");
    // The departure is the first time the recorded left tyre edge is beyond the line: the
    // telemetry puts the edge inside the lane one sample before.
    let telemetry = &r.telemetry[0].samples;
    let params = Model::BmwX5.params::<f64>();
    let edge = |s: &sim::telemetry::Sample| {
        let w =
            0.5 * params.track_front + 0.5 * params.wheels[ackermann::Wheel::FrontLeft].thickness;
        s.y + params.wheelbase * s.yaw.sin() + w * s.yaw.cos()
    };
    let k = telemetry
        .iter()
        .position(|s| (s.time - t).abs() < 1e-9)
        .unwrap();
    assert!(edge(&telemetry[k]) > 0.0 && edge(&telemetry[k - 1]) <= 0.0);
    assert!(
        r.notes
            .iter()
            .any(|n| n.contains("lane departure to the left at")),
        "{:?}",
        r.notes
    );
}
