//! Shared helpers of the car tests.
#![allow(dead_code, clippy::unwrap_used, clippy::panic)]

use sim::{Simulation, TyreChoice, VehicleId, VehiclePlacement, VehicleSpec, World, WorldConfig};
use vehicle_model::CarParams;
use vehicle_model::{Model, WebotsContact, Wheel};

/// Tyre–ground friction of the speed tests. With Webots' default 1, the front-driven BmwX5
/// (3.97 m/s² needs 8.4 kN of traction from about 8.0 kN of front-axle load) and the
/// rear-driven TeslaModel3 (6.94 m/s²) are traction-limited: 1.5 lets every model follow its
/// motor ramp.
pub const GRIPPY: f64 = 1.5;

/// Webots' contact: the friction pyramid without force-dependent slip (`tyre = "webots"`).
pub fn webots_tyre() -> TyreChoice {
    TyreChoice::Webots(WebotsContact::default())
}

/// A simulation with one `model` on its default slip-based tyres on flat ground of friction
/// `mu`, settled for 1 s.
pub fn settled(model: Model, mu: f64) -> (Simulation, VehicleId) {
    settled_on(model, mu, &TyreChoice::of_model(model))
}

/// A simulation with one `model` on `tyre` on flat ground of friction `mu`, settled for 1 s.
pub fn settled_on(model: Model, mu: f64, tyre: &TyreChoice) -> (Simulation, VehicleId) {
    settled_with_step(model, mu, tyre, WorldConfig::default().basic_time_step_ms)
}

/// As [`settled_on`], with a `dt_ms` step (ms).
pub fn settled_with_step(
    model: Model,
    mu: f64,
    tyre: &TyreChoice,
    dt_ms: u32,
) -> (Simulation, VehicleId) {
    settled_car(model.params(), mu, tyre, dt_ms)
}

/// The car of `params` on `tyre` on flat ground of friction `mu`, stepped at `dt_ms` (ms),
/// settled for 1 s.
pub fn settled_car(
    params: CarParams<f64>,
    mu: f64,
    tyre: &TyreChoice,
    dt_ms: u32,
) -> (Simulation, VehicleId) {
    let world = World::new(WorldConfig {
        ground_friction: mu,
        basic_time_step_ms: dt_ms,
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let (id, report) = sim
        .add_car(
            sim::CarBuilder::new(params)
                .tyre(tyre.clone())
                .mounting(crate::MOUNTING)
                .placement(VehiclePlacement::default()),
        )
        .unwrap();
    assert!(report.is_empty(), "{report:?}");
    run(&mut sim, 1.0);
    (sim, id)
}

/// The car of `params` on the default tyres and the suite's mounting.
pub fn spec(params: &CarParams<f64>) -> VehicleSpec {
    let mut spec = VehicleSpec::from_car(params).unwrap();
    spec.mounting = crate::MOUNTING;
    spec
}

/// Steps `sim` for `seconds` (s).
pub fn run(sim: &mut Simulation, seconds: f64) {
    let steps = (seconds / sim.world().dt()).round() as usize;
    for _ in 0..steps {
        sim.step().unwrap();
    }
}

/// Steps until `done` holds or `limit` seconds have passed; returns the elapsed time (s).
pub fn run_until(
    sim: &mut Simulation,
    limit: f64,
    mut done: impl FnMut(&Simulation) -> bool,
) -> Option<f64> {
    let t0 = sim.world().time();
    while sim.world().time() - t0 < limit {
        sim.step().unwrap();
        if done(sim) {
            return Some(sim.world().time() - t0);
        }
    }
    None
}

/// Runs until 1 s after the speed reaches `target_kmh` (or for `limit` s); returns when it
/// reached it (s; `None` if it did not) and whether a wheel spun at more than twice the ground
/// speed meanwhile.
pub fn accelerate(
    sim: &mut Simulation,
    id: VehicleId,
    target_kmh: f64,
    limit: f64,
) -> (Option<f64>, bool) {
    let mut spun = false;
    let reached = run_until(sim, limit, |s| {
        let t = s.telemetry(id).unwrap();
        spun |= Wheel::ALL
            .into_iter()
            .any(|w| t.state.tyres[w].slip_ratio > 1.0);
        t.speed * 3.6 >= target_kmh
    });
    if reached.is_some() {
        run(sim, 1.0);
    }
    (reached, spun)
}

/// Brakes at intensity 1 in torque mode (throttle 0: the speed-mode motors would overpower the
/// brakes) until the car stops, its speed first below 1 cm/s (or for `limit` s); returns when
/// it stopped (s; `None` if it did not) and whether its rear wheels locked while the front
/// ones still rolled.
pub fn brake_to_rest(sim: &mut Simulation, id: VehicleId, limit: f64) -> (Option<f64>, bool) {
    let d = sim.driver_mut(id).unwrap();
    d.set_throttle(0.0);
    d.set_brake_intensity(1.0);
    let mut rear_first = false;
    let stopped = run_until(sim, limit, |s| {
        let t = s.telemetry(id).unwrap();
        let locked = |w: Wheel| t.state.tyres[w].slip_ratio < -0.5;
        rear_first |= locked(Wheel::RearRight) && !locked(Wheel::FrontRight);
        t.speed < 0.01
    });
    (stopped, rear_first)
}
