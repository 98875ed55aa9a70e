//! Criterion benchmarks of `sim::vec_env::VecEnv`, the Rust core of
//! `webots_vehicle.gym.VectorEnv` (issue #33): one `step` of a batch of LaneKeep-v0 and ACC-v0
//! worlds (BmwX5s on cast mountings, 10 ms basic time steps, 4 per action, no camera), with
//! autoreset of the episodes that ended, as the Python vector environment runs it. The summary
//! prints car steps per second on this one thread (a car step: one car advanced 10 ms).
//! `vec_env/single/lane_keep` is one `sim::vec_env::TaskEnv::step` on a simulation of its own,
//! what the single environment `webots_vehicle.gym.LaneKeepEnv` runs per `step()` (and what
//! `python/bench/gym_step.py` subtracts from the Python `step()`, timed in its process).
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from the shipped worlds: a failure is a fixture bug and must stop the run"
)]

use std::hint::black_box;

use benches::report::{self, Medians, format_ns};
use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, BenchmarkId, Criterion, Throughput, criterion_group};
use sim::Simulation;
use sim::vec_env::{ACTION_LEN, Start, StepOut, Task, TaskEnv, VecEnv};
use sim::world_file;

/// Basic time steps per action (the gym environments' default `frame_skip`).
const FRAME_SKIP: u32 = 4;
/// Batch sizes measured.
const SIZES: [usize; 2] = [1, 16];

/// The world of `task` as the Python package ships it.
fn world(task: Task) -> world_file::WorldDescription {
    let name = match task {
        Task::LaneKeep => "lane_keep.toml",
        Task::Acc => "acc.toml",
        Task::Track => "track.toml",
    };
    let path = format!(
        "{}/../python/packages/webots_vehicle/worlds/{name}",
        env!("CARGO_MANIFEST_DIR")
    );
    world_file::load(&path).unwrap()
}

/// A start of `task`'s episodes: the middle of `gym.py`'s random draws.
fn start(task: Task) -> Start {
    match task {
        Task::LaneKeep => Start {
            x: 20.0,
            y: -5.625,
            yaw: 0.0,
            speed: 15.0,
            lead_speed: 0.0,
        },
        _ => Start {
            x: 0.0,
            y: 0.0,
            yaw: 0.0,
            speed: 15.0,
            lead_speed: 15.0,
        },
    }
}

/// Cars simulated per environment.
fn cars(task: Task) -> usize {
    if task == Task::Acc { 2 } else { 1 }
}

fn vec_env(c: &mut Criterion) {
    let mut g = c.benchmark_group("vec_env");
    for (name, task) in [("lane_keep", Task::LaneKeep), ("acc", Task::Acc)] {
        let description = world(task);
        for n in SIZES {
            let mut batch = VecEnv::new(&description, task, n, FRAME_SKIP).unwrap();
            let m = task.observation_len();
            let mut obs = vec![0.0f32; n * m];
            for i in 0..n {
                batch
                    .reset(i, &start(task), &mut obs[i * m..(i + 1) * m])
                    .unwrap();
            }
            // Straight ahead at a constant cruise target: the episodes run until the world's
            // duration (or the LaneKeep curve takes the car off the road) and are reset then,
            // so the resets are part of the cost as in training.
            let actions = vec![0.0; n * ACTION_LEN];
            let starts = vec![start(task); n];
            let (mut rewards, mut terminated, mut truncated) =
                (vec![0.0; n], vec![false; n], vec![false; n]);
            let mut reset = vec![false; n];
            g.throughput(Throughput::Elements(
                (n * cars(task)) as u64 * u64::from(FRAME_SKIP),
            ));
            g.bench_function(BenchmarkId::new(name, n), |b| {
                b.iter(|| {
                    batch
                        .step(
                            black_box(&actions),
                            &reset,
                            &starts,
                            StepOut {
                                observations: &mut obs,
                                rewards: &mut rewards,
                                terminated: &mut terminated,
                                truncated: &mut truncated,
                            },
                        )
                        .unwrap();
                    for ((r, t), u) in reset.iter_mut().zip(&terminated).zip(&truncated) {
                        *r = *t || *u;
                    }
                })
            });
        }
    }
    single(&mut g);
    g.finish();
}

/// `vec_env/single/{lane_keep,acc}`: one `TaskEnv::step` on a simulation of its own.
fn single(g: &mut BenchmarkGroup<'_, WallTime>) {
    for (name, task) in [("lane_keep", Task::LaneKeep), ("acc", Task::Acc)] {
        let (mut sim, _) = Simulation::from_description(&world(task)).unwrap();
        let mut env = TaskEnv::new(&sim, task, FRAME_SKIP).unwrap();
        let loaded = sim.snapshot();
        let mut obs = vec![0.0f32; task.observation_len()];
        env.start(&mut sim, &start(task), &mut obs).unwrap();
        g.throughput(Throughput::Elements(
            cars(task) as u64 * u64::from(FRAME_SKIP),
        ));
        g.bench_function(BenchmarkId::new("single", name), |b| {
            b.iter(|| {
                let outcome = env.step(&mut sim, black_box([0.0; 2]), &mut obs).unwrap();
                // A new episode when this one ends, as a training loop resets.
                if outcome.terminated || outcome.truncated {
                    sim.restore(&loaded).unwrap();
                    env.start(&mut sim, &start(task), &mut obs).unwrap();
                }
            })
        });
    }
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = vec_env
}

/// Car steps per second of each case, from this run's medians.
fn summary(m: &Medians) {
    println!("\nvec_env: car steps (one car, 10 ms) per second on one thread");
    for (name, task) in [("lane_keep", Task::LaneKeep), ("acc", Task::Acc)] {
        let ids = SIZES
            .iter()
            .map(|n| (format!("vec_env/{name}/{n}"), *n))
            .chain([(format!("vec_env/single/{name}"), 1)]);
        for (id, n) in ids {
            if let Some(ns) = m.get(&id) {
                let car_steps = (n * cars(task)) as f64 * f64::from(FRAME_SKIP);
                println!(
                    "  {id:<22} {:>10} per step  {:>9.0} car steps/s",
                    format_ns(ns),
                    car_steps / (ns * 1e-9)
                );
            }
        }
    }
}

fn main() {
    report::main_with_summary(benches, summary);
}
