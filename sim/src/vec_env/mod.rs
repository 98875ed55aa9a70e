//! Many independent copies of one world stepped with one call: the core of the Python
//! package's `webots_vehicle.gym.VectorEnv`, and (module `task`) the one environment each copy
//! runs, which the single environments (`webots_vehicle.gym.LaneKeepEnv` ...) run too.
//!
//! A [`VecEnv`] holds `N` [`Simulation`]s of the same world description, each with its own
//! start snapshot and [`TaskEnv`], and runs the gymnasium environments' per-step work for all
//! of them in Rust: the action's steering and cruise-control target, `frame_skip` basic time
//! steps, the observation, the default reward and the end of the episode. It writes into
//! caller buffers (`N × k` actions in, `N × m` observations, `N` rewards and flags out) so
//! that a binding passes whole arrays and builds no per-environment object.
//!
//! Autoreset follows gymnasium's `NEXT_STEP` mode: the caller flags the environments whose
//! episode ended at the previous step; in the next [`VecEnv::step`] those are reset to the
//! [`Start`] given (their action is ignored) and report reward 0, not terminated and not
//! truncated.
//!
//! Units: m, m/s, rad, rad/s, s; the actions are shares of [`MAX_STEERING`] and
//! [`MAX_ACCELERATION`].

mod task;

pub use task::{
    ACTION_LEN, MAX_ACCELERATION, MAX_SPEED, MAX_STEERING, Outcome, RADAR_TARGETS, Start, Task,
    TaskEnv, UnknownTask,
};

use crate::world_file::WorldDescription;
use crate::{SimError, Simulation, Snapshot, SnapshotError};

/// Why a batch or one environment ([`TaskEnv`]) cannot be built, reset or stepped.
#[derive(Debug, thiserror::Error)]
pub enum VecEnvError {
    /// `num_envs` or `frame_skip` zero.
    #[error("{name} must be at least 1, not 0")]
    Zero {
        /// The argument.
        name: &'static str,
    },
    /// A buffer whose length does not fit the batch.
    #[error("{name} has {len} values where the batch needs {expected}")]
    Buffer {
        /// The buffer.
        name: &'static str,
        /// Its length.
        len: usize,
        /// The length the batch needs.
        expected: usize,
    },
    /// An action value that is not finite (nothing was stepped).
    #[error("actions[{env}][{index}] must be finite, not {value}")]
    Action {
        /// The environment.
        env: usize,
        /// The value's index in the action.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A start value that is not finite.
    #[error("the start of environment {env}: {field} must be finite, not {value}")]
    Start {
        /// The environment.
        env: usize,
        /// The field of [`Start`].
        field: &'static str,
        /// The value.
        value: f64,
    },
    /// An environment index not below the batch's size.
    #[error("no environment {0} in this batch")]
    UnknownEnv(usize),
    /// The world lacks the task's car.
    #[error("the world has no car {0}, which the task drives")]
    NoCar(usize),
    /// The start snapshot could not be restored (a bug: it is this simulation's own).
    #[error("environment {env}: {source}")]
    Restore {
        /// The environment.
        env: usize,
        /// Why.
        source: SnapshotError,
    },
    /// A refused placement or a physics failure of environment `env`.
    #[error("environment {env}: {source}")]
    Sim {
        /// The environment.
        env: usize,
        /// The simulation's error.
        source: SimError,
    },
}

/// The buffers one [`VecEnv::step`] fills, each row-major with one row per environment.
pub struct StepOut<'a> {
    /// `N × observation_len` observations.
    pub observations: &'a mut [f32],
    /// `N` rewards.
    pub rewards: &'a mut [f64],
    /// `N` terminated flags.
    pub terminated: &'a mut [bool],
    /// `N` truncated flags (the world's duration elapsed).
    pub truncated: &'a mut [bool],
}

/// One environment of the batch: its simulation, the snapshot its episodes start from, and
/// the task's state.
struct Env {
    sim: Simulation,
    start: Snapshot,
    task: TaskEnv,
}

impl Env {
    /// Restores the start snapshot and starts an episode from `start` (checked first: a
    /// refused start changes nothing).
    fn reset(&mut self, start: &Start, observation: &mut [f32]) -> Result<(), VecEnvError> {
        self.task.check_start(start)?;
        self.sim
            .restore(&self.start)
            .map_err(|source| VecEnvError::Restore {
                env: self.task.index,
                source,
            })?;
        self.task.start(&mut self.sim, start, observation)
    }
}

/// `N` independent simulations of one world: see the module docs.
pub struct VecEnv {
    task: Task,
    envs: Vec<Env>,
}

impl VecEnv {
    /// `n` copies of the world of `description` for `task`, each advanced `frame_skip` basic
    /// time steps per action. Call [`VecEnv::reset`] on each before stepping it.
    ///
    /// # Errors
    /// [`VecEnvError::Zero`] for `n` or `frame_skip` zero; [`VecEnvError::NoCar`] if the
    /// world lacks the task's car; [`VecEnvError::Sim`] for an error building the world.
    pub fn new(
        description: &WorldDescription,
        task: Task,
        n: usize,
        frame_skip: u32,
    ) -> Result<VecEnv, VecEnvError> {
        if n == 0 {
            return Err(VecEnvError::Zero { name: "num_envs" });
        }
        let envs = (0..n)
            .map(|index| {
                let (sim, _reports) = Simulation::from_description(description)
                    .map_err(|source| VecEnvError::Sim { env: index, source })?;
                let mut task = TaskEnv::new(&sim, task, frame_skip)?;
                task.index = index;
                let start = sim.snapshot();
                Ok(Env { sim, start, task })
            })
            .collect::<Result<Vec<_>, VecEnvError>>()?;
        Ok(VecEnv { task, envs })
    }

    /// The number of environments.
    pub fn len(&self) -> usize {
        self.envs.len()
    }

    /// Always false: a batch has at least one environment.
    pub fn is_empty(&self) -> bool {
        self.envs.is_empty()
    }

    /// The task.
    pub fn task(&self) -> Task {
        self.task
    }

    /// Simulated time per step (s).
    pub fn dt(&self) -> f64 {
        self.envs[0].task.dt()
    }

    /// Simulated time of environment `i` (s).
    ///
    /// # Panics
    /// If `i` is not below [`VecEnv::len`].
    pub fn time(&self, i: usize) -> f64 {
        self.envs[i].sim.world().time()
    }

    /// Starts a new episode of environment `i` from `start` and writes its first observation
    /// into `observation` (`observation_len` values): the world's snapshot as loaded restored,
    /// then [`TaskEnv::start`].
    ///
    /// # Errors
    /// [`VecEnvError::UnknownEnv`] for `i` out of range; those of [`TaskEnv::start`].
    pub fn reset(
        &mut self,
        i: usize,
        start: &Start,
        observation: &mut [f32],
    ) -> Result<(), VecEnvError> {
        let env = self.envs.get_mut(i).ok_or(VecEnvError::UnknownEnv(i))?;
        env.reset(start, observation)
    }

    /// One step of every environment: environment `i` takes row `i` of `actions`
    /// (`N × ACTION_LEN`, [`TaskEnv::step`]), or is reset to `starts[i]` where `reset[i]`
    /// (autoreset, `NEXT_STEP` mode). Fills `out`.
    ///
    /// # Errors
    /// [`VecEnvError::Buffer`] naming the buffer whose length does not fit, or
    /// [`VecEnvError::Action`] for an action value that is not finite (nothing is stepped
    /// then); a refused start or a physics failure (the environments before it have stepped).
    pub fn step(
        &mut self,
        actions: &[f64],
        reset: &[bool],
        starts: &[Start],
        out: StepOut<'_>,
    ) -> Result<(), VecEnvError> {
        let n = self.envs.len();
        let m = self.task.observation_len();
        for (name, len, want) in [
            ("actions", actions.len(), n * ACTION_LEN),
            ("reset", reset.len(), n),
            ("starts", starts.len(), n),
            ("observations", out.observations.len(), n * m),
            ("rewards", out.rewards.len(), n),
            ("terminated", out.terminated.len(), n),
            ("truncated", out.truncated.len(), n),
        ] {
            if len != want {
                return Err(VecEnvError::Buffer {
                    name,
                    len,
                    expected: want,
                });
            }
        }
        if let Some((k, &value)) = actions.iter().enumerate().find(|(_, a)| !a.is_finite()) {
            return Err(VecEnvError::Action {
                env: k / ACTION_LEN,
                index: k % ACTION_LEN,
                value,
            });
        }
        for (i, env) in self.envs.iter_mut().enumerate() {
            let obs = &mut out.observations[i * m..(i + 1) * m];
            if reset[i] {
                env.reset(&starts[i], obs)?;
                out.rewards[i] = 0.0;
                out.terminated[i] = false;
                out.truncated[i] = false;
                continue;
            }
            let action = [actions[i * ACTION_LEN], actions[i * ACTION_LEN + 1]];
            let outcome = env.task.step(&mut env.sim, action, obs)?;
            out.rewards[i] = outcome.reward;
            out.terminated[i] = outcome.terminated;
            out.truncated[i] = outcome.truncated;
        }
        Ok(())
    }
}
