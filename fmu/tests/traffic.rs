//! A world of several cars in the FMU: it drives the car without a programme, the others run
//! theirs (the same `sim::traffic` as under a C controller), parameters reach the driven car,
//! and the run equals the engine's own to the bit, also after a state is set back.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::Path;

use sim::Simulation;
use sim::traffic::Traffic;
use sim::world_file::{self, KeyPath};
use vehicle_fmu::instance::{Instance, Version};
use vehicle_fmu::variables::{CONTROL_MODE, CRUISING_SPEED, Kind};

/// A lead car 40 m ahead that cruises at 36 km/h and brakes at 4 s, and the free car behind.
const CONVOY: &str = "basicTimeStep = 10\n\
[[vehicle]]\nmodel = \"BmwX5\"\nname = \"lead\"\ntranslation = [40, 0, 0.5]\n\
[[vehicle.programme]]\nat = 0.0\ncruising_speed = 36\n\
[[vehicle.programme]]\nat = 4.0\ncruising_speed = 0\nbrake_intensity = 1\n\
[[vehicle]]\nmodel = \"TeslaModel3\"\nname = \"ego\"\n";

#[test]
fn the_free_car_is_driven_and_the_others_run_their_programmes() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fmu-traffic");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("world.toml"), CONVOY).unwrap();
    let mut fmu = Instance::new("convoy", &dir, Version::Fmi2).unwrap();
    // vehicle.mass is the driven car's: the second [[vehicle]].
    assert_eq!(
        fmu.get(1000, Kind::Real).unwrap(),
        1847.0,
        "the TeslaModel3's mass"
    );
    fmu.enter_initialisation().unwrap();
    fmu.set(1000, Kind::Real, 2000.0).unwrap();
    fmu.exit_initialisation().unwrap();
    assert_eq!(fmu.get(1000, Kind::Real).unwrap(), 2000.0);
    fmu.set(CONTROL_MODE, Kind::Integer, 0.0).unwrap();
    fmu.set(CRUISING_SPEED, Kind::Real, 8.0).unwrap();

    let mass = KeyPath::parse("vehicle[1].mass").unwrap();
    let description = world_file::parse_with_numbers("w", CONVOY, &[(mass, 2000.0)]).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let ids: Vec<_> = sim.car_ids().collect();
    let mut traffic = Traffic::new(&description, &ids, 1);
    sim.driver_mut(ids[1])
        .unwrap()
        .set_cruising_speed(8.0 * 3.6);

    let mut state = None;
    let mut trace = Vec::new();
    for k in 0..60 {
        fmu.do_step(f64::from(k) * 0.1, 0.1).unwrap();
        for _ in 0..10 {
            traffic.issue_due(&mut sim);
            sim.step().unwrap();
        }
        let x = fmu.get(100, Kind::Real).unwrap();
        assert_eq!(
            x.to_bits(),
            sim.telemetry(ids[1]).unwrap().state.position.x.to_bits()
        );
        trace.push(x.to_bits());
        if k == 29 {
            state = Some(fmu.state());
        }
    }
    // The lead drove off at 10 m/s and has braked since 4 s (at about 4 m/s², so below
    // 3 m/s at 6 s); the driven car keeps its own 8 m/s.
    let lead = sim.telemetry(ids[0]).unwrap();
    assert!(lead.state.position.x > 60.0 && lead.speed < 3.0, "{lead:?}");
    assert!((sim.telemetry(ids[1]).unwrap().speed - 8.0).abs() < 0.5);
    // Back to 3 s: the lead's programme is back where it was too (it brakes again at 4 s).
    fmu.set_state(&state.unwrap()).unwrap();
    let again: Vec<u64> = (30..60)
        .map(|k| {
            fmu.do_step(f64::from(k) * 0.1, 0.1).unwrap();
            fmu.get(100, Kind::Real).unwrap().to_bits()
        })
        .collect();
    assert_eq!(again, trace[30..]);
}
