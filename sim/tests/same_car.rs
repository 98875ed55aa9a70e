//! One car, every way of building it: a world file's car on joints, on Webots' tyre contact,
//! with proportioned brakes is the same car (the same spec, the same first 100 steps of
//! telemetry, bit for bit) through `Simulation::from_description` (what the C API and Python
//! build), the `vehicle-sim` programme (the CLI's scenario code) and the Rust `CarBuilder`.
//! (The C and Python front-ends are compared with the programme by the capi and Python tests.)

// Test helpers report failures by panicking.
#![allow(clippy::unwrap_used)]

use sim::scenario::{self, Scenario};
use sim::telemetry::Sample;
use sim::world_file::{self, WorldDescription};
use sim::{CarBuilder, Mounting, Simulation, TyreChoice, World};
use vehicle_model::{BrakeBalance, Model, WebotsContact};

const WORLD: &str = "\
basicTimeStep = 10
duration = 1.0
[vehicle]
model = \"BmwX5\"
mounting = \"joints\"
tyre = \"webots\"
brake_balance = \"proportioned\"
[[vehicle.programme]]
at = 0.0
cruising_speed = 40
[[vehicle.programme]]
at = 0.5
steering_angle = 0.1
";

/// The world's commands, given through the driver at the programme's instants.
fn drive(sim: &mut Simulation) -> Vec<Sample> {
    let id = sim.car_ids().next().unwrap();
    sim.record("run");
    for _ in 0..100 {
        let t = sim.world().time();
        if t == 0.0 {
            sim.driver_mut(id).unwrap().set_cruising_speed(40.0);
        }
        if (t - 0.5).abs() < 1e-9 {
            sim.driver_mut(id).unwrap().set_steering_angle(0.1);
        }
        sim.step().unwrap();
    }
    let report = sim.report("w").unwrap().unwrap();
    report.results[0].telemetry[0].samples.clone()
}

fn description() -> WorldDescription {
    world_file::parse_str("w.toml", WORLD).unwrap()
}

#[test]
fn a_world_file_car_is_the_same_car_every_way_it_is_built() {
    let description = description();
    let (mut described, reports) = Simulation::from_description(&description).unwrap();
    assert!(reports.iter().all(|r| r.is_empty()));

    let mut built = Simulation::new(World::new(description.config.clone()).unwrap());
    let car = CarBuilder::of_model(Model::BmwX5)
        .mounting(Mounting::Joints)
        .tyre(TyreChoice::Webots(WebotsContact::default()))
        .brake_balance(BrakeBalance::Proportioned);
    built.add_car(car).unwrap();

    let spec = |sim: &Simulation| {
        *sim.world()
            .vehicle(sim.car_ids().next().unwrap())
            .unwrap()
            .spec()
    };
    assert_eq!(spec(&described), spec(&built));
    assert_eq!(spec(&built).mounting, Mounting::Joints);
    assert_eq!(
        built
            .driver(built.car_ids().next().unwrap())
            .unwrap()
            .brake_balance(),
        BrakeBalance::Proportioned
    );

    let from_description = drive(&mut described);
    let from_builder = drive(&mut built);
    assert_eq!(from_description.len(), 101);
    assert_eq!(from_description, from_builder);

    // The programme scenario (vehicle-sim --scenario programme) runs the same commands.
    let run = scenario::run(&description, Scenario::Programme, &mut |_| {}).unwrap();
    let programme = &run.results[0].telemetry[0].samples;
    assert_eq!(programme, &from_description);
}
