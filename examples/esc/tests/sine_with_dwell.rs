//! The FMVSS 126 sine with dwell on the shipped BmwX5, which oversteers at the limit (Webots'
//! data: one tyre front and rear, no anti-roll bars) and spins without a stability control:
//! with the controller braking single front wheels, it meets the yaw-ratio criteria.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use esc_example::EscParams;
use sim::Simulation;
use sim::scenario::manoeuvre_metrics::sine_with_dwell;
use sim::scenario::{self, Scenario, Value};
use sim::world_file::parse_str;
use vehicle_model::Wheel;

const WORLD: &str = "[vehicle]\nmodel = \"BmwX5\"\n";

/// The controller for the BmwX5 (wheelbase from its parameters): a neutral-steer reference
/// within 0.85 g (its tyres' peak friction 1 on the ground's 1, less the load transfer's loss);
/// 0.05 rad/s of dead band (the yaw-rate noise of a real sensor is a few hundredths); 5000
/// N·m per rad/s, so that 0.3 rad/s of excess brakes a front wheel near its grip (F_z·μ·r ≈
/// 5500 N × 1 × 0.37 m ≈ 2000 N·m), capped there.
fn controller(wheelbase: f64) -> EscParams {
    EscParams {
        wheelbase: wheelbase as f32,
        understeer_gradient: 0.0,
        max_lateral_accel: 0.85 * 9.81,
        dead_band: 0.05,
        gain: 5000.0,
        max_torque: 2000.0,
    }
}

/// Runs the sine with dwell at `amplitude` (rad, road wheel) from 80 km/h, the controller
/// adding its brake torques when `esc`; returns the yaw-rate ratios and the displacement (m).
fn sine_with_dwell_run(amplitude: f64, esc: bool) -> ((f64, f64), f64) {
    let world = parse_str("w.toml", WORLD).unwrap();
    let (mut sim, _) = Simulation::from_description(&world).unwrap();
    let id = sim.car_ids().next().unwrap();
    let params = controller(world.car().unwrap().params.wheelbase);
    sim.driver_mut(id).unwrap().set_cruising_speed(80.0);
    // The run-up: 25 s reach a steady 80 km/h (the BmwX5's time0To100 is 7.8 s).
    while sim.world().time() < 25.0 {
        sim.step().unwrap();
    }
    sim.driver_mut(id).unwrap().set_throttle(0.0);
    let t0 = sim.world().time();
    let state = *sim.world().vehicle(id).unwrap().state();
    let (p0, yaw0) = (state.position, state.roll_pitch_yaw.yaw);
    let mut yaw_rates = Vec::new();
    let mut displacement = None;
    while sim.world().time() - t0 < sine_with_dwell::completion() + 2.5 {
        let t = sim.world().time() - t0;
        let steer = sine_with_dwell::steering(t, amplitude);
        sim.driver_mut(id).unwrap().set_steering_angle(-steer);
        // The controller's period is the step: the driver's commands, then its torques added.
        let vehicle = sim.world().vehicle(id).unwrap();
        let sensors = vehicle.sensors(sim.world().time());
        let s = *vehicle.state();
        let mut commands = *sim.driver_mut(id).unwrap().step(&sensors);
        if esc {
            let torques =
                params.brake_torques(s.forward_speed as f32, steer as f32, s.yaw_rate as f32);
            for (w, t) in Wheel::ALL.into_iter().zip(torques) {
                commands.brake_torque[w] += f64::from(t);
            }
        }
        sim.world_mut()
            .vehicle_mut(id)
            .unwrap()
            .set_commands(&commands);
        sim.step_others(id).unwrap();
        let s = *sim.world().vehicle(id).unwrap().state();
        let t = sim.world().time() - t0;
        yaw_rates.push((t, s.yaw_rate));
        let lateral = -(s.position.x - p0.x) * yaw0.sin() + (s.position.y - p0.y) * yaw0.cos();
        if displacement.is_none() && t >= sine_with_dwell::DISPLACEMENT_TIME {
            displacement = Some(lateral);
        }
    }
    (
        sine_with_dwell::yaw_ratios(&yaw_rates).unwrap(),
        displacement.unwrap(),
    )
}

#[test]
fn the_controller_turns_a_failing_car_into_a_passing_one() {
    // The amplitude the scenario finds: 6.5 times the steer of 0.3 g.
    let world = parse_str("w.toml", WORLD).unwrap();
    let report = scenario::run(&world, Scenario::SineWithDwell, &mut |_| {}).unwrap();
    let Some(Value::Number(amplitude)) = report.results[0].metric("steer_amplitude_rad") else {
        panic!("no amplitude")
    };
    let (without, d0) = sine_with_dwell_run(amplitude, false);
    println!("without ESC: ratios {without:?}, displacement {d0} m");
    assert!(!sine_with_dwell::passes(without, d0));
    let (with, d1) = sine_with_dwell_run(amplitude, true);
    println!("with ESC: ratios {with:?}, displacement {d1} m");
    assert!(sine_with_dwell::passes(with, d1), "{with:?} {d1}");
}
