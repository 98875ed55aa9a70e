//! `sim::vec_env`: copies are independent and deterministic, a reset starts where it is told,
//! the autoreset flag resets instead of stepping, a `TaskEnv` on a simulation of its own is a
//! copy of a batch bit for bit, the default rewards follow their documented formulas, bad
//! input is refused by name. (The Python tests compare each copy with `webots_vehicle.gym`'s
//! single environment, which runs a `TaskEnv`, bit for bit.)
#![allow(
    clippy::unwrap_used,
    reason = "test fixtures: the shipped world loads; a failure must stop the test"
)]

use sim::Simulation;
use sim::vec_env::{ACTION_LEN, Start, StepOut, Task, TaskEnv, VecEnv, VecEnvError};
use sim::world_file::{self, WorldDescription};

fn lane_keep() -> WorldDescription {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../python/packages/webots_vehicle/worlds/lane_keep.toml"
    );
    world_file::load(path).unwrap()
}

const START: Start = Start {
    x: 20.0,
    y: -5.625,
    yaw: 0.0,
    speed: 15.0,
    lead_speed: 0.0,
};

struct Out {
    obs: Vec<f32>,
    rewards: Vec<f64>,
    terminated: Vec<bool>,
    truncated: Vec<bool>,
}

impl Out {
    fn new(n: usize) -> Out {
        Out {
            obs: vec![0.0; n * Task::LaneKeep.observation_len()],
            rewards: vec![0.0; n],
            terminated: vec![false; n],
            truncated: vec![false; n],
        }
    }

    fn view(&mut self) -> StepOut<'_> {
        StepOut {
            observations: &mut self.obs,
            rewards: &mut self.rewards,
            terminated: &mut self.terminated,
            truncated: &mut self.truncated,
        }
    }
}

fn batch(n: usize) -> (VecEnv, Out) {
    let mut b = VecEnv::new(&lane_keep(), Task::LaneKeep, n, 4).unwrap();
    let mut out = Out::new(n);
    let m = Task::LaneKeep.observation_len();
    for i in 0..n {
        b.reset(i, &START, &mut out.obs[i * m..(i + 1) * m])
            .unwrap();
    }
    (b, out)
}

#[test]
fn a_reset_starts_where_it_is_told() {
    let (b, out) = batch(1);
    // One 10 ms step after the reset: the speed set (15 m/s) less what rolling resistance and
    // the cruise control change in 10 ms (well under 0.05 m/s at under 1 m/s²); the cruise
    // target is the start speed exactly; straight in the middle lane: offset within the
    // 0.05 m the car's settling moves it, lane width 3.75 m, on the road.
    assert!((out.obs[0] - 15.0).abs() < 0.05, "{}", out.obs[0]);
    assert_eq!(out.obs[4], 15.0);
    assert!(out.obs[5].abs() < 0.05, "offset {}", out.obs[5]);
    assert_eq!((out.obs[9], out.obs[10]), (3.75, 1.0));
    assert!((b.time(0) - 0.01).abs() < 1e-12);
}

#[test]
fn copies_are_independent_and_deterministic() {
    // Copy 0 of a batch of 2 whose copy 1 steers hard equals a batch of 1, bit for bit.
    let (mut two, mut out2) = batch(2);
    let (mut one, mut out1) = batch(1);
    let m = Task::LaneKeep.observation_len();
    for t in 0..50 {
        let a0 = [0.1 * f64::from(t % 5) - 0.2, 0.5];
        let actions2 = [a0[0], a0[1], 1.0, -1.0];
        two.step(&actions2, &[false; 2], &[START; 2], out2.view())
            .unwrap();
        one.step(&a0, &[false], &[START], out1.view()).unwrap();
        assert_eq!(out2.obs[..m], out1.obs[..], "step {t}");
        assert_eq!(out2.rewards[0].to_bits(), out1.rewards[0].to_bits());
    }
    // And copy 1 went elsewhere.
    assert_ne!(out2.obs[m..], out2.obs[..m]);
}

#[test]
fn the_reset_flag_resets_instead_of_stepping() {
    let (mut b, mut out) = batch(2);
    let fresh = out.obs.clone();
    let actions = [1.0; 2 * ACTION_LEN];
    for _ in 0..10 {
        b.step(&actions, &[false; 2], &[START; 2], out.view())
            .unwrap();
    }
    b.step(&actions, &[true, false], &[START; 2], out.view())
        .unwrap();
    let m = Task::LaneKeep.observation_len();
    assert_eq!(out.obs[..m], fresh[..m]);
    assert_eq!(
        (out.rewards[0], out.terminated[0], out.truncated[0]),
        (0.0, false, false)
    );
    assert!((b.time(0) - 0.01).abs() < 1e-12);
    assert!((b.time(1) - 0.45).abs() < 1e-12);
}

#[test]
fn a_task_env_on_its_own_simulation_equals_a_copy() {
    // What the Python single environment runs (a TaskEnv on the Simulation it owns) against
    // copy 0 of a batch: the same start and actions give the same bits, actions beyond ±1
    // clipped alike.
    let (mut batch, mut out) = batch(1);
    let (mut sim, _) = Simulation::from_description(&lane_keep()).unwrap();
    let mut env = TaskEnv::new(&sim, Task::LaneKeep, 4).unwrap();
    let mut obs = vec![0.0f32; Task::LaneKeep.observation_len()];
    env.start(&mut sim, &START, &mut obs).unwrap();
    assert_eq!(obs, out.obs);
    for t in 0..60 {
        let a = [0.3 * f64::from(t % 7) - 0.9, 1.5 - 0.1 * f64::from(t)];
        batch.step(&a, &[false], &[START], out.view()).unwrap();
        let outcome = env.step(&mut sim, a, &mut obs).unwrap();
        assert_eq!(obs, out.obs, "step {t}");
        assert_eq!(outcome.reward.to_bits(), out.rewards[0].to_bits());
        assert_eq!(
            (outcome.terminated, outcome.truncated),
            (out.terminated[0], out.truncated[0])
        );
    }
    assert_eq!(sim.world().time(), batch.time(0));
    // The observation's fifth value is the cruise target.
    assert_eq!(env.target() as f32, obs[4]);
}

#[test]
fn the_default_rewards_follow_their_formulas() {
    // The formulas of `Task::reward`'s docs by hand. 0.5, 12, 15, 30, 45 and 3.75 are exact in
    // f32, so only the f64 arithmetic rounds: 1e-12.
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
    let lane = |speed: f32, offset: f32, on_road: f32| {
        [
            speed, 0.0, 0.0, 0.0, speed, offset, 0.0, 0.0, 0.0, 3.75, on_road,
        ]
    };
    let r = |task: Task, obs: &[f32], a: [f64; 2], touching: bool| {
        task.reward(obs, a, touching).unwrap()
    };
    // 15/30 − 0.5² − 0.1 × 1²; within the lane.
    let (reward, ended) = r(Task::LaneKeep, &lane(15.0, 0.5, 1.0), [1.0, 0.0], false);
    assert!(close(reward, 0.15) && !ended, "{reward}");
    // The speed term saturates at 30 m/s.
    assert!(close(
        r(Task::LaneKeep, &lane(45.0, 0.0, 1.0), [0.0; 2], false).0,
        1.0
    ));
    // Off the road: −10, and the episode ends; so it does beyond a lane width off the centre.
    assert_eq!(
        r(Task::LaneKeep, &lane(15.0, 0.0, 0.0), [0.0; 2], false),
        (-10.0, true)
    );
    assert!(r(Task::LaneKeep, &lane(15.0, 3.8, 1.0), [0.0; 2], false).1);
    // 1 − 0.5 − |12 − 10| / 10.
    let (reward, ended) = r(
        Task::Track,
        &[12.0, 0.0, 0.0, 0.0, 12.0, 0.5, 0.0],
        [0.0; 2],
        false,
    );
    assert!(close(reward, 0.3) && !ended, "{reward}");
    assert!(
        r(
            Task::Track,
            &[12.0, 0.0, 0.0, 0.0, 12.0, 10.5, 0.0],
            [0.0; 2],
            false
        )
        .1
    );
    // A target 30 m ahead at 12 m/s: a 2.5 s gap, −(2.5 − 2)² − 0.1 × 0.5².
    let mut acc = vec![0.0f32; Task::Acc.observation_len()];
    acc[0] = 12.0;
    acc[5..9].copy_from_slice(&[30.0, 0.0, 0.0, -40.0]);
    acc[5 + 32] = 1.0;
    let (reward, ended) = r(Task::Acc, &acc, [0.0, 0.5], false);
    assert!(close(reward, -0.275) && !ended, "{reward}");
    assert_eq!(r(Task::Acc, &acc, [0.0, 0.5], true), (-100.0, true));
    acc[5 + 32] = 0.0;
    assert_eq!(r(Task::Acc, &acc, [0.0; 2], false), (-1.0, false));
    assert!(matches!(
        Task::Track.reward(&acc, [0.0; 2], false),
        Err(VecEnvError::Buffer { expected: 7, .. })
    ));
}

#[test]
fn task_names_parse() {
    assert_eq!("LaneKeep".parse::<Task>().unwrap(), Task::LaneKeep);
    assert_eq!("ACC".parse::<Task>().unwrap(), Task::Acc);
    assert_eq!("Track".parse::<Task>().unwrap(), Task::Track);
    assert_eq!(
        "Drift".parse::<Task>().unwrap_err().to_string(),
        "task must be 'LaneKeep', 'ACC' or 'Track', not \"Drift\""
    );
}

#[test]
fn bad_input_is_refused_by_name() {
    let (mut b, mut out) = batch(2);
    let err = b
        .step(
            &[0.0, 0.0, 0.0, f64::NAN],
            &[false; 2],
            &[START; 2],
            out.view(),
        )
        .unwrap_err();
    assert!(
        matches!(
            err,
            VecEnvError::Action {
                env: 1,
                index: 1,
                ..
            }
        ),
        "{err}"
    );
    // Nothing stepped.
    assert!((b.time(0) - 0.01).abs() < 1e-12);
    let err = b
        .step(&[0.0; 3], &[false; 2], &[START; 2], out.view())
        .unwrap_err();
    assert_eq!(
        err.to_string(),
        "actions has 3 values where the batch needs 4"
    );
    let bad = Start {
        speed: f64::INFINITY,
        ..START
    };
    let err = b.reset(1, &bad, &mut out.obs[..11]).unwrap_err();
    assert_eq!(
        err.to_string(),
        "the start of environment 1: start.speed must be finite, not inf"
    );
    assert!(matches!(
        VecEnv::new(&lane_keep(), Task::LaneKeep, 0, 4),
        Err(VecEnvError::Zero { name: "num_envs" })
    ));
    assert!(matches!(
        VecEnv::new(&lane_keep(), Task::Acc, 1, 4),
        Err(VecEnvError::NoCar(1))
    ));
}
