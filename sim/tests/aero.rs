//! Aerodynamic drag and lift on both wheel mountings, against the formulas of
//! `vehicle_model::Aero`: the same car coasting with and without air loses speed faster by
//! exactly the drag over its effective mass, wind shifts the air speed the drag sees, and
//! lift changes the axle loads by the lift forces.
#![allow(clippy::unwrap_used)]

use sim::{CarBuilder, Mounting, Simulation, VehicleId, VehiclePlacement, World, WorldConfig};
use vehicle_model::{Aero, Model, Wheel};

/// The model of these tests: a passenger car with a published drag coefficient.
const MODEL: Model = Model::TeslaModel3;
/// The cruising speed the coast starts from (km/h).
const START_KMH: f64 = 108.0;
/// How long the car cruises before it coasts (s): the TeslaModel3 reaches 108 km/h in about
/// 6 s and its cruise settles well within this.
const CRUISE_SECONDS: f64 = 12.0;

/// The cars' `wheelsDampingConstant` (N·m·s/rad): negligible, as the parameters refuse 0. With the
/// model's 5 the wheels lose `4·c·v/r²` ≈ 4.7 kN at 30 m/s, 18 times the drag, and two cars
/// at speeds a few cm/s apart would differ by more than the tolerance in that loss alone.
const WHEELS_DAMPING: f64 = 1e-6;

/// A simulation of one `MODEL` on `mounting` with `aero`, in `wind` (m/s, world frame), with
/// [`WHEELS_DAMPING`].
fn car(mounting: Mounting, aero: Option<Aero<f64>>, wind: [f64; 3]) -> (Simulation, VehicleId) {
    let world = World::new(WorldConfig {
        wind: wind.into(),
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let mut builder = CarBuilder::of_model(MODEL)
        .mounting(mounting)
        .aero(aero)
        .placement(VehiclePlacement::default());
    builder.params_mut().wheels_damping_constant = WHEELS_DAMPING;
    let (id, _) = sim.add_car(builder).unwrap();
    (sim, id)
}

/// Cruises at [`START_KMH`], then rolls free in torque mode (throttle 0, no brake) for 0.5 s
/// to let the switch settle; returns the speeds (m/s) of the `seconds` that follow, one per
/// step, the first one included.
fn coast(sim: &mut Simulation, id: VehicleId, seconds: f64) -> Vec<f64> {
    sim.driver_mut(id).unwrap().set_cruising_speed(START_KMH);
    let dt = sim.world().dt();
    for _ in 0..(CRUISE_SECONDS / dt) as usize {
        sim.step().unwrap();
    }
    sim.driver_mut(id).unwrap().set_throttle(0.0);
    for _ in 0..(0.5 / dt) as usize {
        sim.step().unwrap();
    }
    let mut speeds = vec![sim.telemetry(id).unwrap().speed];
    for _ in 0..(seconds / dt).round() as usize {
        sim.step().unwrap();
        speeds.push(sim.telemetry(id).unwrap().speed);
    }
    speeds
}

/// The speed the drag alone takes from a car of effective mass `mass` (kg) moving at
/// `speeds` (m/s, one per step of `dt` s) along x in `wind_x` (m/s): `Σ D(v − w)·dt / m`.
fn drag_loss(aero: &Aero<f64>, speeds: &[f64], wind_x: f64, mass: f64, dt: f64) -> f64 {
    speeds[..speeds.len() - 1]
        .iter()
        .map(|v| -aero.forces([v - wind_x, 0.0, 0.0]).drag[0] * dt / mass)
        .sum()
}

#[test]
fn the_extra_speed_lost_with_air_is_the_drag_over_the_effective_mass() {
    let aero = MODEL.aero::<f64>();
    for mounting in [Mounting::Cast, Mounting::Joints] {
        for wind_x in [0.0, -10.0, 10.0] {
            let (mut plain, p) = car(mounting, None, [wind_x, 0.0, 0.0]);
            let (mut windy, a) = car(mounting, Some(aero), [wind_x, 0.0, 0.0]);
            let seconds = 4.0;
            let still = coast(&mut plain, p, seconds);
            let blown = coast(&mut windy, a, seconds);
            let dt = windy.world().dt();
            let spec = windy.world().vehicle(a).unwrap().spec();
            let expected = drag_loss(&aero, &blown, wind_x, spec.effective_mass(), dt);
            let lost_plain = still[0] - still[still.len() - 1];
            let lost_air = blown[0] - blown[blown.len() - 1];
            let measured = lost_air - lost_plain;
            // 2 %: the coast-down tolerance. What is left between the two cars is
            // the rolling resistance at slightly different speeds and tyre slips.
            assert!(
                (measured - expected).abs() <= 0.02 * expected,
                "{mounting:?}, wind {wind_x} m/s: lost {measured:.5} m/s more with air, \
                 the drag predicts {expected:.5} m/s"
            );
        }
    }
}

#[test]
fn lift_changes_the_axle_loads_by_the_lift_forces() {
    // A body with downforce at both axles, more at the rear.
    let aero = Aero {
        drag_coefficient: 0.0,
        lift_coefficient_front: -0.3,
        lift_coefficient_rear: -0.6,
        ..MODEL.aero::<f64>()
    };
    for mounting in [Mounting::Cast, Mounting::Joints] {
        let (mut plain, p) = car(mounting, None, [0.0; 3]);
        let (mut pressed, a) = car(mounting, Some(aero), [0.0; 3]);
        let axle_loads = |sim: &mut Simulation, id: VehicleId| {
            sim.driver_mut(id).unwrap().set_cruising_speed(START_KMH);
            let dt = sim.world().dt();
            for _ in 0..(CRUISE_SECONDS / dt) as usize {
                sim.step().unwrap();
            }
            // Averaged over 1 s: the suspension still breathes a little.
            let steps = (1.0 / dt) as usize;
            let mut sums = [0.0, 0.0, 0.0];
            for _ in 0..steps {
                sim.step().unwrap();
                let t = sim.telemetry(id).unwrap();
                let fz = |w: Wheel| t.state.tyres[w].fz;
                sums[0] += fz(Wheel::FrontRight) + fz(Wheel::FrontLeft);
                sums[1] += fz(Wheel::RearRight) + fz(Wheel::RearLeft);
                sums[2] += t.speed;
            }
            sums.map(|s| s / steps as f64)
        };
        let [front_plain, rear_plain, _] = axle_loads(&mut plain, p);
        let [front_air, rear_air, speed] = axle_loads(&mut pressed, a);
        let f = aero.forces([speed, 0.0, 0.0]);
        // 2 % of the lift: what the speed varies over the averaging second squared.
        let front_gain = front_air - front_plain;
        let rear_gain = rear_air - rear_plain;
        assert!(
            (front_gain + f.lift_front).abs() <= 0.02 * f.lift_front.abs(),
            "{mounting:?}: front axle +{front_gain:.1} N, lift {:.1} N",
            f.lift_front
        );
        assert!(
            (rear_gain + f.lift_rear).abs() <= 0.02 * f.lift_rear.abs(),
            "{mounting:?}: rear axle +{rear_gain:.1} N, lift {:.1} N",
            f.lift_rear
        );
    }
}

#[test]
fn a_car_without_air_is_unchanged_by_the_wind() {
    let (mut calm, c) = car(Mounting::Cast, None, [0.0; 3]);
    let (mut gale, g) = car(Mounting::Cast, None, [30.0, -20.0, 0.0]);
    assert_eq!(coast(&mut calm, c, 1.0), coast(&mut gale, g, 1.0));
}
