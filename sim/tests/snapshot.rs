//! `Simulation::snapshot` / `restore`: a run restored and continued equals the run never
//! interrupted, bit for bit, on both mountings, with noisy devices, a dynamic body in contact,
//! the recording, and restores to an earlier time done twice.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::devices::Reading;
use sim::{Simulation, SnapshotError, VehicleId, VehicleState, world_file};

/// A BmwX5 driving at 40 km/h while steering, with noisy devices (GPS accuracy, gyro and
/// accelerometer noise through their lookup tables, a distance sensor and a radar looking at a
/// dynamic box that it pushes), and the box resting on the ground: contacts with warm-start
/// impulses, sleeping islands and noise generators all carry state from step to step.
fn world(mounting: &str) -> String {
    format!(
        r#"[vehicle]
model = "BmwX5"
mounting = "{mounting}"
seed = 7
[[vehicle.device]]
type = "GPS"
samplingPeriod = 10
accuracy = 0.3
noiseCorrelation = 0.5
[[vehicle.device]]
type = "Gyro"
samplingPeriod = 20
lookupTable = [[-100, -100, 0.05], [100, 100, 0.05]]
[[vehicle.device]]
type = "Accelerometer"
samplingPeriod = 10
lookupTable = [[-100, -100, 0.02], [100, 100, 0.02]]
[[vehicle.device]]
type = "DistanceSensor"
samplingPeriod = 10
slot = "front"
sensorType = "laser"
lookupTable = [[0, 0, 0], [20, 20, 0.05]]
[[vehicle.device]]
type = "Radar"
samplingPeriod = 30
slot = "front"
[[body]]
translation = [9, 0, 0.5]
size = [1, 1, 1]
mass = 40
radarCrossSection = 10
"#
    )
}

/// Everything compared after each step: the car's physical state, its driver's speed
/// estimate, every device reading, and the box's pose.
#[derive(Debug, Clone, PartialEq)]
struct Frame {
    time_ms: u64,
    state: VehicleState,
    estimated_speed_kmh: f64,
    readings: Vec<Reading>,
    boxes: Vec<([f64; 3], [f64; 3])>,
}

fn frame(sim: &Simulation, id: VehicleId) -> Frame {
    let t = sim.telemetry(id).unwrap();
    Frame {
        time_ms: sim.world().time_ms(),
        state: t.state,
        estimated_speed_kmh: t.estimated_speed_kmh,
        readings: sim
            .devices(id)
            .unwrap()
            .iter()
            .map(|d| d.reading().clone())
            .collect(),
        boxes: sim
            .world()
            .bodies()
            .iter()
            .map(|b| (b.position.coords.into(), b.velocity.into()))
            .collect(),
    }
}

fn run(sim: &mut Simulation, id: VehicleId, steps: usize) -> Vec<Frame> {
    (0..steps)
        .map(|_| {
            sim.step().unwrap();
            frame(sim, id)
        })
        .collect()
}

/// The simulation of `world(mounting)`, recording, with every device enabled and the car
/// told to drive off steering left.
fn start(mounting: &str) -> (Simulation, VehicleId) {
    let description = world_file::parse_str("snapshot.toml", &world(mounting)).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    sim.record("snapshot");
    let driver = sim.driver_mut(id).unwrap();
    driver.set_cruising_speed(40.0);
    driver.set_steering_angle(-0.05);
    (sim, id)
}

fn continues_bit_for_bit(mounting: &str) {
    let (mut sim, id) = start(mounting);
    let early = run(&mut sim, id, 20);
    let a = sim.snapshot();
    let after_a = run(&mut sim, id, 60);
    let b = sim.snapshot();
    let after_b = run(&mut sim, id, 100);
    assert!(
        after_b.iter().any(|f| f.boxes[0].1[0].abs() > 0.1),
        "the car should push the box (contacts carry state across the snapshot)"
    );
    let samples = sim.car_log(id).unwrap().len();

    // Back to b: the same 100 steps, and the log as long as before.
    sim.restore(&b).unwrap();
    assert_eq!(run(&mut sim, id, 100), after_b);
    assert_eq!(sim.car_log(id).unwrap().len(), samples);

    // Back to the earlier a, twice, each time on to the end.
    for _ in 0..2 {
        sim.restore(&a).unwrap();
        assert_eq!(sim.world().time_ms(), early.last().unwrap().time_ms);
        assert_eq!(
            sim.car_log(id).unwrap().len(),
            21,
            "the first sample and 20 steps"
        );
        let again_a = run(&mut sim, id, 60);
        assert_eq!(again_a, after_a);
        assert_eq!(run(&mut sim, id, 100), after_b);
        assert_eq!(sim.car_log(id).unwrap().len(), samples);
    }
}

#[test]
fn cast_car_continues_bit_for_bit() {
    continues_bit_for_bit("cast");
}

#[test]
fn joints_car_continues_bit_for_bit() {
    continues_bit_for_bit("joints");
}

#[test]
fn a_snapshot_before_the_recording_drops_it() {
    let description = world_file::parse_str("snapshot.toml", &world("cast")).unwrap();
    let (mut sim, id) = {
        let (sim, _) = Simulation::from_description(&description).unwrap();
        let id = sim.car_ids().next().unwrap();
        (sim, id)
    };
    let snap = sim.snapshot();
    sim.record("late");
    sim.step().unwrap();
    sim.restore(&snap).unwrap();
    assert!(!sim.is_recording());
    assert!(sim.car_log(id).is_none());
}

#[test]
fn another_simulations_snapshot_is_refused() {
    let (mut first, _) = start("cast");
    let (second, _) = start("cast");
    assert_eq!(
        first.restore(&second.snapshot()).unwrap_err(),
        SnapshotError::OtherSimulation
    );
}

#[test]
fn a_restarted_recording_is_refused_and_left_alone() {
    let (mut sim, id) = start("cast");
    let snap = sim.snapshot();
    sim.record("again");
    sim.step().unwrap();
    // Compared as text: the gyro's first reading is NaN, and Debug writes each f64 so that
    // it reads back to the same bits.
    let before = format!("{:?}", frame(&sim, id));
    assert_eq!(
        sim.restore(&snap).unwrap_err(),
        SnapshotError::OtherRecording
    );
    assert_eq!(format!("{:?}", frame(&sim, id)), before);
}
