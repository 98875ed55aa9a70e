//! No energy from nowhere (issue #37): a car gains no more mechanical energy than its engine
//! gives (the work of its drive torques), whatever happens to it: a roll-over at full lock on
//! a high-friction ground, tumbling, landing on its roof, on either mounting.
//!
//! (The wedging that threw a rolled car up, a leaning suspension's friction feeding its own
//! normal load, is tested where it was fixed, in the contact solve's unit tests: it needs the
//! cruise control's imposed wheel spin, an unlimited source the budget here cannot bound.)

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::Simulation;
use vehicle_model::Wheel;

/// Runs `world` and returns the car's mechanical energy (J) at `cut` s, and the most by which
/// it exceeds afterwards that energy plus the engine's work since: each step, each driven
/// wheel's torque times its mean spin over the step (exact for a spin the torque alone
/// changes). Not `engineMaxPower` times the time: a combustion curve is not held to it (the
/// BmwX5's gives some 200 kW at 6000 rpm), and since a driven wheel carries its engine's
/// inertia (`Commands::driveline`), a car on its roof spins that up in the air, its driven
/// wheels at twice Webots' engine speed (the mean of all four wheels): 780 kJ in 6 s.
fn energy_after_cut(world: &str, cut: f64) -> (f64, f64) {
    let d = sim::world_file::parse_str("energy.toml", world).unwrap();
    let (mut s, _) = Simulation::from_description(&d).unwrap();
    let id = s.car_ids().next().unwrap();
    let mut programme = d.cars[0].programme.cursor();
    let dt = s.world().dt();
    let (mut at_cut, mut most, mut work) = (None, f64::NEG_INFINITY, 0.0);
    while !s.is_over() {
        let t = s.world().time();
        let _ = programme.apply_due(t, s.driver_mut(id).unwrap());
        let before = s.world().vehicle(id).unwrap().state().wheel_speeds;
        s.step().unwrap();
        let car = s.world().vehicle(id).unwrap();
        let after = car.state().wheel_speeds;
        let e = s.world().mechanical_energy(id).unwrap();
        let now = s.world().time();
        if now < cut {
            continue;
        }
        // The work of the steps after the one that ends at the cut.
        if at_cut.is_some()
            && let Some(c) = car.commands()
        {
            work += Wheel::ALL
                .into_iter()
                .filter_map(|w| Some(c.drive[w].torque()? * 0.5 * (before[w] + after[w]) * dt))
                .sum::<f64>();
        }
        let start = *at_cut.get_or_insert(e);
        most = most.max(e - start - work);
    }
    (at_cut.unwrap(), most)
}

fn world(model: &str, mounting: &str, step_ms: u32, friction: f64, cut: f64) -> String {
    format!(
        "basicTimeStep = {step_ms}\nduration = {}\n[ground]\nfriction = {friction}\n\
         [[vehicle]]\nmodel = \"{model}\"\nmounting = \"{mounting}\"\n\
         [[vehicle.programme]]\nat = 0\nthrottle = 1\ngear = 1\n\
         [[vehicle.programme]]\nat = 3\ngear = 2\n[[vehicle.programme]]\nat = 6\ngear = 3\n\
         [[vehicle.programme]]\nat = {cut}\nsteering_angle = 0.6\n",
        cut + 15.0
    )
}

#[test]
fn a_car_rolling_over_gains_no_more_energy_than_its_engine_gives() {
    for (model, mounting, step, friction, cut) in [
        ("BmwX5", "cast", 10, 10.0, 10.0),
        ("BmwX5", "cast", 10, 3.0, 10.0),
        ("Tractor", "cast", 1, 3.0, 12.0),
        ("BmwX5", "joints", 10, 10.0, 10.0),
    ] {
        let (at_cut, excess) = energy_after_cut(&world(model, mounting, step, friction, cut), cut);
        // Moving at the cut (a roll-over needs speed): over 100 kJ.
        assert!(at_cut > 1e5, "{model} {mounting}: {at_cut} J");
        // The excess starts at 0 at the cut. Tolerance 0.1 % of the energy: rapier corrects
        // the drift of its joints and contacts with a velocity bias, which adds energy in
        // proportion to the drift (the BmwX5 on joints shows 0.02 % when its wheels hit the
        // ground after the roll); what the issue saw was 10⁴ times the car's energy.
        assert!(
            excess <= 1e-3 * at_cut,
            "{model} on {mounting}, {step} ms, μ = {friction}: {excess} J more than the \
             engine could give after {at_cut} J"
        );
    }
}
