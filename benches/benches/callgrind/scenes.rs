//! The simulation cases: cars on the circle and on the ring road, on joints, behind the FMU,
//! the DifferentialWheels robot, and rapier's own ray-cast vehicle beside them.

use std::hint::black_box;

use benches::control::LoopMode;
use benches::energy::{EnergyCase, SETTLE_STEPS as ENERGY_SETTLE_STEPS, energy_scene};
use benches::fmu::{FmuLoop, NativeLoop};
use benches::peer::{PeerParams, RayCastCar};
use benches::scenes::{CarScene, RobotScene, ring_road_world};
use sim::{Mounting, Simulation, TyreChoice};

/// Steps run (uncounted) before the counted ones in the simulation cases: 8 s, so the cars
/// cruise on their circles (speed mode reaches 10 m/s in 3 s, the torque-mode throttle
/// controller about 9.7 m/s in 8 s).
const SETTLE_STEPS: u64 = 800;

#[inline(never)]
fn cg_car_step(scene: &mut CarScene) {
    scene.step().unwrap();
}

pub(crate) fn run_car<const TORQUE_MODE: bool>(steps: u64) {
    let mode = if TORQUE_MODE {
        LoopMode::Torque
    } else {
        LoopMode::Speed
    };
    let mut scene = CarScene::new(1, mode).unwrap();
    for _ in 0..SETTLE_STEPS {
        scene.step().unwrap();
    }
    for _ in 0..steps {
        cg_car_step(&mut scene);
    }
}

/// The speed-mode car of `run_car` on the ring road of `scenes::ring_road_world`: all four
/// wheels on the road's lane meshes at every step (compare with `sim_car_speed_1`).
pub(crate) fn run_road_car(steps: u64) {
    let mut scene = CarScene::in_world(
        ring_road_world().unwrap(),
        1,
        LoopMode::Speed,
        &TyreChoice::default(),
        Mounting::Cast,
    )
    .unwrap();
    for _ in 0..SETTLE_STEPS {
        scene.step().unwrap();
    }
    for _ in 0..steps {
        cg_car_step(&mut scene);
    }
}

/// The speed-mode car of `run_car` with its wheels on rapier joints.
pub(crate) fn run_joints_car(steps: u64) {
    let mut scene =
        CarScene::mounted(1, LoopMode::Speed, &TyreChoice::default(), Mounting::Joints).unwrap();
    for _ in 0..SETTLE_STEPS {
        scene.step().unwrap();
    }
    for _ in 0..steps {
        cg_car_step(&mut scene);
    }
}

#[inline(never)]
fn cg_fmu_native_step(l: &mut NativeLoop) {
    l.step().unwrap();
}

/// A controller's 10 ms step on the TeslaModel3's default world (`benches::fmu`): compare
/// with `fmu_do_step`.
pub(crate) fn run_fmu_native(steps: u64) {
    let mut l = NativeLoop::new().unwrap();
    for _ in 0..200 {
        l.step().unwrap();
    }
    for _ in 0..steps {
        cg_fmu_native_step(&mut l);
    }
}

#[inline(never)]
fn cg_fmu_do_step(l: &mut FmuLoop) {
    l.step().unwrap();
}

/// The same step through the FMU's entry points.
pub(crate) fn run_fmu(steps: u64) {
    let mut l = FmuLoop::new().unwrap();
    for _ in 0..200 {
        l.step().unwrap();
    }
    for _ in 0..steps {
        cg_fmu_do_step(&mut l);
    }
}

#[inline(never)]
fn cg_robot_step(scene: &mut RobotScene) {
    scene.step().unwrap();
}

pub(crate) fn run_robot(steps: u64) {
    let mut scene = RobotScene::physics().unwrap();
    for _ in 0..SETTLE_STEPS {
        scene.step().unwrap();
    }
    for _ in 0..steps {
        cg_robot_step(&mut scene);
    }
}

#[inline(never)]
fn cg_peer_step(car: &mut RayCastCar, steering: f32) {
    let force = car.cruise_force(10.0);
    car.step(force, steering);
}

pub(crate) fn run_peer(steps: u64) {
    let mut car = RayCastCar::new(&PeerParams::default());
    // Settle and reach cruise speed before counting.
    for _ in 0..SETTLE_STEPS {
        let force = car.cruise_force(10.0);
        car.step(force, 0.1);
    }
    for _ in 0..steps {
        cg_peer_step(&mut car, black_box(0.1));
    }
}

#[inline(never)]
fn cg_energy_step(sim: &mut Simulation) {
    sim.step().unwrap();
}

/// The energy benchmark's TeslaModel3 of `CASE` (an `EnergyCase` by its place in
/// `EnergyCase::ALL`), settled as the criterion bench's.
pub(crate) fn run_energy<const CASE: usize>(steps: u64) {
    let mut sim = energy_scene(EnergyCase::ALL[CASE], ENERGY_SETTLE_STEPS).unwrap();
    for _ in 0..steps {
        cg_energy_step(&mut sim);
    }
}
