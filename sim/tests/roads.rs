//! Cars on roads: both wheel mountings stand on a road's surface (its height, normal and
//! friction), with the forces that grade, crest and banking give.
#![allow(clippy::unwrap_used, clippy::panic)]

use sim::nalgebra::Point2;
use sim::road::{Cubic, Curve, Profile, Road, RoadNetwork};
use sim::{CarBuilder, Mounting, Simulation, VehicleId, VehiclePlacement, World, WorldConfig};
use vehicle_model::Model;

const G: f64 = 9.81;

/// A simulation with a BmwX5 on `mounting` at station `s` of the right lane (t = −1.75 m) of
/// `road`, its wheels 5 cm above the surface, on a world with that one road.
fn car_on(road: Road, mounting: Mounting, s: f64) -> (Simulation, VehicleId) {
    let p = road.surface_point(s, -1.75);
    let heading = road.plan_at(s).heading;
    let params = Model::BmwX5.params();
    let radius = params.radius_rear();
    let world = World::new(WorldConfig {
        roads: RoadNetwork {
            roads: vec![road],
            junctions: Vec::new(),
        },
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let placement = VehiclePlacement {
        x: p.x,
        y: p.y,
        yaw: heading,
        z: Some(p.z + radius + 0.05),
    };
    let (id, _) = sim
        .add_car(
            CarBuilder::new(params)
                .mounting(mounting)
                .placement(placement),
        )
        .unwrap();
    (sim, id)
}

/// The sums over the four tyres of the forces along the wheel heading, along the axis and
/// the loads (N) after the last step.
fn tyre_sums(sim: &Simulation, id: VehicleId) -> [f64; 3] {
    let t = sim.world().vehicle(id).unwrap().state().tyres;
    let mut out = [0.0; 3];
    for w in ackermann::Wheel::ALL {
        out[0] += t[w].fx;
        out[1] += t[w].fy;
        out[2] += t[w].fz;
    }
    out
}

/// Steers car `id` onto the lane centre t = −1.75 m of the world's only road by pure pursuit
/// (look-ahead 10 m): the steering angle (rad, positive right) that puts the rear axle on the
/// arc through the look-ahead point.
fn steer(sim: &mut Simulation, id: VehicleId) {
    let state = *sim.world().vehicle(id).unwrap().state();
    let road = &sim.world().config().roads.roads[0];
    let here = Point2::new(state.position.x, state.position.y);
    let (s, _, _) = road.station_of(&here);
    let ahead = 10.0;
    let target = road.surface_point(s + ahead, -1.75);
    let yaw = state.roll_pitch_yaw.yaw;
    let d = Point2::new(target.x, target.y) - here;
    let alpha = d.y.atan2(d.x) - yaw;
    let curvature = 2.0 * alpha.sin() / d.norm();
    let wheelbase: f64 = Model::BmwX5.params().wheelbase;
    sim.driver_mut(id)
        .unwrap()
        .set_steering_angle(-(wheelbase * curvature).atan());
}

/// Runs `seconds` (s), steering, and returns the mean of `tyre_sums` over the last `window`
/// (s) with the mean forward speed (m/s).
fn drive(sim: &mut Simulation, id: VehicleId, seconds: f64, window: f64) -> ([f64; 3], f64) {
    let dt = sim.world().dt();
    let steps = (seconds / dt).round() as usize;
    let last = (window / dt).round() as usize;
    let (mut sums, mut speed) = ([0.0; 3], 0.0);
    for i in 0..steps {
        steer(sim, id);
        sim.step().unwrap();
        if i + last >= steps {
            let f = tyre_sums(sim, id);
            for k in 0..3 {
                sums[k] += f[k] / last as f64;
            }
            speed += sim.world().vehicle(id).unwrap().state().forward_speed / last as f64;
        }
    }
    (sums, speed)
}

const BOTH: [Mounting; 2] = [Mounting::Cast, Mounting::Joints];

#[test]
fn a_braked_car_on_a_grade_holds_g_sin_theta_along_it() {
    // A 10 % grade (θ = atan 0.1): held by its brakes, the tyres carry m·g·sin θ along the
    // road and m·g·cos θ across it, whatever the mass: Σfx/Σfz = tan θ.
    for mounting in BOTH {
        let mut road =
            Road::two_way("grade", Point2::origin(), 0.0, &[(200.0, Curve::Line)], 3.5).unwrap();
        road.elevation = Profile::new(vec![Cubic {
            s: 0.0,
            coefficients: [0.0, 0.1, 0.0, 0.0],
        }]);
        let (mut sim, id) = car_on(road, mounting, 100.0);
        sim.driver_mut(id).unwrap().set_brake_intensity(1.0);
        let ([fx, _, fz], speed) = drive(&mut sim, id, 3.0, 0.5);
        // Both sums are the means of the last half second of a car at rest (|v| < 1 cm/s).
        assert!(speed.abs() < 0.01, "{mounting:?}: {speed}");
        // The road pushes the car up the grade: forward.
        let ratio = fx / fz;
        // 2 % for the settled car's residual oscillation and the f32 mesh.
        assert!((ratio - 0.1).abs() < 0.002, "{mounting:?}: {ratio}");
        // On the road's surface, not the ground: the body is 10 m up there.
        let z = sim.world().vehicle(id).unwrap().state().position.z;
        assert!(z > 10.0, "{z}");
    }
}

#[test]
fn a_crest_unloads_the_wheels_by_m_v2_over_r() {
    // Up a 30 % grade, over a crest of vertical radius R = 100 m (z'' = −1/R over 60 m), down
    // again; the car cruising at 15 m/s. At the top, Σfz = m·(g − v²/R): the loads fall by
    // v²/(g·R) = 23 % of the weight measured on the flat start.
    let r = 100.0;
    for mounting in BOTH {
        let mut road =
            Road::two_way("crest", Point2::origin(), 0.0, &[(400.0, Curve::Line)], 3.5).unwrap();
        let (flat, up, top) = (100.0, 40.0, 30.0);
        road.elevation = Profile::new(vec![
            Cubic {
                s: 0.0,
                coefficients: [0.0; 4],
            },
            // A smooth start of the climb: z'' = +1/R from flat to 30 % over 30 m.
            Cubic {
                s: flat,
                coefficients: [0.0, 0.0, 0.5 / r, 0.0],
            },
            Cubic {
                s: flat + 30.0,
                coefficients: [4.5, 0.3, 0.0, 0.0],
            },
            Cubic {
                s: flat + 30.0 + up,
                coefficients: [16.5, 0.3, -0.5 / r, 0.0],
            },
            // Down at 30 % and level again at 12 m.
            Cubic {
                s: flat + 30.0 + up + 60.0,
                coefficients: [16.5, -0.3, 0.5 / r, 0.0],
            },
            Cubic {
                s: flat + 30.0 + up + 90.0,
                coefficients: [12.0, 0.0, 0.0, 0.0],
            },
        ]);
        let crest = flat + 30.0 + up + top;
        let (mut sim, id) = car_on(road, mounting, 10.0);
        sim.driver_mut(id).unwrap().set_cruising_speed(15.0 * 3.6);
        // On the flat at cruising speed: the weight.
        let ([_, _, weight], v0) = drive(&mut sim, id, 5.0, 0.5);
        assert!((v0 - 15.0).abs() < 0.3, "{v0}");
        // On to the crest's top (the rear axle at s = crest); the loads averaged over ±0.2 s.
        loop {
            steer(&mut sim, id);
            sim.step().unwrap();
            let x = sim.world().vehicle(id).unwrap().state().position.x;
            if x > crest - 3.0 - 0.2 * 15.0 {
                break;
            }
        }
        let ([_, _, fz], v) = drive(&mut sim, id, 0.4, 0.4);
        let expected = weight * (1.0 - v * v / (G * r));
        // 3 % of the weight: the suspension's pitch and heave after the changes of z'', and
        // the mean over 6 m of a curvature the car's 2.9 m wheelbase straddles.
        assert!(
            (fz - expected).abs() < 0.03 * weight,
            "{mounting:?}: {fz} vs {expected} (weight {weight}, v {v})"
        );
    }
}

#[test]
fn on_a_curve_banked_for_its_speed_the_tyres_carry_no_side_force() {
    // A left arc of R = 60 m banked by φ with tan φ = v²/(g·R) at v = 15 m/s: the road's
    // normal force alone turns the car, the tyres' side forces vanish. On the same arc unbanked
    // they carry m·v²/R.
    let (r, v) = (60.0, 15.0);
    let phi = (v * v / (G * r)).atan();
    for mounting in BOTH {
        let mut side = [0.0; 2];
        let mut weight = 0.0;
        for (k, bank) in [0.0, phi].into_iter().enumerate() {
            let segments = [
                (150.0, Curve::Line),
                (
                    40.0,
                    Curve::Spiral {
                        curvature_start: 0.0,
                        curvature_end: 1.0 / r,
                    },
                ),
                (r * 3.0, Curve::Arc { curvature: 1.0 / r }),
            ];
            let mut road = Road::two_way("bank", Point2::origin(), 0.0, &segments, 3.5).unwrap();
            // Lifting the outer (right) side: a negative roll; ramped in along the spiral.
            road.superelevation = Profile::new(vec![
                Cubic {
                    s: 0.0,
                    coefficients: [0.0; 4],
                },
                Cubic {
                    s: 150.0,
                    coefficients: [0.0, -bank / 40.0, 0.0, 0.0],
                },
                Cubic {
                    s: 190.0,
                    coefficients: [-bank, 0.0, 0.0, 0.0],
                },
            ]);
            let (mut sim, id) = car_on(road, mounting, 20.0);
            sim.driver_mut(id).unwrap().set_cruising_speed(v * 3.6);
            let ([_, _, fz], _) = drive(&mut sim, id, 6.0, 0.5);
            weight = fz;
            // Into the arc and 3 s round it.
            let ([_, fy, _], speed) = drive(&mut sim, id, 14.0, 3.0);
            assert!((speed - v).abs() < 0.3, "{speed}");
            side[k] = fy;
        }
        let m = weight / G;
        let needed = m * v * v / r;
        // Unbanked: the tyres' axis forces (toward the centre, to the left) give m·v²/R
        // within 5 % (the steered fronts' axes are a few degrees off the car's).
        assert!(
            (side[0] - needed).abs() < 0.05 * needed,
            "{mounting:?}: {} vs {needed}",
            side[0]
        );
        // Banked: under 5 % of it.
        assert!(
            side[1].abs() < 0.05 * needed,
            "{mounting:?}: {} vs {needed}",
            side[1]
        );
    }
}
