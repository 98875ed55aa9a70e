//! `_native.VecSim`: `sim::vec_env::VecEnv` for `webots_vehicle.gym.VectorEnv`.
//!
//! Arrays cross through the buffer protocol (numpy arrays, C order): one call copies the
//! whole `N × 2` action array in and the `N × m` observations, `N` rewards and `N` flags out,
//! with no Python object per environment. Flags travel as `uint8` (the buffer protocol's
//! `bool` has no pyo3 element type): the Python side passes `bool` arrays viewed as `uint8`.

use pyo3::buffer::PyBuffer;
use pyo3::exceptions::{PyIndexError, PyValueError};
use pyo3::prelude::*;

use sim::vec_env::{ACTION_LEN, Start, StepOut, VecEnv, VecEnvError};
use sim::world_file;

use crate::gym_env::task_of;
use crate::{SimulationError, WorldError};

/// Values of one start row: x (m), y (m), yaw (rad), speed (m/s), the ACC lead's speed (m/s).
pub(crate) const START_LEN: usize = 5;

/// A batch of simulations of one world: see the module docs.
#[pyclass(module = "webots_vehicle._native", unsendable)]
pub(crate) struct VecSim {
    batch: VecEnv,
    actions: Vec<f64>,
    reset: Vec<bool>,
    starts: Vec<Start>,
    start_rows: Vec<f64>,
    flags: Vec<u8>,
    observations: Vec<f32>,
    rewards: Vec<f64>,
    terminated: Vec<bool>,
    truncated: Vec<bool>,
}

pub(crate) fn batch_error(e: VecEnvError) -> PyErr {
    match e {
        VecEnvError::UnknownEnv(_) => PyIndexError::new_err(e.to_string()),
        VecEnvError::Sim {
            source: sim::SimError::Param(_),
            ..
        }
        | VecEnvError::Zero { .. }
        | VecEnvError::Buffer { .. }
        | VecEnvError::Action { .. }
        | VecEnvError::Start { .. }
        | VecEnvError::NoCar(_) => PyValueError::new_err(e.to_string()),
        VecEnvError::Restore { .. } | VecEnvError::Sim { .. } => {
            SimulationError::new_err(e.to_string())
        }
    }
}

pub(crate) fn start_of(row: &[f64]) -> Start {
    Start {
        x: row[0],
        y: row[1],
        yaw: row[2],
        speed: row[3],
        lead_speed: row[4],
    }
}

/// Bools as the `uint8` the Python side views its `bool` arrays as.
fn write_flags(
    py: Python<'_>,
    scratch: &mut Vec<u8>,
    flags: &[bool],
    out: &PyBuffer<u8>,
) -> PyResult<()> {
    scratch.clear();
    scratch.extend(flags.iter().map(|&f| u8::from(f)));
    out.copy_from_slice(py, scratch)
}

impl VecSim {
    /// One step of the whole batch with the actions, reset flags and starts held, into the
    /// held outputs: what `step` and `bench_steps` both run.
    fn step_batch(&mut self) -> PyResult<()> {
        self.batch
            .step(
                &self.actions,
                &self.reset,
                &self.starts,
                StepOut {
                    observations: &mut self.observations,
                    rewards: &mut self.rewards,
                    terminated: &mut self.terminated,
                    truncated: &mut self.truncated,
                },
            )
            .map_err(batch_error)
    }
}

#[pymethods]
impl VecSim {
    /// `num_envs` copies of world file `world` for `task` ("LaneKeep", "ACC" or "Track"), each
    /// stepped `frame_skip` basic time steps per action.
    #[new]
    fn new(world: &str, task: &str, num_envs: usize, frame_skip: u32) -> PyResult<Self> {
        let task = task_of(task)?;
        let description =
            world_file::load(world).map_err(|e| WorldError::new_err(e.to_string()))?;
        let batch = VecEnv::new(&description, task, num_envs, frame_skip).map_err(batch_error)?;
        let zero = Start {
            x: 0.0,
            y: 0.0,
            yaw: 0.0,
            speed: 0.0,
            lead_speed: 0.0,
        };
        Ok(VecSim {
            actions: vec![0.0; num_envs * ACTION_LEN],
            reset: vec![false; num_envs],
            starts: vec![zero; num_envs],
            start_rows: vec![0.0; num_envs * START_LEN],
            flags: Vec::with_capacity(num_envs),
            observations: vec![0.0; num_envs * task.observation_len()],
            rewards: vec![0.0; num_envs],
            terminated: vec![false; num_envs],
            truncated: vec![false; num_envs],
            batch,
        })
    }

    /// The number of environments.
    #[getter]
    fn num_envs(&self) -> usize {
        self.batch.len()
    }

    /// Values in one observation row.
    #[getter]
    fn observation_len(&self) -> usize {
        self.batch.task().observation_len()
    }

    /// Simulated time per step (s).
    #[getter]
    fn dt(&self) -> f64 {
        self.batch.dt()
    }

    /// Simulated time of environment `i` (s).
    fn time(&self, i: usize) -> PyResult<f64> {
        if i >= self.batch.len() {
            return Err(batch_error(VecEnvError::UnknownEnv(i)));
        }
        Ok(self.batch.time(i))
    }

    /// Starts a new episode of environment `i` from `start` (x m, y m, yaw rad, speed m/s,
    /// lead speed m/s) and writes its first observation into row `i` of `observations`
    /// (`float32`, `N × m`).
    fn reset(
        &mut self,
        py: Python<'_>,
        i: usize,
        start: [f64; START_LEN],
        observations: PyBuffer<f32>,
    ) -> PyResult<()> {
        let m = self.batch.task().observation_len();
        if i >= self.batch.len() {
            return Err(batch_error(VecEnvError::UnknownEnv(i)));
        }
        self.batch
            .reset(
                i,
                &start_of(&start),
                &mut self.observations[i * m..(i + 1) * m],
            )
            .map_err(batch_error)?;
        observations.copy_from_slice(py, &self.observations)
    }

    /// One step of every environment (see `sim::vec_env::VecEnv::step`): `actions` (`float64`,
    /// `N × 2`), `reset` (`uint8`, `N`: reset instead of stepping, from the row of `starts`,
    /// `float64`, `N × 5`); fills `observations` (`float32`, `N × m`), `rewards` (`float64`,
    /// `N`), `terminated` and `truncated` (`uint8`, `N`).
    #[allow(clippy::too_many_arguments)]
    fn step(
        &mut self,
        py: Python<'_>,
        actions: PyBuffer<f64>,
        reset: PyBuffer<u8>,
        starts: PyBuffer<f64>,
        observations: PyBuffer<f32>,
        rewards: PyBuffer<f64>,
        terminated: PyBuffer<u8>,
        truncated: PyBuffer<u8>,
    ) -> PyResult<()> {
        actions.copy_to_slice(py, &mut self.actions)?;
        self.flags.resize(self.batch.len(), 0);
        reset.copy_to_slice(py, &mut self.flags)?;
        for (r, &f) in self.reset.iter_mut().zip(&self.flags) {
            *r = f != 0;
        }
        if self.reset.iter().any(|&r| r) {
            starts.copy_to_slice(py, &mut self.start_rows)?;
            for (s, row) in self
                .starts
                .iter_mut()
                .zip(self.start_rows.chunks(START_LEN))
            {
                *s = start_of(row);
            }
        }
        self.step_batch()?;
        observations.copy_from_slice(py, &self.observations)?;
        rewards.copy_from_slice(py, &self.rewards)?;
        write_flags(py, &mut self.flags, &self.terminated, &terminated)?;
        write_flags(py, &mut self.flags, &self.truncated, &truncated)
    }

    /// Steps the batch `steps` times from Rust with the actions of the last `step` call (zero
    /// before), resetting each environment whose episode ended to `start` (x m, y m, yaw rad,
    /// speed m/s, lead speed m/s) as the autoreset does; returns the wall time taken (s).
    /// `python/bench/gym_step.py` times the same steps through `step()` in the same process:
    /// the difference is the cost of the Python layers.
    fn bench_steps(&mut self, steps: u64, start: [f64; START_LEN]) -> PyResult<f64> {
        let begin = std::time::Instant::now();
        self.starts.fill(start_of(&start));
        for _ in 0..steps {
            for (r, (t, u)) in self
                .reset
                .iter_mut()
                .zip(self.terminated.iter().zip(&self.truncated))
            {
                *r = *t || *u;
            }
            self.step_batch()?;
        }
        Ok(begin.elapsed().as_secs_f64())
    }
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<VecSim>()
}
